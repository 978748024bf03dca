//! Distance queries between triangles and convex polytopes.
//!
//! Conservative advancement needs, at each step, the distance `d` between
//! the two bodies and the closest direction `n`; this module supplies both:
//! [`closest`] for exact triangle-level queries (the ground truth and the
//! per-triangle-pair query of a bounding-volume traversal), [`gjk`] for
//! convex polytopes. Everything is `no_std`, allocation-free and generic over
//! [`Float`](crate::Float).

// `!(x > 0)` is written on purpose throughout: unlike `x <= 0` it is true
// for NaN, which must take the degenerate branch.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub(crate) mod closest;
#[cfg(feature = "testkit")]
pub(crate) mod exact;
pub(crate) mod gjk;
mod intersect;
mod predicates;
mod scale;
mod simplex;
