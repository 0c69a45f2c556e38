//! 64-bit integers (`uint64_t`, `int64_t`: `GL_EXT_shader_explicit_arithmetic_types_int64`,
//! `GL_ARB_gpu_shader_int64`) held as two 32-bit words, low word first, in the SPIR-V naga's
//! SPIR-V front reads: WGSL and WebGPU have no 64-bit integers. Such values are mostly
//! handles and indices a buffer holds (a material's texture index as `uint64_t`), read,
//! compared and narrowed; a `uvec2` has the same size, alignment and stride in every
//! layout, so the buffers keep their offsets.
//!
//! The 64-bit type becomes `uvec2`; its constants the pair of their words. What holds,
//! moves or chooses a value (loads, stores, access chains, composites, `OpSelect`, `OpPhi`,
//! calls, bitwise operations) stays as it is; these become 32-bit arithmetic with the
//! exact 64-bit result:
//! - narrowing (`uint(x)`) takes the low word; widening adds a zero or sign high word;
//! - `==`, `!=`, `<`, `<=`, `>`, `>=` (signed or unsigned) compare the high words, then
//!   the low ones;
//! - `+` and `-` carry from the low word to the high one;
//! - conversion to `float` is `hi · 2³² + lo`.
//!
//! Anything else a 64-bit value takes part in (multiplication, shifts, vectors of 64-bit
//! integers, atomics, a `switch` on one) leaves the module as it was, for naga to refuse.

use std::collections::HashMap;

use rspirv::binary::Assemble;

use crate::front::spirv_binary::{result_types, Added, PerInstruction};
use rspirv::dr::{self, Instruction, Operand};
use rspirv::spirv::{Capability, Op, Word};

/// `words` with its 64-bit integers held in pairs of 32-bit words, as the module doc says;
/// unchanged where it has none, or uses one otherwise.
pub(crate) fn wide_integers_as_pairs(words: Vec<u32>) -> Vec<u32> {
    let Ok(module) = dr::load_words(&words) else { return words };
    let wide = |i: &Instruction| i.class.opcode == Op::TypeInt && i.operands.first() == Some(&Operand::LiteralBit32(64));
    if !module.types_global_values.iter().any(wide) {
        return words;
    }
    Pairs::new(module).and_then(Pairs::run).unwrap_or(words)
}

/// The lowering in progress.
struct Pairs {
    module: dr::Module,
    added: Added,
    /// The 64-bit types, with their signedness.
    wide: HashMap<Word, bool>,
    /// 32-bit `uint`, `int`, `bool`, `bvec2`, `float` (declared where missing).
    uint: Word,
    int: Word,
    boolean: Word,
    bvec2: Word,
    /// Result types of every id with one.
    types: HashMap<Word, Word>,
}

impl Pairs {
    fn new(module: dr::Module) -> Option<Pairs> {
        module.header.as_ref()?;
        let mut p =
            Pairs { added: Added::of(&module), module, wide: HashMap::new(), uint: 0, int: 0, boolean: 0, bvec2: 0, types: HashMap::new() };
        // The 32-bit types first: the pair type is declared from them, before any use.
        let (uint, int) = (p.fresh(), p.fresh());
        let mut globals = vec![
            Instruction::new(Op::TypeInt, None, Some(uint), vec![Operand::LiteralBit32(32), Operand::LiteralBit32(0)]),
            Instruction::new(Op::TypeInt, None, Some(int), vec![Operand::LiteralBit32(32), Operand::LiteralBit32(1)]),
        ];
        (p.uint, p.int) = (uint, int);
        let mut lowered = Vec::new();
        for i in std::mem::take(&mut p.module.types_global_values) {
            match (i.class.opcode, &i.operands[..]) {
                (Op::TypeInt, [Operand::LiteralBit32(64), Operand::LiteralBit32(signed)]) => {
                    let r = i.result_id?;
                    p.wide.insert(r, *signed == 1);
                    lowered.push(Instruction::new(Op::TypeVector, None, Some(r), vec![Operand::IdRef(uint), Operand::LiteralBit32(2)]));
                }
                (Op::TypeVector, [Operand::IdRef(c), _]) if p.wide.contains_key(c) => return None,
                (Op::Constant, [Operand::LiteralBit64(v)]) if i.result_type.is_some_and(|t| p.wide.contains_key(&t)) => {
                    let (lo, hi) = (p.fresh(), p.fresh());
                    lowered.push(Instruction::new(Op::Constant, Some(uint), Some(lo), vec![Operand::LiteralBit32(*v as u32)]));
                    lowered.push(Instruction::new(Op::Constant, Some(uint), Some(hi), vec![Operand::LiteralBit32((*v >> 32) as u32)]));
                    lowered.push(Instruction::new(
                        Op::ConstantComposite,
                        i.result_type,
                        i.result_id,
                        vec![Operand::IdRef(lo), Operand::IdRef(hi)],
                    ));
                }
                (Op::SpecConstant | Op::SpecConstantOp, _) if i.result_type.is_some_and(|t| p.wide.contains_key(&t)) => return None,
                _ => lowered.push(i),
            }
        }
        globals.extend(lowered);
        p.module.types_global_values = globals;
        p.boolean = p.global(Op::TypeBool, vec![]);
        p.bvec2 = p.global(Op::TypeVector, vec![Operand::IdRef(p.boolean), Operand::LiteralBit32(2)]);
        p.types = result_types(&p.module);
        Some(p)
    }

