//! Tori (rings).

use alloc::vec::Vec;
use core::f64::consts::PI;

use crate::bodies::{grid_size, positive, sweep_tube, SceneError};
use crate::{Float, TriMesh, Vec3};

/// A torus about the `z` axis, centred at the origin: the circle of radius
/// `minor_radius` swept around the circle of radius `major_radius` in the
/// `xy` plane, with `rings` circles of `sides` vertices; `rings x sides`
/// vertices and `2 x rings x sides` triangles.
///
/// # Errors
/// [`SceneError::Count`] for fewer than 3 rings or sides or more than `2^22`
/// vertices; [`SceneError::Length`] for radii that are not positive and
/// finite or `minor_radius >= major_radius` (a self-intersecting torus);
/// [`SceneError::Mesh`] if it is too large for `T`.
///
/// ```
/// use motion_bound::bodies::torus;
/// let ring = torus::<f64>(1.0, 0.25, 48, 16)?;
/// assert_eq!(ring.triangle_count(), 2 * 48 * 16);
/// // Volume 2 pi^2 R r^2, approached from below by the inscribed polyhedron.
/// let exact = 2.0 * std::f64::consts::PI.powi(2) * 1.0 * 0.25f64.powi(2);
/// assert!(ring.signed_volume() < exact && ring.signed_volume() > 0.97 * exact);
/// # Ok::<(), motion_bound::bodies::SceneError>(())
/// ```
pub fn torus<T: Float>(
    major_radius: f64,
    minor_radius: f64,
    rings: u32,
    sides: u32,
) -> Result<TriMesh<T>, SceneError> {
    let big_r = positive(major_radius, "major_radius")?;
    let r = positive(minor_radius, "minor_radius")?;
    if r >= big_r {
        return Err(SceneError::Length {
            name: "minor_radius (must be below major_radius)",
        });
    }
    grid_size(rings, sides)?;
    // Travel along +phi (t = e_phi); u = e_r outward, v = t x u = -e_z.
    let frames: Vec<_> = (0..rings)
        .map(|i| {
            let phi = 2.0 * PI * f64::from(i) / f64::from(rings);
            let (s, c) = (<f64 as Float>::sin(phi), <f64 as Float>::cos(phi));
            let e_r = Vec3::new(c, s, 0.0);
            (e_r * big_r, e_r, Vec3::new(0.0, 0.0, -1.0))
        })
        .collect();
    sweep_tube(&frames, r, sides)
}

#[cfg(test)]
mod tests {
    use super::torus;
    use crate::bodies::checks::{assert_solid, euler};
    use crate::bodies::SceneError;

    #[test]
    fn tori_are_closed_outward_genus_one() {
        for (n, m) in [(3, 3), (4, 7), (64, 24)] {
            let t = torus::<f32>(2.0, 0.5, n, m).unwrap();
            assert_solid(&t, 2 * (n * m) as usize, "torus");
            assert_eq!(euler(&t), 0, "genus 1");
        }
        assert!(
            matches!(torus::<f64>(1.0, 1.0, 8, 8), Err(SceneError::Length { .. })),
            "horn torus"
        );
    }
}
