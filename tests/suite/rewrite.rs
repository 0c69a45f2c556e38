//! Rewrite corpus: `tests/rewrite/NN-name/` holds one legal GLSL program (stage files
//! grouped by stem). The test proves it legal with `glslangValidator -l` (Vulkan GLSL:
//! `-V -l`); each must check without errors or rewrite failures (W0190), naga must validate every stage it can parse,
//! and the 4.50 text naga sees is snapshotted as `snapshots/rewrite/<dir>-<file>.snap`.
//!
//! Legal GLSL effectc still rejects, or checks without naga (note N0102), or cannot
//! translate, lives in `tests/rewrite_known_failures/`, each with a `why` file. That list
//! is kept true: an entry that starts passing fails the test (move it to `tests/rewrite/`).

use std::process::Command;

use effectc::diag;

use crate::common;

#[test]
fn rewrite_corpus() {
    let dirs = common::fixtures("tests/rewrite", common::REWRITE_FIXTURES);
    let mut settings = insta::Settings::clone_current();
    settings.set_snapshot_path("../../snapshots/rewrite");
    settings.set_prepend_module_to_snapshot(false);
    settings.set_omit_expression(true);
    let mut problems = Vec::new();
    for dir in &dirs {
        let name = common::name_of(dir);
        common::assert_crlf_kept(dir);
        match common::glslang_links(dir) {
            Some(true) => {}
            Some(false) => problems.push(format!("{name}: glslangValidator does not link it, so it is no legal fixture")),
            None => eprintln!("glslangValidator not found: {name} not proven legal"),
        }
        let (outcome, checked) = common::check(dir);
        // A legal program the rewrite cannot take is effectc's bug (W0190), not a warning.
        let rewrite_failed = outcome.diagnostics.iter().any(|d| d.code == diag::Code::RewriteFailed);
        if diag::has_errors(&outcome.diagnostics) || outcome.programs != 1 || rewrite_failed {
            problems.push(format!("{name}:\n{}", common::render(&outcome)));
            continue;
        }
        let program = &checked[0].units.first().expect("a checked program").program;
        assert_eq!(program.stages.len(), common::stage_files(dir).len(), "{name}: every stage file compiled");
        for stage in &program.stages {
            let path = outcome.files.path(stage.syntax.file);
            let file = path.rsplit('/').next().unwrap();
            let rewritten = stage.rewritten.as_ref().unwrap_or_else(|| panic!("{path}: no rewrite"));
            assert!(stage.naga.is_some(), "{path}: naga did not validate the rewrite");
            assert!(rewritten.text.starts_with("#version 450"), "{path}: rewrite is not 4.50");
            settings.bind(|| insta::assert_snapshot!(format!("{name}-{file}"), rewritten.text));
        }
    }
    assert!(problems.is_empty(), "legal GLSL rejected:\n{}", problems.join("\n"));
}

/// Every known failure still fails (check errors, a stage naga does not validate, or no
/// translation); one that passes must move to `tests/rewrite/`, so the list stays true.
#[test]
fn rewrite_known_failures_still_fail() {
    let mut now_passing = Vec::new();
    for dir in common::fixtures("tests/rewrite_known_failures", 4) {
        let name = common::name_of(&dir);
        let why = std::fs::read_to_string(dir.join("why")).unwrap_or_default();
        assert!(!why.trim().is_empty(), "{name}: no `why` file");
        let (outcome, checked) = common::check(&dir);
        let status = if diag::has_errors(&outcome.diagnostics) {
            "check errors".to_string()
        } else {
            let program = &checked[0].units.first().expect("a checked program").program;
            let unvalidated = program.stages.iter().filter(|s| s.syntax.stage.naga().is_some() && s.naga.is_none()).count();
            if unvalidated > 0 {
                format!("{unvalidated} stage(s) not validated by naga")
            } else {
                match effectc::back::translate(&name, program, None, effectc::back::TranslateOptions::default()) {
                    Ok(_) => {
                        now_passing.push(name.clone());
                        "passes".to_string()
                    }
                    Err(_) => "does not translate".to_string(),
                }
            }
        };
        eprintln!("{}: {status}\nwhy: {why}{}", dir.display(), common::render(&outcome));
    }
    assert!(
        now_passing.is_empty(),
        "known failures that now pass (move them to tests/rewrite/ with a snapshot): {}",
        now_passing.join(", ")
    );
}

/// Geometry programs (`tests/geometry/NN-name/`, legal by `glslangValidator -l`): the
/// geometry stage is not run by naga, but it is rewritten to 4.50 with the others (shared
/// uniform block, the plan's locations), and each rewritten stage compiles on its own
/// (`glslangValidator -V`): the lowering of geometry stages starts from these texts. (They
/// are not linked by name: the rewrite may rename a block member that collides with a
/// vertex input, which location matching does not mind.)
#[test]
fn geometry_programs_rewrite_to_legal_450_stages() {
    for dir in common::fixtures("tests/geometry", 13) {
        let name = common::name_of(&dir);
        assert_ne!(common::glslang_links(&dir), Some(false), "{name}: glslangValidator does not link it, so it is no legal fixture");
        let (outcome, checked) = common::check(&dir);
        assert!(!diag::has_errors(&outcome.diagnostics), "{name}:\n{}", common::render(&outcome));
        let program = &checked[0].units.first().expect("a checked program").program;
        let scratch = common::scratch("geometry-rewrite", &name);
        let mut files = Vec::new();
        for stage in &program.stages {
            let geometry = stage.syntax.stage == effectc::stage::StageKind::Geometry;
            assert_eq!(stage.naga.is_none(), geometry, "{name}: naga runs on every stage but the geometry stage");
            let rewritten =
                stage.rewritten.as_ref().unwrap_or_else(|| panic!("{name}: the {} stage was not rewritten", stage.syntax.stage));
            assert!(rewritten.text.contains("#version 450"), "{name}: not 4.50");
            let file = scratch.join(outcome.files.path(stage.syntax.file).rsplit('/').next().unwrap());
            std::fs::write(&file, &rewritten.text).unwrap();
            files.push(file);
        }
        for file in &files {
            match Command::new("glslangValidator").current_dir(&scratch).arg("-V").arg(file).output() {
                Ok(o) => assert!(o.status.success(), "{name}: {} is not legal:\n{}", file.display(), String::from_utf8_lossy(&o.stdout)),
                Err(_) => assert!(!common::in_ci(), "glslangValidator is missing (Debian package glslang-tools; ./setup.sh installs it)"),
            }
        }
    }
}
