//! A link's fixed cover: a few dozen balls in `f32` whose union holds every
//! triangle of the link's collision mesh, fitted once when the chain is
//! built (`proofs/13-chains.md`, Lemma 13.9). What the rake over time
//! (`rake.rs`) places in lanes and tests before anything finer.
//!
//! The fit: every triangle is cut into congruent pieces (a barycentric grid
//! of `n x n` small triangles, `n` from the triangle's longest edge), the
//! pieces are split top-down at the median of their centroids along the
//! widest axis, and the node of largest radius is split until the count is
//! reached; each ball of the cut is then centred by a few Badoiu-Clarkson
//! steps. Only containment is claimed: the centre is stored in `f32` first,
//! then the radius is the largest `f64` distance from it to the node's piece
//! corners, widened by the pieces' rounding and rounded up to `f32`. A ball
//! holds the convex hull of the corners it holds, so it holds the exact
//! pieces, and the exact pieces tile the triangles.

use alloc::vec::Vec;

use crate::Float;

/// The most pieces a triangle is cut into along an edge.
const MAX_SPLIT: usize = 48;

/// The most pieces a link is cut into (a coarser piece size above it).
const MAX_PIECES: usize = 4_000;

/// The most candidate centres a cover's fit weighs.
const MAX_CANDIDATES: usize = 320;

/// Balls in the link frame whose union holds every triangle of the link.
#[derive(Clone, Debug, Default)]
pub(crate) struct LinkCover {
    /// The balls' centres and radii, structure of arrays.
    pub(crate) cx: Vec<f32>,
    pub(crate) cy: Vec<f32>,
    pub(crate) cz: Vec<f32>,
    pub(crate) r: Vec<f32>,
    /// A ball holding every ball of the cover: its centre and radius.
    pub(crate) centre: [f32; 3],
    pub(crate) radius: f32,
    /// An upper bound of `|c| + r` over the balls (the cover's reach from
    /// the link frame's origin).
    pub(crate) reach: f64,
}

