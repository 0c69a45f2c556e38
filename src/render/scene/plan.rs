//! What a scene draws and binds, decided on the CPU alone: the mesh, the attribute each
//! vertex input reads, each uniform's value and each sampler's texture, with a warning
//! for every guess. [`Scene::new`](super::Scene::new) makes the GPU side from it, and
//! `effectc check` of a manifest reports the same warnings without a device
//! ([`crate::render::preview`]).

use std::collections::BTreeMap;

use crate::assets::mesh::Mesh;
use crate::back::Translation;
use crate::diag::{Code, Diagnostic};
use crate::front::program::CompiledProgram;
use crate::front::syntax::Storage;
use crate::manifest::{Effect, MeshAttribute, TexelKind, TextureDecl, TextureKind, TextureSource, UniformValue};
use crate::render::attributes::{self, Choice};
use crate::render::uniforms::{self, UniformBuffer};

use super::mesh_choice::{at_declaration, choose_mesh, documented_fullscreen_input, report_attributes, MeshNote};
use super::toml_key;

/// What a plan is made from: [`super::SceneInput`] without the device's objects.
pub(crate) struct PlanInput<'a> {
    pub translation: &'a Translation,
    pub program: &'a CompiledProgram,
    pub effect: Option<&'a Effect>,
    /// Set for one pass of a multi-pass effect: (sampler by the user's GLSL name, target)
    /// for each sampler that reads an earlier pass's target.
    pub pass: Option<Vec<(String, String)>>,
    /// Uniform values over the effect's (`--set`, a bench knob, a stress case).
    pub overrides: &'a [(String, UniformValue)],
    /// Uniforms nobody set are zero, as in GL, instead of guessed (`--gl-defaults`).
    pub gl_defaults: bool,
}

/// Where a texture binding's texels come from.
pub(crate) enum TextureChoice<'a> {
    /// An earlier pass's target (its name).
    Target(String),
    /// A multisampled texture: only a render target can fill one, so a cleared placeholder.
    Multisampled { depth: bool },
    /// A depth texture without a pass target: cleared to the far plane.
    Depth,
    /// An integer texture: a zero placeholder.
    Integer { unsigned: bool },
    /// The manifest's image or generator.
    Image(&'a TextureDecl),
    /// Nothing given: the placeholder of this kind.
    Placeholder(TextureKind),
}

/// The scene's CPU-side decisions.
pub(crate) struct Plan<'a> {
    pub mesh: Mesh,
    pub mesh_note: MeshNote,
    /// Each per-vertex input's attribute.
    pub choices: Vec<Choice>,
    pub uniforms: Vec<UniformBuffer>,
    /// Each texture binding's source, by binding name.
    pub textures: BTreeMap<String, TextureChoice<'a>>,
    /// Every guess, at the declaration it concerns.
    pub warnings: Vec<Diagnostic>,
    /// One line for `--verbose`: the mesh, and what feeds each input, uniform and sampler.
    pub describe: String,
    /// The values the program gives its uniforms ([`crate::front::initial_values::of`]).
    pub initial: Vec<crate::front::initial_values::Initial>,
    /// Block matrices stored row-major ([`crate::front::initial_values::row_major`]).
    pub row_major: Vec<(String, String)>,
}

pub(crate) fn plan<'a>(input: &PlanInput<'a>) -> Result<Plan<'a>, Vec<Diagnostic>> {
    let r = &input.translation.reflection;
    let first_file = input.program.stages[0].syntax.file;
    let mut warnings = Vec::new();
    let (mesh, mesh_note) = choose_mesh(input, &mut warnings)?;
    let explicit = input.effect.and_then(|e| e.mesh.as_ref()).map(|m| m.attributes.clone()).unwrap_or_default();
    // Borrowed: a `values` list holds one entry per vertex of the mesh.
    let values: &[crate::manifest::InstanceAttribute] = input.effect.and_then(|e| e.mesh.as_ref()).map_or(&[], |m| &m.values);
    if let Some(e) = input.effect {
        vertex_values_counted(e, values, mesh.vertex_count())?;
    }
    let instances = input.effect.and_then(|e| e.instances.as_ref());
    let per_instance = |name: &str| instances.is_some_and(|d| d.attributes.iter().any(|a| a.input == name));
    let per_vertex: Vec<_> = r.vertex_inputs.iter().filter(|v| !per_instance(&v.name)).cloned().collect();
    let mut choices = attributes::choose(&per_vertex, &explicit, values);
    // A full-screen pass draws effectc's triangle, whose attributes `position` and `uv` are
    // documented under those names: matching an input named so is the contract, not a guess.
    if input.pass.is_some() && matches!(mesh_note, MeshNote::Fullscreen) {
        for c in choices.iter_mut().filter(|c| c.attribute.is_some() && documented_fullscreen_input(&c.input) == c.attribute) {
            c.guessed = None;
        }
    }
    report_attributes(input.program, &choices, &mut warnings);
    let initial = crate::front::initial_values::of(input.program);
    let row_major = crate::front::initial_values::row_major(input.program);
    let (uniforms, guessed) =
        uniforms::buffers(&input.translation.module, input.effect, &initial, &row_major, input.overrides, !input.gl_defaults)
            .map_err(|e| vec![Diagnostic::new(Code::PipelineRejected, e).in_file(first_file)])?;
    for g in guessed {
        let mut d = Diagnostic::new(Code::UniformGuessed, format!("uniform `{}` has no value in the manifest: using {}", g.name, g.what));
        d = at_declaration(d, input.program, &g.name, Storage::Uniform, "declared here");
        let help = if g.aggregate {
            format!("give its members values in [uniforms]: `\"{}.<member>\" = …` (arrays: `\"{}[0]\"`)", g.name, g.name)
        } else {
            format!("give it a value in [uniforms]: `{} = …` or `{{ semantic = \"…\" }}`", toml_key(&g.name))
        };
        warnings.push(d.with_help(help));
    }
    let textures = textures(input, &mut warnings)?;
    let describe = describe(input, (&mesh_note, &mesh), &choices, &uniforms, &textures);
    Ok(Plan { mesh, mesh_note, choices, uniforms, textures, warnings, describe, initial, row_major })
}

