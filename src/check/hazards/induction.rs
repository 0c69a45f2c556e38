//! Induction variables: locals a loop steps by a constant at most once per iteration
//! (`for (int i = 0; i < 8; ++i, t += step)`: `i` and `t`). Intervals alone lose how they
//! move together, so widening sends an accumulator such as `t` to infinity although the
//! loop's counter stops after 8 iterations. After the fixpoint, the number of iterations
//! the loop's head can have seen is read from any induction variable the exit test bounds,
//! and every induction variable is cut back to its entry value plus that many steps.
//! A counter's update is also checked against its integer type (W0719).

use naga::{BinaryOperator, Block, Expression, Function, Handle, LocalVariable, Statement};

use super::interval::Iv;
use super::value::{Num, Val};
use super::walk::{Analyzer, Call, State};
use super::Hazard;

/// A local stepped by a constant (`x = x + step`, `x = x - step`, `x += step`).
#[derive(Debug, Clone, Copy)]
struct Induction {
    local: Handle<LocalVariable>,
    /// The expression of the step (a literal or a constant; negated for `-`).
    step: Handle<Expression>,
    subtract: bool,
    /// Stepped on every iteration the loop completes (in `continuing`, or in the body
    /// outside any `if`/`switch` with no `continue` in the body), not just at most once.
    every: bool,
}

/// The induction variables of the loop `body` + `continuing` of `fun`: each local the loop
/// stores whole exactly once, outside any nested loop, as itself plus or minus a literal or
/// constant, and reaches through no other pointer.
fn find(fun: &Function, body: &Block, continuing: &Block) -> Vec<Induction> {
    let mut stores: Vec<Store> = Vec::new();
    let mut other: Vec<Handle<Expression>> = Vec::new();
    let mut continues = false;
    collect(fun, body, Where::Top, &mut stores, &mut other, &mut continues);
    let in_body = stores.len();
    let mut ignored = false;
    collect(fun, continuing, Where::Top, &mut stores, &mut other, &mut ignored);
    let mut out = Vec::new();
    for (i, &Store { pointer, value, at }) in stores.iter().enumerate() {
        let Expression::LocalVariable(local) = fun.expressions[pointer] else { continue };
        let same = |p: &Handle<Expression>| root_local(fun, *p) == Some(local);
        if at == Where::InLoop || stores.iter().filter(|s| same(&s.pointer)).count() != 1 || other.iter().any(same) {
            continue;
        }
        let every = at == Where::Top && (i >= in_body || !continues);
        let Expression::Binary { op, left, right } = fun.expressions[value] else { continue };
        let loads_self = |h: Handle<Expression>| matches!(fun.expressions[h], Expression::Load { pointer } if matches!(fun.expressions[pointer], Expression::LocalVariable(l) if l == local));
        let constant = |h: Handle<Expression>| matches!(fun.expressions[h], Expression::Literal(_) | Expression::Constant(_));
        let found = match op {
            BinaryOperator::Add if loads_self(left) && constant(right) => Some((right, false)),
            BinaryOperator::Add if loads_self(right) && constant(left) => Some((left, false)),
            BinaryOperator::Subtract if loads_self(left) && constant(right) => Some((right, true)),
            _ => None,
        };
        if let Some((step, subtract)) = found {
            out.push(Induction { local, step, subtract, every });
        }
    }
    out
}

/// One `Store` of the loop and where it stands.
#[derive(Debug, Clone, Copy)]
struct Store {
    pointer: Handle<Expression>,
    value: Handle<Expression>,
    at: Where,
}

/// Where a statement stands in the loop.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Where {
    /// Runs whenever the block it is in runs to its end.
    Top,
    /// Inside an `if` or `switch`.
    Branch,
    /// Inside a nested loop (may run many times an iteration).
    InLoop,
}

/// Every `Store` in `block`, every other pointer the block hands on (call arguments,
/// atomics, stores into part of a variable), and whether a `continue` of this loop is in it.
fn collect(fun: &Function, block: &Block, at: Where, stores: &mut Vec<Store>, other: &mut Vec<Handle<Expression>>, continues: &mut bool) {
    let branch = if at == Where::Top { Where::Branch } else { at };
    for s in block.iter() {
        match s {
            Statement::Store { pointer, value } => {
                if matches!(fun.expressions[*pointer], Expression::LocalVariable(_)) {
                    stores.push(Store { pointer: *pointer, value: *value, at });
                } else {
                    other.push(*pointer);
                }
            }
            Statement::Call { arguments, .. } => other.extend(arguments.iter().copied()),
            Statement::Continue if at != Where::InLoop => *continues = true,
            Statement::Block(b) => collect(fun, b, at, stores, other, continues),
            Statement::If { accept, reject, .. } => {
                collect(fun, accept, branch, stores, other, continues);
                collect(fun, reject, branch, stores, other, continues);
            }
            Statement::Switch { cases, .. } => {
                // `continue` in a switch still continues this loop.
                cases.iter().for_each(|case| collect(fun, &case.body, branch, stores, other, continues))
            }
            Statement::Loop { body, continuing, .. } => {
                collect(fun, body, Where::InLoop, stores, other, continues);
                collect(fun, continuing, Where::InLoop, stores, other, continues);
            }
            Statement::Atomic { pointer, .. } => other.push(*pointer),
            _ => {}
        }
    }
}

