//! GLSL's built-in names (functions, variables, opaque types), from the GLSL 4.60 and
//! compatibility-profile specifications.
//!
//! naga's GLSL front knows only part of them. When naga says "unknown function
//! `textureQueryLod`", that is a limitation of naga, not an error in the user's program;
//! when it says "unknown function `textur`", it is. These lists tell the two apart.

use crate::front::version::{Profile, Version};

/// Built-in functions of GLSL 1.10–4.60 (core and compatibility) and the common extensions.
const FUNCTIONS: &[&str] = &[
    // Angle, trigonometry, exponential.
    "radians", "degrees", "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "asinh", "acosh",
    "atanh", "pow", "exp", "log", "exp2", "log2", "sqrt", "inversesqrt",
    // Common.
    "abs", "sign", "floor", "trunc", "round", "roundEven", "ceil", "fract", "mod", "modf", "min", "max", "clamp",
    "mix", "step", "smoothstep", "isnan", "isinf", "floatBitsToInt", "floatBitsToUint", "intBitsToFloat",
    "uintBitsToFloat", "fma", "frexp", "ldexp", "doubleBitsToInt64", "doubleBitsToUint64", "int64BitsToDouble",
    "uint64BitsToDouble",
    // Packing.
    "packUnorm2x16", "packSnorm2x16", "packUnorm4x8", "packSnorm4x8", "unpackUnorm2x16", "unpackSnorm2x16",
    "unpackUnorm4x8", "unpackSnorm4x8", "packHalf2x16", "unpackHalf2x16", "packDouble2x32", "unpackDouble2x32",
    // Geometric, matrix, vector relational.
    "length", "distance", "dot", "cross", "normalize", "ftransform", "faceforward", "reflect", "refract",
    "matrixCompMult", "outerProduct", "transpose", "determinant", "inverse", "lessThan", "lessThanEqual",
    "greaterThan", "greaterThanEqual", "equal", "notEqual", "any", "all", "not",
    // Integer.
    "uaddCarry", "usubBorrow", "umulExtended", "imulExtended", "bitfieldExtract", "bitfieldInsert",
    "bitfieldReverse", "bitCount", "findLSB", "findMSB",
    // Texture queries and lookups.
    "textureSize", "textureQueryLod", "textureQueryLevels", "textureSamples", "texture", "textureProj",
    "textureLod", "textureOffset", "texelFetch", "texelFetchOffset", "textureProjOffset", "textureLodOffset",
    "textureProjLod", "textureProjLodOffset", "textureGrad", "textureGradOffset", "textureProjGrad",
    "textureProjGradOffset", "textureGather", "textureGatherOffset", "textureGatherOffsets",
    "texture1D", "texture1DProj", "texture1DLod", "texture1DProjLod", "texture2D", "texture2DProj",
    "texture2DLod", "texture2DProjLod", "texture3D", "texture3DProj", "texture3DLod", "texture3DProjLod",
    "textureCube", "textureCubeLod", "shadow1D", "shadow2D", "shadow1DProj", "shadow2DProj", "shadow1DLod",
    "shadow2DLod", "shadow1DProjLod", "shadow2DProjLod", "texture2DRect", "texture2DRectProj", "shadow2DRect",
    "texture2DLodEXT", "texture2DProjLodEXT", "textureCubeLodEXT", "texture2DGradEXT", "textureCubeGradEXT",
    "texture2DArray", "texture2DArrayLod", "shadow2DArray", "texture1DArray", "sparseTextureARB",
    // Atomic counters, atomics, images.
    "atomicCounterIncrement", "atomicCounterDecrement", "atomicCounter", "atomicCounterAdd",
    "atomicCounterSubtract", "atomicCounterMin", "atomicCounterMax", "atomicCounterAnd", "atomicCounterOr",
    "atomicCounterXor", "atomicCounterExchange", "atomicCounterCompSwap", "atomicAdd", "atomicMin", "atomicMax",
    "atomicAnd", "atomicOr", "atomicXor", "atomicExchange", "atomicCompSwap", "imageSize", "imageSamples",
    "imageLoad", "imageStore", "imageAtomicAdd", "imageAtomicMin", "imageAtomicMax", "imageAtomicAnd",
    "imageAtomicOr", "imageAtomicXor", "imageAtomicExchange", "imageAtomicCompSwap",
    // Geometry, fragment processing, noise, barriers.
    "EmitStreamVertex", "EndStreamPrimitive", "EmitVertex", "EndPrimitive", "dFdx", "dFdy", "dFdxFine",
    "dFdyFine", "dFdxCoarse", "dFdyCoarse", "fwidth", "fwidthFine", "fwidthCoarse", "interpolateAtCentroid",
    "interpolateAtSample", "interpolateAtOffset", "noise1", "noise2", "noise3", "noise4", "barrier",
    "memoryBarrier", "memoryBarrierAtomicCounter", "memoryBarrierBuffer", "memoryBarrierShared",
    "memoryBarrierImage", "groupMemoryBarrier", "subpassLoad", "anyInvocation", "allInvocations",
    "allInvocationsEqual", "anyInvocationARB", "allInvocationsARB", "allInvocationsEqualARB",
    "ballotARB", "readInvocationARB", "readFirstInvocationARB", "subgroupBallot", "subgroupElect",
    "nonuniformEXT", "sparseTextureLodARB", "sparseTexelFetchARB", "sparseTextureOffsetARB",
    "sparseTextureGradARB", "sparseTextureGatherARB", "sparseTexelsResidentARB", "sparseTextureClampARB",
];

