//! Varying packing: GL's linker packs scalar and narrow vector varyings four components to
//! a location (`out float m[16]` takes 4 of them in Mesa), so a program may pass more of
//! them than WebGPU has locations (16 by default): each one takes a whole location in WGSL.
//! When the vertex → fragment interface needs more locations than that, its scalars and
//! 2/3-vectors of one kind and interpolation are packed into 4-vectors, component after
//! component (a vector may straddle two locations, as in Mesa's packing).
//!
//! Both entry points keep their code: each becomes a plain function, called by a new entry
//! point with the packed interface (the vertex one composes the packed vectors from the
//! old result, the fragment one hands the old function its components).

use std::collections::BTreeMap;

use super::prune::location_of;

use naga::{
    Binding, Block, EntryPoint, Expression, Function, FunctionArgument, FunctionResult, Handle, Literal, Module, Scalar, ScalarKind,
    ShaderStage, Span, Statement, StructMember, Type, TypeInner, VectorSize,
};

/// WebGPU's default `maxInterStageShaderVariables`: locations 0 to 15.
pub const WEBGPU_LOCATIONS: u32 = 16;

/// Where one varying of the old interface goes.
#[derive(Debug, Clone)]
enum Place {
    /// A location of its own (a 4-vector, a matrix column, anything not packed).
    Own(u32),
    /// (location, component) of each of its components, in order.
    Packed(Vec<(u32, u32)>),
}

/// Packs the vertex → fragment interface of `module` (one vertex and one fragment entry
/// point) when it uses more than `limit` locations. Returns whether it did.
pub fn pack_varyings(module: &mut Module, limit: u32) -> bool {
    let Some(vi) = module.entry_points.iter().position(|e| e.stage == ShaderStage::Vertex) else { return false };
    let Some(result) = module.entry_points[vi].function.result.clone() else { return false };
    let TypeInner::Struct { members, .. } = module.types[result.ty].inner.clone() else { return false };
    if members.iter().filter(|m| location_of(&m.binding).is_some()).count() as u32 <= limit {
        return false;
    }
    let fragment = module.entry_points.iter().position(|e| e.stage == ShaderStage::Fragment);
    if let Some(fi) = fragment {
        // Struct-typed inputs (members bound one by one) are left alone.
        let args = &module.entry_points[fi].function.arguments;
        if args.iter().any(|a| a.binding.is_none() && matches!(module.types[a.ty].inner, TypeInner::Struct { .. })) {
            return false;
        }
    }
    let (places, packed) = plan(module, &members);
    if packed.is_empty() {
        return false;
    }
    let packed_ty = packed_struct(module, &members, &places, &packed);
    wrap_vertex(module, vi, &members, &places, packed_ty);
    if let Some(fi) = fragment {
        wrap_fragment(module, fi, &places, &packed);
    }
    true
}

/// What can share a 4-vector with what: scalar kind and width, interpolation, sampling.
type Class = (ScalarKind, u8, Option<naga::Interpolation>, Option<naga::Sampling>);

/// A scalar or 2/3-vector of 32-bit numbers: (class, components).
fn packable(module: &Module, m: &StructMember) -> Option<(Class, u32)> {
    let Some(Binding::Location { interpolation, sampling, blend_src: None, per_primitive: false, .. }) = m.binding else { return None };
    let (scalar, width) = match module.types[m.ty].inner {
        TypeInner::Scalar(s) => (s, 1),
        TypeInner::Vector { size, scalar } if size != VectorSize::Quad => (scalar, size as u32),
        _ => return None,
    };
    if scalar.width != 4 || !matches!(scalar.kind, ScalarKind::Float | ScalarKind::Sint | ScalarKind::Uint) {
        return None;
    }
    Some(((scalar.kind, scalar.width, interpolation, sampling), width))
}

