//! Geometry stages folded into the vertex stage: the vertex and geometry stages' 4.50 texts
//! become one vertex-stage text that naga parses like any other (naga and WebGPU have no
//! geometry stage). The fold is a text-to-text pass before naga, so it lives in the front:
//! `check` validates the folded stage with naga and looks for hazards in it, and `translate`,
//! `render`, `stress` and `bench` receive a plain vertex + fragment program.
//!
//! The draw has [`GeometryLayout::slots_per_primitive`] vertices per input primitive. Each
//! invocation finds its primitive and the corner of the output primitive it draws from
//! `gl_VertexIndex`, pulls the primitive's vertices from two read-only storage buffers
//! ([`INDEX_BUFFER`], [`VERTEX_BUFFER`]: one `vec4` per vertex input per vertex), runs the
//! vertex stage once per corner of the input primitive, then the geometry stage, whose
//! `EmitVertex()` keeps the last three emitted vertices and captures the invocation's own.
//! Strips become lists in GL's order (odd triangles keep GL's winding); a slot no strip
//! fills lies outside the clip volume and draws nothing, so `max_vertices` holds and the
//! primitives rasterize in input order.
//!
//! Every global and function of the two stages is renamed apart (`effectc_vs_…`,
//! `effectc_gs_…`); uniforms, textures and samplers keep their names and the vertex stage's
//! declarations (the front gave both stages the same ones).
//!
//! `gl_Layer` and `gl_ViewportIndex` cannot route a primitive in WebGPU: the draw keeps the
//! primitives of the layer and viewport [`INDEX_BUFFER`]'s header names (−1: all), so a
//! layered target is drawn one layer per draw.
//!
//! The `gl_PrimitiveID` the geometry stage writes reaches a fragment stage that reads it as a
//! flat varying ([`Lowered::primitive_location`]; WebGPU has the built-in only as a feature).
//!
//! The varyings between the two stages become private variables
//! ([`interface`](crate::front::fold_parts::interface)): arrays, matrices, structs and blocks
//! (named or not) pass as GL passes them, matched by location. The stages before the
//! geometry stage are the vertex stage, or tessellation stages folded ahead of it
//! ([`Upstream`]).
//!
//! Not folded (an error naming the construct): arrays of struct varyings, arrays of blocks
//! other than the geometry stage's inputs, vertex inputs other than scalars, vectors and
//! arrays of them, `gl_Layer`/`gl_ViewportIndex`/`gl_PrimitiveID` in the vertex stage of a
//! geometry program.

use std::fmt::Write as _;

use crate::config::TargetEnv;
use crate::diag::FileId;
use crate::front::fold_parts::interface::{self, next_location};
use crate::front::fold_parts::part::{self, Part, Role};
use crate::front::fold_parts::{pull_corner, pulled_declarations, run_vertex, Piece};
pub use crate::front::fold_parts::{Folded, Lowered, Pulling, Shape, ATTRIBUTE_PREFIX, HEADER_WORDS, INDEX_BUFFER, VERTEX_BUFFER};
use crate::front::geometry_layout::{GeometryLayout, OutputPrimitive};
use crate::front::syntax::{self, StageSyntax};
use crate::stage::StageKind;

/// What runs before the geometry stage, once per corner of its input primitive.
pub enum Upstream<'a> {
    /// The vertex stage's 4.50 text.
    Vertex(&'a str),
    /// Tessellation stages folded ahead of it: each corner is a corner of a primitive they
    /// generate.
    Tessellated(crate::front::tessellation_fold::Upstream),
}

