//! A planner's edge at a planner's price: the joint-space segment certified
//! free in one pass where every link's ball is clear of what it is checked
//! against, and split (in time, or down a ball tree) only where it is not
//! (`proofs/13-chains.md`, Lemmas 13.5 and 13.6).
//!
//! The engine works on *items*: a node of a link's ball tree and what it is
//! checked against (a shape obstacle, a node of a point cloud's or a mesh
//! obstacle's tree, or a node of another link's tree). Over a time interval
//! `[t0, t1]` the chain is placed once at its middle `m`; an item is clear
//! over the whole interval when its certified gap at `m` exceeds the
//! distance its balls can sweep in half the interval (Lemma 13.5: the chain
//! bound taken both ways from `m`). Items that are not clear are refined
//! down a tree when a ball is larger than the sweep, measured exactly at the
//! leaves (a triangle against a shape, a triangle or a cloud's points), or
//! kept; the kept ones are checked again on each half of the interval,
//! the earlier half first. So the intervals before the one being checked
//! are certified free, and a contact is declared at `m` on an exact
//! distance within the contact distance: never later than the first touch.

use alloc::vec::Vec;

use crate::bvh::{Hierarchy, Node, NO_CHILD};
use crate::chain::bound::LinkMotion;
use crate::chain::gap::{axes_gap, box_support_up, from_box, placed_corners, slab_gap};
use crate::chain::report::ChainPair;
use crate::chain::segment::{take_motion, Segment, Work};
use crate::chain::shapes::{node_points, triangle_points_gap, Against, Geometry, ShapeObstacle};
use crate::geometry::closest::{point_triangle_vec, triangle_triangle_vec};
use crate::geometry::gjk::{gjk_distance_from, ConvexPolytope, GjkParams};
use crate::rounding::{add_up, diff_up, gamma, gap_down, mul_up, sum_up};
use crate::{Float, Vec3};

/// How an edge query ended ([`ChainScene::check_edge`](crate::chain::ChainScene::check_edge)).
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum EdgeOutcome<T> {
    /// Every checked pair is certified apart (beyond the padding) over the
    /// whole segment.
    Free,
    /// A contact: the segment is certified free on `[0, free_until]`, and at
    /// `at` (`free_until <= at`, at most half a checked interval later) the
    /// pair's surfaces are within the contact distance plus the padding
    /// (computed distance).
    Contact {
        /// The segment is free before this time.
        free_until: T,
        /// The time at which the contact was measured.
        at: T,
        /// The pair found within the contact distance.
        pair: ChainPair,
    },
    /// The work budget ([`ChainParams::edge_budget`](crate::chain::ChainParams::edge_budget))
    /// ran out: free on `[0, free_until]`, the rest undecided. A planner
    /// treats it as not free.
    Undecided {
        /// The segment is free before this time.
        free_until: T,
    },
}

impl<T> EdgeOutcome<T> {
    /// Whether the edge is certified free.
    #[must_use]
    pub const fn is_free(&self) -> bool {
        matches!(self, Self::Free)
    }
}

/// What an edge query did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct EdgeStats {
    /// Items tested (a ball or triangle against what it is checked
    /// against), the rake's lane tests among them
    /// ([`lane_tests`](Self::lane_tests)): the work the budget counts.
    pub tests: usize,
    /// Leaf pairs among them (a triangle against a shape, a triangle or a
    /// cloud's points), measured at one time: by slab gaps first, and by
    /// their closest points only where the slabs do not clear them.
    pub leaf_tests: usize,
    /// Time intervals the chain was placed for (forward kinematics).
    pub intervals: usize,
    /// The rake's sub-intervals (0 when the edge was not raked).
    pub raked_intervals: usize,
    /// The rake's lane tests: a ball (or a link's enclosing ball) against a
    /// proxy or a ball, at eight sub-intervals at once.
    pub lane_tests: usize,
    /// The (sub-interval, pair) items the rake handed on to the finer
    /// engine.
    pub handed: usize,
}

impl core::ops::AddAssign for EdgeStats {
    fn add_assign(&mut self, o: Self) {
        self.tests += o.tests;
        self.leaf_tests += o.leaf_tests;
        self.intervals += o.intervals;
        self.raked_intervals += o.raked_intervals;
        self.lane_tests += o.lane_tests;
        self.handed += o.handed;
    }
}

/// An edge query's outcome and work.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct EdgeReport<T> {
    /// How it ended.
    pub outcome: EdgeOutcome<T>,
    /// What it did.
    pub stats: EdgeStats,
}

/// What an item's link node is checked against.
#[derive(Clone, Copy, Debug)]
pub(super) enum Target {
    /// Shape obstacle `s` (not a cloud).
    Shape(u32),
    /// Node `k` of cloud `s`'s tree.
    Cloud(u32, u32),
    /// Node `k` of mesh obstacle `o`'s tree.
    Mesh(u32, u32),
    /// Node `k` of link `b`'s tree.
    Link(u32, u32),
}

