//! `[instances]`: instanced drawing, with per-instance vertex inputs and where their values
//! come from.

use std::ops::Range;

/// `[instances]`: instanced drawing (one draw call, `count` instances).
#[derive(Debug, Clone, PartialEq)]
pub struct InstancesDecl {
    pub span: Range<usize>,
    /// 1–1 000 000.
    pub count: u32,
    /// Per-instance vertex inputs, in manifest order.
    pub attributes: Vec<InstanceAttribute>,
}

/// One vertex input fed the manifest's own numbers, and where they come from: one value
/// per instance (`[instances.attributes]`) or per vertex (a table in `[mesh.attributes]`).
#[derive(Debug, Clone, PartialEq)]
pub struct InstanceAttribute {
    /// The vertex shader input it feeds.
    pub input: String,
    pub input_span: Range<usize>,
    pub source: InstanceSource,
    /// Components per value (1–4).
    pub components: usize,
}

/// Where per-instance (or per-vertex) values come from; `i` below is the instance's (or
/// the vertex's) index.
#[derive(Debug, Clone, PartialEq)]
pub enum InstanceSource {
    /// Exactly `count` values (each 1–4 numbers).
    Values(Vec<[f32; 4]>),
    /// Uniformly random in the box `[lo, hi]` per component, from `seed` (deterministic).
    Random { lo: [f32; 4], hi: [f32; 4], seed: u32 },
    /// `start + i × step` for instance `i`.
    Sequence { start: [f32; 4], step: [f32; 4] },
}

/// Most instances `[instances] count` accepts.
pub const MAX_INSTANCES: u32 = 1_000_000;
