//! Reading the files a user's input names, bounded: only regular files, never more than a
//! limit, and (for files a shader names) only inside the project root.
//!
//! effectc reads pull requests nobody has reviewed: a stage or `#include` of `/dev/zero`
//! would grow without end, a FIFO would block, and `#include "/proc/self/environ"` would
//! print the CI job's secrets in a diagnostic's snippet. Every stage and included file goes
//! through [`bounded`]; included files also through [`confined`].

use std::io::Read;
use std::path::{Path, PathBuf};

/// Largest stage or included file read (bytes): far above any real shader (the largest
/// generated stages met are ~2 MB), far below what would exhaust memory.
pub const MAX_FILE_BYTES: u64 = 16 << 20;

/// Why a file was not read.
#[derive(Debug)]
pub enum Refused {
    /// Not a regular file: what it is (`a directory`, `a device`, `a FIFO`, `a socket`).
    NotAFile(&'static str),
    /// Larger than the limit (bytes).
    TooLarge(u64),
    /// The operating system's error (missing, no permission, a symlink loop).
    Io(std::io::Error),
}

impl std::fmt::Display for Refused {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Refused::NotAFile(what) => write!(f, "it is {what}, not a regular file"),
            Refused::TooLarge(limit) => write!(f, "it is larger than effectc's limit of {} MiB per file", limit >> 20),
            Refused::Io(e) => write!(f, "{e}"),
        }
    }
}

/// The bytes of the regular file at `path` (symlinks followed), at most `limit` of them.
pub fn bounded(path: &Path, limit: u64) -> Result<Vec<u8>, Refused> {
    let meta = std::fs::metadata(path).map_err(Refused::Io)?;
    if !meta.is_file() {
        return Err(Refused::NotAFile(kind_of(&meta)));
    }
    let file = std::fs::File::open(path).map_err(Refused::Io)?;
    // The size on disk can lie (`/proc` files say 0) or change: the read itself is capped.
    let mut bytes = Vec::with_capacity(meta.len().min(limit) as usize);
    file.take(limit + 1).read_to_end(&mut bytes).map_err(Refused::Io)?;
    if bytes.len() as u64 > limit {
        return Err(Refused::TooLarge(limit));
    }
    Ok(bytes)
}

/// [`bounded`] as text, bytes that are not UTF-8 replaced (for looking into a file, not
/// for compiling it).
pub fn bounded_text_lossy(path: &Path) -> Result<String, Refused> {
    bounded(path, MAX_FILE_BYTES).map(|b| String::from_utf8_lossy(&b).into_owned())
}

/// The note of a refusal to read outside `root` (E0106): which directory, why, and that
/// `what` (the stage, the manifest) is under review.
pub fn outside_root_note(root: &Path, what: &str) -> String {
    format!(
        "effectc reads only files inside `{}` (the nearest directory with an `effectc.toml` or `.git`, else the {what}'s own): a {what} under review must not read the machine's files",
        root.display()
    )
}

fn kind_of(meta: &std::fs::Metadata) -> &'static str {
    use std::os::unix::fs::FileTypeExt;
    let t = meta.file_type();
    if t.is_dir() {
        "a directory"
    } else if t.is_fifo() {
        "a FIFO"
    } else if t.is_socket() {
        "a socket"
    } else if t.is_char_device() || t.is_block_device() {
        "a device"
    } else {
        "not a regular file"
    }
}

/// The project root of a file a user named: the nearest directory above it holding an
/// `effectc.toml` or a `.git`, else the file's own directory.
pub fn project_root(file: &Path) -> PathBuf {
    let file = std::fs::canonicalize(file).unwrap_or_else(|_| file.to_path_buf());
    let dir = file.parent().map(Path::to_path_buf).unwrap_or_else(|| PathBuf::from("."));
    dir.ancestors().find(|d| d.join("effectc.toml").is_file() || d.join(".git").exists()).map(Path::to_path_buf).unwrap_or(dir)
}

/// `target` resolved (symlinks, `..`) lies inside `root`: where a file a shader names may be.
/// A target that does not exist is judged by its path as written, made absolute.
pub fn confined(target: &Path, root: &Path) -> bool {
    let resolved = std::fs::canonicalize(target).unwrap_or_else(|_| lexically_absolute(target));
    let root = std::fs::canonicalize(root).unwrap_or_else(|_| lexically_absolute(root));
    resolved.starts_with(root)
}

/// `path` made absolute with `.` and `..` folded, without touching the file system.
fn lexically_absolute(path: &Path) -> PathBuf {
    let base = if path.is_absolute() { PathBuf::new() } else { std::env::current_dir().unwrap_or_default() };
    let mut out = PathBuf::new();
    for c in base.join(path).components() {
        match c {
            std::path::Component::ParentDir => {
                out.pop();
            }
            std::path::Component::CurDir => {}
            other => out.push(other),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn special_files_and_large_files_are_refused() {
        assert!(matches!(bounded(Path::new("/dev/zero"), MAX_FILE_BYTES), Err(Refused::NotAFile("a device"))));
        assert!(matches!(bounded(Path::new("src"), MAX_FILE_BYTES), Err(Refused::NotAFile("a directory"))));
        assert!(matches!(bounded(Path::new("Cargo.toml"), 10), Err(Refused::TooLarge(10))));
        assert!(bounded(Path::new("Cargo.toml"), MAX_FILE_BYTES).is_ok_and(|b| b.starts_with(b"[package]")));
    }

    #[test]
    fn confinement_follows_dot_dot_and_absolute_paths() {
        let root = Path::new("tests");
        assert!(confined(Path::new("tests/fail/../rewrite"), root));
        assert!(!confined(Path::new("tests/../Cargo.toml"), root));
        assert!(!confined(Path::new("/proc/self/environ"), root));
        assert!(!confined(Path::new("tests/no/such/../../../../outside.txt"), root));
    }
}
