//! Still bodies of a chain's surroundings given as shapes, not meshes:
//! convex primitives, half-spaces and point clouds (a depth camera's
//! points, each a ball of one radius). What a planner's scene is made of;
//! the edge queries ([`ChainScene::edge_is_free`](crate::chain::ChainScene::edge_is_free))
//! measure a link's balls and triangles against them exactly, without
//! meshing them (`proofs/13-chains.md`, Lemma 13.6).

use alloc::string::String;

use alloc::vec::Vec;

use crate::bvh::{VertexTree, NO_CHILD};
use crate::ca::{certified_gap_to_exact, support_error_up, PlacedCore};
use crate::chain::model::ChainError;
use crate::chain::proxy::{convex_proxy, Proxy};
use crate::geometry::closest::point_triangle_vec;
use crate::rounding::{gamma, gap_down, sum_up};
use crate::{gjk_distance, Convex, ConvexPolytope, Float, GjkParams, Pose, Vec3, VertexSet};

/// The balls of a point cloud's rake proxy (its tree's top nodes).
const CLOUD_BALLS: usize = 32;

/// What a [`ShapeObstacle`] is.
#[derive(Clone, Debug)]
pub(super) enum Geometry<T: 'static> {
    /// A convex primitive (ball, capsule, cuboid, cylinder, cone, rounded or
    /// not) placed by the obstacle's pose.
    Convex(Convex<'static, T>),
    /// The half-space `{x : m . (x - o) <= 0}` of the world unit normal `m`
    /// through the pose's origin `o`.
    HalfSpace(Vec3<T>),
    /// Balls of radius `radius` about the points (world coordinates), with
    /// the ball tree over the points.
    Points {
        tree: VertexTree<T>,
        radius: T,
        ball: Convex<'static, T>,
    },
}

/// A still obstacle given as a shape: a convex primitive placed by a pose,
/// a half-space, or a point cloud of balls.
///
/// ```
/// use motion_bound::chain::ShapeObstacle;
/// use motion_bound::{Convex, Pose, Vec3};
/// let table = ShapeObstacle::try_new("table", Convex::try_cuboid([0.5, 0.4, 0.02])?,
///     Pose::from_translation(Vec3::new(0.6, 0.0, 0.3)))?;
/// let floor = ShapeObstacle::try_half_space("floor", [0.0, 0.0, 1.0], [0.0, 0.0, -0.01])?;
/// let cloud = ShapeObstacle::try_points("camera", &[[0.5, 0.5, 0.5], [0.5, 0.52, 0.5]], 0.01)?;
/// assert_eq!((table.name(), floor.name(), cloud.name()), ("table", "floor", "camera"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug)]
pub struct ShapeObstacle<T: 'static> {
    name: String,
    pub(super) geometry: Geometry<T>,
    pub(super) pose: Pose<T>,
    /// An upper bound of the placement's rounding (taken as the shape's
    /// own: the pose's numbers are exact by convention, as for meshes).
    pub(super) delta: T,
    /// An upper bound of the rounding of its support's evaluation at its
    /// exact pose, along any computed unit direction (a convex shape's
    /// [`support_error_up`], a plane's [`plane_error_up`]; `0` for a cloud,
    /// whose balls take their own): what a slab gap to it subtracts.
    pub(super) support_err: T,
    /// What the rake's `f32` lanes test against (Lemma 13.12; `None`: the
    /// rake leaves it to the edge engine).
    pub(super) proxy: Option<Proxy>,
}

