//! Reflection of the emitted module (`<effect>.reflect.json`) and packing of uniform values
//! into the generated uniform block's bytes.
//!
//! The reflection describes the module after pruning: exactly the bindings, uniform members
//! and interface the emitted code has. Offsets are those of the emitted code (WGSL's uniform
//! layout, which the SPIR-V, MSL and HLSL outputs share), so a renderer can fill the buffer
//! from the JSON alone; [`pack`] does that from manifest values.

use std::collections::{BTreeMap, BTreeSet};

use naga::{AddressSpace, Binding, Handle, Module, ScalarKind, Statement, Type, TypeInner};
use serde::Serialize;

use crate::back::merge::visit_statements;

mod block;
mod images;
mod names;
mod pass;
mod values;
use crate::back::prune::LeftOut;
use crate::front::plan::UNIFORM_BLOCK;
use crate::front::program::CompiledProgram;
use crate::manifest::{Effect, UniformValue};
pub use block::{ArrayLayout, Fill, UniformBlock, UniformMember};
use block::{BlockSources, GlslFields};
use images::describe_image;
use names::WgslNames;
pub use pass::{pass_info, PassInfo, PassRead, PassTarget, TargetExtent};
pub use values::write_slot;

/// Version of the reflection JSON schema (documented in the README).
pub const SCHEMA_VERSION: u32 = 1;

#[derive(Debug, Clone, Serialize)]
pub struct Reflection {
    pub schema: u32,
    pub effect: String,
    pub entry_points: Vec<EntryPointInfo>,
    pub bindings: Vec<BindingInfo>,
    pub uniform_block: Option<UniformBlock>,
    pub vertex_inputs: Vec<InterfaceVar>,
    pub varyings: Vec<InterfaceVar>,
    pub fragment_outputs: Vec<InterfaceVar>,
    pub left_out: Vec<LeftOut>,
    /// A program with a geometry stage: how to draw its folded vertex stage.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub geometry: Option<GeometryDraw>,
    /// One pass of a multi-pass effect: its targets and the targets it reads.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pass: Option<PassInfo>,
}

/// How to draw a program whose geometry stage is folded into the vertex stage: no vertex
/// buffers; the index and vertex data in two storage buffers; a non-indexed draw of
/// `vertices_per_primitive` vertices per input primitive (× instances) with `topology`.
#[derive(Debug, Clone, Serialize)]
pub struct GeometryDraw {
    /// `points`, `lines` or `triangles`: what one input primitive is.
    pub input_primitive: &'static str,
    /// `points`, `line_strip` or `triangle_strip`, as the geometry stage declared.
    pub output_primitive: &'static str,
    pub max_vertices: u32,
    pub invocations: u32,
    /// The pipeline's primitive topology: `point-list`, `line-list` or `triangle-list`.
    pub topology: &'static str,
    /// Vertices to draw per input primitive: `draw(primitives × this, instances)`.
    pub vertices_per_primitive: u32,
    /// A 16-byte header (`i32` layer, `i32` viewport: the draw keeps only the primitives the
    /// geometry stage sends to that layer and viewport, −1 for all; two unused words), then
    /// `u32` vertex indices, `stride` per input primitive, in draw order.
    pub index_buffer: PulledBuffer,
    /// Per vertex, one `vec4<f32>` per entry of `inputs` (unused components ignored).
    pub vertex_buffer: PulledBuffer,
    /// The vertex stage's inputs in their `vec4` order within a vertex (the first is at
    /// `vertex * inputs.len()`); also listed in `vertex_inputs`.
    pub inputs: Vec<String>,
    /// A program with tessellation stages folded in (no geometry stage): its patches'
    /// tessellation; `vertices_per_primitive` then counts slots per patch at the level cap.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tessellation: Option<TessellationDraw>,
    /// `layer` and/or `viewport` when the geometry stage writes `gl_Layer` /
    /// `gl_ViewportIndex` (WebGPU cannot route a primitive: draw once per layer or viewport
    /// with the header naming it).
    pub selects: Vec<&'static str>,
}

