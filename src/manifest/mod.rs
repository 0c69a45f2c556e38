//! `effects/<name>/effect.toml` → [`Effect`].
//!
//! The manifest names an effect's stages, the default values of its uniforms, the textures
//! bound to its samplers and the mesh it is drawn with. The user-facing format is documented
//! in `docs/manifest.md`.
//!
//! # How it is read
//! The text is parsed with toml's spanned document parser ([`toml::de::DeTable`]), which keeps
//! a byte span for every key and value, recovers from syntax errors and reports them all.
//! The resulting tree is then walked by hand rather than with `#[derive(Deserialize)]`:
//! a derive stops at the first problem, while the walk reports every unknown key, wrong type
//! and invalid value in one pass, each at the span of the offending key or value. Spans are
//! byte offsets into the original text (CRLF line ends and a BOM included).
//!
//! # Diagnostic codes
//! | code    | constant                 | meaning |
//! |---------|--------------------------|---------|
//! | `E0001` | [`E_SYNTAX`]             | TOML syntax error, or the file is not UTF-8 |
//! | `E0002` | [`E_IO`]                 | the manifest could not be read (the CLI exits with 2) |
//! | `E0003` | [`E_STAGE_NOT_FOUND`]    | a stage file does not exist |
//! | `E0004` | [`E_UNKNOWN_KEY`]        | unknown key (with the valid keys and a "did you mean") |
//! | `E0005` | [`E_TYPE`]               | a value has the wrong TOML type |
//! | `E0006` | [`E_VALUE`]              | a value has the right type but is invalid (unknown name, out of bounds, `nan`, `lo > hi`, …) |
//! | `E0007` | [`E_MISSING`]            | something required is missing (`[stages]`, a uniform's `value`/`semantic`, a texture source, a mesh source) |
//! | `E0008` | [`E_ASSET_NOT_FOUND`]    | a texture image or `.obj` file does not exist |
//! | `E0009` | [`E_CONFLICT`]           | keys that exclude each other (`value` and `semantic`, `builtin` and `obj`, compute with graphics stages, …) |
//! | `W0001` | [`W_STAGE_EXTENSION`]    | a stage file's extension names another stage (`vertex = "a.frag"`) |
//! | `W0002` | [`W_OUT_OF_RANGE`]       | a uniform's default value lies outside its declared `range` |
//! | `W0003` | [`W_UNUSED_PARAM`]       | a texture generator parameter the chosen generator ignores |

mod parse;
mod passes;
#[cfg(test)]
mod tests;

use std::ops::Range;
use std::path::{Path, PathBuf};

use crate::diag::{Diagnostic, FileId, Files};
use crate::stage::StageKind;

pub use passes::{PassClear, PassDecl, PassDraw, SampleDecl, SampleKind, TargetDecl, TargetFormat, TargetRef, TargetSize};

/// TOML syntax error, or the manifest is not valid UTF-8.
pub const E_SYNTAX: &str = "E0001";
/// The manifest file could not be read (missing, permissions, …). Maps to exit code 2.
pub const E_IO: &str = "E0002";
/// A stage listed in `[stages]` names a file that does not exist.
pub const E_STAGE_NOT_FOUND: &str = "E0003";
/// A key that is not part of the format.
pub const E_UNKNOWN_KEY: &str = "E0004";
/// A value of the wrong TOML type (`vertex = 3`, `range = "x"`).
pub const E_TYPE: &str = "E0005";
/// A value of the right type that is not acceptable (unknown name, out of bounds, `nan`, …).
pub const E_VALUE: &str = "E0006";
/// A required key or section is missing.
pub const E_MISSING: &str = "E0007";
/// A texture image or mesh file does not exist.
pub const E_ASSET_NOT_FOUND: &str = "E0008";
/// Two keys that exclude each other.
pub const E_CONFLICT: &str = "E0009";
/// A stage file's extension implies a different stage than the key it is listed under.
pub const W_STAGE_EXTENSION: &str = "W0001";
/// A uniform default lies outside its declared `range`.
pub const W_OUT_OF_RANGE: &str = "W0002";
/// A texture generator parameter that the chosen generator does not use.
pub const W_UNUSED_PARAM: &str = "W0003";

