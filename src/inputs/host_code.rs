//! Programs as the host code names them: the stages a C, C++, Python, JavaScript, … file
//! (or a scene description in XML) names together are one program.
//!
//! A folder with several vertex stages and no shared stems (`PCN.vert`, `PN.vert`,
//! `DiffuseOnly.frag`, `Phong.frag`, …) says nothing about its pairs: they live in the code
//! that loads the files. effectc reads the string literals of that code and takes stage
//! files named
//! - in one call or one initializer: `LoadProgram("PCN.vert", "Diffuse.frag")`,
//!   `{"PN.vert", "Phong.frag"}`, `Shader("a.vs", "a.fs")`, `<prog vert="a.vert" frag="b.frag"/>`;
//! - or in the statements of one function body, one literal each:
//!   `list.push_back(LoadShader(GL_VERTEX_SHADER, "a.vert")); list.push_back(LoadShader(GL_FRAGMENT_SHADER, "b.frag"));`,
//!   `if (!AddShader(GL_VERTEX_SHADER, "a.vs")) { return false; } if (!AddShader(…, "a.fs")) …`
//!   (at top level, where no function bounds them, only consecutive statements).
//!
//! Within such a sequence each vertex stage pairs with the next fragment stage, with the
//! geometry or tessellation stages named between them (`"a.vert", "b.vert", "x.frag"`:
//! both with `x.frag`; `"a.vert", "a.frag", "b.vert", "b.frag"`: two programs). A literal
//! names a stage file by its trailing path (`"data/PCN.vert"`, `"../shader/x.vert.glsl"`);
//! where several files end so, the one nearest the host file is meant (sharing the most
//! folders with it, then the shallowest), and a tie names none.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Component, Path, PathBuf};

use crate::diag::{Code, Diagnostic};
use crate::inputs::{program_name, Formed, ProgramInput};
use crate::stage::StageKind;

/// Extensions of files read as host code: programming languages that load shaders, and
/// markup that describes scenes.
const HOST_EXTENSIONS: &[&str] = &[
    "c", "cc", "cpp", "cxx", "h", "hh", "hpp", "hxx", "inl", "m", "mm", "cs", "java", "kt", "scala", "py", "js", "mjs", "ts", "rs", "go",
    "lua", "swift", "dart", "zig", "nim", "xml", "html", "json",
];

/// Markup: `<…>` holds one element's attributes.
const MARKUP: &[&str] = &["xml", "html"];

/// Host files larger than this are not read (generated sources, bundles).
const HOST_BYTES: u64 = 2 << 20;

/// Whether `path` is read as host code.
pub fn is_host_file(path: &Path) -> bool {
    path.extension().and_then(|e| e.to_str()).is_some_and(|e| HOST_EXTENSIONS.iter().any(|h| e.eq_ignore_ascii_case(h)))
}

/// A program the host code names, and where.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Named {
    /// Its stage files in pipeline order.
    pub files: Vec<(PathBuf, StageKind)>,
    /// The host file and the 1-based line of the first literal.
    pub host: PathBuf,
    pub line: usize,
}

