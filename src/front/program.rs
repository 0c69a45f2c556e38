//! One GLSL program (the stages of an effect) through the whole front.
//!
//! analyse every stage → plan shared bindings and locations → rewrite each stage to 4.50 →
//! naga parse + validate. A geometry stage is folded into the vertex stage
//! ([`geometry_fold`]) and naga validates the fold; tessellation stages, and geometry
//! stages effectc cannot fold, are checked at the syntax and interface level only, and a
//! note says so.

use std::ops::Range;

use crate::diag::{Code, Diagnostic, FileId, Files};
use crate::front::aggregate_varyings;
use crate::front::edits::OffsetMap;
use crate::front::geometry_fold::{self, Folded};
use crate::front::limits;
use crate::front::naga_run::{self, Limitation, Outcome, Validated};
use crate::front::plan::{self, Plan};
use crate::front::reference;
use crate::front::rewrite::{self, Rewritten};
use crate::front::syntax::{self, StageSyntax};
use crate::front::through_spirv;
use crate::front::webgpu_features;
use crate::stage::StageKind;

/// Options for the front.
#[derive(Debug, Clone, Copy, Default)]
pub struct FrontOptions {
    /// Constructs the declared GLSL version forbids are errors, not warnings.
    pub strict: bool,
    /// The GLSL dialect (OpenGL or Vulkan), or told by the text.
    pub env: crate::config::TargetEnv,
    /// Take 64-bit floats as 32-bit ones ([`doubles`](crate::front::doubles)): the
    /// commands that draw on WebGPU, and translation to targets without f64.
    pub doubles_as_floats: bool,
    /// How much of a stage effectc reads and models (E0107 beyond).
    pub limits: crate::limits::Limits,
}

/// A stage as compiled by the front.
#[derive(Debug)]
pub struct CompiledStage {
    pub syntax: StageSyntax,
    pub rewritten: Option<Rewritten>,
    pub naga: Option<Validated>,
    /// A legal construct naga cannot take (the stage is checked for syntax and interface only).
    pub limitation: Option<Limitation>,
    /// `naga` was read from glslang's SPIR-V ([`through_spirv`]), not by naga's GLSL front;
    /// `rewritten` is the text glslang compiled, which the module's spans index: the
    /// stage's own text, or its 4.50 rewrite for a stage glslang makes no SPIR-V of as written.
    pub through_spirv: bool,
}

/// The front's result for a program: per-stage results, the shared plan, and diagnostics.
#[derive(Debug)]
pub struct CompiledProgram {
    pub stages: Vec<CompiledStage>,
    pub plan: Plan,
    /// A program with a geometry stage: its vertex and geometry stages folded into one
    /// vertex module, or what kept them from being folded ([`fold_geometry`]; None before
    /// it ran, or without a geometry stage).
    pub folded: Option<Result<Folded, String>>,
    /// glslang's verdict on the program (None when glslang could not be set up).
    pub reference: Option<reference::Judgement>,
}

impl CompiledProgram {
    /// The compiled stage of `kind`.
    pub fn stage(&self, kind: StageKind) -> Option<&CompiledStage> {
        self.stages.iter().find(|s| s.syntax.stage == kind)
    }
    /// The folded vertex + geometry module, when there is a geometry stage and it folded.
    pub fn fold(&self) -> Option<&Folded> {
        self.folded.as_ref().and_then(|f| f.as_ref().ok())
    }
    /// Where a range of the text naga read for `stage` lies in the user's files: the stage's
    /// rewritten text, or for the vertex stage of a folded program the drawn fold's text.
    pub fn user_span(&self, stage: StageKind, range: Range<usize>) -> Option<(FileId, Range<usize>)> {
        match self.fold() {
            Some(f) if stage == StageKind::Vertex => self.user_span_in(&f.drawn, range),
            _ => {
                let s = self.stage(stage)?;
                Some((s.syntax.file, s.rewritten.as_ref()?.map.range_to_original(range)))
            }
        }
    }
    /// Where a range of a folded text lies in the user's files (None in generated glue).
    pub fn user_span_in(&self, lowered: &geometry_fold::Lowered, range: Range<usize>) -> Option<(FileId, Range<usize>)> {
        let (kind, range) = lowered.locate(range)?;
        let s = self.stage(kind)?;
        Some((s.syntax.file, s.rewritten.as_ref()?.map.range_to_original(range)))
    }
}

