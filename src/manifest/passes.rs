//! The multi-pass part of a manifest: `[targets]`, `[[passes]]` and `output`.
//!
//! A multi-pass effect has no top-level `[stages]`; each pass names its own stages (or
//! reuses another effect's) and inherits the top-level uniforms, textures, mesh, camera and
//! render state. [`Effect::pass_view`] turns one pass into the single-pass [`Effect`] that
//! check, translate and render already understand.

use std::ops::Range;
use std::path::PathBuf;

use super::{Blend, Cull, Effect, Filter, InstancesDecl, MeshDecl, ModelDecl, StageRef, UniformDefault};

/// One `[targets]` entry: a named render target.
#[derive(Debug, Clone, PartialEq)]
pub struct TargetDecl {
    pub name: String,
    pub name_span: Range<usize>,
    pub format: TargetFormat,
    pub size: TargetSize,
}

/// How big a target is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TargetSize {
    /// A factor of the output size (`scale = 0.5`), at least one pixel per side.
    Scale(f32),
    /// `size = [w, h]`.
    Absolute(u32, u32),
}

impl TargetSize {
    /// The size in pixels for an output of `output` pixels.
    pub fn resolve(self, output: (u32, u32)) -> (u32, u32) {
        match self {
            TargetSize::Scale(s) => {
                let side = |n: u32| ((n as f32 * s).round() as u32).max(1);
                (side(output.0), side(output.1))
            }
            TargetSize::Absolute(w, h) => (w, h),
        }
    }
}

/// What a target's texels are, as GLSL samplers see them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SampleKind {
    /// `sampler2D` (float and normalised formats).
    Float,
    /// `isampler2D`.
    Sint,
    /// `usampler2D`.
    Uint,
    /// A depth target (attached with `depth = …`, not sampled).
    Depth,
}

impl SampleKind {
    /// The GLSL sampler type that reads this kind.
    pub fn sampler(self) -> &'static str {
        match self {
            SampleKind::Float => "sampler2D",
            SampleKind::Sint => "isampler2D",
            SampleKind::Uint => "usampler2D",
            SampleKind::Depth => "sampler2DShadow",
        }
    }
    /// What a fragment output written to this kind must be made of.
    pub fn output_scalar(self) -> &'static str {
        match self {
            SampleKind::Float | SampleKind::Depth => "float",
            SampleKind::Sint => "int",
            SampleKind::Uint => "uint",
        }
    }
}

macro_rules! formats {
    ($($variant:ident $name:literal $kind:ident $components:literal $wgpu:ident,)*) => {
        /// A render target format, by its manifest name.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        pub enum TargetFormat { $($variant,)* }

        impl TargetFormat {
            pub const ALL: &'static [TargetFormat] = &[$(TargetFormat::$variant,)*];
            pub fn name(self) -> &'static str {
                match self { $(TargetFormat::$variant => $name,)* }
            }
            pub fn kind(self) -> SampleKind {
                match self { $(TargetFormat::$variant => SampleKind::$kind,)* }
            }
            /// Colour components stored (1–4; 1 for depth).
            pub fn components(self) -> u32 {
                match self { $(TargetFormat::$variant => $components,)* }
            }
            pub fn wgpu(self) -> wgpu::TextureFormat {
                match self { $(TargetFormat::$variant => wgpu::TextureFormat::$wgpu,)* }
            }
        }
    };
}

formats! {
    Rgba8 "rgba8" Float 4 Rgba8Unorm,
    Rgba16f "rgba16f" Float 4 Rgba16Float,
    Rgba32f "rgba32f" Float 4 Rgba32Float,
    R16f "r16f" Float 1 R16Float,
    R32f "r32f" Float 1 R32Float,
    Rg16f "rg16f" Float 2 Rg16Float,
    Rg32f "rg32f" Float 2 Rg32Float,
    Rgba32i "rgba32i" Sint 4 Rgba32Sint,
    Rgba32ui "rgba32ui" Uint 4 Rgba32Uint,
    R32i "r32i" Sint 1 R32Sint,
    R32ui "r32ui" Uint 1 R32Uint,
    Depth32f "depth32f" Depth 1 Depth32Float,
}

impl TargetFormat {
    pub fn from_name(name: &str) -> Option<TargetFormat> {
        Self::ALL.iter().copied().find(|f| f.name() == name)
    }
}

/// A target named in a pass (`targets`, `depth`, `samples`) or as `output`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TargetRef {
    pub name: String,
    pub span: Range<usize>,
}

/// One `samples` entry: a sampler uniform reading an earlier pass's target.
#[derive(Debug, Clone, PartialEq)]
pub struct SampleDecl {
    pub sampler: String,
    pub sampler_span: Range<usize>,
    pub target: TargetRef,
    pub filter: Filter,
}

