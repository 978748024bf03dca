//! The still bodies of a chain's surroundings: a mesh with its ball tree,
//! placed in the world, with its placement's rounding.

use alloc::string::String;

use alloc::vec::Vec;

use crate::chain::model::{distinct, ChainError};
use crate::geometry::gjk::ConvexPolytope;
use crate::geometry::hull_vertices::hull_vertex_indices;
use crate::rounding::gamma;
use crate::{BallTree, Float, Pose, TriMesh};

/// A still body of the chain's surroundings: a mesh (its ball tree) placed
/// in the world.
#[derive(Clone, Debug)]
pub struct Obstacle<T> {
    name: String,
    pub(super) mesh: TriMesh<T>,
    pub(super) tree: BallTree<T>,
    pub(super) pose: Pose<T>,
    /// `|x| + reach`, the magnitude of every placed point.
    pub(super) reach: T,
    /// The placement's rounding (`gamma_4` of `reach`).
    pub(super) delta: T,
    /// The mesh's distinct vertices reduced to a superset of its convex
    /// hull's vertices, in its own frame: its first cover against a link's
    /// hull (`proofs/13-chains.md`, Lemma 13.8).
    pub(super) hull: Vec<[T; 3]>,
    /// The hull's bound of its vertices' 1-norms (`None`: a vertex GJK
    /// refuses; the query then descends the tree alone).
    pub(super) hull_rho: Option<T>,
}

impl<T: Float> Obstacle<T> {
    /// An obstacle from its mesh (in its own frame; its ball tree is built
    /// here, once) and its world pose.
    ///
    /// # Errors
    /// [`ChainError::InvalidParameter`] for a pose that is not finite or
    /// whose rotation has an entry beyond 2 (not a rotation);
    /// [`ChainError::Mesh`] for a mesh a ball tree cannot be built on.
    pub fn try_new(
        name: impl Into<String>,
        mesh: TriMesh<T>,
        pose: Pose<T>,
    ) -> Result<Self, ChainError> {
        if !pose.is_finite()
            || pose.translation.max_abs() > T::MAX_INPUT
            || pose.rotation_max_abs() > T::TWO
        {
            return Err(ChainError::InvalidParameter("an obstacle's pose"));
        }
        let name = name.into();
        let tree = BallTree::try_whole_from_mesh(&mesh)
            .map_err(|e| ChainError::Mesh(alloc::format!("obstacle {name:?}: {e}")))?;
        let reach = (pose.translation.length() + tree.whole.reach) * (T::ONE + gamma::<T>(4));
        let delta = gamma::<T>(8) * reach + T::from_u32(4) * T::ETA_NORMAL;
        // The same hull with fewer supports (Lemma 13.7, item 5).
        let all = distinct(mesh.vertices());
        let hull: Vec<[T; 3]> = hull_vertex_indices(&all)
            .into_iter()
            .map(|i| all[i])
            .collect();
        let hull_rho = ConvexPolytope::try_new(&hull, Pose::IDENTITY)
            .ok()
            .map(|p| p.radius_l1());
        Ok(Self {
            name,
            mesh,
            tree,
            pose,
            reach: reach + delta,
            delta,
            hull,
            hull_rho,
        })
    }

    /// The obstacle's name.
    #[must_use]
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Its mesh, in its own frame.
    #[must_use]
    pub fn mesh(&self) -> &TriMesh<T> {
        &self.mesh
    }

    /// Its ball tree (whole triangles: the chain builds no pieces).
    #[must_use]
    pub fn tree(&self) -> &BallTree<T> {
        &self.tree
    }

    /// Its world pose.
    #[must_use]
    pub fn pose(&self) -> Pose<T> {
        self.pose
    }
}
