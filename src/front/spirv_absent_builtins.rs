//! Built-in inputs WebGPU has no counterpart of, as the constants they hold in effectc's
//! own draws, in the SPIR-V naga's SPIR-V front reads (naga's WGSL writer refuses them):
//! - `gl_PointCoord` is (0.5, 0.5), as the GLSL route's rewrite reads it (N0104): WebGPU
//!   draws points one pixel wide, and the centre of a one-pixel point is where GL's
//!   coordinate is;
//! - the draw parameters `gl_BaseVertex`, `gl_BaseInstance` and `gl_DrawID` are 0: effectc
//!   draws once, from vertex and instance 0 (WGSL's `vertex_index` and `instance_index`
//!   already count from the draw's bases), as the GLSL route's uniform members of them
//!   default to;
//! - `gl_ViewIndex` is 0: effectc draws one view;
//! - `gl_SubgroupSize` is 1, `gl_SubgroupInvocationID` 0, and the masks those of the one
//!   invocation of a subgroup (`gl_SubgroupEqMask`, `…Ge…`, `…Le…` bit 0; `…Gt…`, `…Lt…`
//!   none), `gl_NumSubgroups` the workgroup's invocations and `gl_SubgroupID` the local
//!   invocation index, as [`spirv_subgroups`](crate::front::spirv_subgroups) computes the
//!   operations.
//!
//! Each input variable decorated with one of those built-ins becomes a private variable
//! initialised to its value, and every whole load of it the value itself: its decoration
//! goes, and so does its place in the entry point's interface, with the extension and
//! capability that declared it. The lengths change, so this runs before [`Lines`] is taken.
//!
//! [`Lines`]: crate::front::spirv_binary::Lines

use std::collections::HashMap;

use rspirv::binary::Assemble;
use rspirv::dr::{self, Instruction, Operand};
use rspirv::spirv::{BuiltIn, Capability, Decoration, Op, StorageClass, Word};

/// Extensions and capabilities that only declare the built-ins made constant here.
const EXTENSIONS: [&str; 2] = ["SPV_KHR_shader_draw_parameters", "SPV_KHR_multiview"];
const CAPABILITIES: [Capability; 2] = [Capability::DrawParameters, Capability::MultiView];

