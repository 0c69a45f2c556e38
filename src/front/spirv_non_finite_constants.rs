//! Infinite and NaN float constants made at run time: GLSL folds `1.0 / 0.0` (the
//! `INF` of ray casters and deferred renderers) and `0.0 / 0.0` into constants, glslang
//! writes them as `OpConstant`s, and naga refuses a non-finite literal (WGSL has none: a
//! constant expression that overflows is an error there). In every function that uses such
//! a constant, directly or inside a constant composite, its bits are loaded from a function
//! variable of type `uint` and bitcast to the float: a value no compiler folds, the same
//! bits at run time. Composites holding one are built with `OpCompositeConstruct`; a
//! function variable initialised with one is stored to instead; the constants themselves
//! go (naga declares every constant of the module, used or not). A use outside function
//! bodies (a specialization constant's operation) leaves the module as it was, and naga's
//! refusal names the literal. The lengths change, so this runs before [`Lines`] is taken.
//!
//! [`Lines`]: crate::front::spirv_binary::Lines

use std::collections::{HashMap, HashSet};

use rspirv::binary::Assemble;
use rspirv::dr::{self, Instruction, Operand};
use rspirv::spirv::{Op, StorageClass, Word};

use crate::front::spirv_binary::{instructions, Added};

/// The exponent bits of a 32-bit float: all set in an infinity or a NaN.
const EXPONENT: u32 = 0x7f80_0000;

/// `words` with every non-finite 32-bit float constant of the module doc made at run time.
pub(crate) fn non_finite_constants_at_run_time(words: Vec<u32>) -> Vec<u32> {
    let candidate = |(at, op, count): (usize, u16, usize)| {
        op == Op::Constant as u16 && count == 4 && words.get(at + 3).is_some_and(|b| b & EXPONENT == EXPONENT)
    };
    if !instructions(&words).any(candidate) {
        return words;
    }
    let Ok(mut module) = dr::load_words(&words) else { return words };
    match make_at_run_time(&mut module) {
        Some(()) => module.assemble(),
        None => words,
    }
}

/// A non-finite constant (its float type and bits) or a composite holding one.
enum Value {
    Scalar { ty: Word, bits: u32 },
    Composite { ty: Word, parts: Vec<Word> },
}

/// None where the module has no such constant or cannot be rewritten.
fn make_at_run_time(module: &mut dr::Module) -> Option<()> {
    let values = non_finite_values(module);
    if values.is_empty() {
        return None;
    }
    // A use at module scope (other than by a composite of `values`) cannot be a run-time value.
    let global_use = module
        .types_global_values
        .iter()
        .filter(|i| i.result_id.is_none_or(|r| !values.iter().any(|(v, _)| *v == r)))
        .any(|i| i.operands.iter().any(|o| matches!(o, Operand::IdRef(x) if values.iter().any(|(v, _)| v == x))));
    if global_use {
        return None;
    }
    let mut added = Added::of(module);
    let uint = added.global(module, Op::TypeInt, None, vec![Operand::LiteralBit32(32), Operand::LiteralBit32(0)]);
    let pointer = added.global(module, Op::TypePointer, None, vec![Operand::StorageClass(StorageClass::Function), Operand::IdRef(uint)]);
    for f in 0..module.functions.len() {
        let used = used_in(&module.functions[f], &values);
        if used.is_empty() {
            continue;
        }
        let mut made = Made { added: &mut added, uint, pointer, ids: HashMap::new(), variables: Vec::new(), code: Vec::new() };
        for (id, value) in values.iter().filter(|(id, _)| used.contains(id)) {
            made.make(module, *id, value);
        }
        let Made { ids, variables, mut code, .. } = made;
        let entry = module.functions[f].blocks.first_mut()?;
        // A function variable's initializer must be a constant: it is stored to instead.
        for v in entry.instructions.iter_mut().filter(|i| i.class.opcode == Op::Variable) {
            if let Some(&Operand::IdRef(init)) = v.operands.get(1) {
                if let Some(&value) = ids.get(&init) {
                    v.operands.truncate(1);
                    code.push(Instruction::new(Op::Store, None, None, vec![Operand::IdRef(v.result_id?), Operand::IdRef(value)]));
                }
            }
        }
        for i in module.functions[f].blocks.iter_mut().flat_map(|b| b.instructions.iter_mut()) {
            for o in &mut i.operands {
                if let Operand::IdRef(x) = o {
                    if let Some(&value) = ids.get(x) {
                        *x = value;
                    }
                }
            }
        }
        let entry = &mut module.functions[f].blocks[0].instructions;
        let after_variables = entry.iter().rposition(|i| i.class.opcode == Op::Variable).map_or(0, |p| p + 1);
        entry.splice(after_variables..after_variables, code);
        entry.splice(0..0, variables);
    }
    // Unused now, and naga would still declare (and refuse) them.
    let gone = |i: &Instruction| {
        let named = i.result_id.or_else(|| i.operands.first().and_then(|o| if let Operand::IdRef(x) = o { Some(*x) } else { None }));
        named.is_some_and(|id| values.iter().any(|(v, _)| *v == id))
    };
    module.types_global_values.retain(|i| !gone(i));
    module.debug_names.retain(|i| !gone(i));
    module.annotations.retain(|i| !gone(i));
    added.add_to(module)
}

