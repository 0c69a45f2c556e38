//! `effectc render`: check, translate to WGSL, build the scene, draw the frames and write
//! them as PNG (plus a contact sheet, a GIF, non-finite masks), or stream them to stdout.
//!
//! The adapter and device are opened once per run and every program reuses them; each
//! program's pipeline and target are created once and reused by its frames. Frames are
//! encoded on a pool while the next ones render, and written in order (`render::sink`).
//! Frame times come from the frame index (`start + i × step`), never from the wall clock,
//! so the same command gives the same bytes.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::{Duration, Instant};

use crate::back::TranslateOptions;
use crate::check::{self, Outcome};
use crate::diag::{Code, Diagnostic, FileId};
use crate::output::{self, write_atomic};
use crate::render::device::Gpu;
pub use crate::render::drawer::DEFAULT_SIZE;
use crate::render::drawer::{build, frame_state, prepare, BuildSettings, BuildVariant, Drawer};
use crate::render::encode;
use crate::render::frames::{Frame, FrameError, FrameTarget, GpuClock};
use crate::render::scene::ColorMode;
pub use crate::render::sink::StreamFormat;
use crate::render::sink::{Drawn, Sink};

/// Frames kept in memory for `--contact-sheet` / `--gif` may use at most this much.
pub const MAX_KEPT_BYTES: u64 = 2 << 30;
/// Default frame rate when neither the manifest nor the flags give one.
pub const DEFAULT_FPS: f64 = 30.0;

/// How time advances between frames.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TimeStep {
    /// The manifest's `[render] fps`, else [`DEFAULT_FPS`].
    Default,
    Fps(f64),
    Seconds(f64),
}

/// What `render` was asked to do.
#[derive(Debug, Clone)]
pub struct Request {
    pub input: check::InputSpec,
    pub back: TranslateOptions,
    /// `None`: the manifest's `[render] frames`, else 1.
    pub frames: Option<u32>,
    pub step: TimeStep,
    pub start: f64,
    /// `None`: the manifest's `[render] size`, else [`DEFAULT_SIZE`].
    pub size: Option<(u32, u32)>,
    /// `None`: `out/<effect>/frames/`.
    pub out: Option<PathBuf>,
    /// `Some`: the frames go to stdout in this format instead (`out` is unused); one
    /// program only, no contact sheet, GIF, float masks or target dumps.
    pub stream: Option<StreamFormat>,
    pub contact_sheet: bool,
    pub gif: bool,
    pub float: bool,
    /// Seconds a frame may take; `None`: [`Gpu::default_frame_timeout`].
    pub timeout: Option<Duration>,
    /// Show a progress bar (on a terminal, outside CI).
    pub progress: bool,
    /// When the process started, for the time to the first frame.
    pub started: Instant,
    /// Multi-pass effects: write every intermediate target too (nothing pruned or shared).
    pub dump_targets: bool,
    /// `--gl-defaults`: uniforms nobody set are zero, as in GL (no guesses).
    pub gl_defaults: bool,
    /// `--timings`: time frames with GPU timestamp queries.
    pub timings: bool,
    /// `--watch` after a change: render only the programs that read one of these files
    /// (absolute paths); `None` renders every program.
    pub only: Option<Vec<PathBuf>>,
}

impl Request {
    /// A request for what `input` names with every flag at its default (the manifest's
    /// frames, size and frame rate; the adapter's frame timeout; frames to `out/<effect>/frames/`).
    pub fn new(input: check::InputSpec) -> Request {
        Request {
            input,
            back: TranslateOptions::for_rendering(true),
            frames: None,
            step: TimeStep::Default,
            start: 0.0,
            size: None,
            out: None,
            stream: None,
            contact_sheet: false,
            gif: false,
            float: false,
            timeout: None,
            progress: false,
            started: Instant::now(),
            dump_targets: false,
            gl_defaults: false,
            timings: false,
            only: None,
        }
    }

    /// Does this request render `c`? (Under `--watch`, only programs whose files changed.)
    fn wants(&self, c: &check::Checked) -> bool {
        self.only.as_ref().is_none_or(|changed| c.read.iter().any(|p| changed.contains(&crate::diag::paths::absolute(p))))
    }

