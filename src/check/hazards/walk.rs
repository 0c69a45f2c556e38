//! Abstract interpretation of a naga function: statements in order, both branches of every
//! `if` (refined by the condition), loops iterated to a fixpoint with widening, calls
//! inlined. Expressions are evaluated in [`super::eval`]; hazards are recorded there.
//!
//! A loop's first iteration runs on its own; the later ones are iterated quietly until
//! their state stops changing (bounds that keep
//! growing jump to infinity after two rounds; the loop's exit test then cuts them back,
//! and [`super::induction`] the variables stepped with the counter), then run once more
//! with reporting on, so every hazard is judged on the final state.

use std::collections::HashMap;
use std::hash::{Hash, Hasher};
use std::rc::Rc;

use naga::{Block, Expression, Function, Handle, LocalVariable, Module, Statement};

use super::facts::Facts;
use super::interval::Iv;
use super::value::Val;
use super::Hazard;

/// Where a pointer points.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum Root {
    /// A local variable of the call frame at this depth.
    Local(usize, Handle<LocalVariable>),
    Global(Handle<naga::GlobalVariable>),
}

/// One step into an aggregate, vector or matrix.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Step {
    Index(u32),
    Dynamic,
}

#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Place {
    pub root: Root,
    pub path: Vec<Step>,
}

/// The value of an expression: a value or a pointer.
#[derive(Debug, Clone)]
pub enum Ev {
    V(Val),
    P(Place),
}

/// A refinement learnt from a condition: the value with this key lies in `iv` and
/// `|value| >= gap`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Refined {
    pub iv: Iv,
    pub gap: f64,
}

/// The maps a [`State`] holds: keyed by handles and hashes, so a fast hasher.
pub type Map<K, V> = naga::FastHashMap<K, V>;

/// Everything that flows along the control flow.
///
/// Variables hold shared values: a state is copied at every branch and loop round, and
/// most variables (the fold's arrays of per-vertex structs among them) are not written
/// between two copies, so a copy shares them and a join of two states skips the values
/// both still share.
#[derive(Debug, Clone, PartialEq)]
pub struct State {
    pub locals: Map<(usize, Handle<LocalVariable>), Rc<Val>>,
    pub globals: Map<Handle<naga::GlobalVariable>, Rc<Val>>,
    pub versions: Map<Root, u64>,
    /// The key of the value last stored whole into a variable: loading it back gives the
    /// same key, so `float len = length(v); if (len > 0.0) normalize(v)` is guarded.
    pub stored: Map<Root, u64>,
    pub refined: Map<u64, Refined>,
    /// False on paths that cannot run (after `break`, `return`, `discard`).
    pub live: bool,
    /// Witness runs: every execution that reaches the function's entry reaches this point
    /// (no undecided branch or exit lies between them).
    pub sure: bool,
}

impl State {
    /// Entries held (what a join walks).
    pub fn size(&self) -> u64 {
        (self.locals.len() + self.globals.len() + self.versions.len() + self.stored.len() + self.refined.len()) as u64
    }

    pub fn dead() -> State {
        State {
            locals: Map::default(),
            globals: Map::default(),
            versions: Map::default(),
            stored: Map::default(),
            refined: Map::default(),
            live: false,
            sure: false,
        }
    }

    /// The state on a path that may not run.
    pub(super) fn unsure(mut self) -> State {
        self.sure = false;
        self
    }

    /// Both paths: values joined, refinements kept where both agree on a key.
    pub fn join(&self, o: &State, fresh: &mut u64) -> State {
        if !self.live {
            return o.clone();
        }
        if !o.live {
            return self.clone();
        }
        let mut out = self.clone();
        out.sure = self.sure && o.sure;
        join_values(&mut out.locals, &o.locals);
        join_values(&mut out.globals, &o.globals);
        for (k, v) in &o.versions {
            if out.versions.get(k) != Some(v) {
                *fresh += 1;
                out.versions.insert(k.clone(), *fresh);
            }
        }
        out.stored.retain(|k, v| o.stored.get(k) == Some(v));
        out.refined.retain(|k, r| match o.refined.get(k) {
            Some(q) => {
                *r = Refined { iv: r.iv.join(q.iv), gap: r.gap.min(q.gap) };
                true
            }
            None => false,
        });
        out
    }

