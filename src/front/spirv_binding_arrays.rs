//! Arrays of textures, images and samplers (`uniform sampler2D textures[];`,
//! `texture2D t[4]`, `sampler s[2]`, `image2D images[]`) as one variable per element, in the
//! SPIR-V of a whole program before naga's SPIR-V front reads it: naga reads such arrays as
//! binding arrays, which WGSL has only behind an extension tint does not know, and the
//! sampler splitter takes no arrays.
//!
//! - An array sized in the text keeps its length; a runtime-sized one (bindless,
//!   `GL_EXT_nonuniform_qualifier`) gets [`RUNTIME_ELEMENTS`] elements. An array a stage
//!   never reads is left out of that stage.
//! - Element `k` of an array at binding `b` takes binding `b + k`; every other resource of
//!   the set at a higher binding moves up by the elements added below it, in every stage
//!   alike.
//! - An element read at a constant index is that element's variable. A value computed from
//!   an element chosen at run time (`texture(textures[nonuniformEXT(i)], uv)`,
//!   `imageLoad(images[i], p)`, `textureSize`) is computed from every element and the
//!   indexed one kept (`OpSelect`), as the GLSL route's choice among elements does; from
//!   elements of two arrays (`sampler2D(textures[i], samplers[j])`), from every pair. An
//!   index past the end reads the last element (GL leaves it undefined).
//! - A copy of an opaque value (glslang's `nonuniformEXT(sampler2D(…))`) is the value.
//!
//! - A store to an element chosen at run time (`imageStore(images[i], p, v)`) is a `switch`
//!   on the index with one case per element.
//!
//! An array used otherwise (passed to a function, a store in a loop's header block, arrays
//! of arrays) leaves every stage of the program as it was, for naga's binding arrays.

use std::collections::{BTreeMap, HashMap, HashSet};

use rspirv::binary::Assemble;
use rspirv::dr::{self, Instruction, Operand};
use rspirv::spirv::{Decoration, Op, StorageClass, Word};

use crate::front::spirv_binary::{result_types, Added};
use crate::front::spirv_interface_blocks::name_of;

/// Elements given an array of textures or samplers whose length the text leaves to run time.
pub(crate) const RUNTIME_ELEMENTS: u32 = 4;

/// One array variable of a stage.
#[derive(Debug, Clone)]
struct ArrayVariable {
    variable: Word,
    set: u32,
    binding: u32,
    element: Word,
    /// The declared length, None for a runtime-sized array.
    length: Option<u32>,
    name: String,
}

/// Every stage of a program (`stages`, SPIR-V words) with its arrays of textures and
/// samplers made one variable per element, as the module doc says; unchanged where any
/// stage uses one in a way this does not follow.
pub(crate) fn binding_arrays_as_elements(stages: &mut [Vec<u32>]) {
    let Some(modules) = stages.iter().map(|w| dr::load_words(w).ok()).collect::<Option<Vec<dr::Module>>>() else { return };
    let arrays: Vec<Vec<ArrayVariable>> = modules.iter().map(array_variables).collect();
    if arrays.iter().all(Vec::is_empty) {
        return;
    }
    let mut moved = Bindings { arrays: BTreeMap::new() };
    for a in arrays.iter().flatten() {
        let n = moved.arrays.entry((a.set, a.binding)).or_default().entry(a.name.clone()).or_insert(1);
        *n = (*n).max(a.length.unwrap_or(RUNTIME_ELEMENTS)).max(1);
    }
    let mut out = Vec::new();
    for (module, arrays) in modules.into_iter().zip(&arrays) {
        match Rewrite::new(module, &moved).run(arrays) {
            Some(words) => out.push(words),
            None => return,
        }
    }
    for (words, new) in stages.iter_mut().zip(out) {
        *words = new;
    }
}

