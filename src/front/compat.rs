//! The compatibility profile's built-ins (GLSL 1.10–1.50 `compatibility`): what each one
//! is, how effectc declares it for naga, and what a program needs of them.
//!
//! naga knows none of them; the rewrite declares each one the program uses under its own
//! name, so uses stay as the user wrote them:
//! - **fixed-function vertex attributes** (`gl_Vertex`, `gl_Normal`, `gl_Color`,
//!   `gl_MultiTexCoordN`, …): vertex inputs, bound by the renderer like named attributes,
//!   reading GL's current value where the mesh has no such attribute;
//! - **uniform state** (the matrices, `gl_LightSource[]`, `gl_FrontMaterial`, `gl_Fog`, …):
//!   members of the shared uniform block, fed from the scene's camera and model or GL's
//!   documented initial values; the inverse/transpose matrix forms are computed from
//!   their matrix where they are read, the light products from the light, material and
//!   light-model state first in `main`, as GL derives them;
//! - **fixed-function varyings**: `gl_FrontColor`, `gl_FrontSecondaryColor`,
//!   `gl_FogFragCoord` and `gl_TexCoord[]` written by the vertex stage and read by the
//!   fragment stage as `gl_Color`, `gl_SecondaryColor`, `gl_FogFragCoord`, `gl_TexCoord[]`
//!   (two-sided colour is off, GL's default: the fragment stage reads the front colours,
//!   clamped to [0, 1] as GL's initial `CLAMP_VERTEX_COLOR` does);
//!   back colours and `gl_ClipVertex` are computed and not used;
//! - **draw parameters** (`gl_BaseVertex`, `gl_BaseInstance`, `gl_DrawID`, and their
//!   `ARB` forms; GL 4.6 and Vulkan GLSL too), which WGSL has no built-in for: members of
//!   the shared uniform block like the state above, zero for effectc's own draws (WGSL's
//!   `vertex_index` and `instance_index` already count from the draw's bases);
//! - `ftransform()` is `gl_ModelViewProjectionMatrix * gl_Vertex`; the implementation
//!   constants (`gl_MaxLights`, …) are Mesa's.

use std::collections::BTreeSet;

use crate::front::syntax::{GlslType, Referent, StageSyntax};
use crate::stage::StageKind;

/// A fixed-function vertex attribute.
#[derive(Debug, Clone, Copy)]
pub struct Attribute {
    pub name: &'static str,
    pub ty: &'static str,
    /// GL's initial current value, which the attribute reads when no array feeds it.
    pub current: [f32; 4],
}

const ZERO_W1: [f32; 4] = [0.0, 0.0, 0.0, 1.0];

/// The attributes, in the order their locations are handed out (`gl_Vertex` first, as
/// GL aliases it with generic attribute 0).
pub const ATTRIBUTES: &[Attribute] = &[
    Attribute { name: "gl_Vertex", ty: "vec4", current: ZERO_W1 },
    Attribute { name: "gl_Normal", ty: "vec3", current: [0.0, 0.0, 1.0, 0.0] },
    Attribute { name: "gl_Color", ty: "vec4", current: [1.0; 4] },
    Attribute { name: "gl_SecondaryColor", ty: "vec4", current: ZERO_W1 },
    Attribute { name: "gl_FogCoord", ty: "float", current: [0.0; 4] },
    Attribute { name: "gl_MultiTexCoord0", ty: "vec4", current: ZERO_W1 },
    Attribute { name: "gl_MultiTexCoord1", ty: "vec4", current: ZERO_W1 },
    Attribute { name: "gl_MultiTexCoord2", ty: "vec4", current: ZERO_W1 },
    Attribute { name: "gl_MultiTexCoord3", ty: "vec4", current: ZERO_W1 },
    Attribute { name: "gl_MultiTexCoord4", ty: "vec4", current: ZERO_W1 },
    Attribute { name: "gl_MultiTexCoord5", ty: "vec4", current: ZERO_W1 },
    Attribute { name: "gl_MultiTexCoord6", ty: "vec4", current: ZERO_W1 },
    Attribute { name: "gl_MultiTexCoord7", ty: "vec4", current: ZERO_W1 },
];

/// The attribute named `name`.
pub fn attribute(name: &str) -> Option<&'static Attribute> {
    ATTRIBUTES.iter().find(|a| a.name == name)
}

