//! The baseline of the render benchmarks: a translated program's pipeline drawn in a
//! minimal wgpu loop (uniforms written, one draw, copy, map, read; no PNG).

use std::path::Path;
use std::time::Instant;

use effectc::back::{Target as BackTarget, TranslateOptions};
use effectc::check::InputSpec;
use effectc::render::device::Gpu;
use effectc::render::scene::{ColorMode, Scene, SceneInput};
use effectc::render::semantics::FrameState;

/// The same pipeline drawn in a minimal loop: write uniforms, draw, copy, map, read.
pub fn bare_loop_ms(gpu: &Gpu, manifest: &Path, size: u32, frames: u32) -> f64 {
    let (_, checked) = InputSpec { paths: vec![manifest.to_path_buf()], ..InputSpec::default() }.check();
    let unit = checked[0].units.first().expect("checks");
    let t = effectc::back::units::translate_unit(unit, TranslateOptions::for_rendering(true)).expect("translates");
    let wgsl = String::from_utf8(effectc::back::emit(&t, BackTarget::Wgsl).unwrap().remove(0).bytes).unwrap();
    let input = SceneInput {
        translation: &t,
        wgsl: &wgsl,
        program: &unit.program,
        effect: unit.effect.as_ref(),
        mode: ColorMode::Unorm8,
        flipped_y: true,
        pass: None,
        degenerate: None,
        overrides: &[],
        gl_defaults: false,
    };
    let mut scene = Scene::new(gpu, &input).expect("scene");
    let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
        label: None,
        size: wgpu::Extent3d { width: size, height: size, depth_or_array_layers: 1 },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::Rgba8Unorm,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    });
    let view = texture.create_view(&Default::default());
    let depth = scene.depth.then(|| {
        gpu.device
            .create_texture(&wgpu::TextureDescriptor {
                label: None,
                size: wgpu::Extent3d { width: size, height: size, depth_or_array_layers: 1 },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: wgpu::TextureFormat::Depth32Float,
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
                view_formats: &[],
            })
            .create_view(&Default::default())
    });
    let row = (size * 4).div_ceil(256) * 256;
    let readback = gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: u64::from(row) * u64::from(size),
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let view_at = effectc::assets::camera::view_at(&scene.camera, 0.0, 1.0);
    let mut draw_one = |i: u32| {
        let state = FrameState {
            index: i,
            time: f64::from(i) / 30.0,
            delta: 1.0 / 30.0,
            size: (size, size),
            view: view_at,
            model: glam::Mat4::IDENTITY,
        };
        for (data, buffer) in &mut scene.uniforms {
            data.update(&scene.module, &state).unwrap();
            gpu.queue.write_buffer(buffer, 0, &data.bytes);
        }
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        {
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: None,
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: &view,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations { load: wgpu::LoadOp::Clear(wgpu::Color::BLACK), store: wgpu::StoreOp::Store },
                })],
                depth_stencil_attachment: depth.as_ref().map(|d| wgpu::RenderPassDepthStencilAttachment {
                    view: d,
                    depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Discard }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            effectc::render::frames::record_draw(&mut pass, &scene);
        }
        encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo { texture: &texture, mip_level: 0, origin: wgpu::Origin3d::ZERO, aspect: wgpu::TextureAspect::All },
            wgpu::TexelCopyBufferInfo {
                buffer: &readback,
                layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(row), rows_per_image: Some(size) },
            },
            wgpu::Extent3d { width: size, height: size, depth_or_array_layers: 1 },
        );
        gpu.queue.submit([encoder.finish()]);
        let slice = readback.slice(..);
        slice.map_async(wgpu::MapMode::Read, |_| {});
        gpu.device.poll(wgpu::PollType::wait_indefinitely()).unwrap();
        let bytes = slice.get_mapped_range().unwrap().to_vec();
        readback.unmap();
        std::hint::black_box(bytes);
    };
    for i in 0..2 {
        draw_one(i);
    }
    let best = (0..3)
        .map(|_| {
            let start = Instant::now();
            for i in 0..frames {
                draw_one(i);
            }
            start.elapsed().as_secs_f64()
        })
        .fold(f64::INFINITY, f64::min);
    best * 1e3 / f64::from(frames)
}
