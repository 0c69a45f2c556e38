//! Structural fuzzing: the input is not GLSL but a recipe (bytes decoded by hand below) that
//! builds a deep and wide fragment stage: nested `if`/`for`/`while`/`do`/`switch` blocks and
//! parentheses (depth up to 1,500), long sums (12,000 terms), chains of functions (2,000),
//! many statements in `main` (20,000), doubling macros (24 levels), many uniforms and struct
//! or block members, arrays of up to 10^8 elements. The whole `check` of the program runs on
//! a thread with effectc's analysis stack ([`ANALYSIS_STACK`]), as the binary runs it; the
//! diagnostics render (human and JSON). What must hold:
//!
//! - no panic, no stack overflow, no timeout;
//! - a macro that expands past 2^20 tokens, a macro used in a statement that then passes
//!   200,000 tokens, a stage past `stage-tokens` (macros expanded), or a uniform or global
//!   array of more than 65,536 elements, is refused with E0107 (an error; the limits are
//!   `Limits::DEFAULT`);
//! - a stage built only from legal parts, within every limit and as deep as glslang's parser
//!   takes, has no error diagnostic.
//!
//! Recipe: byte 0 holds flags (bit 0: add a vertex stage, bit 1: `#version 330 core`), then
//! up to [`MAX_PARTS`] parts, each an opcode byte and its parameters (see [`Part::read`]);
//! bytes past the end read as 0. `EFFECTC_FUZZ_DUMP=path` writes the generated stage there
//! and what `check` said to `path.txt`.
//!
//! `EFFECTC_FUZZ_SKIP_KNOWN_SLOW=1` keeps recipes away from shapes already known to take
//! exponential or cubic time (so a run finds something new rather than them again): at
//! most 3 nested loops (deeper levels become `if`s), fans of at most 16 functions, and at
//! most 256 functions defined after their callers.
#![no_main]
use std::fmt::Write as _;

use effectc::check::{check_stages, ANALYSIS_STACK};
use effectc::diag::{render_human, render_json, Code, Diagnostic, Files};
use effectc::front::program::FrontOptions;
use effectc::limits::Limits;
use effectc::stage::StageKind;
use libfuzzer_sys::fuzz_target;

const MAX_PARTS: usize = 12;
/// Budgets over the whole recipe, so every input stays within the sizes named above.
const MAX_DEPTH: u64 = 1_500;
const MAX_TERMS: u64 = 12_000;
const MAX_FUNCTIONS: u64 = 2_000;
const MAX_STATEMENTS: u64 = 20_000;
const MAX_UNIFORMS: u64 = 5_000;
const MAX_MEMBERS: u64 = 2_000;
const MAX_MACRO_LEVELS: u64 = 24;
const MAX_ARRAY: u64 = 100_000_000;
/// effectc's default limits (src/limits.rs), which the recipes straddle.
const MACRO_TOKEN_LIMIT: u64 = Limits::DEFAULT.macro_tokens;
const ARRAY_ELEMENT_LIMIT: u64 = Limits::DEFAULT.array_elements;
/// glslang's bison stack holds 10,000 entries: a legal stage deeper than this estimate (in
/// parser stack entries, see [`Gen::stack`]) may be refused by glslang with E0105, which
/// is a documented limit, not a finding.
const GLSLANG_STACK_BUDGET: u64 = 8_000;

/// With `EFFECTC_FUZZ_SKIP_KNOWN_SLOW`: nested loops (the hazard analysis walks each loop's
/// body once per round, so its time is exponential in loop depth), functions in a fan (it
/// walks each call's body anew: 2^n paths), functions defined after their callers
/// (glslang's `checkCallGraphBodies`, cubic).
const KNOWN_SLOW_LOOPS: u64 = 3;
const KNOWN_SLOW_FAN: u64 = 16;
const KNOWN_SLOW_REVERSED: u64 = 256;

/// Bytes read in order; past the end, zeros.
struct Reader<'a>(&'a [u8]);

