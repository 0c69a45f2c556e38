//! Two-row matrices (`mat2`, `mat3x2`, `mat4x2`) in std140 blocks, stored as arrays of
//! `vec4` columns for naga.
//!
//! std140 puts a matrix's columns 16 bytes apart; naga's IR lays a two-row matrix's
//! columns 8 bytes apart and its SPIR-V front refuses the block ("unsupported matrix stride
//! 16 for a 3x2 matrix": gfx-rs/wgpu#4375). Such a member (column-major, `MatrixStride 16`,
//! alone or in an array) becomes an array of `vec4` with `ArrayStride 16`: the same bytes.
//! Access chains into it get pointers to the stored types (a column is a `vec4`, an element
//! stays a scalar), and a load of a column takes its `.xy`, a load of the matrix builds it
//! from its columns' `.xy`.
//!
//! A struct holding such a member may be loaded whole (`Light l = u.lights[i];`): the
//! matrix or column extracted from the value is rebuilt the same way. Anything else done
//! with such a pointer or value (a store, a copy, a whole array of matrices loaded at once,
//! the value passed on) leaves the module as it was: naga's refusal stands and names the
//! construct. The lengths change, so this runs before [`Lines`] is taken.
//!
//! [`Lines`]: crate::front::spirv_binary::Lines

use std::collections::{HashMap, HashSet};

use rspirv::spirv::{Decoration, Op};

use crate::front::spirv_binary::{has_result_type, instruction, instructions, HEADER_WORDS};

const OP_TYPE_INT: u16 = Op::TypeInt as u16;
const OP_TYPE_FLOAT: u16 = Op::TypeFloat as u16;
const OP_TYPE_VECTOR: u16 = Op::TypeVector as u16;
const OP_TYPE_MATRIX: u16 = Op::TypeMatrix as u16;
const OP_TYPE_ARRAY: u16 = Op::TypeArray as u16;
const OP_TYPE_RUNTIME_ARRAY: u16 = Op::TypeRuntimeArray as u16;
const OP_TYPE_STRUCT: u16 = Op::TypeStruct as u16;
const OP_TYPE_POINTER: u16 = Op::TypePointer as u16;
const OP_CONSTANT: u16 = Op::Constant as u16;
const OP_DECORATE: u16 = Op::Decorate as u16;
const OP_MEMBER_DECORATE: u16 = Op::MemberDecorate as u16;
const OP_LOAD: u16 = Op::Load as u16;
const OP_ACCESS_CHAIN: u16 = Op::AccessChain as u16;
const OP_IN_BOUNDS_ACCESS_CHAIN: u16 = Op::InBoundsAccessChain as u16;
const OP_FUNCTION: u16 = Op::Function as u16;
const OP_COMPOSITE_EXTRACT: u16 = Op::CompositeExtract as u16;
const MATRIX_STRIDE: u32 = Decoration::MatrixStride as u32;
const ARRAY_STRIDE: u32 = Decoration::ArrayStride as u32;
const ROW_MAJOR: u32 = Decoration::RowMajor as u32;
const COL_MAJOR: u32 = Decoration::ColMajor as u32;

/// `words` with the two-row matrices of the module doc stored as columns, or as they were.
pub(crate) fn two_row_matrices_as_columns(words: Vec<u32>) -> Vec<u32> {
    Module::read(&words).and_then(|m| m.lowered(&words)).unwrap_or(words)
}

/// The operands of a function-body instruction that may be ids (all but its opcode word,
/// less the literals of the instructions that commonly carry some: a literal equal to a
/// tracked id would otherwise undo the pass for nothing).
fn ids_used(op: u16, w: &[u32]) -> &[u32] {
    let end = |n: usize| &w[1..n.min(w.len())];
    match Op::from_u32(u32::from(op)) {
        Some(Op::Line | Op::NoLine | Op::LoopMerge | Op::SelectionMerge | Op::Label | Op::Branch) => &[],
        Some(Op::CompositeExtract) => end(4),
        Some(Op::VectorShuffle) => end(5),
        Some(Op::Store) => end(3),
        Some(Op::Load) => end(4),
        Some(Op::Switch) => end(2),
        Some(Op::ExtInst) => &w[5.min(w.len())..],
        _ => &w[1.min(w.len())..],
    }
}