/// `[mesh.attributes] x = { values = […] }` gives exactly one value per vertex of the mesh
/// drawn (known only once an OBJ file is read).
fn vertex_values_counted(
    effect: &crate::manifest::Effect,
    values: &[crate::manifest::InstanceAttribute],
    vertices: usize,
) -> Result<(), Vec<Diagnostic>> {
    let wrong: Vec<Diagnostic> = values
        .iter()
        .filter_map(|a| match &a.source {
            crate::manifest::InstanceSource::Values(v) if v.len() != vertices => Some(
                Diagnostic::new(Code::ManifestValue, format!("`mesh.attributes.{}` has {} values for a mesh of {vertices} vertices", a.input, v.len()))
                    .at(effect.file, a.input_span.clone(), format!("expected {vertices} values"))
                    .with_help("give one value per vertex (`effectc render --verbose` names the mesh and counts its vertices), or a `sequence` or `random` that needs no count"),
            ),
            _ => None,
        })
        .collect();
    if wrong.is_empty() {
        Ok(())
    } else {
        Err(wrong)
    }
}

/// The source of every texture binding the program uses, and a warning for each placeholder;
/// an error where a manifest texture's format is not of the kind its sampler reads.
fn textures<'a>(input: &PlanInput<'a>, warnings: &mut Vec<Diagnostic>) -> Result<BTreeMap<String, TextureChoice<'a>>, Vec<Diagnostic>> {
    let plan = &input.program.plan;
    let mut out = BTreeMap::new();
    let mut wrong = Vec::new();
    for b in input.translation.reflection.bindings.iter().filter(|b| !b.visibility.is_empty() && b.kind == "texture") {
        let user = plan.textures.iter().find(|t| t.name == b.name).map(|t| t.user_name.clone());
        let name = user.clone().unwrap_or_else(|| b.name.clone());
        let decl = user.as_deref().and_then(|u| input.effect.and_then(|e| e.texture(u)));
        let from_target = user.as_ref().and_then(|u| input.pass.as_ref()?.iter().find(|(s, _)| s == u)).map(|(_, t)| t);
        let choice = match (from_target, decl, b.sample_type) {
            (Some(target), _, _) => TextureChoice::Target(target.clone()),
            (None, _, sample_type) if b.multisampled => {
                let d = Diagnostic::new(
                    Code::TexturePlaceholder,
                    format!("sampler `{name}` is multisampled: it reads a placeholder cleared to magenta"),
                );
                let d = at_declaration(d, input.program, &name, Storage::Uniform, "this sampler");
                warnings.push(d.with_note("only render targets are multisampled; an image file cannot fill one"));
                TextureChoice::Multisampled { depth: sample_type == Some("depth") }
            }
            (None, _, Some("depth")) => TextureChoice::Depth,
            (None, Some(decl), sample_type) if !reads(decl.format.kind(), sample_type) => {
                if let Some(effect) = input.effect {
                    wrong.push(format_mismatch(effect, decl, &name, sample_type));
                }
                continue;
            }
            (None, None, Some(kind @ ("sint" | "uint"))) => TextureChoice::Integer { unsigned: kind == "uint" },
            (None, Some(decl), _) => TextureChoice::Image(decl),
            (None, None, _) => {
                let kind = if b.dimension == Some("cube") { TextureKind::Cube } else { TextureKind::D2 };
                let what = match kind {
                    TextureKind::Cube => "sky-gradient cube map",
                    TextureKind::D2 => "magenta and black checker",
                };
                let d = Diagnostic::new(
                    Code::TexturePlaceholder,
                    format!("sampler `{name}` has no texture in the manifest: it reads a placeholder {what}"),
                );
                let d = at_declaration(d, input.program, &name, Storage::Uniform, "this sampler");
                let key = toml_key(&name);
                warnings.push(d.with_help(format!("bind it in [textures]: `{key} = \"image.png\"` or `{{ generate = \"noise\" }}`")));
                TextureChoice::Placeholder(kind)
            }
        };
        out.insert(b.name.clone(), choice);
    }
    if wrong.is_empty() {
        Ok(out)
    } else {
        Err(wrong)
    }
}

