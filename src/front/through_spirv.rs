//! The route through SPIR-V, for programs glslang accepts and naga's GLSL front cannot
//! take: glslang compiles the program to SPIR-V with line information, combined image
//! samplers are split into a texture and a sampler (WebGPU has no combined ones), naga's
//! SPIR-V front reads each stage, and every span of the module is moved from the SPIR-V
//! binary to the line of the user's text that the `OpLine` in force there names. What
//! works on the IR (translation, hazards, stress culprits, reflection) then points at the
//! user's GLSL as it does for the GLSL route.
//!
//! Bindings and locations are the user's (Vulkan GLSL) or mapped once for the whole program
//! by glslang (OpenGL GLSL ≥ 1.40 under relaxed Vulkan rules: loose uniforms in one block
//! named [`UNIFORM_BLOCK`]); a sampler split off a combined one takes the next binding.
//! Push constants, which WebGPU lacks, become a uniform buffer (a read-only storage buffer
//! when their layout breaks uniform alignment).

use std::panic::{catch_unwind, AssertUnwindSafe};

use naga::{AddressSpace, Block, Module, ResourceBinding, Span, Statement, TypeInner};

use crate::config::VulkanVersion;
use crate::diag::{FileId, Files};
use crate::front::naga_run::{self, Validated};
use crate::front::plan::{Plan, UNIFORM_BLOCK};
use crate::front::reference::compiler::{self, Dialect, SpirvSetup};
use crate::front::reference::log::{self, LineTable};
use crate::front::spirv_absent_builtins::absent_builtins_as_constants;
use crate::front::spirv_aggregate_varyings::split_aggregate_varyings;
use crate::front::spirv_array_sizes::{array_sizes_by_parts, layers_queried};
use crate::front::spirv_binary::{readable_by_naga, space_bindings_for_split, split_combined_samplers, Lines};
use crate::front::spirv_binding_arrays::binding_arrays_as_elements;
use crate::front::spirv_float_tests::float_tests_from_bits;
use crate::front::spirv_interface_blocks::split_interface_blocks;
use crate::front::spirv_non_finite_constants::non_finite_constants_at_run_time;
use crate::front::spirv_outer_products::outer_products_by_columns;
use crate::front::spirv_refusals::{self, Refusal};
use crate::front::spirv_signedness::signedness_naga_reads;
use crate::front::spirv_spec_constants::spec_constants_naga_reads;
use crate::front::spirv_subgroups::subgroups_of_one;
use crate::front::spirv_subpass_inputs::subpass_inputs_as_textures;
use crate::front::spirv_texel_buffers::texel_buffers_as_storage;
use crate::front::spirv_two_row_matrices::two_row_matrices_as_columns;
use crate::front::spirv_wide_integers::wide_integers_as_pairs;
use crate::front::uniform_struct_padding;
use crate::front::version::Profile;
use crate::stage::StageKind;
use respan::respan_module;

/// One stage through SPIR-V: its validated module, spans indexing `text` (the stage's text
/// as glslang compiled it, includes inlined: offsets are those of the user's stage).
#[derive(Debug)]
pub struct SpirvStage {
    pub kind: StageKind,
    pub validated: Validated,
    pub text: String,
}

/// Every stage of the program (`ordered`, pipeline order) through SPIR-V, or why not (the
/// first thing that failed).
pub fn compile(files: &Files, ordered: &[(FileId, StageKind)], dialect: Dialect, plan: &Plan) -> Result<Vec<SpirvStage>, Refusal> {
    let mut texts: Vec<String> = ordered.iter().map(|(f, _)| crate::front::lexical::quiet_pragmas(files.text(*f)).into_owned()).collect();
    if dialect == Dialect::OpenGl {
        texts = texts.into_iter().map(gl_as_written_for_spirv).collect::<Result<_, _>>()?;
    }
    let sources: Vec<(&str, StageKind)> = texts.iter().zip(ordered).map(|(t, (_, k))| (t.as_str(), *k)).collect();
    let setup = SpirvSetup { uniform_block: UNIFORM_BLOCK, set: 0, binding: 0 };
    let binaries = before_split(compiler::spirv(&sources, dialect, &setup).map_err(no_spirv)?);
    let mut modules = Vec::new();
    for (words, (file, kind)) in binaries.into_iter().zip(ordered) {
        modules.push(module_of(words, *kind, files.text(*file), plan)?);
    }
    if dialect == Dialect::OpenGl {
        one_binding_per_resource(&mut modules);
    }
    uniform_struct_padding::pad_uniform_structs(&mut modules);
    let immediates = uniform_buffers_for_push_constants(&mut modules);
    let mut out = Vec::new();
    for ((module, (file, kind)), immediates) in modules.into_iter().zip(ordered).zip(immediates) {
        out.push(SpirvStage { kind: *kind, validated: validate(module, immediates, *kind)?, text: files.text(*file).to_string() });
    }
    Ok(out)
}

