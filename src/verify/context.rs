//! A headless OpenGL context on the system's driver: EGL's surfaceless platform (Mesa's
//! llvmpipe on a machine without a GPU, a GPU's own driver where there is one; EGL's
//! default display where a vendor's EGL has no surfaceless platform), a 4.5
//! compatibility-profile context (GLSL 1.10–4.50 compile in it), made current on the
//! calling thread, with `glow` for the calls.
//!
//! libEGL is loaded at run time: a machine without it gets a clear error (exit 2) from
//! `effectc verify` while every other command works.

use khronos_egl as egl;

/// `EGL_PLATFORM_SURFACELESS_MESA`: a display with no window system.
const PLATFORM_SURFACELESS: egl::Enum = 0x31DD;
/// `EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT`.
const COMPATIBILITY_PROFILE: egl::Int = 0x2;

/// The context and the loaded driver; GL calls go through [`GlContext::gl`]. It is current
/// on the thread that made it, and must be used there only.
pub struct GlContext {
    pub gl: glow::Context,
    egl: egl::DynamicInstance<egl::EGL1_5>,
    display: egl::Display,
    context: egl::Context,
    /// `GL_RENDERER` and `GL_VERSION`, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Compatibility Profile) Mesa 22.3.6".
    pub describe: String,
}

/// Why there is no GL context (a usage/environment error: exit 2).
#[derive(Debug, Clone)]
pub struct NoGl(pub String);

impl GlContext {
    /// Opens the driver. Set `MESA_GL_VERSION_OVERRIDE`/`MESA_GLSL_VERSION_OVERRIDE` before
    /// the first call to reach GLSL 4.60 on Mesa (done by `effectc verify` at start-up).
    pub fn new() -> Result<GlContext, NoGl> {
        // SAFETY: loading libEGL runs its initialisers; it is the system's EGL loader.
        let egl = unsafe { egl::DynamicInstance::<egl::EGL1_5>::load_required() }
            .map_err(|e| NoGl(format!("cannot load the system's EGL 1.5 library (libEGL.so.1): {e}")))?;
        // SAFETY: the surfaceless platform takes no native display; the default display
        // (a vendor's EGL without Mesa's surfaceless platform) takes the default handle.
        let display = unsafe { egl.get_platform_display(PLATFORM_SURFACELESS, egl::DEFAULT_DISPLAY, &[egl::ATTRIB_NONE]) }
            .ok()
            .or_else(|| unsafe { egl.get_display(egl::DEFAULT_DISPLAY) })
            .ok_or_else(|| NoGl("EGL has neither a surfaceless nor a default display".into()))?;
        egl.initialize(display).map_err(|e| NoGl(format!("cannot initialise the EGL display: {e}")))?;
        let made = Self::context(&egl, display);
        let context = match made {
            Ok(c) => c,
            Err(e) => {
                let _ = egl.terminate(display);
                return Err(e);
            }
        };
        // SAFETY: the context is current on this thread; the loader returns its functions.
        let load = |name: &str| egl.get_proc_address(name).map_or(std::ptr::null(), |f| f as *const std::ffi::c_void);
        let gl = unsafe { glow::Context::from_loader_function(load) };
        super::fixed_function::load(load);
        let describe = {
            use glow::HasContext;
            // SAFETY: plain queries on the current context.
            unsafe { format!("{}, {}", gl.get_parameter_string(glow::RENDERER), gl.get_parameter_string(glow::VERSION)) }
        };
        Ok(GlContext { gl, egl, display, context, describe })
    }

    fn context(egl: &egl::DynamicInstance<egl::EGL1_5>, display: egl::Display) -> Result<egl::Context, NoGl> {
        egl.bind_api(egl::OPENGL_API).map_err(|e| NoGl(format!("EGL cannot bind desktop OpenGL: {e}")))?;
        // A surfaceless display has no window configurations (the default surface type).
        let attributes = [egl::SURFACE_TYPE, egl::PBUFFER_BIT, egl::RENDERABLE_TYPE, egl::OPENGL_BIT, egl::NONE];
        let config = egl
            .choose_first_config(display, &attributes)
            .map_err(|e| NoGl(format!("EGL has no OpenGL configuration: {e}")))?
            .ok_or_else(|| NoGl("EGL has no configuration that renders desktop OpenGL".into()))?;
        let context_attributes = [
            egl::CONTEXT_MAJOR_VERSION,
            4,
            egl::CONTEXT_MINOR_VERSION,
            5,
            egl::CONTEXT_OPENGL_PROFILE_MASK,
            COMPATIBILITY_PROFILE,
            egl::NONE,
        ];
        let context = egl
            .create_context(display, config, None, &context_attributes)
            .map_err(|e| NoGl(format!("the driver cannot make an OpenGL 4.5 compatibility context: {e}")))?;
        egl.make_current(display, None, None, Some(context))
            .map_err(|e| NoGl(format!("cannot make the OpenGL context current (surfaceless): {e}")))?;
        Ok(context)
    }
}

impl Drop for GlContext {
    fn drop(&mut self) {
        let _ = self.egl.make_current(self.display, None, None, None);
        let _ = self.egl.destroy_context(self.display, self.context);
        let _ = self.egl.terminate(self.display);
    }
}
