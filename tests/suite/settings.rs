//! Suppressions (`effectc: allow(…)` comments) and the repository's `effectc.toml`: each
//! silences exactly what it names, mistakes in them are warnings, globs choose the paths
//! read; diagnostics name files relative to the working directory.

use std::path::{Path, PathBuf};

use crate::common::effectc;

/// A vertex stage whose `unused` output the fragment stage never reads (W0201 at line
/// `3 + above`, where `above` lines are inserted before the declaration).
fn vertex(above: &str, after_decl: &str) -> String {
    format!("#version 330 core\nlayout(location = 0) in vec3 position;\n{above}out vec3 unused;{after_decl}\nout vec3 colour;\nvoid main() {{\n    unused = position;\n    colour = position;\n    gl_Position = vec4(position, 1.0);\n}}\n")
}

const FRAGMENT: &str = "#version 330 core\nin vec3 colour;\nout vec4 frag;\nvoid main() {\n    frag = vec4(colour, 1.0);\n}\n";

/// A fresh directory holding `a.vert` (from `vert`) and `a.frag`.
fn program(name: &str, vert: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("effectc-settings-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("a.vert"), vert).unwrap();
    std::fs::write(dir.join("a.frag"), FRAGMENT).unwrap();
    dir
}

/// `effectc check --format json` over `args`: (exit code, the codes reported in order).
fn codes(args: &[&str]) -> (i32, Vec<String>) {
    let mut all = vec!["check", "--format", "json"];
    all.extend_from_slice(args);
    let out = effectc(&all);
    let doc: serde_json::Value =
        serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&out.stdout)));
    let codes = doc["diagnostics"].as_array().unwrap().iter().map(|d| d["code"].as_str().unwrap().to_string()).collect();
    (out.status.code().unwrap(), codes)
}

fn path(p: &Path) -> &str {
    p.to_str().unwrap()
}

#[test]
fn a_suppression_silences_exactly_its_code_on_its_line() {
    let plain = program("plain", &vertex("", ""));
    assert_eq!(codes(&[path(&plain)]), (0, vec!["W0201".to_string()]), "the warning the suppressions silence");

    let above = program("above", &vertex("// effectc: allow(W0201) -- kept for a debug view\n", ""));
    assert_eq!(codes(&[path(&above)]), (0, vec![]), "a comment on the line before");

    let stacked = program("stacked", &vertex("// effectc: allow(W0201)\n\n/* effectc: allow(W0202) */\n", ""));
    let (_, got) = codes(&[path(&stacked)]);
    assert_eq!(got, ["W0005"], "stacked comments reach the next code line; the W0202 one is unused");

    let trailing = program("trailing", &vertex("", " // effectc: allow(W0201)"));
    assert_eq!(codes(&[path(&trailing)]), (0, vec![]), "a comment after code covers its own line");

    let whole = program("whole", &format!("{}// effectc: allow-file(W0201)\n", vertex("", "")));
    assert_eq!(codes(&[path(&whole)]), (0, vec![]), "allow-file covers the whole file");

    let other_code = program("other", &vertex("// effectc: allow(W0717)\n", ""));
    let (_, got) = codes(&[path(&other_code)]);
    assert_eq!(got, ["W0005", "W0201"], "another code does not silence W0201, and is unused");

    let wrong_line = program(
        "wrong-line",
        &vertex("// effectc: allow(W0201)\nout vec3 spare;\n", "").replace("unused = position;", "unused = position; spare = position;"),
    );
    let (_, got) = codes(&[path(&wrong_line)]);
    assert_eq!(got.iter().filter(|c| *c == "W0201").count(), 1, "only the line below is silenced: {got:?}");
}

#[test]
fn mistakes_in_suppressions_are_warnings() {
    let unknown = program("unknown", &vertex("// effectc: allow(W0210)\n", ""));
    let out = effectc(&["check", "--color", "never", path(&unknown)]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("warning[W0004]: unknown diagnostic code `W0210`"), "{text}");
    assert!(text.contains("did you mean `W0201`"), "{text}");
    assert!(text.contains("warning[W0201]"), "the unknown suppression silences nothing: {text}");

    let error = program("error", &vertex("// effectc: allow(E0201)\n", ""));
    let (_, got) = codes(&[path(&error)]);
    assert!(got.contains(&"W0004".to_string()), "an error cannot be allowed: {got:?}");

    let malformed = program("malformed", &vertex("// effectc: ignore(W0201)\n// effectc: allow(W0201\n", ""));
    let (_, got) = codes(&[path(&malformed)]);
    assert_eq!(got.iter().filter(|c| *c == "W0004").count(), 2, "{got:?}");
}

