//! One stage through glsl-lang: the text prepared for it (`#version`, conditionals,
//! renamed keywords, lexical masks), its syntax errors in the user's terms, and whether it
//! is Vulkan GLSL.

use std::collections::HashMap;
use std::ops::Range;

use glsl_lang::ast;
use glsl_lang::parse::DefaultParse;

use crate::config::TargetEnv;
use crate::diag::{Code, Diagnostic, FileId};
use crate::front::syntax::collect::Collector;
use crate::front::syntax::model::{Referent, StageSyntax};
use crate::front::syntax::types::Storage;
use crate::front::version::{self, Renames};
use crate::stage::StageKind;

/// The stage enables an extension whose name holds one of `names` (an `#extension` line
/// not set to `disable`).
fn enables(text: &str, names: &[&str]) -> bool {
    text.lines().any(|l| {
        let t = l.trim_start();
        t.starts_with('#') && t[1..].trim_start().starts_with("extension") && names.iter().any(|n| t.contains(n)) && !t.contains("disable")
    })
}

/// The stage enables 64-bit floating-point types by extension (`GL_ARB_gpu_shader_fp64`,
/// `GL_ARB_vertex_attrib_64bit`).
fn enables_fp64(text: &str) -> bool {
    enables(text, &["GL_ARB_gpu_shader_fp64", "GL_ARB_vertex_attrib_64bit"])
}

