//! Drawing one frame into an offscreen target and reading it back.
//!
//! The target (colour attachments for every fragment output, a depth buffer, a readback
//! buffer with rows padded to 256 bytes, timestamp queries when the adapter has them) is
//! created once per run and reused by every frame. Waiting for a frame is bounded by a
//! timeout so that a shader stuck in a loop ends the run with an error instead of hanging.
//! Frames are unpacked straight from the mapped readback into buffers the writer hands
//! back ([`Spare`]), so a long run does not fault in fresh pages for every frame.

use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use crate::render::device::Gpu;
use crate::render::scene::{ColorMode, Draw, Scene};
use crate::render::semantics::FrameState;
use crate::render::uniforms::UniformBuffer;

/// The pixels of a frame, top row first, without row padding.
pub enum Pixels {
    Rgba8(Vec<u8>),
    Rgba32F(Vec<f32>),
}

/// Frame buffers handed back after use, for the next frames to reuse (shared between the
/// render loop and whoever consumes the frames; a few are kept, the rest dropped).
#[derive(Clone, Default)]
pub struct Spare(Arc<Mutex<Vec<Vec<u8>>>>);

impl Spare {
    /// Buffers kept at most.
    const KEPT: usize = 8;

    /// An empty buffer with room for `len` bytes (a reused one when there is one).
    pub fn take(&self, len: usize) -> Vec<u8> {
        let reused = self.0.lock().ok().and_then(|mut free| free.pop());
        match reused {
            Some(mut v) if v.capacity() >= len => {
                v.clear();
                v
            }
            _ => Vec::with_capacity(len),
        }
    }

    /// Hands a buffer back for reuse.
    pub fn give(&self, v: Vec<u8>) {
        if let Ok(mut free) = self.0.lock() {
            if free.len() < Self::KEPT && v.capacity() > 0 {
                free.push(v);
            }
        }
    }
}

/// How the GPU time of a frame was measured.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GpuClock {
    /// Timestamp queries around the render pass.
    Timestamps,
    /// Wall time from submit until the GPU finished (includes the readback copy).
    Wall,
}

/// A rendered frame.
pub struct Frame {
    pub pixels: Pixels,
    pub gpu_ms: f64,
    /// CPU time to prepare and submit the frame and to unpack the readback.
    pub cpu_ms: f64,
    /// Intermediate targets of a multi-pass effect (`--dump-targets`).
    pub dumps: Vec<Dump>,
}

/// An intermediate target read back with the frame.
pub struct Dump {
    pub target: String,
    pub size: (u32, u32),
    /// RGBA8, top row first.
    pub rgba: Vec<u8>,
}

/// Why a frame could not be rendered.
#[derive(Debug, Clone, PartialEq)]
pub enum FrameError {
    /// The GPU did not finish within the timeout (a shader that never ends?).
    Timeout(Duration),
    /// wgpu reported an error (validation, lost device, mapping).
    Device(String),
}

/// Two timestamp queries (start of the first pass, end of the last) and their buffers.
pub struct Timestamps {
    pub set: wgpu::QuerySet,
    resolve: wgpu::Buffer,
    read: wgpu::Buffer,
    period_ns: f64,
}

impl Timestamps {
    /// `None` when the adapter has no timestamp queries.
    pub fn new(gpu: &Gpu) -> Option<Timestamps> {
        gpu.device.features().contains(wgpu::Features::TIMESTAMP_QUERY).then(|| Timestamps {
            set: gpu.device.create_query_set(&wgpu::QuerySetDescriptor {
                label: Some("frame time"),
                ty: wgpu::QueryType::Timestamp,
                count: 2,
            }),
            resolve: gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("timestamps"),
                size: 16,
                usage: wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
                mapped_at_creation: false,
            }),
            read: gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("timestamps read"),
                size: 16,
                usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
                mapped_at_creation: false,
            }),
            period_ns: f64::from(gpu.queue.get_timestamp_period()),
        })
    }

    /// Records the resolve and the copy to the readable buffer.
    pub fn resolve(&self, encoder: &mut wgpu::CommandEncoder) {
        encoder.resolve_query_set(&self.set, 0..2, &self.resolve, 0);
        encoder.copy_buffer_to_buffer(&self.resolve, 0, &self.read, 0, 16);
    }

    /// Milliseconds between the two timestamps (after the frame finished).
    pub fn read_ms(&self, gpu: &Gpu) -> Result<f64, FrameError> {
        let ts = map_read(gpu, &self.read)?;
        let begin = u64::from_le_bytes(ts[0..8].try_into().unwrap_or_default());
        let end = u64::from_le_bytes(ts[8..16].try_into().unwrap_or_default());
        Ok(end.saturating_sub(begin) as f64 * self.period_ns / 1e6)
    }
}

