//! A pair touching at the start of an interval: does body A go deeper into
//! body B, past the plane that separated them at the start, or does it
//! slide along it or leave?
//!
//! A cast that starts within the contact distance answers
//! [`CaOutcome::InitialContact`](crate::ca::CaOutcome::InitialContact) and
//! says nothing of the rest of the interval. An engine's body resting on,
//! or sliding along, a surface it was stopped at is in that state every
//! step; asking the cast again with a smaller contact distance costs a full
//! query each step (many iterations for a spinning body). [`past_contact`]
//! answers the question that matters instead, with a closed form or one
//! cast against a half-space (usually one iteration): with `n` the given
//! direction (the start's contact normal from A to B; any nonzero vector is
//! sound), the **overlap** is A's greatest `n . x` less B's least. Until
//! the answer's time it stays below a ceiling, the start's overlap (or
//! zero) plus the contact distance `d` (`proofs/12-shapes.md`, Lemmas 12.11
//! and 12.14), so nothing thicker than that along `n` is passed through:
//! first the closed form of how much the overlap may grow over the interval
//! (the relative speed along `n`, each body's turn times its reach), and
//! when that does not decide, the half-space at the ceiling, carried by the
//! body that turns less (lowered by what that turn may move), cast against
//! the other. [`past_contact_below`] is the same rule with a ceiling carried
//! from step to step by an engine's pass (a held pair keeps it, so nothing
//! creeps in a step at a time) and a floor, the engine's allowed
//! penetration.

use crate::ca::{placement_error, time_of_impact, AnyPair, CaError, CaOutcome, CaParams, Shape};
use crate::rounding::{add_up, mul_up};
use crate::{Float, HalfSpace, Point3, Pose, RigidMotion, Vec3};

/// What a pair touching at the start does over the rest of the interval
/// ([`past_contact`]).
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum PastContact<T> {
    /// A's extent along the direction, beyond B's least, never grows by the
    /// contact distance over the interval (certified: it slides along or
    /// leaves).
    Never,
    /// It may from this time on (never later than the first time it does).
    /// The interval's start when A already reaches more than the contact
    /// distance past B's least along the direction (a pair held at the
    /// cast's time every step would otherwise creep in by up to the contact
    /// distance a step).
    At(T),
    /// Not decided: both bodies rotate, a body is a half-space, or a value
    /// overflowed. Ask the full cast again (with a contact
    /// distance below the gap) or hold the body.
    Undecided,
}

/// Whether body A, touching body B at the start of the motions' interval
/// (within the contact distance), goes deeper into B along `normal` (the
/// start's contact normal from A to B; any nonzero vector is sound) over the
/// interval, certified (see the module docs and `proofs/12-shapes.md`,
/// Lemma 12.11). B must not rotate, or A must not (then the roles swap:
/// B is cast against the half-space carried by A, along `-normal`).
///
/// # Errors
/// [`CaError::Input`] for a zero or non-finite `normal`; the parameters'
/// [`CaError::InvalidParameter`]; [`CaError::IntervalMismatch`] for motions
/// over different intervals, as [`time_of_impact`].
///
/// ```
/// use motion_bound::ca::{past_contact, CaParams, PastContact, Shape};
/// use motion_bound::{Convex, RigidMotion, Vec3};
/// // A box spinning fast 5e-5 from a wall's face (x >= 0.5), at the
/// // contact distance 1e-4.
/// let board = Shape::Convex(Convex::try_cuboid([0.1, 0.4, 0.1])?);
/// let wall = Shape::Convex(Convex::try_cuboid([0.5, 2.0, 2.0])?);
/// let p = CaParams::default().with_contact_distance(1e-4);
/// let still = RigidMotion::try_from_arrays([1.0, 0.0, 0.0], [0.0; 3], [0.0; 3])?;
/// let x = [1.0 - 0.5 - 0.1 - 5e-5, 0.0, 0.0];
/// // Sliding along the face: never deeper.
/// let slide = RigidMotion::try_from_arrays(x, [0.0, 3.0, 0.0], [0.0; 3])?;
/// let n = Vec3::new(1.0, 0.0, 0.0);
/// assert_eq!(past_contact(board, &slide, wall, &still, n, &p)?, PastContact::Never);
/// // Pushed in at 2: from the time it is within the contact distance of
/// // the plane 1.5e-4 past the face, 5e-5 + (0.5 to 1.5) e-4 on.
/// let push = RigidMotion::try_from_arrays(x, [2.0, 0.0, 0.0], [0.0; 3])?;
/// match past_contact(board, &push, wall, &still, n, &p)? {
///     PastContact::At(t) => assert!(t >= 0.5e-4 * (1.0 - 1e-9) && t <= 1e-4),
///     other => panic!("{other:?}"),
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn past_contact<T: Float>(
    a: Shape<'_, T>,
    motion_a: &RigidMotion<T>,
    b: Shape<'_, T>,
    motion_b: &RigidMotion<T>,
    normal: Vec3<T>,
    params: &CaParams<T>,
) -> Result<PastContact<T>, CaError> {
    let r = past_contact_below(a, motion_a, b, motion_b, normal, None, T::ZERO, params)?;
    // Stateless: a pair already deeper than the contact distance is held at
    // the start (a caller that stops it at the answer's time every step,
    // with nothing carried, would otherwise let it creep in by `d` a step).
    Ok(match r.answer {
        PastContact::At(_) if r.overlap > params.contact_distance => {
            PastContact::At(motion_a.interval().start())
        }
        other => other,
    })
}

