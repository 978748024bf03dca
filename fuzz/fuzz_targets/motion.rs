//! Motion evaluation on raw input (any bit pattern, biased to the range
//! analysis' boundary values), in `f32` and `f64`:
//!
//! * `RigidMotion::try_new` returns `Ok` exactly when every component of the
//!   centre, `v` and `w` is finite and at most `MAX_INPUT`, and otherwise the
//!   typed error naming the first offending quantity; it never panics;
//! * `arm_at`, `point_at`, `velocity_at`, `directed_speed_at`, `angle_at`,
//!   `centre_at` never panic on any input; for a body point and time in range
//!   they give finite (no NaN) results, and
//!   - `|arm_at(r, t)| = |r|` to a relative 1e-12 (f64; 1e-5 for f32), plus
//!     64 eta for underflow (rotation preserves length);
//!   - `arm_at` matches Rodrigues' rotation by `|w| t` evaluated in the
//!     oracle's precision, within `(64 + 8 |theta|) u |r|` (for `|w|` at least
//!     `TINY_LENGTH` and `|theta| <= 1024`), and the axis is a unit vector;
//!   - `point_at = x0 + v t + arm`, `velocity_at = v + w x arm` and
//!     `directed_speed_at = velocity . n` to `6 u` of their magnitudes;
//! * `restrict` returns the documented typed error (non-finite or too large
//!   time, reversed, not a sub-interval) or the sub-interval, keeping the
//!   epoch, centre and velocities.

#![no_main]

use libfuzzer_sys::fuzz_target;
use motion_bound::reference::Real;
use motion_bound::{BodyPoint, Direction, InputError, Quantity, RigidMotion, TimeInterval};
use motion_bound_fuzz::inputs::{MotionCase, MotionInput, Precisions};
use motion_bound_fuzz::{
    check_components_result, checked_motion, in_range, norm, nums, wide, Precision,
};

fn run<T: Precision>(raw: &MotionInput<T>) {
    let centre = nums(raw.centre);
    let linear = nums(raw.linear);
    let angular = nums(raw.angular);
    let [i0, i1] = nums(raw.interval);
    let iv = TimeInterval::try_new(i0, i1).unwrap_or(TimeInterval::UNIT);
    let Some(m) = checked_motion(centre, linear, angular, iv) else {
        return;
    };
    assert!(
        m.centre().to_array() == centre
            && m.linear().to_array() == linear
            && m.angular().to_array() == angular
            && m.interval() == iv,
        "({}) accessors do not return the inputs: {m:?}",
        T::NAME
    );
    let omega = m.angular_speed();
    let u = T::UNIT_ROUNDOFF.to_f64();
    assert!(
        !omega.is_nan() && omega >= T::ZERO && omega.is_finite(),
        "({}) |w| = {omega:?} for w {angular:?}",
        T::NAME
    );
    let axis_len = norm::<T>(m.axis().to_array()).to_f64();
    if omega == T::ZERO {
        assert!(axis_len == 0.0, "({}) zero w, axis {:?}", T::NAME, m.axis());
    } else if omega >= T::TINY_LENGTH {
        assert!(
            (axis_len - 1.0).abs() <= 8.0 * u,
            "({}) axis {:?} of length {axis_len:?} for w {angular:?}",
            T::NAME,
            m.axis()
        );
    }

    let n = Direction::try_from_array(nums(raw.n)).unwrap_or(Direction::Z);
    let point = nums(raw.point);
    let [t0, t1] = nums(raw.times);
    for t in [t0, t1, iv.start(), iv.end()] {
        evaluate(&m, point, t, n);
    }
    check_restrict(&m, nums(raw.sub));
}

