//! Running a multi-pass effect: one [`Scene`] per pass that reaches the output, targets
//! allocated as the [`graph`](crate::graph) plans them (shared textures for targets whose
//! lifetimes do not overlap), every pass recorded into one command buffer per frame, and
//! the output target (with `--dump-targets` every target) read back.

use std::collections::BTreeMap;
use std::time::{Duration, Instant};

use crate::assets::camera;
use crate::back::Translation;
use crate::diag::{Code, Diagnostic};
use crate::front::program::CompiledProgram;
use crate::graph::{self, PassPlan};
use crate::manifest::{Effect, Filter, PassClear, PassDraw, TargetFormat};
use crate::render::device::Gpu;
use crate::render::frames::{self, Dump, Frame, FrameError, GpuClock, Pixels};
use crate::render::scene::{ColorMode, PassBinding, Scene, SceneInput};
use crate::render::semantics::FrameState;

/// One pass, translated and ready to become a scene.
pub struct PassProgram<'a> {
    /// Index into `Effect::passes`.
    pub index: usize,
    pub translation: &'a Translation,
    pub wgsl: &'a str,
    pub program: &'a CompiledProgram,
    /// The pass's view ([`Effect::pass_view`]).
    pub view: &'a Effect,
}

/// How a pass graph is built for one run.
#[derive(Debug, Clone, Copy)]
pub struct GraphOptions {
    pub mode: ColorMode,
    /// The translation negated clip y (rows are flipped back on readback).
    pub flipped_y: bool,
    /// `--dump-targets`: read every target back (the plan keeps every pass).
    pub dump: bool,
    /// The size of the output target at scale 1.
    pub output_size: (u32, u32),
    /// `effectc stress`: passes that draw a mesh draw this variant of it.
    pub degenerate: Option<crate::assets::degenerate::Degenerate>,
    /// Uniforms nobody set are zero, as in GL (`--gl-defaults`).
    pub gl_defaults: bool,
}

/// A pass as it runs every frame.
struct RunningPass {
    /// Index into `Effect::passes`.
    index: usize,
    name: String,
    scene: Scene,
    colors: Vec<Option<wgpu::TextureView>>,
    depth: Option<wgpu::TextureView>,
    keep_depth: bool,
    clear: Option<[f32; 4]>,
    size: (u32, u32),
    /// The targets attached, by location (`None`: nothing attached there).
    color_targets: Vec<Option<String>>,
    /// The depth target; `None` with `depth` set: a depth buffer of the pass's own.
    depth_target: Option<String>,
    /// (sampler, target) of the pass's `samples`.
    samples: Vec<(String, String)>,
}

/// One running pass as another API needs it to draw the same graph (`effectc verify`).
pub struct PassView<'a> {
    pub name: &'a str,
    pub scene: &'a Scene,
    /// Attached colour targets by location, with their formats.
    pub colors: Vec<Option<(&'a str, wgpu::TextureFormat)>>,
    /// The depth target; `own_depth`: a transient depth buffer instead.
    pub depth_target: Option<&'a str>,
    pub own_depth: bool,
    /// Depth is loaded from the target rather than cleared (and kept).
    pub keep_depth: bool,
    pub clear: Option<[f32; 4]>,
    pub size: (u32, u32),
    /// (sampler, target) pairs.
    pub samples: &'a [(String, String)],
}

/// A texture read back after the passes.
struct Readback {
    target: String,
    texture: usize,
    format: wgpu::TextureFormat,
    size: (u32, u32),
    padded_row: u32,
    buffer: wgpu::Buffer,
}

/// A multi-pass effect on the GPU.
pub struct PassGraph {
    pub name: String,
    pub plan: PassPlan,
    passes: Vec<RunningPass>,
    textures: Vec<wgpu::Texture>,
    output: Readback,
    dumps: Vec<Readback>,
    mode: ColorMode,
    flipped_y: bool,
    timestamps: Option<frames::Timestamps>,
    /// What was guessed while building the scenes, as warnings.
    pub warnings: Vec<Diagnostic>,
    pub camera: crate::manifest::CameraDecl,
    pub model: crate::manifest::ModelDecl,
}

