//! The programs `effectc.toml` declares (`[[program]]`): each stage's patterns resolved
//! against the settings file's directory (a path, or a glob matched below it), and one
//! program formed per combination of the files matched — `vertex = "PCN.vert"` with
//! `fragment = ["Diffuse*.frag"]` is one program per fragment file, each with `PCN.vert`.
//! A pattern that matches nothing is warning W0006: a declared program that checks nothing
//! must not pass silently.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use globset::GlobSet;

use super::{Formed, ProgramInput};
use crate::config::{DeclaredProgram, Selection};
use crate::diag::paths::absolute;
use crate::diag::{Code, Diagnostic};
use crate::stage::StageKind;

/// The declared programs, resolved.
#[derive(Debug, Default)]
pub struct Declared {
    /// Each program with the absolute paths of its files (to tell which input holds it).
    pub programs: Vec<(ProgramInput, Vec<PathBuf>)>,
    /// Every file a declared program uses (absolute): the directory walk forms no other
    /// program of them.
    pub files: BTreeSet<PathBuf>,
    pub diagnostics: Vec<Diagnostic>,
}

/// Resolves `selection.programs`; empty when there are none.
pub fn resolve(selection: &Selection) -> Declared {
    let mut out = Declared::default();
    if selection.programs.is_empty() {
        return out;
    }
    let tree = files_below(&selection.root, selection);
    for p in &selection.programs {
        let mut stages: Vec<(StageKind, Vec<PathBuf>)> = Vec::new();
        for (kind, patterns) in &p.stages {
            let matched = matching(&selection.root, &tree, patterns);
            if matched.is_empty() {
                out.diagnostics.push(
                    Diagnostic::new(Code::NoProgramFound, format!("{}: `{kind} = {:?}` matches no file", title(p), patterns))
                        .with_note(format!("patterns are relative to `{}`", selection.root.display())),
                );
            }
            stages.push((*kind, matched));
        }
        if stages.iter().any(|(_, m)| m.is_empty()) {
            continue;
        }
        for combination in combinations(&stages) {
            let varying: Vec<String> = stages
                .iter()
                .zip(&combination)
                .filter(|((_, m), _)| m.len() > 1)
                .map(|(_, (path, _))| path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default())
                .collect();
            let name = match (&p.name, varying.is_empty()) {
                (Some(n), true) => n.clone(),
                (Some(n), false) => format!("{n}/{}", varying.join("+")),
                (None, _) => super::program_name(&combination),
            };
            let defines = combination.iter().map(|(_, k)| (*k, p.defines.clone())).filter(|(_, d)| !d.is_empty()).collect();
            let paths: Vec<PathBuf> = combination.iter().map(|(f, _)| absolute(f)).collect();
            out.files.extend(paths.iter().cloned());
            out.programs.push((ProgramInput::Stages { name, files: combination, defines, formed: Formed::Declared }, paths));
        }
    }
    out
}

/// `[[program]] N` (or its name), for messages.
fn title(p: &DeclaredProgram) -> String {
    match &p.name {
        Some(n) => format!("[[program]] `{n}` in effectc.toml"),
        None => format!("[[program]] {} in effectc.toml", p.number),
    }
}

/// Every file below `root` the walk may enter (relative paths), sorted.
fn files_below(root: &Path, selection: &Selection) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![root.to_path_buf()];
    while let Some(d) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&d) else { continue };
        for e in entries.flatten() {
            let p = e.path();
            if p.is_dir() {
                if selection.enters(&p) && !p.file_name().is_some_and(|n| n == ".git" || n == "target") {
                    stack.push(p);
                }
            } else if let Ok(relative) = p.strip_prefix(root) {
                out.push(relative.to_path_buf());
            }
        }
    }
    out.sort();
    out
}

/// The files `patterns` name (paths as written, or globs matched in `tree`), in order.
fn matching(root: &Path, tree: &[PathBuf], patterns: &[String]) -> Vec<PathBuf> {
    let mut out: Vec<PathBuf> = Vec::new();
    for pattern in patterns {
        let is_glob = pattern.contains(['*', '?', '[', '{']);
        if !is_glob {
            let path = root.join(pattern);
            if path.is_file() && !out.contains(&path) {
                out.push(path);
            }
            continue;
        }
        let Ok(glob) = crate::config::glob(pattern) else { continue };
        let set: GlobSet = match globset::GlobSetBuilder::new().add(glob).build() {
            Ok(s) => s,
            Err(_) => continue,
        };
        for relative in tree.iter().filter(|r| set.is_match(r)) {
            let path = root.join(relative);
            if !out.contains(&path) {
                out.push(path);
            }
        }
    }
    out
}

/// Every choice of one file per stage.
fn combinations(stages: &[(StageKind, Vec<PathBuf>)]) -> Vec<Vec<(PathBuf, StageKind)>> {
    let mut out: Vec<Vec<(PathBuf, StageKind)>> = vec![Vec::new()];
    for (kind, files) in stages {
        out = out.into_iter().flat_map(|prefix| files.iter().map(move |f| [prefix.clone(), vec![(f.clone(), *kind)]].concat())).collect();
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_program_per_combination_of_matched_files() {
        let stages = vec![
            (StageKind::Vertex, vec![PathBuf::from("PCN.vert")]),
            (StageKind::Fragment, vec![PathBuf::from("Diffuse.frag"), PathBuf::from("Phong.frag")]),
        ];
        let c = combinations(&stages);
        assert_eq!(c.len(), 2);
        assert_eq!(c[1], vec![(PathBuf::from("PCN.vert"), StageKind::Vertex), (PathBuf::from("Phong.frag"), StageKind::Fragment)]);
    }
}
