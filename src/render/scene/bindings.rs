//! A scene's buffers and bind groups: uniform buffers, storage buffers (by name, so a
//! caller can zero and read them back), textures and samplers bound by reflection.

use std::collections::BTreeMap;

use crate::back::reflect::{BindingInfo, Reflection};
use crate::render::device::{Gpu, PipelineSpec};
use crate::render::uniforms::UniformBuffer;

use super::textures::Textures;

/// The storage buffers a scene made, by binding name.
pub(crate) type StorageBuffers = Vec<(String, wgpu::Buffer)>;

/// The images bound to storage textures: (group, binding), the texture and its format.
pub(crate) type StorageImages = Vec<((u32, u32), wgpu::Texture, wgpu::TextureFormat)>;

/// What the bind groups of a pipeline hold.
pub(crate) struct Bound {
    pub groups: Vec<(u32, wgpu::BindGroup)>,
    pub storage: StorageBuffers,
    /// (group, binding) of each of `storage`, in its order.
    pub storage_at: Vec<(u32, u32)>,
    pub images: StorageImages,
}

/// Side of the zeroed images bound to storage textures of a drawn scene (GL programs size
/// them to their framebuffer; the scene's frame size is not known there).
pub(super) const IMAGE_SIDE: u32 = 256;

/// The bind groups of a pipeline (`layout_of` gives a group's layout) with the reflection's
/// resources; storage-texture images are `image_size` (`IMAGE_SIDE` square for a drawn
/// scene, the frame for a compute program).
pub(crate) fn bind_groups(
    gpu: &Gpu,
    layout_of: &dyn Fn(u32) -> wgpu::BindGroupLayout,
    r: &Reflection,
    (uniforms, textures): (&[(UniformBuffer, wgpu::Buffer)], &Textures),
    filled: &[(u32, &[u8])],
    image_size: (u32, u32),
) -> Bound {
    let mut by_group: BTreeMap<u32, Vec<&BindingInfo>> = BTreeMap::new();
    for b in r.bindings.iter().filter(|b| !b.visibility.is_empty()) {
        by_group.entry(b.group).or_default().push(b);
    }
    let mut storage = Vec::new();
    // (group, binding) of each storage buffer made (names can be empty: an unnamed block).
    let mut at = Vec::new();
    for b in by_group.values().flatten().filter(|b| b.kind == "storage_buffer") {
        // Group 0's storage buffers with data of their own: a folded geometry stage's vertices.
        if let Some((_, bytes)) = filled.iter().find(|(binding, _)| b.group == 0 && *binding == b.binding) {
            storage.push((b.name.clone(), buffer_init(gpu, "pulled", bytes, wgpu::BufferUsages::STORAGE)));
            at.push((b.group, b.binding));
            continue;
        }
        let size = u64::from(b.size.unwrap_or(16)).max(16) + 65536;
        storage.push((
            b.name.clone(),
            gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(&b.name),
                size,
                // Callers may zero a storage buffer before a run and read it back (stress's counts).
                usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            }),
        ));
        at.push((b.group, b.binding));
    }
    // Storage textures (GL image units): zeroed images of each binding's format.
    let images: Vec<((u32, u32), wgpu::Texture, wgpu::TextureFormat, wgpu::TextureView)> = by_group
        .values()
        .flatten()
        .filter(|b| b.kind == "storage_texture")
        .filter_map(|b| {
            let (texture, format, view) = storage_texture(gpu, b, image_size)?;
            Some(((b.group, b.binding), texture, format, view))
        })
        .collect();
    let mut groups = Vec::new();
    for (group, bindings) in by_group {
        let mut entries = Vec::new();
        for b in bindings {
            let resource = match b.kind {
                "uniform_buffer" => {
                    uniforms.iter().find(|(u, _)| u.group == b.group && u.binding == b.binding).map(|(_, buf)| buf.as_entire_binding())
                }
                "storage_buffer" => at.iter().position(|a| *a == (b.group, b.binding)).map(|i| storage[i].1.as_entire_binding()),
                "texture" => textures.views.get(&b.name).map(wgpu::BindingResource::TextureView),
                "storage_texture" => {
                    images.iter().find(|(at, ..)| *at == (b.group, b.binding)).map(|(.., v)| wgpu::BindingResource::TextureView(v))
                }
                "sampler" | "comparison_sampler" => textures.samplers.get(&b.name).map(wgpu::BindingResource::Sampler),
                _ => None,
            };
            if let Some(resource) = resource {
                entries.push(wgpu::BindGroupEntry { binding: b.binding, resource });
            }
        }
        let layout = layout_of(group);
        let bg = gpu.device.create_bind_group(&wgpu::BindGroupDescriptor { label: None, layout: &layout, entries: &entries });
        groups.push((group, bg));
    }
    let images = images.into_iter().map(|(at, texture, format, _)| (at, texture, format)).collect();
    Bound { groups, storage, storage_at: at, images }
}

