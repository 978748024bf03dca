//! Ground truth: an exact triangle-triangle intersection test.
//!
//! Every decision is the sign of an `orient2d` or `orient3d` determinant
//! from the [`robust`] crate (georust's transcription of Shewchuk's adaptive
//! predicates): a floating-point filter, then expansion arithmetic until the
//! sign is certain, so the sign is that of the exact determinant of the
//! given `f64` coordinates (barring overflow or underflow of intermediate
//! products: keep coordinates between about `1e-100` and `1e100` in
//! magnitude, or zero). The crate is small, dependency-free, widely used
//! (geo, spade) and maintained by the georust organisation; writing expansion
//! arithmetic here would only duplicate it. The no_std core uses the same
//! crate as the fallback of its filtered predicates (`predicates`), so the
//! two tests cross-check their case splits, not their signs; the signs are
//! checked against `i128` determinants (`predicates`' unit tests).
//!
//! The case split (written apart from the floating-point one, and for exact
//! signs only):
//! * a triangle with three equal vertices is a point; one with collinear
//!   vertices (all three coordinate-plane projections have zero area) is the
//!   segment between its lexicographically smallest and largest vertex (the
//!   two extremes along the line);
//! * two proper triangles meet iff an edge of one meets the other: if they
//!   are not coplanar their intersection is a segment on the line common to
//!   both planes whose ends are ends of one triangle's chord, hence on its
//!   boundary; if coplanar and neither contains the other their boundaries
//!   cross, and if one contains the other its edges lie in the other;
//! * a segment meets a proper triangle iff (not coplanar) it reaches the
//!   plane and the line passes every edge on the same side (Pluecker signs),
//!   or an end on the plane lies in the triangle, or (coplanar) it meets it
//!   in a projection that is one-to-one on the plane;
//! * two segments meet iff coplanar and, in a one-to-one projection, the
//!   classic four-orientation test says so, or (collinear) their extents
//!   overlap.

use robust::{orient2d, orient3d, Coord, Coord3D};

type P = [f64; 3];

fn o3(a: P, b: P, c: P, d: P) -> f64 {
    let c3 = |p: P| Coord3D {
        x: p[0],
        y: p[1],
        z: p[2],
    };
    orient3d(c3(a), c3(b), c3(c), c3(d))
}

/// Projection dropping axis `k` (cyclic order, as a normal component).
fn proj(p: P, k: usize) -> Coord<f64> {
    let (i, j) = ((k + 1) % 3, (k + 2) % 3);
    Coord { x: p[i], y: p[j] }
}

fn o2(a: P, b: P, c: P, k: usize) -> f64 {
    orient2d(proj(a, k), proj(b, k), proj(c, k))
}

fn sign(x: f64) -> i8 {
    if x > 0.0 {
        1
    } else if x < 0.0 {
        -1
    } else {
        0
    }
}

/// The axis along which the projection of `a, b, c` has nonzero area.
fn proper_axis(a: P, b: P, c: P) -> Option<usize> {
    (0..3).find(|&k| o2(a, b, c, k) != 0.0)
}

enum Shape {
    Point(P),
    Segment(P, P),
    Triangle([P; 3], usize),
}

fn lex_less(a: &P, b: &P) -> bool {
    a.partial_cmp(b) == Some(core::cmp::Ordering::Less)
}

fn classify(t: &[P; 3]) -> Shape {
    if let Some(k) = proper_axis(t[0], t[1], t[2]) {
        return Shape::Triangle(*t, k);
    }
    if t[0] == t[1] && t[1] == t[2] {
        return Shape::Point(t[0]);
    }
    let mut lo = t[0];
    let mut hi = t[0];
    for p in &t[1..] {
        if lex_less(p, &lo) {
            lo = *p;
        }
        if lex_less(&hi, p) {
            hi = *p;
        }
    }
    Shape::Segment(lo, hi)
}

/// Whether two closed triangles (solid, possibly degenerate) share a point,
/// decided exactly.
///
/// ```
/// use motion_bound::testkit::triangles_intersect_exact;
/// let a = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
/// // Touching a at one vertex, from above.
/// let b = [[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [1.0, 1.0, 1.0]];
/// assert!(triangles_intersect_exact(&a, &b));
/// // A hair above: 0.1 + 0.2 is not 0.3 in binary, and the test knows it.
/// let c = [[0.1, 0.1, 0.3 - (0.1 + 0.2)], [5.0, 0.0, 1.0], [0.0, 5.0, 1.0]];
/// assert_eq!(triangles_intersect_exact(&a, &c), 0.3 - (0.1 + 0.2) <= 0.0);
/// ```
#[must_use]
pub fn triangles_intersect_exact(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]) -> bool {
    match (classify(a), classify(b)) {
        (Shape::Triangle(ta, ka), Shape::Triangle(tb, kb)) => {
            (0..3).any(|i| segment_triangle(ta[i], ta[(i + 1) % 3], &tb, kb))
                || (0..3).any(|i| segment_triangle(tb[i], tb[(i + 1) % 3], &ta, ka))
        }
        (Shape::Triangle(t, k), Shape::Segment(p, q))
        | (Shape::Segment(p, q), Shape::Triangle(t, k)) => segment_triangle(p, q, &t, k),
        (Shape::Triangle(t, k), Shape::Point(p)) | (Shape::Point(p), Shape::Triangle(t, k)) => {
            point_in_triangle(p, &t, k)
        }
        (Shape::Segment(p, q), Shape::Segment(r, s)) => segment_segment(p, q, r, s),
        (Shape::Segment(p, q), Shape::Point(x)) | (Shape::Point(x), Shape::Segment(p, q)) => {
            point_on_segment(x, p, q)
        }
        (Shape::Point(x), Shape::Point(y)) => x == y,
    }
}

