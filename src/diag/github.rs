//! GitHub Actions workflow commands (`::error file=...::message`), which GitHub turns into
//! annotations on the pull request.

use std::fmt::Write as _;

use super::{Diagnostic, Files, Severity};

/// Escape workflow-command message data: `%`, `\r`, `\n`.
fn escape_data(s: &str) -> String {
    s.replace('%', "%25").replace('\r', "%0D").replace('\n', "%0A")
}

/// Escape a workflow-command property value: as message data, plus `:` and `,`.
fn escape_property(s: &str) -> String {
    escape_data(s).replace(':', "%3A").replace(',', "%2C")
}

/// Render diagnostics as GitHub Actions workflow commands, one line each (every line ends
/// with `\n`):
///
/// `::error file=PATH,line=L,col=C,endLine=L2,endColumn=C2,title=CODE::MESSAGE`
///
/// `::warning` for warnings, `::notice` for notes. `file` is left out when the diagnostic has
/// no file, and the position properties when it has no span. Lines and columns are 1-based
/// (columns in characters; `endColumn` is just past the last character). MESSAGE is the
/// message, then one line per secondary label (`PATH:LINE:COL: label`), per note, and
/// `help: ...`, joined by escaped newlines (`%0A`). Escaping follows GitHub's rules: `%`,
/// `\r`, `\n` everywhere, additionally `:` and `,` in property values.
pub fn render_github(diags: &[Diagnostic], files: &Files) -> String {
    let diags = &files.resolved(diags)[..];
    let mut out = String::new();
    for d in diags {
        let command = match d.severity() {
            Severity::Error => "error",
            Severity::Warning => "warning",
            Severity::Note => "notice",
        };
        let mut props = Vec::new();
        if let Some((id, file)) = d.file.and_then(|id| Some((id, files.try_get(id)?))) {
            props.push(format!("file={}", escape_property(&file.path)));
            if let Some(loc) = d.span.clone().and_then(|span| files.span_location(id, span)) {
                props.push(format!("line={}", loc.line));
                props.push(format!("col={}", loc.column));
                props.push(format!("endLine={}", loc.end_line));
                props.push(format!("endColumn={}", loc.end_column));
            }
        }
        props.push(format!("title={}", escape_property(d.code.as_str())));

        let mut lines = vec![d.message.clone()];
        for label in &d.labels {
            if let Some(loc) = files.span_location(label.file, label.span.clone()) {
                let path = files.path(label.file);
                lines.push(format!("{path}:{}:{}: {}", loc.line, loc.column, label.message));
            }
        }
        lines.extend(d.notes.iter().cloned());
        if let Some(help) = &d.help {
            lines.push(format!("help: {help}"));
        }
        let message = lines.iter().map(|l| escape_data(l)).collect::<Vec<_>>().join("%0A");
        let _ = writeln!(out, "::{command} {}::{message}", props.join(","));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diag::Code;

    #[test]
    fn escaping_rules() {
        assert_eq!(escape_data("50%: a,b\r\nc"), "50%25: a,b%0D%0Ac");
        assert_eq!(escape_property("50%: a,b\r\nc"), "50%25%3A a%2Cb%0D%0Ac");
    }

    #[test]
    fn github_commands() {
        let mut files = Files::new();
        let vs = files.add("dir,1/a:b.vert", "out vec3 c;\n");
        let fs = files.add("a.frag", "in vec4 c;\r\nvoid main() {}\r\n");
        let diags = vec![
            Diagnostic::new(Code::BindingConflict, "type mismatch: vec4, vec3\nsecond line 100%")
                .at(fs, 12..16, "here")
                .with_label(vs, 9..10, "declared here")
                .with_note("note one")
                .with_help("fix it"),
            Diagnostic::new(Code::StageExtension, "run-level warning"),
            Diagnostic::new(Code::SyntaxAndInterfaceOnly, "file note").in_file(vs),
        ];
        let out = render_github(&diags, &files);
        let lines: Vec<&str> = out.lines().collect();
        assert_eq!(
            lines,
            [
                "::error file=a.frag,line=2,col=1,endLine=2,endColumn=5,title=E0301::type mismatch: vec4, vec3\
                 %0Asecond line 100%25%0Adir,1/a:b.vert:1:10: declared here%0Anote one%0Ahelp: fix it",
                "::warning title=W0001::run-level warning",
                "::notice file=dir%2C1/a%3Ab.vert,title=N0101::file note",
            ]
        );
        assert!(out.ends_with('\n'));
        assert_eq!(out.matches('\n').count(), 3);
    }
}
