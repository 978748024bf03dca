//! Shared input types and oracle checks for the `motion-bound` fuzz targets.
//!
//! Every target decodes its input with `arbitrary` into typed values and
//! turns a violated property into a panic (`assert!` with the offending
//! values in the message), which libFuzzer reports as a crash.
//!
//! * [`Precision`] pairs a bound precision with the oracle precision it is
//!   checked against: `f64` for `f32` bounds, [`DoubleDouble`] for `f64`
//!   bounds (the same pairing as `tests/common`).
//! * [`Num`] is a raw float with a bias: any bit pattern, a moderate value,
//!   or one of the boundary values of the crate's range analysis.
//! * [`check_sound`] is the soundness oracle shared by the bound targets,
//!   evaluated on an exactly rescaled copy of the case ([`oracle`]).

#![forbid(unsafe_code)]

use std::fmt::Debug;

use arbitrary::Arbitrary;
use motion_bound::reference::{DoubleDouble, Real};
use motion_bound::testkit::{Case, CaseSpec};
use motion_bound::{
    DirectedBound, Float, InputError, Point3, Quantity, RigidMotion, TimeInterval, Vec3, VertexSet,
};

pub mod oracle;
pub mod seeds;

pub use oracle::{check_one_sided, check_sound, Oracle, Scaled};

/// Raw bytes read as bounded numbers, for targets whose input is a plain
/// byte string (`toi`): each read takes the next bytes, and bytes past the
/// end read as zero, so every input decodes.
#[derive(Clone, Debug)]
pub struct Bytes<'a> {
    data: &'a [u8],
    at: usize,
}

impl<'a> Bytes<'a> {
    /// Reads `data` from its start.
    #[must_use]
    pub const fn new(data: &'a [u8]) -> Self {
        Self { data, at: 0 }
    }

    /// The next byte (zero past the end).
    pub fn u8(&mut self) -> u8 {
        let b = self.data.get(self.at).copied().unwrap_or(0);
        self.at += 1;
        b
    }

    /// The next two bytes as a value in `[lo, hi]`: `lo + (hi - lo) k / 65535`.
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        let k = u16::from_le_bytes([self.u8(), self.u8()]);
        lo + (hi - lo) * f64::from(k) / 65535.0
    }
}

/// Vertices of a [`CaseSpec`] beyond this many are dropped before the case is
/// built: the high-precision oracle costs microseconds per vertex, and a
/// longer list only repeats the per-vertex cases (the bounds take a maximum
/// over vertices). The `validation` target feeds longer lists to the bounds.
pub const MAX_CASE_VERTICES: usize = 32;

/// A bound precision with its oracle precision and the boundary values of the
/// crate's range analysis.
pub trait Precision: Float + for<'a> Arbitrary<'a> {
    /// The arithmetic the oracle runs in for bounds of this precision.
    type R: Real;
    /// `"f32"` or `"f64"`.
    const NAME: &'static str;
    /// The largest finite value.
    const MAX: Self;
    /// The smallest positive normal value.
    const MIN_POSITIVE: Self;
    /// A quiet NaN.
    const NAN: Self;
    /// Relative precision of [`Self::R`] (a safe upper bound of its unit roundoff).
    const R_EPS: f64;
}

impl Precision for f32 {
    type R = f64;
    const NAME: &'static str = "f32";
    const MAX: Self = f32::MAX;
    const MIN_POSITIVE: Self = f32::MIN_POSITIVE;
    const NAN: Self = f32::NAN;
    const R_EPS: f64 = f64::EPSILON;
}

impl Precision for f64 {
    type R = DoubleDouble;
    const NAME: &'static str = "f64";
    const MAX: Self = f64::MAX;
    const MIN_POSITIVE: Self = f64::MIN_POSITIVE;
    const NAN: Self = f64::NAN;
    const R_EPS: f64 = 1.0 / (1u128 << 100) as f64;
}

