//! [`Swept`]: a collider shape wrapper that is its inner shape in every
//! respect but its kind, so that rapier hands its CCD pairs to the query
//! dispatcher; its forwarding impls (`RayCast`, `PointQuery`, `Shape`).

use std::sync::Arc;

use super::parry;
use parry::bounding_volume::{Aabb, BoundingSphere};
use parry::mass_properties::MassProperties;
use parry::math::{Pose, Real, Vector};
use parry::query::{PointProjection, PointQuery, Ray, RayCast, RayIntersection};
use parry::shape::{
    CompositeShape, FeatureId, PolygonalFeatureMap, Shape, ShapeType, SharedShape, SubShapeId,
    SupportMap, TypedShape,
};

/// A collider shape whose continuous collision detection rapier hands to
/// its narrow phase's query dispatcher: with a [`CertifiedDispatcher`],
/// every CCD pair with this collider is answered by the certified cast.
///
/// Not needed to certify plain shapes: `rapier::CertifiedPass` (feature
/// `rapier`) casts every CCD body's actual motion over the step, whatever
/// its shapes, with nothing wrapped; that is the setup the README gives.
/// `Swept` is for when the pass is not run (its cost is a scan of every
/// collider per CCD body, for a few fast bodies, not thousands): it makes
/// rapier's own CCD, within rapier's broad phase, ask the dispatcher for
/// the wrapped collider's casts.
///
/// Rapier's CCD sweeps most pairs itself (balls, cuboids, capsules, convex
/// polyhedra, compounds of these) and calls the dispatcher's
/// `cast_shapes_nonlinear` only for pairs its own sweeps do not take
/// (cylinders, cones, half-spaces, custom shapes); it never sweeps a moving
/// triangle mesh at all (a fast mesh body relies on speculative contacts,
/// and can pass through a thin wall). `Swept` is the inner shape in every
/// respect (its bounding volumes, mass properties, ray and point queries,
/// support map, composite structure, all delegated) except its kind: it
/// says [`ShapeType::Custom`] and [`TypedShape::Custom`], which rapier's
/// sweeps do not take, so they go to the dispatcher.
///
/// Its kind cannot be the inner shape's, soundly:
/// - rapier chooses between its own sweep and the dispatcher by
///   [`as_typed_shape`](Shape::as_typed_shape): a `Swept` answering the
///   inner kind there would be swept by rapier itself, that is, do nothing;
/// - `as_ball()`, `as_cuboid()` and the other `as_*()`, and
///   `as_shape::<T>()`, are parry's downcasts of the concrete type, not
///   methods a shape implements: on a `Swept` they answer `None`;
/// - parry's own dispatcher matches on [`shape_type`](Shape::shape_type)
///   and then unwraps the matching `as_*()` (a height field's, for one): a
///   `shape_type()` saying the inner kind while `as_*()` says `None` would
///   make it panic.
///
/// So a collider wrapped in `Swept` says `Custom` to whatever inspects
/// shapes (a debug renderer, your own `match` on the kind): give it
/// [`Swept::see_through`], which answers every one of these as the inner
/// shape does.
///
/// ```
/// use motion_bound_parry::{CertifiedDispatcher, Swept};
/// use parry3d_f64::shape::{Ball, SharedShape};
/// use rapier3d_f64::prelude::{ColliderBuilder, NarrowPhase};
/// let (vertices, triangles) = Ball::new(0.3).to_trimesh(12, 12);
/// let mesh = SharedShape::trimesh(vertices, triangles)?;
/// let collider = ColliderBuilder::new(Swept::shared(mesh)).build();
/// let narrow_phase = NarrowPhase::with_query_dispatcher(CertifiedDispatcher::new());
/// # let _ = (collider, narrow_phase);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// Pitfalls:
/// - Only with a dispatcher that sees through it, as [`CertifiedDispatcher`]
///   does in every query (contacts, distances, casts). Parry's own
///   dispatcher and its free functions (`parry::query::contact` and the
///   like) do not know it: given a `Swept`, they answer `Unsupported`, and
///   rapier then makes no contact at all for the pair. Strip it with
///   [`Swept::see_through`] before calling them yourself.
/// - Wrap a collider's top-level shape only, never a part of a compound
///   (parry's compound queries would meet it).
/// - Rapier's own sweeps are no longer used for the collider, so a pair
///   the certified cast does not take (a heightfield, a polyline, voxels)
///   is handed to parry's `cast_shapes_nonlinear` (counted in
///   [`DispatchStats::handed_to_parry`]).
/// - What rapier does with a time of impact is its own: it ignores a hit at
///   fraction `0` (shapes already touching), and it moves bodies along its
///   own interpolation, so a body can still end a step in contact late; and
///   rapier casts nothing between two bullets (two CCD-enabled dynamic
///   bodies), wrapped or not.
/// - [`ccd_thickness`](Shape::ccd_thickness) is the inner shape's, except
///   for shapes whose own is zero (meshes, compounds holding one): see
///   [`Swept::ccd_thickness_of`].
///
/// [`CertifiedDispatcher`]: super::CertifiedDispatcher
/// [`DispatchStats::handed_to_parry`]: super::DispatchStats::handed_to_parry
#[derive(Clone, Debug)]
pub struct Swept(pub SharedShape);

