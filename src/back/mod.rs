//! Back end: a checked program's validated stage modules → one translated module → targets.
//!
//! Steps: fix `switch` fall-through per stage (spans still map to the user's file) → merge
//! the stages into one module ([`merge`]) → make interpolation explicit and map GL clip
//! depth to WebGPU's ([`fixes`]) → leave out what nothing uses ([`prune`]) → pack narrow
//! varyings where WebGPU's locations run out ([`varying_packing`]) → validate →
//! reflect ([`reflect`]). Each target writer takes only the validated module.
//! A program with a geometry stage arrives folded ([`crate::front::geometry_fold`]): its
//! vertex and geometry stages are one vertex module that pulls its vertices from two
//! storage buffers; the reflection says how to draw it.
//!
//! | code  | meaning |
//! |-------|---------|
//! | E0301 | two stages bind different resources at the same (group, binding) |
//! | E0302 | a `switch` case falls through into the next case's code (WGSL cannot say it) |
//! | E0303 | a stage naga cannot translate (a geometry or tessellation stage effectc cannot fold) |
//! | E0304 | a stage did not validate, so the program cannot be translated |
//! | E0305 | internal: the translated module failed validation or a writer failed |
//! | E0306 | a target cannot express the program (e.g. `noperspective` in GLSL ES 3.00) |

mod arguments;
pub mod fixes;
mod glsl_es;
mod hlsl;
pub mod ir_text;
pub mod merge;
mod msl;
pub mod prune;
pub mod reflect;
mod spirv;
mod uniform_loads;
pub mod units;
mod varying_packing;
mod wgsl;

pub use wgsl::verify as verify_wgsl;

use naga::valid::ModuleInfo;
use naga::Module;

use crate::diag::{Code, Diagnostic};
use crate::front::plan::UNIFORM_BLOCK;
use crate::front::program::CompiledProgram;
use crate::manifest::Effect;
use crate::stage::StageKind;

/// An output format of `effectc translate`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Target {
    Wgsl,
    Spv,
    Spvasm,
    Glsl,
    Msl,
    Hlsl,
    Reflect,
    Ir,
}

impl Target {
    pub const ALL: [Target; 8] =
        [Target::Wgsl, Target::Spv, Target::Spvasm, Target::Glsl, Target::Msl, Target::Hlsl, Target::Reflect, Target::Ir];

    pub fn name(self) -> &'static str {
        match self {
            Target::Wgsl => "wgsl",
            Target::Spv => "spv",
            Target::Spvasm => "spvasm",
            Target::Glsl => "glsl",
            Target::Msl => "msl",
            Target::Hlsl => "hlsl",
            Target::Reflect => "reflect",
            Target::Ir => "ir",
        }
    }
}

/// Options of the translation.
#[derive(Debug, Clone, Copy)]
pub struct TranslateOptions {
    /// Map GL clip-space depth (z in [-w, w]) to WebGPU/Vulkan's (z in [0, w]).
    pub gl_depth: bool,
    /// Widen fragment colour outputs to four components (for rendering into RGBA targets).
    pub widen_outputs: bool,
    /// Negate clip y so the framebuffer runs bottom-up like GL's (`gl_FragCoord.y`, `dFdy`
    /// as in GL); the renderer flips rows back and treats clockwise faces as front faces.
    pub flip_y: bool,
    /// Keep 64-bit floats (`double`, `dvec*`): every target asked for has them (SPIR-V with
    /// the Float64 capability, HLSL); WGSL, MSL and GLSL ES do not.
    pub float64: bool,
    /// Keep 64-bit integers (`int64_t`, `uint64_t`, GL_ARB_gpu_shader_int64): every target
    /// asked for has them (SPIR-V with the Int64 capability); WGSL and GLSL ES do not.
    pub int64: bool,
}

impl Default for TranslateOptions {
    fn default() -> Self {
        TranslateOptions { gl_depth: true, widen_outputs: false, flip_y: false, float64: false, int64: false }
    }
}

