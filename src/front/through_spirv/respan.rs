//! Moving every span of a naga module read from SPIR-V to where its `OpLine` points in the
//! user's text.

use naga::{Block, Module, Span};

/// Every span of `module` through `f` (naga keeps spans in its arenas and blocks).
pub(super) fn respan_module(module: &mut Module, f: &dyn Fn(Span) -> Span) {
    respan_arena(&mut module.global_variables, f);
    respan_arena(&mut module.global_expressions, f);
    respan_arena(&mut module.constants, f);
    respan_arena(&mut module.overrides, f);
    let functions = module.functions.iter_mut().map(|(_, func)| func);
    for func in functions.chain(module.entry_points.iter_mut().map(|ep| &mut ep.function)) {
        respan_arena(&mut func.expressions, f);
        respan_arena(&mut func.local_variables, f);
        respan_block(&mut func.body, f);
    }
}

fn respan_arena<T>(arena: &mut naga::Arena<T>, f: &dyn Fn(Span) -> Span) {
    let items: Vec<(T, Span)> = arena.drain().map(|(_, value, span)| (value, span)).collect();
    for (value, span) in items {
        arena.append(value, f(span));
    }
}

fn respan_block(block: &mut Block, f: &dyn Fn(Span) -> Span) {
    for (statement, span) in block.span_iter_mut() {
        if let Some(span) = span {
            *span = f(*span);
        }
        for b in crate::front::statements::child_blocks(statement) {
            respan_block(b, f);
        }
    }
}
