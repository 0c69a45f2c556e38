//! Syntax analysis of one GLSL stage with glsl-lang: declarations and resolved use sites.
//!
//! The result, [`StageSyntax`], is what both the GL link checks and the rewrite to 4.50 work
//! from: every global declaration with its qualifiers and spans, every function with its
//! parameters, and every place an identifier refers to a global (or to an opaque function
//! parameter), with the surrounding index / field / call-argument context. Scopes are
//! tracked, so a local that shadows a uniform is never rewritten.

use std::collections::{HashMap, HashSet};
use std::ops::Range;

use glsl_lang::ast::{self, NodeContent};
use glsl_lang::parse::DefaultParse;
use glsl_lang::transpiler::glsl::{show_expr, show_type_specifier_non_array, FormattingState};

use crate::diag::{Diagnostic, FileId};
use crate::front::version::{self, Renames, Version};
use crate::stage::StageKind;

/// Storage class of a global declaration, as written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Storage {
    Uniform,
    In,
    Out,
    /// 1xx `attribute` (a vertex input).
    Attribute,
    /// 1xx `varying` (an output in the vertex stage, an input in the fragment stage).
    Varying,
    Buffer,
    Const,
    /// A private global (`float x;`).
    Private,
}

/// Interpolation qualifiers that must agree across a link.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Interp {
    Smooth,
    Flat,
    NoPerspective,
}

/// A GLSL type as written: base name plus array dimensions (None = unsized).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct GlslType {
    pub base: String,
    pub dims: Vec<Option<u32>>,
}

impl GlslType {
    pub fn scalar(base: &str) -> Self {
        GlslType { base: base.to_string(), dims: Vec::new() }
    }
    pub fn is_array(&self) -> bool {
        !self.dims.is_empty()
    }
    pub fn element(&self) -> GlslType {
        GlslType { base: self.base.clone(), dims: self.dims.iter().skip(1).cloned().collect() }
    }
    /// Integer scalar or vector (`int`, `uvec3`, …): never interpolated, so `flat` in effect.
    pub fn is_integer(&self) -> bool {
        matches!(self.base.as_str(), "int" | "uint")
            || ["ivec", "uvec"].iter().any(|p| self.base.strip_prefix(p).is_some_and(|n| matches!(n, "2" | "3" | "4")))
    }
    /// Opaque (sampler) base type.
    pub fn is_sampler(&self) -> bool {
        sampler_parts(&self.base).is_some()
    }
}

impl std::fmt::Display for GlslType {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.base)?;
        for d in &self.dims {
            match d {
                Some(n) => write!(f, "[{n}]")?,
                None => f.write_str("[]")?,
            }
        }
        Ok(())
    }
}

/// `[4][2]` for a type's dimensions.
pub fn dims_text(ty: &GlslType) -> String {
    ty.dims.iter().map(|d| d.map_or("[]".to_string(), |n| format!("[{n}]"))).collect()
}

/// For a combined sampler type, the separate texture type and sampler type naga wants.
pub fn sampler_parts(base: &str) -> Option<(&'static str, &'static str)> {
    Some(match base {
        "sampler1D" => ("texture1D", "sampler"),
        "sampler2D" => ("texture2D", "sampler"),
        "sampler3D" => ("texture3D", "sampler"),
        "samplerCube" => ("textureCube", "sampler"),
        "sampler2DArray" => ("texture2DArray", "sampler"),
        "samplerCubeArray" => ("textureCubeArray", "sampler"),
        "sampler2DMS" => ("texture2DMS", "sampler"),
        "sampler2DShadow" => ("texture2D", "samplerShadow"),
        "samplerCubeShadow" => ("textureCube", "samplerShadow"),
        "sampler2DArrayShadow" => ("texture2DArray", "samplerShadow"),
        "isampler2D" => ("itexture2D", "sampler"),
        "isampler3D" => ("itexture3D", "sampler"),
        "isamplerCube" => ("itextureCube", "sampler"),
        "isampler2DArray" => ("itexture2DArray", "sampler"),
        "usampler2D" => ("utexture2D", "sampler"),
        "usampler3D" => ("utexture3D", "sampler"),
        "usamplerCube" => ("utextureCube", "sampler"),
        "usampler2DArray" => ("utexture2DArray", "sampler"),
        "sampler2DRect" => ("texture2D", "sampler"),
        "samplerBuffer" => ("textureBuffer", "sampler"),
        _ => return None,
    })
}

