//! The certified cast against sampled ground truth on random pairs of parry
//! shapes and motions: every pair of twelve shape kinds (the primitives, the
//! round shapes, a convex hull, a capsule on an off-axis segment, a mesh, two
//! compounds and a half-space), random start poses, local centres, linear
//! and angular velocities, through parry's own `NonlinearRigidMotion` and
//! parry's static `intersection_test` at 257 times (independent of the code
//! under test: parry's kinematics, parry's exact or GJK intersection, and no
//! conversion of ours).
//!
//! MISSED: the sampling finds the shapes intersecting and the cast reports
//! no hit. LATE: the cast's time is after the first sampled intersection.
//! `PARRY_GT_QUERIES=N` sets the queries per pair kind (default 8).

use motion_bound_parry::{cast_shapes_nonlinear, CastError, ShapeCache};
use parry3d_f64::math::{Pose, Real, Rotation, Vector};
use parry3d_f64::query::{self, NonlinearRigidMotion, ShapeCastStatus};
use parry3d_f64::shape::{Ball, Compound, ConvexPolyhedron, Shape, SharedShape, TypedShape};

/// Sampled times over the interval, ends included: `SAMPLES + 1`.
const SAMPLES: usize = 256;

/// SplitMix64: a small, seeded, reproducible generator.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn unit(&mut self) -> Vector {
        loop {
            let v = Vector::new(
                self.uniform(-1.0, 1.0),
                self.uniform(-1.0, 1.0),
                self.uniform(-1.0, 1.0),
            );
            let l = v.length();
            if l > 0.1 && l <= 1.0 {
                return v / l;
            }
        }
    }
    fn rotation(&mut self) -> Rotation {
        Rotation::from_scaled_axis(self.unit() * self.uniform(0.0, std::f64::consts::PI))
    }
}

/// The shapes, named; the half-space last.
fn shapes() -> Vec<(&'static str, SharedShape)> {
    let mut rng = Rng(7);
    let hull_points: Vec<Vector> = (0..24).map(|_| rng.unit() * 0.3).collect();
    let (sphere_v, sphere_i) = Ball::new(0.3).to_trimesh(10, 10);
    let at = |x: f64, y: f64, z: f64| Pose::from_translation(Vector::new(x, y, z));
    let dumbbell = Compound::new(vec![
        (at(-0.3, 0.0, 0.0), SharedShape::ball(0.12)),
        (at(0.3, 0.0, 0.0), SharedShape::ball(0.12)),
        (
            Pose::from_parts(
                Vector::ZERO,
                Rotation::from_rotation_z(std::f64::consts::FRAC_PI_2),
            ),
            SharedShape::capsule_y(0.3, 0.04),
        ),
    ]);
    // Parry allows no mesh inside a compound: a hull and a box.
    let hull_and_box = Compound::new(vec![
        (
            at(0.0, 0.15, 0.0),
            SharedShape::convex_hull(&sphere_v).expect("a hull"),
        ),
        (
            Pose::from_parts(Vector::new(0.0, -0.2, 0.0), Rotation::from_rotation_y(0.4)),
            SharedShape::cuboid(0.25, 0.05, 0.2),
        ),
    ]);
    vec![
        ("ball", SharedShape::ball(0.3)),
        ("cuboid", SharedShape::cuboid(0.3, 0.2, 0.25)),
        ("capsule", SharedShape::capsule_y(0.3, 0.15)),
        (
            "capsule off-axis",
            SharedShape::capsule(
                Vector::new(-0.2, 0.1, 0.0),
                Vector::new(0.25, -0.1, 0.1),
                0.1,
            ),
        ),
        ("cylinder", SharedShape::cylinder(0.3, 0.2)),
        ("cone", SharedShape::cone(0.3, 0.25)),
        (
            "round cuboid",
            SharedShape::round_cuboid(0.25, 0.15, 0.2, 0.05),
        ),
        (
            "round cylinder",
            SharedShape::round_cylinder(0.25, 0.15, 0.05),
        ),
        (
            "convex hull",
            SharedShape::new(ConvexPolyhedron::from_convex_hull(&hull_points).expect("a hull")),
        ),
        (
            "mesh",
            SharedShape::trimesh(sphere_v, sphere_i).expect("a mesh"),
        ),
        ("dumbbell", SharedShape::new(dumbbell)),
        ("hull and box", SharedShape::new(hull_and_box)),
        ("ground", SharedShape::halfspace(Vector::Y)),
    ]
}

