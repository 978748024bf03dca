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
use parry3d_f64::math::{Pose, Real, Vector};
use parry3d_f64::query::{self, NonlinearRigidMotion, ShapeCastStatus};
use parry3d_f64::shape::{Ball, SharedShape};

#[path = "common/cases.rs"]
mod cases;

use cases::{first_sampled, fly_by, shapes, Rng};

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
    let mut rng = Rng::new(2026);
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
