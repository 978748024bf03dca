//! The certified cast: [`cast_shapes_nonlinear`] and the cast of two
//! converted bodies behind it (the contact distance grown by the
//! conversion's rounding, a start within it resolved, the outcome as
//! parry's hit).

use motion_bound::ca::{
    time_of_impact, AnyPair, CaOutcome, CaParams, CaReport, ContactCriterion, MeshWorkspace,
    Shape as Ours,
};

use super::convert::{in_world_axes, rigid_motion, vector, Body};
use super::error::CastError;
use super::parry;
use parry::math::{Real, Vector};
use parry::query::{NonlinearRigidMotion, ShapeCastHit, ShapeCastStatus};
use parry::shape::Shape;

/// Parry's `cast_shapes_nonlinear`, answered by `motion-bound`'s certified
/// conservative advancement with `motion-bound`'s default parameters
/// ([`CaParams::default`]: contact declared within `1e-4`, in your length
/// unit): the same arguments and meaning.
///
/// - `Ok(Some(hit))`: `hit.time_of_impact` is never later than the first
///   time in `[start_time, end_time]` the shapes touch (certified, rounding
///   included), and at it they are within the contact distance (status
///   [`ShapeCastStatus::Converged`]); witnesses and normals in each shape's
///   local frame, as parry's. Touching at `start_time`: the hit at
///   `start_time` with [`ShapeCastStatus::PenetratingOrWithinTargetDist`].
///   Shapes apart at `start_time` but within the contact distance are
///   asked again with a contact distance a quarter of the gap found (up to
///   four times), so that, as with parry's cast, a hit at `start_time`
///   means shapes touching (or closer than the last contact distance
///   tried), not merely close: rapier ignores a hit at fraction `0`, and a
///   body its CCD has just stopped short of a wall starts its next step
///   within the contact distance of it.
///   A query undecided from some time on (its iteration or work budget ran
///   out, or the placement's rounding cannot resolve the contact distance)
///   is a possible contact at that time, [`ShapeCastStatus::OutOfIterations`]
///   ("a conservative approximation", as parry says of it).
/// - `Ok(None)`: no contact anywhere in the interval, certified.
///
/// `stop_at_penetration = false` (parry: a penetration at `start_time` of
/// shapes moving apart is ignored and a later impact sought): a contact at
/// `start_time` is still reported, since no later first contact can be
/// certified while the shapes touch; rapier ignores a hit at fraction `0`
/// of a solid pair, as it does parry's.
///
/// This free function converts both shapes at every call (a mesh's tree is
/// built each time): keep a [`ShapeCache`] (or a [`CertifiedDispatcher`])
/// for meshes.
///
/// [`ShapeCache`]: super::ShapeCache
/// [`CertifiedDispatcher`]: super::CertifiedDispatcher
///
/// # Errors
/// [`CastError`]: an unsupported shape, an invalid shape or motion, or a
/// NaN or infinite time.
pub fn cast_shapes_nonlinear(
    motion1: &NonlinearRigidMotion,
    g1: &dyn Shape,
    motion2: &NonlinearRigidMotion,
    g2: &dyn Shape,
    start_time: Real,
    end_time: Real,
    stop_at_penetration: bool,
) -> Result<Option<ShapeCastHit>, CastError> {
    let b1 = Body::try_new(g1)?;
    let b2 = Body::try_new(g2)?;
    cast_bodies(
        motion1,
        &b1,
        motion2,
        &b2,
        start_time,
        end_time,
        stop_at_penetration,
        &CaParams::default(),
        RESOLVE_ATTEMPTS,
        MeshWorkspace::new(),
    )
    .0
}

/// How many times a cast starting within the contact distance, but apart,
/// is asked again with a contact distance a quarter of the gap found.
pub(super) const RESOLVE_ATTEMPTS: u32 = 4;

