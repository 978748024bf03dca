//! Certified rounding margins, each a formula in the unit roundoff `u`.
//!
//! The derivations are in `proofs/floating-point.md`; every constant here
//! names its section there. Notation: `u` is [`Float::UNIT_ROUNDOFF`]
//! (`2^-53` for `f64`, `2^-24` for `f32`), `eta` is [`Float::ETA`], and
//! `gamma_k = k u / (1 - k u)` is Higham's constant for `k` chained roundings.

use crate::Float;

/// An upper bound of `gamma_k = k u / (1 - k u)`: `(k + 1) u`, valid whenever
/// `k (k + 1) u <= 1` (so for every `k` used here in both precisions), and
/// computed exactly (a small integer times a power of two).
#[inline]
#[must_use]
pub(crate) fn gamma<T: Float>(k: u32) -> T {
    T::from_u32(k + 1) * T::UNIT_ROUNDOFF
}

/// Section "Summary": the factor that rounds the computed largest radius up,
/// `R^ = fl(sqrt(max fl(|r_i|^2))) (1 + gamma_5) + 2 sqrt(eta)`.
#[inline]
#[must_use]
pub(crate) fn radius_up<T: Float>(max_sq: T) -> T {
    max_sq.sqrt() * (T::ONE + gamma::<T>(5)) + T::TWO * T::SQRT_ETA_UP
}

/// Section "Summary": the radius of a ball of computed centre `s` holding
/// points `v_i`, from `max_sq = max_i fl(|fl(v_i - s)|^2)`: the subtraction
/// errs by at most `u |v_i - s|` per component, so `|v_i - s| <= |fl(v_i - s)| / (1 - u)`,
/// covered by the extra factor: `radius_up(max_sq) (1 + gamma_2)`.
#[inline]
#[must_use]
pub(crate) fn offset_radius_up<T: Float>(max_sq: T) -> T {
    radius_up(max_sq) * (T::ONE + gamma::<T>(2))
}

/// Section "Linear term": `|v.n| <= |fl(v.n)| + gamma_4 * fl(sum |v_k n_k|)`.
#[inline]
#[must_use]
pub(crate) fn linear_up<T: Float>(a: T, a_mag: T) -> T {
    a.abs() + gamma::<T>(4) * a_mag
}

/// Section "NEVQ": `|n x w| R <= fl|n x w| R^ (1 + gamma_3) + 2 gamma_2 |w|_1 R^`
/// plus the underflow term `2 sqrt(eta) R^ + 4 eta (1 + R^)`.
#[inline]
#[must_use]
pub(crate) fn nevq_rotational_up<T: Float>(c_norm: T, w_l1: T, r_hat: T) -> T {
    c_norm * r_hat * (T::ONE + gamma::<T>(3))
        + T::TWO * gamma::<T>(2) * w_l1 * r_hat
        + T::TWO * T::SQRT_ETA_UP * r_hat
        + T::from_u32(4) * T::ETA_NORMAL * (T::ONE + r_hat)
}

/// Section "EVQ": with `E^` the computed extremal value and `theta_m` the
/// largest `|angle|` at the interval ends,
/// `|c| E <= fl|c| E^ (1 + gamma_8) + fl|c| R^ u (48 + 12 theta_m)
///           + 24 u |w|_1 R^ + 2 sqrt(eta)(R^ + fl|c|) + 16 eta (1 + R^)(1 + fl|c|)`.
#[inline]
#[must_use]
pub(crate) fn evq_rotational_up<T: Float>(c_norm: T, e_hat: T, theta_m: T, w_l1: T, r_hat: T) -> T {
    let u = T::UNIT_ROUNDOFF;
    c_norm * e_hat * (T::ONE + gamma::<T>(8))
        + c_norm * r_hat * (u * (T::from_u32(48) + T::from_u32(12) * theta_m))
        + T::from_u32(24) * u * w_l1 * r_hat
        + T::TWO * T::SQRT_ETA_UP * (r_hat + c_norm)
        + T::from_u32(16) * T::ETA_NORMAL * (T::ONE + r_hat) * (T::ONE + c_norm)
}

