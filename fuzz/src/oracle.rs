//! The soundness oracle of the bound targets, evaluated on an exactly
//! rescaled copy of each case.
//!
//! # Why rescale
//!
//! Double-double has the exponent range of `f64`: its extra precision is
//! gone for values below about `2^-968`, and the reference's `hypot(P, Q)`
//! squares the sinusoid's coefficients, so it loses them entirely below about
//! `2^-511`. Fuzzed cases reach those magnitudes (a sweep of `1e-310` rad, a
//! body of `1e-300`), and the unscaled oracle then reported bounds "below the
//! exact value" that were in fact sound (`fuzz/README.md`, "Findings").
//!
//! Speeds are homogeneous in the inputs, so the oracle runs on a copy of the
//! case scaled by powers of two ([`Scaled`]): time by `2^b` (with `w` by
//! `2^-b`, so `|w'|` is in `[1, 2)` and every angle `|w| t` is unchanged) and
//! speeds by `2^s` (`v` by `2^s`, the body by `2^(s + b)`), with `s` chosen so
//! that the speed magnitude `sum |v_k n_k| + |w| max |r_i|` becomes about 1.
//! The linear term `v . n / |n|` is taken from the original `v` with exact
//! products ([`Oracle::new`]), so a velocity component too large to rescale
//! (paired with a tiny component of `n`) needs no special case.
//! Scaling by a power of two is exact except for components that fall into
//! the subnormal range, and those are below `2^-1022` of the dominant
//! magnitude: far below the oracle's own `2^-104` (or `2^-53`) relative
//! error, which is itself far below the bounds' margins (multiples of the
//! bound type's `u` times the same magnitude). The bound is never rescaled:
//! the comparison `bound * 2^s >= sup'` is made exactly on exponents and
//! mantissas ([`ge_scaled`]).
//!
//! # What is checked
//!
//! [`check_sound`]: the bound's speed and displacement are not NaN, not
//! negative, `speed >= sup_t max_i |p_i'(t) . n|` and
//! `displacement >= sup * (t_b - t_a)`, both against the exact values in the
//! oracle's precision, rounded to nearest `f64` at the end. The second is
//! stronger than `displacement >= max_i integral |p_i'(t) . n| dt`, because
//! that integral never exceeds `sup * (t_b - t_a)` (the `reference` target
//! checks the reference's integral against exactly that); it is also what
//! NEVQ and EVQ document (`displacement` is `speed * (t_b - t_a)` rounded up).

use std::fmt::Debug;

use motion_bound::reference::{Frame, Real};
use motion_bound::testkit::Case;
use motion_bound::{DirectedBound, Point3, RigidMotion, TimeInterval, Vec3};

use crate::Precision;

/// `floor(log2 |x|)` for a finite nonzero `x`, subnormals included.
#[must_use]
pub fn ilogb(x: f64) -> i32 {
    let bits = x.abs().to_bits();
    let biased = (bits >> 52) as i32;
    if biased == 0 {
        // 63 - leading_zeros is the index of the top bit of the mantissa
        63 - bits.leading_zeros() as i32 - 1074
    } else {
        biased - 1023
    }
}

/// `2^e` for `e` in `[-1074, 1023]`.
#[must_use]
pub fn pow2(e: i32) -> f64 {
    assert!((-1074..=1023).contains(&e), "2^{e} is not an f64");
    if e >= -1022 {
        f64::from_bits(((e + 1023) as u64) << 52)
    } else {
        f64::from_bits(1u64 << (e + 1074))
    }
}

/// `x * 2^e`, correctly rounded (one rounding at most: every step but the
/// last is exact).
#[must_use]
pub fn ldexp(mut x: f64, mut e: i32) -> f64 {
    while e > 1000 && x.is_finite() && x != 0.0 {
        x *= pow2(1000); // exact unless it overflows
        e -= 1000;
    }
    while e < -1000 && x.is_finite() && x != 0.0 && ilogb(x) - 1000 >= -1022 {
        x *= pow2(-1000); // exact: the result is normal
        e += 1000;
    }
    if !x.is_finite() || x == 0.0 {
        return x;
    }
    if e < -1074 {
        // here |x| < 2^-22, so |x 2^e| < 2^-1096 rounds to zero
        return 0.0 * x.signum();
    }
    x * pow2(e.min(1023))
}

