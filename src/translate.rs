//! `effectc translate`: check, then translate every clean program and write its targets.
//!
//! A program with check errors is not translated (its diagnostics are the output, exit 1);
//! the others still are. Files are written atomically (temporary file + rename) into the
//! output directory, which is created as needed; a path that is one of the inputs is never
//! written.

use std::path::{Path, PathBuf};

use crate::back::units::{emit_contained, target_error, translate_units};
use crate::back::{Target, TranslateOptions, Translation};
use crate::check::{self, Outcome};
use crate::diag::{Code, Diagnostic};
use crate::output::{input_paths, write_atomic};

/// What `translate` was asked to do.
#[derive(Debug, Clone)]
pub struct Request {
    pub input: check::InputSpec,
    pub back: TranslateOptions,
    pub targets: Vec<Target>,
    /// `None`: `out/<effect>/` for each program.
    pub out: Option<PathBuf>,
}

/// One translated program and the files written for it.
#[derive(Debug)]
pub struct Written {
    pub translation: Translation,
    pub dir: PathBuf,
    pub files: Vec<PathBuf>,
}

/// Runs check and translation; diagnostics of both are in the outcome.
pub fn run(request: &Request) -> (Outcome, Vec<Written>) {
    let (mut outcome, checked) = request.input.check();
    let inputs = input_paths(&outcome, &request.input.paths);
    let mut written = Vec::new();
    'programs: for c in &checked {
        for (result, dir_name) in translate_units(c, request.back) {
            let translation = match result {
                Ok(t) => t,
                Err(diags) => {
                    outcome.diagnostics.extend(diags);
                    continue;
                }
            };
            let file = translation.file;
            let dir = request.out.clone().unwrap_or_else(|| Path::new("out").join(&dir_name));
            let mut files = Vec::new();
            for &target in &request.targets {
                let outputs = match emit_contained(&translation, target) {
                    Ok(o) => o,
                    Err(e) => {
                        outcome.diagnostics.push(target_error(file, target, &e));
                        continue;
                    }
                };
                for o in outputs {
                    let path = dir.join(&o.file_name);
                    match write_atomic(&path, &o.bytes, &inputs) {
                        Ok(()) => files.push(path),
                        Err(e) => {
                            // The first failed write stops the command, with one message; the
                            // program's files written so far go, so nothing is half there.
                            for f in &files {
                                let _ = std::fs::remove_file(f);
                            }
                            outcome.io_error = true;
                            outcome.diagnostics.push(
                                Diagnostic::new(Code::OutputIo, e)
                                    .with_note("nothing more was written: the first failed write stops the run"),
                            );
                            break 'programs;
                        }
                    }
                }
            }
            written.push(Written { translation, dir, files });
        }
    }
    crate::diag::sort(&mut outcome.diagnostics);
    (outcome, written)
}

/// Human summary of one translated program, with `--explain` detail when asked.
pub fn summary(w: &Written, explain: bool) -> String {
    let names: Vec<String> = w.files.iter().map(|f| f.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default()).collect();
    let mut text = format!("translated {} → {}: {}\n", w.translation.name, w.dir.display(), names.join(", "));
    if let Some(g) = &w.translation.reflection.geometry {
        text.push_str(&geometry_plan(g, explain));
    }
    let left = w.translation.left_out();
    if !left.is_empty() {
        if explain {
            text.push_str(&format!("  left out {} item{}:\n", left.len(), if left.len() == 1 { "" } else { "s" }));
            for l in left {
                text.push_str(&format!("    {} `{}`: {}\n", l.kind, l.name, l.reason));
            }
        } else {
            let mut kinds: Vec<&str> = left.iter().map(|l| l.kind).collect();
            kinds.dedup();
            text.push_str(&format!(
                "  left out {} unused item{} ({}); --explain lists them\n",
                left.len(),
                if left.len() == 1 { "" } else { "s" },
                kinds.join(", ")
            ));
        }
    }
    text
}

