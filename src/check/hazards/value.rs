//! Abstract values: what the analysis knows about one runtime value.
//!
//! A number (scalar, vector or matrix) is one [`Iv`] per component plus facts intervals
//! alone lose: the Euclidean length of a vector (so `dot` of two unit vectors stays in
//! [-1, 1]), the gain of a matrix (so a normal matrix keeps normals non-zero), a gap
//! around zero (`|x| >= gap`, from guards such as `if (abs(phi) < 1e-4) return;`), and
//! whether interpolating the value across a triangle can reach zero (`cone`). Structs and
//! arrays are lists of values. `known` is false when any input was unknown: hazards are
//! reported only on known values, so an unknown input never raises an alarm.

use naga::{Module, ScalarKind, TypeInner};

use super::interval::Iv;

/// A scalar, vector or matrix.
#[derive(Debug, Clone, PartialEq)]
pub struct Num {
    /// Components; matrices column by column.
    pub c: Vec<Iv>,
    /// Matrix columns (1 for scalars and vectors).
    pub cols: usize,
    pub kind: ScalarKind,
    /// Vectors: Euclidean length. Scalars: `|x|`.
    pub len: Iv,
    /// Length of the first three components (vec4 `xyz`); `len` for shorter values.
    pub len3: Iv,
    /// Matrices: bounds of `|M v| / |v|` for the upper-left 3x3.
    pub gain: Iv,
    /// Scalars: `|x| >= gap`.
    pub gap: f64,
    /// Vectors: interpolating the per-vertex values over any triangle never gives zero.
    pub cone: bool,
    /// The same for every invocation of one draw (uniforms, constants).
    pub per_draw: bool,
    /// Derived from known facts only.
    pub known: bool,
}

/// Any value.
#[derive(Debug, Clone, PartialEq)]
pub enum Val {
    Num(Num),
    /// Struct members or array elements.
    Agg(Vec<Val>),
}

impl Num {
    /// A value from its components, facts derived from them.
    pub fn from_comps(c: Vec<Iv>, cols: usize, kind: ScalarKind, known: bool) -> Num {
        let len = if cols == 1 { length_of(&c) } else { Iv::NON_NEGATIVE };
        let len3 = if cols == 1 && c.len() == 4 { length_of(&c[..3]) } else { len };
        let gain = if cols > 1 { gain_of(&c, cols) } else { Iv::NON_NEGATIVE };
        let gap = if c.len() == 1 { c[0].mig() } else { 0.0 };
        Num { c, cols, kind, len, len3, gain, gap, cone: false, per_draw: false, known }
    }
    pub fn scalar(iv: Iv, kind: ScalarKind, known: bool) -> Num {
        Num::from_comps(vec![iv], 1, kind, known)
    }
    pub fn float(iv: Iv) -> Num {
        Num::scalar(iv, ScalarKind::Float, true)
    }
    pub fn unknown(n: usize, cols: usize, kind: ScalarKind) -> Num {
        let top = if kind == ScalarKind::Bool { Iv::UNIT } else { Iv::TOP };
        Num::from_comps(vec![top; n], cols, kind, false)
    }
    /// The one component of a scalar (or the hull of all components).
    pub fn iv(&self) -> Iv {
        let mut r = self.c[0];
        for c in &self.c[1..] {
            r = r.join(*c);
        }
        r
    }
    pub fn is_vector(&self) -> bool {
        self.cols == 1 && self.c.len() > 1
    }
    pub fn rows(&self) -> usize {
        self.c.len() / self.cols
    }
    /// Lower bound of the length, combining the fact with the components.
    pub fn min_len(&self) -> f64 {
        if self.c.len() == 1 {
            return self.c[0].mig().max(self.gap);
        }
        self.len.lo.max(length_of(&self.c).lo)
    }
    /// Restricts facts that are not true of a value derived element-wise.
    pub fn plain(mut self) -> Num {
        self.cone = false;
        self
    }
    pub fn join(&self, o: &Num) -> Num {
        if self.c.len() != o.c.len() {
            return Num::unknown(self.c.len(), self.cols, self.kind);
        }
        Num {
            c: self.c.iter().zip(&o.c).map(|(a, b)| a.join(*b)).collect(),
            cols: self.cols,
            kind: self.kind,
            len: self.len.join(o.len),
            len3: self.len3.join(o.len3),
            gain: self.gain.join(o.gain),
            gap: self.gap.min(o.gap),
            cone: self.cone && o.cone,
            per_draw: self.per_draw && o.per_draw,
            known: self.known && o.known,
        }
    }
    /// Jumps every bound that grew from `old` to infinity (loop widening).
    pub fn widen(&self, old: &Num) -> Num {
        let mut n = self.clone();
        for (c, o) in n.c.iter_mut().zip(&old.c) {
            if c.lo < o.lo {
                c.lo = f64::NEG_INFINITY;
            }
            if c.hi > o.hi {
                c.hi = f64::INFINITY;
            }
        }
        if n.len.hi > old.len.hi {
            n.len.hi = f64::INFINITY;
        }
        if n.len3.hi > old.len3.hi {
            n.len3.hi = f64::INFINITY;
        }
        if n.len.lo < old.len.lo {
            n.len.lo = 0.0;
        }
        if n.len3.lo < old.len3.lo {
            n.len3.lo = 0.0;
        }
        if n.gap < old.gap {
            n.gap = 0.0;
        }
        n
    }
}

