//! Robustness: truncated, mutated and garbage input never panics, and whenever the front
//! rejects a stage (no program, or no naga module for a stage naga can parse) an error
//! diagnostic says why. Every diagnostic must point inside a registered file.
//!
//! Inputs: every stage file in `effects/` and `tests/rewrite/`, each compiled together with
//! the program's other (intact) stages: every prefix at a step of 7 bytes plus cuts at every
//! line end (between `\r` and `\n` too), and 200 deterministic mutations (xorshift).

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};

use effectc::check::check_inputs;
use effectc::diag::{self, Diagnostic, Files};
use effectc::front::program::{compile, FrontOptions};
use effectc::inputs::stage_of;
use effectc::stage::StageKind;

use crate::common;

const MUTATIONS: usize = 200;

/// Marsaglia's xorshift64: deterministic, no dependencies.
struct XorShift(u64);

impl XorShift {
    fn next(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        self.0 = x;
        x
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

/// Fragments that tend to reach unusual paths: directives, brackets, sampler syntax, big numbers.
#[rustfmt::skip]
const SNIPPETS: &[&str] = &[
    "#version 100\n", "#version 460 core\n", "#define X(", "#if 1\n", "#endif\n",
    "#extension GL_foo : enable\n", "uniform ", "in ", "out ", "flat ",
    "layout(location = 99999999999) ", "layout(binding=", "[", "]", "[[", "]]", "{", "}", "(", ")",
    ";", ",", ".", "..", "sampler2D ", "samplerCube s[", "struct S { sampler2D t; } ",
    "gl_FragData[", "gl_FragColor", "texture2D(", "texture(", "main", "void main(){}", "0x",
    "1e99999", "4294967296u", "-", "++", "/*", "*/", "//", "\\\n", "\r", "\r\n", "\t", "é",
    "\u{feff}", "\0", "sample", "buffer", "shared", "return;", "discard;", "break;", "switch(1){",
    "case ", "default:", "const int N = -1;", "float a[N];", "vert_out.", "} frag_in;",
    "interface", "precision highp float;", "#line 0\n", "#undef main\n", "##",
];

struct Program {
    /// Stage files of one program, with their stages.
    stages: Vec<(PathBuf, StageKind)>,
}

fn programs() -> Vec<Program> {
    let mut dirs = common::fixtures("tests/rewrite", common::REWRITE_FIXTURES);
    dirs.extend(common::fixtures("effects", 21));
    dirs.into_iter()
        .map(|d| Program {
            stages: common::stage_files(&d)
                .into_iter()
                .map(|p| {
                    let k = stage_of(&p, None).unwrap();
                    (p, k)
                })
                .collect(),
        })
        .collect()
}

/// Compiles `program` with stage `which` replaced by `text`, like `effectc check` does
/// (front, then link). Returns a description of what went wrong, if anything.
fn run(program: &Program, which: usize, text: &str) -> Result<bool, String> {
    let result = catch_unwind(AssertUnwindSafe(|| {
        let mut files = Files::new();
        let mut ids = Vec::new();
        for (i, (path, kind)) in program.stages.iter().enumerate() {
            let t = if i == which { text.to_string() } else { std::fs::read_to_string(path).unwrap() };
            ids.push((files.add(path.display().to_string(), t), *kind));
        }
        let mut diags = Vec::new();
        let compiled = compile(&files, &ids, FrontOptions::default(), &mut diags);
        // A stage the reference compiler accepts and effectc's own parser cannot read is
        // not rejected: check notes it (N0106) and translate says why it stops.
        let mut rejected = compiled.is_none() && !diags.iter().any(|d| d.code == effectc::diag::Code::ReferenceOnly);
        if let Some(p) = &compiled {
            // naga parses vertex, fragment and compute stages: each must have a module, or a
            // limitation (legal GLSL naga does not take) that check reports as a note.
            rejected |= p.stages.iter().any(|s| s.syntax.stage.naga().is_some() && s.naga.is_none() && s.limitation.is_none());
            let syntaxes: Vec<_> = p.stages.iter().map(|s| s.syntax.clone()).collect();
            diags.extend(effectc::link::check_interface(&syntaxes));
        }
        let _ = diag::render_human(&diags, &files, false);
        (rejected, diags, files)
    }));
    let (rejected, diags, files) = result.map_err(|e| {
        let msg = e.downcast_ref::<String>().cloned().or_else(|| e.downcast_ref::<&str>().map(|s| s.to_string()));
        format!("panicked: {}", msg.unwrap_or_default())
    })?;
    if rejected && !diag::has_errors(&diags) {
        return Err("rejected without an error diagnostic".into());
    }
    spans_in_files(&diags, &files)?;
    Ok(rejected)
}

/// Every diagnostic points at a registered file, inside its text.
fn spans_in_files(diags: &[Diagnostic], files: &Files) -> Result<(), String> {
    for d in diags {
        let mut spans: Vec<_> = d.labels.iter().map(|l| (Some(l.file), Some(l.span.clone()))).collect();
        spans.push((d.file, d.span.clone()));
        for (file, span) in spans {
            let Some(file) = file else { continue };
            let Some(f) = files.try_get(file) else {
                return Err(format!("{}: unregistered file id", d.code));
            };
            if let Some(s) = span {
                if s.start > s.end || s.end > f.text.len() {
                    return Err(format!("{}: span {s:?} outside `{}` ({} bytes): {}", d.code, f.path, f.text.len(), d.message));
                }
            }
        }
    }
    Ok(())
}

/// Largest char boundary `<= at`.
fn floor_boundary(text: &str, mut at: usize) -> usize {
    while !text.is_char_boundary(at) {
        at -= 1;
    }
    at
}

fn mutate(rng: &mut XorShift, original: &[u8]) -> String {
    let mut bytes = original.to_vec();
    for _ in 0..1 + rng.below(3) {
        let at = rng.below(bytes.len() + 1);
        match rng.below(5) {
            0 if !bytes.is_empty() => {
                let i = at.min(bytes.len() - 1);
                const PUNCT: &[u8] = b" \n{}()[];,.#0aZ_/*\r\t\"'\\+-=<>!?";
                bytes[i] = PUNCT[rng.below(PUNCT.len())];
            }
            1 => {
                let end = (at + 1 + rng.below(12)).min(bytes.len());
                bytes.drain(at.min(end)..end);
            }
            2 => {
                let end = (at + 1 + rng.below(40)).min(bytes.len());
                let copy = bytes[at.min(end)..end].to_vec();
                let to = rng.below(bytes.len() + 1);
                bytes.splice(to..to, copy);
            }
            3 if !bytes.is_empty() => {
                let i = at.min(bytes.len() - 1);
                bytes[i] = rng.next() as u8;
            }
            _ => {
                let s = SNIPPETS[rng.below(SNIPPETS.len())].as_bytes();
                bytes.splice(at..at, s.iter().copied());
            }
        }
    }
    // Files hold text: invalid UTF-8 becomes U+FFFD (the not-UTF-8 path is tested below).
    String::from_utf8_lossy(&bytes).into_owned()
}

#[test]
fn truncations_and_mutations_never_panic() {
    let programs = programs();
    let failures = std::sync::Mutex::new(Vec::new());
    let counts = std::sync::Mutex::new((0usize, 0usize)); // (accepted, rejected)
    std::thread::scope(|scope| {
        for (pi, program) in programs.iter().enumerate() {
            let (failures, counts) = (&failures, &counts);
            scope.spawn(move || {
                for (which, (path, _)) in program.stages.iter().enumerate() {
                    let bytes = std::fs::read(path).unwrap();
                    let text = String::from_utf8(bytes.clone()).unwrap();
                    let mut cuts: Vec<usize> = (0..text.len()).step_by(7).map(|c| floor_boundary(&text, c)).collect();
                    cuts.extend(text.match_indices('\n').flat_map(|(i, _)| [i, i + 1]));
                    cuts.sort_unstable();
                    cuts.dedup();
                    let mut rng = XorShift(0x9E37_79B9_7F4A_7C15 ^ ((pi as u64 + 1) * 0x1000_0001) ^ which as u64);
                    let cases = cuts
                        .into_iter()
                        .map(|c| (format!("prefix of {c} bytes"), text[..c].to_string()))
                        .chain((0..MUTATIONS).map(|i| (format!("mutation {i}"), mutate(&mut rng, &bytes))));
                    for (what, input) in cases {
                        let result = run(program, which, &input);
                        match result {
                            Ok(false) => counts.lock().unwrap().0 += 1,
                            Ok(true) => counts.lock().unwrap().1 += 1,
                            Err(_) => {}
                        }
                        if let Err(e) = result {
                            let dump = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!(
                                "robust-{}-{}",
                                failures.lock().unwrap().len(),
                                path.file_name().unwrap().to_string_lossy()
                            ));
                            let _ = std::fs::write(&dump, &input);
                            failures.lock().unwrap().push(format!("{} ({what}, saved to {}): {e}", path.display(), dump.display()));
                        }
                    }
                }
            });
        }
    });
    let failures = failures.into_inner().unwrap();
    let (accepted, rejected) = counts.into_inner().unwrap();
    eprintln!("robust: {accepted} inputs accepted, {rejected} rejected with an error, {} failures", failures.len());
    assert!(accepted > 100 && rejected > 1000, "suspiciously few cases: {accepted} accepted, {rejected} rejected");
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures.join("\n"));
}

