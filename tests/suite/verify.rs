//! `effectc verify`: every shipped effect and every program of the semantics suite
//! (`tests/verify/semantics/`: one fragment stage each behind the shared full-screen vertex
//! stage, or a directory holding a program's own stages) draws the same picture through the translation as through the system's OpenGL
//! driver (Mesa's llvmpipe in CI; never skipped there). Programs that do not match yet are
//! listed in `tests/verify/known_failures.txt`, and an entry that starts matching fails.

use std::path::Path;

use crate::common::{code, effectc, fixtures, in_ci, name_of, scratch, stdout};
use crate::render::have_gpu;

/// Frame size of the semantics programs (they are written for 64×64).
const SEMANTICS_SIZE: &str = "64x64";
/// Programs in the semantics suite.
const SEMANTICS: usize = 101;

/// Programs in the compatibility-profile suite (`tests/verify/compat/`: one directory per
/// program, GLSL 1.10–1.50 reading fixed-function state).
const COMPAT: usize = 57;

/// Whether verify can run here: CI must have a GL driver and an adapter.
fn can_verify() -> bool {
    if !have_gpu() {
        return false;
    }
    let ok = effectc::verify::context::GlContext::new();
    if let Err(e) = &ok {
        assert!(!in_ci(), "no OpenGL driver in CI: {}", e.0);
        eprintln!("no OpenGL driver ({}): verify tests skipped", e.0);
    }
    ok.is_ok()
}

