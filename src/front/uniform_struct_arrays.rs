//! Arrays of scalars and 2-vectors inside a struct that only uniforms have as their type
//! (`struct Light { int diffuse[2]; }; uniform Light lights[16];`, or a member of a uniform
//! block): std140 strides each element to 16 bytes, naga's IR keeps that stride, and WGSL's
//! uniform rules refuse an `i32` or `vec2` array with it. Such a member is stored as an array
//! of 4-vectors (`ivec4 diffuse[2]`, the same bytes) and every use reads its first components
//! back (`lights[i].diffuse[j].x`; the rewrite's `uniform_struct_arrays`), as a uniform
//! block's own members are ([`crate::front::rewrite`]'s `block_members`).
//!
//! Decided once for the program (every stage declares the struct alike, and the shared
//! uniform block holds it): only a struct named nowhere but in its definitions and in the
//! declarations of uniforms (or uniform block members) of its type, in every stage, whose
//! widened members are read only as `uniform[…].member[i]` / `uniform.member[i]`; any other
//! struct is left as written (translate then names the stride, E0306).

use std::collections::BTreeMap;
use std::ops::Range;

use crate::front::syntax::{bracket_after, word_occurrences, Global, GlslType, Referent, StageSyntax, Storage, Use};
use crate::front::uniform_repr::{repr_for, Repr};

/// How a member is stored as 4-vectors ([`repr_for`]'s padded arrays of `float`, `int`,
/// `uint` and their 2-vectors): the stored type and the components that read it back.
pub fn widened(ty: &GlslType) -> Option<(String, &'static str)> {
    match repr_for(ty, false) {
        (stored, Repr::Padded { swizzle, bool_elems: false }) if !stored.base.starts_with('d') => Some((stored.base, swizzle)),
        _ => None,
    }
}

/// The type the name a use reads has as a uniform: a loose uniform's type, or the type of
/// the unnamed uniform block member of that name.
fn uniform_type<'a>(g: &'a Global, name: &str) -> Option<&'a GlslType> {
    if g.storage != Storage::Uniform {
        return None;
    }
    match &g.block {
        None => Some(&g.ty),
        Some(b) if b.instance.is_none() => b.members.iter().find(|m| m.name == name).map(|m| &m.ty),
        Some(_) => None,
    }
}

/// Each use in `s` of a member of struct `name` as a uniform's: (the use, the member).
pub fn member_reads<'a>(s: &'a StageSyntax, name: &'a str) -> impl Iterator<Item = (&'a Use, &'a str)> + 'a {
    s.uses.iter().filter_map(move |u| {
        let Referent::Global(gi) = u.target else { return None };
        let ty = uniform_type(&s.globals[gi], &u.name)?;
        let (field, _) = u.field.as_ref()?;
        (ty.base == name).then_some((u, field.as_str()))
    })
}

/// The end of the `[…]` right after a member read's dot expression, if one follows.
pub fn index_end(s: &StageSyntax, u: &Use) -> Option<usize> {
    bracket_after(&s.text, u.field.as_ref()?.1.end)
}

/// The members to store as 4-vectors, by struct name (module doc).
pub fn widened_members(stages: &[StageSyntax]) -> BTreeMap<String, Vec<String>> {
    let mut out = BTreeMap::new();
    let names: std::collections::BTreeSet<&str> = stages.iter().flat_map(|s| s.structs.iter().map(|d| d.name.as_str())).collect();
    for name in names {
        let Some(def) = stages.iter().find_map(|s| s.struct_def(name)) else { continue };
        let members: Vec<String> = def.members.iter().filter(|m| widened(&m.ty).is_some()).map(|m| m.name.clone()).collect();
        if !members.is_empty() && stages.iter().all(|s| followed(s, name, &members)) {
            out.insert(name.to_string(), members);
        }
    }
    out
}

/// Whether stage `s` names struct `name` only where the rewrite can follow it and reads each
/// of `members` indexed.
fn followed(s: &StageSyntax, name: &str, members: &[String]) -> bool {
    let typed: Vec<Range<usize>> = s
        .globals
        .iter()
        .filter(|g| g.storage == Storage::Uniform)
        .flat_map(|g| match &g.block {
            None => (g.ty.base == name).then(|| g.decl_span.clone()).into_iter().collect::<Vec<_>>(),
            Some(b) => b.members.iter().filter(|m| m.ty.base == name).map(|m| m.field_span.clone()).collect(),
        })
        .collect();
    let definition = s.struct_def(name).map(|d| d.name_span.clone());
    let named_elsewhere = word_occurrences(&s.text, 0..s.text.len(), name)
        .into_iter()
        .any(|at| Some(&at) != definition.as_ref() && !typed.iter().any(|t| t.start <= at.start && at.end <= t.end));
    !named_elsewhere && member_reads(s, name).filter(|(_, f)| members.iter().any(|m| m == f)).all(|(u, _)| index_end(s, u).is_some())
}
