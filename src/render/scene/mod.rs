//! Everything one effect needs on the GPU, created once per run: the pipeline, the vertex
//! and index buffers, textures and samplers, uniform buffers and bind groups.
//!
//! The manifest drives it; what the manifest leaves open is guessed and reported as a
//! warning at the declaration in the user's GLSL (attributes by name, uniforms by name,
//! samplers get a placeholder texture, the mesh follows what the vertex stage reads).

pub(crate) mod bindings;
mod mesh_choice;
pub(crate) mod plan;
pub(crate) mod pulled;
pub mod replay;
pub(crate) mod textures;

use bindings::{bind_groups, buffer_init};
use mesh_choice::MeshNote;
use textures::Textures;

use std::collections::BTreeMap;

use crate::assets::degenerate::Degenerate;
use crate::assets::mesh::Mesh;
use crate::back::Translation;
use crate::diag::{Code, Diagnostic, FileId};
use crate::front::program::CompiledProgram;
use crate::front::syntax::Storage;
use crate::manifest::{Blend, CameraDecl, Cull, Effect, Filter, MeshAttribute, ModelDecl};
use crate::render::attributes;
use crate::render::device::{color_formats, topology, Gpu, PipelineSpec};
use crate::render::uniforms::UniformBuffer;

/// The colour format frames are rendered into.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ColorMode {
    /// Rgba8Unorm, written as PNG.
    Unorm8,
    /// Rgba32Float, scanned for NaN and Inf.
    Float32,
}

impl ColorMode {
    pub fn format(self) -> wgpu::TextureFormat {
        match self {
            ColorMode::Unorm8 => wgpu::TextureFormat::Rgba8Unorm,
            ColorMode::Float32 => wgpu::TextureFormat::Rgba32Float,
        }
    }
}

/// Refuses what cannot be drawn into frames: no vertex stage, or (outside a pass) a 16-bit
/// float colour output (integer outputs are drawn into an integer frame and shown as their
/// values).
fn drawable(r: &crate::back::reflect::Reflection, in_pass: bool) -> Result<(), Diagnostic> {
    if !r.entry_points.iter().any(|e| e.name == "vs_main") {
        return Err(Diagnostic::new(Code::Unrenderable, "the program has no vertex stage to draw with")
            .with_help("add a vertex stage (a full-screen triangle is enough for a post effect)"));
    }
    let Some(first) = r.fragment_outputs.first().filter(|o| !in_pass && o.location == 0 && o.wgsl_type.contains("f16")) else {
        return Ok(());
    };
    let output =
        if first.name.is_empty() { "the fragment output at location 0".to_string() } else { format!("fragment output `{}`", first.name) };
    // wgpu matches a 16-bit float output with no colour target (WebGPU allows it).
    Err(Diagnostic::new(Code::Unrenderable, format!("{output} is a 16-bit float; wgpu draws frames only from 32-bit float colours")))
}

/// How the mesh is drawn.
pub enum Draw {
    Indexed {
        buffer: wgpu::Buffer,
        count: u32,
    },
    /// Vertices without an index buffer (a vertex stage that makes its own positions).
    Vertices(u32),
}

