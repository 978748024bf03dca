//! # motion-bound
//!
//! Certified continuous collision detection of rigid bodies: the first time
//! of contact of two moving bodies by conservative advancement (CA), never
//! later than the first touch and never missed, with the rounding of every
//! step accounted for. CA steps time forward by `d / mu`, `d` the bodies'
//! distance and `mu` an upper bound of how fast any point approaches along
//! the closest direction; this crate computes such bounds ([NEVQ and
//! EVQ](#the-bounds-nevq-and-evq)), proves them, and drives CA with them for
//! every kind of shape an engine has.
//!
//! ## Time of impact of two shapes
//!
//! A body is a [`ca::Shape`] in its own frame: a [`Convex`] shape (ball,
//! capsule, cuboid, cylinder, cone, polytope, rounded or not), a
//! [`VertexSet`], a [`BoundingBall`], a triangle mesh through its
//! [`BallTree`], a [`HalfSpace`] or a [`ca::Compound`] of these. A motion is
//! its pose at `t = 0` with constant linear and angular velocity over an
//! interval ([`RigidMotion`]). [`ca::AnyPair`] picks the stepper for any two
//! shapes and [`ca::time_of_impact`] runs CA with it:
//!
//! ```
//! use motion_bound::ca::{time_of_impact, AnyPair, CaOutcome, CaParams, Shape};
//! use motion_bound::{BallTree, Convex, RigidMotion, TriMesh};
//!
//! // A tetrahedron, its tree built once in its own frame, standing still.
//! let tet = TriMesh::try_new(
//!     vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
//!     vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
//! )?;
//! let tree = BallTree::try_from_mesh(&tet)?;
//! let still = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0; 3])?;
//! // A board (half extents 0.5, 0.1, 0.3) flung at it along +x over [0, 1],
//! // spinning about z at 3 rad per unit time.
//! let board = Convex::try_cuboid([0.5, 0.1, 0.3])?;
//! let flung = RigidMotion::try_from_arrays([-3.0, 0.2, 0.2], [4.0, 0.0, 0.0], [0.0, 0.0, 3.0])?;
//!
//! let mut pair = AnyPair::try_new(Shape::Convex(board), Shape::Mesh(&tree))?;
//! let report = time_of_impact(&mut pair, &flung, &still, &CaParams::default())?;
//! match report.outcome {
//!     // Whatever its angle, the board reaches at most |(0.5, 0.1, 0.3)| < 0.6
//!     // and at least 0.1 from its centre: it cannot meet the tetrahedron's
//!     // face x = 0 before its centre passes x = -0.6 (t = 2.4 / 4), and it
//!     // touches that face by the time its centre reaches x = -0.1 (t = 2.9 / 4).
//!     CaOutcome::Contact { contact, .. } => {
//!         assert!(contact.time > 2.4 / 4.0 && contact.time <= 2.9 / 4.0)
//!     }
//!     other => panic!("expected a contact, got {other:?}"),
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! Outcomes: a [`Contact`](ca::CaOutcome::Contact) (with the time, the
//! witness points and the normal), an
//! [`InitialContact`](ca::CaOutcome::InitialContact), a certified
//! [`Separated`](ca::CaOutcome::Separated), or a possible contact at the time
//! reached ([`ca::CaOutcome::IterationLimit`],
//! [`ca::CaOutcome::WorkLimit`], [`ca::CaOutcome::PrecisionLimit`]), never a
//! miss. A contact is never later than the first time the surfaces come
//! within half the contact distance ([`proofs::ca_toi`]). Every query runs in
//! the pair's own frame (the world translated to body A's start), so its
//! precision does not depend on where the pair is, and its work is bounded
//! ([`ca::CaParams::work_budget`]). A contact's witness is the closest
//! triangle pair ([`ca::WitnessSearch`]).
//!
//! Each pair of kinds has its stepper, which [`ca::AnyPair`] picks: two
//! meshes through their ball trees ([`ca::MeshPair`]), a mesh and a convex
//! shape or half-space ([`ca::MeshConvexPair`]), convex vertex sets with GJK
//! or an engine's own distance oracle ([`ca::VertexSetPair`]), two balls
//! ([`ca::BallPair`]), two convex shapes ([`ca::ConvexPair`]), a convex shape
//! and a half-space ([`ca::HalfSpacePair`]). Build one directly to tune it,
//! or implement [`ca::CaStep`] for your own geometry. In an engine loop, make
//! each frame's motions with [`RigidMotion::try_about_centre`] or
//! [`RigidMotion::try_between`] and keep one [`ca::MeshWorkspace`]: a steady
//! loop then allocates nothing.
//!
//! ## Scenes
//!
//! [`scene::Scene`] holds many bodies of any kinds over one frame and answers
//! every pair's first contact at once, after a certified broad phase (each
//! body's [`scene::SweptBox`], a sweep and prune) that skips what cannot
//! touch; the skips are proved in [`proofs::scene`] and counted in
//! [`scene::SceneStats`]. With the feature `parallel`,
//! [`Scene::par_query`][par-query] runs the narrow phase on every core. See the [`scene`] module.
//!
//! ```
//! use motion_bound::ca::Shape;
//! use motion_bound::scene::{Scene, SceneParams, SceneWorkspace};
//! use motion_bound::{Convex, HalfSpace, Isometry, RigidMotion, TimeInterval, Vec3};
//!
//! let mut scene = Scene::try_new(TimeInterval::try_new(0.0, 1.0)?)?;
//! let ground = Shape::HalfSpace(HalfSpace::try_new(Vec3::new(0.0, 1.0, 0.0))?);
//! let ball = Shape::Convex(Convex::try_ball(0.5)?);
//! scene.try_add_static(ground, Isometry::try_from_translation(Vec3::new(0.0, 0.0, 0.0))?)?;
//! // A ball falling from y = 2.5 at 4 per unit time, and one far off drifting sideways.
//! let falling = scene.try_add(ball, RigidMotion::try_from_arrays([0.0, 2.5, 0.0], [0.0, -4.0, 0.0], [0.0; 3])?)?;
//! scene.try_add(ball, RigidMotion::try_from_arrays([50.0, 20.0, 0.0], [1.0, 0.0, 0.0], [0.0; 3])?)?;
//! let mut ws = SceneWorkspace::new();
//! let report = scene.query(&mut ws, &SceneParams::default())?;
//! // The falling ball's lowest point reaches the ground at t = 2 / 4.
//! let (t, _ground) = report.earliest_for(falling).expect("it lands");
//! assert!(t <= 0.5 && t > 0.5 - 1e-4);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! ## The bounds: NEVQ and EVQ
//!
//! Both follow Zhang, Lee and Kim's erratum "Computation of the Upper Bound
//! of Motion" (2006) to *Interactive continuous collision detection for
//! non-convex polyhedra* (The Visual Computer 23, 2007,
//! [doi:10.1007/s00371-007-0172-y](https://doi.org/10.1007/s00371-007-0172-y)):
//!
//! * [`nevq`], the seed's Eq. 3: `|v.n| + |n x w| max_i |r_i|`, `O(1)` per query;
//! * [`evq`], the seed's Eq. 1 by a corrected case split of its Eq. 2: the
//!   largest `|c(t) . r_i^c|` over the arc swept by `c(t) = R(t)^T (n x w)` in
//!   the rotation plane; `O(N)` per query and never looser than [`nevq`].
//!
//! Every bound is proven in `proofs/`, rendered in [`proofs`] (the printed
//! Eq. 2 is not a valid bound: [`proofs::evq_case_split`] says where and
//! why), is an upper bound for its floating-point inputs with rounding
//! accounted for ([`proofs::floating_point`]), and is checked by property
//! tests against an exact closed-form [`reference`][reference-mod].
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
//! ## Robot arms
//!
//! [`chain::Chain`] is a kinematic tree (links with collision meshes;
//! revolute, continuous, prismatic and fixed joints), from code or a URDF
//! (feature `urdf`); [`chain::ChainScene`] checks its joint-space segments
//! `q0 -> q1` against still obstacles and itself by conservative advancement
//! with a directed bound through the joints above each link
//! ([`proofs::chains`]): the first contact, never later than the first touch,
//! or `Separated`. A planner's motion validator calls
//! [`chain::ChainScene::edge_is_free`] (or a reused [`chain::EdgeChecker`]):
//! the edge certified in one pass per time interval, against meshes, shape
//! obstacles ([`chain::ShapeObstacle`]: primitives, half-spaces, point
//! clouds) and the arm itself. See the [`chain`] module.
//!
//! ## Conventions
//!
//! * **Frames.** `n`, `v`, `w` and positions are world vectors; body points
//!   are in the body's own frame (the frame its [`VertexSet`] or
//!   [`BallTree`] is built in). The bounds are invariant under a rigid change
//!   of the world frame.
//! * **Motion.** `p(t) = x0 + v t + R(w t) Q0 (r - c)`: `Q0` the start
//!   orientation (a [`Rotation`]), `c` the rotation centre in the body frame
//!   (the origin by default), `x0` its world position at the epoch `t = 0`,
//!   `R(w t)` the right-handed rotation about `w/|w|` by `|w| t`
//!   ([`RigidMotion`]).
//! * **Time.** Velocities are per unit time; a motion's interval is any
//!   `[t_a, t_b]` (a frame `[0, T]` from [`RigidMotion::try_from_start`]);
//!   [`RigidMotion::restrict`] narrows it and keeps the epoch.
//! * **Direction.** `n` is the unit closest direction *from the moving body
//!   towards the obstacle*; the absolute bounds bound `|p'(t) . n|` (so they
//!   hold for `-n` too), the one-sided ones ([`nevq_rate`], [`evq_rate`]) the
//!   signed `p'(t) . n`. [`Direction::try_new`] normalises any nonzero vector.
//! * **What is bounded.** [`DirectedBound::speed`] bounds the directed speed
//!   at every time of the interval (what a CA step `d / mu` needs);
//!   [`DirectedBound::displacement`] bounds the directed displacement (the
//!   seed's `mu`, an integral). See [`DirectedBound`].
//! * **Bad input** gets a typed [`InputError`] at construction; evaluation
//!   never panics and never returns NaN; `+inf` (sound) only on overflow.
//!
//! ## Distances
//!
//! [`try_triangle_triangle`] (with [`try_point_triangle`] and [`try_segment_segment`])
//! gives the exact Euclidean distance of two triangles with witness points,
//! and [`gjk_distance`] the distance of two convex bodies given by a
//! [`SupportMap`], such as a [`ConvexPolytope`] placed by a [`Pose`]. GJK's
//! `distance` may over-estimate; its `lower_bound` is certified along its
//! `direction`. See [`GjkResult`].
//!
//! ## Precision
//!
//! Both `f32` (what game engines use) and `f64` are supported through one
//! generic code path over the sealed trait [`Float`], because the error
//! analysis is the same formula in the unit roundoff `u` of either type.
//!
//! ## Proofs
//!
//! Every lemma is written out in `proofs/` and rendered in [`proofs`]: the
//! bounds ([`proofs::nevq`], [`proofs::evq_case_split`]), conservative
//! advancement ([`proofs::ca_toi`]) and the rounding analysis
//! ([`proofs::floating_point`]), each naming the tests that check it.
//!
//! ## Feature flags
//!
//! | feature | default | what it adds |
//! |---|---|---|
//! | `std` | yes | float functions from `std`; implies `alloc` |
//! | `libm` | no | float functions from `libm`; with `std` off the crate is `#![no_std]` (and allocation-free unless `alloc` is on) |
//! | `alloc` | with `std` | owned meshes ([`TriMesh`]), ball trees ([`BallTree`]), the mesh stepper, chains ([`chain`]), OFF and STL input, OFF output; needs no `std` |
//! | `bodies` | no | built-in test bodies ([`bodies`][bodies-mod]): the seed's torus knots, tori, boards, boxes, icospheres (`scenes`, its old name, still turns it on) |
//! | `obj` | no | OBJ input with `tobj` (`TriMesh::from_obj_str`); implies `std` and `alloc` |
//! | `urdf` | no | chains from URDF files (`Chain::from_urdf_file`, with `urdf-rs`), their meshes as OBJ or STL; implies `obj` |
//! | `mint` | no | conversions to and from `mint` vectors, points and quaternions (glam, nalgebra and cgmath interop) |
//! | `approx` | no | `approx` comparison traits on the public vector types |
//! | `reference` | no | **test support**: the exact closed-form oracle ([`reference`][reference-mod]) |
//! | `faer` | no | **test support**: batched dense sampling of the oracle with faer |
//! | `testkit` | no | **test support**: hard-case generators, the time-of-impact ground truth, the Table 1 scenes ([`testkit`][testkit-mod]) |
//! | `parallel` | no | [`Scene::par_query`][par-query]: a scene's narrow phase on every core (rayon); implies `std` |
//! | `arbitrary` | no | **test support**: `Arbitrary` case descriptions for `cargo fuzz` |
//!
//! The core's one dependency is [robust](https://crates.io/crates/robust)
//! (Shewchuk's adaptive predicates, `no_std` and allocation-free): the exact
//! fallback of the filtered orientation predicates with which
//! [`try_triangle_triangle`] decides meeting.
//!

// The links to items behind features: to the item when the feature is on, else to docs.rs
// (built with every feature), so that `cargo doc` has no broken link under any feature set.
#![cfg_attr(feature = "bodies", doc = "[bodies-mod]: crate::bodies")]
#![cfg_attr(
    not(feature = "bodies"),
    doc = "[bodies-mod]: https://docs.rs/motion-bound/latest/motion_bound/bodies/index.html"
)]
#![cfg_attr(feature = "reference", doc = "[reference-mod]: mod@crate::reference")]
#![cfg_attr(
    not(feature = "reference"),
    doc = "[reference-mod]: https://docs.rs/motion-bound/latest/motion_bound/reference/index.html"
)]
#![cfg_attr(feature = "testkit", doc = "[testkit-mod]: crate::testkit")]
#![cfg_attr(
    not(feature = "testkit"),
    doc = "[testkit-mod]: https://docs.rs/motion-bound/latest/motion_bound/testkit/index.html"
)]
#![cfg_attr(
    feature = "parallel",
    doc = "[par-query]: crate::scene::Scene::par_query"
)]
#![cfg_attr(
    not(feature = "parallel"),
    doc = "[par-query]: https://docs.rs/motion-bound/latest/motion_bound/scene/struct.Scene.html#method.par_query"
)]
#![cfg_attr(not(feature = "std"), no_std)]
#![cfg_attr(docsrs, feature(doc_cfg))]
#![forbid(unsafe_code)]
#![warn(missing_docs, unreachable_pub, clippy::missing_assert_message)]

