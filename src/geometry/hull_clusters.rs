//! A polytope's support by clusters of its vertices: each cluster's bound
//! of every computed dot product in it, so that a scan skips the clusters
//! that cannot beat the best vertex found (`proofs/floating-point.md`,
//! section "Clustered support").
//!
//! The support of [`ConvexPolytope`](crate::ConvexPolytope) must return a
//! vertex of the **largest computed** dot product `fl(d . v)` (its slack
//! bounds every vertex's rounding). A cluster `k` of vertices with centre
//! `c_k` and `e_k >= max |v - c_k|_inf` has, for every vertex `v` in it,
//!
//! ```text
//! fl(d . v) <= fl( fl(fl(d . c_k) + fl(|d|_1 E_k)) + h ),
//! E_k = up((e_k + gamma_16 M)(1 + gamma_8)),   h = 16 eta,
//! ```
//!
//! with `M >= max |v|_inf` over the polytope and `|d|_1` computed: Hölder
//! gives `d . v <= d . c_k + |d|_1 e_k`, and the roundings of the two dot
//! products, of `|d|_1`, of the product and of the two sums are covered by
//! `gamma_16 M`, `1 + gamma_8` and `h` (the section's derivation). A
//! cluster whose bound is at most the best computed dot product found so
//! far holds no vertex above it: skipping it returns a vertex of the
//! largest computed dot product still.

#[cfg(feature = "alloc")]
use crate::rounding::gamma;
use crate::{Float, Vec3};

/// A run of a polytope's vertices (`start..end` in its vertex array) with a
/// centre and the bound `reach` of [`the module`](self)'s `E_k`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct HullCluster<T> {
    pub(crate) start: u32,
    pub(crate) end: u32,
    pub(crate) centre: [T; 3],
    pub(crate) reach: T,
}

/// The most vertices a cluster holds for a polytope of `n`: about `sqrt n`,
/// at least 8 (a scan of a few clusters and a bound of each).
#[cfg(feature = "alloc")]
#[must_use]
pub(crate) fn leaf_size(n: usize) -> usize {
    let mut s = 1;
    while s * s < n {
        s += 1;
    }
    s.max(8).max(n.div_ceil(MAX_CLUSTERS / 2))
}

/// The most clusters whose bounds a support keeps (a polytope's clusters
/// are at most this many by [`leaf_size`]'s median split).
pub(crate) const MAX_CLUSTERS: usize = 64;

/// Reorders `vertices` into clusters of at most [`leaf_size`] (a median
/// split of the longest side of each run's box, recursively) and returns
/// the clusters, which cover `0..vertices.len()` in order. The vertices
/// must be finite (a [`ConvexPolytope`](crate::ConvexPolytope)'s are).
#[cfg(feature = "alloc")]
pub(crate) fn cluster_vertices<T: Float>(
    vertices: &mut [[T; 3]],
) -> alloc::vec::Vec<HullCluster<T>> {
    let leaf = leaf_size(vertices.len());
    let mut out = alloc::vec::Vec::new();
    if vertices.is_empty() || u32::try_from(vertices.len()).is_err() {
        return out;
    }
    let big = vertices
        .iter()
        .flat_map(|v| v.iter().map(|x| x.abs()))
        .fold(T::ZERO, T::max_nan);
    split(vertices, 0, leaf.max(1), big, &mut out);
    out
}

