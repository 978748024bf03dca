//! The one dispatch of a chain's pairs by the kinds of their sides: what a
//! link is checked against (a mesh obstacle, a convex primitive, a
//! half-space, a point cloud, another link), which engine answers each
//! query for it, and a link against a shape measured at one configuration.
//!
//! Every query of [`ChainScene`](crate::chain::ChainScene) takes its pairs
//! from one list (`ChainScene::pairs`) and asks here how each is served:
//!
//! | what the link meets | first contact (`check_segment`) | distance at `q` (`clearance`) | edge queries, `collides_at` |
//! |---|---|---|---|
//! | a mesh obstacle, a link | conservative advancement (`advance.rs`, Lemma 13.4) | [`min_gap`] (`gap.rs`) | [`Target::Mesh`], [`Target::Link`] (`edge.rs`) |
//! | a convex primitive, a half-space | the edge engine, depth first in time (Lemma 13.5) | [`shape_min_gap`] (Lemma 13.14) | [`Target::Shape`] |
//! | a point cloud | the edge engine, depth first in time | [`shape_min_gap`] over the cloud's tree | [`Target::Cloud`] |
//!
//! A link against a shape is measured by [`Against`] (`shapes.rs`): the
//! rigid engine's certified slab gaps (`ca::certified_gap_to`,
//! `ca/convex_convex.rs`) along GJK's direction or a closed form, so a new
//! convex core kind serves every chain query with no code here. A new kind
//! of obstacle is a variant of `shapes::Geometry`, an arm of [`target_of`],
//! of [`shape_min_gap`] and of the edge engine's `test`.

use alloc::vec::Vec;

use crate::bvh::{Hierarchy, NO_CHILD};
use crate::ca::PlacedCore;
use crate::chain::bound::LinkMotion;
use crate::chain::edge::Target;
use crate::chain::gap::{min_gap, placed_corners, Near};
use crate::chain::report::{ChainPair, ChainStats};
use crate::chain::shapes::{node_points, triangle_points_gap, Against, Geometry, ShapeObstacle};
use crate::geometry::closest::point_triangle_vec;
use crate::geometry::gjk::{gjk_distance, ConvexPolytope, GjkParams};
use crate::rounding::{gap_down, sum_up};
use crate::{Float, Pose, Vec3};

/// Which engine answers a pair's first-contact query.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum FirstContact {
    /// Conservative advancement of two hierarchies (meshes and links).
    Advance,
    /// The edge engine, depth first in time (shapes and clouds).
    Edge,
}

/// The engine of `pair`'s first-contact query.
#[must_use]
pub(super) const fn first_contact_engine(pair: ChainPair) -> FirstContact {
    match pair {
        ChainPair::Obstacle { .. } | ChainPair::SelfCollision { .. } => FirstContact::Advance,
        ChainPair::Shape { .. } => FirstContact::Edge,
    }
}

/// The link of `pair` (the first of two).
#[must_use]
pub(super) const fn first_link(pair: ChainPair) -> usize {
    match pair {
        ChainPair::SelfCollision { a, .. } => a,
        ChainPair::Obstacle { link, .. } | ChainPair::Shape { link, .. } => link,
    }
}

/// The edge engine's root target of `pair` (the root nodes of trees).
#[must_use]
pub(super) fn target_of<T: Float>(pair: ChainPair, shapes: &[ShapeObstacle<T>]) -> Target {
    match pair {
        ChainPair::Shape { shape, .. } => match shapes[shape].geometry {
            Geometry::Points { .. } => Target::Cloud(shape as u32, 0),
            _ => Target::Shape(shape as u32),
        },
        ChainPair::Obstacle { obstacle, .. } => Target::Mesh(obstacle as u32, 0),
        ChainPair::SelfCollision { b, .. } => Target::Link(b as u32, 0),
    }
}

/// A checked pair with the chain still at one configuration: the first
/// link's hierarchy, the other side's (`None` for a shape) and both sides'
/// motions.
pub(super) struct PlacedPair<'a, T> {
    pub(super) pair: ChainPair,
    pub(super) ta: &'a Hierarchy<T>,
    pub(super) tb: Option<&'a Hierarchy<T>>,
    pub(super) a: &'a LinkMotion<T>,
    pub(super) b: &'a LinkMotion<T>,
}

