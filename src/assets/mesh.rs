//! CPU-side mesh data: the builtin meshes and Wavefront OBJ files, as flat vertex arrays.
//!
//! Builtins: `FullscreenQuad` (clip space, −1..1), `Quad` (xy, −0.5..0.5), `Cube` (24 vertices, flat
//! normals), `UvSphere` (radius 1, seam duplicated) and `PlaneGrid` (xz, −0.5..0.5). OBJ files are read
//! with `tobj`: triangulated, one index per vertex, every object merged into one mesh.
//!
//! Conventions (OpenGL): right-handed, y up; indices are a triangle list with counter-clockwise front
//! faces; uv (0, 0) is the bottom-left of the texture image; normals are unit length; tangents are unit,
//! orthogonal to the normal, with w = ±1 so that bitangent = cross(normal, tangent.xyz) · w (MikkTSpace);
//! colors are linear RGBA, white when the source has none.
//!
//! Builtin normals, uvs and tangents are exact, so they count as provided. For OBJ files missing
//! normals are computed (smooth, area-weighted, shared by every vertex at the same position) and tangents
//! always are, with MikkTSpace (`bevy_mikktspace`); where it has no answer (no uvs, degenerate
//! triangles) the tangent is some unit vector orthogonal to the normal.

use std::borrow::Cow;
use std::collections::HashMap;
use std::f32::consts::PI;
use std::path::Path;

use crate::manifest::BuiltinMesh;

/// Vertex attributes of one mesh, all arrays `vertex_count()` long.
#[derive(Debug, Clone, PartialEq)]
pub struct Mesh {
    pub positions: Vec<[f32; 3]>,
    pub normals: Vec<[f32; 3]>,
    pub uvs: Vec<[f32; 2]>,
    /// xyz tangent, w = bitangent sign (±1), MikkTSpace convention.
    pub tangents: Vec<[f32; 4]>,
    /// Linear RGBA; white when the source has none.
    pub colors: Vec<[f32; 4]>,
    /// Triangle list, counter-clockwise front faces (OpenGL default).
    pub indices: Vec<u32>,
    /// Attributes that came from the source rather than defaults/computation,
    /// by name: "position", "normal", "uv", "tangent", "color".
    pub provided: Vec<&'static str>,
    /// Attributes effectc computed (e.g. "normal" for an OBJ without normals, "tangent").
    pub computed: Vec<&'static str>,
}

/// The names [`Mesh::attribute`] knows.
pub const ATTRIBUTES: [&str; 6] = ["position", "normal", "uv", "tangent", "bitangent", "color"];

const WHITE: [f32; 4] = [1.0; 4];
const X: [f32; 3] = [1.0, 0.0, 0.0];
const Y: [f32; 3] = [0.0, 1.0, 0.0];
const Z: [f32; 3] = [0.0, 0.0, 1.0];

impl Mesh {
    /// A builtin mesh. Sphere and grid sizes below the manifest's minimums (3 segments, 2 rings,
    /// 1 division) are raised to them.
    pub fn builtin(b: BuiltinMesh) -> Mesh {
        match b {
            BuiltinMesh::FullscreenQuad => flat_quad(1.0),
            BuiltinMesh::FullscreenTriangle => fullscreen_triangle(),
            BuiltinMesh::Quad => flat_quad(0.5),
            BuiltinMesh::Cube => cube(),
            BuiltinMesh::UvSphere { segments, rings } => uv_sphere(segments.max(3), rings.max(2)),
            BuiltinMesh::PlaneGrid { divisions } => plane_grid(divisions.max(1)),
        }
    }

    /// Reads a Wavefront OBJ file; the error message is meant for the user.
    pub fn load_obj(path: &Path) -> Result<Mesh, String> {
        let name = file_label(path);
        let bytes = std::fs::read(path).map_err(|e| format!("cannot read {name}: {e}"))?;
        parse_obj(&String::from_utf8_lossy(&bytes), &name)
    }

    /// Like [`Mesh::load_obj`], from OBJ text in memory.
    pub fn from_obj_text(text: &str) -> Result<Mesh, String> {
        parse_obj(text, "the OBJ text")
    }

    /// Attribute data as 4 components per vertex: position w = 1; normal/uv/tangent padded
    /// with 0 (tangent keeps its w sign); color as is; "bitangent" = cross(normal, tangent.xyz) * tangent.w.
    /// None for an unknown name.
    pub fn attribute(&self, name: &str) -> Option<Vec<[f32; 4]>> {
        let data = match name {
            "position" => self.positions.iter().map(|&[x, y, z]| [x, y, z, 1.0]).collect(),
            "normal" => self.normals.iter().map(|&[x, y, z]| [x, y, z, 0.0]).collect(),
            "uv" => self.uvs.iter().map(|&[u, v]| [u, v, 0.0, 0.0]).collect(),
            "tangent" => self.tangents.clone(),
            "bitangent" => self.normals.iter().zip(&self.tangents).map(|(&n, &t)| bitangent(n, t)).collect(),
            "color" => self.colors.clone(),
            _ => return None,
        };
        Some(data)
    }

    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }

    /// Axis-aligned bounds (min, max) of positions; both zero for a mesh without vertices.
    pub fn bounds(&self) -> ([f32; 3], [f32; 3]) {
        let Some(&first) = self.positions.first() else {
            return ([0.0; 3], [0.0; 3]);
        };
        self.positions
            .iter()
            .fold((first, first), |(lo, hi), p| (std::array::from_fn(|i| lo[i].min(p[i])), std::array::from_fn(|i| hi[i].max(p[i]))))
    }
}

fn bitangent(normal: [f32; 3], tangent: [f32; 4]) -> [f32; 4] {
    let [x, y, z] = scale(cross(normal, [tangent[0], tangent[1], tangent[2]]), tangent[3]);
    [x, y, z, 0.0]
}

// ---------------------------------------------------------------------------------------------
// Builtin meshes

/// Collects the vertices and triangles of a builtin mesh.
#[derive(Default)]
struct Builder {
    positions: Vec<[f32; 3]>,
    normals: Vec<[f32; 3]>,
    uvs: Vec<[f32; 2]>,
    tangents: Vec<[f32; 4]>,
    indices: Vec<u32>,
}

impl Builder {
    fn next_index(&self) -> u32 {
        self.positions.len() as u32
    }

    fn vertex(&mut self, position: [f32; 3], normal: [f32; 3], uv: [f32; 2], tangent: [f32; 4]) {
        self.positions.push(position);
        self.normals.push(normal);
        self.uvs.push(uv);
        self.tangents.push(tangent);
    }

    fn triangle(&mut self, a: u32, b: u32, c: u32) {
        self.indices.extend([a, b, c]);
    }

    /// Two triangles for corners listed counter-clockwise (bottom-left, bottom-right, top-right, top-left).
    fn quad(&mut self, a: u32, b: u32, c: u32, d: u32) {
        self.indices.extend([a, b, c, a, c, d]);
    }