/// The format a target is created with: under `--float` every 8- and 16-bit float
/// target becomes 32-bit float so that NaN and Inf survive to the output.
fn effective_format(format: TargetFormat, mode: ColorMode) -> wgpu::TextureFormat {
    match (mode, format) {
        (ColorMode::Float32, TargetFormat::Rgba8 | TargetFormat::Rgba16f) => wgpu::TextureFormat::Rgba32Float,
        (ColorMode::Float32, TargetFormat::R16f) => wgpu::TextureFormat::R32Float,
        (ColorMode::Float32, TargetFormat::Rg16f) => wgpu::TextureFormat::Rg32Float,
        _ => format.wgpu(),
    }
}

impl PassGraph {
    /// Builds the textures and one scene per running pass. `programs` holds the passes
    /// that run (those of `plan`, which was made for `options.output_size`), in order.
    pub fn new(
        gpu: &Gpu,
        effect: &Effect,
        plan: PassPlan,
        programs: &[PassProgram<'_>],
        options: GraphOptions,
    ) -> Result<PassGraph, Vec<Diagnostic>> {
        let GraphOptions { mode, flipped_y, dump, output_size, degenerate, gl_defaults } = options;
        let output_name = effect.output.as_ref().map(|o| o.name.clone()).unwrap_or_default();
        let textures = create_textures(gpu, &plan, mode);
        let view_of = |target: &str| plan.texture_of(target).map(|i| textures[i].create_view(&Default::default()));
        let mut passes = Vec::new();
        let mut warnings = Vec::new();
        let scope = gpu.device.push_error_scope(wgpu::ErrorFilter::Validation);
        for p in programs {
            let decl = &effect.passes[p.index];
            let sampled: BTreeMap<String, (wgpu::TextureView, Filter, String)> = decl
                .samples
                .iter()
                .filter_map(|s| Some((s.sampler.clone(), (view_of(&s.target.name)?, s.filter, s.target.name.clone()))))
                .collect();
            let attached = &plan.attached[p.index];
            let colors: Vec<Option<wgpu::TextureFormat>> = decl
                .targets
                .iter()
                .zip(attached)
                .map(|(t, on)| on.then(|| effect.target(&t.name).map(|d| effective_format(d.format, mode))).flatten())
                .collect();
            let first = decl.targets.first().or(decl.depth.as_ref()).and_then(|t| effect.target(&t.name));
            let size = first.map_or((1, 1), |t| t.size.resolve(output_size));
            let own_depth = decl.depth.is_none() && p.view.render.depth_test && decl.draw != PassDraw::Fullscreen;
            let depth_view = match &decl.depth {
                Some(d) => view_of(&d.name),
                None if own_depth => Some(transient_depth(gpu, size)),
                None => None,
            };
            let binding = PassBinding {
                colors: colors.clone(),
                depth: depth_view.is_some().then_some(wgpu::TextureFormat::Depth32Float),
                sampled: &sampled,
            };
            let input = SceneInput {
                translation: p.translation,
                wgsl: p.wgsl,
                program: p.program,
                effect: Some(p.view),
                mode,
                flipped_y,
                pass: Some(binding),
                degenerate,
                overrides: &[],
                gl_defaults,
            };
            let mut scene = match Scene::new(gpu, &input) {
                Ok(s) => s,
                Err(diags) => {
                    // Leave no error scope behind on the shared device.
                    let _ = pollster::block_on(scope.pop());
                    return Err(diags);
                }
            };
            warnings.append(&mut scene.warnings);
            let color_views = decl.targets.iter().zip(attached).map(|(t, on)| if *on { view_of(&t.name) } else { None }).collect();
            let color_targets = decl.targets.iter().zip(attached).map(|(t, on)| on.then(|| t.name.clone())).collect();
            passes.push(RunningPass {
                index: p.index,
                name: decl.name.clone(),
                scene,
                colors: color_views,
                depth: depth_view,
                keep_depth: decl.depth.is_some(),
                clear: match decl.clear {
                    PassClear::Keep => None,
                    PassClear::Color(c) => Some(c),
                    PassClear::Default => Some(p.view.render.clear),
                },
                size,
                color_targets,
                depth_target: decl.depth.as_ref().map(|d| d.name.clone()),
                samples: decl.samples.iter().map(|s| (s.sampler.clone(), s.target.name.clone())).collect(),
            });
        }
        if let Some(e) = pollster::block_on(scope.pop()) {
            let file = programs.first().map(|p| p.translation.file).unwrap_or(effect.file);
            return Err(vec![Diagnostic::new(Code::PipelineRejected, "wgpu rejected the pass graph")
                .in_file(file)
                .with_note(e.to_string())]);
        }
        let readback = |target: &str| readback(gpu, &plan, mode, target);
        let Some(output) = readback(&output_name) else {
            return Err(vec![Diagnostic::new(Code::Unrenderable, "no pass writes the output target").in_file(effect.file)]);
        };
        let dumps = if dump {
            effect.targets.iter().filter(|t| t.name != output_name).filter_map(|t| readback(&t.name)).collect()
        } else {
            Vec::new()
        };
        // Passes sharing a stage file would report the same guess once each.
        crate::diag::dedup(&mut warnings);
        Ok(PassGraph {
            name: effect.name.clone(),
            plan,
            passes,
            textures,
            output,
            dumps,
            mode,
            flipped_y,
            timestamps: frames::Timestamps::new(gpu),
            warnings,
            camera: effect.camera.clone().unwrap_or_default(),
            model: effect.model.clone(),
        })
    }

    /// Every running pass in order, as another API draws it.
    pub fn pass_views(&self) -> Vec<PassView<'_>> {
        self.passes
            .iter()
            .map(|p| PassView {
                name: &p.name,
                scene: &p.scene,
                colors: p.color_targets.iter().zip(&p.scene.colors).map(|(t, f)| Some((t.as_deref()?, (*f)?))).collect(),
                depth_target: p.depth_target.as_deref(),
                own_depth: p.depth.is_some() && p.depth_target.is_none(),
                keep_depth: p.keep_depth,
                clear: p.clear,
                size: p.size,
                samples: &p.samples,
            })
            .collect()
    }

