//! Several shader objects linked into one stage (GL links them as one: a single `main`,
//! globals and functions shared by name) joined into one text for effectc's own analysis.
//!
//! The reference compiler still compiles and links the files one by one, as GL does; the
//! joined text is registered like an `#include` expansion ([`Files::add_joined`]), so every
//! span effectc reports in it is shown in the file and line it came from. The join:
//! - each file's conditionals are resolved on their own (GL preprocesses every shader
//!   object apart): inactive groups and the directives are blanked, byte for byte;
//! - the file with `main` goes last (the others define what it calls; its prototypes of
//!   them are legal after the definitions);
//! - one `#version` directive, the first file's (or the first one any file has), at the
//!   top; the others are blanked, byte for byte;
//! - a file-scope declaration a file repeats from an earlier one (`varying vec3 normal;` in
//!   both, which GL links as one variable) is blanked in the later file.

use std::collections::HashSet;

use crate::diag::{FileId, Files, Segment};
use crate::front::conditionals::resolve;
use crate::front::version::{blank_comments, parse_version};

/// Joins `units` (the files of one stage) into one text; returns its id.
pub fn join(files: &mut Files, units: &[FileId]) -> FileId {
    let mut ordered: Vec<FileId> = units.to_vec();
    ordered.sort_by_key(|f| defines_main(files.text(*f)));
    let mut out = String::new();
    let mut segments = Vec::new();
    let directives: Vec<Option<std::ops::Range<usize>>> =
        ordered.iter().map(|f| parse_version(files.text(*f)).ok().and_then(|v| v.directive)).collect();
    // The directive goes first: the first file's own place, or lifted from another file.
    let lifted = match directives.first() {
        Some(Some(_)) => None,
        _ => ordered.iter().zip(&directives).find_map(|(f, d)| d.clone().map(|d| (*f, d))),
    };
    if let Some((file, d)) = &lifted {
        let text = &files.text(*file)[d.clone()];
        segments.push(Segment { at: 0..text.len(), file: *file, start: d.start });
        out.push_str(text);
        out.push('\n');
    }
    let mut seen: HashSet<String> = HashSet::new();
    let mut defined: HashSet<String> = HashSet::new();
    let mut variables: HashSet<String> = HashSet::new();
    for (i, (file, directive)) in ordered.iter().zip(&directives).enumerate() {
        // Each file is preprocessed on its own in GL: its conditionals are resolved here
        // (blanked byte for byte), so neither a guard macro another file defines nor a
        // declaration in an inactive group reaches the joined text.
        let own = files.text(*file);
        let resolved = match parse_version(own) {
            Ok(version) => resolve(own, &blank_comments(own), &version),
            Err(_) => own.to_string(),
        };
        let mut text = resolved.as_bytes().to_vec();
        if let Some(d) = directive.clone().filter(|_| i > 0 || lifted.is_some()) {
            blank(&mut text, d);
        }
        let clean = blank_comments(&resolved);
        for statement in file_scope_statements(&clean) {
            let key = normalised(&clean[statement.clone()]);
            // A prototype of a function an earlier file defines (naga's parser refuses a
            // prototype after the definition), or a declaration repeated from one (also
            // with another array size: `vec4 vals[];` and `vec4 vals[2];` are one variable).
            let defined_before = prototype_name(&key).is_some_and(|n| defined.contains(n));
            let variable = variable_name(&key).map(str::to_string);
            let declared_before = variable.as_ref().is_some_and(|v| variables.contains(v));
            if !seen.insert(key) || defined_before || declared_before {
                blank(&mut text, statement);
            } else if let Some(v) = variable {
                variables.insert(v);
            }
        }
        defined.extend(defined_functions(&clean));
        let start = out.len();
        out.push_str(&String::from_utf8(text).unwrap_or(resolved));
        segments.push(Segment { at: start..out.len(), file: *file, start: 0 });
        out.push('\n');
    }
    let main = *ordered.last().expect("a stage has files");
    files.add_joined(main, units, out, segments)
}

