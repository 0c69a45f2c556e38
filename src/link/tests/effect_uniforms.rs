//! `effect.toml` against the shaders.

use super::*;
use crate::manifest::Effect;
use crate::stage::StageKind::{Fragment, Vertex};

/// The program plus its parsed manifest (`extra` is appended after `[stages]`).
struct Setup {
    p: Program,
    effect: Effect,
    /// The manifest's directory, removed with the setup.
    _dir: tempfile::TempDir,
}

impl Setup {
    fn new(vert: &str, frag: &str, extra: &str) -> Setup {
        let root = tempfile::Builder::new().prefix("effectc-link-").tempdir().unwrap();
        let dir = root.path();
        std::fs::write(dir.join("shader.vert"), vert).unwrap();
        std::fs::write(dir.join("shader.frag"), frag).unwrap();
        let text = format!("[stages]\nvertex = \"shader.vert\"\nfragment = \"shader.frag\"\n\n{extra}");
        let mut p = Program::new(&[(Vertex, vert), (Fragment, frag)]);
        let id = p.files.add("effect.toml", text.clone());
        let effect = crate::manifest::parse(&text, id, dir).expect("the manifest parses");
        Setup { p, effect, _dir: root }
    }
    fn check(&self) -> Vec<Diagnostic> {
        super::super::check_manifest(&self.effect, &self.p.stages, &self.p.files)
    }
    fn manifest(&self) -> FileId {
        self.effect.file
    }
}

const VERT: &str = "#version 330\nin vec2 pos;\nout vec2 uv;\nvoid main() { uv = pos; gl_Position = vec4(pos, 0.0, 1.0); }\n";

fn frag(decls: &str, body: &str) -> String {
    format!("#version 330\nin vec2 uv;\nout vec4 fragColor;\n{decls}\nvoid main() {{ {body} }}\n")
}

#[test]
fn unknown_uniform_suggests_the_nearest_name() {
    let f = frag("uniform float minBI;\nuniform float maxBI;", "fragColor = vec4(mix(minBI, maxBI, uv.x));");
    let s = Setup::new(VERT, &f, "[uniforms]\nminBI = 0.2\nmaxBl = 1.4\n");
    let diags = s.check();
    // The typo, and `maxBI` consequently has no default.
    assert_eq!(codes(&diags), [Code::UniformUndeclared, Code::UniformNoDefault], "{diags:#?}");
    let d = only(&diags, Code::UniformUndeclared);
    assert_eq!(primary(&s.p, d), (s.manifest(), "maxBl"));
    assert_eq!(d.help.as_deref(), Some("did you mean `maxBI`?"));
    assert_eq!(label_texts(&s.p, d, s.p.file(Fragment)), ["maxBI"]);
    let w = only(&diags, Code::UniformNoDefault);
    assert_eq!(primary(&s.p, w), (s.p.file(Fragment), "maxBI"));
}

#[test]
fn unknown_uniform_without_a_close_name_lists_the_declarations() {
    let f = frag("uniform float minBI;", "fragColor = vec4(minBI);");
    let s = Setup::new(VERT, &f, "[uniforms]\nminBI = 0.2\nexposure = 1.0\n");
    let diags = s.check();
    let d = only(&diags, Code::UniformUndeclared);
    assert_eq!(d.help, None);
    assert_eq!(label_texts(&s.p, d, s.p.file(Fragment)), ["minBI"]);
    assert!(d.labels[0].message.contains("declares `minBI`"), "{d:#?}");
}

#[test]
fn value_type_mismatch_points_at_value_and_declaration() {
    let f = frag("uniform vec3 tint;", "fragColor = vec4(tint, 1.0);");
    let s = Setup::new(VERT, &f, "[uniforms]\ntint = [1.0, 0.5]\n");
    let diags = s.check();
    assert_eq!(codes(&diags), [Code::UniformDefaultType], "{diags:#?}");
    let d = &diags[0];
    assert_eq!(d.message, "the default for `tint` does not fit its type `vec3`");
    assert_eq!(primary(&s.p, d), (s.manifest(), "[1.0, 0.5]"));
    assert_eq!(d.primary_label, "expected a list of 3 numbers, found a list of 2 numbers");
    assert_eq!(label_texts(&s.p, d, s.p.file(Fragment)), ["tint"]);
}

