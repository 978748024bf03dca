//! The best-first queue of node pairs, and the scratch space a query keeps
//! between steps ([`MeshWorkspace`]).

use alloc::collections::BinaryHeap;
use alloc::vec::Vec;

use super::found::NodeStep;
use super::front::FrontEntry;
use super::placed::PlacedNode;
use crate::Float;

/// The scratch space of a [`MeshPair`](super::MeshPair): its best-first
/// queue, the nodes it placed and the front one step hands to the next,
/// kept between steps and queries so that a query in a steady loop
/// allocates nothing.
///
/// A `MeshPair` made by [`MeshPair::new`](super::MeshPair::new) owns a fresh
/// workspace; an engine that runs many pairs per frame keeps one workspace
/// (per thread) and hands it from pair to pair with
/// [`MeshPair::with_workspace`](super::MeshPair::with_workspace) and
/// [`MeshPair::into_workspace`](super::MeshPair::into_workspace). Its
/// buffers grow to the largest query seen and are then reused. Only the
/// front carries over, from one step to the next of the same query of the
/// same pair (`proofs/09-ca-toi.md`, Lemma 9.9); a pair given a workspace
/// ignores the front in it, so any workspace is sound for any pair.
///
/// ```
/// // `bodies`: the built-in test bodies (feature `bodies`).
/// # #[cfg(feature = "bodies")] {
/// use motion_bound::ca::{time_of_impact, CaParams, MeshPair, MeshWorkspace};
/// use motion_bound::{bodies, BallTree, RigidMotion};
/// let ring = bodies::torus::<f64>(0.5, 0.1, 16, 8)?;
/// let tree = BallTree::try_from_mesh(&ring)?;
/// let mut workspace = MeshWorkspace::new();
/// for frame in 0..3 {
///     let a = RigidMotion::try_from_arrays([-2.0, 0.0, 0.0], [0.5 * (1.0 + frame as f64), 0.0, 0.0], [0.0, 0.0, 1.0])?;
///     let b = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0; 3])?;
///     let mut pair = MeshPair::with_workspace(&tree, &tree, workspace);
///     let report = time_of_impact(&mut pair, &a, &b, &CaParams::default())?;
///     workspace = pair.into_workspace();
///     assert_eq!(report.outcome.contact().is_some(), frame >= 1);
/// }
/// # }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct MeshWorkspace<T> {
    heap: BinaryHeap<Queued>,
    /// The best entry queued since the last pop, held out of the heap: a
    /// pair's better child is usually popped next, and holding it spares the
    /// heap a push and a pop (`pop` takes whichever of it and the heap's top
    /// comes first in the queue's order, so the order is the heap's own).
    held: Option<Queued>,
    /// The node pairs behind the queue's entries, indexed from [`Queued`].
    pub(super) pending: Vec<Pending>,
    /// The nodes placed at the current step, indexed from [`Pending`].
    pub(super) placed: Vec<PlacedNode<T>>,
    /// A direct-mapped cache per body (A, then B, `SEEN` entries each, by
    /// the node's index modulo `SEEN`): the stamp of the step that placed
    /// the node, the node, and where in `placed`, so that a node met in
    /// several pairs of a step is usually placed once.
    seen: Vec<(u32, u32, u32)>,
    /// The current step's stamp (never 0 once a step has begun).
    stamp: u32,
    /// The front the last step of the pair handed over, and the one this
    /// step is making (`front`): read only by the pair that made it, while
    /// its carry holds (a workspace handed to another pair carries none).
    pub(super) front: Vec<FrontEntry>,
    pub(super) next: Vec<FrontEntry>,
}

impl<T: Float> MeshWorkspace<T> {
    /// An empty workspace (no allocation until the first step).
    #[must_use]
    pub const fn new() -> Self {
        Self {
            heap: BinaryHeap::new(),
            held: None,
            pending: Vec::new(),
            placed: Vec::new(),
            seen: Vec::new(),
            stamp: 0,
            front: Vec::new(),
            next: Vec::new(),
        }
    }

    /// Clears the queue for a new step (keeping the buffers).
    pub(super) fn clear(&mut self) {
        self.heap.clear();
        self.held = None;
        self.pending.clear();
        self.placed.clear();
        self.stamp = self.stamp.wrapping_add(1);
        if self.stamp == 0 {
            // Every stamp used: forget them all.
            self.seen.clear();
            self.stamp = 1;
        }
    }