/// Section "One-sided": twice the error bound of one computed endpoint value
/// `f = u . q` of the EVQ scan, times `|c|`, for points within `R^` of the
/// rotation centre: `|c| tau R^ = 2 ((48 + 12 theta_m) u fl|c| + 24 u |w|_1) R^`,
/// rounded up. The one-sided scan's decision `fl|c| (f_a + f_b) >= -|c| tau R^`
/// then never misses an arc that reaches `+q`.
#[inline]
#[must_use]
pub(crate) fn one_sided_decision_slack<T: Float>(c_norm: T, theta_m: T, w_l1: T, r_hat: T) -> T {
    let u = T::UNIT_ROUNDOFF;
    let t = T::TWO
        * ((T::from_u32(48) + T::from_u32(12) * theta_m) * u * c_norm + T::from_u32(24) * u * w_l1)
        * r_hat
        * (T::ONE + gamma::<T>(6));
    if t.is_nan() {
        T::INFINITY
    } else {
        t
    }
}

/// Section "One-sided": an upper bound of the signed speed along the exact
/// unit `n/|n|` from `fl(v.n) = a` (error magnitude `a_mag`), a signed
/// rotational estimate `rot` and the non-negative `margin` that bounds the
/// rotational estimate's error (so the exact rotational speed is at most
/// `rot + margin`, with `|rot|` also counted in `mag`):
/// `X = a + rot + margin + gamma_24 (a_mag + mag + margin)`, then times
/// `1 + gamma_6` if `X >= 0` and `1 - gamma_6` if not (the direction's
/// length, `1/|n| in [1 - gamma_5, 1 + gamma_5]`). NaN gives `+inf`.
#[inline]
#[must_use]
pub(crate) fn one_sided_up<T: Float>(a: T, a_mag: T, rot: T, mag: T, margin: T) -> T {
    let x = a + rot + margin + gamma::<T>(24) * (a_mag + mag + margin);
    let x = if x >= T::ZERO {
        x * (T::ONE + gamma::<T>(6))
    } else {
        x * (T::ONE - gamma::<T>(6))
    };
    if x.is_nan() {
        T::INFINITY
    } else {
        x
    }
}

/// Section "Orientation": an upper bound of the spectral norm of the
/// difference between a [`Rotation`](crate::Rotation)'s computed matrix and
/// the exact rotation of its exactly normalised quaternion,
/// `||M - Q|| <= 80 u` (plus `16 eta` for components that underflow).
#[inline]
#[must_use]
pub(crate) fn orientation_error<T: Float>() -> T {
    T::from_u32(80) * T::UNIT_ROUNDOFF
}

/// Section "Orientation": the coefficient `k` of the frame margin `k R` that
/// the EVQ bounds (absolute and one-sided) add for points within `R` (the
/// lever radius, `|r - c| <= R`) of the rotation centre, when they are
/// evaluated with the body-frame `fl(M^T n)` and `fl(M^T w)` of an oriented
/// motion, and with the points' offsets `fl(r - c)` from a rotation centre
/// `c` off the body origin:
/// `k = u W ((192 + 96 theta_m) [oriented] + 2 [offset]) (1 + gamma_4) + 8 eta`,
/// with `W = fl(|M^T w|_1)` and `theta_m` the arc's largest angle. `0` when
/// neither applies (the bounds are then exactly those of the world frame).
#[inline]
#[must_use]
pub(crate) fn frame_margin_up<T: Float>(w_l1: T, theta_m: T, oriented: bool, offset: bool) -> T {
    let turned = if oriented {
        T::from_u32(192) + T::from_u32(96) * theta_m
    } else {
        T::ZERO
    };
    let c = turned + if offset { T::TWO } else { T::ZERO };
    if c == T::ZERO {
        return T::ZERO;
    }
    let k = T::UNIT_ROUNDOFF * w_l1 * c * (T::ONE + gamma::<T>(4)) + T::from_u32(8) * T::ETA_NORMAL;
    if k.is_nan() {
        T::INFINITY
    } else {
        k
    }
}

/// `proofs/12-shapes.md`, Lemma 12.5: an upper bound of `|w x Q0 y|`, the
/// rate at which a body's `y` axis turns (`Q0` the exact start orientation,
/// `y` the body's unit `y` axis), from the computed body-frame angular
/// velocity `wb = fl(M^T w)` and the computed world `w_l1 = fl(|w|_1)`:
/// `|w_b x y| = sqrt(w_bx^2 + w_bz^2) <= |w_bx| + |w_bz|`, the sum of two
/// absolute values rounded up by one `next_up`; for an oriented motion plus
/// the frame error `|fl(M^T w) - Q0^T w| <= 86 u |w| + 32 eta` (Lemma O.2's
/// matrix and product errors, `|w| <= |w|_1 <= w_l1 (1 + gamma_2)`), taken
/// as `next_up(96 u w_l1) + 32 eta`. `+inf` for a NaN.
#[inline]
#[must_use]
pub(crate) fn axis_tilt_up<T: Float>(wb: [T; 3], w_l1: T, oriented: bool) -> T {
    let tilt = (wb[0].abs() + wb[2].abs()).next_up();
    let tilt = if oriented {
        let err =
            (T::from_u32(96) * T::UNIT_ROUNDOFF * w_l1).next_up() + T::from_u32(32) * T::ETA_NORMAL;
        (tilt + err).next_up()
    } else {
        tilt
    };
    if tilt.is_nan() {
        T::INFINITY
    } else {
        tilt
    }
}

