//! The rewrite's side of [`crate::front::uniform_struct_arrays`]: the members the plan widens
//! are declared as arrays of 4-vectors in this stage's struct definitions, and each read
//! takes its first components back (`lights[i].diffuse[j]` → `lights[i].diffuse[j].x`).

use super::Ctx;
use crate::front::syntax::word_occurrences;
use crate::front::uniform_struct_arrays::{index_end, member_reads, widened};

impl Ctx<'_> {
    pub(super) fn uniform_struct_arrays(&mut self) {
        let s = self.s;
        for (name, members) in &self.plan.widened_struct_members {
            // A struct defined in a loose uniform's declaration (`uniform struct S {…} s;`) is
            // written out again with the shared block (`plan::struct_text`, widened there).
            let in_uniform = |d: &crate::front::syntax::StructDef| {
                s.globals.iter().any(|g| g.block.is_none() && g.decl_span.start <= d.span.start && d.span.end <= g.decl_span.end)
            };
            if let Some(def) = s.struct_def(name).filter(|d| !in_uniform(d)) {
                for m in def.members.iter().filter(|m| members.contains(&m.name)) {
                    let from = m.qualifier_span.as_ref().map_or(m.field_span.start, |q| q.end);
                    let (Some(at), Some((stored, _))) =
                        (word_occurrences(&s.text, from..m.span.start, &m.ty.base).into_iter().next(), widened(&m.ty))
                    else {
                        continue;
                    };
                    self.edits.replace(at, stored);
                }
            }
            for (u, field) in member_reads(s, name) {
                let Some(member) = s.struct_def(name).and_then(|d| d.members.iter().find(|m| m.name == field && members.contains(&m.name)))
                else {
                    continue;
                };
                if let (Some(end), Some((_, swizzle))) = (index_end(s, u), widened(&member.ty)) {
                    self.edits.insert(end, format!(".{swizzle}"));
                }
            }
        }
    }
}