/// One effect's GPU state.
pub struct Scene {
    pub name: String,
    pub module: naga::Module,
    /// The values the program gives uniforms: GLSL initializers, `#pragma parameter`
    /// defaults ([`front::initial_values`](crate::front::initial_values)).
    pub initial: Vec<crate::front::initial_values::Initial>,
    /// Block matrices stored row-major ([`front::initial_values::row_major`](crate::front::initial_values::row_major)).
    pub row_major: Vec<(String, String)>,
    pub pipeline: wgpu::RenderPipeline,
    pub vertex_buffer: Option<wgpu::Buffer>,
    /// Per-instance attributes (vertex buffer slot after the mesh's, or 0 without one).
    pub instance_buffer: Option<wgpu::Buffer>,
    pub draw: Draw,
    /// Instances per draw (1 without `[instances]`).
    pub instances: u32,
    pub bind_groups: Vec<(u32, wgpu::BindGroup)>,
    pub uniforms: Vec<(UniformBuffer, wgpu::Buffer)>,
    /// Colour formats by output location (location 0 is the frame).
    pub colors: Vec<Option<wgpu::TextureFormat>>,
    pub depth: bool,
    pub clear: [f32; 4],
    pub camera: CameraDecl,
    pub model: ModelDecl,
    /// What was guessed, as warnings.
    pub warnings: Vec<Diagnostic>,
    /// A one-line description of the mesh and its attributes, for `--verbose`.
    pub describe: String,
    /// Framebuffer rows run bottom-up (clip y negated): readback flips them.
    pub flipped_y: bool,
    /// The storage buffers the program binds, by name (zeroed and read back by callers
    /// that count with them, like `stress`'s instrumented programs).
    pub storage: Vec<(String, wgpu::Buffer)>,
    /// What the stress variant of the mesh changed; `None` without one, or when the scene
    /// draws no mesh it could change (a full-screen pass, vertices made by the shader).
    pub degenerate: Option<String>,
    /// The scene's CPU data, for drawing it again with another API (`effectc verify`).
    pub replay: replay::Replay,
}

/// What a scene is built from.
pub struct SceneInput<'a> {
    pub translation: &'a Translation,
    pub wgsl: &'a str,
    pub program: &'a CompiledProgram,
    pub effect: Option<&'a Effect>,
    pub mode: ColorMode,
    /// The translation negated clip y (`TranslateOptions::flip_y`).
    pub flipped_y: bool,
    /// Set for one pass of a multi-pass effect: its attachments and sampled targets.
    pub pass: Option<PassBinding<'a>>,
    /// `effectc stress`: draw a degenerate variant of the mesh.
    pub degenerate: Option<Degenerate>,
    /// Uniform values over the effect's (`--set`, a bench knob, a stress case); they reach
    /// bare stage files too, which have no effect.
    pub overrides: &'a [(String, crate::manifest::UniformValue)],
    /// Uniforms nobody set are zero, as in GL, instead of guessed (`--gl-defaults`).
    pub gl_defaults: bool,
}

/// What the pass graph decides for one pass's scene.
pub struct PassBinding<'a> {
    /// Colour formats by output location; `None` where nothing is attached.
    pub colors: Vec<Option<wgpu::TextureFormat>>,
    /// The depth attachment's format, when the pass has one.
    pub depth: Option<wgpu::TextureFormat>,
    /// Sampler uniforms bound to earlier targets: the target's view, the filter and the
    /// target's name.
    pub sampled: &'a BTreeMap<String, (wgpu::TextureView, Filter, String)>,
}

impl SceneInput<'_> {
    /// What the scene's CPU-side decisions are made from.
    pub(crate) fn plan_input(&self) -> plan::PlanInput<'_> {
        plan::PlanInput {
            translation: self.translation,
            program: self.program,
            effect: self.effect,
            pass: self.pass.as_ref().map(|p| p.sampled.iter().map(|(s, (_, _, t))| (s.clone(), t.clone())).collect()),
            overrides: self.overrides,
            gl_defaults: self.gl_defaults,
        }
    }
}

impl Scene {
    /// The storage buffer the program binds under `name`.
    pub fn storage_buffer(&self, name: &str) -> Option<&wgpu::Buffer> {
        self.storage.iter().find(|(n, _)| n == name).map(|(_, b)| b)
    }

