//! One stage of a folded program: its rewritten 4.50 text with its interface made private
//! globals and its names prefixed, so several stages live in one vertex-stage text. The
//! [`Role`] says which stage it plays: how its varyings are arrayed (a geometry or
//! tessellation stage's inputs per corner, a tessellation control stage's outputs per
//! output vertex) and which built-ins the fold supplies.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::ops::Range;

use crate::front::edits::{Edits, OffsetMap};
use crate::front::syntax::{self, matrix_shape, Global, GlslType, Referent, StageSyntax, Storage};

use super::interface::{private_varying, Leaf};

/// The stage a [`Part`] plays in a fold. `shared`: the vertex stage's uniforms, textures
/// and buffers, declared once (dropped from the later stages).
#[derive(Debug, Clone, Copy)]
pub(crate) enum Role<'a> {
    Vertex,
    /// Inputs are arrays over the `corners` of the input primitive.
    Geometry {
        shared: &'a [&'a str],
        corners: u32,
    },
    /// Inputs over the patch's `corners`, per-vertex outputs over the `vertices` it makes.
    TessControl {
        shared: &'a [&'a str],
        corners: u32,
        vertices: u32,
    },
    /// Inputs over the patch's `corners` (the control stage's output vertices).
    TessEval {
        shared: &'a [&'a str],
        corners: u32,
    },
}

impl Role<'_> {
    fn shared(&self) -> Option<&[&str]> {
        match self {
            Role::Vertex => None,
            Role::Geometry { shared, .. } | Role::TessControl { shared, .. } | Role::TessEval { shared, .. } => Some(shared),
        }
    }
    fn is_vertex(&self) -> bool {
        matches!(self, Role::Vertex)
    }
    /// The length of the per-vertex input arrays (None in the vertex stage).
    fn in_corners(&self) -> Option<u32> {
        match self {
            Role::Vertex => None,
            Role::Geometry { corners, .. } | Role::TessControl { corners, .. } | Role::TessEval { corners, .. } => Some(*corners),
        }
    }
    /// The length of the per-vertex output arrays (a tessellation control stage's).
    fn out_corners(&self) -> Option<u32> {
        match self {
            Role::TessControl { vertices, .. } => Some(*vertices),
            _ => None,
        }
    }
    /// The private array that stands for `gl_in`.
    pub(crate) fn gl_in(&self) -> &'static str {
        match self {
            Role::TessControl { .. } => "effectc_tc_gl_in",
            Role::TessEval { .. } => "effectc_te_gl_in",
            _ => "effectc_gl_in",
        }
    }
    /// What a built-in the stage uses becomes (None: kept), or why the fold cannot take it.
    fn builtin(&self, name: &str, selects: &mut std::collections::BTreeSet<String>) -> Option<Result<String, String>> {
        let renamed = |s: &str| Some(Ok(s.to_string()));
        match (self, name) {
            (_, "gl_in") if !self.is_vertex() => renamed(self.gl_in()),
            (_, "gl_VertexID" | "gl_VertexIndex") => renamed("effectc_VertexID"),
            (_, "gl_InstanceID" | "gl_InstanceIndex") => renamed("effectc_InstanceID"),
            (Role::Vertex, "gl_Position" | "gl_PointSize") => Some(Ok(format!("effectc_vs_{name}"))),
            (Role::Vertex, "gl_Layer" | "gl_ViewportIndex" | "gl_PrimitiveID") => {
                Some(Err(format!("`{name}` in the vertex stage of a geometry or tessellation program")))
            }
            (Role::Geometry { .. }, "gl_Position" | "gl_PointSize" | "gl_PrimitiveID") => Some(Ok(format!("effectc_gs_{name}"))),
            (Role::Geometry { .. }, "gl_PrimitiveIDIn" | "gl_InvocationID") => Some(Ok(format!("effectc_{}", &name[3..]))),
            (Role::Geometry { .. }, "gl_Layer" | "gl_ViewportIndex") => {
                selects.insert(name.to_string());
                Some(Ok(format!("effectc_gs_{name}")))
            }
            (Role::TessControl { .. }, "gl_out") => renamed("effectc_gl_out"),
            (Role::TessControl { .. }, "gl_InvocationID") => renamed("effectc_tc_InvocationID"),
            (Role::TessControl { .. }, "gl_PatchVerticesIn") => renamed("effectc_tc_PatchVerticesIn"),
            (Role::TessEval { .. }, "gl_PatchVerticesIn") => renamed("effectc_te_PatchVerticesIn"),
            (Role::TessEval { .. }, "gl_Position" | "gl_PointSize") => Some(Ok(format!("effectc_te_{name}"))),
            (Role::TessEval { .. }, "gl_TessCoord") => renamed("effectc_TessCoord"),
            (Role::TessControl { .. } | Role::TessEval { .. }, "gl_TessLevelOuter" | "gl_TessLevelInner" | "gl_PrimitiveID") => {
                Some(Ok(format!("effectc_{}", &name[3..])))
            }
            _ => None,
        }
    }
}