    fn fresh(&mut self) -> Word {
        self.added.fresh()
    }

    /// A type declared once.
    fn global(&mut self, op: Op, operands: Vec<Operand>) -> Word {
        self.added.global(&self.module, op, None, operands)
    }

    fn constant(&mut self, ty: Word, value: u32) -> Word {
        self.added.global(&self.module, Op::Constant, Some(ty), vec![Operand::LiteralBit32(value)])
    }

    /// The signedness of a 64-bit value (None: not one).
    fn wide_value(&self, id: Word) -> Option<bool> {
        self.types.get(&id).and_then(|t| self.wide.get(t)).copied()
    }

    fn run(mut self) -> Option<Vec<u32>> {
        self.each_instruction()?;
        self.added.add_to(&mut self.module)?;
        self.module.capabilities.retain(|c| c.operands.first() != Some(&Operand::Capability(Capability::Int64)));
        if self.module.capabilities.iter().any(|c| c.operands.first() == Some(&Operand::Capability(Capability::Int64Atomics))) {
            return None;
        }
        Some(self.module.assemble())
    }

    /// One instruction of a function, lowered into `out`; None where a 64-bit value takes
    /// part in what this does not lower.
    fn lowered(&mut self, i: Instruction, out: &mut Vec<Instruction>) -> Option<()> {
        let result_wide = i.result_type.and_then(|t| self.wide.get(&t)).copied();
        let wide_operand = i.operands.iter().find_map(|o| match o {
            Operand::IdRef(x) => self.wide_value(*x),
            _ => None,
        });
        if result_wide.is_none() && wide_operand.is_none() {
            out.push(i);
            return Some(());
        }
        let (ty, r) = (i.result_type, i.result_id);
        let ids: Vec<Word> = i.operands.iter().filter_map(|o| if let Operand::IdRef(x) = o { Some(*x) } else { None }).collect();
        match i.class.opcode {
            Op::Load
            | Op::Store
            | Op::AccessChain
            | Op::InBoundsAccessChain
            | Op::CompositeExtract
            | Op::CompositeConstruct
            | Op::CompositeInsert
            | Op::CopyObject
            | Op::Select
            | Op::Phi
            | Op::FunctionCall
            | Op::ReturnValue
            | Op::Variable
            | Op::BitwiseAnd
            | Op::BitwiseOr
            | Op::BitwiseXor
            | Op::Not
            | Op::Undef => out.push(i),
            // Between the 64-bit types, or with a pair of 32-bit words (`packUint2x32`,
            // `unpackUint2x32`): the same pair.
            Op::Bitcast => {
                let other = if result_wide.is_some() { self.types.get(&ids[0]).copied() } else { ty };
                match other.and_then(|t| self.pair_like(t)) {
                    Some(false) => out.push(Instruction::new(Op::CopyObject, ty, r, vec![Operand::IdRef(ids[0])])),
                    Some(true) => out.push(i),
                    None => return None,
                }
            }
            Op::UConvert | Op::SConvert if result_wide.is_none() => {
                self.int_32(ty?)?;
                // Narrowing: the low word, as the result's signedness.
                let lo = self.word(ids[0], 0, out);
                self.as_type(lo, ty?, r?, out);
            }
            Op::UConvert | Op::SConvert => {
                let x = ids[0];
                let signed_operand = self.int_32(*self.types.get(&x)?)?;
                let low = if signed_operand { self.op(Op::Bitcast, self.uint, &[x], out) } else { x };
                let high = if i.class.opcode == Op::SConvert {
                    let signed = if signed_operand { x } else { self.op(Op::Bitcast, self.int, &[x], out) };
                    let c31 = self.constant(self.uint, 31);
                    let sign = self.op(Op::ShiftRightArithmetic, self.int, &[signed, c31], out);
                    self.op(Op::Bitcast, self.uint, &[sign], out)
                } else {
                    self.constant(self.uint, 0)
                };
                out.push(Instruction::new(Op::CompositeConstruct, ty, r, vec![Operand::IdRef(low), Operand::IdRef(high)]));
            }
            Op::ConvertUToF | Op::ConvertSToF => {
                let (lo, hi) = (self.word(ids[0], 0, out), self.word(ids[0], 1, out));
                let float = ty?;
                let flo = self.op(Op::ConvertUToF, float, &[lo], out);
                let fhi = if wide_operand == Some(true) {
                    let shi = self.op(Op::Bitcast, self.int, &[hi], out);
                    self.op(Op::ConvertSToF, float, &[shi], out)
                } else {
                    self.op(Op::ConvertUToF, float, &[hi], out)
                };
                let scale = self.float_constant(float, 4_294_967_296.0)?;
                let high = self.op(Op::FMul, float, &[fhi, scale], out);
                out.push(Instruction::new(Op::FAdd, ty, r, vec![Operand::IdRef(high), Operand::IdRef(flo)]));
            }
            Op::IEqual | Op::INotEqual => {
                let (each, fold) = if i.class.opcode == Op::IEqual { (Op::IEqual, Op::All) } else { (Op::INotEqual, Op::Any) };
                let words = self.op(each, self.bvec2, &[ids[0], ids[1]], out);
                out.push(Instruction::new(fold, ty, r, vec![Operand::IdRef(words)]));
            }
            op @ (Op::ULessThan
            | Op::ULessThanEqual
            | Op::UGreaterThan
            | Op::UGreaterThanEqual
            | Op::SLessThan
            | Op::SLessThanEqual
            | Op::SGreaterThan
            | Op::SGreaterThanEqual) => self.ordered(op, ids[0], ids[1], ty?, r?, out),
            op @ (Op::IAdd | Op::ISub) => {
                let (alo, ahi, blo, bhi) =
                    (self.word(ids[0], 0, out), self.word(ids[0], 1, out), self.word(ids[1], 0, out), self.word(ids[1], 1, out));
                let lo = self.op(op, self.uint, &[alo, blo], out);
                // The carry out of the low word (a sum below an addend), or the borrow.
                let carried = if op == Op::IAdd {
                    self.op(Op::ULessThan, self.boolean, &[lo, alo], out)
                } else {
                    self.op(Op::ULessThan, self.boolean, &[alo, blo], out)
                };
                let (one, zero) = (self.constant(self.uint, 1), self.constant(self.uint, 0));
                let carry = self.op(Op::Select, self.uint, &[carried, one, zero], out);
                let hi = self.op(op, self.uint, &[ahi, bhi], out);
                let hi = self.op(op, self.uint, &[hi, carry], out);
                out.push(Instruction::new(Op::CompositeConstruct, ty, r, vec![Operand::IdRef(lo), Operand::IdRef(hi)]));
            }
            _ => return None,
        }
        Some(())
    }

