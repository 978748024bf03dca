//! `Scene`: many bodies over one interval, every pair's first contact after
//! the crate's certified broad phase.

use motion_bound::scene::{Scene as RustScene, SceneParams, SceneWorkspace};
use motion_bound::TimeInterval;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};

use crate::body::Body;
use crate::errors::{input, input_in, positive_arg, scene as scene_err};
use crate::motion::{pose_arg, Motion};
use crate::query::{params, Flat, Report};

/// Many bodies moving over `[0, duration]`: `add(body, motion)` (a `Motion`
/// over the same duration, or a pose for a still body) returns the body's
/// number; `query(...)` returns every pair's first contact, as a list of
/// `(i, j, Report)` with `i < j`, for the pairs the broad phase could not
/// rule out (a pair not listed provably stays apart), and fills `stats`
/// (what the broad phase skipped, each skip counted). The GIL is released
/// during the query; by default (`parallel=True`, as for
/// `time_of_impact_batch`) the pairs run on every core, with the same
/// answers bit for bit as `parallel=False` (one core). It pickles: its
/// duration, its bodies with their motions (a body added twice stays one
/// object) and the last query's `stats`.
#[pyclass(module = "motion_bound")]
pub struct Scene {
    duration: f64,
    bodies: Vec<(Py<Body>, Motion)>,
    stats: Option<motion_bound::scene::SceneStats>,
}

#[pymethods]
impl Scene {
    #[new]
    #[pyo3(signature = (duration = 1.0))]
    fn py_new(duration: f64) -> PyResult<Self> {
        // As a motion's duration: finite and positive.
        positive_arg(duration, "duration")?;
        let origin = motion_bound::Isometry::try_from_translation(motion_bound::Vec3::ZERO)
            .map_err(input)?;
        motion_bound::RigidMotion::try_from_start(
            origin,
            motion_bound::Vec3::ZERO,
            motion_bound::Vec3::ZERO,
            duration,
        )
        .map_err(input_in("duration"))?;
        Ok(Self {
            duration,
            bodies: Vec::new(),
            stats: None,
        })
    }

