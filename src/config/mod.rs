//! The repository's settings: `effectc.toml`, found upward from the first input (or named
//! with `--config`).
//!
//! ```toml
//! include = ["shaders/**"]          # only these paths (relative to this file's directory)
//! exclude = ["third_party/**"]      # never these
//! target-env = "opengl"             # GLSL dialect: "auto" (default), "opengl", "vulkan" (1.0), "vulkan1.0"–"vulkan1.3"
//! strict = true                     # like --strict
//! deny-warnings = true              # like --deny-warnings
//! allow = ["W0201"]                 # silenced everywhere
//! deny = ["W0717"]                  # raised to errors
//! define = { PARAMETER_UNIFORM = 1 }  # macros in every stage, as the host code defines them
//! readable = ["../shared/glsl"]     # directories outside the project root that includes
//!                                   # and manifests may read (never /proc, /etc, …)
//! [stages]                          # the stage of extensions effectc does not know
//! glsl = "fragment"
//! [limits]                          # what effectc reads at most (see `crate::limits`)
//! file-bytes = 16777216
//! [hazards]                         # what the hazard analysis assumes of bare stage files
//! time-limit = 3600                 # seconds a time uniform runs (default an hour)
//! [[program]]                       # programs as the host code links them
//! name = "lit"
//! vertex = "data/PCN.vert"
//! fragment = ["data/Diffuse*.frag"] # one program per file matched
//! define = { MAX_LIGHTS = 4 }
//! ```
//!
//! Every mistake in the file is reported at once, each at its key or value
//! (`config::parse`).
//!
//! Globs follow `.gitignore` habits: `*` stays within a directory, `**` crosses them, and a
//! pattern without `/` matches a file or directory name at any depth.

mod parse;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use globset::{Glob, GlobBuilder, GlobSet};

use crate::diag::paths::absolute;
use crate::diag::suppress::Policy;
use crate::diag::{Code, Diagnostic, FileId, Files};
use crate::limits::Limits;
use crate::stage::StageKind;

/// The file name searched for.
pub const FILE_NAME: &str = "effectc.toml";

/// The GLSL dialect of the stages.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub enum TargetEnv {
    /// Vulkan GLSL when the text shows it (descriptor sets, push constants, separate
    /// samplers), else OpenGL GLSL.
    #[default]
    Auto,
    OpenGl,
    /// Vulkan GLSL for this Vulkan version (glslangValidator's `--target-env vulkan1.x`).
    Vulkan(VulkanVersion),
}

/// The Vulkan version Vulkan GLSL is compiled for: it decides the SPIR-V version whose rules
/// apply (subgroup operations need SPIR-V 1.3, Vulkan 1.1). `glslangValidator -V` and an
/// auto-detected Vulkan stage use 1.0.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, PartialOrd, Ord)]
pub enum VulkanVersion {
    #[default]
    V1_0,
    V1_1,
    V1_2,
    V1_3,
}

