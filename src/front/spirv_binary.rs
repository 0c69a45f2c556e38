//! The SPIR-V glslang writes, read and edited as words before naga's SPIR-V front takes it:
//! the instruction walk, the `OpLine` in force at each offset ([`Lines`], which moves naga's
//! spans back to the user's lines), combined image samplers split into a texture and a
//! sampler, and the debug instructions naga does not read dropped.

use std::ops::Range;
use std::panic::{catch_unwind, AssertUnwindSafe};

use naga::Span;
use rspirv::spirv::{ImageFormat, Op};

use crate::front::reference::log::{self, LineTable};

/// SPIR-V opcodes read here (SPIR-V 1.0 §3.32), from rspirv's grammar.
pub(crate) const OP_SOURCE_CONTINUED: u16 = Op::SourceContinued as u16;
pub(crate) const OP_SOURCE: u16 = Op::Source as u16;
pub(crate) const OP_STRING: u16 = Op::String as u16;
pub(crate) const OP_LINE: u16 = Op::Line as u16;
pub(crate) const OP_FUNCTION: u16 = Op::Function as u16;
pub(crate) const OP_LABEL: u16 = Op::Label as u16;
pub(crate) const OP_FUNCTION_END: u16 = Op::FunctionEnd as u16;
pub(crate) const OP_TYPE_SAMPLED_IMAGE: u16 = Op::TypeSampledImage as u16;
pub(crate) const OP_NO_LINE: u16 = Op::NoLine as u16;
pub(crate) const OP_ENTRY_POINT: u16 = Op::EntryPoint as u16;
pub(crate) const OP_EXECUTION_MODE: u16 = Op::ExecutionMode as u16;
pub(crate) const OP_TYPE_FUNCTION: u16 = Op::TypeFunction as u16;
pub(crate) const OP_DECORATE: u16 = Op::Decorate as u16;
pub(crate) const OP_TYPE_POINTER: u16 = Op::TypePointer as u16;
pub(crate) const OP_UNDEF: u16 = Op::Undef as u16;
pub(crate) const OP_VARIABLE: u16 = Op::Variable as u16;
pub(crate) const OP_TYPE_ARRAY: u16 = Op::TypeArray as u16;
pub(crate) const OP_TYPE_INT: u16 = Op::TypeInt as u16;
pub(crate) const OP_TYPE_IMAGE: u16 = Op::TypeImage as u16;
/// `ImageFormat Unknown`: a storage image whose format the API's bound image gives.
const IMAGE_FORMAT_UNKNOWN: u32 = ImageFormat::Unknown as u32;
/// An opcode SPIR-V does not define, under which `OpUndef` waits out the sampler splitter.
pub(crate) const PARKED_UNDEF: u16 = 0xfffe;
/// Words in the SPIR-V header before the first instruction.
pub(crate) const HEADER_WORDS: usize = 5;

/// The words of instruction `op` with `operands` (its word count in the first word).
pub(crate) fn instruction(op: u16, operands: &[u32]) -> Vec<u32> {
    let mut out = vec![((operands.len() as u32 + 1) << 16) | u32::from(op)];
    out.extend_from_slice(operands);
    out
}

/// Whether instructions of `op` start with a result type and a result id (rspirv's grammar).
pub(crate) fn has_result_type(op: u16) -> bool {
    use rspirv::grammar::{CoreInstructionTable, OperandKind};
    CoreInstructionTable::lookup_opcode(op).is_some_and(|i| i.operands.first().is_some_and(|o| o.kind == OperandKind::IdResultType))
}

/// Each instruction of a SPIR-V binary: its first word's index, opcode and word count.
pub(crate) fn instructions(words: &[u32]) -> impl Iterator<Item = (usize, u16, usize)> + '_ {
    let mut i = HEADER_WORDS;
    std::iter::from_fn(move || {
        let w = *words.get(i)?;
        let (count, op) = ((w >> 16) as usize, (w & 0xffff) as u16);
        let at = i;
        i += count.max(1);
        Some((at, op, count))
    })
}

/// The `OpLine` in force at each point of a SPIR-V binary: (byte offset where it starts to
/// hold; the source string and line, or None after `OpNoLine` and at the end of a function).
pub(crate) struct Lines {
    pub(crate) changes: Vec<(usize, Option<(i64, i64)>)>,
    /// (offset as naga counts it, bytes naga's count lags behind the binary from there).
    lags: Vec<(usize, usize)>,
}

