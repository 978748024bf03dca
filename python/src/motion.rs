//! Poses and motions: `Pose`, `Motion`, `MotionBatch`. Each keeps the
//! numbers it was made from, so that a pickled copy is rebuilt through the
//! same constructor and gives bit for bit the same answers.

use motion_bound::{Isometry, RigidMotion, Rotation, Vec3};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;

use crate::arrays::{floats, homogeneous, index, matrices4, matrix4, rows3, to_numpy, vec3, vec4};
use crate::errors::{input_in, positive_arg};

/// How far the last row of a 4x4 pose may be from `(0, 0, 0, 1)`.
const LAST_ROW_TOLERANCE: f64 = 1e-9;

/// What a pose was made from.
#[derive(Clone, Copy, Debug)]
pub(crate) enum PoseSource {
    Matrix([f64; 16]),
    Quaternion {
        wxyz: [f64; 4],
        translation: [f64; 3],
    },
}

/// How far from orthonormal a rotation block may be: every entry of
/// `R^T R - I` within this (the core's `Rotation::MATRIX_TOLERANCE`), and
/// `det R > 0`.
pub(crate) const ROTATION_TOLERANCE: f64 = motion_bound::Rotation::<f64>::MATRIX_TOLERANCE;

/// How far from orthonormal a rotation block may be for `orthonormalize`
/// to clean it: every entry of `R^T R - I` within this.
pub(crate) const ORTHONORMALIZE_LIMIT: f64 = 1e-2;

/// The largest entry of `R^T R - I` in absolute value (NaN for a
/// non-finite `R`).
fn orthonormality_error(r: &[[f64; 3]; 3]) -> f64 {
    let mut worst: f64 = 0.0;
    for i in 0..3 {
        for j in 0..3 {
            let dot = r[0][i] * r[0][j] + r[1][i] * r[1][j] + r[2][i] * r[2][j];
            let d = (dot - if i == j { 1.0 } else { 0.0 }).abs();
            if d.is_nan() {
                return f64::NAN;
            }
            worst = worst.max(d);
        }
    }
    worst
}

fn determinant(r: &[[f64; 3]; 3]) -> f64 {
    r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1])
        - r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0])
        + r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0])
}

/// The rotation nearest `r` (in the Frobenius norm: the orthogonal factor of
/// its polar decomposition), by Newton's iteration `X <- (X + X^-T) / 2`,
/// which converges quadratically from a matrix near a rotation. Refused
/// (`InputError` naming `what`) for a matrix that is not finite, has
/// `det <= 0` (singular or a reflection) or has an entry of `R^T R - I`
/// beyond `ORTHONORMALIZE_LIMIT` (not a rounded rotation: something else).
///
/// Each entry of the answer is within about that largest entry of
/// `R^T R - I` of `r` (the polar factor `Q` of `r = Q H` has
/// `|r - Q| = |H - I| <= |r^T r - I|` in the Frobenius norm), so a point
/// at distance `d` from the body origin moves by at most about
/// `3 * d * max|R^T R - I|`.
pub(crate) fn nearest_rotation(r: [[f64; 3]; 3], what: &str) -> PyResult<[[f64; 3]; 3]> {
    if r.iter().flatten().any(|x| !x.is_finite()) {
        return Err(crate::errors::InputError::new_err(format!(
            "{what} is not finite"
        )));
    }
    let det = determinant(&r);
    if det.is_nan() || det <= 0.0 {
        return Err(crate::errors::InputError::new_err(format!(
            "{what} is not near a rotation: its determinant is {det} (a rotation's is 1; \
             singular or a reflection)"
        )));
    }
    let err = orthonormality_error(&r);
    if err.is_nan() || err > ORTHONORMALIZE_LIMIT {
        return Err(crate::errors::InputError::new_err(format!(
            "{what} is not near a rotation: an entry of R^T R - I is {err:.3e}, beyond the \
             {ORTHONORMALIZE_LIMIT:e} that orthonormalize cleans"
        )));
    }
    let mut x = r;
    for _ in 0..16 {
        let d = determinant(&x);
        // X^-T is the cofactor matrix over the determinant.
        let c = |i: usize, j: usize| {
            let (i1, i2) = ((i + 1) % 3, (i + 2) % 3);
            let (j1, j2) = ((j + 1) % 3, (j + 2) % 3);
            x[i1][j1] * x[i2][j2] - x[i1][j2] * x[i2][j1]
        };
        let mut next = [[0.0; 3]; 3];
        let mut change: f64 = 0.0;
        for (i, row) in next.iter_mut().enumerate() {
            for (j, v) in row.iter_mut().enumerate() {
                *v = 0.5 * (x[i][j] + c(i, j) / d);
                change = change.max((*v - x[i][j]).abs());
            }
        }
        x = next;
        if change <= 4.0 * f64::EPSILON {
            break;
        }
    }
    Ok(x)
}

