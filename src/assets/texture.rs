//! CPU-side texture data: the procedural generators (checker, gradient, noise, solid) for 2D and cube
//! textures, image-file loading, and the placeholders bound to samplers that have no manifest entry.
//!
//! Everything produced here is RGBA8 meant for an `Rgba8Unorm` texture: colours are taken as linear
//! values and stored as `round(clamp(c, 0, 1) * 255)`, with no sRGB conversion on the way in or out,
//! and image files keep their stored byte values.

use std::fmt;
use std::io::Cursor;
use std::path::{Path, PathBuf};

use image::{ImageFormat, ImageReader, Limits};

use crate::manifest::{Generator, GeneratorParams, TextureKind};

/// Images larger than this on either side are refused, and generated sizes are clamped to it.
pub const MAX_IMAGE_SIDE: u32 = 16384;

/// Cube layer names in layer order, as used in error messages.
pub const CUBE_FACE_NAMES: [&str; 6] = ["+x", "-x", "+y", "-y", "+z", "-z"];

/// Octaves beyond this add nothing visible and would overflow the lattice period.
const MAX_OCTAVES: u32 = 16;

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

// ---------------------------------------------------------------------------------------------
// Generators
// ---------------------------------------------------------------------------------------------

/// Generates a square texture of `size` texels per side (0 is treated as 1, more than
/// [`MAX_IMAGE_SIDE`] as that). See the module doc for the colour encoding.
///
/// 2D (`u` = (column + ½) / size, `v` = (row + ½) / size, row 0 at the bottom):
/// - checker: `cells`×`cells` squares; the square at uv (0, 0) (bottom-left) is colour a, then alternating;
/// - gradient: colour a in the first column to colour b in the last, exactly;
/// - noise: tileable value noise (see [`tileable_noise_2d`]) mapped colour a (0) to colour b (1); being a
///   weighted average of octaves it spans 0..1 but mostly stays well inside it;
/// - solid: colour a.
///
/// Cube (each texel evaluated at its direction per the cube-map face table, so faces meet seamlessly):
/// - checker: `cells`×`cells` squares on each face, laid out in face-local (s, t) like the 2D checker;
/// - gradient: by the normalised direction's y, colour a at y = −1 to colour b at y = +1 (a sky);
/// - noise: 3D value noise on the normalised direction, about `cells` lattice cells across a face;
/// - solid: colour a.
pub fn generate(generator: Generator, size: u32, params: &GeneratorParams, kind: TextureKind) -> TexelImage {
    let size = size.clamp(1, MAX_IMAGE_SIDE);
    match kind {
        TextureKind::D2 => build(size, 1, |_, column, row| texel_2d(generator, size, params, column, row)),
        TextureKind::Cube => build(size, 6, |face, column, row| texel_cube(generator, size, params, face, column, row)),
    }
}

/// What a sampler with no manifest entry gets.
///
/// - 2D: 64×64 texels of 8×8 squares alternating magenta (1, 0, 1) and black, magenta at the
///   bottom-left — the usual "missing texture" look, obvious on screen.
/// - Cube: 32×32 faces of a sky gradient by direction y, a dark ground grey-brown (0.12, 0.10, 0.08)
///   straight down to a sky blue (0.25, 0.55, 0.95) straight up.
pub fn placeholder(kind: TextureKind) -> TexelImage {
    match kind {
        TextureKind::D2 => {
            let params = GeneratorParams { colors: [[1.0, 0.0, 1.0, 1.0], [0.0, 0.0, 0.0, 1.0]], cells: 8, ..Default::default() };
            generate(Generator::Checker, 64, &params, TextureKind::D2)
        }
        TextureKind::Cube => {
            let params = GeneratorParams { colors: [[0.12, 0.10, 0.08, 1.0], [0.25, 0.55, 0.95, 1.0]], ..Default::default() };
            generate(Generator::Gradient, 32, &params, TextureKind::Cube)
        }
    }
}

/// Fills `layers` square layers of `size` texels, calling `texel(layer, column, row)` for each.
fn build(size: u32, layers: u32, texel: impl Fn(u32, u32, u32) -> [u8; 4]) -> TexelImage {
    let mut rgba8 = Vec::with_capacity(size as usize * size as usize * layers as usize * 4);
    for layer in 0..layers {
        for row in 0..size {
            for column in 0..size {
                rgba8.extend_from_slice(&texel(layer, column, row));
            }
        }
    }
    TexelImage { width: size, height: size, layers, rgba8 }
}

fn texel_2d(generator: Generator, size: u32, params: &GeneratorParams, column: u32, row: u32) -> [u8; 4] {
    let [a, b] = params.colors;
    let color = match generator {
        Generator::Checker => checker(params, size, column, row),
        Generator::Gradient => mix(a, b, ramp(column, size)),
        Generator::Noise => {
            let (u, v) = (texel_centre(column, size), texel_centre(row, size));
            mix(a, b, tileable_noise_2d(u, v, params.cells, params.octaves, params.seed))
        }
        Generator::Solid => a,
    };
    to_rgba8(color)
}

