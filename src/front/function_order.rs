//! Functions of a naga module put in call order. GLSL calls a function declared by a
//! prototype and defined later; naga's GLSL front can leave such a callee after its caller
//! in the module's function arena, and naga's validator then refuses the module ("depends
//! on … which has not been processed yet"). Callees first (GLSL has no recursion, so the
//! call graph has no cycle): every `Call` and `CallResult` is renumbered.

use naga::{Block, Expression, Function, Handle, Module, Statement};

use crate::front::statements::visit_statements;

/// Reorders `module`'s functions so each comes after every function it calls. A module
/// already in order is left untouched.
pub fn callees_first(module: &mut Module) {
    let handles: Vec<Handle<Function>> = module.functions.iter().map(|(h, _)| h).collect();
    let calls: Vec<Vec<Handle<Function>>> = module.functions.iter_mut().map(|(_, f)| called(&mut f.body)).collect();
    let index = |h: Handle<Function>| handles.iter().position(|x| *x == h);
    let mut order: Vec<usize> = Vec::new();
    let mut state = vec![0u8; handles.len()]; // 0 new, 1 on the path, 2 placed
    for start in 0..handles.len() {
        visit(start, &calls, &index, &mut state, &mut order);
    }
    if order.iter().enumerate().all(|(i, &o)| i == o) {
        return;
    }
    let mut taken: Vec<Option<(Function, naga::Span)>> = module.functions.drain().map(|(_, f, span)| Some((f, span))).collect();
    let mut renumber = vec![None; handles.len()];
    for &i in &order {
        let (f, span) = taken[i].take().expect("each function placed once");
        renumber[i] = Some(module.functions.append(f, span));
    }
    let map = |h: Handle<Function>| index(h).and_then(|i| renumber[i]).unwrap_or(h);
    for (_, f) in module.functions.iter_mut() {
        renumber_calls(f, &map);
    }
    for ep in &mut module.entry_points {
        renumber_calls(&mut ep.function, &map);
    }
}

/// Depth-first, callees before callers.
fn visit(
    i: usize,
    calls: &[Vec<Handle<Function>>],
    index: &dyn Fn(Handle<Function>) -> Option<usize>,
    state: &mut [u8],
    order: &mut Vec<usize>,
) {
    if state[i] != 0 {
        return;
    }
    state[i] = 1;
    for &callee in &calls[i] {
        if let Some(j) = index(callee) {
            visit(j, calls, index, state, order);
        }
    }
    state[i] = 2;
    order.push(i);
}

/// Every function a block calls, nested blocks included.
fn called(block: &mut Block) -> Vec<Handle<Function>> {
    let mut out = Vec::new();
    visit_statements(block, &mut |s| {
        if let Statement::Call { function, .. } = s {
            out.push(*function);
        }
    });
    out
}

fn renumber_calls(f: &mut Function, map: &dyn Fn(Handle<Function>) -> Handle<Function>) {
    for (_, e) in f.expressions.iter_mut() {
        if let Expression::CallResult(h) = e {
            *h = map(*h);
        }
    }
    visit_statements(&mut f.body, &mut |s| {
        if let Statement::Call { function, .. } = s {
            *function = map(*function);
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `main` calls a function declared by a prototype before it and defined after the
    /// functions it calls (the Shadertoy `mainImage` shape): naga's front leaves it first.
    const PROTOTYPES: &str = "#version 450
layout(location = 0) out vec4 o;
void mainImage(out vec4 c, in vec2 p);
void main() { vec4 c; mainImage(c, vec2(0.5)); o = c; }
float model(float x);
float trace(float x) { return model(x) * 2.0; }
float model(float x) { return x + 1.0; }
void mainImage(out vec4 c, in vec2 p) { c = vec4(trace(p.x)); }
";

    fn validate(module: &Module) -> bool {
        let flags = naga::valid::ValidationFlags::all();
        naga::valid::Validator::new(flags, naga::valid::Capabilities::empty()).validate(module).is_ok()
    }

    #[test]
    fn a_callee_defined_after_its_caller_moves_before_it() {
        let options = naga::front::glsl::Options::from(naga::ShaderStage::Fragment);
        let mut module = naga::front::glsl::Frontend::default().parse(&options, PROTOTYPES).unwrap();
        assert!(!validate(&module), "naga's front now orders this itself: the reorder may go");
        let names = |m: &Module| m.functions.iter().map(|(_, f)| f.name.clone().unwrap_or_default()).collect::<Vec<_>>();
        let before = names(&module);
        callees_first(&mut module);
        assert!(validate(&module));
        let after = names(&module);
        assert_eq!(after.len(), before.len());
        let at = |n: &str| after.iter().position(|x| x == n).unwrap();
        assert!(at("model") < at("trace") && at("trace") < at("mainImage"), "{after:?}");
    }
}
