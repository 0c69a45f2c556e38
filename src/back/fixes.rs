//! IR passes that close gaps between what naga's GLSL front produces and what the backends
//! and wgpu accept, plus the one semantic difference between GL and WebGPU clip space.
//!
//! - `switch` cases that end in `return`/`discard`/`break`/`continue` (or are the last case)
//!   are marked as not falling through; naga's WGSL writer rejects non-empty fall-through.
//! - Interpolation of vertex outputs and fragment inputs is made explicit (float: perspective,
//!   centre sampling), so a flattened interface block member (sampling `None`) and a plain
//!   varying (`Center`) agree and wgpu builds the pipeline.
//! - GL clip-space depth (z in [-w, w]) is mapped to WebGPU/Vulkan's (z in [0, w]) at the end
//!   of the vertex stage, so a GL projection matrix keeps its near and far planes. For
//!   rendering, clip y is also negated so the framebuffer runs bottom-up as GL's does.
//! - Interpolation qualifiers of interface-block members (`flat vec4 c;`,
//!   `noperspective`, `centroid` inside `out Block { … }`), which naga's GLSL parser does
//!   not take, are put on the entry point's bindings from the declarations.
//! - Storage buffers no function writes become read-only (`var<storage, read>`): GLSL's
//!   `buffer` blocks are read-write unless `readonly`, and WebGPU forbids writable storage in
//!   the vertex stage, where vertex-pulling samples read them.
//! - For rendering only: fragment colour outputs narrower than four components (`out vec3
//!   color`) are widened to four (missing colour 0, alpha 1), because a WebGPU colour target
//!   needs as many components from the shader as its format has; GL writes the narrower
//!   value into an RGBA framebuffer.

use naga::{
    BinaryOperator, Binding, Expression, Handle, Interpolation, Literal, Module, Sampling, Span, Statement, StructMember, Type, TypeInner,
};

use crate::back::merge::visit_statements;

/// Marks `switch` cases that cannot really fall through. Returns the spans of switches
/// that still have a fall-through case with code (WGSL cannot express them).
pub fn fix_switch_fallthrough(module: &mut Module) -> Vec<Span> {
    let mut remaining = Vec::new();
    for (_, f) in module.functions.iter_mut() {
        fix_block(&mut f.body, &mut remaining);
    }
    for ep in &mut module.entry_points {
        fix_block(&mut ep.function.body, &mut remaining);
    }
    remaining
}

fn fix_block(block: &mut naga::Block, remaining: &mut Vec<Span>) {
    for (s, span) in block.span_iter_mut() {
        if let Statement::Switch { cases, .. } = s {
            let last = cases.len().saturating_sub(1);
            let mut unfixable = false;
            for (i, case) in cases.iter_mut().enumerate() {
                if case.fall_through && (i == last || ends_in_jump(&case.body)) {
                    case.fall_through = false;
                }
                unfixable |= case.fall_through && !case.body.is_empty();
            }
            if unfixable {
                remaining.push(span.map(|s| *s).unwrap_or_default());
            }
        }
        for b in crate::back::merge::child_blocks(s) {
            fix_block(b, remaining);
        }
    }
}

fn ends_in_jump(block: &naga::Block) -> bool {
    match block.last() {
        Some(Statement::Return { .. } | Statement::Kill | Statement::Break | Statement::Continue) => true,
        Some(Statement::Block(inner)) => ends_in_jump(inner),
        Some(Statement::If { accept, reject, .. }) => ends_in_jump(accept) && ends_in_jump(reject),
        _ => false,
    }
}

/// Makes interpolation and sampling explicit on vertex outputs and fragment inputs.
pub fn normalize_interpolation(module: &mut Module) {
    for_each_interface_binding(module, |binding, ty, _| normalize_binding(binding, ty));
}