#[test]
fn manifests_take_hash_comments() {
    let dir = program("manifest", &vertex("", " // effectc: allow(W0201)"));
    std::fs::write(dir.join("a.frag"), FRAGMENT.replace("out vec4 frag;", "out vec4 frag;\nuniform float nobody;")).unwrap();
    // A complete manifest (its mesh and attribute given): check reports no render guesses.
    let manifest =
        "name = \"m\"\n[stages]\nvertex = \"a.vert\"\nfragment = \"a.frag\"\n[uniforms]\n# effectc: allow(W0223)\nnobody = 1.0\n\
                    [mesh]\nbuiltin = \"fullscreen_quad\"\nattributes = { position = \"position\" }\n";
    std::fs::write(dir.join("effect.toml"), manifest).unwrap();
    let (_, got) = codes(&[path(&dir.join("effect.toml"))]);
    assert_eq!(got, ["W0221"], "W0223 at `nobody` in the manifest is silenced, W0221 in the shader is not");
    std::fs::write(dir.join("effect.toml"), manifest.replace("# effectc: allow(W0223)\n", "")).unwrap();
    let (_, got) = codes(&[path(&dir.join("effect.toml"))]);
    assert_eq!(got, ["W0223", "W0221"], "removing the suppression brings the warning back");
}

#[test]
fn the_config_allows_denies_and_selects() {
    let dir = program("config", &vertex("", ""));
    std::fs::create_dir_all(dir.join("third_party")).unwrap();
    std::fs::write(dir.join("third_party/b.vert"), vertex("", "")).unwrap();
    std::fs::write(dir.join("third_party/b.frag"), FRAGMENT).unwrap();
    std::fs::write(dir.join("c.shader"), FRAGMENT).unwrap();

    let (_, got) = codes(&[path(&dir)]);
    assert_eq!(got, ["W0201", "W0201"], "a and third_party/b, c.shader unknown: {got:?}");

    std::fs::write(dir.join("effectc.toml"), "exclude = [\"third_party\"]\n").unwrap();
    assert_eq!(codes(&[path(&dir)]), (0, vec!["W0201".to_string()]), "exclude leaves third_party out");
    assert_eq!(
        codes(&[path(&dir.join("third_party/b.vert")), path(&dir.join("third_party/b.frag"))]).1,
        Vec::<String>::new(),
        "named files too"
    );

    std::fs::write(dir.join("effectc.toml"), "include = [\"third_party/**\"]\nallow = [\"W0201\"]\n").unwrap();
    assert_eq!(codes(&[path(&dir)]), (0, vec![]), "include keeps only third_party, allow silences W0201");

    std::fs::write(dir.join("effectc.toml"), "exclude = [\"third_party\"]\ndeny = [\"W0201\"]\n").unwrap();
    let out = effectc(&["check", "--color", "never", path(&dir)]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "a denied warning fails the run: {text}");
    assert!(text.contains("error[W0201]") && text.contains("raised to an error by `deny`"), "{text}");

    std::fs::write(dir.join("effectc.toml"), "exclude = [\"third_party\"]\ndeny-warnings = true\n").unwrap();
    assert_eq!(codes(&[path(&dir)]).0, 1, "deny-warnings");

    std::fs::write(dir.join("effectc.toml"), "exclude = [\"third_party\", \"a.*\"]\n[stages]\nshader = \"fragment\"\n").unwrap();
    let out = effectc(&["check", "--color", "never", path(&dir)]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("checked 1 program: 1 note") && text.contains("N0002"), "c.shader is read as a fragment stage, alone: {text}");
    std::fs::write(dir.join("effectc.toml"), "exclude = [\"third_party\", \"a.*\"]\n").unwrap();
    let out = effectc(&["check", "--color", "never", path(&dir)]);
    assert!(String::from_utf8_lossy(&out.stdout).contains("checked 0 programs"), "without [stages] it is not");

    let elsewhere = dir.join("elsewhere.toml");
    std::fs::write(&elsewhere, "allow = [\"W0201\", \"W0202\"]\n").unwrap();
    assert_eq!(codes(&["--config", path(&elsewhere), path(&dir)]), (0, vec![]), "--config replaces the discovered file");

    std::fs::write(dir.join("effectc.toml"), "exclude = \"third_party\"\n").unwrap();
    let out = effectc(&["check", "--color", "never", path(&dir)]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(2), "an invalid config is a usage error: {text}");
    assert!(text.contains("error[E0015]") && text.contains("effectc.toml:1:"), "{text}");

    std::fs::write(dir.join("effectc.toml"), "allow = [\"W0201\", \"W9999\"]\n").unwrap();
    assert_eq!(codes(&[path(&dir)]), (0, vec!["W0004".to_string()]), "an unknown code in the config warns");
}

