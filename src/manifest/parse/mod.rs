//! The walk over toml's spanned document tree that builds an [`Effect`].
//!
//! Every helper reports its own problems into [`Ctx::diags`] and returns `None` when the value
//! is unusable, so one pass collects every independent error.
//!
//! This file holds the entry point, the top-level walk and the reporting helpers; each
//! section is read in the file named after it (`stages`, `uniforms`, `textures`, `mesh`,
//! `scene`, `passes`, `knobs`), and [`values`] holds the readers of single values they share.

use std::borrow::Cow;
use std::ops::Range;
use std::path::Path;

use toml::de::{DeTable, DeValue};
use toml::Spanned;

use super::*;
use crate::diag::{Code, Diagnostic, FileId};

mod knobs;
mod mesh;
mod passes;
mod scene;
mod stages;
mod textures;
mod uniforms;
mod values;

type Key<'i> = Spanned<Cow<'i, str>>;
type Val<'i> = Spanned<DeValue<'i>>;

const ROOT_KEYS: &[&str] = &[
    "name",
    "description",
    "stages",
    "uniforms",
    "textures",
    "mesh",
    "camera",
    "model",
    "render",
    "instances",
    "targets",
    "passes",
    "output",
    "knobs",
    "verify",
];

pub(super) fn parse(text: &str, file: FileId, dir: &Path) -> Result<Effect, Vec<Diagnostic>> {
    let (root, errors) = DeTable::parse_recoverable(text);
    if !errors.is_empty() {
        let mut diags: Vec<Diagnostic> = errors.iter().map(|e| syntax_error(e, file, text.len())).collect();
        diags.dedup();
        sort(&mut diags);
        return Err(diags);
    }
    let mut cx = Ctx { file, dir, diags: Vec::new() };
    let mut effect = cx.root(root.get_ref());
    let mut diags = cx.diags;
    sort(&mut diags);
    if diags.iter().any(Diagnostic::is_error) {
        Err(diags)
    } else {
        effect.warnings = diags;
        Ok(effect)
    }
}

fn sort(diags: &mut [Diagnostic]) {
    diags.sort_by_key(|d| d.span.as_ref().map_or(0, |s| s.start));
}

fn syntax_error(e: &toml::de::Error, file: FileId, len: usize) -> Diagnostic {
    let message = e.message().trim();
    let d = Diagnostic::new(Code::ManifestSyntax, format!("TOML syntax error: {message}"));
    match e.span() {
        Some(span) => {
            let start = span.start.min(len);
            let end = span.end.clamp(start, len);
            let label = message.split_once(", expected ").map_or(String::new(), |(_, exp)| format!("expected {exp}"));
            d.at(file, start..end, label)
        }
        None => d.in_file(file),
    }
}

/// Entries of a table in manifest order (toml's map is sorted by key).
fn entries<'t, 'i>(t: &'t DeTable<'i>) -> Vec<(&'t Key<'i>, &'t Val<'i>)> {
    let mut v: Vec<_> = t.iter().collect();
    v.sort_by_key(|(k, _)| k.span().start);
    v
}

fn key<'t>(k: &'t Key<'_>) -> &'t str {
    k.get_ref().as_ref()
}

fn type_name(v: &DeValue<'_>) -> &'static str {
    match v {
        DeValue::String(_) => "a string",
        DeValue::Integer(_) => "an integer",
        DeValue::Float(_) => "a float",
        DeValue::Boolean(_) => "a boolean",
        DeValue::Datetime(_) => "a date-time",
        DeValue::Array(_) => "an array",
        DeValue::Table(_) => "a table",
    }
}

fn is_ident(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some(c) if c.is_ascii_alphabetic() || c == '_') && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

fn parse_int(i: &toml::de::DeInteger<'_>) -> Option<i64> {
    i64::from_str_radix(i.as_str(), i.radix()).ok()
}

fn list(items: &[&str]) -> String {
    items.iter().map(|s| format!("`{s}`")).collect::<Vec<_>>().join(", ")
}

struct Ctx<'a> {
    file: FileId,
    dir: &'a Path,
    diags: Vec<Diagnostic>,
}

