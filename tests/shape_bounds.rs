//! Every convex shape's directed bounds dominate the exact directed speeds of
//! its points (`proofs/12-shapes.md`, Lemma 12.2), in `f32` and `f64`.
//!
//! The oracle: points sampled densely on each shape's boundary (corners,
//! segment ends, rims, apexes, and core points pushed out by the radius in
//! many directions), each point's exact supremum of its directed speed over
//! the interval from the closed-form reference (`reference::Frame`, in
//! double-double for `f64`, in `f64` for `f32`). Samples are pulled towards
//! the body origin by `2^-20` of their length so that rounding never puts one
//! outside the shape. A bound below any sampled point's supremum is a
//! failure; so is a one-sided rate below a point's signed supremum, and an
//! EVQ bound above NEVQ's.

use motion_bound::reference::{DoubleDouble, Frame, Real};
use motion_bound::testkit::toi::Rng;
use motion_bound::{
    BoundKind, Convex, Direction, Float, PreparedMotion, RigidMotion, Rotation, Vec3, VertexSet,
};

/// The pull of samples towards the body origin, `1 - 2^-20`.
const PULL: f64 = 1.0 - 1.0 / 1_048_576.0;

/// Every kind of shape in `T`, with sampled points of its boundary (body
/// frame, in `f64`, from the shape's parameters as rounded to `T`).
/// A named shape with sampled points of its boundary.
type Sampled<T> = (&'static str, Convex<'static, T>, Vec<[f64; 3]>);

fn shapes<T: Float>(rng: &mut Rng) -> Vec<Sampled<T>> {
    let mut out = Vec::new();
    let round = |core: Vec<[f64; 3]>, r: f64, rng: &mut Rng| -> Vec<[f64; 3]> {
        let mut pts = Vec::new();
        for p in core {
            for _ in 0..24 {
                let u = rng.direction();
                pts.push([p[0] + r * u[0], p[1] + r * u[1], p[2] + r * u[2]]);
            }
        }
        pts
    };
    let rims = |h: f64, rho: f64, ys: &[f64]| -> Vec<[f64; 3]> {
        let mut pts = Vec::new();
        for k in 0..64 {
            let phi = f64::from(k) * core::f64::consts::TAU / 64.0;
            for &y in ys {
                pts.push([rho * phi.cos(), y * h, rho * phi.sin()]);
            }
        }
        pts
    };
    // Parameters rounded to T first: the samples are of the shape in T.
    let t = |x: f64| T::from_f64(x);
    let back = |x: T| x.to_f64();
    let (h, r, rho) = (
        back(t(rng.range(0.1, 1.0))),
        back(t(rng.range(0.05, 0.5))),
        back(t(rng.range(0.05, 1.0))),
    );
    let half = [0; 3].map(|_| back(t(rng.range(0.05, 1.0))));
    let corners: Vec<[f64; 3]> = (0..8)
        .map(|k| {
            let s = |bit: u32, x: f64| if k >> bit & 1 == 1 { x } else { -x };
            [s(0, half[0]), s(1, half[1]), s(2, half[2])]
        })
        .collect();
    let mut cone = rims(h, rho, &[-1.0]);
    cone.push([0.0, h, 0.0]);
    let rounded = |c: Convex<'static, T>| c.try_rounded(t(r)).expect("rounded");
    out.push((
        "ball",
        Convex::try_ball(t(r)).expect("ball"),
        round(vec![[0.0; 3]], r, rng),
    ));
    out.push((
        "capsule",
        Convex::try_capsule(t(h), t(r)).expect("capsule"),
        round(vec![[0.0, -h, 0.0], [0.0, h, 0.0]], r, rng),
    ));
    let cuboid = Convex::try_cuboid(half.map(t)).expect("cuboid");
    out.push(("cuboid", cuboid, corners.clone()));
    out.push(("rounded cuboid", rounded(cuboid), round(corners, r, rng)));
    let cylinder = Convex::try_cylinder(t(h), t(rho)).expect("cylinder");
    out.push(("cylinder", cylinder, rims(h, rho, &[-1.0, 1.0])));
    out.push((
        "rounded cylinder",
        rounded(cylinder),
        round(rims(h, rho, &[-1.0, 1.0]), r, rng),
    ));
    let cone_shape = Convex::try_cone(t(h), t(rho)).expect("cone");
    out.push(("cone", cone_shape, cone.clone()));
    out.push(("rounded cone", rounded(cone_shape), round(cone, r, rng)));
    out
}