/// A member of a struct or interface block.
#[derive(Debug, Clone)]
pub struct Member {
    pub name: String,
    pub ty: GlslType,
    pub span: Range<usize>,
    /// Span of the whole field declaration (`sampler2D diffuse;`), shared by siblings
    /// declared together.
    pub field_span: Range<usize>,
    pub interp: Option<Interp>,
    pub centroid: bool,
    /// Declared together with other names (`float a, b;`).
    pub shares_field: bool,
    /// Span of the member's qualifiers (`flat`, `layout(location = 3)`, `layout(row_major)`).
    pub qualifier_span: Option<Range<usize>>,
    pub layout: Vec<(String, Option<i64>)>,
}

/// A struct definition.
#[derive(Debug, Clone)]
pub struct StructDef {
    pub name: String,
    pub name_span: Range<usize>,
    /// The whole definition, `struct S { … };`.
    pub span: Range<usize>,
    pub members: Vec<Member>,
}

/// An interface or uniform block's own facts.
#[derive(Debug, Clone)]
pub struct BlockInfo {
    pub block_name: String,
    pub block_name_span: Range<usize>,
    pub instance: Option<String>,
    pub instance_span: Option<Range<usize>>,
    pub instance_dims: Vec<Option<u32>>,
    pub members: Vec<Member>,
}

/// One global declaration (one declared name; `uniform float a, b;` gives two).
#[derive(Debug, Clone)]
pub struct Global {
    pub storage: Storage,
    /// Variable name, or the block name for blocks.
    pub name: String,
    pub name_span: Range<usize>,
    pub ty: GlslType,
    /// The whole external declaration including `;`.
    pub decl_span: Range<usize>,
    /// Span of the storage keyword (`in`, `varying`, …).
    pub storage_span: Option<Range<usize>>,
    /// Span of an existing `layout(...)` qualifier.
    pub layout_span: Option<Range<usize>>,
    pub layout: Vec<(String, Option<i64>)>,
    pub location: Option<u32>,
    pub interp: Option<Interp>,
    pub centroid: bool,
    pub block: Option<BlockInfo>,
    /// Other names share this declaration.
    pub shares_decl: bool,
    pub initializer: Option<Range<usize>>,
    /// Each item of the layout qualifier (`std140`, `binding = 2`) with its span.
    pub layout_items: Vec<(String, Range<usize>)>,
}

impl Global {
    pub fn is_block(&self) -> bool {
        self.block.is_some()
    }
}

/// A user function (definition or prototype).
#[derive(Debug, Clone)]
pub struct Function {
    pub name: String,
    pub span: Range<usize>,
    pub is_definition: bool,
    pub params: Vec<Param>,
}

#[derive(Debug, Clone)]
pub struct Param {
    pub name: Option<String>,
    pub ty: GlslType,
    /// Span of the whole parameter declaration (`sampler2D s`).
    pub span: Range<usize>,
}

/// What an identifier use refers to.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Target {
    /// Index into [`StageSyntax::globals`].
    Global(usize),
    /// An opaque (sampler) parameter: function index, parameter index.
    Param(usize, usize),
    /// A name declared nowhere in this stage (built-in or an error).
    Unresolved,
}

/// Context around an identifier use.
#[derive(Debug, Clone)]
pub struct Use {
    pub name: String,
    pub target: Target,
    pub span: Range<usize>,
    /// `name[index]`: span of the whole bracket expression, of the index, and its value
    /// when it is an integer literal.
    pub index: Option<(Range<usize>, Range<usize>, Option<i64>)>,
    /// `name.field` / `name[i].field`: field name and the span of the whole dot expression.
    pub field: Option<(String, Range<usize>)>,
    /// Passed directly as an argument to a user-defined function.
    pub user_call_arg: bool,
    /// Function the use occurs in.
    pub in_function: Option<String>,
}

/// `expr.xyz`-shaped field access: if naga finds `expr` is a scalar (GLSL 4.20's scalar
/// swizzle), it is rewritten as a constructor.
#[derive(Debug, Clone)]
pub struct Swizzle {
    pub base: Range<usize>,
    /// The whole `base.field` expression.
    pub whole: Range<usize>,
    /// Number of components selected.
    pub width: usize,
}