fn collinear(a: P, b: P, c: P) -> bool {
    proper_axis(a, b, c).is_none()
}

fn within(x: f64, a: f64, b: f64) -> bool {
    (a <= x && x <= b) || (b <= x && x <= a)
}

/// `x` on segment `[p, q]` (any length).
fn point_on_segment(x: P, p: P, q: P) -> bool {
    collinear(p, q, x) && (0..3).all(|k| within(x[k], p[k], q[k]))
}

/// A point coplanar-tested and then located in the projection `k`.
fn point_in_triangle(x: P, t: &[P; 3], k: usize) -> bool {
    o3(t[0], t[1], t[2], x) == 0.0 && inside_2d(x, t, k)
}

fn inside_2d(x: P, t: &[P; 3], k: usize) -> bool {
    let s0 = sign(o2(t[0], t[1], t[2], k));
    (0..3).all(|i| sign(o2(t[i], t[(i + 1) % 3], x, k)) * s0 >= 0)
}

/// Segments `[p, q]`, `[r, s]` in the plane of projection `k`.
fn segments_2d(p: P, q: P, r: P, s: P, k: usize) -> bool {
    let d1 = sign(o2(p, q, r, k));
    let d2 = sign(o2(p, q, s, k));
    let d3 = sign(o2(r, s, p, k));
    let d4 = sign(o2(r, s, q, k));
    if d1 * d2 < 0 && d3 * d4 < 0 {
        return true;
    }
    let on = |x: P, a: P, b: P| (0..3).all(|c| within(x[c], a[c], b[c]));
    (d1 == 0 && on(r, p, q))
        || (d2 == 0 && on(s, p, q))
        || (d3 == 0 && on(p, r, s))
        || (d4 == 0 && on(q, r, s))
}

fn segment_triangle(p: P, q: P, t: &[P; 3], k: usize) -> bool {
    let sp = sign(o3(t[0], t[1], t[2], p));
    let sq = sign(o3(t[0], t[1], t[2], q));
    match (sp, sq) {
        (0, 0) => {
            inside_2d(p, t, k)
                || inside_2d(q, t, k)
                || (0..3).any(|i| segments_2d(p, q, t[i], t[(i + 1) % 3], k))
        }
        (0, _) => inside_2d(p, t, k),
        (_, 0) => inside_2d(q, t, k),
        _ if sp == sq => false,
        _ => {
            let s = [
                sign(o3(p, q, t[0], t[1])),
                sign(o3(p, q, t[1], t[2])),
                sign(o3(p, q, t[2], t[0])),
            ];
            s.iter().all(|&x| x >= 0) || s.iter().all(|&x| x <= 0)
        }
    }
}

/// Two proper segments (distinct ends) in space.
fn segment_segment(p: P, q: P, r: P, s: P) -> bool {
    if o3(p, q, r, s) != 0.0 {
        return false;
    }
    let axis = proper_axis(p, q, r).or_else(|| proper_axis(p, q, s));
    match axis {
        Some(k) => segments_2d(p, q, r, s, k),
        // All four on one line: extents overlap along every axis.
        None => (0..3).all(|c| {
            let (a0, a1) = (p[c].min(q[c]), p[c].max(q[c]));
            let (b0, b1) = (r[c].min(s[c]), r[c].max(s[c]));
            a0 <= b1 && b0 <= a1
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::triangles_intersect_exact as meet;

    #[test]
    fn hand_made_cases() {
        let base = crate::geometry::HAND_MADE_BASE;
        let cases = crate::geometry::HAND_MADE_CASES;
        for (name, b, expect) in cases {
            assert_eq!(meet(&base, &b), expect, "{name}");
            assert_eq!(meet(&b, &base), expect, "{name} (swapped)");
        }
    }

    #[test]
    fn segments_and_points() {
        let seg = |p: [f64; 3], q: [f64; 3]| [p, q, q];
        let cases = [
            (
                "crossing",
                seg([0.0, 0.0, 0.0], [2.0, 2.0, 0.0]),
                seg([0.0, 2.0, 0.0], [2.0, 0.0, 0.0]),
                true,
            ),
            (
                "skew",
                seg([0.0, 0.0, 0.0], [2.0, 2.0, 0.0]),
                seg([0.0, 2.0, 1.0], [2.0, 0.0, 1.0]),
                false,
            ),
            (
                "collinear overlap",
                seg([0.0; 3], [2.0; 3]),
                seg([1.0; 3], [3.0; 3]),
                true,
            ),
            (
                "collinear apart",
                seg([0.0; 3], [1.0; 3]),
                seg([2.0; 3], [3.0; 3]),
                false,
            ),
            (
                "collinear touching",
                seg([0.0; 3], [1.0; 3]),
                seg([1.0; 3], [3.0; 3]),
                true,
            ),
            (
                "point on segment",
                [[1.0; 3]; 3],
                seg([0.0; 3], [3.0; 3]),
                true,
            ),
            (
                "point off segment",
                [[1.0, 1.0, 1.5]; 3],
                seg([0.0; 3], [3.0; 3]),
                false,
            ),
            ("equal points", [[1.0; 3]; 3], [[1.0; 3]; 3], true),
            (
                "distinct points",
                [[1.0; 3]; 3],
                [[1.0, 1.0, 2.0]; 3],
                false,
            ),
        ];
        for (name, a, b, expect) in cases {
            assert_eq!(meet(&a, &b), expect, "{name}");
            assert_eq!(meet(&b, &a), expect, "{name} (swapped)");
        }
    }
}
