//! Runs naga's GLSL front and validator on rewritten text, mapping errors to the user's file.
//!
//! naga can panic on some inputs; every call here is wrapped in `catch_unwind`, and a panic
//! becomes an error diagnostic instead of taking the process down.
//!
//! `check` asks whether the program is legal GLSL, not whether WebGPU can run it, so a
//! stage is validated with every capability desktop GL has ([`gl_capabilities`]); the
//! capabilities WebGPU lacks are recorded ([`Validated::needs`]) for `translate` to refuse
//! with E0306. An error naga reports on a construct the GLSL specification allows (a
//! built-in naga does not know, a qualifier its parser does not take) is a
//! [`Limitation`], not an error in the user's program.

use std::panic::{catch_unwind, AssertUnwindSafe};

use naga::front::glsl::ErrorKind;
use naga::valid::Capabilities;

use crate::diag::{Code, Diagnostic, FileId};
use crate::front::builtins;
pub use crate::front::limitation::Limitation;
use crate::front::rewrite::Rewritten;
use crate::front::version::Version;

/// A naga module that passed validation, with its analysis.
#[derive(Debug)]
pub struct Validated {
    pub module: naga::Module,
    pub info: naga::valid::ModuleInfo,
    /// Capabilities beyond WebGPU's defaults the module needs (e.g. `PRIMITIVE_INDEX` for
    /// `gl_PrimitiveID`), by name; empty when WebGPU can run it as is.
    pub needs: Vec<String>,
}

/// What naga made of one stage.
#[derive(Debug)]
pub enum Outcome {
    Valid(Validated),
    Limited(Limitation),
    Invalid(Vec<Diagnostic>),
}

/// The validator every backend output goes through: all checks, WebGPU capabilities and
/// the optional features a translation may enable ([`webgpu_optional_capabilities`]).
pub fn validator() -> naga::valid::Validator {
    naga::valid::Validator::new(naga::valid::ValidationFlags::all(), webgpu_capabilities() | webgpu_optional_capabilities())
}

/// WebGPU's optional features a translation may use: the output enables them (`enable
/// primitive_index;`, `enable dual_source_blending;`, `enable f16;`) and the front says so
/// (N0109); `render` asks the device for them.
pub fn webgpu_optional_capabilities() -> Capabilities {
    Capabilities::PRIMITIVE_INDEX | Capabilities::DUAL_SOURCE_BLENDING | Capabilities::SHADER_FLOAT16
}

/// What every WebGPU implementation has: naga's defaults plus the half-float packing
/// built-ins (`pack2x16float`/`unpack2x16float`/`quantizeToF16` are core WGSL; naga gates
/// them behind a capability wgpu grants on every backend).
pub fn webgpu_capabilities() -> Capabilities {
    Capabilities::default() | Capabilities::SHADER_FLOAT16_IN_FLOAT32
}

/// Capabilities a desktop GL 4.6 implementation has that WebGPU's defaults lack.
pub fn gl_capabilities() -> Capabilities {
    webgpu_capabilities()
        | Capabilities::IMMEDIATES
        | Capabilities::FLOAT64
        | Capabilities::PRIMITIVE_INDEX
        | Capabilities::CLIP_DISTANCES
        | Capabilities::CULL_DISTANCE
        | Capabilities::MULTIVIEW
        | Capabilities::EARLY_DEPTH_TEST
        | Capabilities::MULTISAMPLED_SHADING
        | Capabilities::DUAL_SOURCE_BLENDING
        | Capabilities::CUBE_ARRAY_TEXTURES
        | Capabilities::SHADER_INT64
        | Capabilities::TEXTURE_AND_SAMPLER_BINDING_ARRAY
        | Capabilities::BUFFER_BINDING_ARRAY
        | Capabilities::STORAGE_TEXTURE_BINDING_ARRAY
        | Capabilities::STORAGE_BUFFER_BINDING_ARRAY
        | Capabilities::TEXTURE_AND_SAMPLER_BINDING_ARRAY_NON_UNIFORM_INDEXING
        | Capabilities::BUFFER_BINDING_ARRAY_NON_UNIFORM_INDEXING
        | Capabilities::STORAGE_TEXTURE_BINDING_ARRAY_NON_UNIFORM_INDEXING
        | Capabilities::STORAGE_BUFFER_BINDING_ARRAY_NON_UNIFORM_INDEXING
        | Capabilities::SHADER_FLOAT16
        | Capabilities::SHADER_INT16
        | Capabilities::DRAW_INDEX
}

