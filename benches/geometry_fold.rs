//! Benchmark: a program with a geometry stage, folded into the vertex stage, against the
//! same mesh drawn without a geometry stage, in one process.
//!
//! The folded program is `effects/explode` with its explosion's intensity at 0 (so both
//! programs cover the same pixels; triangles in, a strip of 3 out: every output vertex runs
//! the vertex stage for the three corners of its triangle, then the geometry stage). The plain program draws the same mesh with the same fragment stage and a vertex
//! stage that writes what the geometry stage would pass on, with an index buffer (so the
//! GPU may reuse vertices). Both are drawn by the same minimal wgpu loop (uniforms, draw,
//! readback, no PNG; `support/bare_loop.rs`), at the same size, for two meshes: the
//! effect's own sphere and a dense one. The ratio folded / plain is what the geometry issue
//! bounds (≤ 2 at 512×512).
//!
//! Run: `cargo bench --bench geometry_fold` (options: `-- --size 512 --frames 24`).

#[path = "support/args.rs"]
mod args;
#[path = "support/bare_loop.rs"]
mod bare_loop;

use std::path::{Path, PathBuf};

use bare_loop::bare_loop_ms;
use effectc::render::device::Gpu;

/// A vertex stage that writes what the explode geometry stage's fragment stage reads.
const PLAIN_VERT: &str = "#version 420
uniform mat4 transform;
layout (location = 0) in vec3 vertexPosition;
layout (location = 1) in vec2 texCoords;
out geom_vars { vec2 geomTexCoords; } geom_out;
void main() {
    geom_out.geomTexCoords = texCoords;
    gl_Position = transform * vec4(vertexPosition, 1.0);
}
";

fn main() {
    let size = args::number("--size", 512);
    let frames = args::number("--frames", 24);
    let gpu = Gpu::new().expect("a Vulkan adapter (run ./setup.sh)");
    println!("adapter: {}", gpu.describe());
    println!("{size}x{size}, ms/frame of a minimal draw + readback loop, best of 3 runs of {frames} frames\n");
    println!("{:<34} {:>10} {:>12} {:>10} {:>8}", "mesh", "triangles", "folded ms", "plain ms", "ratio");
    let dir = std::env::temp_dir().join(format!("effectc-geometry-bench-{}", std::process::id()));
    for (label, segments, rings) in [("explode's sphere (24 x 12)", 24, 12), ("dense sphere (128 x 64)", 128, 64)] {
        let (folded, plain) = manifests(&dir, segments, rings);
        let folded_ms = bare_loop_ms(&gpu, &folded, size, frames);
        let plain_ms = bare_loop_ms(&gpu, &plain, size, frames);
        let triangles = 2 * segments * (rings - 1);
        println!("{label:<34} {triangles:>10} {folded_ms:>12.3} {plain_ms:>10.3} {:>7.2}x", folded_ms / plain_ms);
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// The explode effect with its mesh at `segments` × `rings`, and its plain twin.
fn manifests(dir: &Path, segments: u32, rings: u32) -> (PathBuf, PathBuf) {
    let dir = dir.join(format!("{segments}x{rings}"));
    std::fs::create_dir_all(&dir).unwrap();
    let effect = Path::new(env!("CARGO_MANIFEST_DIR")).join("effects/explode");
    for stage in ["explode.vert", "explode.frag"] {
        std::fs::copy(effect.join(stage), dir.join(stage)).unwrap();
    }
    // The pieces stay in place (intensity from a uniform set to 0, which no compiler can
    // fold away), so both programs cover the same pixels and only the fold's cost differs.
    let geometry = std::fs::read_to_string(effect.join("explode.geom")).unwrap();
    assert!(geometry.contains("float intensity = 7.0;"), "explode.geom's intensity");
    let geometry = geometry
        .replace("float intensity = 7.0;", "float intensity = spread;")
        .replace("uniform float timeVar;", "uniform float timeVar;\nuniform float spread;");
    std::fs::write(dir.join("explode.geom"), geometry).unwrap();
    std::fs::write(dir.join("plain.vert"), PLAIN_VERT).unwrap();
    let manifest = std::fs::read_to_string(effect.join("effect.toml")).unwrap();
    assert!(manifest.contains("segments = 24\nrings = 12\n"), "the explode manifest names its sphere's segments and rings");
    let mesh = manifest.replace("segments = 24\nrings = 12\n", &format!("segments = {segments}\nrings = {rings}\n"));
    let folded = dir.join("folded.toml");
    std::fs::write(&folded, mesh.replace("timeVar = { semantic = \"time\" }\n", "timeVar = { semantic = \"time\" }\nspread = 0.0\n"))
        .unwrap();
    let plain = dir.join("plain.toml");
    let plain_manifest = mesh.replace("vertex = \"explode.vert\"\ngeometry = \"explode.geom\"\n", "vertex = \"plain.vert\"\n");
    assert_ne!(plain_manifest, mesh);
    std::fs::write(&plain, plain_manifest.replace("timeVar = { semantic = \"time\" }\n", "")).unwrap();
    (folded, plain)
}