/// `x * 2^e >= y`, decided exactly, for `x >= 0` and any `y`, neither NaN.
#[must_use]
pub fn ge_scaled(x: f64, e: i32, y: f64) -> bool {
    assert!(
        !x.is_nan() && !y.is_nan() && x >= 0.0,
        "ge_scaled({x:?}, {e}, {y:?})"
    );
    if y <= 0.0 || x == f64::INFINITY {
        return true;
    }
    if x == 0.0 || y == f64::INFINITY {
        return false;
    }
    let (ex, ey) = (i64::from(ilogb(x)) + i64::from(e), i64::from(ilogb(y)));
    if ex != ey {
        return ex > ey;
    }
    // both mantissas in [1, 2), exactly
    ldexp(x, -ilogb(x)) >= ldexp(y, -ilogb(y))
}

/// A case rescaled by powers of two into the range where the oracle is
/// accurate (see the module docs).
#[derive(Clone, Debug)]
pub struct Scaled<T> {
    /// The rescaled case: `r' = 2^(s+b) r`, `v' = 2^s v`, `w' = 2^-b w`,
    /// `t' = 2^b t`, the centre at the origin, and the very same `n`; except
    /// that a component of `v'` along which `n` is exactly 0 is 0 (it adds
    /// exactly 0 to every directed speed), and one that would not fit below
    /// the crate's `MAX_INPUT` is 0 too (then `faithful` is `false`).
    pub case: Case<T>,
    /// `s`: every directed speed of `case` is `2^s` times the original's.
    pub speed_exp: i32,
    /// `2^s |v . n|_1 + |w'|_inf max |r'_ik|` (from the original `v`): in
    /// `[1, 8)`, or 0 when nothing moves along `n`.
    pub mag: f64,
    /// `false` if a component of `v'` had to be dropped: then only
    /// [`Oracle`] (which takes the linear term from the original `v`) gives
    /// the original case's speeds, not `case` itself.
    pub faithful: bool,
}

/// The largest `|x|` of a list (0 for none).
fn max_abs(xs: impl IntoIterator<Item = f64>) -> f64 {
    xs.into_iter().fold(0.0, |m, x| m.max(x.abs()))
}

/// `x * 2^e` rounded to `T` (one rounding: the `f64` product is exact for
/// every `f32` and is [`ldexp`] for `f64`).
fn scale_t<T: Precision>(x: T, e: i32) -> T {
    T::from_f64(ldexp(x.to_f64(), e))
}

/// The terms `2^s v_k n_k` as pairs of factors near 1 whose exact products
/// they are (up to a factor that falls below the subnormal range): `n_k` is
/// brought to `[1, 2)` first, so no factor over- or underflows.
fn linear_terms(v: [f64; 3], n: [f64; 3], s: i32) -> impl Iterator<Item = (f64, f64)> {
    (0..3)
        .filter(move |&k| v[k] != 0.0 && n[k] != 0.0)
        .map(move |k| {
            let e = -ilogb(n[k]);
            (ldexp(v[k], s - e), ldexp(n[k], e))
        })
}