/// Exact widening of a bound-precision value to the oracle precision.
#[must_use]
pub fn wide<T: Precision>(x: T) -> T::R {
    T::R::from_f64(x.to_f64())
}

/// The number of boundary values [`Num::Special`] picks from.
pub const SPECIALS: u8 = 28;

/// A raw float of precision `T`, biased towards the interesting values.
#[derive(Arbitrary, Clone, Copy, Debug)]
pub enum Num<T> {
    /// Any bit pattern: NaN, infinities, subnormals, huge values.
    Raw(T),
    /// `mant / 2^31 * 2^exp` with `exp` clamped to `[-60, 60]`.
    Moderate {
        /// Signed mantissa.
        mant: i32,
        /// Binary exponent.
        exp: i8,
    },
    /// A boundary value of the range analysis (see [`special`]).
    Special(u8),
}

impl<T: Precision> Num<T> {
    /// The value.
    #[must_use]
    pub fn get(self) -> T {
        match self {
            Self::Raw(x) => x,
            Self::Moderate { mant, exp } => {
                let e = i32::from(exp).clamp(-60, 60);
                T::from_f64(f64::from(mant) / 2147483648.0 * 2f64.powi(e))
            }
            Self::Special(i) => special(i),
        }
    }
}

/// Boundary value number `i % SPECIALS`: zeros, ones, pi and 2 pi, the
/// largest accepted input and the next value above it, `TINY_LENGTH` and the
/// value below it, `sqrt(eta)`, `eta`, the smallest normal, the largest
/// finite value, infinities, NaN, the unit roundoff, and the neighbours of 1.
#[must_use]
pub fn special<T: Precision>(i: u8) -> T {
    match i % SPECIALS {
        0 => T::ZERO,
        1 => -T::ZERO,
        2 => T::ONE,
        3 => -T::ONE,
        4 => T::HALF,
        5 => T::PI,
        6 => T::PI * T::TWO,
        7 => T::MAX_INPUT,
        8 => -T::MAX_INPUT,
        9 => T::MAX_INPUT.next_up(),
        10 => T::TINY_LENGTH,
        11 => T::TINY_LENGTH.next_down(),
        12 => T::SQRT_ETA_UP,
        13 => T::ETA,
        14 => -T::ETA,
        15 => T::MIN_POSITIVE,
        16 => T::MAX,
        17 => -T::MAX,
        18 => T::INFINITY,
        19 => -T::INFINITY,
        20 => T::NAN,
        21 => T::UNIT_ROUNDOFF,
        22 => T::ONE.next_up(),
        23 => T::ONE.next_down(),
        24 => T::from_f64(1e-3),
        25 => T::PI.next_up(),
        26 => T::PI.next_down(),
        _ => T::from_f64(1e3),
    }
}

/// The values of an array of [`Num`]s.
#[must_use]
pub fn nums<T: Precision, const N: usize>(a: [Num<T>; N]) -> [T; N] {
    a.map(Num::get)
}

/// `true` for a value the crate's constructors accept: finite and at most
/// [`Float::MAX_INPUT`] in magnitude.
#[must_use]
pub fn in_range<T: Float>(x: T) -> bool {
    x.is_finite() && x.abs() <= T::MAX_INPUT
}

/// Checks a constructor's result against the documented validation rule for
/// groups of components checked in order: `Ok` iff every component is in
/// range; otherwise the error names the first group with a bad component, as
/// [`InputError::NonFinite`] (only if that group has a NaN or infinite
/// component) or [`InputError::TooLarge`] (only if it has a finite component
/// above `MAX_INPUT`).
///
/// Returns `true` if every component is in range.
pub fn check_components_result<T: Float, X: Debug>(
    what: &str,
    res: &Result<X, InputError>,
    groups: &[(&[T], Quantity)],
) -> bool {
    let bad = groups.iter().find(|(c, _)| c.iter().any(|&x| !in_range(x)));
    match bad {
        None => true,
        Some((c, q)) => {
            let non_finite = c.iter().any(|x| !x.is_finite());
            let too_large = c.iter().any(|&x| x.is_finite() && x.abs() > T::MAX_INPUT);
            let ok = match res {
                Err(InputError::NonFinite(e)) => e == q && non_finite,
                Err(InputError::TooLarge(e)) => e == q && too_large,
                _ => false,
            };
            assert!(
                ok,
                "{what}: expected NonFinite/TooLarge({q:?}) for components {c:?}, got {res:?}; inputs {groups:?}"
            );
            false
        }
    }
}

