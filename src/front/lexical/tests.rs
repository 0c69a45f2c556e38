//! Tests of the masks over a stage's text.

use super::*;

#[test]
fn float_suffixes_below_glsl_130_are_blanked_in_place() {
    let text = "#version 120\nfloat a = 1.0f + 2e3F + .5f; // 3.0f\nint b = 0x1f; float fx = 1.0; vec2 v2f;\n";
    let lenient = lenient_float_suffixes(text);
    assert_eq!(lenient.len(), text.len());
    assert_eq!(lenient, "#version 120\nfloat a = 1.0  + 2e3  + .5 ; // 3.0f\nint b = 0x1f; float fx = 1.0; vec2 v2f;\n");
    let modern = "#version 330\nfloat a = 1.0f;\n";
    assert_eq!(lenient_float_suffixes(modern), modern);
    let es = "#version 100\nfloat a = 1.0f;\n";
    assert_eq!(lenient_float_suffixes(es), es);
}

#[test]
fn line_directives_are_blanked_in_place() {
    let text = "#version 450\n#line 2 \"a.slang\"\nvoid main() {}\n  #  line 7\n#linear\n";
    let blank = blank_line_directives(text);
    assert_eq!(blank.len(), text.len());
    let lines: Vec<&str> = blank.lines().collect();
    assert_eq!(lines[1].trim(), "");
    assert_eq!(lines[3].trim(), "");
    assert_eq!(lines[4], "#linear");
}

#[test]
fn unknown_pragmas_are_blanked_in_place() {
    let text = "#version 450\n#pragma parameter x \"### \u{e9} ###\" 0 0 8 1\n#pragma optimize(off)\nvoid main() {}\n";
    let quiet = quiet_pragmas(text);
    assert_eq!(quiet.len(), text.len());
    assert!(!quiet.contains("parameter") && quiet.contains("#pragma optimize(off)"));
    assert_eq!(quiet.lines().count(), text.lines().count());
}

fn masked(src: &str) -> Masked {
    let m = mask(src, src.as_bytes());
    assert_eq!(m.for_parser.len(), src.len());
    m
}

#[test]
fn int64_literals_are_zeroed_for_the_parser_and_limit_the_stage() {
    let m = masked("uint a = uint(1693ul * 0x0ffffffffffffff0UL); int b = int(-7L); double d = 1.5lf; uint c = 3u;");
    assert!(m.for_parser.contains("a = uint(0u     * 0u                  );"), "{}", m.for_parser);
    assert!(m.for_parser.contains("b = int(-0 );"), "{}", m.for_parser);
    assert!(m.for_parser.contains("d = 1.5lf;") && m.for_parser.contains("c = 3u;"), "{}", m.for_parser);
    assert_eq!(m.unsupported.as_ref().map(|(w, _)| w.as_str()), Some("64-bit integer literals (GL_ARB_gpu_shader_int64)"));
    assert_eq!(m.restore.len(), 3, "{:?}", m.restore);
}

#[test]
fn wide_hex_literals_are_zeroed_for_the_parser_only() {
    let m = masked(
        "uint a = 0xFFFFFFFF; int b = 0x7FFFFFFF; uint c = 0xFFFFFFFFu; int d = 037777777777; uint e = i * 2654435761; int f = 2147483647;",
    );
    assert!(m.for_parser.contains("a = 0x00000000;"));
    assert!(m.for_parser.contains("b = 0x7FFFFFFF;"), "fits int");
    assert!(m.for_parser.contains("c = 0xFFFFFFFFu;"), "suffixed");
    assert!(m.for_parser.contains("d = 000000000000;"));
    assert!(m.for_parser.contains("e = i * 0000000000;"), "{}", m.for_parser);
    assert!(m.for_parser.contains("f = 2147483647;"), "fits int");
    let naga = restored(&m.for_parser, &m.restore);
    assert!(naga.contains("a = 0xFFFFFFFF;") && naga.contains("d = 037777777777;"));
    assert!(naga.contains("e = i * 0x9E3779B1;"), "the same bits in hex: {naga}");
    assert!(m.unsupported.is_none());
}

