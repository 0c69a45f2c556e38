//! Arithmetic and GLSL builtins on abstract values, and the hazards they can hit.
//!
//! Each operation returns a value containing every possible result, and the hazard its
//! operands make possible (if they are known). Vector facts follow the algebra: lengths
//! through the triangle inequality, Cauchy–Schwarz for `dot`, matrix gains for products.
//! [`math`] takes the builtins by family; the geometric ones (`dot`, `normalize`, …) live in
//! `geometric`.

use naga::{BinaryOperator as B, MathFunction as M, ScalarKind};

use super::geometric::geometric;
use super::interval::Iv;
use super::value::Num;
use super::walk::Step;

/// `sin`/`cos` arguments beyond this lose precision: one f32 ulp of 10⁴ is 10⁻³ rad, and
/// GPU range reduction degrades from there (the GL spec bounds the error only in [-π, π]).
pub const TRIG_LIMIT: f64 = 1.0e4;

/// `fract(sin(x) * K)` with `|K|` at least this keeps no reliable bits: sin's allowed
/// absolute error (2⁻¹¹ in GLSL and Vulkan) times K reaches 1/2.
pub const HASH_SCALE_LIMIT: f64 = 1024.0;

/// What an operation can do wrong.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    Division,
    Asin,
    Acos,
    Sqrt,
    Log,
    Pow,
    Normalize,
    InverseSqrt,
    Trig,
    /// Integer `%` with an operand that can be negative (undefined in GLSL).
    NegativeRemainder,
    /// A shift by an amount that can be negative or at least the width (undefined).
    Shift,
    /// `atan(y, x)` with both able to be 0 (undefined).
    Atan2,
}

pub struct Out {
    pub value: Num,
    pub hazard: Option<Kind>,
}

pub(super) fn ok(value: Num) -> Out {
    Out { value, hazard: None }
}

/// Applies `f` to every component.
pub fn map(n: &Num, f: impl Fn(Iv) -> Iv) -> Num {
    let mut r = Num::from_comps(n.c.iter().map(|&x| f(x)).collect(), n.cols, n.kind, n.known);
    r.per_draw = n.per_draw;
    r
}

fn zip(a: &Num, b: &Num, f: impl Fn(Iv, Iv) -> Iv) -> Num {
    let n = a.c.len().max(b.c.len());
    let get = |x: &Num, i: usize| x.c[if x.c.len() == 1 { 0 } else { i.min(x.c.len() - 1) }];
    let cols = if a.c.len() >= b.c.len() { a.cols } else { b.cols };
    let kind = if a.c.len() >= b.c.len() { a.kind } else { b.kind };
    let mut r = Num::from_comps((0..n).map(|i| f(get(a, i), get(b, i))).collect(), cols, kind, a.known && b.known);
    r.per_draw = a.per_draw && b.per_draw;
    r
}

pub fn negate(n: &Num) -> Num {
    let mut r = map(n, Iv::neg);
    r.len = n.len;
    r.len3 = n.len3;
    r.gap = n.gap;
    r.cone = n.cone;
    r.gain = n.gain;
    r
}

pub fn swizzle(n: &Num, pattern: &[naga::SwizzleComponent]) -> Num {
    let idx: Vec<usize> = pattern.iter().map(|p| *p as usize).collect();
    let mut r = Num::from_comps(idx.iter().map(|&i| n.c[i.min(n.c.len() - 1)]).collect(), 1, n.kind, n.known);
    r.per_draw = n.per_draw;
    if idx == [0, 1, 2] {
        r.len = r.len.meet(n.len3);
        r.len3 = r.len;
        r.cone = n.cone;
    }
    r
}

