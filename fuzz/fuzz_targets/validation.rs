//! Input validation and evaluation on fully raw input: arbitrary `f32`/`f64`
//! bit patterns (NaN, infinities, subnormals, huge values, biased to the
//! range analysis' boundary values), a vertex list that may be empty.
//!
//! * `VertexSet::try_new`, `BodySummary::from_radius`, `Direction::try_new`,
//!   `TimeInterval::try_new`, `RigidMotion::try_new`, `RigidMotion::restrict`
//!   never panic and return exactly the documented typed error (or `Ok`);
//!   accepted values satisfy their documented postconditions (the radius
//!   bounds every vertex, `| |n| - 1 | <= gamma_5`, the interval is kept).
//! * Whenever the constructors succeed, `nevq`, `evq` and `directed_bound`
//!   (both kinds, also on the restricted motion) return a speed and a
//!   displacement that are not NaN and are `>= 0` (`+inf` allowed); EVQ is at
//!   most NEVQ; `directed_bound` and `*_speed` agree with `nevq`/`evq`; NEVQ
//!   is monotone in the radius; `time_to_close` of a gap in range is not NaN.
//! * For at most 64 vertices and angles `|w| t` of at most 2^16, the bounds
//!   are also checked for soundness against the high-precision oracle, as in
//!   the `nevq`/`evq` targets (whatever the magnitudes: the oracle runs on an
//!   exactly rescaled copy of the case, `motion_bound_fuzz::oracle`).

#![no_main]

use std::fmt::Debug;

use libfuzzer_sys::fuzz_target;
use motion_bound::reference::Real;
use motion_bound::testkit::Case;
use motion_bound::{
    directed_bound, evq, evq_speed, nevq, nevq_speed, BodySummary, BoundKind, DirectedBound,
    Direction, InputError, Quantity, RigidMotion, TimeInterval, Vec3, VertexSet,
};
use motion_bound_fuzz::inputs::{Precisions, RawInput, ValidationCase};
use motion_bound_fuzz::{
    check_components_result, check_evq_le_nevq, check_sound, checked_motion, in_range, norm, nums,
    Oracle, Precision,
};

