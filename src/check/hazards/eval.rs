//! Evaluation of naga expressions to abstract values, with value keys and refinement by
//! conditions. Arithmetic and builtins are in [`super::ops`]; the hazards they find are
//! reported here, at the expression's span.

use naga::{BinaryOperator as B, Expression, Handle, Literal, Module, ScalarKind, TypeInner, UnaryOperator};

use super::interval::Iv;
use super::ops;
use super::value::{Num, Val};
use super::walk::{Analyzer, Call, Ev, Place, Refined, Root, State, Step};
use super::Hazard;

impl Analyzer<'_> {
    /// The value of `h`: as emitted, or evaluated now (expressions that are never emitted:
    /// literals, constants, arguments, variables).
    pub fn eval(&mut self, c: &mut Call<'_>, state: &State, h: Handle<Expression>) -> Ev {
        match &c.values[h.index()] {
            Some(v) => v.clone(),
            None => self.emit(c, state, h),
        }
    }

    /// Evaluates `h` in `state` and records its value and key.
    pub fn emit(&mut self, c: &mut Call<'_>, state: &State, h: Handle<Expression>) -> Ev {
        let computed = self.compute(c, state, h);
        let key = self.key_of(c, state, h);
        c.keys[h.index()] = key;
        let ev = match (computed, key.and_then(|k| state.refined.get(&k))) {
            (Ev::V(Val::Num(mut n)), Some(r)) if n.c.len() == 1 => {
                n.c[0] = n.c[0].meet(r.iv);
                n.gap = n.gap.max(r.gap).max(n.c[0].mig());
                n.len = Iv::new(n.gap, n.c[0].mag());
                n.len3 = n.len;
                Ev::V(Val::Num(n))
            }
            (ev, _) => ev,
        };
        c.values[h.index()] = Some(ev.clone());
        ev
    }

    /// The value of `h`; pointers read through.
    pub fn value(&mut self, c: &mut Call<'_>, state: &State, h: Handle<Expression>) -> Val {
        match self.eval(c, state, h) {
            Ev::V(v) => v,
            Ev::P(p) => self.read(state, &p),
        }
    }

    fn num(&mut self, c: &mut Call<'_>, state: &State, h: Handle<Expression>) -> Num {
        match self.value(c, state, h) {
            Val::Num(n) => n,
            Val::Agg(_) => Num::unknown(1, 1, ScalarKind::Float),
        }
    }

    fn ty(&self, c: &Call<'_>, h: Handle<Expression>) -> TypeInner {
        c.info[h].ty.inner_with(&self.module.types).clone()
    }

    fn unknown_of(&self, c: &Call<'_>, h: Handle<Expression>) -> Val {
        Val::unknown(self.module, &self.ty(c, h))
    }

    pub fn span(&self, c: &Call<'_>, h: Handle<Expression>) -> naga::Span {
        expression_span(c.fun, h, self.text)
    }

    /// The key of `h`'s value (see [`Analyzer::hash_key`]); `None` for values with no
    /// stable identity.
    pub fn key_of(&mut self, c: &mut Call<'_>, state: &State, h: Handle<Expression>) -> Option<u64> {
        let e = &c.fun.expressions[h];
        let sub = |c: &Call<'_>, x: Handle<Expression>| c.keys[x.index()];
        let k = match e {
            Expression::Literal(l) => Some(Self::hash_key(("lit", format!("{l:?}")))),
            Expression::Constant(k) => Some(Self::hash_key(("const", k.index()))),
            Expression::FunctionArgument(i) => c.args.get(*i as usize).and_then(|a| a.1),
            Expression::Load { pointer } => match self.eval(c, state, *pointer) {
                Ev::P(p) => match state.stored.get(&p.root).filter(|_| p.path.is_empty()) {
                    Some(&k) => Some(k),
                    None => {
                        let version = state.versions.get(&p.root).copied().unwrap_or(0);
                        Some(Self::hash_key(("load", &p, version)))
                    }
                },
                Ev::V(_) => None,
            },
            Expression::Unary { op, expr } => sub(c, *expr).map(|k| Self::hash_key(("un", format!("{op:?}"), k))),
            Expression::Binary { op, left, right } => {
                sub(c, *left).zip(sub(c, *right)).map(|(a, b)| Self::hash_key(("bin", format!("{op:?}"), a, b)))
            }
            Expression::Math { fun, arg, arg1, arg2, .. } => {
                let a = sub(c, *arg)?;
                let b = arg1.map(|x| sub(c, x));
                let d = arg2.map(|x| sub(c, x));
                if b == Some(None) || d == Some(None) {
                    return None;
                }
                Some(math_key(*fun, a, b.flatten(), d.flatten()))
            }
            Expression::AccessIndex { base, index } => sub(c, *base).map(|k| Self::hash_key(("ai", k, *index))),
            Expression::Swizzle { vector, pattern, size } => {
                sub(c, *vector).map(|k| Self::hash_key(("sw", k, format!("{pattern:?}{size:?}"))))
            }
            Expression::As { expr, kind, convert } => sub(c, *expr).map(|k| Self::hash_key(("as", k, format!("{kind:?}{convert:?}")))),
            _ => None,
        };
        k
    }

    fn compute(&mut self, c: &mut Call<'_>, state: &State, h: Handle<Expression>) -> Ev {
        let module = self.module;
        let e = &c.fun.expressions[h];
        let v = match *e {
            Expression::Literal(l) => literal(l),
            Expression::Constant(k) => constant(module, module.constants[k].init),
            Expression::Override(_) => self.unknown_of(c, h),
            Expression::ZeroValue(ty) => Val::zero(module, &module.types[ty].inner),
            Expression::Compose { ty, ref components } => {
                let parts: Vec<Val> = components.iter().map(|&x| self.value(c, state, x)).collect();
                let mut v = compose(module, &module.types[ty].inner, parts);
                if let Val::Num(n) = &mut v {
                    if let Some(g) = self.matrix_from_columns(c, state, components) {
                        n.gain = g;
                    }
                }
                v
            }
            Expression::Access { base, index } => {
                let idx = self.num(c, state, index);
                let step = match idx.c[0] {
                    Iv { lo, hi } if lo == hi && lo >= 0.0 => Step::Index(lo as u32),
                    _ => Step::Dynamic,
                };
                return self.step_into(c, state, base, step);
            }
            Expression::AccessIndex { base, index } => return self.step_into(c, state, base, Step::Index(index)),
            Expression::Splat { size, value } => {
                let n = self.num(c, state, value);
                let mut s = Num::from_comps(vec![n.c[0]; size as usize], 1, n.kind, n.known);
                s.per_draw = n.per_draw;
                Val::Num(s)
            }
            Expression::Swizzle { size, vector, pattern } => {
                let n = self.num(c, state, vector);
                Val::Num(ops::swizzle(&n, &pattern[..size as usize]))
            }
            Expression::FunctionArgument(i) => return c.args.get(i as usize).map_or_else(|| Ev::V(self.unknown_of(c, h)), |a| a.0.clone()),
            Expression::GlobalVariable(g) => return Ev::P(Place { root: Root::Global(g), path: Vec::new() }),
            Expression::LocalVariable(l) => return Ev::P(Place { root: Root::Local(c.depth, l), path: Vec::new() }),
            Expression::Load { pointer } => match self.eval(c, state, pointer) {
                Ev::P(p) => self.read(state, &p),
                Ev::V(v) => v,
            },
            Expression::ImageSample { image, .. } | Expression::ImageLoad { image, .. } => self.sample(c, h, image),
            Expression::ImageQuery { .. } => {
                Val::unknown(module, &self.ty(c, h)).map_nums(&|n| Num::from_comps(vec![Iv::new(1.0, 16384.0); n.c.len()], 1, n.kind, true))
            }
            Expression::Unary { op, expr } => {
                let n = self.num(c, state, expr);
                Val::Num(match op {
                    UnaryOperator::Negate => ops::negate(&n),
                    UnaryOperator::LogicalNot => ops::map(&n, |x| Iv::new(1.0 - x.hi, 1.0 - x.lo)),
                    UnaryOperator::BitwiseNot => Num { known: n.known, ..Num::unknown(n.c.len(), n.cols, n.kind) },
                })
            }
            Expression::Binary { op, left, right } => self.binary(c, state, h, op, left, right),
            Expression::Select { condition, accept, reject } => {
                // A decided condition picks its arm (`abs(N.z) < 0.999 ? … : …`, N constant).
                match self.num(c, state, condition).c.as_slice() {
                    [x] if x.is_point() && x.lo == 1.0 => self.value(c, state, accept),
                    [x] if x.is_point() && x.lo == 0.0 => self.value(c, state, reject),
                    _ => self.value(c, state, accept).join(&self.value(c, state, reject)),
                }
            }
            Expression::Derivative { expr, .. } => {
                // The difference of two neighbouring values, both inside the value's range.
                let n = self.num(c, state, expr);
                Val::Num(ops::map(&n, |x| {
                    let w = x.hi - x.lo;
                    Iv::new(-w, w)
                }))
            }
            Expression::Relational { .. } => {
                Val::unknown(module, &self.ty(c, h)).map_nums(&|n| Num::from_comps(vec![Iv::UNIT; n.c.len()], 1, n.kind, true))
            }
            Expression::Math { fun, arg, arg1, arg2, .. } => {
                let a = self.num(c, state, arg);
                let b = arg1.map(|x| self.num(c, state, x));
                let d = arg2.map(|x| self.num(c, state, x));
                let same = arg1.is_some_and(|x| c.keys[arg.index()].is_some() && c.keys[arg.index()] == c.keys[x.index()]);
                let nonzero = self.proven_nonzero(c, state, arg, fun);
                let out = ops::math(fun, &a, b.as_ref(), d.as_ref(), same, nonzero);
                // atan(0, 0) in an arm of `?:` is the case the condition leaves out; and only
                // when y and x are components of one vector that can be zero is (0, 0)
                // reachable (intervals of two separate values cannot tell).
                let discarded = out.hazard == Some(ops::Kind::Atan2)
                    && (c.select_arms[h.index()] || !arg1.is_some_and(|x| self.same_vector_can_vanish(c, state, arg, x)));
                if let Some(kind) = out.hazard.filter(|_| !discarded) {
                    self.found(c, state, h, Hazard::new(kind, self.span(c, h), &a, b.as_ref()));
                }
                if fun == naga::MathFunction::Fract {
                    self.check_hash(c, state, h, arg);
                }
                Val::Num(self.after_hazard(out))
            }
            Expression::As { expr, kind, convert } => {
                let n = self.num(c, state, expr);
                Val::Num(ops::cast(&n, kind, convert))
            }
            _ => self.unknown_of(c, h),
        };
        Ev::V(v)
    }

    fn step_into(&mut self, c: &mut Call<'_>, state: &State, base: Handle<Expression>, step: Step) -> Ev {
        match self.eval(c, state, base) {
            Ev::P(mut p) => {
                p.path.push(step);
                Ev::P(p)
            }
            Ev::V(v) => Ev::V(index(&v, step)),
        }
    }

    fn binary(
        &mut self,
        c: &mut Call<'_>,
        state: &State,
        h: Handle<Expression>,
        op: B,
        left: Handle<Expression>,
        right: Handle<Expression>,
    ) -> Val {
        let a = self.num(c, state, left);
        let b = self.num(c, state, right);
        if op == B::Subtract {
            if let Some(v) = self.glsl_mod(c, state, left, right, &a) {
                return Val::Num(v);
            }
        }
        let same = c.keys[left.index()].is_some() && c.keys[left.index()] == c.keys[right.index()];
        let out = ops::binary(op, &a, &b, same);
        if let Some(kind) = out.hazard {
            // A division names its divisor; a remainder both operands; a shift its amount.
            let hazard = match kind {
                ops::Kind::NegativeRemainder => Hazard::new(kind, self.span(c, h), &a, Some(&b)),
                _ => Hazard::new(kind, self.span(c, h), &b, None),
            };
            self.found(c, state, h, hazard);
        }
        Val::Num(self.after_hazard(out))
    }

    /// naga writes GLSL's `mod(x, y)` as `x - floor(x / y) * y`: in `[0, y)` for `y > 0`.
    fn glsl_mod(&mut self, c: &mut Call<'_>, state: &State, left: Handle<Expression>, right: Handle<Expression>, x: &Num) -> Option<Num> {
        let Expression::Binary { op: B::Multiply, left: m0, right: m1 } = c.fun.expressions[right] else { return None };
        let is_floor = |h: Handle<Expression>| matches!(c.fun.expressions[h], Expression::Math { fun: naga::MathFunction::Floor, .. });
        let (y, fl) = if is_floor(m1) {
            (m0, m1)
        } else if is_floor(m0) {
            (m1, m0)
        } else {
            return None;
        };
        let Expression::Math { arg: div, .. } = c.fun.expressions[fl] else { return None };
        let Expression::Binary { op: B::Divide, left: x2, right: y2 } = c.fun.expressions[div] else { return None };
        if x2 != left || y2 != y {
            return None;
        }
        let yv = self.num(c, state, y);
        let n = x.c.len();
        let comps: Vec<Iv> = (0..n)
            .map(|i| {
                let yi = yv.c[i.min(yv.c.len() - 1)];
                if yi.lo > 0.0 {
                    Iv::new(0.0, yi.hi)
                } else if yi.hi < 0.0 {
                    Iv::new(yi.lo, 0.0)
                } else {
                    Iv::new(-yi.mag(), yi.mag())
                }
            })
            .collect();
        let mut r = Num::from_comps(comps, 1, x.kind, x.known && yv.known);
        r.per_draw = x.per_draw && yv.per_draw;
        Some(r)
    }

    /// `mat3(m)` written as three `.xyz` columns of one matrix keeps `m`'s gain.
    fn matrix_from_columns(&mut self, c: &mut Call<'_>, state: &State, components: &[Handle<Expression>]) -> Option<Iv> {
        if components.len() != 3 {
            return None;
        }
        let mut source = None;
        for (i, &col) in components.iter().enumerate() {
            let Expression::Swizzle { vector, pattern, size: naga::VectorSize::Tri } = c.fun.expressions[col] else { return None };
            if pattern[..3] != [naga::SwizzleComponent::X, naga::SwizzleComponent::Y, naga::SwizzleComponent::Z] {
                return None;
            }
            let Expression::AccessIndex { base, index } = c.fun.expressions[vector] else { return None };
            if index as usize != i || source.is_some_and(|s| s != base) {
                return None;
            }
            source = Some(base);
        }
        let m = self.num(c, state, source?);
        (m.cols == 4).then_some(m.gain)
    }

    /// `y` and `x` are components of one vector (`v.y`, `v.x`) whose length can be 0.
    fn same_vector_can_vanish(&mut self, c: &mut Call<'_>, state: &State, y: Handle<Expression>, x: Handle<Expression>) -> bool {
        // `v.y` of a value, or a load of `v.y` of a variable.
        let exprs = &c.fun.expressions;
        let base = |h: Handle<Expression>| match exprs[h] {
            Expression::AccessIndex { base, .. } => Some(base),
            Expression::Load { pointer } => match exprs[pointer] {
                Expression::AccessIndex { base, .. } => Some(base),
                _ => None,
            },
            _ => None,
        };
        let same = |a: Handle<Expression>, b: Handle<Expression>| {
            a == b || (c.keys[a.index()].is_some() && c.keys[a.index()] == c.keys[b.index()])
        };
        match (base(y), base(x)) {
            (Some(a), Some(b)) if same(a, b) => {
                // A 2-vector (`atan(d.y, d.x)`), not proven non-zero by a guard on its
                // length (of a longer vector, the pair's own length is not tracked).
                let v = self.num(c, state, a);
                let guarded = c.keys[a.index()].is_some_and(|k| length_proven_positive(state, k));
                v.c.len() == 2 && v.len.lo <= 0.0 && v.gap <= 0.0 && !guarded
            }
            _ => false,
        }
    }

    /// Facts from guards: `length(v)` or `dot(v, v)` proven positive by a condition.
    fn proven_nonzero(&mut self, c: &mut Call<'_>, state: &State, arg: Handle<Expression>, fun: naga::MathFunction) -> bool {
        if fun != naga::MathFunction::Normalize {
            return false;
        }
        c.keys[arg.index()].is_some_and(|k| length_proven_positive(state, k))
    }

    fn sample(&mut self, c: &Call<'_>, h: Handle<Expression>, image: Handle<Expression>) -> Val {
        let unknown = self.unknown_of(c, h);
        let Expression::GlobalVariable(g) = c.fun.expressions[image] else { return unknown };
        let name = self.module.global_variables[g].name.clone().unwrap_or_default();
        let Some(ch) = self.facts.textures.get(&name) else { return unknown };
        unknown.map_nums(&|n| {
            let comps = (0..n.c.len()).map(|i| ch[i.min(3)]).collect();
            Num::from_comps(comps, 1, n.kind, true)
        })
    }

    /// `fract(sin(x) * K)` hashes: sin's allowed error times `K`, and a growing `x`.
    fn check_hash(&mut self, c: &mut Call<'_>, state: &State, h: Handle<Expression>, arg: Handle<Expression>) {
        let Expression::Binary { op: B::Multiply, left, right } = c.fun.expressions[arg] else { return };
        let is_sin = |e: &Expression| matches!(e, Expression::Math { fun: naga::MathFunction::Sin | naga::MathFunction::Cos, .. });
        let (sin, k) = if is_sin(&c.fun.expressions[left]) {
            (left, right)
        } else if is_sin(&c.fun.expressions[right]) {
            (right, left)
        } else {
            return;
        };
        let Expression::Math { arg: x, .. } = c.fun.expressions[sin] else { return };
        let kv = self.num(c, state, k);
        let xv = self.num(c, state, x);
        if kv.known && xv.known && kv.iv().mag() >= ops::HASH_SCALE_LIMIT {
            self.found(c, state, h, Hazard::hash(self.span(c, h), xv.iv(), kv.iv()));
        }
    }

    /// The state on the path where `cond` is `truth`.
    pub fn refine(&mut self, c: &mut Call<'_>, mut state: State, cond: Handle<Expression>, truth: bool) -> State {
        // A condition whose value is decided (`mode == 2` with `mode` known) leaves one side.
        if let Some(b) = self.value(c, &state, cond).num().map(Num::iv).filter(|b| b.is_point()) {
            if (b.lo != 0.0) != truth {
                state.live = false;
                return state;
            }
        }
        match c.fun.expressions[cond] {
            Expression::Unary { op: UnaryOperator::LogicalNot, expr } => return self.refine(c, state, expr, !truth),
            Expression::Binary { op: B::LogicalAnd, left, right } if truth => {
                let s = self.refine(c, state, left, true);
                return self.refine(c, s, right, true);
            }
            Expression::Binary { op: B::LogicalOr, left, right } if !truth => {
                let s = self.refine(c, state, left, false);
                return self.refine(c, s, right, false);
            }
            Expression::Literal(Literal::Bool(b)) if b != truth => {
                state.live = false;
                return state;
            }
            Expression::Binary { op, left, right } => {
                let Some(op) = ops::comparison(op, truth) else { return state };
                let a = self.num(c, &state, left);
                let b = self.num(c, &state, right);
                if a.c.len() != 1 || b.c.len() != 1 {
                    return state;
                }
                // An integer holds its type's range whatever else is unknown about it (a loop to
                // a uniform count never overflows its counter), an unknown one short of the
                // extremes: `i <= n` overflows `i++` only at `n = INT_MAX`, which no one means.
                let range = match a.kind {
                    naga::ScalarKind::Sint => Some(Iv::new(f64::from(i32::MIN), f64::from(i32::MAX))),
                    naga::ScalarKind::Uint => Some(Iv::new(0.0, f64::from(u32::MAX))),
                    _ => None,
                };
                let short = |r: Iv| Iv::new(r.lo + 1.0, r.hi - 1.0);
                let typed = |v: &Num| range.map(|r| if v.known { r } else { short(r) }).map_or(v.c[0], |r| v.c[0].meet(r));
                let (ai, bi) = (typed(&a), typed(&b));
                if ops::never(op, ai, bi) {
                    // This side of the test cannot run (a loop's exit before its first
                    // iteration, when the counter starts inside the bound).
                    state.live = false;
                    return state;
                }
                let int = range.is_some();
                // An integer that is not `N` and is at most `N` is below it (`i != 3` ends a
                // loop counting up from 0).
                let op = match (op, int && bi.is_point()) {
                    (B::NotEqual, true) if ai.hi == bi.lo => B::Less,
                    (B::NotEqual, true) if ai.lo == bi.lo => B::Greater,
                    _ => op,
                };
                self.learn(c, &mut state, left, op, bi, int);
                self.learn(c, &mut state, right, ops::mirror(op), ai, int);
            }
            _ => {}
        }
        state
    }

    /// Records `x op bound` for the expression `x` (and `|y| >= k` when `x` is `abs(y)`).
    /// Between integers a strict comparison is a closed one a step further (`i > 1` is
    /// `i >= 2`).
    fn learn(&mut self, c: &mut Call<'_>, state: &mut State, x: Handle<Expression>, op: B, bound: Iv, int: bool) {
        let Some(key) = c.keys[x.index()] else { return };
        let (op, bound) = match (op, int) {
            (B::Less, true) => (B::LessEqual, Iv::new(bound.lo - 1.0, bound.hi - 1.0)),
            (B::Greater, true) => (B::GreaterEqual, Iv::new(bound.lo + 1.0, bound.hi + 1.0)),
            _ => (op, bound),
        };
        let (iv, gap) = match op {
            B::Less => (Iv::new(f64::NEG_INFINITY, bound.hi), if bound.hi <= 0.0 { f64::MIN_POSITIVE } else { 0.0 }),
            B::LessEqual => (Iv::new(f64::NEG_INFINITY, bound.hi), 0.0),
            B::Greater => (Iv::new(bound.lo, f64::INFINITY), if bound.lo >= 0.0 { f64::MIN_POSITIVE } else { 0.0 }),
            B::GreaterEqual => (Iv::new(bound.lo, f64::INFINITY), 0.0),
            B::Equal => (bound, bound.mig()),
            B::NotEqual if bound == Iv::point(0.0) => (Iv::TOP, f64::MIN_POSITIVE),
            _ => return,
        };
        let merged = match state.refined.get(&key) {
            Some(r) => Refined { iv: r.iv.meet(iv), gap: r.gap.max(gap) },
            None => Refined { iv, gap },
        };
        state.refined.insert(key, merged);
        if let Expression::As { expr, kind: ScalarKind::Float, convert: Some(_) } = c.fun.expressions[x] {
            // `float(i) < 4.0` bounds the integer `i` too (the conversion is monotone).
            if matches!(self.num(c, state, expr).kind, ScalarKind::Sint | ScalarKind::Uint) {
                let whole = Iv::new(bound.lo.ceil(), bound.hi.floor());
                self.learn(c, state, expr, op, if op == B::Equal { whole } else { bound }, false);
            }
        }
        if let Expression::Math { fun: naga::MathFunction::Abs, arg, .. } = c.fun.expressions[x] {
            // abs(y) >= k  ⇒  |y| >= k;  abs(y) <= k  ⇒  y in [-k, k].
            let Some(inner) = c.keys[arg.index()] else { return };
            let r = Refined { iv: Iv::new(-merged.iv.hi, merged.iv.hi), gap: merged.gap.max(merged.iv.lo.max(0.0)) };
            let merged = match state.refined.get(&inner) {
                Some(o) => Refined { iv: o.iv.meet(r.iv), gap: o.gap.max(r.gap) },
                None => r,
            };
            state.refined.insert(inner, merged);
        }
    }

    pub fn argument(&self, a: &naga::FunctionArgument) -> Val {
        let inner = &self.module.types[a.ty].inner;
        let unknown = Val::unknown(self.module, inner);
        match &a.binding {
            Some(naga::Binding::Location { location, .. }) => {
                let fact = match self.stage {
                    naga::ShaderStage::Vertex => self.facts.attributes.get(location),
                    _ => self.facts.varyings.get(location),
                };
                match (fact, &unknown) {
                    (Some(f), Val::Num(u)) => Val::Num(fit(f, u)),
                    _ => unknown,
                }
            }
            Some(naga::Binding::BuiltIn(b)) => self.facts.builtin(*b, unknown),
            None => unknown,
        }
    }
}

