//! Torus-knot tubes, the seed's non-convex benchmark bodies.

use alloc::vec::Vec;
use core::f64::consts::PI;

use crate::bodies::{grid_size, positive, sweep_tube, SceneError};
use crate::{Float, TriMesh, Vec3};

/// A `(p, q)` torus knot swept by a circular tube.
///
/// The centre curve, for `t` in `[0, 2 pi)`, winds `p` times about the `z`
/// axis and `q` times around the torus core (the circle of radius `R` in the
/// `xy` plane):
///
/// ```text
/// c(t) = ((R + b cos qt) cos pt,  (R + b cos qt) sin pt,  b sin qt)
/// ```
///
/// with `R` the [`major_radius`](Self::major_radius) and `b` the
/// [`coil_radius`](Self::coil_radius); the tube has radius `a`, the
/// [`tube_radius`](Self::tube_radius). The knot fits in the cylinder of
/// radius `R + b + a` and height `2 (b + a)` about the origin, its centre of
/// symmetry and rotation centre. `(2, 3)` is the trefoil; `p` or `q` equal
/// to 1 gives an unknotted coil (the CGAL file `knot.off` is such a
/// `(1, 4)` coil, see [`TorusKnot::TREFOIL`]).
///
/// The generator does not check that the tube misses itself: that depends
/// on all five numbers (the defaults leave a clearance, tested).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TorusKnot {
    /// Turns about the `z` axis (at least 1, coprime to `q`).
    pub p: u32,
    /// Turns around the torus core (at least 1, coprime to `p`).
    pub q: u32,
    /// `R`: the radius of the torus core circle.
    pub major_radius: f64,
    /// `b`: the radius at which the curve winds around the core (below `R`).
    pub coil_radius: f64,
    /// `a`: the radius of the tube swept along the curve.
    pub tube_radius: f64,
}

/// The seed benchmark's torus-knot sizes: `N` segments along the curve by `M`
/// sides around the tube, `2 N M` triangles, all of the
/// [`TorusKnot::TREFOIL`] shape.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TorusKnotSize {
    /// 140 x 10: 1,400 vertices, 2,800 triangles.
    K2_8,
    /// 275 x 20: 5,500 vertices, 11,000 triangles.
    K11,
    /// 425 x 40: 17,000 vertices, 34,000 triangles.
    K34,
}

impl TorusKnotSize {
    /// Every size, smallest first.
    pub const ALL: [Self; 3] = [Self::K2_8, Self::K11, Self::K34];

    /// `N`, the segments along the curve.
    #[must_use]
    pub const fn segments(self) -> u32 {
        match self {
            Self::K2_8 => 140,
            Self::K11 => 275,
            Self::K34 => 425,
        }
    }

    /// `M`, the sides around the tube.
    #[must_use]
    pub const fn sides(self) -> u32 {
        match self {
            Self::K2_8 => 10,
            Self::K11 => 20,
            Self::K34 => 40,
        }
    }

    /// `2 N M`.
    #[must_use]
    pub const fn triangle_count(self) -> usize {
        2 * self.segments() as usize * self.sides() as usize
    }

    /// The trefoil mesh at this size.
    ///
    /// # Errors
    /// None in practice for `f32` and `f64` (the sizes and radii are valid);
    /// the `Result` is that of [`TorusKnot::mesh`].
    pub fn mesh<T: Float>(self) -> Result<TriMesh<T>, SceneError> {
        TorusKnot::TREFOIL.mesh(self.segments(), self.sides())
    }
}

impl TorusKnot {
    /// The default trefoil `(2, 3)`, `R = 0.287`, `b = 0.165`, `a = 0.076`,
    /// sized like CGAL's `knot.off` (shipped in `data/`). Measured at
    /// 140 x 10 against that file (`tests/meshes.rs`):
    ///
    /// | | CGAL `knot.off` | `TREFOIL` 140 x 10 | `CGAL_COIL` 140 x 10 |
    /// |---|---|---|---|
    /// | largest distance from the `z` axis | 0.5285 | 0.5276 | 0.5285 |
    /// | half-height | 0.2416 | 0.2408 | 0.2404 |
    /// | volume | 0.0824 | 0.0824 | 0.0825 |
    /// | area | 2.050 | 2.281 | 2.206 |
    ///
    /// The same cylinder and volume; the trefoil's curve is longer, so its
    /// tube is thinner and its area 11 % larger. The closest approach of two
    /// strands of the centre curve is about 0.21, so the tube (0.152 across)
    /// keeps clear of itself.
    ///
    /// CGAL's file is not a trefoil: each half-plane through its axis cuts it
    /// once and the plane `z = 0` eight times, so its curve winds once about
    /// the axis and four times around the core, a `(1, 4)` coil, which is
    /// unknotted. The trefoil is the usual torus-knot benchmark and really
    /// knotted; [`TorusKnot::CGAL_COIL`] gives the CGAL shape.
    pub const TREFOIL: Self = Self {
        p: 2,
        q: 3,
        major_radius: 0.287,
        coil_radius: 0.165,
        tube_radius: 0.076,
    };

