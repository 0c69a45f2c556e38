//! Witness runs: the analysis again with the declared inputs at points (every one at its
//! default; the inputs named near a hazard all at the low, then all at the high ends of
//! their ranges; then one at a time at the ends of its range and, when there are few, its
//! steps), time and frame counters at 0, loops followed iteration by iteration. A hazard a
//! witness run reports happens at those inputs ([`super::tier`]): it is **certain**.
//!
//! Inputs without a declared range keep the interval the analysis assumes, so only what
//! happens for every value of them can be witnessed.

use super::facts::{Declared, Facts};
use super::interval::Iv;
use super::value::Num;
use crate::front::lexical::identifiers;
use crate::manifest::Semantic;

/// Steps of a range tried one by one when there are at most this many.
const MAX_STEPS: f64 = 16.0;

/// One set of inputs: every declared input at its default, except those listed (indices
/// into [`Facts::declared`]) at the values given.
#[derive(Debug, Clone, PartialEq)]
pub struct Sample {
    pub varied: Vec<(usize, f64)>,
}

/// The samples to try, in order: the defaults; the inputs `first` marks all at the low,
/// then all at the high ends of their ranges (two runs where one per input would cost
/// many); then, for the inputs `first` marks and then for the others, one input's range
/// ends, then the steps inside the ranges.
pub fn samples(declared: &[Declared], first: &[bool]) -> Vec<Sample> {
    let (ahead, behind): (Vec<usize>, Vec<usize>) = (0..declared.len()).partition(|&i| first.get(i) == Some(&true));
    let mut out = vec![Sample { varied: Vec::new() }];
    if ahead.len() > 1 {
        for end in [|d: &Declared| d.range.0, |d: &Declared| d.range.1] {
            let varied: Vec<(usize, f64)> =
                ahead.iter().map(|&i| (i, end(&declared[i]))).filter(|&(i, v)| v != declared[i].default).collect();
            if varied.len() > 1 {
                out.push(Sample { varied });
            }
        }
    }
    out.extend(samples_of(declared, &ahead));
    out.extend(samples_of(declared, &behind));
    out
}

/// The range ends, then the steps, of the inputs `which`.
fn samples_of(declared: &[Declared], which: &[usize]) -> Vec<Sample> {
    let mut out: Vec<Sample> = Vec::new();
    let mut inner = Vec::new();
    for &i in which {
        let d = &declared[i];
        let (lo, hi) = d.range;
        for v in [lo, hi] {
            if v != d.default && !out.iter().any(|s| s.varied == [(i, v)]) {
                out.push(Sample { varied: vec![(i, v)] });
            }
        }
        if let Some(step) = d.step.filter(|s| (hi - lo) / s <= MAX_STEPS) {
            let mut k = 1.0;
            while lo + k * step < hi - step * 1e-6 {
                let v = lo + k * step;
                if (v - d.default).abs() > step * 1e-6 {
                    inner.push(Sample { varied: vec![(i, v)] });
                }
                k += 1.0;
            }
        }
    }
    out.extend(inner);
    out
}

/// Which declared inputs are named near the hazards at `spans` of `text`: on their lines,
/// or on a line that assigns a variable named there (one step back). Their samples run
/// first, so a stage with hundreds of parameters spends its witness budget on the ones
/// that matter.
pub fn named_near(declared: &[&str], text: &str, spans: impl Iterator<Item = std::ops::Range<usize>>) -> Vec<bool> {
    let line_of = |at: usize| line_at(text, at);
    let mut lines: Vec<&str> = spans.map(|r| line_of(r.start)).collect();
    lines.sort_unstable();
    lines.dedup();
    let mut words: Vec<&str> = lines.iter().flat_map(|l| identifiers(l)).collect();
    words.sort_unstable();
    words.dedup();
    for w in words.iter().take(64) {
        if declared.contains(w) {
            continue;
        }
        // `w = …`, `w += …`, `float w = …`: the lines that give a named variable its value.
        let mut from = 0;
        while let Some(i) = text[from..].find(w) {
            let at = from + i;
            from = at + w.len();
            let before = text[..at].chars().next_back().is_some_and(|c| c.is_ascii_alphanumeric() || c == '_');
            let after = text[from..].trim_start();
            let assigns = !after.starts_with("==")
                && (after.starts_with('=') || after.get(1..2) == Some("=") && after.starts_with(['+', '-', '*', '/']));
            if !before && assigns && lines.len() < 256 {
                lines.push(line_of(at));
            }
        }
    }
    declared.iter().map(|d| lines.iter().any(|l| identifiers(l).any(|w| w == *d))).collect()
}

