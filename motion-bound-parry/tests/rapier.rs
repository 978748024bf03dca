//! Rapier with [`Swept`] colliders and the [`CertifiedDispatcher`]: contacts
//! and mass properties as unwrapped, the mesh cache shared with the inner
//! shape, and the fast mesh world judged by the example's checker.

use std::sync::Arc;

use motion_bound_parry::{CertifiedDispatcher, ShapeCache, Swept};
use parry3d_f64::math::Vector;
use parry3d_f64::shape::SharedShape;
use rapier3d_f64::prelude::{ColliderBuilder, NarrowPhase, PhysicsWorld, RigidBodyBuilder};

// The example's worlds and checker (its `main` unused here).
#[allow(dead_code)]
#[path = "../examples/rapier_worlds.rs"]
mod worlds;

use worlds::{run_world, sphere_mesh, Mode, World};

/// A ball and a cuboid dropped on a fixed ground, wrapped or not: their
/// resting heights, speeds, masses and principal inertias.
fn drop_on_ground(wrap: bool) -> Vec<(f64, f64, f64, Vector)> {
    let mut w = PhysicsWorld::default();
    w.integration_parameters.dt = worlds::DT;
    let dispatcher = CertifiedDispatcher::new();
    w.narrow_phase = NarrowPhase::with_query_dispatcher(dispatcher.clone());
    w.insert(
        RigidBodyBuilder::fixed().translation(Vector::new(0.0, -0.5, 0.0)),
        ColliderBuilder::cuboid(10.0, 0.5, 10.0),
    );
    let shapes = [
        (SharedShape::ball(0.3), Vector::new(0.0, 2.0, 0.0)),
        (
            SharedShape::cuboid(0.25, 0.25, 0.25),
            Vector::new(2.0, 1.5, 0.0),
        ),
    ];
    let mut handles = Vec::new();
    for (shape, at) in shapes {
        let shape = if wrap { Swept::shared(shape) } else { shape };
        let (h, _) = w.insert(
            RigidBodyBuilder::dynamic()
                .translation(at)
                .linvel(Vector::new(1.0, -3.0, 0.0))
                .ccd_enabled(true),
            ColliderBuilder::new(shape),
        );
        handles.push(h);
    }
    for _ in 0..300 {
        w.step();
    }
    handles
        .iter()
        .map(|h| {
            let rb = &w.bodies[*h];
            (
                rb.translation().y,
                rb.linvel().length(),
                rb.mass(),
                rb.mass_properties().local_mprops.principal_inertia(),
            )
        })
        .collect()
}

#[test]
fn wrapped_bodies_rest_on_the_ground_as_unwrapped() {
    let plain = drop_on_ground(false);
    let wrapped = drop_on_ground(true);
    for ((y, v, m, i), ((py, _, pm, pi), rest)) in wrapped.iter().zip(plain.iter().zip([0.3, 0.25]))
    {
        assert!(
            (y - rest).abs() < 0.01,
            "a wrapped body rests at {y}, not on the ground ({rest}): contacts lost"
        );
        assert!(
            *v < 0.05,
            "a wrapped body still moves at {v} after 300 steps"
        );
        assert!((y - py).abs() < 0.01, "wrapped at {y}, unwrapped at {py}");
        assert_eq!(
            m, pm,
            "the wrapped body's mass differs from the unwrapped one's"
        );
        assert_eq!(
            i, pi,
            "the wrapped body's inertia differs from the unwrapped one's"
        );
    }
}

