//! Each named case of the issue, checked against the exact oracle: zero
//! rotation, `n` parallel to `w`, vertices on the axis, sweeps at and beyond
//! pi and 2 pi, sub-interval arcs, extreme magnitudes, and bad input.

mod common;

use motion_bound::reference::{dd::DoubleDouble, exact, Exact};
use motion_bound::{
    directed_bound, evq, nevq, BoundKind, Direction, Float, InputError, Point3, Quantity,
    RigidMotion, TimeInterval, Vec3, VertexSet,
};

const BLOB: [[f64; 3]; 6] = [
    [1.0, 0.2, -0.3],
    [-0.4, 0.9, 0.1],
    [0.0, 0.0, 1.5],
    [0.3, -0.8, -0.6],
    [-0.7, -0.1, 0.4],
    [0.5, 0.5, 0.5],
];

fn motion(v: [f64; 3], w: [f64; 3], ta: f64, tb: f64) -> RigidMotion<f64> {
    RigidMotion::try_new(
        Point3::ORIGIN,
        Vec3::from_array(v),
        Vec3::from_array(w),
        TimeInterval::try_new(ta, tb).unwrap(),
    )
    .unwrap()
}

/// Both bounds against the double-double oracle; returns (nevq, evq, exact sup).
fn check(vertices: &[[f64; 3]], m: &RigidMotion<f64>, n: Direction<f64>) -> (f64, f64, f64) {
    let body = VertexSet::try_new(vertices).unwrap();
    let nv = nevq(&body.summary(), m, n);
    let ev = evq(&body, m, n);
    let ex: Exact<DoubleDouble> = exact(vertices, m, n);
    let (sup, disp) = (ex.sup_speed.to_f64(), ex.displacement.to_f64());
    for (name, b) in [("NEVQ", nv), ("EVQ", ev)] {
        assert!(b.speed >= sup, "{name} speed {} < exact {sup}", b.speed);
        assert!(
            b.displacement >= disp,
            "{name} displacement {} < exact {disp}",
            b.displacement
        );
    }
    assert!(
        ev.speed <= nv.speed,
        "EVQ {} looser than NEVQ {}",
        ev.speed,
        nv.speed
    );
    (nv.speed, ev.speed, sup)
}

#[test]
fn zero_rotation_leaves_the_linear_term() {
    let m = motion([1.0, -2.0, 0.5], [0.0; 3], 0.0, 1.0);
    let n = Direction::try_new(Vec3::new(0.0, 1.0, 0.0)).unwrap();
    let (nv, ev, sup) = check(&BLOB, &m, n);
    assert_eq!(sup, 2.0, "exact");
    assert!(
        nv <= 2.0 * (1.0 + 1e-14) && ev <= nv,
        "tight up to the margin: {nv} {ev}"
    );
}

#[test]
fn n_parallel_to_w_makes_c_vanish() {
    let m = motion([0.3, 0.0, 0.7], [0.0, 0.0, 5.0], 0.0, 1.0);
    let (nv, ev, sup) = check(&BLOB, &m, Direction::Z);
    assert_eq!(sup, 0.7, "rotation contributes nothing along the axis");
    assert!(nv <= 0.7 * (1.0 + 1e-14) + 1e-14 && ev <= nv, "{nv} {ev}");
    // And within a few ulps of parallel: c is tiny but not zero.
    let tilt = Direction::try_new(Vec3::new(4.0 * f64::EPSILON, 0.0, 1.0)).unwrap();
    check(&BLOB, &m, tilt);
}

#[test]
fn vertices_on_the_axis_do_not_rotate() {
    let on_axis = [[0.0, 0.0, 1.0], [0.0, 0.0, -3.0]];
    let m = motion([0.0; 3], [0.0, 0.0, 2.0], 0.0, 1.0);
    let (_, ev, sup) = check(&on_axis, &m, Direction::X);
    assert_eq!(sup, 0.0, "nothing moves");
    assert!(ev < 1e-13, "EVQ sees that: {ev}");
}

#[test]
fn sweeps_at_and_beyond_pi_and_two_pi() {
    let n = Direction::try_new(Vec3::new(0.3, 1.0, 0.2)).unwrap();
    for sweep in [
        core::f64::consts::PI * (1.0 - f64::EPSILON),
        core::f64::consts::PI,
        core::f64::consts::PI * (1.0 + f64::EPSILON),
        core::f64::consts::TAU * (1.0 - f64::EPSILON),
        core::f64::consts::TAU,
        core::f64::consts::TAU * (1.0 + f64::EPSILON),
        7.5 * core::f64::consts::PI,
    ] {
        let m = motion([0.1, 0.0, 0.0], [0.3, -0.2, 1.0], 0.0, 1.0);
        let w = m.angular_speed();
        let m = m.with_interval(TimeInterval::try_new(0.0, sweep / w).unwrap());
        check(&BLOB, &m, n);
    }
}

