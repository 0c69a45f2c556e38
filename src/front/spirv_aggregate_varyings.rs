//! Varyings of aggregate type (`out vec4 offset[3];`, `in mat4 model;`, a block member
//! `vec2 uv[2]`, `out S s;`) split into one SPIR-V variable per scalar or vector before
//! naga's SPIR-V front reads a vertex or fragment stage: naga takes only numeric scalars
//! and vectors as entry-point inputs and outputs.
//!
//! Each leaf (an array element, a matrix column, a struct member, recursively) becomes an
//! input or output variable of its own at the location GL gives it (an element of an array
//! at location L takes L + i × the element's locations, a matrix's column c takes L + c, a
//! struct member its own location or the next free one), with the interpolation of the
//! variable and of its member. The original variable stays, as a private variable of the
//! same type, so every access to it (a run-time index too) reads and writes it as before:
//! the entry point copies the input leaves into it first, and copies it into the output
//! leaves before each return. Geometry and tessellation stages, whose inputs are arrays
//! per vertex, stay as they are.

use std::collections::{HashMap, HashSet};

use rspirv::binary::Assemble;
use rspirv::dr::{self, Instruction, Operand};
use rspirv::spirv::{Decoration, ExecutionModel, Op, StorageClass, Word};

use crate::front::spirv_interface_blocks::{constant, interpolation, locations, name_of, targets};

/// `words` with every aggregate input and output of a vertex or fragment stage split into
/// scalar and vector variables; the words as they were when there is none, or when one is
/// used in a way the split does not follow (a pointer to it passed to a function).
pub fn split_aggregate_varyings(words: Vec<u32>) -> Vec<u32> {
    let Ok(mut module) = dr::load_words(&words) else { return words };
    let Some(entry) = vertex_or_fragment_entry(&module) else { return words };
    let types = Types::of(&module);
    let variables = types.aggregate_varyings(&module, entry);
    if variables.is_empty() {
        return words;
    }
    let mut split = Split::new(&mut module, types);
    for v in &variables {
        if split.variable(v).is_none() {
            return words;
        }
    }
    if split.finish(entry).is_none() {
        return words;
    }
    module.assemble()
}

/// The entry point function of a module with one vertex or fragment entry point.
fn vertex_or_fragment_entry(module: &dr::Module) -> Option<Word> {
    let [ep] = &module.entry_points[..] else { return None };
    let model = match ep.operands.first()? {
        Operand::ExecutionModel(m) => *m,
        _ => return None,
    };
    matches!(model, ExecutionModel::Vertex | ExecutionModel::Fragment).then_some(())?;
    ep.operands.get(1)?.id_ref_any()
}

/// Types, constants and decorations as the split reads them.
struct Types {
    defs: HashMap<Word, Instruction>,
    /// Ids decorated `BuiltIn`, or structs with a `BuiltIn` member.
    built_in: HashSet<Word>,
}

/// One aggregate input or output variable.
struct Varying {
    id: Word,
    class: StorageClass,
    ty: Word,
    location: u32,
}

/// One scalar or vector part of a varying: the constant indices that reach it, its type,
/// its location and the decorations it takes.
struct Leaf {
    path: Vec<u32>,
    ty: Word,
    location: u32,
    decorations: Vec<Vec<Operand>>,
    name: String,
}

impl Types {
    fn of(module: &dr::Module) -> Types {
        let defs = module.types_global_values.iter().filter_map(|i| Some((i.result_id?, i.clone()))).collect();
        let built_in = module
            .annotations
            .iter()
            .filter(|a| a.operands.contains(&Operand::Decoration(Decoration::BuiltIn)))
            .filter_map(|a| a.operands.first()?.id_ref_any())
            .collect();
        Types { defs, built_in }
    }

    fn op(&self, id: Word) -> Option<Op> {
        Some(self.defs.get(&id)?.class.opcode)
    }

    fn id_operand(&self, id: Word, i: usize) -> Option<Word> {
        self.defs.get(&id)?.operands.get(i)?.id_ref_any()
    }

