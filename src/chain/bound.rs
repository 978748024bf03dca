//! The directed motion bound of a link of a chain moving along a
//! joint-space segment (`proofs/13-chains.md`).

use alloc::vec::Vec;

use crate::chain::model::{Chain, ChainError, JointFrame};
use crate::rounding::gamma;
use crate::{Float, Pose, Vec3};

/// One movable joint on a link's path, at the start `t` of a sub-interval
/// `[t, end]`: its world axis and a point on it, its rate `|q1_j - q0_j|`,
/// and `theta`, an upper bound of the angle its axis turns through over the
/// sub-interval (relative to the pair's frame).
#[derive(Clone, Copy, Debug)]
pub(crate) struct JointTerm<T> {
    pub(crate) axis: Vec3<T>,
    pub(crate) point: Vec3<T>,
    pub(crate) rate: T,
    pub(crate) theta: T,
    pub(crate) rotational: bool,
}

/// A link's motion over `[t, end]` as the bound needs it: the link's world
/// pose at `t`, its path's joints (those below the pair's common ancestor)
/// and the rounding allowances of `proofs/13-chains.md`, Lemma 13.3.
#[derive(Clone, Debug)]
pub(crate) struct LinkMotion<T> {
    pub(crate) pose: Pose<T>,
    /// Deepest joint last.
    pub(crate) terms: Vec<JointTerm<T>>,
    /// `end - t`, rounded up.
    pub(crate) dt: T,
    /// An upper bound of the distance between a computed placed point of
    /// the link and its exact place (`delta` of Lemma 13.3).
    pub(crate) delta: T,
    /// An upper bound of the angle between a computed world axis and the
    /// exact one (`epsilon_R` of Lemma 13.3).
    pub(crate) axis_err: T,
    /// An upper bound of `|p|` for every placed point of the link.
    pub(crate) reach: T,
}

impl<T: Float> LinkMotion<T> {
    /// A still body (an obstacle) placed by `pose`.
    pub(crate) fn still(pose: Pose<T>, delta: T, reach: T) -> Self {
        Self {
            pose,
            terms: Vec::new(),
            dt: T::ZERO,
            delta,
            axis_err: T::ZERO,
            reach,
        }
    }

    /// Fills `self` with link `link`'s motion over `[t, end]` of the segment
    /// with rates `rate[dof] = |q1 - q0|`, from the frames placed at `t`,
    /// counting only the path's joints after the first `skip` (those above a
    /// self-collision pair's common ancestor move both links rigidly).
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn fill(
        &mut self,
        chain: &Chain<T>,
        link: usize,
        poses: &[Pose<T>],
        frames: &[JointFrame<T>],
        rate: &[T],
        skip: usize,
        dt: T,
        errors: &LinkErrors<T>,
    ) {
        let data = &chain.links[link];
        self.pose = poses[link];
        self.dt = dt;
        self.delta = errors.delta[link];
        self.axis_err = errors.axis[link];
        self.reach = errors.reach[link];
        self.terms.clear();
        // The angle through which joint j's axis turns: the rates of the
        // turning joints above it (and below the common ancestor), times dt.
        let mut turned = T::ZERO;
        for &j in &data.path[skip.min(data.path.len())..] {
            let joint = &chain.joints[j];
            let Some(dof) = joint.dof else { continue };
            let r = rate[dof];
            self.terms.push(JointTerm {
                axis: frames[j].axis,
                point: frames[j].point,
                rate: r,
                theta: turned * dt * (T::ONE + gamma::<T>(2)),
                rotational: joint.spec.kind.is_rotational(),
            });
            if joint.spec.kind.is_rotational() {
                turned = (turned + r) * (T::ONE + T::UNIT_ROUNDOFF);
            }
        }
    }

    /// An upper bound of `|p'(s) . n|` over the sub-interval for every point
    /// `p` of the ball of world centre `c` (at `t`) and radius `rho`, with
    /// `n` a computed unit vector (Lemma 13.1, 13.2 and 13.3); and, second,
    /// an upper bound of `|p'(s)|` (the undirected speed,
    /// [`sweep_speed`](Self::sweep_speed)).
    pub(crate) fn ball_speed(&self, c: Vec3<T>, rho: T, n: Vec3<T>) -> (T, T) {
        let slack = T::TWO * self.delta;
        let mut v = T::ZERO;
        let mut mu = T::ZERO;
        for term in self.terms.iter().rev() {
            if term.rate == T::ZERO {
                continue;
            }
            if term.rotational {
                let dmax = self.lever(term, c, rho, slack) + self.dt * v;
                v += term.rate * dmax;
                let s = (n.cross(term.axis).length() * (T::ONE + gamma::<T>(8))
                    + term.theta
                    + self.axis_err)
                    .min_nan(T::ONE + gamma::<T>(8));
                mu += term.rate * s * dmax;
            } else {
                v += term.rate;
                let s = (n.dot(term.axis).abs() * (T::ONE + gamma::<T>(8))
                    + term.theta
                    + self.axis_err)
                    .min_nan(T::ONE + gamma::<T>(8));
                mu += term.rate * s;
            }
        }
        let k = self.speed_factor();
        (mu * k, v * k)
    }