/// Stage files left alone by the other rules (`groups`, one program each) join the programs
/// the `hosts` files name with them ([`programs`]); a note (N0004) names each program so
/// formed and the host line that names it. Programs already formed are not formed twice.
pub fn pair_as_named(groups: &mut Vec<ProgramInput>, hosts: &[PathBuf]) -> Vec<Diagnostic> {
    // Each group's stage files (none for manifests and the two-stage files' macro programs).
    let files: Vec<&[(PathBuf, StageKind)]> = groups
        .iter()
        .map(|g| match g {
            ProgramInput::Stages { files, defines, .. } if defines.is_empty() => files.as_slice(),
            _ => &[],
        })
        .collect();
    let lone_of = |f: &[(PathBuf, StageKind)]| match f {
        [(p, k)] if *k != StageKind::Compute => Some(p.clone()),
        _ => None,
    };
    let lone: BTreeSet<PathBuf> = files.iter().filter_map(|f| lone_of(f)).collect();
    if lone.is_empty() || hosts.is_empty() {
        return Vec::new();
    }
    let stage_files: Vec<(PathBuf, StageKind)> = files.iter().flat_map(|f| f.iter().cloned()).collect();
    let formed: BTreeSet<Vec<&PathBuf>> = files.iter().map(|f| f.iter().map(|(p, _)| p).collect()).collect();
    let mut joined: BTreeSet<PathBuf> = BTreeSet::new();
    let mut notes = Vec::new();
    let mut new = Vec::new();
    for n in programs(hosts, &stage_files) {
        let paths: Vec<&PathBuf> = n.files.iter().map(|(p, _)| p).collect();
        if !paths.iter().any(|p| lone.contains(*p)) || formed.contains(&paths) {
            continue;
        }
        joined.extend(paths.iter().filter(|p| lone.contains(**p)).map(|p| (*p).clone()));
        let shown: Vec<String> = paths.iter().map(|p| format!("`{}`", p.display())).collect();
        notes.push(Diagnostic::new(
            Code::PairedByHostCode,
            format!("{} form one program: `{}:{}` names them together", shown.join(" and "), n.host.display(), n.line),
        ));
        // Named after the fragment stage: programs sharing a vertex stage keep their own names.
        let last = n.files.last().cloned().into_iter().collect::<Vec<_>>();
        new.push(ProgramInput::Stages { name: program_name(&last), files: n.files, defines: Vec::new(), formed: Formed::HostCode });
    }
    // A lone stage that joined a program is no program of its own.
    let gone: Vec<bool> = files.iter().map(|f| lone_of(f).is_some_and(|p| joined.contains(&p))).collect();
    let mut gone = gone.into_iter();
    groups.retain(|_| !gone.next().unwrap_or(false));
    groups.extend(new);
    notes
}

/// A string literal of host code.
#[derive(Debug, Clone, PartialEq, Eq)]
struct Literal {
    text: String,
    line: usize,
    /// The innermost `(`, `{`, `[` (or markup `<`) around it: an id, 0 at top level.
    group: usize,
    /// Statements end at `;`, `{` and `}` (markup: at `>`): consecutive literals sit in
    /// consecutive statements.
    statement: usize,
    /// The innermost block (`{ … }` that is not an initializer) around it: an id, 0 at top
    /// level.
    block: usize,
}

/// The programs the `hosts` files name among `stage_files` (each with its stage), in host
/// file order, each file set once.
pub fn programs(hosts: &[PathBuf], stage_files: &[(PathBuf, StageKind)]) -> Vec<Named> {
    let mut by_name: BTreeMap<String, Vec<(PathBuf, StageKind)>> = BTreeMap::new();
    for (p, k) in stage_files {
        if let Some(name) = p.file_name() {
            by_name.entry(name.to_string_lossy().into_owned()).or_default().push((p.clone(), *k));
        }
    }
    let mut seen: BTreeSet<Vec<PathBuf>> = BTreeSet::new();
    let mut out = Vec::new();
    for host in hosts {
        // Regular files only (a FIFO named `x.cpp` would block a plain read), at most
        // HOST_BYTES.
        let Ok(bytes) = crate::read::bounded(host, HOST_BYTES) else { continue };
        let text = String::from_utf8_lossy(&bytes);
        let markup = host.extension().and_then(|e| e.to_str()).is_some_and(|e| MARKUP.iter().any(|m| e.eq_ignore_ascii_case(m)));
        let resolved: Vec<(Literal, PathBuf, StageKind)> = literals(&text, markup)
            .into_iter()
            .filter_map(|l| {
                let (p, k) = resolve(&l.text, host, &by_name)?;
                Some((l, p, k))
            })
            .collect();
        for sequence in sequences(&resolved) {
            for files in in_order(&sequence) {
                let key: Vec<PathBuf> = files.iter().map(|(p, _, _)| p.clone()).collect();
                if seen.insert(key) {
                    let line = files.iter().map(|(_, _, line)| *line).min().unwrap_or(1);
                    out.push(Named { files: files.into_iter().map(|(p, k, _)| (p, k)).collect(), host: host.clone(), line });
                }
            }
        }
    }
    out
}

