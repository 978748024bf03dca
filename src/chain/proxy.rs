//! What a still obstacle is in the rake's `f32` lanes: a *proxy*, a
//! function `phi` computed in `f32` that is at most zero on every point of
//! the obstacle and `lambda`-Lipschitz, so that `phi(x) / lambda` is a lower
//! bound of `x`'s distance from the obstacle (`proofs/13-chains.md`, Lemma
//! 13.12). Boxes (cuboids, mesh obstacles, cones by their boxes), balls,
//! capsules, cylinders, half-spaces and sets of balls (a point cloud's top
//! nodes); each built once when the obstacle is made, certified to hold it
//! with the rounding of its numbers to `f32`.

// Lane loops index fixed-size arrays by lane: the form the compiler turns
// into SIMD. A gap compared as `!(g > tau)` fails a NaN gap, as it must.
#![allow(clippy::needless_range_loop, clippy::neg_cmp_op_on_partial_ord)]

use alloc::vec::Vec;

use crate::chain::cover::up32;
use crate::chain::lanes::{Lane, LANES};
use crate::{Float, Pose, Vec3};

/// A proxy's shape in `f32`.
#[derive(Clone, Debug)]
pub(crate) enum Kind {
    /// `{x : |u_k . (x - c)| <= h_k}` grown by `r` (rows `u_k`).
    Box {
        c: [f32; 3],
        u: [[f32; 3]; 3],
        h: [f32; 3],
        r: f32,
    },
    /// The ball of centre `c` and radius `r`.
    Ball { c: [f32; 3], r: f32 },
    /// The segment from `a` to `b` grown by `r`.
    Capsule { a: [f32; 3], b: [f32; 3], r: f32 },
    /// `{x : y = U (x - c), y_0^2 + y_2^2 <= radius^2, |y_1| <= half}` grown by `r`.
    Cylinder {
        c: [f32; 3],
        u: [[f32; 3]; 3],
        half: f32,
        radius: f32,
        r: f32,
    },
    /// `{x : m . x <= b}`; near the origin (see [`Proxy::tilt`]).
    Plane { m: [f32; 3], b: f32 },
    /// A union of balls `(c, r)`.
    Balls(Vec<[f32; 4]>),
}

/// A still obstacle in `f32`, with what the gap test needs of it.
#[derive(Clone, Debug)]
pub(crate) struct Proxy {
    pub(crate) kind: Kind,
    /// The Lipschitz constant of `phi` (at least 1).
    pub(crate) lambda: f64,
    /// An upper bound of the proxy's own numbers (`|c|` plus extents and
    /// radii): with the link's reach, the scale of the rounding error.
    pub(crate) size: f64,
    /// For a half-space, `|m32 - m|`: `phi` is at most
    /// `tilt (2 R + |o|)` on the half-space's points within `2 R + |o|` of the
    /// origin, `R` the link's reach (Lemma 13.12); zero otherwise.
    pub(crate) tilt: f64,
    /// For a half-space, `|o|`.
    pub(crate) offset: f64,
}

fn f32v(v: [f64; 3]) -> [f32; 3] {
    v.map(|x| x as f32)
}

fn back(v: [f32; 3]) -> [f64; 3] {
    v.map(f64::from)
}

