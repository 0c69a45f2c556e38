//! `[mesh]`: the geometry an effect is drawn on (a builtin shape or an `.obj` file) and the
//! explicit mapping of vertex shader inputs to mesh attributes.

use std::ops::Range;
use std::path::PathBuf;

/// `[mesh]`: what the effect is drawn on.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshDecl {
    /// Span of the `[mesh]` header / inline table / string.
    pub span: Range<usize>,
    pub source: MeshSource,
    /// Optional explicit mapping: (shader input name, mesh attribute), in manifest order.
    pub attributes: Vec<(String, MeshAttribute)>,
    /// Spans of the shader input names in `attributes`, index for index.
    pub attribute_spans: Vec<Range<usize>>,
    /// Inputs fed the manifest's own numbers, one per vertex (`aBone = { values = […] }`,
    /// `{ sequence = … }`, `{ random = … }`): data no mesh file holds, integers included.
    pub values: Vec<super::InstanceAttribute>,
}

/// An attribute a mesh provides, which `[mesh.attributes]` can map a vertex input to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MeshAttribute {
    Position,
    Normal,
    Uv,
    /// xyz tangent, w = bitangent sign (±1), MikkTSpace convention.
    Tangent,
    /// cross(normal, tangent.xyz) × tangent.w.
    Bitangent,
    Color,
}

impl MeshAttribute {
    pub const ALL: [MeshAttribute; 6] = [
        MeshAttribute::Position,
        MeshAttribute::Normal,
        MeshAttribute::Uv,
        MeshAttribute::Tangent,
        MeshAttribute::Bitangent,
        MeshAttribute::Color,
    ];

    /// The name used in manifests (and by the renderer's mesh).
    pub const fn name(self) -> &'static str {
        match self {
            MeshAttribute::Position => "position",
            MeshAttribute::Normal => "normal",
            MeshAttribute::Uv => "uv",
            MeshAttribute::Tangent => "tangent",
            MeshAttribute::Bitangent => "bitangent",
            MeshAttribute::Color => "color",
        }
    }

    pub fn from_name(name: &str) -> Option<MeshAttribute> {
        MeshAttribute::ALL.into_iter().find(|a| a.name() == name)
    }
}

impl std::fmt::Display for MeshAttribute {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// The names of [`MeshAttribute::ALL`], in that order.
pub const MESH_ATTRIBUTES: &[&str] = &{
    let mut names = [""; MeshAttribute::ALL.len()];
    let mut i = 0;
    while i < names.len() {
        names[i] = MeshAttribute::ALL[i].name();
        i += 1;
    }
    names
};

#[derive(Debug, Clone, PartialEq)]
pub enum MeshSource {
    Builtin(BuiltinMesh),
    /// A Wavefront `.obj` file, resolved against the manifest directory.
    Obj(PathBuf),
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BuiltinMesh {
    /// One triangle pair covering clip space (−1..1), no transforms needed.
    FullscreenQuad,
    /// One triangle covering clip space (−1..3 in x and y, uv 0..2): a full-screen pass
    /// without the diagonal seam of a quad.
    FullscreenTriangle,
    /// A unit quad in the xy plane centred on the origin.
    Quad,
    /// A unit cube centred on the origin, 24 vertices (flat normals).
    Cube,
    /// A unit-radius sphere.
    UvSphere { segments: u32, rings: u32 },
    /// A unit plane in xz, split into `divisions`×`divisions` quads.
    PlaneGrid { divisions: u32 },
}

impl BuiltinMesh {
    pub const NAMES: [&'static str; 6] = ["fullscreen_quad", "fullscreen_triangle", "quad", "cube", "uv_sphere", "plane_grid"];
    pub const DEFAULT_SEGMENTS: u32 = 32;
    pub const DEFAULT_RINGS: u32 = 16;
    pub const DEFAULT_DIVISIONS: u32 = 16;
    pub fn name(&self) -> &'static str {
        match self {
            BuiltinMesh::FullscreenQuad => "fullscreen_quad",
            BuiltinMesh::FullscreenTriangle => "fullscreen_triangle",
            BuiltinMesh::Quad => "quad",
            BuiltinMesh::Cube => "cube",
            BuiltinMesh::UvSphere { .. } => "uv_sphere",
            BuiltinMesh::PlaneGrid { .. } => "plane_grid",
        }
    }
}
