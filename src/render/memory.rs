//! Rendering without files, for `effectc bench` and `effectc stress`: a checked program is
//! translated and its scene (or pass graph) built once, then drawn as often as asked with
//! other uniform values, the pixels and probe counts returned in memory.
//!
//! Building is the expensive part on lavapipe (every pipeline is compiled by LLVM), so a
//! caller that only changes uniform values between runs keeps one [`MemoryDrawer`] and calls
//! [`MemoryDrawer::set_overrides`]; a changed mesh needs a new one.

use std::time::Duration;

use crate::assets::degenerate::Degenerate;
use crate::back::TranslateOptions;
use crate::check::{self, Outcome};
use crate::diag::{Code, Diagnostic, FileId};
use crate::manifest::UniformValue;
use crate::render::device::Gpu;
use crate::render::drawer::{build, frame_state, prepare, with_overrides, BuildSettings, BuildVariant, Drawer, Instrument};
use crate::render::frames::{self, Frame, FrameError, GpuClock, Pixels};
use crate::render::scene::ColorMode;
use crate::render::uniforms;

/// Frames rendered in memory by [`MemoryDrawer::render`].
pub struct MemoryRun {
    /// Pixels per frame, top row first (RGBA8, or RGBA32F with `float`).
    pub frames: Vec<Pixels>,
    pub gpu_ms: Vec<f64>,
    pub clock: GpuClock,
    /// With [`MemoryRequest::read_back`]: per scene that has that storage buffer (index into
    /// `Effect::passes`, 0 for a single pass), its words after the run's frames.
    pub read_back: Vec<(usize, Vec<u32>)>,
    /// What the degenerate mesh changed, per scene that draws one (index into
    /// `Effect::passes`, 0 for a single pass; empty when none did).
    pub degenerate: Vec<(usize, String)>,
}

/// What an [`MemoryDrawer`] draws: `frames` frames at times `start + i × step`.
#[derive(Debug, Clone, Copy)]
pub struct MemoryRequest {
    pub size: (u32, u32),
    pub frames: u32,
    pub start: f64,
    pub step: f64,
    /// Render into Rgba32Float (NaN and Inf survive).
    pub float: bool,
    pub timeout: Duration,
    /// A storage buffer of the program (by name) zeroed before each run and read back
    /// after it (the counts an instrumented program writes).
    pub read_back: Option<&'static str>,
    /// Draw a degenerate variant of the mesh.
    pub degenerate: Option<Degenerate>,
}

/// A program ready to draw in memory.
pub struct MemoryDrawer<'c> {
    c: &'c check::Checked,
    m: MemoryRequest,
    /// `None` after a frame timed out: the device may still be busy with it.
    drawer: Option<Drawer>,
    file: FileId,
}

/// Renders frames of a checked program without writing files, with uniform values
/// replaced by `overrides`. Problems go to `outcome`; `None` when the program cannot be
/// rendered.
pub fn render_in_memory(
    gpu: &Gpu,
    c: &check::Checked,
    outcome: &mut Outcome,
    overrides: &[(String, UniformValue)],
    m: MemoryRequest,
) -> Option<MemoryRun> {
    MemoryDrawer::new(gpu, c, outcome, overrides, m, None)?.render(gpu, outcome, m.start)
}

impl<'c> MemoryDrawer<'c> {
    /// Translates and builds the program with `overrides`, the translations changed by
    /// `instrument` first. Problems go to `outcome`.
    pub fn new(
        gpu: &Gpu,
        c: &'c check::Checked,
        outcome: &mut Outcome,
        overrides: &[(String, UniformValue)],
        m: MemoryRequest,
        instrument: Option<Instrument<'_>>,
    ) -> Option<Self> {
        let settings = BuildSettings {
            back: TranslateOptions::for_rendering(true),
            size: Some(m.size),
            dump_targets: false,
            timestamps: true,
            gl_defaults: false,
        };
        let prepared = prepare(c, outcome, &settings, instrument)?;
        let mode = if m.float { ColorMode::Float32 } else { ColorMode::Unorm8 };
        match build(gpu, &prepared, c, (m.size, mode), &settings, BuildVariant { overrides, degenerate: m.degenerate }) {
            Ok((Drawer::Compute(_), file)) => {
                // Knobs, stress cases and degenerate meshes change a drawn scene's uniforms
                // and mesh; a compute program's dispatch takes neither yet.
                outcome.diagnostics.push(
                    Diagnostic::new(Code::Unrenderable, "`bench` and `stress` draw programs with a vertex stage; this one is compute only")
                        .in_file(file)
                        .with_help("`effectc render` dispatches a compute-only program and shows the image it stores"),
                );
                None
            }
            Ok((drawer, file)) => Some(MemoryDrawer { c, m, drawer: Some(drawer), file }),
            Err(diags) => {
                outcome.diagnostics.extend(diags);
                None
            }
        }
    }