    /// The name of the target the graph's frames show.
    pub fn output_target(&self) -> &str {
        &self.output.target
    }

    /// The scene of every running pass, with its index into `Effect::passes`.
    pub fn scenes(&self) -> impl Iterator<Item = (usize, &Scene)> {
        self.passes.iter().map(|p| (p.index, &p.scene))
    }

    pub fn scenes_mut(&mut self) -> impl Iterator<Item = (usize, &mut Scene)> {
        self.passes.iter_mut().map(|p| (p.index, &mut p.scene))
    }

    pub fn clock(&self) -> GpuClock {
        if self.timestamps.is_some() {
            GpuClock::Timestamps
        } else {
            GpuClock::Wall
        }
    }

    /// The output size.
    pub fn size(&self) -> (u32, u32) {
        self.output.size
    }

    /// Which passes run, which are skipped and why, where targets live (for `--explain`).
    pub fn explain(&self, effect: &Effect) -> String {
        let mut text = String::new();
        for (i, pass) in effect.passes.iter().enumerate() {
            if !self.plan.runs[i] {
                text.push_str(&format!(
                    "  pass {:<12} skipped: nothing it writes ({}) reaches the output\n",
                    pass.name,
                    graph::written(pass).join(", ")
                ));
                continue;
            }
            let mut targets: Vec<String> = Vec::new();
            for (t, on) in pass.targets.iter().zip(&self.plan.attached[i]) {
                targets.push(if *on { t.name.clone() } else { format!("{} (dropped: never read)", t.name) });
            }
            if let Some(d) = &pass.depth {
                targets.push(format!("depth {}", d.name));
            }
            let reads = graph::reads(pass);
            text.push_str(&format!(
                "  pass {:<12} runs: draws into {}{}\n",
                pass.name,
                targets.join(", "),
                if reads.is_empty() { String::new() } else { format!("; reads {}", reads.join(", ")) }
            ));
            // What feeds each input, uniform and sampler of the pass (`--verbose`).
            if let Some(running) = self.passes.iter().find(|p| p.index == i) {
                text.push_str(&format!("    {}\n", running.scene.describe));
            }
        }
        for (k, t) in self.plan.textures.iter().enumerate() {
            let users: Vec<String> = t
                .targets
                .iter()
                .map(|(n, a, b)| {
                    format!("{n} (passes {}–{})", effect.passes[*a].name, effect.passes.get(*b).map_or("end", |p| p.name.as_str()))
                })
                .collect();
            text.push_str(&format!("  texture {k}: {} {}x{}: {}\n", t.format.name(), t.size.0, t.size.1, users.join(", then ")));
        }
        text
    }

