//! Diagnostics as plain data, and the emitters that render them.
//!
//! Every problem effectc finds — in a manifest, a GLSL stage, a link between stages — is a
//! [`Diagnostic`]: a stable [`Code`] (whose letter is the severity; every code is listed
//! once, in `diag::code`), a primary location in one of the user's files, secondary labels
//! (possibly in other files), notes and an optional help line. Spans are byte ranges into
//! the *original* text registered in [`Files`]; never into generated code.
//! One set of emitters renders them: human (codespan-reporting), JSON, GitHub workflow
//! commands and SARIF 2.1.0.

use std::ops::Range;

mod code;
mod github;
mod human;
mod json;
pub mod paths;
mod sarif;
pub mod suppress;

pub use code::{Code, UnknownCode};
pub use github::render_github;
pub use human::render_human;
pub use json::render_json;
pub use sarif::render_sarif;

/// How bad a diagnostic is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    Note,
    Warning,
    Error,
}

/// Index of a file registered in [`Files`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct FileId(pub usize);

/// A secondary (or extra primary) span with its own message.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Label {
    pub file: FileId,
    pub span: Range<usize>,
    pub message: String,
}

/// One problem found in the user's input.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Diagnostic {
    /// Stable code such as `E0101` / `W0201`, documented in the README; its letter is the
    /// severity ([`Diagnostic::severity`]).
    pub code: Code,
    /// Primary location: file and byte span (None for whole-run problems).
    pub file: Option<FileId>,
    pub span: Option<Range<usize>>,
    pub message: String,
    /// Message attached to the primary span (may be empty).
    pub primary_label: String,
    pub labels: Vec<Label>,
    pub notes: Vec<String>,
    pub help: Option<String>,
    /// Raised to an error by the repository's policy (`deny` in `effectc.toml`).
    pub raised: bool,
}

impl Diagnostic {
    /// A diagnostic of `code`, with the severity the code's letter gives.
    pub fn new(code: Code, message: impl Into<String>) -> Self {
        Diagnostic {
            code,
            file: None,
            span: None,
            message: message.into(),
            primary_label: String::new(),
            labels: Vec::new(),
            notes: Vec::new(),
            help: None,
            raised: false,
        }
    }
    /// Set the primary location and its label.
    pub fn at(mut self, file: FileId, span: Range<usize>, label: impl Into<String>) -> Self {
        self.file = Some(file);
        self.span = Some(span);
        self.primary_label = label.into();
        self
    }
    /// Set the primary file without a span (e.g. a file that could not be read).
    pub fn in_file(mut self, file: FileId) -> Self {
        self.file = Some(file);
        self
    }
    pub fn with_label(mut self, file: FileId, span: Range<usize>, message: impl Into<String>) -> Self {
        self.labels.push(Label { file, span, message: message.into() });
        self
    }
    pub fn with_note(mut self, note: impl Into<String>) -> Self {
        self.notes.push(note.into());
        self
    }
    pub fn with_help(mut self, help: impl Into<String>) -> Self {
        self.help = Some(help.into());
        self
    }
    /// How bad it is: from the code ([`Code::severity`]), or an error when raised.
    pub fn severity(&self) -> Severity {
        if self.raised {
            return Severity::Error;
        }
        self.code.severity()
    }
    pub fn is_error(&self) -> bool {
        self.severity() == Severity::Error
    }
}

/// One registered source file: the path as the user should see it and its original text.
#[derive(Debug, Clone)]
pub struct SourceFile {
    pub path: String,
    pub text: String,
}

/// A piece of an expanded stage text (a file with its `#include`s inlined): bytes `at` of
/// the expanded text are bytes `start..` of `file`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Segment {
    pub at: Range<usize>,
    pub file: FileId,
    pub start: usize,
}

/// All files diagnostics may point into.
#[derive(Debug, Clone, Default)]
pub struct Files {
    files: Vec<SourceFile>,
    /// Expanded texts (by their id): where each piece came from, and the file they stand for.
    expansions: std::collections::HashMap<FileId, (FileId, Vec<Segment>)>,
    /// Texts effectc wrote (a fixed-function vertex stage), read from no file.
    generated: std::collections::HashSet<FileId>,
    /// Joined texts of several shader objects of one stage: the files, as given.
    joins: std::collections::HashMap<FileId, Vec<FileId>>,
}