/// GL's fixed limits as Mesa's drivers give them (`gl_MaxLights`, …).
pub const MAX_LIGHTS: u32 = 8;
pub const MAX_CLIP_PLANES: u32 = 8;
pub const MAX_TEXTURE_COORDS: u32 = 8;
pub const MAX_TEXTURE_UNITS: u32 = 8;

const CONSTANTS: &[(&str, u32)] = &[
    ("gl_MaxLights", MAX_LIGHTS),
    ("gl_MaxClipPlanes", MAX_CLIP_PLANES),
    ("gl_MaxTextureCoords", MAX_TEXTURE_COORDS),
    ("gl_MaxTextureUnits", MAX_TEXTURE_UNITS),
];

/// One piece of uniform state: a member of the shared uniform block.
#[derive(Debug, Clone, Copy)]
pub struct State {
    pub name: &'static str,
    pub ty: &'static str,
    pub count: Option<u32>,
}

/// The uniform state, in block order.
pub const STATE: &[State] = &[
    State { name: "gl_ModelViewMatrix", ty: "mat4", count: None },
    State { name: "gl_ProjectionMatrix", ty: "mat4", count: None },
    State { name: "gl_ModelViewProjectionMatrix", ty: "mat4", count: None },
    State { name: "gl_NormalMatrix", ty: "mat3", count: None },
    State { name: "gl_TextureMatrix", ty: "mat4", count: Some(MAX_TEXTURE_COORDS) },
    State { name: "gl_DepthRange", ty: "gl_DepthRangeParameters", count: None },
    State { name: "gl_ClipPlane", ty: "vec4", count: Some(MAX_CLIP_PLANES) },
    State { name: "gl_Point", ty: "gl_PointParameters", count: None },
    State { name: "gl_FrontMaterial", ty: "gl_MaterialParameters", count: None },
    State { name: "gl_BackMaterial", ty: "gl_MaterialParameters", count: None },
    State { name: "gl_LightSource", ty: "gl_LightSourceParameters", count: Some(MAX_LIGHTS) },
    State { name: "gl_LightModel", ty: "gl_LightModelParameters", count: None },
    State { name: "gl_TextureEnvColor", ty: "vec4", count: Some(MAX_TEXTURE_UNITS) },
    State { name: "gl_EyePlaneS", ty: "vec4", count: Some(MAX_TEXTURE_COORDS) },
    State { name: "gl_EyePlaneT", ty: "vec4", count: Some(MAX_TEXTURE_COORDS) },
    State { name: "gl_EyePlaneR", ty: "vec4", count: Some(MAX_TEXTURE_COORDS) },
    State { name: "gl_EyePlaneQ", ty: "vec4", count: Some(MAX_TEXTURE_COORDS) },
    State { name: "gl_ObjectPlaneS", ty: "vec4", count: Some(MAX_TEXTURE_COORDS) },
    State { name: "gl_ObjectPlaneT", ty: "vec4", count: Some(MAX_TEXTURE_COORDS) },
    State { name: "gl_ObjectPlaneR", ty: "vec4", count: Some(MAX_TEXTURE_COORDS) },
    State { name: "gl_ObjectPlaneQ", ty: "vec4", count: Some(MAX_TEXTURE_COORDS) },
    State { name: "gl_Fog", ty: "gl_FogParameters", count: None },
    // The draw parameters (GL 4.6, ARB_shader_draw_parameters, Vulkan GLSL), which WGSL
    // lacks: the host's draw sets them; effectc's draws start at vertex and instance 0.
    State { name: "gl_BaseVertex", ty: "int", count: None },
    State { name: "gl_BaseInstance", ty: "int", count: None },
    State { name: "gl_DrawID", ty: "int", count: None },
    State { name: "gl_BaseVertexARB", ty: "int", count: None },
    State { name: "gl_BaseInstanceARB", ty: "int", count: None },
    State { name: "gl_DrawIDARB", ty: "int", count: None },
];

impl State {
    pub fn glsl_type(&self) -> GlslType {
        GlslType { base: self.ty.to_string(), dims: self.count.map(|n| vec![Some(n)]).unwrap_or_default() }
    }
}