/// Every stage of a program through SPIR-V from effectc's 4.50 rewrite of it (`stages`:
/// each rewritten text, pipeline order), for legal programs glslang makes no SPIR-V of as
/// written (GLSL below 1.40, the compatibility profile) and naga's GLSL front refuses: the
/// rewrite has lowered what Vulkan GLSL lacks (fixed-function state, loose uniforms,
/// combined legacy lookups) and holds the plan's bindings and locations, so glslang compiles
/// it as Vulkan GLSL. The modules' spans index the rewritten texts, as on the GLSL route.
/// A Vulkan GLSL program (`dialect`) is compiled for its Vulkan version with the extensions
/// its stages as written (`originals`, in the order of `stages`) enable, which the rewrite
/// blanks for the parsers that stop at them (subgroup operations, samplerless lookups).
pub fn compile_rewritten(
    stages: &[(&str, StageKind)],
    plan: &Plan,
    dialect: Dialect,
    originals: &[&str],
) -> Result<Vec<Validated>, Refusal> {
    let (version, originals) = match dialect {
        Dialect::Vulkan(v) => (v, originals),
        Dialect::OpenGl => (VulkanVersion::V1_0, &[][..]),
    };
    let texts: Vec<String> = stages
        .iter()
        .enumerate()
        .map(|(i, (t, _))| as_vulkan_glsl(t, &extensions_enabled(originals.get(i).copied().unwrap_or(""))))
        .collect();
    let sources: Vec<(&str, StageKind)> = texts.iter().zip(stages).map(|(t, (_, k))| (t.as_str(), *k)).collect();
    let setup = SpirvSetup { uniform_block: UNIFORM_BLOCK, set: 0, binding: 0 };
    let binaries = before_split(compiler::spirv(&sources, Dialect::Vulkan(version), &setup).map_err(no_spirv)?);
    let mut modules = Vec::new();
    for (words, (text, kind)) in binaries.into_iter().zip(stages) {
        modules.push(module_of(words, *kind, text, plan)?);
    }
    uniform_struct_padding::pad_uniform_structs(&mut modules);
    let immediates = uniform_buffers_for_push_constants(&mut modules);
    let validated =
        modules.into_iter().zip(stages).zip(immediates).map(|((module, (_, kind)), immediates)| validate(module, immediates, *kind));
    Ok(validated.collect::<Result<_, _>>()?)
}

/// A rewritten stage as glslang reads it as Vulkan GLSL: pragmas no compiler acts on and
/// `#line` directives blanked (offsets and lines kept), and `GL_EXT_spirv_intrinsics`
/// enabled after `#version`, the one way glslang takes declarations named `gl_…` (the
/// rewrite declares GL's fixed-function attributes and varyings, `gl_Vertex`, under their
/// own names), and `GL_EXT_samplerless_texture_functions` (the rewrite reads a subpass input
/// as `texelFetch` of a texture), then `extensions` (directives); a `#line` after them keeps
/// every line's number.
fn as_vulkan_glsl(text: &str, extensions: &str) -> String {
    let quiet = crate::front::lexical::quiet_pragmas(text);
    let text = crate::front::lexical::blank_line_directives(&quiet);
    crate::front::version::after_version(
        &text,
        &format!("#extension GL_EXT_spirv_intrinsics : enable\n#extension GL_EXT_samplerless_texture_functions : enable\n{extensions}"),
    )
}

