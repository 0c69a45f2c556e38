//! GL's fixed-function tessellator (OpenGL 4.6, §11.2.2) as GLSL for the folded stage, and
//! its primitive counts on the host.
//!
//! The folded draw spends a fixed number of vertices (slots) on each patch: three per
//! triangle (two per isoline segment) of the most the patch can make at the level cap.
//! `effectc_primitive(t, …)` gives the domain coordinates of the corners of the patch's
//! `t`-th primitive at the levels the control stage wrote, or false past its last one:
//! - triangles: concentric rings (ring `i` has `n − 2i` segments per edge, its corners on
//!   the perpendiculars through the outer edge's `i`-th points), the outermost edges
//!   subdivided by the outer levels, each pair of rings stitched;
//! - quads: the inner grid's cells as two triangles each, and the outer ring stitched;
//! - isolines: `outer[0]` lines (equal spacing) of `outer[1]` segments.
//!
//! Fractional spacing puts its two shorter segments at the ends of an edge (GL places them
//! symmetrically, where is the implementation's choice). A patch whose outer levels are not
//! all positive is discarded. Triangles take the winding `cw`/`ccw` asks for in (u, v).

use std::fmt::Write as _;

/// The largest level (GL's `GL_MAX_TESS_GEN_LEVEL` is at least 64).
pub const MAX_LEVEL: u32 = 64;

/// The tessellation primitive generator's domain.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Domain {
    Triangles,
    Quads,
    Isolines,
}

/// How levels subdivide an edge.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Spacing {
    Equal,
    FractionalEven,
    FractionalOdd,
}

/// The evaluation stage's input layout.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TessLayout {
    pub domain: Domain,
    pub spacing: Spacing,
    pub clockwise: bool,
    pub point_mode: bool,
}

impl TessLayout {
    pub const fn domain_name(&self) -> &'static str {
        match self.domain {
            Domain::Triangles => "triangles",
            Domain::Quads => "quads",
            Domain::Isolines => "isolines",
        }
    }

    /// The pipeline's primitive topology.
    pub const fn topology(&self) -> &'static str {
        match (self.point_mode, self.domain) {
            (true, _) => "point-list",
            (false, Domain::Isolines) => "line-list",
            _ => "triangle-list",
        }
    }

    /// Slots per generated primitive (point mode draws each corner as a point).
    pub const fn corners(&self) -> u32 {
        match self.domain {
            Domain::Isolines => 2,
            _ => 3,
        }
    }

    /// Vertices the folded draw spends on one patch when levels are capped at `cap`.
    pub fn slots_per_patch(&self, cap: u32) -> u32 {
        self.most_primitives(cap) * self.corners()
    }

    /// The most primitives a patch makes with every level at `cap` (the counts grow with
    /// every level).
    pub fn most_primitives(&self, cap: u32) -> u32 {
        let cap = cap.clamp(2, MAX_LEVEL);
        let n = segments(self.spacing, cap, cap as f32);
        match self.domain {
            // Fractional odd spacing under a cap of 2 leaves every level at 1: the single
            // triangle or quad.
            Domain::Triangles if n < 2 => 1,
            Domain::Quads if n < 2 => 2,
            Domain::Triangles => triangle_count(n, [n; 3]),
            Domain::Quads => 2 * (n - 2) * (n - 2) + 4 * (n + n - 2),
            Domain::Isolines => cap * n,
        }
    }
}

/// Segments an edge at level `f` gets (after clamping to the spacing's range under `cap`).
fn segments(spacing: Spacing, cap: u32, f: f32) -> u32 {
    let cap = cap as f32;
    match spacing {
        Spacing::Equal => f.clamp(1.0, cap).ceil() as u32,
        Spacing::FractionalEven => 2 * (f.clamp(2.0, cap) / 2.0).ceil() as u32,
        Spacing::FractionalOdd => 2 * ((f.clamp(1.0, cap - 1.0) - 1.0) / 2.0).ceil() as u32 + 1,
    }
}

/// Triangles of the triangle domain with `n` inner segments (≥ 2) and these outer ones.
fn triangle_count(n: u32, outer: [u32; 3]) -> u32 {
    let mut count = outer.iter().sum::<u32>() + 3 * (n - 2);
    let mut i = 1;
    while n >= 2 * i + 2 {
        count += 3 * ((n - 2 * i) + (n - 2 * i - 2));
        i += 1;
    }
    count + n % 2
}