impl<T: Precision> Scaled<T> {
    /// The rescaled copy of `case` (the original, unscaled, if the rescaled
    /// motion cannot be built, which no target's cases come near).
    #[must_use]
    pub fn new(case: &Case<T>) -> Self {
        let wide = |a: [T; 3]| a.map(T::to_f64);
        let m = &case.motion;
        let (v, w, n) = (
            wide(m.linear().to_array()),
            wide(m.angular().to_array()),
            wide(case.n.to_array()),
        );
        let w_max = max_abs(w);
        let r_max = max_abs(case.vertices.iter().flatten().map(|x| x.to_f64()));

        // Time: |w'|_inf in [1, 2).
        let b = if w_max > 0.0 { ilogb(w_max) } else { 0 };
        // Speed: s = -(the largest binary exponent of |v_k n_k| and |w| |r|).
        let mut top: Option<i32> = (0..3)
            .filter(|&k| v[k] != 0.0 && n[k] != 0.0)
            .map(|k| ilogb(v[k]) + ilogb(n[k]))
            .max();
        if w_max > 0.0 && r_max > 0.0 {
            top = top.max(Some(ilogb(w_max) + ilogb(r_max)));
        }
        let s = top.map_or(0, |t| -t);
        // Every rescaled input stays well below the crate's MAX_INPUT.
        let cap = ilogb(T::MAX_INPUT.to_f64()) - 7;
        let mut faithful = true;
        let linear = m.linear().to_array().map(|x| {
            let y = scale_t(x, s);
            if x != T::ZERO && y.to_f64() != 0.0 && ilogb(y.to_f64()) > cap {
                faithful = false;
                T::ZERO
            } else {
                y
            }
        });
        let linear: [T; 3] =
            core::array::from_fn(|k| if n[k] == 0.0 { T::ZERO } else { linear[k] });
        let mut r_exp = s + b;
        if r_max > 0.0 {
            // binding only when w = 0, where the body does not move anything
            r_exp = r_exp.min(cap - ilogb(r_max));
        }

        let scale = |a: [T; 3], e: i32| a.map(|x| scale_t(x, e));
        let iv = m.interval();
        let scaled = TimeInterval::try_new(scale_t(iv.start(), b), scale_t(iv.end(), b)).and_then(
            |interval| {
                // The start orientation is scale-free; the rotation centre in
                // the body frame scales with the body's points.
                RigidMotion::try_new(
                    Point3::ORIGIN,
                    Vec3::from_array(linear),
                    Vec3::from_array(scale(m.angular().to_array(), -b)),
                    interval,
                )?
                .with_orientation(m.orientation())
                .try_with_local_centre(Vec3::from_array(scale(m.local_centre().to_array(), r_exp)))
            },
        );
        let (case, speed_exp) = match scaled {
            Ok(motion) => (
                Case {
                    vertices: case.vertices.iter().map(|r| scale(*r, r_exp)).collect(),
                    motion,
                    n: case.n,
                },
                s,
            ),
            Err(_) => (case.clone(), 0),
        };
        let w = wide(case.motion.angular().to_array());
        let mag = linear_terms(v, n, speed_exp)
            .map(|(x, y)| (x * y).abs())
            .sum::<f64>()
            + max_abs(w)
                * (max_abs(case.vertices.iter().flatten().map(|x| x.to_f64()))
                    + max_abs(case.motion.local_centre().to_array().map(|x| x.to_f64())));
        Self {
            case,
            speed_exp,
            mag,
            faithful: faithful || speed_exp == 0,
        }
    }
}

/// The exact supremum of the directed speed of a case, from the reference
/// evaluated in the oracle's precision on the rescaled case.
#[derive(Clone, Debug)]
pub struct Oracle<T: Precision> {
    /// The rescaled case the reference ran on.
    pub scaled: Scaled<T>,
    /// `sup_t max_i |p_i'(t) . n|` of the rescaled case.
    pub sup: T::R,
    /// `t_b - t_a` of the original case.
    pub length: T::R,
    /// The largest signed speeds `sup_t max_i p_i'(t) . n` along `+n` and
    /// along `-n`, in the scaled units of `sup`: what one-sided bounds
    /// (`DirectedProbe::rate`) must dominate.
    pub sup_signed: (T::R, T::R),
}

