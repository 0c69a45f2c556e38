//! Members of the user's own uniform blocks that WGSL cannot hold as declared, stored in a
//! type with the same std140 bytes, and read back where used: `bool`/`bvecN` as
//! `uint`/`uvecN` (std140 stores a bool in a 4-byte word), arrays of scalars and 2-vectors
//! as arrays of 4-vectors (std140 strides every array element to 16 bytes; WGSL's uniform
//! rules refuse a 4- or 8-byte stride and naga a `bool` in a uniform buffer). No offset
//! moves, so the bytes a host packs by std140 read the same.

use super::Ctx;
use crate::front::plan::{repr_for, Repr};
use crate::front::syntax::{bracket_after, word_occurrences, Global, GlslType, Member, Storage, Use};
use std::collections::BTreeMap;

/// How member type `ty` of a uniform block is stored (a representation with std140's own
/// layout, or `Plain`).
fn stored(ty: &GlslType, doubles_as_floats: bool) -> (GlslType, Repr) {
    match repr_for(ty, doubles_as_floats) {
        // `mat2` as one `vec4` is the shared block's packing, not std140's (two columns
        // 16 bytes apart).
        (_, Repr::Mat2 | Repr::Mat2Array) => (ty.clone(), Repr::Plain),
        other => other,
    }
}

/// Whether `g` is a uniform block of the user's whose members are stored as declared.
fn user_uniform_block(g: &Global) -> bool {
    g.storage == Storage::Uniform && g.block.is_some() && !g.layout_items.iter().any(|(k, _)| k == "push_constant")
}

impl Ctx<'_> {
    /// The declarations: each field of a member stored otherwise gets the stored type (a
    /// field declaring several names keeps its type unless all are stored alike).
    pub(super) fn user_block_member_types(&mut self) {
        let s = self.s;
        for g in s.globals.iter().filter(|g| user_uniform_block(g)) {
            let b = g.block.as_ref().expect("a block");
            let mut fields: BTreeMap<usize, Vec<&Member>> = BTreeMap::new();
            for m in &b.members {
                fields.entry(m.field_span.start).or_default().push(m);
            }
            for members in fields.values() {
                let bases: Vec<String> =
                    members.iter().map(|m| stored(&m.ty, self.plan.doubles_as_floats)).map(|(ty, _)| ty.base).collect();
                let first = members[0];
                if bases[0] == first.ty.base || bases.iter().any(|b| *b != bases[0]) {
                    continue;
                }
                // The type is written before the first name, after any qualifiers.
                let from = first.qualifier_span.as_ref().map_or(first.field_span.start, |q| q.end);
                let Some(at) = word_occurrences(&s.text, from..first.span.start, &first.ty.base).into_iter().next() else { continue };
                self.edits.replace(at, bases[0].clone());
            }
        }
    }

    /// A use of a member of a user uniform block (`f[i]` of an unnamed block, `b.f[i]` of
    /// a named one): read back from how it is stored.
    pub(super) fn user_block_member_use(&mut self, u: &Use, g: &Global) {
        if !user_uniform_block(g) {
            return;
        }
        let b = g.block.as_ref().expect("a block");
        let text = &self.s.text;
        let (member, span, bracket) = match (&b.instance, &u.field) {
            (None, _) => (u.name.as_str(), u.span.clone(), u.index.as_ref().map(|(bracket, _, _)| bracket.clone())),
            // (An array of blocks, `b[i].f`, keeps its members as declared.)
            (Some(_), Some((field, dot))) if u.index.is_none() => {
                let bracket = bracket_after(text, dot.end).map(|end| dot.start..end);
                (field.as_str(), dot.clone(), bracket)
            }
            _ => return,
        };
        let Some(m) = b.members.iter().find(|m| m.name == member) else { return };
        let (_, repr) = stored(&m.ty, self.plan.doubles_as_floats);
        self.read_repr(&repr, &m.ty, span, bracket);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn brackets_and_type_words_are_found_where_written() {
        let text = "u.f [a[1] + 2].x";
        assert_eq!(bracket_after(text, 3), Some(text.find(".x").unwrap()));
        assert_eq!(bracket_after("u.f + 1", 3), None);
        assert_eq!(word_occurrences("highp float floats;", 0..19, "float"), vec![6..11]);
        assert!(word_occurrences("floats x;", 0..9, "float").is_empty());
    }

    #[test]
    fn std140_keeps_its_bytes() {
        let arr = |b: &str| GlslType { base: b.into(), dims: vec![Some(4)] };
        assert_eq!(stored(&arr("float"), false).0.base, "vec4");
        assert_eq!(stored(&GlslType::scalar("bvec3"), false).0.base, "uvec3");
        assert!(matches!(stored(&GlslType::scalar("mat2"), false).1, Repr::Plain));
        assert!(matches!(stored(&arr("vec3"), false).1, Repr::Plain));
        // A double array: std140's 16-byte stride as `dvec2`, or as a `vec4` once lowered.
        assert_eq!(stored(&arr("double"), false).0.base, "dvec2");
        assert_eq!(stored(&arr("double"), true).0.base, "dvec4");
        assert!(matches!(stored(&arr("dvec2"), false).1, Repr::Plain));
        assert_eq!(stored(&arr("dvec2"), true).0.base, "dvec4");
    }
}
