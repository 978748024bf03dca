//! The arc swept by the rotating direction over a motion's interval,
//! precomputed once per motion.

use crate::rounding::{axis_tilt_up, frame_margin_up};
use crate::{Float, RigidMotion, Vec3};

/// What the EVQ case split needs of a motion's rotation over its interval
/// `[t_a, t_b]`: the angles `theta = |w| t` at the ends, their unit
/// directions `u(theta) = (cos theta, -sin theta)` in the rotation plane, and
/// whether the sweep `theta_b - theta_a` reaches pi.
///
/// Computing it costs two `sin`/`cos` pairs; a conservative-advancement
/// iteration computes it once per body ([`PreparedMotion`](crate::PreparedMotion))
/// and then evaluates thousands of per-node bounds without trigonometry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SweptArc<T> {
    /// The unit rotation axis in the body frame (zero when not rotating).
    pub(crate) axis: Vec3<T>,
    /// `max(|theta_a|, |theta_b|)`, which the rounding margin grows with.
    pub(crate) theta_m: T,
    /// Whether the rotation is trusted at all (`|w|` above `TINY_LENGTH`).
    pub(crate) rotating: bool,
    /// Whether the computed sweep is at least pi.
    pub(crate) full_turn: bool,
    /// `u(theta_a)`.
    pub(crate) ua: (T, T),
    /// `u(theta_b)`.
    pub(crate) ub: (T, T),
}

impl<T: Float> SweptArc<T> {
    /// The arc of `motion` over its interval.
    ///
    /// ```
    /// use motion_bound::{RigidMotion, SweptArc};
    /// let m = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0, 0.0, 4.0]).unwrap();
    /// assert!(SweptArc::new(&m).is_full_turn()); // 4 rad >= pi
    /// assert!(!SweptArc::new(&m.restrict(0.0, 0.5).unwrap()).is_full_turn());
    /// ```
    #[must_use]
    pub fn new(motion: &RigidMotion<T>) -> Self {
        Self::with_body_angular(motion, motion.body_angular())
    }

    /// The arc of `motion` with its body-frame angular velocity `w_b`
    /// ([`RigidMotion::body_angular`]) computed once.
    fn with_body_angular(motion: &RigidMotion<T>, w_b: Vec3<T>) -> Self {
        let omega = if motion.orientation().is_identity() {
            motion.angular_speed()
        } else {
            w_b.length()
        };
        let axis = if omega > T::ZERO {
            Vec3::new(w_b.x / omega, w_b.y / omega, w_b.z / omega)
        } else {
            Vec3::ZERO
        };
        let iv = motion.interval();
        let theta_a = omega * iv.start();
        let theta_b = omega * iv.end();
        let rotating = omega > T::TINY_LENGTH;
        let full_turn = theta_b - theta_a >= T::PI;
        let (ua, ub) = if rotating && !full_turn {
            (
                (theta_a.cos(), -theta_a.sin()),
                (theta_b.cos(), -theta_b.sin()),
            )
        } else {
            ((T::ONE, T::ZERO), (T::ONE, T::ZERO))
        };
        Self {
            axis,
            theta_m: theta_a.abs().max_nan(theta_b.abs()),
            rotating,
            full_turn,
            ua,
            ub,
        }
    }

    /// Whether the computed sweep `|w| (t_b - t_a)` is at least pi (then every
    /// body point's rotation-plane line is met and the EVQ term is each point's
    /// distance from the axis).
    #[inline]
    #[must_use]
    pub const fn is_full_turn(&self) -> bool {
        self.full_turn
    }

    /// Whether the motion rotates at all (`|w|` above [`Float::TINY_LENGTH`];
    /// slower rotations are bounded by NEVQ alone, still soundly).
    #[inline]
    #[must_use]
    pub const fn is_rotating(&self) -> bool {
        self.rotating
    }
}

/// A rigid motion with its [`SweptArc`]: what a body's bounds need of its
/// motion, computed once and reused for every direction `n` and every node
/// of a bounding-volume hierarchy.
///
/// ```
/// use motion_bound::{evq, BoundKind, Direction, PreparedMotion, RigidMotion, VertexSet};
/// let body = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let body = VertexSet::try_new(&body).unwrap();
/// let motion = RigidMotion::try_from_arrays([0.0; 3], [0.0, 0.0, 1.0], [0.0, 0.0, 0.5]).unwrap();
/// let prepared = PreparedMotion::new(&motion);
/// for n in [Direction::X, Direction::Y, Direction::Z] {
///     // The same value as the one-shot function, without its trigonometry.
///     assert_eq!(prepared.probe(n).speed(&body, BoundKind::Evq), evq(&body, &motion, n).speed);
/// }
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PreparedMotion<T> {
    motion: RigidMotion<T>,
    arc: SweptArc<T>,
    /// `Q0^T w`, computed (exactly `w` for the identity orientation).
    body_angular: Vec3<T>,
    /// The coefficient `k` of the EVQ bounds' frame margin `k R` for points
    /// within `R` of the rotation centre (`rounding::frame_margin_up`): `0`
    /// when the body frame is the world frame and the rotation centre the
    /// body origin.
    pub(crate) frame_margin: T,
    /// An upper bound of `|w x Q0 y|`, how fast the body's `y` axis turns
    /// (`rounding::axis_tilt_up`): what an axially symmetric shape's support
    /// moves by under the turn (`proofs/12-shapes.md`, Lemma 12.5).
    pub(crate) axis_tilt: T,
}

impl<T: Float> PreparedMotion<T> {
    /// Precomputes the arc of `motion` over its interval, and the body-frame
    /// quantities.
    #[must_use]
    pub fn new(motion: &RigidMotion<T>) -> Self {
        let body_angular = motion.body_angular();
        let arc = SweptArc::with_body_angular(motion, body_angular);
        let frame_margin = frame_margin_up(
            body_angular.norm_l1(),
            arc.theta_m,
            !motion.orientation().is_identity(),
            motion.local_centre() != Vec3::ZERO,
        );
        let axis_tilt = axis_tilt_up(
            body_angular.to_array(),
            motion.angular().norm_l1(),
            !motion.orientation().is_identity(),
        );
        Self {
            motion: *motion,
            arc,
            body_angular,
            frame_margin,
            axis_tilt,
        }
    }

    /// The motion.
    #[inline]
    #[must_use]
    pub const fn motion(&self) -> &RigidMotion<T> {
        &self.motion
    }

    /// The precomputed arc.
    #[inline]
    #[must_use]
    pub const fn arc(&self) -> &SweptArc<T> {
        &self.arc
    }

    /// The angular velocity in the body frame, `Q0^T w`.
    #[inline]
    #[must_use]
    pub const fn body_angular(&self) -> Vec3<T> {
        self.body_angular
    }
}
