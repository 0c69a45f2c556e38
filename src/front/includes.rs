//! `#include` (GL_GOOGLE_include_directive, GL_ARB_shading_language_include): included
//! files are inlined into the stage text, resolved relative to the including file.
//!
//! The expanded text is registered in [`Files`] beside the user's files, with a map of the
//! pieces it is made of, so every span the front, the link checks or translate report in it
//! is shown in the file it came from (the stage or an included file, at its own line).
//! Include guards work as written (`#ifndef X`/`#define X` are resolved on the expanded
//! text); `#pragma once` is honoured. A file that includes itself is error E0104 at the
//! directive, unless it is guarded (`#pragma once`, or `#ifndef X`/`#define X` around it),
//! which makes the second inclusion empty; one that cannot be read keeps its directive,
//! which the front reports (E0104) unless conditional compilation leaves it out (`#ifdef
//! __cplusplus` in a shared header).
//!
//! Confinement: an included file must lie inside the stage's project root or a directory
//! its `effectc.toml` makes readable ([`crate::read::project_root`]; `..` and symlinks
//! resolved): one outside them (an absolute
//! path, `/proc/self/environ`, a `..` escape) is E0106 and is never opened. A device, FIFO
//! or directory, or a file over the `file-bytes` limit, is E0104 and is not read; a stage
//! that would grow past that limit with its inclusions inlined is E0107.

use std::collections::HashSet;
use std::path::{Path, PathBuf};

use crate::diag::{Code, Diagnostic, FileId, Files, Segment};
use crate::front::conditionals::include_directives;

/// Deepest include nesting followed.
const MAX_DEPTH: usize = 32;

/// The id the front should read for stage `main` (read from `path`): `main` itself, or its
/// expanded text when it includes files. Errors are pushed to `diags` (then `None`).
pub fn expand(path: &Path, main: FileId, files: &mut Files, file_bytes: u64, diags: &mut Vec<Diagnostic>) -> Option<FileId> {
    let text = files.text(main).to_string();
    if !has_include(&text) {
        return Some(main);
    }
    let mut x = Expansion {
        out: String::new(),
        segments: Vec::new(),
        stack: vec![canonical(path)],
        once: HashSet::new(),
        root: crate::read::project_root(path),
        file_bytes,
        failed: false,
    };
    x.inline(path, main, &text, files, diags);
    if x.failed {
        return None;
    }
    Some(files.add_expanded(main, x.out, x.segments))
}

fn has_include(text: &str) -> bool {
    text.contains("include") && !include_directives(text).is_empty()
}

fn canonical(path: &Path) -> PathBuf {
    std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf())
}

struct Expansion {
    out: String,
    segments: Vec<Segment>,
    /// Files being inlined (cycle detection).
    stack: Vec<PathBuf>,
    /// Files with `#pragma once` or an include guard already inlined.
    once: HashSet<PathBuf>,
    /// Where included files must lie.
    root: crate::read::Root,
    /// The most bytes an included file, and the stage with every inclusion inlined, may hold.
    file_bytes: u64,
    failed: bool,
}

impl Expansion {
    fn copy(&mut self, file: FileId, text: &str, from: usize, to: usize) {
        if to > from {
            self.segments.push(Segment { at: self.out.len()..self.out.len() + (to - from), file, start: from });
            self.out.push_str(&text[from..to]);
        }
    }

