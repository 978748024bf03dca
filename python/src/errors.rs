//! The exceptions: one base class, one subclass per kind of Rust error, each
//! carrying the Rust error's message.

use motion_bound::ca::{ArgError, Problem};
use pyo3::create_exception;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

create_exception!(
    motion_bound,
    MotionBoundError,
    PyValueError,
    "Base class of motion_bound's errors (a ValueError): bad input or parameters."
);
create_exception!(
    motion_bound,
    InputError,
    MotionBoundError,
    "A number the core refuses: NaN or infinite, beyond the input range, a zero direction or \
     quaternion, a negative radius, a matrix that is not a rotation, an empty vertex set. The \
     message begins with the argument's name and, in an array, the index."
);
create_exception!(
    motion_bound,
    MeshError,
    MotionBoundError,
    "A triangle mesh the crate cannot use: no triangle, an index out of range, a degenerate mesh, \
     a mesh declared solid that is not closed and wound outward."
);
create_exception!(
    motion_bound,
    QueryError,
    MotionBoundError,
    "A query that cannot run: a parameter out of range, motions over different intervals, a \
     turning half-space, two half-spaces, a scene body on another interval."
);

create_exception!(
    motion_bound,
    UrdfError,
    MotionBoundError,
    "A URDF file that cannot be parsed or uses what is not read: a COLLADA mesh, a planar or \
     floating joint, a mesh file that cannot be read."
);

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("MotionBoundError", py.get_type::<MotionBoundError>())?;
    m.add("InputError", py.get_type::<InputError>())?;
    m.add("MeshError", py.get_type::<MeshError>())?;
    m.add("QueryError", py.get_type::<QueryError>())?;
    m.add("UrdfError", py.get_type::<UrdfError>())?;
    Ok(())
}

/// The core's refusal of an input, as `InputError`.
pub(crate) fn input(e: motion_bound::InputError) -> PyErr {
    InputError::new_err(e.to_string())
}

/// An argument's refusal as the crate words it ([`ArgError`]: the
/// argument's name first, as the C library says it too): `MeshError` for a
/// mesh's, `ValueError` for a compound's part of the wrong kind,
/// `InputError` otherwise.
pub(crate) fn arg(e: ArgError) -> PyErr {
    match e.problem() {
        Problem::Mesh(_) => MeshError::new_err(e.to_string()),
        Problem::NotAPart(_) => PyValueError::new_err(e.to_string()),
        _ => InputError::new_err(e.to_string()),
    }
}

/// The core's refusal of the argument `what` (a name such as `"start"` or
/// `"starts[3]"`), as `InputError` whose message begins with it.
pub(crate) fn input_in(what: &str) -> impl Fn(motion_bound::InputError) -> PyErr + '_ {
    move |e| arg(ArgError::input(what)(e))
}

/// The argument `name`'s value `x` if it is a finite number at least 0 (a
/// length: a radius, a half extent, a rounding), else `InputError` naming it.
pub(crate) fn length_arg(x: f64, name: &str) -> PyResult<f64> {
    ArgError::length(x, name).map_err(arg)
}

/// The argument `name`'s value `x` if it is finite and above 0 (a duration,
/// a cylinder's half height), else `InputError` naming it.
pub(crate) fn positive_arg(x: f64, name: &str) -> PyResult<f64> {
    ArgError::positive(x, name).map_err(arg)
}

/// A query's refusal, as `QueryError` (or `InputError` for the input it
/// carries).
pub(crate) fn query(e: motion_bound::ca::CaError) -> PyErr {
    match e {
        motion_bound::ca::CaError::Input(i) => input(i),
        other => QueryError::new_err(other.to_string()),
    }
}

/// A scene's refusal, as `QueryError`.
pub(crate) fn scene(e: motion_bound::scene::SceneQueryError) -> PyErr {
    QueryError::new_err(e.to_string())
}
