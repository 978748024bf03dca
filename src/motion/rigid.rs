//! Rigid motion with constant linear and angular velocity.

use crate::error::{check_components, InputError, Quantity};
use crate::math::rotation::rotate_about_axis;
use crate::{BodyPoint, Direction, Float, Point3, Pose, TimeInterval, Vec3};

/// A rigid motion with constant linear velocity `v` of the rotation centre and
/// constant angular velocity `w` about it, considered over a time interval.
///
/// A body point `r` (a [`BodyPoint`], given relative to the rotation centre at
/// the epoch `t = 0`) is at
///
/// ```text
/// p(t) = x0 + v t + R(t) r,        p'(t) = v + w x R(t) r,
/// ```
///
/// where `x0` is the centre at `t = 0` and `R(t)` the rotation about the fixed
/// axis `w^ = w/|w|` by the angle `|w| t` (right-handed). The directed speed
/// along a unit `n` is `p'(t) . n = v . n + (n x w) . R(t) r`.
///
/// The interval is where bounds are taken. [`restrict`](Self::restrict)
/// narrows it and keeps the epoch, so per-body summaries computed once stay
/// valid at every step of conservative advancement.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RigidMotion<T> {
    centre: Point3<T>,
    linear: Vec3<T>,
    angular: Vec3<T>,
    interval: TimeInterval<T>,
    omega: T,
    axis: Vec3<T>,
}

impl<T: Float> RigidMotion<T> {
    /// The motion with centre `centre` at `t = 0`, linear velocity `linear`
    /// and angular velocity `angular` (radians per unit time), over `interval`.
    ///
    /// # Errors
    /// [`InputError::NonFinite`] or [`InputError::TooLarge`] (above
    /// [`Float::MAX_INPUT`]) naming the offending quantity.
    ///
    /// ```
    /// use motion_bound::{Point3, RigidMotion, TimeInterval, Vec3};
    /// let m = RigidMotion::try_new(
    ///     Point3::ORIGIN,
    ///     Vec3::new(1.0, 0.0, 0.0),
    ///     Vec3::new(0.0, 0.0, 3.0),
    ///     TimeInterval::UNIT,
    /// )
    /// .unwrap();
    /// assert_eq!(m.angular_speed(), 3.0);
    /// ```
    pub fn try_new(
        centre: Point3<T>,
        linear: Vec3<T>,
        angular: Vec3<T>,
        interval: TimeInterval<T>,
    ) -> Result<Self, InputError> {
        check_components(centre.to_array(), Quantity::Centre)?;
        check_components(linear.to_array(), Quantity::LinearVelocity)?;
        check_components(angular.to_array(), Quantity::AngularVelocity)?;
        let omega = angular.length();
        let axis = if omega > T::ZERO {
            Vec3::new(angular.x / omega, angular.y / omega, angular.z / omega)
        } else {
            Vec3::ZERO
        };
        Ok(Self {
            centre,
            linear,
            angular,
            interval,
            omega,
            axis,
        })
    }

    /// A motion over `[0, 1]` from plain arrays: centre, `v`, `w`.
    ///
    /// # Errors
    /// As [`try_new`](Self::try_new).
    pub fn try_from_arrays(
        centre: [T; 3],
        linear: [T; 3],
        angular: [T; 3],
    ) -> Result<Self, InputError> {
        Self::try_new(
            Point3::from_array(centre),
            Vec3::from_array(linear),
            Vec3::from_array(angular),
            TimeInterval::UNIT,
        )
    }

    /// The same motion, with bounds taken over `[start, end]` instead.
    ///
    /// # Errors
    /// [`InputError::NotASubInterval`] unless `[start, end]` lies inside the
    /// current interval; the errors of [`TimeInterval::try_new`].
    pub fn restrict(&self, start: T, end: T) -> Result<Self, InputError> {
        let sub = TimeInterval::try_new(start, end)?;
        if !self.interval.contains_interval(sub) {
            return Err(InputError::NotASubInterval);
        }
        Ok(Self {
            interval: sub,
            ..*self
        })
    }

    /// The same motion over any interval (not required to be a sub-interval).
    #[must_use]
    pub fn with_interval(&self, interval: TimeInterval<T>) -> Self {
        Self { interval, ..*self }
    }

    /// The rotation centre at `t = 0`.
    #[inline]
    #[must_use]
    pub const fn centre(&self) -> Point3<T> {
        self.centre
    }

    /// The linear velocity `v` of the rotation centre.
    #[inline]
    #[must_use]
    pub const fn linear(&self) -> Vec3<T> {
        self.linear
    }

    /// The angular velocity `w`.
    #[inline]
    #[must_use]
    pub const fn angular(&self) -> Vec3<T> {
        self.angular
    }

    /// The interval over which bounds are taken.
    #[inline]
    #[must_use]
    pub const fn interval(&self) -> TimeInterval<T> {
        self.interval
    }

    /// `|w|`, rounded to nearest (computed once).
    #[inline]
    #[must_use]
    pub const fn angular_speed(&self) -> T {
        self.omega
    }

    /// The unit rotation axis `w / |w|`, or zero when `w = 0`.
    #[inline]
    #[must_use]
    pub const fn axis(&self) -> Vec3<T> {
        self.axis
    }

    /// The rotation angle `|w| t` at time `t`.
    #[inline]
    #[must_use]
    pub fn angle_at(&self, t: T) -> T {
        self.omega * t
    }

    /// The rotation centre at time `t`: `x0 + v t`.
    #[inline]
    #[must_use]
    pub fn centre_at(&self, t: T) -> Point3<T> {
        self.centre + self.linear * t
    }

