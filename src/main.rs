//! The `effectc` binary: parse flags, dispatch to one library module per subcommand, map
//! the outcome to an exit code (0 clean, 1 problems in the input, 2 usage or IO errors).

use std::io::{IsTerminal, Write};
use std::process::ExitCode;

use clap::Parser;
use effectc::cli::{CheckArgs, Cli, ColorChoice, Command, Format};
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
    }
}

fn check(args: CheckArgs) -> ExitCode {
    let options = FrontOptions { strict: args.strict };
    let (outcome, _) = effectc::check::check_inputs(&args.inputs, args.stage.map(Into::into), options);
    let color = match args.color {
        ColorChoice::Always => true,
        ColorChoice::Never => false,
        ColorChoice::Auto => std::io::stdout().is_terminal() && std::env::var_os("NO_COLOR").is_none(),
    };
    let d = &outcome.diagnostics;
    let text = match args.format {
        Format::Human => {
            let mut t = diag::render_human(d, &outcome.files, color);
            t.push_str(&diag::summary_line(d, outcome.programs));
            t.push('\n');
            t
        }
        Format::Json => diag::render_json(d, &outcome.files),
        Format::Github => diag::render_github(d, &outcome.files),
        Format::Sarif => diag::render_sarif(d, &outcome.files),
    };
    let mut stdout = std::io::stdout().lock();
    if stdout.write_all(text.as_bytes()).and_then(|_| stdout.flush()).is_err() {
        return ExitCode::from(2);
    }
    if outcome.io_error {
        ExitCode::from(2)
    } else if diag::has_errors(d) || (args.deny_warnings && diag::count(d, diag::Severity::Warning) > 0) {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}
