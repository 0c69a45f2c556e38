//! The inputs a program declares ranges for, which `stress` varies: a manifest uniform's
//! `range`, and RetroArch's `#pragma parameter NAME "Label" default min max step`
//! ([`crate::front::parameters`]), whose host starts it at its default and moves it in its
//! steps.

use crate::check;
use crate::manifest::UniformValue;
use crate::stress::{fill, numeric};

/// An input the analysis took a range for.
#[derive(Debug, Clone)]
pub struct Declared {
    pub name: String,
    pub default: UniformValue,
    pub lo: f64,
    pub hi: f64,
    pub step: Option<f64>,
}

impl Declared {
    /// `x` on the input's grid: a `#pragma parameter` moves in its steps from its minimum
    /// (its host offers no other value), within its range.
    pub fn on_grid(&self, x: f64) -> f64 {
        let x = match self.step {
            Some(s) => self.lo + ((x - self.lo) / s).round() * s,
            None => x,
        };
        // `-1 + 10 × 0.1` is 0 on the grid, not 1e-17.
        let x = if x.abs() < 1e-9 * self.step.unwrap_or(1.0).max(1e-9) { 0.0 } else { x };
        x.clamp(self.lo, self.hi)
    }
}

/// The declared inputs of `c`: the manifest's ranged numbers, then the `#pragma parameter`s
/// of its stages the manifest does not set; none that `--set` fixed.
pub fn declared(c: &check::Checked) -> Vec<Declared> {
    let mut out: Vec<Declared> = Vec::new();
    if let Some(e) = &c.effect {
        for u in &e.uniforms {
            let (Some((lo, hi)), Some(v)) = (u.range, u.value.as_ref()) else { continue };
            if numeric(v) {
                out.push(Declared { name: u.name.clone(), default: v.clone(), lo, hi, step: None });
            }
        }
    }
    let set_by_manifest = |name: &str| c.effect.as_ref().is_some_and(|e| e.uniform(name).is_some());
    out.retain(|d| !c.values.iter().any(|(n, _)| *n == d.name));
    let fixed = |name: &str| c.values.iter().any(|(n, _)| n == name);
    for unit in &c.units {
        for p in unit.program.stages.iter().flat_map(|s| &s.syntax.parameters) {
            if set_by_manifest(&p.name) || fixed(&p.name) || out.iter().any(|d| d.name == p.name) {
                continue;
            }
            out.push(Declared { name: p.name.clone(), default: UniformValue::Float(p.default), lo: p.min, hi: p.max, step: p.step });
        }
    }
    out
}

/// A case's values, and every other declared input at its default: a `#pragma parameter`
/// starts at its default, as its host sets it, not at zero.
pub fn with_defaults(overrides: &[(String, UniformValue)], inputs: &[Declared]) -> Vec<(String, UniformValue)> {
    let mut out = overrides.to_vec();
    for d in inputs {
        if !out.iter().any(|(n, _)| *n == d.name) {
            out.push((d.name.clone(), d.default.clone()));
        }
    }
    out
}

/// `samples` seeded random points of the inputs' ranges, each value on its input's grid
/// (none without inputs).
pub fn random_points(inputs: &[Declared], samples: u32, seed: u32) -> Vec<Vec<(String, UniformValue)>> {
    if inputs.is_empty() {
        return Vec::new();
    }
    (0..samples)
        .map(|k| {
            inputs
                .iter()
                .enumerate()
                .map(|(i, d)| {
                    let pick = |c: u32| {
                        d.lo + (d.hi - d.lo) * f64::from(crate::render::attributes::unit_random(seed.wrapping_add(k), i as u32, c))
                    };
                    (d.name.clone(), fill(&d.default, &|c| d.on_grid(pick(c))))
                })
                .collect()
        })
        .collect()
}
