//! The program-wide resource plan every stage's rewrite shares.
//!
//! OpenGL links uniforms and varyings by name across the whole program; naga and WGSL bind
//! by (group, binding) and `@location`. The plan fixes those numbers once for all stages:
//! one uniform block `EffectcUniforms` at binding 0 holding every loose non-opaque uniform
//! of every stage (in a representation that validates: `bool` → `uint`, scalar and `vec2`
//! arrays → `vec4` arrays, `mat2` → `vec4`), a texture + sampler binding pair per combined
//! sampler, a binding per user uniform block (by block name), and a location per varying
//! name or block name.

use std::collections::{BTreeMap, HashMap};

use crate::front::compat;
use crate::front::syntax::{dims_text, sampler_parts, GlslType, Referent, StageSyntax, Storage};
pub use crate::front::uniform_repr::{repr_for, Repr};
use crate::front::varying_locations;
pub use crate::front::varying_locations::location_slots;
use crate::stage::StageKind;

/// Name of the generated uniform block (its WGSL struct keeps this name).
pub const UNIFORM_BLOCK: &str = "EffectcUniforms";

/// One user uniform in the generated block.
#[derive(Debug, Clone)]
pub struct BlockMember {
    pub name: String,
    /// Type as the user declared it.
    pub user_ty: GlslType,
    /// Type in the generated block.
    pub block_ty: GlslType,
    pub repr: Repr,
    /// First stage declaring it.
    pub stage: StageKind,
}

/// A combined sampler split into texture + sampler bindings.
#[derive(Debug, Clone)]
pub struct TextureBinding {
    /// The texture global's name in the rewritten code (the user's name, or
    /// `struct_member` / `array_index` for flattened ones).
    pub name: String,
    /// The GLSL expression that reaches it in the stage's text as effectc reads it (`tex`,
    /// `material.diffuse`, `maps[2]`; keywords of newer versions renamed).
    pub user_path: String,
    /// `user_path` as the user wrote it: what the manifest, reflection and the GL driver
    /// call it (OpenGL GLSL's `uniform sampler2D sampler;` is `sample_` to naga).
    pub user_name: String,
    pub user_ty: String,
    pub texture_ty: &'static str,
    pub sampler_ty: &'static str,
    pub sampler_name: String,
    pub texture_binding: u32,
    pub sampler_binding: u32,
}

/// Bindings and locations shared by all stages of a program.
#[derive(Debug, Clone, Default)]
pub struct Plan {
    /// The shared block's members (added only through `push_member`, which indexes them).
    pub members: Vec<BlockMember>,
    /// Index into `members` by name: thousands of uniforms are looked up at every use.
    member_index: HashMap<String, usize>,
    /// Struct names the block needs, in dependency order.
    pub block_structs: Vec<String>,
    pub textures: Vec<TextureBinding>,
    /// User uniform blocks by block name → binding.
    pub user_blocks: BTreeMap<String, u32>,
    /// The shared block's binding in set 0: 0, unless a Vulkan declaration takes it.
    pub block_binding: u32,
    /// Varying (loose name or block name) → first location.
    pub varyings: HashMap<String, u32>,
    /// Varyings packed into a location's later components (`layout(location = 0, component
    /// = 3)`), which naga's GLSL front and WGSL cannot express: (location, component) as
    /// written → a location of their own, the same in every stage.
    pub component_locations: HashMap<(u32, u32), u32>,
    /// Source text of every struct the block needs, for stages that lack it.
    pub struct_texts: BTreeMap<String, String>,
    /// Non-opaque member types of every struct the block needs (its keys are those structs).
    pub struct_members: BTreeMap<String, Vec<GlslType>>,
    /// Structs that get a trailing `vec4` filler member ([`STRUCT_ALIGN_FILLER`]) so naga
    /// aligns them to 16 bytes in the uniform block, as std140 does (naga aligns a struct to
    /// its largest member only, and WGSL's uniform rules then reject it).
    pub padded_structs: Vec<String>,
    /// Struct members stored as arrays of 4-vectors (struct → members;
    /// [`uniform_struct_arrays`](crate::front::uniform_struct_arrays)).
    pub widened_struct_members: BTreeMap<String, Vec<String>>,
    /// Images and atomic counters without a binding of their own → binding (set 0).
    pub opaque: BTreeMap<String, u32>,
    /// The compatibility profile's built-ins the program uses ([`compat`]): their state is
    /// in `members`, their varyings in `varyings`.
    pub compat: compat::ProgramCompat,
    /// The program's doubles become floats after the rewrite ([`repr_for`]).
    pub doubles_as_floats: bool,
    /// Members of instance-named uniform and buffer blocks renamed for naga's GLSL front:
    /// (block name, member, name in the rewrite). naga also declares such a member as a
    /// global, so a global of the same name (`in vec3 color;` beside `uniform Push { vec3
    /// color; } push;`) read `push.color` silently. The IR gets the user's names back.
    pub renamed_members: Vec<(String, String, String)>,
    /// Implicitly sized array members of blocks (`out blk { float foo[]; }`), sized as GL's
    /// linker sizes them: one past the largest constant index any stage uses (block name,
    /// member, size).
    pub sized_members: Vec<(String, String, u32)>,
}