impl TranslateOptions {
    /// What `effectc translate` to `targets` uses. 64-bit floats are kept when every target
    /// has them (SPIR-V, HLSL); otherwise they are taken as 32-bit ones, with W0131 (WGSL,
    /// MSL and GLSL ES have none). 64-bit integers are kept when every target has them
    /// (SPIR-V); otherwise the program is not translated (E0306 names the targets that do).
    pub fn for_targets(targets: &[Target], gl_depth: bool) -> Self {
        let all = |keeps: fn(&Target) -> bool| targets.iter().all(keeps);
        TranslateOptions {
            gl_depth,
            float64: all(|t| matches!(t, Target::Spv | Target::Spvasm | Target::Hlsl | Target::Reflect | Target::Ir)),
            int64: all(|t| matches!(t, Target::Spv | Target::Spvasm | Target::Reflect | Target::Ir)),
            ..TranslateOptions::default()
        }
    }

    /// What `effectc render` translates with: the render-only adaptations on.
    pub fn for_rendering(gl_depth: bool) -> Self {
        TranslateOptions { gl_depth, widen_outputs: true, flip_y: true, float64: false, int64: false }
    }
}

/// A translated program: the merged, fixed, pruned and validated module.
#[derive(Debug)]
pub struct Translation {
    pub name: String,
    pub module: Module,
    pub info: ModuleInfo,
    /// Stages with an entry point, in pipeline order.
    pub stages: Vec<StageKind>,
    pub reflection: reflect::Reflection,
    /// The program's first stage file (where program-wide diagnostics point).
    pub file: crate::diag::FileId,
}

impl Translation {
    pub fn left_out(&self) -> &[prune::LeftOut] {
        &self.reflection.left_out
    }
}

/// One file a target produces.
#[derive(Debug, Clone)]
pub struct Output {
    pub file_name: String,
    pub bytes: Vec<u8>,
}

/// Translates a checked program (no errors) named `name`.
pub fn translate(
    name: &str,
    program: &CompiledProgram,
    effect: Option<&Effect>,
    options: TranslateOptions,
) -> Result<Translation, Vec<Diagnostic>> {
    let Some(first) = program.stages.first() else {
        return Err(vec![Diagnostic::new(Code::StageNotValid, "the program has no stages to translate")]);
    };
    let file = first.syntax.file;
    let modules = stage_modules(program, options)?;
    let refs: Vec<(StageKind, &Module)> = modules.iter().map(|(k, m)| (*k, m)).collect();
    let mut module = merge::merge(&refs).map_err(|c| {
        let file = program.stage(c.stage).map_or(file, |s| s.syntax.file);
        let d = Diagnostic::new(Code::BindingConflict, format!("the stages cannot share one module: {}", c.message)).in_file(file);
        vec![if c.within_stage {
            // Vulkan lets resources alias a binding (a branch picks the one it reads); a
            // WebGPU shader declares one resource per binding.
            d.with_note(
                "WGSL declares one resource per binding; the stage reads both (a branch on a specialization constant still reads both)",
            )
            .with_help("give each resource its own binding, or declare the one this variant uses")
        } else {
            d.with_help("give each resource its own binding in every stage")
        }]
    })?;
    fixes::normalize_interpolation(&mut module);
    fixes::name_uniform_block(&mut module, UNIFORM_BLOCK);
    // Vulkan GLSL's clip space has WebGPU's depth range already and its y axis pointing
    // down: y is negated (as naga's SPIR-V front does unless told to keep the coordinate
    // space) and depth kept; the SPIR-V writer turns y back for Vulkan.
    let vulkan = program.stages.iter().any(|s| s.syntax.vulkan);
    fixes::adjust_clip_position(&mut module, options.gl_depth && !vulkan, options.flip_y != vulkan);
    if options.widen_outputs {
        fixes::widen_fragment_outputs(&mut module);
    }
    // Compaction assumes a valid module; prove it first (with 64-bit floats and integers
    // where every target has them).
    let validator = || {
        let caps = crate::front::naga_run::webgpu_capabilities()
            | wide_capabilities(options)
            | crate::front::naga_run::webgpu_optional_capabilities();
        naga::valid::Validator::new(naga::valid::ValidationFlags::all(), caps)
    };
    validator()
        .validate(&module)
        .map_err(|e| vec![internal_error(file, format!("the merged module does not validate: {}", e.as_inner()))])?;
    let mut left_out = prune::prune(&mut module, UNIFORM_BLOCK);
    if program.fold().is_some() {
        // The fold renamed the stages' globals apart and added glue of its own: report the
        // user's names, and none of the glue.
        left_out.retain_mut(|l| match ["effectc_vs_", "effectc_gs_"].iter().find_map(|p| l.name.strip_prefix(p)) {
            Some(user) if !user.starts_with("gl_") => {
                l.name = user.to_string();
                true
            }
            Some(_) => false,
            None => !l.name.starts_with("effectc_"),
        });
    }
    if program.stages.iter().any(|s| s.through_spirv) {
        // naga's SPIR-V front declares every built-in glslang's SPIR-V lists
        // (`gl_VertexIndex` for a GL stage's `gl_VertexID`), written by the user or not.
        left_out.retain(|l| !l.name.starts_with("gl_"));
    }
    // GL packs narrow varyings four components to a location; WGSL gives each a location.
    // After pruning: only the varyings the fragment stage receives are counted and packed.
    varying_packing::pack_varyings(&mut module, varying_packing::WEBGPU_LOCATIONS);
    fixes::read_only_unwritten_storage(&mut module);
    fixes::narrow_storage_image_access(&mut module);
    let info = validator()
        .validate(&module)
        .map_err(|e| vec![internal_error(file, format!("the translated module does not validate: {}", with_causes(e.as_inner())))])?;
    let reflection = reflect::reflect_program(name, &module, program, effect, left_out);
    Ok(Translation {
        name: name.to_string(),
        module,
        info,
        stages: modules.iter().map(|(k, _)| *k).collect(),
        reflection,
        file: program.stages[0].syntax.file,
    })
}

