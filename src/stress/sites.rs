//! Hazard warnings tested at run time (`stress --confirm`): the operation each warning
//! points at is found in the translated module, and every time it runs the condition the
//! warning names is tested on its real operands: a divisor of 0 (or a denormal, which GPUs
//! flush to 0), an `asin`/`acos` argument outside [-1, 1], a negative `sqrt` or `pow` base,
//! a `log`/`inversesqrt` argument ≤ 0, a zero vector `normalize`d, a `sin`/`cos` argument
//! past 10⁴ rad, a `fract(sin(x) * K)` hash that a `sin` within GLSL's allowed error of
//! 2⁻¹¹ moves by more than a tenth, a negative `%` operand, a shift by ≥ 32, `atan(0, 0)`,
//! and a loop still running after [`LOOP_CAP`] iterations (which the instrumented program
//! then leaves, so a runaway loop cannot hang the device).
//!
//! In a fragment stage, a divisor, a normalized vector or `atan`'s arguments that pass
//! through zero between two neighbouring pixel centres count too ([`crate::stress::crossing`]).
//!
//! Each invocation keeps three bit masks (site reached, condition held, zero between pixels)
//! and adds them into a storage buffer when it ends: per instrumented entry point a region
//! of `1 + 3 × sites` slots, slot 0 counting invocations, then per site (reached, held,
//! between). Sites are matched to warnings by the span in the user's file, so it does not
//! matter which front made the IR.

use std::ops::Range;

use naga::{BinaryOperator as B, Block, Expression, Function, Handle, Literal, MathFunction as M, ScalarKind, Statement, TypeInner};

use crate::back::Translation;
use crate::diag::{Code, FileId};
use crate::front::macro_spans::narrowed_span;
use crate::front::program::CompiledProgram;
use crate::manifest::Effect;
use crate::stage::StageKind;
use crate::stress::crossing::{self, Continuity, Flow};
use crate::stress::ir::{
    count_at_every_exit, counts_buffer, entries, free_binding, literal, map_blocks, private_u32, reachable, revalidate, stage_texts,
    types_of, Builder, Shape,
};

/// Warnings one instrumented module tests at most (one bit each).
pub const MAX_SITES: usize = 32;
/// Iterations after which a loop warned about (W0719) counts as running away and is left:
/// below llvmpipe's own limit (it ends any shader loop after 65,535 iterations, so a
/// runaway loop there looks like one that ended).
pub const LOOP_CAP: u32 = 1 << 15;
/// The `sin` error GLSL allows (absolute, 2⁻¹¹), by which a hash's `sin` is moved.
const SIN_SLACK: f32 = 1.0 / 2048.0;

/// One warning to test: its code, its primary span in the user's file, and that file's
/// text (an operation's span is narrowed as the warning's was, [`narrowed_span`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Wanted {
    pub code: Code,
    pub file: FileId,
    pub range: Range<usize>,
    pub text: std::sync::Arc<str>,
}

/// What [`instrument_translation`] placed.
#[derive(Debug, Clone)]
pub struct Sites {
    /// For bit `k`, the index of its warning in the wanted list.
    pub bits: Vec<usize>,
    /// Warnings whose operation was found after [`MAX_SITES`] others: not instrumented.
    pub crowded: Vec<usize>,
    /// The instrumented entry points and the first slot of their region.
    pub regions: Vec<(StageKind, u32)>,
    pub slots: u32,
}

/// What one instrumented entry point counted.
#[derive(Debug, Clone, PartialEq)]
pub struct Counted {
    pub stage: StageKind,
    pub invocations: u64,
    /// Per bit: invocations that reached the site, those where its condition held, and
    /// those whose operands passed through zero between them and a neighbouring pixel.
    pub reached: Vec<u64>,
    pub held: Vec<u64>,
    pub between: Vec<u64>,
}

