//! Shapes: every kind the crate has, each an opaque handle that owns what a
//! query needs built once (a mesh's tree).

use std::sync::Arc;

use motion_bound::ca::{Compound, Part, Shape};
use motion_bound::{BallTree, Convex, ConvexKind, HalfSpace, Isometry, TriMesh, VertexSet};

use crate::error::{guard, Failure, MbStatus, Res};
use crate::motion::{MbPose, MbVec3};
use crate::ptr::{free_handle, handle_ref, slice_from, write_handle, write_out, Handle, Kind};

/// A convex hull's points and rounding.
#[derive(Clone, Debug)]
pub(crate) struct Hull {
    points: Vec<[f64; 3]>,
    rounding: f64,
}

impl Hull {
    fn new(points: Vec<[f64; 3]>, rounding: f64) -> Res<Self> {
        let hull = Self { points, rounding };
        hull.convex(None)?; // validated once here
        Ok(hull)
    }

    fn convex(&self, at: Option<Isometry<f64>>) -> Res<Convex<'_, f64>> {
        let mut c = Convex::polytope(VertexSet::try_new(&self.points)?);
        if self.rounding != 0.0 {
            c = c.try_rounded(self.rounding)?;
        }
        Ok(match at {
            Some(pose) => c.try_placed(pose)?,
            None => c,
        })
    }
}

/// A triangle mesh and its tree.
#[derive(Debug)]
pub(crate) struct MeshData {
    pub(crate) mesh: TriMesh<f64>,
    tree: BallTree<f64>,
}

impl MeshData {
    fn new(vertices: Vec<[f64; 3]>, triangles: Vec<[u32; 3]>, solid: Option<bool>) -> Res<Self> {
        let mesh = TriMesh::try_new(vertices, triangles)?;
        let solid = solid.unwrap_or_else(|| mesh.is_closed() && mesh.signed_volume() > 0.0);
        let mesh = if solid { mesh.try_solid()? } else { mesh };
        let tree = BallTree::try_from_mesh(&mesh)?;
        Ok(Self { mesh, tree })
    }

    fn transformed(&self, at: &Isometry<f64>) -> Res<Self> {
        let v = self
            .mesh
            .vertices()
            .iter()
            .map(|p| {
                at.transform_point(motion_bound::Point3::from_array(*p))
                    .to_array()
            })
            .collect();
        Self::new(
            v,
            self.mesh.triangles().to_vec(),
            Some(self.mesh.is_solid()),
        )
    }
}

/// One part of a compound, owned, in the compound's frame.
#[derive(Debug)]
pub(crate) enum OwnedPart {
    Convex(Convex<'static, f64>),
    Hull(Hull, Isometry<f64>),
    Mesh(MeshData),
}

/// What a shape holds.
#[derive(Debug)]
pub(crate) enum Data {
    Convex(Convex<'static, f64>),
    Hull(Hull),
    Mesh(MeshData),
    HalfSpace(HalfSpace<f64>),
    Compound(Vec<OwnedPart>),
}

/// A shape borrowed for one query (a compound is assembled for it).
pub(crate) enum Prepared<'a> {
    Shape(Shape<'a, f64>),
    Compound(Compound<'a, f64>),
}

impl Prepared<'_> {
    pub(crate) fn shape(&self) -> Shape<'_, f64> {
        match self {
            Self::Shape(s) => *s,
            Self::Compound(c) => Shape::Compound(c),
        }
    }
}

impl Data {
    pub(crate) fn prepare(&self) -> Res<Prepared<'_>> {
        Ok(match self {
            Self::Convex(c) => Prepared::Shape(Shape::Convex(*c)),
            Self::Hull(h) => Prepared::Shape(Shape::Convex(h.convex(None)?)),
            Self::Mesh(m) => Prepared::Shape(Shape::Mesh(&m.tree)),
            Self::HalfSpace(h) => Prepared::Shape(Shape::HalfSpace(*h)),
            Self::Compound(parts) => {
                let parts = parts
                    .iter()
                    .map(|p| {
                        Ok(match p {
                            OwnedPart::Convex(c) => Part::Convex(*c),
                            OwnedPart::Hull(h, at) => Part::Convex(h.convex(Some(*at))?),
                            OwnedPart::Mesh(m) => Part::Mesh(&m.tree),
                        })
                    })
                    .collect::<Res<Vec<_>>>()?;
                Prepared::Compound(Compound::try_new(parts)?)
            }
        })
    }
}

