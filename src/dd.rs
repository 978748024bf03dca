//! Double-double arithmetic: about 106 bits from two `f64`.
//!
//! A [`DoubleDouble`] is an unevaluated sum `hi + lo` of two `f64` with
//! `hi = RN(hi + lo)`, so `|lo| <= ulp(hi) / 2`. Writing `u = 2^-53` for the
//! unit roundoff of `f64`, it carries about `2 * 53 = 106` significant bits;
//! below, `u^2 = 2^-106 ~ 1.23e-32`. It serves two users: the oracle
//! (`reference`, the test support, which re-exports this module as
//! `reference::dd`), evaluated well beyond `f64` so that an `f64` bound is
//! checked *strictly* against it (an error of a few `u^2` cannot hide a
//! violation of an `f64` bound, whose own granularity is `u`); and a chain's
//! clearance, whose nearest pair's links are re-placed in it
//! (`chain/scene/refine.rs`, `proofs/13-chains.md`, Lemma 13.16).
//!
//! # Algorithms
//!
//! * **Error-free transformations**: [`two_sum`] (Knuth, six flops, no
//!   precondition), [`quick_two_sum`] (Dekker's Fast2Sum, needs
//!   `|a| >= |b|`), and [`two_prod`] (`p = RN(a b)`, `e = fma(a, b, -p)`,
//!   exact unless the product under- or overflows). With the `std` feature
//!   the fused multiply-add is `f64::mul_add`, without it `libm::fma`.
//! * **Add and subtract**: the accurate ("IEEE") double-double sum of the QD
//!   library, `AccurateDWPlusDW` of Joldes, Muller and Popescu (*Tight and
//!   rigorous error bounds for basic building blocks of double-word
//!   arithmetic*, ACM TOMS 44(2), 2017): relative error at most `3 u^2`.
//!   Mixed with an `f64`: `DWPlusFP`, at most `2 u^2`.
//! * **Multiply**: `DWTimesDW3` of the same paper (two fused multiply-adds),
//!   relative error at most `4 u^2`; by an `f64`: `DWTimesFP3`, `2 u^2`.
//! * **Divide**: QD's accurate division: three successive `f64` quotient
//!   digits, each computed from the exact-to-`u^2` remainder, renormalised.
//!   Measured relative error below `1.2 u^2`.
//! * **Square root**: one Newton (Heron) step from the `f64` root `q`:
//!   `q + (a - q^2) / (2 q)` with `q^2` exact by [`two_prod`]; relative
//!   error about `u^2`.
//! * **Floor**: exact.
//! * **Sine and cosine**: the argument is reduced as `x = k (pi/2) + r`,
//!   `k = round(x * 2/pi)`, with `pi/2` held to about 161 bits as three
//!   `f64` (`P1 + P2 + P3`), each product `k Pi` formed *exactly* by
//!   [`two_prod`] and subtracted in double-double (Cody and Waite's scheme
//!   with exact products, so that no bound on the bit length of `k` is
//!   needed for the products themselves). The reduced `|r| <= ~0.79` then
//!   feeds the Taylor series of `sin` or `cos`, summed in double-double
//!   until a term drops below `2^-110` of the leading term (at most 15
//!   terms); the tail is summed first and the leading term (`r` or `1`)
//!   added last. The quadrant `k mod 4` selects the sign and function.
//! * **atan2**: the `f64` `atan2` gives `z`; rotating `(x, y)` by `-z` leaves
//!   `(x cos z + y sin z, y cos z - x sin z)`, whose angle is the remaining
//!   error, so `z + atan(t)` with `t = (y cos z - x sin z) / (x cos z + y sin z)`
//!   is exact. One step with `atan(t) ~ t - t^3/3` suffices (`|t|` is about
//!   one `f64` ulp of `z`); a second step is taken only if the start was
//!   poor. `(x, y)` is first scaled by a power of two (exactly) so that
//!   neither the products overflow nor their error terms underflow.
//! * **acos**: `atan2(sqrt((1 - x)(1 + x)), x)` in double-double, with `x`
//!   clamped to `[-1, 1]`; the factored form keeps full relative accuracy
//!   near `x = +-1`.
//!
//! # Accuracy and range
//!
//! Measured against 400-bit `mpmath` on about 10,000 random double-double
//! arguments (worst case, in units of `u^2 = 2^-106 ~ 1.23e-32`); the unit
//! tests below check slightly looser bounds against stored `mpmath` values
//! and exact identities:
//!
//! | operation | worst error seen |
//! |---|---|
//! | `+`, `-` | 1.9 `u^2` relative |
//! | `*` | 2.3 `u^2` relative |
//! | `/` | 1.2 `u^2` relative |
//! | `sqrt` | 1.9 `u^2` relative |
//! | `sin`, `cos`, `\|x\| <= 2^50` | 1.4 `u^2` absolute (`1.7e-32`) |
//! | `atan2` | 2.1 `u^2` absolute, 2.0 `u^2` relative |
//! | `acos` | 2.0 `u^2` absolute, 2.6 `u^2` relative |
//!
//! The range of `sin` and `cos`:
//!
//! * **`|x| <= 2^50` (about `1.1e15`)**: full accuracy, absolute error below
//!   `2e-32` (the exact products `k Pi` make this hold far beyond the
//!   `|x| <= 1e6` the oracle needs). The reduction itself is
//!   accurate to about `2^-140` absolute for `|x| <= 1e6`, so results near a
//!   zero keep that *absolute* accuracy: `sin(PI)` comes out as
//!   `-2.99476980971834e-33`, right to 12 digits; a result of size `eps`
//!   has relative error about `2^-140 / eps`.
//! * **`2^50 < |x| < 2^80`**: the absolute error grows gracefully, roughly
//!   as `|x| 2^-160` (`4e-31` at `1.4e17`, `8e-28` at `1e21`, `4e-25` at
//!   `7e23`), from the 161-bit `pi/2` and the double-double remainder.
//! * **`|x| >= 2^80`**: `sin(hi + lo)` is assembled from the `f64` library's
//!   (correctly reduced) `sin`/`cos` of `hi` and of `lo`: `f64` accuracy,
//!   about `1e-16` absolute.
//! * Non-finite arguments give NaN. Nothing panics and every loop is bounded
//!   (at most 4 reduction passes, 64 series terms, 3 Newton steps).
//!
//! The `reference` feature implements the oracle's `Real` trait for
//! [`DoubleDouble`] (in `reference/real.rs`); its example is in
//! `reference::dd`'s documentation.

