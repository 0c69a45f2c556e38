//! Varyings and interface blocks between stages; names used across stages.

use super::*;
use crate::stage::StageKind::{Fragment, Geometry, Vertex};

/// The sun shader's vertex stage with the intended block declaration.
const SUN_VERT: &str = "#version 420 core

out vert_out
{
    vec2 outputTexCoords;
    vec3 swirlPosVector; // Modified vertex position
}vert_out;

layout(location = 0) in vec3 vertPosition;
layout(location = 1) in vec2 vertTexCoords;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform float swirlSeed;
uniform float timeVar;
uniform float randomConstant;

float random(float seed)
{
    return fract(sin(seed) * randomConstant);
}

void main()
{
    vec4 transformPosition = model * vec4(vertPosition, 1.0);
    vec2 swirledTexCoord = vertTexCoords;
    float swirlIntensity = 2.0;
    float angle = length(transformPosition.xy) * swirlIntensity + timeVar * random(swirlSeed);
    mat2 swirlAngleMatrix = mat2(cos(angle), sin(angle), -sin(angle), cos(angle));
    vert_out.swirlPosVector = vec3(swirlAngleMatrix * transformPosition.xy, transformPosition.z);
    gl_Position = projection * view * vec4(vert_out.swirlPosVector, 1.0);
    vert_out.outputTexCoords = swirledTexCoord;
}
";

/// The sun shader's fragment stage as published: its input block is called `vert_vars`.
const SUN_FRAG: &str = "#version 420 core

in vert_vars //Receives variables from vertex shader
{
    vec2 outputTexCoords;
    vec3 swirlPosVector;
}frag_in;

out vec4 fragColor;

uniform sampler2D textureSamplerVar;
uniform float timeVarFrag;
uniform float minBI;
uniform float maxBI;
uniform float bFrequency;

const int blurEffectRadius = 6;

void main()
{
    vec4 textureColour = texture(textureSamplerVar, frag_in.outputTexCoords);
    float currentBI = mix(minBI, maxBI, 0.5 + 0.5 * sin(timeVarFrag * bFrequency));
    fragColor = vec4(textureColour.rgb * currentBI, 1.0);
}
";

#[test]
fn sun_block_name_mismatch_is_one_error_in_both_files() {
    let p = Program::new(&[(Vertex, SUN_VERT), (Fragment, SUN_FRAG)]);
    let diags = p.interface();
    assert_eq!(codes(&diags), [Code::InputBlockUnmatched], "{diags:#?}");
    let d = &diags[0];
    assert_eq!(d.severity(), Severity::Error);
    let (vert, frag) = (p.file(Vertex), p.file(Fragment));
    assert_eq!(primary(&p, d), (frag, "vert_vars"));
    assert_eq!(d.message, "fragment input block `vert_vars` has no matching output block in the vertex stage");
    // The secondary label is the vertex *block* name, not its (equal) instance name.
    let block_at = SUN_VERT.find("out vert_out").unwrap() + 4;
    let labels: Vec<_> = d.labels.iter().filter(|l| l.file == vert).collect();
    assert_eq!(labels.len(), 1, "{d:#?}");
    assert_eq!(labels[0].span, block_at..block_at + "vert_out".len());
    assert!(d.notes.iter().any(|n| { n == "interface blocks match by block name (`vert_vars` vs `vert_out`), not by instance name" }));
    assert_eq!(d.help.as_deref(), Some("rename `in vert_vars` to `in vert_out` (the members match)"));
}

#[test]
fn renamed_sun_block_links_cleanly() {
    let frag = SUN_FRAG.replace("in vert_vars", "in vert_out");
    let p = Program::new(&[(Vertex, SUN_VERT), (Fragment, &frag)]);
    assert_eq!(codes(&p.interface()), Vec::<Code>::new());
}

#[test]
fn paired_blocks_with_different_members_list_the_differences() {
    let vert = "#version 330\nout VsOut { vec2 uv; vec3 normal; } vs;\nvoid main() { vs.uv = vec2(0.0); vs.normal = vec3(0.0); }\n";
    let frag = "#version 330\nin FsIn { vec2 uv; vec4 normal; } fs;\nout vec4 c;\nvoid main() { c = fs.normal; }\n";
    let p = Program::new(&[(Vertex, vert), (Fragment, frag)]);
    let diags = p.interface();
    assert_eq!(codes(&diags), [Code::InputBlockUnmatched], "{diags:#?}");
    let d = &diags[0];
    assert_eq!(d.help.as_deref(), Some("rename `in FsIn` to `in VsOut` and make the members agree"));
    assert!(d.notes.iter().any(|n| n.contains("`vec3` in the vertex stage but `vec4`")));
    assert_eq!(label_texts(&p, d, p.file(Vertex)), ["VsOut", "normal"]);
    assert_eq!(label_texts(&p, d, p.file(Fragment)), ["normal"]);
}

