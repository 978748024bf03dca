//! Owned, validated triangle meshes.

use alloc::vec::Vec;

use crate::error::{check_components, Quantity};
use crate::mesh::MeshError;
use crate::{Float, VertexSet};

/// An owned triangle mesh: vertices `[x, y, z]` and triangles of vertex
/// indices, validated once at construction.
///
/// **Conventions.** A mesh used as a moving body has its vertices as offsets
/// from the body's rotation centre at the epoch (the crate's convention for
/// body points, see the crate docs): [`recentred`](Self::recentred) moves the
/// origin to a chosen centre, for instance the centre of mass
/// [`volume_centroid`](Self::volume_centroid). Triangles are wound
/// counter-clockwise seen from outside (right-handed normals point out), so a
/// closed, outward-wound mesh has a positive
/// [`signed_volume`](Self::signed_volume).
///
/// **Hollow or solid.** A mesh is hollow by default: as a body it is its
/// triangles, and a body wholly inside it touches nothing. A closed,
/// outward-wound mesh may be declared solid ([`try_solid`](Self::try_solid)):
/// it is then the region it bounds, and a body starting inside it is in
/// contact.
///
/// **Invariants** (checked by [`try_new`](Self::try_new)): at least one
/// vertex and one triangle; every coordinate finite and at most
/// [`Float::MAX_INPUT`] in magnitude, as [`VertexSet::try_new`] requires;
/// every index in range. Degenerate triangles and unused vertices are
/// allowed: real scans have them, and [`edge_report`](Self::edge_report)
/// counts them.
///
/// ```
/// use motion_bound::TriMesh;
///
/// // A tetrahedron, outward-wound.
/// let mesh = TriMesh::try_new(
///     vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
///     vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
/// )?;
/// assert!(mesh.is_closed());
/// assert!((mesh.signed_volume() - 1.0 / 6.0).abs() < 1e-15);
///
/// // As a body rotating about its centre of mass:
/// let centre = mesh.volume_centroid().unwrap();
/// assert_eq!(centre, [0.25, 0.25, 0.25]);
/// let body = mesh.recentred(centre)?;
/// assert!(body.vertex_set().summary().max_radius() >= 0.6875f64.sqrt()); // corner (1, 0, 0)
/// # Ok::<(), motion_bound::MeshError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct TriMesh<T> {
    vertices: Vec<[T; 3]>,
    triangles: Vec<[u32; 3]>,
    /// Declared solid ([`try_solid`](Self::try_solid)): closed, checked.
    pub(super) solid: bool,
}

/// Checks every vertex as [`VertexSet::try_new`] does.
fn check_vertices<T: Float>(vertices: &[[T; 3]]) -> Result<(), MeshError> {
    if vertices.is_empty() {
        return Err(MeshError::NoVertices);
    }
    for (i, v) in vertices.iter().enumerate() {
        check_components(*v, Quantity::Vertex(i)).map_err(MeshError::Vertex)?;
    }
    Ok(())
}

/// `x` converted to `T`, rounded up (never below `x`). `x >= 0` finite.
fn f64_up<T: Float>(x: f64) -> T {
    crate::rounding::from_f64_up(x)
}

impl<T: Float> TriMesh<T> {
    /// Validates and takes ownership of the vertices and triangles.
    ///
    /// # Errors
    /// [`MeshError::NoVertices`], [`MeshError::NoTriangles`],
    /// [`MeshError::Vertex`] for the first vertex that is not finite or too
    /// large, [`MeshError::IndexOutOfRange`] for the first bad index.
    ///
    /// ```
    /// use motion_bound::{InputError, MeshError, Quantity, TriMesh};
    /// let bad = TriMesh::try_new(vec![[0.0, f64::NAN, 0.0]], vec![[0, 0, 0]]);
    /// assert_eq!(bad, Err(MeshError::Vertex(InputError::NonFinite(Quantity::Vertex(0)))));
    /// let bad = TriMesh::try_new(vec![[0.0f32; 3]], vec![[0, 0, 1]]);
    /// assert!(matches!(bad, Err(MeshError::IndexOutOfRange { triangle: 0, index: 1, .. })));
    /// ```
    pub fn try_new(vertices: Vec<[T; 3]>, triangles: Vec<[u32; 3]>) -> Result<Self, MeshError> {
        check_vertices(&vertices)?;
        if triangles.is_empty() {
            return Err(MeshError::NoTriangles);
        }
        let n = vertices.len();
        for (t, tri) in triangles.iter().enumerate() {
            for &index in tri {
                if usize::try_from(index).map_or(true, |i| i >= n) {
                    return Err(MeshError::IndexOutOfRange {
                        triangle: t,
                        index,
                        vertex_count: n,
                    });
                }
            }
        }
        Ok(Self {
            vertices,
            triangles,
            solid: false,
        })
    }

