//! SPIR-V: one binary per stage (`<effect>.vert.spv`, `<effect>.frag.spv`), each holding
//! that stage's entry point, for Vulkan 1.0 (SPIR-V 1.0). Clip space follows Vulkan (naga
//! flips y, as for WGSL input). `spvasm` is rspirv's disassembly of the same words.

use naga::valid::ModuleInfo;
use naga::{Module, ShaderStage};

fn options() -> naga::back::spv::Options<'static> {
    use naga::back::spv::WriterFlags;
    naga::back::spv::Options {
        lang_version: (1, 0),
        // Fixed flags: the default adds debug info in debug builds, and output must not
        // depend on how effectc was built.
        flags: WriterFlags::ADJUST_COORDINATE_SPACE | WriterFlags::LABEL_VARYINGS | WriterFlags::CLAMP_FRAG_DEPTH,
        ..Default::default()
    }
}

/// SPIR-V words of the entry point `entry` of `stage`. naga's SPIR-V writer has no
/// specialization constants: overrides (`layout(constant_id = N) const`) are fixed at their
/// defaults first (WGSL keeps them as `override`s).
pub fn write(module: &Module, info: &ModuleInfo, stage: ShaderStage, entry: &str) -> Result<Vec<u32>, String> {
    let pipeline = naga::back::spv::PipelineOptions { shader_stage: stage, entry_point: entry.to_string() };
    let written = if module.overrides.is_empty() {
        naga::back::spv::write_vec(module, info, &options(), Some(&pipeline))
    } else {
        let (module, info) = naga::back::pipeline_constants::process_overrides(module, info, Some((stage, entry)), &Default::default())
            .map_err(|e| format!("specialization constants cannot take their defaults: {e}"))?;
        naga::back::spv::write_vec(&module, &info, &options(), Some(&pipeline))
    };
    written.map(image_sizes_without_levels).map_err(|e| format!("naga's SPIR-V writer: {e}"))
}

/// naga's SPIR-V writer (30) asks every arrayed image's layer count with
/// `OpImageQuerySizeLod`, which only sampled, single-sampled images take
/// (VUID-StandaloneSpirv-OpImageQuerySizeLod-04659): `imageSize` of an `image2DArray` gave
/// SPIR-V that spirv-val refuses. For storage and multisampled images the query becomes
/// `OpImageQuerySize`, the same result without a level.
fn image_sizes_without_levels(words: Vec<u32>) -> Vec<u32> {
    use crate::front::spirv_binary::{has_result_type, instructions, HEADER_WORDS, OP_TYPE_IMAGE};
    use rspirv::spirv::Op;
    const SIZE_LOD: u16 = Op::ImageQuerySizeLod as u16;
    const SIZE: u16 = Op::ImageQuerySize as u16;
    if !instructions(&words).any(|(_, op, _)| op == SIZE_LOD) {
        return words;
    }
    // OpTypeImage %id %sampled-type Dim Depth Arrayed MS Sampled Format: MS = 1 or Sampled = 2.
    let mut levelless: Vec<u32> = Vec::new();
    let mut type_of: std::collections::HashMap<u32, u32> = std::collections::HashMap::new();
    for (at, op, count) in instructions(&words) {
        let w = &words[at..(at + count.max(1)).min(words.len())];
        match op {
            OP_TYPE_IMAGE if w.len() >= 9 && (w[6] == 1 || w[7] == 2) => levelless.push(w[1]),
            _ if has_result_type(op) && w.len() >= 3 => {
                type_of.insert(w[2], w[1]);
            }
            _ => {}
        }
    }
    let mut out = Vec::with_capacity(words.len());
    out.extend_from_slice(&words[..HEADER_WORDS]);
    for (at, op, count) in instructions(&words) {
        let w = &words[at..(at + count.max(1)).min(words.len())];
        if op == SIZE_LOD && w.len() == 5 && type_of.get(&w[3]).is_some_and(|t| levelless.contains(t)) {
            out.extend_from_slice(&[(4 << 16) | u32::from(SIZE), w[1], w[2], w[3]]);
        } else {
            out.extend_from_slice(w);
        }
    }
    out
}

/// Little-endian bytes of SPIR-V words (the `.spv` file).
pub fn to_bytes(words: &[u32]) -> Vec<u8> {
    words.iter().flat_map(|w| w.to_le_bytes()).collect()
}

/// Text disassembly of SPIR-V words.
pub fn disassemble(words: &[u32]) -> Result<String, String> {
    use rspirv::binary::Disassemble;
    let module = rspirv::dr::load_words(words).map_err(|e| format!("rspirv cannot load the SPIR-V: {e}"))?;
    let mut text = module.disassemble();
    text.push('\n');
    Ok(text)
}