#[test]
fn differing_instance_names_are_fine() {
    let vert = "#version 330\nout VS_OUT { vec3 n; vec2 uv; } vs_out;\nvoid main() { vs_out.n = vec3(1.0); vs_out.uv = vec2(0.0); }\n";
    let frag = "#version 330\nin VS_OUT { vec3 n; vec2 uv; } fs_in;\nout vec4 c;\nvoid main() { c = vec4(fs_in.n, fs_in.uv.x); }\n";
    let p = Program::new(&[(Vertex, vert), (Fragment, frag)]);
    let diags = p.interface();
    assert!(diags.is_empty(), "{diags:#?}");
}

#[test]
fn block_member_type_mismatch_labels_both_members() {
    let vert = "#version 330\nout VS_OUT { vec3 n; vec2 uv; } vs_out;\nvoid main() { vs_out.n = vec3(1.0); vs_out.uv = vec2(0.0); }\n";
    let frag = "#version 330\nin VS_OUT { vec4 n; vec2 uv; } fs_in;\nout vec4 c;\nvoid main() { c = fs_in.n; }\n";
    let p = Program::new(&[(Vertex, vert), (Fragment, frag)]);
    let diags = p.interface();
    assert_eq!(codes(&diags), [Code::InterfaceBlockMismatch], "{diags:#?}");
    let d = &diags[0];
    let (vf, ff) = (p.file(Vertex), p.file(Fragment));
    assert_eq!(primary(&p, d), (ff, "VS_OUT"));
    assert_eq!(label_texts(&p, d, vf), ["VS_OUT", "n"]);
    assert_eq!(label_texts(&p, d, ff), ["n"]);
    assert_eq!(d.notes[0], "member `n` is `vec3` in the vertex stage but `vec4` in the fragment stage");
}

#[test]
fn block_member_order_and_count_differences_are_one_error() {
    let vert = "#version 330\nout B { vec3 a; vec3 b; float extra; } o;\nvoid main() { o.a = vec3(0.0); }\n";
    let frag = "#version 330\nin B { vec3 b; vec3 a; } i;\nout vec4 c;\nvoid main() { c = vec4(i.a, 1.0); }\n";
    let p = Program::new(&[(Vertex, vert), (Fragment, frag)]);
    let diags = p.interface();
    assert_eq!(codes(&diags), [Code::InterfaceBlockMismatch], "{diags:#?}");
    let notes = &diags[0].notes;
    assert!(notes.iter().any(|n| n == "member `float extra` is declared only in the vertex stage"), "{notes:#?}");
    assert!(notes.iter().any(|n| n.starts_with("the members are in a different order: (a, b)")), "{notes:#?}");
}

#[test]
fn interpolation_mismatch_is_an_error_before_430() {
    let vert = "#version 330\nflat out vec3 color;\nvoid main() { color = vec3(1.0); }\n";
    let frag = "#version 330\nin vec3 color;\nout vec4 c;\nvoid main() { c = vec4(color, 1.0); }\n";
    let p = Program::new(&[(Vertex, vert), (Fragment, frag)]);
    let diags = p.interface();
    assert_eq!(codes(&diags), [Code::InterpolationMismatch], "{diags:#?}");
    let d = &diags[0];
    assert_eq!(d.message, "`color` is `flat` in the vertex stage but `smooth` in the fragment stage");
    assert_eq!(primary(&p, d), (p.file(Fragment), "color"));
    assert_eq!(label_texts(&p, d, p.file(Vertex)), ["color"]);
    assert_eq!(d.primary_label, "`smooth` (no qualifier) here");
}

#[test]
fn interpolation_mismatch_is_a_warning_from_430() {
    let vert = "#version 450\nlayout(location = 0) flat out vec3 color;\nvoid main() { color = vec3(1.0); }\n";
    let frag =
        "#version 450\nlayout(location = 0) in vec3 color;\nlayout(location = 0) out vec4 c;\nvoid main() { c = vec4(color, 1.0); }\n";
    let p = Program::new(&[(Vertex, vert), (Fragment, frag)]);
    let diags = p.interface();
    assert_eq!(codes(&diags), [Code::InterpolationDiffers], "{diags:#?}");
}