/// Calls `f(binding, type, name)` on every vertex output and fragment input binding
/// (struct members included), writing changed struct types back.
fn for_each_interface_binding(module: &mut Module, mut f: impl FnMut(&mut Binding, &TypeInner, Option<&String>)) {
    let mut struct_types = Vec::new();
    for ep in &mut module.entry_points {
        match ep.stage {
            naga::ShaderStage::Vertex => {
                if let Some(r) = &mut ep.function.result {
                    match &mut r.binding {
                        Some(b) => f(b, &module.types[r.ty].inner, None),
                        None => struct_types.push(r.ty),
                    }
                }
            }
            naga::ShaderStage::Fragment => {
                for a in &mut ep.function.arguments {
                    match &mut a.binding {
                        Some(b) => f(b, &module.types[a.ty].inner, a.name.as_ref()),
                        None => struct_types.push(a.ty),
                    }
                }
            }
            _ => {}
        }
    }
    struct_types.sort();
    struct_types.dedup();
    for ty in struct_types {
        let t = module.types[ty].clone();
        let TypeInner::Struct { mut members, span } = t.inner else { continue };
        for m in &mut members {
            if let Some(b) = &mut m.binding {
                f(b, &module.types[m.ty].inner, m.name.as_ref());
            }
        }
        let new = Type { name: t.name, inner: TypeInner::Struct { members, span } };
        // `replace` keeps the handle; it cannot take a value the arena already holds.
        if module.types.get(&new).is_none() {
            module.types.replace(ty, new);
        }
    }
}

fn normalize_binding(binding: &mut Binding, ty: &TypeInner) {
    let Binding::Location { interpolation, sampling, .. } = binding else { return };
    let float = matches!(ty.scalar_kind(), Some(naga::ScalarKind::Float));
    if interpolation.is_none() {
        *interpolation = Some(if float { Interpolation::Perspective } else { Interpolation::Flat });
    }
    match interpolation {
        Some(Interpolation::Perspective | Interpolation::Linear) if sampling.is_none() => *sampling = Some(Sampling::Center),
        _ => {}
    }
}

/// Names the generated uniform block's variable `uniforms` (naga's GLSL front leaves a
/// block without instance name unnamed, and WGSL would call it `global`).
pub fn name_uniform_block(module: &mut Module, block_type: &str) {
    for (_, g) in module.global_variables.iter_mut() {
        if g.name.is_none() && module.types[g.ty].name.as_deref() == Some(block_type) {
            g.name = Some("uniforms".to_string());
        }
    }
}

/// Maps GL clip space to WebGPU's at every `return` of the vertex entry point.
/// `depth`: `position.z = (position.z + position.w) * 0.5` (GL's z in [-w, w] to [0, w]).
/// `flip_y`: `position.y = -position.y`, for rendering upside down so that the framebuffer
/// rows run bottom-up as in GL: `gl_FragCoord.y` and `dFdy` then agree with GL (the
/// renderer flips the rows back on readback and treats clockwise faces as front faces).
/// Returns whether a position was found.
pub fn adjust_clip_position(module: &mut Module, depth: bool, flip_y: bool) -> bool {
    if !(depth || flip_y) {
        return false;
    }
    let mut done = false;
    for ep in module.entry_points.iter_mut().filter(|e| e.stage == naga::ShaderStage::Vertex) {
        let Some(result) = &ep.function.result else { continue };
        let position_member = match &module.types[result.ty].inner {
            TypeInner::Struct { members, .. } => members.iter().position(is_position),
            _ => None,
        };
        let Some(index) = position_member else { continue };
        let TypeInner::Struct { members, .. } = &module.types[result.ty].inner else { continue };
        let vec4 = members[index].ty;
        let result_ty = result.ty;
        let f = &mut ep.function;
        // Find the composed results first; then patch each one.
        for (ret, components) in composed_returns(f, result_ty) {
            let pos = components[index];
            let half = f.expressions.append(Expression::Literal(Literal::F32(0.5)), Span::UNDEFINED);
            let mut add = |e| f.expressions.append(e, Span::UNDEFINED);
            let x = add(Expression::AccessIndex { base: pos, index: 0 });
            let first = x;
            let mut y = add(Expression::AccessIndex { base: pos, index: 1 });
            let mut z = add(Expression::AccessIndex { base: pos, index: 2 });
            let w = add(Expression::AccessIndex { base: pos, index: 3 });
            if depth {
                let sum = add(Expression::Binary { op: BinaryOperator::Add, left: z, right: w });
                z = add(Expression::Binary { op: BinaryOperator::Multiply, left: sum, right: half });
            }
            if flip_y {
                y = add(Expression::Unary { op: naga::UnaryOperator::Negate, expr: y });
            }
            let new_pos = add(Expression::Compose { ty: vec4, components: vec![x, y, z, w] });
            // Expressions may only refer to earlier ones: compose a new result.
            let mut new_components = components.clone();
            new_components[index] = new_pos;
            let new_ret = add(Expression::Compose { ty: result_ty, components: new_components });
            replace_return(&mut f.body, ret, new_ret, naga::Range::new_from_bounds(first, new_ret));
            done = true;
        }
    }
    done
}

