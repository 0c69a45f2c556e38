//! [`Effect`], the parsed manifest as a whole, and [`StageRef`], one entry of `[stages]`.

use std::ops::Range;
use std::path::PathBuf;

use super::{
    CameraDecl, InstancesDecl, KnobDecl, MeshDecl, ModelDecl, PassDecl, RenderDecl, TargetDecl, TargetRef, TextureDecl, UniformDefault,
    VerifyDecl,
};
use crate::diag::{Diagnostic, FileId};
use crate::stage::StageKind;

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
    /// `[verify]`: the tolerance of `effectc verify`.
    pub verify: VerifyDecl,
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
    /// Macros defined for this stage (`{ file = "x.glsl", define = { VERTEX = 1 } }`).
    pub defines: Vec<crate::stage::Define>,
}
