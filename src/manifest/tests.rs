use std::path::{Path, PathBuf};

use super::*;
use crate::diag::{Code, Diagnostic, FileId, Files, Severity};
use crate::stage::StageKind;

/// A fresh directory `<tmp>/<random>/<name>` holding empty `files`, removed with the value.
struct Fixture {
    _root: tempfile::TempDir,
    dir: PathBuf,
}

impl std::ops::Deref for Fixture {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.dir
    }
}

fn fixture_dir(name: &str, files: &[&str]) -> Fixture {
    let root = tempfile::Builder::new().prefix("effectc-manifest-").tempdir().unwrap();
    let dir = root.path().join(name);
    std::fs::create_dir_all(&dir).unwrap();
    for f in files {
        std::fs::write(dir.join(f), "").unwrap();
    }
    Fixture { _root: root, dir }
}

const SUN_FILES: &[&str] = &["sun.vert", "sun.frag", "px.png", "nx.png", "py.png", "ny.png", "pz.png", "nz.png", "wood.png"];

const SUN: &str = r#"name = "sun"
description = "Swirling sun with pulsing bloom"

[stages]
vertex = "sun.vert"
fragment = "sun.frag"

[uniforms]
minBI = 0.2                                   # plain value
maxBI = { value = 1.4, range = [0.0, 4.0] }   # value + range
bFrequency = { value = 2.0, range = [0.1, 10.0] }
tint = [1.0, 0.8, 0.3]                         # vec3
weights = [0.1, 0.2, 0.3]                      # float[3] or vec3
timeVar = { semantic = "time" }
model = { semantic = "model" }

[textures]
textureSamplerVar = { generate = "noise", size = 256, seed = 7 }
skybox = { cube = ["px.png","nx.png","py.png","ny.png","pz.png","nz.png"] }
albedo = { file = "wood.png" }

[mesh]
builtin = "uv_sphere"       # fullscreen_quad | quad | cube | uv_sphere | plane_grid
segments = 64
rings = 32
[mesh.attributes]
vertPosition = "position"
vertTexCoords = "uv"
"#;

fn run(text: &str, dir: &Path) -> Result<Effect, Vec<Diagnostic>> {
    parse(text, FileId(0), dir)
}

fn errors(text: &str, dir: &Path) -> Vec<Diagnostic> {
    match run(text, dir) {
        Ok(e) => panic!("expected errors, parsed {e:#?}"),
        Err(d) => d,
    }
}

fn span_text<'a>(text: &'a str, d: &Diagnostic) -> &'a str {
    &text[d.span.clone().expect("diagnostic has a span")]
}

/// The only diagnostic with `code`.
fn one(diags: &[Diagnostic], code: Code) -> &Diagnostic {
    let found: Vec<_> = diags.iter().filter(|d| d.code == code).collect();
    assert_eq!(found.len(), 1, "expected one {code} in {diags:#?}");
    found[0]
}

fn minimal(extra: &str) -> String {
    format!("{extra}\n[stages]\nvertex = \"a.vert\"\nfragment = \"a.frag\"\n")
}

fn minimal_dir() -> Fixture {
    fixture_dir("fx", &["a.vert", "a.frag", "img.png", "teapot.obj"])
}

#[test]
fn full_example_parses() {
    let dir = fixture_dir("sun", SUN_FILES);
    let e = run(SUN, &dir).unwrap();
    assert_eq!(e.name, "sun");
    assert_eq!(&SUN[e.name_span.clone()], "\"sun\"");
    assert_eq!(e.description.as_deref(), Some("Swirling sun with pulsing bloom"));
    assert_eq!(e.dir, dir.to_path_buf());
    assert!(e.warnings.is_empty(), "{:#?}", e.warnings);

    let kinds: Vec<StageKind> = e.stages.iter().map(|s| s.kind).collect();
    assert_eq!(kinds, [StageKind::Vertex, StageKind::Fragment]);
    assert_eq!(e.stages[0].path, dir.join("sun.vert"));
    assert_eq!(&SUN[e.stages[0].span.clone()], "\"sun.vert\"");
    assert_eq!(&SUN[e.stages[1].key_span.clone()], "fragment");

    let names: Vec<&str> = e.uniforms.iter().map(|u| u.name.as_str()).collect();
    assert_eq!(names, ["minBI", "maxBI", "bFrequency", "tint", "weights", "timeVar", "model"]);
    let min = e.uniform("minBI").unwrap();
    assert_eq!(min.value, Some(UniformValue::Float(0.2)));
    assert_eq!(&SUN[min.name_span.clone()], "minBI");
    assert_eq!(&SUN[min.value_span.clone()], "0.2");
    assert_eq!(min.range, None);
    let max = e.uniform("maxBI").unwrap();
    assert_eq!(max.value, Some(UniformValue::Float(1.4)));
    assert_eq!(&SUN[max.value_span.clone()], "1.4");
    assert_eq!(max.range, Some((0.0, 4.0)));
    assert_eq!(&SUN[max.range_span.clone().unwrap()], "[0.0, 4.0]");
    assert_eq!(e.uniform("bFrequency").unwrap().range, Some((0.1, 10.0)));
    let tint = e.uniform("tint").unwrap();
    assert_eq!(tint.value, Some(UniformValue::List(vec![UniformValue::Float(1.0), UniformValue::Float(0.8), UniformValue::Float(0.3)])));
    assert_eq!(tint.value.as_ref().unwrap().dims(), [3]);
    let time = e.uniform("timeVar").unwrap();
    assert_eq!(time.value, None);
    assert_eq!(time.semantic, Some(Semantic::Time));
    assert_eq!(&SUN[time.semantic_span.clone().unwrap()], "\"time\"");
    assert_eq!(&SUN[time.value_span.clone()], "{ semantic = \"time\" }");
    assert_eq!(e.uniform("model").unwrap().semantic, Some(Semantic::Model));

    let names: Vec<&str> = e.textures.iter().map(|t| t.name.as_str()).collect();
    assert_eq!(names, ["textureSamplerVar", "skybox", "albedo"]);
    let noise = e.texture("textureSamplerVar").unwrap();
    assert_eq!(noise.kind, TextureKind::D2);
    assert_eq!(
        noise.source,
        TextureSource::Generated {
            generator: Generator::Noise,
            size: 256,
            params: GeneratorParams { seed: 7, ..GeneratorParams::default() }
        }
    );
    assert_eq!(&SUN[noise.name_span.clone()], "textureSamplerVar");
    assert_eq!(noise.filter, Filter::Linear);
    assert_eq!(noise.wrap, Wrap::Repeat);
    let sky = e.texture("skybox").unwrap();
    assert_eq!(sky.kind, TextureKind::Cube);
    let faces = ["px.png", "nx.png", "py.png", "ny.png", "pz.png", "nz.png"].map(|f| dir.join(f));
    assert_eq!(sky.source, TextureSource::Faces(faces));
    let albedo = e.texture("albedo").unwrap();
    assert_eq!(albedo.source, TextureSource::File(dir.join("wood.png")));
    assert_eq!(&SUN[albedo.span.clone()], "{ file = \"wood.png\" }");

    let mesh = e.mesh.unwrap();
    assert_eq!(mesh.source, MeshSource::Builtin(BuiltinMesh::UvSphere { segments: 64, rings: 32 }));
    assert_eq!(&SUN[mesh.span.clone()], "[mesh]");
    assert_eq!(mesh.attributes, [("vertPosition".to_owned(), MeshAttribute::Position), ("vertTexCoords".to_owned(), MeshAttribute::Uv)]);
    assert_eq!(&SUN[mesh.attribute_spans[1].clone()], "vertTexCoords");
}