/// A node of a link's tree and what it is checked against, with the
/// motion slots of the link and (for a link pair) of the other link: a pair
/// of links counts only the joints below their common ancestor (Lemma 13.2,
/// part 3), so each side's motion is filled with that many joints skipped.
#[derive(Clone, Copy, Debug)]
pub(super) struct Item {
    pub(super) link: u32,
    pub(super) node: u32,
    pub(super) target: Target,
    pub(super) slot: u16,
    pub(super) slot_b: u16,
}

/// Why an interval stopped the query.
enum Stop<T> {
    Contact { at: T, pair: ChainPair },
    Undecided,
}

/// What testing one item found.
enum Verdict {
    /// Clear over the interval.
    Clear,
    /// Not clear; refine the link's node.
    SplitLink,
    /// Not clear; refine the target's node.
    SplitTarget,
    /// Not clear and nothing to refine: check again on the halves.
    Keep,
    /// Within the contact distance at the interval's middle.
    Contact,
}

/// An edge query's reusable buffers.
#[derive(Clone, Debug, Default)]
pub(super) struct EdgeWork<T> {
    pub(super) work: Work<T>,
    motions: Vec<LinkMotion<T>>,
    still: Vec<LinkMotion<T>>,
    items: Vec<Item>,
    /// Items to test in this interval, with the sweeps of both sides when
    /// known (a parent's: Lemma 13.5, a node's points are its parent's), negative
    /// when not yet computed.
    stack: Vec<(Item, [T; 2])>,
    stats: EdgeStats,
    /// The intervals of one length and of the next (breadth first): each
    /// interval and the range of its items in `items`.
    level: Vec<([T; 2], usize, usize)>,
    next: Vec<([T; 2], usize, usize)>,
    /// The motion slots an interval's items use.
    used: Vec<bool>,
}

/// The scene along one edge, as the engine sees it.
pub(super) struct Edge<'a, T: 'static> {
    pub(super) segment: Segment<'a, T>,
    pub(super) shapes: &'a [ShapeObstacle<T>],
    /// Each link's convex hull (`None` without geometry): a link pair's
    /// first cover (Lemma 13.7).
    pub(super) hulls: &'a [Option<ConvexPolytope<'a, T>>],
    /// Each mesh obstacle's convex hull placed by its pose (`None` when GJK
    /// refuses a vertex): its first cover against a link's (Lemma 13.8).
    pub(super) obstacle_hulls: &'a [Option<ConvexPolytope<'a, T>>],
    /// Contact distance plus padding: what a leaf's computed distance is
    /// declared touching at.
    pub(super) touch: T,
    /// What a certified gap must exceed.
    pub(super) padding: T,
    pub(super) budget: usize,
    /// Whether a contact found must be the first one (depth first in time,
    /// [`by_time`](Self::by_time)), or any one will do
    /// ([`coarse_first`](Self::coarse_first)).
    pub(super) first_contact: bool,
}

