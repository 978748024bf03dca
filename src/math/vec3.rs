//! Free vectors in 3D: velocities, angular velocities, displacements.

use core::ops::{Add, Mul, Neg, Sub};

use crate::Float;

/// A free vector in 3D (a velocity, an angular velocity, a displacement).
///
/// A free vector has no position: it is what [`Point3`](crate::Point3)s differ
/// by. Arithmetic is plain IEEE arithmetic in the written order, which is the
/// order the error analysis of `proofs/floating-point.md` assumes.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Vec3<T> {
    /// The x component.
    pub x: T,
    /// The y component.
    pub y: T,
    /// The z component.
    pub z: T,
}

impl<T: Float> Vec3<T> {
    /// The zero vector.
    pub const ZERO: Self = Self {
        x: T::ZERO,
        y: T::ZERO,
        z: T::ZERO,
    };

    /// A vector from its components.
    #[inline]
    #[must_use]
    pub const fn new(x: T, y: T, z: T) -> Self {
        Self { x, y, z }
    }

    /// A vector from a plain array `[x, y, z]`.
    ///
    /// ```
    /// use motion_bound::Vec3;
    /// assert_eq!(Vec3::from_array([1.0, 2.0, 3.0]).y, 2.0);
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_array(a: [T; 3]) -> Self {
        Self {
            x: a[0],
            y: a[1],
            z: a[2],
        }
    }

    /// The components as a plain array `[x, y, z]`.
    #[inline]
    #[must_use]
    pub const fn to_array(self) -> [T; 3] {
        [self.x, self.y, self.z]
    }

    /// The dot product, evaluated as `(x*x' + y*y') + z*z'`.
    #[inline]
    #[must_use]
    pub fn dot(self, o: Self) -> T {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// `sum |x_k * x'_k|` in the same order as [`dot`](Self::dot): the
    /// magnitude that bounds the rounding error of the dot product
    /// (`|fl(a.b) - a.b| <= gamma_3 * sum |a_k b_k|`).
    #[inline]
    #[must_use]
    pub fn dot_abs(self, o: Self) -> T {
        (self.x * o.x).abs() + (self.y * o.y).abs() + (self.z * o.z).abs()
    }

    /// The cross product `self x o`.
    #[inline]
    #[must_use]
    pub fn cross(self, o: Self) -> Self {
        Self {
            x: self.y * o.z - self.z * o.y,
            y: self.z * o.x - self.x * o.z,
            z: self.x * o.y - self.y * o.x,
        }
    }

    /// The squared Euclidean length.
    #[inline]
    #[must_use]
    pub fn length_squared(self) -> T {
        self.dot(self)
    }

    /// The Euclidean length.
    #[inline]
    #[must_use]
    pub fn length(self) -> T {
        self.length_squared().sqrt()
    }

    /// The 1-norm `|x| + |y| + |z|`, an upper bound of the length that needs
    /// no square root.
    #[inline]
    #[must_use]
    pub fn norm_l1(self) -> T {
        self.x.abs() + self.y.abs() + self.z.abs()
    }

    /// The largest absolute component.
    #[inline]
    #[must_use]
    pub fn max_abs(self) -> T {
        self.x.abs().max_nan(self.y.abs()).max_nan(self.z.abs())
    }

    /// `true` if every component is finite.
    #[inline]
    #[must_use]
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.z.is_finite()
    }

    /// The squared distance `|o - self|^2` between two position vectors.
    ///
    /// ```
    /// use motion_bound::Vec3;
    /// assert_eq!(Vec3::new(1.0, 2.0, 2.0).distance_squared(Vec3::ZERO), 9.0);
    /// ```
    #[inline]
    #[must_use]
    pub fn distance_squared(self, o: Self) -> T {
        (o - self).length_squared()
    }

    /// The point `self + (o - self) t` of the line through `self` and `o`
    /// (`t = 0` gives `self`; `t = 1` gives `o` up to rounding).
    ///
    /// ```
    /// use motion_bound::Vec3;
    /// let m = Vec3::new(0.0, 0.0, 0.0).lerp(Vec3::new(2.0, 4.0, -6.0), 0.5);
    /// assert_eq!(m, Vec3::new(1.0, 2.0, -3.0));
    /// ```
    #[inline]
    #[must_use]
    pub fn lerp(self, o: Self, t: T) -> Self {
        self + (o - self) * t
    }

    /// The vector scaled to unit length, or `None` when its length is zero or
    /// not finite (glam's `try_normalize`).
    #[inline]
    #[must_use]
    pub fn try_normalize(self) -> Option<Self> {
        let len = self.length();
        if len > T::ZERO && len.is_finite() {
            Some(self * (T::ONE / len))
        } else {
            None
        }
    }

    /// The vector scaled to unit length, or `fallback` when that is impossible.
    #[inline]
    #[must_use]
    pub fn normalize_or(self, fallback: Self) -> Self {
        self.try_normalize().unwrap_or(fallback)
    }
}

impl<T: Float> Add for Vec3<T> {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        Self::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl<T: Float> Sub for Vec3<T> {
    type Output = Self;
    #[inline]
    fn sub(self, o: Self) -> Self {
        Self::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl<T: Float> Neg for Vec3<T> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self::new(-self.x, -self.y, -self.z)
    }
}

impl<T: Float> Mul<T> for Vec3<T> {
    type Output = Self;
    #[inline]
    fn mul(self, s: T) -> Self {
        Self::new(self.x * s, self.y * s, self.z * s)
    }
}

impl<T: Float> From<[T; 3]> for Vec3<T> {
    #[inline]
    fn from(a: [T; 3]) -> Self {
        Self::from_array(a)
    }
}

impl<T: Float> From<Vec3<T>> for [T; 3] {
    #[inline]
    fn from(v: Vec3<T>) -> Self {
        v.to_array()
    }
}

#[cfg(test)]
mod tests {
    use super::Vec3;

    #[test]
    fn cross_is_right_handed_and_orthogonal() {
        let x = Vec3::new(1.0, 0.0, 0.0);
        let y = Vec3::new(0.0, 1.0, 0.0);
        assert_eq!(x.cross(y), Vec3::new(0.0, 0.0, 1.0), "x cross y = z");
        let a = Vec3::new(0.3f64, -1.7, 2.2);
        let b = Vec3::new(-4.0, 0.5, 1.25);
        let c = a.cross(b);
        assert!(
            c.dot(a).abs() < 1e-14 && c.dot(b).abs() < 1e-14,
            "orthogonal"
        );
    }

    #[test]
    fn normalize_edge_cases() {
        assert!(Vec3::<f64>::ZERO.try_normalize().is_none(), "zero");
        assert!(
            Vec3::new(f64::NAN, 0.0, 0.0).try_normalize().is_none(),
            "NaN"
        );
        let fallback = Vec3::new(0.0, 0.0, 1.0);
        assert_eq!(
            Vec3::<f32>::ZERO.normalize_or(fallback),
            fallback,
            "fallback"
        );
        let n = Vec3::new(3.0f64, 4.0, 0.0).try_normalize().unwrap();
        assert!((n.length() - 1.0).abs() < 1e-15, "unit");
    }
}
