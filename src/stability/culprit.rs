//! Locating the first non-finite value: the fragment stage is instrumented so that every
//! float arithmetic or builtin result is tested as it is computed, and the colour output
//! becomes the number of the first test that failed in that pixel.
//!
//! A value fails when it is NaN or ±Inf (exponent bits all ones, tested on the bits so no
//! compiler can assume NaN away), and a `normalize` also fails when its argument has zero
//! length (undefined in GLSL; some drivers, llvmpipe among them, return 0 rather than NaN).
//! Probes are numbered in execution order within each function; a pixel reports the first
//! probe that fired, so its number names the expression where the trouble began, not the
//! ones it spread to.

use naga::{
    BinaryOperator as B, Block, Expression, Function, Handle, Literal, MathFunction, Module, RelationalFunction, ScalarKind,
    Span, Statement, TypeInner,
};

/// One instrumented expression.
#[derive(Debug, Clone)]
pub struct Probe {
    /// Written to the red channel when this probe fires first (from 1).
    pub id: u32,
    /// Span in the fragment stage's text.
    pub span: Span,
    /// What it computes (`division`, `normalize`, …).
    pub what: String,
}

/// Instruments the fragment entry point of `module` (validated, `info` its analysis) and
/// every function it calls. `text` is the fragment stage text its spans index. `None` when
/// the fragment output at location 0 is not a `vec4<f32>`.
pub fn instrument(module: &mut Module, info: &naga::valid::ModuleInfo, text: &str) -> Option<Vec<Probe>> {
    let entry = module.entry_points.iter().position(|e| e.stage == naga::ShaderStage::Fragment)?;
    let (member, color_ty) = location0(module, &module.entry_points[entry].function)?;
    let u32_ty = module.types.insert(
        naga::Type { name: None, inner: TypeInner::Scalar(naga::Scalar::U32) },
        Span::UNDEFINED,
    );
    let flag = module.global_variables.append(
        naga::GlobalVariable { name: Some("effectc_first_bad".into()), space: naga::AddressSpace::Private, binding: None, ty: u32_ty, init: None, memory_decorations: naga::MemoryDecorations::empty() },
        Span::UNDEFINED,
    );
    let mut probes = Vec::new();
    for f in reachable(module, &module.entry_points[entry].function) {
        let types = types_of(module, &info[f], module.functions[f].expressions.iter().map(|(h, _)| h));
        let fun = &mut module.functions[f];
        probe_function(fun, &types, flag, text, &mut probes);
    }
    let handles: Vec<_> = module.entry_points[entry].function.expressions.iter().map(|(h, _)| h).collect();
    let types = types_of(module, info.get_entry_point(entry), handles.into_iter());
    probe_function(&mut module.entry_points[entry].function, &types, flag, text, &mut probes);
    let result_ty = module.entry_points[entry].function.result.as_ref()?.ty;
    let members = match &module.types[result_ty].inner {
        TypeInner::Struct { members, .. } => members.len(),
        _ => 1,
    };
    let ep = &mut module.entry_points[entry];
    let body = std::mem::take(&mut ep.function.body);
    ep.function.body = report_at_returns(&mut ep.function, body, flag, member, members, color_ty, result_ty);
    Some(probes)
}

/// The resolved type of every expression of a function, by index.
fn types_of(module: &Module, info: &naga::valid::FunctionInfo, handles: impl Iterator<Item = Handle<Expression>>) -> Vec<TypeInner> {
    handles.map(|h| info[h].ty.inner_with(&module.types).clone()).collect()
}

/// The member index (`None` for a plain result) and type of the location-0 colour output.
fn location0(module: &Module, f: &Function) -> Option<(Option<usize>, Handle<naga::Type>)> {
    let result = f.result.as_ref()?;
    let is_vec4f = |ty: Handle<naga::Type>| {
        matches!(module.types[ty].inner, TypeInner::Vector { size: naga::VectorSize::Quad, scalar } if scalar.kind == ScalarKind::Float && scalar.width == 4)
    };
    if let Some(naga::Binding::Location { location: 0, .. }) = result.binding {
        return is_vec4f(result.ty).then_some((None, result.ty));
    }
    let TypeInner::Struct { members, .. } = &module.types[result.ty].inner else { return None };
    members.iter().enumerate().find_map(|(i, m)| match m.binding {
        Some(naga::Binding::Location { location: 0, .. }) if is_vec4f(m.ty) => Some((Some(i), m.ty)),
        _ => None,
    })
}

