//! `effectc stress`: seed hazards found by rendering at the ends of the ranges and on
//! degenerate geometry, reported at the manifest's `range` (or mesh) with the culprit
//! expression located in the vertex or fragment stage; the shipped effects come out clean.

use effectc::diag::Code;

use crate::common::{code, effectc, scratch, stdout};
use crate::render::have_gpu;

#[test]
fn seed_hazards_are_found_at_the_end_of_their_range() {
    if !have_gpu() {
        return;
    }
    let dir = scratch("stress", "seeds");
    let out = effectc(&["stress", "tests/stress", "--samples", "2", "--out", dir.to_str().unwrap()]);
    let text = stdout(&out);
    assert_eq!(code(&out), 1, "{text}");
    // Seed 003's blur curve divides by (bloomRange - 1): every pixel NaN at bloomRange = 1.
    assert!(text.contains("error[E0701]: bloom-curve: case `bloomRange low` renders 16384 NaN and 0 Inf pixels"), "{text}");
    assert!(text.contains("bloom-curve/effect.toml:9:35"), "at the range [1, 33]:\n{text}");
    assert!(text.contains("`bloomRange` = 1 in this range"), "{text}");
    // The culprit: the instrumented fragment stage names the division by (ranger - 1), the
    // first non-finite value in every pixel, at its span in blur.frag.
    assert!(text.contains("bloom-curve/blur.frag:20:58"), "{text}");
    assert!(text.contains("the first non-finite value (division) in 16384 of 16384 fragment invocations"), "{text}");
    // Seed 003's asin latitude: NaN where |z| > 1, only at the high end.
    assert!(text.contains("error[E0701]: asin-latitude: case `radiusScale high`"), "{text}");
    assert!(!text.contains("case `radiusScale low`"), "{text}");
    assert!(dir.join("bloom-curve_bloomRange_low_nonfinite.png").is_file());
    // Every case's counts, as `--format json` reports them: the nominal frames are clean
    // (the hazards are at the edges only), and full-screen programs draw no mesh a
    // geometry case could change (no such cases).
    let json = stress_json(&["tests/stress", "--samples", "2", "--out", dir.to_str().unwrap()]);
    snapshot("stress-seeds", &json.replace(dir.to_str().unwrap(), "[out]"));
}

/// The `--format json` document of a stress run with what differs between machines made
/// stable: the adapter's name, the mask directory (file names kept) and the largest change
/// from the nominal frame rounded to 1e-3.
fn stress_json(args: &[&str]) -> String {
    let out = effectc(&[&["stress", "--format", "json"][..], args].concat());
    let mut doc: serde_json::Value = serde_json::from_str(&stdout(&out)).unwrap_or_else(|e| panic!("{e}:\n{}", stdout(&out)));
    doc["adapter"] = "[adapter]".into();
    for program in doc["programs"].as_array_mut().expect("programs") {
        for case in program["cases"].as_array_mut().expect("cases") {
            if let Some(mask) = case["mask"].as_str() {
                case["mask"] = mask.rsplit('/').next().unwrap_or(mask).into();
            }
            let delta = case["max_delta"].as_f64().expect("max_delta");
            case["max_delta"] = ((delta * 1e3).round() / 1e3).into();
        }
    }
    serde_json::to_string_pretty(&doc).unwrap()
}

fn snapshot(name: &str, text: &str) {
    let mut settings = insta::Settings::clone_current();
    settings.set_snapshot_path("../../snapshots/stress");
    settings.set_prepend_module_to_snapshot(false);
    settings.set_omit_expression(true);
    settings.bind(|| insta::assert_snapshot!(name, text));
}

/// The body of one diagnostic: from its header line to the next blank line.
fn diagnostic<'t>(text: &'t str, header: &str) -> &'t str {
    let start = text.find(header).unwrap_or_else(|| panic!("no `{header}` in:\n{text}"));
    let rest = &text[start..];
    &rest[..rest.find("\n\n").unwrap_or(rest.len())]
}

