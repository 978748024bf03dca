//! A rigid placement `x -> R x + p`: where a body is at one time.

use crate::{Float, Vec3};

/// A rigid placement `x -> R x + translation`, with `R` a rotation matrix
/// stored row-major: `rotation[i][j]` is row `i`, column `j`.
///
/// [`RigidMotion::pose_at`](crate::RigidMotion::pose_at) gives the pose of a
/// body at a time; geometry code then maps body points (offsets from the
/// rotation centre) to the world with [`Pose::transform_point`], and world
/// directions to the body frame with [`Pose::inverse_transform_vector`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose<T> {
    /// The rotation matrix, row-major.
    pub rotation: [[T; 3]; 3],
    /// The translation (the rotation centre's position).
    pub translation: Vec3<T>,
}

impl<T: Float> Pose<T> {
    /// The identity placement.
    pub const IDENTITY: Self = Self {
        rotation: [
            [T::ONE, T::ZERO, T::ZERO],
            [T::ZERO, T::ONE, T::ZERO],
            [T::ZERO, T::ZERO, T::ONE],
        ],
        translation: Vec3::ZERO,
    };

    /// `R x` (a free vector: no translation).
    ///
    /// ```
    /// use motion_bound::{Pose, Vec3};
    /// let p = Pose::<f64>::IDENTITY;
    /// assert_eq!(p.transform_vector(Vec3::new(1.0, 2.0, 3.0)), Vec3::new(1.0, 2.0, 3.0));
    /// ```
    #[inline]
    #[must_use]
    pub fn transform_vector(&self, x: Vec3<T>) -> Vec3<T> {
        let r = &self.rotation;
        Vec3::new(
            r[0][0] * x.x + r[0][1] * x.y + r[0][2] * x.z,
            r[1][0] * x.x + r[1][1] * x.y + r[1][2] * x.z,
            r[2][0] * x.x + r[2][1] * x.y + r[2][2] * x.z,
        )
    }

    /// `R x + translation` (a body point to the world).
    #[inline]
    #[must_use]
    pub fn transform_point(&self, x: Vec3<T>) -> Vec3<T> {
        self.transform_vector(x) + self.translation
    }

    /// `R^T x` (a world direction to the body frame).
    #[inline]
    #[must_use]
    pub fn inverse_transform_vector(&self, x: Vec3<T>) -> Vec3<T> {
        let r = &self.rotation;
        Vec3::new(
            r[0][0] * x.x + r[1][0] * x.y + r[2][0] * x.z,
            r[0][1] * x.x + r[1][1] * x.y + r[2][1] * x.z,
            r[0][2] * x.x + r[1][2] * x.y + r[2][2] * x.z,
        )
    }
}
