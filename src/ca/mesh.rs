//! Conservative advancement of two triangle meshes through their ball trees.

use alloc::vec::Vec;

use crate::bvh::{BallTree, Leaf};
use crate::ca::driver::{gap_step, placement_error};
use crate::ca::{CaParams, CaStep, StepResult, Witness};
use crate::geometry::triangle_triangle;
use crate::{BoundKind, Direction, Float, Pose, PreparedMotion, Vec3};

/// Work counters of a [`MeshPair`], summed over every step since the last
/// [`MeshPair::reset_stats`]: what a profile of the query needs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TraversalStats {
    /// Node pairs popped from the traversal stack.
    pub node_pairs: u64,
    /// Node pairs discarded because their own safe step already exceeded the
    /// best step found (or the rest of the interval).
    pub pruned: u64,
    /// Triangle pairs whose exact distance was computed.
    pub triangle_pairs: u64,
    /// Directed bounds evaluated (two per node pair that is separated).
    pub bounds: u64,
}

/// Conservative advancement of two non-convex triangle meshes (a
/// [`CaStep`]): one step is a simultaneous descent of both ball trees.
///
/// For a node pair with balls `(s_a, rho_a)`, `(s_b, rho_b)` placed at time
/// `t`, the direction `n` joining the centres separates the balls by the gap
/// `g = |c_b - c_a| - rho_a - rho_b`; every point below the pair moves along
/// `n` at most at the balls' directed bounds `mu_a + mu_b` (EVQ of a ball is
/// `O(1)`), so the pair cannot touch before `g / (mu_a + mu_b)`. A pair whose
/// step is at least the best step found so far is pruned; triangle pairs get
/// their exact distance, their own closest direction and the bounds of their
/// three corners. The least step over the cut is safe for the whole meshes
/// (`proofs/09-ca-toi.md`).
#[derive(Debug)]
pub struct MeshPair<'a, T> {
    a: &'a BallTree<T>,
    b: &'a BallTree<T>,
    stack: Vec<(u32, u32)>,
    stats: TraversalStats,
}

impl<'a, T: Float> MeshPair<'a, T> {
    /// The pair of meshes `a` and `b` (each relative to its rotation centre).
    #[must_use]
    pub fn new(a: &'a BallTree<T>, b: &'a BallTree<T>) -> Self {
        Self {
            a,
            b,
            stack: Vec::with_capacity(64),
            stats: TraversalStats::default(),
        }
    }

    /// The work done since the pair was made or last reset.
    #[must_use]
    pub const fn stats(&self) -> TraversalStats {
        self.stats
    }

    /// Resets the work counters.
    pub fn reset_stats(&mut self) {
        self.stats = TraversalStats::default();
    }
}

/// What one body contributes at the current time.
struct Placed<'p, T> {
    pose: Pose<T>,
    motion: &'p PreparedMotion<T>,
    err: T,
    reach: T,
}

impl<T: Float> Placed<'_, T> {
    fn centre(&self, tree: &BallTree<T>, node: u32) -> Vec3<T> {
        self.pose
            .transform_point(Vec3::from_array(*tree.nodes[node as usize].ball.centre()))
    }

    fn corners(&self, leaf: &Leaf<T>) -> [Vec3<T>; 3] {
        leaf.corners
            .map(|c| self.pose.transform_point(Vec3::from_array(c)))
    }

    fn leaf_speed(&self, leaf: &Leaf<T>, n: Direction<T>, kind: BoundKind) -> T {
        let probe = self.motion.probe(n);
        match kind {
            BoundKind::Nevq => probe.nevq_speed_radius(leaf.r_hat),
            _ => probe.evq_speed_points(&leaf.corners, leaf.r_hat),
        }
    }
}

impl<T: Float> CaStep<T> for MeshPair<'_, T> {
    fn step(
        &mut self,
        t: T,
        a: &PreparedMotion<T>,
        b: &PreparedMotion<T>,
        params: &CaParams<T>,
    ) -> StepResult<T> {
        let place = |tree: &BallTree<T>, m: &'_ PreparedMotion<T>| {
            let (err, reach) = placement_error(m.motion(), t, tree.root_ball().outer_radius_up());
            (m.motion().pose_at(t), err, reach)
        };
        let (pose, err, reach) = place(self.a, a);
        let pa = Placed {
            pose,
            motion: a,
            err,
            reach,
        };
        let (pose, err, reach) = place(self.b, b);
        let pb = Placed {
            pose,
            motion: b,
            err,
            reach,
        };
        let kind = params.bound.cheap_kind();
        let mut best = b.motion().interval().end() - t;
        let mut witness: Option<Witness<T>> = None;
        let mut normal = None;
        self.stack.clear();
        self.stack.push((0, 0));
        while let Some((i, j)) = self.stack.pop() {
            self.stats.node_pairs += 1;
            let (na, nb) = (&self.a.nodes[i as usize], &self.b.nodes[j as usize]);
            if let (Some(la), Some(lb)) = (na.leaf(), nb.leaf()) {
                let (la, lb) = (&self.a.leaves[la], &self.b.leaves[lb]);
                self.stats.triangle_pairs += 1;
                let (ta, tb) = (pa.corners(la), pb.corners(lb));
                let cp = triangle_triangle(&ta, &tb);
                let w = Witness {
                    distance: cp.distance,
                    on_a: cp.on_a,
                    on_b: cp.on_b,
                };
                let dir = Direction::try_new(cp.on_b - cp.on_a);
                let (Ok(n), true) = (dir, cp.distance > params.contact_distance) else {
                    return StepResult::Touching {
                        witness: w,
                        normal: dir.ok().map(Direction::get),
                    };
                };
                let nv = n.get();
                // The slab between the triangles along n: min over B - max over A.
                let lo_b = tb[0].dot(nv).min_nan(tb[1].dot(nv)).min_nan(tb[2].dot(nv));
                let hi_a = ta[0].dot(nv).max_nan(ta[1].dot(nv)).max_nan(ta[2].dot(nv));
                self.stats.bounds += 2;
                let mu = (pa.leaf_speed(la, n, kind), pb.leaf_speed(lb, n, kind));
                let (step, _) = gap_step(lo_b - hi_a, (pa.err, pb.err), (pa.reach, pb.reach), mu);
                if witness.is_none_or(|b: Witness<T>| w.distance < b.distance) {
                    witness = Some(w);
                }
                if step < best {
                    best = step;
                    normal = Some(nv);
                }
                continue;
            }
            let (ca, cb) = (pa.centre(self.a, i), pb.centre(self.b, j));
            let d = cb - ca;
            let (ra, rb) = (na.ball.radius(), nb.ball.radius());
            if let Ok(n) = Direction::try_new(d) {
                let nv = n.get();
                let gap = d.dot(nv) - ra - rb;
                if gap > T::ZERO {
                    self.stats.bounds += 2;
                    let mu = (
                        a.probe(n).ball_speed(&na.ball, kind),
                        b.probe(n).ball_speed(&nb.ball, kind),
                    );
                    let (step, _) = gap_step(gap, (pa.err, pb.err), (pa.reach, pb.reach), mu);
                    if step >= best {
                        self.stats.pruned += 1;
                        continue;
                    }
                }
            }
            // Descend into the larger ball (a leaf is never split).
            let split_a = nb.leaf().is_some() || (na.leaf().is_none() && ra >= rb);
            if split_a {
                self.stack.push((na.right, j));
                self.stack.push((na.left, j));
            } else {
                self.stack.push((i, nb.right));
                self.stack.push((i, nb.left));
            }
        }
        StepResult::Advance {
            step: best,
            witness,
            normal,
        }
    }
}
