//! `effect.toml` against the shaders: `[uniforms]` defaults and `[textures]` entries.
//!
//! A default names a uniform some stage declares — a loose non-opaque uniform or a member
//! of a uniform block without an instance name, optionally followed by a path (`lights[1]`,
//! `material.color`) — and its value must fit the declared type ([`super::values`]). A
//! `semantic` must provide the declared type and `range` needs a scalar number. In the
//! other direction every uniform a stage reads should get a default (samplers a
//! `[textures]` entry), and uniforms nothing reads are reported. What the stages declare
//! is gathered in [`super::declared`].

use std::collections::HashSet;

use super::declared::{parse_path, texture_path, Decl, Decls, Step};
use super::values::Shape;
use super::{is_opaque, is_sampler_like, list, type_text};
use crate::diag::{Code, Diagnostic, FileId, Files};
use crate::front::syntax::{GlslType, StageSyntax, Storage};
use crate::manifest::{did_you_mean, Effect, Semantic, TextureKind, UniformDefault};

pub fn check(effect: &Effect, stages: &[StageSyntax], files: &Files) -> Vec<Diagnostic> {
    check_with_bound(effect, stages, files, &HashSet::new())
}

/// [`check`] for one pass of a multi-pass effect: `bound` are the samplers the pass graph
/// binds to targets (they need no `[textures]` entry).
pub fn check_with_bound(effect: &Effect, stages: &[StageSyntax], files: &Files, bound: &HashSet<String>) -> Vec<Diagnostic> {
    let decls = Decls::collect(stages);
    let mut out = Vec::new();
    let mut covered: HashSet<String> = HashSet::new();
    for u in &effect.uniforms {
        let base = parse_path(&u.name).map_or(u.name.clone(), |(b, _)| b);
        covered.insert(base);
        default(effect.file, "`[uniforms]` entry", u, &decls, stages, files, &mut out);
    }
    textures(effect, &decls, &mut out);
    let mut textured: HashSet<String> = effect.textures.iter().map(|t| texture_path(&t.name)).collect();
    textured.extend(bound.iter().cloned());
    missing(&decls, &covered, &textured, &mut out);
    out
}

/// Values set on the command line (`--set NAME=VALUE`, spans into `mf`, the registered
/// command line) against the declarations, as `[uniforms]` defaults are: unknown names
/// (with the nearest declared one), values that do not fit the type.
pub fn check_values(mf: FileId, values: &[UniformDefault], stages: &[StageSyntax], files: &Files) -> Vec<Diagnostic> {
    let decls = Decls::collect(stages);
    let mut out = Vec::new();
    for u in values {
        default(mf, "`--set`", u, &decls, stages, files, &mut out);
    }
    out
}

/// Checks one `[uniforms]` entry (`what` names where it was written) of the file `mf`.
fn default(mf: FileId, what: &str, u: &UniformDefault, decls: &Decls, stages: &[StageSyntax], files: &Files, out: &mut Vec<Diagnostic>) {
    let (base, steps) = parse_path(&u.name).unwrap_or_else(|| (u.name.clone(), Vec::new()));
    let member;
    let (decl, steps) = match decls.get(&base) {
        Some(decl) => (decl, &steps[..]),
        None => match decls.block_member(&base, &steps) {
            Some((d, rest)) => {
                member = d;
                (&member, rest)
            }
            None => {
                match super::compat_values::check(mf, u, &base, &steps, stages) {
                    Some(diags) => out.extend(diags),
                    None => out.push(unknown(mf, what, u, &base, decls, stages, files)),
                }
                return;
            }
        },
    };
    let (ty, shown) = match follow_path(mf, u, decl, steps) {
        Ok(found) => found,
        Err(d) => {
            out.push(d);
            return;
        }
    };
    let shape = decl.shape(&ty);
    let tt = type_text(decl.stage, &ty);
    let decl_label = format!("`{}` is declared as `{}` here", decl.name, decl.type_text());
    let entry = Entry { mf, u, decl, ty, shown, shape, tt, decl_label };
    entry.check_value(out);
    entry.check_semantic(out);
    entry.check_range(out);
    entry.check_read(out);
}

