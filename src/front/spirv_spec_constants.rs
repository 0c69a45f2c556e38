//! Specialization constants where naga's SPIR-V front needs plain constants, folded to the
//! values they take when the pipeline does not specialize them (their defaults).
//!
//! naga reads `OpSpecConstant` as a pipeline-overridable constant, which is what it is, but
//! it reads no `OpSpecConstantOp` at all, takes no override as an array's length, and reads
//! no `OpExecutionModeId`. Vulkan GLSL meets all three in ordinary code:
//! `layout(constant_id = 0) const uint N = 64; shared float s[N * 2];` is an array sized by
//! an `OpSpecConstantOp`, and `layout(local_size_x_id = 0) in;` compiled for Vulkan 1.2+
//! gives `OpExecutionModeId LocalSizeId` (earlier, a `gl_WorkGroupSize` composite). So:
//! - every `OpSpecConstantOp` of 32-bit integer or boolean scalars is evaluated and becomes
//!   an `OpConstant` (`OpConstantTrue`/`False`);
//! - a specialization constant that sizes an array becomes a plain constant (its `SpecId`
//!   decoration goes, which is what naga reads an override by);
//! - a composite of specialization constants (`gl_WorkGroupSize`, `vec2(SPEC, SPEC)`) becomes
//!   a plain one, its constituents too: naga's overrides are scalars, and it refuses a
//!   constant built from them;
//! - `OpExecutionModeId LocalSizeId`/`LocalSizeHintId` becomes `OpExecutionMode
//!   LocalSize`/`LocalSizeHint` with the values of its ids, and `LocalSize` takes the values
//!   of the `gl_WorkGroupSize` composite where there is one (SPIR-V: it wins; naga reads
//!   only the execution mode).
//!
//! The folded values are the defaults the GLSL declares, as `render` runs the program
//! unspecialized; a program its pipeline specializes differently is translated for the
//! defaults. Instructions the pass cannot evaluate (vectors, 64-bit or float operands) are
//! left for naga to refuse. The lengths change, so this runs before [`Lines`] is taken.
//!
//! [`Lines`]: crate::front::spirv_binary::Lines

use std::collections::{HashMap, HashSet};

use rspirv::spirv::{BuiltIn, Decoration, ExecutionMode, Op};

use crate::front::spirv_binary::{instructions, HEADER_WORDS, OP_DECORATE, OP_EXECUTION_MODE, OP_TYPE_ARRAY, OP_TYPE_INT};

const OP_TYPE_BOOL: u16 = Op::TypeBool as u16;
const OP_TYPE_FLOAT: u16 = Op::TypeFloat as u16;
const OP_CONSTANT: u16 = Op::Constant as u16;
const OP_CONSTANT_TRUE: u16 = Op::ConstantTrue as u16;
const OP_CONSTANT_FALSE: u16 = Op::ConstantFalse as u16;
const OP_CONSTANT_NULL: u16 = Op::ConstantNull as u16;
const OP_SPEC_CONSTANT: u16 = Op::SpecConstant as u16;
const OP_SPEC_CONSTANT_TRUE: u16 = Op::SpecConstantTrue as u16;
const OP_SPEC_CONSTANT_FALSE: u16 = Op::SpecConstantFalse as u16;
const OP_SPEC_CONSTANT_OP: u16 = Op::SpecConstantOp as u16;
const OP_CONSTANT_COMPOSITE: u16 = Op::ConstantComposite as u16;
const OP_SPEC_CONSTANT_COMPOSITE: u16 = Op::SpecConstantComposite as u16;
const OP_EXECUTION_MODE_ID: u16 = Op::ExecutionModeId as u16;

/// A scalar type the evaluator computes in (32-bit integers of either signedness).
#[derive(Clone, Copy, PartialEq)]
enum Scalar {
    Bool,
    Int,
    /// A 32-bit float: only moved between composites (extracted, shuffled, selected).
    Float,
}

/// A value known at translate time: an integer's 32 bits or a boolean.
#[derive(Clone, Copy, PartialEq, Debug)]
enum Value {
    Bits(u32),
    Bool(bool),
}

