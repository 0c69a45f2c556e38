//! `effectc check --list-uniforms`: every uniform a program lets you set, with its type,
//! its value (the manifest's default or semantic, else what the renderer would guess), its
//! range, and whether a stage reads it.

use super::Checked;
use crate::manifest::{Semantic, UniformValue};

/// One program's uniforms.
#[derive(Debug, Clone, serde::Serialize)]
pub struct ProgramUniforms {
    pub program: String,
    pub uniforms: Vec<UniformInfo>,
}

/// One uniform.
#[derive(Debug, Clone, serde::Serialize)]
pub struct UniformInfo {
    pub name: String,
    #[serde(rename = "type")]
    pub ty: String,
    /// The manifest's default.
    pub default: Option<UniformValue>,
    /// The GLSL initializer's value (`uniform float k = 0.5;`): the value where the
    /// manifest gives none, as in GL.
    pub initializer: Option<UniformValue>,
    /// `[lo, hi]` from the manifest.
    pub range: Option<(f64, f64)>,
    /// The manifest's semantic, or the one its name suggests (`guessed` is then true).
    pub semantic: Option<Semantic>,
    /// No manifest value and no initializer: the renderer guesses one (a semantic by name,
    /// else a constant).
    pub guessed: bool,
    /// Some stage reads it.
    pub read: bool,
    /// Its `#pragma parameter` (default, range, step): its host's menu, and its value where
    /// the manifest and an initializer give none.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub parameter: Option<crate::front::parameters::Parameter>,
}

/// The uniforms of every checked program (programs with errors have none to list).
pub fn uniforms(checked: &[Checked]) -> Vec<ProgramUniforms> {
    checked.iter().filter(|c| !c.failed).map(one).collect()
}

fn one(c: &Checked) -> ProgramUniforms {
    let mut uniforms: Vec<UniformInfo> = Vec::new();
    for unit in &c.units {
        let stages: Vec<_> = unit.program.stages.iter().map(|s| s.syntax.clone()).collect();
        let initial = crate::front::initial_values::of(&unit.program);
        for s in crate::link::declared::settable(&stages) {
            if uniforms.iter().any(|u| u.name == s.name) {
                continue;
            }
            let entry = unit.effect.as_ref().and_then(|e| e.uniforms.iter().find(|u| u.name == s.name));
            let guess = crate::manifest::guess::semantic_by_name(&s.name, shape(&s.ty), !s.ty.starts_with(['i', 'u', 'b']));
            let initializer = initial
                .iter()
                .find(|i| i.path == s.name && i.from == crate::front::initial_values::InitialFrom::Initializer)
                .map(|i| i.value.clone());
            // A `#pragma parameter`'s default is no guess either.
            let guessed = entry.is_none() && !initial.iter().any(|i| i.path == s.name);
            uniforms.push(UniformInfo {
                default: entry.and_then(|e| e.value.clone()),
                initializer,
                range: entry.and_then(|e| e.range),
                semantic: entry.map_or(guess.filter(|_| guessed), |e| e.semantic),
                guessed,
                parameter: unit.program.stages.iter().flat_map(|st| &st.syntax.parameters).find(|p| p.name == s.name).cloned(),
                name: s.name,
                ty: s.ty,
                read: s.read,
            });
        }
    }
    ProgramUniforms { program: c.name.clone(), uniforms }
}

/// `(columns, rows)` of a GLSL type name: `vec3` (1, 3), `mat4` (4, 4), `float` (1, 1).
fn shape(ty: &str) -> (u8, u8) {
    let digit = |s: &str| s.chars().last().and_then(|c| c.to_digit(10)).map_or(1, |d| d as u8);
    if let Some(m) = ty.strip_prefix("mat") {
        let n = digit(m);
        return (n, n);
    }
    if ty.contains("vec") {
        return (1, digit(ty));
    }
    (1, 1)
}

/// The listing as text: one block per program, one line per uniform.
pub fn text(programs: &[ProgramUniforms]) -> String {
    let mut out = String::new();
    for p in programs {
        out.push_str(&format!("{}: {} uniform{}\n", p.program, p.uniforms.len(), if p.uniforms.len() == 1 { "" } else { "s" }));
        for u in &p.uniforms {
            let mut what = Vec::new();
            if let Some(v) = &u.default {
                what.push(format!("default {}", serde_json::to_string(v).unwrap_or_default()));
            }
            if let (Some(v), None) = (&u.initializer, &u.default) {
                what.push(format!("initializer {}", serde_json::to_string(v).unwrap_or_default()));
            }
            if let Some((lo, hi)) = u.range {
                what.push(format!("range [{lo}, {hi}]"));
            }
            if let Some(p) = &u.parameter {
                let step = p.step.map(|s| format!(" step {s}")).unwrap_or_default();
                what.push(format!("#pragma parameter: default {} in [{}, {}]{step}", p.default, p.min, p.max));
            }
            match (u.semantic, u.guessed) {
                (Some(s), false) => what.push(format!("semantic {}", serde_json::to_string(&s).unwrap_or_default().trim_matches('"'))),
                (Some(s), true) => {
                    what.push(format!("guessed: semantic {}", serde_json::to_string(&s).unwrap_or_default().trim_matches('"')))
                }
                (None, true) => what.push("guessed: a constant (no manifest value)".into()),
                (None, false) => {}
            }
            if !u.read {
                what.push("never read".into());
            }
            out.push_str(&format!("  {:<20} {:<10} {}\n", u.name, u.ty, what.join(", ")));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    #[test]
    fn shapes_of_type_names() {
        assert_eq!(super::shape("vec3"), (1, 3));
        assert_eq!(super::shape("mat4"), (4, 4));
        assert_eq!(super::shape("float"), (1, 1));
        assert_eq!(super::shape("ivec2"), (1, 2));
    }
}