/// `words` with the module doc's built-ins read as constants.
pub(crate) fn absent_builtins_as_constants(words: Vec<u32>) -> Vec<u32> {
    let Ok(mut module) = dr::load_words(&words) else { return words };
    let absent: Vec<(Word, BuiltIn)> = module
        .annotations
        .iter()
        .filter_map(|a| match (a.class.opcode, &a.operands[..]) {
            (Op::Decorate, [Operand::IdRef(v), Operand::Decoration(Decoration::BuiltIn), Operand::BuiltIn(b)])
                if value_of(*b).is_some() =>
            {
                Some((*v, *b))
            }
            _ => None,
        })
        .collect();
    if absent.is_empty() {
        return words;
    }
    let Some(mut bound) = module.header.as_ref().map(|h| h.bound) else { return words };
    let invocations = workgroup_invocations(&module);
    let mut absent = absent;
    // `gl_SubgroupID` of a subgroup of one is the invocation's own index in the workgroup.
    if let Some(&(subgroup_id, _)) = absent.iter().find(|(_, b)| *b == BuiltIn::SubgroupId) {
        let index = decorated_builtin(&module, BuiltIn::LocalInvocationIndex);
        match index {
            Some(index) => {
                for i in module.functions.iter_mut().flat_map(|f| f.blocks.iter_mut().flat_map(|b| b.instructions.iter_mut())) {
                    for o in &mut i.operands {
                        if *o == Operand::IdRef(subgroup_id) {
                            *o = Operand::IdRef(index);
                        }
                    }
                }
                module.types_global_values.retain(|i| i.result_id != Some(subgroup_id));
            }
            None => {
                for a in &mut module.annotations {
                    if a.operands.first() == Some(&Operand::IdRef(subgroup_id))
                        && a.operands.get(2) == Some(&Operand::BuiltIn(BuiltIn::SubgroupId))
                    {
                        a.operands[2] = Operand::BuiltIn(BuiltIn::LocalInvocationIndex);
                    }
                }
                absent.retain(|(v, _)| *v != subgroup_id);
            }
        }
    }
    let mut values: HashMap<Word, Word> = HashMap::new();
    for &(variable, builtin) in &absent {
        if builtin == BuiltIn::SubgroupId {
            continue;
        }
        let Some(at) = module.types_global_values.iter().position(|i| i.result_id == Some(variable)) else { return words };
        let Some(pointee) = pointee(&module, module.types_global_values[at].result_type) else { return words };
        let mut declared = Vec::new();
        let mut fresh = || {
            bound += 1;
            bound - 1
        };
        let value = fresh();
        // A vector of `n` components: the first `bits`, the others too (`fill`) or zero.
        let mut vector = |declared: &mut Vec<Instruction>, bits: u32, n: usize, fill: bool| -> Option<()> {
            let component = component_type(&module, pointee)?;
            let (x, zero) = (fresh(), fresh());
            declared.push(Instruction::new(Op::Constant, Some(component), Some(x), vec![Operand::LiteralBit32(bits)]));
            declared.push(Instruction::new(Op::ConstantNull, Some(component), Some(zero), vec![]));
            let mut parts = vec![Operand::IdRef(x)];
            parts.resize(n, Operand::IdRef(if fill { x } else { zero }));
            declared.push(Instruction::new(Op::ConstantComposite, Some(pointee), Some(value), parts));
            Some(())
        };
        let made = match value_of(builtin) {
            Some(Value::Centre) => vector(&mut declared, 0.5f32.to_bits(), 2, true),
            Some(Value::FirstBit) => vector(&mut declared, 1, 4, false),
            Some(Value::One) => {
                declared.push(Instruction::new(Op::Constant, Some(pointee), Some(value), vec![Operand::LiteralBit32(1)]));
                Some(())
            }
            Some(Value::Invocations) => invocations.map(|n| {
                declared.push(Instruction::new(Op::Constant, Some(pointee), Some(value), vec![Operand::LiteralBit32(n)]));
            }),
            _ => {
                declared.push(Instruction::new(Op::ConstantNull, Some(pointee), Some(value), vec![]));
                Some(())
            }
        };
        if made.is_none() {
            return words;
        }
        let private = fresh();
        declared.push(Instruction::new(
            Op::TypePointer,
            None,
            Some(private),
            vec![Operand::StorageClass(StorageClass::Private), Operand::IdRef(pointee)],
        ));
        declared.push(Instruction::new(
            Op::Variable,
            Some(private),
            Some(variable),
            vec![Operand::StorageClass(StorageClass::Private), Operand::IdRef(value)],
        ));
        module.types_global_values.splice(at..=at, declared);
        values.insert(variable, value);
    }
    loads_as_constants(&mut module, &values);
    let is_absent = |o: Option<&Operand>| matches!(o, Some(Operand::IdRef(v)) if absent.iter().any(|(a, _)| a == v));
    module.annotations.retain(|a| !is_absent(a.operands.first()));
    for ep in &mut module.entry_points {
        let keep: Vec<Operand> = ep.operands.iter().filter(|o| !is_absent(Some(o))).cloned().collect();
        ep.operands = keep;
    }
    module.extensions.retain(|e| !matches!(e.operands.first(), Some(Operand::LiteralString(s)) if EXTENSIONS.contains(&s.as_str())));
    module.capabilities.retain(|c| !matches!(c.operands.first(), Some(Operand::Capability(c)) if CAPABILITIES.contains(c)));
    if let Some(h) = module.header.as_mut() {
        h.bound = bound;
    }
    module.assemble()
}