/// The rotation block of a row-major 4x4 matrix.
fn block(m: &[f64; 16]) -> [[f64; 3]; 3] {
    [[m[0], m[1], m[2]], [m[4], m[5], m[6]], [m[8], m[9], m[10]]]
}

/// `m` with its rotation block replaced by its nearest rotation.
pub(crate) fn orthonormalized(m: &[f64; 16], what: &str) -> PyResult<[f64; 16]> {
    let q = nearest_rotation(block(m), what)?;
    let mut out = *m;
    for (i, row) in q.iter().enumerate() {
        out[4 * i..4 * i + 3].copy_from_slice(row);
    }
    Ok(out)
}

/// The isometry of a row-major 4x4 homogeneous matrix; an error names the
/// argument `what()` (called only then).
pub(crate) fn isometry_of_matrix(
    m: &[f64; 16],
    what: &dyn Fn() -> String,
) -> PyResult<Isometry<f64>> {
    let last = [m[12], m[13], m[14], m[15] - 1.0];
    if !last.iter().all(|x| x.abs() <= LAST_ROW_TOLERANCE) {
        return Err(PyValueError::new_err(format!(
            "{}: a pose's last row must be (0, 0, 0, 1), got ({}, {}, {}, {})",
            what(),
            m[12],
            m[13],
            m[14],
            m[15]
        )));
    }
    let r = block(m);
    let rotation = Rotation::try_from_matrix(r).map_err(|e| match e {
        motion_bound::InputError::NotARotation => crate::errors::InputError::new_err(format!(
            "{}: matrix is not a rotation: its 3x3 block must have every entry of R^T R - I \
             within {ROTATION_TOLERANCE:e} and det > 0 (here the largest entry is {:.3e}, det \
             {}); Pose(matrix, orthonormalize=True) or motion_bound.orthonormalize(matrix) \
             cleans a rotation rounded to within {ORTHONORMALIZE_LIMIT:e}",
            what(),
            orthonormality_error(&r),
            determinant(&r)
        )),
        other => input_in(&what())(other),
    })?;
    Isometry::try_new(rotation, Vec3::new(m[3], m[7], m[11])).map_err(|e| input_in(&what())(e))
}

fn isometry_of(source: &PoseSource, what: &str) -> PyResult<Isometry<f64>> {
    match source {
        PoseSource::Matrix(m) => isometry_of_matrix(m, &|| what.to_string()),
        PoseSource::Quaternion { wxyz, translation } => {
            let [w, x, y, z] = *wxyz;
            let r = Rotation::try_from_quaternion(w, x, y, z).map_err(input_in(what))?;
            Isometry::try_new(r, Vec3::from_array(*translation)).map_err(input_in(what))
        }
    }
}

/// A motion's refusal by the core, as `InputError` naming the argument it
/// comes from: `linear`, `angular` or `duration` for a motion from
/// velocities, `start, end` for one between two poses (whose velocities
/// they make), each with `[i]` for the `i`-th motion of a batch.
fn motion_error(e: motion_bound::InputError, between: bool, i: Option<usize>) -> PyErr {
    use motion_bound::{InputError as E, Quantity as Q};
    let q = match e {
        E::NonFinite(q) | E::TooLarge(q) => Some(q),
        _ => None,
    };
    let at = i.map(|k| format!("[{k}]")).unwrap_or_default();
    let name = match (q, &e, between) {
        (_, E::NonPositiveDuration, _) | (Some(Q::Duration | Q::Time), _, _) => {
            "duration".to_string()
        }
        (Some(Q::LinearVelocity), _, false) => format!("linear{at}"),
        (Some(Q::AngularVelocity), _, false) => format!("angular{at}"),
        (_, _, true) if i.is_some() => format!("starts{at}, ends{at}"),
        (_, _, true) => "start, end".to_string(),
        (_, _, false) if i.is_some() => format!("starts{at}, linear{at}, angular{at}"),
        (_, _, false) => "start, linear, angular".to_string(),
    };
    let err = input_in(&name)(e);
    err
}

