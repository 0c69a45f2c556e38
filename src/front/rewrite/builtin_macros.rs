//! Object-like macros that rename a built-in type or function to another name
//! (`#define sampler2D sampler2DRect` and `#define texture2D texture2DRect`, Kodi's switch to
//! rectangle textures; `#define texture texture2D` in code written for both GLSL 1.x and 3.x)
//! are applied by the rewrite: the names the rewrite writes itself (`sampler2D`,
//! `texture`, …) would otherwise be renamed by naga's preprocessor too. Each use in code
//! and in later macro bodies becomes the macro's body, unless another edit already rewrote
//! it from the expanded program glsl-lang read; the `#define` goes, and an `#undef` ends
//! the renaming. Macros whose body is no longer than the name are applied earlier, with
//! the offsets kept ([`conditionals`](crate::front::conditionals)).

use crate::front::{builtins, conditionals};

use super::Ctx;

impl Ctx<'_> {
    pub(super) fn builtin_renaming_macros(&mut self) {
        let text = &self.s.text;
        let clean = crate::front::version::blank_comments(text);
        let mut applied: Vec<(String, String)> = Vec::new();
        let mut start = 0;
        for line in clean.split_inclusive(|b| *b == b'\n') {
            let range = start..start + line.len();
            start = range.end;
            let code = String::from_utf8_lossy(line);
            let directive = code.trim_start().strip_prefix('#').map(str::trim_start);
            match directive.map(|d| d.split_at(d.find(|c: char| !c.is_ascii_alphabetic()).unwrap_or(d.len()))) {
                Some(("define", rest)) => {
                    let rest = rest.trim_start();
                    let n = rest.find(|c: char| !c.is_ascii_alphanumeric() && c != '_').unwrap_or(rest.len());
                    let (name, after) = rest.split_at(n);
                    let body = conditionals::renamed_to(after).filter(|b| *b != name);
                    let builtin = is_type_name(name) || builtins::is_function(name);
                    let line = range.start..range.start + code.trim_end().len();
                    if let Some(body) = body.filter(|_| builtin && !self.edits.touches(&line)) {
                        self.edits.delete(line);
                        applied.retain(|(n, _)| n != name);
                        applied.push((name.to_string(), body.to_string()));
                    } else {
                        // A later macro's body uses a renamed name.
                        let body_at = range.end - after.len();
                        self.rename_words(&clean[body_at..range.end], body_at, &applied);
                    }
                }
                Some(("undef", rest)) => {
                    let word = rest.trim_start().split(|c: char| !c.is_ascii_alphanumeric() && c != '_').next().unwrap_or("");
                    applied.retain(|(n, _)| n != word);
                }
                Some(_) => {}
                None => self.rename_words(line, range.start, &applied),
            }
        }
    }

    /// Each whole word of `code` (at `at` in the text) that an applied macro names, replaced
    /// by its body where no other edit touches it.
    fn rename_words(&mut self, code: &[u8], at: usize, applied: &[(String, String)]) {
        if applied.is_empty() {
            return;
        }
        let code = String::from_utf8_lossy(code);
        // Numbers (`1e5`, `2u`) hold no names.
        for (from, word) in crate::front::lexical::words(&code).filter(|(_, w)| !w.starts_with(|c: char| c.is_ascii_digit())) {
            if let Some((_, body)) = applied.iter().find(|(n, _)| n == word) {
                let range = at + from..at + from + word.len();
                if !self.edits.touches(&range) {
                    self.edits.replace(range, body.clone());
                }
            }
        }
    }
}

/// Whether `name` is a GLSL type keyword: a scalar, vector or matrix, or an opaque type
/// (`sampler2D`, `isampler3D`, `image2D`, Vulkan GLSL's `texture2D` and `sampler`).
fn is_type_name(name: &str) -> bool {
    let shaped = |prefixes: &[&str]| prefixes.iter().any(|p| name.strip_prefix(p).is_some_and(|n| matches!(n, "2" | "3" | "4")));
    matches!(name, "void" | "bool" | "int" | "uint" | "float" | "double" | "atomic_uint")
        || shaped(&["vec", "bvec", "ivec", "uvec", "dvec"])
        || crate::front::syntax::matrix_shape(name.strip_prefix('d').unwrap_or(name)).is_some()
        || std::iter::once(name).chain(name.strip_prefix(['i', 'u'])).any(|opaque| {
            ["sampler", "image", "texture", "subpassInput"].iter().any(|k| opaque.strip_prefix(k).is_some_and(opaque_dimensions))
        })
}

/// What follows `sampler`, `image` or `texture` in an opaque type's name: nothing, or its
/// dimensions (`2DRect`, `Cube`, `Buffer`, …, then `Array`, `MS`, `Shadow`).
fn opaque_dimensions(rest: &str) -> bool {
    let known = ["", "Shadow", "Cube", "Buffer", "ExternalOES"];
    let dims = known.iter().any(|k| rest.starts_with(k) && !k.is_empty()) || rest.starts_with(|c: char| c.is_ascii_digit());
    (rest.is_empty() || dims) && rest.bytes().all(|b| b.is_ascii_alphanumeric())
}

#[cfg(test)]
mod tests {
    use super::is_type_name;

    #[test]
    fn type_names_are_glsl_types() {
        for t in ["sampler2D", "sampler2DRect", "usampler2D", "texture2D", "sampler", "image2D", "vec3", "dmat4x3", "mat2", "float"] {
            assert!(is_type_name(t), "{t}");
        }
        for t in ["samplers", "vec5", "texture_2d", "lerp", "myType", "sampler_state"] {
            assert!(!is_type_name(t), "{t}");
        }
    }
}
