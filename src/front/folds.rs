//! The folds that run stages WebGPU lacks inside the vertex stage: a geometry stage
//! ([`geometry_fold`]) or tessellation stages ([`tessellation_fold`]), for a program the
//! link rules found no errors in. naga validates each fold twice: the stage that is drawn
//! (vertices pulled from storage buffers) and the one the static analysis reads (vertices
//! from the vertex inputs).

use crate::diag::{Code, Diagnostic};
use crate::front::edits::OffsetMap;
use crate::front::geometry_fold::{self, Folded, Lowered, Pulling};
use crate::front::geometry_layout;
use crate::front::naga_run::{self, Outcome, Validated};
use crate::front::plan;
use crate::front::program::CompiledProgram;
use crate::front::reference;
use crate::front::rewrite::Rewritten;
use crate::front::syntax::StageSyntax;
use crate::front::tessellation_fold::{self, Stages};
use crate::front::through_spirv;
use crate::stage::StageKind;

/// Folds a program's geometry or tessellation stages into its vertex stage (when it has
/// them); a note says why they do not fold.
pub fn fold_stages(program: &mut CompiledProgram, diags: &mut Vec<Diagnostic>) {
    if program.stage(StageKind::TessEval).is_some() {
        return fold_tessellation_stages(program, diags);
    }
    let Some(g) = program.stage(StageKind::Geometry) else { return };
    let syntaxes: Vec<StageSyntax> = program.stages.iter().map(|s| s.syntax.clone()).collect();
    let folded = fold(program, plan::first_free_binding(&program.plan, &syntaxes));
    if let Ok(f) = &folded {
        let selected: Vec<&str> = [(f.drawn.selects_layer, "`gl_Layer`"), (f.drawn.selects_viewport, "`gl_ViewportIndex`")]
            .into_iter()
            .filter(|(s, _)| *s)
            .map(|(_, n)| n)
            .collect();
        if !selected.is_empty() {
            diags.push(
                Diagnostic::new(Code::LayerSelected, format!("the geometry stage writes {}: WebGPU cannot route a primitive to a layer or viewport", selected.join(" and ")))
                    .in_file(g.syntax.file)
                    .with_note("the translation draws the primitives of one layer and viewport per draw (named in the index buffer's header; `render` draws layer 0, viewport 0)"),
            );
        }
    }
    if let Err(why) = &folded {
        diags.push(
            Diagnostic::new(Code::SyntaxAndInterfaceOnly, "the geometry stage is checked for syntax and interface only")
                .in_file(g.syntax.file)
                .with_note(format!("effectc cannot fold it into the vertex stage (how it runs on WebGPU): {why}")),
        );
    }
    program.folded = Some(folded);
}

/// Folds the geometry stage into the vertex stage.
fn fold(program: &CompiledProgram, free_binding: u32) -> Result<Folded, String> {
    let (vs, gs) = (rewritten(program, StageKind::Vertex)?, rewritten(program, StageKind::Geometry)?);
    let g = program.stage(StageKind::Geometry).expect("checked above");
    let layout = geometry_layout_of(&g.syntax)?;
    fold_twice(program, free_binding, &g.syntax, |pulling| {
        geometry_fold::lower(geometry_fold::Upstream::Vertex(&vs.text), &gs.text, layout, pulling, Some(&g.syntax))
    })
}

/// A geometry stage's layout, when a fold can draw it.
fn geometry_layout_of(g: &StageSyntax) -> Result<geometry_layout::GeometryLayout, String> {
    let layout = geometry_layout::geometry_layout(g).map_err(|p| p.message)?;
    if layout.max_vertices == 0 {
        return Err("`max_vertices = 0`: the stage emits no vertex, so there is nothing to draw".into());
    }
    Ok(layout)
}

/// A fold made twice by `lower`: the stage that is drawn (vertices pulled from storage
/// buffers at `free_binding` and the next) and the one the static analysis reads (vertices
/// from the vertex inputs); naga validates both, judged as `stage`.
fn fold_twice(
    program: &CompiledProgram,
    free_binding: u32,
    stage: &StageSyntax,
    lower: impl Fn(Pulling) -> Result<Lowered, String>,
) -> Result<Folded, String> {
    let lower = |pulling: Pulling, dump_name: &str| -> Result<Lowered, String> {
        let lowered = lower(pulling)?;
        dump(dump_name, &lowered);
        Ok(lowered)
    };
    let drawn = lower(Pulling::Storage { index_binding: free_binding, vertex_binding: free_binding + 1 }, "folded.vert");
    let analysed = lower(Pulling::Attributes, "folded-analysis.vert");
    let (drawn, naga) = validate(program, drawn?, stage)?;
    let (analysed, analysis) = validate(program, analysed?, stage)?;
    Ok(Folded { drawn, naga, analysed, analysis })
}

/// The rewritten text a fold starts from, of a stage the front could take.
fn rewritten(program: &CompiledProgram, kind: StageKind) -> Result<&Rewritten, String> {
    let s = program.stage(kind).ok_or_else(|| format!("a program without a {kind} stage"))?;
    if s.limitation.is_some() || (kind == StageKind::Vertex && s.naga.is_none()) {
        return Err(format!("the {kind} stage, which naga did not validate"));
    }
    s.rewritten.as_ref().ok_or_else(|| format!("the {kind} stage, which was not rewritten"))
}

