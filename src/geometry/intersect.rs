//! Does a pair of triangles share a point? Decided with exact signs.
//!
//! The decision follows the same case split as the exact test of the
//! testkit (`geometry::exact`), with signs from
//! [`predicates`](super::predicates): each triangle is classified as a proper
//! triangle, a segment or a point; two proper triangles meet exactly when an
//! edge of one meets the other (their intersection is a segment or polygon
//! whose ends lie on edges); segments and points reduce to segment-triangle
//! and segment-segment tests.
//!
//! The predicates filter in `T` and fall back to exact arithmetic for any
//! sign the filter cannot call, so for coordinates that are 0 or within
//! [`EXACT_RANGE`](super::predicates::EXACT_RANGE) (always so for `f32`;
//! `closest` rescales its points to a largest coordinate in `[1, 2)`, so for
//! `f64` every nonzero coordinate must be at least `2^-200` times the largest)
//! every sign is exact and the answer is exact: the test agrees with the
//! testkit's on the same inputs. Outside that range a sign may still be "too
//! close to call", read as zero, and the answer leans to "meet";
//! `closest` then accepts a "meeting" answer only if it also finds a pair of
//! points that close, and reports the distance of that pair otherwise.

use super::predicates::{coord, orient2d, orient3d, points_in_exact_range, project};
use crate::{Float, Vec3};

/// A triangle after classification.
#[derive(Clone, Copy, Debug)]
enum Shape<T> {
    /// Three equal vertices.
    Point(Vec3<T>),
    /// Collinear (within rounding) vertices: the longest edge.
    Segment(Vec3<T>, Vec3<T>),
    /// A proper triangle, with an axis along which its projection is
    /// certainly non-degenerate (so the projection is one-to-one on its plane).
    Triangle([Vec3<T>; 3], usize),
}

fn classify<T: Float>(t: &[Vec3<T>; 3]) -> Shape<T> {
    let mut best: Option<(usize, T)> = None;
    for k in 0..3 {
        let o = orient2d(project(t[0], k), project(t[1], k), project(t[2], k));
        if o.sign != 0 && best.is_none_or(|(_, v)| o.value.abs() > v) {
            best = Some((k, o.value.abs()));
        }
    }
    if let Some((k, _)) = best {
        return Shape::Triangle(*t, k);
    }
    if t[0] == t[1] && t[0] == t[2] {
        return Shape::Point(t[0]);
    }
    if points_in_exact_range(t) {
        // Exactly collinear (every sign above was exact): the extremes
        // along the line are the lexicographically least and greatest
        // vertex, compared exactly (as in the testkit's exact test).
        let lex_less = |p: &Vec3<T>, q: &Vec3<T>| {
            p.to_array().partial_cmp(&q.to_array()) == Some(core::cmp::Ordering::Less)
        };
        let (mut lo, mut hi) = (t[0], t[0]);
        for p in &t[1..] {
            if lex_less(p, &lo) {
                lo = *p;
            }
            if lex_less(&hi, p) {
                hi = *p;
            }
        }
        return Shape::Segment(lo, hi);
    }
    // Collinear within rounding only: the longest edge.
    let d01 = t[0].distance_squared(t[1]);
    let d02 = t[0].distance_squared(t[2]);
    let d12 = t[1].distance_squared(t[2]);
    if d01 >= d02 && d01 >= d12 {
        Shape::Segment(t[0], t[1])
    } else if d02 >= d12 {
        Shape::Segment(t[0], t[2])
    } else {
        Shape::Segment(t[1], t[2])
    }
}

