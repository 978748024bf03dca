//! Conservative advancement of a convex shape against a half-space.

use crate::ca::convex_convex::{advance, certified_gap, closing};
use crate::ca::step::placement_error;
use crate::ca::{CaError, CaParams, CaStep, StepResult, Witness};
use crate::{Convex, Float, HalfSpace, Point3, PreparedMotion, RigidMotion, Vec3};

/// Conservative advancement of a convex shape (body A) against a half-space
/// (body B: the ground, a wall), a [`CaStep`].
///
/// The direction is the half-space's inward normal `-m`, fixed: the slab
/// between the shape and the half-space along it is the shape's least
/// height above the plane (Lemma 9.1 holds because the half-space's extent
/// along `-m` is bounded: its plane), and every point of the half-space
/// moves at its translation's speed along it. The half-space must not turn
/// (`proofs/12-shapes.md`, Lemma 12.3): a half-space whose motion has a
/// start orientation or an angular velocity is
/// [`CaError::TurnedHalfSpace`]; give its normal in the world frame.
///
/// ```
/// use motion_bound::ca::{time_of_impact, CaParams, HalfSpacePair};
/// use motion_bound::{Convex, HalfSpace, RigidMotion, Vec3};
/// // A cylinder tumbling down onto the ground y <= 0.
/// let can = Convex::try_cylinder(0.5, 0.25)?;
/// let ground = HalfSpace::try_new(Vec3::new(0.0, 1.0, 0.0))?;
/// let a = RigidMotion::try_from_arrays([0.0, 2.0, 0.0], [0.0, -4.0, 0.0], [0.0, 0.0, 3.0])?;
/// let b = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0; 3])?;
/// let report = time_of_impact(&mut HalfSpacePair::new(can, ground), &a, &b, &CaParams::default())?;
/// let contact = report.outcome.contact().expect("it lands");
/// // Its lowest point is between its radius and its reach below its centre.
/// let reach = (0.5f64 * 0.5 + 0.25 * 0.25).sqrt();
/// assert!(contact.time >= (2.0 - reach) / 4.0 && contact.time <= (2.0 - 0.25) / 4.0);
/// assert!(contact.witness.expect("measured").on_b.y.abs() < 1e-12); // on the ground
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Copy, Debug)]
pub struct HalfSpacePair<'a, T> {
    shape: Convex<'a, T>,
    half_space: HalfSpace<T>,
}

impl<'a, T: Float> HalfSpacePair<'a, T> {
    /// The shape `shape` (body A) against the half-space `half_space` (body
    /// B).
    #[must_use]
    pub const fn new(shape: Convex<'a, T>, half_space: HalfSpace<T>) -> Self {
        Self { shape, half_space }
    }
}

/// [`CaError::TurnedHalfSpace`] unless the half-space's motion `b` keeps the
/// world's axes (no start orientation, no angular velocity).
pub(crate) fn check_half_space<T: Float>(b: &RigidMotion<T>) -> Result<(), CaError> {
    if b.angular() == Vec3::ZERO && b.orientation().is_identity() {
        Ok(())
    } else {
        Err(CaError::TurnedHalfSpace)
    }
}

impl<T: Float> CaStep<T> for HalfSpacePair<'_, T> {
    fn check_motions(&self, _a: &RigidMotion<T>, b: &RigidMotion<T>) -> Result<(), CaError> {
        check_half_space(b)
    }

    fn step(
        &mut self,
        t: T,
        a: &PreparedMotion<T>,
        b: &PreparedMotion<T>,
        params: &CaParams<T>,
    ) -> StepResult<T> {
        let (pose_a, pose_b) = (a.motion().pose_at(t), b.motion().pose_at(t));
        let m = self.half_space.normal();
        let n = -m;
        // The shape's deepest point along the inward normal, and its height.
        let local = self
            .shape
            .core_support_point(pose_a.inverse_transform_vector(n.get()));
        let deepest = pose_a.transform_point(local.to_vec3()) + n.get() * self.shape.radius();
        let height = (deepest - pose_b.translation).dot(m.get());
        let foot = deepest - m.get() * height;
        let witness = Witness::new(
            height.max_nan(T::ZERO),
            Point3::from_vec3(deepest),
            Point3::from_vec3(foot),
        );
        if height <= params.contact_distance || height.is_nan() {
            return StepResult::Touching {
                witness,
                normal: Some(n),
            };
        }
        let plane = Convex::point();
        let (ea, reach_a) = placement_error(a.motion(), t, self.shape.reach());
        let (eb, reach_b) = placement_error(b.motion(), t, T::ZERO);
        // The half-space's least point along `n` is its plane's: the support
        // of the point at its body origin (Lemma 12.3).
        let g = certified_gap((&self.shape, &pose_a, ea), (&plane, &pose_b, eb), n.get());
        let mu = closing((a, &self.shape), (b, &plane), n, params);
        advance(g, mu, ((ea, eb), (reach_a, reach_b)), params, (witness, n))
    }
}
