//! Hostile and huge input (generated here, never committed): effectc reads pull requests
//! nobody has reviewed. Deep legal GLSL checks the same with one job and with many (no stack
//! overflow); inputs past effectc's limits are refused with E0107 before any compiler reads
//! them; devices are never read; `#include` cannot leave the project root, and nothing of a
//! refused file (the CI job's environment included) appears in any output format.

use std::process::Command;

use crate::common::{self, code, stdout};

/// `effectc check` of `files` with `args`, with a secret in the environment.
fn check(args: &[&str], files: &[&std::path::Path]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_effectc"))
        .arg("check")
        .args(args)
        .args(files)
        .env("NO_COLOR", "1")
        .env("EFFECTC_TEST_SECRET", "hunter2-secret")
        .output()
        .unwrap()
}

/// `check` of `file` refuses with E0106 (exit 1) in every output format, and no byte of a
/// refused file (the secret in it or in the environment) appears in any of them.
fn refused_in_every_format(file: &std::path::Path, what: &str) {
    for format in ["human", "json", "github", "sarif"] {
        let out = check(&["--format", format], &[file]);
        let all = format!("{}{}", stdout(&out), String::from_utf8_lossy(&out.stderr));
        assert_eq!(code(&out), 1, "{what} ({format}): {all}");
        assert!(all.contains("E0106"), "{what} ({format}): {all}");
        assert!(!all.contains("hunter2"), "{what} ({format}) printed a refused file: {all}");
    }
}

fn sum(terms: usize) -> String {
    let body: Vec<String> = (0..terms).map(|i| format!("u{}", i % 4)).collect();
    format!("#version 330\nuniform float u0, u1, u2, u3;\nout vec4 c;\nvoid main() {{ float x = {}; c = vec4(x); }}\n", body.join(" + "))
}

fn nested_ifs(depth: usize) -> String {
    let open: String = (0..depth).map(|i| format!("if (x > {i}.0) {{\n")).collect();
    format!(
        "#version 330\nuniform float u;\nout vec4 c;\nvoid main() {{ float x = u;\n{open}x += 1.0;\n{}c = vec4(x); }}\n",
        "}\n".repeat(depth)
    )
}

#[test]
fn deep_legal_glsl_checks_alike_on_one_job_and_many() {
    let dir = common::scratch("hostile", "deep");
    for (name, text) in [("sum.frag", sum(10_000)), ("ifs.frag", nested_ifs(1_000))] {
        let file = dir.join(name);
        std::fs::write(&file, text).unwrap();
        for jobs in ["-j1", "-j4"] {
            let out = check(&[jobs], &[&file]);
            assert_eq!(code(&out), 0, "{name} {jobs}: {}", stdout(&out));
            assert!(stdout(&out).contains("checked 1 program: 1 note"), "{name} {jobs}: only the stage-alone note: {}", stdout(&out));
        }
    }
}

#[test]
fn inputs_past_the_limits_are_refused_before_compiling() {
    let dir = common::scratch("hostile", "limits");
    let long = dir.join("long.frag");
    std::fs::write(&long, sum(150_000)).unwrap();
    let mut macros = String::from("#version 330\nuniform float u;\nout vec4 c;\n#define A0 u\n");
    for i in 1..=24 {
        macros.push_str(&format!("#define A{i} A{}+A{}\n", i - 1, i - 1));
    }
    macros.push_str("void main() { c = vec4(A24); }\n");
    let doubling = dir.join("doubling.frag");
    std::fs::write(&doubling, macros).unwrap();
    for file in [&long, &doubling] {
        let out = check(&[], &[file]);
        assert_eq!(code(&out), 1, "{}", stdout(&out));
        assert!(stdout(&out).contains("E0107"), "{}", stdout(&out));
    }
    let out = check(&["--stage", "fragment"], &[std::path::Path::new("/dev/zero")]);
    assert_eq!(code(&out), 2, "{}", stdout(&out));
    assert!(stdout(&out).contains("E0013") && stdout(&out).contains("a device"), "{}", stdout(&out));
}

#[test]
fn includes_stay_inside_the_project_root_and_nothing_refused_is_printed() {
    let outside = common::scratch("hostile", "outside");
    std::fs::write(outside.join("secret.txt"), "float leaked = 1.0; // hunter2-outside\n").unwrap();
    let root = common::scratch("hostile", "pull-request");
    std::fs::write(root.join("effectc.toml"), "").unwrap();
    let shaders = root.join("shaders");
    std::fs::create_dir_all(&shaders).unwrap();
    let targets = [
        "/proc/self/environ".to_string(),
        outside.join("secret.txt").display().to_string(),
        "../../outside/secret.txt".to_string(),
        "link/secret.txt".to_string(),
    ];
    std::os::unix::fs::symlink(&outside, shaders.join("link")).unwrap();
    for (i, target) in targets.iter().enumerate() {
        let file = shaders.join(format!("p{i}.frag"));
        std::fs::write(&file, format!("#version 330\n#include \"{target}\"\nout vec4 c;\nvoid main() {{ c = vec4(1.0); }}\n")).unwrap();
        refused_in_every_format(&file, target);
    }
}