/// Widens fragment outputs at a location that have fewer than four components to four
/// (colour components 0, alpha 1). Returns the names of the widened outputs.
pub fn widen_fragment_outputs(module: &mut Module) -> Vec<String> {
    let mut widened = Vec::new();
    for ep in module.entry_points.iter_mut().filter(|e| e.stage == naga::ShaderStage::Fragment) {
        let Some(result) = &ep.function.result else { continue };
        let result_ty = result.ty;
        let TypeInner::Struct { members, .. } = module.types[result_ty].inner.clone() else { continue };
        // (member index, scalar, component count) of each output to widen.
        let narrow: Vec<(usize, naga::Scalar, u32)> = members
            .iter()
            .enumerate()
            .filter(|(_, m)| matches!(m.binding, Some(Binding::Location { .. })))
            .filter_map(|(i, m)| match module.types[m.ty].inner {
                TypeInner::Scalar(s) => Some((i, s, 1)),
                TypeInner::Vector { size, scalar } if (size as u32) < 4 => Some((i, scalar, size as u32)),
                _ => None,
            })
            .collect();
        if narrow.is_empty() {
            continue;
        }
        let mut new_members = members.clone();
        let mut vec4s = Vec::new();
        for &(i, scalar, _) in &narrow {
            let ty = module
                .types
                .insert(Type { name: None, inner: TypeInner::Vector { size: naga::VectorSize::Quad, scalar } }, Span::UNDEFINED);
            new_members[i].ty = ty;
            vec4s.push(ty);
            widened.push(members[i].name.clone().unwrap_or_default());
        }
        for (i, m) in new_members.iter_mut().enumerate() {
            m.offset = 16 * i as u32;
        }
        let span = 16 * new_members.len() as u32;
        let name = module.types[result_ty].name.clone();
        let new_ty = module.types.insert(Type { name, inner: TypeInner::Struct { members: new_members, span } }, Span::UNDEFINED);
        let f = &mut ep.function;
        for (ret, components) in composed_returns(f, result_ty) {
            // Literals are not emitted: append them before the emitted range.
            let literals: Vec<(Handle<Expression>, Handle<Expression>)> = narrow
                .iter()
                .map(|&(_, scalar, _)| {
                    let (zero, one) = match scalar.kind {
                        naga::ScalarKind::Sint => (Literal::I32(0), Literal::I32(1)),
                        naga::ScalarKind::Uint => (Literal::U32(0), Literal::U32(1)),
                        _ => (Literal::F32(0.0), Literal::F32(1.0)),
                    };
                    (
                        f.expressions.append(Expression::Literal(zero), Span::UNDEFINED),
                        f.expressions.append(Expression::Literal(one), Span::UNDEFINED),
                    )
                })
                .collect();
            let mut first = None;
            let mut add = |e, first: &mut Option<Handle<Expression>>| {
                let h = f.expressions.append(e, Span::UNDEFINED);
                first.get_or_insert(h);
                h
            };
            let mut new_components = components.clone();
            for (k, &(i, _, count)) in narrow.iter().enumerate() {
                let value = components[i];
                let (zero, one) = literals[k];
                let mut parts: Vec<Handle<Expression>> = if count == 1 {
                    vec![value]
                } else {
                    (0..count).map(|c| add(Expression::AccessIndex { base: value, index: c }, &mut first)).collect()
                };
                while parts.len() < 3 {
                    parts.push(zero);
                }
                if parts.len() < 4 {
                    parts.push(one);
                }
                new_components[i] = add(Expression::Compose { ty: vec4s[k], components: parts }, &mut first);
            }
            let new_ret = add(Expression::Compose { ty: new_ty, components: new_components }, &mut first);
            let first = first.unwrap_or(new_ret);
            replace_return(&mut f.body, ret, new_ret, naga::Range::new_from_bounds(first, new_ret));
        }
        if let Some(r) = &mut ep.function.result {
            r.ty = new_ty;
        }
    }
    widened
}

