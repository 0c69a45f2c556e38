//! `effectc stress`: seed hazards found by rendering at the ends of the ranges, reported at
//! the manifest's `range` with the culprit expression located in the fragment stage; the
//! shipped effects come out clean.

use crate::common::{code, effectc, scratch, stdout};
use crate::render::have_gpu;

#[test]
fn seed_hazards_are_found_at_the_end_of_their_range() {
    if !have_gpu() {
        return;
    }
    let dir = scratch("stress", "seeds");
    let out = effectc(&["stress", "tests/stress", "--samples", "2", "--out", dir.to_str().unwrap()]);
    let text = stdout(&out);
    assert_eq!(code(&out), 1, "{text}");
    // Seed 003's blur curve divides by (bloomRange - 1): every pixel NaN at bloomRange = 1.
    assert!(text.contains("error[E0701]: bloom-curve: case `bloomRange low` renders 16384 NaN and 0 Inf pixels"), "{text}");
    assert!(text.contains("bloom-curve/effect.toml:9:35"), "at the range [1, 33]:\n{text}");
    assert!(text.contains("`bloomRange` = 1 in this range"), "{text}");
    // The culprit: the instrumented fragment stage names the division by (ranger - 1), the
    // first non-finite value in every pixel, at its span in blur.frag.
    assert!(text.contains("bloom-curve/blur.frag:20:58"), "{text}");
    assert!(text.contains("the first non-finite value (division) in 16384 of 16384 pixels"), "{text}");
    // Seed 003's asin latitude: NaN where |z| > 1, only at the high end.
    assert!(text.contains("error[E0701]: asin-latitude: case `radiusScale high`"), "{text}");
    assert!(!text.contains("case `radiusScale low`"), "{text}");
    assert!(dir.join("bloom-curve_bloomRange_low_nonfinite.png").is_file());
    // The nominal frames are clean: the hazards are at the edges only.
    assert!(text.contains("nominal                   0        0"), "{text}");
}

#[test]
fn shipped_effects_are_clean_under_stress() {
    if !have_gpu() {
        return;
    }
    let dir = scratch("stress", "effects");
    let out = effectc(&["stress", "effects", "--samples", "2", "--size", "64x64", "--out", dir.to_str().unwrap()]);
    let text = stdout(&out);
    assert_eq!(code(&out), 0, "{text}");
    assert_eq!(text.matches(": no NaN or Inf").count(), 20, "{text}");
    // No intermediate value is non-finite either (W0702 would say where).
    assert!(!text.contains("W0702"), "{text}");
}
