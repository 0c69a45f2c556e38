//! Command-line definitions (clap derive) — every flag and its documentation, in one place —
//! and the requests they make: flags are validated by their value parsers (sizes, counts,
//! times), so a request built here is within the limits.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use clap::{Parser, Subcommand, ValueEnum};

use crate::back::{Target, TranslateOptions};
use crate::check::InputSpec;
use crate::config::{Config, TargetEnv, VulkanVersion};
use crate::front::program::FrontOptions;
use crate::manifest::{MAX_FRAMES, MAX_FRAME_SIDE};
use crate::render::command::TimeStep;
use crate::stage::StageKind;
use crate::{bench, render, stress, translate};

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
    /// Check, translate to WGSL and render frames headlessly with wgpu (PNG, contact sheet,
    /// GIF, or frames streamed to stdout with `--out -`).
    Render(RenderArgs),
    /// Render like `render`, draw the original GLSL with the system's OpenGL driver (same
    /// scene), and compare every frame: exit 1 when a frame differs beyond the tolerance.
    Verify(VerifyArgs),
    /// Sweep quality knobs: GPU ms/frame against the error from the reference value's frames.
    Bench(BenchArgs),
    /// Render into float targets at the ends and random points of the uniform ranges and at
    /// extreme times; count NaN/Inf pixels per case.
    Stress(StressArgs),
    /// Print a shell completion script (e.g. `effectc completions bash > /etc/bash_completion.d/effectc`).
    Completions(CompletionsArgs),
    /// Print the man page (roff: `effectc man > effectc.1; man ./effectc.1`).
    Man,
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
    pub stage: Option<StageKind>,
    /// Diagnostic output format.
    #[arg(long, value_enum, default_value = "human")]
    pub format: Format,
    /// Constructs the file's own `#version` forbids (e.g. `texture2D` in 4.20 core) are errors.
    #[arg(long)]
    pub strict: bool,
    /// Colour for human output.
    #[arg(long, value_enum, default_value = "auto")]
    pub color: ColorChoice,
    /// Settings file (default: the nearest `effectc.toml` upward from the first input).
    #[arg(long, value_name = "FILE")]
    pub config: Option<PathBuf>,
    /// GLSL dialect of the stages (default: `target-env` in effectc.toml, else auto: Vulkan
    /// GLSL when the text shows it).
    #[arg(long, value_enum)]
    pub target_env: Option<TargetEnvArg>,
    /// Programs analysed at once (default: one per core).
    #[arg(long, short = 'j', value_parser = clap::value_parser!(u32).range(1..=256))]
    pub jobs: Option<u32>,
    /// Defines a macro in every stage read, after its `#version` line (repeatable):
    /// `-D VERTEX`, `--define QUALITY=3`.
    #[arg(long = "define", short = 'D', value_name = "NAME[=VALUE]", value_parser = crate::stage::parse_define)]
    pub defines: Vec<crate::stage::Define>,
}

/// GLSL dialects accepted by `--target-env`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TargetEnvArg {
    /// Vulkan GLSL when the text shows it (descriptor sets, push constants, separate samplers).
    Auto,
    /// OpenGL GLSL.
    Opengl,
    /// Vulkan GLSL (as glslangValidator -V): Vulkan 1.0, SPIR-V 1.0 rules.
    Vulkan,
    /// Vulkan GLSL for Vulkan 1.0 (SPIR-V 1.0).
    #[value(name = "vulkan1.0")]
    Vulkan1_0,
    /// Vulkan GLSL for Vulkan 1.1 (SPIR-V 1.3: subgroup operations).
    #[value(name = "vulkan1.1")]
    Vulkan1_1,
    /// Vulkan GLSL for Vulkan 1.2 (SPIR-V 1.5).
    #[value(name = "vulkan1.2")]
    Vulkan1_2,
    /// Vulkan GLSL for Vulkan 1.3 (SPIR-V 1.6).
    #[value(name = "vulkan1.3")]
    Vulkan1_3,
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
    /// Run again whenever an input changes (stage files, manifests, included files,
    /// textures, meshes, new files below input directories), until interrupted.
    #[arg(long)]
    pub watch: bool,
}

