//! `effectc completions SHELL` prints a completion script for every shell clap_complete
//! knows, naming the subcommands and their flags; `effectc man` prints the roff man page.

use crate::common::{code, effectc, stdout};

const SUBCOMMANDS: &[&str] = &["check", "translate", "render", "bench", "stress"];

#[test]
fn completions_for_every_shell_name_the_subcommands_and_flags() {
    for shell in ["bash", "zsh", "fish", "powershell", "elvish"] {
        let out = effectc(&["completions", shell]);
        let text = stdout(&out);
        assert_eq!(code(&out), 0, "{shell}: {}", String::from_utf8_lossy(&out.stderr));
        assert!(!text.trim().is_empty(), "{shell}: empty script");
        for word in SUBCOMMANDS.iter().chain(&["format", "contact-sheet", "completions", "man"]) {
            assert!(text.contains(word), "{shell}: `{word}` missing from the script");
        }
    }
    let out = effectc(&["completions", "tcsh"]);
    assert_eq!(code(&out), 2, "an unknown shell is a usage error");
}

#[test]
fn man_page_is_roff_with_every_subcommand() {
    let out = effectc(&["man"]);
    let text = stdout(&out);
    assert_eq!(code(&out), 0, "{}", String::from_utf8_lossy(&out.stderr));
    assert!(text.contains(".TH"), "a roff title header");
    for word in SUBCOMMANDS.iter().chain(&["completions"]) {
        assert!(text.contains(word), "`{word}` missing from the man page");
    }
}
