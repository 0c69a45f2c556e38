//! `effectc stress --confirm`: every hazard warning of a program (both tiers) is put to a
//! render. The program is drawn with its warned operations instrumented
//! ([`crate::stress::sites`]) under the inputs the analysis assumed, and each warning gets
//! a verdict:
//! - **confirmed**: in some case the condition it names held where it points (the first
//!   such case is named, with how many invocations hit it), or, for a divisor, a normalized
//!   vector or `atan`'s arguments in a fragment stage, they passed through zero between two
//!   neighbouring pixel centres ([`crate::stress::crossing`]): error `E0703`;
//! - **refuted**: the operation ran, in every case, and the condition never held;
//! - **unreached**: the operation never ran in any case;
//! - **untested**: the operation is not in the translation, or runs where this device
//!   cannot count (a vertex stage without storage writes).
//!
//! The cases ([`cases`]) are the inputs the analysis assumed: every declared input (a
//! manifest `range` or a `#pragma parameter`) at its default, at each end of its range, at
//! 0 where the range holds it, all at their low ends and all at their high ends, steps
//! inside the ranges, seeded random points; the same ends at the end of the time the
//! analysis assumed (`[hazards] time-limit`, an hour unless set); and the degenerate
//! meshes `stress` draws. The runs stop once every warning is confirmed.

use std::cell::RefCell;

use crate::assets::degenerate::Degenerate;
use crate::check::{self, Outcome};
use crate::diag::{Code, Diagnostic, FileId};
use crate::manifest::UniformValue;
use crate::render::device::Gpu;
use crate::render::memory::{MemoryDrawer, MemoryRequest};
use crate::stage::StageKind;
use crate::stress::inputs::{declared, random_points, with_defaults, Declared};
use crate::stress::sites::{self, Counted, Sites, Wanted};
use crate::stress::{fill, show, Case, Request, COUNTS_BUFFER};

/// Cases one program is drawn with at most.
pub const MAX_CASES: usize = 200;

/// The verdict on one warning.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Verdict {
    Confirmed,
    Refuted,
    Unreached,
    Untested,
}

/// One warning and what the render showed.
#[derive(Debug, Clone, serde::Serialize)]
pub struct Tested {
    pub code: String,
    /// `file:line` of the warning.
    pub at: String,
    pub message: String,
    /// `certain` or `possible`: the tier the analysis gave it.
    pub tier: &'static str,
    pub verdict: Verdict,
    /// The first case that confirmed it, and its values.
    pub case: Option<String>,
    pub values: Option<String>,
    /// Invocations where the condition held, and those that reached the operation: in the
    /// confirming case, or over every case for the other verdicts.
    pub held: u64,
    /// Invocations whose operands passed through zero between them and a neighbouring
    /// pixel (same case as `held`).
    pub between: u64,
    pub reached: u64,
    /// Invocations of the stage that counted them (same cases).
    pub invocations: u64,
    pub stage: Option<String>,
    /// Why a warning is untested.
    pub reason: Option<String>,
}

/// One program's warnings and their verdicts.
#[derive(Debug, Clone, serde::Serialize)]
pub struct ConfirmReport {
    pub program: String,
    pub size: (u32, u32),
    /// Cases drawn, and planned (the runs stop once every warning is confirmed).
    pub cases: usize,
    pub planned: usize,
    pub hazards: Vec<Tested>,
}

