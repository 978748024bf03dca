//! The per-point scans of the EVQ case split over a body's points, in
//! rotation-plane coordinates: the absolute extremal (`proofs/04-evq-case-split.md`)
//! and the one-sided one (`proofs/10-one-sided.md`, Lemma 10.1).

use crate::{Float, Vec3};

/// Sweep of pi or more: `c(t)` meets the line through every `r_i^c`, so each
/// vertex contributes its squared distance from the axis, `|w^ x r_i|^2`.
#[inline]
pub(crate) fn full_turn_scan<T: Float>(
    vertices: &[[T; 3]],
    offset: Vec3<T>,
    axis: Vec3<T>,
    stop_sq: T,
) -> Option<T> {
    let mut best = T::ZERO;
    for r in vertices {
        let v2 = axis.cross(Vec3::from_array(*r) - offset).length_squared();
        if v2 > best {
            best = v2;
            if best >= stop_sq {
                return None;
            }
        }
    }
    Some(best)
}

/// The rotation-plane coordinates `q = (x, y) = (r' . e1, r' . e2)` of the
/// offset `r' = fl(r - offset)` from the rotation centre, and the sides
/// `g = u x q` of the arc's end directions `ua`, `ub`.
#[inline(always)]
fn plane_sides<T: Float>(
    r: &[T; 3],
    offset: Vec3<T>,
    (e1, e2): (Vec3<T>, Vec3<T>),
    (ua, ub): ((T, T), (T, T)),
) -> (T, T, T, T) {
    let r = Vec3::from_array(*r) - offset;
    let x = r.dot(e1);
    let y = r.dot(e2);
    (x, y, ua.0 * y - ua.1 * x, ub.0 * y - ub.1 * x)
}

/// The end values `f = u . q` of the arc for `q = (x, y)`.
#[inline(always)]
fn end_values<T: Float>(x: T, y: T, ua: (T, T), ub: (T, T)) -> (T, T) {
    (ua.0 * x + ua.1 * y, ub.0 * x + ub.1 * y)
}

/// Sweep below pi: the per-vertex case split in plane coordinates.
/// `u = (cos theta, -sin theta)` are the unit directions of `c(t_a)`, `c(t_b)`
/// in the basis `(e1, e2)`; `f = u . q` and `g = u x q` for `q = (x, y)`.
#[inline]
pub(crate) fn arc_scan<T: Float>(
    vertices: &[[T; 3]],
    offset: Vec3<T>,
    e1: Vec3<T>,
    e2: Vec3<T>,
    (ua, ub): ((T, T), (T, T)),
    stop_sq: T,
) -> Option<T> {
    let mut best = T::ZERO;
    for r in vertices {
        let (x, y, ga, gb) = plane_sides(r, offset, (e1, e2), (ua, ub));
        let v2 = if ga * gb <= T::ZERO {
            // c(t_a), c(t_b) on opposite sides of the line through q (or on it):
            // the arc meets +-q, where |c(t) . q| = |c| |q|.
            x * x + y * y
        } else {
            // Same side: |u . q| has no interior maximum on the arc.
            let (fa, fb) = end_values(x, y, ua, ub);
            (fa * fa).max_nan(fb * fb)
        };
        if v2 > best {
            best = v2;
            if best >= stop_sq {
                return None;
            }
        }
    }
    Some(best)
}

/// The one-sided EVQ scan: `S = max_i max_{arc} u(theta) . q_i` (signed; the
/// largest rotational speed along `+c`, divided by `|c|`), over the points'
/// rotation-plane coordinates `q_i = (r_i . e1, r_i . e2)`; `-inf` for no
/// point.
///
/// Per point (`proofs/10-one-sided.md`, Lemma 10.1): the arc (sweep below
/// pi) reaches `+q` exactly when its ends lie on opposite sides of the line
/// through `q` (`g_a g_b <= 0`) and `f_a + f_b >= 0`; then the value is `|q|`,
/// otherwise `max(f_a, f_b)`. The test `|c| (f_a + f_b) >= -slack`, with
/// `slack` twice the evaluation error of one `f` times `|c|` (an absolute
/// amount, `rounding::one_sided_decision_slack`), can only err towards `|q|`.
#[inline]
pub(crate) fn arc_signed_scan<T: Float>(
    vertices: &[[T; 3]],
    offset: Vec3<T>,
    e1: Vec3<T>,
    e2: Vec3<T>,
    (ua, ub): ((T, T), (T, T)),
    c_norm: T,
    slack: T,
) -> T {
    let mut reach_sq = -T::INFINITY;
    let mut best_f = -T::INFINITY;
    for r in vertices {
        let (x, y, ga, gb) = plane_sides(r, offset, (e1, e2), (ua, ub));
        let (fa, fb) = end_values(x, y, ua, ub);
        if ga * gb <= T::ZERO && c_norm * (fa + fb) >= -slack {
            reach_sq = reach_sq.max_nan(x * x + y * y);
        } else {
            best_f = best_f.max_nan(fa.max_nan(fb));
        }
    }
    if reach_sq >= T::ZERO {
        best_f.max_nan(reach_sq.sqrt())
    } else {
        best_f
    }
}
