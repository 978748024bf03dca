//! Closest points between points, segments and triangles.
//!
//! Every function returns a [`ClosestPoints`]: witness points on each
//! primitive and their distance `|on_b - on_a|`. All of them work on the
//! caller's coordinates rescaled by one power of two (exact), so no
//! intermediate overflows or underflows for finite input, and each candidate
//! they compare is a pair of points of the two primitives (up to rounding):
//! the returned distance is never below the true distance by more than
//! rounding, and is the true distance in exact arithmetic.
//!
//! Degenerate input is allowed everywhere: a segment with equal ends is a
//! point, a triangle with collinear vertices is a segment, one with equal
//! vertices a point. A NaN or infinite coordinate is an
//! [`InputError::NonFinite`] naming the point (never a panic, never a NaN
//! distance).

use super::intersect::triangles_meet;
use super::predicates::points_in_exact_range;
use super::scale::Scale;
use crate::{Float, InputError, Point3, Quantity, Vec3};

/// The closest points of two sets and their distance.
///
/// `on_a` lies on the first set and `on_b` on the second (up to rounding),
/// and `distance` is `|on_b - on_a|` as computed by [`Vec3::length`]. When
/// the sets meet, `distance` is 0 and `on_a == on_b` is a common point.
///
/// The distance is well conditioned; the witnesses need not be. When the
/// minimum is flat (a vertex against an edge almost orthogonal to the
/// closest direction, or parallel edges and faces), pairs far apart along
/// the flat part have distances within rounding of each other, and which
/// one is returned is decided by rounding. So is the direction
/// `on_b - on_a` derived from them.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct ClosestPoints<T> {
    /// The Euclidean distance between the sets, `|on_b - on_a|`.
    pub distance: T,
    /// The witness point on the first set.
    pub on_a: Point3<T>,
    /// The witness point on the second set.
    pub on_b: Point3<T>,
}

/// [`ClosestPoints`] with the witnesses as the vectors the crate computes
/// with (what the mesh stepper uses; the public functions convert).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Closest<T> {
    pub(crate) distance: T,
    pub(crate) on_a: Vec3<T>,
    pub(crate) on_b: Vec3<T>,
}

impl<T: Float> From<Closest<T>> for ClosestPoints<T> {
    #[inline]
    fn from(c: Closest<T>) -> Self {
        Self {
            distance: c.distance,
            on_a: Point3::from_vec3(c.on_a),
            on_b: Point3::from_vec3(c.on_b),
        }
    }
}

impl<T: Float> Closest<T> {
    /// The answer for input with a NaN or infinite coordinate: a NaN
    /// distance, witnesses the first point of each set.
    fn non_finite(on_a: Vec3<T>, on_b: Vec3<T>) -> Self {
        Self {
            distance: nan(),
            on_a,
            on_b,
        }
    }

    /// Witnesses in scaled coordinates, mapped back (the distance is computed
    /// before unscaling, so `distance == |on_b - on_a|` holds bit for bit
    /// whenever the unscaled values neither overflow nor underflow).
    fn from_scaled(scale: &Scale<T>, on_a: Vec3<T>, on_b: Vec3<T>) -> Self {
        let d = (on_b - on_a).length();
        if d == T::ZERO {
            // A common point: make the witnesses equal, as documented.
            let m = scale.undo(on_a.lerp(on_b, T::HALF));
            return Self {
                distance: T::ZERO,
                on_a: m,
                on_b: m,
            };
        }
        Self {
            distance: scale.undo_length(d),
            on_a: scale.undo(on_a),
            on_b: scale.undo(on_b),
        }
    }
}