    /// What building each program takes from these flags.
    pub fn build_settings(&self) -> BuildSettings {
        BuildSettings {
            back: self.back,
            size: self.size,
            dump_targets: self.dump_targets,
            timestamps: self.timings,
            gl_defaults: self.gl_defaults,
        }
    }
}

/// One frame's numbers.
#[derive(Debug, Clone, PartialEq)]
pub struct FrameReport {
    pub index: u32,
    pub time: f64,
    pub gpu_ms: f64,
    pub cpu_ms: f64,
    /// `--float`: NaN / +Inf / −Inf pixel counts.
    pub non_finite: Option<(u64, u64, u64)>,
}

/// One rendered program.
#[derive(Debug, Clone)]
pub struct Rendered {
    pub name: String,
    pub dir: PathBuf,
    pub size: (u32, u32),
    pub files: Vec<PathBuf>,
    /// The frames went to stdout in this format (no files).
    pub stream: Option<StreamFormat>,
    pub frames: Vec<FrameReport>,
    pub clock: GpuClock,
    /// From process start until the first PNG was on disk.
    pub first_frame: Option<Duration>,
    /// Mesh and attribute summary.
    pub scene: String,
    /// Multi-pass effects: the pass plan (what runs, what is skipped, shared textures).
    pub passes: Option<String>,
}

/// The result of a run: diagnostics, what was rendered, the adapter used.
pub struct RunResult {
    pub outcome: Outcome,
    pub rendered: Vec<Rendered>,
    pub adapter: Option<String>,
    /// A frame timed out: the device is still busy, so the caller must exit the process
    /// without waiting for it (everything GPU-side was leaked on purpose).
    pub hung: bool,
}

/// Runs check, translation and rendering for every program of the request.
pub fn run(request: &Request) -> RunResult {
    let (mut outcome, checked) = request.input.check();
    let mut result = RunResult { outcome: Outcome::default(), rendered: Vec::new(), adapter: None, hung: false };
    let inputs = output::input_paths(&outcome, &request.input.paths);
    if request.stream.is_some() && checked.len() > 1 {
        outcome.io_error = true;
        outcome.diagnostics.push(
            Diagnostic::new(
                Code::OutputIo,
                format!("the inputs name {} programs; their frames cannot share one stream on stdout", checked.len()),
            )
            .with_help("render one program per `--out -` run, or write files with `--out DIR`"),
        );
        crate::diag::sort(&mut outcome.diagnostics);
        result.outcome = outcome;
        return result;
    }
    let mut gpu: Option<Gpu> = None;
    for c in checked.iter().filter(|c| request.wants(c)) {
        let Some(prepared) = prepare(c, &mut outcome, &request.build_settings(), None) else { continue };
        let Some(gpu) = open_once(&mut gpu, &mut result.adapter, &mut outcome) else { break };
        let effect = c.effect.as_ref();
        let render = effect.map(|e| e.render.clone()).unwrap_or_default();
        let size = request.size.or(render.size).unwrap_or(DEFAULT_SIZE);
        let frames = request.frames.or(render.frames).unwrap_or(1);
        if let Some(d) = device_limit_error(gpu, size, frames, request) {
            outcome.io_error = true;
            outcome.diagnostics.push(d);
            continue;
        }
        let mode = if request.float { ColorMode::Float32 } else { ColorMode::Unorm8 };
        let (mut drawer, file) = match build(gpu, &prepared, c, (size, mode), &request.build_settings(), BuildVariant::default()) {
            Ok(d) => d,
            Err(diags) => {
                outcome.diagnostics.extend(diags);
                continue;
            }
        };
        outcome.diagnostics.append(drawer.warnings());
        let step = match request.step {
            TimeStep::Fps(f) => 1.0 / f,
            TimeStep::Seconds(s) => s,
            TimeStep::Default => 1.0 / render.fps.unwrap_or(DEFAULT_FPS),
        };
        let dir = request.out.clone().unwrap_or_else(|| Path::new("out").join(drawer.name()).join("frames"));
        let plan = FramePlan { frames, size, step, start: request.start, dir };
        match draw_frames(gpu, &mut drawer, &plan, request, &inputs, file) {
            Ok((mut rendered, diags)) => {
                // Frames that could not be written (or a closed stream) are IO errors.
                outcome.io_error |= diags.iter().any(|d| d.code == Code::OutputIo);
                outcome.diagnostics.extend(diags);
                if let (Drawer::Graph(g), Some(e)) = (&drawer, effect) {
                    rendered.passes = Some(g.explain(e));
                }
                result.rendered.push(rendered);
            }
            Err(Stop::Hung(d)) => {
                outcome.diagnostics.push(*d);
                result.hung = true;
                // The device is still running the frame: dropping it would wait forever.
                std::mem::forget(drawer);
                break;
            }
            Err(Stop::Failed(d)) => outcome.diagnostics.push(*d),
        }
    }
    if result.hung {
        std::mem::forget(gpu);
    }
    crate::diag::sort(&mut outcome.diagnostics);
    result.outcome = outcome;
    result
}

