//! `effectc check`: every program through manifest, front and link; diagnostics collected.
//!
//! One bad program never stops the others. The outcome says whether any input could not
//! be read (exit 2) and holds every diagnostic for the emitters.

pub mod formation;
pub mod hazards;
pub mod listing;
mod load;
mod set_values;

use std::collections::HashSet;
use std::path::{Path, PathBuf};

use crate::config::HazardSettings;
use crate::config::Selection;
use crate::diag::{Code, Diagnostic, FileId, Files};
use crate::front::program::{self, CompiledProgram, FrontOptions};
use crate::graph::PassPlan;
use crate::inputs;
use crate::manifest::Effect;
use crate::stage::StageKind;

/// The result of checking a set of inputs.
#[derive(Debug, Default)]
pub struct Outcome {
    pub files: Files,
    pub diagnostics: Vec<Diagnostic>,
    pub programs: usize,
    /// Some input could not be read at all (usage / IO: exit code 2).
    pub io_error: bool,
    /// Every file the programs read ([`Checked::read`] of all of them).
    pub read: Vec<PathBuf>,
    /// The programs formed, and why ([`formation`]).
    pub formed: Vec<formation::Formation>,
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
    /// Every file the program reads, as registered (manifests, stage files, included
    /// files) and as named by its manifest (textures, meshes): what `--watch` watches.
    pub read: Vec<PathBuf>,
    /// Uniform values set on the command line (`--set`) that this program declares, checked.
    pub values: Vec<(String, crate::manifest::UniformValue)>,
    /// A legal program effectc's own analysis cannot read (checked by the reference compiler
    /// only, note N0106): why translate and render stop (E0306).
    pub untranslatable: Option<Diagnostic>,
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

/// What a command reads: the paths named on the command line, the repository's selection
/// of them, the stage of files whose extension does not tell it, the front's options, and
/// how many programs are analysed at once. Every command starts from one.
#[derive(Debug, Clone, Default)]
pub struct InputSpec {
    pub paths: Vec<PathBuf>,
    pub stage: Option<StageKind>,
    pub front: FrontOptions,
    pub selection: Selection,
    /// Threads analysing programs (`None`: one per core; `Some(1)`: on the calling thread).
    pub jobs: Option<usize>,
    /// `--set NAME=VALUE` as typed: uniform values for every program that declares them.
    pub values: Vec<(String, String)>,
    /// A lone compatibility-profile fragment stage is drawn with GL's fixed-function
    /// vertex stage, a lone vertex stage with its fixed-function fragment stage (the
    /// commands that draw: render, verify, bench, stress).
    pub fixed_function_stages: bool,
    /// `--define`: macros defined in every stage read (before a stage's own defines).
    pub defines: Vec<crate::stage::Define>,
    /// What the hazard analysis assumes where no manifest says (`effectc.toml`'s `[hazards]`).
    pub hazards: crate::config::HazardSettings,
}

impl InputSpec {
    /// The spec of a command that draws on WebGPU: a lone compatibility fragment or vertex
    /// stage gets GL's fixed-function other stage, and doubles are drawn as floats (W0131).
    pub fn for_drawing(self) -> InputSpec {
        InputSpec { fixed_function_stages: true, front: FrontOptions { doubles_as_floats: true, ..self.front }, ..self }
    }