impl<T: Float> Edge<'_, T> {
    /// Runs the query from the items `initial`.
    pub(super) fn run(
        &self,
        initial: &[Item],
        slots: &[(usize, usize)],
        w: &mut EdgeWork<T>,
    ) -> EdgeReport<T> {
        let n = self.prepare(initial, slots, w);
        let found = if self.first_contact {
            self.by_time(w, slots, [T::ZERO, T::ONE], 0, n)
        } else {
            w.level.clear();
            w.level.push(([T::ZERO, T::ONE], 0, n));
            self.coarse_first_from(w, slots)
        };
        self.report(found, w)
    }

    /// Runs the query from the (sub-interval, item) pairs the rake left:
    /// `fails` as `(order, start, item)` for the sub-interval
    /// `[start / times, (start + 1) / times]` (`times` a power of two, so
    /// every end is dyadic), `item` an index into `initial`, sorted (and
    /// with every pair of one sub-interval together); every other
    /// (sub-interval, item) pair is certified clear by the rake (Lemma
    /// 13.13). Depth first in time for the first contact (`order` then zero:
    /// the sub-intervals in time order), else every sub-interval's items
    /// before any halves, in the order given.
    pub(super) fn run_spans(
        &self,
        initial: &[Item],
        fails: &[(u32, u32, u32)],
        (times, lane_tests): (u32, usize),
        slots: &[(usize, usize)],
        w: &mut EdgeWork<T>,
    ) -> EdgeReport<T> {
        self.prepare(&[], slots, w);
        w.stats.raked_intervals = times as usize;
        w.stats.lane_tests = lane_tests;
        w.stats.handed = fails.len();
        // The rake's lane tests count against the budget as items do.
        w.stats.tests = lane_tests;
        if lane_tests > self.budget {
            return self.report(Err((T::ZERO, Stop::Undecided)), w);
        }
        let scale = T::ONE / T::from_u32(times);
        let mut level = core::mem::take(&mut w.level);
        level.clear();
        let mut i = 0;
        while i < fails.len() {
            let (key, first, _) = fails[i];
            let start = w.items.len();
            while i < fails.len() && fails[i].0 == key && fails[i].1 == first {
                w.items.push(initial[fails[i].2 as usize]);
                i += 1;
            }
            let span = [T::from_u32(first) * scale, T::from_u32(first + 1) * scale];
            level.push((span, start, w.items.len()));
        }
        let found = if self.first_contact {
            let mut out = Ok(());
            for &(span, start, end) in &level {
                out = self.by_time(w, slots, span, start, end);
                if out.is_err() {
                    break;
                }
            }
            w.level = level;
            out
        } else {
            w.level = level;
            self.coarse_first_from(w, slots)
        };
        self.report(found, w)
    }

    /// The report of a query's end.
    fn report(&self, found: Result<(), (T, Stop<T>)>, w: &EdgeWork<T>) -> EdgeReport<T> {
        let outcome = match found {
            Ok(()) => EdgeOutcome::Free,
            Err((t0, Stop::Contact { at, pair })) => EdgeOutcome::Contact {
                free_until: t0,
                at,
                pair,
            },
            Err((t0, Stop::Undecided)) => EdgeOutcome::Undecided { free_until: t0 },
        };
        EdgeReport {
            outcome,
            stats: w.stats,
        }
    }

    /// The static check at the segment's start (`q0`; the caller passes
    /// `q1 = q0`): a pair whose surfaces are within `touch` there (computed
    /// distance), or one that no certified gap shows apart by more than the
    /// padding (a tie within rounding, taken as touching); `None` when every
    /// pair is certified apart.
    pub(super) fn static_check(
        &self,
        initial: &[Item],
        slots: &[(usize, usize)],
        w: &mut EdgeWork<T>,
    ) -> Option<ChainPair> {
        let n = self.prepare(initial, slots, w);
        match self.check_interval(w, slots, [T::ZERO, T::ZERO], 0, n) {
            Ok(_) => w.items.get(n).map(|&it| self.pair(it)),
            Err(Stop::Contact { pair, .. }) => Some(pair),
            // Not reached (a point is never halved and the budget is
            // checked): the first item, conservatively.
            Err(Stop::Undecided) => initial.first().map(|&it| self.pair(it)),
        }
    }

    /// The rates, errors, still motions and initial items of a query; the
    /// number of initial items.
    fn prepare(&self, initial: &[Item], slots: &[(usize, usize)], w: &mut EdgeWork<T>) -> usize {
        let chain = self.segment.chain;
        let (q0, q1) = (self.segment.q0, self.segment.q1);
        w.stats = EdgeStats::default();
        w.work.errors.compute(chain, q0, q1);
        w.work.rate.clear();
        w.work.rate.extend(
            q0.iter()
                .zip(q1)
                .map(|(a, b)| (*b - *a).abs() * (T::ONE + gamma::<T>(2))),
        );
        w.motions
            .resize_with(slots.len(), || take_motion(&mut None));
        w.still.clear();
        for o in self.segment.obstacles {
            let mut m = take_motion(&mut None);
            m.pose = o.pose;
            m.delta = o.delta;
            m.reach = o.reach;
            w.still.push(m);
        }
        w.items.clear();
        w.items.extend_from_slice(initial);
        w.items.len()
    }

    /// Checks the items `start..end` over `[t0, t1]` and its halves, the
    /// earlier half first (depth first in time); on a stop, the interval's
    /// start (everything before it is certified free) and why.
    fn by_time(
        &self,
        w: &mut EdgeWork<T>,
        slots: &[(usize, usize)],
        [t0, t1]: [T; 2],
        start: usize,
        end: usize,
    ) -> Result<(), (T, Stop<T>)> {
        let kept = w.items.len();
        let mid = self
            .check_interval(w, slots, [t0, t1], start, end)
            .map_err(|s| (t0, s))?;
        let survivors = w.items.len();
        if survivors > kept {
            let first = self.by_time(w, slots, [t0, mid], kept, survivors);
            let result = first.and_then(|()| self.by_time(w, slots, [mid, t1], kept, survivors));
            w.items.truncate(kept);
            return result;
        }
        Ok(())
    }

    /// The same checks, breadth first: every interval of one length before
    /// any shorter one, so that a contact anywhere on the edge is met at the
    /// coarsest sampling that shows it (what a yes-or-no edge check wants).
    /// On a stop, the earliest start of an interval not yet certified.
    /// The intervals of `w.level` first (sorted by time), each with its
    /// items.
    fn coarse_first_from(
        &self,
        w: &mut EdgeWork<T>,
        slots: &[(usize, usize)],
    ) -> Result<(), (T, Stop<T>)> {
        let mut level = core::mem::take(&mut w.level);
        let mut next = core::mem::take(&mut w.next);
        let mut result = Ok(());
        'levels: while !level.is_empty() {
            next.clear();
            for (at, &(span, start, end)) in level.iter().enumerate() {
                let kept = w.items.len();
                match self.check_interval(w, slots, span, start, end) {
                    Ok(mid) => {
                        let survivors = w.items.len();
                        if survivors > kept {
                            next.push(([span[0], mid], kept, survivors));
                            next.push(([mid, span[1]], kept, survivors));
                        }
                    }
                    Err(stop) => {
                        // The earliest start not yet certified: this span,
                        // the halves found so far and the spans not yet
                        // taken (not in time order when the rake put
                        // urgent ones first).
                        let pending = next.iter().chain(&level[at + 1..]).fold(span[0], |m, i| {
                            if i.0[0] < m {
                                i.0[0]
                            } else {
                                m
                            }
                        });
                        result = Err((pending, stop));
                        break 'levels;
                    }
                }
            }
            core::mem::swap(&mut level, &mut next);
        }
        w.level = level;
        w.next = next;
        result
    }

    /// Places the chain at the middle of `[t0, t1]` and tests the items
    /// `start..end` over the interval, appending those not clear to
    /// `w.items`; the middle, or why the query stops.
    fn check_interval(
        &self,
        w: &mut EdgeWork<T>,
        slots: &[(usize, usize)],
        [t0, t1]: [T; 2],
        start: usize,
        end: usize,
    ) -> Result<T, Stop<T>> {
        let chain = self.segment.chain;
        // Dyadic ends: the middle is exact, and so is the half width
        // (rounded up all the same).
        let mid = (t0 + t1) * T::HALF;
        let half = diff_up(t1, mid);
        // An interval too short to halve (a point `[t, t]` is a static
        // check, and fine).
        if !(mid > t0 && mid < t1) && t0 != t1 {
            return Err(Stop::Undecided);
        }
        w.stats.intervals += 1;
        self.segment.place(&mut w.work, mid);
        // Only the motion slots these items use (their descendants use the
        // same ones): a link's path terms cost as much as a few tests.
        w.used.clear();
        w.used.resize(slots.len(), false);
        for it in &w.items[start..end] {
            w.used[it.slot as usize] = true;
            if matches!(it.target, Target::Link(..)) {
                w.used[it.slot_b as usize] = true;
            }
        }
        for (k, (m, &(link, skip))) in w.motions.iter_mut().zip(slots).enumerate() {
            if w.used[k] {
                w.work.fill(chain, m, link, skip, half);
            }
        }
        for i in start..end {
            w.stack.push((w.items[i], [-T::ONE; 2]));
            while let Some((it, mut sweeps)) = w.stack.pop() {
                w.stats.tests += 1;
                if w.stats.tests > self.budget {
                    w.stack.clear();
                    return Err(Stop::Undecided);
                }
                match self.test(&w.motions, &w.still, &mut w.stats, it, &mut sweeps) {
                    Verdict::Clear => {}
                    Verdict::Keep => w.items.push(it),
                    Verdict::SplitLink => {
                        if let Some(tree) = self.link_tree(it.link) {
                            let node = &tree.nodes[it.node as usize];
                            let m = &w.motions[it.slot as usize];
                            let other = self.target_centre(&w.motions, &w.still, it);
                            let far = |i: u32| {
                                let b = &tree.nodes[i as usize].ball;
                                (m.pose.transform_point(*b.centre()) - other).length() - b.radius()
                            };
                            // The child nearer the other side last: taken
                            // first, where a contact is likeliest.
                            let (near, away) = nearer_last(node.left, node.right, far);
                            for child in [away, near] {
                                w.stack.push((Item { node: child, ..it }, sweeps));
                            }
                        }
                    }
                    Verdict::SplitTarget => self.split_target(w, it, sweeps),
                    Verdict::Contact => {
                        w.stack.clear();
                        return Err(Stop::Contact {
                            at: mid,
                            pair: self.pair(it),
                        });
                    }
                }
            }
        }
        Ok(mid)
    }

    /// Link `link`'s hierarchy (`None` for a link without geometry, which
    /// the scene never puts in an item).
    fn link_tree(&self, link: u32) -> Option<&Hierarchy<T>> {
        self.segment.chain.links[link as usize]
            .tree
            .as_ref()
            .map(|t| &t.whole)
    }

    fn pair(&self, it: Item) -> ChainPair {
        let link = it.link as usize;
        match it.target {
            Target::Shape(s) | Target::Cloud(s, _) => ChainPair::Shape {
                link,
                shape: s as usize,
            },
            Target::Mesh(o, _) => ChainPair::Obstacle {
                link,
                obstacle: o as usize,
            },
            Target::Link(b, _) => ChainPair::SelfCollision {
                a: link.min(b as usize),
                b: link.max(b as usize),
            },
        }
    }

    fn split_target(&self, w: &mut EdgeWork<T>, it: Item, sweeps: [T; 2]) {
        let children = match it.target {
            Target::Shape(_) => return,
            Target::Cloud(s, k) => match &self.shapes[s as usize].geometry {
                Geometry::Points { tree, .. } => {
                    let n = &tree.nodes()[k as usize];
                    [Target::Cloud(s, n.left), Target::Cloud(s, n.right)]
                }
                _ => return,
            },
            Target::Mesh(o, k) => {
                let n = &self.segment.obstacles[o as usize].tree.whole.nodes[k as usize];
                [Target::Mesh(o, n.left), Target::Mesh(o, n.right)]
            }
            Target::Link(b, k) => {
                let Some(tree) = self.link_tree(b) else {
                    return;
                };
                let n = &tree.nodes[k as usize];
                [Target::Link(b, n.left), Target::Link(b, n.right)]
            }
        };
        let here = self.link_tree(it.link).map_or(Vec3::ZERO, |t| {
            w.motions[it.slot as usize]
                .pose
                .transform_point(*t.nodes[it.node as usize].ball.centre())
        });
        let far = |k: usize| {
            let (c, r) = self.target_ball(
                &w.motions,
                &w.still,
                Item {
                    target: children[k],
                    ..it
                },
            );
            (c - here).length() - r
        };
        let (near, away) = nearer_last(0, 1, |k| far(k as usize));
        for k in [away, near] {
            w.stack.push((
                Item {
                    target: children[k as usize],
                    ..it
                },
                sweeps,
            ));
        }
    }

    /// The placed centre and radius of an item's target node (a shape's
    /// placement with radius zero).
    fn target_ball(
        &self,
        motions: &[LinkMotion<T>],
        still: &[LinkMotion<T>],
        it: Item,
    ) -> (Vec3<T>, T) {
        match it.target {
            Target::Shape(s) => (self.shapes[s as usize].pose.translation, T::ZERO),
            Target::Cloud(s, k) => match &self.shapes[s as usize].geometry {
                Geometry::Points { tree, .. } => {
                    let b = &tree.nodes()[k as usize].ball;
                    (Vec3::from_array(*b.centre()), b.radius())
                }
                _ => (Vec3::ZERO, T::ZERO),
            },
            Target::Mesh(o, k) => {
                let b = &self.segment.obstacles[o as usize].tree.whole.nodes[k as usize].ball;
                (
                    still[o as usize].pose.transform_point(*b.centre()),
                    b.radius(),
                )
            }
            Target::Link(b, k) => match self.link_tree(b) {
                Some(tree) => {
                    let ball = &tree.nodes[k as usize].ball;
                    (
                        motions[it.slot_b as usize]
                            .pose
                            .transform_point(*ball.centre()),
                        ball.radius(),
                    )
                }
                None => (Vec3::ZERO, T::ZERO),
            },
        }
    }

    /// The placed centre of an item's target node.
    fn target_centre(
        &self,
        motions: &[LinkMotion<T>],
        still: &[LinkMotion<T>],
        it: Item,
    ) -> Vec3<T> {
        self.target_ball(motions, still, it).0
    }

    /// Tests one item over the current interval (Lemmas 13.5 and 13.6).
    fn test(
        &self,
        motions: &[LinkMotion<T>],
        still: &[LinkMotion<T>],
        stats: &mut EdgeStats,
        it: Item,
        sweeps: &mut [T; 2],
    ) -> Verdict {
        let ma = &motions[it.slot as usize];
        // A link without geometry meets nothing.
        let Some(ta) = self.link_tree(it.link) else {
            return Verdict::Clear;
        };
        let na = &ta.nodes[it.node as usize];
        let ca = ma.pose.transform_point(*na.ball.centre());
        let ra = na.ball.radius();
        // Every point below a node is its parent's: the parent's sweep holds.
        if sweeps[0] < T::ZERO {
            sweeps[0] = mul_up(ma.dt, ma.sweep_speed(ca, ra));
        }
        let sa = sweeps[0];
        let leaf_a = na.leaf();
        match it.target {
            Target::Shape(s) => {
                let o = &self.shapes[s as usize];
                let against = match &o.geometry {
                    Geometry::Convex(shape) => Against::Convex(shape, o.pose, o.support_err),
                    Geometry::HalfSpace(m) => Against::Plane(*m, o.pose, o.support_err),
                    Geometry::Points { .. } => return Verdict::Keep,
                };
                let need = add_up(sa, self.padding);
                if let Some(leaf) = leaf_a {
                    stats.leaf_tests += 1;
                    let tri = placed_corners(ta, leaf, ma);
                    // First the cheap slab gap along the leaf ball's
                    // direction to the shape.
                    if against.triangle_slab(&tri, ca, ma.delta) > need {
                        return Verdict::Clear;
                    }
                    let (gap, estimate) = against.triangle_gap(&tri, ma.delta);
                    return self.leaf_verdict(gap, estimate, need);
                }
                let mut gap = against.ball_gap(ca, ra, ma.delta);
                if gap <= need {
                    // The box's slab gap along the direction from its centre
                    // to the shape: tighter for flat or long nodes.
                    let c = ma.pose.transform_point(na.obb.centre);
                    if let Some(n) = against.towards(c) {
                        let hi = box_support_up(&na.obb, ma, n);
                        let weight = sum_up(c.norm_l1(), na.obb.reach_up());
                        gap = gap.max_nan(against.slab(hi, weight, ma.delta, n));
                    }
                }
                if gap > need {
                    Verdict::Clear
                } else if ra > self.refine_below(gap, sa) {
                    Verdict::SplitLink
                } else {
                    Verdict::Keep
                }
            }
            Target::Cloud(s, k) => {
                let o = &self.shapes[s as usize];
                let Geometry::Points { tree, radius, ball } = &o.geometry else {
                    return Verdict::Keep;
                };
                let nb = &tree.nodes()[k as usize];
                let cb = Vec3::from_array(*nb.ball.centre());
                let rb = sum_up(nb.ball.radius(), *radius);
                let reach = sum_up(ma.reach, sum_up(cb.length(), rb));
                let gap = gap_down((cb - ca).length() - ra - rb, ma.delta, o.delta, reach);
                let need = add_up(sa, self.padding);
                if gap > need {
                    return Verdict::Clear;
                }
                let leaf_b = nb.left == NO_CHILD;
                match (leaf_a, leaf_b) {
                    (Some(leaf), true) => {
                        stats.leaf_tests += 1;
                        let tri = placed_corners(ta, leaf, ma);
                        let points = node_points(tree, nb.start, nb.end);
                        let (gap, estimate) = triangle_points_gap(&tri, ma.delta, points, ball);
                        self.leaf_verdict(gap, estimate, need)
                    }
                    _ => split(
                        leaf_a.is_none(),
                        ra,
                        !leaf_b,
                        rb,
                        self.refine_below(gap, sa),
                    ),
                }
            }
            Target::Mesh(ob, k) => {
                let o = &self.segment.obstacles[ob as usize];
                let tb = &o.tree.whole;
                let mb = &still[ob as usize];
                if it.node == 0 && k == 0 {
                    let nb = &tb.nodes[0];
                    let cb = mb.pose.transform_point(*nb.ball.centre());
                    let rb = nb.ball.radius();
                    // The roots' balls and boxes before the hulls: a box
                    // clears a long or flat obstacle (a pole, a plate)
                    // that its ball does not, for a few slabs (Lemma 13.6).
                    let need = add_up(sa, self.padding);
                    let balls = gap_down(
                        (cb - ca).length() - ra - rb,
                        ma.delta,
                        mb.delta,
                        ma.reach + mb.reach,
                    );
                    if balls > need
                        || box_gap((na, ma, ca, ra), (nb, mb, cb, rb), balls, need) > need
                    {
                        return Verdict::Clear;
                    }
                    let hulls = || {
                        let ha = self
                            .hulls
                            .get(it.link as usize)?
                            .as_ref()?
                            .with_pose(ma.pose)
                            .ok()?;
                        Some((ha, *self.obstacle_hulls.get(ob as usize)?.as_ref()?))
                    };
                    if let Some(v) =
                        self.hull_verdict(hulls, (ma, sa), (mb, T::ZERO), (ca, ra), (cb, rb))
                    {
                        return v;
                    }
                }
                self.node_pair(stats, (ta, it.node, ma, sa), (tb, k, mb, T::ZERO), (ca, ra))
            }
            Target::Link(b, k) => {
                let Some(tb) = self.link_tree(b) else {
                    return Verdict::Clear;
                };
                let mb = &motions[it.slot_b as usize];
                let nb = &tb.nodes[k as usize];
                let cb = mb.pose.transform_point(*nb.ball.centre());
                if sweeps[1] < T::ZERO {
                    sweeps[1] = mul_up(mb.dt, mb.sweep_speed(cb, nb.ball.radius()));
                }
                let sb = sweeps[1];
                if it.node == 0 && k == 0 {
                    let hulls = || {
                        let place = |l: u32, pose| {
                            self.hulls.get(l as usize)?.as_ref()?.with_pose(pose).ok()
                        };
                        Some((place(it.link, ma.pose)?, place(b, mb.pose)?))
                    };
                    if let Some(v) = self.hull_verdict(
                        hulls,
                        (ma, sa),
                        (mb, sb),
                        (ca, ra),
                        (cb, nb.ball.radius()),
                    ) {
                        return v;
                    }
                }
                self.node_pair(stats, (ta, it.node, ma, sa), (tb, k, mb, sb), (ca, ra))
            }
        }
    }

    /// A pair of links at their roots, or a link and a mesh obstacle at
    /// theirs, by their convex hulls (Lemmas 13.7 and 13.8; `hulls` places
    /// them, called only when the root balls do not clear the pair): clear
    /// when the hulls' certified gap exceeds both sweeps and the padding;
    /// kept whole for the interval's halves while that gap is above the
    /// padding; `None` (descend the trees as before) otherwise: the hulls
    /// meet at the middle, or are much nearer than the meshes (a mesh far
    /// from convex).
    fn hull_verdict<'h>(
        &self,
        hulls: impl FnOnce() -> Option<(ConvexPolytope<'h, T>, ConvexPolytope<'h, T>)>,
        (ma, sa): (&LinkMotion<T>, T),
        (mb, sb): (&LinkMotion<T>, T),
        (ca, ra): (Vec3<T>, T),
        (cb, rb): (Vec3<T>, T),
    ) -> Option<Verdict> {
        let need = add_up(add_up(sa, sb), self.padding);
        // The balls first: what the trees' roots would test.
        let balls = gap_down(
            (cb - ca).length() - ra - rb,
            ma.delta,
            mb.delta,
            ma.reach + mb.reach,
        );
        if balls > need {
            return Some(Verdict::Clear);
        }
        let (ha, hb) = hulls()?;
        let params = GjkParams::default()
            .with_rel_tol(T::ONE / T::from_u32(8))
            .with_max_iterations(24);
        // Started along the centre line: near the answer (any start is sound).
        let r = gjk_distance_from(&ha, &hb, &params, cb - ca);
        r.direction?;
        // The hulls placed exactly by the computed poses are within each
        // side's `delta` of the exact hulls (Lemma 13.7; an obstacle's pose
        // is exact, its `delta` subtracted all the same: Lemma 13.8).
        let gap = gap_down(r.lower_bound, ma.delta, mb.delta, ma.reach + mb.reach);
        if gap > need {
            Some(Verdict::Clear)
        } else if gap > self.padding {
            Some(Verdict::Keep)
        } else {
            None
        }
    }

    /// Two nodes of placed hierarchies, each sweeping `s` over the
    /// interval: clear when the balls' certified gap exceeds both sweeps;
    /// at two leaves, the triangles' exact distance.
    #[allow(clippy::type_complexity)]
    fn node_pair(
        &self,
        stats: &mut EdgeStats,
        (ta, ia, ma, sa): (&Hierarchy<T>, u32, &LinkMotion<T>, T),
        (tb, ib, mb, sb): (&Hierarchy<T>, u32, &LinkMotion<T>, T),
        (ca, ra): (Vec3<T>, T),
    ) -> Verdict {
        let na = &ta.nodes[ia as usize];
        let nb = &tb.nodes[ib as usize];
        let cb = mb.pose.transform_point(*nb.ball.centre());
        let rb = nb.ball.radius();
        let gap = gap_down(
            (cb - ca).length() - ra - rb,
            ma.delta,
            mb.delta,
            ma.reach + mb.reach,
        );
        let sweep = add_up(sa, sb);
        let need = add_up(sweep, self.padding);
        if gap > need {
            return Verdict::Clear;
        }
        let gap = box_gap((na, ma, ca, ra), (nb, mb, cb, rb), gap, need);
        if gap > need {
            return Verdict::Clear;
        }
        let lopsided = rb > ra * T::from_u32(4) || ra > rb * T::from_u32(4);
        match (na.leaf(), nb.leaf()) {
            (Some(la), Some(lb)) => {
                stats.leaf_tests += 1;
                let pa = placed_corners(ta, la, ma);
                let pb = placed_corners(tb, lb, mb);
                // First the cheap slab gaps: along the balls' centre line
                // (for a small triangle against a much larger one, a link's
                // against a pole's long side, first the direction from the
                // larger's point nearest the smaller's ball centre), then
                // along the pair's separating axes (near surfaces face each
                // other, or two large triangles lie side by side).
                let line = cb - ca;
                let first = lopsided.then(|| {
                    if rb > ra {
                        point_triangle_vec(ca, pb).on_b - ca
                    } else {
                        cb - point_triangle_vec(cb, pa).on_b
                    }
                });
                for d in first.into_iter().chain([line]) {
                    if slab_gap(&pa, &pb, d, ma, mb, T::ZERO) > need {
                        return Verdict::Clear;
                    }
                }
                if axes_gap(&pa, &pb, ma, mb, T::ZERO, need) > need {
                    return Verdict::Clear;
                }
                let cp = triangle_triangle_vec(&pa, &pb);
                let gap = slab_gap(&pa, &pb, cp.on_b - cp.on_a, ma, mb, T::ZERO);
                self.leaf_verdict(gap, cp.distance, need)
            }
            (a, b) => split(
                a.is_none(),
                ra,
                b.is_none(),
                rb,
                self.refine_below(gap, sweep),
            ),
        }
    }

    /// The ball size below which a node that is not clear is kept for the
    /// halves rather than refined: the sweep, except where the balls meet
    /// at the interval's middle (`gap` within the padding), where refining
    /// looks for a contact at that time (a colliding edge is then found at
    /// its first sample rather than after halving down to the ball's size).
    #[inline]
    fn refine_below(&self, gap: T, sweep: T) -> T {
        if gap > self.padding {
            sweep
        } else {
            T::ZERO
        }
    }

    /// At a leaf: touching when the computed distance is within the contact
    /// distance (and padding), clear when the certified gap exceeds what
    /// the sweeps need, else checked again on the halves.
    fn leaf_verdict(&self, gap: T, estimate: T, need: T) -> Verdict {
        if estimate <= self.touch || estimate.is_nan() {
            Verdict::Contact
        } else if gap > need {
            Verdict::Clear
        } else {
            Verdict::Keep
        }
    }
}

