//! The Khronos reference compiler (glslang) in process, through its C interface
//! (`glslang-sys`): one stage compiled, a program linked, each returning glslang's own
//! verdict and info log.
//!
//! The `glslang` crate's safe layer links with Vulkan + SPIR-V rules only and panics on a
//! log that is not UTF-8, so the C interface is driven here; its default resource limits
//! (glslangValidator's) come from the safe crate.

use std::ffi::{c_char, CStr, CString};
use std::ptr::{self, NonNull};
use std::sync::OnceLock;

use glslang_sys as sys;

use crate::config::VulkanVersion;
use crate::stage::StageKind;

/// The dialect a stage is compiled in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dialect {
    /// OpenGL GLSL as a GL driver compiles it (`glslangValidator` without `-V`/`-G`):
    /// desktop core/compatibility or ES, as its `#version` says; no `#version` is 1.10.
    OpenGl,
    /// Vulkan GLSL (`glslangValidator -V --target-env vulkan1.x`): that Vulkan version's
    /// SPIR-V rules (1.0, 1.3, 1.5, 1.6).
    Vulkan(VulkanVersion),
}

/// glslang's client and SPIR-V versions for a Vulkan version.
fn vulkan_target(v: VulkanVersion) -> (sys::glslang_target_client_version_t, sys::glslang_target_language_version_t) {
    use sys::glslang_target_client_version_t as C;
    use sys::glslang_target_language_version_t as L;
    match v {
        VulkanVersion::V1_0 => (C::Vulkan1_0, L::SPIRV1_0),
        VulkanVersion::V1_1 => (C::Vulkan1_1, L::SPIRV1_3),
        VulkanVersion::V1_2 => (C::Vulkan1_2, L::SPIRV1_5),
        VulkanVersion::V1_3 => (C::Vulkan1_3, L::SPIRV1_6),
    }
}

/// glslang's verdict on one stage or one link.
#[derive(Debug, Clone)]
pub struct Verdict {
    pub ok: bool,
    /// The info log as glslang writes it (`ERROR: 0:12:5: 'x' : undeclared identifier`).
    pub log: String,
}

/// glslang's process-wide set-up, done once (never finalized: threads compile at any time).
fn initialized() -> bool {
    static INIT: OnceLock<bool> = OnceLock::new();
    // SAFETY: glslang_initialize_process has no preconditions; it is reference-counted and
    // guarded by glslang's own lock.
    *INIT.get_or_init(|| unsafe { sys::glslang_initialize_process() } != 0)
}

fn stage_of(kind: StageKind) -> sys::glslang_stage_t {
    match kind {
        StageKind::Vertex => sys::glslang_stage_t::Vertex,
        StageKind::TessControl => sys::glslang_stage_t::TesselationControl,
        StageKind::TessEval => sys::glslang_stage_t::TesselationEvaluation,
        StageKind::Geometry => sys::glslang_stage_t::Geometry,
        StageKind::Fragment => sys::glslang_stage_t::Fragment,
        StageKind::Compute => sys::glslang_stage_t::Compute,
        StageKind::Task => sys::glslang_stage_t::Task,
        StageKind::Mesh => sys::glslang_stage_t::Mesh,
        StageKind::RayGeneration => sys::glslang_stage_t::RayGeneration,
        StageKind::Intersection => sys::glslang_stage_t::Intersect,
        StageKind::AnyHit => sys::glslang_stage_t::AnyHit,
        StageKind::ClosestHit => sys::glslang_stage_t::ClosestHit,
        StageKind::Miss => sys::glslang_stage_t::Miss,
        StageKind::Callable => sys::glslang_stage_t::Callable,
    }
}

fn messages(dialect: Dialect) -> sys::glslang_messages_t {
    let base = sys::glslang_messages_t::DEFAULT | sys::glslang_messages_t::DISPLAY_ERROR_COLUMN;
    match dialect {
        Dialect::OpenGl => base,
        Dialect::Vulkan(_) => base | sys::glslang_messages_t::SPV_RULES | sys::glslang_messages_t::VULKAN_RULES,
    }
}

