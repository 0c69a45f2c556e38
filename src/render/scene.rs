//! Everything one effect needs on the GPU, created once per run: the pipeline, the vertex
//! and index buffers, textures and samplers, uniform buffers and bind groups.
//!
//! The manifest drives it; what the manifest leaves open is guessed and reported as a
//! warning at the declaration in the user's GLSL (attributes by name, uniforms by name,
//! samplers get a placeholder texture, the mesh follows what the vertex stage reads).

use std::collections::BTreeMap;

use crate::assets::degenerate::Degenerate;
use crate::assets::mesh::Mesh;
use crate::assets::texture::{self, TexelImage};
use crate::back::reflect::{BindingInfo, Reflection};
use crate::back::Translation;
use crate::diag::{Diagnostic, FileId};
use crate::front::program::CompiledProgram;
use crate::front::syntax::Storage;
use crate::manifest::{Blend, BuiltinMesh, CameraDecl, Cull, Effect, Filter, MeshSource, ModelDecl, TextureKind, TextureSource, Wrap};
use crate::render::attributes;
use crate::render::device::{color_formats, Gpu, PipelineSpec};
use crate::render::uniforms::{self, UniformBuffer};
use crate::stage::StageKind;

/// A vertex input was matched to a mesh attribute by a guess.
pub const W_ATTRIBUTE_GUESSED: &str = "W0401";
/// A vertex input no mesh attribute fits: it reads zeros.
pub const W_ATTRIBUTE_ZERO: &str = "W0402";
/// A uniform the manifest does not give a value: it got a guessed one.
pub const W_UNIFORM_GUESSED: &str = "W0403";
/// A sampler the manifest binds no texture to: it reads a placeholder.
pub const W_TEXTURE_PLACEHOLDER: &str = "W0404";
/// The mesh was chosen by effectc (no `[mesh]`).
pub const W_MESH_GUESSED: &str = "W0405";
/// wgpu refused the pipeline or a resource (a validation error).
pub const E_PIPELINE: &str = "E0402";
/// A texture image or mesh file could not be loaded.
pub const E_ASSET: &str = "E0406";
/// The program cannot be rendered (no vertex stage, a stage WebGPU lacks, …).
pub const E_UNRENDERABLE: &str = "E0408";

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
}