#[test]
fn centroid_and_location_mismatches() {
    let vert = "#version 410\nlayout(location = 1) centroid out vec2 uv;\nvoid main() { uv = vec2(0.0); }\n";
    let frag = "#version 410\nlayout(location = 2) in vec2 uv;\nout vec4 c;\nvoid main() { c = vec4(uv, 0.0, 1.0); }\n";
    let p = Program::new(&[(Vertex, vert), (Fragment, frag)]);
    let diags = p.interface();
    assert_eq!(codes(&diags), [Code::CentroidMismatch, Code::LocationMismatch], "{diags:#?}");
    let loc = only(&diags, Code::LocationMismatch);
    assert_eq!(primary(&p, loc), (p.file(Fragment), "layout(location = 2)"));
    assert_eq!(label_texts(&p, loc, p.file(Vertex)), ["layout(location = 1)"]);
}

#[test]
fn loose_type_mismatch_labels_both_declarations() {
    let vert = "#version 330\nout vec3 vNormal;\nvoid main() { vNormal = vec3(0.0); }\n";
    let frag = "#version 330\nin vec4 vNormal;\nout vec4 c;\nvoid main() { c = vNormal; }\n";
    let p = Program::new(&[(Vertex, vert), (Fragment, frag)]);
    let diags = p.interface();
    assert_eq!(codes(&diags), [Code::VaryingTypeMismatch], "{diags:#?}");
    let d = &diags[0];
    assert_eq!(d.message, "`vNormal` is `vec3` in the vertex stage but `vec4` in the fragment stage");
    assert_eq!(primary(&p, d), (p.file(Fragment), "vNormal"));
    assert_eq!(label_texts(&p, d, p.file(Vertex)), ["vNormal"]);
    assert_eq!(d.help.as_deref(), Some("declare the fragment input as `in vec3 vNormal;`"));
}

#[test]
fn missing_producer_suggests_the_nearest_output() {
    let vert = "#version 330\nout vec3 vNormal;\nvoid main() { vNormal = vec3(0.0); }\n";
    let frag = "#version 330\nin vec3 vNormals;\nout vec4 c;\nvoid main() { c = vec4(vNormals, 1.0); }\n";
    let p = Program::new(&[(Vertex, vert), (Fragment, frag)]);
    let diags = p.interface();
    // The typo is one error; the misspelt output is not reported again as unread.
    assert_eq!(codes(&diags), [Code::NoProducer], "{diags:#?}");
    let d = &diags[0];
    assert_eq!(primary(&p, d), (p.file(Fragment), "vNormals"));
    assert_eq!(label_texts(&p, d, p.file(Vertex)), ["vNormal"]);
    assert!(d.help.as_deref().unwrap().starts_with("did you mean `vNormal`?"), "{d:#?}");
}

#[test]
fn missing_producer_that_is_a_block_member() {
    let frag = "#version 420 core\nin vec2 outputTexCoords;\nout vec4 c;\nvoid main() { c = vec4(outputTexCoords, 0.0, 1.0); }\n";
    let p = Program::new(&[(Vertex, SUN_VERT), (Fragment, frag)]);
    let diags = p.interface();
    assert_eq!(codes(&diags), [Code::NoProducer], "{diags:#?}");
    let d = &diags[0];
    assert_eq!(
        d.help.as_deref(),
        Some("`outputTexCoords` is a member of output block `vert_out` in the vertex stage; declare the input inside `in vert_out { … }`")
    );
    assert_eq!(label_texts(&p, d, p.file(Vertex)), ["outputTexCoords"]);
}

#[test]
fn unread_input_without_producer_is_only_a_warning() {
    let vert = "#version 330\nvoid main() { gl_Position = vec4(0.0); }\n";
    let frag = "#version 330\nin vec3 unused;\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n";
    let p = Program::new(&[(Vertex, vert), (Fragment, frag)]);
    assert_eq!(codes(&p.interface()), [Code::UnusedInput]);
}