impl<T: Float> ShapeObstacle<T> {
    /// A convex primitive in its body frame placed in the world by `pose`.
    ///
    /// # Errors
    /// [`ChainError::InvalidParameter`] for a pose that is not finite or whose
    /// rotation has an entry beyond 2 (not a rotation), or for a convex hull
    /// (give a hull as a mesh [`Obstacle`](crate::chain::Obstacle)).
    pub fn try_new(
        name: impl Into<String>,
        shape: Convex<'static, T>,
        pose: Pose<T>,
    ) -> Result<Self, ChainError> {
        check_pose(&pose)?;
        if matches!(shape.kind(), crate::ConvexKind::Polytope { .. }) {
            return Err(ChainError::InvalidParameter(
                "a convex hull obstacle: give it as a mesh Obstacle",
            ));
        }
        let reach = sum_up(pose.translation.length(), shape.reach());
        let delta = gamma::<T>(8) * reach + T::from_u32(4) * T::ETA_NORMAL;
        Ok(Self {
            name: name.into(),
            proxy: convex_proxy(&shape, &pose, delta),
            support_err: support_error_up(&shape, &pose),
            geometry: Geometry::Convex(shape),
            pose,
            delta,
        })
    }

    /// The half-space below the plane through `point` with outward normal
    /// `normal` (world coordinates, any nonzero length): a floor, a wall.
    ///
    /// # Errors
    /// [`ChainError::Shape`] for a zero or non-finite normal or a non-finite
    /// point.
    pub fn try_half_space(
        name: impl Into<String>,
        normal: [T; 3],
        point: [T; 3],
    ) -> Result<Self, ChainError> {
        let m = crate::Direction::try_new(Vec3::from_array(normal))
            .map_err(ChainError::Shape)?
            .get();
        crate::error::check_components(point, crate::Quantity::Pose).map_err(ChainError::Shape)?;
        let pose = Pose::from_translation(Vec3::from_array(point));
        let delta = gamma::<T>(8) * pose.translation.length() + T::from_u32(4) * T::ETA_NORMAL;
        Ok(Self {
            name: name.into(),
            geometry: Geometry::HalfSpace(m),
            proxy: Proxy::plane(
                m.to_array().map(T::to_f64),
                point.map(T::to_f64),
                delta.to_f64(),
            ),
            delta,
            support_err: plane_error_up(pose.translation),
            pose,
        })
    }

    /// A point cloud: a ball of radius `radius` about each point (world
    /// coordinates), e.g. a depth camera's points with its noise as the
    /// radius. A ball tree over the points is built here (`O(N log N)`).
    ///
    /// # Errors
    /// [`ChainError::Shape`] for no points, a non-finite point, or a
    /// negative or non-finite radius.
    pub fn try_points(
        name: impl Into<String>,
        points: &[[T; 3]],
        radius: T,
    ) -> Result<Self, ChainError> {
        let set = VertexSet::try_new(points).map_err(ChainError::Shape)?;
        let ball = Convex::try_ball(radius).map_err(ChainError::Shape)?;
        let tree = VertexTree::try_new(&set).map_err(ChainError::Shape)?;
        let reach = points
            .iter()
            .fold(T::ZERO, |m, p| m.max_nan(Vec3::from_array(*p).norm_l1()));
        let delta = gamma::<T>(8) * sum_up(reach, radius) + T::from_u32(4) * T::ETA_NORMAL;
        // The rake's proxy: the tree's top nodes (their balls hold their
        // points), grown by the points' radius.
        let nodes = tree.nodes();
        let mut cut: Vec<usize> = alloc::vec![0];
        while cut.len() < CLOUD_BALLS {
            let widest = (0..cut.len())
                .filter(|&i| nodes[cut[i]].left != NO_CHILD)
                .max_by(|&i, &j| {
                    nodes[cut[i]]
                        .ball
                        .radius()
                        .to_f64()
                        .total_cmp(&nodes[cut[j]].ball.radius().to_f64())
                });
            let Some(i) = widest else { break };
            let n = &nodes[cut[i]];
            cut[i] = n.left as usize;
            cut.push(n.right as usize);
        }
        let balls: Vec<([f64; 3], f64)> = cut
            .iter()
            .map(|&i| {
                let b = &nodes[i].ball;
                (
                    b.centre().map(T::to_f64),
                    b.radius().to_f64() + radius.to_f64(),
                )
            })
            .collect();
        let proxy = Proxy::balls(&balls, delta.to_f64());
        Ok(Self {
            name: name.into(),
            geometry: Geometry::Points { tree, radius, ball },
            pose: Pose::IDENTITY,
            delta,
            support_err: T::ZERO,
            proxy,
        })
    }

