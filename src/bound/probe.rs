//! Directed bounds for one motion along one direction, for many bodies:
//! vertex sets, bounding balls, body summaries, convex shapes.

use crate::bound::projection::{nevq_rate_from, nevq_speed_from, Projection};
use crate::bound::scan::{arc_scan, arc_signed_scan, full_turn_scan};
use crate::rounding::{
    add_up, assemble, evq_rotational_up, lever_up, mul_up, nevq_rotational_up,
    one_sided_decision_slack, one_sided_up, radius_up, sum_up,
};
use crate::{
    BodySummary, BoundKind, BoundingBall, Convex, Direction, Float, PreparedMotion, SweptArc, Vec3,
    VertexSet,
};

/// The per-direction quantities of one motion (`v.n`, `c = n x w` and the
/// rotation-plane basis `e1 = c/|c|`, `e2 = w^ x e1`), computed once by
/// [`PreparedMotion::probe`] and shared by every bound along that direction.
///
/// This is what a bounding-volume traversal uses: one probe per body per
/// node pair, then `O(1)` per [`BoundingBall`] and no trigonometry at all.
/// Every method returns the same rounded-up speed bound as the one-shot
/// functions ([`evq`](crate::evq), [`nevq`](crate::nevq)) would.
#[derive(Clone, Copy, Debug)]
pub struct DirectedProbe<T> {
    p: Projection<T>,
    arc: SweptArc<T>,
    /// The rotation is trusted (`|w|` and `|c|` above `TINY_LENGTH`).
    usable: bool,
    e1: Vec3<T>,
    e2: Vec3<T>,
    /// The rotation centre in the body frame, subtracted from every point.
    offset: Vec3<T>,
    /// `|offset|` rounded up.
    offset_up: T,
    /// The frame margin's coefficient (`rounding::frame_margin_up`).
    frame_margin: T,
    /// An upper bound of `|w x Q0 y|` (`rounding::axis_tilt_up`).
    axis_tilt: T,
}

impl<T: Float> PreparedMotion<T> {
    /// The probe of this motion along `n`: `O(1)`, with `n` taken into the
    /// body frame (`Q0^T n`) for an oriented motion.
    #[inline]
    #[must_use]
    pub fn probe(&self, n: Direction<T>) -> DirectedProbe<T> {
        self.probe_inlined(n)
    }

    /// [`probe`](Self::probe), always inlined: for the mesh descent's hot
    /// loop, where the compiler then keeps only what the bound reads.
    #[inline(always)]
    pub(crate) fn probe_inlined(&self, n: Direction<T>) -> DirectedProbe<T> {
        let m = self.motion();
        let orientation = m.orientation();
        let body = if orientation.is_identity() {
            None
        } else {
            Some((orientation.inverse_rotate(n.get()), self.body_angular()))
        };
        let p = Projection::with_frame(m.linear(), n.get(), body, m.angular());
        let arc = *self.arc();
        let usable = arc.rotating && p.c_norm > T::TINY_LENGTH;
        let (e1, e2) = if usable && !arc.full_turn {
            let e1 = Vec3::new(p.c.x / p.c_norm, p.c.y / p.c_norm, p.c.z / p.c_norm);
            (e1, arc.axis.cross(e1))
        } else {
            (Vec3::ZERO, Vec3::ZERO)
        };
        DirectedProbe {
            p,
            arc,
            usable,
            e1,
            e2,
            offset: m.local_centre(),
            offset_up: m.local_reach(),
            frame_margin: self.frame_margin,
            axis_tilt: self.axis_tilt,
        }
    }
}

impl<T: Float> DirectedProbe<T> {
    /// An upper bound of `|v.n|`, the linear part shared by both bounds.
    #[inline]
    #[must_use]
    pub fn linear_speed(&self) -> T {
        self.p.linear_up()
    }

