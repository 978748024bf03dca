//! Vectors, poses and motions.

use motion_bound::{BodyPoint, Isometry, Point3, RigidMotion, Rotation, Vec3};

use motion_bound::ca::ArgError;

use crate::error::{guard, motion_input, MbStatus, Res};
use crate::ptr::{free_handle, handle_ref, write_handle, write_out, Handle, Plain};

/// A vector or point `(x, y, z)`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MbVec3 {
    /// x.
    pub x: f64,
    /// y.
    pub y: f64,
    /// z.
    pub z: f64,
}

/// A rotation as a quaternion `w + x i + y j + z k`; any finite nonzero
/// quaternion (it is normalised). The identity is `{1, 0, 0, 0}`: a
/// zero-filled quaternion is refused (`MB_STATUS_INVALID_INPUT`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MbQuat {
    /// The real part.
    pub w: f64,
    /// i.
    pub x: f64,
    /// j.
    pub y: f64,
    /// k.
    pub z: f64,
}

/// A rigid pose: a body's frame turned by `rotation`, its origin at
/// `translation` (`p_world = R p_body + translation`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MbPose {
    /// The origin's position.
    pub translation: MbVec3,
    /// The orientation.
    pub rotation: MbQuat,
}

// SAFETY: `repr(C)` structs of `f64`s: every bit pattern is a value.
unsafe impl Plain for MbVec3 {}
// SAFETY: as above.
unsafe impl Plain for MbPose {}

impl MbVec3 {
    pub(crate) const fn vec(self) -> Vec3<f64> {
        Vec3::new(self.x, self.y, self.z)
    }

    /// The vector of the argument `what`, its components finite (else an
    /// error naming the component: `linear.y`).
    pub(crate) fn checked(self, what: &str) -> Res<Vec3<f64>> {
        // The name is formatted only for an error (an engine's step calls
        // this for every body: formatting cost as much as the cast).
        for (c, x) in ["x", "y", "z"].iter().zip(self.array()) {
            if !x.is_finite() {
                ArgError::finite(x, &format!("{what}.{c}"))?;
            }
        }
        Ok(self.vec())
    }

    pub(crate) const fn array(self) -> [f64; 3] {
        [self.x, self.y, self.z]
    }

    pub(crate) const fn from_array(a: [f64; 3]) -> Self {
        Self {
            x: a[0],
            y: a[1],
            z: a[2],
        }
    }
}

impl MbQuat {
    /// The rotation of the argument `what`; errors name it (and the
    /// component: `start.rotation.w`).
    pub(crate) fn rotation(self, what: &str) -> Res<Rotation<f64>> {
        for (c, x) in ["w", "x", "y", "z"]
            .iter()
            .zip([self.w, self.x, self.y, self.z])
        {
            if !x.is_finite() {
                ArgError::finite(x, &format!("{what}.{c}"))?;
            }
        }
        Ok(
            Rotation::try_from_quaternion(self.w, self.x, self.y, self.z)
                .map_err(ArgError::input(what))?,
        )
    }
}

impl MbPose {
    /// The placement of the argument `what` (`start`, `poses[2]`); errors
    /// name it and the field (`start.translation.x`, `poses[2].rotation`).
    pub(crate) fn isometry(self, what: &str) -> Res<Isometry<f64>> {
        // The same computation with no name formatted, when nothing fails;
        // else again below, naming the argument.
        let (q, t) = (self.rotation, self.translation);
        if [q.w, q.x, q.y, q.z, t.x, t.y, t.z]
            .iter()
            .all(|x| x.is_finite())
        {
            if let Some(pose) = Rotation::try_from_quaternion(q.w, q.x, q.y, q.z)
                .ok()
                .and_then(|r| Isometry::try_new(r, t.vec()).ok())
            {
                return Ok(pose);
            }
        }
        let r = self.rotation.rotation(&format!("{what}.rotation"))?;
        let t = self.translation.checked(&format!("{what}.translation"))?;
        Ok(Isometry::try_new(r, t).map_err(ArgError::input(what))?)
    }
}

/// A rigid motion over `[0, duration]`: constant linear and angular
/// velocity (a screw motion), the exact motion the queries bound. Opaque;
/// made by `mb_motion_*`, freed by `mb_motion_free`; immutable.
#[derive(Debug)]
pub struct MbMotion {
    pub(crate) motion: RigidMotion<f64>,
}

impl Handle for MbMotion {
    const KIND: crate::ptr::Kind = crate::ptr::Kind::Motion;
    const NAME: &'static str = "the motion";
}

/// The motion of a body at the pose `start` at `t = 0`, its origin moving at
/// `linear` while it turns about its origin at `angular` (radians per unit
/// time, about the world axis `angular / |angular|`), over `[0, duration]`:
/// what an engine hands over for one step of length `duration`.
///
/// Writes a new handle to `*out` (free it with `mb_motion_free`).
/// `MB_STATUS_INVALID_INPUT` for a NaN or infinite component, a zero
/// quaternion or `duration <= 0`; `MB_STATUS_NULL_POINTER` for `out == NULL`.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `out` is `NULL` or valid for writing a pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_motion_from_velocities(
    start: MbPose,
    linear: MbVec3,
    angular: MbVec3,
    duration: f64,
    out: *mut *mut MbMotion,
) -> MbStatus {
    guard(|| {
        let (start, linear, angular) = (
            start.isometry("start")?,
            linear.checked("linear")?,
            angular.checked("angular")?,
        );
        ArgError::positive(duration, "duration")?;
        let motion =
            RigidMotion::try_from_start(start, linear, angular, duration).map_err(motion_input)?;
        // SAFETY: `out` is NULL or writable (this function's contract).
        unsafe { write_handle(out, MbMotion { motion }) }
    })
}