/// Section "Orientation": a lever radius `(r_hat + c_hat)(1 + gamma_2)` that
/// bounds `|r - c|` for every point within `r_hat` of the body origin and a
/// rotation centre `c` within `c_hat` of it; exactly `r_hat` when `c_hat = 0`.
#[inline]
#[must_use]
pub(crate) fn lever_up<T: Float>(r_hat: T, c_hat: T) -> T {
    if c_hat == T::ZERO {
        r_hat
    } else {
        sum_up(r_hat, c_hat)
    }
}

/// Section "Assembly": the final factor `1 + gamma_16` covers the direction's
/// normalisation (`1/|n| <= 1 + gamma_5`) and the rounding of the evaluation
/// of the non-negative margin expression (at most 10 operations). A NaN can
/// only arise from an overflowed intermediate; it is returned as `+inf`, the
/// sound answer.
#[inline]
#[must_use]
pub(crate) fn assemble<T: Float>(linear: T, rotational: T) -> T {
    let mu = (linear + rotational) * (T::ONE + gamma::<T>(16));
    if mu.is_nan() {
        T::INFINITY
    } else {
        mu
    }
}

/// Section "Displacement": `integral <= sup * (t_b - t_a)` rounded up,
/// `fl(fl(s * fl(t_b - t_a)) (1 + gamma_3)) + eta`.
#[inline]
#[must_use]
pub(crate) fn displacement_up<T: Float>(speed: T, length: T) -> T {
    if length == T::ZERO {
        return T::ZERO;
    }
    let d = speed * length * (T::ONE + gamma::<T>(3)) + T::ETA_NORMAL;
    if d.is_nan() {
        T::INFINITY
    } else {
        d
    }
}

/// `proofs/floating-point.md`, sections "Pose" and "Orientation": an upper
/// bound of the distance between a body point placed by [`Pose`](crate::Pose)
/// in floating point (`RigidMotion::pose_at` then `transform_point`) and its
/// exact position, `delta <= u ((8 |a| + K) R + 8 P) + 8 eta`, for a body
/// point within `R` of its rotation centre (the lever radius), rotated by the
/// angle `a = |w| t`, whose rotation centre lies within `P >= |x0| + |v| |t|`
/// of the origin (plus `|c|` for a rotation centre `c` off the body origin),
/// with `K = pose_rotation_constant(oriented)`: `96` for the identity start
/// orientation, `192` with a start orientation (its matrix's error and the
/// product's rounding). Rounded up by its own `1 + gamma_8`.
#[inline]
#[must_use]
pub(crate) fn pose_error_up<T: Float>(angle: T, radius: T, centre_reach: T, oriented: bool) -> T {
    let u = T::UNIT_ROUNDOFF;
    let e = u
        * ((T::from_u32(8) * angle.abs() + pose_rotation_constant::<T>(oriented)) * radius
            + T::from_u32(8) * centre_reach)
        + T::from_u32(8) * T::ETA_NORMAL;
    let e = e * (T::ONE + gamma::<T>(8));
    if e.is_nan() {
        T::INFINITY
    } else {
        e
    }
}

/// Sections "Pose" and "Orientation": the constant `K` of the rotation's
/// error `||P^ - R(a) Q0|| <= u (6 |a| + K - 12)` and of [`pose_error_up`]:
/// `96` without a start orientation, `192` with one (its matrix errs by
/// `80 u`, the product `fl(R^ M)` by `12 u`).
#[inline]
#[must_use]
pub(crate) fn pose_rotation_constant<T: Float>(oriented: bool) -> T {
    T::from_u32(if oriented { 192 } else { 96 })
}

