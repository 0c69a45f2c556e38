//! `effectc translate`: check, then translate every clean program and write its targets.
//!
//! A program with check errors is not translated (its diagnostics are the output, exit 1);
//! the others still are. Files are written atomically (temporary file + rename) into the
//! output directory, which is created as needed; a path that is one of the inputs is never
//! written.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use crate::back::{self, Target, TranslateOptions, Translation};
use crate::check::{self, Outcome};
use crate::diag::Diagnostic;
use crate::front::program::FrontOptions;
use crate::stage::StageKind;

/// Code for an output that cannot be written (IO: exit 2).
pub const E_OUTPUT_IO: &str = "E0014";

/// What `translate` was asked to do.
#[derive(Debug, Clone)]
pub struct Request {
    pub inputs: Vec<PathBuf>,
    pub stage: Option<StageKind>,
    pub front: FrontOptions,
    pub back: TranslateOptions,
    pub targets: Vec<Target>,
    /// `None`: `out/<effect>/` for each program.
    pub out: Option<PathBuf>,
}

/// One translated program and the files written for it.
#[derive(Debug)]
pub struct Written {
    pub translation: Translation,
    pub dir: PathBuf,
    pub files: Vec<PathBuf>,
}

/// Runs check and translation; diagnostics of both are in the outcome.
pub fn run(request: &Request) -> (Outcome, Vec<Written>) {
    let (mut outcome, checked) = check::check_inputs(&request.inputs, request.stage, request.front);
    let inputs = input_paths(&outcome, &request.inputs);
    let mut written = Vec::new();
    for c in &checked {
        for (result, dir_name) in translate_units(c, &outcome, request.back) {
            let translation = match result {
                Ok(t) => t,
                Err(diags) => {
                    outcome.diagnostics.extend(diags);
                    continue;
                }
            };
            let file = translation.file;
            let dir = request.out.clone().unwrap_or_else(|| Path::new("out").join(&dir_name));
            let mut files = Vec::new();
            for &target in &request.targets {
                let outputs = match emit_contained(&translation, target) {
                    Ok(o) => o,
                    Err(e) => {
                        outcome.diagnostics.push(target_error(file, target, &e));
                        continue;
                    }
                };
                for o in outputs {
                    let path = dir.join(&o.file_name);
                    match write_atomic(&path, &o.bytes, &inputs) {
                        Ok(()) => files.push(path),
                        Err(e) => {
                            outcome.io_error = true;
                            outcome.diagnostics.push(Diagnostic::error(E_OUTPUT_IO, e));
                        }
                    }
                }
            }
            written.push(Written { translation, dir, files });
        }
    }
    crate::diag::sort(&mut outcome.diagnostics);
    (outcome, written)
}

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

/// Canonical paths of every file the run read.
pub fn input_paths(outcome: &Outcome, inputs: &[PathBuf]) -> BTreeSet<PathBuf> {
    let mut set: BTreeSet<PathBuf> =
        outcome.files.iter().filter_map(|(id, _)| std::fs::canonicalize(outcome.files.path(id)).ok()).collect();
    set.extend(inputs.iter().filter_map(|p| std::fs::canonicalize(p).ok()));
    set
}

/// Writes `bytes` to `path` through a temporary file in the same directory and a rename,
/// so readers never see a half-written file. Refuses to replace an input.
pub fn write_atomic(path: &Path, bytes: &[u8], inputs: &BTreeSet<PathBuf>) -> Result<(), String> {
    let dir = path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
    std::fs::create_dir_all(dir).map_err(|e| format!("cannot create `{}`: {e}", dir.display()))?;
    if let Ok(canonical) = std::fs::canonicalize(path) {
        if inputs.contains(&canonical) {
            return Err(format!("refusing to write `{}`: it is one of the inputs", path.display()));
        }
    }
    let file_name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let tmp = dir.join(format!(".{file_name}.{}.tmp", std::process::id()));
    let result = std::fs::write(&tmp, bytes).and_then(|_| std::fs::rename(&tmp, path));
    if let Err(e) = result {
        let _ = std::fs::remove_file(&tmp);
        return Err(format!("cannot write `{}`: {e}", path.display()));
    }
    Ok(())
}

/// Human summary of one translated program, with `--explain` detail when asked.
pub fn summary(w: &Written, explain: bool) -> String {
    let names: Vec<String> = w.files.iter().map(|f| f.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default()).collect();
    let mut text = format!("translated {} → {}: {}\n", w.translation.name, w.dir.display(), names.join(", "));
    let left = w.translation.left_out();
    if !left.is_empty() {
        if explain {
            text.push_str(&format!("  left out {} item{}:\n", left.len(), if left.len() == 1 { "" } else { "s" }));
            for l in left {
                text.push_str(&format!("    {} `{}`: {}\n", l.kind, l.name, l.reason));
            }
        } else {
            let mut kinds: Vec<&str> = left.iter().map(|l| l.kind).collect();
            kinds.dedup();
            text.push_str(&format!(
                "  left out {} unused item{} ({}); --explain lists them\n",
                left.len(),
                if left.len() == 1 { "" } else { "s" },
                kinds.join(", ")
            ));
        }
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn atomic_write_creates_directories_and_never_replaces_an_input() {
        let dir = std::env::temp_dir().join(format!("effectc-write-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let out = dir.join("a/b/out.wgsl");
        write_atomic(&out, b"first", &BTreeSet::new()).unwrap();
        write_atomic(&out, b"second", &BTreeSet::new()).unwrap();
        assert_eq!(std::fs::read(&out).unwrap(), b"second");
        let inputs: BTreeSet<PathBuf> = [std::fs::canonicalize(&out).unwrap()].into();
        let err = write_atomic(&out, b"third", &inputs).unwrap_err();
        assert!(err.contains("one of the inputs"), "{err}");
        assert_eq!(std::fs::read(&out).unwrap(), b"second");
        let leftovers: Vec<_> = std::fs::read_dir(out.parent().unwrap()).unwrap().collect();
        assert_eq!(leftovers.len(), 1, "no temporary files left behind");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