fn len(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

fn diff(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `2^-40`: the relative slack that covers `f64` evaluation here.
const SLACK: f64 = 1.0 / 1_099_511_627_776.0;

/// The spectral norm bound of the matrix of rows `u`, from its Gram matrix
/// (`f32` products are exact in `f64`): `sqrt(1 + |U U^T - I|_F)`.
fn lipschitz(u: &[[f32; 3]; 3]) -> f64 {
    let mut f = 0.0f64;
    for i in 0..3 {
        for j in 0..3 {
            let g = dot(back(u[i]), back(u[j])) - if i == j { 1.0 } else { 0.0 };
            f += g * g;
        }
    }
    (1.0 + f.sqrt() * (1.0 + SLACK) + 8.0 * f64::EPSILON).sqrt() * (1.0 + SLACK)
}

impl Proxy {
    /// The box of rows `axes` (any unit-ish directions) holding `points`,
    /// each known within `err` (a placement's rounding), grown by `r`.
    pub(crate) fn holding(
        points: &[[f64; 3]],
        axes: [[f64; 3]; 3],
        err: f64,
        r: f64,
    ) -> Option<Self> {
        if points.is_empty() || points.iter().flatten().any(|x| !x.is_finite()) {
            return None;
        }
        let u = axes.map(f32v);
        if u.iter().flatten().any(|x| !x.is_finite()) {
            return None;
        }
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for p in points {
            for k in 0..3 {
                let y = dot(back(u[k]), *p);
                lo[k] = lo[k].min(y);
                hi[k] = hi[k].max(y);
            }
        }
        // The centre: the middle of the slabs, in the world (any float).
        let mut c = [0.0f64; 3];
        for k in 0..3 {
            let mid = (lo[k] + hi[k]) * 0.5;
            for d in 0..3 {
                c[d] += f64::from(u[k][d]) * mid;
            }
        }
        let c32 = f32v(c);
        let lambda = lipschitz(&u);
        let mut h = [0.0f32; 3];
        for k in 0..3 {
            let uk = back(u[k]);
            let mut m = 0.0f64;
            for p in points {
                let y = dot(uk, diff(*p, back(c32)));
                m = m.max(y.abs() + SLACK * (len(*p) + len(back(c32))));
            }
            // A point known within `err` moves `u_k . (x - c)` by at most
            // `|u_k| err <= lambda err`.
            h[k] = up32(m + lambda * err);
        }
        let r32 = up32(r * (1.0 + SLACK));
        let size = len(back(c32)) + h.iter().map(|&x| f64::from(x)).sum::<f64>() + f64::from(r32);
        Some(Self {
            kind: Kind::Box {
                c: c32,
                u,
                h,
                r: r32,
            },
            lambda,
            size: size * (1.0 + SLACK),
            tilt: 0.0,
            offset: 0.0,
        })
    }

    /// The ball of centre `c` (known within `err`) and radius `r`.
    pub(crate) fn ball(c: [f64; 3], r: f64, err: f64) -> Option<Self> {
        let c32 = f32v(c);
        let moved = len(diff(c, back(c32)));
        let r32 = up32((r + moved + err) * (1.0 + SLACK));
        let p = Self {
            kind: Kind::Ball { c: c32, r: r32 },
            lambda: 1.0,
            size: (len(back(c32)) + f64::from(r32)) * (1.0 + SLACK),
            tilt: 0.0,
            offset: 0.0,
        };
        p.finite()
    }

    /// The segment `a b` (ends known within `err`) grown by `r`.
    pub(crate) fn capsule(a: [f64; 3], b: [f64; 3], r: f64, err: f64) -> Option<Self> {
        let (a32, b32) = (f32v(a), f32v(b));
        let moved = len(diff(a, back(a32))).max(len(diff(b, back(b32))));
        let r32 = up32((r + moved + err) * (1.0 + SLACK));
        let p = Self {
            kind: Kind::Capsule {
                a: a32,
                b: b32,
                r: r32,
            },
            lambda: 1.0,
            size: (len(back(a32)).max(len(back(b32)))
                + len(diff(back(a32), back(b32)))
                + f64::from(r32))
                * (1.0 + SLACK),
            tilt: 0.0,
            offset: 0.0,
        };
        p.finite()
    }

    /// The cylinder of `pose` (exact), axis its `y`, `|y| <= half`, radius
    /// `radius`, grown by `r`, placed within `err`.
    pub(crate) fn cylinder(
        pose: &Pose<f64>,
        half: f64,
        radius: f64,
        r: f64,
        err: f64,
    ) -> Option<Self> {
        let q = pose.rotation;
        // Rows: the body axes in the world (columns of Q).
        let u = [0, 1, 2].map(|k| f32v([q[0][k], q[1][k], q[2][k]]));
        let t = pose.translation.to_array();
        let c32 = f32v(t);
        let lambda = lipschitz(&u);
        // |U Q - I|_F bounds how far U (x - c32) is from the body
        // coordinates y of x = t + Q y, with |y| <= sqrt(half^2 + radius^2).
        let mut f = 0.0f64;
        for i in 0..3 {
            for j in 0..3 {
                let e =
                    dot(back(u[i]), [q[0][j], q[1][j], q[2][j]]) - if i == j { 1.0 } else { 0.0 };
                f += e * e;
            }
        }
        let shift = f.sqrt() * (1.0 + SLACK) * (half * half + radius * radius).sqrt()
            + lambda * (len(diff(t, back(c32))) + err)
            + SLACK * (len(t) + half + radius);
        let p = Self {
            kind: Kind::Cylinder {
                c: c32,
                u,
                half: up32(half + shift),
                radius: up32(radius + shift),
                r: up32(r * (1.0 + SLACK)),
            },
            lambda,
            size: (len(t) + half + radius + r + shift) * (1.0 + 4.0 * SLACK),
            tilt: 0.0,
            offset: 0.0,
        };
        p.finite()
    }

    /// The half-space `{x : m . (x - o) <= 0}` (unit `m`), placed within `err`.
    pub(crate) fn plane(m: [f64; 3], o: [f64; 3], err: f64) -> Option<Self> {
        let m32 = f32v(m);
        let tilt = len(diff(m, back(m32))) * (1.0 + SLACK);
        let b = dot(m, o);
        let b32 = up32(b + err + SLACK * len(o) + f64::from(f32::MIN_POSITIVE));
        let lambda = (1.0 + tilt) * (1.0 + SLACK);
        let p = Self {
            kind: Kind::Plane { m: m32, b: b32 },
            lambda,
            size: f64::from(b32.abs()) * (1.0 + SLACK),
            tilt,
            offset: len(o),
        };
        p.finite()
    }

    /// The union of balls `(c, r)` (centres known within `err`).
    pub(crate) fn balls(list: &[([f64; 3], f64)], err: f64) -> Option<Self> {
        let mut out = Vec::with_capacity(list.len());
        let mut size = 0.0f64;
        for &(c, r) in list {
            let c32 = f32v(c);
            let r32 = up32((r + len(diff(c, back(c32))) + err) * (1.0 + SLACK));
            size = size.max(len(back(c32)) + f64::from(r32));
            out.push([c32[0], c32[1], c32[2], r32]);
        }
        if out.is_empty() {
            return None;
        }
        Self {
            kind: Kind::Balls(out),
            lambda: 1.0,
            size: size * (1.0 + SLACK),
            tilt: 0.0,
            offset: 0.0,
        }
        .finite()
    }

    fn finite(self) -> Option<Self> {
        (self.size.is_finite() && self.lambda.is_finite()).then_some(self)
    }

    /// `phi` at one point: [`phi`](Self::phi)'s arithmetic for one lane.
    #[inline]
    pub(crate) fn phi1(&self, x: [f32; 3]) -> f32 {
        let mut lanes = [[0.0f32; LANES]; 3];
        for k in 0..3 {
            lanes[k] = [x[k]; LANES];
        }
        match &self.kind {
            Kind::Box { c, u, h, r } => {
                let d = [x[0] - c[0], x[1] - c[1], x[2] - c[2]];
                let mut s = 0.0f32;
                for k in 0..3 {
                    let y = u[k][0] * d[0] + u[k][1] * d[1] + u[k][2] * d[2];
                    let e = (y.abs() - h[k]).max(0.0);
                    s += e * e;
                }
                s.sqrt() - r
            }
            _ => self.phi(&lanes)[0],
        }
    }

    /// `phi` at the points `x` (one per lane), in `f32`.
    #[inline]
    pub(crate) fn phi(&self, x: &[Lane; 3]) -> Lane {
        let mut out = [0.0f32; LANES];
        match &self.kind {
            Kind::Box { c, u, h, r } => {
                for l in 0..LANES {
                    let d = [x[0][l] - c[0], x[1][l] - c[1], x[2][l] - c[2]];
                    let mut s = 0.0f32;
                    for k in 0..3 {
                        let y = u[k][0] * d[0] + u[k][1] * d[1] + u[k][2] * d[2];
                        let e = (y.abs() - h[k]).max(0.0);
                        s += e * e;
                    }
                    out[l] = s.sqrt() - r;
                }
            }
            Kind::Ball { c, r } => {
                for l in 0..LANES {
                    let d = [x[0][l] - c[0], x[1][l] - c[1], x[2][l] - c[2]];
                    out[l] = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt() - r;
                }
            }
            Kind::Capsule { a, b, r } => {
                let ab = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
                let ll = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
                let inv = if ll > 0.0 { 1.0 / ll } else { 0.0 };
                for l in 0..LANES {
                    let d = [x[0][l] - a[0], x[1][l] - a[1], x[2][l] - a[2]];
                    let t = ((d[0] * ab[0] + d[1] * ab[1] + d[2] * ab[2]) * inv).clamp(0.0, 1.0);
                    let e = [d[0] - t * ab[0], d[1] - t * ab[1], d[2] - t * ab[2]];
                    out[l] = (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]).sqrt() - r;
                }
            }
            Kind::Cylinder {
                c,
                u,
                half,
                radius,
                r,
            } => {
                for l in 0..LANES {
                    let d = [x[0][l] - c[0], x[1][l] - c[1], x[2][l] - c[2]];
                    let y = [0, 1, 2].map(|k| u[k][0] * d[0] + u[k][1] * d[1] + u[k][2] * d[2]);
                    let rad = (y[0] * y[0] + y[2] * y[2]).sqrt();
                    let a = (rad - radius).max(0.0);
                    let b = (y[1].abs() - half).max(0.0);
                    out[l] = (a * a + b * b).sqrt() - r;
                }
            }
            Kind::Plane { m, b } => {
                for l in 0..LANES {
                    out[l] = (m[0] * x[0][l] + m[1] * x[1][l] + m[2] * x[2][l]) - b;
                }
            }
            Kind::Balls(list) => {
                out = [f32::INFINITY; LANES];
                for ball in list {
                    for l in 0..LANES {
                        let d = [x[0][l] - ball[0], x[1][l] - ball[1], x[2][l] - ball[2]];
                        let g = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt() - ball[3];
                        out[l] = out[l].min(g);
                    }
                }
            }
        }
        out
    }
}

/// The proxy of a convex primitive placed by `pose` (Lemma 13.12): exact
/// kinds for balls, capsules and cylinders, the box of the core's local
/// bounds for cuboids and cones, each grown by the shape's radius; `None`
/// for a shape whose core is placed in its own frame (a compound's part) or
/// a hull (the rake then leaves it to the edge engine).
pub(crate) fn convex_proxy<T: Float>(
    shape: &crate::Convex<'static, T>,
    pose: &Pose<T>,
    err: T,
) -> Option<Proxy> {
    use crate::shape::convex::Core;
    if shape.is_placed() {
        return None;
    }
    let pose = Pose {
        rotation: pose.rotation.map(|r| r.map(T::to_f64)),
        translation: Vec3::from_array(pose.translation.to_array().map(T::to_f64)),
    };
    let err = err.to_f64();
    let rho = shape.radius().to_f64();
    let world = |p: [f64; 3]| pose.transform_point(Vec3::from_array(p)).to_array();
    let t = pose.translation.to_array();
    // The world placement of a body point errs by a few ulps of the terms.
    let place_err = |reach: f64| err + 8.0 * f64::EPSILON * (len(t) + 2.0 * reach);
    let box_of = |h: [f64; 3]| {
        let mut corners = Vec::with_capacity(8);
        for i in 0..8 {
            let s = [0, 1, 2].map(|k| if i >> k & 1 == 1 { h[k] } else { -h[k] });
            corners.push(world(s));
        }
        let q = pose.rotation;
        let axes = [0, 1, 2].map(|k| [q[0][k], q[1][k], q[2][k]]);
        Proxy::holding(&corners, axes, place_err(len(h)), rho)
    };
    match *shape.core() {
        Core::Point => Proxy::ball(t, rho, place_err(0.0)),
        Core::Segment { half_height } => {
            let h = half_height.to_f64();
            Proxy::capsule(
                world([0.0, -h, 0.0]),
                world([0.0, h, 0.0]),
                rho,
                place_err(h),
            )
        }
        Core::Cuboid { half } => box_of(half.map(T::to_f64)),
        Core::Cylinder {
            half_height,
            radius,
        } => {
            let (h, r) = (half_height.to_f64(), radius.to_f64());
            Proxy::cylinder(&pose, h, r, rho, err)
        }
        Core::Cone {
            half_height,
            radius,
        } => {
            let (h, r) = (half_height.to_f64(), radius.to_f64());
            box_of([r, h, r])
        }
        Core::Polytope(_) => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Points of each proxied shape (sampled, exact in f64) have `phi <= 0`,
    /// and `phi / lambda` never exceeds the distance to a sampled shape.
    #[test]
    fn proxies_hold_their_shapes_and_bound_distances() {
        let mut rng = crate::rng::SplitMix64::new(11);
        for case in 0..200 {
            let angle = rng.range(-3.0, 3.0);
            let axis = rng.direction();
            let rot = crate::chain::model::turn(Vec3::from_array(axis), angle).rotation;
            let pose = Pose {
                rotation: rot,
                translation: Vec3::from_array(rng.vec3().map(|x| x * 3.0)),
            };
            let (a, b, c) = (
                rng.range(0.01, 0.5),
                rng.range(0.01, 0.5),
                rng.range(0.01, 0.5),
            );
            let shape = match case % 4 {
                0 => crate::Convex::try_cuboid([a, b, c]).expect("box"),
                1 => crate::Convex::try_cylinder(a, b).expect("cyl"),
                2 => crate::Convex::try_capsule(a, b).expect("cap"),
                _ => crate::Convex::try_cone(a, b).expect("cone"),
            };
            let p = convex_proxy(&shape, &pose, 0.0).expect("proxy");
            // Points of the shape: body points along random directions
            // scaled to its boundary by bisection on the support-free
            // membership test.
            let inside = |y: [f64; 3]| -> bool {
                match case % 4 {
                    0 => y[0].abs() <= a && y[1].abs() <= b && y[2].abs() <= c,
                    1 => y[1].abs() <= a && (y[0] * y[0] + y[2] * y[2]).sqrt() <= b,
                    2 => {
                        let t = y[1].clamp(-a, a);
                        (y[0] * y[0] + (y[1] - t) * (y[1] - t) + y[2] * y[2]).sqrt() <= b
                    }
                    _ => {
                        let frac = (a - y[1]) / (2.0 * a);
                        y[1].abs() <= a && (y[0] * y[0] + y[2] * y[2]).sqrt() <= b * frac
                    }
                }
            };
            let mut pts = [[0.0f32; LANES]; 3];
            let mut lane = 0;
            for _ in 0..400 {
                let y = [0; 3].map(|_| rng.range(-0.6, 0.6));
                if !inside(y) {
                    continue;
                }
                let w = pose.transform_point(Vec3::from_array(y)).to_array();
                for k in 0..3 {
                    pts[k][lane] = w[k] as f32;
                }
                lane += 1;
                if lane == LANES {
                    let phi = p.phi(&pts);
                    for v in phi {
                        // f32 points are within u|x| of the exact ones.
                        assert!(
                            f64::from(v) <= 1e-5,
                            "case {case}: phi {v} at a point of the shape"
                        );
                    }
                    lane = 0;
                }
            }
        }
    }

    /// The holding test has power: a box proxy fitted to corners 2 % inside
    /// the cuboid's (as if its half extents were rounded down) leaves
    /// points of the cuboid's faces with `phi > 0`.
    #[test]
    fn a_box_fitted_short_leaves_face_points_out() {
        let mut rng = crate::rng::SplitMix64::new(12);
        let mut out = 0;
        for _ in 0..50 {
            let h = [0; 3].map(|_| rng.range(0.05, 0.5));
            let pose = Pose {
                rotation: crate::chain::model::turn(
                    Vec3::from_array(rng.direction()),
                    rng.range(-3.0, 3.0),
                )
                .rotation,
                translation: Vec3::from_array(rng.vec3()),
            };
            let q = pose.rotation;
            let axes = [0, 1, 2].map(|k| [q[0][k], q[1][k], q[2][k]]);
            let corners: Vec<[f64; 3]> = (0..8)
                .map(|i| {
                    let y = [0, 1, 2].map(|k| {
                        if i >> k & 1 == 1 {
                            0.98 * h[k]
                        } else {
                            -0.98 * h[k]
                        }
                    });
                    pose.transform_point(Vec3::from_array(y)).to_array()
                })
                .collect();
            let p = Proxy::holding(&corners, axes, 0.0, 0.0).expect("proxy");
            let mut x = [[0.0f32; LANES]; 3];
            for l in 0..LANES {
                let mut y = [0; 3].map(|k| rng.range(-1.0, 1.0) * h[k]);
                let face = l % 3;
                y[face] = if l % 2 == 0 { h[face] } else { -h[face] };
                let w = pose.transform_point(Vec3::from_array(y)).to_array();
                for k in 0..3 {
                    x[k][l] = w[k] as f32;
                }
            }
            out += usize::from(p.phi(&x).iter().any(|&v| v > 1e-4));
        }
        assert!(
            out > 40,
            "only {out} of 50 short boxes leave a face point out"
        );
    }
}