/// Section "Box": an upper bound of the exact support `sum_k h_k |(R^T n)_k|`
/// of a body-frame box of half extents `h` placed by the computed rotation,
/// from the computed `supp^ = fl(sum_k h_k |fl(R^T n)_k|)`:
/// `supp^ (1 + gamma_4) + pose_error_up(angle, |h|_1, 0) + gamma_8 |h|_1`.
#[cfg(test)]
#[inline]
#[must_use]
pub(crate) fn box_support_up<T: Float>(supp: T, half_l1: T, angle: T, oriented: bool) -> T {
    supp * (T::ONE + gamma::<T>(4))
        + pose_error_up(angle, half_l1, T::ZERO, oriented)
        + gamma::<T>(8) * half_l1
}

/// Section "Oriented box": `box_support_up` with its angle-dependent part
/// computed once per placement. With `k = (u (8 |a| + K)(1 + gamma_8) + gamma_8)(1 + gamma_12)`
/// (`K` from [`pose_rotation_constant`])
/// and `k0 = 32 eta`, `supp^ (1 + gamma_7) + w k + k0` is at least
/// `box_support_up(supp^, w, a)` evaluated exactly (the extra factors cover
/// the evaluation of `k` and of the three-term sum), so the same bound holds.
#[cfg(feature = "alloc")]
#[derive(Clone, Copy, Debug)]
pub(crate) struct BoxError<T> {
    k: T,
    k0: T,
}

#[cfg(feature = "alloc")]
impl<T: Float> BoxError<T> {
    /// The coefficients for a rotation by the angle `angle`, after a start
    /// orientation if `oriented`.
    #[inline]
    pub(crate) fn new(angle: T, oriented: bool) -> Self {
        let u = T::UNIT_ROUNDOFF;
        let k = (u
            * (T::from_u32(8) * angle.abs() + pose_rotation_constant::<T>(oriented))
            * (T::ONE + gamma::<T>(8))
            + gamma::<T>(8))
            * (T::ONE + gamma::<T>(12));
        Self {
            k: if k.is_nan() { T::INFINITY } else { k },
            k0: T::from_u32(32) * T::ETA_NORMAL,
        }
    }

    /// An upper bound of the exact support from the computed `supp^` and the
    /// weight `w` (as [`box_support_up`]).
    #[inline]
    pub(crate) fn support_up(&self, supp: T, weight: T) -> T {
        supp * (T::ONE + gamma::<T>(7)) + weight * self.k + self.k0
    }
}

/// Section "Gap": a lower bound of the exact slab gap along the exact unit
/// direction `n/|n|`, from a computed gap `g^ = min_B fl(q.n) - max_A fl(p.n)`
/// over placed points within `reach` of the origin, each placed with error at
/// most `pose_err_a`, `pose_err_b`:
/// `(g^ - pose_err_a - pose_err_b - gamma_8 reach_sum)(1 + gamma_3) (1 - gamma_7)`
/// rounded down; `<= 0` means "not separated along n".
#[inline]
#[must_use]
pub(crate) fn gap_down<T: Float>(gap: T, pose_err_a: T, pose_err_b: T, reach_sum: T) -> T {
    let slack = gap_slack_up(pose_err_a, pose_err_b, reach_sum);
    let g = (gap - slack) * (T::ONE - gamma::<T>(7));
    if g.is_nan() {
        -T::INFINITY
    } else {
        g
    }
}

/// Section "Gap": what [`gap_down`] subtracts from a computed gap,
/// `(delta_A + delta_B + gamma_8 (P_A + P_B))(1 + gamma_3)`.
#[inline]
#[must_use]
pub(crate) fn gap_slack_up<T: Float>(pose_err_a: T, pose_err_b: T, reach_sum: T) -> T {
    (pose_err_a + pose_err_b + gamma::<T>(8) * reach_sum) * (T::ONE + gamma::<T>(3))
}

/// Section "Resolution": the length below which a step cannot resolve
/// distances: what the certified gap loses ([`gap_slack_up`]) plus
/// `4 sqrt(eta)`, the most by which two bodies' bounding balls can be
/// widened when their squared radii underflow (section "Summary").
/// Not a margin: it only decides when a query reports
/// [`CaOutcome::PrecisionLimit`](crate::ca::CaOutcome::PrecisionLimit).
#[inline]
#[must_use]
pub(crate) fn resolution_up<T: Float>(pose_err_a: T, pose_err_b: T, reach_sum: T) -> T {
    gap_slack_up(pose_err_a, pose_err_b, reach_sum) + T::from_u32(4) * T::SQRT_ETA_UP
}

