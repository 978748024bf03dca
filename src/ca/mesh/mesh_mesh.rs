//! Conservative advancement of two triangle meshes through their ball trees.

use super::found::{Found, Head, NodeStep};
use super::placed::{slab_gap, Placed, Rates};
use super::queue::{MeshWorkspace, Pending, Queued};
use super::seeds::Seeds;
use super::stats::TraversalStats;
use super::traversal::Descent;
use crate::bvh::BallTree;
use crate::ca::{CaError, CaParams, CaStep, MeshParams, StepResult, WitnessSearch, Work};
use crate::rounding::{diff_up, gap_down, least_resolved_reach, resolution_up, step_down};
use crate::{Direction, Float, PreparedMotion};

/// Conservative advancement of two non-convex triangle meshes (a
/// [`CaStep`]): one step is a simultaneous descent of both ball trees.
///
/// For a node pair placed at time `t`, the gap `g` between the nodes'
/// oriented boxes (or balls) is measured along two directions, the line
/// joining their centres and the line joining the nearest points of the
/// boxes' middle rectangles (found approximately), and the larger is
/// kept with its direction `n`; the slab between the nodes closes at most at
/// `mu_a + mu_b`, the balls' directed bounds (`O(1)` each; by default the
/// one-sided rates of A along `n` and of B along `-n`,
/// [`DirectedProbe::ball_rate`](crate::DirectedProbe::ball_rate)), so the
/// pair cannot touch before `g / (mu_a + mu_b)`. A pair far
/// apart for its size is settled with that step ([`MeshParams::far_ratio`]). A pair whose
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
    /// The hierarchies descended, with the work counters and the seeds.
    descent: Descent<'a, T>,
    /// Whether A's and B's hierarchies are those of pieces.
    pieces: (bool, bool),
    /// The queue and the placed nodes: scratch space, reusable.
    ws: MeshWorkspace<T>,
    accept: T,
    closest: Option<(u32, u32)>,
}

impl<'a, T: Float> MeshPair<'a, T> {
    /// The pair of meshes `a` and `b` (each relative to its rotation centre).
    #[must_use]
    pub fn new(a: &'a BallTree<T>, b: &'a BallTree<T>) -> Self {
        let (ha, hb) = (a.against(b), b.against(a));
        Self {
            descent: Descent {
                a: ha,
                b: hb,
                far_ratio: MeshParams::<T>::default().far_ratio,
                stats: TraversalStats::default(),
                seeds: Seeds::default(),
            },
            pieces: (!core::ptr::eq(ha, &a.whole), !core::ptr::eq(hb, &b.whole)),
            ws: MeshWorkspace::new(),
            accept: MeshParams::<T>::default().accept_fraction,
            closest: None,
        }
    }

    /// The pair of meshes `a` and `b` with the scratch space `workspace`
    /// (taken back by [`into_workspace`](Self::into_workspace)): a query in a
    /// steady loop then allocates nothing.
    #[must_use]
    pub fn with_workspace(
        a: &'a BallTree<T>,
        b: &'a BallTree<T>,
        workspace: MeshWorkspace<T>,
    ) -> Self {
        Self {
            ws: workspace,
            ..Self::new(a, b)
        }
    }

    /// The scratch space, for the next pair.
    #[must_use]
    pub fn into_workspace(self) -> MeshWorkspace<T> {
        self.ws
    }

    /// The same pair with the scratch space `workspace`.
    #[must_use]
    pub(crate) fn with_workspace_from(self, workspace: MeshWorkspace<T>) -> Self {
        Self {
            ws: workspace,
            ..self
        }
    }

