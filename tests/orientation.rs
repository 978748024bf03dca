//! The start orientation and the rotation centre off the body origin
//! (`proofs/floating-point.md`, section "Orientation"), checked against
//! computations in higher precision (double-double for `f64`, `f64` for
//! `f32`) that never use the crate's matrices:
//!
//! * Lemma O.1: a [`Rotation`]'s matrix is within `80 u` (spectral norm; the
//!   test checks the larger Frobenius norm) of the exact rotation of its
//!   stored quaternion normalised exactly;
//! * Lemma O.2: the rotational speed evaluated in the computed body frame
//!   (`fl(M^T n)`, `fl(M^T w)`, points `fl(r - c)`) is within the frame
//!   margin `k R` of the exact one, `(n x w) . R(w t) Q0 (r - c)`, at every
//!   time; and the margin is not idle (the measured difference reaches a
//!   sizeable fraction of it).

use motion_bound::reference::{DoubleDouble, Real};
use motion_bound::testkit::SplitMix64;
use motion_bound::{Float, Rotation, Vec3};
use proptest::prelude::*;

mod common;

type V<R> = [R; 3];

fn dot<R: Real>(a: V<R>, b: V<R>) -> R {
    a[0].mul(b[0]).add(a[1].mul(b[1])).add(a[2].mul(b[2]))
}

fn cross<R: Real>(a: V<R>, b: V<R>) -> V<R> {
    [
        a[1].mul(b[2]).sub(a[2].mul(b[1])),
        a[2].mul(b[0]).sub(a[0].mul(b[2])),
        a[0].mul(b[1]).sub(a[1].mul(b[0])),
    ]
}

fn widen<T: Float, R: Real>(v: Vec3<T>) -> V<R> {
    v.to_array().map(|x| R::from_f64(x.to_f64()))
}

/// Rotates `r` by the quaternion `q` normalised in `R`: `q r q^-1`.
fn quat_rotate<R: Real>(q: [R; 4], r: V<R>) -> V<R> {
    let n = q[0]
        .mul(q[0])
        .add(q[1].mul(q[1]))
        .add(q[2].mul(q[2]))
        .add(q[3].mul(q[3]))
        .sqrt();
    let w = q[0].div(n);
    let v = [q[1].div(n), q[2].div(n), q[3].div(n)];
    let two = R::from_f64(2.0);
    let c = cross(v, r);
    let cc = cross(v, c);
    [0, 1, 2].map(|k| r[k].add(two.mul(w).mul(c[k])).add(two.mul(cc[k])))
}

/// Rotates `r` about the unit axis of `w` by `|w| t` (Rodrigues, in `R`).
fn spin<R: Real>(w: V<R>, t: R, r: V<R>) -> V<R> {
    let om = dot(w, w).sqrt();
    if om.to_f64() == 0.0 {
        return r;
    }
    let k = [w[0].div(om), w[1].div(om), w[2].div(om)];
    let a = om.mul(t);
    let (s, c) = (a.sin(), a.cos());
    let kr = cross(k, r);
    let kd = dot(k, r);
    let one = R::from_f64(1.0);
    [0, 1, 2].map(|i| {
        r[i].mul(c)
            .add(kr[i].mul(s))
            .add(k[i].mul(kd.mul(one.sub(c))))
    })
}

/// `||M - Q||_F` for the stored matrix and the exact rotation of the stored
/// quaternion, in `R`.
fn matrix_error<T: Float, R: Real>(rot: &Rotation<T>) -> f64 {
    let q = rot.quaternion().map(|x| R::from_f64(x.to_f64()));
    let m = rot.matrix();
    let mut sum = R::from_f64(0.0);
    for j in 0..3 {
        let mut e = [R::from_f64(0.0); 3];
        e[j] = R::from_f64(1.0);
        let col = quat_rotate(q, e);
        for i in 0..3 {
            let d = R::from_f64(m[i][j].to_f64()).sub(col[i]);
            sum = sum.add(d.mul(d));
        }
    }
    sum.sqrt().to_f64()
}

fn quaternion() -> impl Strategy<Value = [f64; 4]> {
    let c = prop_oneof![
        6 => -1.0f64..1.0,
        1 => Just(0.0),
        1 => (-1.0f64..1.0).prop_map(|x| x * 1e-12),
    ];
    ([c.clone(), c.clone(), c.clone(), c], -300i32..300)
        .prop_map(|(q, e)| q.map(|x| x * 2f64.powi(e / 4)))
}

/// The rotation of the quaternion `q` rounded to `T`, if it is nonzero.
fn rotation<T: Float>(q: [f64; 4]) -> Option<Rotation<T>> {
    let [w, x, y, z] = q.map(T::from_f64);
    Rotation::try_from_quaternion(w, x, y, z).ok()
}