/// A zeroed image for a storage-texture binding, of its format and dimension (None for a
/// format WebGPU cannot bind as storage), `width` × `height` (a 1D image is one row).
fn storage_texture(
    gpu: &Gpu,
    b: &BindingInfo,
    (width, height): (u32, u32),
) -> Option<(wgpu::Texture, wgpu::TextureFormat, wgpu::TextureView)> {
    use wgpu::TextureFormat as T;
    let format = match b.format? {
        "r32float" => T::R32Float,
        "r32uint" => T::R32Uint,
        "r32sint" => T::R32Sint,
        "rg32float" => T::Rg32Float,
        "rg32uint" => T::Rg32Uint,
        "rg32sint" => T::Rg32Sint,
        "rgba8unorm" => T::Rgba8Unorm,
        "rgba8snorm" => T::Rgba8Snorm,
        "rgba8uint" => T::Rgba8Uint,
        "rgba8sint" => T::Rgba8Sint,
        "bgra8unorm" => T::Bgra8Unorm,
        "rgba16float" => T::Rgba16Float,
        "rgba16uint" => T::Rgba16Uint,
        "rgba16sint" => T::Rgba16Sint,
        "rgba32float" => T::Rgba32Float,
        "rgba32uint" => T::Rgba32Uint,
        "rgba32sint" => T::Rgba32Sint,
        // Formats WebGPU's core stores to only with `texture-formats-tier1`, which GL and
        // Vulkan programs use: where the adapter cannot store to one, wgpu says so (E0402).
        "r8unorm" => T::R8Unorm,
        "r8snorm" => T::R8Snorm,
        "r8uint" => T::R8Uint,
        "r8sint" => T::R8Sint,
        "rg8unorm" => T::Rg8Unorm,
        "rg8snorm" => T::Rg8Snorm,
        "rg8uint" => T::Rg8Uint,
        "rg8sint" => T::Rg8Sint,
        "r16uint" => T::R16Uint,
        "r16sint" => T::R16Sint,
        "r16float" => T::R16Float,
        "r16unorm" => T::R16Unorm,
        "r16snorm" => T::R16Snorm,
        "rg16uint" => T::Rg16Uint,
        "rg16sint" => T::Rg16Sint,
        "rg16float" => T::Rg16Float,
        "rg16unorm" => T::Rg16Unorm,
        "rg16snorm" => T::Rg16Snorm,
        "rgba16unorm" => T::Rgba16Unorm,
        "rgba16snorm" => T::Rgba16Snorm,
        "rgb10a2unorm" => T::Rgb10a2Unorm,
        "rgb10a2uint" => T::Rgb10a2Uint,
        "rg11b10ufloat" => T::Rg11b10Ufloat,
        _ => return None,
    };
    let view_dimension = super::textures::view_dimension(b);
    let (dimension, depth) = match view_dimension {
        wgpu::TextureViewDimension::D1 => (wgpu::TextureDimension::D1, 1),
        wgpu::TextureViewDimension::D3 => (wgpu::TextureDimension::D3, 4),
        wgpu::TextureViewDimension::D2Array => (wgpu::TextureDimension::D2, 4),
        _ => (wgpu::TextureDimension::D2, 1),
    };
    let height = if dimension == wgpu::TextureDimension::D1 { 1 } else { height };
    let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
        label: Some(&b.name),
        size: wgpu::Extent3d { width, height, depth_or_array_layers: depth },
        mip_level_count: 1,
        sample_count: 1,
        dimension,
        format,
        usage: wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    });
    let view = texture.create_view(&wgpu::TextureViewDescriptor { dimension: Some(view_dimension), ..Default::default() });
    Some((texture, format, view))
}

