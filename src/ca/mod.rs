//! Conservative advancement: the first time of contact of two moving bodies.
//!
//! At a time `t` the bodies are a gap `g` apart along a unit direction `n`
//! (every point of `A` lies in `{x . n <= h}`, every point of `B` in
//! `{x . n >= h + g}`). If no point of `A` or `B` moves along `n` faster than
//! `mu_A` and `mu_B` over `[t, t_end]` (the directed bounds of this crate),
//! the bodies cannot touch before `t + g / (mu_A + mu_B)`. Stepping time by
//! that amount until the distance falls below a tolerance never steps past
//! the first contact (`proofs/09-ca-toi.md`).
//!
//! * [`CaStep`] is what a geometry provides at a time `t`: a certified gap and
//!   a safe step, or "touching". Implement it for your own geometry, or use
//!   one of the steppers of this crate.
//! * [`time_of_impact`] runs the loop and says what ended it ([`CaOutcome`]),
//!   with the iteration count: a contact (within
//!   [`CaParams::contact_distance`], by distance or by a stall of the steps),
//!   [`CaOutcome::Separated`] when a certified step reaches the end of the
//!   interval, or the iteration limit.
//! * [`CaParams`] holds the tolerances, the iteration limit and the bound
//!   choice ([`BoundChoice`]).

#[cfg(feature = "alloc")]
mod any;
mod balls;
#[cfg(feature = "alloc")]
mod compound;
mod convex;
mod driver;
mod half_space;
#[cfg(feature = "alloc")]
mod mesh;
mod outcome;
mod params;
mod shapes;

#[cfg(feature = "alloc")]
pub use any::{AnyPair, Shape};
pub use balls::BallPair;
#[cfg(feature = "alloc")]
pub use compound::{Compound, Part};
pub use convex::{ConvexPair, GjkProximity, Proximity};
pub use driver::{gap_step, placement_error, time_of_impact, CaStep, StepResult};
pub use half_space::HalfSpacePair;
#[cfg(feature = "alloc")]
pub use mesh::{MeshPair, MeshShapePair, MeshWorkspace, TraversalStats};
pub use outcome::{CaOutcome, CaReport, Contact, ContactCriterion, Witness, Work};
pub use params::{BoundChoice, CaError, CaParams, MeshParams, Parameter, WitnessSearch};
pub use shapes::ShapePair;