/// A body's shape in its own frame: a ball, capsule, cuboid, cylinder, cone
/// (rounded or not), convex hull, triangle mesh (with its tree, built once),
/// half-space or compound. Opaque; made by `mb_shape_*`, freed by
/// `mb_shape_free`; immutable. A compound or a scene copies or shares what
/// it needs, so a shape may be freed once it has been passed to them.
#[derive(Debug)]
pub struct MbShape {
    pub(crate) data: Arc<Data>,
}

impl Handle for MbShape {
    const KIND: Kind = Kind::Shape;
    const NAME: &'static str = "the shape";
}

/// The kind of a shape (`mb_shape_get_kind`).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MbShapeKind {
    /// A ball.
    Ball = 0,
    /// A capsule.
    Capsule = 1,
    /// A cuboid (rounded or not).
    Cuboid = 2,
    /// A cylinder (rounded or not).
    Cylinder = 3,
    /// A cone (rounded or not).
    Cone = 4,
    /// A convex hull of points (rounded or not).
    ConvexHull = 5,
    /// A triangle mesh.
    Mesh = 6,
    /// A half-space.
    HalfSpace = 7,
    /// A compound.
    Compound = 8,
}

/// Whether a triangle mesh is solid (`mb_shape_mesh`): a body starting
/// inside a solid mesh is in contact with it; a hollow mesh is its
/// triangles alone.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MbMeshSolidity {
    /// Solid exactly when the mesh is closed (every edge shared by two
    /// triangles running along it in opposite directions) and wound outward.
    Auto = 0,
    /// Solid; `MB_STATUS_INVALID_MESH` unless closed and wound outward.
    Solid = 1,
    /// Hollow: its triangles alone.
    Hollow = 2,
}

fn new_shape(out: *mut *mut MbShape, data: Data) -> Res<()> {
    let shape = MbShape {
        data: Arc::new(data),
    };
    // SAFETY: every caller passes on its own caller's `out`, which is NULL
    // or writable by each public function's contract.
    unsafe { write_handle(out, shape) }
}

fn convex(
    out: *mut *mut MbShape,
    c: Result<Convex<'static, f64>, motion_bound::InputError>,
) -> Res<()> {
    new_shape(out, Data::Convex(c?))
}

/// A ball of `radius` about the body origin. `MB_STATUS_INVALID_INPUT` for
/// a negative, NaN or infinite radius.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `out` is `NULL` or valid for writing a pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_shape_ball(radius: f64, out: *mut *mut MbShape) -> MbStatus {
    guard(|| convex(out, Convex::try_ball(radius)))
}

/// A capsule: the segment from `(0, -half_height, 0)` to
/// `(0, half_height, 0)` rounded by `radius`.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `out` is `NULL` or valid for writing a pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_shape_capsule(
    half_height: f64,
    radius: f64,
    out: *mut *mut MbShape,
) -> MbStatus {
    guard(|| convex(out, Convex::try_capsule(half_height, radius)))
}

/// The box `[-hx, hx] x [-hy, hy] x [-hz, hz]` of the half extents.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `out` is `NULL` or valid for writing a pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_shape_cuboid(half_extents: MbVec3, out: *mut *mut MbShape) -> MbStatus {
    guard(|| convex(out, Convex::try_cuboid(half_extents.array())))
}

/// The cylinder along the body's `y` axis, `|y| <= half_height`, of radius
/// `radius`. `MB_STATUS_INVALID_INPUT` for a zero height.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `out` is `NULL` or valid for writing a pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_shape_cylinder(
    half_height: f64,
    radius: f64,
    out: *mut *mut MbShape,
) -> MbStatus {
    guard(|| convex(out, Convex::try_cylinder(half_height, radius)))
}

/// The cone along the body's `y` axis: apex `(0, half_height, 0)`, base of
/// radius `radius` at `y = -half_height`.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `out` is `NULL` or valid for writing a pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_shape_cone(
    half_height: f64,
    radius: f64,
    out: *mut *mut MbShape,
) -> MbStatus {
    guard(|| convex(out, Convex::try_cone(half_height, radius)))
}

/// The convex hull of `point_count` points, `points` holding
/// `3 * point_count` doubles `x0, y0, z0, x1, ...` (copied).
/// `MB_STATUS_INVALID_SIZE` for no point, `MB_STATUS_INVALID_INPUT` for a
/// NaN or infinite coordinate.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `points` is `NULL` or valid for reading `3 * point_count` doubles; `out`
/// is `NULL` or valid for writing a pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_shape_convex_hull(
    points: *const f64,
    point_count: usize,
    out: *mut *mut MbShape,
) -> MbStatus {
    guard(|| {
        // SAFETY: `points` is NULL or holds `3 * point_count` doubles (this
        // function's contract).
        let p = unsafe { triples(points, point_count, "points") }?;
        new_shape(out, Data::Hull(Hull::new(p, 0.0)?))
    })
}

