//! The fixed-function state compatibility-profile programs read (`gl_Vertex`,
//! `gl_ModelViewMatrix`, …), set in the GL driver as the translation's scene holds it:
//! the legacy vertex arrays from the same vertex bytes, and the model-view and projection
//! matrices from the frame's camera and model (GL derives the model-view-projection and
//! normal matrices from them, as the translation's semantics do). The rest of GL's state
//! keeps its initial values, which the translation starts from too
//! ([`compat::initial_values`](crate::front::compat::initial_values)).
//!
//! These entry points are not in `glow` (a core-profile binding): they are loaded once
//! from EGL, whose function pointers do not depend on the context.

use std::ffi::c_void;
use std::sync::OnceLock;

use crate::render::semantics::FrameState;

type PointerFn = unsafe extern "system" fn(i32, u32, i32, *const c_void);
type TypedPointerFn = unsafe extern "system" fn(u32, i32, *const c_void);

type ParameterFn = unsafe extern "system" fn(u32, u32, *const f32);

/// The legacy GL 1.x–2.1 entry points verify calls.
struct Legacy {
    light_fv: ParameterFn,
    material_fv: ParameterFn,
    tex_env_fv: ParameterFn,
    tex_gen_fv: ParameterFn,
    light_model_fv: unsafe extern "system" fn(u32, *const f32),
    fog_fv: unsafe extern "system" fn(u32, *const f32),
    point_parameter_fv: unsafe extern "system" fn(u32, *const f32),
    point_size: unsafe extern "system" fn(f32),
    clip_plane: unsafe extern "system" fn(u32, *const f64),
    push_matrix: unsafe extern "system" fn(),
    pop_matrix: unsafe extern "system" fn(),
    load_identity: unsafe extern "system" fn(),
    active_texture: unsafe extern "system" fn(u32),
    matrix_mode: unsafe extern "system" fn(u32),
    load_matrix_f: unsafe extern "system" fn(*const f32),
    enable_client_state: unsafe extern "system" fn(u32),
    client_active_texture: unsafe extern "system" fn(u32),
    vertex_pointer: PointerFn,
    color_pointer: PointerFn,
    secondary_color_pointer: PointerFn,
    tex_coord_pointer: PointerFn,
    normal_pointer: TypedPointerFn,
    fog_coord_pointer: TypedPointerFn,
}

const MODELVIEW: u32 = 0x1700;
const PROJECTION: u32 = 0x1701;
const VERTEX_ARRAY: u32 = 0x8074;
const NORMAL_ARRAY: u32 = 0x8075;
const COLOR_ARRAY: u32 = 0x8076;
const TEXTURE_COORD_ARRAY: u32 = 0x8078;
const FOG_COORD_ARRAY: u32 = 0x8457;
const SECONDARY_COLOR_ARRAY: u32 = 0x845E;
const TEXTURE0: u32 = 0x84C0;

static LEGACY: OnceLock<Option<Legacy>> = OnceLock::new();

/// Loads the entry points with the context's loader (once per process).
pub fn load(loader: impl Fn(&str) -> *const c_void) {
    LEGACY.get_or_init(|| {
        let f = |name: &str| Some(loader(name)).filter(|p| !p.is_null());
        // SAFETY: each pointer is the driver's entry point of that name, whose C
        // signature is the one transmuted to (OpenGL 2.1 compatibility specification).
        unsafe {
            Some(Legacy {
                light_fv: std::mem::transmute::<*const c_void, ParameterFn>(f("glLightfv")?),
                material_fv: std::mem::transmute::<*const c_void, ParameterFn>(f("glMaterialfv")?),
                tex_env_fv: std::mem::transmute::<*const c_void, ParameterFn>(f("glTexEnvfv")?),
                tex_gen_fv: std::mem::transmute::<*const c_void, ParameterFn>(f("glTexGenfv")?),
                light_model_fv: std::mem::transmute::<*const c_void, unsafe extern "system" fn(u32, *const f32)>(f("glLightModelfv")?),
                fog_fv: std::mem::transmute::<*const c_void, unsafe extern "system" fn(u32, *const f32)>(f("glFogfv")?),
                point_parameter_fv: std::mem::transmute::<*const c_void, unsafe extern "system" fn(u32, *const f32)>(f(
                    "glPointParameterfv",
                )?),
                point_size: std::mem::transmute::<*const c_void, unsafe extern "system" fn(f32)>(f("glPointSize")?),
                clip_plane: std::mem::transmute::<*const c_void, unsafe extern "system" fn(u32, *const f64)>(f("glClipPlane")?),
                push_matrix: std::mem::transmute::<*const c_void, unsafe extern "system" fn()>(f("glPushMatrix")?),
                pop_matrix: std::mem::transmute::<*const c_void, unsafe extern "system" fn()>(f("glPopMatrix")?),
                load_identity: std::mem::transmute::<*const c_void, unsafe extern "system" fn()>(f("glLoadIdentity")?),
                active_texture: std::mem::transmute::<*const c_void, unsafe extern "system" fn(u32)>(f("glActiveTexture")?),
                matrix_mode: std::mem::transmute::<*const c_void, unsafe extern "system" fn(u32)>(f("glMatrixMode")?),
                load_matrix_f: std::mem::transmute::<*const c_void, unsafe extern "system" fn(*const f32)>(f("glLoadMatrixf")?),
                enable_client_state: std::mem::transmute::<*const c_void, unsafe extern "system" fn(u32)>(f("glEnableClientState")?),
                client_active_texture: std::mem::transmute::<*const c_void, unsafe extern "system" fn(u32)>(f("glClientActiveTexture")?),
                vertex_pointer: std::mem::transmute::<*const c_void, PointerFn>(f("glVertexPointer")?),
                color_pointer: std::mem::transmute::<*const c_void, PointerFn>(f("glColorPointer")?),
                secondary_color_pointer: std::mem::transmute::<*const c_void, PointerFn>(f("glSecondaryColorPointer")?),
                tex_coord_pointer: std::mem::transmute::<*const c_void, PointerFn>(f("glTexCoordPointer")?),
                normal_pointer: std::mem::transmute::<*const c_void, TypedPointerFn>(f("glNormalPointer")?),
                fog_coord_pointer: std::mem::transmute::<*const c_void, TypedPointerFn>(f("glFogCoordPointer")?),
            })
        }
    });
}