/// Built-in variables of the compatibility profile (removed from core 1.40+/3.xx).
const COMPAT_VARIABLES: &[&str] = &[
    "gl_Vertex", "gl_Normal", "gl_Color", "gl_SecondaryColor", "gl_FogCoord", "gl_MultiTexCoord0",
    "gl_MultiTexCoord1", "gl_MultiTexCoord2", "gl_MultiTexCoord3", "gl_MultiTexCoord4", "gl_MultiTexCoord5",
    "gl_MultiTexCoord6", "gl_MultiTexCoord7", "gl_FrontColor", "gl_BackColor", "gl_FrontSecondaryColor",
    "gl_BackSecondaryColor", "gl_TexCoord", "gl_FogFragCoord", "gl_ClipVertex", "gl_ModelViewMatrix",
    "gl_ProjectionMatrix", "gl_ModelViewProjectionMatrix", "gl_TextureMatrix", "gl_NormalMatrix",
    "gl_ModelViewMatrixInverse", "gl_ProjectionMatrixInverse", "gl_ModelViewProjectionMatrixInverse",
    "gl_TextureMatrixInverse", "gl_ModelViewMatrixTranspose", "gl_ProjectionMatrixTranspose",
    "gl_ModelViewProjectionMatrixTranspose", "gl_TextureMatrixTranspose", "gl_ModelViewMatrixInverseTranspose",
    "gl_ProjectionMatrixInverseTranspose", "gl_ModelViewProjectionMatrixInverseTranspose",
    "gl_TextureMatrixInverseTranspose", "gl_NormalScale", "gl_DepthRange", "gl_ClipPlane", "gl_Point",
    "gl_FrontMaterial", "gl_BackMaterial", "gl_LightSource", "gl_LightModel", "gl_FrontLightModelProduct",
    "gl_BackLightModelProduct", "gl_FrontLightProduct", "gl_BackLightProduct", "gl_TextureEnvColor",
    "gl_EyePlaneS", "gl_EyePlaneT", "gl_EyePlaneR", "gl_EyePlaneQ", "gl_ObjectPlaneS", "gl_ObjectPlaneT",
    "gl_ObjectPlaneR", "gl_ObjectPlaneQ", "gl_Fog", "gl_MaxTextureCoords", "gl_MaxLights",
    "gl_MaxClipPlanes", "gl_MaxTextureUnits",
];

/// Built-in variables and constants of the core profile (every stage).
const CORE_VARIABLES: &[&str] = &[
    "gl_VertexID", "gl_InstanceID", "gl_VertexIndex", "gl_InstanceIndex", "gl_DrawID", "gl_BaseVertex",
    "gl_BaseInstance", "gl_Position", "gl_PointSize", "gl_ClipDistance", "gl_CullDistance", "gl_PerVertex",
    "gl_in", "gl_out", "gl_PrimitiveIDIn", "gl_PrimitiveID", "gl_InvocationID", "gl_Layer", "gl_ViewportIndex",
    "gl_PatchVerticesIn", "gl_TessLevelOuter", "gl_TessLevelInner", "gl_TessCoord", "gl_FragCoord",
    "gl_FrontFacing", "gl_PointCoord", "gl_SampleID", "gl_SamplePosition", "gl_SampleMaskIn", "gl_SampleMask",
    "gl_HelperInvocation", "gl_FragDepth", "gl_FragColor", "gl_FragData", "gl_NumWorkGroups", "gl_WorkGroupSize",
    "gl_WorkGroupID", "gl_LocalInvocationID", "gl_GlobalInvocationID", "gl_LocalInvocationIndex", "gl_ViewIndex",
    "gl_DeviceIndex", "gl_MaxDrawBuffers", "gl_MaxTextureImageUnits", "gl_MaxVertexAttribs",
    "gl_MaxVertexUniformComponents", "gl_MaxVaryingFloats", "gl_MaxVaryingComponents",
    "gl_MaxVertexTextureImageUnits", "gl_MaxCombinedTextureImageUnits", "gl_MaxFragmentUniformComponents",
    "gl_MaxClipDistances", "gl_MaxPatchVertices", "gl_MaxSamples", "gl_NumSamples",
];

