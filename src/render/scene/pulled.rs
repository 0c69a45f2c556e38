//! The data a folded geometry program pulls instead of vertex buffers: the vertex indices
//! of every input primitive and one `vec4` per vertex input per vertex (the reflection's
//! [`GeometryDraw`] says where they are bound and how many vertices to draw).
//!
//! A triangle mesh feeds the geometry stage's input primitive as GL would with the matching
//! draw mode: `triangles` its triangles, `lines` each triangle's three edges (as a wireframe
//! drawn with `GL_LINES`), `points` each vertex once; `triangles_adjacency` each triangle
//! with the far corner of the triangle across each edge (matched by position, so seams of
//! split vertices count as shared; across a border edge, the triangle's own third corner);
//! `lines_adjacency` each triangle edge with the triangle's third corner before and after.

use std::collections::HashMap;

use crate::assets::mesh::Mesh;
use crate::back::reflect::{GeometryDraw, Reflection};
use crate::diag::{Code, Diagnostic};
use crate::front::tessellation_fold::{LEVEL_CAP_WORD, SLOTS_WORD};
use crate::render::attributes::Choice;

/// Bytes of the two storage buffers and the draw's vertex count.
pub(super) struct Pulled {
    pub indices: Vec<u8>,
    pub vertices: Vec<u8>,
    /// Vertices to draw: input primitives × vertices per primitive.
    pub count: u32,
    /// Bindings (group 0) of the index and the vertex buffer.
    bindings: [u32; 2],
}

impl Pulled {
    /// (binding in group 0, contents) of the two storage buffers.
    pub fn buffers(&self) -> Vec<(u32, &[u8])> {
        vec![(self.bindings[0], &self.indices[..]), (self.bindings[1], &self.vertices[..])]
    }
}

/// The pulled data when the program is a folded geometry program (None otherwise).
pub(super) fn for_geometry(
    r: &Reflection,
    choices: &[Choice],
    mesh: &Mesh,
    own_vertices: bool,
    instance_attributes: bool,
) -> Result<Option<Pulled>, Diagnostic> {
    let Some(g) = &r.geometry else { return Ok(None) };
    if instance_attributes {
        return Err(Diagnostic::new(
            Code::Unrenderable,
            "per-instance attributes ([instances] attributes) cannot feed a geometry stage yet",
        )
        .with_help("read `gl_InstanceID` in the vertex stage and index a uniform array instead"));
    }
    Ok(Some(pulled(g, choices, mesh, own_vertices)))
}

/// The pulled data of `mesh` (`own_vertices`: the program draws three vertices of its own).
pub(super) fn pulled(draw: &GeometryDraw, choices: &[Choice], mesh: &Mesh, own_vertices: bool) -> Pulled {
    use wgpu::VertexFormat as F;
    let vertex_count = if own_vertices { 3 } else { mesh.vertex_count() };
    let indices = match draw.tessellation {
        Some(_) => patches(draw.index_buffer.stride, mesh, own_vertices),
        None => primitive_indices(draw.input_primitive, mesh, own_vertices),
    };
    let columns: Vec<Option<Vec<[f32; 4]>>> = choices.iter().map(|c| c.attribute.map(|a| mesh.attribute(a))).collect();
    let mut vertices = Vec::with_capacity(vertex_count * choices.len() * 16);
    for v in 0..vertex_count {
        for (column, choice) in columns.iter().zip(choices) {
            let value = crate::render::attributes::vertex_value(choice, column.as_deref(), v, [0.0; 4]);
            // Integer inputs travel as their bit patterns (the stage reads floatBitsTo*Int).
            let bits = |x: f32| match choice.format {
                F::Uint32 | F::Uint32x2 | F::Uint32x3 | F::Uint32x4 => (x.max(0.0) as u32).to_le_bytes(),
                F::Sint32 | F::Sint32x2 | F::Sint32x3 | F::Sint32x4 => (x as i32).to_le_bytes(),
                _ => x.to_le_bytes(),
            };
            vertices.extend(value.iter().flat_map(|x| bits(*x)));
        }
    }
    let primitives = indices.len() as u32 / draw.index_buffer.stride.max(1);
    // The header: layer 0 and viewport 0 are drawn (the frame is one 2D target); for
    // tessellation the level cap and the slots per patch.
    let mut header = [0u32; 4];
    let mut per_primitive = draw.vertices_per_primitive;
    if let Some(t) = &draw.tessellation {
        let cap = t.level_cap(primitives, TESSELLATED_VERTICES);
        per_primitive = t.vertices_per_patch(cap);
        header[LEVEL_CAP_WORD as usize] = cap;
        header[SLOTS_WORD as usize] = t.layout.slots_per_patch(cap);
    }
    Pulled {
        indices: header.iter().chain(&indices).flat_map(|i| i.to_le_bytes()).collect(),
        vertices,
        count: primitives * per_primitive,
        bindings: [draw.index_buffer.binding, draw.vertex_buffer.binding],
    }
}

