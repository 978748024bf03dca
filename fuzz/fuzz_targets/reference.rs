//! The oracle against dense sampling. For a fuzzed hard case (in `f64`, or in
//! `f32` where the `f64`-precision oracle used for `f32` bounds is
//! cross-checked as well):
//!
//! * the double-double exact sup speed is not NaN, is at least 0, and is at
//!   least `|speed|` at 257 evenly spaced times of the interval, evaluated by
//!   the oracle's own `Frame::profile(..).speed_at(t)` in double-double (the
//!   closed-form sup against its own sinusoid; a tolerance of 1e-28 of the
//!   sinusoid's coefficients covers double-double rounding only);
//! * it is at least the directed speed computed independently by
//!   `RigidMotion::directed_speed_at` (plain floating point, Rodrigues'
//!   rotation) at the same times, up to a relative 1e-9 (f64; 1e-4 for f32)
//!   of the magnitude `|v| + |w| max |r|` plus 1e-300 absolute: that sample
//!   is a floating-point approximation, so a tolerance is legitimate there;
//! * the exact displacement is not NaN, at least 0 and at most
//!   `sup * length * (1 + 1e-12)`;
//! * for `f32` cases, the `f64`-evaluated oracle agrees with the
//!   double-double one to 1e-9 of the magnitude (so the strict comparisons of
//!   `f32` bounds against the `f64` oracle are meaningful).

#![no_main]

use libfuzzer_sys::fuzz_target;
use motion_bound::reference::{exact, DoubleDouble, Exact, Frame, Real};
use motion_bound::testkit::{Case, CaseSpec};
use motion_bound::BodyPoint;
use motion_bound_fuzz::{build_case, clamp, norm, Precision};

type DD = DoubleDouble;

const SAMPLES: u32 = 257;

fn dd(x: f64) -> DD {
    <DD as Real>::from_f64(x)
}

fn run<T: Precision>(spec: &CaseSpec) {
    let Some(case) = build_case::<T>(spec) else {
        return;
    };
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

    let iv = case.motion.interval();
    let (ta, tb) = (dd(iv.start().to_f64()), dd(iv.end().to_f64()));
    let len = Real::sub(tb, ta);

    // 1. The closed-form sup against the oracle's own sinusoid, in double-double.
    let frame: Frame<DD> = Frame::new(&case.motion, case.n);
    for r in &case.vertices {
        let prof = frame.profile(*r);
        let coeffs = Real::add(
            Real::add(Real::abs(prof.a), Real::abs(prof.p)),
            Real::abs(prof.q),
        );
        let limit = Real::add(sup, Real::mul(coeffs, dd(1e-28)));
        for j in 0..SAMPLES {
            let t = if j == 0 {
                ta
            } else if j == SAMPLES - 1 {
                tb
            } else {
                let t = Real::add(
                    ta,
                    Real::mul(len, dd(f64::from(j) / f64::from(SAMPLES - 1))),
                );
                if t < ta {
                    ta
                } else if t > tb {
                    tb
                } else {
                    t
                }
            };
            let s = Real::abs(prof.speed_at(t));
            assert!(
                !s.is_nan() && s <= limit,
                "({}) sampled |speed| {s:?} at t = {t:?} (sample {j}) exceeds the closed-form sup {sup:?}; vertex {r:?}, profile {prof:?}; case {case:?}",
                T::NAME
            );
        }
    }

    // 2. Against the library's own plain floating-point evaluation of p'(t).n.
    let r_max = case
        .vertices
        .iter()
        .map(|r| norm::<T>(*r).to_f64())
        .fold(0.0f64, f64::max);
    let v_norm = norm::<T>(case.motion.linear().to_array()).to_f64();
    let w_norm = norm::<T>(case.motion.angular().to_array()).to_f64();
    let rel = if T::NAME == "f64" { 1e-9 } else { 1e-4 };
    let tol = rel * (v_norm + w_norm * r_max) + 1e-300;
    let sup_f = sup.to_f64();
    let (s_t, e_t) = (iv.start(), iv.end());
    for j in 0..SAMPLES {
        let t = if j == 0 {
            s_t
        } else if j == SAMPLES - 1 {
            e_t
        } else {
            clamp(
                s_t + (e_t - s_t) * T::from_f64(f64::from(j) / f64::from(SAMPLES - 1)),
                s_t,
                e_t,
            )
        };
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
    let cap = Real::mul(Real::mul(sup, len), dd(1.0 + 1e-12));
    assert!(
        disp <= cap,
        "({}) exact displacement {disp:?} above sup * length = {:?} (sup {sup:?}, length {len:?}); case {case:?}",
        T::NAME,
        Real::mul(sup, len)
    );

    // 4. The f64-evaluated oracle (used for f32 bounds) against double-double.
    if T::NAME == "f32" {
        cross_check_f64_oracle(&case, &ex, v_norm + w_norm * r_max, len.to_f64());
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

fuzz_target!(|input: (CaseSpec, bool)| {
    let (spec, double) = input;
    if double {
        run::<f64>(&spec);
    } else {
        run::<f32>(&spec);
    }
});
