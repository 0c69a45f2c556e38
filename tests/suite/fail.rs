//! Failure fixtures: `tests/fail/NN-name/` holds an `effect.toml` with its stages, or stage
//! files only, plus an `expect` file listing the diagnostic code(s) it must produce.
//!
//! Each fixture must produce at least one error — or, when its name ends in `-warning`, at
//! least one warning and no error — and every expected code. The human rendering is
//! snapshotted as `snapshots/fail/<dir name>.snap`, so message, span and label changes
//! show up in review.

use effectc::diag::{self, Code, Severity};

use crate::common;

#[test]
fn fail_fixtures() {
    let dirs = common::fixtures("tests/fail", 60);
    let mut settings = insta::Settings::clone_current();
    settings.set_snapshot_path("../../snapshots/fail");
    settings.set_prepend_module_to_snapshot(false);
    settings.set_omit_expression(true);
    let mut problems = Vec::new();
    for dir in &dirs {
        let name = common::name_of(dir);
        let expect = std::fs::read_to_string(dir.join("expect")).unwrap_or_else(|e| panic!("{name}: missing `expect` file: {e}"));
        common::assert_crlf_kept(dir);
        let (outcome, _) = common::check(dir);
        let diags = &outcome.diagnostics;
        let text = common::render(&outcome);
        if name.ends_with("-warning") {
            if diag::has_errors(diags) || diag::count(diags, Severity::Warning) == 0 {
                problems.push(format!("{name}: expected warnings only, got:\n{text}"));
            }
        } else if !diag::has_errors(diags) {
            problems.push(format!("{name}: expected an error, got:\n{text}"));
        }
        for code in expect.split_whitespace() {
            match code.parse::<Code>() {
                Ok(code) if diags.iter().any(|d| d.code == code) => {}
                Ok(code) => problems.push(format!("{name}: expected code {code}, got:\n{text}")),
                Err(e) => problems.push(format!("{name}: `expect` names an {e}")),
            }
        }
        settings.bind(|| insta::assert_snapshot!(name.as_str(), text));
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}
