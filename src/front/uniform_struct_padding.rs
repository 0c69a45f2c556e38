//! Structs in uniform buffers laid out the way WGSL writes them. naga's WGSL writer places a
//! struct's members at their natural offsets and writes no offsets, so a struct whose IR
//! offsets are larger — std140's, from SPIR-V: `struct PointLight { BaseLight Base; vec3
//! LocalPos; vec3 WorldPos; Attenuation Atten; }` puts `Atten` at 64 where WGSL would put it
//! at 60 — came out as WGSL that reads other bytes and that WGSL's uniform rules refuse.
//! Such a struct gets `f32` filler members (`effectc_padN`, as the GLSL route's block has)
//! in its gaps, so the natural layout is the IR's, and every member access is renumbered.

use std::collections::HashMap;

use naga::{Expression, Function, Handle, Module, Scalar, StructMember, Type, TypeInner};

/// Pads every struct reachable from a uniform buffer whose offsets WGSL's natural layout
/// does not reproduce, in each of a program's stage modules. Leaves the modules as they are
/// when that cannot be done (a gap that is no whole number of 4-byte words or follows a
/// struct or an array, no `f32`-sized scalar type to fill with, a struct built with a
/// constructor), where the WGSL writer's own checks name the problem.
///
/// The stages of one program share their uniform buffers' types: either every module is
/// padded or none is (one left unpadded would give the stages two types of one binding).
pub fn pad_uniform_structs(modules: &mut [Module]) {
    let prepared: Option<Vec<Padding>> = modules.iter().map(prepare).collect();
    for (module, padding) in modules.iter_mut().zip(prepared.unwrap_or_default()) {
        apply(module, padding);
    }
}

/// What padding one module takes: the padded types and the renumbered member accesses.
struct Padding {
    plans: Plans,
    /// (function, or entry point by position; expression; new member index)
    renumbered: Vec<(Owner, Handle<Expression>, u32)>,
}

/// The module's padding (empty when it needs none); None when it cannot be padded.
fn prepare(module: &Module) -> Option<Padding> {
    let mut layouter = naga::proc::Layouter::default();
    layouter.update(module.to_ctx()).ok()?;
    let plans = plan(module, &layouter)?;
    if plans.is_empty() {
        return Some(Padding { plans, renumbered: Vec::new() });
    }
    if constructed(module, &plans) {
        return None;
    }
    let mut renumbered = Vec::new();
    let owners = module.functions.iter().map(|(h, f)| (Owner::Function(h), f));
    for (owner, f) in owners.chain(module.entry_points.iter().enumerate().map(|(i, e)| (Owner::EntryPoint(i), &e.function))) {
        for (e, s, index) in struct_accesses(module, f)? {
            if let Some((_, new)) = plans.get(&s) {
                // A member index past the struct is not naga's IR.
                renumbered.push((owner, e, *new.get(index as usize)?));
            }
        }
    }
    Some(Padding { plans, renumbered })
}

fn apply(module: &mut Module, padding: Padding) {
    for (ty, (padded, _)) in padding.plans {
        module.types.replace(ty, padded);
    }
    for (owner, e, new) in padding.renumbered {
        let f = match owner {
            Owner::Function(h) => &mut module.functions[h],
            Owner::EntryPoint(i) => &mut module.entry_points[i].function,
        };
        if let Expression::AccessIndex { index, .. } = &mut f.expressions[e] {
            *index = new;
        }
    }
}

/// A member access: (expression, struct type, member index).
type Access = (Handle<Expression>, Handle<Type>, u32);

/// Per struct to pad: the padded type, and each old member's new index.
type Plans = HashMap<Handle<Type>, (Type, Vec<u32>)>;

#[derive(Clone, Copy)]
enum Owner {
    Function(Handle<Function>),
    EntryPoint(usize),
}

/// Every member access of `f` on a struct (a struct value held by handle, or a pointer to
/// one): (expression, struct type, member index). None when a type does not resolve.
fn struct_accesses(module: &Module, f: &Function) -> Option<Vec<Access>> {
    let ctx = naga::proc::ResolveContext::with_locals(module, &f.local_variables, &f.arguments);
    let mut typifier = naga::front::Typifier::new();
    let mut out = Vec::new();
    for (e, expression) in f.expressions.iter() {
        typifier.grow(e, &f.expressions, &ctx).ok()?;
        let Expression::AccessIndex { base, index } = *expression else { continue };
        let accessed = match (typifier.get(base, &module.types), &typifier[base]) {
            (TypeInner::Pointer { base, .. }, _) => Some(*base),
            (TypeInner::Struct { .. }, naga::proc::TypeResolution::Handle(h)) => Some(*h),
            _ => None,
        };
        if let Some(s) = accessed.filter(|s| matches!(module.types[*s].inner, TypeInner::Struct { .. })) {
            out.push((e, s, index));
        }
    }
    Some(out)
}

