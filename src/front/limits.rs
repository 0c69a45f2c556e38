//! Limits a stage must keep before any compiler reads it (E0107): glslang, glsl-lang, naga
//! and effectc's own walks recurse once per term of a sum and per expanded macro level, so
//! an input far beyond real code would exhaust the stack or memory rather than fail.
//! The values are the run's [`Limits`] (defaults, or `effectc.toml`'s `[limits]`):
//!
//! - one statement of more than `statement-tokens` tokens, macros expanded (a sum of ~100,000 terms;
//!   glslangValidator itself crashes near there, and 10,000 terms are accepted);
//! - a macro that expands to more than `macro-tokens` tokens (`#define A1 A0+A0`,
//!   doubling at each level);
//! - a stage of more than `stage-tokens` tokens, macros expanded: what the compilers read,
//!   and what their memory grows with (0.4–1.4 KB a token);
//! - ([`check_globals`], on the declarations) a uniform or private global array of more than
//!   `array-elements` elements.
//!
//! A statement's and the stage's tokens count each macro as what it expands to. They are
//! counted on the text in one pass, linear in its size.

use std::collections::HashMap;

use crate::diag::{Code, Diagnostic, FileId};
use crate::limits::Limits;

/// The first global of `s` beyond `limits.array_elements`, as an error.
pub fn check_globals(s: &crate::front::syntax::StageSyntax, limits: &Limits) -> Option<Diagnostic> {
    use crate::front::syntax::Storage;
    let most = limits.array_elements;
    s.globals.iter().filter(|g| matches!(g.storage, Storage::Uniform | Storage::Private)).find_map(|g| {
        let elements = g.ty.dims.iter().map(|d| u64::from(d.unwrap_or(1))).fold(1u64, u64::saturating_mul);
        (elements > most).then(|| {
            Diagnostic::new(Code::StageLimit, format!("`{}` has {elements} elements, more than effectc's limit of {most}", g.name))
                .at(s.file, g.name_span.clone(), "declared here")
                .with_note("GL drivers hold a few thousand uniform components per stage (Mesa refuses more when it links); use a storage buffer or a texture for bulk data")
                .with_note(Limits::how_to_raise("array-elements"))
        })
    })
}

/// The first limit the stage `text` (of `file`) breaks, as an error.
pub fn check(file: FileId, text: &str, limits: &Limits) -> Option<Diagnostic> {
    let (most_tokens, most_macro, most_stage) = (limits.statement_tokens, limits.macro_tokens, limits.stage_tokens);
    let mut statement_start = 0;
    let mut count = 0u64;
    let mut stage = 0u64;
    let mut defines: Vec<(String, std::ops::Range<usize>)> = Vec::new();
    let mut bodies: HashMap<String, Vec<String>> = HashMap::new();
    let mut sizes: HashMap<String, u64> = HashMap::new();
    let mut line_start = 0;
    for line in logical_lines(text) {
        let (at, body) = (line_start, line);
        line_start += line.len();
        let trimmed = body.trim_start();
        if let Some(d) = trimmed.strip_prefix('#') {
            if let Some(rest) = d.trim_start().strip_prefix("define") {
                let rest = rest.trim_start();
                let name_len = rest.find(|c: char| !(c.is_alphanumeric() || c == '_')).unwrap_or(rest.len());
                let name = rest[..name_len].to_string();
                let after = &rest[name_len..];
                // A function-like macro's parameters are not part of its body.
                let body_text = if after.starts_with('(') { after.find(')').map_or("", |i| &after[i + 1..]) } else { after };
                let indent = body.len() - trimmed.len();
                bodies.insert(name.clone(), tokens(body_text).map(|(t, _)| t.to_string()).collect());
                sizes.clear();
                defines.push((name, at + indent..at + body.trim_end().len()));
            }
            continue;
        }
        for (token, offset) in tokens(body) {
            // A macro counts as what it expands to: what the compilers will read.
            let weight = if bodies.contains_key(token) { expanded_size(token, &bodies, &mut sizes, &mut Vec::new()) } else { 1 };
            count = count.saturating_add(weight);
            stage = stage.saturating_add(weight);
            // The statement's first 80 bytes, made only when a limit is reported.
            let start = statement_start;
            let here = move || {
                let end = (at + offset + token.len()).min(start + 80).max(start);
                char_floor(text, start)..char_floor(text, end)
            };
            if matches!(token, ";" | "{" | "}") {
                count = 0;
                statement_start = at + offset + 1;
            } else if count > most_tokens {
                return Some(
                    Diagnostic::new(Code::StageLimit, format!("a statement of more than {most_tokens} tokens (its macros expanded)"))
                        .at(file, here(), "this statement")
                        .with_note("effectc refuses expressions this long before compiling them (glslangValidator itself crashes near 100,000 terms); split the sum into several statements")
                        .with_note(Limits::how_to_raise("statement-tokens")),
                );
            }
            if stage > most_stage {
                return Some(
                    Diagnostic::new(
                        Code::StageLimit,
                        format!("the stage expands to more than {most_stage} tokens (its includes inlined, its macros expanded)"),
                    )
                    .at(file, here(), "the limit is passed here")
                    .with_note("each token costs the compilers memory: a stage this large would take more than a gigabyte to check")
                    .with_note(Limits::how_to_raise("stage-tokens")),
                );
            }
        }
    }
    for (name, span) in &defines {
        if expanded_size(name, &bodies, &mut sizes, &mut Vec::new()) > most_macro {
            return Some(
                Diagnostic::new(Code::StageLimit, format!("`{name}` expands to more than {most_macro} tokens"))
                    .at(file, span.clone(), "defined here")
                    .with_note(
                        "each level of this macro repeats the one below it: its expansion grows exponentially, which no compiler can read",
                    )
                    .with_note(Limits::how_to_raise("macro-tokens")),
            );
        }
    }
    None
}

