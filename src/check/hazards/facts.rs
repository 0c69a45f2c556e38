//! What is known before a shader runs: uniform ranges and defaults from the manifest,
//! semantics (time, matrices, resolution) over the effect's animation, vertex attributes
//! from the mesh data, and texture channels from the texels.
//!
//! Semantic matrices and the camera position are sampled over the camera keys and one
//! full turn of the model's spin (257 instants); the hull of the samples is the fact.
//! Time runs over `[0, time limit]` (an hour unless `effectc.toml`'s `[hazards]` says
//! otherwise) unless the time uniform has a `range`.

use std::cell::Cell;
use std::collections::HashMap;

use glam::{Mat3, Mat4};
use naga::{Module, ScalarKind, TypeInner};

use super::interval::Iv;
use super::value::{singular_bounds, Num, Val};
use crate::assets::mesh::Mesh;
use crate::manifest::{CameraDecl, Effect, MeshAttribute, MeshSource, ModelDecl, Semantic, TextureSource, UniformDefault, UniformValue};

/// Frames a second a frame counter (`FrameCount`, `iFrame`) advances by.
const FRAMES_PER_SECOND: f64 = 60.0;

/// Largest frame size assumed for `resolution`-like values and `gl_FragCoord`.
const MAX_SIZE: f64 = 16_384.0;

/// Facts for one program.
#[derive(Debug, Default, Clone)]
pub struct Facts {
    /// Uniforms by manifest path (`minBI`, `lights[0].color`).
    pub uniforms: HashMap<String, Num>,
    /// Vertex inputs by location.
    pub attributes: HashMap<u32, Num>,
    /// Texture channels (r, g, b, a) by sampler name; unknown samplers are absent.
    pub textures: HashMap<String, [Iv; 4]>,
    /// Fragment inputs by location (from the vertex stage's outputs).
    pub varyings: HashMap<u32, Num>,
    /// `gl_FragCoord.xy` bounds.
    pub frame_size: (f64, f64),
    pub instances: u32,
    /// Vertices the effect's mesh draws (`gl_VertexID` stays below); `None` without a
    /// mesh: the index then depends on meshes nothing here knows, and stays unknown.
    pub vertices: Option<u32>,
    pub time_limit: f64,
    /// Bare stage files: the value of each semantic, for uniforms whose name suggests one
    /// (as the renderer guesses); empty for an effect.
    pub guessed: HashMap<Semantic, Num>,
    /// Inputs with a declared range (a manifest uniform's `range`, a `#pragma parameter`):
    /// the witness runs set each to points of it.
    pub declared: Vec<Declared>,
    /// Manifest uniforms that count time or frames.
    pub clocks: Vec<String>,
    /// Set once the analysis read a time or frame uniform.
    pub read_clock: Cell<bool>,
}

/// A scalar input with a declared range.
#[derive(Debug, Clone, PartialEq)]
pub struct Declared {
    /// The uniform (a member name for a block member).
    pub name: String,
    pub default: f64,
    pub range: (f64, f64),
    pub step: Option<f64>,
    pub by: DeclaredBy,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DeclaredBy {
    Manifest,
    Pragma,
}

impl DeclaredBy {
    /// Where the range comes from, for people: "manifest", "`#pragma parameter`".
    pub fn source(self) -> &'static str {
        match self {
            DeclaredBy::Manifest => "manifest",
            DeclaredBy::Pragma => "`#pragma parameter`",
        }
    }
}

impl Facts {
    /// Adds the stage's `#pragma parameter` declarations: a uniform of that name without a
    /// manifest fact takes any value of the declared range, and is declared.
    pub fn declare_parameters(&mut self, parameters: &[crate::front::parameters::Parameter]) {
        for p in parameters {
            if self.uniforms.contains_key(&p.name) || self.declared.iter().any(|d| d.name == p.name) {
                continue;
            }
            let mut n = Num::float(Iv::new(p.min, p.max));
            n.per_draw = true;
            self.uniforms.insert(p.name.clone(), n);
            let default = p.default.clamp(p.min, p.max);
            self.declared.push(Declared { name: p.name.clone(), default, range: (p.min, p.max), step: p.step, by: DeclaredBy::Pragma });
        }
    }
}

