//! Sampled ground truth for bodies of any shape, independent of the code
//! under test: each part's core tessellated *inside* itself (rims by
//! inscribed polygons, segments and points as degenerate triangles, meshes
//! as they are) with its radius, placed at each sampled time by the
//! testkit's own quaternion placement; two bodies touch at a sample when two
//! of their parts' triangles are within the sum of the parts' radii (the
//! exact triangle distance). An inscribed core lies inside the true one, so
//! a sampled contact is a true contact. Shared by `examples/mixed_scene.rs`
//! (`#[path = "../tests/common/shape_truth.rs"] mod shape_truth;`).

#![allow(dead_code, unreachable_pub)]

use motion_bound::testkit::ground_truth::place;
use motion_bound::testkit::toi::Rng;
use motion_bound::{
    try_triangle_triangle, Convex, Isometry, Point3, RigidMotion, TriMesh, VertexSet,
};

/// Sides of the inscribed polygons of rims.
pub const SIDES: usize = 16;

/// A triangle as three body points.
pub type Tri = [[f64; 3]; 3];

/// A body for the ground truth: its parts, each inscribed triangles and a
/// radius, in the body frame.
#[derive(Clone, Debug, Default)]
pub struct Solid {
    pub parts: Vec<(Vec<Tri>, f64)>,
}

fn ring(h: f64, rho: f64, y: f64) -> Vec<[f64; 3]> {
    (0..SIDES)
        .map(|k| {
            let phi = k as f64 * core::f64::consts::TAU / SIDES as f64;
            let r = rho * (1.0 - 1e-12);
            [r * phi.cos(), y * h * (1.0 - 1e-12), r * phi.sin()]
        })
        .collect()
}

fn fan(centre: [f64; 3], rim: &[[f64; 3]]) -> Vec<Tri> {
    (0..rim.len())
        .map(|k| [centre, rim[k], rim[(k + 1) % rim.len()]])
        .collect()
}

impl Solid {
    fn one(triangles: Vec<Tri>, radius: f64) -> Self {
        Self {
            parts: vec![(triangles, radius)],
        }
    }

    pub fn ball(r: f64) -> Self {
        Self::one(vec![[[0.0; 3]; 3]], r)
    }

    pub fn capsule(h: f64, r: f64) -> Self {
        Self::one(vec![[[0.0, -h, 0.0], [0.0, h, 0.0], [0.0, h, 0.0]]], r)
    }

    pub fn cuboid(half: [f64; 3], r: f64) -> Self {
        let c = |k: usize| [0, 1, 2].map(|i| if k >> i & 1 == 1 { half[i] } else { -half[i] });
        let mut tris = Vec::new();
        for axis in 0..3 {
            for side in 0..2 {
                let q: Vec<[f64; 3]> = (0..8).filter(|&k| (k >> axis) & 1 == side).map(c).collect();
                tris.extend([
                    [q[0], q[1], q[2]],
                    [q[1], q[2], q[3]],
                    [q[0], q[1], q[3]],
                    [q[0], q[2], q[3]],
                ]);
            }
        }
        Self::one(tris, r)
    }

    pub fn cylinder(h: f64, rho: f64) -> Self {
        let (top, bottom) = (ring(h, rho, 1.0), ring(h, rho, -1.0));
        let mut tris = Vec::new();
        for k in 0..SIDES {
            let j = (k + 1) % SIDES;
            tris.push([top[k], top[j], bottom[k]]);
            tris.push([top[j], bottom[j], bottom[k]]);
        }
        tris.extend(fan([0.0, h, 0.0], &top));
        tris.extend(fan([0.0, -h, 0.0], &bottom));
        Self::one(tris, 0.0)
    }

    pub fn cone(h: f64, rho: f64) -> Self {
        let bottom = ring(h, rho, -1.0);
        let mut tris = fan([0.0, h * (1.0 - 1e-12), 0.0], &bottom);
        tris.extend(fan([0.0, -h, 0.0], &bottom));
        Self::one(tris, 0.0)
    }

    pub fn mesh(m: &TriMesh<f64>) -> Self {
        Self::one(m.triangle_corners().collect(), 0.0)
    }

    /// The parts mapped by `pose` (its stored matrix and translation: the
    /// crate's placed shape is defined by the stored matrix).
    pub fn placed(mut self, pose: &Isometry<f64>) -> Self {
        let m = pose.rotation().matrix();
        let t = pose.translation().to_array();
        for (tris, _) in &mut self.parts {
            for tri in tris.iter_mut() {
                *tri = tri
                    .map(|p| [0, 1, 2].map(|i| (0..3).map(|j| m[i][j] * p[j]).sum::<f64>() + t[i]));
            }
        }
        self
    }

    /// The union of bodies' parts (a compound).
    pub fn union(solids: Vec<Solid>) -> Self {
        Self {
            parts: solids.into_iter().flat_map(|s| s.parts).collect(),
        }
    }