impl Swept {
    /// `shape` wrapped, as a shared shape for a collider (`shape` itself
    /// when it is already a `Swept`).
    #[must_use]
    pub fn shared(shape: SharedShape) -> SharedShape {
        if shape.as_shape::<Self>().is_some() {
            return shape;
        }
        SharedShape(Arc::new(Self(shape)))
    }

    /// The inner shape.
    #[must_use]
    pub fn inner(&self) -> &SharedShape {
        &self.0
    }

    /// `shape` with any `Swept` layers removed (`shape` itself when it is
    /// not one): what parry's own queries take.
    #[must_use]
    pub fn see_through(shape: &dyn Shape) -> &dyn Shape {
        let mut s = shape;
        while let Some(w) = s.as_shape::<Self>() {
            s = w.0.as_ref();
        }
        s
    }

    /// `shape` with any `Swept` layers removed, as a shared shape.
    #[must_use]
    pub fn see_through_shared(shape: &SharedShape) -> &SharedShape {
        let mut s = shape;
        while let Some(w) = s.as_shape::<Self>() {
            s = &w.0;
        }
        s
    }

    /// The CCD thickness a `Swept` reports for `shape`: rapier counts a body
    /// as fast (and runs its CCD) when a point of it may move more than half
    /// its colliders' smallest thickness in a step.
    ///
    /// - The shape's own [`ccd_thickness`](Shape::ccd_thickness) when it is
    ///   positive (every convex shape).
    /// - Else (a triangle mesh, a compound holding one: parry says `0`, which
    ///   would make the body fast at every step, each step a cast against
    ///   every neighbour of its swept box): the smallest half extent of its
    ///   local bounding box, the rule parry applies to a convex polyhedron,
    ///   so that a mesh body is fast exactly when its hull would be; at
    ///   least `1/20` of its bounding sphere's radius, so that a flat mesh (a
    ///   zero extent) is fast when it moves more than `1/40` of its size.
    ///
    /// Below that speed, rapier's speculative contacts are what keep the
    /// body out of others, as for any shape.
    #[must_use]
    pub fn ccd_thickness_of(shape: &dyn Shape) -> Real {
        let own = shape.ccd_thickness();
        if own > 0.0 {
            return own;
        }
        let half = shape.compute_local_aabb().half_extents().min_element();
        let radius = shape.compute_local_bounding_sphere().radius();
        half.max(radius / 20.0)
    }
}

impl RayCast for Swept {
    fn cast_local_ray(&self, ray: &Ray, max_time_of_impact: Real, solid: bool) -> Option<Real> {
        self.0.cast_local_ray(ray, max_time_of_impact, solid)
    }

    fn cast_local_ray_and_get_normal(
        &self,
        ray: &Ray,
        max_time_of_impact: Real,
        solid: bool,
    ) -> Option<RayIntersection> {
        self.0
            .cast_local_ray_and_get_normal(ray, max_time_of_impact, solid)
    }

    fn intersects_local_ray(&self, ray: &Ray, max_time_of_impact: Real) -> bool {
        self.0.intersects_local_ray(ray, max_time_of_impact)
    }

    fn cast_ray(&self, m: &Pose, ray: &Ray, max_time_of_impact: Real, solid: bool) -> Option<Real> {
        self.0.cast_ray(m, ray, max_time_of_impact, solid)
    }

    fn cast_ray_and_get_normal(
        &self,
        m: &Pose,
        ray: &Ray,
        max_time_of_impact: Real,
        solid: bool,
    ) -> Option<RayIntersection> {
        self.0
            .cast_ray_and_get_normal(m, ray, max_time_of_impact, solid)
    }

