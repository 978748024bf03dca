//! What a directed bound bounds ([`DirectedBound`]), and which one ([`BoundKind`]).

use crate::rounding::displacement_up;
use crate::{Float, RigidMotion};

/// Which directed bound one evaluation computes: NEVQ or EVQ.
///
/// This is the choice for a single bound ([`directed_bound`](crate::directed_bound),
/// [`DirectedProbe::speed`](crate::DirectedProbe::speed)). A
/// conservative-advancement query chooses with
/// [`ca::BoundChoice`](crate::ca::BoundChoice) instead, a policy over its
/// many bounds: `Nevq` and `Evq` use this kind everywhere, `Auto` picks one
/// per evaluation by its cost ([`BoundChoice::cheap_kind`](crate::ca::BoundChoice::cheap_kind)).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum BoundKind {
    /// The seed's Eq. 3: `|v.n| + |n x w| max_i |r_i|`; `O(1)` per query.
    #[default]
    Nevq,
    /// The seed's Eq. 1 evaluated by the corrected per-vertex case split of
    /// Eq. 2 over the arc swept by `c(t)`; `O(N)` per query, never looser than
    /// [`BoundKind::Nevq`].
    Evq,
}

/// Upper bounds of the motion of every body point along a direction `n`
/// over the motion's interval `[t_a, t_b]`.
///
/// * `speed >= sup_{t in [t_a, t_b]} max_i |p_i'(t) . n|` bounds the directed
///   **speed** at every time. This is what a conservative-advancement step
///   `dt = d / speed` needs: a point whose speed along `n` never exceeds
///   `speed` cannot close a gap `d` in less than `d / speed`.
/// * `displacement >= max_i integral_{t_a}^{t_b} |p_i'(t) . n| dt` bounds the
///   directed **displacement**, the seed's `mu`. For the NEVQ and EVQ bounds
///   it is `speed * (t_b - t_a)` rounded up; the exact displacement (see the
///   `reference` module) can be much smaller. A step `d / displacement` over
///   the unit interval is **not** conservative in general
///   (`proofs/02-ca-step.md`).
///
/// Both are upper bounds for the floating-point inputs as given, with
/// rounding accounted for (`proofs/floating-point.md`); `+inf` is returned
/// only if a bound overflows, and NaN never.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct DirectedBound<T> {
    /// Upper bound of the directed speed at every time of the interval.
    pub speed: T,
    /// Upper bound of the directed displacement over the interval.
    pub displacement: T,
}

impl<T: Float> DirectedBound<T> {
    /// A bound with these values (for a caller's own bound, or a test).
    #[inline]
    #[must_use]
    pub const fn new(speed: T, displacement: T) -> Self {
        Self {
            speed,
            displacement,
        }
    }

    pub(crate) fn from_speed(speed: T, motion: &RigidMotion<T>) -> Self {
        Self {
            speed,
            displacement: displacement_up(speed, motion.interval().length()),
        }
    }

    /// The conservative-advancement time step `d / speed` for a gap `d`: no
    /// body point can travel `d` along `n` in less time.
    ///
    /// * `0` for a gap that is not positive, or NaN: no step is safe (a
    ///   negative time is never returned);
    /// * `+inf` for a positive gap when the bound is zero (nothing moves along
    ///   `n`), or for an infinite gap;
    /// * otherwise the quotient, rounded to nearest (for a step certified in
    ///   floating point, see [`ca::gap_step`](crate::ca::gap_step)).
    ///
    /// ```
    /// use motion_bound::DirectedBound;
    /// let b = DirectedBound::new(2.0, 2.0);
    /// assert_eq!(b.time_to_close(1.0), 0.5);
    /// assert_eq!(b.time_to_close(-3.0), 0.0);
    /// assert_eq!(b.time_to_close(f64::NAN), 0.0);
    /// let still = DirectedBound::new(0.0, 0.0);
    /// assert_eq!(still.time_to_close(1.0), f64::INFINITY);
    /// assert_eq!(still.time_to_close(-1.0), 0.0);
    /// ```
    #[inline]
    #[must_use]
    pub fn time_to_close(&self, gap: T) -> T {
        if gap.is_nan() || gap <= T::ZERO {
            T::ZERO
        } else if self.speed == T::ZERO {
            T::INFINITY
        } else {
            let s = gap / self.speed;
            if s.is_nan() || s < T::ZERO {
                T::ZERO
            } else {
                s
            }
        }
    }
}
