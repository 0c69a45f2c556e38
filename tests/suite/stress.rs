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

/// `programs[].hazards[]` of a `stress --confirm --format json` run as one line each:
/// program, code, tier, verdict and the confirming case (what stays the same between
/// machines with the same driver; the counts are asserted where they matter).
fn verdicts(json: &str) -> String {
    let doc: serde_json::Value = serde_json::from_str(json).unwrap_or_else(|e| panic!("{e}:\n{json}"));
    let mut lines = Vec::new();
    for program in doc["programs"].as_array().expect("programs") {
        for h in program["hazards"].as_array().expect("hazards") {
            let case = h["case"].as_str().map(|c| format!(" `{c}`")).unwrap_or_default();
            lines.push(format!(
                "{} {} {} {} {}{case}",
                program["program"].as_str().unwrap().rsplit('/').next().unwrap(),
                h["code"].as_str().unwrap(),
                h["at"].as_str().unwrap().rsplit('/').next().unwrap(),
                h["tier"].as_str().unwrap(),
                h["verdict"].as_str().unwrap()
            ));
        }
    }
    lines.join("\n")
}

#[test]
fn confirm_puts_every_seed_hazard_warning_to_a_render() {
    if !have_gpu() {
        return;
    }
    let seeds = [
        "tests/fail/42-hazard-flower-bend-warning",
        "tests/fail/43-hazard-bloom-time-warning",
        "tests/fail/44-hazard-sun-hash-warning",
        "tests/fail/45-hazard-degenerate-cross-warning",
        "tests/fail/46-hazard-zero-normal-warning",
        "tests/fail/47-hazard-loop-counter-warning",
        "tests/fail/48-hazard-pow-log-sqrt-warning",
        "tests/stress/explode-degenerate",
    ];
    let out = effectc(&[&["stress", "--confirm", "--format", "json"][..], &seeds].concat());
    let json = stdout(&out);
    // A confirmed warning is error E0703: the run fails.
    assert_eq!(code(&out), 1, "{json}");
    let table = verdicts(&json);
    // The flower's R = h / phi divides by 0 once the light stands overhead (lightX = 0, lightZ
    // at its default 0); the acos before it stays in [-1, 1] on this driver. The bloom's
    // sin passes 1e4 rad only at bFrequency's high end after the hour the analysis assumes;
    // the hash, the runaway march (at the defaults already: the march's path wraps round the
    // texture without meeting a texel above 0.6 in some pixels), and all four Phong terms
    // happen. The seed's exploding geometry stage gets a zero cross product from the
    // collapsed triangles of the degenerate mesh (in the fixture and in the stress test). No
    // pixel centre meets the flipped leaf normal exactly at zero, but it passes through zero
    // between neighbouring pixels, which confirms it too.
    let expected = "\
flower-bend W0711 flower.vert:38 possible refuted
flower-bend W0710 flower.vert:40 possible confirmed `lightX = 0`
bloom-time W0717 sun.frag:25 possible confirmed `bFrequency high at 3600 s`
sun-hash W0718 sun.vert:24 possible confirmed `defaults`
degenerate-cross W0715 explode.geom:32 possible confirmed `zero-area tris`
zero-normal W0715 leaf.frag:13 possible confirmed `defaults`
loop-counter W0719 march.frag:17 certain confirmed `defaults`
pow-log-sqrt W0714 phong.frag:27 possible confirmed `defaults`
pow-log-sqrt W0712 phong.frag:32 certain confirmed `sinT2Scale high`
pow-log-sqrt W0716 phong.frag:36 certain confirmed `lightFalloff low`
pow-log-sqrt W0713 phong.frag:39 certain confirmed `exposure low`
explode-degenerate W0715 shards.geom:12 possible confirmed `zero-area tris`";
    assert_eq!(table, expected, "{json}");
    let doc: serde_json::Value = serde_json::from_str(&json).unwrap();
    let hazard = |program: &str, code: &str| {
        let p = doc["programs"].as_array().unwrap().iter().find(|p| p["program"] == program).unwrap();
        p["hazards"].as_array().unwrap().iter().find(|h| h["code"] == code).unwrap().clone()
    };
    // Every pixel takes the sqrt of a negative number at sinT2Scale = 1.5.
    let sqrt = hazard("pow-log-sqrt", "W0712");
    assert_eq!((sqrt["held"].as_u64(), sqrt["invocations"].as_u64(), sqrt["stage"].as_str()), (Some(13552), Some(13552), Some("fragment")));
    // A zero between pixels is said so: no pixel centre held it.
    let leaf = hazard("zero-normal", "W0715");
    assert!(leaf["held"] == 0 && leaf["between"].as_u64().unwrap() > 0 && leaf["stage"] == "fragment", "{leaf}");
    // A refuted warning says how often its operation ran.
    let acos = hazard("flower-bend", "W0711");
    assert!(acos["held"] == 0 && acos["reached"].as_u64().unwrap() > 1000, "{acos}");
    // The human form: the table, the error with the case's values, the verdict on the warning.
    let human = stdout(&effectc(&["stress", "--confirm", seeds[0]]));
    assert!(human.contains("flower-bend — 2 hazard warnings"), "{human}");
    let error = diagnostic(&human, "error[E0703]: flower-bend: W0710 confirmed by a render");
    assert!(error.contains("flower.vert:40:15") && error.contains("case `lightX = 0`: lightX=0"), "{error}");
    assert!(error.contains("the divisor was 0 (or a denormal, which GPUs flush to 0) in 1264 of 1264 vertex invocations"), "{error}");
    let refuted = diagnostic(&human, "warning[W0711]");
    assert!(refuted.contains("`stress --confirm`: refuted: the operation ran in"), "{refuted}");
}

