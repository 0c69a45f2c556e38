//! CPU-side texture data: the procedural generators (checker, gradient, noise, solid) for 2D and cube
//! textures, image-file loading, and the placeholders bound to samplers that have no manifest entry.
//!
//! Everything produced here is RGBA8 meant for an `Rgba8Unorm` texture: colours are taken as linear
//! values and stored as `round(clamp(c, 0, 1) * 255)`, with no sRGB conversion on the way in or out,
//! and image files keep their stored byte values.
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

pub use cube_map::cube_direction;
pub use generators::{generate, placeholder, to_rgba8};
pub use image_file::{decode_rgba8, load_faces, load_file};
pub use noise::{sphere_noise, tileable_noise_2d};

/// Images larger than this on either side are refused, and generated sizes are clamped to it.
pub const MAX_IMAGE_SIDE: u32 = 16384;

/// Cube layer names in layer order, as used in error messages.
pub const CUBE_FACE_NAMES: [&str; 6] = ["+x", "-x", "+y", "-y", "+z", "-z"];

/// RGBA8 texels, `layers` = 1 (2D) or 6 (cube: +x −x +y −y +z −z), each layer width×height,
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
    pub rgba8: Vec<u8>,
}

impl fmt::Debug for TexelImage {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("TexelImage")
            .field("width", &self.width)
            .field("height", &self.height)
            .field("layers", &self.layers)
            .field("bytes", &self.rgba8.len())
            .finish()
    }
}

impl TexelImage {
    /// Bytes in one layer (`width * height * 4`).
    pub fn layer_len(&self) -> usize {
        self.width as usize * self.height as usize * 4
    }

    /// The bytes of one layer, or `None` when `layer` is out of range.
    pub fn layer(&self, layer: u32) -> Option<&[u8]> {
        let len = self.layer_len();
        let start = (layer as usize).checked_mul(len)?;
        self.rgba8.get(start..start.checked_add(len)?)
    }

    /// One texel by layer, column and stored row (row 0 first), or `None` when out of range.
    pub fn texel(&self, layer: u32, column: u32, row: u32) -> Option<[u8; 4]> {
        if column >= self.width || row >= self.height {
            return None;
        }
        let start = (row as usize * self.width as usize + column as usize) * 4;
        let texel = self.layer(layer)?.get(start..start + 4)?;
        Some([texel[0], texel[1], texel[2], texel[3]])
    }

    /// The next mipmap level: half the size (at least 1), every texel the box-filtered mean
    /// of the 2×2 (or, at an odd edge, 1×2 / 2×1) texels it covers, per layer — what
    /// `glGenerateMipmap` produces.
    pub fn half(&self) -> TexelImage {
        let (w, h) = ((self.width / 2).max(1), (self.height / 2).max(1));
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
        TexelImage { width: w, height: h, layers: self.layers, rgba8 }
    }

    /// Mipmap levels after this one, down to 1×1.
    pub fn mip_chain(&self) -> Vec<TexelImage> {
        let mut levels: Vec<TexelImage> = Vec::new();
        while levels.last().map_or((self.width, self.height), |l| (l.width, l.height)) != (1, 1) {
            let next = levels.last().unwrap_or(self).half();
            levels.push(next);
        }
        levels
    }
}