/// The motion with constant velocities that carries a body from the pose
/// `start` at `t = 0` to `end` at `t = duration`, turning about its origin
/// by the shortest rotation (angle at most `pi`), its origin on the straight
/// line between the two positions (FCL's `InterpMotion`): for an engine
/// that has the poses before and after a step.
///
/// Writes a new handle to `*out`. Errors as `mb_motion_from_velocities`.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `out` is `NULL` or valid for writing a pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_motion_between(
    start: MbPose,
    end: MbPose,
    duration: f64,
    out: *mut *mut MbMotion,
) -> MbStatus {
    guard(|| {
        let (start, end) = (start.isometry("start")?, end.isometry("end")?);
        ArgError::positive(duration, "duration")?;
        let motion = RigidMotion::try_between(start, end, duration).map_err(motion_input)?;
        // SAFETY: `out` is NULL or writable (this function's contract).
        unsafe { write_handle(out, MbMotion { motion }) }
    })
}

/// As `mb_motion_between`, turning about the body point `local_centre`
/// (the centre of mass, as engines integrate) instead of the body origin:
/// that point moves on the straight line between its two positions.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `out` is `NULL` or valid for writing a pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_motion_between_about(
    start: MbPose,
    end: MbPose,
    duration: f64,
    local_centre: MbVec3,
    out: *mut *mut MbMotion,
) -> MbStatus {
    guard(|| {
        let (start, end) = (start.isometry("start")?, end.isometry("end")?);
        ArgError::positive(duration, "duration")?;
        let local = local_centre.checked("local_centre")?;
        let motion =
            RigidMotion::try_between_about(start, end, duration, local).map_err(motion_input)?;
        // SAFETY: `out` is NULL or writable (this function's contract).
        unsafe { write_handle(out, MbMotion { motion }) }
    })
}

/// The motion of a body turning about its body point `local_centre` (its
/// centre of mass), as an engine tracks it: that point's world position
/// `centre` at `t = 0`, the start orientation `rotation`, the point's
/// linear velocity `linear` and the angular velocity `angular` (world
/// vectors), over `[0, duration]`:
/// `p(t) = centre + linear t + R(angular t) rotation (r - local_centre)`.
///
/// Writes a new handle to `*out`. Errors as `mb_motion_from_velocities`.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `out` is `NULL` or valid for writing a pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_motion_about_centre(
    centre: MbVec3,
    local_centre: MbVec3,
    rotation: MbQuat,
    linear: MbVec3,
    angular: MbVec3,
    duration: f64,
    out: *mut *mut MbMotion,
) -> MbStatus {
    guard(|| {
        let centre = Point3::from_array(centre.checked("centre")?.to_array());
        let local = local_centre.checked("local_centre")?;
        let rotation = rotation.rotation("rotation")?;
        let (linear, angular) = (linear.checked("linear")?, angular.checked("angular")?);
        ArgError::positive(duration, "duration")?;
        let motion =
            RigidMotion::try_about_centre(centre, local, rotation, linear, angular, duration)
                .map_err(motion_input)?;
        // SAFETY: `out` is NULL or writable (this function's contract).
        unsafe { write_handle(out, MbMotion { motion }) }
    })
}

/// Where the body point `body_point` (in the body frame) is at time `t`
/// under `motion`, written to `*out`.
///
/// `MB_STATUS_INVALID_INPUT` for a NaN or infinite `t` or point.
///
/// **Thread safety**: any thread; `motion` may be shared.
///
/// # Safety
/// `motion` is not freed during the call; `out` is `NULL` or valid for
/// writing an `mb_vec3`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_motion_point_at(
    motion: *const MbMotion,
    body_point: MbVec3,
    t: f64,
    out: *mut MbVec3,
) -> MbStatus {
    guard(|| {
        // SAFETY: `motion` is not freed during the call (this function's contract).
        let m = unsafe { handle_ref(motion, "motion") }?;
        body_point.checked("body_point")?;
        ArgError::finite(t, "t")?;
        let p = m
            .motion
            .point_at(BodyPoint::new(body_point.x, body_point.y, body_point.z), t);
        // SAFETY: `out` is NULL or writable (this function's contract).
        unsafe { write_out(out, MbVec3::from_array(p.to_array()), "out") }
    })
}

/// Frees a motion (nothing for `NULL`). `MB_STATUS_INVALID_HANDLE` for a
/// handle freed before or not a motion (then nothing is freed).
///
/// **Thread safety**: no other thread may use `motion` during or after the
/// call.
///
/// # Safety
/// As stated: `motion` is not in use elsewhere.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_motion_free(motion: *mut MbMotion) -> MbStatus {
    // SAFETY: no other thread uses `motion` (this function's contract).
    guard(|| unsafe { free_handle(motion, "motion") })
}
