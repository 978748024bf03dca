//! Shared by the ground-truth tests and the `casts` benchmark: parry shapes
//! of every kind the adapter takes, random fly-bys as parry motions, and the
//! sampled ground truth by parry's own kinematics and static intersection
//! test (independent of the code under test).

#![allow(dead_code, unreachable_pub)]

use parry3d_f64::math::{Pose, Rotation, Vector};
use parry3d_f64::query::{self, NonlinearRigidMotion};
use parry3d_f64::shape::{Ball, Compound, ConvexPolyhedron, Shape, SharedShape, TypedShape};

/// Sampled times over the interval, ends included: `SAMPLES + 1`.
pub const SAMPLES: usize = 256;

/// The seeded generator (the testkit's SplitMix64, through the workspace's devkit).
pub use motion_bound_devkit::Rng;

/// A random unit vector (from the cube, of length more than 0.1 before normalising).
pub fn unit(rng: &mut Rng) -> Vector {
    Vector::from(motion_bound_devkit::direction(rng, 0.1))
}

/// A random rotation: a random axis, an angle in `[0, pi)`.
pub fn rotation(rng: &mut Rng) -> Rotation {
    Rotation::from_scaled_axis(unit(rng) * rng.range(0.0, std::f64::consts::PI))
}

/// The shapes, named; the half-space last.
pub fn shapes() -> Vec<(&'static str, SharedShape)> {
    let mut rng = Rng::new(7);
    let hull_points: Vec<Vector> = (0..24).map(|_| unit(&mut rng) * 0.3).collect();
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
pub fn intersects(p1: &Pose, g1: &dyn Shape, p2: &Pose, g2: &dyn Shape) -> bool {
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
pub fn first_sampled(
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
pub fn fly_by(rng: &mut Rng, ground: bool) -> (NonlinearRigidMotion, NonlinearRigidMotion) {
    let spin = |rng: &mut Rng| unit(rng) * rng.range(0.0, 12.0);
    let local_center = |rng: &mut Rng| unit(rng) * rng.range(0.0, 0.1);
    let start_a = Pose::from_parts(unit(rng) * rng.range(0.0, 0.2), rotation(rng));
    let a = NonlinearRigidMotion::new(
        start_a,
        local_center(rng),
        unit(rng) * rng.range(0.0, 0.5),
        spin(rng),
    );
    if ground {
        let start = Pose::from_parts(
            Vector::new(
                rng.range(-0.5, 0.5),
                rng.range(0.5, 1.5),
                rng.range(-0.5, 0.5),
            ),
            rotation(rng),
        );
        let fall = Vector::new(
            rng.range(-0.5, 0.5),
            -rng.range(0.5, 2.0),
            rng.range(-0.5, 0.5),
        );
        let body = NonlinearRigidMotion::new(start, local_center(rng), fall, spin(rng));
        let tilt = Pose::from_parts(
            Vector::new(0.0, rng.range(-0.2, 0.0), 0.0),
            Rotation::from_scaled_axis(unit(rng) * rng.range(0.0, 0.2)),
        );
        let ground = NonlinearRigidMotion::new(
            tilt,
            Vector::ZERO,
            Vector::new(0.0, rng.range(0.0, 0.3), 0.0),
            Vector::ZERO,
        );
        return (body, ground);
    }
    let from = unit(rng) * rng.range(1.2, 2.2);
    let aim = unit(rng) * rng.range(0.0, 0.5);
    let speed = rng.range(1.0, 3.5);
    let b = NonlinearRigidMotion::new(
        Pose::from_parts(from, rotation(rng)),
        local_center(rng),
        (aim - from).normalize() * speed,
        spin(rng),
    );
    (a, b)
}
