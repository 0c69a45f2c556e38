//! Where rendered frames go: PNG files in a directory, or one stream on stdout (PNGs one
//! after another, or raw RGBA8 frames).
//!
//! Frames are encoded on rayon's pool, several at once, while one writer takes the
//! results in frame order; so a cheap shader is not bound by one encoder thread, and the
//! bytes written never depend on the scheduling.

use std::collections::{BTreeSet, VecDeque};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::Instant;

use crate::diag::{Code, Diagnostic};
use crate::output::write_atomic;
use crate::render::encode::{self, NonFinite};
use crate::render::frames::{Dump, Pixels, Spare};

/// Frames encoding at once hold at most about this many bytes of pixels.
const IN_FLIGHT_BYTES: usize = 256 << 20;

/// The format of frames streamed to stdout (`--out -`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StreamFormat {
    /// One PNG file after another (`ffmpeg -f image2pipe -i -` reads them).
    Png,
    /// Width × height × 4 bytes per frame, rows top-down (`--raw`).
    Raw,
}

/// A frame as the render loop hands it over.
pub struct Drawn {
    pub index: u32,
    pub pixels: Pixels,
    pub dumps: Vec<Dump>,
}

/// Where and how one program's frames are written.
pub struct Sink<'a> {
    pub name: &'a str,
    /// Files go here (unused when streaming).
    pub dir: &'a Path,
    pub size: (u32, u32),
    /// Keep every frame's RGBA8 (contact sheet, GIF).
    pub keep: bool,
    /// Files that must never be replaced.
    pub inputs: &'a BTreeSet<PathBuf>,
    /// `Some`: the frames go to stdout in this format instead of files.
    pub stream: Option<StreamFormat>,
    /// Where RGBA8 frames go back once encoded or streamed.
    pub spare: Spare,
}

/// What the sink wrote.
#[derive(Default)]
pub struct Written {
    pub files: Vec<PathBuf>,
    /// `--float`: each frame's NaN/Inf counts and its mask, if it has one.
    pub non_finite: Vec<(u32, NonFinite, Option<PathBuf>)>,
    pub kept: Vec<Vec<u8>>,
    /// When the first frame was on disk (or in the stream).
    pub first_written: Option<Instant>,
    /// Frames completely written.
    pub frames: u32,
    /// Encoding and write failures (`E0014`); a closed stream is one of them.
    pub errors: Vec<Diagnostic>,
}

/// One frame encoded: its images in write order, the float scan's result.
struct Encoded {
    index: u32,
    images: Vec<Image>,
    non_finite: Option<(NonFinite, Option<PathBuf>)>,
    kept: Option<Vec<u8>>,
}

/// Encoded bytes for a file (`path`) or, without one, for the stream.
struct Image {
    path: Option<PathBuf>,
    bytes: Result<Vec<u8>, String>,
}

