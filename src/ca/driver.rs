//! The conservative-advancement loop.

use crate::ca::{CaError, CaOutcome, CaParams, CaReport, Contact, ContactCriterion, Witness, Work};
use crate::rounding::{
    advance_down, centre_reach_up, diff_down, lever_up, placed_reach_up, pose_error_up,
    sum_reaches, sum_up,
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
    /// The step's share of the work budget
    /// ([`CaParams::work_budget`], less what earlier steps of the query used)
    /// ran out before a step was certified: the query ends with
    /// [`CaOutcome::WorkLimit`] at `t`.
    WorkLimit,
    /// The bodies are within the contact distance plus what the placement's
    /// rounding can resolve, and the contact distance is below that
    /// `resolution`: no step can be certified, and no distance within the
    /// contact distance trusted. The query ends with
    /// [`CaOutcome::PrecisionLimit`] at `t`.
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
    /// to `[t, t_end]`, in the pair's frame: [`time_of_impact`]). The
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
    /// [`time_of_impact`] charges to the query's
    /// [`work_budget`](CaParams::work_budget) and reports in
    /// [`CaReport::work`]. The default counts nothing; a stepper that wraps
    /// another should forward it (else each step gets the whole budget).
    fn work(&self) -> Work {
        Work::ZERO
    }

    /// Whether the stepper takes these motions, checked once per query
    /// before the first step ([`time_of_impact`] returns the error). The
    /// default takes any.
    ///
    /// # Errors
    /// The stepper's own: [`CaError::TurnedHalfSpace`] for a half-space
    /// that turns.
    fn check_motions(&self, a: &RigidMotion<T>, b: &RigidMotion<T>) -> Result<(), CaError> {
        let _ = (a, b);
        Ok(())
    }

    /// An overlap at the query's start that the steps do not measure: a
    /// body starting inside a solid mesh (`TriMesh::try_solid`,
    /// `proofs/09-ca-toi.md`, Lemma 9.7). [`time_of_impact`] asks once per
    /// query, at its start `t`, after the first step when that step neither
    /// touched nor ran out of work, with the first step's motions and
    /// `params` holding what is left of the budget. A result replaces the
    /// first step's: `Touching` ends the query with
    /// [`CaOutcome::InitialContact`], `WorkLimit` with
    /// [`CaOutcome::WorkLimit`]. The default finds nothing; a stepper that
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
}

/// The first time of contact of two moving bodies over the motions' common
/// interval, by conservative advancement with `stepper`.
///
/// The reported contact time is never later than the true first contact of the
/// exact motions (given a sound stepper): every step is certified contact-free.
///
/// # Errors
/// [`CaError::InvalidParameter`] for bad parameters, [`CaError::IntervalMismatch`]
/// when the motions' intervals differ, and the stepper's own
/// ([`CaStep::check_motions`]).
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
    stepper.check_motions(motion_a, motion_b)?;
    // The pair's frame (`proofs/floating-point.md`, "Pair frame"): the world
    // translated so that A's rotation centre starts at the origin. Every
    // placement's rounding then follows the pair's own extent and motion,
    // not its distance from the world origin; witnesses go back at the end.
    let origin = motion_a.centre();
    let (motion_a, motion_b) = (&motion_a.rebased(origin), &motion_b.rebased(origin));
    let to_world = |w: Witness<T>| Witness {
        on_a: w.on_a + origin.to_vec3(),
        on_b: w.on_b + origin.to_vec3(),
        ..w
    };
    let end = motion_a.interval().end();
    let mut t = motion_a.interval().start();
    let mut iterations = 0;
    let mut last_step: Option<T> = None;
    let work_before = stepper.work();
    let report = |outcome, iterations, work: Work| {
        Ok(CaReport {
            outcome,
            iterations,
            work: work.saturating_sub(work_before),
        })
    };
    loop {
        if iterations == params.max_iterations {
            return report(
                CaOutcome::IterationLimit { time: t },
                iterations,
                stepper.work(),
            );
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
        // What is left of the query's work budget is this step's.
        let used = stepper.work().saturating_sub(work_before);
        let step_params = params.with_work_budget(params.work_budget.saturating_sub(used));
        let mut result = stepper.step(t, &pa, &pb, &step_params);
        if iterations == 1
            && matches!(
                result,
                StepResult::Advance { .. } | StepResult::PrecisionLimit { .. }
            )
        {
            // A body starting inside a solid mesh (Lemma 9.7).
            let used = stepper.work().saturating_sub(work_before);
            let left = params.with_work_budget(params.work_budget.saturating_sub(used));
            if let Some(r) = stepper.initial_overlap(t, &pa, &pb, &left) {
                result = r;
            }
        }
        match result {
            StepResult::WorkLimit => {
                let outcome = CaOutcome::WorkLimit { time: t };
                return report(outcome, iterations, stepper.work());
            }
            StepResult::PrecisionLimit { resolution } => {
                let outcome = CaOutcome::PrecisionLimit {
                    time: t,
                    resolution,
                };
                return report(outcome, iterations, stepper.work());
            }
            StepResult::Touching { witness, normal } => {
                let contact = Contact {
                    time: t,
                    witness: Some(to_world(witness)),
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
                return report(outcome, iterations, stepper.work());
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
                    return report(CaOutcome::Separated, iterations, stepper.work());
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
                        witness: witness.map(to_world),
                        normal: normal.or_else(|| witness.and_then(|w| w.normal())),
                    };
                    return report(
                        CaOutcome::Contact {
                            contact,
                            criterion: ContactCriterion::TimeTolerance,
                        },
                        iterations,
                        stepper.work(),
                    );
                }
                if next <= t {
                    // Time cannot advance any more (a step below its
                    // resolution) within the tolerance of the end.
                    return report(
                        CaOutcome::IterationLimit { time: t },
                        iterations,
                        stepper.work(),
                    );
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
