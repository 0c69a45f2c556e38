//! `check` of a two-stage program: the input is a vertex and a fragment stage separated by
//! a line `//--`. Front, link rules and hazards run; diagnostics, never a panic.
#![no_main]
use effectc::check::check_stages;
use effectc::diag::{render_human, render_json, Files};
use effectc::front::program::FrontOptions;
use effectc::stage::StageKind;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let (vert, frag) = text.split_once("\n//--\n").unwrap_or((text, "#version 330\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n"));
    let mut files = Files::new();
    let v = files.add("fuzz.vert", vert);
    let f = files.add("fuzz.frag", frag);
    let (_, diags) = check_stages(&files, &[(v, StageKind::Vertex), (f, StageKind::Fragment)], None, FrontOptions::default());
    let _ = render_human(&diags, &files, false);
    let _ = render_json(&diags, &files);
});