/// The largest exact supremum over `points` of the directed speed along `n`
/// over the motion's interval: absolute and signed.
fn exact<T: Float, R: Real>(m: &RigidMotion<T>, n: Direction<T>, points: &[[T; 3]]) -> (f64, f64) {
    let frame = Frame::<R>::new(m, n);
    let iv = m.interval();
    let (ta, tb) = (
        R::from_f64(iv.start().to_f64()),
        R::from_f64(iv.end().to_f64()),
    );
    let (mut abs, mut signed) = (f64::NEG_INFINITY, f64::NEG_INFINITY);
    for p in points {
        let profile = frame.profile(*p);
        abs = abs.max(profile.sup_abs(ta, tb).to_f64());
        signed = signed.max(profile.sup_signed(ta, tb).to_f64());
    }
    (abs, signed)
}

fn check<T: Float, R: Real>(cases: usize, seed: u64) -> usize {
    let mut rng = Rng::new(seed);
    let mut checked = 0;
    for case in 0..cases {
        let spin = [0.0, 0.5, 4.0, 40.0][case % 4];
        let w = rng.direction().map(|x| x * spin * rng.unit());
        let v = rng.direction().map(|x| x * rng.range(0.0, 3.0));
        let x0 = rng.direction().map(|x| x * rng.range(0.0, 2.0));
        let mut m = RigidMotion::try_from_arrays(
            x0.map(T::from_f64),
            v.map(T::from_f64),
            w.map(T::from_f64),
        )
        .expect("motion");
        if case % 3 == 1 {
            let q = [
                rng.unit(),
                rng.range(-1.0, 1.0),
                rng.range(-1.0, 1.0),
                rng.range(-1.0, 1.0),
            ];
            if let Ok(rot) = Rotation::try_from_quaternion(
                T::from_f64(q[0]),
                T::from_f64(q[1]),
                T::from_f64(q[2]),
                T::from_f64(q[3]),
            ) {
                m = m.with_orientation(rot);
            }
        }
        if case % 5 == 2 {
            let c = rng.direction().map(|x| T::from_f64(x * 0.3));
            m = m
                .try_with_local_centre(Vec3::from_array(c))
                .expect("centre");
        }
        // A sub-interval, as conservative advancement takes.
        let (a, b) = (rng.unit() * 0.5, 0.5 + rng.unit() * 0.5);
        let m = m
            .restrict(T::from_f64(a), T::from_f64(b))
            .expect("sub-interval");
        let n = Direction::try_from_array(rng.direction().map(T::from_f64)).expect("direction");
        let prepared = PreparedMotion::new(&m);
        let probe = prepared.probe(n);
        // A polytope too: random points, its vertices sampled.
        let poly: Vec<[T; 3]> = (0..12)
            .map(|_| {
                rng.direction()
                    .map(|x| T::from_f64(x * rng.range(0.1, 1.0)))
            })
            .collect();
        let set = VertexSet::try_new(&poly).expect("set");
        // Every kind also placed at a random pose (a compound's part): its
        // samples mapped by the pose (in f64; the 2^-20 pull covers the
        // stored matrix's 80 u).
        let q = [
            rng.unit(),
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
        ];
        let rot = Rotation::try_from_quaternion(
            T::from_f64(q[0]),
            T::from_f64(q[1]),
            T::from_f64(q[2]),
            T::from_f64(q[3]),
        )
        .expect("rotation");
        let shift = rng
            .direction()
            .map(|x| T::from_f64(x * rng.range(0.0, 0.8)));
        let pose = motion_bound::Isometry::try_new(rot, Vec3::from_array(shift)).expect("pose");
        let matrix = rot.matrix().map(|row| row.map(|x| x.to_f64()));
        let mut all = Vec::new();
        for (name, shape, samples) in shapes::<T>(&mut rng) {
            // Pulled towards the part's own origin (inside: every core is
            // star-shaped about it) before the pose, then not again.
            let placed: Vec<[f64; 3]> = samples
                .iter()
                .map(|p| {
                    let p = p.map(|x| x * PULL);
                    [0, 1, 2].map(|i| {
                        (0..3).map(|j| matrix[i][j] * p[j]).sum::<f64>() + shift[i].to_f64()
                    })
                })
                .collect();
            let samples: Vec<[f64; 3]> = samples.iter().map(|p| p.map(|x| x * PULL)).collect();
            all.push((name, shape, samples));
            all.push(("placed", shape.try_placed(pose).expect("placed"), placed));
        }
        for (name, shape, samples) in all {
            let pts: Vec<[T; 3]> = samples.iter().map(|p| p.map(T::from_f64)).collect();
            verify::<T, R>(name, &shape, &probe, &m, n, &pts);
            checked += 1;
        }
        for rounded in [false, true] {
            let shape = if rounded {
                Convex::polytope(set)
                    .try_rounded(T::from_f64(0.2))
                    .expect("rounded")
            } else {
                Convex::polytope(set)
            };
            let mut pts: Vec<[T; 3]> = poly
                .iter()
                .map(|p| p.map(|x| T::from_f64(x.to_f64() * (1.0 - 1.0 / 1048576.0))))
                .collect();
            if rounded {
                let mut out = Vec::new();
                for p in &pts {
                    for _ in 0..16 {
                        let u = rng.direction();
                        out.push([0, 1, 2].map(|k| {
                            T::from_f64((p[k].to_f64() + 0.2 * u[k]) * (1.0 - 1.0 / 1048576.0))
                        }));
                    }
                }
                pts = out;
            }
            verify::<T, R>(
                if rounded {
                    "rounded polytope"
                } else {
                    "polytope"
                },
                &shape,
                &probe,
                &m,
                n,
                &pts,
            );
            checked += 1;
        }
    }
    checked
}