impl Lines {
    pub(crate) fn of(words: &[u32]) -> Lines {
        let mut strings: Vec<(u32, String)> = Vec::new();
        let mut changes = Vec::new();
        let mut lags = vec![(0, 0)];
        let mut lag = 0;
        for (at, op, count) in instructions(words) {
            let operands = words.get(at + 1..at + count).unwrap_or(&[]);
            // naga's SPIR-V front reads some operand lists past its byte count (the entry
            // point's interface, execution mode operands, a function type's parameters):
            // its spans lag behind the binary by those words from there on.
            let unread = match op {
                OP_ENTRY_POINT => {
                    count.saturating_sub(3 + operands.iter().skip(2).position(|w| w.to_le_bytes().contains(&0)).map_or(0, |i| i + 1))
                }
                OP_EXECUTION_MODE | OP_TYPE_FUNCTION => count.saturating_sub(3),
                _ => 0,
            };
            if unread > 0 {
                lag += unread * 4;
                lags.push(((at + count) * 4 - lag, lag));
            }
            match op {
                OP_STRING if !operands.is_empty() => {
                    let bytes: Vec<u8> = operands[1..].iter().flat_map(|w| w.to_le_bytes()).take_while(|b| *b != 0).collect();
                    strings.push((operands[0], String::from_utf8_lossy(&bytes).into_owned()));
                }
                OP_LINE if operands.len() >= 3 => {
                    // The first string is the stage's own text (string 0); another is a
                    // source string a `#line N "name"` or `#line N M` directive named.
                    let string = match strings.iter().position(|(id, _)| *id == operands[0]) {
                        Some(0) | None => 0,
                        Some(i) => strings[i].1.parse::<i64>().unwrap_or_else(|_| log::string_id(&strings[i].1)),
                    };
                    changes.push((at * 4, Some((string, i64::from(operands[1])))));
                }
                OP_NO_LINE | OP_FUNCTION_END => changes.push((at * 4, None)),
                _ => {}
            }
        }
        Lines { changes, lags }
    }

    /// The binary offset of what naga counts as offset `naga`.
    fn in_binary(&self, naga: usize) -> usize {
        let i = self.lags.partition_point(|(at, _)| *at <= naga);
        naga + i.checked_sub(1).map_or(0, |i| self.lags[i].1)
    }

    /// The user's line (trimmed) for a span naga gave in SPIR-V bytes.
    pub(crate) fn user_span(&self, span: Span, table: &LineTable, text: &str) -> Span {
        let Some(range) = span.to_range() else { return Span::UNDEFINED };
        self.binary_user_span(self.in_binary(range.start), table, text)
    }

    /// The user's line (trimmed) of the instruction at byte `start` of the binary.
    pub(crate) fn binary_user_span(&self, start: usize, table: &LineTable, text: &str) -> Span {
        let i = self.changes.partition_point(|(at, _)| *at <= start);
        let Some((string, line)) = i.checked_sub(1).and_then(|i| self.changes[i].1) else { return Span::UNDEFINED };
        match table.line_range(string, line) {
            Some(r) => Span::from(trimmed(text, r)),
            None => Span::UNDEFINED,
        }
    }
}

/// A line's range without its indentation and line break.
fn trimmed(text: &str, line: Range<usize>) -> Range<usize> {
    let body = &text[line.clone()];
    let start = line.start + (body.len() - body.trim_start().len());
    let end = line.start + body.trim_end().len();
    start..end.max(start)
}

/// Splits combined image samplers (absent from WGSL and naga) into a texture and a sampler
/// at the next binding, with `spirv_combimgsampsplitter` (panics contained).
///
/// The splitter removes the instructions it blanks out by their opcode, which it takes to
/// be `OpNop` but is `OpUndef` (1): every `OpUndef` of the stage would go with them, and
/// its uses be left undefined (glslang writes one for the value a non-void function
/// returns when its end is reachable without a `return`). They are parked under an opcode
/// SPIR-V does not define while the splitter works, and restored after.
pub(crate) fn split_combined_samplers(words: Vec<u32>) -> Result<Vec<u32>, String> {
    if !instructions(&words).any(|(_, op, _)| op == OP_TYPE_SAMPLED_IMAGE) {
        return Ok(words);
    }
    let parked = with_opcode(words, OP_UNDEF, PARKED_UNDEF);
    match catch_unwind(AssertUnwindSafe(|| spirv_combimgsampsplitter::combimgsampsplitter(&parked))) {
        Ok(Ok(split)) => Ok(with_opcode(split, PARKED_UNDEF, OP_UNDEF)),
        _ => Err("its combined image samplers could not be split into textures and samplers (arrays of samplers, or samplers passed in ways the splitter does not follow)".into()),
    }
}

