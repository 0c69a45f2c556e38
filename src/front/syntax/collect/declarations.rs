//! Global declarations: interface and uniform blocks, variables (one [`Global`] per
//! declared name), default-qualifier declarations, and unsized arrays their initializer sizes.

use std::ops::Range;

use glsl_lang::ast;

use super::specifiers::{location_of, Quals};
use super::Collector;
use crate::front::syntax::model::{BlockInfo, DefaultDecl, Global};
use crate::front::syntax::nodes::span_of;
use crate::front::syntax::types::{GlslType, Storage};

impl Collector<'_> {
    pub(super) fn global_declaration(&mut self, d: &ast::Declaration, span: Range<usize>) {
        match &d.content {
            ast::DeclarationData::FunctionPrototype(p) => {
                if self.s.first_function.is_none() {
                    self.s.first_function = Some(span.start);
                }
                self.function(p, span, false);
            }
            ast::DeclarationData::Precision(..) => self.s.precision_statements.push(span),
            ast::DeclarationData::Block(b) => {
                let q = self.qualifiers(Some(&b.qualifier));
                let layout_items = q.layout_items.clone();
                let Quals { interp, centroid, invariant, storage, layout_span, layout, .. } = q;
                let members = self.members(&b.fields);
                let (instance, instance_span, instance_dims) = match &b.identifier {
                    Some(id) => (
                        Some(id.ident.0.to_string()),
                        Some(span_of(&id.ident)),
                        id.array_spec.as_ref().map(|a| self.dims(a)).unwrap_or_default(),
                    ),
                    None => (None, None, Vec::new()),
                };
                let location = location_of(&layout);
                let block_name = b.name.0.to_string();
                let block_name_span = span_of(&b.name);
                self.s.globals.push(Global {
                    storage: storage.as_ref().map(|s| s.0).unwrap_or(Storage::Uniform),
                    name: block_name.clone(),
                    name_span: block_name_span.clone(),
                    ty: GlslType { base: block_name.clone(), dims: instance_dims.clone() },
                    decl_span: span,
                    storage_span: storage.map(|s| s.1),
                    layout_span,
                    layout,
                    location,
                    interp,
                    centroid,
                    invariant,
                    block: Some(BlockInfo { block_name, block_name_span, instance, instance_span, instance_dims, members }),
                    shares_decl: false,
                    initializer: None,
                    layout_items,
                });
            }
            ast::DeclarationData::InitDeclaratorList(list) => {
                let head = &list.head;
                let q = self.qualifiers(head.ty.qualifier.as_ref());
                let layout_items = q.layout_items.clone();
                let Quals { interp, centroid, invariant, storage, layout_span, layout, .. } = q;
                if let (Some(a), Some(init)) = (head.array_specifier.as_ref().or(head.ty.ty.array_specifier.as_ref()), &head.initializer) {
                    self.unsized_from_initializer(a, init);
                }
                for t in &list.tail {
                    if let (Some(a), Some(init)) = (&t.ident.array_spec, &t.initializer) {
                        self.unsized_from_initializer(a, init);
                    }
                }
                let base = self.type_of(&head.ty.ty);
                let shares = !list.tail.is_empty();
                let storage_kind = storage.as_ref().map(|s| s.0).unwrap_or(Storage::Private);
                let declare =
                    |this: &mut Self, name: &ast::Identifier, array: Option<&ast::ArraySpecifier>, init: Option<&ast::Initializer>| {
                        let mut ty = base.clone();
                        if let Some(a) = array {
                            let mut dims = this.dims(a);
                            dims.extend(ty.dims);
                            ty.dims = dims;
                        }
                        if let Some(i) = init {
                            this.initializer(i);
                            if storage_kind == Storage::Const && (ty.base == "int" || ty.base == "uint") && !ty.is_array() {
                                if let ast::InitializerData::Simple(e) = &i.content {
                                    if let Some(v) = this.const_int(e) {
                                        this.s.int_consts.insert(name.0.to_string(), v);
                                    }
                                }
                            }
                        }
                        this.s.globals.push(Global {
                            storage: storage_kind,
                            name: name.0.to_string(),
                            name_span: span_of(name),
                            ty,
                            decl_span: span.clone(),
                            storage_span: storage.as_ref().map(|s| s.1.clone()),
                            layout_span: layout_span.clone(),
                            layout: layout.clone(),
                            location: location_of(&layout),
                            interp,
                            centroid,
                            invariant: invariant.clone(),
                            block: None,
                            shares_decl: shares,
                            initializer: init.map(span_of),
                            layout_items: layout_items.clone(),
                        });
                    };
                if let Some(name) = &head.name {
                    declare(self, name, head.array_specifier.as_ref(), head.initializer.as_ref());
                }
                for t in &list.tail {
                    declare(self, &t.ident.ident, t.ident.array_spec.as_ref(), t.initializer.as_ref());
                }
            }
            ast::DeclarationData::TypeOnly(q) => {
                let q = self.qualifiers(Some(q));
                self.s.defaults.push(DefaultDecl { span, storage: q.storage.map(|s| s.0), layout: q.layout });
            }
            ast::DeclarationData::Invariant(_) => {}
        }
    }

    /// `T name[] = T[](a, b, c)` / `= { a, b, c }`: the size is the initializer's length.
    pub(super) fn unsized_from_initializer(&mut self, a: &ast::ArraySpecifier, init: &ast::Initializer) {
        let Some(first) = a.dimensions.first() else { return };
        if !matches!(first.content, ast::ArraySpecifierDimensionData::Unsized) {
            return;
        }
        let n = match &init.content {
            ast::InitializerData::List(items) => items.len(),
            ast::InitializerData::Simple(e) => match &e.content {
                ast::ExprData::FunCall(f, args) if matches!(&f.content, ast::FunIdentifierData::TypeSpecifier(t) if t.array_specifier.is_some()) => {
                    args.len()
                }
                _ => return,
            },
        };
        self.s.unsized_sizes.push((span_of(first), n as u32));
    }
}
