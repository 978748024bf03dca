//! The first-contact queries' composition (`check_segment`, `check_path`):
//! each pair by its kinds' engine (`dispatch.rs`), conservative advancement
//! for meshes and links, the edge engine depth first in time for shapes,
//! narrowed to the first contact (Lemma 13.15).

use alloc::vec::Vec;

use super::{ChainScene, EdgeChecker};
use crate::chain::advance::{advance_pair, PairEnd};
use crate::chain::broad::broad_phase;
use crate::chain::dispatch::{first_contact_engine, first_link, shape_min_gap, FirstContact};
use crate::chain::edge::{Edge, EdgeOutcome, EdgeReport, Item, Target};
use crate::chain::report::{ChainContact, ChainPair, ChainStats, SegmentOutcome, SegmentReport};
use crate::chain::segment::Work;
use crate::rounding::gamma;
use crate::{Float, Point3, Vec3};

impl<T: Float> ChainScene<T> {
    /// An edge checker for the first-contact queries' shape pairs (`None`
    /// without shape obstacles).
    pub(super) fn shape_checker(&self) -> Option<EdgeChecker<'_, T>> {
        (!self.shapes.is_empty()).then(|| self.edge_checker())
    }

    /// The first contact on the segment: the pairs of meshes and links by
    /// conservative advancement, the shape pairs by `checker`'s edge engine
    /// (`dispatch.rs`; `checker` is `None` without shapes).
    pub(super) fn segment(
        &self,
        q0: &[T],
        q1: &[T],
        work: &mut Work<T>,
        checker: Option<&mut EdgeChecker<'_, T>>,
    ) -> SegmentReport<T> {
        let mut stats = ChainStats::default();
        let mut best: Option<ChainContact<T>> = None;
        let mut limit: Option<(T, ChainPair)> = None;
        let (advanced, edged): (Vec<_>, Vec<_>) = self
            .pairs()
            .into_iter()
            .partition(|&(p, _)| first_contact_engine(p) == FirstContact::Advance);
        if let (Some(checker), Some(&(first, _))) = (checker, edged.first()) {
            let r = checker.shape_first_contact(q0, q1);
            stats.pairs += edged.len();
            stats.node_pairs += r.stats.tests;
            stats.leaf_pairs += r.stats.leaf_tests;
            match r.outcome {
                EdgeOutcome::Free => {}
                EdgeOutcome::Contact {
                    free_until,
                    at,
                    pair,
                } => best = Some(self.shape_contact(q0, q1, free_until, at, pair, work)),
                EdgeOutcome::Undecided { free_until } => limit = Some((free_until, first)),
            }
        }
        work.errors.compute(&self.chain, q0, q1);
        work.rate.clear();
        work.rate.extend(
            q0.iter()
                .zip(q1)
                .map(|(a, b)| (*b - *a).abs() * (T::ONE + gamma::<T>(2))),
        );
        let segment = self.segment_view(q0, q1);
        let mut live = broad_phase(&segment, &advanced, work, &mut stats);
        // Pairs whose swept volumes meet earliest first: an early contact
        // found first ends every later pair's advance there.
        live.sort_by_key(|&(_, mask)| mask.trailing_zeros());
        for (pair, mask) in live {
            let until = best
                .map_or(T::ONE, |c| c.time)
                .min_nan(limit.map_or(T::ONE, |l| l.0));
            match advance_pair(&segment, pair, mask, until, work, &mut stats) {
                PairEnd::Contact(c) => best = Some(c),
                PairEnd::Undecided(t) => {
                    if limit.is_none_or(|(lt, _)| t < lt) {
                        limit = Some((t, pair));
                    }
                }
                PairEnd::Free => {}
            }
        }
        let outcome = match (best, limit) {
            (Some(c), Some((lt, p))) if lt < c.time => {
                SegmentOutcome::IterationLimit { time: lt, pair: p }
            }
            (Some(c), _) => SegmentOutcome::Contact(c),
            (None, Some((lt, p))) => SegmentOutcome::IterationLimit { time: lt, pair: p },
            (None, None) => SegmentOutcome::Separated,
        };
        SegmentReport { outcome, stats }
    }

    /// The contact the edge engine found for shape pair `pair` on the
    /// segment: certified free before `free_until` (its time), the pair's
    /// computed distance and witnesses measured at `at`, where the engine
    /// found it within the contact distance.
    pub(super) fn shape_contact(
        &self,
        q0: &[T],
        q1: &[T],
        free_until: T,
        at: T,
        pair: ChainPair,
        work: &mut Work<T>,
    ) -> ChainContact<T> {
        let segment = self.segment_view(q0, q1);
        work.errors.compute(&self.chain, q0, q1);
        work.rate.clear();
        work.rate.resize(self.chain.dofs, T::ZERO);
        segment.place(work, at);
        segment.fill_motions(work, pair, T::ZERO);
        let near = match (pair, &self.chain.links[first_link(pair)].tree, &work.a) {
            (ChainPair::Shape { shape, .. }, Some(tree), Some(a)) => {
                shape_min_gap(
                    &tree.whole,
                    a,
                    &self.shapes[shape],
                    T::INFINITY,
                    T::INFINITY,
                    &mut work.stack,
                    &mut ChainStats::default(),
                )
                .closest
            }
            _ => None,
        };
        let (distance, on_a, on_b) = near.unwrap_or((T::ZERO, Vec3::ZERO, Vec3::ZERO));
        ChainContact {
            time: free_until,
            pair,
            distance,
            on_a: Point3::from_vec3(on_a),
            on_b: Point3::from_vec3(on_b),
        }
    }
}