/// What the pass changes in one instruction.
enum Change {
    /// An `OpSpecConstantOp` replaced by the constant of its value.
    Folded(Value),
    /// A specialization constant kept as a plain one (same operands).
    Plain(u16),
    /// A `SpecId` decoration dropped.
    Dropped,
    /// An `OpExecutionModeId` written with literals (mode, values), or an `OpExecutionMode
    /// LocalSize` given the `gl_WorkGroupSize` composite's values.
    Literal(u32, Vec<u32>),
    /// An `OpSpecConstantOp VectorShuffle` of constant composites: the composite of the
    /// components it picks.
    Shuffled(Vec<u32>),
}

/// `words` with the specialization constants of the module doc folded.
pub(crate) fn spec_constants_naga_reads(words: Vec<u32>) -> Vec<u32> {
    let spec_ops = [
        OP_SPEC_CONSTANT_OP,
        OP_EXECUTION_MODE_ID,
        OP_SPEC_CONSTANT_COMPOSITE,
        OP_SPEC_CONSTANT,
        OP_SPEC_CONSTANT_TRUE,
        OP_SPEC_CONSTANT_FALSE,
    ];
    if !instructions(&words).any(|(_, op, _)| spec_ops.contains(&op)) {
        return words;
    }
    let mut scalars: HashMap<u32, Scalar> = HashMap::new();
    let mut values: HashMap<u32, Value> = HashMap::new();
    let mut composites: HashMap<u32, Vec<u32>> = HashMap::new();
    let mut spec: HashMap<u32, (usize, u16)> = HashMap::new();
    let mut changes: HashMap<usize, Change> = HashMap::new();
    let mut made_plain: HashSet<u32> = HashSet::new();
    let mut make_plain = |id: u32, spec: &HashMap<u32, (usize, u16)>, changes: &mut HashMap<usize, Change>| {
        if let Some(&(spec_at, spec_op)) = spec.get(&id) {
            let plain = match spec_op {
                OP_SPEC_CONSTANT => OP_CONSTANT,
                OP_SPEC_CONSTANT_TRUE => OP_CONSTANT_TRUE,
                OP_SPEC_CONSTANT_FALSE => OP_CONSTANT_FALSE,
                _ => OP_CONSTANT_COMPOSITE,
            };
            changes.insert(spec_at, Change::Plain(plain));
            made_plain.insert(id);
        }
    };
    let workgroup_size = workgroup_size_composite(&words);
    let mut local_size_at = None;
    let mut mode_ids = Vec::new();
    for (at, op, count) in instructions(&words) {
        let w = &words[at..(at + count.max(1)).min(words.len())];
        note_value(op, w, &mut scalars, &mut values);
        match op {
            OP_SPEC_CONSTANT | OP_SPEC_CONSTANT_TRUE | OP_SPEC_CONSTANT_FALSE if w.len() >= 3 => {
                spec.insert(w[2], (at, op));
            }
            OP_CONSTANT_COMPOSITE if w.len() >= 3 => {
                composites.insert(w[2], w[3..].to_vec());
            }
            // A composite of specialization constants is no override in naga (overrides are
            // scalars) but a constant built from overrides, which naga refuses: it and its
            // constituents become plain.
            OP_SPEC_CONSTANT_COMPOSITE if w.len() >= 3 => {
                composites.insert(w[2], w[3..].to_vec());
                spec.insert(w[2], (at, op));
                make_plain(w[2], &spec, &mut changes);
                for c in &w[3..] {
                    make_plain(*c, &spec, &mut changes);
                }
            }
            OP_SPEC_CONSTANT_OP if w.len() >= 7 && w[3] == Op::VectorShuffle as u32 => {
                // (SMAA's `vec2(reverseScreenWidth, …).xy` of specialization constants.)
                if let Some(picked) = shuffled(&w[4..], &composites) {
                    composites.insert(w[2], picked.clone());
                    changes.insert(at, Change::Shuffled(picked));
                }
            }
            OP_SPEC_CONSTANT_OP if w.len() >= 5 => {
                let result_type = scalars.get(&w[1]).copied();
                if let Some(value) = result_type.and_then(|t| evaluate(w[3], &w[4..], t, &values, &composites)) {
                    values.insert(w[2], value);
                    changes.insert(at, Change::Folded(value));
                }
            }
            // OpTypeArray result element length
            OP_TYPE_ARRAY if w.len() == 4 => make_plain(w[3], &spec, &mut changes),
            OP_EXECUTION_MODE if w.len() == 6 && w[2] == ExecutionMode::LocalSize as u32 => local_size_at = Some(at),
            OP_EXECUTION_MODE_ID if w.len() >= 3 => mode_ids.push(at),
            _ => {}
        }
    }
    // OpExecutionModeId entry mode ids… (before the constants it names)
    for at in mode_ids {
        let w = &words[at..at + (words[at] >> 16) as usize];
        let mode = match w[2] {
            m if m == ExecutionMode::LocalSizeId as u32 => ExecutionMode::LocalSize,
            m if m == ExecutionMode::LocalSizeHintId as u32 => ExecutionMode::LocalSizeHint,
            _ => continue,
        };
        if let Some(literals) = w[3..].iter().map(|id| bits_of(&values, *id)).collect::<Option<Vec<u32>>>() {
            changes.insert(at, Change::Literal(mode as u32, literals));
        }
    }
    // `gl_WorkGroupSize` (a composite decorated `BuiltIn WorkgroupSize`) is the size the
    // stage runs with, whatever `LocalSize` says: naga reads only the latter.
    let size = workgroup_size
        .and_then(|id| composites.get(&id))
        .and_then(|c| c.iter().map(|id| bits_of(&values, *id)).collect::<Option<Vec<u32>>>());
    if let (Some(at), Some(size)) = (local_size_at, size.filter(|s| s.len() == 3)) {
        changes.insert(at, Change::Literal(ExecutionMode::LocalSize as u32, size));
    }
    // Folded results are plain constants now: a `SpecId` on one (or on a constant made
    // plain) would make naga read an override again.
    let folded: HashSet<u32> =
        changes.iter().filter(|(_, c)| matches!(c, Change::Folded(_))).map(|(at, _)| words[*at + 2]).chain(made_plain).collect();
    for (at, op, count) in instructions(&words) {
        if op == OP_DECORATE && count == 4 && words[at + 2] == Decoration::SpecId as u32 && folded.contains(&words[at + 1]) {
            changes.insert(at, Change::Dropped);
        }
    }
    if changes.is_empty() {
        return words;
    }
    applied(&words, &changes)
}