/// Every `return` of `f` whose value composes a `result_ty`: (value, components).
fn composed_returns(f: &mut naga::Function, result_ty: Handle<Type>) -> Vec<(Handle<Expression>, Vec<Handle<Expression>>)> {
    let mut returns: Vec<Handle<Expression>> = Vec::new();
    visit_statements(&mut f.body, &mut |s| {
        if let Statement::Return { value: Some(v) } = s {
            returns.push(*v);
        }
    });
    returns
        .into_iter()
        .filter_map(|ret| match &f.expressions[ret] {
            Expression::Compose { ty, components } if *ty == result_ty => Some((ret, components.clone())),
            _ => None,
        })
        .collect()
}

fn is_position(m: &StructMember) -> bool {
    matches!(m.binding, Some(Binding::BuiltIn(naga::BuiltIn::Position { .. })))
}

/// Makes the `return` of `old` return `new`, with `Emit(range)` right before it.
fn replace_return(block: &mut naga::Block, old: Handle<Expression>, new: Handle<Expression>, range: naga::Range<Expression>) -> bool {
    let at = block.iter().position(|s| matches!(s, Statement::Return { value: Some(v) } if *v == old));
    if let Some(at) = at {
        if let Some(Statement::Return { value }) = block.get_mut(at) {
            *value = Some(new);
        }
        let mut emit = naga::Block::new();
        emit.push(Statement::Emit(range), Span::UNDEFINED);
        block.splice(at..at, emit);
        return true;
    }
    for s in block.iter_mut() {
        for b in crate::back::merge::child_blocks(s) {
            if replace_return(b, old, new, range.clone()) {
                return true;
            }
        }
    }
    false
}

/// Marks storage buffers that no function or entry point writes as read-only.
pub fn read_only_unwritten_storage(module: &mut Module) {
    let Ok(info) = crate::front::naga_run::validator().validate(module) else { return };
    let written = |h: naga::Handle<naga::GlobalVariable>| {
        module.functions.iter().any(|(f, _)| info[f][h].intersects(naga::valid::GlobalUse::WRITE | naga::valid::GlobalUse::ATOMIC))
            || (0..module.entry_points.len())
                .any(|i| info.get_entry_point(i)[h].intersects(naga::valid::GlobalUse::WRITE | naga::valid::GlobalUse::ATOMIC))
    };
    let unwritten: Vec<_> = module
        .global_variables
        .iter()
        .filter(|(h, v)| {
            matches!(v.space, naga::AddressSpace::Storage { access } if access.contains(naga::StorageAccess::STORE)) && !written(*h)
        })
        .map(|(h, _)| h)
        .collect();
    for h in unwritten {
        module.global_variables[h].space = naga::AddressSpace::Storage { access: naga::StorageAccess::LOAD };
    }
}

