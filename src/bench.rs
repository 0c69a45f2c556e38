//! `effectc bench`: error against run time for quality knobs.
//!
//! For each knob (from `--knob NAME=v1,v2,…` or the manifest's `[knobs]`), every value
//! renders the same frames (`--frames`, `--size`) `--repeats` times. GPU time per frame comes
//! from timestamp queries around the passes when the adapter has them, else from the wall
//! time between submit and completion (the report says which). Each frame is compared with
//! the same frame at the knob's reference value: mean and max absolute error (8-bit
//! levels, RGB), PSNR and SSIM (the `image-compare` crate's hybrid YUV SSIM; 1 = identical).
//!
//! Codes: `E0801` a knob names no numeric `[uniforms]` entry, `E0802` nothing to bench (no
//! knob given and none in the manifest), `E0803` a `--knob` value list that is not numbers.

pub mod plot;

use std::time::Duration;

use crate::check::{self, Outcome};
use crate::diag::{Code, Diagnostic};
use crate::manifest::{Effect, UniformValue};
use crate::render::command;
use crate::render::device::Gpu;
use crate::render::frames::{GpuClock, Pixels};
use crate::render::memory::{self, MemoryRequest, MemoryRun};

/// What `bench` was asked to do.
#[derive(Debug, Clone)]
pub struct Request {
    pub input: check::InputSpec,
    /// `--knob NAME=v1,v2,…` (the last value is the reference); empty: the manifest's knobs.
    pub knobs: Vec<(String, Vec<f64>)>,
    pub frames: u32,
    pub size: (u32, u32),
    pub repeats: u32,
    /// Seconds of effect time between frames.
    pub step: f64,
    pub timeout: Duration,
}

/// One knob value's measurements.
#[derive(Debug, Clone, serde::Serialize)]
pub struct Row {
    pub value: f64,
    pub is_reference: bool,
    /// GPU ms per frame over every frame of every repeat.
    pub ms_median: f64,
    pub ms_min: f64,
    pub ms_max: f64,
    /// Mean over frames of the mean absolute error (8-bit levels, RGB).
    pub mean_error: f64,
    /// Largest absolute error of any channel of any frame (8-bit levels).
    pub max_error: f64,
    /// Mean over frames; `None` (infinite) when every frame equals the reference.
    pub psnr_db: Option<f64>,
    /// Mean over frames; 1 = identical.
    pub ssim: f64,
}

/// One knob of one program.
#[derive(Debug, Clone, serde::Serialize)]
pub struct KnobReport {
    pub program: String,
    pub knob: String,
    pub reference: f64,
    pub frames: u32,
    pub size: (u32, u32),
    pub repeats: u32,
    /// `"timestamps"` or `"wall"`.
    pub clock: &'static str,
    pub rows: Vec<Row>,
}

/// The result of a run.
pub struct BenchResult {
    pub outcome: Outcome,
    pub reports: Vec<KnobReport>,
    pub adapter: Option<String>,
}

/// Runs check, then the sweeps of every program with knobs.
pub fn run(request: &Request) -> BenchResult {
    let (mut outcome, checked) = request.input.check();
    let mut result = BenchResult { outcome: Outcome::default(), reports: Vec::new(), adapter: None };
    let mut gpu: Option<Gpu> = None;
    for c in checked.iter().filter(|c| !c.failed) {
        let Some(effect) = c.effect.as_ref() else {
            outcome.diagnostics.push(
                Diagnostic::new(Code::NothingToBench, format!("`{}` has no manifest: nothing to sweep", c.name))
                    .with_help("bench an effect.toml with a [knobs] table or a --knob over one of its [uniforms]"),
            );
            continue;
        };
        let knobs = match knobs_of(effect, request) {
            Ok(k) => k,
            Err(d) => {
                outcome.diagnostics.push(*d);
                continue;
            }
        };
        let Some(gpu) = command::open_once(&mut gpu, &mut result.adapter, &mut outcome) else { break };
        for (name, values, reference, template) in knobs {
            if let Some(report) = sweep(gpu, c, &mut outcome, request, &name, &values, reference, &template) {
                result.reports.push(report);
            }
        }
    }
    crate::diag::sort(&mut outcome.diagnostics);
    result.outcome = outcome;
    result
}

/// The knobs to sweep: (name, values, reference, the default value as a template of its type).
type Knob = (String, Vec<f64>, f64, UniformValue);