/// The capabilities of [`gl_capabilities`] beyond WebGPU's defaults that `module`, which
/// WebGPU's defaults do not validate, needs.
fn needed_beyond_webgpu(module: &naga::Module) -> Vec<String> {
    let extra = gl_capabilities() - webgpu_capabilities();
    extra.iter_names().filter(|(_, cap)| !valid_with(module, gl_capabilities() - *cap)).map(|(name, _)| name.to_string()).collect()
}

fn valid_with(module: &naga::Module, caps: Capabilities) -> bool {
    catch_unwind(AssertUnwindSafe(|| naga::valid::Validator::new(naga::valid::ValidationFlags::all(), caps).validate(module).is_ok()))
        .unwrap_or(false)
}

/// naga's validation with desktop GL's capabilities ([`gl_capabilities`]) and the ones
/// beyond WebGPU's that the module needs. Most modules need none: WebGPU's defaults are
/// tried first, and their analysis is the GL one (capabilities only decide what is
/// refused), so such a module is validated once.
pub fn validate_for_gl(
    module: &naga::Module,
) -> Result<(naga::valid::ModuleInfo, Vec<String>), naga::WithSpan<naga::valid::ValidationError>> {
    if let Ok(info) = naga::valid::Validator::new(naga::valid::ValidationFlags::all(), webgpu_capabilities()).validate(module) {
        return Ok((info, Vec::new()));
    }
    let info = naga::valid::Validator::new(naga::valid::ValidationFlags::all(), gl_capabilities()).validate(module)?;
    Ok((info, needed_beyond_webgpu(module)))
}

/// Whether naga's error is about a construct GLSL allows (a naga limitation). The text
/// already passed glsl-lang's full GLSL grammar, so a naga syntax error is a limitation.
fn limitation(kind: &ErrorKind, version: &Version) -> Option<String> {
    // Conservative: naga's syntax errors, unexpected qualifiers and preprocessor errors stay
    // errors (glsl-lang's grammar is looser than GLSL in places, so they can be real).
    Some(match kind {
        ErrorKind::NotImplemented(what) => format!("{what} (not implemented in naga)"),
        ErrorKind::UnknownLayoutQualifier(q) if builtins::is_layout_qualifier(q) => format!("`layout({q})`"),
        ErrorKind::UnsupportedMatrixWithTwoRowsInStd140 { columns } => {
            format!("`mat{columns}x2` in a std140 block (naga issue gfx-rs/wgpu#4375)")
        }
        ErrorKind::UnknownVariable(name) if builtins::is_variable_naga_lacks(name, version) => {
            format!("the built-in `{name}`")
        }
        ErrorKind::UnknownType(name) if builtins::is_type(name) => format!("the type `{name}`"),
        ErrorKind::SemanticError(msg) if msg.contains("override-expression") => {
            "a specialization constant where naga needs a constant (an array size)".to_string()
        }
        ErrorKind::SemanticError(msg) => {
            let name = msg.strip_prefix("Unknown function '").and_then(|r| r.strip_suffix('\''));
            match name {
                Some(f) if builtins::is_function_naga_lacks(f) => format!("the built-in function `{f}`"),
                _ => return None,
            }
        }
        ErrorKind::InternalError(what) => format!("this code (naga internal error: {what})"),
        _ => return None,
    })
}

/// The text of a caught panic.
pub(crate) fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        s.to_string()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "unknown panic".to_string()
    }
}

/// std140/std430 lay out every legal block; naga's layout rules for the uniform and storage
/// address spaces (WGSL's) reject some of them (a `bool` or a `float[N]` inside a struct).
/// That is naga's limitation, not an error in the program.
fn layout_limitation(module: &naga::Module, err: &naga::valid::ValidationError) -> Option<String> {
    if let naga::valid::ValidationError::Type { source: naga::valid::TypeError::InvalidArrayBaseType(base), .. } = err {
        // `uniform sampler s[3];`, `uniform texture2D t[2];`: GLSL arrays of opaque
        // handles, which naga's GLSL front types as plain arrays (binding arrays elsewhere).
        let opaque = matches!(
            module.types[*base].inner,
            naga::TypeInner::Image { .. } | naga::TypeInner::Sampler { .. } | naga::TypeInner::AccelerationStructure { .. }
        );
        return opaque.then(|| "an array of textures or samplers (naga's GLSL front has no binding arrays)".to_string());
    }
    let naga::valid::ValidationError::GlobalVariable { handle, source, .. } = err else { return None };
    match source {
        naga::valid::GlobalVariableError::Alignment(..) | naga::valid::GlobalVariableError::InvalidType(..) => {
            let var = &module.global_variables[*handle];
            let ty = module.types[var.ty].name.clone().unwrap_or_else(|| "a uniform block".into());
            Some(format!("the std140/std430 layout of `{ty}` (naga's uniform/storage layout rules differ: {source})"))
        }
        _ => None,
    }
}

