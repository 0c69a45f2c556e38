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
        // Block members declared `name[]`: the size GL's linker gives them (the plan's).
        for g in &s.globals {
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
        let clean = crate::front::version::blank_comments(&self.s.text);
        let mut from = 0;
        while let Some(at) = find_word(&clean, "for", from) {
            from = at + 3;
            let Some(open) = skip_spaces(&clean, from).filter(|&i| clean[i] == b'(') else { continue };
            let Some(first) = top_level_semicolon(&clean, open + 1) else { continue };
            let Some(cond) = skip_spaces(&clean, first + 1) else { continue };
            let Some(end) = top_level_semicolon(&clean, cond) else { continue };
            let word_end = (cond..end).find(|&i| !(clean[i].is_ascii_alphanumeric() || clean[i] == b'_')).unwrap_or(end);
            let word = std::str::from_utf8(&clean[cond..word_end]).unwrap_or("");
            let constructs = skip_spaces(&clean, word_end).is_some_and(|i| clean[i] == b'(');
            if constructs && is_arithmetic_type(word) {
                self.edits.insert(cond, "(");
                self.edits.insert(end, ")");
            }
        }
    }
}

/// A scalar, vector or matrix type name (`float`, `ivec2`, `mat3x4`, `dvec3`).
fn is_arithmetic_type(word: &str) -> bool {
    if matches!(word, "float" | "int" | "uint" | "bool" | "double") {
        return true;
    }
    let shape = word.strip_prefix(['i', 'u', 'b', 'd']).unwrap_or(word);
    let n = |t: &str| matches!(t, "2" | "3" | "4");
    shape.strip_prefix("vec").is_some_and(n)
        || shape.strip_prefix("mat").is_some_and(|m| n(m) || m.split_once('x').is_some_and(|(a, b)| n(a) && n(b)))
}

/// The first occurrence of `word` as a whole identifier at or after `from`.
fn find_word(text: &[u8], word: &str, from: usize) -> Option<usize> {
    let ident = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
    let mut i = from;
    while let Some(off) = text.get(i..)?.windows(word.len()).position(|w| w == word.as_bytes()) {
        let at = i + off;
        let before = at == 0 || !ident(text[at - 1]);
        let after = text.get(at + word.len()).is_none_or(|b| !ident(*b));
        if before && after {
            return Some(at);
        }
        i = at + 1;
    }
    None
}

/// The first non-space byte at or after `from`.
fn skip_spaces(text: &[u8], from: usize) -> Option<usize> {
    (from..text.len()).find(|&i| !text[i].is_ascii_whitespace())
}

/// The first `;` at or after `from` outside parentheses and brackets.
fn top_level_semicolon(text: &[u8], from: usize) -> Option<usize> {
    let mut depth = 0i32;
    for (i, &b) in text.iter().enumerate().skip(from) {
        match b {
            b'(' | b'[' => depth += 1,
            b')' | b']' => {
                depth -= 1;
                if depth < 0 {
                    return None;
                }
            }
            b';' if depth == 0 => return Some(i),
            _ => {}
        }
    }
    None
}