fn knobs_of(effect: &Effect, request: &Request) -> Result<Vec<Knob>, Box<Diagnostic>> {
    let default_of = |name: &str| effect.uniform(name).and_then(|u| u.value.clone()).filter(|v| v.as_f64().is_some());
    if request.knobs.is_empty() {
        if effect.knobs.is_empty() {
            return Err(Box::new(Diagnostic::new(Code::NothingToBench, format!("effect `{}` has no [knobs] and no --knob was given", effect.name))
                .in_file(effect.file)
                .with_help("add e.g. `[knobs]` / `numLayers = { values = [4, 8, 16, 32], reference = 32 }`, or pass --knob numLayers=4,8,16,32")));
        }
        return Ok(effect
            .knobs
            .iter()
            .filter_map(|k| Some((k.name.clone(), k.values.clone(), k.reference, default_of(&k.name)?)))
            .collect());
    }
    let mut out = Vec::new();
    for (name, values) in &request.knobs {
        let Some(template) = default_of(name) else {
            let numeric: Vec<String> = effect
                .uniforms
                .iter()
                .filter(|u| u.value.as_ref().and_then(UniformValue::as_f64).is_some())
                .map(|u| format!("`{}`", u.name))
                .collect();
            return Err(Box::new(
                Diagnostic::new(Code::KnobUnknown, format!("--knob `{name}` names no numeric [uniforms] entry of `{}`", effect.name))
                    .in_file(effect.file)
                    .with_note(if numeric.is_empty() {
                        "the manifest gives no numeric uniform".to_string()
                    } else {
                        format!("numeric uniforms: {}", numeric.join(", "))
                    }),
            ));
        };
        let reference = *values.last().expect("parsed lists are non-empty");
        out.push((name.clone(), values.clone(), reference, template));
    }
    Ok(out)
}

/// `value` in the uniform's own kind: an integer uniform gets an integer.
fn typed(value: f64, template: &UniformValue) -> UniformValue {
    match template {
        UniformValue::Int(_) => UniformValue::Int(value.round() as i64),
        _ => UniformValue::Float(value),
    }
}

#[allow(clippy::too_many_arguments)]
fn sweep(
    gpu: &Gpu,
    c: &check::Checked,
    outcome: &mut Outcome,
    request: &Request,
    name: &str,
    values: &[f64],
    reference: f64,
    template: &UniformValue,
) -> Option<KnobReport> {
    let memory = MemoryRequest {
        size: request.size,
        frames: request.frames,
        start: 0.0,
        step: request.step,
        float: false,
        timeout: request.timeout,
        read_back: None,
        degenerate: None,
    };
    // Warm-up: the first pipelines and the first frames are slower (caches, page faults).
    memory::render_in_memory(gpu, c, outcome, &[], MemoryRequest { frames: request.frames.min(2), ..memory })?;
    let mut runs: Vec<(f64, MemoryRun, Vec<f64>)> = Vec::new();
    for &value in values {
        let overrides = [(name.to_string(), typed(value, template))];
        let mut first = None;
        let mut times = Vec::new();
        for _ in 0..request.repeats.max(1) {
            let run = memory::render_in_memory(gpu, c, outcome, &overrides, memory)?;
            times.extend_from_slice(&run.gpu_ms);
            first.get_or_insert(run);
        }
        runs.push((value, first?, times));
    }
    let reference_frames = runs.iter().find(|(v, _, _)| *v == reference).map(|(_, r, _)| rgba8(&r.frames))?;
    let clock = match runs[0].1.clock {
        GpuClock::Timestamps => "timestamps",
        GpuClock::Wall => "wall",
    };
    let rows = runs
        .into_iter()
        .map(|(value, run, mut times)| {
            times.sort_by(f64::total_cmp);
            let errors: Vec<FrameError> =
                rgba8(&run.frames).iter().zip(&reference_frames).map(|(a, b)| frame_error(a, b, request.size)).collect();
            let n = errors.len().max(1) as f64;
            let psnr: Vec<f64> = errors.iter().filter_map(|e| e.psnr_db).collect();
            Row {
                value,
                is_reference: value == reference,
                ms_median: times[times.len() / 2],
                ms_min: times[0],
                ms_max: times[times.len() - 1],
                mean_error: errors.iter().map(|e| e.mean).sum::<f64>() / n,
                max_error: errors.iter().map(|e| e.max).fold(0.0, f64::max),
                // Frames equal to the reference have infinite PSNR; the mean is over the others.
                psnr_db: (!psnr.is_empty()).then(|| psnr.iter().sum::<f64>() / psnr.len() as f64),
                ssim: errors.iter().map(|e| e.ssim).sum::<f64>() / n,
            }
        })
        .collect();
    Some(KnobReport {
        program: c.effect.as_ref().map_or(c.name.clone(), |e| e.name.clone()),
        knob: name.to_string(),
        reference,
        frames: request.frames,
        size: request.size,
        repeats: request.repeats.max(1),
        clock,
        rows,
    })
}

/// The frames as RGBA8.
fn rgba8(frames: &[Pixels]) -> Vec<Vec<u8>> {
    frames
        .iter()
        .map(|p| match p {
            Pixels::Rgba8(b) => b.clone(),
            Pixels::Rgba32F(f) => crate::render::encode::float_to_rgba8(f),
        })
        .collect()
}

/// Errors of one frame against the reference frame.
struct FrameError {
    mean: f64,
    max: f64,
    psnr_db: Option<f64>,
    ssim: f64,
}