/// Tiers accepted by `--hazards`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum HazardsArg {
    Certain,
    Possible,
}

impl From<HazardsArg> for crate::config::HazardReport {
    fn from(a: HazardsArg) -> Self {
        match a {
            HazardsArg::Certain => crate::config::HazardReport::Certain,
            HazardsArg::Possible => crate::config::HazardReport::Possible,
        }
    }
}

#[derive(Debug, clap::Args)]
pub struct CheckArgs {
    #[command(flatten)]
    pub common: CommonArgs,
    /// Exit with 1 when there are warnings.
    #[arg(long)]
    pub deny_warnings: bool,
    /// List every uniform each program lets you set (type, default, range, semantic, guess)
    /// before the diagnostics; with `--format json`, under `programs`.
    #[arg(long)]
    pub list_uniforms: bool,
    /// List the programs formed (their stage files, the macros defined for them, and why
    /// they were grouped) before the diagnostics; JSON always has them under `formed`.
    #[arg(long)]
    pub verbose: bool,
    /// Run again whenever an input changes (stage files, manifests, included files,
    /// textures, meshes, new files below input directories), until interrupted.
    #[arg(long)]
    pub watch: bool,
    /// Which numeric hazards to report: `certain` (a run at fixed inputs showed them) or
    /// `possible` (also those the analysis cannot rule out). Default: `report` in
    /// effectc.toml's `[hazards]`, else certain for bare stage files, possible for effects.
    #[arg(long, value_enum, value_name = "TIER")]
    pub hazards: Option<HazardsArg>,
}

/// Which frames `render` and `verify` draw, and with which uniform values.
#[derive(Debug, clap::Args)]
pub struct FrameArgs {
    /// `NAME=VALUE`: a uniform's value (`0.5`, `3`, `true`, `1,0.5,0`), checked against the
    /// declarations like a manifest default; wins over the manifest (repeatable).
    #[arg(long = "set", value_name = "NAME=VALUE", value_parser = parse_set)]
    pub set: Vec<(String, String)>,
    /// Number of frames (default: the manifest's `[render] frames`, else 1).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=i64::from(MAX_FRAMES)))]
    pub frames: Option<u32>,
    /// Frames per second of effect time (default: the manifest's `[render] fps`, else 30).
    #[arg(long, conflicts_with = "time_step", value_parser = parse_positive)]
    pub fps: Option<f64>,
    /// Seconds of effect time between frames (instead of --fps).
    #[arg(long, value_parser = parse_finite, allow_negative_numbers = true)]
    pub time_step: Option<f64>,
    /// Effect time of the first frame, in seconds.
    #[arg(long, default_value_t = 0.0, value_parser = parse_finite, allow_negative_numbers = true)]
    pub start: f64,
    /// Frame size `WIDTHxHEIGHT` (default: the manifest's `[render] size`, else 512x512).
    #[arg(long, value_parser = parse_size)]
    pub size: Option<(u32, u32)>,
    /// GL's uniform rules: a uniform nobody gave a value (manifest, `--set`, GLSL
    /// initializer) is zero, as in GL, instead of a guess by its name.
    #[arg(long)]
    pub gl_defaults: bool,
}

impl FrameArgs {
    /// How time advances between frames.
    pub fn step(&self) -> TimeStep {
        match (self.fps, self.time_step) {
            (Some(f), _) => TimeStep::Fps(f),
            (None, Some(s)) => TimeStep::Seconds(s),
            (None, None) => TimeStep::Default,
        }
    }
}