impl Sites {
    pub fn read(&self, counts: &[u32]) -> Vec<Counted> {
        let n = self.bits.len();
        self.regions
            .iter()
            .filter_map(|&(stage, base)| {
                let r = counts.get(base as usize..base as usize + 1 + 3 * n)?;
                let slot = |k: usize, j: usize| u64::from(r[1 + 3 * k + j]);
                Some(Counted {
                    stage,
                    invocations: u64::from(r[0]),
                    reached: (0..n).map(|k| slot(k, 0)).collect(),
                    held: (0..n).map(|k| slot(k, 1)).collect(),
                    between: (0..n).map(|k| slot(k, 2)).collect(),
                })
            })
            .collect()
    }
}

/// Instruments the sites of `wanted` in a translation of `program` (the vertex stage only
/// with `vertex`: the device must allow storage writes there). Warnings whose operation
/// is not found (or past [`MAX_SITES`]) get no bit. Zeros between pixels are tested where
/// the module still validates with them (else the sites are placed without them).
pub fn instrument_translation(
    t: &mut Translation,
    program: &CompiledProgram,
    effect: Option<&Effect>,
    wanted: &[Wanted],
    vertex: bool,
) -> Result<Sites, String> {
    let before = t.module.clone();
    instrument(t, program, effect, wanted, vertex, true).or_else(|_| {
        t.module = before;
        instrument(t, program, effect, wanted, vertex, false)
    })
}

fn instrument(
    t: &mut Translation,
    program: &CompiledProgram,
    effect: Option<&Effect>,
    wanted: &[Wanted],
    vertex: bool,
    between: bool,
) -> Result<Sites, String> {
    let stages: &[StageKind] = if vertex { &[StageKind::Vertex, StageKind::Fragment] } else { &[StageKind::Fragment] };
    let entries = entries(&t.module, stages);
    if entries.is_empty() {
        return Err("the program has no vertex or fragment stage to instrument".into());
    }
    // Every function once, with the text of the first stage that calls it.
    let mut functions: Vec<(Place, StageKind)> = Vec::new();
    for &(entry, stage) in &entries {
        for f in reachable(&t.module, &t.module.entry_points[entry].function) {
            if !functions.iter().any(|(p, _)| *p == Place::Function(f)) {
                functions.push((Place::Function(f), stage));
            }
        }
        functions.push((Place::Entry(entry), stage));
    }
    let found = find(t, program, wanted, &functions);
    // The operations of each warning: those at its very span; else those inside it (a
    // front may place a chain `a / b / c` differently, and the divisor the warning means is
    // one of them); else the best overlap.
    let (bits, crowded, chosen) = choose(&found, wanted.len());
    let flow = between.then(|| (Flow::of(&t.module, &t.info), Continuity::new(&t.module)));
    let module = &mut t.module;
    let reached = private_u32(module, "effectc_sites_reached");
    let held = private_u32(module, "effectc_sites_held");
    let crossed = private_u32(module, "effectc_sites_between");
    let loops: Vec<(u32, Handle<naga::GlobalVariable>)> = bits
        .iter()
        .enumerate()
        .filter(|(_, w)| wanted[**w].code == Code::HazardCounterOverflow)
        .map(|(bit, _)| (bit as u32, private_u32(module, &format!("effectc_site_loop{bit}"))))
        .collect();
    for &(place, _) in &functions {
        let here: Vec<(Handle<Expression>, u32)> = chosen.iter().filter(|c| c.0 == place).map(|c| (c.1, c.2)).collect();
        if here.is_empty() {
            continue;
        }
        // Where the body starts in uniform flow of a fragment stage: Some(true).
        let start = flow.as_ref().map(|(flow, _)| match place {
            Place::Function(f) => flow.function_is_uniform(f),
            Place::Entry(e) => module.entry_points[e].stage == naga::ShaderStage::Fragment,
        });
        let (fun, info) = match place {
            Place::Function(f) => (&mut module.functions[f], &t.info[f]),
            Place::Entry(e) => (&mut module.entry_points[e].function, t.info.get_entry_point(e)),
        };
        let types = types_of_mut(&module.types, info, fun);
        // The sites whose operands are continuous over a primitive, where a zero between
        // pixels is tested.
        let continuous: Vec<Handle<Expression>> = match (&flow, start) {
            (Some((_, continuity)), Some(true)) => {
                let entry = matches!(place, Place::Entry(_));
                let code = |bit: u32| wanted[bits[bit as usize]].code;
                here.iter()
                    .filter(|(h, bit)| continuity.at(&module.global_variables, fun, entry, code(*bit), *h))
                    .map(|(h, _)| *h)
                    .collect()
            }
            _ => Vec::new(),
        };
        let ctx = Ctx {
            here: &here,
            continuous: &continuous,
            types: &types,
            uniform: &crossing::uniformity(info, fun),
            codes: &bits.iter().map(|w| wanted[*w].code).collect::<Vec<_>>(),
            reached,
            held,
            crossed,
            loops: &loops,
        };
        let body = std::mem::take(&mut fun.body);
        fun.body = ctx.block(fun, body, start);
    }
    let n = bits.len() as u32;
    let width = 1 + 3 * n;
    let binding = free_binding(module);
    let counts = counts_buffer(module, width * entries.len() as u32, binding)?;
    let mut regions = Vec::new();
    for (k, &(entry, stage)) in entries.iter().enumerate() {
        let base = k as u32 * width;
        regions.push((stage, base));
        count_at_every_exit(module, entry, &|fun, out| push_counts(fun, out, [reached, held, crossed], counts, base, n));
    }
    revalidate(t, program, effect)?;
    Ok(Sites { bits, crowded, regions, slots: width * entries.len() as u32 })
}