#[test]
fn unread_output_is_a_warning() {
    let vert = "#version 330\nout vec3 used;\nout float extra;\nvoid main() { used = vec3(0.0); extra = 1.0; gl_Position = vec4(0.0); }\n";
    let frag = "#version 330\nin vec3 used;\nout vec4 c;\nvoid main() { c = vec4(used, 1.0); }\n";
    let p = Program::new(&[(Vertex, vert), (Fragment, frag)]);
    let diags = p.interface();
    assert_eq!(codes(&diags), [Code::UnreadOutput], "{diags:#?}");
    let d = &diags[0];
    assert_eq!(d.message, "vertex output `extra` is never read by the fragment stage");
    assert_eq!(primary(&p, d), (p.file(Vertex), "extra"));
}

#[test]
fn loose_outputs_read_as_a_block_are_one_error() {
    let vert = "#version 330\nout vec2 outputTexCoords;\nout vec3 swirlPosVector;\nvoid main() { outputTexCoords = vec2(0.0); swirlPosVector = vec3(0.0); }\n";
    let p = Program::new(&[(Vertex, vert), (Fragment, SUN_FRAG)]);
    let diags = p.interface();
    assert_eq!(codes(&diags), [Code::InputBlockUnmatched], "{diags:#?}");
    let d = &diags[0];
    assert_eq!(label_texts(&p, d, p.file(Vertex)), ["outputTexCoords", "swirlPosVector"]);
    assert!(d.help.as_deref().unwrap().contains("as separate outputs"), "{d:#?}");
}

#[test]
fn other_stage_instance_name_is_explained() {
    let vert = "#version 330\nout VS { vec2 uv; } vs_out;\nvoid main() { vs_out.uv = vec2(0.0); }\n";
    let frag = "#version 330\nin VS { vec2 uv; } fs_in;\nout vec4 c;\nvoid main() { c = vec4(vs_out.uv, fs_in.uv); c += vec4(vs_out.uv, 0.0, 0.0); }\n";
    let p = Program::new(&[(Vertex, vert), (Fragment, frag)]);
    let diags = p.interface();
    assert_eq!(codes(&diags), [Code::OtherStageName], "{diags:#?}");
    let d = &diags[0];
    let (vf, ff) = (p.file(Vertex), p.file(Fragment));
    assert_eq!(primary(&p, d), (ff, "vs_out"));
    assert_eq!(d.span.as_ref().unwrap().start, frag.find("vs_out").unwrap());
    assert_eq!(label_texts(&p, d, vf), ["vs_out"]);
    assert_eq!(label_texts(&p, d, ff), ["fs_in", "vs_out"]);
    assert_eq!(d.help.as_deref(), Some("in this stage the block instance is called `fs_in`: write `fs_in.uv`"));
}

#[test]
fn seed_style_use_of_the_vertex_instance_in_the_fragment() {
    let frag = SUN_FRAG.replace("frag_in.outputTexCoords", "vert_out.outputTexCoords");
    let p = Program::new(&[(Vertex, SUN_VERT), (Fragment, &frag)]);
    let diags = p.interface();
    // The block-name mismatch (unread now, so a warning) and the foreign instance name.
    assert_eq!(codes(&diags), [Code::OtherStageName, Code::UnusedInput], "{diags:#?}");
    let d = only(&diags, Code::OtherStageName);
    assert_eq!(d.help.as_deref(), Some("in this stage the block instance is called `frag_in`: write `frag_in.outputTexCoords`"));
}

#[test]
fn block_name_used_as_a_variable() {
    let vert = "#version 330\nout VS { vec2 uv; } vs_out;\nvoid main() { vs_out.uv = vec2(0.0); }\n";
    let frag = "#version 330\nin VS { vec2 uv; } fs_in;\nout vec4 c;\nvoid main() { c = vec4(VS.uv, fs_in.uv); }\n";
    let p = Program::new(&[(Vertex, vert), (Fragment, frag)]);
    let d = only(&p.interface(), Code::OtherStageName).clone();
    assert_eq!(d.message, "`VS` is a block name, not a variable");
    assert_eq!(primary(&p, &d).1, "VS");
}

#[test]
fn uniform_declared_only_in_another_stage() {
    let vert = "#version 330\nuniform float timeVar;\nvoid main() { gl_Position = vec4(timeVar); }\n";
    let frag = "#version 330\nout vec4 c;\nvoid main() { c = vec4(timeVar); }\n";
    let p = Program::new(&[(Vertex, vert), (Fragment, frag)]);
    let diags = p.interface();
    let d = only(&diags, Code::OtherStageName);
    assert_eq!(primary(&p, d), (p.file(Fragment), "timeVar"));
    assert_eq!(label_texts(&p, d, p.file(Vertex)), ["timeVar"]);
    assert!(d.help.as_deref().unwrap().starts_with("declare `uniform float timeVar;`"), "{d:#?}");
}