/// For each struct to pad: its padded type and each old member's new index. None when some
/// struct cannot be padded.
fn plan(module: &Module, layouter: &naga::proc::Layouter) -> Option<Plans> {
    let mut plans = HashMap::new();
    for ty in crate::front::naga_run::uniform_structs(module, |_| true) {
        let TypeInner::Struct { members, span } = &module.types[ty].inner else { continue };
        if let Some(padded) = padded(module, layouter, ty, members, *span)? {
            plans.insert(ty, padded);
        }
    }
    Some(plans)
}

/// The struct with fillers where WGSL's natural layout falls short of `members`' offsets,
/// and the new index of each member; `Some(None)` when nothing needs filling, `None` when a
/// gap cannot be filled.
fn padded(
    module: &Module,
    layouter: &naga::proc::Layouter,
    ty: Handle<Type>,
    members: &[StructMember],
    span: u32,
) -> Option<Option<(Type, Vec<u32>)>> {
    let mut out: Vec<StructMember> = Vec::new();
    let mut index = Vec::new();
    let mut cursor = 0u32;
    let mut fillers = 0u32;
    let mut align = naga::proc::Alignment::ONE;
    let mut filler = None;
    let mut fill = |out: &mut Vec<StructMember>, from: u32, to: u32| -> Option<()> {
        if !(to - from).is_multiple_of(4) || !from.is_multiple_of(4) {
            return None;
        }
        // Types may refer only to earlier types: the filler must precede the struct.
        let f32_ty = *filler.get_or_insert_with(|| word_type(module, ty));
        let f32_ty = f32_ty?;
        for offset in (from..to).step_by(4) {
            out.push(StructMember { name: Some(format!("effectc_pad{fillers}")), ty: f32_ty, binding: None, offset });
            fillers += 1;
        }
        Some(())
    };
    // WGSL's uniform rules want a struct or array member followed by nothing closer than
    // roundUp(16, its size): a filler cannot go there (std140 rounds a struct's size to 16,
    // which naga's span of it does not say).
    let mut after_aggregate = false;
    for m in members {
        let layout = layouter[m.ty];
        let natural = layout.alignment.round_up(cursor);
        if m.offset < natural {
            return None;
        }
        if m.offset > natural {
            if after_aggregate {
                return None;
            }
            fill(&mut out, cursor, m.offset)?;
        }
        index.push(out.len() as u32);
        out.push(m.clone());
        cursor = m.offset + layout.size;
        align = align.max(layout.alignment);
        after_aggregate = matches!(module.types[m.ty].inner, TypeInner::Struct { .. } | TypeInner::Array { .. });
    }
    if align.round_up(cursor) < span {
        if after_aggregate {
            return None;
        }
        fill(&mut out, cursor, span)?;
    }
    if fillers == 0 {
        return Some(None);
    }
    let name = module.types[ty].name.clone();
    Some(Some((Type { name, inner: TypeInner::Struct { members: out, span } }, index)))
}

/// A 4-byte scalar type declared before `before` (`f32`, else `u32` or `i32`).
fn word_type(module: &Module, before: Handle<Type>) -> Option<Handle<Type>> {
    [Scalar::F32, Scalar::U32, Scalar::I32]
        .into_iter()
        .find_map(|s| module.types.iter().find(|(h, t)| h.index() < before.index() && t.inner == TypeInner::Scalar(s)).map(|(h, _)| h))
}

/// Whether any code builds one of the structs with a constructor (it would need the fillers).
fn constructed(module: &Module, plans: &Plans) -> bool {
    let builds = |e: &Expression| matches!(e, Expression::Compose { ty, .. } if plans.contains_key(ty));
    module.global_expressions.iter().any(|(_, e)| builds(e))
        || module.functions.iter().any(|(_, f)| f.expressions.iter().any(|(_, e)| builds(e)))
        || module.entry_points.iter().any(|ep| ep.function.expressions.iter().any(|(_, e)| builds(e)))
}
