//! Same-length masks over a stage's text for constructs glsl-lang cannot lex or parse.
//!
//! Legal GLSL that glsl-lang's grammar lacks is replaced, byte for byte, by text it takes,
//! so every span stays the user's:
//! - hex, octal and decimal literals above `INT_MAX` without a `u` suffix (`0xFFFFFFFF`,
//!   `2654435761`: an `int` with that bit pattern): zeroed for glsl-lang, put back for naga,
//!   which reads them (a decimal one as the same bits in hex, same length);
//! - the unsigned texture types (`utexture2D`; glsl-lang's grammar lacks them): the signed
//!   ones for glsl-lang, put back for naga;
//! - `debugPrintfEXT("…", …)` calls (GL_EXT_debug_printf; glsl-lang has no string
//!   literals): blanked for both parsers, they compute nothing;
//! - explicit arithmetic types (`float32_t`, `u8vec4`, `uint64_t`, `f16mat3`;
//!   GL_EXT_shader_explicit_arithmetic_types): the 32-bit ones are exact aliases and become
//!   the core type for both parsers; 8/16/64-bit ones become the core type of their kind
//!   for glsl-lang, and naga (which has none of them) is not asked: the stage is limited;
//! - 64-bit integer literals (`1693ul`, `7L`; GL_ARB_gpu_shader_int64): a 32-bit zero of
//!   the same signedness for glsl-lang, put back for naga, and the stage is limited (naga
//!   has no 64-bit integers in GLSL);
//! - `buffer_reference` blocks (GL_EXT_buffer_reference), used as types: the block reads as
//!   a struct for glsl-lang, and the stage is limited (naga has no buffer references);
//! - ray-query types, `pervertexEXT` and multisampled storage images (`image2DMS`, which
//!   naga reads as a name): a core type (or nothing) for both parsers, and the stage is
//!   limited; `samplerExternalOES` (GL_OES_EGL_image_external): `sampler2D` for both;
//! - `nonuniformEXT` as a declaration's qualifier (GL_EXT_nonuniform_qualifier): blanked;
//! - `precise` (4.00), `coherent`, `restrict` (4.20), GL_KHR_memory_scope_semantics' scoped
//!   `…coherent` and `nonprivate`: blanked (WGSL's barriers make storage visible; no aliasing);
//! - control-flow attributes (`[[unroll]]`, `[[branch]]`; GL_EXT_control_flow_attributes),
//!   compiler hints: blanked for both parsers;
//! - precision qualifiers outside `precision` statements (`highp vec2 w` as a parameter or
//!   block member, which naga's parser rejects): blanked; desktop GL and WGSL ignore them.

use std::ops::Range;

/// The masked text and what naga cannot be given.
#[derive(Debug, Clone, Default)]
pub struct Masked {
    /// The text glsl-lang parses.
    pub for_parser: String,
    /// Spans to put back (with the original text) in what naga gets.
    pub restore: Vec<(Range<usize>, String)>,
    /// A construct naga has no form of, with its first span: the stage is checked for
    /// syntax and interface only.
    pub unsupported: Option<(String, Range<usize>)>,
    /// Offsets of `pervertexEXT` qualifiers (their inputs have one element per vertex).
    pub per_vertex: Vec<usize>,
}