/// The cases of a program with inputs `inputs`, in the order they are drawn, at most
/// [`MAX_CASES`] (the second value: how many were planned).
pub fn cases(inputs: &[Declared], first: &[bool], samples: u32, seed: u32, time_limit: f64) -> (Vec<Case>, usize) {
    let case = |name: String, overrides: Vec<(String, UniformValue)>, time: f64| Case { name, overrides, time, degenerate: None };
    let at = |d: &Declared, x: f64| (d.name.clone(), fill(&d.default, &|_| d.on_grid(x)));
    // The end of the time the analysis assumed, after each case at time 0.
    let late = |c: &Case| Case { name: format!("{} at {time_limit} s", c.name), time: time_limit, ..c.clone() };
    let defaults = case("defaults".into(), Vec::new(), 0.0);
    let mut out = vec![late(&defaults)];
    out.insert(0, defaults);
    let ends = |d: &Declared| {
        let mut v = vec![case(format!("{} low", d.name), vec![at(d, d.lo)], 0.0), case(format!("{} high", d.name), vec![at(d, d.hi)], 0.0)];
        if d.lo < 0.0 && d.hi > 0.0 && d.on_grid(0.0) == 0.0 {
            v.push(case(format!("{} = 0", d.name), vec![at(d, 0.0)], 0.0));
        }
        v
    };
    // The inputs named near a warning first: a program with hundreds of parameters reaches
    // the ones that matter within MAX_CASES.
    let near = |i: usize| first.get(i).copied().unwrap_or(false);
    let mut near_ends: Vec<Case> = (0..inputs.len()).filter(|i| near(*i)).flat_map(|i| ends(&inputs[i])).collect();
    if inputs.len() > 1 {
        near_ends.push(case("all low".into(), inputs.iter().map(|d| at(d, d.lo)).collect(), 0.0));
        near_ends.push(case("all high".into(), inputs.iter().map(|d| at(d, d.hi)).collect(), 0.0));
    }
    let far_ends: Vec<Case> = (0..inputs.len()).filter(|i| !near(*i)).flat_map(|i| ends(&inputs[i])).collect();
    for group in [near_ends, far_ends] {
        out.extend(group.iter().cloned());
        out.extend(group.iter().map(late));
    }
    let ordered: Vec<&Declared> =
        (0..inputs.len()).filter(|i| near(*i)).chain((0..inputs.len()).filter(|i| !near(*i))).map(|i| &inputs[i]).collect();
    for &d in &ordered {
        let steps = match d.step {
            Some(s) if (d.hi - d.lo) / s <= 16.0 => ((d.hi - d.lo) / s).round() as u32,
            _ => 4,
        };
        for k in 1..steps {
            let x = d.on_grid(d.lo + (d.hi - d.lo) * f64::from(k) / f64::from(steps));
            out.push(case(format!("{} = {}", d.name, show(&UniformValue::Float(x))), vec![at(d, x)], 0.0));
        }
    }
    for (k, overrides) in random_points(inputs, samples, seed).into_iter().enumerate() {
        out.push(case(format!("random {}", k + 1), overrides, 0.0));
    }
    for d in Degenerate::ALL {
        out.push(Case { name: d.name().into(), overrides: Vec::new(), time: 0.0, degenerate: Some(d) });
    }
    let planned = out.len();
    // Degenerate meshes are kept: no input reaches them.
    if planned > MAX_CASES {
        let keep = MAX_CASES - Degenerate::ALL.len();
        out.drain(keep..planned - Degenerate::ALL.len());
    }
    (out, planned)
}

/// What the runs showed of one warning so far.
#[derive(Debug, Clone, Default)]
struct Tally {
    reached: u64,
    invocations: u64,
    stage: Option<StageKind>,
    /// The first case where the condition held or its zero lay between pixels.
    first: Option<First>,
}

/// What confirmed a warning, summed over the stages that counted in that case.
#[derive(Debug, Clone, Copy)]
struct First {
    case: usize,
    held: u64,
    between: u64,
    reached: u64,
    invocations: u64,
    stage: StageKind,
}

/// The hazard warnings of `c` in `diagnostics`: those in files its stages read.
fn warnings_of(c: &check::Checked, diagnostics: &[Diagnostic]) -> Vec<Diagnostic> {
    let files: Vec<FileId> = c.units.iter().flat_map(|u| u.program.stages.iter().map(|s| s.syntax.file)).collect();
    diagnostics.iter().filter(|d| d.code.is_hazard() && d.file.is_some_and(|f| files.contains(&f)) && d.span.is_some()).cloned().collect()
}