/// What a built-in WebGPU lacks holds in effectc's draws.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Value {
    Zero,
    One,
    /// (0.5, 0.5).
    Centre,
    /// `uvec4(1, 0, 0, 0)`: the one invocation of a subgroup of one.
    FirstBit,
    /// The workgroup's invocations: `gl_NumSubgroups` of subgroups of one.
    Invocations,
}

fn value_of(b: BuiltIn) -> Option<Value> {
    Some(match b {
        BuiltIn::PointCoord => Value::Centre,
        BuiltIn::BaseVertex | BuiltIn::BaseInstance | BuiltIn::DrawIndex | BuiltIn::ViewIndex => Value::Zero,
        // A subgroup of one invocation (`spirv_subgroups`).
        BuiltIn::SubgroupSize => Value::One,
        BuiltIn::SubgroupLocalInvocationId | BuiltIn::SubgroupGtMask | BuiltIn::SubgroupLtMask => Value::Zero,
        BuiltIn::SubgroupEqMask | BuiltIn::SubgroupGeMask | BuiltIn::SubgroupLeMask => Value::FirstBit,
        BuiltIn::NumSubgroups => Value::Invocations,
        // The local invocation index (read from that built-in, not made constant).
        BuiltIn::SubgroupId => Value::Zero,
        _ => return None,
    })
}

/// Every whole load of a variable of `values` (variable → its constant value) replaced by
/// the constant itself: a constant is uniform where tint's analysis takes every load of a
/// private variable for a value that may differ between invocations (a barrier after a
/// branch on `gl_SubgroupSize`). Loads through an access chain keep the variable.
fn loads_as_constants(module: &mut dr::Module, values: &HashMap<Word, Word>) {
    let mut same: HashMap<Word, Word> = HashMap::new();
    for b in module.functions.iter_mut().flat_map(|f| f.blocks.iter_mut()) {
        b.instructions.retain(|i| match (i.class.opcode, i.result_id, i.operands.first()) {
            (Op::Load, Some(r), Some(Operand::IdRef(v))) if values.contains_key(v) => {
                same.insert(r, values[v]);
                false
            }
            _ => true,
        });
    }
    for i in module.functions.iter_mut().flat_map(|f| f.blocks.iter_mut().flat_map(|b| b.instructions.iter_mut())) {
        for o in &mut i.operands {
            if let Some(c) = if let Operand::IdRef(x) = o { same.get(x) } else { None } {
                *o = Operand::IdRef(*c);
            }
        }
    }
}

/// The number of invocations of a workgroup (`LocalSize`'s product), for a compute stage.
fn workgroup_invocations(module: &dr::Module) -> Option<u32> {
    let mode = module
        .execution_modes
        .iter()
        .find(|m| m.operands.get(1) == Some(&Operand::ExecutionMode(rspirv::spirv::ExecutionMode::LocalSize)))?;
    mode.operands[2..].iter().map(|o| if let Operand::LiteralBit32(n) = o { Some(*n) } else { None }).product()
}

/// The variable decorated as built-in `b`.
fn decorated_builtin(module: &dr::Module, b: BuiltIn) -> Option<Word> {
    module.annotations.iter().find_map(|a| match &a.operands[..] {
        [Operand::IdRef(v), Operand::Decoration(Decoration::BuiltIn), Operand::BuiltIn(x)] if *x == b => Some(*v),
        _ => None,
    })
}

/// The type a pointer type points to.
fn pointee(module: &dr::Module, pointer: Option<Word>) -> Option<Word> {
    let p = module.types_global_values.iter().find(|i| pointer.is_some() && i.result_id == pointer)?;
    match p.operands[..] {
        [Operand::StorageClass(_), Operand::IdRef(t)] => Some(t),
        _ => None,
    }
}

/// A vector type's component type.
fn component_type(module: &dr::Module, vector: Word) -> Option<Word> {
    let v = module.types_global_values.iter().find(|i| i.result_id == Some(vector) && i.class.opcode == Op::TypeVector)?;
    match v.operands.first() {
        Some(Operand::IdRef(t)) => Some(*t),
        _ => None,
    }
}
