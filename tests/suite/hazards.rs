//! Static hazards (`effectc check`, W0710–W0719): provably safe code raises nothing.
//!
//! Each seed hazard has a fixture under `tests/fail/4N-hazard-*-warning` (run by
//! [`crate::fail`], snapshotted). Here: the same hazards written with their guards under
//! `tests/safe/` produce no diagnostic at all, and neither do the shipped effects.

use crate::common;

#[test]
fn guarded_hazards_raise_nothing() {
    let dirs = common::fixtures("tests/safe", 4);
    for dir in dirs.iter().chain(common::fixtures("effects", 21).iter()) {
        let (outcome, _) = common::check(dir);
        assert!(outcome.diagnostics.is_empty(), "{}:\n{}", dir.display(), common::render(&outcome));
    }
}
