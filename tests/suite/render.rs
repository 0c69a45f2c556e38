//! `effectc render`: frames are written, deterministic and show what they should; float
//! frames report NaN/Inf; a frame that takes too long stops the run; limits are refused
//! before anything is allocated; OBJ meshes load or fail with a diagnostic at the manifest;
//! generated cube maps and camera keyframes reach the frames.
//!
//! These need a Vulkan adapter (lavapipe in CI). Without one (outside CI) they are skipped
//! with a message; in CI a missing adapter fails.

use std::path::Path;

use effectc::diag::Code;
use effectc::render::compare;

use crate::common::{code, effectc, in_ci, scratch, stdout};

/// True when rendering can run here; panics in CI when it cannot.
pub fn have_gpu() -> bool {
    match effectc::render::device::Gpu::new() {
        Ok(_) => true,
        Err(e) => {
            assert!(!in_ci(), "no wgpu adapter in CI: {e}");
            eprintln!("no wgpu adapter ({e}): render tests skipped");
            false
        }
    }
}

fn png(path: &Path) -> Vec<u8> {
    compare::read_png(path).unwrap_or_else(|e| panic!("{}: {e}", path.display())).0
}

#[test]
fn sun_frames_are_written_deterministic_and_animated() {
    if !have_gpu() {
        return;
    }
    let (a, b) = (scratch("render", "sun-a"), scratch("render", "sun-b"));
    for dir in [&a, &b] {
        let out = effectc(&["render", "effects/sun/effect.toml", "--frames", "3", "--size", "96x96", "--out", dir.to_str().unwrap()]);
        assert_eq!(code(&out), 0, "{}", stdout(&out));
        assert!(stdout(&out).contains("rendered sun"), "{}", stdout(&out));
    }
    let names = ["sun_0000.png", "sun_0001.png", "sun_0002.png"];
    for n in names {
        assert_eq!(std::fs::read(a.join(n)).unwrap(), std::fs::read(b.join(n)).unwrap(), "{n} differs between two runs");
    }
    let frames: Vec<Vec<u8>> = names.iter().map(|n| png(&a.join(n))).collect();
    assert_ne!(frames[0], frames[1], "the sun swirls: frames must differ");
    assert_ne!(frames[1], frames[2]);
    // The sun is orange in the middle and the background black at the corner.
    let px = |f: &[u8], x: usize, y: usize| -> [u8; 4] { f[(y * 96 + x) * 4..][..4].try_into().unwrap() };
    let centre = px(&frames[0], 48, 48);
    assert!(centre[0] > 180 && centre[0] > centre[2] + 100, "orange sun at the centre: {centre:?}");
    assert_eq!(px(&frames[0], 1, 1), [0, 0, 0, 255], "black background");
}