fn frame_error(frame: &[u8], reference: &[u8], (w, h): (u32, u32)) -> FrameError {
    let mut sum = 0.0f64;
    let mut sum_sq = 0.0f64;
    let mut max = 0.0f64;
    let mut count = 0usize;
    for (a, b) in frame.chunks_exact(4).zip(reference.chunks_exact(4)) {
        for c in 0..3 {
            let d = (f64::from(a[c]) - f64::from(b[c])).abs();
            sum += d;
            sum_sq += d * d;
            max = max.max(d);
            count += 1;
        }
    }
    let count = count.max(1) as f64;
    let mse = sum_sq / count;
    let rgb = |p: &[u8]| image::RgbImage::from_raw(w, h, p.chunks_exact(4).flat_map(|c| [c[0], c[1], c[2]]).collect());
    let ssim = match (rgb(frame), rgb(reference)) {
        (Some(a), Some(b)) => image_compare::rgb_hybrid_compare(&a, &b).map_or(f64::NAN, |s| s.score),
        _ => f64::NAN,
    };
    FrameError { mean: sum / count, max, psnr_db: (mse > 0.0).then(|| 10.0 * (255.0f64 * 255.0 / mse).log10()), ssim }
}

/// `NAME=v1,v2,…` → (name, values).
pub fn parse_knob(s: &str) -> Result<(String, Vec<f64>), String> {
    let (name, list) = s.split_once('=').ok_or_else(|| format!("{}: expected NAME=v1,v2,…, got `{s}`", Code::KnobValues))?;
    let values: Result<Vec<f64>, String> = list
        .split(',')
        .map(|v| {
            v.trim()
                .parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| format!("{}: `{v}` is not a finite number", Code::KnobValues))
        })
        .collect();
    let values = values?;
    if name.trim().is_empty() || values.is_empty() {
        return Err(format!("{}: expected NAME=v1,v2,…, got `{s}`", Code::KnobValues));
    }
    Ok((name.trim().to_string(), values))
}

/// The human table of one report.
pub fn table(r: &KnobReport) -> String {
    let clock = match r.clock {
        "timestamps" => "GPU timestamps",
        _ => "wall time from submit to completion (no timestamp queries)",
    };
    let mut text = format!(
        "{} — knob `{}` (reference {}), {} frame{} at {}x{}, {} repeat{}; ms/frame from {clock}\n",
        r.program,
        r.knob,
        number(r.reference),
        r.frames,
        if r.frames == 1 { "" } else { "s" },
        r.size.0,
        r.size.1,
        r.repeats,
        if r.repeats == 1 { "" } else { "s" },
    );
    text.push_str(&format!(
        "  {:>10}  {:>26}  {:>9}  {:>8}  {:>8}  {:>7}\n",
        "value", "ms/frame median [min-max]", "mean err", "max err", "PSNR dB", "SSIM"
    ));
    for row in &r.rows {
        let psnr = row.psnr_db.map_or("inf".to_string(), |p| format!("{p:.1}"));
        let ms = format!("{:.3} [{:.3}-{:.3}]", row.ms_median, row.ms_min, row.ms_max);
        text.push_str(&format!(
            "  {:>10}  {ms:>26}  {:>9.3}  {:>8.0}  {psnr:>8}  {:>7.4}{}\n",
            number(row.value),
            row.mean_error,
            row.max_error,
            row.ssim,
            if row.is_reference { "  (reference)" } else { "" }
        ));
    }
    text
}

/// A knob value as written (`4`, not `4.0`).
fn number(v: f64) -> String {
    if v.fract() == 0.0 && v.abs() < 1e15 {
        format!("{}", v as i64)
    } else {
        format!("{v}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn knob_flags_parse() {
        assert_eq!(parse_knob("numLayers=4,8, 16").unwrap(), ("numLayers".to_string(), vec![4.0, 8.0, 16.0]));
        assert!(parse_knob("numLayers").is_err());
        assert!(parse_knob("numLayers=4,x").is_err());
        assert!(parse_knob("=4").is_err());
        assert!(parse_knob("a=nan").is_err());
    }

    #[test]
    fn frame_errors_measure_difference() {
        let a = [100u8, 100, 100, 255].repeat(64);
        let same = frame_error(&a, &a, (8, 8));
        assert_eq!((same.mean, same.max, same.psnr_db), (0.0, 0.0, None));
        assert!((same.ssim - 1.0).abs() < 1e-6);
        let mut b = a.clone();
        b[0] = 110; // one channel of one pixel off by 10
        let e = frame_error(&b, &a, (8, 8));
        assert_eq!(e.max, 10.0);
        assert!((e.mean - 10.0 / 192.0).abs() < 1e-9);
        let psnr = e.psnr_db.unwrap();
        assert!((psnr - 10.0 * (255.0f64 * 255.0 / (100.0 / 192.0)).log10()).abs() < 1e-9);
        assert!(e.ssim < 1.0);
        assert_eq!(typed(3.6, &UniformValue::Int(1)), UniformValue::Int(4));
        assert_eq!(typed(3.5, &UniformValue::Float(1.0)), UniformValue::Float(3.5));
    }
}