#[test]
fn values_of_every_shape() {
    let decls = "uniform float a; uniform int b; uniform uint c; uniform bool d; uniform ivec2 e;\nuniform mat2 m; uniform mat3 n; uniform float w[3]; uniform vec2 v[2];";
    let body = "fragColor = vec4(a + float(b) + float(c) + float(d) + float(e.x) + m[0][0] + n[0][0] + w[0] + v[0].x);";
    let good = "[uniforms]\na = 1\nb = 2\nc = 3\nd = true\ne = [1, 2]\nm = [1.0, 0.0, 0.0, 1.0]\nn = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]\nw = [0.1, 0.2, 0.3]\nv = [[0.0, 1.0], [1.0, 0.0]]\n";
    let s = Setup::new(VERT, &frag(decls, body), good);
    let diags = s.check();
    assert!(diags.is_empty(), "{diags:#?}");
    let bad = "[uniforms]\na = true\nb = 2.5\nc = -1\nd = 1\ne = [1.0, 2]\nm = [1.0, 0.0, 0.0]\nn = [[1.0, 0.0], [0.0, 1.0]]\nw = [0.1, 0.2]\nv = [0.0, 1.0]\n";
    let s = Setup::new(VERT, &frag(decls, body), bad);
    let diags = s.check();
    assert_eq!(codes(&diags), [Code::UniformDefaultType; 9], "{diags:#?}");
    let c = diags.iter().find(|d| d.message.contains("`c`")).unwrap();
    assert_eq!(c.primary_label, "expected a non-negative integer, found the negative integer `-1`");
}

#[test]
fn semantic_and_range_must_fit_the_type() {
    let f = frag("uniform vec2 t;\nuniform bvec3 tint;\nuniform float time;", "fragColor = vec4(t, float(tint.x), time);");
    let s = Setup::new(
        VERT,
        &f,
        "[uniforms]\nt = { semantic = \"time\" }\ntint = { value = [true, true, true], range = [0.0, 1.0] }\ntime = { semantic = \"time\" }\n",
    );
    let diags = s.check();
    assert_eq!(codes(&diags), [Code::SemanticType, Code::RangeNotNumeric], "{diags:#?}");
    let sem = only(&diags, Code::SemanticType);
    assert_eq!(primary(&s.p, sem), (s.manifest(), "\"time\""));
    assert_eq!(label_texts(&s.p, sem, s.p.file(Fragment)), ["t"]);
    assert!(sem.help.as_deref().unwrap().contains("`resolution`"), "{sem:#?}");
    let range = only(&diags, Code::RangeNotNumeric);
    assert_eq!(primary(&s.p, range), (s.manifest(), "[0.0, 1.0]"));
}

#[test]
fn read_uniform_without_default_warns_with_an_example() {
    let f = frag("uniform float bFrequency;\nuniform float timeVarFrag;", "fragColor = vec4(sin(timeVarFrag * bFrequency));");
    let s = Setup::new(VERT, &f, "");
    let diags = s.check();
    assert_eq!(codes(&diags), [Code::UniformNoDefault, Code::UniformNoDefault], "{diags:#?}");
    assert_eq!(diags[0].message, "uniform `bFrequency` has no default in effect.toml");
    assert_eq!(primary(&s.p, &diags[0]), (s.p.file(Fragment), "bFrequency"));
    assert_eq!(diags[0].help.as_deref(), Some("add `bFrequency = 0.0` under [uniforms] in effect.toml"));
    assert!(diags[1].help.as_deref().unwrap().contains("{ semantic = \"time\" }"), "{:#?}", diags[1]);
}

