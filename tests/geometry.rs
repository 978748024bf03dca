//! Triangle distances, triangle intersection and GJK against independent
//! computations:
//!
//! * `triangle_triangle` against dense barycentric sampling of both triangles
//!   (an upper bound that converges to the distance) and against the
//!   separating-axis certificate along its own witness direction (a lower
//!   bound: for convex sets, `d >= min_b b.n - max_a a.n` for every unit
//!   `n`, with equality at the closest direction); the witnesses must lie on
//!   their triangles, so the reported distance is realised;
//! * planted common points must give exactly 0;
//! * the floating-point meeting decision against `triangles_intersect_exact`
//!   (exact predicates), on random, small-integer and near-degenerate input;
//! * `gjk_distance` on random convex vertex sets (flat, collinear, repeated,
//!   single points) against the brute-force minimum of `triangle_triangle`
//!   over all vertex triples plus a containment test, and its certified lower
//!   bound against the separation along its direction evaluated in
//!   double-double arithmetic from the exact pose map `R r + x`.
//!
//! Every property runs for `f64` and `f32` (inputs rounded to `f32` first;
//! references evaluated on the rounded values).

use motion_bound::reference::DoubleDouble;
use motion_bound::testkit::triangles_intersect_exact;
use motion_bound::{
    gjk_distance, rotate_about_axis, try_point_triangle, try_segment_segment,
    try_triangle_triangle, ClosestPoints, ConvexPolytope, Float, GjkParams, Point3, Pose, Vec3,
};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

// Every point these tests build is finite: the distance functions' typed
// error for non-finite input is checked in their unit tests.
fn triangle_triangle<T: Float>(a: &[Point3<T>; 3], b: &[Point3<T>; 3]) -> ClosestPoints<T> {
    try_triangle_triangle(a, b).expect("finite points")
}

fn point_triangle<T: Float>(p: Point3<T>, t: [Point3<T>; 3]) -> ClosestPoints<T> {
    try_point_triangle(p, t).expect("finite points")
}

fn segment_segment<T: Float>(
    p0: Point3<T>,
    p1: Point3<T>,
    q0: Point3<T>,
    q1: Point3<T>,
) -> ClosestPoints<T> {
    try_segment_segment(p0, p1, q0, q1).expect("finite points")
}

type Tri = [[f64; 3]; 3];

/// `PROPTEST_CASES` from the environment, else `default`.
fn cases(default: u32) -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(default)
}

// ---------------------------------------------------------------- helpers

fn round_to<T: Float>(t: &Tri) -> Tri {
    t.map(|p| p.map(|x| T::from_f64(x).to_f64()))
}

fn to_t<T: Float>(t: &Tri) -> [Point3<T>; 3] {
    t.map(|p| Point3::new(T::from_f64(p[0]), T::from_f64(p[1]), T::from_f64(p[2])))
}

