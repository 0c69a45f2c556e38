//! Structs in the user's std140 uniform blocks, laid out as std140 lays them out. naga
//! aligns a struct to its largest member and sizes it to that alignment; std140 aligns a
//! struct (and an array of structs) to 16 bytes and rounds its size up to 16, and WGSL's
//! uniform rules want the same, so naga refused such a block. Float fillers
//! (`effectc_pad_<struct or block>_<byte>`, which reflection marks as padding) go where
//! std140 leaves a gap: before a struct member, inside a struct or in the block, at a
//! struct's end, and at the end of a block declared as an array (`uniform B { float v; }
//! b[4];`: each element is a buffer of its own, naga's IR an array of 16-byte stride).
//! Every offset is then std140's, so the bytes a host packs by std140 read the same.
//!
//! Only what the fillers can make exact is touched: members that are scalars, vectors,
//! matrices with 3- or 4-row columns (16-byte column strides in both layouts), such structs,
//! and arrays of such structs. A block with anything else, or with a struct the program
//! constructs (its constructor would change), passes between stages or the shared uniform
//! block also holds, is left as written.

use std::collections::BTreeMap;

use super::Ctx;
use crate::front::syntax::{GlslType, Member, Storage, StructDef};

/// Fillers to insert: (offset in the stage's text, how many floats, the struct or block and
/// the byte offset of the first, which name them the same in every stage and apart from
/// every other filler, members of blocks without an instance name being globals).
type Fillers = Vec<(usize, u32, String, u32)>;

/// (size, alignment) of a non-struct member type, the same in naga's layout and std140's
/// (64-bit types only once they are taken as 32-bit ones, `doubles`).
fn plain_layout(ty: &GlslType, doubles: bool) -> Option<(u32, u32)> {
    if ty.is_array() {
        return None;
    }
    let base = match ty.base.as_str() {
        "double" if doubles => "float",
        "dvec2" if doubles => "vec2",
        "dvec3" if doubles => "vec3",
        "dvec4" if doubles => "vec4",
        other => other,
    };
    Some(match base {
        "float" | "int" | "uint" => (4, 4),
        "vec2" | "ivec2" | "uvec2" => (8, 8),
        "vec3" | "ivec3" | "uvec3" => (12, 16),
        "vec4" | "ivec4" | "uvec4" => (16, 16),
        "mat3" | "mat3x3" | "mat4x3" | "mat2x3" => (16 * columns(&ty.base), 16),
        "mat4" | "mat4x4" | "mat3x4" | "mat2x4" => (16 * columns(&ty.base), 16),
        _ => return None,
    })
}

/// Columns of a matrix type name (`mat3x4` has 3).
fn columns(base: &str) -> u32 {
    base.as_bytes().get(3).map_or(0, |c| u32::from(c - b'0'))
}

/// The std140 plan of the structs one block needs: each struct's size and its fillers.
struct Layouts<'a> {
    structs: &'a [StructDef],
    /// A struct that cannot be padded (constructed, shared, or with members the fillers
    /// cannot make exact).
    refused: &'a dyn Fn(&str) -> bool,
    /// The program's doubles are taken as floats.
    doubles: bool,
    sizes: BTreeMap<String, u32>,
    fillers: Fillers,
}

