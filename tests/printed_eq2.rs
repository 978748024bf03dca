//! The seed's Eq. 2, transcribed literally, is refuted by the same soundness
//! property that the crate's bounds pass (`proofs/04-evq-case-split.md`,
//! section "The printed Eq. 2 is not a bound").

mod common;

use common::{check_sound, plain_spec};
use motion_bound::testkit::{Case, CaseSpec};
use motion_bound::{Direction, RigidMotion, Vec3};
use proptest::test_runner::{Config, TestCaseError, TestError, TestRunner};

fn rotate(v: [f64; 3], k: [f64; 3], th: f64) -> [f64; 3] {
    let (s, c) = (th.sin(), th.cos());
    let kv = Vec3::new(k[0], k[1], k[2]);
    let vv = Vec3::new(v[0], v[1], v[2]);
    (vv * c + kv.cross(vv) * s + kv * (kv.dot(vv) * (1.0 - c))).to_array()
}

/// REFUTED FORM. The seed's Eq. 1 with its Eq. 2 exactly as printed:
///
/// ```text
/// |c(t).r^c| = |c(t)||r^c|                   if (c(0) x r^c).(c(1) x r^c) > 0
///              max_i(c(0).r^c, c(1).r^c)     if (c(0) x r^c).(c(1) x r^c) <= 0
/// mu = |v.n| + max_i of that.
/// ```
///
/// Kept only to show that the property tests catch it. Do not use.
fn printed_eq2_speed(vertices: &[[f64; 3]], motion: &RigidMotion<f64>, n: Direction<f64>) -> f64 {
    let n = n.get();
    let w = motion.angular();
    let c = n.cross(w);
    let omega = w.length();
    let lin = motion.linear().dot(n).abs();
    if omega == 0.0 {
        return lin;
    }
    let k = (w * (1.0 / omega)).to_array();
    let iv = motion.interval();
    // c(t) = R(t)^T c: c rotated by -|w| t.
    let c0 = Vec3::from_array(rotate(c.to_array(), k, -omega * iv.start()));
    let c1 = Vec3::from_array(rotate(c.to_array(), k, -omega * iv.end()));
    let kv = Vec3::from_array(k);
    let mut best = f64::NEG_INFINITY;
    for r in vertices {
        let r = Vec3::from_array(*r);
        let rc = r - kv * kv.dot(r);
        let term = if c0.cross(rc).dot(c1.cross(rc)) > 0.0 {
            c.length() * kv.cross(r).length()
        } else {
            c0.dot(rc).max(c1.dot(rc))
        };
        best = best.max(term);
    }
    lin + best
}

fn printed_is_sound(spec: &CaseSpec) -> Result<(), TestCaseError> {
    let Some(case): Option<Case<f64>> = spec.build() else {
        return Ok(());
    };
    let mu = printed_eq2_speed(&case.vertices, &case.motion, case.n);
    check_sound(
        &case,
        mu,
        mu * case.motion.interval().length(),
        "printed Eq. 2",
    )
}

#[test]
fn the_printed_eq2_fails_the_soundness_property() {
    let mut runner = TestRunner::new(Config {
        cases: 512,
        failure_persistence: None,
        ..Config::default()
    });
    match runner.run(&plain_spec(), |spec| printed_is_sound(&spec)) {
        Err(TestError::Fail(reason, shrunk)) => {
            let case: Case<f64> = shrunk.build().expect("valid case");
            println!("printed Eq. 2 refuted: {reason}");
            println!("shrunk spec: {shrunk:#?}");
            println!(
                "vertices {:?}\nv {:?}\nw {:?}\ninterval [{}, {}]\nn {:?}",
                case.vertices,
                case.motion.linear(),
                case.motion.angular(),
                case.motion.interval().start(),
                case.motion.interval().end(),
                case.n
            );
        }
        Err(e) => panic!("unexpected runner error {e}"),
        Ok(()) => panic!("the printed Eq. 2 survived 512 cases: the property has lost its power"),
    }
}

#[test]
fn a_hand_made_counterexample_to_the_printed_eq2() {
    // One vertex at (1, 0, 0), spin about z by 0.2 rad, measured along
    // n = y rotated so that c(0) and c(1) straddle the vertex's line: c(t)
    // sweeps through r^c, where the true value is |c||r^c|, but the printed
    // form takes the endpoint value instead.
    let w: f64 = 0.2;
    let motion = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0, 0.0, w]).unwrap();
    // c = n x w; choose n so that c(0.5) is along +x: c(t) turns by -w t.
    let half = -w * 0.5;
    let n = Direction::try_new(Vec3::new(-half.sin(), -half.cos(), 0.0)).unwrap();
    let c = n.get().cross(motion.angular());
    assert!(c.y.abs() > 0.0, "c is not yet aligned at t = 0");
    let body = [[1.0, 0.0, 0.0]];
    let printed = printed_eq2_speed(&body, &motion, n);
    let exact = motion_bound::reference::exact::<f64, f64>(&body, &motion, n).sup_speed;
    assert!(
        (exact - w).abs() < 1e-15,
        "the exact sup is |c||r| = w, got {exact}"
    );
    assert!(
        printed < exact * 0.999,
        "printed {printed} should fall short of {exact}"
    );
    let ours = motion_bound::evq(
        &motion_bound::VertexSet::try_new(&body).unwrap(),
        &motion,
        n,
    )
    .speed;
    assert!(
        ours >= exact,
        "the corrected split is sound: {ours} >= {exact}"
    );
}
