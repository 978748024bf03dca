//! Closed convex meshes: a mesh whose triangles are the whole boundary of
//! the convex hull of its vertices, decided exactly when its tree is built
//! (`proofs/12-shapes.md`, Lemma 12.9). A body that does not overlap the
//! inside of that hull is as far from the triangles as from the hull, so a
//! mesh stepper may measure it against the hull, a polytope
//! ([`MeshConvexPair`](crate::ca::MeshConvexPair)).

use alloc::vec::Vec;

use crate::geometry::predicates::{orient3d, points_in_exact_range};
use crate::mesh::topology::edge_report_of;
use crate::{Float, Vec3};

/// The most distinct vertices a mesh may have for its hull to be kept: the
/// check is `O(F V)` exact orientations, and the hull's support a scan of
/// its vertices (a choice of speed only: a larger mesh keeps its tree).
pub(crate) const MAX_HULL_VERTICES: usize = 64;

/// The vertices of the triangles, once each, when the mesh is closed and
/// convex: every directed edge once and its reverse once, no triangle
/// repeating an index ([`EdgeReport::is_closed`](crate::EdgeReport::is_closed)),
/// and one sign `s` such that every vertex `v` lies on the side `s` of every
/// triangle `(a, b, c)` or on its plane (`orient3d(a, b, c, v)` is `s` or
/// `0`), with some vertex strictly off each triangle's plane. Every sign is
/// exact (the vertices must be 0 or of magnitude within the predicates'
/// exact range). `None` otherwise, or with more than
/// [`MAX_HULL_VERTICES`] vertices.
pub(crate) fn closed_convex_vertices<T: Float>(
    vertices: &[[T; 3]],
    triangles: &[[u32; 3]],
) -> Option<Vec<[T; 3]>> {
    if triangles.is_empty() || !edge_report_of(triangles).is_closed() {
        return None;
    }
    let mut used: Vec<u32> = triangles.iter().flatten().copied().collect();
    used.sort_unstable();
    used.dedup();
    if used.len() > MAX_HULL_VERTICES {
        return None;
    }
    let points = used
        .iter()
        .map(|&i| vertices.get(i as usize).map(|v| Vec3::from_array(*v)))
        .collect::<Option<Vec<_>>>()?;
    if !points_in_exact_range(&points) {
        return None;
    }
    let corner = |i: u32| Vec3::from_array(vertices[i as usize]);
    let mut side = 0i8;
    for &[a, b, c] in triangles {
        let (a, b, c) = (corner(a), corner(b), corner(c));
        let mut strict = false;
        for &v in &points {
            let s = orient3d(a, b, c, v).sign;
            if s == 0 {
                continue;
            }
            if side == 0 {
                side = s;
            } else if s != side {
                return None;
            }
            strict = true;
        }
        if !strict {
            return None;
        }
    }
    Some(points.iter().map(|p| p.to_array()).collect())
}

#[cfg(test)]
mod tests {
    use super::closed_convex_vertices;
    use alloc::vec::Vec;

    fn cube() -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
        let v = (0..8)
            .map(|k| [0, 1, 2].map(|i| if k >> i & 1 == 1 { 1.0 } else { -1.0 }))
            .collect();
        let t = crate::mesh::BOX_TRIANGLES.to_vec();
        (v, t)
    }

    /// A cube, either way round, is closed and convex; with one triangle
    /// flipped, one missing, a corner pushed in (a dent), or flattened onto
    /// a plane, it is not.
    #[test]
    fn cubes_are_closed_and_convex_and_their_defects_are_not() {
        let (v, t) = cube();
        assert_eq!(closed_convex_vertices(&v, &t).map(|h| h.len()), Some(8));
        let inward: Vec<[u32; 3]> = t.iter().map(|&[a, b, c]| [a, c, b]).collect();
        assert!(closed_convex_vertices(&v, &inward).is_some(), "inward");
        let mut flipped = t.clone();
        flipped[3] = [flipped[3][0], flipped[3][2], flipped[3][1]];
        assert!(closed_convex_vertices(&v, &flipped).is_none(), "flipped");
        assert!(closed_convex_vertices(&v, &t[1..]).is_none(), "open");
        let mut dented = v.clone();
        dented[7] = [0.2, 0.2, 0.2];
        assert!(closed_convex_vertices(&dented, &t).is_none(), "dented");
        let flat: Vec<[f64; 3]> = v.iter().map(|p| [p[0], p[1], 0.0]).collect();
        assert!(closed_convex_vertices(&flat, &t).is_none(), "flat");
        // A corner pushed out by one ulp past a face's plane.
        let mut bulged = v.clone();
        bulged[7][0] = 1.0 + f64::EPSILON;
        assert!(
            closed_convex_vertices(&bulged, &t).is_none(),
            "bulged by an ulp"
        );
        // Two triangles back to back: closed, but flat.
        let two = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
        assert!(closed_convex_vertices(&two, &[[0, 1, 2], [0, 2, 1]]).is_none());
    }
}