/// Masks `text` (the stage after keyword renames; `clean` is the same text with comments blanked).
pub fn mask(text: &str, clean: &[u8]) -> Masked {
    let mut parser = text.as_bytes().to_vec();
    let mut restore = Vec::new();
    let mut per_vertex = Vec::new();
    let mut previous_word_precision = false;
    let mut unsupported: Option<(String, Range<usize>)> = None;
    let mut limit = |what: String, span: Range<usize>| {
        unsupported.get_or_insert((what, span));
    };
    let mut i = 0;
    while i < clean.len() {
        let c = clean[i];
        if c == b'#' && line_start(clean, i) {
            // Preprocessor lines keep their text (`#if X > 0xFFFF`), but for the explicit
            // arithmetic types of a `#define`'s body (`#define mem_i16 int16_t`), which the
            // parsers meet wherever the macro is used.
            let start = i;
            while i < clean.len() && clean[i] != b'\n' {
                i += 1;
            }
            if let Some((what, span)) = define_body_types(clean, start..i, &mut parser) {
                limit(what, span);
            }
            continue;
        }
        if c.is_ascii_alphabetic() || c == b'_' {
            let start = i;
            while i < clean.len() && (clean[i].is_ascii_alphanumeric() || clean[i] == b'_') {
                i += 1;
            }
            let word = std::str::from_utf8(&clean[start..i]).unwrap_or("");
            let after_precision = std::mem::replace(&mut previous_word_precision, word == "precision");
            if matches!(word, "coherent" | "restrict" | "devicecoherent" | "queuefamilycoherent" | "workgroupcoherent" | "nonprivate") {
                // Memory qualifiers naga does not take: `restrict` is an aliasing promise, `coherent`
                // (and GL_KHR_memory_scope_semantics' scoped ones) asks for what WGSL's barriers give.
                blank(&mut parser, start..i);
            } else if word == "nonuniformEXT" && clean[i..].iter().find(|b| !b.is_ascii_whitespace()) != Some(&b'(') {
                // GL_EXT_nonuniform_qualifier's qualifier on a declaration
                // (`nonuniformEXT uint index = …;`), which neither parser takes: it only
                // tells the compiler a value may differ between invocations, which changes
                // nothing WebGPU can express. The call form `nonuniformEXT(i)` is kept.
                blank(&mut parser, start..i);
            } else if word == "precise" {
                // GLSL 4.00's `precise` (still a keyword here: older versions had it
                // renamed) only forbids reassociating the computation; naga has no such
                // qualifier and WGSL evaluates as written.
                blank(&mut parser, start..i);
            } else if matches!(word, "highp" | "mediump" | "lowp") && !after_precision {
                // Precision qualifiers mean nothing on desktop and nothing to WGSL; naga's
                // parser rejects them on parameters and block members.
                blank(&mut parser, start..i);
            } else if let Some((core, exact)) = explicit_arithmetic_type(word) {
                parser[start..i].copy_from_slice(pad(&core, word.len()).as_bytes());
                if !exact {
                    limit(format!("the type `{word}` (GL_EXT_shader_explicit_arithmetic_types)"), start..i);
                }
            } else if let Some((mask, what)) = extension_word(word) {
                parser[start..i].copy_from_slice(pad(mask, word.len()).as_bytes());
                what.into_iter().for_each(|what| limit(what.to_string(), start..i));
                if word == "pervertexEXT" {
                    per_vertex.push(start);
                }
            } else if word.starts_with("utexture") {
                // glsl-lang's grammar lacks the unsigned texture types (its lexer has
                // them): the signed one for glsl-lang, the user's word for naga.
                parser[start] = b'i';
                restore.push((start..i, word.to_string()));
            } else if word == "debugPrintfEXT" {
                if let Some(end) = call_end(clean, text.as_bytes(), i) {
                    blank(&mut parser, start..end);
                    i = end;
                }
            } else if word == "layout" {
                if let Some(end) = buffer_reference(clean, &mut parser, start) {
                    limit("`buffer_reference` blocks (GL_EXT_buffer_reference)".to_string(), start..end);
                    i = end;
                }
            }
            continue;
        }
        if c.is_ascii_digit() {
            let start = i;
            while i < clean.len() && (clean[i].is_ascii_alphanumeric() || clean[i] == b'.') {
                i += 1;
            }
            let literal = std::str::from_utf8(&clean[start..i]).unwrap_or("");
            if let Some(what) = mask_literal(literal, start, &mut parser, &mut restore) {
                limit(what, start..i);
            }
            continue;
        }
        if c == b'[' && clean.get(i + 1) == Some(&b'[') {
            // `[[unroll]]`, `[[branch]]`, `[[dependency_length(4)]]` (GL_EXT_control_flow_attributes):
            // hints to the compiler, which neither parser takes; `[[` starts nothing else in GLSL.
            if let Some(end) = attribute_end(clean, i) {
                blank(&mut parser, i..end);
                i = end;
                continue;
            }
        }
        i += 1;
    }
    let for_parser = String::from_utf8(parser).unwrap_or_else(|_| text.to_string());
    Masked { for_parser, restore, unsupported, per_vertex }
}

