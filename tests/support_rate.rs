//! The support-rate bounds of convex shapes (`proofs/12-shapes.md`, Lemma
//! 12.5) dominate how fast each shape's exact support moves, in `f32` and
//! `f64`, on motions that map the shape onto itself (a ball spinning about
//! its centre; a capsule, cylinder or cone spinning about its axis, exactly
//! or nearly), and on any other motion.
//!
//! The oracle is independent of the crate's bounds: the exact support of the
//! placed shape, `h(t) = max_{s in S} s . n`, from the motion's own stored
//! numbers (the start quaternion normalised in `f64`, the angular velocity,
//! Rodrigues' formula for the turn) and the shapes' closed-form supports
//! written out here, at 2,001 times over the interval. Every rise of `h`
//! between two neighbouring times must be at most the one-sided rate times
//! the time between them, every change at most the absolute speed times it
//! (up to the oracle's own rounding, `1e-12` of the scale for `f64`), and
//! neither bound may exceed the point bounds (`convex_rate`,
//! `convex_speed`) it refines.

use motion_bound::testkit::toi::Rng;
use motion_bound::{
    BoundKind, Convex, Direction, Float, PreparedMotion, RigidMotion, Rotation, TimeInterval, Vec3,
};

type V = [f64; 3];

fn dot(a: V, b: V) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: V, b: V) -> V {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn add(a: V, b: V) -> V {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
fn scale(a: V, s: f64) -> V {
    [a[0] * s, a[1] * s, a[2] * s]
}
fn norm(a: V) -> f64 {
    dot(a, a).sqrt()
}

/// The rotation of a quaternion `[w, x, y, z]` normalised in `f64`, applied
/// to `v`.
fn quat_rotate(q: [f64; 4], v: V) -> V {
    let l = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).sqrt();
    let (w, u) = (q[0] / l, [q[1] / l, q[2] / l, q[3] / l]);
    // v + 2 w (u x v) + 2 u x (u x v)
    let uv = cross(u, v);
    add(add(v, scale(uv, 2.0 * w)), scale(cross(u, uv), 2.0))
}

/// The inverse rotation of the same quaternion.
fn quat_inverse_rotate(q: [f64; 4], v: V) -> V {
    quat_rotate([q[0], -q[1], -q[2], -q[3]], v)
}

/// Rodrigues: `v` turned about the unit `axis` by `angle`.
fn turn(axis: V, angle: f64, v: V) -> V {
    let (s, c) = angle.sin_cos();
    add(
        add(scale(v, c), scale(cross(axis, v), s)),
        scale(axis, dot(axis, v) * (1.0 - c)),
    )
}

/// The shapes, as their parameters: the core and the radius.
#[derive(Clone, Copy, Debug)]
enum Core {
    Point,
    Segment(f64),
    Cylinder(f64, f64),
    Cone(f64, f64),
}

/// The core's support `max_{k in K} k . d` in its own frame (closed forms).
fn core_support(core: Core, d: V) -> f64 {
    let across = (d[0] * d[0] + d[2] * d[2]).sqrt();
    match core {
        Core::Point => 0.0,
        Core::Segment(h) => h * d[1].abs(),
        Core::Cylinder(h, rho) => h * d[1].abs() + rho * across,
        Core::Cone(h, rho) => (h * d[1]).max(rho * across - h * d[1]),
    }
}

fn convex<T: Float>(core: Core, radius: f64) -> Convex<'static, T> {
    let t = T::from_f64;
    let shape = match core {
        Core::Point => Convex::try_ball(T::ZERO),
        Core::Segment(h) => Convex::try_capsule(t(h), T::ZERO),
        Core::Cylinder(h, rho) => Convex::try_cylinder(t(h), t(rho)),
        Core::Cone(h, rho) => Convex::try_cone(t(h), t(rho)),
    }
    .expect("valid shape");
    if radius > 0.0 {
        shape.try_rounded(t(radius)).expect("valid radius")
    } else {
        shape
    }
}

/// The exact support of the shape along the unit `n` at time `t`, from the
/// motion's stored numbers.
fn support<T: Float>(m: &RigidMotion<T>, core: Core, radius: f64, n: V, t: f64) -> f64 {
    let f = |v: Vec3<T>| [v.x.to_f64(), v.y.to_f64(), v.z.to_f64()];
    let q = m.orientation().quaternion().map(Float::to_f64);
    let (x0, v, w, c) = (
        f(m.centre().to_vec3()),
        f(m.linear()),
        f(m.angular()),
        f(m.local_centre()),
    );
    let omega = norm(w);
    let turn_t = |x: V| {
        if omega > 0.0 {
            turn(scale(w, 1.0 / omega), omega * t, x)
        } else {
            x
        }
    };
    let turn_back = |x: V| {
        if omega > 0.0 {
            turn(scale(w, 1.0 / omega), -omega * t, x)
        } else {
            x
        }
    };
    // s = x0 + v t + R Q0 (k - c): s . n = (x0 + v t - R Q0 c) . n + k . (Q0^T R^T n).
    let origin = add(add(x0, scale(v, t)), scale(turn_t(quat_rotate(q, c)), -1.0));
    let d = quat_inverse_rotate(q, turn_back(n));
    dot(origin, n) + core_support(core, d) + radius
}