/// The operations of `functions` that match a warning of `wanted` by code and span.
fn find(t: &Translation, program: &CompiledProgram, wanted: &[Wanted], functions: &[(Place, StageKind)]) -> Vec<Found> {
    let texts = stage_texts(program);
    let text_of = |stage: StageKind| texts.iter().find(|(s, _)| *s == stage).map(|(_, t)| *t).unwrap_or("");
    let mut found: Vec<Found> = Vec::new();
    for &(place, stage) in functions {
        let (fun, info) = match place {
            Place::Function(f) => (&t.module.functions[f], &t.info[f]),
            Place::Entry(e) => (&t.module.entry_points[e].function, t.info.get_entry_point(e)),
        };
        let types = types_of(&t.module, info, fun.expressions.iter().map(|(h, _)| h));
        let user = |h: Handle<Expression>| {
            let span = crate::check::hazards::eval::expression_span(fun, h, text_of(stage));
            program.user_span(stage, span.to_range()?)
        };
        for (h, e) in fun.expressions.iter() {
            for (w, want) in wanted.iter().enumerate() {
                let matches = match want.code {
                    Code::HazardCounterOverflow => counter_step(e, types.get(h.index())),
                    code => operation(code, e, &fun.expressions),
                };
                if !matches {
                    continue;
                }
                let Some((file, range)) = user(h) else { continue };
                if file != want.file {
                    continue;
                }
                let range = narrowed_span(&want.text, range);
                let score = overlap(&range, &want.range);
                if score > 0.0 {
                    let inside = want.range.start <= range.start && range.end <= want.range.end;
                    found.push(Found { wanted: w, place, h, score, inside });
                }
            }
        }
    }
    found
}

