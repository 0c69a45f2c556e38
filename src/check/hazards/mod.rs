//! Static hazard analysis: interval propagation over the naga IR of each stage, from the
//! manifest's uniform ranges and defaults, the mesh's attribute data, texture texels, time
//! and builtins, reporting operations that can produce NaN, Inf or garbage, at the span of
//! the user's GLSL.
//!
//! - [`interval`]: interval arithmetic; [`value`]: abstract values with vector facts;
//! - [`facts`]: what is known before the shader runs;
//! - [`walk`]: statements and control flow ([`induction`]: variables stepped with a loop's
//!   counter); [`eval`]: expressions; [`ops`]: the algebra.
//! - [`witness`]: the analysis again at fixed inputs ([`unroll`]: loops iteration by
//!   iteration); [`tier`]: what makes a hazard certain rather than possible.
//!
//! The vertex stage runs first; its outputs become the fragment stage's inputs (the hull
//! of values is preserved by interpolation). Only values derived from known facts raise a
//! hazard: an input nothing is known about never does, and once a hazard is reported its
//! result is unknown, so one mistake gives one warning. A hazard a witness run shows is
//! certain; the others are possible, and bare stage files report them only on request.

pub mod eval;
pub mod facts;
mod geometric;
mod induction;
pub mod interval;
pub mod ops;
mod tier;
mod unroll;
pub mod value;
pub mod walk;
mod witness;

use std::collections::HashMap;

use crate::config::{HazardReport, HazardSettings};
use crate::diag::{Code, Diagnostic, FileId};
use crate::front::program::CompiledProgram;
use crate::manifest::Effect;
use crate::stage::StageKind;
use interval::Iv;
use ops::Kind;
use value::Num;

/// One finding, at a span of the rewritten stage text.
#[derive(Debug, Clone)]
pub struct Hazard {
    pub code: Code,
    pub span: naga::Span,
    pub message: String,
    pub label: String,
    pub notes: Vec<String>,
    pub help: String,
    /// Every value the operands can take hits it ([`tier::certain`]): what a witness run
    /// reports.
    pub certain: bool,
    /// Some value the operands can take would make it certain ([`tier::witnessable`]):
    /// worth witness runs.
    pub witnessable: bool,
}