/// Functions called, directly or not, from `f`, callees first.
fn reachable(module: &Module, f: &Function) -> Vec<Handle<Function>> {
    fn calls(block: &Block, out: &mut Vec<Handle<Function>>) {
        for s in block.iter() {
            match s {
                Statement::Call { function, .. } => out.push(*function),
                Statement::Block(b) => calls(b, out),
                Statement::If { accept, reject, .. } => {
                    calls(accept, out);
                    calls(reject, out);
                }
                Statement::Loop { body, continuing, .. } => {
                    calls(body, out);
                    calls(continuing, out);
                }
                Statement::Switch { cases, .. } => cases.iter().for_each(|c| calls(&c.body, out)),
                _ => {}
            }
        }
    }
    let mut seen: Vec<Handle<Function>> = Vec::new();
    let mut todo = Vec::new();
    calls(&f.body, &mut todo);
    while let Some(h) = todo.pop() {
        if !seen.contains(&h) {
            seen.push(h);
            calls(&module.functions[h].body, &mut todo);
        }
    }
    seen
}

fn probe_function(fun: &mut Function, types: &[TypeInner], flag: Handle<naga::GlobalVariable>, text: &str, probes: &mut Vec<Probe>) {
    let body = std::mem::take(&mut fun.body);
    fun.body = probe_block(fun, body, types, flag, text, probes);
}

fn probe_block(fun: &mut Function, block: Block, types: &[TypeInner], flag: Handle<naga::GlobalVariable>, text: &str, probes: &mut Vec<Probe>) -> Block {
    let mut out = Block::with_capacity(block.len());
    for (stmt, span) in block.span_into_iter() {
        let stmt = match stmt {
            Statement::Block(b) => Statement::Block(probe_block(fun, b, types, flag, text, probes)),
            Statement::If { condition, accept, reject } => Statement::If {
                condition,
                accept: probe_block(fun, accept, types, flag, text, probes),
                reject: probe_block(fun, reject, types, flag, text, probes),
            },
            Statement::Loop { body, continuing, break_if } => Statement::Loop {
                body: probe_block(fun, body, types, flag, text, probes),
                continuing: probe_block(fun, continuing, types, flag, text, probes),
                break_if,
            },
            Statement::Switch { selector, cases } => Statement::Switch {
                selector,
                cases: cases
                    .into_iter()
                    .map(|c| naga::SwitchCase { body: probe_block(fun, c.body, types, flag, text, probes), ..c })
                    .collect(),
            },
            other => other,
        };
        let emitted = if let Statement::Emit(range) = &stmt { range.clone().collect::<Vec<_>>() } else { Vec::new() };
        out.push(stmt, span);
        for h in emitted {
            let Some(what) = candidate(&fun.expressions[h], types.get(h.index())) else { continue };
            let id = probes.len() as u32 + 1;
            probes.push(Probe { id, span: crate::stability::hazards::eval::expression_span(fun, h, text), what });
            let (emit, check) = build_check(fun, h, types.get(h.index()), flag, id);
            out.push(emit, Span::UNDEFINED);
            out.push(check, Span::UNDEFINED);
        }
    }
    out
}

/// Expressions worth a probe: float arithmetic and builtins with scalar or vector results.
fn candidate(e: &Expression, ty: Option<&TypeInner>) -> Option<String> {
    let float = match ty? {
        TypeInner::Scalar(s) | TypeInner::Vector { scalar: s, .. } => s.kind == ScalarKind::Float && s.width == 4,
        _ => false,
    };
    if !float {
        return None;
    }
    match e {
        Expression::Binary { op: B::Divide, .. } => Some("division".into()),
        Expression::Binary { op: B::Add | B::Subtract | B::Multiply | B::Modulo, .. } => Some("arithmetic".into()),
        Expression::Math { fun, .. } => Some(format!("{fun:?}").to_lowercase()),
        _ => None,
    }
}