impl Files {
    pub fn new() -> Self {
        Self::default()
    }
    /// Registers a file; its path is shown as [`paths::display_path`] makes it (cleaned,
    /// relative to the working directory).
    pub fn add(&mut self, path: impl Into<String>, text: impl Into<String>) -> FileId {
        let path = paths::display_path(&path.into(), std::env::current_dir().ok().as_deref());
        self.files.push(SourceFile { path, text: text.into() });
        FileId(self.files.len() - 1)
    }
    /// Registers the expanded text of `origin` (its `#include`s inlined). The front reads
    /// this id; spans into it are resolved to the files the text came from before they are
    /// shown ([`Files::resolve`]).
    pub fn add_expanded(&mut self, origin: FileId, text: String, segments: Vec<Segment>) -> FileId {
        let path = self.path(origin).to_string();
        let id = self.add(path, text);
        self.expansions.insert(id, (origin, segments));
        id
    }
    /// Registers the text joining the shader objects `units` of one stage
    /// (`front::units`), led by `main` (the file with `main`).
    pub fn add_joined(&mut self, main: FileId, units: &[FileId], text: String, segments: Vec<Segment>) -> FileId {
        let id = self.add_expanded(main, text, segments);
        self.joins.insert(id, units.to_vec());
        id
    }
    /// The shader objects a joined text is made of.
    pub fn units_of(&self, id: FileId) -> Option<&[FileId]> {
        self.joins.get(&id).map(Vec::as_slice)
    }
    /// The joined text of exactly these shader objects (any order).
    pub fn joined(&self, units: &[FileId]) -> Option<FileId> {
        let mut want = units.to_vec();
        want.sort();
        self.joins
            .iter()
            .find(|(_, u)| {
                let mut u = (*u).clone();
                u.sort();
                u == want
            })
            .map(|(id, _)| *id)
    }
    /// Where a span of `id` lies in the user's files: itself, or for an expanded text the
    /// included (or including) file and offset it came from (through every level: a
    /// joined text of files with `#include`s). A span crossing pieces is cut at the end of
    /// the piece it starts in.
    pub fn resolve(&self, id: FileId, span: Option<Range<usize>>) -> (FileId, Option<Range<usize>>) {
        let (file, span) = self.resolve_once(id, span);
        if file != id && self.expansions.contains_key(&file) {
            return self.resolve(file, span);
        }
        (file, span)
    }
    fn resolve_once(&self, id: FileId, span: Option<Range<usize>>) -> (FileId, Option<Range<usize>>) {
        let Some((origin, segments)) = self.expansions.get(&id) else { return (id, span) };
        let Some(span) = span else { return (*origin, None) };
        let seg = segments
            .iter()
            .find(|g| g.at.start <= span.start && span.start < g.at.end)
            .or_else(|| segments.iter().rev().find(|g| g.at.start <= span.start))
            .or(segments.first());
        match seg {
            Some(g) => {
                let start = g.start + span.start.saturating_sub(g.at.start);
                let end = g.start + span.end.min(g.at.end).max(span.start).saturating_sub(g.at.start);
                (g.file, Some(start..end))
            }
            None => (*origin, None),
        }
    }
    /// `diags` with every span resolved to the user's files ([`Files::resolve`]).
    pub fn resolved(&self, diags: &[Diagnostic]) -> Vec<Diagnostic> {
        let mut out = diags.to_vec();
        if self.expansions.is_empty() {
            return out;
        }
        for d in &mut out {
            if let Some(f) = d.file {
                let (file, span) = self.resolve(f, d.span.clone());
                d.file = Some(file);
                d.span = span;
            }
            for l in &mut d.labels {
                let (file, span) = self.resolve(l.file, Some(l.span.clone()));
                l.file = file;
                l.span = span.unwrap_or(0..0);
            }
        }
        out
    }
    /// `id` is an expanded text ([`Files::add_expanded`]), not a file of the user's.
    pub fn is_expanded(&self, id: FileId) -> bool {
        self.expansions.contains_key(&id)
    }
    /// Registers a text effectc wrote, shown under `name` (no file on disk has it).
    pub fn add_generated(&mut self, name: impl Into<String>, text: impl Into<String>) -> FileId {
        self.files.push(SourceFile { path: name.into(), text: text.into() });
        let id = FileId(self.files.len() - 1);
        self.generated.insert(id);
        id
    }
    pub fn is_generated(&self, id: FileId) -> bool {
        self.generated.contains(&id)
    }
    pub fn get(&self, id: FileId) -> &SourceFile {
        &self.files[id.0]
    }
    pub fn path(&self, id: FileId) -> &str {
        &self.files[id.0].path
    }
    pub fn text(&self, id: FileId) -> &str {
        &self.files[id.0].text
    }
    /// Number of registered files.
    pub fn len(&self) -> usize {
        self.files.len()
    }
    pub fn is_empty(&self) -> bool {
        self.files.is_empty()
    }
    /// Like [`Files::get`], but `None` for an id that was not registered here.
    pub fn try_get(&self, id: FileId) -> Option<&SourceFile> {
        self.files.get(id.0)
    }
    pub fn iter(&self) -> impl Iterator<Item = (FileId, &SourceFile)> {
        self.files.iter().enumerate().map(|(i, f)| (FileId(i), f))
    }
    /// 1-based line and column (in characters) of a byte offset. A `\r\n` line end counts
    /// as one line break; offsets past the end clamp to the end.
    /// The file and line of a diagnostic's primary span (None without one).
    pub fn primary_line(&self, d: &Diagnostic) -> Option<(FileId, usize)> {
        let file = d.file?;
        Some((file, self.line_col(file, d.span.as_ref()?.start).0))
    }