/// A component of a vector or a column of a matrix.
pub fn component(n: &Num, step: Step) -> Num {
    let rows = n.rows();
    let pick = |i: usize| -> Num {
        let c = if n.cols > 1 { n.c[i * rows..(i + 1) * rows].to_vec() } else { vec![n.c[i.min(n.c.len() - 1)]] };
        let mut r = Num::from_comps(c, 1, n.kind, n.known);
        r.per_draw = n.per_draw;
        r
    };
    let count = if n.cols > 1 { n.cols } else { n.c.len() };
    match step {
        Step::Index(i) if (i as usize) < count => pick(i as usize),
        _ => (1..count).fold(pick(0), |acc, i| acc.join(&pick(i))),
    }
}

/// `n` with one component (or matrix column) replaced.
pub fn set_component(n: &Num, step: Step, x: &Num) -> Num {
    let rows = n.rows();
    let mut c = n.c.clone();
    let width = if n.cols > 1 { rows } else { 1 };
    let count = c.len() / width;
    match step {
        Step::Index(i) if (i as usize) < count => {
            for k in 0..width {
                c[i as usize * width + k] = x.c[k.min(x.c.len() - 1)];
            }
        }
        _ => {
            for (j, slot) in c.iter_mut().enumerate() {
                *slot = slot.join(x.c[(j % width).min(x.c.len() - 1)]);
            }
        }
    }
    let mut r = Num::from_comps(c, n.cols, n.kind, n.known && x.known);
    r.per_draw = n.per_draw && x.per_draw;
    r
}

/// Integer results wrap: beyond the type's range anything in it is possible.
fn wrap(mut n: Num) -> Num {
    let range = match n.kind {
        ScalarKind::Sint => Iv::new(f64::from(i32::MIN), f64::from(i32::MAX)),
        ScalarKind::Uint => Iv::new(0.0, f64::from(u32::MAX)),
        _ => return n,
    };
    for c in n.c.iter_mut() {
        *c = Iv::new(c.lo.ceil(), c.hi.floor());
        if c.lo < range.lo || c.hi > range.hi {
            *c = range;
        }
    }
    n
}

pub fn binary(op: B, a: &Num, b: &Num, same: bool) -> Out {
    let int = matches!(a.kind, ScalarKind::Sint | ScalarKind::Uint);
    let value = match op {
        B::Add | B::Subtract => {
            let sub = op == B::Subtract;
            if same && sub && a.c.len() == b.c.len() {
                return ok(map(a, |_| Iv::point(0.0)));
            }
            let mut r = zip(a, b, |x, y| if sub { x.sub(y) } else { x.add(y) });
            if a.is_vector() && b.is_vector() {
                let lo = (a.len.lo - b.len.hi).max(b.len.lo - a.len.hi).max(0.0);
                r.len = r.len.meet(Iv::new(lo, a.len.hi + b.len.hi).rounded());
            }
            r
        }
        B::Multiply => multiply(a, b, same),
        B::Divide | B::Modulo => {
            let zero = b.c.iter().any(|x| x.contains(0.0)) && !(b.c.len() == 1 && b.gap > 0.0);
            // Negative within a bounded range: a value that may have wrapped around (a loop
            // counter the analysis cannot bound) spans the whole type and says nothing.
            let negative = |n: &Num| n.c.iter().any(|x| x.lo < 0.0 && bounded(*x));
            let signed_remainder = op == B::Modulo && a.kind == ScalarKind::Sint && (negative(a) || negative(b));
            let hazard = match (zero && b.known, signed_remainder && a.known && b.known) {
                (true, _) => Some(Kind::Division),
                (false, true) => Some(Kind::NegativeRemainder),
                _ => None,
            };
            let mut r = if op == B::Divide {
                zip(a, b, |x, y| divide(x, y, b.gap))
            } else {
                zip(a, b, |x, y| {
                    let m = y.mag();
                    if x.lo >= 0.0 {
                        Iv::new(0.0, m.min(x.hi.max(0.0)))
                    } else {
                        Iv::new(-m, m)
                    }
                })
            };
            if hazard.is_some() {
                r.known = false;
            }
            if a.is_vector() && b.c.len() == 1 && b.c[0].mig().max(b.gap) > 0.0 {
                let d = Iv::new(b.c[0].mig().max(b.gap), b.c[0].mag());
                r.len = r.len.meet(Iv::new(a.len.lo / d.hi, a.len.hi / d.lo).rounded());
                r.cone = a.cone && b.per_draw && b.c[0].lo > 0.0;
            }
            return Out { value: if int { wrap(r) } else { r }, hazard };
        }
        B::Equal | B::NotEqual | B::Less | B::LessEqual | B::Greater | B::GreaterEqual => {
            let mut r = zip(a, b, |x, y| compare(op, x, y));
            r.kind = ScalarKind::Bool;
            r
        }
        B::LogicalAnd | B::LogicalOr => {
            let mut r = zip(a, b, |x, y| {
                if op == B::LogicalAnd {
                    Iv::new(x.lo.min(y.lo), x.hi.min(y.hi))
                } else {
                    Iv::new(x.lo.max(y.lo), x.hi.max(y.hi))
                }
            });
            r.kind = ScalarKind::Bool;
            r
        }
        B::And | B::InclusiveOr | B::ExclusiveOr | B::ShiftLeft | B::ShiftRight => {
            let mut r = zip(a, b, |x, y| super::interval::bits(op, x, y, a.kind));
            if a.kind == ScalarKind::Bool {
                r = zip(a, b, |_, _| Iv::UNIT);
            }
            let shift = matches!(op, B::ShiftLeft | B::ShiftRight);
            if shift && b.known && b.c.iter().any(|y| bounded(*y) && (y.lo < 0.0 || y.hi >= 32.0)) {
                return Out { value: map(&r, |_| Iv::TOP), hazard: Some(Kind::Shift) };
            }
            r
        }
    };
    ok(if int { wrap(value) } else { value })
}

