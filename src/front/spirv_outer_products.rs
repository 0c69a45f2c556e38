//! `outerProduct` (`OpOuterProduct`) computed column by column, as the GLSL route's rewrite
//! does (`effectc_outerProduct`): naga reads it as `Math::Outer`, which its WGSL, MSL and
//! HLSL writers cannot write. Column `j` of `outerProduct(c, r)` is `c * r[j]`
//! (`OpCompositeExtract` of the row's component, `OpVectorTimesScalar`), and
//! `OpCompositeConstruct` gives the original result id the matrix. The lengths change, so
//! this runs before [`Lines`] is taken.
//!
//! [`Lines`]: crate::front::spirv_binary::Lines

use std::collections::HashMap;

use rspirv::spirv::Op;

use crate::front::spirv_binary::{has_result_type, instructions, HEADER_WORDS};

const OP_OUTER_PRODUCT: u16 = Op::OuterProduct as u16;
const OP_TYPE_VECTOR: u16 = Op::TypeVector as u16;
const OP_COMPOSITE_EXTRACT: u16 = Op::CompositeExtract as u16;
const OP_VECTOR_TIMES_SCALAR: u16 = Op::VectorTimesScalar as u16;
const OP_COMPOSITE_CONSTRUCT: u16 = Op::CompositeConstruct as u16;

/// `words` with every `OpOuterProduct` of the module doc computed column by column.
pub(crate) fn outer_products_by_columns(words: Vec<u32>) -> Vec<u32> {
    if !instructions(&words).any(|(_, op, _)| op == OP_OUTER_PRODUCT) {
        return words;
    }
    // Vector types: id → (component type, component count).
    let mut vectors: HashMap<u32, (u32, u32)> = HashMap::new();
    let mut type_of: HashMap<u32, u32> = HashMap::new();
    // The products to rewrite: offset → (column type, component type of the row, row length).
    let mut products: HashMap<usize, (u32, u32, u32)> = HashMap::new();
    for (at, op, count) in instructions(&words) {
        let w = &words[at..(at + count.max(1)).min(words.len())];
        match op {
            OP_TYPE_VECTOR if w.len() == 4 => {
                vectors.insert(w[1], (w[2], w[3]));
            }
            OP_OUTER_PRODUCT if w.len() == 5 => {
                if let (Some(&column), Some(&(scalar, length))) = (type_of.get(&w[3]), type_of.get(&w[4]).and_then(|t| vectors.get(t))) {
                    products.insert(at, (column, scalar, length));
                }
            }
            _ => {}
        }
        let typed = has_result_type(op);
        if typed && w.len() >= 3 {
            type_of.insert(w[2], w[1]);
        }
    }
    let mut out = Vec::with_capacity(words.len() + 16 * products.len());
    out.extend_from_slice(&words[..HEADER_WORDS]);
    let mut bound = words[3];
    for (at, _, count) in instructions(&words) {
        let w = &words[at..(at + count.max(1)).min(words.len())];
        let Some(&(column_type, scalar, length)) = products.get(&at) else {
            out.extend_from_slice(w);
            continue;
        };
        let (matrix, result, column, row) = (w[1], w[2], w[3], w[4]);
        let mut columns = Vec::with_capacity(length as usize);
        for j in 0..length {
            let (component, product) = (bound, bound + 1);
            bound += 2;
            out.extend_from_slice(&[(5 << 16) | u32::from(OP_COMPOSITE_EXTRACT), scalar, component, row, j]);
            out.extend_from_slice(&[(5 << 16) | u32::from(OP_VECTOR_TIMES_SCALAR), column_type, product, column, component]);
            columns.push(product);
        }
        out.push(((3 + length) << 16) | u32::from(OP_COMPOSITE_CONSTRUCT));
        out.extend_from_slice(&[matrix, result]);
        out.extend_from_slice(&columns);
    }
    out[3] = bound;
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_outer_product_is_built_from_columns() {
        #[rustfmt::skip]
        let words = vec![
            0x0723_0203, 0x0001_0000, 0, 20, 0,
            (3 << 16) | 22, 2, 32,                  // %2 = OpTypeFloat 32
            (4 << 16) | 23, 3, 2, 3,                // %3 = OpTypeVector %2 3
            (4 << 16) | 23, 4, 2, 2,                // %4 = OpTypeVector %2 2
            (4 << 16) | 24, 5, 3, 2,                // %5 = OpTypeMatrix %3 2
            (3 << 16) | 1, 3, 6,                    // %6 = OpUndef %3
            (3 << 16) | 1, 4, 7,                    // %7 = OpUndef %4
            (5 << 16) | 147, 5, 8, 6, 7,            // %8 = OpOuterProduct %5 %6 %7
        ];
        let out = outer_products_by_columns(words);
        assert_eq!(out[3], 24, "four fresh ids");
        let ops: Vec<(u16, Vec<u32>)> = instructions(&out).skip(6).map(|(at, op, n)| (op, out[at + 1..at + n].to_vec())).collect();
        assert_eq!(
            ops,
            [
                (OP_COMPOSITE_EXTRACT, vec![2, 20, 7, 0]),
                (OP_VECTOR_TIMES_SCALAR, vec![3, 21, 6, 20]),
                (OP_COMPOSITE_EXTRACT, vec![2, 22, 7, 1]),
                (OP_VECTOR_TIMES_SCALAR, vec![3, 23, 6, 22]),
                (OP_COMPOSITE_CONSTRUCT, vec![5, 8, 21, 23]),
            ]
        );
    }
}
