//! Multi-pass effects (`tests/render/passes/`): passes that never reach the output are
//! really skipped, unread MRT attachments are dropped, targets share textures when their
//! lifetimes allow, `--dump-targets` writes every intermediate target, `translate` writes
//! one program per running pass.

use effectc::diag::Code;
use effectc::render::compare;

use crate::common::{code, effectc, scratch, stdout};
use crate::render::have_gpu;

const FIXTURE: &str = "tests/render/passes/effect.toml";
const PLAIN: &str = "tests/render/passes/plain.toml";

fn rgba_at(pixels: &[u8], width: u32, x: u32, y: u32) -> [u8; 4] {
    let i = ((y * width + x) * 4) as usize;
    [pixels[i], pixels[i + 1], pixels[i + 2], pixels[i + 3]]
}

#[test]
fn a_pass_that_never_reaches_the_output_is_skipped() {
    if !have_gpu() {
        return;
    }
    let dir = scratch("passes", "skipped");
    // Control: with --dump-targets every pass runs, and the `slow` pass overruns the
    // 3 s timeout (E0403, exit 1).
    let control = effectc(&["render", FIXTURE, "--size", "256x256", "--timeout", "3", "--dump-targets", "--out", dir.to_str().unwrap()]);
    assert_eq!(code(&control), 1, "{}", stdout(&control));
    assert!(stdout(&control).contains(Code::FrameTimeout.as_str()), "{}", stdout(&control));
    // Pruned, the same render finishes well within the timeout.
    let dir = scratch("passes", "skipped");
    let started = std::time::Instant::now();
    let out = effectc(&["render", FIXTURE, "--size", "256x256", "--timeout", "3", "--explain", "--out", dir.to_str().unwrap()]);
    let text = stdout(&out);
    assert_eq!(code(&out), 0, "{text}");
    assert!(started.elapsed().as_secs() < 30, "the render took {:?}", started.elapsed());
    assert!(!text.contains(Code::FrameTimeout.as_str()), "{text}");
    assert!(text.contains("pass slow         skipped: nothing it writes (debug) reaches the output"), "{text}");
    assert!(text.contains(Code::PassUnused.as_str()), "check warns about the skipped pass:\n{text}");
    assert!(text.contains("t1, spare (dropped: never read)"), "{text}");
    // Four chained targets in two textures: t3 reuses t1's, final reuses t2's.
    assert!(text.contains("t1 (passes scene–invert1), then t3 (passes invert2–invert3)"), "{text}");
    assert!(text.contains("t2 (passes invert1–invert2), then final (passes invert3–end)"), "{text}");

    // Three inversions of the uv gradient: (1 - u, 1 - v, 0.5). uv runs bottom-up as in
    // GL, so the bottom-left pixel is near (1, 1, 0.5) and the top-right near (0, 0, 0.5);
    // a vertex stage that lost its texCoord (naga's block-member shadowing) would make the
    // frame one flat colour.
    let (pixels, w, h) = compare::read_png(&dir.join("passes_0000.png")).unwrap();
    let bottom_left = rgba_at(&pixels, w, 0, h - 1);
    let top_right = rgba_at(&pixels, w, w - 1, 0);
    assert!(bottom_left[0] > 240 && bottom_left[1] > 240 && (120..=135).contains(&bottom_left[2]), "{bottom_left:?}");
    assert!(top_right[0] < 15 && top_right[1] < 15 && (120..=135).contains(&top_right[2]), "{top_right:?}");
}

#[test]
fn dump_targets_writes_every_intermediate_target() {
    if !have_gpu() {
        return;
    }
    let dir = scratch("passes", "dump");
    let out =
        effectc(&["render", PLAIN, "--size", "32x32", "--frames", "2", "--dump-targets", "--explain", "--out", dir.to_str().unwrap()]);
    let text = stdout(&out);
    assert_eq!(code(&out), 0, "{text}");
    // Nothing is dropped or shared when dumping: every target can be read back.
    assert!(!text.contains("(dropped: never read)"), "{text}");
    assert!(!text.contains(", then "), "{text}");
    for frame in ["0000", "0001"] {
        for target in ["t1", "spare", "t2", "t3"] {
            let path = dir.join(format!("passes_{frame}_{target}.png"));
            assert!(path.is_file(), "{} missing:\n{text}", path.display());
        }
        assert!(dir.join(format!("passes_{frame}.png")).is_file());
    }
    // The spare attachment holds the scene pass's magenta; t2 is t1 inverted.
    let (spare, w, _) = compare::read_png(&dir.join("passes_0000_spare.png")).unwrap();
    assert_eq!(rgba_at(&spare, w, 5, 5), [255, 0, 255, 255]);
    let (t1, w, _) = compare::read_png(&dir.join("passes_0000_t1.png")).unwrap();
    let (t2, _, _) = compare::read_png(&dir.join("passes_0000_t2.png")).unwrap();
    for (x, y) in [(0, 0), (31, 31), (10, 20)] {
        let (a, b) = (rgba_at(&t1, w, x, y), rgba_at(&t2, w, x, y));
        for c in 0..3 {
            assert!((i32::from(a[c]) + i32::from(b[c]) - 255).abs() <= 2, "({x},{y}): {a:?} vs {b:?}");
        }
    }
}

