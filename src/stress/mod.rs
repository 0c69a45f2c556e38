//! `effectc stress`: renders every program into float targets under stiff and extreme
//! inputs and counts the NaN and Inf pixels of each case.
//!
//! Cases, each one frame:
//! - `nominal`: the manifest's defaults at time 0 (the frame the others are compared with);
//! - every ranged uniform at its low and at its high end, the others nominal;
//! - all ranged uniforms low, all high;
//! - `--samples` random points of the ranges (seeded, so a run is repeatable);
//! - extreme times 1e3, 1e5 and 1e7 s with the defaults;
//! - degenerate geometry ([`Degenerate`]): every normal zero; every second triangle
//!   collapsed to zero area (only where the program draws a mesh whose data it reads).
//!
//! Every case renders twice: plain, for the pixels, and instrumented
//! ([`crate::stress::culprit`]), where each vertex and fragment invocation counts the
//! first expression that computed a non-finite value. A case with NaN or Inf pixels is an error (`E0701`)
//! at the manifest entry it changed, labelled with those expressions in the GLSL, and its
//! mask is written next to the frames (NaN red, +Inf yellow, −Inf cyan). A case whose
//! pixels are finite but whose intermediate values are not is a warning (`W0702`).

pub mod confirm;
mod crossing;
pub mod culprit;
pub mod inputs;
mod ir;
pub mod sites;

use std::path::{Path, PathBuf};
use std::time::Duration;

use crate::assets::degenerate::Degenerate;
use crate::check::{self, Outcome};
use crate::diag::{Code, Diagnostic};
use crate::manifest::UniformValue;
use crate::render::command;
use crate::render::device::Gpu;
use crate::render::encode;
use crate::render::frames::Pixels;
use crate::render::memory::{MemoryDrawer, MemoryRequest, MemoryRun};
use crate::stage::StageKind;
use crate::stress::culprit::{Instrumented, Probe, StageCounts};
use crate::stress::inputs::{random_points, with_defaults, Declared};
pub use crate::stress::ir::COUNTS_BUFFER;

/// Effect times of the time cases (seconds).
pub const EXTREME_TIMES: [f64; 3] = [1e3, 1e5, 1e7];

/// What `stress` was asked to do.
#[derive(Debug, Clone)]
pub struct Request {
    pub input: check::InputSpec,
    /// Random points of the uniform ranges.
    pub samples: u32,
    pub seed: u32,
    pub size: (u32, u32),
    pub timeout: Duration,
    /// Masks of failing cases go here (`<effect>_<case>_nonfinite.png`); none when `None`.
    pub out: Option<PathBuf>,
    /// Put every hazard warning to a render instead ([`confirm`]).
    pub confirm: bool,
    /// Seconds of run time the hazard analysis assumed (`[hazards] time-limit`): the late
    /// cases of [`confirm`].
    pub time_limit: f64,
}

/// One input configuration.
#[derive(Debug, Clone, PartialEq)]
pub struct Case {
    pub name: String,
    pub overrides: Vec<(String, UniformValue)>,
    pub time: f64,
    pub degenerate: Option<Degenerate>,
}

/// One case's result.
#[derive(Debug, Clone, serde::Serialize)]
pub struct CaseReport {
    pub case: String,
    /// The changed uniforms and the time, as `name=value` text.
    pub values: String,
    pub nan: u64,
    pub inf: u64,
    /// Fragment invocations where some intermediate value was non-finite (all passes).
    pub bad_fragments: u64,
    /// Vertex invocations where some intermediate value was non-finite (all passes; 0 when
    /// the device cannot write storage from vertex shaders, see `StressReport::vertex_probes`).
    pub bad_vertices: u64,
    /// Largest absolute difference of a finite channel from the nominal frame.
    pub max_delta: f64,
    pub mask: Option<PathBuf>,
}

/// One program's cases.
#[derive(Debug, Clone, serde::Serialize)]
pub struct StressReport {
    pub program: String,
    pub size: (u32, u32),
    /// Whether the vertex stage was instrumented too.
    pub vertex_probes: bool,
    pub cases: Vec<CaseReport>,
}