/// One stage's text with its interface made private and its names prefixed.
pub(crate) struct Part {
    pub prefix: &'static str,
    /// Private declarations of the interface (and struct types for its blocks).
    pub declarations: String,
    /// The stage's text after the edits (without `#version`), and its map back.
    pub body: String,
    pub map: OffsetMap,
    /// Vertex stage: its inputs (location, user name, components, GLSL type).
    pub inputs: Vec<(u32, String, u32, String)>,
    /// Its outputs, made private.
    pub outputs: Vec<Leaf>,
    /// Geometry and tessellation stages: their per-vertex inputs, made private (arrays
    /// over the corners).
    pub ins: Vec<Leaf>,
    /// Tessellation stages: their `patch` inputs and outputs, made private.
    pub patch_ins: Vec<Leaf>,
    pub patch_outs: Vec<Leaf>,
    /// Geometry stage: which of `gl_Layer` and `gl_ViewportIndex` it uses.
    pub selects: std::collections::BTreeSet<String>,
    /// The built-in outputs the rewrite made private globals ([`PRIVATE_BUILTINS`]) that the
    /// stage declares, with their array length (a redeclared `gl_ClipDistance[3]` has 3).
    pub private_builtins: Vec<(&'static str, Option<u32>)>,
    /// Geometry stage: it reads `gl_in[].gl_ClipDistance`.
    pub reads_clip_distance: bool,
}

/// Built-in outputs WebGPU lacks that the rewrite computes in a private float global (the
/// global's name, the `gl_in[]` member it feeds, its array length).
pub(crate) const PRIVATE_BUILTINS: [(&str, &str, Option<u32>); 2] =
    [("effectc_PointSize", "gl_PointSize", None), ("effectc_ClipDistance", "gl_ClipDistance", Some(8))];

impl Part {
    /// The vertex stage's inputs in pulling order: (location, name, components), and their
    /// GLSL types.
    pub(crate) fn pulled_inputs(&self) -> (Vec<(u32, String, u32)>, Vec<String>) {
        (self.inputs.iter().map(|(l, n, c, _)| (*l, n.clone(), *c)).collect(), self.inputs.iter().map(|(_, _, _, t)| t.clone()).collect())
    }

