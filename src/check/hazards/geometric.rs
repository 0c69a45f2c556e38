//! GLSL's geometric builtins on abstract values: `dot` (Cauchy–Schwarz), `cross`, `length`,
//! `distance`, `normalize` (the hazard of a zero-length argument), `faceforward`, `reflect`, `refract`.

use naga::{BinaryOperator as B, MathFunction as M};

use super::interval::Iv;
use super::ops::{binary, hazard_if, map, ok, or_unknown, Kind, Out};
use super::value::{length_of, Num};

/// Geometric functions (dot, cross, length, normalize, reflect…); `None` for other builtins.
pub(super) fn geometric(fun: M, a: &Num, b: Option<&Num>, d: Option<&Num>, same: bool, nonzero: bool) -> Option<Out> {
    let value = match fun {
        M::Dot => {
            let o = or_unknown(b);
            let mut r = if same {
                Iv::new(a.min_len().powi(2), a.len.hi.powi(2)).rounded()
            } else {
                let sum = a.c.iter().zip(&o.c).fold(Iv::point(0.0), |acc, (x, y)| acc.add(x.mul(*y)));
                let cs = a.len.hi * o.len.hi * (1.0 + 1e-6);
                sum.meet(Iv::new(-cs, cs))
            };
            if same {
                r = r.meet(a.c.iter().fold(Iv::point(0.0), |acc, x| acc.add(x.square())));
            }
            let mut n = Num::float(r);
            n.known = a.known && o.known;
            n.per_draw = a.per_draw && o.per_draw;
            n
        }
        M::Cross => {
            let o = or_unknown(b);
            let (x, y) = (&a.c, &o.c);
            let comps = vec![x[1].mul(y[2]).sub(x[2].mul(y[1])), x[2].mul(y[0]).sub(x[0].mul(y[2])), x[0].mul(y[1]).sub(x[1].mul(y[0]))];
            let mut n = Num::from_comps(comps, 1, a.kind, a.known && o.known);
            n.len = n.len.meet(Iv::new(0.0, a.len.hi * o.len.hi).rounded());
            n.per_draw = a.per_draw && o.per_draw;
            n
        }
        M::Length => {
            let mut n = Num::float(Iv::new(a.min_len(), a.len.hi.min(length_of(&a.c).hi)));
            n.known = a.known;
            n.per_draw = a.per_draw;
            n
        }
        M::Distance => {
            let diff = binary(B::Subtract, a, &or_unknown(b), same).value;
            let mut n = Num::float(Iv::new(diff.min_len(), diff.len.hi));
            n.known = diff.known;
            n
        }
        M::Normalize => {
            let min = a.min_len();
            let zero = min <= 0.0 && !nonzero;
            let mut n = if min > 0.0 {
                map(a, |x| x.mul(Iv::new(1.0 / a.len.hi, 1.0 / min)).meet(Iv::SIGNED_UNIT))
            } else {
                map(a, |_| Iv::SIGNED_UNIT)
            };
            n.len = Iv::new(1.0 - 1e-6, 1.0 + 1e-6);
            n.len3 = if a.c.len() == 3 { n.len } else { n.len3 };
            n.cone = a.cone;
            return Some(Out { value: n, hazard: hazard_if(a, zero, Kind::Normalize) });
        }
        M::FaceForward => {
            let mut r = a.clone();
            r.c = a.c.iter().map(|x| Iv::new(-x.mag(), x.mag())).collect();
            r.per_draw = false;
            r
        }
        M::Reflect => {
            // I - 2 dot(N, I) N: |R| <= |I| (1 + 2 |N|²).
            let nv = or_unknown(b);
            let bound = a.len.hi * (1.0 + 2.0 * nv.len.hi * nv.len.hi);
            let mut r = map(a, |_| Iv::new(-bound, bound));
            r.known = a.known && nv.known;
            if nv.len.lo >= 1.0 - 1e-3 && nv.len.hi <= 1.0 + 1e-3 {
                r.len = r.len.meet(Iv::new(a.len.lo * 0.99, a.len.hi * 1.01));
            }
            r
        }
        M::Refract => {
            let nv = or_unknown(b);
            let eta = d.map_or(Iv::TOP, |e| e.iv());
            let bound = eta.mag() * a.len.hi + (eta.mag() * nv.len.hi * a.len.hi + (1.0 + eta.mag() * eta.mag()).sqrt()) * nv.len.hi;
            let mut r = map(a, |_| Iv::new(-bound, bound));
            r.known = a.known && nv.known;
            r
        }
        _ => return None,
    };
    Some(ok(value))
}
