//! `[textures]` entries: the image bound to a sampler uniform, where its pixels come from
//! (a file, six cube faces, or a procedural [`Generator`]) and how it is sampled.

use std::ops::Range;
use std::path::PathBuf;

/// One entry of `[textures]`: the image bound to a sampler uniform.
#[derive(Debug, Clone, PartialEq)]
pub struct TextureDecl {
    /// The sampler uniform it binds.
    pub name: String,
    pub name_span: Range<usize>,
    pub kind: TextureKind,
    pub source: TextureSource,
    /// Span of the whole entry's value (string or table).
    pub span: Range<usize>,
    pub filter: Filter,
    pub wrap: Wrap,
    /// The texel format it is uploaded in (`format = "…"`; RGBA8 by default).
    pub format: TexelFormat,
}

/// The sampler dimensionality a texture provides.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TextureKind {
    /// `sampler2D`.
    D2,
    /// `samplerCube`.
    Cube,
}

impl TextureKind {
    pub fn name(self) -> &'static str {
        match self {
            TextureKind::D2 => "2d",
            TextureKind::Cube => "cube",
        }
    }
    /// The GLSL sampler type that matches.
    pub fn glsl_sampler(self) -> &'static str {
        match self {
            TextureKind::D2 => "sampler2D",
            TextureKind::Cube => "samplerCube",
        }
    }
}

/// Where a texture's pixels come from. Paths are resolved against the manifest directory.
#[derive(Debug, Clone, PartialEq)]
pub enum TextureSource {
    File(PathBuf),
    /// A cube map from six images, in the order +x −x +y −y +z −z.
    Faces([PathBuf; 6]),
    /// A procedural texture (`size`×`size`; for a cube, each face).
    Generated {
        generator: Generator,
        size: u32,
        params: GeneratorParams,
    },
}

/// Procedural texture generators.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Generator {
    /// `cells`×`cells` squares alternating `colors[0]` / `colors[1]`.
    Checker,
    /// Horizontal ramp from `colors[0]` (u = 0) to `colors[1]` (u = 1).
    Gradient,
    /// Tileable value noise: `cells` lattice cells per side at the first octave, `octaves`
    /// octaves (each doubling the frequency, halving the amplitude), `seed`; mapped from
    /// `colors[0]` (0) to `colors[1]` (1).
    Noise,
    /// Every texel `colors[0]`.
    Solid,
}

impl Generator {
    pub const ALL: [Generator; 4] = [Generator::Checker, Generator::Gradient, Generator::Noise, Generator::Solid];
    pub fn name(self) -> &'static str {
        match self {
            Generator::Checker => "checker",
            Generator::Gradient => "gradient",
            Generator::Noise => "noise",
            Generator::Solid => "solid",
        }
    }
    /// The parameter keys (besides `size`) this generator reads.
    pub fn params(self) -> &'static [&'static str] {
        match self {
            Generator::Checker => &["colors", "cells"],
            Generator::Gradient => &["colors"],
            Generator::Noise => &["colors", "cells", "seed", "octaves"],
            Generator::Solid => &["colors"],
        }
    }
}

/// Parameters of a generated texture; keys a generator does not use keep their defaults.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GeneratorParams {
    /// Linear RGBA colours a and b, as written (f64: an integer format's whole numbers up
    /// to `u32::MAX` are exact). Default: white `[1,1,1,1]` and black `[0,0,0,1]`.
    pub colors: [[f64; 4]; 2],
    /// Checker squares / noise lattice cells per side. Default 8.
    pub cells: u32,
    /// Noise seed. Default 0.
    pub seed: u32,
    /// Noise octaves. Default 4.
    pub octaves: u32,
}

impl Default for GeneratorParams {
    fn default() -> Self {
        GeneratorParams { colors: [[1.0, 1.0, 1.0, 1.0], [0.0, 0.0, 0.0, 1.0]], cells: 8, seed: 0, octaves: 4 }
    }
}

/// Default size of a generated texture.
pub const DEFAULT_TEXTURE_SIZE: u32 = 256;
/// Largest accepted generated texture size.
pub const MAX_TEXTURE_SIZE: u32 = 8192;

/// Texture filtering (minification and magnification).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Filter {
    #[default]
    Linear,
    Nearest,
}

/// Texture addressing mode, for all coordinates.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Wrap {
    #[default]
    Repeat,
    Clamp,
    Mirror,
}

/// The format a manifest texture is uploaded in (`format = "…"`), as GL's internal formats
/// name them. Floating-point ones hold values beyond [0, 1]; integer ones are read by
/// `isampler*`/`usampler*` as the integers given, one mipmap level, nearest filtering.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum TexelFormat {
    /// 8 bits per channel, normalized: bytes read as 0..1.
    #[default]
    Rgba8,
    Rgba16f,
    Rgba32f,
    R32f,
    Rgba32i,
    Rgba32ui,
    R32i,
    R32ui,
}

/// What a sampler reads from a texel format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TexelKind {
    /// Floating-point values (normalized or not): `sampler*`.
    Float,
    /// Signed integers: `isampler*`.
    Sint,
    /// Unsigned integers: `usampler*`.
    Uint,
}

impl TexelFormat {
    pub const ALL: [TexelFormat; 8] = [
        TexelFormat::Rgba8,
        TexelFormat::Rgba16f,
        TexelFormat::Rgba32f,
        TexelFormat::R32f,
        TexelFormat::Rgba32i,
        TexelFormat::Rgba32ui,
        TexelFormat::R32i,
        TexelFormat::R32ui,
    ];

    pub fn name(self) -> &'static str {
        match self {
            TexelFormat::Rgba8 => "rgba8",
            TexelFormat::Rgba16f => "rgba16f",
            TexelFormat::Rgba32f => "rgba32f",
            TexelFormat::R32f => "r32f",
            TexelFormat::Rgba32i => "rgba32i",
            TexelFormat::Rgba32ui => "rgba32ui",
            TexelFormat::R32i => "r32i",
            TexelFormat::R32ui => "r32ui",
        }
    }

    pub fn kind(self) -> TexelKind {
        match self {
            TexelFormat::Rgba32i | TexelFormat::R32i => TexelKind::Sint,
            TexelFormat::Rgba32ui | TexelFormat::R32ui => TexelKind::Uint,
            _ => TexelKind::Float,
        }
    }

    /// Channels stored: 1 for the `r` formats (a sampler reads (r, 0, 0, 1)), else 4.
    pub fn channels(self) -> usize {
        match self {
            TexelFormat::R32f | TexelFormat::R32i | TexelFormat::R32ui => 1,
            _ => 4,
        }
    }

    /// Bytes per channel.
    pub fn channel_bytes(self) -> usize {
        match self {
            TexelFormat::Rgba8 => 1,
            TexelFormat::Rgba16f => 2,
            _ => 4,
        }
    }

    pub fn texel_bytes(self) -> usize {
        self.channels() * self.channel_bytes()
    }

    /// Whether mipmaps are made and filtering applies (not for integer formats).
    pub fn filterable(self) -> bool {
        self.kind() == TexelKind::Float
    }
}
