//! EVQ of a whole body by branch and bound over a `VertexTree`
//! (`proofs/08-ball-bound.md`, "Whole bodies"): on the hard cases, grown by
//! up to 600 random points scaled to the case's size, the tree's speed and
//! one-sided rates are sound against the exact closed form in higher
//! precision, never above the scan's, and within twice the scan's rounding
//! margin of it.

mod common;

use common::{case_spec, cases, check_sound, Oracle};
use motion_bound::reference::dd::DoubleDouble;
use motion_bound::reference::exact_sup_signed;
use motion_bound::testkit::{random_blob, Case, CaseSpec, SplitMix64};
use motion_bound::{
    evq_speed_unmargined, BoundKind, DirectedBound, Float, PreparedMotion, VertexSet, VertexTree,
};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

/// The case with `extra` random points inside the case's own bounding cube.
fn grown<T: Float>(spec: &CaseSpec, extra: usize, seed: u64) -> Option<Case<T>> {
    let mut case = spec.build::<T>()?;
    let scale = case
        .vertices
        .iter()
        .flatten()
        .map(|x| x.to_f64().abs())
        .fold(0.0f64, f64::max);
    let mut rng = SplitMix64(seed);
    case.vertices.extend(
        random_blob::<f64>(&mut rng, extra)
            .into_iter()
            .map(|p| p.map(|x| T::from_f64(x * scale))),
    );
    Some(case)
}

fn check<T: Oracle>(spec: &CaseSpec, extra: usize, seed: u64) -> Result<(), TestCaseError> {
    let Some(case) = grown::<T>(spec, extra, seed) else {
        return Ok(());
    };
    let body = VertexSet::try_new(&case.vertices).expect("valid body");
    let tree = VertexTree::try_new(&body).expect("valid tree");
    let probe = PreparedMotion::new(&case.motion).probe(case.n);
    let scan = probe.evq_speed(&body);
    let fast = tree.evq_speed(&probe);
    // Sound against the exact value (and dense samples), as every bound is.
    let b = DirectedBound::new(fast, tree.evq(&case.motion, case.n).displacement);
    check_sound(&case, b.speed, b.displacement, "tree EVQ")?;
    // Never above the scan, and within twice its rounding margin below it
    // (Lemma 8.2): the scan's margin is what it adds to the unmargined value.
    let raw = evq_speed_unmargined(&body, &case.motion, case.n);
    prop_assert!(
        fast <= scan,
        "tree {:e} above the scan {:e}",
        fast.to_f64(),
        scan.to_f64()
    );
    let margin = 2.0 * (scan - raw).to_f64().max(0.0);
    prop_assert!(
        scan.to_f64() - fast.to_f64() <= margin,
        "tree {:e} more than the margin {margin:e} below the scan {:e}",
        fast.to_f64(),
        scan.to_f64()
    );
    // One-sided rates along both directions.
    for n in [case.n, -case.n] {
        let probe = PreparedMotion::new(&case.motion).probe(n);
        let exact: DoubleDouble = exact_sup_signed(&case.vertices, &case.motion, n);
        for kind in [BoundKind::Evq, BoundKind::Nevq] {
            let rate = tree.rate(&probe, kind);
            let scan = probe.rate(&body, kind);
            prop_assert!(
                rate.to_f64() >= exact.to_f64(),
                "tree rate {kind:?} {:e} below the exact signed sup {:e}",
                rate.to_f64(),
                exact.to_f64()
            );
            prop_assert!(
                rate <= scan || kind == BoundKind::Evq,
                "NEVQ rate {:e} differs from {:e}",
                rate.to_f64(),
                scan.to_f64()
            );
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    #[test]
    fn tree_evq_is_sound_and_matches_the_scan_f64(
        spec in case_spec(), extra in prop_oneof![Just(0usize), 1usize..600], seed in any::<u64>()
    ) {
        check::<f64>(&spec, extra, seed)?;
    }

    #[test]
    fn tree_evq_is_sound_and_matches_the_scan_f32(
        spec in case_spec(), extra in prop_oneof![Just(0usize), 1usize..600], seed in any::<u64>()
    ) {
        check::<f32>(&spec, extra, seed)?;
    }
}

/// On a large body the tree visits a small part of it and agrees with the
/// scan to the last bit on most directions.
#[test]
fn a_large_body_visits_few_nodes() {
    let mut rng = SplitMix64(5);
    let points = random_blob::<f64>(&mut rng, 20_000);
    let body = VertexSet::try_new(&points).unwrap();
    let tree = VertexTree::try_new(&body).unwrap();
    let (mut equal, mut visited) = (0, 0);
    for k in 0..50 {
        let t = f64::from(k);
        let m = motion_bound::RigidMotion::try_from_arrays(
            [0.0; 3],
            [0.1 * t.sin(), 0.2, 0.0],
            [t.cos(), (0.7 * t).sin(), 0.5],
        )
        .unwrap();
        let n = motion_bound::Direction::try_from_array([1.0, 0.3 * t.cos(), -0.2]).unwrap();
        let probe = PreparedMotion::new(&m).probe(n);
        let (fast, v) = tree.speed_with_stats(&probe);
        visited += v;
        equal += usize::from(fast == probe.evq_speed(&body));
    }
    println!(
        "20,000 points: {equal} of 50 equal to the scan, {} nodes visited per query",
        visited / 50
    );
    assert!(equal >= 40, "{equal} of 50 equal");
    assert!(visited / 50 < 500, "{} nodes per query", visited / 50);
}
