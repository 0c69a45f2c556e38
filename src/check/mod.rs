//! `effectc check`: every program through manifest, front and link; diagnostics collected.
//!
//! One bad program never stops the others. The outcome says whether any input could not
//! be read (exit 2) and holds every diagnostic for the emitters.

pub mod hazards;

use std::collections::{HashMap, HashSet};
use std::path::Path;

use crate::diag::{Code, Diagnostic, FileId, Files};
use crate::front::program::{self, CompiledProgram, FrontOptions};
use crate::graph::PassPlan;
use crate::inputs::{self, ProgramInput};
use crate::manifest::{self, Effect};
use crate::stage::StageKind;

/// The result of checking a set of inputs.
#[derive(Debug, Default)]
pub struct Outcome {
    pub files: Files,
    pub diagnostics: Vec<Diagnostic>,
    pub programs: usize,
    /// Some input could not be read at all (usage / IO: exit code 2).
    pub io_error: bool,
}

/// A checked program, kept for later steps (translate, render, stress, bench): the one
/// value they all start from.
#[derive(Debug)]
pub struct Checked {
    pub name: String,
    pub effect: Option<Effect>,
    /// Errors were found in this program (`units` is then empty).
    pub failed: bool,
    /// What there is to translate and draw: one unit for a single-pass program; one per
    /// pass of a multi-pass effect, in manifest order (those that do not reach the
    /// output have `runs == false`).
    pub units: Vec<Unit>,
    /// Multi-pass effects: the pass plan, computed once here (at output size 1×1; see
    /// [`crate::graph::PassPlan::sized`]).
    pub plan: Option<PassPlan>,
}

/// One program of a checked input: what one translation is made from.
#[derive(Debug)]
pub struct Unit {
    /// Index into `Effect::passes` (0 for a single-pass program).
    pub pass: usize,
    /// The translation's name: the effect's, the pass view's (`<effect>.<pass>`), or for
    /// bare stage files the first file's stem.
    pub name: String,
    /// The effect the program is translated and drawn with: the manifest's, or for a pass
    /// its view ([`Effect::pass_view`], the top-level uniforms and textures narrowed to
    /// those the pass's stages declare). `None` for bare stage files.
    pub effect: Option<Effect>,
    pub program: CompiledProgram,
    /// The unit reaches the output (always, for a single-pass program).
    pub runs: bool,
}

impl Checked {
    /// The units that reach the output, in order.
    pub fn running(&self) -> impl Iterator<Item = &Unit> {
        self.units.iter().filter(|u| u.runs)
    }
    /// The unit of pass `pass` (0 for a single-pass program).
    pub fn unit(&self, pass: usize) -> Option<&Unit> {
        self.units.iter().find(|u| u.pass == pass)
    }
    /// The effect when it has passes.
    pub fn multi_pass(&self) -> Option<&Effect> {
        self.effect.as_ref().filter(|e| e.is_multi_pass())
    }
}

/// What a command reads: the paths named on the command line, the stage of files whose
/// extension does not tell it, and the front's options. Every command starts from one.
#[derive(Debug, Clone, Default)]
pub struct InputSpec {
    pub paths: Vec<std::path::PathBuf>,
    pub stage: Option<StageKind>,
    pub front: FrontOptions,
}

impl InputSpec {
    /// Checks every program the spec names.
    pub fn check(&self) -> (Outcome, Vec<Checked>) {
        check_inputs(&self.paths, self.stage, self.front)
    }
}

/// Checks every program named by `inputs`.
pub fn check_inputs(inputs: &[std::path::PathBuf], forced: Option<StageKind>, options: FrontOptions) -> (Outcome, Vec<Checked>) {
    let mut out = Outcome::default();
    let (programs, diags) = inputs::collect(inputs, forced);
    out.io_error |= diags.iter().any(|d| d.code == Code::InputIo);
    out.diagnostics.extend(diags);
    let mut checked = Vec::new();
    for p in programs {
        out.programs += 1;
        checked.push(check_program(&p, options, &mut out));
    }
    crate::diag::sort(&mut out.diagnostics);
    (out, checked)
}

