//! Metal Shading Language 2.0: one file holding every entry point.

use naga::valid::ModuleInfo;
use naga::Module;

pub fn write(module: &Module, info: &ModuleInfo) -> Result<String, String> {
    let options = naga::back::msl::Options { lang_version: (2, 0), ..Default::default() };
    naga::back::msl::write_string(module, info, &options, &naga::back::msl::PipelineOptions::default())
        .map(|(text, _)| text)
        .map_err(|e| format!("naga's MSL writer: {e}"))
}