/// A rigid placement: a rotation and a translation.
///
/// `Pose(matrix)` takes a 4x4 homogeneous matrix whose upper-left 3x3 block
/// `R` is a rotation to within 1e-6: every entry of `R^T R - I` at most
/// 1e-6 in absolute value and `det R > 0` (a scaled or mirrored matrix, or
/// one rounded to five decimals, is an `InputError`).
/// `Pose(matrix, orthonormalize=True)` first replaces `R` by the nearest
/// rotation (see `orthonormalize`: accepted when every entry of `R^T R - I`
/// is within 1e-2, refused beyond). `Pose()` is the identity; `Pose.from_wxyz(q, t)` and
/// `Pose.from_xyzw(q, t)` take a quaternion in either order (normalised) and
/// a translation; `Pose.from_translation(t)`. Wherever a pose is expected, a
/// 4x4 array is accepted too.
#[pyclass(frozen, module = "motion_bound")]
#[derive(Clone, Debug)]
pub struct Pose {
    pub(crate) source: PoseSource,
    pub(crate) iso: Isometry<f64>,
}

impl Pose {
    pub(crate) fn from_source(source: PoseSource) -> PyResult<Self> {
        Self::from_source_named(source, "pose")
    }
}

/// A pose from a `Pose` or a 4x4 array-like; an error names `what`.
pub(crate) fn pose_arg(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<Pose> {
    if let Ok(p) = obj.extract::<PyRef<'_, Pose>>() {
        return Ok(p.clone());
    }
    Pose::from_source_named(PoseSource::Matrix(matrix4(obj, what)?), what)
}

impl Pose {
    /// The rotation's entries row by row, then the translation: what `==` compares.
    fn entries(&self) -> [f64; 12] {
        let r = self.iso.rotation().matrix();
        let t = self.iso.translation().to_array();
        [
            r[0][0], r[0][1], r[0][2], r[1][0], r[1][1], r[1][2], r[2][0], r[2][1], r[2][2], t[0],
            t[1], t[2],
        ]
    }

    /// As `from_source`, an error naming the argument `what`.
    pub(crate) fn from_source_named(source: PoseSource, what: &str) -> PyResult<Self> {
        Ok(Self {
            iso: isometry_of(&source, what)?,
            source,
        })
    }
}

#[pymethods]
impl Pose {
    #[new]
    #[pyo3(signature = (matrix = None, orthonormalize = false))]
    fn py_new(matrix: Option<&Bound<'_, PyAny>>, orthonormalize: bool) -> PyResult<Self> {
        match matrix {
            Some(m) => {
                let mut m = matrix4(m, "matrix")?;
                if orthonormalize {
                    m = orthonormalized(&m, "matrix")?;
                }
                Self::from_source_named(PoseSource::Matrix(m), "matrix")
            }
            None => Self::from_source(PoseSource::Quaternion {
                wxyz: [1.0, 0.0, 0.0, 0.0],
                translation: [0.0; 3],
            }),
        }
    }

    /// The pose of the quaternion `(w, x, y, z)` (normalised; any finite
    /// nonzero quaternion) and the translation `(x, y, z)`.
    #[staticmethod]
    #[pyo3(signature = (quaternion, translation = None))]
    fn from_wxyz(
        quaternion: &Bound<'_, PyAny>,
        translation: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let wxyz = vec4(quaternion, "quaternion")?;
        let translation = match translation {
            Some(t) => vec3(t, "translation")?,
            None => [0.0; 3],
        };
        Self::from_source_named(
            PoseSource::Quaternion { wxyz, translation },
            "quaternion, translation",
        )
    }