/// The closest points of segments `[p0, p1]` and `[q0, q1]`.
///
/// Parallel, collinear and zero-length segments are handled: the minimum is
/// taken over the interior critical point of the two lines (when they are not
/// parallel and it lies on both segments) and the four endpoint-to-segment
/// projections, which in exact arithmetic contain the minimiser. The
/// interior point uses the cross-product form
/// `s = ((q0 - p0) x d2) . n / |n|^2`, `n = d1 x d2`, whose relative error
/// grows like `u / sin(angle)` rather than the `u / sin^2(angle)` of the
/// normal equations.
///
/// # Errors
/// [`InputError::NonFinite`] with [`Quantity::Vertex`] naming the first
/// point (`0` to `3`: `p0`, `p1`, `q0`, `q1`) with a NaN or infinite
/// coordinate.
///
/// ```
/// use motion_bound::{try_segment_segment, InputError, Point3, Quantity};
/// // Two skew segments one unit apart.
/// let c = try_segment_segment(
///     Point3::new(-1.0, 0.0, 0.0), Point3::new(1.0, 0.0, 0.0),
///     Point3::new(0.0, -1.0, 1.0), Point3::new(0.0, 1.0, 1.0),
/// )?;
/// assert_eq!(c.distance, 1.0);
/// assert_eq!(c.on_a, Point3::new(0.0, 0.0, 0.0));
/// assert_eq!(c.on_b, Point3::new(0.0, 0.0, 1.0));
/// // Overlapping parallel segments: any pair across the overlap is closest.
/// let c = try_segment_segment(
///     Point3::new(0.0, 0.0, 0.0), Point3::new(2.0, 0.0, 0.0),
///     Point3::new(1.0, 3.0, 0.0), Point3::new(5.0, 3.0, 0.0),
/// )?;
/// assert_eq!(c.distance, 3.0);
/// let bad = try_segment_segment(Point3::ORIGIN, Point3::ORIGIN, Point3::new(f64::NAN, 0.0, 0.0), Point3::ORIGIN);
/// assert_eq!(bad, Err(InputError::NonFinite(Quantity::Vertex(2))));
/// # Ok::<(), InputError>(())
/// ```
pub fn try_segment_segment<T: Float>(
    p0: Point3<T>,
    p1: Point3<T>,
    q0: Point3<T>,
    q1: Point3<T>,
) -> Result<ClosestPoints<T>, InputError> {
    check_points(&[p0, p1, q0, q1])?;
    Ok(segment_segment_vec(p0.to_vec3(), p1.to_vec3(), q0.to_vec3(), q1.to_vec3()).into())
}

/// [`InputError::NonFinite`] naming the first point with a NaN or infinite
/// coordinate, by its position in `points`.
fn check_points<T: Float>(points: &[Point3<T>]) -> Result<(), InputError> {
    match points.iter().position(|p| !p.to_vec3().is_finite()) {
        Some(k) => Err(InputError::NonFinite(Quantity::Vertex(k))),
        None => Ok(()),
    }
}

/// [`try_segment_segment`] on the crate's vectors (a NaN distance for
/// non-finite input).
pub(crate) fn segment_segment_vec<T: Float>(
    p0: Vec3<T>,
    p1: Vec3<T>,
    q0: Vec3<T>,
    q1: Vec3<T>,
) -> Closest<T> {
    if ![p0, p1, q0, q1].iter().all(|p| p.is_finite()) {
        return Closest::non_finite(p0, q0);
    }
    let s = Scale::for_points(&[p0, p1, q0, q1]);
    let (x, y) = seg_seg(s.apply(p0), s.apply(p1), s.apply(q0), s.apply(q1));
    Closest::from_scaled(&s, x, y)
}

/// The closest point to `p` on the (solid) triangle `[a, b, c]`.
///
/// The nearest of four candidates: the projection onto the plane when `p`
/// projects inside the triangle (by the signs of the barycentric numerators
/// of Ericson's region method, C. Ericson, *Real-Time Collision Detection*,
/// 2005, section 5.1.5) and the closest points of the three edges. Every
/// candidate is a point of the triangle up to rounding and the closest point
/// is one of them, so degenerate triangles (a vanishing area) and slivers
/// (where the region signs are rounding noise) get their closest point up to
/// rounding too.
/// `on_a` is `p` itself, `on_b` the point on the triangle.
///
/// # Errors
/// [`InputError::NonFinite`] with [`Quantity::Vertex`] naming the first
/// point with a NaN or infinite coordinate (`0` for `p`, `1` to `3` for the
/// triangle's corners).
///
/// ```
/// use motion_bound::{try_point_triangle, Point3};
/// let tri = [Point3::new(0.0, 0.0, 0.0), Point3::new(2.0, 0.0, 0.0), Point3::new(0.0, 2.0, 0.0)];
/// let c = try_point_triangle(Point3::new(0.5, 0.5, 3.0), tri)?;
/// assert_eq!((c.distance, c.on_b), (3.0, Point3::new(0.5, 0.5, 0.0)));
/// // Beyond the hypotenuse: the closest point is on that edge.
/// let c = try_point_triangle(Point3::new(2.0, 2.0, 0.0), tri)?;
/// assert_eq!(c.on_b, Point3::new(1.0, 1.0, 0.0));
/// // A degenerate (collinear) triangle is its longest edge.
/// let flat = [Point3::new(0.0, 0.0, 0.0), Point3::new(1.0, 0.0, 0.0), Point3::new(3.0, 0.0, 0.0)];
/// assert_eq!(try_point_triangle(Point3::new(2.0, 1.0, 0.0), flat)?.distance, 1.0);
/// # Ok::<(), motion_bound::InputError>(())
/// ```
pub fn try_point_triangle<T: Float>(
    p: Point3<T>,
    triangle: [Point3<T>; 3],
) -> Result<ClosestPoints<T>, InputError> {
    check_points(&[p, triangle[0], triangle[1], triangle[2]])?;
    Ok(point_triangle_vec(p.to_vec3(), triangle.map(Point3::to_vec3)).into())
}