#[test]
fn unread_uniform_and_its_default_warn() {
    let f = frag("uniform float used;\nuniform float unused;", "fragColor = vec4(used);");
    let s = Setup::new(VERT, &f, "[uniforms]\nused = 1.0\nunused = 2.0\n");
    let diags = s.check();
    assert_eq!(codes(&diags), [Code::UniformUnread, Code::DefaultUnread], "{diags:#?}");
    let w = only(&diags, Code::UniformUnread);
    assert_eq!(w.message, "uniform `unused` is declared but never read");
    assert_eq!(primary(&s.p, w), (s.p.file(Fragment), "unused"));
    let m = only(&diags, Code::DefaultUnread);
    assert_eq!(primary(&s.p, m), (s.manifest(), "unused"));
    assert_eq!(label_texts(&s.p, m, s.p.file(Fragment)), ["unused"]);
}

#[test]
fn a_uniform_read_in_any_stage_counts_as_read() {
    let vert = "#version 330\nin vec2 pos;\nout vec2 uv;\nuniform float scale;\nvoid main() { uv = pos; gl_Position = vec4(pos * scale, 0.0, 1.0); }\n";
    let f = frag("uniform float scale;", "fragColor = vec4(uv, 0.0, 1.0);");
    let s = Setup::new(vert, &f, "[uniforms]\nscale = 1.0\n");
    assert!(s.check().is_empty());
}

#[test]
fn anonymous_block_members_take_defaults() {
    let f = frag("layout(std140) uniform Params { float gain; vec3 tint; };", "fragColor = vec4(tint * gain, 1.0);");
    let s = Setup::new(VERT, &f, "[uniforms]\ngain = 2.0\ntint = [1.0, 0.5]\n");
    let diags = s.check();
    assert_eq!(codes(&diags), [Code::UniformDefaultType], "{diags:#?}");
}

#[test]
fn struct_paths_and_whole_structs() {
    let f = frag("struct Light { vec3 color; float power; };\nuniform Light light;", "fragColor = vec4(light.color * light.power, 1.0);");
    let s = Setup::new(VERT, &f, "[uniforms]\nlight = 1.0\n\"light.color\" = [1.0, 1.0, 1.0]\n\"light.powr\" = 2.0\n");
    let diags = s.check();
    assert_eq!(codes(&diags), [Code::UniformDefaultType, Code::UniformPathMismatch], "{diags:#?}");
    assert_eq!(only(&diags, Code::UniformPathMismatch).help.as_deref(), Some("did you mean `light.power`?"));
    assert!(only(&diags, Code::UniformDefaultType).help.as_deref().unwrap().contains("`light.color`"));
}

#[test]
fn textures_against_samplers() {
    let f = frag(
        "uniform sampler2D textureSamplerVar;\nuniform samplerCube sky;\nuniform sampler2D noTexture;",
        "fragColor = texture(textureSamplerVar, uv) + texture(sky, vec3(uv, 1.0)) + texture(noTexture, uv);",
    );
    let s = Setup::new(VERT, &f, "[textures]\ntextureSampler = { generate = \"noise\" }\nsky = { generate = \"checker\" }\n");
    let diags = s.check();
    // `textureSampler` is a typo (and so `textureSamplerVar` has no texture), `sky` is
    // bound to a 2d texture, `noTexture` has none.
    assert_eq!(
        codes(&diags),
        [Code::TextureNoSampler, Code::TextureKindMismatch, Code::SamplerNoTexture, Code::SamplerNoTexture],
        "{diags:#?}"
    );
    let d = only(&diags, Code::TextureNoSampler);
    assert_eq!(primary(&s.p, d), (s.manifest(), "textureSampler"));
    assert_eq!(d.help.as_deref(), Some("did you mean `textureSamplerVar`?"));
    let k = only(&diags, Code::TextureKindMismatch);
    assert_eq!(label_texts(&s.p, k, s.p.file(Fragment)), ["sky"]);
}