    fn widen(&self, old: &State) -> State {
        let mut out = self.clone();
        widen_values(&mut out.locals, &old.locals);
        widen_values(&mut out.globals, &old.globals);
        out
    }
}

/// `o`'s values joined into `out`'s (a value both share is its own join).
fn join_values<K: Hash + Eq + Copy>(out: &mut Map<K, Rc<Val>>, o: &Map<K, Rc<Val>>) {
    for (k, v) in o {
        match out.get_mut(k) {
            Some(a) if Rc::ptr_eq(a, v) => {}
            Some(a) => *a = Rc::new(a.join(v)),
            None => {
                out.insert(*k, v.clone());
            }
        }
    }
}

/// `out`'s values widened against `old`'s (a value both share is unchanged).
fn widen_values<K: Hash + Eq>(out: &mut Map<K, Rc<Val>>, old: &Map<K, Rc<Val>>) {
    for (k, v) in out.iter_mut() {
        if let Some(o) = old.get(k).filter(|o| !Rc::ptr_eq(o, v)) {
            *v = Rc::new(v.widen(o));
        }
    }
}

/// Where control goes at the end of a construct.
#[derive(Default)]
pub struct Exits {
    pub breaks: Vec<State>,
    pub continues: Vec<State>,
}

/// One function invocation.
pub struct Call<'f> {
    pub fun: &'f Function,
    pub info: &'f naga::valid::FunctionInfo,
    pub depth: usize,
    pub args: Vec<(Ev, Option<u64>)>,
    pub values: Vec<Option<Ev>>,
    pub keys: Vec<Option<u64>>,
    pub returned: Vec<(State, Option<Val>)>,
    /// Stores in a `continuing` block are loop-counter updates.
    pub in_continuing: bool,
    /// The innermost loop whose `continuing` block runs (its address).
    pub loop_id: usize,
    /// Expressions computed only for an arm of a `?:` (`Select`): GLSL's condition picks
    /// the arm, so a value undefined in the other one is discarded (`len > 0.0 ? atan(y,
    /// x) : 0.0`).
    pub select_arms: Vec<bool>,
}

/// Which expressions of `fun` lie in the operand tree of a `Select`'s arms, or of the
/// right operand of `&&` and `||`: GLSL evaluates them only when the condition (the left
/// operand) says so, naga's IR always.
fn select_arms(fun: &Function) -> Vec<bool> {
    let mut arms = vec![false; fun.expressions.len()];
    let mut stack: Vec<Handle<naga::Expression>> = Vec::new();
    for (_, e) in fun.expressions.iter() {
        match e {
            naga::Expression::Select { accept, reject, .. } => stack.extend([*accept, *reject]),
            naga::Expression::Binary { op: naga::BinaryOperator::LogicalAnd | naga::BinaryOperator::LogicalOr, right, .. } => {
                stack.push(*right)
            }
            _ => {}
        }
    }
    while let Some(h) = stack.pop() {
        if std::mem::replace(&mut arms[h.index()], true) {
            continue;
        }
        match &fun.expressions[h] {
            naga::Expression::Math { arg, arg1, arg2, arg3, .. } => stack.extend([Some(*arg), *arg1, *arg2, *arg3].into_iter().flatten()),
            naga::Expression::Binary { left, right, .. } => stack.extend([*left, *right]),
            naga::Expression::Unary { expr, .. } | naga::Expression::As { expr, .. } => stack.push(*expr),
            naga::Expression::AccessIndex { base, .. } => stack.push(*base),
            naga::Expression::Swizzle { vector, .. } => stack.push(*vector),
            _ => {}
        }
    }
    arms
}

