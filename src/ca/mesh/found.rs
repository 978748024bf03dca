//! What one step finds: a node pair's safe step or nearness
//! ([`NodeStep`]), and the witnesses of the pairs it measured ([`Found`]).

use crate::ca::Witness;
use crate::Direction;

/// What the safe step of a node pair found (`Descent::node_step`,
/// `MeshConvexPair::node_step`).
#[derive(Clone, Copy, Debug)]
pub(super) enum NodeStep<T> {
    /// Certified apart by more than the contact distance, with its safe step;
    /// `far`: far apart for its size (its step is taken as it is).
    Apart { step: T, far: bool },
    /// Its certified gap (`-inf` when no direction separates the volumes) is
    /// at most the contact distance: it must be split.
    Near(T),
}

/// What one step's measured triangle pairs found.
#[derive(Clone, Copy, Debug)]
pub(super) struct Found<T> {
    /// The closest pair measured, and its triangles.
    pub(super) closest: Option<Witness<T>>,
    pub(super) closest_triangles: Option<(u32, u32)>,
    /// The direction of the pair with the least step.
    pub(super) normal: Option<Direction<T>>,
    /// The closest pair within the contact distance, if any: its witness,
    /// triangles and direction.
    pub(super) touching: Option<Witness<T>>,
    pub(super) touching_triangles: Option<(u32, u32)>,
    pub(super) touching_normal: Option<Direction<T>>,
}

impl<T> Default for Found<T> {
    fn default() -> Self {
        Self {
            closest: None,
            closest_triangles: None,
            normal: None,
            touching: None,
            touching_triangles: None,
            touching_normal: None,
        }
    }
}
