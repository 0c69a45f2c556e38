//! How sure a finding is. The interval analysis finds what *can* go wrong over the ranges
//! it assumes: a **possible** hazard. A witness run ([`super::witness`]) that shows the
//! operation going wrong for every value its operands can take, at a point every execution
//! reaches, makes it **certain**: it happens at the inputs that run fixed.

use naga::{Expression, Handle};

use super::interval::Iv;
use super::ops::{self, Kind};
use super::value::Num;
use super::walk::{Analyzer, Call, State};
use super::Hazard;

/// A value no larger than this that is not an exact point is zero up to the rounding slack
/// of the operations that made it (`0.5 - 0.5 * cos(0.0)`).
const ROUNDED_ZERO: f64 = 1e-6;

/// A `sin`/`cos` argument whose own f32 rounding (2⁻⁸ rad from 2¹⁵ on) exceeds one step of
/// an 8-bit result: the loss is certain to show. Below it (from [`super::ops::TRIG_LIMIT`],
/// where GPUs stop guaranteeing accuracy) it is possible only.
const VISIBLE_TRIG: f64 = 32_768.0;

/// Zero, exactly or up to rounding.
fn zero(x: Iv) -> bool {
    if x.is_point() {
        x.lo == 0.0
    } else {
        x.mag() <= ROUNDED_ZERO
    }
}

/// Below zero by more than rounding.
fn negative(x: Iv) -> bool {
    x.hi < 0.0 && !zero(x)
}

/// Whether every value the operands can take hits hazard `kind`: `a` and `b` as
/// [`super::Hazard::new`] takes them (a division's divisor; `pow`'s base and exponent;
/// `atan`'s y and x; a remainder's operands; a shift's amount).
pub fn certain(kind: Kind, a: &Num, b: Option<&Num>) -> bool {
    let paired = |i: usize| b.and_then(|n| n.c.get(i).or(n.c.first())).copied();
    match kind {
        Kind::Division => a.c.iter().any(|&x| zero(x)),
        Kind::Asin | Kind::Acos => a.c.iter().any(|x| x.mig() > 1.0 + ROUNDED_ZERO),
        Kind::Sqrt => a.c.iter().any(|&x| negative(x)),
        Kind::Log | Kind::InverseSqrt => a.c.iter().any(|&x| negative(x) || zero(x)),
        Kind::Pow => a.c.iter().enumerate().any(|(i, &x)| negative(x) || (zero(x) && paired(i).is_some_and(|y| y.hi <= 0.0))),
        Kind::Normalize => a.c.iter().all(|&x| zero(x)),
        Kind::Trig => a.c.iter().any(|x| x.mig() >= VISIBLE_TRIG),
        Kind::NegativeRemainder => a.c.iter().chain(b.map_or(&[][..], |n| &n.c[..])).any(|x| x.hi < 0.0),
        Kind::Shift => a.c.iter().any(|x| x.hi < 0.0 || x.lo >= 32.0),
        Kind::Atan2 => a.c.iter().enumerate().any(|(i, &y)| zero(y) && paired(i).is_some_and(zero)),
    }
}

/// Whether some values the operands can take would make `kind` certain: a witness run,
/// whose operands lie inside these, can show it.
pub fn witnessable(kind: Kind, a: &Num, b: Option<&Num>) -> bool {
    let near_zero = |x: Iv| x.lo <= ROUNDED_ZERO && x.hi >= -ROUNDED_ZERO;
    let below = |x: Iv| x.lo < -ROUNDED_ZERO;
    let paired = |i: usize| b.and_then(|n| n.c.get(i).or(n.c.first())).copied();
    match kind {
        Kind::Division => a.c.iter().any(|&x| near_zero(x)),
        Kind::Asin | Kind::Acos => a.c.iter().any(|x| x.mag() > 1.0 + ROUNDED_ZERO),
        Kind::Sqrt => a.c.iter().any(|&x| below(x)),
        Kind::Log | Kind::InverseSqrt => a.c.iter().any(|&x| below(x) || near_zero(x)),
        Kind::Pow => a.c.iter().enumerate().any(|(i, &x)| below(x) || (near_zero(x) && paired(i).is_some_and(|y| y.lo <= 0.0))),
        Kind::Normalize => a.c.iter().all(|&x| near_zero(x)),
        Kind::Trig => a.c.iter().any(|x| x.mag() >= VISIBLE_TRIG),
        Kind::NegativeRemainder => a.c.iter().chain(b.map_or(&[][..], |n| &n.c[..])).any(|x| x.lo < 0.0),
        Kind::Shift => a.c.iter().any(|x| x.lo < 0.0 || x.hi >= 32.0),
        Kind::Atan2 => a.c.iter().enumerate().any(|(i, &y)| near_zero(y) && paired(i).is_some_and(near_zero)),
    }
}