/// An integer interval narrower than the whole 32-bit range.
fn bounded(x: Iv) -> bool {
    x.lo > f64::from(i32::MIN) && x.hi < f64::from(u32::MAX)
}

fn divide(x: Iv, y: Iv, gap: f64) -> Iv {
    if !y.contains(0.0) {
        return x.div(y);
    }
    if gap > 0.0 {
        // y in [lo, -gap] ∪ [gap, hi].
        let mut r: Option<Iv> = None;
        if y.lo <= -gap {
            r = Some(x.div(Iv::new(y.lo, -gap)));
        }
        if y.hi >= gap {
            let q = x.div(Iv::new(gap, y.hi));
            r = Some(r.map_or(q, |p| p.join(q)));
        }
        return r.unwrap_or(Iv::TOP);
    }
    Iv::TOP
}

/// The comparison that holds when `op` evaluates to `truth`.
pub fn comparison(op: B, truth: bool) -> Option<B> {
    let flipped = match op {
        B::Less => B::GreaterEqual,
        B::LessEqual => B::Greater,
        B::Greater => B::LessEqual,
        B::GreaterEqual => B::Less,
        B::Equal => B::NotEqual,
        B::NotEqual => B::Equal,
        _ => return None,
    };
    Some(if truth { op } else { flipped })
}

/// `a op b` seen from `b`.
pub fn mirror(op: B) -> B {
    match op {
        B::Less => B::Greater,
        B::LessEqual => B::GreaterEqual,
        B::Greater => B::Less,
        B::GreaterEqual => B::LessEqual,
        other => other,
    }
}

/// Whether the ordering or equality `a op b` is false for every `a` and `b` in the
/// intervals (what [`compare`] folds to 0).
pub fn never(op: B, a: Iv, b: Iv) -> bool {
    matches!(op, B::Less | B::LessEqual | B::Greater | B::GreaterEqual | B::Equal) && compare(op, a, b) == Iv::point(0.0)
}

