//! Image files: 2D textures and the six faces of a cube texture, decoded to RGBA8 with the `image`
//! crate (byte values kept as stored), within [`MAX_IMAGE_SIDE`] on a side.

use std::io::Cursor;
use std::path::{Path, PathBuf};

use image::{ImageFormat, ImageReader, Limits};

use super::{TexelImage, CUBE_FACE_NAMES, MAX_IMAGE_SIDE};

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
