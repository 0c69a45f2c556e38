//! Zeros between pixel centres (`stress --confirm`). A rasterizer evaluates a fragment stage
//! at pixel centres only, so an interpolated divisor, a vector about to be `normalize`d or
//! the two arguments of `atan(y, x)` can pass through zero on a line no pixel centre of this
//! frame meets, while another size or camera puts a centre on it. Each such operation in
//! uniform control flow is also tested on the segment from the fragment's operands to those
//! of its right and its upper neighbour (the fine screen derivatives, in the same
//! primitive): the condition counts as met between pixels when every component of the
//! operand reaches zero at one point of that segment, within the rasterizer's sub-pixel
//! grid ([`SUBPIXEL`]).
//!
//! Derivatives are defined only where all four invocations of a quad run together, so the
//! test is placed only in uniform control flow ([`Flow`]): not inside loops, not in branches
//! on values that vary per fragment, not after such a branch has left the function early,
//! and not in functions a vertex stage calls or a non-uniform branch calls. And a value that
//! jumps (`sign(x)`, `floor(x)`, a conversion from an integer, a texel, a variable assigned
//! in a branch) changes sign without passing through zero, so the test is placed only on
//! operands made of interpolated inputs, uniforms and constants by continuous operations
//! ([`Continuity`]).

use naga::{
    BinaryOperator as B, Block, DerivativeAxis, DerivativeControl, Expression, Function, Handle, Literal, MathFunction as M, Module,
    Statement, TypeInner, VectorSize,
};

use crate::diag::Code;
use crate::stage::StageKind;
use crate::stress::ir::{each_statement, entries, reachable, Builder};

/// The sub-pixel precision of a rasterizer's grid (8 bits): components that reach zero
/// within this share of the distance between two pixel centres reach it at one point.
pub const SUBPIXEL: f32 = 1.0 / 256.0;

/// Where derivatives are defined in a module's fragment stages.
pub struct Flow {
    /// Functions no vertex stage calls and every fragment call of which is in uniform flow.
    uniform_functions: Vec<Handle<Function>>,
}

impl Flow {
    /// The flow of `module`'s fragment stages (`info`: its validation).
    pub fn of(module: &Module, info: &naga::valid::ModuleInfo) -> Flow {
        let all = entries(module, &[StageKind::Vertex, StageKind::Fragment]);
        let of = |stage: StageKind| all.iter().filter(move |(_, s)| *s == stage).map(|(e, _)| *e);
        let vertex_reach: Vec<Handle<Function>> =
            of(StageKind::Vertex).flat_map(|e| reachable(module, &module.entry_points[e].function)).collect();
        let fragment: Vec<usize> = of(StageKind::Fragment).collect();
        // Per function: None unseen, Some(true) every call so far uniform.
        let mut calls: Vec<Option<bool>> = vec![None; module.functions.len()];
        let mut todo: Vec<(Handle<Function>, bool)> = Vec::new();
        for &e in &fragment {
            let fun = &module.entry_points[e].function;
            let uniform = uniformity(info.get_entry_point(e), fun);
            walk(&fun.body, true, &uniform, &mut |f, flow| todo.push((f, flow)));
        }
        while let Some((f, flow)) = todo.pop() {
            let was = calls[f.index()];
            let now = was.unwrap_or(true) && flow;
            if was == Some(now) {
                continue;
            }
            calls[f.index()] = Some(now);
            let uniform = uniformity(&info[f], &module.functions[f]);
            walk(&module.functions[f].body, now, &uniform, &mut |g, flow| todo.push((g, flow)));
        }
        let uniform_functions =
            module.functions.iter().map(|(h, _)| h).filter(|h| calls[h.index()] == Some(true) && !vertex_reach.contains(h)).collect();
        Flow { uniform_functions }
    }

    /// Whether the body of function `f` starts in uniform flow.
    pub fn function_is_uniform(&self, f: Handle<Function>) -> bool {
        self.uniform_functions.contains(&f)
    }
}