pub struct StressResult {
    pub outcome: Outcome,
    pub reports: Vec<StressReport>,
    /// With [`Request::confirm`]: the verdicts on every program's hazard warnings.
    pub confirmed: Vec<confirm::ConfirmReport>,
    pub adapter: Option<String>,
}

/// The cases of a program with declared inputs `inputs` ([`inputs::declared`]): nominal
/// (every input at its default), each input low and high, all low, all high, `samples`
/// random points (on a `#pragma parameter`'s grid), extreme times, degenerate meshes.
pub fn cases(inputs: &[Declared], samples: u32, seed: u32) -> Vec<Case> {
    let case = |name: String, overrides: Vec<(String, UniformValue)>| Case { name, overrides, time: 0.0, degenerate: None };
    let at = |d: &Declared, x: f64| (d.name.clone(), fill(&d.default, &|_| d.on_grid(x)));
    let mut out = vec![case("nominal".into(), Vec::new())];
    for d in inputs {
        out.push(case(format!("{} low", d.name), vec![at(d, d.lo)]));
        out.push(case(format!("{} high", d.name), vec![at(d, d.hi)]));
    }
    if inputs.len() > 1 {
        out.push(case("all low".into(), inputs.iter().map(|d| at(d, d.lo)).collect()));
        out.push(case("all high".into(), inputs.iter().map(|d| at(d, d.hi)).collect()));
    }
    for (k, overrides) in random_points(inputs, samples, seed).into_iter().enumerate() {
        out.push(case(format!("random {}", k + 1), overrides));
    }
    for t in EXTREME_TIMES {
        out.push(Case { name: format!("time {t:e} s"), overrides: Vec::new(), time: t, degenerate: None });
    }
    for d in Degenerate::ALL {
        out.push(Case { name: d.name().into(), overrides: Vec::new(), time: 0.0, degenerate: Some(d) });
    }
    out
}

/// A number, or a list of numbers (a vector).
pub(crate) fn numeric(v: &UniformValue) -> bool {
    match v {
        UniformValue::Int(_) | UniformValue::Float(_) => true,
        UniformValue::List(items) => !items.is_empty() && items.iter().all(|i| matches!(i, UniformValue::Int(_) | UniformValue::Float(_))),
        UniformValue::Bool(_) => false,
    }
}

/// `template` with every component replaced by `value(component)`; integers stay integers.
pub(crate) fn fill(template: &UniformValue, value: &dyn Fn(u32) -> f64) -> UniformValue {
    let one = |t: &UniformValue, c: u32| match t {
        UniformValue::Int(_) => UniformValue::Int(value(c).round() as i64),
        _ => UniformValue::Float(value(c)),
    };
    match template {
        UniformValue::List(items) => UniformValue::List(items.iter().enumerate().map(|(c, t)| one(t, c as u32)).collect()),
        t => one(t, 0),
    }
}

pub(crate) fn show(v: &UniformValue) -> String {
    match v {
        UniformValue::Int(i) => i.to_string(),
        UniformValue::Float(f) => format!("{}", (f * 1e4).round() / 1e4),
        UniformValue::Bool(b) => b.to_string(),
        UniformValue::List(items) => format!("[{}]", items.iter().map(show).collect::<Vec<_>>().join(", ")),
    }
}

/// Runs check, then every case of every clean program.
pub fn run(request: &Request) -> StressResult {
    let (mut outcome, checked) = request.input.check();
    let mut result = StressResult { outcome: Outcome::default(), reports: Vec::new(), confirmed: Vec::new(), adapter: None };
    let mut gpu: Option<Gpu> = None;
    for c in checked.iter().filter(|c| !c.failed && !c.units.is_empty()) {
        let Some(gpu) = command::open_once(&mut gpu, &mut result.adapter, &mut outcome) else { break };
        if request.confirm {
            result.confirmed.extend(confirm::confirm_program(gpu, c, &mut outcome, request));
        } else if let Some(report) = stress_program(gpu, c, &mut outcome, request) {
            result.reports.push(report);
        }
    }
    crate::diag::sort(&mut outcome.diagnostics);
    result.outcome = outcome;
    result
}

