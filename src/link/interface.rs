//! The interface between two consecutive stages: outputs of one against inputs of the next.
//!
//! Loose varyings match by variable name, interface blocks by *block* name (instance names
//! may differ). Matched pairs must agree on type and array size, interpolation, `centroid`
//! and explicit locations. Inputs of the tessellation and geometry stages are per-vertex
//! arrays of the previous stage's outputs (`in vec3 n[]` matches `out vec3 n`), and so are
//! the tessellation control stage's outputs. Built-ins (`gl_*`, `gl_PerVertex`) are left to
//! the compiler.
//!
//! An unmatched input block is paired with the previous stage's unmatched output block that
//! most likely was meant (same members, else shared member names, else the only one left),
//! so the classic `out vert_out {…}` / `in vert_vars {…}` mismatch is one diagnostic, not
//! one per member plus an unread-output warning.

use std::collections::HashSet;

use super::blocks::{self, MemberDiff, Side};
use super::{interp_text, is_builtin, is_read, list, same_type, stage_title, type_text};
use super::{
    E_BLOCK_MISMATCH, E_BLOCK_UNMATCHED, E_CENTROID, E_INTERP, E_LOCATION, E_NOT_ARRAYED, E_NO_PRODUCER, E_VARYING_TYPE, W_CENTROID,
    W_INTERP, W_UNREAD_OUTPUT, W_UNUSED_INPUT,
};
use crate::diag::Diagnostic;
use crate::front::syntax::{Global, GlslType, Interp, StageSyntax, Storage};
use crate::manifest::did_you_mean;
use crate::stage::StageKind;

/// Direction of a global across a stage boundary.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dir {
    In,
    Out,
}

/// Whether `g` is a user input or output of `stage` at a stage boundary (vertex inputs and
/// fragment outputs face the application, not another stage).
pub fn direction(stage: StageKind, g: &Global) -> Option<Dir> {
    match (g.storage, stage) {
        (_, StageKind::Compute) => None,
        (Storage::Out, StageKind::Fragment) => None,
        (Storage::Out, _) => Some(Dir::Out),
        (Storage::Varying, StageKind::Vertex) => Some(Dir::Out),
        (Storage::Varying, _) => Some(Dir::In),
        (Storage::In, StageKind::Vertex) => None,
        (Storage::In, _) => Some(Dir::In),
        _ => None,
    }
}

/// Stages whose inputs are arrays with one element per vertex.
fn arrayed_inputs(kind: StageKind) -> bool {
    matches!(kind, StageKind::TessControl | StageKind::TessEval | StageKind::Geometry)
}

/// Whether input `gi` of `s` has one element per vertex (a geometry or tessellation
/// stage's, or a fragment input qualified `pervertexEXT`).
fn input_arrayed(s: &StageSyntax, gi: usize) -> bool {
    let g = &s.globals[gi];
    arrayed_inputs(s.stage) || s.per_vertex.iter().any(|o| g.decl_span.contains(o))
}

/// Stages whose outputs are arrays with one element per vertex.
fn arrayed_outputs(kind: StageKind) -> bool {
    kind == StageKind::TessControl
}

/// Drops the per-vertex array dimension.
fn per_vertex(dims: &[Option<u32>], arrayed: bool) -> Vec<Option<u32>> {
    if arrayed && !dims.is_empty() {
        dims[1..].to_vec()
    } else {
        dims.to_vec()
    }
}

fn dims_text(dims: &[Option<u32>]) -> String {
    GlslType { base: String::new(), dims: dims.to_vec() }.to_string()
}

/// Indices of a stage's loose and block inputs or outputs.
struct Ports {
    loose: Vec<usize>,
    blocks: Vec<usize>,
}

fn ports(s: &StageSyntax, dir: Dir) -> Ports {
    let mut p = Ports { loose: Vec::new(), blocks: Vec::new() };
    for (i, g) in s.globals.iter().enumerate() {
        if direction(s.stage, g) != Some(dir) || is_builtin(s, g) {
            continue;
        }
        if g.is_block() {
            p.blocks.push(i);
        } else {
            p.loose.push(i);
        }
    }
    p
}

