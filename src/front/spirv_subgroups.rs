//! Subgroup operations (`GL_KHR_shader_subgroup_*`) computed for subgroups of one
//! invocation, in the SPIR-V naga's SPIR-V front reads: WGSL has subgroups only behind an
//! extension (`enable subgroups;`) that naga's WGSL front does not take, so no WGSL with
//! them is valid for both. A subgroup size of 1 is one Vulkan allows (a power of two, at
//! least 1), so every result below is one a conforming device could give:
//! - `subgroupElect()` and `subgroupAllEqual(x)` are true; `subgroupAll(p)`, `subgroupAny(p)`
//!   are `p`;
//! - broadcasts, shuffles, quad operations and every reduction or inclusive scan
//!   (`subgroupAdd`, `subgroupMin`, `subgroupOr`, …, clustered too) are the invocation's own
//!   value; an exclusive scan is the operation's identity (0, 1, the type's extreme, all
//!   bits);
//! - `subgroupBallot(p)` is `uvec4(p ? 1 : 0, 0, 0, 0)`; bit counts and bit tests read its
//!   bit 0 (0 for an exclusive count); `subgroupBallotFindLSB/MSB` are 0;
//! - `subgroupBarrier()` and subgroup-scope memory barriers have nothing to wait for.
//!
//! The built-ins (`gl_SubgroupSize` 1, `gl_SubgroupInvocationID` 0, the masks) are
//! [`spirv_absent_builtins`](crate::front::spirv_absent_builtins)'. An operation not listed
//! (partitioned, non-uniform across a cluster size the module computes) leaves the module
//! as it was, for naga to refuse.

use std::collections::HashMap;

use rspirv::binary::Assemble;

use crate::front::spirv_binary::{Added, PerInstruction};
use rspirv::dr::{self, Instruction, Operand};
use rspirv::spirv::{Capability, GroupOperation, Op, Scope, Word};

/// `words` with its subgroup operations computed for a subgroup of one invocation.
pub(crate) fn subgroups_of_one(words: Vec<u32>) -> Vec<u32> {
    let Ok(module) = dr::load_words(&words) else { return words };
    let group = |i: &Instruction| (Op::GroupNonUniformElect as u32..=Op::GroupNonUniformQuadSwap as u32).contains(&(i.class.opcode as u32));
    let has = module.functions.iter().flat_map(|f| f.blocks.iter().flat_map(|b| b.instructions.iter())).any(group);
    let barrier = module
        .functions
        .iter()
        .flat_map(|f| f.blocks.iter().flat_map(|b| b.instructions.iter()))
        .any(|i| matches!(i.class.opcode, Op::ControlBarrier | Op::MemoryBarrier));
    if !has && !barrier {
        return words;
    }
    One::new(module).and_then(One::run).unwrap_or(words)
}

struct One {
    module: dr::Module,
    added: Added,
    /// Ids a result stands for (the invocation's own value, a constant).
    same: HashMap<Word, Word>,
    changed: bool,
}

impl One {
    fn new(module: dr::Module) -> Option<One> {
        module.header.as_ref()?;
        Some(One { added: Added::of(&module), module, same: HashMap::new(), changed: false })
    }

    fn fresh(&mut self) -> Word {
        self.added.fresh()
    }

    fn def(&self, id: Word) -> Option<&Instruction> {
        self.added.def(&self.module, id)
    }

    fn global(&mut self, op: Op, ty: Option<Word>, operands: Vec<Operand>) -> Word {
        self.added.global(&self.module, op, ty, operands)
    }

    /// The value of a 32-bit integer constant (scopes are given as constants).
    fn constant_value(&self, id: Word) -> Option<u32> {
        let i = self.def(id).filter(|i| i.class.opcode == Op::Constant)?;
        match i.operands.first() {
            Some(Operand::LiteralBit32(v)) => Some(*v),
            _ => None,
        }
    }

