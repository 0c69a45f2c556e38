//! Small readers of glsl-lang AST nodes: a node's span in the text, an expression as text.

use std::ops::Range;

use glsl_lang::ast::{self, NodeContent};
use glsl_lang::transpiler::glsl::{show_expr, FormattingState};

pub(super) fn span_of<T: NodeContent>(node: &ast::Node<T>) -> Range<usize> {
    node.span.map(|s| usize::from(s.range().start())..usize::from(s.range().end())).unwrap_or(0..0)
}

/// Render an expression (used for messages only).
pub fn expr_text(e: &ast::Expr) -> String {
    let mut out = String::new();
    let _ = show_expr(&mut out, e, &mut FormattingState::default());
    out
}

/// Where `name` stands as a whole identifier in `text[within]`.
pub fn word_occurrences(text: &str, within: Range<usize>, name: &str) -> Vec<Range<usize>> {
    let is_ident = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
    let bytes = text.as_bytes();
    let Some(region) = text.get(within.clone()) else { return Vec::new() };
    region
        .match_indices(name)
        .map(|(i, _)| within.start + i..within.start + i + name.len())
        .filter(|r| (r.start == 0 || !is_ident(bytes[r.start - 1])) && (r.end >= bytes.len() || !is_ident(bytes[r.end])))
        .collect()
}

/// The end of the `[…]` that follows `at` in `text` (after blanks), if one does.
pub fn bracket_after(text: &str, at: usize) -> Option<usize> {
    let rest = text.get(at..)?;
    let open = at + rest.len() - rest.trim_start().len();
    if !text[open..].starts_with('[') {
        return None;
    }
    let mut depth = 0usize;
    for (i, c) in text[open..].char_indices() {
        match c {
            '[' => depth += 1,
            ']' => {
                depth -= 1;
                if depth == 0 {
                    return Some(open + i + 1);
                }
            }
            _ => {}
        }
    }
    None
}