#[test]
fn precision_qualifiers_leave_all_but_precision_statements() {
    let m = masked("precision highp float; float f(highp vec2 w); uniform B { mediump mat3 n; };");
    assert_eq!(m.for_parser, "precision highp float; float f(      vec2 w); uniform B {         mat3 n; };");
}

#[test]
fn nonuniform_qualifiers_are_blanked_and_calls_kept() {
    let m = masked("nonuniformEXT uint i = id; vec4 c = texture(t[nonuniformEXT (i)], uv);");
    assert_eq!(m.for_parser, "              uint i = id; vec4 c = texture(t[nonuniformEXT (i)], uv);");
}

#[test]
fn memory_qualifiers_naga_lacks_are_blanked() {
    let m = masked("layout(r32ui) coherent uniform uimage2D a; restrict readonly buffer B { uint x[]; };");
    assert_eq!(m.for_parser, "layout(r32ui)          uniform uimage2D a;          readonly buffer B { uint x[]; };");
}

#[test]
fn debug_printf_calls_are_blanked() {
    let m = masked("void main() { debugPrintfEXT(\"p = %f (%d)\", x, f(y)); z = 1; }");
    assert_eq!(m.for_parser, "void main() {                                       ; z = 1; }");
    assert!(m.restore.is_empty());
}

#[test]
fn control_flow_attributes_are_blanked() {
    let text = "void main() { [[unroll, dependency_length(4)]] for (int i = 0; i < 4; i++) { x[i] = y[z[i]]; } [[branch]] if (b) {} }";
    let m = masked(text);
    assert!(!m.for_parser.contains("[["), "{}", m.for_parser);
    assert!(m.for_parser.contains("x[i] = y[z[i]]") && m.for_parser.len() == text.len(), "{}", m.for_parser);
    assert!(m.unsupported.is_none());
}

#[test]
fn explicit_arithmetic_types_in_a_define_body() {
    let m = masked("#define mem_i16 int16_t\n#define W uint32_t\nmem_i16 a; W b;");
    assert!(m.for_parser.starts_with("#define mem_i16 int    \n#define W uint    \n"), "{}", m.for_parser);
    assert_eq!(m.unsupported.as_ref().map(|(what, _)| what.as_str()), Some("the type `int16_t` (GL_EXT_shader_explicit_arithmetic_types)"));
}

#[test]
fn explicit_arithmetic_types() {
    let m = masked("uint32_t a; f32vec3 b; float16_t c; u8vec4 d; i64vec2 e; f64mat3x4 f; int g;");
    assert!(m.for_parser.starts_with("uint     a; vec3    b;"), "32-bit aliases are exact: {}", m.for_parser);
    assert!(m.for_parser.contains("float     c; uvec4  d; ivec2   e; dmat3x4   f; int g;"), "{}", m.for_parser);
    let (what, span) = m.unsupported.expect("16-bit types are limited");
    assert!(what.contains("float16_t"));
    assert_eq!(span, 23..32);
}

#[test]
fn buffer_reference_blocks_read_as_structs() {
    let src = "layout(buffer_reference) buffer Node;\nlayout(buffer_reference, std430) readonly buffer Verts { vec4 v[]; };\nlayout(push_constant) uniform PC { Verts verts; } pc;";
    let m = masked(src);
    assert!(m.for_parser.starts_with("                                     \n"), "{}", m.for_parser);
    assert!(m.for_parser.contains("                                          struct Verts { vec4 v[]; };"), "{}", m.for_parser);
    assert!(m.for_parser.contains("layout(push_constant) uniform PC"));
    assert!(m.unsupported.expect("limited").0.contains("buffer_reference"));
}

#[test]
fn multisampled_storage_images_limit_the_stage() {
    let src = "layout(binding = 0, rgba8) uniform readonly uimage2DMSArray msaa;\n";
    let m = masked(src);
    assert!(m.for_parser.contains("uniform readonly image2D         msaa;"), "{}", m.for_parser);
    let (what, span) = m.unsupported.expect("limited");
    assert!(what.starts_with("multisampled storage images"), "{what}");
    assert_eq!(&src[span], "uimage2DMSArray");
}