/// Section "Resolution": the least reach of a body whose bounds this crate
/// resolves, `2^8 * 2 sqrt(eta)` (about `1.1e-159` in `f64`, `2.7e-20` in
/// `f32`): below it the underflow allowance `2 sqrt(eta)` of every radius
/// (section "Summary") is more than `1/256` of the body, its balls and
/// speed bounds are dominated by it, and a mesh query reports
/// [`CaOutcome::PrecisionLimit`](crate::ca::CaOutcome::PrecisionLimit) at once.
#[cfg(feature = "alloc")]
#[inline]
#[must_use]
pub(crate) fn least_resolved_reach<T: Float>() -> T {
    T::from_u32(512) * T::SQRT_ETA_UP
}

/// Section "Step": a time step no longer than `(gap - clearance) / (mu_a + mu_b)`,
/// the longest step over which points moving along `n` at speeds at most
/// `mu_a` and `mu_b` cannot close a gap `gap` to `clearance`:
/// `fl(fl(fl(gap - clearance) / fl((mu_a + mu_b)(1 + gamma_2))) (1 - gamma_3))`.
/// `+inf` when nothing closes (`mu_a + mu_b <= 0`: one-sided rates may be
/// negative); `0` when the gap is at most the clearance, or for a NaN.
#[inline]
#[must_use]
pub(crate) fn step_down<T: Float>(gap: T, clearance: T, mu_a: T, mu_b: T) -> T {
    let gap = gap - clearance;
    if gap.is_nan() || gap <= T::ZERO {
        return T::ZERO;
    }
    let mu = (mu_a + mu_b) * (T::ONE + gamma::<T>(2));
    if mu.is_nan() {
        return T::ZERO;
    }
    // One-sided rates may be negative: a pair that cannot close over the
    // bounds' interval has no limit on its step (`proofs/10-one-sided.md`).
    if mu <= T::ZERO {
        return T::INFINITY;
    }
    let s = gap / mu * (T::ONE - gamma::<T>(3));
    if s.is_nan() {
        T::ZERO
    } else {
        s
    }
}

/// Section "Exact sums": Knuth's TwoSum, `a + b = hi + lo` exactly with
/// `hi = fl(a + b)`, for finite `a`, `b` whose rounded sum is finite (six
/// additions, no branch; exact also in the subnormal range, where additions
/// are exact).
#[inline]
#[must_use]
pub(crate) fn two_sum<T: Float>(a: T, b: T) -> (T, T) {
    let hi = a + b;
    let bb = hi - a;
    let lo = (a - (hi - bb)) + (b - bb);
    (hi, lo)
}

/// Section "Pair frame": the slack of a centre moved into a pair's frame,
/// `s' = (s + |lo_x| + |lo_y| + |lo_z|)(1 + gamma_3)` from the previous
/// slack `s >= 0` and TwoSum's exact residuals `lo` of the centre's three
/// differences: at least `s + |lo|_2`, the distance of the stored centre
/// from the exact one. Exactly `s` when every residual is zero.
#[inline]
#[must_use]
pub(crate) fn rebase_slack_up<T: Float>(slack: T, lo: [T; 3]) -> T {
    if lo == [T::ZERO; 3] {
        return slack;
    }
    (slack + lo[0].abs() + lo[1].abs() + lo[2].abs()) * (T::ONE + gamma::<T>(3))
}

/// Section "Exact sums": whether `t + step >= end` holds in exact arithmetic
/// (`t`, `end` finite; `step >= 0` or `+inf`; NaN is `false`). This is how
/// the driver decides that a certified step reaches the interval's end.
#[inline]
#[must_use]
pub(crate) fn sum_reaches<T: Float>(t: T, step: T, end: T) -> bool {
    if step.is_nan() {
        return false;
    }
    let (hi, lo) = two_sum(t, step);
    // An overflowed sum (or `step = +inf`) exceeds every finite `end`.
    if !hi.is_finite() {
        return hi > T::ZERO;
    }
    hi > end || (hi == end && lo >= T::ZERO)
}

/// Section "Exact sums": the largest float at most `t + step` in exact
/// arithmetic (`t` finite, `step >= 0` finite with a finite sum): the rounded
/// sum, moved down one ulp only when rounding went up.
#[inline]
#[must_use]
pub(crate) fn advance_down<T: Float>(t: T, step: T) -> T {
    let (hi, lo) = two_sum(t, step);
    if lo < T::ZERO {
        hi.next_down()
    } else {
        hi
    }
}

