//! Checks on the pass graph of a multi-pass effect, each reported at the manifest span it
//! concerns (with the shader declaration as a second label where one is involved).
//!
//! | code    | meaning |
//! |---------|---------|
//! | `E0240` | a pass or `output` names a target `[targets]` does not declare |
//! | `E0241` | a pass reads a target no earlier pass writes (or `output` is never written) |
//! | `E0242` | a cycle: a pass samples a target it draws into, or reads what a later pass makes from its own results |
//! | `E0243` | a format that does not fit: a sampler or fragment output of another kind than the target, a depth target used as colour or the reverse |
//! | `E0244` | the fragment stage's outputs do not match the pass's `targets` (MRT count / locations) |
//! | `E0245` | a `samples` entry names no sampler uniform of the pass's stages |
//! | `E0246` | the attachments of one pass have different sizes |
//! | `W0240` | a pass whose results never reach `output` (it is skipped) |
//! | `N0241` | an MRT attachment nobody reads later (it is not attached) |
//!
//! Top-level `[uniforms]` / `[textures]` entries no pass declares are reported with the
//! single-pass codes (`E0220`, `E0224`).

use std::collections::BTreeSet;

use crate::diag::{Code, Diagnostic, FileId};
use crate::front::syntax::{StageSyntax, Storage};
use crate::graph;
use crate::manifest::{did_you_mean, Effect, PassDecl, SampleKind, TargetRef, TargetSize};
use crate::stage::StageKind;

/// What the shaders of one pass tell the graph checks (`None` when they did not compile).
pub struct PassShaders<'a> {
    pub stages: Option<&'a [StageSyntax]>,
}

/// Checks the graph of `effect` (which has passes); `shaders` is index for index with
/// `effect.passes`. Also returns the pass plan (at output size 1×1, see
/// [`graph::PassPlan::sized`]) when the graph has no errors.
pub fn check(effect: &Effect, shaders: &[PassShaders<'_>]) -> (Vec<Diagnostic>, Option<graph::PassPlan>) {
    let mut out = Vec::new();
    let file = effect.file;
    let names: Vec<&str> = effect.targets.iter().map(|t| t.name.as_str()).collect();
    let known = |r: &TargetRef, out: &mut Vec<Diagnostic>| -> bool {
        if effect.target(&r.name).is_some() {
            return true;
        }
        let mut d = Diagnostic::new(Code::PassUnknownTarget, format!("unknown target `{}`", r.name)).at(
            file,
            r.span.clone(),
            "not declared in [targets]",
        );
        d = match did_you_mean(&r.name, &names) {
            Some(s) => d.with_help(format!("did you mean `{s}`?")),
            None if names.is_empty() => d.with_help(format!("declare it: `[targets]` / `{} = {{ format = \"rgba8\" }}`", r.name)),
            None => d.with_note(format!("the targets are {}", quoted(&names))),
        };
        out.push(d);
        false
    };
    let mut all_known = true;
    for pass in &effect.passes {
        for r in pass.targets.iter().chain(&pass.depth).chain(pass.samples.iter().map(|s| &s.target)) {
            all_known &= known(r, &mut out);
        }
    }
    if let Some(o) = &effect.output {
        all_known &= known(o, &mut out);
    }
    for (i, pass) in effect.passes.iter().enumerate() {
        attachment_kinds(effect, pass, &mut out);
        attachment_sizes(effect, pass, &mut out);
        reads(effect, i, &mut out);
        if let Some(stages) = shaders.get(i).and_then(|s| s.stages) {
            samplers(effect, pass, stages, &mut out);
            outputs(effect, pass, stages, &mut out);
        }
    }
    if let Some(o) = effect.output.as_ref().filter(|o| effect.target(&o.name).is_some()) {
        if !effect.passes.iter().any(|p| p.writes(&o.name)) {
            out.push(
                Diagnostic::new(Code::PassReadBeforeWrite, format!("no pass writes the output target `{}`", o.name))
                    .at(file, o.span.clone(), "the frame comes from this target")
                    .with_help("add it to the `targets` of the last pass"),
            );
        } else if effect.target(&o.name).is_some_and(|t| t.format.kind() == SampleKind::Depth) {
            out.push(
                Diagnostic::new(Code::PassFormat, format!("the output `{}` is a depth target", o.name))
                    .at(file, o.span.clone(), "frames are colour images")
                    .with_help("name a colour target as `output`"),
            );
        }
    }
    if !all_known || out.iter().any(Diagnostic::is_error) {
        return (out, None);
    }
    let plan = graph::plan(effect, (1, 1), false);
    pruning(effect, &plan, &mut out);
    (out, Some(plan))
}

/// "an" before a word read with a vowel sound (`an int`, `an rgba8`, `an isampler2D`).
fn article(word: &str) -> &'static str {
    match word.chars().next() {
        Some('a' | 'e' | 'i' | 'o' | 'r') => "an",
        _ => "a",
    }
}

