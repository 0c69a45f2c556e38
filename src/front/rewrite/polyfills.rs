//! Built-in functions naga cannot take or its back ends cannot write (its GLSL front has
//! no `matrixCompMult`; its WGSL writer has no `isnan`, `isinf` or `outerProduct`), called
//! under effectc names and defined in the header as overloads for every size:
//! `isnan`/`isinf` from the float's bits (no comparison a compiler could fold away),
//! `outerProduct` and `matrixCompMult` column by column. (`inverse` stays naga's: its
//! WGSL writer has it, and a definition of our own would hide the normal-matrix facts the
//! hazard analysis reads from it.)

use std::fmt::Write;

use super::Ctx;

/// The built-ins replaced, with the name they are called by.
const REPLACED: [(&str, &str); 4] = [
    ("isnan", "effectc_isnan"),
    ("isinf", "effectc_isinf"),
    ("outerProduct", "effectc_outerProduct"),
    ("matrixCompMult", "effectc_matrixCompMult"),
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
            if !self.polyfills.contains(builtin) {
                self.polyfills.push(builtin);
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
