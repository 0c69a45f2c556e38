//! The GL program's uniforms fed with the values the wgpu scene draws with: every active
//! uniform GL reports (`lights[0].color`, `Material.diffuse`, `weights[3]`) is found in the
//! translated module's uniform buffers by its GLSL path, and the bytes the scene wrote for
//! this frame (manifest values, semantics, guesses, `--set`) are read from there: loose
//! uniforms through `glUniform*`, block members into a uniform buffer at the offsets and
//! strides GL reports for the block. Samplers get a texture unit each.

use glow::HasContext;
use naga::{Handle, Module, ScalarKind, Type, TypeInner};

use crate::back::reflect::resolve_path;
use crate::render::scene::Scene;

/// Where a value lies in the scene's uniform buffers.
#[derive(Debug, Clone, Copy)]
struct Source {
    /// Index into `Scene::uniforms`.
    buffer: usize,
    offset: u32,
    ty: Handle<Type>,
}

/// A GL type's shape: component kind, columns, rows (1 column for vectors and scalars).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shape {
    pub kind: ScalarKind,
    pub columns: u32,
    pub rows: u32,
}

/// One element of a loose uniform.
struct Loose {
    location: glow::UniformLocation,
    shape: Shape,
    source: Source,
}

/// One element of a block member, at its offset in the GL block.
struct Member {
    offset: usize,
    matrix_stride: usize,
    row_major: bool,
    shape: Shape,
    source: Source,
}

/// One uniform block and its buffer.
struct Block {
    buffer: glow::Buffer,
    binding: u32,
    bytes: Vec<u8>,
    members: Vec<Member>,
}

/// A sampler uniform: its texture unit and GLSL name.
pub struct SamplerUnit {
    pub name: String,
    pub unit: u32,
    /// The GL sampler type (`GL_SAMPLER_2D`, …).
    pub gl_type: u32,
}

/// How the GL program's uniforms are fed every frame.
pub struct GlUniforms {
    loose: Vec<Loose>,
    blocks: Vec<Block>,
    pub samplers: Vec<SamplerUnit>,
    /// Active uniforms GL reads that the translation has no value for (GL's zero stays).
    pub unmatched: Vec<String>,
}

impl GlUniforms {
    /// Reads the program's active uniforms and blocks and finds each in `scene`.
    pub fn new(gl: &glow::Context, program: glow::Program, scene: &Scene) -> Result<GlUniforms, String> {
        let mut out = GlUniforms { loose: Vec::new(), blocks: Vec::new(), samplers: Vec::new(), unmatched: Vec::new() };
        let globals = uniform_globals(scene);
        // SAFETY: queries and object creation on the current context.
        unsafe {
            let count = gl.get_active_uniforms(program);
            let indices: Vec<u32> = (0..count).collect();
            let param = |pname| gl.get_active_uniforms_parameter(program, &indices, pname);
            let (block_of, offsets, array_strides, matrix_strides, row_major) = if count > 0 {
                (
                    param(glow::UNIFORM_BLOCK_INDEX),
                    param(glow::UNIFORM_OFFSET),
                    param(glow::UNIFORM_ARRAY_STRIDE),
                    param(glow::UNIFORM_MATRIX_STRIDE),
                    param(glow::UNIFORM_IS_ROW_MAJOR),
                )
            } else {
                Default::default()
            };
            let block_count = gl.get_program_parameter_i32(program, glow::ACTIVE_UNIFORM_BLOCKS).max(0) as u32;
            for b in 0..block_count {
                let size = gl.get_active_uniform_block_parameter_i32(program, b, glow::UNIFORM_BLOCK_DATA_SIZE).max(16) as usize;
                let buffer = gl.create_buffer()?;
                gl.uniform_block_binding(program, b, b);
                out.blocks.push(Block { buffer, binding: b, bytes: vec![0; size], members: Vec::new() });
            }
            for i in 0..count as usize {
                let Some(u) = gl.get_active_uniform(program, i as u32) else { continue };
                let base = u.name.strip_suffix("[0]").unwrap_or(&u.name).to_string();
                let arrayed = u.name.ends_with("[0]");
                if let Some(_sampler) = sampler_type(u.utype) {
                    for e in 0..u.size.max(1) {
                        let name = if arrayed { format!("{base}[{e}]") } else { base.clone() };
                        let unit = out.samplers.len() as u32;
                        if let Some(location) = gl.get_uniform_location(program, &name) {
                            gl.use_program(Some(program));
                            gl.uniform_1_i32(Some(&location), unit as i32);
                        }
                        out.samplers.push(SamplerUnit { name, unit, gl_type: u.utype });
                    }
                    continue;
                }
                if u.name.starts_with("gl_") {
                    // GL's own state (`gl_LightSource[0].diffuse`, the light products): set
                    // through its fixed-function entry points (`fixed_function::set_state`).
                    continue;
                }
                let Some(shape) = shape_of(u.utype) else {
                    out.unmatched.push(format!("{} (a type verify cannot feed yet)", u.name));
                    continue;
                };
                let in_block = block_of.get(i).copied().unwrap_or(-1);
                for e in 0..u.size.max(1) as usize {
                    let name = if arrayed { format!("{base}[{e}]") } else { base.clone() };
                    let Some(source) = find(scene, &globals, &name, in_block >= 0) else {
                        out.unmatched.push(name);
                        continue;
                    };
                    if in_block >= 0 {
                        let offset = offsets[i].max(0) as usize + e * array_strides[i].max(0) as usize;
                        let member = Member {
                            offset,
                            matrix_stride: matrix_strides[i].max(0) as usize,
                            row_major: row_major[i] != 0,
                            shape,
                            source,
                        };
                        out.blocks[in_block as usize].members.push(member);
                    } else if let Some(location) = gl.get_uniform_location(program, &name) {
                        out.loose.push(Loose { location, shape, source });
                    }
                }
            }
        }
        Ok(out)
    }