/// Same-length spaces over `range` (line ends kept).
fn blank(text: &mut [u8], range: std::ops::Range<usize>) {
    for b in &mut text[range] {
        if *b != b'\n' {
            *b = b' ';
        }
    }
}

/// Whether `text` (a stage file) defines `main`.
fn defines_main(text: &str) -> bool {
    let clean = blank_comments(text);
    let clean = String::from_utf8_lossy(&clean);
    clean.match_indices("main").any(|(at, _)| {
        let before = clean[..at].trim_end();
        let after = clean[at + 4..].trim_start();
        before.ends_with("void") && after.starts_with('(')
    })
}

/// The spans of file-scope statements ending in `;` (declarations, prototypes), outside
/// function bodies and preprocessor lines, in the comment-blanked text.
fn file_scope_statements(clean: &[u8]) -> Vec<std::ops::Range<usize>> {
    let mut out = Vec::new();
    let (mut depth, mut start, mut i) = (0i32, 0usize, 0usize);
    // Whether the brace open at depth 1 is a function body (a `)` before it): a struct or
    // block body is part of the declaration that ends at its `;`.
    let mut body = false;
    while i < clean.len() {
        let c = clean[i];
        let line_start = i == 0 || clean[i - 1] == b'\n';
        if c == b'#' && (line_start || clean[..i].iter().rev().take_while(|b| **b != b'\n').all(u8::is_ascii_whitespace)) {
            while i < clean.len() && clean[i] != b'\n' {
                i += 1;
            }
            start = i;
            continue;
        }
        match c {
            b'{' => {
                if depth == 0 {
                    body = clean[..i].iter().rev().find(|b| !b.is_ascii_whitespace()) == Some(&b')');
                }
                depth += 1;
            }
            b'}' => {
                depth -= 1;
                if depth == 0 && body {
                    start = i + 1;
                }
            }
            b';' if depth == 0 => {
                out.push(start..i + 1);
                start = i + 1;
            }
            _ => {}
        }
        i += 1;
    }
    out
}

/// The function a file-scope statement declares, when it is a prototype (`vec3 f(int a);`).
fn prototype_name(statement: &str) -> Option<&str> {
    if statement.contains('=') || statement.contains('{') || !statement.trim_end_matches(';').trim_end().ends_with(')') {
        return None;
    }
    let open = statement.find('(')?;
    let name = statement[..open].trim_end().rsplit(|c: char| !c.is_ascii_alphanumeric() && c != '_').next()?;
    (!name.is_empty()).then_some(name)
}

