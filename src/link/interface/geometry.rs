//! Geometry-stage inputs receive every vertex of the input primitive, so each loose input
//! and each input block instance must be an array.

use super::Pair;
use crate::diag::{Code, Diagnostic};
use crate::link::type_text;
use crate::stage::StageKind;

impl Pair<'_> {
    /// Geometry inputs must be arrays (tessellation inputs may be `patch in`, which the
    /// syntax facts do not record, so only geometry is checked).
    pub(super) fn arrayed_geometry_inputs(&mut self) {
        if self.b.stage != StageKind::Geometry {
            return;
        }
        let b = self.b;
        for &i in &self.ins.loose {
            let g = &b.globals[i];
            if g.ty.is_array() {
                continue;
            }
            let name = b.original_name(&g.name);
            let ty = type_text(b, &g.ty);
            self.out.push(
                Diagnostic::new(
                    Code::GeometryInputNotArray,
                    format!("geometry input `{name}` must be an array"),
                )
                .at(b.file, g.name_span.clone(), "declared without `[]`")
                .with_note("a geometry shader receives every vertex of its input primitive, so each input is an array with one element per vertex")
                .with_help(format!("declare it as `in {ty} {name}[];`")),
            );
        }
        for &i in &self.ins.blocks {
            let g = &b.globals[i];
            let Some(blk) = &g.block else { continue };
            if !blk.instance_dims.is_empty() {
                continue;
            }
            let bn = b.original_name(&blk.block_name);
            let (span, label) = match &blk.instance_span {
                Some(s) => (s.clone(), "instance declared without `[]`"),
                None => (blk.block_name_span.clone(), "block declared without an instance array"),
            };
            let inst = blk.instance.as_deref().map_or("gs_in", |n| b.original_name(n));
            self.out.push(
                Diagnostic::new(
                    Code::GeometryInputNotArray,
                    format!("geometry input block `{bn}` must be declared as an array"),
                )
                .at(b.file, span, label)
                .with_note("a geometry shader receives every vertex of its input primitive, so an input block's instance is an array with one element per vertex")
                .with_help(format!("declare it as `in {bn} {{ … }} {inst}[];`")),
            );
        }
    }
}
