use std::f32::consts::PI;

use glam::Vec3;

use super::tangents::compute_tangents;
use super::*;
use crate::manifest::BuiltinMesh;

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

fn close3(a: impl Into<Vec3>, b: impl Into<Vec3>) -> bool {
    let (a, b) = (a.into(), b.into());
    (0..3).all(|i| close(a[i], b[i]))
}

fn v3(v: [f32; 3]) -> Vec3 {
    Vec3::from(v)
}

fn xyz(v: [f32; 4]) -> Vec3 {
    Vec3::new(v[0], v[1], v[2])
}

fn length(v: impl Into<Vec3>) -> f32 {
    v.into().length()
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
    for name in MeshAttribute::ALL {
        let data = mesh.attribute(name);
        assert_eq!(data.len(), n, "{what}: {name}");
        assert!(data.iter().flatten().all(|c| c.is_finite()), "{what}: {name} not finite");
    }
    for (i, (&normal, &tangent)) in mesh.normals.iter().zip(&mesh.tangents).enumerate() {
        assert!(close(length(normal), 1.0), "{what}: normal {i} = {normal:?}");
        assert!(close(length(xyz(tangent)), 1.0), "{what}: tangent {i} = {tangent:?}");
        assert!(close(v3(normal).dot(xyz(tangent)), 0.0), "{what}: tangent {i} not ⟂ normal");
        assert!(tangent[3] == 1.0 || tangent[3] == -1.0, "{what}: tangent sign {i} = {}", tangent[3]);
    }
}

/// cross(b − a, c − a) points the way of the vertex normals (CCW front faces).
fn check_winding(mesh: &Mesh, what: &str) {
    for [a, b, c] in triangles(mesh) {
        let p = |i: usize| v3(mesh.positions[i]);
        let face = (p(b) - p(a)).cross(p(c) - p(a));
        let normals = v3(mesh.normals[a]) + v3(mesh.normals[b]) + v3(mesh.normals[c]);
        assert!(face.dot(normals) > 0.0, "{what}: triangle {a} {b} {c} is clockwise");
    }
}

