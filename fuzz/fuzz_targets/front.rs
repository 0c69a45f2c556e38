//! One fragment stage through the whole front (version, conditionals, masks, glsl-lang,
//! rewrite, naga parse + validate): diagnostics, never a panic; they all render.
#![no_main]
use effectc::diag::{render_human, Files};
use effectc::front::program::{compile, FrontOptions};
use effectc::stage::StageKind;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let mut files = Files::new();
    let id = files.add("fuzz.frag", text);
    let mut diags = Vec::new();
    let _ = compile(&files, &[(id, StageKind::Fragment)], FrontOptions::default(), &mut diags);
    let _ = render_human(&diags, &files, false);
});