/// A C string of `text`; a NUL byte (which no GLSL source holds) ends the text there, as it
/// would for a driver reading a C string.
fn c_text(text: &str) -> CString {
    let end = text.find('\0').unwrap_or(text.len());
    CString::new(&text[..end]).expect("no NUL before `end`")
}

fn log_of(ptr: *const c_char) -> String {
    if ptr.is_null() {
        return String::new();
    }
    // SAFETY: glslang returns a NUL-terminated string it owns, valid until the next call on
    // the same object; it is copied at once.
    unsafe { CStr::from_ptr(ptr) }.to_string_lossy().into_owned()
}

/// One compiled stage (a glslang shader object), kept for linking.
pub struct CompiledShader {
    handle: NonNull<sys::glslang_shader_t>,
    /// glslang keeps pointers into the input and its text until the shader is deleted.
    _input: Box<sys::glslang_input_t>,
    _code: CString,
    pub kind: StageKind,
    pub verdict: Verdict,
}

// SAFETY: a glslang shader object is used by one thread at a time (it moves with its
// program's analysis); glslang's shared state is initialised once and read-only after.
unsafe impl Send for CompiledShader {}

impl Drop for CompiledShader {
    fn drop(&mut self) {
        // SAFETY: created by glslang_shader_create, deleted once.
        unsafe { sys::glslang_shader_delete(self.handle.as_ptr()) }
    }
}

/// Compiles one stage's text (includes already inlined) as `dialect`.
pub fn compile(text: &str, kind: StageKind, dialect: Dialect) -> Option<CompiledShader> {
    create(text, kind, dialect, None)
}

/// How stages are compiled for SPIR-V ([`spirv`]).
#[derive(Debug, Clone, Copy)]
pub struct SpirvSetup<'a> {
    /// Name, descriptor set and binding of the block GL's loose uniforms are gathered into
    /// (glslang's relaxed Vulkan rules).
    pub uniform_block: &'a str,
    pub set: u32,
    pub binding: u32,
}

