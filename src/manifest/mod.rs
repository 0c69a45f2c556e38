//! `effects/<name>/effect.toml` → [`Effect`].
//!
//! The manifest names an effect's stages, the default values of its uniforms, the textures
//! bound to its samplers and the mesh it is drawn with. The user-facing format is documented
//! in `docs/manifest.md`.
//!
//! # How it is read
//! The text is parsed with toml's spanned document parser ([`toml::de::DeTable`]), which keeps
//! a byte span for every key and value, recovers from syntax errors and reports them all.
//! The resulting tree is then walked by hand rather than with `#[derive(Deserialize)]`:
//! a derive stops at the first problem, while the walk reports every unknown key, wrong type
//! and invalid value in one pass, each at the span of the offending key or value. Spans are
//! byte offsets into the original text (CRLF line ends and a BOM included).
//!
//! # Diagnostic codes
//! | code    | constant                 | meaning |
//! |---------|--------------------------|---------|
//! | `E0001` | [`E_SYNTAX`]             | TOML syntax error, or the file is not UTF-8 |
//! | `E0002` | [`E_IO`]                 | the manifest could not be read (the CLI exits with 2) |
//! | `E0003` | [`E_STAGE_NOT_FOUND`]    | a stage file does not exist |
//! | `E0004` | [`E_UNKNOWN_KEY`]        | unknown key (with the valid keys and a "did you mean") |
//! | `E0005` | [`E_TYPE`]               | a value has the wrong TOML type |
//! | `E0006` | [`E_VALUE`]              | a value has the right type but is invalid (unknown name, out of bounds, `nan`, `lo > hi`, …) |
//! | `E0007` | [`E_MISSING`]            | something required is missing (`[stages]`, a uniform's `value`/`semantic`, a texture source, a mesh source) |
//! | `E0008` | [`E_ASSET_NOT_FOUND`]    | a texture image or `.obj` file does not exist |
//! | `E0009` | [`E_CONFLICT`]           | keys that exclude each other (`value` and `semantic`, `builtin` and `obj`, compute with graphics stages, …) |
//! | `W0001` | [`W_STAGE_EXTENSION`]    | a stage file's extension names another stage (`vertex = "a.frag"`) |
//! | `W0002` | [`W_OUT_OF_RANGE`]       | a uniform's default value lies outside its declared `range` |
//! | `W0003` | [`W_UNUSED_PARAM`]       | a texture generator parameter the chosen generator ignores |

mod effect;
mod instances;
mod knobs;
mod mesh;
mod parse;
mod passes;
mod scene;
#[cfg(test)]
mod tests;
mod textures;
mod uniforms;

use std::path::{Path, PathBuf};

use crate::diag::{Diagnostic, FileId, Files};

pub use effect::{Effect, StageRef};
pub use instances::{InstanceAttribute, InstanceSource, InstancesDecl, MAX_INSTANCES};
pub use knobs::KnobDecl;
pub use mesh::{BuiltinMesh, MeshAttribute, MeshDecl, MeshSource, MESH_ATTRIBUTES};
pub use passes::{PassClear, PassDecl, PassDraw, SampleDecl, SampleKind, TargetDecl, TargetFormat, TargetRef, TargetSize};
pub use scene::{Blend, CameraDecl, CameraKey, Cull, DepthCompare, Ease, ModelDecl, RenderDecl, MAX_FRAMES, MAX_FRAME_SIDE};
pub use textures::{
    Filter, Generator, GeneratorParams, TextureDecl, TextureKind, TextureSource, Wrap, DEFAULT_TEXTURE_SIZE, MAX_TEXTURE_SIZE,
};
pub use uniforms::{Semantic, UniformDefault, UniformValue};

/// TOML syntax error, or the manifest is not valid UTF-8.
pub const E_SYNTAX: &str = "E0001";
/// The manifest file could not be read (missing, permissions, …). Maps to exit code 2.
pub const E_IO: &str = "E0002";
/// A stage listed in `[stages]` names a file that does not exist.
pub const E_STAGE_NOT_FOUND: &str = "E0003";
/// A key that is not part of the format.
pub const E_UNKNOWN_KEY: &str = "E0004";
/// A value of the wrong TOML type (`vertex = 3`, `range = "x"`).
pub const E_TYPE: &str = "E0005";
/// A value of the right type that is not acceptable (unknown name, out of bounds, `nan`, …).
pub const E_VALUE: &str = "E0006";
/// A required key or section is missing.
pub const E_MISSING: &str = "E0007";
/// A texture image or mesh file does not exist.
pub const E_ASSET_NOT_FOUND: &str = "E0008";
/// Two keys that exclude each other.
pub const E_CONFLICT: &str = "E0009";
/// A stage file's extension implies a different stage than the key it is listed under.
pub const W_STAGE_EXTENSION: &str = "W0001";
/// A uniform default lies outside its declared `range`.
pub const W_OUT_OF_RANGE: &str = "W0002";
/// A texture generator parameter that the chosen generator does not use.
pub const W_UNUSED_PARAM: &str = "W0003";