/// Runs the front over `stages` (file ids registered in `files`, any order).
pub fn compile(
    files: &Files,
    stages: &[(FileId, StageKind)],
    options: FrontOptions,
    diags: &mut Vec<Diagnostic>,
) -> Option<CompiledProgram> {
    let mut ordered: Vec<(FileId, StageKind)> = stages.to_vec();
    ordered.sort_by_key(|(_, k)| *k);
    let beyond: Vec<Diagnostic> = ordered.iter().filter_map(|(f, _)| limits::check(*f, files.text(*f), &options.limits)).collect();
    if !beyond.is_empty() {
        diags.extend(beyond);
        return None;
    }
    // Mesh shading and ray tracing: glslang's verdict only.
    if let Some(&(first, kind)) = ordered.iter().find(|(_, k)| k.reference_only()) {
        let title = kind.title();
        let note = Diagnostic::new(Code::ReferenceOnly, format!("WebGPU has no {title} stage: the program is checked by the reference compiler only"))
            .in_file(first)
            .with_note(format!("effectc's own analysis (interface rules, hazards, translation) models the stages WebGPU draws with; glslang compiles the {title} stage and links the program"));
        diags.extend(verdict_or(reference::judge(files, &ordered, options.env), note));
        return None;
    }
    // Shader objects of one stage: effectc reads their joined text (`units`), glslang each.
    let mut own_order = ordered.clone();
    if let Some(kind) = reference::repeated_stage(&ordered) {
        match joined_stages(files, &ordered) {
            Some(joined) => own_order = joined,
            None => {
                diags.extend(units_judged_by_glslang(files, &ordered, kind, reference::judge(files, &ordered, options.env)));
                return None;
            }
        }
    }
    // glslang decides what is legal; effectc's own findings in a stage it accepts are its
    // limits, not the user's errors ([`accept_what_glslang_accepts`]). Neither reads the
    // other's result, so they run side by side (one large program uses two cores).
    let (mut judgement, (program, own)) = rayon::join(
        || reference::judge(files, &ordered, options.env),
        || {
            let mut own = Vec::new();
            let program = compile_own(files, &own_order, options, &mut own);
            (program, own)
        },
    );
    if let Some(j) = &mut judgement {
        // A joined text is accepted where glslang accepts each of its files.
        for &(f, _) in own_order.iter().filter(|(f, _)| !ordered.iter().any(|(o, _)| o == f)) {
            let units = files.units_of(f).unwrap_or_default();
            let accepted = units.iter().all(|u| j.stage(*u).is_some_and(|v| v.accepted));
            j.stages.push(reference::StageVerdict { file: f, accepted, errors: Vec::new() });
        }
    }
    let Some(judgement) = judgement else {
        diags.extend(own);
        return program;
    };
    let (merged, naga_refused) = accept_what_glslang_accepts(files, &judgement, own);
    diags.extend(merged);
    if program.is_none() && !diags.iter().any(Diagnostic::is_error) {
        // effectc's own analysis could not read a stage glslang accepts (now a note): the
        // program is glslang's to link.
        diags.extend(judgement.link_errors.iter().cloned());
    }
    if let Some(p) = &program {
        let last = p.stage(StageKind::Geometry).or_else(|| p.stage(StageKind::Vertex));
        diags.extend(last.and_then(|s| webgpu_features::clip_distances_dropped(&s.syntax)));
    }
    let dialect = judgement.dialect;
    let program = program.map(|mut p| {
        for stage in &mut p.stages {
            if stage.naga.is_none() && stage.limitation.is_none() && stage.syntax.stage.naga().is_some() {
                // naga refused a stage glslang accepts: translate names what naga said.
                stage.limitation = naga_refused.iter().find(|(f, _)| *f == stage.syntax.file).map(|(_, l)| l.clone());
            }
        }
        p.reference = Some(judgement);
        through_spirv_where_naga_refuses(files, (own_order == ordered).then_some(&ordered[..]), dialect, &mut p, diags);
        p
    });
    if let Some(p) = &program {
        let folded = p.stage(StageKind::Geometry).is_some();
        if let Some((s, v)) = p.stage(StageKind::Fragment).and_then(|f| Some((&f.syntax, f.naga.as_ref()?))) {
            diags.extend(webgpu_features::optional_features_needed(s, v, folded));
        }
        for stage in &p.stages {
            diags.extend(webgpu_features::stage_notes(&stage.syntax, stage.naga.as_ref()));
        }
    }
    program
}