/// A function call site.
#[derive(Debug, Clone)]
pub struct Call {
    pub name: String,
    pub name_span: Range<usize>,
    pub span: Range<usize>,
    pub in_function: Option<String>,
    /// Spans of the arguments.
    pub args: Vec<Range<usize>>,
    /// The first argument when it is a bare identifier (a sampler, for texture calls).
    pub first_arg_name: Option<String>,
    /// The call is written in a `#define` body (`name_span` is there; no arguments known).
    pub from_macro: bool,
}

/// Everything the checker and the rewrite need to know about one stage's source.
#[derive(Debug, Clone)]
pub struct StageSyntax {
    pub file: FileId,
    pub stage: StageKind,
    pub version: Version,
    /// A legal construct naga has no form of, found while masking the text for glsl-lang
    /// (what, where): the stage is checked for syntax and interface only.
    pub unsupported: Option<(String, Range<usize>)>,
    /// Swizzle-shaped field accesses (`x.rrr`), in source order.
    pub swizzles: Vec<Swizzle>,
    /// Offsets of `pervertexEXT` qualifiers: the inputs they qualify are arrays with one
    /// element per vertex, like a geometry stage's.
    pub per_vertex: Vec<usize>,
    pub renames: Renames,
    /// Source after same-length keyword renames (offsets equal the original's).
    pub text: String,
    pub globals: Vec<Global>,
    pub structs: Vec<StructDef>,
    pub functions: Vec<Function>,
    pub uses: Vec<Use>,
    pub calls: Vec<Call>,
    /// Spans of global `precision` statements.
    pub precision_statements: Vec<Range<usize>>,
    /// Start of the first function definition or prototype.
    pub first_function: Option<usize>,
    /// Names of integer constants (`const int N = 4;`) with their values.
    pub int_consts: HashMap<String, i64>,
    pub has_main: bool,
    /// Span of `main`'s body `{ … }`.
    pub main_body: Option<Range<usize>>,
    /// `return` statements inside `main`.
    pub main_returns: Vec<Range<usize>>,
    /// Default-qualifier declarations (`layout(std140, row_major) uniform;`, `layout(triangles) in;`).
    pub defaults: Vec<DefaultDecl>,
    /// Unsized array dimensions (`[]`) whose size the initializer gives: span and size.
    pub unsized_sizes: Vec<(Range<usize>, u32)>,
    /// Array sizes and case labels written with local constants (`[TAPS + 1]`, `case TAPS:`):
    /// the expression and its value, which the rewrite writes for naga.
    pub constant_sizes: Vec<(Range<usize>, u32)>,
    /// Written in Vulkan GLSL (descriptor sets, push constants, specialization constants,
    /// `gl_VertexIndex`, separate textures and samplers): interfaces match by location only.
    pub vulkan: bool,
}

/// A declaration made of qualifiers only: it sets defaults for later declarations.
#[derive(Debug, Clone)]
pub struct DefaultDecl {
    pub span: Range<usize>,
    pub storage: Option<Storage>,
    pub layout: Vec<(String, Option<i64>)>,
}

impl StageSyntax {
    pub fn global(&self, name: &str) -> Option<&Global> {
        self.globals.iter().find(|g| g.name == name)
    }
    pub fn struct_def(&self, name: &str) -> Option<&StructDef> {
        self.structs.iter().find(|s| s.name == name)
    }
    /// The user's spelling of a (possibly renamed) identifier.
    pub fn original_name<'a>(&'a self, name: &'a str) -> &'a str {
        self.renames.original(name)
    }
}

fn span_of<T: NodeContent>(node: &ast::Node<T>) -> Range<usize> {
    node.span.map(|s| usize::from(s.range().start())..usize::from(s.range().end())).unwrap_or(0..0)
}

