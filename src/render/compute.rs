//! A compute-only program made drawable: its `cs_main` dispatched over the frame, one
//! invocation per pixel at least (`ceil(width / local_size_x)` × `ceil(height /
//! local_size_y)` workgroups), and the first 2D image it stores to (by group and binding;
//! else layer or slice 0 of a 2D array or 3D one) read back as the frame, bottom row last
//! as GL shows a texture; a program that stores to
//! no 2D image shows the words of the first storage buffer it stores to instead
//! ([`buffer_words`](crate::render::buffer_words), note N0401). Uniforms, textures and
//! samplers are guessed and reported as for a drawn scene; every image is the frame's size
//! and starts zeroed, every buffer zeroed, and both keep what the program wrote from one
//! frame to the next, as GL's image units and buffer bindings do.

use std::time::{Duration, Instant};

use crate::back::reflect::BindingInfo;
use crate::diag::{Code, Diagnostic};
use crate::manifest::{CameraDecl, ModelDecl};
use crate::render::buffer_words::{self, WordLayout};
use crate::render::device::Gpu;
use crate::render::frames::{self, Frame, FrameError, Pixels};
use crate::render::semantics::FrameState;
use crate::render::uniforms::UniformBuffer;

use crate::render::scene::bindings::{bind_groups, uniform_buffers, Bound};
use crate::render::scene::textures::Textures;
use crate::render::scene::{pipeline_error, plan, ColorMode, SceneInput};

/// One compute program's GPU state.
pub struct ComputeScene {
    pub name: String,
    pub module: naga::Module,
    pipeline: wgpu::ComputePipeline,
    bind_groups: Vec<(u32, wgpu::BindGroup)>,
    uniforms: Vec<(UniformBuffer, wgpu::Buffer)>,
    workgroups: [u32; 3],
    shown: Shown,
    size: (u32, u32),
    readback: wgpu::Buffer,
    padded_row: u32,
    mode: ColorMode,
    pub camera: CameraDecl,
    pub model: ModelDecl,
    /// What was guessed, as warnings.
    pub warnings: Vec<Diagnostic>,
    /// A one-line description of the dispatch, for `--verbose`.
    pub describe: String,
}

/// What the frame shows.
enum Shown {
    /// A 2D storage image: its texture and format.
    Image(wgpu::Texture, wgpu::TextureFormat),
    /// A storage buffer's first words (`bytes` of them are read back), read by their layout.
    Buffer(wgpu::Buffer, u64, WordLayout),
}

