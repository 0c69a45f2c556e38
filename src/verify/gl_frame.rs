//! Frames drawn by the OpenGL driver: a framebuffer per run, GL textures for every target
//! (a single-pass program's colour outputs, or a multi-pass effect's named targets), each
//! pass drawn into its attachments in order, and the output read back top row first.

use std::collections::BTreeMap;

use glow::HasContext;

use crate::render::scene::Scene;

use super::gl_scene::GlScene;

/// A target texture and its format.
pub struct GlTarget {
    pub texture: glow::Texture,
    pub format: wgpu::TextureFormat,
    pub size: (u32, u32),
}

/// Where one pass draws.
pub struct PassTargets<'a> {
    /// Colour target names by location (`None`: nothing attached there).
    pub colors: Vec<Option<&'a str>>,
    /// The depth target's name, or a depth buffer of the pass's own.
    pub depth: Option<&'a str>,
    pub own_depth: bool,
    pub keep_depth: bool,
    pub clear: Option<[f32; 4]>,
    pub size: (u32, u32),
    /// (sampler, target) of the pass's `samples`.
    pub samples: &'a [(String, String)],
}

/// The framebuffer and every target of a program.
pub struct GlFrames {
    fbo: glow::Framebuffer,
    pub targets: BTreeMap<String, GlTarget>,
    /// Transient depth buffers by size.
    depths: BTreeMap<(u32, u32), glow::Texture>,
}

impl GlFrames {
    pub fn new(gl: &glow::Context) -> Result<GlFrames, String> {
        // SAFETY: object creation on the current context.
        let fbo = unsafe { gl.create_framebuffer()? };
        Ok(GlFrames { fbo, targets: BTreeMap::new(), depths: BTreeMap::new() })
    }

    /// Creates target `name` once.
    pub fn target(&mut self, gl: &glow::Context, name: &str, format: wgpu::TextureFormat, size: (u32, u32)) -> Result<(), String> {
        if self.targets.contains_key(name) {
            return Ok(());
        }
        let texture = texture(gl, format, size)?;
        self.targets.insert(name.to_string(), GlTarget { texture, format, size });
        Ok(())
    }

    /// Draws one pass of `scene` with `gl_scene` into `at`.
    pub fn draw(&mut self, gl: &glow::Context, gl_scene: &mut GlScene, scene: &Scene, at: &PassTargets<'_>) -> Result<(), String> {
        let depth = match (at.depth, at.own_depth) {
            (Some(name), _) => self.targets.get(name).map(|t| t.texture),
            (None, true) => Some(match self.depths.get(&at.size) {
                Some(t) => *t,
                None => {
                    let t = texture(gl, wgpu::TextureFormat::Depth32Float, at.size)?;
                    self.depths.insert(at.size, t);
                    t
                }
            }),
            (None, false) => None,
        };
        // Samplers that read earlier passes' targets, by the sampler's GLSL name.
        let textures: BTreeMap<String, glow::Texture> =
            at.samples.iter().filter_map(|(sampler, target)| Some((sampler.clone(), self.targets.get(target)?.texture))).collect();
        // SAFETY: framebuffer state and clears on the current context with its objects.
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(self.fbo));
            let mut draw_buffers = Vec::new();
            for i in 0..8u32 {
                let attached = at.colors.get(i as usize).copied().flatten().and_then(|n| self.targets.get(n));
                gl.framebuffer_texture_2d(glow::FRAMEBUFFER, glow::COLOR_ATTACHMENT0 + i, glow::TEXTURE_2D, attached.map(|t| t.texture), 0);
                if i < at.colors.len() as u32 {
                    draw_buffers.push(if attached.is_some() { glow::COLOR_ATTACHMENT0 + i } else { glow::NONE });
                }
            }
            gl.framebuffer_texture_2d(glow::FRAMEBUFFER, glow::DEPTH_ATTACHMENT, glow::TEXTURE_2D, depth, 0);
            gl.draw_buffers(&draw_buffers);
            let status = gl.check_framebuffer_status(glow::FRAMEBUFFER);
            if status != glow::FRAMEBUFFER_COMPLETE {
                return Err(format!("the GL framebuffer of this pass is incomplete (status 0x{status:x})"));
            }
            gl.viewport(0, 0, at.size.0 as i32, at.size.1 as i32);
            gl.disable(glow::SCISSOR_TEST);
            gl.color_mask(true, true, true, true);
            if let Some(c) = at.clear {
                for (i, name) in at.colors.iter().enumerate() {
                    let Some(t) = name.and_then(|n| self.targets.get(n)) else { continue };
                    if crate::render::frames::is_integer(t.format) {
                        gl.clear_buffer_i32_slice(glow::COLOR, i as u32, &c.map(|x| x as i32));
                    } else {
                        gl.clear_buffer_f32_slice(glow::COLOR, i as u32, &c);
                    }
                }
            }
            if depth.is_some() && (at.clear.is_some() || !at.keep_depth) {
                gl.depth_mask(true);
                gl.clear_buffer_f32_slice(glow::DEPTH, 0, &[1.0]);
            }
        }
        gl_scene.draw(gl, scene, &textures)?;
        // SAFETY: as above.
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
        Ok(())
    }

    /// The pixels of target `name` as RGBA8, top row first (float targets converted the way
    /// `render` converts its own).
    pub fn read(&self, gl: &glow::Context, name: &str) -> Option<Vec<u8>> {
        let t = self.targets.get(name)?;
        let (w, h) = t.size;
        let row = w as usize * 4;
        // SAFETY: reads into buffers sized for the target.
        unsafe {
            gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(self.fbo));
            for i in 1..8u32 {
                gl.framebuffer_texture_2d(glow::READ_FRAMEBUFFER, glow::COLOR_ATTACHMENT0 + i, glow::TEXTURE_2D, None, 0);
            }
            gl.framebuffer_texture_2d(glow::READ_FRAMEBUFFER, glow::DEPTH_ATTACHMENT, glow::TEXTURE_2D, None, 0);
            gl.framebuffer_texture_2d(glow::READ_FRAMEBUFFER, glow::COLOR_ATTACHMENT0, glow::TEXTURE_2D, Some(t.texture), 0);
            gl.read_buffer(glow::COLOR_ATTACHMENT0);
            gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
            let bottom_up = if t.format == wgpu::TextureFormat::Rgba8Unorm {
                let mut bytes = vec![0u8; row * h as usize];
                gl.read_pixels(0, 0, w as i32, h as i32, glow::RGBA, glow::UNSIGNED_BYTE, glow::PixelPackData::Slice(Some(&mut bytes)));
                bytes
            } else if crate::render::frames::is_integer(t.format) {
                // Integer targets are read as integers (GL refuses a float read of them) and
                // shown as `render` shows its integer frames.
                let signed = matches!(t.format, wgpu::TextureFormat::Rgba32Sint | wgpu::TextureFormat::R32Sint);
                let mut words = vec![0u8; row * 4 * h as usize];
                let ty = if signed { glow::INT } else { glow::UNSIGNED_INT };
                gl.read_pixels(0, 0, w as i32, h as i32, glow::RGBA_INTEGER, ty, glow::PixelPackData::Slice(Some(&mut words)));
                let values: Vec<f32> = words
                    .chunks_exact(4)
                    .map(|b| {
                        if signed {
                            i32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f32
                        } else {
                            u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f32
                        }
                    })
                    .collect();
                crate::render::encode::integers_to_rgba8(&values)
            } else {
                let mut floats = vec![0u8; row * 4 * h as usize];
                gl.read_pixels(0, 0, w as i32, h as i32, glow::RGBA, glow::FLOAT, glow::PixelPackData::Slice(Some(&mut floats)));
                let f: Vec<f32> = floats.chunks_exact(4).map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]])).collect();
                crate::render::encode::float_to_rgba8(&f)
            };
            gl.bind_framebuffer(glow::READ_FRAMEBUFFER, None);
            Some(bottom_up.chunks_exact(row).rev().flatten().copied().collect())
        }
    }

    /// Deletes every object.
    pub fn delete(self, gl: &glow::Context) {
        // SAFETY: objects of the current context.
        unsafe {
            gl.delete_framebuffer(self.fbo);
            for t in self.targets.values() {
                gl.delete_texture(t.texture);
            }
            for t in self.depths.values() {
                gl.delete_texture(*t);
            }
        }
    }
}

