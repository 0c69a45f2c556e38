//! Sampler arrays indexed at run time (`texture(s[i], uv)`: legal since GLSL 4.00, ES 3.20,
//! and with `GL_ARB_gpu_shader5`, for dynamically uniform indices). effectc splits a sampler
//! array into one texture and one sampler binding per element (WGSL and naga have no
//! arrays of combined samplers), so a built-in call on an element chosen at run time
//! becomes a choice among the calls on each element:
//! `texture(s[i], uv)` → `(int(i) == 0 ? texture(sampler2D(s_0, s_0_sampler), uv) : … :
//! texture(sampler2D(s_3, s_3_sampler), uv))`. The call's other arguments are written once
//! per element, with every other rewrite inside them; only the chosen call is evaluated.
//! An index past the array's end reads the last element (GL leaves it undefined).
//! Arrays of structs with sampler members (`texture(m[i].tex, uv)`) are taken the same way.

use std::ops::Range;

use super::uses::combined_ctor;
use super::Ctx;
use crate::front::syntax::Use;

/// One built-in call whose sampler argument is an element chosen at run time.
#[derive(Debug, Clone)]
pub(super) struct DynamicLookup {
    /// The whole call.
    call: Range<usize>,
    /// The sampler argument (`s[i]`, `m[i].tex`), written once per element.
    argument: Range<usize>,
    /// The index expression.
    index: Range<usize>,
    /// Each element's combined sampler, in order (`sampler2D(s_0, s_0_sampler)`).
    elements: Vec<String>,
}

impl Ctx<'_> {
    /// When `u` (an element of the sampler array `name` chosen by the index at `index`,
    /// spanning `argument`) is the sampler argument of a built-in call, records the call
    /// for [`dynamic_lookups`](Self::dynamic_lookups) and returns true. `member`: the
    /// sampler member of an array of structs. Index expressions with side effects are
    /// left alone (the choice reads the index once per element).
    pub(super) fn dynamic_lookup(
        &mut self,
        u: &Use,
        argument: &Range<usize>,
        index: &Range<usize>,
        name: &str,
        member: Option<&str>,
    ) -> bool {
        let s = self.s;
        if u.user_call_arg || has_side_effects(&s.text[index.clone()]) {
            return false;
        }
        let Some(call) = s.calls.iter().find(|c| !c.from_macro && c.args.first() == Some(argument)) else { return false };
        if s.functions.iter().any(|f| f.name == call.name) {
            return false;
        }
        let Some(global) = s.global(name) else { return false };
        let Some(Some(count)) = global.ty.dims.first().copied().filter(|_| global.ty.dims.len() == 1) else { return false };
        let mut elements = Vec::new();
        for k in 0..count {
            let path = match member {
                Some(m) => format!("{name}[{k}].{m}"),
                None => format!("{name}[{k}]"),
            };
            let Some(t) = self.plan.texture(&path) else { return false };
            elements.push(format!("{}({}, {})", combined_ctor(&t.user_ty), t.name, t.sampler_name));
        }
        if elements.is_empty() {
            return false;
        }
        self.dynamic_lookups.push(DynamicLookup { call: call.span.clone(), argument: argument.clone(), index: index.clone(), elements });
        true
    }

    /// Writes each recorded call as the choice among its elements, after every other
    /// rewrite inside it (calls inside an argument first).
    pub(super) fn dynamic_lookups(&mut self) {
        let mut lookups = std::mem::take(&mut self.dynamic_lookups);
        lookups.sort_by_key(|l| l.call.len());
        let text = &self.s.text;
        for l in lookups {
            let index = self.edits.text_within(text, l.index.clone());
            let before = self.edits.text_within(text, l.call.start..l.argument.start);
            let after = self.edits.text_within(text, l.argument.end..l.call.end);
            self.edits.take_out(text, l.call.clone());
            let last = l.elements.len() - 1;
            let mut choice = String::from("(");
            for (k, element) in l.elements.iter().enumerate() {
                if k < last {
                    choice.push_str(&format!("int({index}) == {k} ? "));
                }
                choice.push_str(&format!("{before}{element}{after}"));
                if k < last {
                    choice.push_str(" : ");
                }
            }
            choice.push(')');
            self.edits.insert(l.call.start, choice);
        }
    }
}

/// An assignment, increment or call in an index expression (`s[i++]`, `s[next()]`):
/// evaluated once per element it would run more than once. Constructors and conversions
/// (`int(x)`, `vec2(a, b)`, `mat2(..)`) and `abs`/`min`/`max`/`clamp` are pure.
pub(super) fn has_side_effects(index: &str) -> bool {
    let bytes = index.as_bytes();
    let assigns = bytes.iter().enumerate().any(|(i, b)| {
        *b == b'=' && {
            let prev = i.checked_sub(1).map(|p| bytes[p]);
            let next = bytes.get(i + 1).copied();
            !matches!(prev, Some(b'=' | b'!' | b'<' | b'>')) && next != Some(b'=')
        }
    });
    let calls = index.char_indices().filter(|(_, c)| *c == '(').any(|(i, _)| {
        let callee: String = index[..i].chars().rev().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect();
        let callee: String = callee.chars().rev().collect();
        !callee.is_empty() && !is_pure(&callee)
    });
    assigns || index.contains("++") || index.contains("--") || calls
}

/// A constructor, a conversion or a pure built-in.
fn is_pure(callee: &str) -> bool {
    let vector = callee.trim_start_matches(['i', 'u', 'b', 'd']).strip_prefix("vec").is_some_and(|n| matches!(n, "2" | "3" | "4"));
    let matrix = callee
        .trim_start_matches('d')
        .strip_prefix("mat")
        .is_some_and(|n| matches!(n, "2" | "3" | "4" | "2x2" | "2x3" | "2x4" | "3x2" | "3x3" | "3x4" | "4x2" | "4x3" | "4x4"));
    vector || matrix || matches!(callee, "int" | "uint" | "float" | "double" | "bool" | "abs" | "min" | "max" | "clamp")
}

#[cfg(test)]
mod tests {
    use super::has_side_effects;

    #[test]
    fn index_side_effects() {
        assert!(!has_side_effects("n"));
        assert!(!has_side_effects("int(u.x) + 1"));
        assert!(!has_side_effects("i == j ? 0 : 1"));
        assert!(!has_side_effects("min(i, 3)"));
        assert!(has_side_effects("i++"));
        assert!(has_side_effects("i = 2"));
        assert!(has_side_effects("i += 2"));
        assert!(has_side_effects("pick(i)"));
    }

    #[test]
    fn constructors_and_conversions_have_no_side_effects() {
        for pure in ["i", "int(x) + 1", "vec2(-0.5, 0.5)", "ivec2(p) * 2", "mat2(1.0)", "clamp(i, 0, 3)", "a[j] == b"] {
            assert!(!has_side_effects(pure), "{pure}");
        }
        for effect in ["i++", "--i", "i = 2", "next()", "vec2(f(x))", "i += 1"] {
            assert!(has_side_effects(effect), "{effect}");
        }
    }
}