    /// `a op b` for an ordering of 64-bit values: by the high words (signed for a signed
    /// comparison), and by the low words (unsigned) where those are equal.
    fn ordered(&mut self, op: Op, a: Word, b: Word, ty: Word, r: Word, out: &mut Vec<Instruction>) {
        let signed = matches!(op, Op::SLessThan | Op::SLessThanEqual | Op::SGreaterThan | Op::SGreaterThanEqual);
        let (strict, low) = match op {
            Op::ULessThan | Op::SLessThan => (Op::ULessThan, Op::ULessThan),
            Op::ULessThanEqual | Op::SLessThanEqual => (Op::ULessThan, Op::ULessThanEqual),
            Op::UGreaterThan | Op::SGreaterThan => (Op::UGreaterThan, Op::UGreaterThan),
            _ => (Op::UGreaterThan, Op::UGreaterThanEqual),
        };
        let (alo, ahi, blo, bhi) = (self.word(a, 0, out), self.word(a, 1, out), self.word(b, 0, out), self.word(b, 1, out));
        let high = if signed {
            let (sa, sb) = (self.op(Op::Bitcast, self.int, &[ahi], out), self.op(Op::Bitcast, self.int, &[bhi], out));
            let strict = if strict == Op::ULessThan { Op::SLessThan } else { Op::SGreaterThan };
            self.op(strict, self.boolean, &[sa, sb], out)
        } else {
            self.op(strict, self.boolean, &[ahi, bhi], out)
        };
        let same_high = self.op(Op::IEqual, self.boolean, &[ahi, bhi], out);
        let low = self.op(low, self.boolean, &[alo, blo], out);
        let by_low = self.op(Op::LogicalAnd, self.boolean, &[same_high, low], out);
        out.push(Instruction::new(Op::LogicalOr, Some(ty), Some(r), vec![Operand::IdRef(high), Operand::IdRef(by_low)]));
    }

