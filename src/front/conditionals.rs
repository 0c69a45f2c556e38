//! Conditional compilation resolved the way the driver would, for the file's own `#version`.
//!
//! naga's preprocessor knows no `__VERSION__`, no `GL_ES` or extension macros, and stumbles
//! on directives in the middle of a declaration (`#ifdef X` / `layout(location = 5)` /
//! `#endif` / `uniform vec4 c;`); glsl-lang's and naga's would also see the version effectc
//! rewrites to (4.50) rather than the user's. So `#if`/`#ifdef`/`#ifndef`/`#elif`/`#else`/
//! `#endif` are evaluated here, with the macros a GL implementation predefines (those
//! glslangValidator predefines), and the text is blanked byte for byte: the conditional
//! directives and every line of an inactive group become spaces, keeping all offsets.
//! `#define`/`#undef` stay for the parsers to expand; they are tracked to evaluate `#if`.
//!
//! An object-like macro that renames a type effectc's rewrite writes itself
//! (`#define texture2D texture`, to call the 1.x function by its new name) would also rename
//! the generated `texture2D` declarations; such a macro is applied here (same length,
//! padded) and its `#define` blanked.
//!
//! Text this cannot follow (an unbalanced `#endif`, a function-like macro in `#if`) is
//! returned unchanged, and the parsers report on it as before.

use std::collections::HashMap;

use crate::front::version::{Profile, Version};

/// `(line range incl. its end, file name, name span)` of every `#include` line outside comments.
pub fn include_directives(text: &str) -> Vec<(std::ops::Range<usize>, String, std::ops::Range<usize>)> {
    let clean = crate::front::version::blank_comments(text);
    let mut found = Vec::new();
    let mut start = 0;
    for line in clean.split_inclusive(|b| *b == b'\n') {
        let l = String::from_utf8_lossy(line);
        let t = l.trim_start();
        if let Some(rest) = t.strip_prefix('#').map(str::trim_start).and_then(|r| r.strip_prefix("include")) {
            let r = rest.trim_start();
            let close = match r.chars().next() {
                Some('"') => Some('"'),
                Some('<') => Some('>'),
                _ => None,
            };
            if let Some(n) = close.and_then(|c| r[1..].find(c)) {
                let name_at = start + (l.len() - r.len()) + 1;
                found.push((start..start + line.len(), r[1..1 + n].to_string(), name_at..name_at + n));
            }
        }
        start += line.len();
    }
    found
}

/// The name an object-like macro gives, when its replacement list (`after`: the text after
/// the macro's name) is one identifier (`#define texture2D texture2DRect`).
pub fn renamed_to(after: &str) -> Option<&str> {
    let body = after.trim();
    let identifier = !body.is_empty() && body.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_');
    (!after.starts_with('(') && identifier).then_some(body)
}

/// `(macro name, body span)` of every `#define` line (the body starts after the name, or
/// after the parameter list's name for function-like macros).
pub fn define_lines(text: &str) -> Vec<(String, std::ops::Range<usize>)> {
    let is_ident = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
    let mut out = Vec::new();
    let mut line_start = 0;
    for line in text.split_inclusive('\n') {
        if let Some(rest) = line.trim_start().strip_prefix('#').map(str::trim_start).and_then(|r| r.strip_prefix("define")) {
            let rest_trim = rest.trim_start();
            let name_len = rest_trim.bytes().take_while(|b| is_ident(*b)).count();
            let body = line.len() - rest_trim.len() + name_len;
            out.push((rest_trim[..name_len].to_string(), line_start + body..line_start + line.len()));
        }
        line_start += line.len();
    }
    out
}

/// Type names the rewrite generates (Vulkan GLSL's separate textures and samplers).
const GENERATED_TYPES: &[&str] = &[
    "texture1D",
    "texture2D",
    "texture3D",
    "textureCube",
    "texture2DRect",
    "texture1DArray",
    "texture2DArray",
    "textureCubeArray",
    "texture2DMS",
    "texture2DMSArray",
    "itexture2D",
    "utexture2D",
    "itexture3D",
    "utexture3D",
    "itexture2DArray",
    "utexture2DArray",
    "sampler",
    "samplerShadow",
];

