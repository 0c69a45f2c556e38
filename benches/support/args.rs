//! The benchmarks' command-line options: `-- --size 512 --frames 24`.

/// The value after `--name` on the command line, or `default`.
pub fn number(name: &str, default: u32) -> u32 {
    let args: Vec<String> = std::env::args().collect();
    args.iter().position(|a| a == name).and_then(|i| args.get(i + 1)).and_then(|v| v.parse().ok()).unwrap_or(default)
}
