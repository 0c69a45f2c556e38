//! HLSL (shader model 5.1): one file holding every entry point.

use naga::valid::ModuleInfo;
use naga::Module;

pub fn write(module: &Module, info: &ModuleInfo) -> Result<String, String> {
    let options = naga::back::hlsl::Options::default();
    let pipeline = naga::back::hlsl::PipelineOptions::default();
    let mut text = String::new();
    naga::back::hlsl::Writer::new(&mut text, &options, &pipeline)
        .write(module, info, None)
        .map_err(|e| format!("naga's HLSL writer: {e}"))?;
    Ok(text)
}