/// Tokens `name` expands to (object-like expansion of its body; memoised in `sizes`,
/// cycles count 1).
fn expanded_size(name: &str, bodies: &HashMap<String, Vec<String>>, sizes: &mut HashMap<String, u64>, open: &mut Vec<String>) -> u64 {
    if let Some(s) = sizes.get(name) {
        return *s;
    }
    let Some(body) = bodies.get(name) else { return 1 };
    if open.iter().any(|o| o == name) {
        return 1;
    }
    open.push(name.to_string());
    let mut total: u64 = 0;
    for t in body {
        let size = if bodies.contains_key(t.as_str()) { expanded_size(t, bodies, sizes, open) } else { 1 };
        total = total.saturating_add(size);
    }
    open.pop();
    sizes.insert(name.to_string(), total);
    total
}

/// Lines with `\`-continuations joined (each piece keeps its bytes, so offsets add up).
fn logical_lines(text: &str) -> impl Iterator<Item = &str> {
    let mut rest = text;
    std::iter::from_fn(move || {
        if rest.is_empty() {
            return None;
        }
        let mut end = 0;
        loop {
            match rest[end..].find('\n') {
                Some(i) => {
                    let nl = end + i;
                    end = nl + 1;
                    if !rest[..nl].trim_end_matches('\r').ends_with('\\') {
                        break;
                    }
                }
                None => {
                    end = rest.len();
                    break;
                }
            }
        }
        let (line, tail) = rest.split_at(end);
        rest = tail;
        Some(line)
    })
}

/// The tokens of a line (words, numbers, single punctuation) with their byte offsets;
/// `//` comments end the line (block comments count as punctuation: close enough for a limit).
fn tokens(line: &str) -> impl Iterator<Item = (&str, usize)> {
    let code = line.find("//").map_or(line, |i| &line[..i]);
    let mut i = 0;
    std::iter::from_fn(move || {
        let rest = &code[i..];
        let skip = rest.len() - rest.trim_start().len();
        i += skip;
        let rest = &code[i..];
        let first = rest.chars().next()?;
        let len = if first.is_alphanumeric() || first == '_' || first == '.' {
            rest.find(|c: char| !(c.is_alphanumeric() || c == '_' || c == '.')).unwrap_or(rest.len())
        } else {
            first.len_utf8()
        };
        let at = i;
        i += len;
        Some((&code[at..at + len], at))
    })
}

fn char_floor(s: &str, mut i: usize) -> usize {
    i = i.min(s.len());
    while !s.is_char_boundary(i) {
        i -= 1;
    }
    i
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_sums_and_doubling_macros_are_refused_and_real_code_is_not() {
        let sum = |n: usize| format!("void main() {{ float x = {}; }}\n", vec!["u"; n].join(" + "));
        assert!(check(FileId(0), &sum(10_000), &Limits::default()).is_none(), "glslang-sized sums pass");
        let d = check(FileId(0), &sum(150_000), &Limits::default()).expect("a 150,000-term sum");
        assert_eq!(d.code, Code::StageLimit);
        let mut macros = String::from("#define A0 u\n");
        for i in 1..=16 {
            macros.push_str(&format!("#define A{i} A{}+A{}\n", i - 1, i - 1));
        }
        assert!(check(FileId(0), &macros, &Limits::default()).is_none(), "2^16 tokens pass");
        macros.push_str("#define A21 A16+A16+A16+A16+A16+A16+A16+A16+A16+A16+A16+A16+A16+A16+A16+A16+A16\n");
        assert!(check(FileId(0), &macros, &Limits::default()).is_some_and(|d| d.message.contains("`A21`")));
        let continued = "#define F(x) \\\n  (x) * \\\n  (x)\nvoid main() { float y = F(2.0); }\n";
        assert!(check(FileId(0), continued, &Limits::default()).is_none());
        // A macro counts as its expansion: a 2^18-term sum written as one word is refused.
        let mut used = String::from("#define A0 u\n");
        for i in 1..=17 {
            used.push_str(&format!("#define A{i} A{}+A{}\n", i - 1, i - 1));
        }
        used.push_str("void main() { float x = A17; }\n");
        let d = check(FileId(0), &used, &Limits::default()).expect("a statement of 2^18 terms");
        assert!(d.message.contains("macros expanded"), "{}", d.message);
        let stage = Limits { stage_tokens: 50, ..Limits::default() };
        let d = check(FileId(0), &sum(30), &stage).expect("a stage past its tokens");
        assert!(d.notes.iter().any(|n| n.contains("`stage-tokens`")), "{d:?}");
        let low = Limits { statement_tokens: 100, ..Limits::default() };
        let d = check(FileId(0), &sum(60), &low).expect("a lowered limit holds");
        assert!(d.message.contains("more than 100 tokens") && d.notes.iter().any(|n| n.contains("`statement-tokens`")), "{d:?}");
    }
}
