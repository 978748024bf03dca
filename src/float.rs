//! The sealed scalar trait implemented by `f32` and `f64`.
//!
//! One generic code path serves both precisions, so every error bound in
//! `proofs/floating-point.md` is written once, in terms of the unit roundoff
//! [`Float::UNIT_ROUNDOFF`] of the type at hand. The transcendental functions
//! map to `std` when the `std` feature is on and to `libm` otherwise.

use core::fmt::{Debug, Display};
use core::ops::{Add, AddAssign, Div, Mul, MulAssign, Neg, Sub, SubAssign};

mod sealed {
    pub trait Sealed {}
    impl Sealed for f32 {}
    impl Sealed for f64 {}
}

/// A binary IEEE 754 floating-point type: `f32` or `f64`.
///
/// The trait is sealed: the error analysis of `proofs/floating-point.md`
/// assumes round-to-nearest binary arithmetic with the constants below, so no
/// other type may implement it.
pub trait Float:
    sealed::Sealed
    + Copy
    + Default
    + Debug
    + Display
    + PartialEq
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + AddAssign
    + SubAssign
    + MulAssign
    + Send
    + Sync
    + 'static
{
    /// `0`.
    const ZERO: Self;
    /// `1`.
    const ONE: Self;
    /// `2`.
    const TWO: Self;
    /// `1/2`.
    const HALF: Self;
    /// The `Self` value nearest to pi.
    const PI: Self;
    /// Positive infinity: the sound answer when a bound overflows.
    const INFINITY: Self;
    /// The unit roundoff `u = 2^-p` (`2^-53` for `f64`, `2^-24` for `f32`):
    /// half of [`f64::EPSILON`]. Every rounding margin is a formula in `u`.
    const UNIT_ROUNDOFF: Self;
    /// The smallest positive subnormal `eta` (`2^-1074`, `2^-149`): the absolute
    /// error of a product that underflows is at most `eta / 2`.
    const ETA: Self;
    /// The smallest positive normal number (`2^-1022`, `2^-126`): what every
    /// absolute underflow allowance of the rounding margins is written in
    /// instead of `eta` (a larger allowance is still an upper bound,
    /// `proofs/floating-point.md`, "Model"), so that no margin is ever
    /// computed in subnormal arithmetic, which costs tens of times a normal
    /// operation on common hardware.
    const ETA_NORMAL: Self;
    /// An upper bound of `sqrt(eta)` (`2^-537`, `2^-74`): what a square that
    /// underflows can hide in its square root.
    const SQRT_ETA_UP: Self;
    /// The largest magnitude accepted for any input coordinate, velocity
    /// component or time: `2^(emax/2 - 4)` (`2^507` for `f64`, `2^59` for
    /// `f32`). Below it no intermediate of the bounds can overflow
    /// (`proofs/floating-point.md`, section "Range").
    const MAX_INPUT: Self;
    /// `2^-(emin/2)` rounded to a power of two (`2^-510` for `f64`, `2^-62`
    /// for `f32`): below this a length's square is subnormal and its square
    /// root loses relative accuracy, so normalising by it is not trusted.
    const TINY_LENGTH: Self;

    /// Conversion from an `f64` constant (rounded to nearest for `f32`).
    fn from_f64(x: f64) -> Self;
    /// Exact widening to `f64`.
    fn to_f64(self) -> f64;
    /// Exact conversion of a small integer.
    fn from_u32(x: u32) -> Self;
    /// Absolute value.
    fn abs(self) -> Self;
    /// Correctly rounded square root.
    fn sqrt(self) -> Self;
    /// Sine (assumed within 2 ulps; see `proofs/floating-point.md`).
    fn sin(self) -> Self;
    /// Cosine (assumed within 2 ulps).
    fn cos(self) -> Self;
    /// Four-quadrant arctangent (used only by the reference).
    fn atan2(self, x: Self) -> Self;
    /// Arc cosine (used only by the reference).
    fn acos(self) -> Self;
    /// Largest integer not above `self`.
    fn floor(self) -> Self;
    /// `true` for neither infinite nor NaN.
    fn is_finite(self) -> bool;
    /// `true` for NaN.
    fn is_nan(self) -> bool;
    /// The largest representable value below `self` (IEEE `nextDown`; NaN
    /// stays NaN, `-inf` stays `-inf`).
    fn next_down(self) -> Self;
    /// The least representable value above `self` (IEEE `nextUp`; NaN stays
    /// NaN, `+inf` stays `+inf`).
    fn next_up(self) -> Self;

    /// The larger of two numbers; NaN if either is NaN (unlike `f64::max`,
    /// which would silently drop a NaN and could hide an unsound value).
    #[inline]
    #[must_use]
    fn max_nan(self, other: Self) -> Self {
        if self.is_nan() || other.is_nan() {
            self + other
        } else if self >= other {
            self
        } else {
            other
        }
    }

    /// The smaller of two numbers; NaN if either is NaN.
    #[inline]
    #[must_use]
    fn min_nan(self, other: Self) -> Self {
        if self.is_nan() || other.is_nan() {
            self + other
        } else if self <= other {
            self
        } else {
            other
        }
    }
}

