//! A bounding-volume hierarchy of balls over a triangle mesh, relative to the
//! body's rotation centre: what conservative advancement of non-convex
//! meshes traverses.

use alloc::vec::Vec;

mod eigen;
mod oriented_box;
mod pieces;
mod vertex_tree;

use eigen::principal_axes;

pub(crate) use oriented_box::OrientedBox;
pub use vertex_tree::VertexTree;

use crate::rounding::{add_up, offset_radius_up};
use crate::{BoundingBall, Float, InputError};

/// Marks a leaf in [`Node::right`].
const LEAF: u32 = u32::MAX;

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

/// The default piece length: this fraction of the mesh's reach (the largest
/// vertex distance from the rotation centre).
const PIECE_FRACTION: f64 = 1.0 / 32.0;

/// By default a mesh gets a hierarchy of pieces when its longest edge
/// exceeds this fraction of its reach.
const PIECE_TRIGGER: f64 = 0.5;

/// The default budget of pieces: this many per triangle, and at least
/// [`MIN_PIECE_BUDGET`].
const PIECES_PER_TRIANGLE: usize = 4;
const MIN_PIECE_BUDGET: usize = 16384;

/// The budget of pieces for a length given by the caller.
const PIECE_BUDGET: usize = 1 << 16;

/// How a tree's hierarchy of pieces is made: it exists when some triangle's
/// longest edge exceeds `trigger`; every triangle longer than the piece
/// length is cut down to it, the length being `length` or the least
/// multiple of it by a power of `sqrt 2` whose pieces fit in `budget`.
struct PiecePlan {
    length: f64,
    trigger: f64,
    budget: usize,
}

/// A query uses a mesh's hierarchy of pieces when its largest leaf ball is
/// more than this many times the other mesh's median leaf ball.
pub(crate) const PIECES_RATIO: f64 = 4.0;

/// One bounding-volume hierarchy: its nodes (the root first) and leaves.
#[derive(Clone, Debug)]
pub(crate) struct Hierarchy<T> {
    pub(crate) nodes: Vec<Node<T>>,
    pub(crate) leaves: Vec<Leaf<T>>,
    depth: usize,
    /// An upper bound of the distance from the rotation centre of every
    /// node centre and every box point.
    pub(crate) reach: T,
}

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
/// Built top-down, one triangle per leaf (`2 N - 1` nodes for `N`
/// triangles): each node is split at the median of whichever of three keys
/// (centroids along the widest axis or along the box's longest axis,
/// normals along their principal axis) gives the children the smallest total
/// box surface. `O(N log^2 N)`: about 0.5 s for 34K triangles here.
///
/// A mesh with a triangle much longer than its size scale (an edge over
/// half its reach, as a board's or a box's) also gets a second hierarchy in
/// which its long triangles are cut into pieces
/// ([`try_with_piece_length`](Self::try_with_piece_length)); a query takes
/// it against a mesh of much smaller triangles. That hierarchy splits at the
/// median of one key (centroids along the widest axis): about 46 ms for
/// the 13,768 pieces of a 12-triangle board here, paid by the first query
/// that takes it (with `std`; without, when the tree is built).
#[derive(Clone, Debug)]
pub struct BallTree<T> {
    /// Every triangle whole.
    pub(crate) whole: Hierarchy<T>,
    /// Long triangles cut into pieces (`pieces()`), when the mesh has any.
    pieces: PieceCell<T>,
    triangles: usize,
    /// The largest and the median leaf ball radius of `whole`.
    leaf_max: f64,
    leaf_median: f64,
}