/// Every code this module emits, with a one-line description (for `--explain`-style listings).
pub const CODES: &[(&str, &str)] = &[
    (E_SYNTAX, "TOML syntax error in the manifest"),
    (E_IO, "the manifest could not be read"),
    (E_STAGE_NOT_FOUND, "stage file not found"),
    (E_UNKNOWN_KEY, "unknown key in the manifest"),
    (E_TYPE, "manifest value has the wrong type"),
    (E_VALUE, "invalid manifest value"),
    (E_MISSING, "required manifest key missing"),
    (E_ASSET_NOT_FOUND, "texture or mesh file not found"),
    (E_CONFLICT, "conflicting manifest keys"),
    (W_STAGE_EXTENSION, "stage file extension names another stage"),
    (W_OUT_OF_RANGE, "uniform default outside its declared range"),
    (W_UNUSED_PARAM, "texture generator parameter has no effect"),
];

/// True for the diagnostic produced when the manifest could not be read; the CLI maps it
/// to exit code 2 (usage / IO problems) rather than 1 (problems in the user's files).
pub fn is_io_error(d: &Diagnostic) -> bool {
    d.code == E_IO
}

/// A parsed `effect.toml`.
#[derive(Debug, Clone, PartialEq)]
pub struct Effect {
    /// The manifest in [`Files`].
    pub file: FileId,
    /// The directory holding the manifest; relative paths are resolved against it.
    pub dir: PathBuf,
    /// `name`, or the directory's name when absent.
    pub name: String,
    /// Span of the `name` value; `0..0` when the name came from the directory.
    pub name_span: Range<usize>,
    pub description: Option<String>,
    /// In pipeline order (vertex, tess_control, tess_eval, geometry, fragment, compute).
    pub stages: Vec<StageRef>,
    /// In manifest order.
    pub uniforms: Vec<UniformDefault>,
    /// In manifest order.
    pub textures: Vec<TextureDecl>,
    pub mesh: Option<MeshDecl>,
    /// `[camera]`; `None` when absent (the renderer's default camera).
    pub camera: Option<CameraDecl>,
    /// `[model]`: the model matrix (identity when absent).
    pub model: ModelDecl,
    /// `[render]`: frame size, count, rate, clear colour, culling, depth and blending.
    pub render: RenderDecl,
    /// `[instances]`: draw the mesh this many times, with per-instance attributes.
    pub instances: Option<InstancesDecl>,
    /// `[[passes]]` in manifest order (run in this order); empty for a single-pass effect.
    pub passes: Vec<PassDecl>,
    /// `[targets]` in manifest order.
    pub targets: Vec<TargetDecl>,
    /// `output`: the target written as the frame (multi-pass effects).
    pub output: Option<TargetRef>,
    /// `[knobs]`: uniforms `effectc bench` sweeps, in manifest order.
    pub knobs: Vec<KnobDecl>,
    /// Warnings found while reading the manifest (the effect is still usable).
    pub warnings: Vec<Diagnostic>,
}

impl Effect {
    pub fn stage(&self, kind: StageKind) -> Option<&StageRef> {
        self.stages.iter().find(|s| s.kind == kind)
    }
    pub fn uniform(&self, name: &str) -> Option<&UniformDefault> {
        self.uniforms.iter().find(|u| u.name == name)
    }
    pub fn texture(&self, name: &str) -> Option<&TextureDecl> {
        self.textures.iter().find(|t| t.name == name)
    }
}

/// One entry of `[stages]`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StageRef {
    pub kind: StageKind,
    /// `dir.join(<path in the manifest>)`.
    pub path: PathBuf,
    /// Span of the path string in the manifest.
    pub span: Range<usize>,
    /// Span of the stage key (`vertex`).
    pub key_span: Range<usize>,
}

/// One entry of `[uniforms]`.
#[derive(Debug, Clone, PartialEq)]
pub struct UniformDefault {
    /// The uniform's name as the shader declares it (`minBI`, `lights[0].color`).
    pub name: String,
    pub name_span: Range<usize>,
    /// The default value; `None` for a uniform bound to a semantic.
    pub value: Option<UniformValue>,
    /// Span of the value; for a table without `value`, the span of the whole table.
    pub value_span: Range<usize>,
    /// `range = [lo, hi]`, with `lo <= hi`, both finite.
    pub range: Option<(f64, f64)>,
    pub range_span: Option<Range<usize>>,
    pub semantic: Option<Semantic>,
    /// Span of the `semantic` string.
    pub semantic_span: Option<Range<usize>>,
}

/// A default value. Its GLSL type is resolved against the shader's declaration later: a
/// `vec3` is a `List` of 3 numbers; a `mat3` a `List` of 3 column `List`s of 3, or a flat
/// `List` of 9 (column-major); arrays are `List`s. Numbers are finite.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[serde(untagged)]
pub enum UniformValue {
    Bool(bool),
    Int(i64),
    Float(f64),
    List(Vec<UniformValue>),
}

