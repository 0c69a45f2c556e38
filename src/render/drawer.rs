//! One program made drawable: a checked program translated to WGSL ([`prepare`]), then its
//! scene or pass graph built on the device ([`build`]) as a [`Drawer`] that draws frames.
//! `effectc render` writes what it draws to files; `bench` and `stress` draw in memory
//! ([`crate::render::memory`]) with other uniform values or a degenerate mesh.

use std::time::Duration;

use crate::assets::camera;
use crate::assets::degenerate::Degenerate;
use crate::back::units;
use crate::back::{Target as BackTarget, TranslateOptions, Translation};
use crate::check::{self, Outcome, Unit};
use crate::diag::{Diagnostic, FileId};
use crate::manifest::{CameraDecl, Effect, ModelDecl, UniformValue};
use crate::render::compute::{is_compute_only, ComputeScene};
use crate::render::device::Gpu;
use crate::render::frames::{self, Frame, FrameError, FrameTarget, GpuClock};
use crate::render::pass_graph::{GraphOptions, PassGraph, PassProgram};
use crate::render::scene::{ColorMode, Scene, SceneInput};
use crate::render::semantics::FrameState;

/// Default frame size.
pub const DEFAULT_SIZE: (u32, u32) = (512, 512);

/// What building a program needs from the command's settings.
#[derive(Debug, Clone, Copy)]
pub struct BuildSettings {
    pub back: TranslateOptions,
    /// `None`: the manifest's `[render] size`, else [`DEFAULT_SIZE`].
    pub size: Option<(u32, u32)>,
    /// Multi-pass effects: every pass and target kept (nothing pruned or shared).
    pub dump_targets: bool,
    /// Time each frame on the GPU with timestamp queries (when the adapter has them);
    /// otherwise the wall time of the wait stands in. The queries cost a second readback
    /// per frame, so only `--timings` and `bench` ask for them.
    pub timestamps: bool,
    /// Uniforms nobody set are zero, as in GL, instead of guessed.
    pub gl_defaults: bool,
}

/// Changes a translation before it is built (`stress` instruments it): called with the
/// unit it was translated from.
pub type Instrument<'a> = &'a dyn Fn(&Unit, &mut Translation) -> Result<(), String>;

/// A checked program translated to WGSL: one unit for a single-pass program, one per
/// running pass for a multi-pass effect.
pub(crate) struct Translated {
    /// (pass index, translation, WGSL); the index is 0 for a single-pass program.
    pub(crate) units: Vec<(usize, Translation, String)>,
    /// The pass plan of a multi-pass effect, at the frame size.
    pub(crate) plan: Option<crate::graph::PassPlan>,
}

/// Translates what `c` draws; diagnostics go to `outcome`. `None` when there is nothing
/// to draw (check or translation errors).
pub(crate) fn prepare(
    c: &check::Checked,
    outcome: &mut Outcome,
    settings: &BuildSettings,
    instrument: Option<Instrument<'_>>,
) -> Option<Translated> {
    if c.failed {
        return None;
    }
    if let Some(d) = &c.untranslatable {
        outcome.diagnostics.push(d.clone());
        return None;
    }
    let plan = match (c.multi_pass(), &c.plan) {
        (Some(effect), Some(plan)) => {
            let size = settings.size.or(effect.render.size).unwrap_or(DEFAULT_SIZE);
            Some(if settings.dump_targets { crate::graph::plan(effect, size, true) } else { plan.sized(effect, size) })
        }
        _ => None,
    };
    let mut units = Vec::new();
    for unit in c.units.iter().filter(|u| plan.as_ref().map_or(u.runs, |p| p.runs[u.pass])) {
        let mut translation = match units::translate_unit(unit, settings.back) {
            Ok(t) => t,
            Err(diags) => {
                outcome.diagnostics.extend(diags);
                return None;
            }
        };
        if let Some(instrument) = instrument {
            if let Err(message) = instrument(unit, &mut translation) {
                outcome.diagnostics.push(crate::back::internal_error(translation.file, message));
                return None;
            }
        }
        let wgsl = match units::emit_contained(&translation, BackTarget::Wgsl) {
            Ok(o) => String::from_utf8_lossy(&o[0].bytes).into_owned(),
            Err(e) => {
                outcome.diagnostics.push(units::target_error(translation.file, BackTarget::Wgsl, &e));
                return None;
            }
        };
        units.push((unit.pass, translation, wgsl));
    }
    (!units.is_empty()).then_some(Translated { units, plan })
}

