//! The size of an arrayed image with its layer count (`textureSize` of a `sampler2DArray`,
//! `samplerCubeArray`, `sampler1DArray` or `sampler2DMSArray`, `imageSize` of an
//! `image2DArray`): naga's SPIR-V front (30) reads `OpImageQuerySize(Lod)` of an arrayed
//! image as its dimensions without the layers, a vector one component short of the SPIR-V
//! result type, and no SPIR-V instruction reads as naga's `ImageQuery::NumLayers`.
//!
//! Two steps around naga's parse:
//! - [`array_sizes_by_parts`] (words): the query asks for the dimensions only, an
//!   `OpImageQueryLevels` of the same image stands in for the layer count, and
//!   `OpCompositeConstruct` gives the original result id the full vector;
//! - [`layers_queried`] (naga IR): where a vector is composed of exactly those two queries
//!   of one arrayed image, the second becomes `ImageQuery::NumLayers`. Every size query of
//!   an arrayed image went through the first step, so the pattern is found nowhere else.

use std::collections::HashMap;

use naga::{Expression, Handle, ImageQuery, Module, TypeInner};
use rspirv::spirv::Op;

use crate::front::spirv_binary::{has_result_type, instructions, HEADER_WORDS, OP_TYPE_IMAGE};

const OP_TYPE_VECTOR: u16 = Op::TypeVector as u16;
const OP_IMAGE_QUERY_SIZE: u16 = Op::ImageQuerySize as u16;
const OP_IMAGE_QUERY_SIZE_LOD: u16 = Op::ImageQuerySizeLod as u16;
const OP_IMAGE_QUERY_LEVELS: u16 = Op::ImageQueryLevels as u16;
const OP_COMPOSITE_CONSTRUCT: u16 = Op::CompositeConstruct as u16;

/// One size query to split: the component type and the type of the dimensions alone.
struct Query {
    component: u32,
    dimensions: u32,
}

/// `words` with every size query of an arrayed image split as the module doc says.
pub(crate) fn array_sizes_by_parts(words: Vec<u32>) -> Vec<u32> {
    let queries = |op: u16| op == OP_IMAGE_QUERY_SIZE || op == OP_IMAGE_QUERY_SIZE_LOD;
    if !instructions(&words).any(|(_, op, _)| queries(op)) {
        return words;
    }
    // Vector types: id → (component type, count), and back.
    let mut vectors: HashMap<u32, (u32, u32)> = HashMap::new();
    let mut vector_of: HashMap<(u32, u32), u32> = HashMap::new();
    let mut arrayed_images: Vec<u32> = Vec::new();
    let mut type_of: HashMap<u32, u32> = HashMap::new();
    let mut found: HashMap<usize, (u32, u32)> = HashMap::new();
    for (at, op, count) in instructions(&words) {
        let w = &words[at..(at + count.max(1)).min(words.len())];
        match op {
            OP_TYPE_VECTOR if w.len() == 4 => {
                vectors.insert(w[1], (w[2], w[3]));
                vector_of.entry((w[2], w[3])).or_insert(w[1]);
            }
            // OpTypeImage %id %sampled-type Dim Depth Arrayed MS Sampled Format
            OP_TYPE_IMAGE if w.len() >= 9 && w[5] == 1 => arrayed_images.push(w[1]),
            op if queries(op) && w.len() >= 4 && type_of.get(&w[3]).is_some_and(|t| arrayed_images.contains(t)) => {
                if let Some(&(component, n)) = vectors.get(&w[1]) {
                    found.insert(at, (component, n));
                }
            }
            _ => {}
        }
        if w.len() >= 3 && has_result_type(op) {
            type_of.insert(w[2], w[1]);
        }
    }
    if found.is_empty() {
        return words;
    }
    let mut bound = words[3];
    // Vector types the dimensions need that the module lacks: declared after the full one.
    let mut added: HashMap<u32, Vec<u32>> = HashMap::new();
    let mut plan: HashMap<usize, Query> = HashMap::new();
    for (&at, &(component, n)) in &found {
        let dimensions = if n == 2 {
            component
        } else if let Some(&v) = vector_of.get(&(component, n - 1)) {
            v
        } else {
            let v = bound;
            bound += 1;
            vector_of.insert((component, n - 1), v);
            let full = vector_of[&(component, n)];
            added.entry(full).or_default().extend_from_slice(&[(4 << 16) | u32::from(OP_TYPE_VECTOR), v, component, n - 1]);
            v
        };
        plan.insert(at, Query { component, dimensions });
    }
    let mut out = Vec::with_capacity(words.len() + 12 * plan.len());
    out.extend_from_slice(&words[..HEADER_WORDS]);
    for (at, op, count) in instructions(&words) {
        let w = &words[at..(at + count.max(1)).min(words.len())];
        let Some(q) = plan.get(&at) else {
            out.extend_from_slice(w);
            if op == OP_TYPE_VECTOR && w.len() == 4 {
                out.extend(added.get(&w[1]).into_iter().flatten());
            }
            continue;
        };
        let (result_type, result, image) = (w[1], w[2], w[3]);
        let (dims, layers) = (bound, bound + 1);
        bound += 2;
        out.push(w[0]);
        out.extend_from_slice(&[q.dimensions, dims]);
        out.extend_from_slice(&w[3..]);
        out.extend_from_slice(&[(4 << 16) | u32::from(OP_IMAGE_QUERY_LEVELS), q.component, layers, image]);
        out.extend_from_slice(&[(5 << 16) | u32::from(OP_COMPOSITE_CONSTRUCT), result_type, result, dims, layers]);
    }
    out[3] = bound;
    out
}