fn f64_of<T: Float>(v: Point3<T>) -> [f64; 3] {
    [v.x.to_f64(), v.y.to_f64(), v.z.to_f64()]
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn norm(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

fn max_abs(points: &[[f64; 3]]) -> f64 {
    points
        .iter()
        .flat_map(|p| p.iter())
        .fold(0.0f64, |m, x| m.max(x.abs()))
}

fn longest_edge(t: &Tri) -> f64 {
    (0..3)
        .map(|i| norm(sub(t[i], t[(i + 1) % 3])))
        .fold(0.0, f64::max)
}

/// An upper bound of the distance from `p` to triangle `t`, independent of
/// the crate: the least distance from `p` to an explicit point of the
/// triangle (the nearest on each edge, and the point at `p`'s barycentric
/// coordinates when they lie in the triangle), plus what rounding may have
/// moved those points off it.
///
/// A point `a + l (b - a)` with `0 <= l <= 1`, or `t0 + l1 e1 + l2 e2` with
/// `l1, l2 >= 0` and `l1 + l2 <= 1`, is on the triangle in exact arithmetic
/// whatever `l` is, so an inaccurate `l` only makes the bound looser, never
/// too small; each coordinate computed in `f64` is within `8 u s` of that
/// point (`u` = 2^-53, `s` the largest coordinate: one rounding of each
/// difference, product and sum, each of magnitude at most `5 s`), and the
/// norm adds relative `4 u`. The barycentric coordinates are solved by the
/// normal equations with one step of iterative refinement, so that on a
/// long narrow triangle (where the crate's `point_triangle` errs by the
/// triangle's condition) the point found is the nearest to rounding.
fn distance_to_triangle_above(p: [f64; 3], t: &Tri) -> f64 {
    let s = max_abs(&[p, t[0], t[1], t[2]]);
    let add = |a: [f64; 3], e: [f64; 3], l: f64| [0, 1, 2].map(|k| a[k] + l * e[k]);
    let mut best = f64::INFINITY;
    for i in 0..3 {
        let (a, b) = (t[i], t[(i + 1) % 3]);
        let e = sub(b, a);
        let ee = dot(e, e);
        let l = if ee > 0.0 {
            (dot(sub(p, a), e) / ee).clamp(0.0, 1.0)
        } else {
            0.0
        };
        best = best.min(norm(sub(p, add(a, e, l))));
    }
    let (e1, e2) = (sub(t[1], t[0]), sub(t[2], t[0]));
    let (g11, g12, g22) = (dot(e1, e1), dot(e1, e2), dot(e2, e2));
    let det = g11 * g22 - g12 * g12;
    if det > 0.0 {
        let solve = |r: [f64; 3]| {
            let (r1, r2) = (dot(e1, r), dot(e2, r));
            ((g22 * r1 - g12 * r2) / det, (g11 * r2 - g12 * r1) / det)
        };
        let (mut l1, mut l2) = solve(sub(p, t[0]));
        let x = add(add(t[0], e1, l1), e2, l2);
        let (d1, d2) = solve(sub(p, x));
        l1 += d1;
        l2 += d2;
        if l1 >= 0.0 && l2 >= 0.0 && l1 + l2 <= 1.0 {
            best = best.min(norm(sub(p, add(add(t[0], e1, l1), e2, l2))));
        }
    }
    let u = f64::EPSILON / 2.0;
    best * (1.0 + 4.0 * u) + 16.0 * u * s
}

/// How ill-conditioned a triangle's plane is: the largest
/// `|e1| |e2| / |e1 x e2|` over its corners, i.e. `1 / sin` of its worst
/// angle (1 for an exactly flat, zero-area triangle, which the code treats
/// as a segment and never takes a plane of). The error of a point's
/// distance to the plane, computed through the normal, grows like this
/// factor times `u s`.
fn plane_condition(t: &Tri) -> f64 {
    let k = (0..3)
        .map(|i| {
            let (e1, e2) = (sub(t[(i + 1) % 3], t[i]), sub(t[(i + 2) % 3], t[i]));
            norm(e1) * norm(e2) / norm(cross(e1, e2))
        })
        .fold(1.0, f64::max);
    if k.is_finite() {
        k
    } else {
        1.0
    }
}

/// The distance between barycentric grids of `n` subdivisions on each
/// triangle: an upper bound of the true distance, within
/// `(longest edge of a + longest edge of b) / n` of it.
fn sampled_distance(a: &Tri, b: &Tri, n: usize) -> f64 {
    let grid = |t: &Tri| {
        let mut pts = Vec::new();
        for i in 0..=n {
            for j in 0..=n - i {
                let (s, r) = (i as f64 / n as f64, j as f64 / n as f64);
                pts.push(
                    [0, 1, 2].map(|k| t[0][k] + (t[1][k] - t[0][k]) * s + (t[2][k] - t[0][k]) * r),
                );
            }
        }
        pts
    };
    let (ga, gb) = (grid(a), grid(b));
    let mut best = f64::INFINITY;
    for p in &ga {
        for q in &gb {
            best = best.min(dot(sub(*p, *q), sub(*p, *q)));
        }
    }
    best.sqrt()
}

/// `min_b b.n - max_a a.n` over vertices (the extremes of a linear function
/// on a triangle): a lower bound of the distance for unit `n`.
fn separation(a: &[[f64; 3]], b: &[[f64; 3]], n: [f64; 3]) -> f64 {
    let max_a = a
        .iter()
        .map(|p| dot(*p, n))
        .fold(f64::NEG_INFINITY, f64::max);
    let min_b = b.iter().map(|p| dot(*p, n)).fold(f64::INFINITY, f64::min);
    min_b - max_a
}

// ------------------------------------------------------------- strategies

fn coord() -> impl Strategy<Value = f64> {
    prop_oneof![8 => -1.0f64..1.0, 1 => Just(0.0), 1 => Just(0.5), 1 => Just(-1.0)]
}

fn point() -> impl Strategy<Value = [f64; 3]> {
    [coord(), coord(), coord()]
}

fn grid_point() -> impl Strategy<Value = [f64; 3]> {
    [-2i8..=2, -2i8..=2, -2i8..=2].prop_map(|p| p.map(f64::from))
}

/// One triangle, biased to degenerate shapes.
fn triangle() -> BoxedStrategy<Tri> {
    prop_oneof![
        6 => [point(), point(), point()],
        1 => (point(), point(), 0.0f64..1.0).prop_map(|(p, q, t)| {
            [p, q, [0, 1, 2].map(|k| p[k] + (q[k] - p[k]) * t)]
        }),
        1 => (point(), point()).prop_map(|(p, q)| [p, p, q]),
        1 => point().prop_map(|p| [p, p, p]),
    ]
    .boxed()
}

/// A pair of triangles in some relation.
fn pair() -> BoxedStrategy<(Tri, Tri)> {
    prop_oneof![
        // Independent, at a random offset and scale.
        6 => (triangle(), triangle(), point(), -3i32..=3).prop_map(|(a, b, off, e)| {
            let s = 10f64.powi(e);
            let m = |t: Tri, o: f64| t.map(|p| [0, 1, 2].map(|k| (p[k] + off[k] * o) * s));
            (m(a, 0.0), m(b, 1.5))
        }),
        // Coplanar in z = c.
        2 => (triangle(), triangle(), coord()).prop_map(|(a, b, c)| {
            let f = |t: Tri| t.map(|p| [p[0], p[1], c]);
            (f(a), f(b))
        }),
        // Parallel planes a small gap apart.
        1 => (triangle(), triangle(), 1e-9f64..1e-3).prop_map(|(a, b, g)| {
            (a.map(|p| [p[0], p[1], 0.0]), b.map(|p| [p[0], p[1], g]))
        }),
        // A shared vertex.
        2 => (triangle(), point(), point()).prop_map(|(a, p, q)| (a, [a[1], p, q])),
        // A shared edge.
        1 => (triangle(), point()).prop_map(|(a, p)| (a, [a[2], a[0], p])),
        // Small integers: exact degeneracies of every kind.
        3 => ([grid_point(), grid_point(), grid_point()], [grid_point(), grid_point(), grid_point()]),
    ]
    .boxed()
}

// ------------------------------------------------- triangle_triangle checks

fn check_triangle_pair<T: Float>(a64: &Tri, b64: &Tri) -> Result<(), TestCaseError> {
    let (a64, b64) = (round_to::<T>(a64), round_to::<T>(b64));
    let (a, b) = (to_t::<T>(&a64), to_t::<T>(&b64));
    let c = triangle_triangle(&a, &b);
    let u = T::UNIT_ROUNDOFF.to_f64();
    let s = max_abs(&a64).max(max_abs(&b64)).max(f64::MIN_POSITIVE);
    let tol = 1024.0 * u * s;
    let d = c.distance.to_f64();
    prop_assert!(d.is_finite() && d >= 0.0, "finite, non-negative: {d}");
    prop_assert_eq!(
        c.distance,
        (c.on_b - c.on_a).length(),
        "distance is |on_b - on_a|"
    );
    if d == 0.0 {
        prop_assert_eq!(c.on_a, c.on_b, "a common point when meeting");
    }
    // The witnesses are on their triangles, so `d` is realised (d >= true);
    // measured independently of the crate (its own `point_triangle` errs by
    // a narrow triangle's condition: a witness on a triangle 0.02 wide and
    // 1.5 long measured 1.2e-13 off it, where exact predicates put it on).
    let wa = distance_to_triangle_above(f64_of(c.on_a), &a64);
    let wb = distance_to_triangle_above(f64_of(c.on_b), &b64);
    prop_assert!(
        wa <= tol && wb <= tol,
        "witnesses off their triangles: {wa}, {wb}"
    );
    // Sampling: an upper bound of the truth that converges to it.
    let n = 12;
    let sampled = sampled_distance(&a64, &b64, n);
    prop_assert!(
        d <= sampled + tol,
        "above the sampled upper bound: {d} > {sampled}"
    );
    let slack = (longest_edge(&a64) + longest_edge(&b64)) / n as f64;
    prop_assert!(
        d >= sampled - slack - tol,
        "far below sampling: {d} < {sampled} - {slack}"
    );
    // The separating-axis certificate along the witness direction. A pair
    // within `eps` of the optimum fixes the direction only to about
    // `sqrt(eps / d)` when the minimum is flat (a vertex against an edge that
    // is nearly orthogonal to the closest direction), so for `K = A - B` of
    // diameter `D` the sound statement is
    // `sep(n) >= d - D sqrt(2 d eps + eps^2) / d`.
    let eps = 256.0 * u * s;
    if d > 1e3 * eps {
        let w = sub(f64_of(c.on_b), f64_of(c.on_a));
        let nrm = norm(w);
        let dir = w.map(|x| x / nrm);
        let diam = longest_edge(&a64) + longest_edge(&b64);
        let sep = separation(&a64, &b64, dir);
        let slack = diam * (2.0 * d * eps + eps * eps).sqrt() / d + eps;
        prop_assert!(
            sep >= d - slack,
            "not optimal: separation {sep} < distance {d} - {slack}"
        );
    }
    // The tight check: GJK (signed volumes, an independent algorithm) on the
    // two triangles as polytopes. Its lower bound is certified, and the
    // realised distance may not exceed it by more than rounding.
    let (va, vb) = (a.map(|p| p.to_array()), b.map(|p| p.to_array()));
    let pa = ConvexPolytope::try_new(&va, Pose::IDENTITY)
        .map_err(|e| TestCaseError::fail(format!("{e}")))?;
    let pb = ConvexPolytope::try_new(&vb, Pose::IDENTITY)
        .map_err(|e| TestCaseError::fail(format!("{e}")))?;
    let g = gjk_distance(&pa, &pb, &GjkParams::default());
    let lb = g.lower_bound.to_f64();
    prop_assert!(d >= lb, "below GJK's certified lower bound: {d} < {lb}");
    if g.converged && !g.intersecting {
        let tight = 32768.0 * u * s;
        prop_assert!(
            d <= lb + tight,
            "above GJK's lower bound: {d} > {lb} + {tight}"
        );
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases(512)))]

    #[test]
    fn triangle_distance_is_realised_optimal_and_matches_sampling_f64((a, b) in pair()) {
        check_triangle_pair::<f64>(&a, &b)?;
        check_triangle_pair::<f64>(&b, &a)?;
    }

    #[test]
    fn triangle_distance_is_realised_optimal_and_matches_sampling_f32((a, b) in pair()) {
        check_triangle_pair::<f32>(&a, &b)?;
    }
}

