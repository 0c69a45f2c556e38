//! effectc: a shader toolchain for desktop-GLSL effects.
//!
//! # Steps
//! 1. [`inputs`]: command-line paths → programs (manifests, directories, stage files);
//!    [`front::includes`] inlines `#include`d files into a stage, with the map back to each file.
//! 2. [`manifest`]: `effect.toml` → [`manifest::Effect`] (stages, uniform defaults, textures, mesh).
//! 3. [`front`]: each GLSL stage → syntax facts (glsl-lang, spans) → GLSL 4.50 rewrite with an
//!    offset map → naga parse + validate.
//! 4. [`link`]: cross-stage interface checks by OpenGL link rules; manifest ↔ shader uniforms.
//! 5. [`check`]: all of the above per program, one bad program never stopping the others.
//!    Multi-pass effects are checked pass by pass, then as a [`graph`] of passes and targets
//!    (`link::passes`).
//! 6. [`back`]: a clean program's stage modules → one merged, fixed, pruned module →
//!    WGSL, SPIR-V, GLSL ES, MSL, HLSL, reflection; [`translate`] writes them (per pass, for
//!    the passes that reach the output).
//! 7. [`render`]: wgpu headless: scenes, targets, frames, pass graphs (one scene per pass).
//! 8. [`stability`]: static hazards (interval analysis on the IR, warnings in `check`) and
//!    `effectc stress`, renders under extreme inputs counting NaN/Inf, with the culprit
//!    expression located by instrumenting the fragment stage.
//! 9. [`bench`]: quality knobs swept, GPU time against error from the reference frames.
//!
//! Every finding is a [`diag::Diagnostic`], rendered by one emitter (human, JSON, GitHub
//! annotations, SARIF).

pub mod assets;
pub mod back;
pub mod bench;
pub mod check;
pub mod cli;
pub mod diag;
pub mod front;
pub mod graph;
pub mod inputs;
pub mod link;
pub mod manifest;
pub mod output;
pub mod render;
pub mod stage;
pub mod stress;
pub mod translate;