    fn inline(&mut self, path: &Path, id: FileId, text: &str, files: &mut Files, diags: &mut Vec<Diagnostic>) {
        let mut copied = 0;
        for (line, name, name_span) in include_directives(text) {
            self.copy(id, text, copied, line.start);
            copied = line.end;
            let target = path.parent().unwrap_or(Path::new(".")).join(&name);
            let key = canonical(&target);
            if !crate::read::confined(&target, &self.root) {
                let d = Diagnostic::new(Code::OutsideRoot, format!("`{name}` lies outside the project root"))
                    .at(id, name_span, "included here")
                    .with_note(crate::read::outside_root_note(&self.root, "stage"));
                self.fail(diags, d);
                continue;
            }
            if self.once.contains(&key) {
                // `#pragma once` or its guard: the second inclusion is empty.
                continue;
            }
            if self.stack.contains(&key) || self.stack.len() > MAX_DEPTH {
                self.fail(
                    diags,
                    Diagnostic::new(Code::IncludeUnresolved, format!("`{name}` includes itself")).at(id, name_span, "included again here"),
                );
                continue;
            }
            let bytes = match crate::read::bounded(&target, self.file_bytes) {
                Ok(bytes) => bytes,
                Err(why @ (crate::read::Refused::NotAFile(_) | crate::read::Refused::TooLarge(_))) => {
                    let d = Diagnostic::new(Code::IncludeUnresolved, format!("`{name}` cannot be included: {why}")).at(
                        id,
                        name_span,
                        "included here",
                    );
                    self.fail(diags, d);
                    continue;
                }
                // Kept as written: inside an inactive `#ifdef __cplusplus` it is blanked
                // with its group; where it is compiled the front reports it (E0104).
                Err(crate::read::Refused::Io(_)) => {
                    self.copy(id, text, line.start, line.end);
                    continue;
                }
            };
            if (self.out.len() + bytes.len()) as u64 > self.file_bytes {
                // Each file is within the limit, but a header included many times (no
                // guard) multiplies: the stage as the compiler would read it is bounded too.
                let d = Diagnostic::new(
                    Code::StageLimit,
                    format!("with `{name}` inlined here the stage grows past effectc's limit of {} bytes", self.file_bytes),
                )
                .at(id, name_span, "included here")
                .with_note(crate::limits::Limits::how_to_raise("file-bytes"));
                self.fail(diags, d);
                return;
            }
            // Bytes outside UTF-8 stand as `?`, one for one ([`source_text`]); outside
            // comments the included text then fails to compile where they stand.
            let included = crate::front::source_text::of(bytes).unwrap_or_else(|(_, text)| text);
            if guarded(&included) {
                self.once.insert(key.clone());
            }
            let inc_id = files.add(target.display().to_string(), included.clone());
            self.stack.push(key);
            self.inline(&target, inc_id, &included, files, diags);
            self.stack.pop();
            if !self.out.ends_with('\n') {
                self.out.push('\n');
            }
        }
        self.copy(id, text, copied, text.len());
    }

    fn fail(&mut self, diags: &mut Vec<Diagnostic>, d: Diagnostic) {
        self.failed = true;
        diags.push(d);
    }
}

