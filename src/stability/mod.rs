//! Numerical stability: hazards found statically and by rendering.
//!
//! - [`hazards`]: `effectc check`'s static analysis, intervals propagated over the naga IR
//!   from uniform ranges, mesh data, textures and time; warnings W0710–W0719.
//! - [`culprit`]: the fragment stage instrumented to name the first expression that goes
//!   non-finite in each pixel.
//! - [`stress`]: `effectc stress`: float renders at the ends and random points of the
//!   uniform ranges and at extreme times; NaN/Inf per case, masks, difference from nominal.

pub mod culprit;
pub mod hazards;
pub mod stress;
