//! Reading the files a user's input names, bounded: only regular files, never more than a
//! limit, and (for files a shader names) only inside the project root.
//!
//! effectc reads pull requests nobody has reviewed: a stage or `#include` of `/dev/zero`
//! would grow without end, a FIFO would block, and `#include "/proc/self/environ"` would
//! print the CI job's secrets in a diagnostic's snippet. Every stage and included file goes
//! through [`bounded`]; included files also through [`confined`], which admits the project
//! root and the directories its `effectc.toml` makes readable (`readable = ["../shared"]`;
//! never `/proc`, `/etc` and the like).

use std::io::Read;
use std::path::{Path, PathBuf};

/// Largest file read that is no stage (a manifest, `effectc.toml`, a look into a file to
/// tell its stage): far above any real shader (the largest generated stages met are
/// ~2 MB), far below what would exhaust memory. Stages and included files have the run's
/// `[limits] file-bytes` ([`crate::limits::Limits`], the same by default).
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
            Refused::TooLarge(limit) if limit % (1 << 20) == 0 => {
                write!(f, "it is larger than effectc's limit of {} MiB per file (`[limits] file-bytes`)", limit >> 20)
            }
            Refused::TooLarge(limit) => write!(f, "it is larger than effectc's limit of {limit} bytes per file (`[limits] file-bytes`)"),
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

/// The note of a refusal to read outside `root` (E0106): which directories, why, and that
/// `what` (the stage, the manifest) is under review.
pub fn outside_root_note(root: &Root, what: &str) -> String {
    let also = if root.readable.is_empty() {
        String::new()
    } else {
        let dirs: Vec<String> = root.readable.iter().map(|d| format!("`{}`", d.display())).collect();
        format!(" and in {}, which its `effectc.toml` makes readable", dirs.join(", "))
    };
    format!(
        "effectc reads only files inside `{}` (the nearest directory with an `effectc.toml` or `.git`, else the {what}'s own){also}: a {what} under review must not read the machine's files; `readable = [\"dir\"]` in that `effectc.toml` allows a directory outside it",
        root.dir.display()
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

/// Where the files a shader or manifest names may lie: its project root, and the
/// directories outside it that the root's `effectc.toml` makes readable.
#[derive(Debug, Clone)]
pub struct Root {
    /// The nearest directory above the file holding an `effectc.toml` or a `.git`, else
    /// the file's own directory.
    pub dir: PathBuf,
    /// `readable = [...]` of `dir`'s `effectc.toml`, resolved (each one passed
    /// [`readable_dir`]; an entry that does not is left out, and `effectc.toml`'s own
    /// check reports it).
    pub readable: Vec<PathBuf>,
}

/// The [`Root`] of a file a user named.
pub fn project_root(file: &Path) -> Root {
    let file = std::fs::canonicalize(file).unwrap_or_else(|_| file.to_path_buf());
    let own = file.parent().map(Path::to_path_buf).unwrap_or_else(|| PathBuf::from("."));
    let dir = own.ancestors().find(|d| d.join(CONFIG).is_file() || d.join(".git").exists()).map(Path::to_path_buf).unwrap_or(own);
    let readable = readable_of(&dir.join(CONFIG));
    Root { dir, readable }
}

/// The settings file whose directory is a project root (`config` reads the rest of it).
const CONFIG: &str = "effectc.toml";

/// The `readable` directories of the settings file at `config`, those that resolve.
fn readable_of(config: &Path) -> Vec<PathBuf> {
    #[derive(serde::Deserialize)]
    struct Readable {
        #[serde(default)]
        readable: Vec<String>,
    }
    let Ok(bytes) = bounded(config, MAX_FILE_BYTES) else { return Vec::new() };
    let Ok(r) = toml::from_str::<Readable>(&String::from_utf8_lossy(&bytes)) else { return Vec::new() };
    let base = config.parent().unwrap_or(Path::new("."));
    r.readable.iter().filter_map(|entry| readable_dir(base, entry).ok()).collect()
}

/// Directories never made readable, nor any directory holding one of them: the machine's
/// processes, devices and settings, where the job's secrets live.
const NEVER_READABLE: [&str; 7] = ["/proc", "/sys", "/dev", "/etc", "/run", "/root", "/var/run"];

/// `entry` of `readable = [...]` (relative to `base`, the settings file's directory)
/// resolved to the directory it names; why not, when it names no directory or one that
/// may never be read.
pub fn readable_dir(base: &Path, entry: &str) -> Result<PathBuf, String> {
    let dir = std::fs::canonicalize(base.join(entry)).map_err(|e| format!("`{entry}` cannot be resolved: {e}"))?;
    if !dir.is_dir() {
        return Err(format!("`{entry}` is not a directory"));
    }
    let home = std::env::var_os("HOME").map(PathBuf::from);
    let system = NEVER_READABLE.iter().map(PathBuf::from).chain(home).find(|s| s.starts_with(&dir) || dir.starts_with(s));
    match system {
        Some(s) => Err(format!("`{entry}` ({}) would make `{}` readable, which holds the machine's own files", dir.display(), s.display())),
        None => Ok(dir),
    }
}

/// `target` resolved (symlinks, `..`) lies inside `root`'s directory or one it makes
/// readable: where a file a shader names may be. A target that does not exist is judged by
/// its path as written, made absolute.
pub fn confined(target: &Path, root: &Root) -> bool {
    let resolved = std::fs::canonicalize(target).unwrap_or_else(|_| lexically_absolute(target));
    let dir = std::fs::canonicalize(&root.dir).unwrap_or_else(|_| lexically_absolute(&root.dir));
    std::iter::once(&dir).chain(&root.readable).any(|d| resolved.starts_with(d))
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
        let root = Root { dir: PathBuf::from("tests"), readable: Vec::new() };
        assert!(confined(Path::new("tests/fail/../rewrite"), &root));
        assert!(!confined(Path::new("tests/../Cargo.toml"), &root));
        assert!(!confined(Path::new("/proc/self/environ"), &root));
        assert!(!confined(Path::new("tests/no/such/../../../../outside.txt"), &root));
        let also = Root { readable: vec![std::fs::canonicalize("src").unwrap()], ..root };
        assert!(confined(Path::new("tests/../src/lib.rs"), &also));
        assert!(!confined(Path::new("tests/../Cargo.toml"), &also));
    }

    #[test]
    fn system_directories_are_never_readable() {
        assert!(readable_dir(Path::new("."), "src").is_ok());
        assert!(readable_dir(Path::new("."), "Cargo.toml").unwrap_err().contains("not a directory"));
        for dir in ["/", "/proc/self", "/etc", "/dev", "../../../../../../../../.."] {
            assert!(readable_dir(Path::new("."), dir).is_err(), "{dir}");
        }
    }
}
