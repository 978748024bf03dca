//! Rigid placements given as a rotation and a translation: a body's pose as
//! an engine hands it over.

use crate::error::{check_components, InputError, Quantity};
use crate::{Float, Point3, Pose, Rotation, Vec3};

/// A rigid placement `r |-> Q r + x` of a body frame in the world frame, with
/// `Q` a [`Rotation`] (a unit quaternion) and `x` where the body frame's
/// origin goes: a body's pose at one instant, as a caller gives it (checked
/// on construction). The crate evaluates it as a [`Pose`] (a matrix) for
/// its hot loops: [`to_pose`](Self::to_pose).
///
/// ```
/// use motion_bound::{Isometry, Point3, Rotation, Vec3};
/// let turn = Rotation::try_from_axis_angle(Vec3::new(0.0, 0.0, 1.0), core::f64::consts::FRAC_PI_2)?;
/// let pose = Isometry::try_new(turn, Vec3::new(1.0, 0.0, 0.0))?;
/// let p = pose.transform_point(Point3::new(1.0, 0.0, 0.0));
/// assert!((p - Point3::new(1.0, 1.0, 0.0)).length() < 1e-15);
/// # Ok::<(), motion_bound::InputError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Isometry<T> {
    rotation: Rotation<T>,
    translation: Vec3<T>,
}

impl<T: Float> Isometry<T> {
    /// The identity placement.
    pub const IDENTITY: Self = Self {
        rotation: Rotation::IDENTITY,
        translation: Vec3::ZERO,
    };

    /// The placement by `rotation`, then `translation`.
    ///
    /// # Errors
    /// [`InputError::NonFinite`] or [`InputError::TooLarge`] with
    /// [`Quantity::Pose`] for a translation that is not finite or beyond
    /// [`Float::MAX_INPUT`].
    pub fn try_new(rotation: Rotation<T>, translation: Vec3<T>) -> Result<Self, InputError> {
        check_components(translation.to_array(), Quantity::Pose)?;
        Ok(Self {
            rotation,
            translation,
        })
    }

    /// A pure translation.
    ///
    /// # Errors
    /// As [`try_new`](Self::try_new).
    pub fn try_from_translation(translation: Vec3<T>) -> Result<Self, InputError> {
        Self::try_new(Rotation::IDENTITY, translation)
    }

    /// The rotation `Q`.
    #[inline]
    #[must_use]
    pub const fn rotation(&self) -> Rotation<T> {
        self.rotation
    }

    /// The translation `x`.
    #[inline]
    #[must_use]
    pub const fn translation(&self) -> Vec3<T> {
        self.translation
    }

    /// `Q r + x` for a body point `r` (in the body frame): a [`Point3`] or
    /// a vertex as stored, `[T; 3]`.
    #[inline]
    #[must_use]
    pub fn transform_point(&self, r: impl Into<Point3<T>>) -> Point3<T> {
        Point3::from_vec3(self.rotation.rotate(r.into().to_vec3()) + self.translation)
    }

    /// The same placement as a [`Pose`] (matrix and translation).
    #[inline]
    #[must_use]
    pub const fn to_pose(&self) -> Pose<T> {
        Pose::new(self.rotation.matrix(), self.translation)
    }
}

impl<T: Float> Default for Isometry<T> {
    #[inline]
    fn default() -> Self {
        Self::IDENTITY
    }
}