/// What the pass reads of a module.
#[derive(Default)]
struct Module {
    /// Where each type or constant is declared.
    at: HashMap<u32, usize>,
    /// Offset of the instruction after the last annotation (`OpDecorate` and kin).
    after_annotations: usize,
    float32: Option<u32>,
    vec4: Option<u32>,
    uint32: Option<u32>,
    /// Integer constants: id → value.
    constants: HashMap<u32, u32>,
    /// Vectors: id → (component type, count).
    vectors: HashMap<u32, (u32, u32)>,
    /// Two-row matrices of 32-bit floats: id → (column type, column count).
    matrices: HashMap<u32, (u32, u32)>,
    /// Arrays (runtime ones too): id → (element type, length constant).
    arrays: HashMap<u32, (u32, Option<u32>)>,
    structs: HashMap<u32, Vec<u32>>,
    /// Pointer types: id → (storage class, pointee).
    pointers: HashMap<u32, (u32, u32)>,
    type_of: HashMap<u32, u32>,
    matrix_stride: HashMap<(u32, u32), u32>,
    row_major: HashSet<(u32, u32)>,
    array_stride: HashMap<u32, u32>,
}

/// What the pass writes.
#[derive(Default)]
struct Plan {
    bound: u32,
    /// New type and constant declarations, in order.
    types: Vec<u32>,
    /// New `ArrayStride` decorations.
    decorations: Vec<u32>,
    vec4: u32,
    /// The members stored otherwise: (struct, member).
    members: HashSet<(u32, u32)>,
    /// Stored type of each two-row matrix and array of them.
    stored: HashMap<u32, u32>,
    /// Pointer types made: (storage class, pointee) → id.
    pointer_types: HashMap<(u32, u32), u32>,
    /// Access chains into stored members: offset → their new result type.
    chains: HashMap<usize, u32>,
    /// Pointers those chains give: id → (storage class, the type GLSL declared there).
    logical: HashMap<u32, (u32, u32)>,
    /// Loads through them: offset → the declared type loaded.
    loads: HashMap<usize, u32>,
    /// Values of a struct or array holding a stored member (loaded whole).
    holding: HashSet<u32>,
    /// Extractions of a stored member from such values: offset → the declared type.
    extracts: HashMap<usize, u32>,
}

impl Plan {
    fn fresh(&mut self) -> u32 {
        self.bound += 1;
        self.bound - 1
    }

    /// Declares a type or constant (`op`, operands with `0` where the result id goes).
    fn declare(&mut self, op: Op, mut operands: Vec<u32>) -> u32 {
        let id = self.fresh();
        let slot = if op == Op::Constant { 1 } else { 0 };
        operands[slot] = id;
        self.types.extend(instruction(op as u16, &operands));
        id
    }

    fn pointer(&mut self, storage: u32, pointee: u32) -> u32 {
        if let Some(&id) = self.pointer_types.get(&(storage, pointee)) {
            return id;
        }
        let id = self.declare(Op::TypePointer, vec![0, storage, pointee]);
        self.pointer_types.insert((storage, pointee), id);
        id
    }
}