/// How a folded tessellation program spends its draw: `vertices_per_primitive` slots per
/// patch, enough for every level at `level_cap` (header words 2 and 3 of the index buffer
/// hold the cap and the slots; a smaller cap draws fewer vertices, levels above it are
/// drawn at it).
#[derive(Debug, Clone, Serialize)]
pub struct TessellationDraw {
    /// `triangles`, `quads` or `isolines`.
    pub domain: &'static str,
    pub level_cap: u32,
    /// A geometry stage after the tessellation: the vertices it spends on each generated
    /// primitive (0 without one).
    pub geometry_slots: u32,
    #[serde(skip)]
    pub layout: crate::front::tessellation_fold::tessellator::TessLayout,
}

impl TessellationDraw {
    /// The draw's vertices per patch at level cap `cap`.
    pub fn vertices_per_patch(&self, cap: u32) -> u32 {
        match self.geometry_slots {
            0 => self.layout.slots_per_patch(cap),
            per => self.layout.most_primitives(cap) * per,
        }
    }

    /// The largest even level cap (2 … 64) at which `patches` patches take at most `budget`
    /// vertices.
    pub fn level_cap(&self, patches: u32, budget: u64) -> u32 {
        (1..=crate::front::tessellation_fold::tessellator::MAX_LEVEL / 2)
            .map(|h| h * 2)
            .take_while(|cap| u64::from(patches.max(1)) * u64::from(self.vertices_per_patch(*cap)) <= budget)
            .last()
            .unwrap_or(2)
    }
}

/// A storage buffer the folded stage reads.
#[derive(Debug, Clone, Serialize)]
pub struct PulledBuffer {
    pub name: &'static str,
    pub group: u32,
    pub binding: u32,
    /// Elements per input primitive (index buffer) or per vertex (vertex buffer).
    pub stride: u32,
}

/// The reflection of a translated program: [`reflect`], and for a folded geometry stage its
/// draw plan, with the pulled inputs as the vertex inputs.
pub fn reflect_program(
    name: &str,
    module: &Module,
    program: &crate::front::program::CompiledProgram,
    effect: Option<&Effect>,
    left_out: Vec<LeftOut>,
) -> Reflection {
    let mut reflection = reflect(name, module, program, effect, left_out);
    if let Some((draw, inputs)) = program.fold().and_then(|f| geometry_draw(&f.drawn)) {
        reflection.geometry = Some(draw);
        reflection.vertex_inputs = inputs;
    }
    reflection
}

/// The draw plan of a folded geometry program, and its pulled inputs as vertex inputs.
pub fn geometry_draw(lowered: &crate::front::geometry_fold::Lowered) -> Option<(GeometryDraw, Vec<InterfaceVar>)> {
    use crate::front::geometry_fold::Shape;
    use crate::front::geometry_fold::{Pulling, INDEX_BUFFER, VERTEX_BUFFER};
    use crate::front::geometry_layout::OutputPrimitive;
    use crate::front::tessellation_fold::tessellator::MAX_LEVEL;
    let Pulling::Storage { index_binding, vertex_binding } = lowered.pulling else { return None };
    let inputs: Vec<InterfaceVar> = lowered
        .vertex_inputs
        .iter()
        .zip(&lowered.input_types)
        .map(|((location, name, components), ty)| {
            let (scalar, format) = match ty.chars().next() {
                Some('i') => ("i32", "sint32"),
                Some('u') => ("u32", "uint32"),
                _ => ("f32", "float32"),
            };
            InterfaceVar {
                location: *location,
                name: name.clone(),
                wgsl_name: None,
                wgsl_type: if *components == 1 { scalar.to_string() } else { format!("vec{components}<{scalar}>") },
                format: Some(if *components == 1 { format.to_string() } else { format!("{format}x{components}") }),
                interpolation: None,
            }
        })
        .collect();
    let (input_primitive, output_primitive, max_vertices, invocations, topology, vertices_per_primitive, stride, tessellation) =
        match lowered.shape {
            Shape::Geometry(l) => (
                l.input.name(),
                l.output.name(),
                l.max_vertices,
                l.invocations,
                match l.output {
                    OutputPrimitive::Points => "point-list",
                    OutputPrimitive::LineStrip => "line-list",
                    OutputPrimitive::TriangleStrip => "triangle-list",
                },
                l.slots_per_primitive(),
                l.input.vertices(),
                None,
            ),
            Shape::Tessellation { layout, patch_vertices } => {
                let t = TessellationDraw { domain: layout.domain_name(), level_cap: MAX_LEVEL, geometry_slots: 0, layout };
                let slots = t.vertices_per_patch(MAX_LEVEL);
                ("patches", layout.domain_name(), slots, 1, layout.topology(), slots, patch_vertices, Some(t))
            }
            Shape::TessellatedGeometry { geometry: l, layout, patch_vertices } => {
                let t = TessellationDraw {
                    domain: layout.domain_name(),
                    level_cap: MAX_LEVEL,
                    geometry_slots: l.slots_per_primitive(),
                    layout,
                };
                let topology = match l.output {
                    OutputPrimitive::Points => "point-list",
                    OutputPrimitive::LineStrip => "line-list",
                    OutputPrimitive::TriangleStrip => "triangle-list",
                };
                let slots = t.vertices_per_patch(MAX_LEVEL);
                ("patches", l.output.name(), l.max_vertices, l.invocations, topology, slots, patch_vertices, Some(t))
            }
        };
    let draw = GeometryDraw {
        input_primitive,
        output_primitive,
        max_vertices,
        invocations,
        topology,
        vertices_per_primitive,
        tessellation,
        index_buffer: PulledBuffer { name: INDEX_BUFFER, group: 0, binding: index_binding, stride },
        vertex_buffer: PulledBuffer { name: VERTEX_BUFFER, group: 0, binding: vertex_binding, stride: inputs.len() as u32 },
        inputs: inputs.iter().map(|i| i.name.clone()).collect(),
        selects: [(lowered.selects_layer, "layer"), (lowered.selects_viewport, "viewport")]
            .into_iter()
            .filter(|(s, _)| *s)
            .map(|(_, n)| n)
            .collect(),
    };
    Some((draw, inputs))
}

