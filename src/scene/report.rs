//! A scene query's answer (each pair's report, each body's earliest
//! contact, the counters) and the workspace that keeps it across frames.

use alloc::vec::Vec;

use super::swept_box::SweptBox;
use crate::ca::{CaReport, MeshWorkspace};
use crate::Float;

/// The outcome of one pair that the broad phase kept.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct PairReport<T> {
    /// The first body (the lower number).
    pub a: usize,
    /// The second body.
    pub b: usize,
    /// The pair's conservative-advancement report: its first contact (time,
    /// witnesses, normal from `a` to `b`), or `Separated`.
    pub report: CaReport<T>,
    /// Node pairs visited (mesh pairs; 0 otherwise).
    pub node_pairs: u64,
}

/// What a scene query did, and what it skipped (each count for the last
/// query).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct SceneStats {
    /// Bodies in the scene.
    pub bodies: usize,
    /// Bodies that do not move (`v = 0`, `w = 0`): no rate at all.
    pub static_bodies: usize,
    /// Bodies that move without turning (`w = 0`): the translation-only path,
    /// exact velocities for their boxes, no arc.
    pub translating_bodies: usize,
    /// Bodies that turn: six one-sided ball rates for their boxes.
    pub turning_bodies: usize,
    /// Half-space bodies (tested by their plane, not in the sweep; counted
    /// among the static bodies when they do not move).
    pub half_spaces: usize,
    /// Axis rates evaluated for the swept boxes (six per turning body).
    pub box_rates: usize,
    /// Axis rates skipped (six per static or translating body).
    pub box_rates_skipped: usize,
    /// All pairs of bodies, `n (n - 1) / 2`.
    pub pairs_all: u64,
    /// Pairs of two static bodies: never a query.
    pub pairs_static: u64,
    /// Pairs of two half-spaces, not both static: never a query.
    pub pairs_of_half_spaces: u64,
    /// Pairs whose swept boxes are apart: provably no contact in the frame.
    pub pairs_culled: u64,
    /// Pairs the caller's filter or the bodies' groups excluded (counted
    /// among the pairs the broad phase kept).
    pub pairs_filtered: u64,
    /// Pairs sent to the narrow phase.
    pub pairs_tested: u64,
    /// Conservative-advancement iterations over the tested pairs.
    pub iterations: u64,
    /// Convex-pair steps where the automatic policy took NEVQ alone (NEVQ's
    /// step already ends the query, or neither body turns).
    pub evq_skipped: u64,
    /// Convex-pair steps where it evaluated EVQ as well.
    pub evq_evaluated: u64,
}

/// The answer to a scene query, kept in the [`SceneWorkspace`].
#[derive(Clone, Debug, Default)]
pub struct SceneReport<T> {
    pub(super) pairs: Vec<PairReport<T>>,
    pub(super) earliest: Vec<Option<(T, usize)>>,
    pub(super) stats: SceneStats,
}

impl<T: Float> SceneReport<T> {
    /// Every pair the broad phase kept and the filter passed, in increasing
    /// order of `(a, b)`, with its outcome. A pair not listed provably does
    /// not come within the contact distance during the frame (or was
    /// excluded by the filter, or is of two static bodies).
    #[must_use]
    pub fn pairs(&self) -> &[PairReport<T>] {
        &self.pairs
    }

    /// The pairs that report a contact (or could not rule one out: an
    /// iteration limit), in pair order.
    pub fn contacts(&self) -> impl Iterator<Item = &PairReport<T>> {
        self.pairs
            .iter()
            .filter(|p| p.report.outcome.earliest_possible_contact().is_some())
    }

    /// The earliest possible contact of `body` with any other body: the time
    /// and the other body (the first in pair order among equal times).
    #[must_use]
    pub fn earliest_for(&self, body: usize) -> Option<(T, usize)> {
        self.earliest.get(body).copied().flatten()
    }

    /// The pair with the earliest possible contact over the scene (the first
    /// in pair order among equal times).
    #[must_use]
    pub fn earliest(&self) -> Option<&PairReport<T>> {
        let mut best: Option<(T, &PairReport<T>)> = None;
        for p in &self.pairs {
            if let Some(t) = p.report.outcome.earliest_possible_contact() {
                if best.is_none_or(|(b, _)| t < b) {
                    best = Some((t, p));
                }
            }
        }
        best.map(|(_, p)| p)
    }

    /// What the query did and skipped.
    #[must_use]
    pub const fn stats(&self) -> SceneStats {
        self.stats
    }
}

/// The scratch space and the answer of scene queries: keep one across frames
/// and a query allocates nothing once the vectors have grown to the scene's
/// size (the serial query; the parallel one allocates per thread).
#[derive(Debug)]
pub struct SceneWorkspace<T> {
    pub(super) boxes: Vec<SweptBox<T>>,
    pub(super) skip: Vec<bool>,
    pub(super) order: Vec<(T, u32)>,
    pub(super) overlapping: Vec<(u32, u32)>,
    pub(super) candidates: Vec<(u32, u32)>,
    pub(super) mesh: MeshWorkspace<T>,
    pub(super) report: SceneReport<T>,
}

impl<T: Float> Default for SceneWorkspace<T> {
    fn default() -> Self {
        Self::new()
    }
}

impl<T: Float> SceneWorkspace<T> {
    /// An empty workspace.
    #[must_use]
    pub fn new() -> Self {
        Self {
            boxes: Vec::new(),
            skip: Vec::new(),
            order: Vec::new(),
            overlapping: Vec::new(),
            candidates: Vec::new(),
            mesh: MeshWorkspace::new(),
            report: SceneReport {
                pairs: Vec::new(),
                earliest: Vec::new(),
                stats: SceneStats::default(),
            },
        }
    }

    /// The last query's answer.
    #[must_use]
    pub const fn report(&self) -> &SceneReport<T> {
        &self.report
    }

    /// Each body's swept box, from the last broad phase.
    #[must_use]
    pub fn swept_boxes(&self) -> &[SweptBox<T>] {
        &self.boxes
    }

    /// The pairs the last broad phase kept for the narrow phase, in order.
    pub fn candidates(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        self.candidates
            .iter()
            .map(|&(a, b)| (a as usize, b as usize))
    }
}
