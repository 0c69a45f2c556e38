//! Tests of the link checks, on real GLSL through [`crate::front::syntax::analyse`].

mod effect_uniforms;
mod interface;
mod uniforms;

use std::ops::Range;

pub(super) use crate::diag::Severity;
use crate::diag::{Code, Diagnostic, FileId, Files};
use crate::front::syntax::{analyse, StageSyntax};
use crate::stage::StageKind;

/// Registered stage sources and their syntax facts.
pub(super) struct Program {
    pub files: Files,
    pub stages: Vec<StageSyntax>,
}

impl Program {
    pub fn new(sources: &[(StageKind, &str)]) -> Program {
        let mut files = Files::new();
        let mut stages = Vec::new();
        for (kind, text) in sources {
            let id = files.add(format!("shader.{}", kind.short_name()), *text);
            match analyse(id, text, *kind, crate::config::TargetEnv::Auto) {
                Ok(s) => stages.push(s),
                Err(e) => panic!("{} does not parse: {e:?}", kind.short_name()),
            }
        }
        Program { files, stages }
    }

    pub fn file(&self, kind: StageKind) -> FileId {
        self.stages.iter().find(|s| s.stage == kind).expect("stage").file
    }

    /// The text a span covers.
    pub fn text(&self, file: FileId, span: &Range<usize>) -> &str {
        &self.files.text(file)[span.clone()]
    }

    pub fn interface(&self) -> Vec<Diagnostic> {
        super::check_interface(&self.stages)
    }
}

/// The diagnostics' codes, sorted (for count assertions that name every code).
pub(super) fn codes(diags: &[Diagnostic]) -> Vec<Code> {
    let mut c: Vec<Code> = diags.iter().map(|d| d.code).collect();
    c.sort_unstable();
    c
}

/// The only diagnostic with `code`.
pub(super) fn only(diags: &[Diagnostic], code: Code) -> &Diagnostic {
    let found: Vec<&Diagnostic> = diags.iter().filter(|d| d.code == code).collect();
    assert_eq!(found.len(), 1, "expected one {code}, got {diags:#?}");
    found[0]
}

/// The primary location as (file, covered text).
pub(super) fn primary<'a>(p: &'a Program, d: &Diagnostic) -> (FileId, &'a str) {
    let file = d.file.expect("a primary file");
    (file, p.text(file, d.span.as_ref().expect("a primary span")))
}

/// Texts covered by the labels in `file`.
pub(super) fn label_texts<'a>(p: &'a Program, d: &Diagnostic, file: FileId) -> Vec<&'a str> {
    d.labels.iter().filter(|l| l.file == file).map(|l| p.text(file, &l.span)).collect()
}