/// Opaque and extended types of GLSL that naga's GLSL front may not know.
const TYPES: &[&str] = &[
    "atomic_uint", "double", "dvec2", "dvec3", "dvec4", "dmat2", "dmat3", "dmat4", "dmat2x2", "dmat2x3",
    "dmat2x4", "dmat3x2", "dmat3x3", "dmat3x4", "dmat4x2", "dmat4x3", "dmat4x4", "samplerBuffer",
    "isamplerBuffer", "usamplerBuffer", "sampler1DArray", "sampler1DShadow", "sampler1DArrayShadow",
    "sampler2DRectShadow", "isampler1D", "usampler1D", "isampler1DArray", "usampler1DArray", "isampler2DRect",
    "usampler2DRect", "isamplerCubeArray", "usamplerCubeArray", "samplerCubeArrayShadow", "sampler2DMS",
    "isampler2DMS", "usampler2DMS", "sampler2DMSArray", "isampler2DMSArray", "usampler2DMSArray",
    "textureBuffer", "itextureBuffer", "utextureBuffer", "imageBuffer", "iimageBuffer", "uimageBuffer",
    "image1D", "image2D", "image3D", "imageCube", "image2DRect", "image1DArray", "image2DArray",
    "imageCubeArray", "image2DMS", "image2DMSArray", "iimage1D", "iimage2D", "iimage3D", "iimageCube",
    "iimage2DArray", "uimage1D", "uimage2D", "uimage3D", "uimageCube", "uimage2DArray", "subpassInput",
    "subpassInputMS", "isubpassInput", "usubpassInput", "int64_t", "uint64_t", "i64vec2", "i64vec3",
    "i64vec4", "u64vec2", "u64vec3", "u64vec4", "float16_t", "f16vec2", "f16vec3", "f16vec4",
    "accelerationStructureEXT", "rayQueryEXT",
];

/// Built-in functions naga 30's GLSL front implements (its `builtins.rs`). For these an
/// "unknown function" from naga means no overload matched the arguments: a real error.
const NAGA_FUNCTIONS: &[&str] = &[
    "abs", "acos", "acosh", "all", "any", "asin", "asinh", "atan", "atanh", "barrier", "bitCount",
    "bitfieldExtract", "bitfieldInsert", "bitfieldReverse", "ceil", "clamp", "cos", "cosh", "cross", "dFdx",
    "dFdxCoarse", "dFdxFine", "dFdy", "dFdyCoarse", "dFdyFine", "degrees", "determinant", "distance", "dot",
    "equal", "exp", "exp2", "faceforward", "findLSB", "findMSB", "floatBitsToInt", "floatBitsToUint", "floor",
    "fma", "fract", "frexp", "fwidth", "fwidthCoarse", "fwidthFine", "greaterThan", "greaterThanEqual",
    "imageLoad", "imageSize", "imageStore", "intBitsToFloat", "inverse", "inversesqrt", "isinf", "isnan",
    "ldexp", "length", "lessThan", "lessThanEqual", "log", "log2", "max", "min", "mix", "mod", "modf",
    "normalize", "not", "notEqual", "outerProduct", "packHalf2x16", "packSnorm2x16", "packSnorm4x8",
    "packUnorm2x16", "packUnorm4x8", "pow", "radians", "reflect", "refract", "round", "roundEven", "sign", "sin",
    "sinh", "smoothstep", "sqrt", "step", "tan", "tanh", "texelFetch", "texelFetchOffset", "texture",
    "textureGrad", "textureGradOffset", "textureLod", "textureLodOffset", "textureOffset", "textureProj",
    "textureProjGrad", "textureProjGradOffset", "textureProjLod", "textureProjLodOffset", "textureProjOffset",
    "textureQueryLevels", "textureSize", "transpose", "trunc", "uintBitsToFloat", "unpackHalf2x16",
    "unpackSnorm2x16", "unpackSnorm4x8", "unpackUnorm2x16", "unpackUnorm4x8",
];