/// Per expression of a function: its value is the same in every invocation of a draw.
pub fn uniformity(info: &naga::valid::FunctionInfo, fun: &Function) -> Vec<bool> {
    fun.expressions.iter().map(|(h, _)| info[h].uniformity.non_uniform_result.is_none()).collect()
}

/// The flow inside a statement's blocks, and after it, when it starts in `flow`.
pub fn flow_of(stmt: &Statement, flow: bool, uniform: &[bool]) -> (bool, bool) {
    let is = |h: &Handle<Expression>| uniform.get(h.index()).copied().unwrap_or(false);
    let inside = match stmt {
        Statement::If { condition, .. } => flow && is(condition),
        Statement::Switch { selector, .. } => flow && is(selector),
        // naga counts every local variable as varying, so no loop is proven uniform.
        Statement::Loop { .. } => false,
        _ => flow,
    };
    // Some invocations may have left the function or the draw inside a varying branch.
    let after = match stmt {
        Statement::If { accept, reject, .. } => inside || flow && !leaves(accept) && !leaves(reject),
        Statement::Switch { cases, .. } => inside || flow && !cases.iter().any(|c| leaves(&c.body)),
        Statement::Loop { body, continuing, .. } => flow && !leaves(body) && !leaves(continuing),
        Statement::Block(b) => flow && !leaves(b),
        _ => flow,
    };
    (inside, after)
}

/// `block` returns or discards somewhere (a loop's `break` only leaves the loop).
fn leaves(block: &Block) -> bool {
    let mut found = false;
    each_statement(block, &mut |s| found |= matches!(s, Statement::Return { .. } | Statement::Kill));
    found
}

/// Calls `call` with every function `block` calls and the flow at the call.
fn walk(block: &Block, mut flow: bool, uniform: &[bool], call: &mut dyn FnMut(Handle<Function>, bool)) {
    for s in block.iter() {
        let (inside, after) = flow_of(s, flow, uniform);
        match s {
            Statement::Call { function, .. } => call(*function, flow),
            Statement::Block(b) => walk(b, inside, uniform, call),
            Statement::If { accept, reject, .. } => {
                walk(accept, inside, uniform, call);
                walk(reject, inside, uniform, call);
            }
            Statement::Loop { body, continuing, .. } => {
                walk(body, inside, uniform, call);
                walk(continuing, inside, uniform, call);
            }
            Statement::Switch { cases, .. } => cases.iter().for_each(|c| walk(&c.body, inside, uniform, call)),
            _ => {}
        }
        flow = after;
    }
}

/// Which values of a module are continuous over a primitive.
pub struct Continuity {
    /// Private globals only ever stored from an entry point's arguments: interpolated inputs
    /// (a `flat` one is constant over a primitive).
    inputs: Vec<Handle<naga::GlobalVariable>>,
}

/// How deep [`Continuity::of`] follows an operand's expressions and variables.
const DEPTH: u32 = 64;

impl Continuity {
    pub fn new(module: &Module) -> Continuity {
        let mut stores: Vec<(Handle<naga::GlobalVariable>, bool)> = Vec::new();
        let mut note = |fun: &Function, entry: bool| {
            each_store(&fun.body, &mut |pointer, value| {
                if let Some(Root::Global(g)) = root(fun, pointer) {
                    let from_argument = entry && argument_part(fun, value);
                    stores.push((g, from_argument));
                }
            })
        };
        module.functions.iter().for_each(|(_, f)| note(f, false));
        module.entry_points.iter().for_each(|e| note(&e.function, true));
        let inputs = module
            .global_variables
            .iter()
            .filter(|(g, v)| {
                v.space == naga::AddressSpace::Private
                    && stores.iter().any(|s| s.0 == *g)
                    && stores.iter().filter(|s| s.0 == *g).all(|s| s.1)
            })
            .map(|(g, _)| g)
            .collect();
        Continuity { inputs }
    }

    /// Whether `h` of `fun` (an entry point's own function with `entry`) is continuous over a
    /// primitive: built from interpolated inputs, uniforms and constants by continuous
    /// operations, through local variables stored once, outside any branch or loop.
    fn of(&self, globals: &naga::Arena<naga::GlobalVariable>, fun: &Function, entry: bool, h: Handle<Expression>) -> bool {
        self.within(globals, fun, entry, h, DEPTH)
    }

