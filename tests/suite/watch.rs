//! `--watch`: the binary reports, a file changes, it reports again (and `render` renders
//! again only the program whose file changed); the test stops it.

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::mpsc::{channel, Receiver};
use std::time::{Duration, Instant};

const VERTEX: &str = "#version 330 core\nlayout(location = 0) in vec2 aPos;\nout vec2 uv;\nvoid main() {\n    uv = aPos;\n    gl_Position = vec4(aPos, 0.0, 1.0);\n}\n";
const FRAGMENT: &str = "#version 330 core\nin vec2 uv;\nout vec4 colour;\nvoid main() {\n    colour = vec4(uv, 0.0, 1.0);\n}\n";

/// A fresh directory with the programs `names` (`<name>.vert` + `<name>.frag`).
fn programs(test: &str, names: &[&str]) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("effectc-watch-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    for n in names {
        std::fs::write(dir.join(format!("{n}.vert")), VERTEX).unwrap();
        std::fs::write(dir.join(format!("{n}.frag")), FRAGMENT).unwrap();
    }
    dir
}

/// The running `effectc … --watch` and its output, line by line (stdout and stderr).
struct Watching {
    child: Child,
    lines: Receiver<String>,
}

impl Watching {
    fn start(args: &[&str]) -> Watching {
        let mut child = Command::new(env!("CARGO_BIN_EXE_effectc"))
            .args(args)
            .env("NO_COLOR", "1")
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("run effectc");
        let (tx, lines) = channel();
        for stream in [Box::new(child.stdout.take().unwrap()) as Box<dyn std::io::Read + Send>, Box::new(child.stderr.take().unwrap())] {
            let tx = tx.clone();
            std::thread::spawn(move || {
                for line in BufReader::new(stream).lines().map_while(Result::ok) {
                    let _ = tx.send(line);
                }
            });
        }
        Watching { child, lines }
    }

    /// One round's lines: up to the first that contains `marker` (the watcher's line on
    /// stderr, panics after 90 s), plus what stdout delivers within a second after it (the
    /// two streams are read by two threads, so their order is not kept).
    fn until(&self, marker: &str) -> Vec<String> {
        let mut seen = self.up_to(marker);
        while let Ok(line) = self.lines.recv_timeout(Duration::from_secs(1)) {
            seen.push(line);
        }
        seen
    }

    fn up_to(&self, marker: &str) -> Vec<String> {
        let deadline = Instant::now() + Duration::from_secs(90);
        let mut seen = Vec::new();
        while let Some(left) = deadline.checked_duration_since(Instant::now()) {
            match self.lines.recv_timeout(left) {
                Ok(line) => {
                    let done = line.contains(marker);
                    seen.push(line);
                    if done {
                        return seen;
                    }
                }
                Err(_) => break,
            }
        }
        panic!("no line with `{marker}` within 90 s; saw:\n{}", seen.join("\n"));
    }
}

impl Drop for Watching {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn arg(p: &Path) -> &str {
    p.to_str().unwrap()
}

#[test]
fn check_reports_again_after_a_change() {
    let dir = programs("check", &["a"]);
    let w = Watching::start(&["check", "--watch", "--color", "never", arg(&dir)]);
    let first = w.until("watching");
    assert!(first.iter().any(|l| l.contains("checked 1 program: no problems")), "{first:#?}");
    // Give the watcher a moment to settle, then break the fragment stage.
    std::thread::sleep(Duration::from_millis(300));
    std::fs::write(dir.join("a.frag"), FRAGMENT.replace("colour = vec4(uv, 0.0, 1.0);", "colour = vec4(uv, 0.0);")).unwrap();
    let second = w.until("watching");
    assert!(second.iter().any(|l| l.contains("[watch] changed:") && l.contains("a.frag")), "{second:#?}");
    assert!(second.iter().any(|l| l.contains("checked 1 program: 1 error")), "the second report sees the change: {second:#?}");
    // A new stage file below the watched directory makes a third report with two programs.
    std::thread::sleep(Duration::from_millis(300));
    std::fs::write(dir.join("a.frag"), FRAGMENT).unwrap();
    std::fs::write(dir.join("b.vert"), VERTEX).unwrap();
    std::fs::write(dir.join("b.frag"), FRAGMENT).unwrap();
    let third = w.until("watching");
    assert!(third.iter().any(|l| l.contains("checked 2 programs: no problems")), "{third:#?}");
}

#[test]
fn render_renders_again_only_what_changed() {
    let dir = programs("render", &["one", "two"]);
    let out = dir.join("frames");
    let w = Watching::start(&["render", "--watch", "--size", "16x16", "--color", "never", "--out", arg(&out), arg(&dir)]);
    let first = w.until("watching");
    let rendered = |lines: &[String], name: &str| lines.iter().any(|l| l.starts_with(&format!("rendered {name} ")));
    assert!(rendered(&first, "one") && rendered(&first, "two"), "{first:#?}");
    std::thread::sleep(Duration::from_millis(300));
    std::fs::write(dir.join("two.frag"), FRAGMENT.replace("vec4(uv, 0.0, 1.0)", "vec4(1.0 - uv.x, uv.y, 0.5, 1.0)")).unwrap();
    let second = w.until("watching");
    assert!(rendered(&second, "two") && !rendered(&second, "one"), "only `two` again: {second:#?}");
}

#[test]
fn a_named_file_deleted_and_written_again_is_watched_again() {
    let dir = programs("recreate", &["a"]);
    let (vert, frag) = (dir.join("a.vert"), dir.join("a.frag"));
    let w = Watching::start(&["check", "--watch", "--color", "never", arg(&vert), arg(&frag)]);
    let first = w.until("watching");
    assert!(first.iter().any(|l| l.contains("checked 1 program")), "{first:#?}");
    std::thread::sleep(Duration::from_millis(300));
    std::fs::remove_file(&frag).unwrap();
    let second = w.until("watching");
    assert!(second.iter().any(|l| l.contains("E0010")), "the deleted file is reported: {second:#?}");
    std::thread::sleep(Duration::from_millis(300));
    std::fs::write(&frag, FRAGMENT.replace("colour = vec4(uv, 0.0, 1.0);", "colour = vec4(uv, 0.0);")).unwrap();
    let third = w.until("watching");
    assert!(third.iter().any(|l| l.contains("checked 1 program: 1 error")), "the file written again is read again: {third:#?}");
}