/// The span of `h` in the stage text. naga's GLSL front gives builtin calls no span:
/// theirs is rebuilt from the arguments' spans, widened to the call's name and parentheses.
pub fn expression_span(fun: &naga::Function, h: Handle<Expression>, text: &str) -> naga::Span {
    let span = fun.expressions.get_span(h);
    if span != naga::Span::UNDEFINED {
        return span;
    }
    let union =
        |spans: Vec<naga::Span>| spans.into_iter().filter(|s| *s != naga::Span::UNDEFINED).reduce(|a, b| a.until(&b)).unwrap_or_default();
    let sub = |x: Handle<Expression>| expression_span(fun, x, text);
    match fun.expressions[h] {
        Expression::Math { arg, arg1, arg2, arg3, .. } => {
            widen_to_call(text, union([Some(arg), arg1, arg2, arg3].into_iter().flatten().map(sub).collect()))
        }
        Expression::Derivative { expr, .. } | Expression::Relational { argument: expr, .. } => widen_to_call(text, sub(expr)),
        Expression::Binary { left, right, .. } => union(vec![sub(left), sub(right)]),
        Expression::Unary { expr, .. } | Expression::As { expr, .. } | Expression::Swizzle { vector: expr, .. } => sub(expr),
        Expression::Compose { ref components, .. } => union(components.iter().map(|&x| sub(x)).collect()),
        _ => span,
    }
}

