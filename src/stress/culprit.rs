//! Locating the first non-finite value: the vertex and fragment stages are instrumented so
//! that every float arithmetic or builtin result is tested as it is computed, and each
//! invocation counts, in a storage buffer, the number of the first test that failed in it.
//!
//! A value fails when it is NaN or ±Inf (exponent bits all ones, tested on the bits so no
//! compiler can assume NaN away), and a `normalize` also fails when its argument has zero
//! length (undefined in GLSL; some drivers, llvmpipe among them, return 0 rather than NaN).
//! Probes are numbered in execution order within each function; an invocation reports the
//! first probe that fired, so its number names the expression where the trouble began, not
//! the ones it spread to.
//!
//! The colour outputs are left alone: an instrumented frame is the plain frame, so one
//! render gives both the pixels and the culprits, and a pass of a multi-pass effect still
//! feeds the next. The counts live in one `array<atomic<u32>>` bound at a free binding
//! ([`COUNTS_BUFFER`]): a region of `probes + 1` slots per instrumented entry point, slot 0
//! counting the invocations where every probe passed.

use naga::{
    BinaryOperator as B, Block, Expression, Function, Handle, Literal, MathFunction, Module, RelationalFunction, ScalarKind, Span,
    Statement, TypeInner,
};

use crate::back::Translation;
use crate::front::program::CompiledProgram;
use crate::manifest::Effect;
use crate::stage::StageKind;
use crate::stress::ir::{
    count_at_every_exit, counts_buffer, entries, free_binding, map_blocks, private_u32, reachable, revalidate, stage_texts, types_of,
};

pub use crate::stress::ir::COUNTS_BUFFER;

/// One instrumented expression.
#[derive(Debug, Clone)]
pub struct Probe {
    /// Its slot in every region of the counts buffer (from 1).
    pub id: u32,
    /// Span in the text of `stage` (a helper both stages share keeps the vertex stage's).
    pub span: Span,
    pub stage: StageKind,
    /// What it computes (`division`, `normalize`, …).
    pub what: String,
}

/// What [`instrument`] did to a module.
#[derive(Debug, Clone)]
pub struct Instrumented {
    pub probes: Vec<Probe>,
    /// The instrumented entry points and the first slot of their region, in module order.
    pub regions: Vec<(StageKind, u32)>,
    /// Slots of the counts buffer (regions × (probes + 1)).
    pub slots: u32,
    /// Where the counts buffer is bound (group, binding).
    pub binding: (u32, u32),
}

/// What one instrumented entry point counted: per probe, the invocations where it fired first.
#[derive(Debug, Clone, PartialEq)]
pub struct StageCounts {
    pub stage: StageKind,
    /// Invocations where every probe passed.
    pub clean: u64,
    /// `(probe id, invocations)` for every probe that fired first somewhere.
    pub first: Vec<(u32, u64)>,
}

impl StageCounts {
    /// Invocations with some non-finite intermediate value.
    pub fn bad(&self) -> u64 {
        self.first.iter().map(|(_, n)| n).sum()
    }
}

impl Instrumented {
    /// Splits the counts buffer into its regions.
    pub fn read(&self, counts: &[u32]) -> Vec<StageCounts> {
        let width = self.probes.len() + 1;
        self.regions
            .iter()
            .filter_map(|&(stage, base)| {
                let region = counts.get(base as usize..base as usize + width)?;
                let first = region.iter().enumerate().skip(1).filter(|(_, n)| **n > 0).map(|(id, n)| (id as u32, u64::from(*n))).collect();
                Some(StageCounts { stage, clean: u64::from(region[0]), first })
            })
            .collect()
    }

    pub fn probe(&self, id: u32) -> Option<&Probe> {
        self.probes.iter().find(|p| p.id == id)
    }
}

/// Instruments a translation: its fragment stage, and its vertex stage too with `vertex`
/// (the device must allow storage writes in vertex shaders). `program` and `effect` are
/// what `t` was translated from; the module is validated and reflected again, so the
/// renderer binds the counts buffer like any other storage buffer.
pub fn instrument_translation(
    t: &mut Translation,
    program: &CompiledProgram,
    effect: Option<&Effect>,
    vertex: bool,
) -> Result<Instrumented, String> {
    let stages: &[StageKind] = if vertex { &[StageKind::Vertex, StageKind::Fragment] } else { &[StageKind::Fragment] };
    let texts = stage_texts(program);
    let binding = free_binding(&t.module);
    let instrumented = instrument(&mut t.module, &t.info, &texts, stages, binding)?;
    revalidate(t, program, effect)?;
    Ok(instrumented)
}