/// The analysis of one stage.
pub struct Analyzer<'a> {
    pub module: &'a Module,
    pub info: &'a naga::valid::ModuleInfo,
    pub facts: &'a Facts,
    pub stage: naga::ShaderStage,
    /// The stage text naga parsed (spans index it).
    pub text: &'a str,
    pub hazards: Vec<Hazard>,
    /// > 0 while a loop is iterated to its fixpoint: no reports.
    pub quiet: u32,
    pub fresh: u64,
    /// Location outputs of the entry point (joined over its returns).
    pub outputs: HashMap<u32, Val>,
    /// Each global's value before the stage writes it, made once: a uniform block of
    /// thousands of members is read member by member, not rebuilt at each read.
    initials: std::cell::RefCell<HashMap<Handle<naga::GlobalVariable>, Rc<Val>>>,
    /// Work done (statements walked, state entries joined) and the most allowed
    /// ([`WORK_LIMIT`]): nested loops iterate to a fixpoint round after round and calls are
    /// walked at every call site, so the work can grow exponentially with nesting. Past the
    /// limit the rest of the stage is taken as unreachable (no warning, false or true) and
    /// `stopped` is set (note N0701).
    pub work: u64,
    /// Work after which the analysis stops ([`WORK_LIMIT`] unless the caller sets less).
    pub work_limit: u64,
    pub stopped: bool,
    /// A witness run ([`super::witness`]): inputs at points, loops run iteration by
    /// iteration, and only hazards that surely happen reported.
    pub witness: bool,
    /// Exits taken on a live path so far: a branch that may take one leaves the code
    /// after it unsure.
    pub exits: ExitCount,
    /// The loops ([`Call::loop_id`]) a witness run saw iterate past [`UNROLL_LIMIT`] on a
    /// sure path, while it iterates the rest of them to a fixpoint.
    pub runaway: Vec<usize>,
}

/// Exits taken on live paths, by kind.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ExitCount {
    /// `return` and `discard`.
    pub leaves: u64,
    pub breaks: u64,
    pub continues: u64,
}

/// Work units one stage's analysis may take: real shaders take a few thousand to a few
/// hundred thousand; 8 nested loops about 2 million (0.4 s).
pub const WORK_LIMIT: u64 = 4_000_000;

/// Iterations a witness run follows one by one before it iterates the rest of a loop to a
/// fixpoint.
pub const UNROLL_LIMIT: usize = 64;

const MAX_ROUNDS: usize = 12;
const MAX_CALL_DEPTH: usize = 24;

impl<'a> Analyzer<'a> {
    pub fn new(module: &'a Module, info: &'a naga::valid::ModuleInfo, facts: &'a Facts, stage: naga::ShaderStage, text: &'a str) -> Self {
        Analyzer {
            module,
            info,
            facts,
            stage,
            text,
            hazards: Vec::new(),
            quiet: 0,
            fresh: 0,
            outputs: HashMap::new(),
            initials: Default::default(),
            work: 0,
            work_limit: WORK_LIMIT,
            stopped: false,
            witness: false,
            exits: ExitCount::default(),
            runaway: Vec::new(),
        }
    }

    /// Runs the entry point of the stage.
    pub fn run_entry(&mut self) {
        let Some((index, ep)) = self.module.entry_points.iter().enumerate().find(|(_, e)| e.stage == self.stage) else {
            return;
        };
        let info = self.info.get_entry_point(index);
        let args = ep.function.arguments.iter().map(|a| (Ev::V(self.argument(a)), None)).collect();
        let mut state = State::dead();
        state.live = true;
        state.sure = true;
        let returned = self.call(&ep.function, info, args, 0, state);
        if let (Some(result), Some(v)) = (&ep.function.result, returned.1) {
            self.collect_outputs(result, v);
        }
    }

    fn collect_outputs(&mut self, result: &naga::FunctionResult, v: Val) {
        match (&result.binding, &self.module.types[result.ty].inner, v) {
            (Some(naga::Binding::Location { location, .. }), _, v) => {
                self.outputs.insert(*location, v);
            }
            (None, naga::TypeInner::Struct { members, .. }, Val::Agg(items)) => {
                for (m, item) in members.iter().zip(items) {
                    if let Some(naga::Binding::Location { location, .. }) = m.binding {
                        self.outputs.insert(location, item);
                    }
                }
            }
            _ => {}
        }
    }