    /// `original`: the stage as the user wrote it, when known (the interpolation qualifiers
    /// of its output block members, which the 4.50 text leaves out).
    pub(crate) fn new(s: &StageSyntax, prefix: &'static str, role: Role, original: Option<&StageSyntax>) -> Result<Part, String> {
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
            patch_ins: Vec::new(),
            patch_outs: Vec::new(),
            private_builtins: Vec::new(),
            reads_clip_distance: !role.is_vertex()
                && s.uses.iter().any(|u| u.name == "gl_in" && u.field.as_ref().is_some_and(|(f, _)| f == "gl_ClipDistance")),
        };
        if let Some(start) = text.find("#version") {
            let end = text[start..].find('\n').map_or(text.len(), |e| start + e);
            edits.delete(start..end);
        }
        for d in &s.defaults {
            if !role.is_vertex() && matches!(d.storage, Some(Storage::In | Storage::Out)) {
                edits.delete(d.span.clone());
            }
        }
        // Geometry inputs whose corners hold arrays or matrices: user name → (private
        // name, type at one corner); read at a run-time corner through an accessor.
        let mut accessed: BTreeMap<String, (String, String)> = Default::default();
        if part.reads_clip_distance {
            accessed.insert("gl_in".into(), (role.gl_in().into(), "effectc_PerVertex".into()));
        }
        let mut deleted = part.hoist_structs(s, role, &mut edits);
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
                    if role.shared().is_some_and(|shared| shared.contains(&g.name.as_str())) {
                        delete(&mut edits, &g.decl_span);
                    }
                    continue;
                }
                Storage::In | Storage::Attribute if role.is_vertex() => {
                    part.pull_input(g, &renamed)?;
                    delete(&mut edits, &g.decl_span);
                }
                Storage::In | Storage::Out | Storage::Varying => {
                    let as_written = original.and_then(|o| o.globals.iter().find(|x| x.name == g.name && x.storage == g.storage));
                    let patch = is_patch(text, g);
                    let output = g.storage == Storage::Out || (g.storage == Storage::Varying && role.is_vertex());
                    let corners = match (patch, output) {
                        (true, _) => None,
                        (false, true) => role.out_corners(),
                        (false, false) => role.in_corners(),
                    };
                    let leaves = private_varying(g, s, as_written, &renamed, corners, &mut part.declarations)?;
                    match (patch, output) {
                        (true, true) => part.patch_outs.extend(leaves),
                        (true, false) => part.patch_ins.extend(leaves),
                        (false, true) => part.outputs.extend(leaves),
                        (false, false) => {
                            if let Some(nested) = role.in_corners().and_then(|_| nested_corner(g, prefix)) {
                                accessed.insert(nested.0, (nested.1, nested.2));
                            }
                            part.ins.extend(leaves);
                        }
                    }
                    delete(&mut edits, &g.decl_span);
                }
                _ => edits.replace(g.name_span.clone(), renamed),
            }
        }
        part.inputs.sort_by_key(|(location, _, _, _)| *location);
        part.rename_uses(s, &accessed, role, &mut edits)?;
        let user_functions: Vec<&str> = s.functions.iter().map(|f| f.name.as_str()).collect();
        for f in s.functions.iter().filter(|f| f.is_definition || f.name != "main") {
            let name_at = find_name(text, &f.span, &f.name).ok_or_else(|| format!("the definition of `{}`", f.name))?;
            edits.replace(name_at..name_at + f.name.len(), format!("{prefix}{}", f.name));
        }
        for c in &s.calls {
            match c.name.as_str() {
                "EmitVertex" if matches!(role, Role::Geometry { .. }) => edits.replace(c.span.clone(), "effectc_emit()"),
                "EndPrimitive" if matches!(role, Role::Geometry { .. }) => edits.replace(c.span.clone(), "effectc_end_primitive()"),
                name if user_functions.contains(&name) => edits.replace(c.name_span.clone(), format!("{prefix}{name}")),
                _ => {}
            }
        }
        if let Some(corners) = role.in_corners() {
            for (private, ty) in accessed.values() {
                part.declarations.push_str(&corner_accessor(private, ty, corners));
            }
        }
        (part.body, part.map, _) = edits.apply(text);
        Ok(part)
    }

    /// A vertex input the fold pulls instead: a private global, and its pulled inputs (one
    /// per element of an array input, at consecutive locations).
    fn pull_input(&mut self, g: &Global, renamed: &str) -> Result<(), String> {
        let unreadable = || format!("vertex input `{}` of type `{}`", g.name, g.ty);
        let location = g.location.unwrap_or(u32::MAX);
        match g.ty.dims.as_slice() {
            [] => {
                let components = components(&g.ty).ok_or_else(unreadable)?;
                self.inputs.push((location, g.name.clone(), components, g.ty.base.clone()));
            }
            [Some(n)] => {
                let components = components(&g.ty.element()).ok_or_else(unreadable)?;
                for i in 0..*n {
                    self.inputs.push((location.saturating_add(i), format!("{}[{i}]", g.name), components, g.ty.base.clone()));
                }
            }
            _ => return Err(unreadable()),
        }
        writeln!(self.declarations, "{} {renamed}{};", g.ty.base, syntax::dims_text(&g.ty)).unwrap();
        Ok(())
    }

    /// Moves the stage's struct definitions up to its declarations (a varying of struct
    /// type is declared there), or drops those an earlier stage defined; returns the spans
    /// deleted.
    fn hoist_structs(&mut self, s: &StageSyntax, role: Role, edits: &mut Edits) -> Vec<Range<usize>> {
        let mut deleted = Vec::new();
        for d in &s.structs {
            // The definition with its closing `;`.
            let rest = &s.text[d.span.end..];
            let span = match rest.find(';').filter(|i| rest[..*i].trim().is_empty()) {
                Some(i) => d.span.start..d.span.end + i + 1,
                None => d.span.clone(),
            };
            if !role.shared().is_some_and(|shared| shared.contains(&d.name.as_str())) {
                let definition = &s.text[span.clone()];
                writeln!(self.declarations, "{definition}{}", if definition.ends_with(';') { "" } else { ";" }).unwrap();
            }
            edits.delete(span.clone());
            deleted.push(span);
        }
        deleted
    }

    /// Renames the stage's uses of its globals and of the built-ins the fold replaces;
    /// inputs in `accessed` read at a run-time corner go through their accessor.
    fn rename_uses(
        &mut self,
        s: &StageSyntax,
        accessed: &BTreeMap<String, (String, String)>,
        role: Role,
        edits: &mut Edits,
    ) -> Result<(), String> {
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
                Referent::Unresolved => match role.builtin(&u.name, &mut self.selects) {
                    Some(Ok(name)) => edits.replace(u.span.clone(), name),
                    Some(Err(why)) => return Err(why),
                    None => {}
                },
                _ => {}
            }
        }
        Ok(())
    }
}

