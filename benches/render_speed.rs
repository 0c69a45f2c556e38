//! Benchmark: `effectc render` against a bare wgpu loop, in one process.
//!
//! For each program: the steady-state ms/frame of effectc's whole render path (check,
//! translate, scene, frames, readback, PNG encoding on the second thread, atomic writes) is
//! the difference between a long and a short run divided by the extra frames, so start-up
//! costs cancel. The baseline draws the same pipeline, with the same bind groups and vertex
//! buffers, into the same target format and size and reads every frame back — no PNG. The
//! ratio effectc / bare is the number the render issue bounds (≤ 1.25).
//!
//! Then the time to the first PNG: the release binary rendering one frame of `sun`, as a
//! process, wall time from spawn to exit, median of 5 after one warm-up run (Mesa's shader
//! cache warm).
//!
//! Run: `cargo bench --bench render_speed` (options: `-- --size 512 --frames 24`).

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

#[path = "support/args.rs"]
mod args;
#[path = "support/bare_loop.rs"]
mod bare_loop;

use bare_loop::bare_loop_ms;
use effectc::check::InputSpec;
use effectc::render::command::{self, Request};
use effectc::render::device::Gpu;

/// (label, manifest, frames per `--frames`): a cheap shader's frame takes ~2 ms, so it
/// runs 20 times as many frames as the sun for a run long enough to time (~1 s).
const PROGRAMS: &[(&str, &str, u32)] =
    &[("sun (169-tap in-shader blur)", "effects/sun/effect.toml", 1), ("obj triangle (cheap shader)", "tests/render/obj/effect.toml", 20)];

/// Timed runs of each side; the best one counts (lavapipe's scheduling on a shared
/// 2-core VM makes single runs of the cheap shader vary by 2x).
const RUNS: usize = 5;

fn main() {
    let size = args::number("--size", 512);
    let frames = args::number("--frames", 24);
    let gpu = Gpu::new().expect("a Vulkan adapter (run ./setup.sh)");
    println!("adapter: {}", gpu.describe());
    println!("{size}x{size}, steady state (difference of an N+4 and a 4 frame run), best of {RUNS}\n");
    println!("{:<32} {:>7} {:>14} {:>14} {:>8}", "program", "frames", "effectc ms/fr", "bare ms/fr", "ratio");
    for (label, manifest, scale) in PROGRAMS {
        let n = frames * scale;
        let effectc_ms = effectc_steady_ms(Path::new(manifest), size, n);
        // bare_loop_ms is itself the best of 3 runs.
        let bare_ms = (0..RUNS.div_ceil(3)).map(|_| bare_loop_ms(&gpu, Path::new(manifest), size, n)).fold(f64::INFINITY, f64::min);
        println!("{label:<32} {n:>7} {effectc_ms:>14.3} {bare_ms:>14.3} {:>7.3}x", effectc_ms / bare_ms);
    }
    println!();
    first_png();
}

fn request(manifest: &Path, size: u32, frames: u32, out: PathBuf) -> Request {
    let input = InputSpec { paths: vec![manifest.to_path_buf()], ..InputSpec::default() };
    Request {
        frames: Some(frames),
        size: Some((size, size)),
        out: Some(out),
        timeout: Some(Duration::from_secs(60)),
        ..Request::new(input)
    }
}

/// effectc's ms/frame in steady state: (t(n + 4 frames) − t(4 frames)) / n, best of
/// [`RUNS`].
fn effectc_steady_ms(manifest: &Path, size: u32, frames: u32) -> f64 {
    let out = std::env::temp_dir().join(format!("effectc-bench-{}", std::process::id()));
    let run = |n: u32| {
        let start = Instant::now();
        let result = command::run(&request(manifest, size, n, out.clone()));
        assert!(!effectc::diag::has_errors(&result.outcome.diagnostics), "{:?}", result.outcome.diagnostics);
        assert_eq!(result.rendered[0].frames.len(), n as usize);
        start.elapsed().as_secs_f64()
    };
    run(2); // warm-up: shader cache, page cache
    let best = |n: u32| (0..RUNS).map(|_| run(n)).fold(f64::INFINITY, f64::min);
    let (short, long) = (best(4), best(4 + frames));
    let _ = std::fs::remove_dir_all(&out);
    (long - short) * 1e3 / f64::from(frames)
}

/// Wall time of `effectc render effects/sun/effect.toml --frames 1` as a process.
fn first_png() {
    let bin = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/release/effectc");
    if !bin.is_file() {
        println!("time to first PNG: skipped (build the release binary: cargo build --release)");
        return;
    }
    let out = std::env::temp_dir().join(format!("effectc-first-{}", std::process::id()));
    let run = || {
        let start = Instant::now();
        let status = std::process::Command::new(&bin)
            .args(["render", "effects/sun/effect.toml", "--frames", "1", "--out"])
            .arg(&out)
            .stdout(std::process::Stdio::null())
            .status()
            .unwrap();
        assert!(status.success());
        start.elapsed().as_secs_f64() * 1e3
    };
    run();
    let mut times: Vec<f64> = (0..5).map(|_| run()).collect();
    times.sort_by(f64::total_cmp);
    let _ = std::fs::remove_dir_all(&out);
    println!(
        "time to first PNG (sun, 512x512, release binary, warm shader cache): median {:.0} ms [{:.0}–{:.0}] over 5 runs",
        times[2], times[0], times[4]
    );
}