    /// The `(1, 4)` coil `R = 0.29`, `b = 0.163`, `a = 0.079` fitted to CGAL's
    /// `knot.off`: extent and volume within 0.5 % (table at
    /// [`TREFOIL`](Self::TREFOIL)). Its area is still 7.6 % larger than the
    /// file's: CGAL's tube is not a circle swept along a torus-knot curve
    /// (its cross-sections are not circular), so no choice of the three radii
    /// matches it exactly.
    pub const CGAL_COIL: Self = Self {
        p: 1,
        q: 4,
        major_radius: 0.29,
        coil_radius: 0.163,
        tube_radius: 0.079,
    };

    /// The point `c(t)` of the centre curve.
    #[must_use]
    pub fn point(&self, t: f64) -> Vec3<f64> {
        let (p, q) = (f64::from(self.p), f64::from(self.q));
        let r = self.major_radius + self.coil_radius * cos(q * t);
        Vec3::new(
            r * cos(p * t),
            r * sin(p * t),
            self.coil_radius * sin(q * t),
        )
    }

    /// The derivative `c'(t)`, never zero when `b < R`.
    #[must_use]
    pub fn tangent(&self, t: f64) -> Vec3<f64> {
        let (p, q) = (f64::from(self.p), f64::from(self.q));
        let b = self.coil_radius;
        let r = self.major_radius + b * cos(q * t);
        let dr = -b * q * sin(q * t);
        Vec3::new(
            dr * cos(p * t) - r * p * sin(p * t),
            dr * sin(p * t) + r * p * cos(p * t),
            b * q * cos(q * t),
        )
    }

    fn validate(&self) -> Result<(), SceneError> {
        for (name, value) in [("p", self.p), ("q", self.q)] {
            if value == 0 {
                return Err(SceneError::Count { name, value });
            }
        }
        if gcd(self.p, self.q) != 1 {
            return Err(SceneError::NotCoprime {
                p: self.p,
                q: self.q,
            });
        }
        let big_r = positive(self.major_radius, "major_radius")?;
        let b = positive(self.coil_radius, "coil_radius")?;
        positive(self.tube_radius, "tube_radius")?;
        if b >= big_r {
            return Err(SceneError::Length {
                name: "coil_radius (must be below major_radius)",
            });
        }
        Ok(())
    }

    /// The tube mesh with `segments` rings of `sides` vertices:
    /// `segments x sides` vertices, `2 x segments x sides` triangles.
    ///
    /// Ring `i` sits at `c(2 pi i / N)`. Its frame is rotation-minimising
    /// (the double-reflection method of Wang, Jüttler, Zheng and Liu,
    /// "Computation of rotation minimizing frames", ACM TOG 27(1), 2008,
    /// [doi:10.1145/1330511.1330513](https://doi.org/10.1145/1330511.1330513)),
    /// so the tube does not twist the way a Frenet frame does near
    /// inflections; the angle by which the frame fails to close after one
    /// turn is spread evenly over the rings, so the last ring joins the
    /// first without a seam.
    ///
    /// # Errors
    /// [`SceneError::Count`] for `p` or `q` zero, fewer than 3 segments or
    /// sides, or more than `2^22` vertices; [`SceneError::NotCoprime`];
    /// [`SceneError::Length`] for radii that are not positive and finite or
    /// `coil_radius >= major_radius`; [`SceneError::Mesh`] if the knot is too
    /// large for `T`.
    pub fn mesh<T: Float>(&self, segments: u32, sides: u32) -> Result<TriMesh<T>, SceneError> {
        self.validate()?;
        grid_size(segments, sides)?;
        sweep_tube(&self.frames(segments), self.tube_radius, sides)
    }

