//! Rewrites one stage's desktop GLSL into GLSL 4.50 that naga accepts.
//!
//! Every change is a text edit on the user's file (see [`edits`](super::edits)), so naga's
//! errors map back to the user's line and column. What changes:
//! `#version` → 450; loose uniforms → members of the shared `EffectcUniforms` block;
//! combined samplers → texture + sampler pairs (declarations, uses, function parameters and
//! call arguments); locations on every varying, vertex input and fragment output;
//! 1xx `attribute`/`varying`; legacy built-ins (`texture2D`, `gl_FragColor`, …).

use std::collections::BTreeMap;
use std::fmt::Write;
use std::ops::Range;

use crate::diag::Diagnostic;
use crate::front::edits::{Edits, OffsetMap};
use crate::front::limitation::Limitation;
pub use crate::front::plan::is_unblocked_opaque;
use crate::front::plan::{block_size_align, location_slots, struct_text, Plan, Repr, UNIFORM_BLOCK};
pub use crate::front::syntax::dims_text;
use crate::front::syntax::{GlslType, StageSyntax, Storage, Target};
use crate::stage::StageKind;

/// A stage rewritten to 4.50, with the map back to the user's file.
#[derive(Debug, Clone)]
pub struct Rewritten {
    pub text: String,
    pub map: OffsetMap,
    /// A legal construct the rewrite cannot express for naga (the stage is then checked for
    /// syntax and interface only).
    pub limitation: Option<Limitation>,
}

/// Sets that user-numbered bindings (`layout(binding = N)` without a set) move to. GL
/// numbers uniform blocks, storage blocks, images and atomic counters in separate
/// namespaces (binding 0 of each can coexist), so each kind gets a set of its own.
pub const USER_UNIFORM_SET: u32 = 1;
pub const USER_BUFFER_SET: u32 = 2;
pub const USER_IMAGE_SET: u32 = 3;
pub const USER_COUNTER_SET: u32 = 4;

/// Prefix of a uniform block member another stage declares and this stage shadows.
pub const OTHER_STAGE_PREFIX: &str = "effectc_other_";

/// Legacy built-in functions and their 4.50 names; `true` when the result must be widened
/// to `vec4` (the 1xx shadow functions returned vec4).
const LEGACY_FUNCTIONS: &[(&str, &str, bool)] = &[
    ("texture1D", "texture", false),
    ("texture2D", "texture", false),
    ("texture3D", "texture", false),
    ("textureCube", "texture", false),
    ("texture2DRect", "texture", false),
    ("texture1DLod", "textureLod", false),
    ("texture2DLod", "textureLod", false),
    ("texture3DLod", "textureLod", false),
    ("textureCubeLod", "textureLod", false),
    ("texture2DProj", "textureProj", false),
    ("texture2DProjLod", "textureProjLod", false),
    ("texture2DGrad", "textureGrad", false),
    ("texture2DLodEXT", "textureLod", false),
    ("textureCubeLodEXT", "textureLod", false),
    ("texture2DGradEXT", "textureGrad", false),
    ("shadow2D", "texture", true),
    ("shadow2DProj", "textureProj", true),
];

struct Ctx<'a> {
    s: &'a StageSyntax,
    plan: &'a Plan,
    strict: bool,
    edits: Edits,
    diags: Vec<Diagnostic>,
    need_mat2_helper: bool,
    /// Statements run first in `main` (matrix inputs assembled from columns).
    prologue: String,
    /// Statements run before `main` returns (matrix outputs split into columns).
    epilogue: String,
    limitation: Option<Limitation>,
}

/// Rewrites `s` under the program plan. Warnings (and, with `strict`, errors) for legacy
/// constructs go to the returned diagnostics.
pub fn rewrite(s: &StageSyntax, plan: &Plan, strict: bool) -> (Rewritten, Vec<Diagnostic>) {
    rewrite_with(s, plan, strict, &[])
}

/// [`rewrite`], with the swizzles (indices into `s.swizzles`) naga found applied to a
/// scalar written as constructors: `x.rrr` → `vec3(x)`, `x.r` → `(x)`.
pub fn rewrite_with(s: &StageSyntax, plan: &Plan, strict: bool, scalar_swizzles: &[usize]) -> (Rewritten, Vec<Diagnostic>) {
    let limitation = s.unsupported.as_ref().map(|(construct, span)| Limitation { construct: construct.clone(), span: Some(span.clone()) });
    let mut c = Ctx {
        s,
        plan,
        strict,
        edits: Edits::new(),
        diags: Vec::new(),
        need_mat2_helper: false,
        prologue: String::new(),
        epilogue: String::new(),
        limitation,
    };
    c.version();
    c.declarations();
    c.uses();
    c.shadowed_block_members();
    c.functions();
    c.calls();
    c.struct_samplers();
    c.defaults_and_layouts();
    c.row_major_uses();
    c.unsized_arrays();
    for &i in scalar_swizzles {
        let w = &s.swizzles[i];
        let ctor = if w.width == 1 { "(".to_string() } else { format!("vec{}(", w.width) };
        // Only `.field` is replaced, so a parenthesised base keeps its own parentheses.
        let dot = s.text[w.whole.clone()].rfind('.').map_or(w.base.end, |d| w.whole.start + d);
        c.edits.insert(w.base.start, ctor);
        c.edits.replace(dot..w.whole.end, ")");
    }
    c.insert_header();
    c.insert_main_hooks();
    let Ctx { edits, mut diags, limitation, .. } = c;
    let (text, map, dropped) = edits.apply(&s.text);
    for e in dropped {
        diags.push(
            Diagnostic::warning("W0190", "effectc could not rewrite this expression for naga")
                .at(s.file, e.range.clone(), "overlapping rewrites here")
                .with_note("this is a limitation of effectc; naga may report an error nearby"),
        );
    }
    (Rewritten { text, map, limitation }, diags)
}