impl Hazard {
    /// A hazard of an operation whose relevant operand is `a` (for a division, the divisor).
    pub fn new(kind: Kind, span: naga::Span, a: &Num, b: Option<&Num>) -> Hazard {
        let (code, message, label, note, help) = match kind {
            Kind::Division => (
                Code::HazardDivision,
                "division by a value that can be zero".to_string(),
                format!("the divisor can be 0: {}", describe(a)),
                "x / 0 is ±Inf, and 0 / 0 is NaN".to_string(),
                "divide by `max(d, 1e-6)` (or `sign(d) * max(abs(d), 1e-6)`), guard with an `if`, or narrow the uniform's `range`",
            ),
            Kind::Asin | Kind::Acos => {
                let f = if kind == Kind::Asin { "asin" } else { "acos" };
                (
                    Code::HazardAsin,
                    format!("`{f}` of a value that can leave [-1, 1]"),
                    format!("the argument lies in {}", describe(a)),
                    format!("{f} is undefined outside [-1, 1] (NaN on GPUs); rounding alone takes a dot product of unit vectors just past 1"),
                    "clamp the argument: `clamp(x, -1.0, 1.0)`",
                )
            }
            Kind::Sqrt => (
                Code::HazardSqrt,
                "`sqrt` of a value that can be negative".to_string(),
                format!("the argument lies in {}", describe(a)),
                "sqrt of a negative number is NaN".to_string(),
                "use `sqrt(max(x, 0.0))`",
            ),
            Kind::Log => (
                Code::HazardLog,
                "`log` of a value that can be zero or negative".to_string(),
                format!("the argument lies in {}", describe(a)),
                "log(0) is -Inf and log of a negative number NaN".to_string(),
                "use `log(max(x, 1e-6))`",
            ),
            Kind::Pow => (
                Code::HazardPow,
                "`pow` with a base that can be negative, or zero to a power <= 0".to_string(),
                format!("the base lies in {}{}", describe(a), b.map(|e| format!(", the exponent in {}", describe(e))).unwrap_or_default()),
                "GLSL leaves pow(x, y) undefined for x < 0, and for x = 0 with y <= 0 (NaN or Inf on GPUs)".to_string(),
                "use `pow(max(x, 0.0), y)` (with `y > 0`), e.g. `pow(max(dot(r, v), 0.0), shininess)`",
            ),
            Kind::Normalize => (
                Code::HazardNormalize,
                "`normalize` of a vector that can be zero".to_string(),
                format!("its length can be 0: {}", describe(a)),
                "normalize(0) divides by a zero length: NaN on most GPUs (0 on some, such as llvmpipe)".to_string(),
                "use `v * inversesqrt(max(dot(v, v), 1e-12))`, or guard with `if (length(v) > 0.0)`",
            ),
            Kind::InverseSqrt => (
                Code::HazardInverseSqrt,
                "`inversesqrt` of a value that can be zero or negative".to_string(),
                format!("the argument lies in {}", describe(a)),
                "inversesqrt(0) is +Inf and of a negative number NaN".to_string(),
                "use `inversesqrt(max(x, 1e-12))`",
            ),
            Kind::Trig => (
                Code::HazardTrig,
                "trigonometric function of an argument too large for f32".to_string(),
                format!("the argument reaches {}", big(a.iv().mag())),
                format!(
                    "beyond {} rad one f32 step of the argument exceeds 10⁻³ rad, and GPUs only guarantee sin/cos accuracy in [-π, π]: the result turns to noise as time grows",
                    big(ops::TRIG_LIMIT)
                ),
                "wrap the phase first: `sin(mod(t, 2π / f) * f)`, or give the time uniform a `range`",
            ),
            Kind::NegativeRemainder => (
                Code::HazardNegativeRemainder,
                "integer `%` of a value that can be negative".to_string(),
                format!(
                    "the operands lie in {}{}",
                    describe(a),
                    b.map(|d| format!(" and {}", describe(d))).unwrap_or_default()
                ),
                "GLSL leaves `%` undefined when an operand is negative: OpenGL drivers and WebGPU give different results (`effectc verify` shows them)".to_string(),
                "keep both operands non-negative (`abs(x) % n`), or write the remainder you mean: `x - n * int(floor(float(x) / float(n)))`",
            ),
            Kind::Shift => (
                Code::HazardShift,
                "shift by an amount that can be negative or at least 32".to_string(),
                format!("the amount lies in {}", describe(b.unwrap_or(a))),
                "GLSL leaves such shifts undefined: WebGPU uses the amount's low 5 bits, drivers differ".to_string(),
                "bound the amount: `x << clamp(s, 0, 31)`",
            ),
            Kind::Atan2 => (
                Code::HazardAtan2,
                "`atan(y, x)` where both can be 0".to_string(),
                format!("y lies in {}{}", describe(a), b.map(|x| format!(", x in {}", describe(x))).unwrap_or_default()),
                "GLSL leaves atan(0, 0) undefined: drivers return 0, π or NaN".to_string(),
                "guard the origin: `length(v) > 1e-6 ? atan(v.y, v.x) : 0.0`",
            ),
        };
        let (certain, witnessable) = (tier::certain(kind, a, b), tier::witnessable(kind, a, b));
        Hazard { code, span, message, label, notes: vec![note], help: help.to_string(), certain, witnessable }
    }

    pub fn hash(span: naga::Span, x: Iv, k: Iv) -> Hazard {
        let grows = x.mag() > std::f64::consts::PI;
        let mut notes = vec![format!(
            "GLSL and Vulkan allow sin an absolute error of 2⁻¹¹; times {} that is more than half a unit, so fract keeps no reliable bits: the pattern differs between GPUs",
            big(k.mag())
        )];
        if grows {
            notes.push(format!("the argument of sin reaches {}, where sin is not even that accurate", big(x.mag())));
        }
        Hazard {
            code: Code::HazardSinHash,
            span,
            message: "`fract(sin(x) * K)` hash depends on the GPU's sin precision".into(),
            label: format!("K = {}{}", describe_iv(k), if grows { format!(", x in {}", describe_iv(x)) } else { String::new() }),
            notes,
            help: "use an integer hash (e.g. PCG: `uint h = uint(x) * 747796405u + 2891336453u; …`) or a sine-free hash such as Dave Hoskins' `hash11`".into(),
            certain: tier::certain_hash(x),
            witnessable: tier::certain_hash(Iv::new(x.mag(), x.mag())),
        }
    }