/// Follows an entry's path (`[1]`, `.color`) from its declaration to the type being set:
/// that type and the path as shown (`lights[1].color`), or why the path does not fit.
fn follow_path(mf: FileId, u: &UniformDefault, decl: &Decl, steps: &[Step]) -> Result<(GlslType, String), Diagnostic> {
    let mut ty = decl.ty.clone();
    let mut shown = decl.name.clone();
    for step in steps {
        match step {
            Step::Index(i) => {
                let Some(first) = ty.dims.first().copied() else {
                    return Err(Diagnostic::new(Code::UniformPathMismatch, format!("`{shown}` is not an array"))
                        .at(mf, u.name_span.clone(), format!("indexes `{shown}`"))
                        .with_label(decl.file(), decl.span(), format!("`{shown}` is a `{}`", type_text(decl.stage, &ty))));
                };
                if let Some(k) = first {
                    if *i >= u64::from(k) {
                        return Err(Diagnostic::new(Code::UniformPathMismatch, format!("index {i} is out of bounds for `{shown}`"))
                            .at(mf, u.name_span.clone(), format!("`{shown}` has {k} elements (0..={})", k.saturating_sub(1)))
                            .with_label(decl.file(), decl.span(), format!("declared as `{}`", type_text(decl.stage, &ty))));
                    }
                }
                ty = ty.element();
                shown = format!("{shown}[{i}]");
            }
            Step::Field(f) => {
                let def = (!ty.is_array()).then(|| decl.stage.struct_def(&ty.base)).flatten();
                let Some(def) = def else {
                    return Err(Diagnostic::new(Code::UniformPathMismatch, format!("`{shown}` has no field `{f}`"))
                        .at(mf, u.name_span.clone(), format!("`{shown}` is a `{}`, not a struct", type_text(decl.stage, &ty)))
                        .with_label(decl.file(), decl.span(), "declared here"));
                };
                let Some(m) = def.members.iter().find(|m| decl.stage.original_name(&m.name) == f) else {
                    let names: Vec<&str> = def.members.iter().map(|m| decl.stage.original_name(&m.name)).collect();
                    let sname = decl.stage.original_name(&def.name);
                    let mut d = Diagnostic::new(Code::UniformPathMismatch, format!("struct `{sname}` has no member `{f}`"))
                        .at(mf, u.name_span.clone(), format!("`{shown}` is a `{sname}`"))
                        .with_label(decl.stage.file, def.name_span.clone(), format!("`{sname}` is defined here"));
                    d = match did_you_mean(f, &names) {
                        Some(c) => d.with_help(format!("did you mean `{shown}.{c}`?")),
                        None => d.with_note(format!("its members are {}", list(&names.iter().map(|n| n.to_string()).collect::<Vec<_>>()))),
                    };
                    return Err(d);
                };
                ty = m.ty.clone();
                shown = format!("{shown}.{f}");
            }
        }
    }
    Ok((ty, shown))
}

/// One `[uniforms]` entry and the declared uniform (or part of one) it sets.
struct Entry<'a> {
    /// The manifest.
    mf: FileId,
    u: &'a UniformDefault,
    decl: &'a Decl<'a>,
    /// The type at the end of the entry's path, its shape and its GLSL text.
    ty: GlslType,
    /// The entry's path as shown in messages.
    shown: String,
    shape: Shape,
    tt: String,
    /// "`x` is declared as `T` here", for the label at the declaration.
    decl_label: String,
}

