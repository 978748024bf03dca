// The adapter, compiled once per precision: `src/f64.rs` and `src/f32.rs`
// each bring their parry (`parry3d-f64` or `parry3d`) into scope as `parry`
// and include this file as their module `adapter`.

use std::collections::HashMap;
use std::fmt;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex, PoisonError, Weak};

use motion_bound::ca::{
    time_of_impact, AnyPair, CaError, CaOutcome, CaParams, CaReport, Compound, ContactCriterion,
    MeshWorkspace, Part, Shape as Ours,
};
use motion_bound::{
    BallTree, Convex, HalfSpace as OurHalfSpace, InputError, Isometry, Point3, RigidMotion,
    Rotation, TimeInterval, Vec3, VertexSet,
};

use super::parry;
use parry::bounding_volume::{Aabb, BoundingSphere};
use parry::mass_properties::MassProperties;
use parry::math::{Pose, Real, Vector};
use parry::query::{
    ClosestPoints, Contact, DefaultQueryDispatcher, NonlinearRigidMotion, PointProjection,
    PointQuery, QueryDispatcher, Ray, RayCast, RayIntersection, ShapeCastHit, ShapeCastStatus,
    ShapeDistance, ShapeIntersection, Unsupported,
};
use parry::shape::{
    CompositeShape, FeatureId, PolygonalFeatureMap, Shape, ShapeType, SharedShape, SubShapeId,
    SupportMap, TypedShape,
};

/// Why a query could not be answered by the certified cast.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum CastError {
    /// A shape kind this adapter does not take (named as parry names it:
    /// `"HeightField"`, `"Polyline"`, `"Voxels"`, `"Custom"`, a compound
    /// within a compound, a half-space within a compound), or a pair it
    /// cannot step (two half-spaces, a turning half-space).
    Unsupported(&'static str),
    /// A shape or a motion with an invalid quantity (NaN, infinite, beyond
    /// `motion-bound`'s input range, a negative radius, an empty mesh).
    Input(InputError),
    /// The conservative advancement refused the pair or its parameters.
    Ca(CaError),
    /// A NaN or infinite `start_time` or `end_time`.
    Interval,
}

impl fmt::Display for CastError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Unsupported(what) => write!(f, "unsupported by the certified cast: {what}"),
            Self::Input(e) => write!(f, "invalid shape or motion: {e}"),
            Self::Ca(e) => write!(f, "conservative advancement: {e}"),
            Self::Interval => f.write_str("start_time and end_time must be finite"),
        }
    }
}

impl std::error::Error for CastError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Self::Input(e) => Some(e),
            Self::Ca(e) => Some(e),
            _ => None,
        }
    }
}

impl From<InputError> for CastError {
    fn from(e: InputError) -> Self {
        Self::Input(e)
    }
}

impl From<CaError> for CastError {
    fn from(e: CaError) -> Self {
        match e {
            CaError::Unsupported => Self::Unsupported("two half-spaces"),
            CaError::TurnedHalfSpace => Self::Unsupported("a half-space that turns"),
            other => Self::Ca(other),
        }
    }
}

fn vec3(v: Vector) -> Vec3<Real> {
    Vec3::new(v.x, v.y, v.z)
}