/// The operations each warning gets, with its bit: `(bits, crowded, chosen)`, where
/// `bits[k]` is the warning of bit `k`, `crowded` the warnings past [`MAX_SITES`], and
/// `chosen` every (function, operation, bit) to instrument.
fn choose(found: &[Found], wanted: usize) -> (Vec<usize>, Vec<usize>, Vec<Chosen>) {
    let mut bits: Vec<usize> = Vec::new();
    let mut crowded: Vec<usize> = Vec::new();
    let mut chosen: Vec<Chosen> = Vec::new();
    for w in 0..wanted {
        let mine: Vec<&Found> = found.iter().filter(|f| f.wanted == w).collect();
        let best = mine.iter().map(|f| f.score).fold(0.0, f64::max);
        let pick: Vec<&Found> = match (best == 2.0, mine.iter().any(|f| f.inside)) {
            (true, _) => mine.into_iter().filter(|f| f.score == 2.0).collect(),
            (false, true) => mine.into_iter().filter(|f| f.inside).collect(),
            (false, false) => mine.into_iter().filter(|f| f.score == best).collect(),
        };
        if pick.is_empty() {
            continue;
        }
        if bits.len() == MAX_SITES {
            crowded.push(w);
            continue;
        }
        let bit = bits.len() as u32;
        bits.push(w);
        chosen.extend(pick.into_iter().map(|f| (f.place, f.h, bit)));
    }
    (bits, crowded, chosen)
}

/// An operation to instrument: its function, its expression, its bit.
type Chosen = (Place, Handle<Expression>, u32);

/// A function of the module: one it declares, or an entry point's.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Place {
    Function(Handle<Function>),
    Entry(usize),
}

/// An operation that matches a warning, and how well its span matches the warning's.
struct Found {
    wanted: usize,
    place: Place,
    h: Handle<Expression>,
    score: f64,
    /// Its span lies inside the warning's.
    inside: bool,
}

/// 2 for the same range, else the share of the union both ranges cover.
fn overlap(a: &Range<usize>, b: &Range<usize>) -> f64 {
    if a == b {
        return 2.0;
    }
    let inter = a.end.min(b.end).saturating_sub(a.start.max(b.start));
    let union = a.end.max(b.end) - a.start.min(b.start);
    if union == 0 {
        return 0.0;
    }
    inter as f64 / union as f64
}

fn types_of_mut(types: &naga::UniqueArena<naga::Type>, info: &naga::valid::FunctionInfo, fun: &Function) -> Vec<TypeInner> {
    fun.expressions.iter().map(|(h, _)| info[h].ty.inner_with(types).clone()).collect()
}

/// The operation warning `code` is about.
fn operation(code: Code, e: &Expression, arena: &naga::Arena<Expression>) -> bool {
    match (code, e) {
        (Code::HazardDivision, Expression::Binary { op: B::Divide, .. }) => true,
        (Code::HazardNegativeRemainder, Expression::Binary { op: B::Modulo, .. }) => true,
        (Code::HazardShift, Expression::Binary { op: B::ShiftLeft | B::ShiftRight, .. }) => true,
        (Code::HazardSinHash, Expression::Math { fun: M::Fract, arg, .. }) => hash_parts(arena, *arg).is_some(),
        (_, Expression::Math { fun, .. }) => matches!(
            (code, fun),
            (Code::HazardAsin, M::Asin | M::Acos)
                | (Code::HazardSqrt, M::Sqrt)
                | (Code::HazardLog, M::Log | M::Log2)
                | (Code::HazardPow, M::Pow)
                | (Code::HazardNormalize, M::Normalize)
                | (Code::HazardInverseSqrt, M::InverseSqrt)
                | (Code::HazardTrig, M::Sin | M::Cos | M::Tan)
                | (Code::HazardAtan2, M::Atan2)
        ),
        _ => false,
    }
}

/// A loop counter's integer step (`i + 1`), which W0719 points at.
fn counter_step(e: &Expression, ty: Option<&TypeInner>) -> bool {
    let int = matches!(ty, Some(TypeInner::Scalar(s)) if matches!(s.kind, ScalarKind::Sint | ScalarKind::Uint));
    int && matches!(e, Expression::Binary { op: B::Add | B::Subtract | B::Multiply, .. })
}

/// The `sin(x)` and `K` of a hash's `sin(x) * K`.
fn hash_parts(arena: &naga::Arena<Expression>, product: Handle<Expression>) -> Option<(Handle<Expression>, Handle<Expression>)> {
    let Expression::Binary { op: B::Multiply, left, right } = arena[product] else { return None };
    let trig = |h: Handle<Expression>| matches!(arena[h], Expression::Math { fun: M::Sin | M::Cos, .. });
    match (trig(left), trig(right)) {
        (true, _) => Some((left, right)),
        (_, true) => Some((right, left)),
        _ => None,
    }
}