/// A legal program (glslang accepts and links it) with a stage naga's GLSL front cannot
/// take goes through SPIR-V instead ([`through_spirv`]), every stage of it, so the stages
/// share one binding and location plan: the stages as written (`ordered`, when each stage
/// is one file), else, where glslang makes no SPIR-V of them (GLSL below 1.40, the
/// compatibility profile), effectc's 4.50 rewrite of them. When that works, naga's
/// refusals are no longer limits of the program and their notes go; otherwise the program
/// stays as it was.
fn through_spirv_where_naga_refuses(
    files: &Files,
    ordered: Option<&[(FileId, StageKind)]>,
    dialect: reference::Dialect,
    program: &mut CompiledProgram,
    diags: &mut Vec<Diagnostic>,
) {
    let legal = program.reference.as_ref().is_some_and(|j| j.stages.iter().all(|v| v.accepted) && j.link_errors.is_empty());
    let refused = program.stages.iter().any(|s| s.limitation.is_some());
    let naga_stages = program.stages.iter().all(|s| s.syntax.stage.naga().is_some());
    if !legal || !refused || !naga_stages || diags.iter().any(Diagnostic::is_error) {
        return;
    }
    let debug = |why: &str| {
        if std::env::var_os("EFFECTC_DUMP_REFERENCE").is_some() {
            // Debugging aid: why a route through SPIR-V did not take the program.
            eprintln!("[through SPIR-V] {why}");
        }
    };
    let mut refused = None;
    let as_written = match ordered {
        Some(ordered) => match through_spirv::compile(files, ordered, dialect, &program.plan) {
            Ok(stages) => Some(stages),
            Err(why) => {
                debug(&why.message);
                refused = why.construct;
                None
            }
        },
        None => None,
    };
    if let Some(stages) = as_written {
        for (stage, spirv) in program.stages.iter_mut().zip(stages) {
            debug_assert_eq!(stage.syntax.stage, spirv.kind);
            let len = spirv.text.len();
            stage.rewritten = Some(Rewritten { text: spirv.text, map: OffsetMap::identity(len), limitation: None });
            stage.naga = Some(spirv.validated);
        }
    } else {
        let Some(texts) =
            program.stages.iter().map(|s| Some((s.rewritten.as_ref()?.text.as_str(), s.syntax.stage))).collect::<Option<Vec<_>>>()
        else {
            return name_what_stopped_the_route(program, refused, diags);
        };
        let originals: Vec<&str> = program.stages.iter().map(|s| files.text(s.syntax.file)).collect();
        let validated = match through_spirv::compile_rewritten(&texts, &program.plan, dialect, &originals) {
            Ok(v) => v,
            Err(why) => {
                debug(&format!("from the rewrite: {why}"));
                // Spans index the rewritten text: moved to the user's file.
                let from_rewrite = why.construct.and_then(|(kind, mut limit)| {
                    let map = &program.stages.iter().find(|s| s.syntax.stage == kind)?.rewritten.as_ref()?.map;
                    limit.span = limit.span.map(|r| map.to_original(r.start)..map.to_original(r.end));
                    Some((kind, limit))
                });
                return name_what_stopped_the_route(program, from_rewrite.or(refused), diags);
            }
        };
        for (stage, v) in program.stages.iter_mut().zip(validated) {
            stage.naga = Some(restore_member_names(v, &program.plan.renamed_members));
        }
    }
    for stage in &mut program.stages {
        stage.limitation = None;
        stage.through_spirv = true;
    }
    let files_of: Vec<FileId> = program.stages.iter().map(|s| s.syntax.file).collect();
    diags.retain(|d| !(d.code == Code::NagaCannotTake && d.file.is_some_and(|f| files_of.contains(&f))));
}