    /// A flat square of `divisions`×`divisions` quads around `center`, u along `u_axis` and v along
    /// `v_axis`; it faces cross(u_axis, v_axis) and spans `half` either side of the centre.
    fn patch(&mut self, center: [f32; 3], u_axis: [f32; 3], v_axis: [f32; 3], half: f32, divisions: u32) {
        let normal = cross(u_axis, v_axis);
        let tangent = [u_axis[0], u_axis[1], u_axis[2], 1.0];
        let first = self.next_index();
        let row = divisions + 1;
        for j in 0..row {
            let v = j as f32 / divisions as f32;
            for i in 0..row {
                let u = i as f32 / divisions as f32;
                let offset = add(scale(u_axis, half * (2.0 * u - 1.0)), scale(v_axis, half * (2.0 * v - 1.0)));
                self.vertex(add(center, offset), normal, [u, v], tangent);
            }
        }
        for j in 0..divisions {
            for i in 0..divisions {
                let a = first + j * row + i;
                self.quad(a, a + 1, a + row + 1, a + row);
            }
        }
    }

    fn finish(self) -> Mesh {
        let colors = vec![WHITE; self.positions.len()];
        Mesh {
            positions: self.positions,
            normals: self.normals,
            uvs: self.uvs,
            tangents: self.tangents,
            colors,
            indices: self.indices,
            provided: vec!["position", "normal", "uv", "tangent"],
            computed: Vec::new(),
        }
    }
}

/// A square in the xy plane facing +z, `half` either side of the origin.
fn flat_quad(half: f32) -> Mesh {
    let mut b = Builder::default();
    b.patch([0.0; 3], X, Y, half, 1);
    b.finish()
}

/// One triangle whose inside covers clip space −1..1: corners (−1, −1), (3, −1), (−1, 3),
/// uv 0..2 so that uv runs 0..1 across the visible part.
fn fullscreen_triangle() -> Mesh {
    Mesh {
        positions: vec![[-1.0, -1.0, 0.0], [3.0, -1.0, 0.0], [-1.0, 3.0, 0.0]],
        normals: vec![Z; 3],
        uvs: vec![[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]],
        tangents: vec![[1.0, 0.0, 0.0, 1.0]; 3],
        colors: vec![WHITE; 3],
        indices: vec![0, 1, 2],
        provided: vec!["position", "normal", "uv"],
        computed: vec!["tangent"],
    }
}

/// Faces as (u axis, v axis), chosen so every face reads upright from outside; the side faces have
/// v = +y, the top has v towards −z and the bottom v towards +z (as seen with +z facing the viewer).
const CUBE_FACES: [([f32; 3], [f32; 3]); 6] = [
    ([0.0, 0.0, -1.0], Y), // +x
    (Z, Y),                // −x
    (X, [0.0, 0.0, -1.0]), // +y
    (X, Z),                // −y
    (X, Y),                // +z
    ([-1.0, 0.0, 0.0], Y), // −z
];

fn cube() -> Mesh {
    let mut b = Builder::default();
    for (u_axis, v_axis) in CUBE_FACES {
        b.patch(scale(cross(u_axis, v_axis), 0.5), u_axis, v_axis, 0.5, 1);
    }
    b.finish()
}

/// The plane y = 0 facing +y, u along +x and v along −z.
fn plane_grid(divisions: u32) -> Mesh {
    let mut b = Builder::default();
    b.patch([0.0; 3], X, [0.0, 0.0, -1.0], 0.5, divisions);
    b.finish()
}

/// A point of the unit sphere at column `segment` (u = segment / segments) and v: u = 0 (and 1) at −z,
/// u = 0.5 facing +z; v = 0 at y = −1.
fn sphere_position(segment: u32, segments: u32, v: f32) -> [f32; 3] {
    // `segment % segments` puts the seam column exactly on the first one.
    let (sin, cos) = (2.0 * PI * (segment % segments) as f32 / segments as f32).sin_cos();
    let (radius, y) = (PI * v).sin_cos();
    [-sin * radius, -y, -cos * radius]
}

/// The unit tangent ∂P/∂u at u: it does not depend on v, so it is defined at the poles too.
fn sphere_tangent(u: f32) -> [f32; 4] {
    let (sin, cos) = (2.0 * PI * u).sin_cos();
    [-cos, 0.0, sin, 1.0]
}

/// Each pole is a row of `segments` vertices, u in the middle of its column, so no triangle is
/// degenerate; every ring between is a row of `segments + 1` vertices, the last repeating the first
/// with u = 1.
fn uv_sphere(segments: u32, rings: u32) -> Mesh {
    let mut b = Builder::default();
    let pole_u = |i: u32| (i as f32 + 0.5) / segments as f32;
    let south = b.next_index();
    for i in 0..segments {
        b.vertex([0.0, -1.0, 0.0], [0.0, -1.0, 0.0], [pole_u(i), 0.0], sphere_tangent(pole_u(i)));
    }
    let first_ring = b.next_index();
    let row = segments + 1;
    for j in 1..rings {
        let v = j as f32 / rings as f32;
        for i in 0..row {
            let u = i as f32 / segments as f32;
            let position = sphere_position(i, segments, v);
            b.vertex(position, normalize(position).unwrap_or(Y), [u, v], sphere_tangent(u));
        }
    }
    let north = b.next_index();
    for i in 0..segments {
        b.vertex([0.0, 1.0, 0.0], [0.0, 1.0, 0.0], [pole_u(i), 1.0], sphere_tangent(pole_u(i)));
    }

    for i in 0..segments {
        b.triangle(south + i, first_ring + i + 1, first_ring + i);
    }
    for j in 0..rings - 2 {
        for i in 0..segments {
            let a = first_ring + j * row + i;
            b.quad(a, a + 1, a + row + 1, a + row);
        }
    }
    let last_ring = first_ring + (rings - 2) * row;
    for i in 0..segments {
        b.triangle(last_ring + i, last_ring + i + 1, north + i);
    }
    b.finish()
}

// ---------------------------------------------------------------------------------------------
// OBJ files

fn file_label(path: &Path) -> String {
    format!("`{}`", path.display())
}

/// Reads OBJ `text`; `name` says where it came from in messages (“`teapot.obj`”).
fn parse_obj(text: &str, name: &str) -> Result<Mesh, String> {
    let scan = scan_obj(text).map_err(|(line, problem)| format!("line {line} of {name}: {problem}"))?;
    scan.check_colors(name)?;
    // tobj turns `l` lines of three or more points into faces; polylines are not surfaces.
    let text = if scan.polylines { Cow::Owned(without_polylines(text)) } else { Cow::Borrowed(text) };
    let no_materials = |_: &Path| Err(tobj::LoadError::OpenFileFailed);
    let (models, _) = tobj::load_obj_buf(&mut text.as_bytes(), &tobj::GPU_LOAD_OPTIONS, no_materials)
        .map_err(|e| format!("cannot read {name} as OBJ: {e}"))?;
    check_finite(&models, name)?;
    let merged = ObjVertices::merge(&models, name)?;
    if merged.indices.is_empty() {
        return Err(if scan.faces == 0 {
            format!("no triangles in {name}: it has no `f` lines")
        } else {
            format!("no triangles in {name}: its faces are all points or lines")
        });
    }
    Ok(merged.into_mesh())
}