    /// Sets every uniform from the scene's buffers as they are for the frame just drawn.
    pub fn upload(&mut self, gl: &glow::Context, program: glow::Program, scene: &Scene) {
        let module = &scene.module;
        // SAFETY: calls on the current context with objects it created.
        unsafe {
            gl.use_program(Some(program));
            for l in &self.loose {
                let v = read(module, scene, l.source, l.shape);
                let loc = Some(&l.location);
                let n = (l.shape.columns * l.shape.rows) as usize;
                match (l.shape.kind, l.shape.columns, l.shape.rows) {
                    (ScalarKind::Float, 1, r) => {
                        let f: Vec<f32> = v.iter().map(|w| f32::from_bits(*w)).collect();
                        match r {
                            1 => gl.uniform_1_f32_slice(loc, &f[..n]),
                            2 => gl.uniform_2_f32_slice(loc, &f[..n]),
                            3 => gl.uniform_3_f32_slice(loc, &f[..n]),
                            _ => gl.uniform_4_f32_slice(loc, &f[..n]),
                        }
                    }
                    (ScalarKind::Float, c, r) => {
                        let f: Vec<f32> = v.iter().map(|w| f32::from_bits(*w)).collect();
                        match (c, r) {
                            (2, 2) => gl.uniform_matrix_2_f32_slice(loc, false, &f),
                            (3, 3) => gl.uniform_matrix_3_f32_slice(loc, false, &f),
                            (4, 4) => gl.uniform_matrix_4_f32_slice(loc, false, &f),
                            (2, 3) => gl.uniform_matrix_2x3_f32_slice(loc, false, &f),
                            (2, 4) => gl.uniform_matrix_2x4_f32_slice(loc, false, &f),
                            (3, 2) => gl.uniform_matrix_3x2_f32_slice(loc, false, &f),
                            (3, 4) => gl.uniform_matrix_3x4_f32_slice(loc, false, &f),
                            (4, 2) => gl.uniform_matrix_4x2_f32_slice(loc, false, &f),
                            _ => gl.uniform_matrix_4x3_f32_slice(loc, false, &f),
                        }
                    }
                    (ScalarKind::Uint, _, r) => match r {
                        1 => gl.uniform_1_u32_slice(loc, &v[..n]),
                        2 => gl.uniform_2_u32_slice(loc, &v[..n]),
                        3 => gl.uniform_3_u32_slice(loc, &v[..n]),
                        _ => gl.uniform_4_u32_slice(loc, &v[..n]),
                    },
                    // Signed integers and booleans (GL sets a bool from an int).
                    (_, _, r) => {
                        let i: Vec<i32> = v.iter().map(|w| *w as i32).collect();
                        match r {
                            1 => gl.uniform_1_i32_slice(loc, &i[..n]),
                            2 => gl.uniform_2_i32_slice(loc, &i[..n]),
                            3 => gl.uniform_3_i32_slice(loc, &i[..n]),
                            _ => gl.uniform_4_i32_slice(loc, &i[..n]),
                        }
                    }
                }
            }
            for b in &mut self.blocks {
                for m in &b.members {
                    let mut v = read(module, scene, m.source, m.shape);
                    if m.row_major && m.shape.columns == m.shape.rows {
                        // effectc stores a row-major block matrix transposed, as GL does:
                        // its value is the transpose of the column-major read.
                        let n = m.shape.rows as usize;
                        v = (0..n * n).map(|i| v[(i % n) * n + i / n]).collect();
                    }
                    for c in 0..m.shape.columns as usize {
                        for r in 0..m.shape.rows as usize {
                            let at = match (m.shape.columns, m.row_major) {
                                (1, _) => m.offset + 4 * r,
                                (_, false) => m.offset + c * m.matrix_stride + 4 * r,
                                (_, true) => m.offset + r * m.matrix_stride + 4 * c,
                            };
                            let word = v[c * m.shape.rows as usize + r];
                            if let Some(dst) = b.bytes.get_mut(at..at + 4) {
                                dst.copy_from_slice(&word.to_le_bytes());
                            }
                        }
                    }
                }
                gl.bind_buffer(glow::UNIFORM_BUFFER, Some(b.buffer));
                gl.buffer_data_u8_slice(glow::UNIFORM_BUFFER, &b.bytes, glow::DYNAMIC_DRAW);
                gl.bind_buffer_base(glow::UNIFORM_BUFFER, b.binding, Some(b.buffer));
            }
        }
    }