/// The certified cast of two converted bodies, with the scratch space
/// handed back.
#[allow(clippy::too_many_arguments)]
pub(super) fn cast_bodies(
    motion1: &NonlinearRigidMotion,
    b1: &Body,
    motion2: &NonlinearRigidMotion,
    b2: &Body,
    start_time: Real,
    end_time: Real,
    _stop_at_penetration: bool,
    params: &CaParams<Real>,
    attempts: u32,
    ws: MeshWorkspace<Real>,
) -> (Result<Option<ShapeCastHit>, CastError>, MeshWorkspace<Real>) {
    if !start_time.is_finite() || !end_time.is_finite() {
        return (Err(CastError::Interval), ws);
    }
    // An empty or reversed interval: parry answers for the start alone.
    let end_time = if end_time > start_time {
        end_time
    } else {
        let bump = start_time.abs().max(1.0) * Real::EPSILON * 4.0;
        start_time + bump
    };
    // A half-space that only translates, turned at the start: its normal
    // taken into the world, its motion a translation (the same plane at
    // every time); `motion-bound` takes half-spaces in the world's axes.
    let world1 = in_world_axes(b1, motion1);
    let world2 = in_world_axes(b2, motion2);
    let (b1, motion1_w) = world1.as_ref().map_or((b1, motion1), |(b, m)| (b, m));
    let (b2, motion2_w) = world2.as_ref().map_or((b2, motion2), |(b, m)| (b, m));
    let motions = rigid_motion(motion1_w, start_time, end_time)
        .and_then(|m1| Ok((m1, rigid_motion(motion2_w, start_time, end_time)?)));
    let (m1, m2) = match motions {
        Ok(m) => m,
        Err(e) => return (Err(e), ws),
    };
    let mut ws = Some(ws);
    let report = b1.with_shape(|s1| {
        b2.with_shape(|s2| {
            let mut pair = AnyPair::try_new(s1, s2)?.with_workspace(ws.take().unwrap_or_default());
            // The contact distance grown by twice the displacements the
            // conversion's rounding may cause (`proofs/12-shapes.md`,
            // "Parry's shapes and motions"), so that the clearance still
            // covers them.
            let slack = rounding_slack(
                (motion1_w, reach_of(&s1)),
                (motion2_w, reach_of(&s2)),
                start_time.abs().max(end_time.abs()),
            );
            let params = &params.with_contact_distance(params.contact_distance + slack);
            let mut r = time_of_impact(&mut pair, &m1, &m2, params);
            // Within the contact distance at the start but apart: asked
            // again with a contact distance below the gap, so that a
            // contact at `start_time` means touching (parry's meaning),
            // and the answer is still never later than the first contact.
            let mut p = *params;
            for _ in 0..attempts {
                let gap = match &r {
                    Ok(CaReport {
                        outcome: CaOutcome::InitialContact(c),
                        ..
                    }) => c.witness.map_or(0.0, |w| w.distance),
                    _ => break,
                };
                p.contact_distance = gap / 4.0 + slack;
                if gap <= 0.0 || p.validate().is_err() {
                    break;
                }
                r = time_of_impact(&mut pair, &m1, &m2, &p);
            }
            ws = Some(pair.into_workspace());
            r
        })
    });
    let ws = ws.unwrap_or_default();
    let report = match report {
        Ok(Ok(Ok(r))) => r,
        Ok(Ok(Err(e))) => return (Err(e.into()), ws),
        Ok(Err(e)) | Err(e) => return (Err(e), ws),
    };
    (Ok(hit(&report.outcome, motion1, motion2, start_time)), ws)
}

/// An upper bound of the distance from its body origin of any point of a
/// shape (`0` for a half-space, whose plane passes through it).
fn reach_of(s: &Ours<'_, Real>) -> Real {
    match s {
        Ours::Convex(c) => c.reach(),
        Ours::Mesh(t) => t.root_ball().centre_norm_up() + t.root_ball().radius(),
        Ours::Compound(c) => c.reach(),
        _ => 0.0,
    }
}

/// Twice how far the conversion's rounding may move a point of either
/// body relative to the other (`proofs/12-shapes.md`, "Parry's shapes and
/// motions"): each rotation centre `c = Q l + T` is computed in floating
/// point, off by at most `8 u (|l| + |T|)`; a half-space turned into the
/// world's axes has a rounded normal, off by at most `8 u` times the
/// distance from its origin of the points that matter (the other body's, at
/// any time of the interval: within the sum of both translations, local
/// centres, reaches and travels). `16 u` times that sum covers both, with
/// a margin for the norms' own rounding; doubled for the clearance.
fn rounding_slack(
    (m1, reach1): (&NonlinearRigidMotion, Real),
    (m2, reach2): (&NonlinearRigidMotion, Real),
    time: Real,
) -> Real {
    let u = Real::EPSILON / 2.0;
    let extent = |m: &NonlinearRigidMotion, reach: Real| {
        m.start.translation.length() + m.local_center.length() + reach + m.linvel.length() * time
    };
    2.0 * 16.0 * u * (extent(m1, reach1) + extent(m2, reach2))
}

/// `motion-bound`'s outcome as parry's hit.
fn hit(
    outcome: &CaOutcome<Real>,
    motion1: &NonlinearRigidMotion,
    motion2: &NonlinearRigidMotion,
    start_time: Real,
) -> Option<ShapeCastHit> {
    let (time, status, contact) = match outcome {
        CaOutcome::Separated => return None,
        CaOutcome::InitialContact(c) => (
            start_time,
            ShapeCastStatus::PenetratingOrWithinTargetDist,
            Some(c),
        ),
        CaOutcome::Contact { contact, criterion } => (
            contact.time,
            if *criterion == ContactCriterion::Distance {
                ShapeCastStatus::Converged
            } else {
                ShapeCastStatus::OutOfIterations
            },
            Some(contact),
        ),
        CaOutcome::IterationLimit { time }
        | CaOutcome::WorkLimit { time }
        | CaOutcome::PrecisionLimit { time, .. } => (*time, ShapeCastStatus::OutOfIterations, None),
        _ => return None,
    };
    let pos1 = motion1.position_at_time(time);
    let pos2 = motion2.position_at_time(time);
    let (mut w1, mut w2, mut n1) = (Vector::ZERO, Vector::ZERO, Vector::X);
    if let Some(c) = contact {
        if let Some(w) = c.witness {
            w1 = pos1.inverse_transform_point(vector(w.on_a.to_vec3()));
            w2 = pos2.inverse_transform_point(vector(w.on_b.to_vec3()));
        }
        if let Some(n) = c.normal {
            n1 = vector(n.get());
        }
    }
    Some(ShapeCastHit {
        time_of_impact: time,
        witness1: w1,
        witness2: w2,
        normal1: pos1.rotation.inverse() * n1,
        normal2: pos2.rotation.inverse() * -n1,
        status,
        subshape1: 0,
        subshape2: 0,
    })
}
