//! Pixel snapshots: every effect under `effects/` is rendered and compared with its
//! reference frames `snapshots/png/<effect>_<NNNN>.png`.
//!
//! Tolerance (stated, per test): a pixel differs when any channel differs by more than
//! [`TOLERANCE`]`.channel` (of 255); the frame passes when at most `max_differing` of its
//! pixels differ. This absorbs rounding differences between lavapipe/LLVM versions while a
//! wrong texture, colour, transform or time step fails.
//!
//! A missing reference fails. On failure `<frame>-actual.png` and `<frame>-difference.png`
//! are written next to the reference (git-ignored). `EFFECTC_UPDATE_PNG=1 cargo test pixels`
//! rewrites the references (never set in CI).

use std::path::{Path, PathBuf};

use effectc::render::compare::{self, Tolerance};

use crate::common::{code, effectc, fixtures, in_ci, name_of, scratch, stdout};
use crate::render::have_gpu;

/// Per-channel difference allowed, and the share of pixels that may exceed it.
pub const TOLERANCE: Tolerance = Tolerance { channel: 8, max_differing: 0.005 };
/// Reference frame size (small: the suite renders every effect).
pub const SIZE: &str = "128x128";
/// Frames rendered per effect; the first and the last are compared.
pub const FRAMES: u32 = 4;

fn updating() -> bool {
    let update = std::env::var("EFFECTC_UPDATE_PNG").is_ok_and(|v| v == "1");
    assert!(!(update && in_ci()), "EFFECTC_UPDATE_PNG must not be set in CI");
    update
}

#[test]
fn every_effect_matches_its_reference_frames() {
    if !have_gpu() {
        return;
    }
    let references = Path::new("snapshots/png");
    std::fs::create_dir_all(references).unwrap();
    let mut failures = Vec::new();
    for effect in fixtures("effects", 21) {
        let name = name_of(&effect);
        let out_dir = scratch("pixels", &name);
        let manifest = effect.join("effect.toml");
        let frames = FRAMES.to_string();
        let out = effectc(&["render", manifest.to_str().unwrap(), "--frames", &frames, "--size", SIZE, "--out", out_dir.to_str().unwrap()]);
        if code(&out) != 0 {
            failures.push(format!("{name}: render failed\n{}", stdout(&out)));
            continue;
        }
        for index in [0, FRAMES - 1] {
            let frame = format!("{name}_{index:04}");
            if let Err(e) = check_frame(&out_dir.join(format!("{frame}.png")), &references.join(format!("{frame}.png"))) {
                failures.push(format!("{frame}: {e}"));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Compares `actual` with `reference` (or rewrites the reference in update mode).
fn check_frame(actual: &Path, reference: &Path) -> Result<(), String> {
    if updating() {
        std::fs::copy(actual, reference).map_err(|e| e.to_string())?;
        return Ok(());
    }
    if !reference.is_file() {
        return Err(format!(
            "no reference frame {} (run `EFFECTC_UPDATE_PNG=1 cargo test pixels` and review the new PNGs)",
            reference.display()
        ));
    }
    let (want, ww, wh) = compare::read_png(reference)?;
    let (got, gw, gh) = compare::read_png(actual)?;
    let result = compare::compare_sized(&want, (ww, wh), &got, (gw, gh), TOLERANCE)?;
    if result.passed {
        return Ok(());
    }
    let stem = reference.with_extension("");
    let sibling = |suffix: &str| PathBuf::from(format!("{}-{suffix}.png", stem.display()));
    std::fs::copy(actual, sibling("actual")).map_err(|e| e.to_string())?;
    let diff = effectc::render::encode::png_bytes(&result.difference, ww, wh)?;
    std::fs::write(sibling("difference"), diff).map_err(|e| e.to_string())?;
    Err(format!(
        "{} of {} pixels differ by more than {} (max channel difference {}, mean {:.3}); see {} and {}",
        result.differing,
        result.total,
        TOLERANCE.channel,
        result.max_channel_diff,
        result.mean_abs_diff,
        sibling("actual").display(),
        sibling("difference").display()
    ))
}