fn quoted(names: &[&str]) -> String {
    names.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", ")
}

/// Colour targets must be colour formats, `depth` a depth format.
fn attachment_kinds(effect: &Effect, pass: &PassDecl, out: &mut Vec<Diagnostic>) {
    for t in &pass.targets {
        if let Some(decl) = effect.target(&t.name).filter(|d| d.format.kind() == SampleKind::Depth) {
            out.push(
                Diagnostic::new(Code::PassFormat, format!("pass `{}` draws colour into the depth target `{}`", pass.name, t.name))
                    .at(effect.file, t.span.clone(), "a colour attachment")
                    .with_label(effect.file, decl.name_span.clone(), format!("`{}` is {}", t.name, decl.format.name()))
                    .with_help(format!("attach it with `depth = \"{}\"`", t.name)),
            );
        }
    }
    if let Some(d) = &pass.depth {
        if let Some(decl) = effect.target(&d.name).filter(|t| t.format.kind() != SampleKind::Depth) {
            out.push(
                Diagnostic::new(Code::PassFormat, format!("pass `{}` uses the colour target `{}` as its depth buffer", pass.name, d.name))
                    .at(effect.file, d.span.clone(), "a depth attachment")
                    .with_label(effect.file, decl.name_span.clone(), format!("`{}` is {}", d.name, decl.format.name()))
                    .with_help("declare a target with `format = \"depth32f\"` for it"),
            );
        }
    }
}

/// All attachments of a pass must have one size.
fn attachment_sizes(effect: &Effect, pass: &PassDecl, out: &mut Vec<Diagnostic>) {
    let attached: Vec<&TargetRef> = pass.targets.iter().chain(&pass.depth).collect();
    let Some((first, first_size)) = attached.iter().find_map(|r| effect.target(&r.name).map(|t| (*r, t.size))) else { return };
    for r in &attached[1..] {
        let Some(t) = effect.target(&r.name) else { continue };
        if t.size != first_size {
            out.push(
                Diagnostic::new(Code::PassSizeMismatch, format!("the attachments of pass `{}` differ in size", pass.name))
                    .at(effect.file, r.span.clone(), size_text(t.size))
                    .with_label(effect.file, first.span.clone(), size_text(first_size))
                    .with_note("every target a pass draws into (colours and depth) must have the same size")
                    .with_help("give these targets the same `scale` or `size`"),
            );
        }
    }
}

fn size_text(s: TargetSize) -> String {
    match s {
        TargetSize::Scale(f) => format!("scale {f} of the output"),
        TargetSize::Absolute(w, h) => format!("{w}×{h} pixels"),
    }
}

