//! Struct and block definitions: sampler members out, filler members in, default-qualifier
//! declarations and layout items naga does not take out, row-major matrices read through
//! `transpose`.

use std::collections::BTreeMap;
use std::ops::Range;

use super::io_blocks::awkward_member;
use super::Ctx;
use crate::front::limitation::Limitation;
use crate::front::plan::STRUCT_ALIGN_FILLER;
use crate::front::syntax::{Referent, StageSyntax, Storage};
use crate::stage::StageKind;

impl Ctx<'_> {
    /// Sampler members leave struct definitions (they became their own bindings); structs
    /// the plan pads get their filler member.
    pub(super) fn struct_samplers(&mut self) {
        let s = self.s;
        for st in &s.structs {
            let in_uniform_decl = s
                .globals
                .iter()
                .any(|g| g.storage == Storage::Uniform && g.decl_span.start <= st.span.start && st.span.end <= g.decl_span.end);
            if self.plan.padded_structs.contains(&st.name) && !in_uniform_decl {
                if let Some(close) = s.text[..st.span.end].rfind('}') {
                    self.edits.insert(close, format!(" vec4 {STRUCT_ALIGN_FILLER};"));
                }
            }
            let mut done: Vec<Range<usize>> = Vec::new();
            let opaque: Vec<_> = st.members.iter().filter(|m| m.ty.is_sampler()).collect();
            if opaque.is_empty() {
                continue;
            }
            for m in &opaque {
                if !done.contains(&m.field_span) {
                    done.push(m.field_span.clone());
                    self.edits.delete(m.field_span.clone());
                }
            }
            if opaque.len() == st.members.len() {
                // GLSL structs cannot be empty.
                if let Some(m) = opaque.first() {
                    self.edits.insert(m.field_span.start, "int effectc_unused;");
                }
            }
        }
    }

    /// Default-qualifier declarations (`layout(std140, row_major) uniform;`) leave the text;
    /// block layout items naga does not take (`row_major`, `column_major`, `shared`,
    /// `packed`, `index = 0`) leave their qualifiers; member qualifiers of blocks
    /// (`flat`, `layout(location = 3)`, `layout(row_major)`) leave the members (naga's
    /// parser takes none of them: locations follow the block's, integers are flat anyway).
    pub(super) fn defaults_and_layouts(&mut self) {
        let s = self.s;
        // A geometry stage's blocks are passed by the geometry fold, which takes them.
        let io_block_array = s
            .globals
            .iter()
            .filter(|g| s.stage != StageKind::Geometry && !self.flattens(g))
            .find_map(|g| awkward_member(g).map(|m| (g.name.clone(), m.span.clone())));
        if let (None, Some((block, span))) = (&self.limitation, io_block_array) {
            // naga's GLSL front gives every member of an interface block one location, so
            // an array member collides with the member after it; and it takes no matrix
            // varyings. Blocks of the shapes `flattens` takes are passed as loose varyings.
            self.limitation = Some(Limitation {
                construct: format!(
                    "an array or matrix member of the interface block `{}` (naga gives each member one location and no matrix varyings)",
                    s.original_name(&block)
                ),
                span: Some(span),
            });
        }
        for d in &s.defaults {
            if matches!(d.storage, Some(Storage::Uniform | Storage::Buffer)) {
                self.edits.delete(d.span.clone());
            }
        }
        let dual_source = s.globals.iter().any(|g| g.layout.iter().any(|(k, v)| k == "index" && *v != Some(0)));
        let mut by_decl: BTreeMap<usize, &crate::front::syntax::Global> = BTreeMap::new();
        for g in &s.globals {
            by_decl.entry(g.decl_span.start).or_insert(g);
        }
        by_decl.retain(|_, g| !self.flattens(g));
        for g in by_decl.values() {
            let is_block = g.block.is_some();
            let drop = |name: &str| match name {
                "row_major" | "column_major" | "shared" | "packed" => is_block,
                "index" => !is_block && !dual_source,
                item => super::subpass::drops_layout_item(&g.ty.base, item),
            };
            if let (Some(first), Some(last)) = (g.layout_items.first(), g.layout_items.last()) {
                if g.layout_items.iter().any(|(n, _)| drop(n)) {
                    let mut kept: Vec<&str> = g.layout_items.iter().filter(|(n, _)| !drop(n)).map(|(_, sp)| &s.text[sp.clone()]).collect();
                    if kept.is_empty() && is_block {
                        // `layout()` is not GLSL: a block keeps the packing naga uses anyway.
                        kept.push(if g.storage == Storage::Buffer { "std430" } else { "std140" });
                    }
                    if !kept.is_empty() {
                        // One edit over the items only: what `add_layout` inserts right
                        // after `layout(` stays in front of them.
                        self.edits.replace(first.1.start..last.1.end, kept.join(", "));
                    }
                }
            }
            let Some(b) = &g.block else { continue };
            let mut done: Vec<Range<usize>> = Vec::new();
            for m in &b.members {
                if let Some(q) = &m.qualifier_span {
                    if done.contains(q) {
                        continue;
                    }
                    done.push(q.clone());
                    let text = &s.text[q.clone()];
                    let only_precision = ["highp", "mediump", "lowp"].contains(&text.trim());
                    if !only_precision {
                        self.edits.delete(q.clone());
                    }
                }
            }
        }
    }

    /// Row-major square matrices in uniform and buffer blocks: naga reads every matrix
    /// column-major, so the stored matrix is the transpose; each read becomes
    /// `transpose(…)`.
    pub(super) fn row_major_uses(&mut self) {
        let s = self.s;
        let row_major = row_major_members(s);
        if row_major.is_empty() {
            return;
        }
        for u in &s.uses {
            let Referent::Global(gi) = u.target else { continue };
            let b = s.globals[gi].block.as_ref();
            let span = match (&u.field, b.and_then(|b| b.instance.as_ref())) {
                (Some((field, dot)), Some(_)) if row_major.iter().any(|(g, m)| *g == gi && m == field) => dot.clone(),
                (_, None) if row_major.iter().any(|(g, m)| *g == gi && *m == u.name) => u.span.clone(),
                _ => continue,
            };
            self.edits.insert(span.start, "transpose(");
            self.edits.insert(span.end, ")");
        }
    }
}

