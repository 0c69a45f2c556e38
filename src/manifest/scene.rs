//! The scene sections: `[camera]` (look-at camera and keyframes), `[model]` (the model
//! matrix) and `[render]` (frame defaults and fixed pipeline state).

use std::ops::Range;

/// `[camera]`: a look-at camera with a perspective projection, optionally moved by keyframes.
#[derive(Debug, Clone, PartialEq)]
pub struct CameraDecl {
    pub span: Range<usize>,
    pub eye: [f32; 3],
    pub target: [f32; 3],
    pub up: [f32; 3],
    /// Vertical field of view in degrees (0, 180).
    pub fov: f32,
    pub near: f32,
    pub far: f32,
    /// Keyframes in increasing time; empty for a still camera.
    pub keys: Vec<CameraKey>,
    pub ease: Ease,
}

impl Default for CameraDecl {
    fn default() -> Self {
        CameraDecl {
            span: 0..0,
            eye: [1.8, 1.4, 2.6],
            target: [0.0, 0.0, 0.0],
            up: [0.0, 1.0, 0.0],
            fov: 45.0,
            near: 0.1,
            far: 100.0,
            keys: Vec::new(),
            ease: Ease::Linear,
        }
    }
}

/// One camera keyframe: where the camera is and looks at `time` seconds.
#[derive(Debug, Clone, PartialEq)]
pub struct CameraKey {
    pub time: f64,
    pub eye: [f32; 3],
    pub target: [f32; 3],
}

/// How the camera moves between keyframes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Ease {
    /// Constant speed (the seed's `naive_lerp`).
    #[default]
    Linear,
    /// Smoothstep: starts and stops gently at every key.
    Smooth,
}

/// `[model]`: scale, then rotation (degrees about x, y, z, plus `spin` degrees per second),
/// then translation.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelDecl {
    pub translate: [f32; 3],
    pub rotate: [f32; 3],
    pub scale: [f32; 3],
    pub spin: [f32; 3],
}

impl Default for ModelDecl {
    fn default() -> Self {
        ModelDecl { translate: [0.0; 3], rotate: [0.0; 3], scale: [1.0; 3], spin: [0.0; 3] }
    }
}

/// `[render]`: defaults for `effectc render` (flags override them) and fixed pipeline state.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderDecl {
    pub size: Option<(u32, u32)>,
    pub frames: Option<u32>,
    pub fps: Option<f64>,
    /// Linear RGBA clear colour; default opaque black.
    pub clear: [f32; 4],
    pub cull: Cull,
    /// Depth test (less) with a depth buffer; default on.
    pub depth_test: bool,
    /// Depth writes when the depth test is on; default on (off for see-through layers).
    pub depth_write: bool,
    /// The depth test's comparison (`glDepthFunc`); default `less`, as GL's.
    pub depth_compare: DepthCompare,
    pub blend: Blend,
}

/// `[verify]`: how close `effectc verify` wants the translation's frames to the OpenGL
/// driver's (defaults: 2/255 per channel on at most 0.1% of the pixels).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct VerifyDecl {
    /// `tolerance`: the largest channel difference (0–255) a pixel may have and match.
    pub tolerance: Option<u8>,
    /// `max_differing`: the percentage of pixels (0–100) allowed beyond the tolerance.
    pub max_differing: Option<f64>,
}

/// `glDepthFunc`: when a fragment passes the depth test.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum DepthCompare {
    Never,
    #[default]
    Less,
    Equal,
    /// `GL_LEQUAL`: the skybox trick (`gl_Position = pos.xyww` lands on the cleared depth 1.0).
    LessEqual,
    Greater,
    NotEqual,
    GreaterEqual,
    Always,
}

impl DepthCompare {
    /// Manifest names, in GL's order.
    pub const CHOICES: &'static [(&'static str, DepthCompare)] = &[
        ("never", DepthCompare::Never),
        ("less", DepthCompare::Less),
        ("equal", DepthCompare::Equal),
        ("lequal", DepthCompare::LessEqual),
        ("greater", DepthCompare::Greater),
        ("notequal", DepthCompare::NotEqual),
        ("gequal", DepthCompare::GreaterEqual),
        ("always", DepthCompare::Always),
    ];
}

impl Default for RenderDecl {
    fn default() -> Self {
        RenderDecl {
            size: None,
            frames: None,
            fps: None,
            clear: [0.0, 0.0, 0.0, 1.0],
            cull: Cull::None,
            depth_test: true,
            depth_write: true,
            depth_compare: DepthCompare::Less,
            blend: Blend::None,
        }
    }
}

/// How fragment colours combine with the target.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Blend {
    /// Replace.
    #[default]
    None,
    /// `src.rgb * src.a + dst.rgb * (1 - src.a)` (glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA)).
    Alpha,
    /// `src.rgb * src.a + dst.rgb` (glBlendFunc(GL_SRC_ALPHA, GL_ONE)).
    Additive,
    /// `src.rgb + dst.rgb * (1 - src.a)` (premultiplied alpha).
    Premultiplied,
}

/// Which faces are culled (counter-clockwise is front, as in OpenGL).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Cull {
    #[default]
    None,
    Back,
    Front,
}

/// Largest frame side `[render] size` and `--size` accept.
pub const MAX_FRAME_SIDE: u32 = 8192;
/// Most frames `[render] frames` and `--frames` accept.
pub const MAX_FRAMES: u32 = 100_000;
