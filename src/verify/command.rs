//! `effectc verify`: every program drawn twice — the translation through wgpu exactly as
//! `render` draws it, and the user's original GLSL through the system's OpenGL driver with
//! the same scene — and every frame compared. A frame beyond the tolerance is E0503, with
//! the three pictures (translation, GL, heat map) written beside each other.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use serde::Serialize;

use crate::check::{Checked, Outcome};
use crate::diag::{Code, Diagnostic, FileId, Files};
use crate::front::reference::compiler::Dialect;
use crate::output::{self, write_atomic};
use crate::render::command::{open_once, Request, TimeStep, DEFAULT_FPS};
use crate::render::device::Gpu;
use crate::render::drawer::{build, frame_state, prepare, BuildVariant, Drawer, DEFAULT_SIZE};
use crate::render::encode;
use crate::render::frames::{Frame, FrameError, Pixels};
use crate::render::scene::ColorMode;
use crate::render::semantics::FrameState;
use crate::stage::StageKind;

use super::context::GlContext;
use super::diff::{self, FrameDiff, Tolerance};
use super::gl_frame::{GlFrames, PassTargets};
use super::gl_scene::GlScene;
use super::program;

/// What `verify` was asked to do: a render request (frames, times, size, `--set`, output
/// directory) and a tolerance over the manifests' own.
#[derive(Debug, Clone)]
pub struct VerifyRequest {
    pub render: Request,
    /// `--tolerance`: per-channel difference that still matches (0–255).
    pub tolerance: Option<u8>,
    /// `--max-differing`: percent of pixels allowed beyond the tolerance.
    pub max_differing: Option<f64>,
}

/// One frame's comparison.
#[derive(Debug, Clone, Serialize)]
pub struct FrameVerdict {
    pub index: u32,
    pub time: f64,
    #[serde(flatten)]
    pub diff: FrameDiff,
    /// The translation's frame, GL's frame, and the heat map when any pixel differs.
    pub files: Vec<PathBuf>,
}

/// One verified program.
#[derive(Debug, Clone, Serialize)]
pub struct Verified {
    pub name: String,
    pub size: (u32, u32),
    pub tolerance: Tolerance,
    /// Channels compared (the output's components: GL leaves the others undefined).
    pub channels: usize,
    pub frames: Vec<FrameVerdict>,
    /// Every frame within the tolerance.
    pub matches: bool,
}

/// The result of a run.
pub struct RunResult {
    pub outcome: Outcome,
    pub verified: Vec<Verified>,
    /// The wgpu adapter and the GL renderer.
    pub adapter: Option<String>,
    pub gl: Option<String>,
}