/// The offscreen target frames are drawn into.
pub struct FrameTarget {
    pub width: u32,
    pub height: u32,
    pub mode: ColorMode,
    colors: Vec<Option<wgpu::TextureView>>,
    color0: wgpu::Texture,
    /// The frame's format: the mode's, or a 32-bit integer one for an integer output at
    /// location 0 (shown as its values, [`crate::render::encode::integers_to_rgba8`]).
    format: wgpu::TextureFormat,
    /// Rows arrive bottom-up (the scene was translated with clip y negated).
    bottom_up: bool,
    depth: Option<wgpu::TextureView>,
    readback: wgpu::Buffer,
    padded_row: u32,
    timestamps: Option<Timestamps>,
    /// RGBA8 frame buffers to reuse.
    pub spare: Spare,
}

impl FrameTarget {
    /// A target of `width`×`height` in `mode`; `timestamps`: time frames with GPU
    /// timestamp queries when the adapter has them.
    pub fn new(gpu: &Gpu, scene: &Scene, (width, height, mode): (u32, u32, ColorMode), timestamps: bool) -> FrameTarget {
        let texture = |format: wgpu::TextureFormat, usage: wgpu::TextureUsages, label: &str| {
            gpu.device.create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size: wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        let attach = wgpu::TextureUsages::RENDER_ATTACHMENT;
        let format = match scene.colors.first().copied().flatten() {
            Some(f) if is_integer(f) => f,
            _ => mode.format(),
        };
        let color0 = texture(format, attach | wgpu::TextureUsages::COPY_SRC, "frame");
        let mut colors = Vec::new();
        for (i, f) in scene.colors.iter().enumerate() {
            colors.push(match f {
                None => None,
                Some(_) if i == 0 => Some(color0.create_view(&Default::default())),
                Some(f) => Some(texture(*f, attach, "extra output").create_view(&Default::default())),
            });
        }
        let depth = scene.depth.then(|| texture(wgpu::TextureFormat::Depth32Float, attach, "depth").create_view(&Default::default()));
        let padded_row = padded_row_of(width, format);
        let readback = gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
            size: u64::from(padded_row) * u64::from(height),
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        let timestamps = if timestamps { Timestamps::new(gpu) } else { None };
        let spare = Spare::default();
        FrameTarget {
            width,
            height,
            mode,
            colors,
            color0,
            format,
            bottom_up: scene.flipped_y,
            depth,
            readback,
            padded_row,
            timestamps,
            spare,
        }
    }

    /// How [`Frame::gpu_ms`] is measured on this target.
    pub fn clock(&self) -> GpuClock {
        if self.timestamps.is_some() {
            GpuClock::Timestamps
        } else {
            GpuClock::Wall
        }
    }

    /// Bytes of the readback buffer: rows padded to wgpu's copy alignment.
    pub fn readback_size(width: u32, height: u32, mode: ColorMode) -> u64 {
        u64::from(padded_row(width, mode)) * u64::from(height)
    }
}

fn padded_row(width: u32, mode: ColorMode) -> u32 {
    padded_row_of(width, mode.format())
}

/// Bytes per readback row of `format` (depth formats: their depth aspect): `width` texels
/// rounded up to `COPY_BYTES_PER_ROW_ALIGNMENT`.
pub fn padded_row_of(width: u32, format: wgpu::TextureFormat) -> u32 {
    let bpp = format.block_copy_size(None).or(format.block_copy_size(Some(wgpu::TextureAspect::DepthOnly))).unwrap_or(4);
    (width * bpp).div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT) * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT
}

/// Colour attachments for `views` (None: not attached), cleared to `clear` or, without
/// one, loaded with what earlier passes drew; always stored.
pub fn color_attachments(views: &[Option<wgpu::TextureView>], clear: Option<[f32; 4]>) -> Vec<Option<wgpu::RenderPassColorAttachment<'_>>> {
    let load = match clear {
        Some(c) => wgpu::LoadOp::Clear(wgpu::Color { r: c[0].into(), g: c[1].into(), b: c[2].into(), a: c[3].into() }),
        None => wgpu::LoadOp::Load,
    };
    views
        .iter()
        .map(|v| {
            v.as_ref().map(|view| wgpu::RenderPassColorAttachment {
                view,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations { load, store: wgpu::StoreOp::Store },
            })
        })
        .collect()
}

