//! Unit directions: the closest direction `n` of a conservative-advancement step.

use core::ops::Neg;

use crate::error::{InputError, Quantity};
use crate::{Float, Vec3};

/// A unit vector: the direction `n` along which a bound measures motion.
///
/// A `Direction` is always the normalisation of a finite, nonzero vector, so
/// its length is `1` up to rounding: `| |n| - 1 | <= gamma_5` (see
/// `proofs/floating-point.md`, section "Direction"). Every bound of this
/// crate bounds motion along the exact unit vector `n / |n|` of the stored
/// components, and absorbs that factor in its rounding margin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Direction<T>(Vec3<T>);

impl<T: Float> Direction<T> {
    /// The unit x axis.
    pub const X: Self = Self(Vec3::new(T::ONE, T::ZERO, T::ZERO));
    /// The unit y axis.
    pub const Y: Self = Self(Vec3::new(T::ZERO, T::ONE, T::ZERO));
    /// The unit z axis.
    pub const Z: Self = Self(Vec3::new(T::ZERO, T::ZERO, T::ONE));

    /// The direction of `v`, normalised.
    ///
    /// Any finite nonzero vector is accepted, however long or short: it is
    /// first divided by its largest component (so neither the squares
    /// overflow nor the tiny ones vanish), then by its length.
    ///
    /// # Errors
    /// [`InputError::NonFinite`] for NaN or infinite components,
    /// [`InputError::ZeroDirection`] for the zero vector.
    ///
    /// ```
    /// use motion_bound::{Direction, InputError, Vec3};
    /// let n = Direction::try_new(Vec3::new(0.0, 3.0, 4.0)).unwrap();
    /// assert_eq!(n.get().to_array(), [0.0, 0.6, 0.8]);
    /// assert_eq!(Direction::try_new(Vec3::<f64>::ZERO), Err(InputError::ZeroDirection));
    /// ```
    pub fn try_new(v: Vec3<T>) -> Result<Self, InputError> {
        if !v.is_finite() {
            return Err(InputError::NonFinite(Quantity::Direction));
        }
        let m = v.max_abs();
        if m == T::ZERO {
            return Err(InputError::ZeroDirection);
        }
        let s = Vec3::new(v.x / m, v.y / m, v.z / m);
        let len = s.length();
        Ok(Self(Vec3::new(s.x / len, s.y / len, s.z / len)))
    }

    /// As [`try_new`](Self::try_new), faster where `|v|^2` is a normal,
    /// finite number: one square root, one division and three products
    /// (`proofs/floating-point.md`, "Direction": same `gamma_5` guarantee).
    #[cfg(feature = "alloc")]
    #[inline]
    pub(crate) fn try_new_fast(v: Vec3<T>) -> Result<Self, InputError> {
        let q = v.length_squared();
        if q.is_finite() && q >= T::TINY_LENGTH * T::TINY_LENGTH {
            let r = T::ONE / q.sqrt();
            Ok(Self(Vec3::new(v.x * r, v.y * r, v.z * r)))
        } else {
            Self::try_new(v)
        }
    }

    /// A vector already normalised by [`Vec3::try_normalize`] from a vector
    /// whose squared length is a normal float: its length is within
    /// `gamma_5` of 1, the invariant of this type (the same argument as
    /// `try_new_fast`'s, `proofs/floating-point.md`, "Direction").
    #[inline]
    pub(crate) const fn from_normalized(v: Vec3<T>) -> Self {
        Self(v)
    }

    /// The direction of `v`, or `fallback` when `v` is zero or not finite.
    #[must_use]
    pub fn new_or(v: Vec3<T>, fallback: Self) -> Self {
        Self::try_new(v).unwrap_or(fallback)
    }

    /// The direction from plain components, normalised (see [`try_new`](Self::try_new)).
    ///
    /// # Errors
    /// As [`try_new`](Self::try_new).
    pub fn try_from_array(a: [T; 3]) -> Result<Self, InputError> {
        Self::try_new(Vec3::from_array(a))
    }

    /// The unit vector.
    #[inline]
    #[must_use]
    pub const fn get(self) -> Vec3<T> {
        self.0
    }

    /// The components as a plain array.
    #[inline]
    #[must_use]
    pub const fn to_array(self) -> [T; 3] {
        self.0.to_array()
    }
}

impl<T: Float> Neg for Direction<T> {
    type Output = Self;
    /// The opposite direction (exact: only signs change).
    #[inline]
    fn neg(self) -> Self {
        Self(-self.0)
    }
}

impl<T: Float> TryFrom<Vec3<T>> for Direction<T> {
    type Error = InputError;
    fn try_from(v: Vec3<T>) -> Result<Self, InputError> {
        Self::try_new(v)
    }
}

#[cfg(test)]
mod tests {
    use super::Direction;
    use crate::{InputError, Quantity, Vec3};

    #[test]
    fn extreme_magnitudes_normalise_without_overflow_or_underflow() {
        for scale in [f64::MAX, 1e300, 1.0, 1e-300, 5e-324] {
            let n = Direction::try_new(Vec3::new(scale, scale, 0.0)).unwrap();
            assert!(
                (n.get().length() - 1.0).abs() < 4.0 * f64::EPSILON,
                "scale {scale}"
            );
        }
        let n = Direction::try_new(Vec3::new(f32::MAX, -f32::MAX, f32::MAX)).unwrap();
        assert!(
            (n.get().length() - 1.0).abs() < 4.0 * f32::EPSILON,
            "f32 max"
        );
    }

    #[test]
    fn bad_input_is_a_typed_error() {
        assert_eq!(
            Direction::try_new(Vec3::new(f64::NAN, 1.0, 0.0)),
            Err(InputError::NonFinite(Quantity::Direction)),
            "NaN"
        );
        assert_eq!(
            Direction::try_new(Vec3::new(0.0, f32::INFINITY, 0.0)),
            Err(InputError::NonFinite(Quantity::Direction)),
            "inf"
        );
        assert_eq!(
            Direction::try_new(Vec3::new(-0.0, 0.0, 0.0)),
            Err(InputError::ZeroDirection),
            "-0"
        );
        assert_eq!(
            Direction::new_or(Vec3::<f64>::ZERO, Direction::Z),
            Direction::Z,
            "fallback"
        );
    }
}