    /// Checks every program the spec names: files are read in input order, then the
    /// programs are analysed in parallel; the report is the same for any number of jobs.
    pub fn check(&self) -> (Outcome, Vec<Checked>) {
        let mut out = Outcome::default();
        let (programs, diags) = inputs::collect(&self.paths, self.stage, &self.selection);
        out.io_error |= diags.iter().any(|d| d.code == Code::InputIo);
        out.diagnostics.extend(diags);
        let mut loaded = Vec::with_capacity(programs.len());
        let mut registered = Vec::with_capacity(programs.len());
        for p in &programs {
            let before = out.files.len();
            let reading = load::Reading {
                fixed_function_stages: self.fixed_function_stages,
                file_bytes: self.front.limits.file_bytes,
                defines: &self.defines,
            };
            let l = load::load(p, &mut out.files, &reading);
            out.formed.push(formation::of(p, l.effect.as_ref(), &self.defines));
            if let Some(lone) = &l.stage_added_for {
                // Not alone after all: GL's fixed-function stage links with it.
                let alone = format!("`{lone}` is checked alone");
                out.diagnostics.retain(|d| !(d.code == Code::StageAlone && d.message.starts_with(&alone)));
            }
            loaded.push(l);
            registered.push(before..out.files.len());
        }
        out.programs = loaded.len();
        let files = &out.files;
        let options = self.front;
        let hazards = self.hazards;
        let analysed: Vec<(Checked, Vec<Diagnostic>, bool)> = self.on_threads(|| {
            use rayon::prelude::*;
            // One task per program: programs differ a lot in cost (a generated texture's
            // hazard facts, a multi-pass graph), and rayon's default chunks left one of two
            // threads idle a third of the time (1.46x instead of 1.76x on 252 programs).
            loaded.into_par_iter().with_max_len(1).map(|l| analyse(l, files, options, hazards)).collect()
        });
        let mut checked = Vec::with_capacity(analysed.len());
        for ((mut c, diags, io_error), ids) in analysed.into_iter().zip(registered) {
            out.io_error |= io_error;
            out.diagnostics.extend(diags);
            c.read = ids
                .map(FileId)
                .filter(|id| !out.files.is_expanded(*id) && !out.files.is_generated(*id))
                .map(|id| PathBuf::from(out.files.path(id)))
                .collect();
            c.read.extend(c.effect.iter().chain(c.units.iter().filter_map(|u| u.effect.as_ref())).flat_map(assets));
            c.read.sort();
            c.read.dedup();
            out.read.extend(c.read.iter().cloned());
            checked.push(c);
        }
        out.read.sort();
        out.read.dedup();
        unique_names(&mut checked);
        if !self.values.is_empty() {
            set_values::apply(&self.values, &mut out, &mut checked);
        }
        crate::diag::sort(&mut out.diagnostics);
        (out, checked)
    }

    /// Runs `work` on a pool of [`InputSpec::jobs`] threads, each with an
    /// [`ANALYSIS_STACK`] (one job: one such thread), so every `--jobs` reads the same inputs.
    fn on_threads<T: Send>(&self, work: impl FnOnce() -> T + Send) -> T {
        let threads = self.jobs.unwrap_or(0);
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).stack_size(ANALYSIS_STACK);
        match pool.build() {
            Ok(pool) => pool.install(work),
            Err(_) => work(),
        }
    }
}

/// The stack of every thread that analyses programs (and of the command's own thread):
/// glslang, glsl-lang, naga and effectc's walks recurse once per nesting level and per
/// term of a long sum. Reserved, not committed: a thread touches only what it uses.
pub const ANALYSIS_STACK: usize = 512 << 20;

/// Checks every program named by `inputs` (every path selected, one thread per core).
pub fn check_inputs(inputs: &[PathBuf], forced: Option<StageKind>, options: FrontOptions) -> (Outcome, Vec<Checked>) {
    InputSpec { paths: inputs.to_vec(), stage: forced, front: options, ..InputSpec::default() }.check()
}

/// Analyses one read program: its checked value, its diagnostics, whether a file could
/// not be read.
fn analyse(l: load::Loaded, files: &Files, options: FrontOptions, hazards: HazardSettings) -> (Checked, Vec<Diagnostic>, bool) {
    let mut diags = l.diagnostics;
    let io_error = l.io_error;
    let mut units = Vec::new();
    let mut plan = None;
    match l.body {
        load::Body::Nothing => {}
        load::Body::Single(stage_files) => {
            let (program, d) = check_stages(files, &stage_files, l.effect.as_ref(), (options, hazards));
            diags.extend(d);
            if let Some(program) = program {
                let name = l.effect.as_ref().map_or_else(|| stem_of(files, &program), |e| e.name.clone());
                units.push(Unit { pass: 0, name, effect: l.effect.clone(), program, runs: true });
            }
        }
        load::Body::Passes(passes) => {
            if let Some(effect) = &l.effect {
                (units, plan) = check_passes(effect, passes, files, (options, hazards), &mut diags);
            }
            crate::diag::dedup(&mut diags);
        }
    }
    let failed = diags.iter().any(Diagnostic::is_error);
    if failed {
        units.clear();
    }
    let untranslatable = if failed { None } else { diags.iter().find(|d| d.code == Code::ReferenceOnly).map(untranslatable) };
    (Checked { name: l.name, effect: l.effect, failed, units, plan, read: Vec::new(), values: Vec::new(), untranslatable }, diags, io_error)
}