fn compare(op: B, x: Iv, y: Iv) -> Iv {
    let (always, never) = match op {
        B::Less => (x.hi < y.lo, x.lo >= y.hi),
        B::LessEqual => (x.hi <= y.lo, x.lo > y.hi),
        B::Greater => (x.lo > y.hi, x.hi <= y.lo),
        B::GreaterEqual => (x.lo >= y.hi, x.hi < y.lo),
        B::Equal => (x.is_point() && x == y, x.hi < y.lo || y.hi < x.lo),
        _ => (x.hi < y.lo || y.hi < x.lo, x.is_point() && x == y),
    };
    if always {
        Iv::point(1.0)
    } else if never {
        Iv::point(0.0)
    } else {
        Iv::UNIT
    }
}

fn multiply(a: &Num, b: &Num, same: bool) -> Num {
    let (ma, mb) = (a.cols > 1, b.cols > 1);
    if same && !ma && !mb && a.c.len() == b.c.len() {
        let mut r = map(a, Iv::square);
        r.per_draw = a.per_draw;
        return r;
    }
    if ma && !mb && b.c.len() == a.cols {
        return mat_vec(a, b);
    }
    if !ma && mb && a.c.len() == b.rows() {
        return vec_mat(a, b);
    }
    if ma && mb {
        return mat_mat(a, b);
    }
    // Scalar × vector/matrix, or component-wise.
    let mut r = zip(a, b, |x, y| x.mul(y));
    let (s, v) = if a.c.len() == 1 { (a, b) } else { (b, a) };
    if s.c.len() == 1 && v.c.len() > 1 {
        let f = Iv::new(s.c[0].mig().max(s.gap), s.c[0].mag());
        if v.cols == 1 {
            r.len = r.len.meet(Iv::new(v.len.lo * f.lo, v.len.hi * f.hi).rounded());
            r.len3 = r.len3.meet(Iv::new(v.len3.lo * f.lo, v.len3.hi * f.hi).rounded());
            r.cone = v.cone && s.per_draw && f.lo > 0.0;
        } else {
            r.gain = Iv::new(v.gain.lo * f.lo, v.gain.hi * f.hi);
        }
    }
    r
}

fn mat_vec(m: &Num, v: &Num) -> Num {
    let rows = m.rows();
    let comps = (0..rows).map(|r| (0..m.cols).fold(Iv::point(0.0), |acc, col| acc.add(m.c[col * rows + r].mul(v.c[col])))).collect();
    let mut out = Num::from_comps(comps, 1, m.kind, m.known && v.known);
    out.per_draw = m.per_draw && v.per_draw;
    let gain = Iv::new(m.gain.lo, m.gain.hi);
    let linear3 = rows >= 3 && m.cols >= 3;
    if linear3 && (v.c.len() == 3 || (v.c.len() == 4 && v.c[3] == Iv::point(0.0))) {
        let l = Iv::new(v.len3.lo * gain.lo, v.len3.hi * gain.hi).rounded();
        out.len3 = out.len3.meet(l);
        if rows == 3 {
            out.len = out.len.meet(l);
        }
        out.cone = v.cone && m.per_draw && gain.lo > 0.0;
    }
    out
}

fn vec_mat(v: &Num, m: &Num) -> Num {
    let rows = m.rows();
    let comps = (0..m.cols).map(|col| (0..rows).fold(Iv::point(0.0), |acc, r| acc.add(v.c[r].mul(m.c[col * rows + r])))).collect();
    let mut out = Num::from_comps(comps, 1, m.kind, m.known && v.known);
    out.per_draw = m.per_draw && v.per_draw;
    if rows == 3 && m.cols == 3 {
        out.len = out.len.meet(Iv::new(v.len.lo * m.gain.lo, v.len.hi * m.gain.hi).rounded());
        out.cone = v.cone && m.per_draw && m.gain.lo > 0.0;
    }
    out
}

