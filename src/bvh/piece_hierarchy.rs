//! A ball tree's second hierarchy, of its long triangles cut into pieces:
//! the piece length coarsened to fit a budget, then one hierarchy over the
//! pieces and the triangles short enough to stay whole. Built the first time
//! a pair of trees needs it (`BallTree`'s `LazyPieces`), so that a mesh met
//! only by convex shapes never pays for it.

use alloc::vec::Vec;

use super::hierarchy::{Hierarchy, Split};
use super::pieces::{self, Cutter};
use crate::Float;

/// The hierarchy of pieces of `whole`'s leaves (the distinct whole
/// triangles): the finest length from `length` up by factors `sqrt 2` whose
/// pieces fit in `budget`, every triangle longer than it cut, the others
/// whole. `None` when no triangle is longer than the length that fits (the
/// whole triangles then serve), or if a piece's corners were out of range
/// (never for a valid mesh: they lie in its triangles' hulls).
///
/// One hierarchy over every piece and short triangle, so that pieces of
/// different triangles near one another (the two faces of a thin board)
/// share nodes. Nodes of more than [`PIECE_TRIALS`] leaves are split at the
/// median of one key (centroids along the widest axis); smaller ones by the
/// best of three keys ([`Split::BestBelow`]), where a board's faces part:
/// `O(L log L)` for `L` leaves, the length's search `O(N)` per length tried
/// and `O(budget)` for the one that fits.
/// The largest node of pieces whose split tries the three keys. With 64, a
/// 12-triangle board's pieces against the bunny take 1,505 node pairs a
/// query (p99 4,527) against 1,702 (5,891) with one key and 1,437 (4,370)
/// with fitted trials everywhere, and the build costs 1.2 times one key's
/// where those trials cost 2.7 (`examples/coarse_fine.rs`;
/// `docs/performance.md`, 2026-12-04).
const PIECE_TRIALS: usize = 64;

pub(super) fn build_pieces<T: Float>(
    whole: &Hierarchy<T>,
    (length, budget): (f64, usize),
) -> Option<Hierarchy<T>> {
    let leaves = &whole.leaves;
    let edges: Vec<f64> = leaves
        .iter()
        .map(|l| pieces::longest_edge(&l.corners.map(|c| c.map(T::to_f64))).0)
        .collect();
    let longest = edges.iter().copied().fold(0.0f64, f64::max);
    let fits = |length: f64| {
        // Every triangle longer than the length is cut in two at least: a
        // length too fine for that is passed over without cutting.
        let long = edges.iter().filter(|&&e| e > length).count();
        let mut left = budget;
        long <= budget / 2
            && leaves.iter().zip(&edges).all(|(l, &e)| {
                e <= length || Cutter::new(l.corners, length).count_within(&mut left)
            })
    };
    let mut length = length;
    while length < longest && !fits(length) {
        length *= core::f64::consts::SQRT_2;
    }
    if length >= longest {
        return None;
    }
    let mut cut = Vec::new();
    for (leaf, &e) in leaves.iter().zip(&edges) {
        if e > length {
            Cutter::new(leaf.corners, length)
                .push_pieces(&mut cut, leaf.triangle)
                .ok()?;
        } else {
            cut.push(*leaf);
        }
    }
    Hierarchy::try_new(cut, Split::BestBelow(PIECE_TRIALS)).ok()
}
