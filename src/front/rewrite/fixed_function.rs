//! The compatibility profile's built-ins ([`compat`]): their declarations in the header
//! (attribute inputs take the first vertex-input locations, as GL aliases `gl_Vertex` with
//! attribute 0), the copies in and out of `gl_TexCoord[]`, the light products computed
//! first in `main`, matrix forms read as functions of their matrix, and `ftransform()`.

use super::varyings::LocationAllocator;
use super::Ctx;
use crate::front::compat;
use crate::front::syntax::Referent;

impl Ctx<'_> {
    pub(super) fn fixed_function(&mut self, vertex_inputs: &mut LocationAllocator) {
        let (s, plan) = (self.s, self.plan);
        let d = compat::declarations(s, &plan.compat, |name| plan.varyings.get(name).copied().unwrap_or(0), |n| vertex_inputs.next(n));
        self.compat_header = d.header;
        self.prologue.push_str(&d.prologue);
        self.epilogue.push_str(&d.epilogue);
        for u in s.uses.iter().filter(|u| u.target == Referent::Unresolved) {
            let Some((matrix, forms)) = compat::matrix_form(&u.name) else { continue };
            let open: String = forms.iter().rev().map(|f| format!("{f}(")).collect();
            let close = ")".repeat(forms.len());
            // `gl_TextureMatrixInverse[i]` picks a matrix of the array before the form is taken;
            // `gl_ModelViewMatrixInverse[3]` indexes a column of the form.
            match u.index.as_ref().filter(|_| matrix == "gl_TextureMatrix") {
                Some((bracket, _, _)) => {
                    self.edits.replace(u.span.clone(), format!("{open}{matrix}"));
                    self.edits.insert(bracket.end, close);
                }
                None => self.edits.replace(u.span.clone(), format!("{open}{matrix}{close}")),
            }
        }
        if compat::calls_ftransform(s) {
            for c in s.calls.iter().filter(|c| c.name == compat::FTRANSFORM && !c.from_macro) {
                self.edits.replace(c.span.clone(), "(gl_ModelViewProjectionMatrix * gl_Vertex)");
            }
        }
    }
}