    /// The NEVQ speed bound of a body with this summary (as [`nevq_speed`](crate::nevq_speed)).
    #[inline]
    #[must_use]
    pub fn nevq_speed(&self, body: &BodySummary<T>) -> T {
        nevq_speed_from(&self.p, lever_up(body.max_radius(), self.offset_up))
    }

    /// The EVQ speed bound of a vertex set (as [`evq_speed`](crate::evq_speed)).
    #[must_use]
    pub fn evq_speed(&self, body: &VertexSet<'_, T>) -> T {
        self.evq_speed_points(body.vertices(), body.summary().max_radius())
    }

    /// EVQ over `points`, all within `r_hat` of the body origin (`r_hat`
    /// rounded up as by `rounding::radius_up`).
    #[inline]
    pub(crate) fn evq_speed_points(&self, points: &[[T; 3]], r_hat: T) -> T {
        let lever = lever_up(r_hat, self.offset_up);
        let nevq = nevq_speed_from(&self.p, lever);
        match self.extremal_sq(points, lever * lever) {
            None => nevq,
            Some(e_sq) => {
                let rot = evq_rotational_up(
                    self.p.c_norm,
                    e_sq.sqrt(),
                    self.arc.theta_m,
                    self.p.w_l1,
                    lever,
                );
                assemble(self.p.linear_up(), self.with_frame_margin(rot, lever)).min_nan(nevq)
            }
        }
    }

    /// `rot` plus the frame margin for points within `lever` of the
    /// rotation centre (`proofs/floating-point.md`, "Orientation"): the sum
    /// is one addition deeper than "Assembly" budgets, so it is rounded up by
    /// `1 + gamma_2` as in section "Ball". Unchanged when there is no margin.
    #[inline]
    fn with_frame_margin(&self, rot: T, lever: T) -> T {
        if self.frame_margin == T::ZERO {
            rot
        } else {
            sum_up(rot, self.frame_margin * lever)
        }
    }

    /// NEVQ for points within `r_hat` of the body origin.
    #[cfg(feature = "alloc")]
    #[inline]
    pub(crate) fn nevq_speed_radius(&self, r_hat: T) -> T {
        nevq_speed_from(&self.p, lever_up(r_hat, self.offset_up))
    }

    /// The speed bound of kind `kind` for a vertex set.
    #[inline]
    #[must_use]
    pub fn speed(&self, body: &VertexSet<'_, T>, kind: BoundKind) -> T {
        match kind {
            BoundKind::Nevq => self.nevq_speed(&body.summary()),
            BoundKind::Evq => self.evq_speed(body),
        }
    }

    /// An upper bound of the signed rate `v . n` (along the exact unit
    /// `n/|n|`) at which the motion's rotation centre moves along `n`: the
    /// rate of the support `x(t) . n + rho` of a ball of any radius `rho`
    /// centred on the rotation centre, which the rotation turns in place
    /// (`proofs/09-ca-toi.md`, Lemma 9.8). What a body turning fast within
    /// such a ball can be stepped by, whatever it turns.
    ///
    /// ```
    /// use motion_bound::{Direction, PreparedMotion, RigidMotion};
    /// // Spinning at 200 rad per unit time, drifting along x at 1.
    /// let m = RigidMotion::try_from_arrays([0.0; 3], [1.0, 0.0, 0.0], [0.0, 200.0, 0.0])?;
    /// let rate = PreparedMotion::new(&m).probe(Direction::X).centre_rate();
    /// assert!(rate >= 1.0 && rate < 1.0 + 1e-12);
    /// # Ok::<(), motion_bound::InputError>(())
    /// ```
    #[inline]
    #[must_use]
    pub fn centre_rate(&self) -> T {
        one_sided_up(self.p.a, self.p.a_mag, T::ZERO, T::ZERO, T::ZERO)
    }

