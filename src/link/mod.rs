//! Cross-stage checks by OpenGL link rules, and the manifest ↔ shader uniform checks.
//!
//! naga sees one stage at a time and, after our rewrite to 4.50, loses block and instance
//! names, so everything the GL linker would check between stages runs here on the syntax
//! facts of [`StageSyntax`]. glslang's `linkValidate` is the reference for what is an
//! error; the messages try to say *why* two declarations do not link and what to change.
//!
//! - [`interface`]: outputs of one stage against inputs of the next (loose varyings by
//!   name, interface blocks by block name).
//! - [`blocks`]: member-by-member comparison of two blocks, shared by the interface and
//!   uniform checks.
//! - [`names`]: uses of a name that only another stage declares (`vert_out.x` in the
//!   fragment stage).
//! - [`uniforms`]: uniforms are program-wide, so declarations of one name must agree.
//! - [`effect_uniforms`] (with [`values`]): `effect.toml` `[uniforms]` / `[textures]` against
//!   the declarations, which [`declared`] gathers.
//!
//! Names are compared and displayed as the user wrote them ([`StageSyntax::original_name`]):
//! each stage renames newer keywords on its own, so internal names may differ per stage.
//!
//! # Diagnostic codes
//! | code    | severity | meaning |
//! |---------|----------|---------|
//! | `E0201` | error    | an input block has no output block of the same *block* name in the previous stage (paired with the likely intended block when there is one) |
//! | `E0202` | error    | a loose input the stage reads has no output of that name in the previous stage |
//! | `E0203` | error    | a use of a name this stage does not declare but another stage does (block instance or block name, varying, uniform), or of a block by its block name |
//! | `E0204` | error    | one loose uniform name declared with different types in two stages |
//! | `E0205` | error    | one uniform / buffer block name declared with different members in two stages |
//! | `E0206` | error    | a struct used by uniforms defined differently in two stages |
//! | `E0207` | error    | an output and the input of the same name have different types or array sizes |
//! | `E0208` | error    | interpolation qualifiers (`flat`, `noperspective`, `smooth`) differ, or one stage writes one and the other none (GLSL before 4.30) |
//! | `E0209` | error    | `centroid` differs (GLSL before 4.30) |
//! | `E0210` | error    | explicit `layout(location)` values differ |
//! | `E0211` | error    | interface blocks of the same block name differ (members, order, types, qualifiers, array size, location) |
//! | `E0212` | error    | a geometry-stage input is not an array |
//! | `E0213` | error    | GLSL ES 3.00+: a fragment stage with several outputs leaves one without `layout(location)` |
//! | `E0214` | error    | a geometry stage without its input primitive, output primitive or `max_vertices`, or with two different ones |
//! | `E0220` | error    | a `[uniforms]` entry names no declared uniform |
//! | `E0221` | error    | a `[uniforms]` default does not fit the declared type |
//! | `E0222` | error    | a `semantic` provides a type the uniform is not declared with |
//! | `E0223` | error    | `range` on a uniform that is not a number or a numeric vector |
//! | `E0224` | error    | a `[textures]` entry names no sampler uniform |
//! | `E0225` | error    | a `[uniforms]` path (`a[2]`, `s.field`) does not fit the declaration |
//! | `E0226` | error    | a texture's kind (`2d` / `cube`) does not match its sampler's type |
//! | `W0201` | warning  | an output the next stage never reads (declares no input for) |
//! | `W0202` | warning  | an input (or input block) with no producer, which the stage never reads |
//! | `W0203` | warning  | interpolation qualifiers differ (allowed since GLSL 4.30: the later stage's wins) |
//! | `E0227` | error    | a `[mesh.attributes]` / `[instances.attributes]` name that is no vertex input |
//! | `E0228` | error    | a vertex input fed per vertex and per instance, or given more components than it holds |
//! | `W0204` | warning  | `centroid` differs (allowed since GLSL 4.30: the later stage's wins) |
//! | `W0220` | warning  | a uniform some stage reads has no default in `effect.toml` |
//! | `W0221` | warning  | a uniform (or uniform block) no stage reads |
//! | `W0222` | warning  | a sampler uniform some stage reads has no `[textures]` entry |
//! | `W0223` | warning  | a `[uniforms]` default for a uniform no stage reads |