/// Why a program checked by glslang only is not translated: E0306 where its N0106 note is.
fn untranslatable(note: &Diagnostic) -> Diagnostic {
    let mut d =
        Diagnostic::new(Code::TargetCannotExpress, "the program cannot be translated: it is checked by the reference compiler only");
    d.file = note.file;
    d.span = note.span.clone();
    d.primary_label = "checked by the reference compiler only".into();
    d.notes = std::iter::once(note.message.clone()).chain(note.notes.iter().cloned()).collect();
    d
}

/// The image and mesh files an effect names.
fn assets(effect: &Effect) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for t in &effect.textures {
        match &t.source {
            crate::manifest::TextureSource::File(p) => out.push(p.clone()),
            crate::manifest::TextureSource::Faces(faces) => out.extend(faces.iter().cloned()),
            _ => {}
        }
    }
    if let Some(crate::manifest::MeshSource::Obj(p)) = effect.mesh.as_ref().map(|m| &m.source) {
        out.push(p.clone());
    }
    out
}

/// Programs of bare stage files are named after their first file's stem, so one vertex
/// stage paired with several fragment stages (a folder's, or a `[[program]]`'s) gave them
/// one name, and each one's outputs overwrote the last's. Such names get the program's own
/// (`PCN-Diffuse`, `PCN-Phong`), or a number when that does not tell them apart.
fn unique_names(checked: &mut [Checked]) {
    let mut count: std::collections::HashMap<String, usize> = std::collections::HashMap::new();
    for c in checked.iter().filter(|c| c.effect.is_none()) {
        for u in &c.units {
            *count.entry(u.name.clone()).or_default() += 1;
        }
    }
    let mut taken: HashSet<String> = count.iter().filter(|(_, n)| **n == 1).map(|(k, _)| k.clone()).collect();
    for c in checked.iter_mut().filter(|c| c.effect.is_none()) {
        let own = Path::new(&c.name).file_name().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
        for u in c.units.iter_mut().filter(|u| count.get(&u.name).is_some_and(|n| *n > 1)) {
            let mut name = if own.is_empty() || own == u.name { u.name.clone() } else { format!("{}-{own}", u.name) };
            let mut n = 2;
            while taken.contains(&name) {
                name = format!("{}-{n}", u.name);
                n += 1;
            }
            taken.insert(name.clone());
            u.name = name;
        }
    }
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
    (options, settings): (FrontOptions, HazardSettings),
) -> (Option<CompiledProgram>, Vec<Diagnostic>) {
    let mut diags = Vec::new();
    let mut program = program::compile(files, stage_files, options, &mut diags);
    if let Some(p) = &mut program {
        let syntaxes: Vec<_> = p.stages.iter().map(|s| s.syntax.clone()).collect();
        diags.extend(crate::link::check_interface(&syntaxes));
        diags.extend(reference_link_errors(p, &diags));
        drop_reference_repeats(files, &mut diags);
        if let Some(e) = effect {
            diags.extend(crate::link::check_manifest(e, &syntaxes, files));
        }
        if !diags.iter().any(Diagnostic::is_error) {
            crate::front::folds::fold_stages(p, &mut diags);
            diags.extend(hazards::analyse(effect, p, settings));
        }
    }
    crate::front::macro_spans::narrow(files, &mut diags);
    (program, diags)
}

/// glslang's link errors for a program effectc's own front and link rules found no error in
/// (where they did, their errors name the problem with both declarations labelled).
fn reference_link_errors(program: &CompiledProgram, so_far: &[Diagnostic]) -> Vec<Diagnostic> {
    match &program.reference {
        Some(j) if !so_far.iter().any(Diagnostic::is_error) => j.link_errors.iter().map(|d| label_link_error(program, d.clone())).collect(),
        _ => Vec::new(),
    }
}

