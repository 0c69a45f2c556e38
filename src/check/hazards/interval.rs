//! Closed intervals of reals with outward-safe arithmetic, the numbers of the hazard analysis.
//!
//! Bounds are `f64` and may be infinite; an interval is never empty and never holds NaN
//! bounds (a result that would be NaN widens to the whole line). Each operation returns an
//! interval containing every result of the operation on members of its operands; f32
//! rounding is covered by widening results by a relative 2⁻²⁰ ([`Iv::rounded`]).

/// `[lo, hi]`, `lo <= hi`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Iv {
    pub lo: f64,
    pub hi: f64,
}

/// Relative slack for f32 rounding of one operation (generous: f32 has 2⁻²⁴).
const SLACK: f64 = 1.0 / (1u64 << 20) as f64;

// Named methods rather than `std::ops` traits: every operation rounds outward, and the
// names read as the interval operations they are (`Iv::add` in folds).
#[allow(clippy::should_implement_trait)]
impl Iv {
    pub const TOP: Iv = Iv { lo: f64::NEG_INFINITY, hi: f64::INFINITY };
    pub const UNIT: Iv = Iv { lo: 0.0, hi: 1.0 };
    pub const SIGNED_UNIT: Iv = Iv { lo: -1.0, hi: 1.0 };
    pub const NON_NEGATIVE: Iv = Iv { lo: 0.0, hi: f64::INFINITY };

    pub fn new(lo: f64, hi: f64) -> Iv {
        if lo.is_nan() || hi.is_nan() {
            return Iv::TOP;
        }
        Iv { lo: lo.min(hi), hi: lo.max(hi) }
    }
    pub fn point(x: f64) -> Iv {
        Iv::new(x, x)
    }
    pub fn contains(self, x: f64) -> bool {
        self.lo <= x && x <= self.hi
    }
    pub fn is_point(self) -> bool {
        self.lo == self.hi
    }
    /// Largest magnitude of a member.
    pub fn mag(self) -> f64 {
        self.lo.abs().max(self.hi.abs())
    }
    /// Smallest magnitude of a member (0 when the interval holds 0).
    pub fn mig(self) -> f64 {
        if self.contains(0.0) {
            0.0
        } else {
            self.lo.abs().min(self.hi.abs())
        }
    }
    pub fn is_finite(self) -> bool {
        self.lo.is_finite() && self.hi.is_finite()
    }
    pub fn join(self, o: Iv) -> Iv {
        Iv { lo: self.lo.min(o.lo), hi: self.hi.max(o.hi) }
    }
    /// The intersection, or `self` when they do not meet (facts that disagree are ignored
    /// rather than producing an empty interval).
    pub fn meet(self, o: Iv) -> Iv {
        let lo = self.lo.max(o.lo);
        let hi = self.hi.min(o.hi);
        if lo <= hi {
            Iv { lo, hi }
        } else {
            self
        }
    }
    /// Widened for f32 rounding of the operation that produced it.
    pub fn rounded(self) -> Iv {
        let pad = |x: f64| x.abs() * SLACK;
        Iv::new(self.lo - pad(self.lo), self.hi + pad(self.hi))
    }

