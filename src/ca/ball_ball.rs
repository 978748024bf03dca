//! The simplest stepper: two bounding balls.

use crate::ca::step::{gap_step, placement_error, precision_limit};
use crate::ca::{CaParams, CaStep, StepResult, Witness};
use crate::{BoundingBall, Direction, Float, Point3, PreparedMotion, Vec3};

/// Conservative advancement of two balls (each given relative to its body's
/// rotation centre): exact sphere distance, `O(1)` directed bounds.
///
/// Useful on its own for sphere-bounded bodies, and as the broad phase of a
/// pair: a ball pair that separates over the interval certifies its bodies do.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BallPair<T> {
    a: BoundingBall<T>,
    b: BoundingBall<T>,
}

impl<T: Float> BallPair<T> {
    /// The pair of balls `a` (on body A) and `b` (on body B).
    #[must_use]
    pub const fn new(a: BoundingBall<T>, b: BoundingBall<T>) -> Self {
        Self { a, b }
    }

    /// The balls' radii.
    pub(crate) const fn radii(&self) -> (T, T) {
        (self.a.radius(), self.b.radius())
    }
}

impl<T: Float> CaStep<T> for BallPair<T> {
    fn bounding_balls(&self) -> Option<(BoundingBall<T>, BoundingBall<T>)> {
        Some((self.a, self.b))
    }

    fn step(
        &mut self,
        t: T,
        a: &PreparedMotion<T>,
        b: &PreparedMotion<T>,
        params: &CaParams<T>,
    ) -> StepResult<T> {
        let ca = a.motion().pose_at(t).transform_point(*self.a.centre());
        let cb = b.motion().pose_at(t).transform_point(*self.b.centre());
        let d = cb - ca;
        let len = d.length();
        let (ra, rb) = (self.a.radius(), self.b.radius());
        let dist = (len - ra - rb).max_nan(T::ZERO);
        let Ok(n) = Direction::try_new(d) else {
            return touching(ca, cb, dist);
        };
        let nv = n.get();
        let witness = Witness {
            distance: dist,
            on_a: Point3::from_array((ca + nv * ra).to_array()),
            on_b: Point3::from_array((cb - nv * rb).to_array()),
        };
        if dist <= params.contact_distance {
            return StepResult::Touching {
                witness,
                normal: Some(n),
            };
        }
        let (ea, pa) = placement_error(a.motion(), t, self.a.outer_radius_up());
        let (eb, pb) = placement_error(b.motion(), t, self.b.outer_radius_up());
        let kind = params.bound.cheap_kind();
        // A ball centred on its body's rotation centre only translates: its
        // support along n moves at the centre's rate, whatever the body
        // turns (Lemma 9.8); any other ball at the rate of its points.
        let centred = |ball: &BoundingBall<T>, m: &PreparedMotion<T>| {
            *ball.centre() == m.motion().local_centre().to_array()
        };
        let (ca_on, cb_on) = (centred(&self.a, a), centred(&self.b, b));
        // One-sided (Lemma 10.2): A along n, B along -n.
        let (mu_a, mu_b) = if params.one_sided {
            let (pa, pb) = (a.probe(n), b.probe(-n));
            (
                if ca_on {
                    pa.centre_rate()
                } else {
                    pa.ball_rate(&self.a, kind)
                },
                if cb_on {
                    pb.centre_rate()
                } else {
                    pb.ball_rate(&self.b, kind)
                },
            )
        } else {
            let (pa, pb) = (a.probe(n), b.probe(n));
            (
                if ca_on {
                    pa.centre_speed()
                } else {
                    pa.ball_speed(&self.a, kind)
                },
                if cb_on {
                    pb.centre_speed()
                } else {
                    pb.ball_speed(&self.b, kind)
                },
            )
        };
        // Along n the balls span [ca.n - ra, ca.n + ra] and [cb.n - rb, cb.n + rb].
        let gap = d.dot(nv) - ra - rb;
        let (step, _) = gap_step(gap, params.clearance(), (ea, eb), (pa, pb), (mu_a, mu_b));
        if let Some(limit) = precision_limit(step, params.clearance(), (ea, eb), (pa, pb)) {
            return limit;
        }
        StepResult::Advance {
            step,
            witness: Some(witness),
            normal: Some(n),
        }
    }
}

fn touching<T: Float>(ca: Vec3<T>, cb: Vec3<T>, dist: T) -> StepResult<T> {
    StepResult::Touching {
        witness: Witness {
            distance: dist,
            on_a: Point3::from_array(ca.to_array()),
            on_b: Point3::from_array(cb.to_array()),
        },
        normal: None,
    }
}
