//! Directed motion bounds: what they bound, and choosing one per query.

use crate::rounding::{displacement_up, linear_up};
use crate::{Direction, Float, RigidMotion, Vec3, VertexSet};

/// Which directed bound a query uses.
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
pub struct DirectedBound<T> {
    /// Upper bound of the directed speed at every time of the interval.
    pub speed: T,
    /// Upper bound of the directed displacement over the interval.
    pub displacement: T,
}

impl<T: Float> DirectedBound<T> {
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
    /// let b = DirectedBound { speed: 2.0, displacement: 2.0 };
    /// assert_eq!(b.time_to_close(1.0), 0.5);
    /// assert_eq!(b.time_to_close(-3.0), 0.0);
    /// assert_eq!(b.time_to_close(f64::NAN), 0.0);
    /// let still = DirectedBound { speed: 0.0, displacement: 0.0 };
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

/// The per-query quantities both bounds share: `a = v.n`, `c = n x w`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Projection<T> {
    /// `fl(v . n)`.
    pub(crate) a: T,
    /// `fl(sum |v_k n_k|)`, the magnitude bounding the error of `a`.
    pub(crate) a_mag: T,
    /// `fl(n x w)`.
    pub(crate) c: Vec3<T>,
    /// `fl(|fl(n x w)|)`.
    pub(crate) c_norm: T,
    /// `fl(|w|_1)`.
    pub(crate) w_l1: T,
}

impl<T: Float> Projection<T> {
    #[inline]
    pub(crate) fn new(motion: &RigidMotion<T>, n: Direction<T>) -> Self {
        let n = n.get();
        let v = motion.linear();
        let w = motion.angular();
        let c = n.cross(w);
        Self {
            a: v.dot(n),
            a_mag: v.dot_abs(n),
            c,
            c_norm: c.length(),
            w_l1: w.norm_l1(),
        }
    }

    #[inline]
    pub(crate) fn linear_up(&self) -> T {
        linear_up(self.a, self.a_mag)
    }
}

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