fn run<T: Precision>(raw: &RawInput<T>) {
    // VertexSet::try_new
    let verts: Vec<[T; 3]> = raw.vertices.iter().map(|v| nums(*v)).collect();
    let vs = VertexSet::try_new(&verts);
    if verts.is_empty() {
        assert!(
            vs == Err(InputError::EmptyVertexSet),
            "({}) empty vertex set gave {vs:?}",
            T::NAME
        );
    } else {
        let bad = verts.iter().position(|r| !r.iter().all(|&x| in_range(x)));
        match bad {
            Some(i) => {
                let groups: Vec<(&[T], Quantity)> = verts
                    .iter()
                    .enumerate()
                    .map(|(j, r)| (&r[..], Quantity::Vertex(j)))
                    .collect();
                assert!(
                    !check_components_result("VertexSet::try_new", &vs, &groups),
                    "vertex {i}"
                );
            }
            None => {
                let body = vs.unwrap_or_else(|e| {
                    panic!(
                        "({}) valid vertices rejected with {e:?}: {verts:?}",
                        T::NAME
                    )
                });
                assert!(body.len() == verts.len() && !body.is_empty(), "length");
                let r_hat = body.summary().max_radius();
                assert!(
                    r_hat.is_finite() && r_hat >= T::ZERO,
                    "({}) max_radius {r_hat:?} for {verts:?}",
                    T::NAME
                );
                let slack = <T::R as Real>::from_f64(1.0 + 4.0 * T::R_EPS);
                for r in &verts {
                    let len = norm::<T>(*r);
                    assert!(
                        Real::mul(<T::R as Real>::from_f64(r_hat.to_f64()), slack) >= len,
                        "({}) max_radius {:e} below |{r:?}| = {:e}",
                        T::NAME,
                        r_hat.to_f64(),
                        len.to_f64()
                    );
                }
            }
        }
    }

    // BodySummary::from_radius
    let radius = raw.radius.get();
    let rs = BodySummary::from_radius(radius);
    if check_components_result(
        "BodySummary::from_radius",
        &rs,
        &[(&[radius], Quantity::Radius)],
    ) {
        expect(
            &rs,
            radius < T::ZERO,
            InputError::NegativeRadius,
            |s| s.max_radius() == radius,
            &("radius", radius),
        );
    }

    // Direction::try_new
    let nraw = nums(raw.n);
    let dir = Direction::try_new(Vec3::from_array(nraw));
    if nraw.iter().any(|x| !x.is_finite()) {
        assert!(
            dir == Err(InputError::NonFinite(Quantity::Direction)),
            "({}) direction {nraw:?} gave {dir:?}",
            T::NAME
        );
    } else if nraw.iter().all(|&x| x == T::ZERO) {
        assert!(
            dir == Err(InputError::ZeroDirection),
            "({}) direction {nraw:?} gave {dir:?}",
            T::NAME
        );
    } else {
        let d = dir.unwrap_or_else(|e| panic!("({}) direction {nraw:?} gave {e:?}", T::NAME));
        let len = norm::<T>(d.to_array());
        let u = T::UNIT_ROUNDOFF.to_f64();
        let gamma5 = 5.0 * u / (1.0 - 5.0 * u);
        let err = Real::abs(Real::sub(len, <T::R as Real>::from_f64(1.0))).to_f64();
        assert!(
            err <= gamma5 + 4.0 * T::R_EPS,
            "({}) Direction::try_new({nraw:?}) = {d:?} has length 1 {err:+e}, above gamma_5",
            T::NAME
        );
        assert!(
            (-d).to_array()
                .iter()
                .zip(d.to_array())
                .all(|(a, b)| *a == -b),
            "negation"
        );
    }

    // TimeInterval::try_new
    let [i0, i1] = nums(raw.interval);
    let ti = TimeInterval::try_new(i0, i1);
    if check_components_result("TimeInterval::try_new", &ti, &[(&[i0, i1], Quantity::Time)]) {
        expect(
            &ti,
            i1 < i0,
            InputError::ReversedInterval,
            |t| (t.start(), t.end()) == (i0, i1),
            &("interval", [i0, i1]),
        );
    }

    // RigidMotion::try_new
    let centre = nums(raw.centre);
    let linear = nums(raw.linear);
    let angular = nums(raw.angular);
    let iv = ti.unwrap_or(TimeInterval::UNIT);
    let mres = checked_motion(centre, linear, angular, iv);

    // The bounds, whenever the constructors succeeded.
    let (Ok(body), Ok(n), Some(motion)) = (vs, dir, mres) else {
        return;
    };
    let gap = raw.gap.get();
    let (nb, _) = bounds(&body, &motion, n, gap);

    if let Ok(summary) = rs {
        let nr = nevq(&summary, &motion, n);
        check_plain("nevq (radius)", nr, &motion);
        if summary.max_radius() >= body.summary().max_radius() {
            assert!(
                nr.speed >= nb.speed,
                "({}) nevq not monotone in the radius: {:?} (R {:?}) < {:?} (R {:?})",
                T::NAME,
                nr.speed,
                summary.max_radius(),
                nb.speed,
                body.summary().max_radius()
            );
        }
    }

    let [sa, sb] = nums(raw.sub);
    if let Ok(sub) = motion.restrict(sa, sb) {
        bounds(&body, &sub, n, gap);
        oracle(&verts, &sub, n, rs.ok(), true);
    }
    oracle(&verts, &motion, n, rs.ok(), false);
}

/// A constructor's result on components in range: `Err(err)` if `rejected`,
/// else `Ok` with `accepted` true of the value.
fn expect<X: Debug>(
    res: &Result<X, InputError>,
    rejected: bool,
    err: InputError,
    accepted: impl Fn(&X) -> bool,
    input: &dyn Debug,
) {
    let ok = match res {
        Ok(x) => !rejected && accepted(x),
        Err(e) => rejected && *e == err,
    };
    assert!(ok, "{input:?} gave {res:?}");
}