/// `count` triples of doubles from `ptr`, copied.
///
/// # Safety
/// `ptr` is `NULL` or valid for reading `3 * count` doubles.
unsafe fn triples(ptr: *const f64, count: usize, what: &str) -> Res<Vec<[f64; 3]>> {
    if count == 0 {
        return Err(Failure::new(MbStatus::InvalidSize, format!("no {what}")));
    }
    let len = count
        .checked_mul(3)
        .ok_or_else(|| Failure::new(MbStatus::InvalidSize, format!("too many {what}")))?;
    // SAFETY: the caller's contract: `3 * count` readable doubles.
    let flat = unsafe { slice_from(ptr, len, what) }?;
    Ok(flat.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect())
}

/// The shape `shape` rounded by `radius` more: every point within `radius`
/// of it (a rounded box, cylinder, cone or hull; a ball or capsule grows),
/// as a new handle. `MB_STATUS_INVALID_INPUT` for a mesh, half-space or
/// compound, or a negative, NaN or infinite radius.
///
/// **Thread safety**: any thread; `shape` may be shared.
///
/// # Safety
/// `shape` is not freed during the call; `out` is `NULL` or valid for
/// writing a pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_shape_rounded(
    shape: *const MbShape,
    radius: f64,
    out: *mut *mut MbShape,
) -> MbStatus {
    guard(|| {
        // SAFETY: `shape` is not freed during the call (this function's contract).
        let s = unsafe { handle_ref(shape) }?;
        let data = match &*s.data {
            Data::Convex(c) => Data::Convex(c.try_rounded(radius)?),
            Data::Hull(h) => {
                let total = h.rounding + radius;
                if radius.is_nan() || radius < 0.0 {
                    return Err(motion_bound::InputError::NegativeRadius.into());
                }
                Data::Hull(Hull::new(h.points.clone(), total)?)
            }
            _ => {
                return Err(Failure::new(
                    MbStatus::InvalidInput,
                    "only convex shapes (primitives and hulls) can be rounded",
                ))
            }
        };
        new_shape(out, data)
    })
}

/// A triangle mesh of `vertex_count` vertices (`vertices`: `3 *
/// vertex_count` doubles) and `triangle_count` triangles (`indices`: `3 *
/// triangle_count` vertex indices, counter-clockwise seen from outside for
/// a solid mesh), copied; its tree is built here, once. It need not be
/// closed or convex. `solidity` says whether a body starting inside it is in
/// contact (`mb_mesh_solidity`: `0` auto, `1` solid, `2` hollow).
///
/// `MB_STATUS_INVALID_MESH` for an index out of range or a mesh that
/// cannot be solid; `MB_STATUS_INVALID_SIZE` for no vertex or no triangle;
/// `MB_STATUS_INVALID_INPUT` for a NaN or infinite vertex or an unknown
/// `solidity`.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `vertices` and `indices` are `NULL` or valid for reading their counts;
/// `out` is `NULL` or valid for writing a pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_shape_mesh(
    vertices: *const f64,
    vertex_count: usize,
    indices: *const u32,
    triangle_count: usize,
    solidity: u32,
    out: *mut *mut MbShape,
) -> MbStatus {
    guard(|| {
        let solid = match solidity {
            0 => None,
            1 => Some(true),
            2 => Some(false),
            other => {
                return Err(Failure::new(
                    MbStatus::InvalidInput,
                    format!("unknown mesh solidity {other} (0 auto, 1 solid, 2 hollow)"),
                ))
            }
        };
        // SAFETY: `vertices` is NULL or holds `3 * vertex_count` doubles (this
        // function's contract).
        let v = unsafe { triples(vertices, vertex_count, "vertices") }?;
        if triangle_count == 0 {
            return Err(Failure::new(MbStatus::InvalidSize, "no triangles"));
        }
        let len = triangle_count
            .checked_mul(3)
            .ok_or_else(|| Failure::new(MbStatus::InvalidSize, "too many triangles"))?;
        // SAFETY: `indices` is NULL or holds `3 * triangle_count` indices
        // (this function's contract).
        let flat = unsafe { slice_from(indices, len, "indices") }?;
        let t = flat.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect();
        new_shape(out, Data::Mesh(MeshData::new(v, t, solid)?))
    })
}

