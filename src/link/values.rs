//! Whether a manifest default value fits a GLSL type, and how to say what was expected.
//!
//! `float` ← integer or float; `int` ← integer; `uint` ← integer ≥ 0; `bool` ← boolean;
//! `vecN` ← N numbers; `ivecN`/`uvecN` ← N integers; `bvecN` ← N booleans; `matCxR` ← C
//! column lists of R numbers or one flat list of C·R (column-major); `T[K]` ← K values
//! each fitting `T`. Structs and samplers take no value.

use crate::front::syntax::GlslType;
use crate::manifest::UniformValue;

/// Scalar kinds a value is checked against.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scalar {
    Float,
    Int,
    Uint,
    Bool,
}

/// The value shape a GLSL type needs.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Shape {
    Scalar(Scalar),
    Vector(Scalar, usize),
    /// Columns, rows.
    Matrix(usize, usize),
    /// Element shape and length (None = unsized).
    Array(Box<Shape>, Option<u32>),
    Struct(String),
    Sampler,
    /// A type effectc does not know how to fill (`atomic_uint`, images, …).
    Other(String),
}

impl Shape {
    /// The shape of `ty`; `is_struct` tells whether a base name is a struct.
    pub fn of(ty: &GlslType, is_struct: &dyn Fn(&str) -> bool) -> Shape {
        if let Some((first, _)) = ty.dims.split_first() {
            return Shape::Array(Box::new(Shape::of(&ty.element(), is_struct)), *first);
        }
        let base = ty.base.as_str();
        if ty.is_sampler() || base.contains("sampler") {
            return Shape::Sampler;
        }
        if let Some(s) = scalar(base) {
            return Shape::Scalar(s);
        }
        for (prefix, s) in
            [("vec", Scalar::Float), ("dvec", Scalar::Float), ("ivec", Scalar::Int), ("uvec", Scalar::Uint), ("bvec", Scalar::Bool)]
        {
            if let Some(n) = base.strip_prefix(prefix).and_then(size) {
                return Shape::Vector(s, n);
            }
        }
        for prefix in ["mat", "dmat"] {
            if let Some(rest) = base.strip_prefix(prefix) {
                if let Some(n) = size(rest) {
                    return Shape::Matrix(n, n);
                }
                if let Some((c, r)) = rest.split_once('x') {
                    if let (Some(c), Some(r)) = (size(c), size(r)) {
                        return Shape::Matrix(c, r);
                    }
                }
            }
        }
        if is_struct(base) {
            Shape::Struct(base.to_string())
        } else {
            Shape::Other(base.to_string())
        }
    }

    /// Scalar numbers (`float`, `int`, `uint`, `double`).
    pub fn is_scalar_number(&self) -> bool {
        matches!(self, Shape::Scalar(s) if *s != Scalar::Bool)
    }

    /// Numbers and vectors of numbers: the types `range` applies to (a vector's range
    /// bounds each component).
    pub fn takes_range(&self) -> bool {
        match self {
            Shape::Vector(s, _) => *s != Scalar::Bool,
            other => other.is_scalar_number(),
        }
    }

    /// What a value of this shape looks like, for "expected …" messages.
    pub fn expected(&self) -> String {
        match self {
            Shape::Scalar(s) => scalar_text(*s, false).to_string(),
            Shape::Vector(s, n) => format!("a list of {n} {}", scalar_text(*s, true)),
            Shape::Matrix(c, r) => format!("{c} lists (columns) of {r} numbers, or a flat list of {}", c * r),
            Shape::Array(elem, Some(k)) => {
                format!("a list of {k} values, each {}", elem.expected())
            }
            Shape::Array(elem, None) => format!("a list of values, each {}", elem.expected()),
            Shape::Struct(name) => format!("no value (`{name}` is a struct)"),
            Shape::Sampler => "no value (samplers are bound under [textures])".to_string(),
            Shape::Other(name) => format!("no value (effectc cannot set a `{name}`)"),
        }
    }