    /// As `from_wxyz`, with the quaternion in scipy's order `(x, y, z, w)`.
    #[staticmethod]
    #[pyo3(signature = (quaternion, translation = None))]
    fn from_xyzw(
        quaternion: &Bound<'_, PyAny>,
        translation: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let [x, y, z, w] = vec4(quaternion, "quaternion")?;
        let translation = match translation {
            Some(t) => vec3(t, "translation")?,
            None => [0.0; 3],
        };
        Self::from_source_named(
            PoseSource::Quaternion {
                wxyz: [w, x, y, z],
                translation,
            },
            "quaternion, translation",
        )
    }

    /// The pose that only translates by `(x, y, z)`.
    #[staticmethod]
    fn from_translation(translation: &Bound<'_, PyAny>) -> PyResult<Self> {
        Self::from_source_named(
            PoseSource::Quaternion {
                wxyz: [1.0, 0.0, 0.0, 0.0],
                translation: vec3(translation, "translation")?,
            },
            "translation",
        )
    }

    /// The 4x4 homogeneous matrix of the pose as the crate uses it.
    #[getter]
    fn matrix<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        homogeneous(
            py,
            self.iso.rotation().matrix(),
            self.iso.translation().to_array(),
        )
    }

    /// The unit quaternion `(w, x, y, z)`.
    #[getter]
    fn wxyz<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_numpy(py, self.iso.rotation().quaternion().to_vec(), &[4])
    }

    /// The translation `(x, y, z)`.
    #[getter]
    fn translation<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_numpy(py, self.iso.translation().to_array().to_vec(), &[3])
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let cls = py.get_type::<Self>();
        let this = slf.get();
        match this.source {
            PoseSource::Matrix(m) => {
                let arr = to_numpy(py, m.to_vec(), &[4, 4])?;
                PyTuple::new(py, [cls.into_any(), PyTuple::new(py, [arr])?.into_any()])
            }
            PoseSource::Quaternion { wxyz, translation } => {
                let f = cls.getattr("from_wxyz")?;
                let args = PyTuple::new(
                    py,
                    [
                        to_numpy(py, wxyz.to_vec(), &[4])?,
                        to_numpy(py, translation.to_vec(), &[3])?,
                    ],
                )?;
                PyTuple::new(py, [f, args.into_any()])
            }
        }
    }

    /// Equal when their matrices (`matrix`, as the crate uses it) are, entry by entry: the
    /// same placement, whatever it was made from (`Pose() == Pose(numpy.eye(4))`).
    fn __eq__(&self, other: &Self) -> bool {
        self.entries() == other.entries()
    }

    /// Consistent with `==` (equal poses hash alike), so that a pose can be a dict key.
    fn __hash__(&self) -> u64 {
        hash_floats(&self.entries())
    }

    fn __repr__(&self) -> String {
        let q = self.iso.rotation().quaternion();
        let t = self.iso.translation();
        format!(
            "Pose(wxyz=({:.6}, {:.6}, {:.6}, {:.6}), translation=({}, {}, {}))",
            q[0], q[1], q[2], q[3], t.x, t.y, t.z
        )
    }
}

/// A hash of floats consistent with `==` on them (`-0.0` and `0.0` hash alike; none is NaN
/// where it is used).
fn hash_floats(xs: &[f64]) -> u64 {
    use std::hash::{Hash, Hasher};
    let mut h = std::collections::hash_map::DefaultHasher::new();
    for x in xs {
        // `x + 0.0` turns `-0.0` into `0.0`.
        (x + 0.0).to_bits().hash(&mut h);
    }
    h.finish()
}

/// What a motion was made from.
#[derive(Clone, Copy, Debug)]
pub(crate) enum MotionSource {
    Between {
        start: PoseSource,
        end: PoseSource,
        duration: f64,
    },
    Velocities {
        start: PoseSource,
        linear: [f64; 3],
        angular: [f64; 3],
        duration: f64,
    },
}

