//! Rotation about a fixed axis, and the rotation plane.

use crate::{Float, Vec3};

/// Rotates `r` about the unit `axis` by `angle` radians (right-handed),
/// by Rodrigues' formula
/// `R r = r cos(a) + (k x r) sin(a) + k (k . r)(1 - cos(a))`.
#[inline]
#[must_use]
pub fn rotate_about_axis<T: Float>(r: Vec3<T>, axis: Vec3<T>, angle: T) -> Vec3<T> {
    let (s, c) = (angle.sin(), angle.cos());
    r * c + axis.cross(r) * s + axis * (axis.dot(r) * (T::ONE - c))
}

/// The plane through the rotation centre orthogonal to the angular velocity:
/// where the seed's rotating direction `c(t) = R(t)^T (n x w)` lives.
///
/// The seed's Eq. 1 needs only the projection `r^c = r - (r . w^) w^` of each
/// body point onto this plane, because `c(t)` is orthogonal to `w^` at every
/// time: `c(t) . r = c(t) . r^c`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RotationPlane<T> {
    axis: Vec3<T>,
}

impl<T: Float> RotationPlane<T> {
    /// The plane orthogonal to `w`, or `None` when `w` is zero or not finite.
    ///
    /// ```
    /// use motion_bound::{RotationPlane, Vec3};
    /// let plane = RotationPlane::try_new(Vec3::new(0.0, 0.0, 2.0)).unwrap();
    /// assert_eq!(plane.project(Vec3::new(1.0, 2.0, 3.0)), Vec3::new(1.0, 2.0, 0.0));
    /// assert_eq!(plane.radius(Vec3::new(3.0, 4.0, 5.0)), 5.0);
    /// ```
    #[must_use]
    pub fn try_new(w: Vec3<T>) -> Option<Self> {
        w.try_normalize().map(|axis| Self { axis })
    }

    /// The unit normal `w^ = w / |w|` of the plane.
    #[inline]
    #[must_use]
    pub const fn axis(self) -> Vec3<T> {
        self.axis
    }

    /// The projection `r^c = r - (r . w^) w^` of `r` onto the plane.
    #[inline]
    #[must_use]
    pub fn project(self, r: Vec3<T>) -> Vec3<T> {
        r - self.axis * self.axis.dot(r)
    }

    /// The distance `|r^c| = |w^ x r|` of `r` from the rotation axis,
    /// computed through the cross product (no cancellation when `r` is almost
    /// on the axis).
    #[inline]
    #[must_use]
    pub fn radius(self, r: Vec3<T>) -> T {
        self.axis.cross(r).length()
    }
}

#[cfg(test)]
mod tests {
    use super::{rotate_about_axis, RotationPlane};
    use crate::Vec3;

    #[test]
    fn quarter_turn_about_z_maps_x_to_y() {
        let r = rotate_about_axis(
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(0.0, 0.0, 1.0),
            core::f64::consts::FRAC_PI_2,
        );
        assert!((r - Vec3::new(0.0, 1.0, 0.0)).length() < 1e-15, "got {r:?}");
    }

    #[test]
    fn projection_is_orthogonal_to_the_axis_and_idempotent() {
        let plane = RotationPlane::try_new(Vec3::new(1.0f64, -2.0, 0.5)).unwrap();
        let r = Vec3::new(0.3, 4.0, -7.0);
        let p = plane.project(r);
        assert!(p.dot(plane.axis()).abs() < 1e-14, "orthogonal");
        assert!((plane.project(p) - p).length() < 1e-14, "idempotent");
        assert!(
            (plane.radius(r) - p.length()).abs() < 1e-13,
            "radius is |r^c|"
        );
    }
}
