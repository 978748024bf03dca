//! One-sided (signed) directed bounds (`proofs/10-one-sided.md`): sound
//! against the exact closed form of the largest signed speed, for vertex
//! sets and balls, in f32 and f64 on the hard cases; never above the
//! absolute bounds; and strictly tighter where a body recedes.

mod common;

use common::{ball_around_first, c_over_n, case_spec, cases};
use motion_bound::reference::dd::DoubleDouble;
use motion_bound::reference::{exact_sup_signed, Real};
use motion_bound::testkit::CaseSpec;
use motion_bound::{BoundKind, Direction, Float, PreparedMotion, RigidMotion, VertexSet};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

/// The absolute bound plus the difference of the two bounds' rounding
/// margins, `64 u (sum_k |v_k n_k| + (|n x w| + |w|_1) R) + 64 eta` (`R` the
/// largest distance from the rotation centre): the one-sided
/// bound is never looser than the absolute one beyond that
/// (`proofs/10-one-sided.md`, "Floating point").
fn slack_above<T: Float>(abs: T, motion: &RigidMotion<T>, n: Direction<T>, radius: f64) -> f64 {
    let (v, w, n) = (motion.linear(), motion.angular(), n.get());
    let a_mag =
        (v.x * n.x).abs().to_f64() + (v.y * n.y).abs().to_f64() + (v.z * n.z).abs().to_f64();
    let c = n.cross(w).length().to_f64() + w.norm_l1().to_f64();
    let u = T::UNIT_ROUNDOFF.to_f64();
    abs.to_f64() + 64.0 * u * (a_mag + c * radius) + 64.0 * T::ETA.to_f64()
}

fn signed_sound<T: Float, R: Real>(spec: &CaseSpec, grow: f64) -> Result<(), TestCaseError> {
    let Some(case) = spec.build::<T>() else {
        return Ok(());
    };
    let body = VertexSet::try_new(&case.vertices).expect("valid body");
    for n in [case.n, -case.n] {
        let probe = PreparedMotion::new(&case.motion).probe(n);
        let exact: R = exact_sup_signed(&case.vertices, &case.motion, n);
        let exact = exact.to_f64();
        for kind in [BoundKind::Evq, BoundKind::Nevq] {
            let rate = probe.rate(&body, kind);
            prop_assert!(!rate.is_nan(), "NaN rate");
            prop_assert!(
                rate.to_f64() >= exact,
                "{kind:?} one-sided rate {:e} below the exact signed sup {exact:e}",
                rate.to_f64()
            );
            let abs = probe.speed(&body, kind);
            // R bounds the distance from the rotation centre (the body
            // origin's distance plus the local centre's).
            let r = body.summary().max_radius().to_f64() + case.motion.local_reach().to_f64();
            prop_assert!(
                rate.to_f64() <= slack_above(abs, &case.motion, n, r),
                "{kind:?} rate {rate:?} above the absolute bound {abs:?}"
            );
        }
        // A ball around the first vertex holding every vertex: its rate
        // dominates the exact signed sup of its centre plus |c| rho (the
        // sup over the ball), hence every vertex's.
        let Some(ball) = ball_around_first(&case.vertices, grow) else {
            continue;
        };
        let (s, rho) = (*ball.centre(), ball.radius());
        let centre: R = exact_sup_signed(&[s], &case.motion, n);
        let over_ball = centre
            .add(c_over_n::<T, R>(n, &case.motion).mul(R::from_f64(rho.to_f64())))
            .to_f64();
        for kind in [BoundKind::Evq, BoundKind::Nevq] {
            let rate = probe.ball_rate(&ball, kind);
            prop_assert!(
                rate.to_f64() >= over_ball,
                "{kind:?} ball rate {:e} below the exact signed sup over the ball {over_ball:e}",
                rate.to_f64()
            );
            prop_assert!(
                rate.to_f64() >= exact,
                "{kind:?} ball rate below its vertices' sup"
            );
            let abs = probe.ball_speed(&ball, kind);
            let r = ball.outer_radius_up().to_f64() + case.motion.local_reach().to_f64();
            prop_assert!(
                rate.to_f64() <= slack_above(abs, &case.motion, n, r),
                "{kind:?} ball rate {rate:?} above {abs:?}"
            );
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    #[test]
    fn one_sided_rates_dominate_the_exact_signed_sup_f64(spec in case_spec(), grow in 0.0f64..2.0) {
        signed_sound::<f64, DoubleDouble>(&spec, grow)?;
    }

    #[test]
    fn one_sided_rates_dominate_the_exact_signed_sup_f32(spec in case_spec(), grow in 0.0f64..2.0) {
        signed_sound::<f32, f64>(&spec, grow)?;
    }
}

#[test]
fn a_receding_turning_body_gets_a_negative_rate() {
    // A rod along x, the body drifting along -y at 1 and turning at 0.5 about
    // z over [0, 1]: along +y its points move at -1 + 0.5 x cos(0.5 t) with
    // x in [-1, 1], so the largest signed speed is -1 + 0.5 = -0.5 (at x = 1,
    // t = 0), while the absolute bound is 1.5.
    let rod = [[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0]];
    let body = VertexSet::try_new(&rod).expect("valid");
    let m =
        RigidMotion::try_from_arrays([0.0; 3], [0.0, -1.0, 0.0], [0.0, 0.0, 0.5]).expect("valid");
    let probe = PreparedMotion::new(&m).probe(Direction::Y);
    let rate = probe.rate(&body, BoundKind::Evq);
    assert!((-0.5..-0.4999).contains(&rate), "rate {rate}");
    let speed = probe.speed(&body, BoundKind::Evq);
    assert!(speed >= 1.5, "absolute {speed}");
    // Along -y the same points approach at 1 - 0.5 x cos: at most 1.5.
    let back = PreparedMotion::new(&m)
        .probe(-Direction::Y)
        .rate(&body, BoundKind::Evq);
    assert!((1.5..1.5001).contains(&back), "rate along -y {back}");
    // NEVQ's one-sided rate only signs the linear part: -1 + 0.5 * 1.
    let nevq = probe.rate(&body, BoundKind::Nevq);
    assert!((-0.5..-0.4999).contains(&nevq), "NEVQ rate {nevq}");
}

#[test]
fn the_arc_must_reach_plus_q_not_minus_q() {
    // Lemma 10.1's case split: the point r = (cos 1, -sin 1, 0) turning about
    // z by theta in [0, 2]. Along y it moves at (R r)_x = cos(theta - 1): the
    // arc passes the point's direction +q at theta = 1 (signed sup 1), and
    // along -y at -cos(theta - 1), where the arc passes -q instead (signed
    // sup -cos 1 at the ends). The absolute bound is 1 both ways.
    let p = [[1.0f64.cos(), -(1.0f64.sin()), 0.0]];
    let body = VertexSet::try_new(&p).expect("valid");
    let m = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0, 0.0, 2.0])
        .expect("valid")
        .restrict(0.0, 1.0)
        .expect("valid");
    let pm = PreparedMotion::new(&m);
    let plus = pm.probe(Direction::Y).rate(&body, BoundKind::Evq);
    let minus = pm.probe(-Direction::Y).rate(&body, BoundKind::Evq);
    assert!((2.0..2.0 + 1e-12).contains(&plus), "along +y: {plus}");
    let c1 = -2.0 * 1.0f64.cos();
    assert!(
        minus >= c1 && minus < c1 + 1e-12,
        "along -y: {minus} vs {c1}"
    );
    let abs = pm.probe(-Direction::Y).speed(&body, BoundKind::Evq);
    assert!(abs >= 2.0, "absolute {abs}");
}
