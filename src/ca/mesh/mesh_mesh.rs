//! Conservative advancement of two triangle meshes through their ball trees.

use super::found::{Found, Head, NodeStep};
use super::front::{Carry, FrontEntry};
use super::placed::{slab_gap, Placed, Rates};
use super::queue::{MeshWorkspace, Origin, Pending, Queued};
use super::seeds::{Seeds, SEEDS};
use super::stats::TraversalStats;
use super::traversal::Descent;
use crate::bvh::BallTree;
use crate::ca::solid::StartCheck;
use crate::ca::{CaError, CaParams, CaStep, MeshParams, Shape, StepResult, WitnessSearch, Work};
use crate::rounding::{diff_up, gap_down, least_resolved_reach, resolution_up, step_down};
use crate::{BoundingBall, Direction, Float, PreparedMotion};

/// What a seed's measurement certified (step, gap, closing rate), when it
/// certified one.
type SeedSteps<T> = [Option<(T, T, T)>; SEEDS];

/// A node pair (node of A, node of B) and where its nodes are placed in the
/// workspace.
type PlacedPair = ((u32, u32), (u32, u32));

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
///
/// A step of a query may start from the cut of node pairs the last step
/// ended with (its front), each keeping the step it certified until that
/// runs out or it may be within the contact distance, and measure only
/// those anew (Lemma 9.9, [`MeshParams::carry_front`]): it does when at
/// least half of the front would keep its step, and when a seed is already
/// within the contact distance (the search for the closest pair then
/// starts from the last step's front: about 6 % fewer instructions on the
/// knots).
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
    /// Whether steps carry the front, and what the front in the workspace
    /// is valid for (none: the next step descends from the roots).
    carry_front: bool,
    carry: Option<Carry<T>>,
    /// Whether the front this step is making covers every pair it left.
    front_ok: bool,
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
            carry_front: MeshParams::<T>::default().carry_front,
            carry: None,
            front_ok: false,
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
            carry: None,
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
    /// // `bodies`: the built-in test bodies (feature `bodies`).
    /// # #[cfg(feature = "bodies")] {
    /// use motion_bound::ca::{CaError, MeshPair, MeshParams, Parameter};
    /// use motion_bound::{bodies, BallTree};
    /// let tree = BallTree::try_from_mesh(&bodies::torus::<f64>(0.5, 0.1, 16, 8)?)?;
    /// let pair = MeshPair::new(&tree, &tree).try_with_params(MeshParams::default().with_far_ratio(f64::INFINITY))?;
    /// let bad = MeshPair::new(&tree, &tree).try_with_params(MeshParams::default().with_accept_fraction(1.5));
    /// assert_eq!(bad.err(), Some(CaError::InvalidParameter(Parameter::AcceptFraction)));
    /// # }
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn try_with_params(mut self, params: MeshParams<T>) -> Result<Self, CaError> {
        params.validate()?;
        self.accept = params.accept_fraction;
        self.descent.far_ratio = params.far_ratio;
        self.carry_front = params.carry_front;
        self.carry = None;
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
    /// // `bodies`: the built-in test bodies (feature `bodies`).
    /// # #[cfg(feature = "bodies")] {
    /// use motion_bound::ca::MeshPair;
    /// use motion_bound::{bodies, BallTree};
    /// let board = BallTree::try_from_mesh(&bodies::board::<f64>(2.0, 2.0, 0.002)?)?;
    /// let ball = BallTree::try_from_mesh(&bodies::icosphere::<f64>(0.3, 3)?)?;
    /// assert_eq!(MeshPair::new(&board, &ball).pieces_in_use(), (true, false));
    /// assert_eq!(MeshPair::new(&board, &board).pieces_in_use(), (false, false));
    /// # }
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
        let mut found = Found::new(params.witness_tolerance);
        self.closest = None;
        // The front of the last step, when it is this query's (Lemma 9.9).
        let motions = (*a.motion(), *b.motion());
        let key = frame.carry_key();
        let carry = self.carry.take().filter(|c| {
            self.carry_front
                && !frame.limited
                && c.takes(t, (&motions.0, &motions.1), key, self.ws.front.len())
        });
        self.front_ok = self.carry_front && !frame.limited;
        let pairs_before = self.descent.stats.node_pairs;
        let (seeds, measured) = self.measure_seeds(&frame, &mut best, &mut found);
        // Worth carrying when a seed is already within the contact distance
        // (the rest of the step is the search for the closest pair, among
        // the pairs near the last step's front, not a new descent), or
        // when most of it would keep its step: at least half its pairs
        // with a step left beyond the seeds' (a choice of speed only: a
        // fine front measured pair by pair costs more than a coarse
        // descent, `docs/performance.md`).
        let carry = carry.filter(|_| {
            if found.touching.is_some() {
                return true;
            }
            let stale = self.ws.front.iter().filter(|e| e.stale(t, best)).count();
            2 * stale <= self.ws.front.len()
        });
        if !self.descend(
            &frame,
            (&seeds, &measured),
            carry.is_some(),
            &mut best,
            &mut found,
        ) {
            return StepResult::WorkLimit;
        }
        self.closest = found.witness_triangles();
        let result = found.verdict(best, frame.limited, frame.resolution);
        if self.front_ok && matches!(result, StepResult::Advance { .. }) {
            self.ws.swap_fronts();
            let pairs = self.descent.stats.node_pairs - pairs_before;
            self.carry = Some(Carry::after(carry, (t, best), motions, key, pairs));
        }
        result
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
    /// The step's time, and the end of the interval its bounds hold over.
    t: T,
    horizon: T,
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
            t,
            horizon: a.motion().interval().end(),
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

    /// The parameters a front's certificates depend on.
    #[inline]
    fn carry_key(&self) -> (T, T, crate::BoundKind, bool) {
        (self.cd, self.clear, self.rates.kind, self.rates.one_sided)
    }

    /// The front entry of node pair `(i, j)` with its certified `step`,
    /// `gap` and closing `rate`.
    #[inline]
    fn entry(&self, pair: (u32, u32), (step, gap, rate): (T, T, T)) -> FrontEntry {
        FrontEntry::new(pair, self.t, self.horizon, (step, gap, rate, self.cd))
    }

    /// The front entry of a queued pair left at the step's end.
    #[inline]
    fn pending_entry(&self, p: &Pending) -> FrontEntry {
        p.front_entry(self.t, self.horizon, self.cd)
    }
}

