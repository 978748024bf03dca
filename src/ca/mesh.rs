//! Conservative advancement of two triangle meshes through their ball trees.

use alloc::collections::BinaryHeap;
use alloc::vec::Vec;

use crate::bvh::{BallTree, Leaf};
use crate::ca::driver::{gap_step, placement_error};
use crate::ca::{CaParams, CaStep, StepResult, Witness};
use crate::geometry::closest::triangle_triangle;
use crate::rounding::{diff_up, gamma, gap_down, step_down, BoxError};
use crate::{BoundKind, BoundingBall, Direction, Float, Pose, PreparedMotion, Vec3};

/// The default of [`MeshPair::with_far_ratio`].
const FAR_RATIO: f64 = 6.0;

/// Work counters of a [`MeshPair`], summed over every step since the last
/// [`MeshPair::reset_stats`]: what a profile of the query needs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TraversalStats {
    /// Node pairs popped from the best-first queue and worked on (split,
    /// settled, or a leaf pair measured; a seed's leaf pair popped again is
    /// counted and skipped). The pair at which a descent stops is counted
    /// in `pruned` instead.
    pub node_pairs: u64,
    /// Node pairs discarded because their own safe step already reached the
    /// best step found (times the accept fraction at the queue's head), with
    /// the pairs left in the queue when a descent stops.
    pub pruned: u64,
    /// Triangle pairs whose exact distance was computed (the seeds measured
    /// before each descent included).
    pub triangle_pairs: u64,
    /// Directed bounds evaluated, one per body: two per node pair not
    /// already pruned by the crude speed bound, two per leaf-pair pre-check
    /// and two per measured triangle pair.
    pub bounds: u64,
    /// Node pairs far apart for their size, whose own step was taken
    /// without splitting them ([`MeshPair::with_far_ratio`]).
    pub settled: u64,
    /// Child node pairs whose volumes no tested direction separates (a zero
    /// safe step): they can only be split.
    pub overlapping: u64,
}

/// Conservative advancement of two non-convex triangle meshes (a
/// [`CaStep`]): one step is a simultaneous descent of both ball trees.
///
/// For a node pair placed at time `t`, the gap `g` between the nodes'
/// oriented boxes (or balls) is measured along three directions, the line
/// joining their centres and each box's thinnest axis, and the largest is
/// kept with its direction `n`; the slab between the nodes closes at most at
/// `mu_a + mu_b`, the balls' directed bounds (`O(1)` each; by default the
/// one-sided rates of A along `n` and of B along `-n`,
/// [`DirectedProbe::ball_rate`](crate::DirectedProbe::ball_rate)), so the
/// pair cannot touch before `g / (mu_a + mu_b)`. A pair far
/// apart for its size is settled with that step ([`MeshPair::with_far_ratio`]). A pair whose
/// step is at least the best step found so far is pruned; triangle pairs get
/// their exact distance, their own closest direction and the bounds of their
/// three corners. The least step over the cut is safe for the whole meshes
/// (`proofs/09-ca-toi.md`).
///
/// A `MeshPair` remembers the (up to four) triangle pairs with the least
/// steps of its last step and measures them first, at the new time, before
/// the descent: their steps, usually close to the final one, let it prune
/// children as they are made (Lemma 9.4; about 10 % fewer node pairs on the
/// knots). Any seeds are sound, so a pair may be reused across queries.
#[derive(Debug)]
pub struct MeshPair<'a, T> {
    a: &'a BallTree<T>,
    b: &'a BallTree<T>,
    heap: BinaryHeap<Queued>,
    /// The node pairs behind the queue's entries, indexed from [`Queued`].
    pending: Vec<Pending>,
    /// The nodes placed at the current step, indexed from [`Pending`].
    placed: Vec<PlacedNode<T>>,
    stats: TraversalStats,
    accept: T,
    far_ratio: T,
    closest: Option<(u32, u32)>,
    /// The leaf pairs with the least steps found by the last step, measured
    /// first by the next one.
    seeds: Seeds,
}

/// How many leaf pairs a step hands to the next one.
const SEEDS: usize = 4;

/// The leaf pairs (indices into the trees' leaves) with the least steps
/// measured in one step, least first.
#[derive(Clone, Copy, Debug, Default)]
struct Seeds {
    pairs: [(u32, u32); SEEDS],
    steps: [f64; SEEDS],
    len: usize,
}

