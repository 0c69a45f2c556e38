//! 64-bit floats taken as 32-bit ones, for the commands that draw (`render`, `verify`,
//! `bench`, `stress`) and for `translate` to targets without them (WGSL, MSL, GLSL ES):
//! a program with `double`s is drawn and translated at f32 precision, with warning W0131,
//! rather than not at all. `translate` to SPIR-V and HLSL alone keeps the doubles.
//!
//! Applied to the rewritten 4.50 text just before naga reads it, byte for byte, so the
//! map back to the user's file holds: `double` → `float `, `dvecN` → `vecN `, `dmatN[xM]`
//! → `matN[xM] `, and the `lf`/`LF` suffix of a literal blanked.

use std::ops::Range;

/// Lowers `text` in place; the replaced spans (in `text`), in order.
pub fn as_floats(text: &mut String) -> Vec<Range<usize>> {
    let clean = crate::front::version::blank_comments(text);
    let mut bytes = std::mem::take(text).into_bytes();
    let mut replaced = Vec::new();
    let mut i = 0;
    while i < clean.len() {
        let c = clean[i];
        let word_start = i == 0 || !(clean[i - 1].is_ascii_alphanumeric() || clean[i - 1] == b'_');
        if !word_start || !(c.is_ascii_alphanumeric() || c == b'_' || c == b'.') {
            i += 1;
            continue;
        }
        let end = i + clean[i..].iter().take_while(|b| b.is_ascii_alphanumeric() || **b == b'_' || **b == b'.').count();
        let word = &clean[i..end];
        if c.is_ascii_digit() || c == b'.' {
            // A literal: `1.0lf`, `2LF`, `1e3lf`.
            if word.len() > 2 && (word.ends_with(b"lf") || word.ends_with(b"LF")) {
                bytes[end - 2] = b' ';
                bytes[end - 1] = b' ';
                replaced.push(i..end);
            }
        } else if let Some(replacement) = float_type(word) {
            bytes[i..end].copy_from_slice(&replacement);
            replaced.push(i..end);
        }
        i = end.max(i + 1);
    }
    *text = String::from_utf8(bytes).expect("ASCII replacements keep UTF-8");
    replaced
}

/// The 32-bit type of a 64-bit one, padded to its length: `dvec3` → `vec3 `.
fn float_type(word: &[u8]) -> Option<Vec<u8>> {
    let w = std::str::from_utf8(word).ok()?;
    let short = match w {
        "double" => "float".to_string(),
        _ => {
            let rest = w.strip_prefix('d')?;
            let shape = rest.strip_prefix("vec").map(|n| ("vec", n)).or_else(|| rest.strip_prefix("mat").map(|n| ("mat", n)))?;
            let digits_ok = match shape.0 {
                "vec" => matches!(shape.1, "2" | "3" | "4"),
                _ => {
                    let dims: Vec<&str> = shape.1.split('x').collect();
                    !dims.is_empty() && dims.len() <= 2 && dims.iter().all(|d| matches!(*d, "2" | "3" | "4"))
                }
            };
            if !digits_ok {
                return None;
            }
            rest.to_string()
        }
    };
    let mut out = short.into_bytes();
    out.resize(word.len(), b' ');
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn doubles_become_floats_byte_for_byte() {
        let mut t = "uniform dvec4 x; // double in a comment\ndouble s = 1.5lf * 2.0LF; dmat2x3 m; float mydouble; int d2;\n".to_string();
        let before = t.len();
        let replaced = as_floats(&mut t);
        assert_eq!(t.len(), before);
        assert_eq!(replaced.len(), 5);
        assert_eq!(&t[replaced[0].clone()], "vec4 ");
        assert_eq!(t, "uniform vec4  x; // double in a comment\nfloat  s = 1.5   * 2.0  ; mat2x3  m; float mydouble; int d2;\n");
        let mut plain = "vec4 a = vec4(1.0);".to_string();
        assert!(as_floats(&mut plain).is_empty());
    }
}
