//! The route through SPIR-V: `tests/through_spirv/NN-name/` holds legal programs (glslangValidator
//! links them) with a construct naga's GLSL front does not take. Each checks without errors,
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
    for dir in common::fixtures("tests/through_spirv", 4) {
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