impl Val {
    /// Nothing known about a value of this type.
    pub fn unknown(module: &Module, ty: &TypeInner) -> Val {
        match *ty {
            TypeInner::Scalar(s) => Val::Num(Num::unknown(1, 1, s.kind)),
            TypeInner::Vector { size, scalar } => Val::Num(Num::unknown(size as usize, 1, scalar.kind)),
            TypeInner::Matrix { columns, rows, scalar } => {
                Val::Num(Num::unknown(columns as usize * rows as usize, columns as usize, scalar.kind))
            }
            TypeInner::Array { base, size: naga::ArraySize::Constant(n), .. } => {
                let e = Val::unknown(module, &module.types[base].inner);
                Val::Agg(vec![e; n.get() as usize])
            }
            TypeInner::Struct { ref members, .. } => {
                Val::Agg(members.iter().map(|m| Val::unknown(module, &module.types[m.ty].inner)).collect())
            }
            TypeInner::Atomic(s) => Val::Num(Num::unknown(1, 1, s.kind)),
            _ => Val::Agg(Vec::new()),
        }
    }
    /// Zero of a type (WGSL zero-initialises variables).
    pub fn zero(module: &Module, ty: &TypeInner) -> Val {
        Val::unknown(module, ty).map_nums(&|n| {
            let mut z = Num::from_comps(vec![Iv::point(0.0); n.c.len()], n.cols, n.kind, true);
            z.per_draw = true;
            z
        })
    }
    pub fn map_nums(&self, f: &dyn Fn(&Num) -> Num) -> Val {
        match self {
            Val::Num(n) => Val::Num(f(n)),
            Val::Agg(items) => Val::Agg(items.iter().map(|i| i.map_nums(f)).collect()),
        }
    }
    pub fn num(&self) -> Option<&Num> {
        match self {
            Val::Num(n) => Some(n),
            Val::Agg(_) => None,
        }
    }
    pub fn join(&self, o: &Val) -> Val {
        match (self, o) {
            (Val::Num(a), Val::Num(b)) => Val::Num(a.join(b)),
            (Val::Agg(a), Val::Agg(b)) if a.len() == b.len() => Val::Agg(a.iter().zip(b).map(|(x, y)| x.join(y)).collect()),
            _ => self.forget(),
        }
    }
    pub fn widen(&self, old: &Val) -> Val {
        match (self, old) {
            (Val::Num(a), Val::Num(b)) if a.c.len() == b.c.len() => Val::Num(a.widen(b)),
            (Val::Agg(a), Val::Agg(b)) if a.len() == b.len() => Val::Agg(a.iter().zip(b).map(|(x, y)| x.widen(y)).collect()),
            _ => self.forget(),
        }
    }
    /// The same shape, nothing known.
    pub fn forget(&self) -> Val {
        self.map_nums(&|n| Num::unknown(n.c.len(), n.cols, n.kind))
    }
    /// Every element of an aggregate joined (a dynamically indexed array).
    pub fn join_elements(&self) -> Option<Val> {
        match self {
            Val::Agg(items) => items.iter().skip(1).fold(items.first().cloned(), |acc, i| acc.map(|a| a.join(i))),
            Val::Num(_) => None,
        }
    }
}

