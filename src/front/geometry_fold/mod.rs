//! Geometry stages folded into the vertex stage: the vertex and geometry stages' 4.50 texts
//! become one vertex-stage text that naga parses like any other (naga and WebGPU have no
//! geometry stage). The fold is a text-to-text pass before naga, so it lives in the front:
//! `check` validates the folded stage with naga and looks for hazards in it, and `translate`,
//! `render`, `stress` and `bench` receive a plain vertex + fragment program.
//!
//! The draw has [`GeometryLayout::slots_per_primitive`] vertices per input primitive. Each
//! invocation finds its primitive and the corner of the output primitive it draws from
//! `gl_VertexIndex`, pulls the primitive's vertices from two read-only storage buffers
//! ([`INDEX_BUFFER`], [`VERTEX_BUFFER`]: one `vec4` per vertex input per vertex), runs the
//! vertex stage once per corner of the input primitive, then the geometry stage, whose
//! `EmitVertex()` keeps the last three emitted vertices and captures the invocation's own.
//! Strips become lists in GL's order (odd triangles keep GL's winding); a slot no strip
//! fills lies outside the clip volume and draws nothing, so `max_vertices` holds and the
//! primitives rasterize in input order.
//!
//! Every global and function of the two stages is renamed apart (`effectc_vs_…`,
//! `effectc_gs_…`); uniforms, textures and samplers keep their names and the vertex stage's
//! declarations (the front gave both stages the same ones).
//!
//! `gl_Layer` and `gl_ViewportIndex` cannot route a primitive in WebGPU: the draw keeps the
//! primitives of the layer and viewport [`INDEX_BUFFER`]'s header names (−1: all), so a
//! layered target is drawn one layer per draw.
//!
//! The `gl_PrimitiveID` the geometry stage writes reaches a fragment stage that reads it as a
//! flat varying ([`Lowered::primitive_location`]; WebGPU has the built-in only as a feature).
//!
//! The varyings between the two stages become private variables ([`interface`]): arrays,
//! matrices and blocks (named or not) pass as GL passes them, matched by location.
//!
//! Not folded (an error naming the construct): varyings of struct type, arrays of blocks
//! other than the geometry stage's inputs, vertex inputs other than scalars and vectors,
//! `gl_Layer`/`gl_ViewportIndex`/`gl_PrimitiveID` in the vertex stage of a geometry program.

mod interface;

use std::fmt::Write as _;
use std::ops::Range;

use crate::config::TargetEnv;
use crate::diag::FileId;
use crate::front::edits::{Edits, OffsetMap};
use crate::front::geometry_layout::{GeometryLayout, OutputPrimitive};
use crate::front::naga_run::Validated;
use crate::front::syntax::{self, matrix_shape, Global, GlslType, Referent, StageSyntax, Storage};
use crate::stage::StageKind;
use interface::{next_location, private_varying, Leaf};

/// Name of the storage buffer of vertex indices (three, two or one per input primitive),
/// as the translated code names it (its block type is `EffectcIndices`).
pub const INDEX_BUFFER: &str = "effectc_indices";
/// Words before the indices in [`INDEX_BUFFER`]: the layer and the viewport a draw keeps
/// (as `i32`, −1 for all), two unused.
pub const HEADER_WORDS: u32 = 4;
/// Name of the storage buffer of vertex inputs, `vec4` per input (in location order) per
/// vertex, as the translated code names it (its block type is `EffectcVertices`).
pub const VERTEX_BUFFER: &str = "effectc_vertices";

/// Prefix of the vertex inputs of the [`Pulling::Attributes`] fold (the user's names could
/// clash with the geometry stage's globals); the input is the user's input of that name.
pub const ATTRIBUTE_PREFIX: &str = "effectc_in_";

/// Where the folded stage reads its primitives' vertices.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pulling {
    /// From [`INDEX_BUFFER`] and [`VERTEX_BUFFER`] at these bindings of group 0: the stage
    /// that is drawn.
    Storage { index_binding: u32, vertex_binding: u32 },
    /// Every corner from the vertex inputs, as declared (location and name): a stage for the
    /// static analysis, whose facts about vertex inputs are known by location and name.
    Attributes,
}