/// The Euclidean length of `a`, in `R`, without overflow or underflow of the
/// squares (scaled by the largest component, which is exact to widen).
#[must_use]
pub fn norm<T: Precision>(a: [T; 3]) -> T::R {
    let zero = T::R::from_f64(0.0);
    let s = a.iter().fold(0.0f64, |m, x| m.max(x.to_f64().abs()));
    if s == 0.0 {
        return zero;
    }
    let s = T::R::from_f64(s);
    let mut sum = zero;
    for x in a {
        let y = wide(x).div(s);
        sum = sum.add(y.mul(y));
    }
    s.mul(sum.sqrt())
}

/// EVQ never looser than NEVQ, in speed and in displacement.
pub fn check_evq_le_nevq<T: Precision>(
    evq: DirectedBound<T>,
    nevq: DirectedBound<T>,
    context: &dyn Debug,
) {
    assert!(
        evq.speed <= nevq.speed,
        "({}) evq speed {:?} above nevq speed {:?}; case {context:?}",
        T::NAME,
        evq.speed,
        nevq.speed
    );
    assert!(
        evq.displacement <= nevq.displacement,
        "({}) evq displacement {:?} above nevq displacement {:?}; case {context:?}",
        T::NAME,
        evq.displacement,
        nevq.displacement
    );
}

/// Builds a fuzzed case description, with the vertex list capped at
/// [`MAX_CASE_VERTICES`]. `None` when the description yields no valid input.
#[must_use]
pub fn build_case<T: Precision>(spec: &CaseSpec) -> Option<Case<T>> {
    if spec.vertices.len() > MAX_CASE_VERTICES {
        let mut capped = spec.clone();
        capped.vertices.truncate(MAX_CASE_VERTICES);
        capped.build::<T>()
    } else {
        spec.build::<T>()
    }
}

/// The vertex set of a built case; a built case is valid by construction,
/// so a rejection is a failure.
#[must_use]
pub fn vertex_set<T: Precision>(case: &Case<T>) -> VertexSet<'_, T> {
    VertexSet::try_new(&case.vertices)
        .unwrap_or_else(|e| panic!("({}) built case rejected: {e:?}; case {case:?}", T::NAME))
}

/// `RigidMotion::try_new` on raw components, checked against the documented
/// validation rule ([`check_components_result`]: `Ok` exactly when every
/// component of the centre, `v` and `w` is in range, else the error naming
/// the first offending quantity); the motion if it was accepted.
#[must_use]
pub fn checked_motion<T: Precision>(
    centre: [T; 3],
    linear: [T; 3],
    angular: [T; 3],
    interval: TimeInterval<T>,
) -> Option<RigidMotion<T>> {
    let res = RigidMotion::try_new(
        Point3::from_array(centre),
        Vec3::from_array(linear),
        Vec3::from_array(angular),
        interval,
    );
    let valid = check_components_result(
        "RigidMotion::try_new",
        &res,
        &[
            (&centre, Quantity::Centre),
            (&linear, Quantity::LinearVelocity),
            (&angular, Quantity::AngularVelocity),
        ],
    );
    assert!(
        valid == res.is_ok(),
        "({}) RigidMotion::try_new({centre:?}, {linear:?}, {angular:?}) gave {res:?}",
        T::NAME
    );
    res.ok()
}