/// The overlap a pair may reach along its direction over a step, carried
/// from step to step by a caller that keeps it ([`past_contact_below`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ceiling<T> {
    /// The overlap along the direction (A's greatest `n . x` less B's
    /// least) the pair stays below.
    pub value: T,
    /// Whether the answer was [`PastContact::At`] (the caller stops the
    /// pair then, or earlier): the next step keeps this ceiling.
    pub held: bool,
}

/// [`past_contact_below`]'s answer, with what it measured.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct Below<T> {
    /// [`PastContact::Never`]: the overlap stays below the ceiling over the
    /// whole interval; [`PastContact::At`]: until that time;
    /// [`PastContact::Undecided`]: nothing certified.
    pub answer: PastContact<T>,
    /// An upper bound of the overlap along the direction at the start.
    pub overlap: T,
    /// The ceiling used (carry it to the next step with the same direction).
    pub ceiling: Ceiling<T>,
    /// Whether a cast was made (`false`: decided by the closed form, or not
    /// at all).
    pub cast: bool,
}

/// For a pair touching at the start of the motions' interval, the certified
/// answer to: does the overlap along `normal` (A's greatest `n . x` less B's
/// least) stay below a ceiling over the interval (`proofs/12-shapes.md`,
/// Lemma 12.14)? The ceiling is `last`'s when the pair was held then
/// ([`Ceiling::held`]): a pair stopped every step cannot creep in; otherwise
/// the start's overlap (or zero) plus the contact distance, no more than
/// `last`'s value when one is carried, or `floor` when that is more: the
/// overlap a solver left may grow by at most the contact distance over a
/// step and never past the ceiling carried (so no run of steps creeps in),
/// and always up to `floor` (an engine's allowed penetration, which its
/// solver leaves resting bodies within; `0` for none).
///
/// First a closed form, no cast: the overlap grows by at most
/// `((v_A - v_B) . n)^+ T + min(|w_A| T, 2) rho_A + min(|w_B| T, 2) rho_B`
/// over an interval of length `T` (`rho` each body's reach from its rotation
/// centre); when that stays below the ceiling the answer is
/// [`PastContact::Never`], whatever both bodies do (a body resting or
/// sliding costs a few support points). Otherwise one cast of A (or B, when
/// only A rotates) against the half-space at the ceiling, as
/// [`past_contact`]; both bodies rotating: [`PastContact::Undecided`].
/// Pass the same `normal` while the ceiling is carried (any nonzero vector
/// is sound).
///
/// # Errors
/// As [`past_contact`].
///
/// ```
/// use motion_bound::ca::{past_contact_below, CaParams, PastContact, Shape};
/// use motion_bound::{Convex, RigidMotion, Vec3};
/// // A box resting 2e-3 deep in a floor (z <= 0), both turning slowly.
/// let cube = Shape::Convex(Convex::try_cuboid([0.5, 0.5, 0.5])?);
/// let floor = Shape::Convex(Convex::try_cuboid([4.0, 4.0, 0.5])?);
/// let p = CaParams::default();
/// let dt = 1.0 / 60.0;
/// let rest = RigidMotion::try_from_start(
///     motion_bound::Isometry::try_new(motion_bound::Rotation::IDENTITY, Vec3::new(0.0, 0.0, 0.498))?,
///     Vec3::new(1e-4, 0.0, -1e-4), Vec3::new(1e-5, 0.0, 0.0), dt)?;
/// let base = RigidMotion::try_from_start(
///     motion_bound::Isometry::try_new(motion_bound::Rotation::IDENTITY, Vec3::new(0.0, 0.0, -0.5))?,
///     Vec3::ZERO, Vec3::new(0.0, 1e-5, 0.0), dt)?;
/// let n = Vec3::new(0.0, 0.0, -1.0);
/// let r = past_contact_below(cube, &rest, floor, &base, n, None, 0.0, &p)?;
/// assert_eq!(r.answer, PastContact::Never);
/// assert!(!r.cast);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[allow(clippy::too_many_arguments)] // the pair, the direction, what is carried
pub fn past_contact_below<T: Float>(
    a: Shape<'_, T>,
    motion_a: &RigidMotion<T>,
    b: Shape<'_, T>,
    motion_b: &RigidMotion<T>,
    normal: Vec3<T>,
    last: Option<Ceiling<T>>,
    floor: T,
    params: &CaParams<T>,
) -> Result<Below<T>, CaError> {
    params.validate()?;
    // The normal checked (zero, NaN, infinite) as the half-space's.
    let plane = HalfSpace::try_new(-normal)?;
    if motion_a.interval() != motion_b.interval() {
        return Err(CaError::IntervalMismatch);
    }
    let d = params.contact_distance;
    // `n` the exact negation of the half-space's stored outward normal: the
    // direction every extent below is taken along.
    let n = -plane.normal().get();
    let t0 = motion_a.interval().start();
    let undecided = |overlap: T| Below {
        answer: PastContact::Undecided,
        overlap,
        ceiling: Ceiling {
            value: T::INFINITY,
            held: false,
        },
        cast: false,
    };
    let (Some((_, hi_up)), Some((_, neg_lo_up))) = (
        extent_bounds(&a, motion_a, t0, n),
        extent_bounds(&b, motion_b, t0, -n),
    ) else {
        return Ok(undecided(T::INFINITY));
    };
    // `lo_down <= m_B` (B's exact least `n . y`), `M_A <= hi_up` (A's exact
    // greatest).
    let lo_down = -neg_lo_up;
    let overlap = (hi_up - lo_down).next_up();
    if !overlap.is_finite() {
        return Ok(undecided(T::INFINITY));
    }
    let ceiling = match last {
        Some(c) if c.held => c.value,
        // Carried, not held: never above the last ceiling (above the
        // floor), so that no run of steps creeps in; `floor` NaN or
        // negative counts as zero.
        Some(c) => add_up(overlap.max_nan(T::ZERO), d)
            .min_nan(c.value)
            .max_nan(floor.max_nan(T::ZERO)),
        None => add_up(overlap.max_nan(T::ZERO), d).max_nan(floor.max_nan(T::ZERO)),
    };
    let held = |answer: PastContact<T>, cast: bool| Below {
        answer,
        overlap,
        ceiling: Ceiling {
            value: ceiling,
            held: matches!(answer, PastContact::At(_)),
        },
        cast,
    };
    // The closed form (Lemma 12.14, Claim 1): no cast.
    let (Some(turn_a), Some(turn_b)) = (turn_up(&a, motion_a), turn_up(&b, motion_b)) else {
        return Ok(held(PastContact::Undecided, false));
    };
    let growth = add_up(linear_up(motion_a, motion_b, n), add_up(turn_a, turn_b));
    if add_up(overlap, growth) < ceiling {
        return Ok(held(PastContact::Never, false));
    }
    // The cast (Claim 2): the body that turns less carries the half-space,
    // lowered by what its turn may move its extent.
    let carried_by_b = turn_b <= turn_a;
    let charge = if carried_by_b { turn_b } else { turn_a };
    // Room below the ceiling at the start; none: held at the start (or
    // undecided, when it is the carrier's turn that takes it).
    let room = ((ceiling - overlap).next_down() - charge).next_down();
    // NaN too: no room.
    if room.partial_cmp(&T::ZERO) != Some(core::cmp::Ordering::Greater) {
        let answer = if charge > T::ZERO {
            PastContact::Undecided
        } else {
            PastContact::At(t0)
        };
        return Ok(held(answer, false));
    }
    let answer = if carried_by_b {
        let offset = ((lo_down + ceiling).next_down() - charge).next_down();
        cast_to_plane(a, motion_a, motion_b, plane, offset, room, params)?
    } else {
        // The roles swapped: B against the half-space `-n . y >= -hi_up +
        // ceiling` carried by A; the same overlap.
        let flipped = HalfSpace::try_new(normal)?;
        let offset = ((-hi_up + ceiling).next_down() - charge).next_down();
        cast_to_plane(b, motion_b, motion_a, flipped, offset, room, params)?
    };
    Ok(held(answer, true))
}

