//! Tessellation stages folded into the vertex stage: the vertex, tessellation control (when
//! there is one) and tessellation evaluation stages' 4.50 texts become one vertex-stage text
//! that naga parses like any other (naga and WebGPU have no tessellation stages), as
//! [`geometry_fold`](crate::front::geometry_fold) does for a geometry stage.
//!
//! The draw spends a number of vertices (slots) on each patch that the header of
//! [`INDEX_BUFFER`] gives, with the level cap it was counted at ([`LEVEL_CAP_WORD`],
//! [`SLOTS_WORD`]; [`tessellator::TessLayout::slots_per_patch`]). Each invocation finds its
//! patch and slot from `gl_VertexIndex`, pulls the patch's control points as the geometry
//! fold pulls a primitive's corners, runs the vertex stage once per control point, the
//! control stage once per output vertex (the stretches of `main` between `barrier()`s one
//! after the other for every output vertex), then GL's tessellator
//! ([`tessellator::glsl`]) for the domain coordinates of its slot's corner, and the
//! evaluation stage there. A slot past the patch's last primitive lies outside the clip
//! volume and draws nothing. Levels above the cap are drawn at the cap.
//!
//! Every global and function of the stages is renamed apart (`effectc_vs_…`, `effectc_tc_…`,
//! `effectc_te_…`); uniforms, textures, samplers and struct types keep their names and the
//! first declaration.

pub use crate::front::tessellator;

use std::fmt::Write as _;

use crate::config::TargetEnv;
use crate::diag::FileId;
use crate::front::fold_parts::interface::{self, Leaf};
use crate::front::fold_parts::part::{is_patch, shared_names, Part, Role};
use crate::front::fold_parts::{self, Lowered, Piece, Pulling, Shape, INDEX_BUFFER};
use crate::front::syntax::{self, StageSyntax, Storage};
use crate::stage::StageKind;
use tessellator::{Domain, Spacing, TessLayout};

/// The word of [`INDEX_BUFFER`]'s header that holds the level cap (the draw's slots per
/// patch were counted at it).
pub const LEVEL_CAP_WORD: u32 = 2;
/// The word of [`INDEX_BUFFER`]'s header that holds the slots per patch.
pub const SLOTS_WORD: u32 = 3;
const _: () = assert!(LEVEL_CAP_WORD < SLOTS_WORD && SLOTS_WORD < fold_parts::HEADER_WORDS);

/// The evaluation stage's input layout (`layout(quads, fractional_odd_spacing, cw) in;`).
pub fn tess_layout(tes: &StageSyntax) -> Result<TessLayout, String> {
    let mut domain = None;
    let mut layout = TessLayout { domain: Domain::Triangles, spacing: Spacing::Equal, clockwise: false, point_mode: false };
    for d in tes.defaults.iter().filter(|d| d.storage == Some(Storage::In)) {
        for (name, _) in &d.layout {
            match name.as_str() {
                "triangles" => domain = Some(Domain::Triangles),
                "quads" => domain = Some(Domain::Quads),
                "isolines" => domain = Some(Domain::Isolines),
                "equal_spacing" => layout.spacing = Spacing::Equal,
                "fractional_even_spacing" => layout.spacing = Spacing::FractionalEven,
                "fractional_odd_spacing" => layout.spacing = Spacing::FractionalOdd,
                "cw" => layout.clockwise = true,
                "ccw" => layout.clockwise = false,
                "point_mode" => layout.point_mode = true,
                _ => {}
            }
        }
    }
    layout.domain = domain.ok_or("the evaluation stage declares no primitive domain (`layout(triangles) in;`)")?;
    Ok(layout)
}

/// The control stage's `layout(vertices = N) out;`.
pub fn output_vertices(tcs: &StageSyntax) -> Result<u32, String> {
    for d in tcs.defaults.iter().filter(|d| d.storage == Some(Storage::Out)) {
        match d.layout.iter().find(|(k, _)| k == "vertices") {
            Some((_, Some(n))) if (1..=32).contains(n) => return Ok(*n as u32),
            Some(_) => return Err("`vertices` is an expression effectc cannot evaluate (write the number)".into()),
            None => {}
        }
    }
    Err("the control stage declares no `layout(vertices = N) out;`".into())
}

