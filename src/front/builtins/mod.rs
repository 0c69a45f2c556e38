//! GLSL's built-in names (functions, variables, opaque types), from the GLSL 4.60 and
//! compatibility-profile specifications.
//!
//! naga's GLSL front knows only part of them. When naga says "unknown function
//! `textureQueryLod`", that is a limitation of naga, not an error in the user's program;
//! when it says "unknown function `textur`", it is. These lists tell the two apart:
//! `glsl_lists` holds GLSL's names, `naga_lists` the ones naga knows; the questions asked
//! of them are here.

pub mod constants;
mod glsl_lists;
mod naga_lists;

use crate::front::version::{Profile, Version};
pub use glsl_lists::IMAGE_FORMATS;
use glsl_lists::{COMPAT_VARIABLES, CORE_VARIABLES, EXTENSION_VARIABLES, FUNCTIONS, LAYOUT_QUALIFIERS, TYPES};
use naga_lists::{NAGA_FUNCTIONS, NAGA_VARIABLES};

/// Whether `name` is a built-in function of GLSL that naga's GLSL front does not implement.
pub fn is_function_naga_lacks(name: &str) -> bool {
    (FUNCTIONS.contains(&name) || name.starts_with("subgroup") || name.starts_with("rayQuery")) && !NAGA_FUNCTIONS.contains(&name)
}

/// Whether `name` is a built-in variable the program's version and profile declare and
/// naga's GLSL front does not.
pub fn is_variable_naga_lacks(name: &str, version: &Version) -> bool {
    if NAGA_VARIABLES.contains(&name) {
        return false;
    }
    if EXTENSION_VARIABLES.contains(&name) {
        return true;
    }
    // Output-only and stage-specific ones effectc rewrites are not listed here.
    const CORE_NAGA_LACKS: &[&str] = &[
        "gl_Layer",
        "gl_ViewportIndex",
        "gl_SampleMaskIn",
        "gl_SampleMask",
        "gl_SamplePosition",
        "gl_HelperInvocation",
        "gl_NumSamples",
        "gl_ViewIndex",
        "gl_DeviceIndex",
        "gl_MaxDrawBuffers",
        "gl_MaxTextureImageUnits",
        "gl_MaxVertexAttribs",
        "gl_MaxClipDistances",
        "gl_MaxSamples",
    ];
    if CORE_NAGA_LACKS.contains(&name) {
        return CORE_VARIABLES.contains(&name);
    }
    COMPAT_VARIABLES.contains(&name) && has_compatibility_builtins(version)
}

/// Whether `name` is a compatibility-profile built-in variable.
pub fn is_compat_variable(name: &str) -> bool {
    COMPAT_VARIABLES.contains(&name)
}

/// Versions and profiles that declare the fixed-function built-ins (`gl_Vertex`, …).
pub fn has_compatibility_builtins(version: &Version) -> bool {
    !version.is_es() && (version.number <= 130 || version.profile == Profile::Compatibility || version.directive.is_none())
}

/// Whether `name` is a built-in function of GLSL.
pub fn is_function(name: &str) -> bool {
    FUNCTIONS.contains(&name)
}

/// Whether `name` is a built-in type of GLSL.
pub fn is_type(name: &str) -> bool {
    TYPES.contains(&name)
}

/// Layout qualifier identifiers of GLSL (and GL_EXT_/GL_ARB_ ones seen in practice).
pub fn is_layout_qualifier(name: &str) -> bool {
    LAYOUT_QUALIFIERS.contains(&name) || IMAGE_FORMATS.contains(&name)
}
