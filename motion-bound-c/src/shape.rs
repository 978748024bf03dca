//! Shapes: every kind the crate has, each an opaque handle that owns what a
//! query needs built once (a mesh's tree).

use std::sync::Arc;

use motion_bound::ca::{ArgError, OwnedShape, Primitive};
use motion_bound::ConvexKind;

use crate::error::{guard, Failure, MbStatus, Res};
use crate::motion::{MbPose, MbVec3};
use crate::ptr::{free_handle, handle_ref, slice_from, write_handle, write_out, Handle, Kind};

/// A body's shape in its own frame: a ball, capsule, cuboid, cylinder, cone
/// (rounded or not), convex hull, triangle mesh (with its tree, built once),
/// half-space or compound. Opaque; made by `mb_shape_*`, freed by
/// `mb_shape_free`; immutable. A compound or a scene copies or shares what
/// it needs, so a shape may be freed once it has been passed to them.
#[derive(Debug)]
pub struct MbShape {
    pub(crate) data: Arc<OwnedShape<f64>>,
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

fn new_shape(out: *mut *mut MbShape, data: Result<OwnedShape<f64>, ArgError>) -> Res<()> {
    let shape = MbShape {
        data: Arc::new(data?),
    };
    // SAFETY: every caller passes on its own caller's `out`, which is NULL
    // or writable by each public function's contract.
    unsafe { write_handle(out, shape) }
}

fn primitive(out: *mut *mut MbShape, p: Primitive<f64>) -> Res<()> {
    new_shape(out, OwnedShape::try_primitive(p, 0.0))
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
    guard(|| primitive(out, Primitive::Ball(radius)))
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
    guard(|| primitive(out, Primitive::Capsule(half_height, radius)))
}

/// The box `[-hx, hx] x [-hy, hy] x [-hz, hz]` of the half extents.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `out` is `NULL` or valid for writing a pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_shape_cuboid(half_extents: MbVec3, out: *mut *mut MbShape) -> MbStatus {
    guard(|| primitive(out, Primitive::Cuboid(half_extents.array())))
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
    guard(|| primitive(out, Primitive::Cylinder(half_height, radius)))
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
    guard(|| primitive(out, Primitive::Cone(half_height, radius)))
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
        let p = unsafe { triples(points, point_count, "points", "point_count") }?;
        new_shape(out, OwnedShape::try_hull(p, 0.0))
    })
}

/// `count` triples of doubles from `ptr`, copied.
///
/// # Safety
/// `ptr` is `NULL` or valid for reading `3 * count` doubles.
unsafe fn triples(
    ptr: *const f64,
    count: usize,
    what: &str,
    count_name: &str,
) -> Res<Vec<[f64; 3]>> {
    if count == 0 {
        return Err(Failure::new(
            MbStatus::InvalidSize,
            format!("{count_name} is 0 (no {what})"),
        ));
    }
    let len = count.checked_mul(3).ok_or_else(|| {
        Failure::new(
            MbStatus::InvalidSize,
            format!("{count_name} is {count}: too many {what}"),
        )
    })?;
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
        let s = unsafe { handle_ref(shape, "shape") }?;
        new_shape(out, s.data.try_rounded(radius))
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
                    format!("solidity is {other}: 0 (auto), 1 (solid) or 2 (hollow)"),
                ))
            }
        };
        // SAFETY: `vertices` is NULL or holds `3 * vertex_count` doubles (this
        // function's contract).
        let v = unsafe { triples(vertices, vertex_count, "vertices", "vertex_count") }?;
        if triangle_count == 0 {
            return Err(Failure::new(
                MbStatus::InvalidSize,
                "triangle_count is 0 (no triangles)",
            ));
        }
        let len = triangle_count.checked_mul(3).ok_or_else(|| {
            Failure::new(
                MbStatus::InvalidSize,
                format!("triangle_count is {triangle_count}: too many triangles"),
            )
        })?;
        // SAFETY: `indices` is NULL or holds `3 * triangle_count` indices
        // (this function's contract).
        let flat = unsafe { slice_from(indices, len, "indices") }?;
        let t = flat.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect();
        new_shape(
            out,
            OwnedShape::try_mesh(v, t, solid, ["vertices", "indices", "solidity"]),
        )
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
    guard(|| new_shape(out, OwnedShape::try_half_space(normal.array())))
}

/// Several shapes moving as one body: `parts[k]` placed at `poses[k]` in the
/// compound's frame, for `k < count`. Parts are convex shapes and meshes
/// (not half-spaces or compounds); they are copied (a mesh's tree is
/// rebuilt at its pose), so the parts may be freed afterwards.
/// `MB_STATUS_INVALID_SIZE` for `count == 0`, `MB_STATUS_INVALID_INPUT` for a
/// half-space or compound part or a bad pose. `parts` is an array of the
/// handles as made (`mb_shape *parts[]`: C does not convert `mb_shape **`
/// to `const mb_shape *const *` without a warning; the parts are only
/// read).
///
/// **Thread safety**: any thread; the parts may be shared.
///
/// # Safety
/// `parts` and `poses` are `NULL` or valid for reading `count` items; the
/// parts are not freed during the call; `out` is `NULL` or valid for
/// writing a pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_shape_compound(
    parts: *const *mut MbShape,
    poses: *const MbPose,
    count: usize,
    out: *mut *mut MbShape,
) -> MbStatus {
    guard(|| {
        if count == 0 {
            return Err(Failure::new(
                MbStatus::InvalidSize,
                "count is 0: a compound needs a part",
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
        let mut given = Vec::with_capacity(count);
        for (k, (&p, pose)) in ps.iter().zip(at).enumerate() {
            // SAFETY: the parts are not freed during the call (this function's contract).
            let part = unsafe { handle_ref(p.cast_const(), &format!("parts[{k}]")) }?;
            given.push((&*part.data, pose.isometry(&format!("poses[{k}]"))?));
        }
        new_shape(out, OwnedShape::try_compound(given))
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
        let s = unsafe { handle_ref(shape, "shape") }?;
        let kind = match &*s.data {
            OwnedShape::Convex(c) => match c.kind() {
                ConvexKind::Ball => MbShapeKind::Ball,
                ConvexKind::Capsule => MbShapeKind::Capsule,
                ConvexKind::Cuboid { .. } => MbShapeKind::Cuboid,
                ConvexKind::Cylinder { .. } => MbShapeKind::Cylinder,
                ConvexKind::Cone { .. } => MbShapeKind::Cone,
                _ => MbShapeKind::ConvexHull,
            },
            OwnedShape::Hull(_) => MbShapeKind::ConvexHull,
            OwnedShape::Mesh(_) => MbShapeKind::Mesh,
            OwnedShape::HalfSpace(_) => MbShapeKind::HalfSpace,
            _ => MbShapeKind::Compound,
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
    guard(|| unsafe { free_handle(shape, "shape") })
}