/// A `fract(sin(x) * K)` hash whose argument surely lies where sin itself visibly loses
/// precision.
pub fn certain_hash(x: Iv) -> bool {
    x.mig() >= VISIBLE_TRIG
}

impl Analyzer<'_> {
    /// The value of an operation. In a witness run, what an operation that can go wrong
    /// gives is unknown: its interval assumes the operation went right, and nothing
    /// downstream of a NaN is witnessed.
    pub(super) fn after_hazard(&self, out: ops::Out) -> Num {
        match out.hazard {
            Some(_) if self.witness => Num::unknown(out.value.c.len(), out.value.cols, out.value.kind),
            _ => out.value,
        }
    }

    /// Reports `hazard` of expression `h`. A witness run skips the arms of `?:` and the
    /// right operands of `&&` and `||`: GLSL may not evaluate them.
    pub(super) fn found(&mut self, c: &Call<'_>, state: &State, h: Handle<Expression>, hazard: Hazard) {
        if !(self.witness && c.select_arms[h.index()]) {
            self.report(hazard, state.sure);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use naga::ScalarKind;

    fn num(c: &[Iv]) -> Num {
        Num::from_comps(c.to_vec(), 1, ScalarKind::Float, true)
    }

    #[test]
    fn a_divisor_is_certainly_zero_only_when_every_value_is() {
        assert!(certain(Kind::Division, &num(&[Iv::point(0.0)]), None));
        assert!(certain(Kind::Division, &num(&[Iv::new(-3e-8, 3e-8)]), None), "0 up to rounding");
        assert!(!certain(Kind::Division, &num(&[Iv::new(0.0, 1.0)]), None));
        assert!(!certain(Kind::Division, &num(&[Iv::point(1e-7)]), None), "an exact small constant is not 0");
        assert!(certain(Kind::Division, &num(&[Iv::point(1.0), Iv::point(0.0)]), None), "one component of a vector");
    }

    #[test]
    fn pow_of_a_negative_base_and_zero_to_a_non_positive_power() {
        let two = num(&[Iv::point(2.0)]);
        assert!(certain(Kind::Pow, &num(&[Iv::point(-6.0)]), Some(&two)));
        assert!(!certain(Kind::Pow, &num(&[Iv::new(-6.0, 6.0)]), Some(&two)));
        assert!(!certain(Kind::Pow, &num(&[Iv::point(0.0)]), Some(&two)));
        assert!(certain(Kind::Pow, &num(&[Iv::point(0.0)]), Some(&num(&[Iv::point(-1.0)]))));
    }

    #[test]
    fn rounding_past_one_is_not_a_certain_acos() {
        assert!(!certain(Kind::Acos, &num(&[Iv::new(-1.0000001, 1.0000001)]), None));
        assert!(certain(Kind::Acos, &num(&[Iv::new(1.5, 2.0)]), None));
        assert!(!certain(Kind::Sqrt, &num(&[Iv::new(-1e-7, -1e-8)]), None));
    }

    #[test]
    fn only_operands_that_reach_the_hazard_are_worth_witness_runs() {
        assert!(witnessable(Kind::Division, &num(&[Iv::new(0.0, 1.0)]), None));
        assert!(!witnessable(Kind::Trig, &num(&[Iv::new(0.0, 12_000.0)]), None), "never past 2^15 rad");
        assert!(witnessable(Kind::Trig, &num(&[Iv::new(0.0, 1e6)]), None));
        assert!(!witnessable(Kind::Acos, &num(&[Iv::new(-1.0000001, 1.0000001)]), None), "rounding slack only");
    }

    #[test]
    fn a_trig_argument_is_certainly_too_large_once_its_rounding_shows() {
        assert!(!certain(Kind::Trig, &num(&[Iv::point(10_377.0)]), None), "past 10^4 rad, 0.001 rad rounding");
        assert!(certain(Kind::Trig, &num(&[Iv::point(40_000.0)]), None));
        assert!(!certain(Kind::Trig, &num(&[Iv::new(0.0, 1e6)]), None), "time from 0");
    }
}
