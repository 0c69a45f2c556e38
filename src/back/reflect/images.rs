//! What the reflection says about a texture or storage texture binding: dimension, sample
//! type, multisampling, and a storage texture's texel format (WGSL's spelling) and access.

use naga::{ImageClass, ImageDimension, ScalarKind};

use super::BindingInfo;

/// A texture or storage texture binding's dimension, sample type and (storage) format and
/// access.
pub(super) fn describe_image(info: &mut BindingInfo, dim: ImageDimension, arrayed: bool, class: &ImageClass) {
    info.kind = if matches!(class, ImageClass::Storage { .. }) { "storage_texture" } else { "texture" };
    info.dimension = Some(match (dim, arrayed) {
        (ImageDimension::D1, _) => "1d",
        (ImageDimension::D2, false) => "2d",
        (ImageDimension::D2, true) => "2d_array",
        (ImageDimension::D3, _) => "3d",
        (ImageDimension::Cube, false) => "cube",
        (ImageDimension::Cube, true) => "cube_array",
    });
    match class {
        ImageClass::Sampled { kind, multi } => {
            info.multisampled = *multi;
            info.sample_type = Some(match kind {
                ScalarKind::Sint => "sint",
                ScalarKind::Uint => "uint",
                _ => "float",
            });
        }
        ImageClass::Depth { multi } => {
            info.multisampled = *multi;
            info.sample_type = Some("depth");
        }
        ImageClass::Storage { format, access } => {
            info.format = storage_format_name(*format);
            let (read, write) = (access.contains(naga::StorageAccess::LOAD), access.contains(naga::StorageAccess::STORE));
            info.access = Some(match (read, write) {
                (true, true) => "read_write",
                (false, true) => "write",
                _ => "read",
            });
        }
        _ => {}
    }
}

/// WGSL's name of a storage texel format WebGPU can bind (None for the others).
fn storage_format_name(f: naga::StorageFormat) -> Option<&'static str> {
    use naga::StorageFormat as F;
    Some(match f {
        F::R32Float => "r32float",
        F::R32Uint => "r32uint",
        F::R32Sint => "r32sint",
        F::Rg32Float => "rg32float",
        F::Rg32Uint => "rg32uint",
        F::Rg32Sint => "rg32sint",
        F::Rgba8Unorm => "rgba8unorm",
        F::Rgba8Snorm => "rgba8snorm",
        F::Rgba8Uint => "rgba8uint",
        F::Rgba8Sint => "rgba8sint",
        F::Bgra8Unorm => "bgra8unorm",
        F::Rgba16Float => "rgba16float",
        F::Rgba16Uint => "rgba16uint",
        F::Rgba16Sint => "rgba16sint",
        F::Rgba32Float => "rgba32float",
        F::Rgba32Uint => "rgba32uint",
        F::Rgba32Sint => "rgba32sint",
        _ => return None,
    })
}