#[derive(Debug, clap::Args)]
pub struct RenderArgs {
    #[command(flatten)]
    pub common: CommonArgs,
    #[command(flatten)]
    pub frames: FrameArgs,
    /// Output directory (default: `out/<effect>/frames/`); frames are `<effect>_NNNN.png`.
    /// `-`: stream the frames to stdout instead, one PNG after another (for `ffmpeg -f
    /// image2pipe -i -`); the report goes to stderr.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// With `--out -`: raw RGBA8 frames instead of PNGs (width × height × 4 bytes each,
    /// rows top-down; `ffmpeg -f rawvideo -pix_fmt rgba -s WxH -i -`).
    #[arg(long)]
    pub raw: bool,
    /// Also tile every frame into `<effect>_sheet.png`.
    #[arg(long)]
    pub contact_sheet: bool,
    /// Also write the frames as an animated `<effect>.gif`.
    #[arg(long)]
    pub gif: bool,
    /// Render into Rgba32Float and count NaN/Inf pixels per frame (masks written; exit 1 if any).
    #[arg(long)]
    pub float: bool,
    /// Seconds a frame may take on the GPU before the run stops (a shader stuck in a loop;
    /// default 5, or 30 on a software renderer such as lavapipe).
    #[arg(long, value_parser = parse_timeout, allow_negative_numbers = true)]
    pub timeout: Option<Duration>,
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
    /// Run again whenever an input changes (stage files, manifests, included files,
    /// textures, meshes, new files below input directories), until interrupted.
    #[arg(long)]
    pub watch: bool,
    /// Also draw the original GLSL with the system's OpenGL driver and compare every
    /// frame, as `effectc verify` does (frames, GL frames and heat maps to `--out`, else
    /// `out/<effect>/verify/`; exit 1 when a frame differs beyond the tolerance).
    #[arg(long)]
    pub verify: bool,
}

#[derive(Debug, clap::Args)]
pub struct VerifyArgs {
    #[command(flatten)]
    pub common: CommonArgs,
    #[command(flatten)]
    pub frames: FrameArgs,
    /// Output directory (default: `out/<effect>/verify/`): per frame `<effect>_NNNN.png`
    /// (the translation), `<effect>_NNNN_gl.png` (the OpenGL driver) and, when they differ
    /// at all, `<effect>_NNNN_diff.png` (a heat map).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Largest per-channel difference (0–255) that still matches (default: the manifest's
    /// `[verify] tolerance`, else 2).
    #[arg(long)]
    pub tolerance: Option<u8>,
    /// Percent of pixels allowed beyond the tolerance (default: the manifest's `[verify]
    /// max_differing`, else 0.1).
    #[arg(long, value_parser = parse_percent)]
    pub max_differing: Option<f64>,
    /// Seconds a frame may take on the GPU before the run stops (a shader stuck in a loop;
    /// default 5, or 30 on a software renderer such as lavapipe).
    #[arg(long, value_parser = parse_timeout, allow_negative_numbers = true)]
    pub timeout: Option<Duration>,
    /// Print the adapter and the GL renderer.
    #[arg(long)]
    pub verbose: bool,
}

impl RenderArgs {
    /// `render --verify`: the verify request these flags make (the manifest's tolerance).
    pub fn verify_request(&self, config: &Config, started: Instant) -> crate::verify::command::VerifyRequest {
        crate::verify::command::VerifyRequest { render: self.request(config, started), tolerance: None, max_differing: None }
    }
}

impl VerifyArgs {
    /// The request these flags make.
    pub fn request(&self, config: &Config) -> crate::verify::command::VerifyRequest {
        let f = &self.frames;
        let mut input = InputSpec { values: f.set.clone(), ..self.common.input_spec(config).for_drawing() };
        // A frame that differs from the driver's is explained by any undefined behaviour
        // the analysis cannot rule out, so `verify` reports the possible hazards too.
        input.hazards.report = input.hazards.report.or(Some(crate::config::HazardReport::Possible));
        let mut render = render::command::Request::new(input);
        render.frames = f.frames;
        render.step = f.step();
        render.start = f.start;
        render.size = f.size;
        render.gl_defaults = f.gl_defaults;
        render.out = self.out.clone();
        render.timeout = self.timeout;
        crate::verify::command::VerifyRequest { render, tolerance: self.tolerance, max_differing: self.max_differing }
    }
}

fn parse_percent(s: &str) -> Result<f64, String> {
    let v: f64 = s.trim().trim_end_matches('%').parse().map_err(|_| format!("`{s}` is not a number"))?;
    if (0.0..=100.0).contains(&v) {
        Ok(v)
    } else {
        Err(format!("{v} is not a percentage between 0 and 100"))
    }
}