#[test]
fn garbage_and_empty_files_are_errors() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("robust-files");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let mut rng = XorShift(42);
    let garbage: Vec<u8> = (0..4096).map(|_| rng.next() as u8).collect();
    let printable: String = (0..4096).map(|_| (b' ' + rng.below(95) as u8) as char).collect();
    let cases: [(&str, Vec<u8>); 4] =
        [("garbage.frag", garbage), ("empty.frag", Vec::new()), ("printable.frag", printable.into_bytes()), ("nul.frag", vec![0; 64])];
    for (name, bytes) in cases {
        let path = dir.join(name);
        std::fs::write(&path, &bytes).unwrap();
        let (outcome, _) = catch_unwind(|| check_inputs(std::slice::from_ref(&path), None, FrontOptions::default()))
            .unwrap_or_else(|_| panic!("{name}: panicked"));
        let text = common::render(&outcome);
        assert!(diag::has_errors(&outcome.diagnostics), "{name}: no error:\n{text}");
        spans_in_files(&outcome.diagnostics, &outcome.files).unwrap_or_else(|e| panic!("{name}: {e}"));
    }
}

#[test]
fn latin1_in_comments_is_read_and_spans_after_it_hold() {
    // Comments written before editors saved UTF-8 (`Iñigo Quílez` in Latin-1): glslang and
    // Mesa read them; every byte stands for one byte, so a span after them is the user's.
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("robust-latin1");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("quilez.frag");
    std::fs::write(
        &path,
        b"#version 330\n// after I\xf1igo Qu\xedlez /* \xe9t\xe9 */\nout vec4 c;\nvoid main() { c = vec4(undeclared); }\n",
    )
    .unwrap();
    let (outcome, _) = check_inputs(std::slice::from_ref(&path), None, FrontOptions::default());
    let errors: Vec<&Diagnostic> = outcome.diagnostics.iter().filter(|d| d.is_error()).collect();
    assert_eq!(errors.len(), 1, "{}", common::render(&outcome));
    assert_ne!(errors[0].code.as_str(), "E0012", "{}", common::render(&outcome));
    assert!(common::render(&outcome).contains("quilez.frag:4:24"), "{}", common::render(&outcome));
    std::fs::write(&path, b"#version 330\n// I\xf1igo\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n").unwrap();
    let (outcome, _) = check_inputs(std::slice::from_ref(&path), None, FrontOptions::default());
    assert!(!diag::has_errors(&outcome.diagnostics), "{}", common::render(&outcome));
}