impl Facts {
    /// The facts an effect gives; `None` (bare stage files) knows nothing but builtins.
    /// `time_limit`: how long a time uniform without a `range` runs.
    pub fn of(effect: Option<&Effect>, attribute_names: &[(u32, String)], time_limit: f64) -> Facts {
        let mut f = Facts { frame_size: (MAX_SIZE, MAX_SIZE), instances: 1, time_limit, ..Facts::default() };
        let Some(e) = effect else { return f };
        if let Some((w, h)) = e.render.size {
            f.frame_size = (w as f64, h as f64);
        }
        f.instances = e.instances.as_ref().map_or(1, |i| i.count);
        if let Some(t) = e.uniforms.iter().find(|u| u.semantic == Some(Semantic::Time)).and_then(|u| u.range) {
            f.time_limit = t.1.max(0.0);
        }
        let motion = Motion::sample(e.camera.clone().unwrap_or_default(), &e.model, e.render.size);
        for u in &e.uniforms {
            if let Some(n) = uniform_fact(u, &motion, f.time_limit) {
                f.uniforms.insert(u.name.clone(), n);
            }
            if matches!(u.semantic, Some(Semantic::Time | Semantic::Frame)) {
                f.clocks.push(u.name.clone());
            }
            let scalar = u.value.as_ref().map(|v| v.scalars()).filter(|s| s.len() == 1).and_then(|s| s[0].as_f64());
            if let (Some((lo, hi)), None) = (u.range, u.semantic) {
                let default = scalar.unwrap_or(lo).clamp(lo, hi);
                f.declared.push(Declared { name: u.name.clone(), default, range: (lo, hi), step: None, by: DeclaredBy::Manifest });
            }
        }
        if let Some(mesh) = e.mesh.as_ref().and_then(|m| match &m.source {
            MeshSource::Builtin(b) => Some(Mesh::builtin(*b)),
            MeshSource::Obj(p) => Mesh::load_obj(p).ok(),
        }) {
            let explicit = e.mesh.as_ref().map(|m| m.attributes.clone()).unwrap_or_default();
            let per_instance = |name: &str| e.instances.as_ref().is_some_and(|d| d.attributes.iter().any(|a| a.input == name));
            f.mesh_attributes(&mesh, &explicit, attribute_names, &per_instance);
            f.vertices = u32::try_from(mesh.positions.len().max(mesh.indices.len())).ok();
        }
        for t in &e.textures {
            if let Some(channels) = texture_channels(&t.source, t.format) {
                f.textures.insert(t.name.clone(), channels);
            }
        }
        f
    }
}

impl Facts {
    /// The value of built-in input `b` (`unknown`, its type's unknown value, where
    /// nothing is known of it).
    pub fn builtin(&self, b: naga::BuiltIn, unknown: Val) -> Val {
        use naga::BuiltIn as Bi;
        let (w, h) = self.frame_size;
        let comps: Option<Vec<Iv>> = match b {
            Bi::Position { .. } => Some(vec![Iv::new(0.0, w), Iv::new(0.0, h), Iv::UNIT, Iv::new(f64::MIN_POSITIVE, f64::INFINITY)]),
            Bi::FrontFacing => Some(vec![Iv::UNIT]),
            Bi::VertexIndex => self.vertices.map(|n| vec![Iv::new(0.0, f64::from(n.max(1) - 1))]),
            Bi::InstanceIndex => Some(vec![Iv::new(0.0, f64::from(self.instances.max(1) - 1))]),
            Bi::PointCoord => Some(vec![Iv::UNIT, Iv::UNIT]),
            _ => None,
        };
        match (comps, unknown) {
            (Some(c), Val::Num(u)) if c.len() == u.c.len() => Val::Num(Num::from_comps(c, 1, u.kind, true)),
            (_, u) => u,
        }
    }

    /// The facts of bare stage files: what the renderer guesses for them. A uniform named
    /// like a semantic (`iTime`, `u_resolution`, `projection`) takes its values (time up to
    /// `time_limit`, the default camera's matrices). The vertex inputs stay unknown: the mesh the
    /// renderer guesses (a unit cube, a full-screen quad) says little about the user's own
    /// meshes, and its per-component hull made false positives (a cube's z spans 0 though
    /// no corner has z = 0).
    pub fn guessed(time_limit: f64) -> Facts {
        let mut f = Facts { frame_size: (MAX_SIZE, MAX_SIZE), instances: 1, time_limit, ..Facts::default() };
        let motion = Motion::sample(Default::default(), &Default::default(), None);
        for s in Semantic::ALL {
            if let Some(n) = semantic_fact(s, &motion, f.time_limit, None) {
                f.guessed.insert(s, Num { per_draw: true, ..n });
            }
        }
        f
    }