impl Entry<'_> {
    /// The value fits the type: no value for a sampler or a whole struct.
    fn check_value(&self, out: &mut Vec<Diagnostic>) {
        let Entry { u, decl, ty, shown, shape, tt, decl_label, .. } = self;
        let mf = self.mf;
        match (&u.value, &shape) {
            _ if is_sampler_like(ty) => out.push(
                Diagnostic::new(Code::UniformDefaultType, format!("`{shown}` is a sampler (`{tt}`) and takes no value"))
                    .at(mf, u.name_span.clone(), "a sampler under [uniforms]")
                    .with_label(decl.file(), decl.span(), decl_label.clone())
                    .with_help(format!("bind a texture under [textures] instead: `{shown} = {{ file = \"…\" }}`")),
            ),
            (_, Shape::Struct(sname)) => {
                let sname = decl.stage.original_name(sname).to_string();
                let members: Vec<String> = decl
                    .stage
                    .struct_def(&ty.base)
                    .map(|def| def.members.iter().map(|m| format!("{shown}.{}", decl.stage.original_name(&m.name))).collect())
                    .unwrap_or_default();
                out.push(
                    Diagnostic::new(Code::UniformDefaultType, format!("`{shown}` is a struct (`{sname}`) and cannot take one value"))
                        .at(mf, u.value_span.clone(), "a value for a whole struct")
                        .with_label(decl.file(), decl.span(), decl_label.clone())
                        .with_help(format!("set the members one by one: {}", list(&members))),
                );
            }
            (Some(v), _) => {
                if let Err(why) = shape.fit(v) {
                    out.push(
                        Diagnostic::new(Code::UniformDefaultType, format!("the default for `{shown}` does not fit its type `{tt}`"))
                            .at(mf, u.value_span.clone(), why)
                            .with_label(decl.file(), decl.span(), decl_label.clone())
                            .with_note(format!("a `{tt}` takes {}", shape.expected())),
                    );
                }
            }
            (None, _) => {}
        }
    }

    /// The semantic provides the declared type.
    fn check_semantic(&self, out: &mut Vec<Diagnostic>) {
        let Entry { u, decl, ty, shown, tt, decl_label, .. } = self;
        let mf = self.mf;
        if let Some(sem) = u.semantic {
            let fits = !ty.is_array() && sem.glsl_types().contains(&tt.as_str());
            if !fits {
                let span = u.semantic_span.clone().unwrap_or_else(|| u.value_span.clone());
                let provides = sem.glsl_types().join("` or `");
                let others: Vec<String> = Semantic::ALL
                    .iter()
                    .filter(|s| !ty.is_array() && s.glsl_types().contains(&tt.as_str()))
                    .map(|s| s.name().to_string())
                    .collect();
                let help = if others.is_empty() {
                    format!("declare `{shown}` as `{provides}`; no semantic provides a `{tt}`")
                } else {
                    format!("declare `{shown}` as `{provides}`, or use a semantic that provides a `{tt}`: {}", list(&others))
                };
                out.push(
                    Diagnostic::new(
                        Code::SemanticType,
                        format!("semantic `{}` provides a `{provides}`, but `{shown}` is a `{tt}`", sem.name()),
                    )
                    .at(mf, span, format!("provides `{provides}`"))
                    .with_label(decl.file(), decl.span(), decl_label.clone())
                    .with_help(help),
                );
            }
        }
    }

    /// `range` only on a number or a numeric vector.
    fn check_range(&self, out: &mut Vec<Diagnostic>) {
        let Entry { u, decl, shown, shape, tt, decl_label, .. } = self;
        let mf = self.mf;
        if let Some(span) = &u.range_span {
            if !shape.takes_range() {
                out.push(
                    Diagnostic::new(
                        Code::RangeNotNumeric,
                        format!("`range` needs a number or a vector of numbers, but `{shown}` is a `{tt}`"),
                    )
                    .at(mf, span.clone(), "a range on a uniform that is not a number or vector")
                    .with_label(decl.file(), decl.span(), decl_label.clone())
                    .with_note("`range` bounds a number (`float`, `int`, `uint`, `double`) or each component of a numeric vector")
                    .with_help("remove `range` from this entry"),
                );
            }
        }
    }

    /// A default for a uniform no stage reads.
    fn check_read(&self, out: &mut Vec<Diagnostic>) {
        let Entry { u, decl, .. } = self;
        let mf = self.mf;
        if !decl.read {
            out.push(
                Diagnostic::new(Code::DefaultUnread, format!("`{}` has a default, but no stage reads it", decl.name))
                    .at(mf, u.name_span.clone(), "default for an unread uniform")
                    .with_label(decl.file(), decl.span(), "declared here, never read")
                    .with_help("remove the entry, or use the uniform in a shader"),
            );
        }
    }
}