/// The local a pointer expression leads into, through any accesses.
fn root_local(fun: &Function, mut h: Handle<Expression>) -> Option<Handle<LocalVariable>> {
    loop {
        match fun.expressions[h] {
            Expression::LocalVariable(l) => return Some(l),
            Expression::Access { base, .. } | Expression::AccessIndex { base, .. } => h = base,
            _ => return None,
        }
    }
}

impl Analyzer<'_> {
    /// `head` (the loop's fixpoint) with every induction variable cut back to its value in
    /// `entry` plus as many steps as the head can have seen (read from the induction
    /// variables the exit test bounds); `head` unchanged when none is bounded.
    pub(super) fn bound_inductions(&mut self, c: &mut Call<'_>, entry: &State, mut head: State, body: &Block, continuing: &Block) -> State {
        let inductions = find(c.fun, body, continuing);
        if inductions.is_empty() {
            return head;
        }
        // (local, entry value, head value, step, every) of each scalar induction variable.
        let mut known = Vec::new();
        for ind in &inductions {
            let key = (c.depth, ind.local);
            let (Some(Val::Num(start)), Some(Val::Num(now))) = (entry.locals.get(&key).map(|v| &**v), head.locals.get(&key).map(|v| &**v))
            else {
                continue;
            };
            let Some(step) = self.value(c, &head, ind.step).num().map(Num::iv) else { continue };
            let step = if ind.subtract { Iv::new(-step.hi, -step.lo) } else { step };
            if start.c.len() != 1 || now.c.len() != 1 || !step.is_finite() || (step.lo < 0.0 && step.hi > 0.0) || step.mag() == 0.0 {
                continue;
            }
            known.push((key, start.clone(), now.clone(), step, ind.every));
        }
        // Iterations the head has seen: bounded by any variable that moves one way from
        // its entry value and that the exit test keeps finite on that side.
        let iterations = known
            .iter()
            .filter_map(|(_, start, now, step, _)| {
                let (s, n) = (start.c[0], now.c[0]);
                let k = if step.lo > 0.0 { (n.hi - s.lo) / step.lo } else { (s.hi - n.lo) / -step.hi };
                k.is_finite().then_some(k.max(0.0))
            })
            .fold(f64::INFINITY, f64::min);
        if !iterations.is_finite() {
            return head;
        }
        // The head follows at least one completed iteration (the first runs on its own).
        for (key, start, now, step, every) in known {
            let travelled = Iv::new(if every { 1.0_f64.min(iterations) } else { 0.0 }, iterations).mul(step);
            let bound = start.c[0].add(travelled);
            let cut = now.c[0].meet(bound);
            if cut != now.c[0] {
                head.locals.insert(key, std::rc::Rc::new(Val::Num(Num::from_comps(vec![cut], 1, now.kind, now.known && start.known))));
            }
        }
        head
    }
}

impl Analyzer<'_> {
    /// A loop counter updated in `continuing` must stay inside its integer type.
    pub(super) fn check_counter(&mut self, c: &mut Call<'_>, state: &State, value: Handle<Expression>, span: naga::Span) {
        let Expression::Binary { op, left, right } = c.fun.expressions[value] else { return };
        if !matches!(op, naga::BinaryOperator::Add | naga::BinaryOperator::Subtract | naga::BinaryOperator::Multiply) {
            return;
        }
        let (Some(a), Some(b)) = (self.value(c, state, left).num().cloned(), self.value(c, state, right).num().cloned()) else {
            return;
        };
        let (lo, hi) = match a.kind {
            naga::ScalarKind::Sint => (f64::from(i32::MIN), f64::from(i32::MAX)),
            naga::ScalarKind::Uint => (0.0, f64::from(u32::MAX)),
            _ => return,
        };
        // Integer steps are exact (f64 holds every 32-bit sum and product): no float
        // rounding slack, which near 2^31 is wider than the step itself.
        let (x, y) = (a.iv(), b.iv());
        let raw = match op {
            naga::BinaryOperator::Add => Iv::new(x.lo + y.lo, x.hi + y.hi),
            naga::BinaryOperator::Subtract => Iv::new(x.lo - y.hi, x.hi - y.lo),
            _ => {
                let p = [x.lo * y.lo, x.lo * y.hi, x.hi * y.lo, x.hi * y.hi].map(|v| if v.is_nan() { 0.0 } else { v });
                Iv::new(p.iter().copied().fold(f64::INFINITY, f64::min), p.iter().copied().fold(f64::NEG_INFINITY, f64::max))
            }
        };
        // A step can overflow only the way it moves: `i + 1` past the top, never below the
        // bottom (the counter's own lower bound may be lost to widening, not to the step).
        let (step_up, step_down) = match op {
            naga::BinaryOperator::Add => (b.iv().hi > 0.0, b.iv().lo < 0.0),
            naga::BinaryOperator::Subtract => (b.iv().lo < 0.0, b.iv().hi > 0.0),
            _ => (true, true),
        };
        if a.known && b.known && ((step_up && raw.hi > hi) || (step_down && raw.lo < lo)) {
            // A witness: this loop ran past the unrolling limit at fixed inputs on a sure
            // path, and its counter is still unbounded.
            let certain = self.runaway.contains(&c.loop_id);
            self.report(Hazard { certain, ..Hazard::counter(span, a.iv(), raw, a.kind) }, state.sure || certain);
        }
    }
}
