//! A body that starts inside a solid mesh is in contact with it: the check
//! the mesh steppers make once per query, at its start
//! (`proofs/09-ca-toi.md`, Lemma 9.7).
//!
//! The steps measure distances between surfaces, so a body wholly inside a
//! closed mesh is never near its triangles. A body that does not meet a
//! solid mesh's surface lies wholly inside or wholly outside it (each of
//! its connected pieces does), so one point of each piece, tested exactly
//! against the placed triangles, decides; and a motion cannot carry a body
//! inside without crossing the surface, which the steps see, so the start is
//! the only time to check.

use alloc::vec::Vec;

use crate::bvh::{BallTree, Hierarchy};
use crate::ca::step::placement_error;
use crate::ca::{Shape, StepResult, Witness, Work};
use crate::geometry::winding::{ray_crossing, Winding};
use crate::rounding::sum_up;
use crate::shape::convex::Core;
use crate::{Float, Point3, Pose, PreparedMotion, Vec3};

/// The points of a body tested inside the other body's solid mesh, in its
/// body frame.
#[derive(Clone, Copy, Debug)]
enum Probes<'a, T> {
    /// A convex shape's, a vertex set's or a ball's one point: a point of
    /// its core (the core's origin, or a polytope's first vertex, placed
    /// as the shape's support places it), a set's first vertex, a ball's
    /// centre.
    Point([T; 3]),
    /// A mesh's point of each connected component (`BallTree::probes`).
    Mesh(&'a [[T; 3]]),
    /// None: a half-space is unbounded, so it cannot lie inside a mesh
    /// without crossing its surface; a compound's parts are paired one by
    /// one (`CompoundPair`).
    Nothing,
}

impl<'a, T: Float> Probes<'a, T> {
    fn of(shape: Shape<'a, T>) -> Self {
        match shape {
            Shape::Convex(c) => {
                let local = match c.core() {
                    Core::Polytope(set) => Vec3::from_array(set.vertices()[0]),
                    _ => Vec3::ZERO,
                };
                Self::Point(c.place_core_point(local).to_array())
            }
            Shape::VertexSet(set) => Self::Point(set.vertices()[0]),
            Shape::Ball(ball) => Self::Point(*ball.centre()),
            Shape::Mesh(tree) => Self::Mesh(&tree.probes),
            Shape::HalfSpace(_) | Shape::Compound(_) => Self::Nothing,
        }
    }

    fn points(&self) -> &[[T; 3]] {
        match self {
            Self::Point(p) => core::slice::from_ref(p),
            Self::Mesh(points) => points,
            Self::Nothing => &[],
        }
    }
}

/// How many node visits (a placed centre and three comparisons, about
/// 10 ns) and how many ray-triangle tests the check does for one node pair
/// and one triangle pair of the work budget (a node pair of a descent costs
/// 0.6 to 1 us: `CaParams::DEFAULT_WORK_BUDGET`).
const PER_UNIT: u64 = 16;

/// The check at a query's start of a pair of bodies A and B: B's points
/// inside A's mesh when A is solid, A's inside B's when B is. Its work (a
/// node pair per [`PER_UNIT`] nodes of the solid hierarchy visited, a
/// triangle pair per [`PER_UNIT`] triangles tested) is counted with the
/// stepper's.
#[derive(Debug)]
pub(crate) struct StartCheck<'a, T> {
    into_a: Option<(&'a BallTree<T>, Probes<'a, T>)>,
    into_b: Option<(&'a BallTree<T>, Probes<'a, T>)>,
    /// Nodes visited and triangles tested since the check was made.
    visits: u64,
    tests: u64,
    stack: Vec<u32>,
}