    /// Deletes the buffers.
    pub fn delete(&self, gl: &glow::Context) {
        // SAFETY: objects of the current context.
        unsafe {
            for b in &self.blocks {
                gl.delete_buffer(b.buffer);
            }
        }
    }
}

/// Reads float values by GLSL path (`gl_LightSource[0].diffuse`) from the scene's
/// uniform buffers as they are for the frame just drawn: `None` where no buffer holds it.
pub fn float_reader(scene: &Scene) -> impl Fn(&str) -> Option<Vec<f32>> + '_ {
    let globals = uniform_globals(scene);
    move |path: &str| {
        let source = find(scene, &globals, path, false)?;
        let (columns, rows) = match scene.module.types[source.ty].inner {
            TypeInner::Scalar(_) => (1, 1),
            TypeInner::Vector { size, .. } => (1, size as u32),
            TypeInner::Matrix { columns, rows, .. } => (columns as u32, rows as u32),
            _ => return None,
        };
        let shape = Shape { kind: ScalarKind::Float, columns, rows };
        Some(read(&scene.module, scene, source, shape).into_iter().map(f32::from_bits).collect())
    }
}

/// (index into `Scene::uniforms`, the global's type, its type name, its own name).
type UniformGlobal = (usize, Handle<Type>, Option<String>, Option<String>);

fn uniform_globals(scene: &Scene) -> Vec<UniformGlobal> {
    let m = &scene.module;
    scene
        .uniforms
        .iter()
        .enumerate()
        .filter_map(|(i, (u, _))| {
            let (_, g) = m.global_variables.iter().find(|(_, g)| {
                g.space == naga::AddressSpace::Uniform && g.binding.as_ref().is_some_and(|b| b.group == u.group && b.binding == u.binding)
            })?;
            Some((i, g.ty, m.types[g.ty].name.clone(), g.name.clone()))
        })
        .collect()
}