#[test]
fn every_effect_matches_the_gl_driver() {
    if !can_verify() {
        return;
    }
    let mut failures = Vec::new();
    for effect in fixtures("effects", 21) {
        let name = name_of(&effect);
        let out_dir = scratch("verify", &name);
        let manifest = effect.join("effect.toml");
        let args = ["verify", manifest.to_str().unwrap(), "--frames", "4", "--size", "128x128", "--out", out_dir.to_str().unwrap()];
        let out = effectc(&args);
        let text = stdout(&out);
        if code(&out) != 0 || !text.contains("4/4 frames match") {
            failures.push(format!("{name}: exit {}\n{text}", code(&out)));
        }
        // Every frame is written three ways when they differ at all: the translation, GL, the heat map.
        assert!(out_dir.join(format!("{name}_0003_gl.png")).is_file(), "{name}: no GL frame written\n{text}");
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// A driver that crashes on one program (simulated: the child process that draws aborts on
/// the first program) costs that program's verdict only: E0502 names it, the other program
/// is verified, and effectc exits 1 with its report, not with the signal.
#[test]
fn a_driver_crash_costs_one_programs_verdict() {
    if !can_verify() {
        return;
    }
    let dir = Path::new("tests/verify/semantics");
    let (a, b) = (dir.join("anonymous_structs"), dir.join("flat_aggregates"));
    let out_dir = scratch("verify-crash", "two");
    let args = [
        "verify",
        a.to_str().unwrap(),
        b.to_str().unwrap(),
        "--format",
        "json",
        "--size",
        SEMANTICS_SIZE,
        "--out",
        out_dir.to_str().unwrap(),
    ];
    let run = |fault: Option<&str>| {
        let mut c = std::process::Command::new(env!("CARGO_BIN_EXE_effectc"));
        c.args(args);
        if let Some(f) = fault {
            c.env("EFFECTC_VERIFY_FAULT", f);
        }
        c.output().unwrap()
    };
    let clean = run(None);
    assert_eq!(code(&clean), 0, "{}", stdout(&clean));
    let out = run(Some("0"));
    let text = stdout(&out);
    assert_eq!(code(&out), 1, "{text}");
    let doc: serde_json::Value = serde_json::from_str(&text).expect("one JSON report");
    let crashes: Vec<&serde_json::Value> =
        doc["diagnostics"]["diagnostics"].as_array().unwrap().iter().filter(|d| d["code"] == "E0502").collect();
    assert_eq!(crashes.len(), 1, "{text}");
    assert!(crashes[0]["message"].as_str().unwrap().contains("SIGABRT"), "{text}");
    assert_eq!(doc["programs"].as_array().unwrap().len(), 1, "the other program is verified: {text}");
}

fn known_failures() -> Vec<String> {
    let text = std::fs::read_to_string("tests/verify/known_failures.txt").unwrap();
    text.lines().filter(|l| !l.starts_with('#') && !l.trim().is_empty()).map(|l| l.split_whitespace().next().unwrap().to_string()).collect()
}

#[test]
fn semantics_programs_match_the_gl_driver() {
    if !can_verify() {
        return;
    }
    let dir = Path::new("tests/verify/semantics");
    let mut programs: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| {
            let e = e.ok()?;
            let name = e.file_name().to_str()?.to_owned();
            if e.path().is_dir() {
                Some(name)
            } else {
                name.strip_suffix(".frag").map(str::to_owned)
            }
        })
        .collect();
    programs.sort();
    assert_eq!(programs.len(), SEMANTICS, "tests/verify/semantics: expected {SEMANTICS} programs");
    let known = known_failures();
    for k in &known {
        assert!(programs.contains(k), "known failure `{k}` names no program");
    }
    let vertex = dir.join("fullscreen.vert");
    let mut wrong = Vec::new();
    for p in &programs {
        let own = dir.join(p);
        let frag = dir.join(format!("{p}.frag"));
        // A directory is a program of its own; a fragment stage goes behind the shared vertex stage.
        let stages: Vec<&str> =
            if own.is_dir() { vec![own.to_str().unwrap()] } else { vec![vertex.to_str().unwrap(), frag.to_str().unwrap()] };
        let out_dir = scratch("verify-semantics", p);
        let mut args = vec!["verify"];
        args.extend(stages);
        args.extend(["--size", SEMANTICS_SIZE, "--format", "json", "--out", out_dir.to_str().unwrap()]);
        let out = effectc(&args);
        let text = stdout(&out);
        let matched = code(&out) == 0 && json_matches(&text);
        match (matched, known.contains(p)) {
            (true, true) => wrong.push(format!("{p}: matches now; remove it from tests/verify/known_failures.txt")),
            (false, false) => wrong.push(format!("{p}: does not match the GL driver (exit {})\n{text}", code(&out))),
            _ => {}
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// Every compatibility-profile program (fixed-function attributes, matrices and their
/// forms, light, material, fog, point and plane state at GL's initial values, the
/// fixed-function varyings, uniform initializers) draws what Mesa's GL draws.
#[test]
fn compatibility_programs_match_the_gl_driver() {
    if !can_verify() {
        return;
    }
    let dir = Path::new("tests/verify/compat");
    let mut programs: Vec<_> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).filter(|p| p.is_dir()).collect();
    programs.sort();
    assert_eq!(programs.len(), COMPAT, "tests/verify/compat: expected {COMPAT} programs");
    let mut wrong = Vec::new();
    for p in &programs {
        let name = name_of(p);
        let out_dir = scratch("verify-compat", &name);
        let args = ["verify", p.to_str().unwrap(), "--size", SEMANTICS_SIZE, "--format", "json", "--out", out_dir.to_str().unwrap()];
        let out = effectc(&args);
        let text = stdout(&out);
        if code(&out) != 0 || !json_matches(&text) {
            wrong.push(format!("{name}: does not match the GL driver (exit {})\n{text}", code(&out)));
        }
        // Fixed-function state is GL's, not a guess: no W0401/W0403 for it.
        assert!(!text.contains("\"W0403\"") && !text.contains("\"W0401\""), "{name}: fixed-function state reported as a guess\n{text}");
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// The JSON report has one program, all of whose frames match.
fn json_matches(text: &str) -> bool {
    let v: serde_json::Value = serde_json::from_str(text).unwrap_or_default();
    let programs = v["programs"].as_array().cloned().unwrap_or_default();
    programs.len() == 1 && programs[0]["matches"] == true
}

#[test]
fn a_mismatch_is_e0503_with_the_three_pictures() {
    if !can_verify() {
        return;
    }
    let out_dir = scratch("verify", "mismatch");
    let vertex = Path::new("tests/verify/semantics/fullscreen.vert");
    let frag = Path::new("tests/verify/undefined/negative_remainder.frag");
    let out = effectc(&["verify", vertex.to_str().unwrap(), frag.to_str().unwrap(), "--size", "64x64", "--out", out_dir.to_str().unwrap()]);
    let text = stdout(&out);
    assert_eq!(code(&out), 1, "{text}");
    assert!(text.contains("error[E0503]") && text.contains("heat map:"), "{text}");
    // The check warning about the undefined `%` is there, and the mismatch names it.
    assert!(text.contains("warning[W0720]") && text.contains("GLSL leaves undefined") && text.contains("(W0720)"), "{text}");
    for suffix in ["", "_gl", "_diff"] {
        assert!(out_dir.join(format!("fullscreen_0000{suffix}.png")).is_file(), "no fullscreen_0000{suffix}.png\n{text}");
    }
    // A tolerance wide enough for the difference makes it a match.
    let out = effectc(&[
        "verify",
        vertex.to_str().unwrap(),
        frag.to_str().unwrap(),
        "--size",
        "64x64",
        "--max-differing",
        "60",
        "--out",
        out_dir.to_str().unwrap(),
    ]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
}

#[test]
fn vulkan_glsl_is_not_verified() {
    if !can_verify() {
        return;
    }
    let program = Path::new("tests/through_spirv/02-vulkan-push-constants-gather");
    let out = effectc(&["verify", program.to_str().unwrap(), "--out", scratch("verify", "vulkan").to_str().unwrap()]);
    let text = stdout(&out);
    assert_eq!(code(&out), 1, "{text}");
    assert!(text.contains("error[E0504]") && !text.contains("match"), "{text}");
}

#[test]
fn undefined_behaviour_is_warned_at_its_line() {
    let dir = Path::new("tests/verify/undefined");
    for (file, warning, line) in
        [("negative_remainder.frag", "W0720", 10), ("shift_out_of_range.frag", "W0721", 9), ("atan_origin.frag", "W0722", 9)]
    {
        let vertex = Path::new("tests/verify/semantics/fullscreen.vert");
        // Possible hazards: they depend on the frame's size and what the draw covers.
        let out =
            effectc(&["check", "--color", "never", "--hazards", "possible", vertex.to_str().unwrap(), dir.join(file).to_str().unwrap()]);
        let text = stdout(&out);
        assert_eq!(code(&out), 0, "{file}: warnings only\n{text}");
        assert!(text.contains(&format!("warning[{warning}]")), "{file}: no {warning}\n{text}");
        assert!(text.contains(&format!("{file}:{line}:")), "{file}: {warning} not at line {line}\n{text}");
    }
}

#[test]
fn render_verify_compares_like_verify() {
    if !can_verify() {
        return;
    }
    let out_dir = scratch("verify", "render-verify");
    let out = effectc(&["render", "--verify", "effects/phong", "--size", "64x64", "--out", out_dir.to_str().unwrap()]);
    let text = stdout(&out);
    assert_eq!(code(&out), 0, "{text}");
    assert!(text.contains("verified phong: 1/1 frame match"), "{text}");
    assert!(out_dir.join("phong_0000_gl.png").is_file(), "{text}");
}

#[test]
fn a_driver_error_is_placed_at_the_users_line() {
    if !can_verify() {
        return;
    }
    let vertex = Path::new("tests/verify/semantics/fullscreen.vert");
    let frag = Path::new("tests/verify/driver_rejects/late_extension.frag");
    let out_dir = scratch("verify", "driver-rejects");
    let out =
        effectc(&["verify", "--color", "never", vertex.to_str().unwrap(), frag.to_str().unwrap(), "--out", out_dir.to_str().unwrap()]);
    let text = stdout(&out);
    assert_eq!(code(&out), 1, "{text}");
    assert!(text.contains("error[E0502]") && text.contains("late_extension.frag:5:1"), "{text}");
    assert!(text.contains("#extension directive is not allowed"), "the driver's own words are kept\n{text}");
}

/// The programs of `tests/rewrite/` that do not match GL, and what verify says instead.
const REWRITE_EXPECTED: &[(&str, &str)] = &[
    // glslang links these; Mesa does not (its words are shown at the program).
    ("28-v440-location-matching", "error[E0502]"),
    // Vulkan GLSL is not compared.
    ("30-v450-vulkan-resources", "error[E0504]"),
    ("48-v450-vulkan-subpass-input", "error[E0504]"),
    ("49-v450-vulkan-unsigned-texture", "error[E0504]"),
    ("50-v460-vulkan-base-instance", "error[E0504]"),
    // gl_PointCoord outside points is undefined (N0104 named in the note).
    ("35-v330-point-sprite", "error[E0503]"),
    // Mesa's GL driver has no 16-bit float extension (glslang takes it in GL GLSL).
    ("55-v450-float16-varyings", "error[E0502]"),
    // An external image binds in GL only from an EGLImage, which verify's GL side does not
    // make: GL samples nothing (the note names the uniform verify cannot feed).
    ("63-es100-external-image", "a type verify cannot feed yet"),
];

#[test]
fn every_rewrite_program_matches_the_gl_driver() {
    if !can_verify() {
        return;
    }
    let mut wrong = Vec::new();
    for dir in crate::common::fixtures("tests/rewrite", crate::common::REWRITE_FIXTURES) {
        let name = name_of(&dir);
        let out = effectc(&[
            "verify",
            "--color",
            "never",
            dir.to_str().unwrap(),
            "--size",
            "64x64",
            "--out",
            scratch("verify-rewrite", &name).to_str().unwrap(),
        ]);
        let text = stdout(&out);
        match REWRITE_EXPECTED.iter().find(|(n, _)| *n == name) {
            Some((_, expected)) if !text.contains(expected) => wrong.push(format!("{name}: expected {expected}\n{text}")),
            None if code(&out) != 0 || !text.contains("1/1 frame match") => wrong.push(format!("{name}: exit {}\n{text}", code(&out))),
            _ => {}
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn gl_defaults_leave_unset_uniforms_at_zero_as_gl_does() {
    // Without a value anywhere, `render` guesses (white for `color`, W0403); with
    // `--gl-defaults` the uniform is zero, as GL starts it, and the frame still matches GL.
    if !can_verify() {
        return;
    }
    let dir = scratch("verify-gl-defaults", "program");
    std::fs::create_dir_all(&dir).unwrap();
    let vert = dir.join("gd.vert");
    let frag = dir.join("gd.frag");
    std::fs::write(&vert, "#version 120\nvoid main() { gl_Position = gl_Vertex; }\n").unwrap();
    std::fs::write(&frag, "#version 120\nuniform vec4 color;\nuniform float k = 0.5;\nvoid main() { gl_FragColor = color + vec4(k); }\n")
        .unwrap();
    let (v, f) = (vert.to_str().unwrap(), frag.to_str().unwrap());
    let guessed = effectc(&["verify", v, f, "--size", "16x16", "--out", dir.join("guessed").to_str().unwrap()]);
    assert!(code(&guessed) == 0 && stdout(&guessed).contains("W0403"), "{}", stdout(&guessed));
    let zero = effectc(&["verify", v, f, "--size", "16x16", "--gl-defaults", "--out", dir.join("zero").to_str().unwrap()]);
    assert!(code(&zero) == 0 && !stdout(&zero).contains("W0403"), "{}", stdout(&zero));
    let png = image::open(dir.join("zero/gd_0000.png")).unwrap().to_rgba8();
    // color = 0, k = its initializer 0.5.
    assert_eq!(png.get_pixel(8, 8).0, [128, 128, 128, 128]);
}

/// `[mesh.attributes]` tables feed vertex inputs of any type the manifest's own numbers, one
/// per vertex (`values`, `sequence`, `random`), integers included: both drivers draw the same
/// picture from them, and a `values` list of another length than the mesh's is an error.
#[test]
fn manifest_values_feed_vertex_inputs_of_any_type() {
    if !can_verify() {
        return;
    }
    let dir = scratch("verify-vertex-values", "program");
    let out = effectc(&["verify", "tests/verify/vertex_values/effect.toml", "--size", "64x64", "--out", dir.join("o").to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let png = image::open(dir.join("o/vertex-values_0000.png")).unwrap().to_rgba8();
    // Each triangle's flat `aIds` from its provoking vertex, GL's last (ids.x 2 and 3, read as
    // x / 4): the quad's lower left triangle ends at its upper left corner (vertex 2), the
    // upper right one at its upper right corner (vertex 3).
    let (lower_left, upper_right) = (png.get_pixel(16, 48).0, png.get_pixel(48, 16).0);
    assert_eq!((lower_left[0], upper_right[0]), (128, 191), "{lower_left:?} {upper_right:?}");
    // The `sequence` interpolates across the quad; the `random` mask's w is 100..250.
    assert_ne!(png.get_pixel(20, 44).0[2], png.get_pixel(44, 20).0[2]);
    assert!(lower_left[3] >= 100 && upper_right[3] >= 100, "{lower_left:?} {upper_right:?}");
    let bad = dir.join("bad");
    std::fs::create_dir_all(&bad).unwrap();
    for f in ["va.vert", "va.frag"] {
        std::fs::copy(Path::new("tests/verify/vertex_values").join(f), bad.join(f)).unwrap();
    }
    let manifest = std::fs::read_to_string("tests/verify/vertex_values/effect.toml").unwrap().replace("[3, 7]]", "[3, 7], [1, 1]]");
    std::fs::write(bad.join("effect.toml"), manifest).unwrap();
    let wrong = effectc(&["render", bad.join("effect.toml").to_str().unwrap(), "--out", dir.join("w").to_str().unwrap()]);
    assert_eq!(code(&wrong), 1, "{}", stdout(&wrong));
    assert!(stdout(&wrong).contains("`mesh.attributes.aIds` has 5 values for a mesh of 4 vertices"), "{}", stdout(&wrong));
}

#[test]
fn members_of_instance_named_blocks_take_values_by_gl_names() {
    // `uniform Block { vec4 a; } block_name;`: GL names the member `Block.a`; `--set` and the
    // manifest take that name (or `block_name.a`), and GL draws the same picture.
    if !can_verify() {
        return;
    }
    let dir = scratch("verify-named-block", "program");
    std::fs::create_dir_all(&dir).unwrap();
    let vert = dir.join("nb.vert");
    let frag = dir.join("nb.frag");
    std::fs::write(&vert, "#version 150\nin vec4 position;\nvoid main() { gl_Position = position; }\n").unwrap();
    std::fs::write(
        &frag,
        "#version 150\nlayout(std140) uniform Block { vec4 pad; vec4 a; } block_name;\nout vec4 c;\nvoid main() { c = block_name.a; }\n",
    )
    .unwrap();
    let (v, f) = (vert.to_str().unwrap(), frag.to_str().unwrap());
    let out = effectc(&["verify", v, f, "--size", "16x16", "--set", "Block.a=0.25,1,0.5,1", "--out", dir.join("o").to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let png = image::open(dir.join("o/nb_0000.png")).unwrap().to_rgba8();
    assert_eq!(png.get_pixel(8, 8).0, [64, 255, 128, 255]);
    let wrong = effectc(&["render", v, f, "--set", "Block.b=1", "--out", dir.join("w").to_str().unwrap()]);
    assert_eq!(code(&wrong), 1, "{}", stdout(&wrong));
    assert!(stdout(&wrong).contains("`Block.a`"), "{}", stdout(&wrong));
}

/// Row-major block matrices (a member's layout, a block's, and `column_major` overriding
/// it) hold the values `--set` gives them as GLSL reads them: effectc stores them
/// transposed as GL does, and the picture is GL's and the one the values give.
#[test]
fn row_major_block_matrices_hold_the_values_set_by_name() {
    if !can_verify() {
        return;
    }
    let dir = scratch("verify-row-major", "program");
    let out = effectc(&[
        "verify",
        "tests/verify/ubo/row_major.vert",
        "tests/verify/ubo/row_major.frag",
        "--set",
        "turn=0.1,0.2,0.3,0.4,0.5,0.6,0.7,0.8,0.9",
        "--set",
        "plain=0,0,0,0.3,0.4,0,0,0,0",
        "--set",
        "Mixed.whole=0.05,0.6,0,0,0.3,0,0,0,0,0,0,0,0,0,0,0",
        "--set",
        "Mixed.kept=0,0,0,0,0,0,0,0,0.7,0.2,0,0,0,0,0,0",
        "--size",
        "16x16",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let png = image::open(dir.join("row_major_0000.png")).unwrap().to_rgba8();
    // turn's first column (0.1, 0.2, 0.3) + plain[1] (0.3, 0.4, 0); whole[0] (0.05, 0.6, …)
    // + kept's third column (0.7, 0.2, …); halved: (0.2, 0.675, 0.4, 0.5).
    assert_eq!(png.get_pixel(8, 8).0, [51, 172, 102, 128]);
}

/// The user's own std140 blocks with `bool`s and arrays of scalars and 2-vectors (stored in
/// WGSL as words and 4-vectors, same offsets) draw what GL draws for the values `--set`
/// gives them, and other values draw another picture.
#[test]
fn std140_block_members_wgsl_cannot_hold_read_as_gl_reads_them() {
    if !can_verify() {
        return;
    }
    let stages = ["tests/verify/ubo/std140.vert", "tests/verify/ubo/std140.frag"];
    let values = [
        [
            "r=true",
            "gb=false,true",
            "weights=0.1,0.2,0.3,0.05",
            "on=false,true",
            "Params.f=0.05,0.1,0.15",
            "Params.use_f=true",
            "Shading.gain=0.5",
        ],
        [
            "r=false",
            "gb=true,true",
            "weights=0.3,0.1,0.1,0.25",
            "on=true,false",
            "Params.f=0.15,0.1,0.05",
            "Params.use_f=true",
            "Shading.gain=0.25",
        ],
    ];
    // Structs in a block at std140's offsets (fillers where naga would pack them tighter).
    let shading = [
        ["Shading.shade.tint.r=0.4", "Shading.shade.gb=0.1,0.05", "Shading.shade.a=0.1", "Shading.bias=0.05"],
        ["Shading.shade.tint.r=0.8", "Shading.shade.gb=0.0,0.2", "Shading.shade.a=0.05", "Shading.bias=0.15"],
    ];
    let mut frames = Vec::new();
    for (i, set) in values.iter().enumerate() {
        let out_dir = scratch("verify-std140", &format!("values{i}"));
        let mut args: Vec<&str> = vec!["verify"];
        args.extend(stages);
        for v in set.iter().chain(&shading[i]) {
            args.extend(["--set", v]);
        }
        args.extend(["--size", "32x32", "--format", "json", "--out", out_dir.to_str().unwrap()]);
        let out = effectc(&args);
        assert!(code(&out) == 0 && json_matches(&stdout(&out)), "values {i}: {}", stdout(&out));
        frames.push(std::fs::read(out_dir.join("std140_0000.png")).unwrap());
    }
    assert_ne!(frames[0], frames[1], "the block's values reach the picture");
}

/// `[textures]` entries in float and integer formats: a sampler reads the values the manifest
/// gives (beyond [0, 1], integers), GL draws the same picture from the same texels, and a
/// format its sampler cannot read or a colour its format cannot hold is an error.
#[test]
fn manifest_textures_in_float_and_integer_formats_read_as_given() {
    if !can_verify() {
        return;
    }
    let dir = scratch("verify-texel-formats", "program");
    let out = effectc(&["verify", "tests/verify/texel_formats", "--size", "64x64", "--out", dir.join("o").to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let png = image::open(dir.join("o/texel-formats_0000.png")).unwrap().to_rgba8();
    // Red: the rgba32f gradient's -2 (left) and 3 (right) as (h + 2) / 5; green: the
    // rgba16f gradient's 0 and 50 as g / 50; blue: the r32ui checker's 7 (bottom left) and
    // 1000 as id / 1000; alpha: the rgba32i texel's -5 + 5 + 3, and 1 for its exact
    // 2^24 + 1 (beyond f32's integers), as a share of 8.
    assert_eq!(png.get_pixel(0, 63).0, [0, 0, 2, 128]);
    assert_eq!(png.get_pixel(63, 63).0, [255, 255, 255, 128]);
    assert_eq!(png.get_pixel(0, 0).0, [0, 0, 255, 128]);
    let manifest = std::fs::read_to_string("tests/verify/texel_formats/effect.toml").unwrap();
    let with = |name: &str, text: String| {
        let bad = dir.join(name);
        std::fs::create_dir_all(&bad).unwrap();
        for f in ["quad.vert", "formats.frag"] {
            std::fs::copy(Path::new("tests/verify/texel_formats").join(f), bad.join(f)).unwrap();
        }
        std::fs::write(bad.join("effect.toml"), text).unwrap();
        let out = effectc(&["check", bad.to_str().unwrap()]);
        assert_eq!(code(&out), 1, "{}", stdout(&out));
        stdout(&out)
    };
    let float_for_uint = with("mismatch", manifest.replace("format = \"r32ui\"", "format = \"rgba32f\""));
    assert!(float_for_uint.contains("texture `ids` is `rgba32f`, but sampler `ids` reads unsigned integers"), "{float_for_uint}");
    let fractions = with("fractions", manifest.replace("[[7, 0, 0, 0]", "[[7.5, 0, 0, 0]"));
    assert!(fractions.contains("`r32ui` holds integers; its colours must be whole numbers"), "{fractions}");
}

/// Infinite and NaN constants, made at run time from their bits on the route through SPIR-V
/// (naga refuses them as literals), draw what the GL driver draws.
#[test]
fn infinite_constants_match_the_gl_driver() {
    if !can_verify() {
        return;
    }
    let dir = "tests/through_spirv/10-v330-infinite-constants";
    let out =
        effectc(&["verify", "--color", "never", dir, "--size", "64x64", "--out", scratch("verify-infinite", "spans").to_str().unwrap()]);
    let text = stdout(&out);
    assert_eq!(code(&out), 0, "{text}");
    assert!(text.contains("1/1 frame match"), "{text}");
}

/// The size of array textures on the route through SPIR-V (`textureSize` of a
/// `sampler2DArray` and a `samplerCubeArray`, layers included) draws what the GL driver draws.
#[test]
fn array_texture_sizes_match_the_gl_driver() {
    if !can_verify() {
        return;
    }
    let dir = "tests/through_spirv/11-v400-array-texture-size";
    let out = effectc(&[
        "verify",
        "--color",
        "never",
        dir,
        "--size",
        "64x64",
        "--out",
        scratch("verify-array-sizes", "layers").to_str().unwrap(),
    ]);
    let text = stdout(&out);
    assert_eq!(code(&out), 0, "{text}");
    assert!(text.contains("1/1 frame match"), "{text}");
}

/// Two-row matrices in std140 blocks (a loose `mat3x2`, `mat2` and `mat3x2` arrays in a
/// uniform block, a struct holding a `mat2` loaded whole), stored as `vec4` columns on the
/// route through SPIR-V, draw what the GL driver draws with the manifest's values.
#[test]
fn std140_two_row_matrices_match_the_gl_driver() {
    if !can_verify() {
        return;
    }
    let dir = "tests/through_spirv/09-v430-std140-two-row-matrices";
    let out =
        effectc(&["verify", "--color", "never", dir, "--size", "64x64", "--out", scratch("verify-two-row", "columns").to_str().unwrap()]);
    let text = stdout(&out);
    assert_eq!(code(&out), 0, "{text}");
    assert!(text.contains("1/1 frame match"), "{text}");
    assert!(!text.contains("W0403"), "every uniform has the manifest's value:\n{text}");
}