    /// Adds `body` moving by `motion` (a `Motion`, or a pose for a body that
    /// stays still); returns its number.
    fn add(&mut self, body: Bound<'_, Body>, motion: &Bound<'_, PyAny>) -> PyResult<usize> {
        let m = if let Ok(m) = motion.extract::<PyRef<'_, Motion>>() {
            m.clone()
        } else {
            // A pose (a `Pose` or a 4x4 array): its own error (a matrix that
            // is not a rotation, say) names `motion`; anything else is not one.
            let pose = pose_arg(motion, "motion").map_err(|e| {
                if e.is_instance_of::<pyo3::exceptions::PyValueError>(motion.py()) {
                    e
                } else {
                    PyTypeError::new_err("motion must be a Motion, a Pose or a 4x4 array")
                }
            })?;
            Motion::from_source(crate::motion::MotionSource::Velocities {
                start: pose.source,
                linear: [0.0; 3],
                angular: [0.0; 3],
                duration: self.duration,
            })?
        };
        let i = m.motion.interval();
        if i.start() != 0.0 || i.end() != self.duration {
            return Err(crate::errors::QueryError::new_err(format!(
                "motion: body {} moves over [{}, {}], the scene is over [0, {}] (give the motion \
                 the scene's duration)",
                self.bodies.len(),
                i.start(),
                i.end(),
                self.duration
            )));
        }
        self.bodies.push((body.unbind(), m));
        Ok(self.bodies.len() - 1)
    }

    fn __len__(&self) -> usize {
        self.bodies.len()
    }

    /// Every pair's first contact: a list of `(i, j, Report)`. On every
    /// core by default (`parallel=True`); `parallel=False` runs on one, with
    /// the same answers bit for bit.
    #[pyo3(
        signature = (contact_distance = 1e-4, tolerance = 1e-9, max_iterations = crate::query::Iterations::DEFAULT, parallel = true),
        text_signature = "($self, contact_distance=1e-4, tolerance=1e-9, max_iterations=100, parallel=True)"
    )]
    fn query(
        &mut self,
        py: Python<'_>,
        contact_distance: f64,
        tolerance: f64,
        max_iterations: crate::query::Iterations,
        parallel: bool,
    ) -> PyResult<Vec<(usize, usize, Report)>> {
        let p =
            SceneParams::default().with_ca(params(contact_distance, tolerance, max_iterations)?);
        let bodies: Vec<(&Body, motion_bound::RigidMotion<f64>)> = self
            .bodies
            .iter()
            .map(|(b, m)| (b.get(), m.motion))
            .collect();
        let duration = self.duration;
        let (pairs, stats) = py.detach(|| -> PyResult<_> {
            let prepared = bodies
                .iter()
                .map(|(b, _)| b.prepare())
                .collect::<PyResult<Vec<_>>>()?;
            let interval = TimeInterval::try_new(0.0, duration).map_err(input)?;
            let mut scene = RustScene::try_new(interval).map_err(scene_err)?;
            for (prep, (_, motion)) in prepared.iter().zip(&bodies) {
                scene.try_add(prep.shape(), *motion).map_err(scene_err)?;
            }
            let mut ws = SceneWorkspace::new();
            let report = if parallel {
                scene.par_query(&mut ws, &p)
            } else {
                scene.query(&mut ws, &p)
            }
            .map_err(|e| named_scene_error(e, &bodies))?;
            let pairs: Vec<(usize, usize, Flat)> = report
                .pairs()
                .iter()
                .map(|r| (r.a, r.b, Flat::of(&r.report)))
                .collect();
            Ok((pairs, report.stats()))
        })?;
        self.stats = Some(stats);
        Ok(pairs
            .into_iter()
            .map(|(a, b, flat)| (a, b, Report { flat }))
            .collect())
    }

    /// The last query's counters (bodies, pairs culled by the broad phase,
    /// pairs tested, iterations, ...), or `None` before the first query.
    #[getter]
    fn stats<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(s) = self.stats else {
            return Ok(None);
        };
        let d = PyDict::new(py);
        d.set_item("bodies", s.bodies)?;
        d.set_item("static_bodies", s.static_bodies)?;
        d.set_item("pairs_all", s.pairs_all)?;
        d.set_item("pairs_static", s.pairs_static)?;
        d.set_item("pairs_culled", s.pairs_culled)?;
        d.set_item("pairs_tested", s.pairs_tested)?;
        d.set_item("iterations", s.iterations)?;
        Ok(Some(d))
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let this = slf.borrow();
        let bodies = PyList::empty(py);
        for (body, motion) in &this.bodies {
            bodies.append((body.clone_ref(py), Bound::new(py, motion.clone())?))?;
        }
        let state = (bodies, this.stats(py)?).into_pyobject(py)?;
        PyTuple::new(
            py,
            [
                py.get_type::<Self>().into_any(),
                (this.duration,).into_pyobject(py)?.into_any(),
                state.into_any(),
            ],
        )
    }

    /// Adds the pickled bodies and motions (as `add`) and restores the stats.
    fn __setstate__(&mut self, state: SceneState<'_>) -> PyResult<()> {
        let (bodies, stats) = state;
        for (body, motion) in bodies {
            self.add(body, &motion)?;
        }
        self.stats = match stats {
            None => None,
            Some(d) => {
                let get = |key: &str| -> PyResult<Bound<'_, PyAny>> {
                    d.get_item(key)?.ok_or_else(|| {
                        pyo3::exceptions::PyKeyError::new_err(format!("stats: no {key:?}"))
                    })
                };
                let mut s = motion_bound::scene::SceneStats::default();
                s.bodies = get("bodies")?.extract()?;
                s.static_bodies = get("static_bodies")?.extract()?;
                s.pairs_all = get("pairs_all")?.extract()?;
                s.pairs_static = get("pairs_static")?.extract()?;
                s.pairs_culled = get("pairs_culled")?.extract()?;
                s.pairs_tested = get("pairs_tested")?.extract()?;
                s.iterations = get("iterations")?.extract()?;
                Some(s)
            }
        };
        Ok(())
    }

    fn __repr__(&self) -> String {
        format!(
            "Scene({} bodies, duration={})",
            self.bodies.len(),
            self.duration
        )
    }
}

/// A pickled scene's state: its bodies with their motions, and the last query's stats.
type SceneState<'py> = (
    Vec<(Bound<'py, Body>, Bound<'py, PyAny>)>,
    Option<Bound<'py, PyDict>>,
);

/// A scene query's refusal, naming the body it is about where the crate's
/// message does not: a half-space whose motion turns.
fn named_scene_error(
    e: motion_bound::scene::SceneQueryError,
    bodies: &[(&Body, motion_bound::RigidMotion<f64>)],
) -> PyErr {
    use motion_bound::ca::CaError;
    use motion_bound::scene::SceneQueryError as E;
    if let E::Ca(CaError::TurnedHalfSpace) = e {
        let turned = bodies.iter().position(|(b, m)| {
            b.kind_name() == "half_space"
                && (m.angular() != motion_bound::Vec3::ZERO
                    || m.orientation().quaternion() != [1.0, 0.0, 0.0, 0.0])
        });
        if let Some(i) = turned {
            return crate::errors::QueryError::new_err(format!(
                "body {i}: a half-space may only translate (no start orientation, no spin): \
                 give its normal in the world frame and a motion with the identity rotation and \
                 no angular velocity"
            ));
        }
    }
    scene_err(e)
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Scene>()?;
    Ok(())
}
