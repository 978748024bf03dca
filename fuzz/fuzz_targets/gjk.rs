//! GJK on small convex polytopes (one to eight vertices each, degenerate ones
//! included: repeated points, segments, flat sets, grid coordinates; gaps
//! from 0.5 down to 1e-12 and 0, scales from 2^-40 to 1e3), each identity
//! placed or placed by a fuzzed matrix and translation, in `f64` and `f32`.
//!
//! * `gjk_distance` never panics and returns a finite, non-negative distance
//!   and lower bound.
//! * **The certificate holds.** With a direction `n`, every pair of exactly
//!   placed vertices satisfies `(b - a) . n >= lower_bound max(1, |n|)`
//!   (so both `(b - a) . n >= lower_bound` and `|b - a| >= lower_bound`),
//!   evaluated in double-double (products exact, sums to about `2^-104` of
//!   the terms); without a direction the bound is 0. This is the guarantee a
//!   caller's conservative-advancement step taken from `gjk_distance`'s
//!   bound and direction relies on (`GjkResult`; `proofs/09-ca-toi.md`,
//!   Lemma 9.1). This crate's `VertexSetPair` measures its own certified gap
//!   along GJK's witness direction instead.
//! * The bound is at most the distance, and both are 0 when GJK reports an
//!   intersection.
//!
//! The distance estimate is not checked against the truth: its rounding
//! grows with the conditioning of the final simplex (an early version of this
//! target found a point on an edge of a sliver face 0.003 thin,
//! converged at a distance of `1.46e-12`, about `6,600 u s`, with bound 0;
//! `fuzz/README.md`, "Findings"). The certificate is the documented guarantee.
//!
//! The input is raw bytes read as bounded numbers (missing bytes read as
//! zero).

#![no_main]

use libfuzzer_sys::fuzz_target;
use motion_bound::reference::DoubleDouble;
use motion_bound::{gjk_distance, ConvexPolytope, Float, GjkParams, Pose, Vec3};
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

/// A placement: identity, or (selector 1) any matrix with entries in
/// `[-1, 1]` and a translation within 2 (`ConvexPolytope` does not need `R`
/// to be orthonormal: the hull is that of the exact `R r + x`).
fn pose(b: &mut Bytes<'_>) -> Option<([[f64; 3]; 3], [f64; 3])> {
    (b.u8() % 4 == 1).then(|| {
        let mut m = [[0.0; 3]; 3];
        for row in &mut m {
            *row = [b.range(-1.0, 1.0), b.range(-1.0, 1.0), b.range(-1.0, 1.0)];
        }
        (
            m,
            [b.range(-2.0, 2.0), b.range(-2.0, 2.0), b.range(-2.0, 2.0)],
        )
    })
}

/// The exactly placed point `R r + x` in double-double (products exact,
/// sums to about `2^-104` of `sum |R_kj r_j| + |x_k|`), and that magnitude.
fn place(p: Option<&([[f64; 3]; 3], [f64; 3])>, r: [f64; 3]) -> ([DoubleDouble; 3], [f64; 3]) {
    let Some((m, x)) = p else {
        return (r.map(DoubleDouble::from_f64), r.map(f64::abs));
    };
    let mut out = [DoubleDouble::from_f64(0.0); 3];
    let mut mag = [0.0; 3];
    for k in 0..3 {
        let mut s = DoubleDouble::from_f64(x[k]);
        mag[k] = x[k].abs();
        for j in 0..3 {
            s = s.add_dd(DoubleDouble::from_f64(r[j]).mul_f64(m[k][j]));
            mag[k] += (r[j] * m[k][j]).abs();
        }
        out[k] = s;
    }
    (out, mag)
}

type Placement = Option<([[f64; 3]; 3], [f64; 3])>;

fn check<T: Float>(bodies: [(&[[f64; 3]], &Placement); 2]) {
    // Everything rounded to T; the checks use the rounded values exactly.
    let round = |v: &[[f64; 3]]| -> Vec<[T; 3]> { v.iter().map(|p| p.map(T::from_f64)).collect() };
    let round_pose = |p: &Placement| -> Placement {
        p.map(|(m, x)| {
            let r = |v: f64| T::from_f64(v).to_f64();
            (m.map(|row| row.map(r)), x.map(r))
        })
    };
    let [(va, qa), (vb, qb)] = bodies;
    let (ta, tb) = (round(va), round(vb));
    let (qa, qb) = (round_pose(qa), round_pose(qb));
    let to_pose = |p: &Placement| match p {
        None => Pose::IDENTITY,
        Some((m, x)) => Pose::new(
            m.map(|row| row.map(T::from_f64)),
            Vec3::from_array(x.map(T::from_f64)),
        ),
    };
    let pa = ConvexPolytope::try_new(&ta, to_pose(&qa)).expect("finite vertices and pose");
    let pb = ConvexPolytope::try_new(&tb, to_pose(&qb)).expect("finite vertices and pose");
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
            // `(b - a) . n >= lb` and `|b - a| >= lb`: both follow from
            // `(b - a) . n >= lb max(1, |n|)`.
            let norm = nn.sqrt();
            let need = if norm.to_f64() < 1.0 {
                DoubleDouble::from_f64(lb)
            } else {
                norm.mul_f64(lb)
            };
            let placed = |t: &[[T; 3]], q: &Placement| -> Vec<([DoubleDouble; 3], [f64; 3])> {
                t.iter()
                    .map(|p| place(q.as_ref(), p.map(T::to_f64)))
                    .collect()
            };
            for (a, ma) in placed(&ta, &qa) {
                for (b, mb) in placed(&tb, &qb) {
                    let sep = (0..3).fold(DoubleDouble::from_f64(0.0), |s, k| {
                        s.add_dd(b[k].sub_dd(a[k]).mul_f64(n[k]))
                    });
                    // Double-double's own error, about 2^-104 of the terms.
                    let terms: f64 = (0..3).map(|k| (ma[k] + mb[k]) * n[k].abs()).sum();
                    let slack = DoubleDouble::from_f64(terms * 2f64.powi(-96));
                    assert!(
                        sep.add_dd(slack).sub_dd(need).to_f64() >= 0.0,
                        "not certified: (b - a) . {n:?} = {} < {lb} max(1, |n|) ({r:?}; A {ta:?} at {qa:?}, B {tb:?} at {qb:?})",
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
    let f64_case = b.u8().is_multiple_of(2);
    let (qa, qb) = (pose(&mut b), pose(&mut b));
    let sq = |q: Placement| q.map(|(m, x)| (m, x.map(|c| c * scale)));
    let (qa, qb) = (sq(qa), sq(qb));
    if f64_case {
        check::<f64>([(&va, &qa), (&vb, &qb)]);
        check::<f64>([(&vb, &qb), (&va, &qa)]);
    } else {
        check::<f32>([(&va, &qa), (&vb, &qb)]);
    }
}

fuzz_target!(|data: &[u8]| run(data));
