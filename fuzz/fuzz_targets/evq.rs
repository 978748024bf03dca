//! EVQ soundness and tightness order: for a fuzzed hard case in `f32` or
//! `f64`, the EVQ and NEVQ speeds and displacements are not NaN and are at
//! least the high-precision exact values, and EVQ's are at most NEVQ's; the
//! same again on a sub-interval picked by two fractions of the input
//! (`RigidMotion::restrict`, what a conservative-advancement step does).
//! The one-sided rates of both kinds (`DirectedProbe::rate`, along `n` and
//! `-n`) are at least the exact largest signed speeds, and EVQ's at most
//! NEVQ's.

#![no_main]

use libfuzzer_sys::fuzz_target;
use motion_bound::testkit::{Case, CaseSpec};
use motion_bound::{evq, nevq, BoundKind, PreparedMotion};
use motion_bound_fuzz::{
    build_case, check_evq_le_nevq, check_one_sided, check_sound, clamp, in_precision, vertex_set,
    Oracle, Precision,
};

fn check<T: Precision>(sub: bool, case: &Case<T>) {
    let body = vertex_set(case);
    let e = evq(&body, &case.motion, case.n);
    let n = nevq(&body.summary(), &case.motion, case.n);
    let oracle = Oracle::new(case);
    let (we, wn) = if sub {
        ("evq on the sub-interval", "nevq on the sub-interval")
    } else {
        ("evq", "nevq")
    };
    check_sound(we, &oracle, e, case);
    check_sound(wn, &oracle, n, case);
    check_evq_le_nevq(e, n, case);
    let prepared = PreparedMotion::new(&case.motion);
    let (plus, minus) = (prepared.probe(case.n), prepared.probe(-case.n));
    let rates = |kind| (plus.rate(&body, kind), minus.rate(&body, kind));
    let (re, rn) = (rates(BoundKind::Evq), rates(BoundKind::Nevq));
    check_one_sided(we, &oracle, re, case);
    check_one_sided(wn, &oracle, rn, case);
    assert!(
        re.0 <= rn.0 && re.1 <= rn.1,
        "({}) one-sided EVQ {re:?} above one-sided NEVQ {rn:?}; case {case:?}",
        T::NAME
    );
}

fn run<T: Precision>(spec: &CaseSpec, fa: u16, fb: u16) {
    let Some(case) = build_case::<T>(spec) else {
        return;
    };
    check(false, &case);

    // A sub-interval [ta, tb] of the case's interval.
    let iv = case.motion.interval();
    let (s, e) = (iv.start(), iv.end());
    let at = |f: u16| clamp(s + (e - s) * T::from_f64(f64::from(f) / 65535.0), s, e);
    let (mut ta, mut tb) = (at(fa), at(fb));
    if tb < ta {
        core::mem::swap(&mut ta, &mut tb);
    }
    let motion = case.motion.restrict(ta, tb).unwrap_or_else(|err| {
        panic!(
            "({}) restrict({ta:?}, {tb:?}) of {iv:?} failed: {err:?}; case {case:?}",
            T::NAME
        )
    });
    assert!(
        motion.interval().start() == ta && motion.interval().end() == tb,
        "({}) restrict({ta:?}, {tb:?}) gave {:?}",
        T::NAME,
        motion.interval()
    );
    let sub = Case {
        vertices: case.vertices.clone(),
        motion,
        n: case.n,
    };
    check(true, &sub);
}

fuzz_target!(|input: (CaseSpec, bool, u16, u16)| {
    let (spec, double, fa, fb) = input;
    in_precision!(double, run(&spec, fa, fb));
});
