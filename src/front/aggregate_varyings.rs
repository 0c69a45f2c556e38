//! Interpolation qualifiers of struct and array varyings, put back after naga's GLSL front.
//!
//! naga's GLSL front passes a struct or array varying (`flat out Foo f;`, `noperspective
//! out float d[2];`, `centroid in vec2 uv[3];`) member by member, one location each, and
//! gives every member the default interpolation of its type: the variable's own qualifier
//! is dropped, and a `flat` float struct member is interpolated across the triangle. The
//! members' bindings (entry-point arguments of the fragment stage, result members of the
//! vertex stage) get the variable's qualifier back, at the locations naga walked them to.

use naga::{Binding, Interpolation, Module, Sampling, ShaderStage, TypeInner};

use crate::front::plan::Plan;
use crate::front::syntax::{Interp, StageSyntax, Storage};

/// Puts each qualified struct or array varying's interpolation (and `centroid`) back on
/// the bindings naga made of its members.
pub fn qualify(module: &mut Module, s: &StageSyntax, plan: &Plan) {
    let (inputs, stage) = match s.stage.naga() {
        Some(ShaderStage::Fragment) => (true, ShaderStage::Fragment),
        Some(ShaderStage::Vertex) => (false, ShaderStage::Vertex),
        _ => return,
    };
    let mut qualified: Vec<(u32, Interpolation, Option<Sampling>)> = Vec::new();
    for g in &s.globals {
        let interface = match g.storage {
            Storage::In => inputs,
            Storage::Out => !inputs,
            Storage::Varying => true,
            _ => false,
        };
        if !interface || g.block.is_some() || (matches!(g.interp, None | Some(Interp::Smooth)) && !g.centroid) {
            continue;
        }
        let Some(location) = plan.varyings.get(&g.name).copied().or(g.location) else { continue };
        let Some(ty) = module.global_variables.iter().find(|(_, v)| v.name.as_deref() == Some(g.name.as_str())).map(|(_, v)| v.ty) else {
            continue;
        };
        if !matches!(module.types[ty].inner, TypeInner::Array { .. } | TypeInner::Struct { .. }) {
            continue;
        }
        let interpolation = match g.interp {
            Some(Interp::Flat) => Interpolation::Flat,
            Some(Interp::NoPerspective) => Interpolation::Linear,
            _ => Interpolation::Perspective,
        };
        let sampling = (g.centroid && interpolation != Interpolation::Flat).then_some(Sampling::Centroid);
        let mut leaves = Vec::new();
        walk(module, ty, location, &mut leaves);
        qualified.extend(leaves.into_iter().map(|l| (l, interpolation, sampling)));
    }
    if qualified.is_empty() {
        return;
    }
    let set = |binding: &mut Option<Binding>| {
        if let Some(Binding::Location { location, interpolation, sampling, .. }) = binding {
            if let Some((_, i, s)) = qualified.iter().find(|(l, ..)| l == location) {
                *interpolation = Some(*i);
                *sampling = *s;
            }
        }
    };
    for ep in module.entry_points.iter_mut().filter(|ep| ep.stage == stage) {
        if inputs {
            ep.function.arguments.iter_mut().for_each(|a| set(&mut a.binding));
            continue;
        }
        let Some(result) = &ep.function.result else { continue };
        let mut t = module.types[result.ty].clone();
        if let TypeInner::Struct { members, .. } = &mut t.inner {
            members.iter_mut().for_each(|m| set(&mut m.binding));
        }
        if module.types.get(&t).is_none() {
            module.types.replace(result.ty, t);
        }
    }
}

/// The locations naga's GLSL front gives the leaves of a varying of type `ty` at
/// `location` (its `arg_type_walker`): an array's elements one location apart from the
/// first, a struct's members one location per member without a binding of its own.
fn walk(module: &Module, ty: naga::Handle<naga::Type>, location: u32, out: &mut Vec<u32>) {
    match &module.types[ty].inner {
        TypeInner::Array { base, size: naga::ArraySize::Constant(n), .. } => {
            for i in 0..n.get() {
                walk(module, *base, location + i, out);
            }
        }
        TypeInner::Struct { members, .. } => {
            for (at, m) in (location..).zip(members.iter().filter(|m| m.binding.is_none())) {
                walk(module, m.ty, at, out);
            }
        }
        _ => out.push(location),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diag::FileId;
    use crate::front::naga_run::{self, Outcome};
    use crate::front::rewrite;
    use crate::stage::StageKind;

    /// The qualifiers of each varying argument of a fragment stage's entry point, after
    /// the front and [`qualify`].
    fn fragment_inputs(text: &str) -> Vec<(String, Option<Interpolation>, Option<Sampling>)> {
        let s = crate::front::syntax::analyse(FileId(0), text, StageKind::Fragment, Default::default()).expect("syntax");
        let plan = crate::front::plan::plan(std::slice::from_ref(&s), false);
        let (rewritten, _) = rewrite::rewrite(&s, &plan, false);
        let Outcome::Valid(mut v) = naga_run::parse_and_validate(s.file, &rewritten, ShaderStage::Fragment, &s.version) else {
            panic!("naga refused:\n{}", rewritten.text)
        };
        qualify(&mut v.module, &s, &plan);
        let ep = &v.module.entry_points[0];
        ep.function
            .arguments
            .iter()
            .filter_map(|a| match &a.binding {
                Some(Binding::Location { interpolation, sampling, .. }) => {
                    Some((a.name.clone().unwrap_or_default(), *interpolation, *sampling))
                }
                _ => None,
            })
            .collect()
    }

    #[test]
    fn struct_and_array_varyings_keep_their_qualifiers() {
        let text = "#version 330 core\nstruct Foo { vec4 a; vec2 b; };\nflat in Foo f;\nnoperspective in float d[2];\ncentroid in vec2 uv[2];\nin Foo plain;\nout vec4 c;\nvoid main() { c = f.a + vec4(f.b, d[0] + d[1], 0.0) + vec4(uv[0], uv[1]) + plain.a; }\n";
        let inputs = fragment_inputs(text);
        let flat = inputs.iter().filter(|(_, i, _)| *i == Some(Interpolation::Flat)).count();
        let linear = inputs.iter().filter(|(_, i, _)| *i == Some(Interpolation::Linear)).count();
        let centroid = inputs.iter().filter(|(_, _, s)| *s == Some(Sampling::Centroid)).count();
        assert_eq!((flat, linear, centroid), (2, 2, 2), "{inputs:?}");
        // `plain` keeps the default: perspective.
        assert_eq!(inputs.len(), 8, "{inputs:?}");
        assert_eq!(inputs.iter().filter(|(_, i, s)| *i == Some(Interpolation::Perspective) && s.is_none()).count(), 2, "{inputs:?}");
    }
}