use core::cmp::Ordering;
use core::ops::{Add, Div, Mul, Neg, Sub};

use crate::Float;

/// `a * b + c` with a single rounding.
#[inline]
fn fma(a: f64, b: f64, c: f64) -> f64 {
    #[cfg(feature = "std")]
    {
        a.mul_add(b, c)
    }
    #[cfg(not(feature = "std"))]
    {
        libm::fma(a, b, c)
    }
}

/// Error-free sum: `(s, e)` with `s = RN(a + b)` and `s + e = a + b` exactly
/// (Knuth's TwoSum; no precondition, barring overflow).
#[must_use]
#[inline]
pub fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

/// Error-free sum for `|a| >= |b|` (or `a = 0`): `(s, e)` with
/// `s = RN(a + b)` and `s + e = a + b` exactly (Dekker's Fast2Sum).
#[must_use]
#[inline]
pub fn quick_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let e = b - (s - a);
    (s, e)
}

/// Error-free product: `(p, e)` with `p = RN(a b)` and `p + e = a b`
/// exactly, by one fused multiply-add, unless the product overflows or
/// `e` underflows (`|a b| < 2^-969` or so).
#[must_use]
#[inline]
pub fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let e = fma(a, b, -p);
    (p, e)
}

/// A double-double number: the unevaluated sum `hi + lo`, normalised so
/// that `hi = RN(hi + lo)` and hence `|lo| <= ulp(hi) / 2`.
///
/// The derived ordering compares `hi` and then `lo`, which for normalised
/// values is the ordering of the sums.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
pub struct DoubleDouble {
    /// The leading part, `RN(hi + lo)`.
    pub hi: f64,
    /// The trailing part, at most half an ulp of `hi`.
    pub lo: f64,
}

/// `pi/2 = P1 + P2 + P3` to about 161 bits (each the nearest `f64` of the
/// remainder).
const PIO2_1: f64 = core::f64::consts::FRAC_PI_2;
const PIO2_2: f64 = 6.123_233_995_736_766e-17;
const PIO2_3: f64 = -1.497_384_904_859_169_8e-33;

/// Arguments at least this large are reduced by the `f64` library instead.
const HUGE_ARG: f64 = 1_208_925_819_614_629_174_706_176.0; // 2^80

/// A Taylor term below this fraction of the sum ends the series.
const SERIES_EPS: f64 = 7.703_719_777_548_943e-34; // 2^-110

impl DoubleDouble {
    /// Zero.
    pub const ZERO: Self = Self { hi: 0.0, lo: 0.0 };
    /// One.
    pub const ONE: Self = Self { hi: 1.0, lo: 0.0 };
    /// pi, to about 2^-107 relative (`pi - PI ~ -3.0e-33`).
    pub const PI: Self = Self {
        hi: core::f64::consts::PI,
        lo: 1.224_646_799_147_353_2e-16,
    };
    /// pi/2, to about 2^-108 relative (`pi/2 - FRAC_PI_2 ~ -1.5e-33`).
    pub const FRAC_PI_2: Self = Self {
        hi: PIO2_1,
        lo: PIO2_2,
    };

    /// The sum `hi + lo` of any two finite `f64`, normalised.
    #[must_use]
    pub fn new(hi: f64, lo: f64) -> Self {
        let (hi, lo) = two_sum(hi, lo);
        Self::from_parts(hi, lo)
    }

    /// The exact value `x` (`lo = 0`).
    #[must_use]
    pub const fn from_f64(x: f64) -> Self {
        Self { hi: x, lo: 0.0 }
    }

    /// The nearest `f64`: `RN(hi + lo)`.
    #[must_use]
    pub fn to_f64(self) -> f64 {
        self.hi + self.lo
    }

    /// `true` if both parts are finite.
    #[must_use]
    pub fn is_finite(self) -> bool {
        self.hi.is_finite() && self.lo.is_finite()
    }

    /// `true` if the value is NaN.
    #[must_use]
    pub fn is_nan(self) -> bool {
        self.hi.is_nan() || self.lo.is_nan()
    }

    /// A pair from an error-free transformation, with non-finite leading parts
    /// kept clean (`lo = 0`) so that infinities propagate as infinities.
    #[inline]
    fn from_parts(hi: f64, lo: f64) -> Self {
        if hi.is_finite() {
            Self { hi, lo }
        } else {
            Self { hi, lo: 0.0 }
        }
    }

    /// `self + b` for an `f64` `b` (`DWPlusFP`, relative error `<= 2 u^2`).
    #[must_use]
    pub fn add_f64(self, b: f64) -> Self {
        let (s, e) = two_sum(self.hi, b);
        if !s.is_finite() {
            return Self::from_parts(s, 0.0);
        }
        let (s, e) = quick_two_sum(s, e + self.lo);
        Self { hi: s, lo: e }
    }

    /// `self + b` (accurate double-double sum, relative error `<= 3 u^2`).
    #[must_use]
    pub fn add_dd(self, b: Self) -> Self {
        let (s, e) = two_sum(self.hi, b.hi);
        if !s.is_finite() {
            return Self::from_parts(s, 0.0);
        }
        let (t, f) = two_sum(self.lo, b.lo);
        let (s, e) = quick_two_sum(s, e + t);
        let (s, e) = quick_two_sum(s, e + f);
        Self { hi: s, lo: e }
    }

    /// `self * b` for an `f64` `b` (`DWTimesFP3`, relative error `<= 2 u^2`).
    #[must_use]
    pub fn mul_f64(self, b: f64) -> Self {
        let (p, e) = two_prod(self.hi, b);
        if !p.is_finite() {
            return Self::from_parts(p, 0.0);
        }
        let (p, e) = quick_two_sum(p, fma(self.lo, b, e));
        Self { hi: p, lo: e }
    }

