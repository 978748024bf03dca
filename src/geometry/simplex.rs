//! The point of a simplex (up to 4 points) nearest the origin, by signed
//! volumes.
//!
//! This is the distance sub-algorithm of GJK in the signed-volume form of
//! Montanari, Petrinic and Barbieri, "Improving the GJK algorithm for faster
//! and more reliable distance queries between convex objects", ACM TOG 36(3),
//! 2017, [doi:10.1145/3083724](https://doi.org/10.1145/3083724): barycentric
//! coordinates of the origin's projection are ratios of signed volumes
//! (areas in the projection where the triangle is largest, lengths along the
//! segment), and when the projection falls outside, only the faces (edges)
//! opposite a vertex whose coordinate has the wrong sign are searched. A
//! degenerate simplex has a zero total volume, for which no sign agrees, so
//! every face is searched: flat and repeated points need no special case.
//! Unlike Johnson's sub-algorithm it makes no assumption about which vertex
//! was added last.

use super::predicates::project;
use crate::{Float, Vec3};

/// The nearest point of a simplex to the origin.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Nearest<T> {
    /// The nearest point `v = sum lambda_i w_i`.
    pub(crate) v: Vec3<T>,
    /// Barycentric weights of the input points (zero outside `mask`).
    pub(crate) lambda: [T; 4],
    /// Bit `i` set when point `i` carries weight (the support set).
    pub(crate) mask: u8,
    /// The origin is inside the full-dimensional tetrahedron.
    pub(crate) contains_origin: bool,
}

fn same_sign<T: Float>(a: T, b: T) -> bool {
    (a > T::ZERO && b > T::ZERO) || (a < T::ZERO && b < T::ZERO)
}

fn vertex<T: Float>(w: &[Vec3<T>], i: usize) -> Nearest<T> {
    let mut lambda = [T::ZERO; 4];
    lambda[i] = T::ONE;
    Nearest {
        v: w[i],
        lambda,
        mask: 1 << i,
        contains_origin: false,
    }
}

/// Keeps the nearer of two candidates (a NaN candidate never wins).
fn nearer<T: Float>(best: Option<Nearest<T>>, c: Nearest<T>) -> Option<Nearest<T>> {
    match best {
        Some(b) if !(c.v.length_squared() < b.v.length_squared()) => Some(b),
        _ => Some(c),
    }
}

/// The nearest point of `w[..n]`, `1 <= n <= 4`.
pub(crate) fn nearest<T: Float>(w: &[Vec3<T>]) -> Nearest<T> {
    match w.len() {
        0 | 1 => vertex(w, 0),
        2 => s1d(w, 0, 1),
        3 => s2d(w, [0, 1, 2]),
        _ => s3d(w),
    }
}

fn s1d<T: Float>(w: &[Vec3<T>], i: usize, j: usize) -> Nearest<T> {
    let (s1, s2) = (w[i], w[j]);
    let t = s2 - s1;
    let tt = t.length_squared();
    if !(tt > T::ZERO) {
        return vertex(w, i);
    }
    let mu = -s1.dot(t) / tt;
    if !(mu > T::ZERO) {
        return vertex(w, i);
    }
    if mu >= T::ONE {
        return vertex(w, j);
    }
    let mut lambda = [T::ZERO; 4];
    lambda[i] = T::ONE - mu;
    lambda[j] = mu;
    Nearest {
        v: s1 + t * mu,
        lambda,
        mask: (1 << i) | (1 << j),
        contains_origin: false,
    }
}

