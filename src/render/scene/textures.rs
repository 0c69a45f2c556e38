//! A scene's textures and samplers: the manifest's images and generators uploaded with
//! mipmaps, cube maps, targets of earlier passes, and placeholders for samplers the
//! manifest leaves open, as [`super::plan`] chose (and reported) them.

use std::collections::BTreeMap;

use crate::assets::texture::{self, TexelImage};
use crate::back::reflect::BindingInfo;
use crate::diag::{Code, Diagnostic, FileId};
use crate::manifest::{Filter, TexelFormat, TextureSource, Wrap};
use crate::render::device::Gpu;

use super::plan::TextureChoice;
use super::replay::ReplayTexture;
use super::SceneInput;

/// Textures and samplers by binding name.
pub(crate) struct Textures {
    pub(super) views: BTreeMap<String, wgpu::TextureView>,
    pub(super) samplers: BTreeMap<String, wgpu::Sampler>,
    /// What each texture holds, on the CPU ([`super::replay`]).
    pub(super) replay: BTreeMap<String, ReplayTexture>,
    /// Each sampler's filter, wrap and comparison.
    pub(super) replay_samplers: BTreeMap<String, (Filter, Wrap, bool)>,
}

impl Textures {
    pub(crate) fn create(
        gpu: &Gpu,
        input: &SceneInput<'_>,
        plan: &BTreeMap<String, TextureChoice<'_>>,
    ) -> Result<Textures, Vec<Diagnostic>> {
        let r = &input.translation.reflection;
        let program_plan = &input.program.plan;
        let mut views = BTreeMap::new();
        let mut samplers = BTreeMap::new();
        let mut replay = BTreeMap::new();
        let mut replay_samplers = BTreeMap::new();
        for b in r.bindings.iter().filter(|b| !b.visibility.is_empty()) {
            match b.kind {
                "texture" => {
                    let Some(choice) = plan.get(&b.name) else { continue };
                    let dimension = b.dimension.unwrap_or("2d");
                    let view = match choice {
                        TextureChoice::Target(_) => {
                            let Some(user) = program_plan.textures.iter().find(|t| t.name == b.name).map(|t| &t.user_name) else {
                                continue;
                            };
                            let Some((view, _, _)) = input.pass.as_ref().and_then(|p| p.sampled.get(user)) else { continue };
                            // The replay binds the target its sampler reads by the sampler's name.
                            replay.insert(b.name.clone(), ReplayTexture::Target(user.clone()));
                            view.clone()
                        }
                        TextureChoice::Multisampled { depth } => {
                            replay.insert(b.name.clone(), ReplayTexture::Multisampled { depth: *depth });
                            multisampled_placeholder(gpu, b, *depth)
                        }
                        TextureChoice::Depth => {
                            replay.insert(b.name.clone(), ReplayTexture::Depth { dimension });
                            depth_placeholder(gpu, b)
                        }
                        TextureChoice::Integer { unsigned } => {
                            replay.insert(b.name.clone(), ReplayTexture::Integer { unsigned: *unsigned, dimension });
                            integer_placeholder(gpu, b)
                        }
                        TextureChoice::Image(decl) => {
                            let image = load(decl).map_err(|e| {
                                let file = input.effect.map(|e| e.file).unwrap_or(FileId(0));
                                vec![Diagnostic::new(Code::AssetLoad, format!("cannot load texture `{}`: {e}", decl.name)).at(
                                    file,
                                    decl.span.clone(),
                                    "this texture",
                                )]
                            })?;
                            let view = upload(gpu, &image, b);
                            replay.insert(b.name.clone(), ReplayTexture::Image { image, dimension });
                            view
                        }
                        TextureChoice::Placeholder(kind) => {
                            let image = texture::placeholder(*kind);
                            let view = upload(gpu, &image, b);
                            replay.insert(b.name.clone(), ReplayTexture::Image { image, dimension });
                            view
                        }
                    };
                    views.insert(b.name.clone(), view);
                }
                "sampler" | "comparison_sampler" => {
                    let texture = program_plan.textures.iter().find(|t| t.sampler_name == b.name);
                    let user = texture.map(|t| t.user_name.clone());
                    // A rectangle texture (read as 2D) has one level and clamps, as in GL.
                    let rect = texture.is_some_and(|t| crate::front::syntax::is_rect_sampler(&t.user_ty));
                    let decl = user.as_deref().and_then(|u| input.effect.and_then(|e| e.texture(u)));
                    let target = user.as_deref().and_then(|u| input.pass.as_ref()?.sampled.get(u));
                    let (filter, wrap) = match target {
                        // Targets are read like GL render textures: clamped at the edges.
                        Some((_, filter, _)) => (*filter, Wrap::Clamp),
                        None if rect => (decl.map(|d| d.filter).unwrap_or_default(), Wrap::Clamp),
                        None => decl.map(|d| (d.filter, d.wrap)).unwrap_or_default(),
                    };
                    samplers.insert(b.name.clone(), sampler(gpu, (filter, wrap, rect), b.kind == "comparison_sampler"));
                    replay_samplers.insert(b.name.clone(), (filter, wrap, b.kind == "comparison_sampler"));
                }
                _ => {}
            }
        }
        Ok(Textures { views, samplers, replay, replay_samplers })
    }
}