pub mod attributes;
pub mod blocks;
mod compat_values;
pub mod declared;
pub mod effect_uniforms;
pub mod graph_rules;
pub mod interface;
pub mod names;
pub mod uniforms;
pub mod values;

#[cfg(test)]
mod tests;

use crate::diag::{Code, Diagnostic, Files};
use crate::front::syntax::{Global, GlslType, Referent, StageSyntax};
use crate::stage::StageKind;

/// OpenGL link rules between consecutive stages of one program, plus the program-wide
/// uniform rules. `stages` are in pipeline order (vertex → tessellation → geometry →
/// fragment, the middle ones optional); compute stages are checked on their own (uniforms only).
pub fn check_interface(stages: &[StageSyntax]) -> Vec<Diagnostic> {
    let graphics: Vec<&StageSyntax> = stages.iter().filter(|s| s.stage != StageKind::Compute).collect();
    let mut out = Vec::new();
    for pair in graphics.windows(2) {
        interface::check_pair(pair[0], pair[1], &mut out);
    }
    for s in &graphics {
        es_fragment_output_locations(s, &mut out);
        geometry_layout(s, &mut out);
    }
    names::check(&graphics, &mut out);
    uniforms::check(&graphics, &mut out);
    out
}

/// GLSL §4.4.1.2/§4.4.2.2: a geometry stage declares its input primitive, its output
/// primitive and `max_vertices` (once, or the same each time); glslang refuses to link
/// without them, and effectc's lowering needs them.
fn geometry_layout(s: &StageSyntax, out: &mut Vec<Diagnostic>) {
    // A passthrough geometry stage (GL_NV_geometry_shader_passthrough) emits its input
    // primitive as it is: it declares no output primitive or `max_vertices`.
    let passthrough = s.globals.iter().any(|g| g.layout.iter().any(|(k, _)| k == "passthrough"));
    if s.stage != StageKind::Geometry || passthrough {
        return;
    }
    let problem = match crate::front::geometry_layout::geometry_layout(s) {
        // A count effectc cannot evaluate is legal: only the lowering reports it.
        Err(problem) if !problem.unreadable => problem,
        _ => return,
    };
    let mut d = Diagnostic::new(Code::GeometryLayout, problem.message);
    d = match problem.span {
        Some(span) => d.at(s.file, span, "this declaration"),
        None => d.in_file(s.file),
    };
    if let Some(example) = problem.example {
        d = d.with_help(format!("declare it before `main`, e.g. `{example}`"));
    }
    out.push(d.with_note("a geometry stage says what primitive it takes, what it emits, and at most how many vertices"));
}

/// GLSL ES 3.00 §4.3.8.2: with more than one fragment output, every one needs a location
/// (desktop GL can bind them from the API, ES cannot).
fn es_fragment_output_locations(s: &StageSyntax, out: &mut Vec<Diagnostic>) {
    if s.stage != StageKind::Fragment || !s.version.is_es() || s.version.number < 300 {
        return;
    }
    let outputs: Vec<&Global> = s.globals.iter().filter(|g| g.storage == crate::front::syntax::Storage::Out && !is_builtin(s, g)).collect();
    if outputs.len() < 2 {
        return;
    }
    for g in outputs.iter().filter(|g| g.location.is_none()) {
        out.push(
            Diagnostic::new(
                Code::EsOutputLocation,
                format!(
                    "fragment output `{}` has no `layout(location)`, but the stage has {} outputs",
                    s.original_name(&g.name),
                    outputs.len()
                ),
            )
            .at(s.file, g.name_span.clone(), "declared without a location")
            .with_note(
                "in GLSL ES 3.00 and later, when a fragment stage has more than one output, every output needs `layout(location = N)`",
            )
            .with_help(format!(
                "declare it as `layout(location = N) out {} {};`",
                type_text(s, &g.ty),
                s.original_name(&g.name)
            )),
        );
    }
}

