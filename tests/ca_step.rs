//! A conservative-advancement step needs a speed bound, not a displacement
//! bound (`proofs/02-ca-step.md`).

mod common;

use common::{cases, plain_spec};
use motion_bound::reference::{exact, Exact, Frame, SpeedProfile};
use motion_bound::{evq, Direction, RigidMotion, VertexSet};
use proptest::prelude::*;

#[test]
fn a_step_by_the_seeds_displacement_mu_overshoots() {
    let m = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0, 0.0, core::f64::consts::PI])
        .unwrap();
    let tip = [[1.0, 0.0, 0.0]];
    let ex: Exact<f64> = exact(&tip, &m, Direction::Y);
    assert!(
        (ex.displacement - 2.0).abs() < 1e-13,
        "mu = 2, got {}",
        ex.displacement
    );
    let d = 0.5;
    let step = d / ex.displacement;
    let travelled: Exact<f64> = exact(&tip, &m.restrict(0.0, step).unwrap(), Direction::Y);
    assert!(
        travelled.displacement > d + 0.2,
        "the tip travels {} > d = {d} in the step: not conservative",
        travelled.displacement
    );
    // The speed bound's step is conservative.
    let s = evq(&VertexSet::try_new(&tip).unwrap(), &m, Direction::Y).speed;
    let safe: Exact<f64> = exact(&tip, &m.restrict(0.0, d / s).unwrap(), Direction::Y);
    assert!(
        safe.displacement <= d,
        "speed step travels {} <= {d}",
        safe.displacement
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases() / 2))]

    /// With `S` the EVQ speed bound, no vertex's directed displacement over
    /// `[t_a, t_a + d/S]` exceeds `d`: the step cannot close the gap.
    #[test]
    fn an_evq_speed_step_never_closes_the_gap(spec in plain_spec(), d in 1e-3f64..10.0) {
        let Some(case) = spec.build::<f64>() else { return Ok(()) };
        let body = VertexSet::try_new(&case.vertices).unwrap();
        let s = evq(&body, &case.motion, case.n).speed;
        prop_assume!(s > 0.0);
        let iv = case.motion.interval();
        let t1 = (iv.start() + d / s).min(iv.end());
        let step = case.motion.restrict(iv.start(), t1).unwrap();
        let f: Frame<f64> = Frame::new(&step, case.n);
        for r in &case.vertices {
            let p: SpeedProfile<f64> = f.profile(*r);
            // signed displacement along n is at most the integral of |s|
            let moved = p.integral_abs(iv.start(), t1);
            prop_assert!(moved <= d * (1.0 + 1e-12), "moved {moved} > gap {d}");
        }
    }
}
