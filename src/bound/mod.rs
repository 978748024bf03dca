//! Directed motion bounds: NEVQ (the seed's Eq. 3), EVQ (its Eq. 1 by the
//! corrected case split of Eq. 2), their one-sided forms, and the probe that
//! evaluates them for many bodies along one direction.
//!
//! Layering inside: [`directed`] (what a bound is) and [`projection`] (the
//! per-direction quantities) at the bottom, then [`scan`] (the per-point case
//! split), [`probe`] (one motion, one direction, any body), and the one-shot
//! functions [`nevq`] and [`evq`] on top.

pub(crate) mod directed;
pub(crate) mod evq;
pub(crate) mod nevq;
pub(crate) mod probe;
pub(crate) mod projection;
pub(crate) mod scan;

use crate::{BoundKind, DirectedBound, Direction, Float, RigidMotion, VertexSet};

/// The directed bound of kind `kind` for `body` under `motion` along `n`.
///
/// ```
/// use motion_bound::{directed_bound, BoundKind, Direction, RigidMotion, VertexSet};
/// let body = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let body = VertexSet::try_new(&body).unwrap();
/// let motion = RigidMotion::try_from_arrays([0.0; 3], [0.0, 0.0, 1.0], [0.0, 0.0, 0.5]).unwrap();
/// let n = Direction::try_from_array([0.0, 1.0, 1.0]).unwrap();
/// let nevq = directed_bound(BoundKind::Nevq, &body, &motion, n);
/// let evq = directed_bound(BoundKind::Evq, &body, &motion, n);
/// assert!(evq.speed <= nevq.speed);
/// ```
#[must_use]
pub fn directed_bound<T: Float>(
    kind: BoundKind,
    body: &VertexSet<'_, T>,
    motion: &RigidMotion<T>,
    n: Direction<T>,
) -> DirectedBound<T> {
    match kind {
        BoundKind::Nevq => crate::nevq(&body.summary(), motion, n),
        BoundKind::Evq => crate::evq(body, motion, n),
    }
}
