//! The bytes of every uniform buffer the module binds, built once from manifest values and
//! guesses, with the semantic slots rewritten every frame.
//!
//! Each uniform buffer's struct is walked member by member. A member is filled from the
//! manifest entries whose name starts with it (`minBI`, `lights[0].color`); a member the
//! manifest does not mention gets a [`Guess`] (a semantic by name, the identity for
//! matrices, …) that is reported. Offsets come from the translated module, so the bytes
//! match the WGSL that is rendered.

use naga::{Handle, Module, ScalarKind, Type, TypeInner};

use crate::back::reflect::write_slot;
use crate::front::compat;
use crate::front::initial_values::Initial;
use crate::manifest::{Effect, Semantic, UniformValue};
use crate::render::semantics::{self, FrameState, Guess, Shape};

/// One uniform buffer binding and its contents.
#[derive(Debug, Clone)]
pub struct UniformBuffer {
    pub group: u32,
    pub binding: u32,
    /// Bytes with the constant values written (semantic slots hold last frame's values).
    pub bytes: Vec<u8>,
    /// Slots rewritten every frame.
    pub per_frame: Vec<SemanticSlot>,
    /// What each uniform (a block member, by its GLSL path) receives, for `--verbose`:
    /// `the manifest's value`, `semantic time`, `its initializer`, a guess.
    pub sources: Vec<(String, String)>,
    /// Square matrices stored row-major (`layout(row_major)`): (offset, order, column
    /// stride). Values are written column-major, then these are transposed in place.
    pub row_major: Vec<(u32, u32, u32)>,
}

#[derive(Debug, Clone)]
pub struct SemanticSlot {
    pub offset: u32,
    pub ty: Handle<Type>,
    pub shape: Shape,
    pub semantic: Semantic,
}

/// A uniform that received a guessed value, for the warning the renderer prints.
#[derive(Debug, Clone, PartialEq)]
pub struct Guessed {
    /// The GLSL name of the uniform (a uniform buffer member).
    pub name: String,
    /// What it received: `the semantic `time``, `the identity matrix`, `zero`.
    pub what: String,
    /// A struct or array (its members are given values one by one).
    pub aggregate: bool,
}

/// Builds the buffers of every uniform-address-space global that has a binding.
/// `overrides` (`--set`, a bench knob, a stress case) win over the effect's values and
/// over guesses; `initial` (the GLSL initializers of uniforms, [`front::initial_values`](crate::front::initial_values)) give the
/// value of a uniform the effect does not mention. Without `guesses` (`--gl-defaults`) a
/// uniform nothing gives a value is zero, as in GL.
pub fn buffers(
    module: &Module,
    effect: Option<&Effect>,
    initial: &[Initial],
    row_major: &[(String, String)],
    overrides: &[(String, UniformValue)],
    guesses: bool,
) -> Result<(Vec<UniformBuffer>, Vec<Guessed>), String> {
    let mut out = Vec::new();
    let mut guessed = Vec::new();
    for (_, g) in module.global_variables.iter() {
        let (naga::AddressSpace::Uniform, Some(rb)) = (g.space, &g.binding) else { continue };
        let mut buffer = UniformBuffer {
            group: rb.group,
            binding: rb.binding,
            bytes: Vec::new(),
            per_frame: Vec::new(),
            sources: Vec::new(),
            row_major: row_major_slots(module, g.ty, row_major),
        };
        let local = |name: &str| in_block(module, g, name).map(str::to_string);
        fill_block(module, g.ty, effect, initial, guesses, &mut buffer, &mut guessed)?;
        // A named block's members as GL names them (`Block.member`).
        let named: Vec<(String, UniformValue)> = effect
            .map(|e| e.uniforms.iter().filter_map(|u| Some((local(&u.name).filter(|l| *l != u.name)?, u.value.clone()?))).collect())
            .unwrap_or_default();
        let overrides: Vec<(String, UniformValue)> =
            named.into_iter().chain(overrides.iter().map(|(n, v)| (local(n).unwrap_or_else(|| n.clone()), v.clone()))).collect();
        for (name, value) in &overrides {
            if let Some((offset, slot_ty)) = crate::back::reflect::resolve_path(module, g.ty, name) {
                write_slot(module, slot_ty, offset, value, &mut buffer.bytes).map_err(|e| format!("`{name}`: {e}"))?;
                buffer.per_frame.retain(|s| s.offset != offset);
                set_source(&mut buffer.sources, name, "an override".into());
                guessed.retain(|gu| {
                    gu.name != name.as_str() && !name.starts_with(&format!("{}.", gu.name)) && !name.starts_with(&format!("{}[", gu.name))
                });
            }
        }
        derive_gl_state(module, g.ty, &mut buffer.bytes);
        for &(offset, order, stride) in &buffer.row_major {
            transpose_in_place(&mut buffer.bytes, offset, order, stride);
        }
        out.push(buffer);
    }
    Ok((out, guessed))
}