#[test]
fn geometry_inputs_are_arrays_of_vertex_outputs() {
    let vert = "#version 330\nout vec3 normal;\nout VS_OUT { vec2 uv; } vs_out;\nvoid main() { normal = vec3(0.0); vs_out.uv = vec2(0.0); gl_Position = vec4(0.0); }\n";
    let geom = "#version 330\nlayout(triangles) in;\nlayout(triangle_strip, max_vertices = 3) out;\nin vec3 normal[];\nin VS_OUT { vec2 uv; } gs_in[];\nout vec3 gNormal;\nvoid main() { for (int i = 0; i < 3; i++) { gNormal = normal[i] * gs_in[i].uv.x; gl_Position = gl_in[i].gl_Position; EmitVertex(); } EndPrimitive(); }\n";
    let frag = "#version 330\nin vec3 gNormal;\nout vec4 c;\nvoid main() { c = vec4(gNormal, 1.0); }\n";
    let p = Program::new(&[(Vertex, vert), (Geometry, geom), (Fragment, frag)]);
    let diags = p.interface();
    assert!(diags.is_empty(), "{diags:#?}");
}

#[test]
fn geometry_input_type_mismatch_and_missing_array() {
    let vert = "#version 330\nout vec3 normal;\nout vec2 uv;\nvoid main() { normal = vec3(0.0); uv = vec2(0.0); }\n";
    let geom = "#version 330\nlayout(points) in;\nlayout(points, max_vertices = 1) out;\nin vec4 normal[];\nin vec2 uv;\nvoid main() { gl_Position = normal[0] + vec4(uv, 0.0, 0.0); EmitVertex(); }\n";
    let p = Program::new(&[(Vertex, vert), (Geometry, geom)]);
    let diags = p.interface();
    assert_eq!(codes(&diags), [Code::VaryingTypeMismatch, Code::GeometryInputNotArray], "{diags:#?}");
    let ty = only(&diags, Code::VaryingTypeMismatch);
    assert_eq!(ty.help.as_deref(), Some("declare the geometry input as `in vec3 normal[];`"));
    assert_eq!(primary(&p, only(&diags, Code::GeometryInputNotArray)), (p.file(Geometry), "uv"));
}

#[test]
fn tessellation_stages_match_per_vertex_arrays() {
    use crate::stage::StageKind::{TessControl, TessEval};
    let vert = "#version 410\nout vec3 vPos;\nvoid main() { vPos = vec3(0.0); }\n";
    let tesc = "#version 410\nlayout(vertices = 3) out;\nin vec3 vPos[];\nout vec3 tcPos[];\nvoid main() { tcPos[gl_InvocationID] = vPos[gl_InvocationID]; }\n";
    let tese = "#version 410\nlayout(triangles) in;\nin vec3 tcPos[];\nout vec3 tePos;\nvoid main() { tePos = tcPos[0]; gl_Position = vec4(tePos, 1.0); }\n";
    let frag = "#version 410\nin vec3 tePos;\nout vec4 c;\nvoid main() { c = vec4(tePos, 1.0); }\n";
    let p = Program::new(&[(Vertex, vert), (TessControl, tesc), (TessEval, tese), (Fragment, frag)]);
    let diags = p.interface();
    assert!(diags.is_empty(), "{diags:#?}");
}

#[test]
fn loose_output_read_as_a_member_of_a_matched_block() {
    let vert = "#version 330\nout VS { vec2 uv; } o;\nout vec3 normal;\nvoid main() { o.uv = vec2(0.0); normal = vec3(0.0); }\n";
    let frag = "#version 330\nin VS { vec2 uv; vec3 normal; } i;\nout vec4 c;\nvoid main() { c = vec4(i.normal, i.uv.x); }\n";
    let p = Program::new(&[(Vertex, vert), (Fragment, frag)]);
    let diags = p.interface();
    assert_eq!(codes(&diags), [Code::InterfaceBlockMismatch, Code::UnreadOutput], "{diags:#?}");
    let w = only(&diags, Code::UnreadOutput);
    assert_eq!(primary(&p, w), (p.file(Vertex), "normal"));
    assert_eq!(label_texts(&p, w, p.file(Fragment)), ["normal"]);
    assert_eq!(w.help.as_deref(), Some("move the output into `out VS { … }` in the vertex stage"));
}