/// The device of a run, opened on first use (the adapter's description goes to `adapter`).
/// `None` when there is no adapter: `E0401` is in `outcome`, which then exits with 2.
pub fn open_once<'g>(gpu: &'g mut Option<Gpu>, adapter: &mut Option<String>, outcome: &mut Outcome) -> Option<&'g Gpu> {
    if gpu.is_none() {
        match Gpu::new() {
            Ok(g) => {
                *adapter = Some(g.describe());
                *gpu = Some(g);
            }
            Err(e) => {
                outcome.io_error = true;
                outcome.diagnostics.push(Diagnostic::new(Code::NoAdapter, e.0));
            }
        }
    }
    gpu.as_ref()
}

/// Limits that depend on the device and on what the run keeps in memory.
fn device_limit_error(gpu: &Gpu, (w, h): (u32, u32), frames: u32, request: &Request) -> Option<Diagnostic> {
    let limits = gpu.device.limits();
    let max_side = limits.max_texture_dimension_2d;
    if w == 0 || h == 0 || w > max_side || h > max_side {
        return Some(Diagnostic::new(Code::RenderLimit, format!("a {w}x{h} frame exceeds the adapter's limit of {max_side} per side")));
    }
    let mode = if request.float { ColorMode::Float32 } else { ColorMode::Unorm8 };
    let needed = FrameTarget::readback_size(w, h, mode);
    if needed > limits.max_buffer_size {
        return Some(Diagnostic::new(
            Code::RenderLimit,
            format!("a {w}x{h} frame needs {} MiB, beyond the adapter's buffers", needed >> 20),
        ));
    }
    let kept = u64::from(w) * u64::from(h) * 4 * u64::from(frames);
    if (request.contact_sheet || request.gif) && kept > MAX_KEPT_BYTES {
        return Some(
            Diagnostic::new(Code::RenderLimit, format!("--contact-sheet/--gif would keep {} MiB of frames in memory", kept >> 20))
                .with_note(format!("the limit is {} MiB; use fewer frames or a smaller --size", MAX_KEPT_BYTES >> 20)),
        );
    }
    None
}

struct FramePlan {
    frames: u32,
    size: (u32, u32),
    step: f64,
    start: f64,
    dir: PathBuf,
}

enum Stop {
    Hung(Box<Diagnostic>),
    Failed(Box<Diagnostic>),
}