fn vector(v: Vec3<Real>) -> Vector {
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
/// part) when given.
fn tree(shape: &dyn Shape, pose: Option<&Pose>) -> Result<Option<BallTree<Real>>, CastError> {
    let TypedShape::TriMesh(m) = shape.as_typed_shape() else {
        return Ok(None);
    };
    let vertices: Vec<[Real; 3]> = m
        .vertices()
        .iter()
        .map(|v| vec3(pose.map_or(*v, |p| *p * *v)).to_array())
        .collect();
    Ok(Some(BallTree::try_new(&vertices, m.indices())?))
}

/// One part of a converted body.
#[derive(Debug)]
enum Piece {
    Convex(Convex<'static, Real>),
    Polytope {
        vertices: Vec<[Real; 3]>,
        radius: Real,
        place: Option<Isometry<Real>>,
    },
    Mesh(BallTree<Real>),
}

impl Piece {
    /// The piece of `shape` at `pose` in its body's frame (`None`: the
    /// body's own frame).
    fn new(shape: &dyn Shape, pose: Option<&Pose>) -> Result<Self, CastError> {
        if let Some((c, own)) = convex(shape)? {
            let place = match (pose, own) {
                (None, None) => return Ok(Self::Convex(c)),
                (Some(p), None) => *p,
                (None, Some(p)) => p,
                (Some(p), Some(o)) => *p * o,
            };
            return Ok(Self::Convex(c.try_placed(isometry(&place)?)?));
        }
        if let Some((vertices, radius)) = polytope(shape) {
            let place = pose.map(isometry).transpose()?;
            let piece = Self::Polytope {
                vertices,
                radius,
                place,
            };
            // Checked once here, so that a query never meets a bad vertex.
            piece.convex()?;
            return Ok(piece);
        }
        if let Some(t) = tree(shape, pose)? {
            return Ok(Self::Mesh(t));
        }
        Err(CastError::Unsupported(kind_name(shape)))
    }

    fn convex(&self) -> Result<Option<Convex<'_, Real>>, InputError> {
        match self {
            Self::Convex(c) => Ok(Some(*c)),
            Self::Polytope {
                vertices,
                radius,
                place,
            } => {
                let mut c = Convex::polytope(VertexSet::try_new(vertices)?);
                if *radius != 0.0 {
                    c = c.try_rounded(*radius)?;
                }
                if let Some(p) = place {
                    c = c.try_placed(*p)?;
                }
                Ok(Some(c))
            }
            Self::Mesh(_) => Ok(None),
        }
    }

    fn part(&self) -> Result<Part<'_, Real>, InputError> {
        Ok(match self {
            Self::Mesh(t) => Part::Mesh(t),
            other => Part::Convex(other.convex()?.expect("a convex piece")),
        })
    }
}

/// A parry shape converted once into `motion-bound`'s terms: a convex
/// shape (core and radius), a half-space, a mesh with its tree, or a
/// compound of these. Building one is the costly part of a first query on a
/// mesh (its tree); a [`ShapeCache`] keeps one per shared shape.
#[derive(Debug)]
pub struct Body {
    kind: BodyKind,
}

#[derive(Debug)]
enum BodyKind {
    Piece(Piece),
    HalfSpace(OurHalfSpace<Real>),
    Compound(Vec<Piece>),
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
        let kind = match shape.as_typed_shape() {
            TypedShape::HalfSpace(h) => BodyKind::HalfSpace(OurHalfSpace::try_new(vec3(h.normal))?),
            TypedShape::Compound(c) => {
                let mut pieces = Vec::with_capacity(c.shapes().len());
                for (pose, part) in c.shapes() {
                    let part = Swept::see_through(part.as_ref());
                    if matches!(
                        part.as_typed_shape(),
                        TypedShape::Compound(_) | TypedShape::HalfSpace(_)
                    ) {
                        return Err(CastError::Unsupported(match part.as_typed_shape() {
                            TypedShape::Compound(_) => "a compound within a compound",
                            _ => "a half-space within a compound",
                        }));
                    }
                    pieces.push(Piece::new(part, Some(pose))?);
                }
                if pieces.is_empty() {
                    return Err(InputError::EmptyCompound.into());
                }
                BodyKind::Compound(pieces)
            }
            _ => BodyKind::Piece(Piece::new(shape, None)?),
        };
        Ok(Self { kind })
    }

    /// Whether this body holds a mesh tree (the conversions worth caching).
    #[must_use]
    pub fn has_tree(&self) -> bool {
        match &self.kind {
            BodyKind::Piece(p) => matches!(p, Piece::Mesh(_)),
            BodyKind::Compound(ps) => ps.iter().any(|p| matches!(p, Piece::Mesh(_))),
            BodyKind::HalfSpace(_) => false,
        }
    }

    /// Calls `f` with this body as a [`motion_bound::ca::Shape`].
    ///
    /// # Errors
    /// None for a body made by [`try_new`](Self::try_new) (its vertices
    /// were checked then); the `Result` carries `motion-bound`'s checks.
    pub fn with_shape<R>(&self, f: impl FnOnce(Ours<'_, Real>) -> R) -> Result<R, CastError> {
        match &self.kind {
            BodyKind::HalfSpace(h) => Ok(f(Ours::HalfSpace(*h))),
            BodyKind::Piece(Piece::Mesh(t)) => Ok(f(Ours::Mesh(t))),
            BodyKind::Piece(p) => Ok(f(Ours::Convex(p.convex()?.expect("a convex piece")))),
            BodyKind::Compound(pieces) => {
                let parts = pieces
                    .iter()
                    .map(Piece::part)
                    .collect::<Result<Vec<_>, _>>()?;
                let compound = Compound::try_new(parts)?;
                Ok(f(Ours::Compound(&compound)))
            }
        }
    }
}

