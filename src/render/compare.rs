//! Pixel comparison for reference-image tests: per-channel tolerance, a pass fraction, summary
//! statistics and a difference image, plus reading reference PNGs.
//!
//! Images are top-down RGBA8. Sizes are checked with [`compare_sized`] or [`size_mismatch`];
//! [`compare`] itself never panics on mismatched buffers (it fails the test instead).

use std::fmt;
use std::path::Path;

/// The tolerance of a pixel test: a pixel differs when any channel differs by more than
/// `channel` (0–255); the test passes when at most `max_differing` (fraction 0–1) of pixels differ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerance {
    pub channel: u8,
    pub max_differing: f64,
}

impl Tolerance {
    /// Every pixel must match exactly.
    pub const EXACT: Tolerance = Tolerance { channel: 0, max_differing: 0.0 };
}

/// The outcome of [`compare`].
#[derive(Clone, PartialEq)]
pub struct Comparison {
    /// Pixels with a channel difference beyond the tolerance.
    pub differing: u64,
    /// Pixels compared (`width * height`).
    pub total: u64,
    /// The largest difference of any channel (alpha included) of any pixel.
    pub max_channel_diff: u8,
    /// The mean absolute difference over all channels of all pixels.
    pub mean_abs_diff: f64,
    /// Whether `differing <= max_differing * total` (and the buffers had the stated size).
    pub passed: bool,
    /// Top-down RGBA8 image, opaque: black where equal; red, brighter with the largest channel
    /// difference (64 at a difference of 1 up to 255 at the tolerance), where within tolerance;
    /// bright magenta (255, 0, 255) where beyond it.
    pub difference: Vec<u8>,
}

impl fmt::Debug for Comparison {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Comparison")
            .field("differing", &self.differing)
            .field("total", &self.total)
            .field("max_channel_diff", &self.max_channel_diff)
            .field("mean_abs_diff", &self.mean_abs_diff)
            .field("passed", &self.passed)
            .field("difference_bytes", &self.difference.len())
            .finish()
    }
}

/// Difference-image colours.
pub const EQUAL_RGBA: [u8; 4] = [0, 0, 0, 255];
pub const BEYOND_RGBA: [u8; 4] = [255, 0, 255, 255];

/// Red of a pixel whose largest difference is the smallest non-zero one.
const WITHIN_RED_MIN: u32 = 64;

/// Compares two top-down RGBA8 images of `width`×`height`.
///
/// Neither buffer should differ from `width * height * 4` bytes (see [`size_mismatch`]); if one does,
/// pixels missing from either buffer count as differing by 255 in every channel, and the test fails.
pub fn compare(reference: &[u8], actual: &[u8], width: u32, height: u32, tol: Tolerance) -> Comparison {
    let total = width as u64 * height as u64;
    let mut differing = 0u64;
    let mut max_channel_diff = 0u8;
    let mut diff_sum = 0u64;
    let mut difference = Vec::with_capacity(usize::try_from(total.saturating_mul(4)).unwrap_or(0));
    for index in 0..total {
        let diff = pixel_difference(pixel(reference, index), pixel(actual, index));
        let largest = diff.iter().copied().max().unwrap_or(0);
        max_channel_diff = max_channel_diff.max(largest);
        diff_sum += diff.iter().map(|&d| d as u64).sum::<u64>();
        if largest > tol.channel {
            differing += 1;
        }
        difference.extend_from_slice(&difference_colour(largest, tol.channel));
    }
    let channels = total * 4;
    let mean_abs_diff = if channels == 0 { 0.0 } else { diff_sum as f64 / channels as f64 };
    let sized = size_mismatch(reference, actual, width, height).is_none();
    let passed = sized && differing as f64 <= tol.max_differing * total as f64;
    Comparison { differing, total, max_channel_diff, mean_abs_diff, passed, difference }
}

/// [`compare`] for images of possibly different sizes: `Err` describing the mismatch when the sizes
/// differ or a buffer does not hold its stated size.
pub fn compare_sized(
    reference: &[u8],
    reference_size: (u32, u32),
    actual: &[u8],
    actual_size: (u32, u32),
    tol: Tolerance,
) -> Result<Comparison, String> {
    let ((rw, rh), (aw, ah)) = (reference_size, actual_size);
    if reference_size != actual_size {
        return Err(format!("image size differs: reference is {rw}×{rh}, actual is {aw}×{ah}"));
    }
    if let Some(problem) = size_mismatch(reference, actual, rw, rh) {
        return Err(problem);
    }
    Ok(compare(reference, actual, rw, rh, tol))
}