/// Confirms the warnings of one program; verdict notes go onto the warnings in `outcome`.
pub fn confirm_program(gpu: &Gpu, c: &check::Checked, outcome: &mut Outcome, request: &Request) -> Option<ConfirmReport> {
    let program = c.effect.as_ref().map_or(c.name.clone(), |e| e.name.clone());
    let warnings = warnings_of(c, &outcome.diagnostics);
    let wanted: Vec<Wanted> = warnings
        .iter()
        .filter_map(|d| {
            let file = d.file?;
            Some(Wanted { code: d.code, file, range: d.span.clone()?, text: outcome.files.try_get(file)?.text.as_str().into() })
        })
        .collect();
    let inputs = declared(c);
    let (cases, planned) = cases(&inputs, &named_first(&inputs, &wanted), request.samples, request.seed, request.time_limit);
    let vertex = gpu.vertex_storage();
    let built: RefCell<Vec<(usize, Sites)>> = RefCell::new(Vec::new());
    let failed: RefCell<Option<String>> = RefCell::new(None);
    let instrument = |unit: &check::Unit, t: &mut crate::back::Translation| {
        match sites::instrument_translation(t, &unit.program, unit.effect.as_ref(), &wanted, vertex) {
            Ok(s) => built.borrow_mut().push((unit.pass, s)),
            Err(e) => *failed.borrow_mut() = Some(e),
        }
        Ok(())
    };
    let m = MemoryRequest {
        size: request.size,
        frames: 1,
        start: 0.0,
        step: 0.0,
        float: true,
        timeout: request.timeout,
        read_back: Some(COUNTS_BUFFER),
        degenerate: None,
    };
    let mut tallies = vec![Tally::default(); wanted.len()];
    let mut drawn = 0;
    let mut placed: Vec<bool> = vec![false; wanted.len()];
    let mut crowded: Vec<usize> = Vec::new();
    let defaults = with_defaults(&[], &inputs);
    let drawer = if wanted.is_empty() { None } else { MemoryDrawer::new(gpu, c, outcome, &defaults, m, Some(&instrument)) };
    // Why the runs ended before every warning had its chance.
    let mut stopped =
        (!wanted.is_empty() && drawer.is_none()).then(|| "the program could not be drawn (the errors above say why)".to_string());
    if let Some(mut drawer) = drawer {
        let main_sites = built.take();
        for (_, s) in &main_sites {
            for &w in &s.bits {
                placed[w] = true;
            }
            crowded.extend(s.crowded.iter().copied());
        }
        for (i, case) in cases.iter().enumerate() {
            if (0..wanted.len()).all(|w| !placed[w] || tallies[w].first.is_some()) {
                break;
            }
            let (run, sites) = match case.degenerate {
                Some(d) => {
                    let Some(mut program) =
                        MemoryDrawer::new(gpu, c, outcome, &defaults, MemoryRequest { degenerate: Some(d), ..m }, Some(&instrument))
                    else {
                        continue;
                    };
                    let sites = built.take();
                    let Some(run) = program.render(gpu, outcome, case.time) else {
                        stopped = Some(format!("the runs stopped at case `{}`, which could not be drawn", case.name));
                        break;
                    };
                    if run.degenerate.is_empty() {
                        continue;
                    }
                    (run, sites)
                }
                None => {
                    if let Err(e) = drawer.set_overrides(&with_defaults(&case.overrides, &inputs)) {
                        outcome.diagnostics.push(Diagnostic::new(Code::PipelineRejected, e));
                        stopped = Some(format!("the runs stopped at case `{}`, whose values the program refused", case.name));
                        break;
                    }
                    let Some(run) = drawer.render(gpu, outcome, case.time) else {
                        stopped = Some(format!("the runs stopped at case `{}`, which could not be drawn", case.name));
                        break;
                    };
                    (run, main_sites.clone())
                }
            };
            drawn += 1;
            for (pass, words) in &run.read_back {
                let Some((_, s)) = sites.iter().find(|(p, _)| p == pass) else { continue };
                for counted in s.read(words) {
                    tally(&mut tallies, s, &counted, i);
                }
            }
        }
    }
    let why_not = failed.take().map(|e| format!("the program could not be instrumented: {e}")).or(stopped);
    let run = Runs { tallies: &tallies, placed: &placed, crowded: &crowded, cases: &cases, why_not: why_not.as_deref(), vertex };
    let hazards: Vec<Tested> = warnings.iter().enumerate().map(|(w, d)| run.judge(c, &outcome.files, w, d)).collect();
    for (d, t) in warnings.iter().zip(&hazards) {
        annotate(outcome, &program, d, t, drawn);
    }
    Some(ConfirmReport { program, size: request.size, cases: drawn, planned, hazards })
}

/// Which inputs are named near some warning ([`crate::check::hazards::inputs_named_near`]).
fn named_first(inputs: &[Declared], wanted: &[Wanted]) -> Vec<bool> {
    let names: Vec<&str> = inputs.iter().map(|d| d.name.as_str()).collect();
    let mut first = vec![false; inputs.len()];
    for w in wanted {
        for (i, near) in crate::check::hazards::inputs_named_near(&names, &w.text, std::iter::once(w.range.clone())).into_iter().enumerate()
        {
            first[i] |= near;
        }
    }
    first
}

/// What the runs of one program showed, to judge each warning by.
struct Runs<'a> {
    tallies: &'a [Tally],
    placed: &'a [bool],
    /// Warnings left out past [`sites::MAX_SITES`].
    crowded: &'a [usize],
    cases: &'a [Case],
    /// Why the runs ended before every warning had its chance.
    why_not: Option<&'a str>,
    /// The vertex stage was instrumented too.
    vertex: bool,
}