/// Section "Exact sums": a float at least `end - t` in exact arithmetic (the
/// rounded difference, moved up one ulp only when rounding went down), for
/// finite `end >= t`.
#[inline]
#[must_use]
pub(crate) fn diff_up<T: Float>(end: T, t: T) -> T {
    let (hi, lo) = two_sum(end, -t);
    if lo > T::ZERO {
        hi.next_up()
    } else {
        hi
    }
}

/// Section "Exact sums": a float at most `end - t` in exact arithmetic.
#[inline]
#[must_use]
pub(crate) fn diff_down<T: Float>(end: T, t: T) -> T {
    let (hi, lo) = two_sum(end, -t);
    if lo < T::ZERO {
        hi.next_down()
    } else {
        hi
    }
}

/// Section "Ball": an upper bound of the exact sum `a + b` of two
/// non-negative values, `fl(fl(a + b)(1 + gamma_2))`
/// (`(1 - u)^2 (1 + 3u) >= 1`): one addition more than an analysis budgets.
#[inline]
#[must_use]
pub(crate) fn sum_up<T: Float>(a: T, b: T) -> T {
    (a + b) * (T::ONE + gamma::<T>(2))
}

/// Section "Pose": `P >= |x0| + |v| |t|` for the rotation centre's
/// position at `t`, from the 1-norms (which dominate the 2-norms):
/// `fl((|x0|_1 + |v|_1 |t|)(1 + gamma_4))` covers the three roundings.
#[inline]
#[must_use]
pub(crate) fn centre_reach_up<T: Float>(x0_l1: T, v_l1: T, t: T) -> T {
    (x0_l1 + v_l1 * t.abs()) * (T::ONE + gamma::<T>(4))
}

/// Section "Gap": the reach of every placed point, `|x(t)| + R` plus the
/// placement error `err`: `fl(fl(P + R)(1 + gamma_2)) + err`, then the last
/// addition's rounding is covered by `err`'s own `1 + gamma_8`.
#[inline]
#[must_use]
pub(crate) fn placed_reach_up<T: Float>(centre_reach: T, lever: T, err: T) -> T {
    sum_up(centre_reach, lever) + err
}

/// `proofs/09-ca-toi.md`, Lemma 9.2: the crude, direction-free bound of the
/// speed of every point within `lever` of the rotation centre,
/// `|v| + |w| lever <= |v|_1 + |w|_1 lever`, rounded up (at most five
/// roundings, covered by `1 + gamma_8`).
#[cfg(feature = "alloc")]
#[inline]
#[must_use]
pub(crate) fn crude_speed_up<T: Float>(v_l1: T, w_l1: T, lever: T) -> T {
    (v_l1 + w_l1 * lever) * (T::ONE + gamma::<T>(8))
}

/// Section "Oriented box": the residual radius of a fitted box,
/// `rho = fl((radius_up(max |r^|^2) + gamma_6 fl(sum_j m_j) + 16 eta)(1 + gamma_2))`,
/// then times `1 + gamma_7` for the length of the computed direction the
/// support is taken along (`|n| <= 1 + gamma_5`).
#[cfg(feature = "alloc")]
#[inline]
#[must_use]
pub(crate) fn box_residual_up<T: Float>(max_sq: T, max_mag: T) -> T {
    let rho = (radius_up(max_sq) + gamma::<T>(6) * max_mag + T::from_u32(16) * T::ETA_NORMAL)
        * (T::ONE + gamma::<T>(2));
    rho * (T::ONE + gamma::<T>(7))
}

/// Section "Oriented box": the error weight `2 |h|_1` of a box's support
/// bound, rounded up.
#[cfg(feature = "alloc")]
#[inline]
#[must_use]
pub(crate) fn box_weight_up<T: Float>(half_sum: T) -> T {
    T::TWO * half_sum * (T::ONE + gamma::<T>(2))
}

/// Section "Oriented box": an upper bound of `|c| + sum_k h_k |u_k| + rho`
/// from the rounded-up `|c|` and the rounded-up sum of the other terms
/// (`1 + gamma_6` covers the additions).
#[cfg(feature = "alloc")]
#[inline]
#[must_use]
pub(crate) fn box_reach_up<T: Float>(centre_up: T, extent_up: T) -> T {
    (centre_up + extent_up) * (T::ONE + gamma::<T>(6))
}

/// Section "GJK": `rho >= max_i |r_i|_1` from the computed 1-norms
/// (`fl(|r|_1)` may fall short by `gamma_2 |r|_1`).
#[inline]
#[must_use]
pub(crate) fn polytope_radius_up<T: Float>(max_l1: T) -> T {
    max_l1 * (T::ONE + gamma::<T>(3))
}

