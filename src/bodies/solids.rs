//! Convex solids: boxes, thin boards, prisms and icospheres.

use alloc::collections::BTreeMap;
use alloc::vec::Vec;

use crate::bodies::{positive, to_t, SceneError, MAX_VERTICES};
use crate::{Float, TriMesh, Vec3};

/// The box `[-x/2, x/2] x [-y/2, y/2] x [-z/2, z/2]` for `size = [x, y, z]`:
/// 8 vertices, 12 triangles.
///
/// # Errors
/// [`SceneError::Length`] for a size that is not positive and finite;
/// [`SceneError::Mesh`] if it is too large for `T`.
///
/// ```
/// use motion_bound::bodies::cuboid;
/// let b = cuboid::<f64>([1.0, 2.0, 3.0])?;
/// assert!((b.signed_volume() - 6.0).abs() < 1e-12);
/// # Ok::<(), motion_bound::bodies::SceneError>(())
/// ```
pub fn cuboid<T: Float>(size: [f64; 3]) -> Result<TriMesh<T>, SceneError> {
    let h = [
        positive(size[0], "size x")? / 2.0,
        positive(size[1], "size y")? / 2.0,
        positive(size[2], "size z")? / 2.0,
    ];
    // Corner i has coordinate k at +h[k] when bit k of i is set.
    let vertices = (0..8u32)
        .map(|i| {
            let s = |k: u32| if i >> k & 1 == 1 { 1.0 } else { -1.0 };
            to_t(Vec3::new(s(0) * h[0], s(1) * h[1], s(2) * h[2]))
        })
        .collect();
    // Two triangles per face, counter-clockwise seen from outside.
    let triangles = alloc::vec![
        [0, 2, 3],
        [0, 3, 1], // -z
        [4, 5, 7],
        [4, 7, 6], // +z
        [0, 1, 5],
        [0, 5, 4], // -y
        [2, 6, 7],
        [2, 7, 3], // +y
        [0, 4, 6],
        [0, 6, 2], // -x
        [1, 3, 7],
        [1, 7, 5], // +x
    ];
    Ok(TriMesh::try_new(vertices, triangles)?)
}

/// A thin board: [`cuboid`] `[width, height, thickness]`, lying in the `xy`
/// plane with its thickness along `z`; 12 triangles. The seed's scenes drop
/// bodies onto such boards.
///
/// # Errors
/// As [`cuboid`].
pub fn board<T: Float>(width: f64, height: f64, thickness: f64) -> Result<TriMesh<T>, SceneError> {
    cuboid([width, height, thickness])
}

/// The same thin board as [`board`], its two large faces cut into
/// `cells x cells` grids of squares (two triangles each) and its rim into
/// strips: `4 cells^2 + 8 cells` triangles, all small. The same solid as
/// [`board`], for comparing a mesh of a few large triangles with a fine one.
///
/// # Errors
/// As [`cuboid`], and [`SceneError::Count`] for no cell or more than 1,024
/// cells a side.
///
/// ```
/// use motion_bound::bodies::tessellated_board;
/// let b = tessellated_board::<f64>(2.0, 2.0, 0.002, 8)?;
/// assert_eq!(b.triangle_count(), 4 * 64 + 8 * 8);
/// assert!((b.signed_volume() - 2.0 * 2.0 * 0.002).abs() < 1e-12);
/// # Ok::<(), motion_bound::bodies::SceneError>(())
/// ```
pub fn tessellated_board<T: Float>(
    width: f64,
    height: f64,
    thickness: f64,
    cells: u32,
) -> Result<TriMesh<T>, SceneError> {
    let (w, h, z) = (
        positive(width, "width")?,
        positive(height, "height")?,
        positive(thickness, "thickness")? / 2.0,
    );
    if cells == 0 || cells > 1024 {
        return Err(SceneError::Count {
            name: "cells",
            value: cells,
        });
    }
    let side_len = (cells + 1) * (cells + 1);
    let idx = |side: u32, i: u32, j: u32| side * side_len + i * (cells + 1) + j;
    let mut vertices = Vec::with_capacity(2 * side_len as usize);
    let mut triangles = Vec::with_capacity((4 * cells * cells + 8 * cells) as usize);
    for (side, zs) in [(0, z), (1, -z)] {
        for i in 0..=cells {
            for j in 0..=cells {
                let x = w * (f64::from(i) / f64::from(cells) - 0.5);
                let y = h * (f64::from(j) / f64::from(cells) - 0.5);
                vertices.push(to_t(Vec3::new(x, y, zs)));
            }
        }
        for i in 0..cells {
            for j in 0..cells {
                let (a, b, c, d) = (
                    idx(side, i, j),
                    idx(side, i + 1, j),
                    idx(side, i + 1, j + 1),
                    idx(side, i, j + 1),
                );
                if side == 0 {
                    triangles.push([a, b, c]);
                    triangles.push([a, c, d]);
                } else {
                    triangles.push([a, c, b]);
                    triangles.push([a, d, c]);
                }
            }
        }
    }
    // The rim: walk the grid's boundary counter-clockwise, joining top to bottom.
    let mut rim = Vec::with_capacity(4 * cells as usize);
    rim.extend((0..cells).map(|j| (0, j)));
    rim.extend((0..cells).map(|i| (i, cells)));
    rim.extend((1..=cells).rev().map(|j| (cells, j)));
    rim.extend((1..=cells).rev().map(|i| (i, 0)));
    for k in 0..rim.len() {
        let (p, q) = (rim[k], rim[(k + 1) % rim.len()]);
        let (a, b) = (idx(0, p.0, p.1), idx(0, q.0, q.1));
        let (c, d) = (idx(1, p.0, p.1), idx(1, q.0, q.1));
        triangles.push([a, d, c]);
        triangles.push([a, b, d]);
    }
    Ok(TriMesh::try_new(vertices, triangles)?)
}