/// `text` (the parser's, possibly renamed further) with the masked literals put back.
pub fn restored(text: &str, restore: &[(Range<usize>, String)]) -> String {
    let mut out = text.to_string();
    for (span, original) in restore {
        if out.get(span.clone()).is_some_and(|t| t.len() == original.len()) {
            out.replace_range(span.clone(), original);
        }
    }
    out
}

/// Types and qualifiers glsl-lang or naga lacks: what both read instead, what naga cannot take.
fn extension_word(word: &str) -> Option<(&'static str, Option<&'static str>)> {
    Some(match word {
        "image2DMS" | "iimage2DMS" | "uimage2DMS" | "image2DMSArray" | "iimage2DMSArray" | "uimage2DMSArray" => {
            ("image2D", Some(MULTISAMPLED_IMAGES))
        }
        "accelerationStructureEXT" => ("image2D", Some("ray queries (`accelerationStructureEXT`, GL_EXT_ray_query)")),
        "rayQueryEXT" => ("int", Some("ray queries (`rayQueryEXT`, GL_EXT_ray_query)")),
        "pervertexEXT" => ("", Some("per-vertex fragment inputs (`pervertexEXT`, GL_EXT_fragment_shader_barycentric)")),
        "samplerExternalOES" => ("sampler2D", None),
        _ => return None,
    })
}

const MULTISAMPLED_IMAGES: &str = "multisampled storage images (`image2DMS`, `image2DMSArray`: WGSL has none)";

/// The end (past `]]`) of the attribute list opening with `[[` at `at`, on its line.
fn attribute_end(clean: &[u8], at: usize) -> Option<usize> {
    let mut i = at + 2;
    while i + 1 < clean.len() && clean[i] != b'\n' {
        if clean[i] == b']' && clean[i + 1] == b']' {
            return Some(i + 2);
        }
        i += 1;
    }
    None
}

/// The explicit arithmetic types in the body of the `#define` at `line` of `clean`, masked in
/// `parser` as elsewhere; the first one naga has no form of, with its span.
fn define_body_types(clean: &[u8], line: Range<usize>, parser: &mut [u8]) -> Option<(String, Range<usize>)> {
    let text = std::str::from_utf8(&clean[line.clone()]).ok()?;
    if !text.get(1..)?.trim_start().starts_with("define") {
        return None;
    }
    let mut first = None;
    for (at, word) in words(text) {
        if let Some((core, exact)) = explicit_arithmetic_type(word) {
            let span = line.start + at..line.start + at + word.len();
            parser[span.clone()].copy_from_slice(pad(&core, word.len()).as_bytes());
            if !exact && first.is_none() {
                first = Some((format!("the type `{word}` (GL_EXT_shader_explicit_arithmetic_types)"), span));
            }
        }
    }
    first
}

/// Each identifier-like word of `line` with its offset.
pub(crate) fn words(line: &str) -> impl Iterator<Item = (usize, &str)> {
    let bytes = line.as_bytes();
    let mut i = 0;
    std::iter::from_fn(move || {
        while i < bytes.len() && !(bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
            i += 1;
        }
        let start = i;
        while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
            i += 1;
        }
        (start < i).then(|| (start, &line[start..i]))
    })
}

fn line_start(clean: &[u8], at: usize) -> bool {
    clean[..at].iter().rev().take_while(|b| **b != b'\n').all(|b| b.is_ascii_whitespace())
}

fn blank(bytes: &mut [u8], span: Range<usize>) {
    for b in &mut bytes[span] {
        if *b != b'\n' && *b != b'\r' {
            *b = b' ';
        }
    }
}

fn pad(word: &str, len: usize) -> String {
    format!("{word:<len$}")
}