/// Runs check, translation, both renderers and the comparison for every program.
pub fn run(request: &VerifyRequest) -> RunResult {
    prefer_newest_glsl();
    let (mut outcome, checked) = request.render.input.check();
    let mut result = RunResult { outcome: Outcome::default(), verified: Vec::new(), adapter: None, gl: None };
    let inputs = output::input_paths(&outcome, &request.render.input.paths);
    let mut gpu: Option<Gpu> = None;
    let mut gl: Option<GlContext> = None;
    let crashed = super::isolation::crashed();
    for (index, c) in checked.iter().enumerate() {
        if let Some((_, signal)) = crashed.iter().find(|(i, _)| *i == index) {
            if let Some(stage) = c.units.first().and_then(|u| u.program.stages.first()) {
                let name = c.effect.as_ref().map_or(c.name.as_str(), |e| e.name.as_str());
                outcome.diagnostics.push(super::isolation::crash_diagnostic(name, stage.syntax.file, *signal));
            }
            continue;
        }
        super::isolation::drawing(index);
        if let Some(d) = vulkan_dialect(c) {
            outcome.diagnostics.push(d);
            continue;
        }
        let settings = request.render.build_settings();
        let Some(prepared) = prepare(c, &mut outcome, &settings, None) else { continue };
        let Some(gpu) = open_once(&mut gpu, &mut result.adapter, &mut outcome) else { break };
        let Some(gl) = open_gl(&mut gl, &mut result.gl, &mut outcome) else { break };
        let render = c.effect.as_ref().map(|e| e.render.clone()).unwrap_or_default();
        let size = request.render.size.or(render.size).unwrap_or(DEFAULT_SIZE);
        let (mut drawer, file) = match build(gpu, &prepared, c, (size, ColorMode::Unorm8), &settings, BuildVariant::default()) {
            Ok(d) => d,
            Err(diags) => {
                outcome.diagnostics.extend(diags);
                continue;
            }
        };
        outcome.diagnostics.append(drawer.warnings());
        if matches!(drawer, Drawer::Compute(_)) {
            outcome.diagnostics.push(
                Diagnostic::new(Code::Unrenderable, "`verify` compares drawn frames with GL's; this program is compute only")
                    .in_file(file)
                    .with_help("`effectc render` dispatches it and shows the image it stores"),
            );
            continue;
        }
        let mut original = match GlDrawer::new(&gl.gl, &outcome.files, c, &drawer) {
            Ok(o) => o,
            Err(diags) => {
                outcome.diagnostics.extend(diags);
                continue;
            }
        };
        let tolerance = tolerance(request, c);
        let undefined = undefined_behaviour(&outcome, c);
        let plan = Plan {
            frames: request.render.frames.or(render.frames).unwrap_or(1),
            size,
            step: match request.render.step {
                TimeStep::Fps(f) => 1.0 / f,
                TimeStep::Seconds(s) => s,
                TimeStep::Default => 1.0 / render.fps.unwrap_or(DEFAULT_FPS),
            },
            start: request.render.start,
            dir: request.render.out.clone().unwrap_or_else(|| Path::new("out").join(drawer.name()).join("verify")),
            tolerance,
            undefined,
        };
        let run = FrameRun { gpu, gl, plan: &plan, request, file };
        let verified = compare_frames(&run, &mut drawer, &mut original, &inputs, &mut outcome);
        original.delete(&gl.gl);
        if let Some(v) = verified {
            result.verified.push(v);
        }
    }
    super::isolation::drawn_all();
    crate::diag::sort(&mut outcome.diagnostics);
    result.outcome = outcome;
    result
}

/// Mesa compiles GLSL 4.60 only when told to; a driver that has it anyway ignores these.
fn prefer_newest_glsl() {
    for (k, v) in [("MESA_GL_VERSION_OVERRIDE", "4.6COMPAT"), ("MESA_GLSL_VERSION_OVERRIDE", "460")] {
        if std::env::var_os(k).is_none() {
            // Set before any thread reads the environment (check has not started yet).
            std::env::set_var(k, v);
        }
    }
}

/// Vulkan GLSL is not a GL program: there is nothing to compare with.
fn vulkan_dialect(c: &Checked) -> Option<Diagnostic> {
    let unit = c.units.first()?;
    let judgement = unit.program.reference.as_ref()?;
    matches!(judgement.dialect, Dialect::Vulkan(_)).then(|| {
        Diagnostic::new(Code::NotAGlProgram, format!("`{}` is Vulkan GLSL: an OpenGL driver cannot draw it, so there is nothing to verify against", c.name))
            .in_file(unit.program.stages[0].syntax.file)
            .with_note("verify compares a translation with the original program on the system's OpenGL driver; Vulkan GLSL (set/binding layouts, push constants) is not GLSL for GL")
            .with_help("render it with `effectc render`; verify the GL version of the effect if there is one")
    })
}

/// The GL context, opened on first use. `None`: E0501 is in `outcome` (exit 2).
fn open_gl<'g>(gl: &'g mut Option<GlContext>, describe: &mut Option<String>, outcome: &mut Outcome) -> Option<&'g GlContext> {
    if gl.is_none() {
        match GlContext::new() {
            Ok(c) => {
                *describe = Some(c.describe.clone());
                *gl = Some(c);
            }
            Err(e) => {
                outcome.io_error = true;
                outcome.diagnostics.push(
                    Diagnostic::new(Code::NoGlDriver, "no OpenGL driver to verify against").with_note(e.0).with_help(
                        "install the driver: `apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri` (Mesa; or the GPU vendor's)",
                    ),
                );
            }
        }
    }
    gl.as_ref()
}

/// The flags' tolerance over the manifest's over the default.
fn tolerance(request: &VerifyRequest, c: &Checked) -> Tolerance {
    let decl = c.effect.as_ref().map(|e| e.verify).unwrap_or_default();
    let default = Tolerance::default();
    Tolerance {
        channel: request.tolerance.or(decl.tolerance).unwrap_or(default.channel),
        fraction: request.max_differing.or(decl.max_differing).map_or(default.fraction, |p| p / 100.0),
    }
}

