//! Conservative advancement of two triangle meshes through their ball trees.

use super::found::{Found, Head, NodeStep};
use super::placed::{slab_gap, Placed, Rates};
use super::queue::{MeshWorkspace, Pending, Queued};
use super::seeds::Seeds;
use super::stats::TraversalStats;
use super::traversal::Descent;
use crate::bvh::BallTree;
use crate::ca::solid::StartCheck;
use crate::ca::{CaError, CaParams, CaStep, MeshParams, Shape, StepResult, WitnessSearch, Work};
use crate::rounding::{diff_up, gap_down, least_resolved_reach, resolution_up, step_down};
use crate::{BoundingBall, Direction, Float, PreparedMotion};

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
    /// A body starting inside a solid mesh (Lemma 9.7).
    start: StartCheck<'a, T>,
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
            start: StartCheck::new(Shape::Mesh(a), Shape::Mesh(b)),
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
    fn bounding_balls(&self) -> Option<(BoundingBall<T>, BoundingBall<T>)> {
        Some((self.descent.a.nodes[0].ball, self.descent.b.nodes[0].ball))
    }

    // One step at time `t`, in stages: the bodies placed (`Frame::new`),
    // the seeds measured (`measure_seeds`), the descent of both hierarchies
    // (`descend`), and the verdict from what they found (`Found::verdict`).
    fn step(
        &mut self,
        t: T,
        a: &PreparedMotion<T>,
        b: &PreparedMotion<T>,
        params: &CaParams<T>,
    ) -> StepResult<T> {
        let frame = Frame::new(&self.descent, t, (a, b), params);
        // Bodies so small that their squared lengths underflow: their balls
        // and bounds are the underflow allowances' (section "Resolution").
        let least = least_resolved_reach::<T>();
        if self.descent.a.reach < least || self.descent.b.reach < least {
            return StepResult::PrecisionLimit {
                resolution: frame.resolution.max_nan(least),
            };
        }
        // Every pair whose step reaches the end of the bounds' interval is
        // pruned against a best step that is at least the exact rest of it,
        // so a descent that finds nothing shorter returns a step the driver
        // reads as reaching the end (section "Exact sums").
        let mut best = diff_up(b.motion().interval().end(), t);
        let mut found = Found::default();
        self.closest = None;
        let seeds = self.measure_seeds(&frame, &mut best, &mut found);
        if !self.descend(&frame, &seeds, &mut best, &mut found) {
            return StepResult::WorkLimit;
        }
        self.closest = found.witness_triangles();
        found.verdict(best, frame.limited, frame.resolution)
    }

    fn work(&self) -> Work {
        self.descent.stats.work().saturating_add(self.start.work())
    }

    fn initial_overlap(
        &mut self,
        t: T,
        a: &PreparedMotion<T>,
        b: &PreparedMotion<T>,
        params: &CaParams<T>,
    ) -> Option<StepResult<T>> {
        self.start.run(t, a, b, params.work_budget)
    }
}

/// What a step of a [`MeshPair`] fixes before it measures anything.
struct Frame<'p, T> {
    /// Both bodies placed at the step's time.
    pa: Placed<'p, T>,
    pb: Placed<'p, T>,
    /// How a pair's closing speed is bounded.
    rates: Rates,
    /// The contact distance and the clearance.
    cd: T,
    clear: T,
    /// The resolution of the placements, and whether the clearance is
    /// below it: then a pair within the contact distance cannot be told
    /// from one within its clearance, so no near pair is split to look for
    /// a contact (it would split every pair within the resolution, down to
    /// every triangle pair), and a zero step ends the query
    /// (`proofs/09-ca-toi.md`, Lemma 9.6).
    resolution: T,
    limited: bool,
    /// Only the first contact is wanted, not the closest pair.
    first_only: bool,
    /// The work counters at the step's start, and the step's budget.
    start: TraversalStats,
    budget: Work,
}

