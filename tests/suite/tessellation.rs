//! Tessellation on WebGPU: the fold of the vertex, control and evaluation stages
//! (`effectc::front::tessellation_fold`) validates, translates to WGSL naga and tint take,
//! and draws what Mesa's OpenGL driver draws from the same patches (`effectc verify`, at
//! its stated tolerance: 2/255 on at most 0.1% of the pixels). Fixtures whose frames differ
//! for a stated reason are listed in `tests/tessellation/known_differences.txt`.

use std::path::Path;

use crate::common::{self, code, effectc, scratch, stdout};

/// The fixture directories, sorted.
fn fixtures() -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir("tests/tessellation")
        .unwrap()
        .filter_map(|e| e.ok().filter(|e| e.path().is_dir()).and_then(|e| e.file_name().to_str().map(str::to_owned)))
        .collect();
    names.sort();
    names
}

#[test]
fn every_tessellation_program_folds_into_a_vertex_stage_naga_validates() {
    // (fixture, patch vertices, slots per patch at the level cap of 64)
    let expected = [
        ("01-triangles", 3, 3 * (64 * 3 + 3 * 62 + (1..32).map(|i| 3 * ((64 - 2 * i) + (62 - 2 * i))).sum::<u32>())),
        ("02-quads", 4, 3 * (2 * 62 * 62 + 4 * (64 + 62))),
        ("03-isolines", 4, 2 * 64 * 64),
        ("04-evaluation-only", 3, 0),
        ("05-barrier", 3, 0),
        ("06-with-geometry", 3, 0),
    ];
    assert_eq!(fixtures().len(), expected.len());
    for (name, patch, slots) in expected {
        let (_, mut checked) = common::check(Path::new(&format!("tests/tessellation/{name}")));
        let c = checked.remove(0);
        let folded = match &c.units[0].program.folded {
            Some(Ok(f)) => f,
            other => panic!("{name}: {:?}", other.as_ref().map(|r| r.as_ref().err())),
        };
        use effectc::front::geometry_fold::Shape;
        let (Shape::Tessellation { layout, patch_vertices } | Shape::TessellatedGeometry { layout, patch_vertices, .. }) =
            folded.drawn.shape
        else {
            panic!("{name}: not a tessellation fold")
        };
        // A geometry stage after the tessellation takes its triangles.
        assert_eq!(matches!(folded.drawn.shape, Shape::TessellatedGeometry { .. }), name == "06-with-geometry", "{name}");
        assert_eq!(patch_vertices, patch, "{name}");
        if slots > 0 {
            assert_eq!(layout.slots_per_patch(64), slots, "{name}");
        }
        for module in [&folded.naga.module, &folded.analysis.module] {
            assert_eq!(module.entry_points.len(), 1, "{name}");
            assert_eq!(module.entry_points[0].stage, naga::ShaderStage::Vertex, "{name}");
        }
    }
}

#[test]
fn tessellation_translates_to_wgsl_with_its_draw_plan() {
    for name in fixtures() {
        let out_dir = scratch("tessellation-translate", &name);
        let dir = format!("tests/tessellation/{name}");
        let out = effectc(&["translate", &dir, "--to", "wgsl,spv", "--explain", "--out", out_dir.to_str().unwrap()]);
        let text = stdout(&out);
        assert_eq!(code(&out), 0, "{name}: {text}");
        assert!(text.contains("tessellation stages folded into the vertex stage"), "{name}: {text}");
        assert!(text.contains("u32 level cap, u32 tessellated vertices per patch"), "{name}: {text}");
        let wgsl = std::fs::read_dir(&out_dir).unwrap().filter_map(|e| e.ok()).find(|e| e.path().extension().is_some_and(|x| x == "wgsl"));
        let wgsl = std::fs::read_to_string(wgsl.expect("a .wgsl file").path()).unwrap();
        assert_eq!(wgsl.matches("@vertex").count(), 1, "{name}");
        assert!(wgsl.contains("effectc_indices"), "{name}: the folded stage pulls its patches");
    }
}

#[test]
fn tessellation_draws_what_the_gl_driver_draws() {
    let ok = effectc::verify::context::GlContext::new();
    if let Err(e) = ok {
        assert!(!common::in_ci(), "CI needs an OpenGL driver: {}", e.0);
        eprintln!("no OpenGL driver ({}): tessellation verify skipped", e.0);
        return;
    }
    let text = std::fs::read_to_string("tests/tessellation/known_differences.txt").unwrap();
    let known: Vec<&str> =
        text.lines().filter(|l| !l.starts_with('#') && !l.trim().is_empty()).filter_map(|l| l.split_whitespace().next()).collect();
    let names = fixtures();
    for k in &known {
        assert!(names.iter().any(|n| n == k), "known difference `{k}` names no fixture");
    }
    let mut wrong = Vec::new();
    for name in &names {
        let out_dir = scratch("tessellation-verify", name);
        let dir = format!("tests/tessellation/{name}");
        let out = effectc(&["verify", &dir, "--size", "128x128", "--format", "json", "--out", out_dir.to_str().unwrap()]);
        let v: serde_json::Value = serde_json::from_str(&stdout(&out)).unwrap_or_default();
        let programs = v["programs"].as_array().cloned().unwrap_or_default();
        let matched = code(&out) == 0 && programs.len() == 1 && programs[0]["matches"] == true;
        match (matched, known.contains(&name.as_str())) {
            (true, true) => wrong.push(format!("{name}: matches now; remove it from tests/tessellation/known_differences.txt")),
            (false, false) => wrong.push(format!("{name}: does not match the GL driver (exit {})\n{}", code(&out), stdout(&out))),
            _ => {}
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}
