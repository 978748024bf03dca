//! [`BallTree`]: a mesh's hierarchy of whole triangles and, when it has long
//! triangles, its hierarchy of pieces; which of the two a query descends.

use alloc::vec::Vec;

use super::distinct::distinct;
use super::hierarchy::{Hierarchy, Split};
use super::node::Leaf;
use super::piece_hierarchy::build_pieces;
use super::pieces;
use crate::{BoundingBall, Float, InputError};

/// The default piece length: this fraction of the mesh's reach (the largest
/// vertex distance from the rotation centre).
const PIECE_FRACTION: f64 = 1.0 / 32.0;

/// By default a mesh gets a hierarchy of pieces when its longest edge
/// exceeds this fraction of its reach.
const PIECE_TRIGGER: f64 = 0.5;

/// The default budget of pieces: this many per distinct triangle, and at
/// least [`MIN_PIECE_BUDGET`].
const PIECES_PER_TRIANGLE: usize = 4;
const MIN_PIECE_BUDGET: usize = 16384;

/// The budget of pieces for a length given by the caller.
const PIECE_BUDGET: usize = 1 << 16;

/// How a tree's hierarchy of pieces is made: it exists when some triangle's
/// longest edge exceeds `trigger`; every triangle longer than the piece
/// length is cut down to it, the length being `length` or the least
/// multiple of it by a power of `sqrt 2` whose pieces fit in `budget`
/// (`None`: [`PIECES_PER_TRIANGLE`] per distinct triangle, at least
/// [`MIN_PIECE_BUDGET`]).
struct PiecePlan {
    length: f64,
    trigger: f64,
    budget: Option<usize>,
}

/// A query uses a mesh's hierarchy of pieces when its largest leaf ball is
/// more than this many times the other mesh's median leaf ball.
const PIECES_RATIO: f64 = 4.0;

/// A triangle mesh with its bounding-volume hierarchy, built once per body.
///
/// Vertices are offsets from the body's rotation centre at the epoch (the
/// crate's convention for body points). Each node has two volumes, each
/// certified to contain every point of its triangles in exact arithmetic:
/// an oriented box along the principal axes of its corners (what gaps are
/// measured with; thin for a flat patch, `proofs/floating-point.md`,
/// "Oriented box") and a ball centred at the box's centre (what the node's
/// directed bound is computed from, in `O(1)`:
/// [`DirectedProbe::ball_speed`](crate::DirectedProbe::ball_speed)).
///
/// Built top-down, one leaf per distinct triangle (`2 M - 1` nodes for `M`
/// distinct triangles): exact duplicates, the same corners in any order
/// (from the same or from doubled vertices, a repeated corner counted once),
/// are one set of points and share the leaf of the first, so a mesh of
/// 100,000 copies of one triangle is one leaf (`proofs/09-ca-toi.md`,
/// Lemma 9.2, "Duplicates"). Each node is split at the median position of
/// whichever of three keys (centroids along the widest axis or along the
/// box's longest axis, normals along their principal axis) gives the
/// children the smallest total box surface; keys that tie are split there
/// too, so the depth is `ceil(log2 M) + 1` whatever the keys.
/// `O(N log^2 N)`: about 0.5 s for 34K triangles here.
///
/// A mesh with a triangle much longer than its size scale (an edge over
/// half its reach, as a board's or a box's) also gets a second hierarchy in
/// which its long triangles are cut into pieces
/// ([`try_with_piece_length`](Self::try_with_piece_length)); a query takes
/// it against a mesh of much smaller triangles. That hierarchy is one over
/// the pieces and the short triangles together, so that pieces of different
/// triangles near one another (a thin board's two faces) share nodes; its
/// nodes split at the median of one key (centroids along the widest axis),
/// except the small ones near the leaves, which take the best of the three
/// keys by a cheaper measure (boxes along the node's own axes). It is built
/// the first time a pair needs it (about 38 ms for the 13,768 pieces of a
/// 12-triangle board here; with the `std` feature, else with the tree), so
/// that a mesh met only by convex shapes never pays for it.
#[derive(Clone, Debug)]
pub struct BallTree<T> {
    /// Every triangle whole.
    pub(crate) whole: Hierarchy<T>,
    /// Long triangles cut into pieces, when the mesh has any: built when a
    /// query first needs them (boxed: most trees never do).
    pieces: alloc::boxed::Box<LazyPieces<T>>,
    triangles: usize,
    /// The largest and the median leaf ball radius of `whole`.
    leaf_max: f64,
    leaf_median: f64,
    /// Whether the mesh is declared solid ([`TriMesh::try_solid`](crate::TriMesh::try_solid)).
    solid: bool,
    /// One point of each connected component of the triangles
    /// (`mesh::component_points`): what is tested inside a solid mesh.
    pub(crate) probes: Vec<[T; 3]>,
    /// The vertices of a closed convex mesh (`mesh::closed_convex_vertices`,
    /// `proofs/12-shapes.md`, Lemma 12.9): its triangles are the boundary of
    /// their hull.
    pub(crate) hull: Option<Vec<[T; 3]>>,
}

