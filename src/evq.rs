//! The EVQ bound: the seed's Eq. 1 by the corrected case split of Eq. 2.
//!
//! With `c = n x w`, the rotating direction `c(t) = R(t)^T c` lies in the
//! rotation plane and turns by `-|w| t`. In the in-plane basis
//! `e1 = c/|c|`, `e2 = w^ x e1`,
//!
//! ```text
//! c(t) / |c| = cos(theta) e1 - sin(theta) e2,     theta = |w| t,
//! ```
//!
//! and a body point contributes `c(t) . r_i = |c| (cos(theta) x_i - sin(theta) y_i)`
//! where `(x_i, y_i) = (r_i . e1, r_i . e2)` are the coordinates of its
//! rotation-plane projection `r_i^c = r_i - (r_i . w^) w^`. Over the arc
//! `theta in [theta_a, theta_b]`, `max |c(t) . r_i^c|` is (`proofs/04-evq-case-split.md`):
//!
//! * `|c| |r_i^c|` when the arc meets the line through `r_i^c` (the sweep is at
//!   least pi, or `c(t_a)` and `c(t_b)` lie on opposite sides of that line);
//! * `max(|c(t_a) . r_i^c|, |c(t_b) . r_i^c|)` otherwise.
//!
//! The seed's printed Eq. 2 has these two cases swapped, drops the absolute
//! value and has no case for sweeps of pi or more; see the proof.

use crate::{DirectedBound, Direction, Float, PreparedMotion, RigidMotion, Vec3, VertexSet};

/// The EVQ bound: `|v.n| + max_i max_{t in [t_a, t_b]} |c(t) . r_i^c|`,
/// rounded up and never above [`nevq`](crate::nevq).
///
/// `O(N)` per query over the body's vertices (convex-hull vertices suffice).
/// It bounds the directed speed at every time of the motion's interval, and
/// the displacement as speed times length. Work a query does not need is
/// skipped: no scan at all when `c = n x w` vanishes (no rotation, or `n`
/// parallel to `w`); no trigonometry when the sweep is pi or more; and the
/// scan stops as soon as one vertex reaches the NEVQ value.
///
/// For a rotation so slow or a `c` so short that its square is subnormal
/// (below [`Float::TINY_LENGTH`]), the NEVQ value is returned: still sound.
///
/// ```
/// use motion_bound::{evq, nevq, Direction, RigidMotion, VertexSet};
/// // A rod along x spinning slowly about z, measured along y.
/// let rod = [[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0]];
/// let body = VertexSet::try_new(&rod).unwrap();
/// let motion = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0, 0.0, 0.1]).unwrap();
/// let tight = evq(&body, &motion, Direction::Y).speed;
/// let loose = nevq(&body.summary(), &motion, Direction::Y).speed;
/// // Along y the rod's ends move at 0.1 cos(theta) for theta in [0, 0.1]: the sup is 0.1
/// // at t = 0; along x they move at 0.1 sin(theta) <= 0.1 sin(0.1).
/// assert!(tight >= 0.1 && tight <= loose);
/// let along_x = evq(&body, &motion, Direction::X).speed;
/// assert!(along_x < 0.0101 && along_x >= 0.1 * 0.1f64.sin());
/// ```
#[must_use]
pub fn evq<T: Float>(
    body: &VertexSet<'_, T>,
    motion: &RigidMotion<T>,
    n: Direction<T>,
) -> DirectedBound<T> {
    DirectedBound::from_speed(evq_speed(body, motion, n), motion)
}

/// The EVQ speed bound alone (see [`evq`]).
#[must_use]
pub fn evq_speed<T: Float>(body: &VertexSet<'_, T>, motion: &RigidMotion<T>, n: Direction<T>) -> T {
    PreparedMotion::new(motion).probe(n).evq_speed(body)
}

/// The EVQ speed in plain floating point, without any rounding margin:
/// `fl(|v.n| + |c| E^)`. Not a sound bound; exposed only so that tests can
/// show the margin is needed (`proofs/floating-point.md`, "Power").
#[cfg(feature = "testkit")]
#[must_use]
pub fn evq_speed_unmargined<T: Float>(
    body: &VertexSet<'_, T>,
    motion: &RigidMotion<T>,
    n: Direction<T>,
) -> T {
    let probe = PreparedMotion::new(motion).probe(n);
    let e = match probe.extremal_sq(body.vertices(), T::INFINITY) {
        None => body.summary().max_radius(),
        Some(e_sq) => e_sq.sqrt(),
    };
    probe.linear_raw() + probe.c_norm() * e
}

/// Sweep of pi or more: `c(t)` meets the line through every `r_i^c`, so each
/// vertex contributes its squared distance from the axis, `|w^ x r_i|^2`.
#[inline]
pub(crate) fn full_turn_scan<T: Float>(
    vertices: &[[T; 3]],
    axis: Vec3<T>,
    stop_sq: T,
) -> Option<T> {
    let mut best = T::ZERO;
    for r in vertices {
        let v2 = axis.cross(Vec3::from_array(*r)).length_squared();
        if v2 > best {
            best = v2;
            if best >= stop_sq {
                return None;
            }
        }
    }
    Some(best)
}

/// The rotation-plane coordinates `q = (x, y) = (r . e1, r . e2)` of `r` and
/// the sides `g = u x q` of the arc's end directions `ua`, `ub`.
#[inline(always)]
fn plane_sides<T: Float>(
    r: &[T; 3],
    e1: Vec3<T>,
    e2: Vec3<T>,
    ua: (T, T),
    ub: (T, T),
) -> (T, T, T, T) {
    let r = Vec3::from_array(*r);
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
    e1: Vec3<T>,
    e2: Vec3<T>,
    ua: (T, T),
    ub: (T, T),
    stop_sq: T,
) -> Option<T> {
    let mut best = T::ZERO;
    for r in vertices {
        let (x, y, ga, gb) = plane_sides(r, e1, e2, ua, ub);
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
    e1: Vec3<T>,
    e2: Vec3<T>,
    ua: (T, T),
    ub: (T, T),
    c_norm: T,
    slack: T,
) -> T {
    let mut reach_sq = -T::INFINITY;
    let mut best_f = -T::INFINITY;
    for r in vertices {
        let (x, y, ga, gb) = plane_sides(r, e1, e2, ua, ub);
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