/// Renders one frame of `scene` for `state` into `target` and reads it back.
pub fn render(gpu: &Gpu, scene: &mut Scene, target: &FrameTarget, state: &FrameState, timeout: Duration) -> Result<Frame, FrameError> {
    let cpu_start = Instant::now();
    let scope = gpu.device.push_error_scope(wgpu::ErrorFilter::Validation);
    if let Err(e) = write_uniforms(gpu, scene, state) {
        // Leave no error scope behind on the shared device.
        let _ = pollster::block_on(scope.pop());
        return Err(e);
    }
    let mut encoder = gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("frame") });
    {
        let attachments = color_attachments(&target.colors, Some(scene.clear));
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some(&scene.name),
            color_attachments: &attachments,
            depth_stencil_attachment: target.depth.as_ref().map(|view| wgpu::RenderPassDepthStencilAttachment {
                view,
                depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Discard }),
                stencil_ops: None,
            }),
            timestamp_writes: target.timestamps.as_ref().map(|t| wgpu::RenderPassTimestampWrites {
                query_set: &t.set,
                beginning_of_pass_write_index: Some(0),
                end_of_pass_write_index: Some(1),
            }),
            occlusion_query_set: None,
            multiview_mask: None,
        });
        record_draw(&mut pass, scene);
    }
    encoder.copy_texture_to_buffer(
        wgpu::TexelCopyTextureInfo {
            texture: &target.color0,
            mip_level: 0,
            origin: wgpu::Origin3d::ZERO,
            aspect: wgpu::TextureAspect::All,
        },
        wgpu::TexelCopyBufferInfo {
            buffer: &target.readback,
            layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(target.padded_row), rows_per_image: Some(target.height) },
        },
        wgpu::Extent3d { width: target.width, height: target.height, depth_or_array_layers: 1 },
    );
    if let Some(t) = &target.timestamps {
        t.resolve(&mut encoder);
    }
    let submitted = gpu.queue.submit([encoder.finish()]);
    if let Some(e) = pollster::block_on(scope.pop()) {
        return Err(FrameError::Device(e.to_string()));
    }
    let mut cpu = cpu_start.elapsed();
    let wall = wait(gpu, submitted, timeout)?;
    let unpack_start = Instant::now();
    let pixels = map_with(gpu, &target.readback, |bytes| unpad(bytes, target))?;
    let gpu_ms = match &target.timestamps {
        Some(t) => t.read_ms(gpu)?,
        None => wall.as_secs_f64() * 1e3,
    };
    if let Some(e) = gpu.take_error() {
        return Err(FrameError::Device(e));
    }
    cpu += unpack_start.elapsed();
    Ok(Frame { pixels, gpu_ms, cpu_ms: cpu.as_secs_f64() * 1e3, dumps: Vec::new() })
}

/// Writes the scene's uniforms for `state` (semantics re-evaluated).
pub fn write_uniforms(gpu: &Gpu, scene: &mut Scene, state: &FrameState) -> Result<(), FrameError> {
    write_uniform_buffers(gpu, &mut scene.uniforms, &scene.module, state)
}

/// Writes `uniforms` (of `module`) for `state`: a drawn scene's or a compute program's.
pub fn write_uniform_buffers(
    gpu: &Gpu,
    uniforms: &mut [(UniformBuffer, wgpu::Buffer)],
    module: &naga::Module,
    state: &FrameState,
) -> Result<(), FrameError> {
    for (data, buffer) in uniforms {
        data.update(module, state).map_err(FrameError::Device)?;
        gpu.queue.write_buffer(buffer, 0, &data.bytes);
    }
    Ok(())
}

/// Waits for a submission, at most `timeout`; returns the time waited.
pub fn wait(gpu: &Gpu, submitted: wgpu::SubmissionIndex, timeout: Duration) -> Result<Duration, FrameError> {
    let start = Instant::now();
    match gpu.device.poll(wgpu::PollType::Wait { submission_index: Some(submitted), timeout: Some(timeout) }) {
        Ok(_) => Ok(start.elapsed()),
        Err(wgpu::PollError::Timeout) => Err(FrameError::Timeout(timeout)),
        Err(e) => Err(FrameError::Device(e.to_string())),
    }
}

