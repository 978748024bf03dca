//! The conservative-advancement loop.

use crate::ca::step::{CaStep, StepResult};
use crate::ca::{
    BallPair, CaError, CaOutcome, CaParams, CaReport, Contact, ContactCriterion, Witness, Work,
};
use crate::rounding::{advance_down, diff_down, offset_radius_up, sum_reaches, sum_up};
use crate::{BoundingBall, Float, Point3, PreparedMotion, RigidMotion, Vec3};

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
    let max_iterations = params.iteration_limit(motion_a, motion_b);
    let mut swept = Swept::new(stepper.bounding_balls(), motion_a, motion_b);
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
        if iterations == max_iterations {
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
        let mut result = swept.step(stepper, t, (&pa, &pb), &step_params);
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

/// The balls about both bodies' rotation centres that hold them (Lemma 9.8
/// of `proofs/09-ca-toi.md`), and whether the bodies turn much faster than
/// they translate.
struct Swept<T> {
    balls: Option<BallPair<T>>,
    /// Step the balls alone: the bodies' turning speeds (`|w| rho`) are at
    /// least four times their relative translation speed, so the balls'
    /// step, where they are apart, is the better one (below that the
    /// stepper's is taken too, and the longer kept: the factor keeps the
    /// knots' Table 1 counts, `docs/performance.md`).
    alone: bool,
}

impl<T: Float> Swept<T> {
    fn new(
        balls: Option<(BoundingBall<T>, BoundingBall<T>)>,
        a: &RigidMotion<T>,
        b: &RigidMotion<T>,
    ) -> Self {
        let turning = a.angular_speed() > T::ZERO || b.angular_speed() > T::ZERO;
        let about = |ball: BoundingBall<T>, m: &RigidMotion<T>| {
            let c = m.local_centre();
            let d = Vec3::from_array(*ball.centre()) - c;
            let radius = sum_up(offset_radius_up(d.dot(d)), ball.radius());
            BoundingBall::try_new(Point3::from_vec3(c), radius).ok()
        };
        let balls = balls
            .filter(|_| turning)
            .and_then(|(ba, bb)| Some(BallPair::new(about(ba, a)?, about(bb, b)?)));
        let alone = balls.as_ref().is_some_and(|p| {
            let (ra, rb) = p.radii();
            let spin = a.angular_speed() * ra + b.angular_speed() * rb;
            spin >= T::from_u32(4) * (a.linear() - b.linear()).length()
        });
        Self { balls, alone }
    }

    /// The step at `t`: the balls' where they are apart (a step longer than
    /// the time tolerance), alone when the bodies turn fast, else the
    /// longer of theirs and the stepper's; the stepper's where they are not.
    fn step<S: CaStep<T> + ?Sized>(
        &mut self,
        stepper: &mut S,
        t: T,
        (a, b): (&PreparedMotion<T>, &PreparedMotion<T>),
        params: &CaParams<T>,
    ) -> StepResult<T> {
        let ball_step = match self.balls.as_mut().map(|p| p.step(t, a, b, params)) {
            Some(StepResult::Advance { step, .. }) if step > params.time_tolerance => Some(step),
            _ => None,
        };
        let Some(ball_step) = ball_step else {
            return stepper.step(t, a, b, params);
        };
        if self.alone {
            return StepResult::Advance {
                step: ball_step,
                witness: None,
                normal: None,
            };
        }
        match stepper.step(t, a, b, params) {
            StepResult::Advance {
                step,
                witness,
                normal,
            } => StepResult::Advance {
                // Both are certified: the longer (a NaN step, the balls').
                step: if step >= ball_step { step } else { ball_step },
                witness,
                normal,
            },
            other => other,
        }
    }
}