/// Section "GJK": the support slack of a placed polytope,
/// `4 gamma_4 (6 m rho + x)(1 + gamma_8) + 64 eta (1 + m)(1 + rho)`, with `m`
/// the largest `|R_kl|`, `rho` the vertices' largest 1-norm and `x` the
/// translation's largest component.
#[inline]
#[must_use]
pub(crate) fn polytope_support_slack<T: Float>(m: T, rho: T, x: T) -> T {
    let six = T::from_u32(6);
    T::from_u32(4) * gamma::<T>(4) * (six * m * rho + x) * (T::ONE + gamma::<T>(8))
        + T::from_u32(64) * T::ETA_NORMAL * (T::ONE + m) * (T::ONE + rho)
}

/// Section "GJK": a certified lower bound of the separation
/// `min (b - a) . n` of two support maps along a computed unit `n` from the
/// computed difference `delta = fl(beta - alpha)` of their supports' dot
/// products, the dot products' magnitudes `mags = sum |s_k n_k|` (both
/// supports) and the maps' own slacks: `delta - M` with
/// `M = fl((u |delta| + gamma_3 mags + slack (1 + gamma_4))(1 + gamma_4)) + 8 eta`,
/// rounded down by `1 - gamma_8` (the subtraction and the division by
/// `|n| <= 1 + gamma_6`); `0` when not positive.
#[inline]
#[must_use]
pub(crate) fn separation_down<T: Float>(delta: T, mags: T, slacks: T) -> T {
    let slack = slacks * (T::ONE + gamma::<T>(4));
    let m = (T::UNIT_ROUNDOFF * delta.abs() + gamma::<T>(3) * mags + slack)
        * (T::ONE + gamma::<T>(4))
        + T::from_u32(8) * T::ETA_NORMAL;
    let sep = delta - m;
    if sep > T::ZERO {
        sep * (T::ONE - gamma::<T>(8))
    } else {
        T::ZERO
    }
}

/// Section "Meeting": the largest distance a triangle pair that meets may
/// be snapped from, `2^10 u s` with `s` the largest coordinate magnitude.
#[inline]
#[must_use]
pub(crate) fn snap_tolerance<T: Float>(scale: T) -> T {
    T::from_u32(1024) * T::UNIT_ROUNDOFF * scale
}

/// Section "Meeting": the rounding of a slab width `min_B q . n - max_A p . n`
/// over points within `s` (largest coordinate) along a computed `n`:
/// `16 u s |n|_1` (each dot product errs by `gamma_3 s |n|_1`).
#[inline]
#[must_use]
pub(crate) fn slab_rounding<T: Float>(scale: T, n_l1: T) -> T {
    T::from_u32(16) * T::UNIT_ROUNDOFF * scale * n_l1
}

/// Section "Meeting" (Lemma FP-M): Shewchuk's a-priori bound of the 3D
/// orientation determinant's error, `errboundA = (7 + 56 u) u` times the
/// permanent, plus `8 eta (1 + |a_z| + |b_z| + |c_z|)` for products that
/// underflow (Shewchuk 1997, section 4.2, his `epsilon` our `u`).
#[inline]
#[must_use]
pub(crate) fn orient3d_error<T: Float>(permanent: T, z_sum: T) -> T {
    let u = T::UNIT_ROUNDOFF;
    (T::from_u32(7) + T::from_u32(56) * u) * u * permanent
        + T::from_u32(8) * T::ETA_NORMAL * (T::ONE + z_sum)
}

/// Section "Meeting" (Lemma FP-M): the 2D orientation's bound,
/// `(3 + 16 u) u (|l| + |r|) + 4 eta`.
#[inline]
#[must_use]
pub(crate) fn orient2d_error<T: Float>(magnitude: T) -> T {
    let u = T::UNIT_ROUNDOFF;
    (T::from_u32(3) + T::from_u32(16) * u) * u * magnitude + T::from_u32(4) * T::ETA_NORMAL
}

/// Section "Summary": `x` (a non-negative finite `f64`) converted to `T`,
/// rounded up: the conversion rounds to nearest, so a result below `x` is
/// moved up by `y (1 + 2u)` (at least the next float for a normal `y`) plus
/// `eta` (for a subnormal or zero `y`).
#[cfg(feature = "alloc")]
#[inline]
#[must_use]
pub(crate) fn from_f64_up<T: Float>(x: f64) -> T {
    let y = T::from_f64(x);
    if y.to_f64() >= x {
        y
    } else {
        y * (T::ONE + T::TWO * T::UNIT_ROUNDOFF) + T::ETA_NORMAL
    }
}

