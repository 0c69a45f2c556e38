//! The generated uniform block in the reflection: every member with its offset, size and
//! types, down to the fields of structs and the layout of arrays, and which bytes the
//! manifest or a GLSL initializer fills. A program can pack the buffer from this alone.

use std::collections::BTreeMap;

use naga::{Handle, Module, Type, TypeInner};
use serde::Serialize;

use super::names::WgslNames;
use super::{resolve_path, type_name};
use crate::front::plan::{Plan, Repr, UNIFORM_BLOCK};
use crate::manifest::{Effect, UniformValue};

#[derive(Debug, Clone, Serialize)]
pub struct UniformBlock {
    pub name: String,
    pub group: u32,
    pub binding: u32,
    pub size: u32,
    pub members: Vec<UniformMember>,
    /// Which manifest entry or GLSL initializer fills which bytes.
    pub fills: Vec<Fill>,
}

#[derive(Debug, Clone, Serialize)]
pub struct UniformMember {
    /// The GLSL name (effectc's own for padding).
    pub name: String,
    /// The name the WGSL declares (`light0_` for `light0`).
    pub wgsl_name: String,
    /// Type as the user declared it in GLSL.
    pub glsl_type: String,
    /// Type in the emitted code (WGSL spelling).
    pub wgsl_type: String,
    /// Bytes from the start of the block (for an array's fields: those of element 0).
    pub offset: u32,
    pub size: u32,
    /// How the GLSL value is stored: `plain`, `bool_as_uint`, `padded_to_vec4`, `mat2_as_vec4`, `mat2_array_as_vec4_array`,
    /// `columns_as_vec4` (a two-row matrix's columns each in a `vec4`'s `.xy`, 16 bytes apart).
    pub repr: &'static str,
    /// Filler effectc inserted to keep the GLSL layout: never written.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub padding: bool,
    /// An array: element `i` starts at `offset + i * stride`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub array: Option<ArrayLayout>,
    /// A matrix (or an array of them): bytes from one column to the next.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub column_stride: Option<u32>,
    /// A struct (or an array of structs): its fields, offsets from the start of the block.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub members: Vec<UniformMember>,
}

#[derive(Debug, Clone, Copy, Serialize)]
pub struct ArrayLayout {
    pub length: u32,
    pub stride: u32,
}

#[derive(Debug, Clone, Serialize)]
pub struct Fill {
    /// Manifest uniform name (`minBI`, `lights[0].color`).
    pub uniform: String,
    /// Byte range `[start, end)` in the block.
    pub bytes: [u32; 2],
    #[serde(skip_serializing_if = "Option::is_none")]
    pub value: Option<UniformValue>,
    /// Filled per frame by the renderer instead of a value.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub semantic: Option<String>,
    /// `manifest`, or `initializer` for a GLSL initializer the manifest does not override.
    pub from: &'static str,
}

/// The GLSL types of the fields of the program's structs, by (struct, field).
pub(super) type GlslFields = BTreeMap<(String, String), String>;

/// Everything [`block_of`] reads besides the module.
pub(super) struct BlockSources<'a> {
    pub plan: &'a Plan,
    pub effect: Option<&'a Effect>,
    /// GLSL initializers of uniforms (`uniform float gain = 2.0;`), `#pragma parameter`
    /// defaults.
    pub initial: &'a [crate::front::initial_values::Initial],
    pub names: &'a WgslNames,
    pub fields: &'a GlslFields,
}

pub(super) fn block_of(module: &Module, ty: Handle<Type>, rb: &naga::ResourceBinding, sources: &BlockSources<'_>) -> UniformBlock {
    let (members, size) = match &module.types[ty].inner {
        TypeInner::Struct { members, span } => (members.clone(), *span),
        _ => (Vec::new(), 0),
    };
    let mut layouter = naga::proc::Layouter::default();
    let _ = layouter.update(module.to_ctx());
    let out_members = members
        .iter()
        .enumerate()
        .map(|(i, m)| {
            let name = m.name.clone().unwrap_or_default();
            let pm = sources.plan.member(&name);
            let wgsl_name = sources.names.member(ty, i).unwrap_or_else(|| name.clone());
            let glsl_type = pm.map(|p| p.user_ty.to_string()).unwrap_or_else(|| type_name(module, m.ty));
            let repr = match pm.map(|p| repr_name(&p.repr)) {
                Some("plain") | None => stored_as(&glsl_type, &type_name(module, m.ty)),
                Some(planned) => planned,
            };
            describe(module, &layouter, sources, (m.ty, m.offset), Named { name, wgsl_name, glsl_type, repr })
        })
        .collect();
    let mut fills = Vec::new();
    let mut fill = |uniform: &str, value: Option<UniformValue>, semantic: Option<String>, from| {
        let Some((offset, t)) = resolve_path(module, ty, uniform) else { return };
        fills.push(Fill { uniform: uniform.to_string(), bytes: [offset, offset + layouter[t].size], value, semantic, from });
    };
    let uniforms = sources.effect.map(|e| &e.uniforms[..]).unwrap_or_default();
    for u in uniforms {
        fill(&u.name, u.value.clone(), u.semantic.map(|s| s.name().to_string()), "manifest");
    }
    // An initializer is the value where the manifest gives none (of the uniform or a part).
    let root = |path: &str| path[..path.find(['.', '[']).unwrap_or(path.len())].to_string();
    for i in sources.initial {
        if !uniforms.iter().any(|u| root(&u.name) == root(&i.path)) {
            fill(&i.path, Some(i.value.clone()), None, i.from.key());
        }
    }
    UniformBlock { name: UNIFORM_BLOCK.to_string(), group: rb.group, binding: rb.binding, size, members: out_members, fills }
}