    /// The second value of [`ball_speed`](Self::ball_speed) alone: an upper
    /// bound of `|p'(s)|` over the sub-interval for every point of the ball
    /// (what an edge query sweeps a ball by, Lemma 13.5).
    #[inline]
    pub(crate) fn sweep_speed(&self, c: Vec3<T>, rho: T) -> T {
        let slack = T::TWO * self.delta;
        let mut v = T::ZERO;
        for term in self.terms.iter().rev() {
            if term.rate == T::ZERO {
                continue;
            }
            if term.rotational {
                v += term.rate * (self.lever(term, c, rho, slack) + self.dt * v);
            } else {
                v += term.rate;
            }
        }
        v * self.speed_factor()
    }

    /// `dist(p, axis)` at `t` for every point `p` of the ball, from the
    /// computed centre, axis point and axis: each point is within `delta` of
    /// its exact place (`slack = 2 delta` for both), and the axis direction
    /// within `axis_err`, which moves the distance by up to
    /// `axis_err |c - o|` (Lemma 13.3).
    #[inline]
    fn lever(&self, term: &JointTerm<T>, c: Vec3<T>, rho: T, slack: T) -> T {
        let lever = c - term.point;
        (lever.cross(term.axis).length() + rho + slack + self.axis_err * lever.length())
            * (T::ONE + gamma::<T>(8))
    }

    /// The rounding factor of the speeds' sums.
    #[inline]
    fn speed_factor(&self) -> T {
        T::ONE + gamma::<T>(4 * self.terms.len() as u32 + 16)
    }
}

/// Per link, for one segment: the placement error `delta`, the world-axis
/// error `epsilon_R` and the reach of placed points (Lemma 13.3).
#[derive(Clone, Debug, Default)]
pub(crate) struct LinkErrors<T> {
    pub(crate) delta: Vec<T>,
    pub(crate) axis: Vec<T>,
    pub(crate) reach: Vec<T>,
}

impl<T: Float> LinkErrors<T> {
    /// Lemma 13.3 for the segment `q0 -> q1`, every link, with each link's
    /// points within its mesh's reach ([`link_errors`]).
    pub(crate) fn compute(&mut self, chain: &Chain<T>, q0: &[T], q1: &[T]) {
        let n = chain.links.len();
        self.delta.clear();
        self.axis.clear();
        self.reach.clear();
        for l in 0..n {
            let (delta, eps, reach) = link_errors(chain, q0, q1, l, chain.links[l].reach);
            self.delta.push(delta);
            self.axis.push(eps);
            self.reach.push(reach);
        }
    }
}

/// Lemma 13.3 for link `l` of a chain on the segment `q0 -> q1`, for the
/// link's points within `local_reach` of its frame's origin: `(delta,
/// epsilon_R, reach)`. For a link whose path from the root has `m` joints
/// (fixed ones included),
/// `epsilon_R = gamma_{128 (m + 1)} + sum over its turning joints of gamma_3 (|q0_j| + |q1_j - q0_j|) + eta_N`
/// and `delta = epsilon_R L + sum over its sliding joints of gamma_3 (|q0_j| + |q1_j - q0_j|) + 16 eta_N`,
/// `L = |x_base| + sum |o_j| + sum over sliding joints max(|q0_j|, |q1_j|) + local_reach`
/// (each rounded up); `reach = L + delta` bounds every placed point. Valid
/// while `m (m + 1) u <= 2^-9` (`m <= 180` in `f32`); deeper, `+inf`.
pub(crate) fn link_errors<T: Float>(
    chain: &Chain<T>,
    q0: &[T],
    q1: &[T],
    l: usize,
    local_reach: T,
) -> (T, T, T) {
    let base = chain.base.translation.length();
    let mut depth = 0u32;
    let mut q_rot = T::ZERO;
    let mut q_slide = T::ZERO;
    let mut slide_len = T::ZERO;
    let mut at = l;
    while let Some(j) = chain.links[at].parent_joint {
        depth += 1;
        let joint = &chain.joints[j];
        if let Some(dof) = joint.dof {
            let mag = q0[dof].abs() + (q1[dof] - q0[dof]).abs();
            if joint.spec.kind.is_rotational() {
                q_rot += mag;
            } else {
                q_slide += mag;
                slide_len += q0[dof].abs().max_nan(q1[dof].abs());
            }
        }
        at = joint.spec.parent;
    }
    let data = &chain.links[l];
    let len =
        (base + data.origin_reach + slide_len + local_reach) * (T::ONE + gamma::<T>(2 * depth + 4));
    // Second-order terms stay inside the constant's slack while
    // `m (m + 1) u <= 2^-9` (proofs/13-chains.md, Lemma 13.3).
    let too_deep = T::from_f64(f64::from(depth) * (f64::from(depth) + 1.0)) * T::UNIT_ROUNDOFF
        > T::from_f64(1.0 / 512.0);
    let eps = if too_deep {
        T::INFINITY
    } else {
        gamma::<T>(128 * (depth + 1))
            + gamma::<T>(3) * q_rot * (T::ONE + gamma::<T>(depth + 2))
            + T::ETA_NORMAL
    };
    let delta = (eps * len + gamma::<T>(3) * q_slide) * (T::ONE + gamma::<T>(4))
        + T::from_u32(16) * T::ETA_NORMAL;
    (delta, eps, len + delta)
}

