//! Subpass inputs (input attachments: `subpassInput`, `subpassInputMS`, and their `i`/`u`
//! forms) as 2D textures read at the fragment's own pixel, in the SPIR-V naga's SPIR-V front
//! reads: it reads no `SubpassData` image dimension, and WebGPU has no input attachments.
//! `subpassLoad(s)` reads the attachment at the fragment's framebuffer position, so it is
//! `texelFetch(t, ivec2(gl_FragCoord.xy), 0)` (GL_KHR_vulkan_glsl defines it so), and
//! `subpassLoad(s, sample)` of a multisampled one `texelFetch(t, ivec2(gl_FragCoord.xy),
//! sample)`. This covers inputs declared or read through macros, which the GLSL route's
//! rewrite (`rewrite::subpass`) does not see. The binding stays; the stage gains a
//! `gl_FragCoord` input if it had none. The lengths change, so this runs before [`Lines`]
//! is taken.
//!
//! [`Lines`]: crate::front::spirv_binary::Lines

use std::collections::HashSet;

use rspirv::spirv::{BuiltIn, Decoration, Dim, ImageOperands, Op, StorageClass};

use crate::front::spirv_binary::{
    instruction, instructions, HEADER_WORDS, OP_DECORATE, OP_ENTRY_POINT, OP_FUNCTION, OP_TYPE_IMAGE, OP_TYPE_INT, OP_TYPE_POINTER,
    OP_VARIABLE,
};

const OP_TYPE_FLOAT: u16 = Op::TypeFloat as u16;
const OP_TYPE_VECTOR: u16 = Op::TypeVector as u16;
const OP_LOAD: u16 = Op::Load as u16;
const OP_IMAGE_READ: u16 = Op::ImageRead as u16;

/// Ids of the types and values the lowering reads or declares.
struct Ids {
    float: Option<u32>,
    int: Option<u32>,
    /// (component, count) → vector type.
    vectors: Vec<((u32, u32), u32)>,
    input_vec4: Option<u32>,
    frag_coord: Option<u32>,
}

/// `words` with subpass inputs read as the module doc says.
pub(crate) fn subpass_inputs_as_textures(words: Vec<u32>) -> Vec<u32> {
    let subpass = |at: usize, op: u16, count: usize| op == OP_TYPE_IMAGE && count >= 9 && words[at + 3] == Dim::DimSubpassData as u32;
    if !instructions(&words).any(|(at, op, count)| subpass(at, op, count)) {
        return words;
    }
    lowered(&words)
}

fn scan(words: &[u32]) -> (Ids, HashSet<u32>) {
    let mut ids = Ids { float: None, int: None, vectors: Vec::new(), input_vec4: None, frag_coord: None };
    let mut images = HashSet::new();
    for (at, op, count) in instructions(words) {
        let w = &words[at..(at + count.max(1)).min(words.len())];
        match op {
            OP_TYPE_FLOAT if w.len() == 3 && w[2] == 32 => ids.float = ids.float.or(Some(w[1])),
            OP_TYPE_INT if w.len() == 4 && w[2] == 32 && w[3] == 1 => ids.int = ids.int.or(Some(w[1])),
            OP_TYPE_VECTOR if w.len() == 4 => ids.vectors.push(((w[2], w[3]), w[1])),
            OP_TYPE_IMAGE if w.len() >= 9 && w[3] == Dim::DimSubpassData as u32 => {
                images.insert(w[1]);
            }
            OP_DECORATE if w.len() == 4 && w[2] == Decoration::BuiltIn as u32 && w[3] == BuiltIn::FragCoord as u32 => {
                ids.frag_coord = Some(w[1]);
            }
            _ => {}
        }
    }
    let vec4 = ids.float.and_then(|f| ids.vectors.iter().find(|(k, _)| *k == (f, 4)).map(|(_, v)| *v));
    for (at, op, count) in instructions(words) {
        if op == OP_TYPE_POINTER && count == 4 && words[at + 2] == StorageClass::Input as u32 && Some(words[at + 3]) == vec4 {
            ids.input_vec4 = Some(words[at + 1]);
        }
    }
    (ids, images)
}

/// `OpTypeImage` `w` (result sampled-type dim depth arrayed ms sampled format) as a 2D
/// texture `texelFetch` reads.
fn texture_2d(w: &[u32]) -> Vec<u32> {
    let mut t = w.to_vec();
    t[3] = Dim::Dim2D as u32;
    t[7] = 1;
    t
}

