//! EVQ of a whole body without visiting every vertex: a ball tree over the
//! body's vertices and a branch and bound over it.

use alloc::vec::Vec;

use crate::geometry::hull_clusters::median_split;
use crate::shape::ball::enclosing_ball;
use crate::{
    BodySummary, BoundKind, BoundingBall, DirectedBound, DirectedProbe, Direction, Float,
    InputError, PreparedMotion, Quantity, RigidMotion, VertexSet,
};

/// Vertices per leaf.
const LEAF_SIZE: usize = 8;
/// No child.
pub(crate) const NONE: u32 = u32::MAX;

/// A node: the ball of its vertices `start..end` (of the tree's reordered
/// vertices), and its children (`NONE` for a leaf of at most 8 vertices).
#[derive(Clone, Copy, Debug)]
pub(crate) struct VNode<T> {
    pub(crate) ball: BoundingBall<T>,
    pub(crate) start: u32,
    pub(crate) end: u32,
    pub(crate) left: u32,
    pub(crate) right: u32,
}

/// A body's vertices with a ball tree over them, built once per body
/// (`O(N log N)`), so that its EVQ bounds cost far less than a scan of every
/// vertex ([`evq_speed`](Self::evq_speed), [`rate`](Self::rate)).
///
/// The value is a branch and bound (`proofs/08-ball-bound.md`, "Whole
/// bodies"): a node whose ball's `O(1)` bound
/// ([`DirectedProbe::ball_speed`]) is at most the best leaf bound found so
/// far is skipped, since every point below it moves no faster; the leaves
/// visited are bounded by the same scan as [`DirectedProbe::evq_speed`].
/// The result is a sound EVQ bound of the whole body, never above the scan's
/// and at most its rounding margin below it.
///
/// ```
/// use motion_bound::{evq_speed, BoundKind, Direction, RigidMotion, VertexSet, VertexTree};
/// // A coarse sphere of 2,000 points.
/// let points: Vec<[f64; 3]> = (0..2000)
///     .map(|i| {
///         let (a, b) = (i as f64 * 2.399963, (1.0 - 2.0 * (i as f64 + 0.5) / 2000.0).acos());
///         [b.sin() * a.cos(), b.sin() * a.sin(), b.cos()]
///     })
///     .collect();
/// let body = VertexSet::try_new(&points)?;
/// let tree = VertexTree::try_new(&body)?;
/// let m = RigidMotion::try_from_arrays([0.0; 3], [0.3, 0.0, 0.0], [0.0, 0.0, 0.5])?;
/// let n = Direction::try_from_array([1.0, 0.2, 0.1])?;
/// let (scan, fast) = (evq_speed(&body, &m, n), tree.evq(&m, n).speed);
/// assert!(fast <= scan && fast >= scan * (1.0 - 1e-12));
/// # Ok::<(), motion_bound::InputError>(())
/// ```
#[derive(Clone, Debug)]
pub struct VertexTree<T> {
    vertices: Vec<[T; 3]>,
    nodes: Vec<VNode<T>>,
    summary: BodySummary<T>,
}

impl<T: Float> VertexTree<T> {
    /// The tree over `body`'s vertices (already validated by
    /// [`VertexSet::try_new`]).
    ///
    /// # Errors
    /// [`InputError::TooLarge`] with [`Quantity::Radius`] for a body so
    /// large that a node's ball radius exceeds [`Float::MAX_INPUT`].
    pub fn try_new(body: &VertexSet<'_, T>) -> Result<Self, InputError> {
        let mut vertices = body.vertices().to_vec();
        let mut nodes = Vec::with_capacity(2 * vertices.len() / LEAF_SIZE + 1);
        build(&mut vertices, 0, &mut nodes)?;
        Ok(Self {
            vertices,
            nodes,
            summary: body.summary(),
        })
    }

    /// The nodes, the root first.
    pub(crate) fn nodes(&self) -> &[VNode<T>] {
        &self.nodes
    }

    /// The vertices, in the order the nodes' ranges index.
    pub(crate) fn vertices(&self) -> &[[T; 3]] {
        &self.vertices
    }

    /// The number of vertices.
    #[must_use]
    pub fn len(&self) -> usize {
        self.vertices.len()
    }

