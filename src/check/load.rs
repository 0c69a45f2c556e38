//! Reading a program's files before it is analysed: its manifest, the effects its passes
//! reuse, its stage files with their `#include`s. Every file is registered in the run's
//! one [`Files`], in input order, so file ids (and the report) do not depend on how many
//! threads analyse the programs afterwards.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use crate::diag::{Code, Diagnostic, FileId, Files};
use crate::front::compat;
use crate::inputs::ProgramInput;
use crate::manifest::{self, Effect};
use crate::stage::{Define, StageKind};

/// A program whose files are read.
#[derive(Debug)]
pub struct Loaded {
    pub name: String,
    pub effect: Option<Effect>,
    pub body: Body,
    /// What reading found (missing files, manifest errors, manifest warnings).
    pub diagnostics: Vec<Diagnostic>,
    /// Some file could not be read at all (exit 2).
    pub io_error: bool,
    /// The lone stage given GL's fixed-function other stage (it is not alone): a fragment
    /// stage GL's vertex processing, a vertex stage GL's fragment processing.
    pub stage_added_for: Option<String>,
    /// The most bytes a stage or included file may hold (`[limits] file-bytes`).
    file_bytes: u64,
    /// Macros defined in every stage (`--define`), before a stage's own.
    defines: Vec<Define>,
}

/// How a program's files are read.
#[derive(Debug, Clone, Copy)]
pub struct Reading<'a> {
    /// A program that is one compatibility-profile fragment stage gets GL's fixed-function
    /// vertex stage ([`compat::fixed_function_vertex_stage`]), one that is a vertex stage
    /// GL's fixed-function fragment stage ([`compat::fixed_function_fragment_stage`]), as
    /// GL draws them.
    pub fixed_function_stages: bool,
    /// No stage or included file over this many bytes is read.
    pub file_bytes: u64,
    /// `--define`: macros defined in every stage.
    pub defines: &'a [Define],
}

/// What there is to analyse.
#[derive(Debug)]
pub enum Body {
    /// Nothing: the manifest or a stage file could not be read.
    Nothing,
    /// One program of these stage files.
    Single(Vec<(FileId, StageKind)>),
    /// A multi-pass effect, pass by pass.
    Passes(Vec<PassFiles>),
}

/// One pass of a multi-pass effect, read.
#[derive(Debug)]
pub struct PassFiles {
    /// The pass's view of the effect ([`Effect::pass_view`]).
    pub view: Effect,
    /// Its stage files, `None` when one could not be read or the effect it reuses failed.
    pub stages: Option<Vec<(FileId, StageKind)>>,
}

/// Reads the files of `input` into `files` as `how` says.
pub fn load(input: &ProgramInput, files: &mut Files, how: &Reading<'_>) -> Loaded {
    let mut l = Loaded {
        name: input.display_name(),
        effect: None,
        body: Body::Nothing,
        diagnostics: Vec::new(),
        io_error: false,
        stage_added_for: None,
        file_bytes: how.file_bytes,
        defines: how.defines.to_vec(),
    };
    match input {
        ProgramInput::Manifest(path) => match manifest::load(path, files) {
            Ok(e) => {
                l.diagnostics.extend(e.warnings.iter().cloned());
                l.body = if e.is_multi_pass() {
                    Body::Passes(load_passes(&e, files, &mut l))
                } else {
                    let stages: Vec<(PathBuf, StageKind, &[Define])> =
                        e.stages.iter().map(|s| (s.path.clone(), s.kind, &s.defines[..])).collect();
                    read_all(&stages, files, &mut l).map_or(Body::Nothing, Body::Single)
                };
                l.effect = Some(e);
            }
            Err(diags) => {
                l.io_error |= diags.iter().any(manifest::is_io_error);
                l.diagnostics.extend(diags);
            }
        },
        ProgramInput::Stages { files: stages, defines, .. } => {
            let of_kind = |k: StageKind| defines.iter().find(|(d, _)| *d == k).map_or(&[][..], |(_, list)| &list[..]);
            let stages: Vec<(PathBuf, StageKind, &[Define])> = stages.iter().map(|(p, k)| (p.clone(), *k, of_kind(*k))).collect();
            l.body = read_all(&stages, files, &mut l).map_or(Body::Nothing, Body::Single);
        }
    }
    if let (Body::Single(stages), true) = (&mut l.body, how.fixed_function_stages) {
        let lone = |kind: StageKind| stages.first().filter(|_| stages.iter().all(|(_, k)| *k == kind)).map(|(f, _)| *f);
        // The fragment stage alone (one file, or several shader objects of it), or the
        // vertex stage alone.
        let added = if let Some(fragment) = lone(StageKind::Fragment) {
            compat::fixed_function_vertex_stage(&joined_text(stages, files)).map(|t| (fragment, t, StageKind::Vertex, "vertex"))
        } else if let Some(vertex) = lone(StageKind::Vertex) {
            compat::fixed_function_fragment_stage(&joined_text(stages, files)).map(|t| (vertex, t, StageKind::Fragment, "fragment"))
        } else {
            None
        };
        if let Some((lone, text, kind, words)) = added {
            let name = format!("{} (GL's fixed-function {words} stage)", files.path(lone));
            l.stage_added_for = Some(files.path(lone).to_string());
            let generated = (files.add_generated(name, text), kind);
            match kind {
                StageKind::Vertex => stages.insert(0, generated),
                _ => stages.push(generated),
            }
        }
    }
    l
}

