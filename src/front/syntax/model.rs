//! What the analysis records for one stage, [`StageSyntax`]: global declarations and
//! blocks, structs, functions, identifier uses with their context, and calls.

use std::collections::HashMap;
use std::ops::Range;

use crate::diag::FileId;
use crate::front::syntax::types::{GlslType, Interp, Storage};
use crate::front::version::{Renames, Version};
use crate::stage::StageKind;

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
    /// The `invariant` qualifier's span, when written on the declaration.
    pub invariant: Option<Range<usize>>,
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

/// The non-negative integer a layout qualifier gives `key` (`location = 2`, `component = 3`).
pub fn layout_number(layout: &[(String, Option<i64>)], key: &str) -> Option<u32> {
    layout.iter().find(|(k, _)| k == key).and_then(|(_, v)| v.and_then(|v| u32::try_from(v).ok()))
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
pub enum Referent {
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
    pub target: Referent,
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
    /// A `gpu_shader5` extension is enabled (`#extension GL_ARB_gpu_shader5 : require`): what
    /// GLSL 4.00 allows below it (sampler arrays indexed at run time). `text` has no
    /// `#extension` lines.
    pub gpu_shader5: bool,
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
    /// `for` conditions that start with a constructor (`float(i) < n`), which naga's parser
    /// takes for a declaration.
    pub constructor_conditions: Vec<Range<usize>>,
    /// Written in Vulkan GLSL (descriptor sets, push constants, specialization constants,
    /// `gl_VertexIndex`, separate textures and samplers): interfaces match by location only.
    pub vulkan: bool,
    /// `a && f()` / `a || f()` whose right operand has side effects: naga's GLSL front
    /// evaluates it even when `a` decides the result, so the rewrite writes `?:`.
    pub lazy_logic: Vec<LazyLogic>,
    /// `do { … continue; … } while (c);`: naga's `continue` there skips `c`, so the rewrite
    /// writes a `for` loop that tests `c` after every iteration but the first.
    pub do_while_continue: Vec<DoWhileContinue>,
    /// The first global of each name (index into `globals`), made once the stage is read
    /// ([`StageSyntax::index_globals`]): a stage of thousands of uniforms is looked up by
    /// name at every use.
    pub global_index: HashMap<String, usize>,
    /// `#pragma parameter` declarations: uniforms a host sets, with their ranges.
    pub parameters: Vec<crate::front::parameters::Parameter>,
}

/// A short-circuit operator whose right operand must not run when the left decides.
#[derive(Debug, Clone, PartialEq)]
pub struct LazyLogic {
    /// The left operand as written (with its parentheses).
    pub left: Range<usize>,
    /// The `&&` or `||` token.
    pub op: Range<usize>,
    /// The right operand as written (with its parentheses).
    pub right: Range<usize>,
    /// `&&` (else `||`).
    pub and: bool,
}

/// A `do … while` loop whose body has a `continue` of its own.
#[derive(Debug, Clone, PartialEq)]
pub struct DoWhileContinue {
    /// `do` up to the body.
    pub keyword: Range<usize>,
    /// The condition expression.
    pub cond: Range<usize>,
    /// From the end of the body through the `;` after `while (c)`.
    pub tail: Range<usize>,
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
        if !self.global_index.is_empty() {
            return self.global_index.get(name).map(|&i| &self.globals[i]);
        }
        self.globals.iter().find(|g| g.name == name)
    }
    /// Indexes the globals by name (the first of each name), once they are all collected.
    pub fn index_globals(&mut self) {
        self.global_index.clear();
        for (i, g) in self.globals.iter().enumerate() {
            self.global_index.entry(g.name.clone()).or_insert(i);
        }
    }
    pub fn struct_def(&self, name: &str) -> Option<&StructDef> {
        self.structs.iter().find(|s| s.name == name)
    }
    /// The user's spelling of a (possibly renamed) identifier.
    pub fn original_name<'a>(&'a self, name: &'a str) -> &'a str {
        self.renames.original(name)
    }
}