    /// An upper bound of `|v . n|` (along the exact unit `n/|n|`): the
    /// absolute counterpart of [`centre_rate`](Self::centre_rate).
    #[inline]
    #[must_use]
    pub fn centre_speed(&self) -> T {
        assemble(self.p.linear_up(), T::ZERO)
    }

    /// The speed bound of kind `kind` for every point of a ball (relative to
    /// the rotation centre at the epoch), in `O(1)`.
    ///
    /// EVQ of a ball of centre `s` and radius `rho` is the EVQ term of its
    /// centre plus `|c| rho` (`proofs/08-ball-bound.md`); NEVQ is
    /// `|c| (|s| + rho)`. Both are rounded up, and EVQ is never above NEVQ.
    ///
    /// ```
    /// use motion_bound::{BoundKind, BoundingBall, Direction, PreparedMotion, RigidMotion};
    /// // A ball of radius 0.1 centred 1 from the axis, turning slowly about z.
    /// let ball = BoundingBall::try_new([1.0, 0.0, 0.0], 0.1).unwrap();
    /// let m = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0, 0.0, 0.1]).unwrap();
    /// let probe = PreparedMotion::new(&m).probe(Direction::X);
    /// let evq = probe.ball_speed(&ball, BoundKind::Evq);
    /// let nevq = probe.ball_speed(&ball, BoundKind::Nevq);
    /// // Along x the centre moves at 0.1 sin(theta) <= 0.1 sin(0.1); the rim adds 0.1 * 0.1.
    /// assert!(evq >= 0.1 * 0.1f64.sin() + 0.01 && evq < 0.0201);
    /// assert!(nevq >= 0.11 && evq <= nevq);
    /// ```
    #[must_use]
    pub fn ball_speed(&self, ball: &BoundingBall<T>, kind: BoundKind) -> T {
        let linear = self.p.linear_up();
        let nevq = nevq_speed_from(&self.p, lever_up(ball.outer_radius_up(), self.offset_up));
        if kind == BoundKind::Nevq {
            return nevq;
        }
        let Some(e_sq) = self.extremal_sq(core::slice::from_ref(ball.centre()), T::INFINITY) else {
            return nevq;
        };
        let lever = lever_up(ball.centre_norm_up(), self.offset_up);
        let centre = evq_rotational_up(
            self.p.c_norm,
            e_sq.sqrt(),
            self.arc.theta_m,
            self.p.w_l1,
            lever,
        );
        let rim = nevq_rotational_up(self.p.c_norm, self.p.w_l1, ball.radius());
        // One more addition and one more product than "Assembly" budgets:
        // `proofs/floating-point.md`, section "Ball".
        let rot = sum_up(centre, rim);
        let rot = self.with_frame_margin(rot, lever + ball.radius());
        assemble(linear, rot).min_nan(nevq)
    }

