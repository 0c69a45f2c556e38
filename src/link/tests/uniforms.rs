//! Program-wide uniform rules.

use super::*;
use crate::stage::StageKind::{Fragment, Vertex};

#[test]
fn uniform_type_conflict_labels_both_stages() {
    let vert = "#version 330\nuniform vec3 tint;\nvoid main() { gl_Position = vec4(tint, 1.0); }\n";
    let frag = "#version 330\nuniform vec4 tint;\nout vec4 c;\nvoid main() { c = tint; }\n";
    let p = Program::new(&[(Vertex, vert), (Fragment, frag)]);
    let diags = p.interface();
    assert_eq!(codes(&diags), [Code::UniformTypeMismatch], "{diags:#?}");
    let d = &diags[0];
    assert_eq!(d.message, "uniform `tint` is `vec3` in the vertex stage but `vec4` in the fragment stage");
    assert_eq!(primary(&p, d), (p.file(Fragment), "tint"));
    assert_eq!(label_texts(&p, d, p.file(Vertex)), ["tint"]);
}

#[test]
fn same_uniform_in_two_stages_is_fine() {
    let vert = "#version 330\nuniform float t[4];\nvoid main() { gl_Position = vec4(t[0]); }\n";
    let frag = "#version 330\nuniform float t[4];\nout vec4 c;\nvoid main() { c = vec4(t[1]); }\n";
    let p = Program::new(&[(Vertex, vert), (Fragment, frag)]);
    assert!(p.interface().is_empty());
}

#[test]
fn uniform_array_size_conflict() {
    let vert = "#version 330\nuniform float t[4];\nvoid main() { gl_Position = vec4(t[0]); }\n";
    let frag = "#version 330\nuniform float t[3];\nout vec4 c;\nvoid main() { c = vec4(t[1]); }\n";
    let p = Program::new(&[(Vertex, vert), (Fragment, frag)]);
    assert_eq!(codes(&p.interface()), [Code::UniformTypeMismatch]);
}

#[test]
fn uniform_block_member_conflict() {
    let vert = "#version 330\nlayout(std140) uniform Matrices { mat4 view; mat4 proj; };\nvoid main() { gl_Position = proj * view * vec4(1.0); }\n";
    let frag = "#version 330\nlayout(std140) uniform Matrices { mat4 view; } m;\nout vec4 c;\nvoid main() { c = m.view[0]; }\n";
    let p = Program::new(&[(Vertex, vert), (Fragment, frag)]);
    let diags = p.interface();
    assert_eq!(codes(&diags), [Code::UniformBlockMismatch], "{diags:#?}");
    let d = &diags[0];
    assert_eq!(primary(&p, d), (p.file(Fragment), "Matrices"));
    assert_eq!(label_texts(&p, d, p.file(Vertex)), ["Matrices", "proj"]);
}

#[test]
fn struct_used_by_uniforms_defined_differently() {
    let vert = "#version 330\nstruct Light { vec3 pos; vec3 color; };\nuniform Light light;\nvoid main() { gl_Position = vec4(light.pos, 1.0); }\n";
    let frag =
        "#version 330\nstruct Light { vec3 pos; vec4 color; };\nuniform Light light;\nout vec4 c;\nvoid main() { c = light.color; }\n";
    let p = Program::new(&[(Vertex, vert), (Fragment, frag)]);
    let diags = p.interface();
    assert_eq!(codes(&diags), [Code::UniformStructMismatch], "{diags:#?}");
    let d = &diags[0];
    assert_eq!(primary(&p, d), (p.file(Fragment), "Light"));
    assert_eq!(label_texts(&p, d, p.file(Vertex)), ["Light", "color"]);
    assert_eq!(label_texts(&p, d, p.file(Fragment)), ["color"]);
}