fn draw_frames(
    gpu: &Gpu,
    drawer: &mut Drawer,
    plan: &FramePlan,
    request: &Request,
    inputs: &BTreeSet<PathBuf>,
    file: FileId,
) -> Result<(Rendered, Vec<Diagnostic>), Stop> {
    let (w, h) = plan.size;
    let name = drawer.name().to_owned();
    let bar = progress_bar(request, plan.frames, &name);
    let keep = request.contact_sheet || request.gif;
    let mut reports = Vec::new();
    let mut stop = None;
    let spare = drawer.spare().unwrap_or_default();
    let sink = Sink { name: &name, dir: &plan.dir, size: plan.size, keep, inputs, stream: request.stream, spare };
    let (tx, rx) = mpsc::sync_channel::<Drawn>(2);
    let encoded = std::thread::scope(|s| {
        let writer = s.spawn(|| sink.run(rx));
        for i in 0..plan.frames {
            let time = plan.start + f64::from(i) * plan.step;
            let state = frame_state(drawer, i, time, plan.step, plan.size);
            match drawer.draw(gpu, &state, request.timeout.unwrap_or_else(|| gpu.default_frame_timeout())) {
                Ok(Frame { pixels, gpu_ms, cpu_ms, dumps }) => {
                    reports.push(FrameReport { index: i, time, gpu_ms, cpu_ms, non_finite: None });
                    if tx.send(Drawn { index: i, pixels, dumps }).is_err() {
                        break;
                    }
                }
                Err(FrameError::Timeout(t)) => {
                    stop = Some(Stop::Hung(Box::new(
                        Diagnostic::new(Code::FrameTimeout, format!("frame {i} did not finish within {:.1} s", t.as_secs_f64()))
                            .in_file(file)
                            .with_note("a shader that never leaves a loop keeps the GPU busy forever")
                            .with_help("check the loop conditions, or raise --timeout for a very slow effect"),
                    )));
                    break;
                }
                Err(FrameError::Device(e)) => {
                    stop = Some(Stop::Failed(Box::new(
                        Diagnostic::new(Code::FrameFailed, format!("frame {i} failed on the device")).in_file(file).with_note(e),
                    )));
                    break;
                }
            }
            if let Some(b) = &bar {
                b.inc(1);
            }
        }
        drop(tx);
        writer.join().unwrap_or_default()
    });
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    if let Some(stop) = stop {
        return Err(stop);
    }
    let mut diags = encoded.errors;
    let mut files = encoded.files;
    if diags.iter().any(|d| d.code == Code::OutputIo) {
        // Written frames only: a write that failed ended the run there.
        reports.truncate(encoded.frames as usize);
    }
    for (index, nf, mask) in &encoded.non_finite {
        if let Some(r) = reports.iter_mut().find(|r| r.index == *index) {
            r.non_finite = Some((nf.nan, nf.pos_inf, nf.neg_inf));
        }
        if nf.nan + nf.pos_inf + nf.neg_inf > 0 {
            let mut d = Diagnostic::new(
                Code::NonFinitePixels,
                format!("frame {index}: {} NaN, {} +Inf, {} -Inf pixels", nf.nan, nf.pos_inf, nf.neg_inf),
            )
            .in_file(file);
            if let Some(m) = mask {
                d = d.with_note(format!("mask: {} (NaN red, +Inf yellow, -Inf cyan)", m.display()));
            }
            diags.push(d);
        }
    }
    let frames_rgba: Vec<&[u8]> = encoded.kept.iter().map(|f| f.as_slice()).collect();
    if request.contact_sheet && !frames_rgba.is_empty() {
        let (sheet, sw, sh) = encode::contact_sheet(&frames_rgba, w, h, 0);
        let path = plan.dir.join(format!("{name}_sheet.png"));
        write_png(&path, &sheet, sw, sh, inputs, &mut files, &mut diags);
    }
    if request.gif && !frames_rgba.is_empty() {
        let delay = (plan.step * 1000.0).round().clamp(20.0, 60_000.0) as u32;
        let path = plan.dir.join(format!("{name}.gif"));
        match encode::gif_bytes(&frames_rgba, w, h, delay) {
            Ok(bytes) => write_file(&path, &bytes, inputs, &mut files, &mut diags),
            Err(e) => diags.push(Diagnostic::new(Code::OutputIo, format!("cannot encode {}: {e}", path.display()))),
        }
    }
    let rendered = Rendered {
        name: name.clone(),
        dir: plan.dir.clone(),
        size: plan.size,
        files,
        stream: request.stream,
        frames: reports,
        clock: drawer.clock(),
        first_frame: encoded.first_written.map(|t| t.duration_since(request.started)),
        scene: drawer.describe(),
        passes: None,
    };
    Ok((rendered, diags))
}

