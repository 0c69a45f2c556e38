//! Globals initialised at run time: GLSL evaluates a global's initializer before `main`,
//! and desktop GLSL lets it read uniforms, inputs and other globals (`float t =
//! float(FrameCount) * 0.025;`); naga takes only constant initializers. Such a global's
//! initializer becomes the body of a function in place (so every other rewrite still edits
//! its text) and `main` assigns the global from it first: `float t; float
//! effectc_init_t() { return float(FrameCount) * 0.025; }` and `t = effectc_init_t();`.

use std::collections::HashMap;
use std::fmt::Write;

use super::Ctx;
use crate::front::lexical::identifiers;
use crate::front::syntax::{dims_text, Referent, Storage};

impl Ctx<'_> {
    pub(super) fn runtime_initializers(&mut self) {
        let s = self.s;
        if s.main_body.is_none() {
            return;
        }
        let bodies = macro_bodies(&s.text);
        for g in &s.globals {
            let Some(init) = g.initializer.clone() else { continue };
            if g.storage != Storage::Private || g.block.is_some() || g.shares_decl || !self.reads_run_time_values(&init, &bodies) {
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
    /// input, a global that is not `const`, or calls a function of the stage (also through
    /// the macros `bodies` of the stage).
    fn reads_run_time_values(&self, init: &std::ops::Range<usize>, bodies: &HashMap<String, &str>) -> bool {
        let s = self.s;
        let inside = |r: &std::ops::Range<usize>| r.start >= init.start && r.end <= init.end;
        let reads = s.uses.iter().filter(|u| inside(&u.span)).any(|u| match u.target {
            Referent::Global(i) => s.globals[i].storage != Storage::Const,
            _ => false,
        });
        reads
            || s.calls.iter().filter(|c| inside(&c.span)).any(|c| s.functions.iter().any(|f| f.name == c.name))
            || self.macros_read_run_time_values(&s.text[init.clone()], bodies)
    }

    /// A macro the initializer uses (`#define tilt vec2(tx, ty)`, `cos(tilt)`) names a
    /// global that is not `const` or a function of the stage, directly or through other
    /// macros: its uses are in the `#define` line, outside the initializer.
    fn macros_read_run_time_values(&self, init: &str, bodies: &HashMap<String, &str>) -> bool {
        let s = self.s;
        if bodies.is_empty() {
            return false;
        }
        let run_time =
            |name: &str| s.global(name).is_some_and(|g| g.storage != Storage::Const) || s.functions.iter().any(|f| f.name == name);
        let mut seen: Vec<&str> = Vec::new();
        let mut todo: Vec<&str> = identifiers(init).filter(|w| bodies.contains_key(*w)).collect();
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
fn macro_bodies(text: &str) -> HashMap<String, &str> {
    let mut out = HashMap::new();
    for (name, body) in crate::front::conditionals::define_lines(text) {
        let body = &text[body];
        let body = match body.strip_prefix('(') {
            Some(rest) => rest.find(')').map_or("", |i| &rest[i + 1..]),
            None => body,
        };
        if !name.is_empty() {
            out.insert(name, body);
        }
    }
    out
}
