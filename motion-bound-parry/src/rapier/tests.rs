use super::touching::extent;
use super::{swept_box, Placed};
use motion_bound::ca::Ceiling;
use motion_bound_devkit::Rng;
use parry3d_f64::bounding_volume::{Aabb, BoundingVolume};
use parry3d_f64::math::{Pose, Rotation, Vector};
use parry3d_f64::query::NonlinearRigidMotion;
use parry3d_f64::shape::SharedShape;
use rapier3d_f64::geometry::ColliderHandle;

/// Against dense sampling of the motion (parry's own
/// `position_at_time`, the shape's box at 4,097 times): every sampled
/// box lies in the swept box, and the swept box is no larger than the
/// sampled ones' union grown by the twice the radius and the margins
/// (so that a box of everything would fail). Shapes whose motion's
/// centre lies off them (a local centre up to 0.5 away, as a compound's
/// part has), turns of 0 to 3 radians a step (both ways of the box), and
/// still shapes.
#[test]
fn swept_boxes_hold_every_sampled_pose_and_are_tight() {
    let mut r = Rng::new(55);
    let dt = 1.0 / 60.0;
    let reach = 1e-4;
    const N: usize = 4096;
    let shapes = [
        SharedShape::cuboid(1.0, 0.02, 0.3),
        SharedShape::cylinder(0.3, 0.05),
        SharedShape::cone(0.3, 0.08),
        SharedShape::capsule_y(0.2, 0.05),
        SharedShape::ball(0.05),
        SharedShape::cuboid(0.005, 4.0, 4.0),
    ];
    let v = |r: &mut Rng, s: f64| Vector::new(r.range(-s, s), r.range(-s, s), r.range(-s, s));
    let (mut turned, mut ball_only) = (0, 0);
    for case in 0..3000 {
        let shape = &shapes[case % shapes.len()];
        let axis = v(&mut r, 1.0).normalize_or(Vector::X);
        let start = Pose::from_parts(
            v(&mut r, 10.0),
            Rotation::from_axis_angle(axis, r.range(0.0, 3.0)),
        );
        let (linvel, angvel) = if case % 7 == 0 {
            (Vector::ZERO, Vector::ZERO)
        } else {
            let w = v(&mut r, 1.0).normalize_or(Vector::Y) * r.range(0.0, 3.0) / dt;
            (v(&mut r, 200.0), w)
        };
        let m = NonlinearRigidMotion::new(start, v(&mut r, 0.5), linvel, angvel);
        let ball = shape.compute_local_bounding_sphere();
        let radius = (ball.center - m.local_center).length() + ball.radius;
        let centre = m.start * m.local_center;
        let boxed = swept_box(&m, shape.as_ref(), centre, radius, dt, reach);
        let mut union = Aabb::new_invalid();
        for k in 0..=N {
            let t = dt * k as f64 / N as f64;
            let a = shape.compute_aabb(&m.position_at_time(t));
            assert!(
                boxed.contains(&a),
                "case {case}: the pose at {t} ({a:?}) is outside {boxed:?}"
            );
            union.merge(&a);
        }
        let turn = angvel.length() * dt;
        turned += usize::from(turn > 0.0 && turn < 1.0);
        ball_only += usize::from(turn >= 1.0);
        let loose = union.loosened(2.0 * radius + 2.0 * reach + 1e-6);
        assert!(
            loose.contains(&boxed),
            "case {case}: {boxed:?} is more than twice the radius {radius} off the sampled {union:?}"
        );
    }
    assert!(turned > 500 && ball_only > 500, "{turned} {ball_only}");
}

fn placed(r: &mut Rng) -> Placed {
    let v = |r: &mut Rng, s: f64| Vector::new(r.range(-s, s), r.range(-s, s), r.range(-s, s));
    Placed {
        body: None,
        centre: v(r, 1.0),
        velocity: v(r, 150.0),
        radius: r.range(0.0, 0.5),
        turning: 0.0,
        motion: NonlinearRigidMotion::constant_position(Pose::IDENTITY),
        swept: parry3d_f64::bounding_volume::Aabb::new_invalid(),
        handle: ColliderHandle::invalid(),
    }
}

/// Against dense sampling of the centres' distance: a pair that comes
/// within reach at a sample is never said apart, and a pair that stays
/// well apart at every sample (by more than the centres move between
/// samples) is.
#[test]
fn bounding_balls_are_said_apart_exactly_when_sampling_finds_them_apart() {
    let mut r = Rng::new(17);
    let dt = 1.0 / 60.0;
    let reach = 1e-3;
    const N: usize = 4096;
    let (mut apart, mut near) = (0, 0);
    for _ in 0..20_000 {
        let (a, b) = (placed(&mut r), placed(&mut r));
        let need = a.radius + b.radius + reach;
        let least = (0..=N)
            .map(|k| {
                let t = dt * k as f64 / N as f64;
                ((b.centre + b.velocity * t) - (a.centre + a.velocity * t)).length()
            })
            .fold(f64::INFINITY, f64::min);
        let said = a.apart_over(&b, dt, reach);
        assert_eq!(said, b.apart_over(&a, dt, reach));
        if least <= need {
            assert!(!said, "sampled {least} within {need}, said apart");
            near += 1;
        }
        let step = (b.velocity - a.velocity).length() * dt / N as f64;
        if least > need + step + 1e-6 {
            assert!(said, "sampled {least} beyond {need} by more than {step}");
            apart += 1;
        }
    }
    // Both kinds occur.
    assert!(apart > 2000 && near > 2000, "apart {apart}, near {near}");
}