fn legacy() -> Result<&'static Legacy, String> {
    LEGACY.get().and_then(Option::as_ref).ok_or_else(|| "the OpenGL driver has no compatibility-profile entry points".to_string())
}

/// Feeds the fixed-function attribute `name` from the bound array buffer (`size`
/// components of `ty` at `offset`, `stride` apart), in the bound vertex array. `Ok(false)`
/// when `name` is not one.
///
/// # Safety
/// A GL context must be current, with the vertex array and the array buffer bound.
pub unsafe fn bind_attribute(name: &str, size: i32, ty: u32, stride: i32, offset: i32) -> Result<bool, String> {
    let l = legacy()?;
    let at = offset as usize as *const c_void;
    match name {
        "gl_Vertex" => {
            (l.enable_client_state)(VERTEX_ARRAY);
            (l.vertex_pointer)(size.max(2), ty, stride, at);
        }
        "gl_Normal" => {
            (l.enable_client_state)(NORMAL_ARRAY);
            (l.normal_pointer)(ty, stride, at);
        }
        "gl_Color" => {
            (l.enable_client_state)(COLOR_ARRAY);
            (l.color_pointer)(size.max(3), ty, stride, at);
        }
        "gl_SecondaryColor" => {
            (l.enable_client_state)(SECONDARY_COLOR_ARRAY);
            (l.secondary_color_pointer)(3, ty, stride, at);
        }
        "gl_FogCoord" => {
            (l.enable_client_state)(FOG_COORD_ARRAY);
            (l.fog_coord_pointer)(ty, stride, at);
        }
        _ => {
            let Some(unit) = name.strip_prefix("gl_MultiTexCoord").and_then(|n| n.parse::<u32>().ok()) else { return Ok(false) };
            (l.client_active_texture)(TEXTURE0 + unit);
            (l.enable_client_state)(TEXTURE_COORD_ARRAY);
            (l.tex_coord_pointer)(size, ty, stride, at);
            (l.client_active_texture)(TEXTURE0);
        }
    }
    Ok(true)
}

/// Loads the frame's model-view (view × model) and projection matrices, or GL's initial
/// identity matrices (`None`: a program drawn by GL's fixed-function vertex stage, which
/// effectc's stand-in draws with its initial state).
///
/// # Safety
/// A GL context must be current.
pub unsafe fn load_matrices(state: Option<&FrameState>) -> Result<(), String> {
    let l = legacy()?;
    let identity = glam::Mat4::IDENTITY;
    let model_view = state.map_or(identity, |s| s.view.view * s.model).to_cols_array();
    let projection = state.map_or(identity, |s| s.view.projection).to_cols_array();
    (l.matrix_mode)(PROJECTION);
    (l.load_matrix_f)(projection.as_ptr());
    (l.matrix_mode)(MODELVIEW);
    (l.load_matrix_f)(model_view.as_ptr());
    Ok(())
}

// Parameter names of the OpenGL 2.1 compatibility state.
const LIGHT0: u32 = 0x4000;
const FRONT: u32 = 0x0404;
const BACK: u32 = 0x0405;
const TEXTURE: u32 = 0x1702;
const TEXTURE_ENV: u32 = 0x2300;
const TEXTURE_ENV_COLOR: u32 = 0x2201;
const EYE_PLANE: u32 = 0x2502;
const OBJECT_PLANE: u32 = 0x2501;
const CLIP_PLANE0: u32 = 0x3000;
const LIGHT_MODEL_AMBIENT: u32 = 0x0B53;
const LIGHT_FIELDS: [(&str, u32); 10] = [
    ("ambient", 0x1200),
    ("diffuse", 0x1201),
    ("specular", 0x1202),
    ("position", 0x1203),
    ("spotDirection", 0x1204),
    ("spotExponent", 0x1205),
    ("spotCutoff", 0x1206),
    ("constantAttenuation", 0x1207),
    ("linearAttenuation", 0x1208),
    ("quadraticAttenuation", 0x1209),
];
const MATERIAL_FIELDS: [(&str, u32); 5] =
    [("ambient", 0x1200), ("diffuse", 0x1201), ("specular", 0x1202), ("emission", 0x1600), ("shininess", 0x1601)];
