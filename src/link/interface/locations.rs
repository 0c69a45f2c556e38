//! Inputs with an explicit `layout(location)` (GL 4.5 §7.4.1, and every input in Vulkan
//! GLSL) are matched to the output at the same location, whatever the names: the slots
//! each declaration occupies, and the checks on the pairs they form.

use super::{arrayed_outputs, input_arrayed, is_vulkan, per_vertex, Pair};
use crate::diag::{Code, Diagnostic};
use crate::front::syntax::{layout_number, GlslType, StageSyntax};
use crate::link::{is_read, same_type, type_text};

/// One location an output or input occupies: the declaration and the type there.
#[derive(Debug, Clone)]
struct Slot {
    location: u32,
    /// The first component (`layout(component = N)`; 0 when not written).
    component: u32,
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
                    let component = layout_number(&g.layout, "component").unwrap_or(0);
                    out.push(Slot { location: loc, component, global: gi, member: None, ty, span: g.name_span.clone() });
                }
            }
            Some(b) => {
                let mut next = g.location;
                for (mi, m) in b.members.iter().enumerate() {
                    let own = layout_number(&m.layout, "location");
                    let Some(loc) = own.or(next) else { continue };
                    let component = layout_number(&m.layout, "component").unwrap_or(0);
                    out.push(Slot { location: loc, component, global: gi, member: Some(mi), ty: m.ty.clone(), span: m.span.clone() });
                    next = Some(loc + crate::front::plan::location_slots(&m.ty, s));
                }
            }
        }
    }
    out
}

/// "location 2", or "location 2, component 3" for a varying packed into a later component.
fn place(location: u32, component: u32) -> String {
    match component {
        0 => format!("location {location}"),
        c => format!("location {location}, component {c}"),
    }
}

impl Pair<'_> {
    /// GL 4.5 §7.4.1 (and Vulkan, where names never matter): an input with an explicit
    /// location is matched by location to the output at that location, whatever the names.
    /// Inputs handled here leave the name-based checks.
    pub(super) fn location_inputs(&mut self) {
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
                let at_slot = place(slot.location, slot.component);
                let Some(o) = out_slots.iter().find(|o| o.location == slot.location && o.component == slot.component) else {
                    if read {
                        let what = self.slot_name(b, slot);
                        self.out.push(
                            Diagnostic::new(
                                Code::NoProducer,
                                format!("{bt} input `{what}` at {at_slot} has no matching output in the {at} stage"),
                            )
                            .at(b.file, slot.span.clone(), format!("no {at} output has {at_slot}"))
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
                        Diagnostic::new(
                            Code::VaryingTypeMismatch,
                            format!("{at_slot}: `{wb}` is `{tb}` in the {bt} stage but the {at} stage's `{wa}` there is `{ta}`"),
                        )
                        .at(b.file, slot.span.clone(), format!("{bt} input `{tb}` at {at_slot}"))
                        .with_label(a.file, o.span.clone(), format!("{at} output `{ta}` at {at_slot}"))
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
}