/// Parses one stage. Errors are syntax diagnostics at the user's spans.
/// `env` forces the dialect, else the text tells it ([`TargetEnv::Auto`]).
pub fn analyse(file: FileId, original: &str, stage: StageKind, env: TargetEnv) -> Result<StageSyntax, Vec<Diagnostic>> {
    let version = match version::parse_version(original) {
        Ok(v) => v,
        Err((msg, span)) => {
            return Err(vec![Diagnostic::new(Code::BadVersion, msg)
                .at(file, span, "in this `#version` directive")
                .with_note("effectc accepts GLSL 1.10–4.60 (core or compatibility) and ES 1.00/3.00")])
        }
    };
    // Unacted pragmas blanked: quoted text (`#pragma parameter x "// A //" 0 1`) swallowed the stage.
    let quiet = crate::front::lexical::blank_line_directives(&crate::front::lexical::quiet_pragmas(original)).into_owned();
    let unextended = version::blank_extensions(&quiet);
    let resolved = crate::front::conditionals::resolve(&unextended, &version::blank_comments(&unextended), &version);
    if let Some(span) = compiled_include(&resolved) {
        return Err(vec![Diagnostic::new(Code::IncludeUnresolved, format!("cannot read included file `{}`", &original[span.clone()]))
            .at(file, span, "not found relative to the including file")
            .with_note("`#include` names a file relative to the file that includes it")]);
    }
    // Vulkan GLSL's types (`texture2D`, `sampler`, `subpassInput`) are keywords there only.
    let target_vulkan = match env {
        TargetEnv::Auto => vulkan_source(original),
        TargetEnv::OpenGl => false,
        TargetEnv::Vulkan(_) => true,
    };
    let (text, mut renames) = version::rename_new_keywords(&resolved, &version, original, target_vulkan);
    let masked = crate::front::lexical::mask(&text, &version::blank_comments(&text));
    let mut text = masked.for_parser;
    let opts = glsl_lang::parse::ParseOptions { default_version: 110, target_vulkan, ..Default::default() };
    if !opts.target_vulkan && version.number < 400 && !version.is_es() && enables_fp64(original) {
        // glsl-lang knows `double`/`dvecN`/`dmatN` from `#version 400` only (extensions are
        // blanked for it); GL_ARB_gpu_shader_fp64 brings them to 1.50. The identifiers that
        // are keywords in newer versions are already renamed, so the parse is the same.
        if let Some(span) = version.number_span.clone() {
            text.replace_range(span, "400");
        }
    }
    if (opts.target_vulkan && version.number >= 400) || (version.is_es() && version.number >= 310) {
        // glsl-lang has Vulkan's types (`subpassInput`) from `#version 460` only (Vulkan GLSL
        // from 4.50 and ES 3.10), and gates types by the number alone (ES 3.10's `atomic_uint`,
        // `image2D`). Same-length digits and a blanked `es` keep every offset.
        if let Some(span) = version.number_span.clone() {
            text.replace_range(span, "460");
        }
        if let Some(span) = version.profile_span.clone().filter(|_| version.is_es()) {
            text.replace_range(span.clone(), &" ".repeat(span.len()));
        }
    }
    let parse = |text: &str| {
        // Comments blanked (same length): glsl-lang's lexer stops with "invalid token" on
        // some (`/**` … `**/` banners, legal C comments).
        let text = String::from_utf8(version::blank_comments(text)).unwrap_or_else(|_| text.to_string());
        std::panic::catch_unwind(|| {
            ast::TranslationUnit::parse_with_options(&text, &opts).map(|(tu, _, _)| tu).map_err(|e| {
                let pos = e.pos();
                let start = usize::from(pos.start());
                let end = usize::from(pos.end());
                (trim_expected(&e.inner().to_string()), start..end)
            })
        })
    };
    let mut parsed = parse(text.as_str());
    // glsl-lang's lexer takes a struct's name for a type everywhere, but GLSL lets a local
    // variable hide it (`float Attenuation = …;` beside `struct Attenuation`). Rename the
    // local, from its declaration to the end of its block, and parse again.
    for _ in 0..16 {
        let Ok(Err((msg, span))) = &parsed else { break };
        let Some(hidden) = rename_struct_hiding_local(&text, msg, span.start, &mut renames) else { break };
        text = hidden;
        parsed = parse(text.as_str());
    }
    let tu = match parsed {
        Ok(Ok(tu)) => tu,
        Ok(Err((msg, span))) => {
            let span = clamp(span, original);
            return Err(vec![Diagnostic::new(Code::SyntaxError, format!("syntax error: {msg}")).at(
                file,
                span,
                "the GLSL parser stopped here",
            )]);
        }
        Err(_) => return Err(vec![Diagnostic::new(Code::SyntaxError, "syntax error: the GLSL parser failed on this file").in_file(file)]),
    };
    let mut syntax = StageSyntax {
        file,
        stage,
        gpu_shader5: enables(original, &["_gpu_shader5"]),
        version,
        renames,
        text: crate::front::lexical::restored(&text, &masked.restore),
        unsupported: masked.unsupported,
        per_vertex: masked.per_vertex,
        swizzles: Vec::new(),
        globals: Vec::new(),
        structs: Vec::new(),
        functions: Vec::new(),
        uses: Vec::new(),
        calls: Vec::new(),
        precision_statements: Vec::new(),
        first_function: None,
        int_consts: HashMap::new(),
        has_main: false,
        main_body: None,
        main_returns: Vec::new(),
        defaults: Vec::new(),
        unsized_sizes: Vec::new(),
        constant_sizes: Vec::new(),
        constructor_conditions: Vec::new(),
        vulkan: false,
        lazy_logic: Vec::new(),
        do_while_continue: Vec::new(),
        global_index: HashMap::new(),
        parameters: crate::front::parameters::parameters(original),
    };
    Collector::run(&mut syntax, &tu);
    size_globals_by_initializer(&mut syntax);
    syntax.index_globals();
    syntax.vulkan = matches!(env, TargetEnv::Vulkan(_)) || (env == TargetEnv::Auto && looks_like_vulkan(&syntax, original));
    Ok(syntax)
}

