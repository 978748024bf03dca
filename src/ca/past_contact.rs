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
//! answers the question that matters instead, with one cast against a
//! half-space (usually one iteration): with `n` the given direction (the
//! start's contact normal from A to B; any nonzero vector is sound), `hi`
//! the greatest of `n . x` over A and `lo` the least over B at the start,
//! the half-space `n . x >= max(hi, lo) + 3/2 d` (`d` the contact distance),
//! carried along by B's translation, is cast against A's motion.
//! Until the cast's time, A's extent along `n` beyond B's least grows by
//! less than `d` over what it was at the start (`proofs/12-shapes.md`,
//! Lemma 12.11), so nothing thicker than that along `n` is passed through.

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
    params.validate()?;
    // The normal checked (zero, NaN, infinite) as the half-space's.
    HalfSpace::try_new(normal)?;
    if motion_a.interval() != motion_b.interval() {
        return Err(CaError::IntervalMismatch);
    }
    if motion_b.angular() == Vec3::ZERO {
        cast_to_plane(a, motion_a, b, motion_b, normal, params)
    } else if motion_a.angular() == Vec3::ZERO {
        cast_to_plane(b, motion_b, a, motion_a, -normal, params)
    } else {
        Ok(PastContact::Undecided)
    }
}

/// [`past_contact`] with B translating.
fn cast_to_plane<T: Float>(
    a: Shape<'_, T>,
    motion_a: &RigidMotion<T>,
    b: Shape<'_, T>,
    motion_b: &RigidMotion<T>,
    normal: Vec3<T>,
    params: &CaParams<T>,
) -> Result<PastContact<T>, CaError> {
    let d = params.contact_distance;
    let t0 = motion_a.interval().start();
    // The half-space's outward normal as stored; `n` its exact negation,
    // the direction every extent below is taken along.
    let plane = HalfSpace::try_new(-normal)?;
    let n = -plane.normal().get();
    let (Some(hi), Some(neg_lo)) = (
        extent_down(&a, motion_a, t0, n),
        extent_down(&b, motion_b, t0, -n),
    ) else {
        return Ok(PastContact::Undecided);
    };
    // `hi` is at most A's exact greatest `n . x`; `lo = -neg_lo` at most B's
    // exact least (`neg_lo` is rounded up for that: see `extent_down`).
    let lo = -neg_lo;
    let deep = hi > lo + d;
    // The plane's offset, lowered by a margin for the rounding of its point
    // (Lemma 12.11, "Rounding").
    let c = hi.max_nan(lo) + T::from_f64(1.5) * d;
    let v = motion_b.linear();
    let spread = add_up(c.abs(), mul_up(T::TWO * v.norm_l1(), t0.abs()));
    let c = c - mul_up(T::from_u32(16) * T::UNIT_ROUNDOFF, spread).next_up();
    if !c.is_finite() {
        return Ok(PastContact::Undecided);
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
    let report = time_of_impact(&mut pair, motion_a, &carried, params)?;
    // An undecided cast (iteration, work or precision limit) is a possible
    // contact from its time on: still an answer.
    Ok(match report.outcome {
        CaOutcome::Separated => PastContact::Never,
        _ if deep => PastContact::At(t0),
        other => other
            .earliest_possible_contact()
            .map_or(PastContact::Undecided, PastContact::At),
    })
}

/// A float at most the exact greatest `n . x` over `shape` placed by
/// `motion` at `t` (`proofs/12-shapes.md`, Lemma 12.11, "Rounding"): the
/// computed greatest over its support point, vertices or parts, lowered by
/// the placement's error bound and the dot product's, `None` for a
/// half-space or a non-finite value.
fn extent_down<T: Float>(
    shape: &Shape<'_, T>,
    motion: &RigidMotion<T>,
    t: T,
    n: Vec3<T>,
) -> Option<T> {
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
    let slack = add_up(err, mul_up(T::from_u32(16) * T::UNIT_ROUNDOFF, reach));
    let low = e - slack.next_up();
    low.is_finite().then_some(low.next_down())
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