    /// Whether the operands of the operation `h` warned about with `code` ([`operands`]) are
    /// all continuous over a primitive.
    pub fn at(&self, globals: &naga::Arena<naga::GlobalVariable>, fun: &Function, entry: bool, code: Code, h: Handle<Expression>) -> bool {
        let operands = operands(code, &fun.expressions[h]);
        !operands.is_empty() && operands.iter().all(|o| self.of(globals, fun, entry, *o))
    }

    fn within(&self, globals: &naga::Arena<naga::GlobalVariable>, fun: &Function, entry: bool, h: Handle<Expression>, depth: u32) -> bool {
        let go = |x: Handle<Expression>| depth > 0 && self.within(globals, fun, entry, x, depth - 1);
        match &fun.expressions[h] {
            Expression::Literal(_) | Expression::Constant(_) | Expression::ZeroValue(_) | Expression::Override(_) => true,
            Expression::FunctionArgument(_) => entry,
            Expression::Binary { op: B::Add | B::Subtract | B::Multiply | B::Divide, left, right } => go(*left) && go(*right),
            Expression::Unary { op: naga::UnaryOperator::Negate, expr } => go(*expr),
            Expression::Splat { value, .. } => go(*value),
            Expression::Swizzle { vector, .. } => go(*vector),
            Expression::AccessIndex { base, .. } => go(*base),
            Expression::Compose { components, .. } => components.iter().all(|c| go(*c)),
            Expression::Math { fun: f, arg, arg1, arg2, .. } => {
                continuous_math(*f) && go(*arg) && [arg1, arg2].into_iter().flatten().all(|a| go(*a))
            }
            Expression::Load { pointer } => match root(fun, *pointer) {
                Some(Root::Global(g)) => {
                    let space = globals[g].space;
                    matches!(space, naga::AddressSpace::Uniform | naga::AddressSpace::Immediate) || self.inputs.contains(&g)
                }
                Some(Root::Local(l)) => match stored_once(fun, l) {
                    Some(value) => go(value),
                    None => false,
                },
                None => false,
            },
            _ => false,
        }
    }
}

/// An entry point's argument, or a member or element of one (an interface block's).
fn argument_part(fun: &Function, h: Handle<Expression>) -> bool {
    match fun.expressions[h] {
        Expression::FunctionArgument(_) => true,
        Expression::AccessIndex { base, .. } => argument_part(fun, base),
        _ => false,
    }
}

/// `sign`, `floor`, `fract`, `step`, `tan`, `atan2`, derivatives and the like jump.
fn continuous_math(f: M) -> bool {
    matches!(
        f,
        M::Abs
            | M::Min
            | M::Max
            | M::Clamp
            | M::Saturate
            | M::Cos
            | M::Cosh
            | M::Sin
            | M::Sinh
            | M::Tanh
            | M::Asin
            | M::Acos
            | M::Atan
            | M::Radians
            | M::Degrees
            | M::Exp
            | M::Exp2
            | M::Log
            | M::Log2
            | M::Pow
            | M::Dot
            | M::Cross
            | M::Distance
            | M::Length
            | M::Normalize
            | M::Reflect
            | M::Mix
            | M::SmoothStep
            | M::Sqrt
            | M::InverseSqrt
            | M::Fma
            | M::Transpose
            | M::Determinant
            | M::Outer
    )
}

/// The variable a pointer expression points into.
#[derive(Clone, Copy, PartialEq)]
enum Root {
    Global(Handle<naga::GlobalVariable>),
    Local(Handle<naga::LocalVariable>),
}

fn root(fun: &Function, pointer: Handle<Expression>) -> Option<Root> {
    match fun.expressions[pointer] {
        Expression::GlobalVariable(g) => Some(Root::Global(g)),
        Expression::LocalVariable(l) => Some(Root::Local(l)),
        Expression::AccessIndex { base, .. } | Expression::Access { base, .. } => root(fun, base),
        _ => None,
    }
}

