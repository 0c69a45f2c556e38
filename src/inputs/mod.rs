//! Turns command-line inputs into programs: manifests, directories, loose stage files.
//!
//! - a manifest (`*.toml`) is one program;
//! - a directory contributes every `effect.toml` below it, plus stage files no manifest
//!   there names, grouped by directory and program stem (`sun.vert` + `sun.frag`,
//!   `sun.vert.glsl` + `sun_fs.glsl`); a `.glsl` file the name does not place is placed by
//!   its text ([`stage_names`], note N0003 with the evidence), or is one program of both
//!   stages when it holds them behind `#if defined(VERTEX)` … `#elif defined(FRAGMENT)`
//!   (the emulator packs' format: read twice, each macro defined in turn); a folder with one vertex
//!   stage pairs it with each fragment stage that has no vertex stage of its own (note
//!   N0001); a stage left alone gets note N0002 (no link rule ran); a folder with no program
//!   at all is warning W0006;
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
use crate::stage::{Define, StageKind};

pub mod declared;
pub mod host_code;
pub mod stage_names;

/// One program to check.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ProgramInput {
    Manifest(PathBuf),
    /// Stage files; `defines` are macros defined for the stages of a kind (the single-file
    /// two-stage format: `VERTEX` for the vertex stage, `FRAGMENT` for the fragment stage);
    /// `formed` says why these files make one program.
    Stages {
        name: String,
        files: Vec<(PathBuf, StageKind)>,
        defines: Vec<(StageKind, Vec<Define>)>,
        formed: Formed,
    },
}

/// Why stage files were grouped into one program.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Formed {
    /// Named together on the command line.
    Named,
    /// One folder and one stem (`sun.vert` + `sun.frag`), or a file alone.
    Stem,
    /// A fragment stage with the one vertex stage of its folder (note N0001).
    FolderVertex,
    /// The one program of a folder with the folder's one geometry stage (note N0001).
    FolderGeometry,
    /// One file holding both stages behind `VERTEX`/`FRAGMENT` macros.
    TwoStages,
    /// A `[[program]]` of `effectc.toml`.
    Declared,
    /// Named together by the host code (note N0004, [`host_code`]).
    HostCode,
}

impl Formed {
    /// In words, for `--verbose` and JSON.
    pub fn describe(self, files: usize) -> &'static str {
        match self {
            _ if files == 1 => "alone: no other stage has its stem, and nothing pairs it",
            Formed::Named => "named together on the command line",
            Formed::Stem => "one folder and one stem",
            Formed::FolderVertex => "a fragment stage with the one vertex stage of its folder",
            Formed::FolderGeometry => "the one program of its folder with the folder's one geometry stage",
            Formed::TwoStages => "one file holding both stages, read with each stage's macro defined",
            Formed::Declared => "declared by a [[program]] in effectc.toml",
            Formed::HostCode => "named together by the host code (one call or initializer, or consecutive statements)",
        }
    }
}

impl ProgramInput {
    pub fn display_name(&self) -> String {
        match self {
            ProgramInput::Manifest(p) => p.display().to_string(),
            ProgramInput::Stages { name, .. } => name.clone(),
        }
    }
}

