//! `effectc verify`: proof that a translation draws what the original GLSL draws on a real
//! OpenGL driver, frame by frame.
//!
//! # Steps
//! - [`context`]: a headless GL 4.5 compatibility context through EGL (surfaceless).
//! - [`program`]: the user's GLSL compiled and linked by the driver; its errors placed in
//!   the user's files.
//! - [`uniforms`]: GL's active uniforms fed from the wgpu scene's uniform buffers.
//! - [`gl_scene`]: the same vertices, textures and state for one scene.
//! - [`gl_frame`]: targets, passes in order, the output read back.
//! - [`diff`]: the comparison of two frames and its heat map.
//! - [`command`]: the run.
//! - [`isolation`]: the run in a child process, so a driver that crashes on one program
//!   costs only that program's verdict.

pub mod command;
pub mod context;
pub mod diff;
pub mod fixed_function;
pub mod gl_frame;
pub mod gl_scene;
pub mod isolation;
pub mod program;
pub mod uniforms;