    /// Word `k` (0 low, 1 high) of a 64-bit value, as `uint`.
    fn word(&mut self, pair: Word, k: u32, out: &mut Vec<Instruction>) -> Word {
        let r = self.fresh();
        out.push(Instruction::new(Op::CompositeExtract, Some(self.uint), Some(r), vec![Operand::IdRef(pair), Operand::LiteralBit32(k)]));
        r
    }

    /// `op` on `operands`, of type `ty`: its new id.
    fn op(&mut self, op: Op, ty: Word, operands: &[Word], out: &mut Vec<Instruction>) -> Word {
        let r = self.fresh();
        out.push(Instruction::new(op, Some(ty), Some(r), operands.iter().map(|x| Operand::IdRef(*x)).collect()));
        r
    }

    /// `value` (a `uint`) as `ty` (a 32-bit integer type), under id `r`.
    fn as_type(&mut self, value: Word, ty: Word, r: Word, out: &mut Vec<Instruction>) {
        let op = if self.int_32(ty) == Some(true) { Op::Bitcast } else { Op::CopyObject };
        out.push(Instruction::new(op, Some(ty), Some(r), vec![Operand::IdRef(value)]));
    }

    /// Some(signed) for a 32-bit integer type, None for the others.
    fn int_32(&self, ty: Word) -> Option<bool> {
        let i = self.module.types_global_values.iter().find(|i| i.result_id == Some(ty) && i.class.opcode == Op::TypeInt)?;
        match i.operands[..] {
            [Operand::LiteralBit32(32), Operand::LiteralBit32(signed)] => Some(signed == 1),
            _ => None,
        }
    }

    /// What a bitcast between `ty` and a 64-bit value is: Some(false) for the same pair (a
    /// 64-bit type, `uvec2`), Some(true) for a reinterpretation of it (`ivec2`), None for
    /// one this does not lower (`double`).
    fn pair_like(&self, ty: Word) -> Option<bool> {
        if self.wide.contains_key(&ty) {
            return Some(false);
        }
        let v = self.module.types_global_values.iter().find(|i| i.result_id == Some(ty) && i.class.opcode == Op::TypeVector)?;
        match v.operands[..] {
            [Operand::IdRef(c), Operand::LiteralBit32(2)] => self.int_32(c),
            _ => None,
        }
    }

    /// A 32-bit float constant of `ty` (None for another float width).
    fn float_constant(&mut self, ty: Word, value: f32) -> Option<Word> {
        let is_f32 = self
            .module
            .types_global_values
            .iter()
            .any(|i| i.result_id == Some(ty) && i.operands.first() == Some(&Operand::LiteralBit32(32)));
        is_f32.then(|| self.constant(ty, value.to_bits()))
    }
}

impl PerInstruction for Pairs {
    fn module_mut(&mut self) -> &mut dr::Module {
        &mut self.module
    }

    fn instruction(&mut self, i: Instruction, out: &mut Vec<Instruction>) -> Option<()> {
        self.lowered(i, out)
    }
}