impl UniformValue {
    /// The number as `f64`, for `Int` and `Float`.
    pub fn as_f64(&self) -> Option<f64> {
        match *self {
            UniformValue::Int(i) => Some(i as f64),
            UniformValue::Float(f) => Some(f),
            _ => None,
        }
    }
    /// Dimensions of nested lists, outermost first: `[]` for a scalar, `[3]` for
    /// `[1, 2, 3]`, `[3, 3]` for a mat3 written as columns. Lists are checked to be
    /// rectangular when parsed.
    pub fn dims(&self) -> Vec<usize> {
        let mut dims = Vec::new();
        let mut v = self;
        while let UniformValue::List(items) = v {
            dims.push(items.len());
            match items.first() {
                Some(first) => v = first,
                None => break,
            }
        }
        dims
    }
    /// All scalars in order (row of the flattened nested lists).
    pub fn scalars(&self) -> Vec<&UniformValue> {
        fn walk<'a>(v: &'a UniformValue, out: &mut Vec<&'a UniformValue>) {
            match v {
                UniformValue::List(items) => items.iter().for_each(|i| walk(i, out)),
                s => out.push(s),
            }
        }
        let mut out = Vec::new();
        walk(self, &mut out);
        out
    }
}

/// A value the runtime supplies every frame instead of a constant default.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Semantic {
    /// Seconds since start.
    Time,
    /// Frame index.
    Frame,
    /// Seconds since the previous frame.
    DeltaTime,
    /// Render target size in pixels (`vec3`: z = 1, like Shadertoy's `iResolution`).
    Resolution,
    Model,
    View,
    Projection,
    ModelView,
    ViewProjection,
    #[serde(rename = "mvp")]
    ModelViewProjection,
    /// Inverse-transpose of the model-view matrix.
    NormalMatrix,
    /// World-space camera position.
    CameraPosition,
    /// Pointer position in pixels (`vec4`: Shadertoy's `iMouse` layout).
    Mouse,
}

impl Semantic {
    pub const ALL: [Semantic; 13] = [
        Semantic::Time,
        Semantic::Frame,
        Semantic::DeltaTime,
        Semantic::Resolution,
        Semantic::Model,
        Semantic::View,
        Semantic::Projection,
        Semantic::ModelView,
        Semantic::ViewProjection,
        Semantic::ModelViewProjection,
        Semantic::NormalMatrix,
        Semantic::CameraPosition,
        Semantic::Mouse,
    ];

    /// The name used in manifests.
    pub fn name(&self) -> &'static str {
        match self {
            Semantic::Time => "time",
            Semantic::Frame => "frame",
            Semantic::DeltaTime => "delta_time",
            Semantic::Resolution => "resolution",
            Semantic::Model => "model",
            Semantic::View => "view",
            Semantic::Projection => "projection",
            Semantic::ModelView => "model_view",
            Semantic::ViewProjection => "view_projection",
            Semantic::ModelViewProjection => "mvp",
            Semantic::NormalMatrix => "normal_matrix",
            Semantic::CameraPosition => "camera_position",
            Semantic::Mouse => "mouse",
        }
    }

    /// Parse a manifest name (including the alias `model_view_projection`).
    pub fn from_name(name: &str) -> Option<Semantic> {
        if name == "model_view_projection" {
            return Some(Semantic::ModelViewProjection);
        }
        Semantic::ALL.into_iter().find(|s| s.name() == name)
    }

    /// The GLSL types a uniform bound to this semantic may be declared with.
    pub fn glsl_types(&self) -> &'static [&'static str] {
        match self {
            Semantic::Time | Semantic::DeltaTime => &["float"],
            Semantic::Frame => &["int", "uint", "float"],
            Semantic::Resolution => &["vec2", "vec3"],
            Semantic::Model
            | Semantic::View
            | Semantic::Projection
            | Semantic::ModelView
            | Semantic::ViewProjection
            | Semantic::ModelViewProjection => &["mat4"],
            Semantic::NormalMatrix => &["mat3", "mat4"],
            Semantic::CameraPosition => &["vec3", "vec4"],
            Semantic::Mouse => &["vec2", "vec4"],
        }
    }
}

