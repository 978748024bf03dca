//! A point set reduced to a superset of its convex hull's vertices, with
//! exact orientation predicates (`proofs/13-chains.md`, Lemma 13.7, item 5).
//!
//! Extreme points along a fixed set of directions form a set `E` (kept);
//! every supporting plane through three points of `E` (all of `E` on one
//! side, exact [`orient3d`] signs) bounds a closed half-space containing
//! `E`, and the intersection of these half-spaces is the hull of `E` (every
//! facet of a full-dimensional 3-polytope spans three of its vertices). A
//! point on the inner side of, or on, every such plane is in the hull of `E`
//! and dropped; every other point is kept. The hull of what is kept is the
//! hull of the input, and no extreme point is ever dropped.

use super::predicates::{orient3d, points_in_exact_range};
use crate::{Float, Vec3};
use alloc::vec::Vec;

/// Directions sampled for the extreme points: a Fibonacci sphere.
const DIRECTIONS: usize = 128;

/// The indices of the points to keep, ascending: a subset of `0..points.len()`
/// holding every vertex of the points' convex hull, so that the kept points'
/// hull is the whole set's hull. Every index is kept when the set has fewer
/// than five points, is not full-dimensional, or has a coordinate outside
/// the exact predicates' range (non-finite included).
pub(crate) fn hull_vertex_indices<T: Float>(points: &[[T; 3]]) -> Vec<usize> {
    let all = || (0..points.len()).collect::<Vec<_>>();
    let v: Vec<Vec3<T>> = points.iter().map(|p| Vec3::new(p[0], p[1], p[2])).collect();
    if points.len() < 5 || !points_in_exact_range(&v) {
        return all();
    }
    // The extreme points along the directions (any choice is sound: `E` is
    // only ever kept).
    let mut in_e = alloc::vec![false; points.len()];
    let golden = core::f64::consts::PI * (3.0 - <f64 as Float>::sqrt(5.0));
    for k in 0..DIRECTIONS {
        let z = 1.0 - (2 * k + 1) as f64 / DIRECTIONS as f64;
        let r = <f64 as Float>::sqrt(1.0 - z * z);
        let phi = golden * k as f64;
        let d = [
            r * <f64 as Float>::cos(phi),
            r * <f64 as Float>::sin(phi),
            z,
        ];
        let mut best = (f64::NEG_INFINITY, 0);
        for (i, p) in points.iter().enumerate() {
            let s = d[0] * p[0].to_f64() + d[1] * p[1].to_f64() + d[2] * p[2].to_f64();
            if s > best.0 {
                best = (s, i);
            }
        }
        in_e[best.1] = true;
    }
    let e: Vec<usize> = (0..points.len()).filter(|&i| in_e[i]).collect();
    // The supporting planes through three points of `E`, each with the sign
    // of its inner side.
    let mut planes: Vec<(usize, usize, usize, i8)> = Vec::new();
    for (x, &a) in e.iter().enumerate() {
        for (y, &b) in e.iter().enumerate().skip(x + 1) {
            for &c in e.iter().skip(y + 1) {
                let (mut pos, mut neg) = (false, false);
                for &f in &e {
                    match orient3d(v[a], v[b], v[c], v[f]).sign {
                        1 => pos = true,
                        -1 => neg = true,
                        _ => {}
                    }
                    if pos && neg {
                        break;
                    }
                }
                if pos != neg {
                    planes.push((a, b, c, if pos { 1 } else { -1 }));
                }
            }
        }
    }
    if planes.is_empty() {
        // `E` is flat: no half-space bounds its hull in 3-D.
        return all();
    }
    (0..points.len())
        .filter(|&i| {
            in_e[i]
                || planes
                    .iter()
                    .any(|&(a, b, c, side)| orient3d(v[a], v[b], v[c], v[i]).sign == -side)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::hull_vertex_indices;
    use proptest::prelude::*;

    fn support(points: &[[f64; 3]], d: [f64; 3]) -> f64 {
        points
            .iter()
            .map(|p| p[0] * d[0] + p[1] * d[1] + p[2] * d[2])
            .fold(f64::NEG_INFINITY, f64::max)
    }

    /// Whether `p` is a vertex of the hull of `points`, by an independent test:
    /// `p` is extreme when some direction among many strictly prefers it
    /// by more than `margin` (the computed dot products' rounding).
    /// (Used one way only: a point found extreme must be kept.)
    fn strictly_extreme(points: &[[f64; 3]], i: usize, dirs: &[[f64; 3]], margin: f64) -> bool {
        dirs.iter().any(|&d| {
            let s = |p: &[f64; 3]| p[0] * d[0] + p[1] * d[1] + p[2] * d[2];
            let si = s(&points[i]);
            points
                .iter()
                .enumerate()
                .all(|(j, p)| j == i || s(p) < si - margin)
        })
    }

    fn check(points: &[[f64; 3]], dirs: &[[f64; 3]]) {
        let kept = hull_vertex_indices(points);
        assert!(
            kept.windows(2).all(|w| w[0] < w[1]) && kept.iter().all(|&i| i < points.len()),
            "the kept indices are a subset, ascending: {kept:?}"
        );
        let reduced: Vec<[f64; 3]> = kept.iter().map(|&i| points[i]).collect();
        let scale = points
            .iter()
            .map(|p| p[0].abs() + p[1].abs() + p[2].abs())
            .fold(0.0, f64::max);
        for &d in dirs {
            // The exact largest dot product over a set is at a hull vertex;
            // the computed ones differ from the exact by a few ulps of the
            // largest norm (a point on an edge may round above its ends).
            let (all, kept) = (support(points, d), support(&reduced, d));
            assert!(
                kept <= all && all <= kept + 1e-13 * scale,
                "support along {d:?}: {all} over every point, {kept} over the kept ones"
            );
        }
        for i in 0..points.len() {
            if strictly_extreme(points, i, dirs, 1e-13 * scale) {
                assert!(kept.contains(&i), "the extreme point {i} was dropped");
            }
        }
    }

    fn directions(seed: u64, n: usize) -> Vec<[f64; 3]> {
        let mut rng = crate::rng::SplitMix64::new(seed);
        (0..n)
            .map(|_| {
                let d = rng.vec3();
                let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt().max(1e-300);
                d.map(|x| x / l)
            })
            .collect()
    }

    /// The Panda's collision meshes: every distinct vertex's support is kept,
    /// and the sets shrink (the counts are printed for the journal).
    #[test]
    fn panda_link_hulls_keep_every_support() {
        let dir = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/data/arms/franka_panda/meshes/collision"
        );
        let Ok(entries) = std::fs::read_dir(dir) else {
            // The published crate leaves `data/` out.
            return;
        };
        let dirs = directions(7, 4000);
        for entry in entries {
            let path = entry.expect("a directory entry").path();
            let text = std::fs::read_to_string(&path).expect("a readable mesh");
            let mut points: Vec<[f64; 3]> = text
                .lines()
                .filter_map(|l| l.strip_prefix("v "))
                .map(|l| {
                    let c: Vec<f64> = l
                        .split_whitespace()
                        .map(|x| x.parse().expect("a coordinate"))
                        .collect();
                    [c[0], c[1], c[2]]
                })
                .collect();
            points.sort_by(|a, b| a.partial_cmp(b).expect("finite"));
            points.dedup();
            check(&points, &dirs);
            let kept = hull_vertex_indices(&points).len();
            std::println!("{}: {} -> {kept}", path.display(), points.len());
        }
    }

    /// Near-degenerate sets: lattice points (many coplanar and collinear,
    /// exact ties along the axes), points on a sphere, a flat set.
    #[test]
    fn lattices_and_flat_sets_keep_every_support() {
        let dirs = directions(11, 2000);
        let mut cube = Vec::new();
        for x in 0..5 {
            for y in 0..5 {
                for z in 0..5 {
                    cube.push([f64::from(x) * 0.1, f64::from(y) * 0.1, f64::from(z) * 0.1]);
                }
            }
        }
        check(&cube, &dirs);
        let kept = hull_vertex_indices(&cube);
        assert!(kept.len() < cube.len(), "the cube's interior is dropped");
        let flat: Vec<[f64; 3]> = cube.iter().map(|p| [p[0], p[1], 0.0]).collect();
        check(&flat, &dirs);
    }

    proptest! {
        #[test]
        fn random_sets_keep_every_support(
            pts in prop::collection::vec(
                prop_oneof![
                    // Spread points, and points a few ulps from a plane.
                    (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0).prop_map(|(x, y, z)| [x, y, z]),
                    (-1.0f64..1.0, -1.0f64..1.0, -4i32..4).prop_map(|(x, y, k)| [x, y, f64::from(k) * f64::EPSILON]),
                    (0.0f64..6.3, -1.0f64..1.0).prop_map(|(t, z)| [t.cos(), t.sin(), z.round()]),
                ],
                5..120,
            ),
            seed in any::<u64>(),
        ) {
            check(&pts, &directions(seed, 300));
        }
    }
}