    /// Rewrites every uniform buffer from the manifest with `overrides` applied (the
    /// semantic slots are rewritten each frame anyway).
    pub fn set_overrides(&mut self, overrides: &[(String, UniformValue)]) -> Result<(), String> {
        let Some(drawer) = self.drawer.as_mut() else { return Err("the device is still busy with a frame that timed out".into()) };
        let c = self.c;
        for (pass, scene) in drawer.scenes_mut() {
            let effect = c.unit(pass).and_then(|u| u.effect.as_ref()).map(|e| with_overrides(e, overrides));
            let (buffers, _) = uniforms::buffers(&scene.module, effect.as_ref(), &scene.initial, &scene.row_major, overrides, true)?;
            for (data, (old, _)) in buffers.into_iter().zip(&mut scene.uniforms) {
                *old = data;
            }
        }
        Ok(())
    }

    /// Replaces the bytes of uniform buffers with `bytes(pass, group, binding)` where it
    /// gives some: a buffer a program packed on its own, from the reflection JSON (the
    /// semantic slots are still rewritten every frame). Returns how many were replaced.
    pub fn set_uniform_bytes(&mut self, bytes: &dyn Fn(usize, u32, u32) -> Option<Vec<u8>>) -> Result<usize, String> {
        let Some(drawer) = self.drawer.as_mut() else { return Err("the device is still busy with a frame that timed out".into()) };
        let mut replaced = 0;
        for (pass, scene) in drawer.scenes_mut() {
            for (data, _) in &mut scene.uniforms {
                let Some(mut new) = bytes(pass, data.group, data.binding) else { continue };
                if new.len() > data.bytes.len() {
                    return Err(format!("{} bytes for a buffer of {}", new.len(), data.bytes.len()));
                }
                // The buffer is the block's size rounded up to 16 bytes, as wgpu wants.
                new.resize(data.bytes.len(), 0);
                data.bytes = new;
                replaced += 1;
            }
        }
        Ok(replaced)
    }

    /// Draws the request's frames from effect time `start`. Probe counts start from zero.
    pub fn render(&mut self, gpu: &Gpu, outcome: &mut Outcome, start: f64) -> Option<MemoryRun> {
        let MemoryRequest { size, frames, step, timeout, .. } = self.m;
        let drawer = self.drawer.as_mut()?;
        let read_back = self.m.read_back;
        for (_, scene) in drawer.scenes() {
            if let Some(buffer) = read_back.and_then(|name| scene.storage_buffer(name)) {
                gpu.queue.write_buffer(buffer, 0, &vec![0u8; buffer.size() as usize]);
            }
        }
        let degenerate = drawer.scenes().filter_map(|(i, s)| Some((i, s.degenerate.clone()?))).collect();
        let mut run = MemoryRun { frames: Vec::new(), gpu_ms: Vec::new(), clock: drawer.clock(), read_back: Vec::new(), degenerate };
        for i in 0..frames {
            let state = frame_state(drawer, i, start + f64::from(i) * step, step, size);
            match drawer.draw(gpu, &state, timeout) {
                Ok(Frame { pixels, gpu_ms, .. }) => {
                    run.frames.push(pixels);
                    run.gpu_ms.push(gpu_ms);
                }
                Err(e) => {
                    let hung = matches!(e, FrameError::Timeout(_));
                    let message = match e {
                        FrameError::Timeout(t) => format!("frame {i} did not finish within {:.1} s", t.as_secs_f64()),
                        FrameError::Device(d) => format!("frame {i} failed on the device: {d}"),
                    };
                    outcome
                        .diagnostics
                        .push(Diagnostic::new(if hung { Code::FrameTimeout } else { Code::FrameFailed }, message).in_file(self.file));
                    if hung {
                        // The device is still busy: dropping the scene would wait for it.
                        std::mem::forget(self.drawer.take());
                    }
                    return None;
                }
            }
        }
        for (pass, scene) in drawer.scenes() {
            let Some(buffer) = read_back.and_then(|name| scene.storage_buffer(name)) else { continue };
            match frames::read_u32s(gpu, buffer) {
                Ok(words) => run.read_back.push((pass, words)),
                Err(e) => {
                    let message = match e {
                        FrameError::Timeout(t) => format!("the storage buffer was not ready within {:.1} s", t.as_secs_f64()),
                        FrameError::Device(d) => format!("the storage buffer could not be read: {d}"),
                    };
                    outcome.diagnostics.push(Diagnostic::new(Code::FrameFailed, message).in_file(self.file));
                    return None;
                }
            }
        }
        Some(run)
    }
}
