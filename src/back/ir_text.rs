//! A stable, reviewable text form of a naga module (`<effect>.ir.txt`, IR snapshots).
//!
//! One line per type, constant, global and expression (`[n] = <Debug of the item>`), and
//! the statement tree indented by nesting. Spans are left out, so the text changes only
//! when the translation does.

use std::fmt::Write;

use naga::{Block, Function, Module, Statement, TypeInner};

/// The module as text.
pub fn write(module: &Module) -> String {
    let mut out = String::new();
    out.push_str("types:\n");
    for (h, t) in module.types.iter() {
        let name = t.name.as_deref().unwrap_or("_");
        match &t.inner {
            TypeInner::Struct { members, span } => {
                let _ = writeln!(out, "  [{}] {name}: struct (span {span})", h.index());
                for m in members {
                    let binding = m.binding.as_ref().map(|b| format!(" {b:?}")).unwrap_or_default();
                    let _ = writeln!(out, "      +{} {}: [{}]{binding}", m.offset, m.name.as_deref().unwrap_or("_"), m.ty.index());
                }
            }
            inner => {
                let _ = writeln!(out, "  [{}] {name}: {inner:?}", h.index());
            }
        }
    }
    if !module.constants.is_empty() {
        out.push_str("constants:\n");
        for (h, c) in module.constants.iter() {
            let _ = writeln!(out, "  [{}] {}: [{}] = g[{}]", h.index(), c.name.as_deref().unwrap_or("_"), c.ty.index(), c.init.index());
        }
    }
    if !module.overrides.is_empty() {
        out.push_str("overrides:\n");
        for (h, o) in module.overrides.iter() {
            let _ = writeln!(out, "  [{}] {:?}", h.index(), o);
        }
    }
    if !module.global_expressions.is_empty() {
        out.push_str("global expressions:\n");
        for (h, e) in module.global_expressions.iter() {
            let _ = writeln!(out, "  g[{}] = {e:?}", h.index());
        }
    }
    out.push_str("globals:\n");
    for (h, g) in module.global_variables.iter() {
        let binding = g.binding.as_ref().map(|b| format!(" @group({}) @binding({})", b.group, b.binding)).unwrap_or_default();
        let init = g.init.map(|i| format!(" = g[{}]", i.index())).unwrap_or_default();
        let _ = writeln!(out, "  [{}] {}: {:?} [{}]{binding}{init}", h.index(), g.name.as_deref().unwrap_or("_"), g.space, g.ty.index());
    }
    for (h, f) in module.functions.iter() {
        let _ = writeln!(out, "function [{}]", h.index());
        function(&mut out, f);
    }
    for ep in &module.entry_points {
        let _ = writeln!(out, "entry point {:?} {}", ep.stage, ep.name);
        function(&mut out, &ep.function);
    }
    out
}

fn function(out: &mut String, f: &Function) {
    let args: Vec<String> = f
        .arguments
        .iter()
        .map(|a| {
            let binding = a.binding.as_ref().map(|b| format!(" {b:?}")).unwrap_or_default();
            format!("{}: [{}]{binding}", a.name.as_deref().unwrap_or("_"), a.ty.index())
        })
        .collect();
    let result = f
        .result
        .as_ref()
        .map(|r| {
            let binding = r.binding.as_ref().map(|b| format!(" {b:?}")).unwrap_or_default();
            format!(" -> [{}]{binding}", r.ty.index())
        })
        .unwrap_or_default();
    let _ = writeln!(out, "  {}({}){result}", f.name.as_deref().unwrap_or("_"), args.join(", "));
    for (h, l) in f.local_variables.iter() {
        let init = l.init.map(|i| format!(" = [{}]", i.index())).unwrap_or_default();
        let _ = writeln!(out, "  local l{}: {} [{}]{init}", h.index(), l.name.as_deref().unwrap_or("_"), l.ty.index());
    }
    for (h, e) in f.expressions.iter() {
        let name = f.named_expressions.get(&h).map(|n| format!(" ({n})")).unwrap_or_default();
        let _ = writeln!(out, "  [{}]{name} = {e:?}", h.index());
    }
    out.push_str("  body:\n");
    block(out, &f.body, 2);
}

fn block(out: &mut String, b: &Block, depth: usize) {
    let pad = "  ".repeat(depth);
    for s in b.iter() {
        match s {
            Statement::Block(inner) => {
                let _ = writeln!(out, "{pad}block");
                block(out, inner, depth + 1);
            }
            Statement::If { condition, accept, reject } => {
                let _ = writeln!(out, "{pad}if [{}]", condition.index());
                block(out, accept, depth + 1);
                if !reject.is_empty() {
                    let _ = writeln!(out, "{pad}else");
                    block(out, reject, depth + 1);
                }
            }
            Statement::Switch { selector, cases } => {
                let _ = writeln!(out, "{pad}switch [{}]", selector.index());
                for c in cases {
                    let ft = if c.fall_through { " (falls through)" } else { "" };
                    let _ = writeln!(out, "{pad}  case {:?}{ft}", c.value);
                    block(out, &c.body, depth + 2);
                }
            }
            Statement::Loop { body, continuing, break_if } => {
                let _ = writeln!(out, "{pad}loop");
                block(out, body, depth + 1);
                if !continuing.is_empty() || break_if.is_some() {
                    let brk = break_if.map(|b| format!(" break if [{}]", b.index())).unwrap_or_default();
                    let _ = writeln!(out, "{pad}continuing{brk}");
                    block(out, continuing, depth + 1);
                }
            }
            other => {
                let _ = writeln!(out, "{pad}{other:?}");
            }
        }
    }
}