/// The middle of a set of pieces' corners' box.
#[derive(Clone, Copy, Debug)]
struct Part {
    centre: [f64; 3],
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn norm(a: [f64; 3]) -> f64 {
    (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
}

/// The pieces: corner points and, per piece, its three corner indices.
struct Pieces {
    points: Vec<[f64; 3]>,
    corners: Vec<[u32; 3]>,
    centroids: Vec<[f64; 3]>,
}

impl Pieces {
    fn cut(vertices: &[[f64; 3]], triangles: &[[u32; 3]], size: f64) -> Self {
        let mut out = Self {
            points: Vec::new(),
            corners: Vec::new(),
            centroids: Vec::new(),
        };
        let mut grid: Vec<u32> = Vec::new();
        for t in triangles {
            let [a, b, c] = t.map(|i| vertices[i as usize]);
            let longest = norm(sub(b, a)).max(norm(sub(c, b))).max(norm(sub(a, c)));
            // `n` pieces along each edge (at least one).
            let n = if longest > size {
                (ceil(longest / size) as usize).min(MAX_SPLIT)
            } else {
                1
            };
            let inv = 1.0 / n as f64;
            let (ab, ac) = (sub(b, a), sub(c, a));
            grid.clear();
            // Grid point (i, j), i + j <= n: a + (i/n) ab + (j/n) ac; the
            // corners themselves where they fall (exact).
            for i in 0..=n {
                for j in 0..=(n - i) {
                    let p = if i == 0 && j == 0 {
                        a
                    } else if i == n {
                        b
                    } else if j == n {
                        c
                    } else {
                        let (s, u) = (i as f64 * inv, j as f64 * inv);
                        [0, 1, 2].map(|k| a[k] + s * ab[k] + u * ac[k])
                    };
                    grid.push(out.points.len() as u32);
                    out.points.push(p);
                }
            }
            // Index of (i, j) in the grid: rows of decreasing length.
            // Row `i` starts after the rows `0..i`, of lengths `n + 1 - k`.
            let idx = |i: usize, j: usize| grid[i * (n + 1) - i * i.saturating_sub(1) / 2 + j];
            for i in 0..n {
                for j in 0..(n - i) {
                    out.push_piece([idx(i, j), idx(i + 1, j), idx(i, j + 1)]);
                    if i + j + 1 < n {
                        out.push_piece([idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)]);
                    }
                }
            }
        }
        out
    }

    fn push_piece(&mut self, c: [u32; 3]) {
        let p = c.map(|i| self.points[i as usize]);
        self.centroids
            .push([0, 1, 2].map(|k| (p[0][k] + p[1][k] + p[2][k]) / 3.0));
        self.corners.push(c);
    }
}

impl LinkCover {
    /// The cover of the mesh `(vertices, triangles)` by at most `max_balls`
    /// balls (fewer when the mesh has fewer pieces); `None` for an empty
    /// mesh or one that is not finite.
    pub(crate) fn fit<T: Float>(
        vertices: &[[T; 3]],
        triangles: &[[u32; 3]],
        max_balls: usize,
    ) -> Option<Self> {
        let v: Vec<[f64; 3]> = vertices.iter().map(|p| p.map(T::to_f64)).collect();
        if triangles.is_empty() || v.iter().flatten().any(|x| !x.is_finite()) {
            return None;
        }
        // The pieces' size: a fraction of the mesh's box diagonal, coarser
        // until the count is bounded.
        let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        for t in triangles {
            for &i in t {
                for k in 0..3 {
                    lo[k] = lo[k].min(v[i as usize][k]);
                    hi[k] = hi[k].max(v[i as usize][k]);
                }
            }
        }
        let diag = norm(sub(hi, lo)).max(f64::MIN_POSITIVE);
        let mut size = diag / 32.0;
        let count = |size: f64| -> usize {
            triangles
                .iter()
                .map(|t| {
                    let [a, b, c] = t.map(|i| v[i as usize]);
                    let l = norm(sub(b, a)).max(norm(sub(c, b))).max(norm(sub(a, c)));
                    let n = if l > size {
                        (ceil(l / size) as usize).min(MAX_SPLIT)
                    } else {
                        1
                    };
                    n * n
                })
                .sum()
        };
        while count(size) > MAX_PIECES {
            size *= 1.5;
        }
        let pieces = Pieces::cut(&v, triangles, size);
        // A bound of every computed grid point's distance from its exact
        // place: the grid points are `a + s ab + u ac` with `s`, `u` in
        // `[0, 1]`, six roundings of terms at most `3 |p|_max` each
        // (proofs/13-chains.md, Lemma 13.9).
        let biggest = v.iter().map(|p| norm(*p)).fold(0.0f64, f64::max);
        let piece_err = 16.0 * f64::EPSILON * 3.0 * biggest + 4.0 * f64::MIN_POSITIVE;
        // The balls first by deep centres (each ball a little more than
        // the largest ball about its centre inside the hull), then, for any
        // piece those leave, by the top-down split.
        let groups = deep_cover(&pieces, &v, triangles, diag, max_balls);
        let mut cover = Self::default();
        let mut reach = 0.0f64;
        for (centre, members) in &groups {
            let c32 = centre.map(|x| x as f32);
            let c64 = c32.map(f64::from);
            let mut r = 0.0f64;
            for &q in members {
                for &i in &pieces.corners[q as usize] {
                    r = r.max(norm(sub(pieces.points[i as usize], c64)));
                }
            }
            // The f64 distance errs by a few ulps; the pieces' corners by
            // `piece_err`; then up to the next f32.
            let r32 = up32(r * (1.0 + 8.0 * f64::EPSILON) + piece_err);
            reach = reach.max(norm(c64) * (1.0 + 4.0 * f64::EPSILON) + f64::from(r32));
            cover.cx.push(c32[0]);
            cover.cy.push(c32[1]);
            cover.cz.push(c32[2]);
            cover.r.push(r32);
        }
        cover.finish(reach);
        Some(cover)
    }