/// Describes how either buffer fails to be a `width`×`height` RGBA8 image, or `None` when both are.
pub fn size_mismatch(reference: &[u8], actual: &[u8], width: u32, height: u32) -> Option<String> {
    let expected = (width as u64 * height as u64).checked_mul(4);
    let describe = |name: &str, len: usize| match expected {
        Some(expected) if expected == len as u64 => None,
        Some(expected) => Some(format!("{name} has {len} bytes, a {width}×{height} RGBA8 image has {expected}")),
        None => Some(format!("{width}×{height} is too large")),
    };
    describe("reference", reference.len()).or_else(|| describe("actual", actual.len()))
}

/// Pixel `index` of an RGBA8 buffer, `None` past its end.
fn pixel(rgba8: &[u8], index: u64) -> Option<&[u8]> {
    let start = usize::try_from(index.checked_mul(4)?).ok()?;
    rgba8.get(start..start.checked_add(4)?)
}

/// Per-channel absolute differences; a missing pixel differs by 255 everywhere.
fn pixel_difference(reference: Option<&[u8]>, actual: Option<&[u8]>) -> [u8; 4] {
    match (reference, actual) {
        (Some(r), Some(a)) => std::array::from_fn(|i| r[i].abs_diff(a[i])),
        _ => [255; 4],
    }
}

fn difference_colour(largest: u8, channel_tolerance: u8) -> [u8; 4] {
    if largest == 0 {
        EQUAL_RGBA
    } else if largest <= channel_tolerance {
        let span = 255 - WITHIN_RED_MIN;
        let steps = (channel_tolerance as u32).saturating_sub(1).max(1);
        let red = WITHIN_RED_MIN + (largest as u32 - 1) * span / steps;
        [red.min(255) as u8, 0, 0, 255]
    } else {
        BEYOND_RGBA
    }
}

