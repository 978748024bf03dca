//! One leaf per distinct triangle: a mesh's exact duplicates (the same
//! corners in any order, from the same or from doubled vertices) are one
//! set of points, so a hierarchy keeps the first of them and drops the
//! others (`proofs/09-ca-toi.md`, Lemma 9.2, "Duplicates").

use alloc::vec::Vec;
use core::cmp::Ordering;

use super::node::Leaf;
use crate::Float;

/// A triangle's corners as the set of points they are, in a canonical
/// order: sorted, `-0` read as `+0`, and a repeated corner counted once
/// (`[a, a, b]` and `[a, b, b]` are both the segment `ab`, kept as
/// `[a, b, b]`). Two triangles with the same key have the same distinct
/// corners, hence the same convex hull: the same points.
fn point_set<T: Float>(corners: &[[T; 3]; 3]) -> [[f64; 3]; 3] {
    // `x + 0` is `x` except that `-0 + 0 = +0`; `to_f64` is exact.
    let mut p = corners.map(|c| c.map(|x| x.to_f64() + 0.0));
    p.sort_unstable_by(point_order);
    if p[0] == p[1] {
        p[1] = p[2];
    }
    p
}

/// The lexicographic order of points (a total order: `total_cmp`).
fn point_order(a: &[f64; 3], b: &[f64; 3]) -> Ordering {
    a[0].total_cmp(&b[0])
        .then(a[1].total_cmp(&b[1]))
        .then(a[2].total_cmp(&b[2]))
}

/// The leaves whose triangles are distinct sets of points: of each group of
/// leaves with the same point set, the one of the least triangle index,
/// in the order of `leaves`. `O(N log N)`.
pub(super) fn distinct<T: Float>(leaves: Vec<Leaf<T>>) -> Vec<Leaf<T>> {
    let keys: Vec<[[f64; 3]; 3]> = leaves.iter().map(|l| point_set(&l.corners)).collect();
    let key_order = |a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]| {
        point_order(&a[0], &b[0])
            .then(point_order(&a[1], &b[1]))
            .then(point_order(&a[2], &b[2]))
    };
    let mut order: Vec<u32> = (0..leaves.len() as u32).collect();
    order.sort_unstable_by(|&i, &j| {
        key_order(&keys[i as usize], &keys[j as usize]).then(
            leaves[i as usize]
                .triangle
                .cmp(&leaves[j as usize].triangle),
        )
    });
    let mut keep = alloc::vec![false; leaves.len()];
    let mut last: Option<&[[f64; 3]; 3]> = None;
    for &i in &order {
        let key = &keys[i as usize];
        if last.is_none_or(|k| key_order(k, key) != Ordering::Equal) {
            keep[i as usize] = true;
        }
        last = Some(key);
    }
    leaves
        .into_iter()
        .zip(keep)
        .filter_map(|(leaf, kept)| kept.then_some(leaf))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::{distinct, point_set};
    use crate::bvh::Leaf;

    fn leaf(corners: [[f64; 3]; 3], triangle: u32) -> Leaf<f64> {
        Leaf {
            corners,
            r_hat: 0.0,
            inflate: 0.0,
            triangle,
        }
    }

    #[test]
    fn the_same_points_in_any_order_are_one_leaf() {
        let (a, b, c) = ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        let z = [-0.0, 0.0, -0.0];
        let leaves = alloc::vec![
            leaf([a, b, c], 0),
            leaf([c, a, b], 1),                  // the same triangle, turned
            leaf([b, a, c], 2),                  // the same, flipped
            leaf([a, b, [0.0, 1.0, 1e-300]], 3), // another triangle
            leaf([a, a, b], 4),                  // the segment ab
            leaf([b, b, a], 5),                  // the same segment
            leaf([z, a, b], 6),                  // -0 is 0: the segment ab again
            leaf([a, a, a], 7),                  // the point a
            leaf([a, z, a], 8),                  // the same point
        ];
        let kept: alloc::vec::Vec<u32> = distinct(leaves).iter().map(|l| l.triangle).collect();
        assert_eq!(kept, [0, 3, 4, 7], "the first of each set of points");
        assert_eq!(point_set(&[b, a, a]), [a, b, b], "a repeated corner once");
    }
}