    /// Runs `fun` from `state`; the state after it and its return value.
    pub fn call(
        &mut self,
        fun: &Function,
        info: &naga::valid::FunctionInfo,
        args: Vec<(Ev, Option<u64>)>,
        depth: usize,
        mut state: State,
    ) -> (State, Option<Val>) {
        if depth > MAX_CALL_DEPTH {
            let v = fun.result.as_ref().map(|r| Val::unknown(self.module, &self.module.types[r.ty].inner));
            return (state, v);
        }
        // A `return` leaves the callee only: the caller's code after the call is as sure
        // as the call.
        let (sure, taken) = (state.sure, self.exits);
        let n = fun.expressions.len();
        let mut c = Call {
            fun,
            info,
            depth,
            args,
            values: vec![None; n],
            keys: vec![None; n],
            returned: Vec::new(),
            in_continuing: false,
            loop_id: 0,
            select_arms: select_arms(fun),
        };
        for (h, local) in fun.local_variables.iter() {
            let v = match local.init {
                Some(init) => self.value(&mut c, &state, init),
                None => Val::zero(self.module, &self.module.types[local.ty].inner),
            };
            state.locals.insert((depth, h), Rc::new(v));
        }
        let mut exits = Exits::default();
        let end = self.block(&mut c, &fun.body, state, &mut exits);
        let mut out = end;
        let mut result: Option<Val> = None;
        for (s, v) in std::mem::take(&mut c.returned) {
            out = out.join(&s, &mut self.fresh);
            if let Some(v) = v {
                result = Some(match result {
                    Some(r) => r.join(&v),
                    None => v,
                });
            }
        }
        out.locals.retain(|(d, _), _| *d != depth);
        out.live = true;
        out.sure = sure;
        self.exits = taken;
        if result.is_none() {
            result = fun.result.as_ref().map(|r| Val::unknown(self.module, &self.module.types[r.ty].inner));
        }
        (out, result)
    }

    pub fn block(&mut self, c: &mut Call<'_>, block: &Block, mut state: State, exits: &mut Exits) -> State {
        for (stmt, span) in block.span_iter() {
            if !state.live {
                break;
            }
            state = self.statement(c, stmt, *span, state, exits);
        }
        state
    }

    fn statement(&mut self, c: &mut Call<'_>, stmt: &Statement, span: naga::Span, mut state: State, exits: &mut Exits) -> State {
        self.work += 1;
        if self.work > self.work_limit {
            self.stopped = true;
            return State::dead();
        }
        match stmt {
            Statement::Emit(range) => {
                for h in range.clone() {
                    self.emit(c, &state, h);
                }
                state
            }
            Statement::Block(b) => self.block(c, b, state, exits),
            Statement::If { condition, accept, reject } => {
                let (sure, before) = (state.sure, self.exits);
                let yes = self.refine(c, state.clone(), *condition, true);
                let no = self.refine(c, state, *condition, false);
                let decided = !yes.live || !no.live;
                let (yes, no) = if decided { (yes, no) } else { (yes.unsure(), no.unsure()) };
                let a = self.block(c, accept, yes, exits);
                let b = self.block(c, reject, no, exits);
                self.work += a.size() + b.size();
                let mut out = a.join(&b, &mut self.fresh);
                // After an undecided `if` whose arms both fall through, the code runs as
                // surely as before it.
                if !decided && out.live {
                    out.sure = sure && self.exits == before;
                }
                out
            }
            Statement::Switch { selector, cases } if self.witness => self.witness_switch(c, *selector, cases, state, exits),
            Statement::Switch { cases, .. } => {
                let mut inner = Exits::default();
                let out = self.every_case(c, cases, state, &mut inner);
                self.close_switch(out, inner, exits)
            }
            Statement::Loop { body, continuing, break_if } if self.witness => self.unroll(c, body, continuing, *break_if, state),
            Statement::Loop { body, continuing, break_if } => self.run_loop(c, body, continuing, *break_if, state),
            Statement::Break => {
                self.exits.breaks += 1;
                exits.breaks.push(state);
                State::dead()
            }
            Statement::Continue => {
                self.exits.continues += 1;
                exits.continues.push(state);
                State::dead()
            }
            Statement::Return { value } => {
                self.exits.leaves += 1;
                let v = value.map(|h| self.value(c, &state, h));
                c.returned.push((state, v));
                State::dead()
            }
            Statement::Kill => {
                self.exits.leaves += 1;
                State::dead()
            }
            Statement::Store { pointer, value } => {
                let v = self.value(c, &state, *value);
                if c.in_continuing {
                    self.check_counter(c, &state, *value, span);
                }
                if let Ev::P(place) = self.eval(c, &state, *pointer) {
                    self.write(&mut state, &place, v);
                    match c.keys[value.index()].filter(|_| place.path.is_empty()) {
                        Some(k) => state.stored.insert(place.root.clone(), k),
                        None => state.stored.remove(&place.root),
                    };
                }
                state
            }
            Statement::Call { function, arguments, result } => {
                let args: Vec<(Ev, Option<u64>)> = arguments.iter().map(|&a| (self.eval(c, &state, a), c.keys[a.index()])).collect();
                let callee = &self.module.functions[*function];
                let info = &self.info[*function];
                let (after, v) = self.call(callee, info, args, c.depth + 1, state);
                if let (Some(r), Some(v)) = (result, v) {
                    c.values[r.index()] = Some(Ev::V(v));
                }
                after
            }
            _ => {
                // Barriers, image stores, atomics, ray queries, subgroup operations: they
                // change no value the analysis tracks, or give results it knows nothing of.
                state
            }
        }
    }