/// One entry of `[textures]`: the image bound to a sampler uniform.
#[derive(Debug, Clone, PartialEq)]
pub struct TextureDecl {
    /// The sampler uniform it binds.
    pub name: String,
    pub name_span: Range<usize>,
    pub kind: TextureKind,
    pub source: TextureSource,
    /// Span of the whole entry's value (string or table).
    pub span: Range<usize>,
    pub filter: Filter,
    pub wrap: Wrap,
}

/// The sampler dimensionality a texture provides.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TextureKind {
    /// `sampler2D`.
    D2,
    /// `samplerCube`.
    Cube,
}

impl TextureKind {
    pub fn name(self) -> &'static str {
        match self {
            TextureKind::D2 => "2d",
            TextureKind::Cube => "cube",
        }
    }
    /// The GLSL sampler type that matches.
    pub fn glsl_sampler(self) -> &'static str {
        match self {
            TextureKind::D2 => "sampler2D",
            TextureKind::Cube => "samplerCube",
        }
    }
}

/// Where a texture's pixels come from. Paths are resolved against the manifest directory.
#[derive(Debug, Clone, PartialEq)]
pub enum TextureSource {
    File(PathBuf),
    /// A cube map from six images, in the order +x −x +y −y +z −z.
    Faces([PathBuf; 6]),
    /// A procedural texture (`size`×`size`; for a cube, each face).
    Generated {
        generator: Generator,
        size: u32,
        params: GeneratorParams,
    },
}

/// Procedural texture generators.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Generator {
    /// `cells`×`cells` squares alternating `colors[0]` / `colors[1]`.
    Checker,
    /// Horizontal ramp from `colors[0]` (u = 0) to `colors[1]` (u = 1).
    Gradient,
    /// Tileable value noise: `cells` lattice cells per side at the first octave, `octaves`
    /// octaves (each doubling the frequency, halving the amplitude), `seed`; mapped from
    /// `colors[0]` (0) to `colors[1]` (1).
    Noise,
    /// Every texel `colors[0]`.
    Solid,
}

impl Generator {
    pub const ALL: [Generator; 4] = [Generator::Checker, Generator::Gradient, Generator::Noise, Generator::Solid];
    pub fn name(self) -> &'static str {
        match self {
            Generator::Checker => "checker",
            Generator::Gradient => "gradient",
            Generator::Noise => "noise",
            Generator::Solid => "solid",
        }
    }
    /// The parameter keys (besides `size`) this generator reads.
    pub fn params(self) -> &'static [&'static str] {
        match self {
            Generator::Checker => &["colors", "cells"],
            Generator::Gradient => &["colors"],
            Generator::Noise => &["colors", "cells", "seed", "octaves"],
            Generator::Solid => &["colors"],
        }
    }
}

/// Parameters of a generated texture; keys a generator does not use keep their defaults.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GeneratorParams {
    /// Linear RGBA colours a and b. Default: white `[1,1,1,1]` and black `[0,0,0,1]`.
    pub colors: [[f32; 4]; 2],
    /// Checker squares / noise lattice cells per side. Default 8.
    pub cells: u32,
    /// Noise seed. Default 0.
    pub seed: u32,
    /// Noise octaves. Default 4.
    pub octaves: u32,
}

impl Default for GeneratorParams {
    fn default() -> Self {
        GeneratorParams { colors: [[1.0, 1.0, 1.0, 1.0], [0.0, 0.0, 0.0, 1.0]], cells: 8, seed: 0, octaves: 4 }
    }
}

/// Default size of a generated texture.
pub const DEFAULT_TEXTURE_SIZE: u32 = 256;
/// Largest accepted generated texture size.
pub const MAX_TEXTURE_SIZE: u32 = 8192;

/// Texture filtering (minification and magnification).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Filter {
    #[default]
    Linear,
    Nearest,
}

/// Texture addressing mode, for all coordinates.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Wrap {
    #[default]
    Repeat,
    Clamp,
    Mirror,
}

/// `[mesh]`: what the effect is drawn on.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshDecl {
    /// Span of the `[mesh]` header / inline table / string.
    pub span: Range<usize>,
    pub source: MeshSource,
    /// Optional explicit mapping: (shader input name, mesh attribute), in manifest order.
    /// Mesh attributes are the names in [`MESH_ATTRIBUTES`].
    pub attributes: Vec<(String, String)>,
    /// Spans of the shader input names in `attributes`, index for index.
    pub attribute_spans: Vec<Range<usize>>,
}

/// The attributes a mesh provides.
pub const MESH_ATTRIBUTES: &[&str] = &["position", "normal", "uv", "tangent", "color"];

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

