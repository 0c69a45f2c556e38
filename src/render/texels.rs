//! Texels read back from the device as RGBA floats: render targets of every format a pass
//! can have, and the images a compute program stores to.

/// Texels of `format` as RGBA floats (missing channels 0, alpha 1; normalized formats as
/// their value in [0, 1] or [−1, 1], integers as their values), rows top first
/// (`bottom_up`: the bytes hold the bottom row first).
pub fn decode_rgba(bytes: &[u8], format: wgpu::TextureFormat, (w, h): (u32, u32), padded_row: u32, bottom_up: bool) -> Vec<f32> {
    use wgpu::TextureFormat as F;
    let channels = format.components() as usize;
    let size = format.block_copy_size(None).unwrap_or(4) as usize / channels.max(1);
    let mut out = Vec::with_capacity((w * h * 4) as usize);
    for y in 0..h as usize {
        let row = if bottom_up { h as usize - 1 - y } else { y };
        let start = row * padded_row as usize;
        for x in 0..w as usize {
            let mut px = [0.0f32, 0.0, 0.0, 1.0];
            for (c, slot) in px.iter_mut().enumerate().take(channels) {
                let at = start + (x * channels + c) * size;
                let Some(b) = bytes.get(at..at + size) else { continue };
                *slot = match (format, size) {
                    (F::Rgba8Unorm | F::Bgra8Unorm, _) => f32::from(b[0]) / 255.0,
                    (F::Rgba8Snorm, _) => (f32::from(b[0] as i8) / 127.0).max(-1.0),
                    (F::Rgba8Uint, _) => f32::from(b[0]),
                    (F::Rgba8Sint, _) => f32::from(b[0] as i8),
                    (F::Rgba16Float | F::R16Float | F::Rg16Float, _) => half::f16::from_le_bytes([b[0], b[1]]).to_f32(),
                    (F::Rgba16Uint, _) => f32::from(u16::from_le_bytes([b[0], b[1]])),
                    (F::Rgba16Sint, _) => f32::from(i16::from_le_bytes([b[0], b[1]])),
                    (F::Rgba32Sint | F::Rg32Sint | F::R32Sint, _) => i32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f32,
                    (F::Rgba32Uint | F::Rg32Uint | F::R32Uint, _) => u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f32,
                    (_, 4) => f32::from_le_bytes([b[0], b[1], b[2], b[3]]),
                    _ => 0.0,
                };
            }
            if format == F::Bgra8Unorm {
                px.swap(0, 2);
            }
            if channels == 1 && format == F::Depth32Float {
                px = [px[0], px[0], px[0], 1.0];
            }
            out.extend_from_slice(&px);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_decode_to_rgba_floats_top_row_first() {
        // Two rows of one texel each, bottom row first in memory.
        let half = |v: f32| half::f16::from_f32(v).to_le_bytes();
        let bytes: Vec<u8> = [half(0.5), half(1.0), half(0.0), half(0.25), half(2.0), half(0.0), half(0.0), half(1.0)].concat();
        let rgba = decode_rgba(&bytes, wgpu::TextureFormat::Rgba16Float, (1, 2), 8, true);
        assert_eq!(rgba, [2.0, 0.0, 0.0, 1.0, 0.5, 1.0, 0.0, 0.25]);
        let r32: Vec<u8> = 7.5f32.to_le_bytes().to_vec();
        assert_eq!(decode_rgba(&r32, wgpu::TextureFormat::R32Float, (1, 1), 4, false), [7.5, 0.0, 0.0, 1.0]);
        let snorm = [0x81u8, 0x7f, 0, 0x40];
        let d = decode_rgba(&snorm, wgpu::TextureFormat::Rgba8Snorm, (1, 1), 4, false);
        assert_eq!(&d[..3], [-1.0, 1.0, 0.0]);
        let ints: Vec<u8> = [(-3i32).to_le_bytes(), 9i32.to_le_bytes()].concat();
        assert_eq!(decode_rgba(&ints, wgpu::TextureFormat::Rg32Sint, (1, 1), 8, false), [-3.0, 9.0, 0.0, 1.0]);
    }
}
