//! The oracle against dense sampling. For a fuzzed hard case (in `f64`, or in
//! `f32` where the `f64`-precision oracle used for `f32` bounds is
//! cross-checked as well), on the exactly rescaled copy of the case that the
//! bound targets' oracle uses (`motion_bound_fuzz::oracle`: speeds of
//! magnitude about 1, `|w|` in `[1, 2)`):
//!
//! * the double-double exact sup speed is not NaN, is at least 0, and is at
//!   least `|speed|` at 257 evenly spaced times of the interval, evaluated by
//!   the oracle's own sinusoid `a + p cos(omega t) + q sin(omega t)` (the
//!   formula of `SpeedProfile::speed_at`) in double-double; the tolerance is
//!   1e-28 of the sinusoid's coefficients (double-double rounding) plus
//!   2^-520 of the case's speed magnitude (coefficients whose squares
//!   underflow in the reference's `hypot`);
//! * it is at least the directed speed computed independently by
//!   `RigidMotion::directed_speed_at` (plain floating point, Rodrigues'
//!   rotation) at the same times, up to a relative 1e-9 (f64; 1e-4 for f32)
//!   of the magnitude `|v| + |w| max |r|` plus 8 `eta` of the bound type
//!   (underflow): that sample is a floating-point approximation, so a
//!   tolerance is legitimate there;
//! * the exact displacement is not NaN, at least 0 and at most
//!   `sup * length (1 + 1e-12)` plus 1e-28 (double-double rounding of the
//!   phase) and 2^-520 (as above) of the speed magnitude times the length,
//!   plus 64 `eta` (sweeps so short that the angle is subnormal);
//! * for `f32` cases, the `f64`-evaluated oracle agrees with the
//!   double-double one to 1e-9 of the magnitude (so the strict comparisons of
//!   `f32` bounds against the `f64` oracle are meaningful).

#![no_main]

use libfuzzer_sys::fuzz_target;
use motion_bound::reference::{exact, DoubleDouble, Exact, Frame, Real};
use motion_bound::testkit::{Case, CaseSpec};
use motion_bound::BodyPoint;
use motion_bound_fuzz::{build_case, clamp, in_precision, norm, oracle::pow2, Precision, Scaled};

type DD = DoubleDouble;

const SAMPLES: u32 = 257;

fn dd(x: f64) -> DD {
    <DD as Real>::from_f64(x)
}

/// The `j`-th of [`SAMPLES`] evenly spaced times of `[start, end]`, with both
/// ends exact.
fn sample_time<X: PartialOrd + Copy>(j: u32, start: X, end: X, lerp: impl Fn(X, X, f64) -> X) -> X {
    if j == 0 {
        start
    } else if j == SAMPLES - 1 {
        end
    } else {
        let t = lerp(start, end, f64::from(j) / f64::from(SAMPLES - 1));
        if t < start {
            start
        } else if t > end {
            end
        } else {
            t
        }
    }
}