/// The stage files a host file names in order: the literals of one group that name two
/// stages or more, and runs of literals in consecutive statements (each in its own group).
fn sequences(resolved: &[(Literal, PathBuf, StageKind)]) -> Vec<Vec<(PathBuf, StageKind, usize)>> {
    let mut groups: BTreeMap<usize, Vec<usize>> = BTreeMap::new();
    for (i, (l, _, _)) in resolved.iter().enumerate() {
        groups.entry(l.group).or_default().push(i);
    }
    let mut in_group = vec![false; resolved.len()];
    let mut out: Vec<(usize, Vec<usize>)> = Vec::new();
    for members in groups.values() {
        let kinds: BTreeSet<StageKind> = members.iter().map(|i| resolved[*i].2).collect();
        if kinds.len() >= 2 {
            for i in members {
                in_group[*i] = true;
            }
            out.push((members[0], members.clone()));
        }
    }
    // Inside a function body the statements of one block run on across statements that
    // name no stage (`if (!AddShader(GL_VERTEX_SHADER, "a.vs")) { return false; }` then the
    // fragment stage); at top level only the next statement follows.
    let mut run: Vec<usize> = Vec::new();
    for i in (0..resolved.len()).filter(|i| !in_group[*i]) {
        let follows = run.last().is_some_and(|&j| {
            let (here, last) = (&resolved[i].0, &resolved[j].0);
            here.block == last.block && (here.block != 0 || here.statement <= last.statement + 1)
        });
        if !follows {
            if run.len() >= 2 {
                out.push((run[0], std::mem::take(&mut run)));
            }
            run.clear();
        }
        run.push(i);
    }
    if run.len() >= 2 {
        out.push((run[0], run));
    }
    out.sort_by_key(|(first, _)| *first);
    out.into_iter().map(|(_, ids)| ids.into_iter().map(|i| (resolved[i].1.clone(), resolved[i].2, resolved[i].0.line)).collect()).collect()
}

/// Each vertex stage of a sequence with the next fragment stage, and the geometry and
/// tessellation stages named between them; a vertex stage after a fragment stage starts
/// the next program. Two parallel lists (`vs[] = {"a.vert", "b.vert"}; fs[] = {"a.frag",
/// "b.frag"}`: as many vertex stages as fragment stages, all the vertex stages first) pair
/// by position.
fn in_order(sequence: &[(PathBuf, StageKind, usize)]) -> Vec<Vec<(PathBuf, StageKind, usize)>> {
    let half = sequence.len() / 2;
    let parallel = half >= 2
        && sequence.len() == 2 * half
        && sequence[..half].iter().all(|(_, k, _)| *k == StageKind::Vertex)
        && sequence[half..].iter().all(|(_, k, _)| *k == StageKind::Fragment);
    if parallel {
        return sequence[..half].iter().zip(&sequence[half..]).map(|(v, f)| vec![v.clone(), f.clone()]).collect();
    }
    let mut out = Vec::new();
    let mut vertices: Vec<&(PathBuf, StageKind, usize)> = Vec::new();
    let mut between: BTreeMap<StageKind, &(PathBuf, StageKind, usize)> = BTreeMap::new();
    let mut after_fragment = false;
    for item in sequence {
        match item.1 {
            // Host code pairs the stages of a raster pipeline with vertices.
            kind if kind == StageKind::Compute || kind.reference_only() => continue,
            StageKind::Fragment => {
                for v in &vertices {
                    let mut files = vec![(*v).clone()];
                    files.extend(between.values().map(|b| (*b).clone()));
                    files.push(item.clone());
                    files.sort_by_key(|(_, k, _)| *k);
                    out.push(files);
                }
                after_fragment = true;
                continue;
            }
            _ if after_fragment => {
                vertices.clear();
                between.clear();
                after_fragment = false;
            }
            _ => {}
        }
        match item.1 {
            StageKind::Vertex => vertices.push(item),
            kind => {
                between.insert(kind, item);
            }
        }
    }
    out
}

