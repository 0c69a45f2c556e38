//! naga IR plumbing the run-time instrumentations share ([`crate::stress::culprit`] and
//! [`crate::stress::sites`]): the storage buffer they count into, a binding for it, the
//! functions an entry point calls, a hook before every statement that ends an
//! invocation, and a builder that appends expressions and emits them.

use naga::{
    BinaryOperator as B, Block, Expression, Function, Handle, Literal, MathFunction as M, Module, RelationalFunction, ScalarKind, Span,
    Statement, TypeInner, VectorSize,
};

use crate::back::Translation;
use crate::front::program::CompiledProgram;
use crate::manifest::Effect;
use crate::stage::StageKind;

/// The name of the storage buffer the counts are written to.
pub const COUNTS_BUFFER: &str = "effectc_probe_counts";

/// `var<storage, read_write> effectc_probe_counts: array<atomic<u32>, slots>` at `binding`.
pub fn counts_buffer(module: &mut Module, slots: u32, (group, binding): (u32, u32)) -> Result<Handle<naga::GlobalVariable>, String> {
    let atomic = module.types.insert(naga::Type { name: None, inner: TypeInner::Atomic(naga::Scalar::U32) }, Span::UNDEFINED);
    let size = std::num::NonZeroU32::new(slots).ok_or("no probe slots")?;
    let array = module.types.insert(
        naga::Type { name: None, inner: TypeInner::Array { base: atomic, size: naga::ArraySize::Constant(size), stride: 4 } },
        Span::UNDEFINED,
    );
    Ok(module.global_variables.append(
        naga::GlobalVariable {
            name: Some(COUNTS_BUFFER.into()),
            space: naga::AddressSpace::Storage { access: naga::StorageAccess::LOAD | naga::StorageAccess::STORE },
            binding: Some(naga::ResourceBinding { group, binding }),
            ty: array,
            init: None,
            memory_decorations: naga::MemoryDecorations::empty(),
        },
        Span::UNDEFINED,
    ))
}

/// A private `u32` of every invocation (zero when it starts).
pub fn private_u32(module: &mut Module, name: &str) -> Handle<naga::GlobalVariable> {
    let u32_ty = module.types.insert(naga::Type { name: None, inner: TypeInner::Scalar(naga::Scalar::U32) }, Span::UNDEFINED);
    module.global_variables.append(
        naga::GlobalVariable {
            name: Some(name.into()),
            space: naga::AddressSpace::Private,
            binding: None,
            ty: u32_ty,
            init: None,
            memory_decorations: naga::MemoryDecorations::empty(),
        },
        Span::UNDEFINED,
    )
}

/// A binding no resource of `module` uses: the next binding of its last group (group 0
/// when it has none), so no new bind group is needed.
pub fn free_binding(module: &Module) -> (u32, u32) {
    let used: Vec<(u32, u32)> =
        module.global_variables.iter().filter_map(|(_, g)| g.binding.as_ref().map(|b| (b.group, b.binding))).collect();
    let group = used.iter().map(|b| b.0).max().unwrap_or(0);
    let binding = used.iter().filter(|b| b.0 == group).map(|b| b.1 + 1).max().unwrap_or(0);
    (group, binding)
}

/// Calls `f` with every statement of `block` and of the blocks it holds, outer first.
pub fn each_statement(block: &Block, f: &mut dyn FnMut(&Statement)) {
    for s in block.iter() {
        f(s);
        match s {
            Statement::Block(b) => each_statement(b, f),
            Statement::If { accept, reject, .. } => {
                each_statement(accept, f);
                each_statement(reject, f);
            }
            Statement::Loop { body, continuing, .. } => {
                each_statement(body, f);
                each_statement(continuing, f);
            }
            Statement::Switch { cases, .. } => cases.iter().for_each(|c| each_statement(&c.body, f)),
            _ => {}
        }
    }
}