impl Ctx<'_> {
    /// Reports `code` at `span` of the manifest (its severity from the code).
    fn report(&mut self, code: Code, span: Range<usize>, msg: String, label: impl Into<String>) -> &mut Diagnostic {
        let d = Diagnostic::new(code, msg).at(self.file, span, label);
        self.diags.push(d);
        self.diags.last_mut().expect("just pushed")
    }

    fn unknown_key(&mut self, name: &str, span: Range<usize>, place: &str, valid: &[&str]) {
        let suggestion = did_you_mean(name, valid);
        let d = self.report(Code::ManifestUnknownKey, span, format!("unknown key `{name}` {place}"), "unknown key");
        d.notes.push(format!("valid keys: {}", list(valid)));
        if let Some(s) = suggestion {
            d.help = Some(format!("did you mean `{s}`?"));
        }
    }

    fn wrong_type(&mut self, v: &Val<'_>, what: &str, expected: &str) {
        let found = type_name(v.get_ref());
        self.report(Code::ManifestType, v.span(), format!("{what} must be {expected}, found {found}"), format!("expected {expected}"));
    }

    fn root(&mut self, root: &DeTable<'_>) -> Effect {
        let mut name = None;
        let mut description = None;
        let mut stages = Vec::new();
        let mut saw_stages = false;
        let mut uniforms = Vec::new();
        let mut textures = Vec::new();
        let mut mesh = None;
        let mut camera = None;
        let mut model = ModelDecl::default();
        let mut render = RenderDecl::default();
        let mut verify = VerifyDecl::default();
        let mut instances = None;
        let mut stages_key = None;
        let mut passes = Vec::new();
        let mut passes_key = None;
        let mut targets = Vec::new();
        let mut targets_key = None;
        let mut output = None;
        let mut knobs = Vec::new();
        for (k, v) in entries(root) {
            match key(k) {
                "name" => name = self.effect_name(v),
                "description" => description = self.string(v, "`description`").map(str::to_owned),
                "stages" => {
                    saw_stages = true;
                    stages_key = Some(k.span());
                    stages = self.stages_table(k, v);
                }
                "uniforms" => {
                    if let Some(t) = self.table(v, "`uniforms`") {
                        uniforms = self.uniforms(t);
                    }
                }
                "textures" => {
                    if let Some(t) = self.table(v, "`textures`") {
                        textures = self.textures(t);
                    }
                }
                "mesh" => mesh = self.mesh(v),
                "camera" => camera = self.camera(v),
                "model" => model = self.model(v).unwrap_or_default(),
                "render" => render = self.render(v).unwrap_or_default(),
                "verify" => verify = self.verify(v).unwrap_or_default(),
                "instances" => instances = self.instances(v),
                "passes" => {
                    passes_key = Some(k.span());
                    passes = self.passes(v);
                }
                "targets" => {
                    targets_key = Some(k.span());
                    if let Some(t) = self.table(v, "`targets`") {
                        targets = self.targets(t);
                    }
                }
                "knobs" => {
                    if let Some(t) = self.table(v, "`knobs`") {
                        knobs = self.knobs(t);
                    }
                }
                "output" => {
                    if let Some(s) = self.string(v, "`output`") {
                        output = Some(TargetRef { name: s.to_owned(), span: v.span() });
                    }
                }
                other => self.unknown_key(other, k.span(), "at the top level", ROOT_KEYS),
            }
        }
        self.check_pass_keys(&passes, stages_key, &output, targets_key, passes_key.clone());
        if !saw_stages && passes_key.is_none() {
            let d = Diagnostic::new(Code::ManifestMissing, "the manifest has no `[stages]` table")
                .in_file(self.file)
                .with_help("add a `[stages]` table, e.g. `[stages]` / `vertex = \"effect.vert\"` / `fragment = \"effect.frag\"`");
            self.diags.push(d);
        }
        self.check_textures_not_uniforms(&textures, &uniforms);
        self.check_knobs_are_numbers(&knobs, &uniforms);
        let (name, name_span) = name.unwrap_or_else(|| (default_name(self.dir), 0..0));
        Effect {
            file: self.file,
            dir: self.dir.to_path_buf(),
            name,
            name_span,
            description,
            stages,
            uniforms,
            textures,
            mesh,
            camera,
            model,
            render,
            instances,
            passes,
            targets,
            output,
            knobs,
            verify,
            warnings: Vec::new(),
        }
    }

    /// `name`: a non-empty string, with its span.
    fn effect_name(&mut self, v: &Val<'_>) -> Option<(String, Range<usize>)> {
        let s = self.string(v, "`name`")?;
        if s.trim().is_empty() {
            self.report(Code::ManifestValue, v.span(), "`name` is empty".into(), "empty name");
            return None;
        }
        Some((s.to_owned(), v.span()))
    }

    /// A sampler is bound in `[textures]`, never given a value in `[uniforms]` as well.
    fn check_textures_not_uniforms(&mut self, textures: &[TextureDecl], uniforms: &[UniformDefault]) {
        let file = self.file;
        for t in textures {
            if let Some(u) = uniforms.iter().find(|u: &&UniformDefault| u.name == t.name) {
                let d = self.report(
                    Code::ManifestConflict,
                    t.name_span.clone(),
                    format!("`{}` is listed both in [uniforms] and in [textures]", t.name),
                    "bound to a texture here",
                );
                d.labels.push(crate::diag::Label { file, span: u.name_span.clone(), message: "given a value here".into() });
                d.help = Some("samplers get a texture in [textures]; other uniforms get a value in [uniforms]".into());
            }
        }
    }

    /// Every knob sweeps a `[uniforms]` entry with a numeric default.
    fn check_knobs_are_numbers(&mut self, knobs: &[KnobDecl], uniforms: &[UniformDefault]) {
        for k in knobs {
            if !uniforms.iter().any(|u| u.name == k.name && u.value.as_ref().and_then(UniformValue::as_f64).is_some()) {
                let d = self.report(
                    Code::ManifestValue,
                    k.name_span.clone(),
                    format!("knob `{}` is not a number in [uniforms]", k.name),
                    "no numeric [uniforms] entry of this name",
                );
                d.help = Some(format!("a knob sweeps a uniform's value: add `{} = <default>` to [uniforms]", k.name));
            }
        }
    }
}

/// The effect name when the manifest gives none: the directory's name.
fn default_name(dir: &Path) -> String {
    let name = dir.file_name().map(|n| n.to_owned()).or_else(|| dir.canonicalize().ok()?.file_name().map(|n| n.to_owned()));
    name.map(|n| n.to_string_lossy().into_owned()).unwrap_or_else(|| "effect".to_owned())
}