/// The vertices of a patch as the fold draws it. GL takes the patch size from the draw
/// (`GL_PATCH_VERTICES`); programs draw the size their control stage reads: one past the
/// largest constant index it reads `gl_in[]` or a per-vertex input at, at least its output
/// vertices where it reads them at `gl_InvocationID` (its output vertices when it reads
/// neither way). Without a control stage: 3 for triangles (GL's default) and 4 for quads and
/// isolines.
pub fn patch_vertices(layout: TessLayout, control: Option<(&StageSyntax, u32)>) -> u32 {
    let Some((tcs, vertices)) = control else {
        return match layout.domain {
            Domain::Triangles => 3,
            Domain::Quads | Domain::Isolines => 4,
        };
    };
    let per_vertex = |u: &syntax::Use| match u.target {
        syntax::Referent::Global(i) => tcs.globals[i].storage == Storage::In && !is_patch(&tcs.text, &tcs.globals[i]),
        syntax::Referent::Unresolved => u.name == "gl_in",
        _ => false,
    };
    let (mut largest, mut by_invocation) = (None::<u32>, false);
    for (index, literal) in tcs.uses.iter().filter(|u| per_vertex(u)).filter_map(|u| u.index.as_ref().map(|(_, i, l)| (i, l))) {
        match literal {
            Some(n) => largest = largest.max(u32::try_from(*n).ok().map(|n| n + 1)),
            None => by_invocation |= tcs.text[index.clone()].trim() == "gl_InvocationID",
        }
    }
    match largest {
        Some(n) if by_invocation => n.max(vertices),
        Some(n) => n.clamp(1, 32),
        None => vertices,
    }
}

/// The stages to fold: rewritten 4.50 texts, with the stages as the user wrote them
/// (interpolation qualifiers of block members).
pub struct Stages<'a> {
    pub vertex: &'a str,
    pub control: Option<(&'a str, &'a StageSyntax)>,
    pub evaluation: (&'a str, &'a StageSyntax),
}

/// The tessellation stages folded, ready to feed a later stage: their declarations and
/// bodies, the tessellator and `bool effectc_tess_vertex(uint v)`, which evaluates the
/// draw's vertex `v` (its patch, and the corner of a generated primitive) into the
/// evaluation stage's private outputs and `effectc_te_gl_Position` (false past the patch's
/// last primitive).
pub struct Upstream {
    pub text: String,
    pub(crate) pieces: Vec<Piece>,
    /// The evaluation stage's outputs, made private.
    pub(crate) outputs: Vec<Leaf>,
    /// Names the stages declare that a later stage takes instead of declaring them again.
    pub shared: Vec<String>,
    pub vertex_inputs: Vec<(u32, String, u32)>,
    pub input_types: Vec<String>,
    pub layout: TessLayout,
    pub patch_vertices: u32,
}

/// Folds the tessellation stages into the vertex stage.
pub fn lower(stages: Stages, layout: TessLayout, pulling: Pulling) -> Result<Lowered, String> {
    let u = upstream(stages, layout, pulling, false)?;
    let mut text = String::from("#version 450\n");
    let at = text.len();
    text.push_str(&u.text);
    let pieces = u.pieces.into_iter().map(|p| p.shifted(at)).collect();
    let (declarations, assign) = interface::stage_outputs(&u.outputs, |_, o| o.access(None));
    text.push_str(&declarations);
    let primitive_location = interface::next_location(&u.outputs);
    writeln!(text, "layout(location = {primitive_location}) flat out uint effectc_out_primitive;").unwrap();
    text.push_str("void main() {\n    if (effectc_tess_vertex(uint(gl_VertexIndex))) {\n        gl_Position = effectc_te_gl_Position;\n");
    text.push_str(&assign);
    text.push_str("        effectc_out_primitive = uint(effectc_PrimitiveID);\n    } else {\n        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);\n    }\n}\n");
    let shape = Shape::Tessellation { layout, patch_vertices: u.patch_vertices };
    let (vertex_inputs, input_types) = (u.vertex_inputs, u.input_types);
    Ok(Lowered {
        text,
        shape,
        pulling,
        vertex_inputs,
        input_types,
        pieces,
        primitive_location,
        selects_layer: false,
        selects_viewport: false,
    })
}