/// What a pass draws.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum PassDraw {
    /// The pass's mesh (or the effect's).
    #[default]
    Mesh,
    /// One triangle covering the target.
    Fullscreen,
}

/// How a pass starts.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum PassClear {
    /// `[render] clear`, depth 1.0.
    #[default]
    Default,
    /// `clear = [r, g, b, a]`, depth 1.0.
    Color([f32; 4]),
    /// `clear = false`: keep what earlier passes wrote (colour and depth).
    Keep,
}

/// One `[[passes]]` entry.
#[derive(Debug, Clone, PartialEq)]
pub struct PassDecl {
    pub name: String,
    /// Span of the `name` value (or of the pass table without one).
    pub name_span: Range<usize>,
    /// Span of the whole pass table.
    pub span: Range<usize>,
    pub stages: Vec<StageRef>,
    /// `effect = "../sun"`: the manifest whose stages, uniforms, textures and mesh this pass uses.
    pub reuse: Option<(PathBuf, Range<usize>)>,
    pub draw: PassDraw,
    pub mesh: Option<MeshDecl>,
    pub instances: Option<InstancesDecl>,
    pub model: Option<ModelDecl>,
    /// Per-pass uniform values (override the top-level ones).
    pub uniforms: Vec<UniformDefault>,
    /// Colour targets by output location.
    pub targets: Vec<TargetRef>,
    pub targets_span: Option<Range<usize>>,
    pub depth: Option<TargetRef>,
    pub samples: Vec<SampleDecl>,
    pub blend: Option<Blend>,
    pub cull: Option<Cull>,
    pub depth_write: Option<bool>,
    pub depth_compare: Option<super::DepthCompare>,
    pub clear: PassClear,
}

impl PassDecl {
    /// Whether the pass writes `target` (as a colour or the depth attachment).
    pub fn writes(&self, target: &str) -> bool {
        self.targets.iter().any(|t| t.name == target) || self.depth.as_ref().is_some_and(|d| d.name == target)
    }
}

impl Effect {
    /// True for an effect made of `[[passes]]`.
    pub fn is_multi_pass(&self) -> bool {
        !self.passes.is_empty()
    }

    pub fn target(&self, name: &str) -> Option<&TargetDecl> {
        self.targets.iter().find(|t| t.name == name)
    }

    /// The single-pass effect one pass amounts to: the pass's stages with the top-level
    /// uniforms, textures, mesh, camera and render state, overridden by the pass's own.
    /// A pass that reuses another effect gets `reused` (that effect, already loaded) instead
    /// of the top-level defaults: its spans point into its own manifest.
    pub fn pass_view(&self, pass: &PassDecl, reused: Option<&Effect>) -> Effect {
        let mut view = match reused {
            Some(r) => Effect { camera: self.camera.clone().or_else(|| r.camera.clone()), ..r.clone() },
            None => Effect { stages: pass.stages.clone(), passes: Vec::new(), targets: Vec::new(), output: None, ..self.clone() },
        };
        view.name = format!("{}.{}", self.name, pass.name);
        view.warnings = Vec::new();
        view.render.size = self.render.size;
        view.render.frames = self.render.frames;
        view.render.fps = self.render.fps;
        for u in &pass.uniforms {
            view.uniforms.retain(|v| v.name != u.name);
            view.uniforms.push(u.clone());
        }
        if pass.draw == PassDraw::Fullscreen {
            view.mesh = Some(MeshDecl {
                span: pass.name_span.clone(),
                source: super::MeshSource::Builtin(super::BuiltinMesh::FullscreenTriangle),
                attributes: pass.mesh.as_ref().map(|m| m.attributes.clone()).unwrap_or_default(),
                attribute_spans: pass.mesh.as_ref().map(|m| m.attribute_spans.clone()).unwrap_or_default(),
                values: pass.mesh.as_ref().map(|m| m.values.clone()).unwrap_or_default(),
            });
            view.render.depth_test = false;
        } else if let Some(m) = &pass.mesh {
            view.mesh = Some(m.clone());
        }
        if let Some(i) = &pass.instances {
            view.instances = Some(i.clone());
        }
        if let Some(m) = &pass.model {
            view.model = m.clone();
        }
        if let Some(b) = pass.blend {
            view.render.blend = b;
        }
        if let Some(c) = pass.cull {
            view.render.cull = c;
        }
        if let Some(w) = pass.depth_write {
            view.render.depth_write = w;
        }
        if let Some(c) = pass.depth_compare {
            view.render.depth_compare = c;
        }
        if pass.depth.is_some() {
            view.render.depth_test = true;
        }
        if let PassClear::Color(c) = pass.clear {
            view.render.clear = c;
        }
        view
    }
}
