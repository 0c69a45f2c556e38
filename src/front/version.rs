//! The `#version` directive and the identifiers that became keywords after it.
//!
//! naga accepts only `#version 440|450|460`. Replacing the digits in place keeps every
//! byte offset; a missing directive means GLSL 1.10. Words that are keywords in GLSL 4.50
//! but plain identifiers in the user's version (`sample`, `buffer`, `shared`, …) are renamed
//! to identifiers of the same length before parsing, so offsets stay put.

use std::collections::HashMap;
use std::ops::Range;

/// The profile named on the `#version` line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Profile {
    Core,
    Compatibility,
    Es,
}

/// What the `#version` directive says.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Version {
    pub number: u16,
    pub profile: Profile,
    /// Span of the whole directive line (without the line end), None when absent.
    pub directive: Option<Range<usize>>,
    /// Span of the version digits.
    pub number_span: Option<Range<usize>>,
    /// Span of the profile word, if present.
    pub profile_span: Option<Range<usize>>,
}

impl Version {
    pub fn is_es(&self) -> bool {
        self.profile == Profile::Es || self.number == 100
    }

    /// The desktop version whose keyword set matches this one.
    pub fn desktop_equivalent(&self) -> u16 {
        if self.is_es() {
            match self.number {
                100 => 120,
                300 => 330,
                310 => 430,
                _ => 450,
            }
        } else {
            self.number
        }
    }

    /// True where the core profile removed the legacy built-ins (`texture2D`, `gl_FragColor`,
    /// `attribute`/`varying`, …): glslang rejects them from desktop 4.20 core and in ES 3.00+.
    pub fn forbids_legacy_builtins(&self) -> bool {
        if self.is_es() {
            self.number >= 300
        } else {
            self.number >= 420 && self.profile == Profile::Core
        }
    }
}

/// Strips `//` and `/* */` comments from a line-oriented scan, keeping offsets.
pub(crate) fn blank_comments(text: &str) -> Vec<u8> {
    let bytes = text.as_bytes();
    let mut out = bytes.to_vec();
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'/' && bytes.get(i + 1) == Some(&b'/') {
            while i < bytes.len() && bytes[i] != b'\n' {
                out[i] = b' ';
                i += 1;
            }
        } else if bytes[i] == b'/' && bytes.get(i + 1) == Some(&b'*') {
            out[i] = b' ';
            out[i + 1] = b' ';
            i += 2;
            while i < bytes.len() && !(bytes[i] == b'*' && bytes.get(i + 1) == Some(&b'/')) {
                if bytes[i] != b'\n' {
                    out[i] = b' ';
                }
                i += 1;
            }
            if i < bytes.len() {
                out[i] = b' ';
                if i + 1 < out.len() {
                    out[i + 1] = b' ';
                }
                i += 2;
            }
        } else {
            i += 1;
        }
    }
    out
}

/// `text` with `directives` (whole lines) after its `#version` line (at the start when it has
/// none), and a `#line` after them: every later line keeps its number, which diagnostics and
/// the module's spans are placed by. `#line N` names the next line `N` from GLSL 3.30 and ES
/// 3.00 on, and `N + 1` before (GLSL 1.10 §3.3), as glslang and GL drivers read it.
pub fn after_version(text: &str, directives: &str) -> String {
    let parsed = parse_version(text).ok();
    // The 0-based line of the `#version` directive (comments aside), if the text has one.
    let version = parsed.as_ref().and_then(|v| v.directive.as_ref()).map(|d| text[..d.start].matches('\n').count());
    let names_next_line = parsed.is_some_and(|v| v.number >= if v.is_es() { 300 } else { 330 });
    // 1-based number of the first line after the inserted ones.
    let next = version.map_or(1, |v| v + 2);
    let line = format!("{directives}#line {}\n", if names_next_line { next } else { next - 1 });
    let mut out = String::with_capacity(text.len() + line.len());
    if version.is_none() {
        out.push_str(&line);
    }
    for (i, l) in text.split_inclusive('\n').enumerate() {
        out.push_str(l);
        if Some(i) == version {
            if !l.ends_with('\n') {
                out.push('\n');
            }
            out.push_str(&line);
        }
    }
    out
}