fn check_matrix<T: Float, R: Real>(q: [f64; 4]) -> Result<(), TestCaseError> {
    let Some(rot) = rotation::<T>(q) else {
        return Ok(());
    };
    let err = matrix_error::<T, R>(&rot);
    let bound = rot.matrix_error().to_f64() + 16.0 * T::ETA.to_f64();
    prop_assert!(
        err <= bound,
        "||M - Q||_F = {err:e} above {bound:e} for {q:?}"
    );
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(common::cases()))]

    /// Lemma O.1, `f64` against double-double.
    #[test]
    fn the_rotation_matrix_is_within_its_error_bound_f64(q in quaternion()) {
        check_matrix::<f64, DoubleDouble>(q)?;
    }

    /// Lemma O.1, `f32` against `f64`.
    #[test]
    fn the_rotation_matrix_is_within_its_error_bound_f32(q in quaternion()) {
        check_matrix::<f32, f64>(q)?;
    }
}

/// The frame margin's coefficient, as `rounding::frame_margin_up` states it
/// (`proofs/floating-point.md`, "Orientation"), computed here in `f64`.
fn margin_coefficient<T: Float>(w_body_l1: f64, theta_m: f64, offset: bool) -> f64 {
    let u = T::UNIT_ROUNDOFF.to_f64();
    u * w_body_l1 * (192.0 + 96.0 * theta_m + if offset { 2.0 } else { 0.0 })
}

/// Lemma O.2 for one random case in precision `T`, evaluated in `R`:
/// returns the largest `|exact - frame| / (k R)` over sampled times.
fn frame_perturbation<T: Float, R: Real>(rng: &mut SplitMix64) -> f64 {
    let q = [0; 4].map(|_| rng.signed_unit());
    let Some(rot) = rotation::<T>(q) else {
        return 0.0;
    };
    let scale = 10f64.powi((rng.next_u64() % 7) as i32 - 3);
    let vec =
        |rng: &mut SplitMix64, s: f64| Vec3::from_array(rng.vec3().map(|x| T::from_f64(x * s)));
    let n = motion_bound::Direction::new_or(vec(rng, 1.0), motion_bound::Direction::X);
    let spin_rate = 20.0 * rng.signed_unit().abs();
    let w = vec(rng, spin_rate);
    let c = if rng.next_u64().is_multiple_of(2) {
        vec(rng, scale)
    } else {
        Vec3::ZERO
    };
    let r = vec(rng, scale);
    // The crate's body frame (what `PreparedMotion::probe` computes).
    let nb = rot.inverse_rotate(n.get());
    let wb = rot.inverse_rotate(w);
    let rho = r - c;
    // Exact in R: world frame with the exact rotation of the quaternion.
    let (nr, wr) = (widen::<T, R>(n.get()), widen::<T, R>(w));
    let qr = rot.quaternion().map(|x| R::from_f64(x.to_f64()));
    let d = [0, 1, 2].map(|k| widen::<T, R>(r)[k].sub(widen::<T, R>(c)[k]));
    let arm0 = quat_rotate(qr, d);
    let cw = cross(nr, wr);
    // The computed frame's quantity, evaluated exactly for its float inputs.
    let (nbr, wbr, rhor) = (widen::<T, R>(nb), widen::<T, R>(wb), widen::<T, R>(rho));
    let cb = cross(nbr, wbr);
    let lever = (r.length().to_f64() + c.length().to_f64()) * (1.0 + 1e-6);
    let mut worst = 0.0f64;
    let t_max = 1.0 + 3.0 * rng.signed_unit().abs();
    let theta_m = wb.length().to_f64() * t_max;
    let k = margin_coefficient::<T>(wb.norm_l1().to_f64(), theta_m, c != Vec3::ZERO);
    for i in 0..=16 {
        let t = R::from_f64(t_max * f64::from(i) / 16.0);
        let exact = dot(cw, spin(wr, t, arm0));
        let frame = dot(cb, spin(wbr, t, rhor));
        let diff = exact.sub(frame).abs().to_f64();
        worst = worst.max(diff / (k * lever));
    }
    worst
}

fn frame_lemma<T: Float, R: Real>(seed: u64) {
    let mut rng = SplitMix64(seed);
    let mut worst = 0.0f64;
    for _ in 0..2000 {
        worst = worst.max(frame_perturbation::<T, R>(&mut rng));
    }
    println!(
        "{}: largest frame perturbation over the margin: {worst:.3}",
        core::any::type_name::<T>()
    );
    assert!(worst <= 1.0, "the frame margin is exceeded: {worst}");
    // The margin is not idle: the perturbation it covers is a sizeable part
    // of it (a margin far above every perturbation would hide a wrong
    // derivation of its constants).
    assert!(
        worst >= 1e-3,
        "the frame margin covers nothing measurable: {worst}"
    );
}

#[test]
fn the_body_frame_speed_is_within_the_frame_margin_f64() {
    frame_lemma::<f64, DoubleDouble>(17);
}

#[test]
fn the_body_frame_speed_is_within_the_frame_margin_f32() {
    frame_lemma::<f32, f64>(18);
}
