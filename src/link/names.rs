//! Uses of a name that this stage does not declare but another stage does.
//!
//! Each stage has its own names: `vert_out.x` in the fragment stage does not reach the
//! vertex stage's block instance `vert_out`, and a uniform declared only in the vertex
//! stage is unknown in the fragment stage. naga only says "unknown variable"; this check
//! says where the name *is* declared and what this stage calls the same thing. It also
//! catches a block used through its block name instead of its instance name.

use std::collections::HashMap;
use std::ops::Range;

use super::interface::{direction, Dir};
use super::type_text;
use crate::diag::{Code, Diagnostic};
use crate::front::syntax::{BlockInfo, Global, Referent, StageSyntax, Storage};

/// Use sites of one name: span and the field accessed (`name.field`), if any.
type Sites = Vec<(Range<usize>, Option<String>)>;

/// How many further uses get their own label.
const MAX_EXTRA_LABELS: usize = 3;

/// A block used in one stage, by its instance or block name.
struct Found<'a> {
    stage: &'a StageSyntax,
    global: &'a Global,
}

pub fn check(stages: &[&StageSyntax], out: &mut Vec<Diagnostic>) {
    for (si, s) in stages.iter().enumerate() {
        // Unresolved uses grouped by the user's name, in order of first use.
        let mut order: Vec<String> = Vec::new();
        let mut uses: HashMap<String, Sites> = HashMap::new();
        for u in &s.uses {
            if u.target != Referent::Unresolved {
                continue;
            }
            let name = s.original_name(&u.name).to_string();
            if name.starts_with("gl_") {
                continue;
            }
            let field = u.field.as_ref().map(|(f, _)| s.original_name(f).to_string());
            uses.entry(name.clone())
                .or_insert_with(|| {
                    order.push(name.clone());
                    Vec::new()
                })
                .push((u.span.clone(), field));
        }
        for name in order {
            let sites = &uses[&name];
            let diag = own_block_name(s, &name, sites).or_else(|| other_stage(stages, si, &name, sites));
            if let Some(mut d) = diag {
                for (span, _) in sites.iter().skip(1).take(MAX_EXTRA_LABELS) {
                    d = d.with_label(s.file, span.clone(), "also used here");
                }
                if sites.len() > 1 + MAX_EXTRA_LABELS {
                    d = d.with_note(format!("`{name}` is used {} times in this stage", sites.len()));
                }
                out.push(d);
            }
        }
    }
}

fn first_field(sites: &[(Range<usize>, Option<String>)]) -> Option<&str> {
    sites.iter().find_map(|(_, f)| f.as_deref())
}

fn storage_word(g: &Global, s: &StageSyntax) -> &'static str {
    match g.storage {
        Storage::Uniform => "uniform",
        Storage::Buffer => "buffer",
        _ => match direction(s.stage, g) {
            Some(Dir::In) => "input",
            Some(Dir::Out) => "output",
            None => "interface",
        },
    }
}

/// The help for reaching a block's members in stage `s` through block `g`.
fn how_to_reach(s: &StageSyntax, blk: &BlockInfo, field: Option<&str>) -> String {
    match &blk.instance {
        Some(inst) => {
            let inst = s.original_name(inst);
            match field {
                Some(f) => format!("in this stage the block instance is called `{inst}`: write `{inst}.{f}`"),
                None => format!("in this stage the block instance is called `{inst}`"),
            }
        }
        None => {
            let bn = s.original_name(&blk.block_name);
            match field {
                Some(f) => format!("in this stage the block `{bn}` has no instance name: write `{f}` directly"),
                None => format!("in this stage the block `{bn}` has no instance name: use its members directly"),
            }
        }
    }
}

