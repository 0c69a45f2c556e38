//! The walk over glsl-lang's AST that fills a [`StageSyntax`]: external declarations and
//! function prototypes here; types and qualifiers, global declarations, statements and
//! expressions in the submodules. Scopes are tracked so locals never resolve to globals.

mod declarations;
mod evaluation;
mod expressions;
mod specifiers;
mod statements;

use std::collections::{HashMap, HashSet};
use std::ops::Range;

use glsl_lang::ast;

use crate::front::syntax::model::{Function, Param, StageSyntax};
use crate::front::syntax::nodes::span_of;

/// The walk: the stage being filled, the scopes open at this point, and what the
/// current function and expression need.
pub(super) struct Collector<'a> {
    s: &'a mut StageSyntax,
    scopes: Vec<HashMap<String, Option<usize>>>,
    current_function: Option<(String, usize)>,
    user_functions: HashSet<String>,
    /// The expression being walked is a whole argument of a user-function call.
    arg_context: bool,
    /// Macro-body occurrences already recorded (a macro expands at many sites).
    macro_uses: HashSet<(String, usize)>,
    /// `const int` locals of the current function with their values.
    local_consts: HashMap<String, i64>,
    /// The body spans of the stage's `#define` lines, found once (a stage of many macro
    /// uses asked the whole text for them at each use).
    macro_bodies: Vec<std::ops::Range<usize>>,
    /// Object-like macros that rename one identifier: (macro name, the name it gives).
    renames: Vec<(String, String)>,
}

impl<'a> Collector<'a> {
    pub(super) fn run(s: &'a mut StageSyntax, tu: &ast::TranslationUnit) {
        let user_functions =
            tu.0.iter()
                .filter_map(|d| match &d.content {
                    ast::ExternalDeclarationData::FunctionDefinition(f) => Some(f.prototype.name.0.to_string()),
                    ast::ExternalDeclarationData::Declaration(d) => match &d.content {
                        ast::DeclarationData::FunctionPrototype(p) => Some(p.name.0.to_string()),
                        _ => None,
                    },
                    _ => None,
                })
                .collect();
        let defines = crate::front::conditionals::define_lines(&s.text);
        // Object-like macros whose body is one identifier (`#define texture2D texture2DRect`).
        let renames = defines
            .iter()
            .filter_map(|(name, body)| Some((name.clone(), crate::front::conditionals::renamed_to(&s.text[body.clone()])?.to_string())))
            .collect();
        let macro_bodies = defines.into_iter().map(|(_, body)| body).collect();
        let mut c = Collector {
            s,
            scopes: Vec::new(),
            current_function: None,
            user_functions,
            arg_context: false,
            macro_uses: HashSet::new(),
            local_consts: HashMap::new(),
            macro_bodies,
            renames,
        };
        for decl in &tu.0 {
            c.external(decl);
        }
    }

    fn external(&mut self, decl: &ast::ExternalDeclaration) {
        let span = span_of(decl);
        match &decl.content {
            ast::ExternalDeclarationData::Preprocessor(_) => {}
            ast::ExternalDeclarationData::FunctionDefinition(def) => {
                if self.s.first_function.is_none() {
                    self.s.first_function = Some(span.start);
                }
                let idx = self.function(&def.prototype, span, true);
                let name = def.prototype.name.0.to_string();
                if name == "main" {
                    self.s.has_main = true;
                    self.s.main_body = Some(span_of(&def.statement));
                }
                self.current_function = Some((name, idx));
                self.local_consts.clear();
                let mut scope = HashMap::new();
                for p in &self.s.functions[idx].params {
                    if let Some(n) = &p.name {
                        scope.insert(n.clone(), None);
                    }
                }
                self.scopes.push(scope);
                self.compound(&def.statement);
                self.scopes.pop();
                self.current_function = None;
            }
            ast::ExternalDeclarationData::Declaration(d) => self.global_declaration(d, span),
        }
    }

    fn function(&mut self, proto: &ast::FunctionPrototype, span: Range<usize>, is_definition: bool) -> usize {
        let mut params = Vec::new();
        for p in &proto.parameters {
            let pspan = span_of(p);
            match &p.content {
                ast::FunctionParameterDeclarationData::Named(_, d) => {
                    let mut ty = self.type_of(&d.ty);
                    if let Some(a) = &d.ident.array_spec {
                        ty.dims.extend(self.dims(a));
                    }
                    params.push(Param { name: Some(d.ident.ident.0.to_string()), ty, span: pspan });
                }
                ast::FunctionParameterDeclarationData::Unnamed(_, t) => {
                    params.push(Param { name: None, ty: self.type_of(t), span: pspan });
                }
            }
        }
        self.s.functions.push(Function { name: proto.name.0.to_string(), span, is_definition, params });
        self.s.functions.len() - 1
    }
}
