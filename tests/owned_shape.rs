//! `ca::OwnedShape`, the owning twin of `ca::Shape` that the C library and
//! the Python module build on: every bad argument refused with its name (the
//! words both bindings print), and every kind lent to a query answering as
//! the closed form of its geometry says.

use motion_bound::ca::{
    time_of_impact, AnyPair, ArgError, CaParams, OwnedShape, Primitive, Problem, Shape,
};
use motion_bound::{Isometry, RigidMotion, Vec3};

/// The closed cube `[-h, h]^3`, outward wound.
fn cube(h: f64) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let v = [
        [-1., -1., -1.],
        [1., -1., -1.],
        [1., 1., -1.],
        [-1., 1., -1.],
        [-1., -1., 1.],
        [1., -1., 1.],
        [1., 1., 1.],
        [-1., 1., 1.],
    ]
    .map(|p| p.map(|x| x * h));
    let t = vec![
        [0, 2, 1],
        [0, 3, 2],
        [4, 5, 6],
        [4, 6, 7],
        [0, 1, 5],
        [0, 5, 4],
        [2, 3, 7],
        [2, 7, 6],
        [1, 2, 6],
        [1, 6, 5],
        [0, 4, 7],
        [0, 7, 3],
    ];
    (v.to_vec(), t)
}

const NAMES: [&str; 3] = ["vertices", "faces", "solid"];

fn at(x: f64, y: f64, z: f64) -> Isometry<f64> {
    Isometry::try_from_translation(Vec3::new(x, y, z)).expect("a translation")
}

#[test]
fn every_bad_argument_is_named() {
    let msg = |r: Result<OwnedShape<f64>, ArgError>| r.expect_err("refused").to_string();
    let p = |p, r| msg(OwnedShape::try_primitive(p, r));
    let cases = [
        (
            p(Primitive::Cuboid([1.0, -2.0, 1.0]), 0.0),
            "half_extents[1] is negative (got -2)",
        ),
        (
            p(Primitive::Cuboid([1.0, 1.0, f64::NAN]), 0.0),
            "half_extents[2] is not finite (got NaN)",
        ),
        (
            p(Primitive::Ball(-0.5), 0.0),
            "radius is negative (got -0.5)",
        ),
        (
            p(Primitive::Capsule(f64::INFINITY, 1.0), 0.0),
            "half_height is not finite (got inf)",
        ),
        (
            p(Primitive::Cylinder(0.0, 1.0), 0.0),
            "half_height must be positive and finite (got 0)",
        ),
        (
            p(Primitive::Cone(1.0, 1.0), -1.0),
            "rounding is negative (got -1)",
        ),
        (
            p(Primitive::Ball(1e300), 0.0),
            "radius: radius exceeds the largest supported magnitude",
        ),
        (
            msg(OwnedShape::try_hull(vec![], 0.0)),
            "points: vertex set is empty",
        ),
        (
            msg(OwnedShape::try_hull(vec![[0.0, f64::NAN, 0.0]], 0.0)),
            "points: vertex 0 is not finite",
        ),
        (
            msg(OwnedShape::try_half_space([0.0; 3])),
            "normal: direction has zero length",
        ),
        (
            msg(OwnedShape::try_compound([])),
            "parts: a compound with no part",
        ),
    ];
    for (got, want) in cases {
        assert_eq!(got, want);
    }
    // A mesh's refusals name the binding's own argument names.
    let (v, t) = cube(1.0);
    let bad_index = vec![[0, 1, 9]];
    let e = OwnedShape::try_mesh(v.clone(), bad_index, None, NAMES).expect_err("refused");
    assert!(matches!(e.problem(), Problem::Mesh(_)), "{e}");
    assert!(e.to_string().starts_with("faces: triangle 0"), "{e}");
    let open = t[..11].to_vec();
    let e = OwnedShape::try_mesh(v, open, Some(true), ["v", "t", "solidity"]).expect_err("open");
    assert!(e.to_string().starts_with("solidity: "), "{e}");
    // A part that cannot be one, by its index; rounding what is not convex.
    let ball = OwnedShape::try_primitive(Primitive::Ball(1.0), 0.0).expect("a ball");
    let ground = OwnedShape::try_half_space([0.0, 0.0, 1.0]).expect("a plane");
    let e = OwnedShape::try_compound([(&ball, at(0., 0., 0.)), (&ground, at(0., 0., 0.))]);
    assert!(msg(e).starts_with("parts[1] is a half_space"));
    assert!(msg(ground.try_rounded(0.1)).starts_with("shape is not convex"));
    assert_eq!(msg(ball.try_rounded(-0.1)), "radius is negative (got -0.1)");
}

/// The first contact of `a` falling at `speed` from height `z` onto the
/// ground `z = 0`, as a query of the owned shapes reports it.
fn fall_onto_ground(a: &OwnedShape<f64>, z: f64, speed: f64) -> f64 {
    let ground = OwnedShape::try_half_space([0.0, 0.0, 1.0]).expect("a plane");
    let (pa, pg) = (a.prepare().expect("lent"), ground.prepare().expect("lent"));
    let mut pair = AnyPair::try_new(pa.shape(), pg.shape()).expect("a pair");
    let ma = RigidMotion::try_from_arrays([0.0, 0.0, z], [0.0, 0.0, -speed], [0.0; 3]).unwrap();
    let mg = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0; 3]).unwrap();
    let report = time_of_impact(&mut pair, &ma, &mg, &CaParams::default()).expect("a query");
    report.outcome.contact().expect("a contact").time
}

/// Every kind against the ground, its lowest point's height over the speed
/// (the closed form), to within the contact distance over the speed.
#[test]
fn every_kind_meets_the_ground_when_its_lowest_point_does() {
    let d = CaParams::<f64>::default().contact_distance;
    let (v, t) = cube(0.5);
    let mesh = OwnedShape::try_mesh(v.clone(), t, None, NAMES).expect("a cube");
    assert!(matches!(mesh.prepare().unwrap().shape(), Shape::Mesh(_)));
    let hull = OwnedShape::try_hull(v, 0.0).expect("a hull");
    let rounded_hull = hull.try_rounded(0.25).expect("rounded");
    let ball = OwnedShape::try_primitive(Primitive::Ball(0.3), 0.0).expect("a ball");
    let box_ = OwnedShape::try_primitive(Primitive::Cuboid([0.5, 0.5, 0.2]), 0.1).expect("box");
    // A dumbbell of two balls at x = -1, 1 and the cube 1 below its origin.
    let dumbbell = OwnedShape::try_compound([
        (&ball, at(-1.0, 0.0, 0.0)),
        (&ball, at(1.0, 0.0, 0.0)),
        (&mesh, at(0.0, 0.0, -1.0)),
        (&hull, at(0.0, 3.0, 0.5)),
    ])
    .expect("a compound");
    // (shape, its lowest point below its origin)
    let cases = [
        (&mesh, 0.5),
        (&hull, 0.5),
        (&rounded_hull, 0.75),
        (&ball, 0.3),
        (&box_, 0.3),
        (&dumbbell, 1.5),
    ];
    for (k, (shape, below)) in cases.into_iter().enumerate() {
        let (z, speed) = (2.0, 2.5); // over the motions' interval [0, 1]
        let t = fall_onto_ground(shape, z, speed);
        let touch = (z - below) / speed;
        assert!(
            t <= touch + 1e-12 && t >= touch - d / speed - 1e-12,
            "case {k}: contact at {t}, the lowest point touches at {touch}"
        );
    }
}
