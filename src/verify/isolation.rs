//! `verify` draws every program with two drivers in process: the system's OpenGL driver
//! and wgpu's. A driver that crashes on one program (llvmpipe's LLVM back end has been seen
//! to, on a geometry stage indexing a sampler array) would take effectc down, and every
//! other program's verdict with it. So the command runs in a child process (the same
//! executable, the same arguments) that notes which program it is drawing; when the child
//! dies by a signal, the parent runs it again with that program skipped and reported as
//! E0502 (the driver crashed), until a child finishes. That child's output and exit code
//! are the command's. Where no child can be started, the command runs in process.

use std::path::PathBuf;
use std::process::ExitCode;

use crate::diag::{Code, Diagnostic, FileId};

/// Set in the child: the file it writes the index of the program it is drawing to.
const PROGRESS: &str = "EFFECTC_VERIFY_PROGRESS";
/// Set in the child: the programs an earlier child crashed on, `index:signal,…`.
const CRASHED: &str = "EFFECTC_VERIFY_CRASHED";

/// In the parent: runs children until one finishes and returns its exit code. `None` in
/// the child itself, and where no child can be started (then the caller runs in process).
#[cfg(unix)]
pub fn supervise() -> Option<ExitCode> {
    use std::os::unix::process::ExitStatusExt;
    if std::env::var_os(PROGRESS).is_some() {
        return None;
    }
    let exe = std::env::current_exe().ok()?;
    let progress = Progress(std::env::temp_dir().join(format!("effectc-verify-{}", std::process::id())));
    let mut crashed: Vec<(usize, i32)> = Vec::new();
    loop {
        let _ = std::fs::remove_file(&progress.0);
        let status = std::process::Command::new(&exe)
            .args(std::env::args_os().skip(1))
            .env(PROGRESS, &progress.0)
            .env(CRASHED, crashed.iter().map(|(i, s)| format!("{i}:{s}")).collect::<Vec<_>>().join(","))
            .status()
            .ok()?;
        let Some(signal) = status.signal() else {
            return Some(ExitCode::from(u8::try_from(status.code().unwrap_or(2)).unwrap_or(2)));
        };
        let drawing = std::fs::read_to_string(&progress.0).ok().and_then(|t| t.trim().parse::<usize>().ok());
        match drawing {
            Some(i) if !crashed.iter().any(|(j, _)| *j == i) => crashed.push((i, signal)),
            _ => {
                eprintln!("error: effectc verify stopped on {} outside the drawing of a program", signal_name(signal));
                return Some(ExitCode::from(2));
            }
        }
    }
}

#[cfg(not(unix))]
pub fn supervise() -> Option<ExitCode> {
    None
}

/// The progress file, removed when the parent is done with it.
struct Progress(PathBuf);

impl Drop for Progress {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

/// In the child: the programs (index in the order they are checked) an earlier child
/// crashed on, with the signal.
pub fn crashed() -> Vec<(usize, i32)> {
    let list = std::env::var(CRASHED).unwrap_or_default();
    list.split(',')
        .filter_map(|p| {
            let (i, s) = p.split_once(':')?;
            Some((i.parse().ok()?, s.parse().ok()?))
        })
        .collect()
}

/// Fault injection for the tests: the child aborts when it starts drawing the program of
/// this index, as a crashing driver would.
const FAULT: &str = "EFFECTC_VERIFY_FAULT";

/// In the child: notes that program `index` is being drawn.
pub fn drawing(index: usize) {
    if let Some(path) = std::env::var_os(PROGRESS) {
        let _ = std::fs::write(path, index.to_string());
        if std::env::var(FAULT).ok().and_then(|f| f.parse::<usize>().ok()) == Some(index) {
            std::process::abort();
        }
    }
}

/// In the child: notes that no program is being drawn any more (a crash after the last one,
/// in a driver's teardown, is no program's).
pub fn drawn_all() {
    if let Some(path) = std::env::var_os(PROGRESS) {
        let _ = std::fs::write(path, "");
    }
}

/// The diagnostic for a program a driver crashed on.
pub fn crash_diagnostic(name: &str, file: FileId, signal: i32) -> Diagnostic {
    Diagnostic::new(Code::GlRejects, format!("a driver crashed ({}) while `{name}` was drawn: it is not verified", signal_name(signal)))
        .in_file(file)
        .with_note("verify draws the original with the system's OpenGL driver and the translation with wgpu; one of them died on this program (a driver bug), and the other programs were verified without it")
}

fn signal_name(signal: i32) -> String {
    let name = match signal {
        4 => "SIGILL",
        6 => "SIGABRT",
        7 => "SIGBUS",
        8 => "SIGFPE",
        9 => "SIGKILL",
        11 => "SIGSEGV",
        _ => return format!("signal {signal}"),
    };
    format!("signal {signal}, {name}")
}

#[cfg(test)]
mod tests {
    use super::signal_name;

    #[test]
    fn signals_are_named() {
        assert_eq!(signal_name(11), "signal 11, SIGSEGV");
        assert_eq!(signal_name(42), "signal 42");
    }
}
