//! Each body's certified swept box over the frame (`proofs/11-scene.md`,
//! Lemma 11.1), what the broad phase sweeps.

use crate::ca::placement_error;
use crate::rounding::{add_up, diff_up, reach_along_up, sub_down};
use crate::{
    BoundKind, BoundingBall, Direction, Float, HalfSpace, Point3, PreparedMotion, RigidMotion, Vec3,
};

/// An axis-aligned box that holds every point of a body at every time of its
/// motion's interval (`proofs/11-scene.md`, Lemma 11.1).
///
/// Built from the body's bounding ball placed at the start, plus along each
/// of the six axis directions the ball's one-sided rate
/// ([`DirectedProbe::ball_rate`](crate::DirectedProbe::ball_rate), EVQ)
/// times the interval's length, every operation rounded outwards: tighter
/// than the ball grown by `(|v| + |w| r) T`, since a body drifting along
/// `+x` does not grow along `-x`, and its rotation only along the directions
/// its arc sweeps. A body that does not turn takes its exact velocity
/// (`v . e_k = v_k`) and no bound at all; a body that does not move, none
/// either.
///
/// ```
/// use motion_bound::scene::SweptBox;
/// use motion_bound::{BoundingBall, RigidMotion};
/// let ball = BoundingBall::try_new([0.0; 3], 1.0)?;
/// // Drifting along +x at 2 over [0, 1], not turning.
/// let m = RigidMotion::try_from_arrays([0.0; 3], [2.0, 0.0, 0.0], [0.0; 3])?;
/// let b = SweptBox::new(&ball, &m);
/// assert!(b.hi().x >= 3.0 && b.hi().x < 3.0 + 1e-12);
/// assert!(b.lo().x <= -1.0 && b.lo().x > -1.0 - 1e-12); // nothing grows backwards
/// # Ok::<(), motion_bound::InputError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SweptBox<T> {
    pub(super) lo: [T; 3],
    pub(super) hi: [T; 3],
}

/// Which path a swept box took (for the scene's counters).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum BoxPath {
    /// `v = 0` and `w = 0`: the start box, no rate.
    Static,
    /// `w = 0`: exact velocities, no bound and no arc.
    Translating,
    /// Six one-sided EVQ ball rates.
    Turning,
}

impl<T: Float> SweptBox<T> {
    /// The swept box of a body held by `ball` (in the body frame) moving by
    /// `motion` over its interval.
    #[must_use]
    pub fn new(ball: &BoundingBall<T>, motion: &RigidMotion<T>) -> Self {
        Self::with_path(ball, motion).0
    }

    pub(super) fn with_path(ball: &BoundingBall<T>, motion: &RigidMotion<T>) -> (Self, BoxPath) {
        let iv = motion.interval();
        let t0 = iv.start();
        // The ball's centre placed at the start, within `err` of its exact
        // position (`proofs/floating-point.md`, "Pose" and "Orientation").
        let (err, _) = placement_error(motion, t0, ball.outer_radius_up());
        let c = motion
            .pose_at(t0)
            .transform_point(*ball.centre())
            .to_array();
        let rho = ball.radius();
        let mut lo: [T; 3] = core::array::from_fn(|k| sub_down(sub_down(c[k], rho), err));
        let mut hi: [T; 3] = core::array::from_fn(|k| add_up(add_up(c[k], rho), err));
        let (v, w) = (motion.linear().to_array(), motion.angular());
        let path = if w != Vec3::ZERO {
            BoxPath::Turning
        } else if v != [T::ZERO; 3] {
            BoxPath::Translating
        } else {
            BoxPath::Static
        };
        let len = diff_up(iv.end(), t0);
        match path {
            BoxPath::Static => {}
            BoxPath::Translating => {
                for k in 0..3 {
                    hi[k] = add_up(hi[k], reach_along_up(v[k], len));
                    lo[k] = sub_down(lo[k], reach_along_up(-v[k], len));
                }
            }
            BoxPath::Turning => {
                let prepared = PreparedMotion::new(motion);
                for (k, axis) in [Direction::X, Direction::Y, Direction::Z]
                    .into_iter()
                    .enumerate()
                {
                    let up = prepared.probe(axis).ball_rate(ball, BoundKind::Evq);
                    let down = prepared.probe(-axis).ball_rate(ball, BoundKind::Evq);
                    hi[k] = add_up(hi[k], reach_along_up(up, len));
                    lo[k] = sub_down(lo[k], reach_along_up(down, len));
                }
            }
        }
        (Self { lo, hi }, path)
    }