/// The test's own measure of a witness (`distance_to_triangle_above`) on
/// long narrow triangles (0.02 wide, 1.5 long, turned at random): points
/// on them measure within rounding of 0, and points lifted off the plane
/// by `h` or pushed past an edge by `h` measure within rounding of `h`
/// (an upper bound, so never below it).
#[test]
fn the_witness_measure_is_tight_on_narrow_triangles() {
    let mut rng = motion_bound::testkit::toi::Rng::new(0x5eed);
    let mut r = || rng.unit();
    let u = f64::EPSILON / 2.0;
    for _ in 0..2000 {
        let o = [r() - 0.5, r() - 0.5, r() - 0.5];
        let long = {
            let v = [r() - 0.5, r() - 0.5, r() - 0.5];
            v.map(|x| x / norm(v))
        };
        let side = {
            let v = cross(long, [r() - 0.5, r() - 0.5, r() - 0.5]);
            v.map(|x| x / norm(v))
        };
        let up = cross(long, side);
        let at = |x: f64, y: f64, z: f64| {
            [0, 1, 2].map(|k| o[k] + x * long[k] + y * side[k] + z * up[k])
        };
        let t: Tri = [
            at(0.0, 0.0, 0.0),
            at(1.5, 0.0, 0.0),
            at(0.75 * r(), 0.02, 0.0),
        ];
        let s = max_abs(&t);
        let (l1, l2) = (r(), r());
        let (l1, l2) = if l1 + l2 > 1.0 {
            (1.0 - l1, 1.0 - l2)
        } else {
            (l1, l2)
        };
        let p = [0, 1, 2].map(|k| t[0][k] + l1 * (t[1][k] - t[0][k]) + l2 * (t[2][k] - t[0][k]));
        let d = distance_to_triangle_above(p, &t);
        assert!(
            d <= 32.0 * u * s,
            "a point on the triangle measured {d} off it"
        );
        let h = 1e-6 * r();
        let lifted = [0, 1, 2].map(|k| p[k] + h * up[k]);
        let d = distance_to_triangle_above(lifted, &t);
        assert!(
            d >= h && d <= h + 32.0 * u * s,
            "lifted by {h}: measured {d}"
        );
        let x = 0.75 * r();
        let past = [0, 1, 2].map(|k| o[k] + x * long[k] - h * side[k]);
        let d = distance_to_triangle_above(past, &t);
        assert!(
            d >= h && d <= h + 32.0 * u * s,
            "past an edge by {h}: measured {d}"
        );
    }
}