/// The state member named `name`.
pub fn state(name: &str) -> Option<&'static State> {
    STATE.iter().find(|s| s.name == name)
}

/// GL's initial values of the state member `name` (the OpenGL 2.1 specification's state
/// tables; derived values and the point size limit as Mesa's driver gives them), leaf by
/// leaf: (path, components). Leaves not listed start at zero.
pub fn initial_values(name: &str) -> Vec<(String, Vec<f32>)> {
    let Some(st) = state(name) else { return Vec::new() };
    let elements: Vec<String> = match st.count {
        Some(n) => (0..n).map(|i| format!("{name}[{i}]")).collect(),
        None => vec![name.to_string()],
    };
    let mut out = Vec::new();
    for (i, at) in elements.iter().enumerate() {
        let mut leaf = |member: &str, v: &[f32]| {
            let path = if member.is_empty() { at.clone() } else { format!("{at}.{member}") };
            out.push((path, v.to_vec()));
        };
        let identity = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0];
        let axis = |k: usize| {
            let mut v = [0.0; 4];
            v[k] = 1.0;
            v
        };
        match name {
            "gl_TextureMatrix" => leaf("", &identity),
            "gl_DepthRange" => {
                leaf("near", &[0.0]);
                leaf("far", &[1.0]);
                leaf("diff", &[1.0]);
            }
            "gl_Point" => {
                leaf("size", &[1.0]);
                leaf("sizeMin", &[0.0]);
                leaf("sizeMax", &[255.0]);
                leaf("fadeThresholdSize", &[1.0]);
                leaf("distanceConstantAttenuation", &[1.0]);
            }
            "gl_FrontMaterial" | "gl_BackMaterial" => {
                leaf("emission", &ZERO_W1);
                leaf("ambient", &[0.2, 0.2, 0.2, 1.0]);
                leaf("diffuse", &[0.8, 0.8, 0.8, 1.0]);
                leaf("specular", &ZERO_W1);
            }
            "gl_LightSource" => {
                let bright = if i == 0 { [1.0; 4] } else { ZERO_W1 };
                leaf("ambient", &ZERO_W1);
                leaf("diffuse", &bright);
                leaf("specular", &bright);
                leaf("position", &[0.0, 0.0, 1.0, 0.0]);
                // Mesa derives `halfVector` only while fixed-function lighting is on (a
                // program replaces it: zero), and keeps the cosine of the initial 180°
                // cutoff at 0, not -1 ("negative values not admitted").
                leaf("spotDirection", &[0.0, 0.0, -1.0]);
                leaf("spotCutoff", &[180.0]);
                leaf("constantAttenuation", &[1.0]);
            }
            "gl_LightModel" => leaf("ambient", &[0.2, 0.2, 0.2, 1.0]),
            "gl_EyePlaneS" | "gl_ObjectPlaneS" => leaf("", &axis(0)),
            "gl_EyePlaneT" | "gl_ObjectPlaneT" => leaf("", &axis(1)),
            "gl_Fog" => {
                leaf("density", &[1.0]);
                leaf("end", &[1.0]);
                leaf("scale", &[1.0]);
            }
            // Clip planes, texture environment colours and the R and Q planes start at zero.
            _ => {}
        }
    }
    out
}

/// The built-in struct types, as the compatibility profile declares them: name and
/// members (type, name).
pub const STRUCTS: &[(&str, &[(&str, &str)])] = &[
    ("gl_DepthRangeParameters", &[("float", "near"), ("float", "far"), ("float", "diff")]),
    (
        "gl_PointParameters",
        &[
            ("float", "size"),
            ("float", "sizeMin"),
            ("float", "sizeMax"),
            ("float", "fadeThresholdSize"),
            ("float", "distanceConstantAttenuation"),
            ("float", "distanceLinearAttenuation"),
            ("float", "distanceQuadraticAttenuation"),
        ],
    ),
    (
        "gl_MaterialParameters",
        &[("vec4", "emission"), ("vec4", "ambient"), ("vec4", "diffuse"), ("vec4", "specular"), ("float", "shininess")],
    ),
    (
        "gl_LightSourceParameters",
        &[
            ("vec4", "ambient"),
            ("vec4", "diffuse"),
            ("vec4", "specular"),
            ("vec4", "position"),
            ("vec4", "halfVector"),
            ("vec3", "spotDirection"),
            ("float", "spotExponent"),
            ("float", "spotCutoff"),
            ("float", "spotCosCutoff"),
            ("float", "constantAttenuation"),
            ("float", "linearAttenuation"),
            ("float", "quadraticAttenuation"),
        ],
    ),
    ("gl_LightModelParameters", &[("vec4", "ambient")]),
    ("gl_FogParameters", &[("vec4", "color"), ("float", "density"), ("float", "start"), ("float", "end"), ("float", "scale")]),
    ("gl_LightModelProducts", &[("vec4", "sceneColor")]),
    ("gl_LightProducts", &[("vec4", "ambient"), ("vec4", "diffuse"), ("vec4", "specular")]),
];

