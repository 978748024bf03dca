//! Positions: world points and body points.

use core::ops::{Add, Sub};

use crate::{Float, Vec3};

/// A position in the world frame.
///
/// Points and free vectors share a layout but not their operations: two
/// points can be subtracted (giving a [`Vec3`]) but not added.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Point3<T> {
    /// The x coordinate.
    pub x: T,
    /// The y coordinate.
    pub y: T,
    /// The z coordinate.
    pub z: T,
}

impl<T: Float> Point3<T> {
    /// The origin.
    pub const ORIGIN: Self = Self {
        x: T::ZERO,
        y: T::ZERO,
        z: T::ZERO,
    };

    /// A point from its coordinates.
    #[inline]
    #[must_use]
    pub const fn new(x: T, y: T, z: T) -> Self {
        Self { x, y, z }
    }

    /// A point from a plain array.
    #[inline]
    #[must_use]
    pub const fn from_array(a: [T; 3]) -> Self {
        Self::new(a[0], a[1], a[2])
    }

    /// The coordinates as a plain array.
    #[inline]
    #[must_use]
    pub const fn to_array(self) -> [T; 3] {
        [self.x, self.y, self.z]
    }

    /// The point at the tip of `v` from the origin.
    #[inline]
    #[must_use]
    pub const fn from_vec3(v: Vec3<T>) -> Self {
        Self::new(v.x, v.y, v.z)
    }

    /// The vector from the origin to this point.
    #[inline]
    #[must_use]
    pub const fn to_vec3(self) -> Vec3<T> {
        Vec3::new(self.x, self.y, self.z)
    }

    /// `true` if every coordinate is finite.
    #[inline]
    #[must_use]
    pub fn is_finite(self) -> bool {
        self.to_vec3().is_finite()
    }
}

impl<T: Float> Add<Vec3<T>> for Point3<T> {
    type Output = Self;
    #[inline]
    fn add(self, v: Vec3<T>) -> Self {
        Self::new(self.x + v.x, self.y + v.y, self.z + v.z)
    }
}

impl<T: Float> Sub<Vec3<T>> for Point3<T> {
    type Output = Self;
    #[inline]
    fn sub(self, v: Vec3<T>) -> Self {
        Self::new(self.x - v.x, self.y - v.y, self.z - v.z)
    }
}

impl<T: Float> Sub for Point3<T> {
    type Output = Vec3<T>;
    #[inline]
    fn sub(self, o: Self) -> Vec3<T> {
        Vec3::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl<T: Float> From<[T; 3]> for Point3<T> {
    #[inline]
    fn from(a: [T; 3]) -> Self {
        Self::from_array(a)
    }
}

impl<T: Float> From<Point3<T>> for [T; 3] {
    #[inline]
    fn from(p: Point3<T>) -> Self {
        p.to_array()
    }
}

/// A point of a rigid body given relative to the body's rotation centre at
/// the epoch `t = 0`: the `r_i` of the seed, with `r_i(t) = R(t) r_i`.
///
/// Vertex sets are passed as slices of plain `[T; 3]` arrays for zero-copy
/// interop; each array is read as a `BodyPoint`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BodyPoint<T> {
    /// The x offset from the rotation centre.
    pub x: T,
    /// The y offset from the rotation centre.
    pub y: T,
    /// The z offset from the rotation centre.
    pub z: T,
}

impl<T: Float> BodyPoint<T> {
    /// A body point from its offsets.
    #[inline]
    #[must_use]
    pub const fn new(x: T, y: T, z: T) -> Self {
        Self { x, y, z }
    }

    /// A body point from a plain array.
    #[inline]
    #[must_use]
    pub const fn from_array(a: [T; 3]) -> Self {
        Self::new(a[0], a[1], a[2])
    }

    /// The offsets as a plain array.
    #[inline]
    #[must_use]
    pub const fn to_array(self) -> [T; 3] {
        [self.x, self.y, self.z]
    }

    /// The lever arm from the rotation centre as a free vector.
    #[inline]
    #[must_use]
    pub const fn arm(self) -> Vec3<T> {
        Vec3::new(self.x, self.y, self.z)
    }
}

impl<T: Float> From<[T; 3]> for BodyPoint<T> {
    #[inline]
    fn from(a: [T; 3]) -> Self {
        Self::from_array(a)
    }
}

impl<T: Float> From<BodyPoint<T>> for [T; 3] {
    #[inline]
    fn from(p: BodyPoint<T>) -> Self {
        p.to_array()
    }
}

#[cfg(test)]
mod tests {
    use super::{Point3, Vec3};

    #[test]
    fn points_differ_by_vectors() {
        let a = Point3::new(1.0, 2.0, 3.0);
        let b = a + Vec3::new(0.5, 0.5, 0.5);
        assert_eq!(b - a, Vec3::new(0.5, 0.5, 0.5), "round trip");
        assert_eq!(b - Vec3::new(0.5, 0.5, 0.5), a, "sub vector");
    }
}