/// [`try_point_triangle`] on the crate's vectors (a NaN distance for
/// non-finite input).
pub(crate) fn point_triangle_vec<T: Float>(p: Vec3<T>, [a, b, c]: [Vec3<T>; 3]) -> Closest<T> {
    if ![p, a, b, c].iter().all(|p| p.is_finite()) {
        return Closest::non_finite(p, a);
    }
    let s = Scale::for_points(&[p, a, b, c]);
    let p = s.apply(p);
    let q = closest_on_triangle(p, s.apply(a), s.apply(b), s.apply(c));
    Closest::from_scaled(&s, p, q)
}

/// The distance between two solid triangles, with witness points.
///
/// If the triangles share a point the distance is 0 and `on_a == on_b` is a
/// common point. Otherwise the closest pair has a vertex of one triangle or
/// lies on an edge of each, so the result is the minimum over the 6
/// vertex-triangle pairs ([`try_point_triangle`]) and the 9 edge-edge pairs
/// ([`try_segment_segment`]).
///
/// Meeting is decided by a triangle-triangle intersection test on orientation
/// predicates (proper, coplanar, touching and degenerate cases alike; see
/// below). The minimum above cannot detect meeting by itself: two triangles
/// linked like a chain meet through their interiors while every vertex and
/// edge pair is apart. So the minimum also includes, for each edge of one
/// triangle, the point of that edge above the other triangle that is nearest
/// its plane (a segment clipped to the triangle's prism), which is a common
/// point when the edge crosses the triangle.
///
/// # Accuracy
/// Every candidate is a pair of points of the two triangles up to rounding,
/// so the distance is not below the true distance by more than rounding;
/// in exact arithmetic it is the true distance. The result is exactly 0 when
/// the intersection test says the triangles meet and the closest candidate
/// pair is within `2^10 u s` (`s` the largest absolute coordinate). The
/// test's predicates are filtered (Shewchuk's error bounds) with an exact
/// fallback ([`robust`]'s adaptive predicates) for any sign the filter
/// cannot call, so meeting is decided exactly for every finite `f32` input,
/// and for `f64` input whose coordinates are 0 or of magnitude in
/// `[2^-200, 2^200]`, or whose nonzero coordinates are at least `2^-200`
/// times the largest (decided on the exactly rescaled copy). Then a pair
/// that does not meet is reported at 0 only when its closest candidate pair
/// rounds to one point (a sub-ulp gap). Triangles that meet may still get a
/// rounding-level positive distance when their closest candidate is farther
/// than `2^10 u s`. Outside that range an uncertain sign leans to "meet",
/// but never to a 0 when the slab between the corners along the closest
/// pair's direction, or along either triangle's normal (either way),
/// certainly has a positive width (its computed width above the rounding of
/// its evaluation).
/// "Rounding-level" scales with the conditioning of the planes: about
/// `u s / sin(worst angle)` of the thinner triangle, since a point's
/// distance to a sliver's plane goes through a normal computed from nearly
/// parallel edges (a touching pair with a 0.5-degree sliver gave
/// `1850 u s`; `tests/geometry.rs` checks `2^10 u s / sin`). Conservative
/// advancement does not rely on this distance for its step (it takes the
/// slab gap of the corners along the pair's direction,
/// `proofs/09-ca-toi.md`), only to declare contact.
///
/// Degenerate (zero-area) triangles are segments or points and give their
/// correct distance.
///
/// # Errors
/// [`InputError::NonFinite`] with [`Quantity::Vertex`] naming the first
/// corner with a NaN or infinite coordinate (`0` to `2` in `a`, `3` to `5`
/// in `b`).
///
/// ```
/// use motion_bound::{try_triangle_triangle, InputError, Point3, Quantity};
/// let t = |p: [[f64; 3]; 3]| p.map(Point3::from_array);
/// let a = t([[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [0.0, 4.0, 0.0]]);
/// // Parallel, one unit above.
/// let b = t([[1.0, 1.0, 1.0], [2.0, 1.0, 1.0], [1.0, 2.0, 1.0]]);
/// assert_eq!(try_triangle_triangle(&a, &b)?.distance, 1.0);
/// // Linked like a chain: they meet although no vertex or edge pair does.
/// let c = t([[1.0, 1.0, -2.0], [1.0, 1.0, 2.0], [1.0, -3.0, 0.0]]);
/// let hit = try_triangle_triangle(&a, &c)?;
/// assert_eq!(hit.distance, 0.0);
/// assert_eq!(hit.on_a, hit.on_b);
/// // A NaN corner is named, not a NaN distance.
/// let nan = t([[1.0, 1.0, 1.0], [2.0, f64::NAN, 1.0], [1.0, 2.0, 1.0]]);
/// assert_eq!(try_triangle_triangle(&a, &nan), Err(InputError::NonFinite(Quantity::Vertex(4))));
/// # Ok::<(), InputError>(())
/// ```
pub fn try_triangle_triangle<T: Float>(
    a: &[Point3<T>; 3],
    b: &[Point3<T>; 3],
) -> Result<ClosestPoints<T>, InputError> {
    check_points(&[a[0], a[1], a[2], b[0], b[1], b[2]])?;
    Ok(triangle_triangle_vec(&a.map(Point3::to_vec3), &b.map(Point3::to_vec3)).into())
}