/// Where naga's SPIR-V front refused a construct of a stage (the route that takes the most
/// stopped there), that construct is what the stage's limitation (E0306 in `translate`)
/// and its note N0102 name, not what stopped naga's GLSL front first.
fn name_what_stopped_the_route(program: &mut CompiledProgram, refused: Option<(StageKind, Limitation)>, diags: &mut Vec<Diagnostic>) {
    let Some((kind, limit)) = refused else { return };
    if let Some(stage) = program.stages.iter_mut().find(|s| s.syntax.stage == kind) {
        let file = stage.syntax.file;
        diags.retain(|d| !(d.code == Code::NagaCannotTake && d.file == Some(file)));
        diags.push(limit_note(&limit, &stage.syntax));
        stage.limitation = Some(limit);
    }
}

/// The stages with every repeated stage's files replaced by their joined text
/// ([`units`](crate::front::units)); `None` when one was not joined.
fn joined_stages(files: &Files, ordered: &[(FileId, StageKind)]) -> Option<Vec<(FileId, StageKind)>> {
    let mut out: Vec<(FileId, StageKind)> = Vec::new();
    for &(f, kind) in ordered {
        if out.iter().any(|(_, k)| *k == kind) {
            continue;
        }
        let units: Vec<FileId> = ordered.iter().filter(|(_, k)| *k == kind).map(|(u, _)| *u).collect();
        out.push(if units.len() > 1 { (files.joined(&units)?, kind) } else { (f, kind) });
    }
    Some(out)
}

/// A program with a stage made of several shader objects: glslang compiles each and links
/// them as GL does; effectc's own analysis reads one file per stage, so a legal program is
/// checked by glslang only (note N0106; translate names why it stops).
fn units_judged_by_glslang(
    files: &Files,
    ordered: &[(FileId, StageKind)],
    kind: StageKind,
    judgement: Option<reference::Judgement>,
) -> Vec<Diagnostic> {
    let first = ordered.iter().find(|(_, k)| *k == kind).map(|(f, _)| *f).expect("a repeated stage");
    let count = ordered.iter().filter(|(_, k)| *k == kind).count();
    let names: Vec<String> =
        ordered.iter().filter(|(_, k)| *k == kind).map(|(f, _)| format!("`{}`", files.path(*f).rsplit('/').next().unwrap_or(""))).collect();
    let note = Diagnostic::new(
        Code::ReferenceOnly,
        format!("the {kind} stage is made of {count} shader objects ({}), linked by the reference compiler", names.join(", ")),
    )
    .in_file(first)
    .with_note("GL links several shader objects into one stage; effectc's own analysis (interface rules, hazards, translation) reads one file per stage, so this program is checked by glslang only")
    .with_help("to translate or render it, join the files into one (`#include` the helpers into the file with `main`)");
    verdict_or(judgement, note)
}

/// glslang's verdict on a program effectc's own analysis does not read: its errors (the
/// stages', else the link's), or `note` (N0106) when it accepts; E0105 when glslang could
/// not be set up, since nothing else judges the program.
fn verdict_or(judgement: Option<reference::Judgement>, note: Diagnostic) -> Vec<Diagnostic> {
    let Some(judgement) = judgement else {
        let mut d = Diagnostic::new(Code::ReferenceRejects, format!("{}, and the reference compiler could not be set up", note.message));
        d.file = note.file;
        return vec![d];
    };
    let mut out: Vec<Diagnostic> = judgement.stages.iter().flat_map(|v| v.errors.iter().cloned()).collect();
    if out.is_empty() {
        out.extend(judgement.link_errors.iter().cloned());
    }
    if out.is_empty() {
        out.push(note);
    }
    out
}