/// Old location → place, and each packed location with the binding and scalar it takes
/// from its first varying. Unpackable varyings come first, in location order; then each
/// class's varyings fill 4-vectors component after component.
#[allow(clippy::type_complexity)]
fn plan(module: &Module, members: &[StructMember]) -> (BTreeMap<u32, Place>, BTreeMap<u32, (Binding, Scalar)>) {
    let mut places = BTreeMap::new();
    let mut next = 0u32;
    let mut loose: Vec<(&StructMember, u32, Class, u32)> = Vec::new();
    let mut by_location: Vec<(&StructMember, u32)> = members.iter().filter_map(|m| location_of(&m.binding).map(|l| (m, l))).collect();
    by_location.sort_by_key(|(_, l)| *l);
    for (m, location) in by_location {
        match packable(module, m) {
            Some((class, width)) => loose.push((m, location, class, width)),
            None => {
                places.insert(location, Place::Own(next));
                next += 1;
            }
        }
    }
    let mut packed: BTreeMap<u32, (Binding, Scalar)> = BTreeMap::new();
    // Per class: (location being filled, components used).
    let mut cursors: Vec<(Class, u32, u32)> = Vec::new();
    for (m, location, class, width) in loose {
        let mut slots = Vec::new();
        for _ in 0..width {
            let cursor = match cursors.iter_mut().find(|(c, _, used)| *c == class && *used < 4) {
                Some(c) => c,
                None => {
                    packed.insert(next, (relocated(m.binding.as_ref(), next), scalar_of(module, m.ty)));
                    cursors.push((class, next, 0));
                    next += 1;
                    cursors.last_mut().expect("just pushed")
                }
            };
            slots.push((cursor.1, cursor.2));
            cursor.2 += 1;
        }
        places.insert(location, Place::Packed(slots));
    }
    (places, packed)
}

/// Where a member of the packed output struct comes from.
#[derive(Debug, Clone, Copy)]
enum Source {
    /// The old member of this index (a built-in or an unpacked varying).
    Old(usize),
    /// The components packed into this new location.
    Packed(u32),
}

/// The packed output struct (the built-ins and unpacked varyings, then one 4-vector per
/// packed location), and where each of its members comes from.
fn packed_struct(
    module: &mut Module,
    members: &[StructMember],
    places: &BTreeMap<u32, Place>,
    packed: &BTreeMap<u32, (Binding, Scalar)>,
) -> (Handle<Type>, Vec<Source>) {
    let mut out: Vec<StructMember> = Vec::new();
    let mut sources = Vec::new();
    for (i, m) in members.iter().enumerate() {
        let binding = match location_of(&m.binding).and_then(|l| places.get(&l)) {
            None => m.binding.clone(),
            Some(Place::Own(at)) => Some(relocated(m.binding.as_ref(), *at)),
            Some(Place::Packed(_)) => continue,
        };
        out.push(StructMember { binding, ..m.clone() });
        sources.push(Source::Old(i));
    }
    for (&at, (binding, scalar)) in packed {
        let ty = vec4_of(module, *scalar);
        out.push(StructMember { name: Some(format!("effectc_packed{at}")), ty, binding: Some(binding.clone()), offset: 0 });
        sources.push(Source::Packed(at));
    }
    // Every member at a 16-byte boundary (no member is wider than its rounded size).
    let mut offset = 0;
    for m in &mut out {
        m.offset = offset;
        offset += module.types[m.ty].inner.size(module.to_ctx()).next_multiple_of(16).max(16);
    }
    let inner = TypeInner::Struct { members: out, span: offset };
    (module.types.insert(Type { name: Some("EffectcPackedOutput".into()), inner }, Span::UNDEFINED), sources)
}

fn vec4_of(module: &mut Module, scalar: Scalar) -> Handle<Type> {
    module.types.insert(Type { name: None, inner: TypeInner::Vector { size: VectorSize::Quad, scalar } }, Span::UNDEFINED)
}

fn relocated(b: Option<&Binding>, location: u32) -> Binding {
    match b.cloned() {
        Some(Binding::Location { interpolation, sampling, blend_src, per_primitive, .. }) => {
            Binding::Location { location, interpolation, sampling, blend_src, per_primitive }
        }
        other => {
            other.unwrap_or(Binding::Location { location, interpolation: None, sampling: None, blend_src: None, per_primitive: false })
        }
    }
}