    pub fn new(gpu: &Gpu, input: &SceneInput<'_>) -> Result<Scene, Vec<Diagnostic>> {
        let t = input.translation;
        let r = &t.reflection;
        let first_file = input.program.stages[0].syntax.file;
        drawable(r, input.pass.is_some()).map_err(|d| vec![d.in_file(first_file)])?;
        let plan_input = input.plan_input();
        let plan::Plan { mesh, mesh_note, choices, uniforms: uniform_data, textures: texture_plan, warnings, describe, initial, row_major } =
            plan::plan(&plan_input)?;
        let instances = input.effect.and_then(|e| e.instances.as_ref());
        let read: Vec<MeshAttribute> = choices.iter().filter_map(|c| c.attribute).collect();
        let (mesh, degenerate) = match input.degenerate {
            Some(d) if matches!(mesh_note, MeshNote::Manifest | MeshNote::Cube | MeshNote::Quad) && d.affects(&read) => {
                let (changed, what) = d.apply(&mesh);
                (changed, Some(what))
            }
            _ => (mesh, None),
        };
        let mut interleaved = attributes::interleave(&choices, &mesh);
        let instanced = instances.and_then(|d| attributes::instance_buffer(&r.vertex_inputs, d));
        // A folded geometry program pulls its primitives from two storage buffers instead.
        let own_vertices = matches!(mesh_note, MeshNote::OwnVertices);
        let pulled =
            pulled::for_geometry(r, &choices, &mesh, own_vertices, instanced.is_some()).map_err(|d| vec![d.in_file(first_file)])?;
        let replay_vertices = interleaved.clone();
        if pulled.is_some() {
            interleaved.attributes.clear();
        }

        let scope = gpu.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let render = input.effect.map(|e| e.render.clone()).unwrap_or_default();
        let (depth_format, colors) = match &input.pass {
            Some(p) => (p.depth, p.colors.clone()),
            None => {
                let colors = color_formats(r, input.mode.format());
                // A pipeline needs an attachment: a program that writes no colour (it only
                // discards, or stores to images) draws into a depth buffer of its own.
                let no_color = colors.iter().all(Option::is_none);
                // WebGPU refuses a pipeline whose fragment stage writes depth without a
                // depth attachment (GL writes into the default framebuffer's).
                let writes_depth = writes_frag_depth(&t.module);
                let depth = no_color || writes_depth || (render.depth_test && !matches!(mesh_note, MeshNote::Fullscreen));
                (depth.then_some(wgpu::TextureFormat::Depth32Float), colors)
            }
        };
        let depth = depth_format.is_some();
        let spec = PipelineSpec {
            label: &t.name,
            wgsl: input.wgsl,
            vertex_stride: interleaved.stride,
            attributes: &interleaved.attributes,
            instance_stride: instanced.as_ref().map_or(0, |i| i.stride),
            instance_attributes: instanced.as_ref().map_or(&[], |i| &i.attributes),
            colors: colors.clone(),
            blend: blend_state(render.blend),
            depth: depth_format,
            depth_write: render.depth_write,
            depth_compare: depth_compare(render.depth_compare),
            cull: match render.cull {
                Cull::None => None,
                Cull::Back => Some(wgpu::Face::Back),
                Cull::Front => Some(wgpu::Face::Front),
            },
            // Translated with clip y negated: GL's counter-clockwise front faces arrive
            // clockwise in the framebuffer.
            front_face: if input.flipped_y { wgpu::FrontFace::Cw } else { wgpu::FrontFace::Ccw },
            fragment: r.entry_points.iter().any(|e| e.name == "fs_main"),
            topology: topology(r),
            layout: None,
        };
        let pipeline = bindings::pipeline(gpu, &spec, r).map_err(|e| vec![pipeline_error(first_file, &e)])?;

        let vertex_buffer =
            (!interleaved.attributes.is_empty()).then(|| buffer_init(gpu, "vertices", &interleaved.bytes, wgpu::BufferUsages::VERTEX));
        let instance_buffer = instanced.as_ref().map(|i| buffer_init(gpu, "instances", &i.bytes, wgpu::BufferUsages::VERTEX));
        let draw = draw_of(gpu, r, pulled.as_ref().map(|p| p.count), &mesh_note, &mesh);
        let uniforms = bindings::uniform_buffers(gpu, uniform_data);
        let textures = Textures::create(gpu, input, &texture_plan)?;
        let filled = pulled.as_ref().map(|p| p.buffers()).unwrap_or_default();
        let layout_of = |group| pipeline.get_bind_group_layout(group);
        let image_side = (bindings::IMAGE_SIDE, bindings::IMAGE_SIDE);
        let bindings::Bound { groups: bind_groups, storage, .. } =
            bind_groups(gpu, &layout_of, r, (&uniforms, &textures), &filled, image_side);
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(vec![pipeline_error(first_file, &e.to_string())]);
        }
        let replay = replay::Replay {
            draw: replay_draw(r, &mesh, own_vertices),
            instances: instanced.clone(),
            render: render.clone(),
            depth,
            ..replay_of(input, replay_vertices, &textures)
        };
        Ok(Scene {
            name: t.name.clone(),
            module: t.module.clone(),
            pipeline,
            vertex_buffer,
            instance_buffer,
            draw,
            instances: instances.map_or(1, |d| d.count),
            bind_groups,
            uniforms,
            colors,
            depth,
            clear: render.clear,
            camera: input.effect.and_then(|e| e.camera.clone()).unwrap_or_default(),
            model: input.effect.map(|e| e.model.clone()).unwrap_or_default(),
            warnings,
            describe,
            flipped_y: input.flipped_y,
            storage,
            degenerate,
            replay,
            initial,
            row_major,
        })
    }
}