    /// One frame: every running pass in order, then the readbacks.
    pub fn render(&mut self, gpu: &Gpu, state: &FrameState, timeout: Duration) -> Result<Frame, FrameError> {
        let cpu_start = Instant::now();
        let scope = gpu.device.push_error_scope(wgpu::ErrorFilter::Validation);
        for p in &mut self.passes {
            let aspect = p.size.0 as f32 / p.size.1 as f32;
            let pass_state = FrameState {
                size: p.size,
                view: camera::view_at(&p.scene.camera, state.time, aspect),
                model: camera::model_at(&p.scene.model, state.time),
                ..*state
            };
            if let Err(e) = frames::write_uniforms(gpu, &mut p.scene, &pass_state) {
                let _ = pollster::block_on(scope.pop());
                return Err(e);
            }
        }
        let mut encoder = gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some(&self.name) });
        let last = self.passes.len().saturating_sub(1);
        for (k, p) in self.passes.iter().enumerate() {
            let attachments = frames::color_attachments(&p.colors, p.clear);
            let timestamp_writes = self.timestamps.as_ref().filter(|_| k == 0 || k == last).map(|t| wgpu::RenderPassTimestampWrites {
                query_set: &t.set,
                beginning_of_pass_write_index: (k == 0).then_some(0),
                end_of_pass_write_index: (k == last).then_some(1),
            });
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some(&p.name),
                color_attachments: &attachments,
                depth_stencil_attachment: p.depth.as_ref().map(|view| wgpu::RenderPassDepthStencilAttachment {
                    view,
                    depth_ops: Some(wgpu::Operations {
                        load: if p.clear.is_some() || !p.keep_depth { wgpu::LoadOp::Clear(1.0) } else { wgpu::LoadOp::Load },
                        store: if p.keep_depth { wgpu::StoreOp::Store } else { wgpu::StoreOp::Discard },
                    }),
                    stencil_ops: None,
                }),
                timestamp_writes,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            frames::record_draw(&mut pass, &p.scene);
        }
        for r in std::iter::once(&self.output).chain(&self.dumps) {
            let aspect =
                if r.format == wgpu::TextureFormat::Depth32Float { wgpu::TextureAspect::DepthOnly } else { wgpu::TextureAspect::All };
            encoder.copy_texture_to_buffer(
                wgpu::TexelCopyTextureInfo { texture: &self.textures[r.texture], mip_level: 0, origin: wgpu::Origin3d::ZERO, aspect },
                wgpu::TexelCopyBufferInfo {
                    buffer: &r.buffer,
                    layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(r.padded_row), rows_per_image: Some(r.size.1) },
                },
                wgpu::Extent3d { width: r.size.0, height: r.size.1, depth_or_array_layers: 1 },
            );
        }
        if let Some(t) = &self.timestamps {
            t.resolve(&mut encoder);
        }
        let submitted = gpu.queue.submit([encoder.finish()]);
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(FrameError::Device(e.to_string()));
        }
        let cpu = cpu_start.elapsed();
        let wall = frames::wait(gpu, submitted, timeout)?;
        let unpack_start = Instant::now();
        let gpu_ms = match &self.timestamps {
            Some(t) => t.read_ms(gpu)?,
            None => wall.as_secs_f64() * 1e3,
        };
        let output = self.read(gpu, &self.output)?;
        let pixels = match (self.mode, self.output.format) {
            (ColorMode::Unorm8, _) => Pixels::Rgba8(crate::render::encode::float_to_rgba8(&output)),
            (ColorMode::Float32, _) => Pixels::Rgba32F(output),
        };
        let mut dumps = Vec::new();
        for r in &self.dumps {
            let texels = self.read(gpu, r)?;
            let rgba = if r.format == wgpu::TextureFormat::Depth32Float {
                texels.iter().map(|&d| d.clamp(0.0, 1.0)).collect::<Vec<_>>()
            } else {
                texels
            };
            dumps.push(Dump { target: r.target.clone(), size: r.size, rgba: crate::render::encode::float_to_rgba8(&rgba) });
        }
        if let Some(e) = gpu.take_error() {
            return Err(FrameError::Device(e));
        }
        let cpu_ms = (cpu + unpack_start.elapsed()).as_secs_f64() * 1e3;
        Ok(Frame { pixels, gpu_ms, cpu_ms, dumps })
    }

    /// Maps one readback and decodes it to RGBA floats, top row first.
    fn read(&self, gpu: &Gpu, r: &Readback) -> Result<Vec<f32>, FrameError> {
        let bytes = frames::map_read(gpu, &r.buffer)?;
        Ok(crate::render::texels::decode_rgba(&bytes, r.format, r.size, r.padded_row, self.flipped_y))
    }
}

