//! One GLSL program (the stages of an effect) through the whole front.
//!
//! analyse every stage → plan shared bindings and locations → rewrite each stage to 4.50 →
//! naga parse + validate. Stages naga has no notion of (geometry, tessellation) are checked
//! at the syntax and interface level only, and a note says so.

use crate::diag::{Code, Diagnostic, FileId, Files};
use crate::front::naga_run::{self, Limitation, Outcome, Validated};
use crate::front::plan::{self, Plan};
use crate::front::rewrite::{self, Rewritten};
use crate::front::syntax::{self, StageSyntax};
use crate::stage::StageKind;

/// Options for the front.
#[derive(Debug, Clone, Copy, Default)]
pub struct FrontOptions {
    /// Constructs the declared GLSL version forbids are errors, not warnings.
    pub strict: bool,
}

/// A stage as compiled by the front.
#[derive(Debug)]
pub struct CompiledStage {
    pub syntax: StageSyntax,
    pub rewritten: Option<Rewritten>,
    pub naga: Option<Validated>,
    /// A legal construct naga cannot take (the stage is checked for syntax and interface only).
    pub limitation: Option<Limitation>,
}

/// The front's result for a program: per-stage results, the shared plan, and diagnostics.
#[derive(Debug)]
pub struct CompiledProgram {
    pub stages: Vec<CompiledStage>,
    pub plan: Plan,
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
    let mut syntaxes = Vec::new();
    let mut ok = true;
    for (file, kind) in &ordered {
        match syntax::analyse(*file, files.text(*file), *kind) {
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
    for s in &syntaxes {
        if !s.has_main {
            diags.push(
                Diagnostic::new(Code::NoMain, format!("the {} stage has no `main` function", s.stage))
                    .in_file(s.file)
                    .with_note("every stage of a GL program needs `void main()`"),
            );
        }
    }
    let plan = plan::plan(&syntaxes);
    let mut compiled = Vec::new();
    for s in syntaxes {
        let Some(naga_stage) = s.stage.naga() else {
            diags.push(
                Diagnostic::new(Code::SyntaxAndInterfaceOnly, format!("the {} stage is checked for syntax and interface only", s.stage))
                    .in_file(s.file)
                    .with_note("naga and WGSL have no geometry or tessellation stages, so it is not validated by naga"),
            );
            // A geometry stage is still rewritten to 4.50 (the shared uniform block, the
            // plan's locations, sampler splits): it is what the geometry lowering starts from.
            let rewritten = (s.stage == StageKind::Geometry).then(|| {
                let (rewritten, rdiags) = rewrite::rewrite(&s, &plan, options.strict);
                diags.extend(rdiags);
                dump_rewrite(files, &s, &rewritten);
                rewritten
            });
            compiled.push(CompiledStage { syntax: s, rewritten, naga: None, limitation: None });
            continue;
        };
        let (mut rewritten, mut rdiags) = rewrite::rewrite(&s, &plan, options.strict);
        let run = |rewritten: &Rewritten, rdiags: &[Diagnostic]| match &rewritten.limitation {
            _ if rdiags.iter().any(Diagnostic::is_error) || !s.has_main => None,
            Some(limit) => Some(Outcome::Limited(limit.clone())),
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
                outcome = run(&rewritten, &rdiags);
            }
        }
        dump_rewrite(files, &s, &rewritten);
        diags.extend(rdiags);
        let mut limitation = None;
        let naga = match outcome {
            None => None,
            Some(outcome) => match outcome {
                Outcome::Valid(v) => Some(v),
                Outcome::Limited(limit) => {
                    let d = Diagnostic::new(
                        Code::NagaCannotTake,
                        format!("naga cannot take {}, so the {} stage is checked for syntax and interface only", limit.construct, s.stage),
                    );
                    diags.push(
                        match &limit.span {
                            Some(span) => d.at(s.file, span.clone(), "legal GLSL naga does not take"),
                            None => d.in_file(s.file),
                        }
                        .with_note("`effectc translate` cannot translate this stage until naga takes it"),
                    );
                    limitation = Some(limit);
                    None
                }
                Outcome::Invalid(errs) => {
                    diags.extend(errs);
                    None
                }
            },
        };
        compiled.push(CompiledStage { syntax: s, rewritten: Some(rewritten), naga, limitation });
    }
    Some(CompiledProgram { stages: compiled, plan })
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