/// The lowered vertex stage and what drawing it needs.
#[derive(Debug, Clone)]
pub struct Lowered {
    /// GLSL 4.50 vertex-stage text.
    pub text: String,
    pub layout: GeometryLayout,
    pub pulling: Pulling,
    /// The vertex stage's inputs in the order of their `vec4`s in [`VERTEX_BUFFER`]:
    /// (location, name as the user wrote it, components).
    pub vertex_inputs: Vec<(u32, String, u32)>,
    /// The GLSL type of each of `vertex_inputs` (`vec3`, `uvec2`, `int`): an integer input
    /// travels as its bit pattern in the `vec4`.
    pub input_types: Vec<String>,
    /// The parts of `text` copied from the two rewritten stages, with their offset maps.
    pieces: Vec<Piece>,
    /// The flat `uint` output at this location carries the `gl_PrimitiveID` the geometry stage
    /// wrote (its input primitive's number when it wrote none) to a fragment stage that reads
    /// `gl_PrimitiveID` (WebGPU has it only as an optional feature).
    pub primitive_location: u32,
    /// The geometry stage writes `gl_Layer` / `gl_ViewportIndex`: the draw keeps only the
    /// primitives of the layer and viewport named in [`INDEX_BUFFER`]'s header.
    pub selects_layer: bool,
    pub selects_viewport: bool,
}

/// A range of the lowered text that came from one stage's rewritten text.
#[derive(Debug, Clone)]
struct Piece {
    range: Range<usize>,
    stage: StageKind,
    map: OffsetMap,
}

impl Lowered {
    /// The stage and the range of its rewritten text a range of the lowered text came from
    /// (None for the generated glue).
    pub fn locate(&self, range: Range<usize>) -> Option<(StageKind, Range<usize>)> {
        let p = self.pieces.iter().find(|p| p.range.start <= range.start && range.end <= p.range.end)?;
        Some((p.stage, p.map.range_to_original(range.start - p.range.start..range.end - p.range.start)))
    }
}

/// A folded program: the lowered text that is drawn, with its validated module, and the
/// analysis variant (vertex inputs as attributes) with its module.
#[derive(Debug)]
pub struct Folded {
    pub drawn: Lowered,
    pub naga: Validated,
    pub analysed: Lowered,
    pub analysis: Validated,
}

