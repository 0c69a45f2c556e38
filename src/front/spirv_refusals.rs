//! Why the route through SPIR-V did not take a stage, and, where naga's SPIR-V front
//! refused what glslang wrote for a GLSL construct, that construct in the user's words
//! and at the user's line: `imageAtomicAdd` is `OpImageTexelPointer` into an image, which
//! naga reports as "unsupported storage class %11". Where both routes fail, `translate`
//! names this construct (the route through SPIR-V takes more than naga's GLSL front: what
//! stopped it is what stops the translation), not what stopped naga's GLSL front first.

use naga::front::spv::Error;
use rspirv::spirv::{Capability, Op, StorageClass};

use crate::front::limitation::Limitation;
use crate::front::reference::log::LineTable;
use crate::front::spirv_binary::{instructions, Lines};
use crate::stage::StageKind;

/// Why the route through SPIR-V did not take a program.
#[derive(Debug, Clone)]
pub struct Refusal {
    /// The first thing that failed, in words (for `EFFECTC_DUMP_REFERENCE`).
    pub message: String,
    /// The construct naga's SPIR-V front refused in a stage, spans in that stage's text.
    pub construct: Option<(StageKind, Limitation)>,
}

impl From<String> for Refusal {
    fn from(message: String) -> Self {
        Refusal { message, construct: None }
    }
}

