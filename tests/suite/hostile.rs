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
    // A pull request's manifest tries every path-taking field with every way out of the
    // root: an absolute path, a `..` escape, a symlink inside the root pointing out, and the
    // job's environment. Each is E0106 (exit 1) and nothing of the target is printed.
    let outside = common::scratch("hostile", "manifest-outside");
    std::fs::write(outside.join("secret.frag"), "// hunter2-outside\nvoid main() {}\n").unwrap();
    std::fs::write(outside.join("effect.toml"), "name = \"hunter2-outside\"\n[stages]\nfragment = \"secret.frag\"\n").unwrap();
    let root = common::scratch("hostile", "manifest-pull-request");
    std::fs::write(root.join("effectc.toml"), "").unwrap();
    std::fs::write(root.join("a.vert"), "#version 330\nin vec3 p;\nvoid main() { gl_Position = vec4(p, 1.0); }\n").unwrap();
    std::fs::write(root.join("a.frag"), "#version 330\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n").unwrap();
    std::os::unix::fs::symlink(&outside, root.join("link")).unwrap();
    let ways_out = [
        (outside.join("secret.frag").display().to_string(), outside.display().to_string(), "an absolute path"),
        ("../manifest-outside/secret.frag".to_string(), "../manifest-outside".to_string(), "a `..` escape"),
        ("link/secret.frag".to_string(), "link".to_string(), "a symlink out"),
        ("/proc/self/environ".to_string(), "/proc/self".to_string(), "the job's environment"),
    ];
    for (file, dir, way) in &ways_out {
        let fields = [
            (format!("[stages]\nvertex = \"a.vert\"\nfragment = \"{file}\"\n"), "stage"),
            (format!("[stages]\nvertex = {{ file = \"{file}\", define = {{ A = 1 }} }}\nfragment = \"a.frag\"\n"), "stage with defines"),
            (format!("[stages]\nvertex = \"a.vert\"\nfragment = \"a.frag\"\n[textures]\nt = {{ file = \"{file}\" }}\n"), "texture"),
            (format!("[stages]\nvertex = \"a.vert\"\nfragment = \"a.frag\"\n[mesh]\nobj = \"{file}\"\n"), "mesh"),
            (format!("output = \"o\"\n[targets]\no = {{}}\n[[passes]]\nname = \"p\"\nstages = {{ vertex = \"a.vert\", fragment = \"{file}\" }}\ntargets = [\"o\"]\n"), "pass stage"),
            (format!("output = \"o\"\n[targets]\no = {{}}\n[[passes]]\nname = \"p\"\neffect = \"{dir}\"\ntargets = [\"o\"]\n"), "pass effect"),
        ];
        for (body, what) in fields {
            let manifest = root.join("effect.toml");
            std::fs::write(&manifest, format!("name = \"leak\"\n{body}")).unwrap();
            refused_in_every_format(&manifest, &format!("{what}, {way}"));
        }
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
    assert!(stdout(&out).contains("is a file, and the outputs go into a directory"), "says what is in the way: {}", stdout(&out));
    assert!(!stdout(&out).contains("translated sun"), "{}", stdout(&out));
    if crate::render::have_gpu() {
        let out = common::effectc(&["render", "--frames", "3", "--size", "16x16", "--out", out_dir.to_str().unwrap(), "effects/sun"]);
        assert_eq!(code(&out), 2, "{}", stdout(&out));
        assert_eq!(stdout(&out).matches("E0014").count(), 1, "{}", stdout(&out));
        assert!(stdout(&out).contains("0 frames"), "{}", stdout(&out));
    }
}