/// Records what `name` receives, replacing what it received before (a manifest value
/// over a GL state member, an override over both).
fn set_source(sources: &mut Vec<(String, String)>, name: &str, from: String) {
    match sources.iter_mut().find(|(n, _)| n == name) {
        Some(entry) => entry.1 = from,
        None => sources.push((name.to_string(), from)),
    }
}

/// The compatibility state GL derives from other state, after every value is written:
/// a light's `spotCosCutoff` from its `spotCutoff` (negative cosines kept at 0, as Mesa
/// does), `gl_Fog.scale` from the fog's start and end.
fn derive_gl_state(module: &Module, block: Handle<Type>, bytes: &mut [u8]) {
    let at = |path: &str| crate::back::reflect::resolve_path(module, block, path).map(|(offset, _)| offset as usize);
    let get = |bytes: &[u8], o: usize| bytes.get(o..o + 4).map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]));
    let set = |bytes: &mut [u8], o: usize, v: f32| {
        if let Some(b) = bytes.get_mut(o..o + 4) {
            b.copy_from_slice(&v.to_le_bytes());
        }
    };
    for i in 0..compat::MAX_LIGHTS {
        if let (Some(cutoff), Some(cos)) =
            (at(&format!("gl_LightSource[{i}].spotCutoff")), at(&format!("gl_LightSource[{i}].spotCosCutoff")))
        {
            if let Some(c) = get(bytes, cutoff) {
                set(bytes, cos, c.to_radians().cos().max(0.0));
            }
        }
    }
    if let (Some(start), Some(end), Some(scale)) = (at("gl_Fog.start"), at("gl_Fog.end"), at("gl_Fog.scale")) {
        if let (Some(s), Some(e)) = (get(bytes, start), get(bytes, end)) {
            if e != s {
                set(bytes, scale, 1.0 / (e - s));
            }
        }
    }
}

fn fill_block(
    module: &Module,
    ty: Handle<Type>,
    effect: Option<&Effect>,
    initial: &[Initial],
    guesses: bool,
    buffer: &mut UniformBuffer,
    guessed: &mut Vec<Guessed>,
) -> Result<(), String> {
    let mut layouter = naga::proc::Layouter::default();
    layouter.update(module.to_ctx()).map_err(|e| e.to_string())?;
    let (members, size) = match &module.types[ty].inner {
        TypeInner::Struct { members, span } => (members.clone(), *span),
        // A uniform that is not a struct (naga wraps GLSL blocks in structs; be safe).
        _ => (Vec::new(), layouter[ty].size),
    };
    // Room to spare: wgpu wants uniform bindings of at least the struct size, 16-aligned.
    buffer.bytes = vec![0u8; (size as usize).div_ceil(16) * 16];
    for m in &members {
        let name = m.name.clone().unwrap_or_default();
        let entries: Vec<_> = effect.map(|e| e.uniforms.iter().filter(|u| root_name(&u.name) == name).collect()).unwrap_or_default();
        let gl = compat::state(&name).is_some();
        if name.starts_with("effectc_pad") {
            continue;
        }
        if gl {
            buffer.sources.push((name.clone(), "GL's state".into()));
            // GL's state, at its initial values first: the manifest may set some members only.
            gl_state(module, ty, (&name, effect.is_some()), m.ty, m.offset, buffer)?;
            if !entries.is_empty() {
                buffer.per_frame.retain(|s| s.offset != m.offset);
            }
        }
        if entries.is_empty() {
            if gl {
                continue;
            }
            let from_initializer: Vec<&Initial> = initial.iter().filter(|i| root_name(&i.path) == name).collect();
            for Initial { path, value, .. } in from_initializer.iter().copied() {
                // The whole uniform, or a member of a struct one (`s[1].f`).
                let Some((offset, slot)) = crate::back::reflect::resolve_path(module, ty, path) else { continue };
                write_slot(module, slot, offset, value, &mut buffer.bytes).map_err(|e| format!("`{path}`'s initializer: {e}"))?;
            }
            let from = if let Some(i) = from_initializer.first() {
                i.from.describe().to_string()
            } else if guesses {
                guess_member(module, &name, m.ty, m.offset, buffer, guessed)?
            } else {
                "zero".to_string()
            };
            buffer.sources.push((name, from));
            continue;
        }
        for u in entries {
            let Some((offset, slot_ty)) = crate::back::reflect::resolve_path(module, ty, &u.name) else { continue };
            let from = match (&u.value, u.semantic) {
                (Some(_), _) => "the manifest's value".to_string(),
                (None, Some(s)) => format!("semantic {}", s.name()),
                (None, None) => continue,
            };
            set_source(&mut buffer.sources, &u.name, from);
            match (&u.value, u.semantic) {
                (Some(v), _) => write_slot(module, slot_ty, offset, v, &mut buffer.bytes).map_err(|e| format!("`{}`: {e}", u.name))?,
                (None, Some(s)) => {
                    let shape = shape_of(module, slot_ty).ok_or_else(|| format!("`{}` cannot hold a semantic", u.name))?;
                    buffer.per_frame.push(SemanticSlot { offset, ty: slot_ty, shape, semantic: s });
                }
                (None, None) => {}
            }
        }
    }
    Ok(())
}

