//! The procedural generators (checker, gradient, noise, solid) for 2D and cube textures, the
//! placeholders bound to samplers that have no manifest entry, and linear colour to RGBA8 bytes.

use super::cube_map::{cube_direction, normalize};
use super::noise::{sphere_noise, tileable_noise_2d};
use super::{TexelImage, MAX_IMAGE_SIDE};
use crate::manifest::{Generator, GeneratorParams, TexelFormat, TextureKind};

/// Generates a square texture of `size` texels per side (0 is treated as 1, more than
/// [`MAX_IMAGE_SIDE`] as that) in `format`. See the module doc for the colour encoding.
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
pub fn generate(generator: Generator, size: u32, params: &GeneratorParams, kind: TextureKind, format: TexelFormat) -> TexelImage {
    let size = size.clamp(1, MAX_IMAGE_SIDE);
    match kind {
        TextureKind::D2 => build(size, 1, format, |_, column, row| texel_2d(generator, size, params, column, row)),
        TextureKind::Cube => build(size, 6, format, |face, column, row| texel_cube(generator, size, params, face, column, row)),
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
            generate(Generator::Checker, 64, &params, TextureKind::D2, TexelFormat::Rgba8)
        }
        TextureKind::Cube => {
            let params = GeneratorParams { colors: [[0.12, 0.10, 0.08, 1.0], [0.25, 0.55, 0.95, 1.0]], ..Default::default() };
            generate(Generator::Gradient, 32, &params, TextureKind::Cube, TexelFormat::Rgba8)
        }
    }
}

/// Fills `layers` square layers of `size` texels, calling `texel(layer, column, row)` for each.
fn build(size: u32, layers: u32, format: TexelFormat, texel: impl Fn(u32, u32, u32) -> [f64; 4]) -> TexelImage {
    let texels = (0..layers).flat_map(|layer| (0..size).flat_map(move |row| (0..size).map(move |column| (layer, column, row))));
    TexelImage::from_values(size, size, layers, format, texels.map(|(layer, column, row)| texel(layer, column, row)))
}

/// Colours a and b as the blending generators (gradient, noise) mix them, in f32; checker
/// and solid texels are the colours as written.
fn blend_colors(params: &GeneratorParams) -> [[f32; 4]; 2] {
    params.colors.map(|c| c.map(|x| x as f32))
}

fn texel_2d(generator: Generator, size: u32, params: &GeneratorParams, column: u32, row: u32) -> [f64; 4] {
    let [a, b] = blend_colors(params);
    match generator {
        Generator::Checker => checker(params, size, column, row),
        Generator::Gradient => mix(a, b, ramp(column, size)),
        Generator::Noise => {
            let (u, v) = (texel_centre(column, size), texel_centre(row, size));
            mix(a, b, tileable_noise_2d(u, v, params.cells, params.octaves, params.seed))
        }
        Generator::Solid => params.colors[0],
    }
}

fn texel_cube(generator: Generator, size: u32, params: &GeneratorParams, face: u32, column: u32, row: u32) -> [f64; 4] {
    let [a, b] = blend_colors(params);
    let sc = texel_centre(column, size) * 2.0 - 1.0;
    let tc = texel_centre(row, size) * 2.0 - 1.0;
    let direction = normalize(cube_direction(face, sc, tc));
    match generator {
        Generator::Checker => checker(params, size, column, row),
        Generator::Gradient => mix(a, b, ((direction[1] + 1.0) * 0.5) as f32),
        Generator::Noise => mix(a, b, sphere_noise(direction, params.cells, params.octaves, params.seed)),
        Generator::Solid => params.colors[0],
    }
}

/// Colour a or b for the checker square holding the texel's centre.
fn checker(params: &GeneratorParams, size: u32, column: u32, row: u32) -> [f64; 4] {
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

fn mix(a: [f32; 4], b: [f32; 4], t: f32) -> [f64; 4] {
    std::array::from_fn(|i| f64::from(a[i] + (b[i] - a[i]) * t))
}

/// Linear float colour to bytes: `round(clamp(c, 0, 1) * 255)`, NaN → 0.
pub fn to_rgba8(color: [f32; 4]) -> [u8; 4] {
    color.map(unit_to_byte)
}

pub(super) fn unit_to_byte(c: f32) -> u8 {
    if c.is_nan() {
        return 0;
    }
    // round() of a non-negative value, as floor(x + 0.5) in f64 (exact, and cheaper than `f32::round`).
    (f64::from(c.clamp(0.0, 1.0) * 255.0) + 0.5) as u8
}
