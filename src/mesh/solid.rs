//! Solid meshes: a closed, outward-wound mesh declared to bound a solid
//! ([`TriMesh::try_solid`]), and the exact inside test
//! ([`TriMesh::winding_number`]).

use crate::geometry::winding::{winding_number, Winding};
use crate::mesh::MeshError;
use crate::{Float, TriMesh, Vec3};

impl<T: Float> TriMesh<T> {
    /// The mesh declared **solid**: as a body it is the closed region its
    /// triangles bound, not only its surface. A body that starts inside a
    /// solid mesh is then in contact with it
    /// ([`CaOutcome::InitialContact`](crate::ca::CaOutcome::InitialContact));
    /// a hollow mesh (the default) is its triangles alone, and a body wholly
    /// inside it touches nothing. [`BallTree::try_from_mesh`](crate::BallTree::try_from_mesh)
    /// carries the declaration to the tree every query uses.
    ///
    /// The mesh must be closed and outward-wound: every edge shared by
    /// exactly two triangles running along it in opposite directions, no
    /// triangle repeating a vertex index ([`EdgeReport::is_closed`](crate::EdgeReport::is_closed)),
    /// and a positive [`signed_volume`](Self::signed_volume). Its inside is
    /// where its [`winding_number`](Self::winding_number) is not zero (for
    /// a mesh that does not cross itself, the region it encloses; a cavity
    /// bounded by an inward-wound inner shell is outside). `O(F log F)`.
    ///
    /// The transformations ([`translated`](Self::translated),
    /// [`recentred`](Self::recentred), [`scaled`](Self::scaled),
    /// [`try_convert`](Self::try_convert)) keep the declaration: they move
    /// vertices, not the triangles' indices, so the mesh stays closed.
    ///
    /// # Errors
    /// [`MeshError::NotClosed`] with the counts of the defects (a hole, a
    /// crack, a flipped or doubled triangle); [`MeshError::InsideOut`] when
    /// the signed volume is not positive (wound inward, or enclosing
    /// nothing).
    ///
    /// ```
    /// use motion_bound::{MeshError, TriMesh};
    /// let v = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let tetra = TriMesh::try_new(v.clone(), vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])?;
    /// assert!(tetra.try_solid()?.is_solid());
    /// // Without its slanted face: a hole of three edges.
    /// let open = TriMesh::try_new(v.clone(), vec![[0, 2, 1], [0, 1, 3], [0, 3, 2]])?;
    /// assert!(matches!(open.try_solid(), Err(MeshError::NotClosed { unpaired: 3, .. })));
    /// // Every triangle reversed: wound inward.
    /// let inward = TriMesh::try_new(v, vec![[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]])?;
    /// assert_eq!(inward.try_solid(), Err(MeshError::InsideOut));
    /// # Ok::<(), MeshError>(())
    /// ```
    pub fn try_solid(mut self) -> Result<Self, MeshError> {
        let r = self.edge_report();
        if !r.is_closed() {
            return Err(MeshError::NotClosed {
                unpaired: r.unpaired,
                repeated: r.repeated,
                degenerate_triangles: r.degenerate_triangles,
            });
        }
        // Also NaN (an overflowing volume): not positive.
        if self.signed_volume().partial_cmp(&0.0) != Some(core::cmp::Ordering::Greater) {
            return Err(MeshError::InsideOut);
        }
        self.solid = true;
        Ok(self)
    }

    /// The mesh declared **hollow** (the default of every constructor): as a
    /// body it is its triangles alone.
    #[must_use]
    pub fn hollow(mut self) -> Self {
        self.solid = false;
        self
    }

    /// Whether the mesh is declared solid ([`try_solid`](Self::try_solid)).
    #[inline]
    #[must_use]
    pub const fn is_solid(&self) -> bool {
        self.solid
    }