impl VulkanVersion {
    /// Every version with the name `--target-env` and `effectc.toml` give it.
    pub const NAMED: [(&'static str, VulkanVersion); 5] = [
        ("vulkan", VulkanVersion::V1_0),
        ("vulkan1.0", VulkanVersion::V1_0),
        ("vulkan1.1", VulkanVersion::V1_1),
        ("vulkan1.2", VulkanVersion::V1_2),
        ("vulkan1.3", VulkanVersion::V1_3),
    ];
}

/// Which paths a run reads, the stage of extensions effectc does not know, and the
/// programs the file declares.
#[derive(Debug, Clone, Default)]
pub struct Selection {
    /// The directory the globs are relative to (absolute).
    pub root: PathBuf,
    pub include: Option<GlobSet>,
    pub exclude: Option<GlobSet>,
    /// Extension (without the dot) → stage.
    pub stages: BTreeMap<String, StageKind>,
    /// `[[program]]`: programs formed as declared, not guessed from names.
    pub programs: Vec<DeclaredProgram>,
}

/// One `[[program]]`: for each stage, the files that may fill it (paths or globs, relative
/// to the settings file); one program is formed per combination of them
/// (`vertex = "PCN.vert"`, `fragment = ["Diffuse*.frag"]`: one program per fragment file,
/// each with `PCN.vert`).
#[derive(Debug, Clone)]
pub struct DeclaredProgram {
    /// `name`, or the programs are named after their files.
    pub name: Option<String>,
    /// Stage → its patterns, as written.
    pub stages: Vec<(StageKind, Vec<String>)>,
    /// `define = { NAME = VALUE }`: macros defined in every stage of it.
    pub defines: Vec<crate::stage::Define>,
    /// Which `[[program]]` of the file it is (from 1), for messages.
    pub number: usize,
}

impl Selection {
    /// Does the run read the file `path`? It must match `include` (when given) and no
    /// `exclude` pattern; paths outside the root are always read.
    pub fn admits(&self, path: &Path) -> bool {
        if self.include.is_none() && self.exclude.is_none() {
            return true;
        }
        let Some(relative) = relative_to(&self.root, path) else { return true };
        let excluded = self.exclude.as_ref().is_some_and(|g| matches_or_parent(g, &relative));
        let included = self.include.as_ref().is_none_or(|g| matches_or_parent(g, &relative));
        included && !excluded
    }
    /// Does the run look inside the directory `path`? Only `exclude` prunes directories
    /// (the files below are matched against `include`).
    pub fn enters(&self, path: &Path) -> bool {
        let Some(exclude) = &self.exclude else { return true };
        relative_to(&self.root, path).is_none_or(|r| !matches_or_parent(exclude, &r))
    }
    /// The stage configured for `path`'s extension.
    pub fn stage_of(&self, path: &Path) -> Option<StageKind> {
        path.extension().and_then(|e| e.to_str()).and_then(|e| self.stages.get(e)).copied()
    }
}

/// A path or one of its parent directories matches (so `build` excludes `build/a.vert`).
fn matches_or_parent(globs: &GlobSet, relative: &Path) -> bool {
    relative.ancestors().filter(|a| !a.as_os_str().is_empty()).any(|a| globs.is_match(a))
}

/// `path` relative to `root`, both made absolute and cleaned lexically; `None` when it
/// lies elsewhere.
fn relative_to(root: &Path, path: &Path) -> Option<PathBuf> {
    absolute(path).strip_prefix(absolute(root)).ok().map(Path::to_path_buf)
}

/// The settings of a run.
#[derive(Debug, Clone, Default)]
pub struct Config {
    /// The file they came from (`None`: no `effectc.toml`, the defaults).
    pub path: Option<PathBuf>,
    pub selection: Selection,
    pub target_env: TargetEnv,
    pub strict: bool,
    pub deny_warnings: bool,
    pub policy: Policy,
    /// How much of an input a run reads and models (`[limits]`).
    pub limits: Limits,
    /// `define = { NAME = VALUE }`: macros defined in every stage (as `--define`, which
    /// adds to them and wins for a name both give).
    pub defines: Vec<crate::stage::Define>,
    /// `[hazards]`: what the hazard analysis assumes where no manifest says.
    pub hazards: HazardSettings,
}

/// What the hazard analysis assumes where no manifest declares a range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HazardSettings {
    /// Seconds a time uniform runs (`time`, `iTime`, …) without a `range`: an hour, a
    /// realistic session, unless `[hazards] time-limit` says otherwise.
    pub time_limit: f64,
    /// Which hazards to report: `None` leaves it to the input (bare stage files report
    /// certain ones, effects both tiers).
    pub report: Option<HazardReport>,
}

/// The hazards reported: certain ones only, or possible ones too.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HazardReport {
    /// Hazards a witness run showed at fixed inputs.
    Certain,
    /// Also those the analysis cannot rule out over the ranges it assumes.
    Possible,
}

impl HazardSettings {
    /// An hour.
    pub const DEFAULT_TIME_LIMIT: f64 = 3600.0;
}

impl Default for HazardSettings {
    fn default() -> Self {
        HazardSettings { time_limit: Self::DEFAULT_TIME_LIMIT, report: None }
    }
}

/// A loaded configuration: the settings, and the file's text with the diagnostics about
/// it (spans into that text, as file [`FileId`]`(0)` of their own [`Files`]).
#[derive(Debug, Default)]
pub struct Loaded {
    pub config: Config,
    pub files: Files,
    pub diagnostics: Vec<Diagnostic>,
}

impl Loaded {
    /// The file could not be read or has an invalid setting (a usage error: exit 2).
    pub fn failed(&self) -> bool {
        self.diagnostics.iter().any(Diagnostic::is_error)
    }
    /// The diagnostics about the file, pointing into `files` (where the file is registered
    /// when there are any).
    pub fn attach(&self, files: &mut Files) -> Vec<Diagnostic> {
        let Some(source) = self.files.try_get(FileId(0)).filter(|_| !self.diagnostics.is_empty()) else {
            return self.diagnostics.clone();
        };
        let id = files.add(source.path.clone(), source.text.clone());
        let moved = |f: FileId| if f == FileId(0) { id } else { f };
        let mut out = self.diagnostics.clone();
        for d in &mut out {
            d.file = d.file.map(moved);
            for l in &mut d.labels {
                l.file = moved(l.file);
            }
        }
        out
    }
}

/// The nearest `effectc.toml` in the directory of `input` (or `input` itself, when it is a
/// directory) and its ancestors.
pub fn discover(input: &Path) -> Option<PathBuf> {
    let absolute = std::env::current_dir().ok()?.join(input);
    let start = if absolute.is_dir() { absolute.as_path() } else { absolute.parent()? };
    // Anything by that name counts (a directory too, which `load` then refuses): a settings
    // file that is silently skipped would let a run pass under defaults nobody chose.
    start.ancestors().map(|d| d.join(FILE_NAME)).find(|p| p.exists())
}