fn mat_mat(a: &Num, b: &Num) -> Num {
    let (ar, br) = (a.rows(), b.rows());
    let mut comps = Vec::new();
    for col in 0..b.cols {
        for r in 0..ar {
            comps.push((0..a.cols).fold(Iv::point(0.0), |acc, k| acc.add(a.c[k * ar + r].mul(b.c[col * br + k.min(br - 1)]))));
        }
    }
    let mut out = Num::from_comps(comps, b.cols, a.kind, a.known && b.known);
    out.per_draw = a.per_draw && b.per_draw;
    // The upper-left 3x3 of a product is the product of the 3x3s when b's last row is
    // (0, 0, 0, 1) on those columns (affine b) or both are 3x3.
    let affine = br == 3 || (br == 4 && (0..3).all(|col| b.c[col * 4 + 3] == Iv::point(0.0)));
    if affine {
        out.gain = out.gain.meet(Iv::new(a.gain.lo * b.gain.lo, a.gain.hi * b.gain.hi));
    }
    out
}

pub fn cast(n: &Num, kind: ScalarKind, convert: Option<u8>) -> Num {
    if convert.is_none() {
        // Bit reinterpretation: nothing known about the value.
        return Num { known: n.known, ..Num::unknown(n.c.len(), n.cols, kind) };
    }
    let mut r = match kind {
        ScalarKind::Sint | ScalarKind::Uint => wrap(Num { kind, ..map(n, Iv::floor_toward_zero) }),
        ScalarKind::Bool => map(n, |x| {
            if x == Iv::point(0.0) {
                Iv::point(0.0)
            } else if !x.contains(0.0) {
                Iv::point(1.0)
            } else {
                Iv::UNIT
            }
        }),
        _ => map(n, |x| x),
    };
    r.kind = kind;
    r.per_draw = n.per_draw;
    r.len = r.len.meet(n.len);
    r.len3 = r.len3.meet(n.len3);
    r.cone = n.cone;
    r
}

impl Iv {
    fn floor_toward_zero(self) -> Iv {
        Iv::new(self.lo.trunc(), self.hi.trunc())
    }
}

/// A GLSL builtin. `same`: the two arguments are the same value; `nonzero`: a guard proved
/// the argument of `normalize` non-zero. Builtins the analysis does not model give unknown values.
pub fn math(fun: M, a: &Num, b: Option<&Num>, d: Option<&Num>, same: bool, nonzero: bool) -> Out {
    common(fun, a, b, d)
        .or_else(|| trigonometric(fun, a, b))
        .or_else(|| exponential(fun, a, b))
        .or_else(|| geometric(fun, a, b, d, same, nonzero))
        .or_else(|| matrix(fun, a, b))
        .unwrap_or_else(|| ok(Num { known: false, ..Num::unknown(a.c.len(), a.cols, a.kind) }))
}

/// An optional argument as a value: when it is absent, a float nothing is known about.
pub(super) fn or_unknown(x: Option<&Num>) -> Num {
    x.cloned().unwrap_or_else(|| Num::unknown(1, 1, ScalarKind::Float))
}

/// `kind` when `cond` holds and the argument `a` is known.
pub(super) fn hazard_if(a: &Num, cond: bool, kind: Kind) -> Option<Kind> {
    (cond && a.known).then_some(kind)
}

