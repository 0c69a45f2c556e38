//! File-scope punctuation naga's parser does not take: a `;` after a function body
//! (`void f() { … };`, an empty declaration glslang and GL drivers accept; GLSL 4.60 names
//! it) is left out.

use super::Ctx;

impl Ctx<'_> {
    pub(super) fn stray_semicolons(&mut self) {
        let s = self.s;
        for f in s.functions.iter().filter(|f| f.is_definition) {
            let rest = &s.text[f.span.end.min(s.text.len())..];
            let skipped = rest.len() - rest.trim_start().len();
            if rest[skipped..].starts_with(';') {
                let at = f.span.end + skipped;
                self.edits.delete(at..at + 1);
            }
        }
    }
}