    /// The winding number of the mesh about `point`, decided exactly on the
    /// floating-point coordinates: the signed count of the triangles that a
    /// ray from `point` along `+x` crosses (`+1` leaving through a triangle
    /// wound counter-clockwise seen from where the ray goes, `-1`
    /// entering), the ray's origin moved by a symbolic infinitesimal
    /// `(0, eps, eps^2)` so that it passes through no edge or vertex; every
    /// sign is an exact orientation (the `robust` crate's predicates).
    ///
    /// For a closed mesh ([`is_closed`](Self::is_closed)) and a point off
    /// it, this is the mesh's winding number: `1` inside an outward-wound
    /// mesh that does not cross itself, `0` outside; the point is inside a
    /// [solid](Self::try_solid) mesh exactly when it is not `0`. For an open
    /// mesh it is the count along that one ray, not a property of the
    /// point. `None` when the moved ray starts on a triangle (`point` is on
    /// the surface; a point on the surface may also be given the number of
    /// the moved point beside it), or when a triangle the ray meets has
    /// coordinates the exact predicates cannot take (nonzero magnitudes
    /// more than `2^200` apart, with the point's). `O(F)`.
    ///
    /// ```
    /// use motion_bound::TriMesh;
    /// let v = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let tetra = TriMesh::try_new(v, vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])?;
    /// assert_eq!(tetra.winding_number([0.1, 0.1, 0.1]), Some(1));
    /// assert_eq!(tetra.winding_number([0.5, 0.5, 0.5]), Some(0));
    /// // The ray from here runs along the edge from (0, 0, 0) to (1, 0, 0).
    /// assert_eq!(tetra.winding_number([-1.0, 0.0, 0.0]), Some(0));
    /// assert_eq!(tetra.winding_number([0.0, 0.25, 0.25]), None, "on a face");
    /// # Ok::<(), motion_bound::MeshError>(())
    /// ```
    #[must_use]
    pub fn winding_number(&self, point: [T; 3]) -> Option<i64> {
        let corners = self.triangle_corners().map(|t| t.map(Vec3::from_array));
        match winding_number(Vec3::from_array(point), corners) {
            Winding::Number(n) => Some(n),
            Winding::Surface | Winding::Undecided => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::{MeshError, TriMesh};
    use alloc::vec;

    #[test]
    fn a_solid_mesh_stays_solid_through_its_transformations() {
        let v = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        let t = vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
        let m = TriMesh::try_new(v, t).unwrap();
        assert!(!m.is_solid(), "hollow by default");
        let s = m.try_solid().unwrap();
        assert!(s.translated([1.0, 2.0, 3.0]).unwrap().is_solid(), "moved");
        assert!(s.recentred([0.25; 3]).unwrap().is_solid(), "recentred");
        assert!(s.scaled(3.0).unwrap().is_solid(), "scaled");
        assert!(s.try_convert::<f32>().unwrap().is_solid(), "converted");
        assert!(!s.clone().hollow().is_solid(), "declared hollow");
        assert_ne!(s.clone().hollow(), s, "the declaration is part of the mesh");
    }

    #[test]
    fn a_mesh_with_a_doubled_or_degenerate_triangle_is_not_solid() {
        let v = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        let mut t = vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
        t.push([1, 2, 3]);
        let doubled = TriMesh::try_new(v.clone(), t.clone()).unwrap();
        assert!(
            matches!(
                doubled.try_solid(),
                Err(MeshError::NotClosed { repeated: 3, .. })
            ),
            "doubled face"
        );
        t.pop();
        t.push([0, 0, 1]);
        let degenerate = TriMesh::try_new(v.clone(), t).unwrap();
        assert!(
            matches!(
                degenerate.try_solid(),
                Err(MeshError::NotClosed {
                    degenerate_triangles: 1,
                    ..
                })
            ),
            "degenerate triangle"
        );
        // Two copies of one triangle, opposite: closed, but no volume.
        let flat = TriMesh::try_new(v, vec![[0, 1, 2], [0, 2, 1]]).unwrap();
        assert_eq!(flat.try_solid(), Err(MeshError::InsideOut), "flat");
    }
}
