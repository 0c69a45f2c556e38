//! CPU-side texture data: the procedural generators (checker, gradient, noise, solid) for 2D and cube
//! textures, image-file loading, and the placeholders bound to samplers that have no manifest entry.
//!
//! Texels are stored in the manifest's [`TexelFormat`] (RGBA8 unless it says otherwise), as
//! the GPU takes them. For RGBA8, colours are taken as linear values and stored as
//! `round(clamp(c, 0, 1) * 255)`, with no sRGB conversion on the way in or out, and image
//! files keep their stored byte values; floating-point formats keep colours as given (image
//! files: 8- and 16-bit channels as 0..1, HDR and EXR files as stored); integer formats keep
//! the integers given (image files: the stored 8- or 16-bit channel values).
//!
//! - `image_file`: image files, 2D and cube faces, decoded with the `image` crate.
//! - `generators`: the generators and placeholders, and the colour-to-byte conversion.
//! - `noise`: the value noise the noise generator samples.
//! - `cube_map`: texel directions on cube-map faces.

mod cube_map;
mod generators;
mod image_file;
mod noise;
#[cfg(test)]
mod tests;

use std::fmt;

use crate::manifest::{TexelFormat, TexelKind};

pub use cube_map::cube_direction;
pub use generators::{generate, placeholder, to_rgba8};
pub use image_file::{decode_rgba8, load_faces, load_file, load_file_as};
pub use noise::{sphere_noise, tileable_noise_2d};

/// Images larger than this on either side are refused, and generated sizes are clamped to it.
pub const MAX_IMAGE_SIDE: u32 = 16384;

/// Cube layer names in layer order, as used in error messages.
pub const CUBE_FACE_NAMES: [&str; 6] = ["+x", "-x", "+y", "-y", "+z", "-z"];

/// Texels in `format`, `layers` = 1 (2D) or 6 (cube: +x −x +y −y +z −z), each layer width×height,
/// rows stored bottom-up (GL convention: row 0 is v = 0, the image's bottom), as wgpu will
/// upload them row 0 first.
///
/// For cube layers, row 0 is t = 0 and column 0 is s = 0 of the cube-map face table (GL 4.6
/// table 8.19, identical in Vulkan and wgpu). On the four side faces t = 0 is the *upper* edge, so
/// cube face files are conventionally stored as-is (top row first) and [`load_faces`] does not flip them.
#[derive(Clone, PartialEq, Eq)]
pub struct TexelImage {
    pub width: u32,
    pub height: u32,
    pub layers: u32,
    pub format: TexelFormat,
    /// The texels as the GPU takes them ([`TexelFormat::texel_bytes`] each, little-endian).
    pub bytes: Vec<u8>,
}

impl fmt::Debug for TexelImage {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("TexelImage")
            .field("width", &self.width)
            .field("height", &self.height)
            .field("layers", &self.layers)
            .field("format", &self.format)
            .field("bytes", &self.bytes.len())
            .finish()
    }
}

impl TexelImage {
    /// RGBA8 texels.
    pub fn rgba8(width: u32, height: u32, layers: u32, bytes: Vec<u8>) -> TexelImage {
        TexelImage { width, height, layers, format: TexelFormat::Rgba8, bytes }
    }

    /// Texels in `format` from their values (layer by layer, row by row): RGBA8 as
    /// `round(clamp(c, 0, 1) * 255)`, 16-bit floats rounded to nearest, integers as given
    /// (saturated to the format's range); an `r` format keeps the first channel.
    pub fn from_values(width: u32, height: u32, layers: u32, format: TexelFormat, values: impl Iterator<Item = [f64; 4]>) -> TexelImage {
        let mut bytes = Vec::with_capacity(width as usize * height as usize * layers as usize * format.texel_bytes());
        for v in values {
            for c in &v[..format.channels()] {
                match (format, format.kind()) {
                    (TexelFormat::Rgba8, _) => bytes.push(generators::unit_to_byte(*c as f32)),
                    (TexelFormat::Rgba16f, _) => bytes.extend(half::f16::from_f64(*c).to_le_bytes()),
                    (_, TexelKind::Float) => bytes.extend((*c as f32).to_le_bytes()),
                    (_, TexelKind::Sint) => bytes.extend((c.round().clamp(f64::from(i32::MIN), f64::from(i32::MAX)) as i32).to_le_bytes()),
                    (_, TexelKind::Uint) => bytes.extend((c.round().clamp(0.0, f64::from(u32::MAX)) as u32).to_le_bytes()),
                }
            }
        }
        TexelImage { width, height, layers, format, bytes }
    }

    /// Bytes in one layer.
    pub fn layer_len(&self) -> usize {
        self.width as usize * self.height as usize * self.format.texel_bytes()
    }

    /// The bytes of one layer, or `None` when `layer` is out of range.
    pub fn layer(&self, layer: u32) -> Option<&[u8]> {
        let len = self.layer_len();
        let start = (layer as usize).checked_mul(len)?;
        self.bytes.get(start..start.checked_add(len)?)
    }