    /// `self * b` (`DWTimesDW3`, relative error `<= 4 u^2`).
    #[must_use]
    pub fn mul_dd(self, b: Self) -> Self {
        let (p, e) = two_prod(self.hi, b.hi);
        if !p.is_finite() {
            return Self::from_parts(p, 0.0);
        }
        let t = fma(self.hi, b.lo, self.lo * b.lo);
        let t = fma(self.lo, b.hi, t);
        let (p, e) = quick_two_sum(p, e + t);
        Self { hi: p, lo: e }
    }

    /// `self / b` for an `f64` `b`.
    #[must_use]
    pub fn div_f64(self, b: f64) -> Self {
        let q1 = self.hi / b;
        if !q1.is_finite() {
            return Self::from_parts(q1, 0.0);
        }
        // the remainder self - q1 b, exact up to the rounding of its tail
        let (p, pe) = two_prod(q1, b);
        let (s, e) = two_sum(self.hi, -p);
        let e = (e + self.lo) - pe;
        let q2 = (s + e) / b;
        let (q, qe) = quick_two_sum(q1, q2);
        Self { hi: q, lo: qe }
    }

    /// `self / b` (QD's accurate division: three quotient digits).
    #[must_use]
    pub fn div_dd(self, b: Self) -> Self {
        let q1 = self.hi / b.hi;
        if !q1.is_finite() {
            return Self::from_parts(q1, 0.0);
        }
        let r = self.sub_dd(b.mul_f64(q1));
        let q2 = r.hi / b.hi;
        let r = r.sub_dd(b.mul_f64(q2));
        let q3 = r.hi / b.hi;
        let (q1, q2) = quick_two_sum(q1, q2);
        Self { hi: q1, lo: q2 }.add_f64(q3)
    }

    /// `self - b`.
    #[must_use]
    pub fn sub_dd(self, b: Self) -> Self {
        self.add_dd(-b)
    }

    /// `-self` (exact).
    #[must_use]
    pub fn neg_dd(self) -> Self {
        Self {
            hi: -self.hi,
            lo: -self.lo,
        }
    }

    /// Absolute value (exact).
    #[must_use]
    pub fn abs(self) -> Self {
        if self.hi < 0.0 {
            -self
        } else {
            self
        }
    }

    /// Square root, by one Newton step from the `f64` root (relative error
    /// about `u^2`). Zero gives zero, a negative value NaN.
    #[must_use]
    pub fn sqrt(self) -> Self {
        if self.hi == 0.0 {
            return Self::from_f64(self.hi);
        }
        if self.hi < 0.0 {
            return Self::from_f64(f64::NAN);
        }
        let q = Float::sqrt(self.hi);
        if !self.hi.is_finite() {
            return Self::from_f64(q);
        }
        let (p, e) = two_prod(q, q);
        // self.hi - p is exact (Sterbenz): p is within 2 ulps of self.hi
        let r = ((self.hi - p) - e + self.lo) / (q + q);
        let (s, t) = quick_two_sum(q, r);
        Self { hi: s, lo: t }
    }

    /// Largest integer not above `self` (exact).
    #[must_use]
    pub fn floor(self) -> Self {
        let h = Float::floor(self.hi);
        if !h.is_finite() {
            return Self::from_f64(h);
        }
        if h == self.hi {
            // hi is an integer: the fractional part, if any, is in lo
            let (s, e) = two_sum(h, Float::floor(self.lo));
            Self { hi: s, lo: e }
        } else {
            // hi is at least one ulp from any integer and |lo| at most half
            Self::from_f64(h)
        }
    }

    /// pi.
    #[must_use]
    pub const fn pi() -> Self {
        Self::PI
    }

    /// `x = k (pi/2) + r` with `|r| <= ~0.79` for finite `|x| < 2^80`;
    /// returns `r` and `k mod 4`.
    fn reduce(self) -> (Self, u8) {
        let mut r = self;
        let mut quadrant = 0u8;
        // Four passes bring |r| from below 2^80 under 0.8: each pass leaves
        // at most ~|k| 2^-52 from the rounding of k.
        for _ in 0..4 {
            if Float::abs(r.hi) <= 0.8 {
                break;
            }
            let k = Float::floor(r.hi * core::f64::consts::FRAC_2_PI + 0.5);
            let (p1, e1) = two_prod(k, PIO2_1);
            let (p2, e2) = two_prod(k, PIO2_2);
            let (p3, e3) = two_prod(k, PIO2_3);
            r = r
                .sub_dd(Self { hi: p1, lo: e1 })
                .sub_dd(Self { hi: p2, lo: e2 })
                .sub_dd(Self { hi: p3, lo: e3 });
            // k mod 4 (exact for any integral f64)
            let m = k - 4.0 * Float::floor(k * 0.25);
            quadrant = quadrant.wrapping_add(m as u8) & 3;
        }
        (r, quadrant)
    }

    /// `sum_{j >= 0} (-1)^j r^(2j + s) / (2j + s)!` with `first = r^s` and
    /// `n = s`. The tail (`j >= 1`) is summed on its own and added to `first`
    /// last, so that its rounding errors count relative to the tail only.
    fn series(first: Self, r2: Self, mut n: f64) -> Self {
        let mut term = first;
        let mut tail = Self::ZERO;
        let bound = SERIES_EPS * Float::abs(first.hi);
        // at most 15 terms for |r| <= 0.8; the cap only matters for
        // arguments that failed to reduce
        for _ in 0..64 {
            term = -term.mul_dd(r2).div_f64((n + 1.0) * (n + 2.0));
            n += 2.0;
            if Float::abs(term.hi) <= bound {
                break;
            }
            tail = tail.add_dd(term);
        }
        if tail.hi == 0.0 {
            first // keeps the sign of sin(-0)
        } else {
            first.add_dd(tail)
        }
    }

    /// Taylor series of `sin r` (for small `|r|`).
    fn sin_taylor(r: Self) -> Self {
        Self::series(r, r.mul_dd(r), 1.0)
    }

