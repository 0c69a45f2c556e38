//! Loads from workgroup memory right after a control barrier, written as WGSL's
//! `workgroupUniformLoad` (for the WGSL output only).
//!
//! Compute code shares a decision through workgroup memory: one invocation writes a `shared`
//! variable (or ORs bits into a `shared` atomic), `barrier()`, then every invocation reads it
//! and branches on it, and a later `barrier()` sits behind that branch (Granite's `hiz` pass
//! asks "am I the last workgroup?", its meshlet culling builds a ballot so). Every invocation
//! reads the same value, but WGSL's uniformity analysis takes any read of workgroup memory as
//! possibly non-uniform, and tint refuses the later barrier ("'workgroupBarrier' must only be
//! called from uniform control flow"). `workgroupUniformLoad(p)` is how WGSL says it: a
//! control barrier, then a load whose value is uniform.
//!
//! A load from workgroup memory that follows a control barrier in the same block, with only
//! expression evaluation between, becomes one. The barrier proves the place is reached by the
//! whole workgroup (uniform control flow), and nothing is stored between it and the load, so
//! the barrier `workgroupUniformLoad` adds changes no value read. Loads through an index
//! computed at run time (WGSL wants a uniform pointer) or of a vector or matrix component
//! (no pointer to a whole value) are left as they are.

use naga::{AddressSpace, Block, Expression, Function, Handle, Module, Range, Span, Statement, Type, TypeInner};

use crate::front::statements::child_blocks;

/// `module` with the loads of the module doc made `workgroupUniformLoad`s, or `None` when it
/// has none.
pub(crate) fn after_barriers(module: &Module) -> Option<Module> {
    // Control barriers are for compute-like stages only: other modules are not copied.
    if !module.entry_points.iter().any(|e| e.stage.compute_like()) {
        return None;
    }
    let mut out = module.clone();
    let mut changed = false;
    let Module { types, global_variables, functions, entry_points, .. } = &mut out;
    let functions = functions.iter_mut().map(|(_, f)| f).chain(entry_points.iter_mut().map(|e| &mut e.function));
    for function in functions {
        let Function { expressions, body, .. } = function;
        let mut context = Context { types, globals: global_variables, expressions, changed: false };
        rewrite_block(body, &mut context);
        changed |= context.changed;
    }
    changed.then_some(out)
}

struct Context<'a> {
    types: &'a mut naga::UniqueArena<Type>,
    globals: &'a naga::Arena<naga::GlobalVariable>,
    expressions: &'a mut naga::Arena<Expression>,
    changed: bool,
}

impl Context<'_> {
    /// The type a `workgroupUniformLoad` through `pointer` returns, when `pointer` points at a
    /// whole value in workgroup memory (an atomic's value is its scalar).
    fn uniform_load_type(&mut self, pointer: Handle<Expression>) -> Option<Handle<Type>> {
        let pointee = self.pointee(pointer)?;
        match self.types[pointee].inner {
            TypeInner::Atomic(scalar) => Some(self.types.insert(Type { name: None, inner: TypeInner::Scalar(scalar) }, Span::UNDEFINED)),
            _ => self.plain(pointee).then_some(pointee),
        }
    }

    /// Whether a value of `ty` can be loaded whole (no atomics, pointers or resources in it).
    fn plain(&self, ty: Handle<Type>) -> bool {
        match self.types[ty].inner {
            TypeInner::Scalar(_) | TypeInner::Vector { .. } | TypeInner::Matrix { .. } => true,
            TypeInner::Array { base, size: naga::ArraySize::Constant(_), .. } => self.plain(base),
            TypeInner::Struct { ref members, .. } => members.iter().all(|m| self.plain(m.ty)),
            _ => false,
        }
    }

    /// The type `pointer` points at, when it is a global in workgroup memory or a struct
    /// member or array element of one at a constant index (`workgroupUniformLoad` takes a
    /// uniform pointer only, and an index computed at run time may not be).
    fn pointee(&self, pointer: Handle<Expression>) -> Option<Handle<Type>> {
        match self.expressions[pointer] {
            Expression::GlobalVariable(g) => (self.globals[g].space == AddressSpace::WorkGroup).then_some(self.globals[g].ty),
            Expression::AccessIndex { base, index } => match self.types[self.pointee(base)?].inner {
                TypeInner::Struct { ref members, .. } => members.get(index as usize).map(|m| m.ty),
                TypeInner::Array { base, .. } => Some(base),
                _ => None,
            },
            _ => None,
        }
    }
}

fn rewrite_block(block: &mut Block, context: &mut Context) {
    let old = std::mem::take(block);
    let mut after_barrier = false;
    for (mut statement, span) in old.span_into_iter() {
        for child in child_blocks(&mut statement) {
            rewrite_block(child, context);
        }
        match statement {
            Statement::ControlBarrier(_) => {
                after_barrier = true;
                block.push(statement, span);
            }
            Statement::Emit(range) if after_barrier => emit_with_uniform_loads(block, range, span, context),
            _ => {
                after_barrier = false;
                block.push(statement, span);
            }
        }
    }
}

/// Pushes `Emit(range)`, split around the loads it turns into `workgroupUniformLoad`s.
fn emit_with_uniform_loads(block: &mut Block, range: Range<Expression>, span: Span, context: &mut Context) {
    let handles: Vec<Handle<Expression>> = range.clone().collect();
    let mut pending: Vec<Handle<Expression>> = Vec::new();
    let flush = |block: &mut Block, pending: &mut Vec<Handle<Expression>>| {
        if let (Some(&first), Some(&last)) = (pending.first(), pending.last()) {
            block.push(Statement::Emit(Range::new_from_bounds(first, last)), span);
        }
        pending.clear();
    };
    for handle in handles {
        let uniform = match context.expressions[handle] {
            Expression::Load { pointer } => context.uniform_load_type(pointer).map(|ty| (pointer, ty)),
            _ => None,
        };
        let Some((pointer, ty)) = uniform else {
            pending.push(handle);
            continue;
        };
        flush(block, &mut pending);
        context.expressions[handle] = Expression::WorkGroupUniformLoadResult { ty };
        block.push(Statement::WorkGroupUniformLoad { pointer, result: handle }, span);
        context.changed = true;
    }
    flush(block, &mut pending);
}
