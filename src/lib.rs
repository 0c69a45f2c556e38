//! effectc: a shader toolchain for desktop-GLSL effects.
//!
//! # Steps
//! A program flows down this list; each module imports only modules on earlier lines
//! (`tests/suite/layout.rs` checks every `crate::` path against this order, and that no
//! module's own submodules import each other in a cycle).
//!
//! 1. [`diag`], [`stage`], [`limits`], [`read`]: every finding is a [`diag::Diagnostic`]
//!    with a typed code, rendered by one emitter (human, JSON, GitHub annotations, SARIF),
//!    silenced by suppressions (`diag::suppress`); stage kinds; how much of an input effectc
//!    reads and models; bounded reads of the files a user's input names (regular files only,
//!    a size limit, confinement to the project root and the directories it allows).
//! 2. [`config`]: the repository's `effectc.toml` (paths read, dialect, codes allowed or
//!    denied).
//! 3. [`manifest`]: `effect.toml` → [`manifest::Effect`] (stages, uniform defaults, textures,
//!    mesh, passes).
//! 4. [`graph`]: the pass graph of a multi-pass effect: reads/writes, what reaches the
//!    output, target lifetimes and sharing.
//! 5. [`inputs`]: command-line paths → programs (manifests, directories, stage files).
//! 6. [`assets`]: CPU-side scene data: meshes, textures, the camera over time, degenerate
//!    mesh variants (no GPU; shared by the static analysis and the renderer).
//! 7. [`front`]: each GLSL stage → `#include`s inlined → glslang's verdict (`front::reference`,
//!    the reference compiler in process, what is legal) → syntax facts (glsl-lang, spans) →
//!    GLSL 4.50 rewrite with an offset map → naga parse + validate; where naga's GLSL
//!    front refuses a legal stage, glslang → SPIR-V → naga instead (`front::through_spirv`).
//! 8. [`link`]: cross-stage interface checks by OpenGL link rules; manifest ↔ shader
//!    declarations; the pass graph's rules.
//! 9. [`check`]: all of the above per program, one bad program never stopping the others;
//!    its static hazard analysis (`check::hazards`, interval analysis on the IR).
//! 10. [`back`]: a clean program's stage modules → one merged, fixed, pruned module →
//!     WGSL, SPIR-V, GLSL ES, MSL, HLSL, reflection (`back::units`: one unit per program or
//!     per pass that reaches the output).
//! 11. [`output`]: atomic file writes that never replace an input.
//! 12. [`translate`]: `effectc translate`: check, translate, write the targets.
//! 13. [`render`]: wgpu headless: one drawer per program (scene or pass graph), frames, PNG.
//! 14. [`verify`]: the translation's frames against the original GLSL drawn by the
//!     system's OpenGL driver (glow + EGL), frame by frame.
//! 15. [`stress`]: renders under extreme inputs counting NaN/Inf, the culprit expression
//!     located by instrumenting the translation (`stress::culprit`).
//! 16. [`bench`]: quality knobs swept, GPU time against error from the reference frames.
//! 17. [`cli`], [`watch`]: the command line (clap), above every command it configures;
//!     `--watch` running a command again when a file it read changes.

pub mod assets;
pub mod back;
pub mod bench;
pub mod check;
pub mod cli;
pub mod config;
pub mod diag;
pub mod front;
pub mod graph;
pub mod inputs;
pub mod limits;
pub mod link;
pub mod manifest;
pub mod output;
pub mod read;
pub mod render;
pub mod stage;
pub mod stress;
pub mod translate;
pub mod verify;
pub mod watch;