    pub fn neg(self) -> Iv {
        Iv { lo: -self.hi, hi: -self.lo }
    }
    pub fn add(self, o: Iv) -> Iv {
        Iv::new(self.lo + o.lo, self.hi + o.hi).rounded()
    }
    pub fn sub(self, o: Iv) -> Iv {
        self.add(o.neg())
    }
    pub fn mul(self, o: Iv) -> Iv {
        let products = [mul0(self.lo, o.lo), mul0(self.lo, o.hi), mul0(self.hi, o.lo), mul0(self.hi, o.hi)];
        hull(&products).rounded()
    }
    /// `self * self` for one value (never negative), tighter than `mul`.
    pub fn square(self) -> Iv {
        let m = self.mig();
        let big = self.mag();
        Iv::new(m * m, big * big).rounded()
    }
    /// Quotient; the whole line when the divisor holds zero.
    pub fn div(self, o: Iv) -> Iv {
        if o.contains(0.0) {
            return Iv::TOP;
        }
        let inv = Iv::new(1.0 / o.hi, 1.0 / o.lo);
        self.mul(inv)
    }
    pub fn abs(self) -> Iv {
        Iv::new(self.mig(), self.mag())
    }
    pub fn min(self, o: Iv) -> Iv {
        Iv::new(self.lo.min(o.lo), self.hi.min(o.hi))
    }
    pub fn max(self, o: Iv) -> Iv {
        Iv::new(self.lo.max(o.lo), self.hi.max(o.hi))
    }
    pub fn clamp(self, lo: Iv, hi: Iv) -> Iv {
        self.max(lo).min(hi)
    }
    /// Applies a function that does not decrease.
    pub fn monotone(self, f: impl Fn(f64) -> f64) -> Iv {
        Iv::new(f(self.lo), f(self.hi)).rounded()
    }
    pub fn sqrt(self) -> Iv {
        Iv::new(self.lo.max(0.0).sqrt(), self.hi.max(0.0).sqrt()).rounded()
    }
    pub fn floor(self) -> Iv {
        Iv::new(self.lo.floor(), self.hi.floor())
    }
    pub fn ceil(self) -> Iv {
        Iv::new(self.lo.ceil(), self.hi.ceil())
    }
    /// `x - floor(x)`: `[0, 1)`, or exact when `x` stays within one unit step.
    pub fn fract(self) -> Iv {
        if self.is_finite() && self.lo.floor() == self.hi.floor() {
            Iv::new(self.lo - self.lo.floor(), self.hi - self.hi.floor())
        } else {
            Iv::UNIT
        }
    }
    /// `sin`: exact where the interval covers no extremum, `[-1, 1]` otherwise.
    pub fn sin(self) -> Iv {
        periodic(self, f64::sin, std::f64::consts::FRAC_PI_2)
    }
    pub fn cos(self) -> Iv {
        periodic(self, f64::cos, 0.0)
    }
    /// `sign(x)`.
    pub fn sign(self) -> Iv {
        Iv::new(self.lo.signum_or_zero(), self.hi.signum_or_zero())
    }
    /// `mix(a, b, t) = a + (b - a) t`, bounded also by the hull of `a` and `b` for t in [0, 1].
    pub fn mix(a: Iv, b: Iv, t: Iv) -> Iv {
        let general = a.add(b.sub(a).mul(t));
        if t.lo >= 0.0 && t.hi <= 1.0 {
            general.meet(a.join(b).rounded())
        } else {
            general
        }
    }
    /// `pow(x, y)` for `x >= 0` (the part of `x` below 0 is the caller's hazard).
    pub fn pow(self, y: Iv) -> Iv {
        let x = Iv::new(self.lo.max(0.0), self.hi.max(0.0));
        let corners = [x.lo.powf(y.lo), x.lo.powf(y.hi), x.hi.powf(y.lo), x.hi.powf(y.hi)];
        let mut r = hull(&corners);
        // pow is monotone in each argument on x > 0 except around x = 1 in y; include 1.
        if x.contains(1.0) {
            r = r.join(Iv::point(1.0));
        }
        if x.lo == 0.0 && y.contains(0.0) {
            r = r.join(Iv::point(1.0));
        }
        r.rounded()
    }
}

/// An integer bit operation (`&`, `|`, `^`, `<<`, `>>`) on intervals of `kind`.
pub fn bits(op: naga::BinaryOperator, x: Iv, y: Iv, kind: naga::ScalarKind) -> Iv {
    use naga::{BinaryOperator as B, ScalarKind};
    let full = if kind == ScalarKind::Uint { Iv::new(0.0, f64::from(u32::MAX)) } else { Iv::new(f64::from(i32::MIN), f64::from(i32::MAX)) };
    if let (Some(a), Some(b)) = (whole(x), whole(y)) {
        // Two known integers: the exact result, in the type's 32 bits.
        let exact = match (op, kind == ScalarKind::Uint) {
            (B::And, _) => Some(a & b),
            (B::InclusiveOr, _) => Some(a | b),
            (B::ExclusiveOr, _) => Some(a ^ b),
            (B::ShiftLeft, _) if (0..32).contains(&b) => Some(((a as u32) << b) as i64),
            (B::ShiftRight, true) if (0..32).contains(&b) => Some(((a as u32) >> b) as i64),
            (B::ShiftRight, false) if (0..32).contains(&b) => Some(((a as i32) >> b) as i64),
            _ => None,
        };
        if let Some(r) = exact {
            let r = if kind == ScalarKind::Uint { f64::from(r as u32) } else { f64::from(r as i32) };
            return Iv::point(r);
        }
    }
    if x.lo < 0.0 || y.lo < 0.0 {
        return full;
    }
    match op {
        B::And => Iv::new(0.0, x.hi.min(y.hi)),
        B::InclusiveOr | B::ExclusiveOr => {
            let m = x.hi.max(y.hi);
            Iv::new(0.0, (2f64).powf((m + 1.0).log2().ceil()) - 1.0)
        }
        B::ShiftRight => Iv::new(0.0, x.hi),
        _ => full,
    }
}