#[test]
fn diagnostics_name_files_relative_to_the_working_directory() {
    let detour = "tests/fail/05-unread-output-warning/../05-unread-output-warning";
    let files: Vec<String> = std::fs::read_dir("tests/fail/05-unread-output-warning")
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".vert") || n.ends_with(".frag"))
        .map(|n| format!("{detour}/{n}"))
        .collect();
    let mut args = vec!["check", "--format", "github"];
    args.extend(files.iter().map(String::as_str));
    let out = effectc(&args);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("file=tests/fail/05-unread-output-warning/"), "{text}");
    assert!(!text.contains(".."), "{text}");
    let absolute = std::env::current_dir().unwrap().join(&files[0]);
    let mut args = vec!["check".to_string(), "--format".into(), "json".into(), absolute.display().to_string()];
    args.extend(files[1..].iter().cloned());
    let out = effectc(&args.iter().map(String::as_str).collect::<Vec<_>>());
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        !text.contains(&std::env::current_dir().unwrap().display().to_string()),
        "absolute paths below the working directory become relative: {text}"
    );
}

#[test]
fn a_pragma_parameter_starts_at_its_default_in_a_block_or_not() {
    // RetroArch starts each `#pragma parameter` uniform at its default, not at zero: a loose
    // uniform and a member of a named block.
    let dir = program("parameter", &vertex("", ""));
    std::fs::write(
        dir.join("a.frag"),
        "#version 330 core\n#pragma parameter GAIN \"Gain\" 0.6 0.0 1.0 0.05\n#pragma parameter TINT \"Tint\" 1.0 0.0 1.0 1.0\n\
in vec3 colour;\nuniform float GAIN;\nlayout(std140) uniform Params { float TINT; } params;\nout vec4 frag;\n\
void main() {\n    frag = vec4(GAIN, params.TINT, 0.0, 1.0) + vec4(colour * 0.0, 0.0);\n}\n",
    )
    .unwrap();
    let out = dir.join("frames");
    let pixel = |sets: &[&str]| {
        let _ = std::fs::remove_dir_all(&out);
        let mut args = vec!["render", "--color", "never", "--size", "8x8", "--verbose", "--out", path(&out), path(&dir)];
        for s in sets {
            args.extend(["--set", s]);
        }
        let r = effectc(&args);
        assert_eq!(r.status.code(), Some(0), "{}", String::from_utf8_lossy(&r.stdout));
        let png = std::fs::read_dir(&out).unwrap().map(|e| e.unwrap().path()).find(|p| p.extension().is_some_and(|e| e == "png")).unwrap();
        (image::open(&png).unwrap().to_rgba8().get_pixel(4, 4).0, String::from_utf8_lossy(&r.stdout).to_string())
    };
    let (p, text) = pixel(&[]);
    assert_eq!(p, [153, 255, 0, 255], "GAIN = 0.6 and TINT = 1, their defaults");
    assert!(text.contains("GAIN ← its `#pragma parameter` default"), "{text}");
    assert!(!text.contains("uniform `GAIN` has no value"), "a declared default is no guess (no W0403):\n{text}");
    // `--set` wins over the default.
    assert_eq!(pixel(&["GAIN=0"]).0, [0, 255, 0, 255]);
    // The listing says what the menu would.
    let r = effectc(&["check", "--list-uniforms", "--format", "json", path(&dir)]);
    let doc: serde_json::Value = serde_json::from_str(&String::from_utf8_lossy(&r.stdout)).unwrap();
    let gain = doc["programs"][0]["uniforms"].as_array().unwrap().iter().find(|u| u["name"] == "GAIN").unwrap().clone();
    assert_eq!(gain["parameter"], serde_json::json!({"name": "GAIN", "default": 0.6, "min": 0.0, "max": 1.0, "step": 0.05}));
    assert_eq!(gain["guessed"], false);
}

#[test]
fn set_gives_uniforms_their_value_and_checks_it() {
    let dir = program("set", &vertex("", ""));
    std::fs::write(dir.join("a.frag"), "#version 330 core\nin vec3 colour;\nuniform vec3 tint;\nuniform float gain;\nout vec4 frag;\nvoid main() {\n    frag = vec4(tint * gain + colour * 0.0, 1.0);\n}\n").unwrap();
    let out = dir.join("frames");
    let render = |sets: &[&str]| {
        let mut args = vec!["render", "--color", "never", "--size", "8x8", "--out", path(&out), path(&dir)];
        for s in sets {
            args.extend(["--set", s]);
        }
        effectc(&args)
    };
    let r = render(&["tint=1,0,1", "gain=1"]);
    assert_eq!(r.status.code(), Some(0), "{}", String::from_utf8_lossy(&r.stdout));
    let png = std::fs::read_dir(&out).unwrap().map(|e| e.unwrap().path()).find(|p| p.extension().is_some_and(|e| e == "png")).unwrap();
    let pixel = image::open(&png).unwrap().to_rgba8().get_pixel(4, 4).0;
    assert_eq!(pixel, [255, 0, 255, 255], "the bare program's uniforms take the --set values");

    let r = render(&["tnt=1,0,0"]);
    let text = String::from_utf8_lossy(&r.stdout);
    assert_eq!(r.status.code(), Some(1), "{text}");
    assert!(text.contains("error[E0220]") && text.contains("did you mean `tint`?") && text.contains("command line:1:7"), "{text}");
    let r = render(&["gain=1,2"]);
    assert!(String::from_utf8_lossy(&r.stdout).contains("error[E0221]"), "a list for a float does not fit");
    let r = render(&["gain=abc"]);
    assert_eq!(r.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&r.stdout).contains("is not a finite number a shader can hold, a boolean or a list"));
}

