//! The `effectc` binary: parse flags, dispatch to one library module per subcommand, map
//! the outcome to an exit code (0 clean, 1 problems in the input, 2 usage or IO errors).

use std::io::{IsTerminal, Write};
use std::process::ExitCode;

use clap::Parser;
use effectc::back::{Target, TranslateOptions};
use effectc::check::Outcome;
use effectc::cli::{BenchArgs, CheckArgs, Cli, ColorChoice, Command, CommonArgs, Format, RenderArgs, StressArgs, TargetArg, TranslateArgs};
use effectc::diag;
use effectc::front::program::FrontOptions;

fn main() -> ExitCode {
    // naga can panic on odd inputs; those panics are caught and reported as diagnostics,
    // so the default hook's message would only be noise.
    if std::env::var_os("EFFECTC_SHOW_PANICS").is_none() {
        std::panic::set_hook(Box::new(|_| {}));
    }
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            let _ = e.print();
            return ExitCode::from(if e.use_stderr() { 2 } else { 0 });
        }
    };
    match cli.command {
        Command::Check(args) => check(args),
        Command::Translate(args) => translate(args),
        Command::Render(args) => render(args),
        Command::Bench(args) => bench(args),
        Command::Stress(args) => stress(args),
    }
}

fn render(args: RenderArgs) -> ExitCode {
    let started = std::time::Instant::now();
    let c = &args.common;
    if !(args.timeout.is_finite() && args.timeout > 0.0) {
        eprintln!("error: --timeout must be a positive number of seconds");
        return ExitCode::from(2);
    }
    let step = match (args.fps, args.time_step) {
        (Some(f), _) => effectc::render::command::Step::Fps(f),
        (None, Some(s)) => effectc::render::command::Step::Seconds(s),
        (None, None) => effectc::render::command::Step::Default,
    };
    let request = effectc::render::command::Request {
        inputs: c.inputs.clone(),
        stage: c.stage.map(Into::into),
        front: FrontOptions { strict: c.strict },
        back: TranslateOptions::for_rendering(!args.keep_gl_depth),
        frames: args.frames,
        step,
        start: args.start,
        size: args.size,
        out: args.out.clone(),
        contact_sheet: args.contact_sheet,
        gif: args.gif,
        float: args.float,
        timeout: std::time::Duration::from_secs_f64(args.timeout),
        progress: std::io::stderr().is_terminal() && std::env::var_os("CI").is_none(),
        started,
        dump_targets: args.dump_targets,
    };
    let result = effectc::render::command::run(&request);
    let mut text = String::new();
    if c.format == Format::Human {
        if let (true, Some(a)) = (args.verbose, &result.adapter) {
            text.push_str(&format!("adapter: {a}\n"));
        }
        for r in &result.rendered {
            text.push_str(&effectc::render::command::summary(r, args.timings, args.verbose, args.explain));
        }
    }
    text.push_str(&diagnostics_text(c, &result.outcome));
    let printed = print(&text);
    if result.hung {
        // The GPU is still running the stuck frame; leave without waiting for it.
        std::process::exit(1);
    }
    if printed.is_err() {
        return ExitCode::from(2);
    }
    exit_code(&result.outcome, false)
}

fn bench(args: BenchArgs) -> ExitCode {
    let c = &args.common;
    let limits_ok = args.frames >= 1
        && args.frames <= 1000
        && args.repeats >= 1
        && args.repeats <= 100
        && (1..=effectc::manifest::MAX_FRAME_SIDE).contains(&args.size.0)
        && (1..=effectc::manifest::MAX_FRAME_SIDE).contains(&args.size.1)
        && args.timeout.is_finite()
        && args.timeout > 0.0;
    if !limits_ok {
        eprintln!("error: --frames must be 1..=1000, --repeats 1..=100, --size 1..=8192 per side, --timeout positive");
        return ExitCode::from(2);
    }
    let request = effectc::bench::Request {
        inputs: c.inputs.clone(),
        stage: c.stage.map(Into::into),
        front: FrontOptions { strict: c.strict },
        knobs: args.knobs.clone(),
        frames: args.frames,
        size: args.size,
        repeats: args.repeats,
        step: 0.125,
        timeout: std::time::Duration::from_secs_f64(args.timeout),
    };
    let mut result = effectc::bench::run(&request);
    if let Some(path) = &args.plot {
        if let Err(e) = effectc::bench::plot::write_svg(path, &result.reports) {
            result.outcome.io_error |= !result.reports.is_empty();
            result.outcome.diagnostics.push(effectc::diag::Diagnostic::error(effectc::output::E_OUTPUT_IO, e));
        }
    }
    let text = match c.format {
        Format::Json => report_json("reports", &result.reports, &result.adapter, &result.outcome),
        _ => {
            let mut text = String::new();
            if let Some(a) = &result.adapter {
                text.push_str(&format!("adapter: {a}\n"));
            }
            for r in &result.reports {
                text.push_str(&effectc::bench::table(r));
            }
            if let Some(p) = args.plot.as_ref().filter(|_| !result.reports.is_empty()) {
                text.push_str(&format!("plot: {}\n", p.display()));
            }
            text + &diagnostics_text(c, &result.outcome)
        }
    };
    if print(&text).is_err() {
        return ExitCode::from(2);
    }
    exit_code(&result.outcome, false)
}

