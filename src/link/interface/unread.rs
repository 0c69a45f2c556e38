//! Outputs of the earlier stage that no input of the later stage reads (or that only a
//! member of an input block of the same name would have read).

use super::Pair;
use crate::diag::{Code, Diagnostic};

impl Pair<'_> {
    /// Outputs of `a` that no input of `b` accounts for.
    pub(super) fn unread_outputs(&mut self) {
        let (a, b, at, bt) = (self.a, self.b, self.at, self.bt);
        for ai in self.outs.loose.clone() {
            if self.consumed.contains(&ai) {
                continue;
            }
            let g = &a.globals[ai];
            let name = a.original_name(&g.name);
            let mut d = Diagnostic::new(Code::UnreadOutput, format!("{at} output `{name}` is never read by the {bt} stage")).at(
                a.file,
                g.name_span.clone(),
                "written here, read nowhere",
            );
            let member = self.ins.blocks.iter().find_map(|&bi| {
                let blk = b.globals[bi].block.as_ref()?;
                let m = blk.members.iter().find(|m| b.original_name(&m.name) == name)?;
                Some((b.original_name(&blk.block_name), m))
            });
            match member {
                Some((block, m)) => {
                    d = d
                        .with_label(b.file, m.span.clone(), format!("a member of input block `{block}`"))
                        .with_note(format!(
                            "the {bt} stage reads `{name}` as a member of input block `{block}`; a loose output only matches a loose input"
                        ))
                        .with_help(format!("move the output into `out {block} {{ … }}` in the {at} stage"));
                }
                None => {
                    d = d.with_note(format!("the {bt} stage declares no input named `{name}`, so the value is discarded"));
                }
            }
            self.out.push(d);
        }
        for ai in self.outs.blocks.clone() {
            if self.consumed.contains(&ai) {
                continue;
            }
            let Some(blk) = &a.globals[ai].block else {
                continue;
            };
            let name = a.original_name(&blk.block_name);
            self.out.push(
                Diagnostic::new(Code::UnreadOutput, format!("{at} output block `{name}` is never read by the {bt} stage"))
                    .at(a.file, blk.block_name_span.clone(), "written here, read nowhere")
                    .with_note(format!(
                        "the {bt} stage declares no input block named `{name}` (blocks match by block name, not by instance name)"
                    )),
            );
        }
    }
}
