//! `gl_PointCoord` as the constant (0.5, 0.5), as the GLSL route's rewrite reads it (N0104):
//! WebGPU draws points one pixel wide and has no point coordinate (naga's WGSL writer
//! refuses the built-in), and the centre of a one-pixel point is where GL's coordinate is
//! (0.5, 0.5). The input variable decorated `BuiltIn PointCoord` becomes a private variable
//! initialised to that value: its decoration goes, and so does its place in the entry
//! point's interface. The lengths change, so this runs before [`Lines`] is taken.
//!
//! [`Lines`]: crate::front::spirv_binary::Lines

use rspirv::spirv::{BuiltIn, Decoration, Op, StorageClass};

use crate::front::spirv_binary::{instruction, instructions, HEADER_WORDS, OP_DECORATE, OP_ENTRY_POINT, OP_TYPE_POINTER, OP_VARIABLE};

const OP_CONSTANT: u16 = Op::Constant as u16;

/// `words` with `gl_PointCoord` read as (0.5, 0.5).
pub(crate) fn point_coord_at_the_centre(words: Vec<u32>) -> Vec<u32> {
    let is_point_coord = |at: usize, op: u16, count: usize| {
        op == OP_DECORATE && count == 4 && words[at + 2] == Decoration::BuiltIn as u32 && words[at + 3] == BuiltIn::PointCoord as u32
    };
    let Some(var) = instructions(&words).find(|&(at, op, count)| is_point_coord(at, op, count)).map(|(at, ..)| words[at + 1]) else {
        return words;
    };
    // The variable's pointer type, the vec2 it points to, and its float.
    let declared = |wanted: u16, id_at: usize, id: u32, result_at: usize| {
        instructions(&words)
            .find_map(|(at, op, count)| (op == wanted && count >= 4 && words[at + id_at] == id).then_some(words[at + result_at]))
    };
    let pointer = declared(OP_VARIABLE, 2, var, 1);
    let vec2 = pointer.and_then(|p| declared(OP_TYPE_POINTER, 1, p, 3));
    let float = vec2.and_then(|v| declared(Op::TypeVector as u16, 1, v, 2));
    let (Some(vec2), Some(float)) = (vec2, float) else { return words };
    let mut bound = words[3];
    let mut fresh = || {
        bound += 1;
        bound - 1
    };
    let (private_pointer, half, centre) = (fresh(), fresh(), fresh());
    let mut out = words[..HEADER_WORDS].to_vec();
    for (at, op, count) in instructions(&words) {
        let w = &words[at..(at + count.max(1)).min(words.len())];
        match op {
            // OpEntryPoint model entry name… interface…: the name is a nul-terminated
            // string; ids after it are the interface, where the variable is left out.
            OP_ENTRY_POINT => {
                let name_words = w[3..].iter().position(|word| word.to_le_bytes().contains(&0)).map_or(w.len(), |p| 3 + p + 1);
                let mut e: Vec<u32> = w[..name_words.min(w.len())].to_vec();
                e.extend(w[name_words.min(w.len())..].iter().filter(|id| **id != var));
                e[0] = ((e.len() as u32) << 16) | u32::from(OP_ENTRY_POINT);
                out.extend(e);
            }
            OP_DECORATE if w.len() >= 3 && w[1] == var => {}
            OP_VARIABLE if w.len() >= 4 && w[2] == var => {
                out.extend(instruction(OP_TYPE_POINTER, &[private_pointer, StorageClass::Private as u32, vec2]));
                out.extend(instruction(OP_CONSTANT, &[float, half, 0.5f32.to_bits()]));
                out.extend(instruction(Op::ConstantComposite as u16, &[vec2, centre, half, half]));
                out.extend(instruction(OP_VARIABLE, &[private_pointer, var, StorageClass::Private as u32, centre]));
            }
            _ => out.extend_from_slice(w),
        }
    }
    out[3] = bound;
    out
}
