//! Identifier uses: loose uniforms read from the shared block in their stored form,
//! combined samplers as texture + sampler pairs, legacy and naga-typed built-ins renamed,
//! block members a loose global would shadow renamed.

use std::ops::Range;

use super::Ctx;
use crate::diag::{Code, Diagnostic};
use crate::front::limitation::Limitation;
use crate::front::plan::Repr;
use crate::front::syntax::{GlslType, Referent, StageSyntax, Storage};
use crate::stage::StageKind;

impl Ctx<'_> {
    pub(super) fn uses(&mut self) {
        let s = self.s;
        for u in &s.uses {
            match &u.target {
                Referent::Global(_) if names_builtin(s, u) => self.builtin_use(u),
                Referent::Global(gi) => {
                    let g = &s.globals[*gi];
                    if g.storage == Storage::Uniform && g.block.is_some() {
                        self.user_block_member_use(u, g);
                        continue;
                    }
                    if g.storage != Storage::Uniform {
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
                                    if !(self.dynamic_sampler_index_legal() && self.dynamic_lookup(u, dot_span, isp, &g.name, Some(field)))
                                    {
                                        self.dynamic_sampler_index(isp.clone(), &g.name);
                                    }
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
                Referent::Param(fi, pi) => {
                    if let Some(g) = self.array_param_global(&u.target).map(|gi| &s.globals[gi]) {
                        self.sampler_use(u, &g.name, &g.ty);
                        continue;
                    }
                    let p = &s.functions[*fi].params[*pi];
                    let name = p.name.clone().unwrap_or_default();
                    let text = if u.user_call_arg {
                        format!("{name}, {name}_sampler")
                    } else {
                        format!("{}({name}, {name}_sampler)", combined_ctor(&p.ty.base))
                    };
                    self.edits.replace(u.span.clone(), text);
                }
                Referent::Unresolved => {
                    if self.limitation.is_none()
                        && crate::front::builtins::is_variable_naga_lacks(&u.name, &s.version)
                        && !crate::front::compat::handles(&u.name, s.stage)
                        && crate::front::builtins::constants::declaration(&u.name).is_none()
                    {
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
    pub(super) fn shadowed_block_members(&mut self) {
        let s = self.s;
        let loose: std::collections::HashSet<&str> = s.globals.iter().filter(|g| g.block.is_none()).map(|g| g.name.as_str()).collect();
        let mut renamed: Vec<(usize, String, String)> = Vec::new();
        for (gi, g) in s.globals.iter().enumerate() {
            let Some(b) = &g.block else { continue };
            match (&b.instance, g.storage) {
                (Some(instance), Storage::In | Storage::Out) if !self.flattens(g) => {
                    // (A flattened block passes as loose varyings; its members live in a
                    // private struct.)
                    for m in b.members.iter().filter(|m| loose.contains(m.name.as_str())) {
                        renamed.push((gi, m.name.clone(), format!("{instance}_{}", m.name)));
                    }
                }
                // Uniform and buffer blocks: the plan's names, the same in every stage
                // ([`renamed_members`](crate::front::plan::Plan::renamed_members)).
                (Some(_), Storage::Uniform | Storage::Buffer) => {
                    for (_, member, new) in self.plan.renamed_members.iter().filter(|(bn, _, _)| *bn == b.block_name) {
                        renamed.push((gi, member.clone(), new.clone()));
                    }
                }
                _ => {}
            }
        }
        self.rename_block_members(&renamed);
    }

    /// Renames members (global index, member, new name) in their declaration and at every
    /// `instance.member`.
    fn rename_block_members(&mut self, renamed: &[(usize, String, String)]) {
        let s = self.s;
        for (gi, member, new) in renamed {
            let b = s.globals[*gi].block.as_ref().expect("a block");
            if let Some(m) = b.members.iter().find(|m| m.name == *member) {
                self.edits.replace(m.span.clone(), new.clone());
            }
        }
        for u in &s.uses {
            let Referent::Global(gi) = u.target else { continue };
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
            Some((bracket, isp, None)) if ty.is_array() => {
                if !(self.dynamic_sampler_index_legal() && self.dynamic_lookup(u, bracket, isp, name, None)) {
                    self.dynamic_sampler_index(isp.clone(), name);
                }
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

    /// Whether the stage may index a sampler array with a non-constant expression: GLSL
    /// 4.00 and ES 3.20 on, ES 1.00 (loop indices, its constant-index-expressions), or a
    /// `gpu_shader5` extension enabled.
    fn dynamic_sampler_index_legal(&self) -> bool {
        let v = &self.s.version;
        (!v.is_es() && v.number >= 400) || (v.is_es() && (v.number >= 320 || v.number == 100)) || self.s.gpu_shader5
    }

    fn dynamic_sampler_index(&mut self, span: Range<usize>, name: &str) {
        if self.dynamic_sampler_index_legal() {
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
            Diagnostic::new(
                Code::NonConstantSamplerIndex,
                format!("`{}` is indexed with a non-constant expression", self.s.original_name(name)),
            )
            .at(self.s.file, span, "not a constant index")
            .with_note(
                "effectc splits sampler arrays into one texture binding per element; WGSL and naga have no arrays of combined samplers",
            )
            .with_help("index with a literal or a `const int`, e.g. unroll the loop"),
        );
    }

    fn member_use(&mut self, u: &crate::front::syntax::Use, name: &str) {
        let plan = self.plan;
        let Some(m) = plan.member(name) else { return };
        let bracket = u.index.as_ref().map(|(bracket, _, _)| bracket.clone());
        self.read_repr(&m.repr, &m.user_ty, u.span.clone(), bracket);
    }

    /// A use of a uniform stored as `repr` read back as its declared type `user_ty`: `span`
    /// is the use (`f`, `block.f`), `bracket` the whole expression indexing it (`f[i]`).
    pub(super) fn read_repr(&mut self, repr: &Repr, user_ty: &GlslType, span: Range<usize>, bracket: Option<Range<usize>>) {
        let name = self.s.text[span.clone()].to_string();
        match repr {
            Repr::Plain => {}
            Repr::Bool { components: 1 } => self.edits.replace(span, format!("({name} != 0u)")),
            Repr::Bool { components } => self.edits.replace(span, format!("bvec{components}({name})")),
            Repr::Padded { swizzle, bool_elems } => match bracket {
                Some(bracket) => {
                    if *bool_elems {
                        self.edits.insert(bracket.start, "(");
                        self.edits.insert(bracket.end, format!(".{swizzle} != 0u)"));
                    } else {
                        self.edits.insert(bracket.end, format!(".{swizzle}"));
                    }
                }
                None => {
                    let n = user_ty.dims.first().copied().flatten().unwrap_or(0);
                    let elems: Vec<String> = (0..n)
                        .map(|i| if *bool_elems { format!("({name}[{i}].x != 0u)") } else { format!("{name}[{i}].{swizzle}") })
                        .collect();
                    self.edits.replace(span, format!("{}[{n}]({})", user_ty.base, elems.join(", ")));
                }
            },
            Repr::Mat2 => {
                self.need_mat2_helper = true;
                self.edits.insert(span.start, "effectc_mat2(");
                self.edits.insert(span.end, ")");
            }
            Repr::Mat2Array => {
                self.need_mat2_helper = true;
                if let Some(bracket) = bracket {
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
                    Diagnostic::new(Code::NonConstantFragDataIndex, "`gl_FragData` is indexed with a non-constant expression")
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
                    Diagnostic::new(Code::PointCoordConstant, "`gl_PointCoord` is (0.5, 0.5): WebGPU draws points one pixel wide")
                        .at(self.s.file, u.span.clone(), "the centre of a one-pixel point")
                        .with_note("WebGPU has no point sprites (and no `gl_PointSize`); draw a quad per point to keep a sprite's texture coordinates"),
                );
            }
            ("gl_HelperInvocation", StageKind::Fragment) => self.helper_invocation(u.span.clone()),
            ("gl_ClipDistance", StageKind::Vertex | StageKind::Geometry) => self.edits.replace(u.span.clone(), "effectc_ClipDistance"),
            ("gl_CullDistance", StageKind::Vertex | StageKind::Geometry) => self.edits.replace(u.span.clone(), "effectc_CullDistance"),
            _ => {}
        }
    }
}

/// Whether `u` names a built-in variable: one declared nowhere, or one the stage redeclares
/// (`out float gl_ClipDistance[2];`, or a member of `out gl_PerVertex { … };` redeclared
/// without an instance name: the rewrite drops the redeclaration).
pub fn names_builtin(s: &StageSyntax, u: &crate::front::syntax::Use) -> bool {
    match u.target {
        Referent::Unresolved => true,
        Referent::Global(i) => {
            let g = &s.globals[i];
            let declared = match &g.block {
                None => true,
                Some(b) => b.instance.is_none() && u.name.starts_with("gl_"),
            };
            g.name.starts_with("gl_") && declared && matches!(g.storage, Storage::In | Storage::Out)
        }
        Referent::Param(..) => false,
    }
}

/// The combined-sampler constructor naga knows for a user's sampler type (a rectangle
/// texture is read as a 2D one, its coordinates scaled, and so is a 1D depth texture, at
/// the middle of its one row: `calls::reshaped_lookup`).
pub(super) fn combined_ctor(user_ty: &str) -> &str {
    match user_ty {
        "sampler2DRect" => "sampler2D",
        "isampler2DRect" => "isampler2D",
        "usampler2DRect" => "usampler2D",
        "sampler2DRectShadow" | "sampler1DShadow" => "sampler2DShadow",
        other => other,
    }
}