impl Module {
    fn read(words: &[u32]) -> Option<Module> {
        let mut m = Module::default();
        for (at, op, count) in instructions(words) {
            let w = &words[at..(at + count.max(1)).min(words.len())];
            let declares =
                [OP_TYPE_INT, OP_TYPE_FLOAT, OP_TYPE_VECTOR, OP_TYPE_MATRIX, OP_TYPE_ARRAY, OP_TYPE_RUNTIME_ARRAY, OP_TYPE_STRUCT]
                    .contains(&op)
                    || op == OP_TYPE_POINTER;
            if (declares || op == OP_CONSTANT) && w.len() >= 3 {
                m.at.insert(if op == OP_CONSTANT { w[2] } else { w[1] }, at);
            }
            let annotation = (Op::Decorate as u16..=Op::GroupMemberDecorate as u16).contains(&op)
                || [Op::DecorateId, Op::DecorateString, Op::MemberDecorateString].iter().any(|a| *a as u16 == op);
            if annotation {
                m.after_annotations = at + count.max(1);
            }
            match op {
                OP_TYPE_FLOAT if w.len() >= 3 && w[2] == 32 => m.float32 = m.float32.or(Some(w[1])),
                OP_TYPE_INT if w.len() == 4 && w[2] == 32 && w[3] == 0 => m.uint32 = m.uint32.or(Some(w[1])),
                OP_TYPE_VECTOR if w.len() == 4 => {
                    m.vectors.insert(w[1], (w[2], w[3]));
                    if Some(w[2]) == m.float32 && w[3] == 4 {
                        m.vec4 = m.vec4.or(Some(w[1]));
                    }
                }
                OP_TYPE_MATRIX if w.len() == 4 && m.is_column(w[2]) => {
                    m.matrices.insert(w[1], (w[2], w[3]));
                }
                OP_TYPE_ARRAY if w.len() == 4 => _ = m.arrays.insert(w[1], (w[2], Some(w[3]))),
                OP_TYPE_RUNTIME_ARRAY if w.len() == 3 => _ = m.arrays.insert(w[1], (w[2], None)),
                OP_TYPE_STRUCT if w.len() >= 2 => _ = m.structs.insert(w[1], w[2..].to_vec()),
                OP_TYPE_POINTER if w.len() == 4 => _ = m.pointers.insert(w[1], (w[2], w[3])),
                OP_CONSTANT if w.len() == 4 => _ = m.constants.insert(w[2], w[3]),
                OP_MEMBER_DECORATE if w.len() == 5 && w[3] == MATRIX_STRIDE => _ = m.matrix_stride.insert((w[1], w[2]), w[4]),
                OP_MEMBER_DECORATE if w.len() == 4 && w[3] == ROW_MAJOR => _ = m.row_major.insert((w[1], w[2])),
                OP_DECORATE if w.len() == 4 && w[2] == ARRAY_STRIDE => _ = m.array_stride.insert(w[1], w[3]),
                _ => {}
            }
            let typed = has_result_type(op);
            if typed && w.len() >= 3 {
                m.type_of.insert(w[2], w[1]);
            }
        }
        (m.after_annotations > 0).then_some(m)
    }

    /// The two-row matrix a member's type holds (alone or as an array's elements), when
    /// std140 strides its columns 16 bytes apart.
    fn std140_matrix(&self, owner: u32, member: u32, ty: u32) -> Option<u32> {
        let element = self.arrays.get(&ty).map_or(ty, |(e, _)| *e);
        let strided = self.matrix_stride.get(&(owner, member)) == Some(&16) && !self.row_major.contains(&(owner, member));
        (strided && self.matrices.contains_key(&element)).then_some(element)
    }

    fn lowered(&self, words: &[u32]) -> Option<Vec<u32>> {
        let mut plan = Plan { bound: words[3], ..Plan::default() };
        for (&id, &(storage, pointee)) in &self.pointers {
            plan.pointer_types.entry((storage, pointee)).or_insert(id);
        }
        for (&s, types) in &self.structs {
            for (k, &ty) in types.iter().enumerate() {
                if self.std140_matrix(s, k as u32, ty).is_some() {
                    plan.members.insert((s, k as u32));
                }
            }
        }
        let insert_at = plan.members.iter().filter_map(|(s, _)| self.at.get(s)).min().copied()?;
        let before = |id: &u32| self.at.get(id).is_some_and(|&at| at < insert_at);
        plan.vec4 = match self.vec4.filter(before) {
            Some(v) => v,
            None => plan.declare(Op::TypeVector, vec![0, self.float32?, 4]),
        };
        let uint = match self.uint32.filter(before) {
            Some(u) => u,
            None => plan.declare(Op::TypeInt, vec![0, 32, 0]),
        };
        let mut members: Vec<(u32, u32)> = plan.members.iter().copied().collect();
        members.sort_unstable();
        for (s, k) in members {
            let ty = self.structs[&s][k as usize];
            let matrix = self.std140_matrix(s, k, ty)?;
            if !plan.stored.contains_key(&matrix) {
                let length = plan.declare(Op::Constant, vec![uint, 0, self.matrices[&matrix].1]);
                let columns = plan.declare(Op::TypeArray, vec![0, plan.vec4, length]);
                plan.decorations.extend(instruction(OP_DECORATE, &[columns, ARRAY_STRIDE, 16]));
                plan.stored.insert(matrix, columns);
            }
            if let (Some(&(_, length)), false) = (self.arrays.get(&ty), plan.stored.contains_key(&ty)) {
                let columns = plan.stored[&matrix];
                let outer = match length {
                    Some(length) => plan.declare(Op::TypeArray, vec![0, columns, length]),
                    None => plan.declare(Op::TypeRuntimeArray, vec![0, columns]),
                };
                if let Some(&stride) = self.array_stride.get(&ty) {
                    plan.decorations.extend(instruction(OP_DECORATE, &[outer, ARRAY_STRIDE, stride]));
                }
                plan.stored.insert(ty, outer);
            }
        }
        self.plan_uses(words, &mut plan)?;
        Some(self.emit(words, &mut plan, insert_at))
    }

