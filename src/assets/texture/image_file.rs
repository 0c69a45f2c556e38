//! Image files: 2D textures and the six faces of a cube texture, decoded with the `image`
//! crate into a texel format (RGBA8: byte values kept as stored; floating point: 8- and
//! 16-bit channels as 0..1, HDR and EXR values as stored; integers: the stored 8- or 16-bit
//! channel values), within [`MAX_IMAGE_SIDE`] on a side.

use std::io::Cursor;
use std::path::{Path, PathBuf};

use image::{DynamicImage, ImageFormat, ImageReader, Limits};

use super::{TexelImage, CUBE_FACE_NAMES, MAX_IMAGE_SIDE};
use crate::manifest::{TexelFormat, TexelKind};

/// Loads a 2D texture from any format the `image` crate was built with, converted to RGBA8
/// (byte values kept as stored) and flipped so row 0 is the image's bottom.
pub fn load_file(path: &Path) -> Result<TexelImage, String> {
    load_file_as(path, TexelFormat::Rgba8)
}

/// [`load_file`] into `format` (see the module doc).
pub fn load_file_as(path: &Path, format: TexelFormat) -> Result<TexelImage, String> {
    let image = decode(path)?;
    let (width, height) = (image.width(), image.height());
    let bytes = texels(&image, format).map_err(|e| format!("{}: {e}", path.display()))?;
    let rows: Vec<&[u8]> = bytes.chunks_exact(width as usize * format.texel_bytes()).rev().collect();
    Ok(TexelImage { width, height, layers: 1, format, bytes: rows.concat() })
}

/// The texels of `image` in `format`, rows top-down as stored: RGBA8 its bytes as they are.
fn texels(image: &DynamicImage, format: TexelFormat) -> Result<Vec<u8>, String> {
    if format == TexelFormat::Rgba8 {
        return Ok(image.to_rgba8().into_raw());
    }
    let values = values_of(image, format)?;
    Ok(TexelImage::from_values(image.width(), image.height(), 1, format, values.into_iter()).bytes)
}

/// The texel values of `image` as a format other than RGBA8 takes them, rows top-down.
fn values_of(image: &DynamicImage, format: TexelFormat) -> Result<Vec<[f64; 4]>, String> {
    let wide = |v: &[f32]| v.chunks_exact(4).map(|c| std::array::from_fn(|i| f64::from(c[i]))).collect();
    let ints = |v: Vec<u32>| v.chunks_exact(4).map(|c| std::array::from_fn(|i| f64::from(c[i]))).collect();
    Ok(match format.kind() {
        TexelKind::Float => wide(image.to_rgba32f().as_raw()),
        _ => match image.color().bytes_per_pixel() / image.color().channel_count() {
            1 => ints(image.to_rgba8().into_raw().into_iter().map(u32::from).collect()),
            2 => ints(image.to_rgba16().into_raw().into_iter().map(u32::from).collect()),
            _ => return Err(format!("`{}` holds integers: it takes an image of 8- or 16-bit channels, not floating point", format.name())),
        },
    })
}

/// Loads the six faces of a cube texture, in layer order +x −x +y −y +z −z. Faces must be square and
/// all the same size. Faces are *not* flipped: a face file's top row becomes row 0 (t = 0), which is
/// the usual skybox convention (see [`TexelImage`]).
pub fn load_faces(paths: &[PathBuf; 6], format: TexelFormat) -> Result<TexelImage, String> {
    let mut bytes = Vec::new();
    let mut first_size = None;
    for (path, name) in paths.iter().zip(CUBE_FACE_NAMES) {
        let image = decode(path).map_err(|e| format!("cube face {name}: {e}"))?;
        let (width, height) = (image.width(), image.height());
        let face = texels(&image, format).map_err(|e| format!("cube face {name} ({}): {e}", path.display()))?;
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
        bytes.extend(face);
    }
    let size = first_size.unwrap_or(1);
    Ok(TexelImage { width: size, height: size, layers: 6, format, bytes })
}

/// Decodes an image file to RGBA8, rows top-down as stored, returning (bytes, width, height).
/// Errors name the path; images of zero size or larger than [`MAX_IMAGE_SIDE`] on a side are refused.
pub fn decode_rgba8(path: &Path) -> Result<(Vec<u8>, u32, u32), String> {
    let rgba = decode(path)?.to_rgba8();
    let (width, height) = rgba.dimensions();
    Ok((rgba.into_raw(), width, height))
}

/// Decodes an image file, within the size limits; errors name the path.
fn decode(path: &Path) -> Result<DynamicImage, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let hint = ImageFormat::from_path(path).ok();
    decode_bytes(&bytes, hint).map_err(|e| format!("cannot load {}: {e}", path.display()))
}

fn decode_bytes(bytes: &[u8], hint: Option<ImageFormat>) -> Result<DynamicImage, String> {
    let (width, height) = image_reader(bytes, hint)?.into_dimensions().map_err(|e| e.to_string())?;
    check_dimensions(width, height)?;
    let mut reader = image_reader(bytes, hint)?;
    reader.limits(decode_limits());
    reader.decode().map_err(|e| e.to_string())
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