/// The texts of `stages` joined (a stage made of several shader objects).
fn joined_text(stages: &[(FileId, StageKind)], files: &Files) -> String {
    stages.iter().map(|(f, _)| files.text(*f)).collect::<Vec<_>>().join("\n")
}

/// Every stage file, or `None` when one of them could not be read.
fn read_all(stages: &[(PathBuf, StageKind, &[Define])], files: &mut Files, l: &mut Loaded) -> Option<Vec<(FileId, StageKind)>> {
    let read: Vec<Option<(FileId, StageKind)>> =
        stages.iter().map(|(path, kind, defines)| read_stage(path, defines, files, l).map(|id| (id, *kind))).collect();
    let read: Option<Vec<_>> = read.into_iter().collect();
    let read = read.filter(|r| !r.is_empty())?;
    // Several files of one stage are shader objects GL links into it: effectc's own
    // analysis reads them joined (`front::units`); the reference compiler, each one.
    let mut kinds: Vec<StageKind> = read.iter().map(|(_, k)| *k).collect();
    kinds.sort();
    kinds.dedup();
    for kind in kinds {
        let units: Vec<FileId> = read.iter().filter(|(_, k)| *k == kind).map(|(f, _)| *f).collect();
        if units.len() > 1 {
            crate::front::units::join(files, &units);
        }
    }
    Some(read)
}

/// The passes of a multi-pass effect: each one's view and stage files (a file two passes
/// share is read once).
fn load_passes(effect: &Effect, files: &mut Files, l: &mut Loaded) -> Vec<PassFiles> {
    let mut read: HashMap<(PathBuf, Vec<Define>), Option<FileId>> = HashMap::new();
    let mut passes = Vec::new();
    for pass in &effect.passes {
        let reused = match &pass.reuse {
            None => None,
            Some((path, span)) => match manifest::load(path, files) {
                Ok(r) if r.is_multi_pass() => {
                    l.diagnostics.push(
                        Diagnostic::new(Code::ManifestConflict, format!("pass `{}` reuses a multi-pass effect", pass.name))
                            .at(effect.file, span.clone(), "has [[passes]] of its own")
                            .with_help("reuse a single-pass effect, or copy its passes into this manifest"),
                    );
                    None
                }
                Ok(r) => Some(r),
                Err(diags) => {
                    l.io_error |= diags.iter().any(manifest::is_io_error);
                    l.diagnostics.push(
                        Diagnostic::new(Code::ManifestValue, format!("pass `{}` reuses an effect that has errors", pass.name)).at(
                            effect.file,
                            span.clone(),
                            "this effect",
                        ),
                    );
                    l.diagnostics.extend(diags);
                    None
                }
            },
        };
        let view = effect.pass_view(pass, reused.as_ref());
        if pass.reuse.is_some() && reused.is_none() {
            passes.push(PassFiles { view, stages: None });
            continue;
        }
        let mut stages = Vec::new();
        let mut readable = true;
        for s in &view.stages {
            let key = (s.path.clone(), s.defines.clone());
            let id = match read.get(&key) {
                Some(id) => *id,
                None => {
                    let id = read_stage(&s.path, &s.defines, files, l);
                    read.insert(key, id);
                    id
                }
            };
            match id {
                Some(id) => stages.push((id, s.kind)),
                None => readable = false,
            }
        }
        let stages = (readable && !stages.is_empty()).then_some(stages);
        passes.push(PassFiles { view, stages });
    }
    passes
}

/// Reads one stage file, inlines its `#include`s and writes the run's and the stage's
/// `defines` after its `#version` line: the id of the text the front reads.
fn read_stage(path: &Path, defines: &[Define], files: &mut Files, l: &mut Loaded) -> Option<FileId> {
    match crate::read::bounded(path, l.file_bytes) {
        Ok(bytes) => match crate::front::source_text::of(bytes) {
            Ok(text) => {
                let id = files.add(path.display().to_string(), text);
                let expanded = crate::front::includes::expand(path, id, files, l.file_bytes, &mut l.diagnostics)?;
                let all: Vec<Define> = l.defines.iter().chain(defines).cloned().collect();
                Some(crate::front::defines::apply(files, expanded, &all))
            }
            Err((at, text)) => {
                let id = files.add(path.display().to_string(), text);
                l.diagnostics.push(
                    Diagnostic::new(Code::NotText, "this stage file is not UTF-8 text")
                        .at(id, at..at + 1, "invalid byte here")
                        .with_note("GLSL sources are text (bytes outside UTF-8 are read only inside comments); is this a binary file?"),
                );
                None
            }
        },
        Err(crate::read::Refused::Io(e)) => {
            l.io_error = true;
            l.diagnostics.push(Diagnostic::new(Code::InputIo, format!("cannot read `{}`: {e}", path.display())));
            None
        }
        Err(why) => {
            l.io_error = true;
            l.diagnostics.push(Diagnostic::new(Code::InputRefused, format!("`{}` is not read: {why}", path.display())));
            None
        }
    }
}
