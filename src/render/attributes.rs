//! Which mesh attribute feeds each vertex shader input, and the interleaved vertex buffer.
//!
//! In order of trust: the manifest's `[mesh.attributes]`; the input's name (`aPos`,
//! `vertPosition`, `in_Normal`, `aTexCoords`, `tangent`, `vColor`, …); its location and
//! type (location 0 is the position; a later `vec2` a uv, `vec3` a normal, `vec4` a colour).
//! Every choice not written in the manifest is reported as a guess; an input nothing fits
//! reads zeros.

use crate::assets::attribute_names::by_name;
use crate::assets::mesh::Mesh;
use crate::back::reflect::InterfaceVar;
use crate::manifest::{InstanceAttribute, MeshAttribute};

/// Where one vertex input's data comes from.
#[derive(Debug, Clone, PartialEq)]
pub struct Choice {
    pub location: u32,
    pub input: String,
    pub format: wgpu::VertexFormat,
    /// The mesh attribute, or `None` for zeros (or `values`).
    pub attribute: Option<MeshAttribute>,
    /// The manifest's own numbers, one per vertex (`[mesh.attributes] x = { values = … }`).
    pub values: Option<InstanceAttribute>,
    /// Why it was chosen, when the manifest did not say (`by its name`, `by its location`).
    pub guessed: Option<&'static str>,
}

/// Matches every input to a mesh attribute, or to the manifest's own per-vertex `values`.
pub fn choose(inputs: &[InterfaceVar], explicit: &[(String, MeshAttribute)], values: &[InstanceAttribute]) -> Vec<Choice> {
    inputs
        .iter()
        .map(|input| {
            let format = input_format(input);
            if let Some(a) = values.iter().find(|a| a.input == input.name) {
                let values = Some(a.clone());
                return Choice { location: input.location, input: input.name.clone(), format, attribute: None, values, guessed: None };
            }
            let given = explicit.iter().find(|(name, _)| *name == input.name).map(|(_, attr)| *attr);
            let (attribute, guessed) = match given {
                Some(a) => (Some(a), None),
                // The compatibility profile's attributes mean what GL says they mean.
                None if crate::front::compat::attribute(&input.name).is_some() => (fixed_function(&input.name), None),
                None => match by_name(&input.name) {
                    Some(a) => (Some(a), Some("by its name")),
                    None => match by_location(input.location, format) {
                        Some(a) => (Some(a), Some("by its location and type")),
                        None => (None, Some("nothing matches it")),
                    },
                },
            };
            Choice { location: input.location, input: input.name.clone(), format, attribute, values: None, guessed }
        })
        .collect()
}

/// The mesh attribute a fixed-function attribute reads (`gl_Vertex` → position); `None`
/// where the mesh has none, and the input reads GL's current value.
fn fixed_function(name: &str) -> Option<MeshAttribute> {
    match name {
        "gl_Vertex" => Some(MeshAttribute::Position),
        "gl_Normal" => Some(MeshAttribute::Normal),
        "gl_Color" => Some(MeshAttribute::Color),
        "gl_MultiTexCoord0" => Some(MeshAttribute::Uv),
        _ => None,
    }
}

fn by_location(location: u32, format: wgpu::VertexFormat) -> Option<MeshAttribute> {
    use wgpu::VertexFormat as F;
    match (location, format) {
        (0, _) => Some(MeshAttribute::Position),
        (_, F::Float32x2) => Some(MeshAttribute::Uv),
        (_, F::Float32x3) => Some(MeshAttribute::Normal),
        (_, F::Float32x4) => Some(MeshAttribute::Color),
        _ => None,
    }
}

/// wgpu's vertex format for a reflection format name (`float32x3`).
pub fn vertex_format(name: &str) -> wgpu::VertexFormat {
    use wgpu::VertexFormat as F;
    match name {
        "float32" => F::Float32,
        "float32x2" => F::Float32x2,
        "float32x3" => F::Float32x3,
        "sint32" => F::Sint32,
        "sint32x2" => F::Sint32x2,
        "sint32x3" => F::Sint32x3,
        "sint32x4" => F::Sint32x4,
        "uint32" => F::Uint32,
        "uint32x2" => F::Uint32x2,
        "uint32x3" => F::Uint32x3,
        "uint32x4" => F::Uint32x4,
        "float64" => F::Float64,
        "float64x2" => F::Float64x2,
        "float64x3" => F::Float64x3,
        "float64x4" => F::Float64x4,
        _ => F::Float32x4,
    }
}

/// One vertex buffer holding every input, interleaved in input order.
#[derive(Clone)]
pub struct Interleaved {
    pub bytes: Vec<u8>,
    pub stride: u64,
    pub attributes: Vec<wgpu::VertexAttribute>,
}

/// The wgpu format of a vertex input (from its reflected format name).
pub fn input_format(input: &InterfaceVar) -> wgpu::VertexFormat {
    vertex_format(input.format.as_deref().unwrap_or("float32x4"))
}