/// Rewrites one function's blocks.
struct Ctx<'a> {
    /// The operations of this function to test, with their bits.
    here: &'a [(Handle<Expression>, u32)],
    /// Those of them whose operands are continuous over a primitive.
    continuous: &'a [Handle<Expression>],
    /// Resolved types of the function's original expressions.
    types: &'a [TypeInner],
    /// Which of them are the same in every invocation.
    uniform: &'a [bool],
    /// The warning code of every bit.
    codes: &'a [Code],
    reached: Handle<naga::GlobalVariable>,
    held: Handle<naga::GlobalVariable>,
    crossed: Handle<naga::GlobalVariable>,
    /// The iteration counter of every loop bit.
    loops: &'a [(u32, Handle<naga::GlobalVariable>)],
}

impl Ctx<'_> {
    /// `block` rewritten; `flow`: whether it runs in uniform flow of a fragment stage, where
    /// zeros between pixels are tested (`None`: not tested in this function).
    fn block(&self, fun: &mut Function, block: Block, mut flow: Option<bool>) -> Block {
        let mut out = Block::with_capacity(block.len());
        for (stmt, span) in block.span_into_iter() {
            let (inside, after) = match flow {
                Some(f) => {
                    let (i, a) = crossing::flow_of(&stmt, f, self.uniform);
                    (Some(i), Some(a))
                }
                None => (None, None),
            };
            let stmt = match stmt {
                Statement::Loop { body, continuing, break_if } => {
                    let bit = self.loop_bit(&continuing);
                    let mut body = self.block(fun, body, inside);
                    let continuing = self.block(fun, continuing, inside);
                    if let Some((bit, counter)) = bit {
                        let mut b = Builder::new(fun);
                        b.mark(self.reached, bit);
                        b.set_u32(counter, 0);
                        for (s, sp) in b.finish().span_into_iter() {
                            out.push(s, sp);
                        }
                        body = self.cap(fun, body, bit, counter);
                    }
                    Statement::Loop { body, continuing, break_if }
                }
                other => map_blocks(other, &mut |b| self.block(fun, b, inside)),
            };
            let emitted: Vec<Handle<Expression>> = if let Statement::Emit(r) = &stmt { r.clone().collect() } else { Vec::new() };
            out.push(stmt, span);
            for h in emitted {
                for &(_, bit) in self.here.iter().filter(|(x, bit)| *x == h && self.codes[*bit as usize] != Code::HazardCounterOverflow) {
                    let mut b = Builder::new(fun);
                    b.mark(self.reached, bit);
                    let condition = self.condition(&mut b, h, bit);
                    let mut accept = Builder::new(b.fun);
                    accept.mark(self.held, bit);
                    let accept = accept.finish();
                    b.stmt(Statement::If { condition, accept, reject: Block::new() });
                    if flow == Some(true) {
                        self.between(&mut b, h, bit);
                    }
                    for (s, sp) in b.finish().span_into_iter() {
                        out.push(s, sp);
                    }
                }
            }
            flow = after;
        }
        out
    }

    /// `if (the operands of h pass through zero between pixels) { crossed |= bit; }`.
    fn between(&self, b: &mut Builder<'_>, h: Handle<Expression>, bit: u32) {
        let code = self.codes[bit as usize];
        if !self.continuous.contains(&h) {
            return;
        }
        let operands = crossing::operands(code, &b.fun.expressions[h]);
        let Some(condition) = crossing::between_pixels(b, code, &operands, &|x| self.types.get(x.index())) else { return };
        let mut accept = Builder::new(b.fun);
        accept.mark(self.crossed, bit);
        let accept = accept.finish();
        b.stmt(Statement::If { condition, accept, reject: Block::new() });
    }

    /// The bit and counter of a loop whose `continuing` steps a counter warned about.
    fn loop_bit(&self, continuing: &Block) -> Option<(u32, Handle<naga::GlobalVariable>)> {
        fn emits(block: &Block, h: Handle<Expression>) -> bool {
            block.iter().any(|s| match s {
                Statement::Emit(r) => r.clone().any(|x| x == h),
                Statement::Block(b) => emits(b, h),
                Statement::If { accept, reject, .. } => emits(accept, h) || emits(reject, h),
                _ => false,
            })
        }
        let (_, bit) =
            self.here.iter().find(|(h, bit)| self.codes[*bit as usize] == Code::HazardCounterOverflow && emits(continuing, *h))?;
        self.loops.iter().find(|(b, _)| b == bit).copied()
    }

    /// `counter += 1; if (counter > LOOP_CAP) { held |= bit; break; }` before `body`.
    fn cap(&self, fun: &mut Function, body: Block, bit: u32, counter: Handle<naga::GlobalVariable>) -> Block {
        let mut b = Builder::new(fun);
        let ptr = b.add(Expression::GlobalVariable(counter));
        let now = b.add(Expression::Load { pointer: ptr });
        let one = b.add(Expression::Literal(Literal::U32(1)));
        let next = b.add(Expression::Binary { op: B::Add, left: now, right: one });
        b.stmt(Statement::Store { pointer: ptr, value: next });
        let cap = b.add(Expression::Literal(Literal::U32(LOOP_CAP)));
        let over = b.add(Expression::Binary { op: B::Greater, left: next, right: cap });
        let mut accept = Builder::new(b.fun);
        accept.mark(self.held, bit);
        accept.stmt(Statement::Break);
        let accept = accept.finish();
        b.stmt(Statement::If { condition: over, accept, reject: Block::new() });
        let mut out = b.finish();
        for (s, sp) in body.span_into_iter() {
            out.push(s, sp);
        }
        out
    }

    /// The scalar `bool` that says the condition of `bit`'s warning holds at `h`.
    fn condition(&self, b: &mut Builder<'_>, h: Handle<Expression>, bit: u32) -> Handle<Expression> {
        let shape = |x: Handle<Expression>| Shape::of(self.types.get(x.index()));
        let e = b.fun.expressions[h].clone();
        match (self.codes[bit as usize], e) {
            (Code::HazardDivision, Expression::Binary { right, .. }) => {
                let s = shape(right);
                match s.kind {
                    ScalarKind::Float => {
                        let a = b.math(M::Abs, right, None);
                        let min = b.splat_f32(f32::MIN_POSITIVE, s);
                        b.any_cmp(B::Less, a, min, s)
                    }
                    _ => {
                        let zero = b.zero(s);
                        b.any_cmp(B::Equal, right, zero, s)
                    }
                }
            }
            (Code::HazardNegativeRemainder, Expression::Binary { left, right, .. }) => {
                let l = b.any_sign(left, shape(left));
                let r = b.any_sign(right, shape(right));
                b.add(Expression::Binary { op: B::LogicalOr, left: l, right: r })
            }
            (Code::HazardShift, Expression::Binary { right, .. }) => {
                let s = shape(right);
                let limit = b.splat(literal(s.kind, 32.0), s);
                b.any_cmp(B::GreaterEqual, right, limit, s)
            }
            (Code::HazardSinHash, Expression::Math { arg, .. }) => self.hash_condition(b, h, arg),
            (code, Expression::Math { arg, arg1, .. }) => {
                let s = shape(arg);
                match code {
                    Code::HazardAsin => {
                        let a = b.math(M::Abs, arg, None);
                        let one = b.splat_f32(1.0, s);
                        b.any_cmp(B::Greater, a, one, s)
                    }
                    Code::HazardSqrt => {
                        let zero = b.zero(s);
                        b.any_cmp(B::Less, arg, zero, s)
                    }
                    Code::HazardLog | Code::HazardInverseSqrt => {
                        let zero = b.zero(s);
                        b.any_cmp(B::LessEqual, arg, zero, s)
                    }
                    Code::HazardNormalize => {
                        let d = b.math(M::Dot, arg, Some(arg));
                        let min = b.add(Expression::Literal(Literal::F32(f32::MIN_POSITIVE)));
                        b.add(Expression::Binary { op: B::Less, left: d, right: min })
                    }
                    Code::HazardTrig => {
                        let a = b.math(M::Abs, arg, None);
                        let limit = b.splat_f32(crate::check::hazards::ops::TRIG_LIMIT as f32, s);
                        b.any_cmp(B::Greater, a, limit, s)
                    }
                    Code::HazardPow => {
                        let y = arg1.unwrap_or(arg);
                        let zero = b.zero(s);
                        let negative = b.cmp(B::Less, arg, zero);
                        let at_zero = b.cmp(B::Equal, arg, zero);
                        let y_zero = b.zero(shape(y));
                        let power = b.cmp(B::LessEqual, y, y_zero);
                        let both = b.add(Expression::Binary { op: B::And, left: at_zero, right: power });
                        let bad = b.add(Expression::Binary { op: B::InclusiveOr, left: negative, right: both });
                        b.any(bad, s)
                    }
                    Code::HazardAtan2 => {
                        let x = arg1.unwrap_or(arg);
                        let zero = b.zero(s);
                        let y0 = b.cmp(B::Equal, arg, zero);
                        let x0 = b.cmp(B::Equal, x, zero);
                        let both = b.add(Expression::Binary { op: B::And, left: y0, right: x0 });
                        b.any(both, s)
                    }
                    _ => b.add(Expression::Literal(Literal::Bool(false))),
                }
            }
            _ => b.add(Expression::Literal(Literal::Bool(false))),
        }
    }

    /// A hash `fract(sin(x) * K)` at `h` moved by more than a tenth when its `sin` is moved by
    /// GLSL's allowed error, either way.
    fn hash_condition(&self, b: &mut Builder<'_>, h: Handle<Expression>, product: Handle<Expression>) -> Handle<Expression> {
        let Some((sin, k)) = hash_parts(&b.fun.expressions, product) else { return b.add(Expression::Literal(Literal::Bool(false))) };
        let (ss, rs) = (Shape::of(self.types.get(sin.index())), Shape::of(self.types.get(h.index())));
        let mut any = None;
        for slack in [SIN_SLACK, -SIN_SLACK] {
            let e = b.splat_f32(slack, ss);
            let moved = b.add(Expression::Binary { op: B::Add, left: sin, right: e });
            let p = b.add(Expression::Binary { op: B::Multiply, left: moved, right: k });
            let f = b.math(M::Fract, p, None);
            let d = b.add(Expression::Binary { op: B::Subtract, left: f, right: h });
            let d = b.math(M::Abs, d, None);
            let one = b.splat_f32(1.0, rs);
            let around = b.add(Expression::Binary { op: B::Subtract, left: one, right: d });
            let dist = b.math(M::Min, d, Some(around));
            let tenth = b.splat_f32(0.1, rs);
            let far = b.any_cmp(B::Greater, dist, tenth, rs);
            any = Some(match any {
                Some(a) => b.add(Expression::Binary { op: B::LogicalOr, left: a, right: far }),
                None => far,
            });
        }
        any.unwrap_or_else(|| b.add(Expression::Literal(Literal::Bool(false))))
    }
}