    fn intersects_ray(&self, m: &Pose, ray: &Ray, max_time_of_impact: Real) -> bool {
        self.0.intersects_ray(m, ray, max_time_of_impact)
    }
}

impl PointQuery for Swept {
    fn project_local_point_with_max_dist(
        &self,
        pt: Vector,
        solid: bool,
        max_dist: Real,
    ) -> Option<PointProjection> {
        self.0
            .project_local_point_with_max_dist(pt, solid, max_dist)
    }

    fn project_point_with_max_dist(
        &self,
        m: &Pose,
        pt: Vector,
        solid: bool,
        max_dist: Real,
    ) -> Option<PointProjection> {
        self.0.project_point_with_max_dist(m, pt, solid, max_dist)
    }

    fn project_local_point(&self, pt: Vector, solid: bool) -> PointProjection {
        self.0.project_local_point(pt, solid)
    }

    fn project_local_point_and_get_feature(&self, pt: Vector) -> (PointProjection, FeatureId) {
        self.0.project_local_point_and_get_feature(pt)
    }

    fn distance_to_local_point(&self, pt: Vector, solid: bool) -> Real {
        self.0.distance_to_local_point(pt, solid)
    }

    fn contains_local_point(&self, pt: Vector) -> bool {
        self.0.contains_local_point(pt)
    }

    fn project_point(&self, m: &Pose, pt: Vector, solid: bool) -> PointProjection {
        self.0.project_point(m, pt, solid)
    }

    fn distance_to_point(&self, m: &Pose, pt: Vector, solid: bool) -> Real {
        self.0.distance_to_point(m, pt, solid)
    }

    fn project_point_and_get_feature(&self, m: &Pose, pt: Vector) -> (PointProjection, FeatureId) {
        self.0.project_point_and_get_feature(m, pt)
    }

    fn contains_point(&self, m: &Pose, pt: Vector) -> bool {
        self.0.contains_point(m, pt)
    }
}

impl Shape for Swept {
    fn compute_local_aabb(&self) -> Aabb {
        self.0.compute_local_aabb()
    }

    fn compute_local_bounding_sphere(&self) -> BoundingSphere {
        self.0.compute_local_bounding_sphere()
    }

    fn clone_dyn(&self) -> Box<dyn Shape> {
        Box::new(self.clone())
    }

    fn scale_dyn(&self, scale: Vector, num_subdivisions: u32) -> Option<Box<dyn Shape>> {
        let scaled = self.0.scale_dyn(scale, num_subdivisions)?;
        Some(Box::new(Self(SharedShape(Arc::from(scaled)))))
    }

    fn compute_aabb(&self, position: &Pose) -> Aabb {
        self.0.compute_aabb(position)
    }

    fn compute_bounding_sphere(&self, position: &Pose) -> BoundingSphere {
        self.0.compute_bounding_sphere(position)
    }

    fn mass_properties(&self, density: Real) -> MassProperties {
        self.0.mass_properties(density)
    }

    fn shape_type(&self) -> ShapeType {
        ShapeType::Custom
    }

    fn as_typed_shape(&self) -> TypedShape<'_> {
        TypedShape::Custom(self)
    }

    fn ccd_thickness(&self) -> Real {
        Self::ccd_thickness_of(self.0.as_ref())
    }

    fn ccd_angular_thickness(&self) -> Real {
        self.0.ccd_angular_thickness()
    }

    fn is_convex(&self) -> bool {
        self.0.is_convex()
    }

    fn as_support_map(&self) -> Option<&dyn SupportMap> {
        self.0.as_support_map()
    }

    fn as_composite_shape(&self) -> Option<&(dyn CompositeShape + Sync)> {
        self.0.as_composite_shape()
    }

    fn as_polygonal_feature_map(&self) -> Option<(&dyn PolygonalFeatureMap, Real)> {
        self.0.as_polygonal_feature_map()
    }

    fn feature_normal_at_point(
        &self,
        subshape: SubShapeId,
        feature: FeatureId,
        point: Vector,
    ) -> Option<Vector> {
        self.0.feature_normal_at_point(subshape, feature, point)
    }

    fn compute_swept_aabb(&self, start_pos: &Pose, end_pos: &Pose) -> Aabb {
        self.0.compute_swept_aabb(start_pos, end_pos)
    }
}
