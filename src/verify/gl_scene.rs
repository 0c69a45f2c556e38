//! One scene drawn by the OpenGL driver from the original GLSL: the same vertex bytes, the
//! same textures and sampler state, the uniform values the wgpu scene drew with, the same
//! depth, blend and cull state — in GL's own conventions (lower-left origin, [-1, 1] clip
//! depth, counter-clockwise front faces, the last vertex provoking `flat` values), which is
//! what the original program means.

use std::collections::BTreeMap;

use glow::HasContext;

use crate::manifest::{Blend, Cull, DepthCompare, Filter, TexelFormat, Wrap};
use crate::render::scene::replay::ReplayTexture;
use crate::render::scene::Scene;

use super::program::GlProgram;
use super::uniforms::GlUniforms;

/// A texture GL created, bound to one unit.
struct Bound {
    unit: u32,
    target: u32,
    texture: glow::Texture,
    /// Owned here (deleted with the scene); targets of other passes are not.
    owned: bool,
}

/// The GL objects of one scene.
pub struct GlScene {
    pub program: GlProgram,
    pub uniforms: GlUniforms,
    vao: glow::VertexArray,
    buffers: Vec<glow::Buffer>,
    textures: Vec<Bound>,
    /// Sampler uniforms that read the target of an earlier pass: (unit, sampler's GLSL
    /// name, filter).
    target_samplers: Vec<(u32, String, Filter)>,
    mode: u32,
    /// `GL_PATCH_VERTICES` for a draw of patches.
    patch_vertices: i32,
    indexed: bool,
    count: i32,
    instances: i32,
    /// Vertex inputs GL reads that the scene has no data for.
    pub unfed_inputs: Vec<String>,
}