fn motion_of(source: &MotionSource, start_name: &str) -> PyResult<RigidMotion<f64>> {
    match source {
        MotionSource::Between {
            start,
            end,
            duration,
        } => {
            let (s, e) = (isometry_of(start, "start")?, isometry_of(end, "end")?);
            positive_arg(*duration, "duration")?;
            RigidMotion::try_between(s, e, *duration).map_err(|e| motion_error(e, true, None))
        }
        MotionSource::Velocities {
            start,
            linear,
            angular,
            duration,
        } => {
            let s = isometry_of(start, start_name)?;
            positive_arg(*duration, "duration")?;
            RigidMotion::try_from_start(
                s,
                Vec3::from_array(*linear),
                Vec3::from_array(*angular),
                *duration,
            )
            .map_err(|e| motion_error(e, false, None))
        }
    }
}

/// A body's rigid motion over `[0, duration]`: its pose at `t = 0`, its
/// origin moving at the constant linear velocity `linear` while the body
/// turns about its origin at the constant angular velocity `angular`
/// (radians per unit time; world vectors).
///
/// `Motion(start, linear, angular, duration=1.0)`, or
/// `Motion.between(start, end, duration=1.0)`: from pose `start` at `t = 0`
/// to pose `end` at `t = duration` (the origin on the straight line, the
/// rotation by the shortest angle, at constant rates). `Motion.still(pose)`
/// does not move.
#[pyclass(frozen, module = "motion_bound")]
#[derive(Clone, Debug)]
pub struct Motion {
    pub(crate) source: MotionSource,
    pub(crate) motion: RigidMotion<f64>,
}

impl Motion {
    pub(crate) fn from_source(source: MotionSource) -> PyResult<Self> {
        Self::from_source_named(source, "start")
    }

    /// As `from_source`, the start pose of a motion from velocities named
    /// `start_name` in an error (`Motion.still` calls it `pose`).
    fn from_source_named(source: MotionSource, start_name: &str) -> PyResult<Self> {
        Ok(Self {
            motion: motion_of(&source, start_name)?,
            source,
        })
    }
}

#[pymethods]
impl Motion {
    #[new]
    #[pyo3(signature = (start, linear, angular, duration = 1.0))]
    fn py_new(
        start: &Bound<'_, PyAny>,
        linear: &Bound<'_, PyAny>,
        angular: &Bound<'_, PyAny>,
        duration: f64,
    ) -> PyResult<Self> {
        Self::from_source(MotionSource::Velocities {
            start: pose_arg(start, "start")?.source,
            linear: vec3(linear, "linear")?,
            angular: vec3(angular, "angular")?,
            duration,
        })
    }

    /// The motion from pose `start` at `t = 0` to pose `end` at
    /// `t = duration`.
    #[staticmethod]
    #[pyo3(signature = (start, end, duration = 1.0))]
    fn between(start: &Bound<'_, PyAny>, end: &Bound<'_, PyAny>, duration: f64) -> PyResult<Self> {
        Self::from_source(MotionSource::Between {
            start: pose_arg(start, "start")?.source,
            end: pose_arg(end, "end")?.source,
            duration,
        })
    }

    /// A body that stays at `pose` over `[0, duration]`.
    #[staticmethod]
    #[pyo3(signature = (pose, duration = 1.0))]
    fn still(pose: &Bound<'_, PyAny>, duration: f64) -> PyResult<Self> {
        Self::from_source_named(
            MotionSource::Velocities {
                start: pose_arg(pose, "pose")?.source,
                linear: [0.0; 3],
                angular: [0.0; 3],
                duration,
            },
            "pose",
        )
    }

    /// The length of the motion's interval.
    #[getter]
    fn duration(&self) -> f64 {
        let i = self.motion.interval();
        i.end() - i.start()
    }