impl Reader<'_> {
    fn u8(&mut self) -> u8 {
        match self.0.split_first() {
            Some((b, rest)) => {
                self.0 = rest;
                *b
            }
            None => 0,
        }
    }
    fn u16(&mut self) -> u16 {
        u16::from_le_bytes([self.u8(), self.u8()])
    }
    fn u32(&mut self) -> u32 {
        u32::from_le_bytes([self.u8(), self.u8(), self.u8(), self.u8()])
    }
    /// A count up to `max`: a class byte (small, medium, up to `max`) and two bytes.
    fn count(&mut self, max: u64) -> u64 {
        let class = self.u8();
        let raw = u64::from(self.u16());
        let top = match class % 4 {
            0 => 16,
            1 => 256,
            _ => max,
        };
        raw % (top.min(max) + 1)
    }
}

#[derive(Debug)]
enum Part {
    /// `depth` nested blocks; `first`/`step` pick the block kind at each level. Later parts
    /// go inside the innermost block.
    Nest { depth: u64, first: u8, step: u8 },
    /// One assignment of `depth` nested wrappers (parentheses, calls, `?:`, swizzles).
    Parens { depth: u64, first: u8, step: u8 },
    /// One statement `x += t0 op t1 op …` of `terms` terms.
    Sum { terms: u64, first: u8, step: u8 },
    /// `count` functions calling each other (`shape`: chain, fan, star, prototypes, inout).
    Functions { count: u64, shape: u8 },
    /// `count` statements in the current block.
    Statements { count: u64, kind: u8 },
    /// `#define M1 M0+M0` … up to `levels`, each level `width` copies of the one below.
    Macro { levels: u64, width: u64, reverse: bool, used: bool },
    /// `count` uniforms of one type, declared one by one or in one declaration, all read.
    Uniforms { count: u64, ty: u8, one_declaration: bool },
    /// A struct (or uniform block) of `members` members nested `nesting` deep.
    Struct { members: u64, nesting: u64, form: u8 },
    /// An array of `len` elements (`dims` 2: `w[len][2]`, not GLSL 3.30).
    Array { len: u64, ty: u8, storage: u8, dims: u8 },
    /// A few tokens from a small alphabet, in `main` or among the globals (not legal).
    Wild { tokens: Vec<u8>, global: bool },
}

impl Part {
    fn read(r: &mut Reader) -> Part {
        match r.u8() % 10 {
            0 => Part::Nest { depth: r.count(MAX_DEPTH), first: r.u8(), step: r.u8() },
            1 => Part::Parens { depth: r.count(MAX_DEPTH), first: r.u8(), step: r.u8() },
            2 => Part::Sum { terms: r.count(MAX_TERMS), first: r.u8(), step: r.u8() },
            3 => Part::Functions { count: r.count(MAX_FUNCTIONS), shape: r.u8() },
            4 => Part::Statements { count: r.count(MAX_STATEMENTS), kind: r.u8() },
            5 => {
                let (levels, b) = (u64::from(r.u8()) % (MAX_MACRO_LEVELS + 1), r.u8());
                Part::Macro { levels, width: 2 + u64::from(b & 3) % 3, reverse: b & 4 != 0, used: b & 8 != 0 }
            }
            6 => {
                let (count, b) = (r.count(MAX_UNIFORMS), r.u8());
                Part::Uniforms { count, ty: b & 7, one_declaration: b & 8 != 0 }
            }
            7 => Part::Struct { members: r.count(MAX_MEMBERS), nesting: u64::from(r.u8() % 33), form: r.u8() },
            8 => {
                let class = r.u8();
                let raw = u64::from(r.u32());
                let len = match class % 4 {
                    0 => 1 + raw % 16,
                    // Around the limit: 65,536 - 16 … 65,536 + 16.
                    1 => ARRAY_ELEMENT_LIMIT - 16 + raw % 33,
                    2 => 1 + raw % (4 * ARRAY_ELEMENT_LIMIT),
                    _ => 1 + raw % MAX_ARRAY,
                };
                Part::Array { len, ty: r.u8(), storage: r.u8(), dims: 1 + (class >> 2) % 2 }
            }
            _ => {
                let n = r.u8() % 32;
                let global = n & 1 != 0;
                Part::Wild { tokens: (0..n).map(|_| r.u8()).collect(), global }
            }
        }
    }
}