    /// The obstacle's name.
    #[must_use]
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Its world pose (the identity for a point cloud; a half-space's
    /// translation is the point on its plane).
    #[must_use]
    pub fn pose(&self) -> Pose<T> {
        self.pose
    }

    /// The point cloud's points (reordered by its tree), if it is one.
    #[must_use]
    pub fn points(&self) -> Option<&[[T; 3]]> {
        match &self.geometry {
            Geometry::Points { tree, .. } => Some(tree.vertices()),
            _ => None,
        }
    }
}

/// An upper bound of the rounding of a half-space's least `x . n` along its
/// inward unit normal `n` computed as `fl(o . n)` from the point `o` on its
/// plane, with its share of the gap's subtraction: `5 u |o|_1`, rounded up,
/// and the underflow of three products (`proofs/13-chains.md`, Lemma 13.6).
fn plane_error_up<T: Float>(o: Vec3<T>) -> T {
    let e =
        T::from_u32(5) * sum_up(o.norm_l1(), T::ZERO) * T::UNIT_ROUNDOFF * (T::ONE + gamma::<T>(8))
            + T::from_u32(8) * T::ETA_NORMAL;
    if e.is_nan() {
        T::INFINITY
    } else {
        e
    }
}

fn check_pose<T: Float>(pose: &Pose<T>) -> Result<(), ChainError> {
    if !pose.is_finite()
        || pose.translation.max_abs() > T::MAX_INPUT
        || pose.rotation_max_abs() > T::TWO
    {
        return Err(ChainError::InvalidParameter("an obstacle's pose"));
    }
    Ok(())
}

/// What a link's ball or triangle is measured against: a convex shape (a
/// primitive, or one ball of a cloud) placed by a pose, or a half-space's
/// plane seen along its inward normal; each with its pose (exact by
/// convention) and the rounding of its support's evaluation
/// ([`ShapeObstacle`]'s `support_err`).
#[derive(Clone, Copy)]
pub(super) enum Against<'s, T: 'static> {
    Convex(&'s Convex<'static, T>, Pose<T>, T),
    Plane(Vec3<T>, Pose<T>, T),
}

impl<'s, T: Float> Against<'s, T> {
    /// The certified gap from the ball of world centre `c` and radius `r`
    /// (placed within `err` of its exact place) to the shape, along the
    /// direction from `c` to the shape's nearest core point (Lemma 13.6:
    /// a slab gap, so sound along any direction); `-inf` when `c` is in the
    /// core.
    pub(super) fn ball_gap(&self, c: Vec3<T>, r: T, err: T) -> T {
        match self.towards(c) {
            Some(n) => self.slab(c.dot(n) + r, sum_up(c.norm_l1(), r), err, n),
            None => -T::INFINITY,
        }
    }

    /// The certified slab gap from the triangle `tri` to the shape along
    /// the direction from `c` (a point near it) to the shape's nearest
    /// core point: cheaper than [`triangle_gap`](Self::triangle_gap) and
    /// often enough; `-inf` when there is no direction.
    pub(super) fn triangle_slab(&self, tri: &[Vec3<T>; 3], c: Vec3<T>, err: T) -> T {
        let Some(n) = self.towards(c) else {
            return -T::INFINITY;
        };
        let upper = tri.iter().map(|p| p.dot(n)).fold(-T::INFINITY, T::max_nan);
        let weight = tri.iter().fold(T::ZERO, |w, p| w.max_nan(p.norm_l1()));
        self.slab(upper, weight, err, n)
    }

    /// The unit direction from `c` to the shape's nearest core point (the
    /// inward normal for a plane), or `None` when `c` is in the core.
    pub(super) fn towards(&self, c: Vec3<T>) -> Option<Vec3<T>> {
        let n = match *self {
            Against::Plane(m, ..) => -m,
            Against::Convex(shape, pose, _) => {
                let local = pose.inverse_transform_vector(c - pose.translation);
                let near = match shape.core_closest_point(local) {
                    Some(q) => pose.transform_vector(q) + pose.translation,
                    None => {
                        let core = PlacedCore { shape, pose: &pose };
                        let point = [c.to_array()];
                        let p = ConvexPolytope::try_new(&point, Pose::IDENTITY).ok()?;
                        gjk_distance(&p, &core, &GjkParams::default())
                            .on_b
                            .to_vec3()
                    }
                };
                (near - c).try_normalize()?
            }
        };
        Some(n)
    }