/// The stage of a file from its name (`.vert`, `x.vert.glsl`, `x_vs.glsl`, …) or the
/// `--stage` override.
pub fn stage_of(path: &Path, forced: Option<StageKind>) -> Option<StageKind> {
    forced.or_else(|| stage_names::from_name(path).map(|(k, _)| k))
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
    let declared = declared::resolve(selection);
    diags.extend(declared.diagnostics.iter().cloned());
    let mut emitted = vec![false; declared.programs.len()];
    // The declared programs `held` says an input holds, once each.
    let mut emit = |programs: &mut Vec<ProgramInput>, held: &dyn Fn(&[PathBuf]) -> bool| {
        for (i, (p, paths)) in declared.programs.iter().enumerate() {
            if !emitted[i] && held(paths) {
                emitted[i] = true;
                programs.push(p.clone());
            }
        }
    };
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
            let dir = crate::diag::paths::absolute(input);
            emit(&mut programs, &|paths| paths.iter().all(|f| f.starts_with(&dir)));
            let (p, d) = collect_dir(input, selection, &declared.files);
            programs.extend(p);
            diags.extend(d);
        } else if is_manifest(input) {
            programs.push(ProgramInput::Manifest(input.clone()));
        } else {
            // The text's two stages win over a name that seems to give one (`blur-vert.glsl`
            // is often a vertical blur); `--stage` wins over both.
            let text = glsl_text(input);
            if let Some((program, note)) = text.as_deref().filter(|_| forced.is_none()).and_then(|t| two_stage_file(input, t)) {
                diags.push(note);
                programs.push(program);
                continue;
            }
            match stage_of(input, forced).or_else(|| selection.stage_of(input)) {
                Some(kind) => loose.push((input.clone(), kind)),
                None => match text.as_deref().and_then(|t| stage_from_text(input, t)) {
                    Some((kind, note)) => {
                        diags.push(note);
                        loose.push((input.clone(), kind));
                    }
                    None => diags.push(
                        Diagnostic::new(Code::UnknownStage, format!("cannot tell the stage of `{}` from its name or its text", input.display()))
                            .with_help("name it .vert/.vs/.vsh, .frag/.fs/.fsh, .geom/.gs (or x.vert.glsl, x_vs.glsl), or pass --stage vertex|fragment|geometry|…"),
                    ),
                },
            }
        }
    }
    // A named file a `[[program]]` uses is checked in the programs declared with it.
    let (in_declared, rest): (Vec<_>, Vec<_>) =
        loose.into_iter().partition(|(p, _)| declared.files.contains(&crate::diag::paths::absolute(p)));
    for (p, _) in &in_declared {
        let file = crate::diag::paths::absolute(p);
        emit(&mut programs, &|paths| paths.contains(&file));
    }
    let loose = rest;
    let loose_named = !loose.is_empty() || !in_declared.is_empty();
    if !loose.is_empty() {
        let kinds: BTreeSet<StageKind> = loose.iter().map(|(_, k)| *k).collect();
        if kinds.len() == loose.len() || units_of_one_program(&loose) {
            programs.push(ProgramInput::Stages { name: program_name(&loose), files: loose, defines: Vec::new(), formed: Formed::Named });
        } else {
            programs.extend(group_by_stem(loose));
        }
    }
    if programs.is_empty() && !loose_named {
        for dir in inputs.iter().filter(|p| p.is_dir()) {
            diags.push(
                Diagnostic::new(Code::NoProgramFound, format!("no program found in `{}`: nothing was checked", dir.display()))
                    .with_note("effectc looks for `effect.toml` manifests and stage files: `.vert`/`.frag`/… , `x.vert.glsl`, `x_vs.glsl`, `vertex.glsl`, or `.glsl` files with a `main` whose text shows the stage")
                    .with_help("name the stage files, or list them in `effectc.toml` (`[stages] \"*.shader\" = \"fragment\"`)"),
            );
        }
    }
    for p in &programs {
        if let ProgramInput::Stages { files, .. } = p {
            if let [(path, kind)] = files.as_slice() {
                // A compute or ray-tracing stage has no stage interface to check.
                if *kind != StageKind::Compute && !kind.vulkan_only() {
                    diags.push(
                        Diagnostic::new(Code::StageAlone, format!("`{}` is checked alone: no link rule ran", path.display()))
                            .with_note(format!("a {} stage on its own is not a program; its interface with the other stages was not checked", kind.title()))
                            .with_help("name its stages together (`effectc check a.vert b.frag`), give them one stem (`a.vert` + `a.frag`), or keep one vertex stage in its folder"),
                    );
                }
            }
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
        let text = crate::read::bounded_text_lossy(path).unwrap_or_default();
        *mains.entry(*kind).or_default() += usize::from(defines_main(&text));
    }
    mains.values().all(|n| *n <= 1)
}

/// The text defines `void main(`, outside comments.
fn defines_main(text: &str) -> bool {
    code_defines_main(&without_comments(text))
}

