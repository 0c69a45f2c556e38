//! `[uniforms]` entries: a uniform's default [`UniformValue`], its `range`, or the
//! [`Semantic`] the runtime feeds it every frame.

use std::ops::Range;

/// One entry of `[uniforms]`.
#[derive(Debug, Clone, PartialEq)]
pub struct UniformDefault {
    /// The uniform's name as the shader declares it (`minBI`, `lights[0].color`).
    pub name: String,
    pub name_span: Range<usize>,
    /// The default value; `None` for a uniform bound to a semantic.
    pub value: Option<UniformValue>,
    /// Span of the value; for a table without `value`, the span of the whole table.
    pub value_span: Range<usize>,
    /// `range = [lo, hi]`, with `lo <= hi`, both finite.
    pub range: Option<(f64, f64)>,
    pub range_span: Option<Range<usize>>,
    pub semantic: Option<Semantic>,
    /// Span of the `semantic` string.
    pub semantic_span: Option<Range<usize>>,
}

/// A default value. Its GLSL type is resolved against the shader's declaration later: a
/// `vec3` is a `List` of 3 numbers; a `mat3` a `List` of 3 column `List`s of 3, or a flat
/// `List` of 9 (column-major); arrays are `List`s. Numbers are finite.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[serde(untagged)]
pub enum UniformValue {
    Bool(bool),
    Int(i64),
    Float(f64),
    List(Vec<UniformValue>),
}

impl UniformValue {
    /// The number as `f64`, for `Int` and `Float`.
    pub fn as_f64(&self) -> Option<f64> {
        match *self {
            UniformValue::Int(i) => Some(i as f64),
            UniformValue::Float(f) => Some(f),
            _ => None,
        }
    }
    /// Dimensions of nested lists, outermost first: `[]` for a scalar, `[3]` for
    /// `[1, 2, 3]`, `[3, 3]` for a mat3 written as columns. Lists are checked to be
    /// rectangular when parsed.
    pub fn dims(&self) -> Vec<usize> {
        let mut dims = Vec::new();
        let mut v = self;
        while let UniformValue::List(items) = v {
            dims.push(items.len());
            match items.first() {
                Some(first) => v = first,
                None => break,
            }
        }
        dims
    }
    /// All scalars in order (row of the flattened nested lists).
    pub fn scalars(&self) -> Vec<&UniformValue> {
        fn walk<'a>(v: &'a UniformValue, out: &mut Vec<&'a UniformValue>) {
            match v {
                UniformValue::List(items) => items.iter().for_each(|i| walk(i, out)),
                s => out.push(s),
            }
        }
        let mut out = Vec::new();
        walk(self, &mut out);
        out
    }
}

/// A value the runtime supplies every frame instead of a constant default.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Semantic {
    /// Seconds since start.
    Time,
    /// Frame index.
    Frame,
    /// Seconds since the previous frame.
    DeltaTime,
    /// Render target size in pixels (`vec3`: z = 1, like Shadertoy's `iResolution`).
    Resolution,
    Model,
    View,
    Projection,
    ModelView,
    ViewProjection,
    #[serde(rename = "mvp")]
    ModelViewProjection,
    /// Inverse-transpose of the model-view matrix.
    NormalMatrix,
    /// World-space camera position.
    CameraPosition,
    /// Pointer position in pixels (`vec4`: Shadertoy's `iMouse` layout).
    Mouse,
}

impl Semantic {
    pub const ALL: [Semantic; 13] = [
        Semantic::Time,
        Semantic::Frame,
        Semantic::DeltaTime,
        Semantic::Resolution,
        Semantic::Model,
        Semantic::View,
        Semantic::Projection,
        Semantic::ModelView,
        Semantic::ViewProjection,
        Semantic::ModelViewProjection,
        Semantic::NormalMatrix,
        Semantic::CameraPosition,
        Semantic::Mouse,
    ];

    /// The name used in manifests.
    pub fn name(&self) -> &'static str {
        match self {
            Semantic::Time => "time",
            Semantic::Frame => "frame",
            Semantic::DeltaTime => "delta_time",
            Semantic::Resolution => "resolution",
            Semantic::Model => "model",
            Semantic::View => "view",
            Semantic::Projection => "projection",
            Semantic::ModelView => "model_view",
            Semantic::ViewProjection => "view_projection",
            Semantic::ModelViewProjection => "mvp",
            Semantic::NormalMatrix => "normal_matrix",
            Semantic::CameraPosition => "camera_position",
            Semantic::Mouse => "mouse",
        }
    }

    /// Parse a manifest name (including the alias `model_view_projection`).
    pub fn from_name(name: &str) -> Option<Semantic> {
        if name == "model_view_projection" {
            return Some(Semantic::ModelViewProjection);
        }
        Semantic::ALL.into_iter().find(|s| s.name() == name)
    }

    /// The GLSL types a uniform bound to this semantic may be declared with.
    pub fn glsl_types(&self) -> &'static [&'static str] {
        match self {
            Semantic::Time | Semantic::DeltaTime => &["float"],
            Semantic::Frame => &["int", "uint", "float"],
            Semantic::Resolution => &["vec2", "vec3"],
            Semantic::Model
            | Semantic::View
            | Semantic::Projection
            | Semantic::ModelView
            | Semantic::ViewProjection
            | Semantic::ModelViewProjection => &["mat4"],
            Semantic::NormalMatrix => &["mat3", "mat4"],
            Semantic::CameraPosition => &["vec3", "vec4"],
            Semantic::Mouse => &["vec2", "vec4"],
        }
    }
}
