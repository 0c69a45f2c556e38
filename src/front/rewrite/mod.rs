//! Rewrites one stage's desktop GLSL into GLSL 4.50 that naga accepts.
//!
//! Every change is a text edit on the user's file (see [`edits`](super::edits)), so naga's
//! errors map back to the user's line and column. What changes:
//! `#version` → 450; loose uniforms → members of the shared `EffectcUniforms` block;
//! combined samplers → texture + sampler pairs (declarations, uses, function parameters and
//! call arguments); locations on every varying, vertex input and fragment output;
//! 1xx `attribute`/`varying`; legacy built-ins (`texture2D`, `gl_FragColor`, …).
//!
//! The edits are made by concern: `declarations` (uniforms and blocks: bindings, the shared
//! block), `varyings` (locations, 1xx storage, matrix varyings), `uses` (identifier uses:
//! block members, sampler splits, legacy built-ins), `calls` (sampler parameters, legacy and
//! texture calls), `blocks` (struct and block definitions, layout qualifiers, row-major
//! matrices), `expressions` (array sizes, scalar swizzles), `header` (what goes before the
//! first function: the shared block, split textures, built-in replacements),
//! `initializers` (globals initialised from uniforms or inputs, assigned first in `main`),
//! `file_scope` (a `;` after a function body), `dynamic_samplers` (a sampler array element
//! chosen at run time), `evaluation` (short-circuit operators with
//! side effects, `continue` in `do … while`), `polyfills` (built-ins naga cannot write),
//! `fixed_function` (the compatibility profile's built-ins), `builtin_macros` (macros that
//! rename a built-in type or function).

mod block_members;
mod blocks;
mod builtin_macros;
mod calls;
mod declarations;
mod dynamic_samplers;
mod evaluation;
mod expressions;
mod file_scope;
mod fixed_function;
mod header;
mod initializers;
mod integer_lookups;
mod interpolation;
mod io_blocks;
mod polyfills;
mod query_lod;
mod sampler_array_params;
mod std140_structs;
mod subpass;
mod uniform_struct_arrays;
mod uses;
mod varyings;
mod workgroup_size;

use std::ops::Range;

use crate::diag::{Code, Diagnostic};
use crate::front::edits::{Edits, OffsetMap};
use crate::front::limitation::Limitation;
pub use crate::front::plan::is_unblocked_opaque;
use crate::front::plan::Plan;
pub use crate::front::syntax::dims_text;
use crate::front::syntax::StageSyntax;
pub use blocks::row_major_members;
pub use uses::names_builtin;

/// A stage rewritten to 4.50, with the map back to the user's file.
#[derive(Debug, Clone)]
pub struct Rewritten {
    pub text: String,
    pub map: OffsetMap,
    /// A legal construct the rewrite cannot express for naga (the stage is then checked for
    /// syntax and interface only).
    pub limitation: Option<Limitation>,
}

/// Sets that user-numbered bindings (`layout(binding = N)` without a set) move to. GL
/// numbers uniform blocks, storage blocks, images and atomic counters in separate
/// namespaces (binding 0 of each can coexist), so each kind gets a set of its own.
pub const USER_UNIFORM_SET: u32 = 1;
pub const USER_BUFFER_SET: u32 = 2;
pub const USER_IMAGE_SET: u32 = 3;
pub const USER_COUNTER_SET: u32 = 4;

/// Prefix of the constant holding a uniform's GLSL initializer (`uniform float k = 0.5;`
/// → `const float effectc_initial_k = 0.5;`): the renderer starts the uniform there.
pub const INITIAL_PREFIX: &str = "effectc_initial_";

/// Prefix of a uniform block member another stage declares and this stage shadows.
pub const OTHER_STAGE_PREFIX: &str = "effectc_other_";

/// One stage's rewrite in progress: the edits so far, and what `main` and the header
/// still need.
struct Ctx<'a> {
    s: &'a StageSyntax,
    plan: &'a Plan,
    strict: bool,
    edits: Edits,
    diags: Vec<Diagnostic>,
    need_mat2_helper: bool,
    /// Statements run first in `main` (matrix inputs assembled from columns).
    prologue: String,
    /// Statements run before `main` returns (matrix outputs split into columns).
    epilogue: String,
    /// The header (shared block, split textures) goes before this offset too: a global
    /// initialised at run time becomes a function there ([`initializers`]).
    header_before: Option<usize>,
    limitation: Option<Limitation>,
    /// Built-ins called under effectc names ([`polyfills`]), defined in the header.
    polyfills: Vec<&'static str>,
    /// Declarations of the compatibility built-ins the stage uses ([`fixed_function`]).
    compat_header: String,
    /// Built-in calls on a sampler array element chosen at run time ([`dynamic_samplers`]).
    dynamic_lookups: Vec<dynamic_samplers::DynamicLookup>,
    /// Sampler-array parameters that stand for a uniform array ([`sampler_array_params`]).
    array_params: Vec<sampler_array_params::ArrayParam>,
}