/// Common functions (abs, min, max, clamp, rounding, mix, step…); `None` for other builtins.
fn common(fun: M, a: &Num, b: Option<&Num>, d: Option<&Num>) -> Option<Out> {
    let value = match fun {
        M::Abs => {
            let mut r = map(a, Iv::abs);
            r.len = a.len;
            r.gap = a.gap;
            r
        }
        M::Min => zip(a, &or_unknown(b), Iv::min),
        M::Max => zip(a, &or_unknown(b), Iv::max),
        M::Clamp => {
            let lo = or_unknown(b);
            let hi = or_unknown(d);
            let r = zip(a, &lo, Iv::max);
            zip(&r, &hi, Iv::min)
        }
        M::Saturate => map(a, |x| x.clamp(Iv::point(0.0), Iv::point(1.0))),
        M::Ceil => map(a, Iv::ceil),
        M::Floor => map(a, Iv::floor),
        M::Round => map(a, |x| Iv::new(x.lo.round(), x.hi.round())),
        M::Trunc => map(a, Iv::floor_toward_zero),
        M::Fract => map(a, Iv::fract),
        M::Sign => map(a, Iv::sign),
        M::Fma => {
            let m = zip(a, &or_unknown(b), |x, y| x.mul(y));
            zip(&m, &or_unknown(d), |x, y| x.add(y))
        }
        M::Mix => {
            let y = or_unknown(b);
            let t = or_unknown(d);
            let n = a.c.len();
            let get = |v: &Num, i: usize| v.c[i.min(v.c.len() - 1)];
            let comps = (0..n).map(|i| Iv::mix(get(a, i), get(&y, i), get(&t, i))).collect();
            let mut r = Num::from_comps(comps, 1, a.kind, a.known && y.known && t.known);
            r.per_draw = a.per_draw && y.per_draw && t.per_draw;
            r
        }
        M::Step => zip(&or_unknown(b), a, |_, _| Iv::UNIT),
        M::SmoothStep => map(d.unwrap_or(a), |_| Iv::UNIT),
        _ => return None,
    };
    Some(ok(value))
}

/// Angle and trigonometric functions; `None` for other builtins.
fn trigonometric(fun: M, a: &Num, b: Option<&Num>) -> Option<Out> {
    use std::f64::consts::{FRAC_PI_2, PI};
    let value = match fun {
        M::Sin | M::Cos => {
            let big = a.c.iter().any(|x| x.mag() > TRIG_LIMIT);
            let f = if fun == M::Sin { Iv::sin } else { Iv::cos };
            return Some(Out { value: map(a, f), hazard: hazard_if(a, big, Kind::Trig) });
        }
        M::Tan => {
            let big = a.c.iter().any(|x| x.mag() > TRIG_LIMIT);
            let r = map(a, |x| if x.lo > -FRAC_PI_2 && x.hi < FRAC_PI_2 { x.monotone(f64::tan) } else { Iv::TOP });
            return Some(Out { value: r, hazard: hazard_if(a, big, Kind::Trig) });
        }
        M::Asin | M::Acos => {
            let outside = a.c.iter().any(|x| x.lo < -1.0 || x.hi > 1.0);
            let r = if fun == M::Asin {
                map(a, |x| x.meet(Iv::SIGNED_UNIT).monotone(f64::asin))
            } else {
                map(a, |x| {
                    let x = x.meet(Iv::SIGNED_UNIT);
                    Iv::new(x.hi.acos(), x.lo.acos())
                })
            };
            let kind = if fun == M::Asin { Kind::Asin } else { Kind::Acos };
            return Some(Out { value: r, hazard: hazard_if(a, outside, kind) });
        }
        M::Atan => map(a, |x| x.monotone(f64::atan)),
        M::Atan2 => {
            // Some component where y and x can both be 0.
            let both_zero = b.is_some_and(|x| a.c.iter().zip(&x.c).any(|(y, x)| y.contains(0.0) && x.contains(0.0)));
            let known = b.is_some_and(|x| a.known && x.known);
            return Some(Out { value: map(a, |_| Iv::new(-PI, PI)), hazard: (both_zero && known).then_some(Kind::Atan2) });
        }
        M::Sinh | M::Cosh | M::Asinh | M::Acosh | M::Atanh | M::Tanh => {
            map(a, |x| if fun == M::Tanh { x.monotone(f64::tanh) } else { Iv::TOP })
        }
        M::Radians => map(a, |x| x.mul(Iv::point(PI / 180.0))),
        M::Degrees => map(a, |x| x.mul(Iv::point(180.0 / PI))),
        _ => return None,
    };
    Some(ok(value))
}