impl<T: Precision> Oracle<T> {
    /// Runs the reference's closed-form supremum (`SpeedProfile::sup_abs`)
    /// on the rescaled `case`. The linear term `a = 2^s v . n / |n|` that
    /// every profile shares is computed here from the original `v`, with the
    /// exact products of [`linear_terms`], rather than by `Frame` from the
    /// rescaled `v` (whose components may have had to be dropped, and whose
    /// products with tiny components of the normalised `n` would be rounded
    /// to the subnormal grid before being scaled up).
    #[must_use]
    pub fn new(case: &Case<T>) -> Self {
        let scaled = Scaled::new(case);
        let c = &scaled.case;
        let frame: Frame<T::R> = Frame::new(&c.motion, c.n);
        let r = |x: f64| <T::R as Real>::from_f64(x);
        let wide = |a: [T; 3]| a.map(T::to_f64);
        let n = wide(case.n.to_array());
        let n_len = n
            .iter()
            .fold(r(0.0), |acc, &x| acc.add(r(x).mul(r(x))))
            .sqrt();
        let a = linear_terms(wide(case.motion.linear().to_array()), n, scaled.speed_exp)
            .fold(r(0.0), |acc, (x, y)| acc.add(r(x).mul(r(y))))
            .div(n_len);
        let (ta, tb) = ends(&c.motion);
        let sup = c.vertices.iter().fold(r(0.0), |m, v| {
            let mut prof = frame.profile(*v);
            prof.a = a;
            m.max(prof.sup_abs(ta, tb))
        });
        let lowest = r(f64::NEG_INFINITY);
        let sup_signed = c.vertices.iter().fold((lowest, lowest), |(p, q), v| {
            let mut prof = frame.profile(*v);
            prof.a = a;
            let plus = prof.sup_signed(ta, tb);
            let zero = r(0.0);
            prof.a = zero.sub(prof.a);
            prof.p = zero.sub(prof.p);
            prof.q = zero.sub(prof.q);
            (p.max(plus), q.max(prof.sup_signed(ta, tb)))
        });
        let (ta, tb) = ends(&case.motion);
        Self {
            scaled,
            sup,
            length: tb.sub(ta),
            sup_signed,
        }
    }

    /// The supremum in the original case's units (for messages).
    #[must_use]
    pub fn sup_unscaled(&self) -> f64 {
        ldexp(self.sup.to_f64(), -self.scaled.speed_exp)
    }
}

/// The motion's interval ends, widened exactly to `T::R` (as
/// `Frame::new` widens them).
#[must_use]
pub fn ends<T: Precision>(m: &RigidMotion<T>) -> (T::R, T::R) {
    let iv = m.interval();
    let w = |t: T| <T::R as Real>::from_f64(t.to_f64());
    (w(iv.start()), w(iv.end()))
}

/// `x * 2^e` in `R`, exactly when no part under- or overflows.
fn scale_r<R: Real>(x: R, e: i32) -> R {
    let h = e / 2;
    x.mul(R::from_f64(pow2(h))).mul(R::from_f64(pow2(e - h)))
}

/// The soundness oracle (see the module docs): `bound` is not NaN, not
/// negative, its speed is at least the exact supremum of the directed speed
/// and its displacement at least that supremum times the interval's length.
pub fn check_sound<T: Precision>(
    what: &str,
    oracle: &Oracle<T>,
    bound: DirectedBound<T>,
    context: &dyn Debug,
) {
    let name = T::NAME;
    let (s, d) = (bound.speed.to_f64(), bound.displacement.to_f64());
    let sup = oracle.sup.to_f64();
    let e = oracle.scaled.speed_exp;
    assert!(
        !sup.is_nan(),
        "{what} ({name}): oracle is NaN: {oracle:?}; case {context:?}"
    );
    assert!(
        !s.is_nan() && !d.is_nan(),
        "{what} ({name}): NaN bound {bound:?}; case {context:?}"
    );
    assert!(
        s >= 0.0 && d >= 0.0,
        "{what} ({name}): negative bound {bound:?}; case {context:?}"
    );
    assert!(
        ge_scaled(s, e, sup),
        "{what} ({name}): speed bound {s:e} ({s:?}) below the exact sup {:e} (2^{} x {sup:?}); oracle {oracle:?}; case {context:?}",
        oracle.sup_unscaled(),
        -e
    );
    // sup * length, with the length brought to [1, 2) so nothing underflows
    let len = oracle.length.to_f64();
    let le = if len > 0.0 { ilogb(len) } else { 0 };
    let prod = oracle.sup.mul(scale_r(oracle.length, -le)).to_f64();
    assert!(
        ge_scaled(d, e - le, prod),
        "{what} ({name}): displacement bound {d:e} ({d:?}) below the exact sup * length {:e} (2^{} x {prod:?}); oracle {oracle:?}; case {context:?}",
        ldexp(prod, le - e),
        le - e
    );
}