impl<T: Float> BallTree<T> {
    /// Builds the hierarchy of `triangles` (indices into `vertices`), with
    /// a hierarchy of pieces when its longest edge exceeds half the mesh's
    /// reach (its largest vertex distance from the rotation centre): every
    /// triangle longer than `1/32` of the reach cut to that length, within
    /// a budget of `max(16,384, 4 M)` pieces for `M` distinct triangles (the
    /// length coarsened until they fit; no hierarchy of pieces when no
    /// triangle is longer than a length that fits). See
    /// [`try_with_piece_length`](Self::try_with_piece_length).
    ///
    /// # Errors
    /// [`InputError::NoTriangles`] when there is no triangle,
    /// [`InputError::TriangleIndexOutOfRange`] for an index past the vertices
    /// (meshes built by [`TriMesh`](crate::TriMesh) never have one), and the
    /// core's range errors for vertices out of range.
    pub fn try_new(vertices: &[[T; 3]], triangles: &[[u32; 3]]) -> Result<Self, InputError> {
        let reach = triangles
            .iter()
            .flatten()
            .filter_map(|&i| vertices.get(i as usize))
            .map(|v| {
                let v = v.map(T::to_f64);
                (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
            })
            .fold(0.0f64, f64::max);
        let plan = PiecePlan {
            length: reach * PIECE_FRACTION,
            trigger: reach * PIECE_TRIGGER,
            budget: None,
        };
        Self::try_build(vertices, triangles, &plan)
    }

    /// Builds the hierarchy with pieces of length `length`: when a triangle's
    /// longest edge exceeds `length`, the tree gets a second hierarchy in
    /// which every such triangle is cut into pieces whose edges are at most
    /// `length` (by longest-edge bisection, at most 4,096 pieces a triangle;
    /// if the mesh's pieces would exceed 65,536, the length grows by factors
    /// `sqrt 2` until they fit, and there is no second hierarchy when no
    /// triangle is longer than a length that fits). `f64::INFINITY` makes no
    /// pieces.
    ///
    /// A large triangle as one leaf has one volume and one ball, whose
    /// directed bound is that of its farthest point, against every node of
    /// the other body near any part of it: a mesh of a few large triangles
    /// then costs far more than the same shape finely cut. A query takes the
    /// hierarchy of pieces when this mesh's largest leaf ball is more than
    /// four times the other mesh's median one (a board against a detailed
    /// model), and the whole triangles otherwise (a box against a box).
    /// Pieces are certified like whole triangles, widened by their corners'
    /// rounding (`proofs/09-ca-toi.md`, Lemma 9.5). Witnesses and
    /// [`closest_triangles`](crate::ca::MeshPair::closest_triangles) name
    /// the mesh's triangles.
    ///
    /// ```
    /// // `bodies`: the built-in test bodies (feature `bodies`).
    /// # #[cfg(feature = "bodies")] {
    /// use motion_bound::{bodies, BallTree};
    /// let board = bodies::board::<f64>(2.0, 2.0, 0.002)?;
    /// let cut = BallTree::try_with_piece_length(board.vertices(), board.triangles(), 0.05)?;
    /// let whole = BallTree::try_with_piece_length(board.vertices(), board.triangles(), f64::INFINITY)?;
    /// assert_eq!((cut.triangle_count(), whole.triangle_count()), (12, 12));
    /// assert!(cut.piece_leaf_count() > 100 && whole.piece_leaf_count() == 0);
    /// # }
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// As [`try_new`](Self::try_new), and [`InputError::PieceLength`] for a
    /// length that is NaN, zero or negative.
    pub fn try_with_piece_length(
        vertices: &[[T; 3]],
        triangles: &[[u32; 3]],
        length: f64,
    ) -> Result<Self, InputError> {
        if length.is_nan() || length <= 0.0 {
            return Err(InputError::PieceLength);
        }
        let plan = PiecePlan {
            length,
            trigger: length,
            budget: Some(PIECE_BUDGET),
        };
        Self::try_build(vertices, triangles, &plan)
    }

    fn try_build(
        vertices: &[[T; 3]],
        triangles: &[[u32; 3]],
        plan: &PiecePlan,
    ) -> Result<Self, InputError> {
        if triangles.is_empty() {
            return Err(InputError::NoTriangles);
        }
        let mut leaves = Vec::with_capacity(triangles.len());
        for (k, tri) in triangles.iter().enumerate() {
            let mut corners = [[T::ZERO; 3]; 3];
            for (c, &i) in corners.iter_mut().zip(tri) {
                *c = *vertices
                    .get(i as usize)
                    .ok_or(InputError::TriangleIndexOutOfRange {
                        triangle: k,
                        index: i,
                    })?;
            }
            let set = crate::VertexSet::try_new(&corners)?;
            leaves.push(Leaf {
                corners,
                r_hat: set.summary().max_radius(),
                inflate: T::ZERO,
                triangle: k as u32,
            });
        }
        // The hierarchy of pieces exists when some triangle is long enough;
        // it is built now, so that pairing the tree costs nothing.
        let longest = leaves
            .iter()
            .map(|l| pieces::longest_edge(&l.corners.map(|c| c.map(T::to_f64))).0)
            .fold(0.0f64, f64::max);
        let whole = Hierarchy::try_new(distinct(leaves), Split::Best)?;
        let budget = plan.budget.unwrap_or_else(|| {
            PIECES_PER_TRIANGLE
                .saturating_mul(whole.leaves.len())
                .max(MIN_PIECE_BUDGET)
        });
        let piece_plan =
            (longest > plan.trigger && plan.length > 0.0).then_some((plan.length, budget));
        let mut radii: Vec<f64> = whole
            .nodes
            .iter()
            .filter(|n| n.leaf().is_some())
            .map(|n| n.ball.radius().to_f64())
            .collect();
        radii.sort_by(f64::total_cmp);
        Ok(Self {
            solid: false,
            probes: crate::mesh::component_points(vertices, triangles),
            hull: crate::mesh::closed_convex_vertices(vertices, triangles),
            leaf_max: radii.last().copied().unwrap_or(0.0),
            leaf_median: radii.get(radii.len() / 2).copied().unwrap_or(0.0),
            pieces: alloc::boxed::Box::new(LazyPieces::new(piece_plan, &whole)),
            whole,
            triangles: triangles.len(),
        })
    }

    /// The hierarchy a query of this mesh against `other` descends: the one
    /// of pieces when this mesh has one and its largest leaf is more than
    /// four times the other's median leaf, else the one of whole triangles.
    pub(crate) fn against(&self, other: &Self) -> &Hierarchy<T> {
        if self.pieces.plan.is_none() || self.leaf_max <= PIECES_RATIO * other.leaf_median {
            return &self.whole;
        }
        self.pieces.get(&self.whole).unwrap_or(&self.whole)
    }
}

/// A tree's hierarchy of pieces (`(length, budget)` of [`build_pieces`]),
/// built the first time a query needs it (with `std`; without, when the
/// tree is built): a mesh against convex shapes never does, and its build
/// (about 40 ms for a 12-triangle board) is then not paid at all.
#[derive(Clone, Debug)]
struct LazyPieces<T> {
    plan: Option<(f64, usize)>,
    #[cfg(feature = "std")]
    built: std::sync::OnceLock<Option<Hierarchy<T>>>,
    #[cfg(not(feature = "std"))]
    built: Option<Hierarchy<T>>,
}

impl<T: Float> LazyPieces<T> {
    #[cfg(feature = "std")]
    fn new(plan: Option<(f64, usize)>, _whole: &Hierarchy<T>) -> Self {
        Self {
            plan,
            built: std::sync::OnceLock::new(),
        }
    }

