//! The one integration-test binary of effectc.
//!
//! The modules live in `tests/suite/`: cargo would build every `tests/*.rs` as a test
//! binary of its own, so only this file sits at the top level.
//!
//! - [`fail`]: every directory under `tests/fail/` produces its expected diagnostic;
//!   the human rendering is snapshotted under `snapshots/fail/`.
//! - [`geometry`]: geometry stages fold into the vertex stage, and the folded draws
//!   render what the same triangles drawn directly render.
//! - [`hazards`]: guarded hazards under `tests/safe/` and the shipped effects check with
//!   no hazard warning.
//! - [`hostile`]: deep legal GLSL alike on any `--jobs`; limits (E0107), devices (E0013) and
//!   includes outside the project root (E0106) refused, nothing refused ever printed.
//! - [`rewrite`]: legal desktop GLSL under `tests/rewrite/` checks clean; the 4.50 text
//!   naga sees is snapshotted under `snapshots/rewrite/`.
//! - [`bench`]: `effectc bench` knob sweeps (error to 0 at the reference, plot, mistakes).
//! - [`cli`]: the `effectc` binary's exit codes, formats and input handling.
//! - [`completions`]: `effectc completions SHELL` and `effectc man`.
//! - [`codes`]: the README's Diagnostics table lists every diagnostic code, and no stale one.
//! - [`robust`]: truncated, mutated and garbage input never panics.
//! - [`reflection`]: the reflection JSON names every uniform member (struct fields and
//!   arrays too) and binding as the WGSL declares them, every pass's targets and reads; a
//!   buffer packed from the JSON alone renders effectc's frame.
//! - [`render`]: `effectc render` frames, determinism, float NaN/Inf, timeout, limits, OBJ.
//! - [`layout`]: the tree's shape: layers import downward, no submodule cycles, file and
//!   function sizes.
//! - [`passes`]: multi-pass effects: skipped passes, dropped attachments, shared
//!   textures, `--dump-targets`, per-pass translation.
//! - [`pixels`]: every effect's frames against reference PNGs under `snapshots/png/`.
//! - [`settings`]: `effectc: allow(…)` suppressions, `effectc.toml` (globs, allow, deny,
//!   `--config`), paths in diagnostics relative to the working directory.
//! - [`stream`]: `effectc render --out -`: PNG and raw frames on stdout (ffmpeg reads
//!   them), the report on stderr, misuse refused, a closed pipe.
//! - [`programs`]: `--define`, a manifest stage's `define`, the single-file two-stage format,
//!   `[[program]]` in `effectc.toml`, and the programs formed listed (`--verbose`, JSON).
//! - [`stress`]: `effectc stress` finds seed hazards at the ends of ranges; shipped effects
//!   are clean.
//! - [`through_spirv`]: legal programs naga's GLSL front refuses go through glslang's SPIR-V;
//!   their hazards still point at GLSL lines; reports snapshotted under `snapshots/through_spirv/`.
//! - [`tessellation`]: tessellation stages folded into the vertex stage validate, translate
//!   and draw what the OpenGL driver draws (known differences listed).
//! - [`translate`]: every effect and rewrite program translates to every target; WGSL,
//!   `spirv-val` and a wgpu pipeline prove the output; IR/WGSL/SPIR-V snapshots.
//! - [`vulkan_stages`]: ray-tracing and mesh stages judged by glslang alone; Vulkan GLSL
//!   compiled for the Vulkan version its constructs need.
//! - [`verify`]: `effectc verify`: every effect and the semantics suite against the system's
//!   OpenGL driver; known failures listed, and failing when they start matching.
//! - [`watch`]: `--watch` reports again after a change; `render` renders only what changed.

#[path = "suite/bench.rs"]
mod bench;
#[path = "suite/cli.rs"]
mod cli;
#[path = "suite/codes.rs"]
mod codes;
#[path = "suite/common.rs"]
mod common;
#[path = "suite/completions.rs"]
mod completions;
#[path = "suite/fail.rs"]
mod fail;
#[path = "suite/geometry.rs"]
mod geometry;
#[path = "suite/hazards.rs"]
mod hazards;
#[path = "suite/hostile.rs"]
mod hostile;
#[path = "suite/layout.rs"]
mod layout;
#[path = "suite/passes.rs"]
mod passes;
#[path = "suite/pixels.rs"]
mod pixels;
#[path = "suite/programs.rs"]
mod programs;
#[path = "suite/reflection.rs"]
mod reflection;
#[path = "suite/render.rs"]
mod render;
#[path = "suite/rewrite.rs"]
mod rewrite;
#[path = "suite/robust.rs"]
mod robust;
#[path = "suite/settings.rs"]
mod settings;
#[path = "suite/stream.rs"]
mod stream;
#[path = "suite/stress.rs"]
mod stress;
#[path = "suite/tessellation.rs"]
mod tessellation;
#[path = "suite/through_spirv.rs"]
mod through_spirv;
#[path = "suite/translate.rs"]
mod translate;
#[path = "suite/verify.rs"]
mod verify;
#[path = "suite/vulkan_stages.rs"]
mod vulkan_stages;
#[path = "suite/watch.rs"]
mod watch;