/// Against dense sampling of parry's own `position_at_time`: when the
/// pass's check certifies a carried pair (Lemma 12.14, "The pass's
/// check"), the overlap along the normal (parry's support points at
/// 4,097 times) stays below the ceiling it returns over the whole step.
/// Boxes and balls (a ball turning about a point off its centre among
/// them), resting, drifting, pressed in and spinning, with held and
/// carried ceilings and floors; with the turn's term halved it fails.
#[test]
fn a_carried_pair_checked_without_a_cast_stays_below_its_ceiling() {
    let mut r = Rng::new(64);
    let dt = 1.0 / 60.0;
    let d = 1e-3;
    const N: usize = 4096;
    let shapes = [
        SharedShape::cuboid(0.1, 0.1, 0.1),
        SharedShape::ball(0.1),
        SharedShape::cuboid(0.5, 0.02, 0.3),
    ];
    let v = |r: &mut Rng, s: f64| Vector::new(r.range(-s, s), r.range(-s, s), r.range(-s, s));
    let (mut certified, mut refused) = (0, 0);
    for case in 0..3000 {
        // Every sixth case where the bound is tight (below), half of
        // them a turning ball.
        let tight = case % 6 == 5;
        let sa = if tight && (case / 6) % 2 == 0 {
            &shapes[1]
        } else {
            &shapes[case % 3]
        };
        let sb = &shapes[(case / 3) % 3];
        let n = v(&mut r, 1.0).normalize_or(Vector::Z);
        let rot = |r: &mut Rng| {
            Rotation::from_axis_angle(v(r, 1.0).normalize_or(Vector::X), r.range(0.0, 3.0))
        };
        // B at the origin, A placed so that its extent along `n` is a
        // little past B's (overlap -2d to 6d).
        let (qa, qb) = (rot(&mut r), rot(&mut r));
        let pb = Pose::from_parts(Vector::ZERO, qb);
        let lo = -extent(sb.as_ref(), &pb, -n).expect("a support map");
        let probe = Pose::from_parts(Vector::ZERO, qa);
        let back = -extent(sa.as_ref(), &probe, -n).expect("a support map");
        let overlap0 = r.range(-2.0, 6.0) * d;
        let shift =
            n * (lo - back - (extent(sa.as_ref(), &probe, n).unwrap() - back)) + n * overlap0;
        let pa = Pose::from_parts(shift, qa);
        // Slow and fast motions: resting jitter, drift, spin.
        let scale = [1e-3, 3e-2, 1.0][case % 3];
        let spin = [1e-2, 1.0, 30.0][(case / 9) % 3];
        let mut ma =
            NonlinearRigidMotion::new(pa, v(&mut r, 0.05), v(&mut r, scale), v(&mut r, spin));
        let mut mb =
            NonlinearRigidMotion::new(pb, v(&mut r, 0.05), v(&mut r, scale), v(&mut r, spin));
        if tight {
            // Where the bound is tight: B still, A pressed in along `n`
            // by up to 4 d, or a ball turning (by 0.1 to 1 rad) about a
            // point 2e-4 to 4e-3 off its centre, which then moves along
            // `n` at nearly the bound's rate.
            mb = NonlinearRigidMotion::constant_position(pb);
            if sa.as_ball().is_some() {
                let u = n.any_orthonormal_vector();
                let off = r.range(2e-4, 4e-3);
                let w = n.cross(u) * (r.range(0.1, 1.0) / dt);
                let sign = if r.range(0.0, 1.0) < 0.5 { 1.0 } else { -1.0 };
                ma =
                    NonlinearRigidMotion::new(pa, qa.inverse() * (u * off), Vector::ZERO, w * sign);
            } else {
                let press = r.range(0.0, 4.0) * d / dt;
                ma = NonlinearRigidMotion::new(pa, Vector::ZERO, n * press, Vector::ZERO);
            }
        }
        let place = |m: &NonlinearRigidMotion, s: &SharedShape| {
            let ball = s.compute_local_bounding_sphere();
            let radius = (ball.center - m.local_center).length() + ball.radius;
            let turning = if s.as_ball().is_some() {
                (ball.center - m.local_center).length()
            } else {
                radius
            };
            Placed {
                body: None,
                centre: m.start * m.local_center,
                velocity: m.linvel,
                radius,
                turning,
                motion: *m,
                swept: Aabb::new_invalid(),
                handle: ColliderHandle::invalid(),
            }
        };
        let (a, b) = (place(&ma, sa), place(&mb, sb));
        let last = Ceiling {
            value: overlap0.max(0.0) + r.range(0.0, 3.0) * d,
            held: case % 2 == 0,
        };
        let floor = if case % 4 == 1 { 5e-3 } else { 0.0 };
        let Some(c) = a.still_below(sa.as_ref(), &b, sb.as_ref(), n, last, floor, d, dt) else {
            refused += 1;
            continue;
        };
        certified += 1;
        for k in 0..=N {
            let t = dt * k as f64 / N as f64;
            let o = extent(sa.as_ref(), &ma.position_at_time(t), n).unwrap()
                + extent(sb.as_ref(), &mb.position_at_time(t), -n).unwrap();
            assert!(
                o < c.value,
                "case {case}: at {t} the overlap {o} reached the ceiling {}",
                c.value
            );
        }
    }
    assert!(certified > 500 && refused > 500, "{certified} {refused}");
}