fn scalar_of(module: &Module, ty: Handle<Type>) -> Scalar {
    match module.types[ty].inner {
        TypeInner::Scalar(s) | TypeInner::Vector { scalar: s, .. } => s,
        _ => Scalar::F32,
    }
}

fn zero(scalar: Scalar) -> Literal {
    match scalar.kind {
        ScalarKind::Sint => Literal::I32(0),
        ScalarKind::Uint => Literal::U32(0),
        _ => Literal::F32(0.0),
    }
}

/// Turns entry point `index` into a plain function (bindings dropped), and returns it with
/// a code-less copy of the entry point and the entry point's own arguments.
fn demote(module: &mut Module, index: usize) -> (Handle<Function>, EntryPoint, Vec<FunctionArgument>) {
    let ep = &mut module.entry_points[index];
    let mut inner = std::mem::take(&mut ep.function);
    let original_args = inner.arguments.clone();
    for a in &mut inner.arguments {
        a.binding = None;
    }
    if let Some(r) = &mut inner.result {
        r.binding = None;
    }
    inner.name = Some(format!("effectc_{}_unpacked", ep.name));
    let shell = EntryPoint { function: Function { name: Some(ep.name.clone()), ..Function::default() }, ..ep.clone() };
    let handle = module.functions.append(inner, Span::UNDEFINED);
    (handle, shell, original_args)
}

/// The vertex entry point: calls the old one and composes the packed struct from its result.
fn wrap_vertex(
    module: &mut Module,
    index: usize,
    members: &[StructMember],
    places: &BTreeMap<u32, Place>,
    (packed_ty, sources): (Handle<Type>, Vec<Source>),
) {
    let (inner, mut ep, args) = demote(module, index);
    let TypeInner::Struct { members: packed_members, .. } = module.types[packed_ty].inner.clone() else { return };
    let f = &mut ep.function;
    f.arguments = args;
    let call_args: Vec<Handle<Expression>> =
        (0..f.arguments.len() as u32).map(|i| f.expressions.append(Expression::FunctionArgument(i), Span::UNDEFINED)).collect();
    let result = f.expressions.append(Expression::CallResult(inner), Span::UNDEFINED);
    // Padding literals first: they are not emitted.
    let zeros: Vec<(Scalar, Handle<Expression>)> = [Scalar::F32, Scalar::I32, Scalar::U32]
        .into_iter()
        .map(|s| (s, f.expressions.append(Expression::Literal(zero(s)), Span::UNDEFINED)))
        .collect();
    let start = f.expressions.len();
    let member =
        |f: &mut Function, i: usize| f.expressions.append(Expression::AccessIndex { base: result, index: i as u32 }, Span::UNDEFINED);
    let mut fields = Vec::new();
    for (pm, source) in packed_members.iter().zip(sources) {
        let at = match source {
            Source::Old(old) => {
                fields.push(member(f, old));
                continue;
            }
            Source::Packed(at) => at,
        };
        let mut components: Vec<(u32, Handle<Expression>)> = Vec::new();
        for (i, m) in members.iter().enumerate() {
            let Some(Place::Packed(slots)) = location_of(&m.binding).and_then(|l| places.get(&l)) else { continue };
            for (k, &(loc, c)) in slots.iter().enumerate() {
                if loc != at {
                    continue;
                }
                let whole = member(f, i);
                let value = if slots.len() == 1 {
                    whole
                } else {
                    f.expressions.append(Expression::AccessIndex { base: whole, index: k as u32 }, Span::UNDEFINED)
                };
                components.push((c, value));
            }
        }
        components.sort_by_key(|(c, _)| *c);
        let scalar = scalar_of(module, pm.ty);
        let pad = zeros.iter().find(|(s, _)| *s == scalar).map_or(zeros[0].1, |(_, h)| *h);
        let mut parts: Vec<Handle<Expression>> = components.into_iter().map(|(_, h)| h).collect();
        parts.resize(4, pad);
        fields.push(f.expressions.append(Expression::Compose { ty: pm.ty, components: parts }, Span::UNDEFINED));
    }
    let value = f.expressions.append(Expression::Compose { ty: packed_ty, components: fields }, Span::UNDEFINED);
    let emitted = f.expressions.range_from(start);
    f.result = Some(FunctionResult { ty: packed_ty, binding: None });
    let mut body = Block::new();
    body.push(Statement::Call { function: inner, arguments: call_args, result: Some(result) }, Span::UNDEFINED);
    body.push(Statement::Emit(emitted), Span::UNDEFINED);
    body.push(Statement::Return { value: Some(value) }, Span::UNDEFINED);
    f.body = body;
    module.entry_points[index] = ep;
}