/// Name of the filler member of [`Plan::padded_structs`].
pub const STRUCT_ALIGN_FILLER: &str = "effectc_align16";

impl Plan {
    pub fn member(&self, name: &str) -> Option<&BlockMember> {
        self.member_index.get(name).map(|&i| &self.members[i])
    }
    /// Adds a member of the shared block (the first of a name is the one found by name).
    fn push_member(&mut self, m: BlockMember) {
        self.member_index.entry(m.name.clone()).or_insert(self.members.len());
        self.members.push(m);
    }
    pub fn texture(&self, user_path: &str) -> Option<&TextureBinding> {
        self.textures.iter().find(|t| t.user_path == user_path)
    }
    /// The plan with [`size_implicit_block_members`]'s sizes.
    pub fn with_sized_members(self, sized_members: Vec<(String, String, u32)>) -> Self {
        Plan { sized_members, ..self }
    }
    pub fn has_block(&self) -> bool {
        !self.members.is_empty()
    }
}

/// [`Plan::renamed_members`]: in any stage, a member of an instance-named uniform or buffer
/// block named like a global that is not a block (the block is renamed in every stage that
/// declares it, so the stages keep one block type).
fn shadowing_block_members(stages: &[StageSyntax]) -> Vec<(String, String, String)> {
    let mut out: Vec<(String, String, String)> = Vec::new();
    for s in stages {
        let loose: std::collections::HashSet<&str> = s.globals.iter().filter(|g| g.block.is_none()).map(|g| g.name.as_str()).collect();
        for g in s.globals.iter().filter(|g| matches!(g.storage, Storage::Uniform | Storage::Buffer)) {
            let Some(b) = &g.block else { continue };
            let Some(instance) = &b.instance else { continue };
            for m in b.members.iter().filter(|m| loose.contains(m.name.as_str())) {
                if !out.iter().any(|(bn, mn, _)| *bn == b.block_name && *mn == m.name) {
                    let new = fresh(format!("{instance}_{}", m.name), stages, &[]);
                    out.push((b.block_name.clone(), m.name.clone(), new));
                }
            }
        }
    }
    out
}

/// Sizes the block members declared `name[]` as GL's linker does ([`Plan::sized_members`],
/// which the caller keeps): every stage's type of the member gets the size, so locations,
/// the interface and the geometry fold see the linked array; the rewrite writes it in.
pub fn size_implicit_block_members(stages: &mut [StageSyntax]) -> Vec<(String, String, u32)> {
    let sized = implicitly_sized_members(stages);
    for s in stages.iter_mut() {
        for g in &mut s.globals {
            let Some(b) = &mut g.block else { continue };
            for m in b.members.iter_mut().filter(|m| m.ty.dims.first() == Some(&None)) {
                if let Some((_, _, n)) = sized.iter().find(|(bn, mn, _)| *bn == b.block_name && *mn == m.name) {
                    m.ty.dims[0] = Some(*n);
                }
            }
        }
    }
    sized
}