/// The module's non-finite 32-bit float constants and the constant composites holding
/// one, in declaration order (a composite after its parts).
fn non_finite_values(module: &dr::Module) -> Vec<(Word, Value)> {
    let floats: HashSet<Word> = module
        .types_global_values
        .iter()
        .filter(|i| i.class.opcode == Op::TypeFloat && i.operands.first() == Some(&Operand::LiteralBit32(32)))
        .filter_map(|i| i.result_id)
        .collect();
    let mut values: Vec<(Word, Value)> = Vec::new();
    for i in &module.types_global_values {
        let (Some(r), Some(ty)) = (i.result_id, i.result_type) else { continue };
        match (i.class.opcode, i.operands.first()) {
            (Op::Constant, Some(&Operand::LiteralBit32(bits))) if floats.contains(&ty) && bits & EXPONENT == EXPONENT => {
                values.push((r, Value::Scalar { ty, bits }));
            }
            (Op::ConstantComposite, _) => {
                let parts: Vec<Word> = i.operands.iter().filter_map(|o| if let Operand::IdRef(x) = o { Some(*x) } else { None }).collect();
                if parts.iter().any(|p| values.iter().any(|(v, _)| v == p)) {
                    values.push((r, Value::Composite { ty, parts }));
                }
            }
            _ => {}
        }
    }
    values
}

/// The values a function uses, with every part of a composite it uses.
fn used_in(function: &dr::Function, values: &[(Word, Value)]) -> HashSet<Word> {
    let mut used: HashSet<Word> = function
        .blocks
        .iter()
        .flat_map(|b| b.instructions.iter().flat_map(|i| i.operands.iter()))
        .filter_map(|o| if let Operand::IdRef(x) = o { Some(*x) } else { None })
        .filter(|x| values.iter().any(|(v, _)| v == x))
        .collect();
    // Composites follow their parts: walking back adds every part before it is needed.
    for (id, value) in values.iter().rev() {
        if let (true, Value::Composite { parts, .. }) = (used.contains(id), value) {
            used.extend(parts.iter().copied().filter(|p| values.iter().any(|(v, _)| v == p)));
        }
    }
    used
}

/// The run-time values of one function: the variables holding the bits (first in its
/// entry block), the loads, bitcasts and constructions after its variables, and the id
/// each constant is replaced by.
struct Made<'a> {
    added: &'a mut Added,
    uint: Word,
    pointer: Word,
    ids: HashMap<Word, Word>,
    variables: Vec<Instruction>,
    code: Vec<Instruction>,
}