/// A compatibility-profile state member (`gl_LightSource`): with a `scene` (a manifest)
/// the matrices are its camera and model every frame; without one (bare stage files) they
/// are GL's initial identity matrices, as a program drawing `glRectf(-1, -1, 1, 1)` in a
/// fresh context has them. The rest takes GL's initial values. None of it is a guess.
fn gl_state(
    module: &Module,
    block: Handle<Type>,
    (name, scene): (&str, bool),
    ty: Handle<Type>,
    offset: u32,
    buffer: &mut UniformBuffer,
) -> Result<(), String> {
    // The matrices an application sets on GL's matrix stacks.
    let semantic = match name {
        "gl_ModelViewMatrix" => Some(Semantic::ModelView),
        "gl_ProjectionMatrix" => Some(Semantic::Projection),
        "gl_ModelViewProjectionMatrix" => Some(Semantic::ModelViewProjection),
        "gl_NormalMatrix" => Some(Semantic::NormalMatrix),
        _ => None,
    };
    if let (Some(semantic), Some(shape)) = (semantic, shape_of(module, ty)) {
        if !scene {
            let value = semantics::matrix(glam::Mat4::IDENTITY, shape);
            return write_slot(module, ty, offset, &value, &mut buffer.bytes).map_err(|e| format!("`{name}`: {e}"));
        }
        buffer.per_frame.push(SemanticSlot { offset, ty, shape, semantic });
        return Ok(());
    }
    for (path, v) in compat::initial_values(name) {
        let Some((offset, slot)) = crate::back::reflect::resolve_path(module, block, &path) else { continue };
        let value = match v.len() {
            1 => UniformValue::Float(f64::from(v[0])),
            16 => semantics::matrix(glam::Mat4::from_cols_slice(&v), (4, 4)),
            _ => semantics::floats(&v.iter().map(|x| f64::from(*x)).collect::<Vec<_>>()),
        };
        write_slot(module, slot, offset, &value, &mut buffer.bytes).map_err(|e| format!("`{path}`: {e}"))?;
    }
    Ok(())
}

/// The path inside uniform buffer `g` of a uniform named `name` by GL: a member of a block
/// with an instance name is `BlockName.member` (or `instance.member`); the block's struct
/// keeps the block's name in naga.
fn in_block<'n>(module: &Module, g: &naga::GlobalVariable, name: &'n str) -> Option<&'n str> {
    let prefixes = [module.types[g.ty].name.as_deref(), g.name.as_deref()];
    prefixes.into_iter().flatten().find_map(|p| name.strip_prefix(p).and_then(|r| r.strip_prefix('.')))
}

/// `lights[0].color` → `lights`.
fn root_name(path: &str) -> &str {
    let end = path.find(['.', '[']).unwrap_or(path.len());
    &path[..end]
}

/// Guesses the value of uniform `name` (a block member) by its name and type, and says
/// what it received.
fn guess_member(
    module: &Module,
    name: &str,
    ty: Handle<Type>,
    offset: u32,
    buffer: &mut UniformBuffer,
    guessed: &mut Vec<Guessed>,
) -> Result<String, String> {
    let Some(shape) = shape_of(module, ty) else {
        // Structs and arrays: every leaf is guessed by its own name.
        let mut leaves = Vec::new();
        guess_leaves(module, ty, offset, name, &mut buffer.bytes, &mut leaves)?;
        leaves.dedup();
        let what = if leaves.is_empty() { "zero".to_string() } else { format!("{}; everything else zero", leaves.join(", ")) };
        guessed.push(Guessed { name: name.into(), what, aggregate: true });
        return Ok("a guess for each member".into());
    };
    match semantics::guess(name, shape, is_float(module, ty)) {
        Guess::Semantic(s) => {
            buffer.per_frame.push(SemanticSlot { offset, ty, shape, semantic: s });
            guessed.push(Guessed { name: name.into(), what: format!("the semantic `{}` (by its name)", s.name()), aggregate: false });
            Ok(format!("semantic {} (guessed by its name)", s.name()))
        }
        Guess::Constant(value, what) => {
            if value != UniformValue::Int(0) {
                write_slot(module, ty, offset, &value, &mut buffer.bytes).map_err(|e| format!("`{name}`: {e}"))?;
            }
            guessed.push(Guessed { name: name.into(), what: what.into(), aggregate: false });
            Ok(format!("{what} (guessed)"))
        }
    }
}

