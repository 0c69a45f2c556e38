//! glslang's info log as effectc diagnostics: each `ERROR: 0:12:5: 'x' : message` line is
//! placed at the user's line and column (through `#line` directives, and through the
//! inlined-includes map [`Files`] keeps for an expanded stage), glslang's wording kept.

use std::ops::Range;

/// One message of a glslang info log.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Message {
    pub error: bool,
    /// `(source string, line, column)` as glslang counts them (column 0: not given).
    pub at: Option<(i64, i64, i64)>,
    /// glslang's text after the location (`'x' : undeclared identifier`).
    pub text: String,
    /// Lines that continue the message (indented detail under a link error).
    pub detail: Vec<String>,
}

/// The messages of `log`, without glslang's closing count (`1 compilation errors. No code
/// generated.`).
pub fn parse(log: &str) -> Vec<Message> {
    let mut out: Vec<Message> = Vec::new();
    for line in log.lines() {
        let (error, rest) = if let Some(r) = line.strip_prefix("ERROR: ") {
            (true, r)
        } else if let Some(r) = line.strip_prefix("INTERNAL ERROR: ") {
            (true, r)
        } else if let Some(r) = line.strip_prefix("WARNING: ") {
            (false, r)
        } else {
            if let Some(last) = out.last_mut() {
                if !line.trim().is_empty() {
                    last.detail.push(line.trim().to_string());
                }
            }
            continue;
        };
        if is_summary(rest) {
            continue;
        }
        let (at, text) = location(rest);
        let text = tidy(text);
        if text == "compilation terminated" {
            // glslang's parser giving up after the errors already reported.
            continue;
        }
        out.push(Message { error, at, text, detail: Vec::new() });
    }
    out
}

/// glslang's text with its padding taken out: `' const int'` → `'const int'`, runs of
/// spaces → one, and an empty token it names nothing with (`'' : array size must be …`) left
/// out.
fn tidy(text: &str) -> String {
    let quoted: Vec<String> =
        text.split('\'').enumerate().map(|(i, part)| if i % 2 == 1 { part.trim().to_string() } else { part.to_string() }).collect();
    let text = quoted.join("'").split_whitespace().collect::<Vec<_>>().join(" ");
    match text.strip_prefix("'' : ") {
        Some(rest) => rest.to_string(),
        None => text,
    }
}

fn is_summary(rest: &str) -> bool {
    rest.ends_with("compilation errors.  No code generated.") || rest.ends_with("compilation errors. No code generated.")
}

/// `0:12:5: text` → ((0, 12, 5), text); `0:12: text` → ((0, 12, 0), text). A source string
/// named by a `#line L "name"` directive (GL_GOOGLE_cpp_style_line_directive) is numbered by
/// [`string_id`].
fn location(rest: &str) -> (Option<(i64, i64, i64)>, &str) {
    let Some(colon) = rest.find(':') else { return (None, rest) };
    let string = &rest[..colon];
    let string = match string.parse::<i64>() {
        Ok(n) => n,
        Err(_) if !string.is_empty() && !string.contains(' ') => string_id(string),
        Err(_) => return (None, rest),
    };
    let mut fields = vec![string];
    let mut at = colon + 1;
    for _ in 0..2 {
        let Some(c) = rest[at..].find(':') else { break };
        match rest[at..at + c].parse::<i64>() {
            Ok(n) => fields.push(n),
            Err(_) => break,
        }
        at += c + 1;
    }
    match fields.as_slice() {
        [s, l] => (Some((*s, *l, 0)), &rest[at..]),
        [s, l, c] => (Some((*s, *l, *c)), &rest[at..]),
        _ => (None, rest),
    }
}

/// A stable number for a source string glslang names (`"common.inc"`): negative, so it
/// never meets a numbered string.
pub fn string_id(name: &str) -> i64 {
    let name = name.trim_matches('"');
    -1 - name.bytes().fold(0i64, |h, b| (h.wrapping_mul(131).wrapping_add(i64::from(b))) & 0x3fff_ffff_ffff)
}

/// The logical `(source string, line)` glslang gives each physical line of `text`, after
/// the `#line` directives in it. `next_line_rule`: `#line L` numbers the line after it `L`
/// (GLSL ≥ 3.30, ES ≥ 3.00) rather than `L + 1`.
pub struct LineTable {
    starts: Vec<usize>,
    /// The first physical line (index into `starts`) of each logical line.
    first: std::collections::HashMap<(i64, i64), usize>,
    len: usize,
}

impl LineTable {
    pub fn new(text: &str) -> Self {
        let next_line_rule = next_line_rule(text);
        let mut starts = vec![0];
        starts.extend(text.match_indices('\n').map(|(i, _)| i + 1));
        let mut logical = Vec::with_capacity(starts.len());
        let (mut string, mut line) = (0i64, 1i64);
        for (i, &s) in starts.iter().enumerate() {
            logical.push((string, line));
            line += 1;
            let end = starts.get(i + 1).copied().unwrap_or(text.len());
            if let Some((l, st)) = line_directive(&text[s..end]) {
                line = if next_line_rule { l } else { l + 1 };
                if let Some(st) = st {
                    string = st;
                }
            }
        }
        // Looked up once per span of a module: a map, not a search, keeps that linear.
        let mut first = std::collections::HashMap::with_capacity(logical.len());
        for (i, l) in logical.into_iter().enumerate() {
            first.entry(l).or_insert(i);
        }
        LineTable { starts, first, len: text.len() }
    }

    /// The byte range of the physical line glslang calls `(string, line)`.
    pub fn line_range(&self, string: i64, line: i64) -> Option<Range<usize>> {
        let i = *self.first.get(&(string, line))?;
        let end = self.starts.get(i + 1).copied().unwrap_or(self.len);
        Some(self.starts[i]..end)
    }
}

