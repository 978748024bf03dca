//! Parry's shapes, poses and motions in `motion-bound`'s terms: the vector
//! and pose conversions, [`rigid_motion`], and [`Body`] (a shape converted
//! once: a convex shape, a half-space, a mesh with its tree, a compound).

use motion_bound::ca::{Hull, OwnedMesh, OwnedPart, OwnedShape, Shape as Ours};
use motion_bound::{
    Convex, HalfSpace as OurHalfSpace, InputError, Isometry, MeshError, Point3, RigidMotion,
    Rotation, TimeInterval, TriMesh, Vec3,
};

use super::error::CastError;
use super::parry;
use super::swept::Swept;
use parry::math::{Pose, Real, Vector};
use parry::query::NonlinearRigidMotion;
use parry::shape::{Shape, TriMeshFlags, TypedShape};

pub(super) fn vec3(v: Vector) -> Vec3<Real> {
    Vec3::new(v.x, v.y, v.z)
}

pub(super) fn vector(v: Vec3<Real>) -> Vector {
    Vector::new(v.x, v.y, v.z)
}

/// Parry's pose as `motion-bound`'s isometry (the quaternion normalised).
///
/// # Errors
/// [`InputError`] for a NaN, infinite or zero quaternion, or a translation
/// out of range.
pub fn isometry(pose: &Pose) -> Result<Isometry<Real>, InputError> {
    let q = pose.rotation;
    Isometry::try_new(
        Rotation::try_from_quaternion(q.w, q.x, q.y, q.z)?,
        vec3(pose.translation),
    )
}

/// Parry's motion over `[start_time, end_time]` as `motion-bound`'s: the
/// point `x` of the body's frame is at
/// `c + linvel t + R(angvel t) (start x - c)` with `c = start local_center`
/// (parry's `NonlinearRigidMotion::position_at_time`), which is
/// [`RigidMotion::try_about_centre`] with the centre `c`, the local centre
/// `local_center` and the start orientation, kept on parry's epoch `t = 0`.
///
/// # Errors
/// [`CastError::Interval`] for a NaN or infinite time, [`CastError::Input`]
/// for an invalid pose, velocity or local centre, or for
/// `end_time <= start_time`.
pub fn rigid_motion(
    motion: &NonlinearRigidMotion,
    start_time: Real,
    end_time: Real,
) -> Result<RigidMotion<Real>, CastError> {
    if !start_time.is_finite() || !end_time.is_finite() {
        return Err(CastError::Interval);
    }
    let start = isometry(&motion.start)?;
    let c = motion.start * motion.local_center;
    let m = RigidMotion::try_about_centre(
        Point3::new(c.x, c.y, c.z),
        vec3(motion.local_center),
        start.rotation(),
        vec3(motion.linvel),
        vec3(motion.angvel),
        1.0,
    )?;
    Ok(m.with_interval(TimeInterval::try_new(start_time, end_time)?))
}