/// What a first pass over the text finds. It reports bad lines by number, and catches what `tobj`
/// would misread or panic on: face indices out of range (huge relative ones overflow its index
/// arithmetic) and vertex colors it would parse only in part.
#[derive(Default)]
struct ObjScan {
    /// `v`, `vt` and `vn` lines so far (the totals once the scan is done).
    counts: [usize; 3],
    /// The largest 1-based index faces use for each kind, and its line.
    largest: [(usize, usize); 3],
    /// `v` lines with a color.
    colored: usize,
    faces: usize,
    polylines: bool,
}

const KINDS: [&str; 3] = ["position", "texture coordinate", "normal"];

fn scan_obj(text: &str) -> Result<ObjScan, (usize, String)> {
    let mut scan = ObjScan::default();
    for (number, line) in text.lines().enumerate() {
        let number = number + 1;
        let mut words = line.split_whitespace();
        let read = |kind: usize, words: &mut std::str::SplitWhitespace, n: usize| {
            let ok = words.by_ref().take(n).filter(|w| w.parse::<f32>().is_ok()).count() == n;
            ok.then_some(()).ok_or_else(|| (number, format!("cannot read the {} in `{}`", KINDS[kind], line.trim())))
        };
        match words.next() {
            Some("v") => {
                read(0, &mut words, 3)?;
                scan.counts[0] += 1;
                let extra: Vec<&str> = words.collect();
                scan.position_extras(&extra, line.trim()).map_err(|problem| (number, problem))?;
            }
            Some("vt") => {
                read(1, &mut words, 2)?;
                scan.counts[1] += 1;
            }
            Some("vn") => {
                read(2, &mut words, 3)?;
                scan.counts[2] += 1;
            }
            Some("f") => {
                scan.faces += 1;
                for corner in words {
                    scan.face_corner(corner, number).map_err(|problem| (number, problem))?;
                }
            }
            Some("l") => scan.polylines = true,
            Some("usemtl") if words.next().is_none() => {
                return Err((number, "`usemtl` needs a material name".to_owned()));
            }
            _ => {}
        }
    }
    scan.check_largest()?;
    Ok(scan)
}

impl ObjScan {
    /// What may follow the x y z of a `v` line: nothing, a w to divide by, or an r g b color.
    fn position_extras(&mut self, extra: &[&str], line: &str) -> Result<(), String> {
        let numbers: Option<Vec<f32>> = extra.iter().map(|w| w.parse().ok()).collect();
        match (extra.len(), numbers) {
            (0, _) => {}
            (1, Some(w)) if w[0] == 0.0 => return Err(format!("`{line}` has w = 0")),
            (1, Some(_)) => {}
            (1, None) => return Err(format!("cannot read the w in `{line}`")),
            (3, Some(_)) => self.colored += 1,
            (3, None) => return Err(format!("cannot read the vertex color in `{line}`")),
            _ => return Err(format!("`{line}` should be x y z, optionally followed by w or by an r g b color")),
        }
        Ok(())
    }

    /// Checks one `v/vt/vn` corner of a face. Relative (negative) indices must point at something
    /// already read; positive ones are checked against the totals at the end.
    fn face_corner(&mut self, corner: &str, line: usize) -> Result<(), String> {
        let unreadable = || format!("cannot read the face corner `{corner}`");
        for (kind, part) in corner.split('/').enumerate() {
            if kind >= KINDS.len() {
                return Err(unreadable());
            }
            if part.is_empty() {
                if kind == 0 {
                    return Err(format!("the face corner `{corner}` has no position index"));
                }
                continue;
            }
            let index: i64 = part.parse().map_err(|_| unreadable())?;
            let so_far = self.counts[kind];
            if index == 0 {
                return Err(format!("the face corner `{corner}` uses index 0; OBJ indices start at 1"));
            }
            if index < 0 && index.unsigned_abs() > so_far as u64 {
                return Err(format!("the face corner `{corner}` refers to {} {index}, but only {so_far} come before it", KINDS[kind]));
            }
            let index = usize::try_from(index).unwrap_or(0);
            if index > self.largest[kind].0 {
                self.largest[kind] = (index, line);
            }
        }
        Ok(())
    }

    fn check_largest(&self) -> Result<(), (usize, String)> {
        for (kind, &(index, line)) in self.largest.iter().enumerate() {
            let count = self.counts[kind];
            if index > count {
                let what = KINDS[kind];
                return Err((line, format!("a face refers to {what} {index}, but there are only {count}")));
            }
        }
        Ok(())
    }

    fn check_colors(&self, name: &str) -> Result<(), String> {
        if self.colored > 0 && self.colored < self.counts[0] {
            return Err(format!(
                "only {} of the {} `v` lines in {name} have a vertex color; give one on every `v` line or on none",
                self.colored, self.counts[0]
            ));
        }
        Ok(())
    }
}

fn without_polylines(text: &str) -> String {
    let keep = |line: &&str| line.split_whitespace().next() != Some("l");
    text.lines().filter(keep).collect::<Vec<_>>().join("\n")
}

fn check_finite(models: &[tobj::Model], name: &str) -> Result<(), String> {
    for model in models {
        let m = &model.mesh;
        let arrays = [
            ("position", &m.positions, 3),
            ("normal", &m.normals, 3),
            ("texture coordinate", &m.texcoords, 2),
            ("vertex color", &m.vertex_color, 3),
        ];
        for (what, values, width) in arrays {
            if let Some(bad) = values.chunks(width).find(|c| c.iter().any(|x| !x.is_finite())) {
                let shown: Vec<String> = bad.iter().map(|x| x.to_string()).collect();
                return Err(format!("{name} has a {what} that is not a finite number: `{}`", shown.join(" ")));
            }
        }
    }
    Ok(())
}

/// The triangles of every OBJ model in one list; `None` where the file gave no value.
#[derive(Default)]
struct ObjVertices {
    positions: Vec<[f32; 3]>,
    normals: Vec<Option<[f32; 3]>>,
    uvs: Vec<Option<[f32; 2]>>,
    colors: Vec<Option<[f32; 4]>>,
    indices: Vec<u32>,
}

impl ObjVertices {
    fn merge(models: &[tobj::Model], name: &str) -> Result<ObjVertices, String> {
        let total: usize = models.iter().map(|m| m.mesh.positions.len() / 3).sum();
        if u32::try_from(total).is_err() {
            return Err(format!("{name} has {total} vertices; at most {} fit in 32-bit indices", u32::MAX));
        }
        let mut merged = ObjVertices::default();
        for model in models {
            merged.append(&model.mesh);
        }
        Ok(merged)
    }