/// A sliver (nearly collinear corners, about 1e-4 wide over 1.4) against a
/// degenerate triangle (a short segment) just below it: the case a random
/// run found, where Ericson's region signs were rounding noise in `f32` and
/// the witness on the sliver came out a sliver's width off it.
#[test]
fn a_point_on_a_sliver_is_on_it() {
    let a: Tri = [[-0.004954330203832879, 0.0, 0.0], [0.0; 3], [0.0; 3]];
    let b: Tri = [
        [-0.9698743650370552, 0.8989657507748913, 1e-9],
        [0.04337087761389626, 0.3590708888529945, 1e-9],
        [0.35636941772486513, 0.19251574083948125, 1e-9],
    ];
    for (x, y) in [(&a, &b), (&b, &a)] {
        check_triangle_pair::<f32>(x, y).unwrap();
        check_triangle_pair::<f64>(x, y).unwrap();
    }
    // Points along edge BC, in f32: on the sliver up to the rounding of
    // their own coordinates, so at rounding distance from it (the corners
    // are within 1 of the origin).
    let t32 = to_t::<f32>(&round_to::<f32>(&b));
    for k in 1..8u8 {
        let p = t32[1] + (t32[2] - t32[1]) * (f32::from(k) / 8.0);
        let d = point_triangle(p, t32).distance;
        assert!(
            f64::from(d) <= 64.0 * f64::from(f32::EPSILON),
            "the point {k}/8 along an edge of the sliver is {d} from it"
        );
    }
}