/// [`try_triangle_triangle`] on the crate's vectors (the mesh stepper's
/// leaf test; a NaN distance for non-finite input, which placed points of
/// validated meshes never are).
pub(crate) fn triangle_triangle_vec<T: Float>(a: &[Vec3<T>; 3], b: &[Vec3<T>; 3]) -> Closest<T> {
    if !a.iter().chain(b.iter()).all(|p| p.is_finite()) {
        return Closest::non_finite(a[0], b[0]);
    }
    let s = Scale::for_points(&[a[0], a[1], a[2], b[0], b[1], b[2]]);
    let (a0, b0) = (a, b);
    let a = a.map(|p| s.apply(p));
    let b = b.map(|p| s.apply(p));
    let mut best = Best::new();
    for i in 0..3 {
        best.offer(a[i], closest_on_triangle(a[i], b[0], b[1], b[2]));
        best.offer(closest_on_triangle(b[i], a[0], a[1], a[2]), b[i]);
        // The edges' interior pairs; their ends against the other's edges
        // are the vertices' candidates above (`closest_on_triangle` offers
        // each corner against all three edges).
        for j in 0..3 {
            if let Some((x, y)) = seg_seg_interior(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3]) {
                best.offer(x, y);
            }
        }
        if let Some(x) = point_over_triangle(a[i], a[(i + 1) % 3], &b) {
            best.offer(x, closest_on_triangle(x, b[0], b[1], b[2]));
        }
        if let Some(y) = point_over_triangle(b[i], b[(i + 1) % 3], &a) {
            best.offer(closest_on_triangle(y, a[0], a[1], a[2]), y);
        }
    }
    let (mut x, mut y) = (best.on_a, best.on_b);
    let m = a
        .iter()
        .chain(b.iter())
        .fold(T::ZERO, |m, p| m.max_nan(p.max_abs()));
    let tol = crate::rounding::snap_tolerance(m);
    if best.d2 > T::ZERO
        && best.d2 <= tol * tol
        && !certainly_apart(&a, &b, y - x, m)
        && meet(a0, b0, &a, &b)
    {
        let mid = x.lerp(y, T::HALF);
        (x, y) = (mid, mid);
    }
    Closest::from_scaled(&s, x, y)
}