/// `code` (comments already out) defines `void main(`.
pub(crate) fn code_defines_main(code: &str) -> bool {
    let mut rest = code;
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
pub(crate) fn without_comments(text: &str) -> String {
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

pub(crate) fn program_name(files: &[(PathBuf, StageKind)]) -> String {
    let first = &files[0].0;
    let stem = first.file_stem().map(|s| s.to_string_lossy().to_string()).unwrap_or_default();
    match first.parent().filter(|p| !p.as_os_str().is_empty()) {
        Some(dir) => format!("{}/{stem}", dir.display()),
        None => stem,
    }
}

/// Stage files grouped by folder and stem. A compute stage never joins graphics stages of
/// its stem (`cloth.comp` beside `cloth.vert` is a program of its own), and a file whose
/// stage the text told keeps the stem before its inner extension (`tess.cont.glsl` is of
/// program `tess`).
fn group_by_stem(files: Vec<(PathBuf, StageKind)>) -> Vec<ProgramInput> {
    let mut groups: BTreeMap<(PathBuf, String, bool), Vec<(PathBuf, StageKind)>> = BTreeMap::new();
    for (path, kind) in files {
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        let stem = stage_names::from_name(&path).map(|(_, stem)| stem).unwrap_or_else(|| {
            let stem = path.file_stem().map(|s| s.to_string_lossy().to_string()).unwrap_or_default();
            match stem.split_once('.') {
                Some((outer, _)) if !outer.is_empty() => outer.to_string(),
                _ => stem,
            }
        });
        groups.entry((dir, stem, kind == StageKind::Compute)).or_default().push((path, kind));
    }
    groups
        .into_values()
        .map(|mut files| {
            files.sort_by_key(|(_, k)| *k);
            ProgramInput::Stages { name: program_name(&files), files, defines: Vec::new(), formed: Formed::Stem }
        })
        .collect()
}

/// The programs below `dir`; files in `declared` (used by a `[[program]]`) form no other.
fn collect_dir(dir: &Path, selection: &Selection, declared: &BTreeSet<PathBuf>) -> (Vec<ProgramInput>, Vec<Diagnostic>) {
    let mut manifests = Vec::new();
    let mut stage_files = Vec::new();
    let mut two_stage = Vec::new();
    let mut hosts = Vec::new();
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
                continue;
            }
            let text = glsl_text(&p);
            if let Some((program, note)) = text.as_deref().and_then(|t| two_stage_file(&p, t)) {
                diags.push(note);
                two_stage.push(program);
            } else if let Some(kind) = stage_of(&p, None).or_else(|| selection.stage_of(&p)) {
                stage_files.push((p, kind));
            } else if let Some((kind, note)) = text.as_deref().and_then(|t| stage_from_text(&p, t)) {
                diags.push(note);
                stage_files.push((p, kind));
            } else if host_code::is_host_file(&p) {
                hosts.push(p);
            }
        }
    }
    manifests.sort();
    // Stage files in a directory that has a manifest belong to it.
    let manifest_dirs: BTreeSet<PathBuf> = manifests.iter().filter_map(|m| m.parent().map(Path::to_path_buf)).collect();
    let in_manifest_dir = |p: &Path| p.parent().is_some_and(|d| manifest_dirs.contains(d));
    let is_declared = |p: &Path| declared.contains(&crate::diag::paths::absolute(p));
    stage_files.retain(|(p, _)| !in_manifest_dir(p) && !is_declared(p));
    two_stage.retain(|p| !matches!(p, ProgramInput::Stages { files, .. } if is_declared(&files[0].0)));
    two_stage.retain(|p| !matches!(p, ProgramInput::Stages { files, .. } if in_manifest_dir(&files[0].0)));
    let mut programs: Vec<ProgramInput> = manifests.into_iter().map(ProgramInput::Manifest).collect();
    let mut groups = group_by_stem(stage_files);
    diags.extend(host_code::pair_as_named(&mut groups, &hosts));
    diags.extend(pair_with_the_folders_vertex_stage(&mut groups));
    diags.extend(join_the_folders_geometry_stage(&mut groups));
    programs.extend(groups);
    programs.extend(two_stage);
    (programs, diags)
}

/// A `.glsl` file (whose `text` is given) holding a vertex and a fragment stage behind the macros its host code
/// defines ([`stage_names::two_stage_macros`]): one program of the file read twice, each
/// time with one stage's macro defined, and the note (N0003) saying so.
fn two_stage_file(path: &Path, text: &str) -> Option<(ProgramInput, Diagnostic)> {
    let (vertex, fragment) = stage_names::two_stage_macros(&without_comments(text))?;
    let name = path.file_stem().map_or_else(|| path.display().to_string(), |s| s.to_string_lossy().into_owned());
    let defined = |m: &str| vec![(m.to_string(), "1".to_string())];
    let program = ProgramInput::Stages {
        name,
        files: vec![(path.to_path_buf(), StageKind::Vertex), (path.to_path_buf(), StageKind::Fragment)],
        defines: vec![(StageKind::Vertex, defined(vertex)), (StageKind::Fragment, defined(fragment))],
        formed: Formed::TwoStages,
    };
    let note = Diagnostic::new(
        Code::StageFromText,
        format!("`{}` holds a vertex and a fragment stage behind `{vertex}` and `{fragment}`: it is read as both, with each macro defined in turn", path.display()),
    );
    Some((program, note))
}

