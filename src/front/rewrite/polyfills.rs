//! Built-in functions naga cannot take or its back ends cannot write (its GLSL front has
//! no `matrixCompMult`; its WGSL writer has no `isnan`, `isinf` or `outerProduct`), called
//! under effectc names and defined in the header as overloads for every size:
//! `isnan`/`isinf` from the float's bits (no comparison a compiler could fold away),
//! `outerProduct` and `matrixCompMult` column by column; the integer built-ins GLSL 4.00
//! added (`uaddCarry`, `usubBorrow`, `umulExtended`, `imulExtended`) from 16-bit halves,
//! `modf` from `trunc` and `frexp` from the float's bits; `noise1`–`noise4` as zero, what
//! Mesa's and most drivers' implementations return (GLSL 4.40 deprecated them). (`inverse`
//! stays naga's: its
//! WGSL writer has it, and a definition of our own would hide the normal-matrix facts the
//! hazard analysis reads from it.)

use std::fmt::Write;

use super::Ctx;

/// The built-ins replaced, with the name they are called by.
const REPLACED: [(&str, &str); 14] = [
    ("isnan", "effectc_isnan"),
    ("isinf", "effectc_isinf"),
    ("outerProduct", "effectc_outerProduct"),
    ("matrixCompMult", "effectc_matrixCompMult"),
    ("uaddCarry", "effectc_uaddCarry"),
    ("usubBorrow", "effectc_usubBorrow"),
    ("umulExtended", "effectc_umulExtended"),
    ("imulExtended", "effectc_imulExtended"),
    ("modf", "effectc_modf"),
    ("frexp", "effectc_frexp"),
    ("noise1", "effectc_noise1"),
    ("noise2", "effectc_noise2"),
    ("noise3", "effectc_noise3"),
    ("noise4", "effectc_noise4"),
];

impl Ctx<'_> {
    /// Calls of the replaced built-ins renamed; which definitions the header needs.
    pub(super) fn polyfills(&mut self) {
        let s = self.s;
        for c in &s.calls {
            let Some((builtin, ours)) = REPLACED.iter().find(|(b, _)| *b == c.name) else { continue };
            // A user function of that name (an overload) is the user's, not the built-in.
            if s.functions.iter().any(|f| f.name == c.name) {
                continue;
            }
            self.edits.replace(c.name_span.clone(), *ours);
            // imulExtended is written with umulExtended.
            let needs: &[&'static str] =
                if *builtin == "imulExtended" { &["umulExtended", "imulExtended"] } else { std::slice::from_ref(builtin) };
            for b in needs {
                if !self.polyfills.contains(b) {
                    self.polyfills.push(b);
                }
            }
        }
    }
}

/// The definitions of the replaced built-ins in `used`, every size.
pub(super) fn definitions(used: &[&str]) -> String {
    let mut h = String::new();
    for b in used {
        match *b {
            "isnan" | "isinf" => {
                let (cmp, vcmp) = if *b == "isnan" { (">", "greaterThan") } else { ("==", "equal") };
                let _ = writeln!(h, "bool effectc_{b}(float x) {{ return (floatBitsToUint(x) & 0x7fffffffu) {cmp} 0x7f800000u; }}");
                for n in 2..=4 {
                    let _ = writeln!(
                        h,
                        "bvec{n} effectc_{b}(vec{n} x) {{ return {vcmp}(floatBitsToUint(x) & uvec{n}(0x7fffffffu), uvec{n}(0x7f800000u)); }}"
                    );
                }
            }
            "matrixCompMult" => {
                for rows in 2..=4 {
                    for columns in 2..=4 {
                        let ty = if rows == columns { format!("mat{rows}") } else { format!("mat{columns}x{rows}") };
                        let cols: Vec<String> = (0..columns).map(|i| format!("a[{i}] * b[{i}]")).collect();
                        let _ = writeln!(h, "{ty} effectc_matrixCompMult({ty} a, {ty} b) {{ return {ty}({}); }}", cols.join(", "));
                    }
                }
            }
            "uaddCarry" | "usubBorrow" | "umulExtended" | "imulExtended" | "modf" => integer_and_modf(&mut h, b),
            "frexp" => frexp(&mut h),
            "shadow1d" => {
                // A 1D depth lookup's (s, unused, ref[, q]) at the middle of a 2D texture's
                // one row: t = 0.5, times q when the lookup is projective.
                h.push_str("vec3 effectc_shadow1d(vec3 p) { return vec3(p.x, 0.5, p.z); }\n");
                h.push_str("vec4 effectc_shadow1d(vec4 p) { return vec4(p.x, 0.5 * p.w, p.z, p.w); }\n");
            }
            "rect" => {
                // A rectangle texture's texel coordinates as a 2D texture's: x and y divided
                // by the size; a projective divisor or a depth reference left as it is.
                h.push_str("vec2 effectc_rect(vec2 p, vec2 size) { return p / size; }\n");
                h.push_str("vec3 effectc_rect(vec3 p, vec2 size) { return vec3(p.xy / size, p.z); }\n");
                h.push_str("vec4 effectc_rect(vec4 p, vec2 size) { return vec4(p.xy / size, p.zw); }\n");
            }
            "textureQueryLod" => h.push_str(&super::query_lod::definitions()),
            "integer_lookups" => h.push_str(&super::integer_lookups::definitions()),
            "noise1" | "noise2" | "noise3" | "noise4" => {
                let result = if *b == "noise1" { "float".to_string() } else { format!("vec{}", &b[5..]) };
                for arg in ["float", "vec2", "vec3", "vec4"] {
                    let _ = writeln!(h, "{result} effectc_{b}({arg} x) {{ return {result}(0.0); }}");
                }
            }
            _ => {
                // outerProduct(c, r): a matrix of r's size in columns, c's in rows; column i is c * r[i].
                for rows in 2..=4 {
                    for columns in 2..=4 {
                        let ty = if rows == columns { format!("mat{rows}") } else { format!("mat{columns}x{rows}") };
                        let cols: Vec<String> = (0..columns).map(|i| format!("c * r[{i}]")).collect();
                        let _ =
                            writeln!(h, "{ty} effectc_outerProduct(vec{rows} c, vec{columns} r) {{ return {ty}({}); }}", cols.join(", "));
                    }
                }
            }
        }
    }
    h
}

