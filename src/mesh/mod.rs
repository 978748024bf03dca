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

/// A box's 12 triangles over its corners numbered so that corner `i` has
/// coordinate `k` at `+h[k]` when bit `k` of `i` is set (else `-h[k]`), two
/// a face, counter-clockwise seen from outside: the box of a URDF `<box>`
/// and of the crate's own tests.
#[cfg(any(test, feature = "urdf"))]
pub(crate) const BOX_TRIANGLES: [[u32; 3]; 12] = [
    [0, 2, 1],
    [1, 2, 3],
    [4, 5, 6],
    [5, 7, 6],
    [0, 1, 4],
    [1, 5, 4],
    [2, 6, 3],
    [3, 6, 7],
    [0, 4, 2],
    [2, 4, 6],
    [1, 3, 5],
    [3, 7, 5],
];
#[cfg(feature = "obj")]
pub use error::ObjError;
pub use error::{MeshError, OffError, OffErrorKind};
pub(crate) use topology::component_points;
pub use topology::EdgeReport;
pub use trimesh::TriMesh;