/// What the pass graph decides for one pass's scene.
pub struct PassBinding<'a> {
    /// Colour formats by output location; `None` where nothing is attached.
    pub colors: Vec<Option<wgpu::TextureFormat>>,
    /// The depth attachment's format, when the pass has one.
    pub depth: Option<wgpu::TextureFormat>,
    /// Sampler uniforms bound to earlier targets: the target's view and the filter.
    pub sampled: &'a BTreeMap<String, (wgpu::TextureView, Filter)>,
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
        let mut warnings = Vec::new();
        if !r.entry_points.iter().any(|e| e.name == "vs_main") {
            return Err(vec![Diagnostic::error(E_UNRENDERABLE, "the program has no vertex stage to draw with")
                .in_file(first_file)
                .with_help("add a vertex stage (a full-screen triangle is enough for a post effect)")]);
        }
        if let Some(first) = r.fragment_outputs.first().filter(|o| input.pass.is_none() && o.location == 0 && !o.wgsl_type.contains("f32"))
        {
            return Err(vec![Diagnostic::error(
                E_UNRENDERABLE,
                format!("fragment output `{}` is an integer; frames can only show float colours", first.name),
            )
            .in_file(first_file)]);
        }
        let (mesh, mesh_note) = choose_mesh(input, &mut warnings)?;
        let explicit = input.effect.and_then(|e| e.mesh.as_ref()).map(|m| m.attributes.clone()).unwrap_or_default();
        let instances = input.effect.and_then(|e| e.instances.as_ref());
        let per_instance = |name: &str| instances.is_some_and(|d| d.attributes.iter().any(|a| a.input == name));
        let per_vertex: Vec<_> = r.vertex_inputs.iter().filter(|v| !per_instance(&v.name)).cloned().collect();
        let choices = attributes::choose(&per_vertex, &explicit, &mesh);
        let read: Vec<&str> = choices.iter().filter_map(|c| c.attribute).collect();
        let (mesh, degenerate) = match input.degenerate {
            Some(d) if matches!(mesh_note, MeshNote::Manifest | MeshNote::Cube) && d.affects(&read) => {
                let (changed, what) = d.apply(&mesh);
                (changed, Some(what))
            }
            _ => (mesh, None),
        };
        // A full-screen pass draws effectc's triangle, whose attributes (position, uv) are
        // documented: matching them by name is the contract, not a guess worth a warning.
        let fullscreen_pass = input.pass.is_some() && matches!(mesh_note, MeshNote::Fullscreen);
        report_attributes(input.program, &choices, fullscreen_pass, &mut warnings);
        let interleaved = attributes::interleave(&choices, &mesh);
        let instanced = instances.and_then(|d| attributes::instance_buffer(&r.vertex_inputs, d));

        let scope = gpu.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let render = input.effect.map(|e| e.render.clone()).unwrap_or_default();
        let (depth_format, colors) = match &input.pass {
            Some(p) => (p.depth, p.colors.clone()),
            None => {
                let depth = render.depth_test && !matches!(mesh_note, MeshNote::Fullscreen);
                (depth.then_some(wgpu::TextureFormat::Depth32Float), color_formats(r, input.mode.format()))
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
        };
        let pipeline = gpu.pipeline(&spec).map_err(|e| vec![pipeline_error(first_file, &e)])?;

        let vertex_buffer =
            (!interleaved.attributes.is_empty()).then(|| buffer_init(gpu, "vertices", &interleaved.bytes, wgpu::BufferUsages::VERTEX));
        let instance_buffer = instanced.as_ref().map(|i| buffer_init(gpu, "instances", &i.bytes, wgpu::BufferUsages::VERTEX));
        let draw = match mesh_note {
            MeshNote::OwnVertices => Draw::Vertices(3),
            _ => {
                let bytes: Vec<u8> = mesh.indices.iter().flat_map(|i| i.to_le_bytes()).collect();
                Draw::Indexed { buffer: buffer_init(gpu, "indices", &bytes, wgpu::BufferUsages::INDEX), count: mesh.indices.len() as u32 }
            }
        };
        let (uniform_data, guessed) =
            uniforms::buffers(&t.module, input.effect).map_err(|e| vec![Diagnostic::error(E_PIPELINE, e).in_file(first_file)])?;
        for g in guessed {
            let mut d =
                Diagnostic::warning(W_UNIFORM_GUESSED, format!("uniform `{}` has no value in the manifest: using {}", g.name, g.what));
            d = at_declaration(d, input.program, &g.name, Storage::Uniform, "declared here");
            let help = if g.aggregate {
                format!("give its members values in [uniforms]: `\"{}.<member>\" = …` (arrays: `\"{}[0]\"`)", g.name, g.name)
            } else {
                format!("give it a value in [uniforms]: `{} = …` or `{{ semantic = \"…\" }}`", toml_key(&g.name))
            };
            warnings.push(d.with_help(help));
        }
        let uniforms: Vec<(UniformBuffer, wgpu::Buffer)> = uniform_data
            .into_iter()
            .map(|u| {
                let b = buffer_init(gpu, "uniforms", &u.bytes, wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST);
                (u, b)
            })
            .collect();
        let textures = Textures::create(gpu, input, &mut warnings)?;
        let (bind_groups, storage) = bind_groups(gpu, &pipeline, r, &uniforms, &textures);
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(vec![pipeline_error(first_file, &e.to_string())]);
        }
        let mut inputs: Vec<String> = choices.iter().map(|c| format!("{} ← {}", c.input, c.attribute.unwrap_or("zeros"))).collect();
        if let Some(d) = instances {
            inputs.extend(d.attributes.iter().map(|a| format!("{} ← per instance", a.input)));
        }
        let describe = format!(
            "{}; {} vertices, {} triangles{}; inputs: {}",
            mesh_note.describe(input.effect),
            mesh.vertex_count(),
            mesh.triangle_count(),
            instances.map(|d| format!(", {} instances", d.count)).unwrap_or_default(),
            inputs.join(", ")
        );
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
        })
    }
}