/// Rewrites `s` under the program plan. Warnings (and, with `strict`, errors) for legacy
/// constructs go to the returned diagnostics.
pub fn rewrite(s: &StageSyntax, plan: &Plan, strict: bool) -> (Rewritten, Vec<Diagnostic>) {
    rewrite_with(s, plan, strict, &[])
}

/// [`rewrite`], with the swizzles (indices into `s.swizzles`) naga found applied to a
/// scalar written as constructors: `x.rrr` → `vec3(x)`, `x.r` → `(x)`.
pub fn rewrite_with(s: &StageSyntax, plan: &Plan, strict: bool, scalar_swizzles: &[usize]) -> (Rewritten, Vec<Diagnostic>) {
    let limitation = s.unsupported.as_ref().map(|(construct, span)| Limitation { construct: construct.clone(), span: Some(span.clone()) });
    let mut c = Ctx {
        s,
        plan,
        strict,
        edits: Edits::new(),
        diags: Vec::new(),
        need_mat2_helper: false,
        prologue: String::new(),
        epilogue: String::new(),
        header_before: None,
        limitation,
        polyfills: Vec::new(),
        compat_header: String::new(),
        dynamic_lookups: Vec::new(),
        array_params: sampler_array_params::array_params(s),
    };
    c.version();
    // First: at the first declaration, the constants go before what the rewrite inserts there.
    c.insert_constants();
    c.declarations();
    c.runtime_initializers();
    c.stray_semicolons();
    c.uses();
    c.shadowed_block_members();
    c.functions();
    c.drop_array_params();
    c.calls();
    c.struct_samplers();
    c.defaults_and_layouts();
    c.spec_constant_workgroup_size();
    c.user_block_member_types();
    c.uniform_struct_arrays();
    c.std140_struct_fillers();
    c.row_major_uses();
    c.unsized_arrays();
    c.constructor_conditions();
    c.scalar_swizzles(scalar_swizzles);
    c.polyfills();
    c.subpass_inputs();
    c.interpolation_calls();
    c.query_lods();
    c.integer_lookups();
    c.dynamic_lookups();
    c.lazy_logic();
    c.do_while_continue();
    // Last: it renames only what no other edit rewrote.
    c.builtin_renaming_macros();
    c.insert_header();
    c.insert_main_hooks();
    let Ctx { edits, mut diags, limitation, .. } = c;
    let (text, map, dropped) = edits.apply(&s.text);
    for e in dropped {
        diags.push(
            Diagnostic::new(Code::RewriteFailed, "effectc could not rewrite this expression for naga")
                .at(s.file, e.range.clone(), "overlapping rewrites here")
                .with_note("this is a limitation of effectc; naga may report an error nearby"),
        );
    }
    (Rewritten { text, map, limitation }, diags)
}

impl Ctx<'_> {
    fn legacy(&mut self, span: Range<usize>, what: &str, replacement: &str) {
        if !self.s.version.forbids_legacy_builtins() {
            return;
        }
        let v = &self.s.version;
        let profile = if v.is_es() { "es".to_string() } else { "core".to_string() };
        let msg = format!("`{what}` is not part of GLSL {} {profile}", v.number);
        let d = if self.strict { Diagnostic::new(Code::RemovedInVersionStrict, msg) } else { Diagnostic::new(Code::RemovedInVersion, msg) };
        self.diags.push(
            d.at(self.s.file, span, format!("removed from the {profile} profile"))
                .with_note("GL drivers and the reference compiler (glslang) reject it in this version")
                .with_help(format!("use `{replacement}` instead")),
        );
    }

    fn version(&mut self) {
        let v = &self.s.version;
        match (&v.number_span, &v.profile_span) {
            (Some(num), profile) => {
                self.edits.replace(num.clone(), "450");
                if let Some(p) = profile {
                    // naga accepts only the core profile word.
                    self.edits.replace(p.clone(), "core");
                }
            }
            (None, _) => self.edits.insert(0, "#version 450 core\n"),
        }
    }
}