/// Parses one stage. Errors are syntax diagnostics at the user's spans.
pub fn analyse(file: FileId, original: &str, stage: StageKind) -> Result<StageSyntax, Vec<Diagnostic>> {
    let version = match version::parse_version(original) {
        Ok(v) => v,
        Err((msg, span)) => {
            return Err(vec![Diagnostic::error("E0101", msg)
                .at(file, span, "in this `#version` directive")
                .with_note("effectc accepts GLSL 1.10–4.60 (core or compatibility) and ES 1.00/3.00")])
        }
    };
    let unextended = version::blank_extensions(original);
    let resolved = crate::front::conditionals::resolve(&unextended, &version::blank_comments(&unextended), &version);
    if let Some(span) = compiled_include(&resolved) {
        return Err(vec![Diagnostic::error(
            crate::front::conditionals::E_INCLUDE,
            format!("cannot read included file `{}`", &original[span.clone()]),
        )
        .at(file, span, "not found relative to the including file")
        .with_note("`#include` names a file relative to the file that includes it")]);
    }
    let (text, mut renames) = version::rename_new_keywords(&resolved, &version, original);
    let masked = crate::front::lexical::mask(&text, &version::blank_comments(&text));
    let mut text = masked.for_parser;
    let opts = glsl_lang::parse::ParseOptions {
        default_version: 110,
        // Vulkan GLSL's types (`texture2D`, `sampler`, `subpassInput`) are keywords there only.
        target_vulkan: vulkan_source(original),
        ..Default::default()
    };
    if opts.target_vulkan && version.number >= 400 && !version.is_es() {
        // glsl-lang enables Vulkan's types from `#version 460` only; Vulkan GLSL has them
        // from 4.50 on. Same-length digits keep every offset.
        if let Some(span) = version.number_span.clone() {
            text.replace_range(span, "460");
        }
    }
    let parse = |text: &str| {
        std::panic::catch_unwind(|| {
            ast::TranslationUnit::parse_with_options(text, &opts).map(|(tu, _, _)| tu).map_err(|e| {
                let pos = e.pos();
                let start = usize::from(pos.start());
                let end = usize::from(pos.end());
                (trim_expected(&e.inner().to_string()), start..end)
            })
        })
    };
    let mut parsed = parse(text.as_str());
    // glsl-lang's lexer takes a struct's name for a type everywhere, but GLSL lets a local
    // variable hide it (`float Attenuation = …;` beside `struct Attenuation`). Rename the
    // local, from its declaration to the end of its block, and parse again.
    for _ in 0..16 {
        let Ok(Err((msg, span))) = &parsed else { break };
        let Some(hidden) = rename_struct_hiding_local(&text, msg, span.start, &mut renames) else { break };
        text = hidden;
        parsed = parse(text.as_str());
    }
    let tu = match parsed {
        Ok(Ok(tu)) => tu,
        Ok(Err((msg, span))) => {
            let span = clamp(span, original);
            return Err(vec![Diagnostic::error("E0102", format!("syntax error: {msg}")).at(file, span, "the GLSL parser stopped here")]);
        }
        Err(_) => return Err(vec![Diagnostic::error("E0102", "syntax error: the GLSL parser failed on this file").in_file(file)]),
    };
    let mut syntax = StageSyntax {
        file,
        stage,
        version,
        renames,
        text: crate::front::lexical::restored(&text, &masked.restore),
        unsupported: masked.unsupported,
        per_vertex: masked.per_vertex,
        swizzles: Vec::new(),
        globals: Vec::new(),
        structs: Vec::new(),
        functions: Vec::new(),
        uses: Vec::new(),
        calls: Vec::new(),
        precision_statements: Vec::new(),
        first_function: None,
        int_consts: HashMap::new(),
        has_main: false,
        main_body: None,
        main_returns: Vec::new(),
        defaults: Vec::new(),
        unsized_sizes: Vec::new(),
        constant_sizes: Vec::new(),
        vulkan: false,
    };
    Collector::run(&mut syntax, &tu);
    syntax.vulkan = looks_like_vulkan(&syntax, original);
    Ok(syntax)
}