    /// The ring centres and right-handed frames `(c_i, u_i, v_i)`, `u x v`
    /// the unit tangent, twist-corrected to close.
    fn frames(&self, n: u32) -> Vec<(Vec3<f64>, Vec3<f64>, Vec3<f64>)> {
        let param = |i: u32| 2.0 * PI * f64::from(i) / f64::from(n);
        let unit_tangent = |i: u32| {
            self.tangent(param(i))
                .normalize_or(Vec3::new(1.0, 0.0, 0.0))
        };
        let t0 = unit_tangent(0);
        let mut r = any_perpendicular(t0);
        let mut frames = Vec::with_capacity(n as usize);
        frames.push((self.point(0.0), t0, r));
        // Double reflection from ring i to ring i + 1; ring n is ring 0 again.
        for i in 0..n {
            let (x_i, t_i, _) = frames[frames.len() - 1];
            let x_next = self.point(param(i + 1));
            let t_next = unit_tangent(i + 1);
            let v1 = x_next - x_i;
            let c1 = v1.dot(v1);
            let (r_l, t_l) = if c1 > 0.0 {
                (
                    r - v1 * (2.0 / c1 * v1.dot(r)),
                    t_i - v1 * (2.0 / c1 * v1.dot(t_i)),
                )
            } else {
                (r, t_i)
            };
            let v2 = t_next - t_l;
            let c2 = v2.dot(v2);
            r = if c2 > 1e-300 {
                r_l - v2 * (2.0 / c2 * v2.dot(r_l))
            } else {
                r_l
            };
            // Keep r exactly perpendicular and unit despite rounding.
            r = (r - t_next * t_next.dot(r)).normalize_or(any_perpendicular(t_next));
            if i + 1 < n {
                frames.push((x_next, t_next, r));
            }
        }
        // `r` is now ring 0's propagated frame after a full turn: the angle
        // gamma from ring 0's own u to it, about t0, is spread over the rings.
        let (_, _, u0) = frames[0];
        let v0 = t0.cross(u0);
        let gamma = <f64 as Float>::atan2(r.dot(v0), r.dot(u0));
        frames
            .iter()
            .enumerate()
            .map(|(i, &(c, t, u))| {
                let v = t.cross(u);
                let beta = -gamma * (i as f64) / f64::from(n);
                let (s, co) = (sin(beta), cos(beta));
                (c, u * co + v * s, v * co - u * s)
            })
            .collect()
    }
}

/// The `(p, q)` torus-knot tube of [`TorusKnot`], the brief's flat signature:
/// `segments x sides` vertices, `2 x segments x sides` triangles.
///
/// # Errors
/// As [`TorusKnot::mesh`].
///
/// ```
/// use motion_bound::bodies::torus_knot;
/// let k = torus_knot::<f64>(3, 5, 300, 12, 1.0, 0.4, 0.1)?;
/// assert_eq!(k.triangle_count(), 2 * 300 * 12);
/// assert!(k.is_closed());
/// # Ok::<(), motion_bound::bodies::SceneError>(())
/// ```
pub fn torus_knot<T: Float>(
    p: u32,
    q: u32,
    segments: u32,
    sides: u32,
    major_radius: f64,
    coil_radius: f64,
    tube_radius: f64,
) -> Result<TriMesh<T>, SceneError> {
    TorusKnot {
        p,
        q,
        major_radius,
        coil_radius,
        tube_radius,
    }
    .mesh(segments, sides)
}

fn gcd(mut a: u32, mut b: u32) -> u32 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// A unit vector perpendicular to the unit vector `t`.
fn any_perpendicular(t: Vec3<f64>) -> Vec3<f64> {
    // Cross with the axis least aligned with t.
    let axis = if t.x.abs() <= t.y.abs() && t.x.abs() <= t.z.abs() {
        Vec3::new(1.0, 0.0, 0.0)
    } else if t.y.abs() <= t.z.abs() {
        Vec3::new(0.0, 1.0, 0.0)
    } else {
        Vec3::new(0.0, 0.0, 1.0)
    };
    t.cross(axis).normalize_or(Vec3::new(0.0, 0.0, 1.0))
}

fn sin(x: f64) -> f64 {
    <f64 as Float>::sin(x)
}

fn cos(x: f64) -> f64 {
    <f64 as Float>::cos(x)
}

#[cfg(test)]
mod tests {
    use super::{TorusKnot, TorusKnotSize};
    use crate::bodies::checks::{assert_solid, euler};
    use crate::bodies::SceneError;
    use crate::Vec3;

