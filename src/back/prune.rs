//! Leave out what the effect does not use, and say what was left out.
//!
//! naga's compaction drops functions never called and globals, constants and types nothing
//! refers to. On top of that this pass drops
//! - fragment inputs the fragment stage never reads,
//! - vertex outputs no fragment input receives (by location; built-ins stay),
//! - members of the generated uniform block no stage reads, re-laid out compactly
//!   (the reflection describes the layout that is really emitted).
//!
//! Every dropped item is reported as a [`LeftOut`] for `--explain`.

use std::collections::{BTreeSet, HashMap};

use naga::{Binding, Expression, Function, GlobalVariable, Handle, Module, Statement, StructMember, Type, TypeInner};

use crate::back::merge::visit_statements;

/// One thing the translation left out, and why.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct LeftOut {
    /// `function`, `varying`, `uniform`, `resource`, `global`, `constant`.
    pub kind: &'static str,
    pub name: String,
    pub reason: String,
}

/// Runs every pruning step; `uniform_block` names the generated uniform struct.
pub fn prune(module: &mut Module, uniform_block: &str) -> Vec<LeftOut> {
    // The constants holding uniform initializers are for the renderer, which reads them
    // from the front's module: unnamed, compaction drops them (no code reads them).
    for (_, c) in module.constants.iter_mut() {
        if c.name.as_deref().is_some_and(|n| n.starts_with(crate::front::rewrite::INITIAL_PREFIX)) {
            c.name = None;
        }
    }
    let mut left = Vec::new();
    left.extend(compact(module));
    let inputs = drop_unread_fragment_inputs(module);
    let outputs = drop_unreceived_vertex_outputs(module);
    // A fragment input left out takes its vertex output with it: one entry for both.
    for mut i in inputs {
        if outputs.iter().any(|o| o.name == i.name) {
            i.reason.push_str(", so the vertex stage's output is left out too");
        }
        left.push(i);
    }
    for o in outputs {
        if !left.iter().any(|l| l.kind == "varying" && l.name == o.name) {
            left.push(o);
        }
    }
    drop_write_only_privates(module);
    left.extend(compact(module));
    left.extend(drop_unread_uniform_members(module, uniform_block));
    compact(module);
    left
}

/// naga's compaction, with the names of what it removed.
fn compact(module: &mut Module) -> Vec<LeftOut> {
    let names = |m: &Module| {
        let f: Vec<String> = m.functions.iter().filter_map(|(_, f)| f.name.clone()).collect();
        let g: Vec<(String, bool)> =
            m.global_variables.iter().filter_map(|(_, g)| g.name.clone().map(|n| (n, g.binding.is_some()))).collect();
        let c: Vec<String> = m.constants.iter().filter_map(|(_, c)| c.name.clone()).collect();
        (f, g, c)
    };
    let (f0, g0, c0) = names(module);
    naga::compact::compact(module, naga::compact::KeepUnused::No);
    let (f1, g1, c1) = names(module);
    let mut left = Vec::new();
    for f in f0.into_iter().filter(|f| !f1.contains(f)) {
        left.push(LeftOut { kind: "function", name: f, reason: "never called from an entry point".into() });
    }
    for (g, bound) in g0.into_iter().filter(|g| !g1.contains(g)) {
        let (kind, reason) =
            if bound { ("resource", "no stage reads it; its binding is not emitted") } else { ("global", "never used by code that runs") };
        left.push(LeftOut { kind, name: g, reason: reason.into() });
    }
    for c in c0.into_iter().filter(|c| !c1.contains(c)) {
        left.push(LeftOut { kind: "constant", name: c, reason: "never used by code that runs".into() });
    }
    left
}

/// Which members of a global's value code can observe. `None`: all of it (or unknown use).
#[derive(Debug, Default)]
struct Reads {
    whole: bool,
    members: BTreeSet<u32>,
}

/// Statements whose operands this module knows how to follow; any other kind of statement
/// in a function makes the analysis assume everything is read.
fn understood(f: &Function) -> bool {
    let mut ok = true;
    let mut body = f.body.clone();
    visit_statements(&mut body, &mut |s| {
        ok &= matches!(
            s,
            Statement::Emit(_)
                | Statement::Block(_)
                | Statement::If { .. }
                | Statement::Switch { .. }
                | Statement::Loop { .. }
                | Statement::Break
                | Statement::Continue
                | Statement::Return { .. }
                | Statement::Kill
                | Statement::Store { .. }
                | Statement::Call { .. }
                | Statement::ControlBarrier(_)
                | Statement::MemoryBarrier(_)
        )
    });
    ok
}

enum User {
    Expr(Handle<Expression>),
    StorePointer,
    Other,
}