/// Extension macros a desktop GL implementation defines (glslangValidator's preamble).
const DESKTOP_EXTENSIONS: &[&str] = &[
    "GL_ARB_texture_rectangle",
    "GL_ARB_shading_language_420pack",
    "GL_ARB_texture_gather",
    "GL_ARB_gpu_shader5",
    "GL_ARB_separate_shader_objects",
    "GL_ARB_compute_shader",
    "GL_ARB_tessellation_shader",
    "GL_ARB_enhanced_layouts",
    "GL_ARB_texture_cube_map_array",
    "GL_ARB_texture_multisample",
    "GL_ARB_shader_texture_lod",
    "GL_ARB_explicit_attrib_location",
    "GL_ARB_explicit_uniform_location",
    "GL_ARB_shader_image_load_store",
    "GL_ARB_shader_atomic_counters",
    "GL_ARB_shader_draw_parameters",
    "GL_ARB_shader_group_vote",
    "GL_ARB_derivative_control",
    "GL_ARB_shader_texture_image_samples",
    "GL_ARB_viewport_array",
    "GL_ARB_gpu_shader_int64",
    "GL_ARB_gpu_shader_fp64",
    "GL_ARB_shader_ballot",
    "GL_ARB_sparse_texture2",
    "GL_ARB_sparse_texture_clamp",
    "GL_ARB_shader_stencil_export",
    "GL_ARB_sample_shading",
    "GL_ARB_shader_image_size",
    "GL_ARB_shading_language_packing",
    "GL_ARB_cull_distance",
    "GL_ARB_post_depth_coverage",
    "GL_ARB_fragment_shader_interlock",
    "GL_ARB_uniform_buffer_object",
    "GL_ARB_shader_bit_encoding",
    "GL_ARB_shader_storage_buffer_object",
    "GL_ARB_texture_query_lod",
    "GL_ARB_vertex_attrib_64bit",
    "GL_ARB_draw_instanced",
    "GL_ARB_fragment_coord_conventions",
    "GL_ARB_conservative_depth",
    "GL_NV_gpu_shader5",
    "GL_EXT_shader_image_load_formatted",
    "GL_EXT_post_depth_coverage",
    "GL_EXT_control_flow_attributes",
    "GL_EXT_nonuniform_qualifier",
    "GL_EXT_samplerless_texture_functions",
    "GL_EXT_scalar_block_layout",
    "GL_EXT_demote_to_helper_invocation",
    "GL_EXT_debug_printf",
    "GL_EXT_shader_16bit_storage",
    "GL_EXT_shader_8bit_storage",
    "GL_KHR_shader_subgroup_basic",
    "GL_KHR_shader_subgroup_vote",
    "GL_KHR_shader_subgroup_arithmetic",
    "GL_KHR_shader_subgroup_ballot",
];

/// Extension macros a GL ES implementation defines (glslangValidator's preamble, the common ones).
const ES_EXTENSIONS: &[&str] = &[
    "GL_FRAGMENT_PRECISION_HIGH",
    "GL_OES_texture_3D",
    "GL_OES_standard_derivatives",
    "GL_EXT_frag_depth",
    "GL_EXT_shader_texture_lod",
    "GL_EXT_shadow_samplers",
    "GL_OES_sample_variables",
    "GL_OES_shader_multisample_interpolation",
    "GL_EXT_geometry_shader",
    "GL_EXT_gpu_shader5",
    "GL_EXT_shader_io_blocks",
    "GL_EXT_tessellation_shader",
    "GL_EXT_texture_buffer",
    "GL_EXT_texture_cube_map_array",
    "GL_EXT_blend_func_extended",
];

/// Macro definitions: `Some(body)` for object-like macros, `None` for function-like ones.
type Macros = HashMap<String, Option<String>>;

