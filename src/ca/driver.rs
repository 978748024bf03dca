//! The conservative-advancement loop.

use crate::ca::{CaError, CaOutcome, CaParams, CaReport, Contact, ContactCriterion, Witness};
use crate::rounding::{
    advance_down, centre_reach_up, diff_down, lever_up, placed_reach_up, pose_error_up, sum_reaches,
};
use crate::{Direction, Float, PreparedMotion, RigidMotion};

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
    /// to `[t, t_end]`).
    fn step(
        &mut self,
        t: T,
        a: &PreparedMotion<T>,
        b: &PreparedMotion<T>,
        params: &CaParams<T>,
    ) -> StepResult<T>;
}

/// The first time of contact of two moving bodies over the motions' common
/// interval, by conservative advancement with `stepper`.
///
/// The reported contact time is never later than the true first contact of the
/// exact motions (given a sound stepper): every step is certified contact-free.
///
/// # Errors
/// [`CaError::InvalidParameter`] for bad parameters, [`CaError::IntervalMismatch`]
/// when the motions' intervals differ.
///
/// ```
/// use motion_bound::ca::{time_of_impact, BallPair, CaParams};
/// use motion_bound::{BoundingBall, RigidMotion};
/// // Two unit balls 4 apart; A moves towards B at 3 per unit time: contact at t = 2/3.
/// let ball = BoundingBall::try_new([0.0; 3], 1.0)?;
/// let a = RigidMotion::try_from_arrays([0.0; 3], [3.0, 0.0, 0.0], [0.0, 0.0, 5.0])?;
/// let b = RigidMotion::try_from_arrays([4.0, 0.0, 0.0], [0.0; 3], [1.0, 0.0, 0.0])?;
/// let report = time_of_impact(&mut BallPair::new(ball, ball), &a, &b, &CaParams::default())?;
/// let t = report.outcome.contact().unwrap().time;
/// assert!(t <= 2.0 / 3.0 && t > 2.0 / 3.0 - 1e-4);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn time_of_impact<T: Float, S: CaStep<T> + ?Sized>(
    stepper: &mut S,
    motion_a: &RigidMotion<T>,
    motion_b: &RigidMotion<T>,
    params: &CaParams<T>,
) -> Result<CaReport<T>, CaError> {
    params.validate()?;
    if motion_a.interval() != motion_b.interval() {
        return Err(CaError::IntervalMismatch);
    }
    let end = motion_a.interval().end();
    let mut t = motion_a.interval().start();
    let mut iterations = 0;
    let mut last_step: Option<T> = None;
    let report = |outcome, iterations| {
        Ok(CaReport {
            outcome,
            iterations,
        })
    };
    loop {
        if iterations == params.max_iterations {
            return report(CaOutcome::IterationLimit { time: t }, iterations);
        }
        iterations += 1;
        // The time-resolved step: bounds over [t, horizon] only.
        let horizon = match last_step {
            Some(s) if params.horizon_factor > T::ZERO => {
                let h = t + s * params.horizon_factor;
                if h > t && h < end {
                    h
                } else {
                    end
                }
            }
            _ => end,
        };
        let pa = PreparedMotion::new(&motion_a.restrict(t, horizon)?);
        let pb = PreparedMotion::new(&motion_b.restrict(t, horizon)?);
        match stepper.step(t, &pa, &pb, params) {
            StepResult::Touching { witness, normal } => {
                let contact = Contact {
                    time: t,
                    witness: Some(witness),
                    normal: normal.or_else(|| witness.normal()),
                };
                let outcome = if iterations == 1 {
                    CaOutcome::InitialContact(contact)
                } else {
                    CaOutcome::Contact {
                        contact,
                        criterion: ContactCriterion::Distance,
                    }
                };
                return report(outcome, iterations);
            }
            StepResult::Advance {
                step,
                witness,
                normal,
            } => {
                let step = if step.is_nan() || step < T::ZERO {
                    T::ZERO
                } else {
                    step
                };
                let step = if horizon < end {
                    // The bounds hold over [t, horizon] only: the step is cut
                    // to at most the exact `horizon - t`, and a step cut so is
                    // not an end (`proofs/09-ca-toi.md`, Lemma 9.3).
                    step.min_nan(diff_down(horizon, t))
                } else if sum_reaches(t, step, end) {
                    // [t, t + step] is contact-free and reaches the end, in
                    // exact arithmetic (section "Exact sums").
                    return report(CaOutcome::Separated, iterations);
                } else {
                    step
                };
                last_step = Some(step);
                let next = advance_down(t, step);
                // Within the time tolerance of the end, a short step is no
                // stall: the query goes on, to a contact, `Separated` or the
                // iteration limit.
                let stalled = step <= params.time_tolerance || next <= t;
                if stalled && !sum_reaches(t, params.time_tolerance, end) {
                    let contact = Contact {
                        time: t,
                        witness,
                        normal: normal.or_else(|| witness.and_then(|w| w.normal())),
                    };
                    return report(
                        CaOutcome::Contact {
                            contact,
                            criterion: ContactCriterion::TimeTolerance,
                        },
                        iterations,
                    );
                }
                if next <= t {
                    // Time cannot advance any more (a step below its
                    // resolution) within the tolerance of the end.
                    return report(CaOutcome::IterationLimit { time: t }, iterations);
                }
                t = next;
            }
        }
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