/// One case: the one-sided rate along `n` and the absolute speed bound the
/// support's moves over the interval, against the oracle.
fn check<T: Float>(m: &RigidMotion<T>, core: Core, radius: f64, n: Direction<T>, what: &str) {
    let shape = convex::<T>(core, radius);
    let probe = PreparedMotion::new(m).probe(n);
    let rate = probe.convex_support_rate(&shape, BoundKind::Evq).to_f64();
    let speed = probe.convex_support_speed(&shape, BoundKind::Evq).to_f64();
    for kind in [BoundKind::Evq, BoundKind::Nevq] {
        let (r, s) = (
            probe.convex_support_rate(&shape, kind),
            probe.convex_support_speed(&shape, kind),
        );
        assert!(
            r <= probe.convex_rate(&shape, kind) && s <= probe.convex_speed(&shape, kind),
            "{what}: a support bound above the point bound it refines ({kind:?})"
        );
    }
    let nv = n.get();
    let nn = [nv.x.to_f64(), nv.y.to_f64(), nv.z.to_f64()];
    let nn = scale(nn, 1.0 / norm(nn));
    let (t0, t1) = (m.interval().start().to_f64(), m.interval().end().to_f64());
    let steps = 2000;
    let h = |t: f64, dir: V| support(m, core, radius, dir, t);
    let reach = norm(m.centre().to_vec3().to_array().map(Float::to_f64))
        + norm(m.linear().to_array().map(Float::to_f64)) * t1.abs().max(t0.abs())
        + 4.0 * (1.0 + norm(m.local_centre().to_array().map(Float::to_f64)));
    // The oracle's own rounding: its sums of terms up to `reach`.
    let tol = 1e-12 * reach;
    let minus = scale(nn, -1.0);
    let (mut prev, mut prev_minus) = (h(t0, nn), h(t0, minus));
    let (first, first_minus) = (prev, prev_minus);
    for k in 1..=steps {
        let t = t0 + (t1 - t0) * f64::from(k) / f64::from(steps);
        let dt = (t1 - t0) / f64::from(steps);
        let (now, now_minus) = (h(t, nn), h(t, minus));
        assert!(
            now - prev <= rate * dt + tol,
            "{what}: the support along n rose by {} over {dt}, above the rate {rate} (at t = {t})",
            now - prev
        );
        assert!(
            (now - prev).abs() <= speed * dt + tol
                && (now_minus - prev_minus).abs() <= speed * dt + tol,
            "{what}: the support moved by {} / {} over {dt}, above the speed {speed} (at t = {t})",
            now - prev,
            now_minus - prev_minus
        );
        (prev, prev_minus) = (now, now_minus);
    }
    assert!(
        prev - first <= rate * (t1 - t0) + tol
            && (prev_minus - first_minus).abs() <= speed * (t1 - t0) + tol,
        "{what}: the support's change over the interval exceeds its bound"
    );
}

/// A unit vector perpendicular to the unit `a`.
fn perpendicular(a: V, rng: &mut Rng) -> V {
    loop {
        let d = rng.direction();
        let p = cross(a, d);
        if norm(p) > 0.1 {
            return scale(p, 1.0 / norm(p));
        }
    }
}