/// An OpenGL GLSL stage as glslang compiles it to SPIR-V as written, under relaxed Vulkan
/// rules. Err: desktop GLSL below 1.40, ES GLSL below 3.10 and the compatibility profile,
/// of which glslang makes no SPIR-V (a compile sure to fail would still build glslang's
/// tables of built-ins for that version, under a lock every compile waits on). Desktop GLSL
/// below 4.30 with atomic counters gets storage buffers enabled: the relaxed rules turn the
/// counters into a storage buffer and `atomicCounterIncrement` into `atomicAdd` on it, which
/// glslang then refuses without `GL_ARB_shader_storage_buffer_object` (`glslangValidator -V
/// -R` stops there too, on GLSL 4.20's own atomic counters).
fn gl_as_written_for_spirv(text: String) -> Result<String, String> {
    let Ok(v) = crate::front::version::parse_version(&text) else { return Ok(text) };
    if matches!((v.profile, v.number), (Profile::Compatibility, _) | (Profile::Core, ..140) | (Profile::Es, ..310)) {
        return Err("glslang makes no SPIR-V of desktop GLSL below 1.40, ES GLSL below 3.10, or the compatibility profile".into());
    }
    let counters =
        !v.is_es() && v.number < 430 && String::from_utf8_lossy(&crate::front::version::blank_comments(&text)).contains("atomic_uint");
    Ok(match counters {
        true => crate::front::version::after_version(&text, "#extension GL_ARB_shader_storage_buffer_object : enable\n"),
        false => text,
    })
}

/// An `#extension NAME : enable` line for every extension `text` names in a directive
/// (outside comments) other than to disable it, in any conditional group: enabling one the
/// active text does not use changes nothing.
fn extensions_enabled(text: &str) -> String {
    let code = crate::front::version::blank_comments(text);
    let mut out = String::new();
    for line in String::from_utf8_lossy(&code).lines() {
        let Some(rest) = line.trim_start().strip_prefix('#').map(str::trim_start).and_then(|r| r.strip_prefix("extension")) else {
            continue;
        };
        let mut parts = rest.split(':');
        let (name, behaviour) = (parts.next().unwrap_or("").trim(), parts.next().unwrap_or("").trim());
        let directive = format!("#extension {name} : enable\n");
        if !name.is_empty() && name != "all" && behaviour != "disable" && !out.contains(&directive) {
            out.push_str(&directive);
        }
    }
    out
}

/// The program's stages as the combined-sampler split takes them: texel buffers and subpass
/// inputs lowered (neither is a combined sampler the split should space a binding for), then
/// bindings spaced for the samplers the split adds.
fn before_split(binaries: Vec<Vec<u32>>) -> Vec<Vec<u32>> {
    let mut binaries: Vec<Vec<u32>> = binaries.into_iter().map(|b| subpass_inputs_as_textures(texel_buffers_as_storage(b))).collect();
    binding_arrays_as_elements(&mut binaries);
    space_bindings_for_split(&mut binaries);
    binaries
}

fn no_spirv(log: String) -> String {
    let first = log::parse(&log).into_iter().find(|m| m.error).map(|m| m.text);
    format!("glslang makes no SPIR-V of it: {}", first.unwrap_or_else(|| log.trim().to_string()))
}