/// The one-sided oracle: `rates = (along +n, along -n)` are not NaN and at
/// least the exact largest signed speeds (which may be negative), compared
/// exactly on exponents as in [`check_sound`].
pub fn check_one_sided<T: Precision>(
    what: &str,
    oracle: &Oracle<T>,
    rates: (T, T),
    context: &dyn Debug,
) {
    let name = T::NAME;
    let e = oracle.scaled.speed_exp;
    for (side, rate, sup) in [
        ("+n", rates.0, oracle.sup_signed.0),
        ("-n", rates.1, oracle.sup_signed.1),
    ] {
        let (x, y) = (rate.to_f64(), sup.to_f64());
        assert!(
            !x.is_nan() && !y.is_nan(),
            "{what} ({name}) along {side}: NaN rate {x:?} or oracle {y:?}; case {context:?}"
        );
        let ok = if x >= 0.0 {
            // rate >= sup 2^-e
            ge_scaled(x, e, y)
        } else {
            // a negative rate needs a negative sup at least as far below 0:
            // |sup| 2^-e >= |rate|
            y < 0.0 && ge_scaled(-y, -e, -x)
        };
        assert!(
            ok,
            "{what} ({name}) along {side}: one-sided rate {x:e} ({x:?}) below the exact signed sup {:e} (2^{} x {y:?}); oracle {oracle:?}; case {context:?}",
            ldexp(y, -e),
            -e
        );
    }
}

#[cfg(test)]
mod tests {
    use super::{check_sound, ge_scaled, ilogb, ldexp, pow2, Oracle};
    use crate::{seeds, Precision};
    use motion_bound::reference::Real;
    use motion_bound::testkit::Case;
    use motion_bound::{DirectedBound, Point3, RigidMotion, Vec3};
    use std::panic::{catch_unwind, AssertUnwindSafe};

    /// `true` if `check_sound` accepts `speed` and `displacement`.
    fn accepts<T: Precision>(
        case: &Case<T>,
        oracle: &Oracle<T>,
        speed: T,
        displacement: T,
    ) -> bool {
        let bound = DirectedBound::new(speed, displacement);
        let hook = std::panic::take_hook();
        std::panic::set_hook(Box::new(|_| {})); // the rejections are expected
        let ok = catch_unwind(AssertUnwindSafe(|| {
            check_sound("test", oracle, bound, case)
        }))
        .is_ok();
        std::panic::set_hook(hook);
        ok
    }

    /// The oracle separates the exact values from their neighbours one ulp
    /// below: `check_sound` accepts the next representable value above the
    /// exact supremum (and sup * length) and rejects the one below.
    fn separates<T: Precision>(case: &Case<T>) {
        let oracle = Oracle::new(case);
        let sup = T::from_f64(oracle.sup_unscaled());
        let sl = oracle.sup.mul(oracle.length).to_f64();
        let sl = T::from_f64(ldexp(sl, -oracle.scaled.speed_exp));
        let big = T::MAX;
        assert!(sup > T::ZERO && sl > T::ZERO, "a moving case: {oracle:?}");
        assert!(
            accepts(case, &oracle, sup.next_up(), big),
            "speed ulp above"
        );
        assert!(
            !accepts(case, &oracle, sup.next_down(), big),
            "speed ulp below"
        );
        assert!(
            accepts(case, &oracle, big, sl.next_up()),
            "displacement ulp above"
        );
        assert!(
            !accepts(case, &oracle, big, sl.next_down()),
            "displacement ulp below"
        );
    }