impl Runs<'_> {
    /// The verdict on warning `w` (`d`).
    fn judge(&self, c: &check::Checked, files: &crate::diag::Files, w: usize, d: &Diagnostic) -> Tested {
        let (t, placed) = (&self.tallies[w], self.placed[w]);
        let verdict = match (&t.first, placed, t.reached) {
            (Some(_), _, _) => Verdict::Confirmed,
            (None, false, _) => Verdict::Untested,
            // A run that ended early proves nothing about what it did not reach.
            (None, true, 0) if self.why_not.is_some() => Verdict::Untested,
            (None, true, 0) => Verdict::Unreached,
            (None, true, _) => Verdict::Refuted,
        };
        let reason = (verdict == Verdict::Untested).then(|| match (placed, self.why_not) {
            (true, Some(why)) => why.to_string(),
            // Nothing was placed: the program could not be instrumented or drawn.
            (false, Some(why)) if !self.placed.iter().any(|p| *p) => why.to_string(),
            (false, _) if self.crowded.contains(&w) => {
                format!("more than {} warnings in one program: the first {} are tested", sites::MAX_SITES, sites::MAX_SITES)
            }
            _ => untested_reason(c, d, self.vertex),
        });
        let (held, between, reached, invocations, stage) = match t.first {
            Some(f) => (f.held, f.between, f.reached, f.invocations, Some(f.stage)),
            None => (0, 0, t.reached, t.invocations, t.stage),
        };
        let case = t.first.map(|f| &self.cases[f.case]);
        Tested {
            code: d.code.as_str().to_string(),
            at: location(files, d),
            message: d.message.clone(),
            tier: if d.notes.iter().any(|n| n.starts_with("certain:")) { "certain" } else { "possible" },
            verdict,
            case: case.map(|c| c.name.clone()),
            values: case.map(values),
            held,
            between,
            reached,
            invocations,
            stage: stage.map(stage_name),
            reason,
        }
    }
}

/// Adds what one instrumented entry point counted in case `case` to the tallies.
fn tally(tallies: &mut [Tally], s: &Sites, counted: &Counted, case: usize) {
    for (k, &w) in s.bits.iter().enumerate() {
        let t = &mut tallies[w];
        let (reached, held, between) = (counted.reached[k], counted.held[k], counted.between[k]);
        if reached == 0 {
            continue;
        }
        t.reached += reached;
        t.invocations += counted.invocations;
        t.stage.get_or_insert(counted.stage);
        if (held > 0 || between > 0) && t.first.is_none_or(|f| f.case == case) {
            let f = t.first.get_or_insert(First { case, held: 0, between: 0, reached: 0, invocations: 0, stage: counted.stage });
            f.held += held;
            f.between += between;
            f.reached += reached;
            f.invocations += counted.invocations;
        }
    }
}

/// Why a warning whose operation got no site is untested.
fn untested_reason(c: &check::Checked, d: &Diagnostic, vertex: bool) -> String {
    let in_vertex =
        c.units.iter().flat_map(|u| &u.program.stages).any(|s| Some(s.syntax.file) == d.file && s.syntax.stage != StageKind::Fragment);
    if in_vertex && !vertex {
        return "this device cannot write storage buffers from vertex shaders, where the operation runs".into();
    }
    "the operation is not in the translation at this line (translation folded or removed it), or the run stopped before its pass".into()
}

/// The case's values as `name=value` text.
fn values(case: &Case) -> String {
    let mut v: Vec<String> = case.overrides.iter().map(|(n, x)| format!("{n}={}", show(x))).collect();
    if case.time != 0.0 {
        v.push(format!("time={}", case.time));
    }
    if let Some(d) = case.degenerate {
        v.push(d.name().to_string());
    }
    v.join(" ")
}

fn stage_name(s: StageKind) -> String {
    match s {
        StageKind::Vertex => "vertex".into(),
        _ => "fragment".into(),
    }
}

fn location(files: &crate::diag::Files, d: &Diagnostic) -> String {
    let Some(file) = d.file else { return String::new() };
    let (file, span) = files.resolve(file, d.span.clone());
    let line = span.and_then(|s| files.span_location(file, s)).map_or(0, |l| l.line);
    let cwd = std::env::current_dir().ok();
    format!("{}:{line}", crate::diag::paths::display_path(files.path(file), cwd.as_deref()))
}