impl<T: Float> BallTree<T> {
    /// Builds the hierarchy of `triangles` (indices into `vertices`), with
    /// a hierarchy of pieces when its longest edge exceeds half the mesh's
    /// reach (its largest vertex distance from the rotation centre): every
    /// triangle longer than `1/32` of the reach cut to that length, within
    /// a budget of `max(16,384, 4 N)` pieces (the length coarsened until they
    /// fit). See [`try_with_piece_length`](Self::try_with_piece_length).
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
            budget: (PIECES_PER_TRIANGLE * triangles.len()).max(MIN_PIECE_BUDGET),
        };
        Self::try_build(vertices, triangles, &plan)
    }

    /// Builds the hierarchy with pieces of length `length`: when a triangle's
    /// longest edge exceeds `length`, the tree gets a second hierarchy in
    /// which every such triangle is cut into pieces whose edges are at most
    /// `length` (by longest-edge bisection, at most 4,096 pieces a triangle;
    /// if the mesh's pieces would exceed 65,536, the length grows by factors
    /// `sqrt 2` until they fit). `f64::INFINITY` makes no pieces.
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
    /// use motion_bound::{bodies, BallTree};
    /// let board = bodies::board::<f64>(2.0, 2.0, 0.002)?;
    /// let cut = BallTree::try_with_piece_length(board.vertices(), board.triangles(), 0.05)?;
    /// let whole = BallTree::try_with_piece_length(board.vertices(), board.triangles(), f64::INFINITY)?;
    /// assert_eq!((cut.triangle_count(), whole.triangle_count()), (12, 12));
    /// assert!(cut.piece_leaf_count() > 100 && whole.piece_leaf_count() == 0);
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
            budget: PIECE_BUDGET,
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
        // it is built on first use (with `std`) or now.
        let longest = leaves
            .iter()
            .map(|l| pieces::longest_edge(&l.corners.map(|c| c.map(T::to_f64))).0)
            .fold(0.0f64, f64::max);
        let piece_plan =
            (longest > plan.trigger && plan.length > 0.0).then_some((plan.length, plan.budget));
        let whole = Hierarchy::try_new(leaves, true)?;
        let mut radii: Vec<f64> = whole
            .nodes
            .iter()
            .filter(|n| n.leaf().is_some())
            .map(|n| n.ball.radius().to_f64())
            .collect();
        radii.sort_by(f64::total_cmp);
        Ok(Self {
            leaf_max: radii.last().copied().unwrap_or(0.0),
            leaf_median: radii.get(radii.len() / 2).copied().unwrap_or(0.0),
            pieces: PieceCell::new(&whole.leaves, piece_plan),
            whole,
            triangles: triangles.len(),
        })
    }

    /// The hierarchy of pieces, built on first use, or `None` when the mesh
    /// has no triangle long enough.
    fn pieces(&self) -> Option<&Hierarchy<T>> {
        self.pieces.get(&self.whole.leaves)
    }

    /// The hierarchy a query of this mesh against `other` descends: the one
    /// of pieces when this mesh has one and its largest leaf is more than
    /// four times the other's median leaf, else the one of whole triangles.
    pub(crate) fn against(&self, other: &Self) -> &Hierarchy<T> {
        if self.pieces.plan.is_some() && self.leaf_max > PIECES_RATIO * other.leaf_median {
            if let Some(p) = self.pieces() {
                return p;
            }
        }
        &self.whole
    }
}

impl<T: Float> Hierarchy<T> {
    /// The hierarchy over `leaves` (at least one). With `trials`, each split
    /// takes the best of three keys by the children's box surface; without,
    /// the first key (for the many small leaves of pieces: a faster build).
    fn try_new(leaves: Vec<Leaf<T>>, trials: bool) -> Result<Self, InputError> {
        let mut order: Vec<u32> = (0..leaves.len() as u32).collect();
        let mut h = Self {
            nodes: Vec::with_capacity(2 * leaves.len()),
            leaves: Vec::new(),
            depth: 0,
            reach: T::ZERO,
        };
        h.depth = h.build(&leaves, &mut order, 1, trials)?;
        h.leaves = leaves;
        h.reach = h.nodes.iter().fold(T::ZERO, |m, n| {
            m.max_nan(n.obb.reach_up())
                .max_nan(n.ball.outer_radius_up())
        });
        Ok(h)
    }

