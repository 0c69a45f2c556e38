//! Buffer textures and buffer images (`samplerBuffer`, `textureBuffer`, `imageBuffer`, and
//! their `i`/`u` forms) as storage buffers of texels, in the SPIR-V naga's SPIR-V front
//! reads: it reads no `Buffer` image dimension, and WebGPU has no texel buffers. Each such
//! variable becomes a storage buffer of one runtime-sized array of 4-vectors of its sampled
//! type (`struct { vec4 texels[]; }`, 16 bytes a texel, as the GLSL route declares one;
//! read-only for a buffer texture), at its own set and binding:
//! - `texelFetch` (`OpImageFetch`) and `imageLoad` (`OpImageRead`) read element `P`;
//! - `imageStore` (`OpImageWrite`) writes it;
//! - `textureSize`/`imageSize` (`OpImageQuerySize`) is the array's length.
//!
//! A texel buffer used otherwise (passed to a function, in an array, atomics through
//! `OpImageTexelPointer`) leaves the module as it is, for naga to refuse. The lengths change,
//! so this runs before [`Lines`] is taken.
//!
//! [`Lines`]: crate::front::spirv_binary::Lines

use std::collections::{BTreeMap, HashMap};

use rspirv::spirv::{Decoration, Dim, Op, StorageClass};

use crate::front::spirv_binary::{
    instruction, instructions, HEADER_WORDS, OP_FUNCTION, OP_TYPE_IMAGE, OP_TYPE_INT, OP_TYPE_POINTER, OP_TYPE_SAMPLED_IMAGE, OP_VARIABLE,
};

const OP_TYPE_VECTOR: u16 = Op::TypeVector as u16;
const OP_FUNCTION_PARAMETER: u16 = Op::FunctionParameter as u16;
const OP_LOAD: u16 = Op::Load as u16;
const OP_IMAGE: u16 = Op::Image as u16;
const OP_IMAGE_FETCH: u16 = Op::ImageFetch as u16;
const OP_IMAGE_READ: u16 = Op::ImageRead as u16;
const OP_IMAGE_WRITE: u16 = Op::ImageWrite as u16;
const OP_IMAGE_QUERY_SIZE: u16 = Op::ImageQuerySize as u16;

/// Instructions that could take a texel buffer (its variable or its value) in a way the
/// lowering does not follow.
const UNFOLLOWED: [u16; 9] = [
    Op::FunctionCall as u16,
    Op::CopyObject as u16,
    Op::SampledImage as u16,
    Op::ImageTexelPointer as u16,
    Op::ImageSparseFetch as u16,
    Op::ImageSparseRead as u16,
    Op::Phi as u16,
    Op::Select as u16,
    Op::Store as u16,
];

/// One lowered texel buffer: its variable and the 4-vector of its sampled type.
struct Lowered {
    element: u32,
    read_only: bool,
}

/// Ids the lowered module declares for each element type.
struct ElementTypes {
    array: u32,
    block: u32,
    block_pointer: u32,
    element_pointer: u32,
}

/// `words` with the module doc's texel buffers read from storage buffers.
pub(crate) fn texel_buffers_as_storage(words: Vec<u32>) -> Vec<u32> {
    let is_buffer_image = |at: usize, op: u16, count: usize| op == OP_TYPE_IMAGE && count >= 9 && words[at + 3] == Dim::DimBuffer as u32;
    if !instructions(&words).any(|(at, op, count)| is_buffer_image(at, op, count)) {
        return words;
    }
    lowered(&words).unwrap_or(words)
}

/// What the module declares that the lowering reads or adds to.
#[derive(Default)]
struct Scan {
    /// 32-bit integer types by signedness; vectors by (component type, count).
    ints: HashMap<bool, u32>,
    vectors: HashMap<(u32, u32), u32>,
    /// Buffer image types and sampled images of them: (sampled type, read-only).
    images: HashMap<u32, (u32, bool)>,
    /// Pointers to those (`UniformConstant`).
    pointers: HashMap<u32, u32>,
    /// Texel-buffer variables: (variable, (sampled type, read-only)).
    variables: Vec<(u32, (u32, bool))>,
}