fn cases<T: Float>(count: usize, seed: u64) -> usize {
    let mut rng = Rng::new(seed);
    let mut tight = 0;
    for case in 0..count {
        let t = |x: f64| T::from_f64(x);
        let r = |x: f64| t(x).to_f64();
        let (h, rho) = (r(rng.range(0.05, 1.0)), r(rng.range(0.05, 1.0)));
        let core = match case % 4 {
            0 => Core::Point,
            1 => Core::Segment(h),
            2 => Core::Cylinder(h, rho),
            _ => Core::Cone(h, rho),
        };
        let radius = if case % 8 < 4 {
            0.0
        } else {
            r(rng.range(0.01, 0.3))
        };
        // A start orientation (every other case), its image of the body's y axis.
        let q = if case % 2 == 0 {
            Rotation::IDENTITY
        } else {
            let a = rng.direction();
            Rotation::try_from_axis_angle(
                Vec3::new(t(a[0]), t(a[1]), t(a[2])),
                t(rng.range(-3.0, 3.0)),
            )
            .expect("rotation")
        };
        let qf = q.quaternion().map(Float::to_f64);
        let axis = quat_rotate(qf, [0.0, 1.0, 0.0]);
        // The spin: about the axis, nearly, or anyhow.
        let spin = rng.range(-60.0, 60.0);
        let tilt = [0.0, 1e-9, 1e-6, 1e-3, 0.1, 1.0][case % 6];
        let w = if case % 7 == 6 {
            scale(rng.direction(), spin)
        } else {
            add(
                scale(axis, spin),
                scale(perpendicular(axis, &mut rng), tilt * spin),
            )
        };
        // The rotation centre: on the axis, or off it by a little or much.
        let off = [0.0, 0.0, 1e-7, 0.05, 0.5][case % 5];
        let c = add(
            [0.0, rng.range(-h, h), 0.0],
            scale(perpendicular([0.0, 1.0, 0.0], &mut rng), off),
        );
        let v = scale(rng.direction(), [0.0, 0.5, 5.0][case % 3]);
        let x0 = scale(rng.direction(), rng.range(0.0, 3.0));
        let vec = |a: V| Vec3::new(t(a[0]), t(a[1]), t(a[2]));
        let (start, end) = (rng.range(0.0, 0.5), rng.range(0.5, 1.0));
        let m = RigidMotion::try_new(
            motion_bound::Point3::new(t(x0[0]), t(x0[1]), t(x0[2])),
            vec(v),
            vec(w),
            TimeInterval::try_new(t(start), t(end)).expect("interval"),
        )
        .expect("motion");
        let m = RigidMotion::try_from_start(
            motion_bound::Isometry::try_new(q, m.centre().to_vec3()).expect("pose"),
            m.linear(),
            m.angular(),
            T::ONE,
        )
        .expect("motion")
        .try_with_local_centre(vec(c))
        .expect("centre")
        .with_interval(TimeInterval::try_new(t(start), t(end)).expect("interval"));
        let n = Direction::try_from_array(rng.direction().map(t)).expect("direction");
        let what = format!("case {case}: {core:?} rounded {radius}, tilt {tilt}, off {off}");
        check(&m, core, radius, n, &what);
        let shape = convex::<T>(core, radius);
        let probe = PreparedMotion::new(&m).probe(n);
        if probe.convex_support_rate(&shape, BoundKind::Evq)
            < probe.convex_rate(&shape, BoundKind::Evq)
        {
            tight += 1;
        }
    }
    tight
}

#[test]
fn support_bounds_dominate_the_exact_support_f64() {
    let tight = cases::<f64>(600, 0x5_0991);
    // Not vacuous: most cases are tighter than the point bounds.
    assert!(
        tight > 300,
        "only {tight} of 600 cases tighter than the point bounds"
    );
}

#[test]
fn support_bounds_dominate_the_exact_support_f32() {
    let tight = cases::<f32>(600, 0x5_0992);
    assert!(
        tight > 300,
        "only {tight} of 600 cases tighter than the point bounds"
    );
}

/// Spins that map the shape onto itself cost nothing: a ball about its
/// centre, a capsule, cylinder or cone about its axis (along any start
/// orientation), rounded or not, leave the support's rate at the
/// translation's.
#[test]
fn spins_that_map_a_shape_onto_itself_cost_nothing() {
    let mut rng = Rng::new(7);
    for core in [
        Core::Point,
        Core::Segment(0.5),
        Core::Cylinder(0.1, 0.5),
        Core::Cone(0.4, 0.3),
    ] {
        for radius in [0.0, 0.05] {
            let shape = convex::<f64>(core, radius);
            let a = rng.direction();
            let q = Rotation::try_from_axis_angle(Vec3::from_array(a), 1.1).expect("rotation");
            let axis = q.rotate(Vec3::new(0.0, 1.0, 0.0));
            let m = RigidMotion::try_from_start(
                motion_bound::Isometry::try_new(q, Vec3::new(0.3, 1.0, -2.0)).expect("pose"),
                Vec3::new(0.0, -2.0, 0.0),
                axis * 40.0,
                1.0 / 60.0,
            )
            .expect("motion");
            let probe = PreparedMotion::new(&m).probe(Direction::X);
            let rate = probe.convex_support_rate(&shape, BoundKind::Evq);
            // The translation has no x part; only rounding margins remain.
            assert!(rate < 1e-9, "{core:?} rounded {radius}: rate {rate}");
            // Where the shape has points off its axis, the point bound sees them turn.
            let on_axis = matches!(core, Core::Point | Core::Segment(_)) && radius == 0.0;
            assert!(
                on_axis || probe.convex_rate(&shape, BoundKind::Evq) > 1e-3,
                "{core:?} rounded {radius}: the point bound should see the spin"
            );
        }
    }
}
