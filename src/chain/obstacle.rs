//! The still bodies of a chain's surroundings: a mesh with its ball tree,
//! placed in the world, with its placement's rounding.

use alloc::string::String;

use alloc::vec::Vec;

use crate::chain::model::{distinct, ChainError};
use crate::chain::proxy::Proxy;
use crate::geometry::gjk::ConvexPolytope;
use crate::geometry::hull_clusters::{cluster_vertices, HullCluster};
use crate::geometry::hull_vertices::hull_vertex_indices;
use crate::rounding::gamma;
use crate::{BallTree, Float, Pose, TriMesh, Vec3};

fn orthonormal_row(v: Vec3<f64>) -> [f64; 3] {
    v.to_array()
}

/// Gram-Schmidt on three directions (a choice of axes, not a claim: the
/// proxy certifies its slabs along whatever axes it is given).
fn orthonormalise(a: [[f64; 3]; 3]) -> [[f64; 3]; 3] {
    let unit = |v: [f64; 3]| {
        let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        if l > 0.0 && l.is_finite() {
            v.map(|x| x / l)
        } else {
            v
        }
    };
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let u0 = unit(a[0]);
    let p1 = dot(a[1], u0);
    let u1 = unit([0, 1, 2].map(|k| a[1][k] - p1 * u0[k]));
    let u2 = [
        u0[1] * u1[2] - u0[2] * u1[1],
        u0[2] * u1[0] - u0[0] * u1[2],
        u0[0] * u1[1] - u0[1] * u1[0],
    ];
    [u0, u1, unit(u2)]
}

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
    /// The hull's vertices' clusters, for its support (`hull` is in their
    /// order).
    pub(super) hull_clusters: Vec<HullCluster<T>>,
    /// The hull's bound of its vertices' 1-norms (`None`: a vertex GJK
    /// refuses; the query then descends the tree alone).
    pub(super) hull_rho: Option<T>,
    /// What the rake's `f32` lanes test against: a box holding the mesh
    /// placed, along its tree's root box's axes (Lemma 13.12).
    pub(super) proxy: Option<Proxy>,
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
        let mut hull: Vec<[T; 3]> = hull_vertex_indices(&all)
            .into_iter()
            .map(|i| all[i])
            .collect();
        let hull_rho = ConvexPolytope::try_new(&hull, Pose::IDENTITY)
            .ok()
            .map(|p| p.radius_l1());
        let hull_clusters = cluster_vertices(&mut hull);
        let pose64 = Pose {
            rotation: pose.rotation.map(|r| r.map(T::to_f64)),
            translation: Vec3::from_array(pose.translation.to_array().map(T::to_f64)),
        };
        let world: Vec<[f64; 3]> = all
            .iter()
            .map(|v| {
                pose64
                    .transform_point(Vec3::from_array(v.map(T::to_f64)))
                    .to_array()
            })
            .collect();
        let axes = tree.whole.nodes[0]
            .obb
            .axes
            .map(|a| orthonormal_row(pose64.transform_vector(Vec3::from_array(a.map(T::to_f64)))));
        let axes = orthonormalise(axes);
        // The placed vertices err by the pose's rounding (`delta`, and the
        // f64 evaluation's few ulps of the reach).
        let err = delta.to_f64() + 8.0 * f64::EPSILON * reach.to_f64();
        let proxy = Proxy::holding(&world, axes, err, 0.0);
        Ok(Self {
            proxy,
            name,
            mesh,
            tree,
            pose,
            reach: reach + delta,
            delta,
            hull,
            hull_clusters,
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
