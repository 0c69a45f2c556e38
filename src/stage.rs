//! Shader stages: what they are called in manifests, file extensions and naga; macros
//! defined for a stage from outside its text (`--define`, a manifest's `define`).

use std::fmt;

/// A programmable pipeline stage, in pipeline order; `--stage` takes its kebab-case name
/// (`tess-control`, `ray-generation`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize, serde::Deserialize, clap::ValueEnum)]
#[serde(rename_all = "snake_case")]
pub enum StageKind {
    Vertex,
    TessControl,
    TessEval,
    Geometry,
    Task,
    Mesh,
    Fragment,
    Compute,
    RayGeneration,
    Intersection,
    AnyHit,
    ClosestHit,
    Miss,
    Callable,
}

impl StageKind {
    pub const ALL: [StageKind; 14] = [
        StageKind::Vertex,
        StageKind::TessControl,
        StageKind::TessEval,
        StageKind::Geometry,
        StageKind::Task,
        StageKind::Mesh,
        StageKind::Fragment,
        StageKind::Compute,
        StageKind::RayGeneration,
        StageKind::Intersection,
        StageKind::AnyHit,
        StageKind::ClosestHit,
        StageKind::Miss,
        StageKind::Callable,
    ];

    /// How the user calls a stage in prose.
    pub fn title(self) -> &'static str {
        match self {
            StageKind::Vertex => "vertex",
            StageKind::TessControl => "tessellation control",
            StageKind::TessEval => "tessellation evaluation",
            StageKind::Geometry => "geometry",
            StageKind::Fragment => "fragment",
            StageKind::Compute => "compute",
            StageKind::Task => "task",
            StageKind::Mesh => "mesh",
            StageKind::RayGeneration => "ray generation",
            StageKind::Intersection => "intersection",
            StageKind::AnyHit => "any-hit",
            StageKind::ClosestHit => "closest-hit",
            StageKind::Miss => "miss",
            StageKind::Callable => "callable",
        }
    }

    /// The manifest key / `--stage` value.
    pub fn name(self) -> &'static str {
        match self {
            StageKind::Vertex => "vertex",
            StageKind::TessControl => "tess_control",
            StageKind::TessEval => "tess_eval",
            StageKind::Geometry => "geometry",
            StageKind::Task => "task",
            StageKind::Mesh => "mesh",
            StageKind::Fragment => "fragment",
            StageKind::Compute => "compute",
            StageKind::RayGeneration => "ray_generation",
            StageKind::Intersection => "intersection",
            StageKind::AnyHit => "any_hit",
            StageKind::ClosestHit => "closest_hit",
            StageKind::Miss => "miss",
            StageKind::Callable => "callable",
        }
    }

    /// Short name used in generated identifiers and file names (`vert`, `frag`, …).
    pub fn short_name(self) -> &'static str {
        match self {
            StageKind::Vertex => "vert",
            StageKind::TessControl => "tesc",
            StageKind::TessEval => "tese",
            StageKind::Geometry => "geom",
            StageKind::Task => "task",
            StageKind::Mesh => "mesh",
            StageKind::Fragment => "frag",
            StageKind::Compute => "comp",
            StageKind::RayGeneration => "rgen",
            StageKind::Intersection => "rint",
            StageKind::AnyHit => "rahit",
            StageKind::ClosestHit => "rchit",
            StageKind::Miss => "rmiss",
            StageKind::Callable => "rcall",
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
            "task" => Some(StageKind::Task),
            "mesh" => Some(StageKind::Mesh),
            "rgen" => Some(StageKind::RayGeneration),
            "rint" => Some(StageKind::Intersection),
            "rahit" => Some(StageKind::AnyHit),
            "rchit" => Some(StageKind::ClosestHit),
            "rmiss" => Some(StageKind::Miss),
            "rcall" => Some(StageKind::Callable),
            _ => None,
        }
    }

    /// A stage of a pipeline WebGPU has no counterpart of and effectc's own analysis does
    /// not model (mesh shading, ray tracing): checked by the reference compiler only.
    pub fn reference_only(self) -> bool {
        matches!(
            self,
            StageKind::Task
                | StageKind::Mesh
                | StageKind::RayGeneration
                | StageKind::Intersection
                | StageKind::AnyHit
                | StageKind::ClosestHit
                | StageKind::Miss
                | StageKind::Callable
        )
    }

    /// Stages only Vulkan GLSL has (glslang compiles ray-tracing stages for SPIR-V only).
    pub fn vulkan_only(self) -> bool {
        matches!(
            self,
            StageKind::RayGeneration
                | StageKind::Intersection
                | StageKind::AnyHit
                | StageKind::ClosestHit
                | StageKind::Miss
                | StageKind::Callable
        )
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

/// One macro: its name and its replacement text (`1` when none was given).
pub type Define = (String, String);

/// `NAME` or `NAME=VALUE` as typed; why not, when the name is no macro name GLSL allows.
pub fn parse_define(typed: &str) -> Result<Define, String> {
    let (name, value) = typed.split_once('=').map_or((typed, "1"), |(n, v)| (n, v));
    let name = name.trim();
    let identifier = name.chars().next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !identifier {
        return Err(format!("`{name}` is not a macro name (letters, digits and `_`, not starting with a digit)"));
    }
    if name.starts_with("GL_") || name.contains("__") {
        return Err(format!("`{name}` is reserved: GLSL keeps names starting with `GL_` or holding `__` for itself"));
    }
    if value.contains('\n') {
        return Err(format!("the value of `{name}` spans lines"));
    }
    Ok((name.to_string(), value.trim().to_string()))
}

/// A macro written in TOML (`define = { NAME = VALUE }` in a manifest or `effectc.toml`):
/// a string, number or boolean value, as its text; why not otherwise.
pub fn define_from_toml(name: &str, value: &toml::de::DeValue<'_>) -> Result<Define, String> {
    use toml::de::DeValue;
    let text = match value {
        DeValue::String(s) => s.to_string(),
        DeValue::Integer(i) => i.as_str().to_string(),
        DeValue::Float(f) => f.as_str().to_string(),
        DeValue::Boolean(b) => b.to_string(),
        _ => return Err(format!("`{name}` must be a string, number or boolean")),
    };
    parse_define(&format!("{name}={text}"))
}

impl fmt::Display for StageKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn macros_are_parsed_as_typed_and_reserved_names_refused() {
        assert_eq!(parse_define("VERTEX"), Ok(("VERTEX".into(), "1".into())));
        assert_eq!(parse_define("QUALITY=3"), Ok(("QUALITY".into(), "3".into())));
        assert_eq!(parse_define("TINT=vec3(1.0, 0.5, 0.0)"), Ok(("TINT".into(), "vec3(1.0, 0.5, 0.0)".into())));
        assert!(
            parse_define("3D").is_err() && parse_define("GL_FOO").is_err() && parse_define("A__B").is_err() && parse_define("").is_err()
        );
    }
}