/// The smallest certified gap of a placed pair (node pairs at least `cap`
/// apart not refined), with the closest leaves' computed distance and
/// witnesses when within `cap_touch`: [`min_gap`] for two hierarchies,
/// [`shape_min_gap`] for a link and a shape.
#[must_use]
pub(super) fn placed_gap<T: Float>(
    p: &PlacedPair<'_, T>,
    shapes: &[ShapeObstacle<T>],
    cap: T,
    cap_touch: T,
    stack: &mut Vec<(u32, u32)>,
    stats: &mut ChainStats,
) -> Near<T> {
    match (p.pair, p.tb) {
        (ChainPair::Shape { shape, .. }, _) => {
            shape_min_gap(p.ta, p.a, &shapes[shape], cap, cap_touch, stack, stats)
        }
        (_, Some(tb)) => min_gap(p.ta, tb, p.a, p.b, cap, T::ZERO, cap_touch, stack, stats),
        (_, None) => Near {
            gap: cap,
            closest: None,
        },
    }
}

/// What a link's node is measured against in [`shape_min_gap`].
fn against_of<T: Float>(o: &ShapeObstacle<T>) -> Option<Against<'_, T>> {
    match &o.geometry {
        Geometry::Convex(shape) => Some(Against::Convex(shape, o.pose, o.support_err)),
        Geometry::HalfSpace(m) => Some(Against::Plane(*m, o.pose, o.support_err)),
        Geometry::Points { .. } => None,
    }
}

/// The smallest certified gap between link tree `ta` placed by `a` and the
/// shape obstacle `o` (Lemma 13.14): branch and bound over the link's tree
/// (and a cloud's), a node pruned when its certified ball gap is at least
/// the best leaf gap found (or `cap`); a leaf measured by [`Against`]'s
/// certified slab gap along GJK's direction (a closed form for a plane or a
/// cloud's points). `closest` is the least computed distance of a leaf
/// within `cap_touch`, with its witnesses (link side first).
#[must_use]
pub(super) fn shape_min_gap<T: Float>(
    ta: &Hierarchy<T>,
    a: &LinkMotion<T>,
    o: &ShapeObstacle<T>,
    cap: T,
    cap_touch: T,
    stack: &mut Vec<(u32, u32)>,
    stats: &mut ChainStats,
) -> Near<T> {
    let mut best = cap;
    let mut closest: Option<(T, Vec3<T>, Vec3<T>)> = None;
    stack.clear();
    stack.push((0, 0));
    while let Some((ia, ib)) = stack.pop() {
        stats.node_pairs += 1;
        let na = &ta.nodes[ia as usize];
        let ca = a.pose.transform_point(*na.ball.centre());
        let ra = na.ball.radius();
        match (&o.geometry, against_of(o)) {
            (_, Some(against)) => {
                let g = against.ball_gap(ca, ra, a.delta);
                if g >= best {
                    continue;
                }
                match na.leaf() {
                    Some(leaf) => {
                        stats.leaf_pairs += 1;
                        let tri = placed_corners(ta, leaf, a);
                        let (gap, estimate) = against.triangle_gap(&tri, a.delta);
                        best = best.min_nan(gap);
                        if (estimate <= cap_touch || estimate.is_nan())
                            && closest.is_none_or(|(d, _, _)| estimate < d)
                        {
                            let (on_a, on_b) = against_witnesses(&against, &tri);
                            closest = Some((estimate, on_a, on_b));
                        }
                    }
                    None => push_link_children(stack, ta, a, ca, na.left, na.right, ib),
                }
            }
            (Geometry::Points { tree, radius, ball }, None) => {
                let nb = &tree.nodes()[ib as usize];
                let cb = Vec3::from_array(*nb.ball.centre());
                let rb = sum_up(nb.ball.radius(), *radius);
                let reach = sum_up(a.reach, sum_up(cb.length(), rb));
                let g = gap_down((cb - ca).length() - ra - rb, a.delta, o.delta, reach);
                if g >= best {
                    continue;
                }
                let leaf_b = nb.left == NO_CHILD;
                match (na.leaf(), leaf_b) {
                    (Some(leaf), true) => {
                        stats.leaf_pairs += 1;
                        let tri = placed_corners(ta, leaf, a);
                        let points = node_points(tree, nb.start, nb.end);
                        let (gap, estimate) = triangle_points_gap(&tri, a.delta, points, ball);
                        best = best.min_nan(gap);
                        if (estimate <= cap_touch || estimate.is_nan())
                            && closest.is_none_or(|(d, _, _)| estimate < d)
                        {
                            let (on_a, on_b) = points_witnesses(&tri, points, *radius);
                            closest = Some((estimate, on_a, on_b));
                        }
                    }
                    // Split the larger ball (the link's when the cloud's
                    // node is a leaf).
                    (None, leaf_b) if leaf_b || ra >= rb => {
                        push_link_children(stack, ta, a, cb, na.left, na.right, ib);
                    }
                    _ => {
                        let nodes = tree.nodes();
                        let far = |k: u32| {
                            let n = &nodes[k as usize];
                            (Vec3::from_array(*n.ball.centre()) - ca).length() - n.ball.radius()
                        };
                        let (near, away) = if far(nb.left) <= far(nb.right) {
                            (nb.left, nb.right)
                        } else {
                            (nb.right, nb.left)
                        };
                        stack.push((ia, away));
                        stack.push((ia, near));
                    }
                }
            }
            // Not reached: a shape is a cloud exactly when `against_of` is `None`.
            _ => {}
        }
    }
    Near { gap: best, closest }
}