fn texel_cube(generator: Generator, size: u32, params: &GeneratorParams, face: u32, column: u32, row: u32) -> [u8; 4] {
    let [a, b] = params.colors;
    let sc = texel_centre(column, size) * 2.0 - 1.0;
    let tc = texel_centre(row, size) * 2.0 - 1.0;
    let direction = normalize(cube_direction(face, sc, tc));
    let color = match generator {
        Generator::Checker => checker(params, size, column, row),
        Generator::Gradient => mix(a, b, ((direction[1] + 1.0) * 0.5) as f32),
        Generator::Noise => mix(a, b, sphere_noise(direction, params.cells, params.octaves, params.seed)),
        Generator::Solid => a,
    };
    to_rgba8(color)
}

/// Colour a or b for the checker square holding the texel's centre.
fn checker(params: &GeneratorParams, size: u32, column: u32, row: u32) -> [f32; 4] {
    let cells = params.cells.max(1);
    let even = (checker_cell(column, size, cells) + checker_cell(row, size, cells)) & 1 == 0;
    params.colors[if even { 0 } else { 1 }]
}

/// The square index of texel `index` along a side: floor((index + ½) / size * cells), in integers.
fn checker_cell(index: u32, size: u32, cells: u32) -> u64 {
    (2 * index as u64 + 1) * cells as u64 / (2 * size.max(1) as u64)
}

/// 0 at the first texel, 1 at the last (0 when there is only one).
fn ramp(index: u32, size: u32) -> f32 {
    if size <= 1 {
        0.0
    } else {
        index as f32 / (size - 1) as f32
    }
}

/// The texture coordinate of a texel's centre.
fn texel_centre(index: u32, size: u32) -> f64 {
    (index as f64 + 0.5) / size.max(1) as f64
}

fn mix(a: [f32; 4], b: [f32; 4], t: f32) -> [f32; 4] {
    std::array::from_fn(|i| a[i] + (b[i] - a[i]) * t)
}

/// Linear float colour to bytes: `round(clamp(c, 0, 1) * 255)`, NaN → 0.
pub fn to_rgba8(color: [f32; 4]) -> [u8; 4] {
    color.map(unit_to_byte)
}

fn unit_to_byte(c: f32) -> u8 {
    if c.is_nan() {
        return 0;
    }
    // round() of a non-negative value, as floor(x + 0.5) in f64 (exact, and cheaper than `f32::round`).
    (f64::from(c.clamp(0.0, 1.0) * 255.0) + 0.5) as u8
}

// ---------------------------------------------------------------------------------------------
// Cube-map geometry
// ---------------------------------------------------------------------------------------------

/// The (unnormalised) direction of face-local coordinates `sc`, `tc` in −1..1 on cube layer `face`
/// (0..6 = +x −x +y −y +z −z), the inverse of the cube-map face selection table (GL 4.6 table 8.19,
/// Vulkan "Cube Map Face Selection"), where s = (sc/|ma| + 1)/2 and t = (tc/|ma| + 1)/2:
///
/// | face | sc  | tc  | ma |
/// |------|-----|-----|----|
/// | +x   | −rz | −ry | rx |
/// | −x   | +rz | −ry | rx |
/// | +y   | +rx | +rz | ry |
/// | −y   | +rx | −rz | ry |
/// | +z   | +rx | −ry | rz |
/// | −z   | −rx | −ry | rz |
///
/// Out-of-range faces are treated as −z.
pub fn cube_direction(face: u32, sc: f64, tc: f64) -> [f64; 3] {
    match face {
        0 => [1.0, -tc, -sc],
        1 => [-1.0, -tc, sc],
        2 => [sc, 1.0, tc],
        3 => [sc, -1.0, -tc],
        4 => [sc, -tc, 1.0],
        _ => [-sc, -tc, -1.0],
    }
}

fn normalize(v: [f64; 3]) -> [f64; 3] {
    let length = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if length > 0.0 {
        v.map(|c| c / length)
    } else {
        v
    }
}

// ---------------------------------------------------------------------------------------------
// Value noise: deterministic integer hashing, quintic interpolation, fractal sum
// ---------------------------------------------------------------------------------------------

/// Tileable fractal value noise at texture coordinates (`u`, `v`), in 0..1.
///
/// Octave `o` (0-based, `octaves` of them, 0 treated as 1, at most 16) has a lattice of
/// `cells * 2^o` cells per side (`cells` 0 treated as 1) wrapped at that period, so the result repeats
/// with period 1 in `u` and `v`, and amplitude `2^-o`; the sum is divided by the total amplitude.
/// Lattice values come from an integer hash of (cell, seed, octave), blended with the quintic
/// fade `6t⁵ − 15t⁴ + 10t³`, so the result is identical on every platform.
pub fn tileable_noise_2d(u: f64, v: f64, cells: u32, octaves: u32, seed: u32) -> f32 {
    let mut sum = 0.0;
    let mut total_amplitude = 0.0;
    let mut amplitude = 1.0;
    for octave in 0..octaves.clamp(1, MAX_OCTAVES) {
        let period = (cells.max(1) as u64) << octave;
        let scale = period as f64;
        sum += amplitude * value_noise_2d(u * scale, v * scale, period, noise_salt(seed, octave));
        total_amplitude += amplitude;
        amplitude *= 0.5;
    }
    (sum / total_amplitude) as f32
}