fn stress(args: StressArgs) -> ExitCode {
    let c = &args.common;
    let sizes_ok =
        (1..=effectc::manifest::MAX_FRAME_SIDE).contains(&args.size.0) && (1..=effectc::manifest::MAX_FRAME_SIDE).contains(&args.size.1);
    if !sizes_ok || args.samples > 10_000 || !(args.timeout.is_finite() && args.timeout > 0.0) {
        eprintln!("error: --size must be 1..=8192 per side, --samples at most 10000, --timeout positive");
        return ExitCode::from(2);
    }
    let request = effectc::stress::Request {
        inputs: c.inputs.clone(),
        stage: c.stage.map(Into::into),
        front: FrontOptions { strict: c.strict },
        samples: args.samples,
        seed: args.seed,
        size: args.size,
        timeout: std::time::Duration::from_secs_f64(args.timeout),
        out: Some(args.out.clone().unwrap_or_else(|| std::path::PathBuf::from("out/stress"))),
    };
    let result = effectc::stress::run(&request);
    let text = match c.format {
        Format::Json => report_json("programs", &result.reports, &result.adapter, &result.outcome),
        _ => {
            let mut text = String::new();
            for r in &result.reports {
                text.push_str(&effectc::stress::table(r));
            }
            text + &diagnostics_text(c, &result.outcome)
        }
    };
    if print(&text).is_err() {
        return ExitCode::from(2);
    }
    exit_code(&result.outcome, false)
}

fn check(args: CheckArgs) -> ExitCode {
    let c = &args.common;
    let options = FrontOptions { strict: c.strict };
    let (outcome, _) = effectc::check::check_inputs(&c.inputs, c.stage.map(Into::into), options);
    let text = diagnostics_text(c, &outcome);
    if print(&text).is_err() {
        return ExitCode::from(2);
    }
    exit_code(&outcome, args.deny_warnings)
}

fn translate(args: TranslateArgs) -> ExitCode {
    let c = &args.common;
    let mut targets: Vec<Target> = Vec::new();
    for t in &args.to {
        match t {
            TargetArg::All => targets.extend(Target::ALL),
            one => targets.push(target_of(*one)),
        }
    }
    targets.sort();
    targets.dedup();
    let request = effectc::translate::Request {
        inputs: c.inputs.clone(),
        stage: c.stage.map(Into::into),
        front: FrontOptions { strict: c.strict },
        back: TranslateOptions { gl_depth: !args.keep_gl_depth, ..TranslateOptions::default() },
        targets,
        out: args.out.clone(),
    };
    let (outcome, written) = effectc::translate::run(&request);
    let mut text = String::new();
    if c.format == Format::Human {
        for w in &written {
            text.push_str(&effectc::translate::summary(w, args.explain));
        }
    }
    text.push_str(&diagnostics_text(c, &outcome));
    if print(&text).is_err() {
        return ExitCode::from(2);
    }
    exit_code(&outcome, false)
}

fn target_of(t: TargetArg) -> Target {
    match t {
        TargetArg::Wgsl => Target::Wgsl,
        TargetArg::Spv => Target::Spv,
        TargetArg::Spvasm => Target::Spvasm,
        TargetArg::Glsl => Target::Glsl,
        TargetArg::Msl => Target::Msl,
        TargetArg::Hlsl => Target::Hlsl,
        TargetArg::Reflect => Target::Reflect,
        TargetArg::Ir | TargetArg::All => Target::Ir,
    }
}

/// The diagnostics in the requested format (human: with the summary line).
fn diagnostics_text(c: &CommonArgs, outcome: &Outcome) -> String {
    let color = match c.color {
        ColorChoice::Always => true,
        ColorChoice::Never => false,
        ColorChoice::Auto => std::io::stdout().is_terminal() && std::env::var_os("NO_COLOR").is_none(),
    };
    let d = &outcome.diagnostics;
    match c.format {
        Format::Human => {
            let mut t = diag::render_human(d, &outcome.files, color);
            t.push_str(&diag::summary_line(d, outcome.programs));
            t.push('\n');
            t
        }
        Format::Json => diag::render_json(d, &outcome.files),
        Format::Github => diag::render_github(d, &outcome.files),
        Format::Sarif => diag::render_sarif(d, &outcome.files),
    }
}

/// The JSON document of `bench` and `stress`: the reports under `key`, the adapter and the
/// diagnostics (the same objects as `--format json` elsewhere).
fn report_json(key: &str, reports: &impl serde::Serialize, adapter: &Option<String>, outcome: &Outcome) -> String {
    let diagnostics: serde_json::Value = serde_json::from_str(&diag::render_json(&outcome.diagnostics, &outcome.files)).unwrap_or_default();
    let mut doc = serde_json::json!({ "version": 1, "adapter": adapter, "diagnostics": diagnostics });
    doc[key] = serde_json::to_value(reports).unwrap_or_default();
    serde_json::to_string_pretty(&doc).unwrap_or_default() + "\n"
}

fn print(text: &str) -> std::io::Result<()> {
    let mut stdout = std::io::stdout().lock();
    stdout.write_all(text.as_bytes()).and_then(|_| stdout.flush())
}

/// 2 for usage/IO errors, 1 for errors in the input (or warnings when denied), else 0.
fn exit_code(outcome: &Outcome, deny_warnings: bool) -> ExitCode {
    let d = &outcome.diagnostics;
    if outcome.io_error {
        ExitCode::from(2)
    } else if diag::has_errors(d) || (deny_warnings && diag::count(d, diag::Severity::Warning) > 0) {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}
