//! Function bodies: statements, scopes, local declarations, and local constants that size
//! arrays or label cases (naga wants their values).

use std::collections::HashMap;

use glsl_lang::ast;

use super::Collector;
use crate::front::syntax::nodes::{expr_text, span_of};

impl Collector<'_> {
    pub(super) fn compound(&mut self, c: &ast::CompoundStatement) {
        self.scopes.push(HashMap::new());
        for st in &c.statement_list {
            self.statement(st);
        }
        self.scopes.pop();
    }

    fn declare_local(&mut self, name: &str) {
        if let Some(scope) = self.scopes.last_mut() {
            scope.insert(name.to_string(), None);
        }
    }

    fn local_declaration(&mut self, d: &ast::Declaration) {
        match &d.content {
            ast::DeclarationData::InitDeclaratorList(list) => {
                if let ast::TypeSpecifierNonArrayData::Struct(st) = &list.head.ty.ty.ty.content {
                    self.struct_def(st, span_of(st));
                }
                if let Some(a) = &list.head.ty.ty.array_specifier {
                    self.array_exprs(a);
                    // `ivec4[] n = ivec4[](…)`: the brackets on the type, sized the same way.
                    if let Some(init) = &list.head.initializer {
                        self.unsized_from_initializer(a, init);
                    }
                }
                if let Some(a) = &list.head.array_specifier {
                    self.array_exprs(a);
                    self.local_constant_sizes(a);
                    if let Some(init) = &list.head.initializer {
                        self.unsized_from_initializer(a, init);
                    }
                }
                let is_const = list.head.ty.qualifier.as_ref().is_some_and(|q| {
                    q.qualifiers.iter().any(|x| matches!(&x.content, ast::TypeQualifierSpecData::Storage(sq) if matches!(sq.content, ast::StorageQualifierData::Const)))
                });
                if let (true, Some(n), Some(ast::InitializerData::Simple(e))) =
                    (is_const, &list.head.name, list.head.initializer.as_ref().map(|i| &i.content))
                {
                    if let Some(v) = self.const_int(e) {
                        self.local_consts.insert(n.0.to_string(), v);
                    }
                }
                for t in &list.tail {
                    if let (Some(a), Some(init)) = (&t.ident.array_spec, &t.initializer) {
                        self.unsized_from_initializer(a, init);
                    }
                }
                if let Some(i) = &list.head.initializer {
                    self.initializer(i);
                }
                if let Some(n) = &list.head.name {
                    self.declare_local(n.0.as_str());
                }
                for t in &list.tail {
                    if let Some(i) = &t.initializer {
                        self.initializer(i);
                    }
                    self.declare_local(t.ident.ident.0.as_str());
                }
            }
            ast::DeclarationData::Block(_) | ast::DeclarationData::FunctionPrototype(_) => {}
            _ => {}
        }
    }

    /// A local array sized by a local `const int` (`float k[TAPS + 1];`): naga resolves
    /// array sizes among globals only, so the rewrite writes the value.
    fn local_constant_sizes(&mut self, a: &ast::ArraySpecifier) {
        for d in &a.dimensions {
            if let ast::ArraySpecifierDimensionData::ExplicitlySized(e) = &d.content {
                self.fold_local_constant(e);
            }
        }
    }

    /// Records `e` for the rewrite to write as its value when it reads a local constant.
    fn fold_local_constant(&mut self, e: &ast::Expr) {
        let uses_local = expr_text(e).split(|c: char| !c.is_ascii_alphanumeric() && c != '_').any(|w| self.local_consts.contains_key(w));
        if let (true, Some(Ok(v))) = (uses_local, self.const_int(e).map(u32::try_from)) {
            self.s.constant_sizes.push((span_of(e), v));
        }
    }

    fn statement(&mut self, st: &ast::Statement) {
        match &st.content {
            ast::StatementData::Declaration(d) => self.local_declaration(d),
            ast::StatementData::Expression(e) => {
                if let Some(e) = &e.0 {
                    self.expr(e);
                }
            }
            ast::StatementData::Selection(sel) => {
                self.expr(&sel.cond);
                match &sel.rest.content {
                    ast::SelectionRestStatementData::Statement(s) => self.scoped_statement(s),
                    ast::SelectionRestStatementData::Else(a, b) => {
                        self.scoped_statement(a);
                        self.scoped_statement(b);
                    }
                }
            }
            ast::StatementData::Switch(sw) => {
                self.expr(&sw.head);
                self.scopes.push(HashMap::new());
                for s in &sw.body {
                    self.statement(s);
                }
                self.scopes.pop();
            }
            ast::StatementData::CaseLabel(c) => {
                if let ast::CaseLabelData::Case(e) = &c.content {
                    self.expr(e);
                    // `case TAPS:` with a local constant: naga wants the value.
                    self.fold_local_constant(e);
                }
            }
            ast::StatementData::Iteration(it) => {
                self.scopes.push(HashMap::new());
                match &it.content {
                    ast::IterationStatementData::While(cond, body) => {
                        self.condition(cond);
                        self.scoped_statement(body);
                    }
                    ast::IterationStatementData::DoWhile(body, cond) => {
                        self.do_while(st, body, cond);
                        self.scoped_statement(body);
                        self.expr(cond);
                    }
                    ast::IterationStatementData::For(init, rest, body) => {
                        match &init.content {
                            ast::ForInitStatementData::Expression(Some(e)) => self.expr(e),
                            ast::ForInitStatementData::Expression(None) => {}
                            ast::ForInitStatementData::Declaration(d) => self.local_declaration(d),
                        }
                        if let Some(c) = &rest.condition {
                            self.condition(c);
                            self.constructor_condition(c);
                        }
                        if let Some(e) = &rest.post_expr {
                            self.expr(e);
                        }
                        self.scoped_statement(body);
                    }
                }
                self.scopes.pop();
            }
            ast::StatementData::Jump(j) => {
                if matches!(j.content, ast::JumpStatementData::Return(_))
                    && self.current_function.as_ref().is_some_and(|(n, _)| n == "main")
                {
                    self.s.main_returns.push(span_of(st));
                }
                if let ast::JumpStatementData::Return(Some(e)) = &j.content {
                    self.expr(e);
                }
            }
            ast::StatementData::Compound(c) => self.compound(c),
        }
    }

    fn scoped_statement(&mut self, st: &ast::Statement) {
        self.scopes.push(HashMap::new());
        self.statement(st);
        self.scopes.pop();
    }

    /// A `for` condition whose text starts with a scalar, vector or matrix constructor.
    fn constructor_condition(&mut self, c: &ast::Condition) {
        let span = span_of(c);
        let text = self.s.text.get(span.clone()).unwrap_or("");
        let word_len = text.bytes().take_while(|b| b.is_ascii_alphanumeric() || *b == b'_').count();
        if text[word_len..].trim_start().starts_with('(') && is_arithmetic_type(&text[..word_len]) {
            self.s.constructor_conditions.push(span);
        }
    }

    fn condition(&mut self, c: &ast::Condition) {
        match &c.content {
            ast::ConditionData::Expr(e) => self.expr(e),
            ast::ConditionData::Assignment(_, name, init) => {
                self.initializer(init);
                self.declare_local(name.0.as_str());
            }
        }
    }
}

/// A scalar, vector or matrix type name (`float`, `ivec2`, `mat3x4`, `dvec3`).
fn is_arithmetic_type(word: &str) -> bool {
    if matches!(word, "float" | "int" | "uint" | "bool" | "double") {
        return true;
    }
    let shape = word.strip_prefix(['i', 'u', 'b', 'd']).unwrap_or(word);
    let n = |t: &str| matches!(t, "2" | "3" | "4");
    shape.strip_prefix("vec").is_some_and(n)
        || shape.strip_prefix("mat").is_some_and(|m| n(m) || m.split_once('x').is_some_and(|(a, b)| n(a) && n(b)))
}