fn users(f: &Function) -> HashMap<Handle<Expression>, Vec<User>> {
    let mut map: HashMap<Handle<Expression>, Vec<User>> = HashMap::new();
    for (h, e) in f.expressions.iter() {
        let mut e = e.clone();
        crate::back::merge::for_each_operand(&mut e, |op| map.entry(*op).or_default().push(User::Expr(h)));
    }
    let mut body = f.body.clone();
    let other = |x: Handle<Expression>, map: &mut HashMap<_, Vec<User>>| map.entry(x).or_default().push(User::Other);
    visit_statements(&mut body, &mut |s| match s {
        Statement::Store { pointer, value } => {
            map.entry(*pointer).or_default().push(User::StorePointer);
            other(*value, &mut map);
        }
        Statement::Call { arguments, .. } => arguments.iter().for_each(|a| other(*a, &mut map)),
        Statement::Return { value: Some(v) } => other(*v, &mut map),
        Statement::If { condition, .. } => other(*condition, &mut map),
        Statement::Switch { selector, .. } => other(*selector, &mut map),
        Statement::Loop { break_if: Some(b), .. } => other(*b, &mut map),
        _ => {}
    });
    map
}

/// What code reads of global `g`, over every function and entry point.
fn reads_of(module: &Module, g: Handle<GlobalVariable>) -> Reads {
    let mut reads = Reads::default();
    for f in crate::back::merge::all_functions(module) {
        let refs: Vec<_> =
            f.expressions.iter().filter(|(_, e)| matches!(e, Expression::GlobalVariable(x) if *x == g)).map(|(h, _)| h).collect();
        if refs.is_empty() {
            continue;
        }
        if !understood(f) {
            reads.whole = true;
            return reads;
        }
        let users = users(f);
        let none = Vec::new();
        let of = |h: Handle<Expression>| users.get(&h).unwrap_or(&none);
        for gv in refs {
            for u in of(gv) {
                match u {
                    User::StorePointer => {}
                    User::Other => reads.whole = true,
                    User::Expr(e) => match &f.expressions[*e] {
                        Expression::AccessIndex { index, .. } => {
                            if of(*e).iter().any(|u| !matches!(u, User::StorePointer)) {
                                reads.members.insert(*index);
                            }
                        }
                        Expression::Load { .. } => {
                            for lu in of(*e) {
                                match lu {
                                    User::Expr(x) => match &f.expressions[*x] {
                                        Expression::AccessIndex { index, .. } => {
                                            reads.members.insert(*index);
                                        }
                                        _ => reads.whole = true,
                                    },
                                    _ => reads.whole = true,
                                }
                            }
                        }
                        _ => reads.whole = true,
                    },
                }
            }
        }
    }
    reads
}

/// The global (and member) a fragment entry point stores argument `arg` into.
fn argument_target(f: &Function, arg: u32) -> Option<(Handle<GlobalVariable>, Option<u32>)> {
    let arg_expr = f.expressions.iter().find(|(_, e)| matches!(e, Expression::FunctionArgument(i) if *i == arg))?.0;
    let mut target = None;
    let mut body = f.body.clone();
    visit_statements(&mut body, &mut |s| {
        if let Statement::Store { pointer, value } = s {
            if *value == arg_expr {
                target = match f.expressions[*pointer] {
                    Expression::GlobalVariable(g) => Some((g, None)),
                    Expression::AccessIndex { base, index } => match f.expressions[base] {
                        Expression::GlobalVariable(g) => Some((g, Some(index))),
                        _ => None,
                    },
                    _ => None,
                };
            }
        }
    });
    target
}

/// The location of a `@location` binding.
pub(super) fn location_of(b: &Option<Binding>) -> Option<u32> {
    match b {
        Some(Binding::Location { location, .. }) => Some(*location),
        _ => None,
    }
}

fn drop_unread_fragment_inputs(module: &mut Module) -> Vec<LeftOut> {
    let mut left = Vec::new();
    let Some(ep_index) = module.entry_points.iter().position(|e| e.stage == naga::ShaderStage::Fragment) else {
        return left;
    };
    let f = &module.entry_points[ep_index].function;
    let mut dead: Vec<u32> = Vec::new();
    for (i, a) in f.arguments.iter().enumerate() {
        if location_of(&a.binding).is_none() {
            continue;
        }
        let Some((g, member)) = argument_target(f, i as u32) else { continue };
        let reads = reads_of(module, g);
        let read = reads.whole || member.map_or(!reads.members.is_empty(), |m| reads.members.contains(&m));
        if !read {
            dead.push(i as u32);
        }
    }
    let f = &mut module.entry_points[ep_index].function;
    for &i in dead.iter().rev() {
        let arg = f.arguments.remove(i as usize);
        left.push(LeftOut {
            kind: "varying",
            name: arg.name.clone().unwrap_or_else(|| format!("location {}", location_of(&arg.binding).unwrap_or(0))),
            reason: "the fragment stage declares this input but never reads it".into(),
        });
        for (_, e) in f.expressions.iter_mut() {
            match e {
                Expression::FunctionArgument(j) if *j == i => *e = Expression::ZeroValue(arg.ty),
                Expression::FunctionArgument(j) if *j > i => *j -= 1,
                _ => {}
            }
        }
    }
    left
}

