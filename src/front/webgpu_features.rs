//! Notes on GL built-ins WebGPU has only as optional features: what the translation does
//! with them, at the GLSL that uses them.

use crate::diag::{Code, Diagnostic};
use crate::front::naga_run::Validated;
use crate::front::rewrite;
use crate::front::syntax::StageSyntax;

/// The notes on what the translation of stage `s` does with what WebGPU lacks; `naga`: the
/// stage's validated module, where naga took it.
pub fn stage_notes(s: &StageSyntax, naga: Option<&Validated>) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    // A stage naga does not take (N0102 says why) has no translation to report on, and the
    // masked construct reads as another type (`accelerationStructureEXT` as an image).
    if naga.is_some() || s.unsupported.is_none() {
        out.extend(image_formats_chosen(s));
        out.extend(runtime_arrays_bound(s));
    }
    if let Some(v) = naga {
        out.extend(float16_needed(s, v));
        out.extend(wide_integers_paired(s));
        out.extend(subgroups_of_one(s));
    }
    out
}

/// N0111 at each image of `s` declared without a format qualifier (legal where the stage
/// only stores to it, or reads with `EXT_shader_image_load_formatted`: GL converts to the
/// format of the image bound): WebGPU storage textures have a format, and the translation
/// gives the widest of the image's type, which holds every value the stage stores; `render`
/// creates the image in it.
pub fn image_formats_chosen(s: &StageSyntax) -> Vec<Diagnostic> {
    let images = s.globals.iter().filter(|g| g.storage == crate::front::syntax::Storage::Uniform);
    images
        .filter_map(|g| Some((g, crate::front::syntax::chosen_image_format(&g.ty.base, &g.layout)?)))
        .map(|(g, format)| {
            Diagnostic::new(Code::ImageFormatChosen, format!("image `{}` has no format: the translation declares it `{format}`", s.original_name(&g.name)))
                .at(s.file, g.name_span.clone(), format!("stored as `{format}`"))
                .with_note("GL converts to the format of the image bound; WebGPU storage textures are declared with a format, and this one holds every value the stage can store")
                .with_help("write the format the image is created in (`layout(rgba8) writeonly uniform image2D …`) to translate to it")
        })
        .collect()
}

/// N0108 at the first use of `gl_ClipDistance` or `gl_CullDistance` in `s`, the stage that
/// feeds the rasterizer (a geometry stage, else the vertex stage): WebGPU has no user clip or
/// cull distances without a feature, so both routes compute them and pass neither, and a
/// program GL draws with `GL_CLIP_DISTANCEi` enabled is drawn unclipped.
pub fn clip_distances_dropped(s: &StageSyntax) -> Option<Diagnostic> {
    let u = s.uses.iter().find(|u| matches!(u.name.as_str(), "gl_ClipDistance" | "gl_CullDistance") && rewrite::names_builtin(s, u))?;
    Some(
        Diagnostic::new(Code::ClipDistancesDropped, format!("`{}` is computed, not passed on: WebGPU clips and culls by neither", u.name))
            .at(s.file, u.span.clone(), "computed, not passed")
            .with_note("WebGPU has user clip distances only with the `clip-distances` feature, and no cull distances: a program GL draws with `GL_CLIP_DISTANCEi` enabled is drawn unclipped by the translation"),
    )
}

/// N0109 in fragment stage `s` when it needs one of WebGPU's optional features: `gl_PrimitiveID`
/// read as the built-in (not the varying a folded geometry stage passes), or a
/// second-source output (`layout(index = 1)`, dual-source blending). The WGSL enables the
/// feature (`enable primitive_index;`), and it runs where the device has it.
/// `folded`: the program has a geometry stage.
pub fn optional_features_needed(s: &StageSyntax, validated: &Validated, folded: bool) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    if !folded && validated.needs.iter().any(|n| n == "PRIMITIVE_INDEX") {
        let d = Diagnostic::new(Code::OptionalWebGpuFeature, "`gl_PrimitiveID` needs WebGPU's optional `primitive-index` feature");
        out.push(at_use(d, s, "gl_PrimitiveID"));
    }
    if validated.needs.iter().any(|n| n == "DUAL_SOURCE_BLENDING") {
        let d =
            Diagnostic::new(Code::OptionalWebGpuFeature, "an `index = 1` output needs WebGPU's optional `dual-source-blending` feature");
        let second = s.globals.iter().find(|g| g.layout.iter().any(|(k, v)| k == "index" && *v == Some(1)));
        out.push(match second {
            Some(g) => d.at(s.file, g.name_span.clone(), "the second source"),
            None => d.in_file(s.file),
        });
    }
    out.into_iter()
        .map(|d| {
            d.with_note("the WGSL enables the feature; a device without it refuses the pipeline (lavapipe and most desktop GPUs have it)")
        })
        .collect()
}