    /// The low corner.
    #[must_use]
    pub fn lo(&self) -> Point3<T> {
        Point3::from_array(self.lo)
    }

    /// The high corner.
    #[must_use]
    pub fn hi(&self) -> Point3<T> {
        Point3::from_array(self.hi)
    }

    /// Whether the boxes are more than `distance` apart along some axis
    /// (certified: the gap is computed rounded down). Bodies in boxes that
    /// are apart by more than the contact distance cannot come within it
    /// during the frame (`proofs/11-scene.md`, Lemma 11.2).
    #[must_use]
    pub fn is_apart(&self, other: &Self, distance: T) -> bool {
        (0..3).any(|k| self.is_apart_along(other, k, distance))
    }

    #[inline]
    pub(super) fn is_apart_along(&self, other: &Self, k: usize, distance: T) -> bool {
        sub_down(other.lo[k], self.hi[k]) > distance || sub_down(self.lo[k], other.hi[k]) > distance
    }
}

/// Half-spaces in the broad phase (`proofs/11-scene.md`, Lemma 11.4).
impl<T: Float> SweptBox<T> {
    /// No point at all (a half-space's place in the sweep: apart from
    /// everything).
    pub(super) fn empty() -> Self {
        Self {
            lo: [T::INFINITY; 3],
            hi: [-T::INFINITY; 3],
        }
    }

    /// Whether the box stays more than `distance` above the plane of the
    /// half-space moving by `motion` (translation only) over the motion's
    /// interval (`proofs/11-scene.md`, Lemma 11.4): its least height along
    /// the normal, rounded down, against the plane's greatest offset over
    /// the frame, rounded up. A turning half-space is never above anything
    /// (its query reports the error).
    pub(super) fn is_above(
        &self,
        half: &HalfSpace<T>,
        motion: &RigidMotion<T>,
        distance: T,
    ) -> bool {
        if motion.angular() != Vec3::ZERO || !motion.orientation().is_identity() {
            return false;
        }
        let m = half.normal().get().to_array();
        // The box's least `x . m` (each term at the corner that minimises it).
        let mut low = T::ZERO;
        for ((&mk, &lo), &hi) in m.iter().zip(&self.lo).zip(&self.hi) {
            let x = if mk >= T::ZERO { lo } else { hi };
            low = add_down(low, mul_down(x, mk));
        }
        // The plane's offset `p . m` at the start, and its rise over the frame.
        let iv = motion.interval();
        let (err, _) = placement_error(motion, iv.start(), T::ZERO);
        let p = motion.pose_at(iv.start()).translation.to_array();
        let mut high = T::ZERO;
        for (&pk, &mk) in p.iter().zip(&m) {
            high = add_up(high, mul_up(pk, mk));
        }
        // `|m| <= 1 + gamma_5 < 2`: the placement error moves the offset by
        // at most `2 err`.
        high = add_up(high, add_up(err, err));
        let v = motion.linear().to_array();
        let mut rise = T::ZERO;
        for (&vk, &mk) in v.iter().zip(&m) {
            rise = add_up(rise, mul_up(vk, mk));
        }
        if rise > T::ZERO {
            high = add_up(high, reach_along_up(rise, diff_up(iv.end(), iv.start())));
        }
        // A height along `m` is at most `|m| <= 1 + 6 u` times the distance.
        let needed = mul_up(distance, T::ONE + T::from_u32(6) * T::UNIT_ROUNDOFF);
        sub_down(low, high) > needed
    }
}

/// `a b` rounded down (`next_down` of the rounded product: at most the
/// exact one, whatever the signs; section "Swept box").
fn mul_down<T: Float>(a: T, b: T) -> T {
    (a * b).next_down()
}

/// `a b` rounded up.
fn mul_up<T: Float>(a: T, b: T) -> T {
    (a * b).next_up()
}

/// `a + b` rounded down.
fn add_down<T: Float>(a: T, b: T) -> T {
    (a + b).next_down()
}