    /// The lever arm `R(t) r` of body point `r` at time `t`.
    #[inline]
    #[must_use]
    pub fn arm_at(&self, r: BodyPoint<T>, t: T) -> Vec3<T> {
        if self.omega == T::ZERO {
            r.arm()
        } else {
            rotate_about_axis(r.arm(), self.axis, self.angle_at(t))
        }
    }

    /// The world position `p(t) = x0 + v t + R(t) r` of body point `r`.
    #[inline]
    #[must_use]
    pub fn point_at(&self, r: BodyPoint<T>, t: T) -> Point3<T> {
        self.centre_at(t) + self.arm_at(r, t)
    }

    /// The pose at time `t`: `p(t) = pose.transform_point(r)` for every body
    /// point `r`, with the rotation matrix `R(t)` built once by Rodrigues'
    /// formula `R = cos(a) I + sin(a) [k]x + (1 - cos(a)) k k^T`, `a = |w| t`.
    ///
    /// ```
    /// use motion_bound::{BodyPoint, RigidMotion, Vec3};
    /// let m = RigidMotion::try_from_arrays([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.5]).unwrap();
    /// let r = BodyPoint::new(0.3, -0.2, 0.7);
    /// let (a, b) = (m.pose_at(0.8).transform_point(r.arm()), m.point_at(r, 0.8).to_vec3());
    /// assert!((a - b).length() < 1e-15);
    /// ```
    #[must_use]
    pub fn pose_at(&self, t: T) -> Pose<T> {
        let translation = self.centre_at(t).to_vec3();
        if self.omega == T::ZERO {
            return Pose {
                translation,
                ..Pose::IDENTITY
            };
        }
        let a = self.angle_at(t);
        let (s, c) = (a.sin(), a.cos());
        let k = self.axis;
        let d = T::ONE - c;
        let rotation = [
            [
                c + d * k.x * k.x,
                d * k.x * k.y - s * k.z,
                d * k.x * k.z + s * k.y,
            ],
            [
                d * k.y * k.x + s * k.z,
                c + d * k.y * k.y,
                d * k.y * k.z - s * k.x,
            ],
            [
                d * k.z * k.x - s * k.y,
                d * k.z * k.y + s * k.x,
                c + d * k.z * k.z,
            ],
        ];
        Pose {
            rotation,
            translation,
        }
    }

    /// The velocity `p'(t) = v + w x R(t) r` of body point `r`.
    #[inline]
    #[must_use]
    pub fn velocity_at(&self, r: BodyPoint<T>, t: T) -> Vec3<T> {
        self.linear + self.angular.cross(self.arm_at(r, t))
    }

    /// The directed speed `p'(t) . n` of body point `r` along `n`.
    #[inline]
    #[must_use]
    pub fn directed_speed_at(&self, r: BodyPoint<T>, t: T, n: Direction<T>) -> T {
        self.velocity_at(r, t).dot(n.get())
    }
}

#[cfg(test)]
mod tests {
    use super::RigidMotion;
    use crate::{BodyPoint, Direction, Point3, TimeInterval, Vec3};

    fn spin() -> RigidMotion<f64> {
        RigidMotion::try_new(
            Point3::new(1.0, 2.0, 3.0),
            Vec3::new(0.5, 0.0, 0.0),
            Vec3::new(0.0, 0.0, core::f64::consts::PI),
            TimeInterval::UNIT,
        )
        .unwrap()
    }

    #[test]
    fn half_turn_over_the_unit_interval() {
        let m = spin();
        let p = m.point_at(BodyPoint::new(1.0, 0.0, 0.0), 1.0);
        assert!(
            (p - Point3::new(0.5, 2.0, 3.0)).length() < 1e-15,
            "got {p:?}"
        );
    }

    #[test]
    fn velocity_is_the_time_derivative_of_position() {
        let m = spin();
        let r = BodyPoint::new(0.3, -0.7, 0.2);
        let (t, h) = (0.37, 1e-6);
        let fd = (m.point_at(r, t + h) - m.point_at(r, t - h)) * (0.5 / h);
        assert!(
            (fd - m.velocity_at(r, t)).length() < 1e-8,
            "finite difference"
        );
        let n = Direction::Y;
        assert!(
            (m.directed_speed_at(r, t, n) - m.velocity_at(r, t).y).abs() < 1e-15,
            "directed"
        );
    }

    #[test]
    fn restriction_keeps_the_epoch_and_checks_containment() {
        let m = spin();
        let sub = m.restrict(0.25, 0.5).unwrap();
        assert_eq!(
            sub.interval(),
            TimeInterval::try_new(0.25, 0.5).unwrap(),
            "interval"
        );
        assert_eq!(
            sub.point_at(BodyPoint::new(1.0, 0.0, 0.0), 0.3),
            m.point_at(BodyPoint::new(1.0, 0.0, 0.0), 0.3),
            "epoch kept"
        );
        assert_eq!(
            m.restrict(0.5, 1.5),
            Err(crate::InputError::NotASubInterval),
            "outside"
        );
        assert_eq!(
            m.restrict(0.5, 0.25),
            Err(crate::InputError::ReversedInterval),
            "reversed"
        );
    }

    #[test]
    fn bad_motion_input_is_typed() {
        use crate::{InputError, Quantity};
        let e = RigidMotion::try_from_arrays([0.0; 3], [f64::NAN, 0.0, 0.0], [0.0; 3]);
        assert_eq!(
            e,
            Err(InputError::NonFinite(Quantity::LinearVelocity)),
            "NaN v"
        );
        let e = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [1e200, 0.0, 0.0]);
        assert_eq!(
            e,
            Err(InputError::TooLarge(Quantity::AngularVelocity)),
            "huge w"
        );
    }
}