/// `uaddCarry`, `usubBorrow`, `umulExtended` (the 64-bit product from four 16-bit
/// products), `imulExtended` (the unsigned product corrected for negative operands) and
/// `modf`, for scalars and every vector size.
fn integer_and_modf(h: &mut String, builtin: &str) {
    for n in 1..=4 {
        let (u, i, f) = if n == 1 {
            ("uint".to_string(), "int".to_string(), "float".to_string())
        } else {
            (format!("uvec{n}"), format!("ivec{n}"), format!("vec{n}"))
        };
        // 1u where x < y, else 0u.
        let below = |x: &str, y: &str| if n == 1 { format!("uint({x} < {y})") } else { format!("{u}(lessThan({x}, {y}))") };
        let _ = match builtin {
            "uaddCarry" => writeln!(
                h,
                "{u} effectc_uaddCarry({u} a, {u} b, out {u} carry) {{ {u} s = a + b; carry = {}; return s; }}",
                below("s", "a")
            ),
            "usubBorrow" => {
                writeln!(h, "{u} effectc_usubBorrow({u} a, {u} b, out {u} borrow) {{ borrow = {}; return a - b; }}", below("a", "b"))
            }
            "umulExtended" => writeln!(
                h,
                "void effectc_umulExtended({u} a, {u} b, out {u} msb, out {u} lsb) {{ \
                 {u} al = a & 0xFFFFu; {u} ah = a >> 16u; {u} bl = b & 0xFFFFu; {u} bh = b >> 16u; \
                 {u} lh = al * bh; {u} hl = ah * bl; {u} mid = ((al * bl) >> 16u) + (lh & 0xFFFFu) + (hl & 0xFFFFu); \
                 msb = ah * bh + (lh >> 16u) + (hl >> 16u) + (mid >> 16u); lsb = a * b; }}"
            ),
            "imulExtended" => writeln!(
                h,
                "void effectc_imulExtended({i} a, {i} b, out {i} msb, out {i} lsb) {{ \
                 {u} ua = {u}(a); {u} ub = {u}(b); {u} hi; {u} lo; effectc_umulExtended(ua, ub, hi, lo); \
                 hi -= {} * ub + {} * ua; msb = {i}(hi); lsb = {i}(lo); }}",
                below("a", &format!("{i}(0)")),
                below("b", &format!("{i}(0)"))
            ),
            _ => writeln!(h, "{f} effectc_modf({f} x, out {f} whole) {{ whole = trunc(x); return x - whole; }}"),
        };
    }
}

/// `frexp`: the exponent field of the float's bits (a denormal scaled up by 2^64 first),
/// the significand put back between 0.5 and 1 with the sign kept; 0 for 0.
fn frexp(h: &mut String) {
    h.push_str(
        "float effectc_frexp(float x, out int e) { if (x == 0.0) { e = 0; return x; } float y = x; int bias = 0; \
         if (abs(x) < 1.17549435e-38) { y = x * 18446744073709551616.0; bias = 64; } uint b = floatBitsToUint(y); \
         e = int((b >> 23u) & 0xFFu) - 126 - bias; return uintBitsToFloat((b & 0x807FFFFFu) | 0x3F000000u); }\n",
    );
    for n in 2..=4 {
        // One local per component: naga's SPIR-V writer fails on an array element passed
        // as an `out` argument.
        let locals: Vec<String> = (0..n).map(|k| format!("e{k}")).collect();
        let parts: Vec<String> = (0..n).map(|k| format!("effectc_frexp(x[{k}], e{k})")).collect();
        let _ = writeln!(
            h,
            "vec{n} effectc_frexp(vec{n} x, out ivec{n} e) {{ int {}; vec{n} r = vec{n}({}); e = ivec{n}({}); return r; }}",
            locals.join(", "),
            parts.join(", "),
            locals.join(", ")
        );
    }
}
