//! What a chain query answers: the pair touching, the first contact, a
//! segment's outcome, the work done, and the reports of a segment and of a
//! path.

use crate::Point3;

/// What a query reports touching: a link and an obstacle, or two links.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ChainPair {
    /// Link `link` and obstacle `obstacle` (indices).
    Obstacle {
        /// The link's index.
        link: usize,
        /// The obstacle's index.
        obstacle: usize,
    },
    /// Link `link` and shape obstacle `shape`
    /// ([`ChainScene::add_shape`](crate::chain::ChainScene::add_shape); indices).
    Shape {
        /// The link's index.
        link: usize,
        /// The shape obstacle's index.
        shape: usize,
    },
    /// Two links (`a < b`).
    SelfCollision {
        /// The first link's index.
        a: usize,
        /// The second link's index.
        b: usize,
    },
}

/// The first contact found on a segment.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct ChainContact<T> {
    /// The time in `[0, 1]` along the segment: never later than the first
    /// time the pair's surfaces touch.
    pub time: T,
    /// Which pair.
    pub pair: ChainPair,
    /// The computed distance between the closest triangles found (at most
    /// the contact distance).
    pub distance: T,
    /// The witness point on the link (or the first link), in the world.
    pub on_a: Point3<T>,
    /// The witness point on the obstacle (or the second link), in the world.
    pub on_b: Point3<T>,
}

/// What a segment query found.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum SegmentOutcome<T> {
    /// The first contact.
    Contact(ChainContact<T>),
    /// No pair touches over the whole segment (certified).
    Separated,
    /// A pair needed more than
    /// [`ChainParams::max_iterations`](crate::chain::ChainParams::max_iterations)
    /// steps: no contact before `time` is certified, nothing after it.
    IterationLimit {
        /// The time up to which the segment is certified free.
        time: T,
        /// The pair that ran out.
        pair: ChainPair,
    },
}

impl<T> SegmentOutcome<T> {
    /// The contact, if any.
    #[must_use]
    pub const fn contact(&self) -> Option<&ChainContact<T>> {
        match self {
            Self::Contact(c) => Some(c),
            _ => None,
        }
    }
}

/// The work a query did, summed over its pairs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct ChainStats {
    /// Pairs of (link, obstacle) and (link, link) with geometry.
    pub pairs: usize,
    /// Pairs never checked: adjacent links and allowed collisions.
    pub excluded: usize,
    /// Pairs the broad phase (swept balls per sub-interval) showed apart.
    pub culled: usize,
    /// Pairs advanced by conservative advancement.
    pub advanced: usize,
    /// Conservative-advancement iterations over all pairs.
    pub iterations: usize,
    /// Node pairs visited.
    pub node_pairs: usize,
    /// Triangle pairs measured.
    pub leaf_pairs: usize,
}

impl core::ops::AddAssign for ChainStats {
    fn add_assign(&mut self, o: Self) {
        self.pairs += o.pairs;
        self.excluded += o.excluded;
        self.culled += o.culled;
        self.advanced += o.advanced;
        self.iterations += o.iterations;
        self.node_pairs += o.node_pairs;
        self.leaf_pairs += o.leaf_pairs;
    }
}

/// A segment query's answer and work.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct SegmentReport<T> {
    /// What was found.
    pub outcome: SegmentOutcome<T>,
    /// The work done.
    pub stats: ChainStats,
}

/// A path query's answer: the first segment with a contact (or an
/// undecided one), and the work.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct PathReport<T> {
    /// The index of the segment the outcome is on (the last one when the
    /// whole path is separated).
    pub segment: usize,
    /// What was found on it.
    pub outcome: SegmentOutcome<T>,
    /// The work done over the segments checked.
    pub stats: ChainStats,
}