    /// The linear velocity of the body's origin.
    #[getter]
    fn linear<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_numpy(py, self.motion.linear().to_array().to_vec(), &[3])
    }

    /// The angular velocity (radians per unit time, world frame).
    #[getter]
    fn angular<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_numpy(py, self.motion.angular().to_array().to_vec(), &[3])
    }

    /// The pose at time `t` as a 4x4 matrix.
    fn matrix_at<'py>(&self, py: Python<'py>, t: f64) -> PyResult<Bound<'py, PyAny>> {
        let p = self.motion.pose_at(t);
        homogeneous(py, p.rotation, p.translation.to_array())
    }

    /// The pose at time `t` (a `Pose`; its matrix is `matrix_at(t)`).
    fn pose_at(&self, t: f64) -> PyResult<Pose> {
        if !t.is_finite() {
            return Err(crate::errors::InputError::new_err(format!(
                "t is not finite (got {t})"
            )));
        }
        let p = self.motion.pose_at(t);
        let r = p.rotation;
        let x = p.translation.to_array();
        Pose::from_source(PoseSource::Matrix([
            r[0][0], r[0][1], r[0][2], x[0], r[1][0], r[1][1], r[1][2], x[1], r[2][0], r[2][1],
            r[2][2], x[2], 0.0, 0.0, 0.0, 1.0,
        ]))
    }

    /// The pose at `t = 0`, as given to the constructor (a `Pose`; a 4x4
    /// array given is kept as its matrix).
    #[getter]
    fn start(&self) -> PyResult<Pose> {
        let s = match self.source {
            MotionSource::Between { start, .. } | MotionSource::Velocities { start, .. } => start,
        };
        Pose::from_source(s)
    }

    /// The pose at `t = duration`: the `end` given to `Motion.between`, else
    /// `pose_at(duration)`.
    #[getter]
    fn end(&self) -> PyResult<Pose> {
        match self.source {
            MotionSource::Between { end, .. } => Pose::from_source(end),
            MotionSource::Velocities { .. } => self.pose_at(self.duration()),
        }
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let cls = py.get_type::<Self>();
        let pose = |s: PoseSource| -> PyResult<Bound<'py, PyAny>> {
            Ok(Bound::new(py, Pose::from_source(s)?)?.into_any())
        };
        let (f, args) = match slf.get().source {
            MotionSource::Between {
                start,
                end,
                duration,
            } => (
                cls.getattr("between")?,
                PyTuple::new(
                    py,
                    [
                        pose(start)?,
                        pose(end)?,
                        duration.into_pyobject(py)?.into_any(),
                    ],
                )?,
            ),
            MotionSource::Velocities {
                start,
                linear,
                angular,
                duration,
            } => (
                cls.into_any(),
                PyTuple::new(
                    py,
                    [
                        pose(start)?,
                        to_numpy(py, linear.to_vec(), &[3])?,
                        to_numpy(py, angular.to_vec(), &[3])?,
                        duration.into_pyobject(py)?.into_any(),
                    ],
                )?,
            ),
        };
        PyTuple::new(py, [f, args.into_any()])
    }

    /// Equal when they are the same motion, bit for bit: the same start pose, velocities and
    /// interval (a pickled copy is equal; two motions made differently may differ in the last
    /// bits).
    fn __eq__(&self, other: &Self) -> bool {
        self.motion == other.motion
    }

    /// Consistent with `==`, so that a motion can be a dict key.
    fn __hash__(&self) -> u64 {
        let m = &self.motion;
        let p = m.start_pose();
        let r = p.rotation().matrix();
        let (t, v, w, i) = (
            p.translation().to_array(),
            m.linear().to_array(),
            m.angular().to_array(),
            m.interval(),
        );
        hash_floats(&[
            r[0][0],
            r[0][1],
            r[0][2],
            r[1][0],
            r[1][1],
            r[1][2],
            r[2][0],
            r[2][1],
            r[2][2],
            t[0],
            t[1],
            t[2],
            v[0],
            v[1],
            v[2],
            w[0],
            w[1],
            w[2],
            i.start(),
            i.end(),
        ])
    }

    fn __repr__(&self) -> String {
        let v = self.motion.linear();
        let w = self.motion.angular();
        format!(
            "Motion(linear=({}, {}, {}), angular=({}, {}, {}), duration={})",
            v.x,
            v.y,
            v.z,
            w.x,
            w.y,
            w.z,
            self.duration()
        )
    }
}

/// What a batch of motions was made from.
#[derive(Clone, Debug)]
enum BatchSource {
    Between {
        starts: Vec<[f64; 16]>,
        ends: Vec<[f64; 16]>,
        duration: f64,
    },
    Velocities {
        starts: Vec<[f64; 16]>,
        linear: Vec<[f64; 3]>,
        angular: Vec<[f64; 3]>,
        duration: f64,
    },
}