/// For a parse error on a struct's name used as a variable at `at`, the text with that
/// name renamed (same length) from `at` to the end of the enclosing `{ … }` block. One
/// name is renamed to one new name however many blocks hide it; a struct member named so
/// (`struct camera { ray ray; }`) is renamed with every field selection of that name
/// (`cam.ray`), which no type name can be.
fn rename_struct_hiding_local(text: &str, msg: &str, at: usize, renames: &mut Renames) -> Option<String> {
    let name = msg.strip_prefix("unexpected type name `")?.split('`').next()?;
    if !text.get(at..)?.starts_with(name) || name.len() < 2 {
        return None;
    }
    let is_ident = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
    let declared_struct = text
        .match_indices("struct")
        .any(|(i, _)| text[i + 6..].trim_start().strip_prefix(name).is_some_and(|r| !r.bytes().next().is_some_and(is_ident)));
    if !declared_struct {
        return None;
    }
    // The local's scope: from the brace that opens the block it is declared in to the one
    // that closes it.
    let bytes = text.as_bytes();
    let (mut depth, mut end) = (0i32, text.len());
    for (i, &b) in bytes.iter().enumerate().skip(at) {
        match b {
            b'{' => depth += 1,
            b'}' if depth == 0 => {
                end = i;
                break;
            }
            b'}' => depth -= 1,
            _ => {}
        }
    }
    let (mut depth, mut open) = (0i32, None);
    for i in (0..at).rev() {
        match bytes[i] {
            b'}' => depth += 1,
            b'{' if depth == 0 => {
                open = Some(i);
                break;
            }
            b'{' => depth -= 1,
            _ => {}
        }
    }
    let member = open.is_some_and(|o| opens_struct_body(&text[..o]));
    let known = renames.to_original.iter().find(|(_, original)| original.as_str() == name).map(|(new, _)| new.clone());
    let new = known.or_else(|| {
        (0..100)
            .map(|k| format!("{}{}", &name[..name.len() - 1], (b'a' + (k % 26) as u8) as char))
            .find(|c| c != name && !text.contains(c.as_str()))
    })?;
    let mut out = text.as_bytes().to_vec();
    let mut i = 0;
    while let Some(off) = text[i..].find(name) {
        let s = i + off;
        let e = s + name.len();
        i = e;
        let whole = (s == 0 || !is_ident(bytes[s - 1])) && (e >= bytes.len() || !is_ident(bytes[e]));
        let selected = text[..s].trim_end().ends_with('.');
        if whole && ((at <= s && s < end) || (member && selected)) {
            out[s..e].copy_from_slice(new.as_bytes());
        }
    }
    renames.to_original.insert(new, name.to_string());
    String::from_utf8(out).ok()
}

/// Whether `before` (the text up to a `{`) ends with `struct` and an optional name: the
/// brace opens a struct's member list.
fn opens_struct_body(before: &str) -> bool {
    let head = before.trim_end();
    let head = head.trim_end_matches(|c: char| c.is_ascii_alphanumeric() || c == '_').trim_end();
    head.ends_with("struct") && !head[..head.len() - 6].ends_with(|c: char| c.is_ascii_alphanumeric() || c == '_')
}

/// glsl-lang lists every token it would accept; keep the message readable.
fn trim_expected(msg: &str) -> String {
    let Some(at) = msg.find(", expected ") else { return msg.to_string() };
    let (head, list) = msg.split_at(at);
    let items: Vec<&str> = list[", expected ".len()..].split(", ").collect();
    if items.len() <= 6 {
        return msg.to_string();
    }
    let mut short: Vec<&str> =
        items.iter().copied().filter(|i| !i.contains("texture") && !i.contains("subpass") && !i.contains("sampler")).take(6).collect();
    if short.is_empty() {
        short = items[..6].to_vec();
    }
    format!("{head}, expected {} …", short.join(", "))
}

fn clamp(span: Range<usize>, text: &str) -> Range<usize> {
    let start = span.start.min(text.len());
    let end = span.end.clamp(start, text.len());
    if start == end && start < text.len() {
        // Point at the offending character rather than nothing.
        let next = text[start..].chars().next().map_or(1, char::len_utf8);
        start..start + next
    } else {
        start..end
    }
}

/// The file name of an `#include` left in the compiled text (one `includes` could not read).
fn compiled_include(text: &str) -> Option<Range<usize>> {
    crate::front::conditionals::include_directives(text).into_iter().next().map(|(_, _, name)| name)
}

