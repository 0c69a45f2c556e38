//! What a stage is when naga cannot take a legal construct in it: limited, not wrong.
//!
//! The rewrite finds some before naga runs (a construct naga has no form of); `naga_run`
//! tells the rest from naga's errors. Either way the stage is then checked for syntax and
//! interface only. Both use this type, so neither imports the other for it.

use std::ops::Range;

/// A legal construct naga cannot take: the stage is checked for syntax and interface only.
#[derive(Debug, Clone)]
pub struct Limitation {
    /// What naga could not take, in words (`textureQueryLod`, `layout(row_major)` …).
    pub construct: String,
    /// Where, in the user's file.
    pub span: Option<Range<usize>>,
}
