//! Rewrite corpus: `tests/rewrite/NN-name/` holds one legal desktop-GLSL program (stage
//! files grouped by stem, accepted by `glslangValidator -l`). Each must check without
//! errors, naga must validate every stage it can parse, and the 4.50 text naga sees is
//! snapshotted as `snapshots/rewrite/<dir>-<file>.snap` for review.
//!
//! Legal GLSL effectc still rejects (or silently miscompiles) lives in
//! `tests/rewrite_known_failures/`, each with a `why` file; those are only run to show
//! their current diagnostics (`cargo test -- --nocapture`), never failed.

use effectc::diag;

use crate::common;

#[test]
fn rewrite_corpus() {
    let dirs = common::subdirs("tests/rewrite");
    assert!(
        dirs.len() >= 20,
        "expected at least 20 programs, found {}",
        dirs.len()
    );
    let mut settings = insta::Settings::clone_current();
    settings.set_snapshot_path("../../snapshots/rewrite");
    settings.set_prepend_module_to_snapshot(false);
    settings.set_omit_expression(true);
    let mut problems = Vec::new();
    for dir in &dirs {
        let name = common::name_of(dir);
        common::assert_crlf_kept(dir);
        let (outcome, checked) = common::check(dir);
        if diag::has_errors(&outcome.diagnostics) || outcome.programs != 1 {
            problems.push(format!("{name}:\n{}", common::render(&outcome)));
            continue;
        }
        let program = checked[0].program.as_ref().expect("a checked program");
        assert_eq!(
            program.stages.len(),
            common::stage_files(dir).len(),
            "{name}: every stage file compiled"
        );
        for stage in &program.stages {
            let path = outcome.files.path(stage.syntax.file);
            let file = path.rsplit('/').next().unwrap();
            let rewritten = stage
                .rewritten
                .as_ref()
                .unwrap_or_else(|| panic!("{path}: no rewrite"));
            assert!(
                stage.naga.is_some(),
                "{path}: naga did not validate the rewrite"
            );
            assert!(
                rewritten.text.starts_with("#version 450"),
                "{path}: rewrite is not 4.50"
            );
            settings.bind(|| insta::assert_snapshot!(format!("{name}-{file}"), rewritten.text));
        }
    }
    assert!(
        problems.is_empty(),
        "legal GLSL rejected:\n{}",
        problems.join("\n")
    );
}

/// Reports (never fails) on the known failures, so a fix is noticed in the test output.
#[test]
fn rewrite_known_failures_report() {
    for dir in common::subdirs("tests/rewrite_known_failures") {
        let (outcome, _) = common::check(&dir);
        let why = std::fs::read_to_string(dir.join("why")).unwrap_or_default();
        let status = if diag::has_errors(&outcome.diagnostics) {
            "errors"
        } else {
            "no errors (fixed, or a silent miscompile: see why)"
        };
        eprintln!(
            "{}: {status}\nwhy: {why}{}",
            dir.display(),
            common::render(&outcome)
        );
    }
}
