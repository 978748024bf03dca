//! # motion-bound
//!
//! Verified directed motion bounds for conservative-advancement (CA)
//! continuous collision detection of rigid bodies.
//!
//! Conservative advancement finds the first time of contact of two moving
//! bodies by repeatedly stepping time forward by `d / mu`, where `d` is their
//! distance and `mu` bounds how fast any point of the moving body can
//! approach along the closest direction `n`. This crate computes such `mu`,
//! following Zhang, Lee and Kim's erratum "Computation of the Upper Bound of
//! Motion" (2006) to *Interactive continuous collision detection for
//! non-convex polyhedra* (The Visual Computer 23, 2007,
//! [doi:10.1007/s00371-007-0172-y](https://doi.org/10.1007/s00371-007-0172-y)):
//!
//! * [`nevq`], the seed's Eq. 3: `|v.n| + |n x w| max_i |r_i|`, `O(1)` per query;
//! * [`evq`], the seed's Eq. 1 by a corrected case split of its Eq. 2: the
//!   largest `|c(t) . r_i^c|` over the arc swept by `c(t) = R(t)^T (n x w)` in
//!   the rotation plane; `O(N)` per query and never looser than [`nevq`].
//!
//! Every bound is proven in `proofs/` (the printed Eq. 2 is not a valid
//! bound: `proofs/04-evq-case-split.md` says where and why), is an upper bound
//! for its floating-point inputs with rounding accounted for
//! (`proofs/floating-point.md`), and is checked by property tests against an
//! exact closed-form [`reference`](mod@reference).
//!
//! ```
//! use motion_bound::{evq, nevq, Direction, RigidMotion, Vec3, VertexSet};
//!
//! // A unit cube's corners, relative to its centre (the rotation centre).
//! let mut corners = [[0.0f64; 3]; 8];
//! for (i, c) in corners.iter_mut().enumerate() {
//!     for k in 0..3 {
//!         c[k] = if i >> k & 1 == 1 { 0.5 } else { -0.5 };
//!     }
//! }
//! let body = VertexSet::try_new(&corners)?; // summary computed once
//! // Moving along +x at 2 units per frame, spinning about z at 1 rad per frame.
//! let motion = RigidMotion::try_from_arrays([0.0; 3], [2.0, 0.0, 0.0], [0.0, 0.0, 1.0])?;
//! let n = Direction::try_new(Vec3::new(1.0, 1.0, 0.0))?;
//! let loose = nevq(&body.summary(), &motion, n);
//! let tight = evq(&body, &motion, n);
//! assert!(tight.speed <= loose.speed);
//! // Conservative advancement: with the bodies 0.1 apart along n, the first
//! // contact cannot happen before t = 0.1 / speed.
//! let dt = tight.time_to_close(0.1);
//! assert!(dt > 0.0);
//!
//! // A CA step restricts the motion to what is left of the frame; the body
//! // summary stays valid because the epoch does not move.
//! let rest = motion.restrict(dt, 1.0)?;
//! assert!(evq(&body, &rest, n).speed <= tight.speed);
//! # Ok::<(), motion_bound::InputError>(())
//! ```
//!
//! ## Conventions
//!
//! * **Frame.** All vectors (`n`, `v`, `w`, body points) are in one frame; the
//!   bounds are invariant under a rigid change of that frame.
//! * **Body points** ([`BodyPoint`], or `[T; 3]` in a [`VertexSet`]) are
//!   offsets from the rotation centre at the epoch `t = 0`:
//!   `p_i(t) = x0 + v t + R(t) r_i`, with `R(t)` the right-handed rotation about
//!   `w/|w|` by `|w| t`.
//! * **Time.** Velocities are per unit time; a frame is usually
//!   [`TimeInterval::UNIT`] `= [0, 1]`. Bounds are taken over the motion's
//!   interval ([`RigidMotion::restrict`] narrows it).
//! * **Direction.** `n` is the unit closest direction *from the moving body
//!   towards the obstacle*; the bounds bound `|p'(t) . n|`, so they hold for
//!   `-n` as well. [`Direction::try_new`] normalises any nonzero vector.
//! * **What is bounded.** [`DirectedBound::speed`] bounds the directed speed
//!   at every time of the interval (what a CA step `d / mu` needs);
//!   [`DirectedBound::displacement`] bounds the directed displacement (the
//!   seed's `mu`, an integral). See [`DirectedBound`].
//! * **Bad input** gets a typed [`InputError`] at construction; evaluation
//!   never panics and never returns NaN; `+inf` (sound) only on overflow.
//!
//! ## Meshes
//!
//! With the `alloc` feature, `TriMesh` owns a validated triangle mesh (the
//! body points of a non-convex body, offsets from its rotation centre), checks
//! that it is closed and outward-wound, reads and writes OFF (and OBJ with the
//! `obj` feature), and hands its vertices to the bounds as a [`VertexSet`];
//! the `scenes` module builds the seed's torus knots and other test bodies.
//! ## Distances
//!
//! A CA step needs the distance `d` and the direction `n` as well as the
//! bound `mu`. [`triangle_triangle`] (with [`point_triangle`] and
//! [`segment_segment`]) gives the exact Euclidean distance of two triangles
//! with witness points, and [`gjk_distance`] the distance of two convex
//! bodies given by a [`SupportMap`], such as a [`ConvexPolytope`] placed by a
//! [`Pose`]. GJK's `distance` may over-estimate (by about its relative
//! tolerance when converged); its `lower_bound` is certified, with the
//! rounding of the support maps accounted for, and holds along its
//! `direction`: use that pair for a step. See [`GjkResult`].
//!
//! ```
//! use motion_bound::{gjk_distance, ConvexPolytope, GjkParams, Pose, Vec3};
//! let tet = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
//! let a = ConvexPolytope::try_new(&tet, Pose::IDENTITY)?;
//! let b = a.with_pose(Pose::from_translation(Vec3::new(0.0, 0.0, 2.5)))?;
//! let r = gjk_distance(&a, &b, &GjkParams::default());
//! assert!(r.lower_bound <= 1.5 && r.lower_bound > 1.5 - 1e-12);
//! assert_eq!(r.direction, Some(Vec3::new(0.0, 0.0, 1.0)));
//! # Ok::<(), motion_bound::InputError>(())
//! ```
//!
//! ## Precision
//!
//! Both `f32` (what game engines use) and `f64` are supported through one
//! generic code path over the sealed trait [`Float`], because the error
//! analysis is the same formula in the unit roundoff `u` of either type: two
//! monomorphic modules would duplicate the proofs' constants for no gain.
//!
//! ## Feature flags
//!
//! | feature | default | what it adds |
//! |---|---|---|
//! | `std` | yes | float functions from `std` |
//! | `libm` | no | float functions from `libm`; with `std` off the crate is `#![no_std]` (and allocation-free unless `alloc` is on) |
//! | `alloc` | no | owned meshes (`TriMesh`), OFF input and output, the `scenes` generators; needs no `std` |
//! | `obj` | no | OBJ input with `tobj` (`TriMesh::from_obj_str`); implies `std` and `alloc` |
//! | `mint` | no | conversions to and from `mint` vectors (glam, nalgebra, cgmath interop) |
//! | `approx` | no | `approx` comparison traits on the public vector types |
//! | `reference` | no | the exact closed-form oracle ([`reference`](mod@reference)) |
//! | `faer` | no | batched dense sampling of the oracle with faer ([`reference::sampled`]) |
//! | `testkit` | no | shared hard-case generators for tests, fuzzing and benchmarks, the time-of-impact ground truth, and an exact triangle intersection test written apart from the core's; implies `alloc` |
//! | `arbitrary` | no | `Arbitrary` case descriptions for `cargo fuzz` |
//!
//! The core's one dependency is [`robust`] (Shewchuk's adaptive predicates,
//! `no_std` and allocation-free): the exact fallback of the filtered
//! orientation predicates with which [`triangle_triangle`] decides meeting.