    fn run(mut self) -> Option<Vec<u32>> {
        self.each_instruction()?;
        if !self.changed {
            return None;
        }
        let same = std::mem::take(&mut self.same);
        let resolve = |mut x: Word| {
            while let Some(y) = same.get(&x) {
                x = *y;
            }
            x
        };
        for i in self.module.functions.iter_mut().flat_map(|f| f.blocks.iter_mut().flat_map(|b| b.instructions.iter_mut())) {
            for o in &mut i.operands {
                if let Operand::IdRef(x) = o {
                    *x = resolve(*x);
                }
            }
        }
        let gone: Vec<Word> = same.keys().copied().collect();
        self.module.annotations.retain(|a| !matches!(a.operands.first(), Some(Operand::IdRef(t)) if gone.contains(t)));
        self.added.add_to(&mut self.module)?;
        self.module.capabilities.retain(|c| {
            !matches!(
                c.operands.first(),
                Some(Operand::Capability(
                    Capability::GroupNonUniform
                        | Capability::GroupNonUniformVote
                        | Capability::GroupNonUniformArithmetic
                        | Capability::GroupNonUniformBallot
                        | Capability::GroupNonUniformShuffle
                        | Capability::GroupNonUniformShuffleRelative
                        | Capability::GroupNonUniformClustered
                        | Capability::GroupNonUniformQuad
                ))
            )
        });
        Some(self.module.assemble())
    }

    /// One instruction, lowered into `out` (nothing where its result stands for another id).
    fn lowered(&mut self, i: Instruction, out: &mut Vec<Instruction>) -> Option<()> {
        let op = i.class.opcode;
        let ids: Vec<Word> = i.operands.iter().filter_map(|o| if let Operand::IdRef(x) = o { Some(*x) } else { None }).collect();
        let group_op = i.operands.iter().find_map(|o| if let Operand::GroupOperation(g) = o { Some(*g) } else { None });
        // The execution scope (an id operand of its own kind): ids are the other operands.
        let scope = i.operands.iter().find_map(|o| if let Operand::IdScope(x) = o { Some(*x) } else { None });
        let subgroup = scope.and_then(|s| self.constant_value(s)) == Some(Scope::Subgroup as u32);
        let (ty, r) = (i.result_type, i.result_id);
        match op {
            // A barrier among the invocations of a subgroup of one waits for nothing.
            Op::ControlBarrier if subgroup => {}
            Op::MemoryBarrier if subgroup => {}
            Op::ControlBarrier | Op::MemoryBarrier => {
                out.push(i);
                return Some(());
            }
            _ if !(Op::GroupNonUniformElect as u32..=Op::GroupNonUniformQuadSwap as u32).contains(&(op as u32)) => {
                out.push(i);
                return Some(());
            }
            _ if !subgroup => return None,
            Op::GroupNonUniformElect | Op::GroupNonUniformAllEqual => {
                let t = self.global(Op::ConstantTrue, ty, vec![]);
                self.same.insert(r?, t);
            }
            Op::GroupNonUniformAll
            | Op::GroupNonUniformAny
            | Op::GroupNonUniformBroadcast
            | Op::GroupNonUniformBroadcastFirst
            | Op::GroupNonUniformShuffle
            | Op::GroupNonUniformShuffleXor
            | Op::GroupNonUniformShuffleUp
            | Op::GroupNonUniformShuffleDown
            | Op::GroupNonUniformQuadBroadcast
            | Op::GroupNonUniformQuadSwap => {
                self.same.insert(r?, *ids.first()?);
            }
            Op::GroupNonUniformBallot => {
                let uvec4 = ty?;
                let uint = self.component(uvec4)?;
                let (one, zero) = (
                    self.global(Op::Constant, Some(uint), vec![Operand::LiteralBit32(1)]),
                    self.global(Op::Constant, Some(uint), vec![Operand::LiteralBit32(0)]),
                );
                let bit = self.fresh();
                out.push(Instruction::new(
                    Op::Select,
                    Some(uint),
                    Some(bit),
                    vec![Operand::IdRef(*ids.first()?), Operand::IdRef(one), Operand::IdRef(zero)],
                ));
                let words = [bit, zero, zero, zero].map(Operand::IdRef).to_vec();
                out.push(Instruction::new(Op::CompositeConstruct, ty, r, words));
            }
            Op::GroupNonUniformInverseBallot | Op::GroupNonUniformBallotBitExtract => {
                let bit = self.bit_zero(*ids.first()?, out)?;
                let uint = self.uint();
                let one = self.global(Op::Constant, Some(uint), vec![Operand::LiteralBit32(1)]);
                out.push(Instruction::new(Op::IEqual, ty, r, vec![Operand::IdRef(bit), Operand::IdRef(one)]));
            }
            Op::GroupNonUniformBallotBitCount => match group_op? {
                GroupOperation::ExclusiveScan => {
                    let zero = self.global(Op::Constant, ty, vec![Operand::LiteralBit32(0)]);
                    self.same.insert(r?, zero);
                }
                _ => {
                    let bit = self.bit_zero(*ids.first()?, out)?;
                    out.push(Instruction::new(Op::CopyObject, ty, r, vec![Operand::IdRef(bit)]));
                }
            },
            Op::GroupNonUniformBallotFindLSB | Op::GroupNonUniformBallotFindMSB => {
                let zero = self.global(Op::Constant, ty, vec![Operand::LiteralBit32(0)]);
                self.same.insert(r?, zero);
            }
            _ => match group_op? {
                GroupOperation::Reduce | GroupOperation::InclusiveScan | GroupOperation::ClusteredReduce => {
                    self.same.insert(r?, *ids.first()?);
                }
                GroupOperation::ExclusiveScan => {
                    let identity = self.identity(op, ty?)?;
                    self.same.insert(r?, identity);
                }
                _ => return None,
            },
        }
        self.changed = true;
        Some(())
    }

