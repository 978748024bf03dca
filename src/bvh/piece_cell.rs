//! A ball tree's second hierarchy, of its long triangles cut into pieces:
//! how it is made (the piece length coarsened to fit a budget) and where it
//! is kept (built on first use with `std`, eagerly without).

use alloc::vec::Vec;

use super::hierarchy::Hierarchy;
use super::node::Leaf;
use super::pieces;
use crate::Float;

/// The hierarchy of pieces of `leaves` (the whole triangles, in the mesh's
/// order): the finest length from `length` up by factors `sqrt 2` whose
/// pieces fit in `budget`; every triangle longer than it cut, the others
/// whole. `None` if a piece's corners were out of range (never for a valid
/// mesh: they lie in its triangles' hulls); the whole triangles then serve.
fn build_pieces<T: Float>(
    leaves: &[Leaf<T>],
    (length, budget): (f64, usize),
) -> Option<Hierarchy<T>> {
    let edges: Vec<f64> = leaves
        .iter()
        .map(|l| pieces::longest_edge(&l.corners.map(|c| c.map(T::to_f64))).0)
        .collect();
    let longest = edges.iter().copied().fold(0.0f64, f64::max);
    let fits = |length: f64| {
        let mut left = budget;
        leaves.iter().zip(&edges).all(|(l, &e)| {
            e <= length || pieces::Cutter::new(l.corners, length).count_within(&mut left)
        })
    };
    let mut length = length;
    while length < longest && !fits(length) {
        length *= core::f64::consts::SQRT_2;
    }
    let mut cut = Vec::new();
    for (leaf, &e) in leaves.iter().zip(&edges) {
        if e > length {
            pieces::Cutter::new(leaf.corners, length)
                .push_pieces(&mut cut, leaf.triangle)
                .ok()?;
        } else {
            cut.push(*leaf);
        }
    }
    Hierarchy::try_new(cut, false).ok()
}

/// Where a tree keeps its hierarchy of pieces and how to make it (the
/// finest length and the budget; `None` when the mesh has no triangle long
/// enough): built on first use with `std` (a `OnceLock`, so that trees stay
/// `Sync` and a mesh never paired with a much finer one never pays for it),
/// eagerly without.
#[derive(Clone, Debug)]
pub(super) struct PieceCell<T> {
    pub(super) plan: Option<(f64, usize)>,
    #[cfg(feature = "std")]
    cell: std::sync::OnceLock<Option<Hierarchy<T>>>,
    #[cfg(not(feature = "std"))]
    built: Option<Hierarchy<T>>,
}

impl<T: Float> PieceCell<T> {
    #[cfg(feature = "std")]
    pub(super) fn new(_leaves: &[Leaf<T>], plan: Option<(f64, usize)>) -> Self {
        Self {
            plan,
            cell: std::sync::OnceLock::new(),
        }
    }

    #[cfg(not(feature = "std"))]
    pub(super) fn new(leaves: &[Leaf<T>], plan: Option<(f64, usize)>) -> Self {
        Self {
            plan,
            built: plan.and_then(|p| build_pieces(leaves, p)),
        }
    }

    /// The hierarchy of pieces of the whole triangles `leaves`, if planned.
    #[cfg(feature = "std")]
    pub(super) fn get(&self, leaves: &[Leaf<T>]) -> Option<&Hierarchy<T>> {
        let plan = self.plan?;
        self.cell
            .get_or_init(|| build_pieces(leaves, plan))
            .as_ref()
    }

    /// The hierarchy of pieces, if planned.
    #[cfg(not(feature = "std"))]
    pub(super) fn get(&self, _leaves: &[Leaf<T>]) -> Option<&Hierarchy<T>> {
        self.built.as_ref()
    }
}