/// Guesses a constant for every scalar, vector and matrix inside a struct or array,
/// by its path (`material.diffuse` → white, `light.position` → a light). Semantics are not
/// bound inside structs. `notes` collects what the leaves that are not zero received.
fn guess_leaves(module: &Module, ty: Handle<Type>, offset: u32, leaf: &str, buf: &mut [u8], notes: &mut Vec<String>) -> Result<(), String> {
    match &module.types[ty].inner {
        TypeInner::Array { base, size: naga::ArraySize::Constant(n), stride } => {
            for i in 0..n.get() {
                guess_leaves(module, *base, offset + i * stride, &format!("{leaf}[{i}]"), buf, notes)?;
            }
        }
        TypeInner::Struct { members, .. } => {
            for m in members {
                let name = format!("{leaf}.{}", m.name.as_deref().unwrap_or_default());
                guess_leaves(module, m.ty, offset + m.offset, &name, buf, notes)?;
            }
        }
        _ => {
            let Some(shape) = shape_of(module, ty) else { return Ok(()) };
            if let Guess::Constant(value, what) = semantics::guess(leaf, shape, is_float(module, ty)) {
                if value != UniformValue::Int(0) {
                    write_slot(module, ty, offset, &value, buf)?;
                    notes.push(format!("`{leaf}` {what}"));
                }
            }
        }
    }
    Ok(())
}

/// `(columns, rows)` of a scalar, vector or matrix slot.
fn shape_of(module: &Module, ty: Handle<Type>) -> Option<Shape> {
    match module.types[ty].inner {
        TypeInner::Scalar(_) => Some((1, 1)),
        TypeInner::Vector { size, .. } => Some((1, size as u8)),
        TypeInner::Matrix { columns, rows, .. } => Some((columns as u8, rows as u8)),
        _ => None,
    }
}

fn is_float(module: &Module, ty: Handle<Type>) -> bool {
    match module.types[ty].inner {
        TypeInner::Scalar(s) | TypeInner::Vector { scalar: s, .. } | TypeInner::Matrix { scalar: s, .. } => s.kind == ScalarKind::Float,
        _ => false,
    }
}

impl UniformBuffer {
    /// Rewrites the semantic slots for this frame.
    pub fn update(&mut self, module: &Module, frame: &FrameState) -> Result<(), String> {
        for s in &self.per_frame {
            let value = semantics::value(s.semantic, frame, s.shape);
            write_slot(module, s.ty, s.offset, &value, &mut self.bytes).map_err(|e| format!("semantic `{}`: {e}", s.semantic.name()))?;
            if let Some(&(offset, order, stride)) = self.row_major.iter().find(|r| r.0 == s.offset) {
                transpose_in_place(&mut self.bytes, offset, order, stride);
            }
        }
        Ok(())
    }
}

/// The row-major square matrices of the block `ty` (a struct named like its GLSL block):
/// (offset, order, column stride) of each.
fn row_major_slots(module: &Module, ty: Handle<Type>, row_major: &[(String, String)]) -> Vec<(u32, u32, u32)> {
    let (Some(block), TypeInner::Struct { members, .. }) = (module.types[ty].name.as_deref(), &module.types[ty].inner) else {
        return Vec::new();
    };
    let mut layouter = naga::proc::Layouter::default();
    if layouter.update(module.to_ctx()).is_err() {
        return Vec::new();
    }
    members
        .iter()
        .filter(|m| row_major.iter().any(|(b, name)| b == block && m.name.as_deref() == Some(name.as_str())))
        .filter_map(|m| match module.types[m.ty].inner {
            TypeInner::Matrix { columns, rows, .. } if columns == rows => {
                let order = columns as u32;
                Some((m.offset, order, layouter[m.ty].size / order))
            }
            _ => None,
        })
        .collect()
}

/// Transposes the `order`×`order` matrix of 4-byte components at `offset` (columns
/// `stride` bytes apart) in place.
fn transpose_in_place(bytes: &mut [u8], offset: u32, order: u32, stride: u32) {
    let at = |c: u32, r: u32| (offset + c * stride + 4 * r) as usize;
    for c in 0..order {
        for r in c + 1..order {
            let (a, b) = (at(c, r), at(r, c));
            if b + 4 > bytes.len() || a + 4 > bytes.len() {
                return;
            }
            for i in 0..4 {
                bytes.swap(a + i, b + i);
            }
        }
    }
}