/// At an exit: one invocation, and per bit whether it reached the site, whether the
/// condition held there, and whether its operands passed through zero between pixels.
fn push_counts(
    fun: &mut Function,
    out: &mut Block,
    masks: [Handle<naga::GlobalVariable>; 3],
    counts: Handle<naga::GlobalVariable>,
    base: u32,
    bits: u32,
) {
    let mut b = Builder::new(fun);
    let buffer = b.add(Expression::GlobalVariable(counts));
    let add = |b: &mut Builder<'_>, slot: u32, value: Handle<Expression>| {
        let index = b.add(Expression::Literal(Literal::U32(base + slot)));
        let pointer = b.add(Expression::Access { base: buffer, index });
        b.stmt(Statement::Atomic { pointer, fun: naga::AtomicFunction::Add, value, result: None });
    };
    let one = b.add(Expression::Literal(Literal::U32(1)));
    add(&mut b, 0, one);
    for (k, j) in (0..bits).flat_map(|k| (0..3).map(move |j| (k, j))) {
        let mask = masks[j as usize];
        let ptr = b.add(Expression::GlobalVariable(mask));
        let now = b.add(Expression::Load { pointer: ptr });
        let shift = b.add(Expression::Literal(Literal::U32(k)));
        let moved = b.add(Expression::Binary { op: B::ShiftRight, left: now, right: shift });
        let one = b.add(Expression::Literal(Literal::U32(1)));
        let value = b.add(Expression::Binary { op: B::And, left: moved, right: one });
        add(&mut b, 1 + 3 * k + j, value);
    }
    for (s, sp) in b.finish().span_into_iter() {
        out.push(s, sp);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use naga::Span;

    #[test]
    fn spans_match_best_when_equal_then_by_shared_share() {
        assert_eq!(overlap(&(10..20), &(10..20)), 2.0);
        assert!((overlap(&(10..20), &(15..25)) - 5.0 / 15.0).abs() < 1e-12);
        assert_eq!(overlap(&(10..20), &(20..30)), 0.0, "touching is not overlapping");
        assert!(overlap(&(10..20), &(12..18)) > overlap(&(10..20), &(0..40)));
    }

    #[test]
    fn counts_split_into_invocations_reached_held_and_between_per_bit() {
        let sites =
            Sites { bits: vec![3, 0], crowded: Vec::new(), regions: vec![(StageKind::Vertex, 0), (StageKind::Fragment, 7)], slots: 14 };
        let counts = sites.read(&[36, 36, 0, 0, 9, 9, 0, 100, 0, 0, 0, 100, 7, 40]);
        let counted = |stage, invocations, reached, held, between| Counted { stage, invocations, reached, held, between };
        assert_eq!(counts[0], counted(StageKind::Vertex, 36, vec![36, 9], vec![0, 9], vec![0, 0]));
        assert_eq!(counts[1], counted(StageKind::Fragment, 100, vec![0, 100], vec![0, 7], vec![0, 40]));
    }

    #[test]
    fn each_warning_matches_its_own_operation() {
        let mut arena = naga::Arena::new();
        let x = arena.append(Expression::Literal(Literal::F32(2.0)), Span::UNDEFINED);
        let sin = arena.append(Expression::Math { fun: M::Sin, arg: x, arg1: None, arg2: None, arg3: None }, Span::UNDEFINED);
        let product = arena.append(Expression::Binary { op: B::Multiply, left: x, right: sin }, Span::UNDEFINED);
        let fract = Expression::Math { fun: M::Fract, arg: product, arg1: None, arg2: None, arg3: None };
        assert!(operation(Code::HazardSinHash, &fract, &arena), "fract(K * sin(x)) is a hash");
        let plain = Expression::Math { fun: M::Fract, arg: x, arg1: None, arg2: None, arg3: None };
        assert!(!operation(Code::HazardSinHash, &plain, &arena));
        assert!(operation(Code::HazardTrig, &arena[sin], &arena));
        assert!(!operation(Code::HazardAsin, &arena[sin], &arena));
        let divide = Expression::Binary { op: B::Divide, left: x, right: x };
        assert!(operation(Code::HazardDivision, &divide, &arena) && !operation(Code::HazardNegativeRemainder, &divide, &arena));
        let int = TypeInner::Scalar(naga::Scalar::I32);
        let step = Expression::Binary { op: B::Add, left: x, right: x };
        assert!(counter_step(&step, Some(&int)) && !counter_step(&step, Some(&TypeInner::Scalar(naga::Scalar::F32))));
    }
}