fn load(decl: &crate::manifest::TextureDecl) -> Result<TexelImage, String> {
    match &decl.source {
        TextureSource::File(p) => texture::load_file_as(p, decl.format),
        TextureSource::Faces(faces) => texture::load_faces(faces, decl.format),
        TextureSource::Generated { generator, size, params } => Ok(texture::generate(*generator, *size, params, decl.kind, decl.format)),
    }
}

pub(super) fn view_dimension(b: &BindingInfo) -> wgpu::TextureViewDimension {
    match b.dimension {
        Some("1d") => wgpu::TextureViewDimension::D1,
        Some("2d_array") => wgpu::TextureViewDimension::D2Array,
        Some("3d") => wgpu::TextureViewDimension::D3,
        Some("cube") => wgpu::TextureViewDimension::Cube,
        Some("cube_array") => wgpu::TextureViewDimension::CubeArray,
        _ => wgpu::TextureViewDimension::D2,
    }
}

/// Six layers for cube (array) views, `None` for the other dimensions.
fn cube_layers(dim: wgpu::TextureViewDimension) -> Option<u32> {
    matches!(dim, wgpu::TextureViewDimension::Cube | wgpu::TextureViewDimension::CubeArray).then_some(6)
}

/// Uploads `image` as the binding's kind of texture, with a full mipmap chain for 2D and
/// cube textures (as `glGenerateMipmap` would make; sampled with trilinear filtering).
/// A 2D image fills every layer a 2D array or cube needs; a 3D texture gets one slice.
fn upload(gpu: &Gpu, image: &TexelImage, b: &BindingInfo) -> wgpu::TextureView {
    let dim = view_dimension(b);
    let layers = cube_layers(dim).unwrap_or(image.layers.max(1));
    let (dimension, depth) = match dim {
        wgpu::TextureViewDimension::D1 => (wgpu::TextureDimension::D1, 1),
        wgpu::TextureViewDimension::D3 => (wgpu::TextureDimension::D3, 1),
        _ => (wgpu::TextureDimension::D2, layers),
    };
    let mipmapped = dimension == wgpu::TextureDimension::D2;
    let mut levels = vec![image.clone()];
    if mipmapped {
        levels.extend(image.mip_chain());
    }
    let height = if dimension == wgpu::TextureDimension::D1 { 1 } else { image.height };
    let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
        label: Some(&b.name),
        size: wgpu::Extent3d { width: image.width, height, depth_or_array_layers: depth },
        mip_level_count: levels.len() as u32,
        sample_count: 1,
        dimension,
        format: wgpu_format(image.format),
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    for (mip, level) in levels.iter().enumerate() {
        let level_height = if dimension == wgpu::TextureDimension::D1 { 1 } else { level.height };
        for layer in 0..depth {
            let Some(data) = level.layer(layer % level.layers.max(1)) else { continue };
            let row = level.width * level.format.texel_bytes() as u32;
            let rows = &data[..(row * level_height) as usize];
            gpu.queue.write_texture(
                wgpu::TexelCopyTextureInfo {
                    texture: &texture,
                    mip_level: mip as u32,
                    origin: wgpu::Origin3d { x: 0, y: 0, z: layer },
                    aspect: wgpu::TextureAspect::All,
                },
                rows,
                wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(row), rows_per_image: Some(level_height) },
                wgpu::Extent3d { width: level.width, height: level_height, depth_or_array_layers: 1 },
            );
        }
    }
    texture.create_view(&wgpu::TextureViewDescriptor { dimension: Some(dim), ..Default::default() })
}

/// The wgpu format of a manifest texture's texels.
pub(super) fn wgpu_format(format: TexelFormat) -> wgpu::TextureFormat {
    use wgpu::TextureFormat as T;
    match format {
        TexelFormat::Rgba8 => T::Rgba8Unorm,
        TexelFormat::Rgba16f => T::Rgba16Float,
        TexelFormat::Rgba32f => T::Rgba32Float,
        TexelFormat::R32f => T::R32Float,
        TexelFormat::Rgba32i => T::Rgba32Sint,
        TexelFormat::Rgba32ui => T::Rgba32Uint,
        TexelFormat::R32i => T::R32Sint,
        TexelFormat::R32ui => T::R32Uint,
    }
}