/// Twice the signed area of `a, b, c` in a projection.
fn area2<T: Float>(a: [T; 2], b: [T; 2], c: [T; 2]) -> T {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

fn s2d<T: Float>(w: &[Vec3<T>], idx: [usize; 3]) -> Nearest<T> {
    let s = idx.map(|i| w[i]);
    let n = (s[1] - s[0]).cross(s[2] - s[0]);
    let nn = n.length_squared();
    let mut search = [true; 3];
    if nn > T::ZERO {
        let p0 = n * (s[0].dot(n) / nn);
        let k = if n.x.abs() >= n.y.abs() && n.x.abs() >= n.z.abs() {
            0
        } else if n.y.abs() >= n.z.abs() {
            1
        } else {
            2
        };
        let q = s.map(|p| project(p, k));
        let o = project(p0, k);
        let mu = area2(q[0], q[1], q[2]);
        let c = [
            area2(o, q[1], q[2]),
            area2(q[0], o, q[2]),
            area2(q[0], q[1], o),
        ];
        if c.iter().all(|&cj| same_sign(mu, cj)) {
            let mut lambda = [T::ZERO; 4];
            for j in 0..3 {
                lambda[idx[j]] = c[j] / mu;
            }
            return Nearest {
                v: p0,
                lambda,
                mask: idx.iter().fold(0, |m, &i| m | (1 << i)),
                contains_origin: false,
            };
        }
        search = c.map(|cj| !same_sign(mu, cj));
    }
    let mut best = None;
    for j in 0..3 {
        if search[j] {
            best = nearer(best, s1d(w, idx[(j + 1) % 3], idx[(j + 2) % 3]));
        }
    }
    best.unwrap_or_else(|| vertex(w, idx[0]))
}

/// The signed volume `(b - a) . ((c - a) x (d - a))`.
fn volume<T: Float>(a: Vec3<T>, b: Vec3<T>, c: Vec3<T>, d: Vec3<T>) -> T {
    (b - a).dot((c - a).cross(d - a))
}

fn s3d<T: Float>(w: &[Vec3<T>]) -> Nearest<T> {
    let o = Vec3::ZERO;
    let c = [
        volume(o, w[1], w[2], w[3]),
        volume(w[0], o, w[2], w[3]),
        volume(w[0], w[1], o, w[3]),
        volume(w[0], w[1], w[2], o),
    ];
    let det = c[0] + c[1] + c[2] + c[3];
    if c.iter().all(|&cj| same_sign(det, cj)) {
        return Nearest {
            v: Vec3::ZERO,
            lambda: c.map(|cj| cj / det),
            mask: 0b1111,
            contains_origin: true,
        };
    }
    let mut best = None;
    for (j, &cj) in c.iter().enumerate() {
        if !same_sign(det, cj) {
            // The face opposite vertex j, in cyclic order.
            let face = [(j + 1) % 4, (j + 2) % 4, (j + 3) % 4];
            best = nearer(best, s2d(w, face));
        }
    }
    best.unwrap_or_else(|| vertex(w, 0))
}

#[cfg(test)]
mod tests {
    use super::nearest;
    use crate::Vec3;

    fn v(x: f64, y: f64, z: f64) -> Vec3<f64> {
        Vec3::new(x, y, z)
    }

    #[test]
    fn each_dimension() {
        let r = nearest(&[v(1.0, -1.0, 2.0), v(1.0, 1.0, 2.0)]);
        assert_eq!((r.v, r.mask), (v(1.0, 0.0, 2.0), 0b11), "segment interior");
        let r = nearest(&[v(1.0, 1.0, 2.0), v(1.0, 3.0, 2.0)]);
        assert_eq!((r.v, r.mask), (v(1.0, 1.0, 2.0), 0b01), "segment end");
        let tri = [v(-1.0, -1.0, 1.0), v(2.0, -1.0, 1.0), v(-1.0, 2.0, 1.0)];
        let r = nearest(&tri);
        assert_eq!((r.v, r.mask), (v(0.0, 0.0, 1.0), 0b111), "triangle face");
        let tri = [v(1.0, 1.0, 1.0), v(2.0, 1.0, 1.0), v(1.0, 2.0, 1.0)];
        let r = nearest(&tri);
        assert_eq!((r.v, r.mask), (v(1.0, 1.0, 1.0), 0b001), "triangle vertex");
        let tet = [
            v(-1.0, -1.0, -1.0),
            v(3.0, -1.0, -1.0),
            v(-1.0, 3.0, -1.0),
            v(-1.0, -1.0, 3.0),
        ];
        let r = nearest(&tet);
        assert!(r.contains_origin, "tetrahedron around the origin");
        let sum: f64 = r.lambda.iter().sum();
        assert!((sum - 1.0).abs() < 1e-15, "weights sum to one");
        let tet = [
            v(1.0, -1.0, -1.0),
            v(1.0, 1.0, -1.0),
            v(1.0, 0.0, 1.0),
            v(3.0, 0.0, 0.0),
        ];
        let r = nearest(&tet);
        assert_eq!(
            (r.v, r.mask),
            (v(1.0, 0.0, 0.0), 0b0111),
            "tetrahedron face"
        );
    }

    #[test]
    fn degenerate_simplices_search_every_face() {
        // Flat tetrahedron (all in z = 1) and repeated points.
        let flat = [
            v(-1.0, -1.0, 1.0),
            v(2.0, -1.0, 1.0),
            v(-1.0, 2.0, 1.0),
            v(0.5, 0.5, 1.0),
        ];
        let r = nearest(&flat);
        assert!(!r.contains_origin, "a flat set cannot contain the origin");
        assert!((r.v - v(0.0, 0.0, 1.0)).length() < 1e-15, "flat: {:?}", r.v);
        let rep = [v(1.0, 2.0, 3.0); 4];
        assert_eq!(nearest(&rep).v, v(1.0, 2.0, 3.0), "one point four times");
        let line = [v(-1.0, 1.0, 0.0), v(1.0, 1.0, 0.0), v(3.0, 1.0, 0.0)];
        assert_eq!(nearest(&line).v, v(0.0, 1.0, 0.0), "collinear triangle");
        let nan = [v(f64::NAN, 0.0, 0.0), v(1.0, 1.0, 1.0)];
        let _ = nearest(&nan); // no panic
    }
}
