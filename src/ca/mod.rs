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

// The vocabulary: the shape of a body, whatever its kind.
#[cfg(feature = "alloc")]
mod shape;
// The one dispatch over pairs of kinds.
#[cfg(feature = "alloc")]
mod dispatch;
// The owning twin of the vocabulary, and its arguments' errors.
#[cfg(feature = "alloc")]
mod arg_error;
#[cfg(feature = "alloc")]
mod owned;
// The loop, its parameters and its answer; what a stepper answers.
mod driver;
mod outcome;
mod params;
mod step;
// One stepper per pair of kinds, each file named by the pair it serves.
mod ball_ball;
#[cfg(feature = "alloc")]
mod compound;
mod convex_convex;
mod convex_half_space;
#[cfg(feature = "alloc")]
mod mesh;
// A pair touching at the start: does it go deeper?
#[cfg(feature = "alloc")]
mod past_contact;
// A body starting inside a solid mesh: the mesh steppers' check at the start.
#[cfg(feature = "alloc")]
mod solid;
mod vertex_set_vertex_set;

pub use ball_ball::BallPair;
pub use convex_convex::ConvexPair;
#[cfg(feature = "alloc")]
pub(crate) use convex_convex::{certified_gap_to_exact, support_error_up, PlacedCore};
#[cfg(feature = "alloc")]
pub use dispatch::AnyPair;
/// The stepper of two [`Convex`](crate::Convex) shapes, under its old name.
#[deprecated(
    since = "0.1.0",
    note = "renamed `ConvexPair` (the pair of two `Convex` shapes)"
)]
pub type ShapePair<'a, T> = ConvexPair<'a, T>;
pub use convex_half_space::HalfSpacePair;
pub use driver::time_of_impact;
#[cfg(feature = "alloc")]
pub use mesh::{MeshConvexPair, MeshPair, MeshWorkspace, TraversalStats};
/// The stepper of a mesh against a convex shape or a half-space, under its
/// old name.
#[cfg(feature = "alloc")]
#[deprecated(since = "0.1.0", note = "renamed `MeshConvexPair`")]
pub type MeshShapePair<'a, T> = MeshConvexPair<'a, T>;
#[cfg(feature = "alloc")]
pub use arg_error::{ArgError, Problem};
pub use outcome::{CaOutcome, CaReport, Contact, ContactCriterion, Witness, Work};
#[cfg(feature = "alloc")]
pub use owned::{Hull, OwnedCompound, OwnedMesh, OwnedPart, OwnedShape, PreparedShape, Primitive};
pub use params::{BoundChoice, CaError, CaParams, MeshParams, Parameter, WitnessSearch};
#[cfg(feature = "alloc")]
pub use past_contact::{past_contact, past_contact_below, Below, Ceiling, PastContact};
#[cfg(feature = "alloc")]
pub use shape::{Compound, Part, Shape, ShapeKind};
pub use step::{gap_step, placement_error, CaStep, StepResult};
pub use vertex_set_vertex_set::{GjkProximity, Proximity, VertexSetPair};
