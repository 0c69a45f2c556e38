//! Uniform values set on the command line (`--set NAME=VALUE`), checked against the
//! declarations the way `[uniforms]` defaults are.
//!
//! The values are registered as a file of their own (`command line`, one `--set` per line)
//! so their diagnostics point at what was typed. A value is TOML (`0.5`, `3`, `true`,
//! `[1, 0, 0]`) or a bare comma list (`1,0,0`). A name no program declares is an error
//! (with the nearest declared name); with several programs, a value goes to the programs
//! that declare it.

use std::ops::Range;

use super::{Checked, Outcome};
use crate::diag::{Code, Diagnostic};
use crate::manifest::{UniformDefault, UniformValue};

/// Checks `values` against every program and gives each its values ([`Checked::values`]);
/// a program whose values do not fit fails.
pub fn apply(values: &[(String, String)], out: &mut Outcome, checked: &mut [Checked]) {
    let text: String = values.iter().map(|(n, v)| format!("--set {n}={v}\n")).collect();
    let file = out.files.add("command line", text);
    let mut defaults = Vec::new();
    let mut unparsed = false;
    let mut start = 0;
    for (name, value) in values {
        let name_at = start + "--set ".len();
        let value_at = name_at + name.len() + 1;
        start = value_at + value.len() + 1;
        match parse_value(value) {
            Some(v) => defaults.push(default(name, name_at..name_at + name.len(), v, value_at..value_at + value.len())),
            None => {
                unparsed = true;
                out.diagnostics.push(
                    Diagnostic::new(
                        Code::ManifestValue,
                        format!("`--set {name}={value}`: `{value}` is not a finite number a shader can hold, a boolean or a list of them"),
                    )
                    .at(file, value_at..value_at + value.len(), "not a value")
                    .with_note("floats must be finite and within 32-bit range (±3.4e38); integers within 32 bits")
                    .with_help("write e.g. `--set speed=0.5`, `--set count=3`, `--set on=true`, `--set tint=1,0.5,0`"),
                )
            }
        }
    }
    if unparsed {
        // The values apply to every program: none is drawn with a value left out.
        for c in checked.iter_mut() {
            c.failed = true;
            c.units.clear();
        }
        return;
    }
    let mut unknown: Vec<Option<Diagnostic>> = vec![None; defaults.len()];
    let mut declared_somewhere = vec![false; defaults.len()];
    for c in checked.iter_mut().filter(|c| !c.failed) {
        let syntaxes: Vec<_> = c.units.iter().flat_map(|u| u.program.stages.iter().map(|s| s.syntax.clone())).collect();
        let mut failed = false;
        for (i, d) in defaults.iter().enumerate() {
            let diags = crate::link::effect_uniforms::check_values(file, std::slice::from_ref(d), &syntaxes, &out.files);
            if let Some(u) = diags.iter().find(|x| x.code == Code::UniformUndeclared) {
                unknown[i].get_or_insert_with(|| u.clone());
                continue;
            }
            declared_somewhere[i] = true;
            failed |= diags.iter().any(Diagnostic::is_error);
            for x in diags {
                if !out.diagnostics.contains(&x) {
                    out.diagnostics.push(x);
                }
            }
            c.values.push((d.name.clone(), d.value.clone().unwrap_or(UniformValue::Int(0))));
        }
        if failed {
            c.failed = true;
            c.units.clear();
        }
    }
    for (i, d) in unknown.into_iter().enumerate() {
        if let (false, Some(d)) = (declared_somewhere[i], d) {
            out.diagnostics.push(d);
            for c in checked.iter_mut() {
                c.failed = true;
                c.units.clear();
            }
        }
    }
}

fn default(name: &str, name_span: Range<usize>, value: UniformValue, value_span: Range<usize>) -> UniformDefault {
    UniformDefault {
        name: name.to_string(),
        name_span,
        value: Some(value),
        value_span,
        range: None,
        range_span: None,
        semantic: None,
        semantic_span: None,
    }
}

/// A TOML value (`0.5`, `3`, `true`, `[1, 0, 0]`), or a bare comma list (`1,0,0`).
pub fn parse_value(text: &str) -> Option<UniformValue> {
    let parse = |t: &str| toml::from_str::<toml::Table>(&format!("v = {t}")).ok().and_then(|mut table| table.remove("v"));
    let v = parse(text).or_else(|| text.contains(',').then(|| parse(&format!("[{text}]"))).flatten())?;
    convert(&v)
}

fn convert(v: &toml::Value) -> Option<UniformValue> {
    Some(match v {
        toml::Value::Integer(i) if (i64::from(i32::MIN)..=i64::from(u32::MAX)).contains(i) => UniformValue::Int(*i),
        // f32 is what a shader holds: 1e39 would arrive as +Inf.
        toml::Value::Float(f) if f.is_finite() && f.abs() <= f64::from(f32::MAX) => UniformValue::Float(*f),
        toml::Value::Boolean(b) => UniformValue::Bool(*b),
        toml::Value::Array(items) if !items.is_empty() => UniformValue::List(items.iter().map(convert).collect::<Option<_>>()?),
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_are_toml_or_comma_lists() {
        assert_eq!(parse_value("0.5"), Some(UniformValue::Float(0.5)));
        assert_eq!(parse_value("3"), Some(UniformValue::Int(3)));
        assert_eq!(parse_value("true"), Some(UniformValue::Bool(true)));
        for bad in ["nan", "inf", "-inf", "1e39", "1e309", "99999999999", "abc"] {
            assert_eq!(parse_value(bad), None, "{bad}");
        }
        let v = Some(UniformValue::List(vec![UniformValue::Int(1), UniformValue::Float(0.5), UniformValue::Int(0)]));
        assert_eq!(parse_value("[1, 0.5, 0]"), v);
        assert_eq!(parse_value("1,0.5,0"), v);
        assert_eq!(parse_value("abc"), None);
        assert_eq!(parse_value("nan"), None);
        assert_eq!(parse_value("[]"), None);
    }
}