fn evaluate<T: Precision>(m: &RigidMotion<T>, point: [T; 3], t: T, n: Direction<T>) {
    let r = BodyPoint::from_array(point);
    let arm = m.arm_at(r, t).to_array();
    let p = m.point_at(r, t).to_array();
    let vel = m.velocity_at(r, t).to_array();
    let ds = m.directed_speed_at(r, t, n);
    let _ = (m.angle_at(t), m.centre_at(t));
    if !(point.iter().all(|&x| in_range(x)) && in_range(t)) {
        return; // outside the documented domain: only "no panic"
    }
    let ctx = || format!("({}) motion {m:?}, r {point:?}, t {t:?}, n {n:?}", T::NAME);
    for (what, x) in [
        ("arm_at", arm),
        ("point_at", p),
        ("velocity_at", vel),
        ("directed_speed_at", [ds; 3]),
    ] {
        assert!(
            x.iter().all(|c| c.is_finite()),
            "{what} = {x:?} is not finite; {}",
            ctx()
        );
    }

    let u = T::UNIT_ROUNDOFF.to_f64();
    let eta = T::ETA.to_f64();
    let r_eps = T::R_EPS;
    let rd = |x: f64| <T::R as Real>::from_f64(x);
    let close = |x: T, ex: T::R, tol: f64| Real::abs(Real::sub(wide(x), ex)) <= rd(tol);

    // Rotation preserves length.
    let rn = norm::<T>(point);
    let an = norm::<T>(arm);
    let rel = if T::NAME == "f64" { 1e-12 } else { 1e-5 };
    let r_len = rn.to_f64();
    assert!(
        Real::abs(Real::sub(an, rn)) <= rd(rel * r_len + 64.0 * eta),
        "|arm_at| = {:e} differs from |r| = {r_len:e} (arm {arm:?}); {}",
        an.to_f64(),
        ctx()
    );

    // Rodrigues' rotation in the oracle's precision.
    let omega = m.angular_speed();
    let theta = omega.to_f64() * t.to_f64();
    if omega >= T::TINY_LENGTH && theta.abs() <= 1024.0 {
        let w = m.angular().to_array().map(wide::<T>);
        let om = norm::<T>(m.angular().to_array());
        let k = w.map(|x| Real::div(x, om));
        let th = Real::mul(om, wide(t));
        let (s, c) = (Real::sin(th), Real::cos(th));
        let one_c = Real::sub(rd(1.0), c);
        let rr = point.map(wide::<T>);
        let kxr = cross(k, rr);
        let kdr = Real::add(
            Real::add(Real::mul(k[0], rr[0]), Real::mul(k[1], rr[1])),
            Real::mul(k[2], rr[2]),
        );
        let tol = (64.0 * u + 8.0 * u * theta.abs()) * r_len + 64.0 * eta;
        for i in 0..3 {
            let ex = Real::add(
                Real::add(Real::mul(rr[i], c), Real::mul(kxr[i], s)),
                Real::mul(k[i], Real::mul(kdr, one_c)),
            );
            assert!(
                close(arm[i], ex, tol),
                "arm_at[{i}] = {:e} but the exact rotation gives {:e} (tolerance {tol:e}, theta {theta:e}); {}",
                arm[i].to_f64(),
                ex.to_f64(),
                ctx()
            );
        }
    }

    // point_at, velocity_at and directed_speed_at: short sums of products,
    // each within 6 u of its magnitude (plus underflow) of the sum in R.
    let check_sum = |what: &str, i: usize, formula: &str, got: T, ex: T::R, mag: f64| {
        let tol = (6.0 * u + 8.0 * r_eps) * mag + 8.0 * eta;
        assert!(
            close(got, ex, tol),
            "{what}[{i}] = {:e}, {formula} = {:e} (tolerance {tol:e}); {}",
            got.to_f64(),
            ex.to_f64(),
            ctx()
        );
    };
    let x0 = m.centre().to_array();
    let v = m.linear().to_array();
    let w = m.angular().to_array();
    for i in 0..3 {
        // point_at = x0 + v t + arm
        let vt = Real::mul(wide(v[i]), wide(t));
        let ex = Real::add(Real::add(wide(x0[i]), vt), wide(arm[i]));
        let mag = x0[i].to_f64().abs() + (v[i].to_f64() * t.to_f64()).abs() + arm[i].to_f64().abs();
        check_sum("point_at", i, "x0 + v t + arm", p[i], ex, mag);

        // velocity_at = v + w x arm
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        let a = Real::mul(wide(w[j]), wide(arm[k]));
        let b = Real::mul(wide(w[k]), wide(arm[j]));
        let ex = Real::add(wide(v[i]), Real::sub(a, b));
        let mag = v[i].to_f64().abs()
            + (w[j].to_f64() * arm[k].to_f64()).abs()
            + (w[k].to_f64() * arm[j].to_f64()).abs();
        check_sum("velocity_at", i, "v + w x arm", vel[i], ex, mag);
    }

    // directed_speed_at = velocity . n
    let nn = n.to_array();
    let mut ex = <T::R as Real>::from_f64(0.0);
    let mut mag = 0.0;
    for i in 0..3 {
        ex = Real::add(ex, Real::mul(wide(vel[i]), wide(nn[i])));
        mag += (vel[i].to_f64() * nn[i].to_f64()).abs();
    }
    check_sum("directed_speed_at", 0, "velocity . n", ds, ex, mag);
}

fn cross<R: Real>(a: [R; 3], b: [R; 3]) -> [R; 3] {
    [
        Real::sub(Real::mul(a[1], b[2]), Real::mul(a[2], b[1])),
        Real::sub(Real::mul(a[2], b[0]), Real::mul(a[0], b[2])),
        Real::sub(Real::mul(a[0], b[1]), Real::mul(a[1], b[0])),
    ]
}

fn check_restrict<T: Precision>(m: &RigidMotion<T>, [sa, sb]: [T; 2]) {
    let res = m.restrict(sa, sb);
    if !check_components_result(
        "RigidMotion::restrict",
        &res,
        &[(&[sa, sb], Quantity::Time)],
    ) {
        return;
    }
    let iv = m.interval();
    let expected = if sb < sa {
        Err(InputError::ReversedInterval)
    } else if !(iv.start() <= sa && sb <= iv.end()) {
        Err(InputError::NotASubInterval)
    } else {
        Ok(())
    };
    match (res, expected) {
        (Ok(sub), Ok(())) => {
            let same = sub.interval().start() == sa
                && sub.interval().end() == sb
                && sub.centre() == m.centre()
                && sub.linear() == m.linear()
                && sub.angular() == m.angular()
                && sub.angular_speed() == m.angular_speed()
                && sub.axis() == m.axis();
            assert!(
                same,
                "({}) restrict({sa:?}, {sb:?}) of {m:?} gave {sub:?}",
                T::NAME
            );
        }
        (Err(e), Err(x)) => assert!(
            e == x,
            "({}) restrict({sa:?}, {sb:?}) of {iv:?}: expected {x:?}, got {e:?}",
            T::NAME
        ),
        (got, want) => panic!(
            "({}) restrict({sa:?}, {sb:?}) of {iv:?}: expected {want:?}, got {got:?}",
            T::NAME
        ),
    }
}

fuzz_target!(|input: MotionCase| match &input {
    Precisions::Single(raw) => run::<f32>(raw),
    Precisions::Double(raw) => run::<f64>(raw),
});