/// glslang's parse of one stage; for SPIR-V (`spirv`), with line information kept and, for
/// OpenGL GLSL, Vulkan's rules relaxed as `glslangValidator -V -R --amb --aml` does.
fn create(text: &str, kind: StageKind, dialect: Dialect, spirv: Option<&SpirvSetup>) -> Option<CompiledShader> {
    if !initialized() {
        return None;
    }
    let code = c_text(text);
    let resource: *const sys::glslang_resource_t = crate::front::builtins::constants::limits();
    let (client, client_version, target, spirv_version, default_version) = match (dialect, spirv) {
        (Dialect::OpenGl, None) => (
            sys::glslang_client_t::None,
            sys::glslang_target_client_version_t::OpenGL450,
            sys::glslang_target_language_t::None,
            sys::glslang_target_language_version_t::SPIRV1_0,
            110,
        ),
        (Dialect::OpenGl, Some(_)) => {
            let (c, l) = vulkan_target(VulkanVersion::V1_0);
            (sys::glslang_client_t::Vulkan, c, sys::glslang_target_language_t::SPIRV, l, 110)
        }
        (Dialect::Vulkan(v), None) => {
            let (c, l) = vulkan_target(v);
            (sys::glslang_client_t::Vulkan, c, sys::glslang_target_language_t::SPIRV, l, 100)
        }
        // SPIR-V for naga: the Vulkan version's GLSL rules, SPIR-V 1.3 at most (Vulkan 1.1's,
        // subgroup operations included). From 1.4 on glslang writes what naga's SPIR-V front
        // does not read (`OpCopyLogical` for a struct copied between layouts, `OpExecutionModeId`)
        // where 1.3 has plain equivalents.
        (Dialect::Vulkan(v), Some(_)) => {
            let (c, _) = vulkan_target(v);
            let (_, l) = vulkan_target(v.min(VulkanVersion::V1_1));
            (sys::glslang_client_t::Vulkan, c, sys::glslang_target_language_t::SPIRV, l, 100)
        }
    };
    let mut messages = messages(if spirv.is_some() { Dialect::Vulkan(VulkanVersion::V1_0) } else { dialect });
    if spirv.is_some() {
        messages |= sys::glslang_messages_t::DEBUG_INFO;
    }
    let input = Box::new(sys::glslang_input_t {
        language: sys::glslang_source_t::GLSL,
        stage: stage_of(kind),
        client,
        client_version,
        target_language: target,
        target_language_version: spirv_version,
        code: code.as_ptr(),
        default_version,
        default_profile: sys::glslang_profile_t::None,
        force_default_version_and_profile: 0,
        forward_compatible: 0,
        messages,
        resource,
        callbacks: sys::glsl_include_callbacks_t { include_system: None, include_local: None, free_include_result: None },
        callbacks_ctx: ptr::null_mut(),
    });
    // SAFETY: `input` and `code` live as long as the shader (both move into it below).
    let handle = NonNull::new(unsafe { sys::glslang_shader_create(&*input) })?;
    if let Some(setup) = spirv {
        let mut options = sys::glslang_shader_options_t::AUTO_MAP_BINDINGS | sys::glslang_shader_options_t::AUTO_MAP_LOCATIONS;
        if dialect == Dialect::OpenGl {
            options |= sys::glslang_shader_options_t::VULKAN_RULES_RELAXED;
        }
        let name = c_text(setup.uniform_block);
        // SAFETY: a live shader; glslang copies the block name.
        unsafe {
            sys::glslang_shader_set_options(handle.as_ptr(), options.0);
            sys::glslang_shader_set_default_uniform_block_name(handle.as_ptr(), name.as_ptr());
            sys::glslang_shader_set_default_uniform_block_set_and_binding(handle.as_ptr(), setup.set, setup.binding);
        }
    }
    // The C interface's parse reads the text its preprocess wrote; given the text itself, it
    // parses as glslangValidator does (the full parse preprocesses too), once instead of
    // twice, and its messages keep the user's columns.
    // SAFETY: a live shader and its own input; glslang copies the text.
    let ok = unsafe {
        sys::glslang_shader_set_preprocessed_code(handle.as_ptr(), code.as_ptr());
        sys::glslang_shader_parse(handle.as_ptr(), &*input) != 0
    };
    // SAFETY: a live shader.
    let log = log_of(unsafe { sys::glslang_shader_get_info_log(handle.as_ptr()) });
    Some(CompiledShader { handle, _input: input, _code: code, kind, verdict: Verdict { ok, log } })
}