/// The GLSL of the tessellator for `layout`: `bool effectc_primitive(int t, out vec3 c0,
/// out vec3 c1, out vec3 c2)` reading `effectc_TessLevelOuter`/`Inner` and
/// `effectc_level_cap`.
pub fn glsl(layout: TessLayout) -> String {
    let mut t = String::new();
    let spacing = match layout.spacing {
        Spacing::Equal => 0,
        Spacing::FractionalEven => 1,
        Spacing::FractionalOdd => 2,
    };
    writeln!(t, "const int effectc_spacing = {spacing};\nfloat effectc_level_cap;").unwrap();
    t.push_str(COMMON);
    let domain = match layout.domain {
        Domain::Triangles => TRIANGLES,
        Domain::Quads => QUADS,
        Domain::Isolines => ISOLINES,
    };
    // The domain's points, the stitch that joins them, then the primitives.
    let primitive = domain.find("bool effectc_primitive").unwrap_or(0);
    t.push_str(&domain[..primitive]);
    if layout.domain != Domain::Isolines {
        t.push_str(STITCH);
    }
    t.push_str(&domain[primitive..]);
    // Winding in (u, v): counter-clockwise has a positive signed area.
    let wrong = if layout.clockwise { "area > 0.0" } else { "area < 0.0" };
    writeln!(
        t,
        "bool effectc_generated(int t, out vec3 c0, out vec3 c1, out vec3 c2) {{
    if (!effectc_primitive(t, c0, c1, c2)) {{
        return false;
    }}
    float area = (c1.x - c0.x) * (c2.y - c0.y) - (c1.y - c0.y) * (c2.x - c0.x);
    if ({wrong}) {{
        vec3 c = c1;
        c1 = c2;
        c2 = c;
    }}
    return true;
}}"
    )
    .unwrap();
    t
}

/// Level clamping and rounding, and the points of a subdivided edge.
const COMMON: &str = "float effectc_clamped(float f) {
    if (effectc_spacing == 1) {
        return clamp(f, 2.0, effectc_level_cap);
    }
    if (effectc_spacing == 2) {
        return clamp(f, 1.0, effectc_level_cap - 1.0);
    }
    return clamp(f, 1.0, effectc_level_cap);
}
int effectc_segments(float f) {
    if (effectc_spacing == 1) {
        return 2 * int(ceil(f / 2.0));
    }
    if (effectc_spacing == 2) {
        return 2 * int(ceil((f - 1.0) / 2.0)) + 1;
    }
    return int(ceil(f));
}
float effectc_at(int j, int n, float f) {
    if (j <= 0) {
        return 0.0;
    }
    if (j >= n) {
        return 1.0;
    }
    if (effectc_spacing == 0 || float(n) == f) {
        return float(j) / float(n);
    }
    float l = 1.0 / f;
    float s = (1.0 - float(n - 2) * l) * 0.5;
    return s + float(j - 1) * l;
}
float effectc_of[4];
int effectc_on[4];
float effectc_if[2];
int effectc_in[2];
bool effectc_outer_levels(int count) {
    for (int e = 0; e < count; e++) {
        float f = effectc_TessLevelOuter[e];
        if (!(f > 0.0)) {
            return false;
        }
        effectc_of[e] = effectc_clamped(f);
        effectc_on[e] = effectc_segments(effectc_of[e]);
    }
    return true;
}
void effectc_inner_level(int k, bool lift) {
    float f = effectc_TessLevelInner[k];
    effectc_if[k] = effectc_clamped(f > 0.0 ? f : 1.0);
    effectc_in[k] = effectc_segments(effectc_if[k]);
    if (lift && effectc_in[k] == 1) {
        effectc_if[k] = effectc_clamped(1.0 + 1.0 / 64.0);
        effectc_in[k] = effectc_segments(effectc_if[k]);
    }
}
";