/// Debugging aid: with `EFFECTC_DUMP_REWRITE=DIR`, each fold is written next to the stages'
/// rewritten texts (before naga sees it).
fn dump(name: &str, lowered: &Lowered) {
    if let Some(dir) = std::env::var_os("EFFECTC_DUMP_REWRITE") {
        let _ = std::fs::write(std::path::Path::new(&dir).join(name), &lowered.text);
    }
}

/// naga's module of a fold (`stage`: the stage whose file and version it is judged under).
fn validate(program: &CompiledProgram, lowered: Lowered, stage: &StageSyntax) -> Result<(Lowered, Validated), String> {
    let as_stage = Rewritten { text: lowered.text.clone(), map: OffsetMap::identity(lowered.text.len()), limitation: None };
    let refused = match naga_run::parse_and_validate(stage.file, &as_stage, naga::ShaderStage::Vertex, &stage.version) {
        Outcome::Valid(v) if v.needs.is_empty() => return Ok((lowered, v)),
        Outcome::Valid(v) => return Err(format!("a construct WebGPU lacks ({})", v.needs.join(", "))),
        Outcome::Limited(limit) => format!("{}, which naga cannot take", limit.construct),
        Outcome::Invalid(errors) => {
            format!("naga rejects the folded stage: {}", errors.first().map(|d| d.message.as_str()).unwrap_or("no message"))
        }
    };
    // What naga's GLSL front refuses in the fold, glslang may compile to SPIR-V that naga's
    // SPIR-V front reads (spans on the fold's lines, as on the GLSL route).
    match through_spirv::compile_rewritten(&[(&lowered.text, StageKind::Vertex)], &program.plan, reference::Dialect::OpenGl, &[]) {
        Ok(mut v) if v[0].needs.is_empty() => Ok((lowered, v.remove(0))),
        _ => Err(refused),
    }
}

/// Folds the tessellation stages into the vertex stage; a note says why they do not fold.
fn fold_tessellation_stages(program: &mut CompiledProgram, diags: &mut Vec<Diagnostic>) {
    let Some(te) = program.stage(StageKind::TessEval) else { return };
    let syntaxes: Vec<StageSyntax> = program.stages.iter().map(|s| s.syntax.clone()).collect();
    let folded = fold_tessellation(program, plan::first_free_binding(&program.plan, &syntaxes));
    // The fold says whether naga validated the stages (each stage's note said it could not,
    // before the fold).
    let files: Vec<_> =
        [StageKind::TessControl, StageKind::TessEval].iter().filter_map(|k| program.stage(*k)).map(|s| s.syntax.file).collect();
    diags.retain(|d| !(d.code == Code::SyntaxAndInterfaceOnly && d.file.is_some_and(|f| files.contains(&f))));
    match &folded {
        Ok(f) => {
            if let geometry_fold::Shape::Tessellation { patch_vertices, .. }
            | geometry_fold::Shape::TessellatedGeometry { patch_vertices, .. } = f.drawn.shape
            {
                diags.push(
                    Diagnostic::new(Code::TessellationFolded, "the tessellation stages run inside the vertex stage (WebGPU has no tessellation stages)")
                        .in_file(te.syntax.file)
                        .with_note(format!(
                            "the translation draws patches of {patch_vertices} vertices and a fixed number of vertices per patch, enough for the levels up to a cap (`translate --explain` shows the plan); `render` lowers the cap to keep a frame's vertices in bounds, and draws higher levels at the cap"
                        )),
                );
            }
        }
        Err(why) => diags.push(
            Diagnostic::new(Code::SyntaxAndInterfaceOnly, "the tessellation stages are checked for syntax and interface only")
                .in_file(te.syntax.file)
                .with_note(format!("effectc cannot fold them into the vertex stage (how they run on WebGPU): {why}")),
        ),
    }
    program.folded = Some(folded);
}

/// Folds the tessellation stages (and a geometry stage after them).
fn fold_tessellation(program: &CompiledProgram, free_binding: u32) -> Result<Folded, String> {
    let te = program.stage(StageKind::TessEval).expect("the caller checked");
    let vs = rewritten(program, StageKind::Vertex)?;
    let te_text = rewritten(program, StageKind::TessEval)?;
    let control = match program.stage(StageKind::TessControl) {
        Some(tc) => Some((rewritten(program, StageKind::TessControl)?.text.as_str(), &tc.syntax)),
        None => None,
    };
    let layout = tessellation_fold::tess_layout(&te.syntax)?;
    // A geometry stage takes the tessellation's primitives.
    let geometry = match program.stage(StageKind::Geometry) {
        Some(g) => Some((rewritten(program, StageKind::Geometry)?, g, geometry_layout_of(&g.syntax)?)),
        None => None,
    };
    fold_twice(program, free_binding, &te.syntax, |pulling| {
        let stages = Stages { vertex: &vs.text, control, evaluation: (&te_text.text, &te.syntax) };
        match geometry {
            Some((gs, g, geometry)) => {
                let upstream = tessellation_fold::upstream(stages, layout, pulling, gs.text.contains("gl_ClipDistance"))?;
                geometry_fold::lower(geometry_fold::Upstream::Tessellated(upstream), &gs.text, geometry, pulling, Some(&g.syntax))
            }
            None => tessellation_fold::lower(stages, layout, pulling),
        }
    })
}
