//! `texture(s, p)` and `textureLod(s, p, lod)` on an integer sampler (`usampler2D`,
//! `isampler2DArray`, …; a uniform or a parameter), which naga and WGSL refuse (WebGPU samples float textures only):
//! GL never filters an integer texture (any other filter than `NEAREST` leaves it
//! incomplete, OpenGL 4.6 §8.17), so a lookup is the nearest texel of the level, which
//! `texelFetch` reads at `floor(p · size)` wrapped as `GL_REPEAT` (GL's and `render`'s
//! default wrap), an array layer at `round(p.layer)` (§8.14.2; GL clamps it to the layers,
//! the translation only at 0: naga's SPIR-V front reads an array's `textureSize` without
//! its layers).
//! `texture` reads the base level (a `NEAREST` minification filter has no mipmaps); the
//! level of `textureLod` is `round(lod)` clamped to the levels. Note N0112 names the
//! assumed wrap. Cube maps (no `texelFetch`) and sampler expressions effectc cannot type stay
//! as they are (N0102).

use crate::diag::{Code, Diagnostic};

use super::Ctx;

impl Ctx<'_> {
    /// Each `texture`/`textureLod` call on a named integer 1D, 2D or 3D sampler (arrays too)
    /// becomes a `texelFetch` at the nearest texel (after [`Ctx::calls`], whose edits of the
    /// call it replaces).
    pub(super) fn integer_lookups(&mut self) {
        let s = self.s;
        let text = &s.text;
        for c in &s.calls {
            let lod = match (c.name.as_str(), c.args.len()) {
                ("texture", 2 | 3) => false,
                ("textureLod", 3) => true,
                _ => continue,
            };
            if c.from_macro || s.functions.iter().any(|f| f.name == c.name) {
                continue;
            }
            // A uniform sampler (no array) or a sampler parameter, and its combined expression.
            let Some((base, s_text)) = self.first_arg_text(c) else { continue };
            if !(base.starts_with("isampler") || base.starts_with("usampler")) {
                continue;
            }
            let helper = match &base[1..] {
                "sampler1D" | "sampler2D" | "sampler3D" => "effectc_nearest",
                "sampler1DArray" | "sampler2DArray" => "effectc_nearest_layer",
                _ => continue,
            };
            let p_text = self.edits.text_within(text, c.args[1].clone());
            let level = if lod {
                let l = self.edits.text_within(text, c.args[2].clone());
                format!("clamp(int(round({l})), 0, textureQueryLevels({s_text}) - 1)")
            } else {
                "0".to_string()
            };
            // An array's size without its layers: naga's SPIR-V front reads `textureSize` of an
            // array as the size of one layer (its layers are not clamped here).
            let size = match helper {
                "effectc_nearest_layer" if base.ends_with("1DArray") => format!("textureSize({s_text}, {level}).x"),
                "effectc_nearest_layer" => format!("textureSize({s_text}, {level}).xy"),
                _ => format!("textureSize({s_text}, {level})"),
            };
            let written = format!("texelFetch({s_text}, {helper}({p_text}, {size}), {level})");
            self.edits.take_out(text, c.span.clone());
            self.edits.insert(c.span.start, written);
            if !self.polyfills.contains(&"integer_lookups") {
                self.polyfills.push("integer_lookups");
                self.diags.push(
                    Diagnostic::new(
                        Code::IntegerTextureFetched,
                        format!(
                            "`{}` of integer sampler `{}` reads the nearest texel, wrapping as GL_REPEAT",
                            c.name,
                            s.original_name(c.first_arg_name.as_deref().unwrap_or_default())
                        ),
                    )
                    .at(s.file, c.span.clone(), "written as `texelFetch`")
                    .with_note("WebGPU samples float textures only; GL reads an integer texture unfiltered, so the lookup is the texel at floor(p × size), the layer at round(p.layer)")
                    .with_help("a sampler set to GL_CLAMP_TO_EDGE or GL_MIRRORED_REPEAT reads other texels outside [0, 1]: keep the coordinates inside"),
                );
            }
        }
    }
}

/// The helpers: texel coordinates of the nearest texel, wrapped (`GL_REPEAT`: floor(p · size)
/// mod size, which is floor(fract(p) · size); no `%`, whose signed form naga's SPIR-V front
/// lowers through 64-bit integers), for 1, 2 and 3 coordinates; an array's layer rounded and
/// kept at 0 or above (above the last layer, WebGPU's bounds checks decide; GL clamps).
pub(super) fn definitions() -> String {
    let mut h = String::new();
    for (p, i) in [("float", "int"), ("vec2", "ivec2"), ("vec3", "ivec3")] {
        h.push_str(&format!("{i} effectc_nearest({p} p, {i} size) {{ return min({i}(floor(fract(p) * {p}(size))), size - 1); }}\n"));
    }
    h.push_str(
        "ivec2 effectc_nearest_layer(vec2 p, int size) { return ivec2(effectc_nearest(p.x, size), max(int(floor(p.y + 0.5)), 0)); }\n",
    );
    h.push_str(
        "ivec3 effectc_nearest_layer(vec3 p, ivec2 size) { return ivec3(effectc_nearest(p.xy, size), max(int(floor(p.z + 0.5)), 0)); }\n",
    );
    h
}