/// The binding a compute program's frame is read from, before the device holds it.
enum Chosen<'r> {
    Image(&'r BindingInfo),
    Buffer(&'r BindingInfo, WordLayout),
}

/// Whether a translation is a compute-only program.
pub fn is_compute_only(r: &crate::back::reflect::Reflection) -> bool {
    !r.entry_points.is_empty() && r.entry_points.iter().all(|e| e.stage == "compute")
}

/// The image a compute program's frame shows: the first 2D storage texture it writes, else
/// the first layer of a 2D array or the first slice of a 3D one.
fn shown_image(r: &crate::back::reflect::Reflection) -> Option<&BindingInfo> {
    let mut written: Vec<&BindingInfo> = r
        .bindings
        .iter()
        .filter(|b| b.kind == "storage_texture" && matches!(b.dimension, Some("2d" | "2d_array" | "3d")))
        .filter(|b| b.access.is_some_and(|a| a.contains("write")))
        .collect();
    written.sort_by_key(|b| (b.dimension != Some("2d"), b.group, b.binding));
    written.first().copied()
}

impl ComputeScene {
    pub fn new(gpu: &Gpu, input: &SceneInput<'_>, size: (u32, u32)) -> Result<ComputeScene, Vec<Diagnostic>> {
        let t = input.translation;
        let r = &t.reflection;
        let file = input.program.stages[0].syntax.file;
        let chosen = shown_image(r).map(Chosen::Image).or_else(|| shown_buffer(r, &t.module).map(|(b, l)| Chosen::Buffer(b, l)));
        let Some(chosen) = chosen else {
            return Err(vec![Diagnostic::new(Code::Unrenderable, "the compute program stores to no 2D image and no buffer: there is no frame to show")
                .in_file(file)
                .with_note(
                    "`render` dispatches a compute-only program over the frame and shows the first 2D image it writes with `imageStore`, else the first storage buffer it writes",
                )]);
        };
        let plan::Plan { uniforms: uniform_data, textures: texture_plan, mut warnings, .. } = plan::plan(&input.plan_input())?;
        let pipeline = gpu.compute_pipeline(&t.name, input.wgsl).map_err(|e| vec![pipeline_error(file, &e)])?;
        let scope = gpu.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let uniforms = uniform_buffers(gpu, uniform_data);
        let textures = Textures::create(gpu, input, &texture_plan)?;
        let layout_of = |group| pipeline.get_bind_group_layout(group);
        let Bound { groups, images, mut storage, storage_at } = bind_groups(gpu, &layout_of, r, (&uniforms, &textures), &[], size);
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(vec![pipeline_error(file, &e.to_string())]);
        }
        let (shown, name) = match chosen {
            Chosen::Image(image) => {
                let Some((_, texture, format)) = images.into_iter().find(|(at, ..)| *at == (image.group, image.binding)) else {
                    return Err(vec![Diagnostic::new(
                        Code::Unrenderable,
                        format!("image `{}` has a format WebGPU cannot store to, so there is no frame to show", image.name),
                    )
                    .in_file(file)]);
                };
                (Shown::Image(texture, format), format!("image `{}` ({format:?})", image.name))
            }
            Chosen::Buffer(b, layout) => {
                // An unnamed block is known by its block name.
                let name = if b.name.is_empty() { b.glsl.clone().unwrap_or_default() } else { b.name.clone() };
                let at = storage_at.iter().position(|at| *at == (b.group, b.binding));
                let Some((_, buffer)) = at.map(|i| storage.swap_remove(i)) else {
                    return Err(vec![Diagnostic::new(Code::Unrenderable, format!("buffer `{name}` was not bound")).in_file(file)]);
                };
                let bytes = buffer.size().min(u64::from(size.0) * u64::from(size.1) * 4) / 4 * 4;
                warnings.push(buffer_shown(file, &name, size));
                (Shown::Buffer(buffer, bytes, layout), format!("the words of buffer `{name}`"))
            }
        };
        let local = t.module.entry_points.iter().find(|e| e.stage == naga::ShaderStage::Compute).map_or([1, 1, 1], |e| e.workgroup_size);
        let workgroups = [size.0.div_ceil(local[0].max(1)), size.1.div_ceil(local[1].max(1)), 1];
        let (padded_row, readback_size) = match &shown {
            Shown::Image(_, format) => {
                let row = frames::padded_row_of(size.0, *format);
                (row, u64::from(row) * u64::from(size.1))
            }
            Shown::Buffer(_, bytes, _) => (0, (*bytes).max(4)),
        };
        let readback = gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("compute readback"),
            size: readback_size,
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        let describe =
            format!("compute: {}×{}×1 workgroups of {}×{}×{}, showing {name}", workgroups[0], workgroups[1], local[0], local[1], local[2]);
        Ok(ComputeScene {
            name: t.name.clone(),
            module: t.module.clone(),
            pipeline,
            bind_groups: groups,
            uniforms,
            workgroups,
            shown,
            size,
            readback,
            padded_row,
            mode: input.mode,
            camera: input.effect.and_then(|e| e.camera.clone()).unwrap_or_default(),
            model: input.effect.map(|e| e.model.clone()).unwrap_or_default(),
            warnings,
            describe,
        })
    }

    /// Dispatches the program once with `state`'s uniforms and reads the image back.
    pub fn draw(&mut self, gpu: &Gpu, state: &FrameState, timeout: Duration) -> Result<Frame, FrameError> {
        let cpu_start = Instant::now();
        frames::write_uniform_buffers(gpu, &mut self.uniforms, &self.module, state)?;
        let scope = gpu.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let mut encoder = gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("dispatch") });
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor { label: Some(&self.name), timestamp_writes: None });
            pass.set_pipeline(&self.pipeline);
            for (group, bg) in &self.bind_groups {
                pass.set_bind_group(*group, bg, &[]);
            }
            let [x, y, z] = self.workgroups;
            pass.dispatch_workgroups(x, y, z);
        }
        let (w, h) = self.size;
        match &self.shown {
            Shown::Image(texture, _) => encoder.copy_texture_to_buffer(
                wgpu::TexelCopyTextureInfo { texture, mip_level: 0, origin: wgpu::Origin3d::ZERO, aspect: wgpu::TextureAspect::All },
                wgpu::TexelCopyBufferInfo {
                    buffer: &self.readback,
                    layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(self.padded_row), rows_per_image: Some(h) },
                },
                wgpu::Extent3d { width: w, height: h, depth_or_array_layers: 1 },
            ),
            Shown::Buffer(buffer, bytes, _) => encoder.copy_buffer_to_buffer(buffer, 0, &self.readback, 0, *bytes),
        }
        let submitted = gpu.queue.submit([encoder.finish()]);
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(FrameError::Device(e.to_string()));
        }
        let cpu = cpu_start.elapsed();
        let wall = frames::wait(gpu, submitted, timeout)?;
        let unpack_start = Instant::now();
        let bytes = frames::map_read(gpu, &self.readback)?;
        let rgba = match &self.shown {
            // Row 0 of a GL image is the bottom of the picture it shows.
            Shown::Image(_, format) => crate::render::texels::decode_rgba(&bytes, *format, (w, h), self.padded_row, true),
            Shown::Buffer(_, _, layout) => buffer_words::picture(&bytes, layout, (w, h)),
        };
        let pixels = match self.mode {
            ColorMode::Unorm8 => Pixels::Rgba8(crate::render::encode::float_to_rgba8(&rgba)),
            ColorMode::Float32 => Pixels::Rgba32F(rgba),
        };
        if let Some(e) = gpu.take_error() {
            return Err(FrameError::Device(e));
        }
        let cpu_ms = (cpu + unpack_start.elapsed()).as_secs_f64() * 1e3;
        Ok(Frame { pixels, gpu_ms: wall.as_secs_f64() * 1e3, cpu_ms, dumps: Vec::new() })
    }
}