/// Functions called, directly or not, from `f`, callees first.
pub fn reachable(module: &Module, f: &Function) -> Vec<Handle<Function>> {
    let calls = |block: &Block, out: &mut Vec<Handle<Function>>| {
        each_statement(block, &mut |s| {
            if let Statement::Call { function, .. } = s {
                out.push(*function);
            }
        })
    };
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

/// Which statements end an invocation in the function being rewritten.
#[derive(Clone, Copy, PartialEq)]
pub enum Exits {
    /// The entry point: its returns and discards.
    ReturnsAndDiscards,
    /// A function it calls: only a discard ends the invocation there.
    Discards,
}

/// `stmt` with `f` applied to each block it holds (a block, both arms of an `if`, a loop's
/// body and continuing, every case of a switch); other statements as they are.
pub fn map_blocks(stmt: Statement, f: &mut dyn FnMut(Block) -> Block) -> Statement {
    match stmt {
        Statement::Block(b) => Statement::Block(f(b)),
        Statement::If { condition, accept, reject } => Statement::If { condition, accept: f(accept), reject: f(reject) },
        Statement::Loop { body, continuing, break_if } => Statement::Loop { body: f(body), continuing: f(continuing), break_if },
        Statement::Switch { selector, cases } => {
            Statement::Switch { selector, cases: cases.into_iter().map(|c| naga::SwitchCase { body: f(c.body), ..c }).collect() }
        }
        other => other,
    }
}

/// `block` with the statements `count` appends placed before every statement that ends
/// the invocation.
pub fn count_at_exits(fun: &mut Function, block: Block, exits: Exits, count: &dyn Fn(&mut Function, &mut Block)) -> Block {
    let mut out = Block::with_capacity(block.len());
    for (stmt, span) in block.span_into_iter() {
        let stmt = match stmt {
            Statement::Kill => {
                count(fun, &mut out);
                Statement::Kill
            }
            exit @ Statement::Return { .. } if exits == Exits::ReturnsAndDiscards => {
                count(fun, &mut out);
                exit
            }
            other => map_blocks(other, &mut |b| count_at_exits(fun, b, exits, count)),
        };
        out.push(stmt, span);
    }
    out
}

/// Counts at every exit of the entry point `entry` and of the functions it calls (a
/// `discard` there ends the invocation), and at the end of a body that ends without a
/// `return`.
pub fn count_at_every_exit(module: &mut Module, entry: usize, count: &dyn Fn(&mut Function, &mut Block)) {
    for f in reachable(module, &module.entry_points[entry].function) {
        let fun = &mut module.functions[f];
        let body = std::mem::take(&mut fun.body);
        fun.body = count_at_exits(fun, body, Exits::Discards, count);
    }
    let fun = &mut module.entry_points[entry].function;
    let body = std::mem::take(&mut fun.body);
    let mut body = count_at_exits(fun, body, Exits::ReturnsAndDiscards, count);
    if !matches!(body.last(), Some(Statement::Return { .. } | Statement::Kill)) {
        count(fun, &mut body);
    }
    fun.body = body;
}

/// The vertex and fragment entry points of `module` among `stages`: (index, stage).
pub fn entries(module: &Module, stages: &[StageKind]) -> Vec<(usize, StageKind)> {
    module
        .entry_points
        .iter()
        .enumerate()
        .filter_map(|(i, e)| {
            let stage = match e.stage {
                naga::ShaderStage::Vertex => StageKind::Vertex,
                naga::ShaderStage::Fragment => StageKind::Fragment,
                _ => return None,
            };
            stages.contains(&stage).then_some((i, stage))
        })
        .collect()
}

/// The resolved type of every expression of a function, by index.
pub fn types_of(module: &Module, info: &naga::valid::FunctionInfo, handles: impl Iterator<Item = Handle<Expression>>) -> Vec<TypeInner> {
    handles.map(|h| info[h].ty.inner_with(&module.types).clone()).collect()
}

/// The text each stage's spans index in a translation of `program`: the rewritten stage,
/// or for the vertex stage of a folded program the fold's text.
pub fn stage_texts(program: &CompiledProgram) -> Vec<(StageKind, &str)> {
    program
        .stages
        .iter()
        .filter_map(|s| match (s.syntax.stage, program.fold()) {
            (StageKind::Vertex, Some(f)) => Some((StageKind::Vertex, f.drawn.text.as_str())),
            (kind, _) => Some((kind, s.rewritten.as_ref()?.text.as_str())),
        })
        .collect()
}

/// Validates and reflects an instrumented translation again (`program` and `effect`: what
/// it was translated from), so the renderer binds the counts buffer like any other
/// storage buffer.
pub fn revalidate(t: &mut Translation, program: &CompiledProgram, effect: Option<&Effect>) -> Result<(), String> {
    t.info = crate::front::naga_run::validator()
        .validate(&t.module)
        .map_err(|e| format!("the translated module does not validate: {}", e.as_inner()))?;
    let left_out = std::mem::take(&mut t.reflection.left_out);
    t.reflection = crate::back::reflect::reflect_program(&t.name, &t.module, program, effect, left_out);
    Ok(())
}

/// The scalar kind and vector size of a value.
#[derive(Debug, Clone, Copy)]
pub struct Shape {
    pub kind: ScalarKind,
    pub size: Option<VectorSize>,
}

impl Shape {
    pub fn of(ty: Option<&TypeInner>) -> Shape {
        match ty {
            Some(TypeInner::Vector { size, scalar }) => Shape { kind: scalar.kind, size: Some(*size) },
            Some(TypeInner::Scalar(s)) => Shape { kind: s.kind, size: None },
            _ => Shape { kind: ScalarKind::Float, size: None },
        }
    }
}

pub fn literal(kind: ScalarKind, x: f64) -> Literal {
    match kind {
        ScalarKind::Sint => Literal::I32(x as i32),
        ScalarKind::Uint => Literal::U32(x as u32),
        _ => Literal::F32(x as f32),
    }
}

/// Appends expressions to a function, emitting them in ranges of what may be emitted, and
/// gathers the statements that evaluate them.
pub struct Builder<'f> {
    pub fun: &'f mut Function,
    out: Block,
    range: Option<(Handle<Expression>, Handle<Expression>)>,
}

