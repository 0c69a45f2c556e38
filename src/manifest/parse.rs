//! The walk over toml's spanned document tree that builds an [`Effect`].
//!
//! Every helper reports its own problems into [`Ctx::diags`] and returns `None` when the value
//! is unusable, so one pass collects every independent error.

use std::borrow::Cow;
use std::ops::Range;
use std::path::{Path, PathBuf};

use toml::de::{DeTable, DeValue};
use toml::Spanned;

use super::*;
use crate::diag::{Diagnostic, FileId};
use crate::stage::StageKind;

mod knobs;
mod passes;
mod scene;

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
];
const UNIFORM_KEYS: &[&str] = &["value", "range", "semantic"];
const TEXTURE_KEYS: &[&str] = &["file", "cube", "generate", "kind", "size", "colors", "cells", "seed", "octaves", "filter", "wrap"];
const MESH_KEYS: &[&str] = &["builtin", "obj", "segments", "rings", "divisions", "attributes"];
/// Uniform default lists nest at most this deep (an array of arrays of mat4 columns is 3).
const MAX_LIST_DEPTH: usize = 6;
const MAX_CELLS: u32 = 4096;
const MAX_OCTAVES: u32 = 16;
const MAX_MESH_DIVISIONS: u32 = 1024;

const FACE_ORDER: &str = "+x, -x, +y, -y, +z, -z";

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
    let d = Diagnostic::error(E_SYNTAX, format!("TOML syntax error: {message}"));
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

/// A name as `glGetUniformLocation` takes it: `ident ( "[" digits "]" | "." ident )*`.
fn is_uniform_name(s: &str) -> bool {
    let end = s.find(['[', '.']).unwrap_or(s.len());
    if !is_ident(&s[..end]) {
        return false;
    }
    let mut rest = &s[end..];
    while !rest.is_empty() {
        if let Some(r) = rest.strip_prefix('[') {
            let Some(close) = r.find(']') else {
                return false;
            };
            if close == 0 || !r[..close].bytes().all(|b| b.is_ascii_digit()) {
                return false;
            }
            rest = &r[close + 1..];
        } else if let Some(r) = rest.strip_prefix('.') {
            let end = r.find(['[', '.']).unwrap_or(r.len());
            if !is_ident(&r[..end]) {
                return false;
            }
            rest = &r[end..];
        } else {
            return false;
        }
    }
    true
}

fn parse_int(i: &toml::de::DeInteger<'_>) -> Option<i64> {
    i64::from_str_radix(i.as_str(), i.radix()).ok()
}

fn list(items: &[&str]) -> String {
    items.iter().map(|s| format!("`{s}`")).collect::<Vec<_>>().join(", ")
}

/// Generated-texture parameter keys (besides the source itself).
const GEN_PARAMS: &[&str] = &["size", "colors", "cells", "seed", "octaves"];

struct Ctx<'a> {
    file: FileId,
    dir: &'a Path,
    diags: Vec<Diagnostic>,
}

