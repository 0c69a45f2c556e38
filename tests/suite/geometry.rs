//! Geometry stages on WebGPU: the fold of the vertex and geometry stages
//! (`effectc::front::geometry_fold`) validates, maps back to the user's files and names
//! what it cannot fold; a folded draw renders what the same triangles drawn directly
//! render, feature by feature (`tests/geometry/*/direct/`).
//!
//! Tolerance (stated): [`TOLERANCE`], a channel may differ by 2 of 255 in at most 0.1% of
//! the pixels. The two draws rasterize the same triangles, so they agree to the bit on
//! lavapipe; the allowance absorbs another rasterizer's rounding, not a missing triangle.

use std::path::Path;

use effectc::check::Checked;
use effectc::front::geometry_fold::{lower, Pulling, Upstream};
use effectc::front::geometry_layout::{geometry_layout, GeometryLayout, InputPrimitive};
use effectc::stage::StageKind;

use effectc::render::compare::{self, Tolerance};

use crate::common::{self, check, code, effectc, stdout};
use crate::render::have_gpu;

/// Per-channel difference allowed, and the share of pixels that may exceed it.
const TOLERANCE: Tolerance = Tolerance { channel: 2, max_differing: 0.001 };

/// The checked program of a fixture directory.
fn checked(dir: &str) -> Checked {
    let (_, mut checked) = check(Path::new(dir));
    checked.remove(0)
}

/// The fixture's vertex and geometry stages as the front rewrote them, and the layout.
fn rewritten(dir: &str) -> (String, String, GeometryLayout) {
    let c = checked(dir);
    let program = &c.units[0].program;
    let text = |kind: StageKind| program.stage(kind).unwrap().rewritten.as_ref().unwrap().text.clone();
    let layout = geometry_layout(&program.stage(StageKind::Geometry).unwrap().syntax).unwrap();
    (text(StageKind::Vertex), text(StageKind::Geometry), layout)
}

#[test]
fn every_geometry_program_folds_into_a_vertex_stage_naga_validates() {
    // (fixture, vertex inputs (location, name, components), draw slots per input primitive)
    type Inputs = &'static [(u32, &'static str, u32)];
    let expected: [(&str, Inputs, u32); 3] = [
        ("01-explode-textured", &[(0, "position", 3), (1, "uv", 2), (2, "normal", 3)], 3),
        ("02-points-to-quads", &[(0, "position", 3), (1, "color", 4)], 6),
        ("03-normal-lines", &[(0, "position", 3), (1, "normal", 3)], 10),
    ];
    for (name, inputs, slots) in expected {
        let c = checked(&format!("tests/geometry/{name}"));
        let folded = match &c.units[0].program.folded {
            Some(Ok(f)) => f,
            other => panic!("{name}: {:?}", other.as_ref().map(|r| r.as_ref().err())),
        };
        for (lowered, module) in [(&folded.drawn, &folded.naga.module), (&folded.analysed, &folded.analysis.module)] {
            assert_eq!(module.entry_points.len(), 1, "{name}");
            assert_eq!(module.entry_points[0].stage, naga::ShaderStage::Vertex, "{name}");
            let got: Vec<(u32, &str, u32)> = lowered.vertex_inputs.iter().map(|(l, n, c)| (*l, n.as_str(), *c)).collect();
            assert_eq!(got, inputs, "{name}");
            let effectc::front::geometry_fold::Shape::Geometry(layout) = lowered.shape else { panic!("{name}: not a geometry fold") };
            assert_eq!(layout.slots_per_primitive(), slots, "{name}");
        }
        // The drawn stage pulls its vertices; the analysed one reads them as vertex inputs.
        let located = |m: &naga::Module| {
            m.entry_points[0].function.arguments.iter().filter(|a| matches!(a.binding, Some(naga::Binding::Location { .. }))).count()
        };
        assert_eq!(located(&folded.naga.module), 0, "{name}");
        assert_eq!(located(&folded.analysis.module), inputs.len(), "{name}");
    }
}