#[test]
fn list_uniforms_shows_types_defaults_and_guesses() {
    let out = effectc(&["check", "--list-uniforms", "--color", "never", "effects/sun"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("effects/sun/effect.toml: 12 uniforms"), "{text}");
    assert!(
        text.lines()
            .any(|l| l.contains("swirlIntensity") && l.contains("float") && l.contains("default 2.0") && l.contains("range [0, 8]")),
        "{text}"
    );
    assert!(text.lines().any(|l| l.contains("timeVar ") && l.contains("semantic time")), "{text}");
    let out = effectc(&["check", "--list-uniforms", "--format", "json", "tests/fail/53-bare-hazards-warning"]);
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let uniforms = &doc["programs"][0]["uniforms"];
    let time = uniforms.as_array().unwrap().iter().find(|u| u["name"] == "iTime").expect("iTime listed");
    assert_eq!((time["type"].as_str(), time["semantic"].as_str(), time["guessed"].as_bool()), (Some("float"), Some("time"), Some(true)));
    // A GLSL initializer is the value where the manifest gives none, as in GL: not a guess.
    let out = effectc(&["check", "--list-uniforms", "--format", "json", "tests/verify/compat/uniform_initializers"]);
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let c = doc["programs"][0]["uniforms"].as_array().unwrap().iter().find(|u| u["name"] == "c").expect("c listed").clone();
    assert_eq!(c["initializer"], serde_json::json!([0.1, 0.5, 0.9]), "{c}");
    assert_eq!(c["guessed"], false, "{c}");
}

#[test]
fn the_config_sets_how_long_time_runs_for_the_hazards() {
    // `sin(time * 10.0)` passes W0717's 10⁴ rad after 1,000 s: inside the default hour,
    // outside a 10-minute session.
    let dir = program("hazard-time", &vertex("", ""));
    std::fs::write(dir.join("a.frag"), "#version 330 core\nin vec3 colour;\nuniform float time;\nout vec4 frag;\nvoid main() {\n    frag = vec4(colour * sin(time * 10.0), 1.0);\n}\n").unwrap();
    let hazard = |got: &[String]| got.iter().filter(|c| *c == "W0717").count();
    // A possible hazard (time reaches the limit by assumption): not in a bare file's default
    // report, which holds what a run at fixed inputs (time 0) shows.
    assert_eq!(hazard(&codes(&[path(&dir)]).1), 0, "certain tier only by default");
    std::fs::write(dir.join("effectc.toml"), "[hazards]\nreport = \"possible\"\n").unwrap();
    assert_eq!(hazard(&codes(&[path(&dir)]).1), 1, "an hour by default");
    std::fs::write(dir.join("effectc.toml"), "[hazards]\ntime-limit = 600\nreport = \"possible\"\n").unwrap();
    assert_eq!(hazard(&codes(&[path(&dir)]).1), 0, "ten minutes: 6,000 rad at most");
    std::fs::write(dir.join("effectc.toml"), "[hazards]\ntime-limit = 86400.0\nreport = \"possible\"\n").unwrap();
    assert_eq!(hazard(&codes(&[path(&dir)]).1), 1, "a day, as a float");
    std::fs::write(dir.join("effectc.toml"), "[hazards]\ntime-limit = 86400.0\nreport = \"certain\"\n").unwrap();
    assert_eq!(hazard(&codes(&[path(&dir)]).1), 0, "a day, certain hazards only");
    for bad in [
        "[hazards]\ntime-limit = -1\n",
        "[hazards]\ntime-limit = \"1h\"\n",
        "[hazards]\nduration = 60\n",
        "hazards = 3\n",
        "[hazards]\nreport = \"all\"\n",
    ] {
        std::fs::write(dir.join("effectc.toml"), bad).unwrap();
        let out = effectc(&["check", "--color", "never", path(&dir)]);
        let text = String::from_utf8_lossy(&out.stdout);
        assert_eq!(out.status.code(), Some(2), "{bad}: {text}");
        assert!(text.contains("effectc.toml:"), "{bad}: {text}");
    }
}