fn next_line_rule(text: &str) -> bool {
    let Some(v) = text.lines().map(str::trim).find(|l| l.starts_with("#") && l[1..].trim_start().starts_with("version")) else {
        return false;
    };
    let rest = v[1..].trim_start()["version".len()..].trim();
    let mut words = rest.split_whitespace();
    let n: i64 = words.next().and_then(|w| w.parse().ok()).unwrap_or(110);
    let es = words.next() == Some("es");
    if es {
        n >= 300
    } else {
        n >= 330
    }
}

fn line_directive(line: &str) -> Option<(i64, Option<i64>)> {
    let t = line.trim_start();
    let t = t.strip_prefix('#')?.trim_start().strip_prefix("line")?;
    if !t.starts_with(|c: char| c.is_whitespace()) {
        return None;
    }
    let mut words = t.split_whitespace();
    let l = words.next()?.parse().ok()?;
    let s = words.next().and_then(|w| w.parse().ok().or_else(|| w.starts_with('"').then(|| string_id(w))));
    Some((l, s))
}

/// The span a message points at on `line` (its byte range in the text): the quoted token
/// glslang names at or after its column, else the word at the column, else the line.
pub fn span_on_line(text: &str, line: Range<usize>, column: i64, message: &str) -> Range<usize> {
    let body = &text[line.clone()];
    let body = &body[..body.trim_end_matches(['\n', '\r']).len()];
    // glslang counts columns in bytes from 1; a byte inside a multi-byte character (a
    // Latin-1 comment read as UTF-8) moves back to the character's start.
    let col = usize::try_from(column - 1).ok().filter(|c| column > 0 && *c <= body.len()).map(|c| char_start(body, c));
    if let Some(token) = quoted(message) {
        let from = col.unwrap_or(0);
        let found = body[from..].find(token).map(|i| from + i).or_else(|| body.find(token));
        if let Some(i) = found {
            return line.start + i..line.start + i + token.len();
        }
    }
    if let Some(c) = col {
        let word = body[c..].find(|ch: char| !(ch.is_alphanumeric() || ch == '_')).unwrap_or(body.len() - c);
        let end = if word == 0 { body[c..].chars().next().map_or(c, |ch| c + ch.len_utf8()) } else { c + word };
        if end > c {
            return line.start + c..line.start + end;
        }
    }
    let indent = body.len() - body.trim_start().len();
    line.start + indent..line.start + body.len()
}

fn char_start(s: &str, mut i: usize) -> usize {
    while !s.is_char_boundary(i) {
        i -= 1;
    }
    i
}

/// The first non-empty `'quoted'` token of a glslang message.
fn quoted(message: &str) -> Option<&str> {
    let start = message.find('\'')? + 1;
    let len = message[start..].find('\'')?;
    Some(&message[start..start + len]).filter(|t| !t.is_empty() && !t.contains(' '))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_locations_and_skips_the_summary() {
        let log = "ERROR: 0:12:5: 'foo' : undeclared identifier \nERROR: 0:3: '' : syntax error\nERROR: 2 compilation errors.  No code generated.\n\n";
        let m = parse(log);
        assert_eq!(m.len(), 2);
        assert_eq!(m[0].at, Some((0, 12, 5)));
        assert_eq!(m[0].text, "'foo' : undeclared identifier");
        assert_eq!(m[1].at, Some((0, 3, 0)));
        assert_eq!(m[1].text, "syntax error", "an empty token is left out");
        let m =
            parse("ERROR: 0:4:13: '=' :  cannot convert from ' const int' to ' temp float'\nERROR: 0:4:16: '' : compilation terminated \n");
        assert_eq!(m.len(), 1);
        assert_eq!(m[0].text, "'=' : cannot convert from 'const int' to 'temp float'");
    }

    #[test]
    fn link_messages_keep_their_detail() {
        let m = parse("ERROR: Linking fragment stage: Missing entry point: Each stage requires one entry point\n    detail line\n");
        assert_eq!(m.len(), 1);
        assert_eq!(m[0].at, None);
        assert_eq!(m[0].detail, vec!["detail line".to_string()]);
    }

    #[test]
    fn line_directives_renumber_by_version() {
        let text = "#version 330\n#line 10 2\nfoo\nbar\n";
        let t = LineTable::new(text);
        assert_eq!(t.line_range(2, 10), Some(24..28));
        let named = "#version 450\n#line 7 \"common.inc\"\nfoo\n";
        let m = parse("ERROR: common.inc:7:2: 'foo' : undeclared identifier\n");
        let (s, l, _) = m[0].at.unwrap();
        assert_eq!(LineTable::new(named).line_range(s, l), Some(34..38));
        let old = "#version 120\n#line 10\nfoo\n";
        let t = LineTable::new(old);
        assert_eq!(t.line_range(0, 11), Some(22..26));
    }

    #[test]
    fn spans_prefer_the_quoted_token() {
        let text = "void main() {\n  x = foo + 1;\n}\n";
        let t = LineTable::new(text);
        let line = t.line_range(0, 2).unwrap();
        let s = span_on_line(text, line.clone(), 7, "'foo' : undeclared identifier");
        assert_eq!(&text[s], "foo");
        let s = span_on_line(text, line, 0, "'' : syntax error");
        assert_eq!(&text[s], "x = foo + 1;");
        let latin = "  v\u{e9}olor = 1;\n";
        let t = LineTable::new(latin);
        let s = span_on_line(latin, t.line_range(0, 1).unwrap(), 5, "'' : syntax error");
        assert!(latin.is_char_boundary(s.start) && latin.is_char_boundary(s.end));
    }
}