/// Attributes packed one after another in the given order, and the stride (at least 4
/// bytes, so a buffer without attributes is still valid).
pub fn packed_layout(inputs: impl Iterator<Item = (u32, wgpu::VertexFormat)>) -> (Vec<wgpu::VertexAttribute>, u64) {
    let mut attributes = Vec::new();
    let mut stride = 0u64;
    for (shader_location, format) in inputs {
        attributes.push(wgpu::VertexAttribute { format, offset: stride, shader_location });
        stride += format.size();
    }
    (attributes, stride.max(4))
}

/// The per-instance buffer: every `[instances.attributes]` input, interleaved, one row per
/// instance, in the formats the shader declares. Returns `None` when the manifest feeds no
/// input per instance.
pub fn instance_buffer(inputs: &[InterfaceVar], decl: &crate::manifest::InstancesDecl) -> Option<Interleaved> {
    let fed: Vec<(&InterfaceVar, &crate::manifest::InstanceAttribute)> =
        decl.attributes.iter().filter_map(|a| inputs.iter().find(|i| i.name == a.input).map(|i| (i, a))).collect();
    if fed.is_empty() {
        return None;
    }
    let (attributes, stride) = packed_layout(fed.iter().map(|(input, _)| (input.location, input_format(input))));
    let mut bytes = Vec::with_capacity(decl.count as usize * stride as usize);
    for i in 0..decl.count {
        for ((_, a), attr) in fed.iter().zip(&attributes) {
            push_vertex_value(&mut bytes, attr.format, element_value(&a.source, i, a.components));
        }
    }
    Some(Interleaved { bytes, stride, attributes })
}

/// The value of one attribute the manifest gives numbers for, for instance (or vertex) `i`
/// (unused components 0, a fourth component 1 when the manifest gives three, like a
/// position).
fn element_value(source: &crate::manifest::InstanceSource, i: u32, components: usize) -> [f32; 4] {
    use crate::manifest::InstanceSource;
    let mut v = match source {
        InstanceSource::Values(values) => values.get(i as usize).copied().unwrap_or([0.0; 4]),
        InstanceSource::Sequence { start, step } => std::array::from_fn(|c| start[c] + step[c] * i as f32),
        InstanceSource::Random { lo, hi, seed } => std::array::from_fn(|c| lo[c] + (hi[c] - lo[c]) * unit_random(*seed, i, c as u32)),
    };
    if components == 3 {
        v[3] = 1.0;
    }
    v
}

/// A deterministic number in [0, 1) from (seed, instance, component): splitmix64.
pub(crate) fn unit_random(seed: u32, instance: u32, component: u32) -> f32 {
    let mut z = (u64::from(seed) << 32 | u64::from(instance)).wrapping_mul(4).wrapping_add(u64::from(component));
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^= z >> 31;
    (z >> 40) as f32 / (1u64 << 24) as f32
}

/// Interleaves the chosen attributes of `mesh` in the formats the shader declares.
pub fn interleave(choices: &[Choice], mesh: &Mesh) -> Interleaved {
    let (attributes, stride) = packed_layout(choices.iter().map(|c| (c.location, c.format)));
    let columns: Vec<Option<Vec<[f32; 4]>>> = choices.iter().map(|c| c.attribute.map(|a| mesh.attribute(a))).collect();
    let count = mesh.vertex_count();
    let mut bytes = Vec::with_capacity(count * stride as usize);
    for v in 0..count {
        let start = bytes.len();
        for (c, column) in choices.iter().zip(&columns) {
            // An input nothing feeds reads zeros; a fixed-function one GL's current value.
            let unfed = crate::front::compat::attribute(&c.input).map_or([0.0; 4], |a| a.current);
            let value = vertex_value(c, column.as_deref(), v, unfed);
            push_vertex_value(&mut bytes, c.format, value);
        }
        bytes.resize(start + stride as usize, 0);
    }
    Interleaved { bytes, stride, attributes }
}

/// The value vertex `v` gives the input of `c`: the manifest's own number, else the mesh
/// attribute's (`column`), else `unfed`.
pub fn vertex_value(c: &Choice, column: Option<&[[f32; 4]]>, v: usize, unfed: [f32; 4]) -> [f32; 4] {
    match &c.values {
        Some(a) => element_value(&a.source, v as u32, a.components),
        None => column.and_then(|col| col.get(v)).copied().unwrap_or(unfed),
    }
}