/// The channels of the compared target that the program writes: the components of the
/// fragment output at its location, at most the target format's.
fn written_channels(drawer: &Drawer, output: &str) -> usize {
    let of = |scene: &crate::render::scene::Scene, location: u32, format: wgpu::TextureFormat| {
        let written = scene.replay.outputs.iter().find(|(l, _)| *l == location).map_or(4, |(_, c)| *c);
        let stored = format.components() as u32;
        written.min(stored).max(1) as usize
    };
    match drawer {
        Drawer::Single { scene, .. } => scene.colors.first().copied().flatten().map_or(4, |f| of(scene, 0, f)),
        Drawer::Compute(_) => 4,
        Drawer::Graph(g) => g
            .pass_views()
            .iter()
            .rev()
            .find_map(|v| {
                let (location, (_, format)) =
                    v.colors.iter().enumerate().find_map(|(i, c)| c.filter(|(n, _)| *n == output).map(|c| (i, c)))?;
                Some(of(v.scene, location as u32, format))
            })
            .unwrap_or(4),
    }
}

/// The original program drawn by GL: one scene per pass and the targets.
struct GlDrawer {
    scenes: Vec<GlScene>,
    frames: GlFrames,
    output: String,
    /// GL reads these without a value from the translation (they stay 0 in GL).
    unmatched: Vec<String>,
    /// Channels of the frame the program writes (a `vec2` output: 2); GL leaves the
    /// others undefined, so only these are compared.
    channels: usize,
    /// GL draws with its initial (identity) matrices: bare stage files, or a program
    /// without a vertex stage.
    initial_matrices: bool,
}

impl GlDrawer {
    fn new(gl: &glow::Context, files: &Files, c: &Checked, drawer: &Drawer) -> Result<GlDrawer, Vec<Diagnostic>> {
        let mut frames = GlFrames::new(gl).map_err(|e| vec![Diagnostic::new(Code::GlRejects, e)])?;
        let mut scenes = Vec::new();
        let mut unmatched = Vec::new();
        let mut fixed_function_vertex = false;
        let fail = |e: String, file: FileId| vec![Diagnostic::new(Code::GlRejects, e).in_file(file)];
        for (pass, scene) in drawer.scenes() {
            let Some(unit) = c.units.iter().find(|u| u.pass == pass) else { continue };
            // A stage effectc wrote for a lone fragment or vertex stage is what GL does
            // without one: GL runs its own fixed-function processing instead.
            fixed_function_vertex |=
                unit.program.stages.iter().any(|s| files.is_generated(s.syntax.file) && s.syntax.stage == StageKind::Vertex);
            let stages: Vec<(FileId, StageKind)> = unit
                .program
                .stages
                .iter()
                .filter(|s| !files.is_generated(s.syntax.file))
                // The shader objects of a stage effectc read joined, as GL links them.
                .flat_map(|s| match files.units_of(s.syntax.file) {
                    Some(units) => units.iter().map(|u| (*u, s.syntax.stage)).collect::<Vec<_>>(),
                    None => vec![(s.syntax.file, s.syntax.stage)],
                })
                .collect();
            let first = stages[0].0;
            let linked = program::link(gl, files, &stages)?;
            let s = GlScene::new(gl, linked, scene).map_err(|e| fail(e, first))?;
            unmatched.extend(s.uniforms.unmatched.iter().cloned());
            unmatched.extend(s.unfed_inputs.iter().map(|i| format!("vertex input `{i}`")));
            scenes.push(s);
        }
        let output = match drawer {
            Drawer::Compute(_) => return Err(fail("a compute program draws nothing GL could compare".into(), FileId(0))),
            Drawer::Graph(g) => {
                for v in g.pass_views() {
                    for (name, format) in v.colors.iter().flatten() {
                        frames.target(gl, name, *format, v.size).map_err(|e| fail(e, FileId(0)))?;
                    }
                    if let Some(d) = v.depth_target {
                        frames.target(gl, d, wgpu::TextureFormat::Depth32Float, v.size).map_err(|e| fail(e, FileId(0)))?;
                    }
                }
                g.output_target().to_string()
            }
            Drawer::Single { scene, target } => {
                for (i, f) in scene.colors.iter().enumerate() {
                    if let Some(f) = f {
                        frames.target(gl, &format!("output{i}"), *f, (target.width, target.height)).map_err(|e| fail(e, FileId(0)))?;
                    }
                }
                // A program with no colour output (a depth-only pass, image stores) shows
                // render's frame as it starts: zeros, never attached.
                frames
                    .target(gl, "output0", wgpu::TextureFormat::Rgba8Unorm, (target.width, target.height))
                    .map_err(|e| fail(e, FileId(0)))?;
                "output0".to_string()
            }
        };
        let channels = written_channels(drawer, &output);
        // Bare stage files draw with GL's initial matrices (identity), a manifest's scene with its camera.
        let initial_matrices = fixed_function_vertex || c.effect.is_none();
        Ok(GlDrawer { scenes, frames, output, unmatched, channels, initial_matrices })
    }