/// Folds `gs` (a geometry stage's 4.50 text) into the stages before it. `original` is the
/// geometry stage as the user wrote it, when known: the interpolation qualifiers of its
/// output block members (the 4.50 text leaves them out, as naga ignores them there).
pub fn lower(
    upstream: Upstream,
    gs: &str,
    layout: GeometryLayout,
    pulling: Pulling,
    original: Option<&StageSyntax>,
) -> Result<Lowered, String> {
    let g = syntax::analyse(FileId(0), gs, StageKind::Geometry, TargetEnv::Auto)
        .map_err(|_| "the rewritten geometry stage does not parse".to_string())?;
    let corners = layout.input.vertices();
    let mut text = String::from("#version 450\n");
    let mut pieces = Vec::new();
    let v = match &upstream {
        Upstream::Vertex(vs) => Some(
            syntax::analyse(FileId(0), vs, StageKind::Vertex, TargetEnv::Auto)
                .map_err(|_| "the rewritten vertex stage does not parse".to_string())?,
        ),
        Upstream::Tessellated(_) => None,
    };
    let vs_part = v.as_ref().map(|v| Part::new(v, "effectc_vs_", Role::Vertex, None)).transpose()?;
    let shared: Vec<&str> = match (&upstream, &v) {
        (Upstream::Tessellated(u), _) => u.shared.iter().map(String::as_str).collect(),
        (_, Some(v)) => part::shared_names(v),
        (Upstream::Vertex(_), None) => unreachable!("parsed above"),
    };
    let gs_part = Part::new(&g, "effectc_gs_", Role::Geometry { shared: &shared, corners }, original)?;
    let (source, (vertex_inputs, input_types), shape) = match (&upstream, &vs_part) {
        (Upstream::Tessellated(u), _) => {
            if u.layout.topology() != layout.input.list_topology() {
                return Err(format!(
                    "the geometry stage takes {} and the tessellation makes a {}",
                    layout.input.name(),
                    u.layout.topology()
                ));
            }
            let at = text.len();
            text.push_str(&u.text);
            pieces.extend(u.pieces.iter().cloned().map(|p| p.shifted(at)));
            let source = CornerSource::Tessellated { outputs: &u.outputs, per_primitive: u.layout.corners() };
            let shape = Shape::TessellatedGeometry { geometry: layout, layout: u.layout, patch_vertices: u.patch_vertices };
            (source, (u.vertex_inputs.clone(), u.input_types.clone()), shape)
        }
        (_, Some(vs)) => {
            text.push_str(&pulled_declarations(pulling, vs));
            // `gl_ClipDistance[]` only where read: it is 8 × 16 bytes of private memory per corner.
            let clip = if gs_part.reads_clip_distance { " float gl_ClipDistance[8];" } else { "" };
            writeln!(text, "struct effectc_PerVertex {{ vec4 gl_Position; float gl_PointSize;{clip} }};").unwrap();
            (CornerSource::Vertex(vs), vs.pulled_inputs(), Shape::Geometry(layout))
        }
        (Upstream::Vertex(_), None) => unreachable!("parsed above"),
    };
    writeln!(text, "effectc_PerVertex effectc_gl_in[{corners}];").unwrap();
    // The tessellation declares the vertex stage's globals itself.
    if let Some(vs) = &vs_part {
        text.push_str(
            "vec4 effectc_vs_gl_Position; float effectc_vs_gl_PointSize; vec4 effectc_gs_gl_Position; float effectc_gs_gl_PointSize;\n",
        );
        text.push_str("int effectc_PrimitiveIDIn; int effectc_InvocationID; int effectc_VertexID; int effectc_InstanceID;\n");
        text.push_str("int effectc_gs_gl_Layer; int effectc_gs_gl_ViewportIndex; int effectc_gs_gl_PrimitiveID;\n");
        text.push_str(&vs.declarations);
        text.push_str(&gs_part.declarations);
        Piece::append(&mut text, vs, StageKind::Vertex, &mut pieces);
    } else {
        text.push_str("vec4 effectc_gs_gl_Position; float effectc_gs_gl_PointSize; int effectc_PrimitiveIDIn; int effectc_InvocationID;\n");
        text.push_str("int effectc_gs_gl_Layer; int effectc_gs_gl_ViewportIndex; int effectc_gs_gl_PrimitiveID;\n");
        text.push_str(&gs_part.declarations);
    }
    text.push_str(&capture(&gs_part, layout.output));
    Piece::append(&mut text, &gs_part, StageKind::Geometry, &mut pieces);
    text.push_str(&driver(&source, &gs_part, layout, pulling)?);
    let (selects_layer, selects_viewport) = (gs_part.selects.contains("gl_Layer"), gs_part.selects.contains("gl_ViewportIndex"));
    let primitive_location = next_location(&gs_part.outputs);
    Ok(Lowered { text, shape, pulling, vertex_inputs, input_types, pieces, primitive_location, selects_layer, selects_viewport })
}

