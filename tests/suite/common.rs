//! Helpers shared by the test modules: fixture discovery and rendering.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use effectc::check::{check_inputs, Checked, InputSpec, Outcome};
use effectc::config::HazardSettings;
use effectc::diag;
use effectc::front::program::FrontOptions;

/// Sorted subdirectories of `dir` (relative to the crate root, so paths in output are stable).
pub fn subdirs(dir: &str) -> Vec<PathBuf> {
    let mut dirs: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("cannot read {dir}: {e}"))
        .map(|e| e.unwrap().path())
        .filter(|p| p.is_dir())
        .collect();
    dirs.sort();
    dirs
}

/// The legal programs of `tests/rewrite/` (every suite that walks them expects this many).
pub const REWRITE_FIXTURES: usize = 64;

/// The fixtures under `dir` (sorted subdirectories), narrowed to the names containing one
/// of the comma-separated words of `EFFECTC_FIXTURE` when it is set (like naga's
/// `NAGA_SNAPSHOT`): `EFFECTC_FIXTURE=33-pass cargo test --locked fail_fixtures` runs one.
/// Without the filter the count must be exactly `expected`, so a fixture that goes missing
/// (or one added without updating the count) fails the run.
pub fn fixtures(dir: &str, expected: usize) -> Vec<PathBuf> {
    let all = subdirs(dir);
    match std::env::var("EFFECTC_FIXTURE").ok().filter(|f| !f.trim().is_empty()) {
        Some(filter) => {
            let words: Vec<&str> = filter.split(',').map(str::trim).filter(|w| !w.is_empty()).collect();
            all.into_iter().filter(|d| words.iter().any(|w| name_of(d).contains(w))).collect()
        }
        None => {
            assert_eq!(all.len(), expected, "{dir}: expected {expected} fixtures, found {}", all.len());
            all
        }
    }
}

/// The last path component as a string.
pub fn name_of(path: &Path) -> String {
    path.file_name().unwrap().to_string_lossy().into_owned()
}

/// Checks one path with default options, and the `[hazards]` settings of an
/// `effectc.toml` in the directory itself when it has one.
pub fn check(path: &Path) -> (Outcome, Vec<Checked>) {
    if !path.join(effectc::config::FILE_NAME).exists() {
        return check_inputs(&[path.to_path_buf()], None, FrontOptions::default());
    }
    let hazards = effectc::config::load(None, &[path.to_path_buf()]).config.hazards;
    check_with_hazards(path, hazards)
}

/// Checks one path with default options and the hazard settings given.
pub fn check_with_hazards(path: &Path, hazards: HazardSettings) -> (Outcome, Vec<Checked>) {
    InputSpec { paths: vec![path.to_path_buf()], hazards, ..InputSpec::default() }.check()
}

/// Human rendering without colour, followed by the summary line.
pub fn render(outcome: &Outcome) -> String {
    let mut text = diag::render_human(&outcome.diagnostics, &outcome.files, false);
    text.push_str(&diag::summary_line(&outcome.diagnostics, outcome.programs));
    text.push('\n');
    text
}

/// Stage files (by extension effectc knows) directly under `dir`, sorted.
pub fn stage_files(dir: &Path) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> =
        std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).filter(|p| effectc::inputs::stage_of(p, None).is_some()).collect();
    files.sort();
    files
}

/// Fixture directories named `*crlf*` must really hold CRLF files (a checkout with
/// `core.autocrlf` could silently normalise them).
pub fn assert_crlf_kept(dir: &Path) {
    if name_of(dir).contains("crlf") {
        for file in stage_files(dir) {
            let bytes = std::fs::read(&file).unwrap();
            assert!(bytes.windows(2).any(|w| w == b"\r\n"), "{}: lost its CRLF line ends", file.display());
        }
    }
}

/// Runs the `effectc` binary without colour.
pub fn effectc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_effectc")).args(args).env("NO_COLOR", "1").output().expect("run effectc")
}

pub fn code(out: &Output) -> i32 {
    out.status.code().expect("exit code")
}

pub fn stdout(out: &Output) -> String {
    String::from_utf8(out.stdout.clone()).expect("UTF-8 stdout")
}

/// A fresh, empty scratch directory for one test of `group`.
pub fn scratch(group: &str, name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(group).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// True under CI (`CI` set): optional tools and devices become required.
pub fn in_ci() -> bool {
    std::env::var_os("CI").is_some()
}

/// `glslangValidator` links the program (OpenGL semantics, else Vulkan's); None when the
/// tool is missing outside CI.
pub fn glslang_links(dir: &Path) -> Option<bool> {
    let files: Vec<std::path::PathBuf> = stage_files(dir).iter().map(|f| std::fs::canonicalize(f).unwrap()).collect();
    let scratch = scratch("rewrite-glslang", &name_of(dir));
    let run = |vulkan: bool| {
        let mut c = Command::new("glslangValidator");
        c.current_dir(&scratch);
        if vulkan {
            c.arg("-V");
        }
        c.arg("-l").args(&files).output()
    };
    match run(false) {
        Err(_) => {
            assert!(!in_ci(), "glslangValidator is missing (Debian package glslang-tools; ./setup.sh installs it)");
            None
        }
        Ok(o) if o.status.success() => Some(true),
        Ok(_) => Some(run(true).is_ok_and(|o| o.status.success())),
    }
}
