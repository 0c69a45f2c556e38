//! Interface blocks between stages (`out VS_OUT { vec3 n; vec2 uv; } vs_out;`) split into
//! one SPIR-V variable per member before naga's SPIR-V front reads a stage. naga takes a
//! stage input only as a variable with a location of its own, and it reads an output block
//! whose location is the block's (as glslang writes GLSL's blocks) as a struct whose members
//! have none, so it passes nothing on. Each member becomes a variable with the location GL
//! gives it (the block's location, counted on member by member, unless the member names its
//! own), the block's interpolation and its own, and the member's name; every access chain
//! into the block starts from the member's variable instead. Arrays of blocks (geometry and
//! tessellation inputs, `out B {..} b[2];`) and the built-in block `gl_PerVertex` stay.

use std::collections::{HashMap, HashSet};

use rspirv::binary::Assemble;
use rspirv::dr::{self, Instruction, Operand};
use rspirv::spirv::{Decoration, Op, StorageClass, Word};

use crate::front::spirv_binary::{instructions, OP_DECORATE, OP_TYPE_POINTER};

/// `words` with every input and output block variable split into its members; the words as
/// they were when there is none, or when a block is used other than through access chains
/// into a member.
pub fn split_interface_blocks(words: Vec<u32>) -> Vec<u32> {
    if !has_interface_block(&words) {
        return words;
    }
    let Ok(mut module) = dr::load_words(&words) else { return words };
    let blocks = Blocks::of(&module);
    let variables = blocks.variables(&module);
    if variables.is_empty() {
        return words;
    }
    for var in &variables {
        if split(&mut module, &blocks, var).is_none() {
            return words;
        }
    }
    module.assemble()
}

/// Whether some input or output pointer type points at a `Block`-decorated struct: the
/// words are only loaded as a module then.
fn has_interface_block(words: &[u32]) -> bool {
    let block = Decoration::Block as u32;
    let mut blocks = HashSet::new();
    for (at, op, count) in instructions(words) {
        let operands = words.get(at + 1..at + count).unwrap_or(&[]);
        match op {
            OP_DECORATE if operands.get(1) == Some(&block) => {
                blocks.insert(operands[0]);
            }
            OP_TYPE_POINTER if operands.len() == 3 => {
                let io = operands[1] == StorageClass::Input as u32 || operands[1] == StorageClass::Output as u32;
                if io && blocks.contains(&operands[2]) {
                    return true;
                }
            }
            _ => {}
        }
    }
    false
}

/// What the module says about its types and decorations, as the split reads it.
struct Blocks {
    /// Struct ids decorated `Block` with no built-in member.
    structs: HashSet<Word>,
    /// Every type, constant and global variable by result id.
    defs: HashMap<Word, Instruction>,
}

/// One block variable to split: its id, storage class and struct type.
struct BlockVariable {
    id: Word,
    class: StorageClass,
    ty: Word,
}

impl Blocks {
    fn of(module: &dr::Module) -> Blocks {
        let decorated = |d: Decoration| {
            module.annotations.iter().filter(move |a| a.class.opcode == Op::Decorate && a.operands.get(1) == Some(&Operand::Decoration(d)))
        };
        let built_in: HashSet<Word> = module
            .annotations
            .iter()
            .filter(|a| a.class.opcode == Op::MemberDecorate && a.operands.get(2) == Some(&Operand::Decoration(Decoration::BuiltIn)))
            .filter_map(|a| a.operands.first()?.id_ref_any())
            .collect();
        let structs =
            decorated(Decoration::Block).filter_map(|a| a.operands.first()?.id_ref_any()).filter(|s| !built_in.contains(s)).collect();
        let defs = module.types_global_values.iter().filter_map(|i| Some((i.result_id?, i.clone()))).collect();
        Blocks { structs, defs }
    }

    /// The input and output variables whose type is one of the blocks (not an array of them).
    fn variables(&self, module: &dr::Module) -> Vec<BlockVariable> {
        let mut out = Vec::new();
        for v in module.types_global_values.iter().filter(|i| i.class.opcode == Op::Variable) {
            let (Some(id), Some(ptr)) = (v.result_id, v.result_type) else { continue };
            let Some(Operand::StorageClass(class)) = v.operands.first() else { continue };
            if !matches!(class, StorageClass::Input | StorageClass::Output) {
                continue;
            }
            let Some(pointee) = self.defs.get(&ptr).and_then(|p| p.operands.get(1)).and_then(Operand::id_ref_any) else { continue };
            if self.structs.contains(&pointee) {
                out.push(BlockVariable { id, class: *class, ty: pointee });
            }
        }
        out
    }

    fn constant(&self, id: Word) -> Option<u32> {
        constant(&self.defs, id)
    }

    fn locations(&self, ty: Word) -> Option<u32> {
        locations(&self.defs, ty)
    }
}

