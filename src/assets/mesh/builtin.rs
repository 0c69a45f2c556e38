//! The builtin meshes: `FullscreenQuad` (clip space, −1..1), `FullscreenTriangle` (covering clip
//! space), `Quad` (xy, −0.5..0.5), `Cube` (24 vertices, flat normals), `UvSphere` (radius 1, seam
//! duplicated) and `PlaneGrid` (xz, −0.5..0.5). Their normals, uvs and tangents are exact.

use std::f32::consts::PI;

use glam::Vec3;

use super::tangents::normalize;
use super::{Mesh, MeshAttribute, WHITE};
use crate::manifest::BuiltinMesh;

/// A builtin mesh, with sphere and grid sizes raised to the manifest's minimums.
pub(super) fn mesh(b: BuiltinMesh) -> Mesh {
    match b {
        BuiltinMesh::FullscreenQuad => flat_quad(1.0),
        BuiltinMesh::FullscreenTriangle => fullscreen_triangle(),
        BuiltinMesh::Quad => flat_quad(0.5),
        BuiltinMesh::Cube => cube(),
        BuiltinMesh::UvSphere { segments, rings } => uv_sphere(segments.max(3), rings.max(2)),
        BuiltinMesh::PlaneGrid { divisions } => plane_grid(divisions.max(1)),
    }
}

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

    fn vertex(&mut self, position: Vec3, normal: Vec3, uv: [f32; 2], tangent: [f32; 4]) {
        self.positions.push(position.to_array());
        self.normals.push(normal.to_array());
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
    fn patch(&mut self, center: Vec3, u_axis: Vec3, v_axis: Vec3, half: f32, divisions: u32) {
        let normal = u_axis.cross(v_axis);
        let tangent = [u_axis.x, u_axis.y, u_axis.z, 1.0];
        let first = self.next_index();
        let row = divisions + 1;
        for j in 0..row {
            let v = j as f32 / divisions as f32;
            for i in 0..row {
                let u = i as f32 / divisions as f32;
                let offset = u_axis * (half * (2.0 * u - 1.0)) + v_axis * (half * (2.0 * v - 1.0));
                self.vertex(center + offset, normal, [u, v], tangent);
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
            provided: vec![MeshAttribute::Position, MeshAttribute::Normal, MeshAttribute::Uv, MeshAttribute::Tangent],
            computed: Vec::new(),
        }
    }
}

/// A square in the xy plane facing +z, `half` either side of the origin: the corners in
/// the order GL programs draw a rectangle in (lower left, lower right, upper left, upper
/// right, as `piglit_draw_rect`'s triangle strip), as the strip's two triangles. So
/// `gl_VertexID` and a `flat` varying's provoking vertex (the last) are GL's: the lower
/// left triangle takes the upper left corner's, the other the upper right's.
fn flat_quad(half: f32) -> Mesh {
    let mut b = Builder::default();
    b.patch(Vec3::ZERO, Vec3::X, Vec3::Y, half, 1);
    b.indices = vec![0, 1, 2, 2, 1, 3];
    b.finish()
}

/// One triangle whose inside covers clip space −1..1: corners (−1, −1), (3, −1), (−1, 3),
/// uv 0..2 so that uv runs 0..1 across the visible part.
fn fullscreen_triangle() -> Mesh {
    Mesh {
        positions: vec![[-1.0, -1.0, 0.0], [3.0, -1.0, 0.0], [-1.0, 3.0, 0.0]],
        normals: vec![Vec3::Z.to_array(); 3],
        uvs: vec![[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]],
        tangents: vec![[1.0, 0.0, 0.0, 1.0]; 3],
        colors: vec![WHITE; 3],
        indices: vec![0, 1, 2],
        provided: vec![MeshAttribute::Position, MeshAttribute::Normal, MeshAttribute::Uv],
        computed: vec![MeshAttribute::Tangent],
    }
}

/// Faces as (u axis, v axis), chosen so every face reads upright from outside; the side faces have
/// v = +y, the top has v towards −z and the bottom v towards +z (as seen with +z facing the viewer).
const CUBE_FACES: [(Vec3, Vec3); 6] = [
    (Vec3::NEG_Z, Vec3::Y), // +x
    (Vec3::Z, Vec3::Y),     // −x
    (Vec3::X, Vec3::NEG_Z), // +y
    (Vec3::X, Vec3::Z),     // −y
    (Vec3::X, Vec3::Y),     // +z
    (Vec3::NEG_X, Vec3::Y), // −z
];

fn cube() -> Mesh {
    let mut b = Builder::default();
    for (u_axis, v_axis) in CUBE_FACES {
        b.patch(u_axis.cross(v_axis) * 0.5, u_axis, v_axis, 0.5, 1);
    }
    b.finish()
}

/// The plane y = 0 facing +y, u along +x and v along −z.
fn plane_grid(divisions: u32) -> Mesh {
    let mut b = Builder::default();
    b.patch(Vec3::ZERO, Vec3::X, Vec3::NEG_Z, 0.5, divisions);
    b.finish()
}

/// A point of the unit sphere at column `segment` (u = segment / segments) and v: u = 0 (and 1) at −z,
/// u = 0.5 facing +z; v = 0 at y = −1.
fn sphere_position(segment: u32, segments: u32, v: f32) -> Vec3 {
    // `segment % segments` puts the seam column exactly on the first one.
    let (sin, cos) = (2.0 * PI * (segment % segments) as f32 / segments as f32).sin_cos();
    let (radius, y) = (PI * v).sin_cos();
    Vec3::new(-sin * radius, -y, -cos * radius)
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
        b.vertex(Vec3::NEG_Y, Vec3::NEG_Y, [pole_u(i), 0.0], sphere_tangent(pole_u(i)));
    }
    let first_ring = b.next_index();
    let row = segments + 1;
    for j in 1..rings {
        let v = j as f32 / rings as f32;
        for i in 0..row {
            let u = i as f32 / segments as f32;
            let position = sphere_position(i, segments, v);
            b.vertex(position, normalize(position).unwrap_or(Vec3::Y), [u, v], sphere_tangent(u));
        }
    }
    let north = b.next_index();
    for i in 0..segments {
        b.vertex(Vec3::Y, Vec3::Y, [pole_u(i), 1.0], sphere_tangent(pole_u(i)));
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
