//! `--watch`: run a command again whenever a file it read changes.
//!
//! A round reports which files it read (stage files, included files, manifests, textures,
//! meshes, the settings file). The watcher (`notify`) follows the directory of each of
//! them, because editors often save by writing a new file and renaming it over the old
//! one, and every input directory below, so a new stage file or manifest is seen too.
//! Changes are debounced: a burst of events (a save, a `git checkout`) makes one round,
//! once the files have been quiet for [`DEBOUNCE`].

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::sync::mpsc::{channel, RecvTimeoutError};
use std::time::Duration;

use notify::{EventKind, RecursiveMode, Watcher};

use crate::diag::paths::absolute;

/// How long the files must be quiet before a round starts.
pub const DEBOUNCE: Duration = Duration::from_millis(200);

/// What the screen is cleared with between rounds on a terminal.
pub const CLEAR: &str = "\x1b[2J\x1b[H";

/// Runs `round(None)`, then `round(Some(changed))` after every change to a file the last
/// round read or below an input directory, until the process is stopped. A round returns
/// the files it read. Only a watcher that cannot be set up ends the loop (an error).
pub fn run(inputs: &[PathBuf], clear: bool, mut round: impl FnMut(Option<&[PathBuf]>) -> Vec<PathBuf>) -> Result<(), String> {
    let (tx, rx) = channel();
    let mut watcher = notify::recommended_watcher(move |event: notify::Result<notify::Event>| {
        if let Ok(e) = event {
            let _ = tx.send(e);
        }
    })
    .map_err(|e| format!("cannot watch files: {e}"))?;
    let roots: Vec<PathBuf> = inputs.iter().map(|p| absolute(p)).filter(|p| p.is_dir()).collect();
    for r in &roots {
        watcher.watch(r, RecursiveMode::Recursive).map_err(|e| format!("cannot watch `{}`: {e}", r.display()))?;
    }
    // The files named on the command line are watched whatever a round read: one deleted
    // and written again (a `git checkout`, an editor's save) must start a round.
    let named: Vec<PathBuf> = inputs.iter().map(|p| absolute(p)).filter(|p| !p.is_dir()).collect();
    let with_named = |read: Vec<PathBuf>| -> BTreeSet<PathBuf> { read.iter().map(|p| absolute(p)).chain(named.iter().cloned()).collect() };
    let mut read: BTreeSet<PathBuf> = with_named(round(None));
    let mut watched: BTreeSet<PathBuf> = BTreeSet::new();
    loop {
        for dir in read.iter().filter_map(|p| p.parent()) {
            if !roots.iter().any(|r| dir.starts_with(r)) && dir.is_dir() && watched.insert(dir.to_path_buf()) {
                // A directory that cannot be watched (removed meanwhile) is tried again
                // after the next round.
                if watcher.watch(dir, RecursiveMode::NonRecursive).is_err() {
                    watched.remove(dir);
                }
            }
        }
        let mut changed = BTreeSet::new();
        let Ok(first) = rx.recv() else { return Ok(()) };
        collect(&first, &read, &roots, &mut changed);
        loop {
            match rx.recv_timeout(DEBOUNCE) {
                Ok(e) => collect(&e, &read, &roots, &mut changed),
                Err(RecvTimeoutError::Timeout) => break,
                Err(RecvTimeoutError::Disconnected) => return Ok(()),
            }
        }
        if changed.is_empty() {
            continue;
        }
        if clear {
            print!("{CLEAR}");
        }
        let changed: Vec<PathBuf> = changed.into_iter().collect();
        read = with_named(round(Some(&changed)));
    }
}

/// Adds the paths of `event` that matter: a file the round read, or below an input
/// directory a stage file, a manifest or a settings file.
fn collect(event: &notify::Event, read: &BTreeSet<PathBuf>, roots: &[PathBuf], changed: &mut BTreeSet<PathBuf>) {
    if !matches!(event.kind, EventKind::Create(_) | EventKind::Modify(_) | EventKind::Remove(_) | EventKind::Any) {
        return;
    }
    for p in &event.paths {
        let p = absolute(p);
        let below_input = roots.iter().any(|r| p.starts_with(r)) && is_program_file(&p);
        if read.contains(&p) || below_input {
            changed.insert(p);
        }
    }
}

/// A file that can add or change a program: a stage file (by any name the directory walk
/// takes, `.glsl` included), a manifest, a settings file.
fn is_program_file(p: &Path) -> bool {
    let ext = p.extension().and_then(|e| e.to_str()).unwrap_or("");
    ext == "toml" || ext == "glsl" || crate::inputs::stage_of(p, None).is_some()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn changes_to_read_files_and_new_stage_files_matter() {
        let root = absolute(Path::new("shaders"));
        let read: BTreeSet<PathBuf> = [absolute(Path::new("lib/common.glsl"))].into_iter().collect();
        let event = |kind, path: &str| notify::Event::new(kind).add_path(absolute(Path::new(path)));
        let mut changed = BTreeSet::new();
        let modify = EventKind::Modify(notify::event::ModifyKind::Any);
        collect(&event(modify, "lib/common.glsl"), &read, std::slice::from_ref(&root), &mut changed);
        collect(
            &event(EventKind::Create(notify::event::CreateKind::File), "shaders/new.frag"),
            &read,
            std::slice::from_ref(&root),
            &mut changed,
        );
        collect(&event(modify, "shaders/out/sun.png"), &read, std::slice::from_ref(&root), &mut changed);
        collect(
            &event(EventKind::Access(notify::event::AccessKind::Any), "lib/common.glsl"),
            &read,
            std::slice::from_ref(&root),
            &mut changed,
        );
        let names: Vec<String> = changed.iter().map(|p| p.file_name().unwrap().to_string_lossy().into_owned()).collect();
        assert_eq!(names, ["common.glsl", "new.frag"]);
    }
}