#[test]
fn sampler_under_uniforms_is_rejected() {
    let f = frag("uniform sampler2D tex;", "fragColor = texture(tex, uv);");
    let s = Setup::new(VERT, &f, "[uniforms]\ntex = 1\n");
    let diags = s.check();
    assert_eq!(codes(&diags), [Code::UniformDefaultType, Code::SamplerNoTexture], "{diags:#?}");
    let d = only(&diags, Code::UniformDefaultType);
    assert_eq!(primary(&s.p, d), (s.manifest(), "tex"));
    assert_eq!(d.help.as_deref(), Some("bind a texture under [textures] instead: `tex = { file = \"…\" }`"));
}

#[test]
fn the_sun_manifest_against_the_sun_shader() {
    let frag = "#version 420 core\nin vert_out { vec2 outputTexCoords; vec3 swirlPosVector; } frag_in;\nout vec4 fragColor;\nuniform sampler2D textureSamplerVar;\nuniform float timeVarFrag;\nuniform float minBI;\nuniform float maxBI;\nuniform float bFrequency;\nvoid main() { vec4 t = texture(textureSamplerVar, frag_in.outputTexCoords); fragColor = t * mix(minBI, maxBI, 0.5 + 0.5 * sin(timeVarFrag * bFrequency)); }\n";
    let vert = "#version 420 core\nout vert_out { vec2 outputTexCoords; vec3 swirlPosVector; } vert_out;\nlayout(location = 0) in vec3 vertPosition;\nuniform mat4 model;\nuniform float timeVar;\nvoid main() { vert_out.outputTexCoords = vertPosition.xy; vert_out.swirlPosVector = vertPosition * timeVar; gl_Position = model * vec4(vertPosition, 1.0); }\n";
    let s = Setup::new(
        vert,
        frag,
        "[uniforms]\nminBI = 0.2\nmaxBI = { value = 1.4, range = [0.0, 4.0] }\nbFrequency = 2.0\ntimeVar = { semantic = \"time\" }\ntimeVarFrag = { semantic = \"time\" }\nmodel = { semantic = \"model\" }\n\n[textures]\ntextureSamplerVar = { generate = \"noise\" }\n",
    );
    let diags = s.check();
    assert!(diags.is_empty(), "{diags:#?}");
    assert!(s.p.interface().is_empty());
}

#[test]
fn sampler_arrays_and_struct_samplers_need_textures_not_values() {
    let f = frag(
        "struct Material { sampler2D diffuse; float shininess; };\nuniform Material material;\nuniform sampler2D maps[2];",
        "fragColor = texture(material.diffuse, uv) * material.shininess + texture(maps[1], uv);",
    );
    let s = Setup::new(VERT, &f, "[textures]\n\"maps[0]\" = { generate = \"checker\" }\n");
    let diags = s.check();
    assert_eq!(codes(&diags), [Code::UniformNoDefault, Code::SamplerNoTexture], "{diags:#?}");
    let w = only(&diags, Code::UniformNoDefault);
    assert_eq!(w.help.as_deref(), Some("add its members under [uniforms] in effect.toml: `material.shininess = 0.0`"));
    let t = only(&diags, Code::SamplerNoTexture);
    assert_eq!(t.message, "sampler `material.diffuse` has no entry in [textures]");
}

#[test]
fn range_applies_to_numbers_and_numeric_vectors_only() {
    let f = frag("uniform vec3 tint;\nuniform mat2 warp;\nuniform bvec2 flags;", "fragColor = vec4(tint * (warp * uv).x, float(flags.x));");
    let s = Setup::new(
        VERT,
        &f,
        "[uniforms]\ntint = { value = [1, 0.5, 0], range = [0, 1] }\nwarp = { value = [1, 0, 0, 1], range = [0, 1] }\nflags = { value = [true, false], range = [0, 1] }\n",
    );
    let diags = s.check();
    let ranges: Vec<&Diagnostic> = diags.iter().filter(|d| d.code == Code::RangeNotNumeric).collect();
    assert_eq!(ranges.len(), 2, "mat2 and bvec2 take no range; vec3 does: {diags:#?}");
    assert!(ranges.iter().all(|d| !d.message.contains("`tint`")), "{diags:#?}");
}
