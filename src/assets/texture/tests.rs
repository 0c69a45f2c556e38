use std::path::{Path, PathBuf};

use image::ImageFormat;

use super::cube_map::normalize;
use super::*;
use crate::manifest::{Generator, GeneratorParams, TextureKind};

const RED: [f32; 4] = [1.0, 0.0, 0.0, 1.0];
const BLUE: [f32; 4] = [0.0, 0.0, 1.0, 1.0];
const BLACK: [f32; 4] = [0.0, 0.0, 0.0, 1.0];
const WHITE: [f32; 4] = [1.0, 1.0, 1.0, 1.0];

fn params(colors: [[f32; 4]; 2], cells: u32, octaves: u32, seed: u32) -> GeneratorParams {
    GeneratorParams { colors: colors.map(|c| c.map(f64::from)), cells, seed, octaves }
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
    let image = generate(Generator::Checker, 16, &params([RED, BLUE], 4, 4, 0), TextureKind::D2, TexelFormat::Rgba8);
    let (red, blue) = (to_rgba8(RED), to_rgba8(BLUE));
    assert_eq!((image.width, image.height, image.layers, image.bytes.len()), (16, 16, 1, 16 * 16 * 4));
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
    let fine = generate(Generator::Checker, 4, &params([WHITE, BLACK], 100, 1, 0), TextureKind::D2, TexelFormat::Rgba8);
    assert_eq!(fine.bytes.len(), 4 * 4 * 4);
    let zero = generate(Generator::Checker, 4, &params([WHITE, BLACK], 0, 0, 0), TextureKind::D2, TexelFormat::Rgba8);
    assert!(zero.bytes.chunks_exact(4).all(|t| t == [255, 255, 255, 255]), "0 cells acts as one square");
}

#[test]
fn gradient_endpoints_and_monotonic() {
    let image = generate(Generator::Gradient, 16, &params([BLACK, WHITE], 8, 4, 0), TextureKind::D2, TexelFormat::Rgba8);
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
    let image = generate(Generator::Solid, 0, &params([color, BLACK], 8, 4, 0), TextureKind::D2, TexelFormat::Rgba8);
    assert_eq!((image.width, image.height), (1, 1));
    assert_eq!(image.bytes, to_rgba8(color).to_vec());
    let cube = generate(Generator::Solid, 3, &params([color, BLACK], 8, 4, 0), TextureKind::Cube, TexelFormat::Rgba8);
    assert_eq!((cube.layers, cube.bytes.len()), (6, 6 * 3 * 3 * 4));
    assert!(cube.bytes.chunks_exact(4).all(|t| t == to_rgba8(color)));
}

#[test]
fn noise_is_deterministic_in_range_and_varied() {
    let p = params([BLACK, WHITE], 4, 4, 7);
    let first = generate(Generator::Noise, 32, &p, TextureKind::D2, TexelFormat::Rgba8);
    assert_eq!(first, generate(Generator::Noise, 32, &p, TextureKind::D2, TexelFormat::Rgba8));
    let reds: Vec<u8> = first.bytes.chunks_exact(4).map(|t| t[0]).collect();
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
    let image = generate(Generator::Noise, 64, &params([BLACK, WHITE], 4, 3, 2), TextureKind::D2, TexelFormat::Rgba8);
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
    let a = generate(Generator::Noise, 16, &params([BLACK, WHITE], 4, 4, 0), TextureKind::D2, TexelFormat::Rgba8);
    let b = generate(Generator::Noise, 16, &params([BLACK, WHITE], 4, 4, 1), TextureKind::D2, TexelFormat::Rgba8);
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
                let pairs =
                    [(texel(image, face, b, a), texel(image, face, b - 1, a)), (texel(image, face, a, b), texel(image, face, a, b - 1))];
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
    let image = generate(Generator::Noise, 48, &params([BLACK, WHITE], 3, 3, 5), TextureKind::Cube, TexelFormat::Rgba8);
    let seam = seam_difference(&image, false);
    let interior = interior_difference(&image);
    assert!(interior > 0);
    assert!(seam <= interior + 2, "seam {seam} vs interior {interior}");
    let wrong = seam_difference(&image, true);
    assert!(wrong > 3 * seam, "the control pairing should be far off: {wrong} vs {seam}");
}