impl Seeds {
    fn insert(&mut self, step: f64, pair: (u32, u32)) {
        let mut k = self.len.min(SEEDS - 1);
        if self.len == SEEDS && step.total_cmp(&self.steps[k]).is_ge() {
            return;
        }
        while k > 0 && step < self.steps[k - 1] {
            self.steps[k] = self.steps[k - 1];
            self.pairs[k] = self.pairs[k - 1];
            k -= 1;
        }
        self.steps[k] = step;
        self.pairs[k] = pair;
        self.len = (self.len + 1).min(SEEDS);
    }

    fn contains(&self, pair: (u32, u32)) -> bool {
        self.pairs[..self.len].contains(&pair)
    }
}

impl<'a, T: Float> MeshPair<'a, T> {
    /// The pair of meshes `a` and `b` (each relative to its rotation centre).
    #[must_use]
    pub fn new(a: &'a BallTree<T>, b: &'a BallTree<T>) -> Self {
        Self {
            a,
            b,
            heap: BinaryHeap::with_capacity(256),
            pending: Vec::with_capacity(512),
            placed: Vec::with_capacity(512),
            stats: TraversalStats::default(),
            accept: T::ONE,
            far_ratio: T::from_f64(FAR_RATIO),
            closest: None,
            seeds: Seeds::default(),
        }
    }

    /// Accepts a step once every pair left in the queue has a step at least
    /// `fraction` of the best found (default `1`: the least step over the
    /// finest cut the traversal reaches). A smaller fraction refines less per
    /// iteration and takes shorter steps; every step stays safe.
    /// A fraction outside `(0, 1]` (or NaN) is taken as `1`.
    #[must_use]
    pub fn with_accept_fraction(mut self, fraction: T) -> Self {
        self.accept = if fraction > T::ZERO && fraction <= T::ONE {
            fraction
        } else {
            T::ONE
        };
        self
    }

    /// Takes a node pair's own step, without splitting it, when the gap
    /// between its volumes is at least `ratio` times the sum of its balls'
    /// radii (default 6): below such a pair the gap grows by at most
    /// `2 / ratio` of itself, so splitting it buys little step and costs a
    /// descent. `+inf` (or NaN, or a negative ratio) always splits.
    #[must_use]
    pub fn with_far_ratio(mut self, ratio: T) -> Self {
        self.far_ratio = if ratio >= T::ZERO { ratio } else { T::INFINITY };
        self
    }

    /// The triangle indices (in A's and B's meshes) of the closest triangle
    /// pair the last step found, if it computed one: the witness's triangles.
    #[must_use]
    pub const fn closest_triangles(&self) -> Option<(u32, u32)> {
        self.closest
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
    /// The rotation's error coefficients for box supports (`|w| t`).
    box_err: BoxError<T>,
    /// `|v|_1` and `|w|_1` (the crude speed bound's ingredients).
    v_l1: T,
    w_l1: T,
}

/// A node placed at the current step: its centre, and its box's thinnest
/// axis in the world frame (normalised), computed once per node per pair
/// creation and shared by the pair's children.
#[derive(Clone, Copy, Debug)]
struct PlacedNode<T> {
    centre: Vec3<T>,
    thin: Option<Direction<T>>,
}

impl<T: Float> Placed<'_, T> {
    fn place(&self, tree: &BallTree<T>, node: u32) -> PlacedNode<T> {
        let n = &tree.nodes[node as usize];
        let thin = self.pose.transform_vector(Vec3::from_array(n.obb.axes[2]));
        PlacedNode {
            centre: self.centre(tree, node),
            thin: Direction::try_new_fast(thin).ok(),
        }
    }

    /// A crude, direction-free bound on the speed of every point within
    /// `radius` of the rotation centre: `|v| + |w| radius <= |v|_1 + |w|_1 radius`,
    /// rounded up (at most five roundings, covered by `1 + gamma_8`). It
    /// bounds the one-sided and the absolute speeds along any unit direction,
    /// so a step from it is safe (Lemma 9.1) and lets a pair be pruned before
    /// its directed bounds are computed.
    #[inline]
    fn crude_speed(&self, radius: T) -> T {
        (self.v_l1 + self.w_l1 * radius) * (T::ONE + gamma::<T>(8))
    }

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