    pub fn line_col(&self, id: FileId, offset: usize) -> (usize, usize) {
        let text = &self.files[id.0].text;
        let mut offset = offset.min(text.len());
        while !text.is_char_boundary(offset) {
            offset -= 1;
        }
        let before = &text[..offset];
        let line = before.matches('\n').count() + 1;
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        let col = before[line_start..].chars().count() + 1;
        (line, col)
    }
}

impl Files {
    /// Clamp a byte span so it is safe to slice the file's text with: both ends lie within
    /// the text and on char boundaries (the start rounds down, the end rounds up so a
    /// partially covered character is included), and `start <= end`; an empty or reversed span
    /// becomes empty at the clamped start.
    /// Returns `None` only for an unregistered `id`.
    pub fn clamp_span(&self, id: FileId, span: Range<usize>) -> Option<Range<usize>> {
        let text = &self.try_get(id)?.text;
        let mut start = span.start.min(text.len());
        while !text.is_char_boundary(start) {
            start -= 1;
        }
        // An empty (or reversed) span stays empty at `start`.
        let mut end = if span.end <= span.start { start } else { span.end.clamp(start, text.len()) };
        while !text.is_char_boundary(end) {
            end += 1;
        }
        Some(start..end)
    }

    /// The clamped span (see [`Files::clamp_span`]) with 1-based line/column of both ends
    /// (columns in characters, as [`Files::line_col`]). `None` for an unregistered `id`.
    pub fn span_location(&self, id: FileId, span: Range<usize>) -> Option<SpanLocation> {
        let span = self.clamp_span(id, span)?;
        let (line, column) = self.line_col(id, span.start);
        let (end_line, end_column) = self.line_col(id, span.end);
        Some(SpanLocation { start: span.start, end: span.end, line, column, end_line, end_column })
    }
}

/// A resolved, clamped span: byte offsets plus 1-based line and character column of both
/// ends. The end is exclusive (`end_column` is the column just after the last character).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub struct SpanLocation {
    pub start: usize,
    pub end: usize,
    pub line: usize,
    pub column: usize,
    pub end_line: usize,
    pub end_column: usize,
}

/// `true` if any diagnostic is an error (the run should fail).
pub fn has_errors(diags: &[Diagnostic]) -> bool {
    diags.iter().any(Diagnostic::is_error)
}

/// Keeps the first of each repeated diagnostic, in order (passes sharing a stage file, or
/// a program checked once per pass, would report the same thing once each).
pub fn dedup(diags: &mut Vec<Diagnostic>) {
    let mut seen: Vec<Diagnostic> = Vec::new();
    for d in diags.drain(..) {
        if !seen.contains(&d) {
            seen.push(d);
        }
    }
    *diags = seen;
}

/// Number of diagnostics of the given severity.
pub fn count(diags: &[Diagnostic], severity: Severity) -> usize {
    diags.iter().filter(|d| d.severity() == severity).count()
}

/// Stable sort into reporting order: diagnostics without a file first, then by file id,
/// span start (no span before any span), severity (errors first) and code. Diagnostics
/// equal on all of these keep their relative order.
pub fn sort(diags: &mut [Diagnostic]) {
    diags.sort_by(|a, b| {
        let key = |d: &Diagnostic| (d.file, d.span.as_ref().map(|s| s.start), std::cmp::Reverse(d.severity()), d.code);
        key(a).cmp(&key(b))
    });
}

