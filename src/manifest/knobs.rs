//! `[knobs]`: the uniforms `effectc bench` sweeps.

use std::ops::Range;

/// One `[knobs]` entry: a quality knob (a `[uniforms]` entry) and the values to sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct KnobDecl {
    /// The uniform's name (an entry of `[uniforms]`).
    pub name: String,
    pub name_span: Range<usize>,
    /// Values to sweep, in manifest order.
    pub values: Vec<f64>,
    /// The most accurate value, which the others are compared with (one of `values`).
    pub reference: f64,
}
