//! The arithmetic the reference is evaluated in: the [`Real`] trait and its
//! `f64` and double-double implementations.

use crate::dd::DoubleDouble;
use crate::Float;

/// The arithmetic the reference is evaluated in.
pub trait Real: Copy + PartialOrd + core::fmt::Debug {
    /// Exact conversion from `f64`.
    fn from_f64(x: f64) -> Self;
    /// The nearest `f64`.
    fn to_f64(self) -> f64;
    /// `self + o`.
    fn add(self, o: Self) -> Self;
    /// `self - o`.
    fn sub(self, o: Self) -> Self;
    /// `self * o`.
    fn mul(self, o: Self) -> Self;
    /// `self / o`.
    fn div(self, o: Self) -> Self;
    /// Square root.
    fn sqrt(self) -> Self;
    /// Sine.
    fn sin(self) -> Self;
    /// Cosine.
    fn cos(self) -> Self;
    /// Four-quadrant arctangent `atan2(self, x)`.
    fn atan2(self, x: Self) -> Self;
    /// Arc cosine of a value in `[-1, 1]`.
    fn acos(self) -> Self;
    /// Largest integer not above.
    fn floor(self) -> Self;
    /// pi.
    fn pi() -> Self;
    /// Absolute value.
    fn abs(self) -> Self {
        if self < Self::from_f64(0.0) {
            Self::from_f64(0.0).sub(self)
        } else {
            self
        }
    }
    /// The larger value.
    fn max(self, o: Self) -> Self {
        if o > self {
            o
        } else {
            self
        }
    }
}

impl Real for f64 {
    fn from_f64(x: f64) -> Self {
        x
    }
    fn to_f64(self) -> f64 {
        self
    }
    fn add(self, o: Self) -> Self {
        self + o
    }
    fn sub(self, o: Self) -> Self {
        self - o
    }
    fn mul(self, o: Self) -> Self {
        self * o
    }
    fn div(self, o: Self) -> Self {
        self / o
    }
    fn sqrt(self) -> Self {
        Float::sqrt(self)
    }
    fn sin(self) -> Self {
        Float::sin(self)
    }
    fn cos(self) -> Self {
        Float::cos(self)
    }
    fn atan2(self, x: Self) -> Self {
        Float::atan2(self, x)
    }
    fn acos(self) -> Self {
        Float::acos(self.clamp(-1.0, 1.0))
    }
    fn floor(self) -> Self {
        Float::floor(self)
    }
    fn pi() -> Self {
        core::f64::consts::PI
    }
}

impl Real for DoubleDouble {
    fn from_f64(x: f64) -> Self {
        DoubleDouble::from_f64(x)
    }
    fn to_f64(self) -> f64 {
        DoubleDouble::to_f64(self)
    }
    fn add(self, o: Self) -> Self {
        self.add_dd(o)
    }
    fn sub(self, o: Self) -> Self {
        self.sub_dd(o)
    }
    fn mul(self, o: Self) -> Self {
        self.mul_dd(o)
    }
    fn div(self, o: Self) -> Self {
        self.div_dd(o)
    }
    fn sqrt(self) -> Self {
        DoubleDouble::sqrt(self)
    }
    fn sin(self) -> Self {
        DoubleDouble::sin(self)
    }
    fn cos(self) -> Self {
        DoubleDouble::cos(self)
    }
    fn atan2(self, x: Self) -> Self {
        DoubleDouble::atan2(self, x)
    }
    fn acos(self) -> Self {
        DoubleDouble::acos(self)
    }
    fn floor(self) -> Self {
        DoubleDouble::floor(self)
    }
    fn pi() -> Self {
        Self::PI
    }
    fn abs(self) -> Self {
        DoubleDouble::abs(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const U2: f64 = 1.232_595_164_407_831e-32; // 2^-106

    fn dd(hi: f64, lo: f64) -> DoubleDouble {
        DoubleDouble::new(hi, lo)
    }

    /// `|a - b|` as an `f64`.
    fn err(a: DoubleDouble, b: DoubleDouble) -> f64 {
        (a - b).abs().to_f64()
    }

    fn rel(a: DoubleDouble, b: DoubleDouble) -> f64 {
        err(a, b) / b.abs().to_f64()
    }

    /// The oracle only sees `Real`: a generic computation through it.
    fn hypot_angle<R: Real>(p: R, q: R) -> (R, R) {
        (p.mul(p).add(q.mul(q)).sqrt(), q.atan2(p))
    }

    #[test]
    fn the_real_impl_delegates() {
        let (b, phi) = hypot_angle(DoubleDouble::from_f64(3.0), DoubleDouble::from_f64(4.0));
        assert_eq!(b, DoubleDouble::from_f64(5.0), "hypot(3, 4)");
        // atan2(4, 3) from mpmath
        let want = dd(0.927_295_218_001_612_2, 4.539_755_490_592_337_4e-17);
        assert!(rel(phi, want) < 2.0 * U2, "atan2(4, 3) = {phi:?}");
        let x = <DoubleDouble as Real>::from_f64(-2.5);
        assert_eq!(Real::floor(x), DoubleDouble::from_f64(-3.0), "floor");
        assert_eq!(Real::abs(x), DoubleDouble::from_f64(2.5), "abs");
        assert_eq!(
            Real::to_f64(<DoubleDouble as Real>::pi()),
            core::f64::consts::PI,
            "pi"
        );
        assert_eq!(Real::to_f64(dd(1.0, 2f64.powi(-53))), 1.0, "to_f64 rounds");
        let h = <DoubleDouble as Real>::from_f64(0.5);
        assert!(
            err(
                Real::mul(Real::acos(h), DoubleDouble::from_f64(3.0)),
                DoubleDouble::PI
            ) < 1e-31,
            "acos"
        );
        assert!(
            err(
                Real::sin(Real::div(DoubleDouble::PI, DoubleDouble::from_f64(6.0))),
                h
            ) < 1e-31,
            "sin"
        );
        assert!(
            err(
                Real::cos(Real::div(DoubleDouble::PI, DoubleDouble::from_f64(3.0))),
                h
            ) < 1e-31,
            "cos"
        );
        assert!(
            Real::max(h, x) == h && Real::sub(h, x) == DoubleDouble::from_f64(3.0),
            "max, sub"
        );
    }
}
