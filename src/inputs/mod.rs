//! Turns command-line inputs into programs: manifests, directories, loose stage files.
//!
//! - a manifest (`*.toml`) is one program;
//! - a directory contributes every `effect.toml` below it, plus stage files no manifest
//!   there names, grouped by directory and file stem (`sun.vert` + `sun.frag`);
//! - stage files named on the command line form one program together; when a stage
//!   repeats, its files are shader objects linked into that stage if at most one of them
//!   defines `main`, else the files are grouped by stem.
//!
//! The repository's [`Selection`] (`effectc.toml`) leaves out paths its globs exclude and
//! names the stage of extensions effectc does not know.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use crate::config::Selection;
use crate::diag::{Code, Diagnostic};
use crate::stage::StageKind;

/// One program to check.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ProgramInput {
    Manifest(PathBuf),
    Stages { name: String, files: Vec<(PathBuf, StageKind)> },
}

impl ProgramInput {
    pub fn display_name(&self) -> String {
        match self {
            ProgramInput::Manifest(p) => p.display().to_string(),
            ProgramInput::Stages { name, .. } => name.clone(),
        }
    }
}

/// The stage of a file from its extension or the `--stage` override.
pub fn stage_of(path: &Path, forced: Option<StageKind>) -> Option<StageKind> {
    forced.or_else(|| path.extension().and_then(|e| e.to_str()).and_then(StageKind::from_extension))
}

fn is_manifest(path: &Path) -> bool {
    path.extension().is_some_and(|e| e == "toml")
}

/// Expands inputs into programs. Problems (missing paths, unknown extensions) come back as
/// diagnostics; the remaining inputs still produce programs.
pub fn collect(inputs: &[PathBuf], forced: Option<StageKind>, selection: &Selection) -> (Vec<ProgramInput>, Vec<Diagnostic>) {
    let mut programs = Vec::new();
    let mut diags = Vec::new();
    let mut loose: Vec<(PathBuf, StageKind)> = Vec::new();
    for input in inputs {
        let meta = match std::fs::metadata(input) {
            Ok(m) => m,
            Err(e) => {
                diags.push(Diagnostic::new(Code::InputIo, format!("cannot read `{}`: {e}", input.display())));
                continue;
            }
        };
        let selected = if meta.is_dir() { selection.enters(input) } else { selection.admits(input) };
        if !selected {
            continue;
        }
        if meta.is_dir() {
            let (p, d) = collect_dir(input, selection);
            programs.extend(p);
            diags.extend(d);
        } else if is_manifest(input) {
            programs.push(ProgramInput::Manifest(input.clone()));
        } else {
            match stage_of(input, forced).or_else(|| selection.stage_of(input)) {
                Some(kind) => loose.push((input.clone(), kind)),
                None => diags.push(
                    Diagnostic::new(Code::UnknownStage, format!("cannot tell the stage of `{}` from its extension", input.display()))
                        .with_help("name it .vert/.vs/.vsh, .frag/.fs/.fsh, .geom/.gs, or pass --stage vertex|fragment|geometry|…"),
                ),
            }
        }
    }
    if !loose.is_empty() {
        let kinds: BTreeSet<StageKind> = loose.iter().map(|(_, k)| *k).collect();
        if kinds.len() == loose.len() || units_of_one_program(&loose) {
            programs.push(ProgramInput::Stages { name: program_name(&loose), files: loose });
        } else {
            programs.extend(group_by_stem(loose));
        }
    }
    (programs, diags)
}

/// Stage files named together where a stage repeats are one program when, for every
/// repeated stage, at most one of its files defines `main`: GL links several shader objects
/// into one stage (`glAttachShader` per file), and a stage has exactly one `main`. Several
/// files of one stage that each define `main` are separate programs (grouped by stem).
fn units_of_one_program(files: &[(PathBuf, StageKind)]) -> bool {
    let mut mains: BTreeMap<StageKind, usize> = BTreeMap::new();
    for (path, kind) in files {
        let text =
            crate::read::bounded(path, crate::read::MAX_FILE_BYTES).map(|b| String::from_utf8_lossy(&b).into_owned()).unwrap_or_default();
        *mains.entry(*kind).or_default() += usize::from(defines_main(&text));
    }
    mains.values().all(|n| *n <= 1)
}