impl Layouts<'_> {
    /// std140 size and alignment of `ty` (a struct is padded on the way) and whether it is
    /// 16-aligned there while naga aligns it less (a struct, an array of structs). In the
    /// block itself (`in_block`) an array of scalars or vectors has std140's 16-byte stride
    /// too ([`block_members`](super::block_members) stores it so).
    fn member(&mut self, ty: &GlslType, in_block: bool) -> Option<(u32, u32, bool)> {
        if let Some((size, align)) = plain_layout(ty, self.doubles) {
            return Some((size, align, false));
        }
        if let ([Some(n)], Some(_)) = (ty.dims.as_slice(), plain_layout(&ty.element(), self.doubles)) {
            let vector = matches!(ty.base.as_str(), "vec3" | "ivec3" | "uvec3" | "vec4" | "ivec4" | "uvec4");
            return (in_block || vector).then_some((16 * n, 16, false));
        }
        let size = self.structure(&ty.base)?;
        match ty.dims.as_slice() {
            [] => Some((size, 16, true)),
            [Some(n)] => Some((size * n, 16, true)),
            _ => None,
        }
    }

    /// std140 size of struct `name`, its fillers planned once.
    fn structure(&mut self, name: &str) -> Option<u32> {
        if let Some(&size) = self.sizes.get(name) {
            return Some(size);
        }
        if (self.refused)(name) {
            return None;
        }
        let def = self.structs.iter().find(|d| d.name == name)?;
        let end = self.members(name, &def.members, false)?;
        let size = end.next_multiple_of(16).max(16);
        if size > end {
            self.fillers.push((def.members.last()?.field_span.end, (size - end) / 4, name.to_string(), end));
        }
        self.sizes.insert(name.to_string(), size);
        Some(size)
    }

    /// The members' std140 end offset, with fillers before each struct-typed one (after the
    /// field before it: the first member is at offset 0, which needs none).
    fn members(&mut self, owner: &str, members: &[Member], in_block: bool) -> Option<u32> {
        let mut offset = 0u32;
        let mut previous: Option<&Member> = None;
        for m in members {
            let (size, align, aggregate) = self.member(&m.ty, in_block)?;
            let target = offset.next_multiple_of(align);
            if aggregate && target > offset {
                // Siblings of one field (`S a, b;`) follow a padded size: never here.
                let p = previous.filter(|p| p.field_span != m.field_span)?;
                self.fillers.push((p.field_span.end, (target - offset) / 4, owner.to_string(), offset));
            }
            previous = Some(m);
            offset = target + size;
        }
        Some(offset)
    }
}

impl Ctx<'_> {
    /// Fillers in the user's std140 uniform blocks that hold structs, and in those structs.
    pub(super) fn std140_struct_fillers(&mut self) {
        let s = self.s;
        let constructed = |name: &str| s.calls.iter().any(|c| c.name == name);
        let shared = |name: &str| self.plan.block_structs.iter().any(|b| b == name);
        // A struct also passed between stages would change its locations.
        let varying = |name: &str| s.globals.iter().any(|g| matches!(g.storage, Storage::In | Storage::Out) && g.ty.base == name);
        let refused = |name: &str| constructed(name) || shared(name) || varying(name);
        let mut done: BTreeMap<String, u32> = BTreeMap::new();
        let mut all: Fillers = Vec::new();
        for g in s.globals.iter().filter(|g| g.storage == Storage::Uniform) {
            let Some(b) = &g.block else { continue };
            let std430 = g.layout_items.iter().any(|(k, _)| k == "std430" || k == "push_constant");
            // An array of blocks is an array of structs in naga's IR: its stride is the
            // block's size, which std140 and WGSL round up to 16.
            let array = !b.instance_dims.is_empty();
            if std430 || !(array || b.members.iter().any(|m| s.struct_def(&m.ty.base).is_some())) {
                continue;
            }
            let mut layouts = Layouts {
                structs: &s.structs,
                refused: &refused,
                doubles: self.plan.doubles_as_floats,
                sizes: done.clone(),
                fillers: Vec::new(),
            };
            if let Some(end) = layouts.members(&b.block_name, &b.members, true) {
                if let Some(last) = b.members.last().filter(|_| array && !end.is_multiple_of(16)) {
                    layouts.fillers.push((last.field_span.end, (end.next_multiple_of(16) - end) / 4, b.block_name.clone(), end));
                }
                done = layouts.sizes;
                all.extend(layouts.fillers);
            }
        }
        all.sort();
        all.dedup();
        for (at, n, owner, offset) in all {
            let text: String = (0..n).map(|k| format!("float effectc_pad_{owner}_{}; ", offset + 4 * k)).collect();
            self.edits.insert(at, text);
        }
    }
}
