//! `effectc render --out -`: frames streamed to stdout as PNGs one after another (what
//! `ffmpeg -f image2pipe -i -` reads) or as raw RGBA8 (`--raw`), byte for byte the frames
//! `--out DIR` writes; the report goes to stderr; flags that write files, several programs
//! and `--raw` without `--out -` are usage errors; a reader that closes the pipe early
//! stops the run with exit 2, never a panic.
//!
//! The ffmpeg test needs `ffmpeg` and `ffprobe` (`setup.sh` installs them): outside CI
//! it is skipped with a message when they are missing, in CI it fails.

use std::io::Read;
use std::process::{Command, Output, Stdio};

use crate::common::{code, in_ci, scratch};
use crate::render::have_gpu;

const OBJ: &str = "tests/render/obj/effect.toml";

/// Runs the `effectc` binary without colour, stdout captured as bytes.
fn effectc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_effectc")).args(args).env("NO_COLOR", "1").output().expect("run effectc")
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// True when `tool` runs here; panics in CI when it does not.
fn have_tool(tool: &str) -> bool {
    match Command::new(tool).arg("-version").stdout(Stdio::null()).stderr(Stdio::null()).status() {
        Ok(s) if s.success() => true,
        other => {
            assert!(!in_ci(), "`{tool}` is required in CI (setup.sh installs ffmpeg): {other:?}");
            eprintln!("`{tool}` not installed: the ffmpeg stream test is skipped");
            false
        }
    }
}

/// Splits PNG files written back to back at their `IEND` chunks.
fn split_pngs(mut bytes: &[u8]) -> Vec<&[u8]> {
    const SIGNATURE: &[u8] = b"\x89PNG\r\n\x1a\n";
    let mut pngs = Vec::new();
    while !bytes.is_empty() {
        assert!(bytes.starts_with(SIGNATURE), "a PNG signature at the start of every frame");
        let mut at = SIGNATURE.len();
        loop {
            let len = u32::from_be_bytes(bytes[at..at + 4].try_into().unwrap()) as usize;
            let kind = &bytes[at + 4..at + 8];
            at += 12 + len;
            if kind == b"IEND" {
                break;
            }
        }
        pngs.push(&bytes[..at]);
        bytes = &bytes[at..];
    }
    pngs
}

#[test]
fn png_stream_feeds_ffmpeg_image2pipe() {
    if !have_gpu() || !have_tool("ffmpeg") || !have_tool("ffprobe") {
        return;
    }
    let dir = scratch("stream", "ffmpeg");
    let mkv = dir.join("out.mkv");
    let mut ffmpeg = Command::new("ffmpeg")
        .args(["-v", "error", "-y", "-f", "image2pipe", "-c:v", "png", "-i", "-", "-c:v", "ffv1"])
        .arg(&mkv)
        .stdin(Stdio::piped())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run ffmpeg");
    let pipe = Stdio::from(ffmpeg.stdin.take().unwrap());
    let render = Command::new(env!("CARGO_BIN_EXE_effectc"))
        .args(["render", "effects/sun/effect.toml", "--frames", "6", "--size", "64x64", "--out", "-"])
        .env("NO_COLOR", "1")
        .stdout(pipe)
        .output()
        .expect("run effectc");
    let encoded = ffmpeg.wait_with_output().unwrap();
    assert_eq!(code(&render), 0, "{}", stderr(&render));
    assert!(stderr(&render).contains("rendered sun → stdout: 6 frames at 64x64"), "the report is on stderr: {}", stderr(&render));
    assert!(encoded.status.success(), "ffmpeg: {}", String::from_utf8_lossy(&encoded.stderr));
    let probe = Command::new("ffprobe")
        .args(["-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries", "stream=nb_read_frames", "-of", "csv=p=0"])
        .arg(&mkv)
        .output()
        .unwrap();
    assert!(probe.status.success(), "ffprobe: {}", String::from_utf8_lossy(&probe.stderr));
    assert_eq!(String::from_utf8_lossy(&probe.stdout).trim(), "6", "ffmpeg read every frame");
}

