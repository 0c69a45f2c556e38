//! Type specifiers, array dimensions, integer constant expressions, struct definitions
//! and qualifiers, read from the AST as the user wrote them.

use std::ops::Range;

use glsl_lang::ast;
use glsl_lang::transpiler::glsl::{show_type_specifier_non_array, FormattingState};

use super::Collector;
use crate::front::syntax::model::{Member, StructDef};
use crate::front::syntax::nodes::span_of;
use crate::front::syntax::types::{GlslType, Interp, Storage};

impl Collector<'_> {
    pub(super) fn type_of(&mut self, t: &ast::TypeSpecifier) -> GlslType {
        let base = match &t.ty.content {
            ast::TypeSpecifierNonArrayData::Struct(st) => self.struct_def(st, span_of(st)),
            _ => {
                let mut out = String::new();
                let _ = show_type_specifier_non_array(&mut out, &t.ty, &mut FormattingState::default());
                out
            }
        };
        let mut ty = GlslType { base, dims: Vec::new() };
        if let Some(a) = &t.array_specifier {
            ty.dims = self.dims(a);
        }
        ty
    }

    pub(super) fn dims(&self, a: &ast::ArraySpecifier) -> Vec<Option<u32>> {
        a.dimensions
            .iter()
            .map(|d| match &d.content {
                ast::ArraySpecifierDimensionData::Unsized => None,
                ast::ArraySpecifierDimensionData::ExplicitlySized(e) => self.const_int(e).and_then(|v| u32::try_from(v).ok()),
            })
            .collect()
    }

    /// Evaluates an integer constant expression made of literals, `const int`s and + - * /.
    pub(super) fn const_int(&self, e: &ast::Expr) -> Option<i64> {
        match &e.content {
            ast::ExprData::IntConst(v) => Some(*v as i64),
            ast::ExprData::UIntConst(v) => Some(*v as i64),
            ast::ExprData::Variable(id) => self
                .local_consts
                .get(id.0.as_str())
                .or_else(|| self.s.int_consts.get(id.0.as_str()))
                .copied()
                .or_else(|| crate::front::builtins::constants::value(id.0.as_str())),
            ast::ExprData::Binary(op, a, b) => {
                let (a, b) = (self.const_int(a)?, self.const_int(b)?);
                match op.content {
                    ast::BinaryOpData::Add => a.checked_add(b),
                    ast::BinaryOpData::Sub => a.checked_sub(b),
                    ast::BinaryOpData::Mult => a.checked_mul(b),
                    ast::BinaryOpData::Div if b != 0 => Some(a / b),
                    _ => None,
                }
            }
            ast::ExprData::Unary(op, a) if op.content == ast::UnaryOpData::Minus => self.const_int(a).map(|v| -v),
            ast::ExprData::FunCall(_, args) if args.len() == 1 => self.const_int(&args[0]),
            // `min`/`max` of constants (array sizes bounded by implementation limits).
            ast::ExprData::FunCall(f, args) if args.len() == 2 => {
                let (a, b) = (self.const_int(&args[0])?, self.const_int(&args[1])?);
                match &f.content {
                    ast::FunIdentifierData::Expr(e) => match &e.content {
                        ast::ExprData::Variable(id) if id.0.as_str() == "min" => Some(a.min(b)),
                        ast::ExprData::Variable(id) if id.0.as_str() == "max" => Some(a.max(b)),
                        _ => None,
                    },
                    _ => None,
                }
            }
            _ => None,
        }
    }

    /// Records the struct `st` defines and returns its name. An anonymous struct (`uniform
    /// struct { vec4 x; } a;`) is named after its members ([`anonymous_struct_name`]), so
    /// the same definition in two stages is one type of the shared uniform block, as GL
    /// links it; its name span is the `struct` keyword.
    pub(super) fn struct_def(&mut self, st: &ast::StructSpecifier, span: Range<usize>) -> String {
        if let Some(name) = st.name.as_ref().filter(|n| self.s.structs.iter().any(|s| s.name == n.0.as_str())) {
            return name.0.to_string();
        }
        let members = self.members(&st.fields);
        let (name, name_span) = match &st.name {
            Some(name) => (name.0.to_string(), span_of(name)),
            None => (anonymous_struct_name(&members), span.start..span.start + "struct".len()),
        };
        if !self.s.structs.iter().any(|s| s.name == name) {
            self.s.structs.push(StructDef { name: name.clone(), name_span, span, members });
        }
        name
    }

    pub(super) fn members(&mut self, fields: &[ast::StructFieldSpecifier]) -> Vec<Member> {
        let mut out = Vec::new();
        for f in fields {
            let base = self.type_of(&f.ty);
            let q = self.qualifiers(f.qualifier.as_ref());
            let (interp, centroid) = (q.interp, q.centroid);
            for id in &f.identifiers {
                let mut ty = base.clone();
                if let Some(a) = &id.array_spec {
                    let mut dims = self.dims(a);
                    dims.extend(ty.dims);
                    ty.dims = dims;
                }
                out.push(Member {
                    name: id.ident.0.to_string(),
                    ty,
                    span: span_of(&id.ident),
                    field_span: span_of(f),
                    interp,
                    centroid,
                    shares_field: f.identifiers.len() > 1,
                    qualifier_span: f.qualifier.as_ref().map(span_of),
                    layout: q.layout.clone(),
                });
            }
        }
        out
    }

    pub(super) fn qualifiers(&self, q: Option<&ast::TypeQualifier>) -> Quals {
        let mut out = Quals::default();
        let Some(q) = q else { return out };
        for spec in &q.qualifiers {
            match &spec.content {
                ast::TypeQualifierSpecData::Interpolation(i) => {
                    out.interp = Some(match i.content {
                        ast::InterpolationQualifierData::Smooth => Interp::Smooth,
                        ast::InterpolationQualifierData::Flat => Interp::Flat,
                        ast::InterpolationQualifierData::NoPerspective => Interp::NoPerspective,
                    })
                }
                ast::TypeQualifierSpecData::Storage(st) => {
                    let sp = span_of(st);
                    let kind = match &st.content {
                        ast::StorageQualifierData::Centroid => {
                            out.centroid = true;
                            None
                        }
                        ast::StorageQualifierData::Uniform => Some(Storage::Uniform),
                        ast::StorageQualifierData::In => Some(Storage::In),
                        ast::StorageQualifierData::Out => Some(Storage::Out),
                        ast::StorageQualifierData::Attribute => Some(Storage::Attribute),
                        ast::StorageQualifierData::Varying => Some(Storage::Varying),
                        ast::StorageQualifierData::Buffer => Some(Storage::Buffer),
                        ast::StorageQualifierData::Const => Some(Storage::Const),
                        _ => None,
                    };
                    if let Some(k) = kind {
                        // `centroid varying` / `const in` keep the meaningful one.
                        if out.storage.is_none() || k != Storage::Const {
                            out.storage = Some((k, sp));
                        }
                    }
                }
                ast::TypeQualifierSpecData::Layout(l) => {
                    out.layout_span = Some(span_of(l));
                    for id in &l.ids {
                        match &id.content {
                            ast::LayoutQualifierSpecData::Identifier(name, value) => {
                                out.layout.push((name.0.to_string(), value.as_ref().and_then(|v| self.const_int(v))));
                                out.layout_items.push((name.0.to_string(), span_of(id)));
                            }
                            ast::LayoutQualifierSpecData::Shared => {
                                out.layout.push(("shared".to_string(), None));
                                out.layout_items.push(("shared".to_string(), span_of(id)));
                            }
                        }
                    }
                }
                ast::TypeQualifierSpecData::Invariant => out.invariant = Some(span_of(spec)),
                _ => {}
            }
        }
        out
    }
}