/// Pushes a link node's children, the one nearer `other` last (taken first).
fn push_link_children<T: Float>(
    stack: &mut Vec<(u32, u32)>,
    ta: &Hierarchy<T>,
    a: &LinkMotion<T>,
    other: Vec3<T>,
    left: u32,
    right: u32,
    ib: u32,
) {
    let far = |i: u32| {
        let b = &ta.nodes[i as usize].ball;
        (a.pose.transform_point(*b.centre()) - other).length() - b.radius()
    };
    let (near, away) = if far(left) <= far(right) {
        (left, right)
    } else {
        (right, left)
    };
    stack.push((away, ib));
    stack.push((near, ib));
}

/// The computed closest points of triangle `tri` and a convex shape or a
/// half-space (on the triangle first).
fn against_witnesses<T: Float>(against: &Against<'_, T>, tri: &[Vec3<T>; 3]) -> (Vec3<T>, Vec3<T>) {
    match *against {
        Against::Plane(m, pose, _) => {
            let (mut low, mut h) = (tri[0], T::INFINITY);
            for p in tri {
                let hp = (*p - pose.translation).dot(m);
                if hp < h {
                    (low, h) = (*p, hp);
                }
            }
            (low, low - m * h.max_nan(T::ZERO))
        }
        Against::Convex(shape, pose, _) => {
            let corners = tri.map(Vec3::to_array);
            let Ok(p) = ConvexPolytope::try_new(&corners, Pose::IDENTITY) else {
                return (tri[0], tri[0]);
            };
            let core = PlacedCore { shape, pose: &pose };
            let r = gjk_distance(&p, &core, &GjkParams::default());
            let (on_a, on_core) = (r.on_a.to_vec3(), r.on_b.to_vec3());
            let on_b = match (on_a - on_core).try_normalize() {
                Some(n) if !r.intersecting => on_core + n * shape.radius(),
                _ => on_core,
            };
            (on_a, on_b)
        }
    }
}

/// The computed closest points of triangle `tri` and the balls of radius
/// `radius` about `points` (on the triangle first).
fn points_witnesses<T: Float>(
    tri: &[Vec3<T>; 3],
    points: &[[T; 3]],
    radius: T,
) -> (Vec3<T>, Vec3<T>) {
    let mut best = (T::INFINITY, tri[0], tri[0]);
    for p in points {
        let p = Vec3::from_array(*p);
        let cp = point_triangle_vec(p, *tri);
        if cp.distance < best.0 {
            let on_b = match (cp.on_b - p).try_normalize() {
                Some(n) => p + n * radius.min_nan(cp.distance),
                None => p,
            };
            best = (cp.distance, cp.on_b, on_b);
        }
    }
    (best.1, best.2)
}