/// The cast of A against the half-space `plane` (outward normal `-n`, `n`
/// the direction) whose inner side starts at `n . x >= offset` and
/// translates with B: [`PastContact::Never`], `At` the cast's earliest
/// possible contact, or `At(t0)` when the room is too small for a contact
/// distance.
fn cast_to_plane<T: Float>(
    a: Shape<'_, T>,
    motion_a: &RigidMotion<T>,
    motion_b: &RigidMotion<T>,
    plane: HalfSpace<T>,
    offset: T,
    room: T,
    params: &CaParams<T>,
) -> Result<PastContact<T>, CaError> {
    let t0 = motion_a.interval().start();
    let n = -plane.normal().get();
    // The plane's offset, lowered by a margin for the rounding of its point
    // (Lemma 12.11, "Rounding").
    let v = motion_b.linear();
    let spread = add_up(offset.abs(), mul_up(T::TWO * v.norm_l1(), t0.abs()));
    let c = offset - mul_up(T::from_u32(16) * T::UNIT_ROUNDOFF, spread).next_up();
    // A contact distance within the room: the cast keeps A more than half of
    // it from the plane, and A starts more than it away.
    let delta = params.contact_distance.min_nan(room * T::HALF);
    let p = params.with_contact_distance(delta);
    if !c.is_finite() || p.validate().is_err() {
        return Ok(PastContact::At(t0));
    }
    // The half-space `n . x >= c` at `t0`, translating with B: its body
    // origin on the plane, at `n c` at `t0`.
    let Ok(carried) = RigidMotion::try_new(
        Point3::from_vec3(n * c - v * t0),
        v,
        Vec3::ZERO,
        motion_a.interval(),
    ) else {
        return Ok(PastContact::Undecided);
    };
    let mut pair = AnyPair::try_new(a, Shape::HalfSpace(plane))?;
    let report = time_of_impact(&mut pair, motion_a, &carried, &p)?;
    // An undecided cast (iteration, work or precision limit) is a possible
    // contact from its time on: still an answer.
    Ok(match report.outcome {
        CaOutcome::Separated => PastContact::Never,
        other => other
            .earliest_possible_contact()
            .map_or(PastContact::Undecided, PastContact::At),
    })
}

