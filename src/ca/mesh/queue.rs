//! The best-first queue of node pairs, and the scratch space a query keeps
//! between steps ([`MeshWorkspace`]).

use alloc::collections::BinaryHeap;
use alloc::vec::Vec;

use super::traversal::PlacedNode;
use crate::Float;

/// The scratch space of a [`MeshPair`](super::MeshPair): its best-first
/// queue and the nodes it placed, kept between steps and queries so that a
/// query in a steady loop allocates nothing.
///
/// A `MeshPair` made by [`MeshPair::new`](super::MeshPair::new) owns a fresh
/// workspace; an engine that runs many pairs per frame keeps one workspace
/// (per thread) and hands it from pair to pair with
/// [`MeshPair::with_workspace`](super::MeshPair::with_workspace) and
/// [`MeshPair::into_workspace`](super::MeshPair::into_workspace). Its
/// buffers grow to the largest query seen and are then reused; the contents
/// never carry over (each step clears them), so any workspace is sound for
/// any pair.
///
/// ```
/// use motion_bound::ca::{time_of_impact, CaParams, MeshPair, MeshWorkspace};
/// use motion_bound::{scenes, BallTree, RigidMotion};
/// let ring = scenes::torus::<f64>(0.5, 0.1, 16, 8)?;
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
        }
    }

    /// Clears the queue for a new step (keeping the buffers).
    pub(super) fn clear(&mut self) {
        self.heap.clear();
        self.held = None;
        self.pending.clear();
        self.placed.clear();
    }

    /// Puts a node pair in the best-first queue.
    #[inline]
    pub(super) fn enqueue(&mut self, pair: Pending) {
        let slot = self.pending.len() as u32;
        let entry = Queued {
            near: pair.near,
            key: pair.key,
            slot,
        };
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
}

impl<T: Float> Default for MeshWorkspace<T> {
    fn default() -> Self {
        Self::new()
    }
}

/// What `MeshPair::node_step` found for a node pair.
#[derive(Clone, Copy, Debug)]
pub(super) enum NodeStep<T> {
    /// Certified apart by more than the contact distance, with its safe step;
    /// `far`: far apart for its size (its step is taken as it is).
    Apart { step: T, far: bool },
    /// Its certified gap (`-inf` when no direction separates the volumes) is
    /// at most the contact distance: it must be split.
    Near(T),
}

/// An entry of the best-first queue: a node pair's key and where the pair is
/// in the workspace's `pending` (kept small: the queue moves its entries). Pairs
/// near enough for contact come first, least gap first; then the others,
/// least step first.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Queued {
    near: bool,
    key: OrdF64,
    pub(super) slot: u32,
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
    /// Where the two nodes' placements are in the workspace's `placed`.
    pub(super) at: (u32, u32),
}

impl Pending {
    pub(super) fn new<T: Float>(found: NodeStep<T>, (i, j): (u32, u32), at: (u32, u32)) -> Self {
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
    /// the least gap, else the pair with the least step; among equal keys the
    /// one queued last (depth first: below the resolution every pair within
    /// the clearance has the step zero, and a dive finds a zero-step leaf
    /// soonest).
    fn cmp(&self, other: &Self) -> core::cmp::Ordering {
        self.near
            .cmp(&other.near)
            .then_with(|| other.key.0.total_cmp(&self.key.0))
            .then_with(|| self.slot.cmp(&other.slot))
    }
}

/// An `f64` key (a step or gap converted exactly from `f32` or `f64`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct OrdF64(pub(super) f64);
