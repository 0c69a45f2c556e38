//! What a scene is made of on the CPU: meshes, textures, the camera over time, and the
//! degenerate mesh variants `stress` draws. Nothing here touches the GPU: the static
//! analysis (`check`'s hazards) reads the same data the renderer uploads.
//!
//! - [`mesh`]: built-in meshes, OBJ files, tangents.
//! - [`attribute_names`]: which mesh attribute a vertex input's name suggests.
//! - [`texture`]: image files, cube maps, generated textures.
//! - [`camera`]: camera and model transforms at a time.
//! - [`degenerate`]: zero normals, zero-area triangles.

pub mod attribute_names;
pub mod camera;
pub mod degenerate;
pub mod mesh;
pub mod texture;
