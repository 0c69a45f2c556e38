//! Varyings, vertex inputs and fragment outputs: `attribute`/`varying` → `in`/`out`, `flat`
//! on integer varyings, a location on every name, matrix varyings split into one vector per
//! column (assembled or split again in `main`).

use std::fmt::Write;

use super::Ctx;
use crate::front::plan::location_slots;
use crate::front::syntax::{dims_text, matrix_shape, Referent, StageSyntax, Storage};
use crate::front::varying_locations::{self, component};
use crate::stage::StageKind;

impl Ctx<'_> {
    /// A varying, vertex input or fragment output declaration: `in`/`out` for 1xx storage,
    /// `flat` for integers, a location on every name, matrices split into columns.
    pub(super) fn varying_declaration(
        &mut self,
        idxs: Vec<usize>,
        vertex_inputs: &mut LocationAllocator,
        fragment_outputs: &mut LocationAllocator,
    ) {
        let s = self.s;
        let first = &s.globals[idxs[0]];
        let decl = first.decl_span.clone();
        if first.name.starts_with("gl_") {
            // Redeclared built-ins (`out gl_PerVertex {…}`, `in vec4 gl_FragCoord`).
            self.edits.delete(decl);
            return;
        }
        if self.flattens(first) {
            self.flatten_block(first);
            return;
        }
        // A geometry stage's matrix outputs stay whole: the geometry fold passes them at each
        // `EmitVertex()`, where columns copied at the end of `main` would come too late.
        let split = idxs.len() == 1
            && first.block.is_none()
            && !first.ty.is_array()
            && matrix_shape(&first.ty.base).is_some()
            && self.s.stage != StageKind::Geometry;
        // A declaration a macro writes (`IN(vec4 vertex, POSITION)` with `#define IN(d, l) in
        // d;`) has its keyword, name and layout inside the macro: the use is written out again.
        let written_out = idxs.len() > 1 || declared_by_macro(s, first);
        if !written_out && !split {
            self.drop_invariant(first);
            // (A matrix split into columns and several names in one declaration are written
            // out again below, keyword too.)
            self.storage_keyword(first);
            self.flat_integer_output(first);
        }
        let kind = if is_vertex_input(s, first.storage) {
            Some(vertex_inputs)
        } else if is_fragment_output(s, first.storage) {
            Some(fragment_outputs)
        } else {
            None
        };
        if split {
            let loc = match (first.location, kind) {
                (Some(l), _) => l,
                (None, Some(alloc)) => alloc.next(location_slots(&first.ty, s)),
                (None, None) => self.plan.varyings.get(&first.name).copied().unwrap_or(0),
            };
            self.split_matrix(first, loc);
            return;
        }
        if !written_out {
            if first.location.is_some() {
                self.unpack_component(first);
                return;
            }
            let loc = match kind {
                Some(alloc) => alloc.next(location_slots(&first.ty, s)),
                None => self.plan.varyings.get(&first.name).copied().unwrap_or(0),
            };
            self.add_layout(first, &format!("location = {loc}"), "location");
        } else {
            // Split `out vec3 a, b;` so each name gets its own location (and write out a
            // macro's declaration).
            let mut text = String::new();
            let mut alloc = kind;
            for &i in &idxs {
                let g = &s.globals[i];
                let loc = match (&mut alloc, g.location) {
                    (_, Some(l)) => l,
                    (Some(a), None) => a.next(location_slots(&g.ty, s)),
                    (None, None) => self.plan.varyings.get(&g.name).copied().unwrap_or(0),
                };
                let interp = match g.interp {
                    Some(i) => format!("{} ", i.keyword()),
                    None if self.needs_flat(g) => "flat ".to_string(),
                    None => String::new(),
                };
                let dir = storage_word(s.stage, g.storage);
                let _ = write!(text, "layout(location = {loc}) {interp}{dir} {} {}{};", g.ty.base, g.name, dims_text(&g.ty));
            }
            self.edits.replace(decl, text);
        }
    }

    /// A matrix input/output becomes one vector per column plus a private matrix.
    fn split_matrix(&mut self, g: &crate::front::syntax::Global, loc: u32) {
        let (cols, rows) = matrix_shape(&g.ty.base).expect("matrix");
        let dir = storage_word(self.s.stage, g.storage);
        let interp = g.interp.map(|i| format!("{} ", i.keyword())).unwrap_or_default();
        let mut text = String::new();
        let names: Vec<String> = (0..cols).map(|c| format!("{}_effectc_col{c}", g.name)).collect();
        for (c, n) in names.iter().enumerate() {
            let _ = write!(text, "layout(location = {}) {interp}{dir} vec{rows} {n}; ", loc + c as u32);
        }
        let _ = write!(text, "{} {};", g.ty.base, g.name);
        self.edits.replace(g.decl_span.clone(), text);
        if dir == "in" {
            let _ = write!(self.prologue, " {} = {}({});", g.name, g.ty.base, names.join(", "));
        } else {
            for (c, n) in names.iter().enumerate() {
                let _ = write!(self.epilogue, " {n} = {}[{c}];", g.name);
            }
        }
    }

    /// `invariant` leaves a user's varying: naga takes it only on `gl_Position`, and it
    /// asks for the same value in every program computing it the same way, which one
    /// translated program does not change.
    fn drop_invariant(&mut self, g: &crate::front::syntax::Global) {
        if let Some(span) = &g.invariant {
            if !g.name.starts_with("gl_") {
                self.edits.delete(span.clone());
            }
        }
    }

    pub(super) fn insert_main_hooks(&mut self) {
        let Some(body) = self.s.main_body.clone() else { return };
        let s = self.s;
        if s.stage == StageKind::Vertex && !s.uses.iter().any(|u| u.name == "gl_Position" && u.target == Referent::Unresolved) {
            // A vertex stage may leave `gl_Position` unwritten (a geometry stage or transform
            // feedback follows); naga's entry point needs the output.
            self.prologue.push_str(" gl_Position = vec4(0.0);");
        }
        if !self.prologue.is_empty() {
            self.edits.insert(body.start + 1, self.prologue.clone());
        }
        if !self.epilogue.is_empty() {
            for r in &self.s.main_returns {
                self.edits.insert(r.start, format!("{{{} ", self.epilogue));
                self.edits.insert(r.end, " }");
            }
            let close = self.s.text[..body.end].rfind('}').unwrap_or(body.end);
            self.edits.insert(close, format!("{}\n", self.epilogue));
        }
    }

    /// Whether `g` is an integer varying naga needs marked `flat` (GLSL interpolates no
    /// integer, and requires `flat` only on the fragment side; naga wants it on both).
    fn needs_flat(&self, g: &crate::front::syntax::Global) -> bool {
        g.interp.is_none()
            && g.block.is_none()
            && g.ty.is_integer()
            && matches!(g.storage, Storage::Out | Storage::Varying | Storage::In)
            && !is_vertex_input(self.s, g.storage)
            && !is_fragment_output(self.s, g.storage)
    }

    fn flat_integer_output(&mut self, g: &crate::front::syntax::Global) {
        if self.needs_flat(g) {
            let at = g.storage_span.as_ref().map(|s| s.start).unwrap_or(g.decl_span.start);
            self.edits.insert(at, "flat ");
        }
    }

    /// `attribute`/`varying` → `in`/`out`.
    fn storage_keyword(&mut self, g: &crate::front::syntax::Global) {
        if !matches!(g.storage, Storage::Attribute | Storage::Varying) {
            return;
        }
        if let Some(span) = &g.storage_span {
            let word = storage_word(self.s.stage, g.storage);
            let what = if g.storage == Storage::Attribute { "attribute" } else { "varying" };
            self.legacy(span.clone(), what, word); // same versions forbid attribute/varying
            self.edits.replace(span.clone(), word);
        }
    }

    /// A varying in a location's later component (`layout(location = 0, component = 3)`)
    /// moves to the location the plan gives its pair; `component` goes (naga's GLSL front has
    /// no such qualifier, and a whole location per varying is what WGSL passes).
    fn unpack_component(&mut self, g: &crate::front::syntax::Global) {
        let (Some(component), Some(location), Some(span)) = (component(g), g.location, g.layout_span.clone()) else {
            return;
        };
        if !varying_locations::is_varying(self.s, g) {
            return;
        }
        let location = self.plan.component_locations.get(&(location, component)).copied().unwrap_or(location);
        let items: Vec<String> = g
            .layout_items
            .iter()
            .filter(|(key, _)| key != "component")
            .map(|(key, at)| if key == "location" { format!("location = {location}") } else { self.s.text[at.clone()].to_string() })
            .collect();
        self.edits.replace(span, format!("layout({})", items.join(", ")));
    }
}