/// Whether a sampler of `sample_type` reads textures of `kind`.
fn reads(kind: TexelKind, sample_type: Option<&str>) -> bool {
    match sample_type {
        Some("sint") => kind == TexelKind::Sint,
        Some("uint") => kind == TexelKind::Uint,
        _ => kind == TexelKind::Float,
    }
}

/// A manifest texture whose format its sampler cannot read (GL leaves such reads undefined).
fn format_mismatch(effect: &Effect, decl: &TextureDecl, sampler: &str, sample_type: Option<&str>) -> Diagnostic {
    let (reads, formats) = match sample_type {
        Some("sint") => ("signed integers (`isampler*`)", "`format = \"rgba32i\"` (or `\"r32i\"`)"),
        Some("uint") => ("unsigned integers (`usampler*`)", "`format = \"rgba32ui\"` (or `\"r32ui\"`)"),
        _ => ("floating-point values", "a floating-point format (`\"rgba8\"`, `\"rgba16f\"`, `\"rgba32f\"` or `\"r32f\"`)"),
    };
    Diagnostic::new(
        Code::ManifestValue,
        format!("texture `{}` is `{}`, but sampler `{sampler}` reads {reads}", decl.name, decl.format.name()),
    )
    .at(effect.file, decl.span.clone(), "this texture")
    .with_help(format!("give the texture {formats}, or change the sampler's type"))
}

/// A one-line description for `--verbose`: the mesh, then what each vertex input,
/// uniform and sampler reads.
fn describe(
    input: &PlanInput<'_>,
    (mesh_note, mesh): (&MeshNote, &Mesh),
    choices: &[Choice],
    uniforms: &[UniformBuffer],
    textures: &BTreeMap<String, TextureChoice<'_>>,
) -> String {
    let effect = input.effect;
    let instances = effect.and_then(|e| e.instances.as_ref());
    let mut inputs: Vec<String> = choices
        .iter()
        .map(|c| {
            let unfed = if crate::front::compat::attribute(&c.input).is_some() { "GL's current value" } else { "zeros" };
            let guess = if c.guessed.is_some() && c.attribute.is_some() { " (guessed)" } else { "" };
            let source = if c.values.is_some() { "the manifest's values" } else { c.attribute.map_or(unfed, MeshAttribute::name) };
            format!("{} ← {source}{guess}", c.input)
        })
        .collect();
    if let Some(d) = instances {
        inputs.extend(d.attributes.iter().map(|a| format!("{} ← per instance", a.input)));
    }
    let mut text = format!(
        "{}; {} vertices, {} triangle{}{}",
        mesh_note.describe(effect),
        mesh.vertex_count(),
        mesh.triangle_count(),
        if mesh.triangle_count() == 1 { "" } else { "s" },
        instances.map(|d| format!(", {} instances", d.count)).unwrap_or_default(),
    );
    let mut part = |label: &str, items: Vec<String>| {
        if !items.is_empty() {
            text.push_str(&format!("; {label}: {}", items.join(", ")));
        }
    };
    part("inputs", inputs);
    part("uniforms", uniforms.iter().flat_map(|u| &u.sources).map(|(name, from)| format!("{name} ← {from}")).collect());
    let plan = &input.program.plan;
    part(
        "samplers",
        textures
            .iter()
            .map(|(binding, choice)| {
                let name = plan.textures.iter().find(|t| &t.name == binding).map_or(binding.as_str(), |t| t.user_name.as_str());
                let from = match choice {
                    TextureChoice::Target(target) => format!("target {target}"),
                    TextureChoice::Multisampled { .. } => "a cleared placeholder (multisampled)".to_string(),
                    TextureChoice::Depth => "a depth placeholder at the far plane".to_string(),
                    TextureChoice::Integer { .. } => "a zero placeholder (integer)".to_string(),
                    TextureChoice::Image(decl) => {
                        let source = match &decl.source {
                            TextureSource::File(path) => path.display().to_string(),
                            TextureSource::Faces(faces) => format!("six faces from {}", faces[0].display()),
                            TextureSource::Generated { generator, .. } => format!("generated {}", generator.name()),
                        };
                        format!("{source} ({})", decl.format.name())
                    }
                    TextureChoice::Placeholder(TextureKind::Cube) => "a placeholder sky cube (guessed)".to_string(),
                    TextureChoice::Placeholder(TextureKind::D2) => "a placeholder checker (guessed)".to_string(),
                };
                format!("{name} ← {from}")
            })
            .collect(),
    );
    text
}