/// Calls `f` with the pointer and value of every store in `block`.
fn each_store(block: &Block, f: &mut dyn FnMut(Handle<Expression>, Handle<Expression>)) {
    each_statement(block, &mut |s| {
        if let Statement::Store { pointer, value } = s {
            f(*pointer, *value);
        }
    })
}

/// The value of local `l` when it is written exactly once, whole, by a store at the top
/// level of the function's body, and never handed to a call (which could write it).
fn stored_once(fun: &Function, l: Handle<naga::LocalVariable>) -> Option<Handle<Expression>> {
    let mine = |p: Handle<Expression>| root(fun, p) == Some(Root::Local(l));
    let mut all = 0;
    each_store(&fun.body, &mut |p, _| all += usize::from(mine(p)));
    let handed = fun.body.iter().any(|s| matches!(s, Statement::Call { arguments, .. } if arguments.iter().any(|a| mine(*a))));
    if all != 1 || handed || fun.local_variables[l].init.is_some() {
        return None;
    }
    fun.body.iter().find_map(|s| match s {
        Statement::Store { pointer, value } if matches!(fun.expressions[*pointer], Expression::LocalVariable(x) if x == l) => Some(*value),
        _ => None,
    })
}

/// The operands of the operation `e` (warning `code`) whose zero between pixels counts:
/// a divisor, a vector `normalize`d, `atan`'s y and x (none for other warnings).
pub fn operands(code: Code, e: &Expression) -> Vec<Handle<Expression>> {
    match (code, e) {
        (Code::HazardDivision, Expression::Binary { op: B::Divide, right, .. }) => vec![*right],
        (Code::HazardNormalize, Expression::Math { fun: M::Normalize, arg, .. }) => vec![*arg],
        (Code::HazardAtan2, Expression::Math { fun: M::Atan2, arg, arg1: Some(x), .. }) => vec![*arg, *x],
        _ => Vec::new(),
    }
}

/// A scalar `bool`: the `operands` of an operation (warning `code`, [`operands`]) pass
/// through zero between this fragment and its right or upper neighbour. `None` where they
/// are not 32-bit floats.
pub fn between_pixels<'t>(
    b: &mut Builder<'_>,
    code: Code,
    operands: &[Handle<Expression>],
    ty: &dyn Fn(Handle<Expression>) -> Option<&'t TypeInner>,
) -> Option<Handle<Expression>> {
    let float = |h: Handle<Expression>| match ty(h) {
        Some(TypeInner::Scalar(s)) if *s == naga::Scalar::F32 => Some(None),
        Some(TypeInner::Vector { size, scalar }) if *scalar == naga::Scalar::F32 => Some(Some(*size)),
        _ => None,
    };
    let size = float(*operands.first()?)?;
    if operands.iter().any(|h| float(*h) != Some(size)) {
        return None;
    }
    let mut any = None;
    for axis in [DerivativeAxis::X, DerivativeAxis::Y] {
        // Per operand: its components here and at the neighbour.
        let ends: Vec<(Scalars, Scalars)> = operands
            .iter()
            .map(|&v| {
                let d = b.add(Expression::Derivative { axis, ctrl: DerivativeControl::Fine, expr: v });
                let n = b.add(Expression::Binary { op: B::Add, left: v, right: d });
                (components(b, v, size), components(b, n, size))
            })
            .collect();
        let lists: Vec<Vec<(Handle<Expression>, Handle<Expression>)>> = match code {
            // A vector is zero when all its components are.
            Code::HazardNormalize => vec![ends[0].0.iter().copied().zip(ends[0].1.iter().copied()).collect()],
            // Component-wise: y and x of one component together.
            _ => (0..ends[0].0.len()).map(|i| ends.iter().map(|(v, n)| (v[i], n[i])).collect()).collect(),
        };
        for list in lists {
            let met = meet(b, &list);
            any = Some(match any {
                Some(a) => b.add(Expression::Binary { op: B::LogicalOr, left: a, right: met }),
                None => met,
            });
        }
    }
    any
}

/// The scalar components of a value, in order.
type Scalars = Vec<Handle<Expression>>;