/// Bindings of every stage of a program spaced so that the sampler split off each combined
/// image sampler (at its binding + 1) takes a binding no other resource holds: within a
/// descriptor set, a resource's binding grows by the number of combined samplers at lower
/// bindings in any stage of the program, so every stage keeps the same numbers. Without the
/// gap the splitter moves colliding bindings itself, in an order that changes from run to
/// run (its hash maps), and two resources could share one. Stages are left as they are
/// where no split sampler would collide.
pub(crate) fn space_bindings_for_split(stages: &mut [Vec<u32>]) {
    let decorations: Vec<Vec<Decoration>> = stages.iter().map(|w| resource_decorations(w)).collect();
    let mut combined: Vec<(u32, u32)> = decorations.iter().flatten().filter(|d| d.combined).map(|d| (d.set, d.binding)).collect();
    combined.sort_unstable();
    combined.dedup();
    let held = |set: u32, binding: u32| decorations.iter().flatten().any(|d| d.set == set && d.binding == binding);
    if !combined.iter().any(|&(set, binding)| held(set, binding + 1)) {
        return;
    }
    for (words, decorations) in stages.iter_mut().zip(&decorations) {
        for d in decorations {
            let below = combined.iter().filter(|&&(set, binding)| set == d.set && binding < d.binding).count();
            words[d.binding_word] = d.binding + u32::try_from(below).unwrap_or(0);
        }
    }
}

/// What a pass over a [`rspirv::dr::Module`] adds to it: fresh ids past the module's bound,
/// and global types and constants, each declared once (found among the module's own or the
/// added ones, else added after them).
pub(crate) struct Added {
    bound: u32,
    pub(crate) globals: Vec<rspirv::dr::Instruction>,
}

impl Added {
    pub(crate) fn of(module: &rspirv::dr::Module) -> Added {
        Added { bound: module.header.as_ref().map_or(0, |h| h.bound), globals: Vec::new() }
    }

    pub(crate) fn fresh(&mut self) -> u32 {
        self.bound += 1;
        self.bound - 1
    }

    /// The global `op` of type `ty` with `operands`, declared once.
    pub(crate) fn global(&mut self, module: &rspirv::dr::Module, op: Op, ty: Option<u32>, operands: Vec<rspirv::dr::Operand>) -> u32 {
        let same = |i: &&rspirv::dr::Instruction| i.class.opcode == op && i.result_type == ty && i.operands == operands;
        if let Some(r) = module.types_global_values.iter().chain(&self.globals).find(same).and_then(|i| i.result_id) {
            return r;
        }
        let r = self.fresh();
        self.globals.push(rspirv::dr::Instruction::new(op, ty, Some(r), operands));
        r
    }

    /// The global (the module's or an added one) that declares `id`.
    pub(crate) fn def<'a>(&'a self, module: &'a rspirv::dr::Module, id: u32) -> Option<&'a rspirv::dr::Instruction> {
        module.types_global_values.iter().chain(&self.globals).find(|i| i.result_id == Some(id))
    }

    /// The added globals put after the module's, and its bound raised past the fresh ids.
    pub(crate) fn add_to(&mut self, module: &mut rspirv::dr::Module) -> Option<()> {
        module.types_global_values.append(&mut self.globals);
        module.header.as_mut()?.bound = self.bound;
        Some(())
    }
}

/// The result type of every id that has one (globals, function parameters, instructions).
pub(crate) fn result_types(module: &rspirv::dr::Module) -> std::collections::HashMap<u32, u32> {
    let globals = module.types_global_values.iter();
    let bodies = module.functions.iter().flat_map(|f| f.parameters.iter().chain(f.blocks.iter().flat_map(|b| b.instructions.iter())));
    globals.chain(bodies).filter_map(|i| Some((i.result_id?, i.result_type?))).collect()
}

/// A word pass that rewrites a module instruction by instruction (every block of every
/// function, in order), each instruction into what `instruction` pushes in its place.
pub(crate) trait PerInstruction {
    fn module_mut(&mut self) -> &mut rspirv::dr::Module;
    /// `i` rewritten into `out`; None where the pass cannot take it (the module is then
    /// left as it was by the caller).
    fn instruction(&mut self, i: rspirv::dr::Instruction, out: &mut Vec<rspirv::dr::Instruction>) -> Option<()>;

