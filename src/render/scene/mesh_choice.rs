//! Which mesh a scene draws (the manifest's, else a guess from what the vertex stage
//! reads), and the warnings that point a guess at its declaration in the user's GLSL.

use crate::assets::mesh::Mesh;
use crate::diag::{Code, Diagnostic, FileId};
use crate::front::program::CompiledProgram;
use crate::front::syntax::Storage;
use crate::manifest::{BuiltinMesh, Effect, MeshAttribute, MeshSource};
use crate::render::attributes;
use crate::stage::StageKind;

use super::plan::PlanInput;

/// How the mesh was chosen.
pub(crate) enum MeshNote {
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
            MeshNote::Fullscreen => match effect.and_then(|e| e.mesh.as_ref()).map(|m| &m.source) {
                // A full-screen pass, or `mesh = "fullscreen_quad"`.
                Some(MeshSource::Builtin(b)) => format!("mesh {}", b.name()),
                _ => "mesh fullscreen_quad (guessed)".into(),
            },
            MeshNote::OwnVertices => "3 vertices without attributes".into(),
        }
    }
}

pub(super) fn choose_mesh(input: &PlanInput<'_>, warnings: &mut Vec<Diagnostic>) -> Result<(Mesh, MeshNote), Vec<Diagnostic>> {
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
    let flat_positions = attributes::choose(&r.vertex_inputs, &[], &[])
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

/// Whether the program transforms its positions with a matrix of the user's: then a 3D
/// mesh is drawn. A vertex stage decides by what it writes to `gl_Position`: an expression
/// of inputs, constants and non-matrix uniforms (`gl_Position = piglit_vertex;`) is drawn
/// on the full-window rectangle `glRectf(-1, -1, 1, 1)` draws, one reading a user matrix,
/// a local or a function (which may hold one) on a 3D mesh. GL's own matrices
/// (`gl_ModelViewMatrix`, identity without a manifest, as in a fresh context) are not the
/// user's. A geometry or tessellation stage that reads a user matrix transforms too.
fn transforms_positions(program: &CompiledProgram) -> bool {
    program.stages.iter().any(|s| match s.syntax.stage {
        StageKind::Vertex => position_uses_matrix(&s.syntax),
        StageKind::Geometry | StageKind::TessEval => reads_user_matrix(&s.syntax),
        _ => false,
    })
}

fn is_matrix(base: &str) -> bool {
    base.starts_with("mat") || base.starts_with("dmat")
}

/// Whether a stage's own uniform (loose, struct or block member) of matrix type is read.
fn reads_user_matrix(st: &crate::front::syntax::StageSyntax) -> bool {
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
}

/// Whether any value written to `gl_Position` may come through a user matrix (see
/// [`transforms_positions`]).
fn position_uses_matrix(st: &crate::front::syntax::StageSyntax) -> bool {
    use crate::front::syntax::Referent;
    let writes: Vec<&str> = st
        .uses
        .iter()
        .filter(|u| u.name == "gl_Position" && u.target == Referent::Unresolved)
        .filter_map(|u| {
            let rest = st.text.get(u.span.end..)?;
            let rhs = rest.trim_start().strip_prefix('=').filter(|r| !r.starts_with('='))?;
            Some(&rhs[..rhs.find(';').unwrap_or(rhs.len())])
        })
        .collect();
    if writes.is_empty() {
        // Written another way (a swizzle, an `out` argument): assume the worst.
        return reads_user_matrix(st);
    }
    let matrix_member = |name: &str| {
        st.globals.iter().filter(|g| g.storage == Storage::Uniform).any(|g| match &g.block {
            Some(b) => b.members.iter().any(|m| m.name == name && is_matrix(&m.ty.base)),
            None => false,
        })
    };
    writes.iter().any(|rhs| {
        rhs.split(|c: char| !c.is_ascii_alphanumeric() && c != '_')
            .filter(|w| w.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_'))
            .any(|w| {
                let constructor = matches!(w, "float" | "int" | "uint" | "bool" | "double")
                    || w.trim_start_matches(['i', 'u', 'b', 'd']).strip_prefix("vec").is_some_and(|n| matches!(n, "2" | "3" | "4"))
                    || st.struct_def(w).is_some();
                if constructor || crate::front::builtins::is_type(w) || w.starts_with("gl_") || crate::front::builtins::is_function(w) {
                    return false;
                }
                match st.global(w) {
                    Some(g) => match g.storage {
                        Storage::Uniform => is_matrix(&g.ty.base) || st.struct_def(&g.ty.base).is_some() || g.block.is_some(),
                        _ => false,
                    },
                    // A local, a user function or a block member: a matrix may be behind it.
                    None => {
                        matrix_member(w)
                            || !st.globals.iter().any(|g| g.block.as_ref().is_some_and(|b| b.members.iter().any(|m| m.name == w)))
                    }
                }
            })
    })
}

pub(super) fn report_attributes(program: &CompiledProgram, choices: &[attributes::Choice], warnings: &mut Vec<Diagnostic>) {
    for c in choices {
        let (code, message) = match (c.attribute, c.guessed) {
            (Some(_), None) => continue,
            // A fixed-function attribute no array feeds reads GL's current value, as in GL.
            (None, None) => continue,
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

/// The attribute of effectc's full-screen triangle an input of this name is documented to
/// read (`position`, `texCoord`, `uv`); other names are matched by a guess, and warned about.
pub(super) fn documented_fullscreen_input(name: &str) -> Option<MeshAttribute> {
    match name.to_ascii_lowercase().as_str() {
        "position" => Some(MeshAttribute::Position),
        "texcoord" | "uv" => Some(MeshAttribute::Uv),
        _ => None,
    }
}

/// Points `d` at the declaration of `name` (a global with `storage`), in the vertex stage
/// for inputs, in any stage for uniforms.
pub(super) fn at_declaration(d: Diagnostic, program: &CompiledProgram, name: &str, storage: Storage, label: &str) -> Diagnostic {
    let input = storage == Storage::In;
    let matches = |s: Storage| s == storage || (input && s == Storage::Attribute);
    // An element or member (`tex[2]`, `layers[1].map`) points at its array's declaration.
    let name = name.split(['[', '.']).next().unwrap_or(name);
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