/// What identifies a cached body's parry shape.
#[derive(Debug)]
enum Identity {
    /// A registered shared shape: while it lives, nothing else sits at its
    /// address, and while the cache holds a `Weak` to it, it cannot be
    /// changed in place (`Arc::get_mut` and `Arc::make_mut` move it).
    Shared(Weak<dyn Shape>),
    /// A mesh met through a `&dyn Shape`: a copy of its vertices and
    /// triangles, compared in full at every lookup (exact, `O(n)`).
    Mesh {
        vertices: Vec<Vector>,
        indices: Vec<[u32; 3]>,
    },
    /// A compound met through a `&dyn Shape`: its parts' shared shapes
    /// (held, so that none is freed and replaced) and poses.
    Compound(Vec<(Pose, SharedShape)>),
}

impl Identity {
    fn of(shape: &dyn Shape) -> Option<Self> {
        match shape.as_typed_shape() {
            TypedShape::TriMesh(m) => Some(Self::Mesh {
                vertices: m.vertices().to_vec(),
                indices: m.indices().to_vec(),
            }),
            TypedShape::Compound(c) => Some(Self::Compound(c.shapes().to_vec())),
            _ => None,
        }
    }

    fn matches(&self, shape: &dyn Shape) -> bool {
        match (self, shape.as_typed_shape()) {
            (Self::Shared(w), _) => w.strong_count() > 0,
            (Self::Mesh { vertices, indices }, TypedShape::TriMesh(m)) => {
                m.vertices() == vertices.as_slice() && m.indices() == indices.as_slice()
            }
            (Self::Compound(parts), TypedShape::Compound(c)) => {
                parts.len() == c.shapes().len()
                    && parts
                        .iter()
                        .zip(c.shapes())
                        .all(|((p0, s0), (p1, s1))| p0 == p1 && Arc::ptr_eq(&s0.0, &s1.0))
            }
            _ => false,
        }
    }
}

#[derive(Debug)]
struct Entry {
    identity: Identity,
    body: Arc<Body>,
}

/// How a [`ShapeCache`] has been used.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct CacheStats {
    /// Bodies built (a tree for each mesh among them).
    pub built: u64,
    /// Lookups answered by a cached body.
    pub hits: u64,
    /// Bodies in the cache now.
    pub len: usize,
}

/// Converted bodies kept across queries: a mesh's tree is built once per
/// shape, and a [`SharedShape`] cloned into a thousand colliders is one
/// shape (one address). Primitive shapes are converted at every query
/// (a few arithmetic operations) and never stored.
///
/// A shape is recognised by its address, and the match is made sure of:
/// a shape [registered](Self::register) as a [`SharedShape`] by a `Weak`
/// reference (`O(1)`: while it lives no other shape has its address, and
/// while the cache holds the `Weak` it cannot be changed in place); any
/// other mesh by comparing its vertices and triangles with a copy (`O(n)`
/// per query, exact); a compound by its parts' shared shapes, which the
/// cache holds. A stale entry is replaced, never used.
///
/// ```
/// use motion_bound_parry::ShapeCache;
/// use parry3d_f64::math::Vector;
/// use parry3d_f64::shape::SharedShape;
/// let tetra = SharedShape::trimesh(
///     vec![Vector::ZERO, Vector::X, Vector::Y, Vector::Z],
///     vec![[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]],
/// )?;
/// let cache = ShapeCache::new();
/// cache.register(&tetra);
/// let clone = tetra.clone(); // a second collider's shape: the same tree
/// let a = cache.body(tetra.as_ref())?;
/// let b = cache.body(clone.as_ref())?;
/// assert!(std::sync::Arc::ptr_eq(&a, &b));
/// assert_eq!(cache.stats().built, 1);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Default)]
pub struct ShapeCache {
    entries: Mutex<HashMap<usize, Entry>>,
    workspaces: Mutex<Vec<MeshWorkspace<Real>>>,
    built: AtomicU64,
    hits: AtomicU64,
}

fn address(shape: &dyn Shape) -> usize {
    std::ptr::from_ref(shape).cast::<()>() as usize
}