/// Names a later stage takes from an earlier one instead of declaring them again:
/// uniforms, buffers, textures and samplers, and struct types.
pub(crate) fn shared_names(s: &StageSyntax) -> Vec<&str> {
    let globals = s.globals.iter().filter(|g| is_shared(g)).map(|g| g.name.as_str());
    globals.chain(s.structs.iter().map(|d| d.name.as_str())).collect()
}

/// A `patch` varying (a tessellation stage's per-patch input or output): the qualifier
/// before its storage keyword.
pub(crate) fn is_patch(text: &str, g: &Global) -> bool {
    let Some(storage) = &g.storage_span else { return false };
    let before = &text[g.decl_span.start.min(storage.start)..storage.start];
    before.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).any(|w| w == "patch")
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
pub(crate) fn corner_accessor(private: &str, ty: &str, corners: u32) -> String {
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
pub(crate) fn is_shared(g: &Global) -> bool {
    matches!(g.storage, Storage::Uniform | Storage::Buffer)
}

/// Components of a float or integer vector (`float`, `int`, `uint` 1 … `vec4`, `ivec4`,
/// `uvec4` 4).
pub(crate) fn components(ty: &GlslType) -> Option<u32> {
    ty.vector_components().filter(|_| !ty.is_array())
}

/// Where `name` is written in the definition at `span`: the first `name` followed by `(`.
pub(crate) fn find_name(text: &str, span: &Range<usize>, name: &str) -> Option<usize> {
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