#[cfg(feature = "alloc")]
extern crate alloc;

#[cfg(not(any(feature = "std", feature = "libm")))]
compile_error!("motion-bound needs either the `std` or the `libm` feature for its float functions");

mod bound;
#[cfg(feature = "alloc")]
mod bvh;
// Without the oracle (`reference`), only a chain's clearance uses it.
pub mod ca;
#[cfg(feature = "alloc")]
#[cfg_attr(docsrs, doc(cfg(feature = "alloc")))]
pub mod chain;
#[cfg_attr(not(feature = "reference"), allow(dead_code, unreachable_pub))]
mod dd;
mod error;
mod features;
mod float;
mod geometry;
mod math;
#[cfg(feature = "alloc")]
mod mesh;
mod motion;
#[cfg(any(test, feature = "testkit"))]
mod rng;
mod rounding;
#[cfg(feature = "alloc")]
#[cfg_attr(docsrs, doc(cfg(feature = "alloc")))]
pub mod scene;
mod shape;

#[cfg(feature = "bodies")]
#[cfg_attr(docsrs, doc(cfg(feature = "bodies")))]
pub mod bodies;
pub mod proofs;
#[cfg(feature = "reference")]
#[cfg_attr(docsrs, doc(cfg(feature = "reference")))]
pub mod reference;
/// The built-in test bodies under their old path: [`bodies`].
#[cfg(feature = "bodies")]
#[doc(hidden)]
#[deprecated(
    since = "0.1.0",
    note = "renamed `bodies` (so that it cannot be read as `scene`)"
)]
pub mod scenes {
    pub use crate::bodies::*;
}
#[cfg(feature = "testkit")]
#[cfg_attr(docsrs, doc(cfg(feature = "testkit")))]
pub mod testkit;

pub use bound::directed::{BoundKind, DirectedBound};
pub use bound::directed_bound;
#[cfg(feature = "testkit")]
pub use bound::evq::evq_speed_unmargined;
pub use bound::evq::{evq, evq_rate, evq_speed};
#[cfg(feature = "testkit")]
pub use bound::nevq::nevq_speed_unmargined;
pub use bound::nevq::{nevq, nevq_rate, nevq_speed};
pub use bound::probe::DirectedProbe;
#[cfg(feature = "alloc")]
pub use bvh::{BallTree, VertexTree};
pub use error::{InputError, Quantity};
pub use float::Float;
pub use geometry::closest::{
    try_point_triangle, try_segment_segment, try_triangle_triangle, ClosestPoints,
};
pub use geometry::gjk::{gjk_distance, ConvexPolytope, GjkParams, GjkResult, SupportMap};
pub use math::direction::Direction;
pub use math::isometry::Isometry;
pub use math::point::{BodyPoint, Point3};
pub use math::pose::Pose;
pub use math::rotation::Rotation;
pub use math::rotation_plane::{rotate_about_axis, RotationPlane};
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
pub use shape::convex::{Convex, ConvexKind};
pub use shape::half_space::HalfSpace;

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