impl ShapeCache {
    /// An empty cache.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// Builds `shape`'s body now (when it holds a mesh) and recognises the
    /// shape in `O(1)` from then on, as long as it lives. Registering a
    /// shape twice, or a clone of it, does nothing more. A [`Swept`] is
    /// registered as its inner shape (the same entry, wrapped or not).
    ///
    /// # Errors
    /// As [`Body::try_new`].
    pub fn try_register(&self, shape: &SharedShape) -> Result<(), CastError> {
        let shape = Swept::see_through_shared(shape);
        let key = address(shape.as_ref());
        let mut entries = self.entries.lock().unwrap_or_else(PoisonError::into_inner);
        if let Some(e) = entries.get(&key) {
            if let Identity::Shared(w) = &e.identity {
                if w.strong_count() > 0 {
                    return Ok(());
                }
            }
            if e.identity.matches(shape.as_ref()) {
                let body = e.body.clone();
                entries.insert(
                    key,
                    Entry {
                        identity: Identity::Shared(Arc::downgrade(&shape.0)),
                        body,
                    },
                );
                return Ok(());
            }
        }
        drop(entries);
        let body = Body::try_new(shape.as_ref())?;
        if body.has_tree() {
            self.built.fetch_add(1, Ordering::Relaxed);
            self.entries
                .lock()
                .unwrap_or_else(PoisonError::into_inner)
                .insert(
                    key,
                    Entry {
                        identity: Identity::Shared(Arc::downgrade(&shape.0)),
                        body: Arc::new(body),
                    },
                );
        }
        Ok(())
    }

    /// [`try_register`](Self::try_register), ignoring a shape this adapter
    /// cannot take (its queries go to parry, or fail, as unregistered).
    pub fn register(&self, shape: &SharedShape) {
        let _ = self.try_register(shape);
    }

    /// The body of `shape`: the cached one when it holds a mesh, else a
    /// fresh conversion. A [`Swept`] is looked up as its inner shape.
    ///
    /// # Errors
    /// As [`Body::try_new`].
    pub fn body(&self, shape: &dyn Shape) -> Result<Arc<Body>, CastError> {
        let shape = Swept::see_through(shape);
        if !matches!(
            shape.as_typed_shape(),
            TypedShape::TriMesh(_) | TypedShape::Compound(_)
        ) {
            return Ok(Arc::new(Body::try_new(shape)?));
        }
        let key = address(shape);
        {
            let entries = self.entries.lock().unwrap_or_else(PoisonError::into_inner);
            if let Some(e) = entries.get(&key) {
                if e.identity.matches(shape) {
                    self.hits.fetch_add(1, Ordering::Relaxed);
                    return Ok(e.body.clone());
                }
            }
        }
        let body = Arc::new(Body::try_new(shape)?);
        self.built.fetch_add(1, Ordering::Relaxed);
        if let Some(identity) = Identity::of(shape) {
            self.entries
                .lock()
                .unwrap_or_else(PoisonError::into_inner)
                .insert(
                    key,
                    Entry {
                        identity,
                        body: body.clone(),
                    },
                );
        }
        Ok(body)
    }

    /// Drops the bodies of registered shapes that no longer live.
    pub fn prune(&self) {
        self.entries
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .retain(|_, e| !matches!(&e.identity, Identity::Shared(w) if w.strong_count() == 0));
    }

    /// Drops every cached body.
    pub fn clear(&self) {
        self.entries
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .clear();
    }

    /// Bodies built, lookups answered, bodies held.
    #[must_use]
    pub fn stats(&self) -> CacheStats {
        CacheStats {
            built: self.built.load(Ordering::Relaxed),
            hits: self.hits.load(Ordering::Relaxed),
            len: self
                .entries
                .lock()
                .unwrap_or_else(PoisonError::into_inner)
                .len(),
        }
    }

    /// [`cast_shapes_nonlinear`] with this cache's bodies, its scratch
    /// space, and `params`.
    ///
    /// # Errors
    /// As [`cast_shapes_nonlinear`].
    #[allow(clippy::too_many_arguments)]
    pub fn cast_shapes_nonlinear(
        &self,
        motion1: &NonlinearRigidMotion,
        g1: &dyn Shape,
        motion2: &NonlinearRigidMotion,
        g2: &dyn Shape,
        start_time: Real,
        end_time: Real,
        stop_at_penetration: bool,
        params: &CaParams<Real>,
    ) -> Result<Option<ShapeCastHit>, CastError> {
        let b1 = self.body(g1)?;
        let b2 = self.body(g2)?;
        let ws = self
            .workspaces
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .pop()
            .unwrap_or_default();
        let (hit, ws) = cast_bodies(
            motion1,
            &b1,
            motion2,
            &b2,
            start_time,
            end_time,
            stop_at_penetration,
            params,
            ws,
        );
        self.workspaces
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .push(ws);
        hit
    }
}