/// Folds `gs` (a geometry stage's 4.50 text) into `vs` (the vertex stage's). `original` is
/// the geometry stage as the user wrote it, when known: the interpolation qualifiers of its
/// output block members (the 4.50 text leaves them out, as naga ignores them there).
pub fn lower(vs: &str, gs: &str, layout: GeometryLayout, pulling: Pulling, original: Option<&StageSyntax>) -> Result<Lowered, String> {
    let v = syntax::analyse(FileId(0), vs, StageKind::Vertex, TargetEnv::Auto)
        .map_err(|_| "the rewritten vertex stage does not parse".to_string())?;
    let g = syntax::analyse(FileId(0), gs, StageKind::Geometry, TargetEnv::Auto)
        .map_err(|_| "the rewritten geometry stage does not parse".to_string())?;
    let corners = layout.input.vertices();
    let mut text = String::from("#version 450\n");
    let vs_part = Part::new(&v, "effectc_vs_", None, None)?;
    let shared: Vec<&str> = v.globals.iter().filter(|x| is_shared(x)).map(|x| x.name.as_str()).collect();
    let gs_part = Part::new(&g, "effectc_gs_", Some((&shared, corners)), original)?;
    let vertex_inputs: Vec<(u32, String, u32)> = vs_part.inputs.iter().map(|(l, n, c, _)| (*l, n.clone(), *c)).collect();
    let input_types: Vec<String> = vs_part.inputs.iter().map(|(_, _, _, t)| t.clone()).collect();
    match pulling {
        Pulling::Storage { index_binding, vertex_binding } => {
            writeln!(
                text,
                "layout(std430, set = 0, binding = {index_binding}) readonly buffer EffectcIndices {{ uint index[]; }} {INDEX_BUFFER};"
            )
            .unwrap();
            writeln!(
                text,
                "layout(std430, set = 0, binding = {vertex_binding}) readonly buffer EffectcVertices {{ vec4 vertex[]; }} {VERTEX_BUFFER};"
            )
            .unwrap();
        }
        Pulling::Attributes => {
            for ((location, name, _), ty) in vertex_inputs.iter().zip(&input_types) {
                writeln!(text, "layout(location = {location}) in {ty} {ATTRIBUTE_PREFIX}{name};").unwrap();
            }
        }
    }
    // `gl_ClipDistance[]` only where read: it is 8 × 16 bytes of private memory per corner.
    let clip = if gs_part.reads_clip_distance { " float gl_ClipDistance[8];" } else { "" };
    writeln!(text, "struct effectc_PerVertex {{ vec4 gl_Position; float gl_PointSize;{clip} }};").unwrap();
    writeln!(text, "effectc_PerVertex effectc_gl_in[{corners}];").unwrap();
    text.push_str(
        "vec4 effectc_vs_gl_Position; float effectc_vs_gl_PointSize; vec4 effectc_gs_gl_Position; float effectc_gs_gl_PointSize;\n",
    );
    text.push_str("int effectc_PrimitiveIDIn; int effectc_InvocationID; int effectc_VertexID; int effectc_InstanceID;\n");
    text.push_str("int effectc_gs_gl_Layer; int effectc_gs_gl_ViewportIndex; int effectc_gs_gl_PrimitiveID;\n");
    text.push_str(&vs_part.declarations);
    text.push_str(&gs_part.declarations);
    let mut pieces = Vec::new();
    let mut append = |text: &mut String, part: &Part, stage: StageKind| {
        let start = text.len();
        text.push_str(&part.body);
        pieces.push(Piece { range: start..text.len(), stage, map: part.map.clone() });
        text.push('\n');
    };
    append(&mut text, &vs_part, StageKind::Vertex);
    text.push_str(&capture(&gs_part, layout.output));
    append(&mut text, &gs_part, StageKind::Geometry);
    text.push_str(&driver(&vs_part, &gs_part, layout, pulling)?);
    let (selects_layer, selects_viewport) = (gs_part.selects.contains("gl_Layer"), gs_part.selects.contains("gl_ViewportIndex"));
    let primitive_location = next_location(&gs_part.outputs);
    Ok(Lowered { text, layout, pulling, vertex_inputs, input_types, pieces, primitive_location, selects_layer, selects_viewport })
}