/// The scene's pipeline. wgpu derives the layout from the shader stage by stage, and refuses
/// a texture one stage only loads or measures (non-filterable) and another samples
/// (filterable): then the layout is built from the reflection and the pipeline made again.
pub(super) fn pipeline(gpu: &Gpu, spec: &PipelineSpec<'_>, r: &Reflection) -> Result<wgpu::RenderPipeline, String> {
    match gpu.pipeline(spec) {
        Err(e) if e.contains("not consistent between stages") => {
            let Some(layout) = explicit_layout(gpu, r) else { return Err(e) };
            gpu.pipeline(&PipelineSpec { layout: Some(&layout), colors: spec.colors.clone(), ..*spec })
        }
        other => other,
    }
}

/// A pipeline layout from the reflection's bindings (None when a binding's kind needs what
/// the reflection does not say: a storage texture's format, a fragment storage buffer's access).
fn explicit_layout(gpu: &Gpu, r: &Reflection) -> Option<wgpu::PipelineLayout> {
    let mut groups: BTreeMap<u32, Vec<wgpu::BindGroupLayoutEntry>> = BTreeMap::new();
    for b in r.bindings.iter().filter(|b| !b.visibility.is_empty()) {
        let mut visibility = wgpu::ShaderStages::NONE;
        for stage in &b.visibility {
            visibility |= if *stage == "vertex" { wgpu::ShaderStages::VERTEX } else { wgpu::ShaderStages::FRAGMENT };
        }
        let ty = match b.kind {
            "uniform_buffer" => {
                wgpu::BindingType::Buffer { ty: wgpu::BufferBindingType::Uniform, has_dynamic_offset: false, min_binding_size: None }
            }
            // Vertex-stage storage is read-only in WebGPU.
            "storage_buffer" if visibility == wgpu::ShaderStages::VERTEX => wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Storage { read_only: true },
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            "texture" => wgpu::BindingType::Texture {
                sample_type: match b.sample_type {
                    Some("sint") => wgpu::TextureSampleType::Sint,
                    Some("uint") => wgpu::TextureSampleType::Uint,
                    Some("depth") => wgpu::TextureSampleType::Depth,
                    _ => wgpu::TextureSampleType::Float { filterable: true },
                },
                view_dimension: super::textures::view_dimension(b),
                multisampled: b.multisampled,
            },
            "sampler" => wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
            "comparison_sampler" => wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Comparison),
            _ => return None,
        };
        groups.entry(b.group).or_default().push(wgpu::BindGroupLayoutEntry { binding: b.binding, visibility, ty, count: None });
    }
    let last = groups.keys().copied().max().map_or(0, |g| g + 1);
    let layouts: Vec<wgpu::BindGroupLayout> = (0..last)
        .map(|g| {
            let entries = groups.get(&g).map_or(&[][..], |e| &e[..]);
            gpu.device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor { label: None, entries })
        })
        .collect();
    let refs: Vec<Option<&wgpu::BindGroupLayout>> = layouts.iter().map(Some).collect();
    Some(gpu.device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor { label: None, bind_group_layouts: &refs, immediate_size: 0 }))
}

/// One uniform buffer per block the plan packed, filled with its bytes (rewritten per frame).
pub(crate) fn uniform_buffers(gpu: &Gpu, data: Vec<UniformBuffer>) -> Vec<(UniformBuffer, wgpu::Buffer)> {
    data.into_iter()
        .map(|u| {
            let b = buffer_init(gpu, "uniforms", &u.bytes, wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST);
            (u, b)
        })
        .collect()
}

pub(crate) fn buffer_init(gpu: &Gpu, label: &str, bytes: &[u8], usage: wgpu::BufferUsages) -> wgpu::Buffer {
    use wgpu::util::DeviceExt;
    // Zero-sized buffers are invalid; a vertex stage without inputs still gets none.
    let padded;
    let contents = if !bytes.len().is_multiple_of(4) || bytes.is_empty() {
        let mut p = bytes.to_vec();
        p.resize(bytes.len().div_ceil(4).max(1) * 4, 0);
        padded = p;
        &padded[..]
    } else {
        bytes
    };
    gpu.device.create_buffer_init(&wgpu::util::BufferInitDescriptor { label: Some(label), contents, usage })
}