/// `name` is the block name of a block this stage declares.
fn own_block_name(s: &StageSyntax, name: &str, sites: &[(Range<usize>, Option<String>)]) -> Option<Diagnostic> {
    let g = s.globals.iter().find(|g| g.block.as_ref().is_some_and(|b| s.original_name(&b.block_name) == name))?;
    let blk = g.block.as_ref()?;
    let kind = storage_word(g, s);
    let mut d = Diagnostic::new(
        Code::OtherStageName,
        format!("`{name}` is a block name, not a variable"),
    )
    .at(s.file, sites[0].0.clone(), format!("the {kind} block `{name}` used by its block name"))
    .with_label(s.file, blk.block_name_span.clone(), "the block is declared here")
    .with_note("code reaches a block's members through its instance name (or directly, when the block has none); the block name only matters for matching between stages")
    .with_help(how_to_reach(s, blk, first_field(sites)));
    if let Some(span) = &blk.instance_span {
        d = d.with_label(s.file, span.clone(), "the instance name");
    }
    Some(d)
}

/// `name` is declared in another stage.
fn other_stage(stages: &[&StageSyntax], si: usize, name: &str, sites: &[(Range<usize>, Option<String>)]) -> Option<Diagnostic> {
    let s = stages[si];
    let st = s.stage.title();
    let others = || stages.iter().enumerate().filter(move |(ti, _)| *ti != si).map(|(_, t)| *t);
    // A block's instance or block name in another stage.
    let block = others().find_map(|t| {
        t.globals
            .iter()
            .find(|g| {
                g.block.as_ref().is_some_and(|b| {
                    b.instance.as_deref().map(|i| t.original_name(i)) == Some(name) || t.original_name(&b.block_name) == name
                })
            })
            .map(|g| Found { stage: t, global: g })
    });
    if let Some(f) = block {
        return Some(foreign_block(s, f, name, sites));
    }
    // A member of another stage's anonymous block.
    let member = others().find_map(|t| {
        t.globals.iter().find_map(|g| {
            let b = g.block.as_ref()?;
            if b.instance.is_some() {
                return None;
            }
            let m = b.members.iter().find(|m| t.original_name(&m.name) == name)?;
            Some((t, g, b, m))
        })
    });
    if let Some((t, g, b, m)) = member {
        let tt = t.stage.title();
        let bn = t.original_name(&b.block_name);
        let kind = storage_word(g, t);
        let keyword = if g.storage == Storage::Uniform { "uniform".to_string() } else { decl_keyword(s, t) };
        return Some(
            Diagnostic::new(Code::OtherStageName, format!("`{name}` is not declared in the {st} stage"))
                .at(s.file, sites[0].0.clone(), format!("`{name}` is a member of the {tt} stage's {kind} block `{bn}`"))
                .with_label(t.file, m.span.clone(), format!("declared here in the {tt} stage"))
                .with_note("each stage sees only its own declarations")
                .with_help(format!("declare `{keyword} {bn} {{ … }};` in the {st} stage too")),
        );
    }
    // A loose global of another stage.
    let (t, g) = others().find_map(|t| t.globals.iter().find(|g| !g.is_block() && t.original_name(&g.name) == name).map(|g| (t, g)))?;
    let tt = t.stage.title();
    let ty = type_text(t, &g.ty);
    let decl = |kw: &str| {
        let base = t.original_name(&g.ty.base);
        let dims = GlslDims(&g.ty.dims);
        format!("{kw} {base} {name}{dims};")
    };
    let d = Diagnostic::new(Code::OtherStageName, format!("`{name}` is not declared in the {st} stage"))
        .with_note("each stage sees only its own declarations");
    let (label, help) = match (g.storage, direction(t.stage, g)) {
        (Storage::Uniform, _) => (
            format!("`{name}` is a uniform of the {tt} stage"),
            format!("declare `{}` in the {st} stage too (uniforms with the same name are shared by all stages)", decl("uniform")),
        ),
        (_, Some(Dir::Out)) if t.stage < s.stage => {
            (format!("`{name}` is an output of the {tt} stage"), format!("declare `{}` to receive it", decl("in")))
        }
        (Storage::In | Storage::Attribute, None) => (
            format!("`{name}` is a vertex input (attribute)"),
            format!("pass it on: declare `out {ty} v_{name};` in the vertex stage, assign it there, and read `in {ty} v_{name};` here"),
        ),
        _ => (format!("`{name}` is declared in the {tt} stage"), format!("declare `{name}` in the {st} stage too")),
    };
    Some(
        d.at(s.file, sites[0].0.clone(), label)
            .with_label(t.file, g.name_span.clone(), format!("declared here in the {tt} stage"))
            .with_help(help),
    )
}