impl std::fmt::Display for Refusal {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

/// naga's SPIR-V front's `error` on `words` (a `kind` stage compiled from `text`) as a
/// refusal naming the construct where it knows it.
pub(crate) fn refusal(error: &Error, words: &[u32], kind: StageKind, text: &str) -> Refusal {
    let message = format!("naga's SPIR-V front cannot read the {kind} stage: {error}");
    let Some((construct, op)) = construct_of(error) else { return message.into() };
    let span = op.and_then(|op| first_line_of(words, op, text));
    Refusal { message, construct: Some((kind, Limitation { construct, span })) }
}

/// The GLSL construct behind a refusal, and the instruction that carries it.
fn construct_of(error: &Error) -> Option<(String, Option<Op>)> {
    const IMAGE_ATOMICS: &str =
        "image atomics (`imageAtomicAdd` and the other `imageAtomic…` functions: WGSL has atomics in buffers and workgroup memory only)";
    // naga reads SPIR-V with a newer `spirv` crate than rspirv's: the same numbers.
    let op = |op: u32| Op::from_u32(op);
    Some(match *error {
        Error::UnsupportedStorageClass(c) if c == StorageClass::Image as u32 => (IMAGE_ATOMICS.into(), Some(Op::ImageTexelPointer)),
        Error::UnsupportedInstruction(_, o) if op(o as u32) == Some(Op::ImageTexelPointer) => {
            (IMAGE_ATOMICS.into(), Some(Op::ImageTexelPointer))
        }
        Error::UnsupportedStorageClass(c) if c == StorageClass::PhysicalStorageBuffer as u32 => {
            ("buffer references (GL_EXT_buffer_reference: pointers into device memory)".into(), None)
        }
        Error::UnsupportedCapability(c) => (capability(Capability::from_u32(c as u32)?), None),
        Error::UnsupportedExtension(ref name) => (extension(name), None),
        // A constant of an integer type naga has no literal for (the width in bytes).
        Error::InvalidTypeWidth(1) => (capability(Capability::Int8), None),
        Error::InvalidTypeWidth(2) => {
            ("16-bit integers (`uint16_t`, `int16_t`, GL_EXT_shader_explicit_arithmetic_types: WGSL has none)".into(), None)
        }
        Error::UnsupportedInstruction(_, o) if op(o as u32) == Some(Op::SpecConstantOp) => {
            ("an expression of specialization constants (`OpSpecConstantOp`) naga does not read".into(), None)
        }
        Error::UnsupportedInstruction(_, o) => (format!("what glslang writes as `Op{o:?}`"), op(o as u32)),
        _ => return None,
    })
}

/// A SPIR-V extension naga does not read, as the GLSL feature that makes glslang declare it.
fn extension(name: &str) -> String {
    let c = match name {
        "SPV_KHR_physical_storage_buffer" | "SPV_EXT_physical_storage_buffer" => {
            return "buffer references (GL_EXT_buffer_reference: pointers into device memory)".into()
        }
        "SPV_KHR_8bit_storage" => Capability::StorageBuffer8BitAccess,
        "SPV_KHR_16bit_storage" => Capability::StorageBuffer16BitAccess,
        "SPV_KHR_ray_query" => Capability::RayQueryKHR,
        "SPV_EXT_shader_stencil_export" => Capability::StencilExportEXT,
        other => return format!("what needs the SPIR-V extension `{other}`"),
    };
    capability(c)
}

fn capability(c: Capability) -> String {
    use Capability as C;
    match c {
        C::Int8 | C::StorageBuffer8BitAccess | C::UniformAndStorageBuffer8BitAccess | C::StoragePushConstant8 => {
            "8-bit integers (GL_EXT_shader_8bit_storage, GL_EXT_shader_explicit_arithmetic_types)".into()
        }
        C::Int16
        | C::Float16
        | C::StorageBuffer16BitAccess
        | C::UniformAndStorageBuffer16BitAccess
        | C::StoragePushConstant16
        | C::StorageInputOutput16 => "16-bit types (GL_EXT_shader_16bit_storage, GL_EXT_shader_explicit_arithmetic_types)".into(),
        C::RayQueryKHR => "ray queries (GL_EXT_ray_query)".into(),
        C::StencilExportEXT => "`gl_FragStencilRefARB` (GL_ARB_shader_stencil_export: WebGPU has no stencil export)".into(),
        other => format!("what needs the SPIR-V capability `{other:?}`"),
    }
}

/// The user's line of the first `op` instruction of `words` (by its `OpLine`).
fn first_line_of(words: &[u32], op: Op, text: &str) -> Option<std::ops::Range<usize>> {
    let (at, _, _) = instructions(words).find(|(_, o, _)| *o == op as u16)?;
    let span = Lines::of(words).binary_user_span(at * 4, &LineTable::new(text), text);
    span.to_range()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refusals_name_the_glsl_construct() {
        let atomics = construct_of(&Error::UnsupportedStorageClass(StorageClass::Image as u32)).unwrap();
        assert!(atomics.0.starts_with("image atomics") && atomics.1 == Some(Op::ImageTexelPointer));
        assert!(construct_of(&Error::UnsupportedCapability(naga::back::spv::Capability::StorageBuffer8BitAccess))
            .unwrap()
            .0
            .starts_with("8-bit integers"));
        let extension = |name: &str| construct_of(&Error::UnsupportedExtension(name.into())).unwrap().0;
        assert!(extension("SPV_KHR_physical_storage_buffer").starts_with("buffer references"));
        assert!(extension("SPV_KHR_8bit_storage").starts_with("8-bit integers"));
        assert!(extension("SPV_KHR_16bit_storage").starts_with("16-bit types"));
        assert_eq!(extension("SPV_NV_made_up"), "what needs the SPIR-V extension `SPV_NV_made_up`");
        assert!(construct_of(&Error::InvalidTypeWidth(2)).unwrap().0.starts_with("16-bit integers"));
        assert!(construct_of(&Error::InvalidHeader).is_none());
        let r = refusal(
            &Error::UnsupportedCapability(naga::back::spv::Capability::RayQueryKHR),
            &[0x0723_0203, 0x10000, 0, 1, 0],
            StageKind::Compute,
            "",
        );
        assert_eq!(r.construct.map(|(k, l)| (k, l.construct)), Some((StageKind::Compute, "ray queries (GL_EXT_ray_query)".to_string())));
        assert!(r.message.contains("cannot read the compute stage"), "{}", r.message);
    }
}
