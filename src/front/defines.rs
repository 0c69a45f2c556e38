//! Macros defined from outside a stage's text: `--define NAME[=VALUE]` on the command line,
//! `define = { NAME = VALUE }` for a stage in a manifest or a program in `effectc.toml`, and
//! the single-file two-stage format (one file read as the vertex stage with `VERTEX`
//! defined and as the fragment stage with `FRAGMENT`).
//!
//! They are written as `#define` lines right after the `#version` line (GLSL allows only
//! comments before it), in a text registered beside the user's file
//! ([`Files::add_expanded`]): a span in the user's part is shown in the user's file at its
//! own line, one in the `#define` lines in a generated file named after them.

use crate::diag::{Files, Segment};
use crate::stage::Define;

/// The id of `stage`'s text with `defines` written after its `#version` line (`stage`
/// itself when there are none).
pub fn apply(files: &mut Files, stage: crate::diag::FileId, defines: &[Define]) -> crate::diag::FileId {
    if defines.is_empty() {
        return stage;
    }
    let text = files.text(stage).to_string();
    let at = after_version_line(&text);
    let mut prelude: String = defines.iter().map(|(n, v)| format!("#define {n} {v}\n")).collect();
    let lead = if at > 0 && !text[..at].ends_with('\n') { "\n" } else { "" };
    prelude.insert_str(0, lead);
    let names: Vec<String> = defines.iter().map(|(n, v)| if v == "1" { n.clone() } else { format!("{n}={v}") }).collect();
    let generated = files.add_generated(format!("(defined for {}: {})", files.path(stage), names.join(" ")), prelude.clone());
    let mut out = String::with_capacity(text.len() + prelude.len());
    out.push_str(&text[..at]);
    out.push_str(&prelude);
    out.push_str(&text[at..]);
    let segments = vec![
        Segment { at: 0..at, file: stage, start: 0 },
        Segment { at: at..at + prelude.len(), file: generated, start: 0 },
        Segment { at: at + prelude.len()..out.len(), file: stage, start: at },
    ];
    files.add_expanded(stage, out, segments)
}

/// Where the line after the `#version` directive starts (the end of the text when it is
/// the last line); 0 when the stage has none.
fn after_version_line(text: &str) -> usize {
    let mut at = 0;
    for line in text.split_inclusive('\n') {
        let code = line.trim_start();
        if code.strip_prefix('#').is_some_and(|d| d.trim_start().starts_with("version")) {
            return at + line.len();
        }
        at += line.len();
    }
    0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defines_follow_the_version_line_and_spans_map_back() {
        let mut files = Files::new();
        let text = "// banner\n#version 330\nout vec4 c;\nvoid main() { c = vec4(Q); }\n";
        let id = files.add("a.frag", text);
        let x = apply(&mut files, id, &[("Q".into(), "0.5".into())]);
        assert_eq!(files.text(x), "// banner\n#version 330\n#define Q 0.5\nout vec4 c;\nvoid main() { c = vec4(Q); }\n");
        let main = files.text(x).find("void").unwrap();
        let at = text.find("void").unwrap();
        assert_eq!(files.resolve(x, Some(main..main + 4)), (id, Some(at..at + 4)));
        let no_version = files.add("b.frag", "void main() {}");
        let y = apply(&mut files, no_version, &[("A".into(), "1".into())]);
        assert_eq!(files.text(y), "#define A 1\nvoid main() {}");
        assert_eq!(apply(&mut files, id, &[]), id);
    }
}
