//! The text inserted after the structs the shared block needs and before the first
//! function: the `EffectcUniforms` block (with std140 fillers), textures split out of struct
//! uniforms, and the declarations that stand in for removed built-ins.

use std::fmt::Write;

use super::uses::names_builtin;
use super::{Ctx, OTHER_STAGE_PREFIX};
use crate::front::builtins::constants;
use crate::front::plan::{block_size_align, UNIFORM_BLOCK};
use crate::front::syntax::{dims_text, Referent, Storage};
use crate::stage::StageKind;

impl Ctx<'_> {
    /// GLSL's implementation constants naga does not declare, at the reference compiler's
    /// values, before the first declaration (array sizes may name them). Found in the
    /// text: sizes in declarations are no recorded uses.
    pub(super) fn insert_constants(&mut self) {
        let s = self.s;
        let mut declared = std::collections::BTreeSet::new();
        let mut text = String::new();
        for (at, _) in s.text.match_indices("gl_M") {
            let name: String = s.text[at..].chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect();
            let starts_word = !s.text[..at].ends_with(|c: char| c.is_ascii_alphanumeric() || c == '_');
            if starts_word && !crate::front::compat::handles(&name, s.stage) && declared.insert(name.clone()) {
                if let Some(d) = constants::declaration(&name) {
                    let _ = writeln!(text, "{d}");
                }
            }
        }
        if text.is_empty() {
            return;
        }
        let first = s.globals.iter().map(|g| g.decl_span.start).chain(s.structs.iter().map(|d| d.span.start)).chain(s.first_function).min();
        let at = first.map_or(s.text.len(), |f| s.text[..f].rfind('\n').map_or(0, |n| n + 1));
        if at == 0 || !s.text[..at].ends_with('\n') {
            text.insert(0, '\n');
        }
        self.edits.insert(at, text);
    }

    pub(super) fn insert_header(&mut self) {
        let s = self.s;
        // Read once per stage (a 6,000-line stage of macros has thousands): where the header
        // goes, and which names the block's members must not take (a uniform of another
        // stage by a name this stage `#define`s before the block would be macro-expanded).
        let defines = crate::front::conditionals::define_lines(&s.text);
        let hoisted = self.late_structs();
        let at = self.header_position(&defines, &hoisted);
        let mut h = String::new();
        for name in &hoisted {
            let span = s.struct_def(name).expect("a struct of the stage").span.clone();
            let with_semicolon = span.start..plain_definition_end(&s.text, &span).expect("a plain definition");
            h.push_str(&self.edits.take_out(&s.text, with_semicolon));
            h.push('\n');
        }
        if self.plan.has_block() {
            for name in &self.plan.block_structs {
                if s.struct_def(name).is_none() {
                    // The block needs a struct this stage does not declare: copy it.
                    if let Some(def) = self.plan.struct_texts.get(name) {
                        let _ = writeln!(h, "{def}");
                    }
                }
            }
            let _ = writeln!(h, "layout(std140, set = 0, binding = {}) uniform {UNIFORM_BLOCK} {{", self.plan.block_binding);
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
            // Macros defined after the header do not reach the block's text.
            let macros: std::collections::HashSet<&str> =
                defines.iter().filter(|(_, body)| body.start < at).map(|(name, _)| name.as_str()).collect();
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
                let shadowed = s.global(&m.name).is_some_and(|g| g.storage != Storage::Uniform) || macros.contains(m.name.as_str());
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
        let unresolved = |n: &str| s.uses.iter().any(|u| u.name == n && names_builtin(s, u));
        if s.stage == StageKind::Fragment && unresolved("gl_FragColor") {
            h.push_str("layout(location = 0) out vec4 effectc_FragColor;\n");
        }
        if s.stage == StageKind::Fragment {
            let mut ks: Vec<i64> = s
                .uses
                .iter()
                .filter(|u| u.name == "gl_FragData" && u.target == Referent::Unresolved)
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
        // User clip planes need a WebGPU feature and cull distances have no WebGPU
        // equivalent: the distances are computed, not used, in an array of the size the
        // stage redeclares (its `length()`), else of Mesa's `gl_MaxClipDistances`.
        for (builtin, private) in [("gl_ClipDistance", "effectc_ClipDistance"), ("gl_CullDistance", "effectc_CullDistance")] {
            if matches!(s.stage, StageKind::Vertex | StageKind::Geometry) && unresolved(builtin) {
                let _ = writeln!(h, "float {private}[{}];", redeclared_length(s, builtin).unwrap_or(8));
            }
        }
        h.push_str(&self.compat_header);
        if self.need_mat2_helper {
            h.push_str("mat2 effectc_mat2(vec4 v) { return mat2(v.xy, v.zw); }\n");
        }
        h.push_str(&super::polyfills::definitions(&self.polyfills));
        if h.is_empty() {
            return;
        }
        let at = if at >= s.text.len() && !s.text.ends_with('\n') {
            h.insert(0, '\n');
            s.text.len()
        } else {
            at
        };
        self.edits.insert(at, h);
    }
}

impl Ctx<'_> {
    /// Where the header goes: after every struct the block needs, before the first
    /// function, and before a `#define` of a block member's own name where one comes
    /// between (`uniform vec2 OutputSize;` … `#define OutputSize vec4(OutputSize, 1.0 /
    /// OutputSize)`, emulator packs): the member keeps its name, which the macro's body
    /// reads.
    /// `defines`: the stage's `#define` lines (name, body).
    /// `hoisted`: the structs moved into the header ([`late_structs`](Self::late_structs)).
    fn header_position(&self, defines: &[(String, std::ops::Range<usize>)], hoisted: &[String]) -> usize {
        let s = self.s;
        let structs_end = self
            .plan
            .block_structs
            .iter()
            .filter(|n| !hoisted.contains(n))
            .filter_map(|n| s.struct_def(n))
            .map(|d| line_end(&s.text, d.span.end))
            .max()
            .unwrap_or(0);
        let at = self.header_point().max(structs_end);
        let member_define = defines
            .iter()
            .filter(|(name, _)| self.plan.member(name).is_some())
            .map(|(_, body)| s.text[..body.start].rfind('\n').map_or(0, |n| n + 1))
            .find(|&line| structs_end <= line && line < at);
        member_define.unwrap_or(at)
    }
}

