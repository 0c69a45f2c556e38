//! Member-by-member comparison of two blocks (interface or uniform) declared in two stages.
//!
//! GL matches blocks by block name and then requires the same members, in the same order,
//! with the same types (array sizes included) and, for interface blocks, the same
//! interpolation and `centroid` qualification. [`diff`] lists every difference with the
//! spans of the members involved, so one diagnostic per block pair can label them all.

use std::collections::HashSet;
use std::ops::Range;

use super::{same_type, type_text};
use crate::front::syntax::{Interp, Member, StageSyntax};

/// One side of a comparison: a stage and a block's (or struct's) members.
#[derive(Clone, Copy)]
pub struct Side<'a> {
    pub stage: &'a StageSyntax,
    pub members: &'a [Member],
    /// Qualifiers written on the block itself, inherited by every member.
    pub block_interp: Option<Interp>,
    pub block_centroid: bool,
}

impl<'a> Side<'a> {
    pub fn new(stage: &'a StageSyntax, members: &'a [Member]) -> Self {
        Side { stage, members, block_interp: None, block_centroid: false }
    }
    fn name(&self, m: &'a Member) -> &'a str {
        self.stage.original_name(&m.name)
    }
    fn names(&self) -> Vec<&'a str> {
        self.members.iter().map(|m| self.name(m)).collect()
    }
    fn find(&self, name: &str) -> Option<&'a Member> {
        self.members.iter().find(|m| self.name(m) == name)
    }
    fn interp(&self, m: &Member) -> Interp {
        m.interp.or(self.block_interp).unwrap_or(Interp::Smooth)
    }
    fn centroid(&self, m: &Member) -> bool {
        m.centroid || self.block_centroid
    }
    fn title(&self) -> &'static str {
        self.stage.stage.title()
    }
}

/// One difference between two blocks, with the member spans to label on each side.
#[derive(Debug, Clone)]
pub struct MemberDiff {
    pub note: String,
    /// An interpolation / `centroid` difference (allowed since GLSL 4.30) rather than one
    /// of names, order or types.
    pub qualifier: bool,
    pub a: Option<(Range<usize>, String)>,
    pub b: Option<(Range<usize>, String)>,
}

/// Same member names and types in the same order (qualifiers not compared).
pub fn same_members(a: Side, b: Side) -> bool {
    a.members.len() == b.members.len()
        && a.members.iter().zip(b.members).all(|(ma, mb)| a.name(ma) == b.name(mb) && same_type(a.stage, &ma.ty, b.stage, &mb.ty))
}

/// Number of member names the two sides share.
pub fn shared_names(a: Side, b: Side) -> usize {
    let bn: HashSet<&str> = b.names().into_iter().collect();
    a.names().into_iter().filter(|n| bn.contains(n)).count()
}

/// Every difference between `a` and `b`. `qualifiers`: also compare interpolation and
/// `centroid` (interface blocks).
pub fn diff(a: Side, b: Side, qualifiers: bool) -> Vec<MemberDiff> {
    let mut out = Vec::new();
    let an = a.names();
    let bn = b.names();
    let (at, bt) = (a.title(), b.title());
    if an != bn {
        let aset: HashSet<&str> = an.iter().copied().collect();
        let bset: HashSet<&str> = bn.iter().copied().collect();
        for m in a.members {
            if !bset.contains(a.name(m)) {
                out.push(MemberDiff {
                    qualifier: false,
                    note: format!("member `{} {}` is declared only in the {at} stage", type_text(a.stage, &m.ty), a.name(m)),
                    a: Some((m.span.clone(), format!("only in the {at} stage"))),
                    b: None,
                });
            }
        }
        for m in b.members {
            if !aset.contains(b.name(m)) {
                out.push(MemberDiff {
                    qualifier: false,
                    note: format!("member `{} {}` is declared only in the {bt} stage", type_text(b.stage, &m.ty), b.name(m)),
                    a: None,
                    b: Some((m.span.clone(), format!("only in the {bt} stage"))),
                });
            }
        }
        let common_a: Vec<&str> = an.iter().copied().filter(|n| bset.contains(n)).collect();
        let common_b: Vec<&str> = bn.iter().copied().filter(|n| aset.contains(n)).collect();
        if common_a != common_b {
            let pos = common_a.iter().zip(&common_b).position(|(x, y)| x != y).unwrap_or(0);
            let (ma, mb) = (a.find(common_a[pos]), b.find(common_b[pos]));
            out.push(MemberDiff {
                qualifier: false,
                note: format!(
                    "the members are in a different order: ({}) in the {at} stage, ({}) in the {bt} stage",
                    common_a.join(", "),
                    common_b.join(", ")
                ),
                a: ma.map(|m| (m.span.clone(), comes(common_a[pos], pos))),
                b: mb.map(|m| (m.span.clone(), comes(common_b[pos], pos))),
            });
        }
    }
    for ma in a.members {
        let name = a.name(ma);
        let Some(mb) = b.find(name) else { continue };
        if !same_type(a.stage, &ma.ty, b.stage, &mb.ty) {
            let (ta, tb) = (type_text(a.stage, &ma.ty), type_text(b.stage, &mb.ty));
            out.push(MemberDiff {
                qualifier: false,
                note: format!("member `{name}` is `{ta}` in the {at} stage but `{tb}` in the {bt} stage"),
                a: Some((ma.span.clone(), format!("`{ta}` here"))),
                b: Some((mb.span.clone(), format!("`{tb}` here"))),
            });
        }
        if !qualifiers {
            continue;
        }
        let (ia, ib) = (a.interp(ma), b.interp(mb));
        if ia != ib {
            out.push(MemberDiff {
                qualifier: true,
                note: format!(
                    "member `{name}` is `{}` in the {at} stage but `{}` in the {bt} stage (no qualifier means `smooth`)",
                    ia.keyword(),
                    ib.keyword()
                ),
                a: Some((ma.span.clone(), format!("`{}` here", ia.keyword()))),
                b: Some((mb.span.clone(), format!("`{}` here", ib.keyword()))),
            });
        }
        let (ca, cb) = (a.centroid(ma), b.centroid(mb));
        if ca != cb {
            let word = |c: bool| if c { "`centroid`" } else { "not `centroid`" };
            out.push(MemberDiff {
                qualifier: true,
                note: format!("member `{name}` is {} in the {at} stage but {} in the {bt} stage", word(ca), word(cb)),
                a: Some((ma.span.clone(), word(ca).to_string())),
                b: Some((mb.span.clone(), word(cb).to_string())),
            });
        }
    }
    out
}

/// "`b` comes 1st here" for the member at 0-based position `pos`.
fn comes(name: &str, pos: usize) -> String {
    format!("`{name}` comes {}{} here", pos + 1, ordinal(pos + 1))
}

fn ordinal(n: usize) -> &'static str {
    match (n % 10, n % 100) {
        (1, x) if x != 11 => "st",
        (2, x) if x != 12 => "nd",
        (3, x) if x != 13 => "rd",
        _ => "th",
    }
}
