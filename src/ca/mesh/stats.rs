//! The work counters of a mesh query.

use crate::ca::Work;

/// Work counters of a [`MeshPair`](super::MeshPair), summed over every step since the last
/// [`MeshPair::reset_stats`](super::MeshPair::reset_stats): what a profile of the query needs.
///
/// The budget counts `node_pairs` and `triangle_pairs` ([`Work`]), and every other unit of a
/// step's work is bounded by them: a node pair popped places at most two nodes (each once per
/// step) and evaluates and queues at most two child pairs, or measures at most one triangle
/// pair (a leaf pair); the seeds, at most four a step, are triangle pairs; and the rest of a
/// step (placing both bodies and both roots) is a constant, at most one a step. The trees are
/// built beforehand ([`BallTree`](crate::BallTree): duplicated triangles share one leaf, long
/// ones are cut with the tree), so making a pair does no work at all.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
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
    /// without splitting them ([`MeshParams::far_ratio`](crate::ca::MeshParams::far_ratio)).
    pub settled: u64,
    /// Child node pairs whose volumes no tested direction separates (a zero
    /// safe step): they can only be split.
    pub overlapping: u64,
    /// Node pairs steps took over from the last step's front
    /// ([`MeshParams::carry_front`](crate::ca::MeshParams::carry_front)),
    /// instead of descending from the roots.
    pub carried: u64,
    /// Carried node pairs measured anew (each also counted in
    /// `node_pairs`): the others kept the step the last step certified.
    pub refreshed: u64,
}

impl TraversalStats {
    /// Whether the work since the counters read `start` has used up either
    /// count of `budget`: checked before every node pair (which measures at
    /// most one triangle pair), so a step never does more than its budget.
    #[inline]
    pub(super) fn out_of_work(&self, start: &Self, budget: Work) -> bool {
        self.node_pairs - start.node_pairs >= budget.node_pairs
            || self.triangle_pairs - start.triangle_pairs >= budget.triangle_pairs
    }

    /// The node pairs and triangle pairs counted, as the driver counts work.
    #[inline]
    pub(super) const fn work(&self) -> Work {
        Work::new(self.node_pairs, self.triangle_pairs)
    }
}
