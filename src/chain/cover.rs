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

use alloc::collections::BinaryHeap;
use alloc::vec::Vec;
use core::cmp::Ordering;

use crate::Float;

/// The most pieces a triangle is cut into along an edge.
const MAX_SPLIT: usize = 48;

/// The most pieces a link is cut into (a coarser piece size above it).
const MAX_PIECES: usize = 60_000;

/// Balls in the link frame whose union holds every triangle of the link.
#[derive(Clone, Debug, Default)]
pub(crate) struct LinkCover {
    /// The balls' centres and radii, structure of arrays.
    pub(crate) cx: Vec<f32>,
    pub(crate) cy: Vec<f32>,
    pub(crate) cz: Vec<f32>,
    pub(crate) r: Vec<f32>,
    /// A ball holding every cover ball: its centre and radius.
    pub(crate) centre: [f32; 3],
    pub(crate) radius: f32,
    /// An upper bound of `|c| + r` over the balls (the cover's reach from
    /// the link frame's origin).
    pub(crate) reach: f64,
}

/// A node of the top-down split: a range of the piece order and its ball.
#[derive(Clone, Copy, Debug)]
struct Part {
    lo: usize,
    hi: usize,
    centre: [f64; 3],
    radius: f64,
}

impl PartialEq for Part {
    fn eq(&self, o: &Self) -> bool {
        self.radius.total_cmp(&o.radius) == Ordering::Equal
    }
}
impl Eq for Part {}
impl PartialOrd for Part {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}
impl Ord for Part {
    fn cmp(&self, o: &Self) -> Ordering {
        self.radius.total_cmp(&o.radius)
    }
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
                ((longest / size).ceil() as usize).min(MAX_SPLIT)
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
                        ((l / size).ceil() as usize).min(MAX_SPLIT)
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
        let mut order: Vec<u32> = (0..pieces.corners.len() as u32).collect();
        let root = part(&pieces, &order, 0, order.len());
        let mut heap = BinaryHeap::new();
        heap.push(root);
        let mut done: Vec<Part> = Vec::new();
        while let Some(p) = heap.pop() {
            if done.len() + heap.len() + 1 >= max_balls.max(1) || p.hi - p.lo < 2 {
                done.push(p);
                if done.len() + heap.len() >= max_balls.max(1) {
                    done.extend(heap.drain());
                    break;
                }
                continue;
            }
            let mid = split(&pieces, &mut order, p.lo, p.hi);
            heap.push(part(&pieces, &order, p.lo, mid));
            heap.push(part(&pieces, &order, mid, p.hi));
        }
        let mut cover = Self::default();
        let mut reach = 0.0f64;
        for p in &done {
            let centre = refine(&pieces, &order, p);
            let c32 = centre.map(|x| x as f32);
            let c64 = c32.map(f64::from);
            let mut r = 0.0f64;
            for &k in &order[p.lo..p.hi] {
                for &i in &pieces.corners[k as usize] {
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
        // The enclosing ball: the middle of the balls' boxes.
        let (mut blo, mut bhi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        for b in 0..cover.r.len() {
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
        for b in 0..cover.r.len() {
            big = big.max(norm(sub(cover.centre_f64(b), mid64)) + f64::from(cover.r[b]));
        }
        cover.centre = mid;
        cover.radius = up32(big * (1.0 + 8.0 * f64::EPSILON));
        cover.reach = reach * (1.0 + 4.0 * f64::EPSILON);
        Some(cover)
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

/// The least `f32` at least `x` (for finite non-negative `x`).
pub(crate) fn up32(x: f64) -> f32 {
    let y = x as f32;
    if f64::from(y) >= x {
        y
    } else {
        y.next_up()
    }
}

/// The ball of the pieces `order[lo..hi]`: the middle of their corners'
/// box, and the largest distance from it.
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
    let centre = [0, 1, 2].map(|d| (a[d] + b[d]) * 0.5);
    let mut radius = 0.0f64;
    for &k in &order[lo..hi] {
        for &i in &pieces.corners[k as usize] {
            radius = radius.max(norm(sub(pieces.points[i as usize], centre)));
        }
    }
    Part {
        lo,
        hi,
        centre,
        radius,
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

/// A smaller ball's centre for a part: Badoiu-Clarkson steps towards the
/// farthest corner, keeping the best centre seen (only a choice: the
/// radius is measured afterwards).
fn refine(pieces: &Pieces, order: &[u32], p: &Part) -> [f64; 3] {
    let far = |c: [f64; 3]| {
        let mut best = (0.0f64, c);
        for &k in &order[p.lo..p.hi] {
            for &i in &pieces.corners[k as usize] {
                let q = pieces.points[i as usize];
                let d = norm(sub(q, c));
                if d > best.0 {
                    best = (d, q);
                }
            }
        }
        best
    };
    let mut c = p.centre;
    let (mut best_r, mut best_c) = (p.radius, p.centre);
    for step in 0..24 {
        let (r, q) = far(c);
        if r < best_r {
            best_r = r;
            best_c = c;
        }
        let f = 1.0 / f64::from(step + 2);
        c = [0, 1, 2].map(|d| c[d] + (q[d] - c[d]) * f);
    }
    best_c
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
        let n = 40;
        for t in triangles {
            let [a, b, c] = t.map(|i| vertices[i as usize]);
            for i in 0..=n {
                for j in 0..=(n - i) {
                    let (s, u) = (f64::from(i) / f64::from(n), f64::from(j) / f64::from(n));
                    let p = [0, 1, 2].map(|k| a[k] + s * (b[k] - a[k]) + u * (c[k] - a[k]));
                    let inside = (0..cover.len()).any(|k| {
                        norm(sub(p, cover.centre_f64(k))) <= f64::from(cover.r[k])
                    });
                    assert!(inside, "point {p:?} of triangle {t:?} is in no ball");
                    let e = norm(sub(p, cover.centre.map(f64::from)));
                    assert!(e <= f64::from(cover.radius), "outside the enclosing ball");
                }
            }
        }
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
        let mut rng = crate::rng::Rng::new(7);
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
