//! Benchmark: `bloom`'s separable passes against `sun`'s in-shader blur, in one process.
//!
//! Seed 000's sun blurs in its fragment shader: a (2r+1)² = 13×13 = 169-tap box loop per
//! pixel at full resolution. Seed 003's bloom blurs in passes: a bright pass, then a
//! horizontal and a vertical single-direction blur of 41 taps each at half resolution
//! (the curve halves about every 2.5 taps: a visual radius of about 5 half-resolution
//! texels, 10 output pixels, close to the sun's 6-texel box on its 256² texture), then an
//! additive combine.
//!
//! `bloom`'s scene pass *is* the sun (with its own blur), so the cost of each blur is a
//! difference of frame times measured here. Two clocks: the steady-state wall ms/frame of
//! effectc's render path (difference of a (n + 4)- and a 4-frame run, best of 2, so
//! start-up cancels) and the GPU timestamps around the passes (median of the frames):
//! - in-shader blur = `sun` − `sun` with the knob `blurEffectRadius = 0` (a copy of the
//!   manifest made for the run);
//! - separable bloom = `bloom` − `sun` (bright pass, two blurs, combine).
//!
//! Run: `cargo bench --bench bloom_vs_sun` (options: `-- --size 512 --frames 12`).

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use effectc::check::InputSpec;
use effectc::render::command::{self, Request};
use effectc::render::frames::GpuClock;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let arg = |name: &str, default: u32| {
        args.iter().position(|a| a == name).and_then(|i| args.get(i + 1)).and_then(|v| v.parse().ok()).unwrap_or(default)
    };
    let size = arg("--size", 512);
    let frames = arg("--frames", 12);
    let scratch = std::env::temp_dir().join(format!("effectc-bloom-bench-{}", std::process::id()));
    let no_blur = sun_without_blur(&scratch.join("sun-noblur"));
    let programs: [(&str, PathBuf); 3] = [
        ("sun, no blur (scene only)", no_blur),
        ("sun (13x13 in-shader blur)", PathBuf::from("effects/sun/effect.toml")),
        ("bloom (sun + separable passes)", PathBuf::from("effects/bloom/effect.toml")),
    ];
    println!("{size}x{size}, {frames} frames; wall = steady-state ms/frame, GPU = timestamps (median [min-max])\n");
    println!("{:<34} {:>10} {:>30}", "program", "wall ms", "GPU ms");
    let mut wall = Vec::new();
    let mut gpu = Vec::new();
    for (label, manifest) in &programs {
        let out = scratch.join("frames");
        let steady = steady_ms(manifest, size, frames, &out);
        let (median, min, max, clock) = gpu_ms(manifest, size, frames, &out);
        assert_eq!(clock, GpuClock::Timestamps, "the adapter has no timestamp queries");
        println!("{label:<34} {steady:>10.1} {:>30}", format!("{median:.1} [{min:.1}-{max:.1}]"));
        wall.push(steady);
        gpu.push(median);
    }
    println!();
    for (clock, t) in [("wall", &wall), ("GPU", &gpu)] {
        let in_shader = t[1] - t[0];
        let separable = t[2] - t[1];
        println!(
            "{clock:>4}: in-shader 13x13 blur {in_shader:7.1} ms/frame, separable bloom passes {separable:7.1} ms/frame: {:.2}x",
            separable / in_shader
        );
    }
    let _ = std::fs::remove_dir_all(&scratch);
}

/// A copy of `effects/sun` whose blur loop has radius 0 (one tap).
fn sun_without_blur(dir: &Path) -> PathBuf {
    std::fs::create_dir_all(dir).unwrap();
    for file in ["effect.toml", "sun.vert", "sun.frag"] {
        let text = std::fs::read_to_string(Path::new("effects/sun").join(file)).unwrap();
        let text = if file == "effect.toml" {
            let changed = text.replace("blurEffectRadius = { value = 6,", "blurEffectRadius = { value = 0,");
            assert_ne!(changed, text, "effect.toml no longer gives blurEffectRadius = 6");
            changed
        } else {
            text
        };
        std::fs::write(dir.join(file), text).unwrap();
    }
    dir.join("effect.toml")
}

fn request(manifest: &Path, size: u32, n: u32, out: &Path) -> Request {
    let input = InputSpec { paths: vec![manifest.to_path_buf()], ..InputSpec::default() };
    Request {
        frames: Some(n),
        size: Some((size, size)),
        out: Some(out.to_path_buf()),
        timeout: Some(Duration::from_secs(60)),
        ..Request::new(input)
    }
}

/// effectc's wall ms/frame in steady state: (t(n + 4 frames) − t(4 frames)) / n, best of 2.
fn steady_ms(manifest: &Path, size: u32, frames: u32, out: &Path) -> f64 {
    let run = |n: u32| {
        let start = Instant::now();
        let result = command::run(&request(manifest, size, n, out));
        assert!(!effectc::diag::has_errors(&result.outcome.diagnostics), "{:?}", result.outcome.diagnostics);
        start.elapsed().as_secs_f64()
    };
    run(2); // warm-up: shader cache, page cache
    let best = |n: u32| (0..2).map(|_| run(n)).fold(f64::INFINITY, f64::min);
    let (short, long) = (best(4), best(4 + frames));
    (long - short) * 1e3 / f64::from(frames)
}

/// Median, min and max GPU ms per frame over `frames` frames.
fn gpu_ms(manifest: &Path, size: u32, frames: u32, out: &Path) -> (f64, f64, f64, GpuClock) {
    let result = command::run(&request(manifest, size, frames, out));
    assert!(!effectc::diag::has_errors(&result.outcome.diagnostics), "{:?}", result.outcome.diagnostics);
    let rendered = &result.rendered[0];
    let mut ms: Vec<f64> = rendered.frames.iter().map(|f| f.gpu_ms).collect();
    ms.sort_by(f64::total_cmp);
    (ms[ms.len() / 2], ms[0], ms[ms.len() - 1], rendered.clock)
}