#[test]
fn the_folded_text_maps_back_to_each_stage() {
    let (vs, gs, layout) = rewritten("tests/geometry/01-explode-textured");
    let lowered = lower(Upstream::Vertex(&vs), &gs, layout, Pulling::Attributes, None).unwrap();
    // The first `effectc_emit()` defines it; the second is the geometry stage's EmitVertex().
    let first = lowered.text.find("effectc_emit()").unwrap();
    let at = lowered.text[first + 1..].find("effectc_emit()").unwrap() + first + 1;
    let (stage, range) = lowered.locate(at..at + "effectc_emit()".len()).unwrap();
    assert_eq!((stage, &gs[range]), (StageKind::Geometry, "EmitVertex()"));
    // The vertex stage's `gl_Position = …`, renamed apart.
    let write = lowered.text.find("effectc_vs_gl_Position = ").unwrap();
    let (stage, range) = lowered.locate(write..write + "effectc_vs_gl_Position".len()).unwrap();
    assert_eq!((stage, &vs[range]), (StageKind::Vertex, "gl_Position"));
    assert_eq!(lowered.locate(0..5), None, "the generated header maps nowhere");
}

#[test]
fn what_is_not_folded_is_named_and_what_folds_differently_is_marked() {
    let (vs, gs, layout) = rewritten("tests/geometry/01-explode-textured");
    // Adjacency folds: gl_in[] has the six vertices GL_TRIANGLES_ADJACENCY gives.
    let adjacency = GeometryLayout { input: InputPrimitive::TrianglesAdjacency, ..layout };
    assert!(lower(Upstream::Vertex(&vs), &gs, adjacency, Pulling::Attributes, None).unwrap().text.contains("effectc_gl_in[6];"));
    // gl_PrimitiveID written by the geometry stage travels to the fragment stage as a flat
    // varying after the stage's outputs (shaded: locations 0 and 1, the fragment stage's
    // inputs being numbered first).
    let primitive_id = gs.replace("EmitVertex();", "gl_PrimitiveID = 7; EmitVertex();");
    let folded = lower(Upstream::Vertex(&vs), &primitive_id, layout, Pulling::Attributes, None).unwrap();
    assert_eq!(folded.primitive_location, 2);
    assert!(folded.text.contains("layout(location = 2) flat out uint effectc_out_primitive;"), "{}", folded.text);
    // In the vertex stage of a geometry program it is named.
    let in_vertex = vs.replace("void main() {", "void main() {\n    gl_Layer = 1;");
    assert_eq!(
        lower(Upstream::Vertex(&in_vertex), &gs, layout, Pulling::Attributes, None).unwrap_err(),
        "`gl_Layer` in the vertex stage of a geometry or tessellation program"
    );
    // A layer is not routed but selected: the draw keeps the primitives of one layer.
    let layered = gs.replace("EmitVertex();", "gl_Layer = 1; EmitVertex();");
    let storage = Pulling::Storage { index_binding: 8, vertex_binding: 9 };
    let folded = lower(Upstream::Vertex(&vs), &layered, layout, storage, None).unwrap();
    assert!(folded.selects_layer && !folded.selects_viewport);
    assert!(folded.text.contains("effectc_cap_Layer == effectc_keep_layer"), "{}", folded.text);
}