/// The line of `text` holding offset `at`.
fn line_at(text: &str, at: usize) -> &str {
    let at = at.min(text.len());
    let start = text[..at].rfind('\n').map_or(0, |i| i + 1);
    let end = text[at..].find('\n').map_or(text.len(), |i| at + i);
    &text[start..end]
}

/// What the analysis assumed of the inputs named on the line at `at`, and where each came
/// from: a declared range, or the time limit (a default assumption unless a manifest or
/// `effectc.toml` sets it). Empty when the line names none.
pub fn assumed_on_line(f: &Facts, text: &str, at: usize) -> Vec<String> {
    let mut words: Vec<&str> = identifiers(line_at(text, at)).collect();
    words.sort_unstable();
    words.dedup();
    let clock = |w: &str| {
        let guessed = !f.guessed.is_empty()
            && matches!(crate::manifest::guess::semantic_by_name(w, (1, 1), true), Some(Semantic::Time | Semantic::Frame));
        f.clocks.iter().any(|c| c == w) || guessed
    };
    let mut out = Vec::new();
    for w in words {
        if let Some(d) = f.declared.iter().find(|d| d.name == w) {
            out.push(format!("{w} in [{}, {}] (its {} range)", super::big(d.range.0), super::big(d.range.1), d.by.source()));
        } else if clock(w) {
            out.push(format!(
                "{w} over a session of {} s (the time limit: an hour unless `[hazards] time-limit` or the manifest says otherwise)",
                super::big(f.time_limit)
            ));
        }
    }
    out
}

/// The facts of one sample: declared inputs and clocks at points, the rest as `base` has it.
pub fn facts_at(base: &Facts, sample: &Sample) -> Facts {
    let mut f = base.clone();
    f.read_clock = Default::default();
    for (i, d) in base.declared.iter().enumerate() {
        let v = sample.varied.iter().find(|(j, _)| *j == i).map_or(d.default, |(_, v)| *v);
        let n = match base.uniforms.get(&d.name) {
            Some(n) => Num::from_comps(vec![Iv::point(v); n.c.len()], n.cols, n.kind, true),
            None => Num::float(Iv::point(v)),
        };
        f.uniforms.insert(d.name.clone(), Num { per_draw: true, ..n });
    }
    for name in &base.clocks {
        if let Some(n) = f.uniforms.get_mut(name) {
            let start = n.iv().lo.max(0.0);
            *n = Num { per_draw: true, ..Num::scalar(Iv::point(start), n.kind, true) };
        }
    }
    for s in [Semantic::Time, Semantic::Frame] {
        if let Some(n) = f.guessed.get_mut(&s) {
            *n = Num { per_draw: true, ..Num::scalar(Iv::point(0.0), n.kind, true) };
        }
    }
    f
}

