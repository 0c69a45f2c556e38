//! Order-of-evaluation facts naga's GLSL front gets wrong: short-circuit operators whose
//! right operand has side effects (naga evaluates it eagerly), and `do … while` loops
//! whose body continues (naga's `continue` skips the condition). The rewrite writes both
//! in forms naga evaluates as GLSL does.

use std::collections::HashSet;
use std::ops::Range;

use glsl_lang::ast;

use super::Collector;
use crate::front::syntax::model::{DoWhileContinue, LazyLogic};
use crate::front::syntax::nodes::span_of;

/// Prefixes of the built-in functions that change state (`atomicAdd`, `imageStore`,
/// `EmitVertex`, `EndStreamPrimitive`, `barrier`); everything else built in is pure.
const IMPURE_BUILTINS: &[&str] = &["atomic", "imageStore", "imageAtomic", "Emit", "End", "barrier"];

impl Collector<'_> {
    /// `a && b` / `a || b` with a side effect in `b`.
    pub(super) fn lazy_logic(&mut self, op: &ast::BinaryOp, a: &ast::Expr, b: &ast::Expr) {
        let and = match op.content {
            ast::BinaryOpData::And => true,
            ast::BinaryOpData::Or => false,
            _ => return,
        };
        if !has_side_effects(b, &self.user_functions) {
            return;
        }
        let text = &self.s.text;
        let (a, b) = (span_of(a), span_of(b));
        let token = if and { "&&" } else { "||" };
        let Some(between) = text.get(a.end..b.start) else { return };
        let Some(at) = between.find(token) else { return };
        let op = a.end + at..a.end + at + 2;
        // Operands written in parentheses: the parentheses between operand and operator
        // belong to the operand.
        let left = widen(text, a.clone(), text[a.end..op.start].matches(')').count());
        let right = widen(text, b.clone(), text[op.end..b.start].matches('(').count());
        self.s.lazy_logic.push(LazyLogic { left, op, right, and });
    }

    /// `do body while (cond);` whose body has a `continue` of its own.
    pub(super) fn do_while(&mut self, st: &ast::Statement, body: &ast::Statement, cond: &ast::Expr) {
        if !continues(body) {
            return;
        }
        let (whole, body, cond) = (span_of(st), span_of(body), span_of(cond));
        let text = &self.s.text;
        let Some(semicolon) = text.get(cond.end..).and_then(|t| t.find(';')) else { return };
        let tail = body.end..cond.end + semicolon + 1;
        if whole.start >= body.start || tail.end < tail.start {
            return;
        }
        self.s.do_while_continue.push(DoWhileContinue { keyword: whole.start..body.start, cond, tail });
    }
}

/// `span` grown over `count` pairs of parentheses written around it.
fn widen(text: &str, span: Range<usize>, count: usize) -> Range<usize> {
    let mut r = span;
    for _ in 0..count {
        let before = text[..r.start].trim_end();
        let after = text[r.end..].trim_start();
        if !before.ends_with('(') || !after.starts_with(')') {
            break;
        }
        r = before.len() - 1..text.len() - after.len() + 1;
    }
    r
}

/// Whether evaluating `e` can change state: a call of a user function or of an impure
/// built-in, an assignment, `++` or `--`.
pub(super) fn has_side_effects(e: &ast::Expr, user_functions: &HashSet<String>) -> bool {
    let s = |x: &ast::Expr| has_side_effects(x, user_functions);
    match &e.content {
        ast::ExprData::Assignment(..) | ast::ExprData::PostInc(_) | ast::ExprData::PostDec(_) => true,
        ast::ExprData::Unary(op, a) => matches!(op.content, ast::UnaryOpData::Inc | ast::UnaryOpData::Dec) || s(a),
        ast::ExprData::Binary(_, a, b) | ast::ExprData::Comma(a, b) | ast::ExprData::Bracket(a, b) => s(a) || s(b),
        ast::ExprData::Ternary(a, b, c) => s(a) || s(b) || s(c),
        ast::ExprData::Dot(a, _) => s(a),
        ast::ExprData::FunCall(f, args) => {
            let name = match &f.content {
                ast::FunIdentifierData::Expr(inner) => match &inner.content {
                    ast::ExprData::Variable(id) => Some(id.0.as_str()),
                    _ => None,
                },
                ast::FunIdentifierData::TypeSpecifier(_) => None,
            };
            let impure = name.is_some_and(|n| user_functions.contains(n) || IMPURE_BUILTINS.iter().any(|p| n.starts_with(p)));
            impure || args.iter().any(s)
        }
        _ => false,
    }
}

/// Whether `st` has a `continue` that belongs to the loop around it (not to a loop inside).
fn continues(st: &ast::Statement) -> bool {
    match &st.content {
        ast::StatementData::Jump(j) => matches!(j.content, ast::JumpStatementData::Continue),
        ast::StatementData::Compound(c) => c.statement_list.iter().any(continues),
        ast::StatementData::Selection(sel) => match &sel.rest.content {
            ast::SelectionRestStatementData::Statement(s) => continues(s),
            ast::SelectionRestStatementData::Else(a, b) => continues(a) || continues(b),
        },
        ast::StatementData::Switch(sw) => sw.body.iter().any(continues),
        _ => false,
    }
}