/// For a parse error on a struct's name used as a variable at `at`, the text with that
/// name renamed (same length) from `at` to the end of the enclosing `{ … }` block.
fn rename_struct_hiding_local(text: &str, msg: &str, at: usize, renames: &mut Renames) -> Option<String> {
    let name = msg.strip_prefix("unexpected type name `")?.split('`').next()?;
    if !text.get(at..)?.starts_with(name) || name.len() < 2 {
        return None;
    }
    let is_ident = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
    let declared_struct = text
        .match_indices("struct")
        .any(|(i, _)| text[i + 6..].trim_start().strip_prefix(name).is_some_and(|r| !r.bytes().next().is_some_and(is_ident)));
    if !declared_struct {
        return None;
    }
    // The local's scope: to the brace that closes the block it is declared in.
    let bytes = text.as_bytes();
    let mut depth = 0i32;
    let mut end = text.len();
    for (i, &b) in bytes.iter().enumerate().skip(at) {
        match b {
            b'{' => depth += 1,
            b'}' => {
                depth -= 1;
                if depth < 0 {
                    end = i;
                    break;
                }
            }
            _ => {}
        }
    }
    let new = (0..100)
        .map(|k| format!("{}{}", &name[..name.len() - 1], (b'a' + (k % 26) as u8) as char))
        .find(|c| c != name && !text.contains(c.as_str()))?;
    let mut out = text.as_bytes().to_vec();
    let mut i = at;
    while let Some(off) = text[i..end].find(name) {
        let s = i + off;
        let e = s + name.len();
        let before_ok = s == 0 || !is_ident(bytes[s - 1]);
        let after_ok = e >= bytes.len() || !is_ident(bytes[e]);
        if before_ok && after_ok {
            out[s..e].copy_from_slice(new.as_bytes());
        }
        i = e;
    }
    renames.to_original.insert(new, name.to_string());
    String::from_utf8(out).ok()
}

/// glsl-lang lists every token it would accept; keep the message readable.
fn trim_expected(msg: &str) -> String {
    let Some(at) = msg.find(", expected ") else { return msg.to_string() };
    let (head, list) = msg.split_at(at);
    let items: Vec<&str> = list[", expected ".len()..].split(", ").collect();
    if items.len() <= 6 {
        return msg.to_string();
    }
    let mut short: Vec<&str> =
        items.iter().copied().filter(|i| !i.contains("texture") && !i.contains("subpass") && !i.contains("sampler")).take(6).collect();
    if short.is_empty() {
        short = items[..6].to_vec();
    }
    format!("{head}, expected {} …", short.join(", "))
}

fn clamp(span: Range<usize>, text: &str) -> Range<usize> {
    let start = span.start.min(text.len());
    let end = span.end.clamp(start, text.len());
    if start == end && start < text.len() {
        // Point at the offending character rather than nothing.
        let next = text[start..].chars().next().map_or(1, char::len_utf8);
        start..start + next
    } else {
        start..end
    }
}

struct Collector<'a> {
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
}