/// The CPU data of a scene that its draw does not decide.
fn replay_of(input: &SceneInput<'_>, vertices: attributes::Interleaved, textures: &Textures) -> replay::Replay {
    let plan = &input.program.plan;
    replay::Replay {
        vertices,
        instances: None,
        draw: replay::ReplayDraw { primitive: "triangles", patch_vertices: 0, indices: None, count: 0 },
        textures: textures.replay.clone(),
        samplers: textures.replay_samplers.clone(),
        render: Default::default(),
        depth: false,
        inputs: input.translation.reflection.vertex_inputs.iter().map(|v| (v.name.clone(), v.location)).collect(),
        plan_textures: plan.textures.iter().map(|t| (t.user_name.clone(), t.name.clone(), t.sampler_name.clone())).collect(),
        outputs: input
            .translation
            .reflection
            .fragment_outputs
            .iter()
            .map(|o| (o.location, declared_components(input.program, &o.name, &o.wgsl_type)))
            .collect(),
    }
}

/// How wgpu draws: the pulled vertices of a folded geometry program, the program's own
/// three vertices, or the mesh's triangles (from GL's provoking vertex when `flat`
/// varyings need it).
fn draw_of(gpu: &Gpu, r: &crate::back::reflect::Reflection, pulled: Option<u32>, mesh_note: &MeshNote, mesh: &Mesh) -> Draw {
    let own = matches!(mesh_note, MeshNote::OwnVertices);
    match (pulled, own, flat_varyings(r)) {
        (Some(count), _, _) => Draw::Vertices(count),
        (None, true, false) => Draw::Vertices(3),
        (None, _, flat) => {
            let triangles = pulled::triangles(mesh, own);
            let indices = if flat { gl_provoking_first(&triangles) } else { triangles };
            let bytes: Vec<u8> = indices.iter().flat_map(|i| i.to_le_bytes()).collect();
            Draw::Indexed { buffer: buffer_init(gpu, "indices", &bytes, wgpu::BufferUsages::INDEX), count: indices.len() as u32 }
        }
    }
}

/// The program passes `flat` varyings from the vertex stage: which vertex provokes them
/// matters.
fn flat_varyings(r: &crate::back::reflect::Reflection) -> bool {
    r.varyings.iter().any(|v| v.interpolation == Some("flat"))
}

/// Every triangle `(a, b, c)` as `(c, a, b)`: the same triangle, wound the same way, whose
/// first vertex — the one WebGPU takes `flat` values from — is GL's provoking vertex, the
/// last.
fn gl_provoking_first(triangles: &[u32]) -> Vec<u32> {
    triangles.chunks_exact(3).flat_map(|t| [t[2], t[0], t[1]]).collect()
}