impl GlScene {
    /// Uploads what `scene` draws with for `program`.
    pub fn new(gl: &glow::Context, program: GlProgram, scene: &Scene) -> Result<GlScene, String> {
        let uniforms = GlUniforms::new(gl, program.program, scene)?;
        let replay = &scene.replay;
        // SAFETY: object creation and state on the current context.
        unsafe {
            let vao = gl.create_vertex_array()?;
            gl.bind_vertex_array(Some(vao));
            let mut buffers = Vec::new();
            let vbo = gl.create_buffer()?;
            buffers.push(vbo);
            gl.bind_buffer(glow::ARRAY_BUFFER, Some(vbo));
            gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, &replay.vertices.bytes, glow::STATIC_DRAW);
            let ibo = match &replay.instances {
                Some(i) => {
                    let b = gl.create_buffer()?;
                    buffers.push(b);
                    gl.bind_buffer(glow::ARRAY_BUFFER, Some(b));
                    gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, &i.bytes, glow::STATIC_DRAW);
                    Some(b)
                }
                None => None,
            };
            let unfed_inputs = feed_attributes(gl, program.program, replay, vbo, ibo)?;
            let indexed = match &replay.draw.indices {
                Some(indices) => {
                    let b = gl.create_buffer()?;
                    buffers.push(b);
                    gl.bind_buffer(glow::ELEMENT_ARRAY_BUFFER, Some(b));
                    let bytes: Vec<u8> = indices.iter().flat_map(|i| i.to_le_bytes()).collect();
                    gl.buffer_data_u8_slice(glow::ELEMENT_ARRAY_BUFFER, &bytes, glow::STATIC_DRAW);
                    true
                }
                None => false,
            };
            gl.bind_vertex_array(None);
            let mut textures = Vec::new();
            let mut target_samplers = Vec::new();
            for s in &uniforms.samplers {
                let plan = scene_plan_texture(scene, &s.name);
                let (texture_name, sampler_name) = plan.unwrap_or_else(|| (s.name.clone(), format!("{}_sampler", s.name)));
                let sampler = replay.samplers.get(&sampler_name).copied().unwrap_or((Filter::Linear, Wrap::Repeat, false));
                match replay.textures.get(&texture_name) {
                    Some(ReplayTexture::Target(target)) => target_samplers.push((s.unit, target.clone(), sampler.0)),
                    Some(t) => {
                        // A rectangle sampler reads a rectangle texture, a 1D shadow sampler a
                        // 1D one, where the translation reads 2D textures.
                        let reshaped =
                            super::uniforms::sampler_type(s.gl_type).filter(|t| matches!(*t, glow::TEXTURE_RECTANGLE | glow::TEXTURE_1D));
                        let (target, texture) = upload(gl, t, sampler, reshaped)?;
                        textures.push(Bound { unit: s.unit, target, texture, owned: true });
                    }
                    None => {}
                }
            }
            let (mode, count) = (primitive_mode(replay.draw.primitive), replay.draw.count as i32);
            let instances = scene.instances as i32;
            let patch_vertices = replay.draw.patch_vertices as i32;
            Ok(GlScene {
                program,
                uniforms,
                vao,
                buffers,
                textures,
                target_samplers,
                mode,
                patch_vertices,
                indexed,
                count,
                instances,
                unfed_inputs,
            })
        }
    }

    /// Draws into the bound framebuffer (viewport and clears done by the caller), with the
    /// uniform values `scene` holds now and earlier passes' targets for its samplers
    /// (`targets`, by sampler name).
    pub fn draw(&mut self, gl: &glow::Context, scene: &Scene, targets: &BTreeMap<String, glow::Texture>) -> Result<(), String> {
        self.uniforms.upload(gl, self.program.program, scene);
        // SAFETY: the context is current.
        unsafe { super::fixed_function::set_state(super::uniforms::float_reader(scene))? };
        let r = &scene.replay.render;
        // SAFETY: state and draws on the current context with its objects.
        unsafe {
            for b in &self.textures {
                gl.active_texture(glow::TEXTURE0 + b.unit);
                gl.bind_texture(b.target, Some(b.texture));
            }
            for (unit, target, filter) in &self.target_samplers {
                gl.active_texture(glow::TEXTURE0 + unit);
                let texture = targets.get(target).copied();
                gl.bind_texture(glow::TEXTURE_2D, texture);
                if texture.is_some() {
                    set_sampler(gl, glow::TEXTURE_2D, (*filter, Wrap::Clamp, false), false);
                }
            }
            gl.active_texture(glow::TEXTURE0);
            // WebGPU filters cube maps across faces; GL does so when asked.
            gl.enable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
            // A vertex stage that writes `gl_PointSize` sets the size of its points in GL.
            gl.enable(glow::PROGRAM_POINT_SIZE);
            if scene.replay.depth {
                gl.enable(glow::DEPTH_TEST);
                gl.depth_func(depth_func(r.depth_compare));
                gl.depth_mask(r.depth_write);
            } else {
                gl.disable(glow::DEPTH_TEST);
            }
            match r.cull {
                Cull::None => gl.disable(glow::CULL_FACE),
                Cull::Back | Cull::Front => {
                    gl.enable(glow::CULL_FACE);
                    gl.cull_face(if r.cull == Cull::Back { glow::BACK } else { glow::FRONT });
                    gl.front_face(glow::CCW);
                }
            }
            set_blend(gl, r.blend);
            gl.bind_vertex_array(Some(self.vao));
            if self.mode == glow::PATCHES {
                gl.patch_parameter_i32(glow::PATCH_VERTICES, self.patch_vertices);
            }
            match (self.indexed, self.instances > 1) {
                (true, false) => gl.draw_elements(self.mode, self.count, glow::UNSIGNED_INT, 0),
                (true, true) => gl.draw_elements_instanced(self.mode, self.count, glow::UNSIGNED_INT, 0, self.instances),
                (false, false) => gl.draw_arrays(self.mode, 0, self.count),
                (false, true) => gl.draw_arrays_instanced(self.mode, 0, self.count, self.instances),
            }
            gl.bind_vertex_array(None);
            gl.depth_mask(true);
        }
        Ok(())
    }

    /// Deletes the GL objects.
    pub fn delete(self, gl: &glow::Context) {
        self.uniforms.delete(gl);
        // SAFETY: objects of the current context.
        unsafe {
            gl.delete_vertex_array(self.vao);
            for b in self.buffers {
                gl.delete_buffer(b);
            }
            for t in self.textures.iter().filter(|t| t.owned) {
                gl.delete_texture(t.texture);
            }
            gl.delete_program(self.program.program);
        }
    }
}