/// Whether the shapes at these poses intersect: parry's static test, with
/// a half-space against a mesh or a compound taken part by part (parry's
/// dispatcher does not pair them), a mesh by its vertices (a mesh meets a
/// half-space where one of its vertices does).
fn intersects(p1: &Pose, g1: &dyn Shape, p2: &Pose, g2: &dyn Shape) -> bool {
    if let Ok(b) = query::intersection_test(p1, g1, p2, g2) {
        return b.intersecting;
    }
    let half_space = |p: &Pose, g: &dyn Shape| match g.as_typed_shape() {
        TypedShape::HalfSpace(h) => Some((p.rotation * h.normal, p.translation)),
        _ => None,
    };
    let (n, o, p, g) = match (half_space(p1, g1), half_space(p2, g2)) {
        (Some((n, o)), None) => (n, o, p2, g2),
        (None, Some((n, o))) => (n, o, p1, g1),
        _ => panic!("parry cannot test this pair"),
    };
    match g.as_typed_shape() {
        TypedShape::TriMesh(m) => m.vertices().iter().any(|v| (*p * *v - o).dot(n) <= 0.0),
        TypedShape::Compound(c) => c.shapes().iter().any(|(q, s)| {
            let h = SharedShape::halfspace(n);
            intersects(
                &Pose::from_translation(o),
                h.as_ref(),
                &(*p * *q),
                s.as_ref(),
            )
        }),
        _ => panic!("parry cannot test this pair"),
    }
}

/// The first sampled time the shapes intersect, if any.
fn first_sampled(
    m1: &NonlinearRigidMotion,
    g1: &dyn Shape,
    m2: &NonlinearRigidMotion,
    g2: &dyn Shape,
    t0: f64,
    t1: f64,
) -> Option<f64> {
    (0..=SAMPLES)
        .map(|k| t0 + (t1 - t0) * k as f64 / SAMPLES as f64)
        .find(|&t| intersects(&m1.position_at_time(t), g1, &m2.position_at_time(t), g2))
}

/// A random fly-by: `a` near the origin, `b` launched at it (or, for the
/// ground, `a` dropped onto it).
fn fly_by(rng: &mut Rng, ground: bool) -> (NonlinearRigidMotion, NonlinearRigidMotion) {
    let spin = |rng: &mut Rng| rng.unit() * rng.uniform(0.0, 12.0);
    let local_center = |rng: &mut Rng| rng.unit() * rng.uniform(0.0, 0.1);
    let start_a = Pose::from_parts(rng.unit() * rng.uniform(0.0, 0.2), rng.rotation());
    let a = NonlinearRigidMotion::new(
        start_a,
        local_center(rng),
        rng.unit() * rng.uniform(0.0, 0.5),
        spin(rng),
    );
    if ground {
        let start = Pose::from_parts(
            Vector::new(
                rng.uniform(-0.5, 0.5),
                rng.uniform(0.5, 1.5),
                rng.uniform(-0.5, 0.5),
            ),
            rng.rotation(),
        );
        let fall = Vector::new(
            rng.uniform(-0.5, 0.5),
            -rng.uniform(0.5, 2.0),
            rng.uniform(-0.5, 0.5),
        );
        let body = NonlinearRigidMotion::new(start, local_center(rng), fall, spin(rng));
        let tilt = Pose::from_parts(
            Vector::new(0.0, rng.uniform(-0.2, 0.0), 0.0),
            Rotation::from_scaled_axis(rng.unit() * rng.uniform(0.0, 0.2)),
        );
        let ground = NonlinearRigidMotion::new(
            tilt,
            Vector::ZERO,
            Vector::new(0.0, rng.uniform(0.0, 0.3), 0.0),
            Vector::ZERO,
        );
        return (body, ground);
    }
    let from = rng.unit() * rng.uniform(1.2, 2.2);
    let aim = rng.unit() * rng.uniform(0.0, 0.5);
    let speed = rng.uniform(1.0, 3.5);
    let b = NonlinearRigidMotion::new(
        Pose::from_parts(from, rng.rotation()),
        local_center(rng),
        (aim - from).normalize() * speed,
        spin(rng),
    );
    (a, b)
}

