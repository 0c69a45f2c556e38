//! Which mesh a scene draws (the manifest's, else a guess from what the vertex stage
//! reads), and the warnings that point a guess at its declaration in the user's GLSL.

use crate::assets::mesh::Mesh;
use crate::diag::{Code, Diagnostic, FileId};
use crate::front::program::CompiledProgram;
use crate::front::syntax::Storage;
use crate::manifest::{BuiltinMesh, Effect, MeshAttribute, MeshSource};
use crate::render::attributes;
use crate::stage::StageKind;

use super::SceneInput;

/// How the mesh was chosen.
pub(super) enum MeshNote {
    Manifest,
    /// No `[mesh]` and matrices in use: a cube.
    Cube,
    /// No `[mesh]`, matrices in use and 2D positions: a quad.
    Quad,
    /// No `[mesh]`, no matrices: a full-screen quad.
    Fullscreen,
    /// No `[mesh]` and no vertex inputs: three vertices, positions made by the shader.
    OwnVertices,
}

impl MeshNote {
    pub(super) fn describe(&self, effect: Option<&Effect>) -> String {
        match self {
            MeshNote::Manifest => match effect.and_then(|e| e.mesh.as_ref()).map(|m| &m.source) {
                Some(MeshSource::Builtin(b)) => format!("mesh {}", b.name()),
                Some(MeshSource::Obj(p)) => format!("mesh {}", p.display()),
                None => "mesh".into(),
            },
            MeshNote::Cube => "mesh cube (guessed)".into(),
            MeshNote::Quad => "mesh quad (guessed: 2D positions)".into(),
            MeshNote::Fullscreen => "mesh fullscreen_quad (guessed)".into(),
            MeshNote::OwnVertices => "3 vertices without attributes".into(),
        }
    }
}

pub(super) fn choose_mesh(input: &SceneInput<'_>, warnings: &mut Vec<Diagnostic>) -> Result<(Mesh, MeshNote), Vec<Diagnostic>> {
    if let Some(decl) = input.effect.and_then(|e| e.mesh.as_ref()) {
        let mesh = match &decl.source {
            MeshSource::Builtin(b) => Mesh::builtin(*b),
            MeshSource::Obj(path) => Mesh::load_obj(path).map_err(|e| {
                let file = input.effect.map(|e| e.file).unwrap_or(FileId(0));
                vec![Diagnostic::new(Code::AssetLoad, format!("cannot load the mesh: {e}")).at(file, decl.span.clone(), "this mesh")]
            })?,
        };
        let note = if matches!(decl.source, MeshSource::Builtin(BuiltinMesh::FullscreenQuad | BuiltinMesh::FullscreenTriangle)) {
            MeshNote::Fullscreen
        } else {
            MeshNote::Manifest
        };
        return Ok((mesh, note));
    }
    let r = &input.translation.reflection;
    let file = input.program.stages[0].syntax.file;
    if r.vertex_inputs.is_empty() {
        return Ok((Mesh::builtin(BuiltinMesh::FullscreenQuad), MeshNote::OwnVertices));
    }
    let uses_matrices = transforms_positions(input.program);
    // A 2D position would flatten a cube's faces onto one plane, where they z-fight.
    let flat_positions = attributes::choose(&r.vertex_inputs, &[])
        .iter()
        .any(|c| c.attribute == Some(MeshAttribute::Position) && c.format == wgpu::VertexFormat::Float32x2);
    let (mesh, note, what) = if uses_matrices && flat_positions {
        (BuiltinMesh::Quad, MeshNote::Quad, "a unit quad (the program uses matrices and 2D positions)")
    } else if uses_matrices {
        (BuiltinMesh::Cube, MeshNote::Cube, "a unit cube (the program uses matrices)")
    } else {
        (BuiltinMesh::FullscreenQuad, MeshNote::Fullscreen, "a full-screen quad (the program uses no matrices)")
    };
    if input.effect.is_some() {
        warnings.push(
            Diagnostic::new(Code::MeshGuessed, format!("the manifest has no [mesh]: drawing {what}"))
                .in_file(input.effect.map(|e| e.file).unwrap_or(file))
                .with_help("add e.g. `mesh = \"uv_sphere\"`"),
        );
    }
    Ok((Mesh::builtin(mesh), note))
}