#[test]
fn translate_writes_one_program_per_running_pass() {
    let dir = scratch("passes", "translate");
    let out = effectc(&["translate", FIXTURE, "--to", "wgsl", "--out", dir.to_str().unwrap()]);
    let text = stdout(&out);
    assert_eq!(code(&out), 0, "{text}");
    for pass in ["scene", "invert1", "invert2", "invert3"] {
        assert!(dir.join(format!("passes.{pass}.wgsl")).is_file(), "passes.{pass}.wgsl missing:\n{text}");
    }
    assert!(!dir.join("passes.slow.wgsl").exists(), "the skipped pass was translated:\n{text}");
    // The renamed block member keeps the vertex input readable.
    let wgsl = std::fs::read_to_string(dir.join("passes.scene.wgsl")).unwrap();
    assert!(wgsl.contains("OUT_texCoord"), "{wgsl}");
}

/// A full-screen pass in the emulator packs' style: `VertexCoord`/`TexCoord` inputs and an
/// `MVPMatrix`, none of them in effectc's documented names, none given in the manifest.
fn unmapped_fullscreen_pass(dir: &std::path::Path) -> std::path::PathBuf {
    std::fs::create_dir_all(dir).unwrap();
    let manifest = "name = \"fx\"\noutput = \"final\"\n[targets]\nscene = { format = \"rgba8\" }\nfinal = { format = \"rgba8\" }\n\
                    [[passes]]\nname = \"scene\"\nstages = { vertex = \"a.vert\", fragment = \"a.frag\" }\ndraw = \"fullscreen\"\n\
                    targets = [\"scene\"]\n[[passes]]\nname = \"post\"\nstages = { vertex = \"post.vert\", fragment = \"post.frag\" }\n\
                    draw = \"fullscreen\"\nsamples = { Source = \"scene\" }\ntargets = [\"final\"]\n";
    std::fs::write(dir.join("effect.toml"), manifest).unwrap();
    let plain_vert = "#version 330\nin vec2 position;\nin vec2 texCoord;\nout vec2 uv;\nvoid main() { uv = texCoord; gl_Position = vec4(position, 0.0, 1.0); }\n";
    std::fs::write(dir.join("a.vert"), plain_vert).unwrap();
    std::fs::write(dir.join("a.frag"), "#version 330\nin vec2 uv;\nout vec4 c;\nvoid main() { c = vec4(uv, 0.5, 1.0); }\n").unwrap();
    let post = "#version 330\nin vec4 VertexCoord;\nin vec4 TexCoord;\nin vec4 COLOR;\nuniform mat4 MVPMatrix;\nout vec2 uv;\n\
                void main() { gl_Position = MVPMatrix * VertexCoord; uv = TexCoord.xy + COLOR.xy; }\n";
    std::fs::write(dir.join("post.vert"), post).unwrap();
    let frag = "#version 330\nin vec2 uv;\nuniform sampler2D Source;\nout vec4 c;\nvoid main() { c = texture(Source, uv); }\n";
    std::fs::write(dir.join("post.frag"), frag).unwrap();
    dir.join("effect.toml")
}

#[test]
fn a_fullscreen_pass_with_unmapped_inputs_warns_in_check_and_render_alike() {
    let dir = scratch("passes", "unmapped");
    let manifest = unmapped_fullscreen_pass(&dir);
    let m = manifest.to_str().unwrap();
    let codes_of = |text: &str| -> Vec<String> {
        let mut codes: Vec<String> = text.lines().filter_map(|l| l.strip_prefix("warning[")).map(|l| l[..5].to_string()).collect();
        codes.sort();
        codes
    };
    let checked = effectc(&["check", "--color", "never", m]);
    let text = stdout(&checked);
    assert_eq!(code(&checked), 0, "{text}");
    // The documented names (`position`, `texCoord`) are the contract; the others are guesses.
    assert!(text.contains("vertex input `VertexCoord` reads the mesh's position (guessed by its name)"), "{text}");
    assert!(text.contains("vertex input `COLOR` reads the mesh's color"), "{text}");
    assert!(text.contains("uniform `MVPMatrix` has no value in the manifest"), "{text}");
    assert!(!text.contains("`TexCoord`") && !text.contains("`position`") && !text.contains("`Source` has no texture"), "{text}");
    let denied = effectc(&["check", "--deny-warnings", m]);
    assert_eq!(code(&denied), 1, "guessed pass inputs fail a lint that denies warnings");
    if !have_gpu() {
        return;
    }
    let out = dir.join("frames");
    let rendered = effectc(&["render", "--color", "never", "--verbose", "--size", "32x32", m, "--out", out.to_str().unwrap()]);
    let render_text = stdout(&rendered);
    assert_eq!(code(&rendered), 0, "{render_text}");
    assert_eq!(codes_of(&render_text), codes_of(&text), "check reports what render reports:\n{text}\n---\n{render_text}");
    // `--verbose` shows what feeds each pass's inputs, uniforms and samplers.
    assert!(render_text.contains("inputs: VertexCoord ← position (guessed), TexCoord ← uv, COLOR ← color (guessed)"), "{render_text}");
    assert!(render_text.contains("uniforms: MVPMatrix ← semantic mvp (guessed by its name)"), "{render_text}");
    assert!(render_text.contains("samplers: Source ← target scene"), "{render_text}");
}
