//! The tree's shape, checked from the sources: layers import downward only (the order in
//! `src/lib.rs`'s Steps), no module's submodules import each other in a cycle, no source
//! file over 700 lines (test files aside) and no function over 120 lines.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

const MAX_FILE_LINES: usize = 700;
const MAX_FN_LINES: usize = 120;

/// Every `.rs` file under `dir`, sorted.
fn rust_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|x| x == "rs") {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

/// The module path of a source file under `src/` (`src/front/rewrite/calls.rs` →
/// `["front", "rewrite", "calls"]`; `mod.rs` names its directory).
fn module_of(path: &Path) -> Vec<String> {
    let rel = path.strip_prefix("src").unwrap().with_extension("");
    let mut parts: Vec<String> = rel.iter().map(|c| c.to_string_lossy().into_owned()).collect();
    if parts.last().is_some_and(|l| l == "mod") {
        parts.pop();
    }
    parts
}

/// `text` without `//` comments (doc comments included) and string literals, so prose
/// and messages that mention a path are not imports.
fn code_only(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for line in text.lines() {
        let mut in_string = false;
        let mut escaped = false;
        let mut chars = line.chars().peekable();
        while let Some(c) = chars.next() {
            if in_string {
                if escaped {
                    escaped = false;
                } else if c == '\\' {
                    escaped = true;
                } else if c == '"' {
                    in_string = false;
                    out.push('"');
                }
                continue;
            }
            if c == '/' && chars.peek() == Some(&'/') {
                break;
            }
            if c == '"' {
                in_string = true;
            }
            out.push(c);
        }
        out.push('\n');
    }
    out
}

/// The paths below `crate::` that `code` names: plain (`crate::a::b`) and grouped
/// (`crate::{a::b, c}`), as segment lists.
fn crate_paths(code: &str) -> Vec<Vec<String>> {
    let mut out = Vec::new();
    let ident = |s: &str| s.split("::").map(|p| p.trim().to_string()).filter(|p| !p.is_empty()).collect::<Vec<_>>();
    let mut rest = code;
    while let Some(i) = rest.find("crate::") {
        let before = rest[..i].chars().last();
        rest = &rest[i + "crate::".len()..];
        if before.is_some_and(|c| c.is_alphanumeric() || c == '_') {
            continue; // `$crate::`, `mycrate::`
        }
        if let Some(group) = rest.strip_prefix('{') {
            let end = group.find('}').unwrap_or(group.len());
            for item in group[..end].split(',') {
                let item = item.split(" as ").next().unwrap_or("").trim();
                let item = item.split('{').next().unwrap_or("");
                let p = ident(item);
                if !p.is_empty() {
                    out.push(p);
                }
            }
        } else {
            let end = rest.find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':')).unwrap_or(rest.len());
            let p = ident(&rest[..end]);
            if !p.is_empty() {
                out.push(p);
            }
        }
    }
    out
}

/// The layer of each top-level module: its numbered line in `src/lib.rs`'s Steps.
fn layers() -> BTreeMap<String, usize> {
    let lib = std::fs::read_to_string("src/lib.rs").unwrap();
    let steps = lib.split("//! # Steps").nth(1).expect("src/lib.rs has a Steps section");
    let mut rank = 0;
    let mut out = BTreeMap::new();
    for line in steps.lines().skip(1).take_while(|l| l.starts_with("//!")) {
        let body = line.trim_start_matches("//!").trim_start();
        let numbered = body.split_once(". ").is_some_and(|(n, _)| n.chars().all(|c| c.is_ascii_digit()) && !n.is_empty());
        if numbered {
            rank += 1;
        }
        if !numbered {
            continue;
        }
        let mut rest = body;
        // The modules a step is about are its leading [`links`] before the colon.
        let head = rest.split(':').next().unwrap_or("");
        rest = head;
        while let Some(i) = rest.find("[`") {
            let end = rest[i..].find("`]").unwrap() + i;
            let name = &rest[i + 2..end];
            if !name.contains("::") {
                out.insert(name.to_string(), rank);
            }
            rest = &rest[end..];
        }
    }
    out
}

#[test]
fn every_module_has_a_layer() {
    let layers = layers();
    let lib = std::fs::read_to_string("src/lib.rs").unwrap();
    let declared: BTreeSet<String> =
        lib.lines().filter_map(|l| l.strip_prefix("pub mod ")).map(|m| m.trim_end_matches(';').to_string()).collect();
    let layered: BTreeSet<String> = layers.keys().cloned().collect();
    assert_eq!(declared, layered, "src/lib.rs's Steps must give every `pub mod` exactly one layer");
}

#[test]
fn layers_import_downward_only() {
    let layers = layers();
    let mut wrong = Vec::new();
    for file in rust_files(Path::new("src")) {
        let module = module_of(&file);
        let Some(top) = module.first().filter(|m| !["lib", "main"].contains(&m.as_str())) else { continue };
        let own = layers[top.as_str()];
        let code = code_only(&std::fs::read_to_string(&file).unwrap());
        for path in crate_paths(&code) {
            let target = &path[0];
            if target == top || target == "self" {
                continue;
            }
            let Some(&rank) = layers.get(target.as_str()) else { continue };
            if rank >= own {
                wrong.push(format!("{} (layer {own}) imports crate::{} (layer {rank})", file.display(), path.join("::")));
            }
        }
    }
    wrong.sort();
    wrong.dedup();
    assert!(wrong.is_empty(), "imports against the layer order of src/lib.rs:\n{}", wrong.join("\n"));
}