// ------------------------------------------------------- planted meetings

fn planted<T: Float>(
    x: [f64; 3],
    u0: [f64; 3],
    u1: [f64; 3],
    v0: [f64; 3],
    v1: [f64; 3],
    flat: bool,
) -> Result<(), TestCaseError> {
    let f = |p: [f64; 3]| if flat { [p[0], p[1], 0.0] } else { p };
    let (u0, u1, v0, v1) = (f(u0), f(u1), f(v0), f(v1));
    // Triangles with centroid x (up to rounding), not too thin.
    let around = |p: [f64; 3], q: [f64; 3]| -> Tri {
        [
            [0, 1, 2].map(|k| x[k] + p[k]),
            [0, 1, 2].map(|k| x[k] + q[k]),
            [0, 1, 2].map(|k| x[k] - p[k] - q[k]),
        ]
    };
    let (a64, b64) = (
        round_to::<T>(&around(u0, u1)),
        round_to::<T>(&around(v0, v1)),
    );
    let thin = |t: &Tri| {
        let n = {
            let (e1, e2) = (sub(t[1], t[0]), sub(t[2], t[0]));
            norm([
                e1[1] * e2[2] - e1[2] * e2[1],
                e1[2] * e2[0] - e1[0] * e2[2],
                e1[0] * e2[1] - e1[1] * e2[0],
            ])
        };
        n < 0.05 * longest_edge(t).powi(2)
    };
    prop_assume!(!thin(&a64) && !thin(&b64));
    if !flat {
        // The planes must cross at a healthy angle for a robust meeting.
        let nrm = |t: &Tri| {
            let (e1, e2) = (sub(t[1], t[0]), sub(t[2], t[0]));
            let n = [
                e1[1] * e2[2] - e1[2] * e2[1],
                e1[2] * e2[0] - e1[0] * e2[2],
                e1[0] * e2[1] - e1[1] * e2[0],
            ];
            n.map(|c| c / norm(n))
        };
        prop_assume!(dot(nrm(&a64), nrm(&b64)).abs() < 0.99);
    }
    prop_assert!(
        triangles_intersect_exact(&a64, &b64),
        "the exact test sees the planted point"
    );
    let c = triangle_triangle(&to_t::<T>(&a64), &to_t::<T>(&b64));
    prop_assert_eq!(
        c.distance.to_f64(),
        0.0,
        "planted common point: distance exactly 0"
    );
    prop_assert_eq!(c.on_a, c.on_b, "one witness");
    let tol = 1024.0 * T::UNIT_ROUNDOFF.to_f64() * 4.0;
    let wa = point_triangle(c.on_a, to_t::<T>(&a64)).distance.to_f64();
    let wb = point_triangle(c.on_a, to_t::<T>(&b64)).distance.to_f64();
    prop_assert!(
        wa <= tol && wb <= tol,
        "the common point is on both: {wa}, {wb}"
    );
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig {
        max_global_rejects: 1 << 20,
        ..ProptestConfig::with_cases(cases(512))
    })]

    #[test]
    fn planted_common_point_gives_zero(
        x in point(), u0 in point(), u1 in point(), v0 in point(), v1 in point(), flat in any::<bool>()
    ) {
        planted::<f64>(x, u0, u1, v0, v1, flat)?;
        planted::<f32>(x, u0, u1, v0, v1, flat)?;
    }
}

// ------------------------------------------------ floating vs exact meeting

/// How strictly the float decision must match the exact one.
#[derive(Clone, Copy, PartialEq)]
enum Agreement {
    /// Exactly: small-integer and random input. The filtered predicates
    /// fall back to exact ones for any sign they cannot call, so meeting is
    /// decided exactly, and the snap to 0 needs a candidate pair within
    /// `2^10 u s`. (Before the fallback, an `f32` vertex 8.8e-7, about
    /// 15 `u`, from an edge of the other triangle was reported at 0 for a
    /// pair that does not meet: `tests/geometry.proptest-regressions`.)
    Exact,
    /// Planted near-contact: a disagreement only within rounding.
    Near,
}

