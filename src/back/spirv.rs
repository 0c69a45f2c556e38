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
    if module.overrides.is_empty() {
        return naga::back::spv::write_vec(module, info, &options(), Some(&pipeline)).map_err(|e| format!("naga's SPIR-V writer: {e}"));
    }
    let (module, info) = naga::back::pipeline_constants::process_overrides(module, info, Some((stage, entry)), &Default::default())
        .map_err(|e| format!("specialization constants cannot take their defaults: {e}"))?;
    naga::back::spv::write_vec(&module, &info, &options(), Some(&pipeline)).map_err(|e| format!("naga's SPIR-V writer: {e}"))
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