#[test]
fn crlf_manifest_parses_with_byte_spans() {
    let dir = fixture_dir("sun", SUN_FILES);
    let text = SUN.replace('\n', "\r\n");
    let e = run(&text, &dir).unwrap();
    assert_eq!(e.uniforms.len(), 7);
    assert_eq!(&text[e.stages[1].span.clone()], "\"sun.frag\"");
    assert_eq!(&text[e.uniform("maxBI").unwrap().value_span.clone()], "1.4");
    assert_eq!(&text[e.mesh.as_ref().unwrap().attribute_spans[0].clone()], "vertPosition");

    // Errors in a CRLF file point at the right bytes and lines too.
    let bad = "[stages]\r\nvertex = \"a.vert\"\r\nfragmnet = \"a.frag\"\r\n";
    let diags = errors(bad, &minimal_dir());
    let d = one(&diags, Code::ManifestUnknownKey);
    assert_eq!(span_text(bad, d), "fragmnet");
    let mut files = Files::new();
    let id = files.add("effect.toml", bad);
    assert_eq!(files.line_col(id, d.span.clone().unwrap().start), (3, 1));
}

#[test]
fn bom_is_accepted() {
    let text = format!("\u{feff}{}", minimal("name = \"x\"\n"));
    let e = run(&text, &minimal_dir()).unwrap();
    assert_eq!(e.name, "x");
    assert_eq!(&text[e.stages[0].span.clone()], "\"a.vert\"");
}

#[test]
fn unknown_key_suggests_the_closest() {
    let text = "[stages]\nvertex = \"a.vert\"\nfragmnet = \"a.frag\"\n";
    let diags = errors(text, &minimal_dir());
    assert_eq!(diags.len(), 1, "{diags:#?}");
    let d = &diags[0];
    assert_eq!(d.code, Code::ManifestUnknownKey);
    assert_eq!(d.severity(), Severity::Error);
    assert_eq!(span_text(text, d), "fragmnet");
    assert_eq!(d.help.as_deref(), Some("did you mean `fragment`?"));
    assert!(d.notes[0].contains("`tess_control`"), "{:?}", d.notes);

    // Top level and nested tables too.
    let text = minimal("[uniform]\nx = 1.0\n[mesh]\nbuiltin = \"cube\"\nbulitin2 = 3\n");
    let diags = errors(&text, &minimal_dir());
    assert_eq!(diags.len(), 2, "{diags:#?}");
    assert_eq!(span_text(&text, &diags[0]), "uniform");
    assert_eq!(diags[0].help.as_deref(), Some("did you mean `uniforms`?"));
    assert_eq!(span_text(&text, &diags[1]), "bulitin2");

    // Far from everything: no suggestion, but the valid keys are listed.
    let text = minimal("zzz = 1\n");
    let d = &errors(&text, &minimal_dir())[0];
    assert_eq!(d.help, None);
    assert!(d.notes[0].contains("`uniforms`"));
}

#[test]
fn wrong_types_are_reported_at_the_value() {
    let text =
        "[stages]\nvertex = 3\nfragment = \"a.frag\"\n[uniforms]\nx = { value = 1.0, range = \"x\" }\ny = \"hello\"\nz = 2024-01-01\n";
    let diags = errors(text, &minimal_dir());
    let spans: Vec<(Code, &str)> = diags.iter().map(|d| (d.code, span_text(text, d))).collect();
    assert_eq!(
        spans,
        [(Code::ManifestType, "3"), (Code::ManifestType, "\"x\""), (Code::ManifestType, "\"hello\""), (Code::ManifestType, "2024-01-01")]
    );
    assert_eq!(diags[0].message, "`stages.vertex` must be a string, found an integer");
    assert!(diags[1].message.contains("`[min, max]`"), "{}", diags[1].message);
}

#[test]
fn string_uniform_that_names_a_semantic_gets_help() {
    let text = minimal("[uniforms]\nt = \"time\"\n");
    let d = one(&errors(&text, &minimal_dir()), Code::ManifestType).clone();
    assert_eq!(d.help.as_deref(), Some("to bind a value the runtime provides, write `{ semantic = \"time\" }`"));
}

#[test]
fn range_low_above_high() {
    let text = minimal("[uniforms]\nx = { value = 1.0, range = [2.0, 1.0] }\n");
    let diags = errors(&text, &minimal_dir());
    let d = one(&diags, Code::ManifestValue);
    assert_eq!(span_text(&text, d), "[2.0, 1.0]");
    assert!(d.message.contains("lower bound 2 is greater than upper bound 1"), "{}", d.message);
    assert_eq!(diags.len(), 1);

    // Wrong arity and non-finite bounds.
    let text = minimal("[uniforms]\nx = { value = 1, range = [1] }\ny = { value = 1, range = [0, nan] }\n");
    let diags = errors(&text, &minimal_dir());
    let spans: Vec<&str> = diags.iter().map(|d| span_text(&text, d)).collect();
    assert_eq!(spans, ["[1]", "nan"]);
}