fn struct_members(name: &str) -> Option<&'static [(&'static str, &'static str)]> {
    STRUCTS.iter().find(|(n, _)| *n == name).map(|(_, m)| *m)
}

/// The type of member `field` of the built-in struct `name`.
pub fn struct_member(name: &str, field: &str) -> Option<&'static str> {
    struct_members(name)?.iter().find(|(_, f)| *f == field).map(|(ty, _)| *ty)
}

/// The member names of the built-in struct `name` (empty for other types).
pub fn struct_fields(name: &str) -> Vec<&'static str> {
    struct_members(name).unwrap_or_default().iter().map(|(_, f)| *f).collect()
}

/// The GLSL definition of the built-in struct `name`.
pub fn struct_text(name: &str) -> Option<String> {
    let fields: String = struct_members(name)?.iter().map(|(ty, field)| format!(" {ty} {field};")).collect();
    Some(format!("struct {name} {{{fields} }};"))
}

/// The member types of a built-in struct, in order.
pub fn struct_member_types(name: &str) -> Vec<GlslType> {
    struct_members(name).unwrap_or_default().iter().map(|(ty, _)| GlslType::scalar(ty)).collect()
}

/// A matrix read in another form: `gl_TextureMatrixInverseTranspose` is
/// `transpose(inverse(gl_TextureMatrix[i]))`. Returns the matrix and the form's functions,
/// innermost first.
pub fn matrix_form(name: &str) -> Option<(&'static str, &'static [&'static str])> {
    const BASES: [&str; 4] = ["gl_ModelViewProjectionMatrix", "gl_ModelViewMatrix", "gl_ProjectionMatrix", "gl_TextureMatrix"];
    let base = BASES.into_iter().find(|b| name.starts_with(b))?;
    let forms: &'static [&'static str] = match &name[base.len()..] {
        "Inverse" => &["inverse"],
        "Transpose" => &["transpose"],
        "InverseTranspose" => &["inverse", "transpose"],
        _ => return None,
    };
    Some((base, forms))
}

/// The light products GL derives from the material, light and light-model state.
pub const PRODUCTS: &[(&str, &str, Option<u32>)] = &[
    ("gl_FrontLightModelProduct", "gl_LightModelProducts", None),
    ("gl_BackLightModelProduct", "gl_LightModelProducts", None),
    ("gl_FrontLightProduct", "gl_LightProducts", Some(MAX_LIGHTS)),
    ("gl_BackLightProduct", "gl_LightProducts", Some(MAX_LIGHTS)),
];

/// The material a product is derived from.
fn product_material(product: &str) -> &'static str {
    if product.starts_with("gl_Front") {
        "gl_FrontMaterial"
    } else {
        "gl_BackMaterial"
    }
}

/// A fixed-function varying: written by the vertex stage, read by the fragment stage
/// under `fragment_name`; `name` is also the link name its locations are planned by.
#[derive(Debug, Clone, Copy)]
pub struct Varying {
    pub name: &'static str,
    pub fragment_name: &'static str,
    pub ty: &'static str,
}

pub const VARYINGS: &[Varying] = &[
    Varying { name: "gl_FrontColor", fragment_name: "gl_Color", ty: "vec4" },
    Varying { name: "gl_FrontSecondaryColor", fragment_name: "gl_SecondaryColor", ty: "vec4" },
    Varying { name: "gl_FogFragCoord", fragment_name: "gl_FogFragCoord", ty: "float" },
];