/// Merges effectc's own findings with glslang's verdict, stage by stage. In a stage glslang
/// accepts, an error from effectc's syntax analysis or from naga becomes a note (effectc's
/// or naga's limit: the stage is checked by glslang and not translated). In a stage glslang
/// rejects, glslang's errors are the stage's, except on a line where effectc's parser or
/// naga reports the same problem (effectc's message, with its labels, is shown there); an
/// error of effectc's parser or naga on a line glslang does not name is its own limit and
/// is dropped. effectc's own rules (`--strict`, a missing `main`) stay errors either way.
/// Also returns, per stage file, what naga refused in a stage glslang accepts (translate
/// names it).
fn accept_what_glslang_accepts(
    files: &Files,
    judgement: &reference::Judgement,
    own: Vec<Diagnostic>,
) -> (Vec<Diagnostic>, Vec<(FileId, Limitation)>) {
    let line_of = |d: &Diagnostic| files.primary_line(d);
    let mut out = Vec::new();
    let mut naga_refused = Vec::new();
    let mut shown_lines = Vec::new();
    for d in own {
        let verdict = d.file.and_then(|f| judgement.stage(f));
        match verdict {
            Some(v) if v.accepted && d.is_error() && limit_of_effectc(d.code) => {
                if let (Some(file), true) = (d.file, is_naga_limit(d.code)) {
                    let construct = format!("a construct naga rejects ({})", d.message);
                    naga_refused.push((file, Limitation { construct, span: d.span.clone() }));
                }
                out.push(as_limitation(d));
            }
            // What naga could not take in a stage glslang rejects says nothing more: the
            // stage is wrong, and its errors are glslang's.
            Some(v) if !v.accepted && d.code == Code::NagaCannotTake => {}
            Some(v) if !v.accepted && d.is_error() && limit_of_effectc(d.code) => {
                let line = line_of(&d);
                // Both refuse the `#version` line: effectc's message says which version.
                // On another line both refuse, effectc's parser and naga's GLSL front say
                // what they expected (`Constructor expects 3 components, found 2`, over the
                // whole constructor); naga's validator speaks of its IR (`The pointer [2]
                // doesn't relate to a valid destination`) and gives way to glslang's words
                // (`l-value required "u"`).
                let same_line = line.is_some() && v.errors.iter().any(|g| line_of(g) == line);
                // glsl-lang's lexer's "invalid token" (a reserved word such as `filter`)
                // names nothing: glslang's words do (`'sample' : Reserved word`).
                let says_what = !(d.code == Code::SyntaxError && d.message.ends_with("invalid token"));
                if d.code == Code::BadVersion || (same_line && says_what && !matches!(d.code, Code::NagaValidation | Code::NagaCrashed)) {
                    shown_lines.extend(line);
                    out.push(d);
                }
            }
            _ => out.push(d),
        }
    }
    for v in judgement.stages.iter().filter(|v| !v.accepted) {
        let version_shown = out.iter().any(|d| d.code == Code::BadVersion && d.file == Some(v.file));
        let placed = |g: &&Diagnostic| match line_of(g) {
            Some(l) => !shown_lines.contains(&l),
            None => !version_shown,
        };
        out.extend(v.errors.iter().filter(placed).cloned());
    }
    (out, naga_refused)
}

/// Errors that come from what effectc's parser or naga can read, not from a GLSL rule
/// effectc enforces on purpose.
fn limit_of_effectc(code: Code) -> bool {
    matches!(
        code,
        Code::BadVersion
            | Code::SyntaxError
            | Code::NonConstantSamplerIndex
            | Code::NonConstantFragDataIndex
            | Code::NagaParse
            | Code::NagaValidation
            | Code::NagaCrashed
    )
}

/// Errors where naga, not effectc's parser, could not take the stage.
fn is_naga_limit(code: Code) -> bool {
    matches!(
        code,
        Code::NagaParse | Code::NagaValidation | Code::NagaCrashed | Code::NonConstantSamplerIndex | Code::NonConstantFragDataIndex
    )
}

