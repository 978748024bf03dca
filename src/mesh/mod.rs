//! Triangle meshes for the bodies of a CA time-of-impact engine: an owned,
//! validated [`TriMesh`], its topology checks, its declaration as a solid
//! and the exact inside test, and OFF and STL (and, with the `obj` feature,
//! OBJ) input.

mod closed_convex;
mod error;
#[cfg(feature = "obj")]
mod obj;
mod off;
mod solid;
mod stl;
mod topology;
mod trimesh;

pub(crate) use closed_convex::closed_convex_vertices;
#[cfg(feature = "obj")]
pub use error::ObjError;
pub use error::{MeshError, OffError, OffErrorKind};
pub(crate) use topology::component_points;
pub use topology::EdgeReport;
pub use trimesh::TriMesh;
