//! `[uniforms]`: a default value (scalar, vector, matrix or array, as nested lists), or a
//! table with `value`, `range` and `semantic`. Names must be GLSL uniform names
//! (`tint`, `lights[0].color`); whether they fit the shaders is checked in `link`.

use std::ops::Range;

use toml::de::{DeTable, DeValue};

use super::{entries, is_ident, key, parse_int, Ctx, Key, Val};
use crate::diag::Code;
use crate::manifest::{did_you_mean, Semantic, UniformDefault, UniformValue};

const UNIFORM_KEYS: &[&str] = &["value", "range", "semantic"];
/// Uniform default lists nest at most this deep (an array of arrays of mat4 columns is 3).
const MAX_LIST_DEPTH: usize = 6;

/// A name as `glGetUniformLocation` takes it: `ident ( "[" digits "]" | "." ident )*`.
fn is_uniform_name(s: &str) -> bool {
    let end = s.find(['[', '.']).unwrap_or(s.len());
    if !is_ident(&s[..end]) {
        return false;
    }
    let mut rest = &s[end..];
    while !rest.is_empty() {
        if let Some(r) = rest.strip_prefix('[') {
            let Some(close) = r.find(']') else {
                return false;
            };
            if close == 0 || !r[..close].bytes().all(|b| b.is_ascii_digit()) {
                return false;
            }
            rest = &r[close + 1..];
        } else if let Some(r) = rest.strip_prefix('.') {
            let end = r.find(['[', '.']).unwrap_or(r.len());
            if !is_ident(&r[..end]) {
                return false;
            }
            rest = &r[end..];
        } else {
            return false;
        }
    }
    true
}