/// Storage images GLSL declares without `readonly`/`writeonly` are read-write in naga's IR;
/// WebGPU takes read-write storage textures only for the 32-bit single-channel formats. An
/// image the program only reads becomes read-only, one it only writes write-only (GL's
/// meaning is the same: the access the code makes). Images passed to functions keep their
/// type (the parameters share it).
pub fn narrow_storage_image_access(module: &mut Module) {
    use naga::valid::GlobalUse;
    use naga::{ImageClass, StorageAccess};
    let Ok(info) = crate::front::naga_run::validator().validate(module) else { return };
    let uses = |h: naga::Handle<naga::GlobalVariable>| {
        let mut u = GlobalUse::empty();
        for (f, _) in module.functions.iter() {
            u |= info[f][h];
        }
        for i in 0..module.entry_points.len() {
            u |= info.get_entry_point(i)[h];
        }
        u
    };
    let passed: Vec<naga::Handle<naga::Type>> = module.functions.iter().flat_map(|(_, f)| f.arguments.iter().map(|a| a.ty)).collect();
    let mut changes = Vec::new();
    for (h, g) in module.global_variables.iter() {
        let TypeInner::Image { dim, arrayed, class: ImageClass::Storage { format, access } } = module.types[g.ty].inner else { continue };
        if access != StorageAccess::LOAD | StorageAccess::STORE || passed.contains(&g.ty) {
            continue;
        }
        let u = uses(h);
        let narrowed = match (u.contains(GlobalUse::READ), u.intersects(GlobalUse::WRITE | GlobalUse::ATOMIC)) {
            (_, true) if u.contains(GlobalUse::ATOMIC) => continue,
            (true, false) | (false, false) => StorageAccess::LOAD,
            (false, true) => StorageAccess::STORE,
            (true, true) => continue,
        };
        let ty = Type {
            name: module.types[g.ty].name.clone(),
            inner: TypeInner::Image { dim, arrayed, class: ImageClass::Storage { format, access: narrowed } },
        };
        changes.push((h, ty));
    }
    for (h, ty) in changes {
        let span = module.types.get_span(module.global_variables[h].ty);
        module.global_variables[h].ty = module.types.insert(ty, span);
    }
}

/// Puts the interpolation and sampling qualifiers the user wrote on interface-block members
/// onto the bindings of this stage's outputs (vertex) or inputs (fragment), by member name.
pub fn block_member_interpolation(module: &mut Module, syntax: &crate::front::syntax::StageSyntax) {
    use crate::front::syntax::{Interp, Storage};
    let side = match syntax.stage {
        crate::stage::StageKind::Vertex => Storage::Out,
        crate::stage::StageKind::Fragment => Storage::In,
        _ => return,
    };
    let mut wanted: std::collections::HashMap<String, (Option<Interp>, bool)> = std::collections::HashMap::new();
    for g in syntax.globals.iter().filter(|g| g.storage == side) {
        let Some(b) = &g.block else { continue };
        for m in b.members.iter().filter(|m| m.interp.is_some() || m.centroid) {
            wanted.insert(m.name.clone(), (m.interp, m.centroid));
            if let Some(instance) = &b.instance {
                wanted.insert(format!("{instance}_{}", m.name), (m.interp, m.centroid));
            }
        }
    }
    if wanted.is_empty() {
        return;
    }
    for_each_interface_binding(module, |binding, _, name| {
        let (Binding::Location { interpolation, sampling, .. }, Some((interp, centroid))) = (binding, name.and_then(|n| wanted.get(n)))
        else {
            return;
        };
        match interp {
            Some(Interp::Flat) => {
                *interpolation = Some(Interpolation::Flat);
                *sampling = None;
                return;
            }
            Some(Interp::NoPerspective) => *interpolation = Some(Interpolation::Linear),
            Some(Interp::Smooth) => *interpolation = Some(Interpolation::Perspective),
            None => {}
        }
        if *centroid {
            *sampling = Some(Sampling::Centroid);
        }
    });
}