/// The macros defined before the first line of a stage written for `version`.
fn predefined(version: &Version) -> Macros {
    let mut m = Macros::new();
    m.insert("__VERSION__".into(), Some(version.number.to_string()));
    m.insert("__LINE__".into(), Some("0".into()));
    m.insert("__FILE__".into(), Some("0".into()));
    if version.is_es() {
        m.insert("GL_ES".into(), Some("1".into()));
        for e in ES_EXTENSIONS {
            m.insert((*e).into(), Some("1".into()));
        }
    } else {
        for e in DESKTOP_EXTENSIONS {
            m.insert((*e).into(), Some("1".into()));
        }
        if version.number >= 150 {
            let profile = if version.profile == Profile::Compatibility { "GL_compatibility_profile" } else { "GL_core_profile" };
            m.insert(profile.into(), Some("1".into()));
        }
    }
    m
}

struct Group {
    /// Lines of this group are compiled.
    active: bool,
    /// Some branch of this `#if` chain was taken already.
    taken: bool,
    /// The enclosing group is active.
    parent: bool,
}

/// `text` with conditional compilation resolved (see the module doc); unchanged when the
/// directives cannot be followed. `clean` is `text` with comments blanked.
pub fn resolve(text: &str, clean: &[u8], version: &Version) -> String {
    resolve_inner(text, clean, version).unwrap_or_else(|| text.to_string())
}

fn resolve_inner(text: &str, clean: &[u8], version: &Version) -> Option<String> {
    if !clean.contains(&b'#') {
        return None;
    }
    let mut out = text.as_bytes().to_vec();
    let mut macros = predefined(version);
    let mut stack: Vec<Group> = Vec::new();
    let mut applied: Vec<(String, String)> = Vec::new();
    let mut changed = false;
    let mut start = 0;
    while start < clean.len() {
        // A logical line: physical lines joined by a trailing backslash.
        let mut end = start;
        loop {
            let nl = clean[end..].iter().position(|b| *b == b'\n').map(|i| end + i).unwrap_or(clean.len());
            let body_end = if nl > 0 && clean.get(nl - 1) == Some(&b'\r') { nl - 1 } else { nl };
            if body_end > end && clean[body_end - 1] == b'\\' && nl < clean.len() {
                end = nl + 1;
                continue;
            }
            end = nl;
            break;
        }
        // Continuations become spaces of the same length, so offsets in `line` are the text's.
        let line = String::from_utf8_lossy(&clean[start..end]).replace("\\\r\n", "   ").replace("\\\n", "  ");
        let active = stack.last().is_none_or(|g| g.active);
        let directive = line.trim_start().strip_prefix('#').map(str::trim_start);
        let (name, rest) = match directive {
            Some(d) => {
                let n = d.bytes().take_while(|b| b.is_ascii_alphabetic()).count();
                (&d[..n], d[n..].trim())
            }
            None => ("", ""),
        };
        let conditional = matches!(name, "if" | "ifdef" | "ifndef" | "elif" | "else" | "endif");
        match (directive.is_some(), name) {
            (true, "if" | "ifdef" | "ifndef") => {
                let cond = if !active {
                    false
                } else if name == "if" {
                    eval(rest, &macros)? != 0
                } else {
                    let word = rest.split(|c: char| !c.is_ascii_alphanumeric() && c != '_').next().unwrap_or("");
                    macros.contains_key(word) == (name == "ifdef")
                };
                stack.push(Group { active: cond, taken: cond, parent: active });
            }
            (true, "elif") => {
                let g = stack.last_mut()?;
                let cond = g.parent && !g.taken && eval(rest, &macros)? != 0;
                g.active = cond;
                g.taken |= cond;
            }
            (true, "else") => {
                let g = stack.last_mut()?;
                g.active = g.parent && !g.taken;
                g.taken = true;
            }
            (true, "endif") => {
                stack.pop()?;
            }
            (true, "define") if active => {
                let n = rest.bytes().take_while(|b| b.is_ascii_alphanumeric() || *b == b'_').count();
                let (macro_name, after) = rest.split_at(n);
                if after.starts_with('(') {
                    macros.insert(macro_name.to_string(), None);
                    if !applied.is_empty() {
                        let body_at = start + (after.as_ptr() as usize - line.as_ptr() as usize);
                        let body_end = body_at + after.len();
                        changed |= substitute(&clean[body_at..body_end], &mut out[body_at..body_end], &applied);
                    }
                } else {
                    let body = after.trim().to_string();
                    let renames_generated = GENERATED_TYPES.contains(&macro_name)
                        && !body.is_empty()
                        && body.len() <= macro_name.len()
                        && body.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_');
                    if renames_generated {
                        applied.push((macro_name.to_string(), body.clone()));
                        blank(&mut out[start..end]);
                        changed = true;
                    } else if !applied.is_empty() {
                        // A later macro's body uses a renamed type's name.
                        let body_at = start + (after.as_ptr() as usize - line.as_ptr() as usize);
                        let body_end = body_at + after.len();
                        changed |= substitute(&clean[body_at..body_end], &mut out[body_at..body_end], &applied);
                    }
                    macros.insert(macro_name.to_string(), Some(body));
                }
            }
            (true, "undef") if active => {
                let word = rest.split(|c: char| !c.is_ascii_alphanumeric() && c != '_').next().unwrap_or("");
                macros.remove(word);
                applied.retain(|(n, _)| n != word);
            }
            (false, _) if active && !applied.is_empty() => {
                changed |= substitute(&clean[start..end], &mut out[start..end], &applied);
            }
            _ => {}
        }
        if conditional || !active {
            blank(&mut out[start..end]);
            changed = true;
        }
        start = end + 1;
    }
    if !stack.is_empty() || !changed {
        return None;
    }
    String::from_utf8(out).ok()
}