/// The stage being built, and what it must yield.
#[derive(Default)]
struct Gen {
    defines: String,
    globals: String,
    body: String,
    closers: Vec<String>,
    /// Budgets spent.
    depth: u64,
    terms: u64,
    functions: u64,
    statements: u64,
    uniforms: u64,
    members: u64,
    /// glslang parser stack entries the open blocks take, and the deepest statement needs
    /// (an estimate).
    nest_stack: u64,
    stack: u64,
    /// Only legal GLSL 3.30 was emitted.
    legal: bool,
    /// Why E0107 must be reported (a macro or an array past effectc's limits).
    limit: Option<String>,
    /// A `uniform`/global array past the limit: refused once effectc's parser reads the stage.
    array_limit: Option<String>,
    /// Tokens the macros used add to the stage's text when expanded.
    expanded: u64,
    /// `EFFECTC_FUZZ_SKIP_KNOWN_SLOW` is set; loops opened so far.
    skip_known_slow: bool,
    loops: u64,
}

fn take(spent: &mut u64, max: u64, want: u64) -> u64 {
    let n = want.min(max - *spent);
    *spent += n;
    n
}

const U: [&str; 4] = ["u0", "u1", "u2", "u3"];

impl Gen {
    fn part(&mut self, p: usize, part: &Part) {
        match *part {
            Part::Nest { depth, first, step } => self.nest(p, depth, first, step),
            Part::Parens { depth, first, step } => self.parens(depth, first, step),
            Part::Sum { terms, first, step } => self.sum(terms, first, step),
            Part::Functions { count, shape } => self.functions(p, count, shape),
            Part::Statements { count, kind } => self.statements(p, count, kind),
            Part::Macro { levels, width, reverse, used } => self.macros(p, levels, width, reverse, used),
            Part::Uniforms { count, ty, one_declaration } => self.uniform_list(p, count, ty, one_declaration),
            Part::Struct { members, nesting, form } => self.structure(p, members, nesting, form),
            Part::Array { len, ty, storage, dims } => self.array(p, len, ty, storage, dims),
            Part::Wild { ref tokens, global } => self.wild(tokens, global),
        }
    }

    fn nest(&mut self, p: usize, depth: u64, first: u8, step: u8) {
        let depth = take(&mut self.depth, MAX_DEPTH, depth);
        for i in 0..depth {
            let u = U[(i % 4) as usize];
            let mut kind = (u64::from(first) + i * u64::from(step)) % 6;
            if matches!(kind, 2..=4) {
                if self.skip_known_slow && self.loops >= KNOWN_SLOW_LOOPS {
                    kind = 0;
                } else {
                    self.loops += 1;
                }
            }
            let (open, close, cost) = match kind {
                0 => (format!("if (x > {i}.0) {{\n"), "}\n".to_string(), 7),
                1 => (format!("if (x > {u}) {{ x += 1.0; }} else {{\n"), "}\n".to_string(), 9),
                2 => (format!("for (int i{p}_{i} = 0; i{p}_{i} < 2; ++i{p}_{i}) {{\n"), "}\n".to_string(), 9),
                3 => (format!("while (x < {i}.0) {{ x += 1.0;\n"), "}\n".to_string(), 7),
                4 => ("do {\n".to_string(), format!("}} while (x < {u});\n"), 5),
                _ => ("switch (int(x)) { case 0: {\n".to_string(), "} break; default: x += 1.0; break; }\n".to_string(), 10),
            };
            self.body.push_str(&open);
            self.closers.push(close);
            self.nest_stack += cost;
        }
    }

    fn parens(&mut self, depth: u64, first: u8, step: u8) {
        let depth = take(&mut self.depth, MAX_DEPTH, depth);
        let (mut open, mut close) = (String::new(), Vec::new());
        let mut cost = 0;
        for i in 0..depth {
            let u = U[(i % 4) as usize];
            let (o, c, k) = match (u64::from(first) + i * u64::from(step)) % 6 {
                0 => (format!("({u} + "), ")".to_string(), 3),
                1 => (format!("({u} * "), ")".to_string(), 3),
                2 => ("abs(".to_string(), ")".to_string(), 3),
                3 => ("-(".to_string(), ")".to_string(), 3),
                4 => (format!("(x > {u} ? "), format!(" : {u})"), 6),
                _ => ("vec2(".to_string(), ", 1.0).x".to_string(), 3),
            };
            open.push_str(&o);
            close.push(c);
            cost += k;
        }
        close.reverse();
        let _ = writeln!(self.body, "x = {open}x{};", close.concat());
        self.stack = self.stack.max(self.nest_stack + cost);
    }