impl Ctx<'_> {
    fn legacy(&mut self, span: Range<usize>, what: &str, replacement: &str) {
        if !self.s.version.forbids_legacy_builtins() {
            return;
        }
        let v = &self.s.version;
        let profile = if v.is_es() { "es".to_string() } else { "core".to_string() };
        let msg = format!("`{what}` is not part of GLSL {} {profile}", v.number);
        let d = if self.strict { Diagnostic::error("E0120", msg) } else { Diagnostic::warning("W0120", msg) };
        self.diags.push(
            d.at(self.s.file, span, format!("removed from the {profile} profile"))
                .with_note("strict compilers such as glslangValidator reject this; effectc accepts it")
                .with_help(format!("use `{replacement}` instead")),
        );
    }

    fn version(&mut self) {
        let v = &self.s.version;
        match (&v.number_span, &v.profile_span) {
            (Some(num), profile) => {
                self.edits.replace(num.clone(), "450");
                if let Some(p) = profile {
                    // naga accepts only the core profile word.
                    self.edits.replace(p.clone(), "core");
                }
            }
            (None, _) => self.edits.insert(0, "#version 450 core\n"),
        }
    }

    fn declarations(&mut self) {
        let s = self.s;
        // Group declarators by declaration span (`uniform float a, b;`).
        let mut by_decl: BTreeMap<usize, Vec<usize>> = BTreeMap::new();
        for (i, g) in s.globals.iter().enumerate() {
            by_decl.entry(g.decl_span.start).or_default().push(i);
        }
        let mut vertex_inputs = LocationAllocator::new(
            s.globals.iter().filter(|g| is_vertex_input(s, g.storage)).filter_map(|g| g.location.map(|l| (l, location_slots(&g.ty, s)))),
        );
        let mut fragment_outputs = LocationAllocator::new(
            s.globals.iter().filter(|g| is_fragment_output(s, g.storage)).filter_map(|g| g.location.map(|l| (l, location_slots(&g.ty, s)))),
        );
        if s.stage == StageKind::Fragment && s.uses.iter().any(|u| u.name == "gl_FragColor" && u.target == Target::Unresolved) {
            fragment_outputs.reserve(0, 1);
        }
        for (_, idxs) in by_decl {
            let first = &s.globals[idxs[0]];
            let decl = first.decl_span.clone();
            match first.storage {
                Storage::Uniform | Storage::Buffer if first.block.is_some() => {
                    let b = first.block.as_ref().expect("block");
                    if first.layout.iter().any(|(k, _)| k == "push_constant") {
                        // Push constants have no binding.
                    } else if first.layout.iter().any(|(k, _)| k == "binding") {
                        // The user's own binding numbers live in set 1, clear of ours.
                        let set = if first.storage == Storage::Buffer { USER_BUFFER_SET } else { USER_UNIFORM_SET };
                        self.add_layout(first, &format!("set = {set}"), "set");
                    } else {
                        let binding = self.plan.user_blocks.get(&b.block_name).copied().unwrap_or(0);
                        self.add_layout(first, &format!("set = 0, binding = {binding}"), "binding");
                    }
                }
                Storage::Uniform if is_unblocked_opaque(&first.ty.base) => {
                    // Images and atomic counters stay declarations of their own.
                    if first.layout.iter().any(|(k, _)| k == "binding") {
                        let base = first.ty.base.as_str();
                        let set = if base == "atomic_uint" {
                            USER_COUNTER_SET
                        } else if ["image", "iimage", "uimage"].iter().any(|p| base.starts_with(p)) {
                            USER_IMAGE_SET
                        } else {
                            USER_UNIFORM_SET
                        };
                        self.add_layout(first, &format!("set = {set}"), "set");
                    } else {
                        let binding = self.plan.opaque.get(&first.name).copied().unwrap_or(0);
                        self.add_layout(first, &format!("set = 0, binding = {binding}"), "binding");
                    }
                }
                Storage::Uniform => {
                    let mut text = String::new();
                    // `uniform struct S { … } s;` keeps the struct type declared.
                    for def in s.structs.iter().filter(|d| decl.start <= d.span.start && d.span.end <= decl.end) {
                        text.push_str(&struct_text(def, self.plan.padded_structs.contains(&def.name)));
                        text.push(' ');
                    }
                    for &i in &idxs {
                        let g = &s.globals[i];
                        for t in
                            self.plan.textures.iter().filter(|t| t.user_path == g.name || t.user_path.starts_with(&format!("{}[", g.name)))
                        {
                            let _ = write!(
                                text,
                                "layout(set = 0, binding = {}) uniform {} {}; layout(set = 0, binding = {}) uniform {} {};",
                                t.texture_binding, t.texture_ty, t.name, t.sampler_binding, t.sampler_ty, t.sampler_name
                            );
                        }
                        if g.initializer.is_some() {
                            self.diags.push(
                                Diagnostic::warning("W0130", format!("initializer of uniform `{}` is ignored", s.original_name(&g.name)))
                                    .at(s.file, g.initializer.clone().unwrap_or(g.name_span.clone()), "this value is not used")
                                    .with_help("set the default in the effect manifest's [uniforms] table"),
                            );
                        }
                    }
                    self.edits.replace(decl, text);
                }
                Storage::In | Storage::Out | Storage::Attribute | Storage::Varying => {
                    if first.name.starts_with("gl_") {
                        // Redeclared built-ins (`out gl_PerVertex {…}`, `in vec4 gl_FragCoord`).
                        self.edits.delete(decl);
                        continue;
                    }
                    self.storage_keyword(first);
                    if idxs.len() == 1 {
                        self.flat_integer_output(first);
                    }
                    let kind = if is_vertex_input(s, first.storage) {
                        Some(&mut vertex_inputs)
                    } else if is_fragment_output(s, first.storage) {
                        Some(&mut fragment_outputs)
                    } else {
                        None
                    };
                    if idxs.len() == 1 && first.block.is_none() && !first.ty.is_array() && matrix_shape(&first.ty.base).is_some() {
                        let loc = match (first.location, kind) {
                            (Some(l), _) => l,
                            (None, Some(alloc)) => alloc.next(location_slots(&first.ty, s)),
                            (None, None) => self.plan.varyings.get(&first.name).copied().unwrap_or(0),
                        };
                        self.split_matrix(first, loc);
                        continue;
                    }
                    if idxs.len() == 1 {
                        if first.location.is_some() {
                            continue;
                        }
                        let loc = match kind {
                            Some(alloc) => alloc.next(location_slots(&first.ty, s)),
                            None => self.plan.varyings.get(&first.name).copied().unwrap_or(0),
                        };
                        self.add_layout(first, &format!("location = {loc}"), "location");
                    } else {
                        // Split `out vec3 a, b;` so each name gets its own location.
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
                                Some(i) => format!("{} ", interp_word(i)),
                                None if self.needs_flat(g) => "flat ".to_string(),
                                None => String::new(),
                            };
                            let dir = storage_word(s.stage, g.storage);
                            let _ = write!(text, "layout(location = {loc}) {interp}{dir} {} {}{};", g.ty.base, g.name, dims_text(&g.ty));
                        }
                        self.edits.replace(decl, text);
                    }
                }
                _ => {}
            }
        }
    }

    /// A matrix input/output becomes one vector per column plus a private matrix.
    fn split_matrix(&mut self, g: &crate::front::syntax::Global, loc: u32) {
        let (cols, rows) = matrix_shape(&g.ty.base).expect("matrix");
        let dir = storage_word(self.s.stage, g.storage);
        let interp = g.interp.map(|i| format!("{} ", interp_word(i))).unwrap_or_default();
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

    fn insert_main_hooks(&mut self) {
        let Some(body) = self.s.main_body.clone() else { return };
        let s = self.s;
        if s.stage == StageKind::Vertex && !s.uses.iter().any(|u| u.name == "gl_Position" && u.target == Target::Unresolved) {
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

    /// Adds `item` to the declaration's layout qualifier (or a new one), unless `key` is set.
    fn add_layout(&mut self, g: &crate::front::syntax::Global, item: &str, key: &str) {
        if g.layout.iter().any(|(k, _)| k == key) {
            return;
        }
        match &g.layout_span {
            Some(span) => {
                let open = self.s.text[span.clone()].find('(').map(|i| span.start + i + 1).unwrap_or(span.start);
                self.edits.insert(open, format!("{item}, "));
            }
            None => self.edits.insert(g.decl_span.start, format!("layout({item}) ")),
        }
    }

    fn uses(&mut self) {
        let s = self.s;
        for u in &s.uses {
            match &u.target {
                Target::Global(gi) => {
                    let g = &s.globals[*gi];
                    if g.storage != Storage::Uniform || g.block.is_some() {
                        continue;
                    }
                    if g.ty.is_sampler() {
                        self.sampler_use(u, &g.name, &g.ty);
                    } else if let Some((field, dot_span)) = &u.field {
                        // `material.diffuse` where the member is a sampler.
                        let path = match &u.index {
                            Some((_, _, Some(k))) => format!("{}[{k}].{field}", g.name),
                            Some((_, isp, None)) => {
                                if self.plan.textures.iter().any(|t| {
                                    t.user_path.starts_with(&format!("{}[", g.name)) && t.user_path.ends_with(&format!(".{field}"))
                                }) {
                                    self.dynamic_sampler_index(isp.clone(), &g.name);
                                    continue;
                                }
                                String::new()
                            }
                            None => format!("{}.{field}", g.name),
                        };
                        if let Some(t) = self.plan.texture(&path) {
                            let text = if u.user_call_arg {
                                format!("{}, {}", t.name, t.sampler_name)
                            } else {
                                format!("{}({}, {})", combined_ctor(&t.user_ty), t.name, t.sampler_name)
                            };
                            self.edits.replace(dot_span.clone(), text);
                            continue;
                        }
                        self.member_use(u, &g.name);
                    } else {
                        self.member_use(u, &g.name);
                    }
                }
                Target::Param(fi, pi) => {
                    let p = &s.functions[*fi].params[*pi];
                    let name = p.name.clone().unwrap_or_default();
                    let text = if u.user_call_arg {
                        format!("{name}, {name}_sampler")
                    } else {
                        format!("{}({name}, {name}_sampler)", combined_ctor(&p.ty.base))
                    };
                    self.edits.replace(u.span.clone(), text);
                }
                Target::Unresolved => {
                    if self.limitation.is_none() && crate::front::builtins::is_variable_naga_lacks(&u.name, &s.version) {
                        // naga reports these unevenly ("unknown variable", or a field
                        // lookup failing on `gl_BaryCoordEXT.x`): decide before asking it.
                        self.limitation = Some(Limitation { construct: format!("the built-in `{}`", u.name), span: Some(u.span.clone()) });
                    }
                    self.builtin_use(u)
                }
            }
        }
        for p in &s.precision_statements {
            // `precision highp sampler2DShadow;` (GLSL ES): naga takes precision for
            // `float` and `int` only, and it means nothing on desktop.
            let text = &s.text[p.clone()];
            if !text.split(|c: char| !c.is_ascii_alphanumeric() && c != '_').any(|w| matches!(w, "float" | "int")) {
                self.edits.delete(p.clone());
            }
        }
    }

    /// naga's GLSL front also declares the members of an instance-named interface block
    /// (`out Vertex { vec2 texCoord; } OUT;`) as globals, so a global of the same name
    /// (`in vec2 texCoord;`, the classic tutorial vertex stage) reads the block member
    /// instead. Such members are renamed `<instance>_<member>` in the rewrite; blocks link
    /// by location after the name-level checks, so the other stage is unaffected.
    fn shadowed_block_members(&mut self) {
        let s = self.s;
        let loose: std::collections::HashSet<&str> = s.globals.iter().filter(|g| g.block.is_none()).map(|g| g.name.as_str()).collect();
        let mut renamed: Vec<(usize, String, String)> = Vec::new();
        for (gi, g) in s.globals.iter().enumerate() {
            let Some(b) = &g.block else { continue };
            let (Some(instance), Storage::In | Storage::Out) = (&b.instance, g.storage) else { continue };
            for m in b.members.iter().filter(|m| loose.contains(m.name.as_str())) {
                let new = format!("{instance}_{}", m.name);
                self.edits.replace(m.span.clone(), new.clone());
                renamed.push((gi, m.name.clone(), new));
            }
        }
        for u in &s.uses {
            let Target::Global(gi) = u.target else { continue };
            let Some((field, dot)) = &u.field else { continue };
            if let Some((_, _, new)) = renamed.iter().find(|(g, m, _)| *g == gi && m == field) {
                if s.text.get(dot.clone()).is_some_and(|t| t.ends_with(field.as_str())) {
                    self.edits.replace(dot.end - field.len()..dot.end, new.clone());
                }
            }
        }
    }

    fn sampler_use(&mut self, u: &crate::front::syntax::Use, name: &str, ty: &GlslType) {
        let (span, path) = match &u.index {
            Some((bracket, _, Some(k))) if ty.is_array() => (bracket.clone(), format!("{name}[{k}]")),
            Some((_, isp, None)) if ty.is_array() => {
                self.dynamic_sampler_index(isp.clone(), name);
                return;
            }
            _ => (u.span.clone(), name.to_string()),
        };
        let Some(t) = self.plan.texture(&path) else { return };
        let text = if u.user_call_arg {
            format!("{}, {}", t.name, t.sampler_name)
        } else {
            format!("{}({}, {})", combined_ctor(&t.user_ty), t.name, t.sampler_name)
        };
        self.edits.replace(span, text);
    }

    fn dynamic_sampler_index(&mut self, span: Range<usize>, name: &str) {
        let v = &self.s.version;
        if (!v.is_es() && v.number >= 400) || (v.is_es() && v.number >= 320) {
            // Legal since GLSL 4.00 (dynamically uniform indices); WGSL has no arrays of
            // combined samplers, which is a translation limit, not an error.
            if self.limitation.is_none() {
                self.limitation = Some(Limitation {
                    construct: format!(
                        "`{}` indexed with a non-constant expression (an array of samplers; WGSL and naga have none)",
                        self.s.original_name(name)
                    ),
                    span: Some(span),
                });
            }
            return;
        }
        self.diags.push(
            Diagnostic::error("E0110", format!("`{}` is indexed with a non-constant expression", self.s.original_name(name)))
                .at(self.s.file, span, "not a constant index")
                .with_note(
                    "effectc splits sampler arrays into one texture binding per element; WGSL and naga have no arrays of combined samplers",
                )
                .with_help("index with a literal or a `const int`, e.g. unroll the loop"),
        );
    }

    fn member_use(&mut self, u: &crate::front::syntax::Use, name: &str) {
        let Some(m) = self.plan.member(name) else { return };
        match &m.repr {
            Repr::Plain => {}
            Repr::Bool { components: 1 } => self.edits.replace(u.span.clone(), format!("({name} != 0u)")),
            Repr::Bool { components } => self.edits.replace(u.span.clone(), format!("bvec{components}({name})")),
            Repr::Padded { swizzle, bool_elems } => match &u.index {
                Some((bracket, _, _)) => {
                    if *bool_elems {
                        self.edits.insert(bracket.start, "(");
                        self.edits.insert(bracket.end, format!(".{swizzle} != 0u)"));
                    } else {
                        self.edits.insert(bracket.end, format!(".{swizzle}"));
                    }
                }
                None => {
                    let n = m.user_ty.dims.first().copied().flatten().unwrap_or(0);
                    let elems: Vec<String> = (0..n)
                        .map(|i| if *bool_elems { format!("({name}[{i}].x != 0u)") } else { format!("{name}[{i}].{swizzle}") })
                        .collect();
                    self.edits.replace(u.span.clone(), format!("{}[{n}]({})", m.user_ty.base, elems.join(", ")));
                }
            },
            Repr::Mat2 => {
                self.need_mat2_helper = true;
                self.edits.insert(u.span.start, "effectc_mat2(");
                self.edits.insert(u.span.end, ")");
            }
            Repr::Mat2Array => {
                self.need_mat2_helper = true;
                if let Some((bracket, _, _)) = &u.index {
                    self.edits.insert(bracket.start, "effectc_mat2(");
                    self.edits.insert(bracket.end, ")");
                }
            }
        }
    }

    fn builtin_use(&mut self, u: &crate::front::syntax::Use) {
        let stage = self.s.stage;
        match (u.name.as_str(), stage) {
            ("gl_FragColor", StageKind::Fragment) => {
                self.legacy(u.span.clone(), "gl_FragColor", "a declared `out vec4`");
                self.edits.replace(u.span.clone(), "effectc_FragColor");
            }
            ("gl_FragData", StageKind::Fragment) => match &u.index {
                Some((bracket, _, Some(k))) => {
                    self.legacy(bracket.clone(), "gl_FragData", "declared `out vec4` outputs");
                    self.edits.replace(bracket.clone(), format!("effectc_FragData{k}"));
                }
                Some((_, isp, None)) => self.diags.push(
                    Diagnostic::error("E0111", "`gl_FragData` is indexed with a non-constant expression")
                        .at(self.s.file, isp.clone(), "not a constant index")
                        .with_help("declare `layout(location = N) out vec4 name;` outputs and write them by name"),
                ),
                None => {}
            },
            // naga types these `uint`; GLSL's are `int`.
            ("gl_VertexID" | "gl_VertexIndex", StageKind::Vertex) => self.edits.replace(u.span.clone(), "int(gl_VertexIndex)"),
            ("gl_InstanceID" | "gl_InstanceIndex", StageKind::Vertex) => self.edits.replace(u.span.clone(), "int(gl_InstanceIndex)"),
            ("gl_DrawID" | "gl_BaseVertex" | "gl_BaseInstance", StageKind::Vertex)
            | ("gl_PrimitiveID" | "gl_SampleID", StageKind::Fragment) => self.edits.replace(u.span.clone(), format!("int({})", u.name)),
            ("gl_PointSize", _) => self.edits.replace(u.span.clone(), "effectc_PointSize"),
            ("gl_PointCoord", StageKind::Fragment) => {
                // WebGPU rasterizes points one pixel wide, so the one fragment of a point
                // is its centre: what GL gives for a point of size 1.
                self.edits.replace(u.span.clone(), "vec2(0.5)");
                self.diags.push(
                    Diagnostic::note("N0104", "`gl_PointCoord` is (0.5, 0.5): WebGPU draws points one pixel wide")
                        .at(self.s.file, u.span.clone(), "the centre of a one-pixel point")
                        .with_note("WebGPU has no point sprites (and no `gl_PointSize`); draw a quad per point to keep a sprite's texture coordinates"),
                );
            }
            ("gl_ClipDistance", StageKind::Vertex) => self.edits.replace(u.span.clone(), "effectc_ClipDistance"),
            ("gl_CullDistance", StageKind::Vertex) => self.edits.replace(u.span.clone(), "effectc_CullDistance"),
            _ => {}
        }
    }

    fn functions(&mut self) {
        let s = self.s;
        for f in &s.functions {
            for p in f.params.iter().filter(|p| p.ty.is_sampler()) {
                let (tex, samp) = crate::front::syntax::sampler_parts(&p.ty.base).expect("sampler");
                let text = match &p.name {
                    Some(n) => format!("{tex} {n}, {samp} {n}_sampler"),
                    None => format!("{tex}, {samp}"),
                };
                self.edits.replace(p.span.clone(), text);
            }
        }
    }

    fn calls(&mut self) {
        let s = self.s;
        for c in &s.calls {
            if s.functions.iter().any(|f| f.name == c.name) {
                continue;
            }
            if c.from_macro {
                // Only the name is known (in the `#define` body): rename legacy built-ins.
                if let Some((old, new, false)) = LEGACY_FUNCTIONS.iter().find(|(o, _, _)| *o == c.name) {
                    self.legacy(c.name_span.clone(), old, new);
                    self.edits.replace(c.name_span.clone(), *new);
                }
                continue;
            }
            let implicit_lod = matches!(c.name.as_str(), "texture" | "texture2D" | "textureCube" | "texture3D" | "texture1D");
            if s.stage == StageKind::Vertex && c.name == "textureOffset" && c.args.len() == 3 {
                // textureOffset(s, P, offset) in a vertex stage: the base level, explicitly.
                self.edits.replace(c.name_span.clone(), "textureLodOffset");
                self.edits.insert(c.args[1].end, ", 0.0");
                continue;
            }
            if s.stage == StageKind::Vertex && implicit_lod {
                // Vertex shaders have no derivatives: GL samples the base level; naga wants it explicit.
                if c.name != "texture" {
                    self.legacy(c.name_span.clone(), &c.name, "textureLod");
                }
                self.edits.replace(c.name_span.clone(), "textureLod");
                let close = s.text[..c.span.end].rfind(')').unwrap_or(c.span.end);
                self.edits.insert(close, ", 0.0");
                continue;
            }
            self.shadow_bias(c);
            if c.name == "texture" && c.args.len() == 2 {
                if let Some(sampler) = self.integer_sampler_text(c) {
                    // GL samples integer textures with NEAREST filtering (they are incomplete
                    // otherwise); naga and WebGPU only fetch them: fetch the texel under `P`.
                    self.edits.replace(c.name_span.clone(), "texelFetch");
                    self.edits.insert(c.args[1].start, format!("ivec2(vec2(textureSize({sampler}, 0)) * ("));
                    self.edits.insert(c.args[1].end, ")), 0");
                    continue;
                }
            }
            if let Some((old, new, widen)) = LEGACY_FUNCTIONS.iter().find(|(o, _, _)| *o == c.name) {
                self.legacy(c.name_span.clone(), old, new);
                if *widen {
                    self.edits.insert(c.span.start, "vec4(");
                    self.edits.replace(c.name_span.clone(), *new);
                    self.edits.insert(c.span.end, ")");
                } else {
                    self.edits.replace(c.name_span.clone(), *new);
                }
            }
        }
    }

    /// For `texture(s, P)` on a 2D integer sampler `s` (a global or a parameter), the
    /// rewritten sampler expression.
    fn integer_sampler_text(&self, c: &crate::front::syntax::Call) -> Option<String> {
        let name = c.first_arg_name.as_deref()?;
        let integer = |ty: &str| matches!(ty, "isampler2D" | "usampler2D" | "isampler2DRect" | "usampler2DRect");
        match self.first_arg_sampler(c)? {
            FirstArg::Param(ty) => integer(&ty).then(|| format!("{}({name}, {name}_sampler)", combined_ctor(&ty))),
            FirstArg::Global(g) if integer(&g.ty.base) && !g.ty.is_array() => {
                let t = self.plan.texture(&g.name)?;
                Some(format!("{}({}, {})", combined_ctor(&t.user_ty), t.name, t.sampler_name))
            }
            FirstArg::Global(_) => None,
        }
    }

    /// The declaration the call's first argument (a bare identifier) names: a parameter of
    /// the enclosing function, else a uniform.
    fn first_arg_sampler(&self, c: &crate::front::syntax::Call) -> Option<FirstArg<'_>> {
        let s = self.s;
        let name = c.first_arg_name.as_deref()?;
        if let Some(f) = c.in_function.as_ref().and_then(|f| s.functions.iter().find(|x| &x.name == f && x.is_definition)) {
            if let Some(p) = f.params.iter().find(|p| p.name.as_deref() == Some(name)) {
                return Some(FirstArg::Param(p.ty.base.clone()));
            }
        }
        s.global(name).filter(|g| g.storage == Storage::Uniform).map(FirstArg::Global)
    }

    /// `texture(shadowSampler, P, bias)`: naga's depth-compare sampling takes no bias (nor
    /// does WGSL's `textureSampleCompare`). The bias only moves the level of detail, which a
    /// comparison of a depth texture without mipmaps (the usual shadow map) never uses:
    /// the bias is dropped, with a note.
    fn shadow_bias(&mut self, c: &crate::front::syntax::Call) {
        let base_args = match c.name.as_str() {
            "texture" | "textureProj" | "shadow2D" | "shadow2DProj" | "shadow1D" | "shadow1DProj" => 2,
            "textureOffset" | "textureProjOffset" => 3,
            _ => return,
        };
        if c.args.len() != base_args + 1 {
            return;
        }
        let shadow = match self.first_arg_sampler(c) {
            Some(FirstArg::Param(ty)) => ty.ends_with("Shadow"),
            Some(FirstArg::Global(g)) => g.ty.base.ends_with("Shadow"),
            None => false,
        };
        if !shadow {
            return;
        }
        let bias = c.args[base_args].clone();
        self.edits.delete(c.args[base_args - 1].end..bias.end);
        self.diags.push(
            Diagnostic::note("N0103", "the bias of this shadow lookup is dropped")
                .at(self.s.file, bias, "level-of-detail bias on a depth comparison")
                .with_note("naga and WGSL compare depth without a bias; it changes nothing unless the depth texture has mipmaps"),
        );
    }

    /// Sampler members leave struct definitions (they became their own bindings); structs
    /// the plan pads get their filler member.
    fn struct_samplers(&mut self) {
        let s = self.s;
        for st in &s.structs {
            let in_uniform_decl = s
                .globals
                .iter()
                .any(|g| g.storage == Storage::Uniform && g.decl_span.start <= st.span.start && st.span.end <= g.decl_span.end);
            if self.plan.padded_structs.contains(&st.name) && !in_uniform_decl {
                if let Some(close) = s.text[..st.span.end].rfind('}') {
                    self.edits.insert(close, format!(" vec4 {};", crate::front::plan::STRUCT_ALIGN_FILLER));
                }
            }
            let mut done: Vec<Range<usize>> = Vec::new();
            let opaque: Vec<_> = st.members.iter().filter(|m| m.ty.is_sampler()).collect();
            if opaque.is_empty() {
                continue;
            }
            for m in &opaque {
                if !done.contains(&m.field_span) {
                    done.push(m.field_span.clone());
                    self.edits.delete(m.field_span.clone());
                }
            }
            if opaque.len() == st.members.len() {
                // GLSL structs cannot be empty.
                if let Some(m) = opaque.first() {
                    self.edits.insert(m.field_span.start, "int effectc_unused;");
                }
            }
        }
    }

    /// Default-qualifier declarations (`layout(std140, row_major) uniform;`) leave the text;
    /// block layout items naga does not take (`row_major`, `column_major`, `shared`,
    /// `packed`, `index = 0`) leave their qualifiers; member qualifiers of blocks
    /// (`flat`, `layout(location = 3)`, `layout(row_major)`) leave the members (naga's
    /// parser takes none of them: locations follow the block's, integers are flat anyway).
    fn defaults_and_layouts(&mut self) {
        let s = self.s;
        let io_block_array =
            s.globals.iter().filter(|g| matches!(g.storage, Storage::In | Storage::Out) && !g.name.starts_with("gl_")).find_map(|g| {
                let b = g.block.as_ref()?;
                // An array member is fine last (nothing follows it to collide with).
                let n = b.members.len();
                b.members
                    .iter()
                    .enumerate()
                    .find(|(i, m)| (m.ty.is_array() && i + 1 < n) || matrix_shape(&m.ty.base).is_some())
                    .map(|(_, m)| (b.block_name.clone(), m.span.clone()))
            });
        if let (None, Some((block, span))) = (&self.limitation, io_block_array) {
            // naga's GLSL front gives every member of an interface block one location, so
            // an array member collides with the member after it; and it takes no matrix
            // varyings.
            self.limitation = Some(Limitation {
                construct: format!(
                    "an array or matrix member of the interface block `{}` (naga gives each member one location and no matrix varyings)",
                    s.original_name(&block)
                ),
                span: Some(span),
            });
        }
        for d in &s.defaults {
            if matches!(d.storage, Some(Storage::Uniform | Storage::Buffer)) {
                self.edits.delete(d.span.clone());
            }
        }
        let dual_source = s.globals.iter().any(|g| g.layout.iter().any(|(k, v)| k == "index" && *v != Some(0)));
        let mut by_decl: BTreeMap<usize, &crate::front::syntax::Global> = BTreeMap::new();
        for g in &s.globals {
            by_decl.entry(g.decl_span.start).or_insert(g);
        }
        for g in by_decl.values() {
            let is_block = g.block.is_some();
            let drop = |name: &str| match name {
                "row_major" | "column_major" | "shared" | "packed" => is_block,
                "index" => !is_block && !dual_source,
                _ => false,
            };
            if let (Some(first), Some(last)) = (g.layout_items.first(), g.layout_items.last()) {
                if g.layout_items.iter().any(|(n, _)| drop(n)) {
                    let mut kept: Vec<&str> = g.layout_items.iter().filter(|(n, _)| !drop(n)).map(|(_, sp)| &s.text[sp.clone()]).collect();
                    if kept.is_empty() && is_block {
                        // `layout()` is not GLSL: a block keeps the packing naga uses anyway.
                        kept.push(if g.storage == Storage::Buffer { "std430" } else { "std140" });
                    }
                    if !kept.is_empty() {
                        // One edit over the items only: what `add_layout` inserts right
                        // after `layout(` stays in front of them.
                        self.edits.replace(first.1.start..last.1.end, kept.join(", "));
                    }
                }
            }
            let Some(b) = &g.block else { continue };
            let mut done: Vec<Range<usize>> = Vec::new();
            for m in &b.members {
                if let Some(q) = &m.qualifier_span {
                    if done.contains(q) {
                        continue;
                    }
                    done.push(q.clone());
                    let text = &s.text[q.clone()];
                    let only_precision = ["highp", "mediump", "lowp"].contains(&text.trim());
                    if !only_precision {
                        self.edits.delete(q.clone());
                    }
                }
            }
        }
    }

    /// Whether matrices of block `g` (a uniform or buffer block) are stored row-major.
    fn block_row_major(&self, g: &crate::front::syntax::Global) -> bool {
        let mut row = false;
        for d in self.s.defaults.iter().filter(|d| d.span.end <= g.decl_span.start) {
            if matches!(d.storage, Some(Storage::Uniform | Storage::Buffer)) && d.storage == Some(g.storage) {
                for (k, _) in &d.layout {
                    match k.as_str() {
                        "row_major" => row = true,
                        "column_major" => row = false,
                        _ => {}
                    }
                }
            }
        }
        for (k, _) in &g.layout {
            match k.as_str() {
                "row_major" => row = true,
                "column_major" => row = false,
                _ => {}
            }
        }
        row
    }

    /// Row-major square matrices in uniform and buffer blocks: naga reads every matrix
    /// column-major, so the stored matrix is the transpose; each read becomes
    /// `transpose(…)`.
    fn row_major_uses(&mut self) {
        let s = self.s;
        let mut row_major: Vec<(usize, String)> = Vec::new();
        for (gi, g) in s.globals.iter().enumerate() {
            let Some(b) = &g.block else { continue };
            if !matches!(g.storage, Storage::Uniform | Storage::Buffer) {
                continue;
            }
            let block_row = self.block_row_major(g);
            for m in &b.members {
                let mut row = block_row;
                for (k, _) in &m.layout {
                    match k.as_str() {
                        "row_major" => row = true,
                        "column_major" => row = false,
                        _ => {}
                    }
                }
                if row && matches!(m.ty.base.as_str(), "mat2" | "mat3" | "mat4" | "mat2x2" | "mat3x3" | "mat4x4") {
                    row_major.push((gi, m.name.clone()));
                }
            }
        }
        if row_major.is_empty() {
            return;
        }
        for u in &s.uses {
            let Target::Global(gi) = u.target else { continue };
            let b = s.globals[gi].block.as_ref();
            let span = match (&u.field, b.and_then(|b| b.instance.as_ref())) {
                (Some((field, dot)), Some(_)) if row_major.iter().any(|(g, m)| *g == gi && m == field) => dot.clone(),
                (_, None) if row_major.iter().any(|(g, m)| *g == gi && *m == u.name) => u.span.clone(),
                _ => continue,
            };
            self.edits.insert(span.start, "transpose(");
            self.edits.insert(span.end, ")");
        }
    }

    /// `vec3 p[] = vec3[](a, b)`: naga cannot construct unsized arrays; the size is the
    /// initializer's length.
    fn unsized_arrays(&mut self) {
        let s = self.s;
        for (span, n) in &s.constant_sizes {
            self.edits.replace(span.clone(), n.to_string());
        }
        for (span, n) in &s.unsized_sizes {
            let text = &s.text[span.clone()];
            if text.trim() == "[]" {
                self.edits.replace(span.clone(), format!("[{n}]"));
            } else if text.trim().is_empty() {
                // The node spans nothing: find the brackets after it.
                if let Some(open) = s.text[span.start..].find('[') {
                    let at = span.start + open + 1;
                    if s.text[at..].trim_start().starts_with(']') {
                        self.edits.insert(at, n.to_string());
                    }
                }
            }
        }
    }

    fn insert_header(&mut self) {
        let s = self.s;
        let mut h = String::new();
        if self.plan.has_block() {
            for name in &self.plan.block_structs {
                if s.struct_def(name).is_none() {
                    // The block needs a struct this stage does not declare: copy it.
                    if let Some(def) = self.plan.struct_texts.get(name) {
                        let _ = writeln!(h, "{def}");
                    }
                }
            }
            let _ = writeln!(h, "layout(std140, set = 0, binding = 0) uniform {UNIFORM_BLOCK} {{");
            // naga's GLSL front aligns a struct member only to its largest member, but WGSL
            // wants structs in uniform buffers 16-aligned and followed by at least
            // roundUp(16, size) bytes: fillers make the layout valid (reflection reads the
            // final offsets from naga's IR).
            let mut pad = 0;
            let mut offset = 0u32;
            let mut filler = |h: &mut String, ty: &str, size: u32, offset: &mut u32| {
                let _ = writeln!(h, "    {ty} effectc_pad{pad};");
                pad += 1;
                *offset = offset.next_multiple_of(size) + size;
            };
            for (i, m) in self.plan.members.iter().enumerate() {
                let is_struct = self.plan.struct_members.contains_key(&m.block_ty.base);
                if is_struct {
                    while !offset.is_multiple_of(16) {
                        filler(&mut h, "uint", 4, &mut offset);
                    }
                }
                let (size, align) = block_size_align(&m.block_ty, self.plan);
                offset = offset.next_multiple_of(align) + size;
                // A uniform another stage declares must not shadow this stage's own
                // variable of that name: keep its bytes, not its name.
                let shadowed = s.global(&m.name).is_some_and(|g| g.storage != Storage::Uniform) || defines_macro(&s.text, &m.name);
                let name = if shadowed { format!("{OTHER_STAGE_PREFIX}{}", m.name) } else { m.name.clone() };
                let _ = writeln!(h, "    {} {name}{};", m.block_ty.base, dims_text(&m.block_ty));
                if is_struct && !m.block_ty.is_array() && i + 1 < self.plan.members.len() {
                    filler(&mut h, "vec4", 16, &mut offset);
                }
            }
            h.push_str("};\n");
        }
        // Textures flattened out of struct uniforms are declared here.
        for t in &self.plan.textures {
            if t.user_path.contains('.') {
                let root = t.user_path.split(['.', '[']).next().unwrap_or("");
                if s.global(root).is_some() {
                    let _ = writeln!(
                        h,
                        "layout(set = 0, binding = {}) uniform {} {}; layout(set = 0, binding = {}) uniform {} {};",
                        t.texture_binding, t.texture_ty, t.name, t.sampler_binding, t.sampler_ty, t.sampler_name
                    );
                }
            }
        }
        let unresolved = |n: &str| s.uses.iter().any(|u| u.name == n && u.target == Target::Unresolved);
        if s.stage == StageKind::Fragment && unresolved("gl_FragColor") {
            h.push_str("layout(location = 0) out vec4 effectc_FragColor;\n");
        }
        if s.stage == StageKind::Fragment {
            let mut ks: Vec<i64> = s
                .uses
                .iter()
                .filter(|u| u.name == "gl_FragData" && u.target == Target::Unresolved)
                .filter_map(|u| u.index.as_ref().and_then(|i| i.2))
                .collect();
            ks.sort();
            ks.dedup();
            for k in ks {
                let _ = writeln!(h, "layout(location = {k}) out vec4 effectc_FragData{k};");
            }
        }
        if unresolved("gl_PointSize") {
            // WebGPU draws points one pixel wide: the size is computed but not used.
            h.push_str("float effectc_PointSize;\n");
        }
        if s.stage == StageKind::Vertex && unresolved("gl_ClipDistance") {
            // User clip planes need a WebGPU feature; the distances are computed, not used.
            h.push_str("float effectc_ClipDistance[8];\n");
        }
        if s.stage == StageKind::Vertex && unresolved("gl_CullDistance") {
            // Cull distances have no WebGPU equivalent; computed, not used.
            h.push_str("float effectc_CullDistance[8];\n");
        }
        if self.need_mat2_helper {
            h.push_str("mat2 effectc_mat2(vec4 v) { return mat2(v.xy, v.zw); }\n");
        }
        if h.is_empty() {
            return;
        }
        // After every struct the block needs, before the first function.
        let structs_end =
            self.plan.block_structs.iter().filter_map(|n| s.struct_def(n)).map(|d| line_end(&s.text, d.span.end)).max().unwrap_or(0);
        let at = s.first_function.unwrap_or(s.text.len()).max(structs_end);
        let at = if at >= s.text.len() && !s.text.ends_with('\n') {
            h.insert(0, '\n');
            s.text.len()
        } else {
            at
        };
        self.edits.insert(at, h);
    }
}

/// Whether `text` has a `#define name` (a uniform of another stage by that name would be
/// macro-expanded in this stage's copy of the shared block).
fn defines_macro(text: &str, name: &str) -> bool {
    crate::front::conditionals::define_lines(text).iter().any(|(n, _)| n == name)
}

/// What the first argument of a built-in call names.
enum FirstArg<'a> {
    /// A parameter of the enclosing function, by its type.
    Param(String),
    Global(&'a crate::front::syntax::Global),
}

/// (columns, rows) of a matrix type name.
fn matrix_shape(base: &str) -> Option<(u32, u32)> {
    let rest = base.strip_prefix("mat")?;
    let d = |c: u8| (b'2'..=b'4').contains(&c).then(|| u32::from(c - b'0'));
    match rest.as_bytes() {
        [n] => d(*n).map(|n| (n, n)),
        [c, b'x', r] => Some((d(*c)?, d(*r)?)),
        _ => None,
    }
}

/// The combined-sampler constructor naga knows for a user's sampler type.
fn combined_ctor(user_ty: &str) -> &str {
    match user_ty {
        "sampler2DRect" => "sampler2D",
        other => other,
    }
}

fn line_end(text: &str, at: usize) -> usize {
    text[at.min(text.len())..].find('\n').map(|i| at + i + 1).unwrap_or(text.len())
}

fn is_vertex_input(s: &StageSyntax, storage: Storage) -> bool {
    s.stage == StageKind::Vertex && matches!(storage, Storage::In | Storage::Attribute)
}

fn is_fragment_output(s: &StageSyntax, storage: Storage) -> bool {
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

fn interp_word(i: crate::front::syntax::Interp) -> &'static str {
    match i {
        crate::front::syntax::Interp::Smooth => "smooth",
        crate::front::syntax::Interp::Flat => "flat",
        crate::front::syntax::Interp::NoPerspective => "noperspective",
    }
}

/// Hands out locations, skipping ones taken explicitly.
struct LocationAllocator {
    used: Vec<(u32, u32)>,
    next: u32,
}

impl LocationAllocator {
    fn new(explicit: impl Iterator<Item = (u32, u32)>) -> Self {
        LocationAllocator { used: explicit.map(|(l, n)| (l, l + n)).collect(), next: 0 }
    }
    fn reserve(&mut self, at: u32, n: u32) {
        self.used.push((at, at + n));
    }
    fn next(&mut self, slots: u32) -> u32 {
        while self.used.iter().any(|&(a, b)| self.next < b && a < self.next + slots) {
            self.next += 1;
        }
        let loc = self.next;
        self.used.push((loc, loc + slots));
        self.next += slots;
        loc
    }
}