/// Both stages follow the GLSL ≥ 4.30 rule that interpolation and `centroid` may differ.
fn qualifiers_relaxed(a: &StageSyntax, b: &StageSyntax) -> bool {
    !a.version.is_es() && !b.version.is_es() && a.version.number >= 430 && b.version.number >= 430
}

struct Pair<'a> {
    a: &'a StageSyntax,
    b: &'a StageSyntax,
    at: &'static str,
    bt: &'static str,
    outs: Ports,
    ins: Ports,
    /// Outputs of `a` accounted for (matched, or part of a diagnostic about an input).
    consumed: HashSet<usize>,
    out: &'a mut Vec<Diagnostic>,
}

/// All link checks between stage `a` and the next stage `b`.
pub fn check_pair(a: &StageSyntax, b: &StageSyntax, out: &mut Vec<Diagnostic>) {
    let mut p = Pair {
        a,
        b,
        at: stage_title(a.stage),
        bt: stage_title(b.stage),
        outs: ports(a, Dir::Out),
        ins: ports(b, Dir::In),
        consumed: HashSet::new(),
        out,
    };
    p.arrayed_geometry_inputs();
    p.location_inputs();
    p.loose_inputs();
    p.block_inputs();
    p.unread_outputs();
}

/// One location an output or input occupies: the declaration and the type there.
#[derive(Debug, Clone)]
struct Slot {
    location: u32,
    global: usize,
    /// The member of a block, when the slot is one.
    member: Option<usize>,
    ty: GlslType,
    span: std::ops::Range<usize>,
}

/// Every explicitly located slot of `ports` (loose variables, blocks with a location,
/// members with their own location). `arrayed`: drop the per-vertex dimension.
fn located_slots(s: &StageSyntax, globals: &[usize], arrayed: bool) -> Vec<Slot> {
    let mut out = Vec::new();
    for &gi in globals {
        let g = &s.globals[gi];
        match &g.block {
            None => {
                if let Some(loc) = g.location {
                    let ty = GlslType { base: g.ty.base.clone(), dims: per_vertex(&g.ty.dims, arrayed && g.ty.is_array()) };
                    out.push(Slot { location: loc, global: gi, member: None, ty, span: g.name_span.clone() });
                }
            }
            Some(b) => {
                let mut next = g.location;
                for (mi, m) in b.members.iter().enumerate() {
                    let own = m.layout.iter().find(|(k, _)| k == "location").and_then(|(_, v)| v.and_then(|v| u32::try_from(v).ok()));
                    let Some(loc) = own.or(next) else { continue };
                    out.push(Slot { location: loc, global: gi, member: Some(mi), ty: m.ty.clone(), span: m.span.clone() });
                    next = Some(loc + crate::front::plan::location_slots(&m.ty, s));
                }
            }
        }
    }
    out
}

/// Whether a stage is written in Vulkan GLSL (interfaces match by location only).
pub fn is_vulkan(s: &StageSyntax) -> bool {
    s.vulkan
}