/// The file makes a second inclusion empty: `#pragma once`, or an include guard (its first
/// directive `#ifndef X` or `#if !defined(X)` followed by `#define X`).
fn guarded(text: &str) -> bool {
    let directives: Vec<&str> = text.lines().filter_map(|l| l.trim_start().strip_prefix('#')).map(str::trim_start).collect();
    if directives.iter().any(|r| r.starts_with("pragma") && r.contains("once")) {
        return true;
    }
    let guard = match directives.first() {
        Some(d) => d
            .strip_prefix("ifndef")
            .or_else(|| d.strip_prefix("if").map(str::trim_start).and_then(|r| r.strip_prefix("!defined")))
            .map(|r| r.trim().trim_start_matches('(').trim_end_matches(')').trim()),
        None => None,
    };
    let defines_guard = match (guard, directives.get(1)) {
        (Some(g), Some(next)) if !g.is_empty() => next.strip_prefix("define").is_some_and(|r| r.split_whitespace().next() == Some(g)),
        _ => false,
    };
    // The guard's `#endif` closes the file: nothing but blank lines and comments after it.
    let after_endif = text.rfind("#endif").map(|i| text[i..].split_once('\n').map_or("", |(_, rest)| rest));
    let closes = after_endif.is_some_and(|rest| rest.lines().all(|l| l.trim().is_empty() || l.trim_start().starts_with("//")));
    defines_guard && closes && directives.last().is_some_and(|d| d.starts_with("endif"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inlines_relative_files_and_maps_spans_back() {
        let dir = std::env::temp_dir().join(format!("effectc-includes-{}", std::process::id()));
        std::fs::create_dir_all(dir.join("lib")).unwrap();
        std::fs::write(dir.join("lib/common.glsl"), "#pragma once\nfloat two() { return 2.0; }\n").unwrap();
        std::fs::write(dir.join("lib/more.glsl"), "#include \"common.glsl\"\nfloat three() { return 3.0; }").unwrap();
        let main = "#version 450\n#include \"lib/common.glsl\"\n// #include \"missing.glsl\"\n#include \"lib/more.glsl\"\nvoid main() {}\n";
        let path = dir.join("a.frag");
        let mut files = Files::new();
        let id = files.add(path.display().to_string(), main);
        let mut diags = Vec::new();
        let x = expand(&path, id, &mut files, crate::read::MAX_FILE_BYTES, &mut diags).expect("expands");
        assert!(diags.is_empty(), "{diags:?}");
        let text = files.text(x).to_string();
        assert_eq!(text.matches("float two()").count(), 1, "pragma once: {text}");
        assert!(text.contains("float three() { return 3.0; }\nvoid main() {}"));
        let at = text.find("three").unwrap();
        let (file, span) = files.resolve(x, Some(at..at + 5));
        assert!(files.path(file).ends_with("more.glsl"));
        assert_eq!(span, Some(29..34));
        let at = text.find("void main").unwrap();
        let (file, span) = files.resolve(x, Some(at..at + 4));
        assert_eq!(file, id);
        assert_eq!(&main[span.unwrap()], "void");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn recursive_includes_are_errors_at_the_directive_and_missing_ones_stay() {
        let dir = std::env::temp_dir().join(format!("effectc-includes-bad-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("self.glsl"), "#include \"self.glsl\"\n").unwrap();
        std::fs::write(dir.join("ok.glsl"), "float one() { return 1.0; }\n").unwrap();
        let path = dir.join("b.frag");
        let mut files = Files::new();
        let id = files.add(path.display().to_string(), "#include <self.glsl>\n");
        let mut diags = Vec::new();
        assert!(expand(&path, id, &mut files, crate::read::MAX_FILE_BYTES, &mut diags).is_none());
        assert_eq!(diags[0].code, Code::IncludeUnresolved);
        let resolved = files.resolved(&diags);
        let f = resolved[0].file.unwrap();
        assert!(files.path(f).ends_with("self.glsl"));
        assert_eq!(&files.text(f)[resolved[0].span.clone().unwrap()], "self.glsl");

        let main = "#ifdef __cplusplus\n#include <glm/glm.hpp>\n#endif\n#include \"ok.glsl\"\n";
        let id = files.add(path.display().to_string(), main);
        let mut diags = Vec::new();
        let x = expand(&path, id, &mut files, crate::read::MAX_FILE_BYTES, &mut diags).expect("a missing file is left to the front");
        assert_eq!(files.text(x), "#ifdef __cplusplus\n#include <glm/glm.hpp>\n#endif\nfloat one() { return 1.0; }\n");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn guards_are_told_from_their_shape() {
        assert!(guarded("#ifndef A_H\n#define A_H\nfloat a;\n#endif\n// end\n"));
        assert!(guarded("// header\n#if !defined(A_H)\n#define A_H\nfloat a;\n#endif // A_H\n"));
        assert!(guarded("#pragma once\nfloat a;\n"));
        assert!(!guarded("#ifndef A_H\n#define A_H\nfloat a;\n#endif\nfloat b;\n"), "code after the guard");
        assert!(!guarded("#ifndef A_H\n#define B_H\nfloat a;\n#endif\n"), "another macro");
        assert!(!guarded("float a;\n"));
    }
}