/// The float meeting decision (distance 0) against the exact predicates.
fn check_meeting<T: Float>(a64: &Tri, b64: &Tri, agree: Agreement) -> Result<(), TestCaseError> {
    let strict = agree != Agreement::Near;
    let (a64, b64) = (round_to::<T>(a64), round_to::<T>(b64));
    let exact = triangles_intersect_exact(&a64, &b64);
    prop_assert_eq!(
        exact,
        triangles_intersect_exact(&b64, &a64),
        "exact test is symmetric"
    );
    let d = triangle_triangle(&to_t::<T>(&a64), &to_t::<T>(&b64))
        .distance
        .to_f64();
    let d_swapped = triangle_triangle(&to_t::<T>(&b64), &to_t::<T>(&a64))
        .distance
        .to_f64();
    let s = max_abs(&a64).max(max_abs(&b64)).max(f64::MIN_POSITIVE);
    // Rounding-level, scaled by the planes' conditioning: a touching pair
    // with a sliver (worst angle about 0.5 degrees) came out at about
    // `1850 u s` (`tests/geometry.proptest-regressions`), `15 u s` times the
    // sliver's condition factor (120); see `triangle_triangle`'s "Accuracy".
    let kappa = plane_condition(&a64).max(plane_condition(&b64));
    let tol = 1024.0 * T::UNIT_ROUNDOFF.to_f64() * s * kappa;
    if strict {
        prop_assert_eq!(
            d == 0.0,
            exact,
            "float distance {} vs exact meeting {}",
            d,
            exact
        );
        prop_assert_eq!(
            d_swapped == 0.0,
            exact,
            "swapped: float distance {} vs exact {}",
            d_swapped,
            exact
        );
    } else if exact != (d == 0.0) {
        prop_assert!(
            d <= tol,
            "disagreement beyond rounding: exact {exact}, distance {d} (tolerance \
             {tol:e} = 1024 u s times the plane condition factor {kappa})"
        );
    }
    Ok(())
}

/// A triangle with one vertex computed onto another triangle's face or edge.
fn touching() -> impl Strategy<Value = (Tri, Tri)> {
    (
        [point(), point(), point()],
        (0.0f64..1.0, 0.0f64..1.0),
        point(),
        point(),
        any::<bool>(),
    )
        .prop_map(|(a, (s, t), p, q, on_edge)| {
            let (s, t) = if on_edge {
                (s, 0.0)
            } else if s + t > 1.0 {
                (1.0 - s, 1.0 - t)
            } else {
                (s, t)
            };
            let x = [0, 1, 2].map(|k| a[0][k] + (a[1][k] - a[0][k]) * s + (a[2][k] - a[0][k]) * t);
            (a, [x, p, q])
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases(1024)))]

    #[test]
    fn meeting_agrees_with_exact_predicates_on_generic_and_integer_input((a, b) in pair()) {
        // Small-integer pairs and generic pairs must agree exactly; the other
        // families of `pair` are within rounding of degenerate by design.
        let integer = a.iter().chain(b.iter()).flatten().all(|x| x.fract() == 0.0 && x.abs() <= 2.0);
        let agree = if integer { Agreement::Exact } else { Agreement::Near };
        check_meeting::<f64>(&a, &b, agree)?;
        check_meeting::<f32>(&a, &b, agree)?;
    }

    #[test]
    fn meeting_agrees_with_exact_predicates_on_random_triangles(
        a in [point(), point(), point()], b in [point(), point(), point()]
    ) {
        check_meeting::<f64>(&a, &b, Agreement::Exact)?;
        check_meeting::<f32>(&a, &b, Agreement::Exact)?;
    }

    #[test]
    fn near_contact_disagrees_only_within_rounding((a, b) in touching()) {
        check_meeting::<f64>(&a, &b, Agreement::Near)?;
        check_meeting::<f32>(&a, &b, Agreement::Near)?;
    }
}

// --------------------------------------------------------------------- GJK

/// A vertex set of 1 to 8 body points, biased to degenerate sets.
fn vertex_set() -> impl Strategy<Value = Vec<[f64; 3]>> {
    prop_oneof![
        4 => prop::collection::vec(point(), 1..=8),
        // Flat (z = 0 in the body frame).
        1 => prop::collection::vec(point(), 3..=8).prop_map(|v| v.into_iter().map(|p| [p[0], p[1], 0.0]).collect()),
        // Collinear.
        1 => (point(), prop::collection::vec(-1.0f64..1.0, 2..=5)).prop_map(|(d, ts)| {
            ts.into_iter().map(|t| d.map(|c| c * t)).collect()
        }),
        // Repeated points.
        1 => prop::collection::vec(point(), 1..=4).prop_map(|v| v.iter().chain(v.iter()).copied().collect()),
        // One point.
        1 => point().prop_map(|p| vec![p]),
    ]
}

fn pose_from(axis: [f64; 3], angle: f64, x: [f64; 3]) -> Pose<f64> {
    let k = Vec3::from_array(axis).normalize_or(Vec3::new(0.0, 0.0, 1.0));
    let col = |e: [f64; 3]| rotate_about_axis(Vec3::from_array(e), k, angle);
    let (c0, c1, c2) = (
        col([1.0, 0.0, 0.0]),
        col([0.0, 1.0, 0.0]),
        col([0.0, 0.0, 1.0]),
    );
    Pose::new(
        [[c0.x, c1.x, c2.x], [c0.y, c1.y, c2.y], [c0.z, c1.z, c2.z]],
        Vec3::from_array(x),
    )
}