/// Parry's `cast_shapes_nonlinear`, answered by `motion-bound`'s certified
/// conservative advancement with `motion-bound`'s default parameters
/// ([`CaParams::default`]: contact declared within `1e-4`, in your length
/// unit): the same arguments and meaning.
///
/// - `Ok(Some(hit))`: `hit.time_of_impact` is never later than the first
///   time in `[start_time, end_time]` the shapes touch (certified, rounding
///   included), and at it they are within the contact distance (status
///   [`ShapeCastStatus::Converged`]); witnesses and normals in each shape's
///   local frame, as parry's. Touching at `start_time`: the hit at
///   `start_time` with [`ShapeCastStatus::PenetratingOrWithinTargetDist`].
///   Shapes apart at `start_time` but within the contact distance are
///   asked again with a contact distance a quarter of the gap found (up to
///   four times), so that, as with parry's cast, a hit at `start_time`
///   means shapes touching (or closer than the last contact distance
///   tried), not merely close: rapier ignores a hit at fraction `0`, and a
///   body its CCD has just stopped short of a wall starts its next step
///   within the contact distance of it.
///   A query undecided from some time on (its iteration or work budget ran
///   out, or the placement's rounding cannot resolve the contact distance)
///   is a possible contact at that time, [`ShapeCastStatus::OutOfIterations`]
///   ("a conservative approximation", as parry says of it).
/// - `Ok(None)`: no contact anywhere in the interval, certified.
///
/// `stop_at_penetration = false` (parry: a penetration at `start_time` of
/// shapes moving apart is ignored and a later impact sought): a contact at
/// `start_time` is still reported, since no later first contact can be
/// certified while the shapes touch; rapier ignores a hit at fraction `0`
/// of a solid pair, as it does parry's.
///
/// This free function converts both shapes at every call (a mesh's tree is
/// built each time): keep a [`ShapeCache`] (or a [`CertifiedDispatcher`])
/// for meshes.
///
/// # Errors
/// [`CastError`]: an unsupported shape, an invalid shape or motion, or a
/// NaN or infinite time.
pub fn cast_shapes_nonlinear(
    motion1: &NonlinearRigidMotion,
    g1: &dyn Shape,
    motion2: &NonlinearRigidMotion,
    g2: &dyn Shape,
    start_time: Real,
    end_time: Real,
    stop_at_penetration: bool,
) -> Result<Option<ShapeCastHit>, CastError> {
    let b1 = Body::try_new(g1)?;
    let b2 = Body::try_new(g2)?;
    cast_bodies(
        motion1,
        &b1,
        motion2,
        &b2,
        start_time,
        end_time,
        stop_at_penetration,
        &CaParams::default(),
        MeshWorkspace::new(),
    )
    .0
}

/// How many times a cast starting within the contact distance, but apart,
/// is asked again with a contact distance a quarter of the gap found.
const RESOLVE_ATTEMPTS: u32 = 4;

/// The certified cast of two converted bodies, with the scratch space
/// handed back.
#[allow(clippy::too_many_arguments)]
fn cast_bodies(
    motion1: &NonlinearRigidMotion,
    b1: &Body,
    motion2: &NonlinearRigidMotion,
    b2: &Body,
    start_time: Real,
    end_time: Real,
    _stop_at_penetration: bool,
    params: &CaParams<Real>,
    ws: MeshWorkspace<Real>,
) -> (Result<Option<ShapeCastHit>, CastError>, MeshWorkspace<Real>) {
    if !start_time.is_finite() || !end_time.is_finite() {
        return (Err(CastError::Interval), ws);
    }
    // An empty or reversed interval: parry answers for the start alone.
    let end_time = if end_time > start_time {
        end_time
    } else {
        let bump = start_time.abs().max(1.0) * Real::EPSILON * 4.0;
        start_time + bump
    };
    // A half-space that only translates, turned at the start: its normal
    // taken into the world, its motion a translation (the same plane at
    // every time); `motion-bound` takes half-spaces in the world's axes.
    let world1 = in_world_axes(b1, motion1);
    let world2 = in_world_axes(b2, motion2);
    let (b1, motion1_w) = world1.as_ref().map_or((b1, motion1), |(b, m)| (b, m));
    let (b2, motion2_w) = world2.as_ref().map_or((b2, motion2), |(b, m)| (b, m));
    let motions = rigid_motion(motion1_w, start_time, end_time)
        .and_then(|m1| Ok((m1, rigid_motion(motion2_w, start_time, end_time)?)));
    let (m1, m2) = match motions {
        Ok(m) => m,
        Err(e) => return (Err(e), ws),
    };
    let mut ws = Some(ws);
    let report = b1.with_shape(|s1| {
        b2.with_shape(|s2| {
            let mut pair = AnyPair::try_new(s1, s2)?.with_workspace(ws.take().unwrap_or_default());
            // The contact distance grown by twice the displacements the
            // conversion's rounding may cause (`proofs/12-shapes.md`,
            // "Parry's shapes and motions"), so that the clearance still
            // covers them.
            let slack = rounding_slack(
                (motion1_w, reach_of(&s1)),
                (motion2_w, reach_of(&s2)),
                start_time.abs().max(end_time.abs()),
            );
            let params = &params.with_contact_distance(params.contact_distance + slack);
            let mut r = time_of_impact(&mut pair, &m1, &m2, params);
            // Within the contact distance at the start but apart: asked
            // again with a contact distance below the gap, so that a
            // contact at `start_time` means touching (parry's meaning),
            // and the answer is still never later than the first contact.
            let mut p = *params;
            for _ in 0..RESOLVE_ATTEMPTS {
                let gap = match &r {
                    Ok(CaReport {
                        outcome: CaOutcome::InitialContact(c),
                        ..
                    }) => c.witness.map_or(0.0, |w| w.distance),
                    _ => break,
                };
                p.contact_distance = gap / 4.0 + slack;
                if gap <= 0.0 || p.validate().is_err() {
                    break;
                }
                r = time_of_impact(&mut pair, &m1, &m2, &p);
            }
            ws = Some(pair.into_workspace());
            r
        })
    });
    let ws = ws.unwrap_or_default();
    let report = match report {
        Ok(Ok(Ok(r))) => r,
        Ok(Ok(Err(e))) => return (Err(e.into()), ws),
        Ok(Err(e)) | Err(e) => return (Err(e), ws),
    };
    (Ok(hit(&report.outcome, motion1, motion2, start_time)), ws)
}

