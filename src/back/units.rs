//! A checked program's translation units: one per single-pass program, one per pass that
//! reaches the output of a multi-pass effect. naga's panics are contained and become
//! diagnostics, like a target writer's errors.

use std::path::Path;

use crate::back::{self, Target, TranslateOptions, Translation};
use crate::check::{self, Outcome};
use crate::diag::Diagnostic;

/// The translations of a checked program, each with the directory name its files go to:
/// one for a single-pass program, one per pass that reaches the output for a multi-pass
/// effect (`<effect>.<pass>`, all in the effect's directory). None when check found errors.
pub fn translate_units(
    c: &check::Checked,
    outcome: &Outcome,
    options: TranslateOptions,
) -> Vec<(Result<Translation, Vec<Diagnostic>>, String)> {
    let Some(effect) = c.effect.as_ref().filter(|e| e.is_multi_pass()) else {
        return translate_checked(c, outcome, options)
            .map(|r| {
                let dir = r.as_ref().map(|t| t.name.clone()).unwrap_or_default();
                (r, dir)
            })
            .into_iter()
            .collect();
    };
    if c.failed {
        return Vec::new();
    }
    let plan = crate::graph::plan(effect, (1, 1), false);
    plan.running()
        .filter_map(|i| {
            let pass = &c.passes[i];
            let program = pass.program.as_ref()?;
            Some((translate_program(&pass.view.name, program, Some(&pass.view), options), effect.name.clone()))
        })
        .collect()
}

/// Translates one compiled program with naga panics contained.
pub fn translate_program(
    name: &str,
    program: &crate::front::program::CompiledProgram,
    effect: Option<&crate::manifest::Effect>,
    options: TranslateOptions,
) -> Result<Translation, Vec<Diagnostic>> {
    let file = program.stages[0].syntax.file;
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| back::translate(name, program, effect, options)))
        .unwrap_or_else(|_| Err(vec![panicked(file, "translation")]))
}

/// Translates a checked program; `None` when check found errors in it. naga panics are
/// contained and reported as diagnostics.
pub fn translate_checked(c: &check::Checked, outcome: &Outcome, options: TranslateOptions) -> Option<Result<Translation, Vec<Diagnostic>>> {
    let (false, Some(program)) = (c.failed, &c.program) else { return None };
    let name = c.effect.as_ref().map(|e| e.name.clone()).unwrap_or_else(|| program_name(outcome, program));
    Some(translate_program(&name, program, c.effect.as_ref(), options))
}

/// Emits one target under `catch_unwind` (naga's writers can panic).
pub fn emit_contained(t: &Translation, target: Target) -> Result<Vec<back::Output>, String> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| back::emit(t, target))).unwrap_or_else(|_| Err("naga panicked".into()))
}

/// A target writer failed: the target cannot express the program (E0306), or naga/effectc
/// has a gap (E0305).
pub fn target_error(file: crate::diag::FileId, target: Target, message: &str) -> Diagnostic {
    let unsupported = ["doesn't support", "not supported", "nsupported", "Unimplemented"];
    if unsupported.iter().any(|u| message.contains(u)) {
        Diagnostic::error("E0306", format!("the {} target cannot express this program", target.name()))
            .in_file(file)
            .with_note(message.to_string())
            .with_help("leave this target out of --to, or avoid the feature in the shader")
    } else {
        Diagnostic::error("E0305", format!("cannot write {}: {message}", target.name()))
            .in_file(file)
            .with_note("this is a gap in naga's backend or a bug in effectc; please report it")
    }
}

fn panicked(file: crate::diag::FileId, what: &str) -> Diagnostic {
    Diagnostic::error("E0305", format!("naga panicked during {what}"))
        .in_file(file)
        .with_note("this is a bug in naga or effectc; please report it with the input files")
}

/// The name of a program without a manifest: its first stage file's stem.
fn program_name(outcome: &Outcome, program: &crate::front::program::CompiledProgram) -> String {
    let path = Path::new(outcome.files.path(program.stages[0].syntax.file));
    path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| "effect".into())
}