    fn sum(&mut self, terms: u64, first: u8, step: u8) {
        let terms = take(&mut self.terms, MAX_TERMS, terms);
        if terms == 0 {
            return;
        }
        let mut s = String::from("x += ");
        for i in 0..terms {
            if i > 0 {
                s.push_str([" + ", " - ", " * ", " / "][((u64::from(first) + i * u64::from(step)) % 4) as usize]);
            }
            s.push_str(if i % 5 == 4 { "1.5" } else { U[(i % 4) as usize] });
        }
        s.push_str(";\n");
        self.body.push_str(&s);
    }

    fn functions(&mut self, p: usize, count: u64, shape: u8) {
        let mut n = take(&mut self.functions, MAX_FUNCTIONS, count);
        if self.skip_known_slow {
            n = n.min(match shape % 5 {
                1 => KNOWN_SLOW_FAN,
                3 => KNOWN_SLOW_REVERSED,
                _ => n,
            });
        }
        if n == 0 {
            return;
        }
        let f = |k: u64| format!("p{p}f{k}");
        let u = |k: u64| U[(k % 4) as usize];
        match shape % 5 {
            // A chain: f_k calls f_{k-1}.
            0 => {
                for k in 0..n {
                    let call = if k == 0 { "a".to_string() } else { format!("{}(a)", f(k - 1)) };
                    let _ = writeln!(self.globals, "float {}(float a) {{ return {call} + {}; }}", f(k), u(k));
                }
                let _ = writeln!(self.body, "x += {}(x);", f(n - 1));
            }
            // A fan: f_k calls f_{k-1} and f_{k-2} (2^n paths through the call graph).
            1 => {
                for k in 0..n {
                    let body = match k {
                        0 => format!("a * {}", u(k)),
                        1 => format!("{}(a) + {}", f(0), u(k)),
                        _ => format!("{}(a) + {}(a * {})", f(k - 1), f(k - 2), u(k)),
                    };
                    let _ = writeln!(self.globals, "float {}(float a) {{ return {body}; }}", f(k));
                }
                let _ = writeln!(self.body, "x += {}(x);", f(n - 1));
            }
            // A star: main calls every one.
            2 => {
                for k in 0..n {
                    let _ = writeln!(self.globals, "float {}(float a) {{ return a * {} + {k}.0; }}", f(k), u(k));
                }
                let calls: Vec<String> = (0..n).map(|k| format!("{}(x)", f(k))).collect();
                self.terms += n;
                let _ = writeln!(self.body, "x += {};", calls.join(" + "));
            }
            // Prototypes first, definitions in reverse order.
            3 => {
                for k in 0..n {
                    let _ = writeln!(self.globals, "float {}(float a);", f(k));
                }
                for k in (0..n).rev() {
                    let call = if k == 0 { "a".to_string() } else { format!("{}(a * 0.5)", f(k - 1)) };
                    let _ = writeln!(self.globals, "float {}(float a) {{ return {call} - {}; }}", f(k), u(k));
                }
                let _ = writeln!(self.body, "x += {}(x);", f(n - 1));
            }
            // `inout` parameters, void functions.
            _ => {
                for k in 0..n {
                    let call = if k == 0 { String::new() } else { format!("{}(a); ", f(k - 1)) };
                    let _ = writeln!(self.globals, "void {}(inout float a) {{ {call}a += {}; }}", f(k), u(k));
                }
                let _ = writeln!(self.body, "{}(x);", f(n - 1));
            }
        }
    }

    fn statements(&mut self, p: usize, count: u64, kind: u8) {
        let n = take(&mut self.statements, MAX_STATEMENTS, count);
        let u = |k: u64| U[(k % 4) as usize];
        let b = &mut self.body;
        for i in 0..n {
            let _ = match kind % 6 {
                0 => writeln!(b, "x += {};", u(i)),
                1 if i == 0 => writeln!(b, "float p{p}t0 = x;"),
                1 => writeln!(b, "float p{p}t{i} = p{p}t{} * {} + 1.0;", i - 1, u(i)),
                2 => writeln!(b, "x = x * {} + 0.5;", u(i)),
                3 => writeln!(b, "if (x > {}) x -= {};", u(i), u(i + 1)),
                4 => writeln!(b, "{{ x += {}; }}", u(i)),
                _ => writeln!(b, "vec4 p{p}v{i} = vec4(x, u0, u1, u2); x += p{p}v{i}.y;"),
            };
        }
        if kind % 6 == 1 && n > 0 {
            let _ = writeln!(b, "x += p{p}t{};", n - 1);
        }
    }

