//! Precision and cost wherever the pair is: two icospheres (20, 80 or 320
//! triangles) at a fuzzed offset from the origin (`f32` up to `1e7`, `f64`
//! up to `1e16`, each component with its own sign) and a fuzzed scale
//! (`2^-120` to `2^120` in `f32`, `2^-1000` to `2^1000` in `f64`), with a
//! fuzzed fly-by, contact distance and work budget
//! (`proofs/floating-point.md`, "Pair frame" and "Resolution").
//!
//! * Building the meshes, the trees and the motions either succeeds or
//!   gives a typed error (a scale beyond `MAX_INPUT`); the query then never
//!   panics and returns `Ok`.
//! * **The budget**: a query never does more work than its budget (node
//!   pairs and triangle pairs).
//! * **The pair frame**: when the relative start of the two bodies is the
//!   exact difference of their centres (in every component), the far pair's
//!   outcome, iterations, work and witness distance equal those of the same
//!   pair at the origin (the bodies' relative start, B at the origin), bit
//!   for bit: both queries see the same frame.
//! * A precision limit comes with no later time than the same pair's other
//!   outcome would allow: its resolution is at least half the contact
//!   distance (else it is not given).
//!
//! The input is raw bytes read as bounded numbers (missing bytes read as
//! zero).

#![no_main]

use libfuzzer_sys::fuzz_target;
use motion_bound::bodies::icosphere;
use motion_bound::ca::{time_of_impact, CaOutcome, CaParams, CaReport, MeshPair, Work};
use motion_bound::{BallTree, Float, Point3, RigidMotion, TimeInterval, Vec3};
use motion_bound_fuzz::Bytes;

/// `2^k`, exactly.
fn pow2(k: i32) -> f64 {
    f64::from_bits(((1023 + k).clamp(1, 2046) as u64) << 52)
}

fn vector(b: &mut Bytes<'_>, half: f64) -> [f64; 3] {
    [
        b.range(-half, half),
        b.range(-half, half),
        b.range(-half, half),
    ]
}

fn run<T: Float>(b: &mut Bytes<'_>, max_offset_exp: i32, max_scale_exp: i32) {
    let subdivisions = u32::from(b.u8() % 3);
    // The offset: each component its own sign, magnitude `m 10^e`.
    let exp = i32::from(b.u8()) % (max_offset_exp + 1);
    let offset: [f64; 3] = [0; 3].map(|_| {
        b.range(-1.0, 1.0) * 10f64.powi(exp) * if b.u8().is_multiple_of(8) { 0.0 } else { 1.0 }
    });
    let scale = pow2(i32::from(b.u8() as i8) * max_scale_exp / 128);
    let rel = vector(b, 1.6);
    let (va, wa) = (vector(b, 3.0), vector(b, 20.0));
    let wb = vector(b, 5.0);
    let contact = [1e-3, 1e-6, 1e-9, 1e-2, 0.1][usize::from(b.u8() % 5)] * scale;
    let budget = Work::new(u64::from(b.u8()) * 40, u64::from(b.u8()) * 8);
    let Ok(mesh) = icosphere::<f64>(0.5, subdivisions)
        .map_err(|_| ())
        .and_then(|m| m.scaled(scale).map_err(|_| ()))
        .and_then(|m| m.try_convert::<T>().map_err(|_| ()))
    else {
        return;
    };
    let Ok(tree) = BallTree::try_from_mesh(&mesh) else {
        return;
    };
    let t = T::from_f64;
    let centre_b = offset.map(t);
    let centre_a: [T; 3] = [0, 1, 2].map(|k| t(offset[k] + rel[k] * scale));
    let motion = |c: [T; 3], v: [f64; 3], w: [f64; 3]| {
        RigidMotion::try_new(
            Point3::from_array(c),
            Vec3::from_array(v.map(|x| t(x * scale))),
            Vec3::from_array(w.map(t)),
            TimeInterval::UNIT,
        )
    };
    let (Ok(a), Ok(b)) = (motion(centre_a, va, wa), motion(centre_b, [0.0; 3], wb)) else {
        return;
    };
    if t(contact) <= T::ZERO {
        // Below `T`'s least subnormal: a zero contact distance is refused.
        return;
    }
    let params = CaParams::<T>::default()
        .with_contact_distance(t(contact))
        .with_work_budget(budget);
    let far =
        time_of_impact(&mut MeshPair::new(&tree, &tree), &a, &b, &params).expect("a valid query");
    check(&far, budget, &params);
    // The same pair at the origin, when the relative start is exact.
    // `centre_a - centre_b` in `T`, exact when TwoSum's residual is zero.
    let exact = |x: T, y: T| {
        let hi = x - y;
        let bb = hi - x;
        ((x - (hi - bb)) + (-y - bb) == T::ZERO).then_some(hi)
    };
    let diff: Option<Vec<T>> = (0..3).map(|k| exact(centre_a[k], centre_b[k])).collect();
    if let Some(diff) = diff {
        let Ok(a0) = motion([diff[0], diff[1], diff[2]], va, wa) else {
            return;
        };
        let b0 = motion([T::ZERO; 3], [0.0; 3], wb).expect("in range");
        let near = time_of_impact(&mut MeshPair::new(&tree, &tree), &a0, &b0, &params)
            .expect("a valid query");
        let same = far.iterations == near.iterations
            && far.work == near.work
            && far.outcome.earliest_possible_contact() == near.outcome.earliest_possible_contact()
            && core::mem::discriminant(&far.outcome) == core::mem::discriminant(&near.outcome)
            && far
                .outcome
                .contact()
                .and_then(|c| c.witness)
                .map(|w| w.distance)
                == near
                    .outcome
                    .contact()
                    .and_then(|c| c.witness)
                    .map(|w| w.distance);
        assert!(
            same,
            "THE FRAME MATTERS: at offset {offset:?} {far:?}, at the origin {near:?}"
        );
    }
}

fn check<T: Float>(r: &CaReport<T>, budget: Work, params: &CaParams<T>) {
    assert!(
        !r.work.exceeds(budget),
        "OVER BUDGET: {:?} against {budget:?} ({r:?})",
        r.work
    );
    if let CaOutcome::PrecisionLimit { resolution, .. } = r.outcome {
        assert!(
            resolution >= params.clearance(),
            "A PRECISION LIMIT BELOW THE CLEARANCE: {r:?}"
        );
    }
}

fuzz_target!(|data: &[u8]| {
    let mut b = Bytes::new(data);
    if b.u8().is_multiple_of(2) {
        run::<f32>(&mut b, 7, 120);
    } else {
        run::<f64>(&mut b, 16, 1000);
    }
});