#[derive(Debug, clap::Args)]
pub struct BenchArgs {
    #[command(flatten)]
    pub common: CommonArgs,
    /// `NAME=VALUE`: a uniform's value (`0.5`, `3`, `true`, `1,0.5,0`), checked against the
    /// declarations like a manifest default; wins over the manifest (repeatable).
    #[arg(long = "set", value_name = "NAME=VALUE", value_parser = parse_set)]
    pub set: Vec<(String, String)>,
    /// `NAME=v1,v2,…`: sweep the uniform NAME over these values, the last being the reference
    /// (repeatable; default: the manifest's [knobs]).
    #[arg(long = "knob", value_parser = crate::bench::parse_knob)]
    pub knobs: Vec<(String, Vec<f64>)>,
    /// Frames per value (effect time advances 1/8 s per frame).
    #[arg(long, default_value_t = 4, value_parser = clap::value_parser!(u32).range(1..=1000))]
    pub frames: u32,
    /// Frame size `WIDTHxHEIGHT` (256x256, not render's 512x512: a sweep draws every value
    /// `--frames` x `--repeats` times, and error against time needs no more pixels).
    #[arg(long, value_parser = parse_size, default_value = "256x256")]
    pub size: (u32, u32),
    /// Renders of every value (ms/frame median and spread over all of them).
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u32).range(1..=100))]
    pub repeats: u32,
    /// Write the error-against-time curve of every knob as an SVG.
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Seconds a frame may take before the run stops (10, between render's 5 on a GPU and
    /// 30 on a software renderer: its frames are small, see `--size`).
    #[arg(long, default_value = "10", value_parser = parse_timeout, allow_negative_numbers = true)]
    pub timeout: Duration,
}

#[derive(Debug, clap::Args)]
pub struct StressArgs {
    #[command(flatten)]
    pub common: CommonArgs,
    /// `NAME=VALUE`: a uniform's value (`0.5`, `3`, `true`, `1,0.5,0`), checked against the
    /// declarations like a manifest default; wins over the manifest (repeatable).
    #[arg(long = "set", value_name = "NAME=VALUE", value_parser = parse_set)]
    pub set: Vec<(String, String)>,
    /// Random points of the uniform ranges, besides their ends.
    #[arg(long, default_value_t = 8, value_parser = clap::value_parser!(u32).range(0..=10_000))]
    pub samples: u32,
    /// Seed of the random points.
    #[arg(long, default_value_t = 1)]
    pub seed: u32,
    /// Frame size `WIDTHxHEIGHT` (128x128, not render's 512x512: every case of every
    /// uniform range is drawn, and a NaN or Inf shows at any size).
    #[arg(long, value_parser = parse_size, default_value = "128x128")]
    pub size: (u32, u32),
    /// Where masks of failing cases go (default `out/stress/`).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Seconds a frame may take before the run stops (10, between render's 5 on a GPU and
    /// 30 on a software renderer: its frames are small, see `--size`).
    #[arg(long, default_value = "10", value_parser = parse_timeout, allow_negative_numbers = true)]
    pub timeout: Duration,
    /// Put every hazard warning (both tiers) to a render instead: its operation is tested
    /// as it runs, under the inputs the analysis assumed, and reported confirmed (error
    /// E0703), refuted, unreached or untested.
    #[arg(long)]
    pub confirm: bool,
}

/// `NAME=VALUE` → (NAME, VALUE); the value is checked once the programs are read.
fn parse_set(s: &str) -> Result<(String, String), String> {
    match s.split_once('=') {
        Some((n, v)) if !n.trim().is_empty() && !v.trim().is_empty() => Ok((n.trim().to_string(), v.trim().to_string())),
        _ => Err(format!("`{s}` is not NAME=VALUE (e.g. `speed=0.5`, `tint=1,0.5,0`)")),
    }
}

#[derive(Debug, clap::Args)]
pub struct CompletionsArgs {
    /// The shell to complete for.
    #[arg(value_enum)]
    pub shell: clap_complete::Shell,
}

