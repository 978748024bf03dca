//! Rigid placements: a rotation matrix and a translation.

use crate::{Float, Vec3};

/// A placement `p |-> R p + x` of a body frame in the world frame: the pose
/// of a rigid body at one time, `x(t) + R(t) r`, evaluated as a matrix.
///
/// The crate has two placements, for two jobs. An
/// [`Isometry`](crate::Isometry) is what a caller *gives*: a checked unit
/// quaternion and translation, mapping typed [`Point3`](crate::Point3)s. A
/// `Pose` is what the crate *evaluates* and hands to steppers and distance
/// oracles ([`RigidMotion::pose_at`](crate::RigidMotion::pose_at),
/// [`Isometry::to_pose`](crate::Isometry::to_pose)): a plain matrix, no
/// checks, mapping [`Vec3`]s and stored vertices (`[T; 3]`) in the hot
/// loops.
///
/// `rotation` is stored row-major (`rotation[k]` is the `k`-th row of `R`).
/// Nothing checks that `R` is orthonormal: every map below is the plain
/// matrix product, and the support error bound of
/// [`ConvexPolytope`](crate::ConvexPolytope) is stated for any matrix. Sums
/// are evaluated in the written order, `(R_k0 p_0 + R_k1 p_1) + R_k2 p_2`,
/// then `+ x_k`.
///
/// ```
/// use motion_bound::{Pose, Vec3};
/// // A quarter turn about z, then a shift along x.
/// let pose = Pose::new(
///     [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]],
///     Vec3::new(2.0, 0.0, 0.0),
/// );
/// assert_eq!(pose.transform_point(Vec3::new(1.0, 0.0, 0.0)), Vec3::new(2.0, 1.0, 0.0));
/// assert_eq!(pose.transform_vector(Vec3::new(1.0, 0.0, 0.0)), Vec3::new(0.0, 1.0, 0.0));
/// // R^T undoes R for a rotation.
/// let v = Vec3::new(0.25, -3.0, 1.5);
/// assert_eq!(pose.inverse_transform_vector(pose.transform_vector(v)), v);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose<T> {
    /// The rotation matrix `R`, row-major.
    pub rotation: [[T; 3]; 3],
    /// The translation `x`: where the body frame's origin goes.
    pub translation: Vec3<T>,
}

impl<T: Float> Pose<T> {
    /// The identity placement (`R = I`, `x = 0`).
    pub const IDENTITY: Self = Self {
        rotation: [
            [T::ONE, T::ZERO, T::ZERO],
            [T::ZERO, T::ONE, T::ZERO],
            [T::ZERO, T::ZERO, T::ONE],
        ],
        translation: Vec3::ZERO,
    };

    /// A pose from a row-major rotation matrix and a translation.
    #[inline]
    #[must_use]
    pub const fn new(rotation: [[T; 3]; 3], translation: Vec3<T>) -> Self {
        Self {
            rotation,
            translation,
        }
    }

    /// A pure translation (`R = I`).
    ///
    /// ```
    /// use motion_bound::{Pose, Vec3};
    /// let pose = Pose::from_translation(Vec3::new(1.0f32, 2.0, 3.0));
    /// assert_eq!(pose.transform_point(Vec3::ZERO), Vec3::new(1.0, 2.0, 3.0));
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_translation(translation: Vec3<T>) -> Self {
        Self {
            rotation: Self::IDENTITY.rotation,
            translation,
        }
    }

    /// `R p + x`: a body point in the world frame. The point is any
    /// `Into<Vec3>`: a [`Vec3`], or a vertex as stored, `[T; 3]`.
    ///
    /// ```
    /// use motion_bound::{Pose, Vec3};
    /// let pose = Pose::from_translation(Vec3::new(0.0, 1.0, 0.0));
    /// let vertices = [[1.0, 0.0, 0.0], [0.0, 0.0, 2.0]];
    /// assert_eq!(pose.transform_point(vertices[1]), Vec3::new(0.0, 1.0, 2.0));
    /// ```
    #[inline]
    #[must_use]
    pub fn transform_point(&self, p: impl Into<Vec3<T>>) -> Vec3<T> {
        self.transform_vector(p.into()) + self.translation
    }

    /// `R v`: a free vector (a direction, a velocity) in the world frame.
    #[inline]
    #[must_use]
    pub fn transform_vector(&self, v: Vec3<T>) -> Vec3<T> {
        mat_vec(&self.rotation, v)
    }

    /// `R^T v`: a world vector in the body frame (the inverse of
    /// [`transform_vector`](Self::transform_vector) when `R` is a rotation).
    #[inline]
    #[must_use]
    pub fn inverse_transform_vector(&self, v: Vec3<T>) -> Vec3<T> {
        mat_t_vec(&self.rotation, v)
    }

