//! The `effectc` binary: exit codes (0 clean, 1 problems, 2 IO/usage), output formats,
//! `--strict`, `--deny-warnings`, `--stage`, and how directories become programs.

use std::path::PathBuf;

use effectc::diag::Code;

use crate::common::{self, code, effectc, stdout};

const SEED: &str = "tests/fail/01-vert-out-vs-vert-vars";

/// A fresh, empty scratch directory for one test.
fn scratch(name: &str) -> PathBuf {
    common::scratch("cli", name)
}

const GOOD_VERT: &str = "#version 330 core\nlayout(location = 0) in vec2 aPos;\nout vec2 uv;\nvoid main()\n{\n    uv = aPos;\n    gl_Position = vec4(aPos, 0.0, 1.0);\n}\n";
const GOOD_FRAG: &str = "#version 330 core\nin vec2 uv;\nout vec4 fragColor;\nvoid main()\n{\n    fragColor = vec4(uv, 0.0, 1.0);\n}\n";

#[test]
fn effects_dir_is_clean() {
    let out = effectc(&["check", "effects/"]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
}

#[test]
fn seed_block_mismatch_names_both_blocks_and_files() {
    let out = effectc(&["check", "--color", "never", SEED]);
    let text = stdout(&out);
    assert_eq!(code(&out), 1, "{text}");
    for needle in ["vert_vars", "vert_out", "sun.vert", "sun.frag", Code::InputBlockUnmatched.as_str()] {
        assert!(text.contains(needle), "missing `{needle}` in:\n{text}");
    }
}

#[test]
fn missing_path_exits_2() {
    let out = effectc(&["check", "tests/fail/does-not-exist.frag"]);
    assert_eq!(code(&out), 2, "{}", stdout(&out));
    assert!(stdout(&out).contains(Code::InputIo.as_str()));
}

#[test]
fn json_parses_and_counts_errors() {
    let out = effectc(&["check", "--format", "json", SEED]);
    assert_eq!(code(&out), 1);
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).expect("valid JSON");
    assert!(v["summary"]["errors"].as_u64().unwrap() > 0, "{v}");
    let all = v["diagnostics"].as_array().unwrap();
    // The student's vertex stage also names its block's instance after the block, which
    // GLSL forbids (glslang reports it in sun.vert); the link bug is reported beside it.
    assert!(all.iter().any(|d| d["code"] == Code::ReferenceRejects.as_str() && d["file"].as_str().unwrap().ends_with("sun.vert")), "{v}");
    let d = all.iter().find(|d| d["code"] == Code::InputBlockUnmatched.as_str()).expect("the renamed block");
    assert!(d["file"].as_str().unwrap().ends_with("sun.frag"));
    assert!(d["labels"][0]["file"].as_str().unwrap().ends_with("sun.vert"));
}

#[test]
fn github_lines_are_error_commands() {
    let out = effectc(&["check", "--format", "github", SEED]);
    assert_eq!(code(&out), 1);
    let text = stdout(&out);
    assert!(!text.is_empty());
    for line in text.lines() {
        assert!(line.starts_with("::error file="), "{line}");
    }
}

#[test]
fn sarif_is_2_1_0() {
    let out = effectc(&["check", "--format", "sarif", SEED]);
    assert_eq!(code(&out), 1);
    let text = stdout(&out);
    assert!(text.contains("\"version\": \"2.1.0\""), "{text}");
    let v: serde_json::Value = serde_json::from_str(&text).expect("valid JSON");
    let results = v["runs"][0]["results"].as_array().unwrap();
    assert!(results.iter().any(|r| r["ruleId"] == Code::InputBlockUnmatched.as_str()), "{text}");
}

#[test]
fn deny_warnings_fails_a_warning_only_input() {
    let dir = "tests/fail/05-unread-output-warning";
    assert_eq!(code(&effectc(&["check", dir])), 0);
    assert_eq!(code(&effectc(&["check", "--deny-warnings", dir])), 1);
}