impl Pair<'_> {
    /// GL 4.5 §7.4.1 (and Vulkan, where names never matter): an input with an explicit
    /// location is matched by location to the output at that location, whatever the names.
    /// Inputs handled here leave the name-based checks.
    fn location_inputs(&mut self) {
        let (a, b, at, bt) = (self.a, self.b, self.at, self.bt);
        let vulkan = is_vulkan(a) || is_vulkan(b);
        let mut outs: Vec<usize> = self.outs.loose.clone();
        outs.extend(self.outs.blocks.iter().copied());
        let out_slots = located_slots(a, &outs, arrayed_outputs(a.stage));
        let mut handled: Vec<usize> = Vec::new();
        let mut ins: Vec<usize> = self.ins.loose.clone();
        ins.extend(self.ins.blocks.iter().copied());
        for bi in ins {
            let in_slots = located_slots(b, &[bi], input_arrayed(b, bi));
            if in_slots.is_empty() {
                continue;
            }
            let g = &b.globals[bi];
            // In GL a same-named counterpart decides (its location is compared there).
            let name_match = match &g.block {
                None => self.outs.loose.iter().any(|&ai| self.aname(ai) == self.bname(bi)),
                Some(blk) => self.outs.blocks.iter().any(|&ai| {
                    a.globals[ai].block.as_ref().is_some_and(|ob| a.original_name(&ob.block_name) == b.original_name(&blk.block_name))
                }),
            };
            if name_match && !vulkan {
                continue;
            }
            handled.push(bi);
            let read = is_read(b, bi);
            for slot in &in_slots {
                let Some(o) = out_slots.iter().find(|o| o.location == slot.location) else {
                    if read {
                        let what = self.slot_name(b, slot);
                        self.out.push(
                            Diagnostic::error(
                                E_NO_PRODUCER,
                                format!("{bt} input `{what}` at location {} has no matching output in the {at} stage", slot.location),
                            )
                            .at(b.file, slot.span.clone(), format!("no {at} output has location {}", slot.location))
                            .with_note("an input with an explicit location matches the output with the same location, whatever its name"),
                        );
                    }
                    continue;
                };
                self.consumed.insert(o.global);
                if !same_type(a, &o.ty, b, &slot.ty) {
                    let (wa, wb) = (self.slot_name(a, o), self.slot_name(b, slot));
                    let (ta, tb) = (type_text(a, &o.ty), type_text(b, &slot.ty));
                    self.out.push(
                        Diagnostic::error(
                            E_VARYING_TYPE,
                            format!(
                                "location {}: `{wb}` is `{tb}` in the {bt} stage but the {at} stage's `{wa}` there is `{ta}`",
                                slot.location
                            ),
                        )
                        .at(b.file, slot.span.clone(), format!("{bt} input `{tb}` at location {}", slot.location))
                        .with_label(a.file, o.span.clone(), format!("{at} output `{ta}` at location {}", o.location))
                        .with_note("an output and an input matched by location must have the same type")
                        .with_help(format!("declare both as `{ta}`, or give them different locations")),
                    );
                }
            }
        }
        self.ins.loose.retain(|i| !handled.contains(i));
        self.ins.blocks.retain(|i| !handled.contains(i));
    }

    fn slot_name(&self, s: &StageSyntax, slot: &Slot) -> String {
        let g = &s.globals[slot.global];
        match (&g.block, slot.member) {
            (Some(b), Some(m)) => format!("{}.{}", s.original_name(&b.block_name), s.original_name(&b.members[m].name)),
            _ => s.original_name(&g.name).to_string(),
        }
    }

    fn aname(&self, i: usize) -> &str {
        self.a.original_name(&self.a.globals[i].name)
    }
    fn bname(&self, i: usize) -> &str {
        self.b.original_name(&self.b.globals[i].name)
    }

    /// Geometry inputs must be arrays (tessellation inputs may be `patch in`, which the
    /// syntax facts do not record, so only geometry is checked).
    fn arrayed_geometry_inputs(&mut self) {
        if self.b.stage != StageKind::Geometry {
            return;
        }
        let b = self.b;
        for &i in &self.ins.loose {
            let g = &b.globals[i];
            if g.ty.is_array() {
                continue;
            }
            let name = b.original_name(&g.name);
            let ty = type_text(b, &g.ty);
            self.out.push(
                Diagnostic::error(
                    E_NOT_ARRAYED,
                    format!("geometry input `{name}` must be an array"),
                )
                .at(b.file, g.name_span.clone(), "declared without `[]`")
                .with_note("a geometry shader receives every vertex of its input primitive, so each input is an array with one element per vertex")
                .with_help(format!("declare it as `in {ty} {name}[];`")),
            );
        }
        for &i in &self.ins.blocks {
            let g = &b.globals[i];
            let Some(blk) = &g.block else { continue };
            if !blk.instance_dims.is_empty() {
                continue;
            }
            let bn = b.original_name(&blk.block_name);
            let (span, label) = match &blk.instance_span {
                Some(s) => (s.clone(), "instance declared without `[]`"),
                None => (blk.block_name_span.clone(), "block declared without an instance array"),
            };
            let inst = blk.instance.as_deref().map_or("gs_in", |n| b.original_name(n));
            self.out.push(
                Diagnostic::error(
                    E_NOT_ARRAYED,
                    format!("geometry input block `{bn}` must be declared as an array"),
                )
                .at(b.file, span, label)
                .with_note("a geometry shader receives every vertex of its input primitive, so an input block's instance is an array with one element per vertex")
                .with_help(format!("declare it as `in {bn} {{ … }} {inst}[];`")),
            );
        }
    }

    fn loose_inputs(&mut self) {
        let input_names: HashSet<String> = self.ins.loose.iter().map(|&i| self.bname(i).to_string()).collect();
        for bi in self.ins.loose.clone() {
            let name = self.bname(bi).to_string();
            let matched = self.outs.loose.iter().copied().find(|&ai| self.aname(ai) == name);
            match matched {
                Some(ai) => {
                    self.consumed.insert(ai);
                    self.compare_loose(ai, bi);
                }
                None => self.no_producer(bi, &input_names),
            }
        }
    }

    /// A loose input of `b` with no loose output of the same name in `a`.
    fn no_producer(&mut self, bi: usize, input_names: &HashSet<String>) {
        let (a, b, at, bt) = (self.a, self.b, self.at, self.bt);
        let g = &b.globals[bi];
        let name = b.original_name(&g.name);
        let read = is_read(b, bi);
        let mut d = if read {
            Diagnostic::error(E_NO_PRODUCER, format!("{bt} input `{name}` has no matching output in the {at} stage"))
        } else {
            Diagnostic::warning(W_UNUSED_INPUT, format!("{bt} input `{name}` has no matching output in the {at} stage (it is never read)"))
        }
        .at(b.file, g.name_span.clone(), format!("no {at} output is named `{name}`"))
        .with_note("an output of one stage and an input of the next match by variable name (interface blocks by block name)");
        // A member of an output block with that name?
        let member = self.outs.blocks.iter().find_map(|&ai| {
            let blk = a.globals[ai].block.as_ref()?;
            let m = blk.members.iter().find(|m| a.original_name(&m.name) == name)?;
            Some((ai, a.original_name(&blk.block_name), m))
        });
        if let Some((ai, block, m)) = member {
            self.consumed.insert(ai);
            d = d.with_label(a.file, m.span.clone(), format!("a member of output block `{block}`")).with_help(format!(
                "`{name}` is a member of output block `{block}` in the {at} stage; declare the input inside `in {block} {{ … }}`"
            ));
        } else {
            let candidates: Vec<&str> =
                self.outs.loose.iter().map(|&ai| a.original_name(&a.globals[ai].name)).filter(|n| !input_names.contains(*n)).collect();
            match did_you_mean(name, &candidates) {
                Some(c) => {
                    let ai = self.outs.loose.iter().copied().find(|&ai| a.original_name(&a.globals[ai].name) == c);
                    if let Some(ai) = ai {
                        self.consumed.insert(ai);
                        d = d.with_label(a.file, a.globals[ai].name_span.clone(), format!("the {at} stage writes `{c}`"));
                    }
                    d = d.with_help(format!("did you mean `{c}`? rename one of the two so the names agree"));
                }
                None => {
                    let outs: Vec<String> = self.outs.loose.iter().map(|&ai| a.original_name(&a.globals[ai].name).to_string()).collect();
                    d = d.with_note(if outs.is_empty() {
                        format!("the {at} stage declares no loose outputs")
                    } else {
                        format!("the {at} stage's outputs are {}", list(&outs))
                    });
                    if read {
                        d = d.with_help(format!(
                            "declare `out {} {name};` in the {at} stage and write it there",
                            type_text(b, &GlslType { base: g.ty.base.clone(), dims: per_vertex(&g.ty.dims, arrayed_inputs(b.stage)) })
                        ));
                    }
                }
            }
        }
        if !read {
            d = d.with_note("GL only rejects an unmatched input the stage reads; this one is dead code");
        }
        self.out.push(d);
    }

    /// Type, interpolation, `centroid` and location of a matched loose pair.
    fn compare_loose(&mut self, ai: usize, bi: usize) {
        let (a, b, at, bt) = (self.a, self.b, self.at, self.bt);
        let (ga, gb) = (&a.globals[ai], &b.globals[bi]);
        let name = b.original_name(&gb.name);
        let ta = GlslType { base: ga.ty.base.clone(), dims: per_vertex(&ga.ty.dims, arrayed_outputs(a.stage)) };
        let b_arrayed = input_arrayed(b, bi) && gb.ty.is_array();
        let tb = GlslType { base: gb.ty.base.clone(), dims: per_vertex(&gb.ty.dims, b_arrayed) };
        if !same_type(a, &ta, b, &tb) {
            let (sa, sb) = (type_text(a, &ga.ty), type_text(b, &gb.ty));
            let mut want_dims = Vec::new();
            if b_arrayed {
                want_dims.push(gb.ty.dims[0]);
            }
            want_dims.extend(ta.dims.iter().copied());
            let want = format!("in {} {name}{}", a.original_name(&ta.base), dims_text(&want_dims));
            let mut d = Diagnostic::error(E_VARYING_TYPE, format!("`{name}` is `{sa}` in the {at} stage but `{sb}` in the {bt} stage"))
                .at(b.file, gb.name_span.clone(), format!("{bt} input declared as `{sb}`"))
                .with_label(a.file, ga.name_span.clone(), format!("{at} output declared as `{sa}`"))
                .with_note("an output and the input of the same name must have the same type and array size");
            if b_arrayed {
                d = d.with_note(format!(
                    "{bt} inputs are arrays with one element per vertex: `in {} {name}[]` matches `out {} {name}`",
                    type_text(a, &ta),
                    type_text(a, &ta)
                ));
            }
            self.out.push(d.with_help(format!("declare the {bt} input as `{want};`")));
        }
        let relaxed = qualifiers_relaxed(a, b);
        // Integers are never interpolated: without a qualifier they are `flat` in effect.
        let effective = |g: &Global| match g.interp {
            Some(i) => i,
            None if g.ty.is_integer() => Interp::Flat,
            None => Interp::Smooth,
        };
        let (ia, ib) = (effective(ga), effective(gb));
        if ia != ib {
            let shown = |g: &Global, i: Interp| match g.interp {
                Some(_) => format!("`{}`", interp_text(i)),
                None => format!("`{}` (no qualifier)", interp_text(i)),
            };
            let message = format!("`{name}` is `{}` in the {at} stage but `{}` in the {bt} stage", interp_text(ia), interp_text(ib));
            let d = if relaxed {
                Diagnostic::warning(W_INTERP, message).with_note(format!(
                    "since GLSL 4.30 the qualifiers may differ and the {bt} stage's `{}` is used; the {at} stage's `{}` has no effect",
                    interp_text(ib),
                    interp_text(ia)
                ))
            } else {
                Diagnostic::error(E_INTERP, message).with_note(
                    "before GLSL 4.30 an output and its input must have the same interpolation qualifier (no qualifier means `smooth`)",
                )
            };
            self.out.push(
                d.at(b.file, gb.name_span.clone(), format!("{} here", shown(gb, ib)))
                    .with_label(a.file, ga.name_span.clone(), format!("{} here", shown(ga, ia)))
                    .with_help("write the same interpolation qualifier in both stages"),
            );
        }
        if ga.centroid != gb.centroid {
            let word = |c: bool| if c { "`centroid`" } else { "not `centroid`" };
            let message = format!("`{name}` is {} in the {at} stage but {} in the {bt} stage", word(ga.centroid), word(gb.centroid));
            let d = if relaxed {
                Diagnostic::warning(W_CENTROID, message)
                    .with_note(format!("since GLSL 4.30 auxiliary qualifiers may differ and the {bt} stage's declaration is used"))
            } else {
                Diagnostic::error(E_CENTROID, message).with_note("before GLSL 4.30 an output and its input must agree on `centroid`")
            };
            self.out.push(
                d.at(b.file, gb.name_span.clone(), word(gb.centroid))
                    .with_label(a.file, ga.name_span.clone(), word(ga.centroid))
                    .with_help("write `centroid` in both stages or in neither"),
            );
        }
        if let (Some(la), Some(lb)) = (ga.location, gb.location) {
            if la != lb {
                let span_a = ga.layout_span.clone().unwrap_or_else(|| ga.name_span.clone());
                let span_b = gb.layout_span.clone().unwrap_or_else(|| gb.name_span.clone());
                self.out.push(
                    Diagnostic::error(
                        E_LOCATION,
                        format!("`{name}` has `location = {la}` in the {at} stage but `location = {lb}` in the {bt} stage"),
                    )
                    .at(b.file, span_b, format!("location {lb}"))
                    .with_label(a.file, span_a, format!("location {la}"))
                    .with_note("when both stages give an explicit location for a varying, the locations must be equal")
                    .with_help("use the same `layout(location = …)` in both stages, or drop it from one"),
                );
            }
        }
    }

    fn block_inputs(&mut self) {
        let (a, b) = (self.a, self.b);
        let block_name = |s: &StageSyntax, i: usize| -> String {
            s.globals[i].block.as_ref().map(|blk| s.original_name(&blk.block_name).to_string()).unwrap_or_default()
        };
        let mut unmatched_b = Vec::new();
        let mut matched_a = HashSet::new();
        for bi in self.ins.blocks.clone() {
            let name = block_name(b, bi);
            match self.outs.blocks.iter().copied().find(|&ai| block_name(a, ai) == name) {
                Some(ai) => {
                    matched_a.insert(ai);
                    self.consumed.insert(ai);
                    self.compare_blocks(ai, bi);
                }
                None => unmatched_b.push(bi),
            }
        }
        let unmatched_a: Vec<usize> = self.outs.blocks.iter().copied().filter(|ai| !matched_a.contains(ai)).collect();
        let mut taken = HashSet::new();
        for &bi in &unmatched_b {
            let mut best: Option<(usize, usize)> = None;
            for &ai in unmatched_a.iter().filter(|ai| !taken.contains(*ai)) {
                let score = self.pair_score(ai, bi);
                if score > 0 && best.is_none_or(|(s, _)| score > s) {
                    best = Some((score, ai));
                }
            }
            let mut pick = best.map(|(_, ai)| ai);
            if pick.is_none() && unmatched_a.len() == 1 && unmatched_b.len() == 1 {
                pick = Some(unmatched_a[0]);
            }
            if let Some(ai) = pick {
                taken.insert(ai);
            }
            self.unmatched_block(bi, pick);
        }
    }

    fn side<'s>(s: &'s StageSyntax, i: usize) -> Side<'s> {
        let g = &s.globals[i];
        let members = g.block.as_ref().map_or(&[][..], |b| &b.members[..]);
        Side { stage: s, members, block_interp: g.interp, block_centroid: g.centroid }
    }

    /// How likely output block `ai` is the one input block `bi` was meant to match.
    fn pair_score(&self, ai: usize, bi: usize) -> usize {
        let (sa, sb) = (Self::side(self.a, ai), Self::side(self.b, bi));
        if blocks::same_members(sa, sb) {
            3
        } else {
            let shared = blocks::shared_names(sa, sb);
            if shared == sa.members.len() && shared == sb.members.len() {
                2
            } else if shared > 0 {
                1
            } else {
                0
            }
        }
    }

    /// An input block with no output block of its block name; `pair` is the output block it
    /// was most likely meant to match.
    fn unmatched_block(&mut self, bi: usize, pair: Option<usize>) {
        let (a, b, at, bt) = (self.a, self.b, self.at, self.bt);
        let g = &b.globals[bi];
        let Some(blk) = &g.block else { return };
        let bname = b.original_name(&blk.block_name);
        let read = is_read(b, bi);
        let message = format!("{bt} input block `{bname}` has no matching output block in the {at} stage");
        let mut d = if read {
            Diagnostic::error(E_BLOCK_UNMATCHED, message)
        } else {
            Diagnostic::warning(W_UNUSED_INPUT, format!("{message} (it is never read)"))
        }
        .at(b.file, blk.block_name_span.clone(), format!("no {at} output block is named `{bname}`"));
        if let Some(ai) = pair {
            self.consumed.insert(ai);
            let ablk = a.globals[ai].block.as_ref().expect("output blocks are blocks");
            let aname = a.original_name(&ablk.block_name);
            d = d
                .with_label(a.file, ablk.block_name_span.clone(), format!("the {at} stage's output block is named `{aname}`"))
                .with_note(format!("interface blocks match by block name (`{bname}` vs `{aname}`), not by instance name"));
            let (sa, sb) = (Self::side(a, ai), Self::side(b, bi));
            if blocks::same_members(sa, sb) {
                d = d.with_help(format!("rename `in {bname}` to `in {aname}` (the members match)"));
            } else {
                for diff in blocks::diff(sa, sb, !qualifiers_relaxed(a, b)) {
                    d = self.add_diff(d, diff);
                }
                d = d.with_help(format!("rename `in {bname}` to `in {aname}` and make the members agree"));
            }
        } else {
            d = d.with_note("interface blocks match by block name, not by instance name");
            // Does `a` write the members as loose outputs?
            let loose: Vec<usize> = self
                .outs
                .loose
                .iter()
                .copied()
                .filter(|&ai| blk.members.iter().any(|m| b.original_name(&m.name) == self.aname(ai)))
                .collect();
            if !loose.is_empty() {
                let names: Vec<String> = loose.iter().map(|&ai| self.aname(ai).to_string()).collect();
                for &ai in &loose {
                    self.consumed.insert(ai);
                    d = d.with_label(a.file, a.globals[ai].name_span.clone(), "a separate output, not a block member");
                }
                d = d.with_help(format!(
                    "the {at} stage writes {} as separate outputs: declare `out {bname} {{ … }}` there, or declare the inputs here as separate `in` variables",
                    list(&names)
                ));
            } else {
                let others: Vec<String> = self
                    .outs
                    .blocks
                    .iter()
                    .filter_map(|&ai| a.globals[ai].block.as_ref())
                    .map(|ob| a.original_name(&ob.block_name).to_string())
                    .collect();
                if !others.is_empty() {
                    d = d.with_note(format!("the {at} stage's output blocks are {}", list(&others)));
                }
                d = d.with_help(format!("declare `out {bname} {{ … }}` with the same members in the {at} stage"));
            }
        }
        if !read {
            d = d.with_note("GL only rejects an unmatched input the stage reads; this one is dead code");
        }
        self.out.push(d);
    }

    fn add_diff(&self, mut d: Diagnostic, diff: MemberDiff) -> Diagnostic {
        if let Some((span, label)) = diff.a {
            d = d.with_label(self.a.file, span, label);
        }
        if let Some((span, label)) = diff.b {
            d = d.with_label(self.b.file, span, label);
        }
        d.with_note(diff.note)
    }

    /// Members and block-level facts of two blocks with the same block name.
    fn compare_blocks(&mut self, ai: usize, bi: usize) {
        let (a, b, at, bt) = (self.a, self.b, self.at, self.bt);
        let (ga, gb) = (&a.globals[ai], &b.globals[bi]);
        let (Some(ba), Some(bb)) = (&ga.block, &gb.block) else {
            return;
        };
        let name = b.original_name(&bb.block_name);
        let relaxed = qualifiers_relaxed(a, b);
        let all = blocks::diff(Self::side(a, ai), Self::side(b, bi), true);
        let (mut errors, warnings): (Vec<MemberDiff>, Vec<MemberDiff>) = all.into_iter().partition(|d| !(relaxed && d.qualifier));
        let da = per_vertex(&ba.instance_dims, arrayed_outputs(a.stage));
        let db = per_vertex(&bb.instance_dims, arrayed_inputs(b.stage) && !bb.instance_dims.is_empty());
        if da != db {
            let shown = |d: &[Option<u32>]| {
                if d.is_empty() {
                    "not an array".to_string()
                } else {
                    format!("an array `{}`", dims_text(d))
                }
            };
            errors.push(MemberDiff {
                qualifier: false,
                note: format!("the instance is {} in the {at} stage but {} in the {bt} stage", shown(&da), shown(&db)),
                a: ba.instance_span.clone().map(|s| (s, shown(&da))),
                b: bb.instance_span.clone().map(|s| (s, shown(&db))),
            });
        }
        if let (Some(la), Some(lb)) = (ga.location, gb.location) {
            if la != lb {
                errors.push(MemberDiff {
                    qualifier: false,
                    note: format!("the block has `location = {la}` in the {at} stage but `location = {lb}` in the {bt} stage"),
                    a: ga.layout_span.clone().map(|s| (s, format!("location {la}"))),
                    b: gb.layout_span.clone().map(|s| (s, format!("location {lb}"))),
                });
            }
        }
        let head = |d: Diagnostic| {
            d.at(b.file, bb.block_name_span.clone(), format!("{bt} input block")).with_label(
                a.file,
                ba.block_name_span.clone(),
                format!("{at} output block"),
            )
        };
        if !errors.is_empty() {
            let mut d =
                head(Diagnostic::error(E_BLOCK_MISMATCH, format!("interface block `{name}` differs between the {at} and {bt} stages")));
            for diff in errors {
                d = self.add_diff(d, diff);
            }
            d = d
                .with_note("blocks with the same block name must declare the same members in the same order, with the same types, array sizes and qualifiers")
                .with_help(format!("copy the block's members from the {at} stage into the {bt} stage"));
            self.out.push(d);
        }
        if !warnings.is_empty() {
            let mut d = head(Diagnostic::warning(
                W_INTERP,
                format!("interface block `{name}` has different qualifiers in the {at} and {bt} stages"),
            ));
            for diff in warnings {
                d = self.add_diff(d, diff);
            }
            self.out.push(
                d.with_note(format!("since GLSL 4.30 interpolation and auxiliary qualifiers may differ and the {bt} stage's are used")),
            );
        }
    }

    /// Outputs of `a` that no input of `b` accounts for.
    fn unread_outputs(&mut self) {
        let (a, b, at, bt) = (self.a, self.b, self.at, self.bt);
        for ai in self.outs.loose.clone() {
            if self.consumed.contains(&ai) {
                continue;
            }
            let g = &a.globals[ai];
            let name = a.original_name(&g.name);
            let mut d = Diagnostic::warning(W_UNREAD_OUTPUT, format!("{at} output `{name}` is never read by the {bt} stage")).at(
                a.file,
                g.name_span.clone(),
                "written here, read nowhere",
            );
            let member = self.ins.blocks.iter().find_map(|&bi| {
                let blk = b.globals[bi].block.as_ref()?;
                let m = blk.members.iter().find(|m| b.original_name(&m.name) == name)?;
                Some((b.original_name(&blk.block_name), m))
            });
            match member {
                Some((block, m)) => {
                    d = d
                        .with_label(b.file, m.span.clone(), format!("a member of input block `{block}`"))
                        .with_note(format!(
                            "the {bt} stage reads `{name}` as a member of input block `{block}`; a loose output only matches a loose input"
                        ))
                        .with_help(format!("move the output into `out {block} {{ … }}` in the {at} stage"));
                }
                None => {
                    d = d.with_note(format!("the {bt} stage declares no input named `{name}`, so the value is discarded"));
                }
            }
            self.out.push(d);
        }
        for ai in self.outs.blocks.clone() {
            if self.consumed.contains(&ai) {
                continue;
            }
            let Some(blk) = &a.globals[ai].block else {
                continue;
            };
            let name = a.original_name(&blk.block_name);
            self.out.push(
                Diagnostic::warning(W_UNREAD_OUTPUT, format!("{at} output block `{name}` is never read by the {bt} stage"))
                    .at(a.file, blk.block_name_span.clone(), "written here, read nowhere")
                    .with_note(format!(
                        "the {bt} stage declares no input block named `{name}` (blocks match by block name, not by instance name)"
                    )),
            );
        }
    }
}