/// Every target a pass reads must be written by an earlier pass; no cycles.
fn reads(effect: &Effect, i: usize, out: &mut Vec<Diagnostic>) {
    let pass = &effect.passes[i];
    let file = effect.file;
    for s in &pass.samples {
        if let Some(w) = pass.targets.iter().chain(&pass.depth).find(|t| t.name == s.target.name) {
            out.push(
                Diagnostic::new(Code::PassCycle, format!("pass `{}` samples `{}` while drawing into it", pass.name, s.target.name))
                    .at(file, s.target.span.clone(), "sampled here")
                    .with_label(file, w.span.clone(), "and drawn into here")
                    .with_note("a texture cannot be read and written in one pass (a feedback loop)")
                    .with_help("draw into a second target and sample the first (ping-pong)"),
            );
        }
    }
    let sampled: Vec<&TargetRef> = pass.samples.iter().map(|s| &s.target).collect();
    let kept: Vec<&TargetRef> =
        if pass.clear == crate::manifest::PassClear::Keep { pass.targets.iter().chain(&pass.depth).collect() } else { Vec::new() };
    let mut reported = BTreeSet::new();
    for (r, how) in sampled.iter().map(|r| (*r, "sampled")).chain(kept.iter().map(|r| (*r, "kept (`clear = false`)"))) {
        if effect.target(&r.name).is_none() || graph::writer_before(effect, i, &r.name).is_some() || !reported.insert(&r.name) {
            continue;
        }
        if pass.samples.iter().any(|s| s.target.name == r.name) && pass.writes(&r.name) {
            continue; // the feedback loop above
        }
        if let Some(path) = graph::cycle_through(effect, i, &r.name) {
            let chain: Vec<String> = path.iter().map(|(p, t)| format!("`{}` ← pass `{}`", t, effect.passes[*p].name)).collect();
            let mut d = Diagnostic::new(Code::PassCycle, format!("passes depend on each other in a cycle through `{}`", r.name)).at(
                file,
                r.span.clone(),
                format!("pass `{}` reads `{}` here", pass.name, r.name),
            );
            for (p, t) in &path {
                let later = &effect.passes[*p];
                if let Some(w) = later.targets.iter().chain(&later.depth).find(|x| x.name == *t) {
                    d = d.with_label(file, w.span.clone(), format!("pass `{}` writes `{t}`", later.name));
                }
            }
            out.push(
                d.with_note(format!("pass `{}` reads {}", pass.name, chain.join(", which reads ")))
                    .with_help("break the cycle: one of these passes must read a target written before it"),
            );
            continue;
        }
        let later = (i + 1..effect.passes.len()).find(|&j| effect.passes[j].writes(&r.name));
        let mut d = Diagnostic::new(
            Code::PassReadBeforeWrite,
            format!("pass `{}` reads `{}` before any pass writes it", pass.name, r.name),
        )
        .at(file, r.span.clone(), how);
        d = match later {
            Some(j) => {
                let w = &effect.passes[j];
                let span =
                    w.targets.iter().chain(&w.depth).find(|x| x.name == r.name).map(|x| x.span.clone()).unwrap_or(w.name_span.clone());
                d.with_label(file, span, format!("written only later, by pass `{}`", w.name))
                    .with_note("passes run in manifest order")
                    .with_help(format!("move pass `{}` before pass `{}`", w.name, pass.name))
            }
            None if how.starts_with("kept") => d.with_help("remove `clear = false`, or draw into the target in an earlier pass"),
            None => d.with_help(format!("no pass draws into `{}`: add it to an earlier pass's `targets`", r.name)),
        };
        out.push(d);
    }
}