    /// For the triangle `tri` (world corners, within `err` of their exact
    /// places): its certified gap to the shape and the estimated distance
    /// (GJK's, or the plane's height; what a contact is declared on).
    pub(super) fn triangle_gap(&self, tri: &[Vec3<T>; 3], err: T) -> (T, T) {
        let (n, estimate) = match *self {
            Against::Plane(m, pose, _) => {
                let h = tri
                    .iter()
                    .map(|p| (*p - pose.translation).dot(m))
                    .fold(T::INFINITY, T::min_nan);
                (-m, h)
            }
            Against::Convex(shape, pose, _) => {
                let corners = tri.map(Vec3::to_array);
                let Ok(p) = ConvexPolytope::try_new(&corners, Pose::IDENTITY) else {
                    return (-T::INFINITY, -T::INFINITY);
                };
                let core = PlacedCore { shape, pose: &pose };
                let r = gjk_distance(&p, &core, &GjkParams::default());
                let estimate = r.distance - shape.radius();
                match r.direction {
                    Some(d) if !r.intersecting => (d.get(), estimate),
                    _ => return (-T::INFINITY, estimate.min_nan(T::ZERO)),
                }
            }
        };
        let upper = tri.iter().map(|p| p.dot(n)).fold(-T::INFINITY, T::max_nan);
        let weight = tri.iter().fold(T::ZERO, |w, p| w.max_nan(p.norm_l1()));
        (self.slab(upper, sum_up(weight, T::ZERO), err, n), estimate)
    }

    /// The certified slab gap along `n` from a body whose computed largest
    /// `x . n` is `upper` (weight `weight`, placement error `err`).
    pub(super) fn slab(&self, upper: T, weight: T, err: T, n: Vec3<T>) -> T {
        match *self {
            Against::Convex(shape, pose, e) => {
                certified_gap_to_exact(upper, weight, err, (shape, &pose, e), n)
            }
            Against::Plane(_, pose, e) => {
                // The half-space's least point along the inward normal `n`
                // is its plane's: the point at its origin (Lemma 12.3).
                let lower = pose.translation.dot(n);
                gap_down(lower - upper, err, e, weight)
            }
        }
    }
}

/// The certified gap between a link's triangle `tri` (within `err` of its
/// exact place) and each cloud point's ball in `points`, with the least
/// estimated distance: what a leaf of a link meets at a leaf of a cloud.
pub(super) fn triangle_points_gap<T: Float>(
    tri: &[Vec3<T>; 3],
    err: T,
    points: &[[T; 3]],
    ball: &Convex<'static, T>,
) -> (T, T) {
    let mut gap = T::INFINITY;
    let mut estimate = T::INFINITY;
    for p in points {
        let p = Vec3::from_array(*p);
        let cp = point_triangle_vec(p, *tri);
        estimate = estimate.min_nan(cp.distance - ball.radius());
        let at = Pose::from_translation(p);
        let against = Against::Convex(ball, at, support_error_up(ball, &at));
        let g = match (p - cp.on_b).try_normalize() {
            Some(n) => {
                let upper = tri.iter().map(|q| q.dot(n)).fold(-T::INFINITY, T::max_nan);
                let weight = tri.iter().fold(T::ZERO, |w, q| w.max_nan(q.norm_l1()));
                against.slab(upper, weight, err, n)
            }
            None => -T::INFINITY,
        };
        gap = gap.min_nan(g);
    }
    (gap, estimate)
}

/// The points of a cloud in a tree node's range.
pub(super) fn node_points<T: Float>(tree: &VertexTree<T>, start: u32, end: u32) -> &[[T; 3]] {
    &tree.vertices()[start as usize..end as usize]
}