    /// Draws one frame with the uniform values the wgpu scenes hold now (after their frame).
    fn draw(&mut self, gl: &glow::Context, drawer: &Drawer, state: &FrameState) -> Result<Vec<u8>, String> {
        // SAFETY: the context is current on this thread.
        unsafe { super::fixed_function::load_matrices((!self.initial_matrices).then_some(state))? };
        match drawer {
            Drawer::Single { scene, target } => {
                let names: Vec<String> = (0..scene.colors.len()).map(|i| format!("output{i}")).collect();
                let at = PassTargets {
                    colors: scene.colors.iter().zip(&names).map(|(f, n)| f.map(|_| n.as_str())).collect(),
                    depth: None,
                    own_depth: scene.replay.depth,
                    keep_depth: false,
                    clear: Some(scene.clear),
                    size: (target.width, target.height),
                    samples: &[],
                };
                self.frames.draw(gl, &mut self.scenes[0], scene, &at)?;
            }
            Drawer::Compute(_) => return Err("a compute program draws nothing GL could compare".into()),
            Drawer::Graph(g) => {
                for (v, s) in g.pass_views().iter().zip(&mut self.scenes) {
                    let at = PassTargets {
                        colors: v.colors.iter().map(|c| c.map(|(n, _)| n)).collect(),
                        depth: v.depth_target,
                        own_depth: v.own_depth,
                        keep_depth: v.keep_depth,
                        clear: v.clear,
                        size: v.size,
                        samples: v.samples,
                    };
                    self.frames.draw(gl, s, v.scene, &at)?;
                }
            }
        }
        self.frames.read(gl, &self.output).ok_or_else(|| format!("GL has no target `{}` to read", self.output))
    }

    fn delete(self, gl: &glow::Context) {
        for s in self.scenes {
            s.delete(gl);
        }
        self.frames.delete(gl);
    }
}

struct Plan {
    frames: u32,
    size: (u32, u32),
    step: f64,
    start: f64,
    dir: PathBuf,
    tolerance: Tolerance,
    /// Where the program does what GLSL leaves undefined (`path:line: message`).
    undefined: Vec<String>,
}

/// Codes of the check findings about behaviour GLSL leaves undefined (or that WebGPU
/// cannot have), where an OpenGL driver and WebGPU may legitimately draw differently:
/// `gl_PointCoord` is undefined outside points, and WebGPU has no point sizes.
const UNDEFINED: [Code; 5] =
    [Code::HazardNegativeRemainder, Code::HazardShift, Code::HazardAtan2, Code::HazardDivision, Code::PointCoordConstant];

/// The program's warnings about undefined behaviour, as `path:line: message`.
fn undefined_behaviour(outcome: &Outcome, c: &Checked) -> Vec<String> {
    let files: Vec<FileId> = c.units.iter().flat_map(|u| u.program.stages.iter().map(|s| s.syntax.file)).collect();
    outcome
        .diagnostics
        .iter()
        .filter(|d| UNDEFINED.contains(&d.code) && d.file.is_some_and(|f| files.contains(&f)))
        .map(|d| {
            let file = d.file.unwrap_or(FileId(0));
            let line = d.span.as_ref().map_or(0, |s| outcome.files.line_col(file, s.start).0);
            format!("{}:{line}: {} ({})", outcome.files.path(file), d.message, d.code.as_str())
        })
        .collect()
}

