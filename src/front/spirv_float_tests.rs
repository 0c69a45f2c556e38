//! `isnan` and `isinf` (`OpIsNan`, `OpIsInf` of 32-bit floats) computed from the float's
//! bits, as the GLSL route's rewrite does (`rewrite::polyfills`): WGSL has neither, so
//! naga's WGSL writer refuses them, and a bit test is one no compiler folds away (WGSL lets
//! an implementation assume no NaN in a comparison). `isnan(x)` is `(bits(x) & 0x7fffffff) >
//! 0x7f800000`, `isinf(x)` is `(bits(x) & 0x7fffffff) == 0x7f800000`, component-wise for
//! vectors. Tests of other widths are left as they are. The lengths change, so this runs
//! before [`Lines`] is taken.
//!
//! [`Lines`]: crate::front::spirv_binary::Lines

use std::collections::HashMap;

use rspirv::spirv::Op;

use crate::front::spirv_binary::{has_result_type, instruction, instructions, HEADER_WORDS, OP_FUNCTION, OP_TYPE_INT};

const OP_IS_NAN: u16 = Op::IsNan as u16;
const OP_IS_INF: u16 = Op::IsInf as u16;
const OP_TYPE_FLOAT: u16 = Op::TypeFloat as u16;
const OP_TYPE_VECTOR: u16 = Op::TypeVector as u16;
/// All bits of a 32-bit float but its sign; its exponent all ones, mantissa zero (infinity).
const MAGNITUDE: u32 = 0x7fff_ffff;
const INFINITY: u32 = 0x7f80_0000;

/// `words` with each 32-bit `OpIsNan`/`OpIsInf` computed from bits.
pub(crate) fn float_tests_from_bits(words: Vec<u32>) -> Vec<u32> {
    if !instructions(&words).any(|(_, op, _)| op == OP_IS_NAN || op == OP_IS_INF) {
        return words;
    }
    // 32-bit float scalar and vector types: id → component count.
    let mut floats: HashMap<u32, u32> = HashMap::new();
    let mut uint = None;
    let mut uvecs: HashMap<u32, u32> = HashMap::new();
    let mut type_of: HashMap<u32, u32> = HashMap::new();
    // The tests to rewrite: (offset, component count).
    let mut tests: HashMap<usize, u32> = HashMap::new();
    for (at, op, count) in instructions(&words) {
        let w = &words[at..(at + count.max(1)).min(words.len())];
        match op {
            OP_TYPE_FLOAT if w.len() == 3 && w[2] == 32 => {
                floats.insert(w[1], 1);
            }
            OP_TYPE_INT if w.len() == 4 && w[2] == 32 && w[3] == 0 => uint = uint.or(Some(w[1])),
            OP_TYPE_VECTOR if w.len() == 4 => {
                if floats.get(&w[2]) == Some(&1) {
                    floats.insert(w[1], w[3]);
                }
                if Some(w[2]) == uint {
                    uvecs.entry(w[3]).or_insert(w[1]);
                }
            }
            OP_IS_NAN | OP_IS_INF if w.len() == 4 => {
                if let Some(&n) = type_of.get(&w[3]).and_then(|t| floats.get(t)) {
                    tests.insert(at, n);
                }
            }
            _ => {}
        }
        let typed = has_result_type(op);
        if typed && w.len() >= 3 {
            type_of.insert(w[2], w[1]);
        }
    }
    if tests.is_empty() {
        return words;
    }
    let mut bound = words[3];
    let mut fresh = || {
        bound += 1;
        bound - 1
    };
    let mut globals = Vec::new();
    let uint = uint.unwrap_or_else(|| {
        let id = fresh();
        globals.extend(instruction(OP_TYPE_INT, &[id, 32, 0]));
        id
    });
    let (magnitude, infinity) = (fresh(), fresh());
    globals.extend(instruction(Op::Constant as u16, &[uint, magnitude, MAGNITUDE]));
    globals.extend(instruction(Op::Constant as u16, &[uint, infinity, INFINITY]));
    // Per component count: (unsigned type, magnitude mask, infinity).
    let mut shapes: HashMap<u32, (u32, u32, u32)> = HashMap::new();
    shapes.insert(1, (uint, magnitude, infinity));
    let mut sizes: Vec<u32> = tests.values().copied().filter(|n| *n > 1).collect();
    sizes.sort_unstable();
    sizes.dedup();
    for n in sizes {
        let t = match uvecs.get(&n) {
            Some(t) => *t,
            None => {
                let t = fresh();
                globals.extend(instruction(OP_TYPE_VECTOR, &[t, uint, n]));
                t
            }
        };
        let (m, i) = (fresh(), fresh());
        globals.extend(instruction(Op::ConstantComposite as u16, &[&[t, m][..], &vec![magnitude; n as usize]].concat()));
        globals.extend(instruction(Op::ConstantComposite as u16, &[&[t, i][..], &vec![infinity; n as usize]].concat()));
        shapes.insert(n, (t, m, i));
    }
    let mut out = words[..HEADER_WORDS].to_vec();
    for (at, op, count) in instructions(&words) {
        let w = &words[at..(at + count.max(1)).min(words.len())];
        if op == OP_FUNCTION && !globals.is_empty() {
            out.extend(std::mem::take(&mut globals));
        }
        let Some(n) = tests.get(&at) else {
            out.extend_from_slice(w);
            continue;
        };
        // OpIsNan/OpIsInf result-type result x
        let (t, mask, inf) = shapes[n];
        let (bits, masked) = (fresh(), fresh());
        out.extend(instruction(Op::Bitcast as u16, &[t, bits, w[3]]));
        out.extend(instruction(Op::BitwiseAnd as u16, &[t, masked, bits, mask]));
        let compare = if op == OP_IS_NAN { Op::UGreaterThan } else { Op::IEqual };
        out.extend(instruction(compare as u16, &[w[1], w[2], masked, inf]));
    }
    out[3] = bound;
    out
}