#[derive(Debug, Clone, Serialize)]
pub struct EntryPointInfo {
    pub stage: &'static str,
    pub name: String,
}

#[derive(Debug, Clone, Serialize)]
pub struct BindingInfo {
    pub group: u32,
    pub binding: u32,
    /// Name in the module: the GLSL name, or effectc's (`tex_sampler` for the sampler half
    /// of a combined sampler, `struct_member` for a flattened one).
    pub name: String,
    /// The name the WGSL declares (naga adds `_` to names ending in a digit: `tex0_`).
    pub wgsl_name: String,
    /// `uniform_buffer`, `storage_buffer`, `texture`, `storage_texture`, `sampler`, `comparison_sampler`.
    pub kind: &'static str,
    /// Textures: `1d`, `2d`, `2d_array`, `3d`, `cube`, `cube_array`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dimension: Option<&'static str>,
    /// Textures: `float`, `sint`, `uint`, `depth`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sample_type: Option<&'static str>,
    /// Textures: multisampled.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub multisampled: bool,
    /// Storage textures: the texel format in WGSL's spelling (`rgba8unorm`), and the access
    /// the code makes (`read`, `write`, `read_write`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub format: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub access: Option<&'static str>,
    /// Buffers: the bound struct's size in bytes.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub size: Option<u32>,
    /// Stages that use it: `vertex`, `fragment`.
    pub visibility: Vec<&'static str>,
    /// What the user wrote in GLSL to reach it (`tex`, `material.diffuse`, `maps[2]`, a
    /// uniform block's name); for samplers, the texture's path.
    pub glsl: Option<String>,
}

#[derive(Debug, Clone, Serialize)]
pub struct InterfaceVar {
    pub location: u32,
    pub name: String,
    /// The name the WGSL declares; absent where it declares none (a lone return value,
    /// inputs a folded geometry program pulls from storage buffers).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wgsl_name: Option<String>,
    pub wgsl_type: String,
    /// Vertex inputs: the wgpu vertex format (`float32x3`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub format: Option<String>,
    /// Varyings: `perspective`, `linear`, `flat`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub interpolation: Option<&'static str>,
}