fn read_stage(path: &Path, files: &mut Files, diags: &mut Vec<Diagnostic>, io_error: &mut bool) -> Option<FileId> {
    match std::fs::read(path) {
        Ok(bytes) => match String::from_utf8(bytes) {
            Ok(text) => {
                let id = files.add(path.display().to_string(), text);
                crate::front::includes::expand(path, id, files, diags)
            }
            Err(e) => {
                let valid = e.utf8_error().valid_up_to();
                let text = String::from_utf8_lossy(e.as_bytes()).to_string();
                let id = files.add(path.display().to_string(), text);
                diags.push(
                    Diagnostic::new(Code::NotText, "this stage file is not UTF-8 text")
                        .at(id, valid..valid + 1, "invalid byte here")
                        .with_note("GLSL sources are text; is this a binary file?"),
                );
                None
            }
        },
        Err(e) => {
            *io_error = true;
            diags.push(Diagnostic::new(Code::InputIo, format!("cannot read `{}`: {e}", path.display())));
            None
        }
    }
}

/// Checks one program; diagnostics go to `out`.
pub fn check_program(input: &ProgramInput, options: FrontOptions, out: &mut Outcome) -> Checked {
    let start = out.diagnostics.len();
    let mut effect = None;
    let mut stage_files: Vec<(FileId, StageKind)> = Vec::new();
    let mut readable = true;
    let mut units = Vec::new();
    let mut plan = None;
    match input {
        ProgramInput::Manifest(path) => match manifest::load(path, &mut out.files) {
            Ok(e) if e.is_multi_pass() => {
                out.diagnostics.extend(e.warnings.iter().cloned());
                (units, plan) = check_passes(&e, options, out);
                dedup_from(&mut out.diagnostics, start);
                effect = Some(e);
            }
            Ok(e) => {
                out.diagnostics.extend(e.warnings.iter().cloned());
                for s in &e.stages {
                    match read_stage(&s.path, &mut out.files, &mut out.diagnostics, &mut out.io_error) {
                        Some(id) => stage_files.push((id, s.kind)),
                        None => readable = false,
                    }
                }
                effect = Some(e);
            }
            Err(diags) => {
                out.io_error |= diags.iter().any(manifest::is_io_error);
                out.diagnostics.extend(diags);
                readable = false;
            }
        },
        ProgramInput::Stages { files, .. } => {
            for (path, kind) in files {
                match read_stage(path, &mut out.files, &mut out.diagnostics, &mut out.io_error) {
                    Some(id) => stage_files.push((id, *kind)),
                    None => readable = false,
                }
            }
        }
    }
    if readable && !stage_files.is_empty() {
        let (program, diags) = check_stages(&out.files, &stage_files, effect.as_ref(), options);
        out.diagnostics.extend(diags);
        if let Some(program) = program {
            let name = effect.as_ref().map_or_else(|| stem_of(&out.files, &program), |e| e.name.clone());
            units.push(Unit { pass: 0, name, effect: effect.clone(), program, runs: true });
        }
    }
    let failed = out.diagnostics[start..].iter().any(Diagnostic::is_error);
    if failed {
        units.clear();
    }
    Checked { name: input.display_name(), effect, failed, units, plan }
}

/// The name of a program from bare stage files: its first file's stem.
fn stem_of(files: &Files, program: &CompiledProgram) -> String {
    let path = Path::new(files.path(program.stages[0].syntax.file));
    path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| "effect".into())
}

/// Checks the stages of one program already in `files` (front, link rules, the manifest
/// when there is one, static hazards): what `check` does after reading the files.
pub fn check_stages(
    files: &Files,
    stage_files: &[(FileId, StageKind)],
    effect: Option<&Effect>,
    options: FrontOptions,
) -> (Option<CompiledProgram>, Vec<Diagnostic>) {
    let mut diags = Vec::new();
    let mut program = program::compile(files, stage_files, options, &mut diags);
    if let Some(p) = &mut program {
        let syntaxes: Vec<_> = p.stages.iter().map(|s| s.syntax.clone()).collect();
        diags.extend(crate::link::check_interface(&syntaxes));
        if let Some(e) = effect {
            diags.extend(crate::link::check_manifest(e, &syntaxes, files));
        }
        if !diags.iter().any(Diagnostic::is_error) {
            program::fold_geometry(p, &mut diags);
            diags.extend(hazards::analyse(effect, p));
        }
    }
    (program, diags)
}

/// Drops repeated diagnostics after `start` (two passes sharing a stage file report its
/// findings once).
fn dedup_from(diags: &mut Vec<Diagnostic>, start: usize) {
    let mut seen: Vec<Diagnostic> = Vec::new();
    let tail: Vec<Diagnostic> = diags.drain(start..).collect();
    for d in tail {
        if !seen.contains(&d) {
            seen.push(d);
        }
    }
    diags.extend(seen);
}

