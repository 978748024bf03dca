//! The per-direction quantities of one motion that every bound shares.

use crate::rounding::{assemble, linear_up, nevq_rotational_up};
use crate::{Direction, Float, RigidMotion, Vec3};

/// The per-query quantities both bounds share: `a = v.n`, `c = n x w`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Projection<T> {
    /// `fl(v . n)`.
    pub(crate) a: T,
    /// `fl(sum |v_k n_k|)`, the magnitude bounding the error of `a`.
    pub(crate) a_mag: T,
    /// `fl(n x w)`.
    pub(crate) c: Vec3<T>,
    /// `fl(|fl(n x w)|)`.
    pub(crate) c_norm: T,
    /// `fl(|w|_1)`.
    pub(crate) w_l1: T,
}

impl<T: Float> Projection<T> {
    #[inline]
    pub(crate) fn new(motion: &RigidMotion<T>, n: Direction<T>) -> Self {
        let n = n.get();
        let v = motion.linear();
        let w = motion.angular();
        let c = n.cross(w);
        Self {
            a: v.dot(n),
            a_mag: v.dot_abs(n),
            c,
            c_norm: c.length(),
            w_l1: w.norm_l1(),
        }
    }

    #[inline]
    pub(crate) fn linear_up(&self) -> T {
        linear_up(self.a, self.a_mag)
    }
}

/// The NEVQ speed bound for points within `r_hat` of the rotation centre.
#[inline]
pub(crate) fn nevq_speed_from<T: Float>(p: &Projection<T>, r_hat: T) -> T {
    assemble(p.linear_up(), nevq_rotational_up(p.c_norm, p.w_l1, r_hat))
}