/// WGSL spelling of a type.
pub fn type_name(module: &Module, ty: Handle<Type>) -> String {
    let t = &module.types[ty];
    match &t.inner {
        TypeInner::Scalar(s) => scalar_name(*s).to_string(),
        TypeInner::Vector { size, scalar } => format!("vec{}<{}>", *size as u8, scalar_name(*scalar)),
        TypeInner::Matrix { columns, rows, scalar } => {
            format!("mat{}x{}<{}>", *columns as u8, *rows as u8, scalar_name(*scalar))
        }
        TypeInner::Array { base, size, .. } => match size {
            naga::ArraySize::Constant(n) => format!("array<{}, {n}>", type_name(module, *base)),
            _ => format!("array<{}>", type_name(module, *base)),
        },
        _ => t.name.clone().unwrap_or_else(|| format!("{:?}", t.inner)),
    }
}

fn scalar_name(s: naga::Scalar) -> &'static str {
    match (s.kind, s.width) {
        (ScalarKind::Float, 2) => "f16",
        (ScalarKind::Float, 8) => "f64",
        (ScalarKind::Float, _) => "f32",
        (ScalarKind::Sint, _) => "i32",
        (ScalarKind::Uint, _) => "u32",
        (ScalarKind::Bool, _) => "bool",
        _ => "?",
    }
}

fn vertex_format(module: &Module, ty: Handle<Type>) -> Option<String> {
    let (scalar, n) = match module.types[ty].inner {
        TypeInner::Scalar(s) => (s, 1),
        TypeInner::Vector { size, scalar } => (scalar, size as u8),
        _ => return None,
    };
    let base = match (scalar.kind, scalar.width) {
        (ScalarKind::Float, 4) => "float32",
        (ScalarKind::Sint, 4) => "sint32",
        (ScalarKind::Uint, 4) => "uint32",
        (ScalarKind::Float, 8) => "float64",
        _ => return None,
    };
    Some(if n == 1 { base.to_string() } else { format!("{base}x{n}") })
}

fn stage_name(s: naga::ShaderStage) -> &'static str {
    match s {
        naga::ShaderStage::Vertex => "vertex",
        naga::ShaderStage::Fragment => "fragment",
        naga::ShaderStage::Compute => "compute",
        _ => "other",
    }
}

/// Globals each entry point reaches (directly or through calls).
fn visibility(module: &Module) -> BTreeMap<Handle<naga::GlobalVariable>, BTreeSet<&'static str>> {
    let mut out: BTreeMap<_, BTreeSet<&'static str>> = BTreeMap::new();
    for ep in &module.entry_points {
        let mut pending = vec![&ep.function];
        let mut seen = BTreeSet::new();
        while let Some(f) = pending.pop() {
            for (_, e) in f.expressions.iter() {
                if let naga::Expression::GlobalVariable(g) = e {
                    out.entry(*g).or_default().insert(stage_name(ep.stage));
                }
            }
            let mut body = f.body.clone();
            let mut calls = Vec::new();
            visit_statements(&mut body, &mut |s| {
                if let Statement::Call { function, .. } = s {
                    calls.push(*function);
                }
            });
            for c in calls {
                if seen.insert(c) {
                    pending.push(&module.functions[c]);
                }
            }
        }
    }
    out
}

fn interpolation_name(b: &Binding) -> Option<&'static str> {
    match b {
        Binding::Location { interpolation: Some(i), .. } => Some(match i {
            naga::Interpolation::Perspective => "perspective",
            naga::Interpolation::Linear => "linear",
            naga::Interpolation::Flat => "flat",
            _ => "other",
        }),
        _ => None,
    }
}

/// One location-bound input or output: location, name, WGSL name, type, binding.
type Located = (u32, String, Option<String>, Handle<Type>, Binding);

/// Location-bound members of an entry point's inputs or output (struct or plain), with the
/// names the WGSL gives them (`wgsl_name(i)` for the plain item `i`).
fn located(
    module: &Module,
    names: &WgslNames,
    items: &[(Option<String>, Handle<Type>, Option<Binding>)],
    wgsl_name: impl Fn(usize) -> Option<String>,
) -> Vec<Located> {
    let mut out = Vec::new();
    for (i, (name, ty, binding)) in items.iter().enumerate() {
        match binding {
            Some(b @ Binding::Location { location, .. }) => {
                out.push((*location, name.clone().unwrap_or_default(), wgsl_name(i), *ty, b.clone()))
            }
            Some(_) => {}
            None => {
                if let TypeInner::Struct { members, .. } = &module.types[*ty].inner {
                    for (j, m) in members.iter().enumerate() {
                        if let Some(b @ Binding::Location { location, .. }) = &m.binding {
                            out.push((*location, m.name.clone().unwrap_or_default(), names.member(*ty, j), m.ty, b.clone()));
                        }
                    }
                }
            }
        }
    }
    out.sort_by_key(|x| x.0);
    out
}