/// Many motions of one body over the same `[0, duration]`, from arrays:
/// `MotionBatch.between(starts, ends, duration=1.0)` with `(n, 4, 4)` pose
/// stacks, or `MotionBatch(starts, linear, angular, duration=1.0)` with an
/// `(n, 4, 4)` stack and `(n, 3)` velocities. `len(batch)`, `batch[i]` (a
/// `Motion`); it pickles.
#[pyclass(frozen, module = "motion_bound")]
#[derive(Debug)]
pub struct MotionBatch {
    source: BatchSource,
    pub(crate) motions: Vec<RigidMotion<f64>>,
}

fn same_length(what: &str, a: usize, b: usize) -> PyResult<()> {
    if a == b {
        Ok(())
    } else {
        Err(PyValueError::new_err(format!(
            "{what}: {a} start poses but {b} entries"
        )))
    }
}

impl MotionBatch {
    fn from_source(source: BatchSource) -> PyResult<Self> {
        let motions = match &source {
            BatchSource::Between {
                starts,
                ends,
                duration,
            } => {
                same_length("ends", starts.len(), ends.len())?;
                positive_arg(*duration, "duration")?;
                starts
                    .iter()
                    .zip(ends)
                    .enumerate()
                    .map(|(i, (s, e))| {
                        RigidMotion::try_between(
                            isometry_of_matrix(s, &|| format!("starts[{i}]"))?,
                            isometry_of_matrix(e, &|| format!("ends[{i}]"))?,
                            *duration,
                        )
                        .map_err(|e| motion_error(e, true, Some(i)))
                    })
                    .collect::<PyResult<Vec<_>>>()?
            }
            BatchSource::Velocities {
                starts,
                linear,
                angular,
                duration,
            } => {
                same_length("linear", starts.len(), linear.len())?;
                same_length("angular", starts.len(), angular.len())?;
                positive_arg(*duration, "duration")?;
                starts
                    .iter()
                    .zip(linear.iter().zip(angular))
                    .enumerate()
                    .map(|(i, (s, (v, w)))| {
                        RigidMotion::try_from_start(
                            isometry_of_matrix(s, &|| format!("starts[{i}]"))?,
                            Vec3::from_array(*v),
                            Vec3::from_array(*w),
                            *duration,
                        )
                        .map_err(|e| motion_error(e, false, Some(i)))
                    })
                    .collect::<PyResult<Vec<_>>>()?
            }
        };
        Ok(Self { source, motions })
    }
}

#[pymethods]
impl MotionBatch {
    #[new]
    #[pyo3(signature = (starts, linear, angular, duration = 1.0))]
    fn py_new(
        starts: &Bound<'_, PyAny>,
        linear: &Bound<'_, PyAny>,
        angular: &Bound<'_, PyAny>,
        duration: f64,
    ) -> PyResult<Self> {
        Self::from_source(BatchSource::Velocities {
            starts: matrices4(starts, "starts")?,
            linear: rows3(linear, "linear")?,
            angular: rows3(angular, "angular")?,
            duration,
        })
    }

    /// The motions from `starts[i]` at `t = 0` to `ends[i]` at
    /// `t = duration`.
    #[staticmethod]
    #[pyo3(signature = (starts, ends, duration = 1.0))]
    fn between(
        starts: &Bound<'_, PyAny>,
        ends: &Bound<'_, PyAny>,
        duration: f64,
    ) -> PyResult<Self> {
        Self::from_source(BatchSource::Between {
            starts: matrices4(starts, "starts")?,
            ends: matrices4(ends, "ends")?,
            duration,
        })
    }

    fn __len__(&self) -> usize {
        self.motions.len()
    }