/// The (texture, sampler) binding names of the GLSL sampler `name` in the scene's plan.
fn scene_plan_texture(scene: &Scene, name: &str) -> Option<(String, String)> {
    scene.replay.plan_textures.iter().find(|(user, _, _)| user == name).map(|(_, t, s)| (t.clone(), s.clone()))
}

fn primitive_mode(primitive: &str) -> u32 {
    match primitive {
        "points" => glow::POINTS,
        "lines" => glow::LINES,
        "lines_adjacency" => glow::LINES_ADJACENCY,
        "triangles_adjacency" => glow::TRIANGLES_ADJACENCY,
        "patches" => glow::PATCHES,
        _ => glow::TRIANGLES,
    }
}

/// Points every vertex input GL reads at the scene's bytes for the translation's input of the
/// same name (a matrix input: each column, at GL's consecutive locations, from the column
/// input the translation split it into: `m_effectc_col0` on the GLSL route, `m_0` through
/// SPIR-V), and the legacy arrays of a program without a vertex stage. Returns the inputs
/// the scene has no data for (GL reads them as 0).
///
/// # Safety
/// A current GL context whose vertex array object is bound; `vbo` and `ibo` are its buffers.
unsafe fn feed_attributes(
    gl: &glow::Context,
    program: glow::Program,
    replay: &crate::render::scene::replay::Replay,
    vbo: glow::Buffer,
    ibo: Option<glow::Buffer>,
) -> Result<Vec<String>, String> {
    let mut unfed_inputs = Vec::new();
    let reflection_inputs = &replay.inputs;
    let mut read: Vec<(String, u32)> = (0..gl.get_active_attributes(program))
        .filter_map(|a| gl.get_active_attribute(program, a))
        .map(|a| (a.name, matrix_columns(a.atype)))
        .collect();
    // Without a vertex stage GL's fixed-function one reads the legacy arrays the
    // translation's stand-in reads.
    let legacy: Vec<(String, u32)> = reflection_inputs
        .iter()
        .map(|(n, _)| n.clone())
        .filter(|n| crate::front::compat::attribute(n).is_some() && !read.iter().any(|(r, _)| r == n))
        .map(|n| (n, 1))
        .collect();
    read.extend(legacy);
    for (name, columns) in read {
        let fixed_function = crate::front::compat::attribute(&name).is_some();
        if name.starts_with("gl_") && !fixed_function {
            continue;
        }
        let location = gl.get_attrib_location(program, &name);
        if location.is_none() && !fixed_function {
            continue;
        }
        let wgsl_location = |n: &str| reflection_inputs.iter().find(|(r, _)| r == n).map(|(_, l)| *l);
        // (GL location offset, the translation's input feeding it)
        let parts: Vec<(u32, Option<u32>)> = match wgsl_location(&name) {
            Some(l) => vec![(0, Some(l))],
            None if columns > 1 => (0..columns)
                .map(|c| (c, wgsl_location(&format!("{name}_effectc_col{c}")).or_else(|| wgsl_location(&format!("{name}_{c}")))))
                .collect(),
            None => vec![(0, None)],
        };
        for (offset, wgsl_location) in parts {
            let per_vertex = wgsl_location.and_then(|l| replay.vertices.attributes.iter().find(|x| x.shader_location == l));
            let per_instance =
                wgsl_location.and_then(|l| replay.instances.as_ref().and_then(|i| i.attributes.iter().find(|x| x.shader_location == l)));
            let (buffer, stride, attribute, divisor) = match (per_vertex, per_instance, ibo) {
                (_, Some(x), Some(b)) => (b, replay.instances.as_ref().map_or(0, |i| i.stride), x, 1),
                (Some(x), _, _) => (vbo, replay.vertices.stride, x, 0),
                _ => {
                    if !unfed_inputs.contains(&name) {
                        unfed_inputs.push(name.clone());
                    }
                    continue;
                }
            };
            gl.bind_buffer(glow::ARRAY_BUFFER, Some(buffer));
            let (size, ty, integer) = vertex_format(attribute.format);
            let Some(location) = location else {
                // `gl_Vertex`, `gl_Normal`, …: the legacy arrays.
                super::fixed_function::bind_attribute(&name, size, ty, stride as i32, attribute.offset as i32)?;
                continue;
            };
            let location = location + offset;
            gl.enable_vertex_attrib_array(location);
            if integer {
                gl.vertex_attrib_pointer_i32(location, size, ty, stride as i32, attribute.offset as i32);
            } else {
                gl.vertex_attrib_pointer_f32(location, size, ty, false, stride as i32, attribute.offset as i32);
            }
            gl.vertex_attrib_divisor(location, divisor);
        }
    }
    Ok(unfed_inputs)
}