/// The text of a `.glsl` file, read once for what its text tells ([`two_stage_file`],
/// [`stage_from_text`]); `None` for other files and unreadable ones.
fn glsl_text(path: &Path) -> Option<String> {
    if !path.extension().is_some_and(|e| e.eq_ignore_ascii_case("glsl")) {
        return None;
    }
    crate::read::bounded_text_lossy(path).ok()
}

/// The stage a `.glsl` file's text shows, with the note (N0003) naming the evidence.
fn stage_from_text(path: &Path, text: &str) -> Option<(StageKind, Diagnostic)> {
    let (kind, why) = stage_names::from_text(text)?;
    Some((kind, Diagnostic::new(Code::StageFromText, format!("`{}` is read as a {} stage: {why}", path.display(), kind.title()))))
}

/// In a folder with exactly one vertex stage, each program with a fragment stage and no
/// vertex stage gets that vertex stage (the common one-vertex-many-fragments layout, where
/// the host code links `PCN.vert` with `Diffuse.frag`, `Phong.frag`, …); the vertex stage
/// no longer stands alone. Where that makes one program in the folder and the folder's one
/// geometry stage stands alone, it joins that program too (`pass.vert`, `explode.geom`,
/// `shade.frag`). A note (N0001) names each pairing.
fn pair_with_the_folders_vertex_stage(groups: &mut Vec<ProgramInput>) -> Vec<Diagnostic> {
    let files_of = |p: &ProgramInput| match p {
        ProgramInput::Stages { files, .. } => files.clone(),
        ProgramInput::Manifest(_) => Vec::new(),
    };
    let dir_of = |path: &Path| path.parent().map(Path::to_path_buf).unwrap_or_default();
    let mut vertex_by_dir: BTreeMap<PathBuf, Vec<PathBuf>> = BTreeMap::new();
    for g in groups.iter() {
        for (path, kind) in files_of(g) {
            if kind == StageKind::Vertex {
                vertex_by_dir.entry(dir_of(&path)).or_default().push(path);
            }
        }
    }
    let mut lone_geometry: BTreeMap<PathBuf, Vec<PathBuf>> = BTreeMap::new();
    for g in groups.iter() {
        if let [(path, StageKind::Geometry)] = files_of(g).as_slice() {
            lone_geometry.entry(dir_of(path)).or_default().push(path.clone());
        }
    }
    let mut paired_in_dir: BTreeMap<PathBuf, usize> = BTreeMap::new();
    for g in groups.iter() {
        let files = files_of(g);
        let kinds: BTreeSet<StageKind> = files.iter().map(|(_, k)| *k).collect();
        if kinds.contains(&StageKind::Fragment) && !kinds.contains(&StageKind::Vertex) && !kinds.contains(&StageKind::Compute) {
            *paired_in_dir.entry(dir_of(&files[0].0)).or_default() += 1;
        }
    }
    let mut notes = Vec::new();
    let mut paired_vertex: BTreeSet<PathBuf> = BTreeSet::new();
    for g in groups.iter_mut() {
        let ProgramInput::Stages { files, formed, .. } = g else { continue };
        let kinds: BTreeSet<StageKind> = files.iter().map(|(_, k)| *k).collect();
        if !kinds.contains(&StageKind::Fragment) || kinds.contains(&StageKind::Vertex) || kinds.contains(&StageKind::Compute) {
            continue;
        }
        let dir = dir_of(&files[0].0);
        let Some([vertex]) = vertex_by_dir.get(&dir).map(Vec::as_slice) else { continue };
        let geometry = match lone_geometry.get(&dir).map(Vec::as_slice) {
            Some([geometry]) if paired_in_dir.get(&dir) == Some(&1) && !kinds.contains(&StageKind::Geometry) => Some(geometry),
            _ => None,
        };
        let message = match geometry {
            Some(geometry) => format!(
                "`{}` is paired with `{}` and `{}`, the one vertex and geometry stages of its folder",
                files[0].0.display(),
                vertex.display(),
                geometry.display()
            ),
            None => format!("`{}` is paired with `{}`, the one vertex stage of its folder", files[0].0.display(), vertex.display()),
        };
        notes.push(Diagnostic::new(Code::PairedInFolder, message));
        if let Some(geometry) = geometry {
            files.push((geometry.clone(), StageKind::Geometry));
            paired_vertex.insert(geometry.clone());
        }
        files.push((vertex.clone(), StageKind::Vertex));
        files.sort_by_key(|(_, k)| *k);
        *formed = Formed::FolderVertex;
        paired_vertex.insert(vertex.clone());
    }
    // A vertex (or geometry) stage now checked with its fragment stages is no program of its own.
    groups.retain(|g| !matches!(g, ProgramInput::Stages { files, .. } if files.len() == 1 && paired_vertex.contains(&files[0].0)));
    notes
}

