//! The NEVQ bound: the seed's Eq. 3.

use crate::bound::projection::{nevq_rate_from, nevq_speed_from, Projection};
use crate::rounding::lever_up;
use crate::{BodySummary, DirectedBound, Direction, Float, RigidMotion};

/// The seed's Eq. 3, `mu = |v.n| + |n x w| max_i |r_i|`, rounded up.
///
/// `O(1)` per query from a [`BodySummary`] computed once. It bounds the
/// directed speed at every time, whatever the interval, because
/// `|(n x w) . R(t) r_i| <= |n x w| |r_i|` (`proofs/03-nevq.md`); the
/// displacement bound is the speed bound times the interval's length.
///
/// Zero rotation or `n` parallel to `w` give `c = n x w = 0` and leave only the
/// linear term (plus the rounding margin).
///
/// ```
/// use motion_bound::{nevq, BodySummary, Direction, RigidMotion};
/// let body = BodySummary::from_radius(2.0).unwrap();
/// let motion = RigidMotion::try_from_arrays([0.0; 3], [3.0, 0.0, 0.0], [0.0, 0.0, 1.0]).unwrap();
/// let b = nevq(&body, &motion, Direction::X);
/// // |v.n| = 3, |n x w| = 1, R = 2: mu = 5 up to a few ulps.
/// assert!(b.speed >= 5.0 && b.speed <= 5.0 * (1.0 + 1e-14));
/// ```
#[must_use]
pub fn nevq<T: Float>(
    body: &BodySummary<T>,
    motion: &RigidMotion<T>,
    n: Direction<T>,
) -> DirectedBound<T> {
    DirectedBound::from_speed(nevq_speed(body, motion, n), motion)
}

/// The one-sided NEVQ bound: an upper bound of the *signed* speed
/// `d/dt (p(t) . n)` of every point of the body over the motion's interval,
/// `v.n + |n x w| max_i |r_i|` rounded up (`proofs/10-one-sided.md`). What a
/// conservative-advancement step needs of one body: the rate at which it
/// closes a gap along `n`. Negative when the body recedes along `n` faster
/// than it can turn towards it.
///
/// ```
/// use motion_bound::{nevq, nevq_rate, BodySummary, Direction, RigidMotion};
/// let body = BodySummary::from_radius(1.0).unwrap();
/// // Moving away along -x at 3, spinning at 1 rad per unit time about z.
/// let m = RigidMotion::try_from_arrays([0.0; 3], [-3.0, 0.0, 0.0], [0.0, 0.0, 1.0]).unwrap();
/// let rate = nevq_rate(&body, &m, Direction::X);
/// assert!(rate < -1.99 && rate >= -2.0); // -3 + 1 * 1
/// assert!(nevq(&body, &m, Direction::X).speed >= 4.0); // the absolute bound
/// ```
#[must_use]
pub fn nevq_rate<T: Float>(body: &BodySummary<T>, motion: &RigidMotion<T>, n: Direction<T>) -> T {
    let p = Projection::new(motion, n);
    nevq_rate_from(&p, lever_up(body.max_radius(), motion.local_reach()))
}

/// The NEVQ speed bound alone (see [`nevq`]).
#[must_use]
pub fn nevq_speed<T: Float>(body: &BodySummary<T>, motion: &RigidMotion<T>, n: Direction<T>) -> T {
    let p = Projection::new(motion, n);
    nevq_speed_from(&p, lever_up(body.max_radius(), motion.local_reach()))
}

/// The NEVQ speed in plain floating point, without any rounding margin:
/// `fl(|v.n| + |n x w| R^)`. Not a sound bound; exposed only so that tests can
/// show the margin is needed (`proofs/floating-point.md`, "Power").
#[cfg(feature = "testkit")]
#[must_use]
pub fn nevq_speed_unmargined<T: Float>(
    body: &BodySummary<T>,
    motion: &RigidMotion<T>,
    n: Direction<T>,
) -> T {
    let p = Projection::new(motion, n);
    p.a.abs() + p.c_norm * body.max_radius()
}