/// Vertex outputs GL reads only with state WebGPU lacks (two-sided colour, user clip
/// planes): computed in a private variable, not passed on.
const VERTEX_SINKS: &[(&str, &str)] = &[("gl_BackColor", "vec4"), ("gl_BackSecondaryColor", "vec4"), ("gl_ClipVertex", "vec4")];

/// The vertex-stage link name of one `gl_TexCoord[]` element.
pub fn tex_coord_varying(i: u32) -> String {
    format!("effectc_TexCoord{i}")
}

/// Whether effectc declares the built-in `name` for a `stage` (so naga is not asked for it).
pub fn handles(name: &str, stage: StageKind) -> bool {
    let in_vertex_or_fragment = matches!(stage, StageKind::Vertex | StageKind::Fragment);
    state(name).is_some()
        || matrix_form(name).is_some()
        || PRODUCTS.iter().any(|p| p.0 == name)
        || CONSTANTS.iter().any(|c| c.0 == name)
        || (stage == StageKind::Vertex && (attribute(name).is_some() || VARYINGS.iter().any(|v| v.name == name)))
        || (matches!(stage, StageKind::Vertex | StageKind::Geometry) && VERTEX_SINKS.iter().any(|v| v.0 == name))
        || (stage == StageKind::Fragment && VARYINGS.iter().any(|v| v.fragment_name == name))
        || (in_vertex_or_fragment && name == "gl_TexCoord")
}

/// `ftransform()`, which the vertex stage may call.
pub const FTRANSFORM: &str = "ftransform";

/// What one program uses of the compatibility built-ins.
#[derive(Debug, Clone, Default)]
pub struct ProgramCompat {
    /// State members of the shared block, in [`STATE`] order.
    pub state: Vec<&'static State>,
    /// Built-in structs the block holds, in dependency order.
    pub block_structs: Vec<&'static str>,
    /// Varyings passed from the vertex to the fragment stage.
    pub varyings: Vec<&'static Varying>,
    /// `gl_TexCoord[]` elements passed from the vertex to the fragment stage.
    pub tex_coords: Vec<u32>,
}

/// The built-ins `s` uses that effectc declares: (name, index when a literal, dynamic index).
fn used(s: &StageSyntax) -> impl Iterator<Item = &crate::front::syntax::Use> {
    s.uses.iter().filter(move |u| is_builtin_use(s, u) && handles(&u.name, s.stage))
}

/// A use of a built-in: declared nowhere, or by the stage's redeclaration of it
/// (`varying vec4 gl_TexCoord[3];`, which GLSL asks for before a variable index).
pub fn is_builtin_use(s: &StageSyntax, u: &crate::front::syntax::Use) -> bool {
    match u.target {
        Referent::Unresolved => true,
        Referent::Global(g) => s.globals[g].name.starts_with("gl_"),
        Referent::Param(..) => false,
    }
}

/// Whether stage `s` reads or writes the built-in `name`.
pub fn stage_uses(s: &StageSyntax, name: &str) -> bool {
    used(s).any(|u| u.name == name)
}

/// Whether stage `s` calls `ftransform()`.
pub fn calls_ftransform(s: &StageSyntax) -> bool {
    s.stage == StageKind::Vertex && s.calls.iter().any(|c| c.name == FTRANSFORM) && !s.functions.iter().any(|f| f.name == FTRANSFORM)
}