/// Finds the first `#version` directive. Returns an error message with a span for a
/// malformed directive.
pub fn parse_version(text: &str) -> Result<Version, (String, Range<usize>)> {
    let clean = blank_comments(text);
    let clean = String::from_utf8_lossy(&clean);
    let mut line_start = 0;
    for line in clean.split_inclusive('\n') {
        let trimmed = line.trim_start();
        let lead = line.len() - trimmed.len();
        if let Some(rest) = trimmed.strip_prefix('#') {
            let rest_trim = rest.trim_start();
            if let Some(args) = rest_trim.strip_prefix("version") {
                let args_off = line_start + lead + 1 + (rest.len() - rest_trim.len()) + "version".len();
                let body_end = line.trim_end().len();
                let directive = line_start + lead..line_start + body_end;
                let mut words = Vec::new();
                let mut pos = args_off;
                for w in args.split(|c: char| c.is_whitespace()) {
                    if !w.is_empty() {
                        let at = text[pos..].find(w).map(|i| pos + i).unwrap_or(pos);
                        words.push((w, at..at + w.len()));
                        pos = at + w.len();
                    }
                }
                let Some((num, num_span)) = words.first().cloned() else {
                    return Err(("`#version` needs a version number".into(), directive));
                };
                let number: u16 = num.parse().map_err(|_| (format!("`{num}` is not a GLSL version number"), num_span.clone()))?;
                let valid = [100, 110, 120, 130, 140, 150, 300, 310, 320, 330, 400, 410, 420, 430, 440, 450, 460];
                if !valid.contains(&number) {
                    return Err((format!("GLSL has no version {number}"), num_span));
                }
                let (profile, profile_span) = match words.get(1) {
                    None if number == 100 => (Profile::Es, None),
                    None => (Profile::Core, None),
                    Some(("core", s)) => (Profile::Core, Some(s.clone())),
                    Some(("compatibility", s)) => (Profile::Compatibility, Some(s.clone())),
                    Some(("es", s)) => (Profile::Es, Some(s.clone())),
                    Some((other, s)) => {
                        return Err((format!("unknown GLSL profile `{other}` (expected core, compatibility or es)"), s.clone()))
                    }
                };
                return Ok(Version { number, profile, directive: Some(directive), number_span: Some(num_span), profile_span });
            }
        }
        line_start += line.len();
    }
    Ok(Version { number: 110, profile: Profile::Compatibility, directive: None, number_span: None, profile_span: None })
}

/// Keywords and type names of GLSL 4.50 with the desktop version that introduced them (an
/// older stage may name a variable `mat4x2`).
const NEWER_KEYWORDS: &[(&str, u16)] = &[
    ("centroid", 120),
    ("invariant", 120),
    ("mat2x2", 120),
    ("mat2x3", 120),
    ("mat2x4", 120),
    ("mat3x2", 120),
    ("mat3x3", 120),
    ("mat3x4", 120),
    ("mat4x2", 120),
    ("mat4x3", 120),
    ("mat4x4", 120),
    ("flat", 130),
    ("smooth", 130),
    ("noperspective", 130),
    ("switch", 130),
    ("case", 130),
    ("default", 130),
    ("layout", 140),
    ("patch", 400),
    ("sample", 400),
    ("subroutine", 400),
    ("precise", 400),
    ("coherent", 420),
    ("volatile", 420),
    ("restrict", 420),
    ("readonly", 420),
    ("writeonly", 420),
    ("buffer", 430),
    ("shared", 430),
];

/// Identifiers renamed so that a 4.50 parser accepts them, keyed by the new name.
#[derive(Debug, Clone, Default)]
pub struct Renames {
    pub to_original: HashMap<String, String>,
}

impl Renames {
    /// The user's name for an identifier in the renamed text.
    pub fn original<'a>(&'a self, name: &'a str) -> &'a str {
        self.to_original.get(name).map(String::as_str).unwrap_or(name)
    }
}

/// Blanks `#extension` lines (keeping offsets): glsl-lang stops at extensions it does not
/// know (`GL_EXT_geometry_shader4`), and naga ignores them anyway.
pub fn blank_extensions(text: &str) -> String {
    let clean = blank_comments(text);
    let mut out = text.as_bytes().to_vec();
    let mut start = 0;
    for line in clean.split_inclusive(|b| *b == b'\n') {
        let s = String::from_utf8_lossy(line);
        let t = s.trim_start();
        if t.starts_with('#') && t[1..].trim_start().starts_with("extension") {
            for b in &mut out[start..start + line.len()] {
                if *b != b'\n' && *b != b'\r' {
                    *b = b' ';
                }
            }
        }
        start += line.len();
    }
    String::from_utf8(out).unwrap_or_else(|_| text.to_string())
}

/// Keywords an `#extension` directive of the file makes reserved before their core version
/// (`buffer` with GL_ARB_shader_storage_buffer_object in a 4.20 shader).
fn extension_keywords(text: &str) -> Vec<&'static str> {
    const BY_EXTENSION: &[(&str, &[&str])] = &[
        ("GL_ARB_shader_storage_buffer_object", &["buffer", "coherent", "volatile", "restrict", "readonly", "writeonly"]),
        ("GL_ARB_compute_shader", &["shared"]),
        ("GL_ARB_shader_image_load_store", &["coherent", "volatile", "restrict", "readonly", "writeonly"]),
        ("GL_ARB_gpu_shader5", &["precise", "sample"]),
        ("GL_ARB_sample_shading", &["sample"]),
        ("GL_ARB_shader_subroutine", &["subroutine"]),
        ("GL_ARB_tessellation_shader", &["patch"]),
        ("GL_ARB_explicit_attrib_location", &["layout"]),
        ("GL_ARB_separate_shader_objects", &["layout"]),
        ("GL_ARB_uniform_buffer_object", &["layout"]),
        ("GL_EXT_gpu_shader4", &["flat", "noperspective", "centroid"]),
    ];
    let clean = blank_comments(text);
    let clean = String::from_utf8_lossy(&clean);
    let mut out = Vec::new();
    for line in clean.lines() {
        let t = line.trim_start();
        let Some(rest) = t.strip_prefix('#').map(str::trim_start).and_then(|r| r.strip_prefix("extension")) else { continue };
        let name = rest.trim_start().split(|c: char| c.is_whitespace() || c == ':').next().unwrap_or("");
        for (ext, words) in BY_EXTENSION {
            if *ext == name {
                out.extend_from_slice(words);
            }
        }
    }
    out
}