/// A folder's one geometry stage that stands alone joins the folder's one program of a
/// vertex and a fragment stage without a geometry stage (`scene.vert` + `scene.frag` and
/// `multiview.geom`, as the host code links them): alone it is no program, and that program
/// is the only one it can belong to. With two such programs in the folder it stays alone
/// (N0002 says how to pair it). A note (N0001) names the joining.
fn join_the_folders_geometry_stage(groups: &mut Vec<ProgramInput>) -> Vec<Diagnostic> {
    let dir_of = |path: &Path| path.parent().map(Path::to_path_buf).unwrap_or_default();
    let mut lone: BTreeMap<PathBuf, Vec<PathBuf>> = BTreeMap::new();
    let mut joinable: BTreeMap<PathBuf, Vec<usize>> = BTreeMap::new();
    for (i, g) in groups.iter().enumerate() {
        let ProgramInput::Stages { files, .. } = g else { continue };
        let kinds: BTreeSet<StageKind> = files.iter().map(|(_, k)| *k).collect();
        let dirs: BTreeSet<PathBuf> = files.iter().map(|(p, _)| dir_of(p)).collect();
        let (Some(dir), 1) = (dirs.first().cloned(), dirs.len()) else { continue };
        if let [(path, StageKind::Geometry)] = files.as_slice() {
            lone.entry(dir).or_default().push(path.clone());
        } else if kinds == BTreeSet::from([StageKind::Vertex, StageKind::Fragment]) {
            joinable.entry(dir).or_default().push(i);
        }
    }
    let mut notes = Vec::new();
    let mut joined: BTreeSet<PathBuf> = BTreeSet::new();
    for (dir, geometry) in &lone {
        let ([geometry], Some([program])) = (geometry.as_slice(), joinable.get(dir).map(Vec::as_slice)) else { continue };
        let ProgramInput::Stages { files, formed, .. } = &mut groups[*program] else { continue };
        let names: Vec<String> = files.iter().map(|(p, _)| format!("`{}`", p.display())).collect();
        notes.push(Diagnostic::new(
            Code::PairedInFolder,
            format!("`{}` joins {}, the one program of its folder", geometry.display(), names.join(" and ")),
        ));
        files.push((geometry.clone(), StageKind::Geometry));
        files.sort_by_key(|(_, k)| *k);
        *formed = Formed::FolderGeometry;
        joined.insert(geometry.clone());
    }
    groups.retain(|g| !matches!(g, ProgramInput::Stages { files, .. } if files.len() == 1 && joined.contains(&files[0].0)));
    notes
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
        let (progs, diags) = collect(std::slice::from_ref(&dir), None, &all);
        assert_eq!(progs.len(), 1, "the folder's one vertex stage pairs with the lone fragment stage");
        assert_eq!(diags.iter().map(|d| d.code).collect::<Vec<_>>(), [Code::PairedInFolder]);
        std::fs::write(dir.join("c.vert"), "void main(){}").unwrap();
        let (progs, diags) = collect(std::slice::from_ref(&dir), None, &all);
        assert_eq!(progs.len(), 3, "two vertex stages: grouped by stem, a, b and c alone");
        assert_eq!(diags.iter().filter(|d| d.code == Code::StageAlone).count(), 3);
        std::fs::remove_file(dir.join("c.vert")).unwrap();
        let (_, diags) = collect(&[dir.join("missing.frag")], None, &all);
        assert_eq!(diags[0].code, Code::InputIo);
        let (_, diags) = collect(&[dir.join("a.vert").with_extension("txt")], None, &all);
        assert_eq!(diags.len(), 1);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