/// One stage's text with its interface made private and its names prefixed.
struct Part {
    prefix: &'static str,
    /// Private declarations of the interface (and struct types for its blocks).
    declarations: String,
    /// The stage's text after the edits (without `#version`), and its map back.
    body: String,
    map: OffsetMap,
    /// Vertex stage: its inputs (location, user name, components, GLSL type).
    inputs: Vec<(u32, String, u32, String)>,
    /// Its outputs, made private.
    outputs: Vec<Leaf>,
    /// Geometry stage: its inputs, made private (arrays over the corners).
    ins: Vec<Leaf>,
    /// Geometry stage: which of `gl_Layer` and `gl_ViewportIndex` it uses.
    selects: std::collections::BTreeSet<String>,
    /// The built-in outputs the rewrite made private globals ([`PRIVATE_BUILTINS`]) that the
    /// stage declares, with their array length (a redeclared `gl_ClipDistance[3]` has 3).
    private_builtins: Vec<(&'static str, Option<u32>)>,
    /// Geometry stage: it reads `gl_in[].gl_ClipDistance`.
    reads_clip_distance: bool,
}

/// Built-in outputs WebGPU lacks that the rewrite computes in a private float global (the
/// global's name, the `gl_in[]` member it feeds, its array length).
const PRIVATE_BUILTINS: [(&str, &str, Option<u32>); 2] =
    [("effectc_PointSize", "gl_PointSize", None), ("effectc_ClipDistance", "gl_ClipDistance", Some(8))];

impl Part {
    /// `geometry`: the vertex stage's shared declarations (dropped here) and `gl_in`'s length.
    fn new(
        s: &StageSyntax,
        prefix: &'static str,
        geometry: Option<(&[&str], u32)>,
        original: Option<&StageSyntax>,
    ) -> Result<Part, String> {
        let text = &s.text;
        let mut edits = Edits::new();
        let mut part = Part {
            prefix,
            declarations: String::new(),
            body: String::new(),
            map: OffsetMap::default(),
            selects: Default::default(),
            inputs: Vec::new(),
            outputs: Vec::new(),
            ins: Vec::new(),
            private_builtins: Vec::new(),
            reads_clip_distance: geometry.is_some()
                && s.uses.iter().any(|u| u.name == "gl_in" && u.field.as_ref().is_some_and(|(f, _)| f == "gl_ClipDistance")),
        };
        if let Some(start) = text.find("#version") {
            let end = text[start..].find('\n').map_or(text.len(), |e| start + e);
            edits.delete(start..end);
        }
        for d in &s.defaults {
            if geometry.is_some() && matches!(d.storage, Some(Storage::In | Storage::Out)) {
                edits.delete(d.span.clone());
            }
        }
        // Geometry inputs whose corners hold arrays or matrices: user name → (private
        // name, type at one corner); read at a run-time corner through an accessor.
        let mut accessed: std::collections::BTreeMap<String, (String, String)> = Default::default();
        if part.reads_clip_distance {
            accessed.insert("gl_in".into(), ("effectc_gl_in".into(), "effectc_PerVertex".into()));
        }
        let mut deleted: Vec<Range<usize>> = Vec::new();
        let mut delete = |edits: &mut Edits, span: &Range<usize>| {
            if !deleted.iter().any(|d| d.start < span.end && span.start < d.end) {
                edits.delete(span.clone());
                deleted.push(span.clone());
            }
        };
        for g in &s.globals {
            let renamed = format!("{prefix}{}", g.name);
            if let Some((name, _, _)) = PRIVATE_BUILTINS.iter().find(|(n, _, _)| *n == g.name) {
                part.private_builtins.push((name, g.ty.dims.first().copied().flatten()));
            }
            match g.storage {
                _ if is_shared(g) => {
                    if geometry.is_some_and(|(shared, _)| shared.contains(&g.name.as_str())) {
                        delete(&mut edits, &g.decl_span);
                    }
                    continue;
                }
                Storage::In | Storage::Attribute if geometry.is_none() => {
                    let components = components(&g.ty).ok_or_else(|| format!("vertex input `{}` of type `{}`", g.name, g.ty.base))?;
                    part.inputs.push((g.location.unwrap_or(u32::MAX), g.name.clone(), components, g.ty.base.clone()));
                    writeln!(part.declarations, "{} {renamed};", g.ty.base).unwrap();
                    delete(&mut edits, &g.decl_span);
                }
                Storage::In | Storage::Out | Storage::Varying => {
                    let as_written = original.and_then(|o| o.globals.iter().find(|x| x.name == g.name && x.storage == g.storage));
                    let leaves = private_varying(g, s, as_written, &renamed, geometry.map(|(_, n)| n), &mut part.declarations)?;
                    if g.storage == Storage::Out || (g.storage == Storage::Varying && geometry.is_none()) {
                        part.outputs.extend(leaves);
                    } else {
                        if let Some(nested) = geometry.and_then(|_| nested_corner(g, prefix)) {
                            accessed.insert(nested.0, (nested.1, nested.2));
                        }
                        part.ins.extend(leaves);
                    }
                    delete(&mut edits, &g.decl_span);
                }
                _ => edits.replace(g.name_span.clone(), renamed),
            }
        }
        part.inputs.sort_by_key(|(location, _, _, _)| *location);
        part.rename_uses(s, &accessed, geometry.is_some(), &mut edits)?;
        let user_functions: Vec<&str> = s.functions.iter().map(|f| f.name.as_str()).collect();
        for f in s.functions.iter().filter(|f| f.is_definition || f.name != "main") {
            let name_at = find_name(text, &f.span, &f.name).ok_or_else(|| format!("the definition of `{}`", f.name))?;
            edits.replace(name_at..name_at + f.name.len(), format!("{prefix}{}", f.name));
        }
        for c in &s.calls {
            match c.name.as_str() {
                "EmitVertex" if geometry.is_some() => edits.replace(c.span.clone(), "effectc_emit()"),
                "EndPrimitive" if geometry.is_some() => edits.replace(c.span.clone(), "effectc_end_primitive()"),
                name if user_functions.contains(&name) => edits.replace(c.name_span.clone(), format!("{prefix}{name}")),
                _ => {}
            }
        }
        if let Some((_, corners)) = geometry {
            for (private, ty) in accessed.values() {
                part.declarations.push_str(&corner_accessor(private, ty, corners));
            }
        }
        (part.body, part.map, _) = edits.apply(text);
        Ok(part)
    }