#[test]
fn value_outside_range_is_a_warning() {
    let text = minimal("[uniforms]\nx = { value = [0.5, 7.0], range = [0, 1] }\n");
    let e = run(&text, &minimal_dir()).unwrap();
    assert_eq!(e.warnings.len(), 1);
    let w = &e.warnings[0];
    assert_eq!(w.code, Code::DefaultOutOfRange);
    assert_eq!(w.severity(), Severity::Warning);
    assert_eq!(span_text(&text, w), "[0.5, 7.0]");
    assert_eq!(&text[w.labels[0].span.clone()], "[0, 1]");
    assert_eq!(e.uniforms[0].range, Some((0.0, 1.0)));
}

#[test]
fn missing_stage_file() {
    let text = "[stages]\nvertex = \"a.vert\"\nfragment = \"nope.frag\"\n";
    let dir = minimal_dir();
    let diags = errors(text, &dir);
    let d = one(&diags, Code::StageFileNotFound);
    assert_eq!(span_text(text, d), "\"nope.frag\"");
    assert_eq!(d.message, "stage file not found: `nope.frag`");
    assert!(d.notes[0].contains(&dir.join("nope.frag").display().to_string()));
}

#[test]
fn missing_or_empty_stages() {
    let dir = minimal_dir();
    let diags = errors("name = \"x\"\n", &dir);
    let d = one(&diags, Code::ManifestMissing);
    assert_eq!(d.span, None);
    assert_eq!(d.file, Some(FileId(0)));

    let text = "[stages]\n[uniforms]\n";
    let d = one(&errors(text, &dir), Code::ManifestMissing).clone();
    assert_eq!(span_text(text, &d), "stages");

    let text = "stages = 5\n";
    let d = one(&errors(text, &dir), Code::ManifestType).clone();
    assert_eq!(span_text(text, &d), "5");
}

#[test]
fn name_defaults_to_directory() {
    let dir = fixture_dir("swirl", &["a.vert", "a.frag"]);
    let e = run(&minimal(""), &dir).unwrap();
    assert_eq!(e.name, "swirl");
    assert_eq!(e.name_span, 0..0);
}

#[test]
fn garbage_input_does_not_panic() {
    let dir = minimal_dir();
    let inputs: Vec<String> = vec![
        "\u{0}\u{1}\u{2}\u{7f}ÿþ garbage ==== [[[".into(),
        "[stages\nvertex = ".into(),
        "a = 1\na = 2\n".into(),
        format!("x = {}{}", "[".repeat(5000), "]".repeat(5000)),
        format!("[uniforms]\nx = {}1{}", "[".repeat(40), "]".repeat(40)),
        "[stages]\nvertex = \"\"\n".into(),
        "[stages]\nvertex = \"a\\u0000b\"\n".into(),
        "[[stages]]\nvertex = \"a.vert\"\n".into(),
        "uniforms = [1, 2]\ntextures = 3\nmesh = []\n".into(),
        "[uniforms]\n\"\" = 1\n\"a b\" = 2\n\"gl_Position\" = 3\n".into(),
        "[mesh.attributes]\n\"1x\" = \"position\"\n".into(),
        String::new(),
    ];
    for text in &inputs {
        let diags = errors(text, &dir);
        assert!(diags.iter().any(|d| d.is_error()), "{text:?}");
        for d in &diags {
            if let Some(span) = &d.span {
                assert!(span.start <= span.end && span.end <= text.len(), "{text:?}: {d:#?}");
                assert!(text.is_char_boundary(span.start) && text.is_char_boundary(span.end));
            }
        }
    }
    let d = &errors(&inputs[0], &dir)[0];
    assert_eq!(d.code, Code::ManifestSyntax);
    let d = one(&errors(&inputs[2], &dir), Code::ManifestSyntax).clone();
    assert_eq!(span_text(&inputs[2], &d), "a");
    assert!(d.message.contains("duplicate key"), "{}", d.message);
    // Our own depth limit, when toml's is not hit first.
    let diags = errors(&inputs[4], &dir);
    assert!(diags.iter().any(|d| d.code == Code::ManifestValue && d.message.contains("nest deeper")), "{diags:#?}");
}

#[test]
fn non_finite_and_huge_numbers() {
    let text =
        minimal("[uniforms]\na = nan\nb = -inf\nc = 1e400\nd = 99999999999999999999\ne = [1.0, +nan]\nf = 0x7fffffffffffffff\ng = -1e39\n");
    let diags = errors(&text, &minimal_dir());
    let spans: Vec<(Code, &str)> = diags.iter().map(|d| (d.code, span_text(&text, d))).collect();
    assert_eq!(
        spans,
        [
            (Code::ManifestValue, "nan"),
            (Code::ManifestValue, "-inf"),
            (Code::ManifestValue, "1e400"),
            (Code::ManifestValue, "99999999999999999999"),
            (Code::ManifestValue, "+nan"),
            (Code::ManifestValue, "-1e39")
        ]
    );
}

#[test]
fn value_and_semantic_rules() {
    let dir = minimal_dir();
    let text = minimal("[uniforms]\na = { range = [0, 1] }\nb = { value = 1.0, semantic = \"time\" }\n");
    let diags = errors(&text, &dir);
    let missing = one(&diags, Code::ManifestMissing);
    assert_eq!(span_text(&text, missing), "{ range = [0, 1] }");
    let conflict = one(&diags, Code::ManifestConflict);
    assert_eq!(span_text(&text, conflict), "semantic");
    assert_eq!(&text[conflict.labels[0].span.clone()], "value");

    let text = minimal(
        "[uniforms]\na = { semantic = \"tme\" }\nb = { semantic = 3 }\nc = { semantic = \"model_view_projection\", range = [0, 1] }\n",
    );
    let diags = errors(&text, &dir);
    assert_eq!(diags.len(), 2, "{diags:#?}");
    assert_eq!(diags[0].code, Code::ManifestValue);
    assert_eq!(span_text(&text, &diags[0]), "\"tme\"");
    assert_eq!(diags[0].help.as_deref(), Some("did you mean `time`?"));
    assert!(diags[0].notes[0].contains("`camera_position`"));
    assert!(!diags[0].notes[0].contains("model_view_projection"));
    assert_eq!(diags[1].code, Code::ManifestType);
    assert_eq!(span_text(&text, &diags[1]), "3");

    let text = minimal("[uniforms]\nc = { semantic = \"model_view_projection\" }\nd = { semantic = \"mvp\" }\n");
    let e = run(&text, &dir).unwrap();
    assert_eq!(e.uniforms[0].semantic, Some(Semantic::ModelViewProjection));
    assert_eq!(e.uniforms[1].semantic, Some(Semantic::ModelViewProjection));
}