    /// The largest absolute entry of `R` (what the rounding error bounds of
    /// the maps above scale with).
    #[inline]
    #[must_use]
    pub fn rotation_max_abs(&self) -> T {
        let r = &self.rotation;
        Vec3::from_array(r[0])
            .max_abs()
            .max_nan(Vec3::from_array(r[1]).max_abs())
            .max_nan(Vec3::from_array(r[2]).max_abs())
    }

    /// `true` if every entry of `R` and `x` is finite.
    #[inline]
    #[must_use]
    pub fn is_finite(&self) -> bool {
        self.rotation
            .iter()
            .all(|row| Vec3::from_array(*row).is_finite())
            && self.translation.is_finite()
    }
}

/// `M v` for a row-major `M`, each entry a dot product left to right (the
/// order the error analysis assumes: three products, two sums).
#[inline]
pub(crate) fn mat_vec<T: Float>(m: &[[T; 3]; 3], v: Vec3<T>) -> Vec3<T> {
    Vec3::new(
        Vec3::from_array(m[0]).dot(v),
        Vec3::from_array(m[1]).dot(v),
        Vec3::from_array(m[2]).dot(v),
    )
}

/// `M^T v` for a row-major `M`, as [`mat_vec`].
#[inline]
pub(crate) fn mat_t_vec<T: Float>(m: &[[T; 3]; 3], v: Vec3<T>) -> Vec3<T> {
    Vec3::new(
        Vec3::new(m[0][0], m[1][0], m[2][0]).dot(v),
        Vec3::new(m[0][1], m[1][1], m[2][1]).dot(v),
        Vec3::new(m[0][2], m[1][2], m[2][2]).dot(v),
    )
}

/// `A B` for row-major matrices, each entry summed left to right.
pub(crate) fn mat_mul<T: Float>(a: &[[T; 3]; 3], b: &[[T; 3]; 3]) -> [[T; 3]; 3] {
    let mut out = [[T::ZERO; 3]; 3];
    for (i, row) in out.iter_mut().enumerate() {
        for (j, e) in row.iter_mut().enumerate() {
            *e = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
        }
    }
    out
}

impl<T: Float> Default for Pose<T> {
    #[inline]
    fn default() -> Self {
        Self::IDENTITY
    }
}

#[cfg(test)]
mod tests {
    use super::Pose;
    use crate::{rotate_about_axis, Vec3};

    #[test]
    fn matches_rodrigues_and_inverts() {
        let axis = Vec3::new(1.0f64, 2.0, -0.5).try_normalize().unwrap();
        let angle = 0.7;
        let cols = [
            rotate_about_axis(Vec3::new(1.0, 0.0, 0.0), axis, angle),
            rotate_about_axis(Vec3::new(0.0, 1.0, 0.0), axis, angle),
            rotate_about_axis(Vec3::new(0.0, 0.0, 1.0), axis, angle),
        ];
        let rotation = [
            [cols[0].x, cols[1].x, cols[2].x],
            [cols[0].y, cols[1].y, cols[2].y],
            [cols[0].z, cols[1].z, cols[2].z],
        ];
        let pose = Pose::new(rotation, Vec3::new(3.0, -1.0, 0.5));
        let p = Vec3::new(0.3, -0.2, 1.1);
        let expect = rotate_about_axis(p, axis, angle) + Vec3::new(3.0, -1.0, 0.5);
        assert!(
            (pose.transform_point(p) - expect).length() < 1e-14,
            "R p + x equals Rodrigues' rotation plus the shift"
        );
        let back = pose.inverse_transform_vector(pose.transform_vector(p));
        assert!((back - p).length() < 1e-14, "R^T R p = p");
        assert_eq!(
            pose.rotation_max_abs(),
            {
                let mut m = 0.0f64;
                for row in rotation {
                    for e in row {
                        m = m.max(e.abs());
                    }
                }
                m
            },
            "largest entry"
        );
    }

    #[test]
    fn identity_and_finiteness() {
        let p = Vec3::new(1.0f32, -2.0, 3.0);
        assert_eq!(Pose::IDENTITY.transform_point(p), p, "identity");
        assert_eq!(Pose::<f32>::default(), Pose::IDENTITY, "default");
        let mut bad = Pose::<f64>::IDENTITY;
        bad.rotation[1][2] = f64::NAN;
        assert!(!bad.is_finite(), "NaN entry detected");
        assert!(Pose::<f64>::IDENTITY.is_finite(), "identity is finite");
    }
}