/// The triangle domain: rings of the inner level, the outermost edges of the outer levels.
const TRIANGLES: &str = "vec3 effectc_ring_corner(int e, int i) {
    float p = effectc_at(i, effectc_in[0], effectc_if[0]);
    vec3 unit = e == 0 ? vec3(0.0, 1.0, 0.0) : (e == 1 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0));
    return vec3(2.0 * p / 3.0) + (1.0 - 2.0 * p) * unit;
}
vec3 effectc_point(int e, int i, int j) {
    vec3 a = effectc_ring_corner(e, i);
    vec3 b = effectc_ring_corner((e + 1) % 3, i);
    if (i == 0) {
        return mix(a, b, effectc_at(j, effectc_on[e], effectc_of[e]));
    }
    int n = effectc_in[0];
    float f = effectc_if[0];
    float p0 = effectc_at(i, n, f);
    float p1 = effectc_at(n - i, n, f);
    float t = p1 > p0 ? (effectc_at(i + j, n, f) - p0) / (p1 - p0) : 0.0;
    return mix(a, b, t);
}
bool effectc_primitive(int t, out vec3 c0, out vec3 c1, out vec3 c2) {
    c0 = vec3(0.0);
    c1 = vec3(0.0);
    c2 = vec3(0.0);
    if (!effectc_outer_levels(3)) {
        return false;
    }
    effectc_inner_level(0, false);
    if (effectc_in[0] == 1 && effectc_on[0] == 1 && effectc_on[1] == 1 && effectc_on[2] == 1) {
        c0 = vec3(0.0, 0.0, 1.0);
        c1 = vec3(1.0, 0.0, 0.0);
        c2 = vec3(0.0, 1.0, 0.0);
        return t == 0;
    }
    effectc_inner_level(0, true);
    int n = effectc_in[0];
    for (int i = 0; n - 2 * i >= 1; i++) {
        if (n - 2 * i == 1) {
            c0 = effectc_ring_corner(0, i);
            c1 = effectc_ring_corner(1, i);
            c2 = effectc_ring_corner(2, i);
            return t == 0;
        }
        int b = max(n - 2 * i - 2, 0);
        for (int e = 0; e < 3; e++) {
            int a = i == 0 ? effectc_on[e] : n - 2 * i;
            if (t < a + b) {
                effectc_stitch(e, i, a, b, t, c0, c1, c2);
                return true;
            }
            t -= a + b;
        }
    }
    return false;
}
";

/// The quad domain: the inner grid, the outer ring stitched to it.
const QUADS: &str = "vec3 effectc_grid(int x, int y) {
    return vec3(effectc_at(x, effectc_in[0], effectc_if[0]), effectc_at(y, effectc_in[1], effectc_if[1]), 0.0);
}
vec3 effectc_point(int e, int ring, int j) {
    int n0 = effectc_in[0];
    int n1 = effectc_in[1];
    if (ring == 0) {
        if (e == 0) {
            return vec3(effectc_at(j, effectc_on[1], effectc_of[1]), 0.0, 0.0);
        }
        if (e == 1) {
            return vec3(1.0, effectc_at(j, effectc_on[2], effectc_of[2]), 0.0);
        }
        if (e == 2) {
            return vec3(1.0 - effectc_at(j, effectc_on[3], effectc_of[3]), 1.0, 0.0);
        }
        return vec3(0.0, 1.0 - effectc_at(j, effectc_on[0], effectc_of[0]), 0.0);
    }
    if (e == 0) {
        return effectc_grid(1 + j, 1);
    }
    if (e == 1) {
        return effectc_grid(n0 - 1, 1 + j);
    }
    if (e == 2) {
        return effectc_grid(n0 - 1 - j, n1 - 1);
    }
    return effectc_grid(1, n1 - 1 - j);
}
bool effectc_primitive(int t, out vec3 c0, out vec3 c1, out vec3 c2) {
    c0 = vec3(0.0);
    c1 = vec3(0.0);
    c2 = vec3(0.0);
    if (!effectc_outer_levels(4)) {
        return false;
    }
    effectc_inner_level(0, false);
    effectc_inner_level(1, false);
    if (effectc_in[0] == 1 && effectc_in[1] == 1 && effectc_on[0] == 1 && effectc_on[1] == 1 && effectc_on[2] == 1 && effectc_on[3] == 1) {
        c0 = vec3(0.0, 0.0, 0.0);
        c1 = t == 0 ? vec3(1.0, 0.0, 0.0) : vec3(1.0, 1.0, 0.0);
        c2 = t == 0 ? vec3(1.0, 1.0, 0.0) : vec3(0.0, 1.0, 0.0);
        return t < 2;
    }
    effectc_inner_level(0, true);
    effectc_inner_level(1, true);
    int n0 = effectc_in[0];
    int n1 = effectc_in[1];
    int cells = (n0 - 2) * (n1 - 2);
    if (t < 2 * cells) {
        int x = (t / 2) % (n0 - 2) + 1;
        int y = (t / 2) / (n0 - 2) + 1;
        c0 = effectc_grid(x, y);
        c1 = t % 2 == 0 ? effectc_grid(x + 1, y) : effectc_grid(x + 1, y + 1);
        c2 = t % 2 == 0 ? effectc_grid(x + 1, y + 1) : effectc_grid(x, y + 1);
        return true;
    }
    t -= 2 * cells;
    for (int e = 0; e < 4; e++) {
        int a = effectc_on[(e + 1) % 4];
        int b = (e % 2 == 0 ? n0 : n1) - 2;
        if (t < a + b) {
            effectc_stitch(e, 0, a, b, t, c0, c1, c2);
            return true;
        }
        t -= a + b;
    }
    return false;
}
";

