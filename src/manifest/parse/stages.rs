//! `[stages]`: a shader file per pipeline stage (or a list of them: shader objects GL links
//! into that stage; each one a path, or `{ file = "x.glsl", define = { VERTEX = 1 } }` with
//! macros defined for it), checked to exist, with a warning when a file's extension names another
//! stage and an error when compute is mixed with graphics.

use std::ops::Range;

use toml::de::DeTable;

use super::{entries, key, Ctx, Key, Val};
use crate::diag::Code;
use crate::manifest::StageRef;
use crate::stage::{Define, StageKind};

impl Ctx<'_> {
    /// The `[stages]` key and its value: a table that lists at least one stage.
    pub(super) fn stages_table(&mut self, k: &Key<'_>, v: &Val<'_>) -> Vec<StageRef> {
        let Some(t) = self.table(v, "`stages`") else {
            return Vec::new();
        };
        if t.is_empty() {
            let d = self.report(Code::ManifestMissing, k.span(), "`[stages]` lists no stage".into(), "no stage here");
            d.help = Some("add e.g. `vertex = \"effect.vert\"` and `fragment = \"effect.frag\"`".into());
        }
        self.stages(t)
    }

    pub(super) fn stages(&mut self, t: &DeTable<'_>) -> Vec<StageRef> {
        let names: Vec<&str> = StageKind::ALL.iter().map(|s| s.name()).collect();
        let mut stages = Vec::new();
        for (k, v) in entries(t) {
            let Some(kind) = StageKind::from_name(key(k)) else {
                self.unknown_key(key(k), k.span(), "in `[stages]`", &names);
                continue;
            };
            let what = format!("`stages.{kind}`");
            // A list: shader objects GL links into the one stage (one of them has `main`).
            let files: Vec<&Val<'_>> = match v.get_ref() {
                toml::de::DeValue::Array(items) if !items.is_empty() => items.iter().collect(),
                _ => vec![v],
            };
            for v in files {
                // `"x.glsl"`, or `{ file = "x.glsl", define = { VERTEX = 1 } }`.
                let (v, defines) = match v.get_ref() {
                    toml::de::DeValue::Table(t) => match self.stage_with_defines(t, v, &what) {
                        Some(found) => found,
                        None => continue,
                    },
                    _ => (v, Vec::new()),
                };
                let Some(path) = self.file_path(v, &what, Code::StageFileNotFound, "stage file") else {
                    continue;
                };
                let implied = path.extension().and_then(|e| e.to_str()).and_then(StageKind::from_extension);
                if let Some(other) = implied.filter(|&o| o != kind) {
                    let d = self.report(
                        Code::StageExtension,
                        v.span(),
                        format!("the {kind} stage is a file whose extension means {other}"),
                        format!("looks like a {other} shader"),
                    );
                    d.help = Some(format!("list it under `{other}` if that is what it is"));
                }
                stages.push(StageRef { kind, path, span: v.span(), key_span: k.span(), defines });
            }
        }
        stages.sort_by_key(|s| s.kind);
        if let Some(compute) = stages.iter().find(|s| s.kind == StageKind::Compute) {
            let graphics: Vec<Range<usize>> = stages.iter().filter(|s| s.kind != StageKind::Compute).map(|s| s.key_span.clone()).collect();
            if !graphics.is_empty() {
                let span = compute.key_span.clone();
                let file = self.file;
                let d = self.report(
                    Code::ManifestConflict,
                    span,
                    "a compute stage cannot be combined with graphics stages".into(),
                    "compute stage",
                );
                for g in graphics {
                    d.labels.push(crate::diag::Label { file, span: g, message: "graphics stage".into() });
                }
                d.help = Some("put the compute shader in an effect of its own".into());
            }
        }
        stages
    }

    /// A stage written as a table: its `file` value and its `define`d macros.
    fn stage_with_defines<'v, 'i>(&mut self, t: &'v DeTable<'i>, whole: &'v Val<'i>, what: &str) -> Option<(&'v Val<'i>, Vec<Define>)> {
        let mut file = None;
        let mut defines = Vec::new();
        for (k, v) in entries(t) {
            match key(k) {
                "file" => file = Some(v),
                "define" => {
                    let Some(table) = self.table(v, &format!("{what}.define")) else { continue };
                    for (name, value) in entries(table) {
                        match crate::stage::define_from_toml(key(name), value.get_ref()) {
                            Ok(d) => defines.push(d),
                            Err(why) => {
                                self.report(Code::ManifestValue, name.span(), why, "not a macro");
                            }
                        }
                    }
                }
                other => self.unknown_key(other, k.span(), &format!("in {what}"), &["file", "define"]),
            }
        }
        match file {
            Some(f) => Some((f, defines)),
            None => {
                self.report(Code::ManifestMissing, whole.span(), format!("{what} needs a `file`"), "no `file` here");
                None
            }
        }
    }
}