/// The state, structs and varyings of the compatibility profile `stages` use.
pub fn analyse(stages: &[StageSyntax]) -> ProgramCompat {
    let mut state: BTreeSet<&str> = BTreeSet::new();
    let mut varyings: BTreeSet<&str> = BTreeSet::new();
    let mut tex_coords: BTreeSet<u32> = BTreeSet::new();
    for s in stages {
        for u in used(s) {
            let name = u.name.as_str();
            if let Some(st) = self::state(name) {
                state.insert(st.name);
            } else if let Some((base, _)) = matrix_form(name) {
                state.insert(base);
            } else if let Some(p) = PRODUCTS.iter().find(|p| p.0 == name) {
                state.extend(["gl_LightSource", "gl_LightModel", product_material(p.0)]);
            } else if name == "gl_TexCoord" {
                match &u.index {
                    Some((_, _, Some(k))) if (0..i64::from(MAX_TEXTURE_COORDS)).contains(k) => {
                        tex_coords.insert(*k as u32);
                    }
                    // A variable index reads any element the redeclaration sizes.
                    _ => {
                        let size = s.global("gl_TexCoord").and_then(|g| g.ty.dims.first().copied().flatten());
                        tex_coords.extend(0..size.unwrap_or(MAX_TEXTURE_COORDS).min(MAX_TEXTURE_COORDS));
                    }
                }
            } else if let Some(v) = VARYINGS
                .iter()
                .find(|v| (s.stage == StageKind::Vertex && v.name == name) || (s.stage == StageKind::Fragment && v.fragment_name == name))
            {
                varyings.insert(v.name);
            }
        }
        if calls_ftransform(s) {
            state.insert("gl_ModelViewProjectionMatrix");
        }
    }
    let state: Vec<&'static State> = STATE.iter().filter(|st| state.contains(st.name)).collect();
    let mut block_structs = Vec::new();
    for st in &state {
        if struct_members(st.ty).is_some() && !block_structs.contains(&st.ty) {
            block_structs.push(st.ty);
        }
    }
    ProgramCompat {
        state,
        block_structs,
        varyings: VARYINGS.iter().filter(|v| varyings.contains(v.name)).collect(),
        tex_coords: tex_coords.into_iter().collect(),
    }
}

/// What the header of stage `s` declares for the compatibility built-ins it uses, apart
/// from the block members: attribute inputs (locations from `next_input`), varyings at
/// the plan's locations, private stand-ins, constants and light products. Statements for
/// the start and the end of `main` go to `prologue` and `epilogue`.
pub struct StageDeclarations {
    pub header: String,
    pub prologue: String,
    pub epilogue: String,
}

/// The declarations of stage `s` (see [`StageDeclarations`]).
pub fn declarations(
    s: &StageSyntax,
    program: &ProgramCompat,
    varying_location: impl Fn(&str) -> u32,
    mut next_input: impl FnMut(u32) -> u32,
) -> StageDeclarations {
    use std::fmt::Write;
    let mut d = StageDeclarations { header: String::new(), prologue: String::new(), epilogue: String::new() };
    let h = &mut d.header;
    for (name, value) in CONSTANTS {
        if stage_uses(s, name) {
            let _ = writeln!(h, "const int {name} = {value};");
        }
    }
    match s.stage {
        StageKind::Vertex => {
            for a in ATTRIBUTES {
                if stage_uses(s, a.name) || (a.name == "gl_Vertex" && calls_ftransform(s)) {
                    let _ = writeln!(h, "layout(location = {}) in {} {};", next_input(1), a.ty, a.name);
                }
            }
            for v in &program.varyings {
                let _ = writeln!(h, "layout(location = {}) out {} {};", varying_location(v.name), v.ty, v.name);
                if v.ty == "vec4" {
                    // GL clamps vertex colours to [0, 1] (CLAMP_VERTEX_COLOR starts TRUE).
                    let _ = write!(d.epilogue, " {0} = clamp({0}, 0.0, 1.0);", v.name);
                }
            }
            sinks(s, h);
        }
        StageKind::Geometry => sinks(s, h),
        StageKind::Fragment => {
            for v in program.varyings.iter().filter(|v| stage_uses(s, v.fragment_name)) {
                let _ = writeln!(h, "layout(location = {}) in {} {};", varying_location(v.name), v.ty, v.fragment_name);
            }
        }
        _ => {}
    }
    if matches!(s.stage, StageKind::Vertex | StageKind::Fragment) && stage_uses(s, "gl_TexCoord") {
        let _ = writeln!(h, "vec4 gl_TexCoord[{MAX_TEXTURE_COORDS}];");
        for &i in &program.tex_coords {
            let link = tex_coord_varying(i);
            let location = varying_location(&link);
            if s.stage == StageKind::Vertex {
                let _ = writeln!(h, "layout(location = {location}) out vec4 {link};");
                let _ = write!(d.epilogue, " {link} = gl_TexCoord[{i}];");
            } else {
                let _ = writeln!(h, "layout(location = {location}) in vec4 {link};");
                let _ = write!(d.prologue, " gl_TexCoord[{i}] = {link};");
            }
        }
    } else if s.stage == StageKind::Vertex && !program.tex_coords.is_empty() {
        // The fragment stage reads texture coordinates this stage leaves undefined.
        for &i in &program.tex_coords {
            let link = tex_coord_varying(i);
            let _ = writeln!(h, "layout(location = {}) out vec4 {link};", varying_location(&link));
        }
    }
    products(s, &mut d);
    d
}