    /// The one-sided speed bound of kind `kind` for every point of a ball:
    /// an upper bound of the *signed* speed `d/dt (p(t) . n)` (along the
    /// exact unit `n/|n|`) over the motion's interval, for every point `p`
    /// of the ball. Negative when every point of the ball recedes along `n`
    /// throughout. In exact arithmetic it is never above
    /// [`ball_speed`](Self::ball_speed); in floating point the two carry
    /// different rounding margins, so it may exceed it by at most
    /// `64 u (sum_k |v_k n_k| + (|n x w| + |w|_1) R) + 64 eta`
    /// (`proofs/10-one-sided.md`, "Floating point"): take the smaller of the
    /// two if you need both orders.
    ///
    /// Conservative advancement needs only this one side: two bodies
    /// separated along `n` close at most at the rate of A along `n` plus
    /// the rate of B along `-n` (`proofs/10-one-sided.md`, Lemma 10.2), so a
    /// body moving away, or turning its near side away, no longer counts
    /// against the step as it does with the absolute `|v.n| + ...` of the
    /// seed's bounds. EVQ's one-sided term asks, per point, whether the arc
    /// reaches the point's direction `+q` (not the line `+-q`): Lemma 10.1.
    ///
    /// ```
    /// use motion_bound::{BoundKind, BoundingBall, Direction, PreparedMotion, RigidMotion};
    /// // A ball of radius 0.1 centred 1 along x, turning at 0.1 rad/s about z
    /// // (so its centre moves along +y), and drifting along -y at 1.
    /// let ball = BoundingBall::try_new([1.0, 0.0, 0.0], 0.1).unwrap();
    /// let m = RigidMotion::try_from_arrays([0.0; 3], [0.0, -1.0, 0.0], [0.0, 0.0, 0.1]).unwrap();
    /// let probe = PreparedMotion::new(&m).probe(Direction::Y);
    /// let rate = probe.ball_rate(&ball, BoundKind::Evq);
    /// // A point at x along the ball moves along y at -1 + 0.1 x cos(theta): at
    /// // most -1 + 0.11 = -0.89, at the rim's far point at t = 0.
    /// assert!(rate >= -0.89 && rate < -0.889);
    /// assert!(probe.ball_speed(&ball, BoundKind::Evq) > 1.0); // the absolute bound
    /// ```
    #[must_use]
    pub fn ball_rate(&self, ball: &BoundingBall<T>, kind: BoundKind) -> T {
        self.ball_rate_inlined(ball, kind)
    }

    /// [`ball_rate`](Self::ball_rate), always inlined (see
    /// [`PreparedMotion::probe_inlined`]).
    #[inline(always)]
    pub(crate) fn ball_rate_inlined(&self, ball: &BoundingBall<T>, kind: BoundKind) -> T {
        let nevq = self.nevq_rate(lever_up(ball.outer_radius_up(), self.offset_up));
        if kind == BoundKind::Nevq || !self.usable {
            return nevq;
        }
        let lever = lever_up(ball.centre_norm_up(), self.offset_up);
        let s = self.signed_extremal(core::slice::from_ref(ball.centre()), lever);
        // The centre's term: |c| S^ and its error; the rim adds |c| rho.
        let margin =
            evq_rotational_up(self.p.c_norm, T::ZERO, self.arc.theta_m, self.p.w_l1, lever)
                + nevq_rotational_up(self.p.c_norm, self.p.w_l1, ball.radius());
        let margin = self.with_frame_margin(margin, lever + ball.radius());
        let rot = self.p.c_norm * s;
        one_sided_up(self.p.a, self.p.a_mag, rot, rot.abs(), margin).min_nan(nevq)
    }

    /// The one-sided speed bound of kind `kind` for every point of a convex
    /// shape (see [`ball_rate`](Self::ball_rate)): its core's cover of
    /// points and balls, each dilated by the shape's radius
    /// (`proofs/12-shapes.md`, "Bounds").
    ///
    /// ```
    /// use motion_bound::{BoundKind, Convex, Direction, PreparedMotion, RigidMotion};
    /// // A capsule standing along y, moving along x at 1 and turning about z.
    /// let capsule = Convex::try_capsule(1.0, 0.25)?;
    /// let m = RigidMotion::try_from_arrays([0.0; 3], [1.0, 0.0, 0.0], [0.0, 0.0, 0.5])?;
    /// let probe = PreparedMotion::new(&m).probe(Direction::X);
    /// // The top end turns along -x, the bottom end along +x, at up to
    /// // 0.5 rad/s at lever 1.25: the rate is at most 1 + 0.625.
    /// let rate = probe.convex_rate(&capsule, BoundKind::Evq);
    /// assert!(rate >= 1.0 + 0.5 * 0.25 && rate <= 1.0 + 0.625 + 1e-12);
    /// # Ok::<(), motion_bound::InputError>(())
    /// ```
    #[must_use]
    pub fn convex_rate(&self, shape: &Convex<'_, T>, kind: BoundKind) -> T {
        self.convex_bound(shape, kind, Self::dilated_rate, shape.radius())
    }

