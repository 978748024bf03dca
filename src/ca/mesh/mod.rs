//! Conservative advancement of triangle meshes through their ball trees.
//!
//! The steppers, each in the file of the pair it serves: two meshes
//! ([`MeshPair`], `mesh_mesh`: its step in stages), a mesh against a convex
//! shape or a half-space ([`MeshConvexPair`], `mesh_convex`). What they
//! share, each in its own file, bottom first (a file imports only from the
//! files listed before it): the work counters ([`TraversalStats`], `stats`),
//! the leaf pairs handed from step to step (`seeds`), the bodies and nodes
//! placed at the step's time with their closing rates (`placed`), what a
//! step finds and the rules both steppers decide by (`found`), the front of
//! node pairs one step hands to the next (`front`), the
//! best-first queue and the reusable scratch space ([`MeshWorkspace`],
//! `queue`), and the measurements of the descent of two meshes
//! (`traversal`).

mod found;
mod front;
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