fn stress_program(gpu: &Gpu, c: &check::Checked, outcome: &mut Outcome, request: &Request) -> Option<StressReport> {
    let effect = c.effect.as_ref();
    let program = effect.map_or(c.name.clone(), |e| e.name.clone());
    let (w, h) = request.size;
    let mut nominal: Option<Vec<f32>> = None;
    let mut reports = Vec::new();
    let plain_request = MemoryRequest {
        size: request.size,
        frames: 1,
        start: 0.0,
        step: 0.0,
        float: true,
        timeout: request.timeout,
        read_back: None,
        degenerate: None,
    };
    // Built once for every case that only changes uniform values or time. The pixels come
    // from the plain program: the instrumented one computes the same values, but the
    // driver compiles it differently and may fold a NaN another way.
    let inputs = inputs::declared(c);
    let defaults = with_defaults(&[], &inputs);
    let mut plain = MemoryDrawer::new(gpu, c, outcome, &defaults, plain_request, None)?;
    let (mut instrumented, probes) = Probed::build(gpu, c, outcome, &defaults, plain_request)?;
    for case in cases(&inputs, request.samples, request.seed) {
        // Every declared input the case does not move stays at its default.
        let all = with_defaults(&case.overrides, &inputs);
        // A case that cannot render (a timeout, a device error) is reported by the render path.
        let (run, probed) = match case.degenerate {
            Some(d) => {
                let m = MemoryRequest { degenerate: Some(d), ..plain_request };
                let run = MemoryDrawer::new(gpu, c, outcome, &all, m, None)?.render(gpu, outcome, case.time)?;
                if run.degenerate.is_empty() {
                    // No mesh the program reads is changed by this variant: nothing to learn.
                    continue;
                }
                let (mut program, probes) = Probed::build(gpu, c, outcome, &all, m)?;
                let probed = program.render(gpu, outcome, case.time)?;
                (run, probes.runs(&probed))
            }
            None => {
                let run = render_case(gpu, &mut plain, &all, case.time, outcome)?;
                let probed = render_case(gpu, &mut instrumented, &all, case.time, outcome)?;
                (run, probes.runs(&probed))
            }
        };
        let culprits = Culprit::all(&probed);
        let Some(Pixels::Rgba32F(frame)) = run.frames.into_iter().next() else { return None };
        let (counts, mask) = encode::non_finite(&frame, w, h);
        let max_delta = nominal.as_ref().map_or(0.0, |n| max_delta(n, &frame));
        let slug: String = case.name.chars().map(|ch| if ch.is_ascii_alphanumeric() { ch } else { '_' }).collect();
        let mask_path = match (mask, &request.out) {
            (Some(m), Some(dir)) => write_mask(dir, &format!("{program}_{slug}_nonfinite.png"), &m, w, h, outcome),
            _ => None,
        };
        let mut values: Vec<String> = case.overrides.iter().map(|(n, v)| format!("{n}={}", show(v))).collect();
        if case.time != 0.0 {
            values.push(format!("time={:e}", case.time));
        }
        let geometry: Vec<String> = run
            .degenerate
            .iter()
            .map(|(pass, what)| match c.multi_pass().and_then(|e| e.passes.get(*pass)) {
                Some(p) => format!("{}: {what}", p.name),
                None => what.clone(),
            })
            .collect();
        if !geometry.is_empty() {
            values.push(geometry.join("; "));
        }
        let inf = counts.pos_inf + counts.neg_inf;
        let bad = |stage: StageKind| probed.iter().flat_map(|p| &p.counts).filter(|s| s.stage == stage).map(|s| s.bad()).sum::<u64>();
        let (bad_fragments, bad_vertices) = (bad(StageKind::Fragment), bad(StageKind::Vertex));
        if counts.nan + inf > 0 {
            let d = case_error(c, &case, &program, (counts.nan, inf), mask_path.as_deref(), &geometry);
            outcome.diagnostics.push(with_culprits(d, c, &culprits));
        } else if !culprits.is_empty() {
            let d = Diagnostic::new(
                Code::StressHiddenNonFinite,
                format!("{program}: case `{}` computes non-finite values, though its output is finite", case.name),
            );
            let d = at_case(d, c, &case, &geometry);
            outcome.diagnostics.push(with_culprits(d, c, &culprits).with_help(
                "a NaN hidden by max/clamp/step, or by a triangle that covers no pixel, is a NaN on another GPU or mesh: guard the expression where it starts",
            ));
        }
        reports.push(CaseReport {
            case: case.name.clone(),
            values: values.join(" "),
            nan: counts.nan,
            inf,
            bad_fragments,
            bad_vertices,
            max_delta,
            mask: mask_path,
        });
        if nominal.is_none() {
            nominal = Some(frame);
        }
    }
    Some(StressReport { program, size: request.size, vertex_probes: gpu.vertex_storage(), cases: reports })
}