    /// The one-sided rate of a leaf's corners along `n`.
    fn leaf_rate(&self, leaf: &Leaf<T>, n: Direction<T>, kind: BoundKind) -> T {
        self.motion
            .probe(n)
            .points_rate(&leaf.corners, leaf.r_hat, kind)
    }
}

/// How a pair's closing speed along `n` (from A to B) is bounded.
#[derive(Clone, Copy)]
struct Rates {
    kind: BoundKind,
    one_sided: bool,
}

impl Rates {
    /// Bounds on the speeds of A and B whose sum bounds the rate at which
    /// the slab between them along `n` closes: one-sided rates of A along
    /// `n` and B along `-n` (Lemma 10.2), or the absolute speeds (Lemma 9.1).
    fn balls<T: Float>(
        self,
        pa: &Placed<'_, T>,
        pb: &Placed<'_, T>,
        balls: (&BoundingBall<T>, &BoundingBall<T>),
        n: Direction<T>,
    ) -> (T, T) {
        if self.one_sided {
            (
                pa.motion.probe(n).ball_rate(balls.0, self.kind),
                pb.motion.probe(-n).ball_rate(balls.1, self.kind),
            )
        } else {
            (
                pa.motion.probe(n).ball_speed(balls.0, self.kind),
                pb.motion.probe(n).ball_speed(balls.1, self.kind),
            )
        }
    }

