//! Numerical stability: stress renders on stiff and extreme inputs.
//!
//! - [`stress`]: `effectc stress`: float renders at the ends and random points of the
//!   uniform ranges and at extreme times; NaN/Inf per case, masks, difference from nominal.
//!
//! Static hazard analysis on the IR (interval propagation) is not built yet.

pub mod stress;
