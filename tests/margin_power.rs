//! The rounding margin is needed: with it removed, an adversarial search
//! with the same soundness property finds a violation
//! (`proofs/floating-point.md`, section "Power").

mod common;

use common::{case_spec, check_sound, Oracle};
use motion_bound::testkit::{Case, CaseSpec};
use motion_bound::{evq_speed_unmargined, nevq_speed_unmargined, Float, VertexSet};
use proptest::test_runner::{Config, TestCaseError, TestError, TestRunner};

#[derive(Clone, Copy, Debug)]
enum Which {
    Nevq,
    Evq,
}

fn unmargined_is_sound<T: Oracle>(spec: &CaseSpec, which: Which) -> Result<(), TestCaseError> {
    let Some(case): Option<Case<T>> = spec.build() else {
        return Ok(());
    };
    let body = VertexSet::try_new(&case.vertices).expect("valid");
    let s = match which {
        Which::Nevq => nevq_speed_unmargined(&body.summary(), &case.motion, case.n),
        Which::Evq => evq_speed_unmargined(&body, &case.motion, case.n),
    };
    let len = case.motion.interval().length();
    check_sound(&case, s, s * len * T::from_f64(1.0 + 1e-3), "unmargined")
}

fn search<T: Oracle>(which: Which) {
    let mut runner = TestRunner::new(Config {
        cases: 20_000,
        failure_persistence: None,
        ..Config::default()
    });
    match runner.run(&case_spec(), |spec| unmargined_is_sound::<T>(&spec, which)) {
        Err(TestError::Fail(reason, shrunk)) => {
            println!(
                "{which:?} ({}) without its margin: {reason}",
                core::any::type_name::<T>()
            );
            println!("shrunk spec: {shrunk:?}");
        }
        Err(e) => panic!("unexpected runner error {e}"),
        Ok(()) => panic!("{which:?} without its margin survived 20000 adversarial cases"),
    }
}

#[test]
fn without_the_margin_nevq_f32_is_refuted() {
    search::<f32>(Which::Nevq);
}

#[test]
fn without_the_margin_nevq_f64_is_refuted() {
    search::<f64>(Which::Nevq);
}

#[test]
fn without_the_margin_evq_f32_is_refuted() {
    search::<f32>(Which::Evq);
}

#[test]
fn without_the_margin_evq_f64_is_refuted() {
    search::<f64>(Which::Evq);
}

fn inflation<T: Oracle>(which: Which) -> (f64, f64) {
    use motion_bound::{evq_speed, nevq_speed};
    use proptest::strategy::{Strategy, ValueTree};
    let mut runner = TestRunner::deterministic();
    let mut ratios = Vec::new();
    for _ in 0..20_000 {
        let spec = common::plain_spec()
            .new_tree(&mut runner)
            .expect("tree")
            .current();
        let Some(case): Option<Case<T>> = spec.build() else {
            continue;
        };
        let body = VertexSet::try_new(&case.vertices).expect("valid");
        let (with, without) = match which {
            Which::Nevq => (
                nevq_speed(&body.summary(), &case.motion, case.n),
                nevq_speed_unmargined(&body.summary(), &case.motion, case.n),
            ),
            Which::Evq => (
                evq_speed(&body, &case.motion, case.n),
                evq_speed_unmargined(&body, &case.motion, case.n),
            ),
        };
        let (with, without) = (with.to_f64(), without.to_f64());
        if without > 0.0 {
            ratios.push(with / without - 1.0);
        }
    }
    ratios.sort_by(f64::total_cmp);
    (ratios[ratios.len() / 2], ratios[ratios.len() - 1])
}

/// The relative inflation the margin costs on ordinary cases (unit-sized
/// bodies, |w| in [0.1, 20], any sweep); reported with `--nocapture`.
#[test]
fn the_margin_costs_a_small_relative_inflation() {
    println!("| bound | median inflation | worst inflation |");
    println!("|---|---|---|");
    // Regression guards from proofs/floating-point.md, "Inflation": NEVQ pays
    // about gamma_16 + gamma_3; EVQ also pays (48 + 12 theta_m) u of |c| R.
    for (name, (med, worst), u, guard) in [
        (
            "NEVQ f64",
            inflation::<f64>(Which::Nevq),
            f64::UNIT_ROUNDOFF,
            64.0,
        ),
        (
            "EVQ f64",
            inflation::<f64>(Which::Evq),
            f64::UNIT_ROUNDOFF,
            512.0,
        ),
        (
            "NEVQ f32",
            inflation::<f32>(Which::Nevq),
            f64::from(f32::UNIT_ROUNDOFF),
            64.0,
        ),
        (
            "EVQ f32",
            inflation::<f32>(Which::Evq),
            f64::from(f32::UNIT_ROUNDOFF),
            512.0,
        ),
    ] {
        println!(
            "| {name} | {med:.3e} ({:.0} u) | {worst:.3e} ({:.0} u) |",
            med / u,
            worst / u
        );
        assert!(med >= 0.0, "{name}: the margin never lowers a bound");
        assert!(
            med < guard * u,
            "{name}: median inflation {med:e} above {guard} u"
        );
    }
}