impl Sink<'_> {
    /// Encodes the frames `rx` delivers on rayon's pool and writes them in frame order.
    /// Returns when `rx` closes, or early when the stream's reader has gone: `rx` is then
    /// dropped, so the render loop's next send fails and it stops.
    pub fn run(&self, rx: mpsc::Receiver<Drawn>) -> Written {
        let mut out = Written::default();
        let mut stdout = self.stream.map(|_| std::io::stdout().lock());
        let window = self.window();
        rayon::in_place_scope(|scope| {
            let mut pending: VecDeque<mpsc::Receiver<Encoded>> = VecDeque::new();
            for drawn in rx.iter() {
                let (tx, done) = mpsc::sync_channel(1);
                scope.spawn(move |_| {
                    let _ = tx.send(self.encode(drawn));
                });
                pending.push_back(done);
                while pending.len() >= window {
                    if !self.write_next(&mut pending, &mut stdout, &mut out) {
                        return;
                    }
                }
            }
            while !pending.is_empty() {
                if !self.write_next(&mut pending, &mut stdout, &mut out) {
                    return;
                }
            }
        });
        if let Some(Err(e)) = stdout.as_mut().map(|s| s.flush()) {
            if out.errors.is_empty() {
                out.errors.push(stream_error(out.frames, &e));
            }
        }
        out
    }

    /// Frames encoding at once: one more than the pool has threads (so none idles while
    /// the writer works), fewer when frames are so large that memory would run short.
    fn window(&self) -> usize {
        // A float frame and its RGBA8 conversion: 20 bytes per pixel.
        let frame = (self.size.0 as usize).saturating_mul(self.size.1 as usize).saturating_mul(20);
        let by_memory = (IN_FLIGHT_BYTES / frame.max(1)).max(1);
        (rayon::current_num_threads() + 1).min(by_memory)
    }

    /// A frame's images: intermediate targets, the NaN/Inf mask, then the frame itself.
    fn encode(&self, Drawn { index, pixels, dumps }: Drawn) -> Encoded {
        let (w, h) = self.size;
        let file = |suffix: &str| self.dir.join(format!("{}_{index:04}{suffix}.png", self.name));
        let mut images: Vec<Image> = dumps
            .iter()
            .map(|d| Image { path: Some(file(&format!("_{}", d.target))), bytes: encode::png_bytes(&d.rgba, d.size.0, d.size.1) })
            .collect();
        let mut non_finite = None;
        let rgba = match pixels {
            Pixels::Rgba8(p) => p,
            Pixels::Rgba32F(f) => {
                let (counts, mask) = encode::non_finite(&f, w, h);
                let mask_path = mask.map(|m| {
                    let path = file("_nonfinite");
                    images.push(Image { path: Some(path.clone()), bytes: encode::png_bytes(&m, w, h) });
                    path
                });
                non_finite = Some((counts, mask_path));
                encode::float_to_rgba8(&f)
            }
        };
        let (frame, kept) = match (self.stream, self.keep) {
            (Some(StreamFormat::Raw), false) => (Ok(rgba), None),
            (Some(StreamFormat::Raw), true) => (Ok(rgba.clone()), Some(rgba)),
            (_, true) => (encode::png_bytes(&rgba, w, h), Some(rgba)),
            (_, false) => {
                let png = encode::png_bytes(&rgba, w, h);
                self.spare.give(rgba);
                (png, None)
            }
        };
        let path = self.stream.is_none().then(|| file(""));
        images.push(Image { path, bytes: frame });
        Encoded { index, images, non_finite, kept }
    }

    /// Writes the oldest pending frame; false when the stream or the disk cannot take more.
    fn write_next(
        &self,
        pending: &mut VecDeque<mpsc::Receiver<Encoded>>,
        stdout: &mut Option<std::io::StdoutLock<'_>>,
        out: &mut Written,
    ) -> bool {
        // A job that panicked sends nothing; the scope re-raises its panic.
        let Some(Ok(encoded)) = pending.pop_front().map(|p| p.recv()) else { return true };
        let index = encoded.index;
        for Image { path, bytes } in encoded.images {
            let bytes = match bytes {
                Ok(b) => b,
                Err(e) => {
                    let what = path.as_ref().map_or_else(|| format!("frame {index}"), |p| p.display().to_string());
                    out.errors.push(Diagnostic::new(Code::OutputIo, format!("cannot encode {what}: {e}")));
                    continue;
                }
            };
            match (path, stdout.as_mut()) {
                (Some(path), _) => match write_atomic(&path, &bytes, self.inputs) {
                    Ok(()) => out.files.push(path),
                    Err(e) => {
                        // A full disk or a directory that cannot be written: the first failed
                        // frame ends the run (the render loop stops when `rx` is dropped).
                        out.errors.push(
                            Diagnostic::new(Code::OutputIo, e)
                                .with_note("no further frame was written: the first failed write stops the run"),
                        );
                        return false;
                    }
                },
                (None, Some(s)) => {
                    if let Err(e) = s.write_all(&bytes) {
                        out.errors.push(stream_error(index, &e));
                        return false;
                    }
                    if self.stream == Some(StreamFormat::Raw) {
                        self.spare.give(bytes);
                    }
                }
                (None, None) => {}
            }
        }
        out.first_written.get_or_insert_with(Instant::now);
        out.frames += 1;
        if let Some((counts, mask)) = encoded.non_finite {
            out.non_finite.push((index, counts, mask));
        }
        out.kept.extend(encoded.kept);
        true
    }
}

/// The stream on stdout failed at frame `index`: its reader closed the pipe (`ffmpeg`
/// stopped early), or stdout is not writable.
fn stream_error(index: u32, e: &std::io::Error) -> Diagnostic {
    let frames = format!("{index} frame{}", if index == 1 { "" } else { "s" });
    if e.kind() == std::io::ErrorKind::BrokenPipe {
        Diagnostic::new(Code::OutputIo, format!("the reader closed the frame stream on stdout after {frames}"))
            .with_note("the frames after those were not written")
    } else {
        Diagnostic::new(Code::OutputIo, format!("cannot write frame {index} to stdout: {e}"))
    }
}