/// Every struct type reachable from a uniform buffer whose own type `root` accepts (through
/// struct members and array elements), each once.
pub fn uniform_structs(module: &naga::Module, root: impl Fn(&naga::Type) -> bool) -> Vec<naga::Handle<naga::Type>> {
    let mut todo: Vec<naga::Handle<naga::Type>> = module
        .global_variables
        .iter()
        .filter(|(_, g)| g.space == naga::AddressSpace::Uniform && root(&module.types[g.ty]))
        .map(|(_, g)| g.ty)
        .collect();
    let mut seen = std::collections::HashSet::new();
    let mut structs = Vec::new();
    while let Some(ty) = todo.pop() {
        if !seen.insert(ty) {
            continue;
        }
        match &module.types[ty].inner {
            naga::TypeInner::Struct { members, .. } => {
                todo.extend(members.iter().map(|m| m.ty));
                structs.push(ty);
            }
            naga::TypeInner::Array { base, .. } | naga::TypeInner::BindingArray { base, .. } => todo.push(*base),
            _ => {}
        }
    }
    structs
}

/// A two-row matrix (`mat2`, `mat3x2`, `mat4x2`) in one of the user's uniform blocks, named
/// with the struct holding it. std140 puts its columns 16 bytes apart, which naga's IR
/// cannot say (its `mat2x2` columns are 8 bytes apart). naga's fronts refuse such a matrix
/// as a struct member themselves, but naga's SPIR-V front takes an array of them (`mat2
/// m[2]`, std140 stride 32) as an array of its own 16-byte matrices: every target would
/// then read the block's bytes wrongly. effectc's own block of loose uniforms is laid out
/// by the IR itself and is not concerned.
pub fn std140_two_row_matrix(module: &naga::Module) -> Option<String> {
    let user = |t: &naga::Type| t.name.as_deref() != Some(crate::front::plan::UNIFORM_BLOCK);
    uniform_structs(module, user).into_iter().find_map(|owner| {
        let naga::TypeInner::Struct { members, .. } = &module.types[owner].inner else { return None };
        members.iter().find_map(|m| {
            let mut ty = m.ty;
            while let naga::TypeInner::Array { base, .. } = module.types[ty].inner {
                ty = base;
            }
            let naga::TypeInner::Matrix { columns, rows: naga::VectorSize::Bi, .. } = module.types[ty].inner else { return None };
            let name = module.types[owner].name.as_deref().unwrap_or("a uniform block");
            Some(format!("`mat{}x2` in `{name}`, a std140 uniform block (naga issue gfx-rs/wgpu#4375)", columns as u8))
        })
    })
}

/// Indices into `s.swizzles` of the accesses naga's `errors` (E0150, at the user's spans)
/// report as field lookups on a type that has no fields: scalar bases, as naga has no
/// scalar swizzles.
pub fn scalar_swizzles(s: &crate::front::syntax::StageSyntax, errors: &[Diagnostic]) -> Vec<usize> {
    errors
        .iter()
        .filter(|d| d.code == Code::NagaParse && d.message.starts_with("Can't lookup field on this type"))
        .filter_map(|d| d.span.clone())
        .filter_map(|span| s.swizzles.iter().position(|w| w.whole.end == span.end || (w.base.end <= span.start && span.end <= w.whole.end)))
        .collect()
}

/// Parses and validates one rewritten stage.
pub fn parse_and_validate(file: FileId, rewritten: &Rewritten, stage: naga::ShaderStage, version: &Version) -> Outcome {
    match parse_and_validate_inner(file, rewritten, stage, version) {
        Ok(v) => Outcome::Valid(v),
        Err(Ok(limit)) => Outcome::Limited(limit),
        Err(Err(diags)) => Outcome::Invalid(diags),
    }
}

type Failure = Result<Limitation, Vec<Diagnostic>>;