/// N0109 in stage `s` when it computes with 16-bit floats (`float16_t`, `f16vec4`,
/// GL_EXT_shader_explicit_arithmetic_types): WGSL has them with the optional `shader-f16`
/// feature, which the translation enables (`enable f16;`). At the first such type.
pub fn float16_needed(s: &StageSyntax, validated: &Validated) -> Option<Diagnostic> {
    if !validated.needs.iter().any(|n| n == "SHADER_FLOAT16") {
        return None;
    }
    let d = Diagnostic::new(Code::OptionalWebGpuFeature, "16-bit floats need WebGPU's optional `shader-f16` feature")
        .with_note("the WGSL enables the feature (`enable f16;`); a device without it refuses the pipeline");
    Some(match &s.unsupported {
        Some((what, span)) if what.contains("16") => d.at(s.file, span.clone(), "a 16-bit float type"),
        _ => d.in_file(s.file),
    })
}

/// N0113 at each array of textures, images or samplers of `s` sized at run time (bindless,
/// `uniform sampler2D textures[];`): WGSL has no such arrays, and the translation (through
/// SPIR-V, [`spirv_binding_arrays`](crate::front::spirv_binding_arrays)) declares
/// [`RUNTIME_ELEMENTS`](crate::front::spirv_binding_arrays::RUNTIME_ELEMENTS) of them.
pub fn runtime_arrays_bound(s: &StageSyntax) -> Vec<Diagnostic> {
    let n = crate::front::spirv_binding_arrays::RUNTIME_ELEMENTS;
    // `isampler2D`, `uimage2D`: one prefix (trimming every `i` would eat `image`'s).
    let opaque = |base: &str| {
        let unprefixed = base.strip_prefix(['i', 'u']).unwrap_or(base);
        ["sampler", "texture", "image", "subpassInput"].iter().any(|p| base.starts_with(p) || unprefixed.starts_with(p))
    };
    s.globals
        .iter()
        .filter(|g| g.storage == crate::front::syntax::Storage::Uniform && opaque(&g.ty.base) && g.ty.dims.first() == Some(&None))
        .map(|g| {
            Diagnostic::new(Code::RuntimeArrayBound, format!("`{}` is sized at run time: the translation binds {n} elements of it", s.original_name(&g.name)))
                .at(s.file, g.name_span.clone(), format!("{n} bindings, one per element"))
                .with_note(format!(
                    "WGSL has no arrays of textures or samplers: each element is a binding of its own (the next bindings of the set move up), \
                     a lookup at an index known at run time reads every element and keeps the indexed one, and an index past the {n}th reads the last"
                ))
        })
        .collect()
}

/// N0114 in stage `s` when it computes with 64-bit integers (`uint64_t`, `int64_t`) and
/// naga validated it: the translation holds each in two 32-bit words
/// ([`spirv_wide_integers`](crate::front::spirv_wide_integers)). At the first such type.
pub fn wide_integers_paired(s: &StageSyntax) -> Option<Diagnostic> {
    let (what, span) = s.unsupported.as_ref().filter(|(what, _)| what.contains("int64_t") || what.contains("i64vec"))?;
    Some(
        Diagnostic::new(Code::WideIntegersPaired, format!("{what}: held as two 32-bit words"))
            .at(s.file, span.clone(), "a 64-bit integer type")
            .with_note("WGSL has no 64-bit integers: the translation holds each as `vec2<u32>` (low word first; buffers keep their layout) and computes comparisons, `+`, `-` and conversions from the words"),
    )
}

/// N0115 in stage `s` at its first subgroup operation or built-in, when naga validated it:
/// the translation computes them for subgroups of one invocation
/// ([`spirv_subgroups`](crate::front::spirv_subgroups)).
pub fn subgroups_of_one(s: &StageSyntax) -> Option<Diagnostic> {
    let call = s.calls.iter().find(|c| c.name.starts_with("subgroup")).map(|c| (c.name.clone(), c.name_span.clone()));
    let builtin = || s.uses.iter().find(|u| u.name.starts_with("gl_Subgroup")).map(|u| (u.name.clone(), u.span.clone()));
    let (name, span) = call.or_else(builtin)?;
    Some(
        Diagnostic::new(Code::SubgroupOfOne, format!("`{name}` is computed for a subgroup of one invocation"))
            .at(s.file, span, "a subgroup of one")
            .with_note("WGSL has subgroups only behind `enable subgroups;`, which naga's WGSL front does not take: the translation computes every subgroup operation as a device whose subgroups hold one invocation does (Vulkan allows it): `gl_SubgroupSize` is 1, reductions and broadcasts are the invocation's own value, a ballot has bit 0")
            .with_help("code that needs several invocations per subgroup (a required subgroup size) draws differently"),
    )
}

fn at_use(d: Diagnostic, s: &StageSyntax, name: &str) -> Diagnostic {
    match s.uses.iter().find(|u| u.name == name) {
        Some(u) => d.at(s.file, u.span.clone(), "read here"),
        None => d.in_file(s.file),
    }
}