pub(super) fn is_vertex_input(s: &StageSyntax, storage: Storage) -> bool {
    s.stage == StageKind::Vertex && matches!(storage, Storage::In | Storage::Attribute)
}

pub(super) fn is_fragment_output(s: &StageSyntax, storage: Storage) -> bool {
    s.stage == StageKind::Fragment && storage == Storage::Out
}

fn storage_word(stage: StageKind, storage: Storage) -> &'static str {
    match (storage, stage) {
        (Storage::Attribute, _) | (Storage::In, _) => "in",
        (Storage::Varying, StageKind::Vertex) => "out",
        (Storage::Varying, _) => "in",
        _ => "out",
    }
}

/// Hands out locations, skipping ones taken explicitly.
pub(super) struct LocationAllocator {
    used: Vec<(u32, u32)>,
    next: u32,
}

impl LocationAllocator {
    pub(super) fn new(explicit: impl Iterator<Item = (u32, u32)>) -> Self {
        LocationAllocator { used: explicit.map(|(l, n)| (l, l + n)).collect(), next: 0 }
    }
    pub(super) fn reserve(&mut self, at: u32, n: u32) {
        self.used.push((at, at + n));
    }
    pub(super) fn next(&mut self, slots: u32) -> u32 {
        while self.used.iter().any(|&(a, b)| self.next < b && a < self.next + slots) {
            self.next += 1;
        }
        let loc = self.next;
        self.used.push((loc, loc + slots));
        self.next += slots;
        loc
    }
}

/// Whether `g`'s declaration comes from a macro's expansion: its name is not written at its
/// span (which is the macro use's). The text holds the names as renamed (keywords of 4.50).
fn declared_by_macro(s: &StageSyntax, g: &crate::front::syntax::Global) -> bool {
    s.text.get(g.name_span.clone()) != Some(g.name.as_str())
}