/// What draws the frames of one program.
pub(crate) enum Drawer {
    Single {
        scene: Box<Scene>,
        target: Box<FrameTarget>,
    },
    Graph(Box<PassGraph>),
    /// A compute-only program: dispatched over the frame, its stored image shown.
    Compute(Box<ComputeScene>),
}

impl Drawer {
    pub(crate) fn name(&self) -> &str {
        match self {
            Drawer::Single { scene, .. } => &scene.name,
            Drawer::Graph(g) => &g.name,
            Drawer::Compute(c) => &c.name,
        }
    }
    pub(crate) fn warnings(&mut self) -> &mut Vec<Diagnostic> {
        match self {
            Drawer::Single { scene, .. } => &mut scene.warnings,
            Drawer::Graph(g) => &mut g.warnings,
            Drawer::Compute(c) => &mut c.warnings,
        }
    }
    pub(crate) fn camera(&self) -> &CameraDecl {
        match self {
            Drawer::Single { scene, .. } => &scene.camera,
            Drawer::Graph(g) => &g.camera,
            Drawer::Compute(c) => &c.camera,
        }
    }
    pub(crate) fn model(&self) -> &ModelDecl {
        match self {
            Drawer::Single { scene, .. } => &scene.model,
            Drawer::Graph(g) => &g.model,
            Drawer::Compute(c) => &c.model,
        }
    }
    pub(crate) fn clock(&self) -> GpuClock {
        match self {
            Drawer::Single { target, .. } => target.clock(),
            Drawer::Graph(g) => g.clock(),
            Drawer::Compute(_) => frames::GpuClock::Wall,
        }
    }
    pub(crate) fn describe(&self) -> String {
        match self {
            Drawer::Single { scene, .. } => scene.describe.clone(),
            Drawer::Graph(g) => format!("{} passes run", g.plan.running().count()),
            Drawer::Compute(c) => c.describe.clone(),
        }
    }
    /// Every scene drawn, with its index into `Effect::passes` (0 for a single pass; none
    /// for a compute program, which draws no scene).
    pub(crate) fn scenes(&self) -> Box<dyn Iterator<Item = (usize, &Scene)> + '_> {
        match self {
            Drawer::Single { scene, .. } => Box::new(std::iter::once((0, &**scene))),
            Drawer::Graph(g) => Box::new(g.scenes()),
            Drawer::Compute(_) => Box::new(std::iter::empty()),
        }
    }
    pub(crate) fn scenes_mut(&mut self) -> Box<dyn Iterator<Item = (usize, &mut Scene)> + '_> {
        match self {
            Drawer::Single { scene, .. } => Box::new(std::iter::once((0, &mut **scene))),
            Drawer::Graph(g) => Box::new(g.scenes_mut()),
            Drawer::Compute(_) => Box::new(std::iter::empty()),
        }
    }
    /// Where used RGBA8 frame buffers go back for reuse (single-scene drawers).
    pub(crate) fn spare(&self) -> Option<frames::Spare> {
        match self {
            Drawer::Single { target, .. } => Some(target.spare.clone()),
            Drawer::Graph(_) | Drawer::Compute(_) => None,
        }
    }
    pub(crate) fn draw(&mut self, gpu: &Gpu, state: &FrameState, timeout: Duration) -> Result<Frame, FrameError> {
        match self {
            Drawer::Single { scene, target } => frames::render(gpu, scene, target, state, timeout),
            Drawer::Graph(g) => g.render(gpu, state, timeout),
            Drawer::Compute(c) => c.draw(gpu, state, timeout),
        }
    }
}