/// Each interface-block member declared `name[]` in some stage, with one past the largest
/// constant index written after it in any stage (`inst.name[k]`, or `name[k]` for a block
/// without an instance name). A buffer block's last member declared `name[]` is no such
/// array: it is sized at run time by the buffer bound.
fn implicitly_sized_members(stages: &[StageSyntax]) -> Vec<(String, String, u32)> {
    let mut out: Vec<(String, String, u32)> = Vec::new();
    for s in stages {
        for g in s.globals.iter().filter(|g| matches!(g.storage, Storage::In | Storage::Out)) {
            let Some(b) = &g.block else { continue };
            for m in b.members.iter().filter(|m| m.ty.dims.first() == Some(&None)) {
                if !out.iter().any(|(bn, mn, _)| *bn == b.block_name && *mn == m.name) {
                    out.push((b.block_name.clone(), m.name.clone(), 1));
                }
            }
        }
    }
    for s in stages {
        for u in &s.uses {
            let Referent::Global(gi) = u.target else { continue };
            let Some(b) = &s.globals[gi].block else { continue };
            let k = match (&b.instance, &u.field) {
                (Some(_), Some((field, dot))) => constant_index_after(&s.text, dot.end).map(|k| (field, k)),
                (None, _) => u.index.as_ref().and_then(|(_, _, k)| *k).map(|k| (&u.name, k)),
                _ => None,
            };
            let Some((member, k)) = k else { continue };
            if let Some(entry) = out.iter_mut().find(|(bn, mn, _)| *bn == b.block_name && mn == member) {
                entry.2 = entry.2.max(u32::try_from(k + 1).unwrap_or(1));
            }
        }
    }
    // A stage that declares the member with a size gives it to the others.
    for s in stages {
        for b in s.globals.iter().filter_map(|g| g.block.as_ref()) {
            for m in &b.members {
                if let (Some(Some(n)), Some(entry)) =
                    (m.ty.dims.first(), out.iter_mut().find(|(bn, mn, _)| *bn == b.block_name && *mn == m.name))
                {
                    entry.2 = *n;
                }
            }
        }
    }
    out
}

/// The integer literal in the `[k]` right after `at` (spaces allowed), if there is one.
fn constant_index_after(text: &str, at: usize) -> Option<i64> {
    let rest = text.get(at..)?.trim_start().strip_prefix('[')?;
    let inner = &rest[..rest.find(']')?];
    inner.trim().trim_end_matches(['u', 'U']).parse().ok()
}

/// A path (`material.diffuse`, `maps[2]`) with each identifier spelled as the user wrote it.
fn spelled(s: &StageSyntax, path: &str) -> String {
    let mut out = String::new();
    let mut word = String::new();
    for c in path.chars().chain(std::iter::once('\0')) {
        if c.is_ascii_alphanumeric() || c == '_' {
            word.push(c);
            continue;
        }
        out.push_str(s.original_name(&word));
        word.clear();
        if c != '\0' {
            out.push(c);
        }
    }
    out
}

/// A name not used by any global of any stage.
fn fresh(base: String, stages: &[StageSyntax], taken: &[String]) -> String {
    let mut name = base;
    while stages.iter().any(|s| s.global(&name).is_some() || s.text.contains(&format!(" {name}"))) || taken.contains(&name) {
        name.push('_');
    }
    name
}

/// Opaque uniforms that stay declarations of their own (with a binding): images, atomic
/// counters, and Vulkan GLSL's separate textures, samplers and subpass inputs.
pub fn is_unblocked_opaque(base: &str) -> bool {
    let kinds = ["image", "texture", "subpassInput"];
    let of_kind = |b: &str| kinds.iter().any(|k| b.starts_with(k));
    let integer = base.strip_prefix('i').or_else(|| base.strip_prefix('u')).is_some_and(of_kind);
    base == "atomic_uint"
        || base == "sampler"
        || base == "samplerShadow"
        || of_kind(base)
        || integer
        || crate::front::syntax::texel_buffer_element(base).is_some()
}