    fn literal(&self, id: Word, i: usize) -> Option<u32> {
        match self.defs.get(&id)?.operands.get(i)? {
            Operand::LiteralBit32(v) => Some(*v),
            _ => None,
        }
    }

    /// The interface's aggregate input and output variables with a location (built-ins
    /// and the members of built-in blocks stay).
    fn aggregate_varyings(&self, module: &dr::Module, entry: Word) -> Vec<Varying> {
        let interface: HashSet<Word> = module
            .entry_points
            .iter()
            .filter(|ep| ep.operands.get(1).and_then(Operand::id_ref_any) == Some(entry))
            .flat_map(|ep| ep.operands.iter().skip(3).filter_map(Operand::id_ref_any))
            .collect();
        let mut out = Vec::new();
        for v in module.types_global_values.iter().filter(|i| i.class.opcode == Op::Variable) {
            let (Some(id), Some(ptr)) = (v.result_id, v.result_type) else { continue };
            let Some(Operand::StorageClass(class)) = v.operands.first() else { continue };
            if !matches!(class, StorageClass::Input | StorageClass::Output) || !interface.contains(&id) || self.built_in.contains(&id) {
                continue;
            }
            let Some(ty) = self.id_operand(ptr, 1) else { continue };
            if !matches!(self.op(ty), Some(Op::TypeArray | Op::TypeMatrix | Op::TypeStruct)) || self.built_in.contains(&ty) {
                continue;
            }
            let location = module.annotations.iter().find_map(|a| match &a.operands[..] {
                [Operand::IdRef(t), Operand::Decoration(Decoration::Location), Operand::LiteralBit32(l)] if *t == id => Some(*l),
                _ => None,
            });
            if let Some(location) = location {
                out.push(Varying { id, class: *class, ty, location });
            }
        }
        out
    }

    fn locations(&self, ty: Word) -> Option<u32> {
        locations(&self.defs, ty)
    }

    fn array_length(&self, ty: Word) -> Option<u32> {
        constant(&self.defs, self.id_operand(ty, 1)?)
    }
}

/// A varying made private: its id, its storage class as a varying, and each leaf's
/// variable with the leaf.
type Copies = (Word, StorageClass, Vec<(Word, Leaf)>);

/// The split in progress: new types, variables, names and decorations, and the copies the
/// entry point makes.
struct Split<'m> {
    module: &'m mut dr::Module,
    types: Types,
    bound: Word,
    /// Pointer types by (storage class, pointee), existing and new.
    pointers: HashMap<(StorageClass, Word), Word>,
    /// 32-bit integer constants by value, existing and new.
    constants: HashMap<u32, Word>,
    int: Option<Word>,
    new_globals: Vec<Instruction>,
    /// The varyings made private, and the leaves each copies from or to.
    copies: Vec<Copies>,
}

