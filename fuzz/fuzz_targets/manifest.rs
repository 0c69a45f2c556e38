//! The effect manifest parser on arbitrary text: diagnostics, never a panic; every
//! diagnostic renders (its spans lie inside the file).
#![no_main]
use effectc::diag::{render_human, Files};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let mut files = Files::new();
    let file = files.add("effect.toml", text);
    if let Err(diags) = effectc::manifest::parse(text, file, std::path::Path::new("/nonexistent-effect-dir")) {
        let _ = render_human(&diags, &files, false);
    }
});
