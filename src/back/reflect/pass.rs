//! One pass of a multi-pass effect in its reflection: what it draws into (each colour
//! target by output location, with its format and size, and whether it is attached), its
//! depth target, and which earlier targets its samplers read.

use serde::Serialize;

use crate::graph::PassPlan;
use crate::manifest::{Effect, Filter, PassClear, PassDraw, TargetSize};

#[derive(Debug, Clone, Serialize)]
pub struct PassInfo {
    pub name: String,
    /// Position in the manifest's `[[passes]]` (passes run in this order).
    pub index: usize,
    /// `mesh` or `fullscreen`.
    pub draw: &'static str,
    /// Colour targets by fragment output location.
    pub targets: Vec<PassTarget>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub depth: Option<PassTarget>,
    /// Samplers reading earlier passes' targets.
    pub reads: Vec<PassRead>,
    /// `clear = false`: the pass draws over what earlier passes left in its targets.
    pub keeps_contents: bool,
    /// The effect's `output`: the target written as the frame.
    pub output: Option<String>,
}

#[derive(Debug, Clone, Serialize)]
pub struct PassTarget {
    /// Output location (colour targets).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub location: Option<u32>,
    pub target: String,
    /// `rgba8`, `rgba16f`, `depth32f`, …
    pub format: &'static str,
    /// `[w, h]` in pixels, or a factor of the output size.
    pub size: TargetExtent,
    /// False where no later pass reads the target: the output is discarded.
    pub attached: bool,
}

#[derive(Debug, Clone, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum TargetExtent {
    Pixels([u32; 2]),
    Scale(f32),
}

#[derive(Debug, Clone, Serialize)]
pub struct PassRead {
    /// The sampler uniform's GLSL name (the `glsl` of its texture and sampler bindings).
    pub sampler: String,
    pub target: String,
    pub format: &'static str,
    /// `linear` or `nearest`; edges are clamped.
    pub filter: &'static str,
}

/// The reflection of pass `index` of `effect`; `plan` says which attachments are kept.
pub fn pass_info(effect: &Effect, index: usize, plan: Option<&PassPlan>) -> Option<PassInfo> {
    let pass = effect.passes.get(index)?;
    let target = |name: &str, location: Option<u32>, attached: bool| {
        let decl = effect.target(name);
        PassTarget {
            location,
            target: name.to_string(),
            format: decl.map_or("unknown", |d| d.format.name()),
            size: match decl.map(|d| d.size) {
                Some(TargetSize::Absolute(w, h)) => TargetExtent::Pixels([w, h]),
                Some(TargetSize::Scale(s)) => TargetExtent::Scale(s),
                None => TargetExtent::Scale(1.0),
            },
            attached,
        }
    };
    let attached = |location: usize| plan.and_then(|p| p.attached.get(index)?.get(location).copied()).unwrap_or(true);
    Some(PassInfo {
        name: pass.name.clone(),
        index,
        draw: match pass.draw {
            PassDraw::Mesh => "mesh",
            PassDraw::Fullscreen => "fullscreen",
        },
        targets: pass.targets.iter().enumerate().map(|(i, t)| target(&t.name, Some(i as u32), attached(i))).collect(),
        depth: pass.depth.as_ref().map(|d| target(&d.name, None, true)),
        reads: pass
            .samples
            .iter()
            .map(|s| PassRead {
                sampler: s.sampler.clone(),
                target: s.target.name.clone(),
                format: effect.target(&s.target.name).map_or("unknown", |d| d.format.name()),
                filter: match s.filter {
                    Filter::Linear => "linear",
                    Filter::Nearest => "nearest",
                },
            })
            .collect(),
        keeps_contents: pass.clear == PassClear::Keep,
        output: effect.output.as_ref().map(|o| o.name.clone()),
    })
}
