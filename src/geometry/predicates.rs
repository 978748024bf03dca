//! Orientation predicates: a floating-point filter, then an exact fallback.
//!
//! Shewchuk's `orient2d` and `orient3d` determinants are evaluated once in
//! floating point, with his a-priori error bounds (J. R. Shewchuk, "Adaptive
//! Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates",
//! Discrete Comput. Geom. 18, 1997,
//! [doi:10.1007/PL00009321](https://doi.org/10.1007/PL00009321), section 4.2:
//! `errboundA = (3 + 16u) u` in 2D and `(7 + 56u) u` in 3D, times the
//! permanent), written in the unit roundoff `u` of `T` and extended by an
//! absolute allowance for underflow (each product may lose `eta / 2`). When
//! the filter cannot call the sign, the inputs are widened to `f64` (exact)
//! and the sign is decided by the adaptive, exact predicates of the
//! [`robust`] crate (georust's no_std, allocation-free transcription of the
//! same paper: expansion arithmetic until the sign is certain).
//!
//! Expansion arithmetic is exact only without underflow or overflow (and
//! with IEEE binary64 round-to-nearest-even arithmetic, no extended
//! precision: not x87), so the fallback is taken only when every coordinate
//! is 0 or of magnitude in `[2^-200, 2^200]` ([`EXACT_RANGE`]). Every finite
//! `f32` is (its least subnormal is `2^-149`). `closest` passes the caller's
//! points when they are in the range and else points rescaled exactly by
//! a power of two to a largest coordinate in `[1, 2)`, so for `f64` only
//! nonzero coordinates below `2^-200` times the largest are excluded. The
//! slowest path keeps about 5 KB of expansions on the stack (no heap).
//!
//! A sign returned as `+1` or `-1` is the exact sign of the determinant of
//! the floating-point inputs. `0` means exactly zero, or, outside the exact
//! range only, "too close to call"; callers treat `0` as "touching", the
//! conservative reading for a distance, and verify what they conclude from
//! it.

use crate::{Float, Vec3};

/// A determinant: an approximation of its value and its exact sign.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Orientation<T> {
    /// `+1` or `-1`: the exact sign; `0`: exactly zero, or (only for
    /// coordinates outside [`EXACT_RANGE`]) too close to call.
    pub(crate) sign: i8,
    /// An approximation of the determinant (its magnitude ranks projections;
    /// rounded to `T`, it may be 0 when `sign` is not).
    pub(crate) value: T,
}

/// The magnitudes `[2^-200, 2^200]` within which (or at 0) every coordinate
/// must lie for the exact fallback (`proofs/floating-point.md`, Lemma FP-M).
///
/// Every such `f64` is a multiple of `2^-252`, and rounding a multiple of
/// `2^-m` to `f64` gives one again, so every component of Shewchuk's
/// expansions (sums, differences, Dekker's split parts, products of up to
/// three factors and their error terms) is a multiple of `2^-756`, and his
/// error bounds are small constants times such values (at least about
/// `2^-860`): far above the least normal `2^-1022`, so no step underflows.
/// The largest values stay below about `2^606`: no overflow.
pub(crate) const EXACT_RANGE: (f64, f64) = (
    // 2^-200 and 2^200, written as bit patterns (const-evaluable).
    f64::from_bits((1023 - 200) << 52),
    f64::from_bits((1023 + 200) << 52),
);

/// Whether every coordinate is 0 or within [`EXACT_RANGE`].
fn in_exact_range(coords: &[f64]) -> bool {
    coords
        .iter()
        .all(|&c| c == 0.0 || (EXACT_RANGE.0..=EXACT_RANGE.1).contains(&c.abs()))
}

/// Whether every coordinate of these points is 0 or within [`EXACT_RANGE`]
/// (then every sign of [`orient2d`] and [`orient3d`] on them is exact).
pub(crate) fn points_in_exact_range<T: Float>(points: &[Vec3<T>]) -> bool {
    points
        .iter()
        .all(|p| in_exact_range(&[p.x.to_f64(), p.y.to_f64(), p.z.to_f64()]))
}