/// Built-in variables naga 30's GLSL front declares.
const NAGA_VARIABLES: &[&str] = &[
    "gl_BaseInstance", "gl_BaseVertex", "gl_ClipDistance", "gl_CullDistance", "gl_DrawID", "gl_FragCoord",
    "gl_FragDepth", "gl_FrontFacing", "gl_GlobalInvocationID", "gl_InstanceIndex", "gl_LocalInvocationID",
    "gl_LocalInvocationIndex", "gl_NumWorkGroups", "gl_PointCoord", "gl_PointSize", "gl_Position",
    "gl_PrimitiveID", "gl_SampleID", "gl_VertexIndex", "gl_WorkGroupID", "gl_WorkGroupSize",
];

/// Whether `name` is a built-in function of GLSL that naga's GLSL front does not implement.
pub fn is_function_naga_lacks(name: &str) -> bool {
    (FUNCTIONS.contains(&name) || name.starts_with("subgroup") || name.starts_with("rayQuery"))
        && !NAGA_FUNCTIONS.contains(&name)
}

/// Built-in variables of the GL_EXT_/GL_ARB_/GL_NV_ extensions seen in practice (shading
/// rate, barycentrics, fragment density, subgroups, multiview, stencil export).
const EXTENSION_VARIABLES: &[&str] = &[
    "gl_ShadingRateEXT", "gl_PrimitiveShadingRateEXT", "gl_FragSizeEXT", "gl_FragInvocationCountEXT",
    "gl_BaryCoordEXT", "gl_BaryCoordNoPerspEXT", "gl_BaryCoordNV", "gl_BaryCoordNoPerspNV",
    "gl_SubgroupSize", "gl_SubgroupInvocationID", "gl_SubgroupEqMask", "gl_SubgroupGeMask", "gl_SubgroupGtMask",
    "gl_SubgroupLeMask", "gl_SubgroupLtMask", "gl_NumSubgroups", "gl_SubgroupID", "gl_FragStencilRefARB",
    "gl_ViewportMask", "gl_ViewIndex", "gl_DeviceIndex", "gl_FragFullyCoveredNV", "gl_SecondaryPositionNV",
    "gl_WarpIDNV", "gl_SMIDNV", "gl_ThreadInWarpNV", "gl_WarpSizeNV", "gl_HelperInvocation",
];

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
        "gl_Layer", "gl_ViewportIndex", "gl_SampleMaskIn", "gl_SampleMask", "gl_SamplePosition",
        "gl_HelperInvocation", "gl_NumSamples", "gl_ViewIndex", "gl_DeviceIndex", "gl_MaxDrawBuffers",
        "gl_MaxTextureImageUnits", "gl_MaxVertexAttribs", "gl_MaxClipDistances", "gl_MaxSamples",
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

/// Whether `name` is a built-in type of GLSL.
pub fn is_type(name: &str) -> bool {
    TYPES.contains(&name)
}

/// Layout qualifier identifiers of GLSL (and GL_EXT_/GL_ARB_ ones seen in practice).
pub fn is_layout_qualifier(name: &str) -> bool {
    const LAYOUT: &[&str] = &[
        "shared", "packed", "std140", "std430", "row_major", "column_major", "binding", "offset", "align",
        "set", "push_constant", "input_attachment_index", "constant_id", "location", "component", "index",
        "triangles", "quads", "isolines", "equal_spacing", "fractional_even_spacing", "fractional_odd_spacing",
        "cw", "ccw", "point_mode", "points", "lines", "lines_adjacency", "triangles_adjacency", "invocations",
        "origin_upper_left", "pixel_center_integer", "early_fragment_tests", "local_size_x", "local_size_y",
        "local_size_z", "local_size_x_id", "local_size_y_id", "local_size_z_id", "xfb_buffer", "xfb_stride",
        "xfb_offset", "vertices", "line_strip", "triangle_strip", "max_vertices", "stream", "depth_any",
        "depth_greater", "depth_less", "depth_unchanged", "scalar", "buffer_reference", "buffer_reference_align",
        "post_depth_coverage", "blend_support_all_equations", "r32f", "rgba32f", "rgba16f", "rg32f", "rg16f",
        "r11f_g11f_b10f", "r16f", "rgba16", "rgb10_a2", "rgba8", "rg16", "rg8", "r16", "r8", "rgba16_snorm",
        "rgba8_snorm", "rg16_snorm", "rg8_snorm", "r16_snorm", "r8_snorm", "rgba32i", "rgba16i", "rgba8i",
        "rg32i", "rg16i", "rg8i", "r32i", "r16i", "r8i", "rgba32ui", "rgba16ui", "rgb10_a2ui", "rgba8ui", "rg32ui",
        "rg16ui", "rg8ui", "r32ui", "r16ui", "r8ui", "bindless_sampler", "bindless_image", "viewport_relative",
        "num_views", "primitive_culling",
    ];
    LAYOUT.contains(&name)
}