/// `samples` must name sampler uniforms of the pass, of a type that reads the target's format.
fn samplers(effect: &Effect, pass: &PassDecl, stages: &[StageSyntax], out: &mut Vec<Diagnostic>) {
    let declared = crate::link::declared::declared(stages);
    for s in &pass.samples {
        let Some(ty) = declared.sampler(&s.sampler) else {
            let names: Vec<&str> = declared.samplers.iter().map(|(n, _)| n.as_str()).collect();
            let mut d = Diagnostic::new(
                Code::PassUnknownSampler,
                format!("pass `{}` binds `{}`, but its stages declare no sampler of that name", pass.name, s.sampler),
            )
            .at(effect.file, s.sampler_span.clone(), "no such sampler");
            d = match did_you_mean(&s.sampler, &names) {
                Some(c) => d.with_help(format!("did you mean `{c}`?")),
                None if names.is_empty() => d.with_note("the pass's stages declare no sampler uniform"),
                None => d.with_note(format!("the samplers are {}", quoted(&names))),
            };
            out.push(d);
            continue;
        };
        let Some(target) = effect.target(&s.target.name) else { continue };
        let kind = target.format.kind();
        let decl = sampler_decl(stages, &s.sampler);
        if kind == SampleKind::Depth {
            let mut d = Diagnostic::new(Code::PassFormat, format!("`{}` is a depth target and cannot be sampled", s.target.name))
                .at(effect.file, s.target.span.clone(), format!("{} target", target.format.name()))
                .with_note("effectc attaches depth targets with `depth = …` only")
                .with_help("write what the later pass needs (depth, position) into a colour target such as rgba16f or r32f");
            if let Some((f, span)) = decl {
                d = d.with_label(f, span, format!("`{}` is a `{}`", s.sampler, ty.base));
            }
            out.push(d);
            continue;
        }
        if ty.base != kind.sampler() {
            let mut d = Diagnostic::new(
                Code::PassFormat,
                format!(
                    "`{}` is {} `{}`, but target `{}` is {}",
                    s.sampler,
                    article(&ty.base),
                    ty.base,
                    s.target.name,
                    target.format.name()
                ),
            )
            .at(effect.file, s.target.span.clone(), format!("{} {} target", article(target.format.name()), target.format.name()))
            .with_label(effect.file, target.name_span.clone(), format!("declared {} here", target.format.name()))
            .with_help(format!(
                "read {} {} target through `{}`",
                article(target.format.name()),
                target.format.name(),
                kind.sampler()
            ));
            if let Some((f, span)) = decl {
                d = d.with_label(f, span, format!("declared `{}` here", ty.base));
            }
            if ty.base.starts_with("sampler") && kind != SampleKind::Float || ty.base.starts_with('i') || ty.base.starts_with('u') {
                d = d
                    .with_note("float and normalised formats are read by `sampler2D`, `*i` formats by `isampler2D`, `*ui` by `usampler2D`");
            }
            out.push(d);
        }
    }
}

fn sampler_decl(stages: &[StageSyntax], name: &str) -> Option<(FileId, std::ops::Range<usize>)> {
    stages.iter().find_map(|s| {
        s.globals.iter().find(|g| g.storage == Storage::Uniform && s.original_name(&g.name) == name).map(|g| (s.file, g.name_span.clone()))
    })
}

/// One fragment output location: its declaration and scalar kind.
struct OutputSlot {
    location: u32,
    file: FileId,
    span: std::ops::Range<usize>,
    name: String,
    kind: SampleKind,
}

fn fragment_outputs(stages: &[StageSyntax]) -> Option<Vec<OutputSlot>> {
    let frag = stages.iter().find(|s| s.stage == StageKind::Fragment)?;
    let mut slots = Vec::new();
    let mut next = 0u32;
    for g in frag.globals.iter().filter(|g| g.storage == Storage::Out && g.block.is_none()) {
        let name = frag.original_name(&g.name);
        if name.starts_with("gl_") {
            continue;
        }
        let count = g.ty.dims.first().copied().flatten().unwrap_or(1).max(1);
        let start = g.location.unwrap_or(next);
        let base = g.ty.base.as_str();
        let kind = if base.starts_with('i') {
            SampleKind::Sint
        } else if base.starts_with('u') {
            SampleKind::Uint
        } else {
            SampleKind::Float
        };
        for k in 0..count {
            let shown = if g.ty.is_array() { format!("{name}[{k}]") } else { name.to_string() };
            slots.push(OutputSlot { location: start + k, file: frag.file, span: g.name_span.clone(), name: shown, kind });
        }
        next = start + count;
    }
    Some(slots)
}