    #[test]
    fn seed_sizes_are_closed_outward_tori() {
        for size in TorusKnotSize::ALL {
            let m = size.mesh::<f64>().unwrap();
            assert_solid(&m, size.triangle_count(), "trefoil");
            assert_eq!(euler(&m), 0, "a tube is a torus, genus 1");
            let m32 = size.mesh::<f32>().unwrap();
            assert_solid(&m32, size.triangle_count(), "trefoil f32");
        }
        assert_eq!(
            TorusKnotSize::ALL.map(TorusKnotSize::triangle_count),
            [2_800, 11_000, 34_000],
            "the seed's sizes"
        );
    }

    #[test]
    fn frames_close_and_stay_orthonormal() {
        for knot in [TorusKnot::TREFOIL, TorusKnot::CGAL_COIL] {
            let n = 140;
            let frames = knot.frames(n);
            for (i, &(c, u, v)) in frames.iter().enumerate() {
                let t = knot.tangent(2.0 * core::f64::consts::PI * i as f64 / f64::from(n));
                let t = t.try_normalize().unwrap();
                assert!(
                    (u.length() - 1.0).abs() < 1e-12 && (v.length() - 1.0).abs() < 1e-12,
                    "unit at {i}"
                );
                assert!(
                    (u.cross(v) - t).length() < 1e-12,
                    "right-handed, u x v = t at {i}"
                );
                assert!(c.is_finite(), "centre");
            }
            // The twist correction: ring n - 1's frame carried one more step is
            // ring 0's; successive frames turn by a small angle only.
            let (_, u_last, _) = frames[frames.len() - 1];
            let (_, u0, _) = frames[0];
            assert!(
                u_last.dot(u0) > 0.8,
                "seam without a jump: {}",
                u_last.dot(u0)
            );
            for w in frames.windows(2) {
                assert!(w[0].1.dot(w[1].1) > 0.8, "no twist between rings");
            }
        }
    }

    #[test]
    fn the_default_tube_keeps_clear_of_itself() {
        // Sample the centre curve; two samples far apart along the curve must
        // be more than a tube diameter apart.
        let k = TorusKnot::TREFOIL;
        let n = 2000;
        let pts: alloc::vec::Vec<Vec3<f64>> = (0..n)
            .map(|i| k.point(2.0 * core::f64::consts::PI * f64::from(i) / f64::from(n)))
            .collect();
        let mut closest = f64::INFINITY;
        for i in 0..n as usize {
            for j in i + 1..n as usize {
                // Skip neighbours on the same strand: less than 1/12 of the
                // parameter range apart (a quarter turn around the core).
                let gap = (j - i).min(n as usize - (j - i));
                if gap < n as usize / 12 {
                    continue;
                }
                closest = closest.min((pts[i] - pts[j]).length());
            }
        }
        assert!(
            closest > 2.0 * k.tube_radius * 1.3,
            "closest strands {closest} vs tube diameter {}",
            2.0 * k.tube_radius
        );
        assert!(
            (0.2..0.22).contains(&closest),
            "documented clearance: {closest}"
        );
    }

    #[test]
    fn bad_parameters_are_typed_errors() {
        let k = TorusKnot::TREFOIL;
        let err = |k: TorusKnot, n, m| k.mesh::<f64>(n, m).unwrap_err();
        assert_eq!(
            err(TorusKnot { p: 2, q: 4, ..k }, 100, 8),
            SceneError::NotCoprime { p: 2, q: 4 },
            "link"
        );
        assert!(
            matches!(
                err(TorusKnot { p: 0, ..k }, 100, 8),
                SceneError::Count { name: "p", .. }
            ),
            "p = 0"
        );
        assert!(
            matches!(
                err(k, 2, 8),
                SceneError::Count {
                    name: "segments",
                    ..
                }
            ),
            "segments"
        );
        assert!(
            matches!(err(k, 100, 2), SceneError::Count { name: "sides", .. }),
            "sides"
        );
        assert!(
            matches!(err(k, u32::MAX, u32::MAX), SceneError::Count { .. }),
            "huge"
        );
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(
                matches!(
                    err(
                        TorusKnot {
                            tube_radius: bad,
                            ..k
                        },
                        100,
                        8
                    ),
                    SceneError::Length { .. }
                ),
                "tube radius {bad}"
            );
        }
        assert!(
            matches!(
                err(
                    TorusKnot {
                        coil_radius: 0.5,
                        ..k
                    },
                    100,
                    8
                ),
                SceneError::Length { .. }
            ),
            "coil through the axis"
        );
        assert!(
            matches!(
                TorusKnot {
                    major_radius: 1e300,
                    coil_radius: 1e299,
                    ..k
                }
                .mesh::<f32>(10, 3),
                Err(SceneError::Mesh(_))
            ),
            "too large for f32"
        );
    }
}
