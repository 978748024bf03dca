//! What a stepper answers, and the certified steps it is built from: the
//! placement's rounding, a gap's step, the precision limit.

use crate::ca::{CaError, CaParams, Witness, Work};
use crate::rounding::{centre_reach_up, lever_up, placed_reach_up, pose_error_up, sum_up};
use crate::{BoundingBall, Direction, Float, PreparedMotion, RigidMotion};

/// What a geometry reports at one time of a conservative-advancement query.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StepResult<T> {
    /// The bodies are within the contact distance.
    Touching {
        /// The closest features found.
        witness: Witness<T>,
        /// The contact normal from A to B, if known.
        normal: Option<Direction<T>>,
    },
    /// The step's share of the work budget
    /// ([`CaParams::work_budget`], less what earlier steps of the query used)
    /// ran out before a step was certified: the query ends with
    /// [`CaOutcome::WorkLimit`](crate::ca::CaOutcome::WorkLimit) at `t`.
    WorkLimit,
    /// The bodies are within the contact distance plus what the placement's
    /// rounding can resolve, and the contact distance is below that
    /// `resolution`: no step can be certified, and no distance within the
    /// contact distance trusted. The query ends with
    /// [`CaOutcome::PrecisionLimit`](crate::ca::CaOutcome::PrecisionLimit) at `t`.
    PrecisionLimit {
        /// What the certified gaps lose to rounding at `t`.
        resolution: T,
    },
    /// The bodies do not touch during `[t, t + step]` (certified).
    Advance {
        /// The safe step; anything at least the rest of the interval means no
        /// contact before its end. `+inf` is allowed (nothing approaches).
        step: T,
        /// The closest features found, if the stepper computed them.
        witness: Option<Witness<T>>,
        /// The separating direction used, from A to B, if any.
        normal: Option<Direction<T>>,
    },
}

/// A geometry that conservative advancement can query: at time `t`, with both
/// motions restricted (and prepared) to the rest of the interval `[t, t_end]`,
/// either "touching" (distance at most `params.contact_distance`) or a step
/// `s` such that the bodies certainly do not touch during `[t, t + s]`.
///
/// The contract is soundness: a returned step must never reach past a true
/// contact of the exact motions. The steppers of this crate meet it with the
/// certified gaps and bounds of `proofs/09-ca-toi.md`; an implementation for
/// another geometry can use [`gap_step`] to turn a separating gap into a step.
pub trait CaStep<T: Float> {
    /// Inspects the pair at time `t` (`a` and `b` are the motions restricted
    /// to `[t, t_end]`, in the pair's frame: [`time_of_impact`](crate::ca::time_of_impact)). The
    /// `params` are the query's, with
    /// [`work_budget`](CaParams::work_budget) what is left of it for this
    /// step.
    fn step(
        &mut self,
        t: T,
        a: &PreparedMotion<T>,
        b: &PreparedMotion<T>,
        params: &CaParams<T>,
    ) -> StepResult<T>;

    /// The work this stepper has done since it was made (a running total
    /// that never decreases between the steps of a query): what
    /// [`time_of_impact`](crate::ca::time_of_impact) charges to the query's
    /// [`work_budget`](CaParams::work_budget) and reports in
    /// [`CaReport::work`](crate::ca::CaReport::work). The default counts nothing; a stepper that wraps
    /// another should forward it (else each step gets the whole budget).
    fn work(&self) -> Work {
        Work::ZERO
    }

    /// An overlap at the query's start that the steps do not measure: a
    /// body starting inside a solid mesh (`TriMesh::try_solid`,
    /// `proofs/09-ca-toi.md`, Lemma 9.7). [`time_of_impact`](crate::ca::time_of_impact) asks once per
    /// query, at its start `t`, after the first step when that step neither
    /// touched nor ran out of work, with the first step's motions and
    /// `params` holding what is left of the budget. A result replaces the
    /// first step's: `Touching` ends the query with
    /// [`CaOutcome::InitialContact`](crate::ca::CaOutcome::InitialContact), `WorkLimit` with
    /// [`CaOutcome::WorkLimit`](crate::ca::CaOutcome::WorkLimit). The default finds nothing; a stepper that
    /// wraps another should forward it.
    fn initial_overlap(
        &mut self,
        t: T,
        a: &PreparedMotion<T>,
        b: &PreparedMotion<T>,
        params: &CaParams<T>,
    ) -> Option<StepResult<T>> {
        let _ = (t, a, b, params);
        None
    }