/// Draws and compares every frame; mismatches become E0503 in `outcome`. The pictures
/// are encoded and written on a second thread while the next frame draws.
fn compare_frames(
    run: &FrameRun<'_>,
    drawer: &mut Drawer,
    original: &mut GlDrawer,
    inputs: &BTreeSet<PathBuf>,
    outcome: &mut Outcome,
) -> Option<Verified> {
    let plan = run.plan;
    let name = drawer.name().to_owned();
    let (tx, rx) = std::sync::mpsc::channel::<Vec<(PathBuf, Vec<u8>)>>();
    let (frames, failed) = std::thread::scope(|s| {
        let writer = s.spawn(move || write_pictures(rx, plan.size, inputs));
        let frames = draw_and_compare(run, drawer, original, outcome, &name, &tx);
        drop(tx);
        (frames, writer.join().unwrap_or_default())
    });
    let mut frames = frames?;
    let (unwritten, error) = failed;
    if let Some(e) = error {
        outcome.io_error = true;
        outcome.diagnostics.push(Diagnostic::new(Code::OutputIo, e));
    }
    frames.iter_mut().for_each(|f| f.files.retain(|p| !unwritten.contains(p)));
    let matches = frames.iter().all(|f| f.diff.matches);
    Some(Verified { name, size: plan.size, tolerance: plan.tolerance, channels: original.channels, frames, matches })
}

/// What every frame of one program is drawn and compared with.
struct FrameRun<'a> {
    gpu: &'a Gpu,
    gl: &'a GlContext,
    plan: &'a Plan,
    request: &'a VerifyRequest,
    /// The file program-wide diagnostics point at.
    file: FileId,
}

/// The frame loop: both drawings, the comparison, the pictures sent to the writer.
fn draw_and_compare(
    run: &FrameRun<'_>,
    drawer: &mut Drawer,
    original: &mut GlDrawer,
    outcome: &mut Outcome,
    name: &str,
    pictures: &std::sync::mpsc::Sender<Vec<(PathBuf, Vec<u8>)>>,
) -> Option<Vec<FrameVerdict>> {
    let FrameRun { gpu, gl, plan, request, file } = *run;
    let mut frames = Vec::new();
    for i in 0..plan.frames {
        let time = plan.start + f64::from(i) * plan.step;
        let state = frame_state(drawer, i, time, plan.step, plan.size);
        let translated = match drawer.draw(gpu, &state, request.render.timeout.unwrap_or_else(|| gpu.default_frame_timeout())) {
            Ok(Frame { pixels: Pixels::Rgba8(p), .. }) => p,
            Ok(_) => return None,
            Err(FrameError::Timeout(t)) => {
                outcome.diagnostics.push(
                    Diagnostic::new(Code::FrameTimeout, format!("frame {i} did not finish within {:.1} s", t.as_secs_f64())).in_file(file),
                );
                return None;
            }
            Err(FrameError::Device(e)) => {
                outcome
                    .diagnostics
                    .push(Diagnostic::new(Code::FrameFailed, format!("frame {i} failed on the device")).in_file(file).with_note(e));
                return None;
            }
        };
        let reference = match original.draw(&gl.gl, drawer, &state) {
            Ok(p) => p,
            Err(e) => {
                outcome.diagnostics.push(
                    Diagnostic::new(Code::GlRejects, format!("frame {i}: the OpenGL driver could not draw it")).in_file(file).with_note(e),
                );
                return None;
            }
        };
        let diff = diff::compare(&translated, &reference, plan.size, plan.tolerance, original.channels);
        let mut frame_pictures = Vec::new();
        if diff.max_channel > 0 {
            let heat = diff::heat_map(&translated, &reference, plan.tolerance, original.channels);
            frame_pictures.push((plan.dir.join(format!("{name}_{i:04}_diff.png")), heat));
        }
        frame_pictures.push((plan.dir.join(format!("{name}_{i:04}.png")), translated));
        frame_pictures.push((plan.dir.join(format!("{name}_{i:04}_gl.png")), reference));
        let mut files: Vec<PathBuf> = frame_pictures.iter().map(|(p, _)| p.clone()).collect();
        files.rotate_left(usize::from(diff.max_channel > 0));
        if !diff.matches {
            outcome.diagnostics.push(mismatch(i, &diff, plan, &files, &original.unmatched, file));
        }
        let _ = pictures.send(frame_pictures);
        frames.push(FrameVerdict { index: i, time, diff, files });
    }
    Some(frames)
}