fn verify<T: Float, R: Real>(
    name: &str,
    shape: &Convex<'_, T>,
    probe: &motion_bound::DirectedProbe<T>,
    m: &RigidMotion<T>,
    n: Direction<T>,
    pts: &[[T; 3]],
) {
    let (abs, signed) = exact::<T, R>(m, n, pts);
    for kind in [BoundKind::Evq, BoundKind::Nevq] {
        let speed = probe.convex_speed(shape, kind).to_f64();
        let rate = probe.convex_rate(shape, kind).to_f64();
        assert!(
            speed >= abs && !speed.is_nan(),
            "{name} {kind:?}: speed bound {speed} below the exact {abs} ({m:?}, {n:?})"
        );
        assert!(
            rate >= signed && !rate.is_nan(),
            "{name} {kind:?}: rate {rate} below the exact signed {signed} ({m:?}, {n:?})"
        );
    }
    let (evq, nevq) = (
        probe.convex_speed(shape, BoundKind::Evq),
        probe.convex_speed(shape, BoundKind::Nevq),
    );
    assert!(evq <= nevq, "{name}: EVQ {evq:?} above NEVQ {nevq:?}");
}

#[test]
fn every_shape_bound_dominates_its_sampled_points_f64() {
    let n = check::<f64, DoubleDouble>(300, 12);
    println!("f64: {n} shape bounds checked");
}

#[test]
fn every_shape_bound_dominates_its_sampled_points_f32() {
    let n = check::<f32, f64>(300, 13);
    println!("f32: {n} shape bounds checked");
}