/// Instruments the entry points of `stages` in `module` (validated, `info` its analysis)
/// and every function they call. `texts` are the stage texts the spans index. The counts
/// buffer is bound at `binding`.
pub fn instrument(
    module: &mut Module,
    info: &naga::valid::ModuleInfo,
    texts: &[(StageKind, &str)],
    stages: &[StageKind],
    binding: (u32, u32),
) -> Result<Instrumented, String> {
    let flag = private_u32(module, "effectc_first_bad");
    let text_of = |stage: StageKind| texts.iter().find(|(s, _)| *s == stage).map(|(_, t)| *t).ok_or(format!("no {stage:?} text"));
    let entries = entries(module, stages);
    if entries.is_empty() {
        return Err("the program has no vertex or fragment stage to instrument".into());
    }
    let mut probes = Vec::new();
    let mut done: Vec<Handle<Function>> = Vec::new();
    for &(entry, stage) in &entries {
        let text = text_of(stage)?;
        for f in reachable(module, &module.entry_points[entry].function) {
            if done.contains(&f) {
                continue;
            }
            done.push(f);
            let types = types_of(module, &info[f], module.functions[f].expressions.iter().map(|(h, _)| h));
            probe_function(&mut module.functions[f], &types, flag, stage, text, &mut probes);
        }
        let handles: Vec<_> = module.entry_points[entry].function.expressions.iter().map(|(h, _)| h).collect();
        let types = types_of(module, info.get_entry_point(entry), handles.into_iter());
        probe_function(&mut module.entry_points[entry].function, &types, flag, stage, text, &mut probes);
    }
    let width = probes.len() as u32 + 1;
    let slots = width * entries.len() as u32;
    let counts = counts_buffer(module, slots, binding)?;
    let mut regions = Vec::new();
    for (k, &(entry, stage)) in entries.iter().enumerate() {
        let base = k as u32 * width;
        regions.push((stage, base));
        count_at_every_exit(module, entry, &|fun, out| push_count(fun, out, flag, counts, base));
    }
    Ok(Instrumented { probes, regions, slots, binding })
}

/// Where probes are being placed.
struct Site<'a> {
    types: &'a [TypeInner],
    flag: Handle<naga::GlobalVariable>,
    stage: StageKind,
    text: &'a str,
}

fn probe_function(
    fun: &mut Function,
    types: &[TypeInner],
    flag: Handle<naga::GlobalVariable>,
    stage: StageKind,
    text: &str,
    probes: &mut Vec<Probe>,
) {
    let body = std::mem::take(&mut fun.body);
    let site = Site { types, flag, stage, text };
    fun.body = probe_block(fun, body, &site, probes);
}

fn probe_block(fun: &mut Function, block: Block, site: &Site<'_>, probes: &mut Vec<Probe>) -> Block {
    let mut out = Block::with_capacity(block.len());
    for (stmt, span) in block.span_into_iter() {
        let stmt = map_blocks(stmt, &mut |b| probe_block(fun, b, site, probes));
        let emitted = if let Statement::Emit(range) = &stmt { range.clone().collect::<Vec<_>>() } else { Vec::new() };
        out.push(stmt, span);
        for h in emitted {
            let ty = site.types.get(h.index());
            let Some(what) = candidate(&fun.expressions[h], ty) else { continue };
            let id = probes.len() as u32 + 1;
            let span = crate::check::hazards::eval::expression_span(fun, h, site.text);
            probes.push(Probe { id, span, stage: site.stage, what });
            let (emit, check) = build_check(fun, h, ty, site.flag, id);
            out.push(emit, Span::UNDEFINED);
            out.push(check, Span::UNDEFINED);
        }
    }
    out
}

