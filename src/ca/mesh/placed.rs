//! The bodies and their nodes placed at a step's time, how a pair's
//! closing speed is bounded, and the slab between two placed triangles:
//! what every descent measures with (`proofs/09-ca-toi.md`, Lemmas 9.1 and
//! 9.5).

use crate::bvh::{Hierarchy, Leaf};
use crate::ca::step::placement_error;
use crate::rounding::{add_up, crude_speed_up, lever_up, piece_speed_margin_up, BoxError};
use crate::{BoundKind, BoundingBall, Direction, Float, Pose, PreparedMotion, Vec3};

/// What one body contributes at the current time.
pub(super) struct Placed<'p, T> {
    pub(super) pose: Pose<T>,
    pub(super) motion: &'p PreparedMotion<T>,
    pub(super) err: T,
    pub(super) reach: T,
    /// The rotation's error coefficients for box supports (`|w| t`).
    pub(super) box_err: BoxError<T>,
    /// `|c|` rounded up, for a rotation centre `c` off the body origin.
    pub(super) lever_extra: T,
    /// `|v|_1` and `|w|_1` (the crude speed bound's ingredients).
    pub(super) v_l1: T,
    pub(super) w_l1: T,
}

/// A node placed at the current step: its centre, and its box's two long
/// axes in the world frame with their half extents (the box's middle
/// rectangle), computed once per node per pair creation and shared by the
/// pair's children.
#[derive(Clone, Copy, Debug)]
pub(super) struct PlacedNode<T> {
    pub(super) centre: Vec3<T>,
    pub(super) long: [Vec3<T>; 2],
    pub(super) half: [T; 2],
}

impl<T: Float> PlacedNode<T> {
    /// A node at `centre` with an empty rectangle (for tests).
    #[cfg(test)]
    pub(super) fn at(centre: Vec3<T>) -> Self {
        Self {
            centre,
            long: [Vec3::ZERO; 2],
            half: [T::ZERO; 2],
        }
    }

    /// The point of the node's middle rectangle nearest `p` (exactly so in
    /// exact arithmetic for orthonormal axes; otherwise some point near the
    /// rectangle, which is all its one use needs).
    #[inline]
    pub(super) fn nearest(&self, p: Vec3<T>) -> Vec3<T> {
        let x = p - self.centre;
        let s0 = x
            .dot(self.long[0])
            .max_nan(-self.half[0])
            .min_nan(self.half[0]);
        let s1 = x
            .dot(self.long[1])
            .max_nan(-self.half[1])
            .min_nan(self.half[1]);
        self.centre + self.long[0] * s0 + self.long[1] * s1
    }
}

impl<'p, T: Float> Placed<'p, T> {
    /// What the body of `tree` moving by `motion` contributes at time `t`:
    /// its pose, and the placement error and reach covering every node
    /// centre, box point and corner (all within the tree's certified reach
    /// of the body origin).
    pub(super) fn new(tree: &Hierarchy<T>, motion: &'p PreparedMotion<T>, t: T) -> Self {
        let m = motion.motion();
        let (err, reach) = placement_error(m, t, tree.reach);
        Self {
            pose: m.pose_at(t),
            motion,
            err,
            reach,
            box_err: BoxError::new(m.angle_at(t), !m.orientation().is_identity()),
            lever_extra: m.local_reach(),
            v_l1: m.linear().norm_l1(),
            w_l1: m.angular().norm_l1(),
        }
    }

    pub(super) fn place(&self, tree: &Hierarchy<T>, node: u32) -> PlacedNode<T> {
        let n = &tree.nodes[node as usize];
        let axis = |k: usize| self.pose.transform_vector(Vec3::from_array(n.obb.axes[k]));
        PlacedNode {
            centre: self.centre(tree, node),
            long: [axis(0), axis(1)],
            half: [n.obb.half[0], n.obb.half[1]],
        }
    }

    /// A crude, direction-free bound on the speed of every point within
    /// `radius` of the rotation centre: `|v| + |w| radius <= |v|_1 + |w|_1 radius`,
    /// rounded up (at most five roundings, covered by `1 + gamma_8`). It
    /// bounds the one-sided and the absolute speeds along any unit direction,
    /// so a step from it is safe (Lemma 9.1) and lets a pair be pruned before
    /// its directed bounds are computed.
    #[inline]
    pub(super) fn crude_speed(&self, radius: T) -> T {
        crude_speed_up(self.v_l1, self.w_l1, lever_up(radius, self.lever_extra))
    }