fn transient_depth(gpu: &Gpu, (w, h): (u32, u32)) -> wgpu::TextureView {
    gpu.device
        .create_texture(&wgpu::TextureDescriptor {
            label: Some("pass depth"),
            size: wgpu::Extent3d { width: w, height: h, depth_or_array_layers: 1 },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: wgpu::TextureFormat::Depth32Float,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
            view_formats: &[],
        })
        .create_view(&Default::default())
}

/// One texture per physical texture of the plan (targets with disjoint lifetimes share).
fn create_textures(gpu: &Gpu, plan: &PassPlan, mode: ColorMode) -> Vec<wgpu::Texture> {
    plan.textures
        .iter()
        .map(|t| {
            let names: Vec<&str> = t.targets.iter().map(|(n, _, _)| n.as_str()).collect();
            gpu.device.create_texture(&wgpu::TextureDescriptor {
                label: Some(&names.join("+")),
                size: wgpu::Extent3d { width: t.size.0, height: t.size.1, depth_or_array_layers: 1 },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: effective_format(t.format, mode),
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_SRC,
                view_formats: &[],
            })
        })
        .collect()
}

/// A readback buffer for `target`'s texture (`None` when no running pass touches it).
fn readback(gpu: &Gpu, plan: &PassPlan, mode: ColorMode, target: &str) -> Option<Readback> {
    let texture = plan.texture_of(target)?;
    let t = &plan.textures[texture];
    let format = effective_format(t.format, mode);
    let padded_row = frames::padded_row_of(t.size.0, format);
    Some(Readback {
        target: target.to_owned(),
        texture,
        format,
        size: t.size,
        padded_row,
        buffer: gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(target),
            size: u64::from(padded_row) * u64::from(t.size.1),
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        }),
    })
}