/// `(core type, exact)` for an explicit arithmetic type name: `f16vec3` → (`vec3`, false),
/// `uint32_t` → (`uint`, true).
fn explicit_arithmetic_type(word: &str) -> Option<(String, bool)> {
    let scalar = |kind: &str, bits: &str| -> Option<(String, bool)> {
        let exact = bits == "32";
        let core = match (kind, bits) {
            ("float", "16" | "32") => "float",
            ("float", "64") => "double",
            ("int", "8" | "16" | "32" | "64") => "int",
            ("uint", "8" | "16" | "32" | "64") => "uint",
            _ => return None,
        };
        Some((core.to_string(), exact))
    };
    for kind in ["float", "uint", "int"] {
        if let Some(bits) = word.strip_prefix(kind).and_then(|r| r.strip_suffix("_t")) {
            return scalar(kind, bits);
        }
    }
    // f16vec3, i64vec2, u8vec4, f32mat3x4, f64mat2
    let (prefix, rest) = word.split_at(1);
    let bits_len = rest.bytes().take_while(u8::is_ascii_digit).count();
    let (bits, shape) = rest.split_at(bits_len);
    if !matches!(bits, "8" | "16" | "32" | "64") {
        return None;
    }
    let n = |s: &str| matches!(s, "2" | "3" | "4");
    let vector = shape.strip_prefix("vec").is_some_and(n);
    let matrix = shape.strip_prefix("mat").is_some_and(|m| n(m) || m.split_once('x').is_some_and(|(a, b)| n(a) && n(b)));
    let exact = bits == "32";
    let core = match (prefix, vector, matrix) {
        ("f", true, _) if bits != "8" => {
            if bits == "64" {
                format!("d{shape}")
            } else {
                shape.to_string()
            }
        }
        ("f", _, true) if bits != "8" => {
            if bits == "64" {
                format!("d{shape}")
            } else {
                shape.to_string()
            }
        }
        ("i", true, _) => format!("i{shape}"),
        ("u", true, _) => format!("u{shape}"),
        _ => return None,
    };
    (core.len() <= word.len()).then_some((core, exact))
}

/// An integer literal with a 64-bit suffix (`l`/`L`, `ul`/`UL`; not a double's `lf`):
/// whether it is unsigned.
fn int64_literal(literal: &str) -> Option<bool> {
    let lower = literal.to_ascii_lowercase();
    let hex = lower.starts_with("0x");
    if lower.contains('.') || (!hex && lower.contains('e')) {
        return None;
    }
    let unsigned = lower.ends_with("ul") || lower.ends_with("lu");
    let digits = if unsigned { &lower[..lower.len() - 2] } else { lower.strip_suffix('l')? };
    let digits = digits.strip_prefix("0x").unwrap_or(digits);
    (!digits.is_empty() && digits.bytes().all(|b| b.is_ascii_hexdigit()) && (hex || digits.bytes().all(|b| b.is_ascii_digit())))
        .then_some(unsigned)
}

/// Masks the integer literal `literal` at `start` for glsl-lang (what is put back for naga
/// goes to `restore`); returns what naga has no form of, if so.
fn mask_literal(literal: &str, start: usize, parser: &mut [u8], restore: &mut Vec<(Range<usize>, String)>) -> Option<String> {
    let end = start + literal.len();
    if let Some(unsigned) = int64_literal(literal) {
        // `1693ul`, `0x0ffffffffffffff0ul`, `-1L` (GL_ARB_gpu_shader_int64): a 32-bit
        // zero of the same signedness for glsl-lang; naga has no 64-bit integers.
        restore.push((start..end, literal.to_string()));
        let zero: &[u8] = if unsigned { b"0u" } else { b"0" };
        for (k, b) in parser[start..end].iter_mut().enumerate() {
            *b = zero.get(k).copied().unwrap_or(b' ');
        }
        return Some("64-bit integer literals (GL_ARB_gpu_shader_int64)".to_string());
    }
    if let Some(value) = wide_int_literal(literal) {
        // A decimal one (10 digits) is put back as the same bits in hex (10 characters),
        // which naga reads; glslang takes both.
        let decimal = !literal.starts_with('0');
        let digits_from = match () {
            _ if literal.starts_with("0x") || literal.starts_with("0X") => start + 2,
            _ if decimal => start,
            _ => start + 1,
        };
        restore.push((start..end, if decimal { format!("0x{value:08X}") } else { literal.to_string() }));
        for b in &mut parser[digits_from..end] {
            *b = b'0';
        }
    }
    None
}

/// The value of a hex, octal or decimal integer literal without a `u` suffix above `INT_MAX`
/// that still fits 32 bits (an `int` of that bit pattern, which glslang and GL drivers take).
fn wide_int_literal(literal: &str) -> Option<u64> {
    let value = if let Some(hex) = literal.strip_prefix("0x").or_else(|| literal.strip_prefix("0X")) {
        u64::from_str_radix(hex, 16).ok()
    } else if literal.len() > 1 && literal.starts_with('0') && literal.bytes().all(|b| b.is_ascii_digit()) {
        u64::from_str_radix(&literal[1..], 8).ok()
    } else if literal.bytes().all(|b| b.is_ascii_digit()) {
        literal.parse::<u64>().ok()
    } else {
        None
    };
    value.filter(|v| *v > i32::MAX as u64 && *v <= u32::MAX as u64)
}