/// Whether the triangles meet (given as the caller passed them, and
/// rescaled). Decided on the caller's coordinates when the predicates are
/// exact on them (always for `f32`: rescaling could round its small
/// coordinates into the subnormal range), else on the rescaled ones (exact
/// rescaling whenever those are in the exact range). Only evaluated near
/// contact, before a snap to 0.
fn meet<T: Float>(
    a0: &[Vec3<T>; 3],
    b0: &[Vec3<T>; 3],
    a: &[Vec3<T>; 3],
    b: &[Vec3<T>; 3],
) -> bool {
    if points_in_exact_range(&[a0[0], a0[1], a0[2], b0[0], b0[1], b0[2]]) {
        triangles_meet(a0, b0)
    } else {
        triangles_meet(a, b)
    }
}

/// Whether a slab certainly separates the triangles: along `closest` (the
/// closest pair's direction, from `a` towards `b`), or along either
/// triangle's normal, either way. The closest pair's direction can be
/// tilted by rounding on a sliver (an `f32` pair in planes `2.96e-5` apart,
/// one triangle 0.011 wide, was snapped to 0 although GJK certified
/// `1.7e-5`); the normal of parallel planes is not. Only evaluated near
/// contact, before a snap to 0.
fn certainly_apart<T: Float>(a: &[Vec3<T>; 3], b: &[Vec3<T>; 3], closest: Vec3<T>, m: T) -> bool {
    if slab_separates(a, b, closest, m) {
        return true;
    }
    let na = (a[1] - a[0]).cross(a[2] - a[0]);
    let nb = (b[1] - b[0]).cross(b[2] - b[0]);
    [na, nb]
        .into_iter()
        .any(|n| slab_separates(a, b, n, m) || slab_separates(b, a, n, m))
}

/// Whether the slab between the triangles along `n` (from `a` towards `b`)
/// certainly has a positive width: `min_b q.n - max_a p.n` above the
/// rounding of its evaluation. Each computed dot product errs by at most
/// `gamma_3 m |n|_1` (`m` the largest absolute coordinate), so a computed
/// width above `16 u m |n|_1` is positive in exact arithmetic for this `n`,
/// and then no point is common to the triangles: the filtered intersection
/// test's "meet", which leans to yes near degenerate configurations, is
/// overruled and the distance is not snapped to 0.
fn slab_separates<T: Float>(a: &[Vec3<T>; 3], b: &[Vec3<T>; 3], n: Vec3<T>, m: T) -> bool {
    let lo_b = b[0].dot(n).min_nan(b[1].dot(n)).min_nan(b[2].dot(n));
    let hi_a = a[0].dot(n).max_nan(a[1].dot(n)).max_nan(a[2].dot(n));
    let err = crate::rounding::slab_rounding(m, n.norm_l1());
    lo_b - hi_a > err
}

/// The closest pair so far (by squared distance; a NaN candidate never wins
/// over a number, and a number always replaces a NaN).
struct Best<T> {
    d2: T,
    on_a: Vec3<T>,
    on_b: Vec3<T>,
}

impl<T: Float> Best<T> {
    fn new() -> Self {
        Self {
            d2: nan(), // replaced by the first candidate
            on_a: Vec3::ZERO,
            on_b: Vec3::ZERO,
        }
    }

    fn offer(&mut self, x: Vec3<T>, y: Vec3<T>) {
        let d2 = x.distance_squared(y);
        if self.d2.is_nan() || d2 < self.d2 {
            self.d2 = d2;
            self.on_a = x;
            self.on_b = y;
        }
    }
}

/// A quiet NaN (`0 * inf`; the sealed `Float` has no NaN constant).
fn nan<T: Float>() -> T {
    T::ZERO * T::INFINITY
}

/// The closest point to `p` on segment `[a, b]` (`a` when it has zero length).
pub(crate) fn closest_on_segment<T: Float>(p: Vec3<T>, a: Vec3<T>, b: Vec3<T>) -> Vec3<T> {
    let ab = b - a;
    let num = (p - a).dot(ab);
    if !(num > T::ZERO) {
        return a;
    }
    let den = ab.length_squared();
    if num >= den {
        return b;
    }
    a + ab * (num / den)
}

