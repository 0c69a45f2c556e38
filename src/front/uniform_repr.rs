//! How a uniform's GLSL type is stored in a uniform buffer WGSL accepts, with std140's bytes:
//! `bool`/`bvecN` as `uint`/`uvecN`, arrays of scalars and 2-vectors as arrays of 4-vectors
//! (std140 strides their elements 16 bytes apart), `mat2` as `vec4`. The shared uniform block
//! ([`plan`](crate::front::plan)), the user's uniform blocks and struct members in uniforms
//! ([`uniform_struct_arrays`](crate::front::uniform_struct_arrays)) store them so.

use crate::front::syntax::GlslType;

/// How a uniform is stored.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Repr {
    /// Stored as declared.
    Plain,
    /// `bool`/`bvecN` stored as `uint`/`uvecN`.
    Bool { components: u8 },
    /// Array of scalars or 2-vectors stored as 4-vectors; `swizzle` selects the element.
    Padded { swizzle: &'static str, bool_elems: bool },
    /// `mat2` stored as `vec4` (column-major: xy = column 0, zw = column 1).
    Mat2,
    /// `mat2[N]` stored as `vec4[N]`.
    Mat2Array,
}

/// How a uniform of type `ty` is stored in a uniform buffer WGSL accepts, with std140's
/// bytes; `doubles_as_floats`: the program's doubles become floats after the rewrite
/// ([`doubles`](crate::front::doubles)), so a `double`/`dvec2` array pads to a `dvec4`
/// (a `vec4` once lowered), where with real doubles a `double` array pads to `dvec2`
/// (std140's 16-byte stride) and a `dvec2` array is already strided so.
pub fn repr_for(ty: &GlslType, doubles_as_floats: bool) -> (GlslType, Repr) {
    let base = ty.base.as_str();
    if !ty.is_array() {
        return match base {
            "bool" => (GlslType::scalar("uint"), Repr::Bool { components: 1 }),
            "bvec2" | "bvec3" | "bvec4" => {
                let n = base.as_bytes()[4] - b'0';
                (GlslType::scalar(&format!("uvec{n}")), Repr::Bool { components: n })
            }
            "mat2" | "mat2x2" => (GlslType::scalar("vec4"), Repr::Mat2),
            _ => (ty.clone(), Repr::Plain),
        };
    }
    if ty.dims.len() != 1 {
        return (ty.clone(), Repr::Plain);
    }
    let padded =
        |b: &str, swizzle, bool_elems| (GlslType { base: b.to_string(), dims: ty.dims.clone() }, Repr::Padded { swizzle, bool_elems });
    match base {
        "float" => padded("vec4", "x", false),
        "int" => padded("ivec4", "x", false),
        "uint" => padded("uvec4", "x", false),
        "bool" => padded("uvec4", "x", true),
        "vec2" => padded("vec4", "xy", false),
        "ivec2" => padded("ivec4", "xy", false),
        "uvec2" => padded("uvec4", "xy", false),
        "double" => padded(if doubles_as_floats { "dvec4" } else { "dvec2" }, "x", false),
        "dvec2" if doubles_as_floats => padded("dvec4", "xy", false),
        "mat2" | "mat2x2" => (GlslType { base: "vec4".into(), dims: ty.dims.clone() }, Repr::Mat2Array),
        _ => (ty.clone(), Repr::Plain),
    }
}