/// The stored tangent follows ∂P/∂u and the bitangent ∂P/∂v of each triangle's uv mapping.
fn check_tangent_frame(mesh: &Mesh, what: &str) {
    let bitangents = mesh.attribute(MeshAttribute::Bitangent);
    for [a, b, c] in triangles(mesh) {
        let (e1, e2) = (v3(mesh.positions[b]) - v3(mesh.positions[a]), v3(mesh.positions[c]) - v3(mesh.positions[a]));
        let (uv0, uv1, uv2) = (mesh.uvs[a], mesh.uvs[b], mesh.uvs[c]);
        let (du1, dv1, du2, dv2) = (uv1[0] - uv0[0], uv1[1] - uv0[1], uv2[0] - uv0[0], uv2[1] - uv0[1]);
        let det = du1 * dv2 - du2 * dv1;
        if det.abs() < 1e-6 {
            continue;
        }
        let dp_du = (e1 * dv2 - e2 * dv1) * (1.0 / det);
        let dp_dv = (e2 * du1 - e1 * du2) * (1.0 / det);
        for v in [a, b, c] {
            assert!(xyz(mesh.tangents[v]).dot(dp_du) > 0.0, "{what}: tangent {v} against ∂P/∂u");
            assert!(xyz(bitangents[v]).dot(dp_dv) > 0.0, "{what}: bitangent {v} against ∂P/∂v");
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
        assert_eq!(mesh.provided, [MeshAttribute::Position, MeshAttribute::Normal, MeshAttribute::Uv, MeshAttribute::Tangent], "{what}");
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
        assert!(mesh.normals.iter().all(|&n| n == Vec3::Z.to_array()));
        assert!(mesh.tangents.iter().all(|&t| t == [1.0, 0.0, 0.0, 1.0]));
    }
}

/// The full-window rectangle is drawn as GL programs draw one (`piglit_draw_rect`'s
/// triangle strip): corners lower left, lower right, upper left, upper right; triangles
/// (0, 1, 2) and (2, 1, 3), both counter-clockwise, so the last vertex of each (GL's
/// provoking vertex) is the upper left and the upper right corner.
#[test]
fn the_fullscreen_quad_is_gl_s_triangle_strip() {
    let mesh = Mesh::builtin(BuiltinMesh::FullscreenQuad);
    assert_eq!(mesh.positions, [[-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [-1.0, 1.0, 0.0], [1.0, 1.0, 0.0]]);
    assert_eq!(mesh.indices, [0, 1, 2, 2, 1, 3]);
    for t in mesh.indices.chunks(3) {
        let [a, b, c] = [t[0], t[1], t[2]].map(|i| mesh.positions[i as usize]);
        let area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        assert!(area > 0.0, "{t:?} is not counter-clockwise");
    }
}

#[test]
fn cube_faces_are_flat_outward_and_upright() {
    let mesh = Mesh::builtin(BuiltinMesh::Cube);
    assert_eq!(mesh.bounds(), ([-0.5; 3], [0.5; 3]));
    let bitangents = mesh.attribute(MeshAttribute::Bitangent);
    for (v, bitangent) in bitangents.iter().enumerate() {
        let (face, normal) = (v / 4, mesh.normals[v]);
        assert_eq!(normal, mesh.normals[face * 4], "flat normals on face {face}");
        assert!(close(v3(mesh.positions[v]).dot(v3(normal)), 0.5), "normal points outward on face {face}");
        let up = xyz(*bitangent);
        if normal[1] == 0.0 {
            assert!(close3(up, Vec3::Y), "side face {face}: texture up is +y, got {up:?}");
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
    assert!(close3(mesh.positions[front], Vec3::Z));
    assert!(close3(xyz(mesh.tangents[front]), Vec3::X));
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
    assert!(mesh.normals.iter().all(|&n| n == Vec3::Y.to_array()));
    for [a, b, c] in triangles(&mesh) {
        let p = |i: usize| v3(mesh.positions[i]);
        assert!((p(b) - p(a)).cross(p(c) - p(a)).y > 0.0, "CCW seen from +y");
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
    let positions = mesh.attribute(MeshAttribute::Position);
    assert!(positions.iter().all(|p| p[3] == 1.0));
    assert!(mesh.attribute(MeshAttribute::Normal).iter().all(|n| *n == [0.0, 0.0, 1.0, 0.0]));
    assert_eq!(mesh.attribute(MeshAttribute::Uv)[2], [0.0, 1.0, 0.0, 0.0]);
    assert_eq!(mesh.attribute(MeshAttribute::Color)[0], WHITE);
    assert_eq!(mesh.attribute(MeshAttribute::Bitangent)[0], [0.0, 1.0, 0.0, 0.0]);
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
    assert_eq!(mesh.provided, [MeshAttribute::Position, MeshAttribute::Normal, MeshAttribute::Uv]);
    assert_eq!(mesh.computed, [MeshAttribute::Tangent]);
    assert_eq!(mesh.uvs, [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], "OBJ v = 0 is the bottom, as in GL");
    assert!(mesh.tangents.iter().all(|t| close3(xyz(*t), Vec3::X) && t[3] == 1.0), "{:?}", mesh.tangents);
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
    let bitangents = mesh.attribute(MeshAttribute::Bitangent);
    assert!(bitangents.iter().all(|b| close3(xyz(*b), Vec3::Y) && b[3] == 0.0), "{bitangents:?}");
}

#[test]
fn obj_triangle_without_normals_gets_computed_ones() {
    let mesh = obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    check_invariants(&mesh, "triangle");
    check_winding(&mesh, "triangle");
    assert_eq!(mesh.normals, [Vec3::Z.to_array(); 3]);
    assert_eq!(mesh.provided, [MeshAttribute::Position]);
    assert_eq!(mesh.computed, [MeshAttribute::Normal, MeshAttribute::Tangent]);
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
    assert_eq!(mesh.provided, [MeshAttribute::Position, MeshAttribute::Normal]);
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
    assert!(mesh.provided.contains(&MeshAttribute::Color));
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
    assert_eq!(mesh.computed, [MeshAttribute::Normal, MeshAttribute::Tangent], "one object had no normals");
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
