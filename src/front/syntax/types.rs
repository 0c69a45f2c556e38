//! GLSL types and storage as written: a base name with array dimensions, the storage and
//! interpolation qualifiers, and the texture + sampler pair naga wants for a combined sampler.

/// Storage class of a global declaration, as written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Storage {
    Uniform,
    In,
    Out,
    /// 1xx `attribute` (a vertex input).
    Attribute,
    /// 1xx `varying` (an output in the vertex stage, an input in the fragment stage).
    Varying,
    Buffer,
    Const,
    /// A private global (`float x;`).
    Private,
}

/// Interpolation qualifiers that must agree across a link.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Interp {
    Smooth,
    Flat,
    NoPerspective,
}

impl Interp {
    /// The qualifier as written in GLSL.
    pub const fn keyword(self) -> &'static str {
        match self {
            Interp::Smooth => "smooth",
            Interp::Flat => "flat",
            Interp::NoPerspective => "noperspective",
        }
    }
}

/// A GLSL type as written: base name plus array dimensions (None = unsized).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct GlslType {
    pub base: String,
    pub dims: Vec<Option<u32>>,
}

impl GlslType {
    pub fn scalar(base: &str) -> Self {
        GlslType { base: base.to_string(), dims: Vec::new() }
    }
    pub fn is_array(&self) -> bool {
        !self.dims.is_empty()
    }
    pub fn element(&self) -> GlslType {
        GlslType { base: self.base.clone(), dims: self.dims.iter().skip(1).cloned().collect() }
    }
    /// Integer scalar or vector (`int`, `uvec3`, …): never interpolated, so `flat` in effect.
    pub fn is_integer(&self) -> bool {
        matches!(self.base.as_str(), "int" | "uint")
            || ["ivec", "uvec"].iter().any(|p| self.base.strip_prefix(p).is_some_and(|n| matches!(n, "2" | "3" | "4")))
    }
    /// The index suffix of every element (`[1][0]`), in order; one empty suffix for a
    /// non-array. Unsized dimensions count one element.
    pub fn element_suffixes(&self) -> Vec<String> {
        let mut out = vec![String::new()];
        for d in &self.dims {
            out = out.iter().flat_map(|e| (0..d.unwrap_or(1)).map(move |i| format!("{e}[{i}]"))).collect();
        }
        out
    }
    /// `dst = src;` element by element for an array (naga's GLSL front gives an array in a
    /// struct the std140 stride and one outside it the natural one, and refuses to assign
    /// one to the other whole).
    pub fn copy(&self, dst: &str, src: &str) -> String {
        self.element_suffixes().iter().map(|e| format!(" {dst}{e} = {src}{e};")).collect()
    }
    /// Components of a float or integer scalar or vector base type (`float`, `int`, `uint`
    /// 1 … `vec4`, `ivec4`, `uvec4` 4), whatever the array dimensions.
    pub fn vector_components(&self) -> Option<u32> {
        match self.base.as_str() {
            "float" | "int" | "uint" => Some(1),
            "vec2" | "ivec2" | "uvec2" => Some(2),
            "vec3" | "ivec3" | "uvec3" => Some(3),
            "vec4" | "ivec4" | "uvec4" => Some(4),
            _ => None,
        }
    }
    /// Opaque (sampler) base type.
    pub fn is_sampler(&self) -> bool {
        sampler_parts(&self.base).is_some()
    }
}

impl std::fmt::Display for GlslType {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.base)?;
        for d in &self.dims {
            match d {
                Some(n) => write!(f, "[{n}]")?,
                None => f.write_str("[]")?,
            }
        }
        Ok(())
    }
}

/// (columns, rows) of a float matrix type name (`mat3` (3, 3), `mat2x4` (2, 4)).
pub fn matrix_shape(base: &str) -> Option<(u32, u32)> {
    let rest = base.strip_prefix("mat")?;
    let d = |c: u8| (b'2'..=b'4').contains(&c).then(|| u32::from(c - b'0'));
    match rest.as_bytes() {
        [n] => d(*n).map(|n| (n, n)),
        [c, b'x', r] => Some((d(*c)?, d(*r)?)),
        _ => None,
    }
}