/// Checks every pass of a multi-pass effect, then the graph they form: a unit per pass that
/// compiled, and the pass plan when the graph has no errors.
fn check_passes(effect: &Effect, options: FrontOptions, out: &mut Outcome) -> (Vec<Unit>, Option<PassPlan>) {
    let mut read: HashMap<std::path::PathBuf, Option<FileId>> = HashMap::new();
    let mut units = Vec::new();
    let mut syntaxes_of: Vec<Option<Vec<crate::front::syntax::StageSyntax>>> = Vec::new();
    let mut used_uniforms: HashSet<String> = HashSet::new();
    let mut used_textures: HashSet<String> = HashSet::new();
    let mut all_declared = true;
    for (i, pass) in effect.passes.iter().enumerate() {
        let reused = match &pass.reuse {
            None => None,
            Some((path, span)) => match manifest::load(path, &mut out.files) {
                Ok(r) if r.is_multi_pass() => {
                    out.diagnostics.push(
                        Diagnostic::new(Code::ManifestConflict, format!("pass `{}` reuses a multi-pass effect", pass.name))
                            .at(effect.file, span.clone(), "has [[passes]] of its own")
                            .with_help("reuse a single-pass effect, or copy its passes into this manifest"),
                    );
                    None
                }
                Ok(r) => Some(r),
                Err(diags) => {
                    out.io_error |= diags.iter().any(manifest::is_io_error);
                    out.diagnostics.push(
                        Diagnostic::new(Code::ManifestValue, format!("pass `{}` reuses an effect that has errors", pass.name)).at(
                            effect.file,
                            span.clone(),
                            "this effect",
                        ),
                    );
                    out.diagnostics.extend(diags);
                    None
                }
            },
        };
        let mut view = effect.pass_view(pass, reused.as_ref());
        if pass.reuse.is_some() && reused.is_none() {
            syntaxes_of.push(None);
            all_declared = false;
            continue;
        }
        let mut stage_files = Vec::new();
        let mut readable = true;
        for s in &view.stages {
            let id =
                *read.entry(s.path.clone()).or_insert_with(|| read_stage(&s.path, &mut out.files, &mut out.diagnostics, &mut out.io_error));
            match id {
                Some(id) => stage_files.push((id, s.kind)),
                None => readable = false,
            }
        }
        let mut program = None;
        let mut syntaxes = None;
        if readable && !stage_files.is_empty() {
            let mut diags = Vec::new();
            program = program::compile(&out.files, &stage_files, options, &mut diags);
            if let Some(p) = &mut program {
                let s: Vec<_> = p.stages.iter().map(|s| s.syntax.clone()).collect();
                diags.extend(crate::link::check_interface(&s));
                if pass.reuse.is_none() {
                    let declared = crate::link::declared::declared(&s);
                    view.uniforms.retain(|u| pass.uniforms.iter().any(|p| p.name == u.name) || declared.has_uniform(&u.name));
                    view.textures.retain(|t| declared.sampler(&t.name).is_some());
                    used_uniforms.extend(view.uniforms.iter().map(|u| u.name.clone()));
                    used_textures.extend(view.textures.iter().map(|t| t.name.clone()));
                }
                let bound: HashSet<String> = pass.samples.iter().map(|s| s.sampler.clone()).collect();
                diags.extend(crate::link::check_pass_manifest(&view, &s, &out.files, &bound));
                // Targets an earlier pass drew are unknown to the analysis: they raise nothing.
                if !diags.iter().any(Diagnostic::is_error) {
                    program::fold_geometry(p, &mut diags);
                    diags.extend(hazards::analyse(Some(&view), p));
                }
                syntaxes = Some(s);
            }
            out.diagnostics.extend(diags);
        }
        all_declared &= syntaxes.is_some() || pass.reuse.is_some();
        syntaxes_of.push(syntaxes);
        if let Some(program) = program {
            units.push(Unit { pass: i, name: view.name.clone(), effect: Some(view), program, runs: true });
        }
    }
    if all_declared {
        out.diagnostics.extend(crate::link::graph_rules::unused_entries(effect, &used_uniforms, &used_textures));
    }
    let shaders: Vec<crate::link::graph_rules::PassShaders<'_>> =
        syntaxes_of.iter().map(|s| crate::link::graph_rules::PassShaders { stages: s.as_deref() }).collect();
    let (diags, plan) = crate::link::graph_rules::check(effect, &shaders);
    out.diagnostics.extend(diags);
    if let Some(plan) = &plan {
        for unit in &mut units {
            unit.runs = plan.runs[unit.pass];
        }
    }
    (units, plan)
}