/// The key of a builtin's value from its arguments' keys (shared by evaluation and by the
/// guards that look a `length(v)` or `dot(v, v)` up).
fn math_key(fun: naga::MathFunction, a: u64, b: Option<u64>, d: Option<u64>) -> u64 {
    Analyzer::hash_key(("math", format!("{fun:?}"), a, b, d))
}

/// `f(args)` around the span of `args`: back over `(` and the name, on over `)`.
fn widen_to_call(text: &str, args: naga::Span) -> naga::Span {
    let Some(r) = args.to_range() else { return args };
    let bytes = text.as_bytes();
    let mut start = r.start.min(bytes.len());
    // An argument that starts with a member or swizzle (`lp.xz`): back to its base name.
    if bytes.get(start) == Some(&b'.') {
        while start > 0 && (bytes[start - 1].is_ascii_alphanumeric() || matches!(bytes[start - 1], b'_' | b'.')) {
            start -= 1;
        }
    }
    let mut opens = 0;
    while start > 0 && (bytes[start - 1].is_ascii_whitespace() || bytes[start - 1] == b'(') {
        opens += usize::from(bytes[start - 1] == b'(');
        start -= 1;
    }
    let name_end = start;
    while start > 0 && (bytes[start - 1].is_ascii_alphanumeric() || bytes[start - 1] == b'_') {
        start -= 1;
    }
    if opens == 0 || start == name_end {
        return args;
    }
    let mut end = r.end.min(bytes.len());
    while opens > 0 && end < bytes.len() {
        match bytes[end] {
            b')' => {
                opens -= 1;
                end += 1;
            }
            b if b.is_ascii_whitespace() => end += 1,
            _ => break,
        }
    }
    naga::Span::new(start as u32, end as u32)
}

