//! Soundness of NEVQ and EVQ against the exact high-precision oracle, in f32
//! and f64, on cases biased to the hard ones (`proofs/03-nevq.md`,
//! `proofs/04-evq-case-split.md`, `proofs/05-evq-le-nevq.md`,
//! `proofs/06-sub-intervals.md`, `proofs/floating-point.md`).

mod common;

use common::{case_spec, cases, check_sound, Oracle};
use motion_bound::{evq, nevq, VertexSet};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

fn both_bounds_sound<T: Oracle>(
    spec: &motion_bound::testkit::CaseSpec,
) -> Result<(), TestCaseError> {
    let Some(case) = spec.build::<T>() else {
        return Ok(());
    };
    let body = VertexSet::try_new(&case.vertices).expect("testkit builds valid bodies");
    let n = nevq(&body.summary(), &case.motion, case.n);
    check_sound(&case, n.speed, n.displacement, "NEVQ")?;
    let e = evq(&body, &case.motion, case.n);
    check_sound(&case, e.speed, e.displacement, "EVQ")?;
    prop_assert!(
        e.speed <= n.speed,
        "EVQ {:?} looser than NEVQ {:?}",
        e.speed,
        n.speed
    );
    prop_assert!(
        e.displacement <= n.displacement,
        "EVQ displacement looser than NEVQ"
    );
    Ok(())
}

fn sub_interval_sound<T: Oracle>(
    spec: &motion_bound::testkit::CaseSpec,
    f0: f64,
    f1: f64,
) -> Result<(), TestCaseError> {
    let Some(case) = spec.build::<T>() else {
        return Ok(());
    };
    let iv = case.motion.interval();
    let (a, b) = (iv.start().to_f64(), iv.end().to_f64());
    let (lo, hi) = if f0 <= f1 { (f0, f1) } else { (f1, f0) };
    let ta = T::from_f64(a + (b - a) * lo)
        .max_nan(iv.start())
        .min_nan(iv.end());
    let tb = T::from_f64(a + (b - a) * hi).max_nan(ta).min_nan(iv.end());
    let sub = case.motion.restrict(ta, tb).expect("inside the interval");
    let sub_case = motion_bound::testkit::Case {
        vertices: case.vertices.clone(),
        motion: sub,
        n: case.n,
    };
    let body = VertexSet::try_new(&case.vertices).expect("valid body");
    let e = evq(&body, &sub, case.n);
    check_sound(&sub_case, e.speed, e.displacement, "EVQ on a sub-interval")?;
    let full = evq(&body, &case.motion, case.n);
    // Monotonicity holds exactly for the exact values; the computed ones may
    // differ within the rounding margin (proofs/floating-point.md, "EVQ"):
    // 64 u (NEVQ + |w|_1 R (1 + theta_m)).
    let nv = nevq(&body.summary(), &case.motion, case.n).speed.to_f64();
    let w1 = case.motion.angular().norm_l1().to_f64();
    let theta_m = (case.motion.angular_speed() * iv.end()).to_f64().abs();
    let r = body.summary().max_radius().to_f64();
    let tol = 64.0 * T::UNIT_ROUNDOFF.to_f64() * (nv + w1 * r * (1.0 + theta_m));
    prop_assert!(
        e.speed.to_f64() <= full.speed.to_f64() + tol,
        "a sub-interval's EVQ {:?} exceeds the whole interval's {:?}",
        e.speed,
        full.speed
    );
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    #[test]
    fn bounds_dominate_the_exact_motion_f64(spec in case_spec()) {
        both_bounds_sound::<f64>(&spec)?;
    }

    #[test]
    fn bounds_dominate_the_exact_motion_f32(spec in case_spec()) {
        both_bounds_sound::<f32>(&spec)?;
    }

    #[test]
    fn sub_interval_bounds_are_sound_and_no_larger_f64(spec in case_spec(), f0 in 0.0f64..1.0, f1 in 0.0f64..1.0) {
        sub_interval_sound::<f64>(&spec, f0, f1)?;
    }

    #[test]
    fn sub_interval_bounds_are_sound_and_no_larger_f32(spec in case_spec(), f0 in 0.0f64..1.0, f1 in 0.0f64..1.0) {
        sub_interval_sound::<f32>(&spec, f0, f1)?;
    }
}