    /// The same case with lengths times `2^e`, speeds times `2^(e + b)` and
    /// times times `2^-b`.
    fn rescaled(case: &Case<f64>, e: i32, b: i32) -> Case<f64> {
        let m = &case.motion;
        let iv = m.interval();
        let motion = RigidMotion::try_new(
            Point3::ORIGIN,
            Vec3::from_array(m.linear().to_array().map(|x| ldexp(x, e + b))),
            Vec3::from_array(m.angular().to_array().map(|x| ldexp(x, b))),
            motion_bound::TimeInterval::try_new(ldexp(iv.start(), -b), ldexp(iv.end(), -b))
                .unwrap(),
        )
        .unwrap()
        .with_orientation(m.orientation())
        .try_with_local_centre(Vec3::from_array(
            m.local_centre().to_array().map(|x| ldexp(x, e)),
        ))
        .unwrap();
        Case {
            vertices: case
                .vertices
                .iter()
                .map(|r| r.map(|x| ldexp(x, e)))
                .collect(),
            motion,
            n: case.n,
        }
    }

    #[test]
    fn the_oracle_separates_the_exact_value_from_one_ulp_below() {
        let spec = seeds::base_spec();
        separates(&spec.build::<f32>().unwrap());
        let case = spec.build::<f64>().unwrap();
        separates(&case);
        // where the unscaled double-double oracle failed: tiny bodies and
        // speeds (squares underflow), and sweeps whose angles are subnormal
        separates(&rescaled(&case, -1000, 0));
        separates(&rescaled(&case, -600, -300));
        separates(&rescaled(&case, 400, 100));
        // a velocity of 2^60 along a component 2^-1000 of n, a body of
        // 2^-960: the rescaled velocity would be 2^1000 (dropped from the
        // rescaled case; the oracle takes the linear term from the original)
        let motion =
            RigidMotion::try_from_arrays([0.0; 3], [pow2(60), 3.0, 0.0], [0.0, 0.0, 1.0]).unwrap();
        let tiny = Case {
            vertices: vec![[pow2(-960), 0.0, 0.0], [0.0, 3.0 * pow2(-961), 0.0]],
            motion,
            n: motion_bound::Direction::try_from_array([pow2(-1000), 0.0, 1.0]).unwrap(),
        };
        assert!(!super::Scaled::new(&tiny).faithful, "v' dropped");
        separates(&tiny);
    }

    #[test]
    fn exponent_helpers_are_exact() {
        for e in [-1074, -1073, -1023, -1022, -1, 0, 1, 1023] {
            assert_eq!(ilogb(pow2(e)), e, "ilogb(2^{e})");
        }
        assert_eq!(ilogb(3.0), 1, "ilogb(3)");
        assert_eq!(ilogb(f64::MAX), 1023, "ilogb(MAX)");
        assert_eq!(ldexp(1.0, -1075), 0.0, "eta / 2 rounds to even");
        assert_eq!(ldexp(3.0, -1075), pow2(-1073), "3/2 eta rounds to 2 eta");
        assert_eq!(ldexp(pow2(-1074), 2000), pow2(926), "up from a subnormal");
        assert_eq!(
            ldexp(f64::MAX, -2000),
            f64::MAX * pow2(-1000) * pow2(-1000),
            "down"
        );
        assert!(ge_scaled(pow2(-1074), 2000, pow2(926)), "equal");
        assert!(
            !ge_scaled(pow2(-1074), 2000, pow2(926) * (1.0 + f64::EPSILON)),
            "just above"
        );
        assert!(
            ge_scaled(1.5, -1074, pow2(-1074)),
            "below the subnormal grid"
        );
        assert!(
            ge_scaled(1.5, 0, 1.5) && !ge_scaled(1.5, 0, 1.5000001),
            "mantissas"
        );
        assert!(ge_scaled(0.0, 5, 0.0) && !ge_scaled(0.0, 5, 1e-300), "zero");
        assert!(ge_scaled(f64::INFINITY, -5000, f64::MAX), "infinity");
    }
}