/// The program's arrays, by (set, binding), with their element counts by name: Vulkan lets
/// arrays of different types alias one binding (a bindless table read as 2D, 3D and cube
/// textures), WebGPU does not, so aliases take consecutive elements, in order of name.
struct Bindings {
    arrays: BTreeMap<(u32, u32), BTreeMap<String, u32>>,
}

impl Bindings {
    /// Where a resource at (`set`, `binding`) moves: up by the elements the arrays below it
    /// in its set add.
    fn moved(&self, set: u32, binding: u32) -> u32 {
        let below = self.arrays.iter().filter(|((s, b), _)| *s == set && *b < binding);
        binding + below.map(|(_, named)| named.values().sum::<u32>() - 1).sum::<u32>()
    }

    /// The elements of the array `name` at (`set`, `binding`): its first binding and count.
    fn elements(&self, set: u32, binding: u32, name: &str) -> (u32, u32) {
        let named = self.arrays.get(&(set, binding));
        let before: u32 = named.map_or(0, |n| n.range(..name.to_string()).map(|(_, c)| c).sum());
        (self.moved(set, binding) + before, named.and_then(|n| n.get(name)).copied().unwrap_or(1))
    }
}

fn id(o: &Operand) -> Option<Word> {
    match o {
        Operand::IdRef(i) => Some(*i),
        _ => None,
    }
}

fn literal(o: &Operand) -> Option<u32> {
    match o {
        Operand::LiteralBit32(v) => Some(*v),
        _ => None,
    }
}

/// Set and binding decorations of every decorated id.
fn resource_bindings(module: &dr::Module) -> HashMap<Word, (u32, u32)> {
    let mut sets = HashMap::new();
    let mut bindings = HashMap::new();
    for a in module.annotations.iter().filter(|a| a.class.opcode == Op::Decorate) {
        let (Some(target), Some(Operand::Decoration(d)), Some(value)) =
            (a.operands.first().and_then(id), a.operands.get(1), a.operands.get(2).and_then(literal))
        else {
            continue;
        };
        match d {
            Decoration::DescriptorSet => drop(sets.insert(target, value)),
            Decoration::Binding => drop(bindings.insert(target, value)),
            _ => {}
        }
    }
    bindings.into_iter().map(|(v, b)| (v, (sets.get(&v).copied().unwrap_or(0), b))).collect()
}

fn is_opaque(module: &dr::Module, ty: Word) -> bool {
    module
        .types_global_values
        .iter()
        .any(|i| i.result_id == Some(ty) && matches!(i.class.opcode, Op::TypeSampler | Op::TypeSampledImage | Op::TypeImage))
}

/// The uniform arrays of textures, images, sampled images or samplers `module` declares.
fn array_variables(module: &dr::Module) -> Vec<ArrayVariable> {
    let bindings = resource_bindings(module);
    let def = |ty: Word| module.types_global_values.iter().find(|i| i.result_id == Some(ty));
    let constant = |c: Word| def(c).filter(|i| i.class.opcode == Op::Constant).and_then(|i| i.operands.first().and_then(literal));
    let mut out = Vec::new();
    for v in module.types_global_values.iter().filter(|i| i.class.opcode == Op::Variable) {
        let (Some(variable), Some(pointer)) = (v.result_id, v.result_type) else { continue };
        let Some(p) = def(pointer).filter(|p| p.operands.first() == Some(&Operand::StorageClass(StorageClass::UniformConstant))) else {
            continue;
        };
        let Some(array) = p.operands.get(1).and_then(id).and_then(def) else { continue };
        let (element, length) = match array.class.opcode {
            Op::TypeArray => match (array.operands.first().and_then(id), array.operands.get(1).and_then(id).and_then(constant)) {
                (Some(e), Some(n)) => (e, Some(n)),
                _ => continue,
            },
            Op::TypeRuntimeArray => match array.operands.first().and_then(id) {
                Some(e) => (e, None),
                None => continue,
            },
            _ => continue,
        };
        let Some(&(set, binding)) = bindings.get(&variable) else { continue };
        if is_opaque(module, element) {
            let name = name_of(module, variable, None).unwrap_or_default();
            out.push(ArrayVariable { variable, set, binding, element, length, name });
        }
    }
    out
}