/// One stage's SPIR-V as a naga module: combined samplers split, read by naga's SPIR-V
/// front (panics contained), every span moved to the line of `text` its `OpLine` names,
/// names as the user wrote them.
fn module_of(words: Vec<u32>, kind: StageKind, text: &str, plan: &Plan) -> Result<Module, Refusal> {
    dump_spirv(&words, &format!("{kind}.glslang"));
    // The passes over the words that make glslang's SPIR-V what naga reads, in order.
    let passes: [fn(Vec<u32>) -> Vec<u32>; 13] = [
        readable_by_naga,
        spec_constants_naga_reads,
        wide_integers_as_pairs,
        absent_builtins_as_constants,
        subgroups_of_one,
        non_finite_constants_at_run_time,
        float_tests_from_bits,
        outer_products_by_columns,
        two_row_matrices_as_columns,
        signedness_naga_reads,
        split_interface_blocks,
        split_aggregate_varyings,
        array_sizes_by_parts,
    ];
    let words = passes.iter().fold(split_combined_samplers(words)?, |words, pass| pass(words));
    dump_spirv(&words, &kind.to_string());
    let lines = Lines::of(&words);
    let bytes: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).collect();
    // Clip space as the GLSL wrote it, as the GLSL route leaves it: the back end maps
    // GL's conventions to WebGPU's for both routes alike.
    let options = naga::front::spv::Options { adjust_coordinate_space: false, strict_capabilities: false, block_ctx_dump_prefix: None };
    let mut module = match catch_unwind(AssertUnwindSafe(|| naga::front::spv::parse_u8_slice(&bytes, &options))) {
        Ok(Ok(m)) => m,
        Ok(Err(e)) => return Err(spirv_refusals::refusal(&e, &words, kind, text)),
        Err(_) => return Err(format!("naga's SPIR-V front crashed on the {kind} stage").into()),
    };
    if let Some(construct) = naga_run::std140_two_row_matrix(&module) {
        return Err(format!("naga's SPIR-V front cannot read the {kind} stage: {construct}").into());
    }
    layers_queried(&mut module);
    let table = LineTable::new(text);
    respan_module(&mut module, &|span| lines.user_span(span, &table, text));
    user_names(&mut module);
    name_split_samplers(&mut module, plan);
    name_stage_outputs(&mut module);
    drop_outputs_webgpu_lacks(&mut module);
    single_source_outputs(&mut module);
    unreachable_ends_return_a_value(&mut module);
    comparison_parameters(&mut module);
    emit_only_what_needs_it(&mut module);
    naga_run::write_only_storage_as_read_write(&mut module);
    Ok(module)
}

/// Debugging aid: with `EFFECTC_DUMP_SPIRV=DIR`, the SPIR-V glslang made of a stage
/// (`<stage>.glslang.spv`) and the words naga's SPIR-V front reads (`<stage>.spv`).
fn dump_spirv(words: &[u32], name: &str) {
    if let Some(dir) = std::env::var_os("EFFECTC_DUMP_SPIRV") {
        let bytes: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).collect();
        let _ = std::fs::write(std::path::Path::new(&dir).join(format!("{name}.spv")), bytes);
    }
}

/// naga's validation (with desktop GL's capabilities, as for the GLSL route); push
/// constants become a uniform buffer, or a read-only storage buffer when their layout
/// breaks uniform alignment, and so does a uniform buffer whose layout WGSL's uniform rules
/// refuse (GL_EXT_scalar_block_layout's `scalar`: a `vec2` array 8 bytes apart).
fn validate(mut module: Module, immediates: Vec<naga::Handle<naga::GlobalVariable>>, kind: StageKind) -> Result<Validated, String> {
    let run = |m: &Module| catch_unwind(AssertUnwindSafe(|| naga_run::validate_for_gl(m)));
    let read_only = AddressSpace::Storage { access: naga::StorageAccess::LOAD };
    let mut result = run(&module);
    if !immediates.is_empty() && matches!(result, Ok(Err(_))) {
        for g in &immediates {
            module.global_variables[*g].space = read_only;
        }
        result = run(&module);
    }
    for _ in 0..module.global_variables.len() {
        let Ok(Err(e)) = &result else { break };
        let naga::valid::ValidationError::GlobalVariable {
            handle,
            source: naga::valid::GlobalVariableError::Alignment(AddressSpace::Uniform, ..),
            ..
        } = e.as_inner()
        else {
            break;
        };
        module.global_variables[*handle].space = read_only;
        result = run(&module);
    }
    match result {
        Ok(Ok((info, needs))) => Ok(Validated { module, info, needs }),
        Ok(Err(e)) => {
            let mut why = e.as_inner().to_string();
            let mut cause = std::error::Error::source(e.as_inner());
            while let Some(c) = cause {
                why = format!("{why}: {c}");
                cause = c.source();
            }
            Err(format!("naga does not validate the {kind} stage read from SPIR-V: {why}"))
        }
        Err(_) => Err(format!("naga's validator crashed on the {kind} stage read from SPIR-V")),
    }
}