/// One frame of a built program with the case's uniform values, at its time.
fn render_case(
    gpu: &Gpu,
    program: &mut MemoryDrawer<'_>,
    values: &[(String, UniformValue)],
    time: f64,
    outcome: &mut Outcome,
) -> Option<MemoryRun> {
    if let Err(e) = program.set_overrides(values) {
        outcome.diagnostics.push(Diagnostic::new(Code::PipelineRejected, e));
        return None;
    }
    program.render(gpu, outcome, time)
}

fn max_delta(a: &[f32], b: &[f32]) -> f64 {
    a.iter().zip(b).filter(|(x, y)| x.is_finite() && y.is_finite()).map(|(x, y)| f64::from((x - y).abs())).fold(0.0, f64::max)
}

fn write_mask(dir: &Path, name: &str, rgba: &[u8], w: u32, h: u32, outcome: &mut Outcome) -> Option<PathBuf> {
    let path = dir.join(name);
    let bytes = match encode::png_bytes(rgba, w, h) {
        Ok(b) => b,
        Err(e) => {
            outcome.diagnostics.push(Diagnostic::new(Code::OutputIo, format!("cannot encode {}: {e}", path.display())));
            return None;
        }
    };
    match crate::output::write_atomic(&path, &bytes, &Default::default()) {
        Ok(()) => Some(path),
        Err(e) => {
            outcome.io_error = true;
            outcome.diagnostics.push(Diagnostic::new(Code::OutputIo, e));
            None
        }
    }
}

/// `E0701` at the manifest entry the case changed (the first), else at the manifest.
fn case_error(
    c: &check::Checked,
    case: &Case,
    program: &str,
    (nan, inf): (u64, u64),
    mask: Option<&Path>,
    geometry: &[String],
) -> Diagnostic {
    let d = Diagnostic::new(Code::StressNonFinite, format!("{program}: case `{}` renders {nan} NaN and {inf} Inf pixels", case.name));
    let mut d = at_case(d, c, case, geometry);
    if let Some(m) = mask {
        d = d.with_note(format!("mask: {} (NaN red, +Inf yellow, -Inf cyan)", m.display()));
    }
    d.with_help("guard the expression (clamp, max(x, eps), a branch) or narrow the uniform's `range`")
}

/// Places a case's diagnostic at the manifest entry it changed (the mesh for geometry
/// cases), with the values and what `geometry` says the mesh variant changed as notes.
fn at_case(mut d: Diagnostic, c: &check::Checked, case: &Case, geometry: &[String]) -> Diagnostic {
    let changed: Vec<String> = case.overrides.iter().map(|(n, v)| format!("{n} = {}", show(v))).collect();
    match (c.effect.as_ref(), case.overrides.first()) {
        (Some(e), Some((name, value))) => {
            if let Some(u) = e.uniform(name) {
                let span = u.range_span.clone().unwrap_or(u.name_span.clone());
                let label = match case.overrides.len() {
                    1 => format!("`{name}` = {} in this range", show(value)),
                    n => format!("`{name}` = {} (one of the {n} values this case sets)", show(value)),
                };
                d = d.at(e.file, span, label);
            } else {
                d = d.in_file(e.file);
            }
        }
        (Some(e), None) => match e.mesh.as_ref().filter(|_| case.degenerate.is_some()) {
            Some(mesh) => d = d.at(e.file, mesh.span.clone(), "this mesh, made degenerate"),
            None => d = d.in_file(e.file),
        },
        (None, _) => {
            if let Some(u) = c.units.first() {
                d = d.in_file(u.program.stages[0].syntax.file);
            }
        }
    }
    if !changed.is_empty() {
        d = d.with_note(format!("with {}", changed.join(", ")));
    }
    if case.time != 0.0 {
        d = d.with_note(format!("at effect time {:e} s", case.time));
    }
    for g in geometry {
        d = d.with_note(format!("degenerate geometry: {g}"));
    }
    d
}