    #[cfg(feature = "std")]
    fn get(&self, whole: &Hierarchy<T>) -> Option<&Hierarchy<T>> {
        let plan = self.plan?;
        self.built
            .get_or_init(|| build_pieces(whole, plan))
            .as_ref()
    }

    #[cfg(not(feature = "std"))]
    fn new(plan: Option<(f64, usize)>, whole: &Hierarchy<T>) -> Self {
        Self {
            plan,
            built: plan.and_then(|plan| build_pieces(whole, plan)),
        }
    }

    #[cfg(not(feature = "std"))]
    fn get(&self, _whole: &Hierarchy<T>) -> Option<&Hierarchy<T>> {
        self.built.as_ref()
    }
}

impl<T: Float> BallTree<T> {
    /// The hierarchy of a validated mesh (vertices relative to its rotation
    /// centre), solid when the mesh is declared solid.
    ///
    /// # Errors
    /// Only the core's range errors, for a mesh so large that a node radius
    /// exceeds [`Float::MAX_INPUT`].
    ///
    /// ```
    /// // `bodies`: the built-in test bodies (feature `bodies`).
    /// # #[cfg(feature = "bodies")] {
    /// use motion_bound::{bodies, BallTree};
    /// let mesh = bodies::torus::<f64>(1.0, 0.25, 24, 12).unwrap();
    /// let tree = BallTree::try_from_mesh(&mesh).unwrap();
    /// assert_eq!(tree.triangle_count(), mesh.triangle_count());
    /// # }
    /// ```
    pub fn try_from_mesh(mesh: &crate::TriMesh<T>) -> Result<Self, InputError> {
        let mut tree = Self::try_new(mesh.vertices(), mesh.triangles())?;
        tree.solid = mesh.is_solid();
        Ok(tree)
    }