    /// Appends the subtree over `order` and returns its depth.
    fn build(
        &mut self,
        leaves: &[Leaf<T>],
        order: &mut [u32],
        depth: usize,
        trials: bool,
    ) -> Result<usize, InputError> {
        let index = self.nodes.len();
        let inflate = order
            .iter()
            .fold(T::ZERO, |m, &l| m.max_nan(leaves[l as usize].inflate));
        let (ball, obb) =
            enclosing_volumes(order.iter().map(|&l| &leaves[l as usize].corners), inflate)?;
        if let [only] = order {
            self.nodes.push(Node {
                ball,
                obb,
                left: *only,
                right: LEAF,
            });
            return Ok(depth);
        }
        self.nodes.push(Node {
            ball,
            obb,
            left: 0,
            right: 0,
        });
        // Split at the median of one of three keys: the centroid along the
        // widest axis of the centroids, the centroid along the box's longest
        // axis, and the triangle normal along the normals' principal axis (a
        // tube is cut lengthwise into flatter halves). The split whose
        // children's boxes have the least total surface (`h0 h1 + h1 h2 +
        // h0 h2`) wins: tighter boxes overlap less near contact. Only the
        // tree's shape depends on this choice; every box is certified anyway.
        let centroid = |l: u32| {
            let c = &leaves[l as usize].corners;
            [0, 1, 2].map(|k| c[0][k].to_f64() + c[1][k].to_f64() + c[2][k].to_f64())
        };
        let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        for &l in order.iter() {
            let c = centroid(l);
            for k in 0..3 {
                lo[k] = lo[k].min(c[k]);
                hi[k] = hi[k].max(c[k]);
            }
        }
        let ext = [0, 1, 2].map(|k| hi[k] - lo[k]);
        let axis = if ext[0] >= ext[1] && ext[0] >= ext[2] {
            0
        } else if ext[1] >= ext[2] {
            1
        } else {
            2
        };
        let long = obb.axes[0].map(T::to_f64);
        let normals_axis = principal_axes(normal_scatter(leaves, order))[0];
        let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let keys: [&dyn Fn(u32) -> f64; 3] =
            [&|l| centroid(l)[axis], &|l| dot(centroid(l), long), &|l| {
                dot(unit_normal(&leaves[l as usize].corners), normals_axis)
            }];
        let by = |key: &dyn Fn(u32) -> f64, x: &u32, y: &u32| {
            key(*x)
                .partial_cmp(&key(*y))
                .unwrap_or(core::cmp::Ordering::Equal)
        };
        let mid = order.len() / 2;
        let mut best = (f64::INFINITY, 0);
        if trials && order.len() >= 4 {
            let mut trial = order.to_vec();
            for (k, key) in keys.iter().enumerate() {
                trial.select_nth_unstable_by(mid, |x, y| by(*key, x, y));
                let (l, r) = trial.split_at(mid);
                let area = |set: &[u32]| {
                    let b = OrientedBox::fit(
                        set.iter().flat_map(|&t| leaves[t as usize].corners.iter()),
                    );
                    let h = b.half.map(T::to_f64);
                    h[0] * h[1] + h[1] * h[2] + h[0] * h[2]
                };
                let cost = area(l) + area(r);
                if cost < best.0 {
                    best = (cost, k);
                }
            }
        }
        order.select_nth_unstable_by(mid, |x, y| by(keys[best.1], x, y));
        let (left, right) = order.split_at_mut(mid);
        let left_index = self.nodes.len() as u32;
        let dl = self.build(leaves, left, depth + 1, trials)?;
        let right_index = self.nodes.len() as u32;
        let dr = self.build(leaves, right, depth + 1, trials)?;
        self.nodes[index].left = left_index;
        self.nodes[index].right = right_index;
        Ok(dl.max(dr))
    }
}