impl<'a, T: Float> StartCheck<'a, T> {
    /// The check of bodies of shapes `a` and `b` (nothing to check unless
    /// one is a solid mesh).
    pub(crate) fn new(a: Shape<'a, T>, b: Shape<'a, T>) -> Self {
        let solid = |s: Shape<'a, T>| match s {
            Shape::Mesh(tree) if tree.is_solid() => Some(tree),
            _ => None,
        };
        Self {
            into_a: solid(a).map(|tree| (tree, Probes::of(b))),
            into_b: solid(b).map(|tree| (tree, Probes::of(a))),
            visits: 0,
            tests: 0,
            stack: Vec::new(),
        }
    }

    /// The work done since the check was made, in the budget's units.
    pub(crate) const fn work(&self) -> Work {
        Work::new(
            self.visits.div_ceil(PER_UNIT),
            self.tests.div_ceil(PER_UNIT),
        )
    }

    /// At the query's start `t`, with the bodies moving by `a` and `b`:
    /// `Touching` (distance `0`, both witnesses at the point found, no
    /// normal) when a point of one body is inside the other's solid mesh
    /// (or on its surface, or undecided by the exact predicates: a contact
    /// is reported, never missed); `WorkLimit` when `budget` runs out first;
    /// `None` when every point is outside.
    pub(crate) fn run(
        &mut self,
        t: T,
        a: &PreparedMotion<T>,
        b: &PreparedMotion<T>,
        budget: Work,
    ) -> Option<StepResult<T>> {
        let limit = (
            self.visits
                .saturating_add(budget.node_pairs.saturating_mul(PER_UNIT)),
            self.tests
                .saturating_add(budget.triangle_pairs.saturating_mul(PER_UNIT)),
        );
        for (check, solid, other) in [(self.into_a, a, b), (self.into_b, b, a)] {
            let Some((tree, probes)) = check else {
                continue;
            };
            let hierarchy = &tree.whole;
            let pose = solid.motion().pose_at(t);
            let (err, _) = placement_error(solid.motion(), t, hierarchy.reach);
            let other_pose = other.motion().pose_at(t);
            for q in probes.points() {
                let p = other_pose.transform_point(*q);
                match self.winding(hierarchy, (&pose, err), p, limit) {
                    None => return Some(StepResult::WorkLimit),
                    Some(Winding::Number(0)) => {}
                    Some(_) => {
                        let at = Point3::from_vec3(p);
                        return Some(StepResult::Touching {
                            witness: Witness::new(T::ZERO, at, at),
                            normal: None,
                        });
                    }
                }
            }
        }
        None
    }

    /// The winding number about the placed point `p` of the hierarchy's
    /// triangles placed by `pose` (each placed point within `err` of its
    /// exact place), or `None` when the visits or the tests would pass
    /// `limit`. A node is skipped
    /// when the ray from `p` along `+x` cannot meet its placed triangles:
    /// they lie within `r + 2 err` of its placed centre (its ball holds its
    /// exact triangles, and both the centre and the corners are placed
    /// within `err`), and a rounded difference above a float bound means
    /// the exact one is (rounding is monotone).
    fn winding(
        &mut self,
        tree: &Hierarchy<T>,
        (pose, err): (&Pose<T>, T),
        p: Vec3<T>,
        limit: (u64, u64),
    ) -> Option<Winding> {
        let mut w = Winding::Number(0);
        self.stack.clear();
        self.stack.push(0);
        while let Some(i) = self.stack.pop() {
            // A visit tests at most one triangle.
            if self.visits >= limit.0 || self.tests >= limit.1 {
                return None;
            }
            self.visits += 1;
            let node = &tree.nodes[i as usize];
            let c = pose.transform_point(*node.ball.centre());
            let r = sum_up(node.ball.radius(), err + err);
            if (p.y - c.y).abs() > r || (p.z - c.z).abs() > r || p.x - c.x > r {
                continue;
            }
            match node.leaf() {
                Some(l) => {
                    self.tests += 1;
                    let corners = tree.leaves[l].corners.map(|q| pose.transform_point(q));
                    w = w.add(ray_crossing(p, &corners));
                    if w == Winding::Surface {
                        break;
                    }
                }
                None => {
                    self.stack.push(node.right);
                    self.stack.push(node.left);
                }
            }
        }
        Some(w)
    }
}
