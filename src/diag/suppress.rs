//! Silencing diagnostics, line by line and per repository.
//!
//! - Inline: a comment `effectc: allow(W0717, …)` silences those codes on the next line
//!   that is not blank or another suppression (or, after code on the same line, on its own
//!   line); `effectc: allow-file(W0201)` silences them in the whole file. GLSL files take
//!   `//` or `/* */` comments, manifests (`.toml`) `#` comments.
//! - A [`Policy`] (the repository's `effectc.toml`): codes allowed everywhere, codes raised
//!   to errors.
//!
//! Only warnings and notes can be silenced: an error stops the program whatever a comment
//! says. A suppression that names an unknown code, an error, or is malformed is itself a
//! warning (W0004); one that silenced nothing, on a run without errors, too (W0005).

use std::collections::{BTreeMap, HashSet};
use std::ops::Range;

use super::{Code, Diagnostic, FileId, Files, Severity};

/// A repository's policy: codes silenced everywhere and codes raised to errors.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Policy {
    pub allow: Vec<Code>,
    pub deny: Vec<Code>,
    /// Where the policy comes from (named in the note of a raised diagnostic).
    pub origin: String,
}

/// What one directive silences.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Scope {
    /// 1-based line of the directive's file.
    Line(usize),
    File,
}

/// One code of one directive: where it is written and what it covers.
#[derive(Debug, Clone)]
struct Allowance {
    file: FileId,
    span: Range<usize>,
    code: Code,
    scope: Scope,
}

/// `diags` after the inline suppressions in `files` and the `policy`: silenced diagnostics
/// are gone, denied codes are errors, and the suppressions' own warnings are added.
/// `reaches(code)` says whether this command can report `code` at all (a suppression of a
/// code only `render` reports is not unused when `check` runs).
pub fn apply(diags: Vec<Diagnostic>, files: &Files, policy: &Policy, reaches: &dyn Fn(Code) -> bool) -> Vec<Diagnostic> {
    let (allowances, mut problems) = directives(files);
    let mut used = vec![false; allowances.len()];
    let resolved = files.resolved(&diags);
    let by_path: BTreeMap<&str, Vec<usize>> = allowances.iter().enumerate().fold(BTreeMap::new(), |mut m, (i, a)| {
        m.entry(files.path(a.file)).or_insert_with(Vec::new).push(i);
        m
    });
    let had_errors = diags.iter().any(Diagnostic::is_error);
    let mut out = Vec::with_capacity(diags.len());
    for (d, r) in diags.into_iter().zip(resolved) {
        if !d.is_error() {
            if policy.allow.contains(&d.code) {
                continue;
            }
            let candidates = r.file.and_then(|f| by_path.get(files.path(f))).map(Vec::as_slice).unwrap_or(&[]);
            let line = r.file.zip(r.span.clone()).map(|(f, s)| files.line_col(f, s.start).0);
            let covers = |a: &Allowance| a.code == d.code && (a.scope == Scope::File || line.is_some_and(|l| a.scope == Scope::Line(l)));
            let matching: Vec<usize> = candidates.iter().copied().filter(|&i| covers(&allowances[i])).collect();
            if !matching.is_empty() {
                for i in matching {
                    used[i] = true;
                }
                continue;
            }
        }
        out.push(raise(d, policy));
    }
    if !had_errors {
        for (a, used) in allowances.iter().zip(&used) {
            if !used && reaches(a.code) && !policy.allow.contains(&a.code) {
                let place = match a.scope {
                    Scope::Line(l) => format!("line {l}"),
                    Scope::File => "this file".to_string(),
                };
                problems.push(
                    Diagnostic::new(
                        Code::SuppressionUnused,
                        format!("`{}` is allowed here, but {place} has no {} to silence", a.code, a.code),
                    )
                    .at(a.file, a.span.clone(), "silences nothing")
                    .with_help("remove the suppression (or the code from its list)"),
                );
            }
        }
    }
    out.extend(problems);
    out
}

/// Denied codes become errors (with a note saying why).
fn raise(mut d: Diagnostic, policy: &Policy) -> Diagnostic {
    if d.severity() != Severity::Error && policy.deny.contains(&d.code) {
        d.raised = true;
        d.notes.push(format!("{} is raised to an error by `deny` in {}", d.code, policy.origin));
    }
    d
}

/// Every directive in the user's files (each path once; expanded texts skipped), and the
/// warnings about malformed ones.
fn directives(files: &Files) -> (Vec<Allowance>, Vec<Diagnostic>) {
    let mut seen = HashSet::new();
    let mut allowances = Vec::new();
    let mut problems = Vec::new();
    for (id, file) in files.iter() {
        if files.is_expanded(id) || !seen.insert(file.path.as_str()) || !file.text.contains("effectc:") {
            continue;
        }
        let marks: &[&str] = if file.path.ends_with(".toml") { &["#"] } else { &["//", "/*"] };
        scan(id, &file.text, marks, &mut allowances, &mut problems);
    }
    (allowances, problems)
}