/// Whether two triangles share a point (uncertain cases lean to `true`).
pub(crate) fn triangles_meet<T: Float>(a: &[Vec3<T>; 3], b: &[Vec3<T>; 3]) -> bool {
    match (classify(a), classify(b)) {
        (Shape::Triangle(ta, ka), Shape::Triangle(tb, kb)) => {
            (0..3).any(|i| segment_meets_triangle(ta[i], ta[(i + 1) % 3], &tb, kb))
                || (0..3).any(|i| segment_meets_triangle(tb[i], tb[(i + 1) % 3], &ta, ka))
        }
        (Shape::Triangle(t, k), Shape::Segment(p, q))
        | (Shape::Segment(p, q), Shape::Triangle(t, k)) => segment_meets_triangle(p, q, &t, k),
        (Shape::Triangle(t, k), Shape::Point(p)) | (Shape::Point(p), Shape::Triangle(t, k)) => {
            segment_meets_triangle(p, p, &t, k)
        }
        (Shape::Segment(p, q), Shape::Segment(r, s)) => segments_meet(p, q, r, s),
        (Shape::Segment(p, q), Shape::Point(x)) | (Shape::Point(x), Shape::Segment(p, q)) => {
            segments_meet(p, q, x, x)
        }
        (Shape::Point(x), Shape::Point(y)) => segments_meet(x, x, y, y),
    }
}

/// Segment `pq` against a proper triangle `t` whose projection along axis
/// `k` is non-degenerate.
fn segment_meets_triangle<T: Float>(p: Vec3<T>, q: Vec3<T>, t: &[Vec3<T>; 3], k: usize) -> bool {
    let sp = orient3d(t[0], t[1], t[2], p);
    let sq = orient3d(t[0], t[1], t[2], q);
    if sp.sign * sq.sign > 0 {
        return false;
    }
    if sp.sign == 0 || sq.sign == 0 {
        let tp = [project(t[0], k), project(t[1], k), project(t[2], k)];
        return match (sp.sign, sq.sign) {
            // In the plane: the projection along `k` is one-to-one there.
            (0, 0) => segment_meets_triangle_2d(project(p, k), project(q, k), &tp),
            // One end on the plane, the other off it: only that end can meet.
            (0, _) => segment_meets_triangle_2d(project(p, k), project(p, k), &tp),
            _ => segment_meets_triangle_2d(project(q, k), project(q, k), &tp),
        };
    }
    // A certain crossing of the plane: the line through p, q meets the
    // triangle iff it passes every edge on the same side (Pluecker signs).
    let s = [
        orient3d(p, q, t[0], t[1]).sign,
        orient3d(p, q, t[1], t[2]).sign,
        orient3d(p, q, t[2], t[0]).sign,
    ];
    s.iter().all(|&x| x >= 0) || s.iter().all(|&x| x <= 0)
}

/// Two segments (either may have zero length) in space.
fn segments_meet<T: Float>(p: Vec3<T>, q: Vec3<T>, r: Vec3<T>, s: Vec3<T>) -> bool {
    if orient3d(p, q, r, s).sign != 0 {
        return false; // certainly not coplanar
    }
    // Coplanar (or too close to call): find a projection in which some
    // triple is certainly not collinear; it is one-to-one on their plane.
    let mut best: Option<(usize, T)> = None;
    for k in 0..3 {
        let (pp, pq, pr, ps) = (project(p, k), project(q, k), project(r, k), project(s, k));
        for o in [
            orient2d(pp, pq, pr),
            orient2d(pp, pq, ps),
            orient2d(pr, ps, pp),
            orient2d(pr, ps, pq),
        ] {
            if o.sign != 0 && best.is_none_or(|(_, v)| o.value.abs() > v) {
                best = Some((k, o.value.abs()));
            }
        }
    }
    if let Some((k, _)) = best {
        return segments_meet_2d(project(p, k), project(q, k), project(r, k), project(s, k));
    }
    // Collinear (or too close to call): the segments meet iff their extents
    // overlap along every axis.
    (0..3).all(|k| {
        let (a0, a1) = min_max(coord(p, k), coord(q, k));
        let (b0, b1) = min_max(coord(r, k), coord(s, k));
        a0 <= b1 && b0 <= a1
    })
}

fn min_max<T: Float>(a: T, b: T) -> (T, T) {
    if a <= b {
        (a, b)
    } else {
        (b, a)
    }
}

