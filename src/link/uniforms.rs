//! Uniforms are program-wide: every stage that declares a uniform name shares one value.
//!
//! So declarations of one loose uniform must have the same type in every stage (`E0204`),
//! uniform and buffer blocks of one block name the same members (`E0205`), and a struct a
//! uniform is declared with the same definition wherever uniforms use it (`E0206`).

use std::collections::{BTreeSet, HashMap};

use super::blocks::{self, Side};
use super::{same_type, type_text};
use crate::diag::{Code, Diagnostic};
use crate::front::syntax::{Global, StageSyntax, Storage};

pub fn check(stages: &[&StageSyntax], out: &mut Vec<Diagnostic>) {
    loose(stages, out);
    blocks_by_name(stages, out);
    structs(stages, out);
}

fn loose(stages: &[&StageSyntax], out: &mut Vec<Diagnostic>) {
    let mut first: HashMap<&str, (&StageSyntax, &Global)> = HashMap::new();
    for s in stages {
        for g in &s.globals {
            if g.storage != Storage::Uniform || g.is_block() {
                continue;
            }
            let name = s.original_name(&g.name);
            let Some(&(f, fg)) = first.get(name) else {
                first.insert(name, (s, g));
                continue;
            };
            if std::ptr::eq(f, *s) || same_type(f, &fg.ty, s, &g.ty) {
                continue;
            }
            let (tf, ts) = (type_text(f, &fg.ty), type_text(s, &g.ty));
            let (ft, st) = (f.stage.title(), s.stage.title());
            out.push(
                Diagnostic::new(
                    Code::UniformTypeMismatch,
                    format!("uniform `{name}` is `{tf}` in the {ft} stage but `{ts}` in the {st} stage"),
                )
                .at(s.file, g.name_span.clone(), format!("declared as `{ts}` here"))
                .with_label(f.file, fg.name_span.clone(), format!("declared as `{tf}` in the {ft} stage"))
                .with_note(format!(
                    "uniforms are program-wide: every stage that declares `{name}` shares one value, so all declarations must have the same type and array size"
                ))
                .with_help(format!("declare `{name}` with the same type in both stages")),
            );
        }
    }
}

fn blocks_by_name(stages: &[&StageSyntax], out: &mut Vec<Diagnostic>) {
    let mut first: HashMap<&str, (&StageSyntax, &Global)> = HashMap::new();
    for s in stages {
        for g in &s.globals {
            let Some(blk) = &g.block else { continue };
            if !matches!(g.storage, Storage::Uniform | Storage::Buffer) {
                continue;
            }
            let name = s.original_name(&blk.block_name);
            let Some(&(f, fg)) = first.get(name) else {
                first.insert(name, (s, g));
                continue;
            };
            if std::ptr::eq(f, *s) {
                continue;
            }
            let fb = fg.block.as_ref().expect("a block");
            let diffs = blocks::diff(Side::new(f, &fb.members), Side::new(s, &blk.members), false);
            if diffs.is_empty() {
                continue;
            }
            let (ft, st) = (f.stage.title(), s.stage.title());
            let kind = if g.storage == Storage::Buffer { "buffer" } else { "uniform" };
            let mut d = Diagnostic::new(
                Code::UniformBlockMismatch,
                format!("{kind} block `{name}` is declared differently in the {ft} and {st} stages"),
            )
            .at(s.file, blk.block_name_span.clone(), format!("declared here in the {st} stage"))
            .with_label(f.file, fb.block_name_span.clone(), format!("declared here in the {ft} stage"));
            for diff in diffs {
                if let Some((span, label)) = diff.a {
                    d = d.with_label(f.file, span, label);
                }
                if let Some((span, label)) = diff.b {
                    d = d.with_label(s.file, span, label);
                }
                d = d.with_note(diff.note);
            }
            out.push(
                d.with_note(format!(
                    "{kind} blocks are program-wide: every stage declaring block `{name}` must declare the same members in the same order with the same types (instance names may differ)"
                ))
                .with_help("copy one declaration of the block into the other stage"),
            );
        }
    }
}

/// Struct names reachable from the stage's uniforms (loose or block members), nested
/// structs included.
fn uniform_structs(s: &StageSyntax) -> BTreeSet<String> {
    let mut todo: Vec<&str> = Vec::new();
    for g in &s.globals {
        if !matches!(g.storage, Storage::Uniform | Storage::Buffer) {
            continue;
        }
        match &g.block {
            Some(b) => todo.extend(b.members.iter().map(|m| m.ty.base.as_str())),
            None => todo.push(&g.ty.base),
        }
    }
    let mut seen = BTreeSet::new();
    while let Some(name) = todo.pop() {
        let Some(def) = s.struct_def(name) else {
            continue;
        };
        if seen.insert(name.to_string()) {
            todo.extend(def.members.iter().map(|m| m.ty.base.as_str()));
        }
    }
    seen
}

fn structs(stages: &[&StageSyntax], out: &mut Vec<Diagnostic>) {
    let mut first: HashMap<String, (&StageSyntax, String)> = HashMap::new();
    for s in stages {
        for internal in uniform_structs(s) {
            let name = s.original_name(&internal).to_string();
            let Some((f, f_internal)) = first.get(&name) else {
                first.insert(name, (s, internal));
                continue;
            };
            let (Some(fd), Some(sd)) = (f.struct_def(f_internal), s.struct_def(&internal)) else {
                continue;
            };
            let diffs = blocks::diff(Side::new(f, &fd.members), Side::new(s, &sd.members), false);
            if diffs.is_empty() {
                continue;
            }
            let (ft, st) = (f.stage.title(), s.stage.title());
            let mut d = Diagnostic::new(
                Code::UniformStructMismatch,
                format!("struct `{name}` is used by uniforms but defined differently in the {ft} and {st} stages"),
            )
            .at(s.file, sd.name_span.clone(), format!("defined here in the {st} stage"))
            .with_label(f.file, fd.name_span.clone(), format!("defined here in the {ft} stage"));
            for diff in diffs {
                if let Some((span, label)) = diff.a {
                    d = d.with_label(f.file, span, label);
                }
                if let Some((span, label)) = diff.b {
                    d = d.with_label(s.file, span, label);
                }
                d = d.with_note(diff.note);
            }
            out.push(
                d.with_note("a uniform shared by stages must have the same type in each, so a struct it uses must have the same members in the same order with the same types")
                    .with_help("define the struct identically in both stages (e.g. copy the definition)"),
            );
        }
    }
}
