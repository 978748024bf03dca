//! What a pair touching at the start of a cast does next, on parry's shapes:
//! the core's rule (`motion_bound::ca::past_contact_below`,
//! `proofs/12-shapes.md`, Lemmas 12.11 and 12.14) with parry's contact
//! normal at the start, on the shapes converted as the cast converts them.
//!
//! Rapier ignores a hit at the start of a step (fraction `0`), so a body
//! stopped within the contact distance of a thin wall, pushed on by the
//! solver the next step, would pass through it unchecked. The rule answers
//! whether the pair's overlap along the start's contact normal (A's
//! greatest `n . x` less B's least, an upper bound of the penetration depth)
//! stays below a ceiling: the start's overlap (or zero) plus the contact
//! distance, or, for a caller that carries it (`rapier::CertifiedPass`), the
//! last step's ceiling when the pair was held then. A closed form decides a
//! resting or sliding pair without a cast; otherwise one cast against the
//! half-space at the ceiling, carried by the body that turns less.
//! Heightfields, polylines, voxels, custom shapes and half-spaces are not
//! taken ([`PastContact::Unknown`]).

use motion_bound::ca::{past_contact_below, CaParams, Ceiling, PastContact as Core};

use super::cache::ShapeCache;
use super::convert::{rigid_motion, vec3};
use super::parry;
use super::swept::Swept;
use parry::math::{Real, Vector};
use parry::query::NonlinearRigidMotion;
use parry::shape::Shape;

/// What a pair touching at the start does over the rest of the interval
/// (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum PastContact {
    /// The overlap along the normal stays below the ceiling (certified).
    Never,
    /// It may reach the ceiling from this time on (never later than the
    /// first time it does; the start itself when there is no room).
    At(Real),
    /// Not decided here (both bodies turning too fast, a shape without a
    /// computed extent, no contact normal, or an invalid input).
    Unknown,
}

/// The rule's answer with what a caller carries to the next step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Touching {
    pub(crate) answer: PastContact,
    /// The direction the overlap is taken along (world axes).
    pub(crate) normal: Vector,
    /// The ceiling used, and whether the pair is held.
    pub(crate) ceiling: Ceiling<Real>,
    /// An upper bound of the overlap at the start.
    pub(crate) overlap: Real,
    /// Whether a cast was made (`false`: the closed form decided).
    pub(crate) cast: bool,
}

/// The core's rule on parry's shapes: along `normal` when given, else
/// along parry's contact normal at `start_time` (any direction is sound),
/// with the ceiling `last` carried from the last step (kept when the pair
/// was held then, else the start's overlap plus the contact distance, or
/// `floor` when that is more).
/// `None` when nothing is decided before the rule runs (no contact normal,
/// a shape or motion the conversion refuses).
#[allow(clippy::too_many_arguments)]
pub(crate) fn past_contact_below_parry(
    cache: &ShapeCache,
    params: &CaParams<Real>,
    motion1: &NonlinearRigidMotion,
    g1: &dyn Shape,
    motion2: &NonlinearRigidMotion,
    g2: &dyn Shape,
    start_time: Real,
    end_time: Real,
    normal: Option<Vector>,
    last: Option<Ceiling<Real>>,
    floor: Real,
) -> Option<Touching> {
    let span = end_time - start_time;
    // NaN or an empty interval: not decided.
    if span.is_nan() || span <= 0.0 {
        return None;
    }
    let normal = match normal {
        Some(n) => n,
        None => {
            let (s1, s2) = (Swept::see_through(g1), Swept::see_through(g2));
            let (p1, p2) = (
                motion1.position_at_time(start_time),
                motion2.position_at_time(start_time),
            );
            let d = params.contact_distance;
            let Ok(Some(c)) = parry::query::contact(&p1, s1, &p2, s2, 4.0 * d) else {
                return None;
            };
            c.normal1
        }
    };
    if !normal.is_finite() || (normal.length() - 1.0).abs() > 1e-3 {
        return None;
    }
    let (b1, b2) = (cache.body(g1).ok()?, cache.body(g2).ok()?);
    let m1 = rigid_motion(motion1, start_time, end_time).ok()?;
    let m2 = rigid_motion(motion2, start_time, end_time).ok()?;
    let below = b1
        .with_shape(|s1| {
            b2.with_shape(|s2| {
                past_contact_below(s1, &m1, s2, &m2, vec3(normal), last, floor, params)
            })
        })
        .ok()?
        .ok()?
        .ok()?;
    let answer = match below.answer {
        Core::Never => PastContact::Never,
        Core::At(t) => PastContact::At(t),
        _ => PastContact::Unknown,
    };
    Some(Touching {
        answer,
        normal,
        ceiling: below.ceiling,
        overlap: below.overlap,
        cast: below.cast,
    })
}

/// The rule with nothing carried, for a caller that keeps no state
/// (rapier's CCD through the dispatcher): as
/// [`past_contact_below_parry`], and a pair already deeper than the contact
/// distance at the start is held there when it may go deeper (stopped at
/// the answer's time every step, it would otherwise creep in by up to the
/// contact distance a step).
#[allow(clippy::too_many_arguments)]
pub(crate) fn past_contact_parry(
    cache: &ShapeCache,
    params: &CaParams<Real>,
    motion1: &NonlinearRigidMotion,
    g1: &dyn Shape,
    motion2: &NonlinearRigidMotion,
    g2: &dyn Shape,
    start_time: Real,
    end_time: Real,
) -> PastContact {
    let Some(t) = past_contact_below_parry(
        cache, params, motion1, g1, motion2, g2, start_time, end_time, None, None, 0.0,
    ) else {
        return PastContact::Unknown;
    };
    match t.answer {
        PastContact::At(_) if t.overlap > params.contact_distance => PastContact::At(start_time),
        other => other,
    }
}
