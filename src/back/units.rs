//! A checked program's translation units: one per single-pass program, one per pass that
//! reaches the output of a multi-pass effect. naga's panics are contained and become
//! diagnostics, like a target writer's errors.

use crate::back::{self, Target, TranslateOptions, Translation};
use crate::check::{Checked, Unit};
use crate::diag::{Code, Diagnostic};

/// The translations of a checked program, each with the directory name its files go to:
/// one for a single-pass program, one per pass that reaches the output for a multi-pass
/// effect (`<effect>.<pass>`, all in the effect's directory). None when check found errors.
pub fn translate_units(c: &Checked, options: TranslateOptions) -> Vec<(Result<Translation, Vec<Diagnostic>>, String)> {
    if let Some(d) = &c.untranslatable {
        return vec![(Err(vec![d.clone()]), c.name.clone())];
    }
    c.running()
        .map(|unit| {
            let mut result = translate_unit(unit, options);
            if let (Ok(t), Some(effect)) = (&mut result, c.multi_pass()) {
                t.reflection.pass = back::reflect::pass_info(effect, unit.pass, c.plan.as_ref());
            }
            let dir = match c.multi_pass() {
                Some(effect) => effect.name.clone(),
                None => result.as_ref().map(|t| t.name.clone()).unwrap_or_default(),
            };
            (result, dir)
        })
        .collect()
}

/// Translates one unit with naga panics contained.
pub fn translate_unit(unit: &Unit, options: TranslateOptions) -> Result<Translation, Vec<Diagnostic>> {
    let file = unit.program.stages[0].syntax.file;
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| back::translate(&unit.name, &unit.program, unit.effect.as_ref(), options)))
        .unwrap_or_else(|_| Err(vec![panicked(file, "translation")]))
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
        Diagnostic::new(Code::TargetCannotExpress, format!("the {} target cannot express this program", target.name()))
            .in_file(file)
            .with_note(message.to_string())
            .with_help("leave this target out of --to, or avoid the feature in the shader")
    } else {
        Diagnostic::new(Code::TranslateInternal, format!("cannot write {}: {message}", target.name()))
            .in_file(file)
            .with_note("this is a gap in naga's backend or a bug in effectc; please report it")
    }
}

fn panicked(file: crate::diag::FileId, what: &str) -> Diagnostic {
    Diagnostic::new(Code::TranslateInternal, format!("naga panicked during {what}"))
        .in_file(file)
        .with_note("this is a bug in naga or effectc; please report it with the input files")
}
