//! `motion_bound` for Python: certified continuous collision detection by
//! conservative advancement, never late and never missed, for triangle
//! meshes, convex shapes (balls, capsules, boxes, cylinders, cones, hulls,
//! rounded or not), half-spaces and compounds, from numpy arrays.
//!
//! This crate is the binding only: every number comes from the Rust crate
//! `motion-bound` (its proofs are in its `proofs/`). What the binding adds is
//! the conversion of Python input (with typed exceptions for what is not
//! understood), the release of the GIL during every query, the batch call on
//! every core, and pickling.
//!
//! The Python-facing documentation is in the docstrings below (`help()`
//! shows them), in `motion_bound.pyi` and in `python/README.md`.

mod arrays;
mod body;
mod chain;
mod errors;
mod motion;
mod query;
mod scene;
mod testing;
mod trimesh_scene;

use pyo3::prelude::*;

/// Certified continuous collision detection: the first time of contact of two
/// moving bodies, never late and never missed (conservative advancement with
/// proven motion bounds, the rounding of every step accounted for).
///
/// Bodies: `mesh`, `ball`, `capsule`, `box`, `cylinder`, `cone`,
/// `convex_hull`, `half_space`, `compound`, `from_trimesh`.
/// Poses: `Pose` (a 4x4 matrix whose rotation block is orthonormal to
/// within 1e-6, or a quaternion and a translation); `orthonormalize` cleans
/// a rotation rounded beyond that. Capsules, cylinders and cones lie along
/// y; `box` takes half extents (trimesh: along z, full extents; its
/// primitives go through `from_trimesh`).
/// Motions: `Motion.between(start, end)`, `Motion(start, linear, angular)`,
/// `MotionBatch` for many.
/// Queries: `time_of_impact`, `time_of_impact_batch`, `Scene`.
/// Robot arms: `Chain.from_urdf(path)`, `ChainScene(chain)` (`check_edge`,
/// `edge_is_free`, `edges_are_free`, `check_segment`, `check_path`,
/// `collides_at`).
#[pymodule]
fn motion_bound(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    errors::register(m)?;
    body::register(m)?;
    motion::register(m)?;
    query::register(m)?;
    scene::register(m)?;
    chain::register(m)?;
    testing::register(m)?;
    Ok(())
}