/// The fragment entry point: takes the packed interface and hands the old one its inputs.
fn wrap_fragment(module: &mut Module, index: usize, places: &BTreeMap<u32, Place>, packed: &BTreeMap<u32, (Binding, Scalar)>) {
    // The fragment result keeps its bindings (its struct's, or the result's own).
    let original_result = module.entry_points[index].function.result.clone();
    let (inner, mut ep, old_args) = demote(module, index);
    // The old arguments that keep a location of their own (or are built-ins), then one
    // 4-vector per packed location.
    let mut arguments: Vec<FunctionArgument> = Vec::new();
    for a in &old_args {
        match location_of(&a.binding).and_then(|l| places.get(&l)) {
            Some(Place::Packed(_)) => {}
            Some(Place::Own(at)) => arguments.push(FunctionArgument { binding: Some(relocated(a.binding.as_ref(), *at)), ..a.clone() }),
            None => arguments.push(a.clone()),
        }
    }
    let first_packed = arguments.len();
    // The packed locations the old inputs read (an output no input receives stays unread).
    let read: Vec<u32> = old_args
        .iter()
        .filter_map(|a| match location_of(&a.binding).and_then(|l| places.get(&l)) {
            Some(Place::Packed(slots)) => Some(slots.iter().map(|(loc, _)| *loc).collect::<Vec<_>>()),
            _ => None,
        })
        .flatten()
        .collect();
    let packed: BTreeMap<u32, (Binding, Scalar)> =
        packed.iter().filter(|(at, _)| read.contains(at)).map(|(k, v)| (*k, v.clone())).collect();
    let packed = &packed;
    for (&at, (binding, scalar)) in packed {
        let ty = vec4_of(module, *scalar);
        arguments.push(FunctionArgument { name: Some(format!("effectc_packed{at}")), ty, binding: Some(binding.clone()) });
    }
    let f = &mut ep.function;
    let args: Vec<Handle<Expression>> =
        (0..arguments.len() as u32).map(|i| f.expressions.append(Expression::FunctionArgument(i), Span::UNDEFINED)).collect();
    let packed_arg = |loc: u32| args[first_packed + packed.keys().position(|&k| k == loc).unwrap_or(0)];
    let result = module.functions[inner].result.as_ref().map(|_| f.expressions.append(Expression::CallResult(inner), Span::UNDEFINED));
    let start = f.expressions.len();
    let mut own = 0;
    let mut call_args = Vec::new();
    for a in &old_args {
        let value = match location_of(&a.binding).and_then(|l| places.get(&l)) {
            Some(Place::Packed(slots)) => {
                let mut parts: Vec<Handle<Expression>> = slots
                    .iter()
                    .map(|&(loc, c)| f.expressions.append(Expression::AccessIndex { base: packed_arg(loc), index: c }, Span::UNDEFINED))
                    .collect();
                if parts.len() == 1 {
                    parts.remove(0)
                } else {
                    f.expressions.append(Expression::Compose { ty: a.ty, components: parts }, Span::UNDEFINED)
                }
            }
            _ => {
                own += 1;
                args[own - 1]
            }
        };
        call_args.push(value);
    }
    let emitted = f.expressions.range_from(start);
    f.arguments = arguments;
    f.result = original_result;
    let mut body = Block::new();
    body.push(Statement::Emit(emitted), Span::UNDEFINED);
    body.push(Statement::Call { function: inner, arguments: call_args, result }, Span::UNDEFINED);
    body.push(Statement::Return { value: result }, Span::UNDEFINED);
    f.body = body;
    module.entry_points[index] = ep;
}