/// The end (after `)`) of the call whose name ends before `at`, skipping string literals.
fn call_end(clean: &[u8], raw: &[u8], at: usize) -> Option<usize> {
    let mut i = at;
    while i < clean.len() && clean[i].is_ascii_whitespace() {
        i += 1;
    }
    if clean.get(i) != Some(&b'(') {
        return None;
    }
    let mut depth = 0;
    while i < raw.len() {
        match raw[i] {
            b'"' => {
                i += 1;
                while i < raw.len() && raw[i] != b'"' {
                    i += if raw[i] == b'\\' { 2 } else { 1 };
                }
            }
            b'(' => depth += 1,
            b')' => {
                depth -= 1;
                if depth == 0 {
                    return Some(i + 1);
                }
            }
            _ => {}
        }
        i += 1;
    }
    None
}

/// At `layout` of a `layout(… buffer_reference …) … buffer Name {` declaration, masks it into
/// `struct Name {` (a forward declaration `… buffer Name;` is blanked). Returns the end of
/// the masked head.
fn buffer_reference(clean: &[u8], out: &mut [u8], at: usize) -> Option<usize> {
    let after = at + "layout".len();
    let open = after + clean[after..].iter().position(|b| !b.is_ascii_whitespace())?;
    if clean.get(open) != Some(&b'(') {
        return None;
    }
    let close = open + clean[open..].iter().position(|b| *b == b')')?;
    let items = std::str::from_utf8(&clean[open..close]).ok()?;
    if !items.split(|c: char| !c.is_ascii_alphanumeric() && c != '_').any(|w| w == "buffer_reference") {
        return None;
    }
    // Qualifiers up to `buffer`, then the block name, then `{` or `;`.
    let mut i = close + 1;
    let mut keyword = None;
    while i < clean.len() {
        while i < clean.len() && clean[i].is_ascii_whitespace() {
            i += 1;
        }
        let start = i;
        while i < clean.len() && (clean[i].is_ascii_alphanumeric() || clean[i] == b'_') {
            i += 1;
        }
        match std::str::from_utf8(&clean[start..i]).ok()? {
            "buffer" => {
                keyword = Some(start);
                break;
            }
            "readonly" | "writeonly" | "restrict" | "coherent" | "volatile" => {}
            _ => return None,
        }
    }
    let keyword = keyword?;
    let mut j = keyword + 6;
    while j < clean.len() && (clean[j].is_ascii_whitespace() || clean[j].is_ascii_alphanumeric() || clean[j] == b'_') {
        j += 1;
    }
    match clean.get(j) {
        Some(b';') => {
            blank(out, at..j + 1);
            Some(j + 1)
        }
        Some(b'{') => {
            blank(out, at..keyword);
            out[keyword..keyword + 6].copy_from_slice(b"struct");
            Some(j)
        }
        _ => None,
    }
}

/// The identifiers of `text`: words of letters, digits and `_` that do not start with a
/// digit (keywords included; comments and strings are not told apart).
pub fn identifiers(text: &str) -> impl Iterator<Item = &str> {
    text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).filter(|w| w.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_'))
}

/// `text` with its `#line` directives blanked (same length). Spans are byte offsets, so
/// effectc's parser and naga need no line renumbering, and neither reads the named form
/// (`#line 2 "file.slang"`, GL_GOOGLE_cpp_style_line_directive) that emulator packs use.
/// glslang keeps them: its messages follow them back to the user's line.
pub fn blank_line_directives(text: &str) -> std::borrow::Cow<'_, str> {
    blank_lines_where(text, |directive| directive.starts_with("line") && directive[4..].starts_with(|c: char| c.is_whitespace()))
}