/// The qualifiers of one declaration, as written.
#[derive(Debug, Default)]
pub(super) struct Quals {
    pub(super) interp: Option<Interp>,
    pub(super) centroid: bool,
    /// The `invariant` qualifier's span.
    pub(super) invariant: Option<Range<usize>>,
    pub(super) storage: Option<(Storage, Range<usize>)>,
    pub(super) layout_span: Option<Range<usize>>,
    pub(super) layout: Vec<(String, Option<i64>)>,
    pub(super) layout_items: Vec<(String, Range<usize>)>,
}

pub(super) fn location_of(layout: &[(String, Option<i64>)]) -> Option<u32> {
    crate::front::syntax::layout_number(layout, "location")
}

/// The name effectc gives an anonymous struct: `effectc_struct_` and each member's type and
/// name (`struct { vec4 x; float w[2]; }` → `effectc_struct_vec4_x_float_2_w`).
fn anonymous_struct_name(members: &[Member]) -> String {
    let mut name = String::from("effectc_struct");
    for m in members {
        let dims: String = m.ty.dims.iter().map(|d| d.map_or_else(|| "_".to_string(), |n| format!("_{n}"))).collect();
        name.push_str(&format!("_{}{dims}_{}", m.ty.base, m.name));
    }
    name.chars().map(|c| if c.is_ascii_alphanumeric() || c == '_' { c } else { '_' }).collect()
}
