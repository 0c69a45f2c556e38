//! The interface between two consecutive stages: outputs of one against inputs of the next.
//!
//! Loose varyings match by variable name, interface blocks by *block* name (instance names
//! may differ). Matched pairs must agree on type and array size, interpolation, `centroid`
//! and explicit locations. Inputs of the tessellation and geometry stages are per-vertex
//! arrays of the previous stage's outputs (`in vec3 n[]` matches `out vec3 n`), and so are
//! the tessellation control stage's outputs. Built-ins (`gl_*`, `gl_PerVertex`) are left to
//! the compiler.
//!
//! An unmatched input block is paired with the previous stage's unmatched output block that
//! most likely was meant (same members, else shared member names, else the only one left),
//! so the classic `out vert_out {…}` / `in vert_vars {…}` mismatch is one diagnostic, not
//! one per member plus an unread-output warning.
//!
//! The checks run in this order, each in its own file: `geometry` (geometry inputs are
//! arrays), `locations` (inputs matched by explicit location), `loose_inputs` (loose
//! varyings by name), `block_inputs` (interface blocks by block name) and `unread`
//! (outputs nothing accounts for).

use std::collections::HashSet;

use super::is_builtin;
use crate::diag::Diagnostic;
use crate::front::syntax::{Global, GlslType, StageSyntax, Storage};
use crate::stage::StageKind;

mod block_inputs;
mod geometry;
mod locations;
mod loose_inputs;
mod unread;

/// Direction of a global across a stage boundary.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dir {
    In,
    Out,
}

/// Whether `g` is a user input or output of `stage` at a stage boundary (vertex inputs and
/// fragment outputs face the application, not another stage).
pub fn direction(stage: StageKind, g: &Global) -> Option<Dir> {
    match (g.storage, stage) {
        (_, StageKind::Compute) => None,
        (Storage::Out, StageKind::Fragment) => None,
        (Storage::Out, _) => Some(Dir::Out),
        (Storage::Varying, StageKind::Vertex) => Some(Dir::Out),
        (Storage::Varying, _) => Some(Dir::In),
        (Storage::In, StageKind::Vertex) => None,
        (Storage::In, _) => Some(Dir::In),
        _ => None,
    }
}

/// Stages whose inputs are arrays with one element per vertex.
fn arrayed_inputs(kind: StageKind) -> bool {
    matches!(kind, StageKind::TessControl | StageKind::TessEval | StageKind::Geometry)
}

/// Whether input `gi` of `s` has one element per vertex (a geometry or tessellation
/// stage's, or a fragment input qualified `pervertexEXT`).
fn input_arrayed(s: &StageSyntax, gi: usize) -> bool {
    let g = &s.globals[gi];
    arrayed_inputs(s.stage) || s.per_vertex.iter().any(|o| g.decl_span.contains(o))
}

/// Stages whose outputs are arrays with one element per vertex.
fn arrayed_outputs(kind: StageKind) -> bool {
    kind == StageKind::TessControl
}

/// Drops the per-vertex array dimension.
fn per_vertex(dims: &[Option<u32>], arrayed: bool) -> Vec<Option<u32>> {
    if arrayed && !dims.is_empty() {
        dims[1..].to_vec()
    } else {
        dims.to_vec()
    }
}

fn dims_text(dims: &[Option<u32>]) -> String {
    GlslType { base: String::new(), dims: dims.to_vec() }.to_string()
}

/// Indices of a stage's loose and block inputs or outputs.
struct Ports {
    loose: Vec<usize>,
    blocks: Vec<usize>,
}

fn ports(s: &StageSyntax, dir: Dir) -> Ports {
    let mut p = Ports { loose: Vec::new(), blocks: Vec::new() };
    for (i, g) in s.globals.iter().enumerate() {
        if direction(s.stage, g) != Some(dir) || is_builtin(s, g) {
            continue;
        }
        if g.is_block() {
            p.blocks.push(i);
        } else {
            p.loose.push(i);
        }
    }
    p
}

/// Both stages follow the GLSL ≥ 4.30 rule that interpolation and `centroid` may differ.
fn qualifiers_relaxed(a: &StageSyntax, b: &StageSyntax) -> bool {
    !a.version.is_es() && !b.version.is_es() && a.version.number >= 430 && b.version.number >= 430
}

struct Pair<'a> {
    a: &'a StageSyntax,
    b: &'a StageSyntax,
    at: &'static str,
    bt: &'static str,
    outs: Ports,
    ins: Ports,
    /// Outputs of `a` accounted for (matched, or part of a diagnostic about an input).
    consumed: HashSet<usize>,
    out: &'a mut Vec<Diagnostic>,
}

/// All link checks between stage `a` and the next stage `b`.
pub fn check_pair(a: &StageSyntax, b: &StageSyntax, out: &mut Vec<Diagnostic>) {
    let mut p = Pair {
        a,
        b,
        at: a.stage.title(),
        bt: b.stage.title(),
        outs: ports(a, Dir::Out),
        ins: ports(b, Dir::In),
        consumed: HashSet::new(),
        out,
    };
    p.arrayed_geometry_inputs();
    p.location_inputs();
    p.loose_inputs();
    p.block_inputs();
    p.unread_outputs();
}

/// Whether a stage is written in Vulkan GLSL (interfaces match by location only).
pub fn is_vulkan(s: &StageSyntax) -> bool {
    s.vulkan
}

impl Pair<'_> {
    fn aname(&self, i: usize) -> &str {
        self.a.original_name(&self.a.globals[i].name)
    }
    fn bname(&self, i: usize) -> &str {
        self.b.original_name(&self.b.globals[i].name)
    }
}
