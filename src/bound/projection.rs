//! The per-direction quantities of one motion that every bound shares.

use crate::rounding::{assemble, linear_up, nevq_rotational_up, one_sided_up};
use crate::{Direction, Float, RigidMotion, Vec3};

/// The per-query quantities both bounds share: `a = v.n`, and `c = n x w`
/// twice: in the world frame for NEVQ (`|n x w|` is frame-free), and in the
/// body frame for EVQ (`Q0^T n x Q0^T w`, what the rotation-plane
/// coordinates of the body's points need; `proofs/floating-point.md`,
/// "Orientation").
#[derive(Clone, Copy, Debug)]
pub(crate) struct Projection<T> {
    /// `fl(v . n)`.
    pub(crate) a: T,
    /// `fl(sum |v_k n_k|)`, the magnitude bounding the error of `a`.
    pub(crate) a_mag: T,
    /// `fl(n_b x w_b)` in the body frame.
    pub(crate) c: Vec3<T>,
    /// `fl(|c|)` of the body-frame `c`.
    pub(crate) c_norm: T,
    /// `fl(|w_b|_1)` of the body-frame `w`.
    pub(crate) w_l1: T,
    /// `fl(|n x w|)` in the world frame (NEVQ).
    pub(crate) nevq_c_norm: T,
    /// `fl(|w|_1)` in the world frame (NEVQ).
    pub(crate) nevq_w_l1: T,
}

impl<T: Float> Projection<T> {
    /// The world-frame projection (the body frame is the world frame).
    #[inline]
    pub(crate) fn new(motion: &RigidMotion<T>, n: Direction<T>) -> Self {
        Self::with_frame(motion.linear(), n.get(), None, motion.angular())
    }

    /// With the body frame: `body = Some((Q0^T n, Q0^T w))` computed, or
    /// `None` when the body frame is the world frame.
    #[inline]
    pub(crate) fn with_frame(
        v: Vec3<T>,
        n: Vec3<T>,
        body: Option<(Vec3<T>, Vec3<T>)>,
        w: Vec3<T>,
    ) -> Self {
        let c = n.cross(w);
        let (c_norm, w_l1) = (c.length(), w.norm_l1());
        let (cb, cb_norm, wb_l1) = match body {
            None => (c, c_norm, w_l1),
            Some((nb, wb)) => {
                let cb = nb.cross(wb);
                (cb, cb.length(), wb.norm_l1())
            }
        };
        Self {
            a: v.dot(n),
            a_mag: v.dot_abs(n),
            c: cb,
            c_norm: cb_norm,
            w_l1: wb_l1,
            nevq_c_norm: c_norm,
            nevq_w_l1: w_l1,
        }
    }

    #[inline]
    pub(crate) fn linear_up(&self) -> T {
        linear_up(self.a, self.a_mag)
    }
}

/// The one-sided NEVQ bound `a + |n x w| R` for points within `lever` of the
/// rotation centre, rounded up (`proofs/10-one-sided.md`).
#[inline]
pub(crate) fn nevq_rate_from<T: Float>(p: &Projection<T>, lever: T) -> T {
    let rot = nevq_rotational_up(p.nevq_c_norm, p.nevq_w_l1, lever);
    one_sided_up(p.a, p.a_mag, rot, rot, T::ZERO)
}

/// The NEVQ speed bound for points within `r_hat` of the rotation centre.
#[inline]
pub(crate) fn nevq_speed_from<T: Float>(p: &Projection<T>, r_hat: T) -> T {
    assemble(
        p.linear_up(),
        nevq_rotational_up(p.nevq_c_norm, p.nevq_w_l1, r_hat),
    )
}