    /// Taylor series of `cos r` (for small `|r|`).
    fn cos_taylor(r: Self) -> Self {
        Self::series(Self::ONE, r.mul_dd(r), 0.0)
    }

    /// `(sin x, cos x)` of a single `f64`: double-double for `|x| < 2^80`,
    /// the `f64` library beyond.
    fn sin_cos_f64(x: f64) -> (Self, Self) {
        if Float::abs(x) < HUGE_ARG {
            Self::from_f64(x).sin_cos()
        } else {
            (Self::from_f64(Float::sin(x)), Self::from_f64(Float::cos(x)))
        }
    }

    /// `sin(hi + lo) = sin hi cos lo + cos hi sin lo` for `|hi| >= 2^80`.
    fn sin_cos_huge(self) -> (Self, Self) {
        let (sh, ch) = Self::sin_cos_f64(self.hi);
        let (sl, cl) = Self::sin_cos_f64(self.lo);
        (
            sh.mul_dd(cl).add_dd(ch.mul_dd(sl)),
            ch.mul_dd(cl).sub_dd(sh.mul_dd(sl)),
        )
    }

    /// Sine. Absolute error below `2e-32` for `|x| <= 2^50`, growing as
    /// about `|x| 2^-160` up to `2^80`, `f64` accuracy beyond (see the
    /// module docs); NaN for non-finite arguments.
    #[must_use]
    pub fn sin(self) -> Self {
        if !self.is_finite() {
            return Self::from_f64(f64::NAN);
        }
        if Float::abs(self.hi) >= HUGE_ARG {
            return self.sin_cos_huge().0;
        }
        let (r, q) = self.reduce();
        match q {
            0 => Self::sin_taylor(r),
            1 => Self::cos_taylor(r),
            2 => -Self::sin_taylor(r),
            _ => -Self::cos_taylor(r),
        }
    }

    /// Cosine; accuracy and range as for [`DoubleDouble::sin`].
    #[must_use]
    pub fn cos(self) -> Self {
        if !self.is_finite() {
            return Self::from_f64(f64::NAN);
        }
        if Float::abs(self.hi) >= HUGE_ARG {
            return self.sin_cos_huge().1;
        }
        let (r, q) = self.reduce();
        match q {
            0 => Self::cos_taylor(r),
            1 => -Self::sin_taylor(r),
            2 => -Self::cos_taylor(r),
            _ => Self::sin_taylor(r),
        }
    }

    /// `(sin x, cos x)`, sharing one argument reduction.
    #[must_use]
    pub fn sin_cos(self) -> (Self, Self) {
        if !self.is_finite() {
            let nan = Self::from_f64(f64::NAN);
            return (nan, nan);
        }
        if Float::abs(self.hi) >= HUGE_ARG {
            return self.sin_cos_huge();
        }
        let (r, q) = self.reduce();
        let (s, c) = (Self::sin_taylor(r), Self::cos_taylor(r));
        match q {
            0 => (s, c),
            1 => (c, -s),
            2 => (-s, -c),
            _ => (-c, s),
        }
    }

    /// Four-quadrant arctangent `atan2(self, x)` in `[-pi, pi]`, by Newton
    /// refinement of the `f64` `atan2`; `atan2(0, 0) = 0`.
    #[must_use]
    pub fn atan2(self, x: Self) -> Self {
        let y = self;
        if !(y.is_finite() && x.is_finite()) {
            return Self::from_f64(Float::atan2(y.hi, x.hi));
        }
        if y.hi == 0.0 && x.hi == 0.0 {
            return Self::ZERO;
        }
        // scale both by the same power of two so that the larger is in [1, 2)
        let m = Float::abs(y.hi).max(Float::abs(x.hi));
        let e = ((m.to_bits() >> 52) & 0x7ff) as i32 - 1023;
        let (s1, s2) = (pow2(-e / 2), pow2(-e - (-e / 2)));
        let (y, x) = (y.mul_f64(s1).mul_f64(s2), x.mul_f64(s1).mul_f64(s2));
        let mut z = Self::from_f64(Float::atan2(y.hi, x.hi));
        for _ in 0..3 {
            let (s, c) = z.sin_cos();
            let num = y.mul_dd(c).sub_dd(x.mul_dd(s));
            let den = x.mul_dd(c).add_dd(y.mul_dd(s));
            let t = num.div_dd(den);
            if !t.is_finite() {
                break;
            }
            // atan(t) = t - t^3/3 + O(t^5)
            z = z.add_dd(t.sub_dd(t.mul_dd(t).mul_dd(t).div_f64(3.0)));
            // one step leaves O(t^5): done once |t| is down to f64 level
            if Float::abs(t.hi) <= 1e-12 * Float::abs(z.hi) {
                break;
            }
        }
        z
    }

    /// Arc cosine in `[0, pi]`, the argument clamped to `[-1, 1]`:
    /// `atan2(sqrt((1 - x)(1 + x)), x)`.
    #[must_use]
    pub fn acos(self) -> Self {
        let x = if self > Self::ONE {
            Self::ONE
        } else if self < -Self::ONE {
            -Self::ONE
        } else {
            self
        };
        let y = Self::ONE.sub_dd(x).mul_dd(Self::ONE.add_dd(x)).sqrt();
        y.atan2(x)
    }
}

/// `2^e` for `-1022 <= e <= 1023`.
fn pow2(e: i32) -> f64 {
    f64::from_bits(((e + 1023) as u64) << 52)
}

impl Default for DoubleDouble {
    fn default() -> Self {
        Self::ZERO
    }
}

impl From<f64> for DoubleDouble {
    fn from(x: f64) -> Self {
        Self::from_f64(x)
    }
}

impl PartialEq<f64> for DoubleDouble {
    fn eq(&self, other: &f64) -> bool {
        *self == Self::from_f64(*other)
    }
}

impl PartialOrd<f64> for DoubleDouble {
    fn partial_cmp(&self, other: &f64) -> Option<Ordering> {
        self.partial_cmp(&Self::from_f64(*other))
    }
}