/// The 32-bit value of integer constant `id` (`defs`: types and constants by result id).
pub(crate) fn constant(defs: &HashMap<Word, Instruction>, id: Word) -> Option<u32> {
    let c = defs.get(&id).filter(|c| c.class.opcode == Op::Constant)?;
    match c.operands.first()? {
        Operand::LiteralBit32(v) => Some(*v),
        _ => None,
    }
}

/// The locations a value of type `ty` takes (GLSL 4.60 §4.4.1: a 64-bit `dvec3`/`dvec4`
/// takes two, a matrix one per column, an array or struct the sum of its elements').
pub(crate) fn locations(defs: &HashMap<Word, Instruction>, ty: Word) -> Option<u32> {
    let t = defs.get(&ty)?;
    let id = |i: usize| t.operands.get(i).and_then(Operand::id_ref_any);
    let literal = |i: usize| match t.operands.get(i) {
        Some(Operand::LiteralBit32(v)) => Some(*v),
        _ => None,
    };
    match t.class.opcode {
        Op::TypeFloat | Op::TypeInt | Op::TypeBool => Some(1),
        Op::TypeVector => {
            let wide = defs.get(&id(0)?).and_then(|c| c.operands.first()) == Some(&Operand::LiteralBit32(64));
            Some(if wide && literal(1)? > 2 { 2 } else { 1 })
        }
        Op::TypeMatrix => Some(literal(1)? * locations(defs, id(0)?)?),
        Op::TypeArray => Some(constant(defs, id(1)?)? * locations(defs, id(0)?)?),
        Op::TypeStruct => t.operands.iter().map(|o| locations(defs, o.id_ref_any()?)).sum(),
        _ => None,
    }
}

/// One member of a block as its own variable.
struct Member {
    id: Word,
    ty: Word,
    location: u32,
}

/// Splits `var` in `module`, or `None` when it cannot be (the caller then leaves the stage
/// as glslang wrote it).
fn split(module: &mut dr::Module, blocks: &Blocks, var: &BlockVariable) -> Option<()> {
    let member_types: Vec<Word> = blocks.defs.get(&var.ty)?.operands.iter().map(Operand::id_ref_any).collect::<Option<_>>()?;
    let decorations_of_var: Vec<Instruction> = module.annotations.iter().filter(|a| targets(a, var.id)).cloned().collect();
    let block_location = decorations_of_var.iter().find_map(|a| decoration_value(&a.operands[1..], Decoration::Location));
    let member_decorations = |i: usize| {
        module
            .annotations
            .iter()
            .filter(move |a| a.class.opcode == Op::MemberDecorate && a.operands.first() == Some(&Operand::IdRef(var.ty)))
            .filter(move |a| a.operands.get(1) == Some(&Operand::LiteralBit32(i as u32)))
    };
    let mut bound = module.header.as_ref()?.bound;
    let mut fresh = || {
        bound += 1;
        bound - 1
    };
    // Each member's variable, pointer type and location.
    let mut members = Vec::new();
    let mut next = block_location;
    for (i, &ty) in member_types.iter().enumerate() {
        let own = member_decorations(i).find_map(|a| decoration_value(&a.operands[2..], Decoration::Location));
        let location = own.or(next)?;
        next = Some(location + blocks.locations(ty)?);
        members.push(Member { id: fresh(), ty, location });
    }
    let alias = redirect_access_chains(&mut module.functions, blocks, var.id, &members)?;
    // Pointer types, variables, names and decorations of the members, in place of the block's.
    let at = module.types_global_values.iter().position(|i| i.result_id == Some(var.id))?;
    let mut globals = Vec::new();
    let mut annotations = Vec::new();
    let mut names = Vec::new();
    let block_name = name_of(module, var.id, None);
    for (i, m) in members.iter().enumerate() {
        let existing = module
            .types_global_values
            .iter()
            .chain(&globals)
            .find(|p| p.class.opcode == Op::TypePointer && p.operands == [Operand::StorageClass(var.class), Operand::IdRef(m.ty)]);
        let ptr = match existing.and_then(|p| p.result_id) {
            Some(p) => p,
            None => {
                let p = fresh();
                globals.push(Instruction::new(
                    Op::TypePointer,
                    None,
                    Some(p),
                    vec![Operand::StorageClass(var.class), Operand::IdRef(m.ty)],
                ));
                p
            }
        };
        globals.push(Instruction::new(Op::Variable, Some(ptr), Some(m.id), vec![Operand::StorageClass(var.class)]));
        let name = name_of(module, var.ty, Some(i)).unwrap_or_else(|| format!("{}_{i}", block_name.as_deref().unwrap_or("block")));
        names.push(Instruction::new(Op::Name, None, None, vec![Operand::IdRef(m.id), Operand::LiteralString(name)]));
        let decorate = |rest: &[Operand]| {
            let mut operands = vec![Operand::IdRef(m.id)];
            operands.extend_from_slice(rest);
            Instruction::new(Op::Decorate, None, None, operands)
        };
        annotations.push(decorate(&[Operand::Decoration(Decoration::Location), Operand::LiteralBit32(m.location)]));
        for a in &decorations_of_var {
            if a.operands.get(1).is_some_and(interpolation) {
                annotations.push(decorate(&a.operands[1..]));
            }
        }
        for a in member_decorations(i) {
            if a.operands.get(2).is_some_and(|d| interpolation(d) || *d == Operand::Decoration(Decoration::Component)) {
                annotations.push(decorate(&a.operands[2..]));
            }
        }
    }
    // At the end of the section: every type a member has is declared before it.
    module.types_global_values.remove(at);
    module.types_global_values.extend(globals);
    module
        .annotations
        .retain(|a| !targets(a, var.id) && !a.operands.first().and_then(Operand::id_ref_any).is_some_and(|t| alias.contains_key(&t)));
    module.annotations.extend(annotations);
    module.debug_names.retain(|n| !(n.class.opcode == Op::Name && n.operands.first() == Some(&Operand::IdRef(var.id))));
    module.debug_names.extend(names);
    let member_ids: Vec<Operand> = members.iter().map(|m| Operand::IdRef(m.id)).collect();
    for ep in &mut module.entry_points {
        if let Some(i) = ep.operands.iter().position(|o| *o == Operand::IdRef(var.id)) {
            ep.operands.splice(i..=i, member_ids.iter().cloned());
        }
    }
    module.header.as_mut()?.bound = bound;
    Some(())
}

