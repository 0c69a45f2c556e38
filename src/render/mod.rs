//! Rendering with wgpu (headless; Vulkan, on Mesa's lavapipe where there is no GPU).
//!
//! - [`device`]: the adapter (picked deterministically), device and queue, created once;
//!   render pipelines built from translated WGSL and its reflection.

pub mod device;