/// A manifest key for a GLSL name: quoted when it has `.` or `[`.
fn toml_key(name: &str) -> String {
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

fn pipeline_error(file: FileId, message: &str) -> Diagnostic {
    Diagnostic::error(E_PIPELINE, "wgpu rejected the translated program")
        .in_file(file)
        .with_note(message.trim().to_string())
        .with_note("the WGSL effectc renders is what `effectc translate --to wgsl` writes")
}

fn buffer_init(gpu: &Gpu, label: &str, bytes: &[u8], usage: wgpu::BufferUsages) -> wgpu::Buffer {
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

/// How the mesh was chosen.
enum MeshNote {
    Manifest,
    /// No `[mesh]` and matrices in use: a cube.
    Cube,
    /// No `[mesh]`, no matrices: a full-screen quad.
    Fullscreen,
    /// No `[mesh]` and no vertex inputs: three vertices, positions made by the shader.
    OwnVertices,
}

impl MeshNote {
    fn describe(&self, effect: Option<&Effect>) -> String {
        match self {
            MeshNote::Manifest => match effect.and_then(|e| e.mesh.as_ref()).map(|m| &m.source) {
                Some(MeshSource::Builtin(b)) => format!("mesh {}", b.name()),
                Some(MeshSource::Obj(p)) => format!("mesh {}", p.display()),
                None => "mesh".into(),
            },
            MeshNote::Cube => "mesh cube (guessed)".into(),
            MeshNote::Fullscreen => "mesh fullscreen_quad (guessed)".into(),
            MeshNote::OwnVertices => "3 vertices without attributes".into(),
        }
    }
}

fn choose_mesh(input: &SceneInput<'_>, warnings: &mut Vec<Diagnostic>) -> Result<(Mesh, MeshNote), Vec<Diagnostic>> {
    if let Some(decl) = input.effect.and_then(|e| e.mesh.as_ref()) {
        let mesh = match &decl.source {
            MeshSource::Builtin(b) => Mesh::builtin(*b),
            MeshSource::Obj(path) => Mesh::load_obj(path).map_err(|e| {
                let file = input.effect.map(|e| e.file).unwrap_or(FileId(0));
                vec![Diagnostic::error(E_ASSET, format!("cannot load the mesh: {e}")).at(file, decl.span.clone(), "this mesh")]
            })?,
        };
        let note = if matches!(decl.source, MeshSource::Builtin(BuiltinMesh::FullscreenQuad | BuiltinMesh::FullscreenTriangle)) {
            MeshNote::Fullscreen
        } else {
            MeshNote::Manifest
        };
        return Ok((mesh, note));
    }
    let r = &input.translation.reflection;
    let file = input.program.stages[0].syntax.file;
    if r.vertex_inputs.is_empty() {
        return Ok((Mesh::builtin(BuiltinMesh::FullscreenQuad), MeshNote::OwnVertices));
    }
    let uses_matrices = r.uniform_block.iter().flat_map(|b| &b.members).any(|m| m.glsl_type.starts_with("mat"))
        || r.bindings.iter().any(|b| b.kind == "uniform_buffer" && b.glsl.is_some());
    let (mesh, note, what) = if uses_matrices {
        (BuiltinMesh::Cube, MeshNote::Cube, "a unit cube (the program uses matrices)")
    } else {
        (BuiltinMesh::FullscreenQuad, MeshNote::Fullscreen, "a full-screen quad (the program uses no matrices)")
    };
    if input.effect.is_some() {
        warnings.push(
            Diagnostic::warning(W_MESH_GUESSED, format!("the manifest has no [mesh]: drawing {what}"))
                .in_file(input.effect.map(|e| e.file).unwrap_or(file))
                .with_help("add e.g. `mesh = \"uv_sphere\"`"),
        );
    }
    Ok((Mesh::builtin(mesh), note))
}

fn report_attributes(program: &CompiledProgram, choices: &[attributes::Choice], fullscreen_pass: bool, warnings: &mut Vec<Diagnostic>) {
    for c in choices {
        let (code, message) = match (c.attribute, c.guessed) {
            (Some(_), None) => continue,
            (Some(_), Some(_)) if fullscreen_pass => continue,
            (Some(a), Some(why)) => (W_ATTRIBUTE_GUESSED, format!("vertex input `{}` reads the mesh's {a} (guessed {why})", c.input)),
            (None, _) => (W_ATTRIBUTE_ZERO, format!("vertex input `{}` matches no mesh attribute: it reads zeros", c.input)),
        };
        let d = at_declaration(Diagnostic::warning(code, message), program, &c.input, Storage::In, "this input");
        let example = c.attribute.unwrap_or("position");
        warnings.push(d.with_help(format!(
            "map it in the manifest: [mesh.attributes] `{} = \"{example}\"` (attributes: position, normal, uv, tangent, bitangent, color)",
            c.input
        )));
    }
}

/// Points `d` at the declaration of `name` (a global with `storage`), in the vertex stage
/// for inputs, in any stage for uniforms.
fn at_declaration(d: Diagnostic, program: &CompiledProgram, name: &str, storage: Storage, label: &str) -> Diagnostic {
    let input = storage == Storage::In;
    let matches = |s: Storage| s == storage || (input && s == Storage::Attribute);
    for stage in &program.stages {
        if input && stage.syntax.stage != StageKind::Vertex {
            continue;
        }
        if let Some(g) = stage.syntax.globals.iter().find(|g| g.name == name && matches(g.storage)) {
            return d.at(stage.syntax.file, g.name_span.clone(), label);
        }
        // Members of uniform blocks without an instance name are reached by plain name.
        if let Some(m) = stage
            .syntax
            .globals
            .iter()
            .filter(|g| matches(g.storage))
            .filter_map(|g| g.block.as_ref())
            .flat_map(|b| &b.members)
            .find(|m| m.name == name)
        {
            return d.at(stage.syntax.file, m.span.clone(), label);
        }
    }
    d.in_file(program.stages[0].syntax.file)
}

/// Textures and samplers by binding name.
struct Textures {
    views: BTreeMap<String, wgpu::TextureView>,
    samplers: BTreeMap<String, wgpu::Sampler>,
}

impl Textures {
    fn create(gpu: &Gpu, input: &SceneInput<'_>, warnings: &mut Vec<Diagnostic>) -> Result<Textures, Vec<Diagnostic>> {
        let r = &input.translation.reflection;
        let plan = &input.program.plan;
        let mut views = BTreeMap::new();
        let mut samplers = BTreeMap::new();
        for b in r.bindings.iter().filter(|b| !b.visibility.is_empty()) {
            match b.kind {
                "texture" => {
                    let user = plan.textures.iter().find(|t| t.name == b.name).map(|t| t.user_path.clone());
                    let decl = user.as_deref().and_then(|u| input.effect.and_then(|e| e.texture(u)));
                    if let Some((view, _)) = user.as_deref().and_then(|u| input.pass.as_ref()?.sampled.get(u)) {
                        views.insert(b.name.clone(), view.clone());
                        continue;
                    }
                    let view = match (decl, b.sample_type) {
                        (_, Some("depth")) => depth_placeholder(gpu, b),
                        (_, Some("sint" | "uint")) => integer_placeholder(gpu, b),
                        (Some(decl), _) => {
                            let image = load(decl).map_err(|e| {
                                let file = input.effect.map(|e| e.file).unwrap_or(FileId(0));
                                vec![Diagnostic::error(E_ASSET, format!("cannot load texture `{}`: {e}", decl.name)).at(
                                    file,
                                    decl.span.clone(),
                                    "this texture",
                                )]
                            })?;
                            upload(gpu, &image, b)
                        }
                        (None, _) => {
                            let kind = if b.dimension == Some("cube") { TextureKind::Cube } else { TextureKind::D2 };
                            let name = user.clone().unwrap_or_else(|| b.name.clone());
                            let d = Diagnostic::warning(
                                W_TEXTURE_PLACEHOLDER,
                                format!(
                                    "sampler `{name}` has no texture in the manifest: it reads a placeholder {}",
                                    match kind {
                                        TextureKind::Cube => "sky-gradient cube map",
                                        TextureKind::D2 => "magenta and black checker",
                                    }
                                ),
                            );
                            let d = at_declaration(d, input.program, &name, Storage::Uniform, "this sampler");
                            let key = toml_key(&name);
                            warnings.push(
                                d.with_help(format!("bind it in [textures]: `{key} = \"image.png\"` or `{{ generate = \"noise\" }}`")),
                            );
                            upload(gpu, &texture::placeholder(kind), b)
                        }
                    };
                    views.insert(b.name.clone(), view);
                }
                "sampler" | "comparison_sampler" => {
                    let user = plan.textures.iter().find(|t| t.sampler_name == b.name).map(|t| t.user_path.clone());
                    let decl = user.as_deref().and_then(|u| input.effect.and_then(|e| e.texture(u)));
                    let target = user.as_deref().and_then(|u| input.pass.as_ref()?.sampled.get(u));
                    let (filter, wrap) = match target {
                        // Targets are read like GL render textures: clamped at the edges.
                        Some((_, filter)) => (*filter, Wrap::Clamp),
                        None => decl.map(|d| (d.filter, d.wrap)).unwrap_or_default(),
                    };
                    samplers.insert(b.name.clone(), sampler(gpu, filter, wrap, b.kind == "comparison_sampler"));
                }
                _ => {}
            }
        }
        Ok(Textures { views, samplers })
    }
}

fn load(decl: &crate::manifest::TextureDecl) -> Result<TexelImage, String> {
    match &decl.source {
        TextureSource::File(p) => texture::load_file(p),
        TextureSource::Faces(faces) => texture::load_faces(faces),
        TextureSource::Generated { generator, size, params } => Ok(texture::generate(*generator, *size, params, decl.kind)),
    }
}

fn view_dimension(b: &BindingInfo) -> wgpu::TextureViewDimension {
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
        format: wgpu::TextureFormat::Rgba8Unorm,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    for (mip, level) in levels.iter().enumerate() {
        let level_height = if dimension == wgpu::TextureDimension::D1 { 1 } else { level.height };
        for layer in 0..depth {
            let Some(data) = level.layer(layer % level.layers.max(1)) else { continue };
            let rows = &data[..(level.width * level_height * 4) as usize];
            gpu.queue.write_texture(
                wgpu::TexelCopyTextureInfo {
                    texture: &texture,
                    mip_level: mip as u32,
                    origin: wgpu::Origin3d { x: 0, y: 0, z: layer },
                    aspect: wgpu::TextureAspect::All,
                },
                rows,
                wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(level.width * 4), rows_per_image: Some(level_height) },
                wgpu::Extent3d { width: level.width, height: level_height, depth_or_array_layers: 1 },
            );
        }
    }
    texture.create_view(&wgpu::TextureViewDescriptor { dimension: Some(dim), ..Default::default() })
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
        encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("clear depth placeholder"),
            color_attachments: &[],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &view,
                depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Store }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
    }
    gpu.queue.submit([encoder.finish()]);
    texture.create_view(&wgpu::TextureViewDescriptor { dimension: Some(dim), ..Default::default() })
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

