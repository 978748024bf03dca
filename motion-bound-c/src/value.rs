//! Motions by value: `mb_motion_value`, a plain struct the caller owns (no
//! handle, no allocation, no registry), and the pair queries that take it.
//! An engine's certified pass makes one per body per step; the handles of
//! `mb_motion_*` cost a registry entry and an allocation each (issue 64:
//! 2.6 K instructions a body a step in Bullet's resting stack).

use motion_bound::ca::{past_contact_below, Ceiling, PastContact};
use motion_bound::{Isometry, Point3, RigidMotion};

use crate::error::{guard, motion_input, Failure, MbStatus, Res};
use crate::motion::{MbPose, MbQuat, MbVec3};
use crate::ptr::{handle_ref, read_in, write_out, Plain};
use crate::query::{
    one, pair_failure, touching_rule, MbBelowReport, MbCeiling, MbParams, MbPastOutcome, MbReport,
};
use crate::shape::MbShape;

/// A rigid motion over `[0, duration]` by value: the body turns about its
/// body point `local_centre` (its centre of mass, or `{0, 0, 0}` for its
/// origin), that point at the world position `centre` at `t = 0` and moving
/// at `linear`, the body at the orientation `rotation` at `t = 0` and
/// turning at `angular` (world vectors, radians per unit time):
/// `p(t) = centre + linear t + R(angular t) rotation (r - local_centre)`,
/// exactly the motion `mb_motion_about_centre` makes a handle of.
///
/// A plain struct the caller owns: fill it directly, or with
/// `mb_motion_value_between` / `mb_motion_value_between_about`; nothing to
/// free. Each query that takes one checks it (`MB_STATUS_INVALID_INPUT`
/// for a NaN or infinite component, a zero quaternion, `duration <= 0`,
/// the message naming the field: `motion_a.linear.y`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MbMotionValue {
    /// The world position of the point the body turns about, at `t = 0`.
    pub centre: MbVec3,
    /// That point in the body's frame.
    pub local_centre: MbVec3,
    /// The body's orientation at `t = 0` (any finite nonzero quaternion; it
    /// is normalised).
    pub rotation: MbQuat,
    /// The linear velocity of `centre`.
    pub linear: MbVec3,
    /// The angular velocity (world axis times radians per unit time).
    pub angular: MbVec3,
    /// The interval's length (positive).
    pub duration: f64,
}

// SAFETY: a `repr(C)` struct of `f64`s: every bit pattern is a value.
unsafe impl Plain for MbMotionValue {}

impl MbMotionValue {
    /// The value of a motion that turns about `local_centre` (the fields
    /// the motion keeps, so that [`motion`](Self::motion) makes it again).
    fn of(m: &RigidMotion<f64>) -> Self {
        let q = m.orientation().quaternion();
        Self {
            centre: MbVec3::from_array(m.centre().to_array()),
            local_centre: MbVec3::from_array(m.local_centre().to_array()),
            rotation: MbQuat {
                w: q[0],
                x: q[1],
                y: q[2],
                z: q[3],
            },
            linear: MbVec3::from_array(m.linear().to_array()),
            angular: MbVec3::from_array(m.angular().to_array()),
            duration: m.interval().end(),
        }
    }

    /// The motion this value stands for, every field checked; errors name
    /// the argument `what` and the field (`motion_a.angular.z`).
    pub(crate) fn motion(&self, what: &str) -> Res<RigidMotion<f64>> {
        // The same computation with no name formatted, when nothing fails
        // (a pass calls this for every pair); else again, naming the field.
        let q = self.rotation;
        if let Ok(r) = motion_bound::Rotation::try_from_quaternion(q.w, q.x, q.y, q.z) {
            if let Ok(m) = RigidMotion::try_about_centre(
                Point3::from_array(self.centre.array()),
                self.local_centre.vec(),
                r,
                self.linear.vec(),
                self.angular.vec(),
                self.duration,
            ) {
                return Ok(m);
            }
        }
        let centre = self.centre.checked(&format!("{what}.centre"))?;
        let local = self.local_centre.checked(&format!("{what}.local_centre"))?;
        let r = self.rotation.rotation(&format!("{what}.rotation"))?;
        let linear = self.linear.checked(&format!("{what}.linear"))?;
        let angular = self.angular.checked(&format!("{what}.angular"))?;
        motion_bound::ca::ArgError::positive(self.duration, &format!("{what}.duration"))?;
        RigidMotion::try_about_centre(
            Point3::from_array(centre.to_array()),
            local,
            r,
            linear,
            angular,
            self.duration,
        )
        .map_err(|e| {
            let f = motion_input(e);
            Failure::new(f.status, format!("{what}: {}", f.message))
        })
    }
}