/// One stage's rewrite in progress.
struct Rewrite<'b> {
    module: dr::Module,
    moved: &'b Bindings,
    added: Added,
    /// Result types of every id with one (globals, parameters, function instructions).
    types: HashMap<Word, Word>,
}

/// A pointer to an element chosen at run time: its array's element variables and the index.
#[derive(Clone)]
struct Chosen {
    elements: Vec<Word>,
    index: Word,
}

impl<'b> Rewrite<'b> {
    fn new(module: dr::Module, moved: &'b Bindings) -> Rewrite<'b> {
        Rewrite { types: result_types(&module), added: Added::of(&module), module, moved }
    }

    fn fresh(&mut self) -> Word {
        self.added.fresh()
    }

    fn global(&mut self, op: Op, ty: Option<Word>, operands: Vec<Operand>) -> Word {
        self.added.global(&self.module, op, ty, operands)
    }

    /// The words of the rewritten stage, or None where an array is used otherwise.
    fn run(mut self, arrays: &[ArrayVariable]) -> Option<Vec<u32>> {
        let bindings = resource_bindings(&self.module);
        // Every other resource moves up past the elements added below it.
        for a in self.module.annotations.iter_mut().filter(|a| a.class.opcode == Op::Decorate) {
            let target = a.operands.first().and_then(id);
            if a.operands.get(1) == Some(&Operand::Decoration(Decoration::Binding)) && !arrays.iter().any(|x| Some(x.variable) == target) {
                if let Some(&(set, binding)) = target.and_then(|t| bindings.get(&t)) {
                    a.operands[2] = Operand::LiteralBit32(self.moved.moved(set, binding));
                }
            }
        }
        // An array the stage never reads is left out, as naga would leave it unused.
        let read: HashSet<Word> = self
            .module
            .functions
            .iter()
            .flat_map(|f| f.blocks.iter().flat_map(|b| b.instructions.iter()))
            .flat_map(|i| i.operands.iter().filter_map(id))
            .collect();
        let mut elements: HashMap<Word, Vec<Word>> = HashMap::new();
        for a in arrays.iter().filter(|a| read.contains(&a.variable)) {
            elements.insert(a.variable, self.element_variables(a));
        }
        let removed: HashSet<Word> = arrays.iter().map(|a| a.variable).collect();
        // The arrays' pointer types, then the array types, go too where nothing else names
        // them (naga would still make a binding-array type of each).
        let pointers: Vec<Word> = self
            .module
            .types_global_values
            .iter()
            .filter(|i| removed.contains(&i.result_id.unwrap_or(0)))
            .filter_map(|i| i.result_type)
            .collect();
        self.module.types_global_values.retain(|i| !i.result_id.is_some_and(|r| removed.contains(&r)));
        for p in pointers {
            let array =
                self.module.types_global_values.iter().find(|i| i.result_id == Some(p)).and_then(|i| i.operands.get(1).and_then(id));
            self.drop_unnamed(p);
            if let Some(a) = array {
                self.drop_unnamed(a);
            }
        }
        self.module.annotations.retain(|a| !a.operands.first().and_then(id).is_some_and(|t| removed.contains(&t)));
        self.module.debug_names.retain(|n| !n.operands.first().and_then(id).is_some_and(|t| removed.contains(&t)));
        for ep in &mut self.module.entry_points {
            ep.operands.retain(|o| !id(o).is_some_and(|t| removed.contains(&t)));
        }
        let mut gone = removed;
        for f in 0..self.module.functions.len() {
            let blocks = std::mem::take(&mut self.module.functions[f].blocks);
            let mut rewritten = Vec::new();
            let mut state = Uses { chosen: HashMap::new(), opaque: HashMap::new(), same: HashMap::new() };
            // Blocks split at a store to an element chosen at run time: (label, last part's label).
            let mut split: HashMap<Word, Word> = HashMap::new();
            for block in blocks {
                let parts = self.block(block, &elements, &mut state)?;
                let labels = |b: &dr::Block| b.label.as_ref().and_then(|l| l.result_id);
                if let (Some(first), Some(last)) = (parts.first().and_then(labels), parts.last().and_then(labels)) {
                    if first != last {
                        split.insert(first, last);
                    }
                }
                rewritten.extend(parts);
            }
            // A φ names the predecessor its value comes from: now the split block's last part.
            for i in rewritten.iter_mut().flat_map(|b| b.instructions.iter_mut()).filter(|i| i.class.opcode == Op::Phi) {
                for parent in i.operands.iter_mut().skip(1).step_by(2) {
                    if let Some(last) = id(parent).and_then(|p| split.get(&p)) {
                        *parent = Operand::IdRef(*last);
                    }
                }
            }
            gone.extend(state.chosen.keys().chain(state.opaque.keys()).chain(state.same.keys()));
            for i in rewritten.iter_mut().flat_map(|b| b.instructions.iter_mut()) {
                for o in &mut i.operands {
                    if let Some(e) = id(o).and_then(|x| state.same.get(&x)) {
                        *o = Operand::IdRef(*e);
                    }
                }
            }
            self.module.functions[f].blocks = rewritten;
        }
        // Nothing may still name a removed id: an array passed whole, a value across a φ.
        let bodies = self.module.functions.iter().flat_map(|f| f.blocks.iter().flat_map(|b| b.instructions.iter()));
        if bodies.flat_map(|i| i.operands.iter()).any(|o| id(o).is_some_and(|x| gone.contains(&x))) {
            return None;
        }
        self.module.annotations.retain(|a| !a.operands.first().and_then(id).is_some_and(|t| gone.contains(&t)));
        self.added.add_to(&mut self.module)?;
        Some(self.module.assemble())
    }

    /// The global declaring `ty` taken out, where no instruction names it.
    fn drop_unnamed(&mut self, ty: Word) {
        let globals = self.module.types_global_values.iter();
        let bodies =
            self.module.functions.iter().flat_map(|f| f.parameters.iter().chain(f.blocks.iter().flat_map(|b| b.instructions.iter())));
        let named = globals.chain(bodies).any(|i| i.result_type == Some(ty) || i.operands.iter().any(|o| id(o) == Some(ty)));
        let decorated = self.module.annotations.iter().any(|a| a.operands.first().and_then(id) == Some(ty));
        if !named && !decorated {
            self.module.types_global_values.retain(|i| i.result_id != Some(ty));
            self.module.debug_names.retain(|n| n.operands.first().and_then(id) != Some(ty));
        }
    }

    /// One variable per element of `a`, with its name, set and binding.
    fn element_variables(&mut self, a: &ArrayVariable) -> Vec<Word> {
        let (first, count) = self.moved.elements(a.set, a.binding, &a.name);
        let pointer =
            self.global(Op::TypePointer, None, vec![Operand::StorageClass(StorageClass::UniformConstant), Operand::IdRef(a.element)]);
        let mut out = Vec::new();
        for k in 0..count {
            let v = self.fresh();
            self.added.globals.push(Instruction::new(
                Op::Variable,
                Some(pointer),
                Some(v),
                vec![Operand::StorageClass(StorageClass::UniformConstant)],
            ));
            let decorate = |d: Decoration, value: u32| {
                Instruction::new(Op::Decorate, None, None, vec![Operand::IdRef(v), Operand::Decoration(d), Operand::LiteralBit32(value)])
            };
            self.module.annotations.push(decorate(Decoration::DescriptorSet, a.set));
            self.module.annotations.push(decorate(Decoration::Binding, first + k));
            if !a.name.is_empty() {
                let name = Operand::LiteralString(format!("{}_{k}", a.name));
                self.module.debug_names.push(Instruction::new(Op::Name, None, None, vec![Operand::IdRef(v), name]));
            }
            out.push(v);
        }
        out
    }
}

/// What a function's rewrite has seen: pointers to elements chosen at run time, the opaque
/// values made from them (held back, made again per element where a value is computed),
/// and ids that stand for another (an element read at a constant index, a copy of an opaque
/// value: glslang's `nonuniformEXT(sampler2D(t[i], s))`, which naga's SPIR-V front reads
/// no copy of).
struct Uses {
    chosen: HashMap<Word, Chosen>,
    opaque: HashMap<Word, Instruction>,
    same: HashMap<Word, Word>,
}

impl Uses {
    /// The chosen pointers an instruction reads, directly or through held-back values, in
    /// order of first use.
    fn roots(&self, i: &Instruction, found: &mut Vec<Word>) {
        for x in i.operands.iter().filter_map(id) {
            if self.chosen.contains_key(&x) {
                if !found.contains(&x) {
                    found.push(x);
                }
            } else if let Some(inner) = self.opaque.get(&x) {
                self.roots(inner, found);
            }
        }
    }
}

impl Rewrite<'_> {
    /// A block's instructions with element pointers resolved and every value computed from
    /// elements chosen at run time made per element and selected.
    fn block(&mut self, block: dr::Block, elements: &HashMap<Word, Vec<Word>>, uses: &mut Uses) -> Option<Vec<dr::Block>> {
        let header = block.instructions.iter().any(|i| i.class.opcode == Op::LoopMerge);
        let mut parts = Vec::new();
        let mut label = block.label;
        let mut out = Vec::new();
        for mut i in block.instructions {
            for o in &mut i.operands {
                if let Some(e) = id(o).and_then(|x| uses.same.get(&x)) {
                    *o = Operand::IdRef(*e);
                }
            }
            let base = i.operands.first().and_then(id);
            if matches!(i.class.opcode, Op::AccessChain | Op::InBoundsAccessChain) && base.is_some_and(|b| elements.contains_key(&b)) {
                let element_variables = &elements[&base?];
                let [_, Operand::IdRef(index)] = i.operands[..] else { return None };
                let result = i.result_id?;
                match self.constant_value(index) {
                    Some(k) => drop(uses.same.insert(result, element_variables[(k as usize).min(element_variables.len() - 1)])),
                    None => drop(uses.chosen.insert(result, Chosen { elements: element_variables.clone(), index })),
                }
                continue;
            }
            if let (Op::CopyObject, Some(ty), Some(r), [Operand::IdRef(x)]) = (i.class.opcode, i.result_type, i.result_id, &i.operands[..])
            {
                if is_opaque(&self.module, ty) {
                    uses.same.insert(r, *x);
                    continue;
                }
            }
            let mut roots = Vec::new();
            uses.roots(&i, &mut roots);
            if roots.is_empty() {
                out.push(i);
                continue;
            }
            if i.class.opcode == Op::ImageWrite && !header {
                let [root] = roots[..] else { return None };
                let chosen = uses.chosen[&root].clone();
                let merge = self.store_per_element(&i, root, &chosen, uses, &mut out);
                parts.push(dr::Block { label: label.take(), instructions: std::mem::take(&mut out) });
                parts.extend(merge.1);
                label = Some(Instruction::new(Op::Label, None, Some(merge.0), vec![]));
                continue;
            }
            let (Some(result), Some(ty)) = (i.result_id, i.result_type) else { return None };
            if is_opaque(&self.module, ty) {
                uses.opaque.insert(result, i);
                continue;
            }
            let width = self.vector_width(ty)?;
            let chosen: Vec<(Word, Chosen)> = roots.iter().map(|r| (*r, uses.chosen[r].clone())).collect();
            self.chosen_value(&i, &chosen, width, Some(result), &mut HashMap::new(), uses, &mut out)?;
        }
        parts.push(dr::Block { label, instructions: out });
        Some(parts)
    }