impl<'f> Builder<'f> {
    pub fn new(fun: &'f mut Function) -> Self {
        Builder { fun, out: Block::new(), range: None }
    }

    pub fn add(&mut self, e: Expression) -> Handle<Expression> {
        let pre = e.needs_pre_emit();
        if pre {
            self.flush();
        }
        let h = self.fun.expressions.append(e, Span::UNDEFINED);
        if !pre {
            self.range = Some((self.range.map_or(h, |r| r.0), h));
        }
        h
    }

    pub fn flush(&mut self) {
        if let Some((first, last)) = self.range.take() {
            self.out.push(Statement::Emit(naga::Range::new_from_bounds(first, last)), Span::UNDEFINED);
        }
    }

    pub fn stmt(&mut self, s: Statement) {
        self.flush();
        self.out.push(s, Span::UNDEFINED);
    }

    pub fn finish(mut self) -> Block {
        self.flush();
        self.out
    }

    pub fn math(&mut self, fun: M, arg: Handle<Expression>, arg1: Option<Handle<Expression>>) -> Handle<Expression> {
        self.add(Expression::Math { fun, arg, arg1, arg2: None, arg3: None })
    }

    pub fn splat(&mut self, l: Literal, s: Shape) -> Handle<Expression> {
        let value = self.add(Expression::Literal(l));
        match s.size {
            Some(size) => self.add(Expression::Splat { size, value }),
            None => value,
        }
    }

    pub fn splat_f32(&mut self, x: f32, s: Shape) -> Handle<Expression> {
        self.splat(Literal::F32(x), s)
    }

    pub fn zero(&mut self, s: Shape) -> Handle<Expression> {
        self.splat(literal(s.kind, 0.0), s)
    }

    pub fn cmp(&mut self, op: B, left: Handle<Expression>, right: Handle<Expression>) -> Handle<Expression> {
        self.add(Expression::Binary { op, left, right })
    }

    /// A scalar `bool`: some component of the comparison holds.
    pub fn any(&mut self, b: Handle<Expression>, s: Shape) -> Handle<Expression> {
        match s.size {
            Some(_) => self.add(Expression::Relational { fun: RelationalFunction::Any, argument: b }),
            None => b,
        }
    }

    pub fn any_cmp(&mut self, op: B, left: Handle<Expression>, right: Handle<Expression>, s: Shape) -> Handle<Expression> {
        let c = self.cmp(op, left, right);
        self.any(c, s)
    }

    /// Some component of a signed integer is negative (never, for an unsigned one).
    pub fn any_sign(&mut self, x: Handle<Expression>, s: Shape) -> Handle<Expression> {
        if s.kind != ScalarKind::Sint {
            return self.add(Expression::Literal(Literal::Bool(false)));
        }
        let zero = self.zero(s);
        self.any_cmp(B::Less, x, zero, s)
    }

    /// `mask |= 1u << bit`.
    pub fn mark(&mut self, mask: Handle<naga::GlobalVariable>, bit: u32) {
        let ptr = self.add(Expression::GlobalVariable(mask));
        let now = self.add(Expression::Load { pointer: ptr });
        let one = self.add(Expression::Literal(Literal::U32(1 << bit)));
        let value = self.add(Expression::Binary { op: B::InclusiveOr, left: now, right: one });
        self.stmt(Statement::Store { pointer: ptr, value });
    }

    pub fn set_u32(&mut self, var: Handle<naga::GlobalVariable>, x: u32) {
        let ptr = self.add(Expression::GlobalVariable(var));
        let value = self.add(Expression::Literal(Literal::U32(x)));
        self.stmt(Statement::Store { pointer: ptr, value });
    }
}