    /// The fact of every vertex input the mesh feeds (by the manifest's mapping, else by
    /// name), except those fed per instance.
    fn mesh_attributes(
        &mut self,
        mesh: &Mesh,
        explicit: &[(String, MeshAttribute)],
        attribute_names: &[(u32, String)],
        per_instance: &dyn Fn(&str) -> bool,
    ) {
        for (location, name) in attribute_names {
            if per_instance(name) {
                continue;
            }
            let attr = explicit.iter().find(|(n, _)| n == name).map(|(_, a)| *a).or_else(|| crate::assets::attribute_names::by_name(name));
            if let Some(a) = attr {
                self.attributes.insert(*location, attribute_fact(mesh, a, &mesh.attribute(a)));
            }
        }
    }

    /// The guessed semantic fact for the uniform at `path` whose unknown value is `u`.
    fn guess(&self, path: &str, u: &Num) -> Option<&Num> {
        if self.guessed.is_empty() {
            return None;
        }
        let leaf = path.rsplit('.').next().unwrap_or(path);
        let name = leaf.split('[').next().unwrap_or(leaf);
        let cols = u.cols.max(1);
        let shape = (cols as u8, (u.c.len() / cols) as u8);
        let semantic = crate::manifest::guess::semantic_by_name(name, shape, u.kind == ScalarKind::Float)?;
        // RetroArch's sizes stay unknown to the analysis: the renderer's guess (the frame's
        // size) says nothing of the source a pass really reads, and as a fact it hid two
        // certain divisions of the labelled set behind a possible one.
        if crate::manifest::guess::is_retroarch_size(name) {
            return None;
        }
        if matches!(semantic, Semantic::Time | Semantic::Frame) {
            self.read_clock.set(true);
        }
        self.guessed.get(&semantic)
    }
}

/// Per-component hull, length bounds and the cone property of one mesh attribute.
fn attribute_fact(mesh: &Mesh, attribute: MeshAttribute, data: &[[f32; 4]]) -> Num {
    let mut c = vec![Iv { lo: f64::INFINITY, hi: f64::NEG_INFINITY }; 4];
    let (mut len_lo, mut len_hi, mut l3_lo, mut l3_hi) = (f64::INFINITY, 0.0f64, f64::INFINITY, 0.0f64);
    for v in data {
        for (i, x) in v.iter().enumerate() {
            let x = f64::from(*x);
            c[i] = Iv { lo: c[i].lo.min(x), hi: c[i].hi.max(x) };
        }
        let l3 = v[..3].iter().map(|x| f64::from(*x).powi(2)).sum::<f64>().sqrt();
        let l = (l3 * l3 + f64::from(v[3]).powi(2)).sqrt();
        (len_lo, len_hi, l3_lo, l3_hi) = (len_lo.min(l), len_hi.max(l), l3_lo.min(l3), l3_hi.max(l3));
    }
    if data.is_empty() {
        return Num::unknown(4, 1, ScalarKind::Float);
    }
    let mut n = Num::from_comps(c, 1, ScalarKind::Float, true);
    n.len = n.len.meet(Iv::new(len_lo, len_hi).rounded());
    n.len3 = n.len3.meet(Iv::new(l3_lo, l3_hi).rounded());
    n.cone = matches!(attribute, MeshAttribute::Normal | MeshAttribute::Tangent | MeshAttribute::Bitangent) && cone_holds(mesh, data);
    n
}

/// Whether no triangle's per-vertex vectors (xyz) can interpolate to zero: a sufficient
/// test, every vertex vector has a positive dot product with their sum.
fn cone_holds(mesh: &Mesh, data: &[[f32; 4]]) -> bool {
    mesh.indices.chunks_exact(3).all(|t| {
        let v: Vec<[f64; 3]> = t
            .iter()
            .map(|&i| {
                let d = data[i as usize];
                [f64::from(d[0]), f64::from(d[1]), f64::from(d[2])]
            })
            .collect();
        let s = [v[0][0] + v[1][0] + v[2][0], v[0][1] + v[1][1] + v[2][1], v[0][2] + v[1][2] + v[2][2]];
        v.iter().all(|a| a[0] * s[0] + a[1] * s[1] + a[2] * s[2] > 1e-9)
    })
}