/// `512x512` → (512, 512), each side within 1..=[`MAX_FRAME_SIDE`].
fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s.split_once(['x', 'X']).ok_or("expected WIDTHxHEIGHT, e.g. 512x512")?;
    let side = |t: &str| t.trim().parse::<u32>().map_err(|_| format!("`{t}` is not a whole number of pixels"));
    let (w, h) = (side(w)?, side(h)?);
    if !(1..=MAX_FRAME_SIDE).contains(&w) || !(1..=MAX_FRAME_SIDE).contains(&h) {
        return Err(format!("{w}x{h} is outside 1..={MAX_FRAME_SIDE} per side"));
    }
    Ok((w, h))
}

/// A finite number.
fn parse_finite(s: &str) -> Result<f64, String> {
    match s.trim().parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(format!("`{s}` is not a finite number")),
    }
}

/// A finite number above zero.
fn parse_positive(s: &str) -> Result<f64, String> {
    match parse_finite(s)? {
        v if v > 0.0 => Ok(v),
        _ => Err(format!("`{s}` is not a positive number")),
    }
}

/// Seconds above zero, at most a day.
fn parse_timeout(s: &str) -> Result<Duration, String> {
    let seconds = parse_positive(s)?;
    Duration::try_from_secs_f64(seconds).ok().filter(|d| d.as_secs() <= 86_400).ok_or_else(|| format!("`{s}` s is more than a day"))
}

impl CommonArgs {
    /// What the command reads, with the repository's settings (flags win over them).
    pub fn input_spec(&self, config: &Config) -> InputSpec {
        let env = match self.target_env {
            None => config.target_env,
            Some(TargetEnvArg::Auto) => TargetEnv::Auto,
            Some(TargetEnvArg::Opengl) => TargetEnv::OpenGl,
            Some(TargetEnvArg::Vulkan | TargetEnvArg::Vulkan1_0) => TargetEnv::Vulkan(VulkanVersion::V1_0),
            Some(TargetEnvArg::Vulkan1_1) => TargetEnv::Vulkan(VulkanVersion::V1_1),
            Some(TargetEnvArg::Vulkan1_2) => TargetEnv::Vulkan(VulkanVersion::V1_2),
            Some(TargetEnvArg::Vulkan1_3) => TargetEnv::Vulkan(VulkanVersion::V1_3),
        };
        InputSpec {
            paths: self.inputs.clone(),
            stage: self.stage,
            front: FrontOptions { strict: self.strict || config.strict, env, doubles_as_floats: false, limits: config.limits },
            selection: config.selection.clone(),
            jobs: self.jobs.map(|j| j as usize),
            values: Vec::new(),
            fixed_function_stages: false,
            hazards: config.hazards,
            // The settings' macros, then the command line's (which win for a name both give).
            defines: config
                .defines
                .iter()
                .filter(|(n, _)| !self.defines.iter().any(|(m, _)| m == n))
                .chain(&self.defines)
                .cloned()
                .collect(),
        }
    }
}

impl TranslateArgs {
    /// The request these flags make.
    pub fn request(&self, config: &Config) -> translate::Request {
        let mut targets: Vec<Target> = Vec::new();
        for t in &self.to {
            match t {
                TargetArg::All => targets.extend(Target::ALL),
                one => targets.push(one.target()),
            }
        }
        targets.sort();
        targets.dedup();
        let back = TranslateOptions::for_targets(&targets, !self.keep_gl_depth);
        let mut input = self.common.input_spec(config);
        input.front.doubles_as_floats = !back.float64;
        translate::Request { input, back, targets, out: self.out.clone() }
    }
}

impl TargetArg {
    /// The target (`All` is expanded by the caller; it maps to the last one here).
    fn target(self) -> Target {
        match self {
            TargetArg::Wgsl => Target::Wgsl,
            TargetArg::Spv => Target::Spv,
            TargetArg::Spvasm => Target::Spvasm,
            TargetArg::Glsl => Target::Glsl,
            TargetArg::Msl => Target::Msl,
            TargetArg::Hlsl => Target::Hlsl,
            TargetArg::Reflect => Target::Reflect,
            TargetArg::Ir | TargetArg::All => Target::Ir,
        }
    }
}