/// The fragment outputs must be exactly the pass's colour targets, of fitting kinds.
fn outputs(effect: &Effect, pass: &PassDecl, stages: &[StageSyntax], out: &mut Vec<Diagnostic>) {
    let Some(slots) = fragment_outputs(stages) else { return };
    // gl_FragColor (no declared output) writes location 0.
    let locations: BTreeSet<u32> = if slots.is_empty() { [0].into() } else { slots.iter().map(|s| s.location).collect() };
    let wanted: BTreeSet<u32> = (0..pass.targets.len() as u32).collect();
    if locations != wanted {
        let span = pass.targets_span.clone().unwrap_or(pass.name_span.clone());
        let listed: Vec<String> = slots.iter().map(|s| format!("{} at location {}", s.name, s.location)).collect();
        let mut d = Diagnostic::new(
            Code::PassOutputCount,
            format!(
                "pass `{}` has {} target{}, but its fragment stage writes {} output{}",
                pass.name,
                pass.targets.len(),
                if pass.targets.len() == 1 { "" } else { "s" },
                locations.len(),
                if locations.len() == 1 { "" } else { "s" }
            ),
        )
        .at(effect.file, span, format!("{} target{}", pass.targets.len(), if pass.targets.len() == 1 { "" } else { "s" }));
        if let Some(first) = slots.first() {
            d = d.with_label(first.file, first.span.clone(), format!("outputs: {}", listed.join(", ")));
        }
        out.push(
            d.with_note("output location N is drawn into the N-th entry of `targets`")
                .with_help("list one target per fragment output, in location order"),
        );
        return;
    }
    for s in &slots {
        let Some(t) = pass.targets.get(s.location as usize) else { continue };
        let Some(decl) = effect.target(&t.name) else { continue };
        let kind = decl.format.kind();
        if kind != SampleKind::Depth && kind != s.kind {
            out.push(
                Diagnostic::new(
                    Code::PassFormat,
                    format!("output `{}` is {}-valued, but target `{}` is {}", s.name, s.kind.output_scalar(), t.name, decl.format.name()),
                )
                .at(effect.file, t.span.clone(), format!("{} {} target", article(decl.format.name()), decl.format.name()))
                .with_label(s.file, s.span.clone(), format!("{} {} output", article(s.kind.output_scalar()), s.kind.output_scalar()))
                .with_help(format!("write a {} vector to it, or choose a matching format", kind.output_scalar())),
            );
        }
    }
}

/// Passes that never reach the output, and attachments nobody reads.
fn pruning(effect: &Effect, plan: &graph::PassPlan, out: &mut Vec<Diagnostic>) {
    for (i, pass) in effect.passes.iter().enumerate() {
        if !plan.runs[i] {
            out.push(
                Diagnostic::new(Code::PassUnused, format!("pass `{}` does not contribute to the output: it is skipped", pass.name))
                    .at(effect.file, pass.name_span.clone(), "skipped")
                    .with_note(format!("nothing it writes ({}) is read by a later pass or is the output", quoted(&graph::written(pass))))
                    .with_help("remove the pass, or sample its target in a later pass"),
            );
            continue;
        }
        for (t, on) in pass.targets.iter().zip(&plan.attached[i]) {
            if !on {
                out.push(
                    Diagnostic::new(
                        Code::AttachmentDropped,
                        format!("target `{}` of pass `{}` is never read: it is not attached", t.name, pass.name),
                    )
                    .at(effect.file, t.span.clone(), "dropped")
                    .with_note("the fragment output at this location is discarded"),
                );
            }
        }
    }
}

/// Top-level `[uniforms]` and `[textures]` entries that no pass's stages declare (a pass
/// that reuses another effect does not see them).
pub fn unused_entries(
    effect: &Effect,
    used_uniforms: &std::collections::HashSet<String>,
    used_textures: &std::collections::HashSet<String>,
) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    for u in effect.uniforms.iter().filter(|u| !used_uniforms.contains(&u.name)) {
        out.push(
            Diagnostic::new(
                Code::UniformUndeclared,
                format!("`[uniforms]` entry `{}` names no uniform declared by any pass", u.name),
            )
            .at(effect.file, u.name_span.clone(), "no pass's stages declare it")
            .with_note("top-level uniforms are shared by the passes with their own `stages`; a pass with `effect = …` uses that effect's manifest"),
        );
    }
    for t in effect.textures.iter().filter(|t| !used_textures.contains(&t.name)) {
        out.push(
            Diagnostic::new(Code::TextureNoSampler, format!("`[textures]` entry `{}` names no sampler declared by any pass", t.name))
                .at(effect.file, t.name_span.clone(), "no pass's stages declare it")
                .with_note("samplers that read a target are bound with the pass's `samples`"),
        );
    }
    out
}