/// The declarations of `words` the lowering needs, or None where a texel buffer is passed to
/// a function.
fn scan(words: &[u32]) -> Option<Scan> {
    let mut s = Scan::default();
    for (at, op, count) in instructions(words) {
        let w = &words[at..(at + count.max(1)).min(words.len())];
        match op {
            OP_TYPE_INT if w.len() == 4 && w[2] == 32 => {
                s.ints.entry(w[3] == 1).or_insert(w[1]);
            }
            OP_TYPE_VECTOR if w.len() == 4 => {
                s.vectors.entry((w[2], w[3])).or_insert(w[1]);
            }
            // OpTypeImage result sampled-type dim depth arrayed ms sampled format
            OP_TYPE_IMAGE if w.len() >= 9 && w[3] == Dim::DimBuffer as u32 => {
                s.images.insert(w[1], (w[2], w[7] == 1));
            }
            OP_TYPE_SAMPLED_IMAGE if w.len() == 3 => {
                if let Some(&image) = s.images.get(&w[2]) {
                    s.images.insert(w[1], image);
                }
            }
            OP_TYPE_POINTER if w.len() == 4 && w[2] == StorageClass::UniformConstant as u32 && s.images.contains_key(&w[3]) => {
                s.pointers.insert(w[1], w[3]);
            }
            OP_VARIABLE if w.len() >= 4 => {
                if let Some(image) = s.pointers.get(&w[1]).and_then(|p| s.images.get(p)).copied() {
                    s.variables.push((w[2], image));
                }
            }
            OP_FUNCTION_PARAMETER if w.len() >= 3 && (s.images.contains_key(&w[1]) || s.pointers.contains_key(&w[1])) => return None,
            _ => {}
        }
    }
    (!s.variables.is_empty()).then_some(s)
}

/// The lowering of one module: its scan, the ids it adds, the variables it lowers.
struct Lowering {
    scan: Scan,
    bound: u32,
    int: u32,
    uint: u32,
    zero: u32,
    /// Ordered: the declarations they add come out the same on every run.
    types: BTreeMap<u32, ElementTypes>,
    lowered: BTreeMap<u32, Lowered>,
    /// Ids a texel buffer is loaded as in functions (the load and `OpImage` of it).
    loaded: HashMap<u32, u32>,
}

impl Lowering {
    fn fresh(&mut self) -> u32 {
        self.bound += 1;
        self.bound - 1
    }

    fn new(words: &[u32], mut scan: Scan) -> Lowering {
        let mut l = Lowering {
            scan: Scan::default(),
            bound: words[3],
            int: 0,
            uint: 0,
            zero: 0,
            types: BTreeMap::new(),
            lowered: BTreeMap::new(),
            loaded: HashMap::new(),
        };
        l.int = scan.ints.get(&true).copied().unwrap_or_else(|| l.fresh());
        l.uint = scan.ints.get(&false).copied().unwrap_or_else(|| l.fresh());
        l.zero = l.fresh();
        // glslang declares a variable before types it does not need (its texels' 4-vector).
        for (var, (sampled, read_only)) in std::mem::take(&mut scan.variables) {
            let element = match scan.vectors.get(&(sampled, 4)) {
                Some(id) => *id,
                None => {
                    let id = l.fresh();
                    scan.vectors.insert((sampled, 4), id);
                    id
                }
            };
            if !l.types.contains_key(&element) {
                let t = ElementTypes { array: l.fresh(), block: l.fresh(), block_pointer: l.fresh(), element_pointer: l.fresh() };
                l.types.insert(element, t);
            }
            l.lowered.insert(var, Lowered { element, read_only });
        }
        l.scan = scan;
        l
    }

    /// Decorations of the new types and of read-only variables (before the first type).
    fn annotations(&self) -> Vec<u32> {
        let mut out = Vec::new();
        for t in self.types.values() {
            out.extend(instruction(Op::Decorate as u16, &[t.array, Decoration::ArrayStride as u32, 16]));
            out.extend(instruction(Op::Decorate as u16, &[t.block, Decoration::Block as u32]));
            out.extend(instruction(Op::MemberDecorate as u16, &[t.block, 0, Decoration::Offset as u32, 0]));
        }
        for var in self.lowered.iter().filter(|(_, l)| l.read_only).map(|(var, _)| var) {
            out.extend(instruction(Op::Decorate as u16, &[*var, Decoration::NonWritable as u32]));
        }
        out
    }

    /// The new types, the index constant and the storage-buffer variables (before the first
    /// function). `declared`: the element vectors the module declares itself.
    fn globals(&self, declared: &[u32]) -> Option<Vec<u32>> {
        let mut out = Vec::new();
        if !self.scan.ints.contains_key(&true) {
            out.extend(instruction(OP_TYPE_INT, &[self.int, 32, 1]));
        }
        if !self.scan.ints.contains_key(&false) {
            out.extend(instruction(OP_TYPE_INT, &[self.uint, 32, 0]));
        }
        out.extend(instruction(Op::Constant as u16, &[self.int, self.zero, 0]));
        for (element, t) in &self.types {
            if !declared.contains(element) {
                let sampled = self.scan.vectors.iter().find(|(_, id)| *id == element).map(|((s, _), _)| *s)?;
                out.extend(instruction(OP_TYPE_VECTOR, &[*element, sampled, 4]));
            }
            out.extend(instruction(Op::TypeRuntimeArray as u16, &[t.array, *element]));
            out.extend(instruction(Op::TypeStruct as u16, &[t.block, t.array]));
            out.extend(instruction(OP_TYPE_POINTER, &[t.block_pointer, StorageClass::StorageBuffer as u32, t.block]));
            out.extend(instruction(OP_TYPE_POINTER, &[t.element_pointer, StorageClass::StorageBuffer as u32, *element]));
        }
        for (var, l) in &self.lowered {
            out.extend(instruction(OP_VARIABLE, &[self.types[&l.element].block_pointer, *var, StorageClass::StorageBuffer as u32]));
        }
        Some(out)
    }

