//! Test and benchmark bodies built in code: torus knots at the seed's sizes,
//! tori, thin boards, boxes, prisms and icospheres.
//!
//! Every generator returns a [`TriMesh`] that is closed (every edge shared by
//! two triangles running along it in opposite directions), wound outward
//! (counter-clockwise seen from outside, positive
//! [`signed_volume`](TriMesh::signed_volume)), free of degenerate triangles,
//! and centred on its rotation centre: the origin is the centre of symmetry
//! of the shape, so the vertices are already the body points the bounds
//! expect. Parameters are `f64`; the mesh is computed in `f64` and rounded
//! to `T`.
//!
//! ```
//! use motion_bound::bodies::{board, TorusKnotSize};
//!
//! let knot = TorusKnotSize::K2_8.mesh::<f32>()?;
//! assert_eq!(knot.triangle_count(), 2_800);
//! assert!(knot.is_closed() && knot.signed_volume() > 0.0);
//!
//! let plank = board::<f64>(2.0, 1.0, 0.05)?;
//! assert_eq!(plank.triangle_count(), 12);
//! # Ok::<(), motion_bound::bodies::SceneError>(())
//! ```

mod error;
mod knot;
mod solids;
mod torus;

pub use error::SceneError;
pub use knot::{torus_knot, TorusKnot, TorusKnotSize};
pub use solids::{board, cuboid, icosphere, prism, tessellated_board};
pub use torus::torus;

use alloc::vec::Vec;

use crate::{Float, TriMesh, Vec3};

/// The most vertices a generator makes (`2^22`, about 100 MB as `f64`
/// vertices plus triangles): a bound on what a mistyped count can allocate.
pub(crate) const MAX_VERTICES: u32 = 1 << 22;

/// A positive, finite length, or `SceneError::Length` naming it.
pub(crate) fn positive(x: f64, name: &'static str) -> Result<f64, SceneError> {
    if x > 0.0 && x.is_finite() {
        Ok(x)
    } else {
        Err(SceneError::Length { name })
    }
}

/// `rings * sides` when each is at least 3 and the product at most
/// [`MAX_VERTICES`].
pub(crate) fn grid_size(rings: u32, sides: u32) -> Result<u32, SceneError> {
    if rings < 3 {
        return Err(SceneError::Count {
            name: "segments",
            value: rings,
        });
    }
    if sides < 3 {
        return Err(SceneError::Count {
            name: "sides",
            value: sides,
        });
    }
    rings
        .checked_mul(sides)
        .filter(|&n| n <= MAX_VERTICES)
        .ok_or(SceneError::Count {
            name: "segments x sides",
            value: rings.saturating_mul(sides),
        })
}

/// A closed tube: around each ring centre `c_i` with right-handed frame
/// `(t_i, u_i, v_i)` (`u x v = t`, `t` the direction of travel), the circle
/// `c_i + radius (cos theta_j u_i + sin theta_j v_i)`, and the last ring
/// joined to the first. `2 N M` triangles, outward because
/// `d/dtheta x t` points away from the centre.
pub(crate) fn sweep_tube<T: Float>(
    rings: &[(Vec3<f64>, Vec3<f64>, Vec3<f64>)],
    radius: f64,
    sides: u32,
) -> Result<TriMesh<T>, SceneError> {
    let n = u32::try_from(rings.len()).map_err(|_| SceneError::Count {
        name: "segments",
        value: u32::MAX,
    })?;
    let m = sides;
    grid_size(n, m)?;
    let mut vertices = Vec::with_capacity((n * m) as usize);
    for &(c, u, v) in rings {
        for j in 0..m {
            let theta = 2.0 * core::f64::consts::PI * f64::from(j) / f64::from(m);
            let p = c + (u * theta.cos() + v * theta.sin()) * radius;
            vertices.push(to_t::<T>(p));
        }
    }
    let mut triangles = Vec::with_capacity(2 * (n * m) as usize);
    for i in 0..n {
        let i1 = (i + 1) % n;
        for j in 0..m {
            let j1 = (j + 1) % m;
            let (a00, a01, a10, a11) = (i * m + j, i * m + j1, i1 * m + j, i1 * m + j1);
            triangles.push([a00, a01, a11]);
            triangles.push([a00, a11, a10]);
        }
    }
    Ok(TriMesh::try_new(vertices, triangles)?)
}

/// A point rounded to `T`.
#[inline]
pub(crate) fn to_t<T: Float>(p: Vec3<f64>) -> [T; 3] {
    [T::from_f64(p.x), T::from_f64(p.y), T::from_f64(p.z)]
}

#[cfg(test)]
pub(crate) mod checks {
    //! The properties every generated mesh must have.
    use crate::{Float, TriMesh};

    /// Closed, outward, no degenerate triangle, the expected counts.
    pub(crate) fn assert_solid<T: Float>(m: &TriMesh<T>, triangles: usize, what: &str) {
        assert_eq!(m.triangle_count(), triangles, "{what}: triangle count");
        let r = m.edge_report();
        assert!(r.is_closed(), "{what}: not closed: {r:?}");
        assert!(m.signed_volume() > 0.0, "{what}: not outward");
        for (i, [a, b, c]) in m.triangle_corners().enumerate() {
            let u = [0, 1, 2].map(|k| b[k].to_f64() - a[k].to_f64());
            let v = [0, 1, 2].map(|k| c[k].to_f64() - a[k].to_f64());
            let n = [
                u[1] * v[2] - u[2] * v[1],
                u[2] * v[0] - u[0] * v[2],
                u[0] * v[1] - u[1] * v[0],
            ];
            let area2 = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            let scale = u.iter().chain(&v).map(|x| x * x).sum::<f64>();
            assert!(
                area2 > 1e-6 * scale,
                "{what}: triangle {i} is degenerate (2 area {area2}, squared edges {scale})"
            );
        }
    }

    /// `V - E + F` over the used vertices.
    pub(crate) fn euler<T: Float>(m: &TriMesh<T>) -> i64 {
        let r = m.edge_report();
        m.vertex_count() as i64 - r.edges as i64 + m.triangle_count() as i64
    }
}