    /// The enclosing ball (the middle of the top balls' boxes) and the reach.
    fn finish(&mut self, reach: f64) {
        let cover = self;
        let (mut blo, mut bhi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        for b in 0..cover.len() {
            let c = cover.centre_f64(b);
            let r = f64::from(cover.r[b]);
            for k in 0..3 {
                blo[k] = blo[k].min(c[k] - r);
                bhi[k] = bhi[k].max(c[k] + r);
            }
        }
        let mid = [0, 1, 2].map(|k| ((blo[k] + bhi[k]) * 0.5) as f32);
        let mid64 = mid.map(f64::from);
        let mut big = 0.0f64;
        for b in 0..cover.len() {
            big = big.max(norm(sub(cover.centre_f64(b), mid64)) + f64::from(cover.r[b]));
        }
        cover.centre = mid;
        cover.radius = up32(big * (1.0 + 8.0 * f64::EPSILON));
        cover.reach = reach * (1.0 + 4.0 * f64::EPSILON);
    }

    /// Ball `b`'s centre, exactly.
    #[inline]
    pub(crate) fn centre_f64(&self, b: usize) -> [f64; 3] {
        [
            f64::from(self.cx[b]),
            f64::from(self.cy[b]),
            f64::from(self.cz[b]),
        ]
    }

    /// The number of balls.
    #[inline]
    pub(crate) fn len(&self) -> usize {
        self.r.len()
    }
}

/// Directions on the sphere (a Fibonacci lattice).
fn directions(n: usize) -> Vec<[f64; 3]> {
    let golden = core::f64::consts::PI * (3.0 - 5.0f64.sqrt());
    (0..n)
        .map(|i| {
            let z = 1.0 - 2.0 * (i as f64 + 0.5) / n as f64;
            let r = (1.0 - z * z).max(0.0).sqrt();
            let a = golden * i as f64;
            [r * a.cos(), r * a.sin(), z]
        })
        .collect()
}

/// A choice of balls, each with the pieces it is to hold (only a choice:
/// the radii are measured from the pieces afterwards). Candidate centres on
/// a grid inside the mesh's hull, each with `d`, its distance to the hull's
/// boundary (estimated along 128 directions); a candidate takes the pieces
/// within `d + eps` of it; greedy set cover, `eps` doubled from a
/// fiftieth of the mesh's size until at most `max_balls` balls do; pieces
/// no candidate takes (far from the hull's inside: a flat or thin mesh)
/// grouped by the top-down split.
fn deep_cover(
    pieces: &Pieces,
    v: &[[f64; 3]],
    triangles: &[[u32; 3]],
    diag: f64,
    max_balls: usize,
) -> Vec<([f64; 3], Vec<u32>)> {
    let max_balls = max_balls.max(1);
    let used: Vec<[f64; 3]> = {
        let mut seen = alloc::vec![false; v.len()];
        for t in triangles {
            for &i in t {
                seen[i as usize] = true;
            }
        }
        v.iter()
            .zip(seen)
            .filter(|(_, s)| *s)
            .map(|(p, _)| *p)
            .collect()
    };
    let dirs = directions(128);
    let support: Vec<f64> = dirs
        .iter()
        .map(|u| {
            used.iter()
                .map(|p| p[0] * u[0] + p[1] * u[1] + p[2] * u[2])
                .fold(f64::MIN, f64::max)
        })
        .collect();
    let depth = |c: [f64; 3]| {
        dirs.iter()
            .zip(&support)
            .map(|(u, h)| h - (c[0] * u[0] + c[1] * u[1] + c[2] * u[2]))
            .fold(f64::MAX, f64::min)
    };
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for p in &used {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let step = diag / 16.0;
    let mut cands: Vec<([f64; 3], f64)> = Vec::new();
    let counts = [0, 1, 2].map(|k| (ceil((hi[k] - lo[k]) / step) as usize).clamp(1, 24));
    for i in 0..counts[0] {
        for j in 0..counts[1] {
            for k in 0..counts[2] {
                let c = [
                    lo[0] + (i as f64 + 0.5) * (hi[0] - lo[0]) / counts[0] as f64,
                    lo[1] + (j as f64 + 0.5) * (hi[1] - lo[1]) / counts[1] as f64,
                    lo[2] + (k as f64 + 0.5) * (hi[2] - lo[2]) / counts[2] as f64,
                ];
                let d = depth(c);
                if d > 0.0 {
                    cands.push((c, d));
                }
            }
        }
    }
    // At most `MAX_CANDIDATES`, spread over the grid (the fit's cost).
    if cands.len() > MAX_CANDIDATES {
        let every = cands.len().div_ceil(MAX_CANDIDATES);
        cands = cands.into_iter().step_by(every).collect();
    }
    let n = pieces.corners.len();
    // Per candidate, the pieces by the `eps` it needs to take them (the
    // largest distance to a corner less the candidate's depth), kept up to
    // a quarter of the mesh's size.
    let cap = diag / 6.0;
    let lists: Vec<Vec<(f32, u32)>> = cands
        .iter()
        .map(|&(c, d)| {
            let mut l: Vec<(f32, u32)> = (0..n as u32)
                .filter_map(|q| {
                    let need = pieces.corners[q as usize]
                        .iter()
                        .map(|&i| norm(sub(pieces.points[i as usize], c)))
                        .fold(0.0, f64::max)
                        - d;
                    (need <= cap).then_some((need as f32, q))
                })
                .collect();
            l.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
            l
        })
        .collect();
    let mut eps = diag / 80.0;
    let mut best: Option<Vec<([f64; 3], Vec<u32>)>> = None;
    let mut covered = alloc::vec![false; n];
    for _ in 0..12 {
        // Lazy greedy set cover: a candidate's gain only falls as pieces
        // are covered, so the largest stale gain is re-counted first.
        covered.iter_mut().for_each(|c| *c = false);
        let takes: Vec<&[(f32, u32)]> = lists
            .iter()
            .map(|l| &l[..l.partition_point(|&(need, _)| f64::from(need) <= eps)])
            .collect();
        let mut heap: alloc::collections::BinaryHeap<(usize, usize)> = takes
            .iter()
            .enumerate()
            .map(|(k, t)| (t.len(), k))
            .collect();
        let mut left = n;
        let mut groups: Vec<([f64; 3], Vec<u32>)> = Vec::new();
        while left > 0 && groups.len() <= 4 * max_balls {
            let Some((stale, k)) = heap.pop() else { break };
            if stale == 0 {
                break;
            }
            let gain = takes[k]
                .iter()
                .filter(|&&(_, q)| !covered[q as usize])
                .count();
            if gain < stale {
                heap.push((gain, k));
                continue;
            }
            let mut members = Vec::with_capacity(gain);
            for &(_, q) in takes[k] {
                if !covered[q as usize] {
                    covered[q as usize] = true;
                    members.push(q);
                }
            }
            left -= members.len();
            groups.push((cands[k].0, members));
        }
        // What no candidate took: by the top-down split, a few balls.
        let rest: Vec<u32> = (0..n as u32).filter(|&q| !covered[q as usize]).collect();
        if !rest.is_empty() {
            let room = max_balls.saturating_sub(groups.len()).max(1);
            groups.extend(split_groups(pieces, rest, room));
        }
        let fits = groups.len() <= max_balls;
        if fits || best.as_ref().is_none_or(|b| groups.len() < b.len()) {
            best = Some(groups);
        }
        if fits {
            break;
        }
        eps *= 1.4;
    }
    match best {
        Some(b) if b.len() <= max_balls => b,
        // No `eps` fitted: the top-down split alone, which always does.
        _ => split_groups(pieces, (0..n as u32).collect(), max_balls),
    }
}

/// The pieces `rest` in at most `count` groups by the top-down split, each
/// with the middle of its corners' box as its centre.
fn split_groups(pieces: &Pieces, mut rest: Vec<u32>, count: usize) -> Vec<([f64; 3], Vec<u32>)> {
    let mut parts = alloc::vec![(0usize, rest.len())];
    while parts.len() < count {
        let Some(i) = (0..parts.len())
            .filter(|&i| parts[i].1 - parts[i].0 >= 2)
            .max_by_key(|&i| parts[i].1 - parts[i].0)
        else {
            break;
        };
        let (lo, hi) = parts[i];
        let mid = split(pieces, &mut rest, lo, hi);
        parts[i] = (lo, mid);
        parts.push((mid, hi));
    }
    parts
        .into_iter()
        .map(|(lo, hi)| (part(pieces, &rest, lo, hi).centre, rest[lo..hi].to_vec()))
        .collect()
}

/// The least `f32` at least `x` (for finite non-negative `x`).
pub(crate) fn up32(x: f64) -> f32 {
    let y = x as f32;
    if f64::from(y) >= x {
        y
    } else {
        y.next_up()
    }
}

/// The middle of the box of the corners of the pieces `order[lo..hi]`.
fn part(pieces: &Pieces, order: &[u32], lo: usize, hi: usize) -> Part {
    let (mut a, mut b) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for &k in &order[lo..hi] {
        for &i in &pieces.corners[k as usize] {
            let p = pieces.points[i as usize];
            for d in 0..3 {
                a[d] = a[d].min(p[d]);
                b[d] = b[d].max(p[d]);
            }
        }
    }
    Part {
        centre: [0, 1, 2].map(|d| (a[d] + b[d]) * 0.5),
    }
}

/// Splits `order[lo..hi]` at the median of the centroids along their widest
/// axis; the split point.
fn split(pieces: &Pieces, order: &mut [u32], lo: usize, hi: usize) -> usize {
    let (mut a, mut b) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for &k in &order[lo..hi] {
        let c = pieces.centroids[k as usize];
        for d in 0..3 {
            a[d] = a[d].min(c[d]);
            b[d] = b[d].max(c[d]);
        }
    }
    let axis = (0..3)
        .max_by(|&i, &j| (b[i] - a[i]).total_cmp(&(b[j] - a[j])))
        .unwrap_or(0);
    let mid = (hi - lo) / 2;
    order[lo..hi].select_nth_unstable_by(mid, |&x, &y| {
        pieces.centroids[x as usize][axis].total_cmp(&pieces.centroids[y as usize][axis])
    });
    lo + mid
}

/// `ceil` without `std` (`-floor(-x)`, exact).
fn ceil(x: f64) -> f64 {
    -<f64 as crate::Float>::floor(-x)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every point of every triangle, sampled densely (barycentric grid of
    /// 40 per edge, corners and edges included), lies in some cover ball by
    /// an f64 distance: an independent check of the cover's claim.
    fn check_cover(vertices: &[[f64; 3]], triangles: &[[u32; 3]], balls: usize) {
        let cover = LinkCover::fit(vertices, triangles, balls).expect("a cover");
        assert!(cover.len() <= balls.max(1), "{} balls", cover.len());
        assert!(
            held_all(vertices, triangles, &cover, 1.0),
            "a point in no ball"
        );
    }

    /// Whether every sampled point is in some ball with radii scaled by `scale`.
    fn held_all(
        vertices: &[[f64; 3]],
        triangles: &[[u32; 3]],
        cover: &LinkCover,
        scale: f64,
    ) -> bool {
        let mut all = true;
        let n = 40;
        for t in triangles {
            let [a, b, c] = t.map(|i| vertices[i as usize]);
            for i in 0..=n {
                for j in 0..=(n - i) {
                    let (s, u) = (f64::from(i) / f64::from(n), f64::from(j) / f64::from(n));
                    let p = [0, 1, 2].map(|k| a[k] + s * (b[k] - a[k]) + u * (c[k] - a[k]));
                    let held = |k: usize| {
                        norm(sub(p, cover.centre_f64(k))) <= f64::from(cover.r[k]) * scale
                    };
                    all &= (0..cover.len()).any(held);
                    let e = norm(sub(p, cover.centre.map(f64::from)));
                    all &= e <= f64::from(cover.radius) * scale;
                }
            }
        }
        all
    }

    #[test]
    fn covers_with_smaller_radii_leave_points_out() {
        // The containment checks have power: 2 % less radius leaves a
        // sampled point of some random mesh out.
        let mut rng = crate::rng::SplitMix64::new(7);
        let mut out = 0;
        for case in 0..30 {
            let v: Vec<[f64; 3]> = (0..12)
                .map(|_| [0; 3].map(|_| rng.range(-1.0, 1.0)))
                .collect();
            let t: Vec<[u32; 3]> = (0..10)
                .map(|_| [0; 3].map(|_| (rng.next_u64() % 12) as u32))
                .collect();
            let cover = LinkCover::fit(&v, &t, 1 + case % 20).expect("a cover");
            out += usize::from(!held_all(&v, &t, &cover, 0.98));
        }
        assert!(
            out > 10,
            "only {out} of 30 covers lose a point at 0.98 of their radii"
        );
    }

    #[test]
    fn covers_hold_long_slivers_and_small_triangles() {
        // A long sliver (1 m by 1 cm), a small triangle, and a box.
        let mut v = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.01, 0.0]];
        let mut t = vec![[0u32, 1, 2]];
        v.extend([[0.3, 0.3, 0.3], [0.301, 0.3, 0.3], [0.3, 0.301, 0.3]]);
        t.push([3, 4, 5]);
        check_cover(&v, &t, 16);
        check_cover(&v, &t, 1);
        check_cover(&v, &t, 3);
    }

    #[test]
    fn covers_hold_random_meshes() {
        let mut rng = crate::rng::SplitMix64::new(7);
        for case in 0..30 {
            let scale = [1e-3, 0.1, 1.0, 30.0][case % 4];
            let v: Vec<[f64; 3]> = (0..12)
                .map(|_| [0; 3].map(|_| rng.range(-scale, scale)))
                .collect();
            let t: Vec<[u32; 3]> = (0..10)
                .map(|_| [0; 3].map(|_| (rng.next_u64() % 12) as u32))
                .collect();
            check_cover(&v, &t, 1 + case % 20);
        }
    }
}