impl<T: Float> Chain<T> {
    /// An upper bound of the directed speed `|p'(s) . n|` at every time `s`
    /// of `[t0, t1]` of every point `p` of link `link` within `radius` of
    /// `centre` (in the link's frame), for the joint-space segment
    /// `q(s) = q0 + s (q1 - q0)`, with rounding accounted for
    /// (`proofs/13-chains.md`, Lemmas 13.1 to 13.3); second, a bound of the
    /// undirected speed `|p'(s)|`. What a conservative-advancement step of a
    /// link divides a gap by; `n` is any nonzero direction (normalised).
    ///
    /// ```
    /// use motion_bound::chain::{ChainBuilder, JointKind, JointSpec};
    /// use motion_bound::Pose;
    /// let mut b = ChainBuilder::<f64>::new();
    /// let base = b.add_link("base", None)?;
    /// let arm = b.add_link("arm", None)?;
    /// b.add_joint(JointSpec {
    ///     name: "j".into(), kind: JointKind::Revolute, parent: base, child: arm,
    ///     origin: Pose::IDENTITY, axis: [0.0, 0.0, 1.0], limits: None,
    /// })?;
    /// let chain = b.build()?;
    /// // A point 2 from the z axis turning at 0.5 rad per unit time: speed 1,
    /// // none of it along z.
    /// let (along_x, speed) = chain.directed_speed_bound(&[0.0], &[0.5], arm, [2.0, 0.0, 0.0], 0.0, [1.0, 0.0, 0.0], [0.0, 1.0])?;
    /// assert!(along_x >= 1.0 && along_x < 1.0 + 1e-9 && speed >= 1.0);
    /// let (along_z, _) = chain.directed_speed_bound(&[0.0], &[0.5], arm, [2.0, 0.0, 0.0], 0.0, [0.0, 0.0, 1.0], [0.0, 1.0])?;
    /// assert!(along_z < 1e-9);
    /// # Ok::<(), motion_bound::chain::ChainError>(())
    /// ```
    ///
    /// # Errors
    /// [`ChainError::WrongDof`], [`ChainError::NonFiniteCoordinate`],
    /// [`ChainError::NoSuchLink`], and [`ChainError::InvalidParameter`] for a
    /// zero or non-finite `n`, a negative or non-finite radius or centre, or
    /// an interval not inside `[0, 1]` or reversed.
    #[allow(clippy::too_many_arguments)]
    pub fn directed_speed_bound(
        &self,
        q0: &[T],
        q1: &[T],
        link: usize,
        centre: [T; 3],
        radius: T,
        n: [T; 3],
        [t0, t1]: [T; 2],
    ) -> Result<(T, T), ChainError> {
        self.check_q(q0)?;
        self.check_q(q1)?;
        if link >= self.links.len() {
            return Err(ChainError::NoSuchLink(link));
        }
        // Scaled by its largest component first (exactly for that one), so
        // that no square underflows in the normalisation: the computed unit
        // vector is then within `6u` of `n / |n|` (Lemma 13.3).
        let n = Vec3::from_array(n);
        let big = n.max_abs();
        if !(big > T::ZERO && big.is_finite()) {
            return Err(ChainError::InvalidParameter("n must be nonzero and finite"));
        }
        let n = Vec3::from_array(n.to_array().map(|x| x / big))
            .try_normalize()
            .filter(|n| n.is_finite())
            .ok_or(ChainError::InvalidParameter("n must be nonzero and finite"))?;
        let c = Vec3::from_array(centre);
        if !c.is_finite()
            || c.max_abs() > T::MAX_INPUT
            || !(radius >= T::ZERO && radius.is_finite())
        {
            return Err(ChainError::InvalidParameter(
                "centre and radius must be finite, radius non-negative",
            ));
        }
        if !(T::ZERO <= t0 && t0 <= t1 && t1 <= T::ONE) {
            return Err(ChainError::InvalidParameter(
                "the interval must be inside [0, 1]",
            ));
        }
        let mut poses = alloc::vec![Pose::IDENTITY; self.links.len()];
        let mut frames =
            alloc::vec![JointFrame { axis: Vec3::ZERO, point: Vec3::ZERO }; self.joints.len()];
        self.place(|d| q0[d] + t0 * (q1[d] - q0[d]), &mut poses, &mut frames);
        let rate: Vec<T> = q0
            .iter()
            .zip(q1)
            .map(|(a, b)| (*b - *a).abs() * (T::ONE + gamma::<T>(2)))
            .collect();
        let mut errors = LinkErrors::default();
        errors.compute(self, q0, q1);
        // The centre may lie beyond the link's mesh: its placement error is
        // that of a point at its distance from the link frame's origin.
        let local = self.links[link]
            .reach
            .max_nan(c.length() * (T::ONE + gamma::<T>(2)));
        let (delta, eps, reach) = link_errors(self, q0, q1, link, local);
        errors.delta[link] = delta;
        errors.axis[link] = eps;
        errors.reach[link] = reach;
        let mut m = LinkMotion::still(Pose::IDENTITY, T::ZERO, T::ZERO);
        let dt = (t1 - t0) * (T::ONE + T::UNIT_ROUNDOFF);
        m.fill(self, link, &poses, &frames, &rate, 0, dt, &errors);
        let cw = m.pose.transform_point(c);
        Ok(m.ball_speed(cw, radius, n))
    }