/// The sign of an exact determinant value (robust returns one whose sign is
/// exact).
fn sign_of(x: f64) -> i8 {
    if x > 0.0 {
        1
    } else if x < 0.0 {
        -1
    } else {
        0
    }
}

fn filtered<T: Float>(det: T, errbound: T) -> Orientation<T> {
    let sign = if det > errbound {
        1
    } else if -det > errbound {
        -1
    } else {
        // Also NaN: not certain.
        0
    };
    Orientation { sign, value: det }
}

/// `orient3d(a, b, c, d)`: positive when `d` lies below the plane through
/// `a, b, c` oriented counterclockwise seen from above (Shewchuk's
/// convention), i.e. the determinant of the rows `a - d, b - d, c - d`.
pub(crate) fn orient3d<T: Float>(a: Vec3<T>, b: Vec3<T>, c: Vec3<T>, d: Vec3<T>) -> Orientation<T> {
    let o = orient3d_filtered(a, b, c, d);
    if o.sign != 0 {
        return o;
    }
    let [a, b, c, d] = [a, b, c, d].map(|p| [p.x.to_f64(), p.y.to_f64(), p.z.to_f64()]);
    if !in_exact_range([a, b, c, d].as_flattened()) {
        return o;
    }
    let p = |q: [f64; 3]| robust::Coord3D {
        x: q[0],
        y: q[1],
        z: q[2],
    };
    let exact = robust::orient3d(p(a), p(b), p(c), p(d));
    Orientation {
        sign: sign_of(exact),
        value: T::from_f64(exact),
    }
}

/// The filter of [`orient3d`] alone.
fn orient3d_filtered<T: Float>(a: Vec3<T>, b: Vec3<T>, c: Vec3<T>, d: Vec3<T>) -> Orientation<T> {
    let (ad, bd, cd) = (a - d, b - d, c - d);
    let bdxcdy = bd.x * cd.y;
    let cdxbdy = cd.x * bd.y;
    let cdxady = cd.x * ad.y;
    let adxcdy = ad.x * cd.y;
    let adxbdy = ad.x * bd.y;
    let bdxady = bd.x * ad.y;
    let det = ad.z * (bdxcdy - cdxbdy) + bd.z * (cdxady - adxcdy) + cd.z * (adxbdy - bdxady);
    let permanent = (bdxcdy.abs() + cdxbdy.abs()) * ad.z.abs()
        + (cdxady.abs() + adxcdy.abs()) * bd.z.abs()
        + (adxbdy.abs() + bdxady.abs()) * cd.z.abs();
    let z_sum = ad.z.abs() + bd.z.abs() + cd.z.abs();
    filtered(det, crate::rounding::orient3d_error(permanent, z_sum))
}

/// `orient2d(a, b, c)`: positive when `a, b, c` turn counterclockwise.
pub(crate) fn orient2d<T: Float>(a: [T; 2], b: [T; 2], c: [T; 2]) -> Orientation<T> {
    let o = orient2d_filtered(a, b, c);
    if o.sign != 0 {
        return o;
    }
    let [a, b, c] = [a, b, c].map(|p| [p[0].to_f64(), p[1].to_f64()]);
    if !in_exact_range([a, b, c].as_flattened()) {
        return o;
    }
    let p = |q: [f64; 2]| robust::Coord { x: q[0], y: q[1] };
    let exact = robust::orient2d(p(a), p(b), p(c));
    Orientation {
        sign: sign_of(exact),
        value: T::from_f64(exact),
    }
}