impl<'p, T: Float> Frame<'p, T> {
    /// The frame of a step at time `t` of `descent`'s hierarchies moving by
    /// `a` and `b`.
    #[inline]
    fn new(
        descent: &Descent<'_, T>,
        t: T,
        (a, b): (&'p PreparedMotion<T>, &'p PreparedMotion<T>),
        params: &CaParams<T>,
    ) -> Self {
        let (pa, pb) = (Placed::new(descent.a, a, t), Placed::new(descent.b, b, t));
        let clear = params.clearance();
        let resolution = resolution_up(pa.err, pb.err, pa.reach + pb.reach);
        Self {
            rates: Rates {
                kind: params.bound.cheap_kind(),
                one_sided: params.one_sided,
            },
            cd: params.contact_distance,
            clear,
            resolution,
            limited: resolution >= clear || resolution.is_nan(),
            first_only: params.witness == WitnessSearch::First,
            start: descent.stats,
            budget: params.work_budget,
            pa,
            pb,
        }
    }
}

impl<T: Float> MeshPair<'_, T> {
    /// Measures the leaf pairs the last step handed over (Lemma 9.4), at
    /// the new time, before the descent: each one's own step is safe for
    /// that pair and, usually close to the final step, lets the descent
    /// prune children as they are made. Returns them, for the descent to
    /// skip.
    #[inline]
    fn measure_seeds(&mut self, f: &Frame<'_, T>, best: &mut T, found: &mut Found<T>) -> Seeds {
        let seeds = core::mem::take(&mut self.descent.seeds);
        for &(i, j) in &seeds.pairs[..seeds.len] {
            if self.descent.stats.out_of_work(&f.start, f.budget) {
                break;
            }
            let (i, j) = (i as usize, j as usize);
            let corners = (
                f.pa.corners(&self.descent.a.leaves[i]),
                f.pb.corners(&self.descent.b.leaves[j]),
            );
            self.descent.triangle_pair(
                (&f.pa, &f.pb),
                (i, j),
                (&corners.0, &corners.1),
                (f.rates, f.cd, f.clear),
                (best, found),
            );
        }
        seeds
    }

    /// The best-first descent of both hierarchies from their roots: node
    /// pairs popped from the queue until it is empty or [`Found::head`]
    /// stops the step; a pair far apart for its size settled with its own
    /// step, a leaf pair measured ([`leaf_pair`](Self::leaf_pair)), any
    /// other pair split ([`expand`](Self::expand)). `false` when the work
    /// budget ran out before any contact was found: the step is undecided.
    #[inline]
    fn descend(
        &mut self,
        f: &Frame<'_, T>,
        seeds: &Seeds,
        best: &mut T,
        found: &mut Found<T>,
    ) -> bool {
        self.ws.clear();
        let roots = (
            self.ws.placed_slot(0, 0, || f.pa.place(self.descent.a, 0)),
            self.ws.placed_slot(1, 0, || f.pb.place(self.descent.b, 0)),
        );
        let root = NodeStep::Near(-T::INFINITY).resolved(f.limited);
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
            let out_of_work = self.descent.stats.out_of_work(&f.start, f.budget);
            match found.head((near, key), (*best, self.accept), f.first_only, out_of_work) {
                Head::Go => {}
                Head::Stop => break,
                Head::Cut => {
                    self.descent.stats.pruned += self.ws.len() as u64 + 1;
                    *best = best.min_nan(key);
                    break;
                }
                Head::OutOfWork => return false,
            }
            self.descent.stats.node_pairs += 1;
            if far {
                // Splitting a pair this far apart for its size would gain
                // little: its own step is safe for everything below it.
                self.descent.stats.settled += 1;
                *best = best.min_nan(key);
                continue;
            }
            let (na, nb) = (
                &self.descent.a.nodes[i as usize],
                &self.descent.b.nodes[j as usize],
            );
            match (na.leaf(), nb.leaf()) {
                (Some(li), Some(lj)) => self.leaf_pair(f, ((li, lj), at), seeds, best, found),
                (leaf_a, leaf_b) => {
                    // Descend into the larger ball (a leaf is never split).
                    let split_a = leaf_b.is_some()
                        || (leaf_a.is_none() && na.ball.radius() >= nb.ball.radius());
                    let children = if split_a {
                        [na.left, na.right]
                    } else {
                        [nb.left, nb.right]
                    };
                    self.expand(f, ((i, j), at), (split_a, children), *best, found);
                }
            }
        }
        true
    }

    /// A leaf pair popped from the queue (leaves `li` of A and `lj` of B,
    /// their nodes placed at `at`): skipped when it is a seed (measured
    /// before the descent: its step is in `best`), pruned when the slab of
    /// its corners along the line joining the ball centres (Lemma 9.1 holds
    /// for any direction) shows it no closer than the contact found or,
    /// before a contact, farther apart than the contact distance with a step
    /// that reaches `best`; else measured.
    #[inline]
    fn leaf_pair(
        &mut self,
        f: &Frame<'_, T>,
        ((li, lj), at): ((usize, usize), (u32, u32)),
        seeds: &Seeds,
        best: &mut T,
        found: &mut Found<T>,
    ) {
        if seeds.contains((li as u32, lj as u32)) {
            return;
        }
        let d = &mut self.descent;
        let (la, lb) = (&d.a.leaves[li], &d.b.leaves[lj]);
        let (ta, tb) = (f.pa.corners(la), f.pb.corners(lb));
        let (qa, qb) = (self.ws.placed[at.0 as usize], self.ws.placed[at.1 as usize]);
        if let Ok(n) = Direction::try_new(qb.centre - qa.centre) {
            let g = gap_down(
                slab_gap(&ta, &tb, n.get()),
                f.pa.leaf_err(la),
                f.pb.leaf_err(lb),
                f.pa.reach + f.pb.reach,
            );
            if let Some(touch) = found.touching {
                // The slab's gap is a lower bound of the distance.
                if g >= touch.distance {
                    d.stats.pruned += 1;
                    return;
                }
            } else if g > f.cd {
                // A pair certainly farther apart than the contact distance
                // is pruned when its step reaches the best.
                d.stats.bounds += 2;
                let (mu_a, mu_b) = f.rates.leaves(&f.pa, &f.pb, (la, lb), n);
                if step_down(g, f.clear, mu_a, mu_b) >= *best {
                    d.stats.pruned += 1;
                    return;
                }
            }
        }
        d.triangle_pair(
            (&f.pa, &f.pb),
            (li, lj),
            (&ta, &tb),
            (f.rates, f.cd, f.clear),
            (best, found),
        );
    }

    /// Splits a node pair (nodes `i` of A and `j` of B, placed at `at`)
    /// into the pairs of `children` (of A's node when `split_a`, else of
    /// B's) with the other node, placing each new node once per step (the
    /// kept one is placed), and queues each child pair whose own step
    /// ([`Descent::node_step`]) does not prune it ([`Found::queues`]).
    #[inline]
    fn expand(
        &mut self,
        f: &Frame<'_, T>,
        ((i, j), at): ((u32, u32), (u32, u32)),
        (split_a, children): (bool, [u32; 2]),
        best: T,
        found: &Found<T>,
    ) {
        for child in children {
            let (pair, at) = if split_a {
                let slot = self
                    .ws
                    .placed_slot(0, child, || f.pa.place(self.descent.a, child));
                ((child, j), (slot, at.1))
            } else {
                let slot = self
                    .ws
                    .placed_slot(1, child, || f.pb.place(self.descent.b, child));
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
            let near_within = if f.limited { -T::INFINITY } else { f.cd };
            let step = self
                .descent
                .node_step(
                    &f.pa,
                    &f.pb,
                    pair,
                    q,
                    (f.rates, near_within, f.clear),
                    (best_step, also),
                )
                .resolved(f.limited);
            if found.queues(step, best) {
                self.ws.enqueue(Pending::new(step, pair, at));
            } else {
                self.descent.stats.pruned += 1;
            }
        }
    }
}