/// Builds the plan for a program (stages in pipeline order); `doubles_as_floats` as in
/// [`repr_for`].
pub fn plan(stages: &[StageSyntax], doubles_as_floats: bool) -> Plan {
    let widened_struct_members = crate::front::uniform_struct_arrays::widened_members(stages);
    let mut plan = Plan { doubles_as_floats, widened_struct_members, ..Plan::default() };
    let mut taken: Vec<String> = Vec::new();
    // Uniforms, in stage order then declaration order.
    for s in stages {
        for g in &s.globals {
            if let (Some(b), Storage::Buffer) = (&g.block, g.storage) {
                if !plan.user_blocks.contains_key(&b.block_name) {
                    plan.user_blocks.insert(b.block_name.clone(), 0);
                }
                continue;
            }
            if g.storage != Storage::Uniform {
                continue;
            }
            if let Some(b) = &g.block {
                if !plan.user_blocks.contains_key(&b.block_name) {
                    plan.user_blocks.insert(b.block_name.clone(), 0);
                }
                continue;
            }
            if plan.member(&g.name).is_some() || plan.textures.iter().any(|t| t.user_path == g.name) {
                continue;
            }
            if is_unblocked_opaque(&g.ty.base) {
                // A buffer texture becomes a storage buffer in set 0 whatever its unit.
                let texel_buffer = crate::front::syntax::texel_buffer_element(&g.ty.base).is_some();
                if texel_buffer || !g.layout.iter().any(|(k, _)| k == "binding") {
                    plan.opaque.insert(g.name.clone(), 0);
                }
                continue;
            }
            if let Some((tex, samp)) = sampler_parts(&g.ty.base) {
                let count = g.ty.dims.first().copied().flatten();
                let paths: Vec<(String, String)> = match count {
                    Some(n) if g.ty.dims.len() == 1 => (0..n).map(|i| (format!("{}[{i}]", g.name), format!("{}_{i}", g.name))).collect(),
                    _ => vec![(g.name.clone(), g.name.clone())],
                };
                for (user_path, name) in paths {
                    let sampler_name = fresh(format!("{name}_sampler"), stages, &taken);
                    taken.push(sampler_name.clone());
                    plan.textures.push(TextureBinding {
                        name,
                        user_name: spelled(s, &user_path),
                        user_path,
                        user_ty: g.ty.base.clone(),
                        texture_ty: tex,
                        sampler_ty: samp,
                        sampler_name,
                        texture_binding: 0,
                        sampler_binding: 0,
                    });
                }
                continue;
            }
            // Struct uniforms: sampler members become their own bindings.
            if let Some(st) = s.struct_def(&g.ty.base) {
                let instances: Vec<(String, String)> = match g.ty.dims.first().copied().flatten() {
                    Some(n) if g.ty.dims.len() == 1 => (0..n).map(|i| (format!("{}[{i}]", g.name), format!("{}_{i}", g.name))).collect(),
                    _ => vec![(g.name.clone(), g.name.clone())],
                };
                for m in st.members.iter().filter(|m| m.ty.is_sampler() && !m.ty.is_array()) {
                    let (tex, samp) = sampler_parts(&m.ty.base).expect("checked is_sampler");
                    for (path, flat) in &instances {
                        let name = fresh(format!("{flat}_{}", m.name), stages, &taken);
                        taken.push(name.clone());
                        let sampler_name = fresh(format!("{name}_sampler"), stages, &taken);
                        taken.push(sampler_name.clone());
                        let user_path = format!("{path}.{}", m.name);
                        plan.textures.push(TextureBinding {
                            name,
                            user_name: spelled(s, &user_path),
                            user_path,
                            user_ty: m.ty.base.clone(),
                            texture_ty: tex,
                            sampler_ty: samp,
                            sampler_name,
                            texture_binding: 0,
                            sampler_binding: 0,
                        });
                    }
                }
                need_struct(&g.ty.base, s, &mut plan.block_structs);
            }
            let (block_ty, repr) = repr_for(&g.ty, doubles_as_floats);
            plan.push_member(BlockMember { name: g.name.clone(), user_ty: g.ty.clone(), block_ty, repr, stage: s.stage });
        }
    }
    plan.renamed_members = shadowing_block_members(stages);
    plan.compat = compat::analyse(stages);
    for st in plan.compat.state.clone() {
        let user_ty = st.glsl_type();
        let stage = stages.iter().find(|s| compat::stage_uses(s, st.name)).map_or(StageKind::Vertex, |s| s.stage);
        plan.push_member(BlockMember { name: st.name.to_string(), block_ty: user_ty.clone(), user_ty, repr: Repr::Plain, stage });
    }
    plan.block_structs.extend(plan.compat.block_structs.iter().map(|s| s.to_string()));
    number_bindings(&mut plan, stages);
    let linked: Vec<String> = plan
        .compat
        .varyings
        .iter()
        .map(|v| v.name.to_string())
        .chain(plan.compat.tex_coords.iter().map(|&i| compat::tex_coord_varying(i)))
        .collect();
    (plan.varyings, plan.component_locations) = varying_locations::number(stages, &linked);
    describe_block_structs(&mut plan, stages);
    for name in plan.compat.block_structs.clone() {
        plan.struct_members.insert(name.to_string(), compat::struct_member_types(name));
        plan.struct_texts.insert(name.to_string(), compat::struct_text(name).unwrap_or_default());
    }
    plan
}