/// `words` with `changes` (by instruction offset) made.
fn applied(words: &[u32], changes: &HashMap<usize, Change>) -> Vec<u32> {
    let mut out = Vec::with_capacity(words.len());
    out.extend_from_slice(&words[..HEADER_WORDS]);
    for (at, _, count) in instructions(words) {
        let w = &words[at..(at + count.max(1)).min(words.len())];
        match changes.get(&at) {
            None => out.extend_from_slice(w),
            Some(Change::Dropped) => {}
            Some(Change::Plain(op)) => {
                out.push((w[0] & 0xffff_0000) | u32::from(*op));
                out.extend_from_slice(&w[1..]);
            }
            Some(Change::Folded(Value::Bits(bits))) => out.extend_from_slice(&[(4 << 16) | u32::from(OP_CONSTANT), w[1], w[2], *bits]),
            Some(Change::Folded(Value::Bool(b))) => {
                let op = if *b { OP_CONSTANT_TRUE } else { OP_CONSTANT_FALSE };
                out.extend_from_slice(&[(3 << 16) | u32::from(op), w[1], w[2]]);
            }
            Some(Change::Shuffled(picked)) => {
                out.push(((3 + picked.len() as u32) << 16) | u32::from(OP_CONSTANT_COMPOSITE));
                out.extend_from_slice(&[w[1], w[2]]);
                out.extend_from_slice(picked);
            }
            Some(Change::Literal(mode, literals)) => {
                out.push(((3 + literals.len() as u32) << 16) | u32::from(OP_EXECUTION_MODE));
                out.extend_from_slice(&[w[1], *mode]);
                out.extend_from_slice(literals);
            }
        }
    }
    out
}