fn write_png(path: &Path, rgba: &[u8], w: u32, h: u32, inputs: &BTreeSet<PathBuf>, files: &mut Vec<PathBuf>, diags: &mut Vec<Diagnostic>) {
    match encode::png_bytes(rgba, w, h) {
        Ok(bytes) => write_file(path, &bytes, inputs, files, diags),
        Err(e) => diags.push(Diagnostic::new(Code::OutputIo, format!("cannot encode {}: {e}", path.display()))),
    }
}

fn write_file(path: &Path, bytes: &[u8], inputs: &BTreeSet<PathBuf>, files: &mut Vec<PathBuf>, diags: &mut Vec<Diagnostic>) {
    match write_atomic(path, bytes, inputs) {
        Ok(()) => files.push(path.to_path_buf()),
        Err(e) => diags.push(Diagnostic::new(Code::OutputIo, e)),
    }
}

fn progress_bar(request: &Request, frames: u32, name: &str) -> Option<indicatif::ProgressBar> {
    if !request.progress || frames < 2 {
        return None;
    }
    let bar = indicatif::ProgressBar::new(u64::from(frames));
    let style = indicatif::ProgressStyle::with_template("{prefix} [{bar:30}] {pos}/{len} frames {per_sec} eta {eta}")
        .map(|s| s.progress_chars("=> "))
        .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar());
    bar.set_style(style);
    bar.set_prefix(name.to_string());
    Some(bar)
}

/// Human summary of one rendered program (with per-frame timings when asked).
pub fn summary(r: &Rendered, timings: bool, verbose: bool, explain: bool) -> String {
    let pngs = r.files.iter().filter(|f| !f.to_string_lossy().ends_with("_nonfinite.png")).count();
    let (to, what) = match r.stream {
        None => (r.dir.display().to_string(), format!("{pngs} file{}", if pngs == 1 { "" } else { "s" })),
        Some(StreamFormat::Png) => ("stdout".to_string(), "PNG stream".to_string()),
        Some(StreamFormat::Raw) => ("stdout".to_string(), "raw RGBA8 stream".to_string()),
    };
    let frames = r.frames.len();
    let mut text =
        format!("rendered {} → {to}: {frames} frame{} at {}x{} ({what})\n", r.name, if frames == 1 { "" } else { "s" }, r.size.0, r.size.1);
    if verbose {
        text.push_str(&format!("  scene: {}\n", r.scene));
    }
    if let (true, Some(p)) = (explain || verbose, &r.passes) {
        text.push_str(p);
    }
    for f in &r.frames {
        if let Some((nan, pinf, ninf)) = f.non_finite {
            text.push_str(&format!("  frame {:4} t={:.3}s: {nan} NaN, {pinf} +Inf, {ninf} -Inf pixels\n", f.index, f.time));
        }
    }
    if timings && !r.frames.is_empty() {
        let clock = match r.clock {
            GpuClock::Timestamps => "GPU timestamps",
            GpuClock::Wall => "wall time from submit to completion",
        };
        text.push_str(&format!("  timings (GPU ms: {clock}; CPU ms: prepare, submit, unpack):\n"));
        for f in &r.frames {
            text.push_str(&format!("    frame {:4} t={:8.3}s  gpu {:8.3} ms  cpu {:7.3} ms\n", f.index, f.time, f.gpu_ms, f.cpu_ms));
        }
        let mut gpu: Vec<f64> = r.frames.iter().map(|f| f.gpu_ms).collect();
        gpu.sort_by(f64::total_cmp);
        text.push_str(&format!("    median gpu {:.3} ms/frame\n", gpu[gpu.len() / 2]));
        if let Some(t) = r.first_frame {
            let place = if r.stream.is_some() { "in the stream" } else { "on disk" };
            text.push_str(&format!("    first frame {place} {:.0} ms after start\n", t.as_secs_f64() * 1e3));
        }
    }
    text
}