    fn leaves<T: Float>(
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

impl<T: Float> MeshPair<'_, T> {
    /// The safe step of a node pair (Lemma 9.1): the largest gap between
    /// the placed nodes along one of three directions (the line joining the
    /// box centres, where the balls' gap counts too, and each box's thinnest
    /// axis), over the balls' directed bounds along it.
    ///
    /// A pair whose certified gap is at most the contact distance (or that
    /// no direction separates) is a [`NodeStep::Near`] candidate: triangles
    /// below it may be within the contact distance now, so it is split
    /// whatever its step, nearest first.
    fn node_step(
        &mut self,
        pa: &Placed<'_, T>,
        pb: &Placed<'_, T>,
        (i, j): (u32, u32),
        (qa, qb): (PlacedNode<T>, PlacedNode<T>),
        (rates, contact_distance, clearance): (Rates, T, T),
        best_step: T,
    ) -> NodeStep<T> {
        let (na, nb) = (&self.a.nodes[i as usize], &self.b.nodes[j as usize]);
        let d = qb.centre - qa.centre;
        // The gap of the boxes along `n` (any sign of `n`: the slab between
        // them is measured along whichever way separates).
        let box_gap = |n: Vec3<T>| {
            let along = d.dot(n).abs();
            let sa = na
                .obb
                .support_up_with(pa.pose.inverse_transform_vector(n), &pa.box_err);
            let sb = nb
                .obb
                .support_up_with(pb.pose.inverse_transform_vector(n), &pb.box_err);
            along - sa - sb
        };
        let mut best: Option<(T, Direction<T>)> = None;
        let mut consider = |n: Direction<T>, gap: T| {
            if gap > T::ZERO && best.is_none_or(|(g, _)| gap > g) {
                best = Some((gap, n));
            }
        };
        if let Ok(n) = Direction::try_new_fast(d) {
            let ball_gap = d.dot(n.get()) - na.ball.radius() - nb.ball.radius();
            consider(n, ball_gap.max_nan(box_gap(n.get())));
        }
        for n in [qa.thin, qb.thin].into_iter().flatten() {
            consider(n, box_gap(n.get()));
        }
        let Some((gap, n)) = best else {
            self.stats.overlapping += 1;
            return NodeStep::Near(-T::INFINITY);
        };
        // The certified gap (section "Gap"): below the contact distance the
        // pair is a candidate for contact now.
        let g = gap_down(gap, pa.err, pb.err, pa.reach + pb.reach);
        if g.is_nan() || g <= contact_distance {
            return NodeStep::Near(g);
        }
        // Orient n from A to B: the slab gap is measured along it.
        let n = if d.dot(n.get()) < T::ZERO { -n } else { n };
        let far = gap >= self.far_ratio * (na.ball.radius() + nb.ball.radius());
        // A pair whose step under the crude bound already reaches the best
        // step cannot limit it: no directed bound needed.
        let lower = step_down(
            g,
            clearance,
            pa.crude_speed(na.ball.outer_radius_up()),
            pb.crude_speed(nb.ball.outer_radius_up()),
        );
        if lower >= best_step {
            return NodeStep::Apart { step: lower, far };
        }
        self.stats.bounds += 2;
        let (mu_a, mu_b) = rates.balls(pa, pb, (&na.ball, &nb.ball), n);
        NodeStep::Apart {
            step: step_down(g, clearance, mu_a, mu_b),
            far,
        }
    }

    /// Puts a node pair in the best-first queue.
    #[inline]
    fn enqueue(&mut self, pair: Pending) {
        let slot = self.pending.len() as u32;
        self.heap.push(Queued {
            near: pair.near,
            key: pair.key,
            slot,
        });
        self.pending.push(pair);
    }

    /// Measures one triangle pair (leaf indices `i` in A, `j` in B): its
    /// exact distance (a witness) and, when it is apart, its own safe step
    /// along its closest direction, folded into `best` (Lemma 9.1). Returns
    /// the step's result when the pair is within the contact distance.
    fn triangle_pair(
        &mut self,
        (pa, pb): (&Placed<'_, T>, &Placed<'_, T>),
        (i, j): (usize, usize),
        (ta, tb): (&[Vec3<T>; 3], &[Vec3<T>; 3]),
        (rates, contact_distance, clearance): (Rates, T, T),
        (best, witness, normal): (&mut T, &mut Option<Witness<T>>, &mut Option<Vec3<T>>),
    ) -> Option<StepResult<T>> {
        let (la, lb) = (&self.a.leaves[i], &self.b.leaves[j]);
        self.stats.triangle_pairs += 1;
        let cp = triangle_triangle(ta, tb);
        let w = Witness {
            distance: cp.distance,
            on_a: cp.on_a,
            on_b: cp.on_b,
        };
        let dir = Direction::try_new(cp.on_b - cp.on_a);
        if witness.is_none_or(|b: Witness<T>| w.distance < b.distance) {
            *witness = Some(w);
            self.closest = Some((la.triangle, lb.triangle));
        }
        let (Ok(n), true) = (dir, cp.distance > contact_distance) else {
            self.closest = Some((la.triangle, lb.triangle));
            return Some(StepResult::Touching {
                witness: w,
                normal: dir.ok().map(Direction::get),
            });
        };
        let nv = n.get();
        self.stats.bounds += 2;
        let mu = rates.leaves(pa, pb, (la, lb), n);
        let gap = slab_gap(ta, tb, nv);
        let (step, _) = gap_step(gap, clearance, (pa.err, pb.err), (pa.reach, pb.reach), mu);
        self.seeds.insert(step.to_f64(), (i as u32, j as u32));
        if step < *best {
            *best = step;
            *normal = Some(nv);
        }
        None
    }
}

/// The slab between two placed triangles along `n`: `min_B q.n - max_A p.n`.
#[inline]
fn slab_gap<T: Float>(ta: &[Vec3<T>; 3], tb: &[Vec3<T>; 3], n: Vec3<T>) -> T {
    let lo_b = tb[0].dot(n).min_nan(tb[1].dot(n)).min_nan(tb[2].dot(n));
    let hi_a = ta[0].dot(n).max_nan(ta[1].dot(n)).max_nan(ta[2].dot(n));
    lo_b - hi_a
}

/// What [`MeshPair::node_step`] found for a node pair.
#[derive(Clone, Copy, Debug)]
enum NodeStep<T> {
    /// Certified apart by more than the contact distance, with its safe step;
    /// `far`: far apart for its size (its step is taken as it is).
    Apart { step: T, far: bool },
    /// Its certified gap (`-inf` when no direction separates the volumes) is
    /// at most the contact distance: it must be split.
    Near(T),
}

/// An entry of the best-first queue: a node pair's key and where the pair is
/// in `MeshPair::pending` (kept small: the queue moves its entries). Pairs
/// near enough for contact come first, least gap first; then the others,
/// least step first.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Queued {
    near: bool,
    key: OrdF64,
    slot: u32,
}

/// A node pair waiting in the best-first queue.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Pending {
    /// Near enough for contact now ([`NodeStep::Near`]): `key` is its gap,
    /// and it is split whatever the best step.
    near: bool,
    /// The pair's safe step (or, when `near`, its certified gap).
    key: OrdF64,
    i: u32,
    j: u32,
    /// The pair is far apart for its size: its step is taken as it is.
    far: bool,
    /// Where the two nodes' placements are in `MeshPair::placed`.
    at: (u32, u32),
}