/// An error of effectc's parser or naga in a stage glslang accepts, as the note it is.
fn as_limitation(d: Diagnostic) -> Diagnostic {
    let (code, what) = if is_naga_limit(d.code) {
        (Code::NagaCannotTake, "naga cannot take this stage")
    } else {
        (Code::ReferenceOnly, "effectc's own analysis cannot read this stage")
    };
    let mut n = Diagnostic::new(code, format!("{what}: {}", d.message));
    n.file = d.file;
    n.span = d.span;
    n.primary_label = d.primary_label;
    n.labels = d.labels;
    n.notes = d.notes;
    n.with_note("the reference compiler (glslang) accepts the stage: it is legal GLSL, checked by glslang")
        .with_note("`effectc translate` cannot translate this stage until effectc reads it")
}

/// effectc's own analysis of the program: syntax facts, the shared plan, the 4.50 rewrite
/// and naga.
fn compile_own(
    files: &Files,
    ordered: &[(FileId, StageKind)],
    options: FrontOptions,
    diags: &mut Vec<Diagnostic>,
) -> Option<CompiledProgram> {
    let mut syntaxes = Vec::new();
    let mut ok = true;
    for (file, kind) in ordered {
        match syntax::analyse(*file, files.text(*file), *kind, options.env) {
            Ok(s) => syntaxes.push(s),
            Err(errs) => {
                diags.extend(errs);
                ok = false;
            }
        }
    }
    if !ok {
        return None;
    }
    let beyond: Vec<Diagnostic> = syntaxes.iter().filter_map(|s| limits::check_globals(s, &options.limits)).collect();
    if !beyond.is_empty() {
        diags.extend(beyond);
        return None;
    }
    diags.extend(syntaxes.iter().filter(|s| !s.has_main).map(no_main));
    let sized_members = plan::size_implicit_block_members(&mut syntaxes);
    let plan = plan::plan(&syntaxes, options.doubles_as_floats).with_sized_members(sized_members);
    let mut compiled = Vec::new();
    let lower = |s: &StageSyntax, r: &mut Rewritten| if options.doubles_as_floats { doubles_in(s, r) } else { None };
    for s in syntaxes {
        let Some(naga_stage) = s.stage.naga() else {
            if s.stage != StageKind::Geometry {
                diags.push(
                    Diagnostic::new(
                        Code::SyntaxAndInterfaceOnly,
                        format!("the {} stage is checked for syntax and interface only", s.stage),
                    )
                    .in_file(s.file)
                    .with_note("naga and WGSL have no tessellation stages, so it is not validated by naga"),
                );
            }
            // Geometry and tessellation stages are rewritten to 4.50 like the others (the
            // shared uniform block, the plan's locations, sampler splits): the texts the
            // folds start from.
            let rewritten = {
                let (mut rewritten, rdiags) = rewrite::rewrite(&s, &plan, options.strict);
                diags.extend(rdiags);
                // Its doubles are taken as floats too, as the other stages'.
                if let Some(at) = lower(&s, &mut rewritten) {
                    diags.push(doubles_as_floats(&s, at));
                }
                dump_rewrite(files, &s, &rewritten);
                Some(rewritten)
            };
            compiled.push(CompiledStage { syntax: s, rewritten, naga: None, limitation: None, through_spirv: false });
            continue;
        };
        let (mut rewritten, mut rdiags) = rewrite::rewrite(&s, &plan, options.strict);
        let mut lowered = lower(&s, &mut rewritten);
        let oversized = oversized_function(&s, files.text(s.file));
        let run = |rewritten: &Rewritten, rdiags: &[Diagnostic]| match &rewritten.limitation {
            _ if rdiags.iter().any(Diagnostic::is_error) || !s.has_main => None,
            Some(limit) => Some(Outcome::Limited(limit.clone())),
            None if oversized.is_some() => oversized.clone().map(Outcome::Limited),
            None => Some(naga_run::parse_and_validate(s.file, rewritten, naga_stage, &s.version)),
        };
        let mut outcome = run(&rewritten, &rdiags);
        if allows_scalar_swizzle(&s) {
            // GLSL 4.20 swizzles scalars (`x.rrr`); naga does not. Its "can't lookup field"
            // on a swizzle-shaped access tells which bases are scalars: rewrite those as
            // constructors and parse again.
            let mut scalar: Vec<usize> = Vec::new();
            for _ in 0..8 {
                let Some(Outcome::Invalid(errors)) = &outcome else { break };
                let new: Vec<usize> = naga_run::scalar_swizzles(&s, errors).into_iter().filter(|i| !scalar.contains(i)).collect();
                if new.is_empty() {
                    break;
                }
                scalar.extend(new);
                (rewritten, rdiags) = rewrite::rewrite_with(&s, &plan, options.strict, &scalar);
                lowered = lower(&s, &mut rewritten);
                outcome = run(&rewritten, &rdiags);
            }
        }
        dump_rewrite(files, &s, &rewritten);
        diags.extend(rdiags);
        if let Some(at) = lowered {
            diags.push(doubles_as_floats(&s, at));
        }
        let (naga, limitation) = match outcome {
            Some(outcome) => module_or_limit(outcome, &s, &plan, diags),
            None => (None, None),
        };
        compiled.push(CompiledStage { syntax: s, rewritten: Some(rewritten), naga, limitation, through_spirv: false });
    }
    Some(CompiledProgram { stages: compiled, plan, folded: None, reference: None })
}