/// The columns of a GL attribute type: 2–4 for a matrix (`FLOAT_MAT3x4`: 3), else 1.
fn matrix_columns(atype: u32) -> u32 {
    match atype {
        glow::FLOAT_MAT2 | glow::FLOAT_MAT2x3 | glow::FLOAT_MAT2x4 | glow::DOUBLE_MAT2 | glow::DOUBLE_MAT2x3 | glow::DOUBLE_MAT2x4 => 2,
        glow::FLOAT_MAT3 | glow::FLOAT_MAT3x2 | glow::FLOAT_MAT3x4 | glow::DOUBLE_MAT3 | glow::DOUBLE_MAT3x2 | glow::DOUBLE_MAT3x4 => 3,
        glow::FLOAT_MAT4 | glow::FLOAT_MAT4x2 | glow::FLOAT_MAT4x3 | glow::DOUBLE_MAT4 | glow::DOUBLE_MAT4x2 | glow::DOUBLE_MAT4x3 => 4,
        _ => 1,
    }
}

/// (components, GL type, read as integers) of a wgpu vertex format.
fn vertex_format(f: wgpu::VertexFormat) -> (i32, u32, bool) {
    use wgpu::VertexFormat as F;
    match f {
        F::Float32 => (1, glow::FLOAT, false),
        F::Float32x2 => (2, glow::FLOAT, false),
        F::Float32x3 => (3, glow::FLOAT, false),
        F::Sint32 => (1, glow::INT, true),
        F::Sint32x2 => (2, glow::INT, true),
        F::Sint32x3 => (3, glow::INT, true),
        F::Sint32x4 => (4, glow::INT, true),
        F::Uint32 => (1, glow::UNSIGNED_INT, true),
        F::Uint32x2 => (2, glow::UNSIGNED_INT, true),
        F::Uint32x3 => (3, glow::UNSIGNED_INT, true),
        F::Uint32x4 => (4, glow::UNSIGNED_INT, true),
        _ => (4, glow::FLOAT, false),
    }
}

fn depth_func(c: DepthCompare) -> u32 {
    match c {
        DepthCompare::Never => glow::NEVER,
        DepthCompare::Less => glow::LESS,
        DepthCompare::Equal => glow::EQUAL,
        DepthCompare::LessEqual => glow::LEQUAL,
        DepthCompare::Greater => glow::GREATER,
        DepthCompare::NotEqual => glow::NOTEQUAL,
        DepthCompare::GreaterEqual => glow::GEQUAL,
        DepthCompare::Always => glow::ALWAYS,
    }
}