#[test]
fn files_that_include_each_other_behind_guards_are_no_cycle() {
    let dir = common::scratch("hostile", "guards");
    std::fs::write(dir.join("a.glsl"), "#ifndef A_GLSL\n#define A_GLSL\n#include \"b.glsl\"\nfloat a() { return 1.0; }\n#endif\n").unwrap();
    std::fs::write(dir.join("b.glsl"), "#pragma once\n#include \"a.glsl\"\nfloat b() { return 2.0; }\n").unwrap();
    let file = dir.join("p.frag");
    std::fs::write(&file, "#version 330\n#extension GL_GOOGLE_include_directive : require\n#include \"a.glsl\"\nout vec4 c;\nvoid main() { c = vec4(a() + b()); }\n").unwrap();
    let out = check(&[], &[&file]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
}

#[test]
fn manifest_paths_stay_inside_the_project_root() {
    let outside = common::scratch("hostile", "manifest-outside");
    std::fs::write(outside.join("secret.frag"), "// hunter2-outside\nvoid main() {}\n").unwrap();
    let root = common::scratch("hostile", "manifest-pull-request");
    std::fs::write(root.join("effectc.toml"), "").unwrap();
    std::fs::write(root.join("a.vert"), "#version 330\nin vec3 p;\nvoid main() { gl_Position = vec4(p, 1.0); }\n").unwrap();
    let fields = [
        ("[stages]\nvertex = \"a.vert\"\nfragment = \"../manifest-outside/secret.frag\"\n", "stage"),
        ("[stages]\nvertex = \"a.vert\"\n[textures]\nt = { file = \"/proc/self/environ\" }\n", "texture"),
        ("[stages]\nvertex = \"a.vert\"\n[mesh]\nobj = \"/proc/self/environ\"\n", "mesh"),
    ];
    for (body, what) in fields {
        let manifest = root.join("effect.toml");
        std::fs::write(&manifest, format!("name = \"leak\"\n{body}")).unwrap();
        refused_in_every_format(&manifest, what);
    }
}

#[test]
fn a_report_that_cannot_be_written_and_a_settings_directory_are_said() {
    // `check > /dev/full`: exit 2 with the reason on stderr, not a silent failure.
    let full = std::fs::OpenOptions::new().write(true).open("/dev/full").unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_effectc")).args(["check", "effects/sun"]).stdout(full).output().unwrap();
    assert_eq!(code(&out), 2);
    assert!(String::from_utf8_lossy(&out.stderr).contains("cannot write the report to stdout"), "{}", String::from_utf8_lossy(&out.stderr));
    // An `effectc.toml` that is a directory is refused, not skipped for the defaults.
    let dir = common::scratch("hostile", "settings-dir");
    std::fs::create_dir_all(dir.join("effectc.toml")).unwrap();
    std::fs::write(dir.join("p.frag"), "#version 330\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n").unwrap();
    let out = check(&[], &[&dir.join("p.frag")]);
    assert_eq!(code(&out), 2, "{}", stdout(&out));
    assert!(stdout(&out).contains("E0015") && stdout(&out).contains("a directory"), "{}", stdout(&out));
}

#[test]
fn the_first_failed_write_stops_the_run_with_one_message() {
    // An output directory that cannot be made (a file is in its way): one E0014, exit 2,
    // and no "translated"/frame claims for what was not written.
    let dir = common::scratch("hostile", "unwritable");
    let blocker = dir.join("blocker");
    std::fs::write(&blocker, "a file, not a directory").unwrap();
    let out_dir = blocker.join("out");
    let out = common::effectc(&["translate", "--to", "wgsl,spv,reflect", "--out", out_dir.to_str().unwrap(), "effects/sun"]);
    assert_eq!(code(&out), 2, "{}", stdout(&out));
    assert_eq!(stdout(&out).matches("E0014").count(), 1, "{}", stdout(&out));
    assert!(!stdout(&out).contains("translated sun"), "{}", stdout(&out));
    if crate::render::have_gpu() {
        let out = common::effectc(&["render", "--frames", "3", "--size", "16x16", "--out", out_dir.to_str().unwrap(), "effects/sun"]);
        assert_eq!(code(&out), 2, "{}", stdout(&out));
        assert_eq!(stdout(&out).matches("E0014").count(), 1, "{}", stdout(&out));
        assert!(stdout(&out).contains("0 frames"), "{}", stdout(&out));
    }
}