/// The filter of [`orient2d`] alone.
fn orient2d_filtered<T: Float>(a: [T; 2], b: [T; 2], c: [T; 2]) -> Orientation<T> {
    let acx = a[0] - c[0];
    let bcx = b[0] - c[0];
    let acy = a[1] - c[1];
    let bcy = b[1] - c[1];
    let l = acx * bcy;
    let r = acy * bcx;
    filtered(l - r, crate::rounding::orient2d_error(l.abs() + r.abs()))
}

/// The projection of `p` onto the coordinate plane orthogonal to axis
/// `drop`, in the cyclic order `(y, z)`, `(z, x)`, `(x, y)`, so that
/// `orient2d` of projected points is the `drop` component of the normal
/// `(b - a) x (c - a)`.
#[inline]
pub(crate) fn project<T: Float>(p: Vec3<T>, drop: usize) -> [T; 2] {
    match drop {
        0 => [p.y, p.z],
        1 => [p.z, p.x],
        _ => [p.x, p.y],
    }
}

/// The coordinate of `p` along axis `k`.
#[inline]
pub(crate) fn coord<T: Float>(p: Vec3<T>, k: usize) -> T {
    match k {
        0 => p.x,
        1 => p.y,
        _ => p.z,
    }
}

#[cfg(test)]
mod tests {
    use super::{orient2d, orient2d_filtered, orient3d, orient3d_filtered, project};
    use crate::Vec3;

    /// Signs the filter cannot call are decided exactly. Expected signs
    /// from hand analysis: `f64(2/3) = 6004799503160661 / 2^53` lies below
    /// `2/3`, and `0.5 + 2^-53` is exact.
    #[test]
    fn uncertain_signs_fall_back_to_exact() {
        // The plane z = (x + y) / 3 through a, b, c (counterclockwise from
        // above); at (1, 1) it is at 2/3, and the nearest f64 is just below.
        let a = Vec3::new(0.0f64, 0.0, 0.0);
        let b = Vec3::new(3.0, 0.0, 1.0);
        let c = Vec3::new(0.0, 3.0, 1.0);
        let d = Vec3::new(1.0, 1.0, 2.0 / 3.0);
        // f64(2/3) = 6004799503160661 / 2^53 and 3 * 6004799503160661 =
        // 2^54 - 1, so f64(2/3) = 2/3 - 1 / (3 2^53).
        assert_eq!(2.0f64 / 3.0, 6_004_799_503_160_661.0 / 2f64.powi(53));
        assert_eq!(3 * 6_004_799_503_160_661u64, (1 << 54) - 1);
        let o = orient3d(a, b, c, d);
        assert_eq!(o.sign, 1, "just below the plane: {o:?}");
        assert_eq!(orient3d(b, a, c, d).sign, -1, "swapped orientation");
        // The filter alone cannot call it, so this exercises the fallback.
        assert_eq!(orient3d_filtered(a, b, c, d).sign, 0);
        // f32: the same configuration widened exactly (f32(2/3) is above
        // 2/3: 11184811 / 2^24).
        let w = |p: Vec3<f64>| Vec3::new(p.x as f32, p.y as f32, p.z as f32);
        let d32 = Vec3::new(1.0f32, 1.0, 2.0 / 3.0);
        // f32(2/3) = 11184811 / 2^24 and 3 * 11184811 = 2^25 + 1.
        assert_eq!(2.0f32 / 3.0, 11_184_811.0 / 2f32.powi(24));
        assert_eq!(3 * 11_184_811u32, (1 << 25) + 1);
        assert_eq!(orient3d_filtered(w(a), w(b), w(c), d32).sign, 0);
        assert_eq!(orient3d(w(a), w(b), w(c), d32).sign, -1, "f32: above");
        // orient2d: (0.5, 0.5 + 2^-53) is left of the line from (0, 0) to
        // (1, 1); the computed determinant is 2^-53, below the filter's bound.
        let up = 0.5 + f64::EPSILON / 2.0;
        assert_eq!(orient2d_filtered([0.0, 0.0], [1.0, 1.0], [0.5, up]).sign, 0);
        assert_eq!(orient2d([0.0, 0.0], [1.0, 1.0], [0.5, up]).sign, 1);
        assert_eq!(orient2d([1.0, 1.0], [0.0, 0.0], [0.5, up]).sign, -1);
        assert_eq!(
            orient2d([0.0, 0.0], [1.0, 1.0], [0.5, 0.5]).sign,
            0,
            "exactly collinear"
        );
        // Outside the exact range (a coordinate of 1e-300 beside ones of
        // order 1) the fallback is not taken: "too close to call".
        let tiny = Vec3::new(1e-300, 0.0, 0.0);
        assert_eq!(orient3d(tiny, b, c, d).sign, 0, "documented guard");
    }

