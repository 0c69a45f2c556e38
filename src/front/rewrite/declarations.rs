//! Uniform declarations: blocks and opaque uniforms get their bindings (the plan's in set 0,
//! or the user's own moved to a set per kind); loose uniforms leave for the shared block,
//! combined samplers become texture + sampler pairs. Every declaration is dispatched here.

use std::collections::BTreeMap;
use std::fmt::Write;
use std::ops::Range;

use super::varyings::{is_fragment_output, is_vertex_input, LocationAllocator};
use super::{Ctx, INITIAL_PREFIX, USER_BUFFER_SET, USER_COUNTER_SET, USER_IMAGE_SET, USER_UNIFORM_SET};
use crate::diag::{Code, Diagnostic};
use crate::front::plan::{is_unblocked_opaque, location_slots, struct_text};
use crate::front::syntax::{Referent, Storage};
use crate::stage::StageKind;

impl Ctx<'_> {
    /// Every global declaration (declarators grouped, `uniform float a, b;`), by storage.
    pub(super) fn declarations(&mut self) {
        let s = self.s;
        // Group declarators by declaration span (`uniform float a, b;`).
        let mut by_decl: BTreeMap<usize, Vec<usize>> = BTreeMap::new();
        for (i, g) in s.globals.iter().enumerate() {
            by_decl.entry(g.decl_span.start).or_default().push(i);
        }
        let mut vertex_inputs = LocationAllocator::new(
            s.globals.iter().filter(|g| is_vertex_input(s, g.storage)).filter_map(|g| g.location.map(|l| (l, location_slots(&g.ty, s)))),
        );
        let mut fragment_outputs = LocationAllocator::new(
            s.globals.iter().filter(|g| is_fragment_output(s, g.storage)).filter_map(|g| g.location.map(|l| (l, location_slots(&g.ty, s)))),
        );
        if s.stage == StageKind::Fragment && s.uses.iter().any(|u| u.name == "gl_FragColor" && u.target == Referent::Unresolved) {
            fragment_outputs.reserve(0, 1);
        }
        self.fixed_function(&mut vertex_inputs);
        for (_, idxs) in by_decl {
            let first = &s.globals[idxs[0]];
            let decl = first.decl_span.clone();
            match first.storage {
                Storage::Uniform | Storage::Buffer if first.block.is_some() => self.block_binding(first),
                Storage::Uniform if crate::front::syntax::texel_buffer_element(&first.ty.base).is_some() => self.texel_buffers(decl, idxs),
                Storage::Uniform if is_unblocked_opaque(&first.ty.base) => self.opaque_binding(first),
                Storage::Uniform => self.loose_uniforms(decl, idxs),
                Storage::In | Storage::Out | Storage::Attribute | Storage::Varying => {
                    self.varying_declaration(idxs, &mut vertex_inputs, &mut fragment_outputs)
                }
                _ => {}
            }
        }
    }

    /// A uniform or buffer block: a binding in set 0 from the plan, or the user's binding
    /// moved to a set of its own.
    fn block_binding(&mut self, first: &crate::front::syntax::Global) {
        let b = first.block.as_ref().expect("block");
        if let Some((_, at)) = first.layout_items.iter().find(|(k, _)| k == "push_constant") {
            // WebGPU has no push constants: the block becomes a uniform buffer (std140, as
            // naga's uniform rules want) at the plan's binding for it.
            let binding = self.plan.user_blocks.get(&b.block_name).copied().unwrap_or(0);
            let std430 = first.layout_items.iter().find(|(k, _)| k == "std430").map(|(_, r)| r.clone());
            let std140 = first.layout_items.iter().any(|(k, _)| k == "std140");
            let packing = if std140 || std430.is_some() { "" } else { "std140, " };
            self.edits.replace(at.clone(), format!("{packing}set = 0, binding = {binding}"));
            if let Some(r) = std430 {
                self.edits.replace(r, "std140");
            }
        } else if first.layout.iter().any(|(k, _)| k == "descriptor_heap") {
            // Reached through a descriptor heap (GL_EXT_descriptor_heap), not bound: no set
            // or binding (glslang's SPIR-V writer crashes on a heap block given one).
        } else if first.layout.iter().any(|(k, _)| k == "binding") {
            // The user's own binding numbers live in set 1, clear of ours (GL numbers each
            // kind apart); Vulkan GLSL's are set 0's when no set is named.
            let set = if self.s.vulkan {
                0
            } else if first.storage == Storage::Buffer {
                USER_BUFFER_SET
            } else {
                USER_UNIFORM_SET
            };
            self.add_layout(first, &format!("set = {set}"), "set");
        } else {
            let binding = self.plan.user_blocks.get(&b.block_name).copied().unwrap_or(0);
            self.add_layout(first, &format!("set = 0, binding = {binding}"), "binding");
        }
    }

    /// Buffer textures (`uniform samplerBuffer s;`), which WebGPU lacks: each a read-only
    /// storage buffer holding the array of its texels, `effectc_texels_s` (a block without
    /// an instance name: naga's `.length()` of an instance's member loads the whole block;
    /// lookups in `calls::texel_buffer_lookup`), at the plan's binding. Arrays of them are
    /// left to naga.
    fn texel_buffers(&mut self, decl: Range<usize>, idxs: Vec<usize>) {
        let s = self.s;
        if idxs.iter().any(|&i| s.globals[i].ty.is_array()) {
            return;
        }
        let mut text = String::new();
        for &i in &idxs {
            let g = &s.globals[i];
            let element = crate::front::syntax::texel_buffer_element(&g.ty.base).expect("a buffer texture");
            let binding = self.plan.opaque.get(&g.name).copied().unwrap_or(0);
            let _ = write!(
                text,
                "layout(std430, set = 0, binding = {binding}) readonly buffer effectc_texel_buffer_{name} {{ {element} effectc_texels_{name}[]; }};",
                name = g.name
            );
            self.diags.push(
                Diagnostic::new(Code::TexelBufferAsStorage, format!("buffer texture `{}` is read from a storage buffer", s.original_name(&g.name)))
                    .at(s.file, g.name_span.clone(), "a buffer texture")
                    .with_note("WebGPU has no buffer textures: `texelFetch` reads a read-only storage buffer of texels; `render` fills it with zeros, as GL reads a buffer texture with no buffer bound"),
            );
        }
        self.edits.replace(decl, text);
    }

    /// An image, atomic counter or separate texture/sampler: the same, for opaque uniforms.
    fn opaque_binding(&mut self, first: &crate::front::syntax::Global) {
        if let Some(format) = crate::front::syntax::chosen_image_format(&first.ty.base, &first.layout) {
            // WebGPU storage textures have a format (N0111).
            self.add_layout(first, format, format);
        }
        if matches!(first.ty.base.as_str(), "imageBuffer" | "iimageBuffer" | "uimageBuffer") {
            let s = self.s;
            self.diags.push(
                Diagnostic::new(Code::TexelBufferAsStorage, format!("buffer image `{}` is read and written as a storage buffer", s.original_name(&first.name)))
                    .at(s.file, first.name_span.clone(), "a buffer image")
                    .with_note("WebGPU has no buffer images: `imageLoad`/`imageStore` read and write a storage buffer of texels (one 4-vector each) and `imageSize` is its length; `render` binds it zeroed"),
            );
        }
        // Images and atomic counters stay declarations of their own; one reached through a
        // descriptor heap has no binding.
        if first.layout.iter().any(|(k, _)| k == "descriptor_heap") {
        } else if first.layout.iter().any(|(k, _)| k == "binding") {
            let base = first.ty.base.as_str();
            let set = if self.s.vulkan {
                0
            } else if base == "atomic_uint" {
                USER_COUNTER_SET
            } else if ["image", "iimage", "uimage"].iter().any(|p| base.starts_with(p)) {
                USER_IMAGE_SET
            } else {
                USER_UNIFORM_SET
            };
            self.add_layout(first, &format!("set = {set}"), "set");
        } else {
            let binding = self.plan.opaque.get(&first.name).copied().unwrap_or(0);
            self.add_layout(first, &format!("set = 0, binding = {binding}"), "binding");
        }
    }

    /// Loose uniforms leave their declaration (they are members of the shared block);
    /// combined samplers become texture + sampler declarations in its place.
    fn loose_uniforms(&mut self, decl: Range<usize>, idxs: Vec<usize>) {
        let s = self.s;
        let mut text = String::new();
        // `uniform struct S { … } s;` keeps the struct type declared.
        for def in s.structs.iter().filter(|d| decl.start <= d.span.start && d.span.end <= decl.end) {
            text.push_str(&struct_text(def, self.plan.padded_structs.contains(&def.name), self.plan.widened_struct_members.get(&def.name)));
            text.push(' ');
        }
        for &i in &idxs {
            let g = &s.globals[i];
            for t in self.plan.textures.iter().filter(|t| t.user_path == g.name || t.user_path.starts_with(&format!("{}[", g.name))) {
                let _ = write!(
                    text,
                    "layout(set = 0, binding = {}) uniform {} {}; layout(set = 0, binding = {}) uniform {} {};",
                    t.texture_binding, t.texture_ty, t.name, t.sampler_binding, t.sampler_ty, t.sampler_name
                );
            }
            if let Some(init) = &g.initializer {
                if struct_with_array(s, &g.ty.base) {
                    self.diags.push(
                        Diagnostic::new(
                            Code::UniformInitializerIgnored,
                            format!("initializer of uniform `{}` is ignored", s.original_name(&g.name)),
                        )
                        .at(s.file, init.clone(), "a struct with an array of scalars: effectc does not read this value")
                        .with_note("naga lays the array member out for the uniform block, and the constructor's array does not match it")
                        .with_help("set the default in the effect manifest's [uniforms] table"),
                    );
                    continue;
                }
                // GL starts the uniform at its initializer: the renderer reads it here.
                let _ = write!(
                    text,
                    "const {} {INITIAL_PREFIX}{}{} = {};",
                    g.ty.base,
                    g.name,
                    crate::front::syntax::dims_text(&g.ty),
                    &s.text[init.clone()]
                );
            }
        }
        self.edits.replace(decl, text);
    }

    /// Adds `item` to the declaration's layout qualifier (or a new one), unless `key` is set.
    pub(super) fn add_layout(&mut self, g: &crate::front::syntax::Global, item: &str, key: &str) {
        if g.layout.iter().any(|(k, _)| k == key) {
            return;
        }
        match &g.layout_span {
            Some(span) => {
                let open = self.s.text[span.clone()].find('(').map(|i| span.start + i + 1).unwrap_or(span.start);
                self.edits.insert(open, format!("{item}, "));
            }
            None => self.edits.insert(g.decl_span.start, format!("layout({item}) ")),
        }
    }
}

/// Whether struct `name` (or a struct it holds) has an array of scalars or 2-vectors,
/// which the uniform block lays out with a 16-byte stride (std140).
fn struct_with_array(s: &crate::front::syntax::StageSyntax, name: &str) -> bool {
    let narrow = |base: &str| matches!(base, "float" | "int" | "uint" | "bool" | "vec2" | "ivec2" | "uvec2" | "bvec2");
    s.struct_def(name)
        .is_some_and(|d| d.members.iter().any(|m| (m.ty.is_array() && narrow(&m.ty.base)) || struct_with_array(s, &m.ty.base)))
}