/// `run::<f64>(args)` if the fuzzed flag `double` is set, else
/// `run::<f32>(args)`.
#[macro_export]
macro_rules! in_precision {
    ($double:expr, $run:ident($($arg:expr),*)) => {
        if $double {
            $run::<f64>($($arg),*)
        } else {
            $run::<f32>($($arg),*)
        }
    };
}

/// `x` clamped to `[lo, hi]` (for `lo <= hi`).
#[must_use]
pub fn clamp<T: Float>(x: T, lo: T, hi: T) -> T {
    if x < lo {
        lo
    } else if x > hi {
        hi
    } else {
        x
    }
}

/// The typed inputs of the `motion` and `validation` targets.
pub mod inputs {
    use super::Num;
    use arbitrary::Arbitrary;

    /// Raw motion-evaluation input in precision `T`.
    #[derive(Arbitrary, Clone, Debug)]
    pub struct MotionInput<T> {
        /// Rotation centre at the epoch.
        pub centre: [Num<T>; 3],
        /// Linear velocity `v`.
        pub linear: [Num<T>; 3],
        /// Angular velocity `w`.
        pub angular: [Num<T>; 3],
        /// The motion's interval `[start, end]` (the unit interval if invalid).
        pub interval: [Num<T>; 2],
        /// A body point (not validated by the crate: any value).
        pub point: [Num<T>; 3],
        /// Two evaluation times (not validated by the crate: any value).
        pub times: [Num<T>; 2],
        /// A candidate sub-interval for `restrict`.
        pub sub: [Num<T>; 2],
        /// A raw direction (`Direction::Z` if invalid).
        pub n: [Num<T>; 3],
    }

    /// An input in `f32` or in `f64`.
    #[derive(Arbitrary, Clone, Debug)]
    pub enum Precisions<S, D> {
        /// In `f32`.
        Single(S),
        /// In `f64`.
        Double(D),
    }

    /// The `motion` target's input.
    pub type MotionCase = Precisions<MotionInput<f32>, MotionInput<f64>>;

    /// Fully raw input of every constructor, in precision `T`.
    #[derive(Arbitrary, Clone, Debug)]
    pub struct RawInput<T> {
        /// Vertices for `VertexSet::try_new` (possibly empty).
        pub vertices: Vec<[Num<T>; 3]>,
        /// Radius for `BodySummary::from_radius`.
        pub radius: Num<T>,
        /// Direction for `Direction::try_new`.
        pub n: [Num<T>; 3],
        /// Interval for `TimeInterval::try_new`.
        pub interval: [Num<T>; 2],
        /// Centre, `v`, `w` for `RigidMotion::try_new`.
        pub centre: [Num<T>; 3],
        /// Linear velocity.
        pub linear: [Num<T>; 3],
        /// Angular velocity.
        pub angular: [Num<T>; 3],
        /// A candidate sub-interval for `RigidMotion::restrict`.
        pub sub: [Num<T>; 2],
        /// A gap for `DirectedBound::time_to_close`.
        pub gap: Num<T>,
    }

    /// The `validation` target's input.
    pub type ValidationCase = Precisions<RawInput<f32>, RawInput<f64>>;
}

#[cfg(test)]
mod tests {
    use super::Bytes;

    #[test]
    fn bytes_read_zero_past_the_end_and_span_the_range() {
        let mut b = Bytes::new(&[7, 0xff, 0xff, 0x00]);
        assert_eq!(b.u8(), 7);
        // 0xffff: the top of the range, exactly.
        assert_eq!(b.range(-2.0, 3.0), 3.0);
        // One byte left, then zeros: 0x0000 is the bottom.
        assert_eq!(b.range(-2.0, 3.0), -2.0);
        assert_eq!(b.u8(), 0);
        let mut e = Bytes::new(&[]);
        assert_eq!((e.u8(), e.range(-1.0, 1.0)), (0, -1.0));
    }
}