/// The variable a plain file-scope declaration declares (`varying vec4 c;`, `vec4
/// vals[2];`): one name, no initializer, no block or struct body, no function.
fn variable_name(statement: &str) -> Option<&str> {
    if statement.contains(['(', '{', '=', ',']) {
        return None;
    }
    let body = statement.trim_end_matches(';').trim_end();
    let body = body.find('[').map_or(body, |b| body[..b].trim_end());
    let mut words = body.split_whitespace();
    let name = words.next_back()?;
    (words.count() >= 1 && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')).then_some(name)
}

/// Names of the functions `clean` (comment-blanked) defines: `name(…) {` at file scope.
fn defined_functions(clean: &[u8]) -> Vec<String> {
    let text = String::from_utf8_lossy(clean);
    let bytes = text.as_bytes();
    let mut out = Vec::new();
    let mut depth = 0i32;
    for (i, &c) in bytes.iter().enumerate() {
        match c {
            b'{' => {
                if depth == 0 {
                    let head = text[..i].trim_end();
                    if let Some(open) = head.strip_suffix(')').and_then(|h| matching_open(h.as_bytes())) {
                        let name = head[..open].trim_end().rsplit(|c: char| !c.is_ascii_alphanumeric() && c != '_').next().unwrap_or("");
                        if !name.is_empty() {
                            out.push(name.to_string());
                        }
                    }
                }
                depth += 1;
            }
            b'}' => depth -= 1,
            _ => {}
        }
    }
    out
}

/// The offset of the `(` that the `)` just after `text` closes.
fn matching_open(text: &[u8]) -> Option<usize> {
    let mut depth = 1;
    for i in (0..text.len()).rev() {
        match text[i] {
            b')' => depth += 1,
            b'(' => {
                depth -= 1;
                if depth == 0 {
                    return Some(i);
                }
            }
            _ => {}
        }
    }
    None
}

/// A statement with its whitespace collapsed (so `varying  vec3 n;` repeats `varying vec3 n;`).
fn normalised(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).split_whitespace().collect::<Vec<_>>().join(" ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn helpers_first_one_directive_repeated_declarations_once() {
        let mut files = Files::new();
        let main = files.add("a.vert", "#version 120\nvarying vec3 n;\nvec3 f();\nvoid main() { n = f(); gl_Position = vec4(0.0); }\n");
        let helper = files.add("b.vert", "#version 120\nvarying  vec3 n;\nvec3 f() { return gl_Normal; }\n");
        let joined = join(&mut files, &[main, helper]);
        let text = files.text(joined).to_string();
        assert_eq!(text.matches("#version").count(), 1, "{text}");
        assert_eq!(text.matches("varying").count(), 1, "{text}");
        assert!(text.find("return gl_Normal").unwrap() < text.find("void main").unwrap(), "{text}");
        // Spans map back to the file they came from.
        let at = text.find("f() { return").unwrap();
        let (file, span) = files.resolve(joined, Some(at..at + 1));
        assert_eq!(file, helper);
        assert_eq!(&files.text(helper)[span.unwrap()], "f");
        assert_eq!(files.units_of(joined), Some(&[main, helper][..]));
        // One variable declared with and without its size (GL links them as one).
        let sized = files.add("c.vert", "#version 120\nvec4 vals[2];\nvoid set();\nvoid main() { vals[1] = gl_Vertex; set(); }\n");
        let bare = files.add("d.vert", "#version 120\nvec4 vals[];\nvoid set() { gl_Position = vals[1]; }\n");
        let joined = join(&mut files, &[sized, bare]);
        assert_eq!(files.text(joined).matches("vals[").count(), 3, "{}", files.text(joined));
        // Two struct or block declarations end in `};`: each is one statement, so the second
        // keeps its `;`; a struct both files define is kept once.
        let structs = "#version 430\nstruct S { vec3 a; };\nbuffer B { S s[]; };\nvoid f();\n";
        let user = files.add("e.comp", format!("{structs}layout(local_size_x = 1) in;\nvoid main() {{ f(); }}\n"));
        let helper = files.add("f.comp", "#version 430\nstruct S { vec3 a; };\nvoid f() {}\n");
        let joined = join(&mut files, &[user, helper]);
        let text = files.text(joined);
        assert!(text.contains("buffer B { S s[]; };"), "{text}");
        assert_eq!(text.matches("struct S").count(), 1, "{text}");
    }

    /// GL preprocesses each shader object on its own: a guard one file defines does not hide
    /// another file's declarations, and a struct in an inactive group is no earlier definition
    /// of the active one.
    #[test]
    fn each_file_is_preprocessed_on_its_own() {
        let mut files = Files::new();
        let lib = "#ifndef LIGHT\n#define LIGHT\n#if 0\nstruct L { vec2 p; };\n#else\nstruct L { vec4 p; };\n#endif\n#endif\n";
        let main = files.add("a.vert", format!("#version 120\n{lib}vec4 f(L l);\nvoid main() {{ gl_Position = f(L(gl_Vertex)); }}\n"));
        let helper = files.add("b.vert", format!("#version 120\n{lib}vec4 f(L l) {{ return l.p; }}\n"));
        let joined = join(&mut files, &[main, helper]);
        let text = files.text(joined);
        assert_eq!(text.matches("struct L { vec4 p; };").count(), 1, "{text}");
        assert!(!text.contains("vec2 p") && !text.contains("#if"), "inactive groups and directives blanked: {text}");
        assert!(text.contains("vec4 f(L l) { return l.p; }") && text.contains("gl_Position = f(L(gl_Vertex))"), "{text}");
    }
}