/// The directives of one file.
fn scan(file: FileId, text: &str, marks: &[&str], allowances: &mut Vec<Allowance>, problems: &mut Vec<Diagnostic>) {
    let lines: Vec<(usize, &str)> = line_starts(text);
    for (index, &(start, line)) in lines.iter().enumerate() {
        let Some(at) = line.find("effectc:") else { continue };
        let before = line[..at].trim_end();
        let Some(mark) = marks.iter().find(|m| before.ends_with(*m)) else { continue };
        let code_before = !before[..before.len() - mark.len()].trim().is_empty();
        let body_start = at + "effectc:".len();
        let body = &line[body_start..];
        let trimmed = body.trim_start();
        let offset = start + body_start + (body.len() - trimmed.len());
        let (scope, rest) = if let Some(r) = trimmed.strip_prefix("allow-file(") {
            (Scope::File, r)
        } else if let Some(r) = trimmed.strip_prefix("allow(") {
            let target = if code_before { index + 1 } else { next_code_line(&lines, index, marks) };
            (Scope::Line(target), r)
        } else {
            let word_end = trimmed.find(|c: char| c.is_whitespace() || c == '(').unwrap_or(trimmed.len());
            problems.push(
                Diagnostic::new(Code::SuppressionInvalid, format!("unknown suppression `effectc: {}`", &trimmed[..word_end]))
                    .at(file, offset..offset + word_end, "not `allow(…)` or `allow-file(…)`")
                    .with_help("write `effectc: allow(W0717)` for the next line, `effectc: allow-file(W0201)` for the whole file"),
            );
            continue;
        };
        let list_at = offset + (trimmed.len() - rest.len());
        let Some(close) = rest.find(')') else {
            problems.push(Diagnostic::new(Code::SuppressionInvalid, "suppression without a closing `)`").at(
                file,
                offset..offset + trimmed.trim_end().len(),
                "the list of codes is not closed",
            ));
            continue;
        };
        codes(file, &rest[..close], list_at, scope, allowances, problems);
    }
}

/// The codes of one directive's list `list` (at byte `at` of the file).
fn codes(file: FileId, list: &str, at: usize, scope: Scope, allowances: &mut Vec<Allowance>, problems: &mut Vec<Diagnostic>) {
    let mut pos = at;
    if list.trim().is_empty() {
        problems.push(Diagnostic::new(Code::SuppressionInvalid, "suppression names no code").at(
            file,
            at..at,
            "a code such as W0717 goes here",
        ));
    }
    for item in list.split(',') {
        let lead = item.len() - item.trim_start().len();
        let name = item.trim();
        let span = pos + lead..pos + lead + name.len();
        pos += item.len() + 1;
        if name.is_empty() {
            continue;
        }
        match name.parse::<Code>() {
            Ok(code) if code.severity() == Severity::Error => problems.push(
                Diagnostic::new(Code::SuppressionInvalid, format!("`{code}` is an error; errors cannot be allowed"))
                    .at(file, span, "an error")
                    .with_note("an error means the program cannot be translated or drawn as written; fix the code instead"),
            ),
            Ok(code) => allowances.push(Allowance { file, span, code, scope: scope.clone() }),
            Err(_) => problems.push(unknown_code(file, span, name)),
        }
    }
}

/// W0004 for a code that is not one of effectc's, with the nearest one when there is one.
pub fn unknown_code(file: FileId, span: Range<usize>, name: &str) -> Diagnostic {
    let d = Diagnostic::new(Code::SuppressionInvalid, format!("unknown diagnostic code `{name}`")).at(file, span, "not an effectc code");
    match closest_code(name) {
        Some(c) => d.with_help(format!("did you mean `{c}` ({})?", c.title())),
        None => d.with_note("codes are a letter (E, W, N) and four digits; the README's Diagnostics table lists them"),
    }
}

/// The warning or note nearest to `name` (case ignored), if it is close (errors cannot be
/// allowed, so they are never suggested).
fn closest_code(name: &str) -> Option<Code> {
    let upper = name.to_ascii_uppercase();
    Code::ALL
        .iter()
        .copied()
        .filter(|c| c.severity() != Severity::Error)
        .map(|c| {
            let shared = upper.bytes().zip(c.as_str().bytes()).take_while(|(a, b)| a == b).count();
            (strsim::damerau_levenshtein(&upper, c.as_str()), std::cmp::Reverse(shared), c)
        })
        .filter(|(d, _, _)| *d <= 2)
        .min_by_key(|(d, shared, _)| (*d, *shared))
        .map(|(_, _, c)| c)
}

/// `(byte offset, line text without its end)` of every line.
fn line_starts(text: &str) -> Vec<(usize, &str)> {
    let mut out = Vec::new();
    let mut start = 0;
    for line in text.split_inclusive('\n') {
        out.push((start, line.trim_end_matches(['\n', '\r'])));
        start += line.len();
    }
    out
}

/// The 1-based number of the first line after `index` that is neither blank nor only a
/// comment holding another suppression (so suppressions can be stacked).
fn next_code_line(lines: &[(usize, &str)], index: usize, marks: &[&str]) -> usize {
    for (i, (_, line)) in lines.iter().enumerate().skip(index + 1) {
        let t = line.trim_start();
        let directive_only = marks.iter().any(|m| t.starts_with(m)) && t.contains("effectc:");
        if !t.is_empty() && !directive_only {
            return i + 1;
        }
    }
    index + 2
}