impl<T: Float> EdgeChecker<'_, T> {
    /// The first contact of the shape pairs alone, from their root items:
    /// the edge engine's part of [`ChainScene::check_segment`]
    /// (`dispatch.rs`), contact at the contact distance, no padding.
    pub(super) fn shape_first_contact(&mut self, q0: &[T], q1: &[T]) -> EdgeReport<T> {
        let scene = self.scene;
        let items: Vec<Item> = self
            .initial
            .iter()
            .copied()
            .filter(|it| matches!(it.target, Target::Shape(_) | Target::Cloud(..)))
            .collect();
        let edge = Edge {
            segment: scene.segment_view(q0, q1),
            shapes: &scene.shapes,
            hulls: &self.hulls,
            obstacle_hulls: &self.obstacle_hulls,
            touch: scene.params.contact_distance,
            padding: T::ZERO,
            budget: scene.params.edge_budget,
            first_contact: true,
        };
        let mut report = edge.run(&items, &self.slots, &mut self.work);
        // The engine declares a contact at an interval's middle `at`, free
        // only before the interval's start: narrow `[free_until, at]` (a
        // dyadic interval) by running it alone until it is free (the
        // contact is then at `at`) or no wider than rounding lets it split.
        let mut stats = report.stats;
        let floor =
            (T::UNIT_ROUNDOFF * T::from_u32(256)).max_nan(T::from_f64(1.0 / (1u64 << 30) as f64));
        let mut spans: Vec<(u32, u32, u32)> = Vec::new();
        while let EdgeOutcome::Contact {
            free_until: lo,
            at: hi,
            pair,
        } = report.outcome
        {
            let width = hi - lo;
            // (A NaN width stops too.)
            if width.partial_cmp(&floor) != Some(core::cmp::Ordering::Greater) {
                break;
            }
            let times = Float::floor((T::ONE / width).to_f64() + 0.5);
            let start = Float::floor(lo.to_f64() * times + 0.5);
            let (times, start) = (times as u32, start as u32);
            let scale = T::ONE / T::from_u32(times);
            if T::from_u32(start) * scale != lo || T::from_u32(start + 1) * scale != hi {
                break;
            }
            spans.clear();
            spans.extend((0..items.len() as u32).map(|i| (0, start, i)));
            let next = edge.run_spans(&items, &spans, (times, 0), &self.slots, &mut self.work);
            stats += next.stats;
            report = match next.outcome {
                EdgeOutcome::Free => EdgeReport {
                    outcome: EdgeOutcome::Contact {
                        free_until: hi,
                        at: hi,
                        pair,
                    },
                    stats,
                },
                _ => next,
            };
        }
        report.stats = stats;
        report
    }
}
