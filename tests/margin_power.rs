//! The rounding margin is needed: with it removed, an adversarial search
//! with the same soundness property finds a violation
//! (`proofs/floating-point.md`, section "Power").

mod common;

use common::{case_spec, check_sound, Oracle};
use motion_bound::testkit::{Case, CaseSpec};
use motion_bound::{evq_speed_unmargined, nevq_speed_unmargined, VertexSet};
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