fn varying(module: &Module, (location, name, wgsl_name, ty, b): Located) -> InterfaceVar {
    InterfaceVar { location, name, wgsl_name, wgsl_type: type_name(module, ty), format: None, interpolation: interpolation_name(&b) }
}

/// Builds the reflection of a pruned, validated module.
pub fn reflect(name: &str, module: &Module, program: &CompiledProgram, effect: Option<&Effect>, left_out: Vec<LeftOut>) -> Reflection {
    let vis = visibility(module);
    let plan = &program.plan;
    let names = WgslNames::of(module);
    let initial = crate::front::initial_values::of(program);
    let fields: GlslFields = program
        .stages
        .iter()
        .flat_map(|s| &s.syntax.structs)
        .flat_map(|d| d.members.iter().map(move |m| ((d.name.clone(), m.name.clone()), m.ty.to_string())))
        .collect();
    let sources = BlockSources { plan, effect, initial: &initial, names: &names, fields: &fields };
    let mut bindings = Vec::new();
    let mut uniform_block = None;
    for (h, g) in module.global_variables.iter() {
        let Some(rb) = &g.binding else { continue };
        let gname = g.name.clone().unwrap_or_default();
        let mut info = BindingInfo {
            group: rb.group,
            binding: rb.binding,
            name: gname.clone(),
            wgsl_name: names.global(h).unwrap_or_else(|| gname.clone()),
            kind: "uniform_buffer",
            dimension: None,
            sample_type: None,
            multisampled: false,
            format: None,
            access: None,
            size: None,
            visibility: vis.get(&h).map(|s| s.iter().copied().collect()).unwrap_or_default(),
            glsl: None,
        };
        match &module.types[g.ty].inner {
            TypeInner::Image { dim, arrayed, class } => {
                describe_image(&mut info, *dim, *arrayed, class);
                info.glsl = plan.textures.iter().find(|t| t.name == gname).map(|t| t.user_name.clone());
            }
            TypeInner::Sampler { comparison } => {
                info.kind = if *comparison { "comparison_sampler" } else { "sampler" };
                info.glsl = plan.textures.iter().find(|t| t.sampler_name == gname).map(|t| t.user_name.clone());
            }
            TypeInner::Struct { span, .. } => {
                info.kind = if g.space == AddressSpace::Uniform { "uniform_buffer" } else { "storage_buffer" };
                info.size = Some(*span);
                let tname = module.types[g.ty].name.clone().unwrap_or_default();
                if tname == UNIFORM_BLOCK && g.space == AddressSpace::Uniform {
                    uniform_block = Some(block::block_of(module, g.ty, rb, &sources));
                } else {
                    info.glsl = Some(tname);
                }
            }
            TypeInner::Array { size: naga::ArraySize::Constant(n), stride, .. } if matches!(g.space, AddressSpace::Storage { .. }) => {
                info.kind = "storage_buffer";
                info.size = Some(n.get() * stride);
            }
            _ => {}
        }
        bindings.push(info);
    }
    bindings.sort_by_key(|b| (b.group, b.binding));

    let mut vertex_inputs = Vec::new();
    let mut varyings = Vec::new();
    let mut fragment_outputs = Vec::new();
    for (ep_index, ep) in module.entry_points.iter().enumerate() {
        let args: Vec<_> = ep.function.arguments.iter().map(|a| (a.name.clone(), a.ty, a.binding.clone())).collect();
        let result: Vec<_> = ep.function.result.iter().map(|r| (None, r.ty, r.binding.clone())).collect();
        let argument = |i| names.argument(ep_index, i);
        let located_args = || located(module, &names, &args, argument);
        let located_result = || located(module, &names, &result, |_| None);
        match ep.stage {
            naga::ShaderStage::Vertex => {
                for (location, name, wgsl_name, ty, _) in located_args() {
                    vertex_inputs.push(InterfaceVar {
                        location,
                        name,
                        wgsl_name,
                        wgsl_type: type_name(module, ty),
                        format: vertex_format(module, ty),
                        interpolation: None,
                    });
                }
                varyings.extend(located_result().into_iter().map(|v| varying(module, v)));
            }
            naga::ShaderStage::Fragment => {
                if !module.entry_points.iter().any(|e| e.stage == naga::ShaderStage::Vertex) {
                    varyings.extend(located_args().into_iter().map(|v| varying(module, v)));
                }
                for (location, name, wgsl_name, ty, _) in located_result() {
                    fragment_outputs.push(InterfaceVar {
                        location,
                        name,
                        wgsl_name,
                        wgsl_type: type_name(module, ty),
                        format: None,
                        interpolation: None,
                    });
                }
            }
            _ => {}
        }
    }
    Reflection {
        schema: SCHEMA_VERSION,
        effect: name.to_string(),
        entry_points: module.entry_points.iter().map(|e| EntryPointInfo { stage: stage_name(e.stage), name: e.name.clone() }).collect(),
        bindings,
        uniform_block,
        vertex_inputs,
        varyings,
        fragment_outputs,
        left_out,
        geometry: None,
        pass: None,
    }
}