#[test]
fn strict_turns_legacy_warning_into_error() {
    // `texture2D` in 420 core: the reference compiler rejects the stage (E0105) with or
    // without --strict; effectc's own finding, which suggests `texture`, is a warning that
    // --strict raises.
    let dir = "tests/fail/16-texture2d-in-420-core";
    let out = effectc(&["check", dir]);
    assert_eq!(code(&out), 1, "{}", stdout(&out));
    assert!(stdout(&out).contains(Code::ReferenceRejects.as_str()));
    assert!(stdout(&out).contains(Code::RemovedInVersion.as_str()));
    let out = effectc(&["check", "--strict", dir]);
    assert_eq!(code(&out), 1, "{}", stdout(&out));
    assert!(stdout(&out).contains(Code::RemovedInVersionStrict.as_str()));
}

#[test]
fn stage_flag_for_glsl_extension() {
    let dir = scratch("stage-flag");
    let file = dir.join("effect.glsl");
    std::fs::write(&file, GOOD_FRAG.replace("in vec2 uv;\n", "uniform vec2 uv;\n")).unwrap();
    let path = file.to_str().unwrap();
    // Its text shows the stage (a fragment output, no gl_Position): read so, with a note.
    let out = effectc(&["check", path]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    assert!(stdout(&out).contains(Code::StageFromText.as_str()) && stdout(&out).contains("read as a fragment stage"), "{}", stdout(&out));
    // A text that shows no stage needs --stage.
    let blank = dir.join("blank.glsl");
    std::fs::write(&blank, "#version 330\nvoid main() {}\n").unwrap();
    let blank = blank.to_str().unwrap();
    let out = effectc(&["check", blank]);
    assert_eq!(code(&out), 1, "{}", stdout(&out));
    assert!(stdout(&out).contains(Code::UnknownStage.as_str()));
    let out = effectc(&["check", "--stage", "fragment", blank]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    assert!(stdout(&out).contains("checked 1 program"));
}

#[test]
fn directory_without_manifest_groups_by_stem() {
    let dir = scratch("by-stem");
    for stem in ["first", "second"] {
        std::fs::write(dir.join(format!("{stem}.vert")), GOOD_VERT).unwrap();
        std::fs::write(dir.join(format!("{stem}.frag")), GOOD_FRAG).unwrap();
    }
    let out = effectc(&["check", dir.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    assert!(stdout(&out).contains("checked 2 programs: no problems"), "{}", stdout(&out));
}

#[test]
fn one_bad_program_does_not_stop_the_others() {
    let dir = scratch("good-and-bad");
    std::fs::write(dir.join("bad.vert"), GOOD_VERT).unwrap();
    std::fs::write(dir.join("bad.frag"), GOOD_FRAG.replace("vec4(uv", "vec4(uvv")).unwrap();
    std::fs::write(dir.join("good.vert"), GOOD_VERT).unwrap();
    std::fs::write(dir.join("good.frag"), GOOD_FRAG).unwrap();
    let out = effectc(&["check", "--format", "json", dir.to_str().unwrap()]);
    assert_eq!(code(&out), 1);
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).unwrap();
    for d in v["diagnostics"].as_array().unwrap() {
        assert!(d["file"].as_str().unwrap().ends_with("bad.frag"), "{d}");
    }
    let out = effectc(&["check", dir.to_str().unwrap()]);
    let text = stdout(&out);
    assert!(text.contains("checked 2 programs: 1 error"), "{text}");
}

#[test]
fn shader_objects_of_one_stage_are_linked_by_the_reference_compiler() {
    // Files named together where a stage repeats and only one of its files has `main`: the
    // files are shader objects linked into that stage, as GL's glAttachShader does.
    let linked =
        ["tests/shader_objects/linked/edge.vert", "tests/shader_objects/linked/edge.frag", "tests/shader_objects/linked/sobel.frag"];
    // glslang compiles and links the files one by one; effectc's own analysis reads the
    // stage's files joined (`front::units`), so its rules run and the program translates.
    let out = effectc(&[&["check"][..], &linked[..]].concat());
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    assert!(!stdout(&out).contains(Code::ReferenceOnly.as_str()), "{}", stdout(&out));
    assert!(stdout(&out).contains("checked 1 program: no problems"), "{}", stdout(&out));
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("shader-objects-out");
    let out = effectc(&[&["translate", "--out", dir.to_str().unwrap()][..], &linked[..]].concat());
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let wgsl = std::fs::read_to_string(dir.join("edge.wgsl")).unwrap();
    assert!(wgsl.contains("fn sobel") && wgsl.contains("fn fs_main"), "{wgsl}");
    let missing = [
        "tests/shader_objects/missing-body/edge.vert",
        "tests/shader_objects/missing-body/edge.frag",
        "tests/shader_objects/missing-body/sobel.frag",
    ];
    let out = effectc(&[&["check"][..], &missing[..]].concat());
    assert_eq!(code(&out), 1, "{}", stdout(&out));
    assert!(stdout(&out).contains("E0230") && stdout(&out).contains("`edges` is declared but no shader object"), "{}", stdout(&out));
}

#[test]
fn legal_glsl_effectc_cannot_read_is_a_note_and_translate_says_why() {
    // `textureQueryLod` on a cube map (GLSL 4.00) is legal (glslang and Mesa accept it); naga's GLSL front
    // has no such function and its SPIR-V front no `OpImageQueryLod`: check notes it (exit
    // 0), translate stops with E0306 naming what naga said. `textureGather`, which naga's
    // GLSL front lacks too, translates through SPIR-V. A global initialised from a uniform (run-time initializer, which naga
    // takes only as a constant) and a `#pragma` with quoted text (emulator packs), which
    // naga's preprocessor used to stop on, translate.
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("legal-unread");
    std::fs::create_dir_all(&dir).unwrap();
    let vert = dir.join("p.vert");
    let lod = dir.join("p.frag");
    let gather = dir.join("g.frag");
    let init = dir.join("i.frag");
    let pragma = dir.join("q.frag");
    std::fs::write(&vert, "#version 400\nin vec3 position;\nvoid main() { gl_Position = vec4(position, 1.0); }\n").unwrap();
    std::fs::write(
        &lod,
        "#version 400\nuniform samplerCube tex;\nout vec4 color;\nvoid main() { color = vec4(textureQueryLod(tex, vec3(0.5)), 0.0, 1.0); }\n",
    )
    .unwrap();
    std::fs::write(
        &gather,
        "#version 400\nuniform sampler2D tex;\nout vec4 color;\nvoid main() { color = textureGather(tex, vec2(0.5)); }\n",
    )
    .unwrap();
    std::fs::write(
        &init,
        "#version 400\nuniform int frameCount;\nfloat t = float(frameCount) * 0.025;\nout vec4 color;\nvoid main() { color = vec4(t); }\n",
    )
    .unwrap();
    std::fs::write(
        &pragma,
        "#version 400\n#pragma parameter GAMMA \"Gamma value\" 2.2 1.0 3.0\nout vec4 color;\nvoid main() { color = vec4(1.0); }\n",
    )
    .unwrap();
    let v = vert.to_str().unwrap();
    let out = effectc(&["check", v, lod.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    assert!(stdout(&out).contains(Code::NagaCannotTake.as_str()), "{}", stdout(&out));
    let out = effectc(&["translate", "--out", dir.join("out").to_str().unwrap(), v, lod.to_str().unwrap()]);
    assert_eq!(code(&out), 1, "{}", stdout(&out));
    assert!(stdout(&out).contains(Code::TargetCannotExpress.as_str()) && stdout(&out).contains("textureQueryLod"), "{}", stdout(&out));
    let out = effectc(&["check", v, gather.to_str().unwrap()]);
    assert!(code(&out) == 0 && !stdout(&out).contains(Code::NagaCannotTake.as_str()), "{}", stdout(&out));
    for (name, frag) in [("gather", &gather), ("init", &init), ("pragma", &pragma)] {
        let out = effectc(&["translate", "--out", dir.join(name).to_str().unwrap(), v, frag.to_str().unwrap()]);
        assert_eq!(code(&out), 0, "{name}: {}", stdout(&out));
    }
}

#[test]
fn push_constants_become_a_uniform_buffer() {
    // WebGPU has no push constants: the block is translated as a std140 uniform buffer the
    // reflection names, and the WGSL validates.
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("push-constants");
    std::fs::create_dir_all(&dir).unwrap();
    let vert = dir.join("pc.vert");
    let frag = dir.join("pc.frag");
    std::fs::write(&vert, "#version 450\nlayout(location = 0) in vec3 position;\nlayout(location = 0) out vec2 uv;\nlayout(push_constant) uniform Push { mat4 mvp; vec4 tint; float scale; } pc;\nvoid main() { uv = position.xy * pc.scale; gl_Position = pc.mvp * vec4(position, 1.0); }\n").unwrap();
    std::fs::write(&frag, "#version 450\nlayout(location = 0) in vec2 uv;\nlayout(location = 0) out vec4 color;\nlayout(push_constant) uniform Push { mat4 mvp; vec4 tint; float scale; } pc;\nvoid main() { color = pc.tint * vec4(uv, 0.0, 1.0); }\n").unwrap();
    let out_dir = dir.join("out");
    let out =
        effectc(&["translate", "--to", "wgsl,reflect", "--out", out_dir.to_str().unwrap(), vert.to_str().unwrap(), frag.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let wgsl = std::fs::read_to_string(out_dir.join("pc.wgsl")).unwrap();
    assert!(wgsl.contains("var<uniform> pc"), "{wgsl}");
    assert!(effectc::back::verify_wgsl(&wgsl).is_ok(), "{wgsl}");
}

#[test]
fn folders_form_the_programs_their_layout_means() {
    // One vertex stage with many fragment stages (a tutorial's `PCN.vert` beside
    // `DiffuseOnly.frag`, …): each fragment stage is paired with it, so the link rules run and
    // a fragment input no stage writes is caught. `.glsl` names (`x.vert.glsl`, `x_fs.glsl`)
    // and `.glsl` files placed by their text form programs too; a folder with nothing in it
    // is a warning, and fails in a CI format.
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("formation");
    let _ = std::fs::remove_dir_all(&dir);
    let (pairs, glsl, empty) = (dir.join("pairs"), dir.join("glsl"), dir.join("empty"));
    for d in [&pairs, &glsl, &empty] {
        std::fs::create_dir_all(d).unwrap();
    }
    let vert = "#version 330\nin vec3 pos;\nout vec3 N;\nvoid main() { N = pos; gl_Position = vec4(pos, 1.0); }\n";
    std::fs::write(pairs.join("PCN.vert"), vert).unwrap();
    std::fs::write(pairs.join("DiffuseOnly.frag"), "#version 330\nin vec3 N;\nout vec4 c;\nvoid main() { c = vec4(N, 1.0); }\n").unwrap();
    std::fs::write(pairs.join("Typo.frag"), "#version 330\nin vec3 Nrm;\nout vec4 c;\nvoid main() { c = vec4(Nrm, 1.0); }\n").unwrap();
    let out = effectc(&["check", "--color", "never", pairs.to_str().unwrap()]);
    let text = stdout(&out);
    assert_eq!(code(&out), 1, "{text}");
    assert!(text.contains("E0202") && text.contains("Nrm") && text.matches("N0001").count() == 2, "{text}");
    assert!(text.contains("checked 2 programs"), "{text}");

    std::fs::write(glsl.join("quad.vert.glsl"), vert).unwrap();
    std::fs::write(glsl.join("quad_fs.glsl"), "#version 330\nin vec3 N;\nout vec4 c;\nvoid main() { c = vec4(N, 1.0); }\n").unwrap();
    std::fs::write(glsl.join("tint.glsl"), "#version 330\nin vec3 N;\nout vec4 c;\nvoid main() { c = vec4(N * 0.5, 1.0); }\n").unwrap();
    std::fs::write(glsl.join("common.glsl"), "float helper(float x) { return x; }\n").unwrap();
    let out = effectc(&["check", "--color", "never", glsl.to_str().unwrap()]);
    let text = stdout(&out);
    assert_eq!(code(&out), 0, "{text}");
    assert!(text.contains("checked 2 programs") && text.contains("N0003") && text.contains("tint.glsl"), "{text}");
    assert!(!text.contains("N0002"), "every stage is paired: {text}");

    let out = effectc(&["check", "--color", "never", empty.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    assert!(stdout(&out).contains("W0006"), "{}", stdout(&out));
    let out = effectc(&["check", "--format", "sarif", empty.to_str().unwrap()]);
    assert_eq!(code(&out), 1, "a CI format fails when nothing was checked");
}

#[test]
fn a_folders_one_geometry_stage_joins_its_one_program() {
    // `scene.vert` + `scene.frag` and `multiview.geom` (Sascha Willems' viewport-array sample):
    // the host links the three, and the fragment stage reads what only the geometry stage
    // writes. With a second program in the folder the geometry stage stays alone.
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("lone-geometry");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let vert = "#version 450\nlayout(location = 0) in vec3 pos;\nlayout(location = 0) out vec3 n;\n\
                void main() { n = pos; gl_Position = vec4(pos, 1.0); }\n";
    let geom = "#version 450\nlayout(triangles) in;\nlayout(triangle_strip, max_vertices = 3) out;\n\
                layout(location = 0) in vec3 n[];\nlayout(location = 0) out vec3 outN;\nlayout(location = 1) out vec3 view;\n\
                void main() { for (int i = 0; i < 3; i++) { outN = n[i]; view = -gl_in[i].gl_Position.xyz; \
                gl_Position = gl_in[i].gl_Position; EmitVertex(); } EndPrimitive(); }\n";
    let frag = "#version 450\nlayout(location = 0) in vec3 outN;\nlayout(location = 1) in vec3 view;\n\
                layout(location = 0) out vec4 c;\nvoid main() { c = vec4(outN * dot(outN, view), 1.0); }\n";
    std::fs::write(dir.join("scene.vert"), vert).unwrap();
    std::fs::write(dir.join("multiview.geom"), geom).unwrap();
    std::fs::write(dir.join("scene.frag"), frag).unwrap();
    let out = effectc(&["check", "--color", "never", dir.to_str().unwrap()]);
    let text = stdout(&out);
    assert_eq!(code(&out), 0, "{text}");
    assert!(text.contains("N0001") && text.contains("multiview.geom` joins") && text.contains("checked 1 program"), "{text}");
    std::fs::write(dir.join("other.vert"), vert).unwrap();
    std::fs::write(
        dir.join("other.frag"),
        "#version 450\nlayout(location = 0) in vec3 n;\nlayout(location = 0) out vec4 c;\n\
                                            void main() { c = vec4(n, 1.0); }\n",
    )
    .unwrap();
    let out = effectc(&["check", "--color", "never", dir.to_str().unwrap()]);
    let text = stdout(&out);
    assert!(text.contains("N0002") && text.contains("multiview.geom") && !text.contains("` joins `"), "{text}");
}

#[test]
fn doubles_are_kept_for_the_targets_that_have_them() {
    // `dvec4`/`double` (GLSL 4.00): WGSL, MSL and GLSL ES have no 64-bit floats, so translating
    // to one of them takes the doubles as floats (W0131 at the first, naming the targets that
    // keep them); SPIR-V (Float64 capability) and HLSL alone keep them.
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("doubles");
    std::fs::create_dir_all(&dir).unwrap();
    let frag = dir.join("d.frag");
    std::fs::write(
        &frag,
        "#version 400\nuniform dvec4 x;\nuniform double s;\nout vec4 c;\nvoid main() { c = vec4(x * s + dvec4(1.0LF)); }\n",
    )
    .unwrap();
    let out = effectc(&["check", frag.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    assert!(!stdout(&out).contains("W0131"), "check keeps the doubles: {}", stdout(&out));
    let wgsl = dir.join("wgsl");
    let out = effectc(&["translate", frag.to_str().unwrap(), "--to", "wgsl,spv", "--out", wgsl.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    assert!(stdout(&out).contains("W0131") && stdout(&out).contains("d.frag:2:9"), "{}", stdout(&out));
    assert!(stdout(&out).contains("--to spv,spvasm,hlsl"), "{}", stdout(&out));
    let text = std::fs::read_to_string(wgsl.join("d.wgsl")).unwrap();
    assert!(text.contains("vec4<f32>") && !text.contains("f64"), "{text}");
    let kept = dir.join("kept");
    let out = effectc(&["translate", frag.to_str().unwrap(), "--to", "spvasm,hlsl", "--out", kept.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    assert!(!stdout(&out).contains("W0131"), "{}", stdout(&out));
    let asm = std::fs::read_to_string(kept.join("d.frag.spvasm")).unwrap();
    assert!(asm.contains("OpCapability Float64") && asm.contains("OpTypeFloat 64"), "{asm}");
    assert!(std::fs::read_to_string(kept.join("d.hlsl")).unwrap().contains("double4"));
}

#[test]
fn integers_of_64_bits_are_kept_for_spirv_and_refused_for_wgsl_with_the_way_out() {
    // GL_ARB_gpu_shader_int64: WGSL has no 64-bit integers (E0306, naming the targets that
    // keep them); SPIR-V (Int64 capability) alone keeps them.
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("int64");
    std::fs::create_dir_all(&dir).unwrap();
    let frag = dir.join("i.frag");
    std::fs::write(
        &frag,
        "#version 400\n#extension GL_ARB_gpu_shader_int64 : require\nout vec4 color;\nuniform uint val;\n\
         void main() { int64_t t = int64_t(val) << 33; color = t == (1L << 33) ? vec4(0, 1, 0, 1) : vec4(1, 0, 0, 1); }\n",
    )
    .unwrap();
    let out = effectc(&["check", frag.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let out = effectc(&["translate", frag.to_str().unwrap(), "--to", "wgsl,spv", "--out", dir.join("both").to_str().unwrap()]);
    assert_eq!(code(&out), 1, "{}", stdout(&out));
    assert!(stdout(&out).contains("E0306") && stdout(&out).contains("--to spv,spvasm` keeps them"), "{}", stdout(&out));
    let kept = dir.join("kept");
    let out = effectc(&["translate", frag.to_str().unwrap(), "--to", "spvasm,spv", "--out", kept.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let asm = std::fs::read_to_string(kept.join("i.frag.spvasm")).unwrap();
    assert!(asm.contains("OpCapability Int64") && asm.contains("OpTypeInt 64 1"), "{asm}");
}

#[test]
fn vulkan_glsl_is_checked_for_the_vulkan_version_asked() {
    // Subgroup operations need SPIR-V 1.3 (Vulkan 1.1): refused under `glslangValidator -V`'s
    // Vulkan 1.0 with a help naming the option, accepted with `--target-env vulkan1.1` and in
    // effectc.toml.
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("vulkan-version");
    std::fs::create_dir_all(&dir).unwrap();
    let frag = dir.join("sum.frag");
    std::fs::write(
        &frag,
        "#version 450\n#extension GL_KHR_shader_subgroup_arithmetic : require\nlayout(location = 0) in float v;\n\
         layout(location = 0) out vec4 c;\nvoid main() { c = vec4(subgroupAdd(v)); }\n",
    )
    .unwrap();
    let f = frag.to_str().unwrap();
    let out = effectc(&["check", "--color", "never", "--target-env", "vulkan", f]);
    assert_eq!(code(&out), 1, "{}", stdout(&out));
    assert!(stdout(&out).contains("E0105") && stdout(&out).contains("--target-env vulkan1.1"), "{}", stdout(&out));
    let out = effectc(&["check", "--color", "never", "--target-env", "vulkan1.1", f]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    std::fs::write(dir.join("effectc.toml"), "target-env = \"vulkan1.3\"\n").unwrap();
    let out = effectc(&["check", "--color", "never", "--config", dir.join("effectc.toml").to_str().unwrap(), f]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
}