/// Length bounds of a vector from its components.
pub fn length_of(c: &[Iv]) -> Iv {
    let lo: f64 = c.iter().map(|x| x.mig() * x.mig()).sum::<f64>().sqrt();
    let hi: f64 = c.iter().map(|x| x.mag() * x.mag()).sum::<f64>().sqrt();
    Iv::new(lo, hi).rounded()
}

/// Gain bounds of the upper-left 3x3 of a point-valued matrix; `[0, ∞)` otherwise.
fn gain_of(c: &[Iv], cols: usize) -> Iv {
    let rows = c.len() / cols;
    if cols < 3 || rows < 3 || c.iter().any(|x| !x.is_point()) {
        // Frobenius norm still bounds the gain from above.
        let f: f64 = c.iter().map(|x| x.mag() * x.mag()).sum::<f64>().sqrt();
        return Iv::new(0.0, f);
    }
    let m = |col: usize, row: usize| c[col * rows + row].lo;
    let mut mat = [[0.0f64; 3]; 3];
    for (col, column) in mat.iter_mut().enumerate() {
        for (row, v) in column.iter_mut().enumerate() {
            *v = m(col, row);
        }
    }
    let (lo, hi) = singular_bounds(&mat);
    Iv::new(lo, hi)
}

/// Bounds `(σmin, σmax)` of a 3x3 matrix (columns): σmax ≤ ‖M‖_F and
/// σmin ≥ |det M| / ‖M‖_F², both with 1e-6 relative slack.
pub fn singular_bounds(m: &[[f64; 3]; 3]) -> (f64, f64) {
    let f2: f64 = m.iter().flatten().map(|x| x * x).sum();
    let det = m[0][0] * (m[1][1] * m[2][2] - m[2][1] * m[1][2]) - m[1][0] * (m[0][1] * m[2][2] - m[2][1] * m[0][2])
        + m[2][0] * (m[0][1] * m[1][2] - m[1][1] * m[0][2]);
    let hi = f2.sqrt() * (1.0 + 1e-6);
    let lo = if f2 > 0.0 { det.abs() / f2 * (1.0 - 1e-6) } else { 0.0 };
    (lo, hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn facts_from_components() {
        let v = Num::from_comps(vec![Iv::new(0.5, 1.0), Iv::new(-1.0, 1.0), Iv::point(0.0)], 1, ScalarKind::Float, true);
        assert!(v.min_len() >= 0.49 && v.len.hi > 1.41);
        let z = Num::from_comps(vec![Iv::new(-1.0, 1.0); 3], 1, ScalarKind::Float, true);
        assert_eq!(z.min_len(), 0.0);
    }

    #[test]
    fn gain_of_a_scaled_rotation_is_nonzero() {
        let s = 2.0;
        let m = [[0.0, s, 0.0], [-s, 0.0, 0.0], [0.0, 0.0, s]];
        let (lo, hi) = singular_bounds(&m);
        assert!(lo > 0.6 && lo <= 2.0 && (2.0..3.5).contains(&hi));
    }
}
