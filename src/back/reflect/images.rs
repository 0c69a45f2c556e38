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

/// WGSL's name of a storage texel format (naga's spelling, as the WGSL declares it). Formats
/// beyond WebGPU's core storage list (`r16float`, `rgb10a2unorm`) are stored to where the
/// adapter can (`texture-formats-tier1`).
fn storage_format_name(f: naga::StorageFormat) -> Option<&'static str> {
    use naga::common::wgsl::ToWgsl;
    Some(f.to_wgsl())
}