/// Records the scalar type or the known value `w` (an instruction of opcode `op`) declares.
fn note_value(op: u16, w: &[u32], scalars: &mut HashMap<u32, Scalar>, values: &mut HashMap<u32, Value>) {
    match op {
        OP_TYPE_BOOL if w.len() >= 2 => {
            scalars.insert(w[1], Scalar::Bool);
        }
        OP_TYPE_INT if w.len() >= 4 && w[2] == 32 => {
            scalars.insert(w[1], Scalar::Int);
        }
        OP_TYPE_FLOAT if w.len() >= 3 && w[2] == 32 => {
            scalars.insert(w[1], Scalar::Float);
        }
        OP_CONSTANT | OP_SPEC_CONSTANT if w.len() == 4 && scalars.contains_key(&w[1]) => {
            values.insert(w[2], Value::Bits(w[3]));
        }
        OP_CONSTANT_TRUE | OP_CONSTANT_FALSE | OP_SPEC_CONSTANT_TRUE | OP_SPEC_CONSTANT_FALSE if w.len() == 3 => {
            values.insert(w[2], Value::Bool(matches!(op, OP_CONSTANT_TRUE | OP_SPEC_CONSTANT_TRUE)));
        }
        OP_CONSTANT_NULL if w.len() == 3 => {
            match scalars.get(&w[1]) {
                Some(Scalar::Bool) => values.insert(w[2], Value::Bool(false)),
                Some(Scalar::Int | Scalar::Float) => values.insert(w[2], Value::Bits(0)),
                None => None,
            };
        }
        _ => {}
    }
}

/// The components `OpVectorShuffle` `operands` (two vectors, then component indices) picks
/// from constant composites; None where a vector is not one or an index is undefined.
fn shuffled(operands: &[u32], composites: &HashMap<u32, Vec<u32>>) -> Option<Vec<u32>> {
    let [a, b, picks @ ..] = operands else { return None };
    let (a, b) = (composites.get(a)?, composites.get(b)?);
    picks.iter().map(|&i| a.get(i as usize).or_else(|| b.get((i as usize).checked_sub(a.len())?)).copied()).collect()
}

fn bits_of(values: &HashMap<u32, Value>, id: u32) -> Option<u32> {
    match values.get(&id)? {
        Value::Bits(b) => Some(*b),
        Value::Bool(_) => None,
    }
}

/// The id of the composite decorated `BuiltIn WorkgroupSize`, if any.
fn workgroup_size_composite(words: &[u32]) -> Option<u32> {
    instructions(words)
        .find(|&(at, op, count)| {
            op == OP_DECORATE && count == 4 && words[at + 2] == Decoration::BuiltIn as u32 && words[at + 3] == BuiltIn::WorkgroupSize as u32
        })
        .map(|(at, _, _)| words[at + 1])
}