/// A fact resized to the input's component count (a vec3 attribute read as vec4 gets w = 1
/// for positions, 0 otherwise, as vertex fetch does; fewer components keep the first ones).
fn fit(f: &Num, u: &Num) -> Num {
    let n = u.c.len();
    if f.c.len() == n {
        return Num { kind: u.kind, ..f.clone() };
    }
    let mut comps: Vec<Iv> = f.c.iter().copied().take(n).collect();
    while comps.len() < n {
        comps.push(Iv::new(0.0, 1.0));
    }
    let mut r = Num::from_comps(comps, 1, u.kind, f.known);
    if n >= 3 {
        r.len3 = r.len3.meet(f.len3);
        r.cone = f.cone;
    }
    if n == 3 {
        r.len = r.len.meet(f.len3);
    }
    r
}

fn literal(l: Literal) -> Val {
    let (x, kind) = match l {
        Literal::F64(x) => (x, ScalarKind::Float),
        Literal::F32(x) => (f64::from(x), ScalarKind::Float),
        Literal::F16(x) => (f64::from(f32::from(x)), ScalarKind::Float),
        Literal::U32(x) => (f64::from(x), ScalarKind::Uint),
        Literal::I32(x) => (f64::from(x), ScalarKind::Sint),
        Literal::U64(x) => (x as f64, ScalarKind::Uint),
        Literal::I64(x) => (x as f64, ScalarKind::Sint),
        Literal::U16(x) => (f64::from(x), ScalarKind::Uint),
        Literal::I16(x) => (f64::from(x), ScalarKind::Sint),
        Literal::Bool(b) => (f64::from(u8::from(b)), ScalarKind::Bool),
        Literal::AbstractInt(x) => (x as f64, ScalarKind::AbstractInt),
        Literal::AbstractFloat(x) => (x, ScalarKind::AbstractFloat),
    };
    let mut n = Num::scalar(Iv::point(x), kind, true);
    n.per_draw = true;
    Val::Num(n)
}

