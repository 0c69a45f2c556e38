//! Loose varyings, matched by variable name: an input with no producer, and a matched
//! pair's type, interpolation, `centroid` and location.

use std::collections::HashSet;

use super::{arrayed_inputs, arrayed_outputs, dims_text, input_arrayed, per_vertex, qualifiers_relaxed, Pair};
use crate::diag::{Code, Diagnostic};
use crate::front::syntax::{Global, GlslType, Interp};
use crate::link::{is_read, list, same_type, type_text};
use crate::manifest::did_you_mean;

impl Pair<'_> {
    pub(super) fn loose_inputs(&mut self) {
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
            Diagnostic::new(Code::NoProducer, format!("{bt} input `{name}` has no matching output in the {at} stage"))
        } else {
            Diagnostic::new(Code::UnusedInput, format!("{bt} input `{name}` has no matching output in the {at} stage (it is never read)"))
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
            let mut d =
                Diagnostic::new(Code::VaryingTypeMismatch, format!("`{name}` is `{sa}` in the {at} stage but `{sb}` in the {bt} stage"))
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
        // Before 4.30 the qualifiers' presence must match too (GLSL 1.50 §4.3: "the type and
        // presence of the interpolation qualifiers … must match"): an unqualified integer
        // output read as a `flat` input fails to link in GL drivers (Mesa) though it means
        // the same.
        let presence_differs = !relaxed && ga.interp.is_some() != gb.interp.is_some() && ia == ib;
        if ia != ib || presence_differs {
            let shown = |g: &Global, i: Interp| match g.interp {
                Some(_) => format!("`{}`", i.keyword()),
                None => format!("`{}` (no qualifier)", i.keyword()),
            };
            let word = |g: &Global, i: Interp| if g.interp.is_some() { format!("`{}`", i.keyword()) } else { "unqualified".to_string() };
            let message = if presence_differs {
                format!("`{name}` is {} in the {at} stage but {} in the {bt} stage", word(ga, ia), word(gb, ib))
            } else {
                format!("`{name}` is `{}` in the {at} stage but `{}` in the {bt} stage", ia.keyword(), ib.keyword())
            };
            let d = if relaxed {
                Diagnostic::new(Code::InterpolationDiffers, message).with_note(format!(
                    "since GLSL 4.30 the qualifiers may differ and the {bt} stage's `{}` is used; the {at} stage's `{}` has no effect",
                    ib.keyword(),
                    ia.keyword()
                ))
            } else {
                let note = if presence_differs {
                    "before GLSL 4.30 an output and its input must both have the interpolation qualifier or both lack it: an integer means `flat` either way, but GL drivers (Mesa) refuse to link the pair"
                } else {
                    "before GLSL 4.30 an output and its input must have the same interpolation qualifier (no qualifier means `smooth`)"
                };
                Diagnostic::new(Code::InterpolationMismatch, message).with_note(note)
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
                Diagnostic::new(Code::CentroidDiffers, message)
                    .with_note(format!("since GLSL 4.30 auxiliary qualifiers may differ and the {bt} stage's declaration is used"))
            } else {
                Diagnostic::new(Code::CentroidMismatch, message)
                    .with_note("before GLSL 4.30 an output and its input must agree on `centroid`")
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
                    Diagnostic::new(
                        Code::LocationMismatch,
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
}