/// Encodes and writes the pictures it receives (each frame's in parallel); returns the
/// files not written and the first error. After a failure nothing more is written (a
/// full disk stays full), and the error is said once.
fn write_pictures(
    rx: std::sync::mpsc::Receiver<Vec<(PathBuf, Vec<u8>)>>,
    (w, h): (u32, u32),
    inputs: &BTreeSet<PathBuf>,
) -> (Vec<PathBuf>, Option<String>) {
    use rayon::prelude::*;
    let mut unwritten = Vec::new();
    let mut error: Option<String> = None;
    for pictures in rx {
        if error.is_some() {
            unwritten.extend(pictures.into_iter().map(|(p, _)| p));
            continue;
        }
        let failed: Vec<(PathBuf, String)> = pictures
            .par_iter()
            .filter_map(|(path, rgba)| {
                encode::png_bytes(rgba, w, h).and_then(|bytes| write_atomic(path, &bytes, inputs)).err().map(|e| (path.clone(), e))
            })
            .collect();
        for (path, e) in failed {
            unwritten.push(path);
            error.get_or_insert(e);
        }
    }
    (unwritten, error)
}

fn mismatch(i: u32, d: &FrameDiff, plan: &Plan, files: &[PathBuf], unmatched: &[String], file: FileId) -> Diagnostic {
    let tol = plan.tolerance;
    let percent = 100.0 * d.over as f64 / d.pixels.max(1) as f64;
    let psnr = d.psnr.map_or("∞".to_string(), |p| format!("{p:.1}"));
    let mut diag = Diagnostic::new(
        Code::FramesDiffer,
        format!(
            "frame {i}: the translation draws a different picture than the OpenGL driver: {} pixels ({percent:.2}%) differ by more than {}/255",
            d.over, tol.channel
        ),
    )
    .in_file(file)
    .with_note(format!("largest channel difference {}/255, PSNR {psnr} dB; allowed: {:.2}% of the pixels", d.max_channel, tol.fraction * 100.0));
    if let Some((x, y)) = d.first_over {
        diag = diag.with_note(format!("first differing pixel at ({x}, {y}) from the top left"));
    }
    if let Some(heat) = files.iter().find(|f| f.to_string_lossy().ends_with("_diff.png")) {
        diag = diag.with_note(format!("heat map: {} (blue within the tolerance, red to yellow beyond it)", heat.display()));
    }
    if !plan.undefined.is_empty() {
        diag = diag.with_note(format!(
            "the program does what GLSL leaves undefined, where OpenGL and WebGPU may legitimately differ: {}",
            plan.undefined.join("; ")
        ));
    }
    if !unmatched.is_empty() {
        diag = diag.with_note(format!("GL reads values the translation does not feed (they stay 0 in GL): {}", unmatched.join(", ")));
    }
    diag.with_help("set `[verify] tolerance`/`max_differing` in the manifest (or `--tolerance`) when the difference is expected")
}

/// Human summary of one verified program.
pub fn summary(v: &Verified) -> String {
    let ok = v.frames.iter().filter(|f| f.diff.matches).count();
    let mut text = format!(
        "verified {}: {ok}/{} frame{} match the OpenGL driver at {}x{} (tolerance {}/255 on ≤ {:.2}% of the pixels)\n",
        v.name,
        v.frames.len(),
        if v.frames.len() == 1 { "" } else { "s" },
        v.size.0,
        v.size.1,
        v.tolerance.channel,
        v.tolerance.fraction * 100.0
    );
    if v.channels < 4 {
        let names = ["red", "green", "blue", "alpha"][..v.channels].join(", ");
        text.push_str(&format!("  compared {names} only: the output has {} component(s), GL leaves the rest undefined\n", v.channels));
    }
    for f in &v.frames {
        let psnr = f.diff.psnr.map_or("identical".to_string(), |p| format!("PSNR {p:.1} dB"));
        text.push_str(&format!(
            "  frame {:4} t={:.3}s: {} — max difference {}/255, {} pixels over, {psnr}\n",
            f.index,
            f.time,
            if f.diff.matches { "match" } else { "DIFFERS" },
            f.diff.max_channel,
            f.diff.over
        ));
    }
    text
}