    /// Every case of a `switch` entered from `state` (or by falling through the one before):
    /// the state after the cases that end; their `break`s and `continue`s go to `inner`.
    pub(super) fn every_case(&mut self, c: &mut Call<'_>, cases: &[naga::SwitchCase], state: State, inner: &mut Exits) -> State {
        let mut out = State::dead();
        let mut falling = State::dead();
        for case in cases {
            let entry = state.join(&falling, &mut self.fresh);
            let end = self.block(c, &case.body, entry, inner);
            if case.fall_through {
                falling = end;
            } else {
                out = out.join(&end, &mut self.fresh);
                falling = State::dead();
            }
        }
        out
    }

    /// The state after a `switch`: `out` joined with its `break`s; `continue` belongs to the
    /// enclosing loop.
    pub(super) fn close_switch(&mut self, mut out: State, inner: Exits, exits: &mut Exits) -> State {
        for b in inner.breaks {
            out = out.join(&b, &mut self.fresh);
        }
        exits.continues.extend(inner.continues);
        out
    }

    pub(super) fn run_loop(
        &mut self,
        c: &mut Call<'_>,
        body: &Block,
        continuing: &Block,
        break_if: Option<Handle<Expression>>,
        entry: State,
    ) -> State {
        // The first iteration on its own (reported: its values are the loop's too): the
        // head of every later one has seen at least one, so a count or sum the body always
        // adds to is no longer joined with its value before the loop.
        let (first, first_out) = self.loop_round(c, body, continuing, break_if, entry.clone());
        let mut head = first.clone();
        self.quiet += 1;
        for round in 0..MAX_ROUNDS {
            let (next, _) = self.loop_round(c, body, continuing, break_if, head.clone());
            let mut joined = first.join(&next, &mut self.fresh);
            if round >= 2 {
                joined = joined.widen(&head);
            }
            if same_values(&joined, &head) {
                break;
            }
            head = joined;
        }
        self.quiet -= 1;
        let head = self.bound_inductions(c, &entry, head, body, continuing);
        let (_, out) = self.loop_round(c, body, continuing, break_if, head);
        first_out.join(&out, &mut self.fresh)
    }

    /// One iteration from `head`: the state back at the head, and the state after the loop.
    pub(super) fn loop_round(
        &mut self,
        c: &mut Call<'_>,
        body: &Block,
        continuing: &Block,
        break_if: Option<Handle<Expression>>,
        head: State,
    ) -> (State, State) {
        let mut exits = Exits::default();
        let end = self.block(c, body, head, &mut exits);
        let mut cont = end;
        for s in std::mem::take(&mut exits.continues) {
            cont = cont.join(&s, &mut self.fresh);
        }
        let was = (c.in_continuing, c.loop_id);
        (c.in_continuing, c.loop_id) = (true, continuing as *const Block as usize);
        let mut inner = Exits::default();
        let after = self.block(c, continuing, cont, &mut inner);
        (c.in_continuing, c.loop_id) = was;
        let mut out = State::dead();
        let next = match break_if {
            Some(cond) if after.live => {
                self.emit_pending(c, &after, cond);
                out = self.refine(c, after.clone(), cond, true);
                let next = self.refine(c, after, cond, false);
                if out.live && next.live {
                    out.sure = false;
                    next.unsure()
                } else {
                    next
                }
            }
            _ => after,
        };
        for b in exits.breaks {
            out = out.join(&b, &mut self.fresh);
        }
        (next, out)
    }

