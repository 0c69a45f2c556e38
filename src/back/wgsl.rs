//! WGSL: one module holding every entry point (`vs_main`, `fs_main`), re-parsed and
//! re-validated by naga's WGSL front before it is handed out.

use naga::valid::ModuleInfo;
use naga::Module;

/// Writes the module as WGSL and proves the text is valid WGSL.
pub fn write(module: &Module, info: &ModuleInfo) -> Result<String, String> {
    let text = naga::back::wgsl::write_string(module, info, naga::back::wgsl::WriterFlags::empty())
        .map_err(|e| format!("naga's WGSL writer: {e}"))?;
    verify(&text)?;
    Ok(text)
}

/// Parses and validates WGSL text with naga's WGSL front.
pub fn verify(text: &str) -> Result<(), String> {
    let module = naga::front::wgsl::parse_str(text)
        .map_err(|e| format!("the emitted WGSL does not parse: {}", e.emit_to_string(text)))?;
    crate::front::naga_run::validator()
        .validate(&module)
        .map_err(|e| format!("the emitted WGSL does not validate: {}", e.emit_to_string(text)))?;
    Ok(())
}