#[test]
fn inputs_holding_arrays_are_read_at_a_run_time_corner_through_an_accessor() {
    // `shades[next].tint[last]` indexed twice at run time takes llvmpipe minutes to compile
    // (a piglit program: 98 s, 3.6 s through the accessor); a literal corner and an input
    // without arrays (`gl_in[i].gl_Position`) stay plain indexing.
    let (vs, gs, layout) = rewritten("tests/geometry/13-corner-arrays/effect.toml");
    let text = lower(Upstream::Vertex(&vs), &gs, layout, Pulling::Attributes, None).unwrap().text;
    assert!(text.contains("effectc_gs_shades_block effectc_gs_shades_at(int k) { if (k == 0) return effectc_gs_shades[0];"), "{text}");
    assert!(text.contains("float[2] effectc_gs_weight_at(int k) {"), "{text}");
    assert!(text.contains("effectc_gs_shades_at(int(next)).tint[last]"), "{text}");
    assert!(text.contains("effectc_gs_weight_at(int(next))[last - 2]"), "{text}");
    assert!(text.contains("effectc_gl_in[i].gl_Position") && !text.contains("effectc_gl_in_at"), "{text}");
    let literal = gs.replace("shades[next].tint[last]", "shades[1].tint[last]");
    let text = lower(Upstream::Vertex(&vs), &literal, layout, Pulling::Attributes, None).unwrap().text;
    assert!(text.contains("effectc_gs_shades[1].tint[last]"), "{text}");
}

/// The fixtures with a manifest (`effect.toml`) and the expected image's manifest
/// (`direct/effect.toml`: the triangles the geometry stage emits, drawn without one).
fn compared_fixtures() -> Vec<std::path::PathBuf> {
    common::fixtures("tests/geometry", 13).into_iter().filter(|d| d.join("direct/effect.toml").is_file()).collect()
}

#[test]
fn folded_draws_render_what_the_same_triangles_drawn_directly_render() {
    if !have_gpu() {
        return;
    }
    // Per feature: strips with EndPrimitive (back faces culled, so a strip's odd triangles
    // must keep GL's winding) and unused slots; amplification to max_vertices; points →
    // quads; lines (a triangle mesh's edges) → bands; gl_PrimitiveIDIn; instancing;
    // gl_PrimitiveID written for the fragment stage; gl_Layer (the frame shows layer 0);
    // invocations = 3 (gl_InvocationID); a block's array member and an array of arrays read
    // at a run-time corner.
    let fixtures = compared_fixtures();
    if std::env::var("EFFECTC_FIXTURE").is_err() {
        assert_eq!(fixtures.len(), 10, "{fixtures:?}");
    }
    let mut failures = Vec::new();
    for dir in fixtures {
        let name = common::name_of(&dir);
        let frame = |manifest: &Path, what: &str| -> Result<(Vec<u8>, (u32, u32)), String> {
            let out_dir = common::scratch("geometry", &format!("{name}-{what}"));
            let out = effectc(&["render", manifest.to_str().unwrap(), "--frames", "1", "--out", out_dir.to_str().unwrap()]);
            if code(&out) != 0 {
                return Err(format!("{name} ({what}) does not render:\n{}", stdout(&out)));
            }
            let png = std::fs::read_dir(&out_dir).unwrap().map(|e| e.unwrap().path()).find(|p| p.extension().is_some_and(|e| e == "png"));
            let (rgba, w, h) = compare::read_png(&png.ok_or(format!("{name} ({what}): no frame"))?)?;
            Ok((rgba, (w, h)))
        };
        let (lowered, expected) = match (frame(&dir.join("effect.toml"), "folded"), frame(&dir.join("direct/effect.toml"), "direct")) {
            (Ok(a), Ok(b)) => (a, b),
            (a, b) => {
                failures.extend(a.err().into_iter().chain(b.err()));
                continue;
            }
        };
        // Not two black frames: the expected triangles cover part of the frame.
        let lit = expected.0.chunks_exact(4).filter(|p| p[..3] != [0, 0, 0]).count();
        let pixels = (expected.1 .0 * expected.1 .1) as usize;
        assert!(lit > pixels / 50 && lit < pixels, "{name}: the expected frame covers {lit} of {pixels} pixels");
        match compare::compare_sized(&expected.0, expected.1, &lowered.0, lowered.1, TOLERANCE) {
            Ok(r) if r.passed => {}
            Ok(r) => failures.push(format!("{name}: the folded draw differs from the direct one: {r:?}")),
            Err(e) => failures.push(format!("{name}: {e}")),
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
