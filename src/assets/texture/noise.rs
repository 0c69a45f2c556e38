//! Value noise: deterministic integer hashing, quintic interpolation, fractal sum. Only integer and
//! IEEE arithmetic, so every platform makes the same textures.

/// Octaves beyond this add nothing visible and would overflow the lattice period.
const MAX_OCTAVES: u32 = 16;

/// Tileable fractal value noise at texture coordinates (`u`, `v`), in 0..1.
///
/// Octave `o` (0-based, `octaves` of them, 0 treated as 1, at most 16) has a lattice of
/// `cells * 2^o` cells per side (`cells` 0 treated as 1) wrapped at that period, so the result repeats
/// with period 1 in `u` and `v`, and amplitude `2^-o`; the sum is divided by the total amplitude.
/// Lattice values come from an integer hash of (cell, seed, octave), blended with the quintic
/// fade `6t⁵ − 15t⁴ + 10t³`, so the result is identical on every platform.
pub fn tileable_noise_2d(u: f64, v: f64, cells: u32, octaves: u32, seed: u32) -> f32 {
    let mut sum = 0.0;
    let mut total_amplitude = 0.0;
    let mut amplitude = 1.0;
    for octave in 0..octaves.clamp(1, MAX_OCTAVES) {
        let period = (cells.max(1) as u64) << octave;
        let scale = period as f64;
        sum += amplitude * value_noise_2d(u * scale, v * scale, period, noise_salt(seed, octave));
        total_amplitude += amplitude;
        amplitude *= 0.5;
    }
    (sum / total_amplitude) as f32
}

/// Fractal 3D value noise on a unit direction, in 0..1, for cube maps: like [`tileable_noise_2d`] but
/// unwrapped, with the first octave's lattice spacing chosen so about `cells` cells span a face.
pub fn sphere_noise(direction: [f64; 3], cells: u32, octaves: u32, seed: u32) -> f32 {
    // A face spans about √2 of direction space (from −1/√2 to +1/√2 along each face axis).
    let base_frequency = cells.max(1) as f64 / std::f64::consts::SQRT_2;
    let mut sum = 0.0;
    let mut total_amplitude = 0.0;
    let mut amplitude = 1.0;
    for octave in 0..octaves.clamp(1, MAX_OCTAVES) {
        let frequency = base_frequency * (1u64 << octave) as f64;
        let point = direction.map(|c| c * frequency);
        sum += amplitude * value_noise_3d(point, noise_salt(seed, octave));
        total_amplitude += amplitude;
        amplitude *= 0.5;
    }
    (sum / total_amplitude) as f32
}

fn value_noise_2d(x: f64, y: f64, period: u64, salt: u64) -> f64 {
    let (x0, fx) = split(x);
    let (y0, fy) = split(y);
    let (x0, x1) = wrapped_pair(x0, period);
    let (y0, y1) = wrapped_pair(y0, period);
    let corner = |x: u64, y: u64| lattice_value([x, y, 0], salt);
    let (sx, sy) = (fade(fx), fade(fy));
    let bottom = lerp(corner(x0, y0), corner(x1, y0), sx);
    let top = lerp(corner(x0, y1), corner(x1, y1), sx);
    lerp(bottom, top, sy)
}

fn value_noise_3d(point: [f64; 3], salt: u64) -> f64 {
    let (x0, fx) = split(point[0]);
    let (y0, fy) = split(point[1]);
    let (z0, fz) = split(point[2]);
    let corner = |dx: i64, dy: i64, dz: i64| {
        // Negative lattice indices are hashed by their two's-complement bits.
        lattice_value([(x0 + dx) as u64, (y0 + dy) as u64, (z0 + dz) as u64], salt)
    };
    let (sx, sy, sz) = (fade(fx), fade(fy), fade(fz));
    let plane = |dz: i64| {
        let near = lerp(corner(0, 0, dz), corner(1, 0, dz), sx);
        let far = lerp(corner(0, 1, dz), corner(1, 1, dz), sx);
        lerp(near, far, sy)
    };
    lerp(plane(0), plane(1), sz)
}

/// Integer lattice index and fraction of a coordinate (floor by integer conversion, which unlike
/// `f64::floor` needs no library call on baseline x86-64).
fn split(x: f64) -> (i64, f64) {
    let truncated = x as i64;
    let floor = if (truncated as f64) > x { truncated - 1 } else { truncated };
    (floor, x - floor as f64)
}

/// A lattice index and its successor, both wrapped into 0..period.
fn wrapped_pair(index: i64, period: u64) -> (u64, u64) {
    let period = period.max(1);
    // Texture coordinates in 0..=1 give indices in 0..=period; skip the slow division for them.
    let first = match u64::try_from(index) {
        Ok(i) if i < period => i,
        Ok(i) if i == period => 0,
        _ => index.rem_euclid(period as i64) as u64,
    };
    let second = if first + 1 == period { 0 } else { first + 1 };
    (first, second)
}

fn fade(t: f64) -> f64 {
    t * t * t * (t * (t * 6.0 - 15.0) + 10.0)
}

fn lerp(a: f64, b: f64, t: f64) -> f64 {
    a + (b - a) * t
}

/// A value in 0..1 for a lattice point: the point's coordinates, combined with odd multipliers and
/// the octave's salt, through the SplitMix64 finaliser (integer-only, so identical on every platform).
fn lattice_value(coords: [u64; 3], salt: u64) -> f64 {
    let combined = coords[0].wrapping_mul(0x9E37_79B9_7F4A_7C15)
        ^ coords[1].wrapping_mul(0xC2B2_AE3D_27D4_EB4F)
        ^ coords[2].wrapping_mul(0x1656_67B1_9E37_79F9);
    (mix64(combined ^ salt) >> 11) as f64 / (1u64 << 53) as f64
}

/// The per-octave salt, already mixed so that neighbouring seeds give unrelated noise.
fn noise_salt(seed: u32, octave: u32) -> u64 {
    mix64(((seed as u64) << 32) | octave as u64)
}

fn mix64(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}