/// Where a witness found a hazard, for people: "with MASK_TYPE = 0 (the low end of its
/// `#pragma parameter` range) and every other parameter at its default, at time 0".
pub fn describe(declared: &[Declared], sample: &Sample, clock: bool) -> String {
    let clock = if clock { ", at time 0 (the first frame)" } else { "" };
    let place = |d: &Declared, v: f64| {
        if v == d.range.0 {
            "the low end of its"
        } else if v == d.range.1 {
            "the high end of its"
        } else {
            "a step of its"
        }
    };
    let others = if declared.len() > sample.varied.len() { " and every other declared input at its default" } else { "" };
    let Some(&(first, v0)) = sample.varied.first() else {
        return match declared.is_empty() {
            true => format!("on every run that reaches it{clock}"),
            false => format!("with every declared input at its default{clock}"),
        };
    };
    let alike =
        sample.varied.iter().all(|&(i, v)| place(&declared[i], v) == place(&declared[first], v0) && declared[i].by == declared[first].by);
    let values = |with_place: bool| {
        let one = |&(i, v): &(usize, f64)| {
            let d = &declared[i];
            match with_place {
                true => format!("{} = {} ({} {} range)", d.name, super::big(v), place(d, v), d.by.source()),
                false => format!("{} = {}", d.name, super::big(v)),
            }
        };
        sample.varied.iter().map(one).collect::<Vec<_>>().join(", ")
    };
    if sample.varied.len() > 1 && alike {
        // "the low end of its" → "the low ends of their".
        let places = place(&declared[first], v0).replace("end of its", "ends of their").replace("step of its", "steps of their");
        format!("with {} ({places} {} ranges){others}{clock}", values(false), declared[first].by.source())
    } else {
        format!("with {}{others}{clock}", values(true))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::hazards::facts::DeclaredBy;

    fn declared(default: f64, range: (f64, f64), step: Option<f64>) -> Declared {
        Declared { name: "MASK_TYPE".into(), default, range, step, by: DeclaredBy::Pragma }
    }

    #[test]
    fn defaults_then_ends_then_steps() {
        let s = samples(&[declared(4.0, (0.0, 7.0), Some(1.0))], &[]);
        let values: Vec<Option<f64>> = s.iter().map(|s| s.varied.first().map(|(_, v)| *v)).collect();
        assert_eq!(values, [None, Some(0.0), Some(7.0), Some(1.0), Some(2.0), Some(3.0), Some(5.0), Some(6.0)]);
    }

    #[test]
    fn a_fine_step_tries_the_ends_only() {
        assert_eq!(samples(&[declared(0.03, (0.0, 0.2), Some(0.001))], &[]).len(), 3);
        assert_eq!(samples(&[declared(0.0, (0.0, 0.0), Some(0.0))], &[]).len(), 1, "a header parameter");
    }

    #[test]
    fn inputs_named_near_a_hazard_are_tried_first() {
        let named = |n: &str| Declared { name: n.into(), ..declared(1.0, (0.0, 2.0), None) };
        let d = [named("A"), named("B"), named("C")];
        let text = "float s = B * 2.0;\nfloat t = 1.0;\nt += C;\nfloat x = y / (s + t);\n";
        let at = text.find("y /").unwrap();
        let first = named_near(&["A", "B", "C"], text, std::iter::once(at..at + 1));
        assert_eq!(first, [false, true, true]);
        let order: Vec<Vec<usize>> = samples(&d, &first).iter().map(|s| s.varied.iter().map(|(i, _)| *i).collect()).collect();
        assert_eq!(order, [vec![], vec![1, 2], vec![1, 2], vec![1], vec![1], vec![2], vec![2], vec![0], vec![0]]);
    }

    #[test]
    fn the_assumptions_of_a_line_name_their_source() {
        let mut f = Facts::guessed(3600.0);
        f.declared.push(declared(4.0, (0.0, 7.0), Some(1.0)));
        let text = "float a = 1.0;\nfloat b = x / (MASK_TYPE - sin(iTime));\n";
        let said = assumed_on_line(&f, text, text.find("x /").unwrap());
        assert_eq!(said.len(), 2, "{said:?}");
        assert_eq!(said[0], "MASK_TYPE in [0, 7] (its `#pragma parameter` range)");
        assert!(said[1].starts_with("iTime over a session of 3600 s"), "{said:?}");
        assert!(assumed_on_line(&f, text, 0).is_empty());
    }

    #[test]
    fn descriptions_name_the_input_and_where_its_value_lies() {
        let d = [declared(4.0, (0.0, 7.0), Some(1.0))];
        assert_eq!(
            describe(&d, &Sample { varied: vec![(0, 0.0)] }, true),
            "with MASK_TYPE = 0 (the low end of its `#pragma parameter` range), at time 0 (the first frame)"
        );
        assert_eq!(describe(&[], &Sample { varied: Vec::new() }, false), "on every run that reaches it");
        let two = [declared(4.0, (0.0, 7.0), None), Declared { name: "SIZE".into(), ..declared(1.0, (0.5, 2.0), None) }];
        assert_eq!(
            describe(&two, &Sample { varied: vec![(0, 0.0), (1, 0.5)] }, false),
            "with MASK_TYPE = 0, SIZE = 0.5 (the low ends of their `#pragma parameter` ranges)"
        );
    }
}
