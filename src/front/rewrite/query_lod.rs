//! `textureQueryLod(s, p)` (GLSL 4.00), which naga and WGSL lack, computed as GL defines it
//! (GLSL 4.60 §8.9.1, OpenGL 4.6 §8.14.1) from the coordinates' screen-space derivatives in
//! texels: λ = log2(max(|∂(p·size)/∂x|, |∂(p·size)/∂y|)); `.y` is λ, `.x` λ clamped to the
//! levels the texture has (a sampler without mipmaps gives 0 in GL; WGSL cannot tell, so
//! every texture counts as mipmapped). An array's layers take no part; cube maps and sampler
//! expressions effectc cannot type stay as they are (naga refuses them, N0102).

use super::Ctx;

impl Ctx<'_> {
    /// Each `textureQueryLod` call on a named 1D, 2D or 3D sampler (arrays and shadow forms
    /// too) becomes `effectc_queryLod(p * size, levels)`.
    pub(super) fn query_lods(&mut self) {
        let s = self.s;
        let text = &s.text;
        for c in &s.calls {
            if c.name != "textureQueryLod" || c.from_macro || c.args.len() != 2 || s.functions.iter().any(|f| f.name == c.name) {
                continue;
            }
            let Some(sampler) = c.first_arg_name.as_deref().and_then(|n| s.globals.iter().find(|g| g.name == n)) else { continue };
            let kind = sampler.ty.base.trim_start_matches(['i', 'u']).trim_end_matches("Shadow");
            let (coords, size) = match kind {
                "sampler1D" => ("float", "float"),
                "sampler1DArray" => ("float", "float"),
                "sampler2D" | "sampler2DArray" | "sampler2DRect" => ("vec2", "vec2"),
                "sampler3D" => ("vec3", "vec3"),
                _ => continue,
            };
            let array = kind.ends_with("Array");
            let s_text = self.edits.text_within(text, c.args[0].clone());
            let p_text = self.edits.text_within(text, c.args[1].clone());
            let size_of = |what: &str| match (coords, array) {
                ("float", false) => format!("float({what})"),
                ("float", true) => format!("float(({what}).x)"),
                ("vec2", true) => format!("vec2(({what}).xy)"),
                _ => format!("{size}({what})"),
            };
            // An array's coordinates name no layer; its size does (dropped).
            let p = format!("({p_text})");
            let written =
                format!("effectc_queryLod({p} * {}, textureQueryLevels({s_text}))", size_of(&format!("textureSize({s_text}, 0)")));
            self.edits.take_out(text, c.span.clone());
            self.edits.insert(c.span.start, written);
            if !self.polyfills.contains(&"textureQueryLod") {
                self.polyfills.push("textureQueryLod");
            }
        }
    }
}

/// The helper each rewritten call uses, for 1, 2 and 3 coordinates.
pub(super) fn definitions() -> String {
    let mut h = String::new();
    for t in ["float", "vec2", "vec3"] {
        h.push_str(&format!(
            "vec2 effectc_queryLod({t} texels, int levels) {{ float rho = max(length(dFdx(texels)), length(dFdy(texels))); \
             float lambda = log2(rho); return vec2(clamp(lambda, 0.0, float(levels - 1)), lambda); }}\n"
        ));
    }
    h
}
