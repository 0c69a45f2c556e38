//! `out`/`inout` arguments that are part of a variable (`f(v.x)`, `f(v[i])`, `f(a[i])`,
//! `f(m[1])`): GLSL copies the argument in before the call and back after it; naga's
//! GLSL front passes a pointer into the variable instead, which WGSL forbids for a vector
//! component ("cannot take the address of a vector component") and naga's SPIR-V writer
//! fails on for an array element (inside wgpu too). Each such argument becomes a local of
//! the part's type, copied in before the call and back after it: GLSL's own rule.

use naga::valid::ModuleInfo;
use naga::{Block, Expression, Function, Handle, LocalVariable, Module, Span, Statement, Type, TypeInner};

/// Rewrites every call of `module` that passes a pointer to part of a variable. `info` is
/// the validation of `module` as it is.
pub fn copy_partial_pointer_arguments(module: &mut Module, info: &ModuleInfo) {
    let functions: Vec<Handle<Function>> = module.functions.iter().map(|(h, _)| h).collect();
    for h in functions {
        let types = pointee_types(&mut module.types, &module.functions[h], &info[h]);
        rewrite_function(&mut module.functions[h], &types);
    }
    for i in 0..module.entry_points.len() {
        let types = pointee_types(&mut module.types, &module.entry_points[i].function, info.get_entry_point(i));
        rewrite_function(&mut module.entry_points[i].function, &types);
    }
}

/// For every expression of `f` that points to part of a variable (an `Access` or
/// `AccessIndex` of a pointer): the type it points to.
fn pointee_types(
    types: &mut naga::UniqueArena<Type>,
    f: &Function,
    info: &naga::valid::FunctionInfo,
) -> Vec<(Handle<Expression>, Handle<Type>)> {
    let mut out = Vec::new();
    for (e, expr) in f.expressions.iter() {
        if !matches!(expr, Expression::Access { .. } | Expression::AccessIndex { .. }) {
            continue;
        }
        let inner = info[e].ty.inner_with(types).clone();
        let ty = match inner {
            TypeInner::Pointer { base, .. } => base,
            TypeInner::ValuePointer { size: None, scalar, .. } => {
                types.insert(Type { name: None, inner: TypeInner::Scalar(scalar) }, Span::UNDEFINED)
            }
            TypeInner::ValuePointer { size: Some(size), scalar, .. } => {
                types.insert(Type { name: None, inner: TypeInner::Vector { size, scalar } }, Span::UNDEFINED)
            }
            _ => continue,
        };
        out.push((e, ty));
    }
    out
}

fn rewrite_function(f: &mut Function, partial: &[(Handle<Expression>, Handle<Type>)]) {
    if partial.is_empty() {
        return;
    }
    let body = std::mem::take(&mut f.body);
    f.body = rewrite_block(body, f, partial);
}

fn rewrite_block(block: Block, f: &mut Function, partial: &[(Handle<Expression>, Handle<Type>)]) -> Block {
    let mut out = Block::with_capacity(block.len());
    for (statement, span) in block.span_into_iter() {
        match statement {
            Statement::Call { function, mut arguments, result } => {
                let mut after = Vec::new();
                for arg in &mut arguments {
                    let Some(&(_, ty)) = partial.iter().find(|(e, _)| e == arg) else { continue };
                    let name = Some(format!("effectc_arg{}", f.local_variables.len()));
                    let local = f.local_variables.append(LocalVariable { name, ty, init: None }, span);
                    let temp = f.expressions.append(Expression::LocalVariable(local), span);
                    // Copy in.
                    let value = f.expressions.append(Expression::Load { pointer: *arg }, span);
                    out.push(Statement::Emit(naga::Range::new_from_bounds(value, value)), span);
                    out.push(Statement::Store { pointer: temp, value }, span);
                    after.push((*arg, temp));
                    *arg = temp;
                }
                out.push(Statement::Call { function, arguments, result }, span);
                // Copy back.
                for (part, temp) in after {
                    let value = f.expressions.append(Expression::Load { pointer: temp }, span);
                    out.push(Statement::Emit(naga::Range::new_from_bounds(value, value)), span);
                    out.push(Statement::Store { pointer: part, value }, span);
                }
            }
            Statement::Block(b) => out.push(Statement::Block(rewrite_block(b, f, partial)), span),
            Statement::If { condition, accept, reject } => {
                let (accept, reject) = (rewrite_block(accept, f, partial), rewrite_block(reject, f, partial));
                out.push(Statement::If { condition, accept, reject }, span);
            }
            Statement::Switch { selector, mut cases } => {
                for c in &mut cases {
                    c.body = rewrite_block(std::mem::take(&mut c.body), f, partial);
                }
                out.push(Statement::Switch { selector, cases }, span);
            }
            Statement::Loop { body, continuing, break_if } => {
                let (body, continuing) = (rewrite_block(body, f, partial), rewrite_block(continuing, f, partial));
                out.push(Statement::Loop { body, continuing, break_if }, span);
            }
            other => out.push(other, span),
        }
    }
    out
}