    /// The (absolute) speed bound of kind `kind` for every point of a
    /// convex shape (see [`ball_speed`](Self::ball_speed) and
    /// [`convex_rate`](Self::convex_rate)).
    #[must_use]
    pub fn convex_speed(&self, shape: &Convex<'_, T>, kind: BoundKind) -> T {
        self.convex_bound(shape, kind, Self::dilated_speed, shape.radius())
    }

    /// An upper bound of the rate at which a convex shape's **support**
    /// along `n`, `max_{p in S(t)} p . n` (along the exact unit `n/|n|`),
    /// rises over the motion's interval: what conservative advancement
    /// needs (`proofs/12-shapes.md`, Lemma 12.5), and never more than
    /// [`convex_rate`](Self::convex_rate), which bounds every point.
    ///
    /// Motion that maps the shape onto itself does not count:
    /// * the shape's radius is dropped (the support of `K + B(rho)` is the
    ///   core's plus the constant `rho`), so a ball turning about its centre
    ///   rises at its centre's rate, whatever it spins;
    /// * a capsule, cylinder or cone (rounded or not, not placed in a
    ///   compound) whose rotation centre lies on its axis moves as its axis
    ///   does: at most the rate of the axis point nearest the rotation
    ///   centre plus `|w x a| rho_o`, with `a` the axis and `rho_o` the
    ///   core's reach from that point. A wheel rolling about its axle or a
    ///   capsule spinning about its own axis rises at its translation's
    ///   rate. The least of this and the cover's bound is returned.
    ///
    /// ```
    /// use motion_bound::{BoundKind, Convex, Direction, PreparedMotion, RigidMotion};
    /// // A wheel (a cylinder along y) rolling along x at 1 on a floor below it:
    /// // radius 0.5, spinning about its axle y at 2 rad per unit time.
    /// let wheel = Convex::try_cylinder(0.1, 0.5)?;
    /// let m = RigidMotion::try_from_arrays([0.0; 3], [1.0, 0.0, 0.0], [0.0, 2.0, 0.0])?;
    /// let down = PreparedMotion::new(&m).probe(-Direction::Z);
    /// // Every rim point moves along z at up to 2 * 0.5; the support does not move.
    /// assert!(down.convex_rate(&wheel, BoundKind::Evq) >= 1.0);
    /// assert!(down.convex_support_rate(&wheel, BoundKind::Evq) < 1e-12);
    /// # Ok::<(), motion_bound::InputError>(())
    /// ```
    #[must_use]
    pub fn convex_support_rate(&self, shape: &Convex<'_, T>, kind: BoundKind) -> T {
        let cover = self.convex_bound(shape, kind, Self::dilated_rate, T::ZERO);
        match self.axial(shape) {
            Some((o, o_reach, spin)) => cover.min_nan(up_or_inf(add_up(
                self.points_rate(&[o], o_reach, kind),
                spin,
            ))),
            None => cover,
        }
    }

    /// The absolute counterpart of
    /// [`convex_support_rate`](Self::convex_support_rate): an upper bound of
    /// how fast the support along `n` moves either way; never more than
    /// [`convex_speed`](Self::convex_speed).
    #[must_use]
    pub fn convex_support_speed(&self, shape: &Convex<'_, T>, kind: BoundKind) -> T {
        let cover = self.convex_bound(shape, kind, Self::dilated_speed, T::ZERO);
        match self.axial(shape) {
            Some((o, o_reach, spin)) => {
                let centre = match kind {
                    BoundKind::Nevq => nevq_speed_from(&self.p, lever_up(o_reach, self.offset_up)),
                    BoundKind::Evq => self.evq_speed_points(&[o], o_reach),
                };
                cover.min_nan(up_or_inf(add_up(centre, spin)))
            }
            None => cover,
        }
    }