/// Appends `value` converted to `format` (integers truncate; extra components dropped).
fn push_vertex_value(out: &mut Vec<u8>, format: wgpu::VertexFormat, value: [f32; 4]) {
    use wgpu::VertexFormat as F;
    let (count, kind) = match format {
        F::Float32 => (1, 'f'),
        F::Float32x2 => (2, 'f'),
        F::Float32x3 => (3, 'f'),
        F::Float32x4 => (4, 'f'),
        F::Sint32 => (1, 'i'),
        F::Sint32x2 => (2, 'i'),
        F::Sint32x3 => (3, 'i'),
        F::Sint32x4 => (4, 'i'),
        F::Uint32 => (1, 'u'),
        F::Uint32x2 => (2, 'u'),
        F::Uint32x3 => (3, 'u'),
        F::Uint32x4 => (4, 'u'),
        F::Float64 => (1, 'd'),
        F::Float64x2 => (2, 'd'),
        F::Float64x3 => (3, 'd'),
        F::Float64x4 => (4, 'd'),
        _ => (0, 'f'),
    };
    for x in value.iter().take(count) {
        match kind {
            'i' => out.extend_from_slice(&(*x as i32).to_le_bytes()),
            'u' => out.extend_from_slice(&(x.max(0.0) as u32).to_le_bytes()),
            'd' => out.extend_from_slice(&f64::from(*x).to_le_bytes()),
            _ => out.extend_from_slice(&x.to_le_bytes()),
        }
    }
    let written = count * if kind == 'd' { 8 } else { 4 };
    out.resize(out.len() + (format.size() as usize).saturating_sub(written), 0);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A vertex input as the reflection describes it.
    fn input(location: u32, name: &str, format: &str) -> InterfaceVar {
        InterfaceVar {
            location,
            name: name.into(),
            wgsl_name: None,
            wgsl_type: String::new(),
            format: Some(format.into()),
            interpolation: None,
        }
    }

    #[test]
    fn inputs_are_matched_explicitly_then_by_name_then_by_location() {
        let mesh = Mesh::builtin(crate::manifest::BuiltinMesh::Cube);
        let inputs = [input(0, "p0", "float32x3"), input(1, "weird", "float32x2"), input(2, "aNormal", "float32x3")];
        let explicit = vec![("p0".to_string(), MeshAttribute::Position)];
        let c = choose(&inputs, &explicit, &[]);
        assert_eq!((c[0].attribute, c[0].guessed), (Some(MeshAttribute::Position), None));
        assert_eq!((c[1].attribute, c[1].guessed), (Some(MeshAttribute::Uv), Some("by its location and type")));
        assert_eq!((c[2].attribute, c[2].guessed), (Some(MeshAttribute::Normal), Some("by its name")));
        let buf = interleave(&c, &mesh);
        assert_eq!(buf.stride, 12 + 8 + 12);
        assert_eq!(buf.bytes.len(), mesh.vertex_count() * 32);
        assert_eq!(buf.attributes[2].offset, 20);
    }

    #[test]
    fn instance_attributes_are_interleaved_per_instance_and_deterministic() {
        use crate::manifest::{InstanceAttribute, InstanceSource, InstancesDecl};
        let inputs = [input(0, "aPos", "float32x3"), input(2, "aOffset", "float32x3"), input(3, "aSize", "float32")];
        let decl = InstancesDecl {
            span: 0..0,
            count: 5,
            attributes: vec![
                InstanceAttribute {
                    input: "aOffset".into(),
                    input_span: 0..0,
                    source: InstanceSource::Random { lo: [-1.0, 0.0, -1.0, 0.0], hi: [1.0, 2.0, 1.0, 0.0], seed: 9 },
                    components: 3,
                },
                InstanceAttribute {
                    input: "aSize".into(),
                    input_span: 0..0,
                    source: InstanceSource::Sequence { start: [1.0, 0.0, 0.0, 0.0], step: [0.5, 0.0, 0.0, 0.0] },
                    components: 1,
                },
            ],
        };
        let buf = instance_buffer(&inputs, &decl).unwrap();
        assert_eq!((buf.stride, buf.bytes.len()), (16, 5 * 16));
        assert_eq!(buf.attributes.iter().map(|a| a.shader_location).collect::<Vec<_>>(), vec![2, 3]);
        let f = |at: usize| f32::from_le_bytes(buf.bytes[at..at + 4].try_into().unwrap());
        for i in 0..5 {
            let row = i * 16;
            assert!((-1.0..1.0).contains(&f(row)) && (0.0..2.0).contains(&f(row + 4)), "inside the box");
            assert_eq!(f(row + 12), 1.0 + 0.5 * i as f32, "sequence");
        }
        assert_ne!(f(0), f(16), "instances differ");
        assert_eq!(instance_buffer(&inputs, &decl).unwrap().bytes, buf.bytes, "deterministic");
    }

    #[test]
    fn a_vec4_position_gets_w_one_and_integers_truncate() {
        let mut out = Vec::new();
        push_vertex_value(&mut out, wgpu::VertexFormat::Float32x4, [1.0, 2.0, 3.0, 1.0]);
        push_vertex_value(&mut out, wgpu::VertexFormat::Sint32x2, [2.7, -1.2, 0.0, 0.0]);
        assert_eq!(out.len(), 16 + 8);
        assert_eq!(f32::from_le_bytes(out[12..16].try_into().unwrap()), 1.0);
        assert_eq!(i32::from_le_bytes(out[16..20].try_into().unwrap()), 2);
    }
}
