//! Walking the statements of a naga block, nested blocks included: the one walk the front's
//! module passes (respanning, function order) and the back end's share.

use naga::{Block, Statement};

/// The blocks nested directly in a statement.
pub fn child_blocks(s: &mut Statement) -> Vec<&mut Block> {
    match s {
        Statement::Block(b) => vec![b],
        Statement::If { accept, reject, .. } => vec![accept, reject],
        Statement::Switch { cases, .. } => cases.iter_mut().map(|c| &mut c.body).collect(),
        Statement::Loop { body, continuing, .. } => vec![body, continuing],
        _ => Vec::new(),
    }
}

/// Calls `f` on every statement of `block`, nested ones included (parents first).
pub fn visit_statements(block: &mut Block, f: &mut impl FnMut(&mut Statement)) {
    for s in block.iter_mut() {
        f(s);
        for b in child_blocks(s) {
            visit_statements(b, f);
        }
    }
}