/// The private stand-ins of the [`VERTEX_SINKS`] `s` writes (a geometry stage writes them
/// too, for the vertices it emits).
fn sinks(s: &StageSyntax, h: &mut String) {
    use std::fmt::Write;
    for (name, ty) in VERTEX_SINKS {
        if stage_uses(s, name) {
            let _ = writeln!(h, "{ty} {name};");
        }
    }
}

/// The light products `s` reads, computed first in `main` as GL derives them: a light
/// product is the material's colour times the light's, a scene colour the material's
/// emission plus its ambient colour times the light model's (alpha: the diffuse alpha).
fn products(s: &StageSyntax, d: &mut StageDeclarations) {
    use std::fmt::Write;
    let mut structs = BTreeSet::new();
    for (name, ty, count) in PRODUCTS.iter().filter(|p| stage_uses(s, p.0)) {
        structs.insert(*ty);
        let m = product_material(name);
        match count {
            Some(n) => {
                let _ = writeln!(d.header, "{ty} {name}[{n}];");
                let _ = write!(
                    d.prologue,
                    " for (int i = 0; i < {n}; i++) {{ {name}[i] = {ty}({m}.ambient * gl_LightSource[i].ambient, \
                     {m}.diffuse * gl_LightSource[i].diffuse, {m}.specular * gl_LightSource[i].specular); }}"
                );
            }
            None => {
                let _ = writeln!(d.header, "{ty} {name};");
                let _ = write!(
                    d.prologue,
                    " {name} = {ty}(vec4({m}.emission.rgb + {m}.ambient.rgb * gl_LightModel.ambient.rgb, {m}.diffuse.a));"
                );
            }
        }
    }
    let defs: String = structs.iter().filter_map(|t| struct_text(t)).map(|t| t + "\n").collect();
    d.header.insert_str(0, &defs);
}

/// The vertex stage GL runs for a compatibility-profile program that has none: its
/// fixed-function vertex processing with GL's initial state (identity model-view,
/// projection and texture matrices; lighting, texture-coordinate generation and two-sided
/// colour off), which draws a full-window `glRectf(-1, -1, 1, 1)` as given. Written as
/// GLSL in the fragment stage's own version, for the fragment stage's text; `None` when
/// that version has no fixed-function vertex stage (core and ES profiles).
pub fn fixed_function_vertex_stage(fragment_text: &str) -> Option<String> {
    use std::fmt::Write;
    let mut text = compatibility_version_line(fragment_text)?;
    text.push_str("// GL's fixed-function vertex processing in its initial state\nvoid main() {\n");
    text.push_str("    gl_Position = gl_Vertex;\n    gl_FrontColor = gl_Color;\n    gl_FrontSecondaryColor = gl_SecondaryColor;\n");
    // Fog from the fragment's depth (GL's initial fog coordinate source): |eye z|.
    text.push_str("    gl_FogFragCoord = abs(gl_Vertex.z);\n");
    for i in tex_coords_read(fragment_text) {
        let _ = writeln!(text, "    gl_TexCoord[{i}] = gl_MultiTexCoord{i};");
    }
    text.push_str("}\n");
    Some(text)
}

/// The fragment stage GL runs for a compatibility-profile program that has none: its
/// fixed-function fragment processing in GL's initial state (texturing, fog and colour sum
/// off), which writes the interpolated primary colour. Written as GLSL in the vertex
/// stage's own version, for the vertex stage's text; `None` when that version has no
/// fixed-function fragment stage (core and ES profiles).
pub fn fixed_function_fragment_stage(vertex_text: &str) -> Option<String> {
    let mut text = compatibility_version_line(vertex_text)?;
    text.push_str("// GL's fixed-function fragment processing in its initial state\nvoid main() {\n    gl_FragColor = gl_Color;\n}\n");
    Some(text)
}