/// Loads `explicit` (`--config`), else the file [`discover`]ed from the first input, else
/// the defaults.
pub fn load(explicit: Option<&Path>, inputs: &[PathBuf]) -> Loaded {
    let found = explicit.map(Path::to_path_buf).or_else(|| inputs.first().and_then(|i| discover(i)));
    let Some(path) = found else {
        let root = std::env::current_dir().unwrap_or_default();
        return Loaded {
            config: Config { selection: Selection { root, ..Selection::default() }, ..Config::default() },
            ..Loaded::default()
        };
    };
    let mut files = Files::new();
    let text = match crate::read::bounded(&path, crate::read::MAX_FILE_BYTES).map(|b| String::from_utf8(b).map_err(|e| e.utf8_error())) {
        Ok(Ok(t)) => t,
        Ok(Err(e)) => {
            let d = Diagnostic::new(Code::ConfigInvalid, format!("`{}` is not UTF-8 text: {e}", path.display()));
            return Loaded { config: Config::default(), files, diagnostics: vec![d] };
        }
        Err(e) => {
            let d = Diagnostic::new(Code::ConfigInvalid, format!("cannot read `{}`: {e}", path.display()));
            return Loaded { config: Config::default(), files, diagnostics: vec![d] };
        }
    };
    let file = files.add(path.display().to_string(), text.clone());
    let mut diagnostics = Vec::new();
    let config = parse::parse(&text, file, &path, &mut diagnostics);
    Loaded { config, files, diagnostics }
}

/// One pattern, `.gitignore`-style: without a `/` it matches a name at any depth.
pub fn glob(pattern: &str) -> Result<Glob, globset::Error> {
    let p = pattern.trim_start_matches("./");
    let anchored = p.trim_end_matches('/');
    let full = if anchored.contains('/') { anchored.trim_start_matches('/').to_string() } else { format!("**/{anchored}") };
    GlobBuilder::new(&full).literal_separator(true).build()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parsed(text: &str) -> (Config, Vec<Diagnostic>) {
        let mut files = Files::new();
        let id = files.add("effectc.toml", text);
        let mut diags = Vec::new();
        let c = parse::parse(text, id, Path::new("effectc.toml"), &mut diags);
        (c, diags)
    }

    #[test]
    fn globs_select_paths_relative_to_the_file() {
        let (c, diags) = parsed("include = [\"shaders/**\", \"effects\"]\nexclude = [\"third_party\", \"*.gen.frag\"]\n");
        assert!(diags.is_empty(), "{diags:?}");
        let s = &c.selection;
        assert!(s.admits(Path::new("shaders/a.vert")));
        assert!(s.admits(Path::new("effects/sun/effect.toml")));
        assert!(!s.admits(Path::new("tools/a.vert")), "not included");
        assert!(!s.admits(Path::new("shaders/third_party/x.frag")), "a name without / excludes at any depth");
        assert!(!s.admits(Path::new("shaders/b.gen.frag")));
        assert!(s.admits(Path::new("/elsewhere/a.frag")), "outside the root: not filtered");
        assert!(s.enters(Path::new(".")) && s.enters(Path::new("tools")), "include does not prune directories");
        assert!(!s.enters(Path::new("a/third_party")));
    }

    #[test]
    fn settings_and_their_mistakes() {
        let (c, diags) = parsed(
            "target-env = \"vulkan\"\nstrict = true\ndeny-warnings = true\nallow = [\"W0201\", \"w0718\", \"E0201\"]\ndeny = [\"W0717\"]\n[stages]\nglsl = \"fragment\"\nshd = \"pixel\"\n",
        );
        assert_eq!(c.target_env, TargetEnv::Vulkan(VulkanVersion::V1_0));
        assert!(c.strict && c.deny_warnings);
        assert_eq!(c.policy.allow, [Code::UnreadOutput]);
        assert_eq!(c.policy.deny, [Code::HazardTrig]);
        assert_eq!(c.selection.stage_of(Path::new("a.glsl")), Some(StageKind::Fragment));
        let codes: Vec<Code> = diags.iter().map(|d| d.code).collect();
        assert_eq!(codes, [Code::SuppressionInvalid, Code::SuppressionInvalid, Code::ConfigInvalid], "{diags:#?}");
        assert!(diags.iter().any(|d| d.help.as_deref().is_some_and(|h| h.contains("W0718"))), "lowercase w0718 suggests W0718");
        let (_, diags) = parsed("colour = 1\n");
        assert_eq!(diags[0].code, Code::ConfigInvalid);
        assert!(diags[0].message.contains("colour"), "{}", diags[0].message);
    }
}