/// The slot of GL uniform `name` in the scene's buffers. A block member is named
/// `Block.member` by GL when the block has an instance name: tried with and without the
/// block's name, in the global of that block first.
fn find(scene: &Scene, globals: &[UniformGlobal], name: &str, in_block: bool) -> Option<Source> {
    let m = &scene.module;
    let loose_block = Some(crate::front::plan::UNIFORM_BLOCK.to_string());
    let at = |g: &UniformGlobal, path: &str| resolve_path(m, g.1, path).map(|(offset, ty)| Source { buffer: g.0, offset, ty });
    if let Some((prefix, rest)) = name.split_once('.') {
        let prefix = prefix.split('[').next().unwrap_or(prefix);
        let owner = globals.iter().filter(|g| g.2.as_deref() == Some(prefix) || g.3.as_deref() == Some(prefix));
        if let Some(s) = owner.clone().find_map(|g| at(g, rest)) {
            return Some(s);
        }
    }
    // Loose uniforms live in effectc's own block; block members without an instance name
    // in their block's global.
    let order: Vec<&UniformGlobal> = if in_block {
        globals.iter().filter(|g| g.2 != loose_block).chain(globals.iter().filter(|g| g.2 == loose_block)).collect()
    } else {
        globals.iter().filter(|g| g.2 == loose_block).chain(globals.iter().filter(|g| g.2 != loose_block)).collect()
    };
    order.into_iter().find_map(|g| at(g, name).or_else(|| name.split_once('.').and_then(|(_, rest)| at(g, rest))))
}

/// The 32-bit words of the value at `source`, column-major, `shape.columns × shape.rows`
/// of them (missing ones are zero). The slot may hold more than GL's type (a `float`
/// array element padded to a `vec4`, a `mat2` stored as a `vec4`): the leading
/// components are the value.
fn read(module: &Module, scene: &Scene, source: Source, shape: Shape) -> Vec<u32> {
    let bytes = &scene.uniforms[source.buffer].0.bytes;
    let word = |at: usize| bytes.get(at..at + 4).map_or(0, |b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]));
    let base = source.offset as usize;
    let mut words: Vec<u32> = match module.types[source.ty].inner {
        TypeInner::Matrix { columns, rows, .. } => {
            let stride = if rows as usize == 2 { 8 } else { 16 };
            (0..columns as usize)
                .flat_map(|c| (0..rows as usize).map(move |r| (c, r)))
                .map(|(c, r)| word(base + c * stride + 4 * r))
                .collect()
        }
        TypeInner::Vector { size, .. } => (0..size as usize).map(|i| word(base + 4 * i)).collect(),
        // A two-row matrix of a std140 block stored as `vec4` columns (the route through
        // SPIR-V): each column's `.xy`.
        TypeInner::Array { stride, .. } if shape.columns > 1 && shape.rows == 2 => (0..shape.columns as usize)
            .flat_map(|c| (0..2).map(move |r| (c, r)))
            .map(|(c, r)| word(base + c * stride as usize + 4 * r))
            .collect(),
        _ => vec![word(base)],
    };
    let n = (shape.columns * shape.rows) as usize;
    // A GL matrix read from vectors of another height (`mat2` kept as `vec4`) is taken in
    // order; a float slot read as an integer (or back) keeps its value, not its bits.
    words.resize(n, 0);
    let slot_kind = match module.types[source.ty].inner {
        TypeInner::Scalar(s) | TypeInner::Vector { scalar: s, .. } | TypeInner::Matrix { scalar: s, .. } => Some(s.kind),
        _ => None,
    };
    match (slot_kind, shape.kind) {
        (Some(ScalarKind::Float), ScalarKind::Sint | ScalarKind::Bool) => words.iter().map(|w| f32::from_bits(*w) as i32 as u32).collect(),
        (Some(ScalarKind::Float), ScalarKind::Uint) => words.iter().map(|w| f32::from_bits(*w) as u32).collect(),
        (Some(ScalarKind::Sint | ScalarKind::Uint | ScalarKind::Bool), ScalarKind::Float) => {
            words.iter().map(|w| (*w as i32 as f32).to_bits()).collect()
        }
        _ => words,
    }
}

