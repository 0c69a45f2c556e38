//! Programs as the user means them: `--define`, a manifest stage's `define`, the
//! single-file two-stage format, `[[program]]` in `effectc.toml`, and the list of formed
//! programs (`check --verbose`, JSON `formed`). Inputs are generated here.

use crate::common::{self, code, effectc, stdout};

const VERT: &str = "#version 330\nin vec3 p;\nin vec3 n;\nout vec3 normal;\nvoid main() { normal = n; gl_Position = vec4(p, 1.0); }\n";

fn frag(input: &str) -> String {
    format!("#version 330\nin vec3 {input};\nout vec4 c;\nvoid main() {{ c = vec4({input} * LIGHTS, 1.0); }}\n")
}

#[test]
fn defines_reach_every_stage_and_a_manifest_stage_has_its_own() {
    let dir = common::scratch("programs", "defines");
    let file = dir.join("a.frag");
    std::fs::write(&file, "#version 330\nout vec4 c;\nvoid main() { c = vec4(QUALITY * 0.25); }\n").unwrap();
    let out = effectc(&["check", "--color", "never", file.to_str().unwrap()]);
    assert_eq!(code(&out), 1, "QUALITY is undeclared without the define: {}", stdout(&out));
    let out = effectc(&["check", "--color", "never", "-D", "QUALITY=3", file.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let out = effectc(&["check", "--define", "GL_X", file.to_str().unwrap()]);
    assert_eq!(code(&out), 2, "a reserved name is a usage error");
    // The settings define it for every stage; the command line wins for the same name.
    std::fs::write(dir.join("effectc.toml"), "define = { QUALITY = \"nope\" }\n").unwrap();
    let out = effectc(&["check", "--color", "never", file.to_str().unwrap()]);
    assert_eq!(code(&out), 1, "`nope` is undeclared: {}", stdout(&out));
    let out = effectc(&["check", "--color", "never", "-D", "QUALITY=2", file.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    std::fs::remove_file(dir.join("effectc.toml")).unwrap();

    std::fs::write(
        dir.join("both.glsl"),
        format!(
            "#version 330\n#ifdef VS\n{}#else\n{}#endif\n",
            VERT.replace("#version 330\n", ""),
            frag("normal").replace("#version 330\n", "")
        ),
    )
    .unwrap();
    std::fs::write(
        dir.join("effect.toml"),
        "name = \"lit\"\n[stages]\nvertex = { file = \"both.glsl\", define = { VS = 1 } }\nfragment = { file = \"both.glsl\", define = { LIGHTS = 2 } }\n",
    )
    .unwrap();
    let out = effectc(&["check", "--color", "never", "--verbose", dir.join("effect.toml").to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    assert!(stdout(&out).contains("(defined: VS=1)") && stdout(&out).contains("(defined: LIGHTS=2)"), "{}", stdout(&out));
}

#[test]
fn a_file_holding_two_stages_is_one_program_and_its_link_is_checked() {
    let dir = common::scratch("programs", "two-stage");
    let body = |input: &str| {
        format!(
            "#version 130\n#if defined(VERTEX)\nin vec4 VertexCoord;\nout vec2 uv;\nvoid main() {{ uv = VertexCoord.xy; gl_Position = VertexCoord; }}\n#elif defined(FRAGMENT)\nin vec2 {input};\nout vec4 c;\nvoid main() {{ c = vec4({input}, 0.0, 1.0); }}\n#endif\n"
        )
    };
    // `blur-vert.glsl` is a vertical blur holding both stages, not a vertex stage.
    std::fs::write(dir.join("blur-vert.glsl"), body("uv")).unwrap();
    std::fs::write(dir.join("typo.glsl"), body("vu")).unwrap();
    let out = effectc(&["check", "--color", "never", "--format", "json", dir.to_str().unwrap()]);
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let formed = doc["formed"].as_array().unwrap();
    assert_eq!(formed.len(), 2, "{doc}");
    for f in formed {
        assert_eq!(f["stages"].as_array().unwrap().len(), 2, "{f}");
        assert!(f["why"].as_str().unwrap().contains("both stages"), "{f}");
    }
    let errors: Vec<&serde_json::Value> = doc["diagnostics"].as_array().unwrap().iter().filter(|d| d["severity"] == "error").collect();
    assert_eq!(errors.len(), 1, "only the typo's link fails: {errors:?}");
    assert_eq!(errors[0]["code"], "E0202");
    assert!(errors[0]["file"].as_str().unwrap().ends_with("typo.glsl"));
}

#[test]
fn declared_programs_pair_one_vertex_stage_with_many_and_say_so() {
    let dir = common::scratch("programs", "declared");
    let data = dir.join("data");
    std::fs::create_dir_all(&data).unwrap();
    std::fs::write(data.join("PCN.vert"), VERT).unwrap();
    std::fs::write(data.join("Diffuse.frag"), frag("normal")).unwrap();
    std::fs::write(data.join("Phong.frag"), frag("normal")).unwrap();
    std::fs::write(data.join("Toon.frag"), frag("normall")).unwrap();
    std::fs::write(data.join("Other.vert"), VERT).unwrap();
    std::fs::write(
        dir.join("effectc.toml"),
        "[[program]]\nname = \"lit\"\nvertex = \"data/PCN.vert\"\nfragment = [\"data/*.frag\"]\ndefine = { LIGHTS = 2 }\n[[program]]\nvertex = \"data/None*.vert\"\nfragment = \"data/Phong.frag\"\n",
    )
    .unwrap();
    // Two vertex stages in the folder: without the declaration nothing would pair them.
    let out = effectc(&["check", "--color", "never", "--verbose", dir.to_str().unwrap()]);
    let text = stdout(&out);
    assert_eq!(code(&out), 1, "{text}");
    assert!(text.contains("programs formed: 4"), "{text}");
    for name in ["lit/Diffuse", "lit/Phong", "lit/Toon"] {
        assert!(text.contains(&format!("{name}: declared by a [[program]]")), "{name}: {text}");
    }
    assert!(text.contains("E0202") && text.contains("normall"), "the injected typo is caught: {text}");
    assert!(text.contains("W0006") && text.contains("matches no file"), "a pattern matching nothing is said: {text}");
    assert!(text.contains("Other.vert` is checked alone"), "the undeclared stage is still checked: {text}");
    // One vertex stage in several programs: each program's outputs keep their own name.
    std::fs::remove_file(data.join("Toon.frag")).unwrap();
    let out_dir = dir.join("out");
    let out = effectc(&["translate", "--to", "wgsl", "--out", out_dir.to_str().unwrap(), dir.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let mut written: Vec<String> =
        std::fs::read_dir(&out_dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    written.sort();
    assert_eq!(written, ["Other.wgsl", "PCN-Diffuse.wgsl", "PCN-Phong.wgsl"], "{}", stdout(&out));
    // A file named on the command line is checked in the program declared with it.
    let out = effectc(&["check", "--color", "never", "--verbose", data.join("Phong.frag").to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    assert!(stdout(&out).contains("lit/Phong: declared") && !stdout(&out).contains("N0002"), "{}", stdout(&out));
}

#[test]
fn a_compute_stage_stands_apart_and_told_stages_keep_their_stem() {
    let dir = common::scratch("programs", "stems");
    std::fs::write(dir.join("cloth.vert"), VERT).unwrap();
    std::fs::write(dir.join("cloth.frag"), frag("normal").replace(" * LIGHTS", "")).unwrap();
    std::fs::write(dir.join("cloth.comp"), "#version 430\nlayout(local_size_x = 1) in;\nvoid main() {}\n").unwrap();
    // `x.cont.glsl`: an inner extension effectc does not know; the text tells the stage.
    std::fs::write(dir.join("tess.vert.glsl"), "#version 410\nin vec4 p;\nout vec4 vp;\nvoid main() { vp = p; }\n").unwrap();
    std::fs::write(
        dir.join("tess.cont.glsl"),
        "#version 410\nlayout(vertices = 3) out;\nin vec4 vp[];\nout vec4 cp[];\nvoid main() { cp[gl_InvocationID] = vp[gl_InvocationID]; gl_TessLevelOuter[0] = 1.0; gl_TessLevelOuter[1] = 1.0; gl_TessLevelOuter[2] = 1.0; gl_TessLevelInner[0] = 1.0; }\n",
    )
    .unwrap();
    std::fs::write(dir.join("tess.eval.glsl"), "#version 410\nlayout(triangles) in;\nin vec4 cp[];\nvoid main() { gl_Position = gl_TessCoord.x * cp[0] + gl_TessCoord.y * cp[1] + gl_TessCoord.z * cp[2]; }\n").unwrap();
    std::fs::write(dir.join("tess.frag.glsl"), "#version 410\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n").unwrap();
    let out = effectc(&["check", "--format", "json", dir.to_str().unwrap()]);
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let mut shapes: Vec<Vec<String>> = doc["formed"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["stages"].as_array().unwrap().iter().map(|s| s["stage"].as_str().unwrap().to_string()).collect())
        .collect();
    shapes.sort();
    assert_eq!(shapes, [vec!["compute"], vec!["vertex", "fragment"], vec!["vertex", "tess_control", "tess_eval", "fragment"]], "{doc}");
    assert_eq!(code(&out), 0, "{doc}");
}

#[test]
fn the_host_code_pairs_stages_it_names_together_and_a_mismatch_is_caught() {
    let dir = common::scratch("programs", "host-code");
    let data = dir.join("data");
    std::fs::create_dir_all(&data).unwrap();
    let unlit = "#version 330\nin vec3 p;\nout vec3 tint;\nvoid main() { tint = p; gl_Position = vec4(p, 1.0); }\n";
    std::fs::write(data.join("PCN.vert"), VERT).unwrap();
    std::fs::write(data.join("Unlit.vert"), unlit).unwrap();
    std::fs::write(data.join("Diffuse.frag"), frag("normal").replace(" * LIGHTS", "")).unwrap();
    std::fs::write(data.join("Flat.frag"), frag("tint").replace(" * LIGHTS", "")).unwrap();
    // The tutorial's C++ names the pairs: in one initializer, and in consecutive statements.
    std::fs::write(
        dir.join("main.cpp"),
        "// LoadProgram(\"Unlit.vert\", \"Diffuse.frag\");  (commented out: no pair)\n\
         static const Pair pairs[] = { {\"PCN.vert\", \"Diffuse.frag\"} };\n\
         void init() {\n\
         \tshaders.push_back(LoadShader(GL_VERTEX_SHADER, \"Unlit.vert\"));\n\
         \tshaders.push_back(LoadShader(GL_FRAGMENT_SHADER, \"Flat.frag\"));\n\
         \tflat = CreateProgram(shaders);\n}\n",
    )
    .unwrap();
    let out = effectc(&["check", "--color", "never", "--verbose", dir.to_str().unwrap()]);
    let text = stdout(&out);
    assert_eq!(code(&out), 0, "{text}");
    assert!(text.contains("programs formed: 2"), "{text}");
    assert_eq!(text.matches("named together by the host code").count(), 2, "{text}");
    assert!(text.contains("N0004") && text.contains("main.cpp:2` names them together"), "{text}");
    assert!(!text.contains("N0002"), "no stage is left alone: {text}");
    // A typo in one fragment stage is now a link error against the vertex stage the code pairs it with.
    std::fs::write(data.join("Flat.frag"), frag("tnit").replace(" * LIGHTS", "")).unwrap();
    let out = effectc(&["check", "--color", "never", dir.to_str().unwrap()]);
    assert_eq!(code(&out), 1, "{}", stdout(&out));
    assert!(stdout(&out).contains("E0202") && stdout(&out).contains("tnit"), "{}", stdout(&out));
    // Without the host file the folder has two vertex stages and nothing pairs its fragment stages.
    std::fs::remove_file(dir.join("main.cpp")).unwrap();
    let out = effectc(&["check", "--color", "never", dir.to_str().unwrap()]);
    assert_eq!(stdout(&out).matches("N0002").count(), 4, "{}", stdout(&out));
}