/// GL numbers bindings per kind (texture unit 0 and uniform block 0 coexist) and glslang
/// maps each stage's on its own: every resource of the program gets one binding of its
/// own, the same in every stage that declares it (by name), keeping the number it has
/// where no other resource holds it.
fn one_binding_per_resource(modules: &mut [Module]) {
    let mut plan: Vec<(String, ResourceBinding)> = Vec::new();
    for m in modules.iter_mut() {
        for (_, g) in m.global_variables.iter_mut() {
            let Some(b) = g.binding else { continue };
            let key = g.name.clone().or_else(|| m.types[g.ty].name.clone()).unwrap_or_default();
            let assigned = match plan.iter().find(|(k, _)| *k == key) {
                Some((_, at)) => *at,
                None => {
                    let held = |r: &ResourceBinding| plan.iter().any(|(_, at)| at == r);
                    let at = if held(&b) {
                        let free = (0..).find(|n| !held(&ResourceBinding { group: b.group, binding: *n })).expect("a free binding");
                        ResourceBinding { group: b.group, binding: free }
                    } else {
                        b
                    };
                    plan.push((key, at));
                    at
                }
            };
            g.binding = Some(assigned);
        }
    }
}

/// Push-constant blocks (Vulkan has one range for all stages) moved to one uniform buffer
/// at the first binding of group 0 no stage uses; per module, the globals moved.
fn uniform_buffers_for_push_constants(modules: &mut [Module]) -> Vec<Vec<naga::Handle<naga::GlobalVariable>>> {
    let taken: Vec<u32> = modules
        .iter()
        .flat_map(|m| m.global_variables.iter().filter_map(|(_, g)| g.binding.as_ref()).filter(|b| b.group == 0).map(|b| b.binding))
        .collect();
    let binding = (0..).find(|b| !taken.contains(b)).expect("a free binding");
    modules
        .iter_mut()
        .map(|m| {
            let mut moved = Vec::new();
            for (h, g) in m.global_variables.iter_mut().filter(|(_, g)| g.space == AddressSpace::Immediate) {
                g.space = AddressSpace::Uniform;
                g.binding = Some(ResourceBinding { group: 0, binding });
                moved.push(h);
            }
            moved
        })
        .collect()
}

/// glslang names an anonymous block's variable (the loose uniforms' block, `gl_PerVertex`)
/// with the empty string, which writers print as `unnamed`: the uniform block gets no name
/// (the back end names it `uniforms`, as for the GLSL route), `gl_PerVertex` is
/// `per_vertex`, another block its type's name in lower case. glslang names functions by
/// their signature (`coverage(vf2;`): they keep the name the user wrote.
fn user_names(module: &mut Module) {
    for (_, g) in module.global_variables.iter_mut() {
        if g.name.as_deref() != Some("") {
            continue;
        }
        g.name = match module.types[g.ty].name.as_deref() {
            Some("gl_PerVertex") => Some("per_vertex".to_string()),
            Some(t) if g.space != AddressSpace::Uniform => Some(t.to_lowercase()),
            _ => None,
        };
    }
    for (_, f) in module.functions.iter_mut() {
        if let Some(name) = &mut f.name {
            if let Some(i) = name.find('(') {
                name.truncate(i);
            }
        }
    }
}

/// The sampler split off a combined image sampler has no name: it takes the plan's sampler
/// name for its texture (what the GLSL route calls it, so manifests and the renderer find
/// it), else `<texture>_sampler`; a function's sampler parameter split off one (right after
/// its texture parameter) is `<parameter>_sampler`.
fn name_split_samplers(module: &mut Module, plan: &Plan) {
    for (_, f) in module.functions.iter_mut() {
        for i in 1..f.arguments.len() {
            let is_sampler = matches!(module.types[f.arguments[i].ty].inner, TypeInner::Sampler { .. });
            let texture = matches!(module.types[f.arguments[i - 1].ty].inner, TypeInner::Image { .. });
            if is_sampler && texture && f.arguments[i].name.is_none() {
                f.arguments[i].name = f.arguments[i - 1].name.as_ref().map(|t| format!("{t}_sampler"));
            }
        }
    }
    let textures: Vec<(ResourceBinding, String)> = module
        .global_variables
        .iter()
        .filter(|(_, g)| matches!(module.types[g.ty].inner, TypeInner::Image { .. }))
        .filter_map(|(_, g)| Some((g.binding?, g.name.clone()?)))
        .collect();
    for (_, g) in module.global_variables.iter_mut() {
        if g.name.is_some() || !matches!(module.types[g.ty].inner, TypeInner::Sampler { .. }) {
            continue;
        }
        let Some(b) = &g.binding else { continue };
        let texture = textures.iter().find(|(t, _)| t.group == b.group && t.binding + 1 == b.binding).map(|(_, n)| n);
        if let Some(t) = texture {
            let planned = plan.textures.iter().find(|p| &p.name == t).map(|p| p.sampler_name.clone());
            g.name = Some(planned.unwrap_or_else(|| format!("{t}_sampler")));
        }
    }
}