    /// [`try_from_mesh`](Self::try_from_mesh) without the hierarchy of
    /// pieces, for the chain's links and obstacles: its queries bound a long
    /// triangle by its box's nearest face instead (`proofs/13-chains.md`,
    /// Lemma 13.4), so the pieces would only cost their build.
    pub(crate) fn try_whole_from_mesh(mesh: &crate::TriMesh<T>) -> Result<Self, InputError> {
        let mut tree =
            Self::try_with_piece_length(mesh.vertices(), mesh.triangles(), f64::INFINITY)?;
        tree.solid = mesh.is_solid();
        Ok(tree)
    }

    /// Whether the mesh is solid: built by [`try_from_mesh`](Self::try_from_mesh)
    /// from a mesh declared solid ([`TriMesh::try_solid`](crate::TriMesh::try_solid));
    /// a tree built from vertices and triangles is hollow. A body that starts
    /// inside a solid mesh is in contact with it.
    #[must_use]
    pub const fn is_solid(&self) -> bool {
        self.solid
    }

    /// Whether the mesh is closed and convex: its triangles, closed and
    /// consistently wound, are the whole boundary of the convex hull of at
    /// most 64 vertices, decided exactly when the tree is built
    /// (`proofs/12-shapes.md`, Lemma 12.9). A convex shape is then stepped
    /// against that hull, a polytope, wherever it is certified not to
    /// overlap the hull's inside ([`MeshConvexPair`](crate::ca::MeshConvexPair)).
    ///
    /// ```
    /// use motion_bound::{BallTree, TriMesh};
    /// let v = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let t = vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// assert!(BallTree::try_new(&v, &t)?.is_closed_convex());
    /// // Without its slanted face it is open.
    /// assert!(!BallTree::try_new(&v, &t[..3])?.is_closed_convex());
    /// # Ok::<(), motion_bound::InputError>(())
    /// ```
    #[must_use]
    pub const fn is_closed_convex(&self) -> bool {
        self.hull.is_some()
    }

    /// A solid closed convex mesh's hull, the body itself (Lemma 12.9):
    /// a polytope of its vertices.
    pub(crate) fn solid_hull(&self) -> Option<crate::Convex<'_, T>> {
        let v = self.hull.as_deref().filter(|_| self.solid)?;
        Some(crate::Convex::polytope(crate::VertexSet::from_validated(v)))
    }

    /// The root's ball: contains the whole mesh.
    #[must_use]
    pub fn root_ball(&self) -> &BoundingBall<T> {
        &self.whole.nodes[0].ball
    }