/// Reads an image file (PNG or any other format the `image` crate was built with) as top-down
/// RGBA8: (bytes, width, height). Errors name the path.
pub fn read_png(path: &Path) -> Result<(Vec<u8>, u32, u32), String> {
    crate::assets::texture::decode_rgba8(path)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn image(width: u32, height: u32) -> Vec<u8> {
        (0..width * height * 4).map(|i| (i * 7 % 256) as u8).collect()
    }

    fn pixel_at(image: &[u8], width: u32, x: u32, y: u32) -> [u8; 4] {
        let i = ((y * width + x) * 4) as usize;
        [image[i], image[i + 1], image[i + 2], image[i + 3]]
    }

    const LOOSE: Tolerance = Tolerance { channel: 2, max_differing: 0.0 };

    #[test]
    fn identical_images_pass() {
        let reference = image(4, 4);
        let result = compare(&reference, &reference, 4, 4, Tolerance::EXACT);
        assert!(result.passed);
        assert_eq!((result.differing, result.total, result.max_channel_diff), (0, 16, 0));
        assert_eq!(result.mean_abs_diff, 0.0);
        assert_eq!(result.difference, EQUAL_RGBA.repeat(16));
    }

    #[test]
    fn one_pixel_off_by_one_is_within_tolerance() {
        let reference = image(4, 4);
        let mut actual = reference.clone();
        let i = ((2 * 4 + 1) * 4) as usize; // pixel (1, 2)
        actual[i + 1] = actual[i + 1].wrapping_add(1);
        let result = compare(&reference, &actual, 4, 4, LOOSE);
        assert!(result.passed);
        assert_eq!((result.differing, result.max_channel_diff), (0, 1));
        assert!((result.mean_abs_diff - 1.0 / 64.0).abs() < 1e-12);
        let marked = pixel_at(&result.difference, 4, 1, 2);
        assert_eq!(marked, [WITHIN_RED_MIN as u8, 0, 0, 255]);
        assert_eq!(pixel_at(&result.difference, 4, 0, 0), EQUAL_RGBA);
        // The same pixel fails an exact test.
        let exact = compare(&reference, &actual, 4, 4, Tolerance::EXACT);
        assert!(!exact.passed);
        assert_eq!(pixel_at(&exact.difference, 4, 1, 2), BEYOND_RGBA);
    }

    #[test]
    fn beyond_tolerance_fails_and_is_marked() {
        let reference = image(4, 4);
        let mut actual = reference.clone();
        let i = ((3 * 4 + 2) * 4) as usize; // pixel (2, 3)
        actual[i] = actual[i].wrapping_add(50);
        let result = compare(&reference, &actual, 4, 4, LOOSE);
        assert!(!result.passed);
        assert_eq!((result.differing, result.max_channel_diff), (1, 50));
        assert_eq!(pixel_at(&result.difference, 4, 2, 3), BEYOND_RGBA);
        let marked = result.difference.chunks_exact(4).filter(|p| *p != EQUAL_RGBA).count();
        assert_eq!(marked, 1);
        // One pixel of sixteen is 6.25 %: allowed by a 10 % budget, not by 5 %.
        let budget = |max_differing| Tolerance { channel: 2, max_differing };
        assert!(compare(&reference, &actual, 4, 4, budget(0.1)).passed);
        assert!(!compare(&reference, &actual, 4, 4, budget(0.05)).passed);
        assert!(!compare(&reference, &actual, 4, 4, budget(f64::NAN)).passed);
    }

    #[test]
    fn within_tolerance_red_scales_with_difference() {
        let tol = Tolerance { channel: 10, max_differing: 0.0 };
        assert_eq!(difference_colour(1, 10), [64, 0, 0, 255]);
        assert_eq!(difference_colour(10, 10), [255, 0, 0, 255]);
        assert!(difference_colour(5, 10)[0] > 64 && difference_colour(5, 10)[0] < 255);
        assert_eq!(difference_colour(11, 10), BEYOND_RGBA);
        assert_eq!(difference_colour(1, 1), [64, 0, 0, 255]);
        assert_eq!(difference_colour(255, 255), [255, 0, 0, 255]);
        assert!(compare(&[0, 0, 0, 0], &[10, 0, 0, 0], 1, 1, tol).passed);
    }

    #[test]
    fn size_mismatch_is_detected_without_panicking() {
        let reference = image(4, 4);
        let short = image(4, 3);
        let result = compare(&reference, &short, 4, 4, Tolerance { channel: 255, max_differing: 1.0 });
        assert!(!result.passed);
        assert_eq!(result.differing, 0, "a 255 channel tolerance accepts anything present");
        assert_eq!(result.difference.len(), 64);
        let result = compare(&reference, &short, 4, 4, LOOSE);
        assert_eq!(result.differing, 4);
        assert_eq!(pixel_at(&result.difference, 4, 3, 3), BEYOND_RGBA);

        assert!(size_mismatch(&reference, &reference, 4, 4).is_none());
        let problem = size_mismatch(&reference, &short, 4, 4).expect("mismatch");
        assert!(problem.contains("actual"), "{problem}");
        assert!(size_mismatch(&reference, &reference, u32::MAX, u32::MAX).is_some());

        let err = compare_sized(&reference, (4, 4), &image(2, 8), (2, 8), LOOSE).expect_err("sizes differ");
        assert!(err.contains("4×4") && err.contains("2×8"), "{err}");
        assert!(compare_sized(&reference, (4, 4), &short, (4, 4), LOOSE).is_err());
        assert!(compare_sized(&reference, (4, 4), &reference, (4, 4), LOOSE).expect("same size").passed);
        assert!(compare(&[], &[], 0, 0, Tolerance::EXACT).passed);
    }

    #[test]
    fn read_png_is_top_down() {
        let dir = std::env::temp_dir().join(format!("effectc-compare-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temp dir");
        let path = dir.join("reference.png");
        let pixels = image(3, 2);
        let bytes = super::super::encode::png_bytes(&pixels, 3, 2).expect("encode");
        std::fs::write(&path, bytes).expect("write");
        let read = read_png(&path);
        let missing = read_png(&dir.join("missing.png"));
        let _ = std::fs::remove_dir_all(&dir);
        assert_eq!(read.expect("read"), (pixels, 3, 2));
        let err = missing.expect_err("missing");
        assert!(err.contains("missing.png"), "{err}");
    }
}