fn components(b: &mut Builder<'_>, v: Handle<Expression>, size: Option<VectorSize>) -> Vec<Handle<Expression>> {
    match size {
        None => vec![v],
        Some(s) => (0..s as u32).map(|index| b.add(Expression::AccessIndex { base: v, index })).collect(),
    }
}

/// A scalar `bool`: every pair `(here, there)` of scalars reaches zero on the segment from
/// `here` to `there`, all at one point within [`SUBPIXEL`] (a pair zero at both ends is zero
/// all along).
fn meet(b: &mut Builder<'_>, pairs: &[(Handle<Expression>, Handle<Expression>)]) -> Handle<Expression> {
    let f = |b: &mut Builder<'_>, x: f32| b.add(Expression::Literal(Literal::F32(x)));
    let (mut ok, mut lo, mut hi) = (None, None, None);
    for &(here, there) in pairs {
        let (s1, s2) = (b.math(M::Sign, here, None), b.math(M::Sign, there, None));
        let product = b.add(Expression::Binary { op: B::Multiply, left: s1, right: s2 });
        let zero = f(b, 0.0);
        let opposite = b.add(Expression::Binary { op: B::LessEqual, left: product, right: zero });
        let moving = b.add(Expression::Binary { op: B::NotEqual, left: here, right: there });
        let step = b.add(Expression::Binary { op: B::Subtract, left: here, right: there });
        let t = b.add(Expression::Binary { op: B::Divide, left: here, right: step });
        let (past, before) = (f(b, 2.0), f(b, -1.0));
        let t_lo = b.add(Expression::Select { condition: moving, accept: t, reject: past });
        let t_hi = b.add(Expression::Select { condition: moving, accept: t, reject: before });
        ok = Some(match ok {
            Some(o) => b.add(Expression::Binary { op: B::LogicalAnd, left: o, right: opposite }),
            None => opposite,
        });
        lo = Some(match lo {
            Some(l) => b.math(M::Min, l, Some(t_lo)),
            None => t_lo,
        });
        hi = Some(match hi {
            Some(h) => b.math(M::Max, h, Some(t_hi)),
            None => t_hi,
        });
    }
    let (Some(ok), Some(lo), Some(hi)) = (ok, lo, hi) else { return b.add(Expression::Literal(Literal::Bool(false))) };
    let spread = b.add(Expression::Binary { op: B::Subtract, left: hi, right: lo });
    let grid = f(b, SUBPIXEL);
    let together = b.add(Expression::Binary { op: B::LessEqual, left: spread, right: grid });
    b.add(Expression::Binary { op: B::LogicalAnd, left: ok, right: together })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stmt_if(condition: Handle<Expression>, leave: bool) -> Statement {
        let mut accept = Block::new();
        if leave {
            accept.push(Statement::Kill, naga::Span::UNDEFINED);
        }
        Statement::If { condition, accept, reject: Block::new() }
    }

    #[test]
    fn flow_stays_uniform_through_uniform_branches_only() {
        let mut arena: naga::Arena<Expression> = naga::Arena::new();
        let uni = arena.append(Expression::Literal(Literal::Bool(true)), naga::Span::UNDEFINED);
        let var = arena.append(Expression::Literal(Literal::Bool(true)), naga::Span::UNDEFINED);
        let uniform = [true, false];
        // A uniform branch: uniform inside and after, even when it discards.
        assert_eq!(flow_of(&stmt_if(uni, true), true, &uniform), (true, true));
        // A varying branch: varying inside; after it only if no invocation left in it.
        assert_eq!(flow_of(&stmt_if(var, false), true, &uniform), (false, true));
        assert_eq!(flow_of(&stmt_if(var, true), true, &uniform), (false, false));
        // Varying flow stays varying.
        assert_eq!(flow_of(&stmt_if(uni, false), false, &uniform), (false, false));
        let lp = Statement::Loop { body: Block::new(), continuing: Block::new(), break_if: None };
        assert_eq!(flow_of(&lp, true, &uniform), (false, true), "inside a loop is never proven uniform; a break rejoins after it");
    }
}
