//! Rigid motion with constant linear and angular velocity, from a start pose.

use crate::error::{check_components, InputError, Quantity};
use crate::math::pose::mat_mul;
use crate::math::rotation_plane::rotate_about_axis;
use crate::rounding::two_sum;
use crate::{BodyPoint, Direction, Float, Isometry, Point3, Pose, Rotation, TimeInterval, Vec3};

/// A rigid motion with constant linear velocity `v` of the rotation centre and
/// constant angular velocity `w` about it, from a start pose, considered over
/// a time interval.
///
/// A body point `r` (a [`BodyPoint`], given in the body's own frame: the
/// frame its vertex set or tree is built in) is at
///
/// ```text
/// p(t) = x0 + v t + R(w t) Q0 (r - c),        p'(t) = v + w x R(w t) Q0 (r - c),
/// ```
///
/// where `Q0` is the body's orientation at the epoch `t = 0` (a
/// [`Rotation`], identity by default), `c` the rotation centre in the body
/// frame (parry's `local_center`; the body origin by default), `x0` the
/// rotation centre's world position at `t = 0`, and `R(w t)` the rotation
/// about the fixed world axis `w^ = w/|w|` by the angle `|w| t`
/// (right-handed). `v` and `w` are world vectors. The directed speed along a
/// unit `n` is `v . n + (n x w) . R(w t) Q0 (r - c)`; the bounds evaluate its
/// rotational part in the body frame (`Q0^T n` and `Q0^T w`, `O(1)` per
/// direction), so a body's vertex set and tree are built once, whatever its
/// orientation (`proofs/floating-point.md`, "Orientation").
///
/// The interval is where bounds are taken. [`restrict`](Self::restrict)
/// narrows it and keeps the epoch, so per-body summaries computed once stay
/// valid at every step of conservative advancement.
///
/// ```
/// use motion_bound::{BodyPoint, Isometry, Point3, RigidMotion, Rotation, Vec3};
/// // A body turned a quarter about z at the start, moving along x at 2 and
/// // spinning about z at 1 rad per unit time, over [0, 0.5].
/// let turned = Rotation::try_from_axis_angle(Vec3::new(0.0, 0.0, 1.0), core::f64::consts::FRAC_PI_2)?;
/// let start = Isometry::try_new(turned, Vec3::new(1.0, 0.0, 0.0))?;
/// let m = RigidMotion::try_from_start(start, Vec3::new(2.0, 0.0, 0.0), Vec3::new(0.0, 0.0, 1.0), 0.5)?;
/// // The body point (1, 0, 0) starts at (1, 1, 0).
/// let p = m.point_at(BodyPoint::new(1.0, 0.0, 0.0), 0.0);
/// assert!((p - Point3::new(1.0, 1.0, 0.0)).length() < 1e-15);
/// assert_eq!(m.interval().end(), 0.5);
/// # Ok::<(), motion_bound::InputError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RigidMotion<T> {
    centre: Point3<T>,
    orientation: Rotation<T>,
    local_centre: Vec3<T>,
    /// `|c|` rounded up (`rounding::radius_up`), `0` for `c = 0`.
    local_reach: T,
    linear: Vec3<T>,
    angular: Vec3<T>,
    interval: TimeInterval<T>,
    omega: T,
    axis: Vec3<T>,
    /// An upper bound of the distance between `centre` and the exact centre
    /// the motion stands for: `0`, except for a motion moved into a pair's
    /// frame by [`rebased`](Self::rebased), whose centre is the rounded
    /// difference (`proofs/floating-point.md`, "Pair frame").
    centre_slack: T,
}