#[test]
fn confirm_finds_zeros_between_pixel_centres_only_in_values_that_pass_through_them() {
    if !have_gpu() {
        return;
    }
    // A full-window ramp crosses zero at x = 0.3, between two pixel centres of a 32-pixel
    // frame: the divisor and the normalized vector are confirmed. The same ramp's sign times
    // a positive value jumps from negative to positive without passing zero: refuted.
    let dir = scratch("stress", "confirm-between-pixels");
    std::fs::write(
        dir.join("ramp.vert"),
        "#version 330\nlayout(location = 0) in vec3 position;\nout vec2 vUv;\n\
void main() { vUv = position.xy * 0.5 + 0.5; gl_Position = vec4(position.xy, 0.0, 1.0); }\n",
    )
    .unwrap();
    std::fs::write(
        dir.join("ramp.frag"),
        "#version 330\nin vec2 vUv;\nout vec4 color;\nvoid main()\n{\n    float ramp = vUv.x - 0.3;\n    \
float jump = sign(ramp) * (vUv.y + 0.1);\n    float a = 1.0 / ramp;\n    float b = 1.0 / jump;\n    \
vec3 n = normalize(vec3(vUv.y - 0.3, 0.0, 0.0));\n    color = vec4(a, b, n.x, 1.0);\n}\n",
    )
    .unwrap();
    std::fs::write(
        dir.join("effect.toml"),
        "name = \"ramp\"\n[stages]\nvertex = \"ramp.vert\"\nfragment = \"ramp.frag\"\n[mesh]\nbuiltin = \"fullscreen_quad\"\n\
[mesh.attributes]\nposition = \"position\"\n",
    )
    .unwrap();
    let out = effectc(&["stress", "--confirm", "--format", "json", "--size", "32x32", dir.to_str().unwrap()]);
    let json = stdout(&out);
    assert_eq!(code(&out), 1, "{json}");
    assert_eq!(
        verdicts(&json),
        "ramp W0710 ramp.frag:8 possible confirmed `defaults`\nramp W0710 ramp.frag:9 possible refuted\nramp W0715 ramp.frag:10 possible confirmed `defaults`",
        "{json}"
    );
    let doc: serde_json::Value = serde_json::from_str(&json).unwrap();
    for h in doc["programs"][0]["hazards"].as_array().unwrap().iter().filter(|h| h["verdict"] == "confirmed") {
        // One column of pixels on each side of x = 0.3 (and of y = 0.3): 32 rows each.
        assert!(h["held"] == 0 && h["between"].as_u64().unwrap() >= 32, "{h}");
    }
    let human = stdout(&effectc(&["stress", "--confirm", "--size", "32x32", dir.to_str().unwrap()]));
    let error = diagnostic(&human, "error[E0703]: ramp: W0710 confirmed by a render");
    assert!(error.contains("the divisor passed through 0 between neighbouring pixel centres, next to"), "{error}");
    assert!(error.contains("no pixel centre of this frame lies on that zero"), "{error}");
}