/// A `[uniforms]` entry whose base name no stage declares as a settable uniform.
fn unknown(mf: FileId, what: &str, u: &UniformDefault, base: &str, decls: &Decls, stages: &[StageSyntax], files: &Files) -> Diagnostic {
    let mut d = Diagnostic::new(Code::UniformUndeclared, format!("{what} `{}` names no uniform declared by the shaders", u.name)).at(
        mf,
        u.name_span.clone(),
        format!("no stage declares a uniform `{base}`"),
    );
    // A member (or the instance / block name) of a named uniform block?
    for nb in &decls.named_blocks {
        let s = nb.stage;
        let Some(b) = &s.globals[nb.index].block else {
            continue;
        };
        let bn = s.original_name(&b.block_name);
        let inst = b.instance.as_deref().map_or("", |i| s.original_name(i));
        let member = b.members.iter().find(|m| s.original_name(&m.name) == base);
        if member.is_some() || bn == base || inst == base {
            let span = member.map_or(b.block_name_span.clone(), |m| m.span.clone());
            let members: Vec<String> = b.members.iter().map(|m| format!("`{bn}.{}`", s.original_name(&m.name))).collect();
            return d
                .with_label(s.file, span, format!("in uniform block `{bn}` (instance `{inst}`)"))
                .with_note("a member of a block with an instance name is addressed as GL names it: `BlockName.member`")
                .with_help(format!("its members: {}", members.join(", ")));
        }
    }
    // Declared, but not as a uniform?
    for s in stages {
        if let Some(g) = s.globals.iter().find(|g| !g.is_block() && s.original_name(&g.name) == base) {
            let what = match g.storage {
                Storage::In | Storage::Attribute => "an input",
                Storage::Out => "an output",
                Storage::Varying => "a varying",
                Storage::Const => "a `const`",
                Storage::Buffer => "a buffer variable",
                _ => "a global variable",
            };
            let st = s.stage.title();
            return d
                .with_label(s.file, g.name_span.clone(), format!("{what} of the {st} stage, not a uniform"))
                .with_help(format!("only uniforms take defaults; declare `uniform {} {base};` to make it settable", type_text(s, &g.ty)));
        }
    }
    let names: Vec<&str> = decls.list.iter().filter(|d| !is_opaque(d.ty)).map(|d| d.name.as_str()).collect();
    if let Some(c) = did_you_mean(base, &names) {
        let decl = decls.get(c).expect("a candidate is declared");
        return d.with_label(decl.file(), decl.span(), format!("`{c}` is declared here")).with_help(format!("did you mean `{c}`?"));
    }
    if names.is_empty() {
        return d.with_note("no stage declares a uniform that takes a default");
    }
    // Where the uniforms are declared, one label per stage.
    for s in stages {
        let here: Vec<&Decl> = decls.list.iter().filter(|d| !is_opaque(d.ty) && std::ptr::eq(d.stage, s)).collect();
        if let Some(first) = here.first() {
            let names: Vec<String> = here.iter().map(|d| d.name.clone()).collect();
            let path = files.try_get(s.file).map_or("", |f| f.path.as_str());
            d = d.with_label(s.file, first.span(), format!("the {} stage ({path}) declares {}", s.stage.title(), list(&names)));
        }
    }
    d
}