    pub fn counter(span: naga::Span, counter: Iv, next: Iv, kind: naga::ScalarKind) -> Hazard {
        let ty = if kind == naga::ScalarKind::Uint { "uint" } else { "int" };
        Hazard {
            code: Code::HazardCounterOverflow,
            span,
            message: format!("loop counter can overflow `{ty}`"),
            label: format!("the counter reaches {}, its update {}", describe_iv(counter), describe_iv(next)),
            notes: vec!["nothing bounds this loop's counter below the type's limit: it wraps around (signed overflow is undefined)".into()],
            help: "bound the loop by a constant or a uniform with a `range`".into(),
            certain: false,
            witnessable: true,
        }
    }
}

/// A value's components as intervals.
fn describe(n: &Num) -> String {
    if n.c.len() == 1 {
        return describe_iv(n.c[0]);
    }
    let names = ["x", "y", "z", "w"];
    if n.cols == 1 && n.c.len() <= 4 {
        return n.c.iter().zip(names).map(|(c, name)| format!("{name} in {}", describe_iv(*c))).collect::<Vec<_>>().join(", ");
    }
    describe_iv(n.iv())
}

fn describe_iv(iv: Iv) -> String {
    if iv.is_point() {
        return big(iv.lo);
    }
    format!("[{}, {}]", big(iv.lo), big(iv.hi))
}

/// A number for people: `1e7`, `86400`, `0.0001`, `-1`.
fn big(x: f64) -> String {
    if x.is_infinite() {
        return if x > 0.0 { "∞".into() } else { "-∞".into() };
    }
    if x != 0.0 && (x.abs() >= 1e6 || x.abs() < 1e-4) {
        return format!("{x:.3e}");
    }
    // Enough digits to show that 1.0000069 is not 1.
    let digits = if (x - (x * 1e4).round() / 1e4).abs() > 1e-12 && x.abs() < 10.0 { 7 } else { 4 };
    let s = format!("{x:.digits$}");
    let s = s.trim_end_matches('0').trim_end_matches('.').to_string();
    if s == "-0" {
        "0".into()
    } else {
        s
    }
}

/// One stage as the analysis runs it: its IR and text, and where its spans lead back to.
struct Stage<'p> {
    kind: StageKind,
    entry: naga::ShaderStage,
    file: FileId,
    ir: &'p crate::front::naga_run::Validated,
    text: &'p str,
    place: Place<'p>,
}

enum Place<'p> {
    /// The fold of the vertex and geometry stages: spans lead back to either.
    Folded(&'p crate::front::geometry_fold::Folded),
    Rewritten(&'p crate::front::rewrite::Rewritten),
}

/// What one run of one stage found.
struct Run {
    hazards: Vec<Hazard>,
    outputs: HashMap<u32, value::Val>,
    stopped: bool,
    work: u64,
}

/// The vertex stage (the fold with a geometry stage, when there is one) and the fragment
/// stage of `program`, those with IR.
fn stages(program: &CompiledProgram) -> Vec<Stage<'_>> {
    let mut out = Vec::new();
    for (kind, entry) in [(StageKind::Vertex, naga::ShaderStage::Vertex), (StageKind::Fragment, naga::ShaderStage::Fragment)] {
        let Some(s) = program.stages.iter().find(|s| s.syntax.stage == kind) else { continue };
        let file = s.syntax.file;
        match (program.fold().filter(|_| kind == StageKind::Vertex), &s.naga, &s.rewritten) {
            (Some(fd), _, _) => {
                out.push(Stage { kind, entry, file, ir: &fd.analysis, text: fd.analysed.text.as_str(), place: Place::Folded(fd) })
            }
            (None, Some(v), Some(rw)) => out.push(Stage { kind, entry, file, ir: v, text: rw.text.as_str(), place: Place::Rewritten(rw) }),
            _ => {}
        }
    }
    out
}

/// Runs the analysis of `stage` on `facts` (a witness run when `witness`), within
/// `work_limit`. `None` if the analysis panicked: a bug in it loses its warnings only,
/// never the `check`.
fn run(stage: &Stage<'_>, facts: &facts::Facts, witness: bool, work_limit: u64) -> Option<Run> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        let mut a = walk::Analyzer::new(&stage.ir.module, &stage.ir.info, facts, stage.entry, stage.text);
        a.witness = witness;
        a.work_limit = work_limit;
        a.run_entry();
        Run { hazards: without_hash_arguments(&a.hazards).cloned().collect(), outputs: a.outputs, stopped: a.stopped, work: a.work }
    }))
    .ok()
}