/// The integer a point interval holds (within 32 bits).
fn whole(x: Iv) -> Option<i64> {
    let v = x.lo.round();
    (x.lo >= -2_147_483_648.0 && x.hi <= 4_294_967_295.0 && (x.lo - v).abs() < 1e-3 && (x.hi - v).abs() < 1e-3).then_some(v as i64)
}

trait SignumOrZero {
    fn signum_or_zero(self) -> f64;
}
impl SignumOrZero for f64 {
    fn signum_or_zero(self) -> f64 {
        if self == 0.0 {
            0.0
        } else {
            self.signum()
        }
    }
}

/// `0 * ∞ = 0` for interval bounds (a zero factor is exactly zero).
fn mul0(a: f64, b: f64) -> f64 {
    if a == 0.0 || b == 0.0 {
        0.0
    } else {
        a * b
    }
}

fn hull(xs: &[f64]) -> Iv {
    if xs.iter().any(|x| x.is_nan()) {
        return Iv::TOP;
    }
    let lo = xs.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = xs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    Iv::new(lo, hi)
}

/// A 2π-periodic function with a maximum at `peak` (mod 2π) and a minimum half a turn later.
fn periodic(x: Iv, f: fn(f64) -> f64, peak: f64) -> Iv {
    use std::f64::consts::PI;
    if !x.is_finite() || x.hi - x.lo >= 2.0 * PI {
        return Iv::SIGNED_UNIT;
    }
    let mut r = Iv::new(f(x.lo), f(x.hi));
    // Is there an extremum `peak + k π` inside?
    let first = ((x.lo - peak) / PI).ceil();
    let mut k = first;
    while peak + k * PI <= x.hi {
        let at = peak + k * PI;
        r = r.join(Iv::point(f(at)));
        k += 1.0;
    }
    Iv::new((r.lo - 1e-7).max(-1.0), (r.hi + 1e-7).min(1.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arithmetic_contains_every_result() {
        let a = Iv::new(-2.0, 3.0);
        let b = Iv::new(0.5, 4.0);
        let p = a.mul(b);
        assert!(p.contains(-8.0) && p.contains(12.0) && p.lo >= -8.001 && p.hi <= 12.001);
        let q = a.div(b);
        assert!(q.contains(-4.0) && q.contains(6.0));
        assert_eq!(a.div(Iv::new(-1.0, 1.0)), Iv::TOP);
        assert!(Iv::new(-3.0, 2.0).square().lo == 0.0);
        assert!(Iv::new(2.0, 3.0).square().contains(9.0));
    }

    #[test]
    fn trig_is_tight_between_extrema() {
        let s = Iv::new(0.0, 0.5).sin();
        assert!(s.lo >= -1e-6 && s.hi < 0.48 + 1e-6);
        let s = Iv::new(0.0, 2.0).sin();
        assert!((s.hi - 1.0).abs() < 1e-9);
        let c = Iv::new(-0.1, 0.1).cos();
        assert!(c.lo > 0.99 && c.hi <= 1.0);
        assert_eq!(Iv::new(0.0, 100.0).sin(), Iv::SIGNED_UNIT);
    }

    #[test]
    fn mix_and_fract() {
        let m = Iv::mix(Iv::point(1.0), Iv::point(3.0), Iv::UNIT);
        assert!(m.lo >= 0.999 && m.hi <= 3.001);
        assert_eq!(Iv::new(2.25, 2.5).fract(), Iv::new(0.25, 0.5));
        assert_eq!(Iv::new(2.25, 3.5).fract(), Iv::UNIT);
    }
}