/// The text defines `void main(`, outside comments.
fn defines_main(text: &str) -> bool {
    let code = without_comments(text);
    let mut rest = code.as_str();
    while let Some(i) = rest.find("main") {
        let before = rest[..i].trim_end();
        let after = rest[i + 4..].trim_start();
        let word_start = rest[..i].chars().next_back().is_none_or(|c| !(c.is_alphanumeric() || c == '_'));
        if word_start && before.ends_with("void") && after.starts_with('(') {
            return true;
        }
        rest = &rest[i + 4..];
    }
    false
}

/// `text` with its `//` and `/* */` comments left out.
fn without_comments(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    loop {
        let (line, block) = (rest.find("//"), rest.find("/*"));
        match (line, block) {
            (Some(l), b) if b.is_none_or(|b| l < b) => {
                out.push_str(&rest[..l]);
                rest = rest[l..].find('\n').map_or("", |e| &rest[l + e..]);
            }
            (_, Some(b)) => {
                out.push_str(&rest[..b]);
                out.push(' ');
                rest = rest[b + 2..].find("*/").map_or("", |e| &rest[b + 2 + e + 2..]);
            }
            _ => {
                out.push_str(rest);
                return out;
            }
        }
    }
}

fn program_name(files: &[(PathBuf, StageKind)]) -> String {
    let first = &files[0].0;
    let stem = first.file_stem().map(|s| s.to_string_lossy().to_string()).unwrap_or_default();
    match first.parent().filter(|p| !p.as_os_str().is_empty()) {
        Some(dir) => format!("{}/{stem}", dir.display()),
        None => stem,
    }
}

fn group_by_stem(files: Vec<(PathBuf, StageKind)>) -> Vec<ProgramInput> {
    let mut groups: BTreeMap<(PathBuf, String), Vec<(PathBuf, StageKind)>> = BTreeMap::new();
    for (path, kind) in files {
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        let stem = path.file_stem().map(|s| s.to_string_lossy().to_string()).unwrap_or_default();
        groups.entry((dir, stem)).or_default().push((path, kind));
    }
    groups
        .into_values()
        .map(|mut files| {
            files.sort_by_key(|(_, k)| *k);
            ProgramInput::Stages { name: program_name(&files), files }
        })
        .collect()
}

fn collect_dir(dir: &Path, selection: &Selection) -> (Vec<ProgramInput>, Vec<Diagnostic>) {
    let mut manifests = Vec::new();
    let mut stage_files = Vec::new();
    let mut diags = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let entries = match std::fs::read_dir(&d) {
            Ok(e) => e,
            Err(e) => {
                diags.push(Diagnostic::new(Code::InputIo, format!("cannot read directory `{}`: {e}", d.display())));
                continue;
            }
        };
        let mut entries: Vec<PathBuf> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
        entries.sort();
        for p in entries {
            if p.is_dir() {
                if selection.enters(&p) {
                    stack.push(p);
                }
                continue;
            }
            if !selection.admits(&p) {
                continue;
            }
            if p.file_name().is_some_and(|n| n == "effect.toml") {
                manifests.push(p);
            } else if let Some(kind) = stage_of(&p, None).or_else(|| selection.stage_of(&p)) {
                stage_files.push((p, kind));
            }
        }
    }
    manifests.sort();
    // Stage files in a directory that has a manifest belong to it.
    let manifest_dirs: BTreeSet<PathBuf> = manifests.iter().filter_map(|m| m.parent().map(Path::to_path_buf)).collect();
    stage_files.retain(|(p, _)| !p.parent().is_some_and(|d| manifest_dirs.contains(d)));
    let mut programs: Vec<ProgramInput> = manifests.into_iter().map(ProgramInput::Manifest).collect();
    programs.extend(group_by_stem(stage_files));
    (programs, diags)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn named_stage_files_form_one_program() {
        let dir = std::env::temp_dir().join(format!("effectc-inputs-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let v = dir.join("a.vert");
        let f = dir.join("b.frag");
        std::fs::write(&v, "void main(){}").unwrap();
        std::fs::write(&f, "void main(){}").unwrap();
        let all = Selection::default();
        let (progs, diags) = collect(&[v.clone(), f.clone()], None, &all);
        assert!(diags.is_empty());
        assert_eq!(progs.len(), 1);
        let (progs, _) = collect(std::slice::from_ref(&dir), None, &all);
        assert_eq!(progs.len(), 2, "directory groups by stem: a and b");
        let (_, diags) = collect(&[dir.join("missing.frag")], None, &all);
        assert_eq!(diags[0].code, Code::InputIo);
        let (_, diags) = collect(&[dir.join("a.vert").with_extension("txt")], None, &all);
        assert_eq!(diags.len(), 1);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