    /// The vertices.
    #[inline]
    #[must_use]
    pub fn vertices(&self) -> &[[T; 3]] {
        &self.vertices
    }

    /// The triangles, as indices into [`vertices`](Self::vertices).
    #[inline]
    #[must_use]
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// The number of vertices (at least one).
    #[inline]
    #[must_use]
    pub fn vertex_count(&self) -> usize {
        self.vertices.len()
    }

    /// The number of triangles (at least one).
    #[inline]
    #[must_use]
    pub fn triangle_count(&self) -> usize {
        self.triangles.len()
    }

    /// The corners of triangle `i`, or `None` when `i` is out of range.
    #[inline]
    #[must_use]
    pub fn triangle(&self, i: usize) -> Option<[[T; 3]; 3]> {
        let [a, b, c] = *self.triangles.get(i)?;
        Some([self.corner(a), self.corner(b), self.corner(c)])
    }

    /// The corners of every triangle, in order.
    pub fn triangle_corners(&self) -> impl ExactSizeIterator<Item = [[T; 3]; 3]> + '_ {
        self.triangles
            .iter()
            .map(|&[a, b, c]| [self.corner(a), self.corner(b), self.corner(c)])
    }

    /// The vertex with a validated index (in range by the invariant).
    #[inline]
    fn corner(&self, i: u32) -> [T; 3] {
        // Indices were checked at construction; `get` keeps even a broken
        // invariant from panicking.
        self.vertices
            .get(i as usize)
            .copied()
            .unwrap_or([T::ZERO; 3])
    }

    /// The vertices and triangles, giving up the mesh (and its
    /// [solid](Self::try_solid) declaration).
    #[must_use]
    pub fn into_parts(self) -> (Vec<[T; 3]>, Vec<[u32; 3]>) {
        (self.vertices, self.triangles)
    }

    /// The vertices as a [`VertexSet`] for the bounds, with its summary
    /// computed (`O(N)`; cannot fail, the mesh is validated). The bounds then
    /// treat the vertices as offsets from the rotation centre.
    #[must_use]
    pub fn vertex_set(&self) -> VertexSet<'_, T> {
        VertexSet::from_validated(&self.vertices)
    }

    /// The axis-aligned bounding box `(min, max)`, exact.
    #[must_use]
    pub fn aabb(&self) -> ([T; 3], [T; 3]) {
        let mut lo = self.vertices.first().copied().unwrap_or([T::ZERO; 3]);
        let mut hi = lo;
        for v in &self.vertices {
            for k in 0..3 {
                lo[k] = lo[k].min_nan(v[k]);
                hi[k] = hi[k].max_nan(v[k]);
            }
        }
        (lo, hi)
    }

    /// The mean of the vertices (accumulated in `f64`, rounded to `T`).
    ///
    /// Cheap, but it depends on how densely each region is sampled; for the
    /// centre of mass use [`volume_centroid`](Self::volume_centroid).
    #[must_use]
    pub fn centroid(&self) -> [T; 3] {
        let c = self.centroid_f64();
        [T::from_f64(c[0]), T::from_f64(c[1]), T::from_f64(c[2])]
    }

    pub(crate) fn centroid_f64(&self) -> [f64; 3] {
        let mut s = [0.0f64; 3];
        for v in &self.vertices {
            for k in 0..3 {
                s[k] += v[k].to_f64();
            }
        }
        // A mesh has at least one vertex; exact below 2^53 vertices.
        let n = self.vertices.len() as f64;
        [s[0] / n, s[1] / n, s[2] / n]
    }

    /// The centre of mass of the solid the mesh encloses (uniform density),
    /// by the divergence theorem over its triangles, in `f64`.
    ///
    /// Meaningful for a closed mesh (see [`is_closed`](Self::is_closed)).
    /// `None` when the enclosed volume is zero, the computation overflows
    /// (coordinates beyond about `2^300`), or the result is not a valid
    /// coordinate (an open mesh can put it anywhere).
    #[must_use]
    pub fn volume_centroid(&self) -> Option<[T; 3]> {
        let o = self.centroid_f64();
        let mut vol6 = 0.0f64;
        let mut m = [0.0f64; 3];
        for [a, b, c] in self.triangle_corners() {
            let a = sub_f64(a, o);
            let b = sub_f64(b, o);
            let c = sub_f64(c, o);
            let d = det3(a, b, c);
            vol6 += d;
            for k in 0..3 {
                m[k] += d * (a[k] + b[k] + c[k]);
            }
        }
        if vol6 == 0.0 || !vol6.is_finite() {
            return None;
        }
        let mut out = [T::ZERO; 3];
        for k in 0..3 {
            // Centroid of a tetrahedron (o, a, b, c): o + (a + b + c) / 4.
            let x = T::from_f64(o[k] + m[k] / (4.0 * vol6));
            if !x.is_finite() || x.abs() > T::MAX_INPUT {
                return None;
            }
            out[k] = x;
        }
        Some(out)
    }

    /// A sphere `(centre, radius)` containing every vertex: the centre of the
    /// bounding box and the largest distance from it, rounded up so that the
    /// containment holds despite rounding.
    ///
    /// Not the smallest enclosing sphere (which can be up to `sqrt(3)`
    /// times smaller for an elongated diagonal mesh), but `O(N)` and simple.
    ///
    /// ```
    /// use motion_bound::TriMesh;
    /// let m = TriMesh::try_new(vec![[1.0, 0.0, 0.0], [3.0, 0.0, 0.0], [2.0, 1.0, 0.0]],
    ///                          vec![[0, 1, 2]])?;
    /// let (c, r) = m.bounding_sphere();
    /// assert_eq!(c, [2.0, 0.5, 0.0]);
    /// assert!(r >= 1.25f64.sqrt() && r < 1.25f64.sqrt() * (1.0 + 1e-11));
    /// # Ok::<(), motion_bound::MeshError>(())
    /// ```
    #[must_use]
    pub fn bounding_sphere(&self) -> ([T; 3], T) {
        let (lo, hi) = self.aabb();
        // lo/2 + hi/2 cannot overflow; halving is exact above the subnormals.
        let c = [
            lo[0] * T::HALF + hi[0] * T::HALF,
            lo[1] * T::HALF + hi[1] * T::HALF,
            lo[2] * T::HALF + hi[2] * T::HALF,
        ];
        let cf = [c[0].to_f64(), c[1].to_f64(), c[2].to_f64()];
        let mut max_sq = 0.0f64;
        for v in &self.vertices {
            let d = sub_f64(*v, cf);
            max_sq = max_sq.max(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        }
        // The f64 evaluation errs by a few units of 2^-53 relative, plus
        // what underflowing squares hide (below 2^-500 after the root): the
        // margin 2^-40 relative and 2^-500 absolute covers both.
        let r = <f64 as Float>::sqrt(max_sq) * (1.0 + f64::from_bits((1023 - 40) << 52))
            + f64::from_bits((1023 - 500) << 52);
        (c, f64_up(r))
    }

    /// The mesh moved by `offset` (every vertex `v` becomes `v + offset`).
    ///
    /// # Errors
    /// [`MeshError::Vertex`] if `offset` or a moved vertex is not finite or
    /// exceeds [`Float::MAX_INPUT`].
    pub fn translated(&self, offset: [T; 3]) -> Result<Self, MeshError> {
        self.map_vertices(|v| [v[0] + offset[0], v[1] + offset[1], v[2] + offset[2]])
    }

    /// The mesh with its origin moved to `centre`: every vertex `v` becomes
    /// `v - centre`, its offset from `centre`. Use it to express a body's
    /// points relative to its rotation centre, as the bounds expect.
    ///
    /// # Errors
    /// As [`translated`](Self::translated).
    ///
    /// ```
    /// use motion_bound::TriMesh;
    /// let m = TriMesh::try_new(vec![[1.0, 2.0, 3.0]; 3], vec![[0, 1, 2]])?;
    /// assert_eq!(m.recentred([1.0, 2.0, 3.0])?.vertices()[0], [0.0; 3]);
    /// # Ok::<(), motion_bound::MeshError>(())
    /// ```
    pub fn recentred(&self, centre: [T; 3]) -> Result<Self, MeshError> {
        self.map_vertices(|v| [v[0] - centre[0], v[1] - centre[1], v[2] - centre[2]])
    }

    /// The mesh scaled by `factor` about the origin.
    ///
    /// # Errors
    /// [`MeshError::InvalidScale`] unless `factor` is positive and finite (a
    /// negative factor would mirror the mesh and turn its winding inward);
    /// [`MeshError::Vertex`] if a scaled vertex exceeds
    /// [`Float::MAX_INPUT`].
    pub fn scaled(&self, factor: T) -> Result<Self, MeshError> {
        if !(factor > T::ZERO && factor.is_finite()) {
            return Err(MeshError::InvalidScale);
        }
        self.map_vertices(|v| [v[0] * factor, v[1] * factor, v[2] * factor])
    }

    /// The mesh in another precision: exact from `f32` to `f64`, rounded to
    /// nearest from `f64` to `f32`.
    ///
    /// # Errors
    /// [`MeshError::Vertex`] if a vertex exceeds `U`'s
    /// [`MAX_INPUT`](Float::MAX_INPUT) (`2^59` for `f32`).
    pub fn try_convert<U: Float>(&self) -> Result<TriMesh<U>, MeshError> {
        let vertices: Vec<[U; 3]> = self
            .vertices
            .iter()
            .map(|v| {
                [
                    U::from_f64(v[0].to_f64()),
                    U::from_f64(v[1].to_f64()),
                    U::from_f64(v[2].to_f64()),
                ]
            })
            .collect();
        check_vertices(&vertices)?;
        Ok(TriMesh {
            vertices,
            triangles: self.triangles.clone(),
            solid: self.solid,
        })
    }

    /// The mesh with `f` applied to every vertex, revalidated.
    fn map_vertices(&self, f: impl Fn([T; 3]) -> [T; 3]) -> Result<Self, MeshError> {
        let vertices: Vec<[T; 3]> = self.vertices.iter().map(|&v| f(v)).collect();
        check_vertices(&vertices)?;
        Ok(Self {
            vertices,
            triangles: self.triangles.clone(),
            solid: self.solid,
        })
    }
}