impl Ctx<'_> {
    /// Names in `[uniforms]` / `[textures]` must be GLSL uniform names. A `gl_` path may
    /// name the compatibility profile's uniform state (`gl_LightSource[0].diffuse`), which
    /// the link checks against what the program reads; a bare `gl_` name is reserved.
    pub(super) fn check_uniform_name(&mut self, name: &str, span: Range<usize>) -> bool {
        if name.starts_with("gl_") && !is_uniform_name(name) {
            self.report(Code::ManifestValue, span, format!("`{name}` is a reserved GLSL name"), "names starting with `gl_` are reserved");
            return false;
        }
        if !is_uniform_name(name) {
            let d = self.report(Code::ManifestValue, span, format!("`{name}` is not a valid GLSL uniform name"), "not a uniform name");
            d.help = Some("use the name as the shader declares it: `tint`, `lights[0].color`".into());
            return false;
        }
        true
    }

    pub(super) fn uniforms(&mut self, t: &DeTable<'_>) -> Vec<UniformDefault> {
        let mut out = Vec::new();
        for (k, v) in entries(t) {
            let name = key(k);
            let name_ok = self.check_uniform_name(name, k.span());
            let what = format!("uniform `{name}`");
            let parsed = match v.get_ref() {
                DeValue::Table(spec) => self.uniform_spec(name, k, v, spec),
                _ => self.uniform_value(v, &what, 0).map(|value| UniformDefault {
                    name: name.to_owned(),
                    name_span: k.span(),
                    value: Some(value),
                    value_span: v.span(),
                    range: None,
                    range_span: None,
                    semantic: None,
                    semantic_span: None,
                }),
            };
            if let (Some(u), true) = (parsed, name_ok) {
                out.push(u);
            }
        }
        out
    }

    fn uniform_spec(&mut self, name: &str, k: &Key<'_>, v: &Val<'_>, spec: &DeTable<'_>) -> Option<UniformDefault> {
        let mut ok = true;
        let mut value = None;
        let mut value_key = None;
        let mut range = None;
        let mut semantic = None;
        let mut semantic_key = None;
        for (k2, v2) in entries(spec) {
            match key(k2) {
                "value" => {
                    value_key = Some(k2.span());
                    match self.uniform_value(v2, &format!("`uniforms.{name}.value`"), 0) {
                        Some(x) => value = Some((x, v2.span())),
                        None => ok = false,
                    }
                }
                "range" => match self.range(v2, &format!("`uniforms.{name}.range`")) {
                    Some(r) => range = Some((r, v2.span())),
                    None => ok = false,
                },
                "semantic" => {
                    semantic_key = Some(k2.span());
                    let choices: Vec<(&'static str, Semantic)> = Semantic::ALL.iter().map(|s| (s.name(), *s)).collect();
                    let alias = v2.get_ref().as_str().and_then(Semantic::from_name);
                    let what = format!("`uniforms.{name}.semantic`");
                    match alias.or_else(|| self.choice(v2, &what, "semantic", &choices)) {
                        Some(s) => semantic = Some((s, v2.span())),
                        None => ok = false,
                    }
                }
                other => {
                    self.unknown_key(other, k2.span(), &format!("in uniform `{name}`"), UNIFORM_KEYS);
                    ok = false;
                }
            }
        }
        match (&value_key, &semantic_key) {
            (Some(vk), Some(sk)) => {
                let file = self.file;
                let d = self.report(
                    Code::ManifestConflict,
                    sk.clone(),
                    format!("uniform `{name}` has both a `value` and a `semantic`"),
                    "semantic given here",
                );
                d.labels.push(crate::diag::Label { file, span: vk.clone(), message: "value given here".into() });
                d.help = Some("a semantic is set by the runtime every frame: remove `value` or `semantic`".into());
                ok = false;
            }
            (None, None) => {
                let d = self.report(
                    Code::ManifestMissing,
                    v.span(),
                    format!("uniform `{name}` needs a `value` or a `semantic`"),
                    "neither `value` nor `semantic`",
                );
                d.help = Some(format!(
                    "write `{name} = 1.0`, `{name} = {{ value = 1.0, range = [0.0, 2.0] }}` or `{name} = {{ semantic = \"time\" }}`"
                ));
                ok = false;
            }
            _ => {}
        }
        if let (Some((val, vspan)), Some(((lo, hi), rspan))) = (&value, &range) {
            let outside: Vec<f64> = val.scalars().iter().filter_map(|s| s.as_f64()).filter(|x| x < lo || x > hi).collect();
            if let Some(first) = outside.first() {
                let file = self.file;
                let d = self.report(
                    Code::DefaultOutOfRange,
                    vspan.clone(),
                    format!("default of uniform `{name}` lies outside its range [{lo}, {hi}]"),
                    format!("{first} is outside the range"),
                );
                d.labels.push(crate::diag::Label { file, span: rspan.clone(), message: "range declared here".into() });
            }
        }
        if !ok {
            return None;
        }
        let (value, value_span) = match value {
            Some((x, span)) => (Some(x), span),
            None => (None, v.span()),
        };
        Some(UniformDefault {
            name: name.to_owned(),
            name_span: k.span(),
            value,
            value_span,
            range: range.as_ref().map(|r| r.0),
            range_span: range.map(|r| r.1),
            semantic: semantic.as_ref().map(|s| s.0),
            semantic_span: semantic.map(|s| s.1),
        })
    }

    fn uniform_value(&mut self, v: &Val<'_>, what: &str, depth: usize) -> Option<UniformValue> {
        const EXPECTED: &str = "a number, a boolean or an array of them";
        match v.get_ref() {
            DeValue::Boolean(b) => Some(UniformValue::Bool(*b)),
            DeValue::Integer(i) => match parse_int(i) {
                Some(n) => Some(UniformValue::Int(n)),
                None => {
                    self.report(Code::ManifestValue, v.span(), format!("{what}: integer does not fit in 64 bits"), "too large");
                    None
                }
            },
            DeValue::Float(_) => self.number(v, what).map(UniformValue::Float),
            DeValue::String(s) => {
                self.wrong_type(v, what, EXPECTED);
                let s = s.to_string();
                let sem = Semantic::from_name(&s).map(|x| x.name()).or_else(|| {
                    let names: Vec<&str> = Semantic::ALL.iter().map(|x| x.name()).collect();
                    did_you_mean(&s, &names)
                });
                if let (Some(sem), Some(d)) = (sem, self.diags.last_mut()) {
                    d.help = Some(format!("to bind a value the runtime provides, write `{{ semantic = \"{sem}\" }}`"));
                }
                None
            }
            DeValue::Datetime(_) | DeValue::Table(_) => {
                self.wrong_type(v, what, EXPECTED);
                None
            }
            DeValue::Array(items) => {
                if depth >= MAX_LIST_DEPTH {
                    self.report(
                        Code::ManifestValue,
                        v.span(),
                        format!("{what}: arrays nest deeper than {MAX_LIST_DEPTH} levels"),
                        "nested too deeply",
                    );
                    return None;
                }
                if items.is_empty() {
                    self.report(Code::ManifestValue, v.span(), format!("{what} is an empty array"), "empty array");
                    return None;
                }
                let mut out = Vec::with_capacity(items.len());
                let mut ok = true;
                for item in items.iter() {
                    match self.uniform_value(item, what, depth + 1) {
                        Some(x) => out.push(x),
                        None => ok = false,
                    }
                }
                if !ok {
                    return None;
                }
                // Every element must have the shape of the first (rectangular, one scalar kind).
                let shape = |x: &UniformValue| (x.dims(), matches!(x.scalars().first(), Some(UniformValue::Bool(_))));
                let first = shape(&out[0]);
                if let Some(i) = out.iter().position(|x| shape(x) != first) {
                    let describe = |(dims, is_bool): &(Vec<usize>, bool)| {
                        let scalar = if *is_bool { "a boolean" } else { "a number" };
                        match dims.as_slice() {
                            [] => scalar.to_owned(),
                            d => format!(
                                "an array of {} {}{}",
                                d.iter().map(|n| n.to_string()).collect::<Vec<_>>().join("×"),
                                if *is_bool { "boolean" } else { "number" },
                                if d.iter().product::<usize>() == 1 { "" } else { "s" }
                            ),
                        }
                    };
                    let found = shape(&out[i]);
                    let file = self.file;
                    let d = self.report(
                        Code::ManifestValue,
                        items[i].span(),
                        format!("{what}: array elements must all have the same shape"),
                        format!("this is {}", describe(&found)),
                    );
                    d.labels.push(crate::diag::Label {
                        file,
                        span: items[0].span(),
                        message: format!("the first element is {}", describe(&first)),
                    });
                    return None;
                }
                Some(UniformValue::List(out))
            }
        }
    }

    fn range(&mut self, v: &Val<'_>, what: &str) -> Option<(f64, f64)> {
        const EXPECTED: &str = "an array of two numbers `[min, max]`";
        let DeValue::Array(items) = v.get_ref() else {
            self.wrong_type(v, what, EXPECTED);
            return None;
        };
        if items.len() != 2 {
            self.report(
                Code::ManifestValue,
                v.span(),
                format!("{what} must be {EXPECTED}, found {} element(s)", items.len()),
                "expected `[min, max]`",
            );
            return None;
        }
        let lo = self.number(&items[0], &format!("{what} lower bound"));
        let hi = self.number(&items[1], &format!("{what} upper bound"));
        let (lo, hi) = (lo?, hi?);
        if lo > hi {
            let d = self.report(
                Code::ManifestValue,
                v.span(),
                format!("{what} is empty: lower bound {lo} is greater than upper bound {hi}"),
                "min > max",
            );
            d.help = Some(format!("write the range as `[{hi}, {lo}]`"));
            return None;
        }
        Some((lo, hi))
    }
}