/// Numbers the texture + sampler pairs, user blocks and opaque uniforms in set 0, from 1 (0
/// is the shared block, unless a declaration of set 0 holds it: then the block comes first).
fn number_bindings(plan: &mut Plan, stages: &[StageSyntax]) {
    let mut next_binding = 1u32;
    // Declarations that name `set = 0` and a binding keep both (Vulkan GLSL): the bindings
    // handed out here skip theirs.
    let reserved: std::collections::BTreeSet<u32> = stages
        .iter()
        .flat_map(|s| s.globals.iter().map(move |g| (s, g)))
        // Vulkan GLSL without a set means set 0.
        .filter(|(s, g)| match g.layout.iter().find(|(k, _)| k == "set") {
            Some((_, v)) => *v == Some(0),
            None => s.vulkan,
        })
        .map(|(_, g)| g)
        .filter_map(|g| g.layout.iter().find(|(k, _)| k == "binding").and_then(|(_, v)| *v))
        .filter_map(|b| u32::try_from(b).ok())
        .collect();
    let mut next = || {
        while reserved.contains(&next_binding) {
            next_binding += 1;
        }
        next_binding += 1;
        next_binding - 1
    };
    if reserved.contains(&0) && plan.has_block() {
        plan.block_binding = next();
    }
    for t in &mut plan.textures {
        t.texture_binding = next();
        t.sampler_binding = next();
    }
    for b in plan.user_blocks.values_mut() {
        *b = next();
    }
    for b in plan.opaque.values_mut() {
        *b = next();
    }
}

/// The first binding of set 0 after every binding the plan hands out and every `set = 0`
/// binding the stages declare (where the geometry fold puts its storage buffers).
pub fn first_free_binding(plan: &Plan, stages: &[StageSyntax]) -> u32 {
    let declared = stages
        .iter()
        .flat_map(|s| s.globals.iter().map(move |g| (s, g)))
        // Vulkan GLSL without a set means set 0.
        .filter(|(s, g)| match g.layout.iter().find(|(k, _)| k == "set") {
            Some((_, v)) => *v == Some(0),
            None => s.vulkan,
        })
        .map(|(_, g)| g)
        .filter_map(|g| g.layout.iter().find(|(k, _)| k == "binding").and_then(|(_, v)| *v))
        .filter_map(|b| u32::try_from(b).ok());
    let planned = plan.textures.iter().flat_map(|t| [t.texture_binding, t.sampler_binding]).chain(plan.user_blocks.values().copied());
    planned.chain(plan.opaque.values().copied()).chain([plan.block_binding]).chain(declared).max().map_or(1, |b| b + 1)
}