fn drop_unreceived_vertex_outputs(module: &mut Module) -> Vec<LeftOut> {
    let mut left = Vec::new();
    let Some(frag) = module.entry_points.iter().find(|e| e.stage == naga::ShaderStage::Fragment) else { return left };
    let mut received: BTreeSet<u32> = BTreeSet::new();
    for a in &frag.function.arguments {
        match &a.binding {
            Some(b) => received.extend(location_of(&Some(b.clone()))),
            None => {
                if let TypeInner::Struct { members, .. } = &module.types[a.ty].inner {
                    received.extend(members.iter().filter_map(|m| location_of(&m.binding)));
                }
            }
        }
    }
    let Some(vi) = module.entry_points.iter().position(|e| e.stage == naga::ShaderStage::Vertex) else { return left };
    let Some(result) = module.entry_points[vi].function.result.clone() else { return left };
    let old = module.types[result.ty].clone();
    let TypeInner::Struct { members, .. } = &old.inner else { return left };
    let keep: Vec<bool> = members.iter().map(|m| location_of(&m.binding).is_none_or(|l| received.contains(&l))).collect();
    if keep.iter().all(|k| *k) {
        return left;
    }
    // Every return must compose the result, or the members cannot be removed.
    let f = &module.entry_points[vi].function;
    let mut returns = Vec::new();
    let mut body = f.body.clone();
    visit_statements(&mut body, &mut |s| {
        if let Statement::Return { value } = s {
            returns.push(*value);
        }
    });
    if returns.iter().any(|r| !matches!(r.map(|h| &f.expressions[h]), Some(Expression::Compose { ty, .. }) if *ty == result.ty)) {
        return left;
    }
    let kept: Vec<StructMember> = members.iter().zip(&keep).filter(|(_, k)| **k).map(|(m, _)| m.clone()).collect();
    for (m, _) in members.iter().zip(&keep).filter(|(_, k)| !**k) {
        left.push(LeftOut {
            kind: "varying",
            name: m.name.clone().unwrap_or_default(),
            reason: "vertex output no fragment input receives".into(),
        });
    }
    let (new_ty, _) = relaid_struct(module, old.name.clone(), kept, false);
    let f = &mut module.entry_points[vi].function;
    f.result.as_mut().expect("checked").ty = new_ty;
    for r in returns.into_iter().flatten() {
        if let Expression::Compose { ty, components } = f.expressions.get_mut(r) {
            *ty = new_ty;
            let mut i = 0;
            components.retain(|_| {
                i += 1;
                keep[i - 1]
            });
        }
    }
    left
}

/// A struct type with `members` laid out afresh in WGSL's natural layout (naga's WGSL
/// writer emits no offsets, so the IR must use the layout the WGSL text implies).
/// `uniform` also meets the uniform address space rules the natural layout may break
/// (structs and arrays 16-aligned, `roundUp(16, size)` after a struct) by inserting
/// `effectc_padN` filler members, as the front does for the unpruned block.
/// Returns the type and, for each given member, its index in the new struct.
fn relaid_struct(module: &mut Module, name: Option<String>, members: Vec<StructMember>, uniform: bool) -> (Handle<Type>, Vec<u32>) {
    let mut layouter = naga::proc::Layouter::default();
    layouter.update(module.to_ctx()).expect("types of a validated module lay out");
    let filler_ty = module.types.insert(Type { name: None, inner: TypeInner::Scalar(naga::Scalar::F32) }, naga::Span::UNDEFINED);
    let vec4_ty = module.types.insert(
        Type { name: None, inner: TypeInner::Vector { size: naga::VectorSize::Quad, scalar: naga::Scalar::F32 } },
        naga::Span::UNDEFINED,
    );
    let mut out: Vec<StructMember> = Vec::new();
    let mut end = 0u32;
    let mut after_struct = 0u32;
    let mut max_align = 1u32;
    let mut fillers = 0;
    let mut indices = Vec::new();
    for mut m in members {
        let layout = layouter[m.ty];
        let natural = layout.alignment.round_up(1).max(1);
        let aggregate = matches!(module.types[m.ty].inner, TypeInner::Struct { .. } | TypeInner::Array { .. });
        let required = if uniform && aggregate { natural.max(16) } else { natural };
        max_align = max_align.max(natural);
        if uniform && end < after_struct {
            // Every member after a struct starts `roundUp(16, size)` past it, fillers too:
            // one `vec4` (16-aligned) lands exactly there, as the front's filler does.
            let offset = end.next_multiple_of(16);
            out.push(StructMember { name: Some(format!("effectc_pad{fillers}")), ty: vec4_ty, binding: None, offset });
            fillers += 1;
            end = offset + 16;
            max_align = max_align.max(16);
        }
        if uniform {
            while !end.next_multiple_of(natural).is_multiple_of(required) {
                out.push(StructMember { name: Some(format!("effectc_pad{fillers}")), ty: filler_ty, binding: None, offset: end });
                fillers += 1;
                end += 4;
            }
        }
        m.offset = end.next_multiple_of(natural);
        end = m.offset + layout.size;
        after_struct = match module.types[m.ty].inner {
            TypeInner::Struct { .. } => m.offset + layout.size.next_multiple_of(16),
            _ => 0,
        };
        indices.push(out.len() as u32);
        out.push(m);
    }
    let span = end.next_multiple_of(max_align);
    (module.types.insert(Type { name, inner: TypeInner::Struct { members: out, span } }, naga::Span::UNDEFINED), indices)
}