    fn each_instruction(&mut self) -> Option<()> {
        for f in 0..self.module_mut().functions.len() {
            for b in 0..self.module_mut().functions[f].blocks.len() {
                let instructions = std::mem::take(&mut self.module_mut().functions[f].blocks[b].instructions);
                let mut out = Vec::new();
                for i in instructions {
                    self.instruction(i, &mut out)?;
                }
                self.module_mut().functions[f].blocks[b].instructions = out;
            }
        }
        Some(())
    }
}

/// A resource variable's set and binding decorations.
struct Decoration {
    set: u32,
    binding: u32,
    /// Index of the binding's word in the binary.
    binding_word: usize,
    /// The variable is a combined image sampler (or an array of them).
    combined: bool,
}

fn resource_decorations(words: &[u32]) -> Vec<Decoration> {
    const DESCRIPTOR_SET: u32 = rspirv::spirv::Decoration::DescriptorSet as u32;
    const BINDING: u32 = rspirv::spirv::Decoration::Binding as u32;
    let mut sets: Vec<(u32, u32)> = Vec::new();
    let mut bindings: Vec<(u32, u32, usize)> = Vec::new();
    let mut sampled_images: Vec<u32> = Vec::new();
    let mut pointers: Vec<(u32, u32)> = Vec::new();
    let mut variables: Vec<(u32, u32)> = Vec::new();
    for (at, op, count) in instructions(words) {
        let operand = |i: usize| words.get(at + i).copied().filter(|_| i < count);
        match op {
            OP_DECORATE => match (operand(1), operand(2), operand(3)) {
                (Some(id), Some(DESCRIPTOR_SET), Some(set)) => sets.push((id, set)),
                (Some(id), Some(BINDING), Some(binding)) => bindings.push((id, binding, at + 3)),
                _ => {}
            },
            OP_TYPE_SAMPLED_IMAGE => sampled_images.extend(operand(1)),
            OP_TYPE_ARRAY => {
                if let (Some(id), Some(element)) = (operand(1), operand(2)) {
                    if sampled_images.contains(&element) {
                        sampled_images.push(id);
                    }
                }
            }
            OP_TYPE_POINTER => pointers.extend(operand(1).zip(operand(3))),
            OP_VARIABLE => variables.extend(operand(2).zip(operand(1))),
            _ => {}
        }
    }
    bindings
        .into_iter()
        .map(|(id, binding, binding_word)| {
            let ty = variables.iter().find(|(v, _)| *v == id).and_then(|(_, p)| pointers.iter().find(|(q, _)| q == p)).map(|(_, t)| *t);
            Decoration {
                set: sets.iter().find(|(v, _)| *v == id).map_or(0, |(_, s)| *s),
                binding,
                binding_word,
                combined: ty.is_some_and(|t| sampled_images.contains(&t)),
            }
        })
        .collect()
}

/// `words` with every instruction of opcode `from` given opcode `to`.
fn with_opcode(mut words: Vec<u32>, from: u16, to: u16) -> Vec<u32> {
    let at: Vec<usize> = instructions(&words).filter(|(_, op, _)| *op == from).map(|(at, _, _)| at).collect();
    for i in at {
        words[i] = (words[i] & 0xffff_0000) | u32::from(to);
    }
    words
}

