//! **Test support** (the `testkit` feature): shared hard-case generators for
//! property tests, fuzzing and benchmarks, the time-of-impact ground truth
//! and the Table 1 scenes. Not part of the engine API; its items may change
//! with the tests.
//!
//! A [`CaseSpec`] is a plain description (numbers and small enums) of a body,
//! a motion and a direction, biased towards the cases where bounds break:
//! sweeps within a few ulps of pi and 2 pi, tiny and huge `|w|`, `n` within a
//! few ulps of parallel to `w`, vertices on the axis, bodies far from the
//! origin with small extent. Property tests generate it with proptest
//! (`tests/common`), the fuzzer with `arbitrary` (`fuzz/`); both turn it into
//! a [`Case`] with [`CaseSpec::build`], so they explore the same space.

extern crate std;
use std::vec::Vec;

use crate::{Direction, Float, Point3, RigidMotion, TimeInterval, Vec3};

pub use crate::rng::SplitMix64;
pub use exact::triangles_intersect_exact;

mod exact;
pub mod ground_truth;
pub mod table1;
pub mod toi;

/// How the raw vertices are placed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "arbitrary", derive(arbitrary::Arbitrary))]
pub enum Layout {
    /// As given (a blob around the rotation centre).
    Blob,
    /// Every vertex moved onto the rotation axis (rotation moves none of them).
    OnAxis,
    /// Half the vertices on the axis, half as given.
    HalfOnAxis,
    /// Flattened into the rotation plane.
    InPlane,
    /// A small body far from the rotation centre (offset 10^6 body sizes).
    FarFromCentre,
    /// Only the first vertex.
    Single,
}

/// Where the swept angle `|w| (t_b - t_a)` lies.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "arbitrary", derive(arbitrary::Arbitrary))]
pub enum Sweep {
    /// `|x|` clamped to `[0, 20]` radians.
    Free(f64),
    /// `k pi` plus `ulps` units in the last place, `k` in `1..=4`.
    NearMultipleOfPi {
        /// The multiple of pi (taken modulo 4, plus 1).
        k: u8,
        /// The offset in ulps of `k pi` (clamped to `+-64`).
        ulps: i8,
    },
    /// Tiny: `10^-e` radians, `e` in `3..=15`.
    Tiny(u8),
}

/// How `n` relates to `w`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "arbitrary", derive(arbitrary::Arbitrary))]
pub enum Normal {
    /// Any direction (normalised from the raw vector).
    Free([f64; 3]),
    /// `w^` tilted by `ulps` units of `u` towards the raw vector.
    NearlyParallel {
        /// The raw tilt direction.
        towards: [f64; 3],
        /// The tilt in units of `2^-52` (clamped to `0..=64`).
        ulps: u8,
    },
    /// Exactly `+-w^` (as exactly as rounding allows).
    Parallel,
    /// Orthogonal to `w` (towards the raw vector's orthogonal part).
    Orthogonal([f64; 3]),
}

/// The body frame of a case: the body's points are given in the world
/// frame of the hard case, or in a body frame turned by a start orientation
/// (and with a rotation centre off the body origin), so that the bounds
/// must take `n` and `w` into the body frame.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "arbitrary", derive(arbitrary::Arbitrary))]
pub enum BodyFrame {
    /// The world frame: identity start orientation, rotation about the body
    /// origin.
    World,
    /// A start orientation from the raw quaternion `(w, x, y, z)` (the
    /// identity when it is zero or not finite).
    Oriented([f64; 4]),
    /// A start orientation and the rotation centre at the raw body point
    /// (clamped to `[-1, 1]`, times the body size).
    OrientedAbout([f64; 4], [f64; 3]),
}

/// A plain description of one test case.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "arbitrary", derive(arbitrary::Arbitrary))]
pub struct CaseSpec {
    /// Raw vertices (non-finite components become 0; clamped to `[-1, 1]`).
    pub vertices: Vec<[f64; 3]>,
    /// How the vertices are placed.
    pub layout: Layout,
    /// Body size `10^e` with `e` in `-12..=12` (from `i8`, clamped).
    pub size_exp: i8,
    /// Raw rotation axis.
    pub axis: [f64; 3],
    /// `|w| = 10^e` with `e` in `-12..=4` (clamped), times `1 + frac`.
    pub omega_exp: i8,
    /// Fractional mantissa of `|w|` (clamped to `[0, 1]`).
    pub omega_frac: f64,
    /// The swept angle.
    pub sweep: Sweep,
    /// Interval start, as a multiple of the interval length, in `[0, 4]`.
    pub start: f64,
    /// The direction.
    pub normal: Normal,
    /// Raw linear velocity (clamped to `[-1, 1]`), scaled by `|w|` times the size.
    pub linear: [f64; 3],
    /// Extra scale `10^e` of the linear velocity, `e` in `-6..=6`.
    pub linear_exp: i8,
    /// The body frame the points are given in.
    pub frame: BodyFrame,
}

