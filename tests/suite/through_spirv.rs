//! The route through SPIR-V: `tests/through_spirv/NN-name/` holds legal programs (glslangValidator
//! links them) with a construct naga's GLSL front does not take (below GLSL 1.40, where
//! glslang makes no SPIR-V of the text as written, from effectc's 4.50 rewrite of it). Each checks without errors,
//! every stage goes through glslang's SPIR-V (so the fixture tests that route, not the GLSL
//! one), and `check`'s report is snapshotted under `snapshots/through_spirv/`: a hazard in
//! such a program is reported at the user's GLSL line. `translate` proves their output
//! (WGSL, spirv-val, a pipeline) with the other programs.

use effectc::diag;

use crate::common;

#[test]
fn legal_programs_naga_refuses_go_through_spirv() {
    let mut settings = insta::Settings::clone_current();
    settings.set_snapshot_path("../../snapshots/through_spirv");
    settings.set_prepend_module_to_snapshot(false);
    settings.set_omit_expression(true);
    for dir in common::fixtures("tests/through_spirv", 11) {
        let name = common::name_of(&dir);
        assert_ne!(common::glslang_links(&dir), Some(false), "{name}: glslangValidator does not link it, so it is no legal fixture");
        let (outcome, checked) = common::check(&dir);
        assert!(!diag::has_errors(&outcome.diagnostics), "{name}:\n{}", common::render(&outcome));
        let program = &checked[0].units.first().expect("a checked program").program;
        for stage in &program.stages {
            assert!(stage.through_spirv, "{name}: the {} stage did not go through SPIR-V", stage.syntax.stage);
            assert!(stage.naga.is_some() && stage.limitation.is_none(), "{name}: the {} stage has no module", stage.syntax.stage);
        }
        settings.bind(|| insta::assert_snapshot!(name, common::render(&outcome)));
    }
}

/// The hazard fixture's warning points at the GLSL line of the `normalize`, through the
/// `OpLine`s of glslang's SPIR-V.
#[test]
fn hazards_through_spirv_point_at_the_glsl_line() {
    let (outcome, _) = common::check(std::path::Path::new("tests/through_spirv/03-hazard-zero-normal-gather"));
    let warning = outcome.diagnostics.iter().find(|d| d.code == diag::Code::HazardNormalize).expect("W0715");
    let (file, span) = (warning.file.expect("a file"), warning.span.clone().expect("a span"));
    assert!(outcome.files.path(file).ends_with("leaf.frag"));
    assert_eq!(&outcome.files.text(file)[span], "vec3 n = normalize(vNormal);");
}

/// A GLSL 1.20 program goes through glslang from effectc's rewrite: the module's spans index
/// the rewritten text, and its hazard still names the user's line.
#[test]
fn hazards_through_spirv_from_the_rewrite_point_at_the_glsl_line() {
    let (outcome, checked) = common::check(std::path::Path::new("tests/through_spirv/05-v120-compat-from-the-rewrite"));
    let program = &checked[0].units.first().expect("a checked program").program;
    let fragment = program.stage(effectc::stage::StageKind::Fragment).expect("a fragment stage");
    let rewritten = fragment.rewritten.as_ref().expect("the rewrite");
    assert!(rewritten.text.starts_with("#version 450"), "the module comes from the rewrite:\n{}", rewritten.text);
    for (code, line) in
        [(diag::Code::HazardLog, "float ev = log(exposure);"), (diag::Code::HazardNormalize, "vec2 needle = normalize(uv - 0.5);")]
    {
        let warning =
            outcome.diagnostics.iter().find(|d| d.code == code).unwrap_or_else(|| panic!("{code:?}:\n{}", common::render(&outcome)));
        let (file, span) = (warning.file.expect("a file"), warning.span.clone().expect("a span"));
        assert!(outcome.files.path(file).ends_with("gauge.frag"));
        assert_eq!(&outcome.files.text(file)[span], line);
    }
}

/// std140 puts `at` at 32 (a struct is 16-aligned); WGSL's natural place is 28. The
/// filler makes the WGSL offsets the IR's, member reads keep their members, and the
/// struct a function copies the block's into is left alone.
#[test]
fn a_struct_after_a_vec3_in_a_uniform_block_is_padded_to_std140() {
    let text = "#version 450\n\
                struct Att { float c; float l; float e; };\n\
                struct PL { vec3 a; vec3 b; Att at; };\n\
                layout(std140, binding = 0) uniform B { PL p[2]; } u;\n\
                layout(location = 0) out vec4 o;\n\
                float e_of(PL l) { return l.at.e; }\n\
                void main() { o = vec4(u.p[1].at.e + e_of(u.p[0]), u.p[0].b); }\n";
    let validated = effectc::front::through_spirv::compile_rewritten(
        &[(text, effectc::stage::StageKind::Fragment)],
        &effectc::front::plan::Plan::default(),
        effectc::front::reference::compiler::Dialect::OpenGl,
        &[],
    )
    .expect("through SPIR-V");
    let v = &validated[0];
    let padded = v.module.types.iter().find_map(|(_, t)| match &t.inner {
        naga::TypeInner::Struct { members, .. } if members.iter().any(|m| m.name.as_deref() == Some("effectc_pad0")) => Some(members),
        _ => None,
    });
    let members = padded.expect("a padded struct");
    let at: Vec<(Option<&str>, u32)> = members.iter().map(|m| (m.name.as_deref(), m.offset)).collect();
    assert_eq!(at, [(Some("a"), 0), (Some("b"), 16), (Some("effectc_pad0"), 28), (Some("at"), 32)]);
    let wgsl = naga::back::wgsl::write_string(&v.module, &v.info, naga::back::wgsl::WriterFlags::empty()).unwrap();
    let reparsed = naga::front::wgsl::parse_str(&wgsl).unwrap();
    effectc::front::naga_run::validator().validate(&reparsed).unwrap_or_else(|e| panic!("{}\n{wgsl}", e.emit_to_string(&wgsl)));
    assert!(wgsl.contains("effectc_pad0_: f32,\n    at: Att"), "{wgsl}");
    // The read of `at.e` through the block still reads member 3 of the padded struct.
    assert!(wgsl.contains(".at.e"), "{wgsl}");
}

/// GL 4.20's atomic counters go through SPIR-V once effectc enables storage buffers on a
/// line it adds after `#version` (glslang's relaxed rules need them for the counter's
/// buffer); the hazard below that line is still placed on the user's line.
#[test]
fn atomic_counters_below_430_go_through_spirv_with_lines_kept() {
    let (outcome, checked) = common::check(std::path::Path::new("tests/through_spirv/07-v420-atomic-counter"));
    let program = &checked[0].units.first().expect("a checked program").program;
    let fragment = program.stage(effectc::stage::StageKind::Fragment).expect("a fragment stage");
    assert!(fragment.through_spirv && fragment.naga.is_some(), "{}", common::render(&outcome));
    let warning = outcome.diagnostics.iter().find(|d| d.code == diag::Code::HazardLog).expect("W0713");
    let (file, span) = (warning.file.expect("a file"), warning.span.clone().expect("a span"));
    assert!(outcome.files.path(file).ends_with("order.frag"));
    assert_eq!(&outcome.files.text(file)[span], "float ev = log(exposure);");
}
