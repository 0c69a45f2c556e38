//! Geometry stages on WebGPU: the fold of the vertex and geometry stages
//! (`effectc::front::geometry_fold`) validates, maps back to the user's files and names
//! what it cannot fold.

use std::path::Path;

use effectc::check::Checked;
use effectc::front::geometry_fold::{lower, Pulling};
use effectc::front::geometry_layout::{geometry_layout, GeometryLayout, InputPrimitive};
use effectc::stage::StageKind;

use crate::common::check;

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
            assert_eq!(lowered.layout.slots_per_primitive(), slots, "{name}");
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
    let lowered = lower(&vs, &gs, layout, Pulling::Attributes).unwrap();
    // The first `effectc_emit()` defines it; the second is the geometry stage's EmitVertex().
    let first = lowered.text.find("effectc_emit()").unwrap();
    let at = lowered.text[first + 1..].find("effectc_emit()").unwrap() + first + 1;
    let (stage, range) = lowered.locate(at..at + "effectc_emit()".len()).unwrap();
    assert_eq!((stage, &gs[range]), (StageKind::Geometry, "EmitVertex()"));
    // The vertex stage's `gl_Position = …`, renamed apart.
    let write = lowered.text.find("effectc_vs_Position = ").unwrap();
    let (stage, range) = lowered.locate(write..write + "effectc_vs_Position".len()).unwrap();
    assert_eq!((stage, &vs[range]), (StageKind::Vertex, "gl_Position"));
    assert_eq!(lowered.locate(0..5), None, "the generated header maps nowhere");
}

#[test]
fn what_is_not_folded_is_named() {
    let (vs, gs, layout) = rewritten("tests/geometry/01-explode-textured");
    let adjacency = GeometryLayout { input: InputPrimitive::TrianglesAdjacency, ..layout };
    assert_eq!(
        lower(&vs, &gs, adjacency, Pulling::Attributes).unwrap_err(),
        "a `triangles_adjacency` geometry input (adjacency is not lowered)"
    );
    let layered = gs.replace("EmitVertex();", "gl_Layer = 1; EmitVertex();");
    assert_eq!(lower(&vs, &layered, layout, Pulling::Attributes).unwrap_err(), "`gl_Layer` written by a geometry stage");
}