/// Two closed segments in the plane (the classic four-orientation test).
fn segments_meet_2d<T: Float>(p: [T; 2], q: [T; 2], r: [T; 2], s: [T; 2]) -> bool {
    let o1 = orient2d(p, q, r).sign;
    let o2 = orient2d(p, q, s).sign;
    let o3 = orient2d(r, s, p).sign;
    let o4 = orient2d(r, s, q).sign;
    if o1 * o2 > 0 || o3 * o4 > 0 {
        return false;
    }
    if o1 == 0 && o2 == 0 && o3 == 0 && o4 == 0 {
        // Collinear: bounding boxes decide.
        return (0..2).all(|k| {
            let (a0, a1) = min_max(p[k], q[k]);
            let (b0, b1) = min_max(r[k], s[k]);
            a0 <= b1 && b0 <= a1
        });
    }
    true
}

/// A closed segment against a closed non-degenerate triangle in the plane.
fn segment_meets_triangle_2d<T: Float>(p: [T; 2], q: [T; 2], t: &[[T; 2]; 3]) -> bool {
    let s0 = orient2d(t[0], t[1], t[2]).sign;
    let inside = |x: [T; 2]| (0..3).all(|i| orient2d(t[i], t[(i + 1) % 3], x).sign * s0 >= 0);
    if s0 == 0 {
        // Not reached for a classified triangle; fall back to the edges.
        return (0..3).any(|i| segments_meet_2d(p, q, t[i], t[(i + 1) % 3]));
    }
    inside(p) || inside(q) || (0..3).any(|i| segments_meet_2d(p, q, t[i], t[(i + 1) % 3]))
}

#[cfg(test)]
mod tests {
    use super::triangles_meet;
    use crate::Vec3;

    fn tri(p: [[f64; 3]; 3]) -> [Vec3<f64>; 3] {
        p.map(Vec3::from_array)
    }

    #[test]
    fn hand_made_cases() {
        let base = tri(super::super::HAND_MADE_BASE);
        let cases = super::super::HAND_MADE_CASES;
        for (name, b, expect) in cases {
            assert_eq!(triangles_meet(&base, &tri(b)), expect, "{name}");
            assert_eq!(triangles_meet(&tri(b), &base), expect, "{name} (swapped)");
        }
    }

    #[test]
    fn chain_links_meet_although_no_vertex_or_edge_pair_does() {
        // Each triangle pierces the other's interior with one edge.
        let a = tri([[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [2.0, 4.0, 0.0]]);
        let b = tri([[2.0, 1.0, -2.0], [2.0, 1.0, 2.0], [2.0, -3.0, 0.0]]);
        assert!(triangles_meet(&a, &b), "linked");
    }

    #[test]
    fn degenerate_pairs() {
        let seg = |p: [f64; 3], q: [f64; 3]| tri([p, q, q]);
        assert!(
            triangles_meet(
                &seg([0.0, 0.0, 0.0], [2.0, 2.0, 0.0]),
                &seg([0.0, 2.0, 0.0], [2.0, 0.0, 0.0])
            ),
            "crossing segments"
        );
        assert!(
            !triangles_meet(
                &seg([0.0, 0.0, 0.0], [2.0, 2.0, 0.0]),
                &seg([0.0, 2.0, 1.0], [2.0, 0.0, 1.0])
            ),
            "skew segments"
        );
        assert!(
            triangles_meet(
                &seg([0.0, 0.0, 0.0], [2.0, 2.0, 2.0]),
                &seg([1.0, 1.0, 1.0], [3.0, 3.0, 3.0])
            ),
            "overlapping collinear segments"
        );
        assert!(
            !triangles_meet(
                &seg([0.0, 0.0, 0.0], [1.0, 1.0, 1.0]),
                &seg([2.0, 2.0, 2.0], [3.0, 3.0, 3.0])
            ),
            "disjoint collinear segments"
        );
        assert!(
            triangles_meet(
                &tri([[1.0, 1.0, 1.0]; 3]),
                &seg([0.0, 0.0, 0.0], [3.0, 3.0, 3.0])
            ),
            "point on segment"
        );
        assert!(
            !triangles_meet(&tri([[1.0, 1.0, 1.0]; 3]), &tri([[1.0, 1.0, 2.0]; 3])),
            "distinct points"
        );
    }
}