/// Expressions worth a probe: float arithmetic and builtins with scalar or vector results.
fn candidate(e: &Expression, ty: Option<&TypeInner>) -> Option<String> {
    let float = match ty? {
        TypeInner::Scalar(s) | TypeInner::Vector { scalar: s, .. } => s.kind == ScalarKind::Float && s.width == 4,
        _ => false,
    };
    if !float {
        return None;
    }
    match e {
        Expression::Binary { op: B::Divide, .. } => Some("division".into()),
        Expression::Binary { op: B::Add | B::Subtract | B::Multiply | B::Modulo, .. } => Some("arithmetic".into()),
        Expression::Math { fun, .. } => Some(format!("{fun:?}").to_lowercase()),
        _ => None,
    }
}

/// `Emit` of the test, and `if (flag == 0u && bad(h)) { flag = id; }`.
fn build_check(
    fun: &mut Function,
    h: Handle<Expression>,
    ty: Option<&TypeInner>,
    flag: Handle<naga::GlobalVariable>,
    id: u32,
) -> (Statement, Statement) {
    let size = match ty {
        Some(TypeInner::Vector { size, .. }) => Some(*size),
        _ => None,
    };
    let e = &mut fun.expressions;
    // Not emitted: literals and the global's pointer.
    let mask = e.append(Expression::Literal(Literal::U32(0x7f80_0000)), Span::UNDEFINED);
    let zero = e.append(Expression::Literal(Literal::U32(0)), Span::UNDEFINED);
    let fzero = e.append(Expression::Literal(Literal::F32(0.0)), Span::UNDEFINED);
    let value = e.append(Expression::Literal(Literal::U32(id)), Span::UNDEFINED);
    let ptr = e.append(Expression::GlobalVariable(flag), Span::UNDEFINED);
    let normalize_arg = match fun.expressions[h] {
        Expression::Math { fun: MathFunction::Normalize, arg, .. } => Some(arg),
        _ => None,
    };
    let e = &mut fun.expressions;
    let bits = e.append(Expression::As { expr: h, kind: ScalarKind::Uint, convert: None }, Span::UNDEFINED);
    let m = match size {
        Some(size) => e.append(Expression::Splat { size, value: mask }, Span::UNDEFINED),
        None => mask,
    };
    let exponent = e.append(Expression::Binary { op: B::And, left: bits, right: m }, Span::UNDEFINED);
    let all_ones = e.append(Expression::Binary { op: B::Equal, left: exponent, right: m }, Span::UNDEFINED);
    let mut bad = match size {
        Some(_) => e.append(Expression::Relational { fun: RelationalFunction::Any, argument: all_ones }, Span::UNDEFINED),
        None => all_ones,
    };
    if let Some(arg) = normalize_arg {
        let d = e.append(Expression::Math { fun: MathFunction::Dot, arg, arg1: Some(arg), arg2: None, arg3: None }, Span::UNDEFINED);
        let z = e.append(Expression::Binary { op: B::Equal, left: d, right: fzero }, Span::UNDEFINED);
        bad = e.append(Expression::Binary { op: B::LogicalOr, left: bad, right: z }, Span::UNDEFINED);
    }
    let current = e.append(Expression::Load { pointer: ptr }, Span::UNDEFINED);
    let none_yet = e.append(Expression::Binary { op: B::Equal, left: current, right: zero }, Span::UNDEFINED);
    let condition = e.append(Expression::Binary { op: B::LogicalAnd, left: none_yet, right: bad }, Span::UNDEFINED);
    let range = naga::Range::new_from_bounds(bits, condition);
    let mut accept = Block::new();
    accept.push(Statement::Store { pointer: ptr, value }, Span::UNDEFINED);
    (Statement::Emit(range), Statement::If { condition, accept, reject: Block::new() })
}

/// Appends `atomicAdd(&counts[base + flag], 1u)` to `out`.
fn push_count(fun: &mut Function, out: &mut Block, flag: Handle<naga::GlobalVariable>, counts: Handle<naga::GlobalVariable>, base: u32) {
    let e = &mut fun.expressions;
    let flag_ptr = e.append(Expression::GlobalVariable(flag), Span::UNDEFINED);
    let counts_ptr = e.append(Expression::GlobalVariable(counts), Span::UNDEFINED);
    let base_value = e.append(Expression::Literal(Literal::U32(base)), Span::UNDEFINED);
    let one = e.append(Expression::Literal(Literal::U32(1)), Span::UNDEFINED);
    let current = e.append(Expression::Load { pointer: flag_ptr }, Span::UNDEFINED);
    let index = e.append(Expression::Binary { op: B::Add, left: base_value, right: current }, Span::UNDEFINED);
    let slot = e.append(Expression::Access { base: counts_ptr, index }, Span::UNDEFINED);
    out.push(Statement::Emit(naga::Range::new_from_bounds(current, slot)), Span::UNDEFINED);
    out.push(Statement::Atomic { pointer: slot, fun: naga::AtomicFunction::Add, value: one, result: None }, Span::UNDEFINED);
}