    /// For an axially symmetric shape (`Convex::axial_reach`): the axis
    /// point `o = (0, c_y, 0)` nearest the rotation centre `c`, `|o|`, and
    /// an upper bound of `|w x a| rho_o` (Lemma 12.5).
    #[inline]
    fn axial(&self, shape: &Convex<'_, T>) -> Option<([T; 3], T, T)> {
        let y = self.offset.y;
        let reach = shape.axial_reach(y)?;
        Some((
            [T::ZERO, y, T::ZERO],
            y.abs(),
            mul_up(self.axis_tilt, reach),
        ))
    }

    /// `bound` over the shape's cover: the main group dilated by its own
    /// radius plus `radius`, and a cone's apex by `radius`.
    fn convex_bound(
        &self,
        shape: &Convex<'_, T>,
        kind: BoundKind,
        bound: fn(&Self, &[[T; 3]], T, T, BoundKind) -> T,
        radius: T,
    ) -> T {
        let g = shape.bound_groups();
        let points = g.points();
        let r_hat = points
            .iter()
            .map(|p| p[0] * p[0] + p[1] * p[1] + p[2] * p[2])
            .fold(T::ZERO, T::max_nan);
        let main = bound(
            self,
            points,
            radius_up(r_hat),
            dilation_up(g.dilation, radius),
            kind,
        );
        match g.second {
            Some((p, d)) => {
                let r = radius_up(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
                main.max_nan(bound(self, &[p], r, dilation_up(d, radius), kind))
            }
            None => main,
        }
    }

    /// [`ball_rate`](Self::ball_rate) over the balls of radius `dilation`
    /// about `points` (offsets from the body origin within `r_hat`): the
    /// signed extremal over the centres, plus the rim's `|c| dilation`.
    fn dilated_rate(&self, points: &[[T; 3]], r_hat: T, dilation: T, kind: BoundKind) -> T {
        let lever = lever_up(r_hat, self.offset_up);
        let nevq = self.nevq_rate(lever_up(sum_up(r_hat, dilation), self.offset_up));
        if kind == BoundKind::Nevq || !self.usable || points.is_empty() {
            return nevq;
        }
        let s = self.signed_extremal(points, lever);
        let margin =
            evq_rotational_up(self.p.c_norm, T::ZERO, self.arc.theta_m, self.p.w_l1, lever)
                + nevq_rotational_up(self.p.c_norm, self.p.w_l1, dilation);
        let margin = self.with_frame_margin(margin, lever + dilation);
        let rot = self.p.c_norm * s;
        one_sided_up(self.p.a, self.p.a_mag, rot, rot.abs(), margin).min_nan(nevq)
    }

    /// [`ball_speed`](Self::ball_speed) over the balls of radius `dilation`
    /// about `points` (as [`dilated_rate`](Self::dilated_rate)).
    fn dilated_speed(&self, points: &[[T; 3]], r_hat: T, dilation: T, kind: BoundKind) -> T {
        let linear = self.p.linear_up();
        let nevq = nevq_speed_from(&self.p, lever_up(sum_up(r_hat, dilation), self.offset_up));
        if kind == BoundKind::Nevq {
            return nevq;
        }
        let Some(e_sq) = self.extremal_sq(points, T::INFINITY) else {
            return nevq;
        };
        let lever = lever_up(r_hat, self.offset_up);
        let centre = evq_rotational_up(
            self.p.c_norm,
            e_sq.sqrt(),
            self.arc.theta_m,
            self.p.w_l1,
            lever,
        );
        let rim = nevq_rotational_up(self.p.c_norm, self.p.w_l1, dilation);
        let rot = sum_up(centre, rim);
        let rot = self.with_frame_margin(rot, lever + dilation);
        assemble(linear, rot).min_nan(nevq)
    }

    /// The one-sided NEVQ bound for points within `lever` of the rotation
    /// centre.
    #[inline]
    fn nevq_rate(&self, lever: T) -> T {
        nevq_rate_from(&self.p, lever)
    }

    /// The one-sided speed bound of kind `kind` for a vertex set (see
    /// [`ball_rate`](Self::ball_rate)): an upper bound of the signed speed
    /// `d/dt (r_i(t) . n)` of every vertex over the motion's interval.
    #[must_use]
    pub fn rate(&self, body: &VertexSet<'_, T>, kind: BoundKind) -> T {
        self.points_rate(body.vertices(), body.summary().max_radius(), kind)
    }

    /// [`rate`](Self::rate) over `points`, all within `r_hat` of the body
    /// origin (`r_hat` rounded up as by `rounding::radius_up`).
    #[inline]
    pub(crate) fn points_rate(&self, points: &[[T; 3]], r_hat: T, kind: BoundKind) -> T {
        let lever = lever_up(r_hat, self.offset_up);
        let nevq = self.nevq_rate(lever);
        if kind == BoundKind::Nevq || !self.usable || points.is_empty() {
            return nevq;
        }
        let s = self.signed_extremal(points, lever);
        let margin =
            evq_rotational_up(self.p.c_norm, T::ZERO, self.arc.theta_m, self.p.w_l1, lever);
        let margin = self.with_frame_margin(margin, lever);
        let rot = self.p.c_norm * s;
        one_sided_up(self.p.a, self.p.a_mag, rot, rot.abs(), margin).min_nan(nevq)
    }

    /// `S^ = max_i max_arc u . q_i` (signed) over `points` (offsets from the
    /// rotation centre within `lever`); only called when the rotation is
    /// trusted.
    #[inline(always)]
    fn signed_extremal(&self, points: &[[T; 3]], lever: T) -> T {
        if self.arc.full_turn {
            // Every point's direction is reached: its distance from the axis.
            full_turn_scan(points, self.offset, self.arc.axis, T::INFINITY)
                .map_or(T::INFINITY, |sq| sq.sqrt())
        } else {
            let slack =
                one_sided_decision_slack(self.p.c_norm, self.arc.theta_m, self.p.w_l1, lever);
            arc_signed_scan(
                points,
                self.offset,
                self.e1,
                self.e2,
                (self.arc.ua, self.arc.ub),
                self.p.c_norm,
                slack,
            )
        }
    }

    /// `E^2 = max_i max_arc (u . q_i)^2` over `points` (as offsets from the
    /// rotation centre), or `None` when the EVQ term is not used (no trusted
    /// rotation) or a point reaches `stop_sq`.
    #[inline]
    pub(crate) fn extremal_sq(&self, points: &[[T; 3]], stop_sq: T) -> Option<T> {
        if !self.usable {
            return None;
        }
        if self.arc.full_turn {
            full_turn_scan(points, self.offset, self.arc.axis, stop_sq)
        } else {
            arc_scan(
                points,
                self.offset,
                self.e1,
                self.e2,
                (self.arc.ua, self.arc.ub),
                stop_sq,
            )
        }
    }

    /// `fl(|c|)`.
    #[cfg(feature = "testkit")]
    #[inline]
    pub(crate) fn c_norm(&self) -> T {
        self.p.c_norm
    }

    /// `fl(|v.n|)`, without margin.
    #[cfg(feature = "testkit")]
    #[inline]
    pub(crate) fn linear_raw(&self) -> T {
        self.p.a.abs()
    }
}

/// `x`, or `+inf` for a NaN (an overflowed sum of bounds is no bound).
#[inline]
fn up_or_inf<T: Float>(x: T) -> T {
    if x.is_nan() {
        T::INFINITY
    } else {
        x
    }
}

/// `a + b` rounded up (`rounding::sum_up`), exactly `a` when `b = 0`.
#[inline]
fn dilation_up<T: Float>(a: T, b: T) -> T {
    if b == T::ZERO {
        a
    } else if a == T::ZERO {
        b
    } else {
        sum_up(a, b)
    }
}
