//! Readers for single values: strings, tables, names from a fixed set, bounded integers,
//! finite numbers and paths to existing files. Each reports a wrong type or an invalid
//! value at the value's span and returns `None`.

use std::path::PathBuf;

use toml::de::{DeTable, DeValue};

use super::{list, parse_int, Ctx, Val};
use crate::diag::Code;
use crate::manifest::did_you_mean;

impl Ctx<'_> {
    pub(super) fn string<'v>(&mut self, v: &'v Val<'_>, what: &str) -> Option<&'v str> {
        match v.get_ref() {
            DeValue::String(s) => Some(s.as_ref()),
            _ => {
                self.wrong_type(v, what, "a string");
                None
            }
        }
    }

    pub(super) fn table<'v, 'i>(&mut self, v: &'v Val<'i>, what: &str) -> Option<&'v DeTable<'i>> {
        match v.get_ref() {
            DeValue::Table(t) => Some(t),
            _ => {
                self.wrong_type(v, what, "a table");
                None
            }
        }
    }

    /// A string naming one of `choices`; `noun` is what the names are ("semantic").
    pub(super) fn choice<T: Copy>(&mut self, v: &Val<'_>, what: &str, noun: &str, choices: &[(&'static str, T)]) -> Option<T> {
        let names: Vec<&str> = choices.iter().map(|c| c.0).collect();
        let DeValue::String(s) = v.get_ref() else {
            self.wrong_type(v, what, &format!("a string naming a {noun}"));
            let d = self.diags.last_mut().expect("just pushed");
            d.notes.push(format!("expected one of: {}", list(&names)));
            return None;
        };
        if let Some(&(_, t)) = choices.iter().find(|c| c.0 == s.as_ref()) {
            return Some(t);
        }
        let suggestion = did_you_mean(s, &names);
        let d = self.report(Code::ManifestValue, v.span(), format!("unknown {noun} `{s}` in {what}"), format!("unknown {noun}"));
        d.notes.push(format!("expected one of: {}", list(&names)));
        if let Some(sug) = suggestion {
            d.help = Some(format!("did you mean `{sug}`?"));
        }
        None
    }

    /// An integer in `min..=max`.
    pub(super) fn uint(&mut self, v: &Val<'_>, what: &str, min: u32, max: u32) -> Option<u32> {
        let DeValue::Integer(i) = v.get_ref() else {
            self.wrong_type(v, what, "an integer");
            return None;
        };
        match parse_int(i).and_then(|n| u32::try_from(n).ok()) {
            Some(n) if (min..=max).contains(&n) => Some(n),
            _ => {
                self.report(
                    Code::ManifestValue,
                    v.span(),
                    format!("{what} must be between {min} and {max}"),
                    format!("not in {min}..={max}"),
                );
                None
            }
        }
    }

    /// A finite number (integer or float).
    pub(super) fn number(&mut self, v: &Val<'_>, what: &str) -> Option<f64> {
        match v.get_ref() {
            DeValue::Integer(i) => match parse_int(i) {
                Some(n) => Some(n as f64),
                None => {
                    self.report(Code::ManifestValue, v.span(), format!("{what}: integer does not fit in 64 bits"), "too large");
                    None
                }
            },
            DeValue::Float(f) => match f.as_str().parse::<f64>() {
                // Shaders hold f32: 1e39 would arrive as +Inf.
                Ok(x) if x.is_finite() && x.abs() <= f64::from(f32::MAX) => Some(x),
                _ => {
                    let d = self.report(
                        Code::ManifestValue,
                        v.span(),
                        format!("{what} must be a finite 32-bit number"),
                        "not a finite 32-bit number",
                    );
                    d.notes.push("`nan`, `inf` and numbers beyond ±3.4e38 (the 32-bit float range a shader holds) are not accepted".into());
                    None
                }
            },
            _ => {
                self.wrong_type(v, what, "a number");
                None
            }
        }
    }

    /// `path` (written `rel` at `v`) lies inside the manifest's project root or a directory
    /// it makes readable; else E0106, and the path is never opened.
    pub(super) fn confined(&mut self, path: &std::path::Path, v: &Val<'_>, rel: &str, noun: &str) -> bool {
        let root = crate::read::project_root(&self.dir.join("effect.toml"));
        if crate::read::confined(path, &root) {
            return true;
        }
        let d =
            self.report(Code::OutsideRoot, v.span(), format!("{noun} `{rel}` lies outside the project root"), "outside the project root");
        d.notes.push(crate::read::outside_root_note(&root, "manifest"));
        false
    }

    /// A path relative to the manifest directory that must name an existing file inside the
    /// project root ([`crate::read::project_root`]; E0106 outside it, never opened).
    pub(super) fn file_path(&mut self, v: &Val<'_>, what: &str, code: Code, noun: &str) -> Option<PathBuf> {
        let rel = self.string(v, what)?;
        if rel.trim().is_empty() {
            self.report(Code::ManifestValue, v.span(), format!("{what} is an empty path"), "empty path");
            return None;
        }
        let path = self.dir.join(rel);
        if !self.confined(&path, v, rel, noun) {
            return None;
        }
        if !path.is_file() {
            let d = self.report(code, v.span(), format!("{noun} not found: `{rel}`"), "no file at this path");
            d.notes.push(format!("looked for `{}`", path.display()));
            d.notes.push("paths are relative to the directory holding effect.toml".into());
            return None;
        }
        Some(path)
    }
}
