//! The seed's Table 1 scenario from Python: the very queries the Rust
//! benchmarks and the `table1` report run, so that a comparison from Python
//! (with python-fcl, say) is on the same inputs.

use motion_bound::bodies::TorusKnotSize;
use motion_bound::testkit::table1::{KnotScene, CONTACT_DISTANCE, SPIN};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};

use crate::arrays::to_numpy;
use crate::motion::{Motion, MotionSource, PoseSource};

fn motion(m: &motion_bound::RigidMotion<f64>) -> Motion {
    Motion {
        source: MotionSource::Velocities {
            start: PoseSource::Quaternion {
                wxyz: m.orientation().quaternion(),
                translation: m.centre().to_array(),
            },
            linear: m.linear().to_array(),
            angular: m.angular().to_array(),
            duration: 1.0,
        },
        motion: *m,
    }
}

/// The seed's Table 1 scenario of `size` ("2.8K", "11K" or "34K"): a dict
/// with "meshes" (eight turned copies of the torus knot, each a
/// `(vertices, faces)` pair of arrays), "queries" (a list of
/// `(i, j, motion_i, motion_j)`: copy `i` flies past copy `j` over
/// `[0, 1]`) and "contact_distance" (1e-3). The first `queries` fly-bys of
/// the seeded list the Rust `table1` report and benchmarks run.
#[pyfunction]
#[pyo3(signature = (size = "2.8K", queries = 200))]
fn table1_scene<'py>(py: Python<'py>, size: &str, queries: i64) -> PyResult<Bound<'py, PyDict>> {
    let queries = usize::try_from(queries).map_err(|_| {
        PyValueError::new_err(format!("queries must be at least 0 (got {queries})"))
    })?;
    let size = match size {
        "2.8K" => TorusKnotSize::K2_8,
        "11K" => TorusKnotSize::K11,
        "34K" => TorusKnotSize::K34,
        other => {
            return Err(PyValueError::new_err(format!(
                "size must be \"2.8K\", \"11K\" or \"34K\", got {other:?}"
            )))
        }
    };
    let scene = py.detach(|| KnotScene::new(size, queries, SPIN));
    let meshes = PyList::empty(py);
    for m in &scene.meshes {
        let v = to_numpy(py, m.vertices().concat(), &[m.vertices().len(), 3])?;
        let f: Vec<i64> = m
            .triangles()
            .iter()
            .flatten()
            .map(|&i| i64::from(i))
            .collect();
        let f = to_numpy(
            py,
            f.iter().map(|&i| i as f64).collect(),
            &[m.triangles().len(), 3],
        )?
        .call_method1("astype", ("int64",))?;
        meshes.append(PyTuple::new(py, [v, f])?)?;
    }
    let qs = PyList::empty(py);
    for q in &scene.queries {
        let item = (
            q.a,
            q.b,
            Bound::new(py, motion(&q.motion.a))?,
            Bound::new(py, motion(&q.motion.b))?,
        );
        qs.append(item)?;
    }
    let d = PyDict::new(py);
    d.set_item("meshes", meshes)?;
    d.set_item("queries", qs)?;
    d.set_item("contact_distance", CONTACT_DISTANCE)?;
    Ok(d)
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(table1_scene, m)?)?;
    Ok(())
}
