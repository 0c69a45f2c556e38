//! Output images: PNG bytes, contact sheets of several frames, looping animated GIFs, and helpers
//! for float framebuffers (display conversion and a NaN/Inf report with a mask image).
//!
//! Frames here are RGBA8 (or f32 RGBA) with rows top-down, as read back from the GPU; PNG and GIF
//! write them top-down. All encoders are deterministic: the same input gives the same bytes.

use image::codecs::gif::{GifEncoder, Repeat};
use image::codecs::png::{CompressionType, FilterType, PngEncoder};
use image::{Delay, ExtendedColorType, Frame, ImageEncoder, RgbaImage};

/// Width of the gutters around and between contact-sheet tiles, in pixels.
pub const GUTTER: u32 = 4;

/// The gutter (and empty-tile) colour of contact sheets.
pub const GUTTER_RGBA: [u8; 4] = [24, 24, 24, 255];

/// NeuQuant speed for GIF palettes (1 = best, 30 = fastest); 10 is the usual balance.
const GIF_QUANTIZER_SPEED: i32 = 10;

/// GIF frames are at most this many pixels on a side.
const GIF_MAX_SIDE: u32 = u16::MAX as u32;

/// Mask colours of [`non_finite`].
pub const NAN_RGBA: [u8; 4] = [255, 0, 0, 255];
pub const POS_INF_RGBA: [u8; 4] = [255, 255, 0, 255];
pub const NEG_INF_RGBA: [u8; 4] = [0, 255, 255, 255];

/// Finite pixels of the mask show their clamped luminance scaled by this, so the markers stand out.
const MASK_DARKEN: f32 = 0.4;

/// The byte length of a `width`×`height` RGBA8 image, `None` on overflow.
fn rgba8_len(width: u32, height: u32) -> Option<usize> {
    (width as usize).checked_mul(height as usize)?.checked_mul(4)
}

/// Checks a frame is a non-empty `width`×`height` RGBA8 image.
fn check_frame(rgba8: &[u8], width: u32, height: u32) -> Result<(), String> {
    if width == 0 || height == 0 {
        return Err(format!("image is {width}×{height}, which is empty"));
    }
    match rgba8_len(width, height) {
        Some(len) if len == rgba8.len() => Ok(()),
        Some(len) => Err(format!("{width}×{height} RGBA8 image needs {len} bytes, got {}", rgba8.len())),
        None => Err(format!("image of {width}×{height} is too large")),
    }
}

/// Encodes a top-down RGBA8 image as PNG (default compression, adaptive filtering). Deterministic.
pub fn png_bytes(rgba8: &[u8], width: u32, height: u32) -> Result<Vec<u8>, String> {
    check_frame(rgba8, width, height)?;
    let mut out = Vec::new();
    PngEncoder::new_with_quality(&mut out, CompressionType::Fast, FilterType::Sub)
        .write_image(rgba8, width, height, ExtendedColorType::Rgba8)
        .map_err(|e| format!("PNG encoding failed: {e}"))?;
    Ok(out)
}

/// Top-down RGBA8 frames of equal size tiled into one image, `columns` per row (0 = about square), 4 px dark gutters.
///
/// Tiles are laid out left to right, then top to bottom, with [`GUTTER`] pixels of [`GUTTER_RGBA`] around
/// and between them; `columns` larger than the frame count is reduced to it. Returns (pixels, width, height),
/// top-down. A frame of the wrong length is left blank (gutter colour); no frames, or a sheet too large to
/// address, gives an empty 0×0 image.
pub fn contact_sheet(frames: &[&[u8]], width: u32, height: u32, columns: u32) -> (Vec<u8>, u32, u32) {
    let Some(layout) = SheetLayout::new(frames.len(), width, height, columns) else {
        return (Vec::new(), 0, 0);
    };
    let mut sheet = GUTTER_RGBA.repeat(layout.width as usize * layout.height as usize);
    let frame_len = rgba8_len(width, height);
    for (index, frame) in frames.iter().enumerate() {
        if Some(frame.len()) == frame_len {
            layout.blit(&mut sheet, index, frame);
        }
    }
    (sheet, layout.width, layout.height)
}

/// Where contact-sheet tiles go.
struct SheetLayout {
    columns: u32,
    tile_width: u32,
    tile_height: u32,
    width: u32,
    height: u32,
}