/// glslang names each side of a link mismatch on a line of its own (`vertex stage: tex
/// "layout( binding=1) uniform"`): the declaration of that name in that stage is labelled.
fn label_link_error(program: &CompiledProgram, mut d: Diagnostic) -> Diagnostic {
    let mut sides = Vec::new();
    for note in &d.notes {
        let Some((stage, rest)) = note.split_once(" stage: ") else { continue };
        let Some(kind) = crate::front::reference::stage_named(stage) else { continue };
        let name: String = rest.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
        let Some(s) = program.stage(kind) else { continue };
        if let Some(g) = s.syntax.globals.iter().find(|g| g.name == name) {
            sides.push((s.syntax.file, g.name_span.clone(), format!("`{name}` in the {kind} stage")));
        }
    }
    for (i, (file, span, label)) in sides.into_iter().enumerate() {
        d = if i == 0 {
            let mut primary = Diagnostic::new(d.code, d.message.clone()).at(file, span, label);
            primary.notes = d.notes;
            primary
        } else {
            d.with_label(file, span, label)
        };
    }
    d
}

/// Drops a glslang error (E0105) on a line where effectc's own rules report an error too
/// (a geometry input that is no array: effectc's E0212 says it with the declaration
/// labelled).
fn drop_reference_repeats(files: &Files, diags: &mut Vec<Diagnostic>) {
    let own: Vec<_> =
        diags.iter().filter(|d| d.is_error() && d.code != Code::ReferenceRejects).filter_map(|d| files.primary_line(d)).collect();
    diags.retain(|d| d.code != Code::ReferenceRejects || files.primary_line(d).is_none_or(|l| !own.contains(&l)));
}

/// Checks every pass of a multi-pass effect, then the graph they form: a unit per pass that
/// compiled, and the pass plan when the graph has no errors.
fn check_passes(
    effect: &Effect,
    passes: Vec<load::PassFiles>,
    files: &Files,
    (options, settings): (FrontOptions, HazardSettings),
    out: &mut Vec<Diagnostic>,
) -> (Vec<Unit>, Option<PassPlan>) {
    let mut units = Vec::new();
    let mut syntaxes_of: Vec<Option<Vec<crate::front::syntax::StageSyntax>>> = Vec::new();
    let mut used_uniforms: HashSet<String> = HashSet::new();
    let mut used_textures: HashSet<String> = HashSet::new();
    let mut all_declared = true;
    for (i, (pass, read)) in effect.passes.iter().zip(passes).enumerate() {
        let mut view = read.view;
        let mut program = None;
        let mut syntaxes = None;
        if let Some(stage_files) = &read.stages {
            let mut diags = Vec::new();
            program = program::compile(files, stage_files, options, &mut diags);
            if let Some(p) = &mut program {
                let s: Vec<_> = p.stages.iter().map(|s| s.syntax.clone()).collect();
                diags.extend(crate::link::check_interface(&s));
                diags.extend(reference_link_errors(p, &diags));
                drop_reference_repeats(files, &mut diags);
                if pass.reuse.is_none() {
                    let declared = crate::link::declared::declared(&s);
                    view.uniforms.retain(|u| pass.uniforms.iter().any(|p| p.name == u.name) || declared.has_uniform(&u.name));
                    view.textures.retain(|t| declared.sampler(&t.name).is_some());
                    used_uniforms.extend(view.uniforms.iter().map(|u| u.name.clone()));
                    used_textures.extend(view.textures.iter().map(|t| t.name.clone()));
                }
                let bound: HashSet<String> = pass.samples.iter().map(|s| s.sampler.clone()).collect();
                diags.extend(crate::link::check_pass_manifest(&view, &s, files, &bound));
                // Targets an earlier pass drew are unknown to the analysis: they raise nothing.
                if !diags.iter().any(Diagnostic::is_error) {
                    crate::front::folds::fold_stages(p, &mut diags);
                    diags.extend(hazards::analyse(Some(&view), p, settings));
                }
                syntaxes = Some(s);
            }
            out.extend(diags);
        }
        all_declared &= syntaxes.is_some() || pass.reuse.is_some();
        syntaxes_of.push(syntaxes);
        if let Some(program) = program {
            units.push(Unit { pass: i, name: view.name.clone(), effect: Some(view), program, runs: true });
        }
    }
    if all_declared {
        out.extend(crate::link::graph_rules::unused_entries(effect, &used_uniforms, &used_textures));
    }
    let shaders: Vec<crate::link::graph_rules::PassShaders<'_>> =
        syntaxes_of.iter().map(|s| crate::link::graph_rules::PassShaders { stages: s.as_deref() }).collect();
    let (diags, plan) = crate::link::graph_rules::check(effect, &shaders);
    out.extend(diags);
    if let Some(plan) = &plan {
        for unit in &mut units {
            unit.runs = plan.runs[unit.pass];
        }
    }
    (units, plan)
}
