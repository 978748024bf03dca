//! NEVQ soundness: for a fuzzed hard case (`testkit::CaseSpec`, the same
//! description the property tests generate), in `f32` or `f64`, the NEVQ
//! speed and displacement are not NaN and are at least the high-precision
//! exact values (`f64` oracle for `f32` bounds, double-double for `f64`).

#![no_main]

use libfuzzer_sys::fuzz_target;
use motion_bound::testkit::CaseSpec;
use motion_bound::{nevq, VertexSet};
use motion_bound_fuzz::{build_case, check_sound, exact_hp, Precision};

fn run<T: Precision>(spec: &CaseSpec) {
    let Some(case) = build_case::<T>(spec) else {
        return;
    };
    let body = VertexSet::try_new(&case.vertices)
        .unwrap_or_else(|e| panic!("({}) built case rejected: {e:?}; case {case:?}", T::NAME));
    let bound = nevq(&body.summary(), &case.motion, case.n);
    let ex = exact_hp(&case);
    check_sound("nevq", &ex, bound, &case);
}

fuzz_target!(|input: (CaseSpec, bool)| {
    let (spec, double) = input;
    if double {
        run::<f64>(&spec);
    } else {
        run::<f32>(&spec);
    }
});
