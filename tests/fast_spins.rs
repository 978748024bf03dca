//! Fast spins (`proofs/09-ca-toi.md`, Lemma 9.8): a body turning many times
//! over the interval stays in its ball about the rotation centre, which
//! only translates; the iteration limit follows the turns.
//!
//! Ground truth is independent of the code under test: the closed form of
//! two translating balls, and the sampled ground truth of
//! `tests/common/shape_truth.rs` (each shape's core tessellated inside
//! itself, placed by the testkit's own quaternions, exact triangle
//! distances: a sampled contact is a true contact).

#[path = "common/shape_truth.rs"]
mod shape_truth;

use motion_bound::ca::{time_of_impact, AnyPair, BallPair, CaOutcome, CaParams, ConvexPair, Shape};
use motion_bound::testkit::toi::Rng;
use motion_bound::{BoundingBall, Convex, RigidMotion};
use shape_truth::{convex_kinds, first_sampled_contact};

/// The first time in `[0, 1]` at which two balls of radii summing to `r`,
/// centres `x` and `y` moving at `u` and `w`, are `r` apart: the smaller
/// root of `|d + e t|^2 = r^2` with `d = y - x`, `e = w - u`.
fn balls_meet(x: [f64; 3], u: [f64; 3], y: [f64; 3], w: [f64; 3], r: f64) -> Option<f64> {
    let d: Vec<f64> = (0..3).map(|k| y[k] - x[k]).collect();
    let e: Vec<f64> = (0..3).map(|k| w[k] - u[k]).collect();
    let dot = |p: &[f64], q: &[f64]| p.iter().zip(q).map(|(a, b)| a * b).sum::<f64>();
    let (a, b, c) = (dot(&e, &e), 2.0 * dot(&d, &e), dot(&d, &d) - r * r);
    if c <= 0.0 {
        return Some(0.0);
    }
    let disc = b * b - 4.0 * a * c;
    if a == 0.0 || disc < 0.0 {
        return None;
    }
    let t = (-b - disc.sqrt()) / (2.0 * a);
    (0.0..=1.0).contains(&t).then_some(t)
}

#[test]
fn spinning_balls_meet_when_their_centres_say() {
    let mut rng = Rng::new(97);
    let delta = 1e-3;
    let params = CaParams::default().with_contact_distance(delta);
    let (mut contacts, mut max_iterations) = (0, 0);
    for q in 0..300 {
        let (ra, rb) = (rng.range(0.1, 0.6), rng.range(0.1, 0.6));
        let start = rng.direction().map(|x| x * rng.range(1.5, 3.0));
        let aim = rng.direction().map(|x| x * rng.range(0.0, 1.2));
        let v = [0, 1, 2].map(|k| aim[k] - start[k]);
        let spin = [10.0, 200.0, 1000.0][q % 3];
        let wa = rng.direction().map(|x| x * spin * rng.unit());
        let wb = rng.direction().map(|x| x * spin * rng.unit());
        let ma = RigidMotion::try_from_arrays(start, v, wa).expect("motion");
        let mb = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], wb).expect("motion");
        let ball = |r| BoundingBall::try_new([0.0; 3], r).expect("ball");
        let mut pair = BallPair::new(ball(ra), ball(rb));
        let report = time_of_impact(&mut pair, &ma, &mb, &params).expect("a valid query");
        let touch = balls_meet(start, v, [0.0; 3], [0.0; 3], ra + rb);
        // The first time the distance is at most the contact distance: no
        // report may be before it (a contact is declared within it).
        let near = balls_meet(start, v, [0.0; 3], [0.0; 3], ra + rb + delta);
        let what = format!("query {q}: {report:?}, touch {touch:?}, near {near:?}");
        match (report.outcome.earliest_possible_contact(), touch) {
            (None, Some(_)) => panic!("MISSED: {what}"),
            (Some(t), Some(g)) => {
                assert!(t <= g, "LATE: {what}");
                assert!(
                    t >= near.expect("near before touch") - 1e-12,
                    "EARLY: {what}"
                );
            }
            (Some(_), None) => assert!(
                report.outcome.contact().is_none() || near.is_some(),
                "FALSE: {what}"
            ),
            (None, None) => {}
        }
        assert!(
            report.outcome.contact().is_some() || report.outcome == CaOutcome::Separated,
            "undecided: {what}"
        );
        contacts += usize::from(touch.is_some());
        max_iterations = max_iterations.max(report.iterations);
    }
    // The turning does not slow the balls down: a handful of steps each.
    assert!(max_iterations <= 12, "{max_iterations} iterations");
    assert!(contacts >= 100, "{contacts} contacts: too few for power");
}

