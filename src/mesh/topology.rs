//! Closedness, orientation, volume and connected components of a mesh.
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
        edge_report_of(self.triangles())
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

/// The root of `x` in the forest `parent`, halving the path on the way.
fn find(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        let up = parent[parent[x as usize] as usize];
        parent[x as usize] = up;
        x = up;
    }
    x
}

/// Joins the sets of `a` and `b`; the root is the smaller index, so every
/// set's root is its least member.
fn join(parent: &mut [u32], a: u32, b: u32) {
    let (ra, rb) = (find(parent, a), find(parent, b));
    if ra != rb {
        parent[ra.max(rb) as usize] = ra.min(rb);
    }
}

/// [`TriMesh::edge_report`] of the triangles `triangles` (indices only).
pub(crate) fn edge_report_of(triangles: &[[u32; 3]]) -> EdgeReport {
    let mut report = EdgeReport::default();
    let mut edges: Vec<(u32, u32)> = Vec::with_capacity(3 * triangles.len());
    for &[a, b, c] in triangles {
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

/// One point of each connected component of the triangles, as a set of
/// points: two triangles are connected when they share a vertex index or a
/// vertex position. The least-indexed vertex of each component, in index
/// order; vertices that no triangle names are left out, as are indices out
/// of range. `O(V log V + F)`.
///
/// A body made of the triangles is connected within each component, so a
/// component that does not meet a closed surface lies wholly on one side of
/// it, the side of its point (`proofs/09-ca-toi.md`, Lemma 9.7).
pub(crate) fn component_points<T: Float>(
    vertices: &[[T; 3]],
    triangles: &[[u32; 3]],
) -> Vec<[T; 3]> {
    let n = vertices.len().min(u32::MAX as usize);
    let mut parent: Vec<u32> = (0..n as u32).collect();
    let mut used = alloc::vec![false; n];
    for tri in triangles {
        if tri.iter().any(|&i| i as usize >= n) {
            continue;
        }
        for &i in tri {
            used[i as usize] = true;
        }
        join(&mut parent, tri[0], tri[1]);
        join(&mut parent, tri[1], tri[2]);
    }
    // Vertices at one position are one point of the body: sorted by their
    // coordinates' bits (`+ 0.0` makes `-0.0` and `0.0` one key).
    let key = |i: u32| vertices[i as usize].map(|c| (c.to_f64() + 0.0).to_bits());
    let mut order: Vec<u32> = (0..n as u32).filter(|&i| used[i as usize]).collect();
    order.sort_unstable_by_key(|&i| key(i));
    for w in order.windows(2) {
        if key(w[0]) == key(w[1]) {
            join(&mut parent, w[0], w[1]);
        }
    }
    (0..n as u32)
        .filter(|&i| used[i as usize] && find(&mut parent, i) == i)
        .map(|i| vertices[i as usize])
        .collect()
}

#[cfg(test)]
mod tests {
    use super::component_points;
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
    fn one_point_per_connected_component() {
        let v = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [5.0, 0.0, 0.0],
            [6.0, 0.0, 0.0],
            [5.0, 1.0, 0.0],
            [9.0, 9.0, 9.0],
            // At the position of vertex 3: joins its triangle to the second.
            [5.0, 0.0, 0.0],
            [5.0, -1.0, 0.0],
            [4.0, -1.0, -0.0],
        ];
        let t = [[0, 1, 2], [3, 4, 5], [7, 8, 9]];
        assert_eq!(
            component_points(&v, &t),
            vec![[0.0, 0.0, 0.0], [5.0, 0.0, 0.0]],
            "two components; the unused vertex 6 is left out"
        );
        let apart = [[0, 1, 2], [3, 4, 5], [8, 9, 6]];
        assert_eq!(component_points(&v, &apart).len(), 3, "three apart");
        assert_eq!(
            component_points(&v, &[[0, 1, 2], [0, 1, 99]]),
            vec![[0.0, 0.0, 0.0]],
            "an index out of range is skipped"
        );
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