/// The isoline domain: `outer[0]` lines at v = k / lines, each of `outer[1]` segments.
const ISOLINES: &str = "bool effectc_primitive(int t, out vec3 c0, out vec3 c1, out vec3 c2) {
    c0 = vec3(0.0);
    c1 = vec3(0.0);
    c2 = vec3(0.0);
    if (!effectc_outer_levels(2)) {
        return false;
    }
    int lines = int(ceil(clamp(effectc_TessLevelOuter[0], 1.0, effectc_level_cap)));
    int segments = effectc_on[1];
    if (t >= lines * segments) {
        return false;
    }
    float v = float(t / segments) / float(lines);
    int s = t % segments;
    c0 = vec3(effectc_at(s, segments, effectc_of[1]), v, 0.0);
    c1 = vec3(effectc_at(s + 1, segments, effectc_of[1]), v, 0.0);
    c2 = c1;
    return true;
}
";

/// Triangle `s` of the strip between edge `e` of ring `ring` (`a` segments) and the same
/// edge of the ring inside it (`b` segments): each step advances along the edge whose next
/// point comes first.
const STITCH: &str = "bool effectc_outer_first(int o, int i, int a, int b) {
    return i >= b || (o < a && (2 * o + 1) * b <= (2 * i + 1) * a);
}
void effectc_stitch(int e, int ring, int a, int b, int s, out vec3 c0, out vec3 c1, out vec3 c2) {
    int o = 0;
    int i = 0;
    for (int step = 0; step < s; step++) {
        if (effectc_outer_first(o, i, a, b)) {
            o++;
        } else {
            i++;
        }
    }
    c0 = effectc_point(e, ring, o);
    if (effectc_outer_first(o, i, a, b)) {
        c1 = effectc_point(e, ring, o + 1);
    } else {
        c1 = effectc_point(e, ring + 1, i + 1);
    }
    c2 = effectc_point(e, ring + 1, i);
}
";

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn triangle_counts_follow_the_rings() {
        // Inner 2: each outer edge fans to the centre; inner 3: a ring of 1 and the centre
        // triangle; inner 4: two rings, the inner one fanned to the centre.
        assert_eq!(triangle_count(2, [2; 3]), 6);
        assert_eq!(triangle_count(3, [3; 3]), 9 + 3 + 1);
        assert_eq!(triangle_count(4, [4; 3]), 12 + 6 + 6);
        assert_eq!(triangle_count(2, [1; 3]), 3);
    }

    #[test]
    fn slots_cover_the_most_a_patch_makes() {
        let quads = TessLayout { domain: Domain::Quads, spacing: Spacing::Equal, clockwise: false, point_mode: false };
        // Inner 2 × 2: no inner cells, each outer edge of 2 fanned to the centre.
        assert_eq!(quads.most_primitives(2), 8);
        // 64: 62 × 62 cells of two triangles and four edges of 64 + 62.
        assert_eq!(quads.most_primitives(64), 2 * 62 * 62 + 4 * 126);
        let lines = TessLayout { domain: Domain::Isolines, ..quads };
        assert_eq!(lines.slots_per_patch(4), 4 * 4 * 2);
        // Fractional odd spacing rounds a level under an even cap to the odd below it.
        let odd = TessLayout { spacing: Spacing::FractionalOdd, domain: Domain::Triangles, ..quads };
        assert_eq!(odd.most_primitives(4), triangle_count(3, [3; 3]));
        // Under a cap of 2 it leaves every level at 1.
        assert_eq!(odd.most_primitives(2), 1);
        assert_eq!(TessLayout { domain: Domain::Quads, ..odd }.most_primitives(2), 2);
    }
}