impl Ctx<'_> {
    fn error(&mut self, code: &'static str, span: Range<usize>, msg: String, label: impl Into<String>) -> &mut Diagnostic {
        let d = Diagnostic::error(code, msg).at(self.file, span, label);
        self.diags.push(d);
        self.diags.last_mut().expect("just pushed")
    }

    fn warning(&mut self, code: &'static str, span: Range<usize>, msg: String, label: impl Into<String>) -> &mut Diagnostic {
        let d = Diagnostic::warning(code, msg).at(self.file, span, label);
        self.diags.push(d);
        self.diags.last_mut().expect("just pushed")
    }

    fn unknown_key(&mut self, name: &str, span: Range<usize>, place: &str, valid: &[&str]) {
        let suggestion = did_you_mean(name, valid);
        let d = self.error(E_UNKNOWN_KEY, span, format!("unknown key `{name}` {place}"), "unknown key");
        d.notes.push(format!("valid keys: {}", list(valid)));
        if let Some(s) = suggestion {
            d.help = Some(format!("did you mean `{s}`?"));
        }
    }

    fn wrong_type(&mut self, v: &Val<'_>, what: &str, expected: &str) {
        let found = type_name(v.get_ref());
        self.error(E_TYPE, v.span(), format!("{what} must be {expected}, found {found}"), format!("expected {expected}"));
    }

    fn string<'v>(&mut self, v: &'v Val<'_>, what: &str) -> Option<&'v str> {
        match v.get_ref() {
            DeValue::String(s) => Some(s.as_ref()),
            _ => {
                self.wrong_type(v, what, "a string");
                None
            }
        }
    }

    fn table<'v, 'i>(&mut self, v: &'v Val<'i>, what: &str) -> Option<&'v DeTable<'i>> {
        match v.get_ref() {
            DeValue::Table(t) => Some(t),
            _ => {
                self.wrong_type(v, what, "a table");
                None
            }
        }
    }

    /// A string naming one of `choices`; `noun` is what the names are ("semantic").
    fn choice<T: Copy>(&mut self, v: &Val<'_>, what: &str, noun: &str, choices: &[(&'static str, T)]) -> Option<T> {
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
        let d = self.error(E_VALUE, v.span(), format!("unknown {noun} `{s}` in {what}"), format!("unknown {noun}"));
        d.notes.push(format!("expected one of: {}", list(&names)));
        if let Some(sug) = suggestion {
            d.help = Some(format!("did you mean `{sug}`?"));
        }
        None
    }

    /// An integer in `min..=max`.
    fn uint(&mut self, v: &Val<'_>, what: &str, min: u32, max: u32) -> Option<u32> {
        let DeValue::Integer(i) = v.get_ref() else {
            self.wrong_type(v, what, "an integer");
            return None;
        };
        match parse_int(i).and_then(|n| u32::try_from(n).ok()) {
            Some(n) if (min..=max).contains(&n) => Some(n),
            _ => {
                self.error(E_VALUE, v.span(), format!("{what} must be between {min} and {max}"), format!("not in {min}..={max}"));
                None
            }
        }
    }

    /// A finite number (integer or float).
    fn number(&mut self, v: &Val<'_>, what: &str) -> Option<f64> {
        match v.get_ref() {
            DeValue::Integer(i) => match parse_int(i) {
                Some(n) => Some(n as f64),
                None => {
                    self.error(E_VALUE, v.span(), format!("{what}: integer does not fit in 64 bits"), "too large");
                    None
                }
            },
            DeValue::Float(f) => match f.as_str().parse::<f64>() {
                Ok(x) if x.is_finite() => Some(x),
                _ => {
                    let d = self.error(E_VALUE, v.span(), format!("{what} must be a finite number"), "not a finite number");
                    d.notes.push("`nan`, `inf` and numbers beyond the f64 range are not accepted".into());
                    None
                }
            },
            _ => {
                self.wrong_type(v, what, "a number");
                None
            }
        }
    }

    /// A path relative to the manifest directory that must name an existing file.
    fn file_path(&mut self, v: &Val<'_>, what: &str, code: &'static str, noun: &str) -> Option<PathBuf> {
        let rel = self.string(v, what)?;
        if rel.trim().is_empty() {
            self.error(E_VALUE, v.span(), format!("{what} is an empty path"), "empty path");
            return None;
        }
        let path = self.dir.join(rel);
        if !path.is_file() {
            let d = self.error(code, v.span(), format!("{noun} not found: `{rel}`"), "no file at this path");
            d.notes.push(format!("looked for `{}`", path.display()));
            d.notes.push("paths are relative to the directory holding effect.toml".into());
            return None;
        }
        Some(path)
    }

    /// Names in `[uniforms]` / `[textures]` must be GLSL uniform names.
    fn check_uniform_name(&mut self, name: &str, span: Range<usize>) -> bool {
        if name.starts_with("gl_") {
            self.error(E_VALUE, span, format!("`{name}` is a reserved GLSL name"), "names starting with `gl_` are reserved");
            return false;
        }
        if !is_uniform_name(name) {
            let d = self.error(E_VALUE, span, format!("`{name}` is not a valid GLSL uniform name"), "not a uniform name");
            d.help = Some("use the name as the shader declares it: `tint`, `lights[0].color`".into());
            return false;
        }
        true
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
                "name" => {
                    if let Some(s) = self.string(v, "`name`") {
                        if s.trim().is_empty() {
                            self.error(E_VALUE, v.span(), "`name` is empty".into(), "empty name");
                        } else {
                            name = Some((s.to_owned(), v.span()));
                        }
                    }
                }
                "description" => description = self.string(v, "`description`").map(str::to_owned),
                "stages" => {
                    saw_stages = true;
                    stages_key = Some(k.span());
                    if let Some(t) = self.table(v, "`stages`") {
                        if t.is_empty() {
                            let d = self.error(E_MISSING, k.span(), "`[stages]` lists no stage".into(), "no stage here");
                            d.help = Some("add e.g. `vertex = \"effect.vert\"` and `fragment = \"effect.frag\"`".into());
                        }
                        stages = self.stages(t);
                    }
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
            let d = Diagnostic::error(E_MISSING, "the manifest has no `[stages]` table")
                .in_file(self.file)
                .with_help("add a `[stages]` table, e.g. `[stages]` / `vertex = \"effect.vert\"` / `fragment = \"effect.frag\"`");
            self.diags.push(d);
        }
        let file = self.file;
        for t in &textures {
            if let Some(u) = uniforms.iter().find(|u: &&UniformDefault| u.name == t.name) {
                let d = self.error(
                    E_CONFLICT,
                    t.name_span.clone(),
                    format!("`{}` is listed both in [uniforms] and in [textures]", t.name),
                    "bound to a texture here",
                );
                d.labels.push(crate::diag::Label { file, span: u.name_span.clone(), message: "given a value here".into() });
                d.help = Some("samplers get a texture in [textures]; other uniforms get a value in [uniforms]".into());
            }
        }
        for k in &knobs {
            if !uniforms.iter().any(|u| u.name == k.name && u.value.as_ref().and_then(UniformValue::as_f64).is_some()) {
                let d = self.error(
                    E_VALUE,
                    k.name_span.clone(),
                    format!("knob `{}` is not a number in [uniforms]", k.name),
                    "no numeric [uniforms] entry of this name",
                );
                d.help = Some(format!("a knob sweeps a uniform's value: add `{} = <default>` to [uniforms]", k.name));
            }
        }
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
            warnings: Vec::new(),
        }
    }

    fn stages(&mut self, t: &DeTable<'_>) -> Vec<StageRef> {
        let names: Vec<&str> = StageKind::ALL.iter().map(|s| s.name()).collect();
        let mut stages = Vec::new();
        for (k, v) in entries(t) {
            let Some(kind) = StageKind::from_name(key(k)) else {
                self.unknown_key(key(k), k.span(), "in `[stages]`", &names);
                continue;
            };
            let what = format!("`stages.{kind}`");
            let Some(path) = self.file_path(v, &what, E_STAGE_NOT_FOUND, "stage file") else {
                continue;
            };
            let implied = path.extension().and_then(|e| e.to_str()).and_then(StageKind::from_extension);
            if let Some(other) = implied.filter(|&o| o != kind) {
                let d = self.warning(
                    W_STAGE_EXTENSION,
                    v.span(),
                    format!("the {kind} stage is a file whose extension means {other}"),
                    format!("looks like a {other} shader"),
                );
                d.help = Some(format!("list it under `{other}` if that is what it is"));
            }
            stages.push(StageRef { kind, path, span: v.span(), key_span: k.span() });
        }
        stages.sort_by_key(|s| s.kind);
        if let Some(compute) = stages.iter().find(|s| s.kind == StageKind::Compute) {
            let graphics: Vec<Range<usize>> = stages.iter().filter(|s| s.kind != StageKind::Compute).map(|s| s.key_span.clone()).collect();
            if !graphics.is_empty() {
                let span = compute.key_span.clone();
                let file = self.file;
                let d = self.error(E_CONFLICT, span, "a compute stage cannot be combined with graphics stages".into(), "compute stage");
                for g in graphics {
                    d.labels.push(crate::diag::Label { file, span: g, message: "graphics stage".into() });
                }
                d.help = Some("put the compute shader in an effect of its own".into());
            }
        }
        stages
    }

    fn uniforms(&mut self, t: &DeTable<'_>) -> Vec<UniformDefault> {
        let mut out = Vec::new();
        for (k, v) in entries(t) {
            let name = key(k);
            let name_ok = self.check_uniform_name(name, k.span());
            let what = format!("uniform `{name}`");
            let parsed = match v.get_ref() {
                DeValue::Table(spec) => self.uniform_spec(name, k, v, spec),
                _ => self.uniform_value(v, &what, 0).map(|value| UniformDefault {
                    name: name.to_owned(),
                    name_span: k.span(),
                    value: Some(value),
                    value_span: v.span(),
                    range: None,
                    range_span: None,
                    semantic: None,
                    semantic_span: None,
                }),
            };
            if let (Some(u), true) = (parsed, name_ok) {
                out.push(u);
            }
        }
        out
    }

    fn uniform_spec(&mut self, name: &str, k: &Key<'_>, v: &Val<'_>, spec: &DeTable<'_>) -> Option<UniformDefault> {
        let mut ok = true;
        let mut value = None;
        let mut value_key = None;
        let mut range = None;
        let mut semantic = None;
        let mut semantic_key = None;
        for (k2, v2) in entries(spec) {
            match key(k2) {
                "value" => {
                    value_key = Some(k2.span());
                    match self.uniform_value(v2, &format!("`uniforms.{name}.value`"), 0) {
                        Some(x) => value = Some((x, v2.span())),
                        None => ok = false,
                    }
                }
                "range" => match self.range(v2, &format!("`uniforms.{name}.range`")) {
                    Some(r) => range = Some((r, v2.span())),
                    None => ok = false,
                },
                "semantic" => {
                    semantic_key = Some(k2.span());
                    let choices: Vec<(&'static str, Semantic)> = Semantic::ALL.iter().map(|s| (s.name(), *s)).collect();
                    let alias = v2.get_ref().as_str().and_then(Semantic::from_name);
                    let what = format!("`uniforms.{name}.semantic`");
                    match alias.or_else(|| self.choice(v2, &what, "semantic", &choices)) {
                        Some(s) => semantic = Some((s, v2.span())),
                        None => ok = false,
                    }
                }
                other => {
                    self.unknown_key(other, k2.span(), &format!("in uniform `{name}`"), UNIFORM_KEYS);
                    ok = false;
                }
            }
        }
        match (&value_key, &semantic_key) {
            (Some(vk), Some(sk)) => {
                let file = self.file;
                let d = self.error(
                    E_CONFLICT,
                    sk.clone(),
                    format!("uniform `{name}` has both a `value` and a `semantic`"),
                    "semantic given here",
                );
                d.labels.push(crate::diag::Label { file, span: vk.clone(), message: "value given here".into() });
                d.help = Some("a semantic is set by the runtime every frame: remove `value` or `semantic`".into());
                ok = false;
            }
            (None, None) => {
                let d = self.error(
                    E_MISSING,
                    v.span(),
                    format!("uniform `{name}` needs a `value` or a `semantic`"),
                    "neither `value` nor `semantic`",
                );
                d.help = Some(format!(
                    "write `{name} = 1.0`, `{name} = {{ value = 1.0, range = [0.0, 2.0] }}` or `{name} = {{ semantic = \"time\" }}`"
                ));
                ok = false;
            }
            _ => {}
        }
        if let (Some((val, vspan)), Some(((lo, hi), rspan))) = (&value, &range) {
            let outside: Vec<f64> = val.scalars().iter().filter_map(|s| s.as_f64()).filter(|x| x < lo || x > hi).collect();
            if let Some(first) = outside.first() {
                let file = self.file;
                let d = self.warning(
                    W_OUT_OF_RANGE,
                    vspan.clone(),
                    format!("default of uniform `{name}` lies outside its range [{lo}, {hi}]"),
                    format!("{first} is outside the range"),
                );
                d.labels.push(crate::diag::Label { file, span: rspan.clone(), message: "range declared here".into() });
            }
        }
        if !ok {
            return None;
        }
        let (value, value_span) = match value {
            Some((x, span)) => (Some(x), span),
            None => (None, v.span()),
        };
        Some(UniformDefault {
            name: name.to_owned(),
            name_span: k.span(),
            value,
            value_span,
            range: range.as_ref().map(|r| r.0),
            range_span: range.map(|r| r.1),
            semantic: semantic.as_ref().map(|s| s.0),
            semantic_span: semantic.map(|s| s.1),
        })
    }

    fn uniform_value(&mut self, v: &Val<'_>, what: &str, depth: usize) -> Option<UniformValue> {
        const EXPECTED: &str = "a number, a boolean or an array of them";
        match v.get_ref() {
            DeValue::Boolean(b) => Some(UniformValue::Bool(*b)),
            DeValue::Integer(i) => match parse_int(i) {
                Some(n) => Some(UniformValue::Int(n)),
                None => {
                    self.error(E_VALUE, v.span(), format!("{what}: integer does not fit in 64 bits"), "too large");
                    None
                }
            },
            DeValue::Float(_) => self.number(v, what).map(UniformValue::Float),
            DeValue::String(s) => {
                self.wrong_type(v, what, EXPECTED);
                let s = s.to_string();
                let sem = Semantic::from_name(&s).map(|x| x.name()).or_else(|| {
                    let names: Vec<&str> = Semantic::ALL.iter().map(|x| x.name()).collect();
                    did_you_mean(&s, &names)
                });
                if let (Some(sem), Some(d)) = (sem, self.diags.last_mut()) {
                    d.help = Some(format!("to bind a value the runtime provides, write `{{ semantic = \"{sem}\" }}`"));
                }
                None
            }
            DeValue::Datetime(_) | DeValue::Table(_) => {
                self.wrong_type(v, what, EXPECTED);
                None
            }
            DeValue::Array(items) => {
                if depth >= MAX_LIST_DEPTH {
                    self.error(E_VALUE, v.span(), format!("{what}: arrays nest deeper than {MAX_LIST_DEPTH} levels"), "nested too deeply");
                    return None;
                }
                if items.is_empty() {
                    self.error(E_VALUE, v.span(), format!("{what} is an empty array"), "empty array");
                    return None;
                }
                let mut out = Vec::with_capacity(items.len());
                let mut ok = true;
                for item in items.iter() {
                    match self.uniform_value(item, what, depth + 1) {
                        Some(x) => out.push(x),
                        None => ok = false,
                    }
                }
                if !ok {
                    return None;
                }
                // Every element must have the shape of the first (rectangular, one scalar kind).
                let shape = |x: &UniformValue| (x.dims(), matches!(x.scalars().first(), Some(UniformValue::Bool(_))));
                let first = shape(&out[0]);
                if let Some(i) = out.iter().position(|x| shape(x) != first) {
                    let describe = |(dims, is_bool): &(Vec<usize>, bool)| {
                        let scalar = if *is_bool { "a boolean" } else { "a number" };
                        match dims.as_slice() {
                            [] => scalar.to_owned(),
                            d => format!(
                                "an array of {} {}{}",
                                d.iter().map(|n| n.to_string()).collect::<Vec<_>>().join("×"),
                                if *is_bool { "boolean" } else { "number" },
                                if d.iter().product::<usize>() == 1 { "" } else { "s" }
                            ),
                        }
                    };
                    let found = shape(&out[i]);
                    let file = self.file;
                    let d = self.error(
                        E_VALUE,
                        items[i].span(),
                        format!("{what}: array elements must all have the same shape"),
                        format!("this is {}", describe(&found)),
                    );
                    d.labels.push(crate::diag::Label {
                        file,
                        span: items[0].span(),
                        message: format!("the first element is {}", describe(&first)),
                    });
                    return None;
                }
                Some(UniformValue::List(out))
            }
        }
    }

    fn range(&mut self, v: &Val<'_>, what: &str) -> Option<(f64, f64)> {
        const EXPECTED: &str = "an array of two numbers `[min, max]`";
        let DeValue::Array(items) = v.get_ref() else {
            self.wrong_type(v, what, EXPECTED);
            return None;
        };
        if items.len() != 2 {
            self.error(E_VALUE, v.span(), format!("{what} must be {EXPECTED}, found {} element(s)", items.len()), "expected `[min, max]`");
            return None;
        }
        let lo = self.number(&items[0], &format!("{what} lower bound"));
        let hi = self.number(&items[1], &format!("{what} upper bound"));
        let (lo, hi) = (lo?, hi?);
        if lo > hi {
            let d =
                self.error(E_VALUE, v.span(), format!("{what} is empty: lower bound {lo} is greater than upper bound {hi}"), "min > max");
            d.help = Some(format!("write the range as `[{hi}, {lo}]`"));
            return None;
        }
        Some((lo, hi))
    }

    fn textures(&mut self, t: &DeTable<'_>) -> Vec<TextureDecl> {
        let mut out = Vec::new();
        for (k, v) in entries(t) {
            let name = key(k);
            let name_ok = self.check_uniform_name(name, k.span());
            let what = format!("texture `{name}`");
            let decl = match v.get_ref() {
                DeValue::String(_) => self.file_path(v, &what, E_ASSET_NOT_FOUND, "texture file").map(|path| TextureDecl {
                    name: name.to_owned(),
                    name_span: k.span(),
                    kind: TextureKind::D2,
                    source: TextureSource::File(path),
                    span: v.span(),
                    filter: Filter::default(),
                    wrap: Wrap::default(),
                }),
                DeValue::Table(tt) => self.texture_table(name, k, v, tt),
                _ => {
                    self.wrong_type(v, &what, "an image path or a table");
                    let d = self.diags.last_mut().expect("just pushed");
                    d.help = Some("write `{ file = \"image.png\" }`, `{ cube = [six images] }` or `{ generate = \"checker\" }`".into());
                    None
                }
            };
            if let (Some(d), true) = (decl, name_ok) {
                out.push(d);
            }
        }
        out
    }

    fn texture_table(&mut self, name: &str, k: &Key<'_>, v: &Val<'_>, t: &DeTable<'_>) -> Option<TextureDecl> {
        let mut ok = true;
        let mut sources: Vec<(&'static str, Range<usize>)> = Vec::new();
        let mut file = None;
        let mut faces = None;
        let mut generator = None;
        let mut kind = None;
        let mut params_given: Vec<(&'static str, Range<usize>)> = Vec::new();
        let mut size = DEFAULT_TEXTURE_SIZE;
        let mut params = GeneratorParams::default();
        let mut filter = Filter::default();
        let mut wrap = Wrap::default();
        for (k2, v2) in entries(t) {
            let what = format!("`textures.{name}.{}`", key(k2));
            let what = what.as_str();
            match key(k2) {
                "file" => {
                    sources.push(("file", k2.span()));
                    file = self.file_path(v2, what, E_ASSET_NOT_FOUND, "texture file");
                    ok &= file.is_some();
                }
                "cube" => {
                    sources.push(("cube", k2.span()));
                    faces = self.faces(v2, what);
                    ok &= faces.is_some();
                }
                "generate" => {
                    sources.push(("generate", k2.span()));
                    let choices: Vec<_> = Generator::ALL.iter().map(|g| (g.name(), *g)).collect();
                    generator = self.choice(v2, what, "generator", &choices);
                    ok &= generator.is_some();
                }
                "kind" => {
                    let choices = [("2d", TextureKind::D2), ("cube", TextureKind::Cube)];
                    match self.choice(v2, what, "texture kind", &choices) {
                        Some(x) => kind = Some((x, k2.span())),
                        None => ok = false,
                    }
                }
                p @ ("size" | "colors" | "cells" | "seed" | "octaves") => {
                    let p = GEN_PARAMS.iter().copied().find(|g| *g == p).unwrap_or("size");
                    params_given.push((p, k2.span()));
                    let parsed = match p {
                        "size" => self.uint(v2, what, 1, MAX_TEXTURE_SIZE).map(|n| size = n),
                        "colors" => self.colors(v2, what).map(|c| params.colors = c),
                        "cells" => self.uint(v2, what, 1, MAX_CELLS).map(|n| params.cells = n),
                        "seed" => self.uint(v2, what, 0, u32::MAX).map(|n| params.seed = n),
                        _ => self.uint(v2, what, 1, MAX_OCTAVES).map(|n| params.octaves = n),
                    };
                    ok &= parsed.is_some();
                }
                "filter" => {
                    let choices = [("linear", Filter::Linear), ("nearest", Filter::Nearest)];
                    match self.choice(v2, what, "filter", &choices) {
                        Some(f) => filter = f,
                        None => ok = false,
                    }
                }
                "wrap" => {
                    let choices = [("repeat", Wrap::Repeat), ("clamp", Wrap::Clamp), ("mirror", Wrap::Mirror)];
                    match self.choice(v2, what, "wrap mode", &choices) {
                        Some(w) => wrap = w,
                        None => ok = false,
                    }
                }
                other => {
                    self.unknown_key(other, k2.span(), &format!("in texture `{name}`"), TEXTURE_KEYS);
                    ok = false;
                }
            }
        }
        let source_kind = match sources.as_slice() {
            [] => {
                let d = self.error(E_MISSING, v.span(), format!("texture `{name}` has no source"), "no `file`, `cube` or `generate`");
                d.help = Some("add `file = \"image.png\"`, `cube = [six images]` or `generate = \"checker\"`".into());
                return None;
            }
            [(s, _)] => *s,
            [(_, first), (_, second), ..] => {
                let file_id = self.file;
                let (first, second) = (first.clone(), second.clone());
                let d = self.error(E_CONFLICT, second, format!("texture `{name}` has more than one source"), "second source");
                d.labels.push(crate::diag::Label { file: file_id, span: first, message: "first source".into() });
                d.help = Some("keep exactly one of `file`, `cube` and `generate`".into());
                return None;
            }
        };
        // Kind: `cube = [...]` is a cube; `file` is 2D; `generate` is either (default 2D).
        let natural = if source_kind == "cube" { TextureKind::Cube } else { TextureKind::D2 };
        let tex_kind = match kind {
            Some((want, span)) if source_kind != "generate" && want != natural => {
                let msg = match source_kind {
                    "cube" => {
                        format!("texture `{name}` lists six cube faces but says `kind = \"2d\"`")
                    }
                    _ => format!("texture `{name}` is a single image but says `kind = \"cube\"`"),
                };
                let d = self.error(E_CONFLICT, span, msg, "conflicts with the source");
                d.help = Some("a cube map comes from `cube = [six images]` or from `generate` with `kind = \"cube\"`".into());
                ok = false;
                natural
            }
            Some((want, _)) => want,
            None => natural,
        };
        if source_kind != "generate" {
            for (p, span) in &params_given {
                let d = self.error(
                    E_CONFLICT,
                    span.clone(),
                    format!("`{p}` only applies to generated textures"),
                    format!("texture `{name}` is loaded from {}", if source_kind == "cube" { "images" } else { "a file" }),
                );
                d.help = Some(format!("remove `{p}`"));
                ok = false;
            }
        } else if let Some(g) = generator {
            for (p, span) in &params_given {
                if *p != "size" && !g.params().contains(p) {
                    let d = self.warning(
                        W_UNUSED_PARAM,
                        span.clone(),
                        format!("`{p}` has no effect on the `{}` generator", g.name()),
                        "ignored",
                    );
                    d.notes.push(format!("`{}` uses: size, {}", g.name(), g.params().join(", ")));
                }
            }
        }
        if !ok {
            return None;
        }
        let source = match source_kind {
            "file" => TextureSource::File(file?),
            "cube" => TextureSource::Faces(faces?),
            _ => TextureSource::Generated { generator: generator?, size, params },
        };
        Some(TextureDecl { name: name.to_owned(), name_span: k.span(), kind: tex_kind, source, span: v.span(), filter, wrap })
    }

    fn faces(&mut self, v: &Val<'_>, what: &str) -> Option<[PathBuf; 6]> {
        let DeValue::Array(items) = v.get_ref() else {
            self.wrong_type(v, what, "an array of six image paths");
            let d = self.diags.last_mut().expect("just pushed");
            d.notes.push(format!("faces are listed in the order {FACE_ORDER}"));
            return None;
        };
        if items.len() != 6 {
            let d = self.error(E_VALUE, v.span(), format!("{what} needs exactly six images, found {}", items.len()), "expected six paths");
            d.notes.push(format!("faces are listed in the order {FACE_ORDER}"));
            return None;
        }
        let paths: Vec<Option<PathBuf>> =
            items.iter().map(|item| self.file_path(item, what, E_ASSET_NOT_FOUND, "cube face image")).collect();
        let paths: Option<Vec<PathBuf>> = paths.into_iter().collect();
        paths?.try_into().ok()
    }

    /// `colors = [a, b]` (each 3 or 4 numbers), `colors = [a]`, or a single colour `[r, g, b(, a)]`.
    fn colors(&mut self, v: &Val<'_>, what: &str) -> Option<[[f32; 4]; 2]> {
        const EXPECTED: &str = "one or two colours of 3 or 4 numbers (`[[1, 0, 0], [0, 0, 1]]`)";
        let DeValue::Array(items) = v.get_ref() else {
            self.wrong_type(v, what, EXPECTED);
            return None;
        };
        let mut out = GeneratorParams::default().colors;
        let single = items.first().is_some_and(|i| !matches!(i.get_ref(), DeValue::Array(_)));
        let colours: Vec<&Val<'_>> = if single { vec![v] } else { items.iter().collect() };
        if colours.is_empty() || colours.len() > 2 {
            self.error(E_VALUE, v.span(), format!("{what} must be {EXPECTED}"), format!("found {} colours", colours.len()));
            return None;
        }
        let mut ok = true;
        for (slot, c) in colours.into_iter().enumerate() {
            match self.colour(c, what) {
                Some(rgba) => out[slot] = rgba,
                None => ok = false,
            }
        }
        ok.then_some(out)
    }

    fn colour(&mut self, v: &Val<'_>, what: &str) -> Option<[f32; 4]> {
        let DeValue::Array(items) = v.get_ref() else {
            self.wrong_type(v, what, "a colour of 3 or 4 numbers");
            return None;
        };
        if !(3..=4).contains(&items.len()) {
            self.error(
                E_VALUE,
                v.span(),
                format!("{what}: a colour has 3 or 4 components, found {}", items.len()),
                "expected [r, g, b] or [r, g, b, a]",
            );
            return None;
        }
        let mut rgba = [1.0f32; 4];
        let mut ok = true;
        for (i, item) in items.iter().enumerate() {
            match self.number(item, what) {
                Some(x) if (x as f32).is_finite() => rgba[i] = x as f32,
                Some(_) => {
                    self.error(E_VALUE, item.span(), format!("{what}: component is too large"), "beyond f32 range");
                    ok = false;
                }
                None => ok = false,
            }
        }
        ok.then_some(rgba)
    }

    fn mesh(&mut self, v: &Val<'_>) -> Option<MeshDecl> {
        let builtin_choices: Vec<(&'static str, &'static str)> = BuiltinMesh::NAMES.iter().map(|n| (*n, *n)).collect();
        match v.get_ref() {
            DeValue::String(_) => {
                let name = self.choice(v, "`mesh`", "builtin mesh", &builtin_choices)?;
                let source = MeshSource::Builtin(builtin(name, None, None, None));
                Some(MeshDecl { span: v.span(), source, attributes: Vec::new(), attribute_spans: Vec::new() })
            }
            DeValue::Table(t) => self.mesh_table(v, t, &builtin_choices),
            _ => {
                self.wrong_type(v, "`mesh`", "a table (or a builtin mesh name)");
                None
            }
        }
    }

    fn mesh_table(&mut self, v: &Val<'_>, t: &DeTable<'_>, builtin_choices: &[(&'static str, &'static str)]) -> Option<MeshDecl> {
        let mut ok = true;
        let mut sources: Vec<(&'static str, Range<usize>)> = Vec::new();
        let mut builtin_name = None;
        let mut obj = None;
        let mut segments = None;
        let mut rings = None;
        let mut divisions = None;
        let mut attributes = Vec::new();
        let mut attribute_spans = Vec::new();
        for (k, v2) in entries(t) {
            let what = format!("`mesh.{}`", key(k));
            let what = what.as_str();
            match key(k) {
                "builtin" => {
                    sources.push(("builtin", k.span()));
                    builtin_name = self.choice(v2, what, "builtin mesh", builtin_choices);
                    ok &= builtin_name.is_some();
                }
                "obj" => {
                    sources.push(("obj", k.span()));
                    obj = self.file_path(v2, what, E_ASSET_NOT_FOUND, "mesh file");
                    ok &= obj.is_some();
                }
                "segments" => {
                    segments = self.uint(v2, what, 3, MAX_MESH_DIVISIONS).map(|n| (n, k.span()));
                    ok &= segments.is_some();
                }
                "rings" => {
                    rings = self.uint(v2, what, 2, MAX_MESH_DIVISIONS).map(|n| (n, k.span()));
                    ok &= rings.is_some();
                }
                "divisions" => {
                    divisions = self.uint(v2, what, 1, MAX_MESH_DIVISIONS).map(|n| (n, k.span()));
                    ok &= divisions.is_some();
                }
                "attributes" => {
                    let Some(at) = self.table(v2, what) else {
                        ok = false;
                        continue;
                    };
                    let choices: Vec<(&'static str, &'static str)> = MESH_ATTRIBUTES.iter().map(|n| (*n, *n)).collect();
                    for (ak, av) in entries(at) {
                        let input = key(ak);
                        if !is_ident(input) || input.starts_with("gl_") {
                            self.error(E_VALUE, ak.span(), format!("`{input}` is not a vertex shader input name"), "not a GLSL identifier");
                            ok = false;
                            continue;
                        }
                        match self.choice(av, &format!("`mesh.attributes.{input}`"), "mesh attribute", &choices) {
                            Some(attr) => {
                                attributes.push((input.to_owned(), attr.to_owned()));
                                attribute_spans.push(ak.span());
                            }
                            None => ok = false,
                        }
                    }
                }
                other => {
                    self.unknown_key(other, k.span(), "in `[mesh]`", MESH_KEYS);
                    ok = false;
                }
            }
        }
        match sources.as_slice() {
            [] => {
                let d = self.error(E_MISSING, v.span(), "`[mesh]` needs `builtin` or `obj`".into(), "no mesh source");
                d.help = Some(format!("add e.g. `builtin = \"uv_sphere\"`; builtins: {}", list(&BuiltinMesh::NAMES)));
                return None;
            }
            [_] => {}
            [(_, first), (_, second), ..] => {
                let file = self.file;
                let (first, second) = (first.clone(), second.clone());
                let d = self.error(E_CONFLICT, second, "`[mesh]` has both `builtin` and `obj`".into(), "second source");
                d.labels.push(crate::diag::Label { file, span: first, message: "first source".into() });
                d.help = Some("keep one of `builtin` and `obj`".into());
                return None;
            }
        }
        // Shape parameters must belong to the chosen builtin.
        let is = |n: &str| builtin_name == Some(n);
        let mut misplaced = |key: &str, span: &Option<(u32, Range<usize>)>, owner: &str, applies: bool| {
            if let (Some((_, span)), false) = (span, applies) {
                let d = self.error(
                    E_CONFLICT,
                    span.clone(),
                    format!("`{key}` only applies to `builtin = \"{owner}\"`"),
                    "not used by this mesh",
                );
                d.help = Some(format!("remove `{key}`"));
                false
            } else {
                true
            }
        };
        let mut fine = misplaced("segments", &segments, "uv_sphere", is("uv_sphere"));
        fine &= misplaced("rings", &rings, "uv_sphere", is("uv_sphere"));
        fine &= misplaced("divisions", &divisions, "plane_grid", is("plane_grid"));
        if !(ok && fine) {
            return None;
        }
        let source = match (builtin_name, obj) {
            (Some(n), _) => MeshSource::Builtin(builtin(n, segments.map(|s| s.0), rings.map(|r| r.0), divisions.map(|d| d.0))),
            (None, Some(path)) => MeshSource::Obj(path),
            (None, None) => return None,
        };
        Some(MeshDecl { span: v.span(), source, attributes, attribute_spans })
    }
}

fn builtin(name: &str, segments: Option<u32>, rings: Option<u32>, divisions: Option<u32>) -> BuiltinMesh {
    match name {
        "fullscreen_quad" => BuiltinMesh::FullscreenQuad,
        "fullscreen_triangle" => BuiltinMesh::FullscreenTriangle,
        "quad" => BuiltinMesh::Quad,
        "cube" => BuiltinMesh::Cube,
        "uv_sphere" => BuiltinMesh::UvSphere {
            segments: segments.unwrap_or(BuiltinMesh::DEFAULT_SEGMENTS),
            rings: rings.unwrap_or(BuiltinMesh::DEFAULT_RINGS),
        },
        _ => BuiltinMesh::PlaneGrid { divisions: divisions.unwrap_or(BuiltinMesh::DEFAULT_DIVISIONS) },
    }
}

/// The effect name when the manifest gives none: the directory's name.
fn default_name(dir: &Path) -> String {
    let name = dir.file_name().map(|n| n.to_owned()).or_else(|| dir.canonicalize().ok()?.file_name().map(|n| n.to_owned()));
    name.map(|n| n.to_string_lossy().into_owned()).unwrap_or_else(|| "effect".to_owned())
}
