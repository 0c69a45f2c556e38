//! The `effectc` binary: parse flags, dispatch to one library module per subcommand, map
//! the outcome to an exit code (0 clean, 1 problems in the input, 2 usage or IO errors).

use std::io::{IsTerminal, Write};
use std::process::ExitCode;

use clap::{CommandFactory, Parser};
use effectc::check::Outcome;
use effectc::cli::{BenchArgs, CheckArgs, Cli, ColorChoice, Command, CommonArgs, Format, RenderArgs, StressArgs, TranslateArgs};
use effectc::diag;

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

/// A usage error of `effectc render` the parser could not see, printed the way clap prints
/// its own (exit 2).
fn render_usage_error(message: String) -> ExitCode {
    let mut command = Cli::command();
    command.build();
    let mut render = command.find_subcommand_mut("render").cloned().unwrap_or(command);
    let _ = render.error(clap::error::ErrorKind::ArgumentConflict, message).print();
    ExitCode::from(2)
}

fn render(args: RenderArgs) -> ExitCode {
    let started = std::time::Instant::now();
    if let Some(message) = args.usage_error() {
        return render_usage_error(message);
    }
    let streams = args.streams();
    if streams && std::io::stdout().is_terminal() {
        return render_usage_error(
            "`--out -` writes binary frames to stdout, which is a terminal here; pipe it (`| ffmpeg -f image2pipe -i - out.mp4`)".into(),
        );
    }
    let request = args.request(started);
    let c = &args.common;
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
    // With `--out -`, stdout carries only frame bytes: the report goes to stderr.
    let printed = if streams {
        text.push_str(&diagnostics_for(c, &result.outcome, std::io::stderr().is_terminal()));
        let mut stderr = std::io::stderr().lock();
        stderr.write_all(text.as_bytes()).and_then(|_| stderr.flush())
    } else {
        text.push_str(&diagnostics_text(c, &result.outcome));
        print(&text)
    };
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
    let request = args.request();
    let mut result = effectc::bench::run(&request);
    if let Some(path) = &args.plot {
        if let Err(e) = effectc::bench::plot::write_svg(path, &result.reports) {
            result.outcome.io_error |= !result.reports.is_empty();
            result.outcome.diagnostics.push(diag::Diagnostic::new(diag::Code::OutputIo, e));
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
    let request = args.request();
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
    let (outcome, _) = c.input_spec().check();
    let text = diagnostics_text(c, &outcome);
    if print(&text).is_err() {
        return ExitCode::from(2);
    }
    exit_code(&outcome, args.deny_warnings)
}

fn translate(args: TranslateArgs) -> ExitCode {
    let c = &args.common;
    let request = args.request();
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

/// The diagnostics in the requested format for stdout (human: with the summary line).
fn diagnostics_text(c: &CommonArgs, outcome: &Outcome) -> String {
    diagnostics_for(c, outcome, std::io::stdout().is_terminal())
}

/// The diagnostics in the requested format, coloured in `auto` when they go to a terminal.
fn diagnostics_for(c: &CommonArgs, outcome: &Outcome, terminal: bool) -> String {
    let color = match c.color {
        ColorChoice::Always => true,
        ColorChoice::Never => false,
        ColorChoice::Auto => terminal && std::env::var_os("NO_COLOR").is_none(),
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