    /// The stored bytes of one texel by layer, column and stored row (row 0 first), or
    /// `None` when out of range.
    fn texel_bytes(&self, layer: u32, column: u32, row: u32) -> Option<&[u8]> {
        if column >= self.width || row >= self.height {
            return None;
        }
        let size = self.format.texel_bytes();
        let start = (row as usize * self.width as usize + column as usize) * size;
        self.layer(layer)?.get(start..start + size)
    }

    /// One RGBA8 texel's bytes, or `None` when out of range or not RGBA8.
    pub fn texel(&self, layer: u32, column: u32, row: u32) -> Option<[u8; 4]> {
        let t = self.texel_bytes(layer, column, row).filter(|_| self.format == TexelFormat::Rgba8)?;
        Some([t[0], t[1], t[2], t[3]])
    }

    /// What a sampler reads from one texel: RGBA8 as 0..1, the others as stored; an `r`
    /// format as (r, 0, 0, 1).
    pub fn value(&self, layer: u32, column: u32, row: u32) -> Option<[f64; 4]> {
        let t = self.texel_bytes(layer, column, row)?;
        let n = self.format.channel_bytes();
        let channel = |i: usize| -> f64 {
            let b = &t[i * n..(i + 1) * n];
            let word = || [b[0], b[1], b[2], b[3]];
            match (self.format, self.format.kind()) {
                (TexelFormat::Rgba8, _) => f64::from(b[0]) / 255.0,
                (TexelFormat::Rgba16f, _) => f64::from(half::f16::from_le_bytes([b[0], b[1]])),
                (_, TexelKind::Float) => f64::from(f32::from_le_bytes(word())),
                (_, TexelKind::Sint) => f64::from(i32::from_le_bytes(word())),
                (_, TexelKind::Uint) => f64::from(u32::from_le_bytes(word())),
            }
        };
        Some(match self.format.channels() {
            1 => [channel(0), 0.0, 0.0, 1.0],
            _ => std::array::from_fn(channel),
        })
    }

    /// The lowest and highest value of each channel a sampler reads, over every texel.
    pub fn channel_ranges(&self) -> [(f64, f64); 4] {
        let mut out = [(f64::INFINITY, f64::NEG_INFINITY); 4];
        for layer in 0..self.layers {
            for row in 0..self.height {
                for column in 0..self.width {
                    for (o, v) in out.iter_mut().zip(self.value(layer, column, row).unwrap_or_default()) {
                        *o = (o.0.min(v), o.1.max(v));
                    }
                }
            }
        }
        out
    }

    /// The next mipmap level: half the size (at least 1), every texel the box-filtered mean
    /// of the 2×2 (or, at an odd edge, 1×2 / 2×1) texels it covers, per layer — what
    /// `glGenerateMipmap` produces (in floating point for the float formats).
    pub fn half(&self) -> TexelImage {
        let (w, h) = ((self.width / 2).max(1), (self.height / 2).max(1));
        if self.format != TexelFormat::Rgba8 {
            let mut values = Vec::with_capacity(w as usize * h as usize * self.layers as usize);
            for layer in 0..self.layers {
                for row in 0..h {
                    for column in 0..w {
                        let corners = [(0, 0), (1, 0), (0, 1), (1, 1)]
                            .map(|(dc, dr)| self.value(layer, (column * 2 + dc).min(self.width - 1), (row * 2 + dr).min(self.height - 1)));
                        let n = corners.iter().flatten().count().max(1) as f64;
                        values.push(std::array::from_fn(|i| corners.iter().flatten().map(|c| c[i]).sum::<f64>() / n));
                    }
                }
            }
            return TexelImage::from_values(w, h, self.layers, self.format, values.into_iter());
        }
        let mut rgba8 = Vec::with_capacity(w as usize * h as usize * 4 * self.layers as usize);
        for layer in 0..self.layers {
            for row in 0..h {
                for column in 0..w {
                    let mut sum = [0u32; 4];
                    let mut n = 0;
                    for (dc, dr) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                        let (c, r) = ((column * 2 + dc).min(self.width - 1), (row * 2 + dr).min(self.height - 1));
                        if let Some(t) = self.texel(layer, c, r) {
                            for (s, v) in sum.iter_mut().zip(t) {
                                *s += u32::from(v);
                            }
                            n += 1;
                        }
                    }
                    rgba8.extend(sum.map(|s| ((s + n / 2) / n.max(1)) as u8));
                }
            }
        }
        TexelImage::rgba8(w, h, self.layers, rgba8)
    }

    /// Mipmap levels after this one, down to 1×1 (none for an integer format, which GL
    /// cannot filter).
    pub fn mip_chain(&self) -> Vec<TexelImage> {
        let mut levels: Vec<TexelImage> = Vec::new();
        if !self.format.filterable() {
            return levels;
        }
        while levels.last().map_or((self.width, self.height), |l| (l.width, l.height)) != (1, 1) {
            let next = levels.last().unwrap_or(self).half();
            levels.push(next);
        }
        levels
    }
}