    /// Adds one model. Attributes the file gave for only some of its vertices do not line up with
    /// them after tobj's single indexing, so they count as missing.
    fn append(&mut self, mesh: &tobj::Mesh) {
        let count = mesh.positions.len() / 3;
        let base = self.positions.len() as u32;
        self.positions.extend(mesh.positions.chunks_exact(3).map(|p| [p[0], p[1], p[2]]));
        if mesh.normals.len() == count * 3 {
            self.normals.extend(mesh.normals.chunks_exact(3).map(|n| normalize([n[0], n[1], n[2]])));
        } else {
            self.normals.extend(std::iter::repeat_n(None, count));
        }
        if mesh.texcoords.len() == count * 2 {
            self.uvs.extend(mesh.texcoords.chunks_exact(2).map(|t| Some([t[0], t[1]])));
        } else {
            self.uvs.extend(std::iter::repeat_n(None, count));
        }
        if mesh.vertex_color.len() == count * 3 {
            self.colors.extend(mesh.vertex_color.chunks_exact(3).map(|c| Some([c[0], c[1], c[2], 1.0])));
        } else {
            self.colors.extend(std::iter::repeat_n(None, count));
        }
        let usable = mesh.indices.len() - mesh.indices.len() % 3;
        self.indices.extend(mesh.indices[..usable].iter().map(|&i| base + i));
    }

    fn into_mesh(self) -> Mesh {
        let mut provided = vec!["position"];
        let mut computed = Vec::new();
        if self.normals.iter().all(Option::is_some) {
            provided.push("normal");
        } else {
            computed.push("normal");
        }
        if self.uvs.iter().all(Option::is_some) {
            provided.push("uv");
        }
        computed.push("tangent");
        if self.colors.iter().all(Option::is_some) {
            provided.push("color");
        }
        let normals = resolve_normals(&self.positions, &self.normals, &self.indices);
        let tangents = compute_tangents(&self.positions, &normals, &self.uvs, &self.indices);
        Mesh {
            uvs: self.uvs.iter().map(|uv| uv.unwrap_or_default()).collect(),
            colors: self.colors.iter().map(|c| c.unwrap_or(WHITE)).collect(),
            positions: self.positions,
            normals,
            tangents,
            indices: self.indices,
            provided,
            computed,
        }
    }
}

/// The file's normals where it has usable ones, else smooth normals, else +y.
fn resolve_normals(positions: &[[f32; 3]], normals: &[Option<[f32; 3]>], indices: &[u32]) -> Vec<[f32; 3]> {
    let smooth = if normals.iter().any(Option::is_none) { smooth_normals(positions, indices) } else { Vec::new() };
    let from_smooth = |i: usize| smooth.get(i).copied().flatten();
    normals.iter().enumerate().map(|(i, n)| n.or_else(|| from_smooth(i)).unwrap_or(Y)).collect()
}

/// Area-weighted vertex normals, summed over every vertex at the same position so that uv seams
/// stay smooth. `None` where the adjacent triangles have no area.
fn smooth_normals(positions: &[[f32; 3]], indices: &[u32]) -> Vec<Option<[f32; 3]>> {
    // `+ 0.0` turns −0.0 into 0.0, so both land on one key.
    let key = |p: [f32; 3]| p.map(|c| (c + 0.0).to_bits());
    let mut sums: HashMap<[u32; 3], [f32; 3]> = HashMap::new();
    for triangle in indices.chunks_exact(3) {
        let [a, b, c] = [triangle[0], triangle[1], triangle[2]].map(|i| positions[i as usize]);
        // Twice the triangle's area, along its normal.
        let weighted = cross(sub(b, a), sub(c, a));
        for corner in [a, b, c] {
            let sum = sums.entry(key(corner)).or_insert([0.0; 3]);
            *sum = add(*sum, weighted);
        }
    }
    positions.iter().map(|&p| sums.get(&key(p)).and_then(|&sum| normalize(sum))).collect()
}

/// MikkTSpace tangents where there are uvs, made exactly orthonormal; any orthogonal unit vector
/// where MikkTSpace has none.
fn compute_tangents(positions: &[[f32; 3]], normals: &[[f32; 3]], uvs: &[Option<[f32; 2]>], indices: &[u32]) -> Vec<[f32; 4]> {
    let mut found = vec![None; positions.len()];
    if uvs.iter().any(Option::is_some) {
        let uvs: Vec<[f32; 2]> = uvs.iter().map(|uv| uv.unwrap_or_default()).collect();
        let mut geometry = MikkGeometry { positions, normals, uvs: &uvs, indices, tangents: found };
        // It cannot fail today (the error type has no values); vertices it leaves out fall back below.
        let _ = bevy_mikktspace::generate_tangents(&mut geometry);
        found = geometry.tangents;
    }
    normals.iter().zip(found).map(|(&n, t)| orthonormal_tangent(n, t)).collect()
}

/// `tangent` made unit and orthogonal to `normal`, or any such vector if it cannot be.
fn orthonormal_tangent(normal: [f32; 3], tangent: Option<[f32; 4]>) -> [f32; 4] {
    let fixed = tangent.and_then(|t| {
        let [x, y, z] = normalize(reject([t[0], t[1], t[2]], normal))?;
        Some([x, y, z, if t[3] < 0.0 { -1.0 } else { 1.0 }])
    });
    fixed.unwrap_or_else(|| any_tangent(normal))
}

/// A unit vector orthogonal to `normal`: +x (or +z when the normal is close to ±x) projected onto
/// the plane of the normal.
fn any_tangent(normal: [f32; 3]) -> [f32; 4] {
    let axis = if normal[0].abs() < 0.9 { X } else { Z };
    let [x, y, z] = normalize(reject(axis, normal)).unwrap_or(axis);
    [x, y, z, 1.0]
}

/// The triangle list as `bevy_mikktspace` reads it; tangents are collected per vertex.
struct MikkGeometry<'a> {
    positions: &'a [[f32; 3]],
    normals: &'a [[f32; 3]],
    uvs: &'a [[f32; 2]],
    indices: &'a [u32],
    tangents: Vec<Option<[f32; 4]>>,
}

impl MikkGeometry<'_> {
    fn vertex(&self, face: usize, corner: usize) -> usize {
        self.indices[face * 3 + corner] as usize
    }
}