/// The motion value read from `ptr` (the argument `what`), checked.
///
/// # Safety
/// `ptr` is `NULL` or valid for reading an `mb_motion_value`.
unsafe fn value_at(ptr: *const MbMotionValue, what: &str) -> Res<RigidMotion<f64>> {
    // SAFETY: `ptr` is NULL or readable (this function's contract).
    match unsafe { read_in(ptr, what) }? {
        Some(v) => v.motion(what),
        None => Err(Failure::new(
            MbStatus::NullPointer,
            format!("{what} is NULL"),
        )),
    }
}

/// As `mb_motion_between_about` (the motion with constant velocities from
/// the pose `start` at `t = 0` to `end` at `t = duration`, turning about the
/// body point `local_centre` by the shortest rotation), written by value to
/// `*out`: no handle, nothing to free. A query makes the motion again from
/// the fields (its quaternion normalised again): the same motion up to that
/// rounding, and exactly the one it certifies.
///
/// `MB_STATUS_INVALID_INPUT` for a NaN or infinite component, a zero
/// quaternion or `duration <= 0`; `MB_STATUS_NULL_POINTER` for
/// `out == NULL`.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `out` is `NULL` or valid for writing an `mb_motion_value`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_motion_value_between_about(
    start: MbPose,
    end: MbPose,
    duration: f64,
    local_centre: MbVec3,
    out: *mut MbMotionValue,
) -> MbStatus {
    guard(|| {
        let (start, end) = (start.isometry("start")?, end.isometry("end")?);
        let local = local_centre.checked("local_centre")?;
        let value = between(start, end, duration, local)?;
        // SAFETY: `out` is NULL or writable (this function's contract).
        unsafe { write_out(out, value, "out") }
    })
}

/// As `mb_motion_between` (turning about the body origin), by value: the
/// value of `mb_motion_value_between_about` with `local_centre` zero.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `out` is `NULL` or valid for writing an `mb_motion_value`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_motion_value_between(
    start: MbPose,
    end: MbPose,
    duration: f64,
    out: *mut MbMotionValue,
) -> MbStatus {
    guard(|| {
        let (start, end) = (start.isometry("start")?, end.isometry("end")?);
        let value = between(start, end, duration, motion_bound::Vec3::ZERO)?;
        // SAFETY: `out` is NULL or writable (this function's contract).
        unsafe { write_out(out, value, "out") }
    })
}

fn between(
    start: Isometry<f64>,
    end: Isometry<f64>,
    duration: f64,
    local: motion_bound::Vec3<f64>,
) -> Res<MbMotionValue> {
    motion_bound::ca::ArgError::positive(duration, "duration")?;
    let m = RigidMotion::try_between_about(start, end, duration, local).map_err(motion_input)?;
    Ok(MbMotionValue::of(&m))
}

