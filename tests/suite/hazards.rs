//! Static hazards (`effectc check`, W0710–W0722): provably safe code raises nothing, and a
//! bare stage file reports the hazards a witness run shows (certain) only.
//!
//! Each seed hazard has a fixture under `tests/fail/4N-hazard-*-warning` (run by
//! [`crate::fail`], snapshotted). Here: the same hazards written with their guards under
//! `tests/safe/` produce no diagnostic at all, not even a possible one, and neither do the
//! shipped effects.

use std::path::PathBuf;

use effectc::config::{HazardReport, HazardSettings};
use effectc::diag::Diagnostic;

use crate::common;

fn possible() -> HazardSettings {
    HazardSettings { report: Some(HazardReport::Possible), ..HazardSettings::default() }
}

#[test]
fn guarded_hazards_raise_nothing() {
    let dirs = common::fixtures("tests/safe", 4);
    for dir in dirs.iter().chain(common::fixtures("effects", 21).iter()) {
        let (outcome, _) = common::check_with_hazards(dir, possible());
        assert!(outcome.diagnostics.is_empty(), "{}:\n{}", dir.display(), common::render(&outcome));
    }
}

/// A fresh directory holding a pass-through vertex stage and `fragment` as `a.frag`.
fn program(test: &str, fragment: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("effectc-hazards-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let vertex = "#version 330\nlayout(location = 0) in vec4 pos;\nout vec2 uv;\nvoid main() { uv = pos.xy; gl_Position = pos; }\n";
    std::fs::write(dir.join("a.vert"), vertex).unwrap();
    std::fs::write(dir.join("a.frag"), fragment).unwrap();
    dir
}

/// The hazard warnings (W07xx) as (line, tier note) pairs.
fn hazards(diags: &[Diagnostic], files: &effectc::diag::Files) -> Vec<(usize, String)> {
    diags
        .iter()
        .filter(|d| d.code.as_str().starts_with("W07"))
        .map(|d| {
            let line = d.file.zip(d.span.clone()).map_or(0, |(f, s)| files.text(f)[..s.start].matches('\n').count() + 1);
            let tier = d.notes.iter().find(|n| n.starts_with("certain:") || n.starts_with("possible:")).cloned().unwrap_or_default();
            (line, tier)
        })
        .collect()
}

const TIERS: &str = "#version 330
#pragma parameter MASK_TYPE \"Mask type\" 4.0 0.0 7.0 1.0
#pragma parameter SIZE \"Size\" 1.0 1.0 4.0 1.0
uniform float MASK_TYPE, SIZE;
in vec2 uv;
out vec4 color;
void main() {
    float colors = 0.0;
    if (MASK_TYPE == 1.0) colors = 2.0;
    float a = uv.x / colors;
    float b = 1.0 / (SIZE - 2.5);
    color = vec4(a, b, 0.0, 1.0);
}
";

#[test]
fn bare_files_report_the_certain_tier_unless_asked_for_the_possible_one() {
    let dir = program("tiers", TIERS);
    let (outcome, _) = common::check(&dir);
    let found = hazards(&outcome.diagnostics, &outcome.files);
    // `uv.x / colors` at MASK_TYPE's default, 4: no branch sets `colors`.
    assert_eq!(found.len(), 1, "{found:?}");
    assert_eq!(found[0].0, 10);
    assert!(found[0].1.contains("with every declared input at its default"), "{found:?}");
    let (outcome, _) = common::check_with_hazards(&dir, possible());
    let found = hazards(&outcome.diagnostics, &outcome.files);
    // `1.0 / (SIZE - 2.5)`: possible, as no run at SIZE's default, ends or steps hits 2.5.
    assert_eq!(found.iter().map(|(l, t)| (*l, t.starts_with("certain:"))).collect::<Vec<_>>(), [(10, true), (11, false)], "{found:?}");
}

#[test]
fn a_witness_needs_an_operation_that_surely_runs() {
    let fragment = "#version 330
#pragma parameter K \"k\" 1.0 0.0 2.0 0.5
uniform float K;
in vec2 uv;
out vec4 color;
float f(float x) { return 1.0 / x; }
void main() {
    float guarded = K != 0.0 ? 1.0 / K : 0.0;
    float branch = 0.0;
    if (uv.x > 0.5) branch = 1.0 / (K - K * 1.0);
    float both = K > 0.5 && 1.0 / K > 0.0 ? 1.0 : 0.0;
    color = vec4(guarded, branch, both, f(uv.y));
}
";
    let dir = program("sure", fragment);
    let (outcome, _) = common::check(&dir);
    // `?:` and `&&` skip the division at K = 0; the `if` on a varying may not run.
    assert_eq!(hazards(&outcome.diagnostics, &outcome.files), [], "{}", common::render(&outcome));
}

#[test]
fn loops_run_iteration_by_iteration_and_a_switch_takes_its_case() {
    let fragment = "#version 330
#pragma parameter MODE \"mode\" 0.0 0.0 2.0 1.0
uniform float MODE;
in vec2 uv;
out vec4 color;
void main() {
    float sum = 0.0;
    for (int i = -3; i <= 3; i++) {
        sum += pow(float(i), 2.0);
    }
    float d = 1.0;
    switch (int(MODE)) {
        case 0: d = 2.0; break;
        case 1: d = 0.0; break;
        default: d = 3.0;
    }
    color = vec4(sum, uv.x / d, 0.0, 1.0);
}
";
    let dir = program("loops", fragment);
    let (outcome, _) = common::check(&dir);
    let found = hazards(&outcome.diagnostics, &outcome.files);
    assert_eq!(found.iter().map(|(l, _)| *l).collect::<Vec<_>>(), [9, 17], "{}", common::render(&outcome));
    assert!(found[0].1.contains("every declared input at its default"), "{found:?}");
    assert!(found[1].1.contains("MODE = 1 (a step of its `#pragma parameter` range)"), "{found:?}");
}
