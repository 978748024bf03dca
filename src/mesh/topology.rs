//! Closedness, orientation and volume of a mesh.
//!
//! A CA time-of-impact engine for non-convex bodies needs its meshes closed
//! and consistently wound: the inside of the body is then well defined, and
//! an outward normal is the right-handed normal of every triangle. These
//! checks are what the scene generators' and the shipped meshes' tests use.

use alloc::vec::Vec;

use crate::mesh::trimesh::{det3, sub_f64};
use crate::{Float, TriMesh};

/// How a mesh's triangles fit together along their edges
/// ([`TriMesh::edge_report`]).
///
/// Each triangle `[a, b, c]` has the directed edges `a->b`, `b->c`, `c->a`.
/// A mesh is closed and consistently oriented exactly when every directed
/// edge occurs once and its reverse occurs once too: every edge is then
/// shared by exactly two triangles that run along it in opposite directions.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct EdgeReport {
    /// Distinct undirected edges (a degenerate triangle's edge `a->a` is not
    /// counted).
    pub edges: usize,
    /// Distinct directed edges whose reverse no triangle has: boundary edges
    /// of an open mesh, or edges between two triangles wound inconsistently.
    pub unpaired: usize,
    /// Extra occurrences of directed edges that occur more than once:
    /// inconsistently wound neighbours, or an edge shared by more than two
    /// triangles (non-manifold).
    pub repeated: usize,
    /// Triangles that repeat a vertex index.
    pub degenerate_triangles: usize,
}

impl EdgeReport {
    /// `true` when the mesh is closed, manifold along its edges, consistently
    /// oriented and free of index-degenerate triangles.
    #[inline]
    #[must_use]
    pub const fn is_closed(&self) -> bool {
        self.unpaired == 0 && self.repeated == 0 && self.degenerate_triangles == 0
    }
}

impl<T: Float> TriMesh<T> {
    /// How the triangles fit together along their edges (`O(F log F)`, one
    /// allocation of `3 F` edges).
    ///
    /// ```
    /// use motion_bound::TriMesh;
    /// // One triangle: three boundary edges.
    /// let m = TriMesh::try_new(vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
    ///                          vec![[0, 1, 2]])?;
    /// let r = m.edge_report();
    /// assert_eq!((r.edges, r.unpaired, r.repeated), (3, 3, 0));
    /// assert!(!r.is_closed());
    /// # Ok::<(), motion_bound::MeshError>(())
    /// ```
    #[must_use]
    pub fn edge_report(&self) -> EdgeReport {
        let mut report = EdgeReport::default();
        let mut edges: Vec<(u32, u32)> = Vec::with_capacity(3 * self.triangle_count());
        for &[a, b, c] in self.triangles() {
            if a == b || b == c || c == a {
                report.degenerate_triangles += 1;
            }
            for (x, y) in [(a, b), (b, c), (c, a)] {
                if x != y {
                    edges.push((x, y));
                }
            }
        }
        edges.sort_unstable();
        let mut i = 0;
        while i < edges.len() {
            let e = edges[i];
            let mut j = i + 1;
            while j < edges.len() && edges[j] == e {
                j += 1;
            }
            report.repeated += j - i - 1;
            let paired = edges.binary_search(&(e.1, e.0)).is_ok();
            if !paired {
                report.unpaired += 1;
            }
            // Count an undirected edge once: at its smaller-first direction,
            // or at its only direction.
            if e.0 < e.1 || !paired {
                report.edges += 1;
            }
            i = j;
        }
        report
    }

    /// `true` when every edge is shared by exactly two triangles running
    /// along it in opposite directions and no triangle repeats a vertex
    /// index: see [`EdgeReport`].
    #[must_use]
    pub fn is_closed(&self) -> bool {
        self.edge_report().is_closed()
    }

    /// The signed volume enclosed by the mesh, `sum a . (b x c) / 6` over its
    /// triangles, evaluated in `f64` relative to the vertex centroid.
    ///
    /// Positive for a closed, outward-wound (counter-clockwise seen from
    /// outside) mesh, negative when wound inward; for an open mesh it depends
    /// on the reference point. `+-inf` or NaN when the products overflow
    /// (coordinates beyond about `2^300`).
    #[must_use]
    pub fn signed_volume(&self) -> f64 {
        let o = self.centroid_f64();
        let mut vol6 = 0.0;
        for [a, b, c] in self.triangle_corners() {
            vol6 += det3(sub_f64(a, o), sub_f64(b, o), sub_f64(c, o));
        }
        vol6 / 6.0
    }

    /// The total area of the triangles, in `f64`.
    #[must_use]
    pub fn surface_area(&self) -> f64 {
        let mut area2 = 0.0;
        for [a, b, c] in self.triangle_corners() {
            let u = sub_f64(b, [a[0].to_f64(), a[1].to_f64(), a[2].to_f64()]);
            let v = sub_f64(c, [a[0].to_f64(), a[1].to_f64(), a[2].to_f64()]);
            let n = [
                u[1] * v[2] - u[2] * v[1],
                u[2] * v[0] - u[0] * v[2],
                u[0] * v[1] - u[1] * v[0],
            ];
            area2 += <f64 as Float>::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        }
        area2 / 2.0
    }
}

#[cfg(test)]
mod tests {
    use crate::TriMesh;
    use alloc::vec;

    #[test]
    fn edge_report_names_each_defect() {
        let v = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        let closed = vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
        let m = TriMesh::try_new(v.clone(), closed.clone()).unwrap();
        let r = m.edge_report();
        assert!(r.is_closed(), "tetrahedron is closed: {r:?}");
        assert_eq!(r.edges, 6, "six edges");

        let mut flipped = closed.clone();
        flipped[3] = [1, 3, 2];
        let r = TriMesh::try_new(v.clone(), flipped).unwrap().edge_report();
        assert!(
            r.repeated == 3 && r.unpaired == 3 && r.edges == 6,
            "one flipped face: {r:?}"
        );

        let open = TriMesh::try_new(v.clone(), closed[..3].to_vec()).unwrap();
        let r = open.edge_report();
        assert_eq!((r.unpaired, r.repeated, r.edges), (3, 0, 6), "open: {r:?}");

        let mut nonmanifold = closed.clone();
        nonmanifold.push([0, 2, 1]);
        let r = TriMesh::try_new(v.clone(), nonmanifold)
            .unwrap()
            .edge_report();
        assert_eq!(r.repeated, 3, "a doubled face repeats its edges: {r:?}");

        let mut degenerate = closed;
        degenerate.push([0, 0, 1]);
        let r = TriMesh::try_new(v, degenerate).unwrap().edge_report();
        assert_eq!(r.degenerate_triangles, 1, "degenerate: {r:?}");
        assert!(!r.is_closed(), "degenerate is not closed");
    }

    #[test]
    fn volume_sign_follows_winding() {
        let v = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        let out =
            TriMesh::try_new(v.clone(), vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]).unwrap();
        let inward = TriMesh::try_new(v, vec![[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]).unwrap();
        assert!((out.signed_volume() - 1.0 / 6.0).abs() < 1e-15, "outward");
        assert!((inward.signed_volume() + 1.0 / 6.0).abs() < 1e-15, "inward");
        let area = 1.5 + 0.75f64.sqrt();
        assert!((out.surface_area() - area).abs() < 1e-15, "area");
    }
}