fn blank(bytes: &mut [u8]) {
    for b in bytes {
        if *b != b'\n' && *b != b'\r' {
            *b = b' ';
        }
    }
}

/// Replaces whole-word uses of the applied macros in one code line, padded to length.
fn substitute(clean: &[u8], out: &mut [u8], applied: &[(String, String)]) -> bool {
    let mut changed = false;
    let mut i = 0;
    while i < clean.len() {
        if clean[i].is_ascii_alphabetic() || clean[i] == b'_' {
            let s = i;
            while i < clean.len() && (clean[i].is_ascii_alphanumeric() || clean[i] == b'_') {
                i += 1;
            }
            let word = std::str::from_utf8(&clean[s..i]).unwrap_or("");
            if let Some((name, body)) = applied.iter().find(|(n, _)| n == word) {
                let padded = format!("{body:<width$}", width = name.len());
                out[s..i].copy_from_slice(padded.as_bytes());
                changed = true;
            }
        } else if clean[i].is_ascii_digit() {
            while i < clean.len() && (clean[i].is_ascii_alphanumeric() || clean[i] == b'.') {
                i += 1;
            }
        } else {
            i += 1;
        }
    }
    changed
}

#[derive(Debug, Clone, PartialEq)]
enum Tok {
    Num(i64),
    Ident(String),
    Op(&'static str),
}

const OPS: &[&str] =
    &["||", "&&", "==", "!=", "<=", ">=", "<<", ">>", "(", ")", "!", "~", "-", "+", "*", "/", "%", "<", ">", "&", "^", "|", "?", ":", ","];

fn tokenize(expr: &str) -> Option<Vec<Tok>> {
    let b = expr.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        if c.is_ascii_whitespace() {
            i += 1;
        } else if c.is_ascii_digit() {
            let s = i;
            while i < b.len() && (b[i].is_ascii_alphanumeric()) {
                i += 1;
            }
            let lit = expr[s..i].trim_end_matches(['u', 'U', 'l', 'L']);
            let v = if let Some(h) = lit.strip_prefix("0x").or_else(|| lit.strip_prefix("0X")) {
                i64::from_str_radix(h, 16).ok()?
            } else if lit.len() > 1 && lit.starts_with('0') {
                i64::from_str_radix(&lit[1..], 8).ok()?
            } else {
                lit.parse().ok()?
            };
            out.push(Tok::Num(v));
        } else if c.is_ascii_alphabetic() || c == b'_' {
            let s = i;
            while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
                i += 1;
            }
            out.push(Tok::Ident(expr[s..i].to_string()));
        } else {
            let op = OPS.iter().find(|op| expr[i..].starts_with(**op))?;
            out.push(Tok::Op(op));
            i += op.len();
        }
    }
    Some(out)
}

