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
    /// Check, then translate to WGSL, SPIR-V, GLSL ES, MSL, HLSL, reflection JSON or IR text.
    Translate(TranslateArgs),
    /// Check, translate to WGSL and render frames headlessly with wgpu (PNG, contact sheet, GIF).
    Render(RenderArgs),
    /// Sweep quality knobs: GPU ms/frame against the error from the reference value's frames.
    Bench(BenchArgs),
    /// Render into float targets at the ends and random points of the uniform ranges and at
    /// extreme times; count NaN/Inf pixels per case.
    Stress(StressArgs),
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

/// Output targets of `translate`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TargetArg {
    /// `<effect>.wgsl`: one module with `vs_main` and `fs_main`.
    Wgsl,
    /// `<effect>.vert.spv`, `<effect>.frag.spv`: one SPIR-V 1.0 binary per stage.
    Spv,
    /// `<effect>.vert.spvasm`, `<effect>.frag.spvasm`: SPIR-V disassembly.
    Spvasm,
    /// `<effect>.vert.glsl`, `<effect>.frag.glsl`: GLSL ES 3.00 (WebGL2).
    Glsl,
    /// `<effect>.metal`: Metal Shading Language 2.0.
    Msl,
    /// `<effect>.hlsl`: HLSL shader model 5.1.
    Hlsl,
    /// `<effect>.reflect.json`: bindings, uniform block layout, interface (schema in the README).
    Reflect,
    /// `<effect>.ir.txt`: the translated naga IR as text.
    Ir,
    /// Every target above.
    All,
}

/// Options shared by every subcommand that reads programs and prints diagnostics.
#[derive(Debug, clap::Args)]
pub struct CommonArgs {
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
    /// Colour for human output.
    #[arg(long, value_enum, default_value = "auto")]
    pub color: ColorChoice,
}

#[derive(Debug, clap::Args)]
pub struct TranslateArgs {
    #[command(flatten)]
    pub common: CommonArgs,
    /// Targets, comma-separated.
    #[arg(long, value_enum, value_delimiter = ',', default_value = "wgsl,spv")]
    pub to: Vec<TargetArg>,
    /// Output directory (default: `out/<effect>/` for each program).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// List every item left out of the output and why (and, for multi-pass effects, the
    /// passes left out).
    #[arg(long)]
    pub explain: bool,
    /// Keep GL clip-space depth (z in [-w, w]) instead of mapping it to WebGPU's [0, w].
    #[arg(long)]
    pub keep_gl_depth: bool,
}

#[derive(Debug, clap::Args)]
pub struct CheckArgs {
    #[command(flatten)]
    pub common: CommonArgs,
    /// Exit with 1 when there are warnings.
    #[arg(long)]
    pub deny_warnings: bool,
}

#[derive(Debug, clap::Args)]
pub struct RenderArgs {
    #[command(flatten)]
    pub common: CommonArgs,
    /// Number of frames (default: the manifest's `[render] frames`, else 1).
    #[arg(long)]
    pub frames: Option<u32>,
    /// Frames per second of effect time (default: the manifest's `[render] fps`, else 30).
    #[arg(long, conflicts_with = "time_step")]
    pub fps: Option<f64>,
    /// Seconds of effect time between frames (instead of --fps).
    #[arg(long)]
    pub time_step: Option<f64>,
    /// Effect time of the first frame, in seconds.
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    pub start: f64,
    /// Frame size `WIDTHxHEIGHT` (default: the manifest's `[render] size`, else 512x512).
    #[arg(long, value_parser = parse_size)]
    pub size: Option<(u32, u32)>,
    /// Output directory (default: `out/<effect>/frames/`); frames are `<effect>_NNNN.png`.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Also tile every frame into `<effect>_sheet.png`.
    #[arg(long)]
    pub contact_sheet: bool,
    /// Also write the frames as an animated `<effect>.gif`.
    #[arg(long)]
    pub gif: bool,
    /// Render into Rgba32Float and count NaN/Inf pixels per frame (masks written; exit 1 if any).
    #[arg(long)]
    pub float: bool,
    /// Seconds a frame may take on the GPU before the run stops (a shader stuck in a loop).
    #[arg(long, default_value_t = 5.0)]
    pub timeout: f64,
    /// Print GPU and CPU milliseconds per frame and the time to the first frame.
    #[arg(long)]
    pub timings: bool,
    /// Print the adapter, the mesh and how vertex inputs were fed.
    #[arg(long)]
    pub verbose: bool,
    /// Keep GL clip-space depth (z in [-w, w]) instead of mapping it to WebGPU's [0, w].
    #[arg(long)]
    pub keep_gl_depth: bool,
    /// Multi-pass effects: also write every intermediate target as
    /// `<effect>_NNNN_<target>.png` (every pass runs and no texture is shared).
    #[arg(long)]
    pub dump_targets: bool,
    /// Multi-pass effects: print which passes run, which are skipped and why, and which
    /// targets share a texture.
    #[arg(long)]
    pub explain: bool,
}

#[derive(Debug, clap::Args)]
pub struct BenchArgs {
    #[command(flatten)]
    pub common: CommonArgs,
    /// `NAME=v1,v2,…`: sweep the uniform NAME over these values, the last being the reference
    /// (repeatable; default: the manifest's [knobs]).
    #[arg(long = "knob", value_parser = crate::bench::parse_knob)]
    pub knobs: Vec<(String, Vec<f64>)>,
    /// Frames per value (effect time advances 1/8 s per frame).
    #[arg(long, default_value_t = 4)]
    pub frames: u32,
    /// Frame size `WIDTHxHEIGHT`.
    #[arg(long, value_parser = parse_size, default_value = "256x256")]
    pub size: (u32, u32),
    /// Renders of every value (ms/frame median and spread over all of them).
    #[arg(long, default_value_t = 3)]
    pub repeats: u32,
    /// Write the error-against-time curve of every knob as an SVG.
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Seconds a frame may take before the run stops.
    #[arg(long, default_value_t = 10.0)]
    pub timeout: f64,
}

#[derive(Debug, clap::Args)]
pub struct StressArgs {
    #[command(flatten)]
    pub common: CommonArgs,
    /// Random points of the uniform ranges, besides their ends.
    #[arg(long, default_value_t = 8)]
    pub samples: u32,
    /// Seed of the random points.
    #[arg(long, default_value_t = 1)]
    pub seed: u32,
    /// Frame size `WIDTHxHEIGHT`.
    #[arg(long, value_parser = parse_size, default_value = "128x128")]
    pub size: (u32, u32),
    /// Where masks of failing cases go (default `out/stress/`).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Seconds a frame may take before the run stops.
    #[arg(long, default_value_t = 10.0)]
    pub timeout: f64,
}

/// `512x512` → (512, 512).
fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s.split_once(['x', 'X']).ok_or("expected WIDTHxHEIGHT, e.g. 512x512")?;
    let side = |t: &str| t.trim().parse::<u32>().map_err(|_| format!("`{t}` is not a whole number of pixels"));
    Ok((side(w)?, side(h)?))
}