#[test]
fn fast_spins_are_decided_and_never_late() {
    let mut rng = Rng::new(38);
    let kinds = convex_kinds(&mut rng);
    let params = CaParams::default().with_contact_distance(1e-3);
    for spin in [20.0, 200.0] {
        let (mut n, mut decided, mut sampled) = (0, 0, 0);
        for i in 0..kinds.len() {
            for j in i..kinds.len() {
                let ((na, sa, ta), (nb, sb, tb)) = (&kinds[i], &kinds[j]);
                let reach = ta.reach() + tb.reach();
                let start = rng.direction().map(|x| x * reach * rng.range(1.1, 1.5));
                let aim = rng.direction().map(|x| x * reach * 0.6 * rng.unit());
                let v = [0, 1, 2].map(|k| aim[k] - start[k]);
                let wa = rng.direction().map(|x| x * spin);
                let wb = rng.direction().map(|x| x * spin);
                let ma = RigidMotion::try_from_arrays(start, v, wa).expect("motion");
                let mb = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], wb).expect("motion");
                let mut pair = AnyPair::try_new(Shape::Convex(*sa), Shape::Convex(*sb))
                    .expect("a pair of convex kinds");
                let report = time_of_impact(&mut pair, &ma, &mb, &params).expect("a valid query");
                // Sampled up to a little after the reported time (so that
                // a late report would be seen, and the contacts confirmed),
                // about every 0.02 of the fastest point's travel.
                let end = report
                    .outcome
                    .earliest_possible_contact()
                    .map_or(1.0, |t| (t + 0.05).min(1.0));
                let speed = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt() + spin * reach;
                let samples = ((speed * end / 0.02).ceil() as usize).max(50);
                let truth = first_sampled_contact(ta, &ma, tb, &mb, (0.0, end), samples);
                let what = format!("{na} vs {nb} at {spin} rad: {report:?}, sampled {truth:?}");
                match (report.outcome.earliest_possible_contact(), truth) {
                    (None, Some(_)) => panic!("MISSED: {what}"),
                    (Some(t), Some(g)) => assert!(t <= g, "LATE: {what}"),
                    _ => {}
                }
                n += 1;
                sampled += usize::from(truth.is_some());
                decided += usize::from(
                    report.outcome.contact().is_some() || report.outcome == CaOutcome::Separated,
                );
            }
        }
        println!("{spin} rad: {n} fly-bys, {decided} decided, {sampled} sampled contacts");
        assert_eq!(decided, n, "every fly-by decided at {spin} rad");
        assert!(sampled * 2 >= n, "too few sampled contacts for power");
    }
}

#[test]
fn the_iteration_limit_follows_the_turns() {
    use core::f64::consts::TAU;
    // 4.5 and 5 turns over [0, 1]: 9.5, rounded up to 10.
    let a = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0, 4.5 * TAU, 0.0]).expect("a");
    let b =
        RigidMotion::try_from_arrays([3.0, 0.0, 0.0], [0.0; 3], [5.0 * TAU, 0.0, 0.0]).expect("b");
    let p = CaParams::default()
        .with_max_iterations(1)
        .with_iterations_per_turn(3);
    assert_eq!(p.iteration_limit(&a, &b), 1 + 3 * 10);
    assert_eq!(p.with_iterations_per_turn(0).iteration_limit(&a, &b), 1);
    let still = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0; 3]).expect("still");
    assert_eq!(p.iteration_limit(&still, &still), 1);
    // A rod spinning beside another, never touching: each near pass takes
    // its steps, and the query stops at the limit that follows the turns.
    let rod = Convex::try_capsule(1.0, 0.05).expect("rod");
    let near = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0, 0.0, 4.5 * TAU]).expect("a");
    let other =
        RigidMotion::try_from_arrays([2.2, 0.0, 0.0], [0.0; 3], [0.0, 0.0, 5.0 * TAU]).expect("b");
    let report = time_of_impact(&mut ConvexPair::new(rod, rod), &near, &other, &p).expect("query");
    match report.outcome {
        CaOutcome::IterationLimit { .. } => assert_eq!(report.iterations, 31),
        CaOutcome::Separated => assert!(report.iterations <= 31),
        other => panic!("a contact of rods that never meet: {other:?}"),
    }
}