/// Expands `defined` and object-like macros; unknown identifiers are 0 (as in C).
fn expand(tokens: Vec<Tok>, macros: &Macros, depth: u32) -> Option<Vec<Tok>> {
    if depth > 32 {
        return None;
    }
    let mut out = Vec::new();
    let mut it = tokens.into_iter().peekable();
    while let Some(t) = it.next() {
        match t {
            Tok::Ident(w) if w == "defined" => {
                let paren = it.peek() == Some(&Tok::Op("("));
                if paren {
                    it.next();
                }
                let Some(Tok::Ident(name)) = it.next() else { return None };
                if paren && it.next() != Some(Tok::Op(")")) {
                    return None;
                }
                out.push(Tok::Num(macros.contains_key(&name) as i64));
            }
            Tok::Ident(w) => match macros.get(&w) {
                Some(Some(body)) => out.extend(expand(tokenize(body)?, macros, depth + 1)?),
                Some(None) => return None, // a function-like macro: not followed here
                None => out.push(Tok::Num(0)),
            },
            t => out.push(t),
        }
    }
    Some(out)
}

/// Evaluates a `#if` expression.
fn eval(expr: &str, macros: &Macros) -> Option<i64> {
    let tokens = expand(tokenize(expr)?, macros, 0)?;
    let mut p = Parser { t: tokens, i: 0 };
    let v = p.ternary()?;
    (p.i == p.t.len()).then_some(v)
}

struct Parser {
    t: Vec<Tok>,
    i: usize,
}

