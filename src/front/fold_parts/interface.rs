//! The varyings between the folded stages, made private: each loose varying and each block
//! member becomes a [`Leaf`] at its first location (arrays and matrices take several, as GL
//! counts them), so a geometry input is fed from the vertex output at its location, and a
//! geometry output leaves as one `out` per location.

use std::fmt::Write as _;

use crate::front::plan::location_slots;
use crate::front::syntax::{dims_text, matrix_shape, Global, GlslType, Interp, StageSyntax};

/// One varying of the folded interface: a loose varying, or one member of a block.
#[derive(Debug, Clone)]
pub(crate) struct Leaf {
    /// Its first location.
    pub location: u32,
    /// The private variable (for a geometry input: the array over the corners) …
    base: String,
    /// … and, for a member of a named block, the member.
    field: Option<String>,
    /// Its type at one vertex.
    pub ty: GlslType,
    /// Interpolation qualifier as written (`flat`, `noperspective`), or empty.
    pub interp: String,
    /// The locations it takes.
    pub slots: u32,
}

impl Leaf {
    /// The expression naming it (at `corner` of a geometry input).
    pub fn access(&self, corner: Option<u32>) -> String {
        let mut s = self.base.clone();
        if let Some(k) = corner {
            write!(s, "[{k}]").unwrap();
        }
        if let Some(f) = &self.field {
            write!(s, ".{f}").unwrap();
        }
        s
    }

    /// Each location it takes as (location, type of the `out` there, the part of the leaf
    /// written there): array elements in order, a matrix column by column.
    pub fn locations(&self) -> Vec<(u32, String, String)> {
        let (columns, slot_type) = match matrix_shape(&self.ty.base) {
            Some((cols, rows)) => (Some(cols), format!("vec{rows}")),
            None => (None, self.ty.base.clone()),
        };
        let mut out = Vec::new();
        for e in self.ty.element_suffixes() {
            match columns {
                Some(cols) => (0..cols).for_each(|c| out.push((self.location + out.len() as u32, slot_type.clone(), format!("{e}[{c}]")))),
                None => out.push((self.location + out.len() as u32, slot_type.clone(), e)),
            }
        }
        out
    }
}

/// The statements feeding input `input` (at `corner` of an arrayed input) from the earlier
/// stage's `outputs` (at `from` of a tessellation control stage's arrayed outputs): from the
/// output at its location (element by element for an array), or piece by piece where the
/// earlier stage passes it so (the rewrite splits matrix varyings into columns, and a
/// block's array members into elements). None: no output feeds it (undefined in GL; it
/// stays zero).
pub(crate) fn feed(input: &Leaf, corner: Option<u32>, outputs: &[Leaf], from: Option<u32>) -> Option<String> {
    let at = |location: u32| outputs.iter().find(|o| o.location == location);
    let first = at(input.location)?;
    let dst = input.access(corner);
    if first.ty == input.ty {
        return Some(input.ty.copy(&dst, &first.access(from)));
    }
    let mut statements = String::new();
    for (location, _, part) in input.locations() {
        write!(statements, " {dst}{part} = {};", at(location)?.access(from)).unwrap();
    }
    Some(statements)
}

/// The `out` declarations of a folded program's last stage's `outputs`, one per location,
/// and the statements that copy each from `source(i, leaf)` (an expression of the leaf's
/// type).
pub(crate) fn stage_outputs(outputs: &[Leaf], source: impl Fn(usize, &Leaf) -> String) -> (String, String) {
    let (mut declarations, mut assign) = (String::new(), String::new());
    for (i, o) in outputs.iter().enumerate() {
        // naga wants integer outputs `flat` (GL never interpolates them).
        let interp = if o.interp.is_empty() && o.ty.is_integer() { "flat" } else { o.interp.as_str() };
        let from = source(i, o);
        for (location, ty, part) in o.locations() {
            writeln!(declarations, "layout(location = {location}) {interp} out {ty} effectc_out_{location};").unwrap();
            writeln!(assign, "        effectc_out_{location} = {from}{part};").unwrap();
        }
    }
    (declarations, assign)
}

/// The first location after every leaf's.
pub(crate) fn next_location(leaves: &[Leaf]) -> u32 {
    leaves.iter().map(|l| l.location + l.slots).max().unwrap_or(0)
}

/// Whether a varying of this type can be made private and passed on: float and integer
/// scalars, vectors, float matrices, and sized arrays of them.
fn passable(ty: &GlslType) -> bool {
    (ty.vector_components().is_some() || matrix_shape(&ty.base).is_some()) && ty.dims.iter().all(Option::is_some)
}