/// The condition of a warning as a run sees it: (as it held, as it was never seen).
fn phrases(code: Code) -> (String, String) {
    let (held, never): (&str, &str) = match code {
        Code::HazardDivision => ("the divisor was 0 (or a denormal, which GPUs flush to 0)", "was the divisor 0"),
        Code::HazardAsin => ("the argument left [-1, 1]", "did the argument leave [-1, 1]"),
        Code::HazardSqrt => ("the argument was negative", "was the argument negative"),
        Code::HazardLog | Code::HazardInverseSqrt => ("the argument was 0 or negative", "was the argument 0 or negative"),
        Code::HazardPow => ("the base was negative, or 0 with a power <= 0", "was the base negative, or 0 with a power <= 0"),
        Code::HazardNormalize => ("the vector was zero", "was the vector zero"),
        Code::HazardTrig => ("the argument was past 1e4 rad", "was the argument past 1e4 rad"),
        Code::HazardSinHash => (
            "a sin within GLSL's allowed error (±2⁻¹¹) moves the hash by more than 0.1",
            "did a sin within GLSL's allowed error move the hash by more than 0.1",
        ),
        Code::HazardCounterOverflow => {
            let cap = sites::LOOP_CAP;
            return (
                format!("the loop was still running after {cap} iterations (the run left it there)"),
                format!("did the loop run {cap} iterations"),
            );
        }
        Code::HazardNegativeRemainder => ("an operand was negative", "was an operand negative"),
        Code::HazardShift => ("the amount was negative or at least 32", "was the amount negative or at least 32"),
        Code::HazardAtan2 => ("y and x were both 0", "were y and x both 0"),
        _ => ("its condition held", "did its condition hold"),
    };
    (held.to_string(), never.to_string())
}

impl Tested {
    /// Confirmed only by a zero between pixel centres: no invocation held the condition.
    fn between_only(&self) -> bool {
        self.held == 0 && self.between > 0
    }

    /// The invocations that confirmed it: those that held the condition, else those next
    /// to its zero.
    fn confirming(&self) -> u64 {
        if self.between_only() {
            self.between
        } else {
            self.held
        }
    }
}

/// What confirmed warning `code`: the condition as it held and in how many invocations,
/// else its zero between pixel centres and next to how many.
fn seen(code: Code, t: &Tested) -> (String, u64) {
    if !t.between_only() {
        return (format!("{} in", phrases(code).0), t.confirming());
    }
    let what = match code {
        Code::HazardNormalize => "the vector passed through zero",
        Code::HazardAtan2 => "y and x passed through 0 at one point",
        _ => "the divisor passed through 0",
    };
    (format!("{what} between neighbouring pixel centres, next to"), t.confirming())
}

/// The verdict as a note on the warning, and for a confirmed one error `E0703` at it.
fn annotate(outcome: &mut Outcome, program: &str, d: &Diagnostic, t: &Tested, drawn: usize) {
    let stage = t.stage.as_deref().unwrap_or("");
    let never = phrases(d.code).1;
    let (held, count) = seen(d.code, t);
    let note = match t.verdict {
        Verdict::Confirmed => format!(
            "`stress --confirm`: confirmed in case `{}`: {held} {count} of {} {stage} invocations",
            t.case.as_deref().unwrap_or(""),
            t.invocations
        ),
        Verdict::Refuted => format!(
            "`stress --confirm`: refuted: the operation ran in {} {stage} invocations over {drawn} cases, and never {}",
            t.reached, never
        ),
        Verdict::Unreached => format!("`stress --confirm`: unreached: the operation did not run in any of {drawn} cases"),
        Verdict::Untested => format!("`stress --confirm`: untested: {}", t.reason.as_deref().unwrap_or("")),
    };
    if let Some(w) = outcome.diagnostics.iter_mut().find(|x| x.code == d.code && x.file == d.file && x.span == d.span) {
        w.notes.push(note);
    }
    if t.verdict != Verdict::Confirmed {
        return;
    }
    let (Some(file), Some(span)) = (d.file, d.span.clone()) else { return };
    let e = Diagnostic::new(Code::HazardConfirmed, format!("{program}: {} confirmed by a render: {}", d.code.as_str(), d.message))
        .at(file, span, format!("{held} {count} of {} {stage} invocations", t.invocations))
        .with_note(format!(
            "case `{}`{}",
            t.case.as_deref().unwrap_or(""),
            t.values.as_deref().filter(|v| !v.is_empty()).map(|v| format!(": {v}")).unwrap_or_default()
        ));
    let e = if t.between_only() {
        e.with_note("no pixel centre of this frame lies on that zero; one of another frame size or camera does")
    } else {
        e
    };
    outcome.diagnostics.push(match &d.help {
        Some(h) => e.with_help(h.clone()),
        None => e,
    });
}

