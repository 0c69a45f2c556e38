//! The text glslang judges, where glslang is stricter than the GLSL specifications and the
//! GL drivers that follow them: a text of the same meaning, every line keeping its number.
//!
//! - Desktop GLSL below 1.30: the `f` suffix of float literals
//!   ([`lenient_float_suffixes`](crate::front::lexical::lenient_float_suffixes)).
//! - GLSL ES 3.00 and later: glslang declares GL_INTEL_shader_integer_functions2's functions
//!   (`average`, `addSaturate`, `countLeadingZeros`, …) in every such stage, enabled or not,
//!   and ES forbids redeclaring a built-in, so a user function of that name ("'average' :
//!   function name is redeclaration of existing name": three.js's `common` chunk) was
//!   refused; Mesa takes it, as the extension's names are no built-ins until it is enabled.
//!   Where the stage does not name the extension, those names are glslang's to ignore: they
//!   are written with a capital first letter (same length).
//! - Desktop GLSL below 1.40: rectangle textures without `#extension
//!   GL_ARB_texture_rectangle`, which the extension enables implicitly (its issue 15; Mesa
//!   and the desktop drivers do so): the `#extension` line is added after `#version`.

use std::borrow::Cow;

use crate::front::lexical::{identifiers, lenient_float_suffixes};
use crate::front::syntax::word_occurrences;
use crate::front::version::{after_version, blank_comments, parse_version};

/// GL_INTEL_shader_integer_functions2's functions, which glslang declares in every ES 3.00+
/// stage.
const INTEL_FUNCTIONS: [&str; 8] = [
    "countLeadingZeros",
    "countTrailingZeros",
    "absoluteDifference",
    "addSaturate",
    "subtractSaturate",
    "average",
    "averageRounded",
    "multiply32x16",
];

/// GL_ARB_texture_rectangle's types and functions.
const RECTANGLE_WORDS: [&str; 6] =
    ["sampler2DRect", "sampler2DRectShadow", "texture2DRect", "texture2DRectProj", "shadow2DRect", "shadow2DRectProj"];

/// `text` as glslang should judge it (the module doc).
pub fn as_drivers_read(text: &str) -> Cow<'_, str> {
    let Ok(version) = parse_version(text) else { return Cow::Borrowed(text) };
    let text = lenient_float_suffixes(text);
    let (es300, below140) = (version.is_es() && version.number >= 300, !version.is_es() && version.number < 140);
    if !es300 && !below140 {
        return text;
    }
    let clean = blank_comments(&text);
    let clean = String::from_utf8_lossy(&clean);
    let names = |words: &[&str]| identifiers(&clean).any(|w| words.contains(&w));
    if es300 && !clean.contains("GL_INTEL_shader_integer_functions2") && names(&INTEL_FUNCTIONS) {
        return Cow::Owned(capitalized(&text, &clean, &INTEL_FUNCTIONS));
    }
    if below140 && !clean.contains("GL_ARB_texture_rectangle") && names(&RECTANGLE_WORDS) {
        return Cow::Owned(after_version(&text, "#extension GL_ARB_texture_rectangle : enable\n"));
    }
    text
}

/// `text` with every whole identifier among `words` (outside comments, `clean` being `text`
/// with its comments blanked) given a capital first letter.
fn capitalized(text: &str, clean: &str, words: &[&str]) -> String {
    let mut out = text.as_bytes().to_vec();
    for word in words {
        for at in word_occurrences(clean, 0..clean.len(), word) {
            out[at.start] = out[at.start].to_ascii_uppercase();
        }
    }
    // Only an ASCII letter changed case: still UTF-8.
    String::from_utf8(out).unwrap_or_else(|_| text.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extension_function_names_are_users_in_es_without_the_extension() {
        let es = "#version 300 es\nfloat average(vec3 v) { return v.x; } // average\nfloat x = average(vec3(1.0)); int averages;\n";
        assert_eq!(
            as_drivers_read(es),
            "#version 300 es\nfloat Average(vec3 v) { return v.x; } // average\nfloat x = Average(vec3(1.0)); int averages;\n"
        );
        let enabled = "#version 310 es\n#extension GL_INTEL_shader_integer_functions2 : enable\nuint a = average(1u, 3u);\n";
        assert_eq!(as_drivers_read(enabled), enabled);
        let desktop = "#version 330\nfloat average(vec3 v) { return v.x; }\n";
        assert_eq!(as_drivers_read(desktop), desktop, "desktop GLSL overloads built-ins");
    }

    #[test]
    fn rectangle_textures_below_140_have_their_extension_enabled() {
        let old = "#version 120\nuniform sampler2DRect t;\nvoid main() { gl_FragColor = texture2DRect(t, vec2(0.0)); }\n";
        assert_eq!(
            as_drivers_read(old),
            "#version 120\n#extension GL_ARB_texture_rectangle : enable\n#line 1\nuniform sampler2DRect t;\n\
             void main() { gl_FragColor = texture2DRect(t, vec2(0.0)); }\n"
        );
        let bare = "uniform sampler2DRect t;\n";
        assert_eq!(as_drivers_read(bare), "#extension GL_ARB_texture_rectangle : enable\n#line 0\nuniform sampler2DRect t;\n");
        let enabled = "#version 120\n#extension GL_ARB_texture_rectangle : require\nuniform sampler2DRect t;\n";
        assert_eq!(as_drivers_read(enabled), enabled);
        let core = "#version 140\nuniform sampler2DRect t;\n";
        assert_eq!(as_drivers_read(core), core);
    }
}