/// An error and its chain of causes, `: `-separated (naga's "global variable is invalid"
/// says why only in its source).
fn with_causes(e: &dyn std::error::Error) -> String {
    let mut text = e.to_string();
    let mut source = e.source();
    while let Some(s) = source {
        text.push_str(&format!(": {s}"));
        source = s.source();
    }
    text
}

/// Each stage's validated module, fixed per stage, in pipeline order (the vertex stage's
/// is the fold of the vertex and geometry stages when there is a geometry stage); or why
/// a stage cannot be translated.
/// The 64-bit capabilities every requested target has ([`TranslateOptions::float64`],
/// [`TranslateOptions::int64`]).
fn wide_capabilities(options: TranslateOptions) -> naga::valid::Capabilities {
    let mut caps = naga::valid::Capabilities::empty();
    if options.float64 {
        caps |= naga::valid::Capabilities::FLOAT64;
    }
    if options.int64 {
        caps |= naga::valid::Capabilities::SHADER_INT64;
    }
    caps
}

fn stage_modules(program: &CompiledProgram, options: TranslateOptions) -> Result<Vec<(StageKind, Module)>, Vec<Diagnostic>> {
    let wide = wide_capabilities(options);
    let mut diags = Vec::new();
    let mut modules = Vec::new();
    for stage in &program.stages {
        let kind = stage.syntax.stage;
        match (kind, &program.folded) {
            // Folded into the vertex stage's module (below).
            (StageKind::Geometry | StageKind::TessControl | StageKind::TessEval, Some(Ok(_))) => continue,
            (StageKind::Vertex, Some(Ok(folded))) => {
                let mut module = folded.naga.module.clone();
                arguments::copy_partial_pointer_arguments(&mut module, &folded.naga.info);
                for span in fixes::fix_switch_fallthrough(&mut module) {
                    // The span is in the folded text: back to the stage it came from.
                    let at = span.to_range().and_then(|r| program.user_span_in(&folded.drawn, r));
                    diags.push(fall_through(at.map_or((stage.syntax.file, None), |(f, r)| (f, Some(r)))));
                }
                modules.push((kind, module));
                continue;
            }
            (StageKind::Geometry, Some(Err(why))) => {
                diags.push(
                    Diagnostic::new(Code::StageNotTranslatable, "the geometry stage cannot be translated")
                        .in_file(stage.syntax.file)
                        .with_note(format!(
                            "effectc runs a geometry stage on WebGPU by folding it into the vertex stage; this one it cannot fold: {why}"
                        )),
                );
                continue;
            }
            (StageKind::TessControl | StageKind::TessEval, Some(Err(why))) => {
                diags.push(
                    Diagnostic::new(Code::StageNotTranslatable, format!("the {kind} stage cannot be translated"))
                        .in_file(stage.syntax.file)
                        .with_note(format!(
                            "effectc runs tessellation on WebGPU by folding the stages into the vertex stage; these it cannot fold: {why}"
                        )),
                );
                continue;
            }
            _ if kind.naga().is_none() => {
                diags.push(
                    Diagnostic::new(Code::StageNotTranslatable, format!("the {kind} stage cannot be translated"))
                        .in_file(stage.syntax.file)
                        .with_note("naga, WGSL and the WebGPU pipeline have no tessellation stages"),
                );
                continue;
            }
            _ => {}
        }
        if let Some(limit) = &stage.limitation {
            let d = Diagnostic::new(
                Code::TargetCannotExpress,
                format!("the {kind} stage uses {}, which naga cannot translate", limit.construct),
            )
            .with_note(
                "the program is legal GLSL (`effectc check` accepts it); naga, which effectc translates with, does not take this construct",
            );
            diags.push(match &limit.span {
                Some(span) => d.at(stage.syntax.file, span.clone(), "naga does not take this"),
                None => d.in_file(stage.syntax.file),
            });
            continue;
        }
        // A folded geometry stage hands `gl_PrimitiveID` to the fragment stage as a varying.
        let folded_primitive = program.fold().map(|f| f.drawn.primitive_location).filter(|_| kind == StageKind::Fragment);
        let needs_of = |v: &crate::front::naga_run::Validated| -> Vec<String> {
            v.needs
                .iter()
                // WebGPU's optional features (N0109): the WGSL enables them.
                .filter(|n| !crate::front::naga_run::webgpu_optional_capabilities().iter_names().any(|(name, _)| name == n.as_str()))
                .filter(|n| !(wide.contains(naga::valid::Capabilities::FLOAT64) && n.as_str() == "FLOAT64"))
                .filter(|n| !(wide.contains(naga::valid::Capabilities::SHADER_INT64) && n.as_str() == "SHADER_INT64"))
                .cloned()
                .collect()
        };
        if let Some(validated) = stage.naga.as_ref().filter(|v| !needs_of(v).is_empty()) {
            diags.push(
                Diagnostic::new(
                    Code::TargetCannotExpress,
                    format!("the {kind} stage needs {}, which WebGPU does not have", needs_of(validated).join(", ")),
                )
                .in_file(stage.syntax.file)
                .with_note(
                    "legal in desktop GL; WebGPU has these only as optional features (or not at all), so effectc does not translate them",
                )
                .with_help(capability_help(&needs_of(validated))),
            );
            continue;
        }
        let (Some(validated), Some(rewritten)) = (&stage.naga, &stage.rewritten) else {
            diags.push(
                Diagnostic::new(Code::StageNotValid, format!("the {kind} stage did not validate, so it cannot be translated"))
                    .in_file(stage.syntax.file),
            );
            continue;
        };
        let mut module = validated.module.clone();
        arguments::copy_partial_pointer_arguments(&mut module, &validated.info);
        if let Some(location) = folded_primitive {
            fixes::primitive_id_from_location(&mut module, location);
        }
        fixes::block_member_interpolation(&mut module, &stage.syntax);
        for span in fixes::fix_switch_fallthrough(&mut module) {
            diags.push(fall_through((stage.syntax.file, span.to_range().map(|r| rewritten.map.range_to_original(r)))));
        }
        modules.push((kind, module));
    }
    if diags.is_empty() {
        Ok(modules)
    } else {
        Err(diags)
    }
}

