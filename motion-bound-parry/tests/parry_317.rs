//! dimforge/parry#317, "cast_shapes_nonlinear fails to detect collision
//! between cuboids": the reported case (a 470 x 210 x 220 box moving and
//! spinning past a fixed 1300 x 660 x 550 box, far from the origin, in
//! `f32`), through parry's cast and ours, judged by parry's static
//! intersection test at 2,001 times of the same motions. Parry's answer is
//! printed (a finding, not asserted: it may change between releases); ours
//! must be a hit no later than the first sampled intersection. Run with
//! `-- --nocapture` to see both.

/// The case in the precision of `$parry` (`parry3d` or `parry3d_f64`),
/// through `$ours` (`motion_bound_parry::f32` or `::f64`).
macro_rules! case {
    ($name:ident, $parry:ident, $ours:path) => {
        #[test]
        fn $name() {
            use $ours as ours;
            use $parry::math::{Pose, Real, Rotation, Vector};
            use $parry::query::{self, NonlinearRigidMotion};
            use $parry::shape::Cuboid;

            let moving = Cuboid::new(Vector::new(235.0, 105.0, 110.0));
            let motion = NonlinearRigidMotion::new(
                Pose::from_parts(
                    Vector::new(6458.7905, -209.1331, 1014.52124),
                    Rotation::from_xyzw(5.3359954e-20, 9.459897e-20, -0.84035015, -0.542044)
                        .normalize(),
                ),
                Vector::new(99.97085, -2.2888184e-5, -35.0),
                Vector::new(588.2583, -553.06335, 471.54688),
                Vector::new(0.0, 0.0, -1.770823),
            );
            let fixed = Cuboid::new(Vector::new(650.0, 330.0, 275.0));
            let still = NonlinearRigidMotion::constant_position(Pose::from_parts(
                Vector::new(6079.4917, -849.3108, 853.8756),
                Rotation::from_xyzw(0.002524775, -0.00026210435, -0.0012064485, 0.99999607)
                    .normalize(),
            ));
            let samples = 2000;
            let first = (0..=samples)
                .map(|k| k as Real / samples as Real)
                .find(|&t| {
                    query::intersection_test(
                        &motion.position_at_time(t),
                        &moving,
                        &still.position_at_time(t),
                        &fixed,
                    )
                    .expect("cuboids")
                    .intersecting
                })
                .expect("the sampling finds the boxes intersecting");
            let parry =
                query::cast_shapes_nonlinear(&motion, &moving, &still, &fixed, 0.0, 1.0, true)
                    .expect("cuboids");
            // The scene's unit is a millimetre: a contact distance of 0.1.
            let params = motion_bound::ca::CaParams::default().with_contact_distance(0.1);
            let hit = ours::ShapeCache::new()
                .cast_shapes_nonlinear(&motion, &moving, &still, &fixed, 0.0, 1.0, true, &params)
                .expect("a certified answer");
            println!(
                "parry#317 ({}): first sampled intersection at {first}; parry: {:?}; ours: {:?}",
                stringify!($parry),
                parry.map(|h| (h.time_of_impact, h.status)),
                hit.map(|h| (h.time_of_impact, h.status)),
            );
            let hit = hit.expect("ours finds the contact");
            assert!(hit.time_of_impact <= first, "ours is late: {hit:?}");
        }
    };
}

#[cfg(feature = "f64")]
case!(parry_317_in_f64, parry3d_f64, motion_bound_parry::f64);
#[cfg(feature = "f32")]
case!(parry_317_in_f32, parry3d, motion_bound_parry::f32);
