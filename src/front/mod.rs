//! The GLSL front: syntax analysis of desktop GLSL, rewrite to GLSL 4.50, naga parse.
//!
//! - [`version`]: the `#version` line and identifiers that are keywords in 4.50 only.
//! - [`conditionals`]: `#if`/`#ifdef` resolved for the user's `#version`, with GL's predefined
//!   macros (inactive groups blanked).
//! - [`includes`]: `#include`d files inlined into a stage, with the map back to each file.
//! - [`defines`]: macros defined from outside a stage (`--define`, a manifest's `define`,
//!   the single-file two-stage format) written after its `#version` line.
//! - [`lexical`]: same-length masks for legal GLSL glsl-lang cannot lex (wide hex literals,
//!   `debugPrintfEXT`, explicit arithmetic types, buffer references).
//! - [`syntax`]: glsl-lang parse into declarations and scope-resolved use sites.
//! - [`edits`]: text edits with an offset map back to the user's file.
//! - [`geometry_layout`]: a geometry stage's primitives, `max_vertices` and invocations.
//! - [`plan`]: bindings and locations shared by all stages ([`varying_locations`] for the
//!   varyings); [`rewrite`]: one stage to 4.50.
//! - [`limitation`]: a legal construct naga cannot take (the stage is checked, not translated).
//! - [`limits`]: what a stage must keep before any compiler reads it (statement length, macro
//!   expansion): the stack and memory stay bounded.
//! - [`macro_spans`]: a span from a `#define` down to the macro's use narrowed to the use.
//! - [`reference`]: glslang, the Khronos reference compiler, in process: what is legal,
//!   with its errors at the user's lines.
//! - [`parameters`]: `#pragma parameter` declarations (a host-set uniform and its range).
//! - [`naga_run`]: naga parse + validate, panics contained, naga's limitations told from
//!   errors with [`builtins`]; [`aggregate_varyings`]: the interpolation qualifiers naga's
//!   GLSL front drops from struct and array varyings; [`through_spirv`]: glslang → SPIR-V →
//!   naga, where naga's GLSL front cannot take a stage glslang accepts (as written, or from
//!   the rewrite), on the SPIR-V words as [`spirv_binary`] reads and edits them
//!   ([`spirv_interface_blocks`]: blocks between stages as one variable per member;
//!   [`spirv_signedness`]: integer signedness as naga reads it; [`spirv_array_sizes`]: the
//!   layer count of an arrayed image's size, which naga's SPIR-V front leaves out);
//!   [`program`]: all of it per program.

pub mod aggregate_varyings;
pub mod builtins;
pub mod compat;
pub mod conditionals;
pub mod defines;
pub mod doubles;
pub mod edits;
pub mod fold_parts;
pub mod folds;
pub mod function_order;
pub mod geometry_fold;
pub mod geometry_layout;
pub mod includes;
pub mod initial_values;
pub mod lexical;
pub mod limitation;
pub mod limits;
pub mod macro_spans;
pub mod naga_run;
pub mod parameters;
pub mod plan;
pub mod program;
pub mod reference;
pub mod rewrite;
pub mod source_text;
pub mod spirv_absent_builtins;
pub mod spirv_aggregate_varyings;
pub mod spirv_array_sizes;
pub mod spirv_binary;
pub mod spirv_binding_arrays;
pub mod spirv_float_tests;
pub mod spirv_interface_blocks;
pub mod spirv_non_finite_constants;
pub mod spirv_outer_products;
pub mod spirv_refusals;
pub mod spirv_signedness;
pub mod spirv_spec_constants;
pub mod spirv_subgroups;
pub mod spirv_subpass_inputs;
pub mod spirv_texel_buffers;
pub mod spirv_two_row_matrices;
pub mod spirv_wide_integers;
pub mod statements;
pub mod syntax;
pub mod tessellation_fold;
pub mod tessellator;
pub mod through_spirv;
pub mod uniform_repr;
pub mod uniform_struct_arrays;
pub mod uniform_struct_padding;
pub mod units;
pub mod varying_locations;
pub mod version;
pub mod webgpu_features;