/// E0302 at the `switch` (or in its file).
fn fall_through((file, span): (crate::diag::FileId, Option<std::ops::Range<usize>>)) -> Diagnostic {
    let d = Diagnostic::new(Code::SwitchFallThrough, "a `switch` case falls through into the next case's code")
        .with_note("WGSL has no fall-through between cases, so this cannot be translated")
        .with_help("end each case with `break` (repeat the shared code in each case if needed)");
    match span {
        Some(r) => d.at(file, r, "this switch"),
        None => d.in_file(file),
    }
}

/// What the GLSL construct behind each naga capability is.
fn capability_help(needs: &[String]) -> String {
    let what: Vec<&str> = needs
        .iter()
        .map(|n| match n.as_str() {
            "PRIMITIVE_INDEX" => "`gl_PrimitiveID` (WebGPU feature `primitive-index`)",
            "FLOAT64" => "double precision (`double`, `dvec*`, `dmat*`)",
            "DUAL_SOURCE_BLENDING" => "`layout(index = 1)` outputs: dual-source blending (WebGPU feature `dual-source-blending`)",
            "MULTISAMPLED_SHADING" => "per-sample shading (`gl_SampleID`, `sample` inputs)",
            "CLIP_DISTANCES" => "`gl_ClipDistance` (WebGPU feature `clip-distances`)",
            "CULL_DISTANCE" => "`gl_CullDistance`",
            "IMMEDIATES" => "push constants (`layout(push_constant)`)",
            "MULTIVIEW" => "`gl_ViewIndex` (multiview)",
            "EARLY_DEPTH_TEST" => "`layout(early_fragment_tests)` / depth layout qualifiers",
            "SHADER_INT64" => "64-bit integers",
            "SHADER_FLOAT16" => "16-bit floats (`float16_t`, `f16vec*`; WebGPU feature `shader-f16`)",
            "SHADER_INT16" => "16-bit integers",
            "DRAW_INDEX" => "`gl_DrawID`",
            _ => "arrays of textures, samplers or buffers (binding arrays)",
        })
        .collect();
    let mut help = format!("the construct: {}", what.join("; "));
    if needs.iter().any(|n| n == "FLOAT64") {
        help.push_str("; SPIR-V and HLSL have 64-bit floats: `effectc translate --to spv,spvasm,hlsl` keeps them");
    }
    if needs.iter().any(|n| n == "SHADER_INT64") {
        help.push_str("; SPIR-V has 64-bit integers: `effectc translate --to spv,spvasm` keeps them");
    }
    help
}