/// Runs the analysis over a compiled program; warnings at the user's spans. `settings`:
/// what it assumes where the manifest says nothing (`effectc.toml`'s `[hazards]`), and
/// which tier it reports: bare stage files report certain hazards only unless asked for
/// the possible ones; an effect, whose manifest declares its ranges, both.
pub fn analyse(effect: Option<&Effect>, program: &CompiledProgram, settings: HazardSettings) -> Vec<Diagnostic> {
    analyse_with(effect, program, settings, true)
}

/// The interval analysis alone, every hazard reported as possible: the baseline
/// `benches/hazard_speed.rs` times the witness runs against.
pub fn analyse_without_witnesses(effect: Option<&Effect>, program: &CompiledProgram, settings: HazardSettings) -> Vec<Diagnostic> {
    analyse_with(effect, program, HazardSettings { report: Some(HazardReport::Possible), ..settings }, false)
}

fn analyse_with(effect: Option<&Effect>, program: &CompiledProgram, settings: HazardSettings, witnesses: bool) -> Vec<Diagnostic> {
    let stages = stages(program);
    let names = vertex_input_names(stages.iter().find(|s| s.kind == StageKind::Vertex));
    let mut f = match effect {
        Some(_) => facts::Facts::of(effect, &names, settings.time_limit),
        None => facts::Facts::guessed(settings.time_limit),
    };
    for s in &program.stages {
        f.declare_parameters(&s.syntax.parameters);
    }
    let mut out = Vec::new();
    let mut runs: Vec<Option<Run>> = Vec::new();
    for stage in &stages {
        let r = run(stage, &f, false, walk::WORK_LIMIT);
        if r.as_ref().is_some_and(|r| r.stopped) {
            out.push(
                Diagnostic::new(Code::HazardAnalysisStopped, format!("the hazard analysis of the {} stage stopped at its work limit", stage.kind))
                    .in_file(stage.file)
                    .with_note(format!(
                        "loops nested deeply, or calls fanning out, take work growing exponentially; after {} steps the rest of the stage was not analysed, so its warnings are incomplete",
                        walk::WORK_LIMIT
                    )),
            );
        }
        if let (StageKind::Vertex, Some(r)) = (stage.kind, &r) {
            f.varyings = vertex_outputs(r);
        }
        runs.push(r);
    }
    let base_work = runs.iter().flatten().map(|r| r.work).sum();
    let found: Vec<Vec<Hazard>> = runs.into_iter().map(|r| r.map(|r| r.hazards).unwrap_or_default()).collect();
    let confirmed = if witnesses {
        confirm(&stages, &f, found, base_work)
    } else {
        let found = found.into_iter().map(|hs| hs.into_iter().map(|h| (h, None)).collect()).collect();
        Confirmed { found, tried: 0, planned: 0, out_of_work: false }
    };
    let report = settings.report.unwrap_or(if effect.is_some() { HazardReport::Possible } else { HazardReport::Certain });
    for (stage, hazards) in stages.iter().zip(&confirmed.found) {
        for (h, witness) in hazards {
            // The fold's own glue (pulling, the tessellator) is effectc's code: what the
            // analysis only suspects there is not the user's to fix.
            if witness.is_none() && in_fold_glue(stage, program, h) {
                continue;
            }
            let note = match witness {
                Some(w) => format!("certain: it happens {}", w.at),
                None if report == HazardReport::Certain => continue,
                None => {
                    let assumed = h.span.to_range().map(|r| witness::assumed_on_line(&f, stage.text, r.start)).unwrap_or_default();
                    confirmed.possible_note(h, &assumed)
                }
            };
            out.push(at_user(stage, program, h).with_note(note));
        }
    }
    out
}

/// Which of the inputs `names` are named near the hazards at `spans` of `text` (on their
/// lines, or on a line that gives a variable named there its value): the inputs whose
/// values to try first.
pub fn inputs_named_near(names: &[&str], text: &str, spans: impl Iterator<Item = std::ops::Range<usize>>) -> Vec<bool> {
    witness::named_near(names, text, spans)
}

/// The hazards of every stage with the witness that makes each certain, if any.
struct Confirmed {
    found: Vec<Vec<(Hazard, Option<Witness>)>>,
    /// Input sets tried, and planned; whether the work budget ended the runs.
    tried: usize,
    planned: usize,
    out_of_work: bool,
}

/// Where a witness run showed a hazard, and how many declared inputs it moved from their
/// defaults (fewer says more precisely which input matters).
struct Witness {
    at: String,
    inputs: usize,
}

