//! Integer instructions whose signedness naga's SPIR-V front does not adjust, rewritten to
//! ones it reads as SPIR-V means them.
//!
//! GLSL's `findMSB(uint)`, `findLSB(uint)` and `bitCount(uint)` return `int`, and glslang
//! writes them so (`%r = OpExtInst %int FindUMsb %u`, `%r = OpBitCount %int %u`); naga's
//! SPIR-V front gives the result its operand's type instead, while every later instruction
//! still reads `%r` as the declared type: `31 - findMSB(y)` became a subtraction of an `i32`
//! and a `u32`, which naga's validator refuses. Each such query is computed here in its
//! operand's type under a fresh id, and `OpBitcast` to the declared type gives the original
//! result id its value.
//!
//! `OpSNegate` of an unsigned integer (glslang writes `-shift` of a `uint` so: two's
//! complement negation) became naga's unary minus on a `u32`, which WGSL and naga's validator
//! refuse; it is written `(x ^ x) - x` instead, the same bits without a constant.
//!
//! `OpSMod` (glslang's `%` of signed integers) becomes `OpSRem`: GLSL leaves `%` of negative
//! operands undefined (GLSL 4.60 §5.9), so both are conforming, and naga's lowering of
//! `OpSMod` through floats fails on vectors (`ivec3 % 256`) and lowers scalars through 64-bit
//! integers, which WebGPU lacks; `OpSRem` is WGSL's `%`.
//!
//! An atomic's value operand of the other signedness than its result (glslang writes GLSL ES
//! 3.10's `atomicCounterIncrement` as `OpAtomicIAdd %uint %p .. %int_1`, which spirv-val
//! refuses too: "expected Value to be of type Result Type") is bitcast to the result's type
//! first; naga's validator refused the atomic.
//!
//! The lengths change, so this runs before [`Lines`] is taken.
//!
//! [`Lines`]: crate::front::spirv_binary::Lines

use std::collections::HashMap;

use rspirv::spirv::{GLOp, Op};

use crate::front::spirv_binary::{has_result_type, instructions, HEADER_WORDS};

const OP_EXT_INST_IMPORT: u16 = Op::ExtInstImport as u16;
const OP_EXT_INST: u16 = Op::ExtInst as u16;
const OP_BIT_COUNT: u16 = Op::BitCount as u16;
const OP_BITCAST: u16 = Op::Bitcast as u16;
const OP_S_NEGATE: u16 = Op::SNegate as u16;
const OP_I_SUB: u16 = Op::ISub as u16;
const OP_BITWISE_XOR: u16 = Op::BitwiseXor as u16;
const OP_S_MOD: u16 = Op::SMod as u16;
const OP_S_REM: u16 = Op::SRem as u16;
const OP_TYPE_INT: u16 = Op::TypeInt as u16;
const OP_TYPE_VECTOR: u16 = Op::TypeVector as u16;
const OP_ATOMIC_COMPARE_EXCHANGE: u16 = Op::AtomicCompareExchange as u16;
/// Atomics whose one value operand follows pointer, scope and semantics.
const ATOMICS_WITH_VALUE: [Op; 10] = [
    Op::AtomicExchange,
    Op::AtomicIAdd,
    Op::AtomicISub,
    Op::AtomicSMin,
    Op::AtomicUMin,
    Op::AtomicSMax,
    Op::AtomicUMax,
    Op::AtomicAnd,
    Op::AtomicOr,
    Op::AtomicXor,
];
/// The GLSL.std.450 instructions that take an integer and return one of either signedness.
const BIT_QUERIES: [u32; 3] = [GLOp::FindILsb as u32, GLOp::FindSMsb as u32, GLOp::FindUMsb as u32];

/// An instruction rewritten: where, and how.
enum Fix {
    /// A bit query computed in its operand's type (this one), then bitcast.
    InOperandType(u32),
    /// An unsigned negation written as a subtraction from zero.
    UnsignedNegate,
    /// An atomic whose value operands at these word offsets are bitcast to its result type.
    AtomicValues(Vec<usize>),
}