/// Before parsing: does the text use what only Vulkan GLSL has (descriptor sets, push
/// constants, specialization constants, subpass inputs, separate texture and sampler
/// uniforms, `gl_VertexIndex`/`gl_InstanceIndex`, extensions glslang compiles for SPIR-V
/// only: ray tracing and queries, mesh shading, buffer references)? Comments do not count.
pub(crate) fn vulkan_source(text: &str) -> bool {
    // Comments say anything ("a lookup with the uniform sampler"): only code counts.
    let code = crate::front::version::blank_comments(text);
    let code = String::from_utf8_lossy(&code);
    let squeezed: String = code.split_whitespace().collect::<Vec<_>>().join(" ");
    let words: Vec<&str> = squeezed.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).filter(|w| !w.is_empty()).collect();
    squeezed.contains("push_constant")
        || squeezed.contains("input_attachment_index")
        || squeezed.contains("GL_KHR_vulkan_glsl")
        // Extensions glslang compiles for SPIR-V only.
        || words.iter().any(|w| matches!(*w, "GL_EXT_ray_tracing" | "GL_EXT_mesh_shader" | "GL_EXT_buffer_reference" | "GL_EXT_ray_query"))
        || words
            .iter()
            .any(|w| matches!(*w, "gl_VertexIndex" | "gl_InstanceIndex") || w.trim_start_matches(['i', 'u']).starts_with("subpassInput"))
        || words.windows(2).any(|w| w[0] == "uniform" && vulkan_only_uniform_type(w[1]))
        || squeezed.split("layout").skip(1).any(|l| {
            let inside = l.trim_start().strip_prefix('(').and_then(|r| r.split(')').next()).unwrap_or("");
            inside.split(',').any(|item| {
                let key = item.trim().split(['=', ' ']).next().unwrap_or("");
                // Layouts glslang allows only in Vulkan GLSL.
                matches!(
                    key,
                    "set" | "constant_id" | "local_size_x_id" | "local_size_y_id" | "local_size_z_id" | "scalar" | "buffer_reference" | "shaderRecordEXT"
                )
            })
        })
}

/// Whether `ty` is a uniform type only Vulkan GLSL has: a sampler on its own (`sampler`,
/// `samplerShadow`) or a texture without one (`texture2D`, `utexture2DMS`, `textureCubeArray`).
fn vulkan_only_uniform_type(ty: &str) -> bool {
    let texture = ty.trim_start_matches(['i', 'u']).strip_prefix("texture").is_some_and(|d| {
        let d = d.strip_suffix("Array").unwrap_or(d);
        matches!(d, "1D" | "2D" | "3D" | "Cube" | "2DRect" | "2DMS" | "Buffer")
    });
    texture || matches!(ty, "sampler" | "samplerShadow")
}

/// Vulkan GLSL shows itself by what only Vulkan has: in the declarations read, or in the
/// text as the reference compiler's dialect choice reads it ([`vulkan_source`]: a
/// specialization-constant workgroup size, an extension only SPIR-V has), so both agree.
fn looks_like_vulkan(s: &StageSyntax, original: &str) -> bool {
    let layout_vulkan = s
        .globals
        .iter()
        .any(|g| g.layout.iter().any(|(k, _)| matches!(k.as_str(), "set" | "push_constant" | "constant_id" | "input_attachment_index")));
    let separate = s.globals.iter().any(|g| g.storage == Storage::Uniform && vulkan_only_uniform_type(&g.ty.base));
    layout_vulkan
        || separate
        || s.uses.iter().any(|u| matches!(u.name.as_str(), "gl_VertexIndex" | "gl_InstanceIndex") && u.target == Referent::Unresolved)
        || vulkan_source(original)
}

