//! A location for every varying of a program, the same in every stage: explicit locations
//! kept, varyings packed into a location's later components given a location of their own
//! (naga's GLSL front and WGSL have no `component` qualifier), the rest numbered after them.

use std::collections::HashMap;

use crate::front::syntax::{layout_number, Global, GlslType, StageSyntax, Storage};
use crate::stage::StageKind;

/// Varying name → first location, and (location, component) as written → the location a
/// component-packed varying takes instead.
///
/// Explicit locations are kept. A varying at a later component of a location
/// (`layout(location = 0, component = 3)`) gets the first free location range for its
/// (location, component) pair: both ends of an interface write the same pair, so they meet
/// again. The other varyings are numbered after those in first-seen order, by slot count,
/// and the compatibility profile's varyings (`linked`, one slot each) after them.
pub fn number(stages: &[StageSyntax], linked: &[String]) -> (HashMap<String, u32>, HashMap<(u32, u32), u32>) {
    let mut map = HashMap::new();
    let mut used: Vec<(u32, u32)> = Vec::new();
    // (location, component) → slots, widest over the stages, in first-seen order.
    let mut packed: Vec<((u32, u32), u32)> = Vec::new();
    for s in stages {
        for g in s.globals.iter().filter(|g| is_varying(s, g)) {
            let Some(loc) = g.location else { continue };
            let slots = slots_of(g, s);
            match component(g).filter(|&c| c > 0) {
                Some(c) => match packed.iter_mut().find(|(key, _)| *key == (loc, c)) {
                    Some((_, widest)) => *widest = (*widest).max(slots),
                    None => packed.push(((loc, c), slots)),
                },
                None => {
                    map.entry(g.name.clone()).or_insert(loc);
                    used.push((loc, loc + slots));
                }
            }
        }
    }
    let mut components = HashMap::new();
    for (key, slots) in packed {
        let at = first_free(&used, 0, slots);
        used.push((at, at + slots));
        components.insert(key, at);
    }
    for s in stages {
        for g in s.globals.iter().filter(|g| is_varying(s, g)) {
            if let (Some(loc), Some(c)) = (g.location, component(g)) {
                if let Some(&at) = components.get(&(loc, c)) {
                    map.entry(g.name.clone()).or_insert(at);
                }
            }
        }
    }
    // Once a geometry stage is folded, the varyings between the vertex and geometry stages
    // are private: the fragment stage's inputs are numbered first, so the ones WebGPU passes
    // start at location 0 (a wide vertex → geometry interface would push them past its limit).
    let mut order: Vec<&StageSyntax> = stages.iter().collect();
    if stages.iter().any(|s| s.stage == StageKind::Geometry) {
        order.sort_by_key(|s| s.stage != StageKind::Fragment);
    }
    let mut next = 0u32;
    for s in order {
        for g in s.globals.iter().filter(|g| is_varying(s, g)) {
            if map.contains_key(&g.name) {
                continue;
            }
            let slots = slots_of(g, s);
            next = first_free(&used, next, slots);
            map.insert(g.name.clone(), next);
            used.push((next, next + slots));
            next += slots;
        }
    }
    for name in linked {
        next = first_free(&used, next, 1);
        map.insert(name.clone(), next);
        used.push((next, next + 1));
        next += 1;
    }
    (map, components)
}

/// Number of locations a varying of this type uses.
pub fn location_slots(ty: &GlslType, stage: &StageSyntax) -> u32 {
    let per = match ty.base.as_str() {
        "mat2" | "mat2x2" | "mat2x3" | "mat2x4" | "dmat2" => 2,
        "mat3" | "mat3x3" | "mat3x2" | "mat3x4" | "dmat3" => 3,
        "mat4" | "mat4x4" | "mat4x2" | "mat4x3" | "dmat4" => 4,
        other => match stage.struct_def(other) {
            Some(s) => s.members.iter().map(|m| location_slots(&m.ty, stage)).sum::<u32>().max(1),
            None => 1,
        },
    };
    per * ty.dims.iter().map(|d| d.unwrap_or(1)).product::<u32>()
}

/// The `component` of a declaration's layout qualifier.
pub fn component(g: &Global) -> Option<u32> {
    layout_number(&g.layout, "component")
}

/// Whether `g` passes values between two stages (not a vertex input or fragment output).
pub fn is_varying(s: &StageSyntax, g: &Global) -> bool {
    match g.storage {
        Storage::Varying => true,
        Storage::In => s.stage != StageKind::Vertex,
        Storage::Out => s.stage != StageKind::Fragment,
        _ => false,
    }
}

/// The first location at or after `from` where `slots` locations are all free.
fn first_free(used: &[(u32, u32)], from: u32, slots: u32) -> u32 {
    let mut at = from;
    while used.iter().any(|&(a, b)| at < b && a < at + slots) {
        at += 1;
    }
    at
}

fn slots_of(g: &Global, s: &StageSyntax) -> u32 {
    match &g.block {
        Some(b) => b.members.iter().map(|m| location_slots(&m.ty, s)).sum::<u32>().max(1),
        None => {
            // Geometry/tessellation inputs are per-vertex arrays of the varying.
            let ty = if matches!(s.stage, StageKind::Geometry | StageKind::TessControl | StageKind::TessEval) && g.storage == Storage::In {
                g.ty.element()
            } else {
                g.ty.clone()
            };
            location_slots(&ty, s)
        }
    }
}