#[test]
fn many_errors_in_one_pass() {
    let text = "name = 1\n[stages]\nvertex = \"missing.vert\"\nfragmnet = \"a.frag\"\n[uniforms]\nx = { value = 1.0, range = [2, 1] }\ny = { vlaue = 1 }\n[textures]\nt = { generate = \"nosie\", size = -5 }\n[mesh]\nbuiltin = \"sphere\"\n";
    let diags = errors(text, &minimal_dir());
    let got: Vec<(Code, &str)> = diags.iter().map(|d| (d.code, span_text(text, d))).collect();
    assert_eq!(
        got,
        [
            (Code::ManifestType, "1"),
            (Code::StageFileNotFound, "\"missing.vert\""),
            (Code::ManifestUnknownKey, "fragmnet"),
            (Code::ManifestValue, "[2, 1]"),
            (Code::ManifestMissing, "{ vlaue = 1 }"),
            (Code::ManifestUnknownKey, "vlaue"),
            (Code::ManifestValue, "\"nosie\""),
            (Code::ManifestValue, "-5"),
            (Code::ManifestValue, "\"sphere\""),
        ]
    );
    assert_eq!(diags[5].help.as_deref(), Some("did you mean `value`?"));
    assert_eq!(diags[6].help.as_deref(), Some("did you mean `noise`?"));
    assert!(diags[7].message.contains("between 1 and 8192"), "{}", diags[7].message);
    assert_eq!(diags[8].help.as_deref(), Some("did you mean `uv_sphere`?"));
}

#[test]
fn uniform_lists() {
    let text = minimal("[uniforms]\nm = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]\nflat = [1, 0, 0, 0, 1, 0, 0, 0, 1]\nb = [true, false]\ni = 3\n");
    let e = run(&text, &minimal_dir()).unwrap();
    let m = e.uniform("m").unwrap().value.as_ref().unwrap();
    assert_eq!(m.dims(), [3, 3]);
    assert_eq!(m.scalars().len(), 9);
    assert_eq!(e.uniform("flat").unwrap().value.as_ref().unwrap().dims(), [9]);
    assert_eq!(e.uniform("b").unwrap().value, Some(UniformValue::List(vec![UniformValue::Bool(true), UniformValue::Bool(false)])));
    assert_eq!(e.uniform("i").unwrap().value, Some(UniformValue::Int(3)));

    let text = minimal("[uniforms]\nr = [[1, 2], [1, 2, 3]]\nmix = [1, [2]]\nbn = [true, 1]\nempty = []\n");
    let diags = errors(&text, &minimal_dir());
    let got: Vec<&str> = diags.iter().map(|d| span_text(&text, d)).collect();
    assert_eq!(got, ["[1, 2, 3]", "[2]", "1", "[]"]);
    assert!(diags.iter().all(|d| d.code == Code::ManifestValue));
    assert_eq!(&text[diags[0].labels[0].span.clone()], "[1, 2]");
}

#[test]
fn uniform_names_follow_gl_rules() {
    let text = minimal("[uniforms]\n\"lights[0].color\" = [1, 1, 1]\n\"a.b[2]\" = 1\n");
    let e = run(&text, &minimal_dir()).unwrap();
    assert_eq!(e.uniforms[0].name, "lights[0].color");
    // A `gl_` path may name the compatibility profile's state: the link checks it against
    // what the program reads (a bare malformed `gl_` name is still refused here).
    let text = minimal("[uniforms]\n\"a[]\" = 1\n\"gl_Time\" = 1\n\"gl_X[]\" = 1\n");
    let diags = errors(&text, &minimal_dir());
    let got: Vec<&str> = diags.iter().map(|d| span_text(&text, d)).collect();
    assert_eq!(got, ["\"a[]\"", "\"gl_X[]\""]);
}

#[test]
fn texture_rules() {
    let dir = minimal_dir();
    // Shorthand, generated cube, sampler settings, one colour.
    let text = minimal(
        "[textures]\na = \"img.png\"\nb = { generate = \"checker\", kind = \"cube\", cells = 4, colors = [[1, 0, 0], [0, 0, 1, 0.5]], filter = \"nearest\", wrap = \"clamp\" }\nc = { generate = \"solid\", colors = [0.5, 0.5, 0.5] }\n",
    );
    let e = run(&text, &dir).unwrap();
    assert_eq!(e.textures[0].source, TextureSource::File(dir.join("img.png")));
    let b = &e.textures[1];
    assert_eq!(b.kind, TextureKind::Cube);
    assert_eq!((b.filter, b.wrap), (Filter::Nearest, Wrap::Clamp));
    let TextureSource::Generated { generator, size, params } = &b.source else { panic!() };
    assert_eq!((*generator, *size, params.cells), (Generator::Checker, DEFAULT_TEXTURE_SIZE, 4));
    assert_eq!(params.colors, [[1.0, 0.0, 0.0, 1.0], [0.0, 0.0, 1.0, 0.5]]);
    let TextureSource::Generated { params, .. } = &e.textures[2].source else { panic!() };
    assert_eq!(params.colors, [[0.5, 0.5, 0.5, 1.0], [0.0, 0.0, 0.0, 1.0]]);
    // An integer format's colours are exact up to its range (u32::MAX, 2^24 + 1).
    let text = minimal(
        "[textures]\nids = { generate = \"checker\", format = \"rgba32ui\", colors = [[4294967295, 16777217, 0, 1], [0, 0, 0, 0]] }\n",
    );
    let e = run(&text, &dir).unwrap();
    let TextureSource::Generated { params, .. } = &e.textures[0].source else { panic!() };
    assert_eq!(params.colors[0], [4_294_967_295.0, 16_777_217.0, 0.0, 1.0]);

    // Unused generator parameter: a warning, still Ok.
    let text = minimal("[textures]\nt = { generate = \"checker\", seed = 3 }\n");
    let e = run(&text, &dir).unwrap();
    assert_eq!(e.warnings.len(), 1);
    assert_eq!(e.warnings[0].code, Code::UnusedGeneratorParam);
    assert_eq!(span_text(&text, &e.warnings[0]), "seed");

    let text = minimal(
        "[textures]\nnone = { filter = \"linear\" }\ntwo = { file = \"img.png\", generate = \"noise\" }\nsz = { file = \"img.png\", size = 64 }\nk = { file = \"img.png\", kind = \"cube\" }\nfive = { cube = [\"img.png\", \"img.png\"] }\ngone = { file = \"gone.png\" }\ncol = { generate = \"solid\", colors = [[1, 2]] }\nnum = 4\n",
    );
    let diags = errors(&text, &dir);
    let got: Vec<(Code, &str)> = diags.iter().map(|d| (d.code, span_text(&text, d))).collect();
    assert_eq!(
        got,
        [
            (Code::ManifestMissing, "{ filter = \"linear\" }"),
            (Code::ManifestConflict, "generate"),
            (Code::ManifestConflict, "size"),
            (Code::ManifestConflict, "kind"),
            (Code::ManifestValue, "[\"img.png\", \"img.png\"]"),
            (Code::AssetNotFound, "\"gone.png\""),
            (Code::ManifestValue, "[1, 2]"),
            (Code::ManifestType, "4"),
        ]
    );
    assert_eq!(&text[diags[1].labels[0].span.clone()], "file");
}

