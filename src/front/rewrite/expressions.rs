//! Expressions naga reads differently: array sizes written as values (unsized arrays sized
//! by their initializer, sizes and case labels from local constants), scalar swizzles as
//! constructors, a `for` condition that starts with a constructor in parentheses.

use super::Ctx;

impl Ctx<'_> {
    /// `vec3 p[] = vec3[](a, b)`: naga cannot construct unsized arrays; the size is the
    /// initializer's length.
    pub(super) fn unsized_arrays(&mut self) {
        let s = self.s;
        // GLSL 1.10/1.20 size a global declared `float a[];` by the largest constant index
        // the stage uses (an array nothing indexes has one element).
        for (i, g) in s.globals.iter().enumerate() {
            if g.storage != crate::front::syntax::Storage::Private || g.initializer.is_some() || g.ty.dims != [None] {
                continue;
            }
            let largest = s
                .uses
                .iter()
                .filter(|u| u.target == crate::front::syntax::Referent::Global(i))
                .filter_map(|u| u.index.as_ref().and_then(|(_, _, k)| *k))
                .max()
                .unwrap_or(0);
            self.size_empty_brackets(g.name_span.end, largest + 1);
        }
        // Block members declared `name[]`: the size GL's linker gives them (the plan's). A
        // redeclared built-in block (`out gl_PerVertex { float gl_ClipDistance[]; }`) is
        // deleted whole ([`varying_declaration`](Self::varying_declaration)).
        for g in s.globals.iter().filter(|g| !g.name.starts_with("gl_")) {
            let Some(b) = &g.block else { continue };
            for m in &b.members {
                let Some((_, _, n)) = self.plan.sized_members.iter().find(|(bn, mn, _)| *bn == b.block_name && *mn == m.name) else {
                    continue;
                };
                self.size_empty_brackets(m.span.end, i64::from(*n));
            }
        }
        for (span, n) in &s.constant_sizes {
            self.edits.replace(span.clone(), n.to_string());
        }
        // A loose uniform's declaration is replaced whole (it moves into the shared block,
        // sized there from its type).
        let in_loose_uniform = |span: &std::ops::Range<usize>| {
            s.globals.iter().any(|g| {
                g.storage == crate::front::syntax::Storage::Uniform
                    && g.block.is_none()
                    && g.decl_span.start <= span.start
                    && span.end <= g.decl_span.end
            })
        };
        for (span, n) in s.unsized_sizes.iter().filter(|(span, _)| !in_loose_uniform(span)) {
            let text = &s.text[span.clone()];
            if text.trim() == "[]" {
                self.edits.replace(span.clone(), format!("[{n}]"));
            } else if text.trim().is_empty() {
                // The node spans nothing: find the brackets after it.
                if let Some(open) = s.text[span.start..].find('[') {
                    let at = span.start + open + 1;
                    if s.text[at..].trim_start().starts_with(']') {
                        self.edits.insert(at, n.to_string());
                    }
                }
            }
        }
    }

    /// Writes `n` into the `[]` right after `at` (a declared name), when it is empty.
    fn size_empty_brackets(&mut self, at: usize, n: i64) {
        let after = &self.s.text[at..];
        let open = after.len() - after.trim_start().len();
        if after[open..].starts_with('[') && after[open + 1..].trim_start().starts_with(']') {
            self.edits.insert(at + open + 1, n.to_string());
        }
    }

    /// The swizzles (indices into `s.swizzles`) naga found applied to a scalar, written as
    /// constructors: `x.rrr` → `vec3(x)`, `x.r` → `(x)`.
    pub(super) fn scalar_swizzles(&mut self, scalar_swizzles: &[usize]) {
        let s = self.s;
        for &i in scalar_swizzles {
            let w = &s.swizzles[i];
            let ctor = if w.width == 1 { "(".to_string() } else { format!("vec{}(", w.width) };
            // Only `.field` is replaced, so a parenthesised base keeps its own parentheses.
            let dot = s.text[w.whole.clone()].rfind('.').map_or(w.base.end, |d| w.whole.start + d);
            self.edits.insert(w.base.start, ctor);
            self.edits.replace(dot..w.whole.end, ")");
        }
    }

    /// `for (int i = 0; float(i) < n; i++)`: naga's parser takes a condition that starts
    /// with a type name for a declaration and stops at the `(`; in parentheses it is an
    /// expression.
    pub(super) fn constructor_conditions(&mut self) {
        for span in &self.s.constructor_conditions {
            self.edits.insert(span.start, "(");
            self.edits.insert(span.end, ")");
        }
    }
}