/// How the geometry stage's corners are made.
enum CornerSource<'p> {
    /// The vertex stage run on the corner's pulled vertex.
    Vertex(&'p Part),
    /// The tessellation's corner `k` of primitive `p`: its vertex `p × per_primitive + k`,
    /// whose evaluation leaves these outputs.
    Tessellated { outputs: &'p [interface::Leaf], per_primitive: u32 },
}

/// `effectc_emit()` and `effectc_end_primitive()`: the capture of the vertex this invocation
/// draws, without keeping the strip (no arrays indexed at run time, which a GPU compiler
/// keeps in memory): the wanted list primitive is the `f`-th of the strip that started when
/// `effectc_made` primitives were complete, and its corner is the strip's vertex `f + k`
/// (corners 0 and 1 swapped for odd triangles, GL's winding; each primitive begun at its
/// last vertex, GL's provoking vertex). The vertex is held when
/// emitted and kept when the primitive completes; a strip ended earlier drops it.
fn capture(gs: &Part, output: OutputPrimitive) -> String {
    let mut t = String::new();
    t.push_str("uint effectc_want_primitive; uint effectc_want_corner; bool effectc_found; bool effectc_held;\n");
    t.push_str("uint effectc_strip; uint effectc_made; uint effectc_strip_start;\n");
    t.push_str("vec4 effectc_cap_Position; int effectc_cap_Layer; int effectc_cap_ViewportIndex; int effectc_cap_PrimitiveID;\n");
    for (i, o) in gs.outputs.iter().enumerate() {
        writeln!(t, "{} effectc_cap_{i}{};", o.ty.base, syntax::dims_text(&o.ty)).unwrap();
    }
    let n = output.list_vertices();
    t.push_str("void effectc_emit() {\n    if (effectc_found) {\n        return;\n    }\n");
    t.push_str("    if (effectc_want_primitive >= effectc_strip_start) {\n");
    t.push_str("        uint f = effectc_want_primitive - effectc_strip_start;\n        uint k = effectc_want_corner;\n");
    // The list primitive starts at GL's provoking vertex, the strip's last of it (WebGPU
    // takes `flat` values from the first): (a, b, c) drawn as (c, a, b), (a, b) as (b, a).
    match output {
        OutputPrimitive::TriangleStrip => {
            t.push_str("        k = (k + 2u) % 3u;\n");
            t.push_str("        if ((f & 1u) == 1u && k < 2u) {\n            k = 1u - k;\n        }\n");
        }
        OutputPrimitive::LineStrip => t.push_str("        k = 1u - k;\n"),
        _ => {}
    }
    t.push_str("        if (effectc_strip == f + k) {\n            effectc_cap_Position = effectc_gs_gl_Position;\n");
    t.push_str(
        "            effectc_cap_Layer = effectc_gs_gl_Layer;\n            effectc_cap_ViewportIndex = effectc_gs_gl_ViewportIndex;\n            effectc_cap_PrimitiveID = effectc_gs_gl_PrimitiveID;\n",
    );
    for (i, o) in gs.outputs.iter().enumerate() {
        writeln!(t, "           {}", o.ty.copy(&format!("effectc_cap_{i}"), &o.access(None))).unwrap();
    }
    t.push_str("            effectc_held = true;\n        }\n    }\n");
    writeln!(t, "    effectc_strip += 1u;\n    if (effectc_strip >= {n}u) {{\n        effectc_made += 1u;\n    }}").unwrap();
    t.push_str("    effectc_found = effectc_held && effectc_made > effectc_want_primitive;\n}\n");
    t.push_str(
        "void effectc_end_primitive() {\n    effectc_strip = 0u;\n    effectc_strip_start = effectc_made;\n    effectc_held = false;\n}\n",
    );
    t
}

/// The real outputs (the geometry stage's, flattened at their locations) and `main`.
fn driver(source: &CornerSource, gs: &Part, layout: GeometryLayout, pulling: Pulling) -> Result<String, String> {
    let (mut t, mut assign) = interface::stage_outputs(&gs.outputs, |i, _| format!("effectc_cap_{i}"));
    writeln!(t, "layout(location = {}) flat out uint effectc_out_primitive;", next_location(&gs.outputs)).unwrap();
    writeln!(assign, "        effectc_out_primitive = uint(effectc_cap_PrimitiveID);").unwrap();
    let corners = layout.input.vertices();
    let per_invocation = layout.output.max_primitives(layout.max_vertices) * layout.output.list_vertices();
    let per_primitive = layout.slots_per_primitive();
    writeln!(t, "void main() {{\n    uint v = uint(gl_VertexIndex);\n    uint primitive = v / {per_primitive}u;").unwrap();
    writeln!(t, "    uint slot = v % {per_primitive}u;\n    effectc_InvocationID = int(slot / {per_invocation}u);").unwrap();
    writeln!(
        t,
        "    effectc_want_primitive = (slot % {per_invocation}u) / {0}u;\n    effectc_want_corner = slot % {0}u;",
        layout.output.list_vertices()
    )
    .unwrap();
    t.push_str("    effectc_found = false; effectc_held = false; effectc_strip = 0u; effectc_made = 0u; effectc_strip_start = 0u;\n");
    t.push_str("    effectc_gs_gl_Layer = 0; effectc_gs_gl_ViewportIndex = 0;\n");
    t.push_str("    effectc_PrimitiveIDIn = int(primitive); effectc_InstanceID = int(gl_InstanceIndex);\n");
    t.push_str("    effectc_gs_gl_PrimitiveID = effectc_PrimitiveIDIn;\n");
    // A tessellated corner past its patch's last primitive: nothing is drawn.
    let mut keep = String::from("effectc_found");
    if let CornerSource::Tessellated { .. } = source {
        t.push_str("    bool effectc_generated_corners = true;\n");
        keep.push_str(" && effectc_generated_corners");
    }
    // One block per corner with constant indices (no loop): the arrays stay in registers.
    for k in 0..corners {
        let outputs = match source {
            CornerSource::Vertex(vs) => {
                t.push_str(&pull_corner(vs, k, corners, pulling));
                t.push_str(&run_vertex(vs, &format!("effectc_gl_in[{k}]"), gs.reads_clip_distance));
                &vs.outputs[..]
            }
            CornerSource::Tessellated { outputs, per_primitive } => {
                writeln!(
                    t,
                    "    effectc_generated_corners = effectc_tess_vertex(primitive * {per_primitive}u + {k}u) && effectc_generated_corners;\n    effectc_gl_in[{k}].gl_Position = effectc_te_gl_Position;"
                )
                .unwrap();
                outputs
            }
        };
        for i in &gs.ins {
            // An input no earlier output feeds is undefined in GL: it stays zero here.
            let Some(statements) = interface::feed(i, Some(k), outputs, None) else { continue };
            writeln!(t, "   {statements}").unwrap();
        }
    }
    writeln!(t, "    {}main();", gs.prefix).unwrap();
    // The layer and viewport the draw keeps (−1: every one), from the index buffer's header.
    // The header is the buffer's first words (naga cannot load a member beside a
    // runtime-sized array).
    if let Pulling::Storage { .. } = pulling {
        for (word, (written, field, cap)) in
            [("gl_Layer", "layer", "Layer"), ("gl_ViewportIndex", "viewport", "ViewportIndex")].into_iter().enumerate()
        {
            if gs.selects.contains(written) {
                writeln!(t, "    int effectc_keep_{field} = int({INDEX_BUFFER}.index[{word}u]);").unwrap();
                write!(keep, " && (effectc_keep_{field} < 0 || effectc_cap_{cap} == effectc_keep_{field})").unwrap();
            }
        }
    }
    writeln!(t, "    if ({keep}) {{\n        gl_Position = effectc_cap_Position;").unwrap();
    t.push_str(&assign);
    t.push_str("    } else {\n        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);\n    }\n}\n");
    Ok(t)
}