    fn centre(&self, tree: &Hierarchy<T>, node: u32) -> Vec3<T> {
        self.pose
            .transform_point(*tree.nodes[node as usize].ball.centre())
    }

    pub(super) fn corners(&self, leaf: &Leaf<T>) -> [Vec3<T>; 3] {
        leaf.corners.map(|c| self.pose.transform_point(c))
    }

    /// The placement error of a leaf's points: the body's, plus a piece's
    /// corner rounding (Lemma 9.5).
    #[inline]
    pub(super) fn leaf_err(&self, leaf: &Leaf<T>) -> T {
        if leaf.inflate > T::ZERO {
            add_up(self.err, leaf.inflate)
        } else {
            self.err
        }
    }

    /// A bound over the computed corners, widened for a piece to cover
    /// every point within its rounding of them (Lemma 9.5).
    #[inline]
    fn widened(&self, leaf: &Leaf<T>, bound: T) -> T {
        if leaf.inflate > T::ZERO {
            add_up(bound, piece_speed_margin_up(self.w_l1, leaf.inflate))
        } else {
            bound
        }
    }

    #[inline]
    pub(super) fn leaf_speed(&self, leaf: &Leaf<T>, n: Direction<T>, kind: BoundKind) -> T {
        let probe = self.motion.probe(n);
        let speed = match kind {
            BoundKind::Nevq => probe.nevq_speed_radius(leaf.r_hat),
            _ => probe.evq_speed_points(&leaf.corners, leaf.r_hat),
        };
        self.widened(leaf, speed)
    }

    /// The one-sided rate of a leaf's corners along `n`.
    #[inline]
    pub(super) fn leaf_rate(&self, leaf: &Leaf<T>, n: Direction<T>, kind: BoundKind) -> T {
        let rate = self
            .motion
            .probe(n)
            .points_rate(&leaf.corners, leaf.r_hat, kind);
        self.widened(leaf, rate)
    }
}

/// How a pair's closing speed along `n` (from A to B) is bounded.
#[derive(Clone, Copy)]
pub(super) struct Rates {
    pub(super) kind: BoundKind,
    pub(super) one_sided: bool,
}

impl Rates {
    /// Bounds on the speeds of A and B whose sum bounds the rate at which
    /// the slab between them along `n` closes: one-sided rates of A along
    /// `n` and B along `-n` (Lemma 10.2), or the absolute speeds (Lemma 9.1).
    pub(super) fn balls<T: Float>(
        self,
        pa: &Placed<'_, T>,
        pb: &Placed<'_, T>,
        balls: (&BoundingBall<T>, &BoundingBall<T>),
        n: Direction<T>,
    ) -> (T, T) {
        if self.one_sided {
            (
                pa.motion
                    .probe_inlined(n)
                    .ball_rate_inlined(balls.0, self.kind),
                pb.motion
                    .probe_inlined(-n)
                    .ball_rate_inlined(balls.1, self.kind),
            )
        } else {
            (
                pa.motion.probe(n).ball_speed(balls.0, self.kind),
                pb.motion.probe(n).ball_speed(balls.1, self.kind),
            )
        }
    }

    #[inline]
    pub(super) fn leaves<T: Float>(
        self,
        pa: &Placed<'_, T>,
        pb: &Placed<'_, T>,
        leaves: (&Leaf<T>, &Leaf<T>),
        n: Direction<T>,
    ) -> (T, T) {
        if self.one_sided {
            (
                pa.leaf_rate(leaves.0, n, self.kind),
                pb.leaf_rate(leaves.1, -n, self.kind),
            )
        } else {
            (
                pa.leaf_speed(leaves.0, n, self.kind),
                pb.leaf_speed(leaves.1, n, self.kind),
            )
        }
    }
}

/// The slab between two placed triangles along `n`: `min_B q.n - max_A p.n`.
#[inline]
pub(super) fn slab_gap<T: Float>(ta: &[Vec3<T>; 3], tb: &[Vec3<T>; 3], n: Vec3<T>) -> T {
    let lo_b = tb[0].dot(n).min_nan(tb[1].dot(n)).min_nan(tb[2].dot(n));
    let hi_a = ta[0].dot(n).max_nan(ta[1].dot(n)).max_nan(ta[2].dot(n));
    lo_b - hi_a
}