/// One-line run summary, without a trailing newline:
/// `checked 3 programs: 1 error, 2 warnings` (counts that are zero are left out, notes are
/// listed last, singular/plural follow the count) or `checked 1 program: no problems` when
/// there are no diagnostics at all.
pub fn summary_line(diags: &[Diagnostic], programs: usize) -> String {
    fn plural(n: usize, word: &str) -> String {
        format!("{n} {word}{}", if n == 1 { "" } else { "s" })
    }
    let parts: Vec<String> = [(Severity::Error, "error"), (Severity::Warning, "warning"), (Severity::Note, "note")]
        .into_iter()
        .filter_map(|(sev, word)| match count(diags, sev) {
            0 => None,
            n => Some(plural(n, word)),
        })
        .collect();
    let found = if parts.is_empty() { "no problems".to_string() } else { parts.join(", ") };
    format!("checked {}: {found}", plural(programs, "program"))
}

/// Text shared by the non-human emitters: the message, then each note, then
/// `help: ...`, one per line.
pub(crate) fn full_message(d: &Diagnostic) -> String {
    let mut text = d.message.clone();
    for note in &d.notes {
        text.push('\n');
        text.push_str(note);
    }
    if let Some(help) = &d.help {
        text.push_str("\nhelp: ");
        text.push_str(help);
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    #[allow(clippy::reversed_empty_ranges)] // deliberately reversed spans
    fn clamp_span_handles_out_of_range_and_char_boundaries() {
        let mut files = Files::new();
        let id = files.add("a.glsl", "aé\nb"); // 'é' is bytes 1..3
        assert_eq!(files.clamp_span(id, 2..2), Some(1..1));
        assert_eq!(files.clamp_span(id, 0..2), Some(0..3));
        assert_eq!(files.clamp_span(id, 10..20), Some(5..5));
        assert_eq!(files.clamp_span(id, 4..1), Some(4..4));
        assert_eq!(files.clamp_span(FileId(7), 0..1), None);
        let loc = files.span_location(id, 4..5).unwrap();
        assert_eq!((loc.line, loc.column, loc.end_line, loc.end_column), (2, 1, 2, 2));
    }

    #[test]
    fn summary_line_plurals() {
        let e = Diagnostic::new(Code::ManifestSyntax, "x");
        let w = Diagnostic::new(Code::StageExtension, "y");
        let n = Diagnostic::new(Code::SyntaxAndInterfaceOnly, "z");
        assert_eq!(summary_line(&[], 1), "checked 1 program: no problems");
        assert_eq!(summary_line(&[e.clone(), w.clone(), w.clone()], 3), "checked 3 programs: 1 error, 2 warnings");
        assert_eq!(summary_line(&[e.clone(), e, n], 0), "checked 0 programs: 2 errors, 1 note");
        assert_eq!(summary_line(&[w], 2), "checked 2 programs: 1 warning");
    }

    #[test]
    fn counts_and_has_errors() {
        let diags = vec![
            Diagnostic::new(Code::StageExtension, "a"),
            Diagnostic::new(Code::ManifestSyntax, "b"),
            Diagnostic::new(Code::DefaultOutOfRange, "c"),
        ];
        assert!(has_errors(&diags));
        assert!(!has_errors(&diags[..1]));
        assert_eq!(count(&diags, Severity::Warning), 2);
        assert_eq!(count(&diags, Severity::Error), 1);
        assert_eq!(count(&diags, Severity::Note), 0);
    }

    #[test]
    fn sort_orders_by_file_span_severity_code() {
        let (f0, f1) = (FileId(0), FileId(1));
        let mut diags = vec![
            Diagnostic::new(Code::DefaultOutOfRange, "1").at(f1, 0..1, ""),
            Diagnostic::new(Code::StageExtension, "2").at(f0, 5..6, ""),
            Diagnostic::new(Code::ManifestConflict, "3").at(f0, 5..6, ""),
            Diagnostic::new(Code::UnreadOutput, "8").at(f0, 1..2, ""),
            Diagnostic::new(Code::StageExtension, "4").at(f0, 1..2, ""),
            Diagnostic::new(Code::ManifestSyntax, "5"),
            Diagnostic::new(Code::StageExtension, "6").at(f0, 5..9, ""),
            Diagnostic::new(Code::ManifestIo, "7").in_file(f0),
        ];
        sort(&mut diags);
        let order: Vec<&str> = diags.iter().map(|d| d.message.as_str()).collect();
        // "6" equals "2" on every key and came later: stable; "4" (W0001) before "8" (W0201).
        assert_eq!(order, ["5", "7", "4", "8", "3", "2", "6", "1"]);
    }
}