#[test]
fn sub_interval_arcs_far_from_the_epoch() {
    let m = motion([0.0; 3], [0.0, 0.0, 1.0], 0.0, 1000.0);
    let n = Direction::Y;
    let rod = [[1.0, 0.0, 0.0]];
    for (ta, tb) in [
        (0.0, 0.1),
        (0.7, 0.8),
        (3.0, 3.2),
        (999.0, 999.5),
        (500.0, 503.2),
    ] {
        let sub = m.restrict(ta, tb).unwrap();
        let (_, ev, sup) = check(&rod, &sub, n);
        assert!(
            ev <= sup * (1.0 + 1e-9) + 1e-12,
            "EVQ is tight on one vertex: {ev} vs {sup}"
        );
    }
}

#[test]
fn extreme_but_valid_magnitudes_give_finite_or_infinite_never_nan() {
    let big = f64::MAX_INPUT;
    let pts = [[big, -big, big], [1e-300, 0.0, 0.0]];
    let body = VertexSet::try_new(&pts).unwrap();
    let m = RigidMotion::try_from_arrays([big; 3], [big, big, -big], [big, -big, big]).unwrap();
    let n = Direction::try_new(Vec3::new(1.0, 2.0, 3.0)).unwrap();
    for kind in [BoundKind::Nevq, BoundKind::Evq] {
        let b = directed_bound(kind, &body, &m, n);
        assert!(
            !b.speed.is_nan() && !b.displacement.is_nan(),
            "{kind:?}: NaN"
        );
        assert!(b.speed > 0.0, "{kind:?}: positive");
    }
    let tiny = [[1e-300, 2e-300, 0.0]];
    let body = VertexSet::try_new(&tiny).unwrap();
    let m = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [1e-300, 0.0, 1e-300]).unwrap();
    let b = evq(&body, &m, Direction::Y);
    assert!(b.speed >= 0.0 && b.speed.is_finite(), "tiny: {b:?}");
}

#[test]
fn f32_with_fast_spin_and_far_vertices() {
    let pts: Vec<[f32; 3]> = BLOB.iter().map(|p| p.map(|x| x as f32 * 1e6)).collect();
    let m =
        RigidMotion::<f32>::try_from_arrays([0.0; 3], [1.0, 0.0, 0.0], [0.0, 300.0, 1.0]).unwrap();
    let n = Direction::try_new(Vec3::new(0.0f32, 0.6, 0.8)).unwrap();
    let body = VertexSet::try_new(&pts).unwrap();
    let ex: Exact<f64> = exact(&pts, &m, n);
    let e = evq(&body, &m, n);
    assert!(
        f64::from(e.speed) >= ex.sup_speed,
        "f32 EVQ {} < {}",
        e.speed,
        ex.sup_speed
    );
}

#[test]
fn bad_input_gets_typed_errors() {
    assert_eq!(
        VertexSet::<f64>::try_new(&[]),
        Err(InputError::EmptyVertexSet),
        "empty"
    );
    assert_eq!(
        Direction::try_new(Vec3::new(0.0, f64::INFINITY, 0.0)),
        Err(InputError::NonFinite(Quantity::Direction)),
        "infinite direction"
    );
    assert_eq!(
        Direction::try_new(Vec3::<f32>::ZERO),
        Err(InputError::ZeroDirection),
        "zero direction"
    );
    assert_eq!(
        RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [f64::NAN; 3]),
        Err(InputError::NonFinite(Quantity::AngularVelocity)),
        "NaN w"
    );
    assert_eq!(
        RigidMotion::<f32>::try_from_arrays([1e30, 0.0, 0.0], [0.0; 3], [0.0; 3]),
        Err(InputError::TooLarge(Quantity::Centre)),
        "absurd centre"
    );
    assert_eq!(
        TimeInterval::try_new(f64::NAN, 1.0),
        Err(InputError::NonFinite(Quantity::Time)),
        "NaN time"
    );
    let e = motion_bound::BodySummary::from_radius(-1.0f64);
    assert_eq!(e, Err(InputError::NegativeRadius), "negative radius");
}
