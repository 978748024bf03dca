//! The hierarchy's building blocks: a node (its two volumes and its
//! children or leaf) and a leaf (one triangle, or one piece of a large one).

use super::oriented_box::OrientedBox;
use crate::BoundingBall;

/// Marks a leaf in [`Node::right`].
pub(super) const LEAF: u32 = u32::MAX;

/// A node: its bounding ball and box, and either two children or one leaf.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Node<T> {
    /// Contains every point of every triangle below the node; centred at the
    /// box's centre. What the node's directed bound is computed from.
    pub(crate) ball: BoundingBall<T>,
    /// Contains every point of every triangle below the node, tightly: what
    /// the node's gap is measured with.
    pub(crate) obb: OrientedBox<T>,
    /// The left child, or the leaf's index when `right == LEAF`.
    pub(crate) left: u32,
    /// The right child, or `LEAF`.
    pub(crate) right: u32,
}

impl<T> Node<T> {
    #[inline]
    pub(crate) const fn leaf(&self) -> Option<usize> {
        if self.right == LEAF {
            Some(self.left as usize)
        } else {
            None
        }
    }
}

/// A leaf: one triangle or one piece of a large one (`pieces`), its
/// corners (relative to the rotation centre) and the rounded-up largest
/// distance of a point of it from the rotation centre.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Leaf<T> {
    /// The triangle's corners, exactly; a piece's corners as computed.
    pub(crate) corners: [[T; 3]; 3],
    pub(crate) r_hat: T,
    /// `0` for a whole triangle. For a piece, an upper bound of the distance
    /// of each computed corner from its exact position: every point of the
    /// exact piece is within `inflate` of the triangle of `corners`.
    pub(crate) inflate: T,
    /// The triangle's index in the mesh.
    pub(crate) triangle: u32,
}
