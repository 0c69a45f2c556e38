//! CPU-side mesh data: the builtin meshes and Wavefront OBJ files, as flat vertex arrays.
//!
//! Conventions (OpenGL): right-handed, y up; indices are a triangle list with counter-clockwise front
//! faces; uv (0, 0) is the bottom-left of the texture image; normals are unit length; tangents are unit,
//! orthogonal to the normal, with w = ±1 so that bitangent = cross(normal, tangent.xyz) · w (MikkTSpace);
//! colors are linear RGBA, white when the source has none.
//!
//! - `builtin`: the builtin meshes, whose normals, uvs and tangents are exact (so they count as provided).
//! - `obj`: OBJ files, checked line by line, read with `tobj` and merged into one mesh.
//! - `tangents`: normals and tangents an OBJ file lacks (smooth normals, MikkTSpace tangents).

mod builtin;
mod obj;
mod tangents;
#[cfg(test)]
mod tests;

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
    /// Attributes that came from the source rather than defaults/computation.
    pub provided: Vec<MeshAttribute>,
    /// Attributes effectc computed (the normal of an OBJ without normals, the tangent).
    pub computed: Vec<MeshAttribute>,
}

pub use crate::manifest::MeshAttribute;

/// The color of vertices whose source gives none.
const WHITE: [f32; 4] = [1.0; 4];

impl Mesh {
    /// A builtin mesh. Sphere and grid sizes below the manifest's minimums (3 segments, 2 rings,
    /// 1 division) are raised to them.
    pub fn builtin(b: BuiltinMesh) -> Mesh {
        builtin::mesh(b)
    }

    /// Reads a Wavefront OBJ file; the error message is meant for the user.
    pub fn load_obj(path: &Path) -> Result<Mesh, String> {
        obj::load(path)
    }

    /// Like [`Mesh::load_obj`], from OBJ text in memory.
    pub fn from_obj_text(text: &str) -> Result<Mesh, String> {
        obj::parse(text, "the OBJ text")
    }

    /// Attribute data as 4 components per vertex: position w = 1; normal/uv/tangent padded
    /// with 0 (tangent keeps its w sign); color as is; bitangent = cross(normal, tangent.xyz) * tangent.w.
    pub fn attribute(&self, attribute: MeshAttribute) -> Vec<[f32; 4]> {
        match attribute {
            MeshAttribute::Position => self.positions.iter().map(|&[x, y, z]| [x, y, z, 1.0]).collect(),
            MeshAttribute::Normal => self.normals.iter().map(|&[x, y, z]| [x, y, z, 0.0]).collect(),
            MeshAttribute::Uv => self.uvs.iter().map(|&[u, v]| [u, v, 0.0, 0.0]).collect(),
            MeshAttribute::Tangent => self.tangents.clone(),
            MeshAttribute::Bitangent => self.normals.iter().zip(&self.tangents).map(|(&n, &t)| tangents::bitangent(n, t)).collect(),
            MeshAttribute::Color => self.colors.clone(),
        }
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
