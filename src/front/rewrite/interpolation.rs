//! Fragment built-ins WebGPU has no per-call form of, written as what they give on the
//! single-sampled frames effectc draws: `interpolateAtOffset(x, o)` as `x` moved along its
//! screen-space derivatives (`x + dFdx(x) * o.x + dFdy(x) * o.y`: exact for a varying
//! interpolated linearly, first order under perspective), `interpolateAtCentroid(x)` and
//! `interpolateAtSample(x, i)` as `x` (GL evaluates both at the pixel's centre without
//! multisampling; on a multisampled target they move to the centroid or the sample), and
//! `gl_HelperInvocation` as `false` (a helper invocation's stores and atomics have no effect
//! in WebGPU either; a value it computes for a derivative differs). Each is note N0110 at
//! the call.

use super::Ctx;
use crate::diag::{Code, Diagnostic};

/// The functions written, with what they become.
const FUNCTIONS: [&str; 3] = ["interpolateAtOffset", "interpolateAtCentroid", "interpolateAtSample"];

impl Ctx<'_> {
    /// The `interpolateAt*` calls of a fragment stage written without the built-in (after
    /// every rewrite inside their arguments).
    pub(super) fn interpolation_calls(&mut self) {
        let s = self.s;
        if s.stage != crate::stage::StageKind::Fragment {
            return;
        }
        let text = &s.text;
        for c in &s.calls {
            if !FUNCTIONS.contains(&c.name.as_str()) || c.from_macro || s.functions.iter().any(|f| f.name == c.name) {
                continue;
            }
            let Some(value) = c.args.first() else { continue };
            let x = self.edits.text_within(text, value.clone());
            let (written, why) = match (c.name.as_str(), c.args.get(1)) {
                ("interpolateAtOffset", Some(offset)) => {
                    let o = self.edits.text_within(text, offset.clone());
                    if super::dynamic_samplers::has_side_effects(&o) {
                        continue;
                    }
                    (
                        format!("(({x}) + dFdx({x}) * ({o}).x + dFdy({x}) * ({o}).y)"),
                        "the value at the offset is extrapolated from its screen-space derivatives",
                    )
                }
                ("interpolateAtCentroid", _) => {
                    (format!("({x})"), "the value at the pixel's centre: WebGPU has no centroid interpolation per call")
                }
                ("interpolateAtSample", Some(sample)) => {
                    let i = self.edits.text_within(text, sample.clone());
                    if super::dynamic_samplers::has_side_effects(&i) {
                        continue;
                    }
                    (format!("({x})"), "the value at the pixel's centre: WebGPU has no interpolation at a chosen sample")
                }
                _ => continue,
            };
            self.edits.take_out(text, c.span.clone());
            self.edits.insert(c.span.start, written);
            self.diags.push(
                Diagnostic::new(Code::InterpolationApproximated, format!("`{}` is written without the built-in: {why}", c.name))
                    .at(s.file, c.name_span.clone(), "approximated")
                    .with_note("GL evaluates it the same way on a single-sampled target, the kind `render` and `verify` draw"),
            );
        }
    }

    /// `gl_HelperInvocation` read as `false`.
    pub(super) fn helper_invocation(&mut self, span: std::ops::Range<usize>) {
        self.edits.replace(span.clone(), "false");
        self.diags.push(
            Diagnostic::new(
                Code::InterpolationApproximated,
                "`gl_HelperInvocation` is `false`: WebGPU does not tell helper invocations apart",
            )
            .at(self.s.file, span, "always false")
            .with_note("a helper invocation's stores and atomics have no effect in WebGPU, so a guard around them behaves as in GL"),
        );
    }
}