#[test]
fn texture_and_uniform_with_the_same_name() {
    let text = minimal("[uniforms]\ntex = 1\n[textures]\ntex = \"img.png\"\n");
    let diags = errors(&text, &minimal_dir());
    let d = one(&diags, Code::ManifestConflict);
    assert_eq!(d.span.clone().unwrap().start, text.rfind("\ntex =").unwrap() + 1);
    assert_eq!(d.labels[0].span.start, text.find("\ntex =").unwrap() + 1);
}

#[test]
fn mesh_rules() {
    let dir = minimal_dir();
    let e = run(&minimal("mesh = \"cube\"\n"), &dir).unwrap();
    assert_eq!(e.mesh.unwrap().source, MeshSource::Builtin(BuiltinMesh::Cube));
    let e = run(&minimal("[mesh]\nbuiltin = \"uv_sphere\"\n"), &dir).unwrap();
    assert_eq!(e.mesh.unwrap().source, MeshSource::Builtin(BuiltinMesh::UvSphere { segments: 32, rings: 16 }));
    let e = run(&minimal("[mesh]\nbuiltin = \"plane_grid\"\ndivisions = 4\n"), &dir).unwrap();
    assert_eq!(e.mesh.unwrap().source, MeshSource::Builtin(BuiltinMesh::PlaneGrid { divisions: 4 }));
    let e = run(&minimal("[mesh]\nobj = \"teapot.obj\"\n"), &dir).unwrap();
    assert_eq!(e.mesh.unwrap().source, MeshSource::Obj(dir.join("teapot.obj")));
    assert_eq!(run(&minimal(""), &dir).unwrap().mesh, None);

    let cases: &[(&str, Code, &str)] = &[
        ("[mesh]\nbuiltin = \"cube\"\nsegments = 8\n", Code::ManifestConflict, "segments"),
        ("[mesh]\nbuiltin = \"cube\"\nobj = \"teapot.obj\"\n", Code::ManifestConflict, "obj"),
        ("[mesh]\nobj = \"nope.obj\"\n", Code::AssetNotFound, "\"nope.obj\""),
        ("[mesh.attributes]\np = \"position\"\n", Code::ManifestMissing, "mesh"),
        ("[mesh]\nbuiltin = \"uv_sphere\"\nrings = 1\n", Code::ManifestValue, "1"),
        ("[mesh]\nbuiltin = \"quad\"\n[mesh.attributes]\np = \"positoin\"\n", Code::ManifestValue, "\"positoin\""),
        ("mesh = 3\n", Code::ManifestType, "3"),
    ];
    for (extra, code, span) in cases {
        let text = minimal(extra);
        let diags = errors(&text, &dir);
        assert_eq!(diags.len(), 1, "{extra}: {diags:#?}");
        assert_eq!((diags[0].code, span_text(&text, &diags[0])), (*code, *span), "{extra}");
    }
}

#[test]
fn mesh_attributes_accept_every_attribute_the_renderer_feeds() {
    let dir = minimal_dir();
    // `bitangent` was documented and rendered but rejected with E0006.
    let text = minimal("[mesh]\nbuiltin = \"cube\"\n[mesh.attributes]\naBitangent = \"bitangent\"\n");
    let mesh = run(&text, &dir).unwrap().mesh.unwrap();
    assert_eq!(mesh.attributes, [("aBitangent".to_owned(), MeshAttribute::Bitangent)]);
    assert_eq!(MeshAttribute::from_name("bitangent"), Some(MeshAttribute::Bitangent));

    // Every name parses (the renderer's mesh feeds every `MeshAttribute`), and names
    // round-trip through the enum.
    for attr in MeshAttribute::ALL {
        assert_eq!(MeshAttribute::from_name(attr.name()), Some(attr));
        let text = minimal(&format!("[mesh]\nbuiltin = \"cube\"\n[mesh.attributes]\nv = \"{}\"\n", attr.name()));
        assert_eq!(run(&text, &dir).unwrap().mesh.unwrap().attributes[0].1, attr);
    }

    // An unknown name is still E0006, and the valid names listed come from the enum.
    let text = minimal("[mesh]\nbuiltin = \"cube\"\n[mesh.attributes]\nv = \"binormal\"\n");
    let diags = errors(&text, &dir);
    let d = one(&diags, Code::ManifestValue);
    assert_eq!(span_text(&text, d), "\"binormal\"");
    let listed: Vec<String> = MESH_ATTRIBUTES.iter().map(|n| format!("`{n}`")).collect();
    assert_eq!(d.notes, [format!("expected one of: {}", listed.join(", "))]);
    assert_eq!(MeshAttribute::from_name("binormal"), None);
}