/// `[textures]` entries against sampler uniforms.
fn textures(effect: &Effect, decls: &Decls, out: &mut Vec<Diagnostic>) {
    let samplers = decls.samplers();
    for t in &effect.textures {
        let path = texture_path(&t.name);
        if let Some((_, ty, decl)) = samplers.iter().find(|(p, _, _)| *p == path) {
            let fits = match t.kind {
                TextureKind::D2 => {
                    matches!(ty.base.as_str(), "sampler2D" | "sampler2DShadow" | "isampler2D" | "usampler2D" | "sampler2DRect")
                }
                TextureKind::Cube => matches!(ty.base.as_str(), "samplerCube" | "samplerCubeShadow" | "isamplerCube" | "usamplerCube"),
            };
            if !fits {
                let tt = type_text(decl.stage, ty);
                out.push(
                    Diagnostic::new(
                        Code::TextureKindMismatch,
                        format!("texture `{}` is a {} texture, but `{path}` is a `{tt}`", t.name, t.kind.name()),
                    )
                    .at(effect.file, t.span.clone(), format!("a {} texture", t.kind.name()))
                    .with_label(decl.file(), decl.span(), format!("declared as `{tt}` here"))
                    .with_note("effectc textures are `2d` (for `sampler2D`) or `cube` (for `samplerCube`, six faces)")
                    .with_help(format!("declare `{path}` as `{}`, or change the texture", t.kind.glsl_sampler())),
                );
            }
            continue;
        }
        let mut d = Diagnostic::new(Code::TextureNoSampler, format!("`[textures]` entry `{}` names no sampler uniform", t.name)).at(
            effect.file,
            t.name_span.clone(),
            format!("no stage declares a sampler `{path}`"),
        );
        if let Some(decl) = decls.get(&path) {
            d = d
                .with_label(decl.file(), decl.span(), format!("`{path}` is a `{}` uniform", decl.type_text()))
                .with_note("textures bind to sampler uniforms (`sampler2D`, `samplerCube`)");
        } else {
            let names: Vec<&str> = samplers.iter().map(|(p, _, _)| p.as_str()).collect();
            match did_you_mean(&path, &names) {
                Some(c) => {
                    let (_, _, decl) = samplers.iter().find(|(p, _, _)| p == c).expect("a candidate");
                    d = d.with_label(decl.file(), decl.span(), format!("`{c}` is declared here")).with_help(format!("did you mean `{c}`?"));
                }
                None if names.is_empty() => d = d.with_note("no stage declares a sampler uniform"),
                None => {
                    let all: Vec<String> = names.iter().map(|n| n.to_string()).collect();
                    d = d.with_note(format!("the sampler uniforms are {}", list(&all)));
                }
            }
        }
        out.push(d);
    }
}