/// The half-space `{x : normal . x <= 0}` in the body frame (the normal,
/// any nonzero length, points out of the solid): the ground, a wall. It may
/// translate but not turn (a query refuses a turning one with
/// `MB_STATUS_QUERY_ERROR`), and two half-spaces are never paired.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `out` is `NULL` or valid for writing a pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_shape_half_space(normal: MbVec3, out: *mut *mut MbShape) -> MbStatus {
    guard(|| new_shape(out, Data::HalfSpace(HalfSpace::try_new(normal.vec())?)))
}

/// Several shapes moving as one body: `parts[k]` placed at `poses[k]` in the
/// compound's frame, for `k < count`. Parts are convex shapes and meshes
/// (not half-spaces or compounds); they are copied (a mesh's tree is
/// rebuilt at its pose), so the parts may be freed afterwards.
/// `MB_STATUS_INVALID_SIZE` for `count == 0`, `MB_STATUS_INVALID_INPUT` for a
/// half-space or compound part or a bad pose.
///
/// **Thread safety**: any thread; the parts may be shared.
///
/// # Safety
/// `parts` and `poses` are `NULL` or valid for reading `count` items; the
/// parts are not freed during the call; `out` is `NULL` or valid for
/// writing a pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_shape_compound(
    parts: *const *const MbShape,
    poses: *const MbPose,
    count: usize,
    out: *mut *mut MbShape,
) -> MbStatus {
    guard(|| {
        if count == 0 {
            return Err(Failure::new(
                MbStatus::InvalidSize,
                "a compound needs a part",
            ));
        }
        // SAFETY: `parts` and `poses` are NULL or hold `count` items (this
        // function's contract).
        let (ps, at) = unsafe {
            (
                slice_from(parts, count, "parts")?,
                slice_from(poses, count, "poses")?,
            )
        };
        let mut owned = Vec::with_capacity(count);
        for (&p, pose) in ps.iter().zip(at) {
            // SAFETY: the parts are not freed during the call (this function's contract).
            let part = unsafe { handle_ref(p) }?;
            let iso = pose.isometry()?;
            owned.push(match &*part.data {
                Data::Convex(c) => OwnedPart::Convex(c.try_placed(iso)?),
                Data::Hull(h) => OwnedPart::Hull(h.clone(), iso),
                Data::Mesh(m) => OwnedPart::Mesh(m.transformed(&iso)?),
                Data::HalfSpace(_) | Data::Compound(_) => return Err(Failure::new(
                    MbStatus::InvalidInput,
                    "a compound's parts are meshes and convex shapes (no half-space, no compound)",
                )),
            });
        }
        let data = Data::Compound(owned);
        data.prepare()?; // validated once here
        new_shape(out, data)
    })
}

/// The kind of `shape`, written to `*out`.
///
/// **Thread safety**: any thread; `shape` may be shared.
///
/// # Safety
/// `shape` is not freed during the call; `out` is `NULL` or valid for
/// writing an `mb_shape_kind`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_shape_get_kind(
    shape: *const MbShape,
    out: *mut MbShapeKind,
) -> MbStatus {
    guard(|| {
        // SAFETY: `shape` is not freed during the call (this function's contract).
        let s = unsafe { handle_ref(shape) }?;
        let kind = match &*s.data {
            Data::Convex(c) => match c.kind() {
                ConvexKind::Ball => MbShapeKind::Ball,
                ConvexKind::Capsule => MbShapeKind::Capsule,
                ConvexKind::Cuboid { .. } => MbShapeKind::Cuboid,
                ConvexKind::Cylinder { .. } => MbShapeKind::Cylinder,
                ConvexKind::Cone { .. } => MbShapeKind::Cone,
                _ => MbShapeKind::ConvexHull,
            },
            Data::Hull(_) => MbShapeKind::ConvexHull,
            Data::Mesh(_) => MbShapeKind::Mesh,
            Data::HalfSpace(_) => MbShapeKind::HalfSpace,
            Data::Compound(_) => MbShapeKind::Compound,
        };
        // SAFETY: `out` is NULL or writable (this function's contract).
        unsafe { write_out(out, kind, "out") }
    })
}

/// Frees a shape (nothing for `NULL`). Compounds and scenes made from it
/// keep what they need. `MB_STATUS_INVALID_HANDLE` for a handle freed
/// before or not a shape (then nothing is freed).
///
/// **Thread safety**: no other thread may use `shape` during or after the
/// call.
///
/// # Safety
/// As stated: `shape` is not in use elsewhere.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_shape_free(shape: *mut MbShape) -> MbStatus {
    // SAFETY: no other thread uses `shape` (this function's contract).
    guard(|| unsafe { free_handle(shape) })
}