    /// The number of nodes of the hierarchy of whole triangles (`2 M - 1`
    /// for `M` distinct triangles).
    #[must_use]
    pub fn node_count(&self) -> usize {
        self.whole.nodes.len()
    }

    /// The number of distinct triangles, one leaf each: exact duplicates
    /// (the same corners in any order, a repeated corner counted once) are
    /// counted once.
    ///
    /// ```
    /// use motion_bound::BallTree;
    /// let v = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]];
    /// let tree = BallTree::try_new(&v, &[[0, 1, 2], [2, 0, 3], [0, 1, 1], [1, 0, 3]])?;
    /// assert_eq!((tree.triangle_count(), tree.distinct_triangle_count()), (4, 2));
    /// # Ok::<(), motion_bound::InputError>(())
    /// ```
    #[must_use]
    pub fn distinct_triangle_count(&self) -> usize {
        self.whole.leaves.len()
    }

    /// The number of the mesh's triangles.
    #[must_use]
    pub fn triangle_count(&self) -> usize {
        self.triangles
    }

    /// The number of leaves of the hierarchy of pieces (the pieces, and
    /// the distinct triangles short enough to stay whole), or
    /// `0` when the mesh has no triangle long enough to be cut
    /// ([`try_with_piece_length`](Self::try_with_piece_length)).
    #[must_use]
    pub fn piece_leaf_count(&self) -> usize {
        self.pieces.get(&self.whole).map_or(0, |p| p.leaves.len())
    }

    /// The length of the longest root-to-leaf path of the hierarchy of
    /// whole triangles, in nodes.
    #[must_use]
    pub fn depth(&self) -> usize {
        self.whole.depth
    }

    /// The rounded-up largest distance of a vertex from the rotation centre.
    #[must_use]
    pub fn max_radius(&self) -> T {
        self.whole
            .leaves
            .iter()
            .fold(T::ZERO, |m, l| m.max_nan(l.r_hat))
    }
}

#[cfg(test)]
mod tests {
    use super::BallTree;

    #[test]
    fn every_ball_contains_its_triangles_and_the_tree_is_complete() {
        // A strip of 64 triangles along a helix.
        let mut v = alloc::vec::Vec::new();
        let mut t = alloc::vec::Vec::new();
        for i in 0..66u32 {
            let a = f64::from(i) * 0.3;
            v.push([a.cos() * 2.0, a.sin() * 2.0, a * 0.1 + f64::from(i % 2)]);
        }
        for i in 0..64u32 {
            t.push([i, i + 1, i + 2]);
        }
        let tree = BallTree::try_new(&v, &t).unwrap();
        assert_eq!(tree.node_count(), 127, "2N - 1 nodes");
        assert_eq!(tree.triangle_count(), 64, "one leaf per triangle");
        assert!(
            tree.depth() <= 8,
            "median split is balanced: depth {}",
            tree.depth()
        );
        // Every node's ball holds the corners of every leaf below it.
        fn check(tree: &super::Hierarchy<f64>, node: usize) -> alloc::vec::Vec<usize> {
            let n = &tree.nodes[node];
            let below = match n.leaf() {
                Some(l) => alloc::vec![l],
                None => {
                    let mut b = check(tree, n.left as usize);
                    b.extend(check(tree, n.right as usize));
                    b
                }
            };
            let c = n.ball.centre();
            for &l in &below {
                for p in &tree.leaves[l].corners {
                    let d = ((p[0] - c[0]).powi(2) + (p[1] - c[1]).powi(2) + (p[2] - c[2]).powi(2))
                        .sqrt();
                    assert!(
                        d <= n.ball.radius(),
                        "node {node}: corner at {d} > {}",
                        n.ball.radius()
                    );
                }
            }
            below
        }
        let all = check(&tree.whole, 0);
        assert_eq!(all.len(), 64, "every leaf reached once");
    }

    #[test]
    fn bad_meshes_are_typed_errors() {
        let v = [[0.0f32; 3]; 3];
        assert_eq!(
            BallTree::try_new(&v, &[]).err(),
            Some(crate::InputError::NoTriangles),
            "no triangle"
        );
        assert_eq!(
            BallTree::try_new(&v, &[[0, 1, 2], [0, 1, 3]]).err(),
            Some(crate::InputError::TriangleIndexOutOfRange {
                triangle: 1,
                index: 3
            }),
            "index out of range"
        );
    }
}
