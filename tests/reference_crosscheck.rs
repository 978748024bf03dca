//! The closed-form oracle against two independent computations: dense
//! sampling batched with faer (`S = a + V D`), and textbook integrals
//! (`proofs/07-reference.md`).

mod common;

use approx::assert_relative_eq;
use common::{cases, plain_spec};
use motion_bound::reference::{exact, sampled::sample_speeds, Exact};
use motion_bound::{Direction, RigidMotion, TimeInterval, Vec3};
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases() / 4))]

    /// The sampled maximum never exceeds the closed-form sup, and falls short
    /// of it by at most the speed's Lipschitz constant times the sample step;
    /// the trapezoid rule agrees with the closed-form integral to first order.
    #[test]
    fn closed_form_agrees_with_dense_faer_sampling(spec in plain_spec()) {
        let Some(case) = spec.build::<f64>() else { return Ok(()) };
        let m = 4001;
        let s = sample_speeds(&case.vertices, &case.motion, case.n, m);
        let ex: Exact<f64> = exact(&case.vertices, &case.motion, case.n);
        let iv = case.motion.interval();
        let h = iv.length() / (m - 1) as f64;
        let omega = case.motion.angular_speed();
        let rmax = case.vertices.iter().map(|r| Vec3::from_array(*r).length()).fold(0.0, f64::max);
        let amp = case.n.get().cross(case.motion.angular()).length() * rmax;
        let slope = omega * amp; // |d/dt s_i(t)| <= |w| |c| |r_i|
        let round = 1e-13 * (ex.sup_speed + amp + case.motion.linear().length());
        prop_assert!(s.max_abs() <= ex.sup_speed + round, "sampled {} above sup {}", s.max_abs(), ex.sup_speed);
        prop_assert!(ex.sup_speed <= s.max_abs() + slope * h + round, "sup {} far above samples {}", ex.sup_speed, s.max_abs());
        let trap = s.max_trapezoid();
        let tol = iv.length() * slope * h + round * iv.length() + 1e-300;
        prop_assert!((trap - ex.displacement).abs() <= tol, "trapezoid {trap} vs integral {}", ex.displacement);
    }
}

#[test]
fn full_turns_integrate_to_four_amplitudes_per_turn() {
    // Pure rotation, a = 0: integral of |B cos| over k turns is 4 B k / |w|.
    let w = 3.0;
    let turns = 5.0;
    let motion = RigidMotion::try_new(
        motion_bound::Point3::ORIGIN,
        Vec3::ZERO,
        Vec3::new(0.0, 0.0, w),
        TimeInterval::try_new(0.0, turns * core::f64::consts::TAU / w).unwrap(),
    )
    .unwrap();
    let r = 0.7;
    let e: Exact<f64> = exact(&[[r, 0.0, 0.0]], &motion, Direction::X);
    let b = w * r;
    assert_relative_eq!(e.displacement, 4.0 * b * turns / w, max_relative = 1e-13);
    assert_relative_eq!(e.sup_speed, b, max_relative = 1e-15);
}

#[test]
fn a_dominant_linear_term_never_crosses_zero() {
    // |a| > B: |a + B cos| = a + B cos, whose integral over [0, T] is
    // a T + (B/w) sin(w T) (for phase 0).
    let (w, a, r): (f64, f64, f64) = (2.0, 5.0, 1.0);
    let motion = RigidMotion::try_from_arrays([0.0; 3], [0.0, a, 0.0], [0.0, 0.0, w]).unwrap();
    // n = y: s(t) = a + (w x R(t) r).y = a + w r cos(w t).
    let e: Exact<f64> = exact(&[[r, 0.0, 0.0]], &motion, Direction::Y);
    assert_relative_eq!(
        e.displacement,
        a + (r * w / w) * w.sin(),
        max_relative = 1e-14
    );
    assert_relative_eq!(e.sup_speed, a + w * r, max_relative = 1e-15);
}