#[cfg(feature = "alloc")]
fn split<T: Float>(
    run: &mut [[T; 3]],
    start: usize,
    leaf: usize,
    big: T,
    out: &mut alloc::vec::Vec<HullCluster<T>>,
) {
    let (mut lo, mut hi) = ([T::INFINITY; 3], [-T::INFINITY; 3]);
    for v in run.iter() {
        for k in 0..3 {
            lo[k] = lo[k].min_nan(v[k]);
            hi[k] = hi[k].max_nan(v[k]);
        }
    }
    if run.len() <= leaf {
        let half = T::HALF;
        let centre = [0, 1, 2].map(|k| half * lo[k] + half * hi[k]);
        // `fl(|v - c|)` errs by at most `gamma_4` of itself: covered by
        // `1 + gamma_16`.
        let e = run
            .iter()
            .map(|v| {
                let x = [0, 1, 2].map(|k| v[k] - centre[k]);
                (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt()
            })
            .fold(T::ZERO, T::max_nan);
        let reach = cluster_reach(e, big);
        out.push(HullCluster {
            start: start as u32,
            end: (start + run.len()) as u32,
            centre,
            reach,
        });
        return;
    }
    let mid = median_split(run, lo, hi);
    let (left, right) = run.split_at_mut(mid);
    split(left, start, leaf, big, out);
    split(right, start + mid, leaf, big, out);
}

/// Puts the lower half of `run` (by the coordinate along the longest side
/// of its box `lo..hi`) before the upper half and returns where the upper
/// half starts (`run.len() / 2`): the split of the crate's vertex trees and
/// of these clusters.
#[cfg(feature = "alloc")]
pub(crate) fn median_split<T: Float>(run: &mut [[T; 3]], lo: [T; 3], hi: [T; 3]) -> usize {
    let axis = (0..3)
        .max_by(|&a, &b| {
            (hi[a] - lo[a])
                .partial_cmp(&(hi[b] - lo[b]))
                .unwrap_or(core::cmp::Ordering::Equal)
        })
        .unwrap_or(0);
    let mid = run.len() / 2;
    run.select_nth_unstable_by(mid, |a, b| {
        a[axis]
            .partial_cmp(&b[axis])
            .unwrap_or(core::cmp::Ordering::Equal)
    });
    mid
}

/// `E = up((e + 2 gamma_16 M)(1 + gamma_16))` for a cluster's computed
/// `e` and the polytope's `M >= max |v|_inf` (the module's bound).
#[cfg(feature = "alloc")]
#[must_use]
pub(crate) fn cluster_reach<T: Float>(e: T, big: T) -> T {
    let m = (gamma::<T>(16) * (big + big)).next_up();
    ((e + m).next_up() * (T::ONE + gamma::<T>(16))).next_up()
}

/// The index of a vertex of `vertices` (clustered as `clusters`) with the
/// largest computed `fl(d . v)`: the cluster of the largest bound scanned
/// first, then every cluster whose bound is not at most the best found
/// (a NaN bound is scanned).
#[inline]
#[must_use]
pub(crate) fn clustered_support<T: Float>(
    vertices: &[[T; 3]],
    clusters: &[HullCluster<T>],
    d: Vec3<T>,
) -> usize {
    let l2 = (d.x * d.x + d.y * d.y + d.z * d.z).sqrt();
    let h = T::from_u32(16) * T::ETA_NORMAL;
    let bound = |c: &HullCluster<T>| (Vec3::from_array(c.centre).dot(d) + l2 * c.reach) + h;
    let mut bounds = [T::ZERO; MAX_CLUSTERS];
    let mut first = 0;
    let mut top = -T::INFINITY;
    for (k, c) in clusters.iter().take(MAX_CLUSTERS).enumerate() {
        let b = bound(c);
        bounds[k] = b;
        if b > top {
            top = b;
            first = k;
        }
    }
    let dot = |r: &[T; 3]| Vec3::from_array(*r).dot(d);
    let c0 = &clusters[first];
    let mut bi = c0.start as usize;
    let mut best = dot(&vertices[bi]);
    let run = |c: &HullCluster<T>| {
        vertices[c.start as usize..c.end as usize]
            .iter()
            .zip(c.start as usize..)
    };
    for (v, i) in run(c0).skip(1) {
        let s = dot(v);
        if s > best {
            best = s;
            bi = i;
        }
    }
    for (k, c) in clusters.iter().enumerate() {
        // Past `MAX_CLUSTERS` (never, by `leaf_size`) every cluster is scanned.
        if k == first || bounds.get(k).is_some_and(|&b| b <= best) {
            continue;
        }
        for (v, i) in run(c) {
            let s = dot(v);
            if s > best {
                best = s;
                bi = i;
            }
        }
    }
    bi
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::SplitMix64;

    fn brute<T: Float>(v: &[[T; 3]], d: Vec3<T>) -> T {
        v.iter()
            .map(|r| Vec3::from_array(*r).dot(d))
            .fold(-T::INFINITY, T::max_nan)
    }

    fn check<T: Float>(reach_scale: T, seed: u64) -> usize {
        let mut rng = SplitMix64::new(seed);
        let mut misses = 0;
        for case in 0..300 {
            let n = 10 + (rng.next_u64() % 500) as usize;
            // Points on a sphere (every one extreme), some on a flat patch
            // (near ties), at scales from 1e-3 to 1e3, off the origin.
            let scale = T::from_f64(10f64.powi((case % 7) - 3));
            let off = [0, 1, 2].map(|_| T::from_f64(rng.unit() * 4.0 - 2.0) * scale);
            let mut v: alloc::vec::Vec<[T; 3]> = (0..n)
                .map(|i| {
                    let p = [0, 1, 2].map(|_| rng.unit() * 2.0 - 1.0);
                    let l = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt().max(1e-9);
                    let flat = i % 3 == 0;
                    [0, 1, 2].map(|k| {
                        let x = if flat && k == 2 { 1.0 } else { p[k] / l };
                        T::from_f64(x) * scale + off[k]
                    })
                })
                .collect();
            let mut clusters = cluster_vertices(&mut v);
            for c in &mut clusters {
                c.reach *= reach_scale;
            }
            for _ in 0..200 {
                let mut d = [0, 1, 2].map(|_| rng.unit() * 2.0 - 1.0);
                if rng.next_u64().is_multiple_of(4) {
                    d = [0.0, 0.0, 1.0 + rng.unit() * 1e-6];
                }
                let d = Vec3::new(T::from_f64(d[0]), T::from_f64(d[1]), T::from_f64(d[2]));
                let i = clustered_support(&v, &clusters, d);
                if Vec3::from_array(v[i]).dot(d) < brute(&v, d) {
                    misses += 1;
                }
            }
        }
        misses
    }

    /// The clustered scan returns a vertex of the largest computed dot
    /// product (the brute-force scan's value), f64 and f32, on spheres
    /// with flat patches at scales 1e-3 to 1e3; with the clusters' reach
    /// halved it does not (the bound is what makes skipping sound).
    #[test]
    fn clustered_support_attains_the_largest_computed_dot() {
        assert_eq!(check::<f64>(1.0, 7), 0);
        assert_eq!(check::<f32>(1.0, 8), 0);
        assert!(check::<f64>(0.5, 7) > 0);
        assert!(check::<f32>(0.5, 8) > 0);
    }

    /// Clouds of points a few ulps apart (every dot product a near tie):
    /// misses of the clustered scan, with the clusters' reach as computed
    /// (`margin`) or as the bare computed radius (no rounding margin).
    fn ulp_clouds<T: Float>(margin: bool, seed: u64) -> usize {
        let mut rng = SplitMix64::new(seed);
        let mut misses = 0;
        for _ in 0..400 {
            let base = [0, 1, 2].map(|_| T::from_f64(rng.range(0.5, 2.0)));
            let mut v: alloc::vec::Vec<[T; 3]> = (0..40)
                .map(|_| {
                    base.map(|x| {
                        let mut x = x;
                        for _ in 0..(rng.next_u64() % 4) {
                            x = x.next_up();
                        }
                        x
                    })
                })
                .collect();
            let mut clusters = cluster_vertices(&mut v);
            if !margin {
                for c in &mut clusters {
                    let e = v[c.start as usize..c.end as usize]
                        .iter()
                        .map(|p| {
                            let x = [0, 1, 2].map(|k| p[k] - c.centre[k]);
                            (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt()
                        })
                        .fold(T::ZERO, T::max_nan);
                    c.reach = e;
                }
            }
            for _ in 0..50 {
                let d = rng.direction();
                let d = Vec3::new(T::from_f64(d[0]), T::from_f64(d[1]), T::from_f64(d[2]));
                let i = clustered_support(&v, &clusters, d);
                if Vec3::from_array(v[i]).dot(d) < brute(&v, d) {
                    misses += 1;
                }
            }
        }
        misses
    }

    /// Near ties: with the rounding margin the scan never misses; with the
    /// bare radius it does (the margin is what makes the skip sound).
    #[test]
    fn clustered_support_needs_its_rounding_margin() {
        assert_eq!(ulp_clouds::<f64>(true, 11), 0);
        assert_eq!(ulp_clouds::<f32>(true, 12), 0);
        assert!(ulp_clouds::<f64>(false, 11) + ulp_clouds::<f32>(false, 12) > 0);
    }

    /// Every vertex lands in exactly one cluster, each at most the leaf.
    #[test]
    fn clusters_partition_the_vertices() {
        let mut rng = SplitMix64::new(3);
        for n in [1usize, 2, 7, 8, 9, 64, 65, 481] {
            let mut v: alloc::vec::Vec<[f64; 3]> =
                (0..n).map(|_| [0, 1, 2].map(|_| rng.unit())).collect();
            let mut before = v.clone();
            let leaf = leaf_size(n);
            let c = cluster_vertices(&mut v);
            assert_eq!(c[0].start, 0);
            assert_eq!(c.last().map(|c| c.end), Some(n as u32));
            for w in c.windows(2) {
                assert_eq!(w[0].end, w[1].start);
            }
            assert!(c
                .iter()
                .all(|c| c.end > c.start && (c.end - c.start) as usize <= leaf));
            let key = |p: &[f64; 3]| p.map(f64::to_bits);
            before.sort_by_key(key);
            v.sort_by_key(key);
            assert_eq!(before, v);
        }
    }
}
