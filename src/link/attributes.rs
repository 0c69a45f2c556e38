//! `effect.toml` against the vertex stage's inputs: every name in `[mesh.attributes]` and
//! `[instances.attributes]` is a vertex input, no input is fed by both, and the manifest's
//! own per-vertex and per-instance values have no more components than the input holds.

use super::list;
use crate::diag::{Code, Diagnostic};
use crate::front::syntax::{StageSyntax, Storage};
use crate::manifest::{did_you_mean, Effect};
use crate::stage::StageKind;

/// The vertex inputs of the vertex stage: (name, components of its type; 0 when unknown).
fn vertex_inputs(stages: &[StageSyntax]) -> Vec<(String, usize)> {
    let Some(vs) = stages.iter().find(|s| s.stage == StageKind::Vertex) else { return Vec::new() };
    vs.globals
        .iter()
        .filter(|g| matches!(g.storage, Storage::In | Storage::Attribute) && g.block.is_none())
        .map(|g| (g.name.clone(), components(&g.ty.base)))
        .collect()
}

fn components(base: &str) -> usize {
    match base {
        "float" | "int" | "uint" | "bool" | "double" => 1,
        b if b.ends_with('2') => 2,
        b if b.ends_with('3') => 3,
        b if b.ends_with('4') => 4,
        _ => 0,
    }
}

pub fn check(effect: &Effect, stages: &[StageSyntax]) -> Vec<Diagnostic> {
    let inputs = vertex_inputs(stages);
    if !stages.iter().any(|s| s.stage == StageKind::Vertex) {
        return Vec::new();
    }
    let names: Vec<&str> = inputs.iter().map(|(n, _)| n.as_str()).collect();
    let mut out = Vec::new();
    let unknown = |name: &str, span: std::ops::Range<usize>, section: &str, out: &mut Vec<Diagnostic>| {
        let mut d = Diagnostic::new(Code::AttributeUnknown, format!("`{name}` in [{section}] is not an input of the vertex stage")).at(
            effect.file,
            span,
            "no vertex input has this name",
        );
        d = if names.is_empty() {
            d.with_note("the vertex stage declares no inputs")
        } else {
            d.with_note(format!("vertex inputs: {}", list(&inputs.iter().map(|(n, _)| n.clone()).collect::<Vec<_>>())))
        };
        if let Some(s) = did_you_mean(name, &names) {
            d = d.with_help(format!("did you mean `{s}`?"));
        }
        out.push(d);
    };
    // (input, where the manifest names it) of every input fed per vertex.
    let mut per_vertex: Vec<(&str, std::ops::Range<usize>)> = Vec::new();
    if let Some(mesh) = &effect.mesh {
        for ((name, _), span) in mesh.attributes.iter().zip(&mesh.attribute_spans) {
            if !names.contains(&name.as_str()) {
                unknown(name, span.clone(), "mesh.attributes", &mut out);
            }
            per_vertex.push((name, span.clone()));
        }
        for a in &mesh.values {
            match inputs.iter().find(|(name, _)| *name == a.input) {
                None => unknown(&a.input, a.input_span.clone(), "mesh.attributes", &mut out),
                Some((_, n)) => out.extend(too_many_components(effect, a, *n, "vertex")),
            }
            per_vertex.push((&a.input, a.input_span.clone()));
        }
    }
    let Some(instances) = &effect.instances else { return out };
    for a in &instances.attributes {
        let Some((_, n)) = inputs.iter().find(|(name, _)| *name == a.input) else {
            unknown(&a.input, a.input_span.clone(), "instances.attributes", &mut out);
            continue;
        };
        if let Some((_, span)) = per_vertex.iter().find(|(name, _)| *name == a.input) {
            out.push(
                Diagnostic::new(Code::AttributeConflict, format!("vertex input `{}` is fed both per vertex and per instance", a.input))
                    .at(effect.file, a.input_span.clone(), "per instance here")
                    .with_label(effect.file, span.clone(), "per vertex here")
                    .with_help("keep one of the two entries"),
            );
            continue;
        }
        out.extend(too_many_components(effect, a, *n, "instance"));
    }
    out
}

/// The manifest gives `a` more components per `element` (vertex, instance) than its input
/// holds (`n`; 0 when unknown).
fn too_many_components(effect: &Effect, a: &crate::manifest::InstanceAttribute, n: usize, element: &str) -> Option<Diagnostic> {
    (n > 0 && a.components > n).then(|| {
        Diagnostic::new(
            Code::AttributeConflict,
            format!("`{}` gets {} components per {element} but the input holds {n}", a.input, a.components),
        )
        .at(effect.file, a.input_span.clone(), "too many components")
    })
}