    fn macros(&mut self, p: usize, levels: u64, width: u64, reverse: bool, used: bool) {
        let name = |k: u64| format!("P{p}M{k}");
        let mut lines = vec![format!("#define {} u0\n", name(0))];
        let (mut size, mut largest) = (1u64, 1u64);
        for k in 1..=levels {
            let body = vec![name(k - 1); width as usize].join("+");
            lines.push(format!("#define {} {body}\n", name(k)));
            size = size.saturating_mul(width).saturating_add(width - 1);
            largest = largest.max(size);
        }
        if reverse {
            lines.reverse();
        }
        self.defines.push_str(&lines.concat());
        if largest > MACRO_TOKEN_LIMIT {
            self.limit.get_or_insert(format!("macro {} expands to {largest} tokens", name(levels)));
        } else if used {
            // `x += M;`: three tokens and the macro's expansion, which the statement limit
            // counts (a 2^19-term sum in one word overflowed naga's recursive lowering).
            let _ = writeln!(self.body, "x += {};", name(levels));
            self.expanded += largest - 1;
            if largest + 3 > Limits::DEFAULT.statement_tokens {
                self.limit.get_or_insert(format!("`x += {};` is {} tokens, macro expanded", name(levels), largest + 3));
            }
        }
    }

    fn uniform_list(&mut self, p: usize, count: u64, ty: u8, one: bool) {
        let n = take(&mut self.uniforms, MAX_UNIFORMS, count);
        if n == 0 {
            return;
        }
        let (t, read) = [
            ("float", ""),
            ("vec2", ".y"),
            ("vec3", ".z"),
            ("vec4", ".w"),
            ("mat2", "[1].x"),
            ("mat4", "[3].w"),
            ("int", ""),
            ("bool", ""),
        ][usize::from(ty % 8)];
        let names: Vec<String> = (0..n).map(|i| format!("p{p}v{i}")).collect();
        if one {
            let _ = writeln!(self.globals, "uniform {t} {};", names.join(", "));
        } else {
            for v in &names {
                let _ = writeln!(self.globals, "uniform {t} {v};");
            }
        }
        let reads: Vec<String> = names
            .iter()
            .map(|v| match t {
                "int" => format!("float({v})"),
                "bool" => format!("({v} ? 1.0 : 0.0)"),
                _ => format!("{v}{read}"),
            })
            .collect();
        self.terms += n;
        let _ = writeln!(self.body, "x += {};", reads.join(" + "));
    }

    fn structure(&mut self, p: usize, members: u64, nesting: u64, form: u8) {
        let n = take(&mut self.members, MAX_MEMBERS, members).max(1);
        let types = ["float", "vec2", "vec3", "vec4", "float[2]"];
        let value = ["1.0", "vec2(1.0)", "vec3(1.0)", "vec4(1.0)", "float[2](1.0, 2.0)"];
        let read = ["", ".x", ".y", ".z", "[1]"];
        let kind = |i: u64| (i + u64::from(form >> 2)) as usize % types.len();
        let decl = |i: u64| {
            let k = kind(i);
            match types[k] {
                "float[2]" => format!("float m{i}[2];"),
                t => format!("{t} m{i};"),
            }
        };
        let reads = |prefix: &str| -> String {
            (0..n).step_by(((n / 64) as usize).max(1)).map(|i| format!("{prefix}m{i}{}", read[kind(i)])).collect::<Vec<_>>().join(" + ")
        };
        match form % 5 {
            // A uniform block of `n` members (blocks do not nest in 3.30).
            0 => {
                let fields: Vec<String> = (0..n).map(decl).collect();
                let _ = writeln!(self.globals, "uniform P{p}B {{\n{}\n}} p{p}b;", fields.join("\n"));
                let _ = writeln!(self.body, "x += {};", reads(&format!("p{p}b.")));
            }
            // A struct nested `nesting` deep: a uniform, a uniform array, a global with an
            // initializer, or a uniform with one.
            f => {
                let fields: Vec<String> = (0..n).map(decl).collect();
                let _ = writeln!(self.globals, "struct P{p}S0 {{\n{}\n}};", fields.join("\n"));
                let mut init: String = format!("P{p}S0({})", (0..n).map(|i| value[kind(i)]).collect::<Vec<_>>().join(", "));
                for d in 1..=nesting {
                    let _ = writeln!(self.globals, "struct P{p}S{d} {{ P{p}S{} inner; float k; }};", d - 1);
                    init = format!("P{p}S{d}({init}, {d}.0)");
                }
                let path = "inner.".repeat(nesting as usize);
                match f {
                    1 => {
                        let _ = writeln!(self.globals, "uniform P{p}S{nesting} p{p}s;");
                        let _ = writeln!(self.body, "x += {};", reads(&format!("p{p}s.{path}")));
                    }
                    2 => {
                        let _ = writeln!(self.globals, "uniform P{p}S{nesting} p{p}s[3];");
                        let _ = writeln!(self.body, "x += {};", reads(&format!("p{p}s[2].{path}")));
                    }
                    3 => {
                        let _ = writeln!(self.globals, "P{p}S{nesting} p{p}s = {init};");
                        let _ = writeln!(self.body, "x += {};", reads(&format!("p{p}s.{path}")));
                    }
                    _ => {
                        let _ = writeln!(self.globals, "uniform P{p}S{nesting} p{p}s = {init};");
                        let _ = writeln!(self.body, "x += {};", reads(&format!("p{p}s.{path}")));
                    }
                }
            }
        }
    }

