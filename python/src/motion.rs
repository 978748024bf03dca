//! Poses and motions: `Pose`, `Motion`, `MotionBatch`. Each keeps the
//! numbers it was made from, so that a pickled copy is rebuilt through the
//! same constructor and gives bit for bit the same answers.

use motion_bound::{Isometry, RigidMotion, Rotation, Vec3};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;

use crate::arrays::{homogeneous, index, matrices4, matrix4, rows3, to_numpy, vec3, vec4};
use crate::errors::input;

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

/// The isometry of a row-major 4x4 homogeneous matrix.
pub(crate) fn isometry_of_matrix(m: &[f64; 16]) -> PyResult<Isometry<f64>> {
    let last = [m[12], m[13], m[14], m[15] - 1.0];
    if !last.iter().all(|x| x.abs() <= LAST_ROW_TOLERANCE) {
        return Err(PyValueError::new_err(format!(
            "a pose's last row must be (0, 0, 0, 1), got ({}, {}, {}, {})",
            m[12], m[13], m[14], m[15]
        )));
    }
    let r = [[m[0], m[1], m[2]], [m[4], m[5], m[6]], [m[8], m[9], m[10]]];
    let rotation = Rotation::try_from_matrix(r).map_err(input)?;
    Isometry::try_new(rotation, Vec3::new(m[3], m[7], m[11])).map_err(input)
}

fn isometry_of(source: &PoseSource) -> PyResult<Isometry<f64>> {
    match source {
        PoseSource::Matrix(m) => isometry_of_matrix(m),
        PoseSource::Quaternion { wxyz, translation } => {
            let [w, x, y, z] = *wxyz;
            let r = Rotation::try_from_quaternion(w, x, y, z).map_err(input)?;
            Isometry::try_new(r, Vec3::from_array(*translation)).map_err(input)
        }
    }
}

/// A rigid placement: a rotation and a translation.
///
/// `Pose(matrix)` takes a 4x4 homogeneous matrix (its upper-left 3x3 block
/// a rotation to within 1e-6; a scaled or mirrored matrix is an
/// `InputError`); `Pose()` is the identity; `Pose.from_wxyz(q, t)` and
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
        Ok(Self {
            iso: isometry_of(&source)?,
            source,
        })
    }
}

/// A pose from a `Pose` or a 4x4 array-like.
pub(crate) fn pose_arg(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<Pose> {
    if let Ok(p) = obj.extract::<PyRef<'_, Pose>>() {
        return Ok(p.clone());
    }
    Pose::from_source(PoseSource::Matrix(matrix4(obj, what)?))
}

#[pymethods]
impl Pose {
    #[new]
    #[pyo3(signature = (matrix = None))]
    fn py_new(matrix: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
        match matrix {
            Some(m) => Self::from_source(PoseSource::Matrix(matrix4(m, "matrix")?)),
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
        Self::from_source(PoseSource::Quaternion { wxyz, translation })
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
        Self::from_source(PoseSource::Quaternion {
            wxyz: [w, x, y, z],
            translation,
        })
    }

    /// The pose that only translates by `(x, y, z)`.
    #[staticmethod]
    fn from_translation(translation: &Bound<'_, PyAny>) -> PyResult<Self> {
        Self::from_source(PoseSource::Quaternion {
            wxyz: [1.0, 0.0, 0.0, 0.0],
            translation: vec3(translation, "translation")?,
        })
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

    fn __repr__(&self) -> String {
        let q = self.iso.rotation().quaternion();
        let t = self.iso.translation();
        format!(
            "Pose(wxyz=({:.6}, {:.6}, {:.6}, {:.6}), translation=({}, {}, {}))",
            q[0], q[1], q[2], q[3], t.x, t.y, t.z
        )
    }
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

fn motion_of(source: &MotionSource) -> PyResult<RigidMotion<f64>> {
    match source {
        MotionSource::Between {
            start,
            end,
            duration,
        } => RigidMotion::try_between(isometry_of(start)?, isometry_of(end)?, *duration)
            .map_err(input),
        MotionSource::Velocities {
            start,
            linear,
            angular,
            duration,
        } => RigidMotion::try_from_start(
            isometry_of(start)?,
            Vec3::from_array(*linear),
            Vec3::from_array(*angular),
            *duration,
        )
        .map_err(input),
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
        Ok(Self {
            motion: motion_of(&source)?,
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
        Self::from_source(MotionSource::Velocities {
            start: pose_arg(pose, "pose")?.source,
            linear: [0.0; 3],
            angular: [0.0; 3],
            duration,
        })
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
                starts
                    .iter()
                    .zip(ends)
                    .map(|(s, e)| {
                        RigidMotion::try_between(
                            isometry_of_matrix(s)?,
                            isometry_of_matrix(e)?,
                            *duration,
                        )
                        .map_err(input)
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
                starts
                    .iter()
                    .zip(linear.iter().zip(angular))
                    .map(|(s, (v, w))| {
                        RigidMotion::try_from_start(
                            isometry_of_matrix(s)?,
                            Vec3::from_array(*v),
                            Vec3::from_array(*w),
                            *duration,
                        )
                        .map_err(input)
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

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Pose>()?;
    m.add_class::<Motion>()?;
    m.add_class::<MotionBatch>()?;
    Ok(())
}