/// SPIR-V for every stage of a program glslang accepts (texts with includes inlined, in
/// pipeline order), with `OpLine` debug information. Vulkan GLSL: each stage compiled and
/// linked on its own, bindings and locations as written. OpenGL GLSL (1.40 and later, core):
/// one program under relaxed Vulkan rules, loose uniforms gathered into one block, bindings
/// and locations mapped once for the whole program. Err: glslang's log.
pub fn spirv(stages: &[(&str, StageKind)], dialect: Dialect, setup: &SpirvSetup) -> Result<Vec<Vec<u32>>, String> {
    let mut shaders = Vec::new();
    for (text, kind) in stages {
        let shader = create(text, *kind, dialect, Some(setup)).ok_or("glslang could not be set up")?;
        if !shader.verdict.ok {
            return Err(shader.verdict.log.clone());
        }
        shaders.push(shader);
    }
    let groups: Vec<&[CompiledShader]> = match dialect {
        Dialect::OpenGl => vec![&shaders[..]],
        Dialect::Vulkan(_) => shaders.chunks(1).collect(),
    };
    let mut out = Vec::new();
    for group in groups {
        // SAFETY: program created, used and deleted here; the shaders outlive it; the SPIR-V
        // pointer is valid for `size` words until the next generation on the program.
        unsafe {
            let program = NonNull::new(sys::glslang_program_create()).ok_or("glslang could not create a program")?;
            for s in group {
                sys::glslang_program_add_shader(program.as_ptr(), s.handle.as_ptr());
            }
            let linked = sys::glslang_program_link(
                program.as_ptr(),
                (messages(Dialect::Vulkan(VulkanVersion::V1_0)) | sys::glslang_messages_t::DEBUG_INFO).0,
            ) != 0
                && map_io(program, dialect, group[0].kind);
            if !linked {
                let log = log_of(sys::glslang_program_get_info_log(program.as_ptr()));
                sys::glslang_program_delete(program.as_ptr());
                return Err(log);
            }
            for s in group {
                let mut options = sys::glslang_spv_options_t {
                    generate_debug_info: true,
                    strip_debug_info: false,
                    disable_optimizer: true,
                    optimize_size: false,
                    optimize_performance: false,
                    disassemble: false,
                    validate: false,
                    emit_nonsemantic_shader_debug_info: false,
                    emit_nonsemantic_shader_debug_source: false,
                    compile_only: false,
                    optimize_allow_expanded_id_bound: false,
                    compiler_signature: ptr::null(),
                    command_line_arguments: ptr::null(),
                    current_working_directory: ptr::null(),
                };
                sys::glslang_program_SPIRV_generate_with_options(program.as_ptr(), stage_of(s.kind), &mut options);
                let size = sys::glslang_program_SPIRV_get_size(program.as_ptr());
                let words = sys::glslang_program_SPIRV_get_ptr(program.as_ptr());
                if words.is_null() || size == 0 {
                    sys::glslang_program_delete(program.as_ptr());
                    return Err(format!("glslang made no SPIR-V for the {} stage", s.kind));
                }
                out.push(std::slice::from_raw_parts(words, size).to_vec());
            }
            sys::glslang_program_delete(program.as_ptr());
        }
    }
    Ok(out)
}

/// Assigns the locations and bindings the stages leave open. OpenGL GLSL: with glslang's
/// GLSL mapper, which gives an output and the next stage's input of one name one location
/// (GL matches varyings by name; the default mapper numbers each stage's in declaration
/// order, so `out vec4 a; out float b;` met `in float b; in vec4 a;` at swapped locations).
/// Vulkan GLSL: the default mapper, stage by stage.
///
/// # Safety
/// `program` is a linked glslang program.
unsafe fn map_io(program: NonNull<sys::glslang_program_t>, dialect: Dialect, first: StageKind) -> bool {
    if dialect != Dialect::OpenGl {
        return sys::glslang_program_map_io(program.as_ptr()) != 0;
    }
    let resolver = sys::glslang_glsl_resolver_create(program.as_ptr(), stage_of(first));
    let mapper = sys::glslang_glsl_mapper_create();
    let mapped = !resolver.is_null()
        && !mapper.is_null()
        && sys::glslang_program_map_io_with_resolver_and_mapper(program.as_ptr(), resolver, mapper) != 0;
    if !resolver.is_null() {
        sys::glslang_glsl_resolver_delete(resolver);
    }
    if !mapper.is_null() {
        sys::glslang_glsl_mapper_delete(mapper);
    }
    mapped
}

/// Links compiled stages as one program by `dialect`'s rules (GL: what `glslangValidator -l`
/// checks). Every shader must have compiled.
pub fn link(shaders: &[CompiledShader], dialect: Dialect) -> Option<Verdict> {
    if !initialized() || shaders.iter().any(|s| !s.verdict.ok) {
        return None;
    }
    // SAFETY: program created, used and deleted here; the shaders outlive it.
    unsafe {
        let program = NonNull::new(sys::glslang_program_create())?;
        for s in shaders {
            sys::glslang_program_add_shader(program.as_ptr(), s.handle.as_ptr());
        }
        let ok = sys::glslang_program_link(program.as_ptr(), messages(dialect).0) != 0;
        let log = log_of(sys::glslang_program_get_info_log(program.as_ptr()));
        sys::glslang_program_delete(program.as_ptr());
        Some(Verdict { ok, log })
    }
}
