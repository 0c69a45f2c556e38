//! Interface blocks naga cannot take as declared (an array member before another member, or
//! a matrix member: naga's GLSL front gives each member one location and reads no matrix
//! varyings) become loose varyings at the locations GL gives the members, one per member,
//! array element and matrix column; the block itself becomes a private
//! variable of the same shape, copied from the loose inputs at the start of `main` or to the
//! loose outputs at its end, so its uses stay as written.

use std::fmt::Write;

use super::Ctx;
use crate::front::plan::location_slots;
use crate::front::syntax::{dims_text, matrix_shape, Global, Member, Storage};
use crate::stage::StageKind;

/// The member of an interface block that naga cannot take as declared: an array member
/// with a member after it (it would collide with the next location), or a matrix member.
pub(super) fn awkward_member(g: &Global) -> Option<&Member> {
    let b = g.block.as_ref()?;
    if !matches!(g.storage, Storage::In | Storage::Out) || g.name.starts_with("gl_") {
        return None;
    }
    let n = b.members.len();
    b.members.iter().enumerate().find(|(i, m)| (m.ty.is_array() && i + 1 < n) || matrix_shape(&m.ty.base).is_some()).map(|(_, m)| m)
}

impl Ctx<'_> {
    /// Whether `g` is an awkward block this stage passes as loose varyings: a vertex
    /// stage's output or a fragment stage's input (the geometry fold passes a geometry
    /// stage's own blocks), not an array of blocks, members sized scalars, vectors, matrices
    /// of three or four rows, or arrays of scalars and vectors.
    pub(super) fn flattens(&self, g: &Global) -> bool {
        let (Some(b), Some(_)) = (&g.block, awkward_member(g)) else { return false };
        let io = matches!((self.s.stage, g.storage), (StageKind::Vertex, Storage::Out) | (StageKind::Fragment, Storage::In));
        let plain = |m: &Member| {
            // (naga's GLSL front lays every struct out by std140 rules, where it refuses
            // two-row matrices: gfx-rs/wgpu#4375.)
            let matrix = matrix_shape(&m.ty.base).is_some_and(|(_, rows)| rows != 2) && !m.ty.is_array();
            m.ty.dims.iter().all(Option::is_some) && (m.ty.vector_components().is_some() || matrix)
        };
        io && b.instance_dims.is_empty() && b.members.iter().all(plain)
    }

    /// Writes block `g` as loose varyings plus a private variable of its shape, and the
    /// copies between them.
    pub(super) fn flatten_block(&mut self, g: &Global) {
        let s = self.s;
        let b = g.block.as_ref().expect("a block");
        let mut at = g.location.or_else(|| self.plan.varyings.get(&g.name).copied()).unwrap_or(0);
        let dir = if g.storage == Storage::In { "in" } else { "out" };
        let struct_name = format!("effectc_{dir}_{}", b.block_name);
        let mut text = String::new();
        let mut fields = String::new();
        let mut copies = String::new();
        for m in &b.members {
            let interp = m.interp.or(g.interp).map(|i| format!("{} ", i.keyword()));
            let interp = interp.unwrap_or_else(|| if m.ty.is_integer() { "flat ".into() } else { String::new() });
            let centroid = if m.centroid || g.centroid { "centroid " } else { "" };
            let loose = format!("effectc_{}_{}", b.block_name, m.name);
            let private = match &b.instance {
                Some(instance) => format!("{instance}.{}", m.name),
                None => m.name.clone(),
            };
            let dims = dims_text(&m.ty);
            write!(fields, " {} {}{dims};", m.ty.base, m.name).unwrap();
            match matrix_shape(&m.ty.base) {
                Some((cols, rows)) => {
                    let columns: Vec<String> = (0..cols).map(|c| format!("{loose}_col{c}")).collect();
                    for (c, column) in columns.iter().enumerate() {
                        write!(text, "layout(location = {}) {interp}{centroid}{dir} vec{rows} {column}; ", at + c as u32).unwrap();
                        if dir == "out" {
                            write!(copies, " {column} = {private}[{c}];").unwrap();
                        }
                    }
                    if dir == "in" {
                        write!(copies, " {private} = {}({});", m.ty.base, columns.join(", ")).unwrap();
                    }
                }
                None => {
                    // One varying per array element: naga's GLSL front drops the
                    // interpolation qualifier of an array varying's later elements.
                    for (k, element) in m.ty.element_suffixes().iter().enumerate() {
                        let one = format!("{loose}{}", element.replace(['[', ']'], "_").replace("__", "_").trim_end_matches('_'));
                        write!(text, "layout(location = {}) {interp}{centroid}{dir} {} {one}; ", at + k as u32, m.ty.base).unwrap();
                        match dir {
                            "in" => write!(copies, " {private}{element} = {one};").unwrap(),
                            _ => write!(copies, " {one} = {private}{element};").unwrap(),
                        }
                    }
                }
            }
            at += location_slots(&m.ty, s);
        }
        match &b.instance {
            Some(instance) => write!(text, "struct {struct_name} {{{fields} }}; {struct_name} {instance};").unwrap(),
            // An unnamed block's members are used by their own names.
            None => text.push_str(fields.trim_start()),
        }
        self.edits.replace(g.decl_span.clone(), text);
        if dir == "in" {
            self.prologue.push_str(&copies);
        } else {
            self.epilogue.push_str(&copies);
        }
    }
}