/// Fractal 3D value noise on a unit direction, in 0..1, for cube maps: like [`tileable_noise_2d`] but
/// unwrapped, with the first octave's lattice spacing chosen so about `cells` cells span a face.
pub fn sphere_noise(direction: [f64; 3], cells: u32, octaves: u32, seed: u32) -> f32 {
    // A face spans about √2 of direction space (from −1/√2 to +1/√2 along each face axis).
    let base_frequency = cells.max(1) as f64 / std::f64::consts::SQRT_2;
    let mut sum = 0.0;
    let mut total_amplitude = 0.0;
    let mut amplitude = 1.0;
    for octave in 0..octaves.clamp(1, MAX_OCTAVES) {
        let frequency = base_frequency * (1u64 << octave) as f64;
        let point = direction.map(|c| c * frequency);
        sum += amplitude * value_noise_3d(point, noise_salt(seed, octave));
        total_amplitude += amplitude;
        amplitude *= 0.5;
    }
    (sum / total_amplitude) as f32
}

fn value_noise_2d(x: f64, y: f64, period: u64, salt: u64) -> f64 {
    let (x0, fx) = split(x);
    let (y0, fy) = split(y);
    let (x0, x1) = wrapped_pair(x0, period);
    let (y0, y1) = wrapped_pair(y0, period);
    let corner = |x: u64, y: u64| lattice_value([x, y, 0], salt);
    let (sx, sy) = (fade(fx), fade(fy));
    let bottom = lerp(corner(x0, y0), corner(x1, y0), sx);
    let top = lerp(corner(x0, y1), corner(x1, y1), sx);
    lerp(bottom, top, sy)
}

fn value_noise_3d(point: [f64; 3], salt: u64) -> f64 {
    let (x0, fx) = split(point[0]);
    let (y0, fy) = split(point[1]);
    let (z0, fz) = split(point[2]);
    let corner = |dx: i64, dy: i64, dz: i64| {
        // Negative lattice indices are hashed by their two's-complement bits.
        lattice_value([(x0 + dx) as u64, (y0 + dy) as u64, (z0 + dz) as u64], salt)
    };
    let (sx, sy, sz) = (fade(fx), fade(fy), fade(fz));
    let plane = |dz: i64| {
        let near = lerp(corner(0, 0, dz), corner(1, 0, dz), sx);
        let far = lerp(corner(0, 1, dz), corner(1, 1, dz), sx);
        lerp(near, far, sy)
    };
    lerp(plane(0), plane(1), sz)
}

/// Integer lattice index and fraction of a coordinate (floor by integer conversion, which unlike
/// `f64::floor` needs no library call on baseline x86-64).
fn split(x: f64) -> (i64, f64) {
    let truncated = x as i64;
    let floor = if (truncated as f64) > x { truncated - 1 } else { truncated };
    (floor, x - floor as f64)
}

/// A lattice index and its successor, both wrapped into 0..period.
fn wrapped_pair(index: i64, period: u64) -> (u64, u64) {
    let period = period.max(1);
    // Texture coordinates in 0..=1 give indices in 0..=period; skip the slow division for them.
    let first = match u64::try_from(index) {
        Ok(i) if i < period => i,
        Ok(i) if i == period => 0,
        _ => index.rem_euclid(period as i64) as u64,
    };
    let second = if first + 1 == period { 0 } else { first + 1 };
    (first, second)
}

fn fade(t: f64) -> f64 {
    t * t * t * (t * (t * 6.0 - 15.0) + 10.0)
}

fn lerp(a: f64, b: f64, t: f64) -> f64 {
    a + (b - a) * t
}

/// A value in 0..1 for a lattice point: the point's coordinates, combined with odd multipliers and
/// the octave's salt, through the SplitMix64 finaliser (integer-only, so identical on every platform).
fn lattice_value(coords: [u64; 3], salt: u64) -> f64 {
    let combined = coords[0].wrapping_mul(0x9E37_79B9_7F4A_7C15)
        ^ coords[1].wrapping_mul(0xC2B2_AE3D_27D4_EB4F)
        ^ coords[2].wrapping_mul(0x1656_67B1_9E37_79F9);
    (mix64(combined ^ salt) >> 11) as f64 / (1u64 << 53) as f64
}

/// The per-octave salt, already mixed so that neighbouring seeds give unrelated noise.
fn noise_salt(seed: u32, octave: u32) -> u64 {
    mix64(((seed as u64) << 32) | octave as u64)
}