#[test]
fn a_swept_mesh_shares_the_inner_shapes_cache_entry() {
    let mesh = sphere_mesh(0.3);
    let swept = Swept::shared(mesh.clone());
    assert!(
        Arc::ptr_eq(&Swept::shared(swept.clone()).0, &swept.0),
        "wrapped twice"
    );
    assert!(
        std::ptr::addr_eq(Swept::see_through(swept.as_ref()), mesh.as_ref()),
        "see_through gives the inner shape"
    );
    let cache = ShapeCache::new();
    cache.register(&swept);
    let a = cache.body(mesh.as_ref()).expect("a mesh body");
    let b = cache.body(swept.as_ref()).expect("a mesh body");
    assert!(Arc::ptr_eq(&a, &b), "the same cached body, wrapped or not");
    assert_eq!(cache.stats().built, 1, "one tree built");
    // A mesh's own CCD thickness is zero; the wrapper's is its box's.
    assert_eq!(mesh.ccd_thickness(), 0.0, "parry's mesh thickness");
    let t = swept.ccd_thickness();
    assert!(
        (t - 0.3).abs() < 1e-9,
        "a sphere mesh's thickness is its box's half extent, got {t}"
    );
}

#[test]
fn the_fast_mesh_world_does_not_tunnel_with_ours() {
    // The world is a stress: rapier never sweeps a moving mesh by itself.
    let d = run_world(World::Mesh, Mode::Default, 6, 60, true, false);
    assert!(d.tunnelled > 0, "rapier's default tunnels here: {d:?}");
    let t = run_world(World::Mesh, Mode::Ours, 6, 60, true, false);
    assert_eq!(t.tunnelled, 0, "tunnelled launches with ours: {t:?}");
    assert_eq!(t.late, 0, "late launches with ours: {t:?}");
    assert!(t.stats.certified > 0, "the certified cast answered: {t:?}");
    assert_eq!(t.stats.handed_to_parry, 0, "nothing handed to parry: {t:?}");
}

#[test]
fn two_bullets_do_not_pass_through_each_other_with_the_certified_pass() {
    // Rapier casts nothing between two bullets; the pass casts their
    // actual motions.
    let d = run_world(World::Bullets, Mode::Default, 6, 40, true, false);
    assert!(d.tunnelled > 0, "rapier's default tunnels here: {d:?}");
    let t = run_world(World::Bullets, Mode::Ours, 6, 40, true, false);
    assert_eq!((t.tunnelled, t.late), (0, 0), "with ours: {t:?}");
    assert!(t.pass_clamped > 0, "the pass moved bodies back: {t:?}");
}

#[test]
fn shapes_close_but_apart_at_the_start_are_cast_past_it() {
    use parry3d_f64::math::Pose;
    use parry3d_f64::query::NonlinearRigidMotion;
    // A ball 5e-5 from a wall (within the default contact distance, 1e-4)
    // closing at 1: it touches at 5e-5. Rapier ignores a hit at fraction 0,
    // so the answer must be after the start, and never after the contact.
    let ball = SharedShape::ball(0.5);
    let wall = SharedShape::cuboid(0.5, 4.0, 4.0);
    let gap = 5e-5;
    let m1 = NonlinearRigidMotion::new(Pose::IDENTITY, Vector::ZERO, Vector::X, Vector::ZERO);
    let m2 = NonlinearRigidMotion::constant_position(Pose::from_translation(Vector::new(
        1.0 + gap,
        0.0,
        0.0,
    )));
    let hit = motion_bound_parry::cast_shapes_nonlinear(
        &m1,
        ball.as_ref(),
        &m2,
        wall.as_ref(),
        0.0,
        1.0 / 60.0,
        false,
    )
    .expect("a supported pair")
    .expect("a contact");
    assert!(
        hit.time_of_impact > 0.0 && hit.time_of_impact <= gap,
        "the contact at {gap} answered at {}",
        hit.time_of_impact
    );
    // Touching at the start: the hit at the start.
    let touching =
        NonlinearRigidMotion::constant_position(Pose::from_translation(Vector::new(1.0, 0.0, 0.0)));
    let hit = motion_bound_parry::cast_shapes_nonlinear(
        &m1,
        ball.as_ref(),
        &touching,
        wall.as_ref(),
        0.0,
        1.0 / 60.0,
        false,
    )
    .expect("a supported pair")
    .expect("a contact");
    assert_eq!(hit.time_of_impact, 0.0, "touching at the start");
}