/// The components of fragment output `name` as the GLSL declares it (the translation may
/// widen a `vec2` output to fill its target), else as reflected.
fn declared_components(program: &CompiledProgram, name: &str, wgsl_type: &str) -> u32 {
    let declared = program.stage(crate::stage::StageKind::Fragment).and_then(|f| {
        f.syntax.globals.iter().find(|g| g.storage == Storage::Out && g.name == name).map(|g| replay::components(&g.ty.base))
    });
    declared.unwrap_or_else(|| replay::components(wgsl_type))
}

/// How GL draws the original program: the mesh's triangles, the program's own three
/// vertices, or a geometry stage's input primitives or the patches made from them.
fn replay_draw(r: &crate::back::reflect::Reflection, mesh: &Mesh, own_vertices: bool) -> replay::ReplayDraw {
    match &r.geometry {
        Some(g) if g.tessellation.is_some() => {
            let indices = pulled::patches(g.index_buffer.stride, mesh, own_vertices);
            let patch_vertices = g.index_buffer.stride;
            replay::ReplayDraw { primitive: "patches", patch_vertices, count: indices.len() as u32, indices: Some(indices) }
        }
        Some(g) => {
            let indices = pulled::primitive_indices(g.input_primitive, mesh, own_vertices);
            replay::ReplayDraw { primitive: g.input_primitive, patch_vertices: 0, count: indices.len() as u32, indices: Some(indices) }
        }
        None if own_vertices => replay::ReplayDraw { primitive: "triangles", patch_vertices: 0, indices: None, count: 3 },
        None => {
            let triangles = pulled::triangles(mesh, false);
            replay::ReplayDraw { primitive: "triangles", patch_vertices: 0, count: triangles.len() as u32, indices: Some(triangles) }
        }
    }
}

/// A manifest key for a GLSL name: quoted when it has `.` or `[`.
pub(super) fn toml_key(name: &str) -> String {
    if name.contains(['.', '[']) {
        format!("\"{name}\"")
    } else {
        name.to_string()
    }
}

fn depth_compare(c: crate::manifest::DepthCompare) -> wgpu::CompareFunction {
    use crate::manifest::DepthCompare as D;
    use wgpu::CompareFunction as C;
    match c {
        D::Never => C::Never,
        D::Less => C::Less,
        D::Equal => C::Equal,
        D::LessEqual => C::LessEqual,
        D::Greater => C::Greater,
        D::NotEqual => C::NotEqual,
        D::GreaterEqual => C::GreaterEqual,
        D::Always => C::Always,
    }
}

fn blend_state(blend: Blend) -> Option<wgpu::BlendState> {
    use wgpu::{BlendComponent, BlendFactor as F, BlendOperation, BlendState};
    let colour = |src, dst| BlendComponent { src_factor: src, dst_factor: dst, operation: BlendOperation::Add };
    match blend {
        Blend::None => None,
        Blend::Alpha => Some(BlendState::ALPHA_BLENDING),
        Blend::Additive => Some(BlendState { color: colour(F::SrcAlpha, F::One), alpha: colour(F::One, F::One) }),
        Blend::Premultiplied => Some(BlendState::PREMULTIPLIED_ALPHA_BLENDING),
    }
}

pub(crate) fn pipeline_error(file: FileId, message: &str) -> Diagnostic {
    Diagnostic::new(Code::PipelineRejected, "wgpu rejected the translated program")
        .in_file(file)
        .with_note(message.trim().to_string())
        .with_note("the WGSL effectc renders is what `effectc translate --to wgsl` writes")
}

/// Whether the fragment entry point of `module` writes `frag_depth` (`gl_FragDepth`).
fn writes_frag_depth(module: &naga::Module) -> bool {
    let depth = |b: &Option<naga::Binding>| matches!(b, Some(naga::Binding::BuiltIn(naga::BuiltIn::FragDepth)));
    module.entry_points.iter().filter(|e| e.stage == naga::ShaderStage::Fragment).filter_map(|e| e.function.result.as_ref()).any(|r| {
        depth(&r.binding)
            || matches!(&module.types[r.ty].inner, naga::TypeInner::Struct { members, .. } if members.iter().any(|m| depth(&m.binding)))
    })
}
