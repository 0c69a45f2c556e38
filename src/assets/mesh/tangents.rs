//! Normals and tangents a mesh file does not give. Missing normals are smooth (area-weighted, shared by
//! every vertex at the same position); tangents come from MikkTSpace (`bevy_mikktspace`), and where it
//! has no answer (no uvs, degenerate triangles) the tangent is some unit vector orthogonal to the normal.
//!
//! Vector arithmetic is `glam::Vec3` (plain `f32` operations, no SIMD), so results do not depend on
//! the target's vector units.

use std::collections::HashMap;

use glam::Vec3;

/// The file's normals where it has usable ones, else smooth normals, else +y.
pub(super) fn resolve_normals(positions: &[[f32; 3]], normals: &[Option<[f32; 3]>], indices: &[u32]) -> Vec<[f32; 3]> {
    let smooth = if normals.iter().any(Option::is_none) { smooth_normals(positions, indices) } else { Vec::new() };
    let from_smooth = |i: usize| smooth.get(i).copied().flatten();
    normals.iter().enumerate().map(|(i, n)| n.or_else(|| from_smooth(i)).unwrap_or(Vec3::Y.to_array())).collect()
}

/// Area-weighted vertex normals, summed over every vertex at the same position so that uv seams
/// stay smooth. `None` where the adjacent triangles have no area.
fn smooth_normals(positions: &[[f32; 3]], indices: &[u32]) -> Vec<Option<[f32; 3]>> {
    // `+ 0.0` turns −0.0 into 0.0, so both land on one key.
    let key = |p: [f32; 3]| p.map(|c| (c + 0.0).to_bits());
    let mut sums: HashMap<[u32; 3], Vec3> = HashMap::new();
    for triangle in indices.chunks_exact(3) {
        let [a, b, c] = [triangle[0], triangle[1], triangle[2]].map(|i| positions[i as usize]);
        let [pa, pb, pc] = [a, b, c].map(Vec3::from);
        // Twice the triangle's area, along its normal.
        let weighted = (pb - pa).cross(pc - pa);
        for corner in [a, b, c] {
            let sum = sums.entry(key(corner)).or_insert(Vec3::ZERO);
            *sum += weighted;
        }
    }
    positions.iter().map(|&p| sums.get(&key(p)).and_then(|&sum| normalize(sum)).map(<[f32; 3]>::from)).collect()
}

/// MikkTSpace tangents where there are uvs, made exactly orthonormal; any orthogonal unit vector
/// where MikkTSpace has none.
pub(super) fn compute_tangents(positions: &[[f32; 3]], normals: &[[f32; 3]], uvs: &[Option<[f32; 2]>], indices: &[u32]) -> Vec<[f32; 4]> {
    let mut found = vec![None; positions.len()];
    if uvs.iter().any(Option::is_some) {
        let uvs: Vec<[f32; 2]> = uvs.iter().map(|uv| uv.unwrap_or_default()).collect();
        let mut geometry = MikkGeometry { positions, normals, uvs: &uvs, indices, tangents: found };
        // It cannot fail today (the error type has no values); vertices it leaves out fall back below.
        let _ = bevy_mikktspace::generate_tangents(&mut geometry);
        found = geometry.tangents;
    }
    normals.iter().zip(found).map(|(&n, t)| orthonormal_tangent(Vec3::from(n), t)).collect()
}

/// `tangent` made unit and orthogonal to `normal`, or any such vector if it cannot be.
fn orthonormal_tangent(normal: Vec3, tangent: Option<[f32; 4]>) -> [f32; 4] {
    let fixed = tangent.and_then(|t| {
        let unit = normalize(Vec3::new(t[0], t[1], t[2]).reject_from_normalized(normal))?;
        Some([unit.x, unit.y, unit.z, if t[3] < 0.0 { -1.0 } else { 1.0 }])
    });
    fixed.unwrap_or_else(|| any_tangent(normal))
}

/// A unit vector orthogonal to `normal`: +x (or +z when the normal is close to ±x) projected onto
/// the plane of the normal.
fn any_tangent(normal: Vec3) -> [f32; 4] {
    let axis = if normal.x.abs() < 0.9 { Vec3::X } else { Vec3::Z };
    let unit = normalize(axis.reject_from_normalized(normal)).unwrap_or(axis);
    [unit.x, unit.y, unit.z, 1.0]
}

/// cross(normal, tangent.xyz) · tangent.w, padded with w = 0.
pub(super) fn bitangent(normal: [f32; 3], tangent: [f32; 4]) -> [f32; 4] {
    let b = Vec3::from(normal).cross(Vec3::new(tangent[0], tangent[1], tangent[2])) * tangent[3];
    [b.x, b.y, b.z, 0.0]
}

/// `v` at unit length, or `None` if it is zero or not finite. Scaling by the largest component
/// first keeps tiny and huge vectors from underflowing or overflowing.
pub(super) fn normalize(v: Vec3) -> Option<Vec3> {
    if !v.is_finite() {
        return None;
    }
    let largest = v.abs().max_element();
    if largest <= 0.0 {
        return None;
    }
    let v = v / largest;
    let length = v.dot(v).sqrt();
    Some(v / length)
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