impl Parser {
    fn peek_op(&self) -> Option<&'static str> {
        match self.t.get(self.i) {
            Some(Tok::Op(o)) => Some(o),
            _ => None,
        }
    }

    fn ternary(&mut self) -> Option<i64> {
        let c = self.binary(0)?;
        if self.peek_op() == Some("?") {
            self.i += 1;
            let a = self.ternary()?;
            if self.peek_op() != Some(":") {
                return None;
            }
            self.i += 1;
            let b = self.ternary()?;
            return Some(if c != 0 { a } else { b });
        }
        Some(c)
    }

    fn binary(&mut self, min: u8) -> Option<i64> {
        let mut lhs = self.unary()?;
        while let Some(op) = self.peek_op() {
            let prec = match op {
                "||" => 1,
                "&&" => 2,
                "|" => 3,
                "^" => 4,
                "&" => 5,
                "==" | "!=" => 6,
                "<" | ">" | "<=" | ">=" => 7,
                "<<" | ">>" => 8,
                "+" | "-" => 9,
                "*" | "/" | "%" => 10,
                _ => break,
            };
            if prec < min {
                break;
            }
            self.i += 1;
            let rhs = self.binary(prec + 1)?;
            lhs = match op {
                "||" => ((lhs != 0) || (rhs != 0)) as i64,
                "&&" => ((lhs != 0) && (rhs != 0)) as i64,
                "|" => lhs | rhs,
                "^" => lhs ^ rhs,
                "&" => lhs & rhs,
                "==" => (lhs == rhs) as i64,
                "!=" => (lhs != rhs) as i64,
                "<" => (lhs < rhs) as i64,
                ">" => (lhs > rhs) as i64,
                "<=" => (lhs <= rhs) as i64,
                ">=" => (lhs >= rhs) as i64,
                "<<" => lhs.checked_shl(u32::try_from(rhs).ok()?)?,
                ">>" => lhs.checked_shr(u32::try_from(rhs).ok()?)?,
                "+" => lhs.wrapping_add(rhs),
                "-" => lhs.wrapping_sub(rhs),
                "*" => lhs.wrapping_mul(rhs),
                "/" => lhs.checked_div(rhs)?,
                _ => lhs.checked_rem(rhs)?,
            };
        }
        Some(lhs)
    }

    fn unary(&mut self) -> Option<i64> {
        match self.t.get(self.i).cloned()? {
            Tok::Num(v) => {
                self.i += 1;
                Some(v)
            }
            Tok::Op("(") => {
                self.i += 1;
                let v = self.ternary()?;
                if self.peek_op() != Some(")") {
                    return None;
                }
                self.i += 1;
                Some(v)
            }
            Tok::Op(op @ ("!" | "~" | "-" | "+")) => {
                self.i += 1;
                let v = self.unary()?;
                Some(match op {
                    "!" => (v == 0) as i64,
                    "~" => !v,
                    "-" => v.wrapping_neg(),
                    _ => v,
                })
            }
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::front::version::parse_version;

    fn run(src: &str) -> String {
        let v = parse_version(src).unwrap();
        let out = resolve(src, src.as_bytes(), &v);
        assert_eq!(out.len(), src.len(), "same length");
        out
    }

    #[test]
    fn version_and_profile_macros_choose_the_branch() {
        let src = "#version 150\n#if (!defined(GL_ES) && __VERSION__ >= 130) || (defined(GL_ES) && __VERSION__ >= 300)\n#define NEW\n#endif\n#ifndef NEW\n#define in attribute\n#else\nin vec3 p;\n#endif\n";
        let out = run(src);
        assert!(out.contains("#define NEW"));
        assert!(!out.contains("attribute"));
        assert!(out.contains("in vec3 p;"));
        assert!(!out.contains("#if") && !out.contains("#endif") && !out.contains("#else"));
    }

    #[test]
    fn directives_inside_a_declaration() {
        let src = "#version 150\n#ifdef GL_ARB_explicit_uniform_location\nlayout(location = 5)\n#endif\nuniform vec4 c;\n";
        let out = run(src);
        assert!(out.contains("layout(location = 5)\n"));
        assert!(out.ends_with("uniform vec4 c;\n"));
    }

    #[test]
    fn elif_chains_and_nesting() {
        let src = "#version 330\n#define Q 2\n#if Q == 1\na\n#elif Q == 2\n#if 0\nb\n#else\nc\n#endif\n#elif Q == 2\nd\n#else\ne\n#endif\n";
        let out = run(src);
        let kept: Vec<&str> = out.split_whitespace().collect();
        assert_eq!(kept, ["#version", "330", "#define", "Q", "2", "c"]);
    }

    #[test]
    fn empty_macros_and_arithmetic() {
        let src = "#version 330\n#define DC\n#if DC+0 > 1\nx\n#elif (3 << 2) % 5 == 2 && -1 < 0\ny\n#endif\n";
        let out = run(src);
        assert!(!out.contains('x') && out.contains('y'));
    }

    #[test]
    fn type_renaming_macros_are_applied() {
        let src = "#version 130\n#define texture2D texture\n#define T(s) texture2D(s, vec2(0))\nvec4 f(sampler2D s) { return texture2D(s, vec2(0)); }\n";
        let out = run(src);
        assert!(!out.contains("#define texture2D"));
        assert!(out.contains("#define T(s) texture  (s, vec2(0))"), "{out}");
        assert!(out.contains("return texture  (s, vec2(0));"));
    }

    #[test]
    fn what_it_cannot_follow_is_left_alone() {
        for src in [
            "#version 330\n#endif\n",
            "#version 330\n#if 1\n",
            "#version 330\n#define F(x) x\n#if F(1)\n#endif\n",
            "#version 330\nvoid main(){}\n",
        ] {
            assert_eq!(run(src), src);
        }
    }
}