impl Confirmed {
    /// The note of a possible hazard; `assumed`: what the analysis assumed of the inputs its
    /// line names ([`witness::assumed_on_line`]).
    fn possible_note(&self, h: &Hazard, assumed: &[String]) -> String {
        let assumed = match assumed {
            [] => String::new(),
            _ => format!("; it assumed {}", assumed.join(", ")),
        };
        if !h.witnessable {
            return format!("possible: the analysis cannot rule it out over the ranges it assumes, and no run at fixed inputs could show it: no value its operands can take is sure to go wrong{assumed}");
        }
        let stopped = match self.out_of_work {
            true => format!("; the witness runs reached their work limit after {} of {} sets of inputs", self.tried, self.planned),
            false => String::new(),
        };
        format!(
            "possible: the analysis cannot rule it out over the ranges it assumes, but no run at fixed inputs showed it (each declared input at its default, its range's ends and steps; time 0){stopped}{assumed}"
        )
    }
}

/// Witness runs for the hazards `found` (by stage, in the order of `stages`): input sets
/// from [`witness::samples`] while a hazard is unconfirmed (or confirmed by a set that
/// moved several inputs) and work remains.
fn confirm(stages: &[Stage<'_>], f: &facts::Facts, found: Vec<Vec<Hazard>>, base_work: u64) -> Confirmed {
    let budget = WITNESS_WORK.min(base_work / WITNESS_SHARE + WITNESS_FLOOR);
    let mut out: Vec<Vec<(Hazard, Option<Witness>)>> = found.into_iter().map(|hs| hs.into_iter().map(|h| (h, None)).collect()).collect();
    let mut first = vec![false; f.declared.len()];
    for (st, hs) in stages.iter().zip(&out) {
        let spans = hs.iter().filter_map(|(h, _)| h.span.to_range()).filter(|r| r.end <= st.text.len());
        let names: Vec<&str> = f.declared.iter().map(|d| d.name.as_str()).collect();
        for (i, near) in witness::named_near(&names, st.text, spans).into_iter().enumerate() {
            first[i] |= near;
        }
    }
    let plan = witness::samples(&f.declared, &first);
    let (mut tried, mut work, mut out_of_work) = (0, 0u64, false);
    let open = |out: &[Vec<(Hazard, Option<Witness>)>], i: usize| {
        out[i].iter().any(|(h, w)| h.witnessable && w.as_ref().is_none_or(|w| w.inputs > 1))
    };
    for sample in &plan {
        if !(0..stages.len()).any(|i| open(&out, i)) {
            break;
        }
        if work >= budget {
            out_of_work = true;
            break;
        }
        tried += 1;
        let mut facts = witness::facts_at(f, sample);
        for (i, stage) in stages.iter().enumerate() {
            let vertex = stage.kind == StageKind::Vertex;
            // The vertex stage runs for its own hazards or to feed the fragment stage's.
            let feeds_open = vertex && (i + 1..stages.len()).any(|j| open(&out, j));
            if !(open(&out, i) || feeds_open) {
                continue;
            }
            let Some(r) = run(stage, &facts, true, (budget - work.min(budget)).max(1)) else { continue };
            work += r.work;
            out_of_work |= r.stopped;
            for h in &r.hazards {
                let w = Witness { at: witness::describe(&f.declared, sample, facts.read_clock.get()), inputs: sample.varied.len() };
                // The witness's own values label it: the operands at the inputs it fixed (a
                // counter keeps the fixpoint's range, where it overflows).
                let keep_label = h.code == Code::HazardCounterOverflow;
                match out[i].iter_mut().find(|(b, _)| b.code == h.code && b.span == h.span) {
                    Some((b, old)) if old.as_ref().is_none_or(|o| w.inputs < o.inputs) => {
                        if !keep_label {
                            *b = h.clone();
                        }
                        *old = Some(w);
                    }
                    Some(_) => {}
                    None => out[i].push((h.clone(), Some(w))),
                }
            }
            if vertex {
                facts.varyings = vertex_outputs(&r);
            }
        }
    }
    Confirmed { found: out, tried, planned: plan.len(), out_of_work }
}

/// Work all the witness runs of one program may take together: a share of what its
/// interval analysis took ([`WITNESS_SHARE`]), at least [`WITNESS_FLOOR`] (a small stage
/// gets a few input sets), at most this. A witness run costs about what the analysis
/// does (decided branches are walked once, loops iteration by iteration), so the
/// analysis with its witness runs stays within a fifth more work than without
/// (`benches/hazard_speed.rs`).
const WITNESS_WORK: u64 = 2_000_000;
const WITNESS_SHARE: u64 = 5;
const WITNESS_FLOOR: u64 = 20_000;

/// The vertex stage's outputs as the fragment stage's inputs.
fn vertex_outputs(r: &Run) -> HashMap<u32, Num> {
    r.outputs.iter().filter_map(|(l, v)| v.num().cloned().map(|n| (*l, varying(n)))).collect()
}

/// The vertex inputs by location, with the user's names.
fn vertex_input_names(vertex: Option<&Stage<'_>>) -> Vec<(u32, String)> {
    let Some(ep) = vertex.and_then(|s| s.ir.module.entry_points.iter().find(|e| e.stage == naga::ShaderStage::Vertex)) else {
        return Vec::new();
    };
    ep.function
        .arguments
        .iter()
        .filter_map(|a| match a.binding {
            Some(naga::Binding::Location { location, .. }) => {
                let name = a.name.clone().unwrap_or_default();
                let user = name.strip_prefix(crate::front::geometry_fold::ATTRIBUTE_PREFIX).unwrap_or(&name).to_string();
                Some((location, user))
            }
            _ => None,
        })
        .collect()
}

/// Whether `h` lies in the generated glue of a folded stage (no user span).
fn in_fold_glue(stage: &Stage<'_>, program: &CompiledProgram, h: &Hazard) -> bool {
    match stage.place {
        Place::Folded(fd) => h.span.to_range().is_none_or(|r| program.user_span_in(&fd.analysed, r).is_none()),
        _ => false,
    }
}

/// The diagnostic of `h`, found in `stage`, at the user's span.
fn at_user(stage: &Stage<'_>, program: &CompiledProgram, h: &Hazard) -> Diagnostic {
    match stage.place {
        Place::Folded(fd) => folded_diagnostic(h, program, fd),
        Place::Rewritten(rw) => diagnostic(h, stage.file, rw),
    }
}

/// The hazards less W0717 on the `sin` inside a `fract(sin(x) * K)` hash W0718 reports: a
/// hash means its huge argument, and W0718 already says why its bits differ between GPUs.
fn without_hash_arguments(hazards: &[Hazard]) -> impl Iterator<Item = &Hazard> {
    let hashes: Vec<std::ops::Range<usize>> =
        hazards.iter().filter(|h| h.code == Code::HazardSinHash).filter_map(|h| h.span.to_range()).collect();
    hazards.iter().filter(move |h| {
        let inside = |r: &std::ops::Range<usize>| h.span.to_range().is_some_and(|s| r.start <= s.start && s.end <= r.end);
        !(h.code == Code::HazardTrig && hashes.iter().any(inside))
    })
}

/// A vertex output as the fragment stage sees it: the hull survives interpolation, and a
/// non-zero length only when no triangle's values can interpolate to zero.
fn varying(mut n: Num) -> Num {
    if !n.cone {
        n.len.lo = 0.0;
        n.len = n.len.meet(value::length_of(&n.c));
        n.len3.lo = 0.0;
    }
    n.per_draw = false;
    n
}

fn diagnostic(h: &Hazard, file: FileId, rw: &crate::front::rewrite::Rewritten) -> Diagnostic {
    located(h, file, h.span.to_range().map(|r| rw.map.range_to_original(r)))
}

/// A hazard in the fold of the vertex and geometry stages, at the stage it came from (the
/// geometry stage's file when it lies in generated glue).
fn folded_diagnostic(h: &Hazard, program: &CompiledProgram, folded: &crate::front::geometry_fold::Folded) -> Diagnostic {
    let geometry = program.stage(StageKind::Geometry).map(|s| s.syntax.file).unwrap_or(program.stages[0].syntax.file);
    let at = h.span.to_range().and_then(|r| program.user_span_in(&folded.analysed, r));
    match at {
        Some((file, range)) => located(h, file, Some(range)),
        None => located(h, geometry, None),
    }
}

fn located(h: &Hazard, file: FileId, range: Option<std::ops::Range<usize>>) -> Diagnostic {
    let mut d = Diagnostic::new(h.code, h.message.clone());
    d = match range {
        Some(r) => d.at(file, r, h.label.clone()),
        None => d.in_file(file),
    };
    for n in &h.notes {
        d = d.with_note(n.clone());
    }
    d.with_help(h.help.clone())
}