/// The tessellation stages folded as the [`Upstream`] of a later stage (`clip`: it reads
/// `gl_in[].gl_ClipDistance`).
pub fn upstream(stages: Stages, layout: TessLayout, pulling: Pulling, clip: bool) -> Result<Upstream, String> {
    let analyse = |text: &str, kind: StageKind| {
        syntax::analyse(FileId(0), text, kind, TargetEnv::Auto).map_err(|_| format!("the rewritten {kind} stage does not parse"))
    };
    let v = analyse(stages.vertex, StageKind::Vertex)?;
    let control = match stages.control {
        Some((text, original)) => {
            let (split, phases) = split_at_barriers(&analyse(text, StageKind::TessControl)?)?;
            Some((analyse(&split, StageKind::TessControl)?, phases, output_vertices(original)?))
        }
        None => None,
    };
    let te = analyse(stages.evaluation.0, StageKind::TessEval)?;
    let corners = patch_vertices(layout, stages.control.map(|c| c.1).zip(control.as_ref().map(|c| c.2)));
    let mut shared = shared_names(&v);
    let vs = Part::new(&v, "effectc_vs_", Role::Vertex, None)?;
    let tc = match &control {
        Some((c, _, vertices)) => {
            let role = Role::TessControl { shared: &shared, corners, vertices: *vertices };
            let part = Part::new(c, "effectc_tc_", role, stages.control.map(|c| c.1))?;
            shared.extend(shared_names(c));
            Some(part)
        }
        None => None,
    };
    let te_corners = control.as_ref().map_or(corners, |c| c.2);
    let te_part = Part::new(&te, "effectc_te_", Role::TessEval { shared: &shared, corners: te_corners }, Some(stages.evaluation.1))?;
    shared.extend(shared_names(&te));
    let (vertex_inputs, input_types) = vs.pulled_inputs();
    let mut text = fold_parts::pulled_declarations(pulling, &vs);
    let clip =
        clip || [stages.control.map(|c| c.0), Some(stages.evaluation.0)].into_iter().flatten().any(|t| t.contains("gl_ClipDistance"));
    let clip_member = if clip { " float gl_ClipDistance[8];" } else { "" };
    writeln!(text, "struct effectc_PerVertex {{ vec4 gl_Position; float gl_PointSize;{clip_member} }};").unwrap();
    if let Some((_, _, vertices)) = &control {
        writeln!(text, "effectc_PerVertex effectc_tc_gl_in[{corners}];\neffectc_PerVertex effectc_gl_out[{vertices}];").unwrap();
    }
    writeln!(text, "effectc_PerVertex effectc_te_gl_in[{te_corners}];").unwrap();
    text.push_str(
        "vec4 effectc_vs_gl_Position; float effectc_vs_gl_PointSize; vec4 effectc_te_gl_Position; float effectc_te_gl_PointSize;\n",
    );
    text.push_str(
        "int effectc_VertexID; int effectc_InstanceID; int effectc_tc_InvocationID; int effectc_PrimitiveID; int effectc_phase;\n",
    );
    text.push_str("float effectc_TessLevelOuter[4]; float effectc_TessLevelInner[2]; vec3 effectc_TessCoord;\n");
    writeln!(text, "const int effectc_tc_PatchVerticesIn = {corners};\nconst int effectc_te_PatchVerticesIn = {te_corners};").unwrap();
    for part in [Some(&vs), tc.as_ref(), Some(&te_part)].into_iter().flatten() {
        text.push_str(&part.declarations);
    }
    let mut pieces = Vec::new();
    Piece::append(&mut text, &vs, StageKind::Vertex, &mut pieces);
    if let Some(tc) = &tc {
        Piece::append(&mut text, tc, StageKind::TessControl, &mut pieces);
    }
    Piece::append(&mut text, &te_part, StageKind::TessEval, &mut pieces);
    text.push_str(&tessellator::glsl(layout));
    let control_run = control.as_ref().zip(tc.as_ref()).map(|((_, phases, vertices), part)| (part, *phases, *vertices));
    text.push_str(&evaluate(&vs, control_run, &te_part, layout, corners, pulling, clip));
    let shared = shared.into_iter().map(str::to_owned).collect();
    let outputs = te_part.outputs;
    Ok(Upstream { text, pieces, outputs, shared, vertex_inputs, input_types, layout, patch_vertices: corners })
}

