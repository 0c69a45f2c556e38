//! The multi-pass sections of the manifest: `[targets]`, `[[passes]]` and `output`.
//!
//! Only the shape of each entry is checked here. Whether the graph holds together (targets
//! that exist, read after written, no cycles, formats that fit the samplers and outputs)
//! needs the shaders too and is checked in `link::graph_rules`.

use std::ops::Range;

use toml::de::{DeTable, DeValue};

use super::scene::{BLEND_CHOICES, CULL_CHOICES};
use super::{entries, key, list, Ctx, Val};
use crate::diag::Code;
use crate::manifest::{Filter, PassClear, PassDecl, PassDraw, SampleDecl, TargetDecl, TargetFormat, TargetRef, TargetSize, MAX_FRAME_SIDE};

const TARGET_KEYS: &[&str] = &["format", "scale", "size"];
const PASS_KEYS: &[&str] = &[
    "name",
    "effect",
    "stages",
    "draw",
    "mesh",
    "instances",
    "model",
    "uniforms",
    "targets",
    "depth",
    "samples",
    "blend",
    "cull",
    "depth_write",
    "depth_compare",
    "clear",
];
const SAMPLE_KEYS: &[&str] = &["target", "filter"];
/// A target may be at most this many times the output size per side.
const MAX_SCALE: f32 = 4.0;

