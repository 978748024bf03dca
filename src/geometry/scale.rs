//! Exact power-of-two rescaling of small point sets.
//!
//! The closest-point and intersection routines multiply up to three
//! coordinate differences (`orient3d`), which would overflow for coordinates
//! near `T::MAX` and underflow for tiny ones. Multiplying every coordinate by
//! one power of two is exact (away from the subnormal range) and commutes
//! with rounding, so the routines run on coordinates of magnitude about 1 and
//! their results are scaled back bit for bit.

use crate::{Float, Vec3};

/// The binary exponent `e` of a positive finite value, `2^e <= x < 2^(e+1)`
/// (subnormal `f64` values report `-1023`).
fn exponent<T: Float>(x: T) -> i32 {
    // The shift leaves the 11 exponent bits; they fit an `i32`.
    let biased = ((x.to_f64().to_bits() >> 52) & 0x7ff) as i32;
    biased - 1023
}

/// `2^k` for `|k| <= k_max::<T>()`: exactly representable in `T`.
fn pow2<T: Float>(k: i32) -> T {
    // `k + 1023` lies in `1..=2046` for the clamped `k`, a normal f64 exponent.
    let biased = (k + 1023).clamp(1, 2046) as u64;
    T::from_f64(f64::from_bits(biased << 52))
}

/// The largest `|k|` used: `2 log2(MAX_INPUT)` (1014 for `f64`, 118 for
/// `f32`), below the exponent range of either type.
fn k_max<T: Float>() -> i32 {
    2 * exponent(T::MAX_INPUT)
}

/// A power-of-two scale `s = 2^k` chosen so that the largest absolute
/// coordinate `m` of a point set maps into `[1, 2)` (or as near as the
/// clamp `|k| <= k_max` allows).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Scale<T> {
    down: T,
    up: T,
}

impl<T: Float> Scale<T> {
    /// The scale for these points; the identity when they are all zero or
    /// any coordinate is not finite.
    pub(crate) fn for_points(points: &[Vec3<T>]) -> Self {
        let mut m = T::ZERO;
        for p in points {
            m = m.max_nan(p.max_abs());
        }
        if !(m > T::ZERO) || !m.is_finite() {
            return Self {
                down: T::ONE,
                up: T::ONE,
            };
        }
        let k = (-exponent(m)).clamp(-k_max::<T>(), k_max::<T>());
        Self {
            down: pow2(k),
            up: pow2(-k),
        }
    }

    /// A point in scaled coordinates.
    #[inline]
    pub(crate) fn apply(&self, p: Vec3<T>) -> Vec3<T> {
        p * self.down
    }

    /// A point back in the caller's coordinates.
    #[inline]
    pub(crate) fn undo(&self, p: Vec3<T>) -> Vec3<T> {
        p * self.up
    }

    /// A length back in the caller's units.
    #[inline]
    pub(crate) fn undo_length(&self, d: T) -> T {
        d * self.up
    }
}

#[cfg(test)]
mod tests {
    use super::Scale;
    use crate::Vec3;

    #[test]
    fn maps_the_largest_coordinate_into_one_two() {
        for m in [1e-300f64, 3e-20, 0.7, 1.0, 5.0, 1e200] {
            let s = Scale::for_points(&[Vec3::new(0.25 * m, -m, 0.0)]);
            let y = s.apply(Vec3::new(0.0, -m, 0.0)).y.abs();
            assert!((1.0..2.0).contains(&y), "m = {m}: scaled to {y}");
            assert_eq!(
                s.undo(s.apply(Vec3::new(0.25 * m, -m, 0.0))).x,
                0.25 * m,
                "exact round trip"
            );
        }
        // Beyond the clamp `|k| <= 2 log2(MAX_INPUT)` the range is wider but
        // still far from overflow and underflow.
        let s = Scale::for_points(&[Vec3::new(f64::MAX, 0.0, 0.0)]);
        assert!(
            s.apply(Vec3::new(f64::MAX, 0.0, 0.0)).x < 2048.0,
            "f64::MAX"
        );
        for m in [1e-30f32, 1.0, 3e30, f32::MAX, f32::from_bits(1)] {
            let s = Scale::for_points(&[Vec3::new(m, 0.0, 0.0)]);
            let y = s.apply(Vec3::new(m, 0.0, 0.0)).x;
            assert!(y > 1e-10 && y < 2048.0, "f32 m = {m}: scaled to {y}");
        }
    }

    #[test]
    fn identity_for_zero_and_non_finite() {
        let s = Scale::for_points(&[Vec3::<f64>::ZERO]);
        assert_eq!(s.undo_length(3.0), 3.0, "zero set");
        let s = Scale::for_points(&[Vec3::new(f64::NAN, 1.0, 1.0)]);
        assert_eq!(s.undo_length(3.0), 3.0, "NaN set");
    }
}