macro_rules! impl_float {
    ($t:ident, $libm_sqrt:ident, $libm_sin:ident, $libm_cos:ident, $libm_atan2:ident,
     $libm_acos:ident, $libm_floor:ident, $u:expr, $eta:expr, $sqrt_eta:expr, $max:expr, $tiny:expr) => {
        impl Float for $t {
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const TWO: Self = 2.0;
            const HALF: Self = 0.5;
            const PI: Self = core::$t::consts::PI;
            const INFINITY: Self = $t::INFINITY;
            const UNIT_ROUNDOFF: Self = $u;
            const ETA: Self = $eta;
            const ETA_NORMAL: Self = $t::MIN_POSITIVE;
            const SQRT_ETA_UP: Self = $sqrt_eta;
            const MAX_INPUT: Self = $max;
            const TINY_LENGTH: Self = $tiny;

            #[inline]
            fn from_f64(x: f64) -> Self {
                x as $t
            }
            #[inline]
            fn to_f64(self) -> f64 {
                self as f64
            }
            #[inline]
            fn from_u32(x: u32) -> Self {
                x as $t
            }
            #[inline]
            fn abs(self) -> Self {
                $t::abs(self)
            }
            #[inline]
            fn is_finite(self) -> bool {
                $t::is_finite(self)
            }
            #[inline]
            fn is_nan(self) -> bool {
                $t::is_nan(self)
            }
            #[inline]
            fn next_down(self) -> Self {
                $t::next_down(self)
            }
            #[inline]
            fn next_up(self) -> Self {
                $t::next_up(self)
            }

            #[cfg(feature = "std")]
            #[inline]
            fn sqrt(self) -> Self {
                $t::sqrt(self)
            }
            #[cfg(feature = "std")]
            #[inline]
            fn sin(self) -> Self {
                $t::sin(self)
            }
            #[cfg(feature = "std")]
            #[inline]
            fn cos(self) -> Self {
                $t::cos(self)
            }
            #[cfg(feature = "std")]
            #[inline]
            fn atan2(self, x: Self) -> Self {
                $t::atan2(self, x)
            }
            #[cfg(feature = "std")]
            #[inline]
            fn acos(self) -> Self {
                $t::acos(self)
            }
            #[cfg(feature = "std")]
            #[inline]
            fn floor(self) -> Self {
                $t::floor(self)
            }

            #[cfg(not(feature = "std"))]
            #[inline]
            fn sqrt(self) -> Self {
                libm::$libm_sqrt(self)
            }
            #[cfg(not(feature = "std"))]
            #[inline]
            fn sin(self) -> Self {
                libm::$libm_sin(self)
            }
            #[cfg(not(feature = "std"))]
            #[inline]
            fn cos(self) -> Self {
                libm::$libm_cos(self)
            }
            #[cfg(not(feature = "std"))]
            #[inline]
            fn atan2(self, x: Self) -> Self {
                libm::$libm_atan2(self, x)
            }
            #[cfg(not(feature = "std"))]
            #[inline]
            fn acos(self) -> Self {
                libm::$libm_acos(self)
            }
            #[cfg(not(feature = "std"))]
            #[inline]
            fn floor(self) -> Self {
                libm::$libm_floor(self)
            }
        }
    };
}

impl_float!(
    f64,
    sqrt,
    sin,
    cos,
    atan2,
    acos,
    floor,
    f64::from_bits((1023 - 53) << 52),  // u = 2^-53
    f64::from_bits(1),                  // eta = 2^-1074
    f64::from_bits((1023 - 537) << 52), // 2^-537 = sqrt(2^-1074)
    f64::from_bits((1023 + 507) << 52), // 2^507
    f64::from_bits((1023 - 510) << 52)  // 2^-510
);
impl_float!(
    f32,
    sqrtf,
    sinf,
    cosf,
    atan2f,
    acosf,
    floorf,
    f32::from_bits((127 - 24) << 23), // u = 2^-24
    f32::from_bits(1),                // eta = 2^-149
    f32::from_bits((127 - 74) << 23), // 2^-74 >= sqrt(2^-149) = 2^-74.5
    f32::from_bits((127 + 59) << 23), // 2^59
    f32::from_bits((127 - 62) << 23)  // 2^-62
);

#[cfg(test)]
mod tests {
    use super::Float;

    #[test]
    fn constants_are_the_powers_of_two_they_claim() {
        assert_eq!(<f64 as Float>::UNIT_ROUNDOFF, 2f64.powi(-53), "f64 u");
        assert_eq!(<f32 as Float>::UNIT_ROUNDOFF, 2f32.powi(-24), "f32 u");
        assert_eq!(<f64 as Float>::ETA, f64::from_bits(1), "f64 eta");
        assert_eq!(<f32 as Float>::ETA, f32::from_bits(1), "f32 eta");
        assert_eq!(<f64 as Float>::SQRT_ETA_UP, 2f64.powi(-537), "f64 sqrt eta");
        assert_eq!(<f32 as Float>::SQRT_ETA_UP, 2f32.powi(-74), "f32 sqrt eta");
        assert_eq!(<f64 as Float>::MAX_INPUT, 2f64.powi(507), "f64 max input");
        assert_eq!(<f32 as Float>::MAX_INPUT, 2f32.powi(59), "f32 max input");
        assert_eq!(<f64 as Float>::TINY_LENGTH, 2f64.powi(-510), "f64 tiny");
        assert_eq!(<f32 as Float>::TINY_LENGTH, 2f32.powi(-62), "f32 tiny");
    }

    #[test]
    fn max_nan_propagates_nan_where_max_would_drop_it() {
        assert!(f64::NAN.max_nan(1.0).is_nan(), "NaN on the left");
        assert!(1.0f64.max_nan(f64::NAN).is_nan(), "NaN on the right");
        assert_eq!(f64::max(1.0, f64::NAN), 1.0, "std max drops NaN");
        assert_eq!(2.0f32.max_nan(1.0), 2.0, "ordinary max");
        assert_eq!(2.0f32.min_nan(1.0), 1.0, "ordinary min");
    }
}