/// `[camera]`: a look-at camera with a perspective projection, optionally moved by keyframes.
#[derive(Debug, Clone, PartialEq)]
pub struct CameraDecl {
    pub span: Range<usize>,
    pub eye: [f32; 3],
    pub target: [f32; 3],
    pub up: [f32; 3],
    /// Vertical field of view in degrees (0, 180).
    pub fov: f32,
    pub near: f32,
    pub far: f32,
    /// Keyframes in increasing time; empty for a still camera.
    pub keys: Vec<CameraKey>,
    pub ease: Ease,
}

impl Default for CameraDecl {
    fn default() -> Self {
        CameraDecl {
            span: 0..0,
            eye: [1.8, 1.4, 2.6],
            target: [0.0, 0.0, 0.0],
            up: [0.0, 1.0, 0.0],
            fov: 45.0,
            near: 0.1,
            far: 100.0,
            keys: Vec::new(),
            ease: Ease::Linear,
        }
    }
}

/// One camera keyframe: where the camera is and looks at `time` seconds.
#[derive(Debug, Clone, PartialEq)]
pub struct CameraKey {
    pub time: f64,
    pub eye: [f32; 3],
    pub target: [f32; 3],
}

/// How the camera moves between keyframes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Ease {
    /// Constant speed (the seed's `naive_lerp`).
    #[default]
    Linear,
    /// Smoothstep: starts and stops gently at every key.
    Smooth,
}

/// `[model]`: scale, then rotation (degrees about x, y, z, plus `spin` degrees per second),
/// then translation.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelDecl {
    pub translate: [f32; 3],
    pub rotate: [f32; 3],
    pub scale: [f32; 3],
    pub spin: [f32; 3],
}

impl Default for ModelDecl {
    fn default() -> Self {
        ModelDecl { translate: [0.0; 3], rotate: [0.0; 3], scale: [1.0; 3], spin: [0.0; 3] }
    }
}

/// `[render]`: defaults for `effectc render` (flags override them) and fixed pipeline state.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderDecl {
    pub size: Option<(u32, u32)>,
    pub frames: Option<u32>,
    pub fps: Option<f64>,
    /// Linear RGBA clear colour; default opaque black.
    pub clear: [f32; 4],
    pub cull: Cull,
    /// Depth test (less) with a depth buffer; default on.
    pub depth_test: bool,
    /// Depth writes when the depth test is on; default on (off for see-through layers).
    pub depth_write: bool,
    /// The depth test's comparison (`glDepthFunc`); default `less`, as GL's.
    pub depth_compare: DepthCompare,
    pub blend: Blend,
}

/// One `[knobs]` entry: a quality knob (a `[uniforms]` entry) and the values to sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct KnobDecl {
    /// The uniform's name (an entry of `[uniforms]`).
    pub name: String,
    pub name_span: Range<usize>,
    /// Values to sweep, in manifest order.
    pub values: Vec<f64>,
    /// The most accurate value, which the others are compared with (one of `values`).
    pub reference: f64,
}

/// `glDepthFunc`: when a fragment passes the depth test.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum DepthCompare {
    Never,
    #[default]
    Less,
    Equal,
    /// `GL_LEQUAL`: the skybox trick (`gl_Position = pos.xyww` lands on the cleared depth 1.0).
    LessEqual,
    Greater,
    NotEqual,
    GreaterEqual,
    Always,
}

impl DepthCompare {
    /// Manifest names, in GL's order.
    pub const CHOICES: &'static [(&'static str, DepthCompare)] = &[
        ("never", DepthCompare::Never),
        ("less", DepthCompare::Less),
        ("equal", DepthCompare::Equal),
        ("lequal", DepthCompare::LessEqual),
        ("greater", DepthCompare::Greater),
        ("notequal", DepthCompare::NotEqual),
        ("gequal", DepthCompare::GreaterEqual),
        ("always", DepthCompare::Always),
    ];
}

impl Default for RenderDecl {
    fn default() -> Self {
        RenderDecl {
            size: None,
            frames: None,
            fps: None,
            clear: [0.0, 0.0, 0.0, 1.0],
            cull: Cull::None,
            depth_test: true,
            depth_write: true,
            depth_compare: DepthCompare::Less,
            blend: Blend::None,
        }
    }
}

/// How fragment colours combine with the target.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Blend {
    /// Replace.
    #[default]
    None,
    /// `src.rgb * src.a + dst.rgb * (1 - src.a)` (glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA)).
    Alpha,
    /// `src.rgb * src.a + dst.rgb` (glBlendFunc(GL_SRC_ALPHA, GL_ONE)).
    Additive,
    /// `src.rgb + dst.rgb * (1 - src.a)` (premultiplied alpha).
    Premultiplied,
}

