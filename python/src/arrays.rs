//! Python input to Rust values: any array-like of real numbers (lists, numpy
//! arrays of any real dtype, strided views) is read as contiguous `float64`;
//! index arrays must hold integers. Shapes are checked here, numbers by the
//! core (NaN, infinity and range give `InputError`).

use numpy::{PyArrayMethods, PyReadonlyArrayDyn};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// `obj` as a contiguous numpy array of `dtype` (`"float64"` or `"int64"`),
/// after checking that its values are of the right kind: real numbers for
/// floats (booleans, integers and floats; not complex, strings or objects),
/// integers for indices (not floats, which would be truncated silently).
fn contiguous<'py>(
    obj: &Bound<'py, PyAny>,
    dtype: &str,
    what: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let py = obj.py();
    let np = py.import("numpy")?;
    let raw = np
        .call_method1("asarray", (obj,))
        .map_err(|e| PyTypeError::new_err(format!("{what}: not an array of numbers ({e})")))?;
    let kind: String = raw.getattr("dtype")?.getattr("kind")?.extract()?;
    let allowed = if dtype == "int64" { "iu" } else { "biuf" };
    if !allowed.contains(kind.as_str()) {
        let name: String = raw.getattr("dtype")?.str()?.extract()?;
        let want = if dtype == "int64" {
            "integers"
        } else {
            "real numbers"
        };
        return Err(PyTypeError::new_err(format!(
            "{what} must hold {want}, got dtype {name}"
        )));
    }
    let kwargs = PyDict::new(py);
    kwargs.set_item("dtype", dtype)?;
    np.call_method("ascontiguousarray", (raw,), Some(&kwargs))
}

/// The shape of a numpy array.
fn shape_of(arr: &Bound<'_, PyAny>) -> PyResult<Vec<usize>> {
    arr.getattr("shape")?.extract()
}

fn shape_error(what: &str, want: &str, got: &[usize]) -> PyErr {
    PyValueError::new_err(format!("{what} must have shape {want}, got {got:?}"))
}

/// The `float64` values of `obj` and its shape.
pub(crate) fn floats(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<(Vec<f64>, Vec<usize>)> {
    let arr = contiguous(obj, "float64", what)?;
    let shape = shape_of(&arr)?;
    let ro: PyReadonlyArrayDyn<'_, f64> = arr.extract()?;
    let values = ro.as_slice()?.to_vec();
    Ok((values, shape))
}

/// The `int64` values of `obj` and its shape.
fn integers(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<(Vec<i64>, Vec<usize>)> {
    let arr = contiguous(obj, "int64", what)?;
    let shape = shape_of(&arr)?;
    let ro: PyReadonlyArrayDyn<'_, i64> = arr.extract()?;
    let values = ro.as_slice()?.to_vec();
    Ok((values, shape))
}

/// An `(n, 3)` array of points or vectors.
pub(crate) fn rows3(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<[f64; 3]>> {
    let (v, shape) = floats(obj, what)?;
    if shape.len() != 2 || shape[1] != 3 {
        return Err(shape_error(what, "(n, 3)", &shape));
    }
    Ok(v.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect())
}

/// An `(m, 3)` array of vertex indices, each in `0..2^32`.
pub(crate) fn triangles(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<[u32; 3]>> {
    let (v, shape) = integers(obj, what)?;
    if shape.len() != 2 || shape[1] != 3 {
        return Err(shape_error(what, "(m, 3)", &shape));
    }
    let mut out = Vec::with_capacity(v.len() / 3);
    for (t, c) in v.chunks_exact(3).enumerate() {
        let mut tri = [0u32; 3];
        for (k, &i) in c.iter().enumerate() {
            tri[k] = u32::try_from(i).map_err(|_| {
                PyValueError::new_err(format!(
                    "{what}: triangle {t} has the index {i}, outside 0..2**32"
                ))
            })?;
        }
        out.push(tri);
    }
    Ok(out)
}

/// A vector of three numbers.
pub(crate) fn vec3(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<[f64; 3]> {
    let (v, shape) = floats(obj, what)?;
    if shape != [3] {
        return Err(shape_error(what, "(3,)", &shape));
    }
    Ok([v[0], v[1], v[2]])
}

/// A `(4,)` quaternion.
pub(crate) fn vec4(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<[f64; 4]> {
    let (v, shape) = floats(obj, what)?;
    if shape != [4] {
        return Err(shape_error(what, "(4,)", &shape));
    }
    Ok([v[0], v[1], v[2], v[3]])
}

/// A `(4, 4)` matrix, row-major.
pub(crate) fn matrix4(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<[f64; 16]> {
    let (v, shape) = floats(obj, what)?;
    if shape != [4, 4] {
        return Err(shape_error(what, "(4, 4)", &shape));
    }
    let mut m = [0.0; 16];
    m.copy_from_slice(&v);
    Ok(m)
}

/// An `(n, 4, 4)` stack of matrices, row-major.
pub(crate) fn matrices4(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<[f64; 16]>> {
    let (v, shape) = floats(obj, what)?;
    if shape.len() != 3 || shape[1] != 4 || shape[2] != 4 {
        return Err(shape_error(what, "(n, 4, 4)", &shape));
    }
    Ok(v.chunks_exact(16)
        .map(|c| {
            let mut m = [0.0; 16];
            m.copy_from_slice(c);
            m
        })
        .collect())
}

/// A numpy array of `values` with `shape`.
pub(crate) fn to_numpy<'py>(
    py: Python<'py>,
    values: Vec<f64>,
    shape: &[usize],
) -> PyResult<Bound<'py, PyAny>> {
    let flat = numpy::PyArray1::from_vec(py, values);
    Ok(flat.reshape(shape.to_vec())?.into_any())
}

/// The position of Python index `i` (negative from the end) in a sequence of
/// `n`, or `IndexError` naming `what`.
pub(crate) fn index(i: isize, n: usize, what: &str) -> PyResult<usize> {
    let n = n as isize;
    let k = if i < 0 { i + n } else { i };
    if (0..n).contains(&k) {
        Ok(k as usize)
    } else {
        Err(pyo3::exceptions::PyIndexError::new_err(format!(
            "{what} index out of range"
        )))
    }
}

/// The row-major 4x4 homogeneous matrix of a rotation matrix and a
/// translation, as a numpy array.
pub(crate) fn homogeneous<'py>(
    py: Python<'py>,
    r: [[f64; 3]; 3],
    t: [f64; 3],
) -> PyResult<Bound<'py, PyAny>> {
    let m = vec![
        r[0][0], r[0][1], r[0][2], t[0], r[1][0], r[1][1], r[1][2], t[1], r[2][0], r[2][1],
        r[2][2], t[2], 0.0, 0.0, 0.0, 1.0,
    ];
    to_numpy(py, m, &[4, 4])
}