/// What a build changes from the manifest (`effectc bench`, `effectc stress`).
#[derive(Default, Clone, Copy)]
pub(crate) struct BuildVariant<'a> {
    /// Uniform values in place of the manifest's.
    pub overrides: &'a [(String, UniformValue)],
    /// A degenerate variant of the mesh.
    pub degenerate: Option<Degenerate>,
}

/// Builds the scene (or the pass graph) of a prepared program; also returns the file
/// program-wide diagnostics point at.
pub(crate) fn build(
    gpu: &Gpu,
    prepared: &Translated,
    c: &check::Checked,
    (size, mode): ((u32, u32), ColorMode),
    settings: &BuildSettings,
    variant: BuildVariant<'_>,
) -> Result<(Drawer, FileId), Vec<Diagnostic>> {
    let BuildVariant { overrides, degenerate } = variant;
    // `--set` values first, the variant's (a bench knob, a stress case) over them.
    let mut merged: Vec<(String, UniformValue)> =
        c.values.iter().filter(|(n, _)| !overrides.iter().any(|(m, _)| m == n)).cloned().collect();
    merged.extend(overrides.iter().cloned());
    let overrides = &merged[..];
    let flipped_y = settings.back.flip_y;
    let with_overrides = |e: &Effect| with_overrides(e, overrides);
    match (&prepared.plan, c.multi_pass()) {
        (Some(plan), Some(effect)) => {
            let views: Vec<(usize, Effect, &Unit)> =
                c.units.iter().filter_map(|u| Some((u.pass, with_overrides(u.effect.as_ref()?), u))).collect();
            let programs: Vec<PassProgram<'_>> = prepared
                .units
                .iter()
                .filter_map(|(i, t, wgsl)| {
                    let (_, view, unit) = views.iter().find(|(p, _, _)| p == i)?;
                    Some(PassProgram { index: *i, translation: t, wgsl, program: &unit.program, view })
                })
                .collect();
            let options = GraphOptions {
                mode,
                flipped_y,
                dump: settings.dump_targets,
                output_size: size,
                degenerate,
                gl_defaults: settings.gl_defaults,
            };
            let graph = PassGraph::new(gpu, effect, plan.clone(), &programs, options)?;
            Ok((Drawer::Graph(Box::new(graph)), effect.file))
        }
        _ => {
            let (_, translation, wgsl) = &prepared.units[0];
            let unit = &c.units[0];
            let effect = unit.effect.as_ref().map(with_overrides);
            let input = SceneInput {
                translation,
                wgsl,
                program: &unit.program,
                effect: effect.as_ref(),
                mode,
                flipped_y,
                pass: None,
                degenerate,
                overrides,
                gl_defaults: settings.gl_defaults,
            };
            if is_compute_only(&translation.reflection) {
                let scene = ComputeScene::new(gpu, &input, size)?;
                return Ok((Drawer::Compute(Box::new(scene)), translation.file));
            }
            let scene = Scene::new(gpu, &input)?;
            let target = FrameTarget::new(gpu, &scene, (size.0, size.1, mode), settings.timestamps);
            Ok((Drawer::Single { scene: Box::new(scene), target: Box::new(target) }, translation.file))
        }
    }
}

/// The per-frame values of frame `index` at effect time `time`.
pub(crate) fn frame_state(drawer: &Drawer, index: u32, time: f64, step: f64, (w, h): (u32, u32)) -> FrameState {
    let aspect = w as f32 / h as f32;
    FrameState {
        index,
        time,
        delta: step,
        size: (w, h),
        view: camera::view_at(drawer.camera(), time, aspect),
        model: camera::model_at(drawer.model(), time),
    }
}

/// `effect` with the values of `overrides` in place of the manifest's.
pub fn with_overrides(effect: &Effect, overrides: &[(String, UniformValue)]) -> Effect {
    let mut e = effect.clone();
    for (name, value) in overrides {
        if let Some(u) = e.uniforms.iter_mut().find(|u| u.name == *name) {
            u.value = Some(value.clone());
        }
    }
    e
}
