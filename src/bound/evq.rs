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

use crate::{DirectedBound, Direction, Float, PreparedMotion, RigidMotion, VertexSet};

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

/// The one-sided EVQ bound: an upper bound of the *signed* speed
/// `d/dt (p_i(t) . n)` of every vertex over the motion's interval, by the
/// one-sided case split (does the arc reach each point's direction `+q`?
/// `proofs/10-one-sided.md`, Lemma 10.1), rounded up; never above
/// [`nevq_rate`](crate::nevq_rate) (it takes the smaller).
///
/// ```
/// use motion_bound::{evq_rate, nevq_rate, Direction, RigidMotion, VertexSet};
/// let rod = VertexSet::try_new(&[[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0]]).unwrap();
/// // Turning slowly about z: along y the ends move at +-0.1 cos(theta).
/// let m = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0, 0.0, 0.1]).unwrap();
/// let rate = evq_rate(&rod, &m, Direction::Y);
/// assert!(rate >= 0.1 && rate <= nevq_rate(&rod.summary(), &m, Direction::Y));
/// ```
#[must_use]
pub fn evq_rate<T: Float>(body: &VertexSet<'_, T>, motion: &RigidMotion<T>, n: Direction<T>) -> T {
    PreparedMotion::new(motion)
        .probe(n)
        .rate(body, crate::BoundKind::Evq)
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
