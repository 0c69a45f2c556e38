//! GLSL's built-in implementation constants (`gl_MaxVertexOutputComponents`, …), which
//! naga's GLSL front does not declare. Their values are the resource limits the reference
//! compiler checks the program with, so what `check` accepted and what the translation
//! computes agree (an array sized `gl_MaxGeometryInputComponents` has one size in both).

use glslang_sys::glslang_resource_t as Limits;

/// The resource limits the reference compiler is given: glslang's defaults, as
/// glslangValidator's, except where those are GL's minimum and every desktop driver offers
/// more, so that a program the driver links is not refused for the limit alone:
/// atomic counter buffer bindings (glslang 1, Mesa 16; `layout(binding = 1) uniform
/// atomic_uint`). `reference::compiler` passes these to glslang.
pub fn limits() -> &'static Limits {
    static LIMITS: std::sync::OnceLock<Limits> = std::sync::OnceLock::new();
    LIMITS.get_or_init(|| {
        let defaults = glslang::limits::DEFAULT_LIMITS;
        // SAFETY: `ResourceLimits` is `repr(transparent)` over `glslang_resource_t`, plain data.
        let mut limits: Limits = unsafe { std::ptr::read((&defaults as *const glslang::limits::ResourceLimits).cast::<Limits>()) };
        limits.max_atomic_counter_bindings = 16;
        limits
    })
}

/// Reads one `int` constant's value from the limits.
type Read = fn(&Limits) -> i32;

/// Reads one `ivec3` constant's values from the limits.
type ReadVector = fn(&Limits) -> [i32; 3];

/// Each constant's name and its value among the limits.
const CONSTANTS: &[(&str, Read)] = &[
    ("gl_MaxVertexAttribs", |l| l.max_vertex_attribs),
    ("gl_MaxVertexUniformVectors", |l| l.max_vertex_uniform_vectors),
    ("gl_MaxVertexUniformComponents", |l| l.max_vertex_uniform_components),
    ("gl_MaxVertexOutputComponents", |l| l.max_vertex_output_components),
    ("gl_MaxVaryingComponents", |l| l.max_varying_components),
    ("gl_MaxVaryingVectors", |l| l.max_varying_vectors),
    ("gl_MaxVaryingFloats", |l| l.max_varying_floats),
    ("gl_MaxVertexTextureImageUnits", |l| l.max_vertex_texture_image_units),
    ("gl_MaxVertexImageUniforms", |l| l.max_vertex_image_uniforms),
    ("gl_MaxVertexAtomicCounters", |l| l.max_vertex_atomic_counters),
    ("gl_MaxVertexAtomicCounterBuffers", |l| l.max_vertex_atomic_counter_buffers),
    ("gl_MaxTessPatchComponents", |l| l.max_tess_patch_components),
    ("gl_MaxPatchVertices", |l| l.max_patch_vertices),
    ("gl_MaxTessGenLevel", |l| l.max_tess_gen_level),
    ("gl_MaxTessControlInputComponents", |l| l.max_tess_control_input_components),
    ("gl_MaxTessControlOutputComponents", |l| l.max_tess_control_output_components),
    ("gl_MaxTessControlTextureImageUnits", |l| l.max_tess_control_texture_image_units),
    ("gl_MaxTessControlUniformComponents", |l| l.max_tess_control_uniform_components),
    ("gl_MaxTessControlTotalOutputComponents", |l| l.max_tess_control_total_output_components),
    ("gl_MaxTessEvaluationInputComponents", |l| l.max_tess_evaluation_input_components),
    ("gl_MaxTessEvaluationOutputComponents", |l| l.max_tess_evaluation_output_components),
    ("gl_MaxTessEvaluationTextureImageUnits", |l| l.max_tess_evaluation_texture_image_units),
    ("gl_MaxTessEvaluationUniformComponents", |l| l.max_tess_evaluation_uniform_components),
    ("gl_MaxGeometryInputComponents", |l| l.max_geometry_input_components),
    ("gl_MaxGeometryOutputComponents", |l| l.max_geometry_output_components),
    ("gl_MaxGeometryImageUniforms", |l| l.max_geometry_image_uniforms),
    ("gl_MaxGeometryTextureImageUnits", |l| l.max_geometry_texture_image_units),
    ("gl_MaxGeometryOutputVertices", |l| l.max_geometry_output_vertices),
    ("gl_MaxGeometryTotalOutputComponents", |l| l.max_geometry_total_output_components),
    ("gl_MaxGeometryUniformComponents", |l| l.max_geometry_uniform_components),
    ("gl_MaxGeometryVaryingComponents", |l| l.max_geometry_varying_components),
    ("gl_MaxGeometryAtomicCounters", |l| l.max_geometry_atomic_counters),
    ("gl_MaxGeometryAtomicCounterBuffers", |l| l.max_geometry_atomic_counter_buffers),
    ("gl_MaxFragmentImageUniforms", |l| l.max_fragment_image_uniforms),
    ("gl_MaxFragmentInputComponents", |l| l.max_fragment_input_components),
    ("gl_MaxFragmentInputVectors", |l| l.max_fragment_input_vectors),
    ("gl_MaxFragmentUniformVectors", |l| l.max_fragment_uniform_vectors),
    ("gl_MaxFragmentUniformComponents", |l| l.max_fragment_uniform_components),
    ("gl_MaxFragmentAtomicCounters", |l| l.max_fragment_atomic_counters),
    ("gl_MaxFragmentAtomicCounterBuffers", |l| l.max_fragment_atomic_counter_buffers),
    ("gl_MaxDrawBuffers", |l| l.max_draw_buffers),
    ("gl_MaxTextureImageUnits", |l| l.max_texture_image_units),
    ("gl_MinProgramTexelOffset", |l| l.min_program_texel_offset),
    ("gl_MaxProgramTexelOffset", |l| l.max_program_texel_offset),
    ("gl_MaxImageUnits", |l| l.max_image_units),
    ("gl_MaxImageSamples", |l| l.max_image_samples),
    ("gl_MaxSamples", |l| l.max_samples),
    ("gl_MaxClipDistances", |l| l.max_clip_distances),
    ("gl_MaxCullDistances", |l| l.max_cull_distances),
    ("gl_MaxCombinedClipAndCullDistances", |l| l.max_combined_clip_and_cull_distances),
    ("gl_MaxCombinedTextureImageUnits", |l| l.max_combined_texture_image_units),
    ("gl_MaxCombinedImageUniforms", |l| l.max_combined_image_uniforms),
    ("gl_MaxCombinedImageUnitsAndFragmentOutputs", |l| l.max_combined_image_units_and_fragment_outputs),
    ("gl_MaxCombinedShaderOutputResources", |l| l.max_combined_shader_output_resources),
    ("gl_MaxCombinedAtomicCounters", |l| l.max_combined_atomic_counters),
    ("gl_MaxCombinedAtomicCounterBuffers", |l| l.max_combined_atomic_counter_buffers),
    ("gl_MaxAtomicCounterBindings", |l| l.max_atomic_counter_bindings),
    ("gl_MaxAtomicCounterBufferSize", |l| l.max_atomic_counter_buffer_size),
    ("gl_MaxTransformFeedbackBuffers", |l| l.max_transform_feedback_buffers),
    ("gl_MaxTransformFeedbackInterleavedComponents", |l| l.max_transform_feedback_interleaved_components),
    ("gl_MaxComputeUniformComponents", |l| l.max_compute_uniform_components),
    ("gl_MaxComputeTextureImageUnits", |l| l.max_compute_texture_image_units),
    ("gl_MaxComputeImageUniforms", |l| l.max_compute_image_uniforms),
    ("gl_MaxComputeAtomicCounters", |l| l.max_compute_atomic_counters),
    ("gl_MaxComputeAtomicCounterBuffers", |l| l.max_compute_atomic_counter_buffers),
    ("gl_MaxViewports", |l| l.max_viewports),
];