#[test]
fn contact_sheet_and_gif_hold_every_frame() {
    if !have_gpu() {
        return;
    }
    let dir = scratch("render", "sheet");
    let out = effectc(&[
        "render",
        "effects/sun/effect.toml",
        "--frames",
        "5",
        "--size",
        "32x24",
        "--contact-sheet",
        "--gif",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let (_, w, h) = compare::read_png(&dir.join("sun_sheet.png")).unwrap();
    assert!(w >= 3 * 32 && h >= 2 * 24, "5 frames tiled: {w}x{h}");
    let gif = std::fs::read(dir.join("sun.gif")).unwrap();
    assert_eq!(&gif[..6], b"GIF89a");
    let frames = gif.windows(2).filter(|w| w == &[0x21, 0xF9]).count();
    assert_eq!(frames, 5, "one graphic control extension per frame");
}

#[test]
fn float_frames_count_nan_and_inf_and_fail() {
    if !have_gpu() {
        return;
    }
    let dir = scratch("render", "nan");
    let out = effectc(&["render", "tests/render/nan", "--float", "--size", "64x64", "--out", dir.to_str().unwrap()]);
    let text = stdout(&out);
    assert_eq!(code(&out), 1, "{text}");
    assert!(text.contains("error[E0404]"), "{text}");
    // Left half NaN in red: 32 columns × 64 rows; green is +Inf everywhere.
    assert!(text.contains("2048 NaN, 4096 +Inf, 0 -Inf pixels"), "{text}");
    assert!(dir.join("nan_0000_nonfinite.png").is_file(), "a mask is written");
    let mask = png(&dir.join("nan_0000_nonfinite.png"));
    assert_eq!(&mask[..3], &[255, 0, 0], "NaN is red in the mask");

    let clean = effectc(&["render", "effects/sun/effect.toml", "--float", "--size", "32x32", "--out", dir.to_str().unwrap()]);
    assert_eq!(code(&clean), 0, "{}", stdout(&clean));
    assert!(stdout(&clean).contains("0 NaN, 0 +Inf, 0 -Inf pixels"), "{}", stdout(&clean));
}

#[test]
fn a_frame_that_takes_too_long_stops_the_run() {
    if !have_gpu() {
        return;
    }
    let dir = scratch("render", "slow");
    let start = std::time::Instant::now();
    let out = effectc(&["render", "tests/render/slow", "--size", "64x64", "--timeout", "0.2", "--out", dir.to_str().unwrap()]);
    let text = stdout(&out);
    assert_eq!(code(&out), 1, "{text}");
    assert!(text.contains("error[E0403]: frame 0 did not finish within 0.2 s"), "{text}");
    assert!(start.elapsed().as_secs() < 30, "the run ends soon after the timeout");
    assert!(!dir.join("slow_0000.png").exists());
}

#[test]
fn absurd_requests_are_refused_before_allocating() {
    // Flags beyond the limits are usage errors from their value parsers (clap, exit 2);
    // limits that depend on the adapter or on what the run keeps are E0405 (exit 2).
    for (args, needle) in [
        (&["--size", "100000x100000"][..], "outside 1..=8192"),
        (&["--size", "0x64"][..], "outside 1..=8192"),
        (&["--frames", "0"][..], "--frames <FRAMES>"),
        (&["--frames", "10000000"][..], "--frames <FRAMES>"),
        (&["--fps", "0"][..], "not a positive number"),
        (&["--start", "inf"][..], "not a finite number"),
        (&["--timeout", "-1"][..], "not a positive number"),
    ] {
        let mut all = vec!["render", "effects/sun/effect.toml", "--out", "/nonexistent/never-written"];
        all.extend_from_slice(args);
        let out = effectc(&all);
        let err = String::from_utf8_lossy(&out.stderr).into_owned();
        assert_eq!(code(&out), 2, "{args:?}: {err}");
        assert!(err.contains("invalid value") && err.contains(needle), "{args:?}: {err}");
        assert!(stdout(&out).is_empty(), "{args:?}: nothing runs");
    }
    if have_gpu() {
        let args = ["--size", "8192x8192", "--frames", "100", "--contact-sheet"];
        let out = effectc(&[&["render", "effects/sun/effect.toml", "--out", "/nonexistent/never-written"][..], &args].concat());
        let text = stdout(&out);
        assert_eq!(code(&out), 2, "{text}");
        assert!(text.contains(Code::RenderLimit.as_str()) && text.contains("in memory"), "{text}");
    }
    let bad = effectc(&["render", "effects/sun/effect.toml", "--size", "12by3"]);
    assert_eq!(code(&bad), 2, "a malformed size is a usage error");
    for sub in [&["bench", "--repeats", "0"][..], &["stress", "--samples", "10001"][..], &["bench", "--size", "9000x1"][..]] {
        let mut all = sub.to_vec();
        all.push("effects/sun/effect.toml");
        assert_eq!(code(&effectc(&all)), 2, "{sub:?} is a usage error");
    }
}

#[test]
fn obj_meshes_render_and_broken_ones_fail_at_the_manifest() {
    if !have_gpu() {
        return;
    }
    let dir = scratch("render", "obj");
    let out = effectc(&["render", "tests/render/obj/effect.toml", "--verbose", "--out", dir.to_str().unwrap()]);
    let text = stdout(&out);
    assert_eq!(code(&out), 0, "{text}");
    assert!(text.contains("p0 ← position, t0 ← uv"), "explicit attribute mapping: {text}");
    assert!(text.contains("adapter: "), "--verbose names the adapter: {text}");
    let frame = png(&dir.join("obj-triangle_0000.png"));
    let px = |x: usize, y: usize| -> [u8; 4] { frame[(y * 64 + x) * 4..][..4].try_into().unwrap() };
    let inside = px(32, 36);
    assert!(inside[0] == 255 || inside[2] == 255, "the checker is on the triangle: {inside:?}");
    assert_eq!(px(2, 2), [0, 0, 0, 255], "outside the triangle is the clear colour");

    let broken = effectc(&["render", "tests/render/bad-obj/effect.toml", "--out", dir.to_str().unwrap()]);
    let text = stdout(&broken);
    assert_eq!(code(&broken), 1, "{text}");
    assert!(text.contains("error[E0406]: cannot load the mesh"), "{text}");
    assert!(text.contains("tests/render/bad-obj/effect.toml"), "points at the manifest: {text}");
}

#[test]
fn every_rewrite_program_renders_as_bare_stage_files_with_reported_guesses() {
    if !have_gpu() {
        return;
    }
    let mut failures = Vec::new();
    let mut guessed = 0;
    for program in crate::common::fixtures("tests/rewrite", crate::common::REWRITE_FIXTURES) {
        let name = crate::common::name_of(&program);
        let dir = scratch("render-bare", &name);
        let out = effectc(&["render", program.to_str().unwrap(), "--size", "32x32", "--out", dir.to_str().unwrap()]);
        let text = stdout(&out);
        let frames = std::fs::read_dir(&dir).map(|d| d.count()).unwrap_or(0);
        if code(&out) != 0 || frames == 0 {
            failures.push(format!("{name}: exit {}\n{text}", code(&out)));
        }
        if text.contains("warning[W0401]") && text.contains("warning[W0403]") {
            guessed += 1;
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(guessed >= 10, "guessed attributes and uniforms are reported ({guessed} programs)");
}

#[test]
fn a_generated_cube_map_is_reflected_and_camera_keys_move_the_view() {
    if !have_gpu() {
        return;
    }
    let dir = scratch("render", "cube");
    let out = effectc(&["render", "tests/render/cube", "--frames", "3", "--out", dir.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let frames: Vec<Vec<u8>> = (0..3).map(|i| png(&dir.join(format!("cube-envmap_{i:04}.png")))).collect();
    assert_ne!(frames[0], frames[2], "the camera moved between keys");
    // The sphere shows the two checker colours of the cube map (yellow and blue).
    let colours: std::collections::BTreeSet<[u8; 3]> =
        frames[0].chunks(4).filter(|p| p[..3] != [0, 0, 0]).map(|p| [p[0] / 64, p[1] / 64, p[2] / 64]).collect();
    assert!(colours.contains(&[3, 3, 0]) && colours.contains(&[0, 0, 2]), "{colours:?}");
}

#[test]
fn gl_fragcoord_and_dfdy_follow_gl_conventions() {
    if !have_gpu() {
        return;
    }
    let dir = scratch("render", "fragcoord");
    let out = effectc(&["render", "tests/render/fragcoord", "--out", dir.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let frame = png(&dir.join("fragcoord_0000.png"));
    let px = |x: usize, y: usize| -> [u8; 4] { frame[(y * 32 + x) * 4..][..4].try_into().unwrap() };
    // PNG rows run top-down: row 31 is GL's bottom row.
    assert_eq!(px(16, 31), [255, 255, 255, 255], "bottom: gl_FragCoord low, dFdy up, uv low");
    assert_eq!(px(16, 0), [0, 255, 0, 255], "top: gl_FragCoord high, dFdy up, uv high");
}

#[test]
fn a_missing_adapter_is_a_clear_usage_error() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_effectc"))
        .args(["render", "effects/sun/effect.toml", "--out"])
        .arg(scratch("render", "noadapter"))
        .env("EFFECTC_ADAPTER", "no-such-adapter-anywhere")
        .env("NO_COLOR", "1")
        .output()
        .unwrap();
    let text = stdout(&out);
    assert_eq!(code(&out), 2, "{text}");
    assert!(text.contains("error[E0401]") && text.contains("no-such-adapter-anywhere"), "{text}");
}

#[test]
fn depth_compare_lequal_lets_the_skybox_trick_through() {
    if !have_gpu() {
        return;
    }
    // gl_Position = pos.xyww: depth 1.0, equal to the cleared depth. GL_LESS (the
    // default) rejects every fragment; GL_LEQUAL draws the sky.
    let centre = |manifest: &str| {
        let dir = scratch("render", &format!("xyww-{manifest}"));
        let path = format!("tests/render/xyww/{manifest}");
        let out = effectc(&["render", &path, "--size", "32x32", "--out", dir.to_str().unwrap()]);
        assert_eq!(code(&out), 0, "{}", stdout(&out));
        let (pixels, w, h) = compare::read_png(&dir.join("xyww_0000.png")).unwrap();
        let i = (((h / 2) * w + w / 2) * 4) as usize;
        [pixels[i], pixels[i + 1], pixels[i + 2]]
    };
    assert_eq!(centre("effect.toml"), [51, 102, 230], "lequal draws the far-plane quad");
    assert_eq!(centre("less.toml"), [0, 0, 0], "less keeps the clear colour");
}

#[test]
fn a_bad_value_writes_no_frame_and_leaves_existing_ones_untouched() {
    // `--set` values that are no value, or that no f32 holds (nan, inf, 1e39), stop the run
    // before anything is drawn: the frames of an earlier run stay byte for byte.
    if !have_gpu() {
        return;
    }
    let dir = scratch("render", "bad-value");
    let d = dir.to_str().unwrap();
    let out = effectc(&["render", "effects/sun/effect.toml", "--frames", "1", "--size", "32x32", "--out", d]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let before = std::fs::read(dir.join("sun_0000.png")).unwrap();
    for bad in ["minBI=abc", "minBI=nan", "minBI=inf", "minBI=1e39"] {
        let out = effectc(&["render", "effects/sun/effect.toml", "--frames", "1", "--size", "32x32", "--set", bad, "--out", d]);
        assert_eq!(code(&out), 1, "{bad}: {}", stdout(&out));
        assert!(stdout(&out).contains("E0006"), "{bad}: {}", stdout(&out));
        assert_eq!(std::fs::read(dir.join("sun_0000.png")).unwrap(), before, "{bad} rewrote the frame");
    }
}

/// A compute-only program is dispatched over the frame (a size that is no multiple of its
/// workgroup still covers every pixel) and the image it stores to is the frame, its row 0
/// at the bottom as GL shows an image; one that stores to buffers only has nothing to show
/// and says so.
/// A fragment stage that writes `gl_FragDepth`, drawn on the full-screen quad (no depth
/// test): WebGPU refuses such a pipeline without a depth attachment, so the scene has one,
/// and the colour reaches every pixel (the depths, 0.25–0.75, pass the cleared 1.0).
#[test]
fn a_fragment_stage_that_writes_depth_draws() {
    if !have_gpu() {
        return;
    }
    let dir = scratch("render", "frag-depth");
    let out = effectc(&["render", "tests/render/frag_depth", "--size", "20x12", "--out", dir.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let frame = png(&dir.join("depth_0000.png"));
    let px = |x: usize, y: usize| -> [u8; 4] { frame[(y * 20 + x) * 4..][..4].try_into().unwrap() };
    assert!(px(0, 11)[0] < 16 && px(0, 11)[1] < 16 && (126..=129).contains(&px(0, 11)[2]), "bottom left: uv (0, 0), {:?}", px(0, 11));
    assert!(px(19, 0)[0] > 240 && px(19, 0)[1] > 240, "top right: uv (1, 1), {:?}", px(19, 0));
}

#[test]
fn a_compute_program_shows_the_image_it_stores() {
    if !have_gpu() {
        return;
    }
    let dir = scratch("render", "compute");
    let out = effectc(&["render", "tests/render/compute_image", "--size", "20x12", "--out", dir.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let frame = png(&dir.join("gradient_0000.png"));
    let px = |x: usize, y: usize| -> [u8; 4] { frame[(y * 20 + x) * 4..][..4].try_into().unwrap() };
    assert_eq!(px(0, 11), [0, 0, 0, 255], "bottom left: image texel (0, 0)");
    assert_eq!(px(19, 11), [255, 0, 0, 255], "bottom right: red grows to the right");
    assert_eq!(px(0, 0), [0, 255, 0, 255], "top left: green grows upward");
    assert_eq!(px(19, 0), [255, 255, 0, 255], "the last workgroup column and row ran");
}

/// A compute program that stores to a 3D image only shows its slice 0; one storing to an
/// image of a packed format shows it.
#[test]
fn a_compute_program_storing_to_a_3d_or_packed_image_shows_it() {
    if !have_gpu() {
        return;
    }
    let dir = scratch("render", "compute-3d");
    let out = effectc(&["render", "tests/render/compute_image3d", "--size", "16x8", "--out", dir.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let frame = png(&dir.join("volume_0000.png"));
    assert!(frame.chunks(4).all(|px| px == [255, 0, 255, 255]), "every texel of slice 0 is magenta");
    // An image of a format beyond WebGPU's core storage list, stored to where the adapter can
    // (lavapipe can) and read back from its packed bits.
    let out = effectc(&["render", "tests/render/compute_packed", "--size", "16x8", "--out", dir.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let frame = png(&dir.join("packed_0000.png"));
    assert!(frame.chunks(4).all(|px| px == [255, 0, 128, 255]), "rgb10_a2 (1, 0, 0.5, 1): {:?}", &frame[..4]);
}

/// A compute program that stores to no image shows the words of the buffer it stores to,
/// each as the type its place holds, shaded over its kind's range (N0401).
#[test]
fn a_compute_program_storing_to_a_buffer_shows_its_words() {
    if !have_gpu() {
        return;
    }
    let dir = scratch("render", "compute-buffer");
    let out = effectc(&["render", "tests/render/compute_buffer", "--size", "20x12", "--out", dir.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    assert!(stdout(&out).contains(&Code::BufferShown.to_string()) && stdout(&out).contains("buffer `Items`"), "{}", stdout(&out));
    let frame = png(&dir.join("sum_0000.png"));
    // Word n is pixel (n % 20, n / 20); item i is words 2i (float i/2 - 1) and 2i + 1 (int -i).
    let px = |n: usize| -> [u8; 4] { frame[n * 4..][..4].try_into().unwrap() };
    assert_eq!(px(0), [0, 0, 0, 255], "item 0's position, -1.0: the smallest float");
    assert_eq!(px(126), [255, 255, 255, 255], "item 63's position, 30.5: the largest float");
    assert_eq!(px(1), [255, 255, 255, 255], "item 0's index, 0: the largest int");
    assert_eq!(px(127), [0, 0, 0, 255], "item 63's index, -63: the smallest int");
    assert!(px(64)[0].abs_diff(130) <= 1, "item 32's position, 15.0: 16/31.5 of the float range, {:?}", px(64));
    assert!(px(200)[0].abs_diff(8) <= 1, "an item never written, 0.0: 1/31.5 of the range, {:?}", px(200));
}