fn pose_to<S: Float, T: Float>(p: &Pose<S>) -> Pose<T> {
    let c = |x: S| T::from_f64(x.to_f64());
    Pose::new(
        p.rotation.map(|r| r.map(c)),
        Vec3::new(c(p.translation.x), c(p.translation.y), c(p.translation.z)),
    )
}

fn dd(x: f64) -> DoubleDouble {
    DoubleDouble::new(x, 0.0)
}

/// `(R r + x) . n` in double-double from the exact (widened) inputs.
fn placed_dot_dd(p: &Pose<f64>, r: [f64; 3], n: [f64; 3]) -> DoubleDouble {
    let x = p.translation.to_array();
    let mut acc = dd(0.0);
    for k in 0..3 {
        let mut coord = dd(x[k]);
        for (rkl, rl) in p.rotation[k].iter().zip(r) {
            coord = coord.add_dd(dd(*rkl).mul_f64(rl));
        }
        acc = acc.add_dd(coord.mul_f64(n[k]));
    }
    acc
}

/// The world vertices in `f64` (for the brute force; rounding ~1e-16).
fn world(p: &Pose<f64>, v: &[[f64; 3]]) -> Vec<[f64; 3]> {
    v.iter().map(|r| p.transform_point(*r).to_array()).collect()
}

/// Brute force: the minimum of `triangle_triangle` over all vertex triples
/// (with repetition, so points and segments are included), or 0 when a
/// vertex of one set lies in a non-degenerate tetrahedron of the other.
fn brute_force(a: &[[f64; 3]], b: &[[f64; 3]]) -> f64 {
    let triples = |v: &[[f64; 3]]| {
        let mut t = Vec::new();
        for i in 0..v.len() {
            for j in i..v.len() {
                for k in j..v.len() {
                    t.push([v[i], v[j], v[k]].map(Point3::from_array));
                }
            }
        }
        t
    };
    let contains = |v: &[[f64; 3]], x: [f64; 3]| {
        let vol = |p: [f64; 3], q: [f64; 3], r: [f64; 3], s: [f64; 3]| {
            let (a, b, c) = (sub(q, p), sub(r, p), sub(s, p));
            dot(
                a,
                [
                    b[1] * c[2] - b[2] * c[1],
                    b[2] * c[0] - b[0] * c[2],
                    b[0] * c[1] - b[1] * c[0],
                ],
            )
        };
        let n = v.len();
        for i in 0..n {
            for j in i + 1..n {
                for k in j + 1..n {
                    for l in k + 1..n {
                        let t = vol(v[i], v[j], v[k], v[l]);
                        if t.abs() < 1e-9 {
                            continue;
                        }
                        let l0 = vol(x, v[j], v[k], v[l]) / t;
                        let l1 = vol(v[i], x, v[k], v[l]) / t;
                        let l2 = vol(v[i], v[j], x, v[l]) / t;
                        let l3 = vol(v[i], v[j], v[k], x) / t;
                        if [l0, l1, l2, l3].iter().all(|&w| w >= -1e-12) {
                            return true;
                        }
                    }
                }
            }
        }
        false
    };
    if a.iter().any(|&x| contains(b, x)) || b.iter().any(|&x| contains(a, x)) {
        return 0.0;
    }
    let (ta, tb) = (triples(a), triples(b));
    let mut best = f64::INFINITY;
    for x in &ta {
        for y in &tb {
            best = best.min(triangle_triangle(x, y).distance);
        }
    }
    best
}