/// A built case: vertices relative to the rotation centre, motion, direction.
#[derive(Clone, Debug)]
pub struct Case<T> {
    /// The body points.
    pub vertices: Vec<[T; 3]>,
    /// The motion (its interval is the arc to bound over).
    pub motion: RigidMotion<T>,
    /// The direction.
    pub n: Direction<T>,
}

fn finite_clamped(x: f64, lim: f64) -> f64 {
    if x.is_finite() {
        x.clamp(-lim, lim)
    } else {
        0.0
    }
}

fn raw(v: [f64; 3], lim: f64) -> [f64; 3] {
    [
        finite_clamped(v[0], lim),
        finite_clamped(v[1], lim),
        finite_clamped(v[2], lim),
    ]
}

fn unit_or(v: [f64; 3], fallback: [f64; 3]) -> [f64; 3] {
    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if l > 1e-6 {
        [v[0] / l, v[1] / l, v[2] / l]
    } else {
        fallback
    }
}

fn sub3(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn scale3(a: [f64; 3], s: f64) -> [f64; 3] {
    [a[0] * s, a[1] * s, a[2] * s]
}

fn dot3(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

impl CaseSpec {
    /// The case in precision `T`, or `None` when the description yields no
    /// valid input (which a sanitised spec never does in practice).
    #[must_use]
    pub fn build<T: Float>(&self) -> Option<Case<T>> {
        let axis = unit_or(raw(self.axis, 1.0), [0.0, 0.0, 1.0]);
        let omega = 10f64.powi(i32::from(self.omega_exp.clamp(-12, 4)))
            * (1.0 + finite_clamped(self.omega_frac, 1.0).abs());
        let size = 10f64.powi(i32::from(self.size_exp.clamp(-12, 12)));

        let sweep = match self.sweep {
            Sweep::Free(x) => finite_clamped(x, 20.0).abs(),
            Sweep::NearMultipleOfPi { k, ulps } => {
                let base = f64::from(k % 4 + 1) * core::f64::consts::PI;
                let ulp = base * f64::EPSILON;
                (base + f64::from(ulps.clamp(-64, 64)) * ulp).max(0.0)
            }
            Sweep::Tiny(e) => 10f64.powi(-i32::from(e % 13 + 3)),
        };
        let len = sweep / omega;
        let start = finite_clamped(self.start, 4.0).abs() * len;

        let mut pts: Vec<[f64; 3]> = self.vertices.iter().map(|v| raw(*v, 1.0)).collect();
        if pts.is_empty() {
            pts.push([1.0, 0.0, 0.0]);
        }
        let onto_axis = |p: [f64; 3]| scale3(axis, dot3(p, axis));
        let in_plane = |p: [f64; 3]| sub3(p, onto_axis(p));
        match self.layout {
            Layout::Blob => {}
            Layout::OnAxis => pts.iter_mut().for_each(|p| *p = onto_axis(*p)),
            Layout::HalfOnAxis => pts.iter_mut().step_by(2).for_each(|p| *p = onto_axis(*p)),
            Layout::InPlane => pts.iter_mut().for_each(|p| *p = in_plane(*p)),
            Layout::FarFromCentre => {
                let off = unit_or(
                    in_plane([axis[1] + 0.3, axis[2] - 0.7, axis[0] + 0.1]),
                    [1.0, 0.0, 0.0],
                );
                pts.iter_mut().for_each(|p| {
                    *p = [
                        p[0] * 1e-6 + off[0],
                        p[1] * 1e-6 + off[1],
                        p[2] * 1e-6 + off[2],
                    ]
                });
            }
            Layout::Single => pts.truncate(1),
        }
        let size = if matches!(self.layout, Layout::FarFromCentre) {
            size.max(1e-6)
        } else {
            size
        };

        let n = match self.normal {
            Normal::Free(v) => unit_or(raw(v, 1.0), [0.0, 1.0, 0.0]),
            Normal::Parallel => axis,
            Normal::NearlyParallel { towards, ulps } => {
                let t = unit_or(
                    in_plane(raw(towards, 1.0)),
                    unit_or(in_plane([1.0, 0.3, -0.2]), [1.0, 0.0, 0.0]),
                );
                let eps = f64::from(ulps.min(64)) * f64::EPSILON;
                unit_or(
                    [
                        axis[0] + eps * t[0],
                        axis[1] + eps * t[1],
                        axis[2] + eps * t[2],
                    ],
                    axis,
                )
            }
            Normal::Orthogonal(v) => unit_or(
                in_plane(raw(v, 1.0)),
                unit_or(in_plane([0.2, 1.0, 0.4]), [0.0, 1.0, 0.0]),
            ),
        };
        let lin_scale = omega * size * 10f64.powi(i32::from(self.linear_exp.clamp(-6, 6)));
        let v = scale3(raw(self.linear, 1.0), lin_scale);

        let cast = |p: [f64; 3]| p.map(T::from_f64);
        let interval = TimeInterval::try_new(T::from_f64(start), T::from_f64(start + len)).ok()?;
        let motion = RigidMotion::try_new(
            Point3::ORIGIN,
            Vec3::from_array(cast(v)),
            Vec3::from_array(cast(scale3(axis, omega))),
            interval,
        )
        .ok()?;
        // The hard case's points are world lever arms at the epoch; in a
        // turned body frame they are `Q0^T arm + c` (rounded: the case is
        // then within rounding of the hard one, and the oracle takes the
        // rounded points exactly).
        let (rotation, centre) = match self.frame {
            BodyFrame::World => (None, [0.0; 3]),
            BodyFrame::Oriented(q) => (Some(q), [0.0; 3]),
            BodyFrame::OrientedAbout(q, c) => (Some(q), scale3(raw(c, 1.0), size)),
        };
        let rotation = rotation.map(|q| {
            let q = q.map(|c| finite_clamped(c, 1.0));
            crate::Rotation::<T>::try_from_quaternion(
                T::from_f64(q[0]),
                T::from_f64(q[1]),
                T::from_f64(q[2]),
                T::from_f64(q[3]),
            )
            .unwrap_or(crate::Rotation::IDENTITY)
        });
        let vertices = pts
            .iter()
            .map(|p| {
                let arm = scale3(*p, size);
                match rotation {
                    None => cast(arm),
                    Some(r) => {
                        let m = r.matrix().map(|row| row.map(Float::to_f64));
                        let body = [0, 1, 2].map(|j| {
                            m[0][j] * arm[0] + m[1][j] * arm[1] + m[2][j] * arm[2] + centre[j]
                        });
                        cast(body)
                    }
                }
            })
            .collect();
        let motion = match rotation {
            None => motion,
            Some(r) => motion
                .with_orientation(r)
                .try_with_local_centre(Vec3::from_array(cast(centre)))
                .ok()?,
        };
        let n = Direction::try_new(Vec3::from_array(cast(n))).ok()?;
        Some(Case {
            vertices,
            motion,
            n,
        })
    }
}

/// `count` points on a unit-ish random blob, for benchmarks.
#[must_use]
pub fn random_blob<T: Float>(rng: &mut SplitMix64, count: usize) -> Vec<[T; 3]> {
    (0..count).map(|_| rng.vec3().map(T::from_f64)).collect()
}

/// The oriented box `BallTree` fits to a node's corners (`proofs/floating-point.md`,
/// "Oriented box"): its centre and its certified support about the centre
/// along each of `directions` (body frame, no rotation), for tests that
/// check containment with an independent computation.
#[must_use]
pub fn oriented_box_supports<T: Float>(
    points: &[[T; 3]],
    directions: &[[T; 3]],
) -> ([T; 3], Vec<T>) {
    let b = crate::bvh::OrientedBox::fit(points.iter());
    let s = directions
        .iter()
        .map(|&m| {
            b.support_up_with(
                Vec3::from_array(m),
                &crate::rounding::BoxError::new(T::ZERO, false),
            )
        })
        .collect();
    (b.centre, s)
}