    /// `Ok` if `v` fits; otherwise a short description of what is wrong.
    pub fn fit(&self, v: &UniformValue) -> Result<(), String> {
        let wrong = || Err(format!("expected {}, found {}", self.expected(), describe(v)));
        match self {
            Shape::Scalar(s) => fit_scalar(*s, v),
            Shape::Vector(s, n) => match v {
                UniformValue::List(items) if items.len() == *n => {
                    items.iter().try_for_each(|i| fit_scalar(*s, i)).map_err(|e| format!("expected {}: {e}", self.expected()))
                }
                _ => wrong(),
            },
            Shape::Matrix(c, r) => match v {
                UniformValue::List(items) if items.len() == c * r && items.iter().all(|i| !matches!(i, UniformValue::List(_))) => {
                    items.iter().try_for_each(|i| fit_scalar(Scalar::Float, i))
                }
                UniformValue::List(cols) if cols.len() == *c => {
                    for col in cols {
                        match col {
                            UniformValue::List(rows) if rows.len() == *r => {
                                rows.iter().try_for_each(|i| fit_scalar(Scalar::Float, i))?;
                            }
                            _ => return wrong(),
                        }
                    }
                    Ok(())
                }
                _ => wrong(),
            },
            Shape::Array(elem, len) => match v {
                UniformValue::List(items) if len.is_none_or(|k| items.len() == k as usize) && !items.is_empty() => {
                    for (i, item) in items.iter().enumerate() {
                        elem.fit(item).map_err(|e| format!("element {i}: {e}"))?;
                    }
                    Ok(())
                }
                _ => wrong(),
            },
            Shape::Struct(_) | Shape::Sampler | Shape::Other(_) => wrong(),
        }
    }

    /// A placeholder default of this shape, in TOML (`0.0`, `[0.0, 0.0, 0.0]`).
    pub fn example(&self) -> String {
        match self {
            Shape::Scalar(Scalar::Float) => "0.0".into(),
            Shape::Scalar(Scalar::Int | Scalar::Uint) => "0".into(),
            Shape::Scalar(Scalar::Bool) => "false".into(),
            Shape::Vector(s, n) => {
                let one = Shape::Scalar(*s).example();
                format!("[{}]", vec![one; *n].join(", "))
            }
            Shape::Matrix(c, r) => {
                let cols: Vec<String> = (0..*c)
                    .map(|ci| {
                        let rows: Vec<&str> = (0..*r).map(|ri| if ri == ci { "1.0" } else { "0.0" }).collect();
                        format!("[{}]", rows.join(", "))
                    })
                    .collect();
                format!("[{}]", cols.join(", "))
            }
            Shape::Array(elem, k) => {
                let n = k.unwrap_or(1).min(4) as usize;
                let mut items = vec![elem.example(); n];
                if k.is_some_and(|k| k as usize > n) {
                    items.push("…".into());
                }
                format!("[{}]", items.join(", "))
            }
            Shape::Struct(_) | Shape::Sampler | Shape::Other(_) => "…".into(),
        }
    }
}

fn scalar(base: &str) -> Option<Scalar> {
    Some(match base {
        "float" | "double" => Scalar::Float,
        "int" => Scalar::Int,
        "uint" => Scalar::Uint,
        "bool" => Scalar::Bool,
        _ => return None,
    })
}

fn size(s: &str) -> Option<usize> {
    match s {
        "2" => Some(2),
        "3" => Some(3),
        "4" => Some(4),
        _ => None,
    }
}

fn scalar_text(s: Scalar, plural: bool) -> &'static str {
    match (s, plural) {
        (Scalar::Float, false) => "a number",
        (Scalar::Float, true) => "numbers",
        (Scalar::Int, false) => "an integer",
        (Scalar::Int, true) => "integers",
        (Scalar::Uint, false) => "a non-negative integer",
        (Scalar::Uint, true) => "non-negative integers",
        (Scalar::Bool, false) => "`true` or `false`",
        (Scalar::Bool, true) => "booleans",
    }
}

fn fit_scalar(s: Scalar, v: &UniformValue) -> Result<(), String> {
    let ok = match (s, v) {
        (Scalar::Float, UniformValue::Int(_) | UniformValue::Float(_)) => true,
        (Scalar::Int, UniformValue::Int(_)) => true,
        (Scalar::Uint, UniformValue::Int(i)) => *i >= 0,
        (Scalar::Bool, UniformValue::Bool(_)) => true,
        _ => false,
    };
    if ok {
        Ok(())
    } else {
        Err(format!("expected {}, found {}", scalar_text(s, false), describe(v)))
    }
}

/// A value described for messages: "the float `1.5`", "a list of 4 numbers".
pub fn describe(v: &UniformValue) -> String {
    match v {
        UniformValue::Bool(b) => format!("the boolean `{b}`"),
        UniformValue::Int(i) if *i < 0 => format!("the negative integer `{i}`"),
        UniformValue::Int(i) => format!("the integer `{i}`"),
        UniformValue::Float(f) => format!("the float `{f:?}`"),
        UniformValue::List(items) if items.is_empty() => "an empty list".to_string(),
        UniformValue::List(items) => {
            let what = if items.iter().all(|i| i.as_f64().is_some()) {
                "numbers"
            } else if items.iter().all(|i| matches!(i, UniformValue::Bool(_))) {
                "booleans"
            } else if items.iter().all(|i| matches!(i, UniformValue::List(_))) {
                "lists"
            } else {
                "values"
            };
            format!("a list of {} {what}", items.len())
        }
    }
}