impl RenderArgs {
    /// The request these flags make; `started` is when the process started (for the time
    /// to the first frame).
    pub fn request(&self, config: &Config, started: Instant) -> render::command::Request {
        let f = &self.frames;
        render::command::Request {
            input: InputSpec { values: f.set.clone(), ..self.common.input_spec(config).for_drawing() },
            back: TranslateOptions::for_rendering(!self.keep_gl_depth),
            frames: f.frames,
            step: f.step(),
            start: f.start,
            size: f.size,
            out: self.out.clone().filter(|_| !self.streams()),
            stream: self.streams().then_some(if self.raw {
                render::command::StreamFormat::Raw
            } else {
                render::command::StreamFormat::Png
            }),
            contact_sheet: self.contact_sheet,
            gif: self.gif,
            float: self.float,
            timeout: self.timeout,
            progress: std::io::stderr().is_terminal() && std::env::var_os("CI").is_none(),
            started,
            dump_targets: self.dump_targets,
            timings: self.timings,
            gl_defaults: f.gl_defaults,
            only: None,
        }
    }

    /// The frames go to stdout (`--out -`).
    pub fn streams(&self) -> bool {
        self.out.as_deref() == Some(Path::new("-"))
    }

    /// Flag combinations clap cannot refuse by itself: `--raw` without `--out -`, and the
    /// flags that write files beside the frames (which a stream has no place for) with it.
    pub fn usage_error(&self) -> Option<String> {
        if self.verify {
            let other = [
                ("--out -", self.streams()),
                ("--float", self.float),
                ("--gif", self.gif),
                ("--contact-sheet", self.contact_sheet),
                ("--dump-targets", self.dump_targets),
                ("--watch", self.watch),
                ("--raw", self.raw),
            ];
            if let Some((flag, _)) = other.into_iter().find(|(_, on)| *on) {
                return Some(format!("`--verify` compares RGBA8 frames written as PNG files and cannot be used with `{flag}`"));
            }
            return None;
        }
        if !self.streams() {
            return self.raw.then(|| "`--raw` needs `--out -`: raw frames are only streamed to stdout".to_string());
        }
        let file_flags =
            [("--contact-sheet", self.contact_sheet), ("--gif", self.gif), ("--float", self.float), ("--dump-targets", self.dump_targets)];
        let (flag, _) = file_flags.into_iter().find(|(_, on)| *on)?;
        Some(format!("`{flag}` writes files beside the frames and cannot be used with `--out -` (frames on stdout); use `--out DIR`"))
    }
}

/// The completion script of `shell` for the whole command line.
pub fn completions(shell: clap_complete::Shell) -> Vec<u8> {
    let mut out = Vec::new();
    clap_complete::generate(shell, &mut <Cli as clap::CommandFactory>::command(), "effectc", &mut out);
    out
}

/// The roff man page of `effectc` (the subcommands listed in it).
pub fn man_page() -> std::io::Result<Vec<u8>> {
    let mut out = Vec::new();
    clap_mangen::Man::new(<Cli as clap::CommandFactory>::command()).render(&mut out)?;
    Ok(out)
}

impl BenchArgs {
    /// The request these flags make.
    pub fn request(&self, config: &Config) -> bench::Request {
        bench::Request {
            input: InputSpec { values: self.set.clone(), ..self.common.input_spec(config).for_drawing() },
            knobs: self.knobs.clone(),
            frames: self.frames,
            size: self.size,
            repeats: self.repeats,
            step: 0.125,
            timeout: self.timeout,
        }
    }
}

impl StressArgs {
    /// The request these flags make (masks go to `out/stress/` unless `--out` says otherwise).
    pub fn request(&self, config: &Config) -> stress::Request {
        let mut input = InputSpec { values: self.set.clone(), ..self.common.input_spec(config).for_drawing() };
        // Every warning is put to the render, possible ones too.
        if self.confirm {
            input.hazards.report = Some(crate::config::HazardReport::Possible);
        }
        stress::Request {
            time_limit: input.hazards.time_limit,
            input,
            samples: self.samples,
            seed: self.seed,
            size: self.size,
            timeout: self.timeout,
            out: Some(self.out.clone().unwrap_or_else(|| PathBuf::from("out/stress"))),
            confirm: self.confirm,
        }
    }
}
