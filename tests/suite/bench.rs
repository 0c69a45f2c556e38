//! `effectc bench`: a knob sweep's error falls to 0 at the reference and its plot is
//! written; knobs that name no uniform, effects without knobs and malformed `--knob` flags
//! are reported. (Times are printed, never asserted: speed lives in benchmarks.)

use effectc::diag::Code;

use crate::common::{code, effectc, scratch, stdout};
use crate::render::have_gpu;

#[test]
fn pom_layers_sweep_converges_on_the_reference() {
    if !have_gpu() {
        return;
    }
    let dir = scratch("bench", "pom");
    let plot = dir.join("pom.svg");
    let out = effectc(&[
        "bench",
        "effects/pom/effect.toml",
        "--frames",
        "2",
        "--size",
        "64x64",
        "--repeats",
        "1",
        "--format",
        "json",
        "--plot",
        plot.to_str().unwrap(),
    ]);
    let text = stdout(&out);
    assert_eq!(code(&out), 0, "{text}");
    let doc: serde_json::Value = serde_json::from_str(&text).unwrap_or_else(|e| panic!("{e}: {text}"));
    let report = &doc["reports"][0];
    assert_eq!(report["knob"], "numLayers");
    assert_eq!(report["reference"], 64.0);
    let rows = report["rows"].as_array().unwrap();
    let values: Vec<f64> = rows.iter().map(|r| r["value"].as_f64().unwrap()).collect();
    assert_eq!(values, [2.0, 4.0, 8.0, 16.0, 32.0, 64.0]);
    let errors: Vec<f64> = rows.iter().map(|r| r["mean_error"].as_f64().unwrap()).collect();
    let ssim: Vec<f64> = rows.iter().map(|r| r["ssim"].as_f64().unwrap()).collect();
    assert_eq!(errors[5], 0.0, "{errors:?}");
    assert!(rows[5]["is_reference"].as_bool().unwrap() && rows[5]["psnr_db"].is_null());
    // More layers, less error: every step toward the reference lowers the error.
    assert!(errors.windows(2).all(|w| w[1] < w[0]), "{errors:?}");
    assert!(ssim.windows(2).all(|w| w[1] >= w[0]), "{ssim:?}");
    assert!(errors[0] > 1.0, "two layers are visibly wrong: {errors:?}");
    for r in rows {
        let (lo, mid, hi) = (r["ms_min"].as_f64().unwrap(), r["ms_median"].as_f64().unwrap(), r["ms_max"].as_f64().unwrap());
        assert!(lo > 0.0 && lo <= mid && mid <= hi, "{r}");
    }
    let svg = std::fs::read_to_string(&plot).unwrap();
    assert!(svg.starts_with("<svg") && svg.contains("numLayers") && svg.matches("<circle").count() == 6, "{svg}");
}

#[test]
fn bench_mistakes_are_reported() {
    // A --knob over a name that is not a numeric uniform.
    let out = effectc(&["bench", "effects/pom/effect.toml", "--knob", "numLayer=1,2"]);
    assert_eq!(code(&out), 1, "{}", stdout(&out));
    assert!(stdout(&out).contains(Code::KnobUnknown.as_str()) && stdout(&out).contains("`numLayers`"), "{}", stdout(&out));
    // An effect without [knobs] and no --knob.
    let out = effectc(&["bench", "effects/phong/effect.toml"]);
    assert_eq!(code(&out), 1, "{}", stdout(&out));
    assert!(stdout(&out).contains(Code::NothingToBench.as_str()), "{}", stdout(&out));
    // A malformed flag is a usage error.
    let out = effectc(&["bench", "effects/pom/effect.toml", "--knob", "numLayers=4,x"]);
    assert_eq!(code(&out), 2);
}
