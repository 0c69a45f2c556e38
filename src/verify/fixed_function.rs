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

/// The legacy GL 1.x–2.1 entry points verify calls.
struct Legacy {
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