impl<T: Float> BallTree<T> {
    /// The hierarchy of a validated mesh (vertices relative to its rotation centre).
    ///
    /// # Errors
    /// Only the core's range errors, for a mesh so large that a node radius
    /// exceeds [`Float::MAX_INPUT`].
    ///
    /// ```
    /// use motion_bound::{bodies, BallTree};
    /// let mesh = bodies::torus::<f64>(1.0, 0.25, 24, 12).unwrap();
    /// let tree = BallTree::try_from_mesh(&mesh).unwrap();
    /// assert_eq!(tree.triangle_count(), mesh.triangle_count());
    /// ```
    pub fn try_from_mesh(mesh: &crate::TriMesh<T>) -> Result<Self, InputError> {
        Self::try_new(mesh.vertices(), mesh.triangles())
    }

    /// The root's ball: contains the whole mesh.
    #[must_use]
    pub fn root_ball(&self) -> &BoundingBall<T> {
        &self.whole.nodes[0].ball
    }

    /// The number of nodes of the hierarchy of whole triangles (`2 N - 1`
    /// for `N` triangles).
    #[must_use]
    pub fn node_count(&self) -> usize {
        self.whole.nodes.len()
    }

    /// The number of the mesh's triangles.
    #[must_use]
    pub fn triangle_count(&self) -> usize {
        self.triangles
    }