    /// The largest distance of a part's point from the body origin, plus
    /// its radius.
    pub fn reach(&self) -> f64 {
        self.parts
            .iter()
            .map(|(tris, r)| {
                tris.iter()
                    .flatten()
                    .map(|p| (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt())
                    .fold(0.0, f64::max)
                    + r
            })
            .fold(0.0, f64::max)
    }
}

/// Whether the two bodies touch at time `t`.
pub fn touch_at(
    a: &Solid,
    ma: &RigidMotion<f64>,
    b: &Solid,
    mb: &RigidMotion<f64>,
    t: f64,
) -> bool {
    let placed = |s: &Solid, m: &RigidMotion<f64>| -> Vec<(Vec<[Point3<f64>; 3]>, f64)> {
        s.parts
            .iter()
            .map(|(tris, r)| {
                (
                    tris.iter()
                        .map(|tri| tri.map(|p| Point3::from_array(place(m, p, t))))
                        .collect(),
                    *r,
                )
            })
            .collect()
    };
    let (pa, pb) = (placed(a, ma), placed(b, mb));
    // Each part's bounding sphere, to skip far part pairs and triangles.
    let sphere = |tris: &[[Point3<f64>; 3]]| {
        let n = (tris.len() * 3) as f64;
        let c = tris.iter().flatten().fold([0.0; 3], |s, p| {
            [s[0] + p.x / n, s[1] + p.y / n, s[2] + p.z / n]
        });
        let c = Point3::from_array(c);
        let r = tris
            .iter()
            .flatten()
            .map(|p| (*p - c).length())
            .fold(0.0, f64::max);
        (c, r)
    };
    for (ta, ra) in &pa {
        let (ca, sa) = sphere(ta);
        for (tb, rb) in &pb {
            let (cb, sb) = sphere(tb);
            let reach = ra + rb;
            if (cb - ca).length() > sa + sb + reach {
                continue;
            }
            let near = |tri: &[Point3<f64>; 3], c: Point3<f64>, s: f64| {
                tri.iter().any(|p| (*p - c).length() <= s + reach)
                    || tri_sphere_lower(tri, c) <= s + reach
            };
            let xs: Vec<&[Point3<f64>; 3]> = ta.iter().filter(|x| near(x, cb, sb)).collect();
            let ys: Vec<&[Point3<f64>; 3]> = tb.iter().filter(|y| near(y, ca, sa)).collect();
            for x in &xs {
                for y in &ys {
                    if try_triangle_triangle(x, y).expect("finite").distance <= reach {
                        return true;
                    }
                }
            }
        }
    }
    false
}

/// A lower bound of a triangle's distance from `c` (its centroid's distance
/// less its circumradius about the centroid).
fn tri_sphere_lower(tri: &[Point3<f64>; 3], c: Point3<f64>) -> f64 {
    let g = Point3::from_array(
        [0, 1, 2]
            .map(|k| (tri[0].to_array()[k] + tri[1].to_array()[k] + tri[2].to_array()[k]) / 3.0),
    );
    let r = tri.iter().map(|p| (*p - g).length()).fold(0.0, f64::max);
    (g - c).length() - r
}

/// The first of `samples + 1` evenly spaced times of `[t0, t1]` at which the
/// bodies touch.
pub fn first_sampled_contact(
    a: &Solid,
    ma: &RigidMotion<f64>,
    b: &Solid,
    mb: &RigidMotion<f64>,
    (t0, t1): (f64, f64),
    samples: usize,
) -> Option<f64> {
    (0..=samples)
        .map(|s| t0 + (t1 - t0) * s as f64 / samples as f64)
        .find(|&t| touch_at(a, ma, b, mb, t))
}

/// The first sampled time at which the body comes within its parts' radii
/// of the plane `{x : (x - p(t)) . m <= 0}` (`p` the ground motion's placed
/// origin, `m` a unit normal).
pub fn first_sampled_landing(
    a: &Solid,
    ma: &RigidMotion<f64>,
    ground: &RigidMotion<f64>,
    m: [f64; 3],
    (t0, t1): (f64, f64),
    samples: usize,
) -> Option<f64> {
    (0..=samples)
        .map(|s| t0 + (t1 - t0) * s as f64 / samples as f64)
        .find(|&t| {
            let p = place(ground, [0.0; 3], t);
            a.parts.iter().any(|(tris, r)| {
                tris.iter().flatten().any(|&q| {
                    let x = place(ma, q, t);
                    (0..3).map(|k| (x[k] - p[k]) * m[k]).sum::<f64>() <= *r
                })
            })
        })
}

/// Seven convex kinds of about half a unit across, each with its ground
/// truth: a ball, a capsule, a cuboid, a rounded cuboid, a cylinder, a cone
/// and the hull of eight random points (`rng`).
pub fn convex_kinds(rng: &mut Rng) -> Vec<(&'static str, Convex<'static, f64>, Solid)> {
    let (h, r, rho) = (0.4, 0.15, 0.35);
    let half = [0.4, 0.25, 0.3];
    let vertices: &'static [[f64; 3]] = Box::leak(
        (0..8)
            .map(|_| rng.direction().map(|x| x * rng.range(0.2, 0.45)))
            .collect::<Vec<_>>()
            .into_boxed_slice(),
    );
    let mut hull = Vec::new();
    for i in 0..vertices.len() {
        for j in i + 1..vertices.len() {
            for k in j + 1..vertices.len() {
                hull.push([vertices[i], vertices[j], vertices[k]]);
            }
        }
    }
    let set = VertexSet::try_new(vertices).expect("vertices");
    let ok = |c: Result<Convex<'static, f64>, _>| c.expect("a valid shape");
    vec![
        ("ball", ok(Convex::try_ball(r)), Solid::ball(r)),
        (
            "capsule",
            ok(Convex::try_capsule(h, r)),
            Solid::capsule(h, r),
        ),
        (
            "cuboid",
            ok(Convex::try_cuboid(half)),
            Solid::cuboid(half, 0.0),
        ),
        (
            "rounded cuboid",
            ok(Convex::try_cuboid(half).and_then(|s| s.try_rounded(0.1))),
            Solid::cuboid(half, 0.1),
        ),
        (
            "cylinder",
            ok(Convex::try_cylinder(h, rho)),
            Solid::cylinder(h, rho),
        ),
        ("cone", ok(Convex::try_cone(h, rho)), Solid::cone(h, rho)),
        ("polytope", Convex::polytope(set), Solid::one(hull, 0.0)),
    ]
}