/// An upper bound of the distance from its body origin of any point of a
/// shape (`0` for a half-space, whose plane passes through it).
fn reach_of(s: &Ours<'_, Real>) -> Real {
    match s {
        Ours::Convex(c) => c.reach(),
        Ours::Mesh(t) => t.root_ball().centre_norm_up() + t.root_ball().radius(),
        Ours::Compound(c) => c.reach(),
        _ => 0.0,
    }
}

/// Twice how far the conversion's rounding may move a point of either
/// body relative to the other (`proofs/12-shapes.md`, "Parry's shapes and
/// motions"): each rotation centre `c = Q l + T` is computed in floating
/// point, off by at most `8 u (|l| + |T|)`; a half-space turned into the
/// world's axes has a rounded normal, off by at most `8 u` times the
/// distance from its origin of the points that matter (the other body's, at
/// any time of the interval: within the sum of both translations, local
/// centres, reaches and travels). `16 u` times that sum covers both, with
/// a margin for the norms' own rounding; doubled for the clearance.
fn rounding_slack(
    (m1, reach1): (&NonlinearRigidMotion, Real),
    (m2, reach2): (&NonlinearRigidMotion, Real),
    time: Real,
) -> Real {
    let u = Real::EPSILON / 2.0;
    let extent = |m: &NonlinearRigidMotion, reach: Real| {
        m.start.translation.length() + m.local_center.length() + reach + m.linvel.length() * time
    };
    2.0 * 16.0 * u * (extent(m1, reach1) + extent(m2, reach2))
}

/// A half-space body whose motion has a start orientation and no angular
/// velocity, as the same plane in the world's axes: its normal rotated by
/// the start orientation, its motion the translation of its origin
/// (parry's `position_at_time` with `angvel = 0` is the start pose moved by
/// `linvel t`). `None` for any other body or motion.
fn in_world_axes(
    body: &Body,
    motion: &NonlinearRigidMotion,
) -> Option<(Body, NonlinearRigidMotion)> {
    let BodyKind::HalfSpace(h) = &body.kind else {
        return None;
    };
    if motion.angvel != Vector::ZERO || motion.start.rotation == parry::math::Rotation::IDENTITY {
        return None;
    }
    let normal = motion.start.rotation * vector(h.normal().get());
    let h = OurHalfSpace::try_new(vec3(normal)).ok()?;
    Some((
        Body {
            kind: BodyKind::HalfSpace(h),
        },
        NonlinearRigidMotion::new(
            Pose::from_translation(motion.start.translation),
            Vector::ZERO,
            motion.linvel,
            Vector::ZERO,
        ),
    ))
}