/// `effect.toml` against the stages' declarations: every `[uniforms]` default names a
/// declared uniform and fits its type, every read uniform has a default, every sampler a
/// texture.
pub fn check_manifest(effect: &crate::manifest::Effect, stages: &[StageSyntax], files: &Files) -> Vec<Diagnostic> {
    let mut out = effect_uniforms::check(effect, stages, files);
    out.extend(attributes::check(effect, stages));
    out
}

/// [`check_manifest`] for one pass of a multi-pass effect (`effect` is the pass's view);
/// `bound` are the samplers the pass reads targets through.
pub fn check_pass_manifest(
    effect: &crate::manifest::Effect,
    stages: &[StageSyntax],
    files: &Files,
    bound: &std::collections::HashSet<String>,
) -> Vec<Diagnostic> {
    let mut out = effect_uniforms::check_with_bound(effect, stages, files, bound);
    out.extend(attributes::check(effect, stages));
    out
}

/// Built-in variables and blocks (`gl_Position`, `gl_PerVertex`, `gl_in`).
pub(crate) fn is_builtin(s: &StageSyntax, g: &Global) -> bool {
    s.original_name(&g.name).starts_with("gl_") || g.block.as_ref().is_some_and(|b| s.original_name(&b.block_name).starts_with("gl_"))
}

/// A global's type as the user wrote it (struct names through the renames).
pub(crate) fn type_text(s: &StageSyntax, ty: &GlslType) -> String {
    GlslType { base: s.original_name(&ty.base).to_string(), dims: ty.dims.clone() }.to_string()
}

/// Types of two stages' declarations equal (base names compared as written). An implicitly
/// sized array (`vec4 a[]`) takes its size at link time, so it matches any size of the
/// other stage's (glslang merges them the same way).
pub(crate) fn same_type(a: &StageSyntax, at: &GlslType, b: &StageSyntax, bt: &GlslType) -> bool {
    a.original_name(&at.base) == b.original_name(&bt.base)
        && at.dims.len() == bt.dims.len()
        && at.dims.iter().zip(&bt.dims).all(|(x, y)| x.is_none() || y.is_none() || x == y)
}

/// Opaque types (samplers, separate textures, images, atomic counters): not settable by
/// value. Arrays of them too.
pub(crate) fn is_opaque(ty: &GlslType) -> bool {
    let b = ty.base.as_str();
    ty.is_sampler() || b.contains("sampler") || b.contains("texture") || b.contains("image") || b == "atomic_uint"
}

/// A sampler (combined or separate), the kind of uniform `[textures]` binds.
pub(crate) fn is_sampler_like(ty: &GlslType) -> bool {
    ty.is_sampler() || ty.base.contains("sampler")
}

/// Some use in the stage refers to global `index` (for a block: any member or the instance).
pub(crate) fn is_read(s: &StageSyntax, index: usize) -> bool {
    s.uses.iter().any(|u| u.target == Referent::Global(index))
}

/// Some use reads member `member` of the anonymous block `index` (by its bare name).
pub(crate) fn member_read(s: &StageSyntax, index: usize, member: &str) -> bool {
    s.uses.iter().any(|u| u.target == Referent::Global(index) && u.name == member)
}

/// `a`, `b` and `c` — names in backticks joined for prose; long lists are cut.
pub(crate) fn list(names: &[String]) -> String {
    const MAX: usize = 8;
    let quoted: Vec<String> = names.iter().take(MAX).map(|n| format!("`{n}`")).collect();
    let mut text = match quoted.len() {
        0 => String::new(),
        1 => quoted[0].clone(),
        n => format!("{} and {}", quoted[..n - 1].join(", "), quoted[n - 1]),
    };
    if names.len() > MAX {
        text = format!("{}, … ({} in all)", quoted.join(", "), names.len());
    }
    text
}