/// Section "Swept box": a float at least the exact `a + b` of two finite
/// floats, `next_up(fl(a + b))` (round to nearest never errs by a whole ulp,
/// so the exact sum lies below the next float; gradual underflow included).
#[inline]
#[must_use]
pub(crate) fn add_up<T: Float>(a: T, b: T) -> T {
    (a + b).next_up()
}

/// Section "Swept box": a float at most the exact `a - b`,
/// `next_down(fl(a - b))`.
#[cfg(feature = "alloc")]
#[inline]
#[must_use]
pub(crate) fn sub_down<T: Float>(a: T, b: T) -> T {
    (a - b).next_down()
}

/// Section "Pieces": a float at least the exact `a b` of two finite
/// non-negative floats, `next_up(fl(a b))` (gradual underflow included).
#[inline]
#[must_use]
pub(crate) fn mul_up<T: Float>(a: T, b: T) -> T {
    (a * b).next_up()
}

/// Section "Pieces": an upper bound of the distance between a point
/// `wa a + wb b + wc c` of a triangle (dyadic weights `w >= 0` summing to
/// one, exact in `T`) and its computed `fl(fl(fl(wa a) + fl(wb b)) + fl(wc c))`,
/// from `l1 = fl(|a|_1 + |b|_1 + |c|_1)`:
/// `next_up(next_up(gamma_4 l1) + 16 eta_normal)`.
#[cfg(feature = "alloc")]
#[inline]
#[must_use]
pub(crate) fn piece_corner_error_up<T: Float>(l1: T) -> T {
    (mul_up(gamma::<T>(4), l1) + T::from_u32(16) * T::ETA_NORMAL).next_up()
}

/// Section "Pieces": the speed margin of points within `e` of the
/// computed corners of a piece, for an angular velocity whose computed
/// 1-norm is `w_l1`: `next_up(fl(2 w_l1) e)`, at least `|w| e`.
#[cfg(feature = "alloc")]
#[inline]
#[must_use]
pub(crate) fn piece_speed_margin_up<T: Float>(w_l1: T, e: T) -> T {
    mul_up(T::TWO * w_l1, e)
}

/// Section "Swept box": how far a body's points move along an axis over an
/// interval of length at most `length`, from their one-sided rate `rate`
/// along it: `next_up(fl(max(rate, 0) length))`, at least the exact product
/// (`0` when every point recedes: the extent then never grows).
#[cfg(feature = "alloc")]
#[inline]
#[must_use]
pub(crate) fn reach_along_up<T: Float>(rate: T, length: T) -> T {
    if rate > T::ZERO {
        (rate * length).next_up()
    } else if rate.is_nan() {
        T::INFINITY
    } else {
        T::ZERO
    }
}

#[cfg(test)]
mod tests {
    use super::gamma;

    #[test]
    fn box_error_dominates_box_support_up() {
        // `BoxError` is `box_support_up` with the angle's part hoisted: never
        // below it (the exact claim of `proofs/floating-point.md`,
        // "Oriented box"), for small and large angles, weights and supports.
        for oriented in [false, true] {
            for &a in &[0.0, 1e-9, 0.5, 3.0, 1e3, 1e12] {
                let e = super::BoxError::<f64>::new(a, oriented);
                for &w in &[0.0, 1e-300, 1e-8, 0.7, 1e6] {
                    for &s in &[0.0, 1e-12, 1.0, 3e5] {
                        let (new, old) =
                            (e.support_up(s, w), super::box_support_up(s, w, a, oriented));
                        assert!(new >= old, "a {a} w {w} s {s}: {new} < {old}");
                    }
                }
                let e = super::BoxError::<f32>::new(a as f32, oriented);
                let (new, old) = (
                    e.support_up(1.0, 0.5),
                    super::box_support_up(1.0f32, 0.5, a as f32, oriented),
                );
                assert!(new >= old, "f32 a {a}: {new} < {old}");
            }
        }
    }

    #[test]
    fn gamma_bound_dominates_the_exact_constant() {
        for k in 1..=64u32 {
            let u = 2f64.powi(-24);
            let exact = f64::from(k) * u / (1.0 - f64::from(k) * u);
            assert!(f64::from(gamma::<f32>(k)) >= exact, "k = {k}");
        }
    }
}