    /// Balls, each in its body's frame, that hold the two bodies (`None`
    /// when a body has none: a half-space, or a stepper that does not say).
    /// [`time_of_impact`](crate::ca::time_of_impact) steps the balls about the bodies' rotation centres
    /// that hold these (Lemma 9.8 of `proofs/09-ca-toi.md`) where the bodies
    /// turn faster than they translate: whatever a body turns, it stays in
    /// that ball, which only translates. The default has none.
    fn bounding_balls(&self) -> Option<(BoundingBall<T>, BoundingBall<T>)> {
        None
    }

    /// Whether the stepper takes these motions, checked once per query
    /// before the first step ([`time_of_impact`](crate::ca::time_of_impact) returns the error). The
    /// default takes any.
    ///
    /// # Errors
    /// The stepper's own: [`CaError::TurnedHalfSpace`] for a half-space
    /// that turns.
    fn check_motions(&self, a: &RigidMotion<T>, b: &RigidMotion<T>) -> Result<(), CaError> {
        let _ = (a, b);
        Ok(())
    }
}

/// An upper bound of how far a body point within `radius` of the body
/// origin, placed at time `t` by `motion.pose_at(t)` in floating point, is
/// from its exact position (`proofs/floating-point.md`, sections "Pose" and
/// "Orientation"), and an upper bound of the distance from the origin of
/// every placed point (`|x0| + |v| |t| + radius + |c|`, rounded up, with `c`
/// the rotation centre in the body frame).
#[must_use]
pub fn placement_error<T: Float>(motion: &RigidMotion<T>, t: T, radius: T) -> (T, T) {
    let centre_reach = centre_reach_up(
        motion.centre().to_vec3().norm_l1(),
        motion.linear().norm_l1(),
        t,
    );
    let lever = lever_up(radius, motion.local_reach());
    let err = pose_error_up(
        motion.angle_at(t),
        lever,
        centre_reach + motion.local_reach(),
        !motion.orientation().is_identity(),
    );
    // A centre moved into a pair's frame is off the exact one by at most its
    // slack (section "Pair frame").
    let slack = motion.centre_slack();
    let err = if slack > T::ZERO {
        sum_up(err, slack)
    } else {
        err
    };
    (err, placed_reach_up(centre_reach, lever, err))
}

/// A certified safe step from a computed gap along a direction: `gap` is
/// `min_B fl(q . n) - max_A fl(p . n)` over the placed points of both bodies,
/// `err_*`/`reach_*` come from [`placement_error`], and `mu_*` bound the
/// speeds along `n` (the directed bounds of this crate). The step keeps the
/// slab between the bodies wider than `clearance` (use
/// [`CaParams::clearance`]; `0` for "until they touch"). Returns the step and
/// the certified gap (`<= clearance`: no step, `0`).
#[must_use]
pub fn gap_step<T: Float>(gap: T, clearance: T, err: (T, T), reach: (T, T), mu: (T, T)) -> (T, T) {
    let g = crate::rounding::gap_down(gap, err.0, err.1, reach.0 + reach.1);
    (crate::rounding::step_down(g, clearance, mu.0, mu.1), g)
}

/// For a stepper that found a zero step: [`StepResult::PrecisionLimit`] when
/// the placement cannot resolve the clearance (`err`, `reach` as in
/// [`gap_step`]), so that the zero step is the rounding's, not the bodies'.
pub(crate) fn precision_limit<T: Float>(
    step: T,
    clearance: T,
    err: (T, T),
    reach: (T, T),
) -> Option<StepResult<T>> {
    if step > T::ZERO {
        return None;
    }
    let resolution = crate::rounding::resolution_up(err.0, err.1, reach.0 + reach.1);
    (resolution >= clearance || resolution.is_nan())
        .then_some(StepResult::PrecisionLimit { resolution })
}