/// Uniforms without a default, samplers without a texture, uniforms nothing reads.
fn missing(decls: &Decls, covered: &HashSet<String>, textured: &HashSet<String>, out: &mut Vec<Diagnostic>) {
    let samplers = decls.samplers();
    for decl in &decls.list {
        let shape = decl.shape(decl.ty);
        if !decl.read {
            if decl.in_block {
                continue; // reported per block below
            }
            let mut d = Diagnostic::new(Code::UniformUnread, format!("uniform `{}` is declared but never read", decl.name)).at(
                decl.file(),
                decl.span(),
                "declared here",
            );
            for (file, span, s) in decl.sites.iter().skip(1) {
                d = d.with_label(*file, span.clone(), format!("also declared in the {} stage, not read there either", s.stage.title()));
            }
            out.push(d.with_help("remove the declaration, or use it"));
            continue;
        }
        if is_opaque(decl.ty) {
            if is_sampler_like(decl.ty) && !textured.contains(&decl.name) {
                out.push(no_texture(decl, &decl.name, decl.ty));
            }
            continue;
        }
        match shape {
            Shape::Other(_) => {}
            _ if covered.contains(&decl.name) => {
                // Struct members with samplers still need textures.
                for (path, ty, d) in samplers.iter().filter(|(p, _, d)| std::ptr::eq(*d, decl) && *p != decl.name) {
                    if !textured.contains(path) {
                        out.push(no_texture(d, path, ty));
                    }
                }
            }
            Shape::Struct(ref sname) => {
                let def = decl.stage.struct_def(sname);
                let members: Vec<String> = def
                    .map(|def| {
                        def.members
                            .iter()
                            .filter(|m| !is_opaque(&m.ty))
                            .map(|m| format!("{}.{} = {}", decl.name, decl.stage.original_name(&m.name), decl.shape(&m.ty).example()))
                            .collect()
                    })
                    .unwrap_or_default();
                if !members.is_empty() {
                    out.push(no_default(
                        decl,
                        &decl.type_text(),
                        format!("add its members under [uniforms] in effect.toml: {}", list(&members)),
                    ));
                }
                for (path, ty, d) in samplers.iter().filter(|(_, _, d)| std::ptr::eq(*d, decl)) {
                    if !textured.contains(path) {
                        out.push(no_texture(d, path, ty));
                    }
                }
            }
            _ => {
                let tt = decl.type_text();
                let mut help = format!("add `{} = {}` under [uniforms] in effect.toml", decl.name, shape.example());
                if let Some(sem) = semantic_hint(&decl.name, &tt) {
                    help.push_str(&format!(" (or `{} = {{ semantic = \"{}\" }}` to have the runtime supply it)", decl.name, sem.name()));
                }
                out.push(no_default(decl, &tt, help));
            }
        }
    }
    for (s, i) in &decls.unread_blocks {
        let Some(b) = &s.globals[*i].block else {
            continue;
        };
        let bn = s.original_name(&b.block_name);
        out.push(
            Diagnostic::new(Code::UniformUnread, format!("uniform block `{bn}` is declared but never read"))
                .at(s.file, b.block_name_span.clone(), "no stage reads any of its members")
                .with_help("remove the block, or use it"),
        );
    }
}

/// W0220: a uniform some stage reads has no default.
fn no_default(decl: &Decl, type_text: &str, help: String) -> Diagnostic {
    Diagnostic::new(Code::UniformNoDefault, format!("uniform `{}` has no default in effect.toml", decl.name))
        .at(decl.file(), decl.span(), format!("a `{type_text}` read without a default"))
        .with_help(help)
}

fn no_texture(decl: &Decl, path: &str, ty: &GlslType) -> Diagnostic {
    let tt = type_text(decl.stage, ty);
    let example = if tt.contains("Cube") {
        "{ cube = [\"px.png\", \"nx.png\", \"py.png\", \"ny.png\", \"pz.png\", \"nz.png\"] }"
    } else {
        "{ file = \"….png\" }"
    };
    Diagnostic::new(Code::SamplerNoTexture, format!("sampler `{path}` has no entry in [textures]"))
        .at(decl.file(), decl.span(), format!("a `{tt}` read without a texture"))
        .with_help(format!("add `{path} = {example}` under [textures] in effect.toml (or `{{ generate = \"checker\" }}`)"))
}

/// A semantic the uniform's name and type suggest (`timeVar: float` → `time`).
fn semantic_hint(name: &str, ty: &str) -> Option<Semantic> {
    let n: String = name.to_ascii_lowercase().chars().filter(|c| *c != '_').collect();
    const KEYS: &[(&str, Semantic)] = &[
        ("modelviewprojection", Semantic::ModelViewProjection),
        ("mvp", Semantic::ModelViewProjection),
        ("viewprojection", Semantic::ViewProjection),
        ("viewproj", Semantic::ViewProjection),
        ("modelview", Semantic::ModelView),
        ("normalmatrix", Semantic::NormalMatrix),
        ("deltatime", Semantic::DeltaTime),
        ("time", Semantic::Time),
        ("frame", Semantic::Frame),
        ("resolution", Semantic::Resolution),
        ("mouse", Semantic::Mouse),
        ("camerapos", Semantic::CameraPosition),
        ("campos", Semantic::CameraPosition),
        ("eyepos", Semantic::CameraPosition),
        ("projection", Semantic::Projection),
        ("model", Semantic::Model),
        ("view", Semantic::View),
    ];
    KEYS.iter().find(|(k, s)| n.contains(k) && s.glsl_types().contains(&ty)).map(|(_, s)| *s)
}