    /// Where node `node` of body `side` (0 for A, 1 for B) is placed at the
    /// current step, placing it by `place` if no pair of the step has.
    #[inline(always)]
    pub(super) fn placed_slot(
        &mut self,
        side: usize,
        node: u32,
        place: impl FnOnce() -> PlacedNode<T>,
    ) -> u32 {
        if self.seen.is_empty() {
            self.seen.resize(2 * SEEN, (0, 0, 0));
        }
        let k = side * SEEN + (node as usize) % SEEN;
        let (stamp, at, slot) = self.seen[k];
        if stamp == self.stamp && at == node {
            return slot;
        }
        let slot = self.placed.len() as u32;
        self.placed.push(place());
        self.seen[k] = (self.stamp, node, slot);
        slot
    }

    /// Puts a node pair in the best-first queue.
    #[inline]
    pub(super) fn enqueue(&mut self, pair: Pending) {
        let slot = self.pending.len() as u32;
        let entry = Queued::new(pair.near, pair.key.0, slot);
        self.pending.push(pair);
        match self.held {
            Some(held) if held > entry => self.heap.push(entry),
            Some(held) => {
                self.heap.push(held);
                self.held = Some(entry);
            }
            None => self.held = Some(entry),
        }
    }

    /// Takes the first entry in the queue's order (`Queued`'s `Ord`, a total
    /// order: the same entry a heap of every queued pair would pop).
    #[inline]
    pub(super) fn pop(&mut self) -> Option<Queued> {
        let Some(held) = self.held.take() else {
            return self.heap.pop();
        };
        match self.heap.peek_mut() {
            // The heap's top comes first: it leaves, the held entry takes its
            // place (one sift instead of a push and a pop).
            Some(mut top) if *top > held => Some(core::mem::replace(&mut *top, held)),
            _ => Some(held),
        }
    }

    /// How many entries are queued.
    #[inline]
    pub(super) fn len(&self) -> usize {
        self.heap.len() + usize::from(self.held.is_some())
    }

    /// Makes the front being built the front handed over, and empties the
    /// other for the next step. Both buffers keep the capacity of the
    /// larger: which one is which alternates from step to step (and from
    /// pair to pair of a workspace), and a steady loop allocates nothing.
    pub(super) fn swap_fronts(&mut self) {
        core::mem::swap(&mut self.front, &mut self.next);
        self.next.clear();
        let cap = self.front.capacity().max(self.next.capacity());
        // Exact: a doubling reserve would outgrow the other buffer at every
        // swap.
        self.next.reserve_exact(cap);
        self.front.reserve_exact(cap - self.front.len());
    }

    /// Queues every pair of the front the last step handed over, as carried
    /// to a step at `t` (`Pending::carried`); returns how many.
    pub(super) fn enqueue_front(&mut self, t: T) -> usize {
        let front = core::mem::take(&mut self.front);
        for &e in &front {
            self.enqueue(Pending::carried(e, t));
        }
        let n = front.len();
        self.front = front;
        n
    }

    /// Empties the queue into the front being built, `head` (the pair the
    /// descent stopped at) first: every pair left keeps its step. `t`,
    /// `horizon` and `cd` as in [`Pending::front_entry`].
    pub(super) fn queue_to_front(&mut self, head: &Pending, (t, horizon, cd): (T, T, T)) {
        self.next.push(head.front_entry(t, horizon, cd));
        for q in self.held.take().into_iter().chain(self.heap.drain()) {
            self.next
                .push(self.pending[q.slot() as usize].front_entry(t, horizon, cd));
        }
    }
}

impl<T: Float> Default for MeshWorkspace<T> {
    fn default() -> Self {
        Self::new()
    }
}

/// The entries per body of the placement cache.
const SEEN: usize = 512;

/// An entry of the best-first queue: a node pair's key and where the pair is
/// in the workspace's `pending` (kept small: the queue moves its entries). Pairs
/// near enough for contact come first, least gap first; then the others,
/// least step first; among equal keys the one queued last.
///
/// The three are packed into one integer whose order is the queue's
/// (`BinaryHeap` pops the greatest): bit 96 the nearness, bits 32 to 95
/// the key's total order (`f64::total_cmp`) reversed, bits 0 to 31 the
/// slot. A heap's comparison is then one integer comparison
/// (`tests::the_packed_order_is_the_queues_rule`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(super) struct Queued(u128);