/// Exponential functions (exp, log, pow, sqrt, inversesqrt); `None` for other builtins.
fn exponential(fun: M, a: &Num, b: Option<&Num>) -> Option<Out> {
    let value = match fun {
        M::Exp => map(a, |x| x.monotone(f64::exp)),
        M::Exp2 => map(a, |x| x.monotone(f64::exp2)),
        M::Log | M::Log2 => {
            let bad = a.c.iter().any(|x| x.lo <= 0.0) && !(a.c.len() == 1 && a.gap > 0.0 && a.c[0].lo >= 0.0);
            let f = if fun == M::Log { f64::ln } else { f64::log2 };
            let r = map(a, |x| if x.lo > 0.0 { x.monotone(f) } else { Iv::new(f64::NEG_INFINITY, f(x.hi.max(0.0))) });
            return Some(Out { value: taint(r, bad && a.known), hazard: hazard_if(a, bad, Kind::Log) });
        }
        M::Pow => {
            let e = or_unknown(b);
            let negative = a.c.iter().any(|x| x.lo < 0.0);
            let zero_to_nonpositive =
                a.c.iter().zip(e.c.iter().cycle()).any(|(x, y)| x.contains(0.0) && y.lo <= 0.0) && !(a.c.len() == 1 && a.gap > 0.0);
            let r = zip(a, &e, |x, y| x.pow(y));
            let bad = negative || zero_to_nonpositive;
            return Some(Out { value: r, hazard: (bad && a.known && e.known).then_some(Kind::Pow) });
        }
        M::Sqrt => {
            let bad = a.c.iter().any(|x| x.lo < 0.0);
            return Some(Out { value: map(a, Iv::sqrt), hazard: hazard_if(a, bad, Kind::Sqrt) });
        }
        M::InverseSqrt => {
            let bad = a.c.iter().any(|x| x.lo <= 0.0) && !(a.c.len() == 1 && a.gap > 0.0 && a.c[0].lo >= 0.0);
            let r = map(a, |x| if x.lo > 0.0 { Iv::new(1.0 / x.hi.sqrt(), 1.0 / x.lo.sqrt()).rounded() } else { Iv::NON_NEGATIVE });
            return Some(Out { value: taint(r, bad && a.known), hazard: hazard_if(a, bad, Kind::InverseSqrt) });
        }
        _ => return None,
    };
    Some(ok(value))
}

/// Matrix functions (transpose, inverse, determinant, outer product); `None` for other builtins.
fn matrix(fun: M, a: &Num, b: Option<&Num>) -> Option<Out> {
    let value = match fun {
        M::Transpose => {
            let rows = a.rows();
            let mut comps = Vec::with_capacity(a.c.len());
            for r in 0..rows {
                for col in 0..a.cols {
                    comps.push(a.c[col * rows + r]);
                }
            }
            let mut t = Num::from_comps(comps, rows, a.kind, a.known);
            t.gain = a.gain;
            t.per_draw = a.per_draw;
            t
        }
        M::Inverse => {
            let rows = a.rows();
            let mut r = Num { known: a.known, ..Num::unknown(a.c.len(), a.cols, a.kind) };
            r.per_draw = a.per_draw;
            // An affine 4x4 (last row 0 0 0 1) inverts its upper-left 3x3.
            let affine = a.cols == 4 && rows == 4 && (0..3).all(|col| a.c[col * 4 + 3] == Iv::point(0.0)) && a.c[15] == Iv::point(1.0);
            if a.gain.lo > 0.0 && (a.cols == 3 && rows == 3 || affine) {
                let b = 1.0 / a.gain.lo;
                for col in 0..3 {
                    for row in 0..3 {
                        r.c[col * rows + row] = Iv::new(-b, b);
                    }
                }
                if affine {
                    for col in 0..3 {
                        r.c[col * 4 + 3] = Iv::point(0.0);
                    }
                    r.c[15] = Iv::point(1.0);
                }
                r.gain = Iv::new(1.0 / a.gain.hi, b);
            }
            r
        }
        M::Determinant => Num { known: a.known, ..Num::unknown(1, 1, a.kind) },
        M::Outer => Num { known: a.known, ..Num::unknown(a.c.len() * or_unknown(b).c.len(), or_unknown(b).c.len(), a.kind) },
        _ => return None,
    };
    Some(ok(value))
}

