//! Command-line definitions (clap derive) — every flag and its documentation, in one place.

use std::path::PathBuf;

use clap::{Parser, Subcommand, ValueEnum};

use crate::stage::StageKind;

/// effectc: check, translate and render desktop-GLSL effects.
#[derive(Debug, Parser)]
#[command(name = "effectc", version, about)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Check effects and GLSL programs: syntax, naga validation, OpenGL link rules, manifest.
    Check(CheckArgs),
}

/// Output format for diagnostics.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// codespan-style text with source snippets.
    Human,
    /// A stable JSON document (schema in the README).
    Json,
    /// GitHub Actions workflow commands (`::error file=…`).
    Github,
    /// SARIF 2.1.0 for code scanning.
    Sarif,
}

/// When to colour human output.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ColorChoice {
    Auto,
    Always,
    Never,
}

/// Stage names accepted by `--stage`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum StageArg {
    Vertex,
    Fragment,
    Geometry,
    TessControl,
    TessEval,
    Compute,
}

impl From<StageArg> for StageKind {
    fn from(s: StageArg) -> StageKind {
        match s {
            StageArg::Vertex => StageKind::Vertex,
            StageArg::Fragment => StageKind::Fragment,
            StageArg::Geometry => StageKind::Geometry,
            StageArg::TessControl => StageKind::TessControl,
            StageArg::TessEval => StageKind::TessEval,
            StageArg::Compute => StageKind::Compute,
        }
    }
}

#[derive(Debug, clap::Args)]
pub struct CheckArgs {
    /// Manifests (effect.toml), directories (searched for effect.toml and stage files), or
    /// stage files (.vert .vs .vsh .frag .fs .fsh .geom .gs; named together = one program).
    #[arg(required = true)]
    pub inputs: Vec<PathBuf>,
    /// Stage of stage files whose extension does not tell it.
    #[arg(long, value_enum)]
    pub stage: Option<StageArg>,
    /// Diagnostic output format.
    #[arg(long, value_enum, default_value = "human")]
    pub format: Format,
    /// Constructs the file's own `#version` forbids (e.g. `texture2D` in 4.20 core) are errors.
    #[arg(long)]
    pub strict: bool,
    /// Exit with 1 when there are warnings.
    #[arg(long)]
    pub deny_warnings: bool,
    /// Colour for human output.
    #[arg(long, value_enum, default_value = "auto")]
    pub color: ColorChoice,
}