impl Queued {
    /// The entry of a pair (`near`, `key`) at `slot` of `pending`.
    #[inline]
    pub(super) fn new(near: bool, key: f64, slot: u32) -> Self {
        // `f64::total_cmp`'s order as an unsigned integer's: a negative
        // float's bits reversed, a positive one's above every negative one.
        let bits = key.to_bits();
        let total = if bits >> 63 == 1 {
            !bits
        } else {
            bits | (1 << 63)
        };
        Self((u128::from(near) << 96) | (u128::from(!total) << 32) | u128::from(slot))
    }

    /// Where the pair is in `pending`.
    #[inline]
    pub(super) const fn slot(self) -> u32 {
        self.0 as u32
    }
}

/// A node pair waiting in the best-first queue.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Pending {
    /// Near enough for contact now ([`NodeStep::Near`]): `key` is its gap,
    /// and it is split whatever the best step.
    pub(super) near: bool,
    /// The pair's safe step (or, when `near`, its certified gap).
    pub(super) key: OrdF64,
    pub(super) i: u32,
    pub(super) j: u32,
    /// The pair is far apart for its size: its step is taken as it is.
    pub(super) far: bool,
    /// Where the two nodes' placements are in the workspace's `placed`
    /// (unused for a carried pair: not placed yet).
    pub(super) at: (u32, u32),
    /// Measured at this step, or carried from the last one.
    pub(super) origin: Origin,
}

/// Where a queued pair's key comes from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Origin {
    /// Measured at this step: the certified gap and closing rate its step
    /// was made from (`NodeStep::Apart`; zero and `+inf` for a near pair).
    Fresh { gap: f64, rate: f64 },
    /// Carried from the last step's front, not measured yet: its key is
    /// what is left of its certified step (or `-inf`, near, when it may be
    /// within the contact distance now), and it is measured when popped.
    Carried { deadline: f64, near_from: f64 },
}

impl Pending {
    pub(super) fn new<T: Float>(found: NodeStep<T>, (i, j): (u32, u32), at: (u32, u32)) -> Self {
        let (near, key, far, gap, rate) = match found {
            NodeStep::Apart {
                step,
                far,
                gap,
                rate,
            } => (false, step, far, gap, rate),
            NodeStep::Near(gap) => (true, gap, false, T::ZERO, T::INFINITY),
        };
        Self {
            near,
            key: OrdF64(key.to_f64()),
            i,
            j,
            far,
            at,
            origin: Origin::Fresh {
                gap: gap.to_f64(),
                rate: rate.to_f64(),
            },
        }
    }

    /// The front entry of this pair, left queued at the end of a step at
    /// `t` whose bounds hold until `horizon`, with the contact distance
    /// `cd`: a carried pair's own, or a measured pair's from its step, gap
    /// and rate (`FrontEntry::new`).
    #[inline]
    pub(super) fn front_entry<T: Float>(&self, t: T, horizon: T, cd: T) -> FrontEntry {
        match self.origin {
            Origin::Carried {
                deadline,
                near_from,
            } => FrontEntry {
                i: self.i,
                j: self.j,
                deadline,
                near_from,
            },
            Origin::Fresh { gap, rate } => FrontEntry::new(
                (self.i, self.j),
                t,
                horizon,
                (
                    T::from_f64(self.key.0),
                    T::from_f64(gap),
                    T::from_f64(rate),
                    cd,
                ),
            ),
        }
    }

    /// The front entry `e` carried to a step at `t`: near (first in the
    /// queue, key `-inf`) when it may be within the contact distance at `t`
    /// (`t >= near_from`, which is also the case past its deadline), else
    /// keyed by what is left of its certified step, `deadline - t` rounded
    /// down (Lemma 9.9).
    #[inline]
    pub(super) fn carried<T: Float>(e: FrontEntry, t: T) -> Self {
        // Near too when the time is NaN (never: the times are finite).
        let near = t.to_f64() >= e.near_from || e.near_from.is_nan();
        let key = if near {
            f64::NEG_INFINITY
        } else {
            crate::rounding::diff_down(T::from_f64(e.deadline), t).to_f64()
        };
        Self {
            near,
            key: OrdF64(key),
            i: e.i,
            j: e.j,
            far: false,
            at: (u32::MAX, u32::MAX),
            origin: Origin::Carried {
                deadline: e.deadline,
                near_from: e.near_from,
            },
        }
    }
}

/// An `f64` key (a step or gap converted exactly from `f32` or `f64`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct OrdF64(pub(super) f64);

#[cfg(test)]
mod tests {
    use super::super::placed::PlacedNode;
    use super::{MeshWorkspace, NodeStep, Pending, Queued};
    use crate::Vec3;
    use alloc::collections::BinaryHeap;
    use alloc::vec::Vec;