/// An upper bound of `((v_A - v_B) . n)^+ T` over the motions' interval
/// of length `T` (Lemma 12.14, Claim 1), rounded up.
fn linear_up<T: Float>(motion_a: &RigidMotion<T>, motion_b: &RigidMotion<T>, n: Vec3<T>) -> T {
    let span = (motion_a.interval().end() - motion_a.interval().start()).next_up();
    let u8 = T::from_u32(8) * T::UNIT_ROUNDOFF;
    // `|fl(v . n) - v . n| <= gamma_3 |v| |n|`, within `4 u |v|_1` each; the
    // difference and the sum one rounding more each.
    let (va, vb) = (motion_a.linear(), motion_b.linear());
    let rel = va.dot(n) - vb.dot(n) + mul_up(u8, add_up(va.norm_l1(), vb.norm_l1()));
    mul_up(rel.next_up().max_nan(T::ZERO), span)
}

/// An upper bound of how far a body's turn over the motion's interval may
/// move its extent along `n` (`|n| <= 1 + 2u`), beyond its rotation
/// centre's travel (Lemma 12.14, Claim 1): `min(|w| T, 2) rho`, `rho` the
/// reach from the rotation centre of what turns: a convex shape's core (its
/// radius around the core adds the same `radius |n|` to the extent at every
/// time), a ball's centre, or every point of the bounding ball. `0` for a
/// body that does not turn; `None` for a half-space.
fn turn_up<T: Float>(s: &Shape<'_, T>, m: &RigidMotion<T>) -> Option<T> {
    let turning = match s {
        Shape::HalfSpace(_) => return None,
        _ if m.angular() == Vec3::ZERO => return Some(T::ZERO),
        Shape::Convex(c) => c.placed_core_reach(),
        Shape::Ball(ball) => ball.centre_norm_up(),
        s => {
            let ball = s.bounding_ball().ok()?;
            add_up(ball.centre_norm_up(), ball.radius())
        }
    };
    let span = (m.interval().end() - m.interval().start()).next_up();
    let rho = add_up(turning, m.local_reach());
    // `|w| <= |w|_1`; the 1-norm's own rounding and `|n|` within a relative
    // `8 u`.
    let angle = mul_up(m.angular().norm_l1().next_up(), span).min_nan(T::TWO);
    let t = mul_up(
        mul_up(angle, rho),
        T::ONE + T::from_u32(8) * T::UNIT_ROUNDOFF,
    );
    t.is_finite().then_some(t)
}