/// `v - o` in `f64`.
#[inline]
pub(crate) fn sub_f64<T: Float>(v: [T; 3], o: [f64; 3]) -> [f64; 3] {
    [
        v[0].to_f64() - o[0],
        v[1].to_f64() - o[1],
        v[2].to_f64() - o[2],
    ]
}

/// `a . (b x c)`, six times the signed volume of the tetrahedron `(0, a, b, c)`.
#[inline]
pub(crate) fn det3(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> f64 {
    a[0] * (b[1] * c[2] - b[2] * c[1])
        + a[1] * (b[2] * c[0] - b[0] * c[2])
        + a[2] * (b[0] * c[1] - b[1] * c[0])
}

#[cfg(test)]
mod tests {
    use super::TriMesh;
    use crate::{InputError, MeshError, Quantity};
    use alloc::vec;

    fn tetra() -> TriMesh<f64> {
        TriMesh::try_new(
            vec![
                [0.0, 0.0, 0.0],
                [1.0, 0.0, 0.0],
                [0.0, 1.0, 0.0],
                [0.0, 0.0, 1.0],
            ],
            vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
        )
        .unwrap()
    }

    #[test]
    fn construction_errors_are_typed() {
        assert_eq!(
            TriMesh::<f64>::try_new(vec![], vec![[0, 0, 0]]),
            Err(MeshError::NoVertices),
            "no vertex"
        );
        assert_eq!(
            TriMesh::try_new(vec![[0.0f32; 3]], vec![]),
            Err(MeshError::NoTriangles),
            "no triangle"
        );
        assert_eq!(
            TriMesh::try_new(vec![[0.0; 3], [1e300, 0.0, 0.0]], vec![[0, 1, 1]]),
            Err(MeshError::Vertex(InputError::TooLarge(Quantity::Vertex(1)))),
            "too large"
        );
        assert_eq!(
            TriMesh::try_new(vec![[0.0; 3], [f32::INFINITY, 0.0, 0.0]], vec![[0, 1, 1]]),
            Err(MeshError::Vertex(InputError::NonFinite(Quantity::Vertex(
                1
            )))),
            "infinite"
        );
        assert_eq!(
            TriMesh::try_new(vec![[0.0f64; 3]; 3], vec![[0, 1, 2], [2, u32::MAX, 0]]),
            Err(MeshError::IndexOutOfRange {
                triangle: 1,
                index: u32::MAX,
                vertex_count: 3
            }),
            "index"
        );
    }

    #[test]
    fn transformations_revalidate() {
        let m = tetra();
        assert_eq!(m.scaled(0.0), Err(MeshError::InvalidScale), "zero scale");
        assert_eq!(m.scaled(-1.0), Err(MeshError::InvalidScale), "mirror");
        assert_eq!(m.scaled(f64::NAN), Err(MeshError::InvalidScale), "NaN");
        assert!(
            matches!(m.scaled(1e300), Err(MeshError::Vertex(_))),
            "overflowing scale"
        );
        assert!(
            matches!(
                m.translated([f64::NAN, 0.0, 0.0]),
                Err(MeshError::Vertex(_))
            ),
            "NaN offset"
        );
        let moved = m.translated([1.0, 2.0, 3.0]).unwrap();
        assert_eq!(moved.vertices()[1], [2.0, 2.0, 3.0], "translated");
        assert_eq!(
            moved.recentred([1.0, 2.0, 3.0]).unwrap(),
            m,
            "recentred undoes translated"
        );
        let big = m.scaled(2.0).unwrap();
        assert!(
            (big.signed_volume() - 8.0 / 6.0).abs() < 1e-14,
            "volume scales by 8"
        );
    }

    #[test]
    fn precision_conversion() {
        let m = tetra().scaled(0.1).unwrap();
        let m32 = m.try_convert::<f32>().unwrap();
        assert_eq!(m32.vertices()[1], [0.1f32, 0.0, 0.0], "rounded to nearest");
        let back = m32.try_convert::<f64>().unwrap();
        assert_eq!(
            back.vertices()[1][0],
            f64::from(0.1f32),
            "widening is exact"
        );
        let huge = tetra().scaled(1e30).unwrap();
        assert!(
            matches!(huge.try_convert::<f32>(), Err(MeshError::Vertex(_))),
            "beyond f32's MAX_INPUT"
        );
    }

    #[test]
    fn centroids_and_spheres() {
        let m = tetra();
        assert_eq!(m.centroid(), [0.25; 3], "vertex mean");
        assert_eq!(m.volume_centroid(), Some([0.25; 3]), "centre of mass");
        let far = m.translated([1e6, -1e6, 3e6]).unwrap();
        let c = far.volume_centroid().unwrap();
        assert!(
            (c[0] - (1e6 + 0.25)).abs() < 1e-9 && (c[2] - (3e6 + 0.25)).abs() < 1e-9,
            "far from the origin"
        );
        let flat = TriMesh::try_new(vec![[0.0f64; 3]; 3], vec![[0, 1, 2]]).unwrap();
        assert_eq!(flat.volume_centroid(), None, "no volume");
        for scale in [1e-30, 1.0, 1e15] {
            let s = m.scaled(scale).unwrap().try_convert::<f32>().unwrap();
            let (c, r) = s.bounding_sphere();
            for v in s.vertices() {
                let d: f64 = (0..3)
                    .map(|k| (f64::from(v[k]) - f64::from(c[k])).powi(2))
                    .sum();
                assert!(d.sqrt() <= f64::from(r), "vertex inside at scale {scale}");
            }
        }
        let one = TriMesh::try_new(vec![[1e-300, 0.0, 0.0]], vec![[0, 0, 0]]).unwrap();
        assert!(one.bounding_sphere().1 >= 0.0, "single vertex");
    }

    #[test]
    fn triangle_access_never_panics() {
        let m = tetra();
        assert_eq!(
            m.triangle(0),
            Some([[0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]]),
            "first"
        );
        assert_eq!(m.triangle(4), None, "out of range");
        assert_eq!(m.triangle_corners().len(), 4, "iterator length");
        let body = m.vertex_set();
        assert_eq!(body.len(), 4, "vertex set");
        assert!(body.summary().max_radius() >= 1.0, "radius");
    }
}