fn check_gjk<T: Float>(
    va: &[[f64; 3]],
    vb: &[[f64; 3]],
    pa: &Pose<f64>,
    pb: &Pose<f64>,
) -> Result<(), TestCaseError> {
    // Round everything to T, then use the rounded values as the exact truth.
    let va: Vec<[f64; 3]> = va
        .iter()
        .map(|p| p.map(|x| T::from_f64(x).to_f64()))
        .collect();
    let vb: Vec<[f64; 3]> = vb
        .iter()
        .map(|p| p.map(|x| T::from_f64(x).to_f64()))
        .collect();
    let (pa_t, pb_t) = (pose_to::<f64, T>(pa), pose_to::<f64, T>(pb));
    let (pa, pb) = (pose_to::<T, f64>(&pa_t), pose_to::<T, f64>(&pb_t));
    let va_t: Vec<[T; 3]> = va.iter().map(|p| p.map(T::from_f64)).collect();
    let vb_t: Vec<[T; 3]> = vb.iter().map(|p| p.map(T::from_f64)).collect();
    let a =
        ConvexPolytope::try_new(&va_t, pa_t).map_err(|e| TestCaseError::fail(format!("{e}")))?;
    let b =
        ConvexPolytope::try_new(&vb_t, pb_t).map_err(|e| TestCaseError::fail(format!("{e}")))?;
    let r = gjk_distance(&a, &b, &GjkParams::default());
    let (wa, wb) = (world(&pa, &va), world(&pb, &vb));
    let truth = brute_force(&wa, &wb);
    let s = max_abs(&wa).max(max_abs(&wb)).max(1.0);
    let u = T::UNIT_ROUNDOFF.to_f64();
    let tol = 4096.0 * u * s;
    let lb = r.lower_bound.to_f64();
    let d = r.distance.to_f64();
    prop_assert!(
        lb >= 0.0 && lb <= d,
        "0 <= lower bound {lb} <= distance {d}"
    );
    prop_assert!(
        lb <= truth + 1e-13 * s,
        "lower bound {lb} above the brute force {truth}"
    );
    prop_assert!(
        r.iterations <= GjkParams::<T>::default().max_iterations,
        "iteration cap"
    );
    if r.intersecting {
        prop_assert!(
            truth <= tol,
            "GJK says intersecting, brute force says {truth}"
        );
        prop_assert_eq!(d, 0.0, "zero distance when intersecting");
        return Ok(());
    }
    prop_assert!(
        d >= truth - tol,
        "distance {d} below the brute force {truth}"
    );
    if r.converged {
        prop_assert!(
            d <= truth * (1.0 + 1e-9) + tol,
            "converged distance {d} above the brute force {truth}"
        );
    }
    // The certified directional separation, checked in double-double from
    // the exact pose map: (b - a) . n >= lower_bound for all vertices.
    if let Some(n) = r.direction {
        let n = n.get().to_array().map(Float::to_f64);
        let max_a = va
            .iter()
            .map(|&p| placed_dot_dd(&pa, p, n))
            .fold(dd(f64::NEG_INFINITY), |m, x| if x > m { x } else { m });
        let min_b = vb
            .iter()
            .map(|&p| placed_dot_dd(&pb, p, n))
            .fold(dd(f64::INFINITY), |m, x| if x < m { x } else { m });
        let sep = min_b.sub_dd(max_a);
        prop_assert!(
            sep >= dd(lb),
            "separation along the direction {:?} below the certified bound {lb}",
            sep
        );
        let len = norm(n);
        prop_assert!((len - 1.0).abs() < 8.0 * u, "unit direction: {len}");
    } else {
        prop_assert_eq!(lb, 0.0, "no direction, no bound");
    }
    Ok(())
}

fn pose_strategy() -> impl Strategy<Value = Pose<f64>> {
    (
        point(),
        -4.0f64..4.0,
        [-3.0f64..3.0, -3.0f64..3.0, -3.0f64..3.0],
    )
        .prop_map(|(k, a, x)| pose_from(k, a, x))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases(256)))]

    #[test]
    fn gjk_matches_brute_force_and_certifies_its_bound(
        va in vertex_set(), vb in vertex_set(), pa in pose_strategy(), pb in pose_strategy(),
        far in prop_oneof![3 => Just(0.0f64), 1 => Just(1e3), 1 => Just(-1e6)],
    ) {
        // Far from the origin, the support rounding dwarfs the distances: the
        // hard case for the certified bound.
        let shift = |mut p: Pose<f64>| {
            p.translation = p.translation + Vec3::new(far, 0.5 * far, -far);
            p
        };
        let (pa, pb) = (shift(pa), shift(pb));
        check_gjk::<f64>(&va, &vb, &pa, &pb)?;
        check_gjk::<f32>(&va, &vb, &pa, &pb)?;
    }
}

// ------------------------------------------------------------ stories

#[test]
fn nearly_parallel_segments_keep_their_distance() {
    // Normal equations lose sin^2 of the angle; the cross-product form only sin.
    for k in 4..15 {
        let e = 10f64.powi(-k);
        let c = segment_segment(
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(0.2, 1.0, 0.0),
            Point3::new(0.8, 1.0, e),
        );
        assert!(
            (c.distance - 1.0).abs() < 1e-14,
            "angle 1e-{k}: {}",
            c.distance
        );
    }
}

#[test]
fn a_thin_needle_through_a_triangle_meets_it() {
    // A shallow crossing: the needle's crossing point is ill-conditioned,
    // but its distance is not.
    let a = [
        Point3::new(0.0f64, 0.0, 0.0),
        Point3::new(1.0, 0.0, 0.0),
        Point3::new(0.0, 1.0, 0.0),
    ];
    let b = [
        Point3::new(-1.0, 0.2, -1e-9),
        Point3::new(2.0, 0.2, 2e-9),
        Point3::new(2.0, 0.2 + 1e-12, 2e-9),
    ];
    let c = triangle_triangle(&a, &b);
    assert_eq!(c.distance, 0.0, "meets: {c:?}");
}