/// `layout(location = 0, index = 0) out vec4 c;` with no output at index 1 is an ordinary
/// colour output in GL; naga takes a blend source only as one of a dual-source pair in a
/// struct: without index 1 the index goes.
fn single_source_outputs(module: &mut Module) {
    use naga::Binding;
    let lone = |b: &Option<Binding>| matches!(b, Some(Binding::Location { blend_src: Some(_), .. }));
    let mut structs = Vec::new();
    for ep in module.entry_points.iter_mut().filter(|ep| ep.stage == naga::ShaderStage::Fragment) {
        let Some(result) = &mut ep.function.result else { continue };
        if lone(&result.binding) {
            if let Some(Binding::Location { blend_src, .. }) = &mut result.binding {
                *blend_src = None;
            }
        } else if let TypeInner::Struct { members, .. } = &module.types[result.ty].inner {
            let pair = members.iter().any(|m| matches!(m.binding, Some(Binding::Location { blend_src: Some(1), .. })));
            if !pair && members.iter().any(|m| lone(&m.binding)) {
                structs.push(result.ty);
            }
        }
    }
    for ty in structs {
        let mut t = module.types[ty].clone();
        if let TypeInner::Struct { members, .. } = &mut t.inner {
            for m in members {
                if let Some(Binding::Location { blend_src, .. }) = &mut m.binding {
                    *blend_src = None;
                }
            }
        }
        module.types.replace(ty, t);
    }
}

/// naga's SPIR-V front returns a stage's outputs as a struct with unnamed members: each
/// member with a location takes the name of the variable the entry point returns in it
/// (`uv`), so the translation and its reflection name varyings as the GLSL does.
/// Built-in outputs WebGPU has no use for leave the entry points' results: `gl_PointSize`
/// (WebGPU draws points one pixel wide), `gl_ClipDistance` and `gl_CullDistance` (no user
/// clip planes without a feature). They are computed and not passed, as on the GLSL route.
fn drop_outputs_webgpu_lacks(module: &mut Module) {
    use naga::{Binding, BuiltIn};
    let lacks =
        |b: &Option<Binding>| matches!(b, Some(Binding::BuiltIn(BuiltIn::PointSize | BuiltIn::ClipDistances | BuiltIn::CullDistance)));
    let mut replaced = Vec::new();
    for ep in &mut module.entry_points {
        let Some(result) = &ep.function.result else { continue };
        let TypeInner::Struct { members, .. } = &module.types[result.ty].inner else { continue };
        let dropped: Vec<usize> = members.iter().enumerate().filter(|(_, m)| lacks(&m.binding)).map(|(i, _)| i).collect();
        if dropped.is_empty() || dropped.len() == members.len() {
            continue;
        }
        for e in ep.function.expressions.iter_mut().map(|(_, e)| e) {
            if let naga::Expression::Compose { ty, components } = e {
                if *ty == result.ty {
                    let mut i = 0;
                    components.retain(|_| {
                        i += 1;
                        !dropped.contains(&(i - 1))
                    });
                }
            }
        }
        replaced.push((result.ty, dropped));
    }
    replaced.dedup_by_key(|(ty, _)| *ty);
    for (ty, dropped) in replaced {
        let mut t = module.types[ty].clone();
        if let TypeInner::Struct { members, .. } = &mut t.inner {
            let mut i = 0;
            members.retain(|_| {
                i += 1;
                !dropped.contains(&(i - 1))
            });
        }
        module.types.replace(ty, t);
    }
    // glslang's `gl_PerVertex` also types private variables: its members keep the built-in
    // bindings, which the WGSL writer refuses (`point_size`) outside an entry point's
    // inputs and outputs. They go where the type is not an entry point's.
    let io: Vec<naga::Handle<naga::Type>> = module
        .entry_points
        .iter()
        .flat_map(|ep| ep.function.arguments.iter().map(|a| a.ty).chain(ep.function.result.as_ref().map(|r| r.ty)))
        .collect();
    let private: Vec<naga::Handle<naga::Type>> = module
        .types
        .iter()
        .filter(|(h, t)| {
            !io.contains(h) && matches!(&t.inner, TypeInner::Struct { members, .. } if members.iter().any(|m| lacks(&m.binding)))
        })
        .map(|(h, _)| h)
        .collect();
    for ty in private {
        let mut t = module.types[ty].clone();
        if let TypeInner::Struct { members, .. } = &mut t.inner {
            members.iter_mut().for_each(|m| m.binding = None);
        }
        if module.types.get(&t).is_none() {
            module.types.replace(ty, t);
        }
    }
}

