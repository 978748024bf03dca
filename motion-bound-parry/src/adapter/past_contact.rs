//! What a pair touching at the start of a cast does next: does the moving
//! shape go deeper into the other, past the plane that separated them at
//! the start, or does it slide along it or leave?
//!
//! Rapier ignores a hit at the start of a step (fraction `0`), so a body
//! stopped within the contact distance of a thin wall, pushed on by the
//! solver the next step, would pass through it unchecked. The answer here
//! is certified: with `n` the contact normal at the start (any unit vector
//! would do for soundness; the normal makes sliding along the surface free),
//! `lo2` the least of `n . x` over shape 2 and `hi1` the greatest over
//! shape 1 (both exact support values, from support maps or mesh vertices),
//! the half-space `n . x >= max(hi1, lo2) + 2 d` (`d` the contact distance),
//! carried along by shape 2's translation, is cast against shape 1's motion
//! with the certified cast. Before the cast's time shape 1 stays within
//! `n . x < max(hi1, lo2) + d` (relative to shape 2) and shape 2 within
//! `n . x >= lo2`: their overlap along `n`, which bounds the penetration
//! depth, grows by at most `d` over what it was at the start, so nothing
//! thicker than that along `n` is passed through. The pair is
//! [`PastContact::Never`] when the cast certifies no contact, and
//! [`PastContact::At`] its time otherwise (at least `2 d - d` away at the
//! start, so after the start), or the start itself when the overlap along
//! `n` is already more than `d` (the solver left it there): a pair stopped
//! at the cast's time every step would otherwise creep in by `d` a step. When shape 2 rotates (a ball about its own
//! centre counts as still) and shape 1 does not, the roles swap; both
//! rotating, or a shape whose extent along `n` is not computed here
//! (heightfields, polylines, voxels, custom shapes), is
//! [`PastContact::Unknown`].

use super::dispatcher::CertifiedDispatcher;
use super::parry;
use super::swept::Swept;
use parry::math::{Pose, Real, Vector};
use parry::query::NonlinearRigidMotion;
use parry::shape::{HalfSpace, Shape};

/// What a pair touching at the start does over the rest of the interval
/// (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum PastContact {
    /// Shape 1 never reaches more than the contact distance deeper along
    /// the start's contact normal than it was (certified).
    Never,
    /// It may from this time on (never later than the first time it does;
    /// the start itself for a pair already deeper than the contact
    /// distance).
    At(Real),
    /// Not decided here (shape 2 rotating, a shape without a computed
    /// extent, no contact normal, or a cast error).
    Unknown,
}

/// The greatest of `dir . x` over `shape` at `pose`: a support map's
/// support point, a mesh's vertices, a compound's parts; `None` for other
/// shapes.
fn extent(shape: &dyn Shape, pose: &Pose, dir: Vector) -> Option<Real> {
    let shape = Swept::see_through(shape);
    if let Some(s) = shape.as_support_map() {
        return Some(dir.dot(s.support_point(pose, dir)));
    }
    if let Some(mesh) = shape.as_trimesh() {
        return mesh
            .vertices()
            .iter()
            .map(|v| dir.dot(pose.transform_point(*v)))
            .reduce(Real::max);
    }
    if let Some(c) = shape.as_compound() {
        let mut best: Option<Real> = None;
        for (p, s) in c.shapes() {
            let e = extent(s.as_ref(), &(*pose * *p), dir)?;
            best = Some(best.map_or(e, |b| b.max(e)));
        }
        return best;
    }
    None
}

/// Whether `shape` on `motion` only translates: a still rotation, or a ball
/// whose centre is the rotation's centre (to `1e-3` of the contact distance
/// `d` over the interval `span`: its centre then moves off the line by less
/// than that, which the half-space's margin of `d` takes).
fn translates(motion: &NonlinearRigidMotion, shape: &dyn Shape, span: Real, d: Real) -> bool {
    motion.angvel == Vector::ZERO
        || (Swept::see_through(shape).as_ball().is_some()
            && motion.local_center.length() * (motion.angvel.length() * span).min(2.0) <= 1e-3 * d)
}

impl CertifiedDispatcher {
    /// For shapes touching at `start_time`: whether shape 1 goes deeper
    /// into shape 2 over `[start_time, end_time]` (see the module docs).
    /// When shape 2 rotates and shape 1 only translates, the roles swap:
    /// shape 2 is cast against the half-space carried by shape 1.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn past_contact(
        &self,
        motion1: &NonlinearRigidMotion,
        g1: &dyn Shape,
        motion2: &NonlinearRigidMotion,
        g2: &dyn Shape,
        start_time: Real,
        end_time: Real,
    ) -> PastContact {
        let d = self.params().contact_distance;
        let span = end_time - start_time;
        // NaN or an empty interval: not decided.
        if span.is_nan() || span <= 0.0 {
            return PastContact::Unknown;
        }
        if translates(motion2, g2, span, d) {
            self.cast_to_plane(motion1, g1, motion2, g2, start_time, end_time)
        } else if translates(motion1, g1, span, d) {
            self.cast_to_plane(motion2, g2, motion1, g1, start_time, end_time)
        } else {
            PastContact::Unknown
        }
    }

    /// [`past_contact`](Self::past_contact) with shape 2 translating
    /// (`motion2`'s rotation is left out).
    #[allow(clippy::too_many_arguments)]
    fn cast_to_plane(
        &self,
        motion1: &NonlinearRigidMotion,
        g1: &dyn Shape,
        motion2: &NonlinearRigidMotion,
        g2: &dyn Shape,
        start_time: Real,
        end_time: Real,
    ) -> PastContact {
        let d = self.params().contact_distance;
        let (s1, s2) = (Swept::see_through(g1), Swept::see_through(g2));
        let (p1, p2) = (
            motion1.position_at_time(start_time),
            motion2.position_at_time(start_time),
        );
        let Ok(Some(c)) = parry::query::contact(&p1, s1, &p2, s2, 4.0 * d) else {
            return PastContact::Unknown;
        };
        let n = c.normal1;
        if !n.is_finite() || (n.length() - 1.0).abs() > 1e-3 {
            return PastContact::Unknown;
        }
        let (Some(hi1), Some(neg_lo2)) = (extent(s1, &p1, n), extent(s2, &p2, -n)) else {
            return PastContact::Unknown;
        };
        // Already deeper than the contact distance along `n` (the solver
        // left it so): no deeper at all, or a pair held every step would
        // creep in by `d` a step; the hit is the start.
        let deep = hi1 > -neg_lo2 + d;
        let bound = hi1.max(-neg_lo2) + 2.0 * d;
        if !bound.is_finite() {
            return PastContact::Unknown;
        }
        // The half-space `n . x >= bound` (outward normal `-n`, its plane
        // through `n * bound`), translating with shape 2.
        let plane = HalfSpace::new(-n);
        let motion = NonlinearRigidMotion::new(
            Pose::from_translation(n * bound - motion2.linvel * start_time),
            Vector::ZERO,
            motion2.linvel,
            Vector::ZERO,
        );
        match self.cast_certified(motion1, g1, &motion, &plane, start_time, end_time, true) {
            Ok(None) => PastContact::Never,
            Ok(Some(_)) if deep => PastContact::At(start_time),
            Ok(Some(hit)) if hit.time_of_impact > start_time => PastContact::At(hit.time_of_impact),
            _ => PastContact::Unknown,
        }
    }
}