impl<'m> Split<'m> {
    fn new(module: &'m mut dr::Module, types: Types) -> Split<'m> {
        let bound = module.header.as_ref().map_or(0, |h| h.bound);
        let mut pointers = HashMap::new();
        let mut constants = HashMap::new();
        let mut int = None;
        for i in &module.types_global_values {
            let Some(id) = i.result_id else { continue };
            match (i.class.opcode, &i.operands[..]) {
                (Op::TypePointer, [Operand::StorageClass(c), Operand::IdRef(t)]) => {
                    pointers.entry((*c, *t)).or_insert(id);
                }
                (Op::TypeInt, [Operand::LiteralBit32(32), Operand::LiteralBit32(_)]) if int.is_none() => int = Some(id),
                _ => {}
            }
        }
        for i in module.types_global_values.iter().filter(|i| i.class.opcode == Op::Constant && i.result_type == int && int.is_some()) {
            if let (Some(id), [Operand::LiteralBit32(v)]) = (i.result_id, &i.operands[..]) {
                constants.entry(*v).or_insert(id);
            }
        }
        Split { module, types, bound, pointers, constants, int, new_globals: Vec::new(), copies: Vec::new() }
    }

    fn fresh(&mut self) -> Word {
        self.bound += 1;
        self.bound - 1
    }

    fn pointer(&mut self, class: StorageClass, ty: Word) -> Word {
        if let Some(p) = self.pointers.get(&(class, ty)) {
            return *p;
        }
        let p = self.fresh();
        self.new_globals.push(Instruction::new(Op::TypePointer, None, Some(p), vec![Operand::StorageClass(class), Operand::IdRef(ty)]));
        self.pointers.insert((class, ty), p);
        p
    }

    fn constant(&mut self, v: u32) -> Word {
        if let Some(c) = self.constants.get(&v) {
            return *c;
        }
        let int = match self.int {
            Some(t) => t,
            None => {
                let t = self.fresh();
                self.new_globals.push(Instruction::new(
                    Op::TypeInt,
                    None,
                    Some(t),
                    vec![Operand::LiteralBit32(32), Operand::LiteralBit32(1)],
                ));
                self.int = Some(t);
                t
            }
        };
        let c = self.fresh();
        self.new_globals.push(Instruction::new(Op::Constant, Some(int), Some(c), vec![Operand::LiteralBit32(v)]));
        self.constants.insert(v, c);
        c
    }

    /// The leaves of `ty` at `location` (`None` when a part has no scalar or vector form).
    fn leaves(&self, ty: Word, at: Leaf, out: &mut Vec<Leaf>) -> Option<()> {
        let t = &self.types;
        match t.op(ty)? {
            Op::TypeFloat | Op::TypeInt | Op::TypeBool | Op::TypeVector => out.push(Leaf { ty, ..at }),
            Op::TypeMatrix => {
                let column = t.id_operand(ty, 0)?;
                for c in 0..t.literal(ty, 1)? {
                    let leaf = Leaf {
                        path: [&at.path[..], &[c]].concat(),
                        ty: column,
                        location: at.location + c * t.locations(column)?,
                        decorations: at.decorations.clone(),
                        name: format!("{}_{c}", at.name),
                    };
                    self.leaves(column, leaf, out)?;
                }
            }
            Op::TypeArray => {
                let element = t.id_operand(ty, 0)?;
                let size = t.locations(element)?;
                for i in 0..t.array_length(ty)? {
                    let leaf = Leaf {
                        path: [&at.path[..], &[i]].concat(),
                        ty: element,
                        location: at.location + i * size,
                        decorations: at.decorations.clone(),
                        name: format!("{}_{i}", at.name),
                    };
                    self.leaves(element, leaf, out)?;
                }
            }
            Op::TypeStruct => {
                let members: Vec<Word> = t.defs.get(&ty)?.operands.iter().map(Operand::id_ref_any).collect::<Option<_>>()?;
                let mut next = at.location;
                for (i, &m) in members.iter().enumerate() {
                    let decorations: Vec<Vec<Operand>> = self
                        .module
                        .annotations
                        .iter()
                        .filter(|a| a.class.opcode == Op::MemberDecorate && a.operands.first() == Some(&Operand::IdRef(ty)))
                        .filter(|a| a.operands.get(1) == Some(&Operand::LiteralBit32(i as u32)))
                        .map(|a| a.operands[2..].to_vec())
                        .collect();
                    let own = decorations.iter().find_map(|d| match &d[..] {
                        [Operand::Decoration(Decoration::Location), Operand::LiteralBit32(l)] => Some(*l),
                        _ => None,
                    });
                    let location = own.unwrap_or(next);
                    next = location + t.locations(m)?;
                    let mut inherited = at.decorations.clone();
                    inherited.extend(decorations.into_iter().filter(|d| d.first().is_some_and(interpolation)));
                    let member = name_of(self.module, ty, Some(i)).unwrap_or_else(|| i.to_string());
                    let leaf = Leaf {
                        path: [&at.path[..], &[i as u32]].concat(),
                        ty: m,
                        location,
                        decorations: inherited,
                        name: format!("{}_{member}", at.name),
                    };
                    self.leaves(m, leaf, out)?;
                }
            }
            _ => return None,
        }
        Some(())
    }

    /// Splits one varying: its leaves become variables, it becomes private.
    fn variable(&mut self, v: &Varying) -> Option<()> {
        let own: Vec<Vec<Operand>> =
            self.module.annotations.iter().filter(|a| targets(a, v.id)).map(|a| a.operands[1..].to_vec()).collect();
        let name = name_of(self.module, v.id, None).unwrap_or_else(|| format!("varying{}", v.location));
        let root = Leaf {
            path: Vec::new(),
            ty: v.ty,
            location: v.location,
            decorations: own.into_iter().filter(|d| d.first().is_some_and(interpolation)).collect(),
            name,
        };
        let mut leaves = Vec::new();
        self.leaves(v.ty, root, &mut leaves)?;
        let mut made = Vec::new();
        for leaf in leaves {
            let ptr = self.pointer(v.class, leaf.ty);
            let id = self.fresh();
            self.new_globals.push(Instruction::new(Op::Variable, Some(ptr), Some(id), vec![Operand::StorageClass(v.class)]));
            self.module.debug_names.push(Instruction::new(
                Op::Name,
                None,
                None,
                vec![Operand::IdRef(id), Operand::LiteralString(leaf.name.clone())],
            ));
            let decorate = |rest: Vec<Operand>| Instruction::new(Op::Decorate, None, None, [vec![Operand::IdRef(id)], rest].concat());
            self.module.annotations.push(decorate(vec![Operand::Decoration(Decoration::Location), Operand::LiteralBit32(leaf.location)]));
            for d in &leaf.decorations {
                self.module.annotations.push(decorate(d.clone()));
            }
            made.push((id, leaf));
        }
        // The varying itself: private, undecorated, after the types its new pointer needs.
        let private = self.pointer(StorageClass::Private, v.ty);
        let at = self.module.types_global_values.iter().position(|i| i.result_id == Some(v.id))?;
        let mut var = self.module.types_global_values.remove(at);
        var.result_type = Some(private);
        var.operands = vec![Operand::StorageClass(StorageClass::Private)];
        self.new_globals.push(var);
        self.module.annotations.retain(|a| !targets(a, v.id));
        self.copies.push((v.id, v.class, made));
        Some(())
    }

    /// Retypes the pointers derived from the private varyings, writes the copies into the
    /// entry point, and lists the leaves in its interface.
    fn finish(mut self, entry: Word) -> Option<()> {
        self.retype_pointers()?;
        let mut at_start = Vec::new();
        let mut at_return = Vec::new();
        let copies = std::mem::take(&mut self.copies);
        for (var, class, leaves) in &copies {
            for (leaf_var, leaf) in leaves {
                let mut indices = Vec::new();
                for i in &leaf.path {
                    indices.push(Operand::IdRef(self.constant(*i)));
                }
                let private_ptr = self.pointer(StorageClass::Private, leaf.ty);
                let chain = self.fresh();
                let value = self.fresh();
                let access =
                    Instruction::new(Op::AccessChain, Some(private_ptr), Some(chain), [vec![Operand::IdRef(*var)], indices].concat());
                let (load, store) = if *class == StorageClass::Input {
                    (
                        Instruction::new(Op::Load, Some(leaf.ty), Some(value), vec![Operand::IdRef(*leaf_var)]),
                        Instruction::new(Op::Store, None, None, vec![Operand::IdRef(chain), Operand::IdRef(value)]),
                    )
                } else {
                    (
                        Instruction::new(Op::Load, Some(leaf.ty), Some(value), vec![Operand::IdRef(chain)]),
                        Instruction::new(Op::Store, None, None, vec![Operand::IdRef(*leaf_var), Operand::IdRef(value)]),
                    )
                };
                let target = if *class == StorageClass::Input { &mut at_start } else { &mut at_return };
                target.extend([access, load, store]);
            }
        }
        let function = self.module.functions.iter_mut().find(|f| f.def.as_ref().and_then(|d| d.result_id) == Some(entry))?;
        let first = function.blocks.first_mut()?;
        let after_locals = first.instructions.iter().position(|i| i.class.opcode != Op::Variable).unwrap_or(first.instructions.len());
        first.instructions.splice(after_locals..after_locals, at_start);
        if !at_return.is_empty() {
            for block in &mut function.blocks {
                let Some(end) = block.instructions.iter().rposition(|i| matches!(i.class.opcode, Op::Return | Op::ReturnValue)) else {
                    continue;
                };
                // Each copy needs ids of its own in each block.
                let mut renamed = Vec::with_capacity(at_return.len());
                let mut map = HashMap::new();
                for inst in &at_return {
                    let mut inst: Instruction = inst.clone();
                    if let Some(r) = inst.result_id {
                        self.bound += 1;
                        map.insert(r, self.bound - 1);
                        inst.result_id = Some(self.bound - 1);
                    }
                    for id in inst.operands.iter_mut().filter_map(Operand::id_ref_any_mut) {
                        if let Some(to) = map.get(id) {
                            *id = *to;
                        }
                    }
                    renamed.push(inst);
                }
                block.instructions.splice(end..end, renamed);
            }
        }
        // The leaves in the interface; from SPIR-V 1.4 every global the entry point uses is.
        let listed_privates = self.module.header.as_ref().is_some_and(|h| h.version() >= (1, 4));
        for ep in &mut self.module.entry_points {
            for (var, _, leaves) in &copies {
                let Some(i) = ep.operands.iter().position(|o| *o == Operand::IdRef(*var)) else { continue };
                let mut ids: Vec<Operand> = leaves.iter().map(|(id, _)| Operand::IdRef(*id)).collect();
                if listed_privates {
                    ids.push(Operand::IdRef(*var));
                }
                ep.operands.splice(i..=i, ids);
            }
        }
        let globals = std::mem::take(&mut self.new_globals);
        self.module.types_global_values.extend(globals);
        self.module.header.as_mut()?.bound = self.bound;
        Some(())
    }

    /// Access chains into the private varyings point into private memory: their result
    /// types change class. `None` when such a pointer is used other than by an access
    /// chain, a load or a store (passed to a function, copied).
    fn retype_pointers(&mut self) -> Option<()> {
        let mut derived: HashSet<Word> = self.copies.iter().map(|(v, _, _)| *v).collect();
        let mut retype = Vec::new();
        for f in &self.module.functions {
            for inst in f.blocks.iter().flat_map(|b| b.instructions.iter()) {
                let uses = inst.operands.iter().filter_map(Operand::id_ref_any).any(|id| derived.contains(&id));
                if !uses {
                    continue;
                }
                match inst.class.opcode {
                    Op::AccessChain | Op::InBoundsAccessChain
                        if inst.operands.first().and_then(Operand::id_ref_any).is_some_and(|b| derived.contains(&b)) =>
                    {
                        let r = inst.result_id?;
                        derived.insert(r);
                        let pointee = self.types.id_operand(inst.result_type?, 1)?;
                        retype.push((r, pointee));
                    }
                    Op::Load if inst.operands.len() <= 2 => {}
                    Op::Store if inst.operands.first().and_then(Operand::id_ref_any).is_some_and(|p| derived.contains(&p)) => {
                        let value = inst.operands.get(1).and_then(Operand::id_ref_any)?;
                        if derived.contains(&value) {
                            return None;
                        }
                    }
                    _ => return None,
                }
            }
        }
        let new_types: HashMap<Word, Word> =
            retype.into_iter().map(|(r, pointee)| (r, self.pointer(StorageClass::Private, pointee))).collect();
        for inst in self.module.functions.iter_mut().flat_map(|f| f.blocks.iter_mut()).flat_map(|b| b.instructions.iter_mut()) {
            if let Some(t) = inst.result_id.and_then(|r| new_types.get(&r)) {
                inst.result_type = Some(*t);
            }
        }
        Some(())
    }
}