impl<'a> Collector<'a> {
    fn run(s: &'a mut StageSyntax, tu: &ast::TranslationUnit) {
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
        let mut c = Collector {
            s,
            scopes: Vec::new(),
            current_function: None,
            user_functions,
            arg_context: false,
            macro_uses: HashSet::new(),
            local_consts: HashMap::new(),
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

    fn type_name(&self, t: &ast::TypeSpecifierNonArray) -> String {
        if let ast::TypeSpecifierNonArrayData::Struct(st) = &t.content {
            return st.name.as_ref().map(|n| n.0.to_string()).unwrap_or_else(|| "<anonymous struct>".into());
        }
        let mut out = String::new();
        let _ = show_type_specifier_non_array(&mut out, t, &mut FormattingState::default());
        out
    }

    fn type_of(&mut self, t: &ast::TypeSpecifier) -> GlslType {
        if let ast::TypeSpecifierNonArrayData::Struct(st) = &t.ty.content {
            self.struct_def(st, span_of(st));
        }
        let mut ty = GlslType { base: self.type_name(&t.ty), dims: Vec::new() };
        if let Some(a) = &t.array_specifier {
            ty.dims = self.dims(a);
        }
        ty
    }

    fn dims(&self, a: &ast::ArraySpecifier) -> Vec<Option<u32>> {
        a.dimensions
            .iter()
            .map(|d| match &d.content {
                ast::ArraySpecifierDimensionData::Unsized => None,
                ast::ArraySpecifierDimensionData::ExplicitlySized(e) => self.const_int(e).and_then(|v| u32::try_from(v).ok()),
            })
            .collect()
    }

    /// Evaluates an integer constant expression made of literals, `const int`s and + - * /.
    fn const_int(&self, e: &ast::Expr) -> Option<i64> {
        match &e.content {
            ast::ExprData::IntConst(v) => Some(*v as i64),
            ast::ExprData::UIntConst(v) => Some(*v as i64),
            ast::ExprData::Variable(id) => self.local_consts.get(id.0.as_str()).or_else(|| self.s.int_consts.get(id.0.as_str())).copied(),
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
            _ => None,
        }
    }

    fn struct_def(&mut self, st: &ast::StructSpecifier, span: Range<usize>) {
        let Some(name) = &st.name else { return };
        if self.s.structs.iter().any(|s| s.name == name.0.as_str()) {
            return;
        }
        let members = self.members(&st.fields);
        self.s.structs.push(StructDef { name: name.0.to_string(), name_span: span_of(name), span, members });
    }

    fn members(&mut self, fields: &[ast::StructFieldSpecifier]) -> Vec<Member> {
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

    fn qualifiers(&self, q: Option<&ast::TypeQualifier>) -> Quals {
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
                _ => {}
            }
        }
        out
    }

    fn global_declaration(&mut self, d: &ast::Declaration, span: Range<usize>) {
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
                let Quals { interp, centroid, storage, layout_span, layout, .. } = q;
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
                let Quals { interp, centroid, storage, layout_span, layout, .. } = q;
                if let (Some(a), Some(init)) = (&head.array_specifier, &head.initializer) {
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
    fn unsized_from_initializer(&mut self, a: &ast::ArraySpecifier, init: &ast::Initializer) {
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

    fn initializer(&mut self, i: &ast::Initializer) {
        match &i.content {
            ast::InitializerData::Simple(e) => self.expr(e),
            ast::InitializerData::List(list) => list.iter().for_each(|i| self.initializer(i)),
        }
    }

    fn compound(&mut self, c: &ast::CompoundStatement) {
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

    fn array_exprs(&mut self, a: &ast::ArraySpecifier) {
        for d in &a.dimensions {
            if let ast::ArraySpecifierDimensionData::ExplicitlySized(e) = &d.content {
                self.expr(e);
            }
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

    fn condition(&mut self, c: &ast::Condition) {
        match &c.content {
            ast::ConditionData::Expr(e) => self.expr(e),
            ast::ConditionData::Assignment(_, name, init) => {
                self.initializer(init);
                self.declare_local(name.0.as_str());
            }
        }
    }

    fn resolve(&self, name: &str) -> Target {
        for scope in self.scopes.iter().rev() {
            if scope.contains_key(name) {
                // Locals and parameters: only opaque parameters matter to the rewrite.
                if let Some((_, f)) = &self.current_function {
                    let func = &self.s.functions[*f];
                    if let Some(pi) = func.params.iter().position(|p| p.name.as_deref() == Some(name)) {
                        // A parameter is only visible from the function's outermost scope;
                        // an inner local of the same name shadows it.
                        if std::ptr::eq(scope, &self.scopes[0]) && func.params[pi].ty.is_sampler() {
                            return Target::Param(*f, pi);
                        }
                    }
                }
                return Target::Unresolved;
            }
        }
        // Globals: the last declaration of that name (redeclaration is an error naga reports).
        if let Some(i) = self.s.globals.iter().rposition(|g| g.name == name && g.block.is_none()) {
            return Target::Global(i);
        }
        // Members of anonymous blocks are globals too.
        if let Some(i) = self
            .s
            .globals
            .iter()
            .rposition(|g| g.block.as_ref().is_some_and(|b| b.instance.is_none() && b.members.iter().any(|m| m.name == name)))
        {
            return Target::Global(i);
        }
        // Instance names of blocks.
        if let Some(i) = self.s.globals.iter().rposition(|g| g.block.as_ref().is_some_and(|b| b.instance.as_deref() == Some(name))) {
            return Target::Global(i);
        }
        Target::Unresolved
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
        if is_local && !matches!(target, Target::Param(..)) {
            return;
        }
        let span = span_of(id);
        if self.s.text.get(span.clone()) != Some(name.as_str()) {
            // Expanded from a macro: glsl-lang gives the invocation's span. The name is
            // written in `#define` bodies; record it there (once), so rewrites edit the body.
            for at in macro_body_occurrences(&self.s.text, &name) {
                if self.macro_uses.insert((name.clone(), at.start)) {
                    self.s.uses.push(Use {
                        name: name.clone(),
                        target: target.clone(),
                        span: at,
                        index: None,
                        field: None,
                        user_call_arg,
                        in_function: in_function.clone(),
                    });
                }
            }
            return;
        }
        self.s.uses.push(Use { name, target, span, index, field, user_call_arg, in_function });
    }

    fn expr(&mut self, e: &ast::Expr) {
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
                    let in_function = self.current_function.as_ref().map(|(n, _)| n.clone());
                    let first_arg_name = args.first().and_then(|a| match &a.content {
                        ast::ExprData::Variable(id) => Some(id.0.to_string()),
                        _ => None,
                    });
                    if self.s.text.get(sp.clone()) != Some(n.as_str()) {
                        // Expanded from a macro: the name is written in `#define` bodies.
                        for at in macro_body_occurrences(&self.s.text, &n) {
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
                for a in args {
                    self.arg_context = is_user;
                    self.expr(a);
                }
            }
            ast::ExprData::Unary(_, a) | ast::ExprData::PostInc(a) | ast::ExprData::PostDec(a) => self.expr(a),
            ast::ExprData::Binary(_, a, b) | ast::ExprData::Assignment(a, _, b) | ast::ExprData::Comma(a, b) => {
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

/// The file name of an `#include` left in the compiled text (one `includes` could not read).
fn compiled_include(text: &str) -> Option<Range<usize>> {
    crate::front::conditionals::include_directives(text).into_iter().next().map(|(_, _, name)| name)
}

/// Whole-word occurrences of `name` in the bodies of `#define` lines (after the macro's name).
fn macro_body_occurrences(text: &str, name: &str) -> Vec<Range<usize>> {
    let is_ident = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
    let bytes = text.as_bytes();
    let mut out = Vec::new();
    for (_, body) in crate::front::conditionals::define_lines(text) {
        for (i, _) in text[body.clone()].match_indices(name) {
            let (s, e) = (body.start + i, body.start + i + name.len());
            if (s == 0 || !is_ident(bytes[s - 1])) && (e >= bytes.len() || !is_ident(bytes[e])) {
                out.push(s..e);
            }
        }
    }
    out
}

/// Before parsing: does the text use what only Vulkan GLSL has (descriptor sets, push
/// constants, subpass inputs, separate texture and sampler uniforms)?
fn vulkan_source(text: &str) -> bool {
    let squeezed: String = text.split_whitespace().collect::<Vec<_>>().join(" ");
    squeezed.contains("push_constant")
        || squeezed.contains("subpassInput")
        || squeezed.contains("input_attachment_index")
        || squeezed.contains("GL_KHR_vulkan_glsl")
        || squeezed.contains("uniform sampler ")
        || squeezed.contains("uniform samplerShadow ")
        || ["texture2D", "texture3D", "textureCube", "texture2DArray"].iter().any(|t| squeezed.contains(&format!("uniform {t} ")))
        || squeezed.split("layout").skip(1).any(|l| {
            let inside = l.trim_start().strip_prefix('(').and_then(|r| r.split(')').next()).unwrap_or("");
            inside.split(',').any(|item| item.trim().starts_with("set"))
        })
}

/// Vulkan GLSL shows itself by what only Vulkan has.
fn looks_like_vulkan(s: &StageSyntax, original: &str) -> bool {
    let layout_vulkan = s
        .globals
        .iter()
        .any(|g| g.layout.iter().any(|(k, _)| matches!(k.as_str(), "set" | "push_constant" | "constant_id" | "input_attachment_index")));
    let separate = s.globals.iter().any(|g| {
        g.storage == Storage::Uniform
            && matches!(g.ty.base.as_str(), "sampler" | "samplerShadow" | "texture2D" | "textureCube" | "texture2DArray" | "texture3D")
    });
    layout_vulkan
        || separate
        || s.uses.iter().any(|u| matches!(u.name.as_str(), "gl_VertexIndex" | "gl_InstanceIndex") && u.target == Target::Unresolved)
        || original.contains("GL_KHR_vulkan_glsl")
}

/// The qualifiers of one declaration, as written.
#[derive(Debug, Default)]
struct Quals {
    interp: Option<Interp>,
    centroid: bool,
    storage: Option<(Storage, Range<usize>)>,
    layout_span: Option<Range<usize>>,
    layout: Vec<(String, Option<i64>)>,
    layout_items: Vec<(String, Range<usize>)>,
}

fn location_of(layout: &[(String, Option<i64>)]) -> Option<u32> {
    layout.iter().find(|(k, _)| k == "location").and_then(|(_, v)| v.and_then(|v| u32::try_from(v).ok()))
}

/// Render an expression (used for messages only).
pub fn expr_text(e: &ast::Expr) -> String {
    let mut out = String::new();
    let _ = show_expr(&mut out, e, &mut FormattingState::default());
    out
}