/// The manifest's blend modes as `glBlendFuncSeparate` (the same factors `render` gives wgpu).
fn set_blend(gl: &glow::Context, blend: Blend) {
    // SAFETY: state on the current context.
    unsafe {
        let funcs = match blend {
            Blend::None => {
                gl.disable(glow::BLEND);
                return;
            }
            Blend::Alpha => (glow::SRC_ALPHA, glow::ONE_MINUS_SRC_ALPHA, glow::ONE, glow::ONE_MINUS_SRC_ALPHA),
            Blend::Additive => (glow::SRC_ALPHA, glow::ONE, glow::ONE, glow::ONE),
            Blend::Premultiplied => (glow::ONE, glow::ONE_MINUS_SRC_ALPHA, glow::ONE, glow::ONE_MINUS_SRC_ALPHA),
        };
        gl.enable(glow::BLEND);
        gl.blend_equation(glow::FUNC_ADD);
        gl.blend_func_separate(funcs.0, funcs.1, funcs.2, funcs.3);
    }
}

/// Filter, wrap and comparison on the bound texture of `target`.
fn set_sampler(gl: &glow::Context, target: u32, (filter, wrap, compare): (Filter, Wrap, bool), mipmapped: bool) {
    let (min, mag) = match (filter, mipmapped) {
        (Filter::Linear, true) => (glow::LINEAR_MIPMAP_LINEAR, glow::LINEAR),
        (Filter::Linear, false) => (glow::LINEAR, glow::LINEAR),
        (Filter::Nearest, true) => (glow::NEAREST_MIPMAP_NEAREST, glow::NEAREST),
        (Filter::Nearest, false) => (glow::NEAREST, glow::NEAREST),
    };
    let wrap = match wrap {
        Wrap::Repeat => glow::REPEAT,
        Wrap::Clamp => glow::CLAMP_TO_EDGE,
        Wrap::Mirror => glow::MIRRORED_REPEAT,
    };
    // SAFETY: state of the bound texture on the current context.
    unsafe {
        gl.tex_parameter_i32(target, glow::TEXTURE_MIN_FILTER, min as i32);
        gl.tex_parameter_i32(target, glow::TEXTURE_MAG_FILTER, mag as i32);
        for p in [glow::TEXTURE_WRAP_S, glow::TEXTURE_WRAP_T, glow::TEXTURE_WRAP_R] {
            gl.tex_parameter_i32(target, p, wrap as i32);
        }
        if compare {
            gl.tex_parameter_i32(target, glow::TEXTURE_COMPARE_MODE, glow::COMPARE_REF_TO_TEXTURE as i32);
            gl.tex_parameter_i32(target, glow::TEXTURE_COMPARE_FUNC, glow::LEQUAL as i32);
        }
    }
}

