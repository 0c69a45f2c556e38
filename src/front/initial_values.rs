//! The values a program gives its uniforms before its host sets any, for the renderer,
//! reflection and `--list-uniforms`:
//! - GLSL initializers (`uniform float k = 0.5;`, GLSL 1.20): GL starts such a uniform at
//!   its initializer. The rewrite declares each as a constant
//!   ([`INITIAL_PREFIX`](crate::front::rewrite::INITIAL_PREFIX)) that naga evaluates; they
//!   are read back here.
//! - `#pragma parameter NAME "Label" default min max step` ([`crate::front::parameters`]):
//!   RetroArch starts the uniform (loose, or a member of a block) at its default.
//!
//! Also which block matrices are stored row-major ([`row_major`]): how their values are laid out.

use naga::{Handle, Module};

use crate::manifest::UniformValue;

/// Where a uniform's initial value comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum InitialFrom {
    /// A GLSL initializer.
    Initializer,
    /// A `#pragma parameter`'s default.
    Parameter,
}

impl InitialFrom {
    /// As reflection names it (`fills[].from`).
    pub fn key(self) -> &'static str {
        match self {
            InitialFrom::Initializer => "initializer",
            InitialFrom::Parameter => "parameter",
        }
    }

    /// As `--verbose` says what a uniform receives.
    pub fn describe(self) -> &'static str {
        match self {
            InitialFrom::Initializer => "its initializer",
            InitialFrom::Parameter => "its `#pragma parameter` default",
        }
    }
}

/// One initial value: the uniform or part of it (`s[1].f`), and its source.
#[derive(Debug, Clone, PartialEq)]
pub struct Initial {
    pub path: String,
    pub value: UniformValue,
    pub from: InitialFrom,
}

/// The initial values of the program's uniforms: GLSL initializers, read from the constants
/// the rewrite declares for them ([`INITIAL_PREFIX`](crate::front::rewrite::INITIAL_PREFIX)),
/// then the defaults of `#pragma parameter`s no initializer sets.
pub fn of(program: &crate::front::program::CompiledProgram) -> Vec<Initial> {
    let mut all: Vec<Initial> =
        initializers(program).into_iter().map(|(path, value)| Initial { path, value, from: InitialFrom::Initializer }).collect();
    let root = |path: &str| path[..path.find(['.', '[']).unwrap_or(path.len())].to_string();
    for p in program.stages.iter().flat_map(|s| &s.syntax.parameters) {
        if !all.iter().any(|i| root(&i.path) == p.name) {
            all.push(Initial { path: p.name.clone(), value: UniformValue::Float(p.default), from: InitialFrom::Parameter });
        }
    }
    all
}

/// The square matrices the program's blocks store row-major (`layout(row_major)`), as
/// (block name, member name): naga lays every matrix out column-major and the rewrite reads
/// these transposed, so a value written for one is stored transposed, as GL stores it.
pub fn row_major(program: &crate::front::program::CompiledProgram) -> Vec<(String, String)> {
    let mut out: Vec<(String, String)> = Vec::new();
    for s in program.stages.iter().map(|s| &s.syntax) {
        for (gi, member) in crate::front::rewrite::row_major_members(s) {
            let Some(b) = &s.globals[gi].block else { continue };
            let entry = (b.block_name.clone(), member);
            if !out.contains(&entry) {
                out.push(entry);
            }
        }
    }
    out
}

/// The values GLSL initializers give the program's uniforms.
fn initializers(program: &crate::front::program::CompiledProgram) -> Vec<(String, UniformValue)> {
    let mut out: Vec<(String, UniformValue)> = Vec::new();
    for stage in &program.stages {
        let Some(v) = &stage.naga else { continue };
        let module = &v.module;
        for (_, c) in module.constants.iter() {
            let Some(name) = c.name.as_deref().and_then(|n| n.strip_prefix(crate::front::rewrite::INITIAL_PREFIX)) else { continue };
            if out.iter().any(|(n, _)| n == name) {
                continue;
            }
            flatten(module, c.init, name.to_string(), &mut out);
        }
    }
    out
}

/// The value of constant `expr` at GLSL path `path`: one entry, or for a struct (and an
/// array of structs) one per member (`s[1].f`).
fn flatten(module: &Module, expr: Handle<naga::Expression>, path: String, out: &mut Vec<(String, UniformValue)>) {
    use naga::{Expression, TypeInner};
    let expr = match &module.global_expressions[expr] {
        Expression::Constant(c) => module.constants[*c].init,
        _ => expr,
    };
    if let Expression::Compose { ty, components } = &module.global_expressions[expr] {
        match &module.types[*ty].inner {
            TypeInner::Struct { members, .. } => {
                for (m, c) in members.iter().zip(components) {
                    flatten(module, *c, format!("{path}.{}", m.name.as_deref().unwrap_or_default()), out);
                }
                return;
            }
            TypeInner::Array { base, .. } if matches!(module.types[*base].inner, TypeInner::Struct { .. }) => {
                for (i, c) in components.iter().enumerate() {
                    flatten(module, *c, format!("{path}[{i}]"), out);
                }
                return;
            }
            _ => {}
        }
    }
    if let Some(value) = constant_value(module, expr) {
        out.push((path, value));
    }
}

/// The value of a constant expression of `module` (a GLSL initializer naga evaluated):
/// scalars, vectors, matrices (column by column) and arrays; `None` for what a uniform
/// value cannot hold (structs, zero values of aggregates).
pub fn constant_value(module: &Module, expr: Handle<naga::Expression>) -> Option<UniformValue> {
    use naga::{Expression, Literal, TypeInner};
    Some(match &module.global_expressions[expr] {
        Expression::Literal(l) => match *l {
            // The shortest decimal of the f32 (0.1, not 0.10000000149011612): the same bits.
            Literal::F32(x) => UniformValue::Float(x.to_string().parse().unwrap_or(f64::from(x))),
            Literal::F64(x) => UniformValue::Float(x),
            Literal::I32(x) => UniformValue::Int(i64::from(x)),
            Literal::U32(x) => UniformValue::Int(i64::from(x)),
            Literal::Bool(b) => UniformValue::Bool(b),
            _ => return None,
        },
        Expression::Compose { ty, components } => {
            if matches!(module.types[*ty].inner, TypeInner::Struct { .. }) {
                return None;
            }
            UniformValue::List(components.iter().map(|c| constant_value(module, *c)).collect::<Option<Vec<_>>>()?)
        }
        Expression::Splat { size, value } => UniformValue::List(vec![constant_value(module, *value)?; *size as usize]),
        Expression::Constant(c) => constant_value(module, module.constants[*c].init)?,
        _ => return None,
    })
}