#[test]
fn stage_rules() {
    let dir = fixture_dir("st", &["a.vert", "a.frag", "a.comp", "b.geom"]);
    let text = "[stages]\nfragment = \"a.frag\"\ngeometry = \"b.geom\"\nvertex = \"a.vert\"\n";
    let e = run(text, &dir).unwrap();
    let kinds: Vec<StageKind> = e.stages.iter().map(|s| s.kind).collect();
    assert_eq!(kinds, [StageKind::Vertex, StageKind::Geometry, StageKind::Fragment]);

    let text = "[stages]\nvertex = \"a.frag\"\nfragment = \"a.frag\"\n";
    let e = run(text, &dir).unwrap();
    assert_eq!(e.warnings.len(), 1);
    assert_eq!(e.warnings[0].code, Code::StageExtension);
    assert_eq!(span_text(text, &e.warnings[0]), "\"a.frag\"");

    let text = "[stages]\nvertex = \"a.vert\"\ncompute = \"a.comp\"\n";
    let d = one(&errors(text, &dir), Code::ManifestConflict).clone();
    assert_eq!(span_text(text, &d), "compute");
    assert_eq!(&text[d.labels[0].span.clone()], "vertex");

    let e = run("[stages]\ncompute = \"a.comp\"\n", &dir).unwrap();
    assert_eq!(e.stages[0].kind, StageKind::Compute);

    // An absolute path is read inside the project root, and refused outside it (E0106).
    let abs = dir.join("a.vert");
    let text = format!("[stages]\nvertex = '{}'\n", abs.display());
    assert_eq!(run(&text, &dir).unwrap().stages[0].path, abs);
    one(&errors(&text, Path::new("/nonexistent")), Code::OutsideRoot);
}

#[test]
fn load_reads_registers_and_reports_io_errors() {
    let dir = fixture_dir("loaded", &["a.vert", "a.frag"]);
    let path = dir.join("effect.toml");
    std::fs::write(&path, minimal("[uniforms]\nx = 1.0\n")).unwrap();
    let mut files = Files::new();
    let e = load(&path, &mut files).unwrap();
    assert_eq!(e.name, "loaded");
    assert_eq!(e.dir, dir.to_path_buf());
    assert_eq!(files.path(e.file), path.display().to_string());
    assert_eq!(&files.text(e.file)[e.uniforms[0].value_span.clone()], "1.0");

    let diags = load(&dir.join("missing.toml"), &mut files).unwrap_err();
    assert_eq!(diags.len(), 1);
    assert!(is_io_error(&diags[0]));
    assert_eq!(diags[0].code, Code::ManifestIo);
    assert!(diags[0].message.contains("missing.toml"), "{}", diags[0].message);

    let bin = dir.join("binary.toml");
    std::fs::write(&bin, b"name = \"a\"\n\xff\xfe\x00garbage").unwrap();
    let diags = load(&bin, &mut files).unwrap_err();
    assert_eq!(diags[0].code, Code::ManifestSyntax);
    assert!(!is_io_error(&diags[0]));
    let id = diags[0].file.unwrap();
    assert_eq!(&files.text(id)[diags[0].span.clone().unwrap()], "\u{FFFD}");
}

#[test]
fn semantic_names_and_types() {
    for s in Semantic::ALL {
        assert_eq!(Semantic::from_name(s.name()), Some(s));
        assert!(!s.glsl_types().is_empty());
    }
    assert_eq!(Semantic::from_name("model_view_projection"), Some(Semantic::ModelViewProjection));
    assert_eq!(Semantic::ModelViewProjection.name(), "mvp");
    assert_eq!(Semantic::Time.glsl_types(), ["float"]);
    assert_eq!(Semantic::Resolution.glsl_types(), ["vec2", "vec3"]);
    assert_eq!(Semantic::NormalMatrix.glsl_types(), ["mat3", "mat4"]);
    assert_eq!(Semantic::Frame.glsl_types(), ["int", "uint", "float"]);
    assert_eq!(serde_json::to_string(&Semantic::ModelViewProjection).unwrap(), "\"mvp\"");
    assert_eq!(serde_json::to_string(&Semantic::DeltaTime).unwrap(), "\"delta_time\"");
}

#[test]
fn suggestions() {
    assert_eq!(did_you_mean("fragmnet", &["vertex", "fragment"]), Some("fragment"));
    assert_eq!(did_you_mean("Vertex", &["vertex", "fragment"]), Some("vertex"));
    assert_eq!(did_you_mean("tess-control", &["tess_control", "tess_eval"]), Some("tess_control"));
    assert_eq!(did_you_mean("xyz", &["vertex", "fragment"]), None);
    assert_eq!(did_you_mean("", &["vertex"]), None);
}

/// Random edits of the full example: never a panic, spans always inside the text.
#[test]
fn mutated_manifests_never_panic() {
    let dir = fixture_dir("sun", SUN_FILES);
    let mut seed: u64 = 0x1234_5678;
    let mut rnd = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed
    };
    let alphabet: Vec<char> = "[]{}=,.\"'\n\r #-+_0123456789abcdefnaixyz\u{0}é\\".chars().collect();
    for _ in 0..3000 {
        let mut chars: Vec<char> = SUN.chars().collect();
        for _ in 0..(rnd() % 6 + 1) {
            let at = (rnd() as usize) % (chars.len() + 1);
            match rnd() % 3 {
                0 if at < chars.len() => {
                    chars.remove(at);
                }
                1 if at < chars.len() => chars[at] = alphabet[(rnd() as usize) % alphabet.len()],
                _ => chars.insert(at, alphabet[(rnd() as usize) % alphabet.len()]),
            }
        }
        let text: String = chars.into_iter().collect();
        let r = std::panic::catch_unwind(|| run(&text, &dir));
        match r {
            Err(_) => panic!("panic on {text:?}"),
            Ok(Err(diags)) => {
                for d in &diags {
                    if let Some(span) = &d.span {
                        assert!(
                            span.end <= text.len() && text.is_char_boundary(span.start) && text.is_char_boundary(span.end),
                            "{text:?} {d:?}"
                        );
                    }
                }
            }
            Ok(Ok(_)) => {}
        }
    }
}

#[test]
fn camera_model_and_render_sections_parse() {
    let dir = minimal_dir();
    let text = minimal(
        r#"
[camera]
eye = [0, 1, 4]
target = [0, 0, 0]
fov = 60
ease = "smooth"
keys = [{ time = 0, eye = [0, 0, 3] }, { time = 2.5, eye = [3, 0, 0], target = [0, 1, 0] }]

[model]
scale = 2
spin = [0, 45, 0]

[render]
size = [320, 200]
frames = 12
fps = 8
clear = [0.1, 0.2, 0.3]
cull = "back"
depth_test = false
"#,
    );
    let e = run(&text, &dir).unwrap();
    let cam = e.camera.unwrap();
    assert_eq!((cam.eye, cam.fov, cam.ease), ([0.0, 1.0, 4.0], 60.0, Ease::Smooth));
    assert_eq!(cam.keys.len(), 2);
    assert_eq!(cam.keys[0].target, [0.0, 0.0, 0.0], "a key without target looks at the camera's target");
    assert_eq!(cam.keys[1].target, [0.0, 1.0, 0.0]);
    assert_eq!((e.model.scale, e.model.spin), ([2.0; 3], [0.0, 45.0, 0.0]));
    assert_eq!((e.render.size, e.render.frames, e.render.fps), (Some((320, 200)), Some(12), Some(8.0)));
    assert_eq!((e.render.clear, e.render.cull, e.render.depth_test), ([0.1, 0.2, 0.3, 1.0], Cull::Back, false));
}

