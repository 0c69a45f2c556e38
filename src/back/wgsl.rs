//! WGSL: one module holding every entry point (`vs_main`, `fs_main`), re-parsed and
//! re-validated by naga's WGSL front before it is handed out.
//!
//! GLSL lets `texture()` and `dFdx()` run in non-uniform control flow (derivatives there
//! are undefined, not an error); WGSL rejects that unless told otherwise. When the module
//! takes implicit derivatives, the output starts with `diagnostic(off, derivative_uniformity);`
//! so it keeps GLSL's meaning and passes every WGSL compiler (tint enforces uniformity).
//! Loads from workgroup memory right after a barrier are written `workgroupUniformLoad`
//! ([`uniform_loads`]), so a barrier behind a branch on them passes that analysis too.

use naga::valid::ModuleInfo;
use naga::Module;

use crate::back::uniform_loads;
use crate::front::plan::UNIFORM_BLOCK;

/// Writes the module as WGSL and proves the text is valid WGSL.
pub fn write(module: &Module, info: &ModuleInfo) -> Result<String, String> {
    if let Some(arrays) = strided_arrays(module) {
        return Err(format!(
            "an array in a uniform buffer whose std140 stride WGSL cannot write ({arrays}) is not supported by WGSL: \
             std140 gives each element of a `float`, `int` or `vec2` array 16 bytes and each `mat2` column 16 bytes, \
             and WGSL packs them (a `vec4` array, read as `.x` or `.xy`, has the same layout)"
        ));
    }
    let uniform = uniform_loads::after_barriers(module).and_then(|m| {
        // The original validated; the rewrite adds no capability need.
        let caps = naga::valid::Capabilities::all();
        naga::valid::Validator::new(naga::valid::ValidationFlags::all(), caps).validate(&m).ok().map(|i| (m, i))
    });
    let (module, info) = uniform.as_ref().map_or((module, info), |(m, i)| (m, i));
    let mut text = naga::back::wgsl::write_string(module, info, naga::back::wgsl::WriterFlags::empty())
        .map_err(|e| format!("naga's WGSL writer: {e}"))?;
    text = exact_largest_f32(text);
    if takes_derivatives(module) {
        text.insert_str(0, "diagnostic(off, derivative_uniformity);\n\n");
    }
    if largest_function(module) <= REPARSED_EXPRESSIONS {
        let reparsed = verify(&text)?;
        same_block_layout(module, &reparsed)?;
    }
    Ok(text)
}

/// naga writes an `f32` literal as Rust prints it, the shortest decimal that reads back as
/// the same float. For the largest finite `f32` that decimal, `3.4028235e38`, lies above
/// the value, and WGSL compilers that range-check a literal before rounding it refuse the
/// text (tint: "value cannot be represented as 'f32'"); GLSL's `FLT_MAX` idioms meet it.
/// The exact hexadecimal literal names the same value.
fn exact_largest_f32(text: String) -> String {
    let written = format!("{}f", f32::MAX);
    if !text.contains(&written) {
        return text;
    }
    let mut out = String::with_capacity(text.len());
    let mut rest = text.as_str();
    while let Some(at) = rest.find(&written) {
        let before = rest[..at].chars().next_back();
        let whole = !before.is_some_and(|c| c.is_ascii_alphanumeric() || c == '_' || c == '.');
        out.push_str(&rest[..at]);
        out.push_str(if whole { "0x1.fffffep+127f" } else { &written });
        rest = &rest[at + written.len()..];
    }
    out.push_str(rest);
    out
}

/// Expressions in one function up to which the emitted WGSL is re-parsed to prove it.
///
/// naga's WGSL front types each new expression by walking the function's expressions from
/// the start again (`Typifier::grow`), so re-parsing grows with the square of a function's
/// size: 1.8 s for a 25,000-statement `main`, where writing it takes 0.1 s. Past this
/// size (~8,000 statements; real functions hold a few hundred expressions) the text is
/// handed out as naga wrote it from the validated IR, unproven by a second parse.
pub const REPARSED_EXPRESSIONS: usize = 32 << 10;

/// The most expressions any function or entry point of `module` holds.
fn largest_function(module: &Module) -> usize {
    crate::back::merge::all_functions(module).map(|f| f.expressions.len()).max().unwrap_or(0)
}

/// The uniform block's offsets in the WGSL text must be the IR's (the reflection's).
fn same_block_layout(ir: &Module, reparsed: &Module) -> Result<(), String> {
    let offsets = |m: &Module| {
        m.types.iter().find(|(_, t)| t.name.as_deref() == Some(UNIFORM_BLOCK)).and_then(|(_, t)| match &t.inner {
            naga::TypeInner::Struct { members, span } => Some((members.iter().map(|m| m.offset).collect::<Vec<_>>(), *span)),
            _ => None,
        })
    };
    if offsets(ir) != offsets(reparsed) {
        return Err(format!(
            "the emitted WGSL lays out {UNIFORM_BLOCK} differently from the IR: {:?} vs {:?}",
            offsets(reparsed),
            offsets(ir)
        ));
    }
    Ok(())
}

/// Parses and validates WGSL text with naga's WGSL front; returns the parsed module.
pub fn verify(text: &str) -> Result<Module, String> {
    let module = naga::front::wgsl::parse_str(text).map_err(|e| format!("the emitted WGSL does not parse: {}", e.emit_to_string(text)))?;
    crate::front::naga_run::validator()
        .validate(&module)
        .map_err(|e| format!("the emitted WGSL does not validate: {}", e.emit_to_string(text)))?;
    Ok(module)
}

