//! `effectc.toml`'s text → [`Config`]. The text is read with toml's spanned document
//! parser, recovering past syntax errors, and each key is checked on its own: every
//! mistake in the file is reported at once, at its key or value (an unknown key, a value
//! of the wrong type, a bad glob, an unknown code, a directory that cannot be readable, a
//! limit that is not a positive integer), and the good settings still apply.

use std::collections::BTreeMap;
use std::ops::Range;
use std::path::Path;

use globset::{GlobSet, GlobSetBuilder};
use toml::de::{DeTable, DeValue};
use toml::Spanned;

use super::{glob, Config, DeclaredProgram, HazardReport, HazardSettings, Selection, TargetEnv, FILE_NAME};
use crate::diag::suppress::{self, Policy};
use crate::diag::{Code, Diagnostic, FileId};
use crate::limits::Limits;
use crate::stage::StageKind;

type Val<'i> = Spanned<DeValue<'i>>;

/// The keys at the top of the file.
const KEYS: [&str; 13] = [
    "include",
    "exclude",
    "target-env",
    "strict",
    "deny-warnings",
    "allow",
    "deny",
    "readable",
    "define",
    "stages",
    "limits",
    "hazards",
    "program",
];

/// The settings of `text` (the file at `path`, registered as `file`); problems go to
/// `diags` (errors for what cannot be used, W0004 for unknown codes).
pub(super) fn parse(text: &str, file: FileId, path: &Path, diags: &mut Vec<Diagnostic>) -> Config {
    let dir = std::env::current_dir().unwrap_or_default().join(path.parent().unwrap_or(Path::new("")));
    let mut config = Config {
        path: Some(path.to_path_buf()),
        selection: Selection { root: dir.clone(), ..Selection::default() },
        policy: Policy { origin: path.display().to_string(), ..Policy::default() },
        ..Config::default()
    };
    let (doc, errors) = DeTable::parse_recoverable(text);
    if !errors.is_empty() {
        for e in &errors {
            let span = e.span().unwrap_or(0..0);
            let span = span.start.min(text.len())..span.end.min(text.len());
            diags.push(
                Diagnostic::new(Code::ConfigInvalid, format!("invalid {FILE_NAME}: {}", e.message().trim()))
                    .at(file, span, "here")
                    .with_note(format!("keys: {}", KEYS.join(", "))),
            );
        }
        return config;
    }
    let mut w = Walk { file, diags };
    let mut entries: Vec<_> = doc.get_ref().iter().collect();
    entries.sort_by_key(|(k, _)| k.span().start);
    for (k, v) in entries {
        match k.get_ref().as_ref() {
            "include" => config.selection.include = w.strings(v, "include").and_then(|l| w.globs(&l)),
            "exclude" => config.selection.exclude = w.strings(v, "exclude").and_then(|l| w.globs(&l)),
            "target-env" => config.target_env = w.target_env(v).unwrap_or_default(),
            "strict" => config.strict = w.boolean(v, "strict").unwrap_or(false),
            "deny-warnings" => config.deny_warnings = w.boolean(v, "deny-warnings").unwrap_or(false),
            "allow" => config.policy.allow = w.strings(v, "allow").map(|l| w.codes(&l, false)).unwrap_or_default(),
            "deny" => config.policy.deny = w.strings(v, "deny").map(|l| w.codes(&l, true)).unwrap_or_default(),
            "readable" => w.readable(v, &dir),
            "define" => config.defines = w.defines(v),
            "stages" => config.selection.stages = w.stages(v),
            "limits" => config.limits = w.limits(v),
            "hazards" => config.hazards = w.hazards(v),
            "program" => config.selection.programs = w.programs(v),
            other => {
                let d = w.bad(k.span(), format!("unknown key `{other}` in {FILE_NAME}"), "not a setting");
                w.diags.push(d.with_note(format!("keys: {}", KEYS.join(", "))));
            }
        }
    }
    config
}

/// The walk over the file's keys, collecting every diagnostic.
struct Walk<'d> {
    file: FileId,
    diags: &'d mut Vec<Diagnostic>,
}