    fn __getitem__(&self, i: isize) -> PyResult<Motion> {
        let k = index(i, self.motions.len(), "motion")?;
        let source = match &self.source {
            BatchSource::Between {
                starts,
                ends,
                duration,
            } => MotionSource::Between {
                start: PoseSource::Matrix(starts[k]),
                end: PoseSource::Matrix(ends[k]),
                duration: *duration,
            },
            BatchSource::Velocities {
                starts,
                linear,
                angular,
                duration,
            } => MotionSource::Velocities {
                start: PoseSource::Matrix(starts[k]),
                linear: linear[k],
                angular: angular[k],
                duration: *duration,
            },
        };
        Motion::from_source(source)
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let cls = py.get_type::<Self>();
        let stack = |m: &[[f64; 16]]| to_numpy(py, m.concat(), &[m.len(), 4, 4]);
        let rows = |m: &[[f64; 3]]| to_numpy(py, m.concat(), &[m.len(), 3]);
        let (f, args) = match &slf.get().source {
            BatchSource::Between {
                starts,
                ends,
                duration,
            } => (
                cls.getattr("between")?,
                PyTuple::new(
                    py,
                    [
                        stack(starts)?,
                        stack(ends)?,
                        duration.into_pyobject(py)?.into_any(),
                    ],
                )?,
            ),
            BatchSource::Velocities {
                starts,
                linear,
                angular,
                duration,
            } => (
                cls.into_any(),
                PyTuple::new(
                    py,
                    [
                        stack(starts)?,
                        rows(linear)?,
                        rows(angular)?,
                        duration.into_pyobject(py)?.into_any(),
                    ],
                )?,
            ),
        };
        PyTuple::new(py, [f, args.into_any()])
    }

    fn __repr__(&self) -> String {
        format!("MotionBatch({} motions)", self.motions.len())
    }
}

/// The nearest rotation to a matrix that is almost one: a rotation rounded
/// to a few decimals, a product of many float32 rotations, a rotation read
/// from a file. `matrix` is a 3x3 rotation, a 4x4 pose (its upper-left 3x3
/// block is cleaned, the rest kept) or a stack of either (`(..., 3, 3)` or
/// `(..., 4, 4)`); the answer has the same shape, `float64`.
///
/// The nearest rotation in the Frobenius norm (the orthogonal factor of the
/// polar decomposition, `U V^T` of the SVD), by Newton's iteration
/// `R <- (R + R^-T) / 2`. Each entry moves by about as much as the input is
/// from orthonormal, so a point at distance `d` from the body origin moves
/// by at most about `3 * d * max|R^T R - I|`, and a query's answer changes
/// accordingly. Raises `InputError` naming the matrix (and its index in a
/// stack) for one that is not near a rotation: not finite, `det <= 0`
/// (singular or a reflection), or an entry of `R^T R - I` beyond 1e-2.
#[pyfunction]
fn orthonormalize<'py>(py: Python<'py>, matrix: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
    let (v, shape) = floats(matrix, "matrix")?;
    let n = shape.len();
    let k = if n >= 2 { shape[n - 1] } else { 0 };
    if n < 2 || shape[n - 2] != k || !(k == 3 || k == 4) {
        return Err(PyValueError::new_err(format!(
            "matrix must have shape (3, 3), (4, 4), (..., 3, 3) or (..., 4, 4), got {shape:?}"
        )));
    }
    let lead = &shape[..n - 2];
    let name = |flat: usize| -> String {
        if lead.is_empty() {
            return "matrix".to_string();
        }
        let mut idx = vec![0; lead.len()];
        let mut rest = flat;
        for (d, &len) in lead.iter().enumerate().rev() {
            idx[d] = rest % len;
            rest /= len;
        }
        let idx: Vec<String> = idx.iter().map(ToString::to_string).collect();
        format!("matrix[{}]", idx.join(", "))
    };
    let mut out = Vec::with_capacity(v.len());
    for (i, c) in v.chunks_exact(k * k).enumerate() {
        if k == 3 {
            let r = [[c[0], c[1], c[2]], [c[3], c[4], c[5]], [c[6], c[7], c[8]]];
            out.extend(nearest_rotation(r, &name(i))?.iter().flatten());
        } else {
            let mut m = [0.0; 16];
            m.copy_from_slice(c);
            out.extend(orthonormalized(&m, &name(i))?);
        }
    }
    to_numpy(py, out, &shape)
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(orthonormalize, m)?)?;
    m.add_class::<Pose>()?;
    m.add_class::<Motion>()?;
    m.add_class::<MotionBatch>()?;
    Ok(())
}