impl Neg for DoubleDouble {
    type Output = Self;
    fn neg(self) -> Self {
        self.neg_dd()
    }
}

impl Add for DoubleDouble {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        self.add_dd(o)
    }
}

impl Sub for DoubleDouble {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        self.sub_dd(o)
    }
}

impl Mul for DoubleDouble {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        self.mul_dd(o)
    }
}

impl Div for DoubleDouble {
    type Output = Self;
    fn div(self, o: Self) -> Self {
        self.div_dd(o)
    }
}

impl Add<f64> for DoubleDouble {
    type Output = Self;
    fn add(self, o: f64) -> Self {
        self.add_f64(o)
    }
}

impl Sub<f64> for DoubleDouble {
    type Output = Self;
    fn sub(self, o: f64) -> Self {
        self.add_f64(-o)
    }
}

impl Mul<f64> for DoubleDouble {
    type Output = Self;
    fn mul(self, o: f64) -> Self {
        self.mul_f64(o)
    }
}

impl Div<f64> for DoubleDouble {
    type Output = Self;
    fn div(self, o: f64) -> Self {
        self.div_f64(o)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const U2: f64 = 1.232_595_164_407_831e-32; // 2^-106

    /// The test support's deterministic generator (SplitMix64), so failures
    /// reproduce.
    use crate::rng::SplitMix64 as Rng;

    /// A double-double with a random tail, in about `[a, b)`.
    fn random_dd(g: &mut Rng, a: f64, b: f64) -> DoubleDouble {
        let hi = g.range(a, b);
        let ulp = ulp(hi);
        DoubleDouble::new(hi, g.range(-0.5, 0.5) * ulp)
    }

    fn ulp(x: f64) -> f64 {
        let a = x.abs();
        f64::from_bits(a.to_bits() + 1) - a
    }

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

    fn is_normalised(x: DoubleDouble) -> bool {
        x.hi + x.lo == x.hi && x.lo.abs() <= ulp(x.hi) / 2.0
    }

    #[test]
    fn two_sum_and_quick_two_sum_are_exact_on_integers() {
        let mut g = Rng::new(1);
        for _ in 0..10_000 {
            // integers up to 2^62, so the sums need more than 53 bits
            let a = (g.next_u64() >> 2) as f64;
            let b = (g.next_u64() >> (2 + g.next_u64() % 40)) as f64;
            let b = if g.next_u64() & 1 == 0 { b } else { -b };
            let exact = a as i128 + b as i128;
            let (s, e) = two_sum(a, b);
            assert_eq!(s as i128 + e as i128, exact, "two_sum({a}, {b})");
            assert_eq!(s, a + b, "two_sum's leading part is RN(a + b)");
            let (s, e) = two_sum(b, a);
            assert_eq!(s as i128 + e as i128, exact, "two_sum({b}, {a})");
            let (big, small) = if a.abs() >= b.abs() { (a, b) } else { (b, a) };
            let (s, e) = quick_two_sum(big, small);
            assert_eq!(
                s as i128 + e as i128,
                exact,
                "quick_two_sum({big}, {small})"
            );
        }
    }

    #[test]
    fn two_prod_is_exact_on_integers() {
        let mut g = Rng::new(2);
        for _ in 0..10_000 {
            // integers below 2^50 have products below 2^100: exact in i128
            let a = (g.next_u64() >> (14 + g.next_u64() % 30)) as f64;
            let b = (g.next_u64() >> 14) as f64;
            let b = if g.next_u64() & 1 == 0 { b } else { -b };
            let (p, e) = two_prod(a, b);
            assert_eq!(p, a * b, "two_prod's leading part is RN(a b)");
            assert_eq!(
                p as i128 + e as i128,
                a as i128 * b as i128,
                "two_prod({a}, {b})"
            );
        }
        // and on dyadic fractions: (1 + 2^-30)^2 = 1 + 2^-29 + 2^-60
        let x = 1.0 + 2f64.powi(-30);
        let (p, e) = two_prod(x, x);
        assert_eq!((p, e), (1.0 + 2f64.powi(-29), 2f64.powi(-60)), "square");
    }

    #[test]
    fn add_and_mul_are_exact_when_the_result_fits() {
        let mut g = Rng::new(3);
        for _ in 0..10_000 {
            // a = a1 + a0 and b = b1 + b0 with integer parts; sums below 2^100
            let a1 = ((g.next_u64() >> 20) as f64) * 2f64.powi(50);
            let a0 = (g.next_u64() >> 20) as f64;
            let b1 = ((g.next_u64() >> 20) as f64) * 2f64.powi(50);
            let b0 = -((g.next_u64() >> 20) as f64);
            let (a, b) = (dd(a1, a0), dd(b1, b0));
            let exact = a1 as i128 + a0 as i128 + b1 as i128 + b0 as i128;
            let s = a + b;
            assert!(is_normalised(s), "{s:?} normalised");
            assert_eq!(s.hi as i128 + s.lo as i128, exact, "{a:?} + {b:?}");
            let d = a - b;
            let exact = a1 as i128 + a0 as i128 - b1 as i128 - b0 as i128;
            assert_eq!(d.hi as i128 + d.lo as i128, exact, "{a:?} - {b:?}");
            // products of 40-bit integers (80 bits): exact in double-double
            let x = (g.next_u64() >> 24) as f64;
            let y = (g.next_u64() >> 24) as f64 + 0.5;
            let p = dd(x, 0.0) * dd(y, 0.0);
            let exact = x as i128 * (2.0 * y) as i128;
            assert_eq!(
                2 * (p.hi as i128) + (2.0 * p.lo) as i128,
                exact,
                "{x} * {y}"
            );
        }
    }

    #[test]
    fn division_and_product_identities_hold_to_a_few_u2() {
        let mut g = Rng::new(4);
        let mut worst = 0.0f64;
        for _ in 0..20_000 {
            let scale = 2f64.powi((g.next_u64() % 80) as i32 - 40);
            let a = random_dd(&mut g, -1.0, 1.0) * scale;
            let b = random_dd(&mut g, 0.1, 10.0);
            let b = if g.next_u64() & 1 == 0 { b } else { -b };
            let q = a / b;
            assert!(is_normalised(q), "{q:?} normalised");
            worst = worst.max(rel(q * b, a));
            worst = worst.max(rel(a * b / b, a));
            let f = g.range(-3.0, 3.0);
            worst = worst.max(rel(a / f * f, a));
            worst = worst.max(rel(a * f / f, a));
        }
        assert!(worst < 1e-31, "worst relative error {worst:e}");
        // independent values (mpmath, 400 bits)
        let third = dd(0.333_333_333_333_333_3, 1.850_371_707_708_594e-17);
        let one = DoubleDouble::ONE;
        let three = DoubleDouble::from_f64(3.0);
        assert!(rel(one / three, third) < 2.0 * U2, "1/3");
        assert!(rel(one / 3.0, third) < 2.0 * U2, "1/3 by f64");
        let two_sevenths = dd(0.285_714_285_714_285_7, 1.586_032_892_321_652e-17);
        let two = DoubleDouble::from_f64(2.0);
        assert!(
            rel(two / DoubleDouble::from_f64(7.0), two_sevenths) < 2.0 * U2,
            "2/7"
        );
        assert!((one / DoubleDouble::ZERO).hi.is_infinite(), "1/0");
    }

    #[test]
    fn sqrt_is_accurate() {
        let two = DoubleDouble::from_f64(2.0);
        let r = two.sqrt();
        assert!(err(r * r, two) < 1e-31, "sqrt(2)^2 = {:?}", r * r);
        let sqrt3 = dd(1.732_050_807_568_877_2, 1.003_508_422_180_690_3e-16);
        assert!(
            rel(DoubleDouble::from_f64(3.0).sqrt(), sqrt3) < 1.5 * U2,
            "sqrt 3"
        );
        // a perfect square needing 82 bits
        let n = dd(2f64.powi(40) + 1.0, 0.0);
        assert_eq!((n * n).sqrt(), n, "sqrt of a square");
        assert_eq!(DoubleDouble::from_f64(4.0).sqrt(), two, "sqrt 4");
        assert_eq!(DoubleDouble::ZERO.sqrt(), DoubleDouble::ZERO, "sqrt 0");
        assert!(DoubleDouble::from_f64(-1.0).sqrt().is_nan(), "sqrt -1");
        let mut g = Rng::new(5);
        let mut worst = 0.0f64;
        for _ in 0..10_000 {
            let a = random_dd(&mut g, 0.0, 1.0) * 2f64.powi((g.next_u64() % 200) as i32 - 100);
            let r = a.sqrt();
            assert!(is_normalised(r), "{r:?} normalised");
            worst = worst.max(rel(r * r, a));
        }
        assert!(worst < 1e-31, "worst sqrt^2 relative error {worst:e}");
    }

    #[test]
    fn floor_is_exact() {
        let f = |hi: f64, lo: f64| dd(hi, lo).floor();
        let d = DoubleDouble::from_f64;
        assert_eq!(f(3.7, 0.0), d(3.0), "floor 3.7");
        assert_eq!(f(-0.5, 0.0), d(-1.0), "floor -0.5");
        assert_eq!(f(1.0, -1e-20), d(0.0), "floor 1-");
        assert_eq!(f(1.0, 1e-20), d(1.0), "floor 1+");
        assert_eq!(f(-1.0, 1e-20), d(-1.0), "floor -1+");
        assert_eq!(f(-1.0, -1e-20), d(-2.0), "floor -1-");
        let big = 2f64.powi(60);
        assert_eq!(f(big, 0.5), d(big), "floor 2^60 + 1/2");
        assert_eq!(f(big, -0.5), dd(big, -1.0), "floor 2^60 - 1/2");
        assert_eq!(f(big, 3.25), dd(big, 3.0), "floor 2^60 + 3.25");
        assert_eq!(f(-big, -3.25), dd(-big, -4.0), "floor -2^60 - 3.25");
        assert!(f(f64::INFINITY, 0.0).hi.is_infinite(), "floor inf");
        let mut g = Rng::new(6);
        for _ in 0..10_000 {
            let x = random_dd(&mut g, -1e6, 1e6);
            let fl = x.floor();
            assert!(fl <= x && x < fl + 1.0, "floor({x:?}) = {fl:?}");
            assert_eq!(fl.floor(), fl, "floor is an integer");
        }
    }

    #[test]
    fn pi_constants_meet_the_reduction() {
        // sin(PI) = sin(pi - PI) and cos(FRAC_PI_2) = pi/2 - FRAC_PI_2: both
        // test the three-part reduction far below 2^-106 (mpmath values)
        let s = DoubleDouble::PI.sin();
        assert!(
            (s.to_f64() / -2.994_769_809_718_339_7e-33 - 1.0).abs() < 1e-12,
            "sin(PI) = {s:?}"
        );
        let c = DoubleDouble::FRAC_PI_2.cos();
        assert!(
            (c.to_f64() / -1.497_384_904_859_169_8e-33 - 1.0).abs() < 1e-12,
            "cos(FRAC_PI_2) = {c:?}"
        );
        assert!(
            err(DoubleDouble::PI.cos(), -DoubleDouble::ONE) < 1e-40,
            "cos pi"
        );
        assert_eq!(
            DoubleDouble::FRAC_PI_2 * 2.0,
            DoubleDouble::PI,
            "pi/2 halves pi"
        );
    }

    #[test]
    fn sin_and_cos_at_rational_multiples_of_pi() {
        let pi = DoubleDouble::PI;
        let half = DoubleDouble::from_f64(0.5);
        let checks = [
            ("sin pi/6", (pi / 6.0).sin(), half),
            ("cos pi/3", (pi / 3.0).cos(), half),
            ("sin 5pi/6", (pi * 5.0 / 6.0).sin(), half),
            ("cos 2pi/3", (pi * 2.0 / 3.0).cos(), -half),
            ("sin -pi/6", (-pi / 6.0).sin(), -half),
            ("sin 13pi/6", (pi * 13.0 / 6.0).sin(), half),
            ("cos 10 pi + pi/3", (pi * 10.0 + pi / 3.0).cos(), half),
            ("sin^2 pi/4", (pi / 4.0).sin() * (pi / 4.0).sin(), half),
            ("cos^2 pi/4", (pi / 4.0).cos() * (pi / 4.0).cos(), half),
            ("sin pi/2", (pi / 2.0).sin(), DoubleDouble::ONE),
        ];
        for (what, got, want) in checks {
            assert!(err(got, want) < 1e-30, "{what}: {got:?}");
        }
        // PI is 3e-33 below pi, so 1e5 PI is 3e-28 below 1e5 pi: the error of
        // the argument, not of cos, dominates (sin(pi/3) 3e-28 = 2.6e-28)
        let c = (pi * 100_000.0 + pi / 3.0).cos();
        assert!(err(c, half) < 3e-28, "cos(1e5 pi + pi/3) = {c:?}");
        // sin(k pi): the argument is k pi to 2^-104 k pi, so |sin| is at most that
        for k in 1..=100_000 {
            let x = pi * f64::from(k);
            let s = x.sin();
            let bound = f64::from(k) * core::f64::consts::PI * 2f64.powi(-104);
            assert!(s.abs().to_f64() <= bound, "sin({k} pi) = {s:?}");
        }
    }

    #[test]
    fn sin_and_cos_match_high_precision_values() {
        // (argument, sin, cos, tolerance), references from mpmath at 400 bits
        let cases = [
            (
                dd(1.0, 0.0),
                dd(0.841_470_984_807_896_5, 1.776_845_092_935_536e-18),
                Some(dd(0.540_302_305_868_139_8, -4.760_954_612_604_417e-17)),
                1e-32,
            ),
            (
                dd(1e6, 0.0),
                dd(-0.349_993_502_171_292_94, -1.595_284_880_932_396_8e-17),
                Some(dd(0.936_752_127_533_144_7, 4.637_088_260_214_747e-17)),
                2e-32,
            ),
            (
                dd(100_000.1, 0.0),
                dd(-0.064_199_400_989_459_35, -2.311_691_831_600_734_2e-18),
                None,
                2e-32,
            ),
            (
                dd(123_456.789, 0.0),
                dd(-0.998_664_082_343_224_6, 4.307_313_337_788_326_6e-17),
                Some(dd(0.051_672_532_718_701_38, -6.512_424_953_386_242e-19)),
                2e-32,
            ),
            // beyond 1e6: graceful degradation
            (
                dd(2f64.powi(40), 0.0),
                dd(-0.405_705_011_532_828_73, 1.003_818_670_147_651_3e-17),
                Some(dd(-0.914_004_071_991_557, -2.561_569_827_021_248_2e-17)),
                1e-30,
            ),
            (
                dd(1e22, 0.0),
                dd(-0.852_200_849_767_188_8, -6.780_682_589_677_328_4e-18),
                None,
                1e-24,
            ),
            (
                dd(2f64.powi(79), 0.0),
                dd(-0.493_378_213_445_401_34, 2.477_670_622_601_653e-17),
                None,
                1e-21,
            ),
            // the f64 fallback
            (
                dd(1e300, 0.0),
                dd(-0.817_881_912_115_908_5, -4.781_358_374_403_26e-17),
                None,
                1e-15,
            ),
            (
                dd(2f64.powi(100), 2f64.powi(47)),
                dd(0.838_605_481_713_756_8, 3.971_614_949_558_723_6e-17),
                None,
                1e-15,
            ),
            (
                dd(f64::MAX, 0.0),
                dd(0.004_961_954_789_184_062, -2.504_937_767_649_410_4e-19),
                None,
                1e-15,
            ),
        ];
        for (x, s, c, tol) in cases {
            let e = err(x.sin(), s);
            assert!(e < tol, "sin({x:?}) off by {e:e}");
            assert!(err((-x).sin(), -s) < tol, "sin(-{x:?})");
            assert!(err(x.sin_cos().0, s) < tol, "sin_cos({x:?}).0");
            if let Some(c) = c {
                let e = err(x.cos(), c);
                assert!(e < tol, "cos({x:?}) off by {e:e}");
                assert!(err((-x).cos(), c) < tol, "cos(-{x:?})");
                assert!(err(x.sin_cos().1, c) < tol, "sin_cos({x:?}).1");
            }
        }
    }

    #[test]
    fn pythagoras_and_agreement_with_f64() {
        let mut g = Rng::new(7);
        let mut worst = 0.0f64;
        for i in 0..20_000 {
            let x = if i % 2 == 0 {
                random_dd(&mut g, -1e6, 1e6)
            } else {
                random_dd(&mut g, -4.0, 4.0)
            };
            let (s, c) = x.sin_cos();
            assert_eq!(s, x.sin(), "sin_cos agrees with sin at {x:?}");
            assert_eq!(c, x.cos(), "sin_cos agrees with cos at {x:?}");
            worst = worst.max(err(s * s + c * c, DoubleDouble::ONE));
            assert!(s.abs() <= 1.0 && c.abs() <= 1.0, "{x:?}: |sin|, |cos| <= 1");
        }
        assert!(worst < 1e-31, "worst |sin^2 + cos^2 - 1| = {worst:e}");
        // the leading part rounds to within an f64 ulp of the library's value
        for _ in 0..20_000 {
            let x = g.range(-1e4, 1e4);
            let s = DoubleDouble::from_f64(x).sin().to_f64();
            let c = DoubleDouble::from_f64(x).cos().to_f64();
            let (fs, fc) = (Float::sin(x), Float::cos(x));
            assert!((s - fs).abs() <= 1.5 * ulp(fs), "sin {x}: {s} vs {fs}");
            assert!((c - fc).abs() <= 1.5 * ulp(fc), "cos {x}: {c} vs {fc}");
        }
    }

    #[test]
    fn sin_and_cos_edge_arguments() {
        let z = DoubleDouble::ZERO;
        assert_eq!(z.sin(), z, "sin 0");
        assert_eq!(z.cos(), DoubleDouble::ONE, "cos 0");
        let neg_zero = DoubleDouble::from_f64(-0.0).sin();
        assert!(
            neg_zero.hi == 0.0 && neg_zero.hi.is_sign_negative(),
            "sin -0"
        );
        for t in [1e-300, 1e-200, 1e-20, -1e-20, 2e-17] {
            let x = DoubleDouble::from_f64(t);
            // sin t = t - t^3/6 ...: t^3/6 is below 2^-106 t for |t| < 1e-16
            if t.abs() < 1e-16 {
                assert_eq!(x.sin(), x, "sin {t}");
            }
            // cos t = 1 - t^2/2 + ...; the series stops below 2^-110
            let c = x.cos();
            assert!(err(c, DoubleDouble::ONE - t * t / 2.0) < 1e-33, "cos {t}");
        }
        // 2e-17: sin = t - t^3/6 with t^3/6 = 1.33e-51, well inside the tail
        let x = DoubleDouble::from_f64(2e-17);
        assert!(rel(x.sin(), x - 8e-51 / 6.0) < U2, "sin 2e-17");
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let x = DoubleDouble::from_f64(bad);
            assert!(x.sin().is_nan() && x.cos().is_nan(), "sin, cos of {bad}");
            let (s, c) = x.sin_cos();
            assert!(s.is_nan() && c.is_nan(), "sin_cos of {bad}");
        }
        for big in [
            f64::MAX,
            -f64::MAX,
            1e200,
            2f64.powi(80),
            2f64.powi(80) - 2f64.powi(27),
        ] {
            let (s, c) = DoubleDouble::from_f64(big).sin_cos();
            assert!(s.is_finite() && c.is_finite(), "finite at {big}");
            assert!(err(s * s + c * c, DoubleDouble::ONE) < 1e-15, "{big}");
        }
    }