/// `words` without the debug instructions naga's SPIR-V front does not read: `OpLine` and
/// `OpNoLine` among the global declarations and in a function's header (before its first
/// `OpLabel`), where glslang also puts them, and the stage's source text (`OpSource`'s
/// text operand and `OpSourceContinued`); and a storage image without a format (naga reads
/// it as a sampled one) given the widest of its sampled type, as the GLSL route does
/// ([`chosen_image_format`](crate::front::syntax::chosen_image_format)); and the memory
/// decorations of images (`coherent`, `volatile` storage images), which naga takes on
/// buffers only: WGSL orders storage-texture accesses with its barriers alone.
pub(crate) fn readable_by_naga(words: Vec<u32>) -> Vec<u32> {
    const UNIFORM_CONSTANT: u32 = rspirv::spirv::StorageClass::UniformConstant as u32;
    const MEMORY: [u32; 2] = [rspirv::spirv::Decoration::Coherent as u32, rspirv::spirv::Decoration::Volatile as u32];
    let images: Vec<u32> = instructions(&words)
        .filter(|&(at, op, count)| op == OP_VARIABLE && count >= 4 && words[at + 3] == UNIFORM_CONSTANT)
        .map(|(at, _, _)| words[at + 2])
        .collect();
    let mut out = words[..HEADER_WORDS.min(words.len())].to_vec();
    let mut in_body = false;
    let mut integer_types: Vec<(u32, bool)> = Vec::new();
    for (at, op, count) in instructions(&words) {
        match op {
            // OpTypeInt result width signedness
            OP_TYPE_INT if count >= 4 => integer_types.push((words[at + 1], words[at + 3] == 1)),
            // OpTypeImage result sampled-type dim depth arrayed ms sampled format: a storage
            // image without a format (GL: the bound image's) gets the one naga needs (N0111).
            OP_TYPE_IMAGE if count >= 9 && words[at + 7] == 2 && words[at + 8] == IMAGE_FORMAT_UNKNOWN => {
                let format = match integer_types.iter().find(|(id, _)| *id == words[at + 2]) {
                    Some((_, true)) => ImageFormat::Rgba32i,
                    Some((_, false)) => ImageFormat::Rgba32ui,
                    None => ImageFormat::Rgba32f,
                };
                out.extend_from_slice(&words[at..at + 8]);
                out.push(format as u32);
                out.extend_from_slice(&words[at + 9..at + count]);
                continue;
            }
            OP_FUNCTION | OP_FUNCTION_END => in_body = false,
            OP_LABEL => in_body = true,
            OP_LINE | OP_NO_LINE if !in_body => continue,
            OP_DECORATE if count == 3 && MEMORY.contains(&words[at + 2]) && images.contains(&words[at + 1]) => continue,
            OP_SOURCE_CONTINUED => continue,
            // OpSource language version [file] [text]: the text goes.
            OP_SOURCE if count > 4 => {
                out.push((4 << 16) | u32::from(OP_SOURCE));
                out.extend_from_slice(&words[at + 1..at + 4]);
                continue;
            }
            _ => {}
        }
        out.extend_from_slice(&words[at..(at + count.max(1)).min(words.len())]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn instructions_walk_the_binary_after_the_header() {
        // header, OpNop (1 word), OpLine %1 7 3 (4 words), OpFunctionEnd (1 word)
        let words = [0x0723_0203, 0x0001_0000, 0, 10, 0, 0x0001_0000, (4 << 16) | 8, 1, 7, 3, (1 << 16) | 56];
        let ops: Vec<(usize, u16)> = instructions(&words).map(|(at, op, _)| (at, op)).collect();
        assert_eq!(ops, [(5, 0), (6, OP_LINE), (10, OP_FUNCTION_END)]);
        let lines = Lines::of(&words);
        assert_eq!(lines.changes, [(24, Some((0, 7))), (40, None)]);
    }

    #[test]
    fn spans_after_an_entry_point_interface_are_moved_by_what_naga_does_not_count() {
        // header, OpEntryPoint Fragment %4 "main" %5 %6 (7 words), OpLine %1 7 3, OpFunctionEnd
        let main = u32::from_le_bytes(*b"main");
        let words = [0x0723_0203, 0x0001_0000, 0, 10, 0, (7 << 16) | 15, 4, 4, main, 0, 5, 6, (4 << 16) | 8, 1, 7, 3, (1 << 16) | 56];
        let lines = Lines::of(&words);
        assert_eq!(lines.changes[0], (48, Some((0, 7))));
        // naga reads the two interface ids without counting them: it puts OpLine at 40.
        assert_eq!((lines.in_binary(20), lines.in_binary(40)), (20, 48));
    }

    #[test]
    fn a_span_takes_the_line_in_force() {
        let text = "#version 450\nvoid main() {\n    float x = 1.0;\n}\n";
        let table = LineTable::new(text);
        let lines = Lines { changes: vec![(24, Some((0, 3))), (40, None)], lags: vec![(0, 0)] };
        let at = |r: Range<usize>| lines.user_span(Span::from(r), &table, text).to_range();
        assert_eq!(at(28..32).map(|r| &text[r]), Some("float x = 1.0;"));
        assert_eq!(at(8..12), None, "before any OpLine");
        assert_eq!(at(44..48), None, "after the function ends");
    }
}
