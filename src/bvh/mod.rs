//! A bounding-volume hierarchy of balls over a triangle mesh, relative to the
//! body's rotation centre: what conservative advancement of non-convex
//! meshes traverses.
//!
//! The files, each importing only from those above it in this list:
//! `eigen` (principal axes), `oriented_box` (certified boxes), `node` (a
//! node and a leaf), `distinct` (one leaf per distinct triangle), `pieces`
//! (long triangles cut), `hierarchy` (one hierarchy and its build),
//! `piece_hierarchy` (the hierarchy of pieces), `ball_tree` ([`BallTree`])
//! and `vertex_tree` ([`VertexTree`]).

mod ball_tree;
mod distinct;
mod eigen;
mod hierarchy;
mod node;
mod oriented_box;
mod piece_hierarchy;
mod pieces;
mod vertex_tree;

pub use ball_tree::BallTree;
pub(crate) use hierarchy::Hierarchy;
pub(crate) use node::{Leaf, Node};
// The mesh steppers' box gaps, and the testkit's containment checks.
pub(crate) use oriented_box::OrientedBox;
pub use vertex_tree::VertexTree;
pub(crate) use vertex_tree::NONE as NO_CHILD;
