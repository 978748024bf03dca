//! Writes the hand-crafted hard-case seeds to `corpus/<target>/seed-*`.
//!
//! Run from `fuzz/` with `cargo run --example make_seeds`. Every seed of the
//! `arbitrary`-decoded targets is decoded again (as libFuzzer's
//! `fuzz_target!` does, with `arbitrary_take_rest`) and compared with the
//! intended value, so a change of `arbitrary`'s byte format or of the input
//! types is caught here. The `toi`, `gjk`, `far`, `shapes`, `chain` and `degenerate` targets take raw bytes: their
//! seeds are written as they are.

use std::fmt::Debug;
use std::fs;
use std::path::Path;

use arbitrary::{Arbitrary, Unstructured};
use motion_bound::testkit::CaseSpec;
use motion_bound_fuzz::inputs::{MotionCase, ValidationCase};
use motion_bound_fuzz::seeds::{self, Enc};

fn write<T: for<'a> Arbitrary<'a> + Debug>(target: &str, name: &str, bytes: &[u8], expected: &T) {
    let decoded = T::arbitrary_take_rest(Unstructured::new(bytes))
        .unwrap_or_else(|e| panic!("{target}/{name}: does not decode: {e}"));
    assert_eq!(
        format!("{decoded:?}"),
        format!("{expected:?}"),
        "{target}/{name}: decodes to a different value"
    );
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("corpus")
        .join(target);
    fs::create_dir_all(&dir).expect("create corpus dir");
    fs::write(dir.join(format!("seed-{name}")), bytes).expect("write seed");
}

/// Writes raw-byte seeds as they are; returns how many.
fn write_raw(target: &str, seeds: Vec<(String, Vec<u8>)>) -> usize {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("corpus")
        .join(target);
    fs::create_dir_all(&dir).expect("create corpus dir");
    for (name, bytes) in &seeds {
        fs::write(dir.join(format!("seed-{name}")), bytes).expect("write seed");
    }
    seeds.len()
}

fn main() {
    let mut count = 0;
    for (i, (name, spec)) in seeds::hard_specs().into_iter().enumerate() {
        for double in [false, true] {
            let p = if double { "f64" } else { "f32" };
            let mut e = Enc::default();
            seeds::case_spec(&mut e, &spec);
            e.bool(double);
            let value: (CaseSpec, bool) = (spec.clone(), double);
            write("nevq", &format!("{name}-{p}"), &e.0, &value);
            write("reference", &format!("{name}-{p}"), &e.0, &value);

            // EVQ: the whole interval plus one sub-interval per seed.
            let (fa, fb) = [
                (0u16, 65535u16),
                (16384, 49151),
                (0, 0),
                (65535, 65535),
                (1, 65534),
                (40000, 2),
            ][i % 6];
            let mut e = Enc::default();
            seeds::case_spec(&mut e, &spec);
            e.bool(double).u16(fa).u16(fb);
            let value: (CaseSpec, bool, u16, u16) = (spec.clone(), double, fa, fb);
            write("evq", &format!("{name}-{p}"), &e.0, &value);
            count += 3;
        }
    }
    for (name, case) in seeds::motion_cases() {
        let mut e = Enc::default();
        seeds::motion_case(&mut e, &case);
        write::<MotionCase>("motion", &name, &e.0, &case);
        count += 1;
    }
    for (name, case) in seeds::validation_cases() {
        let mut e = Enc::default();
        seeds::validation_case(&mut e, &case);
        write::<ValidationCase>("validation", &name, &e.0, &case);
        count += 1;
    }
    // The `toi` and `gjk` targets read raw bytes (`motion_bound_fuzz::Bytes`).
    count += write_raw("toi", seeds::toi_seeds());
    count += write_raw("gjk", seeds::gjk_seeds());
    count += write_raw("far", seeds::far_seeds());
    count += write_raw("shapes", seeds::shapes_seeds());
    count += write_raw("chain", seeds::chain_seeds());
    count += write_raw("degenerate", seeds::degenerate_seeds());
    println!("wrote {count} seeds");
}