impl Made<'_> {
    fn make(&mut self, module: &dr::Module, id: Word, value: &Value) {
        let result = self.added.fresh();
        match value {
            Value::Scalar { ty, bits } => {
                let init = self.added.global(module, Op::Constant, Some(self.uint), vec![Operand::LiteralBit32(*bits)]);
                let (variable, loaded) = (self.added.fresh(), self.added.fresh());
                self.variables.push(Instruction::new(
                    Op::Variable,
                    Some(self.pointer),
                    Some(variable),
                    vec![Operand::StorageClass(StorageClass::Function), Operand::IdRef(init)],
                ));
                self.code.push(Instruction::new(Op::Load, Some(self.uint), Some(loaded), vec![Operand::IdRef(variable)]));
                self.code.push(Instruction::new(Op::Bitcast, Some(*ty), Some(result), vec![Operand::IdRef(loaded)]));
            }
            Value::Composite { ty, parts } => {
                let parts = parts.iter().map(|p| Operand::IdRef(*self.ids.get(p).unwrap_or(p))).collect();
                self.code.push(Instruction::new(Op::CompositeConstruct, Some(*ty), Some(result), parts));
            }
        }
        self.ids.insert(id, result);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `%main` stores `vec3(inf, 0, -inf)` and `nan`, and a local is initialised with `inf`.
    fn module() -> Vec<u32> {
        let mut b = rspirv::dr::Builder::new();
        b.capability(rspirv::spirv::Capability::Shader);
        b.memory_model(rspirv::spirv::AddressingModel::Logical, rspirv::spirv::MemoryModel::GLSL450);
        let void = b.type_void();
        let float = b.type_float(32);
        let vec3 = b.type_vector(float, 3);
        let inf = b.constant_bit32(float, 0x7f80_0000);
        let zero = b.constant_bit32(float, 0);
        let minus_inf = b.constant_bit32(float, 0xff80_0000);
        let nan = b.constant_bit32(float, 0x7fc0_0000);
        let far = b.constant_composite(vec3, [inf, zero, minus_inf]);
        let pf = b.type_pointer(None, StorageClass::Private, float);
        let pv = b.type_pointer(None, StorageClass::Private, vec3);
        let fp = b.type_pointer(None, StorageClass::Function, float);
        let g = b.variable(pf, None, StorageClass::Private, None);
        let gv = b.variable(pv, None, StorageClass::Private, None);
        let fty = b.type_function(void, []);
        let main = b.begin_function(void, None, rspirv::spirv::FunctionControl::NONE, fty).unwrap();
        b.begin_block(None).unwrap();
        b.variable(fp, None, StorageClass::Function, Some(inf));
        b.store(gv, far, None, []).unwrap();
        b.store(g, nan, None, []).unwrap();
        b.ret().unwrap();
        b.end_function().unwrap();
        b.entry_point(rspirv::spirv::ExecutionModel::Vertex, main, "main", [g, gv]);
        b.module().assemble()
    }

    #[test]
    fn non_finite_constants_are_bitcast_from_loaded_bits() {
        let out = dr::load_words(non_finite_constants_at_run_time(module())).unwrap();
        let body: Vec<&Instruction> = out.functions[0].blocks[0].instructions.iter().collect();
        let ops: Vec<Op> = body.iter().map(|i| i.class.opcode).collect();
        use Op::*;
        assert_eq!(
            ops,
            [
                Variable,
                Variable,
                Variable,
                Variable,
                Load,
                Bitcast,
                Load,
                Bitcast,
                Load,
                Bitcast,
                CompositeConstruct,
                Store,
                Store,
                Store,
                Return
            ]
        );
        let constant = |id: Word| out.types_global_values.iter().find(|i| i.result_id == Some(id)).map(|i| i.operands.clone());
        let inits: Vec<Option<Vec<Operand>>> = body[..3].iter().map(|v| constant(v.operands[1].unwrap_id_ref())).collect();
        assert_eq!(
            inits,
            [0x7f80_0000, 0xff80_0000, 0x7fc0_0000].map(|b| Some(vec![Operand::LiteralBit32(b)])),
            "the bits of inf, -inf and NaN, as unsigned constants"
        );
        let id = |n: usize| Operand::IdRef(body[n].result_id.unwrap());
        // The composite takes the run-time parts.
        assert_eq!((&body[10].operands[0], &body[10].operands[2]), (&id(5), &id(7)));
        // The local once initialised with inf is stored the run-time inf, after the values.
        assert_eq!(body[3].operands.len(), 1);
        assert_eq!(body[11].operands, [id(3), id(5)]);
        // The stores take the run-time values.
        assert_eq!(body[12].operands[1], id(10));
        assert_eq!(body[13].operands[1], id(9));
    }

    #[test]
    fn finite_modules_are_left_as_they_are() {
        let mut b = rspirv::dr::Builder::new();
        let float = b.type_float(32);
        b.constant_bit32(float, 0x3f80_0000);
        let words = b.module().assemble();
        assert_eq!(non_finite_constants_at_run_time(words.clone()), words);
    }
}