    /// A store (`imageStore`) to the element of `root` chosen at run time: `out` (the
    /// block so far) ends in a switch on the index with one case per element (an index past
    /// the end: the last), each storing to its element; returns the label the blocks meet
    /// at, where the rest of the block goes, and the case blocks.
    fn store_per_element(
        &mut self,
        i: &Instruction,
        root: Word,
        chosen: &Chosen,
        uses: &Uses,
        out: &mut Vec<Instruction>,
    ) -> (Word, Vec<dr::Block>) {
        let merge = self.fresh();
        let cases: Vec<Word> = chosen.elements.iter().map(|_| self.fresh()).collect();
        out.push(Instruction::new(
            Op::SelectionMerge,
            None,
            None,
            vec![Operand::IdRef(merge), Operand::SelectionControl(rspirv::spirv::SelectionControl::NONE)],
        ));
        let last = *cases.last().expect("an array has an element");
        let mut switch = vec![Operand::IdRef(chosen.index), Operand::IdRef(last)];
        for (k, case) in cases.iter().enumerate().take(cases.len() - 1) {
            switch.extend([Operand::LiteralBit32(k as u32), Operand::IdRef(*case)]);
        }
        out.push(Instruction::new(Op::Switch, None, None, switch));
        let mut blocks = Vec::new();
        for (case, element) in cases.iter().zip(&chosen.elements) {
            let mut body = Vec::new();
            self.remade(i, &HashMap::from([(root, *element)]), uses, &mut HashMap::new(), &mut body);
            body.push(Instruction::new(Op::Branch, None, None, vec![Operand::IdRef(merge)]));
            blocks.push(dr::Block { label: Some(Instruction::new(Op::Label, None, Some(*case), vec![])), instructions: body });
        }
        (merge, blocks)
    }