/// The uniform-buffer arrays whose stride WGSL cannot write (`` `Light.falloff` (16 bytes
/// apart, WGSL 4) ``, joined): WGSL lays an array's elements out at their own aligned size,
/// and std140 pads some further: a struct's `float` or `vec2` array to 16 bytes an element,
/// a `mat2` array to two 16-byte columns. The uniform block's own arrays are widened to
/// `vec4` by the rewrite, so these are struct members.
fn strided_arrays(module: &Module) -> Option<String> {
    let mut layouter = naga::proc::Layouter::default();
    layouter.update(module.to_ctx()).ok()?;
    let mut found: Vec<String> = Vec::new();
    for ty in crate::front::naga_run::uniform_structs(module, |_| true) {
        let naga::TypeInner::Struct { members, .. } = &module.types[ty].inner else { continue };
        for m in members {
            if let naga::TypeInner::Array { base, stride, .. } = module.types[m.ty].inner {
                let natural = layouter[base].to_stride();
                if natural != stride {
                    let owner = module.types[ty].name.as_deref().unwrap_or("struct");
                    let member = m.name.as_deref().unwrap_or("?");
                    found.push(format!("`{owner}.{member}` ({stride} bytes apart, WGSL {natural})"));
                }
            }
        }
    }
    (!found.is_empty()).then(|| found.join(", "))
}

/// Whether any function samples with implicit derivatives or takes derivatives.
fn takes_derivatives(module: &Module) -> bool {
    crate::back::merge::all_functions(module).any(|f| {
        f.expressions.iter().any(|(_, e)| {
            matches!(
                e,
                naga::Expression::Derivative { .. }
                    | naga::Expression::ImageSample { level: naga::SampleLevel::Auto | naga::SampleLevel::Bias(_), .. }
            )
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn written(wgsl: &str) -> String {
        let module = naga::front::wgsl::parse_str(wgsl).unwrap();
        let info = crate::front::naga_run::validator().validate(&module).unwrap();
        write(&module, &info).unwrap()
    }

    #[test]
    fn the_largest_f32_is_written_exactly() {
        let text = written(
            "@fragment fn main(@location(0) x: f32) -> @location(0) vec4<f32> {\n\
             let big = select(0.0, 1.0, x == 3.40282347e38 || x == -3.40282347e38);\n\
             return vec4<f32>(big);\n}\n",
        );
        assert!(!text.contains(&f32::MAX.to_string()), "{text}");
        assert!(text.contains("== 0x1.fffffep+127f"), "{text}");
        assert!(text.contains("-0x1.fffffep+127f"), "{text}");
        // It reads back as the same value.
        let reparsed = verify(&text).unwrap();
        let literals: Vec<f32> = reparsed
            .entry_points
            .iter()
            .flat_map(|e| e.function.expressions.iter())
            .filter_map(|(_, e)| match e {
                naga::Expression::Literal(naga::Literal::F32(v)) => Some(v.abs()),
                _ => None,
            })
            .collect();
        assert!(literals.contains(&f32::MAX), "{literals:?}");
    }

    /// std140 lays out a struct's `float` array 16 bytes an element; WGSL cannot write that
    /// stride, and says so by naming the member (not as an internal error).
    #[test]
    fn a_struct_float_array_in_a_uniform_block_is_named_as_beyond_wgsl() {
        let glsl = "#version 450\nstruct Light { vec4 colour; float falloff[3]; };\n\
                    layout(std140, binding = 0) uniform Lights { Light light; vec4 tint[2]; };\n\
                    layout(location = 0) out vec4 color;\n\
                    void main() { color = vec4(light.falloff[2]) + light.colour + tint[1]; }\n";
        let options = naga::front::glsl::Options::from(naga::ShaderStage::Fragment);
        let module = naga::front::glsl::Frontend::default().parse(&options, glsl).unwrap();
        let (info, _) = crate::front::naga_run::validate_for_gl(&module).unwrap();
        let error = write(&module, &info).unwrap_err();
        assert!(error.contains("(`Light.falloff` (16 bytes apart, WGSL 4)) is not supported by WGSL"), "{error}");
        assert!(!error.contains("tint"), "a vec4 array's stride is its own: {error}");
    }

    /// std140 lays out a `mat2` array 32 bytes an element; WGSL's `mat2x2` is 16 bytes (the
    /// fronts refuse such arrays first: this is the writer's own guard).
    #[test]
    fn a_mat2_array_in_a_uniform_block_is_named_as_beyond_wgsl() {
        let wgsl = "struct S2 { v2: vec4<f32>, m22: array<mat2x2<f32>, 2> }\n\
                    @group(0) @binding(0) var<uniform> s: S2;\n\
                    @fragment fn main() -> @location(0) vec4<f32> { return vec4<f32>(s.m22[1][1], s.v2.xy); }\n";
        let mut module = naga::front::wgsl::parse_str(wgsl).unwrap();
        let info = crate::front::naga_run::validator().validate(&module).unwrap();
        let arrays: Vec<_> =
            module.types.iter().filter(|(_, t)| matches!(t.inner, naga::TypeInner::Array { .. })).map(|(h, _)| h).collect();
        for h in arrays {
            let mut ty = module.types[h].clone();
            if let naga::TypeInner::Array { stride, .. } = &mut ty.inner {
                *stride = 32;
            }
            module.types.replace(h, ty);
        }
        let error = write(&module, &info).unwrap_err();
        assert!(error.contains("(`S2.m22` (32 bytes apart, WGSL 16)) is not supported by WGSL"), "{error}");
    }

    #[test]
    fn other_literals_are_left_as_naga_wrote_them() {
        assert_eq!(
            exact_largest_f32("x == 1340282350000000000000000000000000000000f".into()),
            "x == 1340282350000000000000000000000000000000f"
        );
        assert_eq!(exact_largest_f32("a = 2.5f;".into()), "a = 2.5f;");
    }
}