/// A convex shape with its own pose in parry's shape frame, when parry's
/// shape is not centred as ours is (a capsule on any segment).
type Posed = (Convex<'static, Real>, Option<Pose>);

/// A convex shape's core and radius, with its own pose in the shape's frame
/// when parry's shape is not centred as ours is (a capsule on any segment).
fn convex(shape: &dyn Shape) -> Result<Option<Posed>, CastError> {
    let c = match shape.as_typed_shape() {
        TypedShape::Ball(b) => Convex::try_ball(b.radius)?,
        TypedShape::Cuboid(c) => Convex::try_cuboid(vec3(c.half_extents).to_array())?,
        TypedShape::Capsule(c) => return capsule(c.segment.a, c.segment.b, c.radius).map(Some),
        TypedShape::Cylinder(c) => Convex::try_cylinder(c.half_height, c.radius)?,
        TypedShape::Cone(c) => Convex::try_cone(c.half_height, c.radius)?,
        TypedShape::RoundCuboid(r) => {
            Convex::try_cuboid(vec3(r.inner_shape.half_extents).to_array())?
                .try_rounded(r.border_radius)?
        }
        TypedShape::RoundCylinder(r) => {
            Convex::try_cylinder(r.inner_shape.half_height, r.inner_shape.radius)?
                .try_rounded(r.border_radius)?
        }
        TypedShape::RoundCone(r) => {
            Convex::try_cone(r.inner_shape.half_height, r.inner_shape.radius)?
                .try_rounded(r.border_radius)?
        }
        _ => return Ok(None),
    };
    Ok(Some((c, None)))
}

/// A capsule on the segment `[a, b]`: ours along `y`, centred, placed by
/// the rotation taking `y` to `b - a` and the translation to the midpoint.
fn capsule(a: Vector, b: Vector, radius: Real) -> Result<Posed, CastError> {
    let d = b - a;
    let half = d.length() * 0.5;
    let mid = (a + b) * 0.5;
    let c = Convex::try_capsule(half, radius)?;
    if a.x == 0.0 && a.z == 0.0 && b.x == 0.0 && b.z == 0.0 && a.y == -b.y && b.y >= 0.0 {
        return Ok((c, None));
    }
    let rotation = if half > 0.0 {
        parry::math::Rotation::from_rotation_arc(Vector::Y, d / (half * 2.0))
    } else {
        parry::math::Rotation::IDENTITY
    };
    Ok((c, Some(Pose::from_parts(mid, rotation))))
}

/// A polytope's vertices (a convex polyhedron, a triangle, a segment) and
/// its border radius.
fn polytope(shape: &dyn Shape) -> Option<(Vec<[Real; 3]>, Real)> {
    let points = |p: &[Vector]| p.iter().map(|v| vec3(*v).to_array()).collect::<Vec<_>>();
    match shape.as_typed_shape() {
        TypedShape::ConvexPolyhedron(p) => Some((points(p.points()), 0.0)),
        TypedShape::RoundConvexPolyhedron(r) => {
            Some((points(r.inner_shape.points()), r.border_radius))
        }
        TypedShape::Triangle(t) => Some((points(&[t.a, t.b, t.c]), 0.0)),
        TypedShape::RoundTriangle(r) => {
            let t = &r.inner_shape;
            Some((points(&[t.a, t.b, t.c]), r.border_radius))
        }
        TypedShape::Segment(s) => Some((points(&[s.a, s.b]), 0.0)),
        _ => None,
    }
}

fn kind_name(shape: &dyn Shape) -> &'static str {
    match shape.as_typed_shape() {
        TypedShape::HeightField(_) => "HeightField",
        TypedShape::Polyline(_) => "Polyline",
        TypedShape::Voxels(_) => "Voxels",
        TypedShape::Compound(_) => "Compound",
        TypedShape::HalfSpace(_) => "HalfSpace",
        TypedShape::TriMesh(_) => "TriMesh",
        _ => "Custom",
    }
}

/// A tree of parry's mesh, its vertices mapped by `pose` (a compound's
/// part) when given. A mesh flagged [`TriMeshFlags::ORIENTED`] (parry's
/// solid mesh) is solid (`TriMesh::try_solid`): a body starting inside it is
/// in contact; one that is not closed and wound outward is
/// [`CastError::NotSolid`].
fn tree(shape: &dyn Shape, pose: Option<&Pose>) -> Result<Option<OwnedMesh<Real>>, CastError> {
    let TypedShape::TriMesh(m) = shape.as_typed_shape() else {
        return Ok(None);
    };
    let vertices: Vec<[Real; 3]> = m
        .vertices()
        .iter()
        .map(|v| vec3(pose.map_or(*v, |p| *p * *v)).to_array())
        .collect();
    let mesh = TriMesh::try_new(vertices, m.indices().to_vec()).map_err(|e| match e {
        MeshError::Vertex(e) => CastError::Input(e),
        MeshError::IndexOutOfRange {
            triangle, index, ..
        } => CastError::Input(InputError::TriangleIndexOutOfRange { triangle, index }),
        _ => CastError::Input(InputError::NoTriangles),
    })?;
    let mesh = if m.flags().contains(TriMeshFlags::ORIENTED) {
        mesh.try_solid().map_err(|e| CastError::NotSolid {
            closed: !matches!(e, MeshError::NotClosed { .. }),
        })?
    } else {
        mesh
    };
    Ok(Some(OwnedMesh::try_from_mesh(mesh)?))
}

/// The part of a body that `shape` is, at `pose` in the body's frame
/// (`None`: the body's own frame).
fn part(shape: &dyn Shape, pose: Option<&Pose>) -> Result<OwnedPart<Real>, CastError> {
    if let Some((c, own)) = convex(shape)? {
        let place = match (pose, own) {
            (None, None) => return Ok(OwnedPart::Convex(c)),
            (Some(p), None) => *p,
            (None, Some(p)) => p,
            (Some(p), Some(o)) => *p * o,
        };
        return Ok(OwnedPart::Convex(c.try_placed(isometry(&place)?)?));
    }
    if let Some((vertices, radius)) = polytope(shape) {
        let place = pose.map(isometry).transpose()?;
        // Checked once here, so that a query never meets a bad vertex.
        let hull = Hull::try_new(vertices, radius)?;
        hull.convex(place)?;
        return Ok(OwnedPart::Hull(hull, place.unwrap_or(Isometry::IDENTITY)));
    }
    if let Some(m) = tree(shape, pose)? {
        return Ok(OwnedPart::Mesh(m));
    }
    Err(CastError::Unsupported(kind_name(shape)))
}

