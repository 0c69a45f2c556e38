//! What the folds share: one stage of a folded program ([`part`]), the varyings between
//! folded stages ([`interface`]), the lowered vertex-stage text with its map back to the
//! stages ([`Lowered`]), and the glue that pulls a primitive's vertices from storage buffers
//! and runs the vertex stage on them. [`geometry_fold`](crate::front::geometry_fold) and
//! [`tessellation_fold`](crate::front::tessellation_fold) build on it.

pub(crate) mod interface;
pub(crate) mod part;

use std::fmt::Write as _;
use std::ops::Range;

use crate::front::edits::OffsetMap;
use crate::front::geometry_layout::GeometryLayout;
use crate::front::naga_run::Validated;
use crate::front::syntax::GlslType;
use crate::front::tessellator::TessLayout;
use crate::stage::StageKind;
use part::{Part, PRIVATE_BUILTINS};

/// Name of the storage buffer of vertex indices (three, two or one per input primitive),
/// as the translated code names it (its block type is `EffectcIndices`).
pub const INDEX_BUFFER: &str = "effectc_indices";
/// Words before the indices in [`INDEX_BUFFER`]: the layer and the viewport a draw keeps
/// (as `i32`, −1 for all), two unused.
pub const HEADER_WORDS: u32 = 4;
/// Name of the storage buffer of vertex inputs, `vec4` per input (in location order) per
/// vertex, as the translated code names it (its block type is `EffectcVertices`).
pub const VERTEX_BUFFER: &str = "effectc_vertices";

/// Prefix of the vertex inputs of the [`Pulling::Attributes`] fold (the user's names could
/// clash with the geometry stage's globals); the input is the user's input of that name.
pub const ATTRIBUTE_PREFIX: &str = "effectc_in_";

/// Where the folded stage reads its primitives' vertices.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pulling {
    /// From [`INDEX_BUFFER`] and [`VERTEX_BUFFER`] at these bindings of group 0: the stage
    /// that is drawn.
    Storage { index_binding: u32, vertex_binding: u32 },
    /// Every corner from the vertex inputs, as declared (location and name): a stage for the
    /// static analysis, whose facts about vertex inputs are known by location and name.
    Attributes,
}

/// The lowered vertex stage and what drawing it needs.
#[derive(Debug, Clone)]
pub struct Lowered {
    /// GLSL 4.50 vertex-stage text.
    pub text: String,
    pub shape: Shape,
    pub pulling: Pulling,
    /// The vertex stage's inputs in the order of their `vec4`s in [`VERTEX_BUFFER`]:
    /// (location, name as the user wrote it, components).
    pub vertex_inputs: Vec<(u32, String, u32)>,
    /// The GLSL type of each of `vertex_inputs` (`vec3`, `uvec2`, `int`): an integer input
    /// travels as its bit pattern in the `vec4`.
    pub input_types: Vec<String>,
    /// The parts of `text` copied from the rewritten stages, with their offset maps.
    pub(crate) pieces: Vec<Piece>,
    /// The flat `uint` output at this location carries the `gl_PrimitiveID` the geometry stage
    /// wrote (its input primitive's number when it wrote none) to a fragment stage that reads
    /// `gl_PrimitiveID` (WebGPU has it only as an optional feature).
    pub primitive_location: u32,
    /// The geometry stage writes `gl_Layer` / `gl_ViewportIndex`: the draw keeps only the
    /// primitives of the layer and viewport named in [`INDEX_BUFFER`]'s header.
    pub selects_layer: bool,
    pub selects_viewport: bool,
}

/// What the folded draw stands for: a geometry stage's primitives, or the tessellation
/// of patches of `patch_vertices` vertices.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    Geometry(GeometryLayout),
    Tessellation {
        layout: TessLayout,
        patch_vertices: u32,
    },
    /// A geometry stage fed by the tessellation's primitives.
    TessellatedGeometry {
        geometry: GeometryLayout,
        layout: TessLayout,
        patch_vertices: u32,
    },
}

/// A range of the lowered text that came from one stage's rewritten text.
#[derive(Debug, Clone)]
pub(crate) struct Piece {
    pub range: Range<usize>,
    pub stage: StageKind,
    pub map: OffsetMap,
}

impl Piece {
    /// The same piece in a text that begins `by` bytes earlier.
    pub(crate) fn shifted(self, by: usize) -> Piece {
        Piece { range: self.range.start + by..self.range.end + by, ..self }
    }

    /// Appends `part`'s body to `text`, recording where it lies.
    pub(crate) fn append(text: &mut String, part: &Part, stage: StageKind, pieces: &mut Vec<Piece>) {
        let start = text.len();
        text.push_str(&part.body);
        pieces.push(Piece { range: start..text.len(), stage, map: part.map.clone() });
        text.push('\n');
    }
}