#[test]
fn degenerate_geometry_finds_zero_normals_in_either_stage() {
    if !have_gpu() {
        return;
    }
    let out = effectc(&["stress", "tests/stress/zero-normal", "tests/stress/gouraud-degenerate", "--samples", "1"]);
    let text = stdout(&out);
    // Seed 002's Phong normalizes the interpolated normal per pixel: with the mesh's normals
    // zero that is 0/0 in every fragment (lavapipe's normalize returns 0, so the frame stays
    // finite and the warning says the NaN is hidden). The culprit is at its GLSL span.
    let phong = diagnostic(&text, "warning[W0702]: zero-normal: case `zero normals`");
    assert!(phong.contains("zero-normal/effect.toml:15:1") && phong.contains("this mesh, made degenerate"), "{phong}");
    assert!(phong.contains("zero-normal/phong.frag:14:17"), "{phong}");
    assert!(phong.contains("the first non-finite value (normalize) in"), "{phong}");
    assert!(phong.contains("degenerate geometry: all 559 normals zero"), "{phong}");
    // Gouraud lighting normalizes per vertex: the collapsed triangles' zero normals are NaN
    // in the vertex stage, though those triangles cover no pixel.
    let gouraud = diagnostic(&text, "warning[W0702]: gouraud-degenerate: case `zero-area tris`");
    assert!(gouraud.contains("gouraud-degenerate/gouraud.vert:20:17"), "{gouraud}");
    assert!(gouraud.contains("the first non-finite value (normalize) in 18 of 36 vertex invocations"), "{gouraud}");
    assert!(gouraud.contains("degenerate geometry: 6 of 12 triangles collapsed to zero area"), "{gouraud}");
    // The nominal mesh is fine in both.
    assert!(!text.contains("case `nominal`"), "{text}");
    // Per case: bad vertices (18 in the collapsed triangles) and fragments, NaN/Inf pixels.
    snapshot("stress-gouraud-degenerate", &stress_json(&["tests/stress/gouraud-degenerate", "--samples", "1"]));
}

#[test]
fn shipped_effects_are_clean_under_stress() {
    if !have_gpu() {
        return;
    }
    let dir = scratch("stress", "effects");
    let out = effectc(&["stress", "effects", "--samples", "2", "--size", "64x64", "--out", dir.to_str().unwrap()]);
    let text = stdout(&out);
    assert_eq!(code(&out), 0, "{text}");
    assert_eq!(text.matches(": no NaN or Inf").count(), 21, "{text}");
    // No intermediate value is non-finite either (W0702 would say where).
    assert!(!text.contains(Code::StressHiddenNonFinite.as_str()), "{text}");
}

#[test]
fn degenerate_triangles_reach_the_geometry_stage() {
    if !have_gpu() {
        return;
    }
    // The exploding mesh normalizes each face's cross product in its geometry stage, which
    // runs folded into the vertex stage. Statically, `check` finds the unguarded normalize…
    let fixture = "tests/stress/explode-degenerate";
    let checked = stdout(&effectc(&["check", fixture]));
    let warning = diagnostic(&checked, "warning[W0715]: `normalize` of a vector that can be zero");
    assert!(warning.contains("explode-degenerate/shards.geom:12:12"), "{checked}");
    // …and dynamically, only the zero-area case computes it non-finite, at the same span.
    let out = effectc(&["stress", fixture, "--samples", "1", "--size", "64x64", "--out", scratch("stress", "explode").to_str().unwrap()]);
    let text = stdout(&out);
    let case = diagnostic(&text, "warning[W0702]: explode-degenerate: case `zero-area tris`");
    assert!(case.contains("explode-degenerate/shards.geom:12:12"), "{case}");
    assert!(case.contains("the first non-finite value (normalize) in"), "{case}");
    assert!(case.contains("degenerate geometry: 6 of 12 triangles collapsed to zero area"), "{case}");
    assert_eq!(text.matches("warning[W0702]").count(), 1, "the intact cube is clean in every other case:\n{text}");
}
