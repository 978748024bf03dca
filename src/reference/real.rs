//! The arithmetic the reference is evaluated in: the [`Real`] trait and its
//! `f64` implementation (the double-double one is in `dd`).

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