/// `mb_time_of_impact` with motions by value (`motion_a`, `motion_b` point
/// to `mb_motion_value`s, over the same `duration`): the same report, bit
/// for bit, as `mb_time_of_impact` with the handles `mb_motion_about_centre`
/// makes of the same fields. Errors as
/// `mb_time_of_impact`, and `MB_STATUS_NULL_POINTER` for a `NULL` motion,
/// `MB_STATUS_INVALID_INPUT` for a motion value that is not one (named).
///
/// **Thread safety**: any thread; everything read may be shared.
///
/// # Safety
/// The shape handles are not freed during the call; `motion_a`, `motion_b`
/// and `params` are `NULL` or valid for reading; `out` is `NULL` or valid
/// for writing an `mb_report`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_time_of_impact_values(
    shape_a: *const MbShape,
    motion_a: *const MbMotionValue,
    shape_b: *const MbShape,
    motion_b: *const MbMotionValue,
    params: *const MbParams,
    out: *mut MbReport,
) -> MbStatus {
    guard(|| {
        // SAFETY: the handles are not freed during the call, the rest is
        // NULL or readable (this function's contract).
        let (sa, ma, sb, mb, p) = unsafe {
            (
                handle_ref(shape_a, "shape_a")?,
                value_at(motion_a, "motion_a")?,
                handle_ref(shape_b, "shape_b")?,
                value_at(motion_b, "motion_b")?,
                read_in(params, "params")?,
            )
        };
        let p = crate::query::params(p)?;
        let report =
            one(&sa.data, &ma, &sb.data, &mb, &p, &mut None).map_err(|e| pair_failure(e, ""))?;
        // SAFETY: `out` is NULL or writable (this function's contract).
        unsafe { write_out(out, report, "out") }
    })
}

/// `mb_past_contact_below` with motions by value: the same answer, bit for
/// bit, as `mb_past_contact_below` with the handles `mb_motion_about_centre`
/// makes of the same fields. Errors as
/// `mb_past_contact_below`, and `MB_STATUS_NULL_POINTER` for a `NULL`
/// motion, `MB_STATUS_INVALID_INPUT` for a motion value that is not one.
///
/// **Thread safety**: any thread; everything read may be shared.
///
/// # Safety
/// The shape handles are not freed during the call; `motion_a`,
/// `motion_b`, `last` and `params` are `NULL` or valid for reading; `out`
/// is `NULL` or valid for writing an `mb_below_report`.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn mb_past_contact_below_values(
    shape_a: *const MbShape,
    motion_a: *const MbMotionValue,
    shape_b: *const MbShape,
    motion_b: *const MbMotionValue,
    normal: MbVec3,
    last: *const MbCeiling,
    floor: f64,
    params: *const MbParams,
    out: *mut MbBelowReport,
) -> MbStatus {
    guard(|| {
        // SAFETY: the handles are not freed during the call, the rest is
        // NULL or readable (this function's contract).
        let (sa, ma, sb, mb, last, p) = unsafe {
            (
                handle_ref(shape_a, "shape_a")?,
                value_at(motion_a, "motion_a")?,
                handle_ref(shape_b, "shape_b")?,
                value_at(motion_b, "motion_b")?,
                read_in(last, "last")?,
                read_in(params, "params")?,
            )
        };
        let report = below_report((&sa.data, &ma, &sb.data, &mb), normal, last, floor, p)?;
        // SAFETY: `out` is NULL or writable (this function's contract).
        unsafe { write_out(out, report, "out") }
    })
}

/// `mb_past_contact_below`'s answer once its arguments are read (shared by
/// the handle and the value entry points).
pub(crate) fn below_report(
    bodies: (
        &motion_bound::ca::OwnedShape<f64>,
        &RigidMotion<f64>,
        &motion_bound::ca::OwnedShape<f64>,
        &RigidMotion<f64>,
    ),
    normal: MbVec3,
    last: Option<MbCeiling>,
    floor: f64,
    p: Option<MbParams>,
) -> Res<MbBelowReport> {
    let last = last.map(|c| Ceiling {
        value: c.value,
        held: c.held != 0,
    });
    let below = touching_rule(bodies, normal, p, |a, ma, b, mb, n, p| {
        past_contact_below(a, ma, b, mb, n, last, floor, p)
    })?;
    let (outcome, time) = match below.answer {
        PastContact::Never => (MbPastOutcome::Never, f64::NAN),
        PastContact::At(t) => (MbPastOutcome::At, t),
        _ => (MbPastOutcome::Undecided, f64::NAN),
    };
    Ok(MbBelowReport {
        outcome,
        time,
        overlap: below.overlap,
        ceiling: MbCeiling {
            value: below.ceiling.value,
            held: u32::from(below.ceiling.held),
        },
        cast: u32::from(below.cast),
    })
}