/// Whether a stage before the rasterizer reads a matrix of the user's (a loose uniform, a
/// struct or block member): its positions are then transformed, and a 3D mesh is drawn.
/// A matrix only the fragment stage reads, or GL's own (`gl_ModelViewMatrix`, identity
/// without a manifest, as in a fresh GL context), leaves the full-window rectangle
/// `glRectf(-1, -1, 1, 1)` draws.
fn transforms_positions(program: &CompiledProgram) -> bool {
    let is_matrix = |base: &str| base.starts_with("mat") || base.starts_with("dmat");
    program.stages.iter().filter(|s| matches!(s.syntax.stage, StageKind::Vertex | StageKind::Geometry | StageKind::TessEval)).any(|s| {
        let st = &s.syntax;
        let holds_matrix = |ty: &crate::front::syntax::GlslType| {
            is_matrix(&ty.base) || st.struct_def(&ty.base).is_some_and(|d| d.members.iter().any(|m| is_matrix(&m.ty.base)))
        };
        st.globals.iter().enumerate().filter(|(_, g)| g.storage == Storage::Uniform && !g.name.starts_with("gl_")).any(|(i, g)| {
            let read = || st.uses.iter().any(|u| u.target == crate::front::syntax::Referent::Global(i));
            match &g.block {
                // Members of an anonymous block are read by their own names.
                Some(b) => b.members.iter().any(|m| holds_matrix(&m.ty) && (read() || st.uses.iter().any(|u| u.name == m.name))),
                None => holds_matrix(&g.ty) && read(),
            }
        })
    })
}

pub(super) fn report_attributes(
    program: &CompiledProgram,
    choices: &[attributes::Choice],
    fullscreen_pass: bool,
    warnings: &mut Vec<Diagnostic>,
) {
    for c in choices {
        let (code, message) = match (c.attribute, c.guessed) {
            (Some(_), None) => continue,
            // A fixed-function attribute no array feeds reads GL's current value, as in GL.
            (None, None) => continue,
            (Some(_), Some(_)) if fullscreen_pass => continue,
            (Some(a), Some(why)) => (Code::AttributeGuessed, format!("vertex input `{}` reads the mesh's {a} (guessed {why})", c.input)),
            (None, _) => (Code::AttributeZero, format!("vertex input `{}` matches no mesh attribute: it reads zeros", c.input)),
        };
        let d = at_declaration(Diagnostic::new(code, message), program, &c.input, Storage::In, "this input");
        let example = c.attribute.unwrap_or(MeshAttribute::Position);
        warnings.push(d.with_help(format!(
            "map it in the manifest: [mesh.attributes] `{} = \"{example}\"` (attributes: position, normal, uv, tangent, bitangent, color)",
            c.input
        )));
    }
}

/// Points `d` at the declaration of `name` (a global with `storage`), in the vertex stage
/// for inputs, in any stage for uniforms.
pub(super) fn at_declaration(d: Diagnostic, program: &CompiledProgram, name: &str, storage: Storage, label: &str) -> Diagnostic {
    let input = storage == Storage::In;
    let matches = |s: Storage| s == storage || (input && s == Storage::Attribute);
    for stage in &program.stages {
        if input && stage.syntax.stage != StageKind::Vertex {
            continue;
        }
        if let Some(g) = stage.syntax.globals.iter().find(|g| g.name == name && matches(g.storage)) {
            return d.at(stage.syntax.file, g.name_span.clone(), label);
        }
        // Members of uniform blocks without an instance name are reached by plain name.
        if let Some(m) = stage
            .syntax
            .globals
            .iter()
            .filter(|g| matches(g.storage))
            .filter_map(|g| g.block.as_ref())
            .flat_map(|b| &b.members)
            .find(|m| m.name == name)
        {
            return d.at(stage.syntax.file, m.span.clone(), label);
        }
    }
    d.in_file(program.stages[0].syntax.file)
}
