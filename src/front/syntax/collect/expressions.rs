//! Expressions: each identifier resolved through the scopes to a global or an opaque
//! parameter and recorded with its index / field / call-argument context; calls;
//! swizzle-shaped field accesses; names written in `#define` bodies.

use std::ops::Range;

use glsl_lang::ast;

use super::Collector;
use crate::front::syntax::model::{Call, Referent, Swizzle, Use};
use crate::front::syntax::nodes::{span_of, word_occurrences};

impl Collector<'_> {
    /// Whole-word occurrences of `name` in the bodies of `#define` lines (after the macro's name).
    fn macro_body_occurrences(&self, name: &str) -> Vec<Range<usize>> {
        self.macro_bodies.iter().flat_map(|body| word_occurrences(&self.s.text, body.clone(), name)).collect()
    }

    /// Records a call of `n` (its name at `sp`) in the stage's calls: where it is written, or,
    /// expanded from a macro, where its name is written in the macro's use or body.
    fn record_call(&mut self, n: String, sp: Range<usize>, e: &ast::Expr, args: &[ast::Expr]) {
        let in_function = self.current_function.as_ref().map(|(n, _)| n.clone());
        let first_arg_name = args.first().and_then(|a| match &a.content {
            ast::ExprData::Variable(id) => Some(id.0.to_string()),
            _ => None,
        });
        // A macro that renames the function (`#define texture2D texture2DRect`) written at
        // the call: the call is the use's, arguments and all.
        let renamed = self.s.text.get(sp.clone()).is_some_and(|used| self.renames.iter().any(|(name, body)| name == used && *body == n));
        if self.s.text.get(sp.clone()) != Some(n.as_str()) && !renamed {
            // Written in a function-like macro's argument (`round(modf(x, i))` with
            // `#define round(X) ...`): the name is in the use's text, which the span
            // covers; each occurrence there is taken once, in order. Arguments are
            // not known.
            let in_use = word_occurrences(&self.s.text, sp.clone(), &n)
                .into_iter()
                .find(|at| !self.macro_uses.contains(&(n.clone(), at.start)) && !self.in_macro_body(at.start));
            // Expanded from a macro: the name is written in `#define` bodies too.
            for at in in_use.into_iter().chain(self.macro_body_occurrences(&n)) {
                if self.macro_uses.insert((n.clone(), at.start)) {
                    self.s.calls.push(Call {
                        name: n.clone(),
                        name_span: at.clone(),
                        span: at,
                        in_function: in_function.clone(),
                        args: Vec::new(),
                        first_arg_name: None,
                        from_macro: true,
                    });
                }
            }
        } else {
            self.s.calls.push(Call {
                name: n,
                name_span: sp,
                span: span_of(e),
                in_function,
                args: args.iter().map(span_of).collect(),
                first_arg_name,
                from_macro: false,
            });
        }
    }

    /// Whether `at` lies in a `#define` body.
    fn in_macro_body(&self, at: usize) -> bool {
        self.macro_bodies.iter().any(|body| body.contains(&at))
    }

    pub(super) fn initializer(&mut self, i: &ast::Initializer) {
        match &i.content {
            ast::InitializerData::Simple(e) => self.expr(e),
            ast::InitializerData::List(list) => list.iter().for_each(|i| self.initializer(i)),
        }
    }

    pub(super) fn array_exprs(&mut self, a: &ast::ArraySpecifier) {
        for d in &a.dimensions {
            if let ast::ArraySpecifierDimensionData::ExplicitlySized(e) = &d.content {
                self.expr(e);
            }
        }
    }

    fn resolve(&self, name: &str) -> Referent {
        for scope in self.scopes.iter().rev() {
            if scope.contains_key(name) {
                // Locals and parameters: only opaque parameters matter to the rewrite.
                if let Some((_, f)) = &self.current_function {
                    let func = &self.s.functions[*f];
                    if let Some(pi) = func.params.iter().position(|p| p.name.as_deref() == Some(name)) {
                        // A parameter is only visible from the function's outermost scope;
                        // an inner local of the same name shadows it.
                        if std::ptr::eq(scope, &self.scopes[0]) && func.params[pi].ty.is_sampler() {
                            return Referent::Param(*f, pi);
                        }
                    }
                }
                return Referent::Unresolved;
            }
        }
        // Globals: the last declaration of that name (redeclaration is an error naga reports).
        if let Some(i) = self.s.globals.iter().rposition(|g| g.name == name && g.block.is_none()) {
            return Referent::Global(i);
        }
        // Members of anonymous blocks are globals too.
        if let Some(i) = self
            .s
            .globals
            .iter()
            .rposition(|g| g.block.as_ref().is_some_and(|b| b.instance.is_none() && b.members.iter().any(|m| m.name == name)))
        {
            return Referent::Global(i);
        }
        // Instance names of blocks.
        if let Some(i) = self.s.globals.iter().rposition(|g| g.block.as_ref().is_some_and(|b| b.instance.as_deref() == Some(name))) {
            return Referent::Global(i);
        }
        Referent::Unresolved
    }

    fn record(
        &mut self,
        id: &ast::Identifier,
        index: Option<(Range<usize>, Range<usize>, Option<i64>)>,
        field: Option<(String, Range<usize>)>,
        user_call_arg: bool,
    ) {
        let name = id.0.to_string();
        let target = self.resolve(&name);
        let in_function = self.current_function.as_ref().map(|(n, _)| n.clone());
        // Locals are resolved (Unresolved with a scope hit) — only record what matters.
        let is_local = self.scopes.iter().any(|s| s.contains_key(&name));
        if is_local && !matches!(target, Referent::Param(..)) {
            return;
        }
        let span = span_of(id);
        if self.s.text.get(span.clone()) != Some(name.as_str()) {
            // Expanded from a macro: glsl-lang gives the invocation's span. A name passed as
            // the macro's argument is written inside that span (`tex2D(Texture_Color)`):
            // record it there, so rewrites edit the argument.
            let invocation = self.s.text.get(span.clone()).unwrap_or("");
            let object_like = !invocation.is_empty() && invocation.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_');
            // An object-like macro passed straight to a user function (`#define Source
            // Texture` … `blur(Source, uv)`): the argument is edited where it is written,
            // since the body may also be used elsewhere as a plain sampler.
            let in_args =
                if user_call_arg && object_like { vec![span.clone()] } else { word_occurrences(&self.s.text, span.clone(), &name) };
            // Else the name is written in `#define` bodies; record it there (once), so
            // rewrites edit the body.
            let written = if in_args.is_empty() { self.macro_body_occurrences(&name) } else { in_args };
            for at in written {
                if self.macro_uses.insert((name.clone(), at.start)) {
                    let (name, target, in_function) = (name.clone(), target.clone(), in_function.clone());
                    self.s.uses.push(Use { name, target, span: at, index: None, field: None, user_call_arg, in_function });
                }
            }
            return;
        }
        self.s.uses.push(Use { name, target, span, index, field, user_call_arg, in_function });
    }

    pub(super) fn expr(&mut self, e: &ast::Expr) {
        let arg = std::mem::take(&mut self.arg_context);
        match &e.content {
            ast::ExprData::Variable(id) => self.record(id, None, None, arg),
            ast::ExprData::Bracket(base, idx) => {
                if let ast::ExprData::Variable(id) = &base.content {
                    let info = (span_of(e), span_of(idx), self.const_int(idx));
                    self.record(id, Some(info), None, arg);
                } else {
                    self.expr(base);
                }
                self.expr(idx);
            }
            ast::ExprData::Dot(base, field) => {
                let name = field.0.as_str();
                let sets = ["xyzw", "rgba", "stpq"];
                let (whole, base_span) = (span_of(e), span_of(base));
                let swizzle_like = (1..=4).contains(&name.len()) && sets.iter().any(|set| name.chars().all(|c| set.contains(c)));
                if swizzle_like && self.s.text.get(whole.clone()).is_some_and(|t| t.ends_with(name)) && base_span.end <= whole.end {
                    self.s.swizzles.push(Swizzle { base: base_span, whole, width: name.len() });
                }
                let f = Some((field.0.to_string(), span_of(e)));
                match &base.content {
                    ast::ExprData::Variable(id) => self.record(id, None, f, arg),
                    ast::ExprData::Bracket(inner, idx) => {
                        if let ast::ExprData::Variable(id) = &inner.content {
                            let info = (span_of(base), span_of(idx), self.const_int(idx));
                            self.record(id, Some(info), f, arg);
                        } else {
                            self.expr(inner);
                        }
                        self.expr(idx);
                    }
                    _ => self.expr(base),
                }
            }
            ast::ExprData::FunCall(fid, args) => {
                let name = match &fid.content {
                    ast::FunIdentifierData::Expr(inner) => match &inner.content {
                        ast::ExprData::Variable(id) => Some((id.0.to_string(), span_of(id))),
                        _ => {
                            self.expr(inner);
                            None
                        }
                    },
                    ast::FunIdentifierData::TypeSpecifier(t) => {
                        if let Some(a) = &t.array_specifier {
                            self.array_exprs(a);
                            if let Some(d) = a.dimensions.first().filter(|d| matches!(d.content, ast::ArraySpecifierDimensionData::Unsized))
                            {
                                self.s.unsized_sizes.push((span_of(d), args.len() as u32));
                            }
                        }
                        match &t.ty.content {
                            ast::TypeSpecifierNonArrayData::TypeName(n) => Some((n.0.to_string(), span_of(n))),
                            _ => None,
                        }
                    }
                };
                let is_user = name.as_ref().is_some_and(|(n, _)| self.user_functions.contains(n));
                if let Some((n, sp)) = name {
                    self.record_call(n, sp, e, args);
                }
                for a in args {
                    self.arg_context = is_user;
                    self.expr(a);
                }
            }
            ast::ExprData::Unary(_, a) | ast::ExprData::PostInc(a) | ast::ExprData::PostDec(a) => self.expr(a),
            ast::ExprData::Binary(op, a, b) => {
                self.lazy_logic(op, a, b);
                self.expr(a);
                self.expr(b);
            }
            ast::ExprData::Assignment(a, _, b) | ast::ExprData::Comma(a, b) => {
                self.expr(a);
                self.expr(b);
            }
            ast::ExprData::Ternary(a, b, c) => {
                self.expr(a);
                self.expr(b);
                self.expr(c);
            }
            ast::ExprData::IntConst(_)
            | ast::ExprData::UIntConst(_)
            | ast::ExprData::BoolConst(_)
            | ast::ExprData::FloatConst(_)
            | ast::ExprData::DoubleConst(_) => {}
        }
    }
}