    fn array(&mut self, p: usize, len: u64, ty: u8, storage: u8, dims: u8) {
        let (t, read) = [("float", ""), ("vec4", ".z"), ("int", ""), ("mat2", "[0].y")][usize::from(ty % 4)];
        let value = |e: String| if t == "int" { format!("float({e})") } else { format!("{e}{read}") };
        let w = format!("p{p}w");
        let size = if dims == 2 { format!("[{len}][2]") } else { format!("[{len}]") };
        let index = |i: String| if dims == 2 { format!("{w}[{i}][1]") } else { format!("{w}[{i}]") };
        let elements = len.saturating_mul(u64::from(dims));
        if dims == 2 {
            // Arrays of arrays are GLSL 4.30.
            self.legal = false;
        }
        match storage % 3 {
            0 | 1 => {
                let q = if storage % 3 == 0 { "uniform " } else { "" };
                let _ = writeln!(self.globals, "{q}{t} {w}{size};");
                if elements > ARRAY_ELEMENT_LIMIT {
                    self.array_limit.get_or_insert(format!("{q}{t} {w}{size}: {elements} elements"));
                }
            }
            // A local array: no limit applies, nothing may be modelled per element.
            _ => {
                let _ = writeln!(self.body, "{t} {w}{size};");
                if len <= 16 && dims == 1 {
                    let one = match t {
                        "int" => "1",
                        "float" => "u1",
                        "vec4" => "vec4(u1)",
                        _ => "mat2(u1)",
                    };
                    let _ = writeln!(self.body, "for (int i = 0; i < {len}; ++i) {{ {w}[i] = {one}; }}");
                }
            }
        }
        let _ = writeln!(self.body, "x += {} + {};", value(index(format!("{}", len - 1))), value(index(format!("int(abs(x)) % {len}"))));
    }

    fn wild(&mut self, tokens: &[u8], global: bool) {
        const ALPHABET: [&str; 24] = [
            "(", ")", "{", "}", ";", "+", "*", "x", "u0", "if", "else", "for", "1.0", ",", "[", "]", "=", ".", "float", "return", "while",
            "?", ":", "\n#",
        ];
        self.legal = false;
        let text: Vec<&str> = tokens.iter().map(|b| ALPHABET[usize::from(*b) % ALPHABET.len()]).collect();
        let out = if global { &mut self.globals } else { &mut self.body };
        out.push_str(&text.join(" "));
        out.push('\n');
    }

    fn stage(&self, core: bool) -> String {
        let mut s = format!("#version 330{}\nuniform float u0, u1, u2, u3;\nout vec4 c;\n", if core { " core" } else { "" });
        s.push_str(&self.defines);
        s.push_str(&self.globals);
        s.push_str("void main() {\nfloat x = u0;\n");
        s.push_str(&self.body);
        for c in self.closers.iter().rev() {
            s.push_str(c);
        }
        s.push_str("c = vec4(x);\n}\n");
        s
    }
}