    /// With the traversal's tuning knobs `params` (the defaults suit most
    /// scenes).
    ///
    /// # Errors
    /// [`CaError::InvalidParameter`] naming a knob out of range
    /// ([`MeshParams::validate`]).
    ///
    /// ```
    /// use motion_bound::ca::{CaError, MeshPair, MeshParams, Parameter};
    /// use motion_bound::{bodies, BallTree};
    /// let tree = BallTree::try_from_mesh(&bodies::torus::<f64>(0.5, 0.1, 16, 8)?)?;
    /// let pair = MeshPair::new(&tree, &tree).try_with_params(MeshParams::default().with_far_ratio(f64::INFINITY))?;
    /// let bad = MeshPair::new(&tree, &tree).try_with_params(MeshParams::default().with_accept_fraction(1.5));
    /// assert_eq!(bad.err(), Some(CaError::InvalidParameter(Parameter::AcceptFraction)));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn try_with_params(mut self, params: MeshParams<T>) -> Result<Self, CaError> {
        params.validate()?;
        self.accept = params.accept_fraction;
        self.descent.far_ratio = params.far_ratio;
        Ok(self)
    }

    /// The triangle indices (in A's and B's meshes) of the closest triangle
    /// pair the last step found, if it computed one: the witness's triangles.
    #[must_use]
    pub const fn closest_triangles(&self) -> Option<(u32, u32)> {
        self.closest
    }

    /// Whether the query descends A's and B's hierarchies of pieces (their
    /// long triangles cut, [`BallTree::try_with_piece_length`]) rather than
    /// their whole triangles: a mesh's pieces are taken when its largest
    /// leaf ball is more than four times the other mesh's median one.
    ///
    /// ```
    /// use motion_bound::ca::MeshPair;
    /// use motion_bound::{bodies, BallTree};
    /// let board = BallTree::try_from_mesh(&bodies::board::<f64>(2.0, 2.0, 0.002)?)?;
    /// let ball = BallTree::try_from_mesh(&bodies::icosphere::<f64>(0.3, 3)?)?;
    /// assert_eq!(MeshPair::new(&board, &ball).pieces_in_use(), (true, false));
    /// assert_eq!(MeshPair::new(&board, &board).pieces_in_use(), (false, false));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    #[must_use]
    pub const fn pieces_in_use(&self) -> (bool, bool) {
        self.pieces
    }

    /// The work done since the pair was made or last reset.
    #[must_use]
    pub const fn stats(&self) -> TraversalStats {
        self.descent.stats
    }

    /// Resets the work counters.
    pub fn reset_stats(&mut self) {
        self.descent.stats = TraversalStats::default();
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
        let (pa, pb) = (
            Placed::new(self.descent.a, a, t),
            Placed::new(self.descent.b, b, t),
        );
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
        // Below the resolution a pair within the contact distance cannot be
        // told from one within its clearance: no near pair is split to look
        // for a contact (it would split every pair within the resolution,
        // down to every triangle pair), and a zero step ends the query
        // (`proofs/09-ca-toi.md`, Lemma 9.6).
        let resolution = resolution_up(pa.err, pb.err, pa.reach + pb.reach);
        let limited = resolution >= clear || resolution.is_nan();
        // Bodies so small that their squared lengths underflow: their balls
        // and bounds are the underflow allowances' (section "Resolution").
        let least = least_resolved_reach::<T>();
        if self.descent.a.reach < least || self.descent.b.reach < least {
            return StepResult::PrecisionLimit {
                resolution: resolution.max_nan(least),
            };
        }
        let mut found = Found::default();
        let first_only = params.witness == WitnessSearch::First;
        let start = self.descent.stats;
        let budget = params.work_budget;
        // The previous step's leaf pairs with the least steps are measured
        // first (Lemma 9.4): each one's own step is safe for that pair, and,
        // usually close to the final step, it lets the descent prune children
        // as they are made.
        self.closest = None;
        let seed = core::mem::take(&mut self.descent.seeds);
        for &(i, j) in &seed.pairs[..seed.len] {
            if self.descent.stats.out_of_work(&start, budget) {
                break;
            }
            let (i, j) = (i as usize, j as usize);
            let corners = (
                pa.corners(&self.descent.a.leaves[i]),
                pb.corners(&self.descent.b.leaves[j]),
            );
            self.descent.triangle_pair(
                (&pa, &pb),
                (i, j),
                (&corners.0, &corners.1),
                (rates, cd, clear),
                (&mut best, &mut found),
            );
        }
        self.ws.clear();
        let roots = (
            self.ws.placed_slot(0, 0, || pa.place(self.descent.a, 0)),
            self.ws.placed_slot(1, 0, || pb.place(self.descent.b, 0)),
        );
        let root = NodeStep::Near(-T::INFINITY).resolved(limited);
        self.ws.enqueue(Pending::new(root, (0, 0), roots));
        while let Some(Queued { slot, .. }) = self.ws.pop() {
            let Pending {
                near,
                key,
                i,
                j,
                far,
                at,
            } = self.ws.pending[slot as usize];
            let key = T::from_f64(key.0);
            let out_of_work = self.descent.stats.out_of_work(&start, budget);
            match found.head((near, key), (best, self.accept), first_only, out_of_work) {
                Head::Go => {}
                Head::Stop => break,
                Head::Cut => {
                    self.descent.stats.pruned += self.ws.len() as u64 + 1;
                    best = best.min_nan(key);
                    break;
                }
                Head::OutOfWork => return StepResult::WorkLimit,
            }
            self.descent.stats.node_pairs += 1;
            if far {
                // Splitting a pair this far apart for its size would gain
                // little: its own step is safe for everything below it.
                self.descent.stats.settled += 1;
                best = best.min_nan(key);
                continue;
            }
            let (na, nb) = (
                &self.descent.a.nodes[i as usize],
                &self.descent.b.nodes[j as usize],
            );
            let (leaf_a, leaf_b) = (na.leaf(), nb.leaf());
            if let (Some(li), Some(lj)) = (leaf_a, leaf_b) {
                if seed.contains((li as u32, lj as u32)) {
                    // Measured before the descent: its step is in `best`.
                    continue;
                }
                let (la, lb) = (&self.descent.a.leaves[li], &self.descent.b.leaves[lj]);
                let (ta, tb) = (pa.corners(la), pb.corners(lb));
                // Cheap first: the corners' slab along the line joining the
                // ball centres (Lemma 9.1 holds for any direction).
                let (qa, qb) = (self.ws.placed[at.0 as usize], self.ws.placed[at.1 as usize]);
                if let Ok(n) = Direction::try_new(qb.centre - qa.centre) {
                    let g = gap_down(
                        slab_gap(&ta, &tb, n.get()),
                        pa.leaf_err(la),
                        pb.leaf_err(lb),
                        pa.reach + pb.reach,
                    );
                    if let Some(touch) = found.touching {
                        // The slab's gap is a lower bound of the distance.
                        if g >= touch.distance {
                            self.descent.stats.pruned += 1;
                            continue;
                        }
                    } else if g > cd {
                        // A pair certainly farther apart than the contact
                        // distance is pruned when its step reaches the best.
                        self.descent.stats.bounds += 2;
                        let (mu_a, mu_b) = rates.leaves(&pa, &pb, (la, lb), n);
                        if step_down(g, clear, mu_a, mu_b) >= best {
                            self.descent.stats.pruned += 1;
                            continue;
                        }
                    }
                }
                self.descent.triangle_pair(
                    (&pa, &pb),
                    (li, lj),
                    (&ta, &tb),
                    (rates, cd, clear),
                    (&mut best, &mut found),
                );
                continue;
            }
            // Descend into the larger ball (a leaf is never split).
            let split_a =
                leaf_b.is_some() || (leaf_a.is_none() && na.ball.radius() >= nb.ball.radius());
            let (left, right) = if split_a {
                (na.left, na.right)
            } else {
                (nb.left, nb.right)
            };
            for child in [left, right] {
                // Place the new node once per step; the kept one is placed.
                let (pair, at) = if split_a {
                    let slot = self
                        .ws
                        .placed_slot(0, child, || pa.place(self.descent.a, child));
                    ((child, j), (slot, at.1))
                } else {
                    let slot = self
                        .ws
                        .placed_slot(1, child, || pb.place(self.descent.b, child));
                    ((i, child), (at.0, slot))
                };
                let q = (self.ws.placed[at.0 as usize], self.ws.placed[at.1 as usize]);
                // In the search for the closest pair only gaps matter: a
                // best step of zero skips the directed bounds.
                // The closest pair's direction separates the volumes near
                // it best.
                let (best_step, also) = if found.touching.is_some() {
                    (T::ZERO, found.touching_normal)
                } else {
                    (best, None)
                };
                // Below the resolution no pair is near: one within the
                // clearance (or unseparated) is a zero step.
                let near_within = if limited { -T::INFINITY } else { cd };
                let step = self
                    .descent
                    .node_step(
                        &pa,
                        &pb,
                        pair,
                        q,
                        (rates, near_within, clear),
                        (best_step, also),
                    )
                    .resolved(limited);
                if found.queues(step, best) {
                    self.ws.enqueue(Pending::new(step, pair, at));
                } else {
                    self.descent.stats.pruned += 1;
                }
            }
        }
        self.closest = found.witness_triangles();
        found.verdict(best, limited, resolution)
    }

    fn work(&self) -> Work {
        self.descent.stats.work()
    }
}