/// The most vertices a frame of a tessellation program draws: the level cap is the highest
/// that keeps the patches' slots within it (each slot runs the vertex and control stages
/// for the whole patch, so lavapipe draws about a million a second).
const TESSELLATED_VERTICES: u64 = 1 << 21;

/// The patches of `size` control points GL would draw from the mesh: its triangles for
/// patches of 3, their edges for 2, its vertices for 1, and otherwise its vertices in order,
/// `size` at a time (`glDrawArrays(GL_PATCHES, …)`; one patch, the last vertex repeated, when
/// there are fewer).
pub(crate) fn patches(size: u32, mesh: &Mesh, own_vertices: bool) -> Vec<u32> {
    let vertex_count = if own_vertices { 3 } else { mesh.vertex_count() as u32 };
    match size {
        3 => triangles(mesh, own_vertices),
        2 => primitive_indices("lines", mesh, own_vertices),
        1 => (0..vertex_count).collect(),
        _ => {
            let whole = vertex_count / size * size;
            match whole {
                0 => (0..size).map(|i| i.min(vertex_count.saturating_sub(1))).collect(),
                _ => (0..whole).collect(),
            }
        }
    }
}

/// The triangles drawn: the mesh's, or the program's own three vertices.
pub(crate) fn triangles(mesh: &Mesh, own_vertices: bool) -> Vec<u32> {
    if own_vertices {
        vec![0, 1, 2]
    } else {
        mesh.indices.clone()
    }
}

/// The vertex indices of every input primitive of a geometry stage that reads
/// `input_primitive`, made from the triangles drawn as the module doc says (what GL draws
/// with the matching mode; `effectc verify` draws them so).
pub(crate) fn primitive_indices(input_primitive: &str, mesh: &Mesh, own_vertices: bool) -> Vec<u32> {
    let triangles = triangles(mesh, own_vertices);
    let vertex_count = if own_vertices { 3 } else { mesh.vertex_count() };
    match input_primitive {
        "points" => (0..vertex_count as u32).collect(),
        "lines" => triangles.chunks_exact(3).flat_map(|t| [t[0], t[1], t[1], t[2], t[2], t[0]]).collect(),
        "lines_adjacency" => {
            triangles.chunks_exact(3).flat_map(|t| [t[2], t[0], t[1], t[2], t[0], t[1], t[2], t[0], t[1], t[2], t[0], t[1]]).collect()
        }
        "triangles_adjacency" => with_adjacency(&triangles, &mesh.attribute(crate::manifest::MeshAttribute::Position)),
        _ => triangles,
    }
}