/// Declares a varying as private globals in `out` (a struct for a named block, one global
/// per member of an unnamed one; an array of `corners` for a geometry or tessellation
/// input and a tessellation control output) and returns its
/// leaves. `renamed` is its name with the stage's prefix; `as_written` is the declaration in
/// the user's text (the rewritten one lacks member interpolation qualifiers).
pub(super) fn private_varying(
    g: &Global,
    s: &StageSyntax,
    as_written: Option<&Global>,
    renamed: &str,
    corners: Option<u32>,
    out: &mut String,
) -> Result<Vec<Leaf>, String> {
    let keyword = |i: Option<Interp>| i.map(|i| i.keyword().to_string()).unwrap_or_default();
    let per_corner = corners;
    let corner_dims = per_corner.map(|n| format!("[{n}]")).unwrap_or_default();
    let location = g.location.ok_or_else(|| format!("the varying `{}` without a location", g.name))?;
    let Some(b) = &g.block else {
        let ty = if per_corner.is_some() { g.ty.element() } else { g.ty.clone() };
        if let Some(def) = s.structs.iter().find(|d| d.name == ty.base).filter(|_| ty.dims.is_empty()) {
            // A struct varying: one leaf per member, at consecutive locations (the struct
            // is declared with the part's declarations).
            writeln!(out, "{} {renamed}{corner_dims};", ty.base).unwrap();
            let mut leaves = Vec::new();
            let mut at = location;
            for m in &def.members {
                if !passable(&m.ty) {
                    return Err(format!("the varying `{}` of type `{}` with member `{}` of type `{}`", g.name, ty.base, m.name, m.ty));
                }
                let slots = location_slots(&m.ty, s);
                let interp = keyword(m.interp.or(g.interp));
                leaves.push(Leaf { location: at, base: renamed.to_string(), field: Some(m.name.clone()), ty: m.ty.clone(), interp, slots });
                at += slots;
            }
            return Ok(leaves);
        }
        if !passable(&ty) {
            return Err(format!("the varying `{}` of type `{ty}`", g.name));
        }
        writeln!(out, "{} {renamed}{corner_dims}{};", ty.base, dims_text(&ty)).unwrap();
        let slots = location_slots(&ty, s);
        return Ok(vec![Leaf { location, base: renamed.to_string(), field: None, ty, interp: keyword(g.interp), slots }]);
    };
    let instance_dims = b.instance_dims.len() - usize::from(per_corner.is_some() && !b.instance_dims.is_empty());
    if instance_dims > 0 {
        return Err(format!("the array of blocks `{}`", b.block_name));
    }
    let prefix = &renamed[..renamed.len() - g.name.len()];
    let written = as_written.and_then(|w| w.block.as_ref());
    let block_interp = as_written.and_then(|w| w.interp).or(g.interp);
    let (base, struct_name) = match &b.instance {
        // Uses name the instance; the struct is named after it too (an input and an output
        // block may share a block name), both prefixed.
        Some(instance) => (format!("{prefix}{instance}"), Some(format!("{prefix}{instance}_block"))),
        None if per_corner.is_some() => return Err(format!("the input block `{}` without an instance name", b.block_name)),
        None => (String::new(), None),
    };
    let mut leaves = Vec::new();
    let mut at = location;
    let mut fields = String::new();
    for m in &b.members {
        if !passable(&m.ty) {
            return Err(format!("the block member `{}.{}` of type `{}`", b.block_name, m.name, m.ty));
        }
        let interp = written.and_then(|w| w.members.iter().find(|x| x.name == m.name)).and_then(|x| x.interp).or(m.interp).or(block_interp);
        let slots = location_slots(&m.ty, s);
        let (leaf_base, field) = match &struct_name {
            Some(_) => {
                write!(fields, " {} {}{};", m.ty.base, m.name, dims_text(&m.ty)).unwrap();
                (base.clone(), Some(m.name.clone()))
            }
            None => {
                // An unnamed block's members are used by their own names.
                writeln!(out, "{} {prefix}{}{};", m.ty.base, m.name, dims_text(&m.ty)).unwrap();
                (format!("{prefix}{}", m.name), None)
            }
        };
        leaves.push(Leaf { location: at, base: leaf_base, field, ty: m.ty.clone(), interp: keyword(interp), slots });
        at += slots;
    }
    if let Some(struct_name) = struct_name {
        writeln!(out, "struct {struct_name} {{{fields} }};\n{struct_name} {base}{corner_dims};").unwrap();
    }
    Ok(leaves)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn leaf(ty: &str, dims: Vec<Option<u32>>, location: u32) -> Leaf {
        let ty = GlslType { base: ty.into(), dims };
        Leaf { location, base: "v".into(), field: None, ty, interp: String::new(), slots: 0 }
    }

    #[test]
    fn arrays_and_matrices_take_one_location_per_element_and_column() {
        let l = leaf("vec4", vec![Some(3)], 2);
        let at: Vec<(u32, String)> = l.locations().into_iter().map(|(loc, _, part)| (loc, part)).collect();
        assert_eq!(at, vec![(2, "[0]".into()), (3, "[1]".into()), (4, "[2]".into())]);
        let m = leaf("mat3x2", vec![Some(2)], 0);
        let at: Vec<(u32, String, String)> = m.locations();
        assert_eq!(at.len(), 6);
        assert_eq!(at[4], (4, "vec2".into(), "[1][1]".into()));
        assert_eq!(leaf("float", vec![], 7).locations(), vec![(7, "float".into(), String::new())]);
    }

    #[test]
    fn only_sized_numeric_varyings_pass() {
        assert!(passable(&GlslType { base: "mat4".into(), dims: vec![Some(2)] }));
        assert!(passable(&GlslType::scalar("uvec3")));
        assert!(!passable(&GlslType { base: "float".into(), dims: vec![None] }));
        assert!(!passable(&GlslType::scalar("Light")));
        assert!(!passable(&GlslType::scalar("bool")));
        assert_eq!(matrix_shape("mat2x4"), Some((2, 4)));
        assert_eq!(matrix_shape("mat5"), None);
    }
}