/// Records the scene's draw into a render pass: pipeline, bind groups, vertex and index
/// buffers, one draw call.
pub fn record_draw(pass: &mut wgpu::RenderPass<'_>, scene: &Scene) {
    pass.set_pipeline(&scene.pipeline);
    for (group, bg) in &scene.bind_groups {
        pass.set_bind_group(*group, bg, &[]);
    }
    for (slot, buffer) in [&scene.vertex_buffer, &scene.instance_buffer].into_iter().flatten().enumerate() {
        pass.set_vertex_buffer(slot as u32, buffer.slice(..));
    }
    match &scene.draw {
        Draw::Indexed { buffer, count } => {
            pass.set_index_buffer(buffer.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..*count, 0, 0..scene.instances);
        }
        Draw::Vertices(n) => pass.draw(0..*n, 0..scene.instances),
    }
}

/// Copies a storage buffer (usage `COPY_SRC`) to the host as little-endian `u32`s.
pub fn read_u32s(gpu: &Gpu, buffer: &wgpu::Buffer) -> Result<Vec<u32>, FrameError> {
    let staging = gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("probe counts"),
        size: buffer.size(),
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let mut encoder = gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("probe counts") });
    encoder.copy_buffer_to_buffer(buffer, 0, &staging, 0, buffer.size());
    gpu.queue.submit([encoder.finish()]);
    let bytes = map_read(gpu, &staging)?;
    Ok(bytes.chunks_exact(4).map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect())
}

/// Maps a finished buffer, copies its bytes out and unmaps it.
pub fn map_read(gpu: &Gpu, buffer: &wgpu::Buffer) -> Result<Vec<u8>, FrameError> {
    map_with(gpu, buffer, <[u8]>::to_vec)
}

/// Maps a finished buffer, reads its bytes with `read` and unmaps it.
fn map_with<T>(gpu: &Gpu, buffer: &wgpu::Buffer, read: impl FnOnce(&[u8]) -> T) -> Result<T, FrameError> {
    let slice = buffer.slice(..);
    let (tx, rx) = std::sync::mpsc::channel();
    slice.map_async(wgpu::MapMode::Read, move |r| {
        let _ = tx.send(r);
    });
    gpu.device.poll(wgpu::PollType::wait_indefinitely()).map_err(|e| FrameError::Device(e.to_string()))?;
    match rx.recv() {
        Ok(Ok(())) => {}
        _ => return Err(FrameError::Device("the readback buffer could not be mapped".into())),
    }
    let value = read(&slice.get_mapped_range().map_err(|e| FrameError::Device(e.to_string()))?);
    buffer.unmap();
    Ok(value)
}

/// Drops the row padding of the readback and returns the rows top first.
fn unpad(bytes: &[u8], target: &FrameTarget) -> Pixels {
    if is_integer(target.format) {
        let size = (target.width, target.height);
        let values = crate::render::texels::decode_rgba(bytes, target.format, size, target.padded_row, target.bottom_up);
        return match target.mode {
            ColorMode::Unorm8 => Pixels::Rgba8(crate::render::encode::integers_to_rgba8(&values)),
            ColorMode::Float32 => Pixels::Rgba32F(values),
        };
    }
    let bpp = target.mode.format().block_copy_size(None).unwrap_or(4) as usize;
    let row = target.width as usize * bpp;
    let height = target.height as usize;
    let mut out = match target.mode {
        ColorMode::Unorm8 => target.spare.take(row * height),
        ColorMode::Float32 => Vec::with_capacity(row * height),
    };
    for y in 0..height {
        let source_row = if target.bottom_up { height - 1 - y } else { y };
        let start = source_row * target.padded_row as usize;
        out.extend_from_slice(&bytes[start..start + row]);
    }
    match target.mode {
        ColorMode::Unorm8 => Pixels::Rgba8(out),
        ColorMode::Float32 => Pixels::Rgba32F(out.chunks_exact(4).map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect()),
    }
}

/// Whether a colour target holds integers (an `ivec`/`uvec` output).
pub fn is_integer(format: wgpu::TextureFormat) -> bool {
    use wgpu::TextureFormat as F;
    matches!(format, F::Rgba32Sint | F::Rgba32Uint | F::R32Sint | F::R32Uint)
}