/// The closest points of the lines through two segments when both lie
/// within the segments (the pair of interior points where the segments'
/// common perpendicular meets them), in scaled coordinates; `None` for
/// parallel segments or when either point is off its segment.
fn seg_seg_interior<T: Float>(
    p0: Vec3<T>,
    p1: Vec3<T>,
    q0: Vec3<T>,
    q1: Vec3<T>,
) -> Option<(Vec3<T>, Vec3<T>)> {
    let (d1, d2) = (p1 - p0, q1 - q0);
    let n = d1.cross(d2);
    let nn = n.length_squared();
    if nn > T::ZERO {
        let r = q0 - p0;
        let s = r.cross(d2).dot(n) / nn;
        let t = r.cross(d1).dot(n) / nn;
        if (T::ZERO..=T::ONE).contains(&s) && (T::ZERO..=T::ONE).contains(&t) {
            return Some((p0 + d1 * s, q0 + d2 * t));
        }
    }
    None
}

/// Closest points of two segments, in scaled coordinates.
fn seg_seg<T: Float>(p0: Vec3<T>, p1: Vec3<T>, q0: Vec3<T>, q1: Vec3<T>) -> (Vec3<T>, Vec3<T>) {
    let mut best = Best::new();
    if let Some((x, y)) = seg_seg_interior(p0, p1, q0, q1) {
        best.offer(x, y);
    }
    best.offer(p0, closest_on_segment(p0, q0, q1));
    best.offer(p1, closest_on_segment(p1, q0, q1));
    best.offer(closest_on_segment(q0, p0, p1), q0);
    best.offer(closest_on_segment(q1, p0, p1), q1);
    (best.on_a, best.on_b)
}

/// The point of triangle `abc` closest to `p`, in scaled coordinates: the
/// nearest of the face point (when `p` projects inside, by the signs of
/// Ericson's barycentric numerators `va, vb, vc`) and the closest points of
/// the three edges.
///
/// Every candidate is a point of the triangle up to rounding (the face point
/// is a convex combination, offered only when the three numerators are
/// non-negative), and the exact closest point is either the face point or on
/// an edge, so the nearest candidate is the closest point up to rounding
/// whatever the triangle's shape. Ericson's early returns by Voronoi region
/// are not used: for a sliver (nearly collinear corners) the region signs
/// are rounding noise, and a point on one edge could be sent to another edge
/// a sliver's width away (`tests/geometry.rs`,
/// `a_point_on_a_sliver_is_on_it`).
fn closest_on_triangle<T: Float>(p: Vec3<T>, a: Vec3<T>, b: Vec3<T>, c: Vec3<T>) -> Vec3<T> {
    let zero = T::ZERO;
    let (ab, ac, ap, bp, cp) = (b - a, c - a, p - a, p - b, p - c);
    let (d1, d2) = (ab.dot(ap), ac.dot(ap));
    let (d3, d4) = (ab.dot(bp), ac.dot(bp));
    let (d5, d6) = (ab.dot(cp), ac.dot(cp));
    let (va, vb, vc) = (d3 * d6 - d5 * d4, d5 * d2 - d1 * d6, d1 * d4 - d3 * d2);
    let mut best = Best::new();
    let den = va + vb + vc;
    if va >= zero && vb >= zero && vc >= zero && den > zero {
        best.offer(p, a + ab * (vb / den) + ac * (vc / den));
    }
    best.offer(p, closest_on_segment(p, a, b));
    best.offer(p, closest_on_segment(p, a, c));
    best.offer(p, closest_on_segment(p, b, c));
    best.on_b
}

