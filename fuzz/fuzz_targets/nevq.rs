//! NEVQ soundness: for a fuzzed hard case (`testkit::CaseSpec`, the same
//! description the property tests generate), in `f32` or `f64`, the NEVQ
//! speed and displacement are not NaN and are at least the high-precision
//! exact values (`f64` oracle for `f32` bounds, double-double for `f64`),
//! see `motion_bound_fuzz::oracle`.

#![no_main]

use libfuzzer_sys::fuzz_target;
use motion_bound::nevq;
use motion_bound::testkit::CaseSpec;
use motion_bound_fuzz::{build_case, check_sound, in_precision, vertex_set, Oracle, Precision};

fn run<T: Precision>(spec: &CaseSpec) {
    let Some(case) = build_case::<T>(spec) else {
        return;
    };
    let bound = nevq(&vertex_set(&case).summary(), &case.motion, case.n);
    check_sound("nevq", &Oracle::new(&case), bound, &case);
}

fuzz_target!(|input: (CaseSpec, bool)| in_precision!(input.1, run(&input.0)));