#[test]
fn submodules_do_not_import_each_other_in_a_cycle() {
    // Edges between the direct submodules of each top-level module (the top module's own
    // file is the node ""), from `crate::top::sub` paths and `super::sub` in direct children.
    let mut edges: BTreeMap<String, BTreeSet<(String, String)>> = BTreeMap::new();
    for file in rust_files(Path::new("src")) {
        let module = module_of(&file);
        let Some(top) = module.first() else { continue };
        let from = module.get(1).cloned().unwrap_or_default();
        let code = code_only(&std::fs::read_to_string(&file).unwrap());
        let mut targets: Vec<String> = crate_paths(&code)
            .into_iter()
            .filter(|p| p[0] == *top && p.len() > 1 && p[1].chars().next().is_some_and(|c| c.is_lowercase()))
            .map(|p| p[1].clone())
            .collect();
        if module.len() == 2 {
            let mut rest = code.as_str();
            while let Some(i) = rest.find("super::") {
                rest = &rest[i + "super::".len()..];
                let name: String = rest.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
                if name.chars().next().is_some_and(|c| c.is_lowercase()) && name != "super" {
                    targets.push(name);
                }
            }
        }
        let dir = Path::new("src").join(top);
        if !dir.is_dir() {
            continue;
        }
        let subs: BTreeSet<String> = rust_files(&dir).iter().filter_map(|f| module_of(f).get(1).cloned()).collect();
        for to in targets {
            if to != from && subs.contains(&to) {
                edges.entry(top.clone()).or_default().insert((from.clone(), to));
            }
        }
    }
    for (top, e) in &edges {
        // Repeatedly drop nodes without outgoing edges; what remains is in a cycle.
        let mut e: Vec<(String, String)> = e.iter().cloned().collect();
        loop {
            let sources: BTreeSet<&String> = e.iter().map(|(a, _)| a).collect();
            let before = e.len();
            let keep: Vec<(String, String)> = e.iter().filter(|(_, b)| sources.contains(b)).cloned().collect();
            e = keep;
            if e.len() == before {
                break;
            }
        }
        assert!(e.is_empty(), "submodules of `{top}` import each other in a cycle: {e:?}");
    }
}

/// Test files: `tests.rs` and anything under a `tests/` directory.
fn is_test_file(path: &Path) -> bool {
    path.file_name().is_some_and(|n| n == "tests.rs") || path.iter().any(|c| c == "tests")
}

#[test]
fn no_source_file_over_the_limit() {
    let long: Vec<String> = rust_files(Path::new("src"))
        .into_iter()
        .filter(|f| !is_test_file(f))
        .filter_map(|f| {
            let n = std::fs::read_to_string(&f).unwrap().lines().count();
            (n > MAX_FILE_LINES).then(|| format!("{}: {n} lines", f.display()))
        })
        .collect();
    assert!(long.is_empty(), "source files over {MAX_FILE_LINES} lines:\n{}", long.join("\n"));
}

/// The functions of `text` as (name, first line, line count), by brace matching from
/// each `fn` to its closing brace (comments and strings removed first).
fn functions(text: &str) -> Vec<(String, usize, usize)> {
    let code = code_only(text);
    let lines: Vec<&str> = code.lines().collect();
    let mut out = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let t = line.trim_start();
        let t = t.strip_prefix("pub(crate) ").or_else(|| t.strip_prefix("pub(super) ")).or_else(|| t.strip_prefix("pub ")).unwrap_or(t);
        let t = t.strip_prefix("const ").unwrap_or(t);
        let Some(rest) = t.strip_prefix("fn ") else { continue };
        let name: String = rest.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
        let mut depth = 0i64;
        let mut started = false;
        for (j, l) in lines.iter().enumerate().skip(i) {
            if !started && l.contains(';') && !l.contains('{') {
                break; // a declaration without a body
            }
            for c in l.chars() {
                match c {
                    '{' => {
                        depth += 1;
                        started = true;
                    }
                    '}' => depth -= 1,
                    _ => {}
                }
            }
            if started && depth <= 0 {
                out.push((name.clone(), i + 1, j - i + 1));
                break;
            }
        }
    }
    out
}

#[test]
fn no_function_over_the_limit() {
    let mut long = Vec::new();
    for f in rust_files(Path::new("src")) {
        for (name, line, n) in functions(&std::fs::read_to_string(&f).unwrap()) {
            if n > MAX_FN_LINES {
                long.push(format!("{}:{line}: fn {name}: {n} lines", f.display()));
            }
        }
    }
    assert!(long.is_empty(), "functions over {MAX_FN_LINES} lines:\n{}", long.join("\n"));
}

#[test]
fn the_scanners_see_what_they_check() {
    // Guards against a scanner that finds nothing and so passes vacuously.
    let paths = crate_paths(&code_only(
        "use crate::{diag::Diagnostic, front::syntax as s};\nlet x = crate::render::scene::Scene::new(); // crate::bench\nlet m = \"crate::cli\";",
    ));
    assert_eq!(paths, [vec!["diag", "Diagnostic"], vec!["front", "syntax"], vec!["render", "scene", "Scene", "new"]]);
    let f = functions("fn a() {\n    let s = \"}\";\n}\npub fn b(x: u32) -> u32 {\n    x\n}\nfn c();\n");
    assert_eq!(f, [("a".to_string(), 1, 3), ("b".to_string(), 4, 3)]);
    assert!(layers().len() >= 10);
}