/// The stage file a literal names: its trailing path components match; of several, the
/// one sharing the most folders with the host file, then the shallowest; a tie names none.
fn resolve(literal: &str, host: &Path, by_name: &BTreeMap<String, Vec<(PathBuf, StageKind)>>) -> Option<(PathBuf, StageKind)> {
    let wanted: Vec<&str> = literal.split(['/', '\\']).filter(|c| !c.is_empty() && *c != "." && *c != "..").collect();
    let candidates = by_name.get(*wanted.last()?)?;
    let ends_so = |p: &Path| {
        let names: Vec<String> = p
            .components()
            .filter_map(|c| match c {
                Component::Normal(s) => Some(s.to_string_lossy().into_owned()),
                _ => None,
            })
            .collect();
        names.len() >= wanted.len() && names[names.len() - wanted.len()..].iter().zip(&wanted).all(|(a, b)| a == b)
    };
    let host_dir = crate::diag::paths::absolute(host.parent().unwrap_or(Path::new("")));
    let score = |p: &Path| {
        let dir = crate::diag::paths::absolute(p.parent().unwrap_or(Path::new("")));
        let shared = dir.components().zip(host_dir.components()).take_while(|(a, b)| a == b).count();
        (shared, usize::MAX - dir.components().count())
    };
    let scored: Vec<(usize, usize, usize)> = candidates
        .iter()
        .enumerate()
        .filter(|(_, (p, _))| ends_so(p))
        .map(|(i, (p, _))| {
            let (shared, shallow) = score(p);
            (shared, shallow, i)
        })
        .collect();
    let best = scored.iter().map(|(shared, shallow, _)| (*shared, *shallow)).max()?;
    let mut nearest = scored.iter().filter(|(shared, shallow, _)| (*shared, *shallow) == best);
    let (_, _, i) = nearest.next()?;
    if nearest.next().is_some() {
        return None;
    }
    Some(candidates[*i].clone())
}

