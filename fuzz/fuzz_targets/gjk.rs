//! GJK on small convex polytopes (one to eight vertices each, degenerate ones
//! included: repeated points, segments, flat sets, grid coordinates, gaps from
//! 0 to 1e-12 of the scale), in `f64` and `f32`.
//!
//! * `gjk_distance` never panics and returns a finite, non-negative distance
//!   and lower bound.
//! * **The certificate holds.** With a direction `n`, every vertex pair
//!   satisfies `(b - a) . n / |n| >= lower_bound`, evaluated in double-double
//!   (the differences exact, the products and sums to about `2^-104`
//!   relative); without a direction the bound is 0. This is the guarantee a
//!   conservative-advancement step relies on (`proofs/09-ca-toi.md`,
//!   Lemma 9.1).
//! * The bound is at most the distance, and both are 0 when GJK reports an
//!   intersection.
//!
//! The distance estimate is not checked against the truth: its rounding
//! grows with the conditioning of the final simplex (an early version of this
//! target found a point on an edge of a flat quadrilateral 0.003 thick,
//! converged at a distance of `1.46e-12`, about `6,600 u s`, with bound 0;
//! `fuzz/README.md`, "Findings"). The certificate is what CA relies on.
//!
//! The input is raw bytes read as bounded numbers (missing bytes read as
//! zero).

#![no_main]

use libfuzzer_sys::fuzz_target;
use motion_bound::reference::DoubleDouble;
use motion_bound::{gjk_distance, ConvexPolytope, Float, GjkParams, Pose};
use motion_bound_fuzz::Bytes;

/// One coordinate in `[-1, 1]`: a grid value (exact degeneracies) or any.
fn coord(b: &mut Bytes<'_>) -> f64 {
    if b.u8().is_multiple_of(3) {
        f64::from(b.u8() % 5) / 2.0 - 1.0
    } else {
        b.range(-1.0, 1.0)
    }
}

fn body(b: &mut Bytes<'_>) -> Vec<[f64; 3]> {
    let count = 1 + usize::from(b.u8() % 8);
    (0..count).map(|_| [coord(b), coord(b), coord(b)]).collect()
}

/// `(b - a) . n` in double-double.
fn dd_dot_diff(a: [f64; 3], b: [f64; 3], n: [f64; 3]) -> DoubleDouble {
    (0..3).fold(DoubleDouble::from_f64(0.0), |s, k| {
        let d = DoubleDouble::from_f64(b[k]).sub_dd(DoubleDouble::from_f64(a[k]));
        s.add_dd(d.mul_f64(n[k]))
    })
}

fn check<T: Float>(va: &[[f64; 3]], vb: &[[f64; 3]]) {
    // Rounded to T; the checks use the rounded values, exactly, in f64.
    let round = |v: &[[f64; 3]]| -> Vec<[T; 3]> { v.iter().map(|p| p.map(T::from_f64)).collect() };
    let (ta, tb) = (round(va), round(vb));
    let back = |v: &[[T; 3]]| -> Vec<[f64; 3]> { v.iter().map(|p| p.map(T::to_f64)).collect() };
    let (fa, fb) = (back(&ta), back(&tb));
    let pa = ConvexPolytope::try_new(&ta, Pose::IDENTITY).expect("finite vertices");
    let pb = ConvexPolytope::try_new(&tb, Pose::IDENTITY).expect("finite vertices");
    let params = GjkParams::default();
    let r = gjk_distance(&pa, &pb, &params);
    let (d, lb) = (r.distance.to_f64(), r.lower_bound.to_f64());
    assert!(
        d.is_finite() && d >= 0.0 && lb.is_finite() && lb >= 0.0,
        "finite, non-negative: {r:?}"
    );
    match r.direction {
        None => assert!(lb == 0.0, "a bound without a direction: {r:?}"),
        Some(n) => {
            let n = n.to_array().map(T::to_f64);
            let nn = (0..3).fold(DoubleDouble::from_f64(0.0), |s, k| {
                s.add_dd(DoubleDouble::from_f64(n[k]).mul_f64(n[k]))
            });
            let norm = nn.sqrt();
            for &a in &fa {
                for &b in &fb {
                    let sep = dd_dot_diff(a, b, n);
                    // Double-double's own error, about 2^-104 of the terms.
                    let scale: f64 = (0..3).map(|k| (b[k] - a[k]).abs() * n[k].abs()).sum();
                    let slack = DoubleDouble::from_f64(scale * 2f64.powi(-96));
                    let need = norm.mul_f64(lb);
                    assert!(
                        sep.add_dd(slack).sub_dd(need).to_f64() >= 0.0,
                        "not certified: ({b:?} - {a:?}) . {n:?} = {} < {lb} |n| ({r:?}; A {fa:?}, B {fb:?})",
                        sep.to_f64()
                    );
                }
            }
        }
    }
    assert!(lb <= d, "the bound above the distance: {r:?}");
    if r.intersecting {
        assert!(lb == 0.0 && d == 0.0, "intersecting with a gap: {r:?}");
    }
}

fn run(data: &[u8]) {
    let mut b = Bytes::new(data);
    let va = body(&mut b);
    let mut vb = body(&mut b);
    // B shifted by a tiny gap along a fuzzed axis, then the scene scaled.
    let gap = [0.0, 1e-12, 1e-9, 1e-6, 1e-3, 0.5][usize::from(b.u8() % 6)];
    let axis = usize::from(b.u8() % 3);
    for p in &mut vb {
        p[axis] += gap;
    }
    let scale = [1.0, 1e-3, 1e3, 2f64.powi(-40)][usize::from(b.u8() % 4)];
    let sc = |v: &[[f64; 3]]| -> Vec<[f64; 3]> { v.iter().map(|p| p.map(|x| x * scale)).collect() };
    let (va, vb) = (sc(&va), sc(&vb));
    if b.u8().is_multiple_of(2) {
        check::<f64>(&va, &vb);
        check::<f64>(&vb, &va);
    } else {
        check::<f32>(&va, &vb);
    }
}

fuzz_target!(|data: &[u8]| run(data));