#[test]
fn cube_gradient_is_a_seamless_sky() {
    let image = generate(Generator::Gradient, 32, &params([BLACK, WHITE], 8, 4, 0), TextureKind::Cube, TexelFormat::Rgba8);
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
    let image = generate(Generator::Checker, 8, &params([RED, BLUE], 2, 4, 0), TextureKind::Cube, TexelFormat::Rgba8);
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
    assert_eq!((cube.width, cube.layers, cube.bytes.len()), (32, 6, 32 * 32 * 6 * 4));
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
    let cube = load_faces(&paths, TexelFormat::Rgba8).expect("faces");
    assert_eq!((cube.width, cube.height, cube.layers), (2, 2, 6));
    for face in 0..6u32 {
        assert_eq!(texel(&cube, face, 1, 0), [face as u8 * 10, 0, 0, 255], "file top row is row 0");
        assert_eq!(texel(&cube, face, 0, 1), [255; 4]);
    }

    solid_png(&paths[3], 4, 4, [0, 0, 0, 255]);
    let err = load_faces(&paths, TexelFormat::Rgba8).expect_err("size mismatch");
    assert!(err.contains("-y") && err.contains("face3.png"), "{err}");

    solid_png(&paths[3], 2, 2, [0, 0, 0, 255]);
    solid_png(&paths[0], 2, 3, [0, 0, 0, 255]);
    let err = load_faces(&paths, TexelFormat::Rgba8).expect_err("not square");
    assert!(err.contains("+x") && err.contains("square"), "{err}");

    solid_png(&paths[0], 2, 2, [0, 0, 0, 255]);
    std::fs::remove_file(&paths[5]).expect("remove");
    let err = load_faces(&paths, TexelFormat::Rgba8).expect_err("missing face");
    assert!(err.contains("-z") && err.contains("face5.png"), "{err}");
}

#[test]
fn mipmaps_halve_down_to_one_texel_and_average() {
    let image = generate(Generator::Checker, 8, &GeneratorParams { cells: 8, ..Default::default() }, TextureKind::D2, TexelFormat::Rgba8);
    let chain = image.mip_chain();
    let sizes: Vec<(u32, u32)> = chain.iter().map(|l| (l.width, l.height)).collect();
    assert_eq!(sizes, vec![(4, 4), (2, 2), (1, 1)]);
    // A one-texel checker of white and black averages to mid grey at the first level.
    let t = chain[0].texel(0, 0, 0).unwrap();
    assert!((126..=129).contains(&t[0]), "{t:?}");
    let odd = TexelImage::rgba8(3, 1, 1, vec![0, 0, 0, 255, 255, 255, 255, 255, 90, 90, 90, 255]);
    assert_eq!(odd.mip_chain().iter().map(|l| (l.width, l.height)).collect::<Vec<_>>(), vec![(1, 1)]);
    let cube = generate(Generator::Gradient, 4, &GeneratorParams::default(), TextureKind::Cube, TexelFormat::Rgba8);
    assert!(cube.mip_chain().iter().all(|l| l.layers == 6 && l.bytes.len() == l.layer_len() * 6));
}

/// An integer texture's colours are whole numbers as written, beyond f32's 2^24 too.
#[test]
fn generated_integer_textures_hold_their_colours_exactly() {
    let exact = |colors: [[f64; 4]; 2], cells| GeneratorParams { colors, cells, ..GeneratorParams::default() };
    let big = exact([[4_294_967_295.0, 16_777_217.0, 0.0, 1.0], [0.0, 0.0, 0.0, 1.0]], 2);
    let texels = generate(Generator::Checker, 2, &big, TextureKind::D2, TexelFormat::Rgba32ui);
    let first = |i: usize| u32::from_le_bytes(texels.bytes[i * 4..i * 4 + 4].try_into().unwrap());
    assert_eq!((first(0), first(1)), (u32::MAX, 16_777_217), "checker colour a at the bottom-left texel");
    let extremes = exact([[-2_147_483_648.0, 2_147_483_647.0, -16_777_217.0, 0.0], [0.0; 4]], 1);
    let solid = generate(Generator::Solid, 1, &extremes, TextureKind::D2, TexelFormat::Rgba32i);
    let ints: Vec<i32> = solid.bytes.chunks_exact(4).map(|b| i32::from_le_bytes(b.try_into().unwrap())).collect();
    assert_eq!(ints, [i32::MIN, i32::MAX, -16_777_217, 0]);
}