/// Floats at most and at least the exact greatest `n . x` over `shape`
/// placed by `motion` at `t` (`proofs/12-shapes.md`, Lemma 12.11,
/// "Rounding"): the computed greatest over its support point, vertices or
/// parts, lowered and raised by the placement's error bound and the dot
/// product's; `None` for a half-space or a non-finite value.
fn extent_bounds<T: Float>(
    shape: &Shape<'_, T>,
    motion: &RigidMotion<T>,
    t: T,
    n: Vec3<T>,
) -> Option<(T, T)> {
    let ball = match shape {
        Shape::HalfSpace(_) => return None,
        s => s.bounding_ball().ok()?,
    };
    let radius = add_up(ball.centre_norm_up(), ball.radius());
    let (err, reach) = placement_error(motion, t, radius);
    let pose = motion.pose_at(t);
    let e = extent(shape, &pose, n)?;
    // |fl(x . n) - x . n| <= gamma_3 |x| |n| for |x| <= reach, |n| <= 1 + 2u;
    // the radius term adds one product and one sum: 16 u reach covers both.
    let slack = add_up(err, mul_up(T::from_u32(16) * T::UNIT_ROUNDOFF, reach)).next_up();
    let (low, high) = ((e - slack).next_down(), (e + slack).next_up());
    (low.is_finite() && high.is_finite()).then_some((low, high))
}

/// The computed greatest `fl(fl(pose x) . n)` over `shape`'s points at
/// `pose` (a convex shape's support point pushed out by its radius, a vertex
/// set's, a mesh's triangle corners, a compound's parts).
fn extent<T: Float>(shape: &Shape<'_, T>, pose: &Pose<T>, n: Vec3<T>) -> Option<T> {
    let of_points = |points: &mut dyn Iterator<Item = [T; 3]>| {
        points
            .map(|r| pose.transform_point(Vec3::from_array(r)).dot(n))
            .reduce(T::max_nan)
    };
    let convex = |s: &crate::Convex<'_, T>| {
        let local = s.core_support_point(pose.inverse_transform_vector(n));
        (pose.transform_point(local.to_vec3()) + n * s.radius()).dot(n)
    };
    match shape {
        Shape::Convex(s) => Some(convex(s)),
        Shape::VertexSet(s) => of_points(&mut s.vertices().iter().copied()),
        Shape::Ball(ball) => Some(
            pose.transform_point(Vec3::from_array(*ball.centre()))
                .dot(n)
                + ball.radius(),
        ),
        Shape::Mesh(tree) => of_points(&mut tree.whole.leaves.iter().flat_map(|l| l.corners)),
        Shape::Compound(c) => c
            .parts()
            .iter()
            .map(|p| match p {
                crate::ca::Part::Convex(s) => Some(convex(s)),
                crate::ca::Part::Mesh(tree) => {
                    of_points(&mut tree.whole.leaves.iter().flat_map(|l| l.corners))
                }
            })
            .try_fold(-T::INFINITY, |m, e| e.map(|e| m.max_nan(e))),
        Shape::HalfSpace(_) => None,
    }
}