/// The geodesic sphere of `radius` about the origin: an icosahedron whose
/// triangles are split in four `subdivisions` times, new vertices pushed out
/// to the sphere; `20 x 4^s` triangles, `10 x 4^s + 2` vertices.
///
/// # Errors
/// [`SceneError::Count`] for more than 7 subdivisions (327,680 triangles);
/// [`SceneError::Length`] for a radius that is not positive and finite;
/// [`SceneError::Mesh`] if it is too large for `T`.
///
/// ```
/// use motion_bound::bodies::icosphere;
/// let s = icosphere::<f32>(2.0, 3)?;
/// assert_eq!((s.vertex_count(), s.triangle_count()), (642, 1280));
/// # Ok::<(), motion_bound::bodies::SceneError>(())
/// ```
pub fn icosphere<T: Float>(radius: f64, subdivisions: u32) -> Result<TriMesh<T>, SceneError> {
    let radius = positive(radius, "radius")?;
    if subdivisions > 7 {
        return Err(SceneError::Count {
            name: "subdivisions",
            value: subdivisions,
        });
    }
    let g = (1.0 + <f64 as Float>::sqrt(5.0)) / 2.0;
    let mut points: Vec<Vec3<f64>> = [
        [-1.0, g, 0.0],
        [1.0, g, 0.0],
        [-1.0, -g, 0.0],
        [1.0, -g, 0.0],
        [0.0, -1.0, g],
        [0.0, 1.0, g],
        [0.0, -1.0, -g],
        [0.0, 1.0, -g],
        [g, 0.0, -1.0],
        [g, 0.0, 1.0],
        [-g, 0.0, -1.0],
        [-g, 0.0, 1.0],
    ]
    .iter()
    .map(|&p| unit(Vec3::from_array(p)))
    .collect();
    let mut faces: Vec<[u32; 3]> = alloc::vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..subdivisions {
        let mut midpoints: BTreeMap<(u32, u32), u32> = BTreeMap::new();
        let mut mid = |a: u32, b: u32, points: &mut Vec<Vec3<f64>>| -> u32 {
            *midpoints.entry((a.min(b), a.max(b))).or_insert_with(|| {
                let m = unit(points[a as usize] + points[b as usize]);
                points.push(m);
                // At most 10 x 4^7 + 2 points: fits in u32.
                (points.len() - 1) as u32
            })
        };
        let mut next = Vec::with_capacity(4 * faces.len());
        for &[a, b, c] in &faces {
            let ab = mid(a, b, &mut points);
            let bc = mid(b, c, &mut points);
            let ca = mid(c, a, &mut points);
            next.extend_from_slice(&[[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
        }
        faces = next;
    }
    let vertices = points.iter().map(|&p| to_t(p * radius)).collect();
    Ok(TriMesh::try_new(vertices, faces)?)
}

/// The right prism with `sides` sides inscribed in the cylinder of `radius`
/// about the `z` axis, `length` long and centred on the origin, its sides cut
/// into `segments` rings of equal height and its two caps fanned from their
/// centres: `2 sides (segments + 1)` triangles, `sides (segments + 1) + 2`
/// vertices. With `segments = 1` it is the coarse prism a CAD or URDF file
/// gives (48 triangles for 12 sides); more segments give the same solid in
/// smaller triangles (a pole on a ring every few centimetres).
///
/// # Errors
/// [`SceneError::Length`] for a radius or length that is not positive and
/// finite; [`SceneError::Count`] for fewer than 3 sides, no segment, or more
/// than `2^22` vertices; [`SceneError::Mesh`] if it is too large for `T`.
///
/// ```
/// use motion_bound::bodies::prism;
/// let coarse = prism::<f64>(0.02, 1.0, 12, 1)?;
/// let rings = prism::<f64>(0.02, 1.0, 12, 25)?;
/// assert_eq!((coarse.triangle_count(), rings.triangle_count()), (48, 624));
/// assert!((coarse.signed_volume() - rings.signed_volume()).abs() < 1e-15);
/// # Ok::<(), motion_bound::bodies::SceneError>(())
/// ```
pub fn prism<T: Float>(
    radius: f64,
    length: f64,
    sides: u32,
    segments: u32,
) -> Result<TriMesh<T>, SceneError> {
    let (r, h) = (
        positive(radius, "radius")?,
        positive(length, "length")? / 2.0,
    );
    if sides < 3 {
        return Err(SceneError::Count {
            name: "sides",
            value: sides,
        });
    }
    if segments == 0 {
        return Err(SceneError::Count {
            name: "segments",
            value: segments,
        });
    }
    let ring = segments
        .checked_add(1)
        .and_then(|n| n.checked_mul(sides))
        .filter(|&n| n < MAX_VERTICES)
        .ok_or(SceneError::Count {
            name: "sides x (segments + 1)",
            value: sides.saturating_mul(segments.saturating_add(1)),
        })?;
    let mut vertices = Vec::with_capacity(ring as usize + 2);
    for i in 0..=segments {
        let z = -h + 2.0 * h * f64::from(i) / f64::from(segments);
        for k in 0..sides {
            let a = core::f64::consts::TAU * f64::from(k) / f64::from(sides);
            vertices.push(to_t(Vec3::new(
                r * <f64 as Float>::cos(a),
                r * <f64 as Float>::sin(a),
                z,
            )));
        }
    }
    vertices.push(to_t(Vec3::new(0.0, 0.0, -h)));
    vertices.push(to_t(Vec3::new(0.0, 0.0, h)));
    let (bottom, top) = (ring, ring + 1);
    let at = |i: u32, k: u32| i * sides + k % sides;
    let mut triangles = Vec::with_capacity(2 * (sides * (segments + 1)) as usize);
    for i in 0..segments {
        for k in 0..sides {
            // Counter-clockwise seen from outside: the tangent (k to k + 1)
            // crossed with the axis (i to i + 1) points outward.
            let (a, b, c, d) = (at(i, k), at(i, k + 1), at(i + 1, k + 1), at(i + 1, k));
            triangles.push([a, b, c]);
            triangles.push([a, c, d]);
        }
    }
    for k in 0..sides {
        triangles.push([bottom, at(0, k + 1), at(0, k)]);
        triangles.push([top, at(segments, k), at(segments, k + 1)]);
    }
    Ok(TriMesh::try_new(vertices, triangles)?)
}

fn unit(p: Vec3<f64>) -> Vec3<f64> {
    p.normalize_or(Vec3::new(0.0, 0.0, 1.0))
}

#[cfg(test)]
mod tests {
    use super::{board, cuboid, icosphere, prism};
    use crate::bodies::checks::{assert_solid, euler};
    use crate::bodies::SceneError;

    #[test]
    fn convex_solids_are_closed_outward_spheres() {
        let b = board::<f32>(2.0, 1.0, 0.02).unwrap();
        assert_solid(&b, 12, "board");
        assert_eq!(euler(&b), 2, "genus 0");
        assert!((b.signed_volume() - 0.04).abs() < 1e-7, "board volume");
        for s in 0..=4 {
            let ico = icosphere::<f64>(1.5, s).unwrap();
            assert_solid(&ico, 20 * 4usize.pow(s), "icosphere");
            assert_eq!(euler(&ico), 2, "genus 0");
            assert_eq!(ico.vertex_count(), 10 * 4usize.pow(s) + 2, "vertices");
            for v in ico.vertices() {
                let r = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
                assert!((r - 1.5).abs() < 1e-14, "on the sphere");
            }
        }
        for (sides, segments) in [(3, 1), (12, 1), (12, 25), (7, 3)] {
            let p = prism::<f64>(0.5, 2.0, sides, segments).unwrap();
            let n = sides as usize;
            assert_solid(&p, 2 * n * (segments as usize + 1), "prism");
            assert_eq!(euler(&p), 2, "genus 0");
            // The inscribed polygon's area times the length.
            let a = n as f64 / 2.0 * 0.25 * (core::f64::consts::TAU / n as f64).sin();
            assert!((p.signed_volume() - 2.0 * a).abs() < 1e-12, "prism volume");
        }
        assert!(
            matches!(prism::<f64>(1.0, 1.0, 2, 1), Err(SceneError::Count { .. })),
            "two sides"
        );
        assert!(
            matches!(
                prism::<f64>(1.0, -1.0, 6, 1),
                Err(SceneError::Length { .. })
            ),
            "negative length"
        );
        assert!(
            matches!(icosphere::<f64>(1.0, 8), Err(SceneError::Count { .. })),
            "too fine"
        );
        assert!(
            matches!(
                cuboid::<f64>([1.0, 0.0, 1.0]),
                Err(SceneError::Length { .. })
            ),
            "flat box"
        );
    }
}