/// The human table of one program's verdicts.
pub fn table(r: &ConfirmReport) -> String {
    if r.hazards.is_empty() {
        return format!("{} — no hazard warnings to confirm\n", r.program);
    }
    let count = |v: Verdict| r.hazards.iter().filter(|t| t.verdict == v).count();
    let cut = if r.planned > r.cases { format!(" (of {} planned)", r.planned) } else { String::new() };
    let mut text = format!(
        "{} — {} hazard warnings, {} cases{cut} at {}x{}: {} confirmed, {} refuted, {} unreached, {} untested\n",
        r.program,
        r.hazards.len(),
        r.cases,
        r.size.0,
        r.size.1,
        count(Verdict::Confirmed),
        count(Verdict::Refuted),
        count(Verdict::Unreached),
        count(Verdict::Untested)
    );
    for t in &r.hazards {
        let detail = match t.verdict {
            Verdict::Confirmed => format!(
                "case `{}`: {}/{} {} invocations{}",
                t.case.as_deref().unwrap_or(""),
                t.confirming(),
                t.invocations,
                t.stage.as_deref().unwrap_or(""),
                if t.between_only() { ", zero between pixel centres" } else { "" }
            ),
            Verdict::Refuted => format!("ran in {} {} invocations", t.reached, t.stage.as_deref().unwrap_or("")),
            Verdict::Unreached => "never ran".into(),
            Verdict::Untested => t.reason.clone().unwrap_or_default(),
        };
        let verdict = serde_json::to_value(t.verdict).ok().and_then(|v| v.as_str().map(str::to_string)).unwrap_or_default();
        text.push_str(&format!("  {} {:<8} {:<10} {:<28} {detail}\n", t.code, t.tier, verdict, t.at));
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cases_are_the_assumed_inputs_on_their_grid_then_late_then_steps() {
        let input = |name: &str, lo, hi, step| Declared { name: name.into(), default: UniformValue::Float(1.0), lo, hi, step };
        let inputs = [input("X", -1.0, 1.0, Some(0.1)), input("Y", 0.0, 2.0, None)];
        // Y is named near a warning: its ends come first.
        let (all, planned) = cases(&inputs, &[false, true], 2, 1, 3600.0);
        assert_eq!(planned, all.len());
        let names: Vec<&str> = all.iter().map(|c| c.name.as_str()).collect();
        // Defaults (also late), the ends of Y, all low/high, the same late, then X's ends (and
        // X = 0 inside X's range), late too.
        assert_eq!(
            &names[..12],
            [
                "defaults",
                "defaults at 3600 s",
                "Y low",
                "Y high",
                "all low",
                "all high",
                "Y low at 3600 s",
                "Y high at 3600 s",
                "all low at 3600 s",
                "all high at 3600 s",
                "X low",
                "X high"
            ]
        );
        assert_eq!(all[12].overrides, [("X".to_string(), UniformValue::Float(0.0))], "exactly 0 on a 0.1 grid from -1");
        assert!(names.contains(&"X low at 3600 s") && names.contains(&"defaults at 3600 s"));
        assert!(all.iter().filter(|c| c.name.ends_with("at 3600 s")).all(|c| c.time == 3600.0));
        // X's 20 steps are more than 16: quarters, on its grid; Y's quarters.
        assert!(names.contains(&"X = -0.5") && names.contains(&"Y = 1.5"), "{names:?}");
        for c in &all {
            for (_, v) in &c.overrides {
                let UniformValue::Float(x) = v else { panic!() };
                assert!((-1.0..=2.0).contains(x));
            }
        }
        assert_eq!(all.iter().filter(|c| c.degenerate.is_some()).count(), Degenerate::ALL.len());
        // Many inputs: at most MAX_CASES, the degenerate meshes kept.
        let many: Vec<Declared> = (0..80).map(|i| input(&format!("P{i}"), 0.0, 1.0, None)).collect();
        let (cut, planned) = cases(&many, &[], 8, 1, 3600.0);
        assert!(planned > MAX_CASES && cut.len() == MAX_CASES);
        assert!(cut.last().unwrap().degenerate.is_some());
    }
}
