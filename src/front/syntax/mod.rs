//! Syntax analysis of one GLSL stage with glsl-lang: declarations and resolved use sites.
//!
//! The result, [`StageSyntax`], is what both the GL link checks and the rewrite to 4.50 work
//! from: every global declaration with its qualifiers and spans, every function with its
//! parameters, and every place an identifier refers to a global (or to an opaque function
//! parameter), with the surrounding index / field / call-argument context. Scopes are
//! tracked, so a local that shadows a uniform is never rewritten.
//!
//! - `types`: storage, interpolation and types as written; `model`: what is recorded.
//! - `parse`: the text prepared for glsl-lang, its errors, Vulkan GLSL told apart.
//! - `collect`: the walk over the AST (declarations, statements, expressions).
//! - `nodes`: spans and text of AST nodes.

mod collect;
mod model;
mod nodes;
mod parse;
mod types;

pub use model::{
    layout_number, BlockInfo, Call, DefaultDecl, DoWhileContinue, Function, Global, LazyLogic, Member, Param, Referent, StageSyntax,
    StructDef, Swizzle, Use,
};
pub use nodes::{bracket_after, expr_text, word_occurrences};
pub use parse::analyse;
pub(crate) use parse::vulkan_source;
pub use types::{
    chosen_image_format, dims_text, is_rect_sampler, matrix_shape, sampler_parts, texel_buffer_element, GlslType, Interp, Storage,
};