/// The value of `OpSpecConstantOp` `opcode` on `operands` (ids, or literal indices after a
/// composite), in `result` type; None where an operand is unknown or the operation is not
/// one of 32-bit integer or boolean scalars (or the extraction of one from a composite).
fn evaluate(
    opcode: u32,
    operands: &[u32],
    result: Scalar,
    values: &HashMap<u32, Value>,
    composites: &HashMap<u32, Vec<u32>>,
) -> Option<Value> {
    let op = Op::from_u32(opcode)?;
    if result == Scalar::Float && !matches!(op, Op::CompositeExtract | Op::Select) {
        return None;
    }
    if op == Op::CompositeExtract {
        let [composite, index] = operands else { return None };
        return values.get(composites.get(composite)?.get(*index as usize)?).copied();
    }
    let arg = |i: usize| values.get(operands.get(i)?).copied();
    let bits = |i: usize| match arg(i)? {
        Value::Bits(b) => Some(b),
        Value::Bool(_) => None,
    };
    let truth = |i: usize| match arg(i)? {
        Value::Bool(b) => Some(b),
        Value::Bits(_) => None,
    };
    let int = |v: u32| Some(Value::Bits(v));
    let boolean = |v: bool| Some(Value::Bool(v));
    let signed = |i: usize| bits(i).map(|b| b as i32);
    let shift = |i: usize| bits(i).filter(|s| *s < 32);
    match op {
        Op::IAdd => int(bits(0)?.wrapping_add(bits(1)?)),
        Op::ISub => int(bits(0)?.wrapping_sub(bits(1)?)),
        Op::IMul => int(bits(0)?.wrapping_mul(bits(1)?)),
        Op::UDiv => int(bits(0)?.checked_div(bits(1)?)?),
        Op::SDiv => int(signed(0)?.checked_div(signed(1)?)? as u32),
        Op::UMod => int(bits(0)?.checked_rem(bits(1)?)?),
        Op::SRem => int(signed(0)?.checked_rem(signed(1)?)? as u32),
        Op::SMod => {
            let (a, b) = (signed(0)?, signed(1)?);
            let r = a.checked_rem(b)?;
            int((if r != 0 && (r < 0) != (b < 0) { r + b } else { r }) as u32)
        }
        Op::SNegate => int(bits(0)?.wrapping_neg()),
        Op::Not => int(!bits(0)?),
        Op::ShiftLeftLogical => int(bits(0)? << shift(1)?),
        Op::ShiftRightLogical => int(bits(0)? >> shift(1)?),
        Op::ShiftRightArithmetic => int((signed(0)? >> shift(1)?) as u32),
        Op::BitwiseOr => int(bits(0)? | bits(1)?),
        Op::BitwiseAnd => int(bits(0)? & bits(1)?),
        Op::BitwiseXor => int(bits(0)? ^ bits(1)?),
        // Between 32-bit integers of either signedness: the same bits.
        Op::SConvert | Op::UConvert | Op::Bitcast if result == Scalar::Int => int(bits(0)?),
        Op::IEqual => boolean(bits(0)? == bits(1)?),
        Op::INotEqual => boolean(bits(0)? != bits(1)?),
        Op::ULessThan => boolean(bits(0)? < bits(1)?),
        Op::ULessThanEqual => boolean(bits(0)? <= bits(1)?),
        Op::UGreaterThan => boolean(bits(0)? > bits(1)?),
        Op::UGreaterThanEqual => boolean(bits(0)? >= bits(1)?),
        Op::SLessThan => boolean(signed(0)? < signed(1)?),
        Op::SLessThanEqual => boolean(signed(0)? <= signed(1)?),
        Op::SGreaterThan => boolean(signed(0)? > signed(1)?),
        Op::SGreaterThanEqual => boolean(signed(0)? >= signed(1)?),
        Op::LogicalOr => boolean(truth(0)? || truth(1)?),
        Op::LogicalAnd => boolean(truth(0)? && truth(1)?),
        Op::LogicalNot => boolean(!truth(0)?),
        Op::LogicalEqual => boolean(truth(0)? == truth(1)?),
        Op::LogicalNotEqual => boolean(truth(0)? != truth(1)?),
        Op::Select => {
            if truth(0)? {
                arg(1)
            } else {
                arg(2)
            }
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spec_constant_ops_fold_and_array_lengths_and_local_sizes_become_plain() {
        #[rustfmt::skip]
        let words = vec![
            0x0723_0203, 0x0001_0000, 0, 20, 0,
            (6 << 16) | 331, 9, 38, 3, 3, 4,          // OpExecutionModeId %9 LocalSizeId %3 %3 %4
            (4 << 16) | 71, 3, 1, 0,                  // OpDecorate %3 SpecId 0
            (4 << 16) | 71, 5, 1, 1,                  // OpDecorate %5 SpecId 1
            (4 << 16) | 21, 2, 32, 0,                 // %2 = OpTypeInt 32 0
            (4 << 16) | 50, 2, 3, 64,                 // %3 = OpSpecConstant %2 64
            (4 << 16) | 43, 2, 4, 1,                  // %4 = OpConstant %2 1
            (4 << 16) | 50, 2, 5, 3,                  // %5 = OpSpecConstant %2 3 (an array length)
            (6 << 16) | 52, 2, 6, 132, 3, 5,          // %6 = OpSpecConstantOp %2 IMul %3 %5
            (2 << 16) | 22, 7,                        // %7 = OpTypeFloat… (shortened: a type id)
            (4 << 16) | 28, 8, 7, 6,                  // %8 = OpTypeArray %7 %6
            (4 << 16) | 28, 10, 7, 5,                 // %10 = OpTypeArray %7 %5
            (4 << 16) | 23, 11, 2, 2,                 // %11 = OpTypeVector %2 2
            (5 << 16) | 51, 11, 12, 3, 4,             // %12 = OpSpecConstantComposite %11 %3 %4
            (6 << 16) | 52, 2, 13, 81, 12, 0,         // %13 = OpSpecConstantOp %2 CompositeExtract %12 0
        ];
        let out = spec_constants_naga_reads(words);
        let ops: Vec<(u16, Vec<u32>)> = instructions(&out).map(|(at, op, n)| (op, out[at + 1..at + n].to_vec())).collect();
        assert_eq!(ops[0], (OP_EXECUTION_MODE, vec![9, ExecutionMode::LocalSize as u32, 64, 64, 1]));
        assert!(!ops.iter().any(|(op, w)| *op == OP_DECORATE && w[0] == 3), "%3 is in a composite: plain");
        assert!(!ops.iter().any(|(op, w)| *op == OP_DECORATE && w[0] == 5), "%5 sizes an array: plain");
        assert!(ops.contains(&(OP_CONSTANT, vec![2, 5, 3])));
        assert!(ops.contains(&(OP_CONSTANT, vec![2, 6, 192])), "64 * 3 folded");
        assert!(ops.contains(&(OP_CONSTANT, vec![2, 3, 64])));
        assert!(ops.contains(&(OP_CONSTANT_COMPOSITE, vec![11, 12, 3, 4])));
        assert!(ops.contains(&(OP_CONSTANT, vec![2, 13, 64])), "extracted from the composite");
    }

    #[test]
    fn a_lone_spec_constant_stays_an_override_and_local_size_follows_gl_work_group_size() {
        #[rustfmt::skip]
        let words = vec![
            0x0723_0203, 0x0001_0000, 0, 20, 0,
            (6 << 16) | 16, 9, 17, 1, 1, 1,            // OpExecutionMode %9 LocalSize 1 1 1
            (4 << 16) | 71, 3, 1, 0,                  // OpDecorate %3 SpecId 0
            (4 << 16) | 71, 6, 1, 1,                  // OpDecorate %6 SpecId 1
            (4 << 16) | 71, 5, 11, 25,                // OpDecorate %5 BuiltIn WorkgroupSize
            (4 << 16) | 21, 2, 32, 0,                 // %2 = OpTypeInt 32 0
            (4 << 16) | 23, 4, 2, 3,                  // %4 = OpTypeVector %2 3
            (4 << 16) | 50, 2, 3, 64,                 // %3 = OpSpecConstant %2 64
            (4 << 16) | 43, 2, 7, 1,                  // %7 = OpConstant %2 1
            (6 << 16) | 51, 4, 5, 3, 7, 7,            // %5 = OpSpecConstantComposite %4 %3 %7 %7
            (4 << 16) | 50, 2, 6, 8,                  // %6 = OpSpecConstant %2 8 (used elsewhere only)
        ];
        let out = spec_constants_naga_reads(words);
        let ops: Vec<(u16, Vec<u32>)> = instructions(&out).map(|(at, op, n)| (op, out[at + 1..at + n].to_vec())).collect();
        assert_eq!(ops[0], (OP_EXECUTION_MODE, vec![9, ExecutionMode::LocalSize as u32, 64, 1, 1]));
        assert!(ops.contains(&(OP_DECORATE, vec![6, 1, 1])), "%6 stays an override");
        assert!(ops.contains(&(OP_SPEC_CONSTANT, vec![2, 6, 8])));
    }

    #[test]
    fn the_evaluator_follows_spirv_semantics() {
        let values: HashMap<u32, Value> =
            [(1, Value::Bits(-7i32 as u32)), (2, Value::Bits(2)), (3, Value::Bool(true)), (4, Value::Bits(0))].into_iter().collect();
        let int = Scalar::Int;
        let at = |op: Op, ids: &[u32], t| evaluate(op as u32, ids, t, &values, &HashMap::new());
        assert_eq!(at(Op::SDiv, &[1, 2], int), Some(Value::Bits(-3i32 as u32)));
        assert_eq!(at(Op::SMod, &[1, 2], int), Some(Value::Bits(1)));
        assert_eq!(at(Op::SRem, &[1, 2], int), Some(Value::Bits(-1i32 as u32)));
        assert_eq!(at(Op::ShiftRightArithmetic, &[1, 2], int), Some(Value::Bits(-2i32 as u32)));
        assert_eq!(at(Op::UDiv, &[2, 4], int), None, "division by zero is left to naga");
        assert_eq!(at(Op::SLessThan, &[1, 2], Scalar::Bool), Some(Value::Bool(true)));
        assert_eq!(at(Op::Select, &[3, 2, 4], int), Some(Value::Bits(2)));
        assert_eq!(at(Op::FAdd, &[2, 2], int), None);
    }

    /// SMAA's `vec2(reverseScreenWidth, …)` swizzles: a `VectorShuffle` of a composite of
    /// float specialization constants becomes the composite of the picked components, and a
    /// component extracted from it the constant of its default.
    #[test]
    fn float_composites_shuffle_and_extract() {
        #[rustfmt::skip]
        let words = vec![
            0x0723_0203, 0x0001_0000, 0, 20, 0,
            (3 << 16) | 22, 1, 32,                          // %1 = OpTypeFloat 32
            (4 << 16) | 23, 2, 1, 4,                        // %2 = OpTypeVector %1 4
            (4 << 16) | 23, 3, 1, 2,                        // %3 = OpTypeVector %1 2
            (4 << 16) | 50, 1, 4, 0x3f80_0000,              // %4 = OpSpecConstant %1 1.0
            (4 << 16) | 50, 1, 5, 0x4000_0000,              // %5 = OpSpecConstant %1 2.0
            (7 << 16) | 51, 2, 6, 4, 5, 4, 5,               // %6 = OpSpecConstantComposite %2 %4 %5 %4 %5
            (8 << 16) | 52, 3, 7, 79, 6, 6, 1, 2,           // %7 = OpSpecConstantOp %3 VectorShuffle %6 %6 1 2
            (6 << 16) | 52, 1, 8, 81, 7, 0,                 // %8 = OpSpecConstantOp %1 CompositeExtract %7 0
            (6 << 16) | 52, 1, 9, 128, 4, 5,                // %9 = OpSpecConstantOp %1 FAdd %4 %5 (not folded)
        ];
        let out = spec_constants_naga_reads(words);
        let ops: Vec<(u16, Vec<u32>)> = instructions(&out).skip(3).map(|(at, op, n)| (op, out[at + 1..at + n].to_vec())).collect();
        assert_eq!(ops[2], (OP_CONSTANT_COMPOSITE, vec![2, 6, 4, 5, 4, 5]));
        assert_eq!(ops[3], (OP_CONSTANT_COMPOSITE, vec![3, 7, 5, 4]), "components 1 and 2 of %6");
        assert_eq!(ops[4], (OP_CONSTANT, vec![1, 8, 0x4000_0000]), "the default of %5");
        assert_eq!(ops[5].0, OP_SPEC_CONSTANT_OP, "float arithmetic is left to naga's refusal");
    }
}