/// The probes of one instrumented program and what they counted over one run.
struct ProbeRun {
    /// Index into `Effect::passes` (0 for a single-pass program).
    pass: usize,
    instrumented: Instrumented,
    counts: Vec<StageCounts>,
}

/// The probes of every program an instrumented build translated, by pass.
struct Probed(Vec<(usize, Instrumented)>);

impl Probed {
    /// Builds `c` with every translation instrumented (the vertex stage too where the device
    /// allows storage writes there), its counts buffer read back after each run.
    fn build<'c>(
        gpu: &Gpu,
        c: &'c check::Checked,
        outcome: &mut Outcome,
        overrides: &[(String, UniformValue)],
        m: MemoryRequest,
    ) -> Option<(MemoryDrawer<'c>, Probed)> {
        let probes = std::cell::RefCell::new(Vec::new());
        let vertex = gpu.vertex_storage();
        let instrument = |unit: &check::Unit, t: &mut crate::back::Translation| {
            probes.borrow_mut().push((unit.pass, culprit::instrument_translation(t, &unit.program, unit.effect.as_ref(), vertex)?));
            Ok(())
        };
        let m = MemoryRequest { read_back: Some(COUNTS_BUFFER), ..m };
        let program = MemoryDrawer::new(gpu, c, outcome, overrides, m, Some(&instrument))?;
        Some((program, Probed(probes.into_inner())))
    }

    /// What each instrumented program counted in `run`.
    fn runs(&self, run: &MemoryRun) -> Vec<ProbeRun> {
        run.read_back
            .iter()
            .filter_map(|(pass, words)| {
                let (_, instrumented) = self.0.iter().find(|(p, _)| p == pass)?;
                Some(ProbeRun { pass: *pass, instrumented: instrumented.clone(), counts: instrumented.read(words) })
            })
            .collect()
    }
}

/// Where non-finite values begin in one instrumented stage of one pass.
#[derive(Debug, Clone)]
struct Culprit {
    /// Index into `Effect::passes` (0 for a single-pass program).
    pass: usize,
    /// The stage whose invocations counted it (its span may be in a helper of the other).
    invoked: StageKind,
    probe: Probe,
    /// Invocations where it was the first non-finite value.
    first_in: u64,
    /// Invocations with any non-finite intermediate value.
    bad: u64,
    /// All invocations of the stage.
    total: u64,
    /// Other probes that came first in some invocations.
    others: usize,
}

impl Culprit {
    /// For every instrumented stage that saw a non-finite value, the probe that fired first
    /// in the most invocations; in pipeline order (passes as run, vertex before fragment),
    /// so the first is where the trouble begins.
    fn all(runs: &[ProbeRun]) -> Vec<Culprit> {
        let mut out = Vec::new();
        for run in runs {
            for counts in &run.counts {
                let Some(&(id, first_in)) = counts.first.iter().max_by_key(|(id, n)| (*n, std::cmp::Reverse(*id))) else { continue };
                let Some(probe) = run.instrumented.probe(id) else { continue };
                let bad = counts.bad();
                out.push(Culprit {
                    pass: run.pass,
                    invoked: counts.stage,
                    probe: probe.clone(),
                    first_in,
                    bad,
                    total: bad + counts.clean,
                    others: counts.first.len() - 1,
                });
            }
        }
        out
    }
}

/// Labels every culprit at its span in the user's GLSL; the first (where the trouble
/// begins) is the primary span when the diagnostic has none.
fn with_culprits(mut d: Diagnostic, c: &check::Checked, culprits: &[Culprit]) -> Diagnostic {
    for (k, f) in culprits.iter().enumerate() {
        let Some(program) = c.unit(f.pass).map(|u| &u.program) else { continue };
        let Some((file, span)) = f.probe.span.to_range().and_then(|r| program.user_span(f.probe.stage, r)) else { continue };
        let stage_name = match f.invoked {
            StageKind::Vertex => "vertex",
            _ => "fragment",
        };
        let pass = match c.multi_pass() {
            Some(e) => e.passes.get(f.pass).map(|p| format!(" of pass `{}`", p.name)).unwrap_or_default(),
            None => String::new(),
        };
        let lead = if k == 0 { "the first non-finite value" } else { "then non-finite" };
        let label = format!("{lead} ({}) in {} of {} {stage_name} invocations{pass}", f.probe.what, f.first_in, f.total);
        d = if d.span.is_none() { d.at(file, span, label) } else { d.with_label(file, span, label) };
        if f.others > 0 {
            let rest = f.bad - f.first_in;
            d = d.with_note(format!("{} other expressions come first in {rest} more {stage_name} invocations{pass}", f.others));
        }
    }
    d
}