#[test]
fn a_directory_the_settings_make_readable_may_be_included_and_no_other() {
    let shared = common::scratch("hostile", "readable-shared");
    std::fs::write(shared.join("lib.glsl"), "float k() { return 2.0; }\n").unwrap();
    let other = common::scratch("hostile", "readable-other");
    std::fs::write(other.join("lib.glsl"), "float k() { return 3.0; } // hunter2-other\n").unwrap();
    let root = common::scratch("hostile", "readable-root");
    let stage = |dir: &str| {
        let file = root.join(format!("{dir}.frag"));
        let text = format!("#version 330\n#extension GL_GOOGLE_include_directive : require\n#include \"../{dir}/lib.glsl\"\nout vec4 c;\nvoid main() {{ c = vec4(k()); }}\n");
        std::fs::write(&file, text).unwrap();
        file
    };
    let (allowed, refused) = (stage("readable-shared"), stage("readable-other"));
    std::fs::write(root.join("effectc.toml"), "readable = [\"../readable-shared\"]\n").unwrap();
    let out = check(&[], &[&allowed]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    refused_in_every_format(&refused, "a sibling the settings do not name");
    // The settings under review cannot open the machine's own directories.
    std::fs::write(root.join("effectc.toml"), "readable = [\"/proc\", \"/\", \"../readable-shared\"]\n").unwrap();
    let out = check(&[], &[&allowed]);
    assert_eq!(code(&out), 2, "{}", stdout(&out));
    assert_eq!(stdout(&out).matches("`readable` entry refused").count(), 2, "{}", stdout(&out));
}

#[test]
fn every_mistake_in_the_settings_is_reported_at_once() {
    let dir = common::scratch("hostile", "settings-mistakes");
    std::fs::write(
        dir.join("effectc.toml"),
        "colour = 1\nstrict = \"yes\"\ntarget-env = \"metal\"\n[limits]\nfile-bytes = -1\nnesting = 4\n",
    )
    .unwrap();
    std::fs::write(dir.join("p.frag"), "#version 330\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n").unwrap();
    let out = check(&["--format", "json"], &[&dir.join("p.frag")]);
    assert_eq!(code(&out), 2, "{}", stdout(&out));
    for said in
        ["unknown key `colour`", "`strict` must be", "unknown target-env `metal`", "`file-bytes` must be", "unknown limit `nesting`"]
    {
        assert!(stdout(&out).contains(said), "{said}: {}", stdout(&out));
    }
}

#[test]
fn limits_set_in_the_settings_hold_for_stages_statements_and_includes() {
    let dir = common::scratch("hostile", "settings-limits");
    std::fs::write(dir.join("effectc.toml"), "[limits]\nstatement-tokens = 500\narray-elements = 8\nfile-bytes = 4096\n").unwrap();
    let cases = [
        ("statement.frag", sum(300), "E0107", "`statement-tokens`"),
        (
            "array.frag",
            "#version 330\nuniform float w[9];\nout vec4 c;\nvoid main() { c = vec4(w[0]); }\n".to_string(),
            "E0107",
            "`array-elements`",
        ),
        (
            "big.frag",
            format!("#version 330\nout vec4 c;\n{}void main() {{ c = vec4(1.0); }}\n", "// padding\n".repeat(500)),
            "E0013",
            "file-bytes",
        ),
    ];
    for (name, text, code_said, key) in cases {
        let file = dir.join(name);
        std::fs::write(&file, text).unwrap();
        let out = check(&[], &[&file]);
        assert!(code(&out) != 0 && stdout(&out).contains(code_said) && stdout(&out).contains(key), "{name}: {}", stdout(&out));
    }
    // A header included over and over (no guard): each file is small, the stage is not.
    std::fs::write(dir.join("h.glsl"), format!("{}\n", "// a comment line of a header\n".repeat(40))).unwrap();
    let file = dir.join("many.frag");
    let includes = "#include \"h.glsl\"\n".repeat(20);
    std::fs::write(
        &file,
        format!(
            "#version 330\n#extension GL_GOOGLE_include_directive : require\n{includes}out vec4 c;\nvoid main() {{ c = vec4(1.0); }}\n"
        ),
    )
    .unwrap();
    let out = check(&[], &[&file]);
    assert_eq!(code(&out), 1, "{}", stdout(&out));
    assert!(stdout(&out).contains("E0107") && stdout(&out).contains("grows past"), "{}", stdout(&out));
}

/// A `main` of `n` statements.
fn statements(n: usize) -> String {
    let body: String = (0..n).map(|i| format!("  x = x * 1.0001 + {}.5;\n", i % 7)).collect();
    format!("#version 330\nuniform float u;\nout vec4 c;\nvoid main() {{\n  float x = u;\n{body}  c = vec4(x);\n}}\n")
}

#[test]
fn a_huge_function_is_checked_and_translated() {
    // Past 128 KiB a function leaves naga's GLSL front (quadratic in its size) for
    // glslang's SPIR-V: checked, translated to valid WGSL, and said by nothing but the note.
    let dir = common::scratch("hostile", "huge-function");
    let file = dir.join("huge.frag");
    std::fs::write(&file, statements(8_000)).unwrap();
    let out = check(&[], &[&file]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    assert!(stdout(&out).contains("checked 1 program: 1 note"), "only the stage-alone note: {}", stdout(&out));
    let target = dir.join("out");
    let out = common::effectc(&["translate", "--to", "wgsl", "--out", target.to_str().unwrap(), file.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let wgsl = std::fs::read_to_string(target.join("huge.wgsl")).unwrap();
    assert!(wgsl.matches("1.0001").count() >= 8_000, "every statement kept");
    // Past 600,000 tokens (80,000 statements of 8) the stage is refused before compiling:
    // the compilers' memory grows with its tokens.
    std::fs::write(&file, statements(80_000)).unwrap();
    let out = check(&[], &[&file]);
    assert_eq!(code(&out), 1, "{}", stdout(&out));
    assert!(stdout(&out).contains("E0107") && stdout(&out).contains("`stage-tokens`"), "{}", stdout(&out));
}

#[test]
fn a_hazard_in_a_macro_is_shown_at_the_use_not_from_the_define() {
    let dir = common::scratch("hostile", "macro-span");
    let file = dir.join("m.frag");
    let text = "#version 330\n#define D (gl_FragCoord.x - gl_FragCoord.x)\nout vec4 c;\n\n\nvoid main() {\n  float z = 2.0 / D;\n  c = vec4(z);\n}\n";
    std::fs::write(&file, text).unwrap();
    let out = check(&["--format", "json"], &[&file]);
    let report: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let division = report["diagnostics"].as_array().unwrap().iter().find(|d| d["code"] == "W0710").expect("the division is found");
    let span = &division["span"];
    assert_eq!((span["line"].as_u64(), span["end_line"].as_u64()), (Some(7), Some(7)), "{division}");
}

#[test]
fn the_hazard_analysis_stops_at_its_work_limit_and_says_so() {
    // Nested loops are iterated to a fixpoint round after round, calls are walked at every
    // call site: 12 nested loops took 125 s, and a fan of 40 functions each calling the
    // previous two 24 s. The analysis now stops at its work limit with note N0701.
    let dir = common::scratch("hostile", "hazard-work");
    let loops: String = (0..12).map(|i| format!("for (int i{i} = 0; i{i} < 4; i{i}++) {{\n")).collect();
    let nested = format!(
        "#version 330\nuniform float u;\nout vec4 c;\nvoid main() {{ float x = u;\n{loops}x += 1.0 / (x - 1.0);\n{}c = vec4(x); }}\n",
        "}\n".repeat(12)
    );
    let fan: String =
        (1..40u32).map(|i| format!("float f{i}(float x) {{ return f{}(x) + f{}(x * 0.5); }}\n", i - 1, i.saturating_sub(2))).collect();
    let fans = format!(
        "#version 330\nuniform float u;\nout vec4 c;\nfloat f0(float x) {{ return sqrt(x); }}\n{fan}void main() {{ c = vec4(f39(u)); }}\n"
    );
    for (name, text) in [("nested.frag", nested), ("fan.frag", fans)] {
        let file = dir.join(name);
        std::fs::write(&file, text).unwrap();
        let out = check(&[], &[&file]);
        assert_eq!(code(&out), 0, "{name}: {}", stdout(&out));
        assert!(stdout(&out).contains("N0701"), "{name}: {}", stdout(&out));
    }
}