/// The point of segment `[p, q]` lying above the triangle `t` (inside the
/// prism over it) that is nearest the triangle's plane, or `None` when no
/// point of the segment is above it or the triangle has no normal. When the
/// segment crosses the triangle this is the crossing point, computed by
/// minimising the (linear) height over the clipped parameter interval, so its
/// height is rounding-level even for a shallow crossing.
fn point_over_triangle<T: Float>(p: Vec3<T>, q: Vec3<T>, t: &[Vec3<T>; 3]) -> Option<Vec3<T>> {
    let zero = T::ZERO;
    let n = (t[1] - t[0]).cross(t[2] - t[0]);
    if !(n.length_squared() > zero) {
        return None;
    }
    // Liang-Barsky clipping against the three inward edge half-spaces.
    let (mut t0, mut t1) = (zero, T::ONE);
    for i in 0..3 {
        let (v0, v1) = (t[i], t[(i + 1) % 3]);
        let m = n.cross(v1 - v0); // points into the triangle
        let (gp, gq) = (m.dot(p - v0), m.dot(q - v0));
        if gp < zero && gq < zero {
            return None;
        }
        if gp < zero {
            t0 = t0.max_nan(gp / (gp - gq));
        } else if gq < zero {
            t1 = t1.min_nan(gp / (gp - gq));
        }
    }
    if !(t0 <= t1) {
        return None;
    }
    let (hp, hq) = (n.dot(p - t[0]), n.dot(q - t[0]));
    let h = |s: T| hp + (hq - hp) * s;
    let (h0, h1) = (h(t0), h(t1));
    let s = if (h0 <= zero && h1 >= zero) || (h0 >= zero && h1 <= zero) {
        let den = hp - hq;
        let root = if den == zero { t0 } else { hp / den };
        root.max_nan(t0).min_nan(t1)
    } else if h0.abs() <= h1.abs() {
        t0
    } else {
        t1
    };
    if s.is_nan() {
        return None;
    }
    Some(p.lerp(q, s))
}

#[cfg(test)]
mod tests {
    use super::{
        point_triangle_vec as point_triangle, segment_segment_vec as segment_segment,
        triangle_triangle_vec as triangle_triangle,
    };
    use crate::Vec3;

    fn v(x: f64, y: f64, z: f64) -> Vec3<f64> {
        Vec3::new(x, y, z)
    }

    #[test]
    fn segment_cases() {
        // Crossing at a point.
        let c = segment_segment(
            v(0.0, 0.0, 0.0),
            v(2.0, 2.0, 0.0),
            v(0.0, 2.0, 0.0),
            v(2.0, 0.0, 0.0),
        );
        assert_eq!(c.distance, 0.0, "crossing");
        assert_eq!(c.on_a, v(1.0, 1.0, 0.0), "crossing point");
        // Collinear, disjoint: end to end.
        let c = segment_segment(
            v(0.0, 0.0, 0.0),
            v(1.0, 0.0, 0.0),
            v(3.0, 0.0, 0.0),
            v(2.0, 0.0, 0.0),
        );
        assert_eq!(
            (c.distance, c.on_a, c.on_b),
            (1.0, v(1.0, 0.0, 0.0), v(2.0, 0.0, 0.0)),
            "collinear"
        );
        // Both degenerate.
        let c = segment_segment(
            v(1.0, 1.0, 1.0),
            v(1.0, 1.0, 1.0),
            v(1.0, 1.0, 4.0),
            v(1.0, 1.0, 4.0),
        );
        assert_eq!(c.distance, 3.0, "points");
        // Nearly parallel, long: the distance must not be polluted by the
        // normal equations' cancellation.
        let e = 1e-9;
        let c = segment_segment(
            v(-1e3, 0.0, 0.0),
            v(1e3, 0.0, 0.0),
            v(-1e3, 1.0, -e),
            v(1e3, 1.0, e),
        );
        assert!(
            (c.distance - 1.0).abs() < 1e-12,
            "nearly parallel: {}",
            c.distance
        );
    }