/// The human table of one program.
pub fn table(r: &StressReport) -> String {
    let bad = r.cases.iter().filter(|c| c.nan + c.inf > 0).count();
    let mut text = format!(
        "{} — {} cases at {}x{}: {}\n",
        r.program,
        r.cases.len(),
        r.size.0,
        r.size.1,
        if bad == 0 { "no NaN or Inf".to_string() } else { format!("{bad} with NaN or Inf") }
    );
    text.push_str(&format!(
        "  {:<18} {:>8} {:>8} {:>9} {:>9} {:>10}  {}\n",
        "case", "NaN px", "Inf px", "bad frag", "bad vert", "max |Δ|", "values"
    ));
    for c in &r.cases {
        let vertices = if r.vertex_probes { c.bad_vertices.to_string() } else { "-".into() };
        text.push_str(&format!(
            "  {:<18} {:>8} {:>8} {:>9} {:>9} {:>10.4}  {}\n",
            c.case, c.nan, c.inf, c.bad_fragments, vertices, c.max_delta, c.values
        ));
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cases_cover_range_ends_random_points_and_extreme_times() {
        let bare = cases(&[], 4, 1);
        assert_eq!(bare.len(), 1 + EXTREME_TIMES.len() + Degenerate::ALL.len(), "bare programs: nominal, times, geometry");
        assert_eq!(bare.iter().filter_map(|c| c.degenerate).collect::<Vec<_>>(), Degenerate::ALL);
        let v = UniformValue::List(vec![UniformValue::Float(0.5), UniformValue::Float(0.5)]);
        assert_eq!(fill(&v, &|c| f64::from(c)), UniformValue::List(vec![UniformValue::Float(0.0), UniformValue::Float(1.0)]));
        assert_eq!(fill(&UniformValue::Int(3), &|_| 7.6), UniformValue::Int(8));
        assert!(!numeric(&UniformValue::Bool(true)));

        let input = |name: &str, default: UniformValue, lo, hi, step| Declared { name: name.into(), default, lo, hi, step };
        let inputs = [
            input("k", UniformValue::Int(2), 1.0, 9.0, None),
            input("tint", UniformValue::List(vec![UniformValue::Float(0.5); 2]), 0.0, 1.0, None),
            // A `#pragma parameter` moves in its steps.
            input("MASK", UniformValue::Float(1.0), 0.0, 3.0, Some(1.0)),
        ];
        let all = cases(&inputs, 3, 7);
        // nominal, 3 × (low, high), all low, all high, 3 random, 3 times, 2 geometry.
        assert_eq!(all.len(), 1 + 6 + 2 + 3 + 3 + 2, "{all:#?}");
        assert_eq!(all[1].overrides, [("k".to_string(), UniformValue::Int(1))]);
        assert_eq!(all[4].overrides, [("tint".to_string(), UniformValue::List(vec![UniformValue::Float(1.0); 2]))]);
        for random in all.iter().filter(|c| c.name.starts_with("random")) {
            let UniformValue::Int(k) = random.overrides[0].1 else { panic!("k stays an int") };
            assert!((1..=9).contains(&k));
            let UniformValue::Float(mask) = random.overrides[2].1 else { panic!("a float") };
            assert_eq!(mask, mask.round(), "on the parameter's grid");
        }
        assert_eq!(cases(&inputs, 3, 7), all, "seeded: the same cases every run");
        assert_eq!(all[all.len() - 3].time, 1e7);
        // The inputs a case does not move keep their defaults.
        let values = inputs::with_defaults(&all[1].overrides, &inputs);
        assert_eq!(values.len(), 3);
        assert_eq!(values[2], ("MASK".to_string(), UniformValue::Float(1.0)));
    }
}