    /// Component type of a vector type.
    fn component(&self, vector: Word) -> Option<Word> {
        match self.def(vector)?.operands.first() {
            Some(Operand::IdRef(c)) => Some(*c),
            _ => None,
        }
    }

    /// 32-bit `uint`, the type of a ballot's words (declared wherever a ballot is).
    fn uint(&mut self) -> Word {
        self.global(Op::TypeInt, None, vec![Operand::LiteralBit32(32), Operand::LiteralBit32(0)])
    }

    /// Bit 0 of a ballot's first word (the one invocation's bit), as `uint`.
    fn bit_zero(&mut self, ballot: Word, out: &mut Vec<Instruction>) -> Option<Word> {
        let uint = self.uint();
        let one = self.global(Op::Constant, Some(uint), vec![Operand::LiteralBit32(1)]);
        let (word, bit) = (self.fresh(), self.fresh());
        out.push(Instruction::new(Op::CompositeExtract, Some(uint), Some(word), vec![Operand::IdRef(ballot), Operand::LiteralBit32(0)]));
        out.push(Instruction::new(Op::BitwiseAnd, Some(uint), Some(bit), vec![Operand::IdRef(word), Operand::IdRef(one)]));
        Some(bit)
    }

    /// The identity of a subgroup arithmetic operation on `ty` (a scalar or a vector of
    /// 32-bit numbers or booleans): what an exclusive scan gives the first invocation.
    fn identity(&mut self, op: Op, ty: Word) -> Option<Word> {
        let t = self.def(ty)?.clone();
        if t.class.opcode == Op::TypeVector {
            let (Some(Operand::IdRef(c)), Some(Operand::LiteralBit32(n))) = (t.operands.first(), t.operands.get(1)) else { return None };
            let scalar = self.identity(op, *c)?;
            return Some(self.global(Op::ConstantComposite, Some(ty), vec![Operand::IdRef(scalar); *n as usize]));
        }
        if t.class.opcode == Op::TypeBool {
            let value = matches!(op, Op::GroupNonUniformLogicalAnd);
            return Some(self.global(if value { Op::ConstantTrue } else { Op::ConstantFalse }, Some(ty), vec![]));
        }
        if t.operands.first() != Some(&Operand::LiteralBit32(32)) {
            return None;
        }
        let bits: u32 = match op {
            Op::GroupNonUniformIAdd | Op::GroupNonUniformBitwiseOr | Op::GroupNonUniformBitwiseXor | Op::GroupNonUniformUMax => 0,
            Op::GroupNonUniformFAdd => 0f32.to_bits(),
            Op::GroupNonUniformIMul => 1,
            Op::GroupNonUniformFMul => 1f32.to_bits(),
            Op::GroupNonUniformSMin => i32::MAX as u32,
            Op::GroupNonUniformUMin | Op::GroupNonUniformBitwiseAnd => u32::MAX,
            Op::GroupNonUniformFMin => f32::INFINITY.to_bits(),
            Op::GroupNonUniformSMax => i32::MIN as u32,
            Op::GroupNonUniformFMax => f32::NEG_INFINITY.to_bits(),
            _ => return None,
        };
        Some(self.global(Op::Constant, Some(ty), vec![Operand::LiteralBit32(bits)]))
    }
}

impl PerInstruction for One {
    fn module_mut(&mut self) -> &mut dr::Module {
        &mut self.module
    }

    fn instruction(&mut self, i: Instruction, out: &mut Vec<Instruction>) -> Option<()> {
        self.lowered(i, out)
    }
}