/// An internal error of the translation (E0305): a bug, not the user's input.
pub fn internal_error(file: crate::diag::FileId, message: String) -> Diagnostic {
    Diagnostic::new(Code::TranslateInternal, message)
        .in_file(file)
        .with_note("this is a bug in effectc's translation; please report it with the input files")
}

/// The files `target` produces for a translation (names relative to the output directory).
pub fn emit(t: &Translation, target: Target) -> Result<Vec<Output>, String> {
    let (m, info) = (&t.module, &t.info);
    let text = |name: String, text: String| Output { file_name: name, bytes: text.into_bytes() };
    let per_stage = |write: &dyn Fn(StageKind, naga::ShaderStage, &str) -> Result<Output, String>| -> Result<Vec<Output>, String> {
        t.stages.iter().map(|s| write(*s, s.naga().expect("translated stages have naga stages"), merge::entry_name(*s))).collect()
    };
    let stage_file = |stage: StageKind, ext: &str| format!("{}.{}.{ext}", t.name, stage.short_name());
    Ok(match target {
        Target::Wgsl => vec![text(format!("{}.wgsl", t.name), wgsl::write(m, info)?)],
        Target::Spv => per_stage(&|kind, stage, entry| {
            let words = spirv::write(m, info, stage, entry)?;
            Ok(Output { file_name: stage_file(kind, "spv"), bytes: spirv::to_bytes(&words) })
        })?,
        Target::Spvasm => per_stage(&|kind, stage, entry| {
            let words = spirv::write(m, info, stage, entry)?;
            Ok(text(stage_file(kind, "spvasm"), spirv::disassemble(&words)?))
        })?,
        Target::Glsl if t.reflection.geometry.is_some() => {
            return Err("GLSL ES 3.00 (WebGL2) doesn't support storage buffers, which a geometry stage folded into the vertex stage pulls its vertices from".into())
        }
        Target::Glsl => per_stage(&|kind, stage, entry| Ok(text(stage_file(kind, "glsl"), glsl_es::write(m, info, stage, entry)?)))?,
        Target::Msl => vec![text(format!("{}.metal", t.name), msl::write(m, info)?)],
        Target::Hlsl => vec![text(format!("{}.hlsl", t.name), hlsl::write(m, info)?)],
        Target::Reflect => {
            let mut json = serde_json::to_string_pretty(&t.reflection).map_err(|e| e.to_string())?;
            json.push('\n');
            vec![text(format!("{}.reflect.json", t.name), json)]
        }
        Target::Ir => vec![text(format!("{}.ir.txt", t.name), ir_text::write(m))],
    })
}

/// SPIR-V words of one stage (for tests and tools that want the words, not the file).
pub fn spirv_words(t: &Translation, stage: StageKind) -> Result<Vec<u32>, String> {
    let s = stage.naga().ok_or("no naga stage")?;
    spirv::write(&t.module, &t.info, s, merge::entry_name(stage))
}
