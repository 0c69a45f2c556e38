//! Benchmark: the static hazard analysis of many programs, with its witness runs (what
//! `check` does) against the interval analysis alone (the analysis before witness runs,
//! every hazard possible), in one process. The front runs once per program, untimed; each
//! round times both variants over every program, alternating, so drift hits both alike.
//! The hazard issue bounds the ratio with / without at 1.2.
//!
//! Run: `cargo bench --bench hazard_speed -- --corpus DIR --limit 600 --rounds 3`. `DIR`
//! holds one directory per program (checked as bare stage files, the dialect told by the
//! text); without `--corpus`, the repository's effects and test programs.

#[path = "support/args.rs"]
mod args;

use std::path::{Path, PathBuf};
use std::time::Instant;

use effectc::check::hazards;
use effectc::check::InputSpec;
use effectc::config::HazardSettings;

fn main() {
    // naga panics on some real programs; the front contains them (the program is refused),
    // and their messages would bury the figures.
    std::panic::set_hook(Box::new(|_| {}));
    let limit = args::number("--limit", 600) as usize;
    let rounds = args::number("--rounds", 3).max(1);
    let argv: Vec<String> = std::env::args().collect();
    let corpus = argv.iter().position(|a| a == "--corpus").and_then(|i| argv.get(i + 1)).map(PathBuf::from);
    let dirs = match &corpus {
        Some(dir) => subdirs(dir),
        None => ["effects", "tests/rewrite", "tests/fail", "tests/safe"].iter().flat_map(|d| subdirs(Path::new(d))).collect(),
    };
    let mut units = Vec::new();
    for dir in dirs {
        if units.len() >= limit {
            break;
        }
        let (_, checked) = InputSpec { paths: vec![dir], ..InputSpec::default() }.check();
        for c in checked {
            units.extend(c.units.into_iter().map(|u| (u.effect, u.program)));
        }
    }
    units.truncate(limit);
    let settings = HazardSettings::default();
    let (mut with, mut without) = (Vec::new(), Vec::new());
    let mut warnings = (0, 0);
    for _ in 0..rounds {
        let t = Instant::now();
        warnings.1 = units.iter().map(|(e, p)| hazards::analyse_without_witnesses(e.as_ref(), p, settings).len()).sum();
        without.push(t.elapsed().as_secs_f64());
        let t = Instant::now();
        warnings.0 = units.iter().map(|(e, p)| hazards::analyse(e.as_ref(), p, settings).len()).sum();
        with.push(t.elapsed().as_secs_f64());
    }
    let best = |v: &[f64]| v.iter().copied().fold(f64::INFINITY, f64::min);
    let (a, b) = (best(&with), best(&without));
    println!("programs: {} ({})", units.len(), corpus.map_or("repository programs".into(), |c| c.display().to_string()));
    println!(
        "interval analysis alone: {:.1} ms ({:.3} ms/program, {} warnings, all tiers)",
        b * 1e3,
        b * 1e3 / units.len().max(1) as f64,
        warnings.1
    );
    println!(
        "with witness runs:       {:.1} ms ({:.3} ms/program, {} warnings, default tier)",
        a * 1e3,
        a * 1e3 / units.len().max(1) as f64,
        warnings.0
    );
    println!("ratio with / without: {:.2} (best of {rounds} rounds each)", a / b);
}

/// Sorted subdirectories of `dir`.
fn subdirs(dir: &Path) -> Vec<PathBuf> {
    let mut out: Vec<PathBuf> =
        std::fs::read_dir(dir).map(|r| r.flatten().map(|e| e.path()).filter(|p| p.is_dir()).collect()).unwrap_or_default();
    out.sort();
    out
}