#[test]
fn scene_section_errors_point_at_their_values() {
    let dir = minimal_dir();
    let text = minimal(
        r#"
[camera]
eye = [0, 0, 0]
fov = 180
near = 10
far = 1
keys = [{ time = 2, eye = [0, 0, 3] }, { time = 1, eye = [0, 0, 4] }, { eye = [1, 1, 1] }]

[model]
scale = 0

[render]
size = [0, 99999]
cull = "backside"
zoom = 2
"#,
    );
    let diags = errors(&text, &dir);
    let spans: Vec<(Code, &str)> = diags.iter().map(|d| (d.code, span_text(&text, d))).collect();
    assert!(spans.contains(&(Code::ManifestValue, "180")), "{spans:?}");
    assert!(spans.contains(&(Code::ManifestValue, "1")), "decreasing key time: {spans:?}");
    assert!(spans.contains(&(Code::ManifestMissing, "{ eye = [1, 1, 1] }")), "{spans:?}");
    assert!(spans.contains(&(Code::ManifestValue, "0")), "zero scale or size: {spans:?}");
    assert!(spans.contains(&(Code::ManifestValue, "99999")), "{spans:?}");
    assert!(spans.contains(&(Code::ManifestValue, "\"backside\"")), "{spans:?}");
    assert!(spans.contains(&(Code::ManifestUnknownKey, "zoom")), "{spans:?}");
    let near_far = errors(&minimal("[camera]\nnear = 10\nfar = 1\n"), &dir);
    assert_eq!(span_text(&minimal("[camera]\nnear = 10\nfar = 1\n"), one(&near_far, Code::ManifestValue)), "10");
    let degenerate = errors(&minimal("[camera]\neye = [0, 0, 0]\n"), &dir);
    assert!(one(&degenerate, Code::ManifestValue).message.contains("equals its `target`"));
}

#[test]
fn instances_blend_and_depth_write_parse() {
    let dir = minimal_dir();
    let text = minimal(
        r#"
[render]
blend = "additive"
depth_write = false

[instances]
count = 3

[instances.attributes]
aOffset = { random = [[-1, 0, -1], [1, 2, 1]], seed = 5 }
aPhase = { sequence = [0.5, 0.25] }
aTint = { values = [[1, 0, 0], [0, 1, 0], [0, 0, 1]] }
"#,
    );
    let e = run(&text, &dir).unwrap();
    assert_eq!((e.render.blend, e.render.depth_write), (Blend::Additive, false));
    let inst = e.instances.unwrap();
    assert_eq!(inst.count, 3);
    let names: Vec<(&str, usize)> = inst.attributes.iter().map(|a| (a.input.as_str(), a.components)).collect();
    assert_eq!(names, vec![("aOffset", 3), ("aPhase", 1), ("aTint", 3)]);
    assert_eq!(inst.attributes[0].source, InstanceSource::Random { lo: [-1.0, 0.0, -1.0, 0.0], hi: [1.0, 2.0, 1.0, 0.0], seed: 5 });
}

#[test]
fn mesh_attribute_tables_give_values_per_vertex() {
    let dir = minimal_dir();
    let text = minimal(
        r#"
[mesh]
builtin = "quad"

[mesh.attributes]
aPos = "position"
aBone = { values = [[0, 1], [1, 2], [2, 3], [3, 4]] }
aPhase = { sequence = [0.5, 0.25] }
aJitter = { random = [0, 1], seed = 9 }
"#,
    );
    let mesh = run(&text, &dir).unwrap().mesh.unwrap();
    assert_eq!(mesh.attributes, [("aPos".to_owned(), MeshAttribute::Position)]);
    let names: Vec<(&str, usize)> = mesh.values.iter().map(|a| (a.input.as_str(), a.components)).collect();
    assert_eq!(names, vec![("aBone", 2), ("aPhase", 1), ("aJitter", 1)]);
    assert_eq!(&text[mesh.values[0].input_span.clone()], "aBone");
    assert_eq!(mesh.values[2].source, InstanceSource::Random { lo: [0.0; 4], hi: [1.0, 0.0, 0.0, 0.0], seed: 9 });
    // The vertex count is the mesh's: any length parses; a table needs one source.
    let diags = errors(&minimal("[mesh]\nbuiltin = \"quad\"\n[mesh.attributes]\naBone = { value = [1] }\n"), &dir);
    assert!(one(&diags, Code::ManifestUnknownKey).message.contains("`value`"), "{diags:?}");
}

#[test]
fn instance_errors_point_at_their_values() {
    let dir = minimal_dir();
    let text = minimal(
        r#"
[instances]
count = 2

[instances.attributes]
a = { values = [1, 2, 3] }
b = { random = [[0, 0], [1, 1, 1]] }
c = { sequence = [0, 1], seed = 4 }
d = { }
"#,
    );
    let diags = errors(&text, &dir);
    let spans: Vec<(Code, &str)> = diags.iter().map(|d| (d.code, span_text(&text, d))).collect();
    assert!(spans.contains(&(Code::ManifestValue, "[1, 2, 3]")), "3 values for 2 instances: {spans:?}");
    assert!(spans.contains(&(Code::ManifestValue, "[[0, 0], [1, 1, 1]]")), "ends of different sizes: {spans:?}");
    assert!(spans.contains(&(Code::ManifestConflict, "seed")), "seed without random: {spans:?}");
    assert!(spans.contains(&(Code::ManifestMissing, "{ }")), "no source: {spans:?}");
    let no_count = errors(&minimal("[instances]\n"), &dir);
    assert!(one(&no_count, Code::ManifestMissing).message.contains("needs `count`"));
}

const PASSES: &str = r#"name = "post"
output = "final"