/// A member's names, GLSL type and storage, as its parent knows them.
struct Named {
    name: String,
    wgsl_name: String,
    glsl_type: String,
    repr: &'static str,
}

/// One member at `offset` (from the start of the block), with its fields and array layout.
fn describe(
    module: &Module,
    layouter: &naga::proc::Layouter,
    sources: &BlockSources<'_>,
    (ty, offset): (Handle<Type>, u32),
    named: Named,
) -> UniformMember {
    let (array, element) = match module.types[ty].inner {
        TypeInner::Array { base, size: naga::ArraySize::Constant(n), stride } => (Some(ArrayLayout { length: n.get(), stride }), base),
        _ => (None, ty),
    };
    let column_stride = match module.types[element].inner {
        // A column is a vecR: 8 bytes apart for two rows, 16 for three or four (f32).
        TypeInner::Matrix { rows, scalar, .. } => Some(if rows == naga::VectorSize::Bi { 2 } else { 4 } * u32::from(scalar.width)),
        _ => None,
    };
    let members = match &module.types[element].inner {
        TypeInner::Struct { members, .. } => {
            let struct_name = module.types[element].name.clone().unwrap_or_default();
            members
                .iter()
                .enumerate()
                .map(|(i, m)| {
                    let name = m.name.clone().unwrap_or_default();
                    let wgsl_type = type_name(module, m.ty);
                    let glsl_type = sources.fields.get(&(struct_name.clone(), name.clone())).cloned().unwrap_or_else(|| wgsl_type.clone());
                    let repr = stored_as(&glsl_type, &wgsl_type);
                    let wgsl_name = sources.names.member(element, i).unwrap_or_else(|| name.clone());
                    describe(module, layouter, sources, (m.ty, offset + m.offset), Named { name, wgsl_name, glsl_type, repr })
                })
                .collect()
        }
        _ => Vec::new(),
    };
    UniformMember {
        padding: named.name.starts_with("effectc_pad"),
        name: named.name,
        wgsl_name: named.wgsl_name,
        glsl_type: named.glsl_type,
        wgsl_type: type_name(module, ty),
        offset,
        size: layouter[ty].size,
        repr: named.repr,
        array,
        column_stride,
        members,
    }
}

/// How a struct field of GLSL type `glsl` is stored as `wgsl` (fields are not in the
/// plan, which rewrites only the block's own members; a field keeps its GLSL type unless
/// WGSL's uniform rules changed it).
fn stored_as(glsl: &str, wgsl: &str) -> &'static str {
    let scalar_array = glsl.contains('[') && !glsl.contains("vec") && !glsl.contains("mat");
    if glsl.starts_with("bool") || glsl.starts_with("bvec") {
        "bool_as_uint"
    } else if scalar_array && wgsl.starts_with("array<vec4") {
        "padded_to_vec4"
    } else if glsl.starts_with("mat2") && !glsl.contains('[') && wgsl.starts_with("vec4") {
        "mat2_as_vec4"
    } else if glsl.starts_with("mat2") && wgsl.starts_with("array<vec4") && glsl.contains('[') {
        "mat2_array_as_vec4_array"
    } else if two_rows(glsl) && wgsl.starts_with("array<") && wgsl.contains("vec4") {
        // A std140 block's two-row matrix on the route through SPIR-V: each column in a
        // `vec4`'s `.xy`, 16 bytes apart.
        "columns_as_vec4"
    } else {
        "plain"
    }
}

/// Whether GLSL type `glsl` is a matrix of two rows (`mat2`, `mat3x2`, `mat4x2`, arrays too).
fn two_rows(glsl: &str) -> bool {
    let base = glsl.split('[').next().unwrap_or(glsl);
    matches!(base, "mat2" | "mat2x2" | "mat3x2" | "mat4x2")
}

fn repr_name(r: &Repr) -> &'static str {
    match r {
        Repr::Plain => "plain",
        Repr::Bool { .. } => "bool_as_uint",
        Repr::Padded { .. } => "padded_to_vec4",
        Repr::Mat2 => "mat2_as_vec4",
        Repr::Mat2Array => "mat2_array_as_vec4_array",
    }
}
