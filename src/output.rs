//! Files written by the commands: atomically (a temporary file and a rename), into
//! directories created as needed, never over one of the run's inputs.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use crate::check::Outcome;

/// Canonical paths of every file the run read.
pub fn input_paths(outcome: &Outcome, inputs: &[PathBuf]) -> BTreeSet<PathBuf> {
    let mut set: BTreeSet<PathBuf> =
        outcome.files.iter().filter_map(|(id, _)| std::fs::canonicalize(outcome.files.path(id)).ok()).collect();
    set.extend(inputs.iter().filter_map(|p| std::fs::canonicalize(p).ok()));
    set
}

/// Writes `bytes` to `path` through a temporary file in the same directory and a rename,
/// so readers never see a half-written file. Refuses to replace an input.
pub fn write_atomic(path: &Path, bytes: &[u8], inputs: &BTreeSet<PathBuf>) -> Result<(), String> {
    let dir = path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
    std::fs::create_dir_all(dir).map_err(|e| {
        // An `--out` naming a file (`--out effect.toml`): say what is in the way.
        let in_way = dir.ancestors().find(|a| a.is_file());
        match in_way {
            Some(file) => format!(
                "cannot write into `{}`: `{}` is a file, and the outputs go into a directory (`--out` names the directory)",
                dir.display(),
                file.display()
            ),
            None => format!("cannot create `{}`: {e}", dir.display()),
        }
    })?;
    if let Ok(canonical) = std::fs::canonicalize(path) {
        if inputs.contains(&canonical) {
            return Err(format!("refusing to write `{}`: it is one of the inputs", path.display()));
        }
    }
    clean_stale_temporaries(dir);
    let file_name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let tmp = dir.join(format!(".{file_name}.{}.tmp", std::process::id()));
    let result = std::fs::write(&tmp, bytes).and_then(|_| std::fs::rename(&tmp, path));
    if let Err(e) = result {
        let _ = std::fs::remove_file(&tmp);
        return Err(format!("cannot write `{}`: {e}", path.display()));
    }
    Ok(())
}

/// Removes, once per directory and run, the temporary files (`.<name>.<pid>.tmp`) a killed
/// run left there: those of a process that no longer exists.
fn clean_stale_temporaries(dir: &Path) {
    static CLEANED: std::sync::Mutex<BTreeSet<PathBuf>> = std::sync::Mutex::new(BTreeSet::new());
    let Ok(mut cleaned) = CLEANED.lock() else { return };
    if !cleaned.insert(dir.to_path_buf()) {
        return;
    }
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        let Some(pid) = stale_pid(&name) else { continue };
        if pid != std::process::id() && !Path::new(&format!("/proc/{pid}")).exists() {
            let _ = std::fs::remove_file(entry.path());
        }
    }
}

/// The process id in a temporary file's name (`.sun_0000.png.4242.tmp`).
fn stale_pid(name: &str) -> Option<u32> {
    let rest = name.strip_prefix('.')?.strip_suffix(".tmp")?;
    rest.rsplit_once('.')?.1.parse().ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn atomic_write_creates_directories_and_never_replaces_an_input() {
        let dir = std::env::temp_dir().join(format!("effectc-write-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let out = dir.join("a/b/out.wgsl");
        write_atomic(&out, b"first", &BTreeSet::new()).unwrap();
        write_atomic(&out, b"second", &BTreeSet::new()).unwrap();
        assert_eq!(std::fs::read(&out).unwrap(), b"second");
        let inputs: BTreeSet<PathBuf> = [std::fs::canonicalize(&out).unwrap()].into();
        let err = write_atomic(&out, b"third", &inputs).unwrap_err();
        assert!(err.contains("one of the inputs"), "{err}");
        assert_eq!(std::fs::read(&out).unwrap(), b"second");
        let leftovers: Vec<_> = std::fs::read_dir(out.parent().unwrap()).unwrap().collect();
        assert_eq!(leftovers.len(), 1, "no temporary files left behind");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn temporaries_of_dead_runs_are_cleaned() {
        let dir = std::env::temp_dir().join(format!("effectc-stale-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        // Process ids above the kernel's maximum (4194304) never run.
        let stale = dir.join(".frame_0000.png.4294967.tmp");
        let mine = dir.join(format!(".other.png.{}.tmp", std::process::id()));
        std::fs::write(&stale, b"half").unwrap();
        std::fs::write(&mine, b"mine").unwrap();
        assert_eq!(stale_pid(".frame_0000.png.4294967.tmp"), Some(4294967));
        assert_eq!(stale_pid("frame.png"), None);
        write_atomic(&dir.join("frame_0000.png"), b"png", &BTreeSet::new()).unwrap();
        assert!(!stale.exists(), "a dead run's temporary is removed");
        assert!(mine.exists(), "this run's own temporaries stay");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
