//! Human-readable rendering through codespan-reporting.
//!
//! [`Files`] implements codespan's `Files` trait directly (no copy of the sources), so
//! labels may point into any registered file. Spans are clamped before rendering, so a bad
//! span can never make codespan panic.

use std::borrow::Cow;
use std::ops::Range;

use codespan_reporting::diagnostic as cs;
use codespan_reporting::files::{self as csfiles, line_starts};
use codespan_reporting::term::{self, termcolor::Buffer};

use super::{Diagnostic, FileId, Files, Severity};

impl<'a> csfiles::Files<'a> for Files {
    type FileId = FileId;
    type Name = &'a str;
    type Source = Cow<'a, str>;

    fn name(&'a self, id: FileId) -> Result<&'a str, csfiles::Error> {
        Ok(&self.try_get(id).ok_or(csfiles::Error::FileMissing)?.path)
    }

    /// The original text, except that a lone `\r` (not part of `\r\n`) becomes a space so
    /// it cannot garble the terminal. Byte offsets are unchanged. (The `\r` of `\r\n` is
    /// trimmed by codespan itself together with the `\n`.)
    fn source(&'a self, id: FileId) -> Result<Cow<'a, str>, csfiles::Error> {
        let text = &self.try_get(id).ok_or(csfiles::Error::FileMissing)?.text;
        let lone_cr = |(i, _): &(usize, char)| !text[i + 1..].starts_with('\n');
        if !text.char_indices().filter(|(_, c)| *c == '\r').any(|ic| lone_cr(&ic)) {
            return Ok(Cow::Borrowed(text));
        }
        let mut out = String::with_capacity(text.len());
        for (i, c) in text.char_indices() {
            out.push(if c == '\r' && lone_cr(&(i, c)) { ' ' } else { c });
        }
        Ok(Cow::Owned(out))
    }

    fn line_index(&'a self, id: FileId, byte_index: usize) -> Result<usize, csfiles::Error> {
        let text = &self.try_get(id).ok_or(csfiles::Error::FileMissing)?.text;
        Ok(line_starts(text).take_while(|&start| start <= byte_index).count() - 1)
    }

    fn line_range(&'a self, id: FileId, line_index: usize) -> Result<Range<usize>, csfiles::Error> {
        let text = &self.try_get(id).ok_or(csfiles::Error::FileMissing)?.text;
        let mut starts = line_starts(text).skip(line_index);
        let start = starts.next().ok_or_else(|| csfiles::Error::LineTooLarge { given: line_index, max: line_starts(text).count() - 1 })?;
        Ok(start..starts.next().unwrap_or(text.len()))
    }
}

fn to_codespan(d: &Diagnostic, files: &Files) -> cs::Diagnostic<FileId> {
    let severity = match d.severity() {
        Severity::Error => cs::Severity::Error,
        Severity::Warning => cs::Severity::Warning,
        Severity::Note => cs::Severity::Note,
    };
    let mut labels = Vec::new();
    let mut notes = Vec::new();
    // A label on a line too long to show (a generated or hostile file) becomes a note with
    // its position: the snippet would print the whole line.
    let mut place = |file: FileId, span: Range<usize>, message: &str, primary: bool| match long_line(files, file, &span) {
        Some((line, column, len)) => {
            let path = files.try_get(file).map(|f| f.path.as_str()).unwrap_or("");
            notes.push(format!("{path}:{line}:{column}: {message} (the line is {len} bytes long; not shown)"));
        }
        None if primary => labels.push(cs::Label::primary(file, span).with_message(message)),
        None => labels.push(cs::Label::secondary(file, span).with_message(message)),
    };
    if let (Some(file), Some(span)) = (d.file, &d.span) {
        if let Some(span) = files.clamp_span(file, span.clone()) {
            place(file, span, &d.primary_label, true);
        }
    }
    for label in &d.labels {
        if let Some(span) = files.clamp_span(label.file, label.span.clone()) {
            place(label.file, span, &label.message, false);
        }
    }
    if let (None, Some(f)) = (&d.span, d.file.and_then(|file| files.try_get(file))) {
        notes.insert(0, format!("in {}", f.path));
    }
    notes.extend(d.notes.iter().cloned());
    if let Some(help) = &d.help {
        notes.push(format!("help: {help}"));
    }
    cs::Diagnostic::new(severity).with_code(d.code.as_str()).with_message(&d.message).with_labels(labels).with_notes(notes)
}

/// Longest source line a snippet shows (bytes).
const MAX_SHOWN_LINE: usize = 1_000;

/// The 1-based line and column of `span`'s start and its line's length, when that line (or
/// any line the span covers) is longer than [`MAX_SHOWN_LINE`].
fn long_line(files: &Files, file: FileId, span: &Range<usize>) -> Option<(usize, usize, usize)> {
    let text = &files.try_get(file)?.text;
    let start = span.start.min(text.len());
    let line_start = text[..start].rfind('\n').map_or(0, |i| i + 1);
    let end = span.end.clamp(start, text.len());
    let line_end = text[end..].find('\n').map_or(text.len(), |i| end + i);
    let longest = text[line_start..line_end].split('\n').map(str::len).max().unwrap_or(0);
    (longest > MAX_SHOWN_LINE).then(|| {
        let line = text[..line_start].matches('\n').count() + 1;
        let column = text[line_start..start].chars().count() + 1;
        (line, column, longest)
    })
}

/// Render diagnostics for a terminal, rustc style (`error[E0101]: message`, source
/// snippets with the primary span underlined with `^` and secondary labels with `-`,
/// possibly in other files, then notes and `help: ...`). A diagnostic with a file but no
/// span gets an `in PATH` note instead of a snippet. `color` selects ANSI colors; without it
/// the output is plain text. Each diagnostic ends with a blank line; no diagnostics give "".
/// Labels pointing at unregistered files are left out; spans are clamped to their file.
pub fn render_human(diags: &[Diagnostic], files: &Files, color: bool) -> String {
    let diags = &files.resolved(diags)[..];
    let mut buffer = if color { Buffer::ansi() } else { Buffer::no_color() };
    let config = term::Config::default();
    for d in diags {
        let diagnostic = to_codespan(d, files);
        if term::emit_to_write_style(&mut buffer, &config, files, &diagnostic).is_err() {
            // Cannot happen with clamped spans and known files; never lose the message.
            let fallback = cs::Diagnostic::new(diagnostic.severity)
                .with_code(d.code.as_str())
                .with_message(&d.message)
                .with_notes(diagnostic.notes.clone());
            let _ = term::emit_to_write_style(&mut buffer, &config, files, &fallback);
        }
    }
    String::from_utf8_lossy(buffer.as_slice()).into_owned()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diag::Code;

    #[test]
    fn a_label_on_a_huge_line_is_a_note_not_a_snippet() {
        let mut files = Files::new();
        let long = format!("#version 330\nfloat x = {};\n", "(".repeat(50_000));
        let f = files.add("big.frag", &long);
        let d = Diagnostic::new(Code::SyntaxError, "too deep").at(f, 20_013..20_014, "here");
        let out = render_human(&[d], &files, false);
        assert!(out.len() < 1_000, "{} bytes printed", out.len());
        assert!(out.contains("big.frag:2:20001: here (the line is"), "{out}");
    }

    #[test]
    fn two_file_diagnostic_shows_both_files_and_lines() {
        let mut files = Files::new();
        let vs = files.add("shaders/a.vert", "#version 330\nout vec3 vColor;\n");
        let fs = files.add("shaders/a.frag", "#version 330\n\nin vec4 vColor;\nvoid main() {}\n");
        let d = Diagnostic::new(Code::BindingConflict, "interface mismatch for `vColor`")
            .at(fs, 17..28, "declared as vec4 here")
            .with_label(vs, 17..28, "declared as vec3 here")
            .with_note("outputs and inputs must have the same type")
            .with_help("change one of the declarations");
        let out = render_human(&[d], &files, false);
        assert!(out.starts_with("error[E0301]: interface mismatch for `vColor`\n"), "{out}");
        assert!(out.contains("┌─ shaders/a.frag:3:4"), "{out}");
        assert!(out.contains("┌─ shaders/a.vert:2:5"), "{out}");
        assert!(out.contains("3 │ in vec4 vColor;"), "{out}");
        assert!(out.contains("2 │ out vec3 vColor;"), "{out}");
        assert!(out.contains("^^^^^^^^^^^ declared as vec4 here"), "{out}");
        assert!(out.contains("----------- declared as vec3 here"), "{out}");
        assert!(out.contains("= outputs and inputs must have the same type"), "{out}");
        assert!(out.contains("= help: change one of the declarations"), "{out}");
        assert!(!out.contains('\u{1b}'), "no ANSI escapes without color: {out}");
        let colored = render_human(&[Diagnostic::new(Code::ManifestSyntax, "x")], &files, true);
        assert!(colored.contains('\u{1b}'), "{colored}");
    }

    #[test]
    fn crlf_file_has_right_position_and_no_carriage_returns() {
        let mut files = Files::new();
        let text = "#version 330\r\nuniform float t;\r\nvoid main() {\r\n  x = 1;\r\n}\r\n";
        let id = files.add("a.frag", text);
        let start = text.find("x = 1").unwrap();
        assert_eq!(files.line_col(id, start), (4, 3));
        // One single-line and one multi-line label (which spans the `\r\n`s).
        let m = text.find("void").unwrap();
        let d = Diagnostic::new(Code::NagaParse, "undeclared identifier `x`").at(id, start..start + 1, "not declared").with_label(
            id,
            m..text.len() - 2,
            "in this function",
        );
        let out = render_human(&[d], &files, false);
        assert!(out.contains("┌─ a.frag:4:3"), "{out}");
        assert!(out.contains("4 │ │   x = 1;\n"), "{out}");
        assert!(!out.contains('\r'), "{out:?}");
    }

    #[test]
    fn lone_carriage_return_is_blanked_with_offsets_kept() {
        let mut files = Files::new();
        let id = files.add("a.frag", "int a;\rint b;\n");
        let d = Diagnostic::new(Code::StageExtension, "w").at(id, 7..10, "here");
        let out = render_human(&[d], &files, false);
        assert!(!out.contains('\r'), "{out:?}");
        assert!(out.contains("1 │ int a; int b;\n"), "{out}");
        assert!(out.contains("┌─ a.frag:1:8"), "{out}");
    }

    #[test]
    fn no_file_and_file_without_span() {
        let mut files = Files::new();
        let id = files.add("missing.frag", "");
        let out = render_human(
            &[
                Diagnostic::new(Code::ManifestSyntax, "no effect.toml found").with_help("run in an effect directory"),
                Diagnostic::new(Code::ManifestIo, "cannot read file").in_file(id),
            ],
            &files,
            false,
        );
        assert_eq!(
            out,
            "error[E0001]: no effect.toml found\n = help: run in an effect directory\n\n\
             error[E0002]: cannot read file\n = in missing.frag\n\n"
        );
    }

    #[test]
    #[allow(clippy::reversed_empty_ranges)] // deliberately reversed spans
    fn bad_spans_and_unknown_files_do_not_panic() {
        let mut files = Files::new();
        let id = files.add("a.frag", "é\nvoid main() {}");
        let empty = files.add("empty.frag", "");
        let diags = vec![
            Diagnostic::new(Code::ManifestSyntax, "past the end").at(id, 100..200, "here"),
            Diagnostic::new(Code::ManifestIo, "inside a char").at(id, 1..1, "here"),
            Diagnostic::new(Code::StageFileNotFound, "reversed").at(id, 9..3, "here").with_label(empty, 5..9, "empty file"),
            Diagnostic::new(Code::ManifestUnknownKey, "unknown file").at(FileId(42), 0..1, "x").with_label(FileId(9), 0..1, "y"),
        ];
        let out = render_human(&diags, &files, false);
        for code in ["E0001", "E0002", "E0003", "E0004"] {
            assert!(out.contains(&format!("error[{code}]")), "{out}");
        }
        assert!(out.contains("┌─ a.frag:2:15"), "{out}"); // clamped to the end of the text
        assert!(out.contains("┌─ a.frag:1:1"), "{out}"); // rounded down to the char start
        assert!(out.contains("┌─ empty.frag:1:1"), "{out}");
    }
}