/// The layer count of each size split by [`array_sizes_by_parts`], as the module doc says.
pub(crate) fn layers_queried(module: &mut Module) {
    let arrayed =
        |ty: Handle<naga::Type>, types: &naga::UniqueArena<naga::Type>| matches!(types[ty].inner, TypeInner::Image { arrayed: true, .. });
    let functions = module.functions.iter_mut().map(|(_, f)| f).chain(module.entry_points.iter_mut().map(|e| &mut e.function));
    for f in functions {
        let image_is_arrayed = |e: &Expression| match *e {
            Expression::GlobalVariable(g) => arrayed(module.global_variables[g].ty, &module.types),
            Expression::FunctionArgument(i) => f.arguments.get(i as usize).is_some_and(|a| arrayed(a.ty, &module.types)),
            _ => false,
        };
        let mut layers = Vec::new();
        for (_, e) in f.expressions.iter() {
            let Expression::Compose { ref components, .. } = *e else { continue };
            let [dims, count] = components[..] else { continue };
            let (dims, count) = (query_under_cast(&f.expressions, dims), query_under_cast(&f.expressions, count));
            let (Some((image, ImageQuery::Size { .. })), Some((same, ImageQuery::NumLevels))) =
                (dims.map(|(i, q, _)| (i, q)), count.map(|(i, q, _)| (i, q)))
            else {
                continue;
            };
            if image == same && image_is_arrayed(&f.expressions[image]) {
                layers.extend(count.map(|(_, _, h)| h));
            }
        }
        for h in layers {
            if let Expression::ImageQuery { ref mut query, .. } = f.expressions[h] {
                *query = ImageQuery::NumLayers;
            }
        }
    }
}

/// The image query `h` is, or converts (naga's SPIR-V front casts a signed result): its
/// image, the query, and the query expression's handle.
fn query_under_cast(
    exprs: &naga::Arena<Expression>,
    h: Handle<Expression>,
) -> Option<(Handle<Expression>, ImageQuery, Handle<Expression>)> {
    let h = match exprs[h] {
        Expression::As { expr, .. } => expr,
        _ => h,
    };
    match exprs[h] {
        Expression::ImageQuery { image, query } => Some((image, query, h)),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A size query of a 2D image, arrayed or not, whose result has `components` ints.
    fn size_query(arrayed: u32, components: u32) -> Vec<u32> {
        #[rustfmt::skip]
        let words = vec![
            0x0723_0203, 0x0001_0000, 0, 20, 0,
            (4 << 16) | 21, 2, 32, 1,                      // %2 = OpTypeInt 32 1
            (4 << 16) | 23, 3, 2, components,              // %3 = OpTypeVector %2 N
            (3 << 16) | 22, 4, 32,                         // %4 = OpTypeFloat 32
            (9 << 16) | 25, 5, 4, 1, 0, arrayed, 0, 1, 0,  // %5 = OpTypeImage %4 2D 0 Arrayed 0 1 Unknown
            (3 << 16) | 1, 5, 6,                           // %6 = OpUndef %5
            (4 << 16) | 104, 3, 7, 6,                      // %7 = OpImageQuerySize %3 %6
        ];
        words
    }

    #[test]
    fn an_arrayed_size_is_built_from_its_dimensions_and_layers() {
        let out = array_sizes_by_parts(size_query(1, 3));
        assert_eq!(out[3], 23, "a vector type and two results");
        let ops: Vec<(u16, Vec<u32>)> = instructions(&out).map(|(at, op, n)| (op, out[at + 1..at + n].to_vec())).collect();
        assert_eq!(ops[2], (OP_TYPE_VECTOR, vec![20, 2, 2]), "ivec2, declared after ivec3");
        assert_eq!(
            ops[6..],
            [(OP_IMAGE_QUERY_SIZE, vec![20, 21, 6]), (OP_IMAGE_QUERY_LEVELS, vec![2, 22, 6]), (OP_COMPOSITE_CONSTRUCT, vec![3, 7, 21, 22]),]
        );
    }

    #[test]
    fn a_size_of_an_image_that_is_no_array_stays() {
        let words = size_query(0, 2);
        assert_eq!(array_sizes_by_parts(words.clone()), words);
    }
}