/// The `ivec3` constants: name and their three values.
const VECTORS: &[(&str, ReadVector)] = &[
    ("gl_MaxComputeWorkGroupCount", |l| {
        [l.max_compute_work_group_count_x, l.max_compute_work_group_count_y, l.max_compute_work_group_count_z]
    }),
    ("gl_MaxComputeWorkGroupSize", |l| [l.max_compute_work_group_size_x, l.max_compute_work_group_size_y, l.max_compute_work_group_size_z]),
];

/// The value of `int` built-in constant `name`, if it is one.
pub fn value(name: &str) -> Option<i64> {
    CONSTANTS.iter().find(|(n, _)| *n == name).map(|(_, value)| i64::from(value(limits())))
}

/// The GLSL declaration of built-in constant `name` (`const int gl_MaxClipDistances = 8;`),
/// if it is one.
pub fn declaration(name: &str) -> Option<String> {
    let l = limits();
    if let Some((_, value)) = CONSTANTS.iter().find(|(n, _)| *n == name) {
        return Some(format!("const int {name} = {};", value(l)));
    }
    let (_, values) = VECTORS.iter().find(|(n, _)| *n == name)?;
    let [x, y, z] = values(l);
    Some(format!("const ivec3 {name} = ivec3({x}, {y}, {z});"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constants_take_the_reference_compilers_limits() {
        assert_eq!(declaration("gl_MaxGeometryInputComponents").as_deref(), Some("const int gl_MaxGeometryInputComponents = 64;"));
        assert_eq!(declaration("gl_MinProgramTexelOffset").as_deref(), Some("const int gl_MinProgramTexelOffset = -8;"));
        assert!(declaration("gl_MaxComputeWorkGroupSize").unwrap().starts_with("const ivec3 gl_MaxComputeWorkGroupSize = ivec3(1024,"));
        assert_eq!(declaration("gl_Position"), None);
    }
}