/// A constant expression of the module (`const` declarations).
pub fn constant(module: &Module, h: Handle<Expression>) -> Val {
    let e = &module.global_expressions[h];
    let v = match *e {
        Expression::Literal(l) => literal(l),
        Expression::Constant(k) => constant(module, module.constants[k].init),
        Expression::ZeroValue(ty) => Val::zero(module, &module.types[ty].inner),
        Expression::Compose { ty, ref components } => {
            compose(module, &module.types[ty].inner, components.iter().map(|&x| constant(module, x)).collect())
        }
        Expression::Splat { size, value } => match constant(module, value) {
            Val::Num(n) => Val::Num(Num::from_comps(vec![n.c[0]; size as usize], 1, n.kind, true)),
            other => other,
        },
        _ => return Val::Agg(Vec::new()),
    };
    v.map_nums(&|n| Num { per_draw: true, ..n.clone() })
}

/// A vector, matrix, struct or array from its parts.
pub fn compose(module: &Module, ty: &TypeInner, parts: Vec<Val>) -> Val {
    match *ty {
        TypeInner::Vector { scalar, .. } | TypeInner::Matrix { scalar, .. } => {
            let cols = if let TypeInner::Matrix { columns, .. } = *ty { columns as usize } else { 1 };
            let nums: Vec<&Num> = parts.iter().filter_map(Val::num).collect();
            let comps: Vec<Iv> = nums.iter().flat_map(|n| n.c.iter().copied()).collect();
            let known = nums.iter().all(|n| n.known);
            let mut r = Num::from_comps(comps, cols, scalar.kind, known);
            r.per_draw = nums.iter().all(|n| n.per_draw);
            // vec4(v.xyz, w): the xyz facts of v carry over.
            if cols == 1 && nums.len() == 2 && nums[0].c.len() == 3 && r.c.len() == 4 {
                r.len3 = r.len3.meet(nums[0].len);
                r.cone = nums[0].cone;
            }
            let unknown = Val::unknown(module, ty);
            match unknown {
                Val::Num(u) if u.c.len() == r.c.len() => Val::Num(r),
                other => other,
            }
        }
        _ => Val::Agg(parts),
    }
}