/// The two children ordered `(nearer, farther)` by `far` (the nearer is
/// pushed last, so taken first). Only the search's order depends on it.
#[inline]
fn nearer_last<T: Float>(a: u32, b: u32, far: impl Fn(u32) -> T) -> (u32, u32) {
    if far(a) <= far(b) {
        (a, b)
    } else {
        (b, a)
    }
}

/// Which side of a node pair that is not clear to refine: the larger ball
/// that is still larger than the sweep (refining it can clear the pair),
/// else none (the interval is halved instead).
fn split<T: Float>(inner_a: bool, ra: T, inner_b: bool, rb: T, sweep: T) -> Verdict {
    let a = inner_a && ra > sweep;
    let b = inner_b && rb > sweep;
    match (a, b) {
        (true, true) if ra >= rb => Verdict::SplitLink,
        (true, false) => Verdict::SplitLink,
        (_, true) => Verdict::SplitTarget,
        _ => Verdict::Keep,
    }
}

/// The two nodes' oriented boxes' slab gaps (Lemma 13.6, item 2), taken
/// until one exceeds `need`: along the centre line, the thinnest axis of
/// the larger box (a plate's normal) and the direction from the larger
/// box's point nearest the smaller ball's centre; the largest of them and
/// `gap` (a certified gap already known, the balls').
#[allow(clippy::type_complexity)]
fn box_gap<T: Float>(
    (na, ma, ca, ra): (&Node<T>, &LinkMotion<T>, Vec3<T>, T),
    (nb, mb, cb, rb): (&Node<T>, &LinkMotion<T>, Vec3<T>, T),
    gap: T,
    need: T,
) -> T {
    // The boxes' slab gaps: along the centre line, then along the
    // thinnest axis of the larger box (a plate's normal): much tighter
    // than the balls for flat or long nodes.
    let line = cb - ca;
    // The gap along `d` taken from `a` towards `b` (any computed
    // direction is sound: Lemma 13.6 certifies the supports along it).
    let along = |d: Vec3<T>| match d.try_normalize() {
        Some(n) => {
            let hi_a = box_support_up(&na.obb, ma, n);
            let lo_b = -box_support_up(&nb.obb, mb, -n);
            gap_down(lo_b - hi_a, ma.delta, mb.delta, ma.reach + mb.reach)
        }
        None => -T::INFINITY,
    };
    let box_gap = |d: Vec3<T>| along(if d.dot(line) < T::ZERO { -d } else { d });
    let (big, small_c, big_m, big_is_b) = if rb > ra {
        (&nb.obb, ca, mb, true)
    } else {
        (&na.obb, cb, ma, false)
    };
    // From the larger box's point nearest the smaller ball's centre to
    // that centre: the nearest face of a long or wide node (the side of
    // a pole one long triangle spans), where the centre line is tilted.
    let nearest = || {
        let d = from_box(big, big_m, small_c);
        along(if big_is_b { -d } else { d })
    };
    // The thinnest axis of the larger box (a plate's normal).
    let thin = || box_gap(big_m.pose.transform_vector(Vec3::from_array(big.axes[2])));
    // For nodes of like size the centre line first; for a much larger
    // one its nearest face first.
    let lopsided = rb > ra * T::from_u32(4) || ra > rb * T::from_u32(4);
    let mut gap = gap;
    if lopsided {
        gap = gap.max_nan(nearest());
        if gap > need {
            return gap;
        }
        gap = gap.max_nan(thin());
        if gap > need {
            return gap;
        }
    } else {
        gap = gap.max_nan(box_gap(line));
        if gap > need {
            return gap;
        }
        gap = gap.max_nan(thin());
        if gap > need {
            return gap;
        }
        gap = gap.max_nan(nearest());
        if gap > need {
            return gap;
        }
    }
    gap
}