    proptest::proptest! {
        /// The workspace's queue (a held entry beside a heap) pops entries
        /// in the order a plain binary heap of the same entries pops them,
        /// whatever the interleaving of pushes and pops: the traversal's
        /// order, and so its outcomes, are the heap's.
        #[test]
        fn the_held_entry_keeps_the_heaps_order(
            ops in proptest::collection::vec((0u8..4, -3i8..4, proptest::bool::ANY), 1..200)
        ) {
            let mut ws = MeshWorkspace::<f64>::new();
            let mut plain = BinaryHeap::new();
            for (k, (op, key, near)) in ops.into_iter().enumerate() {
                if op == 0 {
                    proptest::prop_assert_eq!(ws.pop(), plain.pop());
                } else {
                    // Few distinct keys: ties are broken by the slot.
                    let step = if near {
                        NodeStep::Near(f64::from(key))
                    } else {
                        NodeStep::Apart { step: f64::from(key), far: false, gap: 1.0, rate: 1.0 }
                    };
                    let pair = Pending::new(step, (k as u32, 0), (0, 0));
                    plain.push(Queued::new(pair.near, pair.key.0, ws.pending.len() as u32));
                    ws.enqueue(pair);
                }
                proptest::prop_assert_eq!(ws.len(), plain.len());
            }
            let rest: Vec<_> = core::iter::from_fn(|| ws.pop()).collect();
            let plain_rest: Vec<_> = core::iter::from_fn(|| plain.pop()).collect();
            proptest::prop_assert_eq!(rest, plain_rest);
        }
    }

    /// The packed entries compare as the queue's rule says, computed here
    /// by hand: near before not near, then the least key by
    /// `f64::total_cmp` (signed zeros, infinities and NaNs included), then
    /// the greater slot (the pair queued last).
    #[test]
    fn the_packed_order_is_the_queues_rule() {
        let keys = [
            f64::NEG_INFINITY,
            -1e300,
            -1.0,
            -f64::MIN_POSITIVE,
            -5e-324,
            -0.0,
            0.0,
            5e-324,
            f64::MIN_POSITIVE,
            0.5,
            1.0,
            1.0 + f64::EPSILON,
            1e300,
            f64::INFINITY,
            f64::NAN,
            -f64::NAN,
        ];
        let slots = [0, 1, 7, u32::MAX - 1, u32::MAX];
        let mut entries = Vec::new();
        for near in [false, true] {
            for &key in &keys {
                for &slot in &slots {
                    entries.push((near, key, slot));
                }
            }
        }
        for &(na, ka, sa) in &entries {
            for &(nb, kb, sb) in &entries {
                let rule = na
                    .cmp(&nb)
                    .then_with(|| kb.total_cmp(&ka))
                    .then_with(|| sa.cmp(&sb));
                let packed = Queued::new(na, ka, sa).cmp(&Queued::new(nb, kb, sb));
                assert_eq!(
                    packed, rule,
                    "({na}, {ka}, {sa}) against ({nb}, {kb}, {sb})"
                );
            }
            assert_eq!(Queued::new(na, ka, sa).slot(), sa, "the slot back");
        }
    }

    /// A node is placed once per step (the cache returns its first slot),
    /// A's and B's nodes of the same index are told apart, two nodes sharing
    /// a cache entry each get their own placement, and a new step places
    /// again.
    #[test]
    fn a_node_is_placed_once_per_step() {
        let mut ws = MeshWorkspace::<f64>::new();
        let mut placements = 0;
        let mut place = |x: f64| {
            placements += 1;
            PlacedNode::at(Vec3::new(x, 0.0, 0.0))
        };
        ws.clear();
        let first = ws.placed_slot(0, 7, || place(1.0));
        assert_eq!(ws.placed_slot(0, 7, || place(9.0)), first);
        let b = ws.placed_slot(1, 7, || place(2.0));
        assert_ne!(b, first);
        let other = ws.placed_slot(0, 7 + super::SEEN as u32, || place(3.0));
        assert_ne!(other, first);
        let again = ws.placed_slot(0, 7, || place(4.0));
        assert_eq!(
            ws.placed[again as usize].centre.x, 4.0,
            "evicted, placed anew"
        );
        ws.clear();
        let next = ws.placed_slot(0, 7, || place(5.0));
        assert_eq!((next, ws.placed[next as usize].centre.x), (0, 5.0));
        assert_eq!(placements, 5);
    }
}