/// A parry shape converted once into `motion-bound`'s terms: a convex
/// shape (core and radius), a half-space, a mesh with its tree, or a
/// compound of these. Building one is the costly part of a first query on a
/// mesh (its tree); a [`ShapeCache`] keeps one per shared shape.
///
/// [`ShapeCache`]: super::ShapeCache
#[derive(Debug)]
pub struct Body {
    shape: OwnedShape<Real>,
}

impl Body {
    /// The body of parry's shape (of the inner shape of a [`Swept`]).
    ///
    /// # Errors
    /// [`CastError::Unsupported`] for heightfields, polylines, voxels,
    /// custom shapes, and compounds holding a compound or a half-space;
    /// [`CastError::Input`] for an invalid shape (a NaN or out-of-range
    /// vertex, an empty mesh, a negative radius).
    pub fn try_new(shape: &dyn Shape) -> Result<Self, CastError> {
        let shape = Swept::see_through(shape);
        let shape = match shape.as_typed_shape() {
            TypedShape::HalfSpace(h) => {
                OwnedShape::HalfSpace(OurHalfSpace::try_new(vec3(h.normal))?)
            }
            TypedShape::Compound(c) => {
                let mut parts = Vec::with_capacity(c.shapes().len());
                for (pose, p) in c.shapes() {
                    let p = Swept::see_through(p.as_ref());
                    match p.as_typed_shape() {
                        TypedShape::Compound(_) => {
                            return Err(CastError::Unsupported("a compound within a compound"))
                        }
                        TypedShape::HalfSpace(_) => {
                            return Err(CastError::Unsupported("a half-space within a compound"))
                        }
                        _ => {}
                    }
                    parts.push(part(p, Some(pose))?);
                }
                OwnedShape::try_compound_of(parts)?
            }
            _ => match part(shape, None)? {
                OwnedPart::Convex(c) => OwnedShape::Convex(c),
                OwnedPart::Hull(h, _) => OwnedShape::Hull(h), // at the identity
                OwnedPart::Mesh(m) => OwnedShape::Mesh(m),
                _ => return Err(CastError::Unsupported(kind_name(shape))),
            },
        };
        Ok(Self { shape })
    }

    /// Whether this body holds a mesh tree (the conversions worth caching).
    #[must_use]
    pub fn has_tree(&self) -> bool {
        match &self.shape {
            OwnedShape::Mesh(_) => true,
            OwnedShape::Compound(c) => c.parts().iter().any(|p| matches!(p, OwnedPart::Mesh(_))),
            _ => false,
        }
    }

    /// Calls `f` with this body as a [`motion_bound::ca::Shape`].
    ///
    /// # Errors
    /// None for a body made by [`try_new`](Self::try_new) (its vertices
    /// were checked then); the `Result` carries `motion-bound`'s checks.
    pub fn with_shape<R>(&self, f: impl FnOnce(Ours<'_, Real>) -> R) -> Result<R, CastError> {
        Ok(f(self.shape.prepare()?.shape()))
    }
}

/// A half-space body whose motion has a start orientation and no angular
/// velocity, as the same plane in the world's axes: its normal rotated by
/// the start orientation, its motion the translation of its origin
/// (parry's `position_at_time` with `angvel = 0` is the start pose moved by
/// `linvel t`). `None` for any other body or motion.
pub(super) fn in_world_axes(
    body: &Body,
    motion: &NonlinearRigidMotion,
) -> Option<(Body, NonlinearRigidMotion)> {
    let OwnedShape::HalfSpace(h) = &body.shape else {
        return None;
    };
    if motion.angvel != Vector::ZERO || motion.start.rotation == parry::math::Rotation::IDENTITY {
        return None;
    }
    let normal = motion.start.rotation * vector(h.normal().get());
    let h = OurHalfSpace::try_new(vec3(normal)).ok()?;
    Some((
        Body {
            shape: OwnedShape::HalfSpace(h),
        },
        NonlinearRigidMotion::new(
            Pose::from_translation(motion.start.translation),
            Vector::ZERO,
            motion.linvel,
            Vector::ZERO,
        ),
    ))
}
