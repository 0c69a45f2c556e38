//! Functions and calls: sampler parameters split into texture + sampler, legacy texture
//! functions renamed, vertex-stage lookups given their level, integer-texture lookups
//! fetched, shadow-lookup biases dropped.

use super::uses::combined_ctor;
use super::Ctx;
use crate::diag::{Code, Diagnostic};
use crate::front::syntax::is_rect_sampler;
use crate::front::syntax::Storage;
use crate::stage::StageKind;

/// Legacy built-in functions and their 4.50 names; `true` when the result must be widened
/// to `vec4` (the 1xx shadow functions returned vec4).
const LEGACY_FUNCTIONS: &[(&str, &str, bool)] = &[
    ("texture1D", "texture", false),
    ("texture2D", "texture", false),
    ("texture3D", "texture", false),
    ("textureCube", "texture", false),
    ("texture2DRect", "texture", false),
    ("texture2DRectProj", "textureProj", false),
    ("texture1DProj", "textureProj", false),
    ("texture1DProjLod", "textureProjLod", false),
    ("texture3DProj", "textureProj", false),
    ("texture3DProjLod", "textureProjLod", false),
    ("texture2DProjLodEXT", "textureProjLod", false),
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
    ("shadow2DLod", "textureLod", true),
    ("shadow2DProjLod", "textureProjLod", true),
    ("shadow1D", "texture", true),
    ("shadow1DProj", "textureProj", true),
    ("shadow1DLod", "textureLod", true),
    ("shadow1DProjLod", "textureProjLod", true),
    ("shadow2DRect", "texture", true),
    ("shadow2DRectProj", "textureProj", true),
    // ARB_shader_texture_lod (GLSL 1.10+) and EXT_shader_texture_lod (ES): explicit gradients.
    ("texture1DGradARB", "textureGrad", false),
    ("texture1DProjGradARB", "textureProjGrad", false),
    ("texture2DGradARB", "textureGrad", false),
    ("texture2DProjGradARB", "textureProjGrad", false),
    ("texture3DGradARB", "textureGrad", false),
    ("texture3DProjGradARB", "textureProjGrad", false),
    ("textureCubeGradARB", "textureGrad", false),
    ("texture2DRectGradARB", "textureGrad", false),
    ("texture2DRectProjGradARB", "textureProjGrad", false),
    ("shadow1DGradARB", "textureGrad", true),
    ("shadow1DProjGradARB", "textureProjGrad", true),
    ("shadow2DGradARB", "textureGrad", true),
    ("shadow2DProjGradARB", "textureProjGrad", true),
    ("shadow2DRectGradARB", "textureGrad", true),
    ("shadow2DRectProjGradARB", "textureProjGrad", true),
    ("texture2DProjGradEXT", "textureProjGrad", false),
    ("textureCubeGradEXT", "textureGrad", false),
];