/// `in` or `out`, as stage `s` would declare a block shared with stage `t`.
fn decl_keyword(s: &StageSyntax, t: &StageSyntax) -> String {
    if t.stage < s.stage { "in" } else { "out" }.to_string()
}

struct GlslDims<'a>(&'a [Option<u32>]);

impl std::fmt::Display for GlslDims<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        for d in self.0 {
            match d {
                Some(n) => write!(f, "[{n}]")?,
                None => f.write_str("[]")?,
            }
        }
        Ok(())
    }
}

/// `name` is the instance or block name of block `f` in another stage.
fn foreign_block(s: &StageSyntax, f: Found, name: &str, sites: &[(Range<usize>, Option<String>)]) -> Diagnostic {
    let (t, g) = (f.stage, f.global);
    let blk = g.block.as_ref().expect("found a block");
    let st = s.stage.title();
    let tt = t.stage.title();
    let bn = t.original_name(&blk.block_name);
    let kind = storage_word(g, t);
    let is_instance = blk.instance.as_deref().map(|i| t.original_name(i)) == Some(name);
    let (what, span) = match (&blk.instance_span, is_instance) {
        (Some(span), true) => (format!("the instance name of the {tt} stage's {kind} block `{bn}`"), span.clone()),
        _ => (format!("the block name of a {kind} block in the {tt} stage"), blk.block_name_span.clone()),
    };
    let field = first_field(sites);
    let mut d = Diagnostic::new(Code::OtherStageName, format!("`{name}` is not declared in the {st} stage"))
        .at(s.file, sites[0].0.clone(), format!("`{name}` is {what}"))
        .with_label(t.file, span, format!("declared here in the {tt} stage"))
        .with_note(
            "each stage names its own block instances; blocks are matched between stages by block name, and instance names may differ",
        );
    match corresponding_block(s, t, g, field) {
        Some(c) => {
            let cb = c.block.as_ref().expect("a block");
            let label_span = cb.instance_span.clone().unwrap_or_else(|| cb.block_name_span.clone());
            d = d
                .with_label(s.file, label_span, format!("the {st} stage's block `{}`", s.original_name(&cb.block_name)))
                .with_help(how_to_reach(s, cb, field));
        }
        None => {
            let inst = blk.instance.as_deref().map(|i| t.original_name(i)).unwrap_or("");
            let keyword = if g.storage == Storage::Uniform || g.storage == Storage::Buffer { kind.to_string() } else { decl_keyword(s, t) };
            d = d.with_help(format!("declare `{keyword} {bn} {{ … }} {inst};` in the {st} stage with the same members"));
        }
    }
    d
}

/// The block of stage `s` that plays the role of `g` (declared in stage `t`): the same block
/// name, else the block of the same kind sharing the most member names (or holding `field`).
fn corresponding_block<'a>(s: &'a StageSyntax, t: &StageSyntax, g: &Global, field: Option<&str>) -> Option<&'a Global> {
    let blk = g.block.as_ref()?;
    let bn = t.original_name(&blk.block_name);
    let uniform_like = matches!(g.storage, Storage::Uniform | Storage::Buffer);
    let candidates: Vec<&Global> = s
        .globals
        .iter()
        .filter(|c| c.is_block())
        .filter(|c| matches!(c.storage, Storage::Uniform | Storage::Buffer) == uniform_like)
        .filter(|c| uniform_like || direction(s.stage, c).is_some())
        .collect();
    if let Some(c) = candidates.iter().find(|c| c.block.as_ref().is_some_and(|cb| s.original_name(&cb.block_name) == bn)) {
        return Some(c);
    }
    let score = |c: &Global| -> usize {
        let cb = c.block.as_ref().expect("a block");
        let shared = cb.members.iter().filter(|m| blk.members.iter().any(|n| t.original_name(&n.name) == s.original_name(&m.name))).count();
        let has_field = field.is_some_and(|f| cb.members.iter().any(|m| s.original_name(&m.name) == f));
        shared + usize::from(has_field) * 100
    };
    candidates.iter().copied().filter(|c| score(c) > 0).max_by_key(|c| score(c))
}