impl Ctx<'_> {
    /// Where the header must come at the latest: before the first function and before the
    /// first use of a uniform the block holds.
    fn header_point(&self) -> usize {
        let first = self.s.first_function.unwrap_or(self.s.text.len());
        self.header_before.map_or(first, |b| b.min(first))
    }

    /// Structs the block needs that the stage defines only after a function reads one of
    /// the block's uniforms (`uniform float pick; void post() { … pick … } struct Light {
    /// … }; uniform Light light;`): the block cannot follow them, so they move up into the
    /// header, in the stage's order. Only plain definitions (`struct S { … };`) whose text
    /// names no global declared between the header and them move; otherwise none does.
    fn late_structs(&self) -> Vec<String> {
        let s = self.s;
        if !self.plan.has_block() {
            return Vec::new();
        }
        let point = self.header_point();
        let mut late: Vec<&crate::front::syntax::StructDef> =
            self.plan.block_structs.iter().filter_map(|n| s.struct_def(n)).filter(|d| d.span.start >= point).collect();
        late.sort_by_key(|d| d.span.start);
        let moving: Vec<&str> = late.iter().map(|d| d.name.as_str()).collect();
        let movable = |d: &crate::front::syntax::StructDef| {
            // The names its text uses, its members' own names aside (`vec3 color;` names no
            // global `color`).
            let mut text = s.text[d.span.clone()].to_string();
            for m in d.members.iter().filter(|m| m.span.start >= d.span.start && m.span.end <= d.span.end) {
                let at = m.span.start - d.span.start..m.span.end - d.span.start;
                text.replace_range(at.clone(), &" ".repeat(at.len()));
            }
            let names = || crate::front::lexical::identifiers(&text);
            let between = |at: usize| at >= point && at < d.span.start;
            // What it names must not stay behind it: a global (a constant size) or a
            // struct that does not move with it.
            let globals = s.globals.iter().filter(|g| between(g.decl_span.start)).any(|g| names().any(|w| w == g.name));
            let structs = s
                .structs
                .iter()
                .filter(|t| between(t.span.start) && !moving.contains(&t.name.as_str()))
                .any(|t| names().any(|w| w == t.name));
            plain_definition_end(&s.text, &d.span).is_some() && !globals && !structs
        };
        if late.iter().all(|d| movable(d)) {
            late.into_iter().map(|d| d.name.clone()).collect()
        } else {
            Vec::new()
        }
    }
}

/// Where a struct specifier at `span` ends as a declaration of its own (`struct S { … };`):
/// after the `;` that follows it; `None` when a declarator follows (`struct S { … } s;`).
fn plain_definition_end(text: &str, span: &std::ops::Range<usize>) -> Option<usize> {
    let after = &text[span.end..];
    let rest = after.trim_start();
    rest.starts_with(';').then(|| span.end + (after.len() - rest.len()) + 1)
}

fn line_end(text: &str, at: usize) -> usize {
    text[at.min(text.len())..].find('\n').map(|i| at + i + 1).unwrap_or(text.len())
}

/// The length of a built-in output array the stage redeclares (`out float
/// gl_ClipDistance[3];`, or as a member of `out gl_PerVertex { … };`).
pub(crate) fn redeclared_length(s: &crate::front::syntax::StageSyntax, builtin: &str) -> Option<u32> {
    let outputs = s.globals.iter().filter(|g| g.storage == Storage::Out);
    let alone = outputs.clone().find(|g| g.name == builtin).map(|g| &g.ty);
    let member = || {
        let blocks = outputs.filter(|g| g.name.starts_with("gl_")).filter_map(|g| g.block.as_ref());
        blocks.flat_map(|b| &b.members).find(|m| m.name == builtin).map(|m| &m.ty)
    };
    alone.or_else(member).and_then(|ty| ty.dims.first().copied().flatten())
}