/// Note N0102: naga cannot take `limit` in stage `s`.
fn limit_note(limit: &Limitation, s: &StageSyntax) -> Diagnostic {
    let d = Diagnostic::new(
        Code::NagaCannotTake,
        format!("naga cannot take {}, so the {} stage is checked for syntax and interface only", limit.construct, s.stage),
    );
    match &limit.span {
        Some(span) => d.at(s.file, span.clone(), "legal GLSL naga does not take"),
        None => d.in_file(s.file),
    }
    .with_note("`effectc translate` cannot translate this stage until naga takes it")
}

/// What naga made of a stage: its module (struct and array varyings' qualifiers back, the
/// user's member names), or the limit it hit (N0102 said where), or its errors (`diags`).
fn module_or_limit(outcome: Outcome, s: &StageSyntax, plan: &Plan, diags: &mut Vec<Diagnostic>) -> (Option<Validated>, Option<Limitation>) {
    match outcome {
        Outcome::Valid(mut v) => {
            aggregate_varyings::qualify(&mut v.module, s, plan);
            (Some(restore_member_names(v, &plan.renamed_members)), None)
        }
        Outcome::Limited(limit) => {
            diags.push(limit_note(&limit, s));
            (None, Some(limit))
        }
        Outcome::Invalid(errs) => {
            diags.extend(errs);
            (None, None)
        }
    }
}

/// E0103: a stage without `main`.
fn no_main(s: &StageSyntax) -> Diagnostic {
    Diagnostic::new(Code::NoMain, format!("the {} stage has no `main` function", s.stage))
        .in_file(s.file)
        .with_note("every stage of a GL program needs `void main()`")
}

/// Bytes of one function body beyond which naga's GLSL front is not used.
///
/// naga's GLSL front types each new expression by walking the function's expressions from
/// the start again (`Typifier::grow` skips through an iterator), so its time grows with the
/// square of a function's size: a 100,000-statement `main` took 45 s where glslang takes
/// under a second. Such a stage goes through glslang's SPIR-V and naga's SPIR-V front
/// instead ([`through_spirv`]), which is linear. 128 KiB (~6,000 statements) keeps naga's
/// share under ~0.2 s; real functions are far smaller.
pub const NAGA_GLSL_FUNCTION_BYTES: usize = 128 << 10;

