//! Through the adapter: parry's ball, cylinder, capsule and cone (and their
//! round forms) spinning about their own centre or axis while sliding or
//! rolling 1.01 to 10 contact distances above a cuboid floor, in `f32` and
//! `f64`, are converted to `Separated` within three iterations
//! (`proofs/12-shapes.md`, Lemma 12.5), and `cast_shapes_nonlinear` reports
//! no hit; the same motions turned towards the floor still hit.

macro_rules! suite {
    ($name:ident, $parry:ident, $ours:path) => {
        #[test]
        fn $name() {
            use motion_bound::ca::{time_of_impact, AnyPair, CaOutcome, CaParams};
            use $ours as ours;
            use $parry::math::{Pose, Real, Rotation, Vector};
            use $parry::query::NonlinearRigidMotion;
            use $parry::shape::{Ball, Capsule, Cone, Cuboid, Cylinder, RoundShape, Shape};

            const CONTACT: Real = 1e-4;
            const DT: Real = 1.0 / 60.0;
            let r: Real = 0.05;
            let rounding: Real = 0.01;
            let round = |inner| rounding + inner;
            // Each: a name, a shape, its lowest point below its origin, the start
            // rotation, the linear velocity (before the push towards the floor)
            // and the angular velocity.
            let axle = Rotation::from_axis_angle(Vector::X, core::f64::consts::FRAC_PI_2 as Real);
            let lying = Rotation::from_axis_angle(Vector::Z, -core::f64::consts::FRAC_PI_2 as Real);
            let cases: Vec<(&str, Box<dyn Shape>, Real, Rotation, Vector, Vector)> = vec![
                (
                    "ball sliding and spinning",
                    Box::new(Ball::new(r)),
                    r,
                    Rotation::IDENTITY,
                    Vector::new(3.0, 0.0, 1.0),
                    Vector::new(14.0, 9.0, -17.0),
                ),
                (
                    "ball rolling",
                    Box::new(Ball::new(r)),
                    r,
                    Rotation::IDENTITY,
                    Vector::new(2.0, 0.0, 0.0),
                    Vector::new(0.0, 0.0, -2.0 / r),
                ),
                (
                    "wheel rolling",
                    Box::new(Cylinder::new(0.02, r)),
                    r,
                    axle,
                    Vector::new(3.0, 0.0, 0.0),
                    Vector::new(0.0, 0.0, -3.0 / r),
                ),
                (
                    "round wheel rolling",
                    Box::new(RoundShape {
                        inner_shape: Cylinder::new(0.02, r),
                        border_radius: rounding,
                    }) as Box<dyn Shape>,
                    round(r),
                    axle,
                    Vector::new(3.0, 0.0, 0.0),
                    Vector::new(0.0, 0.0, -3.0 / round(r)),
                ),
                (
                    "capsule spinning",
                    Box::new(Capsule::new_y(0.2, r)),
                    r,
                    lying,
                    Vector::new(0.0, 0.0, 1.5),
                    Vector::new(40.0, 0.0, 0.0),
                ),
                (
                    "cone spinning",
                    Box::new(Cone::new(0.1, 0.06)),
                    0.1,
                    Rotation::IDENTITY,
                    Vector::new(1.0, 0.0, -1.0),
                    Vector::new(0.0, 30.0, 0.0),
                ),
                (
                    "round cone spinning",
                    Box::new(RoundShape {
                        inner_shape: Cone::new(0.1, 0.06),
                        border_radius: rounding,
                    }) as Box<dyn Shape>,
                    round(0.1),
                    Rotation::IDENTITY,
                    Vector::new(1.0, 0.0, -1.0),
                    Vector::new(0.0, 30.0, 0.0),
                ),
            ];
            let floor = Cuboid::new(Vector::new(2.0, 0.05, 2.0));
            let floor_at = NonlinearRigidMotion::constant_position(Pose::from_parts(
                Vector::new(0.0, -0.05, 0.0),
                Rotation::IDENTITY,
            ));
            let params = CaParams::default().with_contact_distance(CONTACT);
            let cache = ours::ShapeCache::new();
            let mut failed = Vec::new();
            for gap in [1.01 * CONTACT, 2.0 * CONTACT, 10.0 * CONTACT] {
                for (name, shape, low, rotation, lin, ang) in &cases {
                    for toward in [0.0, 1.0] {
                        let motion = NonlinearRigidMotion::new(
                            Pose::from_parts(Vector::new(0.1, gap + low, -0.1), *rotation),
                            Vector::ZERO,
                            *lin - Vector::Y * toward,
                            *ang,
                        );
                        let hit = cache
                            .cast_shapes_nonlinear(
                                &motion,
                                shape.as_ref(),
                                &floor_at,
                                &floor,
                                0.0,
                                DT,
                                true,
                                &params,
                            )
                            .expect("a certified answer");
                        // The conversion, and our query on it, for the iterations.
                        let a = ours::Body::try_new(shape.as_ref()).expect("converted");
                        let b = ours::Body::try_new(&floor).expect("converted");
                        let (ma, mb) = (
                            ours::rigid_motion(&motion, 0.0, DT).expect("motion"),
                            ours::rigid_motion(&floor_at, 0.0, DT).expect("motion"),
                        );
                        let report = a
                            .with_shape(|sa| {
                                b.with_shape(|sb| {
                                    time_of_impact(
                                        &mut AnyPair::try_new(sa, sb).expect("pair"),
                                        &ma,
                                        &mb,
                                        &params,
                                    )
                                    .expect("query")
                                })
                            })
                            .expect("shape")
                            .expect("shape");
                        let ok = if toward == 0.0 {
                            hit.is_none()
                                && matches!(report.outcome, CaOutcome::Separated)
                                && report.iterations <= 3
                        } else {
                            // Down at 1 from `gap`: the hit never after the distance
                            // falls to half the contact distance, and not before it
                            // reaches twice it (the adapter grows the contact distance
                            // by its conversion's rounding: `f32`, a few 1e-6 here).
                            hit.is_some_and(|h| {
                                h.time_of_impact <= gap - CONTACT / 2.0 + 1e-6
                                    && h.time_of_impact >= gap - 2.0 * CONTACT
                            })
                        };
                        if !ok {
                            failed.push(format!(
                                "{name} at {gap} (towards {toward}): hit {:?}, ours {:?} in {}",
                                hit.map(|h| h.time_of_impact),
                                report.outcome,
                                report.iterations
                            ));
                        }
                    }
                }
            }
            assert!(failed.is_empty(), "{}", failed.join("\n"));
        }
    };
}

#[cfg(feature = "f64")]
suite!(
    symmetric_spins_through_the_adapter_f64,
    parry3d_f64,
    motion_bound_parry::f64
);
#[cfg(feature = "f32")]
suite!(
    symmetric_spins_through_the_adapter_f32,
    parry3d,
    motion_bound_parry::f32
);