/// For each struct the block needs: its non-opaque member types, a filler member when naga
/// would align it below 16 bytes where std140 does not, and its text for stages that lack it.
fn describe_block_structs(plan: &mut Plan, stages: &[StageSyntax]) {
    for name in plan.block_structs.clone() {
        let Some(def) = stages.iter().find_map(|s| s.struct_def(&name)) else { continue };
        plan.struct_members.insert(name.clone(), def.members.iter().filter(|m| !m.ty.is_sampler()).map(|m| m.ty.clone()).collect());
        let constructed = stages.iter().any(|s| s.calls.iter().any(|c| c.name == name));
        // A struct alone in the block is aligned by the block's own fillers; one nested in
        // another struct or in an array is not.
        let nested = plan.struct_members.values().flatten().any(|m| m.base == name)
            || stages.iter().any(|s| s.structs.iter().any(|d| d.members.iter().any(|m| m.ty.base == name)))
            || plan.members.iter().any(|m| m.block_ty.base == name && m.block_ty.is_array());
        let (_, align) = block_size_align(&GlslType::scalar(&name), plan);
        if align < 16 && !constructed && nested {
            plan.padded_structs.push(name.clone());
            if let Some(members) = plan.struct_members.get_mut(&name) {
                members.push(GlslType::scalar("vec4"));
            }
        }
        let padded = plan.padded_structs.contains(&name);
        plan.struct_texts.insert(name.clone(), struct_text(def, padded, plan.widened_struct_members.get(&name)));
    }
}

/// (size, alignment) of a type as naga lays it out in a uniform block; structs are looked up in the plan's struct texts'
/// sources (sampler members excluded, as in the rewritten code).
pub fn block_size_align(ty: &GlslType, plan: &Plan) -> (u32, u32) {
    let (size, align) = match ty.base.as_str() {
        "float" | "int" | "uint" | "bool" => (4, 4),
        "vec2" | "ivec2" | "uvec2" | "bvec2" => (8, 8),
        "vec3" | "ivec3" | "uvec3" | "bvec3" => (12, 16),
        "vec4" | "ivec4" | "uvec4" | "bvec4" => (16, 16),
        "mat2" | "mat2x2" => (32, 16),
        "mat3" | "mat3x3" => (48, 16),
        "mat4" | "mat4x4" => (64, 16),
        "mat2x3" | "mat2x4" => (32, 16),
        "mat3x2" | "mat3x4" => (48, 16),
        "mat4x2" | "mat4x3" => (64, 16),
        other => match plan.struct_members.get(other) {
            Some(members) => {
                // naga's GLSL front rounds a struct's size to its largest member alignment
                // only (not to 16 as std140 says), so that is the size WGSL's rules see.
                let mut offset = 0u32;
                let mut align = 4u32;
                for m in members {
                    let (s, a) = block_size_align(m, plan);
                    offset = offset.next_multiple_of(a) + s;
                    align = align.max(a);
                }
                (offset.next_multiple_of(align), align)
            }
            None => (16, 16),
        },
    };
    if ty.is_array() {
        let stride = size.next_multiple_of(16);
        let n: u32 = ty.dims.iter().map(|d| d.unwrap_or(1)).product();
        (stride * n, 16)
    } else {
        (size, align)
    }
}

/// A struct definition as the rewritten code declares it: sampler members removed, the
/// `widened` members as arrays of 4-vectors.
pub fn struct_text(def: &crate::front::syntax::StructDef, padded: bool, widened: Option<&Vec<String>>) -> String {
    let mut text = format!("struct {} {{", def.name);
    let mut any = false;
    for m in def.members.iter().filter(|m| !m.ty.is_sampler()) {
        any = true;
        let stored = crate::front::uniform_struct_arrays::widened(&m.ty).filter(|_| widened.is_some_and(|w| w.contains(&m.name)));
        text.push_str(&format!(" {} {}{};", stored.map_or(m.ty.base.clone(), |(ty, _)| ty), m.name, dims_text(&m.ty)));
    }
    if !any {
        text.push_str(" int effectc_unused;");
    }
    if padded {
        text.push_str(&format!(" vec4 {STRUCT_ALIGN_FILLER};"));
    }
    text.push_str(" };");
    text
}

/// Adds `name` and the structs it uses (first) to `out`.
fn need_struct(name: &str, s: &StageSyntax, out: &mut Vec<String>) {
    if out.iter().any(|n| n == name) {
        return;
    }
    if let Some(st) = s.struct_def(name) {
        for m in &st.members {
            need_struct(&m.ty.base, s, out);
        }
        out.push(name.to_string());
    }
}