/// The control stage's `main` cut at its `barrier()` calls (GLSL allows them only at the top
/// of `main`, before any `return`): each stretch runs when `effectc_phase` is its number, so
/// every output vertex finishes one stretch before any starts the next. The count of
/// stretches comes back.
fn split_at_barriers(s: &StageSyntax) -> Result<(String, u32), String> {
    let barriers: Vec<&syntax::Call> = s.calls.iter().filter(|c| c.name == "barrier" && c.in_function.as_deref() == Some("main")).collect();
    if barriers.is_empty() {
        return Ok((s.text.clone(), 1));
    }
    let body = s.main_body.clone().ok_or("the control stage's `main` has no body")?;
    let mut cuts: Vec<(std::ops::Range<usize>, String)> = Vec::new();
    cuts.push((body.start + 1..body.start + 1, " if (effectc_phase == 0) {".into()));
    for (k, c) in barriers.iter().enumerate() {
        let rest = &s.text[c.span.end..];
        let semicolon =
            rest.find(';').filter(|i| rest[..*i].trim().is_empty()).ok_or("a `barrier()` that is not a statement of its own")?;
        cuts.push((c.span.start..c.span.end + semicolon + 1, format!("}} if (effectc_phase == {}) {{", k + 1)));
    }
    cuts.push((body.end - 1..body.end - 1, "} ".into()));
    let mut text = s.text.clone();
    for (range, with) in cuts.into_iter().rev() {
        text.replace_range(range, &with);
    }
    Ok((text, barriers.len() as u32 + 1))
}

