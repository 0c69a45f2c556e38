//! Cube-map geometry: the direction each texel of a cube face looks along, from the cube-map face
//! selection table shared by GL, Vulkan and wgpu.

/// The (unnormalised) direction of face-local coordinates `sc`, `tc` in −1..1 on cube layer `face`
/// (0..6 = +x −x +y −y +z −z), the inverse of the cube-map face selection table (GL 4.6 table 8.19,
/// Vulkan "Cube Map Face Selection"), where s = (sc/|ma| + 1)/2 and t = (tc/|ma| + 1)/2:
///
/// | face | sc  | tc  | ma |
/// |------|-----|-----|----|
/// | +x   | −rz | −ry | rx |
/// | −x   | +rz | −ry | rx |
/// | +y   | +rx | +rz | ry |
/// | −y   | +rx | −rz | ry |
/// | +z   | +rx | −ry | rz |
/// | −z   | −rx | −ry | rz |
///
/// Out-of-range faces are treated as −z.
pub fn cube_direction(face: u32, sc: f64, tc: f64) -> [f64; 3] {
    match face {
        0 => [1.0, -tc, -sc],
        1 => [-1.0, -tc, sc],
        2 => [sc, 1.0, tc],
        3 => [sc, -1.0, -tc],
        4 => [sc, -tc, 1.0],
        _ => [-sc, -tc, -1.0],
    }
}

/// `v` at unit length, or unchanged when its length is not positive.
pub(super) fn normalize(v: [f64; 3]) -> [f64; 3] {
    let length = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if length > 0.0 {
        v.map(|c| c / length)
    } else {
        v
    }
}
