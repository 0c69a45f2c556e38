//! Sampler arrays passed whole to a function (`vec4 pick(sampler2D ts[4], vec2 uv)` called
//! as `pick(u_textures, uv)`; legal since GLSL 1.00): effectc splits a uniform sampler array
//! into one texture and sampler per element, and WGSL passes no arrays of textures to a
//! function. Where every call of the function passes the same uniform array, the parameter
//! stands for it: its uses read that uniform's elements ([`uses`](super::uses)), and the
//! parameter (in the definition and every prototype) and the arguments go.

use std::ops::Range;

use crate::front::syntax::{Referent, StageSyntax, Storage};

use super::Ctx;

/// A sampler-array parameter every call fills with one uniform array.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct ArrayParam {
    pub function: usize,
    pub param: usize,
    /// Index into the stage's globals.
    pub global: usize,
}

/// The stage's sampler-array parameters that stand for one uniform array.
pub(super) fn array_params(s: &StageSyntax) -> Vec<ArrayParam> {
    let mut out = Vec::new();
    for (fi, f) in s.functions.iter().enumerate().filter(|(_, f)| f.is_definition) {
        // One definition (no overloads), prototypes of its shape.
        let same_name: Vec<_> = s.functions.iter().filter(|g| g.name == f.name).collect();
        if same_name.iter().any(|g| g.params.len() != f.params.len() || (g.is_definition && !std::ptr::eq(*g, f))) {
            continue;
        }
        for (pi, p) in f.params.iter().enumerate().filter(|(_, p)| p.ty.is_sampler() && p.ty.is_array()) {
            let calls: Vec<_> = s.calls.iter().filter(|c| c.name == f.name && !c.from_macro).collect();
            let passed: Option<Vec<usize>> = calls
                .iter()
                .map(|c| {
                    let arg = s.text.get(c.args.get(pi)?.clone())?.trim();
                    let same_type = |g: &crate::front::syntax::Global| g.ty.base == p.ty.base && g.ty.dims == p.ty.dims;
                    s.globals.iter().position(|g| g.name == arg && g.storage == Storage::Uniform && same_type(g))
                })
                .collect();
            if let Some([first, rest @ ..]) = passed.as_deref() {
                if rest.iter().all(|g| g == first) {
                    out.push(ArrayParam { function: fi, param: pi, global: *first });
                }
            }
        }
    }
    out
}

impl Ctx<'_> {
    /// The global a use of a sampler-array parameter stands for.
    pub(super) fn array_param_global(&self, target: &Referent) -> Option<usize> {
        let Referent::Param(fi, pi) = *target else { return None };
        self.array_params.iter().find(|a| a.function == fi && a.param == pi).map(|a| a.global)
    }

    /// Whether parameter `pi` of the function named `name` (its definition or a prototype)
    /// stands for a uniform.
    pub(super) fn is_array_param(&self, name: &str, pi: usize) -> bool {
        self.array_params.iter().any(|a| a.param == pi && self.s.functions[a.function].name == name)
    }

    /// The parameters and arguments that stand for a uniform array, deleted with their commas.
    pub(super) fn drop_array_params(&mut self) {
        let s = self.s;
        for a in self.array_params.clone() {
            let name = &s.functions[a.function].name;
            for f in s.functions.iter().filter(|f| f.name == *name) {
                let spans: Vec<Range<usize>> = f.params.iter().map(|p| p.span.clone()).collect();
                self.edits.delete(with_comma(&spans, a.param));
            }
            for c in s.calls.iter().filter(|c| c.name == *name && !c.from_macro) {
                self.edits.delete(with_comma(&c.args, a.param));
            }
        }
    }
}

/// Item `i` of a comma-separated list (`spans` of its items) with the comma that joins it to
/// the next item (or, the last, to the one before).
fn with_comma(spans: &[Range<usize>], i: usize) -> Range<usize> {
    match (spans.get(i + 1), i.checked_sub(1).and_then(|p| spans.get(p))) {
        (Some(next), _) => spans[i].start..next.start,
        (None, Some(before)) => before.end..spans[i].end,
        (None, None) => spans[i].clone(),
    }
}