/// The buffer a compute program that stores to no image shows: the first storage buffer (by
/// group and binding) a function stores to, with the layout of its words. The translation
/// has made every buffer no function writes read-only (`fixes::read_only_unwritten_storage`,
/// from naga's analysis of each function's global uses).
fn shown_buffer<'r>(r: &'r crate::back::reflect::Reflection, module: &naga::Module) -> Option<(&'r BindingInfo, WordLayout)> {
    let mut buffers: Vec<&BindingInfo> = r.bindings.iter().filter(|b| b.kind == "storage_buffer").collect();
    buffers.sort_by_key(|b| (b.group, b.binding));
    buffers.into_iter().find_map(|b| {
        let (_, var) = module
            .global_variables
            .iter()
            .find(|(_, v)| v.binding.as_ref().is_some_and(|rb| (rb.group, rb.binding) == (b.group, b.binding)))?;
        let written = matches!(var.space, naga::AddressSpace::Storage { access } if access.contains(naga::StorageAccess::STORE));
        written.then(|| (b, WordLayout::of(module, var.ty)))
    })
}

/// N0401: what a buffer-only compute program's frame shows.
fn buffer_shown(file: crate::diag::FileId, name: &str, (w, h): (u32, u32)) -> Diagnostic {
    Diagnostic::new(Code::BufferShown, format!("the frame shows the first {} words of buffer `{name}`, which the program stores to", w * h))
        .in_file(file)
        .with_note("the program stores to no 2D image: each pixel is one 32-bit word of the buffer in reading order (word 0 top left), read as the `float`, `int` or `uint` its place in the buffer's type holds and shaded from black (the smallest finite value of its kind in the frame) to white (the largest); NaN and infinities are magenta, pixels past the buffer's end transparent")
}