/// Access chains into block variable `var` start from the member's variable instead; a
/// chain that only picks the member is the member's variable: the ids of those chains,
/// which are gone, with the member variable that replaces each (every use of them is
/// redirected). `None` when the block is used otherwise.
fn redirect_access_chains(functions: &mut [dr::Function], blocks: &Blocks, var: Word, members: &[Member]) -> Option<HashMap<Word, Word>> {
    let mut alias: HashMap<Word, Word> = HashMap::new();
    for f in functions.iter_mut() {
        for b in &mut f.blocks {
            let mut kept = Vec::with_capacity(b.instructions.len());
            for mut inst in b.instructions.drain(..) {
                let chain = matches!(inst.class.opcode, Op::AccessChain | Op::InBoundsAccessChain);
                if !inst.operands.iter().any(|o| o.id_ref_any() == Some(var)) {
                    kept.push(inst);
                    continue;
                }
                if !chain || inst.operands[0] != Operand::IdRef(var) {
                    return None;
                }
                let index = blocks.constant(inst.operands.get(1)?.id_ref_any()?)? as usize;
                let member = members.get(index)?;
                if inst.operands.len() == 2 {
                    alias.insert(inst.result_id?, member.id);
                    continue;
                }
                inst.operands.splice(0..2, [Operand::IdRef(member.id)]);
                kept.push(inst);
            }
            b.instructions = kept;
        }
    }
    for inst in functions.iter_mut().flat_map(|f| f.blocks.iter_mut()).flat_map(|b| b.instructions.iter_mut()) {
        for id in inst.operands.iter_mut().filter_map(Operand::id_ref_any_mut) {
            if let Some(to) = alias.get(id) {
                *id = *to;
            }
        }
    }
    Some(alias)
}

/// Whether `a` is an `OpDecorate` of `id`.
pub(crate) fn targets(a: &Instruction, id: Word) -> bool {
    a.class.opcode == Op::Decorate && a.operands.first() == Some(&Operand::IdRef(id))
}

/// The literal of decoration `d` in a decoration's operands (`Location 3`).
fn decoration_value(operands: &[Operand], d: Decoration) -> Option<u32> {
    match operands {
        [Operand::Decoration(x), Operand::LiteralBit32(v), ..] if *x == d => Some(*v),
        _ => None,
    }
}

/// Whether a decoration says how a varying is interpolated or kept (what each member's
/// variable takes from the block and from its member; each leaf of an aggregate varying,
/// [`crate::front::spirv_aggregate_varyings`], from its variable and members).
pub(crate) fn interpolation(d: &Operand) -> bool {
    use Decoration as D;
    matches!(d, Operand::Decoration(D::Flat | D::NoPerspective | D::Centroid | D::Sample | D::Invariant | D::Patch | D::RelaxedPrecision))
}

/// The name `OpName` (or, for a member, `OpMemberName`) gives.
pub(crate) fn name_of(module: &dr::Module, id: Word, member: Option<usize>) -> Option<String> {
    module.debug_names.iter().find_map(|n| {
        let named = match member {
            None => n.class.opcode == Op::Name && n.operands.first() == Some(&Operand::IdRef(id)),
            Some(i) => {
                n.class.opcode == Op::MemberName
                    && n.operands.first() == Some(&Operand::IdRef(id))
                    && n.operands.get(1) == Some(&Operand::LiteralBit32(i as u32))
            }
        };
        match n.operands.last() {
            Some(Operand::LiteralString(s)) if named && !s.is_empty() => Some(s.clone()),
            _ => None,
        }
    })
}