/// The string literals of host code that could name a file, with their group and statement.
/// Comments (`//`, `/* */`; markup `<!-- -->`) are skipped. A `{` after `=`, `,`, `(` or
/// `{` opens an initializer, which holds no statements; any other opens a block, whose
/// braces end statements.
fn literals(text: &str, markup: bool) -> Vec<Literal> {
    let bytes = text.as_bytes();
    let mut out = Vec::new();
    let mut stack: Vec<usize> = Vec::new();
    let mut blocks: Vec<bool> = Vec::new();
    let mut block_ids: Vec<usize> = Vec::new();
    let (mut groups, mut statement, mut line, mut i) = (0usize, 0usize, 1usize, 0usize);
    // The offset just past `end`, searched from `from` (the text's end when missing).
    let past =
        |from: usize, end: &[u8]| bytes[from..].windows(end.len()).position(|w| w == end).map_or(bytes.len(), |e| from + e + end.len());
    while i < bytes.len() {
        let rest = &bytes[i..];
        let comment_end = match bytes[i] {
            b'/' if !markup && rest.starts_with(b"//") => Some(past(i, b"\n")),
            b'/' if !markup && rest.starts_with(b"/*") => Some(past(i + 2, b"*/")),
            b'<' if markup && rest.starts_with(b"<!--") => Some(past(i + 4, b"-->")),
            _ => None,
        };
        if let Some(end) = comment_end {
            line += bytes[i..end].iter().filter(|b| **b == b'\n').count();
            i = end;
            continue;
        }
        if let q @ (b'"' | b'\'') = bytes[i] {
            let mut end = i + 1;
            while end < bytes.len() && bytes[end] != q && bytes[end] != b'\n' {
                end += if bytes[end] == b'\\' && !markup { 2 } else { 1 };
            }
            let end = end.min(bytes.len());
            let content = String::from_utf8_lossy(&bytes[i + 1..end]);
            if content.contains('.') && content.len() < 512 {
                let (group, block) = (stack.last().copied().unwrap_or(0), block_ids.last().copied().unwrap_or(0));
                out.push(Literal { text: content.into_owned(), line, group, statement, block });
            }
            // An unterminated literal ends at its line's end, which is counted below.
            i = if bytes.get(end) == Some(&q) { end + 1 } else { end };
            continue;
        }
        match bytes[i] {
            b'\n' => line += 1,
            b'(' | b'[' => {
                groups += 1;
                stack.push(groups);
            }
            b'<' if markup => {
                groups += 1;
                stack.push(groups);
            }
            b'{' => {
                groups += 1;
                stack.push(groups);
                let before = bytes[..i].iter().rev().find(|b| !b.is_ascii_whitespace());
                let block = !matches!(before, Some(b'=' | b',' | b'(' | b'{'));
                blocks.push(block);
                if block {
                    block_ids.push(groups);
                    statement += 1;
                }
            }
            b')' | b']' => {
                stack.pop();
            }
            b'}' => {
                stack.pop();
                if blocks.pop().unwrap_or(true) {
                    block_ids.pop();
                    statement += 1;
                }
            }
            b'>' if markup => {
                stack.pop();
                statement += 1;
            }
            b';' => statement += 1,
            _ => {}
        }
        i += 1;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn files(names: &[(&str, StageKind)]) -> Vec<(PathBuf, StageKind)> {
        names.iter().map(|(n, k)| (PathBuf::from(n), *k)).collect()
    }

    fn named(host: &str, text: &str, stage_files: &[(PathBuf, StageKind)]) -> Vec<Vec<String>> {
        let dir = std::env::temp_dir().join(format!("effectc-host-{}-{}", std::process::id(), host.replace('/', "_")));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(host);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(&path, text).unwrap();
        let rooted: Vec<(PathBuf, StageKind)> = stage_files.iter().map(|(p, k)| (dir.join(p), *k)).collect();
        let out = programs(&[path], &rooted)
            .into_iter()
            .map(|n| n.files.iter().map(|(p, _)| p.strip_prefix(&dir).unwrap().display().to_string()).collect())
            .collect();
        std::fs::remove_dir_all(&dir).unwrap();
        out
    }

    use StageKind::{Fragment as F, Geometry as G, Vertex as V};

    #[test]
    fn literals_in_one_call_or_initializer_pair() {
        let stages = files(&[("data/PCN.vert", V), ("data/PN.vert", V), ("data/Diffuse.frag", F), ("data/Phong.frag", F)]);
        let text = "Program g_progs[] = {\n  {\"PCN.vert\", \"Diffuse.frag\"},\n  {\"PN.vert\", \"Phong.frag\"},\n};\n\
                    void init() { g = Load(\"PN.vert\", \"Diffuse.frag\"); }\n";
        assert_eq!(
            named("main.cpp", text, &stages),
            [
                vec!["data/PCN.vert", "data/Diffuse.frag"],
                vec!["data/PN.vert", "data/Phong.frag"],
                vec!["data/PN.vert", "data/Diffuse.frag"]
            ]
        );
    }

    #[test]
    fn consecutive_statements_pair_and_a_statement_between_ends_the_run() {
        let stages = files(&[("a.vert", V), ("a.geom", G), ("b.frag", F), ("c.frag", F)]);
        let text = "shaders.push_back(LoadShader(GL_VERTEX_SHADER, \"a.vert\"));\n\
                    shaders.push_back(LoadShader(GL_GEOMETRY_SHADER, \"a.geom\"));\n\
                    shaders.push_back(LoadShader(GL_FRAGMENT_SHADER, \"b.frag\"));\n\
                    prog = CreateProgram(shaders);\n\
                    other = Load(\"c.frag\");\n";
        assert_eq!(named("x.cpp", text, &stages), [vec!["a.vert", "a.geom", "b.frag"]]);
    }

    #[test]
    fn a_sequence_pairs_each_vertex_stage_with_the_next_fragment_stage() {
        let stages = files(&[("a.vs", V), ("b.vs", V), ("x.fs", F), ("c.vs", V), ("y.fs", F)]);
        let text = "SHADERS = [\"a.vs\", \"b.vs\", \"x.fs\", \"c.vs\", \"y.fs\"]\n";
        assert_eq!(named("load.py", text, &stages), [vec!["a.vs", "x.fs"], vec!["b.vs", "x.fs"], vec!["c.vs", "y.fs"]]);
    }

    #[test]
    fn a_function_body_runs_on_across_statements_that_name_no_stage() {
        let stages = files(&[("sky.vs", V), ("sky.fs", F), ("other.fs", F)]);
        let text = "bool Init() {\n  if (!AddShader(GL_VERTEX_SHADER, \"sky.vs\")) {\n    return false;\n  }\n\
                    \x20 if (!AddShader(GL_FRAGMENT_SHADER, \"sky.fs\")) {\n    return false;\n  }\n  return Finalize();\n}\n\
                    bool Other() { return AddShader(GL_FRAGMENT_SHADER, \"other.fs\"); }\n";
        assert_eq!(named("technique.cpp", text, &stages), [vec!["sky.vs", "sky.fs"]]);
    }

    #[test]
    fn a_fifo_named_like_host_code_is_not_read() {
        // A plain read of a FIFO blocks until a writer comes: only regular files are read.
        let dir = std::env::temp_dir().join(format!("effectc-host-fifo-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let fifo = dir.join("loader.cpp");
        let made = std::process::Command::new("mkfifo").arg(&fifo).status().expect("mkfifo runs");
        assert!(made.success());
        let stages = vec![(dir.join("a.vert"), V), (dir.join("a.frag"), F)];
        assert!(programs(&[fifo], &stages).is_empty());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn parallel_lists_pair_by_position() {
        let stages = files(&[("a.vert", V), ("b.vert", V), ("x.frag", F), ("y.frag", F)]);
        let text = "const char* vs[] = {\"a.vert\", \"b.vert\"};\nconst char* fs[] = {\"x.frag\", \"y.frag\"};\n";
        assert_eq!(named("lists.c", text, &stages), [vec!["a.vert", "x.frag"], vec!["b.vert", "y.frag"]]);
        // Two vertex stages before one fragment stage both pair with it.
        let text = "{\"a.vert\", \"b.vert\", \"x.frag\"}";
        assert_eq!(named("one.c", text, &stages), [vec!["a.vert", "x.frag"], vec!["b.vert", "x.frag"]]);
    }

    #[test]
    fn markup_attributes_pair_and_comments_do_not() {
        let stages = files(&[("s/a.vert", V), ("s/b.frag", F), ("s/c.frag", F)]);
        let text = "<scene>\n<!-- <prog vert=\"a.vert\" frag=\"c.frag\"/> -->\n<prog vert=\"a.vert\" frag=\"b.frag\"/>\n</scene>\n";
        assert_eq!(named("scene.xml", text, &stages), [vec!["s/a.vert", "s/b.frag"]]);
        let code = "// Load(\"a.vert\", \"c.frag\");\n/* Load(\"a.vert\", \"c.frag\"); */\nint x;\n";
        assert!(named("m.c", code, &stages).is_empty());
    }

    #[test]
    fn the_nearest_file_of_a_name_is_meant_and_a_tie_names_none() {
        let stages = files(&[
            ("Tut 1/data/PN.vert", V),
            ("data/PN.vert", V),
            ("Tut 2/data/PN.vert", V),
            ("Tut 1/data/L.frag", F),
            ("data/L.frag", F),
        ]);
        let text = "p = Load(\"PN.vert\", \"L.frag\");";
        assert_eq!(named("Tut 1/main.cpp", text, &stages), [vec!["Tut 1/data/PN.vert", "Tut 1/data/L.frag"]]);
        // From Tut 3, the shared data/ folder is the shallowest of the files named so.
        assert_eq!(named("Tut 3/main.cpp", text, &stages), [vec!["data/PN.vert", "data/L.frag"]]);
        let tied = files(&[("x/a.vert", V), ("y/a.vert", V), ("x/b.frag", F)]);
        assert!(named("main.cpp", "Load(\"a.vert\", \"b.frag\");", &tied).is_empty());
        // A path in the literal picks among them.
        assert_eq!(named("main.cpp", "Load(\"y/a.vert\", \"b.frag\");", &tied), [vec!["y/a.vert", "x/b.frag"]]);
    }

    #[test]
    fn literals_of_one_stage_or_unknown_files_make_no_program() {
        let stages = files(&[("a.vert", V), ("b.vert", V), ("c.frag", F)]);
        assert!(named("m.cpp", "Load(\"a.vert\", \"b.vert\"); x = \"readme.txt\";", &stages).is_empty());
        assert!(named("m.cpp", "Load(\"a.vert\", \"missing.frag\");", &stages).is_empty());
    }
}