/// Byte offset and type of a GLSL path (`a`, `a.b`, `a[2].c`) inside struct `ty`.
pub fn resolve_path(module: &Module, ty: Handle<Type>, path: &str) -> Option<(u32, Handle<Type>)> {
    let mut offset = 0u32;
    let mut cur = ty;
    let mut rest = path;
    let mut first = true;
    while !rest.is_empty() {
        if let Some(r) = rest.strip_prefix('[') {
            let end = r.find(']')?;
            let index: u32 = r[..end].trim().parse().ok()?;
            rest = &r[end + 1..];
            match module.types[cur].inner {
                TypeInner::Array { base, size: naga::ArraySize::Constant(n), stride } if index < n.get() => {
                    offset += index * stride;
                    cur = base;
                }
                _ => return None,
            }
            continue;
        }
        let r = if first { rest } else { rest.strip_prefix('.')? };
        first = false;
        let end = r.find(['.', '[']).unwrap_or(r.len());
        let field = &r[..end];
        rest = &r[end..];
        let TypeInner::Struct { members, .. } = &module.types[cur].inner else { return None };
        let m = members.iter().find(|m| m.name.as_deref() == Some(field))?;
        offset += m.offset;
        cur = m.ty;
    }
    Some((offset, cur))
}

/// Why a value could not be packed.
#[derive(Debug, Clone, PartialEq)]
pub struct PackError(pub String);

/// Packs `values` (uniform path → value) into a buffer of the block's size. Paths the
/// emitted block does not hold (left out as unread) are skipped; values are written into
/// the leading components of their slot (a padded `float[]` element uses `.x`), booleans
/// as 0/1, matrices column by column with the emitted column stride.
pub fn pack(module: &Module, block_ty: Handle<Type>, values: &[(&str, &UniformValue)]) -> Result<Vec<u8>, PackError> {
    let size = match module.types[block_ty].inner {
        TypeInner::Struct { span, .. } => span as usize,
        _ => return Err(PackError("not a struct".into())),
    };
    let mut buf = vec![0u8; size];
    for (path, value) in values {
        let Some((offset, ty)) = resolve_path(module, block_ty, path) else { continue };
        write_slot(module, ty, offset, value, &mut buf).map_err(|e| PackError(format!("`{path}`: {e}")))?;
    }
    Ok(buf)
}

/// The block's bytes filled with the manifest's default values (semantics left zero).
pub fn pack_defaults(module: &Module, effect: &Effect) -> Result<Option<Vec<u8>>, PackError> {
    let Some(ty) = block_type(module) else { return Ok(None) };
    let values: Vec<(&str, &UniformValue)> =
        effect.uniforms.iter().filter_map(|u| u.value.as_ref().map(|v| (u.name.as_str(), v))).collect();
    pack(module, ty, &values).map(Some)
}

/// The generated uniform block's struct type in `module`, if it has one.
pub fn block_type(module: &Module) -> Option<Handle<Type>> {
    module
        .global_variables
        .iter()
        .find(|(_, g)| g.space == AddressSpace::Uniform && module.types[g.ty].name.as_deref() == Some(UNIFORM_BLOCK))
        .map(|(_, g)| g.ty)
}