#![cfg_attr(not(feature = "std"), no_std)]
#![forbid(unsafe_code)]
#![warn(missing_docs, unreachable_pub, clippy::missing_assert_message)]

#[cfg(feature = "alloc")]
extern crate alloc;

#[cfg(not(any(feature = "std", feature = "libm")))]
compile_error!("motion-bound needs either the `std` or the `libm` feature for its float functions");

mod bound;
#[cfg(feature = "alloc")]
mod bvh;
pub mod ca;
mod error;
mod features;
mod float;
mod geometry;
mod math;
#[cfg(feature = "alloc")]
mod mesh;
mod motion;
mod rounding;
mod shape;

#[cfg(feature = "reference")]
pub mod reference;
#[cfg(feature = "scenes")]
pub mod scenes;
#[cfg(feature = "testkit")]
pub mod testkit;

pub use bound::directed::{BoundKind, DirectedBound};
pub use bound::directed_bound;
#[cfg(feature = "testkit")]
pub use bound::evq::evq_speed_unmargined;
pub use bound::evq::{evq, evq_speed};
#[cfg(feature = "testkit")]
pub use bound::nevq::nevq_speed_unmargined;
pub use bound::nevq::{nevq, nevq_speed};
pub use bound::probe::DirectedProbe;
#[cfg(feature = "alloc")]
pub use bvh::BallTree;
pub use error::{InputError, Quantity};
pub use float::Float;
pub use geometry::closest::{point_triangle, segment_segment, triangle_triangle, ClosestPoints};
pub use geometry::gjk::{gjk_distance, ConvexPolytope, GjkParams, GjkResult, SupportMap};
pub use math::direction::Direction;
pub use math::isometry::Isometry;
pub use math::point::{BodyPoint, Point3};
pub use math::pose::Pose;
pub use math::quaternion::Rotation;
pub use math::rotation::{rotate_about_axis, RotationPlane};
pub use math::vec3::Vec3;
#[cfg(feature = "obj")]
pub use mesh::ObjError;
#[cfg(feature = "alloc")]
pub use mesh::{EdgeReport, MeshError, OffError, OffErrorKind, TriMesh};
pub use motion::arc::{PreparedMotion, SweptArc};
pub use motion::interval::TimeInterval;
pub use motion::rigid::RigidMotion;
pub use shape::ball::BoundingBall;
pub use shape::body::{BodySummary, VertexSet};

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