/// `bool effectc_tess_vertex(uint v)`: the patch and slot of the draw's vertex `v`, the
/// vertex stage per control point, the control stage per output vertex, the tessellator,
/// and the evaluation stage at the slot's corner.
fn evaluate(
    vs: &Part,
    control: Option<(&Part, u32, u32)>,
    te: &Part,
    layout: TessLayout,
    corners: u32,
    pulling: Pulling,
    clip: bool,
) -> String {
    let mut t = String::from("bool effectc_tess_vertex(uint v) {\n");
    match pulling {
        Pulling::Storage { .. } => {
            writeln!(t, "    effectc_level_cap = float(clamp({INDEX_BUFFER}.index[{LEVEL_CAP_WORD}u], 2u, {}u));", tessellator::MAX_LEVEL)
                .unwrap();
            writeln!(t, "    uint slots = max({INDEX_BUFFER}.index[{SLOTS_WORD}u], 1u);").unwrap();
        }
        Pulling::Attributes => {
            let cap = tessellator::MAX_LEVEL;
            writeln!(t, "    effectc_level_cap = {cap}.0;\n    uint slots = {}u;", layout.slots_per_patch(cap)).unwrap();
        }
    }
    t.push_str("    uint primitive = v / slots;\n    uint slot = v % slots;\n");
    t.push_str("    effectc_PrimitiveID = int(primitive); effectc_InstanceID = int(gl_InstanceIndex);\n");
    // The stage that reads the vertex stage's outputs, and its `gl_in`.
    let (first, first_in) = match control {
        Some((tc, _, _)) => (tc, "effectc_tc_gl_in"),
        None => (te, "effectc_te_gl_in"),
    };
    // One block per control point with constant indices (no loop): the arrays stay in
    // registers.
    for k in 0..corners {
        t.push_str(&fold_parts::pull_corner(vs, k, corners, pulling));
        t.push_str(&fold_parts::run_vertex(vs, &format!("{first_in}[{k}]"), clip));
        for i in &first.ins {
            // An input no vertex output feeds is undefined in GL: it stays zero here.
            let Some(statements) = interface::feed(i, Some(k), &vs.outputs, None) else { continue };
            writeln!(t, "   {statements}").unwrap();
        }
    }
    // GL's default patch levels (`glPatchParameterfv`) until the control stage writes them.
    t.push_str("    for (int i = 0; i < 4; i++) {\n        effectc_TessLevelOuter[i] = 1.0;\n    }\n");
    t.push_str("    effectc_TessLevelInner[0] = 1.0; effectc_TessLevelInner[1] = 1.0;\n");
    if let Some((tc, phases, vertices)) = control {
        for phase in 0..phases {
            for j in 0..vertices {
                writeln!(t, "    effectc_tc_InvocationID = {j}; effectc_phase = {phase}; {}main();", tc.prefix).unwrap();
            }
        }
        for j in 0..vertices {
            writeln!(t, "    effectc_te_gl_in[{j}] = effectc_gl_out[{j}];").unwrap();
            for i in &te.ins {
                let Some(statements) = interface::feed(i, Some(j), &tc.outputs, Some(j)) else { continue };
                writeln!(t, "   {statements}").unwrap();
            }
        }
        for i in &te.patch_ins {
            let Some(statements) = interface::feed(i, None, &tc.patch_outs, None) else { continue };
            writeln!(t, "   {statements}").unwrap();
        }
    }
    let per_primitive = layout.corners();
    writeln!(t, "    vec3 c0; vec3 c1; vec3 c2;\n    bool made = effectc_generated(int(slot / {per_primitive}u), c0, c1, c2);").unwrap();
    writeln!(t, "    uint k = slot % {per_primitive}u;\n    effectc_TessCoord = k == 0u ? c0 : (k == 1u ? c1 : c2);").unwrap();
    writeln!(t, "    if (made) {{\n        {}main();\n    }}\n    return made;\n}}", te.prefix).unwrap();
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    fn control(text: &str) -> StageSyntax {
        syntax::analyse(FileId(0), text, StageKind::TessControl, TargetEnv::Auto).expect("parses")
    }

    #[test]
    fn the_patch_is_what_the_control_stage_reads() {
        let layout = TessLayout { domain: Domain::Quads, spacing: Spacing::Equal, clockwise: false, point_mode: false };
        // Four corners read at constant indices, nine vertices made (piglit's `quads`).
        let corners = control(
            "#version 450\nlayout(vertices = 9) out;\nout vec4 p[];\nvoid main() { p[gl_InvocationID] = gl_in[0].gl_Position + gl_in[3].gl_Position; }\n",
        );
        assert_eq!(patch_vertices(layout, Some((&corners, 9))), 4);
        // Read at the invocation: at least the vertices made.
        let own = control(
            "#version 450\nlayout(vertices = 3) out;\nin vec3 q[];\nout vec3 p[];\nvoid main() { p[gl_InvocationID] = q[gl_InvocationID] + q[1]; }\n",
        );
        assert_eq!(patch_vertices(layout, Some((&own, 3))), 3);
        // Neither: the vertices made; no control stage: the domain's corners.
        let neither = control("#version 450\nlayout(vertices = 16) out;\nvoid main() { gl_TessLevelOuter[0] = 1.0; }\n");
        assert_eq!(patch_vertices(layout, Some((&neither, 16))), 16);
        assert_eq!(patch_vertices(layout, None), 4);
        assert_eq!(patch_vertices(TessLayout { domain: Domain::Triangles, ..layout }, None), 3);
    }

    #[test]
    fn barriers_cut_main_into_stretches() {
        let s = control("#version 450\nlayout(vertices = 3) out;\nout float p[];\nvoid main() {\n    p[gl_InvocationID] = 1.0;\n    barrier();\n    p[gl_InvocationID] += p[0];\n}\n");
        let (text, stretches) = split_at_barriers(&s).unwrap();
        assert_eq!(stretches, 2);
        assert!(text.contains("{ if (effectc_phase == 0) {"), "{text}");
        assert!(text.contains("} if (effectc_phase == 1) {"), "{text}");
        assert!(!text.contains("barrier"), "{text}");
    }
}