/// `[4][2]` for a type's dimensions.
pub fn dims_text(ty: &GlslType) -> String {
    ty.dims.iter().map(|d| d.map_or("[]".to_string(), |n| format!("[{n}]"))).collect()
}

/// Whether a sampler type reads a rectangle texture (`ARB_texture_rectangle`, GLSL 1.40):
/// coordinates in texels, one level, clamped at the edges. effectc reads it as a 2D
/// texture with its coordinates scaled.
pub fn is_rect_sampler(base: &str) -> bool {
    matches!(base, "sampler2DRect" | "isampler2DRect" | "usampler2DRect" | "sampler2DRectShadow")
}

/// The texel type of a buffer texture (`samplerBuffer` → `vec4`): WebGPU has no buffer
/// textures, so effectc reads one from a read-only storage buffer of such texels.
pub fn texel_buffer_element(base: &str) -> Option<&'static str> {
    Some(match base {
        "samplerBuffer" => "vec4",
        "isamplerBuffer" => "ivec4",
        "usamplerBuffer" => "uvec4",
        _ => return None,
    })
}

/// For a combined sampler type, the separate texture type and sampler type naga wants.
pub fn sampler_parts(base: &str) -> Option<(&'static str, &'static str)> {
    Some(match base {
        "sampler1D" => ("texture1D", "sampler"),
        "sampler2D" => ("texture2D", "sampler"),
        "sampler3D" => ("texture3D", "sampler"),
        "samplerCube" => ("textureCube", "sampler"),
        "sampler2DArray" => ("texture2DArray", "sampler"),
        "samplerCubeArray" => ("textureCubeArray", "sampler"),
        "sampler2DMS" => ("texture2DMS", "sampler"),
        "sampler2DShadow" => ("texture2D", "samplerShadow"),
        // WGSL has no 1D depth texture: a 2D one of one row (`calls::reshaped_lookup`).
        "sampler1DShadow" => ("texture2D", "samplerShadow"),
        "samplerCubeShadow" => ("textureCube", "samplerShadow"),
        "sampler2DArrayShadow" => ("texture2DArray", "samplerShadow"),
        "isampler2D" => ("itexture2D", "sampler"),
        "isampler3D" => ("itexture3D", "sampler"),
        "isamplerCube" => ("itextureCube", "sampler"),
        "isampler2DArray" => ("itexture2DArray", "sampler"),
        "usampler2D" => ("utexture2D", "sampler"),
        "usampler3D" => ("utexture3D", "sampler"),
        "usamplerCube" => ("utextureCube", "sampler"),
        "usampler2DArray" => ("utexture2DArray", "sampler"),
        "sampler2DRect" => ("texture2D", "sampler"),
        "isampler2DRect" => ("itexture2D", "sampler"),
        "usampler2DRect" => ("utexture2D", "sampler"),
        "sampler2DRectShadow" => ("texture2D", "samplerShadow"),
        _ => return None,
    })
}

/// For an image declared without a format qualifier (`writeonly uniform image2D img;`,
/// legal: GL takes the format of the image bound), the format effectc gives it, as WebGPU
/// needs one: the widest of its sampled type (`rgba32f`, `rgba32i`, `rgba32ui`), which holds
/// every value the stage can store. `None` for other types and images with a format.
pub fn chosen_image_format(base: &str, layout: &[(String, Option<i64>)]) -> Option<&'static str> {
    let format = if base.starts_with("image") {
        "rgba32f"
    } else if base.starts_with("iimage") {
        "rgba32i"
    } else if base.starts_with("uimage") {
        "rgba32ui"
    } else {
        return None;
    };
    (!layout.iter().any(|(k, _)| crate::front::builtins::IMAGE_FORMATS.contains(&k.as_str()))).then_some(format)
}