/// GL's `GL_TRIANGLES_ADJACENCY` order for each triangle (a, b, c): a, across ab, b, across
/// bc, c, across ca, where "across" is the third corner of the triangle on the other side
/// of that edge (found by the edge's positions), or the triangle's own third corner.
fn with_adjacency(triangles: &[u32], positions: &[[f32; 4]]) -> Vec<u32> {
    let key = |i: u32| positions.get(i as usize).map_or([0; 3], |p| [p[0].to_bits(), p[1].to_bits(), p[2].to_bits()]);
    let mut third: HashMap<([u32; 3], [u32; 3]), u32> = HashMap::new();
    for t in triangles.chunks_exact(3) {
        for k in 0..3 {
            third.entry((key(t[k]), key(t[(k + 1) % 3]))).or_insert(t[(k + 2) % 3]);
        }
    }
    let mut out = Vec::with_capacity(triangles.len() * 2);
    for t in triangles.chunks_exact(3) {
        for k in 0..3 {
            let (a, b, own) = (t[k], t[(k + 1) % 3], t[(k + 2) % 3]);
            // The neighbour runs along the shared edge the other way round.
            out.extend([a, third.get(&(key(b), key(a))).copied().unwrap_or(own)]);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::back::reflect::PulledBuffer;
    use crate::manifest::MeshAttribute;

    fn draw(input: &'static str, corners: u32, slots: u32) -> GeometryDraw {
        let buffer = |stride| PulledBuffer { name: "b", group: 0, binding: 9, stride };
        GeometryDraw {
            input_primitive: input,
            output_primitive: "triangle_strip",
            max_vertices: 3,
            invocations: 1,
            topology: "triangle-list",
            vertices_per_primitive: slots,
            index_buffer: buffer(corners),
            vertex_buffer: buffer(1),
            inputs: vec!["position".into()],
            tessellation: None,
            selects: Vec::new(),
        }
    }

    /// The mesh's positions as the one vertex input.
    fn position() -> Choice {
        Choice {
            location: 0,
            input: "position".into(),
            format: wgpu::VertexFormat::Float32x3,
            attribute: Some(MeshAttribute::Position),
            values: None,
            guessed: None,
        }
    }

    /// The indices after the 4-word header (which must name layer 0 and viewport 0).
    fn words(bytes: &[u8]) -> Vec<u32> {
        let all: Vec<u32> = bytes.chunks_exact(4).map(|c| u32::from_le_bytes(c.try_into().unwrap())).collect();
        assert_eq!(all[..4], [0, 0, 0, 0]);
        all[4..].to_vec()
    }

    #[test]
    fn patches_carry_the_level_cap_and_their_slots() {
        use crate::back::reflect::TessellationDraw;
        use crate::front::tessellation_fold::tessellator::{Domain, Spacing, TessLayout};
        let mesh = Mesh::builtin(crate::manifest::BuiltinMesh::Quad);
        let position = position();
        let layout = TessLayout { domain: Domain::Quads, spacing: Spacing::Equal, clockwise: false, point_mode: false };
        let mut d = draw("patches", 4, layout.slots_per_patch(64));
        d.tessellation = Some(TessellationDraw { domain: "quads", level_cap: 64, geometry_slots: 0, layout });
        let p = pulled(&d, std::slice::from_ref(&position), &mesh, false);
        let all: Vec<u32> = p.indices.chunks_exact(4).map(|c| u32::from_le_bytes(c.try_into().unwrap())).collect();
        // One patch of the quad's four vertices in order; a single patch is drawn at GL's
        // largest level.
        assert_eq!(all[4..], [0, 1, 2, 3]);
        assert_eq!(all[..4], [0, 0, 64, layout.slots_per_patch(64)]);
        assert_eq!(p.count, layout.slots_per_patch(64));
        // Patches of three are the mesh's triangles.
        assert_eq!(patches(3, &mesh, false), mesh.indices);
    }

    #[test]
    fn a_mesh_feeds_triangles_edges_or_points() {
        let mesh = Mesh::builtin(crate::manifest::BuiltinMesh::Quad);
        let position = position();
        let t = pulled(&draw("triangles", 3, 3), std::slice::from_ref(&position), &mesh, false);
        assert_eq!(words(&t.indices), mesh.indices);
        assert_eq!(t.count, mesh.indices.len() as u32);
        assert_eq!(t.vertices.len(), mesh.vertex_count() * 16, "one vec4 per input per vertex");
        let l = pulled(&draw("lines", 2, 8), std::slice::from_ref(&position), &mesh, false);
        let i = &mesh.indices;
        assert_eq!(words(&l.indices)[..6], [i[0], i[1], i[1], i[2], i[2], i[0]]);
        assert_eq!(l.count, mesh.indices.len() as u32 * 8);
        let p = pulled(&draw("points", 1, 6), std::slice::from_ref(&position), &mesh, true);
        assert_eq!((words(&p.indices), p.count), (vec![0, 1, 2], 18));
        // The quad's two triangles share their diagonal: each sees the other's far corner
        // across it, and its own third corner across the border edges.
        let a = pulled(&draw("triangles_adjacency", 6, 3), &[position], &mesh, false);
        let adjacency = words(&a.indices);
        assert_eq!(adjacency.len(), 12);
        let (t0, t1) = (&i[0..3], &i[3..6]);
        let across = |t: &[u32], k: usize| adjacency[if t == t0 { 0 } else { 6 } + 2 * k + 1];
        for (t, other) in [(t0, t1), (t1, t0)] {
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                let shared = other.contains(&a) && other.contains(&b);
                let far = other.iter().copied().find(|v| *v != a && *v != b).unwrap();
                assert_eq!(across(t, k), if shared { far } else { t[(k + 2) % 3] }, "edge {a}-{b}");
            }
        }
    }
}