    #[test]
    fn atan2_in_every_quadrant() {
        let pi = DoubleDouble::PI;
        let d = DoubleDouble::from_f64;
        let checks = [
            ("4 atan2(1, 1)", d(1.0).atan2(d(1.0)) * 4.0, pi),
            ("4 atan2(-1, 1)", d(-1.0).atan2(d(1.0)) * 4.0, -pi),
            ("atan2(1, -1)", d(1.0).atan2(d(-1.0)), pi * 3.0 / 4.0),
            ("atan2(-1, -1)", d(-1.0).atan2(d(-1.0)), -pi * 3.0 / 4.0),
            ("atan2(0, -1)", d(0.0).atan2(d(-1.0)), pi),
            ("atan2(1, 0)", d(1.0).atan2(d(0.0)), pi / 2.0),
            ("atan2(-1, 0)", d(-1.0).atan2(d(0.0)), -pi / 2.0),
            ("atan2(0, 1)", d(0.0).atan2(d(1.0)), d(0.0)),
            ("atan2(0, 0)", d(0.0).atan2(d(0.0)), d(0.0)),
            ("atan2(-0, -0)", d(-0.0).atan2(d(-0.0)), d(0.0)),
            ("6 atan2(1, sqrt 3)", d(1.0).atan2(d(3.0).sqrt()) * 6.0, pi),
            ("3 atan2(sqrt 3, 1)", d(3.0).sqrt().atan2(d(1.0)) * 3.0, pi),
        ];
        for (what, got, want) in checks {
            assert!(err(got, want) < 1e-31, "{what}: {got:?}");
        }
        // mpmath references, with scaling extremes
        let a34 = dd(2.498_091_544_796_509, -4.392_407_599_224_622e-18);
        // (powers of two, so that 3 s and -4 s are exact)
        for s in [1.0, 2f64.powi(1000), 2f64.powi(-1000), 2f64.powi(-1060)] {
            let got = d(3.0 * s).atan2(d(-4.0 * s));
            assert!(rel(got, a34) < 2.0 * U2, "atan2(3 {s}, -4 {s}) = {got:?}");
        }
        let small = dd(-1e-10, 3.333_333_333_333_333_8e-31);
        assert!(
            rel(d(-1e-10).atan2(d(1.0)), small) < 2.0 * U2,
            "atan2(-1e-10, 1)"
        );
        // round trip through sin and cos
        let mut g = Rng::new(8);
        let mut worst = 0.0f64;
        for _ in 0..5_000 {
            let t = random_dd(&mut g, -3.1, 3.1);
            let r = g.range(1e-3, 1e3);
            let (s, c) = t.sin_cos();
            worst = worst.max(err((s * r).atan2(c * r), t));
        }
        assert!(worst < 1e-31, "worst atan2 round trip {worst:e}");
    }