impl Lowered {
    /// The stage and the range of its rewritten text a range of the lowered text came from
    /// (None for the generated glue).
    pub fn locate(&self, range: Range<usize>) -> Option<(StageKind, Range<usize>)> {
        let p = self.pieces.iter().find(|p| p.range.start <= range.start && range.end <= p.range.end)?;
        Some((p.stage, p.map.range_to_original(range.start - p.range.start..range.end - p.range.start)))
    }
}

/// A folded program: the lowered text that is drawn, with its validated module, and the
/// analysis variant (vertex inputs as attributes) with its module.
#[derive(Debug)]
pub struct Folded {
    pub drawn: Lowered,
    pub naga: Validated,
    pub analysed: Lowered,
    pub analysis: Validated,
}

/// The storage buffers a [`Pulling::Storage`] fold reads, or the vertex stage's inputs as
/// attributes for a [`Pulling::Attributes`] one.
pub(crate) fn pulled_declarations(pulling: Pulling, vs: &Part) -> String {
    let mut text = String::new();
    match pulling {
        Pulling::Storage { index_binding, vertex_binding } => {
            writeln!(
                text,
                "layout(std430, set = 0, binding = {index_binding}) readonly buffer EffectcIndices {{ uint index[]; }} {INDEX_BUFFER};"
            )
            .unwrap();
            writeln!(
                text,
                "layout(std430, set = 0, binding = {vertex_binding}) readonly buffer EffectcVertices {{ vec4 vertex[]; }} {VERTEX_BUFFER};"
            )
            .unwrap();
        }
        Pulling::Attributes => {
            for (location, name, _, ty) in &vs.inputs {
                writeln!(text, "layout(location = {location}) in {ty} {ATTRIBUTE_PREFIX}{};", attribute_name(name)).unwrap();
            }
        }
    }
    text
}

/// The attribute's name for a pulled input (`Position[1]`, an element of an array input,
/// is `Position_1`).
pub fn attribute_name(input: &str) -> String {
    input.replace('[', "_").replace(']', "")
}

/// The statements that load corner `k` (of `corners` per primitive, the primitive's number
/// in `primitive`) into the vertex stage's private inputs and set `effectc_VertexID`.
pub(crate) fn pull_corner(vs: &Part, k: u32, corners: u32, pulling: Pulling) -> String {
    let mut t = String::new();
    let stride = vs.inputs.len();
    match pulling {
        Pulling::Storage { .. } => {
            writeln!(
                t,
                "    uint index{k} = {INDEX_BUFFER}.index[{HEADER_WORDS}u + primitive * {corners}u + {k}u];\n    effectc_VertexID = int(index{k});"
            )
            .unwrap();
            for (i, (_, name, components, ty)) in vs.inputs.iter().enumerate() {
                let swizzle = ["x", "xy", "xyz", "xyzw"][*components as usize - 1];
                // Integers travel as their bit patterns.
                let bits = match ty.chars().next() {
                    Some('i') => "floatBitsToInt",
                    Some('u') => "floatBitsToUint",
                    _ => "",
                };
                writeln!(t, "    {}{name} = {bits}({VERTEX_BUFFER}.vertex[index{k} * {stride}u + {i}u]).{swizzle};", vs.prefix).unwrap();
            }
        }
        Pulling::Attributes => {
            t.push_str("    effectc_VertexID = int(gl_VertexIndex);\n");
            for (_, name, _, _) in &vs.inputs {
                writeln!(t, "    {}{name} = {ATTRIBUTE_PREFIX}{};", vs.prefix, attribute_name(name)).unwrap();
            }
        }
    }
    t
}

/// Runs the vertex stage and copies its built-in outputs into `gl_in` (the corner's
/// `effectc_PerVertex`; `gl_ClipDistance` only when `clip`).
pub(crate) fn run_vertex(vs: &Part, gl_in: &str, clip: bool) -> String {
    let mut t = format!("    {}main();\n    {gl_in}.gl_Position = effectc_vs_gl_Position;\n", vs.prefix);
    for (private, member, length) in PRIVATE_BUILTINS {
        let Some((_, declared)) = vs.private_builtins.iter().find(|(p, _)| *p == private) else { continue };
        if member != "gl_ClipDistance" || clip {
            // gl_in[]'s array is the largest; the vertex stage's may be shorter.
            let length = length.map(|l| declared.map_or(l, |d| d.min(l)));
            let ty = GlslType { base: "float".into(), dims: length.into_iter().map(Some).collect() };
            writeln!(t, "   {}", ty.copy(&format!("{gl_in}.{member}"), &format!("{}{private}", vs.prefix))).unwrap();
        }
    }
    t
}
