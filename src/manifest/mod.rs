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
//! | code | [`Code`] | meaning |
//! |---|---|---|
//! | `E0001` | [`Code::ManifestSyntax`] | TOML syntax error, or the file is not UTF-8 |
//! | `E0002` | [`Code::ManifestIo`] | the manifest could not be read (the CLI exits with 2) |
//! | `E0003` | [`Code::StageFileNotFound`] | a stage file does not exist |
//! | `E0004` | [`Code::ManifestUnknownKey`] | unknown key (with the valid keys and a "did you mean") |
//! | `E0005` | [`Code::ManifestType`] | a value has the wrong TOML type |
//! | `E0006` | [`Code::ManifestValue`] | a value has the right type but is invalid (unknown name, out of bounds, `nan`, `lo > hi`, …) |
//! | `E0007` | [`Code::ManifestMissing`] | something required is missing (`[stages]`, a uniform's `value`/`semantic`, a texture source, a mesh source) |
//! | `E0008` | [`Code::AssetNotFound`] | a texture image or `.obj` file does not exist |
//! | `E0009` | [`Code::ManifestConflict`] | keys that exclude each other (`value` and `semantic`, `builtin` and `obj`, compute with graphics stages, …) |
//! | `W0001` | [`Code::StageExtension`] | a stage file's extension names another stage (`vertex = "a.frag"`) |
//! | `W0002` | [`Code::DefaultOutOfRange`] | a uniform's default value lies outside its declared `range` |
//! | `W0003` | [`Code::UnusedGeneratorParam`] | a texture generator parameter the chosen generator ignores |

mod effect;
pub mod guess;
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

use crate::diag::{Code, Diagnostic, FileId, Files};

pub use effect::{Effect, StageRef};
pub use instances::{InstanceAttribute, InstanceSource, InstancesDecl, MAX_INSTANCES};
pub use knobs::KnobDecl;
pub use mesh::{BuiltinMesh, MeshAttribute, MeshDecl, MeshSource, MESH_ATTRIBUTES};
pub use passes::{PassClear, PassDecl, PassDraw, SampleDecl, SampleKind, TargetDecl, TargetFormat, TargetRef, TargetSize};
pub use scene::{Blend, CameraDecl, CameraKey, Cull, DepthCompare, Ease, ModelDecl, RenderDecl, VerifyDecl, MAX_FRAMES, MAX_FRAME_SIDE};
pub use textures::{
    Filter, Generator, GeneratorParams, TexelFormat, TexelKind, TextureDecl, TextureKind, TextureSource, Wrap, DEFAULT_TEXTURE_SIZE,
    MAX_TEXTURE_SIZE,
};
pub use uniforms::{Semantic, UniformDefault, UniformValue};

/// True for the diagnostic produced when the manifest could not be read; the CLI maps it
/// to exit code 2 (usage / IO problems) rather than 1 (problems in the user's files).
pub fn is_io_error(d: &Diagnostic) -> bool {
    d.code == Code::ManifestIo
}

/// Parses manifest text (for other modules' unit tests; files are looked up in `dir`).
#[cfg(test)]
pub(crate) fn parse_for_tests(text: &str, file: FileId, dir: &Path) -> Result<Effect, Vec<Diagnostic>> {
    parse::parse(text, file, dir)
}

/// Read `path`, register its text in `files` and parse it. Relative paths in the manifest are
/// resolved against the manifest's directory. An unreadable file gives one [`Code::ManifestIo`]
/// diagnostic (see [`is_io_error`]).
pub fn load(path: &Path, files: &mut Files) -> Result<Effect, Vec<Diagnostic>> {
    let shown = path.display().to_string();
    let bytes = match std::fs::read(path) {
        Ok(bytes) => bytes,
        Err(err) => {
            let id = files.add(shown.clone(), String::new());
            return Err(vec![Diagnostic::new(Code::ManifestIo, format!("cannot read manifest `{shown}`: {err}")).in_file(id)]);
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
            let d = Diagnostic::new(Code::ManifestSyntax, "the manifest is not valid UTF-8")
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