/// The start of a stage GL adds to `text`'s: its `#version` line (none for 1.10 without
/// one); `None` when that version has no fixed-function stages (core and ES profiles).
fn compatibility_version_line(text: &str) -> Option<String> {
    let version = crate::front::version::parse_version(text).ok()?;
    if !crate::front::builtins::has_compatibility_builtins(&version) {
        return None;
    }
    Some(version.directive.as_ref().map_or_else(String::new, |line| format!("{}\n", &text[line.clone()])))
}

/// The `gl_TexCoord[]` elements a stage's text indexes: the literal indices, or all of
/// them where an index is not a literal.
fn tex_coords_read(text: &str) -> BTreeSet<u32> {
    let mut read = BTreeSet::new();
    for (at, _) in text.match_indices("gl_TexCoord") {
        let rest = text[at + "gl_TexCoord".len()..].trim_start();
        let Some(inner) = rest.strip_prefix('[') else { continue };
        let index = inner.split(']').next().unwrap_or("").trim();
        match index.parse::<u32>() {
            Ok(i) if i < MAX_TEXTURE_COORDS => {
                read.insert(i);
            }
            _ => read.extend(0..MAX_TEXTURE_COORDS),
        }
    }
    read
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matrix_forms_name_their_matrix_and_functions() {
        assert_eq!(matrix_form("gl_ModelViewMatrixInverse"), Some(("gl_ModelViewMatrix", &["inverse"][..])));
        assert_eq!(
            matrix_form("gl_ModelViewProjectionMatrixInverseTranspose"),
            Some(("gl_ModelViewProjectionMatrix", &["inverse", "transpose"][..]))
        );
        assert_eq!(matrix_form("gl_TextureMatrixTranspose"), Some(("gl_TextureMatrix", &["transpose"][..])));
        assert_eq!(matrix_form("gl_ModelViewMatrix"), None);
    }

    #[test]
    fn struct_member_types_follow_the_definition() {
        let t: Vec<String> = struct_member_types("gl_MaterialParameters").into_iter().map(|t| t.base).collect();
        assert_eq!(t, ["vec4", "vec4", "vec4", "vec4", "float"]);
        assert_eq!(struct_member_types("gl_LightSourceParameters").len(), 12);
    }

    #[test]
    fn which_stage_declares_what() {
        assert!(handles("gl_Vertex", StageKind::Vertex));
        assert!(!handles("gl_Vertex", StageKind::Fragment));
        assert!(handles("gl_Color", StageKind::Fragment));
        assert!(handles("gl_LightSource", StageKind::Geometry));
        assert!(!handles("gl_FrontColor", StageKind::Geometry));
    }

    #[test]
    fn a_compatibility_fragment_stage_gets_gl_fixed_function_vertex_stage() {
        let v = fixed_function_vertex_stage("#version 120\nvoid main() { gl_FragColor = gl_Color + gl_TexCoord[2]; }\n").unwrap();
        assert!(v.starts_with("#version 120\n"), "{v}");
        assert!(v.contains("gl_Position = gl_Vertex;") && v.contains("gl_TexCoord[2] = gl_MultiTexCoord2;"), "{v}");
        assert!(!v.contains("gl_TexCoord[0]"), "{v}");
        let all = fixed_function_vertex_stage("void main() { int i = 1; gl_FragColor = gl_TexCoord[i]; }").unwrap();
        assert_eq!(all.matches("gl_MultiTexCoord").count(), 8, "{all}");
        assert_eq!(fixed_function_vertex_stage("#version 330 core\nout vec4 c; void main() { c = vec4(1.0); }"), None);
        assert_eq!(fixed_function_vertex_stage("#version 300 es\nout highp vec4 c; void main() { c = vec4(1.0); }"), None);
    }

    #[test]
    fn a_compatibility_vertex_stage_gets_gl_fixed_function_fragment_stage() {
        let f = fixed_function_fragment_stage("#version 120\nvoid main() { gl_Position = ftransform(); }\n").unwrap();
        assert!(f.starts_with("#version 120\n") && f.contains("gl_FragColor = gl_Color;"), "{f}");
        assert!(fixed_function_fragment_stage("void main() { gl_Position = gl_Vertex; }").is_some());
        assert_eq!(fixed_function_fragment_stage("#version 330 core\nin vec4 p; void main() { gl_Position = p; }"), None);
    }
}