impl Ctx<'_> {
    /// `[targets]`: `name = { format = "rgba16f", scale = 0.5 }` (or `size = [w, h]`).
    pub(super) fn targets(&mut self, t: &DeTable<'_>) -> Vec<TargetDecl> {
        let mut out = Vec::new();
        for (k, v) in entries(t) {
            let name = key(k);
            if !super::is_ident(name) {
                self.report(Code::ManifestValue, k.span(), format!("`{name}` is not a valid target name"), "use letters, digits and `_`");
                continue;
            }
            let Some(spec) = self.table(v, &format!("target `{name}`")) else { continue };
            let mut format = TargetFormat::Rgba8;
            let mut size = TargetSize::Scale(1.0);
            let mut size_keys: Vec<Range<usize>> = Vec::new();
            let mut ok = true;
            for (k2, v2) in entries(spec) {
                let what = format!("`targets.{name}.{}`", key(k2));
                match key(k2) {
                    "format" => match self.target_format(v2, &what) {
                        Some(f) => format = f,
                        None => ok = false,
                    },
                    "scale" => {
                        size_keys.push(k2.span());
                        match self.float(v2, &what) {
                            Some(s) if s > 0.0 && s <= MAX_SCALE => size = TargetSize::Scale(s),
                            Some(_) => {
                                self.report(
                                    Code::ManifestValue,
                                    v2.span(),
                                    format!("{what} must be in (0, {MAX_SCALE}]"),
                                    "not a usable scale",
                                );
                                ok = false;
                            }
                            None => ok = false,
                        }
                    }
                    "size" => {
                        size_keys.push(k2.span());
                        match v2.get_ref() {
                            DeValue::Array(items) if items.len() == 2 => {
                                match (self.uint(&items[0], &what, 1, MAX_FRAME_SIDE), self.uint(&items[1], &what, 1, MAX_FRAME_SIDE)) {
                                    (Some(w), Some(h)) => size = TargetSize::Absolute(w, h),
                                    _ => ok = false,
                                }
                            }
                            _ => {
                                self.wrong_type(v2, &what, "`[width, height]`");
                                ok = false;
                            }
                        }
                    }
                    other => {
                        self.unknown_key(other, k2.span(), &format!("in target `{name}`"), TARGET_KEYS);
                        ok = false;
                    }
                }
            }
            if size_keys.len() > 1 {
                let d = self.report(
                    Code::ManifestConflict,
                    size_keys[1].clone(),
                    format!("target `{name}` has both `scale` and `size`"),
                    "second size",
                );
                d.help = Some("give either a scale of the output size or an absolute `size`".into());
                ok = false;
            }
            if ok {
                out.push(TargetDecl { name: name.to_owned(), name_span: k.span(), format, size });
            }
        }
        out
    }

    fn target_format(&mut self, v: &Val<'_>, what: &str) -> Option<TargetFormat> {
        let choices: Vec<(&'static str, TargetFormat)> = TargetFormat::ALL.iter().map(|f| (f.name(), *f)).collect();
        self.choice(v, what, "target format", &choices)
    }

    /// `[[passes]]`: an array of pass tables.
    pub(super) fn passes(&mut self, v: &Val<'_>) -> Vec<PassDecl> {
        let DeValue::Array(items) = v.get_ref() else {
            self.wrong_type(v, "`passes`", "an array of tables (`[[passes]]`)");
            return Vec::new();
        };
        let mut out: Vec<PassDecl> = Vec::new();
        for (i, item) in items.iter().enumerate() {
            let Some(t) = self.table(item, &format!("pass {}", i + 1)) else { continue };
            let Some(pass) = self.pass(item, t, i) else { continue };
            if let Some(first) = out.iter().find(|p| p.name == pass.name) {
                let file = self.file;
                let d = self.report(
                    Code::ManifestValue,
                    pass.name_span.clone(),
                    format!("two passes are named `{}`", pass.name),
                    "second pass of this name",
                );
                d.labels.push(crate::diag::Label { file, span: first.name_span.clone(), message: "first one".into() });
                continue;
            }
            out.push(pass);
        }
        out
    }

    fn pass(&mut self, v: &Val<'_>, t: &DeTable<'_>, index: usize) -> Option<PassDecl> {
        let mut pass = new_pass(v, index);
        let mut ok = true;
        let mut stages_key = None;
        let mut uniforms_key = None;
        for (k, v2) in entries(t) {
            let what = format!("`passes.{}`", key(k));
            let what = what.as_str();
            match key(k) {
                "name" => match self.string(v2, what) {
                    Some(s) if super::is_ident(&s.replace('-', "_")) => {
                        pass.name = s.to_owned();
                        pass.name_span = v2.span();
                    }
                    Some(_) => {
                        let shown = self.string(v2, what).unwrap_or_default().to_owned();
                        self.report(
                            Code::ManifestValue,
                            v2.span(),
                            format!("`{shown}` is not a valid pass name"),
                            "use letters, digits, `_` and `-`",
                        );
                        ok = false;
                    }
                    None => ok = false,
                },
                "effect" => match self.reused_effect(v2) {
                    Some(p) => pass.reuse = Some((p, v2.span())),
                    None => ok = false,
                },
                "stages" => {
                    stages_key = Some(k.span());
                    match self.table(v2, what) {
                        Some(st) => pass.stages = self.stages(st),
                        None => ok = false,
                    }
                }
                "draw" => {
                    let choices = [("mesh", PassDraw::Mesh), ("fullscreen", PassDraw::Fullscreen)];
                    match self.choice(v2, what, "draw", &choices) {
                        Some(d) => pass.draw = d,
                        None => ok = false,
                    }
                }
                "mesh" => pass.mesh = self.mesh(v2),
                "instances" => pass.instances = self.instances(v2),
                "model" => pass.model = self.model(v2),
                "uniforms" => {
                    uniforms_key = Some(k.span());
                    if let Some(ut) = self.table(v2, what) {
                        pass.uniforms = self.uniforms(ut);
                    }
                }
                "targets" => {
                    pass.targets_span = Some(v2.span());
                    match v2.get_ref() {
                        DeValue::Array(items) => {
                            for item in items {
                                if let Some(r) = self.target_ref(item, what) {
                                    pass.targets.push(r);
                                }
                            }
                        }
                        DeValue::String(_) => pass.targets.extend(self.target_ref(v2, what)),
                        _ => {
                            self.wrong_type(v2, what, "an array of target names");
                            ok = false;
                        }
                    }
                }
                "depth" => pass.depth = self.target_ref(v2, what),
                "samples" => match self.table(v2, what) {
                    Some(st) => pass.samples = self.samples(st),
                    None => ok = false,
                },
                "blend" => pass.blend = self.choice(v2, what, "blend mode", BLEND_CHOICES),
                "cull" => pass.cull = self.choice(v2, what, "cull mode", CULL_CHOICES),
                "depth_write" => pass.depth_write = self.boolean(v2, what),
                "depth_compare" => pass.depth_compare = self.choice(v2, what, "depth comparison", crate::manifest::DepthCompare::CHOICES),
                "clear" => match v2.get_ref() {
                    DeValue::Boolean(false) => pass.clear = PassClear::Keep,
                    DeValue::Boolean(true) => pass.clear = PassClear::Default,
                    DeValue::Array(items) if items.len() == 3 => {
                        if let Some(c) = self.floats::<3>(v2, what) {
                            pass.clear = PassClear::Color([c[0], c[1], c[2], 1.0]);
                        }
                    }
                    _ => {
                        if let Some(c) = self.floats::<4>(v2, what) {
                            pass.clear = PassClear::Color(c);
                        }
                    }
                },
                other => {
                    self.unknown_key(other, k.span(), "in a pass", PASS_KEYS);
                    ok = false;
                }
            }
        }
        let ok = self.check_pass(&pass, stages_key, uniforms_key, ok);
        ok.then_some(pass)
    }

    /// What a pass's keys say together: exactly one of `effect` and `stages`, no uniforms
    /// on a reused effect, and some target written. Returns `ok`, false once an error is reported.
    fn check_pass(&mut self, pass: &PassDecl, stages_key: Option<Range<usize>>, uniforms_key: Option<Range<usize>>, mut ok: bool) -> bool {
        let name = pass.name.clone();
        match (&pass.reuse, stages_key) {
            (Some((_, span)), Some(stages)) => {
                let file = self.file;
                let d = self.report(
                    Code::ManifestConflict,
                    span.clone(),
                    format!("pass `{name}` has both `effect` and `stages`"),
                    "reuses an effect",
                );
                d.labels.push(crate::diag::Label { file, span: stages, message: "and names stages".into() });
                d.help = Some("a pass either reuses another effect's stages or names its own".into());
                ok = false;
            }
            (None, None) => {
                let d = self.report(Code::ManifestMissing, pass.name_span.clone(), format!("pass `{name}` names no stages"), "no stages");
                d.help = Some("add `stages = { vertex = \"a.vert\", fragment = \"a.frag\" }` or `effect = \"../other\"`".into());
                ok = false;
            }
            _ => {}
        }
        if let (Some(_), Some(span)) = (&pass.reuse, uniforms_key) {
            let d = self.report(Code::ManifestConflict, span, format!("pass `{name}` reuses an effect and sets uniforms"), "uniforms here");
            d.notes.push("a reused effect keeps its own manifest's uniforms, textures and mesh".into());
            d.help = Some("change the values in the reused effect's manifest, or give this pass its own stages".into());
            ok = false;
        }
        if pass.targets.is_empty() && pass.depth.is_none() && ok {
            let d = self.report(Code::ManifestMissing, pass.name_span.clone(), format!("pass `{name}` writes no target"), "no `targets`");
            d.help = Some("add `targets = [\"name\"]` with names from [targets]".into());
            ok = false;
        }
        ok
    }

    /// `effect = "../sun"` or `"../sun/effect.toml"`: the manifest must exist.
    fn reused_effect(&mut self, v: &Val<'_>) -> Option<std::path::PathBuf> {
        let rel = self.string(v, "`passes.effect`")?;
        let mut path = self.dir.join(rel);
        if !self.confined(&path, v, rel, "the reused effect") {
            return None;
        }
        if path.is_dir() {
            path = path.join("effect.toml");
            // Its `effect.toml` may itself be a link out.
            if !self.confined(&path, v, rel, "the reused effect") {
                return None;
            }
        }
        if !path.is_file() {
            let d = self.report(Code::AssetNotFound, v.span(), format!("effect not found: `{rel}`"), "no effect.toml here");
            d.notes.push(format!("looked for `{}`", path.display()));
            d.notes.push("give the directory of another effect (or its effect.toml), relative to this manifest".into());
            return None;
        }
        Some(path)
    }

    fn target_ref(&mut self, v: &Val<'_>, what: &str) -> Option<TargetRef> {
        let name = self.string(v, what)?;
        Some(TargetRef { name: name.to_owned(), span: v.span() })
    }

    /// `samples = { sampler = "target" }` or `{ sampler = { target = "t", filter = "nearest" } }`.
    fn samples(&mut self, t: &DeTable<'_>) -> Vec<SampleDecl> {
        let mut out = Vec::new();
        for (k, v) in entries(t) {
            let sampler = key(k);
            if !self.check_uniform_name(sampler, k.span()) {
                continue;
            }
            let what = format!("`samples.{sampler}`");
            let (target, filter) = match v.get_ref() {
                DeValue::String(_) => (self.target_ref(v, &what), Filter::Linear),
                DeValue::Table(spec) => {
                    let mut target = None;
                    let mut filter = Filter::Linear;
                    for (k2, v2) in entries(spec) {
                        match key(k2) {
                            "target" => target = self.target_ref(v2, &what),
                            "filter" => {
                                let choices = [("linear", Filter::Linear), ("nearest", Filter::Nearest)];
                                filter = self.choice(v2, &what, "filter", &choices).unwrap_or_default();
                            }
                            other => self.unknown_key(other, k2.span(), &format!("in {what}"), SAMPLE_KEYS),
                        }
                    }
                    if target.is_none() {
                        self.report(Code::ManifestMissing, v.span(), format!("{what} names no `target`"), "no target");
                    }
                    (target, filter)
                }
                _ => {
                    self.wrong_type(v, &what, "a target name or `{ target = \"…\", filter = \"…\" }`");
                    (None, Filter::Linear)
                }
            };
            if let Some(target) = target {
                out.push(SampleDecl { sampler: sampler.to_owned(), sampler_span: k.span(), target, filter });
            }
        }
        out
    }

    /// Rules between the multi-pass keys and the rest of the top level.
    pub(super) fn check_pass_keys(
        &mut self,
        passes: &[PassDecl],
        has_stages: Option<Range<usize>>,
        output: &Option<TargetRef>,
        targets_key: Option<Range<usize>>,
        passes_key: Option<Range<usize>>,
    ) {
        match (passes_key, has_stages) {
            (Some(p), Some(s)) => {
                let file = self.file;
                let d = self.report(Code::ManifestConflict, s, "`[stages]` and `[[passes]]` in one manifest".into(), "top-level stages");
                d.labels.push(crate::diag::Label { file, span: p, message: "passes".into() });
                d.help = Some("a multi-pass effect names the stages in each pass".into());
            }
            (Some(p), None) if output.is_none() && !passes.is_empty() => {
                let names: Vec<&str> = passes.iter().flat_map(|p| p.targets.iter().map(|t| t.name.as_str())).collect();
                let d = self.report(Code::ManifestMissing, p, "a multi-pass effect needs `output`".into(), "passes without an output");
                d.help = Some(match names.last() {
                    Some(last) => format!("add `output = \"{last}\"` at the top level (targets written: {})", list(&names)),
                    None => "add `output = \"<target>\"` at the top level".into(),
                });
            }
            (None, _) => {
                if let Some(o) = output {
                    self.report(Code::ManifestConflict, o.span.clone(), "`output` needs `[[passes]]`".into(), "no passes");
                }
                if let Some(t) = targets_key {
                    self.report(Code::ManifestConflict, t, "`[targets]` needs `[[passes]]`".into(), "no passes");
                }
            }
            _ => {}
        }
    }
}

/// Pass number `index` (from 0) with nothing set yet: named `pass<index + 1>`, drawing the mesh.
fn new_pass(v: &Val<'_>, index: usize) -> PassDecl {
    PassDecl {
        name: format!("pass{}", index + 1),
        name_span: v.span(),
        span: v.span(),
        stages: Vec::new(),
        reuse: None,
        draw: PassDraw::Mesh,
        mesh: None,
        instances: None,
        model: None,
        uniforms: Vec::new(),
        targets: Vec::new(),
        targets_span: None,
        depth: None,
        samples: Vec::new(),
        blend: None,
        cull: None,
        depth_write: None,
        depth_compare: None,
        clear: PassClear::Default,
    }
}
