//! Globals initialised at run time: GLSL evaluates a global's initializer before `main`,
//! and desktop GLSL lets it read uniforms, inputs and other globals (`float t =
//! float(FrameCount) * 0.025;`); naga takes only constant initializers. Such a global's
//! initializer becomes the body of a function in place (so every other rewrite still edits
//! its text) and `main` assigns the global from it first: `float t; float
//! effectc_init_t() { return float(FrameCount) * 0.025; }` and `t = effectc_init_t();`.

use std::fmt::Write;

use super::Ctx;
use crate::front::syntax::{dims_text, Referent, Storage};

impl Ctx<'_> {
    pub(super) fn runtime_initializers(&mut self) {
        let s = self.s;
        if s.main_body.is_none() {
            return;
        }
        for g in &s.globals {
            let Some(init) = g.initializer.clone() else { continue };
            if g.storage != Storage::Private || g.block.is_some() || g.shares_decl || !self.reads_run_time_values(&init) {
                continue;
            }
            let Some(eq) = s.text[..init.start].rfind('=').filter(|&e| e >= g.name_span.end) else { continue };
            let function = format!("effectc_init_{}", g.name);
            let ty = format!("{}{}", g.ty.base, dims_text(&g.ty));
            self.edits.replace(eq..init.start, format!("; {ty} {function}() {{ return "));
            self.edits.insert(g.decl_span.end, " }");
            let _ = write!(self.prologue, " {} = {function}();", g.name);
            self.header_before = Some(self.header_before.map_or(g.decl_span.start, |b| b.min(g.decl_span.start)));
        }
    }

    /// The initializer at `init` reads something that is not a constant: a uniform, an
    /// input, a global that is not `const`, or calls a function of the stage.
    fn reads_run_time_values(&self, init: &std::ops::Range<usize>) -> bool {
        let s = self.s;
        let inside = |r: &std::ops::Range<usize>| r.start >= init.start && r.end <= init.end;
        let reads = s.uses.iter().filter(|u| inside(&u.span)).any(|u| match u.target {
            Referent::Global(i) => s.globals[i].storage != Storage::Const,
            _ => false,
        });
        reads
            || s.calls.iter().filter(|c| inside(&c.span)).any(|c| s.functions.iter().any(|f| f.name == c.name))
            || self.macros_read_run_time_values(&s.text[init.clone()])
    }

    /// A macro the initializer uses (`#define tilt vec2(tx, ty)`, `cos(tilt)`) names a
    /// global that is not `const` or a function of the stage, directly or through other
    /// macros: its uses are in the `#define` line, outside the initializer.
    fn macros_read_run_time_values(&self, init: &str) -> bool {
        let s = self.s;
        let bodies = macro_bodies(&s.text);
        if bodies.is_empty() {
            return false;
        }
        let run_time =
            |name: &str| s.global(name).is_some_and(|g| g.storage != Storage::Const) || s.functions.iter().any(|f| f.name == name);
        let mut seen: Vec<&str> = Vec::new();
        let mut todo: Vec<&str> = identifiers(init).filter(|w| bodies.contains_key(w)).collect();
        while let Some(m) = todo.pop() {
            if seen.contains(&m) || seen.len() > 256 {
                continue;
            }
            seen.push(m);
            for w in identifiers(bodies[m]) {
                if bodies.contains_key(w) {
                    todo.push(w);
                } else if run_time(w) {
                    return true;
                }
            }
        }
        false
    }
}

/// The body of every `#define` of `text` by macro name (a function-like macro's after its
/// parameter list; the last definition of a name wins).
fn macro_bodies(text: &str) -> std::collections::HashMap<&str, &str> {
    let mut out = std::collections::HashMap::new();
    for line in text.lines() {
        let Some(rest) = line.trim_start().strip_prefix('#').map(str::trim_start).and_then(|r| r.strip_prefix("define")) else { continue };
        let rest = rest.trim_start();
        let end = rest.find(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).unwrap_or(rest.len());
        let (name, mut body) = rest.split_at(end);
        if body.starts_with('(') {
            body = body.find(')').map_or("", |i| &body[i + 1..]);
        }
        if !name.is_empty() {
            out.insert(name, body);
        }
    }
    out
}

/// The identifiers of `text` (words that start with a letter or `_`).
fn identifiers(text: &str) -> impl Iterator<Item = &str> {
    text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).filter(|w| w.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_'))
}