/// `motion-bound`'s outcome as parry's hit.
fn hit(
    outcome: &CaOutcome<Real>,
    motion1: &NonlinearRigidMotion,
    motion2: &NonlinearRigidMotion,
    start_time: Real,
) -> Option<ShapeCastHit> {
    let (time, status, contact) = match outcome {
        CaOutcome::Separated => return None,
        CaOutcome::InitialContact(c) => (
            start_time,
            ShapeCastStatus::PenetratingOrWithinTargetDist,
            Some(c),
        ),
        CaOutcome::Contact { contact, criterion } => (
            contact.time,
            if *criterion == ContactCriterion::Distance {
                ShapeCastStatus::Converged
            } else {
                ShapeCastStatus::OutOfIterations
            },
            Some(contact),
        ),
        CaOutcome::IterationLimit { time }
        | CaOutcome::WorkLimit { time }
        | CaOutcome::PrecisionLimit { time, .. } => (*time, ShapeCastStatus::OutOfIterations, None),
        _ => return None,
    };
    let pos1 = motion1.position_at_time(time);
    let pos2 = motion2.position_at_time(time);
    let (mut w1, mut w2, mut n1) = (Vector::ZERO, Vector::ZERO, Vector::X);
    if let Some(c) = contact {
        if let Some(w) = c.witness {
            w1 = pos1.inverse_transform_point(vector(w.on_a.to_vec3()));
            w2 = pos2.inverse_transform_point(vector(w.on_b.to_vec3()));
        }
        if let Some(n) = c.normal {
            n1 = vector(n.get());
        }
    }
    Some(ShapeCastHit {
        time_of_impact: time,
        witness1: w1,
        witness2: w2,
        normal1: pos1.rotation.inverse() * n1,
        normal2: pos2.rotation.inverse() * -n1,
        status,
        subshape1: 0,
        subshape2: 0,
    })
}

/// How many casts a [`CertifiedDispatcher`] answered, and how many it
/// handed to parry.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct DispatchStats {
    /// Casts answered by the certified conservative advancement.
    pub certified: u64,
    /// Casts handed to parry's `cast_shapes_nonlinear`: a shape this
    /// adapter does not take, or an input it refuses (the `CastError` is
    /// counted, parry answers as it would without this dispatcher).
    pub handed_to_parry: u64,
}

/// A query dispatcher for parry and rapier whose `cast_shapes_nonlinear`
/// is the certified one ([`ShapeCache::cast_shapes_nonlinear`]), every
/// other query going to parry's [`DefaultQueryDispatcher`]. Give it to
/// rapier's narrow phase:
///
/// ```
/// use motion_bound_parry::CertifiedDispatcher;
/// use rapier3d_f64::prelude::NarrowPhase;
/// let narrow_phase = NarrowPhase::with_query_dispatcher(CertifiedDispatcher::new());
/// # let _ = narrow_phase;
/// ```
///
/// A pair it cannot take (a heightfield, a polyline, voxels, a custom
/// shape) or an input it refuses goes to parry's own nonlinear cast, and is
/// counted ([`stats`](Self::stats)).
///
/// Every query sees through a [`Swept`] shape (either shape, any query:
/// contacts, distances, casts), so that a collider wrapped to have its CCD
/// answered here makes the same contacts as unwrapped. Rapier calls
/// `cast_shapes_nonlinear` only for the pairs its own sweeps do not take
/// (cylinders, cones, half-spaces, custom shapes such as [`Swept`]): wrap
/// the colliders whose CCD should be certified.
///
/// A clone shares the cache and the counters: keep one to read the stats
/// of the one given to rapier.
#[derive(Clone, Debug, Default)]
pub struct CertifiedDispatcher {
    cache: Arc<ShapeCache>,
    params: CaParams<Real>,
    counters: Arc<Counters>,
}

/// A dispatcher's counters, shared by its clones.
#[derive(Debug, Default)]
struct Counters {
    certified: AtomicU64,
    handed_to_parry: AtomicU64,
}

impl CertifiedDispatcher {
    /// With [`CaParams::default`] and a new cache.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// With conservative advancement's parameters `params` (the contact
    /// distance for your length unit, the iteration and work budgets).
    ///
    /// # Errors
    /// [`CastError::Ca`] for invalid parameters.
    pub fn try_with_params(mut self, params: CaParams<Real>) -> Result<Self, CastError> {
        params.validate()?;
        self.params = params;
        Ok(self)
    }

    /// With the cache `cache` (shared with other dispatchers or with the
    /// program, which may [register](ShapeCache::register) its shapes).
    #[must_use]
    pub fn with_cache(mut self, cache: Arc<ShapeCache>) -> Self {
        self.cache = cache;
        self
    }