/// A 1×1 depth texture cleared to 1.0 (everything lit, for shadow lookups).
fn depth_placeholder(gpu: &Gpu, b: &BindingInfo) -> wgpu::TextureView {
    let dim = view_dimension(b);
    let layers = cube_layers(dim).unwrap_or(1);
    let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
        label: Some(&b.name),
        size: wgpu::Extent3d { width: 1, height: 1, depth_or_array_layers: layers },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::Depth32Float,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::RENDER_ATTACHMENT,
        view_formats: &[],
    });
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    for layer in 0..layers {
        let view = texture.create_view(&wgpu::TextureViewDescriptor {
            dimension: Some(wgpu::TextureViewDimension::D2),
            base_array_layer: layer,
            array_layer_count: Some(1),
            ..Default::default()
        });
        clear(&mut encoder, &view, None);
    }
    gpu.queue.submit([encoder.finish()]);
    texture.create_view(&wgpu::TextureViewDescriptor { dimension: Some(dim), ..Default::default() })
}

/// Clears a placeholder target: a colour target to `color`, a depth target (None) to 1.0.
fn clear(encoder: &mut wgpu::CommandEncoder, view: &wgpu::TextureView, color: Option<wgpu::Color>) {
    let colors = color.map(|c| {
        [Some(wgpu::RenderPassColorAttachment {
            view,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations { load: wgpu::LoadOp::Clear(c), store: wgpu::StoreOp::Store },
        })]
    });
    encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("clear placeholder"),
        color_attachments: colors.as_ref().map_or(&[][..], |c| &c[..]),
        depth_stencil_attachment: color.is_none().then_some(wgpu::RenderPassDepthStencilAttachment {
            view,
            depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Store }),
            stencil_ops: None,
        }),
        timestamp_writes: None,
        occlusion_query_set: None,
        multiview_mask: None,
    });
}

/// A 4-sample 1×1 texture cleared to magenta (depth: to 1.0), for a `sampler2DMS` the
/// manifest cannot fill (only render targets are multisampled).
fn multisampled_placeholder(gpu: &Gpu, b: &BindingInfo, depth: bool) -> wgpu::TextureView {
    let format = if depth { wgpu::TextureFormat::Depth32Float } else { wgpu::TextureFormat::Rgba8Unorm };
    let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
        label: Some(&b.name),
        size: wgpu::Extent3d { width: 1, height: 1, depth_or_array_layers: 1 },
        mip_level_count: 1,
        sample_count: 4,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::RENDER_ATTACHMENT,
        view_formats: &[],
    });
    let view = texture.create_view(&Default::default());
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    clear(&mut encoder, &view, (!depth).then_some(wgpu::Color { r: 1.0, g: 0.0, b: 1.0, a: 1.0 }));
    gpu.queue.submit([encoder.finish()]);
    view
}

/// A 1×1 integer texture of zeros.
fn integer_placeholder(gpu: &Gpu, b: &BindingInfo) -> wgpu::TextureView {
    let dim = view_dimension(b);
    let layers = cube_layers(dim).unwrap_or(1);
    let format = if b.sample_type == Some("uint") { wgpu::TextureFormat::Rgba32Uint } else { wgpu::TextureFormat::Rgba32Sint };
    let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
        label: Some(&b.name),
        size: wgpu::Extent3d { width: 1, height: 1, depth_or_array_layers: layers },
        mip_level_count: 1,
        sample_count: 1,
        dimension: if dim == wgpu::TextureViewDimension::D3 { wgpu::TextureDimension::D3 } else { wgpu::TextureDimension::D2 },
        format,
        usage: wgpu::TextureUsages::TEXTURE_BINDING,
        view_formats: &[],
    });
    texture.create_view(&wgpu::TextureViewDescriptor { dimension: Some(dim), ..Default::default() })
}

/// A sampler with `filter` and `wrap`, reading the base level only when `level0`.
fn sampler(gpu: &Gpu, (filter, wrap, level0): (Filter, Wrap, bool), comparison: bool) -> wgpu::Sampler {
    let mode = match filter {
        Filter::Linear => wgpu::FilterMode::Linear,
        Filter::Nearest => wgpu::FilterMode::Nearest,
    };
    let address = match wrap {
        Wrap::Repeat => wgpu::AddressMode::Repeat,
        Wrap::Clamp => wgpu::AddressMode::ClampToEdge,
        Wrap::Mirror => wgpu::AddressMode::MirrorRepeat,
    };
    gpu.device.create_sampler(&wgpu::SamplerDescriptor {
        label: None,
        address_mode_u: address,
        address_mode_v: address,
        address_mode_w: address,
        mag_filter: mode,
        min_filter: mode,
        mipmap_filter: match filter {
            Filter::Linear => wgpu::MipmapFilterMode::Linear,
            Filter::Nearest => wgpu::MipmapFilterMode::Nearest,
        },
        compare: comparison.then_some(wgpu::CompareFunction::LessEqual),
        lod_max_clamp: if level0 { 0.0 } else { 32.0 },
        ..Default::default()
    })
}