fn run<T: Precision>(spec: &CaseSpec) {
    let Some(original) = build_case::<T>(spec) else {
        return;
    };
    let scaled = Scaled::new(&original);
    let case = &scaled.case;
    // What the reference cannot resolve: coefficients whose squares
    // underflow in its hypot, relative to the (rescaled) speed magnitude.
    let floor = pow2(-520) * scaled.mag;
    let ex: Exact<DD> = exact::<T, DD>(&case.vertices, &case.motion, case.n);
    let (sup, disp) = (ex.sup_speed, ex.displacement);
    assert!(
        !sup.is_nan() && !disp.is_nan(),
        "({}) oracle NaN: {ex:?}; case {case:?}",
        T::NAME
    );
    assert!(
        sup >= dd(0.0) && disp >= dd(0.0),
        "({}) negative oracle: {ex:?}; case {case:?}",
        T::NAME
    );

    if !scaled.faithful {
        // A velocity component too large to rescale with the rest (along a
        // component of n below about 2^-500) was dropped: the rescaled case
        // is not the original's, so the reference cannot be run on it.
        return;
    }

    let iv = case.motion.interval();
    let (ta, tb) = (dd(iv.start().to_f64()), dd(iv.end().to_f64()));
    let len = Real::sub(tb, ta);

    // 1. The closed-form sup against the oracle's own sinusoid, in
    //    double-double; the angle's sine and cosine are shared by all vertices.
    let frame: Frame<DD> = Frame::new(&case.motion, case.n);
    let profiles: Vec<_> = case
        .vertices
        .iter()
        .map(|r| {
            let prof = frame.profile(*r);
            let coeffs = Real::add(
                Real::add(Real::abs(prof.a), Real::abs(prof.p)),
                Real::abs(prof.q),
            );
            let limit = Real::add(Real::add(sup, Real::mul(coeffs, dd(1e-28))), dd(floor));
            (r, prof, limit)
        })
        .collect();
    let omega = profiles.first().map_or(dd(0.0), |p| p.1.omega);
    for j in 0..SAMPLES {
        let t = sample_time(j, ta, tb, |a, b, f| {
            Real::add(a, Real::mul(Real::sub(b, a), dd(f)))
        });
        let (sin, cos) = Real::mul(omega, t).sin_cos();
        for (r, prof, limit) in &profiles {
            // SpeedProfile::speed_at, with the angle's sin and cos shared
            let s = Real::abs(Real::add(
                Real::add(prof.a, Real::mul(prof.p, cos)),
                Real::mul(prof.q, sin),
            ));
            assert!(
                !s.is_nan() && s <= *limit,
                "({}) sampled |speed| {s:?} at t = {t:?} (sample {j}) exceeds the closed-form sup {sup:?}; vertex {r:?}, profile {prof:?}; case {case:?}",
                T::NAME
            );
        }
    }

    // 2. Against the library's own plain floating-point evaluation of p'(t).n.
    // The lever arm is measured from the rotation centre in the body frame.
    let c = case.motion.local_centre().to_array().map(|x| x.to_f64());
    let r_max = case
        .vertices
        .iter()
        .map(|r| {
            let d: [f64; 3] = core::array::from_fn(|k| r[k].to_f64() - c[k]);
            (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
        })
        .fold(0.0f64, f64::max);
    let v_norm = norm::<T>(case.motion.linear().to_array()).to_f64();
    let w_norm = norm::<T>(case.motion.angular().to_array()).to_f64();
    let rel = if T::NAME == "f64" { 1e-9 } else { 1e-4 };
    let tol = rel * (v_norm + w_norm * r_max) + 8.0 * T::ETA.to_f64() + floor;
    let sup_f = sup.to_f64();
    let (s_t, e_t) = (iv.start(), iv.end());
    for j in 0..SAMPLES {
        let t = sample_time(j, s_t, e_t, |a, b, f| {
            clamp(a + (b - a) * T::from_f64(f), a, b)
        });
        for r in &case.vertices {
            let s = case
                .motion
                .directed_speed_at(BodyPoint::from_array(*r), t, case.n)
                .to_f64();
            assert!(
                !s.is_nan() && s.abs() <= sup_f + tol,
                "({}) directed_speed_at({r:?}, {t:?}) = {s:e} exceeds the exact sup {sup_f:e} by more than {tol:e}; case {case:?}",
                T::NAME
            );
        }
    }

    // 3. The displacement is at most sup * length.
    let slack = 1e-28 + pow2(-520);
    let cap = Real::add(
        Real::mul(Real::mul(sup, len), dd(1.0 + 1e-12)),
        Real::add(
            Real::mul(len, dd(slack * scaled.mag)),
            dd(64.0 * pow2(-1074)),
        ),
    );
    assert!(
        disp <= cap,
        "({}) exact displacement {disp:?} above sup * length = {:?} (sup {sup:?}, length {len:?}); case {case:?}",
        T::NAME,
        Real::mul(sup, len)
    );

    // 4. The f64-evaluated oracle (used for f32 bounds) against double-double.
    if T::NAME == "f32" {
        cross_check_f64_oracle(case, &ex, v_norm + w_norm * r_max, len.to_f64());
    }
}

fn cross_check_f64_oracle<T: Precision>(case: &Case<T>, ex: &Exact<DD>, scale: f64, len: f64) {
    let e64: Exact<f64> = exact::<T, f64>(&case.vertices, &case.motion, case.n);
    let (s_dd, d_dd) = (ex.sup_speed.to_f64(), ex.displacement.to_f64());
    let tol = 1e-9 * scale + 1e-300;
    assert!(
        (e64.sup_speed - s_dd).abs() <= tol,
        "({}) f64 oracle sup {:e} differs from double-double {s_dd:e} by more than {tol:e}; case {case:?}",
        T::NAME,
        e64.sup_speed
    );
    let dtol = tol * len + 1e-300;
    assert!(
        (e64.displacement - d_dd).abs() <= dtol,
        "({}) f64 oracle displacement {:e} differs from double-double {d_dd:e} by more than {dtol:e}; case {case:?}",
        T::NAME,
        e64.displacement
    );
}

fuzz_target!(|input: (CaseSpec, bool)| in_precision!(input.1, run(&input.0)));
