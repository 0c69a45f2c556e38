//! Spans of expressions that come from a macro, narrowed to the macro's use.
//!
//! naga's preprocessor gives the tokens of a macro's expansion the place of the macro's
//! body, so an expression that starts inside the expansion (`2.0 / D` with `#define D (a -
//! b)`, its divisor `D`) gets a span from the `#define` line down to the use: a label over
//! every line between them. naga's spans inside an expansion are the body's, so the place
//! of the use within its line is not known: such a span is narrowed to the line of the use
//! (`float z = 2.0 / D;`), where the user reads the expression.

use std::ops::Range;

use crate::diag::{Diagnostic, Files};

/// Narrows every label of `diags` that runs from a `#define` line to a later line.
pub fn narrow(files: &Files, diags: &mut [Diagnostic]) {
    for d in diags {
        if let (Some(file), Some(span)) = (d.file, d.span.clone()) {
            if let Some(n) = files.try_get(file).and_then(|f| narrowed(&f.text, span)) {
                d.span = Some(n);
            }
        }
        for l in &mut d.labels {
            if let Some(n) = files.try_get(l.file).and_then(|f| narrowed(&f.text, l.span.clone())) {
                l.span = n;
            }
        }
    }
}

/// `span` of `text` as [`narrow`] leaves it: narrowed to the line of the macro use it ends
/// on, or as it is.
pub fn narrowed_span(text: &str, span: Range<usize>) -> Range<usize> {
    narrowed(text, span.clone()).unwrap_or(span)
}

/// `span` narrowed to the line of the macro use it ends on, when it starts inside a
/// `#define` and ends on a later line; `None` when it needs no narrowing.
fn narrowed(text: &str, span: Range<usize>) -> Option<Range<usize>> {
    let (start, end) = (span.start, span.end.min(text.len()));
    if start >= end || !text.get(start..end)?.contains('\n') {
        return None;
    }
    let line_start = text[..start].rfind('\n').map_or(0, |i| i + 1);
    let line = text[line_start..].trim_start();
    let defines = line.strip_prefix('#').is_some_and(|rest| rest.trim_start().starts_with("define"));
    if !defines {
        return None;
    }
    // naga's spans inside an expansion are the body's, so where in the line the use sits
    // is not known: the whole line of the use is.
    let line_end = text[end..].find('\n').map_or(text.len(), |i| end + i);
    let body_end = line_body_start(text, end).max(text[..line_end].trim_end().len());
    Some(line_body_start(text, end)..body_end)
}

/// Where the text of `at`'s line starts, after its indentation.
fn line_body_start(text: &str, at: usize) -> usize {
    let start = text[..at].rfind('\n').map_or(0, |i| i + 1);
    start + (text[start..at].len() - text[start..at].trim_start().len())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spans_from_a_define_to_a_use_become_the_use() {
        let text = "#define D (a - b)\n#define INV(x) (1.0 / (x))\nvoid main() {\n  float z = 2.0 / D;\n  float w = INV(u - (v));\n}\n";
        let d_body = text.find("(a - b)").unwrap();
        let d_use = text.find("/ D").unwrap() + 2;
        let line = |s: &str| text.find(s).unwrap()..text.find(s).unwrap() + s.len();
        assert_eq!(narrowed(text, d_body..d_use + 1), Some(line("float z = 2.0 / D;")));
        let inv_body = text.find("1.0 /").unwrap();
        let inv_end = text.find("(v))").unwrap() + 2;
        assert_eq!(narrowed(text, inv_body..inv_end), Some(line("float w = INV(u - (v));")));
        // Spans within one line, or not starting in a `#define`, are left alone.
        assert_eq!(narrowed(text, d_body..d_body + 3), None);
        let main = text.find("void").unwrap();
        assert_eq!(narrowed(text, main..d_use + 1), None);
    }
}