/// After a hazard whose result is unbounded (log, inversesqrt) the result is no longer
/// known: no cascade of reports. Bounded results (asin, sqrt, normalize) stay known.
fn taint(mut n: Num, hazard: bool) -> Num {
    if hazard {
        n.known = false;
    }
    n
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit_vector() -> Num {
        let mut n = Num::from_comps(vec![Iv::SIGNED_UNIT; 3], 1, ScalarKind::Float, true);
        n.len = Iv::new(1.0 - 1e-6, 1.0 + 1e-6);
        n
    }

    #[test]
    fn asin_of_unit_dot_scaled_is_safe_but_unscaled_is_not() {
        let d = math(M::Dot, &unit_vector(), Some(&unit_vector()), None, false, false).value;
        let scaled = binary(B::Divide, &d, &Num::float(Iv::point(1.55)), false).value;
        assert!(math(M::Asin, &scaled, None, None, false, false).hazard.is_none());
        assert_eq!(math(M::Asin, &d, None, None, false, false).hazard, Some(Kind::Asin));
    }

    #[test]
    fn division_guards() {
        let x = Num::float(Iv::new(0.0, 2.0));
        assert_eq!(binary(B::Divide, &Num::float(Iv::point(1.0)), &x, false).hazard, Some(Kind::Division));
        let guarded = math(M::Max, &x, Some(&Num::float(Iv::point(1e-3))), None, false, false).value;
        assert!(binary(B::Divide, &Num::float(Iv::point(1.0)), &guarded, false).hazard.is_none());
        let mut gapped = Num::float(Iv::new(-2.0, 2.0));
        gapped.gap = 1e-4;
        let q = binary(B::Divide, &Num::float(Iv::point(1.0)), &gapped, false);
        assert!(q.hazard.is_none() && q.value.c[0].mag() <= 1.0e4 * 1.001);
    }

    #[test]
    fn normalize_needs_a_nonzero_length() {
        let grid = Num::from_comps(vec![Iv::SIGNED_UNIT, Iv::SIGNED_UNIT, Iv::new(0.2, 1.0)], 1, ScalarKind::Float, true);
        assert!(math(M::Normalize, &grid, None, None, false, false).hazard.is_none());
        let any = Num::from_comps(vec![Iv::SIGNED_UNIT; 3], 1, ScalarKind::Float, true);
        assert_eq!(math(M::Normalize, &any, None, None, false, false).hazard, Some(Kind::Normalize));
        assert!(math(M::Normalize, &any, None, None, false, true).hazard.is_none());
    }

    #[test]
    fn sqrt_of_one_minus_square() {
        let x = Num::float(Iv::new(-0.5, 0.5));
        let sq = binary(B::Multiply, &x, &x, true).value;
        let d = binary(B::Subtract, &Num::float(Iv::point(1.0)), &sq, false).value;
        assert!(math(M::Sqrt, &d, None, None, false, false).hazard.is_none());
        let wide = Num::float(Iv::new(-2.0, 2.0));
        let sq = binary(B::Multiply, &wide, &wide, true).value;
        let d = binary(B::Subtract, &Num::float(Iv::point(1.0)), &sq, false).value;
        assert_eq!(math(M::Sqrt, &d, None, None, false, false).hazard, Some(Kind::Sqrt));
    }

    #[test]
    fn unknown_inputs_raise_nothing() {
        let u = Num::unknown(1, 1, ScalarKind::Float);
        assert!(math(M::Sqrt, &u, None, None, false, false).hazard.is_none());
        assert!(binary(B::Divide, &Num::float(Iv::point(1.0)), &u, false).hazard.is_none());
    }
}