    /// `i` (a value computed from elements chosen at run time: `chosen`, the roots not yet
    /// fixed) for every element of the first root, the indexed one kept: under `result`, or
    /// a new id. `fixed` holds the element each earlier root stands for.
    #[allow(clippy::too_many_arguments)]
    fn chosen_value(
        &mut self,
        i: &Instruction,
        chosen: &[(Word, Chosen)],
        width: Option<u32>,
        result: Option<Word>,
        fixed: &mut HashMap<Word, Word>,
        uses: &Uses,
        out: &mut Vec<Instruction>,
    ) -> Option<Word> {
        let Some(((root, first), rest)) = chosen.split_first() else {
            let made = self.remade(i, fixed, uses, &mut HashMap::new(), out);
            if let Some(r) = result {
                out.push(Instruction::new(Op::CopyObject, i.result_type, Some(r), vec![Operand::IdRef(made)]));
                return Some(r);
            }
            return Some(made);
        };
        let ty = i.result_type?;
        let index_type = self.types.get(&first.index).copied()?;
        let boolean = self.global(Op::TypeBool, None, vec![]);
        let mut values = Vec::new();
        for &element in &first.elements {
            fixed.insert(*root, element);
            values.push(self.chosen_value(i, rest, width, None, fixed, uses, out)?);
        }
        fixed.remove(root);
        let (&last, earlier) = values.split_last()?;
        if earlier.is_empty() {
            return Some(match result {
                Some(r) => {
                    out.push(Instruction::new(Op::CopyObject, Some(ty), Some(r), vec![Operand::IdRef(last)]));
                    r
                }
                None => last,
            });
        }
        let mut acc = last;
        for (k, &value) in earlier.iter().enumerate().rev() {
            let constant = self.global(Op::Constant, Some(index_type), vec![Operand::LiteralBit32(k as u32)]);
            let equal = self.fresh();
            out.push(Instruction::new(Op::IEqual, Some(boolean), Some(equal), vec![Operand::IdRef(first.index), Operand::IdRef(constant)]));
            // SPIR-V 1.3 chooses between vectors by a vector of conditions.
            let condition = match width {
                Some(n) => {
                    let bvec = self.global(Op::TypeVector, None, vec![Operand::IdRef(boolean), Operand::LiteralBit32(n)]);
                    let c = self.fresh();
                    out.push(Instruction::new(Op::CompositeConstruct, Some(bvec), Some(c), vec![Operand::IdRef(equal); n as usize]));
                    c
                }
                None => equal,
            };
            let r = match (k, result) {
                (0, Some(r)) => r,
                _ => self.fresh(),
            };
            out.push(Instruction::new(
                Op::Select,
                Some(ty),
                Some(r),
                vec![Operand::IdRef(condition), Operand::IdRef(value), Operand::IdRef(acc)],
            ));
            acc = r;
        }
        Some(acc)
    }