impl SheetLayout {
    fn new(count: usize, tile_width: u32, tile_height: u32, columns: u32) -> Option<SheetLayout> {
        if count == 0 {
            return None;
        }
        let count = u32::try_from(count).ok()?;
        let columns = if columns == 0 { square_columns(count) } else { columns.min(count) };
        let rows = count.div_ceil(columns);
        let width = sheet_extent(columns, tile_width)?;
        let height = sheet_extent(rows, tile_height)?;
        rgba8_len(width, height)?;
        Some(SheetLayout { columns, tile_width, tile_height, width, height })
    }

    /// Copies frame `index` into its tile.
    fn blit(&self, sheet: &mut [u8], index: usize, frame: &[u8]) {
        let (column, row) = (index as u32 % self.columns, index as u32 / self.columns);
        let left = GUTTER + column * (self.tile_width + GUTTER);
        let top = GUTTER + row * (self.tile_height + GUTTER);
        let row_bytes = self.tile_width as usize * 4;
        for y in 0..self.tile_height as usize {
            let dst_start = ((top as usize + y) * self.width as usize + left as usize) * 4;
            let src_start = y * row_bytes;
            let dst = sheet.get_mut(dst_start..dst_start + row_bytes);
            let src = frame.get(src_start..src_start + row_bytes);
            if let (Some(dst), Some(src)) = (dst, src) {
                dst.copy_from_slice(src);
            }
        }
    }
}

/// The smallest column count whose square holds `count` tiles: ⌈√count⌉.
fn square_columns(count: u32) -> u32 {
    let mut columns = (count as f64).sqrt() as u32;
    while columns.saturating_mul(columns) < count {
        columns += 1;
    }
    columns.max(1)
}

/// `tiles` tiles of `extent` pixels with gutters around and between them, `None` past `u32`.
fn sheet_extent(tiles: u32, extent: u32) -> Option<u32> {
    let pixels = tiles as u64 * extent as u64 + (tiles as u64 + 1) * GUTTER as u64;
    u32::try_from(pixels).ok()
}

/// An animated GIF looping forever, `delay_ms` per frame; deterministic.
///
/// GIF stores delays in hundredths of a second, so `delay_ms` is rounded to the nearest 10 ms (many
/// viewers show delays under 20 ms slower). Each frame gets its own 256-colour palette; alpha is
/// ignored (frames are written opaque) since GIF has no partial transparency. Frames must all be
/// `width`×`height` RGBA8, top-down, at most 65535 pixels on a side.
pub fn gif_bytes(frames: &[&[u8]], width: u32, height: u32, delay_ms: u32) -> Result<Vec<u8>, String> {
    if frames.is_empty() {
        return Err("an animated GIF needs at least one frame".to_string());
    }
    if width > GIF_MAX_SIDE || height > GIF_MAX_SIDE {
        return Err(format!("GIF frames are at most {GIF_MAX_SIDE} pixels on a side, not {width}×{height}"));
    }
    for (index, frame) in frames.iter().enumerate() {
        check_frame(frame, width, height).map_err(|e| format!("GIF frame {index}: {e}"))?;
    }
    let delay = Delay::from_numer_denom_ms(delay_ms.saturating_add(5) / 10 * 10, 1);
    let mut out = Vec::new();
    {
        // The encoder writes the GIF trailer when dropped, at the end of this block.
        let mut encoder = GifEncoder::new_with_speed(&mut out, GIF_QUANTIZER_SPEED);
        encoder.set_repeat(Repeat::Infinite).map_err(|e| format!("GIF encoding failed: {e}"))?;
        for (index, frame) in frames.iter().enumerate() {
            let buffer =
                RgbaImage::from_raw(width, height, opaque(frame)).ok_or_else(|| format!("GIF frame {index} has the wrong size"))?;
            encoder
                .encode_frame(Frame::from_parts(buffer, 0, 0, delay))
                .map_err(|e| format!("GIF encoding of frame {index} failed: {e}"))?;
        }
    }
    Ok(out)
}

/// A copy of an RGBA8 image with every alpha set to 255.
fn opaque(rgba8: &[u8]) -> Vec<u8> {
    let mut out = rgba8.to_vec();
    for pixel in out.chunks_exact_mut(4) {
        pixel[3] = 255;
    }
    out
}