#[test]
fn float_and_integer_formats_keep_the_values_given() {
    let values = [[-2.0, 0.5, 1000.0, 1.0], [3.25, 0.0, 7.0, 0.0]];
    let f32s = TexelImage::from_values(2, 1, 1, TexelFormat::Rgba32f, values.into_iter());
    assert_eq!(f32s.bytes.len(), 2 * 16);
    assert_eq!(f32s.value(0, 0, 0), Some([-2.0, 0.5, 1000.0, 1.0]), "beyond [0, 1], unclamped");
    let f16s = TexelImage::from_values(2, 1, 1, TexelFormat::Rgba16f, values.into_iter());
    assert_eq!((f16s.bytes.len(), f16s.value(0, 1, 0)), (2 * 8, Some([3.25, 0.0, 7.0, 0.0])), "exact in half precision");
    let red = TexelImage::from_values(2, 1, 1, TexelFormat::R32ui, [[7.0, 9.0, 9.0, 9.0], [-3.0, 0.0, 0.0, 0.0]].into_iter());
    assert_eq!(red.bytes.len(), 2 * 4);
    assert_eq!(
        (red.value(0, 0, 0), red.value(0, 1, 0)),
        (Some([7.0, 0.0, 0.0, 1.0]), Some([0.0, 0.0, 0.0, 1.0])),
        "r: (r, 0, 0, 1), saturated"
    );
    let ints = TexelImage::from_values(1, 1, 1, TexelFormat::Rgba32i, [[-5.0, 3.0, 0.0, 1.0]].into_iter());
    assert_eq!(ints.value(0, 0, 0), Some([-5.0, 3.0, 0.0, 1.0]));
    assert!(ints.mip_chain().is_empty() && ints.texel(0, 0, 0).is_none(), "integer textures have one level and no RGBA8 bytes");
    assert_eq!(ints.channel_ranges()[0], (-5.0, -5.0));
    // Float mipmaps average in floating point.
    let quad = TexelImage::from_values(2, 2, 1, TexelFormat::Rgba32f, [[-2.0; 4], [4.0; 4], [0.0; 4], [2.0; 4]].into_iter());
    let mips = quad.mip_chain();
    assert_eq!((mips.len(), mips[0].value(0, 0, 0)), (1, Some([1.0; 4])));
    assert_eq!(quad.channel_ranges()[3], (-2.0, 4.0));
    // RGBA8 keeps its bytes and reads them as 0..1.
    let bytes = TexelImage::from_values(1, 1, 1, TexelFormat::Rgba8, [[1.5, 0.5, -1.0, 1.0]].into_iter());
    assert_eq!((bytes.texel(0, 0, 0), bytes.value(0, 0, 0)), (Some([255, 128, 0, 255]), Some([1.0, 128.0 / 255.0, 0.0, 1.0])));
}

#[test]
fn image_files_load_as_float_and_integer_texels() {
    let dir = TempDir::new("formats");
    // Radiance HDR keeps values past 1 (to its shared-exponent precision), bottom row first.
    let hdr = dir.0.join("bright.hdr");
    image::DynamicImage::ImageRgb32F(image::Rgb32FImage::from_raw(1, 2, vec![5.0, 0.25, 1.0, 0.5, 0.5, 0.5]).unwrap())
        .save(&hdr)
        .expect("save hdr");
    let bright = load_file_as(&hdr, TexelFormat::Rgba32f).expect("load hdr");
    let top = bright.value(0, 0, 1).expect("top row");
    assert!((top[0] - 5.0).abs() < 0.05 && (top[1] - 0.25).abs() < 0.01 && top[3] == 1.0, "{top:?}");
    assert_eq!(bright.value(0, 0, 0).map(|v| v[0]), Some(0.5));
    // A 16-bit PNG gives its stored channel values to an integer format.
    let ids = dir.0.join("ids.png");
    image::DynamicImage::ImageLuma16(image::ImageBuffer::from_raw(2, 1, vec![1000u16, 65535]).unwrap()).save(&ids).expect("save png");
    let texels = load_file_as(&ids, TexelFormat::R32ui).expect("load ids");
    assert_eq!((texels.value(0, 0, 0), texels.value(0, 1, 0)), (Some([1000.0, 0.0, 0.0, 1.0]), Some([65535.0, 0.0, 0.0, 1.0])));
    // ... and as 0..1 to a float one; a floating-point file is refused by an integer format.
    assert_eq!(load_file_as(&ids, TexelFormat::R32f).expect("load").value(0, 1, 0), Some([1.0, 0.0, 0.0, 1.0]));
    let refused = load_file_as(&hdr, TexelFormat::Rgba32i).expect_err("float image as integers");
    assert!(refused.contains("holds integers") && refused.contains("bright.hdr"), "{refused}");
}
