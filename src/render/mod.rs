//! Rendering with wgpu (headless; Vulkan, on Mesa's lavapipe where there is no GPU).
//!
//! # Steps
//! - [`device`]: the adapter (picked deterministically), device and queue, created once;
//!   render pipelines built from translated WGSL.
//!   Meshes, textures, the camera and the stress variants of a mesh are CPU data in
//!   [`crate::assets`].
//! - [`attributes`]: which mesh attribute feeds each vertex input; the vertex buffer.
//! - [`semantics`], [`uniforms`]: per-frame values,
//!   the bytes of every uniform buffer (manifest values, semantics, reported guesses).
//! - [`scene`]: everything one effect needs on the GPU; [`compute`]: a compute-only program
//!   dispatched over the frame, the image it stores read back as the frame, or the words
//!   of the buffer it stores to shown by [`buffer_words`].
//! - [`frames`]: drawing one frame into an offscreen target and reading it back, with a
//!   timeout.
//! - [`pass_graph`]: a multi-pass effect: one scene per pass that reaches the output, targets
//!   shared when lifetimes allow, all passes in one submission per frame.
//! - [`texels`]: read-back texels of any target or image format as RGBA floats.
//! - [`encode`], [`compare`]: PNG, contact sheet, GIF, NaN/Inf masks; reference-image
//!   comparison for pixel tests.
//! - [`sink`]: where frames go (PNG files, or a PNG or raw stream on stdout), encoded on
//!   a pool and written in order.
//! - [`command`]: `effectc render`.
//! - [`preview`]: the warnings a render of a manifest would give, without a device (for
//!   `effectc check`).
//! - [`memory`]: a program built once and drawn in memory with other uniform values
//!   (`effectc bench`, `effectc stress`).

pub mod attributes;
pub mod buffer_words;
pub mod command;
pub mod compare;
pub mod compute;
pub mod device;
pub mod drawer;
pub mod encode;
pub mod frames;
pub mod memory;
pub mod pass_graph;
pub mod preview;
pub mod scene;
pub mod semantics;
pub mod sink;
pub mod texels;
pub mod uniforms;
