//! GLSL ES 3.00 for WebGL2: one file per stage. naga's GLSL writer maps WebGPU clip space
//! back to GL's, so the output behaves like the input on a GL context.

use naga::valid::ModuleInfo;
use naga::{Module, ShaderStage};

/// GLSL ES 3.00 source of the entry point `entry`.
pub fn write(module: &Module, info: &ModuleInfo, stage: ShaderStage, entry: &str) -> Result<String, String> {
    use naga::back::glsl;
    let options = glsl::Options {
        version: glsl::Version::Embedded { version: 300, is_webgl: true },
        writer_flags: glsl::WriterFlags::ADJUST_COORDINATE_SPACE,
        ..Default::default()
    };
    let pipeline = glsl::PipelineOptions { shader_stage: stage, entry_point: entry.to_string(), multiview: None };
    let mut text = String::new();
    let mut writer = glsl::Writer::new(&mut text, module, info, &options, &pipeline, Default::default())
        .map_err(|e| format!("naga's GLSL writer: {e}"))?;
    writer.write().map_err(|e| format!("naga's GLSL writer: {e}"))?;
    Ok(text)
}