    /// `i` made again with each chosen pointer it reads standing for the element `fixed`
    /// gives, the opaque values it reads made first; its new id.
    fn remade(
        &mut self,
        i: &Instruction,
        fixed: &HashMap<Word, Word>,
        uses: &Uses,
        made: &mut HashMap<Word, Word>,
        out: &mut Vec<Instruction>,
    ) -> Word {
        let mut copy = i.clone();
        for o in &mut copy.operands {
            let Some(x) = id(o) else { continue };
            if let Some(element) = fixed.get(&x) {
                *o = Operand::IdRef(*element);
            } else if let Some(inner) = uses.opaque.get(&x) {
                let r = match made.get(&x) {
                    Some(r) => *r,
                    None => {
                        let r = self.remade(inner, fixed, uses, made, out);
                        made.insert(x, r);
                        r
                    }
                };
                *o = Operand::IdRef(r);
            }
        }
        // A store has no result: its id is only a placeholder the caller ignores.
        let r = self.fresh();
        if copy.result_id.is_some() {
            copy.result_id = Some(r);
        }
        out.push(copy);
        r
    }

    /// The value of a 32-bit integer constant.
    fn constant_value(&self, c: Word) -> Option<u32> {
        let i = self.module.types_global_values.iter().find(|i| i.result_id == Some(c))?;
        (i.class.opcode == Op::Constant).then(|| i.operands.first().and_then(literal)).flatten()
    }