impl<T: Float> MeshPair<'_, T> {
    /// Measures the leaf pairs the last step handed over (Lemma 9.4), at
    /// the new time, before the descent: each one's own step is safe for
    /// that pair and, usually close to the final step, lets the descent
    /// prune children as they are made. Returns them, for the descent to
    /// skip, with what each certified.
    #[inline]
    fn measure_seeds(
        &mut self,
        f: &Frame<'_, T>,
        best: &mut T,
        found: &mut Found<T>,
    ) -> (Seeds, SeedSteps<T>) {
        let seeds = core::mem::take(&mut self.descent.seeds);
        let mut measured = [None; SEEDS];
        for (k, &(i, j)) in seeds.pairs[..seeds.len].iter().enumerate() {
            if self.descent.stats.out_of_work(&f.start, f.budget) {
                break;
            }
            let (i, j) = (i as usize, j as usize);
            let corners = (
                f.pa.corners(&self.descent.a.leaves[i]),
                f.pb.corners(&self.descent.b.leaves[j]),
            );
            measured[k] = self.descent.triangle_pair(
                (&f.pa, &f.pb),
                (i, j),
                (&corners.0, &corners.1),
                (f.rates, f.cd, f.clear),
                (best, found),
            );
        }
        (seeds, measured)
    }

    /// Hands node pair `pair`, left unsplit with its certified step, gap
    /// and closing rate `m`, to the front the step is making (when it makes
    /// one: nothing is computed otherwise).
    #[inline]
    fn keep(&mut self, f: &Frame<'_, T>, pair: (u32, u32), m: (T, T, T)) {
        if self.front_ok {
            self.ws.next.push(f.entry(pair, m));
        }
    }

    /// The best-first descent of both hierarchies: from their roots, or
    /// from the last step's front (`carried`, Lemma 9.9). Node pairs are
    /// popped from the queue until it is empty or [`Found::head`] stops the
    /// step; a carried pair measured anew ([`consider`](Self::consider)), a
    /// pair far apart for its size settled with its own step, a leaf pair
    /// measured ([`leaf_pair`](Self::leaf_pair)), any other pair split
    /// ([`split`](Self::split)) and its children measured. Every pair left unsplit goes to the next
    /// front. `false` when the work budget ran out before any contact was
    /// found: the step is undecided.
    #[inline]
    fn descend(
        &mut self,
        f: &Frame<'_, T>,
        seeds: (&Seeds, &SeedSteps<T>),
        carried: bool,
        best: &mut T,
        found: &mut Found<T>,
    ) -> bool {
        self.ws.clear();
        self.ws.next.clear();
        if carried {
            self.descent.stats.carried += self.ws.enqueue_front(f.t) as u64;
        } else {
            let roots = (
                self.ws.placed_slot(0, 0, || f.pa.place(self.descent.a, 0)),
                self.ws.placed_slot(1, 0, || f.pb.place(self.descent.b, 0)),
            );
            let root = NodeStep::Near(-T::INFINITY).resolved(f.limited);
            self.ws.enqueue(Pending::new(root, (0, 0), roots));
        }
        while let Some(slot) = self.ws.pop().map(Queued::slot) {
            let p = self.ws.pending[slot as usize];
            let Pending {
                near,
                key,
                i,
                j,
                far,
                at,
                origin,
            } = p;
            let key = T::from_f64(key.0);
            let out_of_work = self.descent.stats.out_of_work(&f.start, f.budget);
            match found.head((near, key), (*best, self.accept), f.first_only, out_of_work) {
                Head::Go => {}
                Head::Stop => break,
                Head::Cut => {
                    self.descent.stats.pruned += self.ws.len() as u64 + 1;
                    *best = best.min_nan(key);
                    // Every pair left keeps its step: the next front.
                    if self.front_ok {
                        self.ws.queue_to_front(&p, (f.t, f.horizon, f.cd));
                    }
                    break;
                }
                Head::OutOfWork => return false,
            }
            self.descent.stats.node_pairs += 1;
            // The pairs to measure: a carried pair anew, or a split pair's
            // two children (one call site of the node step, which then
            // stays inlined in the hot loop).
            let (pairs, count) = if let Origin::Carried { .. } = origin {
                // Its carried step is short of the best, or it may be near:
                // measured anew, as a child would be.
                self.descent.stats.refreshed += 1;
                let at = (
                    self.ws.placed_slot(0, i, || f.pa.place(self.descent.a, i)),
                    self.ws.placed_slot(1, j, || f.pb.place(self.descent.b, j)),
                );
                ([((i, j), at); 2], 1)
            } else if far {
                // Splitting a pair this far apart for its size would gain
                // little: its own step is safe for everything below it.
                self.descent.stats.settled += 1;
                *best = best.min_nan(key);
                if self.front_ok {
                    self.ws.next.push(f.pending_entry(&p));
                }
                continue;
            } else {
                let (na, nb) = (
                    &self.descent.a.nodes[i as usize],
                    &self.descent.b.nodes[j as usize],
                );
                match (na.leaf(), nb.leaf()) {
                    (Some(li), Some(lj)) => {
                        self.leaf_pair(f, ((i, j), (li, lj), at), seeds, best, found);
                        continue;
                    }
                    (leaf_a, leaf_b) => {
                        // Descend into the larger ball (a leaf is never split).
                        let split_a = leaf_b.is_some()
                            || (leaf_a.is_none() && na.ball.radius() >= nb.ball.radius());
                        let children = if split_a {
                            [na.left, na.right]
                        } else {
                            [nb.left, nb.right]
                        };
                        (self.split(f, ((i, j), at), (split_a, children)), 2)
                    }
                }
            };
            self.consider(f, &pairs[..count], *best, found);
        }
        true
    }

    /// A leaf pair popped from the queue (nodes `i` of A and `j` of B,
    /// leaves `li` and `lj`, placed at `at`): a seed is not measured again
    /// (its step is in `best`); else pruned when the slab of its corners
    /// along the line joining the ball centres (Lemma 9.1 holds for any
    /// direction) shows it no closer than the contact found (less the
    /// witness tolerance, [`Found::bar`]) or, before a
    /// contact, farther apart than the contact distance with a step that
    /// reaches `best`; else measured. Its certified step goes to the front.
    #[inline]
    fn leaf_pair(
        &mut self,
        f: &Frame<'_, T>,
        (pair, (li, lj), at): ((u32, u32), (usize, usize), (u32, u32)),
        (seeds, measured): (&Seeds, &SeedSteps<T>),
        best: &mut T,
        found: &mut Found<T>,
    ) {
        if let Some(k) = seeds.position((li as u32, lj as u32)) {
            match measured[k] {
                Some(m) => self.keep(f, pair, m),
                None => self.front_ok = false,
            }
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
            if let Some(bar) = found.bar() {
                // The slab's gap is a lower bound of the distance.
                if g >= bar {
                    d.stats.pruned += 1;
                    return;
                }
            } else if g > f.cd {
                // A pair certainly farther apart than the contact distance
                // is pruned when its step reaches the best.
                d.stats.bounds += 2;
                let (mu_a, mu_b) = f.rates.leaves(&f.pa, &f.pb, (la, lb), n);
                let step = step_down(g, f.clear, mu_a, mu_b);
                if step >= *best {
                    d.stats.pruned += 1;
                    self.keep(f, pair, (step, g, mu_a + mu_b));
                    return;
                }
            }
        }
        let measured = d.triangle_pair(
            (&f.pa, &f.pb),
            (li, lj),
            (&ta, &tb),
            (f.rates, f.cd, f.clear),
            (best, found),
        );
        match measured {
            Some(m) => self.keep(f, pair, m),
            None => self.front_ok = false,
        }
    }

    /// The pairs a node pair (nodes `i` of A and `j` of B, placed at `at`)
    /// splits into: each of `children` (of A's node when `split_a`, else of
    /// B's) with the other node, each new node placed once per step (the
    /// kept one is placed).
    #[inline]
    fn split(
        &mut self,
        f: &Frame<'_, T>,
        ((i, j), at): ((u32, u32), (u32, u32)),
        (split_a, children): (bool, [u32; 2]),
    ) -> [PlacedPair; 2] {
        [
            self.child(f, ((i, j), at), split_a, children[0]),
            self.child(f, ((i, j), at), split_a, children[1]),
        ]
    }

    /// The pair of `child` (of A's node when `split_a`, else of B's) with
    /// the other node of pair `(i, j)` placed at `at`, the child placed.
    #[inline(always)]
    fn child(
        &mut self,
        f: &Frame<'_, T>,
        ((i, j), at): ((u32, u32), (u32, u32)),
        split_a: bool,
        child: u32,
    ) -> PlacedPair {
        if split_a {
            let slot = self
                .ws
                .placed_slot(0, child, || f.pa.place(self.descent.a, child));
            ((child, j), (slot, at.1))
        } else {
            let slot = self
                .ws
                .placed_slot(1, child, || f.pb.place(self.descent.b, child));
            ((i, child), (at.0, slot))
        }
    }

    /// Measures each node pair of `pairs` placed at its `at` (its own
    /// step, [`Descent::node_step`]) and queues it unless that prunes it
    /// ([`Found::queues`]); a pruned pair goes to the front with its step.
    /// (One call site for the node step, which then stays inlined: the hot
    /// loop.)
    #[inline(always)]
    fn consider(&mut self, f: &Frame<'_, T>, pairs: &[PlacedPair], best: T, found: &Found<T>) {
        for &(pair, at) in pairs {
            self.consider_each(f, (pair, at), best, found);
        }
    }

    /// One pair of [`consider`](Self::consider).
    #[inline(always)]
    fn consider_each(
        &mut self,
        f: &Frame<'_, T>,
        (pair, at): ((u32, u32), (u32, u32)),
        best: T,
        found: &Found<T>,
    ) {
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
            if let NodeStep::Apart {
                step, gap, rate, ..
            } = step
            {
                self.keep(f, pair, (step, gap, rate));
            }
        }
    }
}