    /// What instruction `w` becomes: Some(words) (possibly none) where it declares or uses a
    /// texel buffer, None to keep it; Err where a use is not followed.
    fn rewritten(&mut self, op: u16, w: &[u32]) -> Result<Option<Vec<u32>>, ()> {
        let chain = |l: &Lowering, var: u32, pointer: u32, index: u32| {
            instruction(Op::AccessChain as u16, &[l.types[&l.lowered[&var].element].element_pointer, pointer, var, l.zero, index])
        };
        Ok(Some(match op {
            OP_TYPE_IMAGE | OP_TYPE_SAMPLED_IMAGE if self.scan.images.contains_key(&w[1]) => Vec::new(),
            OP_TYPE_POINTER if self.scan.pointers.contains_key(&w[1]) => Vec::new(),
            OP_VARIABLE if self.lowered.contains_key(&w[2]) => Vec::new(),
            OP_LOAD if w.len() >= 4 && self.lowered.contains_key(&w[3]) => {
                self.loaded.insert(w[2], w[3]);
                Vec::new()
            }
            OP_IMAGE if w.len() == 4 && self.loaded.contains_key(&w[3]) => {
                self.loaded.insert(w[2], self.loaded[&w[3]]);
                Vec::new()
            }
            OP_IMAGE_FETCH | OP_IMAGE_READ if w.len() >= 5 && self.loaded.contains_key(&w[3]) => {
                let var = self.loaded[&w[3]];
                if w[1] != self.lowered[&var].element {
                    return Err(());
                }
                let pointer = self.fresh();
                let mut out = chain(self, var, pointer, w[4]);
                out.extend(instruction(OP_LOAD, &[w[1], w[2], pointer]));
                out
            }
            OP_IMAGE_WRITE if w.len() >= 4 && self.loaded.contains_key(&w[1]) => {
                let var = self.loaded[&w[1]];
                let pointer = self.fresh();
                let mut out = chain(self, var, pointer, w[2]);
                out.extend(instruction(Op::Store as u16, &[pointer, w[3]]));
                out
            }
            OP_IMAGE_QUERY_SIZE if w.len() == 4 && self.loaded.contains_key(&w[3]) => {
                let var = self.loaded[&w[3]];
                if w[1] == self.uint {
                    instruction(Op::ArrayLength as u16, &[self.uint, w[2], var, 0])
                } else {
                    let length = self.fresh();
                    let mut out = instruction(Op::ArrayLength as u16, &[self.uint, length, var, 0]);
                    out.extend(instruction(Op::Bitcast as u16, &[w[1], w[2], length]));
                    out
                }
            }
            // Any other use of a texel buffer (atomics, copies, calls) is not followed.
            _ if UNFOLLOWED.contains(&op) && w[1..].iter().any(|id| self.loaded.contains_key(id) || self.lowered.contains_key(id)) => {
                return Err(())
            }
            _ => return Ok(None),
        }))
    }
}

fn lowered(words: &[u32]) -> Option<Vec<u32>> {
    let mut l = Lowering::new(words, scan(words)?);
    let declared: Vec<u32> = instructions(words)
        .filter(|&(at, op, count)| op == OP_TYPE_VECTOR && count == 4 && l.types.contains_key(&words[at + 1]))
        .map(|(at, ..)| words[at + 1])
        .collect();
    let mut out = words[..HEADER_WORDS].to_vec();
    let (mut annotated, mut declared_globals) = (false, false);
    for (at, op, count) in instructions(words) {
        let w = &words[at..(at + count.max(1)).min(words.len())];
        let is_type_or_value = (Op::TypeVoid as u16..=Op::TypeForwardPointer as u16).contains(&op) || op == OP_VARIABLE;
        if is_type_or_value && !annotated {
            annotated = true;
            out.extend(l.annotations());
        }
        if op == OP_FUNCTION && !declared_globals {
            declared_globals = true;
            out.extend(l.globals(&declared)?);
        }
        match l.rewritten(op, w).ok()? {
            Some(words) => out.extend(words),
            None => out.extend_from_slice(w),
        }
    }
    out[3] = l.bound;
    Some(out)
}