    /// Some(None) for a scalar type, Some(Some(n)) for a vector of n, None for the others
    /// (which `OpSelect` cannot choose between in SPIR-V 1.3).
    fn vector_width(&self, ty: Word) -> Option<Option<u32>> {
        let i = self.module.types_global_values.iter().find(|i| i.result_id == Some(ty))?;
        match i.class.opcode {
            Op::TypeFloat | Op::TypeInt | Op::TypeBool => Some(None),
            Op::TypeVector => Some(i.operands.get(1).and_then(literal)),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn resources_above_an_array_move_up_by_its_added_elements() {
        let named = |n: &[(&str, u32)]| n.iter().map(|(k, v)| (k.to_string(), *v)).collect::<BTreeMap<String, u32>>();
        let moved = Bindings {
            arrays: BTreeMap::from([
                ((0, 2), named(&[("t", 8)])),
                ((0, 5), named(&[("s", 2)])),
                ((1, 0), named(&[("cube", 1), ("flat", 3)])),
            ]),
        };
        assert_eq!(moved.moved(0, 1), 1);
        assert_eq!(moved.moved(0, 2), 2, "the array's first element keeps its binding");
        assert_eq!(moved.moved(0, 3), 10);
        assert_eq!(moved.moved(0, 6), 14, "past both arrays");
        assert_eq!(moved.moved(1, 1), 4);
        assert_eq!(moved.moved(2, 1), 1, "another set");
        assert_eq!(moved.elements(1, 0, "cube"), (0, 1), "aliases of one binding take consecutive elements");
        assert_eq!(moved.elements(1, 0, "flat"), (1, 3));
        assert_eq!(moved.elements(0, 2, "t"), (2, 8));
    }
}