    #[test]
    fn signs_of_simple_configurations() {
        let a = Vec3::new(0.0f64, 0.0, 0.0);
        let b = Vec3::new(1.0, 0.0, 0.0);
        let c = Vec3::new(0.0, 1.0, 0.0);
        assert_eq!(
            orient3d(a, b, c, Vec3::new(0.0, 0.0, -1.0)).sign,
            1,
            "below is positive"
        );
        assert_eq!(
            orient3d(a, b, c, Vec3::new(0.3, 0.3, 1.0)).sign,
            -1,
            "above is negative"
        );
        assert_eq!(
            orient3d(a, b, c, Vec3::new(0.3, 7.0, 0.0)).sign,
            0,
            "in the plane"
        );
        assert_eq!(
            orient3d(a, b, c, a).sign,
            0,
            "a repeated vertex is exactly zero"
        );
        assert_eq!(orient2d([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]).sign, 1, "ccw");
        assert_eq!(
            orient2d([0.0f32, 0.0], [1.0, 1.0], [2.0, 2.0]).sign,
            0,
            "collinear"
        );
        let n = (b - a).cross(c - a);
        assert!(n.z > 0.0, "normal along z");
        assert_eq!(
            orient2d(project(a, 2), project(b, 2), project(c, 2)).sign,
            1,
            "the dropped-axis orientation is the normal's component"
        );
    }
}

/// The signs against exact integer arithmetic (`i128`), independent of the
/// `robust` crate: near-degenerate integer configurations (exactly
/// coplanar or collinear, then moved by one unit) whose determinants the
/// filter cannot call, scaled by powers of two across the exact range.
#[cfg(test)]
mod exact_arithmetic {
    use super::{orient2d, orient2d_filtered, orient3d, orient3d_filtered};
    use crate::Vec3;
    use proptest::prelude::*;

    type I3 = [i64; 3];

    fn det3(a: I3, b: I3, c: I3, d: I3) -> i128 {
        let r = |p: I3| [0, 1, 2].map(|k| i128::from(p[k]) - i128::from(d[k]));
        let (x, y, z) = (r(a), r(b), r(c));
        x[2] * (y[0] * z[1] - z[0] * y[1])
            + y[2] * (z[0] * x[1] - x[0] * z[1])
            + z[2] * (x[0] * y[1] - y[0] * x[1])
    }

    fn sign(x: i128) -> i8 {
        x.signum() as i8
    }

    /// `a + s (b - a) + t (c - a) + nudge` (exactly coplanar without the
    /// nudge), `|a| <= 2^la`, `|b - a|, |c - a| <= 2^le`, `|s|, |t| <= 2^ls`.
    fn near_plane(la: u32, le: u32, ls: u32) -> impl Strategy<Value = (I3, I3, I3, I3)> {
        let p = |m: i64| [-m..=m, -m..=m, -m..=m];
        (
            p(1 << la),
            p(1 << le),
            p(1 << le),
            (-(1i64 << ls)..=1 << ls, -(1i64 << ls)..=1 << ls),
            (0usize..3, -1i64..=1),
        )
            .prop_map(|(a, e, f, (s, t), (k, nudge))| {
                let b = [0, 1, 2].map(|i| a[i] + e[i]);
                let c = [0, 1, 2].map(|i| a[i] + f[i]);
                let mut d = [0, 1, 2].map(|i| a[i] + s * e[i] + t * f[i]);
                d[k] += nudge;
                (a, b, c, d)
            })
    }