/// Float RGBA (f32 per channel) → RGBA8 for display: clamp to `[0, 1]`; NaN → 0.
///
/// Each channel becomes `round(clamp(c, 0, 1) * 255)` with no sRGB encoding (matching the
/// `Rgba8Unorm` textures); the output has one byte per input float.
pub fn float_to_rgba8(rgba32f: &[f32]) -> Vec<u8> {
    rgba32f.iter().map(|&c| unit_to_byte(c)).collect()
}

/// RGBA8 of an integer frame (an `ivec4`/`uvec4` colour output, as RGBA floats): each
/// colour channel its value clamped to 0–255, opaque (an integer output's alpha is data, not
/// coverage).
pub fn integers_to_rgba8(rgba: &[f32]) -> Vec<u8> {
    rgba.chunks_exact(4).flat_map(|p| [p[0], p[1], p[2]].map(|v| v.clamp(0.0, 255.0) as u8).into_iter().chain([255])).collect()
}

fn unit_to_byte(c: f32) -> u8 {
    if c.is_nan() {
        return 0;
    }
    // round() of a non-negative value, as floor(x + 0.5) in f64 (exact, and cheaper than `f32::round`).
    (f64::from(c.clamp(0.0, 1.0) * 255.0) + 0.5) as u8
}

/// Pixel counts of non-finite values (a pixel counts once per category if any channel is it).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct NonFinite {
    pub nan: u64,
    pub pos_inf: u64,
    pub neg_inf: u64,
}

impl NonFinite {
    /// Whether any pixel has a NaN or infinite channel.
    pub fn any(&self) -> bool {
        self.nan + self.pos_inf + self.neg_inf > 0
    }
}

/// Which non-finite categories one pixel falls in.
#[derive(Clone, Copy)]
struct PixelFlags {
    nan: bool,
    pos_inf: bool,
    neg_inf: bool,
}

impl PixelFlags {
    fn of(pixel: &[f32]) -> PixelFlags {
        PixelFlags {
            nan: pixel.iter().any(|c| c.is_nan()),
            pos_inf: pixel.contains(&f32::INFINITY),
            neg_inf: pixel.contains(&f32::NEG_INFINITY),
        }
    }
}

/// Counts and, when any are found, a mask image: NaN red, +Inf yellow, −Inf cyan, other pixels the darkened grey of their clamped luminance.
///
/// The input is top-down f32 RGBA; the mask is top-down RGBA8 of the same size. A pixel in several
/// categories is marked by the first of NaN, +Inf, −Inf. Luminance is Rec. 709
/// (0.2126 r + 0.7152 g + 0.0722 b) of the channels clamped to [0, 1], times 0.4. The mask is `None`
/// when nothing non-finite is found or when the buffer is not `width * height * 4` floats (counts
/// are still made over the whole pixels present).
pub fn non_finite(rgba32f: &[f32], width: u32, height: u32) -> (NonFinite, Option<Vec<u8>>) {
    let mut counts = NonFinite::default();
    for pixel in rgba32f.chunks_exact(4) {
        let flags = PixelFlags::of(pixel);
        counts.nan += flags.nan as u64;
        counts.pos_inf += flags.pos_inf as u64;
        counts.neg_inf += flags.neg_inf as u64;
    }
    let sized = rgba8_len(width, height) == Some(rgba32f.len());
    let mask = (counts.any() && sized).then(|| rgba32f.chunks_exact(4).flat_map(mask_pixel).collect());
    (counts, mask)
}