/// Type names of Vulkan GLSL (GL_KHR_vulkan_glsl) that OpenGL GLSL leaves free as
/// identifiers (`uniform sampler2D sampler;`) and naga's GLSL front always reads as types.
const VULKAN_TYPE_NAMES: &[&str] = &["sampler", "samplerShadow"];

/// Renames identifiers that are keywords in 4.50 but not in `version` (and, in OpenGL GLSL,
/// Vulkan's type names), keeping lengths. `directives` is the text whose `#extension` lines
/// count (the file as written).
pub fn rename_new_keywords(text: &str, version: &Version, directives: &str, vulkan: bool) -> (String, Renames) {
    let v = version.desktop_equivalent();
    let enabled = extension_keywords(directives);
    let mut gated: Vec<&str> = NEWER_KEYWORDS.iter().filter(|(k, since)| *since > v && !enabled.contains(k)).map(|(k, _)| *k).collect();
    if !vulkan {
        gated.extend(VULKAN_TYPE_NAMES);
    }
    let mut renames = Renames::default();
    if gated.is_empty() {
        return (text.to_string(), renames);
    }
    let clean = blank_comments(text);
    let mut out = text.as_bytes().to_vec();
    let mut i = 0;
    let mut chosen: HashMap<&str, String> = HashMap::new();
    while i < clean.len() {
        let c = clean[i];
        if c.is_ascii_alphabetic() || c == b'_' {
            let start = i;
            while i < clean.len() && (clean[i].is_ascii_alphanumeric() || clean[i] == b'_') {
                i += 1;
            }
            let word = std::str::from_utf8(&clean[start..i]).unwrap_or("");
            if let Some(k) = gated.iter().find(|k| **k == word) {
                let new = chosen.entry(k).or_insert_with(|| same_length_name(k, text)).clone();
                out[start..i].copy_from_slice(new.as_bytes());
                renames.to_original.insert(new, k.to_string());
            }
        } else if c.is_ascii_digit() {
            while i < clean.len() && (clean[i].is_ascii_alphanumeric() || clean[i] == b'.') {
                i += 1;
            }
        } else {
            i += 1;
        }
    }
    (String::from_utf8(out).unwrap_or_else(|_| text.to_string()), renames)
}

/// An identifier of the same length as `word` that does not occur in `text`.
fn same_length_name(word: &str, text: &str) -> String {
    let stem = &word[..word.len() - 1];
    for c in ['_', '0', '1', '2', '3', '4', '5', '6', '7', '8', '9', 'Q', 'Z', 'X'] {
        let cand = format!("{stem}{c}");
        if !text.contains(&cand) {
            return cand;
        }
    }
    format!("{}{}", &word[..word.len() - 2], "_q")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_version_and_profile_spans() {
        let src = "// header\r\n#version 330 core\r\nvoid main(){}";
        let v = parse_version(src).unwrap();
        assert_eq!(v.number, 330);
        assert_eq!(v.profile, Profile::Core);
        assert_eq!(&src[v.number_span.clone().unwrap()], "330");
        assert_eq!(&src[v.profile_span.clone().unwrap()], "core");
        assert_eq!(&src[v.directive.unwrap()], "#version 330 core");
    }

    #[test]
    fn missing_version_is_110_and_commented_one_is_ignored() {
        let v = parse_version("/* #version 450 */ void main(){}").unwrap();
        assert_eq!(v.number, 110);
        assert!(v.directive.is_none());
    }

    #[test]
    fn bad_versions_are_errors_with_spans() {
        let src = "#version 333\n";
        let (msg, span) = parse_version(src).unwrap_err();
        assert!(msg.contains("333"));
        assert_eq!(&src[span], "333");
        assert!(parse_version("#version 330 fancy\n").is_err());
    }

    #[test]
    fn renames_new_keywords_keeping_length() {
        let src = "#version 330 core\nin float sample; // sample\nvoid main(){ float x = sample; }";
        let v = parse_version(src).unwrap();
        let (out, renames) = rename_new_keywords(src, &v, src, false);
        assert_eq!(out.len(), src.len());
        assert!(!out.contains("float sample;"));
        assert!(out.contains("// sample"), "comments untouched");
        let new = renames.to_original.keys().next().unwrap();
        assert_eq!(renames.original(new), "sample");
        // Not renamed in 4.50.
        let src450 = src.replace("330", "450");
        let (out450, r) = rename_new_keywords(&src450, &parse_version(&src450).unwrap(), &src450, false);
        assert_eq!(out450, src450);
        assert!(r.to_original.is_empty());
    }
}
