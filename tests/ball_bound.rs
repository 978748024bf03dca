//! The O(1) directed bound of a bounding ball (`proofs/08-ball-bound.md`):
//! sound against the exact closed form of the ball's sup speed, never above
//! the NEVQ of the ball, and the probe agrees with the one-shot functions.

mod common;

use common::{ball_around_first, c_over_n, case_spec, cases, Oracle};
use motion_bound::reference::dd::DoubleDouble;
use motion_bound::reference::{exact, Real};
use motion_bound::testkit::CaseSpec;
use motion_bound::{evq, nevq, BoundKind, BoundingBall, Float, PreparedMotion, VertexSet};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

/// The exact sup over the ball `B(s, rho)` of `|p'(t).n|`, in double-double:
/// `sup_t |v.n + c(t).s| + |c| rho` (attained at `s +- rho c(t)/|c|`).
fn exact_ball_sup<T: Float>(case: &motion_bound::testkit::Case<T>, s: [T; 3], rho: T) -> f64 {
    type R = DoubleDouble;
    let centre: motion_bound::reference::Exact<R> = exact(&[s], &case.motion, case.n);
    let rim = c_over_n::<T, R>(case.n, &case.motion).mul(R::from_f64(rho.to_f64()));
    // `exact` already works along n/|n| for the centre's term.
    centre.sup_speed.add(rim).to_f64()
}

fn ball_sound<T: Oracle>(spec: &CaseSpec, grow: f64) -> Result<(), TestCaseError> {
    let Some(case) = spec.build::<T>() else {
        return Ok(());
    };
    // The ball: centred at the first vertex, holding every vertex, grown a little.
    let Some(ball) = ball_around_first(&case.vertices, grow) else {
        return Ok(());
    };
    let (s, rho) = (*ball.centre(), ball.radius());
    let probe = PreparedMotion::new(&case.motion).probe(case.n);
    let e = probe.ball_speed(&ball, BoundKind::Evq);
    let n = probe.ball_speed(&ball, BoundKind::Nevq);
    prop_assert!(!e.is_nan() && !n.is_nan(), "NaN ball bound");
    prop_assert!(e <= n, "EVQ ball {e:?} above NEVQ ball {n:?}");
    let ex = exact_ball_sup(&case, s, rho);
    prop_assert!(
        e.to_f64() >= ex,
        "EVQ ball bound {:e} below the exact sup over the ball {ex:e}",
        e.to_f64()
    );
    // Every vertex lies in the ball: the ball bound also dominates their exact
    // sup speed and their densely sampled speeds.
    let vx = T::exact_hp(&case).sup_speed;
    prop_assert!(
        e.to_f64() >= vx,
        "ball bound {:e} below its vertices' sup {vx:e}",
        e.to_f64()
    );
    let sampled = T::sampled_hp(&case, 33);
    prop_assert!(
        e.to_f64() >= sampled,
        "ball bound below a sampled vertex speed {sampled:e}"
    );
    Ok(())
}

fn probe_matches<T: Oracle>(spec: &CaseSpec) -> Result<(), TestCaseError> {
    let Some(case) = spec.build::<T>() else {
        return Ok(());
    };
    let body = VertexSet::try_new(&case.vertices).expect("valid body");
    let probe = PreparedMotion::new(&case.motion).probe(case.n);
    let (pe, pn) = (
        probe.speed(&body, BoundKind::Evq),
        probe.speed(&body, BoundKind::Nevq),
    );
    let (e, n) = (
        evq(&body, &case.motion, case.n).speed,
        nevq(&body.summary(), &case.motion, case.n).speed,
    );
    prop_assert!(
        pe.to_f64().to_bits() == e.to_f64().to_bits(),
        "probe EVQ {pe:?} vs evq {e:?}"
    );
    prop_assert!(
        pn.to_f64().to_bits() == n.to_f64().to_bits(),
        "probe NEVQ {pn:?} vs nevq {n:?}"
    );
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    #[test]
    fn ball_bound_dominates_sampled_points_f64(spec in case_spec(), grow in 0.0f64..2.0) {
        ball_sound::<f64>(&spec, grow)?;
    }

    #[test]
    fn ball_bound_dominates_sampled_points_f32(spec in case_spec(), grow in 0.0f64..2.0) {
        ball_sound::<f32>(&spec, grow)?;
    }

    #[test]
    fn probe_matches_the_one_shot_functions(spec in case_spec()) {
        probe_matches::<f64>(&spec)?;
        probe_matches::<f32>(&spec)?;
    }
}

#[test]
fn evq_ball_is_never_above_nevq_ball() {
    // A ball on the axis: EVQ's centre term vanishes, only the rim remains.
    let m = motion_bound::RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0, 0.0, 3.0])
        .expect("valid motion");
    let ball = BoundingBall::try_new([0.0, 0.0, 5.0], 0.5).expect("valid ball");
    let probe = PreparedMotion::new(&m).probe(motion_bound::Direction::X);
    let (e, n) = (
        probe.ball_speed(&ball, BoundKind::Evq),
        probe.ball_speed(&ball, BoundKind::Nevq),
    );
    assert!((1.5..1.5 * (1.0 + 1e-12)).contains(&e), "rim only: {e}");
    assert!(
        n >= 3.0 * 5.5 * (1.0 - 1e-15) && e <= n,
        "NEVQ uses |s| + rho: {n}"
    );
}