    /// The access chains and loads of the module doc, or `None` when a pointer into a stored
    /// member is used otherwise.
    fn plan_uses(&self, words: &[u32], plan: &mut Plan) -> Option<()> {
        let in_functions = instructions(words).skip_while(|(_, op, _)| *op != OP_FUNCTION);
        for (at, op, count) in in_functions {
            let w = &words[at..(at + count.max(1)).min(words.len())];
            match op {
                OP_ACCESS_CHAIN | OP_IN_BOUNDS_ACCESS_CHAIN if w.len() >= 4 => self.plan_chain(at, w, plan)?,
                OP_LOAD if w.len() >= 4 => {
                    if let Some(&(_, logical)) = plan.logical.get(&w[3]) {
                        if !self.matrices.contains_key(&logical) && !self.is_column(logical) {
                            return None;
                        }
                        plan.loads.insert(at, logical);
                    } else if self.holds_stored(w[1], plan) {
                        plan.holding.insert(w[2]);
                    }
                }
                OP_COMPOSITE_EXTRACT if w.len() >= 4 && plan.holding.contains(&w[3]) => self.plan_extract(at, w, plan)?,
                _ if ids_used(op, w).iter().any(|id| plan.logical.contains_key(id) || plan.holding.contains(id)) => return None,
                _ => {}
            }
        }
        Some(())
    }

    /// Plans the access chain at `at`: its result type when it reaches into a stored member.
    fn plan_chain(&self, at: usize, w: &[u32], plan: &mut Plan) -> Option<()> {
        let (storage, mut ty, mut inside) = match plan.logical.get(&w[3]) {
            Some(&(storage, logical)) => (storage, logical, true),
            None => {
                let &(storage, pointee) = self.pointers.get(self.type_of.get(&w[3])?)?;
                (storage, pointee, false)
            }
        };
        for &index in &w[4..] {
            match self.step(ty, self.constants.get(&index).copied(), plan) {
                Some((next, enters)) => (ty, inside) = (next, inside || enters),
                None if inside => return None,
                // A chain through what this pass does not follow: it reaches no stored member.
                None => return Some(()),
            }
        }
        if !inside {
            return Some(());
        }
        let stored = if self.is_column(ty) { Some(plan.vec4) } else { plan.stored.get(&ty).copied() };
        if let Some(stored) = stored {
            let pointer = plan.pointer(storage, stored);
            plan.chains.insert(at, pointer);
            plan.logical.insert(w[2], (storage, ty));
        }
        Some(())
    }

    /// Plans the extraction at `at` from a value holding a stored member: a matrix or column
    /// taken from the stored columns, or a part still holding one.
    fn plan_extract(&self, at: usize, w: &[u32], plan: &mut Plan) -> Option<()> {
        let (mut ty, mut inside) = (*self.type_of.get(&w[3])?, false);
        for &index in &w[4..] {
            let (next, enters) = self.step(ty, Some(index), plan)?;
            (ty, inside) = (next, inside || enters);
        }
        match (inside, self.matrices.contains_key(&ty) || self.is_column(ty)) {
            (true, true) => _ = plan.extracts.insert(at, ty),
            (true, false) if plan.stored.contains_key(&ty) => return None,
            (false, _) if self.holds_stored(ty, plan) => _ = plan.holding.insert(w[2]),
            _ => {}
        }
        Some(())
    }

    /// The type one index into `ty` reaches (`member`: the index's value, which a struct
    /// needs), and whether it enters a stored member; `None` for a type not followed.
    fn step(&self, ty: u32, member: Option<u32>, plan: &Plan) -> Option<(u32, bool)> {
        if let Some(types) = self.structs.get(&ty) {
            let k = member?;
            return Some((*types.get(k as usize)?, plan.members.contains(&(ty, k))));
        }
        let next = self.arrays.get(&ty).map(|a| a.0).or_else(|| self.matrices.get(&ty).map(|m| m.0));
        Some((next.or_else(|| self.vectors.get(&ty).map(|v| v.0))?, false))
    }