#[derive(Default, Debug)]
struct Tally {
    queries: usize,
    sampled: usize,
    hits: usize,
    missed: usize,
    late: usize,
    undecided: usize,
}

#[test]
fn every_pair_of_parry_shapes_is_never_missed_and_never_late() {
    let per_kind: usize = std::env::var("PARRY_GT_QUERIES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(8);
    let shapes = shapes();
    let cache = ShapeCache::new();
    for (_, s) in &shapes {
        cache.try_register(s).expect("every shape converts");
    }
    let mut rng = Rng(2026);
    let mut total = Tally::default();
    let mut kinds = 0;
    for i in 0..shapes.len() {
        for j in i..shapes.len() {
            let ((na, ga), (nb, gb)) = (&shapes[i], &shapes[j]);
            let ground = nb == &"ground";
            if ground && na == &"ground" {
                continue;
            }
            kinds += 1;
            let mut tally = Tally::default();
            for q in 0..per_kind {
                let (m1, m2) = fly_by(&mut rng, ground);
                let (t0, t1) = if q % 3 == 2 { (0.25, 1.25) } else { (0.0, 1.0) };
                let truth = first_sampled(&m1, ga.as_ref(), &m2, gb.as_ref(), t0, t1);
                let hit = cache
                    .cast_shapes_nonlinear(
                        &m1,
                        ga.as_ref(),
                        &m2,
                        gb.as_ref(),
                        t0,
                        t1,
                        true,
                        &Default::default(),
                    )
                    .unwrap_or_else(|e| panic!("{na} against {nb}: {e}"));
                tally.queries += 1;
                tally.sampled += usize::from(truth.is_some());
                if let Some(h) = hit {
                    tally.hits += 1;
                    tally.undecided += usize::from(h.status == ShapeCastStatus::OutOfIterations);
                    assert!(
                        (t0..=t1).contains(&h.time_of_impact),
                        "{na}-{nb} query {q}: time {} outside [{t0}, {t1}]",
                        h.time_of_impact
                    );
                    if h.status == ShapeCastStatus::Converged {
                        // The witnesses, placed by parry's motion, are within
                        // the contact distance (1e-4) of each other.
                        let w1 = m1.position_at_time(h.time_of_impact) * h.witness1;
                        let w2 = m2.position_at_time(h.time_of_impact) * h.witness2;
                        let d = query::distance(
                            &m1.position_at_time(h.time_of_impact),
                            ga.as_ref(),
                            &m2.position_at_time(h.time_of_impact),
                            gb.as_ref(),
                        )
                        .map(|d| d.distance);
                        assert!(
                            (w1 - w2).length() <= 1e-4 + 1e-9,
                            "{na}-{nb} query {q}: witnesses {} apart, parry's distance {d:?}, {h:?}, truth {truth:?}",
                            (w1 - w2).length()
                        );
                    }
                }
                match (truth, hit) {
                    (Some(_), None) => tally.missed += 1,
                    (Some(t), Some(h)) if h.time_of_impact > t + 1e-12 => tally.late += 1,
                    _ => {}
                }
            }
            println!(
                "{na} - {nb}: {} queries, {} sampled contacts, {} hits ({} undecided), missed {}, late {}",
                tally.queries, tally.sampled, tally.hits, tally.undecided, tally.missed, tally.late
            );
            total.queries += tally.queries;
            total.sampled += tally.sampled;
            total.hits += tally.hits;
            total.undecided += tally.undecided;
            total.missed += tally.missed;
            total.late += tally.late;
        }
    }
    println!(
        "{kinds} pair kinds: {} queries, {} sampled contacts, {} hits ({} undecided), missed {}, late {}",
        total.queries, total.sampled, total.hits, total.undecided, total.missed, total.late
    );
    assert_eq!((total.missed, total.late), (0, 0), "{total:?}");
    // The test means something: most fly-bys touch, some do not.
    assert!(total.sampled * 4 > total.queries, "{total:?}");
    assert!(total.sampled < total.queries, "{total:?}");
}

#[test]
fn a_shape_cloned_into_many_colliders_builds_one_tree() {
    let (v, i) = Ball::new(0.3).to_trimesh(10, 10);
    let mesh = SharedShape::trimesh(v, i).expect("a mesh");
    let clones: Vec<SharedShape> = (0..1000).map(|_| mesh.clone()).collect();
    let ball = SharedShape::ball(0.1);
    let cache = ShapeCache::new();
    let far = NonlinearRigidMotion::constant_position(Pose::from_translation(Vector::X * 5.0));
    let still = NonlinearRigidMotion::identity();
    for (k, c) in clones.iter().enumerate() {
        if k % 2 == 0 {
            cache.register(c);
        }
        let hit = cache
            .cast_shapes_nonlinear(
                &still,
                c.as_ref(),
                &far,
                ball.as_ref(),
                0.0,
                1.0,
                true,
                &Default::default(),
            )
            .expect("a certified answer");
        assert!(hit.is_none(), "a still ball 4.6 away never touches");
    }
    let stats = cache.stats();
    assert_eq!(stats.built, 1, "{stats:?}");
    assert_eq!(stats.len, 1, "{stats:?}");
    // A new mesh at a freed address is never taken for the old one.
    drop(clones);
    drop(mesh);
    cache.prune();
    assert_eq!(cache.stats().len, 0);
}

#[test]
fn a_changed_mesh_behind_the_same_reference_is_rebuilt() {
    // The same `TriMesh` value, changed in place between two queries: the
    // cache compares its copy and rebuilds (never answers for the old one).
    let (v, i) = Ball::new(0.3).to_trimesh(8, 8);
    let mut mesh = parry3d_f64::shape::TriMesh::new(v, i).expect("a mesh");
    let ball = Ball::new(0.1);
    let cache = ShapeCache::new();
    let still = NonlinearRigidMotion::identity();
    let near = NonlinearRigidMotion::constant_position(Pose::from_translation(Vector::X * 0.6));
    let cast = |m: &parry3d_f64::shape::TriMesh| {
        cache
            .cast_shapes_nonlinear(&still, m, &near, &ball, 0.0, 1.0, true, &Default::default())
            .expect("a certified answer")
    };
    assert!(cast(&mesh).is_none(), "0.6 apart, radii 0.3 and 0.1");
    mesh = mesh.scaled(Vector::splat(2.0)); // now the mesh reaches 0.6: touching
    assert!(cast(&mesh).is_some(), "the grown mesh touches the ball");
    assert_eq!(cache.stats().built, 2);
}

#[test]
fn unsupported_and_bad_input_are_typed_errors() {
    let still = NonlinearRigidMotion::identity();
    let ball = Ball::new(0.5);
    let nan = NonlinearRigidMotion::new(
        Pose::IDENTITY,
        Vector::ZERO,
        Vector::new(Real::NAN, 0.0, 0.0),
        Vector::ZERO,
    );
    assert!(matches!(
        cast_shapes_nonlinear(&nan, &ball, &still, &ball, 0.0, 1.0, true),
        Err(CastError::Input(_))
    ));
    assert!(matches!(
        cast_shapes_nonlinear(&still, &ball, &still, &ball, Real::NAN, 1.0, true),
        Err(CastError::Interval)
    ));
    let ground = parry3d_f64::shape::HalfSpace::new(Vector::Y);
    assert!(matches!(
        cast_shapes_nonlinear(&still, &ground, &still, &ground, 0.0, 1.0, true),
        Err(CastError::Unsupported(_))
    ));
    let turning = NonlinearRigidMotion::new(Pose::IDENTITY, Vector::ZERO, Vector::ZERO, Vector::Z);
    assert!(matches!(
        cast_shapes_nonlinear(&turning, &ground, &still, &ball, 0.0, 1.0, true),
        Err(CastError::Unsupported(_))
    ));
    assert!(matches!(
        cast_shapes_nonlinear(&still, &Ball::new(-1.0), &still, &ball, 0.0, 1.0, true),
        Err(CastError::Input(_))
    ));
    let line = parry3d_f64::shape::Polyline::new(vec![Vector::ZERO, Vector::X], None);
    assert!(matches!(
        cast_shapes_nonlinear(&still, &line, &still, &ball, 0.0, 1.0, true),
        Err(CastError::Unsupported("Polyline"))
    ));
    // A reversed interval is the start alone: touching there is a hit.
    let hit = cast_shapes_nonlinear(&still, &ball, &still, &ball, 1.0, 0.5, true)
        .expect("an answer")
        .expect("touching");
    assert_eq!(hit.status, ShapeCastStatus::PenetratingOrWithinTargetDist);
    assert_eq!(hit.time_of_impact, 1.0);
}