/// The shape of a GL uniform type; `None` for doubles and opaque types.
pub fn shape_of(utype: u32) -> Option<Shape> {
    use ScalarKind::{Bool, Float, Sint, Uint};
    let s = |kind, columns, rows| Some(Shape { kind, columns, rows });
    match utype {
        glow::FLOAT => s(Float, 1, 1),
        glow::FLOAT_VEC2 => s(Float, 1, 2),
        glow::FLOAT_VEC3 => s(Float, 1, 3),
        glow::FLOAT_VEC4 => s(Float, 1, 4),
        glow::INT => s(Sint, 1, 1),
        glow::INT_VEC2 => s(Sint, 1, 2),
        glow::INT_VEC3 => s(Sint, 1, 3),
        glow::INT_VEC4 => s(Sint, 1, 4),
        glow::UNSIGNED_INT => s(Uint, 1, 1),
        glow::UNSIGNED_INT_VEC2 => s(Uint, 1, 2),
        glow::UNSIGNED_INT_VEC3 => s(Uint, 1, 3),
        glow::UNSIGNED_INT_VEC4 => s(Uint, 1, 4),
        glow::BOOL => s(Bool, 1, 1),
        glow::BOOL_VEC2 => s(Bool, 1, 2),
        glow::BOOL_VEC3 => s(Bool, 1, 3),
        glow::BOOL_VEC4 => s(Bool, 1, 4),
        glow::FLOAT_MAT2 => s(Float, 2, 2),
        glow::FLOAT_MAT3 => s(Float, 3, 3),
        glow::FLOAT_MAT4 => s(Float, 4, 4),
        glow::FLOAT_MAT2x3 => s(Float, 2, 3),
        glow::FLOAT_MAT2x4 => s(Float, 2, 4),
        glow::FLOAT_MAT3x2 => s(Float, 3, 2),
        glow::FLOAT_MAT3x4 => s(Float, 3, 4),
        glow::FLOAT_MAT4x2 => s(Float, 4, 2),
        glow::FLOAT_MAT4x3 => s(Float, 4, 3),
        _ => None,
    }
}

/// The texture target a GL sampler type binds (`None`: not a sampler).
pub fn sampler_type(utype: u32) -> Option<u32> {
    Some(match utype {
        glow::SAMPLER_1D | glow::SAMPLER_1D_SHADOW | glow::INT_SAMPLER_1D | glow::UNSIGNED_INT_SAMPLER_1D => glow::TEXTURE_1D,
        glow::SAMPLER_2D | glow::SAMPLER_2D_SHADOW | glow::INT_SAMPLER_2D | glow::UNSIGNED_INT_SAMPLER_2D => glow::TEXTURE_2D,
        glow::SAMPLER_3D | glow::INT_SAMPLER_3D | glow::UNSIGNED_INT_SAMPLER_3D => glow::TEXTURE_3D,
        glow::SAMPLER_CUBE | glow::SAMPLER_CUBE_SHADOW | glow::INT_SAMPLER_CUBE | glow::UNSIGNED_INT_SAMPLER_CUBE => glow::TEXTURE_CUBE_MAP,
        glow::SAMPLER_2D_ARRAY | glow::SAMPLER_2D_ARRAY_SHADOW | glow::INT_SAMPLER_2D_ARRAY | glow::UNSIGNED_INT_SAMPLER_2D_ARRAY => {
            glow::TEXTURE_2D_ARRAY
        }
        glow::SAMPLER_2D_MULTISAMPLE | glow::INT_SAMPLER_2D_MULTISAMPLE | glow::UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE => {
            glow::TEXTURE_2D_MULTISAMPLE
        }
        glow::SAMPLER_CUBE_MAP_ARRAY | glow::SAMPLER_CUBE_MAP_ARRAY_SHADOW => glow::TEXTURE_CUBE_MAP_ARRAY,
        glow::SAMPLER_2D_RECT | glow::SAMPLER_2D_RECT_SHADOW => glow::TEXTURE_RECTANGLE,
        glow::SAMPLER_BUFFER | glow::INT_SAMPLER_BUFFER | glow::UNSIGNED_INT_SAMPLER_BUFFER => glow::TEXTURE_BUFFER,
        _ => return None,
    })
}