fn mask_pixel(pixel: &[f32]) -> [u8; 4] {
    let flags = PixelFlags::of(pixel);
    if flags.nan {
        NAN_RGBA
    } else if flags.pos_inf {
        POS_INF_RGBA
    } else if flags.neg_inf {
        NEG_INF_RGBA
    } else {
        let channel = |i: usize| pixel.get(i).map_or(0.0, |c| c.clamp(0.0, 1.0));
        let luminance = 0.2126 * channel(0) + 0.7152 * channel(1) + 0.0722 * channel(2);
        let grey = unit_to_byte(luminance * MASK_DARKEN);
        [grey, grey, grey, 255]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use image::codecs::gif::GifDecoder;
    use image::AnimationDecoder;
    use std::io::Cursor;

    /// A `width`×`height` image where pixel (x, y) is (x * 40, y * 40, 7, 255 - x).
    fn pattern(width: u32, height: u32) -> Vec<u8> {
        let mut out = Vec::new();
        for y in 0..height {
            for x in 0..width {
                out.extend_from_slice(&[(x * 40) as u8, (y * 40) as u8, 7, 255 - x as u8]);
            }
        }
        out
    }

    fn pixel(image: &[u8], width: u32, x: u32, y: u32) -> [u8; 4] {
        let i = ((y * width + x) * 4) as usize;
        [image[i], image[i + 1], image[i + 2], image[i + 3]]
    }

    #[test]
    fn png_is_deterministic_and_round_trips_top_down() {
        let image = pattern(5, 3);
        let first = png_bytes(&image, 5, 3).expect("encode");
        assert_eq!(first, png_bytes(&image, 5, 3).expect("encode"));
        let decoded = image::load_from_memory(&first).expect("decode").to_rgba8();
        assert_eq!(decoded.dimensions(), (5, 3));
        assert_eq!(decoded.into_raw(), image);
    }

    #[test]
    fn png_rejects_bad_sizes() {
        assert!(png_bytes(&[0; 15], 2, 2).is_err());
        assert!(png_bytes(&[], 0, 0).is_err());
        assert!(png_bytes(&[0; 4], u32::MAX, u32::MAX).is_err());
    }

    #[test]
    fn contact_sheet_dimensions_and_placement() {
        let colours = [[255, 0, 0, 255], [0, 255, 0, 255], [0, 0, 255, 255]];
        let frames: Vec<Vec<u8>> = colours.iter().map(|c| c.repeat(2 * 3)).collect();
        let refs: Vec<&[u8]> = frames.iter().map(Vec::as_slice).collect();

        // Three 2×3 frames, about square: 2 columns, 2 rows.
        let (sheet, width, height) = contact_sheet(&refs, 2, 3, 0);
        assert_eq!((width, height), (2 * 2 + 3 * GUTTER, 2 * 3 + 3 * GUTTER));
        assert_eq!(sheet.len(), (width * height * 4) as usize);
        assert_eq!(pixel(&sheet, width, 0, 0), GUTTER_RGBA);
        assert_eq!(pixel(&sheet, width, 4, 4), colours[0]);
        assert_eq!(pixel(&sheet, width, 5, 6), colours[0]);
        assert_eq!(pixel(&sheet, width, 6, 4), GUTTER_RGBA);
        assert_eq!(pixel(&sheet, width, 10, 4), colours[1]);
        assert_eq!(pixel(&sheet, width, 4, 11), colours[2]);
        assert_eq!(pixel(&sheet, width, 10, 11), GUTTER_RGBA, "the fourth slot is empty");

        // One row, and columns capped at the frame count.
        let (_, width, height) = contact_sheet(&refs, 2, 3, 3);
        assert_eq!((width, height), (3 * 2 + 4 * GUTTER, 3 + 2 * GUTTER));
        assert_eq!(contact_sheet(&refs, 2, 3, 10).1, width);
        // One column.
        let (sheet, width, height) = contact_sheet(&refs, 2, 3, 1);
        assert_eq!((width, height), (2 + 2 * GUTTER, 3 * 3 + 4 * GUTTER));
        assert_eq!(pixel(&sheet, width, 4, 4 + 2 * (3 + GUTTER)), colours[2]);
    }

    #[test]
    fn contact_sheet_keeps_frame_rows_in_order() {
        let frame = pattern(3, 2);
        let (sheet, width, _) = contact_sheet(&[&frame], 3, 2, 0);
        for y in 0..2 {
            for x in 0..3 {
                assert_eq!(pixel(&sheet, width, GUTTER + x, GUTTER + y), pixel(&frame, 3, x, y));
            }
        }
    }

    #[test]
    fn contact_sheet_tolerates_bad_input() {
        assert_eq!(contact_sheet(&[], 4, 4, 0), (Vec::new(), 0, 0));
        let good = [9u8; 16];
        let short = [9u8; 5];
        let (sheet, width, height) = contact_sheet(&[&good, &short], 2, 2, 0);
        assert_eq!((width, height), (2 * 2 + 3 * GUTTER, 2 + 2 * GUTTER));
        assert_eq!(pixel(&sheet, width, 4, 4), [9; 4]);
        assert_eq!(pixel(&sheet, width, 10, 4), GUTTER_RGBA);
        assert_eq!(contact_sheet(&[&good], u32::MAX, u32::MAX, 0), (Vec::new(), 0, 0));
    }

    #[test]
    fn gif_decodes_with_all_frames_and_loops() {
        let colours = [[255, 0, 0, 255], [0, 255, 0, 128], [0, 0, 255, 0]];
        let frames: Vec<Vec<u8>> = colours.iter().map(|c| c.repeat(4 * 4)).collect();
        let refs: Vec<&[u8]> = frames.iter().map(Vec::as_slice).collect();
        let bytes = gif_bytes(&refs, 4, 4, 100).expect("encode");
        assert_eq!(bytes, gif_bytes(&refs, 4, 4, 100).expect("encode"), "deterministic");
        assert!(bytes.windows(11).any(|w| w == b"NETSCAPE2.0"), "has a loop extension");

        let decoded = GifDecoder::new(Cursor::new(&bytes)).expect("decoder").into_frames().collect_frames();
        let decoded = decoded.expect("frames");
        assert_eq!(decoded.len(), 3);
        for (frame, colour) in decoded.iter().zip(colours) {
            assert_eq!(frame.buffer().dimensions(), (4, 4));
            assert_eq!(frame.delay().numer_denom_ms(), (100, 1));
            let got = frame.buffer().get_pixel(1, 2).0;
            assert_eq!(&got[..3], &colour[..3]);
            assert_eq!(got[3], 255, "written opaque");
        }
    }

    #[test]
    fn gif_rejects_bad_input() {
        assert!(gif_bytes(&[], 4, 4, 100).is_err());
        let frame = [0u8; 64];
        assert!(gif_bytes(&[&frame, &frame[..60]], 4, 4, 100).is_err());
        assert!(gif_bytes(&[&frame], 0, 0, 100).is_err());
        assert!(gif_bytes(&[&frame], 70_000, 1, 100).is_err());
    }

    #[test]
    fn floats_clamp_for_display() {
        let floats = [0.0, 0.5, 1.0, 2.0, -1.0, f32::NAN, f32::INFINITY, f32::NEG_INFINITY];
        assert_eq!(float_to_rgba8(&floats), vec![0, 128, 255, 255, 0, 0, 255, 0]);
    }

    #[test]
    fn non_finite_counts_and_mask() {
        let nan = f32::NAN;
        let inf = f32::INFINITY;
        #[rustfmt::skip]
        let pixels = [
            1.0, 1.0, 1.0, 1.0,    // white
            0.0, nan, 0.0, 1.0,    // NaN
            inf, 0.0, 0.0, 1.0,    // +Inf
            0.0, 0.0, 0.0, -inf,   // −Inf (alpha counts too)
            nan, inf, inf, 1.0,    // NaN and +Inf: counted in both, marked NaN
            2.0, -3.0, 0.0, 1.0,   // out of range but finite
        ];
        let (counts, mask) = non_finite(&pixels, 3, 2);
        assert_eq!(counts, NonFinite { nan: 2, pos_inf: 2, neg_inf: 1 });
        let mask = mask.expect("mask");
        assert_eq!(mask.len(), 3 * 2 * 4);
        let white_grey = (0.4f32 * 255.0).round() as u8;
        assert_eq!(pixel(&mask, 3, 0, 0), [white_grey, white_grey, white_grey, 255]);
        assert_eq!(pixel(&mask, 3, 1, 0), NAN_RGBA);
        assert_eq!(pixel(&mask, 3, 2, 0), POS_INF_RGBA);
        assert_eq!(pixel(&mask, 3, 0, 1), NEG_INF_RGBA);
        assert_eq!(pixel(&mask, 3, 1, 1), NAN_RGBA);
        let red_grey = (0.2126f32 * 0.4 * 255.0).round() as u8;
        assert_eq!(pixel(&mask, 3, 2, 1), [red_grey, red_grey, red_grey, 255]);
    }

    #[test]
    fn non_finite_without_problems_or_with_wrong_size() {
        let (counts, mask) = non_finite(&[0.5; 16], 2, 2);
        assert_eq!((counts, mask), (NonFinite::default(), None));
        let (counts, mask) = non_finite(&[f32::NAN; 10], 2, 2);
        assert_eq!((counts.nan, mask), (2, None));
    }
}