fn name_stage_outputs(module: &mut Module) {
    let mut renames = Vec::new();
    for ep in &module.entry_points {
        let Some(result) = &ep.function.result else { continue };
        let TypeInner::Struct { members, .. } = &module.types[result.ty].inner else { continue };
        let returned = ep.function.body.iter().find_map(|st| match st {
            Statement::Return { value: Some(e) } => Some(*e),
            _ => None,
        });
        let Some(naga::Expression::Compose { components, .. }) = returned.map(|e| &ep.function.expressions[e]) else { continue };
        let names: Vec<Option<String>> = members
            .iter()
            .zip(components)
            .map(|(m, c)| match (&m.name, &m.binding, &ep.function.expressions[*c]) {
                (None, Some(naga::Binding::Location { .. }), naga::Expression::Load { pointer }) => match ep.function.expressions[*pointer]
                {
                    naga::Expression::GlobalVariable(g) => module.global_variables[g].name.clone(),
                    _ => None,
                },
                _ => None,
            })
            .collect();
        if names.iter().any(Option::is_some) {
            renames.push((result.ty, names));
        }
    }
    for (ty, names) in renames {
        let mut t = module.types[ty].clone();
        if let TypeInner::Struct { members, .. } = &mut t.inner {
            for (m, n) in members.iter_mut().zip(names) {
                if m.name.is_none() {
                    m.name = n;
                }
            }
        }
        if module.types.get(&t).is_none() {
            module.types.replace(ty, t);
        }
    }
}

/// A function that can fall off its end without returning (legal GLSL; what it returns is
/// undefined) ends in `OpUnreachable` in glslang's SPIR-V, which naga's SPIR-V front reads
/// as a `return` without a value, and its validator refuses: those returns, never reached,
/// return the zero value of the function's type.
fn unreachable_ends_return_a_value(module: &mut Module) {
    let functions = module.functions.iter_mut().map(|(_, f)| f);
    for f in functions.chain(module.entry_points.iter_mut().map(|ep| &mut ep.function)) {
        let Some(ty) = f.result.as_ref().map(|r| r.ty) else { continue };
        let mut zero = None;
        let expressions = &mut f.expressions;
        crate::front::statements::visit_statements(&mut f.body, &mut |st| {
            if let Statement::Return { value: value @ None } = st {
                *value = Some(*zero.get_or_insert_with(|| expressions.append(naga::Expression::ZeroValue(ty), Span::UNDEFINED)));
            }
        });
    }
}