/// A GL texture for a target of `format`.
fn texture(gl: &glow::Context, format: wgpu::TextureFormat, (w, h): (u32, u32)) -> Result<glow::Texture, String> {
    use wgpu::TextureFormat as F;
    let (internal, fmt, ty) = match format {
        F::Rgba16Float => (glow::RGBA16F, glow::RGBA, glow::FLOAT),
        F::R16Float => (glow::R16F, glow::RED, glow::FLOAT),
        F::Rg16Float => (glow::RG16F, glow::RG, glow::FLOAT),
        F::R32Float => (glow::R32F, glow::RED, glow::FLOAT),
        F::Rg32Float => (glow::RG32F, glow::RG, glow::FLOAT),
        F::Rgba32Float => (glow::RGBA32F, glow::RGBA, glow::FLOAT),
        F::Rgba32Sint => (glow::RGBA32I, glow::RGBA_INTEGER, glow::INT),
        F::Rgba32Uint => (glow::RGBA32UI, glow::RGBA_INTEGER, glow::UNSIGNED_INT),
        F::R32Sint => (glow::R32I, glow::RED_INTEGER, glow::INT),
        F::R32Uint => (glow::R32UI, glow::RED_INTEGER, glow::UNSIGNED_INT),
        F::Depth32Float => (glow::DEPTH_COMPONENT32F, glow::DEPTH_COMPONENT, glow::FLOAT),
        _ => (glow::RGBA8, glow::RGBA, glow::UNSIGNED_BYTE),
    };
    // SAFETY: texture creation on the current context.
    unsafe {
        let t = gl.create_texture()?;
        gl.bind_texture(glow::TEXTURE_2D, Some(t));
        // Zeros, as wgpu starts every texture: a target nothing writes reads back as zeros.
        let texel = match (fmt, ty) {
            (glow::RGBA | glow::RGBA_INTEGER, glow::UNSIGNED_BYTE) => 4,
            (glow::RGBA | glow::RGBA_INTEGER, _) => 16,
            (glow::RG, _) => 8,
            _ => 4,
        };
        let zeros = vec![0u8; w as usize * h as usize * texel];
        gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
        gl.tex_image_2d(glow::TEXTURE_2D, 0, internal as i32, w as i32, h as i32, 0, fmt, ty, glow::PixelUnpackData::Slice(Some(&zeros)));
        gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MIN_FILTER, glow::NEAREST as i32);
        gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MAG_FILTER, glow::NEAREST as i32);
        gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MAX_LEVEL, 0);
        gl.bind_texture(glow::TEXTURE_2D, None);
        Ok(t)
    }
}