    /// The number of leaves of the hierarchy of pieces (the pieces, and
    /// the triangles short enough to stay whole; built now if not yet), or
    /// `0` when the mesh has no triangle long enough to be cut
    /// ([`try_with_piece_length`](Self::try_with_piece_length)).
    #[must_use]
    pub fn piece_leaf_count(&self) -> usize {
        self.pieces().map_or(0, |p| p.leaves.len())
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

/// The hierarchy of pieces of `leaves` (the whole triangles, in the mesh's
/// order): the finest length from `length` up by factors `sqrt 2` whose
/// pieces fit in `budget`; every triangle longer than it cut, the others
/// whole. `None` if a piece's corners were out of range (never for a valid
/// mesh: they lie in its triangles' hulls); the whole triangles then serve.
fn build_pieces<T: Float>(
    leaves: &[Leaf<T>],
    (length, budget): (f64, usize),
) -> Option<Hierarchy<T>> {
    let edges: Vec<f64> = leaves
        .iter()
        .map(|l| pieces::longest_edge(&l.corners.map(|c| c.map(T::to_f64))).0)
        .collect();
    let longest = edges.iter().copied().fold(0.0f64, f64::max);
    let fits = |length: f64| {
        let mut left = budget;
        leaves.iter().zip(&edges).all(|(l, &e)| {
            e <= length || pieces::Cutter::new(l.corners, length).count_within(&mut left)
        })
    };
    let mut length = length;
    while length < longest && !fits(length) {
        length *= core::f64::consts::SQRT_2;
    }
    let mut cut = Vec::new();
    for (leaf, &e) in leaves.iter().zip(&edges) {
        if e > length {
            pieces::Cutter::new(leaf.corners, length)
                .push_pieces(&mut cut, leaf.triangle)
                .ok()?;
        } else {
            cut.push(*leaf);
        }
    }
    Hierarchy::try_new(cut, false).ok()
}

/// Where a tree keeps its hierarchy of pieces and how to make it (the
/// finest length and the budget; `None` when the mesh has no triangle long
/// enough): built on first use with `std` (a `OnceLock`, so that trees stay
/// `Sync` and a mesh never paired with a much finer one never pays for it),
/// eagerly without.
#[derive(Clone, Debug)]
struct PieceCell<T> {
    plan: Option<(f64, usize)>,
    #[cfg(feature = "std")]
    cell: std::sync::OnceLock<Option<Hierarchy<T>>>,
    #[cfg(not(feature = "std"))]
    built: Option<Hierarchy<T>>,
}

impl<T: Float> PieceCell<T> {
    #[cfg(feature = "std")]
    fn new(_leaves: &[Leaf<T>], plan: Option<(f64, usize)>) -> Self {
        Self {
            plan,
            cell: std::sync::OnceLock::new(),
        }
    }

    #[cfg(not(feature = "std"))]
    fn new(leaves: &[Leaf<T>], plan: Option<(f64, usize)>) -> Self {
        Self {
            plan,
            built: plan.and_then(|p| build_pieces(leaves, p)),
        }
    }

    /// The hierarchy of pieces of the whole triangles `leaves`, if planned.
    #[cfg(feature = "std")]
    fn get(&self, leaves: &[Leaf<T>]) -> Option<&Hierarchy<T>> {
        let plan = self.plan?;
        self.cell
            .get_or_init(|| build_pieces(leaves, plan))
            .as_ref()
    }

    /// The hierarchy of pieces, if planned.
    #[cfg(not(feature = "std"))]
    fn get(&self, _leaves: &[Leaf<T>]) -> Option<&Hierarchy<T>> {
        self.built.as_ref()
    }
}

/// The unit normal of a triangle (in `f64`; zero for a degenerate one).
fn unit_normal<T: Float>(c: &[[T; 3]; 3]) -> [f64; 3] {
    let e1 = [0, 1, 2].map(|k| c[1][k].to_f64() - c[0][k].to_f64());
    let e2 = [0, 1, 2].map(|k| c[2][k].to_f64() - c[0][k].to_f64());
    let n = [
        e1[1] * e2[2] - e1[2] * e2[1],
        e1[2] * e2[0] - e1[0] * e2[2],
        e1[0] * e2[1] - e1[1] * e2[0],
    ];
    // Divided by its largest component first: the squares of a cross
    // product (fourth powers of lengths) would overflow or underflow for
    // meshes of coordinates beyond about `1e77` or below `1e-77`.
    let m = n[0].abs().max(n[1].abs()).max(n[2].abs());
    if !(m > 0.0 && m.is_finite()) {
        return [0.0; 3];
    }
    let n = n.map(|x| x / m);
    let len = Float::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    n.map(|x| x / len)
}

/// The scatter matrix of the unit normals of `order`'s triangles about
/// their mean: its principal axis is the direction the normals vary along.
fn normal_scatter<T: Float>(leaves: &[Leaf<T>], order: &[u32]) -> [[f64; 3]; 3] {
    let mut mean = [0.0f64; 3];
    for &l in order {
        let n = unit_normal(&leaves[l as usize].corners);
        for k in 0..3 {
            mean[k] += n[k];
        }
    }
    let mean = mean.map(|x| x / order.len().max(1) as f64);
    let mut s = [[0.0f64; 3]; 3];
    for &l in order {
        let n = unit_normal(&leaves[l as usize].corners);
        let d = [0, 1, 2].map(|k| n[k] - mean[k]);
        for i in 0..3 {
            for j in 0..3 {
                s[i][j] += d[i] * d[j];
            }
        }
    }
    s
}

/// The node's oriented box (`OrientedBox::fit`) and a ball centred at the
/// box's centre holding every corner, its radius the largest corner distance
/// rounded up (`rounding::offset_radius_up`); both widened by `inflate`, the
/// largest rounding of a piece's corners below the node (`0` for whole
/// triangles: unchanged).
fn enclosing_volumes<'a, T: Float + 'a>(
    tris: impl Iterator<Item = &'a [[T; 3]; 3]> + Clone,
    inflate: T,
) -> Result<(BoundingBall<T>, OrientedBox<T>), InputError> {
    let mut obb = OrientedBox::fit(tris.clone().flatten());
    if inflate > T::ZERO {
        obb = obb.widened(inflate);
    }
    let centre = obb.centre;
    let mut max_sq = T::ZERO;
    for tri in tris {
        for c in tri {
            let d = [0, 1, 2].map(|k| c[k] - centre[k]);
            max_sq = max_sq.max_nan(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        }
    }
    let radius = offset_radius_up(max_sq);
    let radius = if inflate > T::ZERO {
        add_up(radius, inflate)
    } else {
        radius
    };
    Ok((BoundingBall::try_new(centre, radius)?, obb))
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