    fn emit_pending(&mut self, c: &mut Call<'_>, state: &State, h: Handle<Expression>) {
        if c.values[h.index()].is_none() {
            self.emit(c, state, h);
        }
    }

    /// Reads the value at `place`.
    pub fn read(&self, state: &State, place: &Place) -> Val {
        let initial;
        let base = match &place.root {
            Root::Local(d, h) => state.locals.get(&(*d, *h)).map(|v| &**v),
            Root::Global(g) => match state.globals.get(g) {
                Some(v) => Some(&**v),
                None => {
                    initial = self.global_initial(*g);
                    Some(&*initial)
                }
            },
        };
        let Some(base) = base else { return Val::Agg(Vec::new()) };
        // Only the part read is copied, not the whole variable.
        let Some((first, rest)) = place.path.split_first() else { return base.clone() };
        let mut v = super::eval::index(base, *first);
        for step in rest {
            v = super::eval::index(&v, *step);
        }
        v
    }

    /// Writes `v` at `place` (a dynamic index joins it into every element).
    pub fn write(&mut self, state: &mut State, place: &Place, v: Val) {
        let current = match &place.root {
            Root::Local(d, h) => state.locals.get(&(*d, *h)).cloned(),
            Root::Global(g) => Some(state.globals.get(g).cloned().unwrap_or_else(|| self.global_initial(*g))),
        };
        let Some(current) = current else { return };
        let updated = Rc::new(super::eval::update(&current, &place.path, v));
        match &place.root {
            Root::Local(d, h) => {
                state.locals.insert((*d, *h), updated);
            }
            Root::Global(g) => {
                state.globals.insert(*g, updated);
            }
        }
        self.fresh += 1;
        state.versions.insert(place.root.clone(), self.fresh);
    }

    /// Records `h`, found where execution is `sure` to come. A witness run records only the
    /// hazards that surely happen: certain on the operands' values, at a point every
    /// execution reaches.
    pub fn report(&mut self, h: Hazard, sure: bool) {
        if self.quiet > 0 || h.span == naga::Span::UNDEFINED {
            return;
        }
        if self.witness && !(h.certain && sure) {
            return;
        }
        if !self.hazards.iter().any(|x| x.code == h.code && x.span == h.span) {
            self.hazards.push(h);
        }
    }

    /// The value of global `g` before the stage writes it (made once per analysis).
    fn global_initial(&self, g: Handle<naga::GlobalVariable>) -> Rc<Val> {
        if let Some(v) = self.initials.borrow().get(&g) {
            return v.clone();
        }
        let v = Rc::new(self.make_global_initial(g));
        self.initials.borrow_mut().insert(g, v.clone());
        v
    }

    fn make_global_initial(&self, g: Handle<naga::GlobalVariable>) -> Val {
        let var = &self.module.global_variables[g];
        let inner = &self.module.types[var.ty].inner;
        match var.space {
            naga::AddressSpace::Uniform | naga::AddressSpace::Immediate => super::facts::uniform_value(self.module, inner, "", self.facts),
            naga::AddressSpace::Private | naga::AddressSpace::WorkGroup => match var.init {
                Some(init) => super::eval::constant(self.module, init),
                None => Val::zero(self.module, inner),
            },
            _ => Val::unknown(self.module, inner),
        }
    }

    /// A stable key for a value: loads of the same place with no store between them, and
    /// the same operations on the same keys, get the same key.
    pub fn hash_key(parts: impl Hash) -> u64 {
        let mut h = std::collections::hash_map::DefaultHasher::new();
        parts.hash(&mut h);
        h.finish()
    }
}

/// States equal in values (versions and refinements aside): the fixpoint test.
fn same_values(a: &State, b: &State) -> bool {
    fn same<K: Hash + Eq>(a: &Map<K, Rc<Val>>, b: &Map<K, Rc<Val>>) -> bool {
        a.len() == b.len() && a.iter().all(|(k, v)| b.get(k).is_some_and(|w| Rc::ptr_eq(v, w) || v == w))
    }
    a.live == b.live && same(&a.locals, &b.locals) && same(&a.globals, &b.globals)
}