/// Tokens of `text` outside directives, counted as effectc's limits count them (words,
/// numbers and `.` runs; any other character one token).
fn tokens(text: &str) -> u64 {
    let mut n = 0;
    for line in text.lines().filter(|l| !l.trim_start().starts_with('#')) {
        let mut word = false;
        for c in line.chars() {
            let w = c.is_alphanumeric() || c == '_' || c == '.';
            if !c.is_whitespace() && !(w && word) {
                n += 1;
            }
            word = w;
        }
    }
    n
}

/// What the check said, for the assertions.
struct Said {
    errors: Vec<String>,
    stage_limit: bool,
}

fn check(stages: Vec<(&'static str, String, StageKind)>, dump: Option<std::ffi::OsString>) -> Said {
    let mut files = Files::new();
    let ids: Vec<_> = stages.into_iter().map(|(name, text, kind)| (files.add(name, text), kind)).collect();
    let (_, diags) = check_stages(&files, &ids, None, FrontOptions::default());
    let human = render_human(&diags, &files, false);
    let json = render_json(&diags, &files);
    if let Some(mut path) = dump {
        path.push(".txt");
        let _ = std::fs::write(path, &human);
    }
    assert!(diags.is_empty() || (!human.is_empty() && json.contains("\"code\"")), "diagnostics that do not render");
    let errors: Vec<String> = diags.iter().filter(|d| d.is_error()).map(|d| format!("{}: {}", d.code, d.message)).collect();
    let stage_limit = diags.iter().any(|d: &Diagnostic| d.code == Code::StageLimit && d.code.to_string() == "E0107" && d.is_error());
    Said { errors, stage_limit }
}

fuzz_target!(|data: &[u8]| {
    let mut r = Reader(data);
    let flags = r.u8();
    let mut parts = Vec::new();
    while !r.0.is_empty() && parts.len() < MAX_PARTS {
        parts.push(Part::read(&mut r));
    }
    let skip_known_slow = std::env::var_os("EFFECTC_FUZZ_SKIP_KNOWN_SLOW").is_some();
    let mut g = Gen { legal: true, skip_known_slow, ..Gen::default() };
    for (p, part) in parts.iter().enumerate() {
        g.part(p, part);
    }
    let frag = g.stage(flags & 2 != 0);
    let stage_tokens = tokens(&frag) + g.expanded;
    let dump = std::env::var_os("EFFECTC_FUZZ_DUMP");
    if let Some(path) = &dump {
        let _ = std::fs::write(path, &frag);
    }
    let mut stages = vec![("fuzz.frag", frag, StageKind::Fragment)];
    if flags & 1 != 0 {
        stages.push(("fuzz.vert", "#version 330\nin vec4 p;\nvoid main() { gl_Position = p; }\n".to_string(), StageKind::Vertex));
    }
    // The check runs as `effectc` runs it: on a thread with the analysis stack.
    let worker =
        std::thread::Builder::new().stack_size(ANALYSIS_STACK).spawn(move || check(stages, dump)).expect("spawn the analysis thread");
    let said = worker.join().unwrap_or_else(|e| std::panic::resume_unwind(e));
    // The stage's tokens, macros expanded, against `stage-tokens` (5% either side of the
    // limit is left unasserted: the count here is an estimate).
    let most = Limits::DEFAULT.stage_tokens;
    if stage_tokens > most + most / 20 {
        g.limit.get_or_insert(format!("the stage is {stage_tokens} tokens"));
    }
    let near_stage_limit = stage_tokens > most - most / 20;
    let limit = g.limit.clone().or(if g.legal { g.array_limit.clone() } else { None });
    if let Some(why) = &limit {
        assert!(said.stage_limit, "{why}: no E0107 (errors: {:?}; parts: {parts:?})", said.errors);
    }
    if g.legal && limit.is_none() && g.array_limit.is_none() && !near_stage_limit && g.stack.max(g.nest_stack) <= GLSLANG_STACK_BUDGET {
        assert!(said.errors.is_empty(), "a legal stage within the limits has errors: {:?} (parts: {parts:?})", first(&said.errors));
    }
});

fn first(errors: &[String]) -> Vec<String> {
    errors.iter().take(3).map(|e| e.chars().take(300).collect()).collect()
}