fn parse_and_validate_inner(
    file: FileId,
    rewritten: &Rewritten,
    stage: naga::ShaderStage,
    version: &Version,
) -> Result<Validated, Failure> {
    let quiet = crate::front::lexical::quiet_pragmas(&rewritten.text);
    let quiet = crate::front::lexical::blank_line_directives(&quiet).into_owned();
    let text: &str = &quiet;
    let map_span = |span: naga::Span| span.to_range().map(|r| rewritten.map.range_to_original(r));
    let parsed = catch_unwind(AssertUnwindSafe(|| {
        let mut frontend = naga::front::glsl::Frontend::default();
        frontend.parse(&naga::front::glsl::Options::from(stage), text)
    }));
    let mut module = match parsed {
        Ok(Ok(m)) => m,
        Ok(Err(errors)) => {
            // A genuine error anywhere in the stage wins over naga's limitations.
            let genuine = errors.errors.iter().any(|e| limitation(&e.kind, version).is_none());
            if !genuine {
                if let Some(e) = errors.errors.first() {
                    let construct = limitation(&e.kind, version).unwrap_or_default();
                    return Err(Ok(Limitation { construct, span: map_span(e.meta) }));
                }
            }
            return Err(Err(errors
                .errors
                .iter()
                .filter(|e| limitation(&e.kind, version).is_none())
                .map(|e| {
                    let d = Diagnostic::new(Code::NagaParse, e.kind.to_string());
                    match map_span(e.meta) {
                        Some(span) => d.at(file, span, "naga's GLSL front rejects this"),
                        None => d.in_file(file),
                    }
                })
                .collect()));
        }
        Err(payload) => return Err(Err(vec![crash(file, "GLSL front", &*payload)])),
    };
    crate::front::function_order::callees_first(&mut module);
    write_only_storage_as_read_write(&mut module);
    let validated = catch_unwind(AssertUnwindSafe(|| validate_for_gl(&module)));
    match validated {
        Ok(Ok((info, needs))) => Ok(Validated { module, info, needs }),
        Ok(Err(err)) => match layout_limitation(&module, err.as_inner()) {
            Some(construct) => Err(Ok(Limitation { construct, span: err.spans().next().and_then(|(s, _)| map_span(*s)) })),
            None => Err(Err(vec![validation_diagnostic(file, &err, &map_span)])),
        },
        Err(payload) => Err(Err(vec![crash(file, "validator", &*payload)])),
    }
}

/// A `writeonly` storage buffer (SPIR-V `NonReadable`) declared `read_write`: WGSL's storage
/// buffers are `read` or `read_write`, and naga refuses one that is store-only; the stores are
/// the same.
pub fn write_only_storage_as_read_write(module: &mut naga::Module) {
    for (_, g) in module.global_variables.iter_mut() {
        if let naga::AddressSpace::Storage { access } = &mut g.space {
            if access.contains(naga::StorageAccess::STORE) && !access.contains(naga::StorageAccess::LOAD) {
                *access |= naga::StorageAccess::LOAD;
            }
        }
    }
}

fn crash(file: FileId, part: &str, payload: &(dyn std::any::Any + Send)) -> Diagnostic {
    Diagnostic::new(Code::NagaCrashed, format!("naga's {part} crashed on this file"))
        .in_file(file)
        .with_note(format!("panic: {}", panic_message(payload)))
        .with_note("this is a bug in naga; effectc contained it. Please report the input")
}

/// A validation error with the whole chain of causes and every span naga attached.
pub fn validation_diagnostic<E: std::error::Error>(
    file: FileId,
    err: &naga::WithSpan<E>,
    map_span: &dyn Fn(naga::Span) -> Option<std::ops::Range<usize>>,
) -> Diagnostic {
    let inner = err.as_inner();
    let mut message = inner.to_string();
    let mut source = inner.source();
    let mut notes = Vec::new();
    while let Some(s) = source {
        notes.push(s.to_string());
        source = s.source();
    }
    if let Some(first) = notes.first() {
        message = format!("{message}: {first}");
        notes.remove(0);
    }
    let mut d = Diagnostic::new(Code::NagaValidation, format!("naga validation: {message}"));
    let mut spans = err.spans().filter_map(|(span, label)| map_span(*span).map(|r| (r, label.clone())));
    match spans.next() {
        Some((r, label)) => {
            d = d.at(file, r, label);
            for (r, label) in spans {
                d = d.with_label(file, r, label);
            }
        }
        None => d = d.in_file(file),
    }
    for n in notes {
        d = d.with_note(n);
    }
    d
}