    #[test]
    fn acos_identities() {
        let pi = DoubleDouble::PI;
        let d = DoubleDouble::from_f64;
        let checks = [
            ("acos(-1)", d(-1.0).acos(), pi),
            ("2 acos(0)", d(0.0).acos() * 2.0, pi),
            ("acos(1)", d(1.0).acos(), d(0.0)),
            ("3 acos(1/2)", d(0.5).acos() * 3.0, pi),
            ("3 acos(-1/2)", d(-0.5).acos() * 1.5, pi),
            ("acos(2) clamps", d(2.0).acos(), d(0.0)),
            ("acos(-2) clamps", d(-2.0).acos(), pi),
        ];
        for (what, got, want) in checks {
            assert!(err(got, want) < 1e-31, "{what}: {got:?}");
        }
        let a = dd(1.266_103_672_779_499_2, -7.783_137_368_524_88e-17);
        assert!(rel(d(0.3).acos(), a) < 2.0 * U2, "acos(0.3)");
        let mut g = Rng::new(9);
        let mut worst = 0.0f64;
        for _ in 0..5_000 {
            let x = random_dd(&mut g, -1.0, 1.0);
            worst = worst.max(err(x.acos().cos(), x));
        }
        assert!(worst < 1e-31, "worst cos(acos x) - x: {worst:e}");
        assert!(d(f64::NAN).acos().is_nan(), "acos NaN");
    }
}
