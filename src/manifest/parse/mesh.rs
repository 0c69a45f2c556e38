//! `[mesh]`: a builtin shape (with its shape parameters) or an `.obj` file, and the
//! optional `[mesh.attributes]` mapping of vertex shader inputs to mesh attributes.

use std::ops::Range;

use toml::de::{DeTable, DeValue};

use super::{entries, is_ident, key, list, Ctx, Val};
use crate::diag::Code;
use crate::manifest::{BuiltinMesh, MeshAttribute, MeshDecl, MeshSource};

const MESH_KEYS: &[&str] = &["builtin", "obj", "segments", "rings", "divisions", "attributes"];
const MAX_MESH_DIVISIONS: u32 = 1024;

impl Ctx<'_> {
    pub(super) fn mesh(&mut self, v: &Val<'_>) -> Option<MeshDecl> {
        let builtin_choices: Vec<(&'static str, &'static str)> = BuiltinMesh::NAMES.iter().map(|n| (*n, *n)).collect();
        match v.get_ref() {
            DeValue::String(_) => {
                let name = self.choice(v, "`mesh`", "builtin mesh", &builtin_choices)?;
                let source = MeshSource::Builtin(builtin(name, None, None, None));
                Some(MeshDecl { span: v.span(), source, attributes: Vec::new(), attribute_spans: Vec::new(), values: Vec::new() })
            }
            DeValue::Table(t) => self.mesh_table(v, t, &builtin_choices),
            _ => {
                self.wrong_type(v, "`mesh`", "a table (or a builtin mesh name)");
                None
            }
        }
    }

    /// `[mesh.attributes]`: each input mapped to a mesh attribute (with the input names'
    /// spans), or fed the manifest's own numbers, one per vertex (a table). None after an
    /// error.
    #[allow(clippy::type_complexity)]
    fn mesh_attributes(
        &mut self,
        v: &Val<'_>,
        what: &str,
    ) -> Option<(Vec<(String, MeshAttribute)>, Vec<Range<usize>>, Vec<crate::manifest::InstanceAttribute>)> {
        let at = self.table(v, what)?;
        let (mut attributes, mut spans, mut values) = (Vec::new(), Vec::new(), Vec::new());
        let mut ok = true;
        let choices: Vec<(&'static str, MeshAttribute)> = MeshAttribute::ALL.iter().map(|a| (a.name(), *a)).collect();
        for (ak, av) in entries(at) {
            let input = key(ak);
            if !is_ident(input) || input.starts_with("gl_") {
                self.report(
                    Code::ManifestValue,
                    ak.span(),
                    format!("`{input}` is not a vertex shader input name"),
                    "not a GLSL identifier",
                );
                ok = false;
                continue;
            }
            if matches!(av.get_ref(), DeValue::Table(_)) {
                // The manifest's own numbers, one per vertex (counted against the mesh when
                // it is built).
                match self.element_values("mesh.attributes", input, ak.span(), av, None) {
                    Some(a) => values.push(a),
                    None => ok = false,
                }
                continue;
            }
            match self.choice(av, &format!("`mesh.attributes.{input}`"), "mesh attribute", &choices) {
                Some(attr) => {
                    attributes.push((input.to_owned(), attr));
                    spans.push(ak.span());
                }
                None => ok = false,
            }
        }
        ok.then_some((attributes, spans, values))
    }

    fn mesh_table(&mut self, v: &Val<'_>, t: &DeTable<'_>, builtin_choices: &[(&'static str, &'static str)]) -> Option<MeshDecl> {
        let mut ok = true;
        let mut sources: Vec<(&'static str, Range<usize>)> = Vec::new();
        let mut builtin_name = None;
        let mut obj = None;
        let mut segments = None;
        let mut rings = None;
        let mut divisions = None;
        let mut attributes = Vec::new();
        let mut attribute_spans = Vec::new();
        let mut values = Vec::new();
        for (k, v2) in entries(t) {
            let what = format!("`mesh.{}`", key(k));
            let what = what.as_str();
            match key(k) {
                "builtin" => {
                    sources.push(("builtin", k.span()));
                    builtin_name = self.choice(v2, what, "builtin mesh", builtin_choices);
                    ok &= builtin_name.is_some();
                }
                "obj" => {
                    sources.push(("obj", k.span()));
                    obj = self.file_path(v2, what, Code::AssetNotFound, "mesh file");
                    ok &= obj.is_some();
                }
                "segments" => {
                    segments = self.uint(v2, what, 3, MAX_MESH_DIVISIONS).map(|n| (n, k.span()));
                    ok &= segments.is_some();
                }
                "rings" => {
                    rings = self.uint(v2, what, 2, MAX_MESH_DIVISIONS).map(|n| (n, k.span()));
                    ok &= rings.is_some();
                }
                "divisions" => {
                    divisions = self.uint(v2, what, 1, MAX_MESH_DIVISIONS).map(|n| (n, k.span()));
                    ok &= divisions.is_some();
                }
                "attributes" => match self.mesh_attributes(v2, what) {
                    Some((a, spans, v)) => {
                        attributes = a;
                        attribute_spans = spans;
                        values = v;
                    }
                    None => ok = false,
                },
                other => {
                    self.unknown_key(other, k.span(), "in `[mesh]`", MESH_KEYS);
                    ok = false;
                }
            }
        }
        match sources.as_slice() {
            [] => {
                let d = self.report(Code::ManifestMissing, v.span(), "`[mesh]` needs `builtin` or `obj`".into(), "no mesh source");
                d.help = Some(format!("add e.g. `builtin = \"uv_sphere\"`; builtins: {}", list(&BuiltinMesh::NAMES)));
                return None;
            }
            [_] => {}
            [(_, first), (_, second), ..] => {
                let file = self.file;
                let (first, second) = (first.clone(), second.clone());
                let d = self.report(Code::ManifestConflict, second, "`[mesh]` has both `builtin` and `obj`".into(), "second source");
                d.labels.push(crate::diag::Label { file, span: first, message: "first source".into() });
                d.help = Some("keep one of `builtin` and `obj`".into());
                return None;
            }
        }
        // Shape parameters must belong to the chosen builtin.
        let is = |n: &str| builtin_name == Some(n);
        let mut misplaced = |key: &str, span: &Option<(u32, Range<usize>)>, owner: &str, applies: bool| {
            if let (Some((_, span)), false) = (span, applies) {
                let d = self.report(
                    Code::ManifestConflict,
                    span.clone(),
                    format!("`{key}` only applies to `builtin = \"{owner}\"`"),
                    "not used by this mesh",
                );
                d.help = Some(format!("remove `{key}`"));
                false
            } else {
                true
            }
        };
        let mut fine = misplaced("segments", &segments, "uv_sphere", is("uv_sphere"));
        fine &= misplaced("rings", &rings, "uv_sphere", is("uv_sphere"));
        fine &= misplaced("divisions", &divisions, "plane_grid", is("plane_grid"));
        if !(ok && fine) {
            return None;
        }
        let source = match (builtin_name, obj) {
            (Some(n), _) => MeshSource::Builtin(builtin(n, segments.map(|s| s.0), rings.map(|r| r.0), divisions.map(|d| d.0))),
            (None, Some(path)) => MeshSource::Obj(path),
            (None, None) => return None,
        };
        Some(MeshDecl { span: v.span(), source, attributes, attribute_spans, values })
    }
}

fn builtin(name: &str, segments: Option<u32>, rings: Option<u32>, divisions: Option<u32>) -> BuiltinMesh {
    match name {
        "fullscreen_quad" => BuiltinMesh::FullscreenQuad,
        "fullscreen_triangle" => BuiltinMesh::FullscreenTriangle,
        "quad" => BuiltinMesh::Quad,
        "cube" => BuiltinMesh::Cube,
        "uv_sphere" => BuiltinMesh::UvSphere {
            segments: segments.unwrap_or(BuiltinMesh::DEFAULT_SEGMENTS),
            rings: rings.unwrap_or(BuiltinMesh::DEFAULT_RINGS),
        },
        _ => BuiltinMesh::PlaneGrid { divisions: divisions.unwrap_or(BuiltinMesh::DEFAULT_DIVISIONS) },
    }
}