/// Channel ranges over every texel of a manifest texture (mipmaps average texels, so they
/// stay inside); `None` when it cannot be read (the renderer reports that).
fn texture_channels(source: &TextureSource, format: crate::manifest::TexelFormat) -> Option<[Iv; 4]> {
    use crate::assets::texture;
    let image = match source {
        TextureSource::File(p) => texture::load_file_as(p, format).ok()?,
        TextureSource::Faces(paths) => texture::load_faces(paths, format).ok()?,
        TextureSource::Generated { generator, size, params } => {
            texture::generate(*generator, *size, params, crate::manifest::TextureKind::D2, format)
        }
    };
    Some(image.channel_ranges().map(|(lo, hi)| Iv::new(lo, hi)))
}

/// Semantic values sampled over the effect's animation.
struct Motion {
    models: Vec<Mat4>,
    views: Vec<crate::assets::camera::View>,
}

impl Motion {
    /// The camera and model over time, at frame size `size` (default 512²).
    fn sample(camera: CameraDecl, model: &ModelDecl, size: Option<(u32, u32)>) -> Motion {
        let (w, h) = size.unwrap_or((512, 512));
        let aspect = w as f32 / h.max(1) as f32;
        let spin = model.spin.iter().map(|s| s.abs()).fold(0.0f32, f32::max);
        let mut span = camera.keys.last().map_or(0.0, |k| k.time);
        if spin > 0.0 {
            span = span.max(360.0 / f64::from(spin));
        }
        let times: Vec<f64> = (0..=256).map(|i| span * f64::from(i) / 256.0).collect();
        Motion {
            models: times.iter().map(|&t| crate::assets::camera::model_at(model, t)).collect(),
            views: times.iter().map(|&t| crate::assets::camera::view_at(&camera, t, aspect)).collect(),
        }
    }

    fn matrices(&self, s: Semantic) -> Vec<Mat4> {
        self.models
            .iter()
            .zip(&self.views)
            .map(|(&m, v)| match s {
                Semantic::Model => m,
                Semantic::View => v.view,
                Semantic::Projection => v.projection,
                Semantic::ModelView => v.view * m,
                Semantic::ViewProjection => v.projection * v.view,
                Semantic::ModelViewProjection => v.projection * v.view * m,
                _ => Mat4::from_mat3(Mat3::from_mat4(v.view * m).inverse().transpose()),
            })
            .collect()
    }
}

fn uniform_fact(u: &UniformDefault, motion: &Motion, time_limit: f64) -> Option<Num> {
    let mut n = match (&u.value, u.semantic) {
        (_, Some(s)) => semantic_fact(s, motion, time_limit, u.range)?,
        (Some(v), None) => {
            let scalars = v.scalars();
            let kind = if scalars.iter().all(|s| matches!(s, UniformValue::Int(_))) { ScalarKind::Sint } else { ScalarKind::Float };
            let comps: Vec<Iv> = scalars
                .iter()
                .map(|s| match s {
                    UniformValue::Bool(b) => Iv::point(f64::from(u8::from(*b))),
                    other => Iv::point(other.as_f64().unwrap_or(0.0)),
                })
                .map(|iv| match u.range {
                    Some((lo, hi)) => Iv::new(lo, hi),
                    None => iv,
                })
                .collect();
            let dims = v.dims();
            let cols = if dims.len() == 2 {
                dims[0]
            } else if comps.len() == 9 || comps.len() == 16 {
                (comps.len() as f64).sqrt() as usize
            } else {
                1
            };
            Num::from_comps(comps, cols, kind, true)
        }
        (None, None) => return None,
    };
    n.per_draw = true;
    Some(n)
}

fn semantic_fact(s: Semantic, motion: &Motion, time_limit: f64, range: Option<(f64, f64)>) -> Option<Num> {
    let scalar = |iv: Iv| Num::float(range.map_or(iv, |(lo, hi)| Iv::new(lo, hi)));
    Some(match s {
        Semantic::Time => scalar(Iv::new(0.0, time_limit)),
        Semantic::DeltaTime => scalar(Iv::new(0.0, 1.0)),
        // A frame counter over the same session, at 60 frames a second.
        Semantic::Frame => Num::scalar(Iv::new(0.0, (time_limit * FRAMES_PER_SECOND).min(f64::from(i32::MAX))), ScalarKind::Sint, true),
        Semantic::Resolution => {
            Num::from_comps(vec![Iv::new(1.0, MAX_SIZE), Iv::new(1.0, MAX_SIZE), Iv::point(1.0)], 1, ScalarKind::Float, true)
        }
        Semantic::Mouse => Num::from_comps(vec![Iv::new(0.0, MAX_SIZE); 4], 1, ScalarKind::Float, true),
        Semantic::CameraPosition => {
            let mut c = vec![Iv { lo: f64::INFINITY, hi: f64::NEG_INFINITY }; 3];
            for v in &motion.views {
                for (i, x) in v.eye.to_array().iter().enumerate() {
                    c[i] = c[i].join(Iv::point(f64::from(*x)));
                }
            }
            c.push(Iv::point(1.0));
            Num::from_comps(c, 1, ScalarKind::Float, true)
        }
        matrix => matrix_fact(&motion.matrices(matrix)),
    })
}