const FOG_FIELDS: [(&str, u32); 4] = [("color", 0x0B66), ("density", 0x0B62), ("start", 0x0B63), ("end", 0x0B64)];
/// Texture-coordinate generation planes: (coordinate, S/T/R/Q suffix).
const PLANES: [(u32, &str); 4] = [(0x2000, "S"), (0x2001, "T"), (0x2002, "R"), (0x2003, "Q")];

/// Sets GL's light, material, light-model, fog, texture-matrix, texture-environment,
/// plane and point state to what the translation's scene holds (`value` reads a GLSL path
/// from its uniform buffers; GL's initial values unless a manifest or `--set` changed
/// them). Positions, directions and planes are given with an identity model-view, so GL
/// keeps them as the eye-space values the translation reads. The derived values
/// (`halfVector`, `spotCosCutoff`, `gl_Fog.scale`, the light products) GL derives itself.
///
/// # Safety
/// A GL context must be current.
pub unsafe fn set_state(value: impl Fn(&str) -> Option<Vec<f32>>) -> Result<(), String> {
    let l = legacy()?;
    (l.matrix_mode)(MODELVIEW);
    (l.push_matrix)();
    (l.load_identity)();
    for i in 0..crate::front::compat::MAX_LIGHTS {
        for (field, pname) in LIGHT_FIELDS {
            if let Some(v) = value(&format!("gl_LightSource[{i}].{field}")) {
                (l.light_fv)(LIGHT0 + i, pname, v.as_ptr());
            }
        }
    }
    for (name, face) in [("gl_FrontMaterial", FRONT), ("gl_BackMaterial", BACK)] {
        for (field, pname) in MATERIAL_FIELDS {
            if let Some(v) = value(&format!("{name}.{field}")) {
                (l.material_fv)(face, pname, v.as_ptr());
            }
        }
    }
    if let Some(v) = value("gl_LightModel.ambient") {
        (l.light_model_fv)(LIGHT_MODEL_AMBIENT, v.as_ptr());
    }
    for (field, pname) in FOG_FIELDS {
        if let Some(v) = value(&format!("gl_Fog.{field}")) {
            (l.fog_fv)(pname, v.as_ptr());
        }
    }
    for i in 0..crate::front::compat::MAX_CLIP_PLANES {
        if let Some(v) = value(&format!("gl_ClipPlane[{i}]")) {
            let plane: Vec<f64> = v.iter().map(|x| f64::from(*x)).collect();
            (l.clip_plane)(CLIP_PLANE0 + i, plane.as_ptr());
        }
    }
    for i in 0..crate::front::compat::MAX_TEXTURE_COORDS {
        (l.active_texture)(TEXTURE0 + i);
        if let Some(v) = value(&format!("gl_TextureMatrix[{i}]")) {
            (l.matrix_mode)(TEXTURE);
            (l.load_matrix_f)(v.as_ptr());
            (l.matrix_mode)(MODELVIEW);
        }
        if let Some(v) = value(&format!("gl_TextureEnvColor[{i}]")) {
            (l.tex_env_fv)(TEXTURE_ENV, TEXTURE_ENV_COLOR, v.as_ptr());
        }
        for (coord, suffix) in PLANES {
            for (kind, pname) in [("Eye", EYE_PLANE), ("Object", OBJECT_PLANE)] {
                if let Some(v) = value(&format!("gl_{kind}Plane{suffix}[{i}]")) {
                    (l.tex_gen_fv)(coord, pname, v.as_ptr());
                }
            }
        }
    }
    (l.active_texture)(TEXTURE0);
    if let Some(v) = value("gl_Point.size") {
        (l.point_size)(v[0]);
    }
    for (field, pname) in [("sizeMin", 0x8126), ("sizeMax", 0x8127), ("fadeThresholdSize", 0x8128)] {
        if let Some(v) = value(&format!("gl_Point.{field}")) {
            (l.point_parameter_fv)(pname, v.as_ptr());
        }
    }
    let attenuation: Option<Vec<f32>> =
        ["Constant", "Linear", "Quadratic"].iter().map(|k| value(&format!("gl_Point.distance{k}Attenuation")).map(|v| v[0])).collect();
    if let Some(a) = attenuation {
        (l.point_parameter_fv)(0x8129, a.as_ptr());
    }
    (l.pop_matrix)();
    Ok(())
}