/// `words` with the instructions of the module doc rewritten.
pub(crate) fn signedness_naga_reads(mut words: Vec<u32>) -> Vec<u32> {
    let modulos: Vec<usize> = instructions(&words).filter(|(_, op, _)| *op == OP_S_MOD).map(|(at, _, _)| at).collect();
    for at in modulos {
        words[at] = (words[at] & 0xffff_0000) | u32::from(OP_S_REM);
    }
    let glsl = instructions(&words)
        .find(|&(at, op, count)| op == OP_EXT_INST_IMPORT && count > 2 && literal_string(&words[at + 2..at + count]) == "GLSL.std.450")
        .map(|(at, _, _)| words[at + 1]);
    // Integer scalar and vector types, by id: (component width, component count), signed.
    let mut shapes: HashMap<u32, ((u32, u32), bool)> = HashMap::new();
    let mut type_of: HashMap<u32, u32> = HashMap::new();
    let mut typed_ops: HashMap<u16, bool> = HashMap::new();
    let mut fixes = Vec::new();
    for (at, op, count) in instructions(&words) {
        match op {
            OP_TYPE_INT if count >= 4 => {
                shapes.insert(words[at + 1], ((words[at + 2], 1), words[at + 3] == 1));
            }
            OP_TYPE_VECTOR if count >= 4 => {
                if let Some(&((width, _), signed)) = shapes.get(&words[at + 2]) {
                    shapes.insert(words[at + 1], ((width, words[at + 3]), signed));
                }
            }
            _ => {}
        }
        let typed = *typed_ops.entry(op).or_insert_with(|| has_result_type(op));
        if !typed || count < 3 {
            continue;
        }
        type_of.insert(words[at + 2], words[at + 1]);
        if op == OP_S_NEGATE && count == 4 && shapes.get(&words[at + 1]).is_some_and(|(_, signed)| !signed) {
            fixes.push((at, Fix::UnsignedNegate));
            continue;
        }
        let values: &[usize] = match op {
            OP_ATOMIC_COMPARE_EXCHANGE if count == 9 => &[7, 8],
            _ if count == 7 && ATOMICS_WITH_VALUE.iter().any(|a| *a as u16 == op) => &[6],
            _ => &[],
        };
        let mistyped: Vec<usize> = values
            .iter()
            .copied()
            .filter(|v| {
                let value_type = type_of.get(&words[at + v]).copied();
                let shape = |t: u32| shapes.get(&t).map(|(shape, _)| *shape);
                value_type.is_some_and(|t| t != words[at + 1] && shape(t).is_some() && shape(t) == shape(words[at + 1]))
            })
            .collect();
        if !mistyped.is_empty() {
            fixes.push((at, Fix::AtomicValues(mistyped)));
            continue;
        }
        let operand = match op {
            OP_EXT_INST if count == 6 && Some(words[at + 3]) == glsl && BIT_QUERIES.contains(&words[at + 4]) => at + 5,
            OP_BIT_COUNT if count == 4 => at + 3,
            _ => continue,
        };
        let (result_type, operand_type) = (words[at + 1], type_of.get(&words[operand]).copied());
        if let Some(operand_type) = operand_type.filter(|t| *t != result_type) {
            let shape = |t: &u32| shapes.get(t).map(|(shape, _)| *shape);
            if shape(&operand_type).is_some() && shape(&operand_type) == shape(&result_type) {
                fixes.push((at, Fix::InOperandType(operand_type)));
            }
        }
    }
    if fixes.is_empty() {
        return words;
    }
    let mut out = Vec::with_capacity(words.len() + 4 * fixes.len());
    out.extend_from_slice(&words[..HEADER_WORDS]);
    let mut bound = words[3];
    let mut fresh = || {
        bound += 1;
        bound - 1
    };
    let mut next = fixes.into_iter().peekable();
    for (at, _, count) in instructions(&words) {
        let instruction = &words[at..(at + count.max(1)).min(words.len())];
        let Some((_, fix)) = next.next_if(|(m, _)| *m == at) else {
            out.extend_from_slice(instruction);
            continue;
        };
        let (result_type, result) = (instruction[1], instruction[2]);
        match fix {
            Fix::InOperandType(operand_type) => {
                let computed = fresh();
                out.push(instruction[0]);
                out.extend_from_slice(&[operand_type, computed]);
                out.extend_from_slice(&instruction[3..]);
                out.extend_from_slice(&[(4 << 16) | u32::from(OP_BITCAST), result_type, result, computed]);
            }
            Fix::UnsignedNegate => {
                let (x, zero) = (instruction[3], fresh());
                out.extend_from_slice(&[(5 << 16) | u32::from(OP_BITWISE_XOR), result_type, zero, x, x]);
                out.extend_from_slice(&[(5 << 16) | u32::from(OP_I_SUB), result_type, result, zero, x]);
            }
            Fix::AtomicValues(offsets) => {
                let mut atomic = instruction.to_vec();
                for offset in offsets {
                    let cast = fresh();
                    out.extend_from_slice(&[(4 << 16) | u32::from(OP_BITCAST), result_type, cast, instruction[offset]]);
                    atomic[offset] = cast;
                }
                out.extend_from_slice(&atomic);
            }
        }
    }
    out[3] = bound;
    out
}