    /// Renames the stage's uses of its globals and of the built-ins the fold replaces;
    /// geometry inputs in `accessed` read at a run-time corner go through their accessor.
    fn rename_uses(
        &mut self,
        s: &StageSyntax,
        accessed: &std::collections::BTreeMap<String, (String, String)>,
        geometry: bool,
        edits: &mut Edits,
    ) -> Result<(), String> {
        let stage_word = if geometry { "gs" } else { "vs" };
        for u in &s.uses {
            if let Some((private, _)) = accessed.get(&u.name).filter(|_| matches!(u.target, Referent::Global(_)) || u.name == "gl_in") {
                if let Some(call) = corner_call(&s.text, u) {
                    edits.replace(u.span.clone(), format!("{private}_at"));
                    edits.replace(call.0, "(int(");
                    edits.replace(call.1, "))");
                    continue;
                }
            }
            match &u.target {
                Referent::Global(i) if !is_shared(&s.globals[*i]) => edits.replace(u.span.clone(), format!("{}{}", self.prefix, u.name)),
                Referent::Unresolved => match u.name.as_str() {
                    "gl_Position" | "gl_PointSize" => edits.replace(u.span.clone(), format!("effectc_{stage_word}_{}", u.name)),
                    "gl_in" => edits.replace(u.span.clone(), "effectc_gl_in"),
                    "gl_PrimitiveIDIn" | "gl_InvocationID" => edits.replace(u.span.clone(), format!("effectc_{}", &u.name[3..])),
                    "gl_VertexID" | "gl_VertexIndex" => edits.replace(u.span.clone(), "effectc_VertexID"),
                    "gl_InstanceID" | "gl_InstanceIndex" => edits.replace(u.span.clone(), "effectc_InstanceID"),
                    "gl_Layer" | "gl_ViewportIndex" if geometry => {
                        self.selects.insert(u.name.clone());
                        edits.replace(u.span.clone(), format!("effectc_gs_{}", u.name))
                    }
                    "gl_PrimitiveID" if geometry => edits.replace(u.span.clone(), "effectc_gs_gl_PrimitiveID"),
                    "gl_Layer" | "gl_ViewportIndex" | "gl_PrimitiveID" => {
                        return Err(format!("`{}` in the vertex stage of a geometry program", u.name))
                    }
                    _ => {}
                },
                _ => {}
            }
        }
        Ok(())
    }
}

/// A geometry input whose corners hold arrays or matrices (a block with such members, or
/// an array of arrays): the name its uses give, its private name and its type at one corner
/// as a GLSL return type ([`interface::private_varying`]'s names). None for the others.
/// Indexing such an input at a run-time corner and then inside the corner makes llvmpipe's
/// code generator (lavapipe) take minutes; the accessor ([`corner_accessor`]) picks the
/// corner by branches instead.
fn nested_corner(g: &Global, prefix: &str) -> Option<(String, String, String)> {
    let nested = |ty: &GlslType| !ty.dims.is_empty() || matrix_shape(&ty.base).is_some();
    match &g.block {
        Some(b) => {
            let instance = b.instance.as_ref()?;
            let private = format!("{prefix}{instance}");
            let ty = format!("{private}_block");
            b.members.iter().any(|m| nested(&m.ty)).then(|| (instance.clone(), private, ty))
        }
        None => {
            let ty = g.ty.element();
            nested(&ty).then(|| (g.name.clone(), format!("{prefix}{}", g.name), format!("{}{}", ty.base, syntax::dims_text(&ty))))
        }
    }
}

/// `T name_at(int k)`: corner `k` of a geometry input (the last corner past the end, where
/// GL's read is undefined).
fn corner_accessor(private: &str, ty: &str, corners: u32) -> String {
    let mut t = format!("{ty} {private}_at(int k) {{");
    for k in 0..corners.saturating_sub(1) {
        write!(t, " if (k == {k}) return {private}[{k}];").unwrap();
    }
    writeln!(t, " return {private}[{}]; }}", corners.saturating_sub(1)).unwrap();
    t
}

/// Where `u` (a geometry input) is indexed at a corner that is not a literal: the ranges of
/// the opening (`[` and what precedes the index) and the closing `]`.
fn corner_call(text: &str, u: &syntax::Use) -> Option<(Range<usize>, Range<usize>)> {
    let (whole, index, literal) = u.index.clone()?;
    let closes = whole.end > index.end && text.get(whole.end - 1..whole.end) == Some("]");
    let opens = text.get(u.span.end..index.start).is_some_and(|t| t.trim() == "[");
    (literal.is_none() && closes && opens).then_some((u.span.end..index.start, index.end..whole.end))
}

/// Uniforms, textures and samplers: shared by the stages, kept under their names.
fn is_shared(g: &Global) -> bool {
    matches!(g.storage, Storage::Uniform | Storage::Buffer)
}

/// Components of a float or integer vector (`float`, `int`, `uint` 1 … `vec4`, `ivec4`,
/// `uvec4` 4).
fn components(ty: &GlslType) -> Option<u32> {
    ty.vector_components().filter(|_| !ty.is_array())
}

/// Where `name` is written in the definition at `span`: the first `name` followed by `(`.
fn find_name(text: &str, span: &Range<usize>, name: &str) -> Option<usize> {
    let body = &text[span.clone()];
    let mut from = 0;
    while let Some(i) = body[from..].find(name) {
        let at = from + i;
        let before_ok = at == 0 || !body.as_bytes()[at - 1].is_ascii_alphanumeric() && body.as_bytes()[at - 1] != b'_';
        let after = body[at + name.len()..].trim_start();
        if before_ok && after.starts_with('(') {
            return Some(span.start + at);
        }
        from = at + name.len();
    }
    None
}

/// `effectc_emit()` and `effectc_end_primitive()`: the capture of the vertex this invocation
/// draws, without keeping the strip (no arrays indexed at run time, which a GPU compiler
/// keeps in memory): the wanted list primitive is the `f`-th of the strip that started when
/// `effectc_made` primitives were complete, and its corner is the strip's vertex `f + k`
/// (corners 0 and 1 swapped for odd triangles, GL's winding; each primitive begun at its
/// last vertex, GL's provoking vertex). The vertex is held when
/// emitted and kept when the primitive completes; a strip ended earlier drops it.
fn capture(gs: &Part, output: OutputPrimitive) -> String {
    let mut t = String::new();
    t.push_str("uint effectc_want_primitive; uint effectc_want_corner; bool effectc_found; bool effectc_held;\n");
    t.push_str("uint effectc_strip; uint effectc_made; uint effectc_strip_start;\n");
    t.push_str("vec4 effectc_cap_Position; int effectc_cap_Layer; int effectc_cap_ViewportIndex; int effectc_cap_PrimitiveID;\n");
    for (i, o) in gs.outputs.iter().enumerate() {
        writeln!(t, "{} effectc_cap_{i}{};", o.ty.base, syntax::dims_text(&o.ty)).unwrap();
    }
    let n = output.list_vertices();
    t.push_str("void effectc_emit() {\n    if (effectc_found) {\n        return;\n    }\n");
    t.push_str("    if (effectc_want_primitive >= effectc_strip_start) {\n");
    t.push_str("        uint f = effectc_want_primitive - effectc_strip_start;\n        uint k = effectc_want_corner;\n");
    // The list primitive starts at GL's provoking vertex, the strip's last of it (WebGPU
    // takes `flat` values from the first): (a, b, c) drawn as (c, a, b), (a, b) as (b, a).
    match output {
        OutputPrimitive::TriangleStrip => {
            t.push_str("        k = (k + 2u) % 3u;\n");
            t.push_str("        if ((f & 1u) == 1u && k < 2u) {\n            k = 1u - k;\n        }\n");
        }
        OutputPrimitive::LineStrip => t.push_str("        k = 1u - k;\n"),
        _ => {}
    }
    t.push_str("        if (effectc_strip == f + k) {\n            effectc_cap_Position = effectc_gs_gl_Position;\n");
    t.push_str(
        "            effectc_cap_Layer = effectc_gs_gl_Layer;\n            effectc_cap_ViewportIndex = effectc_gs_gl_ViewportIndex;\n            effectc_cap_PrimitiveID = effectc_gs_gl_PrimitiveID;\n",
    );
    for (i, o) in gs.outputs.iter().enumerate() {
        writeln!(t, "           {}", o.ty.copy(&format!("effectc_cap_{i}"), &o.access(None))).unwrap();
    }
    t.push_str("            effectc_held = true;\n        }\n    }\n");
    writeln!(t, "    effectc_strip += 1u;\n    if (effectc_strip >= {n}u) {{\n        effectc_made += 1u;\n    }}").unwrap();
    t.push_str("    effectc_found = effectc_held && effectc_made > effectc_want_primitive;\n}\n");
    t.push_str(
        "void effectc_end_primitive() {\n    effectc_strip = 0u;\n    effectc_strip_start = effectc_made;\n    effectc_held = false;\n}\n",
    );
    t
}

/// The real outputs (the geometry stage's, flattened at their locations) and `main`.
fn driver(vs: &Part, gs: &Part, layout: GeometryLayout, pulling: Pulling) -> Result<String, String> {
    let mut t = String::new();
    let mut assign = String::new();
    for (i, o) in gs.outputs.iter().enumerate() {
        // naga wants integer outputs `flat` (GL never interpolates them).
        let interp = if o.interp.is_empty() && o.ty.is_integer() { "flat" } else { o.interp.as_str() };
        for (location, ty, part) in o.locations() {
            writeln!(t, "layout(location = {location}) {interp} out {ty} effectc_out_{location};").unwrap();
            writeln!(assign, "        effectc_out_{location} = effectc_cap_{i}{part};").unwrap();
        }
    }
    writeln!(t, "layout(location = {}) flat out uint effectc_out_primitive;", next_location(&gs.outputs)).unwrap();
    writeln!(assign, "        effectc_out_primitive = uint(effectc_cap_PrimitiveID);").unwrap();
    let corners = layout.input.vertices();
    let per_invocation = layout.output.max_primitives(layout.max_vertices) * layout.output.list_vertices();
    let per_primitive = layout.slots_per_primitive();
    writeln!(t, "void main() {{\n    uint v = uint(gl_VertexIndex);\n    uint primitive = v / {per_primitive}u;").unwrap();
    writeln!(t, "    uint slot = v % {per_primitive}u;\n    effectc_InvocationID = int(slot / {per_invocation}u);").unwrap();
    writeln!(
        t,
        "    effectc_want_primitive = (slot % {per_invocation}u) / {0}u;\n    effectc_want_corner = slot % {0}u;",
        layout.output.list_vertices()
    )
    .unwrap();
    t.push_str("    effectc_found = false; effectc_held = false; effectc_strip = 0u; effectc_made = 0u; effectc_strip_start = 0u;\n");
    t.push_str("    effectc_gs_gl_Layer = 0; effectc_gs_gl_ViewportIndex = 0;\n");
    t.push_str("    effectc_PrimitiveIDIn = int(primitive); effectc_InstanceID = int(gl_InstanceIndex);\n");
    t.push_str("    effectc_gs_gl_PrimitiveID = effectc_PrimitiveIDIn;\n");
    let stride = vs.inputs.len();
    // One block per corner with constant indices (no loop): the arrays stay in registers.
    for k in 0..corners {
        match pulling {
            Pulling::Storage { .. } => {
                writeln!(
                    t,
                    "    uint index{k} = {INDEX_BUFFER}.index[{HEADER_WORDS}u + primitive * {corners}u + {k}u];\n    effectc_VertexID = int(index{k});"
                )
                .unwrap();
                for (i, (_, name, components, ty)) in vs.inputs.iter().enumerate() {
                    let swizzle = ["x", "xy", "xyz", "xyzw"][*components as usize - 1];
                    // Integers travel as their bit patterns.
                    let bits = match ty.chars().next() {
                        Some('i') => "floatBitsToInt",
                        Some('u') => "floatBitsToUint",
                        _ => "",
                    };
                    writeln!(t, "    {}{name} = {bits}({VERTEX_BUFFER}.vertex[index{k} * {stride}u + {i}u]).{swizzle};", vs.prefix)
                        .unwrap();
                }
            }
            Pulling::Attributes => {
                t.push_str("    effectc_VertexID = int(gl_VertexIndex);\n");
                for (_, name, _, _) in &vs.inputs {
                    writeln!(t, "    {}{name} = {ATTRIBUTE_PREFIX}{name};", vs.prefix).unwrap();
                }
            }
        }
        writeln!(t, "    {}main();", vs.prefix).unwrap();
        writeln!(t, "    effectc_gl_in[{k}].gl_Position = effectc_vs_gl_Position;").unwrap();
        for (private, member, length) in PRIVATE_BUILTINS {
            let Some((_, declared)) = vs.private_builtins.iter().find(|(p, _)| *p == private) else { continue };
            if member != "gl_ClipDistance" || gs.reads_clip_distance {
                // gl_in[]'s array is the largest; the vertex stage's may be shorter.
                let length = length.map(|l| declared.map_or(l, |d| d.min(l)));
                let ty = GlslType { base: "float".into(), dims: length.into_iter().map(Some).collect() };
                writeln!(t, "   {}", ty.copy(&format!("effectc_gl_in[{k}].{member}"), &format!("{}{private}", vs.prefix))).unwrap();
            }
        }
        for i in &gs.ins {
            // An input no vertex output feeds is undefined in GL: it stays zero here.
            let Some(statements) = interface::feed(i, k, &vs.outputs) else { continue };
            writeln!(t, "   {statements}").unwrap();
        }
    }
    writeln!(t, "    {}main();", gs.prefix).unwrap();
    // The layer and viewport the draw keeps (−1: every one), from the index buffer's header.
    // The header is the buffer's first words (naga cannot load a member beside a
    // runtime-sized array).
    let mut keep = String::from("effectc_found");
    if let Pulling::Storage { .. } = pulling {
        for (word, (written, field, cap)) in
            [("gl_Layer", "layer", "Layer"), ("gl_ViewportIndex", "viewport", "ViewportIndex")].into_iter().enumerate()
        {
            if gs.selects.contains(written) {
                writeln!(t, "    int effectc_keep_{field} = int({INDEX_BUFFER}.index[{word}u]);").unwrap();
                write!(keep, " && (effectc_keep_{field} < 0 || effectc_cap_{cap} == effectc_keep_{field})").unwrap();
            }
        }
    }
    writeln!(t, "    if ({keep}) {{\n        gl_Position = effectc_cap_Position;").unwrap();
    t.push_str(&assign);
    t.push_str("    } else {\n        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);\n    }\n}\n");
    Ok(t)
}