impl Pending {
    fn new<T: Float>(found: NodeStep<T>, (i, j): (u32, u32), at: (u32, u32)) -> Self {
        let (near, key, far) = match found {
            NodeStep::Apart { step, far } => (false, step, far),
            NodeStep::Near(gap) => (true, gap, false),
        };
        Self {
            near,
            key: OrdF64(key.to_f64()),
            i,
            j,
            far,
            at,
        }
    }
}

impl Eq for Queued {}

impl PartialOrd for Queued {
    fn partial_cmp(&self, other: &Self) -> Option<core::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Queued {
    /// Reversed: `BinaryHeap` pops the greatest, which is the near pair with
    /// the least gap, else the pair with the least step.
    fn cmp(&self, other: &Self) -> core::cmp::Ordering {
        self.near
            .cmp(&other.near)
            .then_with(|| other.key.0.total_cmp(&self.key.0))
    }
}

/// An `f64` key (a step or gap converted exactly from `f32` or `f64`).
#[derive(Clone, Copy, Debug, PartialEq)]
struct OrdF64(f64);

impl<T: Float> CaStep<T> for MeshPair<'_, T> {
    fn step(
        &mut self,
        t: T,
        a: &PreparedMotion<T>,
        b: &PreparedMotion<T>,
        params: &CaParams<T>,
    ) -> StepResult<T> {
        // Every node centre, box point and corner lies within the tree's
        // certified reach of the rotation centre: cover them all.
        let place = |tree: &BallTree<T>, m: &'_ PreparedMotion<T>| {
            let r = tree.reach;
            let (err, reach) = placement_error(m.motion(), t, r);
            (m.motion().pose_at(t), err, reach)
        };
        let (pose, err, reach) = place(self.a, a);
        let pa = Placed {
            pose,
            motion: a,
            err,
            reach,
            box_err: BoxError::new(a.motion().angle_at(t)),
            v_l1: a.motion().linear().norm_l1(),
            w_l1: a.motion().angular().norm_l1(),
        };
        let (pose, err, reach) = place(self.b, b);
        let pb = Placed {
            pose,
            motion: b,
            err,
            reach,
            box_err: BoxError::new(b.motion().angle_at(t)),
            v_l1: b.motion().linear().norm_l1(),
            w_l1: b.motion().angular().norm_l1(),
        };
        let rates = Rates {
            kind: params.bound.cheap_kind(),
            one_sided: params.one_sided,
        };
        // Every pair whose step reaches the end of the bounds' interval is
        // pruned against a best step that is at least the exact rest of it,
        // so a descent that finds nothing shorter returns a step the driver
        // reads as reaching the end (section "Exact sums").
        let mut best = diff_up(b.motion().interval().end(), t);
        let (cd, clear) = (params.contact_distance, params.clearance());
        let mut witness: Option<Witness<T>> = None;
        let mut normal = None;
        self.heap.clear();
        // The previous step's leaf pairs with the least steps are measured
        // first (Lemma 9.4): each one's own step is safe for that pair, and,
        // usually close to the final step, it lets the descent prune children
        // as they are made.
        self.closest = None;
        let seed = core::mem::take(&mut self.seeds);
        for &(i, j) in &seed.pairs[..seed.len] {
            let (i, j) = (i as usize, j as usize);
            let corners = (pa.corners(&self.a.leaves[i]), pb.corners(&self.b.leaves[j]));
            if let Some(touching) = self.triangle_pair(
                (&pa, &pb),
                (i, j),
                (&corners.0, &corners.1),
                (rates, cd, clear),
                (&mut best, &mut witness, &mut normal),
            ) {
                return touching;
            }
        }
        self.placed.clear();
        self.placed.push(pa.place(self.a, 0));
        self.placed.push(pb.place(self.b, 0));
        self.pending.clear();
        self.enqueue(Pending::new(NodeStep::Near(-T::INFINITY), (0, 0), (0, 1)));
        while let Some(Queued { slot, .. }) = self.heap.pop() {
            let Pending {
                near,
                key,
                i,
                j,
                far,
                at,
            } = self.pending[slot as usize];
            let key = T::from_f64(key.0);
            if !near && key >= best * self.accept {
                // Best-first: every pair left has a step at least `key`, so
                // `min(best, key)` is safe for the whole meshes.
                self.stats.pruned += self.heap.len() as u64 + 1;
                best = best.min_nan(key);
                break;
            }
            self.stats.node_pairs += 1;
            if far {
                // Splitting a pair this far apart for its size would gain
                // little: its own step is safe for everything below it.
                self.stats.settled += 1;
                best = best.min_nan(key);
                continue;
            }
            let (na, nb) = (&self.a.nodes[i as usize], &self.b.nodes[j as usize]);
            if let (Some(li), Some(lj)) = (na.leaf(), nb.leaf()) {
                if seed.contains((li as u32, lj as u32)) {
                    // Measured before the descent: its step is in `best`.
                    continue;
                }
                let (la, lb) = (&self.a.leaves[li], &self.b.leaves[lj]);
                let (ta, tb) = (pa.corners(la), pb.corners(lb));
                // Cheap first: the corners' slab along the line joining the
                // ball centres (Lemma 9.1 holds for any direction).
                let (qa, qb) = (self.placed[at.0 as usize], self.placed[at.1 as usize]);
                // A pair certainly farther apart than the contact distance
                // along it is pruned when its step reaches the best.
                if let Ok(n) = Direction::try_new(qb.centre - qa.centre) {
                    let g = gap_down(
                        slab_gap(&ta, &tb, n.get()),
                        pa.err,
                        pb.err,
                        pa.reach + pb.reach,
                    );
                    if g > cd {
                        self.stats.bounds += 2;
                        let (mu_a, mu_b) = rates.leaves(&pa, &pb, (la, lb), n);
                        if step_down(g, clear, mu_a, mu_b) >= best {
                            self.stats.pruned += 1;
                            continue;
                        }
                    }
                }
                if let Some(touching) = self.triangle_pair(
                    (&pa, &pb),
                    (li, lj),
                    (&ta, &tb),
                    (rates, cd, clear),
                    (&mut best, &mut witness, &mut normal),
                ) {
                    return touching;
                }
                continue;
            }
            // Descend into the larger ball (a leaf is never split).
            let split_a = nb.leaf().is_some()
                || (na.leaf().is_none() && na.ball.radius() >= nb.ball.radius());
            let (left, right) = if split_a {
                (na.left, na.right)
            } else {
                (nb.left, nb.right)
            };
            for child in [left, right] {
                // Place the new node once; the kept one is already placed.
                let slot = self.placed.len() as u32;
                let (pair, at) = if split_a {
                    self.placed.push(pa.place(self.a, child));
                    ((child, j), (slot, at.1))
                } else {
                    self.placed.push(pb.place(self.b, child));
                    ((i, child), (at.0, slot))
                };
                let q = (self.placed[at.0 as usize], self.placed[at.1 as usize]);
                match self.node_step(&pa, &pb, pair, q, (rates, cd, clear), best) {
                    NodeStep::Apart { step, .. } if step >= best => self.stats.pruned += 1,
                    found => self.enqueue(Pending::new(found, pair, at)),
                }
            }
        }
        StepResult::Advance {
            step: best,
            witness,
            normal,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{Seeds, SEEDS};

    #[test]
    fn seeds_keep_the_least_steps_in_order() {
        let mut s = Seeds::default();
        let steps = [0.5, 0.1, 0.9, 0.3, 0.05, 0.7, 0.2];
        for (k, &x) in steps.iter().enumerate() {
            s.insert(x, (k as u32, 0));
        }
        // An independent answer: sort a copy.
        let mut sorted: alloc::vec::Vec<(f64, u32)> = steps
            .iter()
            .enumerate()
            .map(|(k, &x)| (x, k as u32))
            .collect();
        sorted.sort_by(|a, b| a.0.total_cmp(&b.0));
        assert_eq!(s.len, SEEDS);
        for (k, want) in sorted.iter().take(SEEDS).enumerate() {
            assert_eq!((s.steps[k], s.pairs[k].0), *want);
        }
        assert!(s.contains((4, 0)) && !s.contains((2, 0)));
        let mut one = Seeds::default();
        one.insert(1.0, (7, 8));
        assert_eq!((one.len, one.pairs[0]), (1, (7, 8)));
    }
}