/// A SPIR-V literal string (nul-terminated UTF-8 in little-endian words).
fn literal_string(words: &[u32]) -> String {
    let bytes: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).take_while(|b| *b != 0).collect();
    String::from_utf8_lossy(&bytes).into_owned()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bit_queries_are_computed_in_their_operands_type_and_unsigned_negation_subtracts() {
        let glsl = u32::from_le_bytes(*b"GLSL");
        let (std, t450) = (u32::from_le_bytes(*b".std"), u32::from_le_bytes(*b".450"));
        #[rustfmt::skip]
        let words = vec![
            0x0723_0203, 0x0001_0000, 0, 20, 0,
            (6 << 16) | 11, 1, glsl, std, t450, 0,  // %1 = OpExtInstImport "GLSL.std.450"
            (4 << 16) | 21, 2, 32, 0,               // %2 = OpTypeInt 32 0
            (4 << 16) | 21, 3, 32, 1,               // %3 = OpTypeInt 32 1
            (4 << 16) | 43, 2, 4, 7,                // %4 = OpConstant %2 7
            (6 << 16) | 12, 3, 5, 1, 75, 4,         // %5 = OpExtInst %3 %1 FindUMsb %4
            (4 << 16) | 205, 3, 6, 4,               // %6 = OpBitCount %3 %4
            (4 << 16) | 205, 2, 7, 4,               // %7 = OpBitCount %2 %4 (types agree)
            (4 << 16) | 126, 2, 8, 4,               // %8 = OpSNegate %2 %4 (unsigned)
            (4 << 16) | 126, 3, 9, 5,               // %9 = OpSNegate %3 %5 (signed: kept)
            (5 << 16) | 139, 3, 10, 9, 9,           // %10 = OpSMod %3 %9 %9
        ];
        let out = signedness_naga_reads(words);
        assert_eq!(out[3], 23, "three fresh ids");
        let ops: Vec<(u16, Vec<u32>)> = instructions(&out).skip(4).map(|(at, op, n)| (op, out[at + 1..at + n].to_vec())).collect();
        assert_eq!(
            ops,
            [
                (OP_EXT_INST, vec![2, 20, 1, 75, 4]),
                (OP_BITCAST, vec![3, 5, 20]),
                (OP_BIT_COUNT, vec![2, 21, 4]),
                (OP_BITCAST, vec![3, 6, 21]),
                (OP_BIT_COUNT, vec![2, 7, 4]),
                (OP_BITWISE_XOR, vec![2, 22, 4, 4]),
                (OP_I_SUB, vec![2, 8, 22, 4]),
                (OP_S_NEGATE, vec![3, 9, 5]),
                (OP_S_REM, vec![3, 10, 9, 9]),
            ]
        );
    }

    #[test]
    fn an_atomics_value_of_the_other_signedness_is_bitcast_to_its_result_type() {
        #[rustfmt::skip]
        let words = vec![
            0x0723_0203, 0x0001_0000, 0, 20, 0,
            (4 << 16) | 21, 2, 32, 0,               // %2 = OpTypeInt 32 0
            (4 << 16) | 21, 3, 32, 1,               // %3 = OpTypeInt 32 1
            (4 << 16) | 43, 2, 4, 1,                // %4 = OpConstant %2 1
            (4 << 16) | 43, 3, 5, 1,                // %5 = OpConstant %3 1
            (7 << 16) | 234, 2, 6, 9, 4, 4, 5,      // %6 = OpAtomicIAdd %2 %9 %4 %4 %5 (signed value)
            (7 << 16) | 234, 2, 7, 9, 4, 4, 4,      // %7 = OpAtomicIAdd %2 %9 %4 %4 %4 (types agree)
            (9 << 16) | 230, 2, 8, 9, 4, 4, 4, 5, 5, // %8 = OpAtomicCompareExchange, both signed
        ];
        let out = signedness_naga_reads(words);
        assert_eq!(out[3], 23, "three fresh ids");
        let ops: Vec<(u16, Vec<u32>)> = instructions(&out).skip(4).map(|(at, op, n)| (op, out[at + 1..at + n].to_vec())).collect();
        assert_eq!(
            ops,
            [
                (OP_BITCAST, vec![2, 20, 5]),
                (Op::AtomicIAdd as u16, vec![2, 6, 9, 4, 4, 20]),
                (Op::AtomicIAdd as u16, vec![2, 7, 9, 4, 4, 4]),
                (OP_BITCAST, vec![2, 21, 5]),
                (OP_BITCAST, vec![2, 22, 5]),
                (Op::AtomicCompareExchange as u16, vec![2, 8, 9, 4, 4, 4, 21, 22]),
            ]
        );
    }
}