#[cfg(test)]
mod tests {
    use super::*;

    const VERT: &str = "#version 450\nlayout(location=0) in vec3 pos;\nlayout(location=1) in vec3 normal;\nlayout(location=0) out vec3 n;\nvoid main() { n = normalize(normal); gl_Position = vec4(pos / pos.z, 1.0); }\n";
    const FRAG: &str = "#version 450\nlayout(set=0,binding=0) uniform U { float k; };\nlayout(location=0) in vec3 n;\nlayout(location=0) out vec4 color;\nvoid main() { if (k < 0.0) { discard; } color = vec4(sqrt(n) / k, 1.0); }\n";

    fn merged() -> Module {
        let parse = |src: &str, stage| naga::front::glsl::Frontend::default().parse(&naga::front::glsl::Options::from(stage), src).unwrap();
        let v = parse(VERT, naga::ShaderStage::Vertex);
        let f = parse(FRAG, naga::ShaderStage::Fragment);
        crate::back::merge::merge(&[(StageKind::Vertex, &v), (StageKind::Fragment, &f)]).unwrap()
    }

    #[test]
    fn both_stages_count_into_their_own_region_and_the_module_stays_valid() {
        let mut module = merged();
        let info = crate::front::naga_run::validator().validate(&module).unwrap();
        let binding = free_binding(&module);
        assert_eq!(binding, (0, 1), "next to the uniform block");
        let texts = [(StageKind::Vertex, VERT), (StageKind::Fragment, FRAG)];
        let done = instrument(&mut module, &info, &texts, &[StageKind::Vertex, StageKind::Fragment], binding).unwrap();
        let info = crate::front::naga_run::validator().validate(&module).unwrap_or_else(|e| panic!("{e:?}"));
        // Vertex: normalize, division; fragment: sqrt, division (and the vec4 compose is no arithmetic).
        let what: Vec<(StageKind, &str)> = done.probes.iter().map(|p| (p.stage, p.what.as_str())).collect();
        assert!(what.contains(&(StageKind::Vertex, "normalize")) && what.contains(&(StageKind::Fragment, "sqrt")), "{what:?}");
        let n = done.probes.len() as u32;
        assert_eq!(done.regions, [(StageKind::Vertex, 0), (StageKind::Fragment, n + 1)]);
        assert_eq!(done.slots, 2 * (n + 1));
        let normalize = done.probes.iter().find(|p| p.what == "normalize").unwrap();
        assert_eq!(&VERT[normalize.span.to_range().unwrap()], "normalize(normal)");
        let wgsl = naga::back::wgsl::write_string(&module, &info, naga::back::wgsl::WriterFlags::empty()).unwrap();
        assert!(wgsl.contains("var<storage, read_write> effectc_probe_counts: array<atomic<u32>"), "{wgsl}");
        // Every exit counts: the discard and the return of the fragment stage, the vertex return.
        assert_eq!(wgsl.matches("atomicAdd(").count(), 3, "{wgsl}");
    }

    #[test]
    fn counts_split_into_regions() {
        let probe = |id, stage| Probe { id, span: Span::default(), stage, what: "division".into() };
        let done = Instrumented {
            probes: vec![probe(1, StageKind::Vertex), probe(2, StageKind::Fragment)],
            regions: vec![(StageKind::Vertex, 0), (StageKind::Fragment, 3)],
            slots: 6,
            binding: (0, 0),
        };
        let counts = done.read(&[10, 2, 0, 90, 0, 7]);
        assert_eq!(counts[0], StageCounts { stage: StageKind::Vertex, clean: 10, first: vec![(1, 2)] });
        assert_eq!(counts[1], StageCounts { stage: StageKind::Fragment, clean: 90, first: vec![(2, 7)] });
        assert_eq!(counts[1].bad(), 7);
    }
}