impl<T: Float> RigidMotion<T> {
    /// The motion of a body with the identity start orientation, rotating
    /// about its origin, whose origin is at `centre` at `t = 0`, with linear
    /// velocity `linear` and angular velocity `angular` (radians per unit
    /// time), over `interval`.
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
            orientation: Rotation::IDENTITY,
            local_centre: Vec3::ZERO,
            local_reach: T::ZERO,
            linear,
            angular,
            interval,
            omega,
            axis,
            centre_slack: T::ZERO,
        })
    }

    /// A motion over `[0, 1]` from plain arrays: centre, `v`, `w` (identity
    /// start orientation, rotation about the body origin).
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

    /// The motion of a body at the pose `start` at `t = 0` (its frame's
    /// origin at `start.translation()`, turned by `start.rotation()`),
    /// rotating about its origin with angular velocity `angular` while the
    /// origin moves at `linear` (world vectors), over `[0, duration]`: what
    /// an engine hands over for one frame of length `duration`.
    ///
    /// # Errors
    /// As [`try_new`](Self::try_new); [`InputError::NonPositiveDuration`]
    /// for `duration <= 0`, [`InputError::NonFinite`] or
    /// [`InputError::TooLarge`] with [`Quantity::Duration`].
    pub fn try_from_start(
        start: Isometry<T>,
        linear: Vec3<T>,
        angular: Vec3<T>,
        duration: T,
    ) -> Result<Self, InputError> {
        let interval = frame_interval(duration)?;
        let m = Self::try_new(
            Point3::from_array(start.translation().to_array()),
            linear,
            angular,
            interval,
        )?;
        Ok(Self {
            orientation: start.rotation(),
            ..m
        })
    }

    /// The motion of a body turning about its body point `local_centre` (its
    /// centre of mass, about which engines integrate), given as an engine
    /// tracks it: the centre's world position `centre` at `t = 0`, the start
    /// orientation `rotation`, the centre's linear velocity `linear` and the
    /// angular velocity `angular` (world vectors), over `[0, duration]`:
    /// `p(t) = centre + linear t + R(angular t) rotation (r - local_centre)`.
    /// The components are kept as given (nothing is rounded), unlike
    /// [`try_with_local_centre`](Self::try_with_local_centre), which moves the
    /// centre so as to keep the body origin's start position.
    ///
    /// # Errors
    /// As [`try_from_start`](Self::try_from_start), and
    /// [`InputError::NonFinite`] or [`InputError::TooLarge`] with
    /// [`Quantity::LocalCentre`].
    ///
    /// ```
    /// use motion_bound::{BodyPoint, Point3, RigidMotion, Rotation, Vec3};
    /// // A body whose centre of mass (1, 0, 0) in its frame sits at the world
    /// // origin, turned a quarter about z, spinning about that centre.
    /// let turned = Rotation::try_from_axis_angle(Vec3::new(0.0, 0.0, 1.0), core::f64::consts::FRAC_PI_2)?;
    /// let m = RigidMotion::try_about_centre(
    ///     Point3::new(0.0, 0.0, 0.0), Vec3::new(1.0, 0.0, 0.0), turned,
    ///     Vec3::ZERO, Vec3::new(0.0, 0.0, 3.0), 1.0,
    /// )?;
    /// let origin = m.point_at(BodyPoint::new(0.0, 0.0, 0.0), 0.0);
    /// assert!((origin.to_vec3() - Vec3::new(0.0, -1.0, 0.0)).length() < 1e-15);
    /// let pivot = m.point_at(BodyPoint::new(1.0, 0.0, 0.0), 0.7);
    /// assert!(pivot.to_vec3().length() < 1e-15);
    /// # Ok::<(), motion_bound::InputError>(())
    /// ```
    pub fn try_about_centre(
        centre: Point3<T>,
        local_centre: Vec3<T>,
        rotation: Rotation<T>,
        linear: Vec3<T>,
        angular: Vec3<T>,
        duration: T,
    ) -> Result<Self, InputError> {
        check_components(local_centre.to_array(), Quantity::LocalCentre)?;
        let m = Self::try_new(centre, linear, angular, frame_interval(duration)?)?;
        Ok(Self {
            orientation: rotation,
            local_centre,
            local_reach: reach_up(local_centre),
            ..m
        })
    }

    /// The motion with constant velocities that carries a body from the pose
    /// `start` at `t = 0` to the pose `end` at `t = duration`, rotating about
    /// its origin by the shortest rotation from `start`'s orientation to
    /// `end`'s (the angle in `[0, pi]`), with its origin on the straight line
    /// between the two positions: the constant-velocity interpolation of
    /// FCL's `InterpMotion(tf_beg, tf_end)` and parry's
    /// `NonlinearRigidMotion` between two poses. The end pose is reached up
    /// to rounding.
    ///
    /// # Errors
    /// As [`try_from_start`](Self::try_from_start) (a velocity beyond
    /// [`Float::MAX_INPUT`] for a tiny duration is `TooLarge`).
    ///
    /// ```
    /// use motion_bound::{Isometry, Point3, RigidMotion, Rotation, Vec3};
    /// let a = Isometry::try_from_translation(Vec3::new(0.0, 0.0, 0.0))?;
    /// let turned = Rotation::try_from_axis_angle(Vec3::new(1.0, 0.0, 0.0), 1.0)?;
    /// let b = Isometry::try_new(turned, Vec3::new(2.0, 0.0, 0.0))?;
    /// let m = RigidMotion::try_between(a, b, 0.25)?;
    /// let r = Point3::new(0.0, 1.0, 0.0);
    /// let at_end = m.pose_at(0.25).transform_point(r.to_vec3());
    /// assert!((Point3::from_array(at_end.to_array()) - b.transform_point(r)).length() < 1e-14);
    /// # Ok::<(), motion_bound::InputError>(())
    /// ```
    pub fn try_between(
        start: Isometry<T>,
        end: Isometry<T>,
        duration: T,
    ) -> Result<Self, InputError> {
        Self::try_between_about(start, end, duration, Vec3::ZERO)
    }

    /// As [`try_between`](Self::try_between), rotating about the body point
    /// `local_centre` (its centre of mass, say) instead of the body origin:
    /// that point moves on the straight line between its two positions, and
    /// the other points follow the rotation about it.
    ///
    /// # Errors
    /// As [`try_between`](Self::try_between), and
    /// [`InputError::NonFinite`] or [`InputError::TooLarge`] with
    /// [`Quantity::LocalCentre`].
    pub fn try_between_about(
        start: Isometry<T>,
        end: Isometry<T>,
        duration: T,
        local_centre: Vec3<T>,
    ) -> Result<Self, InputError> {
        let interval = frame_interval(duration)?;
        check_components(local_centre.to_array(), Quantity::LocalCentre)?;
        let c0 = start.translation() + start.rotation().rotate(local_centre);
        let c1 = end.translation() + end.rotation().rotate(local_centre);
        let linear = (c1 - c0) * (T::ONE / duration);
        let turn = end.rotation() * start.rotation().inverse();
        let angular = turn.to_scaled_axis() * (T::ONE / duration);
        let m = Self::try_new(Point3::from_array(c0.to_array()), linear, angular, interval)?;
        Ok(Self {
            orientation: start.rotation(),
            local_centre,
            local_reach: reach_up(local_centre),
            ..m
        })
    }

    /// The same motion with the start orientation `orientation`: the
    /// rotation centre's world position `x0`, `v` and `w` are kept.
    #[must_use]
    pub const fn with_orientation(self, orientation: Rotation<T>) -> Self {
        Self {
            orientation,
            ..self
        }
    }

    /// The motion with the same start pose (up to rounding) and the same
    /// velocities, but turning about the body point `local_centre` (parry's
    /// `local_center`) instead: the linear velocity is now that centre's,
    /// and the centre's world position is moved so that the body origin
    /// keeps its start position. (To give the centre's world position
    /// directly, as engines track it, use
    /// [`try_about_centre`](Self::try_about_centre).)
    ///
    /// # Errors
    /// [`InputError::NonFinite`] or [`InputError::TooLarge`] with
    /// [`Quantity::LocalCentre`], or with [`Quantity::Centre`] if the new
    /// centre's world position is too large.
    ///
    /// ```
    /// use motion_bound::{BodyPoint, RigidMotion, Vec3};
    /// // Spinning about the body point (1, 0, 0), which stays put.
    /// let m = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0, 0.0, 2.0])?
    ///     .try_with_local_centre(Vec3::new(1.0, 0.0, 0.0))?;
    /// let pivot = m.point_at(BodyPoint::new(1.0, 0.0, 0.0), 0.7);
    /// assert!((pivot.to_vec3() - Vec3::new(1.0, 0.0, 0.0)).length() < 1e-15);
    /// # Ok::<(), motion_bound::InputError>(())
    /// ```
    pub fn try_with_local_centre(self, local_centre: Vec3<T>) -> Result<Self, InputError> {
        check_components(local_centre.to_array(), Quantity::LocalCentre)?;
        let shift = self.orientation.rotate(local_centre - self.local_centre);
        let centre = self.centre + shift;
        check_components(centre.to_array(), Quantity::Centre)?;
        Ok(Self {
            centre,
            local_centre,
            local_reach: reach_up(local_centre),
            ..self
        })
    }

    /// The same motion in a frame translated by `-origin` (the world point
    /// `origin` becomes the frame's origin; axes, velocities and the
    /// interval are kept): what [`time_of_impact`](crate::ca::time_of_impact)
    /// places a pair in, so that rounding follows the pair's own extent, not
    /// its distance from the world origin.
    ///
    /// The new centre is the rounded difference `fl(x0 - origin)`; its
    /// rounding error, known exactly by TwoSum, is carried as the centre's
    /// slack and added to the placement error by
    /// [`placement_error`](crate::ca::placement_error)
    /// (`proofs/floating-point.md`, "Pair frame"). The difference is exact
    /// (no slack) when each component of `origin` is within a factor two of
    /// the centre's (Sterbenz), in particular for `origin = x0`.
    #[must_use]
    pub(crate) fn rebased(&self, origin: Point3<T>) -> Self {
        let (x, y, z) = (
            two_sum(self.centre.x, -origin.x),
            two_sum(self.centre.y, -origin.y),
            two_sum(self.centre.z, -origin.z),
        );
        Self {
            centre: Point3::new(x.0, y.0, z.0),
            centre_slack: crate::rounding::rebase_slack_up(self.centre_slack, [x.1, y.1, z.1]),
            ..*self
        }
    }

    /// An upper bound of the distance between the stored centre and the
    /// exact one: `0` except in a pair's frame ([`rebased`](Self::rebased)).
    #[inline]
    #[must_use]
    pub(crate) const fn centre_slack(&self) -> T {
        self.centre_slack
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

    /// The rotation centre's world position at `t = 0`, `x0`.
    #[inline]
    #[must_use]
    pub const fn centre(&self) -> Point3<T> {
        self.centre
    }

    /// The body's orientation at `t = 0`, `Q0`.
    #[inline]
    #[must_use]
    pub const fn orientation(&self) -> Rotation<T> {
        self.orientation
    }

    /// The rotation centre in the body frame, `c`.
    #[inline]
    #[must_use]
    pub const fn local_centre(&self) -> Vec3<T> {
        self.local_centre
    }

    /// `|c|` rounded up (`0` exactly when the rotation centre is the body
    /// origin): how much farther from the rotation centre than from the body
    /// origin a body point may be.
    #[inline]
    #[must_use]
    pub const fn local_reach(&self) -> T {
        self.local_reach
    }

    /// The body's pose at `t = 0`: `r |-> x0 + Q0 (r - c)`.
    #[must_use]
    pub fn start_pose(&self) -> Isometry<T> {
        let t = self.centre.to_vec3() - self.orientation.rotate(self.local_centre);
        Isometry::try_new(self.orientation, t).unwrap_or(Isometry::IDENTITY)
    }

    /// The angular velocity in the body frame at the epoch, `Q0^T w`
    /// (computed; exactly `w` for the identity orientation).
    #[inline]
    #[must_use]
    pub fn body_angular(&self) -> Vec3<T> {
        if self.orientation.is_identity() {
            self.angular
        } else {
            self.orientation.inverse_rotate(self.angular)
        }
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

    /// The lever arm `R(w t) Q0 (r - c)` of body point `r` at time `t`.
    #[inline]
    #[must_use]
    pub fn arm_at(&self, r: BodyPoint<T>, t: T) -> Vec3<T> {
        let arm = self.orientation.rotate(r.arm() - self.local_centre);
        if self.omega == T::ZERO {
            arm
        } else {
            rotate_about_axis(arm, self.axis, self.angle_at(t))
        }
    }

    /// The world position `p(t) = x0 + v t + R(w t) Q0 (r - c)` of body point `r`.
    #[inline]
    #[must_use]
    pub fn point_at(&self, r: BodyPoint<T>, t: T) -> Point3<T> {
        self.centre_at(t) + self.arm_at(r, t)
    }

    /// The pose at time `t`: `p(t) = pose.transform_point(r)` for every body
    /// point `r`, with the rotation matrix `R(w t)` built once by Rodrigues'
    /// formula `R = cos(a) I + sin(a) [k]x + (1 - cos(a)) k k^T`, `a = |w| t`,
    /// times `Q0`'s matrix, and the translation `x0 + v t - R(w t) Q0 c`.
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
        let centre = self.centre_at(t).to_vec3();
        let spin = self.spin_at(t);
        let rotation = if self.orientation.is_identity() {
            spin
        } else {
            mat_mul(&spin, &self.orientation.matrix())
        };
        let mut pose = Pose {
            rotation,
            translation: centre,
        };
        if self.local_centre != Vec3::ZERO {
            pose.translation = centre - pose.transform_vector(self.local_centre);
        }
        pose
    }

    /// `R(w t)`, row-major, by Rodrigues' formula (the identity when `w = 0`).
    fn spin_at(&self, t: T) -> [[T; 3]; 3] {
        if self.omega == T::ZERO {
            return Pose::<T>::IDENTITY.rotation;
        }
        let a = self.angle_at(t);
        let (s, c) = (a.sin(), a.cos());
        let k = self.axis;
        let d = T::ONE - c;
        [
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
        ]
    }

    /// The velocity `p'(t) = v + w x R(w t) Q0 (r - c)` of body point `r`.
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

/// `|c|` rounded up (`proofs/floating-point.md`, "Summary").
fn reach_up<T: Float>(c: Vec3<T>) -> T {
    if c == Vec3::ZERO {
        T::ZERO
    } else {
        crate::rounding::radius_up(c.length_squared())
    }
}

/// `[0, duration]`, checked.
fn frame_interval<T: Float>(duration: T) -> Result<TimeInterval<T>, InputError> {
    check_components([duration, T::ZERO, T::ZERO], Quantity::Duration)?;
    if duration <= T::ZERO {
        return Err(InputError::NonPositiveDuration);
    }
    TimeInterval::try_new(T::ZERO, duration)
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