/// Creates the GL texture of `t` (with the same mip chain wgpu got) and its sampler state,
/// as the target the program's sampler reads where that is not the translation's
/// (`reshaped`): a rectangle texture has one level and clamps, as GL requires and as
/// `render` samples the 2D texture it reads instead; a 1D depth texture is one row.
fn upload(
    gl: &glow::Context,
    t: &ReplayTexture,
    sampler: (Filter, Wrap, bool),
    reshaped: Option<u32>,
) -> Result<(u32, glow::Texture), String> {
    let rect = reshaped == Some(glow::TEXTURE_RECTANGLE);
    let sampler = if rect { (sampler.0, Wrap::Clamp, sampler.2) } else { sampler };
    let target_of = |dimension: &str| reshaped.unwrap_or_else(|| texture_target(dimension));
    use glow::PixelUnpackData::Slice;
    // SAFETY: texture creation on the current context; slices sized by the images.
    unsafe {
        let texture = gl.create_texture()?;
        let target = match t {
            ReplayTexture::Image { image, dimension } => {
                let target = target_of(dimension);
                gl.bind_texture(target, Some(texture));
                // As `render` uploads: a mip chain for every 2D-based texture (arrays and cube
                // maps too), one level for 1D and 3D.
                let mipmapped =
                    !matches!(target, glow::TEXTURE_1D | glow::TEXTURE_3D | glow::TEXTURE_RECTANGLE) && image.format.filterable();
                let (internal, format, ty) = gl_format(image.format);
                let internal = internal as i32;
                let mut levels = vec![image.clone()];
                if mipmapped {
                    levels.extend(image.mip_chain());
                }
                gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
                for (mip, level) in levels.iter().enumerate() {
                    let (w, h) = (level.width as i32, level.height as i32);
                    let layer = |k: u32| level.layer(k % level.layers.max(1));
                    let m = mip as i32;
                    match target {
                        glow::TEXTURE_CUBE_MAP => {
                            for face in 0..6 {
                                let target = glow::TEXTURE_CUBE_MAP_POSITIVE_X + face;
                                gl.tex_image_2d(target, m, internal, w, h, 0, format, ty, Slice(layer(face)));
                            }
                        }
                        glow::TEXTURE_2D_ARRAY | glow::TEXTURE_3D | glow::TEXTURE_CUBE_MAP_ARRAY => {
                            let depth = match target {
                                glow::TEXTURE_3D => 1,
                                glow::TEXTURE_CUBE_MAP_ARRAY => 6,
                                _ => level.layers.max(1) as i32,
                            };
                            let data: Vec<u8> = (0..depth as u32).filter_map(layer).flatten().copied().collect();
                            gl.tex_image_3d(target, m, internal, w, h, depth, 0, format, ty, Slice(Some(&data)));
                        }
                        glow::TEXTURE_1D => {
                            let row = layer(0).map(|l| &l[..w as usize * level.format.texel_bytes()]);
                            gl.tex_image_1d(target, m, internal, w, 0, format, ty, Slice(row));
                        }
                        _ => gl.tex_image_2d(target, m, internal, w, h, 0, format, ty, Slice(layer(0))),
                    }
                }
                gl.tex_parameter_i32(target, glow::TEXTURE_MAX_LEVEL, levels.len() as i32 - 1);
                // GL reads an integer texture only when it is not filtered (else: incomplete, zeros).
                let sampler = if image.format.filterable() { sampler } else { (Filter::Nearest, sampler.1, sampler.2) };
                set_sampler(gl, target, sampler, mipmapped);
                target
            }
            ReplayTexture::Depth { dimension } => {
                let target = target_of(dimension);
                gl.bind_texture(target, Some(texture));
                depth_placeholder(gl, target);
                set_sampler(gl, target, sampler, false);
                target
            }
            ReplayTexture::Integer { unsigned, dimension } => {
                let target = target_of(dimension);
                gl.bind_texture(target, Some(texture));
                let zeros = [0u8; 16];
                let (internal, format) = if *unsigned { (glow::RGBA32UI, glow::RGBA_INTEGER) } else { (glow::RGBA32I, glow::RGBA_INTEGER) };
                let ty = if *unsigned { glow::UNSIGNED_INT } else { glow::INT };
                let t = if rect { glow::TEXTURE_RECTANGLE } else { glow::TEXTURE_2D };
                gl.tex_image_2d(t, 0, internal as i32, 1, 1, 0, format, ty, Slice(Some(&zeros)));
                set_sampler(gl, target, (Filter::Nearest, Wrap::Clamp, false), false);
                target
            }
            ReplayTexture::Multisampled { depth } => {
                let target = glow::TEXTURE_2D_MULTISAMPLE;
                gl.bind_texture(target, Some(texture));
                let internal = if *depth { glow::DEPTH_COMPONENT32F } else { glow::RGBA8 };
                gl.tex_image_2d_multisample(target, 4, internal as i32, 1, 1, true);
                clear_multisampled(gl, texture, *depth)?;
                target
            }
            ReplayTexture::Target(_) => glow::TEXTURE_2D,
        };
        Ok((target, texture))
    }
}