/// A global `T name[] = T[](a, b, c)` (a uniform's initializer too) has its initializer's
/// size, for everything that reads its type (the shared uniform block above all).
fn size_globals_by_initializer(syntax: &mut StageSyntax) {
    let sizes = &syntax.unsized_sizes;
    for g in syntax.globals.iter_mut().filter(|g| g.ty.dims.first() == Some(&None) && g.initializer.is_some()) {
        if let Some((_, n)) = sizes.iter().find(|(span, _)| g.decl_span.start <= span.start && span.end <= g.decl_span.end) {
            g.ty.dims[0] = Some(*n);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Vulkan GLSL shows itself in code, not in comments: a GLSL 1.10 stage whose comment
    /// speaks of "the uniform sampler" is OpenGL GLSL (it was compiled as Vulkan GLSL and
    /// refused: "ES shaders for SPIR-V require version 310").
    #[test]
    fn vulkan_is_told_from_code_not_comments() {
        let gl = "uniform sampler2D t;\n// a lookup with the uniform sampler\nvec4 f() { return texture2D(t, vec2(0.0)); }\n";
        assert!(!vulkan_source(gl));
        let gl_block = "/* layout(set = 0) uniform sampler s; */ void main() {}\n";
        assert!(!vulkan_source(gl_block));
        assert!(vulkan_source("layout(set = 0, binding = 1) uniform sampler s;\n"));
        assert!(vulkan_source("layout(push_constant) uniform P { vec4 c; } p;\n"));
        // What Vulkan GLSL may hold without descriptor sets: the vertex and instance
        // index, specialization constants, separate integer and multisampled textures.
        assert!(vulkan_source("void main() { gl_Position = vec4(float(gl_VertexIndex)); }\n"));
        assert!(vulkan_source("layout(constant_id = 0) const int N = 4;\n"));
        assert!(vulkan_source("layout(binding = 1) uniform utexture2DMS t;\n"));
        assert!(!vulkan_source("uniform sampler2DMS t; int settings; // gl_VertexIndex\n"));
    }

    /// A member named like a struct (`ray ray;`) and a local hiding the struct take one new
    /// name, in the member list, in every field selection and in the local's block; the
    /// struct itself keeps its name.
    #[test]
    fn a_struct_s_name_on_a_member_and_a_local_is_renamed_alike() {
        let src = "#version 130\nstruct ray { vec3 o; };\nstruct camera { vec3 p; ray ray; };\ncamera cam;\nout vec4 c;\n\
                   void main() {\n    cam.ray.o = vec3(1.0);\n    ray ray = cam. ray;\n    c = vec4(ray.o, 1.0);\n}\n";
        let s = analyse(FileId(0), src, StageKind::Fragment, TargetEnv::Auto).map_err(|d| d[0].message.clone()).expect("parses");
        let new = s.renames.to_original.iter().find(|(_, o)| o.as_str() == "ray").map(|(n, _)| n.clone()).expect("renamed");
        assert_eq!(s.renames.to_original.len(), 1, "{:?}", s.renames.to_original);
        let expected = src
            .replace("ray ray;", &format!("ray {new};"))
            .replace("cam.ray.o", &format!("cam.{new}.o"))
            .replace("ray ray = cam. ray", &format!("ray {new} = cam. {new}"))
            .replace("ray.o, 1.0", &format!("{new}.o, 1.0"));
        assert_eq!(s.text, expected);
    }

    #[test]
    fn fp64_types_by_extension_are_read_below_400() {
        let src = "#version 150\n#extension GL_ARB_gpu_shader_fp64 : require\nuniform dvec4 arg0;\nflat out dvec3 a;\nvoid main() { a = arg0.xyz; }\n";
        let s = analyse(FileId(0), src, StageKind::Vertex, TargetEnv::Auto).expect("GLSL 1.50 with GL_ARB_gpu_shader_fp64 parses");
        let types: Vec<&str> = s.globals.iter().map(|g| g.ty.base.as_str()).collect();
        assert_eq!(types, ["dvec4", "dvec3"]);
        assert_eq!(s.version.number, 150, "the stage keeps its own version");
        let without = "#version 150\nuniform dvec4 arg0;\nvoid main() {}\n";
        assert!(analyse(FileId(0), without, StageKind::Vertex, TargetEnv::Auto).is_err(), "no extension, no doubles");
    }

    #[test]
    fn es_310_types_are_read_in_opengl_es() {
        // ES 3.10 has atomic counters and images (desktop GLSL's from 4.20) and memory
        // qualifiers; glsl-lang gates them by the version number alone. (The desktop
        // keywords it then knows, `patch`, `sample`, `subroutine`, `precise`, ES reserves.)
        let src = "#version 310 es\nprecision highp float;\nlayout(binding = 0, offset = 0) uniform atomic_uint shaded;\n\
                   layout(binding = 1, rgba8) uniform readonly highp image2D picture;\nlayout(location = 0) out vec4 c;\n\
                   void main() { uint order = atomicCounterIncrement(shaded); c = imageLoad(picture, ivec2(0)) * float(order); }\n";
        let s = analyse(FileId(0), src, StageKind::Fragment, TargetEnv::OpenGl).map_err(|d| d[0].message.clone()).expect("parses");
        let types: Vec<&str> = s.globals.iter().map(|g| g.ty.base.as_str()).collect();
        assert_eq!(types, ["atomic_uint", "image2D", "vec4"]);
        assert!(s.version.is_es() && s.version.number == 310, "the stage keeps its own version");
    }

    #[test]
    fn unsized_arrays_are_sized_by_their_initializers_with_brackets_on_the_name_or_the_type() {
        // GLSL 1.20: `T[] x = T[](…)` (brackets on the type) is sized like `T x[] = T[](…)`.
        let src =
            "#version 120\nfloat[] g = float[](1.0, 2.0);\nvoid main() {\n    ivec4[] n = ivec4[](ivec4(0), ivec4(1), ivec4(2));\n    \
                   float k[] = float[](0.5, 0.25, 0.125, 1.0);\n    gl_FragColor = vec4(g[1], k[3], float(n[2].x), 1.0);\n}\n";
        let s = analyse(FileId(0), src, StageKind::Fragment, TargetEnv::Auto).map_err(|d| d[0].message.clone()).expect("parses");
        let mut sizes: Vec<u32> = s.unsized_sizes.iter().map(|(_, n)| *n).collect();
        sizes.sort();
        // Each declaration and each constructor: g (2, 2), n (3, 3), k (4, 4).
        assert_eq!(sizes, [2, 2, 3, 3, 4, 4]);
    }

    #[test]
    fn a_macro_naming_a_function_like_macro_invokes_it() {
        // `#define M2 CUNNY_M2` then `M2(…)`, at the top level and inside another macro's
        // arguments: C's rescanning (vendor/glsl-lang-pp/PATCHED.md).
        let src = "#version 330\n#define CUNNY_M2(a, b, c, d) mat2(a, b, c, d)\n#define M2 CUNNY_M2\n#define mul(v, m) ((m) * (v))\n\
                   out vec4 c;\nvoid main() { vec2 x = vec2(1.0); vec2 r = mul(x, M2(1.0, 2.0, 3.0, 4.0)) + M2 (1.0, 0.0, 0.0, 1.0) * x;\n\
                   c = vec4(r, 0.0, 1.0); }\n";
        let s = analyse(FileId(0), src, StageKind::Fragment, TargetEnv::Auto).map_err(|d| d[0].message.clone());
        assert!(s.expect("the alias is invoked").has_main);
    }

    #[test]
    fn a_sign_after_an_exponent_s_digits_is_an_operator() {
        // `1e2+n.y` is `1e2`, `+`, `n.y`; `0xE+1` is `0xE`, `+`, `1` (vendor/glsl-lang-pp/PATCHED.md).
        let src = "#version 330\nuniform vec2 n;\nout vec4 c;\n\
                   void main() { float h = fract(sin((n.x*1e2+n.y*1e4+1475.4526)*1e-4)*1e6); int k = 0xE+1; c = vec4(h, float(k), 1.5e+2-3.0, 1.0); }\n";
        let s = analyse(FileId(0), src, StageKind::Fragment, TargetEnv::Auto).map_err(|d| d[0].message.clone());
        assert!(s.expect("the numbers end before the sign").has_main);
    }

    #[test]
    fn comment_marks_in_a_pragma_s_quoted_text_hide_nothing() {
        let src = "#version 450\n#pragma parameter g \"// ANALOG /* //\" 0.0 0.0 1.0 1.0\nlayout(location = 0) out vec4 c;\nvoid main() { c = vec4(1.0); }\n";
        let s = analyse(FileId(0), src, StageKind::Fragment, TargetEnv::Auto).map_err(|d| d[0].message.clone());
        assert!(s.expect("parses").has_main);
    }
}