/// `[instances]`: instanced drawing (one draw call, `count` instances).
#[derive(Debug, Clone, PartialEq)]
pub struct InstancesDecl {
    pub span: Range<usize>,
    /// 1–1 000 000.
    pub count: u32,
    /// Per-instance vertex inputs, in manifest order.
    pub attributes: Vec<InstanceAttribute>,
}

/// One per-instance vertex input and where its values come from.
#[derive(Debug, Clone, PartialEq)]
pub struct InstanceAttribute {
    /// The vertex shader input it feeds.
    pub input: String,
    pub input_span: Range<usize>,
    pub source: InstanceSource,
    /// Components per instance (1–4).
    pub components: usize,
}

/// Where per-instance values come from.
#[derive(Debug, Clone, PartialEq)]
pub enum InstanceSource {
    /// Exactly `count` values (each 1–4 numbers).
    Values(Vec<[f32; 4]>),
    /// Uniformly random in the box `[lo, hi]` per component, from `seed` (deterministic).
    Random { lo: [f32; 4], hi: [f32; 4], seed: u32 },
    /// `start + i × step` for instance `i`.
    Sequence { start: [f32; 4], step: [f32; 4] },
}

/// Most instances `[instances] count` accepts.
pub const MAX_INSTANCES: u32 = 1_000_000;

/// Which faces are culled (counter-clockwise is front, as in OpenGL).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Cull {
    #[default]
    None,
    Back,
    Front,
}

/// Largest frame side `[render] size` and `--size` accept.
pub const MAX_FRAME_SIDE: u32 = 8192;
/// Most frames `[render] frames` and `--frames` accept.
pub const MAX_FRAMES: u32 = 100_000;

/// Read `path`, register its text in `files` and parse it. Relative paths in the manifest are
/// resolved against the manifest's directory. An unreadable file gives one [`E_IO`]
/// diagnostic (see [`is_io_error`]).
/// Parses manifest text (for other modules' unit tests; files are looked up in `dir`).
#[cfg(test)]
pub(crate) fn parse_for_tests(text: &str, file: FileId, dir: &Path) -> Result<Effect, Vec<Diagnostic>> {
    parse::parse(text, file, dir)
}

pub fn load(path: &Path, files: &mut Files) -> Result<Effect, Vec<Diagnostic>> {
    let shown = path.display().to_string();
    let bytes = match std::fs::read(path) {
        Ok(bytes) => bytes,
        Err(err) => {
            let id = files.add(shown.clone(), String::new());
            return Err(vec![Diagnostic::error(E_IO, format!("cannot read manifest `{shown}`: {err}")).in_file(id)]);
        }
    };
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    match String::from_utf8(bytes) {
        Ok(text) => {
            let id = files.add(shown, text);
            parse(files.text(id), id, &dir)
        }
        Err(err) => {
            let at = err.utf8_error().valid_up_to();
            let text = String::from_utf8_lossy(err.as_bytes()).into_owned();
            let id = files.add(shown, text);
            let d = Diagnostic::error(E_SYNTAX, "the manifest is not valid UTF-8")
                .at(id, at..at + '\u{FFFD}'.len_utf8(), "invalid UTF-8 here")
                .with_help("save effect.toml as UTF-8 text");
            Err(vec![d])
        }
    }
}

/// Parse manifest text registered as `file`. `dir` is the manifest's directory: stage,
/// texture and mesh paths are joined to it and checked for existence, and it provides the
/// default effect name. On failure the diagnostics hold every error found (and warnings).
pub fn parse(text: &str, file: FileId, dir: &Path) -> Result<Effect, Vec<Diagnostic>> {
    parse::parse(text, file, dir)
}

/// The closest candidate to `word` (case-insensitive, `-` read as `_`), if any is close enough.
pub fn did_you_mean<'a>(word: &str, candidates: &[&'a str]) -> Option<&'a str> {
    let norm = |s: &str| s.to_ascii_lowercase().replace('-', "_");
    let w = norm(word);
    if w.is_empty() {
        return None;
    }
    candidates
        .iter()
        .copied()
        .map(|c| {
            let n = norm(c);
            let score = if n == w { 2.0 } else { strsim::jaro_winkler(&w, &n) };
            (c, score)
        })
        .filter(|&(_, s)| s >= 0.8)
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(c, _)| c)
}