/// Whether matrices of block `g` (a uniform or buffer block) are stored row-major: the
/// default-qualifier declarations before it, then its own layout.
fn block_row_major(s: &StageSyntax, g: &crate::front::syntax::Global) -> bool {
    let layouts = s
        .defaults
        .iter()
        .filter(|d| d.span.end <= g.decl_span.start)
        .filter(|d| matches!(d.storage, Some(Storage::Uniform | Storage::Buffer)) && d.storage == Some(g.storage))
        .map(|d| &d.layout)
        .chain([&g.layout]);
    layouts.fold(false, |row, layout| majority_after(row, layout))
}

/// Whether matrices are row-major after `layout`'s qualifiers (the last of `row_major` and
/// `column_major` wins), starting from `row`.
fn majority_after(row: bool, layout: &[(String, Option<i64>)]) -> bool {
    layout.iter().fold(row, |row, (k, _)| match k.as_str() {
        "row_major" => true,
        "column_major" => false,
        _ => row,
    })
}

/// The square matrices of uniform and buffer blocks stored row-major (by the member's own
/// layout, its block's, or a default declaration): (index of the block's global, member).
/// naga lays every matrix out column-major, so the rewrite reads these transposed and
/// `render` stores them transposed.
pub fn row_major_members(s: &StageSyntax) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    for (gi, g) in s.globals.iter().enumerate() {
        let Some(b) = &g.block else { continue };
        if !matches!(g.storage, Storage::Uniform | Storage::Buffer) {
            continue;
        }
        let block_row = block_row_major(s, g);
        for m in &b.members {
            let row = majority_after(block_row, &m.layout);
            if row && matches!(m.ty.base.as_str(), "mat2" | "mat3" | "mat4" | "mat2x2" | "mat3x3" | "mat4x4") {
                out.push((gi, m.name.clone()));
            }
        }
    }
    out
}