/// The hull of sampled 4x4 matrices with the gain bounds of their upper-left 3x3.
fn matrix_fact(samples: &[Mat4]) -> Num {
    let mut c = vec![Iv { lo: f64::INFINITY, hi: f64::NEG_INFINITY }; 16];
    let mut gain = Iv { lo: f64::INFINITY, hi: 0.0 };
    for m in samples {
        for (i, x) in m.to_cols_array().iter().enumerate() {
            c[i] = c[i].join(Iv::point(f64::from(*x)));
        }
        let a = m.to_cols_array();
        let m3 = [[a[0], a[1], a[2]], [a[4], a[5], a[6]], [a[8], a[9], a[10]]].map(|col| col.map(f64::from));
        let (lo, hi) = singular_bounds(&m3);
        gain = gain.join(Iv::new(lo, hi));
    }
    // Sampling misses values between instants: a little slack on every bound that moves.
    let c = c
        .into_iter()
        .map(|x| if x.is_point() { x } else { Iv::new(x.lo - 1e-3 * x.lo.abs().max(1.0), x.hi + 1e-3 * x.hi.abs().max(1.0)) })
        .collect();
    let mut n = Num::from_comps(c, 4, ScalarKind::Float, true);
    n.gain = Iv::new(gain.lo * 0.99, gain.hi * 1.01);
    n
}

/// The value of a uniform global of type `ty`, member by member from the facts.
pub fn uniform_value(module: &Module, ty: &TypeInner, path: &str, facts: &Facts) -> Val {
    match ty {
        TypeInner::Struct { members, .. } => Val::Agg(
            members
                .iter()
                .map(|m| {
                    let name = m.name.clone().unwrap_or_default();
                    let p = if path.is_empty() { name } else { format!("{path}.{name}") };
                    uniform_value(module, &module.types[m.ty].inner, &p, facts)
                })
                .collect(),
        ),
        TypeInner::Array { base, size: naga::ArraySize::Constant(n), .. } => {
            Val::Agg((0..n.get()).map(|i| uniform_value(module, &module.types[*base].inner, &format!("{path}[{i}]"), facts)).collect())
        }
        _ => {
            let unknown = Val::unknown(module, ty);
            let known = match &unknown {
                Val::Num(u) => facts.uniforms.get(path).or_else(|| facts.guess(path, u)),
                _ => facts.uniforms.get(path),
            };
            if facts.clocks.iter().any(|c| c == path) {
                facts.read_clock.set(true);
            }
            match (known, unknown) {
                (Some(n), Val::Num(u)) if n.c.len() == u.c.len() => {
                    let mut n = n.clone();
                    n.kind = u.kind;
                    n.cols = u.cols;
                    if u.cols > 1 && n.gain == Iv::NON_NEGATIVE {
                        n = Num { gain: n.gain, ..Num::from_comps(n.c.clone(), u.cols, u.kind, true) };
                        n.per_draw = true;
                    }
                    Val::Num(n)
                }
                (Some(n), Val::Num(u)) if u.cols == 1 && n.cols == 1 && u.c.len() < n.c.len() => {
                    // A vec3 camera position, a vec2 resolution: the leading components.
                    let mut m = Num::from_comps(n.c[..u.c.len()].to_vec(), 1, u.kind, true);
                    m.per_draw = true;
                    Val::Num(m)
                }
                (Some(n), Val::Num(u)) if u.cols > 1 && n.cols == 4 && u.cols == 3 && u.c.len() == 9 => {
                    // A mat3 uniform bound to a 4x4 semantic: the upper-left 3x3.
                    let c = (0..3).flat_map(|col| (0..3).map(move |row| (col, row))).map(|(col, row)| n.c[col * 4 + row]).collect();
                    let mut m = Num::from_comps(c, 3, u.kind, true);
                    m.gain = n.gain;
                    m.per_draw = true;
                    Val::Num(m)
                }
                (_, v) => v,
            }
        }
    }
}