/// The largest function of `s` (whose text is `text`) when it is over [`NAGA_GLSL_FUNCTION_BYTES`], as what naga
/// cannot take (within reason) and where.
fn oversized_function(s: &StageSyntax, text: &str) -> Option<Limitation> {
    let f = s.functions.iter().filter(|f| f.is_definition).max_by_key(|f| f.span.len())?;
    // The label covers the header, up to the body's `{`.
    let header = text.get(f.span.clone()).and_then(|t| t.find('{')).unwrap_or(1);
    (f.span.len() > NAGA_GLSL_FUNCTION_BYTES).then(|| Limitation {
        construct: format!(
            "`{}` in reasonable time: its {} KiB body is past {} KiB, where naga's GLSL front slows with the square of a function's size",
            f.name,
            f.span.len() >> 10,
            NAGA_GLSL_FUNCTION_BYTES >> 10
        ),
        span: Some(f.span.start..f.span.start + header),
    })
}

/// The user's names back on block members the rewrite renamed for naga's GLSL front
/// ([`Plan::renamed_members`](plan::Plan::renamed_members)): WGSL, reflection and the values
/// set by name see the names the user wrote.
fn restore_member_names(mut validated: naga_run::Validated, renamed: &[(String, String, String)]) -> naga_run::Validated {
    if renamed.is_empty() {
        return validated;
    }
    let module = &mut validated.module;
    let handles: Vec<_> = module.types.iter().map(|(h, _)| h).collect();
    for h in handles {
        let ty = &module.types[h];
        let Some(block) = ty.name.clone() else { continue };
        let naga::TypeInner::Struct { members, span } = &ty.inner else { continue };
        let mut members = members.clone();
        let mut changed = false;
        for m in &mut members {
            if let Some((_, user, _)) = renamed.iter().find(|(b, _, new)| *b == block && m.name.as_deref() == Some(new.as_str())) {
                m.name = Some(user.clone());
                changed = true;
            }
        }
        if changed {
            let inner = naga::TypeInner::Struct { members, span: *span };
            module.types.replace(h, naga::Type { name: Some(block), inner });
        }
    }
    validated
}

/// Takes the rewritten stage's doubles as floats ([`doubles`](crate::front::doubles)); where
/// W0131 points: the first double the stage's own text writes (a uniform's declaration moves
/// into the shared block). A stage that writes none gets none: the shared block's doubles
/// are reported in the stage that declares them.
fn doubles_in(s: &StageSyntax, r: &mut Rewritten) -> Option<Range<usize>> {
    if crate::front::doubles::as_floats(&mut r.text).is_empty() {
        return None;
    }
    crate::front::doubles::as_floats(&mut s.text.clone()).first().cloned()
}

/// W0131 at the first double the stage takes as a float ([`doubles`](crate::front::doubles)).
fn doubles_as_floats(s: &StageSyntax, at: Range<usize>) -> Diagnostic {
    Diagnostic::new(Code::DoublesAsFloats, format!("the {} stage's 64-bit floats are taken as 32-bit ones", s.stage))
        .at(s.file, at, "a 32-bit float here")
        .with_note(
            "WebGPU (WGSL), MSL and GLSL ES have no 64-bit floats: the program is drawn and translated at f32 precision (`effectc verify` shows where that differs from GL)",
        )
        .with_help("`effectc translate --to spv,spvasm,hlsl` (only targets with 64-bit floats) keeps the doubles")
}

/// Debugging aid: with `EFFECTC_DUMP_REWRITE=DIR`, the 4.50 text of each stage is written
/// to DIR under the stage file's name.
fn dump_rewrite(files: &Files, s: &StageSyntax, rewritten: &Rewritten) {
    if let Some(dir) = std::env::var_os("EFFECTC_DUMP_REWRITE") {
        let name = std::path::Path::new(files.path(s.file)).file_name().map(|n| n.to_os_string()).unwrap_or_default();
        let _ = std::fs::write(std::path::Path::new(&dir).join(name), &rewritten.text);
    }
}

/// Scalar swizzles are GLSL 4.20 (and Vulkan GLSL, which is 4.50).
fn allows_scalar_swizzle(s: &StageSyntax) -> bool {
    (!s.version.is_es() && s.version.number >= 420) || s.vulkan
}