    /// Whether `ty` is a two-row matrix's column (a `vec2` of 32-bit floats).
    fn is_column(&self, ty: u32) -> bool {
        self.vectors.get(&ty).is_some_and(|&(c, n)| Some(c) == self.float32 && n == 2)
    }

    /// Whether a value of type `ty` holds a stored member (a struct or array loaded whole).
    fn holds_stored(&self, ty: u32, plan: &Plan) -> bool {
        if let Some(types) = self.structs.get(&ty) {
            return types.iter().enumerate().any(|(k, &t)| plan.members.contains(&(ty, k as u32)) || self.holds_stored(t, plan));
        }
        self.arrays.get(&ty).is_some_and(|&(e, _)| self.holds_stored(e, plan))
    }

    fn emit(&self, words: &[u32], plan: &mut Plan, insert_at: usize) -> Vec<u32> {
        let mut out = Vec::with_capacity(words.len() + plan.types.len() + plan.decorations.len() + 32 * plan.loads.len());
        out.extend_from_slice(&words[..HEADER_WORDS]);
        for (at, op, count) in instructions(words) {
            let w = &words[at..(at + count.max(1)).min(words.len())];
            if at == self.after_annotations {
                out.extend_from_slice(&plan.decorations);
            }
            if at == insert_at {
                out.extend_from_slice(&plan.types);
            }
            match op {
                OP_MEMBER_DECORATE if w.len() >= 4 && plan.members.contains(&(w[1], w[2])) => {
                    if ![MATRIX_STRIDE, ROW_MAJOR, COL_MAJOR].contains(&w[3]) {
                        out.extend_from_slice(w);
                    }
                }
                OP_TYPE_STRUCT if plan.members.iter().any(|(s, _)| *s == w[1]) => {
                    let (owner, mut w) = (w[1], w.to_vec());
                    for (k, ty) in w[2..].iter_mut().enumerate() {
                        if plan.members.contains(&(owner, k as u32)) {
                            *ty = plan.stored[ty];
                        }
                    }
                    out.extend_from_slice(&w);
                }
                _ if plan.chains.contains_key(&at) => {
                    out.push(w[0]);
                    out.push(plan.chains[&at]);
                    out.extend_from_slice(&w[2..]);
                }
                _ if plan.loads.contains_key(&at) => {
                    let logical = plan.loads[&at];
                    let whole = plan.fresh();
                    out.extend(instruction(OP_LOAD, &[self.stored_type(logical, plan), whole, w[3]]));
                    self.rebuild(whole, logical, w[2], plan, &mut out);
                }
                _ if plan.extracts.contains_key(&at) => {
                    let logical = plan.extracts[&at];
                    let whole = plan.fresh();
                    let mut operands = vec![self.stored_type(logical, plan), whole];
                    operands.extend_from_slice(&w[3..]);
                    out.extend(instruction(OP_COMPOSITE_EXTRACT, &operands));
                    self.rebuild(whole, logical, w[2], plan, &mut out);
                }
                _ => out.extend_from_slice(w),
            }
        }
        out[3] = plan.bound;
        out
    }

    /// The type a matrix or column declared `logical` is stored as.
    fn stored_type(&self, logical: u32, plan: &Plan) -> u32 {
        plan.stored.get(&logical).copied().unwrap_or(plan.vec4)
    }

    /// The value declared `logical` (a two-row matrix or a column) as `result`, from
    /// `whole`, its stored value (`vec4` columns, or one `vec4`).
    fn rebuild(&self, whole: u32, logical: u32, result: u32, plan: &mut Plan, out: &mut Vec<u32>) {
        let shuffle = Op::VectorShuffle as u16;
        let Some(&(column_type, columns)) = self.matrices.get(&logical) else {
            out.extend(instruction(shuffle, &[logical, result, whole, whole, 0, 1]));
            return;
        };
        let mut operands = vec![logical, result];
        for i in 0..columns {
            let (column, xy) = (plan.fresh(), plan.fresh());
            out.extend(instruction(OP_COMPOSITE_EXTRACT, &[plan.vec4, column, whole, i]));
            out.extend(instruction(shuffle, &[column_type, xy, column, column, 0, 1]));
            operands.push(xy);
        }
        out.extend(instruction(Op::CompositeConstruct as u16, &operands));
    }
}
