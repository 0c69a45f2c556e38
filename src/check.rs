//! `effectc check`: every program through manifest, front and link; diagnostics collected.
//!
//! One bad program never stops the others. The outcome says whether any input could not
//! be read (exit 2) and holds every diagnostic for the emitters.

use std::path::Path;

use crate::diag::{Diagnostic, FileId, Files};
use crate::front::program::{self, CompiledProgram, FrontOptions};
use crate::inputs::{self, ProgramInput};
use crate::manifest::{self, Effect};
use crate::stage::StageKind;

/// Code for a stage file that is not UTF-8 text.
pub const E_NOT_TEXT: &str = "E0012";

/// The result of checking a set of inputs.
#[derive(Debug, Default)]
pub struct Outcome {
    pub files: Files,
    pub diagnostics: Vec<Diagnostic>,
    pub programs: usize,
    /// Some input could not be read at all (usage / IO: exit code 2).
    pub io_error: bool,
}

/// A checked program, kept for later steps (translate, render).
#[derive(Debug)]
pub struct Checked {
    pub name: String,
    pub effect: Option<Effect>,
    pub program: Option<CompiledProgram>,
    /// Errors were found in this program.
    pub failed: bool,
}

/// Checks every program named by `inputs`.
pub fn check_inputs(inputs: &[std::path::PathBuf], forced: Option<StageKind>, options: FrontOptions) -> (Outcome, Vec<Checked>) {
    let mut out = Outcome::default();
    let (programs, diags) = inputs::collect(inputs, forced);
    out.io_error |= diags.iter().any(|d| d.code == inputs::E_INPUT_IO);
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
            Ok(text) => Some(files.add(path.display().to_string(), text)),
            Err(e) => {
                let valid = e.utf8_error().valid_up_to();
                let text = String::from_utf8_lossy(e.as_bytes()).to_string();
                let id = files.add(path.display().to_string(), text);
                diags.push(
                    Diagnostic::error(E_NOT_TEXT, "this stage file is not UTF-8 text")
                        .at(id, valid..valid + 1, "invalid byte here")
                        .with_note("GLSL sources are text; is this a binary file?"),
                );
                None
            }
        },
        Err(e) => {
            *io_error = true;
            diags.push(Diagnostic::error(inputs::E_INPUT_IO, format!("cannot read `{}`: {e}", path.display())));
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
    match input {
        ProgramInput::Manifest(path) => match manifest::load(path, &mut out.files) {
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
    let mut program = None;
    if readable && !stage_files.is_empty() {
        let mut diags = Vec::new();
        program = program::compile(&out.files, &stage_files, options, &mut diags);
        if let Some(p) = &program {
            let syntaxes: Vec<_> = p.stages.iter().map(|s| s.syntax.clone()).collect();
            diags.extend(crate::link::check_interface(&syntaxes));
            if let Some(e) = &effect {
                diags.extend(crate::link::check_manifest(e, &syntaxes, &out.files));
            }
        }
        out.diagnostics.extend(diags);
    }
    let failed = out.diagnostics[start..].iter().any(Diagnostic::is_error);
    Checked { name: input.display_name(), effect, program, failed }
}