/// One step into a value.
pub fn index(v: &Val, step: Step) -> Val {
    match (v, step) {
        (Val::Agg(items), Step::Index(i)) => items.get(i as usize).cloned().unwrap_or_else(|| v.forget()),
        (Val::Agg(_), Step::Dynamic) => v.join_elements().unwrap_or_else(|| v.forget()),
        (Val::Num(n), step) => Val::Num(ops::component(n, step)),
    }
}

/// `v` with the part at `path` replaced by `new` (joined into every element at a dynamic step).
pub fn update(v: &Val, path: &[Step], new: Val) -> Val {
    let Some((first, rest)) = path.split_first() else { return new };
    match (v, first) {
        (Val::Agg(items), Step::Index(i)) => {
            let mut items = items.clone();
            if let Some(slot) = items.get_mut(*i as usize) {
                *slot = update(slot, rest, new);
            }
            Val::Agg(items)
        }
        (Val::Agg(items), Step::Dynamic) => Val::Agg(items.iter().map(|it| it.join(&update(it, rest, new.clone()))).collect()),
        (Val::Num(n), step) => match new.num() {
            Some(x) => Val::Num(ops::set_component(n, *step, x)),
            None => v.forget(),
        },
    }
}

/// A condition on the path proved `length(v)` or `dot(v, v)` positive, for the vector
/// whose value key is `k`.
fn length_proven_positive(state: &State, k: u64) -> bool {
    let len = math_key(naga::MathFunction::Length, k, None, None);
    let dot = math_key(naga::MathFunction::Dot, k, Some(k), None);
    [len, dot].iter().any(|key| state.refined.get(key).is_some_and(|r| r.gap > 0.0 || r.iv.lo > 0.0))
}