/// `Emit` of the test, and `if (flag == 0u && bad(h)) { flag = id; }`.
fn build_check(fun: &mut Function, h: Handle<Expression>, ty: Option<&TypeInner>, flag: Handle<naga::GlobalVariable>, id: u32) -> (Statement, Statement) {
    let size = match ty {
        Some(TypeInner::Vector { size, .. }) => Some(*size),
        _ => None,
    };
    let e = &mut fun.expressions;
    // Not emitted: literals and the global's pointer.
    let mask = e.append(Expression::Literal(Literal::U32(0x7f80_0000)), Span::UNDEFINED);
    let zero = e.append(Expression::Literal(Literal::U32(0)), Span::UNDEFINED);
    let fzero = e.append(Expression::Literal(Literal::F32(0.0)), Span::UNDEFINED);
    let value = e.append(Expression::Literal(Literal::U32(id)), Span::UNDEFINED);
    let ptr = e.append(Expression::GlobalVariable(flag), Span::UNDEFINED);
    let normalize_arg = match fun.expressions[h] {
        Expression::Math { fun: MathFunction::Normalize, arg, .. } => Some(arg),
        _ => None,
    };
    let e = &mut fun.expressions;
    let bits = e.append(Expression::As { expr: h, kind: ScalarKind::Uint, convert: None }, Span::UNDEFINED);
    let m = match size {
        Some(size) => e.append(Expression::Splat { size, value: mask }, Span::UNDEFINED),
        None => mask,
    };
    let exponent = e.append(Expression::Binary { op: B::And, left: bits, right: m }, Span::UNDEFINED);
    let all_ones = e.append(Expression::Binary { op: B::Equal, left: exponent, right: m }, Span::UNDEFINED);
    let mut bad = match size {
        Some(_) => e.append(Expression::Relational { fun: RelationalFunction::Any, argument: all_ones }, Span::UNDEFINED),
        None => all_ones,
    };
    if let Some(arg) = normalize_arg {
        let d = e.append(Expression::Math { fun: MathFunction::Dot, arg, arg1: Some(arg), arg2: None, arg3: None }, Span::UNDEFINED);
        let z = e.append(Expression::Binary { op: B::Equal, left: d, right: fzero }, Span::UNDEFINED);
        bad = e.append(Expression::Binary { op: B::LogicalOr, left: bad, right: z }, Span::UNDEFINED);
    }
    let current = e.append(Expression::Load { pointer: ptr }, Span::UNDEFINED);
    let none_yet = e.append(Expression::Binary { op: B::Equal, left: current, right: zero }, Span::UNDEFINED);
    let condition = e.append(Expression::Binary { op: B::LogicalAnd, left: none_yet, right: bad }, Span::UNDEFINED);
    let range = naga::Range::new_from_bounds(bits, condition);
    let mut accept = Block::new();
    accept.push(Statement::Store { pointer: ptr, value }, Span::UNDEFINED);
    (Statement::Emit(range), Statement::If { condition, accept, reject: Block::new() })
}

/// Every `return` of the entry point returns the first probe's number as the colour
/// `vec4(f32(flag), 0, 0, 1)` at location 0 (other outputs unchanged).
fn report_at_returns(
    fun: &mut Function,
    block: Block,
    flag: Handle<naga::GlobalVariable>,
    member: Option<usize>,
    members: usize,
    color_ty: Handle<naga::Type>,
    result_ty: Handle<naga::Type>,
) -> Block {
    let mut out = Block::with_capacity(block.len());
    for (stmt, span) in block.span_into_iter() {
        let stmt = match stmt {
            Statement::Block(b) => Statement::Block(report_at_returns(fun, b, flag, member, members, color_ty, result_ty)),
            Statement::If { condition, accept, reject } => Statement::If {
                condition,
                accept: report_at_returns(fun, accept, flag, member, members, color_ty, result_ty),
                reject: report_at_returns(fun, reject, flag, member, members, color_ty, result_ty),
            },
            Statement::Return { value: Some(v) } => {
                let e = &mut fun.expressions;
                let ptr = e.append(Expression::GlobalVariable(flag), Span::UNDEFINED);
                let zero = e.append(Expression::Literal(Literal::F32(0.0)), Span::UNDEFINED);
                let one = e.append(Expression::Literal(Literal::F32(1.0)), Span::UNDEFINED);
                let current = e.append(Expression::Load { pointer: ptr }, Span::UNDEFINED);
                let as_float = e.append(Expression::As { expr: current, kind: ScalarKind::Float, convert: Some(4) }, Span::UNDEFINED);
                let color = e.append(Expression::Compose { ty: color_ty, components: vec![as_float, zero, zero, one] }, Span::UNDEFINED);
                let result = match member {
                    None => color,
                    Some(k) => {
                        let components = (0..members)
                            .map(|i| if i == k { color } else { fun.expressions.append(Expression::AccessIndex { base: v, index: i as u32 }, Span::UNDEFINED) })
                            .collect();
                        fun.expressions.append(Expression::Compose { ty: result_ty, components }, Span::UNDEFINED)
                    }
                };
                out.push(Statement::Emit(naga::Range::new_from_bounds(current, result)), Span::UNDEFINED);
                Statement::Return { value: Some(result) }
            }
            other => other,
        };
        out.push(stmt, span);
    }
    out
}
