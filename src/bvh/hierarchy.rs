//! One bounding-volume hierarchy over leaves, built top-down: each node's
//! volumes enclose its leaves, and each split is at the median of the key
//! that gives the children the least box surface.

use alloc::vec::Vec;

use super::eigen::principal_axes;
use super::node::{Leaf, Node, LEAF};
use super::oriented_box::OrientedBox;
use crate::rounding::{add_up, offset_radius_up};
use crate::{BoundingBall, Float, InputError};

/// One bounding-volume hierarchy: its nodes (the root first) and leaves.
#[derive(Clone, Debug)]
pub(crate) struct Hierarchy<T> {
    pub(crate) nodes: Vec<Node<T>>,
    pub(crate) leaves: Vec<Leaf<T>>,
    pub(super) depth: usize,
    /// An upper bound of the distance from the rotation centre of every
    /// node centre and every box point.
    pub(crate) reach: T,
}

/// How a hierarchy's nodes are split: each at the median of one of three keys
/// (the centroid along the widest axis of the centroids, the centroid along
/// the box's longest axis, the triangle normal along a third axis), the
/// first key unless the three are tried.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Split {
    /// The best of the three keys at every node, by the children's fitted
    /// boxes' surface (whole triangles).
    Best,
    /// The best of the three in nodes of at most this many leaves, by the
    /// surface of the children's boxes along the node's own axes (no fit);
    /// the first key above. For pieces: the last levels are where a thin
    /// board's two faces part, and this costs about a quarter more than one
    /// key where fitting every trial cost three times as much
    /// (`examples/coarse_fine.rs`, `docs/performance.md`).
    BestBelow(usize),
}

impl<T: Float> Hierarchy<T> {
    /// The hierarchy over `leaves` (at least one), each split chosen as
    /// `split` says.
    pub(super) fn try_new(leaves: Vec<Leaf<T>>, split: Split) -> Result<Self, InputError> {
        let mut order: Vec<u32> = (0..leaves.len() as u32).collect();
        let mut h = Self {
            nodes: Vec::with_capacity(2 * leaves.len()),
            leaves: Vec::new(),
            depth: 0,
            reach: T::ZERO,
        };
        h.depth = h.build(&leaves, &mut order, 1, split)?;
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
        split: Split,
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
        // The keys are tried as `split` says; the third's axis is the
        // normals' principal axis (two passes and an eigensolve) for whole
        // triangles, the box's thinnest axis for pieces (a board's two faces
        // apart).
        let small = match split {
            Split::Best => false,
            Split::BestBelow(n) => order.len() <= n,
        };
        let trying = order.len() >= 4 && (split == Split::Best || small);
        let normals_axis = match split {
            Split::Best if trying => principal_axes(normal_scatter(leaves, order))[0],
            _ => obb.axes[2].map(T::to_f64),
        };
        let frame = obb.axes.map(|a| a.map(T::to_f64));
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
        if trying {
            let mut trial = order.to_vec();
            for (k, key) in keys.iter().enumerate() {
                trial.select_nth_unstable_by(mid, |x, y| by(*key, x, y));
                let (l, r) = trial.split_at(mid);
                // The children's boxes' surface: fitted boxes for whole
                // triangles, boxes along this node's axes for pieces.
                let area = |set: &[u32]| {
                    let h = if small {
                        let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
                        for &t in set {
                            for c in &leaves[t as usize].corners {
                                let c = c.map(T::to_f64);
                                for k in 0..3 {
                                    let x = dot(c, frame[k]);
                                    lo[k] = lo[k].min(x);
                                    hi[k] = hi[k].max(x);
                                }
                            }
                        }
                        [0, 1, 2].map(|k| hi[k] - lo[k])
                    } else {
                        let b = OrientedBox::fit(
                            set.iter().flat_map(|&t| leaves[t as usize].corners.iter()),
                        );
                        b.half.map(T::to_f64)
                    };
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
        let dl = self.build(leaves, left, depth + 1, split)?;
        let right_index = self.nodes.len() as u32;
        let dr = self.build(leaves, right, depth + 1, split)?;
        self.nodes[index].left = left_index;
        self.nodes[index].right = right_index;
        Ok(dl.max(dr))
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