/// Every bound entry point; the plain checks; returns (nevq, evq).
fn bounds<T: Precision>(
    body: &VertexSet<'_, T>,
    motion: &RigidMotion<T>,
    n: Direction<T>,
    gap: T,
) -> (DirectedBound<T>, DirectedBound<T>) {
    let nb = nevq(&body.summary(), motion, n);
    let eb = evq(body, motion, n);
    check_plain("nevq", nb, motion);
    check_plain("evq", eb, motion);
    let ctx = (motion, n, body.vertices());
    check_evq_le_nevq(eb, nb, &ctx);
    let dn = directed_bound(BoundKind::Nevq, body, motion, n);
    let de = directed_bound(BoundKind::Evq, body, motion, n);
    let dd = directed_bound(BoundKind::default(), body, motion, n);
    assert!(
        dn == nb && de == eb && dd == nb,
        "({}) directed_bound disagrees: {dn:?} / {nb:?}, {de:?} / {eb:?}; {ctx:?}",
        T::NAME
    );
    let (ns, es) = (
        nevq_speed(&body.summary(), motion, n),
        evq_speed(body, motion, n),
    );
    assert!(
        ns == nb.speed && es == eb.speed,
        "({}) *_speed disagrees: {ns:?} / {:?}, {es:?} / {:?}; {ctx:?}",
        T::NAME,
        nb.speed,
        eb.speed
    );
    if in_range(gap) && gap >= T::ZERO {
        for b in [nb, eb] {
            let dt = b.time_to_close(gap);
            assert!(
                !dt.is_nan() && dt >= T::ZERO,
                "({}) time_to_close({gap:?}) = {dt:?} for {b:?}",
                T::NAME
            );
        }
    }
    (nb, eb)
}

fn check_plain<T: Precision>(what: &str, b: DirectedBound<T>, motion: &RigidMotion<T>) {
    assert!(
        !b.speed.is_nan()
            && !b.displacement.is_nan()
            && b.speed >= T::ZERO
            && b.displacement >= T::ZERO,
        "({}) {what} gave {b:?} for {motion:?}",
        T::NAME
    );
}

/// Soundness against the oracle, for at most 64 vertices and angles `|w| t`
/// of at most 2^16 at the interval's ends.
fn oracle<T: Precision>(
    verts: &[[T; 3]],
    motion: &RigidMotion<T>,
    n: Direction<T>,
    radius: Option<BodySummary<T>>,
    restricted: bool,
) {
    if verts.len() > 64 {
        return;
    }
    let iv = motion.interval();
    let theta =
        motion.angular_speed().to_f64() * iv.start().to_f64().abs().max(iv.end().to_f64().abs());
    if theta.is_nan() || theta > 65536.0 {
        return;
    }
    let case = Case {
        vertices: verts.to_vec(),
        motion: *motion,
        n,
    };
    let ex = Oracle::new(&case);
    let body = VertexSet::try_new(verts).expect("validated");
    let [wn, we, wr] = if restricted {
        [
            "nevq (restricted)",
            "evq (restricted)",
            "nevq (radius, restricted)",
        ]
    } else {
        ["nevq", "evq", "nevq (radius)"]
    };
    check_sound(wn, &ex, nevq(&body.summary(), motion, n), &case);
    check_sound(we, &ex, evq(&body, motion, n), &case);
    if let Some(s) = radius {
        // A bounding sphere: only if it really contains every vertex.
        let r = <T::R as Real>::from_f64(s.max_radius().to_f64());
        if verts.iter().all(|v| norm::<T>(*v) <= r) {
            check_sound(wr, &ex, nevq(&s, motion, n), &case);
        }
    }
}

fuzz_target!(|input: ValidationCase| match &input {
    Precisions::Single(raw) => run::<f32>(raw),
    Precisions::Double(raw) => run::<f64>(raw),
});
