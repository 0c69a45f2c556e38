//! The `effectc` binary: parse flags, dispatch to one library module per subcommand, map
//! the outcome to an exit code (0 clean, 1 problems in the input, 2 usage or IO errors).

use std::io::{IsTerminal, Write};
use std::path::PathBuf;
use std::process::ExitCode;

use clap::Parser;
use effectc::check::Outcome;
use effectc::cli::{BenchArgs, CheckArgs, Cli, ColorChoice, Command, CommonArgs, Format, RenderArgs, StressArgs, TranslateArgs};
use effectc::{config, diag};

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
    let common = match &cli.command {
        Command::Check(a) => &a.common,
        Command::Translate(a) => &a.common,
        Command::Render(a) => &a.common,
        Command::Bench(a) => &a.common,
        Command::Stress(a) => &a.common,
    };
    match &cli.command {
        Command::Check(args) => repeat(common, args.watch, |s, _| check(args, s)),
        Command::Translate(args) => repeat(common, args.watch, |s, _| translate(args, s)),
        Command::Render(args) => repeat(common, args.watch, |s, changed| render(args, s, changed)),
        Command::Bench(args) => repeat(common, false, |s, _| bench(args, s)),
        Command::Stress(args) => repeat(common, false, |s, _| stress(args, s)),
    }
}

/// Runs `command` with the repository's settings once, or with `--watch` again after
/// every change to a file it read (settings read anew each round) until interrupted.
/// `command` gets the changed files (`None` the first time) and returns its exit code and
/// the files it read.
fn repeat(
    common: &CommonArgs,
    watch: bool,
    mut command: impl FnMut(&config::Loaded, Option<&[PathBuf]>) -> (ExitCode, Vec<PathBuf>),
) -> ExitCode {
    let mut round = |changed: Option<&[PathBuf]>| -> (ExitCode, Vec<PathBuf>) {
        let settings = config::load(common.config.as_deref(), &common.inputs);
        let mut read: Vec<PathBuf> = settings.config.path.iter().cloned().collect();
        if settings.failed() {
            let outcome =
                Outcome { files: settings.files.clone(), diagnostics: settings.diagnostics.clone(), io_error: true, ..Outcome::default() };
            let _ = print(&diagnostics_text(common, &outcome));
            return (ExitCode::from(2), read);
        }
        let (code, r) = command(&settings, changed);
        read.extend(r);
        (code, read)
    };
    if !watch {
        return round(None).0;
    }
    let clear = std::io::stdout().is_terminal();
    let result = effectc::watch::run(&common.inputs, clear, |changed| {
        if let Some(changed) = changed {
            let names: Vec<String> = changed
                .iter()
                .map(|p| diag::paths::display_path(&p.display().to_string(), std::env::current_dir().ok().as_deref()))
                .collect();
            eprintln!("[watch] changed: {}", names.join(", "));
        }
        let (_, read) = round(changed);
        eprintln!("[watch] watching {} files; Ctrl-C stops", read.len());
        read
    });
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("effectc: {e}");
            ExitCode::from(2)
        }
    }
}

/// Which command runs: what it can report, for [`settle`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Reach {
    Check,
    Translate,
    Render,
    Stress,
    Bench,
}

impl Reach {
    /// Can this command report `code` at all? (A suppression of a code only `render`
    /// reports is not unused when `check` runs.)
    fn reports(self, code: diag::Code) -> bool {
        let s = code.as_str();
        let group = &s[1..3];
        match group {
            "00" | "01" | "02" => true,
            "03" => self != Reach::Check,
            "04" => matches!(self, Reach::Render | Reach::Stress | Reach::Bench),
            "07" if matches!(s, "E0701" | "W0702") => self == Reach::Stress,
            "07" => true,
            "08" => self == Reach::Bench,
            _ => true,
        }
    }
}

/// The outcome after the repository's settings: the settings file's own diagnostics added,
/// inline suppressions and the policy applied, in reporting order.
fn settle(mut outcome: Outcome, settings: &config::Loaded, reach: Reach) -> Outcome {
    let about_settings = settings.attach(&mut outcome.files);
    outcome.diagnostics.extend(about_settings);
    let diags = std::mem::take(&mut outcome.diagnostics);
    outcome.diagnostics = diag::suppress::apply(diags, &outcome.files, &settings.config.policy, &|c| reach.reports(c));
    diag::sort(&mut outcome.diagnostics);
    outcome
}

fn render(args: &RenderArgs, settings: &config::Loaded, changed: Option<&[PathBuf]>) -> (ExitCode, Vec<PathBuf>) {
    let mut request = args.request(&settings.config, std::time::Instant::now());
    request.only = changed.map(|c| c.to_vec());
    let c = &args.common;
    let mut result = effectc::render::command::run(&request);
    result.outcome = settle(result.outcome, settings, Reach::Render);
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
        return (ExitCode::from(2), Vec::new());
    }
    (exit_code(&result.outcome, false), result.outcome.read)
}

fn bench(args: &BenchArgs, settings: &config::Loaded) -> (ExitCode, Vec<PathBuf>) {
    let c = &args.common;
    let request = args.request(&settings.config);
    let mut result = effectc::bench::run(&request);
    if let Some(path) = &args.plot {
        if let Err(e) = effectc::bench::plot::write_svg(path, &result.reports) {
            result.outcome.io_error |= !result.reports.is_empty();
            result.outcome.diagnostics.push(diag::Diagnostic::new(diag::Code::OutputIo, e));
        }
    }
    result.outcome = settle(result.outcome, settings, Reach::Bench);
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
        return (ExitCode::from(2), Vec::new());
    }
    (exit_code(&result.outcome, false), result.outcome.read)
}

fn stress(args: &StressArgs, settings: &config::Loaded) -> (ExitCode, Vec<PathBuf>) {
    let c = &args.common;
    let request = args.request(&settings.config);
    let mut result = effectc::stress::run(&request);
    result.outcome = settle(result.outcome, settings, Reach::Stress);
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
        return (ExitCode::from(2), Vec::new());
    }
    (exit_code(&result.outcome, false), result.outcome.read)
}

fn check(args: &CheckArgs, settings: &config::Loaded) -> (ExitCode, Vec<PathBuf>) {
    let c = &args.common;
    let (outcome, checked) = c.input_spec(&settings.config).check();
    let outcome = settle(outcome, settings, Reach::Check);
    let text = match (args.list_uniforms, c.format) {
        (true, Format::Json) => report_json("programs", &effectc::check::listing::uniforms(&checked), &None, &outcome),
        (true, _) => effectc::check::listing::text(&effectc::check::listing::uniforms(&checked)) + &diagnostics_text(c, &outcome),
        (false, _) => diagnostics_text(c, &outcome),
    };
    if print(&text).is_err() {
        return (ExitCode::from(2), Vec::new());
    }
    (exit_code(&outcome, args.deny_warnings || settings.config.deny_warnings), outcome.read)
}

fn translate(args: &TranslateArgs, settings: &config::Loaded) -> (ExitCode, Vec<PathBuf>) {
    let c = &args.common;
    let request = args.request(&settings.config);
    let (outcome, written) = effectc::translate::run(&request);
    let outcome = settle(outcome, settings, Reach::Translate);
    let mut text = String::new();
    if c.format == Format::Human {
        for w in &written {
            text.push_str(&effectc::translate::summary(w, args.explain));
        }
    }
    text.push_str(&diagnostics_text(c, &outcome));
    if print(&text).is_err() {
        return (ExitCode::from(2), Vec::new());
    }
    (exit_code(&outcome, false), outcome.read)
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