/// Removes the stores into private globals nothing reads (a vertex output left out still
/// has its GLSL assignment; this drops it), so compaction can drop the global too.
fn drop_write_only_privates(module: &mut Module) {
    let dead: Vec<Handle<GlobalVariable>> = module
        .global_variables
        .iter()
        .filter(|(_, g)| g.space == naga::AddressSpace::Private)
        .map(|(h, _)| h)
        .filter(|h| {
            let r = reads_of(module, *h);
            !r.whole && r.members.is_empty()
        })
        .collect();
    if dead.is_empty() {
        return;
    }
    for f in crate::back::merge::all_functions_mut(module) {
        let exprs = &f.expressions;
        let into_dead = |mut p: Handle<Expression>| loop {
            match exprs[p] {
                Expression::GlobalVariable(g) => return dead.contains(&g),
                Expression::AccessIndex { base, .. } | Expression::Access { base, .. } => p = base,
                _ => return false,
            }
        };
        remove_stores(&mut f.body, &into_dead);
    }
}

fn remove_stores(block: &mut naga::Block, into_dead: &dyn Fn(Handle<Expression>) -> bool) {
    let old = std::mem::take(block);
    for (mut s, span) in old.span_into_iter() {
        if matches!(s, Statement::Store { pointer, .. } if into_dead(pointer)) {
            continue;
        }
        for b in crate::back::merge::child_blocks(&mut s) {
            remove_stores(b, into_dead);
        }
        block.push(s, span);
    }
}

fn drop_unread_uniform_members(module: &mut Module, block_name: &str) -> Vec<LeftOut> {
    let mut left = Vec::new();
    let found = module
        .global_variables
        .iter()
        .find(|(_, g)| g.space == naga::AddressSpace::Uniform && module.types[g.ty].name.as_deref() == Some(block_name));
    let Some((g, var)) = found else { return left };
    let old_ty = var.ty;
    let TypeInner::Struct { members, .. } = module.types[old_ty].inner.clone() else { return left };
    let reads = reads_of(module, g);
    if reads.whole || reads.members.len() == members.len() {
        return left;
    }
    let mut remap: HashMap<u32, u32> = HashMap::new();
    let mut kept = Vec::new();
    for (i, m) in members.iter().enumerate() {
        if reads.members.contains(&(i as u32)) {
            remap.insert(i as u32, kept.len() as u32);
            kept.push(m.clone());
        } else if !m.name.as_deref().unwrap_or("").starts_with("effectc_pad") {
            left.push(LeftOut {
                kind: "uniform",
                name: m.name.clone().unwrap_or_default(),
                reason: "no stage reads it; left out of the uniform block".into(),
            });
        }
    }
    if kept.is_empty() {
        // Nothing reads the block at all: compaction drops the global instead.
        return left;
    }
    let name = module.types[old_ty].name.clone();
    let (new_ty, indices) = relaid_struct(module, name, kept, true);
    for v in remap.values_mut() {
        *v = indices[*v as usize];
    }
    module.global_variables.get_mut(g).ty = new_ty;
    for f in crate::back::merge::all_functions_mut(module) {
        let gv: Vec<_> =
            f.expressions.iter().filter(|(_, e)| matches!(e, Expression::GlobalVariable(x) if *x == g)).map(|(h, _)| h).collect();
        for (_, e) in f.expressions.iter_mut() {
            if let Expression::AccessIndex { base, index } = e {
                if gv.contains(base) {
                    *index = remap[index];
                }
            }
        }
    }
    left
}