    proptest! {
        #[test]
        fn orient3d_has_the_exact_sign((a, b, c, d) in near_plane(38, 18, 18), k in prop_oneof![Just(0i32), Just(-60), Just(-150), Just(-190), Just(150)]) {
            let want = sign(det3(a, b, c, d));
            let scale = 2f64.powi(k);
            // Exact: integers below 2^53, scaled by a power of two within range.
            let v = |p: I3| Vec3::new(p[0] as f64 * scale, p[1] as f64 * scale, p[2] as f64 * scale);
            let got = orient3d(v(a), v(b), v(c), v(d));
            prop_assert_eq!(got.sign, want, "det {}", det3(a, b, c, d));
            let filtered = orient3d_filtered(v(a), v(b), v(c), v(d)).sign;
            prop_assert!(filtered == 0 || filtered == want, "the filter is never wrong");
        }

        #[test]
        fn orient3d_has_the_exact_sign_in_f32((a, b, c, d) in near_plane(22, 9, 9)) {
            // Coordinates below 2^23: exact in f32.
            let v = |p: I3| Vec3::new(p[0] as f32, p[1] as f32, p[2] as f32);
            prop_assert_eq!(orient3d(v(a), v(b), v(c), v(d)).sign, sign(det3(a, b, c, d)));
        }

        #[test]
        fn orient2d_has_the_exact_sign(a in [-(1i64 << 50)..=1 << 50, -(1i64 << 50)..=1 << 50], e in [-(1i64 << 25)..=1 << 25, -(1i64 << 25)..=1 << 25], s in -(1i64 << 25)..=1 << 25, nudge in -1i64..=1, k in prop_oneof![Just(0i32), Just(-150), Just(140)]) {
            let b = [a[0] + e[0], a[1] + e[1]];
            let c = [a[0] + s * e[0], a[1] + s * e[1] + nudge];
            let det = (i128::from(a[0]) - i128::from(c[0])) * (i128::from(b[1]) - i128::from(c[1]))
                - (i128::from(a[1]) - i128::from(c[1])) * (i128::from(b[0]) - i128::from(c[0]));
            let scale = 2f64.powi(k);
            let v = |p: [i64; 2]| [p[0] as f64 * scale, p[1] as f64 * scale];
            prop_assert_eq!(orient2d(v(a), v(b), v(c)).sign, sign(det));
            let filtered = orient2d_filtered(v(a), v(b), v(c)).sign;
            prop_assert!(filtered == 0 || filtered == sign(det), "the filter is never wrong");
        }
    }

    /// The near-plane family does exercise the fallback (else the tests
    /// above would only check the filter).
    #[test]
    fn the_family_reaches_the_fallback() {
        let a = [1i64 << 38, -(1 << 37), 12345];
        let (e, f) = ([1i64 << 18, 3, -7], [5, -(1i64 << 18), 11]);
        let b = [0, 1, 2].map(|i| a[i] + e[i]);
        let c = [0, 1, 2].map(|i| a[i] + f[i]);
        let mut d = [0, 1, 2].map(|i| a[i] + 100_000 * e[i] - 99_999 * f[i]);
        d[2] += 1;
        let v = |p: I3| Vec3::new(p[0] as f64, p[1] as f64, p[2] as f64);
        assert_ne!(det3(a, b, c, d), 0, "nudged off the plane");
        assert_eq!(
            orient3d_filtered(v(a), v(b), v(c), v(d)).sign,
            0,
            "filter undecided"
        );
        assert_eq!(
            orient3d(v(a), v(b), v(c), v(d)).sign,
            sign(det3(a, b, c, d))
        );
    }
}
