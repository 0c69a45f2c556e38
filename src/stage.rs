//! Shader stages: what they are called in manifests, file extensions and naga.

use std::fmt;

/// A programmable pipeline stage, in pipeline order.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum StageKind {
    Vertex,
    TessControl,
    TessEval,
    Geometry,
    Fragment,
    Compute,
}

impl StageKind {
    pub const ALL: [StageKind; 6] =
        [StageKind::Vertex, StageKind::TessControl, StageKind::TessEval, StageKind::Geometry, StageKind::Fragment, StageKind::Compute];

    /// The manifest key / `--stage` value.
    pub fn name(self) -> &'static str {
        match self {
            StageKind::Vertex => "vertex",
            StageKind::TessControl => "tess_control",
            StageKind::TessEval => "tess_eval",
            StageKind::Geometry => "geometry",
            StageKind::Fragment => "fragment",
            StageKind::Compute => "compute",
        }
    }

    /// Short name used in generated identifiers and file names (`vert`, `frag`, …).
    pub fn short_name(self) -> &'static str {
        match self {
            StageKind::Vertex => "vert",
            StageKind::TessControl => "tesc",
            StageKind::TessEval => "tese",
            StageKind::Geometry => "geom",
            StageKind::Fragment => "frag",
            StageKind::Compute => "comp",
        }
    }

    pub fn from_name(name: &str) -> Option<StageKind> {
        StageKind::ALL.into_iter().find(|s| s.name() == name)
    }

    /// Stage implied by a file extension (`.vert .vs .vsh .frag .fs .fsh .geom .gs …`).
    pub fn from_extension(ext: &str) -> Option<StageKind> {
        match ext.to_ascii_lowercase().as_str() {
            "vert" | "vs" | "vsh" | "vshader" | "vertex" => Some(StageKind::Vertex),
            "frag" | "fs" | "fsh" | "fshader" | "fragment" => Some(StageKind::Fragment),
            "geom" | "gs" | "gsh" | "geometry" => Some(StageKind::Geometry),
            "tesc" => Some(StageKind::TessControl),
            "tese" => Some(StageKind::TessEval),
            "comp" | "cs" => Some(StageKind::Compute),
            _ => None,
        }
    }

    /// The naga stage, for the stages naga can parse.
    pub fn naga(self) -> Option<naga::ShaderStage> {
        match self {
            StageKind::Vertex => Some(naga::ShaderStage::Vertex),
            StageKind::Fragment => Some(naga::ShaderStage::Fragment),
            StageKind::Compute => Some(naga::ShaderStage::Compute),
            _ => None,
        }
    }
}

impl fmt::Display for StageKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