    /// The cache.
    #[must_use]
    pub fn cache(&self) -> &Arc<ShapeCache> {
        &self.cache
    }

    /// Casts answered and handed over so far, by this dispatcher and its
    /// clones.
    #[must_use]
    pub fn stats(&self) -> DispatchStats {
        DispatchStats {
            certified: self.counters.certified.load(Ordering::Relaxed),
            handed_to_parry: self.counters.handed_to_parry.load(Ordering::Relaxed),
        }
    }
}

impl QueryDispatcher for CertifiedDispatcher {
    fn intersection_test(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
    ) -> Result<ShapeIntersection, Unsupported> {
        DefaultQueryDispatcher.intersection_test(
            pos12,
            Swept::see_through(g1),
            Swept::see_through(g2),
        )
    }

    fn distance(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
    ) -> Result<ShapeDistance, Unsupported> {
        DefaultQueryDispatcher.distance(pos12, Swept::see_through(g1), Swept::see_through(g2))
    }

    fn contact(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        prediction: Real,
    ) -> Result<Option<Contact>, Unsupported> {
        DefaultQueryDispatcher.contact(
            pos12,
            Swept::see_through(g1),
            Swept::see_through(g2),
            prediction,
        )
    }

    fn closest_points(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        max_dist: Real,
    ) -> Result<ClosestPoints, Unsupported> {
        DefaultQueryDispatcher.closest_points(
            pos12,
            Swept::see_through(g1),
            Swept::see_through(g2),
            max_dist,
        )
    }

    fn cast_shapes(
        &self,
        pos12: &Pose,
        local_vel12: Vector,
        g1: &dyn Shape,
        g2: &dyn Shape,
        options: parry::query::ShapeCastOptions,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        DefaultQueryDispatcher.cast_shapes(
            pos12,
            local_vel12,
            Swept::see_through(g1),
            Swept::see_through(g2),
            options,
        )
    }

    fn cast_shapes_nonlinear(
        &self,
        motion1: &NonlinearRigidMotion,
        g1: &dyn Shape,
        motion2: &NonlinearRigidMotion,
        g2: &dyn Shape,
        start_time: Real,
        end_time: Real,
        stop_at_penetration: bool,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        match self.cache.cast_shapes_nonlinear(
            motion1,
            g1,
            motion2,
            g2,
            start_time,
            end_time,
            stop_at_penetration,
            &self.params,
        ) {
            Ok(hit) => {
                self.counters.certified.fetch_add(1, Ordering::Relaxed);
                Ok(hit)
            }
            Err(_) => {
                self.counters
                    .handed_to_parry
                    .fetch_add(1, Ordering::Relaxed);
                DefaultQueryDispatcher.cast_shapes_nonlinear(
                    motion1,
                    Swept::see_through(g1),
                    motion2,
                    Swept::see_through(g2),
                    start_time,
                    end_time,
                    stop_at_penetration,
                )
            }
        }
    }
}

impl<ManifoldData, ContactData> parry::query::PersistentQueryDispatcher<ManifoldData, ContactData>
    for CertifiedDispatcher
where
    ManifoldData: Default + Clone + Send + Sync,
    ContactData: Default + Copy + Send + Sync,
{
    fn contact_manifolds(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        prediction: Real,
        manifolds: &mut Vec<parry::query::ContactManifold<ManifoldData, ContactData>>,
        workspace: &mut Option<parry::query::ContactManifoldsWorkspace>,
    ) -> Result<(), Unsupported> {
        parry::query::PersistentQueryDispatcher::contact_manifolds(
            &DefaultQueryDispatcher,
            pos12,
            Swept::see_through(g1),
            Swept::see_through(g2),
            prediction,
            manifolds,
            workspace,
        )
    }

    fn contact_manifold_convex_convex(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        normal_constraints1: Option<&dyn parry::query::details::NormalConstraints>,
        normal_constraints2: Option<&dyn parry::query::details::NormalConstraints>,
        prediction: Real,
        manifold: &mut parry::query::ContactManifold<ManifoldData, ContactData>,
    ) -> Result<(), Unsupported> {
        parry::query::PersistentQueryDispatcher::contact_manifold_convex_convex(
            &DefaultQueryDispatcher,
            pos12,
            Swept::see_through(g1),
            Swept::see_through(g2),
            normal_constraints1,
            normal_constraints2,
            prediction,
            manifold,
        )
    }
}

/// A collider shape whose continuous collision detection rapier hands to
/// its narrow phase's query dispatcher: with a [`CertifiedDispatcher`],
/// every CCD pair with this collider is answered by the certified cast.
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