impl Walk<'_> {
    fn bad(&self, span: Range<usize>, msg: String, label: &str) -> Diagnostic {
        Diagnostic::new(Code::ConfigInvalid, msg).at(self.file, span, label)
    }

    fn wrong_type(&mut self, v: &Val<'_>, key: &str, expected: &str) {
        let d = self.bad(v.span(), format!("`{key}` must be {expected}"), "this value");
        self.diags.push(d);
    }

    fn boolean(&mut self, v: &Val<'_>, key: &str) -> Option<bool> {
        match v.get_ref() {
            DeValue::Boolean(b) => Some(*b),
            _ => {
                self.wrong_type(v, key, "`true` or `false`");
                None
            }
        }
    }

    fn string(&mut self, v: &Val<'_>, key: &str) -> Option<Spanned<String>> {
        match v.get_ref() {
            DeValue::String(s) => Some(Spanned::new(v.span(), s.to_string())),
            _ => {
                self.wrong_type(v, key, "a string");
                None
            }
        }
    }

    /// An array of strings; `None` (reported) when it is not one. A bad item is reported
    /// and left out.
    fn strings(&mut self, v: &Val<'_>, key: &str) -> Option<Vec<Spanned<String>>> {
        let DeValue::Array(items) = v.get_ref() else {
            self.wrong_type(v, key, "an array of strings");
            return None;
        };
        Some(items.iter().filter_map(|i| self.string(i, key)).collect())
    }

    fn globs(&mut self, list: &[Spanned<String>]) -> Option<GlobSet> {
        let mut builder = GlobSetBuilder::new();
        for g in list {
            match glob(g.get_ref()) {
                Ok(glob) => {
                    builder.add(glob);
                }
                Err(e) => {
                    let d = self.bad(g.span(), format!("invalid glob `{}`: {e}", g.get_ref()), "this pattern");
                    self.diags.push(d);
                }
            }
        }
        builder.build().ok()
    }

    fn target_env(&mut self, v: &Val<'_>) -> Option<TargetEnv> {
        let s = self.string(v, "target-env")?;
        match s.get_ref().as_str() {
            "auto" => Some(TargetEnv::Auto),
            "opengl" => Some(TargetEnv::OpenGl),
            other => match crate::config::VulkanVersion::NAMED.iter().find(|(n, _)| *n == other) {
                Some((_, v)) => Some(TargetEnv::Vulkan(*v)),
                None => {
                    let d = self.bad(s.span(), format!("unknown target-env `{other}`"), "not a dialect");
                    self.diags.push(d.with_help("one of: auto, opengl, vulkan, vulkan1.0, vulkan1.1, vulkan1.2, vulkan1.3"));
                    None
                }
            },
        }
    }

    /// Diagnostic codes; errors cannot be allowed (only denied ones may be errors).
    fn codes(&mut self, list: &[Spanned<String>], denying: bool) -> Vec<Code> {
        let mut out = Vec::new();
        for c in list {
            match c.get_ref().parse::<Code>() {
                Ok(code) if code.severity() == crate::diag::Severity::Error && !denying => self.diags.push(
                    Diagnostic::new(Code::SuppressionInvalid, format!("`{code}` is an error; errors cannot be allowed")).at(
                        self.file,
                        c.span(),
                        "an error",
                    ),
                ),
                Ok(code) => out.push(code),
                Err(_) => self.diags.push(suppress::unknown_code(self.file, c.span(), c.get_ref())),
            }
        }
        out
    }

    /// `readable`: each entry must name a directory that may be read
    /// ([`crate::read::readable_dir`]; `crate::read::project_root` honours the ones that do).
    fn readable(&mut self, v: &Val<'_>, dir: &Path) {
        for entry in self.strings(v, "readable").unwrap_or_default() {
            if let Err(why) = crate::read::readable_dir(dir, entry.get_ref()) {
                let d = self.bad(entry.span(), format!("`readable` entry refused: {why}"), "not readable");
                self.diags.push(
                    d.with_note("only directories outside the system's own (/proc, /etc, /dev, the home directory …) can be made readable"),
                );
            }
        }
    }

    /// `[stages]`: extension → stage.
    fn stages(&mut self, v: &Val<'_>) -> BTreeMap<String, StageKind> {
        let mut out = BTreeMap::new();
        let DeValue::Table(t) = v.get_ref() else {
            self.wrong_type(v, "stages", "a table of extension = \"stage\"");
            return out;
        };
        for (ext, stage) in t.iter() {
            let Some(stage) = self.string(stage, "a [stages] value") else { continue };
            match StageKind::from_name(&stage.get_ref().replace('-', "_")) {
                Some(k) => {
                    out.insert(ext.get_ref().trim_start_matches('.').to_string(), k);
                }
                None => {
                    let names: Vec<&str> = StageKind::ALL.iter().map(|k| k.name()).collect();
                    let d = self.bad(stage.span(), format!("unknown stage `{}`", stage.get_ref()), "not a stage");
                    self.diags.push(d.with_help(format!("one of: {}", names.join(", "))));
                }
            }
        }
        out
    }

    /// `[[program]]`: an array of tables, each with a pattern list per stage.
    fn programs(&mut self, v: &Val<'_>) -> Vec<DeclaredProgram> {
        let DeValue::Array(items) = v.get_ref() else {
            self.wrong_type(v, "program", "an array of tables (`[[program]]`)");
            return Vec::new();
        };
        let mut out = Vec::new();
        for (i, item) in items.iter().enumerate() {
            let DeValue::Table(t) = item.get_ref() else {
                self.wrong_type(item, "program", "a table");
                continue;
            };
            let mut p = DeclaredProgram { name: None, stages: Vec::new(), defines: Vec::new(), number: i + 1 };
            let mut entries: Vec<_> = t.iter().collect();
            entries.sort_by_key(|(k, _)| k.span().start);
            for (k, value) in entries {
                let key = k.get_ref().as_ref();
                match (key, StageKind::from_name(&key.replace('-', "_"))) {
                    ("name", _) => p.name = self.string(value, "name").map(|s| s.into_inner()),
                    ("define", _) => p.defines = self.defines(value),
                    (_, Some(kind)) => {
                        let patterns = match value.get_ref() {
                            DeValue::String(_) => self.string(value, key).into_iter().collect(),
                            _ => self.strings(value, key).unwrap_or_default(),
                        };
                        for pattern in &patterns {
                            if let Err(e) = glob(pattern.get_ref()) {
                                let d = self.bad(pattern.span(), format!("invalid glob `{}`: {e}", pattern.get_ref()), "this pattern");
                                self.diags.push(d);
                            }
                        }
                        p.stages.push((kind, patterns.into_iter().map(|s| s.into_inner()).collect()));
                    }
                    (other, None) => {
                        let stages: Vec<&str> = StageKind::ALL.iter().map(|k| k.name()).collect();
                        let d = self.bad(k.span(), format!("unknown key `{other}` in a [[program]]"), "not a stage or setting");
                        self.diags.push(d.with_help(format!("keys: name, define, {}", stages.join(", "))));
                    }
                }
            }
            if p.stages.is_empty() {
                let d = self.bad(item.span(), "a [[program]] names no stage".into(), "this program");
                self.diags.push(d.with_help("e.g. `vertex = \"a.vert\"` and `fragment = [\"*.frag\"]`"));
                continue;
            }
            out.push(p);
        }
        out
    }

    /// `define = { NAME = VALUE }`: each value a string, number or boolean.
    fn defines(&mut self, v: &Val<'_>) -> Vec<crate::stage::Define> {
        let DeValue::Table(t) = v.get_ref() else {
            self.wrong_type(v, "define", "a table of NAME = value");
            return Vec::new();
        };
        let mut out = Vec::new();
        for (name, value) in t.iter() {
            match crate::stage::define_from_toml(name.get_ref(), value.get_ref()) {
                Ok(d) => out.push(d),
                Err(why) => {
                    let d = self.bad(name.span(), why, "not a macro");
                    self.diags.push(d);
                }
            }
        }
        out
    }

    /// `[hazards]`: `time-limit`, a positive number of seconds; `report`, `"certain"` or
    /// `"possible"`.
    fn hazards(&mut self, v: &Val<'_>) -> HazardSettings {
        let mut settings = HazardSettings::default();
        let DeValue::Table(t) = v.get_ref() else {
            self.wrong_type(v, "hazards", "a table (`[hazards]`)");
            return settings;
        };
        for (k, value) in t.iter() {
            let key = k.get_ref().as_ref();
            let seconds = match value.get_ref() {
                DeValue::Integer(i) => i64::from_str_radix(i.as_str(), i.radix()).ok().map(|n| n as f64),
                DeValue::Float(f) => f.as_str().parse::<f64>().ok(),
                _ => None,
            };
            let text = match value.get_ref() {
                DeValue::String(s) => Some(s.as_ref()),
                _ => None,
            };
            match (key, seconds, text) {
                ("time-limit", Some(s), _) if s > 0.0 && s.is_finite() => settings.time_limit = s,
                ("time-limit", _, _) => self.wrong_type(value, key, "a positive number of seconds"),
                ("report", _, Some("certain")) => settings.report = Some(HazardReport::Certain),
                ("report", _, Some("possible")) => settings.report = Some(HazardReport::Possible),
                ("report", _, _) => self.wrong_type(value, key, "\"certain\" or \"possible\""),
                _ => {
                    let d = self.bad(k.span(), format!("unknown key `{key}` in [hazards]"), "not a hazard setting");
                    self.diags.push(d.with_help("one of: time-limit, report"));
                }
            }
        }
        settings
    }

    /// `[limits]`: each a positive integer, named as [`Limits::named`] names them.
    fn limits(&mut self, v: &Val<'_>) -> Limits {
        let mut limits = Limits::default();
        let DeValue::Table(t) = v.get_ref() else {
            self.wrong_type(v, "limits", "a table of limits");
            return limits;
        };
        let names: Vec<&str> = Limits::default().named().iter().map(|(k, _)| *k).collect();
        for (k, value) in t.iter() {
            let key = k.get_ref().as_ref();
            let n = match value.get_ref() {
                DeValue::Integer(i) => u64::from_str_radix(i.as_str(), i.radix()).ok().filter(|n| *n > 0),
                _ => None,
            };
            if !names.contains(&key) {
                let d = self.bad(k.span(), format!("unknown limit `{key}`"), "not a limit");
                self.diags.push(d.with_help(format!("one of: {}", names.join(", "))));
            } else if let Some(n) = n {
                limits.set(key, n);
            } else {
                self.wrong_type(value, key, "a positive integer");
            }
        }
        limits
    }
}
