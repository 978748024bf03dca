//! The rapier pass's touching pairs: the memory carried from step to step
//! and the check of a carried certificate without a cast
//! (`proofs/12-shapes.md`, Lemma 12.14, "The pass's check").

use std::collections::HashMap;

use motion_bound::ca::Ceiling;
use rapier3d_f64::geometry::ColliderHandle;
use rapier3d_f64::math::{Pose, Vector};
use rapier3d_f64::parry::query::NonlinearRigidMotion;

use super::Placed;
use crate::f64::Swept;

/// The pairs touching at a step's start, by their colliders: the normal and
/// the ceiling carried to the next step.
pub(super) type Touchings =
    HashMap<(ColliderHandle, ColliderHandle), (Vector, Ceiling<f64>), PairHash>;

/// A hasher for pairs of collider handles (four `u32`s, not chosen by an
/// adversary): a multiply and a rotate a word, where the default
/// (`SipHash`) costs a fifth of the pass's step in a resting world.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct PairHash;

impl std::hash::BuildHasher for PairHash {
    type Hasher = PairHasher;
    fn build_hasher(&self) -> PairHasher {
        PairHasher(0)
    }
}

/// [`PairHash`]'s hasher.
#[derive(Clone, Copy, Debug)]
pub(super) struct PairHasher(u64);

impl std::hash::Hasher for PairHasher {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(u64::from(b));
        }
    }
    fn write_u32(&mut self, x: u32) {
        self.write_u64(u64::from(x));
    }
    fn write_u64(&mut self, x: u64) {
        self.0 = (self.0.rotate_left(5) ^ x).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }
}

/// The greatest of `dir . x` over `shape` at `pose` (a support map's
/// support point, a mesh's vertices, a compound's parts), `None` for other
/// shapes.
pub(super) fn extent(
    shape: &dyn parry3d_f64::shape::Shape,
    pose: &Pose,
    dir: Vector,
) -> Option<f64> {
    let shape = Swept::see_through(shape);
    if let Some(s) = shape.as_support_map() {
        return Some(dir.dot(s.support_point(pose, dir)));
    }
    if let Some(mesh) = shape.as_trimesh() {
        return mesh
            .vertices()
            .iter()
            .map(|v| dir.dot(pose.transform_point(*v)))
            .reduce(f64::max);
    }
    if let Some(c) = shape.as_compound() {
        let mut best: Option<f64> = None;
        for (p, s) in c.shapes() {
            let e = extent(s.as_ref(), &(*pose * *p), dir)?;
            best = Some(best.map_or(e, |b| b.max(e)));
        }
        return best;
    }
    None
}

impl Placed {
    /// The certificate carried from the last step, checked for this one
    /// without a cast (`proofs/12-shapes.md`, Lemma 12.14, "The pass's
    /// check"): the overlap along `n` (this collider's greatest `n . x`
    /// less `other`'s least) at the start, grown by at most
    /// `((v_a - v_b) . n)^+ dt + min(|w_a| dt, 2) turning_a + min(|w_b| dt,
    /// 2) turning_b` over the step, stays below the ceiling (the carried one
    /// when the pair was held, else the start's overlap plus `d` but no
    /// more than the carried one, or `floor` when that is more). Returns that ceiling (not held), or `None` when the check
    /// does not certify it (the rule then decides with a cast). Rounding:
    /// a few operations on numbers at most `scale`, covered by `1e-9 scale`
    /// as in [`apart_over`](Self::apart_over).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn still_below(
        &self,
        sa: &dyn parry3d_f64::shape::Shape,
        other: &Self,
        sb: &dyn parry3d_f64::shape::Shape,
        n: Vector,
        last: Ceiling<f64>,
        floor: f64,
        d: f64,
        dt: f64,
    ) -> Option<Ceiling<f64>> {
        let hi = extent(sa, &self.motion.start, n)?;
        let lo = -extent(sb, &other.motion.start, -n)?;
        let overlap = hi - lo;
        let ceiling = if last.held {
            last.value
        } else {
            (overlap.max(0.0) + d).min(last.value).max(floor.max(0.0))
        };
        let turn = |m: &NonlinearRigidMotion| (m.angvel.length() * dt).min(2.0);
        let growth = ((self.velocity - other.velocity).dot(n) * dt).max(0.0)
            + (turn(&self.motion) * self.turning + turn(&other.motion) * other.turning)
                * n.length();
        let scale = self.centre.abs().max_element()
            + other.centre.abs().max_element()
            + self.radius
            + other.radius
            + (self.velocity.length() + other.velocity.length()) * dt
            + ceiling.abs();
        // NaN anywhere: not certified.
        (overlap + growth + 1e-9 * scale < ceiling).then_some(Ceiling {
            value: ceiling,
            held: false,
        })
    }
}
