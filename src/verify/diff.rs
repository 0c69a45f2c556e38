//! Two RGBA8 frames of one size compared: the largest channel difference, the pixels
//! beyond the tolerance, PSNR, and a heat map (black: equal; blue: within the tolerance;
//! red to yellow: beyond it, brighter the larger the difference). Only the channels the
//! program writes are compared: a `vec2` output leaves blue and alpha undefined in GL.

use serde::Serialize;

/// When two frames count as the same picture.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Tolerance {
    /// Largest channel difference (0–255) a pixel may have and still match.
    pub channel: u8,
    /// Fraction of pixels (0–1) allowed beyond `channel`.
    pub fraction: f64,
}

impl Default for Tolerance {
    /// 2/255 per channel on at most 0.1% of the pixels.
    fn default() -> Self {
        Tolerance { channel: 2, fraction: 0.001 }
    }
}

/// The comparison of one frame.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrameDiff {
    /// Largest difference of any channel of any pixel (0–255).
    pub max_channel: u8,
    /// Pixels whose largest channel difference exceeds the tolerance.
    pub over: u64,
    pub pixels: u64,
    /// Peak signal-to-noise ratio in dB over all channels; `None` when the frames are equal.
    pub psnr: Option<f64>,
    /// Within the tolerance.
    pub matches: bool,
    /// The first pixel beyond the tolerance (x, y from the top left), if any.
    pub first_over: Option<(u32, u32)>,
}

/// Compares the first `channels` (1–4) channels of `a` and `b` (RGBA8, top row first,
/// `w × h`).
pub fn compare(a: &[u8], b: &[u8], (w, h): (u32, u32), tol: Tolerance, channels: usize) -> FrameDiff {
    let channels = channels.clamp(1, 4);
    let pixels = u64::from(w) * u64::from(h);
    let mut max_channel = 0u8;
    let mut over = 0u64;
    let mut squared = 0u64;
    let mut first_over = None;
    for (i, (pa, pb)) in a.chunks_exact(4).zip(b.chunks_exact(4)).enumerate() {
        let mut m = 0u8;
        for c in 0..channels {
            let d = pa[c].abs_diff(pb[c]);
            m = m.max(d);
            squared += u64::from(d) * u64::from(d);
        }
        max_channel = max_channel.max(m);
        if m > tol.channel {
            over += 1;
            if first_over.is_none() {
                first_over = Some((i as u32 % w.max(1), i as u32 / w.max(1)));
            }
        }
    }
    // Frames of different lengths differ everywhere the shorter one ends.
    let compared = (a.len().min(b.len()) / 4) as u64;
    over += pixels.saturating_sub(compared);
    let mse = squared as f64 / (pixels.max(1) * channels as u64) as f64;
    let psnr = (mse > 0.0).then(|| 10.0 * (255.0f64 * 255.0 / mse).log10());
    let matches = (over as f64) <= tol.fraction * pixels as f64 && a.len() == b.len();
    FrameDiff { max_channel, over, pixels, psnr, matches, first_over }
}

/// The heat map of `a` against `b` (RGBA8, the frames' size) over the first `channels`.
pub fn heat_map(a: &[u8], b: &[u8], tol: Tolerance, channels: usize) -> Vec<u8> {
    let channels = channels.clamp(1, 4);
    let mut out = Vec::with_capacity(a.len());
    for (pa, pb) in a.chunks_exact(4).zip(b.chunks_exact(4)) {
        let d = (0..channels).map(|c| pa[c].abs_diff(pb[c])).max().unwrap_or(0);
        let px = match d {
            0 => [0, 0, 0, 255],
            d if d <= tol.channel => [0, 0, 160, 255],
            // 3..=255 → red 128..255, then yellow as the difference grows past 64.
            d => [128u8.saturating_add(d / 2).max(160), (d.saturating_sub(64) as u16 * 4 / 3).min(255) as u8, 0, 255],
        };
        out.extend_from_slice(&px);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equal_frames_match_with_no_psnr() {
        let a = vec![10u8; 16];
        let d = compare(&a, &a, (2, 2), Tolerance::default(), 4);
        assert_eq!((d.max_channel, d.over, d.psnr, d.matches), (0, 0, None, true));
    }

    #[test]
    fn one_pixel_beyond_the_tolerance_of_four_fails_at_zero_fraction() {
        let a = vec![0u8; 16];
        let mut b = a.clone();
        b[4] = 3;
        let d = compare(&a, &b, (2, 2), Tolerance { channel: 2, fraction: 0.0 }, 4);
        assert_eq!((d.max_channel, d.over, d.matches, d.first_over), (3, 1, false, Some((1, 0))));
        assert!(d.psnr.is_some_and(|p| p > 40.0), "{:?}", d.psnr);
        // Within 2/255 everywhere: a match.
        b[4] = 2;
        assert!(compare(&a, &b, (2, 2), Tolerance { channel: 2, fraction: 0.0 }, 4).matches);
        let heat = heat_map(&a, &b, Tolerance::default(), 4);
        assert_eq!(&heat[..8], &[0, 0, 0, 255, 0, 0, 160, 255]);
    }

    #[test]
    fn channels_the_program_does_not_write_are_not_compared() {
        let a = vec![10u8, 20, 30, 40];
        let b = vec![10u8, 20, 255, 0];
        assert!(compare(&a, &b, (1, 1), Tolerance::default(), 2).matches);
        assert!(!compare(&a, &b, (1, 1), Tolerance { channel: 2, fraction: 0.0 }, 3).matches);
        assert_eq!(heat_map(&a, &b, Tolerance::default(), 2), vec![0, 0, 0, 255]);
    }
}