/// A shadow sampler passed to a function (`float pcf(sampler2DShadow s, vec4 p)`) reaches
/// naga's SPIR-V front as a texture and a sampler parameter of their own, which it types as
/// a plain texture and sampler even where the function compares with them (`texture(s, p)`,
/// `textureGather(s, p.xy, p.z)`), and its validator then refuses the comparison. Such
/// parameters are a depth texture and a comparison sampler, and so are the parameters and
/// globals passed to them.
fn comparison_parameters(module: &mut Module) {
    use naga::{Expression, Function, GlobalVariable, Handle};
    let mut compares: Vec<(Handle<Function>, usize)> = Vec::new();
    for (h, f) in module.functions.iter() {
        for (_, e) in f.expressions.iter() {
            if let Expression::ImageSample { image, sampler, depth_ref: Some(_), .. } = e {
                for operand in [image, sampler] {
                    if let Expression::FunctionArgument(i) = f.expressions[*operand] {
                        compares.push((h, i as usize));
                    }
                }
            }
        }
    }
    if compares.is_empty() {
        return;
    }
    type Passed = (Option<Handle<Function>>, Handle<Function>, usize, Expression);
    // Every argument passed to a function: (caller, callee, index, what is passed).
    let mut passed: Vec<Passed> = Vec::new();
    let functions = module.functions.iter_mut().map(|(h, f)| (Some(h), f));
    for (caller, f) in functions.chain(module.entry_points.iter_mut().map(|ep| (None, &mut ep.function))) {
        let expressions = &f.expressions;
        crate::front::statements::visit_statements(&mut f.body, &mut |st| {
            if let Statement::Call { function, arguments, .. } = st {
                for (i, a) in arguments.iter().enumerate() {
                    passed.push((caller, *function, i, expressions[*a].clone()));
                }
            }
        });
    }
    let mut globals: Vec<Handle<GlobalVariable>> = Vec::new();
    let mut i = 0;
    while i < compares.len() {
        let target = compares[i];
        for (caller, _, _, what) in passed.iter().filter(|(_, callee, at, _)| (*callee, *at) == target) {
            match (what, caller) {
                (Expression::FunctionArgument(j), Some(c)) if !compares.contains(&(*c, *j as usize)) => compares.push((*c, *j as usize)),
                (Expression::GlobalVariable(g), _) => globals.push(*g),
                _ => {}
            }
        }
        i += 1;
    }
    let comparing = |inner: &TypeInner| match *inner {
        TypeInner::Sampler { comparison: false } => Some(TypeInner::Sampler { comparison: true }),
        TypeInner::Image { dim, arrayed, class: naga::ImageClass::Sampled { kind: naga::ScalarKind::Float, multi } } => {
            Some(TypeInner::Image { dim, arrayed, class: naga::ImageClass::Depth { multi } })
        }
        _ => None,
    };
    let retype = |types: &mut naga::UniqueArena<naga::Type>, ty: &mut Handle<naga::Type>| {
        if let Some(inner) = comparing(&types[*ty].inner) {
            *ty = types.insert(naga::Type { name: None, inner }, Span::UNDEFINED);
        }
    };
    for (f, i) in compares {
        if let Some(a) = module.functions[f].arguments.get_mut(i) {
            retype(&mut module.types, &mut a.ty);
        }
    }
    for g in globals {
        retype(&mut module.types, &mut module.global_variables[g].ty);
    }
}

/// naga's SPIR-V front emits some expressions naga holds in scope from the start (the zero
/// value it makes of an `OpUndef`), and its validator then refuses them as introduced
/// twice: they leave their `Emit` ranges.
fn emit_only_what_needs_it(module: &mut Module) {
    let functions = module.functions.iter_mut().map(|(_, f)| f);
    for f in functions.chain(module.entry_points.iter_mut().map(|ep| &mut ep.function)) {
        emits_in(&mut f.body, &f.expressions);
    }
}

fn emits_in(block: &mut Block, expressions: &naga::Arena<naga::Expression>) {
    for st in block.iter_mut() {
        for b in crate::front::statements::child_blocks(st) {
            emits_in(b, expressions);
        }
    }
    let pre_emitted = |r: &naga::Range<naga::Expression>| r.clone().any(|h| expressions[h].needs_pre_emit());
    if !block.iter().any(|st| matches!(st, Statement::Emit(r) if pre_emitted(r))) {
        return;
    }
    for (st, span) in std::mem::take(block).span_into_iter() {
        let Statement::Emit(range) = st else {
            block.push(st, span);
            continue;
        };
        let mut run: Option<(naga::Handle<naga::Expression>, naga::Handle<naga::Expression>)> = None;
        for h in range {
            if expressions[h].needs_pre_emit() {
                if let Some((first, last)) = run.take() {
                    block.push(Statement::Emit(naga::Range::new_from_bounds(first, last)), span);
                }
            } else {
                run = Some((run.map_or(h, |(first, _)| first), h));
            }
        }
        if let Some((first, last)) = run {
            block.push(Statement::Emit(naga::Range::new_from_bounds(first, last)), span);
        }
    }
}

mod respan;

#[cfg(test)]
mod tests;
