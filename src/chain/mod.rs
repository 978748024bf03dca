//! Robot arms and other kinematic trees moving along joint-space segments:
//! certified continuous collision checking against still surroundings and
//! the chain itself.
//!
//! A [`Chain`] is a tree of links (each with a collision mesh in its own
//! frame and its [`BallTree`](crate::BallTree), built once) joined by
//! revolute, continuous, prismatic and fixed joints ([`JointKind`]), as in a
//! URDF (`Chain::from_urdf_file` with the feature `urdf`). A planner's
//! motion between two waypoints is the joint-space segment
//! `q(t) = q0 + t (q1 - q0)`, `t` in `[0, 1]`; no link of it moves with a
//! constant linear and angular velocity, so the rigid bounds of this crate
//! do not apply. What does, proved in `proofs/13-chains.md`:
//!
//! * **The chain bound** (Lemma 13.1): for a point `p` of link `k`, with
//!   `a_j`, `o_j` the world axis and a point on it of each movable joint `j`
//!   on the link's path and `r_j = |q1_j - q0_j|`,
//!   `|p'(t) . n| <= sum_turning r_j |n x a_j(t)| dist(p(t), axis_j(t)) + sum_sliding r_j |n . a_j(t)|`.
//! * **Over a sub-interval** `[t, t + h]` (Lemma 13.2): `|n x a_j|` grows by
//!   at most the angle the axis turns through, `h` times the rates of the
//!   turning joints above `j`; `dist(p, axis_j)` by at most `h` times the
//!   speed of `p` relative to joint `j`'s frame, bounded from the deepest
//!   joint up. For a ball of a link's tree (centre `c`, radius `rho`) both
//!   are `O(depth)` per node: the directed bound of a node pair.
//! * **Self-collision** (Lemma 13.2, last part): two links move rigidly
//!   together under the joints above their common ancestor; only the joints
//!   below it count.
//! * **Rounding** (Lemma 13.3): forward kinematics' error, a formula in `u`.
//!
//! **A planner's edges** (Lemmas 13.5 and 13.6):
//! [`ChainScene::edge_is_free`], [`ChainScene::check_edge`] and an
//! [`EdgeChecker`] for many edges place the chain once per time interval,
//! clear every link's ball (or box, or triangle) whose certified gap exceeds
//! what it can sweep in that interval, and refine down the link trees or
//! halve the interval only where one is not clear; obstacles may be meshes
//! ([`Obstacle`]) or shapes ([`ShapeObstacle`]: convex primitives,
//! half-spaces, point clouds), never meshed.
//!
//! [`ChainScene`] holds a chain and still obstacles of every kind, mixed:
//! meshes ([`Obstacle`]) and shapes ([`ShapeObstacle`]), and every query
//! takes them all. Its [`check_segment`](ChainScene::check_segment) runs
//! conservative advancement per pair of meshes and links (after a broad
//! phase of swept balls per sub-interval, [`ChainStats`]) and the edge
//! engine for the shapes, and reports the first contact's time, pair and
//! witnesses, never later than the first touch, or
//! [`SegmentOutcome::Separated`]; [`check_path`](ChainScene::check_path)
//! goes segment by segment; [`clearance`](ChainScene::clearance) and
//! [`collides_at`](ChainScene::collides_at) answer at one configuration.
//! Which engine serves a pair's kinds is decided in one place
//! (`chain/dispatch.rs`, `docs/architecture.md`).
//!
//! ```
//! use motion_bound::chain::{ChainBuilder, ChainScene, JointKind, JointSpec, Obstacle, SegmentOutcome};
//! use motion_bound::{Pose, TriMesh, Vec3};
//! // A one-link arm: a thin bar 1 long along x, turning about z.
//! let bar = TriMesh::try_new(
//!     vec![[0.0, -0.02, -0.02], [1.0, 0.0, 0.0], [0.0, 0.02, -0.02], [0.0, 0.0, 0.02]],
//!     vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
//! )?;
//! let mut b = ChainBuilder::new();
//! let base = b.add_link("base", None)?;
//! let arm = b.add_link("arm", Some(bar))?;
//! b.add_joint(JointSpec {
//!     name: "j1".into(),
//!     kind: JointKind::Revolute,
//!     parent: base,
//!     child: arm,
//!     origin: Pose::IDENTITY,
//!     axis: [0.0, 0.0, 1.0],
//!     limits: Some([-3.0, 3.0]),
//! })?;
//! let mut scene = ChainScene::new(b.build()?);
//! // A thin pole standing at 45 degrees, 0.7 from the axis.
//! let pole = TriMesh::try_new(
//!     vec![[0.0, 0.0, -1.0], [0.01, 0.0, -1.0], [0.0, 0.01, -1.0], [0.0, 0.0, 1.0]],
//!     vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
//! )?;
//! let at = Pose::from_translation(Vec3::new(0.495, 0.495, 0.0));
//! scene.add_obstacle(Obstacle::try_new("pole", pole, at)?);
//! // Sweeping from 0 to 1.5 rad hits it near 0.785 rad (t near 0.52);
//! // discrete checks 0.1 rad apart would step over the 0.01-wide pole.
//! let report = scene.check_segment(&[0.0], &[1.5])?;
//! let contact = report.outcome.contact().expect("the bar hits the pole");
//! assert!(contact.time > 0.45 && contact.time < 0.53);
//! // Turning the other way misses it.
//! assert_eq!(scene.check_segment(&[0.0], &[-1.5])?.outcome, SegmentOutcome::Separated);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod advance;
mod bound;
mod broad;
mod cover;
mod dispatch;
mod edge;
mod gap;
mod lanes;
mod lever;
mod model;
mod obstacle;
mod params;
mod proxy;
mod rake;
mod report;
mod scene;
mod segment;
mod shapes;
#[cfg(feature = "urdf")]
mod urdf;

pub use edge::{EdgeOutcome, EdgeReport, EdgeStats};
pub use model::{Chain, ChainBuilder, ChainError, JointKind, JointSpec};
pub use obstacle::Obstacle;
pub use params::ChainParams;
pub use report::{ChainContact, ChainPair, ChainStats, PathReport, SegmentOutcome, SegmentReport};
pub use scene::{ChainScene, EdgeChecker};
pub use shapes::ShapeObstacle;
#[cfg(feature = "urdf")]
pub use urdf::UrdfOptions;
