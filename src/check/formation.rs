//! Which programs a run formed and why: the stage files of each (with the macros defined
//! for them) and the rule that grouped them, for `check --verbose` and JSON (`formed`).
//! A lint that silently checks single stages, or nothing, must be seen doing so.

use crate::inputs::ProgramInput;
use crate::stage::{Define, StageKind};

/// One program as formed.
#[derive(Debug, Clone, serde::Serialize)]
pub struct Formation {
    pub name: String,
    /// The rule that grouped its files, in words.
    pub why: String,
    pub stages: Vec<FormedStage>,
}

/// One stage file of a formed program.
#[derive(Debug, Clone, serde::Serialize)]
pub struct FormedStage {
    pub stage: StageKind,
    pub file: String,
    /// `NAME=VALUE` of each macro defined for it (`--define` first).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub defines: Vec<String>,
}

/// How `input` was formed; `effect` is its manifest once read, `global` the run's
/// `--define`s.
pub fn of(input: &ProgramInput, effect: Option<&crate::manifest::Effect>, global: &[Define]) -> Formation {
    let shown = |own: &[Define]| global.iter().chain(own).map(|(n, v)| format!("{n}={v}")).collect::<Vec<_>>();
    // Named as diagnostics name files (relative to the working directory below it).
    let cwd = std::env::current_dir().ok();
    let shown_path = |p: &std::path::Path| crate::diag::paths::display_path(&p.display().to_string(), cwd.as_deref());
    match input {
        ProgramInput::Manifest(path) => Formation {
            name: shown_path(path),
            why: format!("the stages `{}` lists", shown_path(path)),
            stages: effect
                .map(|e| {
                    e.stages.iter().map(|s| FormedStage { stage: s.kind, file: shown_path(&s.path), defines: shown(&s.defines) }).collect()
                })
                .unwrap_or_default(),
        },
        ProgramInput::Stages { name, files, defines, formed } => Formation {
            // Named after its files' folder, or by `[[program]]`: shown as paths are.
            name: shown_path(std::path::Path::new(name)),
            why: formed.describe(files.len()).to_string(),
            stages: files
                .iter()
                .map(|(file, kind)| {
                    let own = defines.iter().find(|(k, _)| k == kind).map_or(&[][..], |(_, d)| &d[..]);
                    FormedStage { stage: *kind, file: shown_path(file), defines: shown(own) }
                })
                .collect(),
        },
    }
}

/// The formed programs as text (`check --verbose`).
pub fn text(formed: &[Formation]) -> String {
    let mut out = format!("programs formed: {}\n", formed.len());
    for f in formed {
        out.push_str(&format!("  {}: {}\n", f.name, f.why));
        for s in &f.stages {
            let defines = if s.defines.is_empty() { String::new() } else { format!("  (defined: {})", s.defines.join(" ")) };
            out.push_str(&format!("    {:<9} {}{defines}\n", s.stage.name(), s.file));
        }
    }
    out.push('\n');
    out
}
