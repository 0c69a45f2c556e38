//! Degenerate variants of a mesh, drawn by `effectc stress` to find shaders that break on
//! the geometry real assets bring: normals of zero length, and triangles of zero area.
//!
//! - [`Degenerate::ZeroNormals`]: every normal is (0, 0, 0), so bitangents are zero too
//!   (tangents keep their direction). A shader's `normalize(normal)` divides by zero.
//! - [`Degenerate::ZeroAreaTriangles`]: the vertices are unshared and every second triangle
//!   is collapsed onto a line (its third vertex moved to the midpoint of the first two: the
//!   edges stay non-zero, the area and `cross(b - a, c - a)` are zero). Its vertices carry
//!   what an exporter or a face-normal computation gives such a triangle: a zero normal
//!   and a zero tangent. These triangles cover no pixel, so what they break shows in the
//!   vertex stage only (what `stress` instruments there); the other half draws as usual.

use crate::assets::mesh::Mesh;
use crate::manifest::MeshAttribute;

/// A stress variant of the mesh.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Degenerate {
    ZeroNormals,
    ZeroAreaTriangles,
}

impl Degenerate {
    pub const ALL: [Degenerate; 2] = [Degenerate::ZeroNormals, Degenerate::ZeroAreaTriangles];

    /// The stress case's name.
    pub fn name(self) -> &'static str {
        match self {
            Degenerate::ZeroNormals => "zero normals",
            Degenerate::ZeroAreaTriangles => "zero-area tris",
        }
    }

    /// Whether the variant changes what a shader reading `attributes` sees.
    pub fn affects(self, attributes: &[MeshAttribute]) -> bool {
        match self {
            Degenerate::ZeroNormals => attributes.iter().any(|a| matches!(a, MeshAttribute::Normal | MeshAttribute::Bitangent)),
            Degenerate::ZeroAreaTriangles => attributes.contains(&MeshAttribute::Position),
        }
    }

    /// The variant of `mesh`, and a sentence saying what changed.
    pub fn apply(self, mesh: &Mesh) -> (Mesh, String) {
        match self {
            Degenerate::ZeroNormals => {
                let mut m = mesh.clone();
                m.normals.iter_mut().for_each(|n| *n = [0.0; 3]);
                let what = format!("all {} normals zero", m.normals.len());
                (m, what)
            }
            Degenerate::ZeroAreaTriangles => {
                let m = collapse_every_second_triangle(mesh);
                let what = format!("{} of {} triangles collapsed to zero area", mesh.triangle_count() / 2, mesh.triangle_count());
                (m, what)
            }
        }
    }
}

/// Unshares the vertices (each triangle gets its own three) and collapses the odd
/// triangles: third vertex at the midpoint of the first two, zero normals and tangents.
fn collapse_every_second_triangle(mesh: &Mesh) -> Mesh {
    let mut out = Mesh { indices: Vec::with_capacity(mesh.indices.len()), ..mesh.clone() };
    out.positions.clear();
    out.normals.clear();
    out.uvs.clear();
    out.tangents.clear();
    out.colors.clear();
    for (t, tri) in mesh.indices.chunks_exact(3).enumerate() {
        let collapse = t % 2 == 1;
        let [a, b] = [tri[0] as usize, tri[1] as usize];
        for (corner, &i) in tri.iter().enumerate() {
            let i = i as usize;
            let position = if collapse && corner == 2 {
                std::array::from_fn(|k| 0.5 * (mesh.positions[a][k] + mesh.positions[b][k]))
            } else {
                mesh.positions[i]
            };
            out.indices.push(out.positions.len() as u32);
            out.positions.push(position);
            out.normals.push(if collapse { [0.0; 3] } else { mesh.normals[i] });
            out.tangents.push(if collapse { [0.0, 0.0, 0.0, mesh.tangents[i][3]] } else { mesh.tangents[i] });
            out.uvs.push(mesh.uvs[i]);
            out.colors.push(mesh.colors[i]);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::manifest::BuiltinMesh;

    fn cross(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
        [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    }

    #[test]
    fn zero_normals_zero_every_normal_and_nothing_else() {
        let cube = Mesh::builtin(BuiltinMesh::Cube);
        let (m, what) = Degenerate::ZeroNormals.apply(&cube);
        assert!(m.normals.iter().all(|n| *n == [0.0; 3]));
        assert_eq!((&m.positions, &m.indices, &m.uvs), (&cube.positions, &cube.indices, &cube.uvs));
        assert_eq!(what, "all 24 normals zero");
        assert!(m.attribute(MeshAttribute::Bitangent).iter().all(|b| b[..3] == [0.0; 3]));
    }

    #[test]
    fn every_second_triangle_has_zero_area_and_non_zero_edges() {
        let cube = Mesh::builtin(BuiltinMesh::Cube);
        let (m, what) = Degenerate::ZeroAreaTriangles.apply(&cube);
        assert_eq!(what, "6 of 12 triangles collapsed to zero area");
        assert_eq!(m.vertex_count(), 36);
        assert_eq!(m.triangle_count(), 12);
        for (t, tri) in m.indices.chunks_exact(3).enumerate() {
            let p = |k: usize| m.positions[tri[k] as usize];
            let sub = |x: [f32; 3], y: [f32; 3]| [x[0] - y[0], x[1] - y[1], x[2] - y[2]];
            let (e1, e2) = (sub(p(1), p(0)), sub(p(2), p(0)));
            let area2: f32 = cross(e1, e2).iter().map(|c| c * c).sum();
            let edge: f32 = e2.iter().map(|c| c * c).sum();
            if t % 2 == 1 {
                assert_eq!(area2, 0.0, "triangle {t}");
                assert!(edge > 0.0, "the collapsed triangle keeps non-zero edges");
                assert!(tri.iter().all(|&i| m.normals[i as usize] == [0.0; 3]));
            } else {
                assert!(area2 > 0.0, "triangle {t} is untouched");
                assert!(tri.iter().all(|&i| m.normals[i as usize] != [0.0; 3]));
            }
        }
    }

    #[test]
    fn a_variant_matters_only_to_shaders_reading_what_it_changes() {
        assert!(Degenerate::ZeroNormals.affects(&[MeshAttribute::Position, MeshAttribute::Normal]));
        assert!(!Degenerate::ZeroNormals.affects(&[MeshAttribute::Position, MeshAttribute::Uv]));
        assert!(Degenerate::ZeroAreaTriangles.affects(&[MeshAttribute::Position]));
        assert!(!Degenerate::ZeroAreaTriangles.affects(&[]));
    }
}