/// A fragment stage behind a folded geometry stage reads `gl_PrimitiveID` from the flat
/// `uint` varying at `location` (the fold writes it there) instead of the built-in, which
/// WebGPU has only as an optional feature.
pub fn primitive_id_from_location(module: &mut Module, location: u32) {
    for ep in module.entry_points.iter_mut().filter(|e| e.stage == naga::ShaderStage::Fragment) {
        for arg in &mut ep.function.arguments {
            if arg.binding == Some(naga::Binding::BuiltIn(naga::BuiltIn::PrimitiveIndex)) {
                arg.binding = Some(naga::Binding::Location {
                    location,
                    interpolation: Some(naga::Interpolation::Flat),
                    sampling: None,
                    blend_src: None,
                    per_primitive: false,
                });
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn module(src: &str, stage: naga::ShaderStage) -> Module {
        naga::front::glsl::Frontend::default().parse(&naga::front::glsl::Options::from(stage), src).unwrap()
    }
    fn wgsl(m: &Module) -> Result<String, String> {
        let info = crate::front::naga_run::validator().validate(m).map_err(|e| format!("{e:?}"))?;
        naga::back::wgsl::write_string(m, &info, naga::back::wgsl::WriterFlags::empty()).map_err(|e| e.to_string())
    }

    #[test]
    fn switch_cases_ending_in_return_write_as_wgsl() {
        let src = "#version 450\nlayout(location=0) flat in int mode;\nlayout(location=0) out vec4 c;\n\
                   vec4 pick(int m) { switch (m) { case 0: return vec4(1.0); case 1: case 2: return vec4(0.5); default: return vec4(0.0); } }\n\
                   void main() { c = pick(mode); }\n";
        let mut m = module(src, naga::ShaderStage::Fragment);
        assert!(wgsl(&m).unwrap_err().contains("fall-through"), "naga's gap is still there");
        assert!(fix_switch_fallthrough(&mut m).is_empty());
        let out = wgsl(&m).unwrap();
        assert!(out.contains("case 1, 2: {"), "{out}");
    }

    #[test]
    fn real_fall_through_is_counted() {
        let src = "#version 450\nlayout(location=0) flat in int mode;\nlayout(location=0) out vec4 c;\n\
                   void main() { float v = 0.0; switch (mode) { case 0: v += 1.0; case 1: v += 2.0; break; } c = vec4(v); }\n";
        let mut m = module(src, naga::ShaderStage::Fragment);
        assert_eq!(fix_switch_fallthrough(&mut m).len(), 1);
    }

    #[test]
    fn block_members_and_plain_varyings_get_the_same_sampling() {
        let src = "#version 450\nlayout(location=0) in Block { vec2 uv; } b;\nlayout(location=1) in vec3 n;\nlayout(location=2) flat in int id;\n\
                   layout(location=0) out vec4 c;\nvoid main() { c = vec4(b.uv, n.x, float(id)); }\n";
        let mut m = module(src, naga::ShaderStage::Fragment);
        normalize_interpolation(&mut m);
        let args = &m.entry_points[0].function.arguments;
        let bindings: Vec<_> = args.iter().filter_map(|a| a.binding.clone()).collect();
        for b in &bindings {
            let Binding::Location { location, interpolation, sampling, .. } = b else { continue };
            if *location == 2 {
                assert_eq!(*interpolation, Some(Interpolation::Flat));
            } else {
                assert_eq!((*interpolation, *sampling), (Some(Interpolation::Perspective), Some(Sampling::Center)), "{b:?}");
            }
        }
        wgsl(&m).unwrap();
    }

    #[test]
    fn gl_depth_is_mapped_to_webgpu_depth() {
        let src = "#version 450\nlayout(location=0) in vec4 p;\nvoid main() { gl_Position = p; }\n";
        let mut m = module(src, naga::ShaderStage::Vertex);
        assert!(adjust_clip_position(&mut m, true, false));
        let out = wgsl(&m).unwrap();
        assert!(out.contains("* 0.5f"), "{out}");
        assert!(!out.contains("-("), "no flip asked: {out}");
        let mut flipped = module(src, naga::ShaderStage::Vertex);
        assert!(adjust_clip_position(&mut flipped, true, true));
        let out = wgsl(&flipped).unwrap();
        assert!(out.contains("-("), "y negated: {out}");
        naga::compact::compact(&mut m, naga::compact::KeepUnused::No);
        wgsl(&m).unwrap();
    }

    #[test]
    fn narrow_colour_outputs_are_widened_with_alpha_one() {
        let src = "#version 450\nlayout(location=0) out vec3 colour;\nlayout(location=1) out float mask;\n\
                   layout(location=2) out vec4 full;\nvoid main() { colour = vec3(0.25, 0.5, 0.75); mask = 0.5; full = vec4(1.0); }\n";
        let mut m = module(src, naga::ShaderStage::Fragment);
        assert_eq!(widen_fragment_outputs(&mut m), vec!["colour".to_string(), "mask".to_string()]);
        let out = wgsl(&m).unwrap();
        assert!(out.contains("@location(0) colour: vec4<f32>"), "{out}");
        assert!(out.contains("@location(1) mask: vec4<f32>"), "{out}");
        assert!(out.contains("@location(2) full: vec4<f32>"), "{out}");
        naga::compact::compact(&mut m, naga::compact::KeepUnused::No);
        wgsl(&m).unwrap();
    }
}