    /// Lemma 13.3's `delta` (`proofs/13-chains.md`): an upper bound of the
    /// distance between a placed point of link `link` as this crate computes
    /// it and its exact place, for every point within the link's mesh reach
    /// (the frame's origin alone for a link without a mesh), at every time
    /// `t` of the segment `q0 -> q1`. "Computed" is
    /// `try_forward_kinematics(q)` with `q = q0 + t * (q1 - q0)` evaluated
    /// in `T`, then `Pose::transform_point`; "exact" is the forward
    /// kinematics of the exact `q0 + t (q1 - q0)` in real arithmetic, with
    /// unit axes `axis / |axis|` and the origins' and base's rotations taken
    /// as exact rotations within `48 u` of the stored matrices.
    ///
    /// ```
    /// use motion_bound::chain::{ChainBuilder, JointKind, JointSpec};
    /// use motion_bound::{Pose, Vec3};
    /// let mut b = ChainBuilder::<f32>::new();
    /// let base = b.add_link("base", None)?;
    /// let arm = b.add_link("arm", None)?;
    /// b.add_joint(JointSpec {
    ///     name: "j".into(), kind: JointKind::Revolute, parent: base, child: arm,
    ///     origin: Pose::from_translation(Vec3::new(1.0, 0.0, 0.0)),
    ///     axis: [0.0, 0.0, 1.0], limits: None,
    /// })?;
    /// let chain = b.build()?;
    /// // The arm's frame origin, 1 from the world origin, one joint deep:
    /// // within about 261 u (gamma_256 and the angle's gamma_3) of its exact place.
    /// let delta = chain.placement_error_bound(&[0.0], &[1.0], arm)?;
    /// assert!(delta > 256.0 * f32::EPSILON / 2.0 && delta < 300.0 * f32::EPSILON / 2.0);
    /// # Ok::<(), motion_bound::chain::ChainError>(())
    /// ```
    ///
    /// # Errors
    /// [`ChainError::WrongDof`], [`ChainError::NonFiniteCoordinate`],
    /// [`ChainError::NoSuchLink`].
    pub fn placement_error_bound(&self, q0: &[T], q1: &[T], link: usize) -> Result<T, ChainError> {
        self.check_q(q0)?;
        self.check_q(q1)?;
        let data = self.links.get(link).ok_or(ChainError::NoSuchLink(link))?;
        Ok(link_errors(self, q0, q1, link, data.reach).0)
    }
}