    /// Always `false`: a vertex set has at least one vertex.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.vertices.is_empty()
    }

    /// The body's summary (for NEVQ).
    #[must_use]
    pub const fn summary(&self) -> BodySummary<T> {
        self.summary
    }

    /// The EVQ speed bound along `probe`'s direction: the same bound as
    /// [`DirectedProbe::evq_speed`] of the whole vertex set, by branch and
    /// bound.
    #[must_use]
    pub fn evq_speed(&self, probe: &DirectedProbe<T>) -> T {
        self.speed_with_stats(probe).0
    }

    /// [`evq_speed`](Self::evq_speed) and the number of nodes visited.
    #[must_use]
    pub fn speed_with_stats(&self, probe: &DirectedProbe<T>) -> (T, usize) {
        let r_hat = self.summary.max_radius();
        let nevq = probe.nevq_speed(&self.summary);
        self.branch_and_bound(
            nevq,
            |ball| probe.ball_speed(ball, BoundKind::Evq),
            |points| probe.evq_speed_points(points, r_hat),
        )
    }

    /// The one-sided bound of kind `kind` along `probe`'s direction (as
    /// [`DirectedProbe::rate`] of the whole vertex set), by branch and bound
    /// over the balls' one-sided rates ([`DirectedProbe::ball_rate`]).
    #[must_use]
    pub fn rate(&self, probe: &DirectedProbe<T>, kind: BoundKind) -> T {
        let r_hat = self.summary.max_radius();
        if kind == BoundKind::Nevq {
            return probe.points_rate(&self.vertices[..1], r_hat, BoundKind::Nevq);
        }
        let nevq = probe.points_rate(&self.vertices[..1], r_hat, BoundKind::Nevq);
        self.branch_and_bound(
            nevq,
            |ball| probe.ball_rate(ball, BoundKind::Evq),
            |points| probe.points_rate(points, r_hat, BoundKind::Evq),
        )
        .0
    }

    /// The one-shot EVQ bound of the body under `motion` along `n` (as
    /// [`evq`](crate::evq)).
    #[must_use]
    pub fn evq(&self, motion: &RigidMotion<T>, n: Direction<T>) -> DirectedBound<T> {
        DirectedBound::from_speed(
            self.evq_speed(&PreparedMotion::new(motion).probe(n)),
            motion,
        )
    }

    /// The largest leaf value over the tree, skipping every node whose
    /// `node` value is at most the best found (the values are upper bounds
    /// for the node's points, `leaf` is one for its points); stops at `cap`
    /// (no leaf value exceeds it: they are all at most NEVQ's).
    fn branch_and_bound(
        &self,
        cap: T,
        node: impl Fn(&BoundingBall<T>) -> T,
        leaf: impl Fn(&[[T; 3]]) -> T,
    ) -> (T, usize) {
        let mut best = -T::INFINITY;
        let mut visited = 0;
        // Depth-first, the child with the larger bound first; the tree's
        // depth is below 64 (median splits of at most 2^32 vertices).
        let mut stack = [(0u32, T::ZERO); 128];
        let mut top = 0;
        stack[0] = (0, node(&self.nodes[0].ball));
        top += 1;
        while top > 0 {
            top -= 1;
            let (i, bound) = stack[top];
            if bound <= best {
                continue;
            }
            visited += 1;
            let n = &self.nodes[i as usize];
            if n.left == NONE {
                let v = leaf(&self.vertices[n.start as usize..n.end as usize]);
                if v > best || v.is_nan() {
                    // NaN propagates: a NaN bound is returned as it is.
                    best = v;
                    if best >= cap || best.is_nan() {
                        break;
                    }
                }
                continue;
            }
            let (l, r) = (n.left, n.right);
            let (bl, br) = (
                node(&self.nodes[l as usize].ball),
                node(&self.nodes[r as usize].ball),
            );
            let (first, second) = if bl >= br {
                ((l, bl), (r, br))
            } else {
                ((r, br), (l, bl))
            };
            if top + 2 > stack.len() {
                // Never reached (see above); scan the subtree instead.
                let v = leaf(&self.vertices[n.start as usize..n.end as usize]);
                best = best.max_nan(v);
                continue;
            }
            stack[top] = second;
            stack[top + 1] = first;
            top += 2;
        }
        (best, visited)
    }
}

/// Builds the subtree over `vertices` (a window of the whole array starting
/// at `offset`), appending its nodes; returns the root's index.
fn build<T: Float>(
    vertices: &mut [[T; 3]],
    offset: usize,
    nodes: &mut Vec<VNode<T>>,
) -> Result<u32, InputError> {
    let ball = enclosing_ball(vertices)?;
    let (mut lo, mut hi) = ([T::INFINITY; 3], [-T::INFINITY; 3]);
    for v in vertices.iter() {
        for k in 0..3 {
            lo[k] = lo[k].min_nan(v[k]);
            hi[k] = hi[k].max_nan(v[k]);
        }
    }
    let index = u32::try_from(nodes.len()).map_err(|_| InputError::TooLarge(Quantity::Radius))?;
    let span = |x: usize| u32::try_from(x).unwrap_or(u32::MAX);
    nodes.push(VNode {
        ball,
        start: span(offset),
        end: span(offset + vertices.len()),
        left: NONE,
        right: NONE,
    });
    if vertices.len() <= LEAF_SIZE {
        return Ok(index);
    }
    let mid = median_split(vertices, lo, hi);
    let (left_half, right_half) = vertices.split_at_mut(mid);
    let left = build(left_half, offset, nodes)?;
    let right = build(right_half, offset + mid, nodes)?;
    let node = &mut nodes[index as usize];
    node.left = left;
    node.right = right;
    Ok(index)
}
