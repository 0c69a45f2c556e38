//! Wavefront OBJ files: a first pass over the text reports bad lines by number and catches what
//! `tobj` would misread, then `tobj` reads it (triangulated, one index per vertex) and every model is
//! merged into one mesh. Missing normals are computed (smooth) and tangents always are.

use std::borrow::Cow;
use std::path::Path;

use glam::Vec3;

use super::tangents::{compute_tangents, normalize, resolve_normals};
use super::{Mesh, MeshAttribute, WHITE};

/// Reads an OBJ file; errors name it.
pub(super) fn load(path: &Path) -> Result<Mesh, String> {
    let name = file_label(path);
    let bytes = std::fs::read(path).map_err(|e| format!("cannot read {name}: {e}"))?;
    parse(&String::from_utf8_lossy(&bytes), &name)
}

fn file_label(path: &Path) -> String {
    format!("`{}`", path.display())
}

/// Reads OBJ `text`; `name` says where it came from in messages (“`teapot.obj`”).
pub(super) fn parse(text: &str, name: &str) -> Result<Mesh, String> {
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
            self.normals.extend(mesh.normals.chunks_exact(3).map(|n| normalize(Vec3::new(n[0], n[1], n[2])).map(<[f32; 3]>::from)));
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
        let mut provided = vec![MeshAttribute::Position];
        let mut computed = Vec::new();
        if self.normals.iter().all(Option::is_some) {
            provided.push(MeshAttribute::Normal);
        } else {
            computed.push(MeshAttribute::Normal);
        }
        if self.uvs.iter().all(Option::is_some) {
            provided.push(MeshAttribute::Uv);
        }
        computed.push(MeshAttribute::Tangent);
        if self.colors.iter().all(Option::is_some) {
            provided.push(MeshAttribute::Color);
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