/// `text` with each line whose directive (the words after `#`) `blank` picks replaced by
/// spaces, same length, line ends kept.
fn blank_lines_where(text: &str, blank: impl Fn(&str) -> bool) -> std::borrow::Cow<'_, str> {
    let picked =
        |line: &str| line.trim_start().strip_prefix('#').map(str::trim_start).is_some_and(&blank) && !line.trim_end().ends_with('\\');
    if !text.split_inclusive('\n').any(picked) {
        return std::borrow::Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len());
    for line in text.split_inclusive('\n') {
        if picked(line) {
            for c in line.chars() {
                match c {
                    '\n' | '\r' => out.push(c),
                    _ => out.extend(std::iter::repeat_n(' ', c.len_utf8())),
                }
            }
        } else {
            out.push_str(line);
        }
    }
    std::borrow::Cow::Owned(out)
}

/// `text` with the lines of `#pragma`s no compiler acts on blanked (same length, so every
/// offset holds). GLSL has implementations ignore a pragma they do not recognise; newer
/// glslang tokenizes one anyway and refuses quoted text such as `#pragma parameter x
/// "### Title ###" 0 0 8 1` (emulator packs), which older glslang and Mesa ignore, and
/// naga's preprocessor stops on it.
pub fn quiet_pragmas(text: &str) -> std::borrow::Cow<'_, str> {
    const ACTED_ON: [&str; 10] = [
        "optimize",
        "debug",
        "STDGL",
        "once",
        "use_storage_buffer",
        "use_vulkan_memory_model",
        "use_variable_pointers",
        "shader_stage",
        "include_alias",
        "invariant",
    ];
    blank_lines_where(text, |directive| {
        directive.strip_prefix("pragma").is_some_and(|rest| !ACTED_ON.iter().any(|w| rest.trim_start().starts_with(w)))
    })
}

/// Desktop GLSL below 1.30 as glslang 12's `glslangValidator -d` and Mesa read it: the `f`
/// suffix of a float literal (`1.0f`, `2e3F`), which GLSL 1.30 added, is taken there; the
/// glslang effectc builds refuses it ("'floating-point suffix' : not supported for this
/// version"). Blanked in glslang's view only, same length. Other versions: as written.
pub fn lenient_float_suffixes(text: &str) -> std::borrow::Cow<'_, str> {
    let old_desktop = match crate::front::version::parse_version(text) {
        Ok(v) => !v.is_es() && v.number < 130,
        Err(_) => false,
    };
    if !old_desktop {
        return std::borrow::Cow::Borrowed(text);
    }
    let clean = crate::front::version::blank_comments(text);
    let mut out = text.as_bytes().to_vec();
    let mut changed = false;
    let mut i = 0;
    while i < clean.len() {
        let c = clean[i];
        if c.is_ascii_alphabetic() || c == b'_' {
            // An identifier (or a hex literal's tail): skip it whole.
            while i < clean.len() && (clean[i].is_ascii_alphanumeric() || clean[i] == b'_') {
                i += 1;
            }
            continue;
        }
        let starts_number = c.is_ascii_digit() || (c == b'.' && clean.get(i + 1).is_some_and(u8::is_ascii_digit));
        if !starts_number {
            i += 1;
            continue;
        }
        let start = i;
        if c == b'0' && matches!(clean.get(i + 1), Some(b'x' | b'X')) {
            i += 2;
            while i < clean.len() && clean[i].is_ascii_hexdigit() {
                i += 1;
            }
            continue;
        }
        let mut float = false;
        while i < clean.len() {
            match clean[i] {
                b'0'..=b'9' => i += 1,
                b'.' => {
                    float = true;
                    i += 1;
                }
                b'e' | b'E' if clean.get(i + 1).is_some_and(|n| n.is_ascii_digit() || *n == b'+' || *n == b'-') => {
                    float = true;
                    i += 2;
                }
                _ => break,
            }
        }
        let suffix = matches!(clean.get(i), Some(b'f' | b'F'));
        let ends = !clean.get(i + 1).is_some_and(|n| n.is_ascii_alphanumeric() || *n == b'_');
        if float && suffix && ends && i > start {
            out[i] = b' ';
            changed = true;
            i += 1;
        }
    }
    if !changed {
        return std::borrow::Cow::Borrowed(text);
    }
    // Only an ASCII letter became a space: still UTF-8.
    std::borrow::Cow::Owned(String::from_utf8(out).unwrap_or_else(|_| text.to_string()))
}

#[cfg(test)]
mod tests;
