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
pub(crate) mod gjk;
// The polytope support's vertex clusters (built with `alloc`).
pub(crate) mod hull_clusters;
// A point set's hull vertices (a superset), for the chains' link hulls.
#[cfg(feature = "alloc")]
pub(crate) mod hull_vertices;
mod intersect;
pub(crate) mod predicates;
mod scale;
mod simplex;
// The exact inside test of closed meshes (solid meshes need `alloc`).
#[cfg(feature = "alloc")]
pub(crate) mod winding;

/// Hand-made triangle pairs shared by the unit tests of both intersection
/// tests (`exact`, the testkit's, and `intersect`, the core's filtered ones
/// with an exact fallback):
/// every case against [`HAND_MADE_BASE`], with the expected answer.
#[cfg(test)]
pub(crate) const HAND_MADE_BASE: [[f64; 3]; 3] =
    [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]];

/// See [`HAND_MADE_BASE`].
#[cfg(test)]
pub(crate) const HAND_MADE_CASES: [(&str, [[f64; 3]; 3], bool); 16] = [
    (
        "piercing",
        [[0.5, 0.5, -1.0], [0.5, 0.5, 1.0], [3.0, 3.0, 0.5]],
        true,
    ),
    (
        "above",
        [[0.5, 0.5, 0.1], [0.6, 0.5, 1.0], [3.0, 3.0, 0.5]],
        false,
    ),
    (
        "shared vertex",
        [[0.0, 0.0, 0.0], [-1.0, 0.0, 1.0], [0.0, -1.0, 1.0]],
        true,
    ),
    (
        "shared edge",
        [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [1.0, -1.0, 1.0]],
        true,
    ),
    (
        "vertex on face",
        [[0.5, 0.5, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 1.0]],
        true,
    ),
    (
        "vertex on edge",
        [[1.0, 0.0, 0.0], [1.0, -1.0, 1.0], [2.0, -1.0, 1.0]],
        true,
    ),
    (
        "standing outside",
        [[3.0, 3.0, 0.0], [0.5, 0.5, 1.0], [0.6, 0.4, 1.0]],
        false,
    ),
    (
        "coplanar overlap",
        [[1.0, 1.0, 0.0], [3.0, 1.0, 0.0], [1.0, 3.0, 0.0]],
        true,
    ),
    (
        "coplanar inside",
        [[0.1, 0.1, 0.0], [0.5, 0.1, 0.0], [0.1, 0.5, 0.0]],
        true,
    ),
    (
        "coplanar apart",
        [[1.5, 1.5, 0.0], [3.0, 1.5, 0.0], [1.5, 3.0, 0.0]],
        false,
    ),
    (
        "coplanar touching",
        [[1.0, 1.0, 0.0], [3.0, 1.0, 0.0], [1.0, 3.0, 0.0]],
        true,
    ),
    (
        "linked",
        [[1.0, 0.5, -2.0], [1.0, 0.5, 2.0], [1.0, -3.0, 0.0]],
        true,
    ),
    (
        "segment through face",
        [[0.5, 0.5, -1.0], [0.5, 0.5, 0.0], [0.5, 0.5, 1.0]],
        true,
    ),
    (
        "segment in plane, outside",
        [[3.0, 0.0, 0.0], [4.0, 0.0, 0.0], [5.0, 0.0, 0.0]],
        false,
    ),
    ("point in face", [[0.5, 0.5, 0.0]; 3], true),
    ("point off face", [[0.5, 0.5, 0.5]; 3], false),
];