#[test]
fn streamed_pngs_and_raw_frames_are_the_frames_out_dir_writes() {
    if !have_gpu() {
        return;
    }
    let dir = scratch("stream", "same");
    let args = ["render", OBJ, "--frames", "3", "--size", "64x48", "--start", "0.25"];
    let files = effectc(&[&args[..], &["--out", dir.to_str().unwrap()]].concat());
    assert_eq!(code(&files), 0, "{}", String::from_utf8_lossy(&files.stdout));
    let written: Vec<Vec<u8>> = (0..3).map(|i| std::fs::read(dir.join(format!("obj-triangle_{i:04}.png"))).unwrap()).collect();

    let pngs = effectc(&[&args[..], &["--out", "-"]].concat());
    assert_eq!(code(&pngs), 0, "{}", stderr(&pngs));
    assert!(stderr(&pngs).contains("rendered obj-triangle → stdout: 3 frames at 64x48 (PNG stream)"), "{}", stderr(&pngs));
    let streamed = split_pngs(&pngs.stdout);
    assert_eq!(streamed.len(), 3, "three PNGs and nothing else on stdout");
    for (i, (s, w)) in streamed.iter().zip(&written).enumerate() {
        assert!(s == w, "streamed frame {i} differs from the file --out DIR writes");
    }

    let raw = effectc(&[&args[..], &["--out", "-", "--raw"]].concat());
    assert_eq!(code(&raw), 0, "{}", stderr(&raw));
    assert!(stderr(&raw).contains("(raw RGBA8 stream)"), "{}", stderr(&raw));
    let frame_len = 64 * 48 * 4;
    assert_eq!(raw.stdout.len(), 3 * frame_len, "frames × width × height × 4 bytes");
    for (i, png) in written.iter().enumerate() {
        let decoded = image::load_from_memory(png).unwrap().to_rgba8();
        assert_eq!((decoded.width(), decoded.height()), (64, 48));
        assert!(raw.stdout[i * frame_len..][..frame_len] == *decoded.as_raw(), "raw frame {i} differs from its PNG");
    }
}

#[test]
fn stream_misuse_is_a_usage_error() {
    let dir = scratch("stream", "misuse");
    let out_dir = dir.to_str().unwrap();
    let raw_to_dir = effectc(&["render", OBJ, "--raw", "--out", out_dir]);
    assert_eq!(code(&raw_to_dir), 2, "{}", stderr(&raw_to_dir));
    assert!(stderr(&raw_to_dir).contains("--raw"), "{}", stderr(&raw_to_dir));
    let raw_alone = effectc(&["render", OBJ, "--raw"]);
    assert_eq!(code(&raw_alone), 2, "{}", stderr(&raw_alone));
    for flag in ["--contact-sheet", "--gif", "--float", "--dump-targets"] {
        let out = effectc(&["render", OBJ, "--out", "-", flag]);
        assert_eq!(code(&out), 2, "{flag}: {}", stderr(&out));
        assert!(stderr(&out).contains(flag), "{flag} is named: {}", stderr(&out));
        assert!(out.stdout.is_empty(), "{flag}: nothing on stdout");
    }
    assert!(std::fs::read_dir(&dir).unwrap().next().is_none(), "nothing written");
}

#[test]
fn several_programs_cannot_share_the_stream() {
    if !have_gpu() {
        return;
    }
    let out = effectc(&["render", "effects/sun/effect.toml", OBJ, "--out", "-"]);
    let text = stderr(&out);
    assert_eq!(code(&out), 2, "{text}");
    assert!(text.contains("error[E0014]") && text.contains("2 programs"), "{text}");
    assert!(out.stdout.is_empty(), "no frame bytes when the stream is refused");
}

#[test]
fn a_reader_that_stops_early_ends_the_run_without_a_panic() {
    if !have_gpu() {
        return;
    }
    let mut child = Command::new(env!("CARGO_BIN_EXE_effectc"))
        .args(["render", OBJ, "--frames", "2000", "--size", "64x64", "--out", "-", "--raw"])
        .env("NO_COLOR", "1")
        .env("EFFECTC_SHOW_PANICS", "1")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = vec![0u8; 64 * 64 * 4];
    child.stdout.take().unwrap().read_exact(&mut first).unwrap();
    // The read end is dropped here: the next writes fail with a broken pipe.
    let out = child.wait_with_output().unwrap();
    let text = stderr(&out);
    assert_eq!(code(&out), 2, "{text}");
    assert!(!text.contains("panicked"), "{text}");
    assert!(text.contains("error[E0014]") && text.contains("closed"), "{text}");
}

#[test]
fn a_stream_to_a_closed_stdout_is_refused() {
    // `>&-`: the frames would go nowhere (Rust reopens a closed stdout on /dev/null), so
    // the run fails with a message instead of passing; `> /dev/null` is a choice and works.
    let bin = env!("CARGO_BIN_EXE_effectc");
    let run = |redirect: &str| {
        Command::new("sh")
            .arg("-c")
            .arg(format!("'{bin}' render --frames 1 --size 8x8 --out - effects/sun {redirect}"))
            .env("NO_COLOR", "1")
            .output()
            .unwrap()
    };
    let closed = run(">&-");
    assert_eq!(code(&closed), 2, "{}", stderr(&closed));
    assert!(stderr(&closed).contains("stdout, which is closed"), "{}", stderr(&closed));
    if have_gpu() {
        let null = run("> /dev/null");
        assert_eq!(code(&null), 0, "{}", stderr(&null));
    }
}