fn lowered(words: &[u32]) -> Vec<u32> {
    let (ids, images) = scan(words);
    let mut bound = words[3];
    let mut fresh = || {
        bound += 1;
        bound - 1
    };
    let vector = |c: Option<u32>, n: u32| c.and_then(|c| ids.vectors.iter().find(|(k, _)| *k == (c, n)).map(|(_, v)| *v));
    // What the reads need, declared where missing: float, int, vec4, vec2, ivec2, an
    // `Input` pointer to vec4, gl_FragCoord and the constant 0.
    let float = ids.float.unwrap_or_else(&mut fresh);
    let int = ids.int.unwrap_or_else(&mut fresh);
    let vec4 = vector(Some(float), 4).unwrap_or_else(&mut fresh);
    let vec2 = vector(Some(float), 2).unwrap_or_else(&mut fresh);
    let ivec2 = vector(Some(int), 2).unwrap_or_else(&mut fresh);
    let input_vec4 = ids.input_vec4.unwrap_or_else(&mut fresh);
    let frag_coord = ids.frag_coord.unwrap_or_else(&mut fresh);
    let zero = fresh();
    let mut globals = Vec::new();
    if ids.float.is_none() {
        globals.extend(instruction(OP_TYPE_FLOAT, &[float, 32]));
    }
    if ids.int.is_none() {
        globals.extend(instruction(OP_TYPE_INT, &[int, 32, 1]));
    }
    for (id, component, n) in [(vec4, float, 4), (vec2, float, 2), (ivec2, int, 2)] {
        if vector(Some(component), n).is_none() {
            globals.extend(instruction(OP_TYPE_VECTOR, &[id, component, n]));
        }
    }
    if ids.input_vec4.is_none() {
        globals.extend(instruction(OP_TYPE_POINTER, &[input_vec4, StorageClass::Input as u32, vec4]));
    }
    if ids.frag_coord.is_none() {
        globals.extend(instruction(OP_VARIABLE, &[input_vec4, frag_coord, StorageClass::Input as u32]));
    }
    globals.extend(instruction(Op::Constant as u16, &[int, zero, 0]));
    // Loads of a subpass input (by result id).
    let mut loaded: HashSet<u32> = HashSet::new();
    let mut out = words[..HEADER_WORDS].to_vec();
    let (mut declared, mut annotated) = (false, false);
    for (at, op, count) in instructions(words) {
        let w = &words[at..(at + count.max(1)).min(words.len())];
        match op {
            // The fragment entry point reads gl_FragCoord: a new one joins its interface.
            OP_ENTRY_POINT if ids.frag_coord.is_none() && w[1] == rspirv::spirv::ExecutionModel::Fragment as u32 => {
                let mut e = w.to_vec();
                e.push(frag_coord);
                e[0] = ((e.len() as u32) << 16) | u32::from(OP_ENTRY_POINT);
                out.extend(e);
                continue;
            }
            // A new gl_FragCoord's decoration, last of the annotations (before the first type).
            _ if !annotated && (Op::TypeVoid as u16..=Op::TypeForwardPointer as u16).contains(&op) => {
                annotated = true;
                if ids.frag_coord.is_none() {
                    out.extend(instruction(OP_DECORATE, &[frag_coord, Decoration::BuiltIn as u32, BuiltIn::FragCoord as u32]));
                }
                if images.contains(&w[1]) {
                    out.extend(texture_2d(w));
                    continue;
                }
            }
            // OpTypeImage result sampled-type dim depth arrayed ms sampled format: a 2D
            // texture read by `texelFetch`.
            OP_TYPE_IMAGE if images.contains(&w[1]) => {
                out.extend(texture_2d(w));
                continue;
            }
            OP_FUNCTION if !declared => {
                declared = true;
                out.extend(std::mem::take(&mut globals));
            }
            OP_LOAD if w.len() >= 4 && images.contains(&w[1]) => {
                loaded.insert(w[2]);
            }
            // OpImageRead result-type result image coordinate [operands…]
            OP_IMAGE_READ if w.len() >= 5 && loaded.contains(&w[3]) => {
                let (fc, xy, pixel, at) = (fresh(), fresh(), fresh(), fresh());
                out.extend(instruction(OP_LOAD, &[vec4, fc, frag_coord]));
                out.extend(instruction(Op::VectorShuffle as u16, &[vec2, xy, fc, fc, 0, 1]));
                out.extend(instruction(Op::ConvertFToS as u16, &[ivec2, pixel, xy]));
                out.extend(instruction(Op::IAdd as u16, &[ivec2, at, pixel, w[4]]));
                let sample = (w.len() >= 7 && w[5] & ImageOperands::SAMPLE.bits() != 0).then(|| w[6]);
                let operands = match sample {
                    Some(s) => [ImageOperands::SAMPLE.bits(), s],
                    None => [ImageOperands::LOD.bits(), zero],
                };
                out.extend(instruction(Op::ImageFetch as u16, &[w[1], w[2], w[3], at, operands[0], operands[1]]));
                continue;
            }
            _ => {}
        }
        out.extend_from_slice(w);
    }
    out[3] = bound;
    out
}