/// Every code this module emits, with a one-line description (for `--explain`-style listings).
pub const CODES: &[(&str, &str)] = &[
    (E_SYNTAX, "TOML syntax error in the manifest"),
    (E_IO, "the manifest could not be read"),
    (E_STAGE_NOT_FOUND, "stage file not found"),
    (E_UNKNOWN_KEY, "unknown key in the manifest"),
    (E_TYPE, "manifest value has the wrong type"),
    (E_VALUE, "invalid manifest value"),
    (E_MISSING, "required manifest key missing"),
    (E_ASSET_NOT_FOUND, "texture or mesh file not found"),
    (E_CONFLICT, "conflicting manifest keys"),
    (W_STAGE_EXTENSION, "stage file extension names another stage"),
    (W_OUT_OF_RANGE, "uniform default outside its declared range"),
    (W_UNUSED_PARAM, "texture generator parameter has no effect"),
];

/// True for the diagnostic produced when the manifest could not be read; the CLI maps it
/// to exit code 2 (usage / IO problems) rather than 1 (problems in the user's files).
pub fn is_io_error(d: &Diagnostic) -> bool {
    d.code == E_IO
}

/// Parses manifest text (for other modules' unit tests; files are looked up in `dir`).
#[cfg(test)]
pub(crate) fn parse_for_tests(text: &str, file: FileId, dir: &Path) -> Result<Effect, Vec<Diagnostic>> {
    parse::parse(text, file, dir)
}

/// Read `path`, register its text in `files` and parse it. Relative paths in the manifest are
/// resolved against the manifest's directory. An unreadable file gives one [`E_IO`]
/// diagnostic (see [`is_io_error`]).
pub fn load(path: &Path, files: &mut Files) -> Result<Effect, Vec<Diagnostic>> {
    let shown = path.display().to_string();
    let bytes = match std::fs::read(path) {
        Ok(bytes) => bytes,
        Err(err) => {
            let id = files.add(shown.clone(), String::new());
            return Err(vec![Diagnostic::error(E_IO, format!("cannot read manifest `{shown}`: {err}")).in_file(id)]);
        }
    };
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    match String::from_utf8(bytes) {
        Ok(text) => {
            let id = files.add(shown, text);
            parse(files.text(id), id, &dir)
        }
        Err(err) => {
            let at = err.utf8_error().valid_up_to();
            let text = String::from_utf8_lossy(err.as_bytes()).into_owned();
            let id = files.add(shown, text);
            let d = Diagnostic::error(E_SYNTAX, "the manifest is not valid UTF-8")
                .at(id, at..at + '\u{FFFD}'.len_utf8(), "invalid UTF-8 here")
                .with_help("save effect.toml as UTF-8 text");
            Err(vec![d])
        }
    }
}

/// Parse manifest text registered as `file`. `dir` is the manifest's directory: stage,
/// texture and mesh paths are joined to it and checked for existence, and it provides the
/// default effect name. On failure the diagnostics hold every error found (and warnings).
pub fn parse(text: &str, file: FileId, dir: &Path) -> Result<Effect, Vec<Diagnostic>> {
    parse::parse(text, file, dir)
}

/// The closest candidate to `word` (case-insensitive, `-` read as `_`), if any is close enough.
pub fn did_you_mean<'a>(word: &str, candidates: &[&'a str]) -> Option<&'a str> {
    let norm = |s: &str| s.to_ascii_lowercase().replace('-', "_");
    let w = norm(word);
    if w.is_empty() {
        return None;
    }
    candidates
        .iter()
        .copied()
        .map(|c| {
            let n = norm(c);
            let score = if n == w { 2.0 } else { strsim::jaro_winkler(&w, &n) };
            (c, score)
        })
        .filter(|&(_, s)| s >= 0.8)
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(c, _)| c)
}
