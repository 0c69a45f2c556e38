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
            if let Some(px) = packed(bytes.get(start + x * 4..start + x * 4 + 4), format) {
                out.extend_from_slice(&px);
                continue;
            }
            let mut px = [0.0f32, 0.0, 0.0, 1.0];
            for (c, slot) in px.iter_mut().enumerate().take(channels) {
                let at = start + (x * channels + c) * size;
                let Some(b) = bytes.get(at..at + size) else { continue };
                *slot = match (format, size) {
                    (F::Rgba8Unorm | F::Bgra8Unorm | F::R8Unorm | F::Rg8Unorm, _) => f32::from(b[0]) / 255.0,
                    (F::Rgba8Snorm | F::R8Snorm | F::Rg8Snorm, _) => (f32::from(b[0] as i8) / 127.0).max(-1.0),
                    (F::Rgba8Uint | F::R8Uint | F::Rg8Uint, _) => f32::from(b[0]),
                    (F::Rgba8Sint | F::R8Sint | F::Rg8Sint, _) => f32::from(b[0] as i8),
                    (F::Rgba16Float | F::R16Float | F::Rg16Float, _) => half::f16::from_le_bytes([b[0], b[1]]).to_f32(),
                    (F::Rgba16Uint | F::R16Uint | F::Rg16Uint, _) => f32::from(u16::from_le_bytes([b[0], b[1]])),
                    (F::Rgba16Sint | F::R16Sint | F::Rg16Sint, _) => f32::from(i16::from_le_bytes([b[0], b[1]])),
                    (F::Rgba16Unorm | F::R16Unorm | F::Rg16Unorm, _) => f32::from(u16::from_le_bytes([b[0], b[1]])) / 65535.0,
                    (F::Rgba16Snorm | F::R16Snorm | F::Rg16Snorm, _) => (f32::from(i16::from_le_bytes([b[0], b[1]])) / 32767.0).max(-1.0),
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

/// A texel of a packed 32-bit format (`rgb10a2unorm`, `rgb10a2uint`, `rg11b10ufloat`: the
/// channels are bit fields of one little-endian word, red lowest); None for other formats.
fn packed(texel: Option<&[u8]>, format: wgpu::TextureFormat) -> Option<[f32; 4]> {
    use wgpu::TextureFormat as F;
    if !matches!(format, F::Rgb10a2Unorm | F::Rgb10a2Uint | F::Rg11b10Ufloat) {
        return None;
    }
    let t = texel?;
    let word = u32::from_le_bytes([t[0], t[1], t[2], t[3]]);
    let field = |shift: u32, bits: u32| ((word >> shift) & ((1 << bits) - 1)) as f32;
    Some(match format {
        F::Rgb10a2Unorm => [field(0, 10) / 1023.0, field(10, 10) / 1023.0, field(20, 10) / 1023.0, field(30, 2) / 3.0],
        F::Rgb10a2Uint => [field(0, 10), field(10, 10), field(20, 10), field(30, 2)],
        _ => {
            // Unsigned floats without a sign bit: 5 exponent bits over a 6- or 5-bit mantissa,
            // the layout of a half float's upper bits.
            let small = |shift: u32, mantissa: u32| {
                let bits = (word >> shift) & ((1 << (5 + mantissa)) - 1);
                half::f16::from_bits((bits << (10 - mantissa)) as u16).to_f32()
            };
            [small(0, 6), small(11, 6), small(22, 5), 1.0]
        }
    })
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
        // rgb10a2: red 1023 (1.0), green 0, blue 512, alpha 1 of 3.
        let word: u32 = 1023 | (512 << 20) | (1 << 30);
        let d = decode_rgba(&word.to_le_bytes(), wgpu::TextureFormat::Rgb10a2Unorm, (1, 1), 4, false);
        assert_eq!((d[0], d[1], d[3]), (1.0, 0.0, 1.0 / 3.0));
        assert!((d[2] - 512.0 / 1023.0).abs() < 1e-6);
        // rg11b10: 1.0 is exponent 15, mantissa 0 in each field; blue 0.5 is exponent 14.
        let one11 = 15u32 << 6;
        let word = one11 | (one11 << 11) | ((14u32 << 5) << 22);
        assert_eq!(decode_rgba(&word.to_le_bytes(), wgpu::TextureFormat::Rg11b10Ufloat, (1, 1), 4, false), [1.0, 1.0, 0.5, 1.0]);
        let r16 = 32768u16.to_le_bytes();
        let d = decode_rgba(&r16, wgpu::TextureFormat::R16Unorm, (1, 1), 2, false);
        assert!((d[0] - 32768.0 / 65535.0).abs() < 1e-6 && d[1] == 0.0);
    }
}