/// The plan's line on the pulled vertex buffer.
fn vertex_buffer_line(g: &crate::back::reflect::GeometryDraw) -> String {
    let v = &g.vertex_buffer;
    let inputs = if g.inputs.is_empty() { "no inputs".to_string() } else { g.inputs.join(", ") };
    format!(
        "    vertices: storage buffer `{}` (group {}, binding {}): {} vec4<f32> per vertex ({inputs})\n",
        v.name, v.group, v.binding, v.stride
    )
}

/// How to run a folded tessellation program: one line, or with `--explain` the whole plan.
fn tessellation_plan(g: &crate::back::reflect::GeometryDraw, t: &crate::back::reflect::TessellationDraw, explain: bool) -> String {
    let per = format!("{} vertices per patch of {}", g.vertices_per_primitive, g.index_buffer.stride);
    if !explain {
        return format!(
            "  tessellation stages folded into the vertex stage: draw {per} as a {} (levels up to {}); --explain shows the plan\n",
            g.topology, t.level_cap
        );
    }
    let i = &g.index_buffer;
    let mut s = String::from("  tessellation stages folded into the vertex stage (WebGPU has no tessellation stages):\n");
    s.push_str(&format!(
        "    indices: storage buffer `{}` (group {}, binding {}): a header (2 unused words, u32 level cap, u32 tessellated vertices per patch at that cap: 3 per triangle, 2 per line), then {} u32 per patch, in draw order\n",
        i.name, i.group, i.binding, i.stride
    ));
    s.push_str(&vertex_buffer_line(g));
    s.push_str(&format!(
        "    draw: no vertex buffers, non-indexed, patches × {} vertices (× instances), topology {}, header level cap {}\n",
        g.vertices_per_primitive, g.topology, t.level_cap
    ));
    s.push_str(&format!(
        "    per patch: the {} domain's primitives at the levels the control stage writes (capped); slots past the last lie outside the clip volume; a smaller cap needs fewer vertices per patch\n",
        t.domain
    ));
    if t.geometry_slots > 0 {
        s.push_str(&format!(
            "    then the geometry stage on each generated primitive: {} vertices each ({} max_vertices = {} as a {})\n",
            t.geometry_slots, g.output_primitive, g.max_vertices, g.topology
        ));
    }
    s
}

/// How to run a folded geometry program: one line, or with `--explain` the whole plan.
fn geometry_plan(g: &crate::back::reflect::GeometryDraw, explain: bool) -> String {
    if let Some(t) = &g.tessellation {
        return tessellation_plan(g, t, explain);
    }
    let per = format!("{} vertices per input {}", g.vertices_per_primitive, g.input_primitive.trim_end_matches('s'));
    if !explain {
        return format!("  geometry stage folded into the vertex stage: draw {per} as a {}; --explain shows the plan\n", g.topology);
    }
    let i = &g.index_buffer;
    let list = match g.topology {
        "point-list" => "point",
        "line-list" => "line",
        _ => "triangle",
    };
    let per_invocation = g.vertices_per_primitive / g.invocations.max(1);
    let mut t = String::from("  geometry stage folded into the vertex stage (WebGPU has no geometry stage):\n");
    t.push_str(&format!(
        "    indices: storage buffer `{}` (group {}, binding {}): a header (i32 layer, i32 viewport to draw, -1 for all; 2 unused words), then {} u32 per input primitive ({}), in draw order\n",
        i.name, i.group, i.binding, i.stride, g.input_primitive
    ));
    t.push_str(&vertex_buffer_line(g));
    if !g.selects.is_empty() {
        let selected = g.selects.join(" and ");
        t.push_str(&format!(
            "    the geometry stage selects the {selected} of each primitive: WebGPU cannot route it, so draw once per {selected} with the header naming it\n"
        ));
    }
    t.push_str(&format!(
        "    draw: no vertex buffers, non-indexed, primitives × {} vertices (× instances), topology {}\n",
        g.vertices_per_primitive, g.topology
    ));
    t.push_str(&format!(
        "    per input primitive: {} invocation{} × {} {list} vertices ({} max_vertices = {} as {list} lists); slots not emitted lie outside the clip volume\n",
        g.invocations,
        if g.invocations == 1 { "" } else { "s" },
        per_invocation,
        g.output_primitive,
        g.max_vertices
    ));
    t
}
