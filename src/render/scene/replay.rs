//! What a scene feeds its program, kept on the CPU so that another API can draw the same
//! scene: `effectc verify` draws the original GLSL through OpenGL from these bytes (the
//! uniform values are the scene's own buffers, rewritten every frame).

use std::collections::BTreeMap;

use crate::assets::texture::TexelImage;
use crate::manifest::{Filter, RenderDecl, Wrap};
use crate::render::attributes::Interleaved;

/// The CPU side of one scene.
pub struct Replay {
    /// Per-vertex attributes at their WGSL locations (for a folded geometry program too,
    /// whose wgpu draw pulls them from storage buffers instead).
    pub vertices: Interleaved,
    /// Per-instance attributes (`[instances]`).
    pub instances: Option<Interleaved>,
    pub draw: ReplayDraw,
    /// Textures by the binding name in the emitted code.
    pub textures: BTreeMap<String, ReplayTexture>,
    /// Sampler state by the sampler binding's name: filter, wrap, comparison (depth).
    pub samplers: BTreeMap<String, (Filter, Wrap, bool)>,
    /// Depth, blend and cull state.
    pub render: RenderDecl,
    /// The scene draws with a depth buffer.
    pub depth: bool,
    /// Vertex inputs: GLSL name → location in the emitted code.
    pub inputs: Vec<(String, u32)>,
    /// Samplers: (GLSL path, texture binding name, sampler binding name).
    pub plan_textures: Vec<(String, String, String)>,
    /// Fragment outputs: (location, components written: 1–4).
    pub outputs: Vec<(u32, u32)>,
}

/// The components of a WGSL or GLSL type (`f32` and `float` 1, `vec3<f32>` and `ivec3` 3).
pub fn components(ty: &str) -> u32 {
    let ty = ty.trim_start_matches(['i', 'u', 'b', 'd']);
    ty.strip_prefix("vec").and_then(|t| t.chars().next()).and_then(|c| c.to_digit(10)).unwrap_or(1)
}

/// How the original program draws: GL's primitive mode and the vertices.
pub struct ReplayDraw {
    /// `triangles`, or for a geometry stage its input primitive (`points`, `lines`,
    /// `lines_adjacency`, `triangles`, `triangles_adjacency`), or `patches`.
    pub primitive: &'static str,
    /// `patches`: the vertices of one patch (`GL_PATCH_VERTICES`); 0 otherwise.
    pub patch_vertices: u32,
    /// Indexed draws: the indices; otherwise `count` vertices in order.
    pub indices: Option<Vec<u32>>,
    pub count: u32,
}

/// What a texture binding holds.
#[derive(Clone)]
pub enum ReplayTexture {
    /// An image (manifest, generated or the placeholder), with a mip chain for 2D and cube
    /// textures. `dimension` as reflected (`2d`, `cube`, `2d_array`, `3d`, `1d`).
    Image { image: TexelImage, dimension: &'static str },
    /// A 1×1 depth texture cleared to 1.0.
    Depth { dimension: &'static str },
    /// A 1×1 integer texture of zeros.
    Integer { unsigned: bool, dimension: &'static str },
    /// A 4-sample 1×1 target cleared to magenta (depth: 1.0).
    Multisampled { depth: bool },
    /// The target of an earlier pass, by the name the manifest's `samples` gives it.
    Target(String),
}