impl bevy_mikktspace::Geometry for MikkGeometry<'_> {
    fn num_faces(&self) -> usize {
        self.indices.len() / 3
    }

    fn num_vertices_of_face(&self, _face: usize) -> usize {
        3
    }

    fn position(&self, face: usize, vert: usize) -> [f32; 3] {
        self.positions[self.vertex(face, vert)]
    }

    fn normal(&self, face: usize, vert: usize) -> [f32; 3] {
        self.normals[self.vertex(face, vert)]
    }

    fn tex_coord(&self, face: usize, vert: usize) -> [f32; 2] {
        self.uvs[self.vertex(face, vert)]
    }

    fn set_tangent(&mut self, tangent_space: Option<bevy_mikktspace::TangentSpace>, face: usize, vert: usize) {
        if let Some(space) = tangent_space {
            let vertex = self.vertex(face, vert);
            self.tangents[vertex] = Some(space.tangent_encoded());
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Vector helpers

fn add(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn sub(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn scale(a: [f32; 3], s: f32) -> [f32; 3] {
    [a[0] * s, a[1] * s, a[2] * s]
}

fn dot(a: [f32; 3], b: [f32; 3]) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// `v` without its component along the unit vector `n`.
fn reject(v: [f32; 3], n: [f32; 3]) -> [f32; 3] {
    sub(v, scale(n, dot(v, n)))
}

/// `v` at unit length, or `None` if it is zero or not finite. Scaling by the largest component
/// first keeps tiny and huge vectors from underflowing or overflowing.
fn normalize(v: [f32; 3]) -> Option<[f32; 3]> {
    if !v.iter().all(|c| c.is_finite()) {
        return None;
    }
    let largest = v.iter().fold(0.0_f32, |m, c| m.max(c.abs()));
    if largest <= 0.0 {
        return None;
    }
    let v = v.map(|c| c / largest);
    let length = dot(v, v).sqrt();
    Some(v.map(|c| c / length))
}

#[cfg(test)]
mod tests {
    use super::*;

    const SPHERE: BuiltinMesh = BuiltinMesh::UvSphere { segments: 8, rings: 4 };
    const TINY_SPHERE: BuiltinMesh = BuiltinMesh::UvSphere { segments: 3, rings: 2 };
    const GRID: BuiltinMesh = BuiltinMesh::PlaneGrid { divisions: 3 };

    fn all_builtins() -> Vec<(BuiltinMesh, Mesh)> {
        [BuiltinMesh::FullscreenQuad, BuiltinMesh::Quad, BuiltinMesh::Cube, SPHERE, TINY_SPHERE, GRID]
            .into_iter()
            .map(|b| (b, Mesh::builtin(b)))
            .collect()
    }

    fn obj(text: &str) -> Mesh {
        match Mesh::from_obj_text(text) {
            Ok(mesh) => mesh,
            Err(e) => panic!("OBJ rejected: {e}\n{text}"),
        }
    }

    fn obj_error(text: &str) -> String {
        match Mesh::from_obj_text(text) {
            Ok(mesh) => panic!("OBJ accepted ({} triangles):\n{text}", mesh.triangle_count()),
            Err(e) => e,
        }
    }

    fn close(a: f32, b: f32) -> bool {
        (a - b).abs() < 1e-4
    }

    fn close3(a: [f32; 3], b: [f32; 3]) -> bool {
        (0..3).all(|i| close(a[i], b[i]))
    }

    fn xyz(v: [f32; 4]) -> [f32; 3] {
        [v[0], v[1], v[2]]
    }

    fn length(v: [f32; 3]) -> f32 {
        dot(v, v).sqrt()
    }

    fn triangles(mesh: &Mesh) -> impl Iterator<Item = [usize; 3]> + '_ {
        mesh.indices.chunks_exact(3).map(|t| [t[0] as usize, t[1] as usize, t[2] as usize])
    }

    /// Everything any mesh must satisfy; `what` names it in failures.
    fn check_invariants(mesh: &Mesh, what: &str) {
        let n = mesh.vertex_count();
        assert_eq!(mesh.normals.len(), n, "{what}: normals");
        assert_eq!(mesh.uvs.len(), n, "{what}: uvs");
        assert_eq!(mesh.tangents.len(), n, "{what}: tangents");
        assert_eq!(mesh.colors.len(), n, "{what}: colors");
        assert_eq!(mesh.indices.len() % 3, 0, "{what}: index count");
        assert!(mesh.indices.iter().all(|&i| (i as usize) < n), "{what}: index out of range");
        for name in ATTRIBUTES {
            let data = mesh.attribute(name).unwrap_or_else(|| panic!("{what}: no {name}"));
            assert_eq!(data.len(), n, "{what}: {name}");
            assert!(data.iter().flatten().all(|c| c.is_finite()), "{what}: {name} not finite");
        }
        for (i, (&normal, &tangent)) in mesh.normals.iter().zip(&mesh.tangents).enumerate() {
            assert!(close(length(normal), 1.0), "{what}: normal {i} = {normal:?}");
            assert!(close(length(xyz(tangent)), 1.0), "{what}: tangent {i} = {tangent:?}");
            assert!(close(dot(normal, xyz(tangent)), 0.0), "{what}: tangent {i} not ⟂ normal");
            assert!(tangent[3] == 1.0 || tangent[3] == -1.0, "{what}: tangent sign {i} = {}", tangent[3]);
        }
    }

    /// cross(b − a, c − a) points the way of the vertex normals (CCW front faces).
    fn check_winding(mesh: &Mesh, what: &str) {
        for [a, b, c] in triangles(mesh) {
            let p = |i: usize| mesh.positions[i];
            let face = cross(sub(p(b), p(a)), sub(p(c), p(a)));
            let normals = add(add(mesh.normals[a], mesh.normals[b]), mesh.normals[c]);
            assert!(dot(face, normals) > 0.0, "{what}: triangle {a} {b} {c} is clockwise");
        }
    }

    /// The stored tangent follows ∂P/∂u and the bitangent ∂P/∂v of each triangle's uv mapping.
    fn check_tangent_frame(mesh: &Mesh, what: &str) {
        let bitangents = mesh.attribute("bitangent").unwrap_or_default();
        for [a, b, c] in triangles(mesh) {
            let (e1, e2) = (sub(mesh.positions[b], mesh.positions[a]), sub(mesh.positions[c], mesh.positions[a]));
            let (uv0, uv1, uv2) = (mesh.uvs[a], mesh.uvs[b], mesh.uvs[c]);
            let (du1, dv1, du2, dv2) = (uv1[0] - uv0[0], uv1[1] - uv0[1], uv2[0] - uv0[0], uv2[1] - uv0[1]);
            let det = du1 * dv2 - du2 * dv1;
            if det.abs() < 1e-6 {
                continue;
            }
            let dp_du = scale(sub(scale(e1, dv2), scale(e2, dv1)), 1.0 / det);
            let dp_dv = scale(sub(scale(e2, du1), scale(e1, du2)), 1.0 / det);
            for v in [a, b, c] {
                assert!(dot(xyz(mesh.tangents[v]), dp_du) > 0.0, "{what}: tangent {v} against ∂P/∂u");
                assert!(dot(xyz(bitangents[v]), dp_dv) > 0.0, "{what}: bitangent {v} against ∂P/∂v");
            }
        }
    }

    #[test]
    fn builtin_counts() {
        let counts = |b| {
            let mesh = Mesh::builtin(b);
            (mesh.vertex_count(), mesh.triangle_count())
        };
        assert_eq!(counts(BuiltinMesh::FullscreenQuad), (4, 2));
        assert_eq!(counts(BuiltinMesh::Quad), (4, 2));
        assert_eq!(counts(BuiltinMesh::Cube), (24, 12));
        // Two pole rows of `segments`, `rings − 1` rows of `segments + 1`.
        assert_eq!(counts(SPHERE), (2 * 8 + 3 * 9, 2 * 8 * 3));
        assert_eq!(counts(TINY_SPHERE), (2 * 3 + 4, 2 * 3));
        assert_eq!(counts(GRID), (16, 18));
        assert_eq!(counts(BuiltinMesh::PlaneGrid { divisions: 1 }), (4, 2));
    }

    #[test]
    fn builtin_sizes_below_minimum_are_raised() {
        assert_eq!(Mesh::builtin(BuiltinMesh::UvSphere { segments: 0, rings: 0 }), Mesh::builtin(TINY_SPHERE));
        let flat = Mesh::builtin(BuiltinMesh::PlaneGrid { divisions: 0 });
        assert_eq!(flat, Mesh::builtin(BuiltinMesh::PlaneGrid { divisions: 1 }));
    }

    #[test]
    fn builtins_are_well_formed() {
        for (b, mesh) in all_builtins() {
            let what = format!("{b:?}");
            check_invariants(&mesh, &what);
            check_winding(&mesh, &what);
            check_tangent_frame(&mesh, &what);
            assert!(mesh.uvs.iter().flatten().all(|c| (0.0..=1.0).contains(c)), "{what}: uv outside 0..1");
            assert!(mesh.colors.iter().all(|&c| c == WHITE), "{what}: colors");
            assert_eq!(mesh.provided, ["position", "normal", "uv", "tangent"], "{what}");
            assert!(mesh.computed.is_empty(), "{what}");
        }
    }

    #[test]
    fn quads_cover_their_square_with_gl_uvs() {
        for (b, half) in [(BuiltinMesh::FullscreenQuad, 1.0), (BuiltinMesh::Quad, 0.5)] {
            let mesh = Mesh::builtin(b);
            assert_eq!(mesh.bounds(), ([-half, -half, 0.0], [half, half, 0.0]));
            for (p, uv) in mesh.positions.iter().zip(&mesh.uvs) {
                assert_eq!(*uv, [(p[0] / half + 1.0) / 2.0, (p[1] / half + 1.0) / 2.0], "{b:?}: v = 0 at the bottom");
            }
            assert!(mesh.normals.iter().all(|&n| n == Z));
            assert!(mesh.tangents.iter().all(|&t| t == [1.0, 0.0, 0.0, 1.0]));
        }
    }

    #[test]
    fn cube_faces_are_flat_outward_and_upright() {
        let mesh = Mesh::builtin(BuiltinMesh::Cube);
        assert_eq!(mesh.bounds(), ([-0.5; 3], [0.5; 3]));
        let bitangents = mesh.attribute("bitangent").unwrap_or_default();
        for (v, bitangent) in bitangents.iter().enumerate() {
            let (face, normal) = (v / 4, mesh.normals[v]);
            assert_eq!(normal, mesh.normals[face * 4], "flat normals on face {face}");
            assert!(close(dot(mesh.positions[v], normal), 0.5), "normal points outward on face {face}");
            let up = xyz(*bitangent);
            if normal[1] == 0.0 {
                assert!(close3(up, Y), "side face {face}: texture up is +y, got {up:?}");
            }
        }
        let distinct: std::collections::HashSet<[i32; 3]> = mesh.normals.iter().map(|n| n.map(|c| c.round() as i32)).collect();
        assert_eq!(distinct.len(), 6);
    }

    #[test]
    fn sphere_follows_its_conventions() {
        let mesh = Mesh::builtin(SPHERE);
        for (v, (&p, &n)) in mesh.positions.iter().zip(&mesh.normals).enumerate() {
            assert!(close(length(p), 1.0), "radius 1 at {v}");
            assert!(close3(p, n), "normal = position at {v}");
            let [_, y, _] = p;
            let v_coord = mesh.uvs[v][1];
            assert!(close(v_coord, (y.clamp(-1.0, 1.0).asin() / PI) + 0.5), "v follows latitude at {v}");
        }
        assert!(mesh.uvs.iter().any(|uv| uv[0] == 1.0), "seam duplicated so u reaches 1");
        let (lo, hi) = mesh.bounds();
        assert!(close3(lo, [-1.0; 3]) && close3(hi, [1.0; 3]), "{lo:?} {hi:?}");
        // u = 0.5 faces +z, with the tangent along +x there.
        let front = mesh.uvs.iter().position(|uv| uv == &[0.5, 0.5]).unwrap_or(usize::MAX);
        assert!(front < mesh.vertex_count(), "a vertex at u = 0.5, v = 0.5");
        assert!(close3(mesh.positions[front], Z));
        assert!(close3(xyz(mesh.tangents[front]), X));
        // The seam column repeats the first column's positions exactly.
        let row = 9;
        for ring in 0..3 {
            let first = 8 + ring * row;
            assert_eq!(mesh.positions[first], mesh.positions[first + 8]);
            assert_eq!((mesh.uvs[first][0], mesh.uvs[first + 8][0]), (0.0, 1.0));
        }
    }

    #[test]
    fn tiny_sphere_has_no_nan() {
        let mesh = Mesh::builtin(TINY_SPHERE);
        check_invariants(&mesh, "3×2 sphere");
        let poles = mesh.positions.iter().filter(|p| p[1].abs() == 1.0).count();
        assert_eq!(poles, 6);
    }

    #[test]
    fn grid_lies_in_xz_facing_up() {
        let mesh = Mesh::builtin(GRID);
        assert_eq!(mesh.bounds(), ([-0.5, 0.0, -0.5], [0.5, 0.0, 0.5]));
        assert!(mesh.normals.iter().all(|&n| n == Y));
        for [a, b, c] in triangles(&mesh) {
            let p = |i: usize| mesh.positions[i];
            assert!(cross(sub(p(b), p(a)), sub(p(c), p(a)))[1] > 0.0, "CCW seen from +y");
        }
        let corner = mesh.positions.iter().position(|p| p == &[-0.5, 0.0, 0.5]).unwrap_or(usize::MAX);
        assert_eq!(mesh.uvs.get(corner), Some(&[0.0, 0.0]), "uv (0, 0) at −x, +z");
    }

    #[test]
    fn mikktspace_agrees_with_analytic_tangents() {
        for b in [BuiltinMesh::Cube, BuiltinMesh::Quad, GRID] {
            let mesh = Mesh::builtin(b);
            let uvs: Vec<Option<[f32; 2]>> = mesh.uvs.iter().map(|&uv| Some(uv)).collect();
            let computed = compute_tangents(&mesh.positions, &mesh.normals, &uvs, &mesh.indices);
            for (v, (c, t)) in computed.iter().zip(&mesh.tangents).enumerate() {
                assert!(close3(xyz(*c), xyz(*t)) && c[3] == t[3], "{b:?} vertex {v}: {c:?} vs {t:?}");
            }
        }
    }

    #[test]
    fn attribute_layouts() {
        let mesh = Mesh::builtin(BuiltinMesh::Quad);
        let positions = mesh.attribute("position").unwrap_or_default();
        assert!(positions.iter().all(|p| p[3] == 1.0));
        assert!(mesh.attribute("normal").unwrap_or_default().iter().all(|n| *n == [0.0, 0.0, 1.0, 0.0]));
        assert_eq!(mesh.attribute("uv").unwrap_or_default()[2], [0.0, 1.0, 0.0, 0.0]);
        assert_eq!(mesh.attribute("color").unwrap_or_default()[0], WHITE);
        assert_eq!(mesh.attribute("bitangent").unwrap_or_default()[0], [0.0, 1.0, 0.0, 0.0]);
        assert_eq!(mesh.attribute("nonsense"), None);
        assert_eq!(mesh.attribute("Position"), None);
    }

    const QUAD_OBJ: &str = "\
# a unit quad facing +z
o quad
v -1 -1 0
v 1 -1 0
v 1 1 0
v -1 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 0 1
f 1/1/1 2/2/1 3/3/1 4/4/1
";

    #[test]
    fn obj_quad_with_uvs_and_normals() {
        let mesh = obj(QUAD_OBJ);
        check_invariants(&mesh, "quad");
        check_winding(&mesh, "quad");
        check_tangent_frame(&mesh, "quad");
        assert_eq!((mesh.vertex_count(), mesh.triangle_count()), (4, 2));
        assert_eq!(mesh.provided, ["position", "normal", "uv"]);
        assert_eq!(mesh.computed, ["tangent"]);
        assert_eq!(mesh.uvs, [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], "OBJ v = 0 is the bottom, as in GL");
        assert!(mesh.tangents.iter().all(|t| close3(xyz(*t), X) && t[3] == 1.0), "{:?}", mesh.tangents);
        assert!(mesh.colors.iter().all(|&c| c == WHITE));
        assert_eq!(mesh.bounds(), ([-1.0, -1.0, 0.0], [1.0, 1.0, 0.0]));
    }

    #[test]
    fn obj_bitangent_sign_follows_mirrored_uvs() {
        let mirrored = QUAD_OBJ.replace("vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1", "vt 1 0\nvt 0 0\nvt 0 1\nvt 1 1");
        let mesh = obj(&mirrored);
        check_invariants(&mesh, "mirrored quad");
        check_tangent_frame(&mesh, "mirrored quad");
        assert!(mesh.tangents.iter().all(|t| close3(xyz(*t), [-1.0, 0.0, 0.0]) && t[3] == -1.0));
        let bitangents = mesh.attribute("bitangent").unwrap_or_default();
        assert!(bitangents.iter().all(|b| close3(xyz(*b), Y) && b[3] == 0.0), "{bitangents:?}");
    }

    #[test]
    fn obj_triangle_without_normals_gets_computed_ones() {
        let mesh = obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        check_invariants(&mesh, "triangle");
        check_winding(&mesh, "triangle");
        assert_eq!(mesh.normals, [Z; 3]);
        assert_eq!(mesh.provided, ["position"]);
        assert_eq!(mesh.computed, ["normal", "tangent"]);
        assert_eq!(mesh.uvs, [[0.0; 2]; 3], "missing uvs are zero");
    }

    #[test]
    fn obj_computed_normals_are_smooth_and_area_weighted() {
        // A roof: a big slope facing +x+y and a small one facing −x+y, sharing the ridge, with a uv
        // seam on the ridge (different vt) that must not split the normal.
        let text = "v 0 1 0\nv 0 1 1\nv 2 -1 0\nv 2 -1 1\nv -1 0 0\nv -1 0 1\nvt 0 0\nvt 1 1\n\
                    f 1/1 2/1 4/1 3/1\nf 1/2 5/2 6/2 2/2\n";
        let mesh = obj(text);
        check_invariants(&mesh, "roof");
        check_winding(&mesh, "roof");
        let ridge: Vec<[f32; 3]> = (0..mesh.vertex_count()).filter(|&v| mesh.positions[v][1] == 1.0).map(|v| mesh.normals[v]).collect();
        assert_eq!(ridge.len(), 4, "the seam duplicates the ridge vertices");
        assert!(ridge.iter().all(|n| close3(*n, ridge[0])), "{ridge:?}");
        assert!(ridge[0][0] > 0.0 && ridge[0][1] > 0.0, "the bigger face weighs more: {:?}", ridge[0]);
    }

    #[test]
    fn obj_without_uvs_gets_fallback_tangents() {
        let mesh = obj("v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\n");
        check_invariants(&mesh, "no uvs");
        assert_eq!(mesh.provided, ["position", "normal"]);
    }

    #[test]
    fn obj_degenerate_triangles_do_not_make_nan() {
        let cases = [
            "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\n",
            "v 0 0 0\nv 0 0 0\nv 0 0 0\nvt 0 0\nf 1/1 2/1 3/1\n",
            "v 1 0 0\nv 1 0 0\nv 1 1 0\nvn 0 0 0\nvt 0.5 0.5\nf 1/1/1 2/1/1 3/1/1\n",
            "v 0 0 0\nv 1e-30 0 0\nv 0 1e-30 0\nf 1 2 3\n",
            "v 0 0 0\nv 3e38 0 0\nv 0 3e38 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 1 0 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1/1 2/2/1 3/3/1\n",
        ];
        for text in cases {
            check_invariants(&obj(text), text);
        }
    }

    #[test]
    fn obj_vertex_colors() {
        let mesh = obj("v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 0.5\nf 1 2 3\n");
        assert_eq!(mesh.colors, [[1.0, 0.0, 0.0, 1.0], [0.0, 1.0, 0.0, 1.0], [0.0, 0.0, 0.5, 1.0]]);
        assert!(mesh.provided.contains(&"color"));
        let partial = obj_error("v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        assert!(partial.contains("only 1 of the 3 `v` lines"), "{partial}");
    }

    #[test]
    fn obj_models_merge_into_one_mesh() {
        let text = "o a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\no b\nv 0 0 5\nv 1 0 5\nv 0 1 5\nvn 0 0 1\n\
                    f 4//1 5//1 6//1\ng c\nf -3 -2 -1\n";
        let mesh = obj(text);
        check_invariants(&mesh, "merged");
        check_winding(&mesh, "merged");
        assert_eq!(mesh.triangle_count(), 3);
        assert_eq!(mesh.indices[3..6].iter().map(|&i| mesh.positions[i as usize][2]).sum::<f32>(), 15.0);
        assert_eq!(mesh.computed, ["normal", "tangent"], "one object had no normals");
        assert_eq!(mesh.bounds(), ([0.0; 3], [1.0, 1.0, 5.0]));
    }

    #[test]
    fn obj_polygons_are_triangulated_and_polylines_ignored() {
        let mesh = obj("v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\nf 1 2 3 4 5\nl 1 2 3\nl 4 5\nf 1 2\n");
        assert_eq!(mesh.triangle_count(), 3);
        check_winding(&mesh, "pentagon");
    }

    #[test]
    fn obj_errors_name_the_problem() {
        let cases = [
            ("", "no triangles in the OBJ text: it has no `f` lines"),
            ("v 0 0 0\nv 1 0 0\nv 0 1 0\n", "no triangles in the OBJ text: it has no `f` lines"),
            ("v 0 0 0\nv 1 0 0\nf 1 2\nf 1\n", "its faces are all points or lines"),
            ("Lorem ipsum dolor sit amet\n\0\u{1}\u{7f}☃\n", "no triangles"),
            ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "line 4 of the OBJ text: a face refers to position 4, but there are only 3"),
            ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "uses index 0"),
            ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 -2 -1\n", "refers to position -4, but only 3 come before it"),
            ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/-3 2/-3 3/-3\n", "texture coordinate -3"),
            ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//-2 2//1 3//1\n", "normal -2"),
            ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//9223372036854775807 2//1 3//1\n", "normal 9223372036854775807"),
            ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf a b c\n", "line 4 of the OBJ text: cannot read the face corner `a`"),
            ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1/1 2 3\n", "cannot read the face corner `1/1/1/1`"),
            ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf //1 2 3\n", "has no position index"),
            ("v 0 0 zero\n", "line 1 of the OBJ text: cannot read the position in `v 0 0 zero`"),
            ("vt 0\n", "cannot read the texture coordinate in `vt 0`"),
            ("v 0 0 0 1 0 x\n", "cannot read the vertex color"),
            ("v NaN 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "has a position that is not a finite number: `NaN 0 0`"),
            ("v 1e39 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "position that is not a finite number: `inf 0 0`"),
            ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn inf 0 1\nf 1//1 2//1 3//1\n", "normal that is not a finite"),
            ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt nan 0\nf 1/1 2/1 3/1\n", "texture coordinate that is not a finite"),
            ("v 0 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "line 1 of the OBJ text: `v 0 0 0 0` has w = 0"),
            ("v 0 0 0 one\n", "cannot read the w in `v 0 0 0 one`"),
            ("v 0 0 0 1 1\n", "`v 0 0 0 1 1` should be x y z, optionally followed by w or by an r g b color"),
            ("v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl\nf 1 2 3\n", "line 4 of the OBJ text: `usemtl` needs a material name"),
        ];
        for (text, expected) in cases {
            let error = obj_error(text);
            assert!(error.contains(expected), "for {text:?}:\n  got      {error}\n  expected {expected}");
        }
    }

    #[test]
    fn load_obj_reads_files_and_names_them() {
        let dir = std::env::temp_dir().join(format!("effectc-mesh-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("create a temporary directory");
        let good = dir.join("quad.obj");
        let empty = dir.join("teapot.obj");
        std::fs::write(&good, QUAD_OBJ).expect("write quad.obj");
        std::fs::write(&empty, "# nothing here\n").expect("write teapot.obj");
        let loaded = Mesh::load_obj(&good);
        let no_triangles = Mesh::load_obj(&empty);
        let missing = Mesh::load_obj(&dir.join("missing.obj"));
        std::fs::remove_dir_all(&dir).expect("remove the temporary directory");

        assert_eq!(loaded, Ok(obj(QUAD_OBJ)));
        let expected = format!("no triangles in `{}`: it has no `f` lines", empty.display());
        assert_eq!(no_triangles, Err(expected));
        let missing = missing.err().unwrap_or_default();
        assert!(missing.starts_with("cannot read `") && missing.contains("missing.obj`: "), "{missing}");
    }

    #[test]
    fn load_obj_accepts_latin1_comments() {
        let mut bytes = b"# caf\xe9\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n".to_vec();
        bytes.extend(b"# end\r\n");
        let path = std::env::temp_dir().join(format!("effectc-mesh-latin1-{}.obj", std::process::id()));
        std::fs::write(&path, &bytes).expect("write the Latin-1 file");
        let loaded = Mesh::load_obj(&path);
        std::fs::remove_file(&path).expect("remove the Latin-1 file");
        assert_eq!(loaded.map(|m| m.triangle_count()), Ok(1));
    }

    /// Random OBJ lines with awkward numbers and indices: never a panic, and whatever is accepted is
    /// well formed.
    #[test]
    fn obj_fuzz_never_panics() {
        const NUMBERS: [&str; 12] = ["0", "1", "-1", "0.5", "2", "1e38", "-1e-39", "3e-45", "0", "1", "0.25", "-2"];
        const CORNERS: [&str; 14] = ["1", "2", "3", "3", "-1", "-2", "1/1", "2/2/1", "3//1", "-1/-1/-1", "1/2", "2/1/2", "2", "1"];
        let mut state: u64 = 0x9e37_79b9_7f4a_7c15;
        let mut next = |n: usize| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % n as u64) as usize
        };
        let mut accepted = 0;
        for _ in 0..3000 {
            let mut text = String::new();
            let colored = next(4) == 0;
            for _ in 0..3 + next(3) {
                let mut line = String::from("v");
                for _ in 0..if colored { 6 } else { 3 } {
                    line = line + " " + NUMBERS[next(NUMBERS.len())];
                }
                if next(50) == 0 {
                    line += " x";
                }
                text = text + &line + "\n";
            }
            if next(3) > 0 {
                text.push_str("vt 0.5 0.5\nvt 1 0\nvn 0 0 1\nvn 0 1 0\n");
            }
            for _ in 0..next(10) {
                let (head, words, count) = match next(8) {
                    0..=3 => ("f", &CORNERS[..], 2 + next(4)),
                    4 => ("vt", &NUMBERS[..], 2 + next(2)),
                    5 => ("vn", &NUMBERS[..], 3),
                    6 => ("v", &NUMBERS[..], if colored { 6 } else { 3 + next(2) }),
                    _ => (["l", "o", "g", "#", "usemtl", "s"][next(6)], &CORNERS[..], next(3)),
                };
                text.push_str(head);
                for _ in 0..count {
                    text.push(' ');
                    text.push_str(words[next(words.len())]);
                }
                text.push('\n');
            }
            if let Ok(mesh) = Mesh::from_obj_text(&text) {
                accepted += 1;
                check_invariants(&mesh, &text);
            }
        }
        assert!(accepted > 500, "only {accepted} of the fuzz inputs were valid");
    }
}