#[test]
fn confirm_drives_pragma_parameters_from_their_defaults_to_their_ends() {
    if !have_gpu() {
        return;
    }
    // Undefined behaviour at a bare program's `#pragma parameter` values: the defaults
    // (SHIFT = 4, not 0) divide by zero, OFFSET's low end takes `%` of a negative number and
    // SHIFT's high end shifts by 40.
    let dir = scratch("stress", "confirm-parameters");
    std::fs::write(
        dir.join("ub.vert"),
        "#version 330\nlayout(location = 0) in vec2 position;\nvoid main() { gl_Position = vec4(position, 0.0, 1.0); }\n",
    )
    .unwrap();
    std::fs::write(
        dir.join("ub.frag"),
        "#version 330\n#pragma parameter SHIFT \"Shift\" 4.0 0.0 40.0 1.0\n#pragma parameter OFFSET \"Offset\" 1.0 -4.0 4.0 1.0\n\
uniform float SHIFT;\nuniform float OFFSET;\nout vec4 color;\nvoid main()\n{\n    int k = int(OFFSET) % 3;\n    uint m = 1u << uint(SHIFT);\n    \
float d = 1.0 / (SHIFT - 4.0);\n    color = vec4(float(k), float(m), d, 1.0);\n}\n",
    )
    .unwrap();
    let files = [dir.join("ub.vert"), dir.join("ub.frag")].map(|p| p.to_str().unwrap().to_string());
    let out = effectc(&["stress", "--confirm", "--format", "json", &files[0], &files[1], "--size", "32x32"]);
    let json = stdout(&out);
    assert_eq!(code(&out), 1, "{json}");
    assert_eq!(
        verdicts(&json),
        "ub W0720 ub.frag:9 certain confirmed `OFFSET low`\nub W0721 ub.frag:10 certain confirmed `SHIFT high`\nub W0710 ub.frag:11 certain confirmed `defaults`",
        "{json}"
    );
    // Without --confirm a bare program reports these certain warnings and draws no error.
    let plain = effectc(&["check", &files[0], &files[1]]);
    assert_eq!(code(&plain), 0, "{}", stdout(&plain));
}

#[test]
fn confirm_instruments_the_first_32_warnings_and_says_so_of_the_rest() {
    if !have_gpu() {
        return;
    }
    // 36 divisions by `P - k`: one bit each for the first 32, the other 4 are named untested
    // with the reason (not "not in the translation").
    let dir = scratch("stress", "confirm-crowded");
    std::fs::write(
        dir.join("many.vert"),
        "#version 330\nlayout(location = 0) in vec2 position;\nvoid main() { gl_Position = vec4(position, 0.0, 1.0); }\n",
    )
    .unwrap();
    let lines: String = (1..=36).map(|k| format!("    a += 1.0 / (P - {k}.0);\n")).collect();
    std::fs::write(
        dir.join("many.frag"),
        format!("#version 330\n#pragma parameter P \"P\" 0.0 0.0 40.0 1.0\nuniform float P;\nout vec4 color;\nvoid main()\n{{\n    float a = 0.0;\n{lines}    color = vec4(a);\n}}\n"),
    )
    .unwrap();
    let files = [dir.join("many.vert"), dir.join("many.frag")].map(|p| p.to_str().unwrap().to_string());
    let json = stdout(&effectc(&["stress", "--confirm", "--format", "json", "--size", "16x16", &files[0], &files[1]]));
    let doc: serde_json::Value = serde_json::from_str(&json).unwrap_or_else(|e| panic!("{e}:\n{json}"));
    let hazards = doc["programs"][0]["hazards"].as_array().expect("hazards");
    assert_eq!(hazards.len(), 36, "{json}");
    let untested: Vec<&serde_json::Value> = hazards.iter().filter(|h| h["verdict"] == "untested").collect();
    assert_eq!(untested.len(), 4, "{json}");
    assert!(untested.iter().all(|h| h["reason"] == "more than 32 warnings in one program: the first 32 are tested"), "{json}");
    // P's defaults and grid points divide by zero where P - k meets them (P = 0 never does).
    assert!(hazards.iter().any(|h| h["verdict"] == "confirmed"), "{json}");
}