/// GL's internal format, pixel format and type for a manifest texture's texels.
fn gl_format(format: TexelFormat) -> (u32, u32, u32) {
    match format {
        TexelFormat::Rgba8 => (glow::RGBA8, glow::RGBA, glow::UNSIGNED_BYTE),
        TexelFormat::Rgba16f => (glow::RGBA16F, glow::RGBA, glow::HALF_FLOAT),
        TexelFormat::Rgba32f => (glow::RGBA32F, glow::RGBA, glow::FLOAT),
        TexelFormat::R32f => (glow::R32F, glow::RED, glow::FLOAT),
        TexelFormat::Rgba32i => (glow::RGBA32I, glow::RGBA_INTEGER, glow::INT),
        TexelFormat::Rgba32ui => (glow::RGBA32UI, glow::RGBA_INTEGER, glow::UNSIGNED_INT),
        TexelFormat::R32i => (glow::R32I, glow::RED_INTEGER, glow::INT),
        TexelFormat::R32ui => (glow::R32UI, glow::RED_INTEGER, glow::UNSIGNED_INT),
    }
}

fn texture_target(dimension: &str) -> u32 {
    match dimension {
        "1d" => glow::TEXTURE_1D,
        "3d" => glow::TEXTURE_3D,
        "cube" => glow::TEXTURE_CUBE_MAP,
        "2d_array" => glow::TEXTURE_2D_ARRAY,
        "cube_array" => glow::TEXTURE_CUBE_MAP_ARRAY,
        _ => glow::TEXTURE_2D,
    }
}

/// The depth placeholder `render` binds (one texel of depth 1.0, every face of a cube map)
/// into the texture bound at `target`.
fn depth_placeholder(gl: &glow::Context, target: u32) {
    use glow::PixelUnpackData::Slice;
    let one = 1.0f32.to_le_bytes();
    let (internal, format, ty) = (glow::DEPTH_COMPONENT32F as i32, glow::DEPTH_COMPONENT, glow::FLOAT);
    // SAFETY: the bound texture of the current context; one float of data.
    unsafe {
        match target {
            glow::TEXTURE_CUBE_MAP => {
                for face in 0..6 {
                    gl.tex_image_2d(glow::TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, internal, 1, 1, 0, format, ty, Slice(Some(&one)));
                }
            }
            glow::TEXTURE_1D => gl.tex_image_1d(target, 0, internal, 1, 0, format, ty, Slice(Some(&one))),
            glow::TEXTURE_RECTANGLE => gl.tex_image_2d(target, 0, internal, 1, 1, 0, format, ty, Slice(Some(&one))),
            _ => gl.tex_image_2d(glow::TEXTURE_2D, 0, internal, 1, 1, 0, format, ty, Slice(Some(&one))),
        }
    }
}

/// Clears a multisampled placeholder as `render` does: magenta, or depth 1.0.
fn clear_multisampled(gl: &glow::Context, texture: glow::Texture, depth: bool) -> Result<(), String> {
    // SAFETY: a temporary framebuffer on the current context.
    unsafe {
        let fbo = gl.create_framebuffer()?;
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fbo));
        let attachment = if depth { glow::DEPTH_ATTACHMENT } else { glow::COLOR_ATTACHMENT0 };
        gl.framebuffer_texture_2d(glow::FRAMEBUFFER, attachment, glow::TEXTURE_2D_MULTISAMPLE, Some(texture), 0);
        if depth {
            gl.clear_buffer_f32_slice(glow::DEPTH, 0, &[1.0]);
        } else {
            gl.draw_buffers(&[glow::COLOR_ATTACHMENT0]);
            gl.clear_buffer_f32_slice(glow::COLOR, 0, &[1.0, 0.0, 1.0, 1.0]);
        }
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        gl.delete_framebuffer(fbo);
    }
    Ok(())
}