    #[test]
    fn triangle_regions() {
        let tri = [v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), v(0.0, 1.0, 0.0)];
        let cases = [
            (v(-1.0, -1.0, 0.0), v(0.0, 0.0, 0.0)),
            (v(2.0, -1.0, 1.0), v(1.0, 0.0, 0.0)),
            (v(-1.0, 2.0, -1.0), v(0.0, 1.0, 0.0)),
            (v(0.5, -1.0, 0.0), v(0.5, 0.0, 0.0)),
            (v(-1.0, 0.5, 0.0), v(0.0, 0.5, 0.0)),
            (v(1.0, 1.0, 0.0), v(0.5, 0.5, 0.0)),
            (v(0.25, 0.25, -2.0), v(0.25, 0.25, 0.0)),
        ];
        for (p, q) in cases {
            let c = point_triangle(p, tri);
            assert!(
                (c.on_b - q).length() < 1e-15,
                "{p:?}: got {:?}, want {q:?}",
                c.on_b
            );
            assert_eq!(c.distance, (q - p).length(), "{p:?}: distance");
        }
        // Found by the property test: a zero-length edge AB passed its
        // region test vacuously and the vertex A came back.
        let c = point_triangle(
            v(0.0, 0.0, 0.0),
            [v(0.0, 1.0, 0.0), v(0.0, 1.0, 0.0), v(0.0, 0.0, 0.0)],
        );
        assert_eq!(c.distance, 0.0, "repeated vertex: {c:?}");
        let single = [v(1.0, 2.0, 3.0); 3];
        assert_eq!(
            point_triangle(v(1.0, 2.0, 5.0), single).distance,
            2.0,
            "point triangle"
        );
    }

    #[test]
    fn extreme_magnitudes_neither_overflow_nor_underflow() {
        for s in [1e-300f64, 1e300, f64::MAX / 8.0] {
            let a = [v(0.0, 0.0, 0.0), v(s, 0.0, 0.0), v(0.0, s, 0.0)];
            let b = [
                v(0.0, 0.0, s / 2.0),
                v(s / 4.0, 0.0, s / 2.0),
                v(0.0, s / 4.0, s / 2.0),
            ];
            let c = triangle_triangle(&a, &b);
            assert_eq!(c.distance, s / 2.0, "scale {s}");
        }
        let big = f32::MAX / 4.0;
        let c = segment_segment(
            Vec3::new(-big, 0.0, 0.0),
            Vec3::new(big, 0.0, 0.0),
            Vec3::new(0.0, -big, big),
            Vec3::new(0.0, big, big),
        );
        assert_eq!(c.distance, big, "f32 near MAX");
    }

    /// The public functions name the first non-finite point (an earlier
    /// version returned a NaN distance, against the crate's "never NaN").
    #[test]
    fn non_finite_input_is_a_typed_error_naming_the_point() {
        use super::{try_point_triangle, try_segment_segment, try_triangle_triangle};
        use crate::{InputError, Point3, Quantity};
        let p = |x: f64, y: f64, z: f64| Point3::new(x, y, z);
        let a = [p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0), p(0.0, 1.0, 0.0)];
        let b = [p(0.0, 0.0, 1.0), p(1.0, 0.0, 1.0), p(0.0, 1.0, 1.0)];
        let err = |k| Err(InputError::NonFinite(Quantity::Vertex(k)));
        for (k, bad) in [f64::NAN, f64::INFINITY, -f64::INFINITY]
            .into_iter()
            .enumerate()
        {
            let mut a2 = a;
            a2[k].y = bad;
            assert_eq!(try_triangle_triangle(&a2, &b), err(k), "corner {k} of a");
            let mut b2 = b;
            b2[k].z = bad;
            assert_eq!(
                try_triangle_triangle(&a, &b2),
                err(3 + k),
                "corner {k} of b"
            );
            assert_eq!(try_point_triangle(a2[k], b), err(0), "the point");
            assert_eq!(try_point_triangle(a[0], b2), err(1 + k), "a corner");
            assert_eq!(try_segment_segment(a[0], a[1], b[0], b2[k]), err(3), "q1");
        }
        let ok = try_triangle_triangle(&a, &b).expect("finite");
        assert_eq!(ok.distance, 1.0, "the finite pair");
    }

    #[test]
    fn non_finite_input_gives_nan() {
        let a = [v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), v(0.0, f64::NAN, 0.0)];
        let b = [v(0.0, 0.0, 1.0), v(1.0, 0.0, 1.0), v(0.0, 1.0, 1.0)];
        assert!(triangle_triangle(&a, &b).distance.is_nan(), "NaN vertex");
        let a = [
            v(0.0, 0.0, 0.0),
            v(f64::INFINITY, 0.0, 0.0),
            v(0.0, 1.0, 0.0),
        ];
        assert!(
            triangle_triangle(&a, &b).distance.is_nan(),
            "infinite vertex"
        );
        assert!(point_triangle(a[1], b).distance.is_nan(), "infinite point");
        assert!(
            segment_segment(a[0], a[1], b[0], b[1]).distance.is_nan(),
            "infinite end"
        );
    }
}