fn sampler(gpu: &Gpu, filter: Filter, wrap: Wrap, comparison: bool) -> wgpu::Sampler {
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
        ..Default::default()
    })
}

fn bind_groups(
    gpu: &Gpu,
    pipeline: &wgpu::RenderPipeline,
    r: &Reflection,
    uniforms: &[(UniformBuffer, wgpu::Buffer)],
    textures: &Textures,
) -> (Vec<(u32, wgpu::BindGroup)>, Vec<(String, wgpu::Buffer)>) {
    let mut by_group: BTreeMap<u32, Vec<&BindingInfo>> = BTreeMap::new();
    for b in r.bindings.iter().filter(|b| !b.visibility.is_empty()) {
        by_group.entry(b.group).or_default().push(b);
    }
    let mut storage = Vec::new();
    for b in by_group.values().flatten().filter(|b| b.kind == "storage_buffer") {
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
    }
    let mut groups = Vec::new();
    for (group, bindings) in by_group {
        let mut entries = Vec::new();
        for b in bindings {
            let resource = match b.kind {
                "uniform_buffer" => {
                    uniforms.iter().find(|(u, _)| u.group == b.group && u.binding == b.binding).map(|(_, buf)| buf.as_entire_binding())
                }
                "storage_buffer" => storage.iter().find(|(n, _)| *n == b.name).map(|(_, buf)| buf.as_entire_binding()),
                "texture" => textures.views.get(&b.name).map(wgpu::BindingResource::TextureView),
                "sampler" | "comparison_sampler" => textures.samplers.get(&b.name).map(wgpu::BindingResource::Sampler),
                _ => None,
            };
            if let Some(resource) = resource {
                entries.push(wgpu::BindGroupEntry { binding: b.binding, resource });
            }
        }
        let layout = pipeline.get_bind_group_layout(group);
        let bg = gpu.device.create_bind_group(&wgpu::BindGroupDescriptor { label: None, layout: &layout, entries: &entries });
        groups.push((group, bg));
    }
    (groups, storage)
}
