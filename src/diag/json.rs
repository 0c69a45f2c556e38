//! Machine-readable JSON output (`--format json`), schema version 1.

use serde::Serialize;

use super::{count, Diagnostic, Files, Severity, SpanLocation};

#[derive(Serialize)]
struct Report<'a> {
    version: u32,
    diagnostics: Vec<JsonDiagnostic<'a>>,
    summary: Summary,
}

#[derive(Serialize)]
struct JsonDiagnostic<'a> {
    severity: Severity,
    code: &'a str,
    message: &'a str,
    file: Option<&'a str>,
    span: Option<SpanLocation>,
    label: Option<&'a str>,
    labels: Vec<JsonLabel<'a>>,
    notes: &'a [String],
    help: Option<&'a str>,
}

#[derive(Serialize)]
struct JsonLabel<'a> {
    file: &'a str,
    span: SpanLocation,
    message: &'a str,
}

#[derive(Serialize)]
struct Summary {
    errors: usize,
    warnings: usize,
    notes: usize,
}

/// Render diagnostics as one pretty-printed JSON document (ending in a newline), in the
/// order given. Keys always appear in this order:
///
/// ```text
/// {
///   "version": 1,
///   "diagnostics": [
///     {
///       "severity": "error" | "warning" | "note",
///       "code": "E0101",
///       "message": "undeclared identifier `x`",
///       "file": "shaders/a.frag" | null,
///       "span": {
///         "start": 120,       // byte offset into the file as read from disk, inclusive
///         "end": 121,         // byte offset, exclusive
///         "line": 4,          // 1-based line of `start`
///         "column": 3,        // 1-based column of `start`, counted in characters
///         "end_line": 4,      // 1-based line of `end`
///         "end_column": 4     // 1-based column of `end` (just past the last character)
///       } | null,
///       "label": "not declared" | null,
///       "labels": [
///         { "file": "shaders/a.vert", "span": { same fields as above }, "message": "..." }
///       ],
///       "notes": ["..."],
///       "help": "..." | null
///     }
///   ],
///   "summary": { "errors": 1, "warnings": 0, "notes": 0 }
/// }
/// ```
///
/// - `file` is null for problems that concern no single file; `span` is null when there is
///   no file or no position within it. A `\r\n` counts as one line break.
/// - Spans are clamped to the file (and to UTF-8 character boundaries), so `start <= end <=`
///   file length always holds.
/// - `label` is the text attached to the primary span; null when there is none.
/// - `labels` are secondary locations, possibly in other files; empty when there are none.
///   Labels pointing at files unknown to the run are left out.
/// - `summary` counts all diagnostics in the document by severity.
/// - New fields may be added within version 1; removals or changes bump `version`.
pub fn render_json(diags: &[Diagnostic], files: &Files) -> String {
    let diags = &files.resolved(diags)[..];
    let diagnostics = diags
        .iter()
        .map(|d| {
            let file = d.file.and_then(|id| files.try_get(id).map(|f| (id, f.path.as_str())));
            JsonDiagnostic {
                severity: d.severity(),
                code: d.code.as_str(),
                message: &d.message,
                file: file.map(|(_, path)| path),
                span: file.zip(d.span.clone()).and_then(|((id, _), span)| files.span_location(id, span)),
                label: Some(d.primary_label.as_str()).filter(|l| !l.is_empty()),
                labels: d
                    .labels
                    .iter()
                    .filter_map(|l| {
                        Some(JsonLabel {
                            file: &files.try_get(l.file)?.path,
                            span: files.span_location(l.file, l.span.clone())?,
                            message: &l.message,
                        })
                    })
                    .collect(),
                notes: &d.notes,
                help: d.help.as_deref(),
            }
        })
        .collect();
    let report = Report {
        version: 1,
        diagnostics,
        summary: Summary {
            errors: count(diags, Severity::Error),
            warnings: count(diags, Severity::Warning),
            notes: count(diags, Severity::Note),
        },
    };
    let mut out = serde_json::to_string_pretty(&report).expect("JSON serialization of plain data cannot fail");
    out.push('\n');
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diag::Code;
    use serde_json::{json, Value};

    #[test]
    fn json_has_schema_fields_and_values() {
        let mut files = Files::new();
        let vs = files.add("a.vert", "out vec3 c;\n");
        let fs = files.add("a.frag", "in vec4 c;\r\nvoid main() { c2; }\r\n");
        let diags = vec![
            Diagnostic::new(Code::NagaParse, "undeclared identifier `c2`")
                .at(fs, 26..28, "not declared")
                .with_label(vs, 9..10, "did you mean this?")
                .with_note("first note")
                .with_help("rename it"),
            Diagnostic::new(Code::StageExtension, "whole-run warning"),
            Diagnostic::new(Code::SyntaxAndInterfaceOnly, "file note").in_file(vs),
        ];
        let out = render_json(&diags, &files);
        assert!(out.ends_with("}\n"));
        let v: Value = serde_json::from_str(&out).unwrap();
        assert_eq!(
            v,
            json!({
                "version": 1,
                "diagnostics": [
                    {
                        "severity": "error",
                        "code": "E0150",
                        "message": "undeclared identifier `c2`",
                        "file": "a.frag",
                        "span": {"start": 26, "end": 28, "line": 2, "column": 15, "end_line": 2, "end_column": 17},
                        "label": "not declared",
                        "labels": [{
                            "file": "a.vert",
                            "span": {"start": 9, "end": 10, "line": 1, "column": 10, "end_line": 1, "end_column": 11},
                            "message": "did you mean this?"
                        }],
                        "notes": ["first note"],
                        "help": "rename it"
                    },
                    {
                        "severity": "warning", "code": "W0001", "message": "whole-run warning",
                        "file": null, "span": null, "label": null, "labels": [], "notes": [], "help": null
                    },
                    {
                        "severity": "note", "code": "N0101", "message": "file note",
                        "file": "a.vert", "span": null, "label": null, "labels": [], "notes": [], "help": null
                    }
                ],
                "summary": {"errors": 1, "warnings": 1, "notes": 1}
            })
        );
        // Key order is fixed (serde structs, not maps).
        let keys = ["\"severity\"", "\"code\"", "\"message\"", "\"file\"", "\"span\"", "\"label\"", "\"labels\""];
        let positions: Vec<usize> = keys.iter().map(|k| out.find(k).unwrap()).collect();
        assert!(positions.windows(2).all(|w| w[0] < w[1]), "{out}");
        assert!(out.find("\"version\"").unwrap() < out.find("\"diagnostics\"").unwrap());
        assert!(out.find("\"diagnostics\"").unwrap() < out.find("\"summary\"").unwrap());
    }

    #[test]
    #[allow(clippy::reversed_empty_ranges)] // deliberately reversed spans
    fn json_clamps_bad_spans() {
        let mut files = Files::new();
        let id = files.add("a.frag", "ab");
        let d = Diagnostic::new(Code::ManifestSyntax, "x").at(id, 5..1, "").with_label(super::super::FileId(3), 0..1, "gone");
        let v: Value = serde_json::from_str(&render_json(&[d], &files)).unwrap();
        let diag = &v["diagnostics"][0];
        assert_eq!(diag["span"], json!({"start": 2, "end": 2, "line": 1, "column": 3, "end_line": 1, "end_column": 3}));
        assert_eq!(diag["labels"], json!([]));
    }
}