impl Ctx<'_> {
    pub(super) fn functions(&mut self) {
        let s = self.s;
        for f in &s.functions {
            for p in f.params.iter().filter(|p| !p.ty.is_sampler()) {
                // `const in Ray ray`: naga's parser takes no `const` on a parameter; it only
                // forbids writes, which glslang has checked.
                let text = &s.text[p.span.clone()];
                let words = text.split(|c: char| !c.is_ascii_alphanumeric() && c != '_');
                let mut at = 0;
                for w in words {
                    if w == "const" {
                        self.edits.delete(p.span.start + at..p.span.start + at + w.len());
                    }
                    if w == p.ty.base {
                        break;
                    }
                    at += w.len() + 1;
                }
            }
            let split: Vec<_> =
                f.params.iter().enumerate().filter(|(pi, p)| p.ty.is_sampler() && !self.is_array_param(&f.name, *pi)).collect();
            for (_, p) in split {
                let (tex, samp) = crate::front::syntax::sampler_parts(&p.ty.base).expect("sampler");
                let text = match &p.name {
                    Some(n) => format!("{tex} {n}, {samp} {n}_sampler"),
                    None => format!("{tex}, {samp}"),
                };
                self.edits.replace(p.span.clone(), text);
            }
        }
    }

    pub(super) fn calls(&mut self) {
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
            if self.texel_buffer_lookup(c) || self.reshaped_lookup(c) {
                continue;
            }
            let implicit_lod =
                matches!(c.name.as_str(), "texture" | "texture2D" | "textureCube" | "texture3D" | "texture1D" | "texture2DRect");
            let no_derivatives = matches!(s.stage, StageKind::Vertex | StageKind::Geometry | StageKind::Compute);
            if no_derivatives && c.name == "textureOffset" && c.args.len() == 3 {
                // textureOffset(s, P, offset) in a vertex stage: the base level, explicitly.
                self.edits.replace(c.name_span.clone(), "textureLodOffset");
                self.edits.insert(c.args[1].end, ", 0.0");
                continue;
            }
            if no_derivatives && implicit_lod {
                // Vertex, geometry and compute shaders have no derivatives: GL samples the
                // base level; naga wants it explicit (a geometry stage runs folded into the
                // vertex stage).
                if c.name != "texture" {
                    self.legacy(c.name_span.clone(), &c.name, "textureLod");
                }
                self.edits.replace(c.name_span.clone(), "textureLod");
                let close = s.text[..c.span.end].rfind(')').unwrap_or(c.span.end);
                self.edits.insert(close, ", 0.0");
                continue;
            }
            self.shadow_bias(c);
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
    /// The user's type of the call's first argument (a sampler parameter, or a uniform
    /// sampler that is no array) and the rewritten combined-sampler expression for it.
    pub(super) fn first_arg_text(&self, c: &crate::front::syntax::Call) -> Option<(String, String)> {
        let name = c.first_arg_name.as_deref()?;
        match self.first_arg_sampler(c)? {
            FirstArg::Param(ty) => {
                let text = format!("{}({name}, {name}_sampler)", combined_ctor(&ty));
                Some((ty, text))
            }
            FirstArg::Global(g) if !g.ty.is_array() => {
                let t = self.plan.texture(&g.name)?;
                Some((t.user_ty.clone(), format!("{}({}, {})", combined_ctor(&t.user_ty), t.name, t.sampler_name)))
            }
            FirstArg::Global(_) => None,
        }
    }

    /// `texelFetch(s, P)` and `textureSize(s)` of a buffer texture `s` (a uniform, no
    /// array), which the rewrite declares as a storage buffer of texels
    /// (`declarations::texel_buffers`): `effectc_texels_s[int(P)]` and
    /// `int(effectc_texels_s.length())`.
    fn texel_buffer_lookup(&mut self, c: &crate::front::syntax::Call) -> bool {
        let Some(FirstArg::Global(g)) = self.first_arg_sampler(c) else { return false };
        if crate::front::syntax::texel_buffer_element(&g.ty.base).is_none() || g.ty.is_array() {
            return false;
        }
        let texels = format!("effectc_texels_{}", g.name);
        match (c.name.as_str(), c.args.len()) {
            ("texelFetch", 2) => {
                self.edits.replace(c.span.start..c.args[1].start, format!("{texels}[int("));
                self.edits.replace(c.args[1].end..c.span.end, ")]");
                true
            }
            ("textureSize", 1) => {
                self.edits.replace(c.span.clone(), format!("int({texels}.length())"));
                true
            }
            _ => false,
        }
    }

    /// A lookup in a texture the rewrite reads as a 2D one ([`Self::rect_lookup`],
    /// [`Self::shadow_1d_lookup`]). True when nothing else is left to rewrite.
    fn reshaped_lookup(&mut self, c: &crate::front::syntax::Call) -> bool {
        let Some((ty, sampler)) = self.first_arg_text(c) else { return false };
        if ty == "sampler1DShadow" {
            return self.shadow_1d_lookup(c);
        }
        is_rect_sampler(&ty) && self.rect_lookup(c, &ty, &sampler)
    }

    /// A comparison in a 1D depth texture (`sampler1DShadow`), which the rewrite reads as a
    /// 2D one of one row: `P` = (s, unused, ref[, q]) becomes (s, 0.5, ref[, q]) with the row
    /// scaled by a projective `q` (`effectc_shadow1d`); `textureSize` keeps the width.
    fn shadow_1d_lookup(&mut self, c: &crate::front::syntax::Call) -> bool {
        match c.name.as_str() {
            "textureSize" => {
                self.edits.insert(c.span.end, ".x");
                true
            }
            "texture" | "textureProj" | "textureLod" | "textureProjLod" | "shadow1D" | "shadow1DProj" | "shadow1DLod"
            | "shadow1DProjLod"
                if c.args.len() >= 2 =>
            {
                self.edits.insert(c.args[1].start, "effectc_shadow1d(");
                self.edits.insert(c.args[1].end, ")");
                if !self.polyfills.contains(&"shadow1d") {
                    self.polyfills.push("shadow1d");
                }
                false
            }
            _ => false,
        }
    }

    /// A lookup in a rectangle texture (`sampler2DRect`, …), which the rewrite reads as a
    /// 2D texture: its coordinates (and gradients) are in texels, so they are divided by
    /// the texture's size (`effectc_rect`, which leaves a projective divisor and a depth
    /// reference alone); `texelFetch` and `textureSize` get the level 0 that rectangle
    /// textures have and 2D ones name; an integer one's `texture` fetches the texel under
    /// `P`, as GL's NEAREST filtering does. True when nothing else is left to rewrite.
    fn rect_lookup(&mut self, c: &crate::front::syntax::Call, ty: &str, sampler: &str) -> bool {
        if c.args.len() < 2 && c.name != "textureSize" {
            return false;
        }
        let scaled: &[usize] = match c.name.as_str() {
            "textureSize" if c.args.len() == 1 => {
                self.edits.insert(c.args[0].end, ", 0");
                return true;
            }
            "texelFetch" | "texelFetchOffset" => {
                self.edits.insert(c.args[1].end, ", 0");
                return true;
            }
            "texture" | "texture2DRect" if c.args.len() == 2 && matches!(ty, "isampler2DRect" | "usampler2DRect") => {
                self.edits.replace(c.name_span.clone(), "texelFetch");
                self.edits.insert(c.args[1].start, "ivec2(");
                self.edits.insert(c.args[1].end, "), 0");
                return true;
            }
            "texture"
            | "texture2DRect"
            | "textureOffset"
            | "textureProj"
            | "texture2DRectProj"
            | "textureProjOffset"
            | "shadow2DRect"
            | "shadow2DRectProj"
            | "textureGather"
            | "textureGatherOffset"
            | "textureGatherOffsets" => &[1],
            "textureGrad" | "textureGradOffset" | "textureProjGrad" | "textureProjGradOffset" if c.args.len() >= 4 => &[1, 2, 3],
            _ => return false,
        };
        let size = format!("vec2(textureSize({sampler}, 0))");
        for &i in scaled {
            self.edits.insert(c.args[i].start, "effectc_rect(");
            self.edits.insert(c.args[i].end, format!(", {size})"));
        }
        if !self.polyfills.contains(&"rect") {
            self.polyfills.push("rect");
        }
        false
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
        let shadow = match self.first_arg_sampler(c) {
            Some(FirstArg::Param(ty)) => ty.ends_with("Shadow"),
            Some(FirstArg::Global(g)) => g.ty.base.ends_with("Shadow"),
            None => false,
        };
        let gradients = c.name.contains("Grad") && !c.name.starts_with("textureGather");
        if shadow && gradients && c.args.len() >= 4 {
            // WGSL compares depth at level 0 or with implicit derivatives only: naga reads a
            // shadow lookup with explicit gradients at level 0.
            let (first, last) = (c.args[2].clone(), c.args[3].clone());
            self.diags.push(
                Diagnostic::new(Code::ShadowBiasDropped, "the gradients of this shadow lookup are dropped: level 0 is read")
                    .at(self.s.file, first.start..last.end, "explicit gradients on a depth comparison")
                    .with_note("WGSL compares depth at level 0 or with implicit derivatives only; it changes nothing unless the depth texture has mipmaps"),
            );
            return;
        }
        let base_args = match c.name.as_str() {
            "texture" | "textureProj" | "shadow2D" | "shadow2DProj" | "shadow1D" | "shadow1DProj" => 2,
            "textureOffset" | "textureProjOffset" => 3,
            _ => return,
        };
        if c.args.len() != base_args + 1 || !shadow {
            return;
        }
        let bias = c.args[base_args].clone();
        self.edits.delete(c.args[base_args - 1].end..bias.end);
        self.diags.push(
            Diagnostic::new(Code::ShadowBiasDropped, "the bias of this shadow lookup is dropped")
                .at(self.s.file, bias, "level-of-detail bias on a depth comparison")
                .with_note("naga and WGSL compare depth without a bias; it changes nothing unless the depth texture has mipmaps"),
        );
    }
}

/// What the first argument of a built-in call names.
enum FirstArg<'a> {
    /// A parameter of the enclosing function, by its type.
    Param(String),
    Global(&'a crate::front::syntax::Global),
}
