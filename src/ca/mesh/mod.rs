//! Conservative advancement of triangle meshes through their ball trees.
//!
//! The steppers, each in the file of the pair it serves: two meshes
//! ([`MeshPair`], `mesh_mesh`), a mesh against a convex shape or a
//! half-space ([`MeshConvexPair`], `mesh_convex`). What they share, each in
//! its own file: the descent of one step (`traversal`), the bodies and nodes
//! placed at the step's time (`placed`), what a step finds (`found`), the
//! best-first queue and the reusable scratch space ([`MeshWorkspace`],
//! `queue`), the leaf pairs handed from step to step (`seeds`) and the work
//! counters ([`TraversalStats`], `stats`).

mod found;
mod mesh_convex;
mod mesh_mesh;
mod placed;
mod queue;
mod seeds;
mod stats;
mod traversal;

pub use mesh_convex::MeshConvexPair;
pub use mesh_mesh::MeshPair;
pub use queue::MeshWorkspace;
pub use stats::TraversalStats;