[uniforms]
amount = 0.5

[targets]
scene = { format = "rgba16f" }
half = { format = "r32f", scale = 0.5 }
fixed = { format = "rgba8", size = [64, 32] }
depth = { format = "depth32f" }
final = {}

[[passes]]
name = "scene"
stages = { vertex = "a.vert", fragment = "a.frag" }
mesh = "cube"
depth = "depth"
targets = ["scene"]
cull = "back"

[[passes]]
name = "post-1"
stages = { vertex = "a.vert", fragment = "b.frag" }
draw = "fullscreen"
uniforms = { amount = 1.0 }
samples = { sceneTex = "scene", lut = { target = "fixed", filter = "nearest" } }
targets = ["final"]
blend = "additive"
clear = false
"#;

#[test]
fn passes_targets_and_output_parse() {
    let dir = fixture_dir("post", &["a.vert", "a.frag", "b.frag"]);
    let e = run(PASSES, &dir).unwrap();
    assert!(e.is_multi_pass() && e.stages.is_empty());
    assert_eq!(e.output.as_ref().unwrap().name, "final");
    let formats: Vec<(&str, TargetFormat)> = e.targets.iter().map(|t| (t.name.as_str(), t.format)).collect();
    assert_eq!(
        formats,
        [
            ("scene", TargetFormat::Rgba16f),
            ("half", TargetFormat::R32f),
            ("fixed", TargetFormat::Rgba8),
            ("depth", TargetFormat::Depth32f),
            ("final", TargetFormat::Rgba8)
        ]
    );
    assert_eq!(e.target("half").unwrap().size.resolve((512, 300)), (256, 150));
    assert_eq!(e.target("fixed").unwrap().size.resolve((512, 300)), (64, 32));
    let [scene, post] = &e.passes[..] else { panic!("two passes") };
    assert_eq!((scene.name.as_str(), scene.stages.len(), scene.depth.as_ref().unwrap().name.as_str()), ("scene", 2, "depth"));
    assert_eq!(scene.cull, Some(Cull::Back));
    assert_eq!(post.draw, PassDraw::Fullscreen);
    assert_eq!(post.clear, PassClear::Keep);
    assert_eq!(post.blend, Some(Blend::Additive));
    let samples: Vec<(&str, &str, Filter)> = post.samples.iter().map(|s| (s.sampler.as_str(), s.target.name.as_str(), s.filter)).collect();
    assert_eq!(samples, [("sceneTex", "scene", Filter::Linear), ("lut", "fixed", Filter::Nearest)]);
    // The pass view: the pass's stages, its uniform value over the shared one, the
    // fullscreen triangle, no depth test without a depth target.
    let view = e.pass_view(post, None);
    assert_eq!(view.name, "post.post-1");
    assert!(view.passes.is_empty() && view.stages.len() == 2);
    assert_eq!(view.uniform("amount").unwrap().value, Some(UniformValue::Float(1.0)));
    assert!(matches!(view.mesh.as_ref().unwrap().source, MeshSource::Builtin(BuiltinMesh::FullscreenTriangle)));
    assert!(!view.render.depth_test);
    assert_eq!(view.render.blend, Blend::Additive);
    assert!(e.pass_view(scene, None).render.depth_test);
}

#[test]
fn pass_mistakes_are_reported_at_their_keys() {
    let dir = fixture_dir("post", &["a.vert", "a.frag", "b.frag"]);
    let cases: &[(&str, Code, &str)] = &[
        ("name = \"post\"\n[stages]\nvertex = \"a.vert\"\n[[passes]]\nstages = { vertex = \"a.vert\" }\ntargets = [\"x\"]\n", Code::ManifestConflict, "stages"),
        ("output = \"x\"\n[[passes]]\nname = \"p\"\nstages = { vertex = \"a.vert\" }\n", Code::ManifestMissing, "\"p\""),
        ("output = \"x\"\n[[passes]]\nname = \"p\"\ntargets = [\"x\"]\n", Code::ManifestMissing, "\"p\""),
        ("[[passes]]\nname = \"p\"\nstages = { vertex = \"a.vert\" }\ntargets = [\"x\"]\n", Code::ManifestMissing, "passes"),
        ("output = \"x\"\n[[passes]]\nname = \"p\"\neffect = \"nowhere\"\ntargets = [\"x\"]\n", Code::AssetNotFound, "\"nowhere\""),
        ("output = \"x\"\n[[passes]]\nname = \"p\"\neffect = \"../elsewhere\"\ntargets = [\"x\"]\n", Code::OutsideRoot, "\"../elsewhere\""),
        ("output = \"x\"\n[targets]\nx = { format = \"rgb9\" }\n[[passes]]\nstages = { vertex = \"a.vert\" }\ntargets = [\"x\"]\n", Code::ManifestValue, "\"rgb9\""),
        ("output = \"x\"\n[targets]\nx = { scale = 0.5, size = [4, 4] }\n[[passes]]\nstages = { vertex = \"a.vert\" }\ntargets = [\"x\"]\n", Code::ManifestConflict, "size"),
        ("output = \"x\"\n[[passes]]\nname = \"a.b\"\nstages = { vertex = \"a.vert\" }\ntargets = [\"x\"]\n", Code::ManifestValue, "\"a.b\""),
        ("output = \"x\"\n[[passes]]\nname = \"p\"\nstages = { vertex = \"a.vert\" }\ntargets = [\"x\"]\n[[passes]]\nname = \"p\"\nstages = { vertex = \"a.vert\" }\ntargets = [\"x\"]\n", Code::ManifestValue, "\"p\""),
        ("output = \"x\"\n[[passes]]\nstages = { vertex = \"a.vert\" }\ntargets = [\"x\"]\ndraw = \"quad\"\n", Code::ManifestValue, "\"quad\""),
        ("output = \"x\"\n[[passes]]\nstages = { vertex = \"a.vert\" }\ntargets = [\"x\"]\nsampels = {}\n", Code::ManifestUnknownKey, "sampels"),
        ("output = \"x\"\n", Code::ManifestConflict, "\"x\""),
    ];
    for (text, code, at) in cases {
        let diags = errors(text, &dir);
        let d = diags.iter().find(|d| d.code == *code).unwrap_or_else(|| panic!("{code} for:\n{text}\ngot {diags:?}"));
        assert_eq!(span_text(text, d), *at, "{text}");
    }
}