fn mix64(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

// ---------------------------------------------------------------------------------------------
// Image files
// ---------------------------------------------------------------------------------------------

/// Loads a 2D texture from any format the `image` crate was built with, converted to RGBA8
/// (byte values kept as stored) and flipped so row 0 is the image's bottom.
pub fn load_file(path: &Path) -> Result<TexelImage, String> {
    let (rgba8, width, height) = decode_rgba8(path)?;
    Ok(TexelImage { width, height, layers: 1, rgba8: flip_rows(&rgba8, width) })
}

/// Loads the six faces of a cube texture, in layer order +x −x +y −y +z −z. Faces must be square and
/// all the same size. Faces are *not* flipped: a face file's top row becomes row 0 (t = 0), which is
/// the usual skybox convention (see [`TexelImage`]).
pub fn load_faces(paths: &[PathBuf; 6]) -> Result<TexelImage, String> {
    let mut rgba8 = Vec::new();
    let mut first_size = None;
    for (path, name) in paths.iter().zip(CUBE_FACE_NAMES) {
        let (face, width, height) = decode_rgba8(path).map_err(|e| format!("cube face {name}: {e}"))?;
        if width != height {
            return Err(format!("cube face {name} ({}) is {width}×{height}; faces must be square", path.display()));
        }
        match first_size {
            None => first_size = Some(width),
            Some(size) if size != width => {
                return Err(format!(
                    "cube face {name} ({}) is {width}×{height}, but face {} is {size}×{size}; faces must be the same size",
                    path.display(),
                    CUBE_FACE_NAMES[0]
                ));
            }
            Some(_) => {}
        }
        rgba8.extend_from_slice(&face);
    }
    let size = first_size.unwrap_or(1);
    Ok(TexelImage { width: size, height: size, layers: 6, rgba8 })
}

/// Decodes an image file to RGBA8, rows top-down as stored, returning (bytes, width, height).
/// Errors name the path; images of zero size or larger than [`MAX_IMAGE_SIDE`] on a side are refused.
pub fn decode_rgba8(path: &Path) -> Result<(Vec<u8>, u32, u32), String> {
    let bytes = std::fs::read(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let hint = ImageFormat::from_path(path).ok();
    decode_bytes(&bytes, hint).map_err(|e| format!("cannot load {}: {e}", path.display()))
}

fn decode_bytes(bytes: &[u8], hint: Option<ImageFormat>) -> Result<(Vec<u8>, u32, u32), String> {
    let (width, height) = image_reader(bytes, hint)?.into_dimensions().map_err(|e| e.to_string())?;
    check_dimensions(width, height)?;
    let mut reader = image_reader(bytes, hint)?;
    reader.limits(decode_limits());
    let image = reader.decode().map_err(|e| e.to_string())?;
    let rgba = image.to_rgba8();
    let (width, height) = rgba.dimensions();
    Ok((rgba.into_raw(), width, height))
}

/// A reader that trusts the file's contents over its extension, falling back to the extension.
fn image_reader(bytes: &[u8], hint: Option<ImageFormat>) -> Result<ImageReader<Cursor<&[u8]>>, String> {
    let mut reader = ImageReader::new(Cursor::new(bytes));
    if let Some(format) = hint {
        reader.set_format(format);
    }
    reader.with_guessed_format().map_err(|e| e.to_string())
}

fn check_dimensions(width: u32, height: u32) -> Result<(), String> {
    if width == 0 || height == 0 {
        Err(format!("image is {width}×{height}, which is empty"))
    } else if width > MAX_IMAGE_SIDE || height > MAX_IMAGE_SIDE {
        Err(format!("image is {width}×{height}, larger than the limit of {MAX_IMAGE_SIDE} on a side"))
    } else {
        Ok(())
    }
}

fn decode_limits() -> Limits {
    let mut limits = Limits::default();
    limits.max_image_width = Some(MAX_IMAGE_SIDE);
    limits.max_image_height = Some(MAX_IMAGE_SIDE);
    // Room for a 16-bit RGBA image of the largest accepted size.
    limits.max_alloc = Some(MAX_IMAGE_SIDE as u64 * MAX_IMAGE_SIDE as u64 * 8);
    limits
}

/// The rows of an RGBA8 image in reverse order.
fn flip_rows(rgba8: &[u8], width: u32) -> Vec<u8> {
    let row_len = width as usize * 4;
    if row_len == 0 {
        return rgba8.to_vec();
    }
    rgba8.chunks_exact(row_len).rev().flatten().copied().collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    const RED: [f32; 4] = [1.0, 0.0, 0.0, 1.0];
    const BLUE: [f32; 4] = [0.0, 0.0, 1.0, 1.0];
    const BLACK: [f32; 4] = [0.0, 0.0, 0.0, 1.0];
    const WHITE: [f32; 4] = [1.0, 1.0, 1.0, 1.0];

    fn params(colors: [[f32; 4]; 2], cells: u32, octaves: u32, seed: u32) -> GeneratorParams {
        GeneratorParams { colors, cells, seed, octaves }
    }

    fn texel(image: &TexelImage, layer: u32, column: u32, row: u32) -> [u8; 4] {
        image.texel(layer, column, row).expect("texel in range")
    }

    /// A fresh directory under the system temp dir, removed on drop.
    struct TempDir(PathBuf);

    impl TempDir {
        fn new(name: &str) -> TempDir {
            let dir = std::env::temp_dir().join(format!("effectc-texture-{}-{name}", std::process::id()));
            let _ = std::fs::remove_dir_all(&dir);
            std::fs::create_dir_all(&dir).expect("create temp dir");
            TempDir(dir)
        }
    }

    impl Drop for TempDir {
        fn drop(&mut self) {
            let _ = std::fs::remove_dir_all(&self.0);
        }
    }

    /// Writes a top-down RGBA8 image as PNG.
    fn write_png(path: &Path, width: u32, height: u32, rgba8: Vec<u8>) {
        image::RgbaImage::from_raw(width, height, rgba8).expect("buffer size").save_with_format(path, ImageFormat::Png).expect("write png");
    }

    fn solid_png(path: &Path, width: u32, height: u32, rgba: [u8; 4]) {
        write_png(path, width, height, rgba.repeat((width * height) as usize));
    }

    #[test]
    fn colours_convert_by_clamp_and_round() {
        assert_eq!(to_rgba8([0.5, -1.0, 2.0, f32::NAN]), [128, 0, 255, 0]);
        assert_eq!(to_rgba8([0.2, 1.0 / 255.0, 0.499 / 255.0, f32::INFINITY]), [51, 1, 0, 255]);
    }

    #[test]
    fn checker_corners_and_cell_boundaries() {
        let image = generate(Generator::Checker, 16, &params([RED, BLUE], 4, 4, 0), TextureKind::D2);
        let (red, blue) = (to_rgba8(RED), to_rgba8(BLUE));
        assert_eq!((image.width, image.height, image.layers, image.rgba8.len()), (16, 16, 1, 16 * 16 * 4));
        // Bottom-left (row 0 = v 0) is colour a; with 4 cells the opposite corner is a too.
        assert_eq!(texel(&image, 0, 0, 0), red);
        assert_eq!(texel(&image, 0, 15, 15), red);
        assert_eq!(texel(&image, 0, 15, 0), blue);
        assert_eq!(texel(&image, 0, 0, 15), blue);
        // Cells are 4 texels wide: the colour changes between texel 3 and 4 in both directions.
        assert_eq!(texel(&image, 0, 3, 0), red);
        assert_eq!(texel(&image, 0, 4, 0), blue);
        assert_eq!(texel(&image, 0, 0, 3), red);
        assert_eq!(texel(&image, 0, 0, 4), blue);
        assert_eq!(texel(&image, 0, 4, 4), red);
        assert_eq!(texel(&image, 0, 7, 7), red);
        assert_eq!(texel(&image, 0, 8, 7), blue);
    }

    #[test]
    fn checker_with_more_cells_than_texels_or_zero_cells_does_not_panic() {
        let fine = generate(Generator::Checker, 4, &params([WHITE, BLACK], 100, 1, 0), TextureKind::D2);
        assert_eq!(fine.rgba8.len(), 4 * 4 * 4);
        let zero = generate(Generator::Checker, 4, &params([WHITE, BLACK], 0, 0, 0), TextureKind::D2);
        assert!(zero.rgba8.chunks_exact(4).all(|t| t == [255, 255, 255, 255]), "0 cells acts as one square");
    }

    #[test]
    fn gradient_endpoints_and_monotonic() {
        let image = generate(Generator::Gradient, 16, &params([BLACK, WHITE], 8, 4, 0), TextureKind::D2);
        for row in 0..16 {
            assert_eq!(texel(&image, 0, 0, row), [0, 0, 0, 255]);
            assert_eq!(texel(&image, 0, 15, row), [255, 255, 255, 255]);
            for column in 1..16 {
                assert!(texel(&image, 0, column, row)[0] > texel(&image, 0, column - 1, row)[0]);
            }
        }
    }

    #[test]
    fn solid_and_size_zero() {
        let color = [0.25, 0.5, 0.75, 0.5];
        let image = generate(Generator::Solid, 0, &params([color, BLACK], 8, 4, 0), TextureKind::D2);
        assert_eq!((image.width, image.height), (1, 1));
        assert_eq!(image.rgba8, to_rgba8(color).to_vec());
        let cube = generate(Generator::Solid, 3, &params([color, BLACK], 8, 4, 0), TextureKind::Cube);
        assert_eq!((cube.layers, cube.rgba8.len()), (6, 6 * 3 * 3 * 4));
        assert!(cube.rgba8.chunks_exact(4).all(|t| t == to_rgba8(color)));
    }

    #[test]
    fn noise_is_deterministic_in_range_and_varied() {
        let p = params([BLACK, WHITE], 4, 4, 7);
        let first = generate(Generator::Noise, 32, &p, TextureKind::D2);
        assert_eq!(first, generate(Generator::Noise, 32, &p, TextureKind::D2));
        let reds: Vec<u8> = first.rgba8.chunks_exact(4).map(|t| t[0]).collect();
        let (min, max) = (reds.iter().min().copied(), reds.iter().max().copied());
        assert!(max.unwrap_or(0) - min.unwrap_or(0) > 100, "noise should vary: {min:?}..{max:?}");
        for i in 0..=200 {
            for j in 0..=200 {
                let n = tileable_noise_2d(i as f64 / 200.0, j as f64 / 200.0, 3, 5, 1);
                assert!((0.0..=1.0).contains(&n), "noise {n} out of range");
            }
        }
        // Pinned values: the hash and interpolation are plain integer / IEEE arithmetic, so any change
        // here means textures changed for every user, on every platform.
        assert_eq!(tileable_noise_2d(0.3, 0.7, 8, 4, 0), 0.4864427);
        assert_eq!(tileable_noise_2d(0.3, 0.7, 8, 4, 1), 0.39028734);
        assert_eq!(sphere_noise([0.6, 0.8, 0.0], 8, 4, 0), 0.45449817);
    }

    #[test]
    fn noise_is_tileable() {
        for cells in [1, 3, 8] {
            for i in 0..=64 {
                let t = i as f64 / 64.0;
                assert_eq!(tileable_noise_2d(0.0, t, cells, 4, 9), tileable_noise_2d(1.0, t, cells, 4, 9));
                assert_eq!(tileable_noise_2d(t, 0.0, cells, 4, 9), tileable_noise_2d(t, 1.0, cells, 4, 9));
                // And continuous across the wrap: just left of u = 1 is close to u = 0.
                let left = tileable_noise_2d(1.0 - 1e-6, t, cells, 4, 9);
                assert!((left - tileable_noise_2d(0.0, t, cells, 4, 9)).abs() < 1e-3);
            }
        }
        // In the texture, the wrap-around step (last column → first) is no larger than steps inside.
        let image = generate(Generator::Noise, 64, &params([BLACK, WHITE], 4, 3, 2), TextureKind::D2);
        let red = |c: u32, r: u32| texel(&image, 0, c, r)[0] as i32;
        let mut inner_max = 0;
        let mut wrap_max = 0;
        for r in 0..64 {
            for c in 1..64 {
                inner_max = inner_max.max((red(c, r) - red(c - 1, r)).abs());
            }
            wrap_max = wrap_max.max((red(0, r) - red(63, r)).abs());
            wrap_max = wrap_max.max((red(r, 0) - red(r, 63)).abs());
        }
        assert!(wrap_max <= inner_max, "wrap step {wrap_max} vs inner step {inner_max}");
    }

    #[test]
    fn noise_differs_by_seed_and_handles_extreme_params() {
        let a = generate(Generator::Noise, 16, &params([BLACK, WHITE], 4, 4, 0), TextureKind::D2);
        let b = generate(Generator::Noise, 16, &params([BLACK, WHITE], 4, 4, 1), TextureKind::D2);
        assert_ne!(a, b);
        for (cells, octaves) in [(0, 0), (u32::MAX, u32::MAX), (1, 100)] {
            let n = tileable_noise_2d(0.25, 0.75, cells, octaves, u32::MAX);
            assert!((0.0..=1.0).contains(&n));
            let s = sphere_noise([0.0, 1.0, 0.0], cells, octaves, u32::MAX);
            assert!((0.0..=1.0).contains(&s));
        }
    }

    /// Cube-map face selection, written from the spec table independently of `cube_direction`:
    /// returns (face, s, t) with s, t in 0..1.
    fn face_coords(d: [f64; 3]) -> (u32, f64, f64) {
        let [x, y, z] = d;
        let (face, sc, tc, ma) = if x.abs() >= y.abs() && x.abs() >= z.abs() {
            if x > 0.0 {
                (0, -z, -y, x)
            } else {
                (1, z, -y, x)
            }
        } else if y.abs() >= z.abs() {
            if y > 0.0 {
                (2, x, z, y)
            } else {
                (3, x, -z, y)
            }
        } else if z > 0.0 {
            (4, x, -y, z)
        } else {
            (5, -x, -y, z)
        };
        (face, (sc / ma.abs() + 1.0) / 2.0, (tc / ma.abs() + 1.0) / 2.0)
    }

    #[test]
    fn cube_direction_matches_the_face_selection_table() {
        let axes = [[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, -1.0]];
        for face in 0..6 {
            assert_eq!(normalize(cube_direction(face, 0.0, 0.0)), axes[face as usize]);
            for (sc, tc) in [(-0.9, -0.9), (0.9, -0.9), (-0.5, 0.7), (0.3, 0.1)] {
                let (f, s, t) = face_coords(cube_direction(face, sc, tc));
                assert_eq!(f, face);
                assert!((s * 2.0 - 1.0 - sc).abs() < 1e-12 && (t * 2.0 - 1.0 - tc).abs() < 1e-12);
            }
        }
        // Spot checks: on the side faces row 0 (t = 0) is up; +x column 0 looks towards +z;
        // +y row 0 looks towards −z; +z column 0 looks towards −x.
        assert_eq!(cube_direction(0, -1.0, -1.0), [1.0, 1.0, 1.0]);
        assert_eq!(cube_direction(4, -1.0, -1.0), [-1.0, 1.0, 1.0]);
        assert_eq!(cube_direction(2, 0.0, -1.0), [0.0, 1.0, -1.0]);
        assert_eq!(cube_direction(5, -1.0, 0.0), [1.0, -0.0, -1.0]);
    }

    /// For every edge texel of every face, the texel found across the edge (by stepping half a texel
    /// outside the face and looking the direction up in the face table) and the largest difference
    /// between them; `flip` deliberately pairs the wrong texel, as a control.
    fn seam_difference(image: &TexelImage, flip: bool) -> i32 {
        let size = image.width;
        let mut max = 0;
        for face in 0..6 {
            for i in 0..size {
                let along = (i as f64 + 0.5) / size as f64 * 2.0 - 1.0;
                let outside = 1.0 + 0.5 / size as f64;
                let edges = [
                    ((0, i), (-outside, along)),
                    ((size - 1, i), (outside, along)),
                    ((i, 0), (along, -outside)),
                    ((i, size - 1), (along, outside)),
                ];
                for ((column, row), (sc, tc)) in edges {
                    let (other, s, t) = face_coords(cube_direction(face, sc, tc));
                    assert_ne!(other, face);
                    let index = |x: f64| ((x * size as f64).floor() as u32).min(size - 1);
                    let (c2, mut r2) = (index(s), index(t));
                    if flip {
                        r2 = size - 1 - r2;
                    }
                    let here = texel(image, face, column, row);
                    let there = texel(image, other, c2, r2);
                    for ch in 0..3 {
                        max = max.max((here[ch] as i32 - there[ch] as i32).abs());
                    }
                }
            }
        }
        max
    }

    /// The largest difference between horizontally or vertically adjacent texels inside faces.
    fn interior_difference(image: &TexelImage) -> i32 {
        let size = image.width;
        let mut max = 0;
        for face in 0..6 {
            for a in 0..size {
                for b in 1..size {
                    let pairs = [
                        (texel(image, face, b, a), texel(image, face, b - 1, a)),
                        (texel(image, face, a, b), texel(image, face, a, b - 1)),
                    ];
                    for (p, q) in pairs {
                        max = max.max((p[0] as i32 - q[0] as i32).abs());
                    }
                }
            }
        }
        max
    }

    #[test]
    fn cube_noise_is_seamless() {
        let image = generate(Generator::Noise, 48, &params([BLACK, WHITE], 3, 3, 5), TextureKind::Cube);
        let seam = seam_difference(&image, false);
        let interior = interior_difference(&image);
        assert!(interior > 0);
        assert!(seam <= interior + 2, "seam {seam} vs interior {interior}");
        let wrong = seam_difference(&image, true);
        assert!(wrong > 3 * seam, "the control pairing should be far off: {wrong} vs {seam}");
    }

    #[test]
    fn cube_gradient_is_a_seamless_sky() {
        let image = generate(Generator::Gradient, 32, &params([BLACK, WHITE], 8, 4, 0), TextureKind::Cube);
        let seam = seam_difference(&image, false);
        assert!(seam <= interior_difference(&image) + 1, "seam {seam}");
        // +y (layer 2) centre ≈ colour b, −y (layer 3) centre ≈ colour a.
        assert!(texel(&image, 2, 16, 16)[0] >= 254);
        assert!(texel(&image, 3, 16, 16)[0] <= 1);
        // On the side faces row 0 is the upper edge, so it is the brighter one.
        for face in [0, 1, 4, 5] {
            assert!(texel(&image, face, 16, 0)[0] > 200 && texel(&image, face, 16, 31)[0] < 55);
        }
        assert!(seam_difference(&image, true) > 100);
    }

    #[test]
    fn cube_checker_uses_face_local_tiles() {
        let image = generate(Generator::Checker, 8, &params([RED, BLUE], 2, 4, 0), TextureKind::Cube);
        for face in 0..6 {
            assert_eq!(texel(&image, face, 0, 0), to_rgba8(RED));
            assert_eq!(texel(&image, face, 4, 0), to_rgba8(BLUE));
            assert_eq!(texel(&image, face, 4, 4), to_rgba8(RED));
        }
    }

    #[test]
    fn placeholders() {
        let flat = placeholder(TextureKind::D2);
        assert_eq!((flat.width, flat.height, flat.layers), (64, 64, 1));
        assert_eq!(texel(&flat, 0, 0, 0), [255, 0, 255, 255]);
        assert_eq!(texel(&flat, 0, 8, 0), [0, 0, 0, 255]);
        let cube = placeholder(TextureKind::Cube);
        assert_eq!((cube.width, cube.layers, cube.rgba8.len()), (32, 6, 32 * 32 * 6 * 4));
        let sky = to_rgba8([0.25, 0.55, 0.95, 1.0]);
        let up = texel(&cube, 2, 16, 16);
        assert!(up.iter().zip(sky).all(|(a, b)| a.abs_diff(b) <= 1), "{up:?}");
    }

    #[test]
    fn loaded_png_rows_are_bottom_up() {
        let dir = TempDir::new("bottom-up");
        let path = dir.0.join("two.png");
        // Top row: red, green. Bottom row: blue, white.
        let pixels = [[255, 0, 0, 255], [0, 255, 0, 255], [0, 0, 255, 255], [255, 255, 255, 255]];
        write_png(&path, 2, 2, pixels.concat());
        let image = load_file(&path).expect("load");
        assert_eq!((image.width, image.height, image.layers), (2, 2, 1));
        assert_eq!(texel(&image, 0, 0, 0), pixels[2]);
        assert_eq!(texel(&image, 0, 1, 0), pixels[3]);
        assert_eq!(texel(&image, 0, 0, 1), pixels[0]);
        assert_eq!(texel(&image, 0, 1, 1), pixels[1]);
    }

    #[test]
    fn load_file_reports_errors_with_the_path() {
        let dir = TempDir::new("errors");
        let missing = dir.0.join("missing.png");
        let err = load_file(&missing).expect_err("missing file");
        assert!(err.contains("missing.png"), "{err}");

        let garbage = dir.0.join("garbage.jpg");
        std::fs::write(&garbage, b"not an image at all").expect("write");
        let err = load_file(&garbage).expect_err("garbage");
        assert!(err.contains("garbage.jpg"), "{err}");

        let truncated = dir.0.join("truncated.png");
        solid_png(&truncated, 8, 8, [1, 2, 3, 4]);
        let bytes = std::fs::read(&truncated).expect("read");
        std::fs::write(&truncated, &bytes[..bytes.len() / 2]).expect("write");
        assert!(load_file(&truncated).is_err());

        let wide = dir.0.join("wide.png");
        solid_png(&wide, MAX_IMAGE_SIDE + 1, 1, [0, 0, 0, 255]);
        let err = load_file(&wide).expect_err("too wide");
        assert!(err.contains("wide.png") && err.contains("16384"), "{err}");
    }

    #[test]
    fn load_file_trusts_contents_over_extension() {
        let dir = TempDir::new("extension");
        let path = dir.0.join("actually-png.jpg");
        solid_png(&path, 3, 2, [10, 20, 30, 255]);
        let image = load_file(&path).expect("load");
        assert_eq!((image.width, image.height), (3, 2));
        assert_eq!(texel(&image, 0, 2, 1), [10, 20, 30, 255]);
    }

    #[test]
    fn loads_jpeg_and_gif_files() {
        let dir = TempDir::new("formats");
        for name in ["photo.jpg", "still.gif"] {
            let path = dir.0.join(name);
            image::RgbImage::from_pixel(8, 4, image::Rgb([200, 100, 50])).save(&path).expect("write");
            let image = load_file(&path).expect("load");
            assert_eq!((image.width, image.height, image.layers), (8, 4, 1), "{name}");
            let t = texel(&image, 0, 3, 2);
            let expected = [200u8, 100, 50, 255];
            assert!(t.iter().zip(expected).all(|(a, b)| a.abs_diff(b) <= 6), "{name}: {t:?}");
        }
    }

    #[test]
    fn load_faces_keeps_face_rows_and_checks_sizes() {
        let dir = TempDir::new("faces");
        let paths: [PathBuf; 6] = std::array::from_fn(|i| dir.0.join(format!("face{i}.png")));
        for (i, path) in paths.iter().enumerate() {
            // Top row grey level i * 10, bottom row white.
            let top = [i as u8 * 10, 0, 0, 255];
            write_png(path, 2, 2, [top, top, [255; 4], [255; 4]].concat());
        }
        let cube = load_faces(&paths).expect("faces");
        assert_eq!((cube.width, cube.height, cube.layers), (2, 2, 6));
        for face in 0..6u32 {
            assert_eq!(texel(&cube, face, 1, 0), [face as u8 * 10, 0, 0, 255], "file top row is row 0");
            assert_eq!(texel(&cube, face, 0, 1), [255; 4]);
        }

        solid_png(&paths[3], 4, 4, [0, 0, 0, 255]);
        let err = load_faces(&paths).expect_err("size mismatch");
        assert!(err.contains("-y") && err.contains("face3.png"), "{err}");

        solid_png(&paths[3], 2, 2, [0, 0, 0, 255]);
        solid_png(&paths[0], 2, 3, [0, 0, 0, 255]);
        let err = load_faces(&paths).expect_err("not square");
        assert!(err.contains("+x") && err.contains("square"), "{err}");

        solid_png(&paths[0], 2, 2, [0, 0, 0, 255]);
        std::fs::remove_file(&paths[5]).expect("remove");
        let err = load_faces(&paths).expect_err("missing face");
        assert!(err.contains("-z") && err.contains("face5.png"), "{err}");
    }

    #[test]
    fn mipmaps_halve_down_to_one_texel_and_average() {
        let image = generate(Generator::Checker, 8, &GeneratorParams { cells: 8, ..Default::default() }, TextureKind::D2);
        let chain = image.mip_chain();
        let sizes: Vec<(u32, u32)> = chain.iter().map(|l| (l.width, l.height)).collect();
        assert_eq!(sizes, vec![(4, 4), (2, 2), (1, 1)]);
        // A one-texel checker of white and black averages to mid grey at the first level.
        let t = chain[0].texel(0, 0, 0).unwrap();
        assert!((126..=129).contains(&t[0]), "{t:?}");
        let odd = TexelImage { width: 3, height: 1, layers: 1, rgba8: vec![0, 0, 0, 255, 255, 255, 255, 255, 90, 90, 90, 255] };
        assert_eq!(odd.mip_chain().iter().map(|l| (l.width, l.height)).collect::<Vec<_>>(), vec![(1, 1)]);
        let cube = generate(Generator::Gradient, 4, &GeneratorParams::default(), TextureKind::Cube);
        assert!(cube.mip_chain().iter().all(|l| l.layers == 6 && l.rgba8.len() == l.layer_len() * 6));
    }
}
