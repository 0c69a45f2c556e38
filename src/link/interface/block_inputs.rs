//! Interface blocks, matched by *block* name (instance names may differ). An input block
//! without a match is paired with the output block most likely meant, so a renamed block is
//! one diagnostic; matched blocks are compared member by member ([`crate::link::blocks`]).

use std::collections::HashSet;

use super::{arrayed_inputs, arrayed_outputs, dims_text, per_vertex, qualifiers_relaxed, Pair};
use crate::diag::{Code, Diagnostic};
use crate::front::syntax::StageSyntax;
use crate::link::blocks::{self, MemberDiff, Side};
use crate::link::{is_read, list};

impl Pair<'_> {
    pub(super) fn block_inputs(&mut self) {
        let (a, b) = (self.a, self.b);
        let block_name = |s: &StageSyntax, i: usize| -> String {
            s.globals[i].block.as_ref().map(|blk| s.original_name(&blk.block_name).to_string()).unwrap_or_default()
        };
        let mut unmatched_b = Vec::new();
        let mut matched_a = HashSet::new();
        for bi in self.ins.blocks.clone() {
            let name = block_name(b, bi);
            match self.outs.blocks.iter().copied().find(|&ai| block_name(a, ai) == name) {
                Some(ai) => {
                    matched_a.insert(ai);
                    self.consumed.insert(ai);
                    self.compare_blocks(ai, bi);
                }
                None => unmatched_b.push(bi),
            }
        }
        let unmatched_a: Vec<usize> = self.outs.blocks.iter().copied().filter(|ai| !matched_a.contains(ai)).collect();
        let mut taken = HashSet::new();
        for &bi in &unmatched_b {
            let mut best: Option<(usize, usize)> = None;
            for &ai in unmatched_a.iter().filter(|ai| !taken.contains(*ai)) {
                let score = self.pair_score(ai, bi);
                if score > 0 && best.is_none_or(|(s, _)| score > s) {
                    best = Some((score, ai));
                }
            }
            let mut pick = best.map(|(_, ai)| ai);
            if pick.is_none() && unmatched_a.len() == 1 && unmatched_b.len() == 1 {
                pick = Some(unmatched_a[0]);
            }
            if let Some(ai) = pick {
                taken.insert(ai);
            }
            self.unmatched_block(bi, pick);
        }
    }

    fn side<'s>(s: &'s StageSyntax, i: usize) -> Side<'s> {
        let g = &s.globals[i];
        let members = g.block.as_ref().map_or(&[][..], |b| &b.members[..]);
        Side { stage: s, members, block_interp: g.interp, block_centroid: g.centroid }
    }

    /// How likely output block `ai` is the one input block `bi` was meant to match.
    fn pair_score(&self, ai: usize, bi: usize) -> usize {
        let (sa, sb) = (Self::side(self.a, ai), Self::side(self.b, bi));
        if blocks::same_members(sa, sb) {
            3
        } else {
            let shared = blocks::shared_names(sa, sb);
            if shared == sa.members.len() && shared == sb.members.len() {
                2
            } else if shared > 0 {
                1
            } else {
                0
            }
        }
    }

    /// An input block with no output block of its block name; `pair` is the output block it
    /// was most likely meant to match.
    fn unmatched_block(&mut self, bi: usize, pair: Option<usize>) {
        let (a, b, at, bt) = (self.a, self.b, self.at, self.bt);
        let g = &b.globals[bi];
        let Some(blk) = &g.block else { return };
        let bname = b.original_name(&blk.block_name);
        let read = is_read(b, bi);
        let message = format!("{bt} input block `{bname}` has no matching output block in the {at} stage");
        let mut d = if read {
            Diagnostic::new(Code::InputBlockUnmatched, message)
        } else {
            Diagnostic::new(Code::UnusedInput, format!("{message} (it is never read)"))
        }
        .at(b.file, blk.block_name_span.clone(), format!("no {at} output block is named `{bname}`"));
        if let Some(ai) = pair {
            self.consumed.insert(ai);
            let ablk = a.globals[ai].block.as_ref().expect("output blocks are blocks");
            let aname = a.original_name(&ablk.block_name);
            d = d
                .with_label(a.file, ablk.block_name_span.clone(), format!("the {at} stage's output block is named `{aname}`"))
                .with_note(format!("interface blocks match by block name (`{bname}` vs `{aname}`), not by instance name"));
            let (sa, sb) = (Self::side(a, ai), Self::side(b, bi));
            if blocks::same_members(sa, sb) {
                d = d.with_help(format!("rename `in {bname}` to `in {aname}` (the members match)"));
            } else {
                for diff in blocks::diff(sa, sb, !qualifiers_relaxed(a, b)) {
                    d = self.add_diff(d, diff);
                }
                d = d.with_help(format!("rename `in {bname}` to `in {aname}` and make the members agree"));
            }
        } else {
            d = d.with_note("interface blocks match by block name, not by instance name");
            // Does `a` write the members as loose outputs?
            let loose: Vec<usize> = self
                .outs
                .loose
                .iter()
                .copied()
                .filter(|&ai| blk.members.iter().any(|m| b.original_name(&m.name) == self.aname(ai)))
                .collect();
            if !loose.is_empty() {
                let names: Vec<String> = loose.iter().map(|&ai| self.aname(ai).to_string()).collect();
                for &ai in &loose {
                    self.consumed.insert(ai);
                    d = d.with_label(a.file, a.globals[ai].name_span.clone(), "a separate output, not a block member");
                }
                d = d.with_help(format!(
                    "the {at} stage writes {} as separate outputs: declare `out {bname} {{ … }}` there, or declare the inputs here as separate `in` variables",
                    list(&names)
                ));
            } else {
                let others: Vec<String> = self
                    .outs
                    .blocks
                    .iter()
                    .filter_map(|&ai| a.globals[ai].block.as_ref())
                    .map(|ob| a.original_name(&ob.block_name).to_string())
                    .collect();
                if !others.is_empty() {
                    d = d.with_note(format!("the {at} stage's output blocks are {}", list(&others)));
                }
                d = d.with_help(format!("declare `out {bname} {{ … }}` with the same members in the {at} stage"));
            }
        }
        if !read {
            d = d.with_note("GL only rejects an unmatched input the stage reads; this one is dead code");
        }
        self.out.push(d);
    }

    fn add_diff(&self, mut d: Diagnostic, diff: MemberDiff) -> Diagnostic {
        if let Some((span, label)) = diff.a {
            d = d.with_label(self.a.file, span, label);
        }
        if let Some((span, label)) = diff.b {
            d = d.with_label(self.b.file, span, label);
        }
        d.with_note(diff.note)
    }

    /// Members and block-level facts of two blocks with the same block name.
    fn compare_blocks(&mut self, ai: usize, bi: usize) {
        let (a, b, at, bt) = (self.a, self.b, self.at, self.bt);
        let (ga, gb) = (&a.globals[ai], &b.globals[bi]);
        let (Some(ba), Some(bb)) = (&ga.block, &gb.block) else {
            return;
        };
        let name = b.original_name(&bb.block_name);
        let relaxed = qualifiers_relaxed(a, b);
        let all = blocks::diff(Self::side(a, ai), Self::side(b, bi), true);
        let (mut errors, warnings): (Vec<MemberDiff>, Vec<MemberDiff>) = all.into_iter().partition(|d| !(relaxed && d.qualifier));
        let da = per_vertex(&ba.instance_dims, arrayed_outputs(a.stage));
        let db = per_vertex(&bb.instance_dims, arrayed_inputs(b.stage) && !bb.instance_dims.is_empty());
        if da != db {
            let shown = |d: &[Option<u32>]| {
                if d.is_empty() {
                    "not an array".to_string()
                } else {
                    format!("an array `{}`", dims_text(d))
                }
            };
            errors.push(MemberDiff {
                qualifier: false,
                note: format!("the instance is {} in the {at} stage but {} in the {bt} stage", shown(&da), shown(&db)),
                a: ba.instance_span.clone().map(|s| (s, shown(&da))),
                b: bb.instance_span.clone().map(|s| (s, shown(&db))),
            });
        }
        if let (Some(la), Some(lb)) = (ga.location, gb.location) {
            if la != lb {
                errors.push(MemberDiff {
                    qualifier: false,
                    note: format!("the block has `location = {la}` in the {at} stage but `location = {lb}` in the {bt} stage"),
                    a: ga.layout_span.clone().map(|s| (s, format!("location {la}"))),
                    b: gb.layout_span.clone().map(|s| (s, format!("location {lb}"))),
                });
            }
        }
        let head = |d: Diagnostic| {
            d.at(b.file, bb.block_name_span.clone(), format!("{bt} input block")).with_label(
                a.file,
                ba.block_name_span.clone(),
                format!("{at} output block"),
            )
        };
        if !errors.is_empty() {
            let mut d = head(Diagnostic::new(
                Code::InterfaceBlockMismatch,
                format!("interface block `{name}` differs between the {at} and {bt} stages"),
            ));
            for diff in errors {
                d = self.add_diff(d, diff);
            }
            d = d
                .with_note("blocks with the same block name must declare the same members in the same order, with the same types, array sizes and qualifiers")
                .with_help(format!("copy the block's members from the {at} stage into the {bt} stage"));
            self.out.push(d);
        }
        if !warnings.is_empty() {
            let mut d = head(Diagnostic::new(
                Code::InterpolationDiffers,
                format!("interface block `{name}` has different qualifiers in the {at} and {bt} stages"),
            ));
            for diff in warnings {
                d = self.add_diff(d, diff);
            }
            self.out.push(
                d.with_note(format!("since GLSL 4.30 interpolation and auxiliary qualifiers may differ and the {bt} stage's are used")),
            );
        }
    }
}
