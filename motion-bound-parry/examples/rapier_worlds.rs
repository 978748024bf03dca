//! Rapier's continuous collision detection, with and without the certified
//! cast, in ten worlds, judged by an independent checker.
//!
//! ```text
//! cargo run --release -p motion-bound-parry --features rapier --example rapier_worlds -- --launches 20 [--rounds 5]
//! ```
//!
//! Each world is launched `--launches` times (default 20; each launch a
//! seed: random start poses, velocities and spins), each launch stepped 150
//! times at `dt = 1/60` with gravity off (but in `stack`) and CCD enabled on every dynamic
//! body, twice with the same launches:
//!
//! - **default**: rapier's narrow phase with parry's dispatcher, plain
//!   shapes;
//! - **ours**: the README's setup: the narrow phase with
//!   [`CertifiedDispatcher`], plain shapes (nothing wrapped), and
//!   [`CertifiedPass`] around each step, made with the dispatcher (the
//!   bodies' actual motions over the step, cast pairwise, moved back to the
//!   earliest time of impact; its time is counted in the step's).
//!
//! With `--swept`, two more runs per world: a `swept` line, the same with
//! every dynamic collider's shape wrapped in [`Swept`] (fixed ones plain),
//! so that rapier's own CCD also hands the dynamic bodies' pairs to the
//! certified cast; and a `swept, no pass` line, the wrapped shapes and the
//! dispatcher without the pass (rapier's own CCD casts only: never between
//! two bullets, clamped along rapier's path).
//!
//! The worlds:
//!
//! - `board`: a thin board (a 2 x 0.04 x 0.6 cuboid) flying at 8 to 30 m/s
//!   and spinning at 20 to 80 rad/s at a thin wall (0.04 thick);
//! - `bullets`: two small balls or cubes flying head-on at 15 to 60 m/s each;
//! - `plate`: a small ball (or spinning cube) at 20 to 150 m/s at a fixed
//!   triangle-mesh plate (zero thickness);
//! - `mesh`: a dynamic triangle-mesh sphere (radius 0.3) at 10 to 60 m/s,
//!   spinning, at a wall 0.1 thick;
//! - `cylinder`: a spinning cylinder or cone at 10 to 50 m/s at a thin wall;
//! - `swarm`: twenty small balls and thin boxes at 150 to 250 m/s, spinning
//!   at 20 to 80 rad/s, at a wall 0.04 thick;
//! - `wall-cuboid`, `wall-mesh`: twenty balls (radius 0.05) and cubes
//!   (half side 0.05) at 200 m/s, spinning up to 60 rad/s, at a wall 0.01
//!   thick: a cuboid, or its 12 triangles as a mesh (issue 55's wall);
//! - `spin-mesh`: twenty balls and cubes of 0.05 at 20 to 60 m/s, spinning
//!   at 100 to 300 rad/s, at that 12-triangle mesh wall (issue 64);
//! - `stack`: four columns of five boxes (half side 0.1) resting on a fixed
//!   floor under gravity (9.81 down `y`), placed 1e-3 apart and jittered
//!   (issue 64: resting contact handed to the solver). Its line also gives
//!   rapier with CCD off (`no-ccd`), the price a resting world should
//!   keep.
//!
//! After the worlds, the `slide` lines: a ball stopped at the cuboid wall
//! of `wall-cuboid` at 200 m/s, under gravity, then sliding down the wall;
//! how far it falls in 120 steps in each setup (rapier's friction gives it
//! a spin as it slides, so it spins even when launched still).
//!
//! # The checker
//!
//! It does not use the cast being judged. For each step and each pair (a
//! dynamic body and any other body), the poses before and after `step()`
//! are interpolated as a constant-velocity motion about each body's centre
//! of mass (centre lerped, rotation slerped), sampled densely (at least 64
//! samples, and enough that no point of either body moves more than half
//! the tolerance between samples), and at each sample the penetration depth
//! is parry's static `contact` (`-dist`, on the plain shapes). With the
//! tolerance `TOL = 0.01`:
//!
//! - **tunnelled**: the body's centre of mass crosses the mid-plane of a
//!   thin fixed obstacle inside its extent during the step, or the start and
//!   end poses penetrate by at most `TOL` while some sample between them
//!   penetrates by more (the body passed through, or into and out of, the
//!   other within the step);
//! - **late**: not a crossing, and the end pose penetrates by more than
//!   `TOL` (the step's contact was caught, but the body was stopped deep).
//!
//! A world's line counts launches with at least one such step, out of
//! `--launches`, and the mean wall-clock time of `step()` (with
//! `--rounds R`, the fastest of R rounds of each mode, alternated: the
//! first checked, the others not; a world of small bodies takes a few
//! microseconds a step, where one round's figure moves by a third on a busy
//! machine).
//!
//! # What the dispatcher alone cannot fix, and the pass does
//!
//! The certified cast answers the question rapier asks: when, along the
//! step's motion, two shapes first touch, never later than they do and
//! never "no impact" when there is one. Given to rapier's CCD (through the
//! dispatcher and [`Swept`]), it fixes what comes from rapier not asking
//! (a moving triangle mesh, which rapier never sweeps: the `mesh` world) or
//! from a cast answering too late. It cannot fix what rapier never asks
//! (it casts nothing between two bullets: the `bullets` world) nor what
//! rapier does with the answer: it ignores a hit at fraction `0` and clamps
//! a body along its own interpolation, not the motion it cast. Traced in
//! the `cylinder` world with the dispatcher alone: our hit left a gap of
//! `8e-5` along the asked motion, rapier's clamped pose (along its own
//! path) was touching, the next step's cast answered `0`, rapier ignored it
//! and a cone spinning at 40 rad/s passed through the wall; the `board`
//! world was late the same way. With the dispatcher alone (no pass), one
//! run of 40 launches: board late 4, bullets tunnelled 25, cylinder
//! tunnelled 2 and late 9; plate and mesh 0.
//!
//! [`CertifiedPass`] closes these: it casts the motions the bodies actually
//! made (the ones the checker interpolates), every CCD body against every
//! collider its swept box meets, and moves each back to its pose on that
//! motion at the earliest time of impact; a pair touching at the start that
//! the step would leave deeper is held at the start.
//!
//! After the world lines: the dispatcher's counts per world (casts answered
//! by the certified cast, casts handed to parry's), and the cost of
//! installing the dispatcher with no shape wrapped (the same launches,
//! without the checker, five alternating rounds, the fastest of each):
//! rapier then calls its `cast_shapes_nonlinear` only for cylinders, cones
//! and half-spaces, so in the other worlds it only forwards queries to
//! parry's. The `ms per step` of the world lines are measured in the
//! checked runs (the checker runs between steps).
//!
//! That cost is not nil in the `mesh` world: 15 to 25 % more per step on an
//! AMD EPYC (with fat LTO too), where the steps are spent in parry's
//! triangle-cuboid contact manifolds. Profiled, the same parry code runs
//! either way, but compiled differently: parry's generic manifold code is
//! instantiated for this dispatcher in the calling crate instead of in
//! rapier, and there a cuboid's `support_point_toward` is not inlined into
//! its separating-axis search. In the worlds of primitives it is within the
//! noise.

use std::time::Instant;

use motion_bound_devkit::{Args, Rng};
use motion_bound_parry::rapier::CertifiedPass;
use motion_bound_parry::{CertifiedDispatcher, DispatchStats, Swept};
use parry3d_f64::math::{Pose, Rotation, Vector};
use parry3d_f64::query;
use parry3d_f64::shape::{Ball, Capsule, Shape, SharedShape};
use rapier3d_f64::prelude::{
    ColliderBuilder, NarrowPhase, PhysicsWorld, RigidBodyBuilder, RigidBodyHandle,
};

/// The time step.
pub(crate) const DT: f64 = 1.0 / 60.0;
/// The checker's penetration tolerance.
pub(crate) const TOL: f64 = 0.01;
/// Steps per launch.
pub(crate) const STEPS: usize = 150;

/// A random unit vector (from the cube, of length more than 0.1 before normalising).
fn unit(r: &mut Rng) -> Vector {
    Vector::from(motion_bound_devkit::direction(r, 0.1))
}

/// A random rotation: a random axis, an angle in `[0, pi)`.
fn rot(r: &mut Rng) -> Rotation {
    let axis = unit(r);
    Rotation::from_axis_angle(axis, r.range(0.0, std::f64::consts::PI))
}

/// The worlds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum World {
    /// A spinning thin board at a thin wall.
    Board,
    /// Two bullets head-on.
    Bullets,
    /// A small fast ball or cube at a fixed triangle-mesh plate.
    Plate,
    /// A fast dynamic triangle-mesh sphere at a wall.
    Mesh,
    /// A spinning cylinder or cone at a thin wall.
    Cylinder,
    /// Twenty small spinning balls and boxes at about 200 m/s at a thin
    /// wall (issue 40's wall world).
    Swarm,
    /// Twenty balls and cubes of 0.05 at 200 m/s, spinning up to 60 rad/s,
    /// at a cuboid wall 0.01 thick (issue 55's wall world).
    WallCuboid,
    /// The same at a 12-triangle mesh of that wall.
    WallMesh,
    /// Twenty small balls and cubes spinning at 100 to 300 rad/s at that
    /// mesh wall (issue 64).
    SpinMesh,
    /// Twenty boxes resting in four columns on a floor, under gravity
    /// (issue 64).
    Stack,
}

impl World {
    /// Every world, in the order printed.
    pub(crate) const ALL: [Self; 10] = [
        Self::Board,
        Self::Bullets,
        Self::Plate,
        Self::Mesh,
        Self::Cylinder,
        Self::Swarm,
        Self::WallCuboid,
        Self::WallMesh,
        Self::SpinMesh,
        Self::Stack,
    ];

    /// The world's short name.
    pub(crate) fn name(self) -> &'static str {
        match self {
            Self::Board => "board",
            Self::Bullets => "bullets",
            Self::Plate => "plate",
            Self::Mesh => "mesh",
            Self::Cylinder => "cylinder",
            Self::Swarm => "swarm",
            Self::WallCuboid => "wall-cuboid",
            Self::WallMesh => "wall-mesh",
            Self::SpinMesh => "spin-mesh",
            Self::Stack => "stack",
        }
    }

    /// The world's gravity (only the stack has one).
    pub(crate) fn gravity(self) -> Vector {
        if self == Self::Stack {
            Vector::new(0.0, -9.81, 0.0)
        } else {
            Vector::ZERO
        }
    }
}

/// How a world is run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Mode {
    /// Parry's dispatcher, plain shapes.
    Default,
    /// [`CertifiedDispatcher`], plain shapes, no pass.
    Installed,
    /// [`CertifiedDispatcher`] and [`CertifiedPass`], plain shapes (the
    /// README's setup).
    Ours,
    /// [`CertifiedDispatcher`] and [`CertifiedPass`], dynamic colliders
    /// wrapped in [`Swept`].
    Swept,
    /// [`CertifiedDispatcher`], dynamic colliders wrapped in [`Swept`], no
    /// pass (the README's "many fast bodies, no pass").
    SweptOnly,
    /// Parry's dispatcher, plain shapes, CCD off (the stack's reference).
    NoCcd,
}

/// A thin fixed obstacle: its local normal axis and half extents, for the
/// crossing test.
#[derive(Clone, Copy)]
struct Thin {
    axis: usize,
    half: Vector,
}

/// One body of a world.
struct Spec {
    shape: SharedShape,
    pose: Pose,
    linvel: Vector,
    angvel: Vector,
    dynamic: bool,
    thin: Option<Thin>,
}

fn dynamic(shape: SharedShape, pose: Pose, linvel: Vector, angvel: Vector) -> Spec {
    Spec {
        shape,
        pose,
        linvel,
        angvel,
        dynamic: true,
        thin: None,
    }
}

fn wall(half_thick: f64, half: f64) -> Spec {
    Spec {
        shape: SharedShape::cuboid(half_thick, half, half),
        pose: Pose::IDENTITY,
        linvel: Vector::ZERO,
        angvel: Vector::ZERO,
        dynamic: false,
        thin: Some(Thin {
            axis: 0,
            half: Vector::new(half_thick, half, half),
        }),
    }
}

/// A triangle-mesh sphere of radius `r`.
pub(crate) fn sphere_mesh(r: f64) -> SharedShape {
    let (v, t) = Ball::new(r).to_trimesh(12, 12);
    SharedShape::trimesh(v, t).expect("a valid sphere mesh")
}

/// A flat square triangle mesh in the plane `y = 0`.
fn plate_mesh(half: f64, n: u32) -> SharedShape {
    let mut v = Vec::new();
    let mut t = Vec::new();
    let step = 2.0 * half / f64::from(n);
    for i in 0..=n {
        for j in 0..=n {
            v.push(Vector::new(
                -half + step * f64::from(i),
                0.0,
                -half + step * f64::from(j),
            ));
        }
    }
    let id = |i: u32, j: u32| i * (n + 1) + j;
    for i in 0..n {
        for j in 0..n {
            t.push([id(i, j), id(i, j + 1), id(i + 1, j)]);
            t.push([id(i + 1, j), id(i, j + 1), id(i + 1, j + 1)]);
        }
    }
    SharedShape::trimesh(v, t).expect("a valid plate mesh")
}

/// The bodies of `world`'s launch `seed`.
fn build(world: World, seed: u64) -> Vec<Spec> {
    let w = World::ALL.iter().position(|x| *x == world).unwrap_or(0) as u64;
    let mut r = Rng::new(seed.wrapping_mul(7919).wrapping_add(w * 1_000_003));
    let jitter = |r: &mut Rng, s: f64| Vector::new(0.0, r.range(-s, s), r.range(-s, s));
    match world {
        World::Board => {
            let pos = Vector::new(
                -2.5 + r.range(-0.5, 0.5),
                r.range(-0.5, 0.5),
                r.range(-0.5, 0.5),
            );
            let v = r.range(8.0, 30.0);
            let lin = Vector::new(v, 0.0, 0.0) + jitter(&mut r, 0.1 * v);
            let ang = unit(&mut r) * r.range(20.0, 80.0);
            vec![
                wall(0.02, 4.0),
                dynamic(
                    SharedShape::cuboid(1.0, 0.02, 0.3),
                    Pose::from_parts(pos, rot(&mut r)),
                    lin,
                    ang,
                ),
            ]
        }
        World::Bullets => {
            let shape = if seed.is_multiple_of(2) {
                SharedShape::ball(0.1)
            } else {
                SharedShape::cuboid(0.1, 0.1, 0.1)
            };
            let (v1, v2) = (r.range(15.0, 60.0), r.range(15.0, 60.0));
            let off = jitter(&mut r, 0.08);
            let a = Pose::from_parts(Vector::new(-2.0, 0.0, 0.0), rot(&mut r));
            let b = Pose::from_parts(Vector::new(2.0, 0.0, 0.0) + off, rot(&mut r));
            vec![
                dynamic(shape.clone(), a, Vector::new(v1, 0.0, 0.0), Vector::ZERO),
                dynamic(shape, b, Vector::new(-v2, 0.0, 0.0), Vector::ZERO),
            ]
        }
        World::Plate => {
            let (shape, ang) = if seed.is_multiple_of(2) {
                (SharedShape::ball(0.05), Vector::ZERO)
            } else {
                (
                    SharedShape::cuboid(0.05, 0.05, 0.05),
                    unit(&mut r) * r.range(10.0, 60.0),
                )
            };
            let v = r.range(20.0, 150.0);
            let tilt = Vector::new(r.range(-0.3, 0.3), 0.0, r.range(-0.3, 0.3));
            let lin = (Vector::new(0.0, -1.0, 0.0) + tilt).normalize() * v;
            let pos = Vector::new(r.range(-0.5, 0.5), 1.5, r.range(-0.5, 0.5));
            vec![
                Spec {
                    shape: plate_mesh(2.0, 4),
                    pose: Pose::IDENTITY,
                    linvel: Vector::ZERO,
                    angvel: Vector::ZERO,
                    dynamic: false,
                    thin: Some(Thin {
                        axis: 1,
                        half: Vector::new(2.0, 0.0, 2.0),
                    }),
                },
                dynamic(shape, Pose::from_parts(pos, rot(&mut r)), lin, ang),
            ]
        }
        World::Mesh => {
            let sp = r.range(10.0, 60.0);
            let lin = Vector::new(sp, 0.0, 0.0) + jitter(&mut r, 0.1 * sp);
            let pos = Vector::new(-3.0, r.range(-0.5, 0.5), r.range(-0.5, 0.5));
            vec![
                wall(0.05, 4.0),
                dynamic(
                    sphere_mesh(0.3),
                    Pose::from_parts(pos, rot(&mut r)),
                    lin,
                    unit(&mut r) * r.range(0.0, 20.0),
                ),
            ]
        }
        World::Cylinder => {
            let shape = if seed.is_multiple_of(2) {
                SharedShape::cylinder(0.3, 0.05)
            } else {
                SharedShape::cone(0.3, 0.08)
            };
            let sp = r.range(10.0, 50.0);
            let lin = Vector::new(sp, 0.0, 0.0) + jitter(&mut r, 0.1 * sp);
            let pos = Vector::new(-2.5, r.range(-0.5, 0.5), r.range(-0.5, 0.5));
            vec![
                wall(0.02, 4.0),
                dynamic(
                    shape,
                    Pose::from_parts(pos, rot(&mut r)),
                    lin,
                    unit(&mut r) * r.range(20.0, 80.0),
                ),
            ]
        }
        World::Swarm => {
            // A 4 x 5 grid across the wall, 1.4 apart, each cell jittered by
            // 0.3: no two bodies start near each other.
            let mut specs = vec![wall(0.02, 4.0)];
            for k in 0..20 {
                let shape = if k % 2 == 0 {
                    SharedShape::ball(0.05)
                } else {
                    SharedShape::cuboid(0.05, 0.02, 0.08)
                };
                let cell = Vector::new(0.0, (k % 4) as f64 * 1.4 - 2.1, (k / 4) as f64 * 1.4 - 2.8);
                let pos =
                    Vector::new(-4.0 + r.range(-1.0, 1.0), 0.0, 0.0) + cell + jitter(&mut r, 0.3);
                let sp = r.range(150.0, 250.0);
                let lin = Vector::new(sp, 0.0, 0.0) + jitter(&mut r, 0.02 * sp);
                let ang = unit(&mut r) * r.range(20.0, 80.0);
                specs.push(dynamic(shape, Pose::from_parts(pos, rot(&mut r)), lin, ang));
            }
            specs
        }
        World::WallCuboid | World::WallMesh | World::SpinMesh => {
            // Issue 55's wall worlds (200 m/s, up to 60 rad/s, from 3 to 5
            // in front of the wall) and issue 64's fast spins (20 to 60
            // m/s, 100 to 300 rad/s, from 0.5 to 1.5 in front of the mesh).
            let spins = world == World::SpinMesh;
            let half = Vector::new(0.005, 4.0, 4.0);
            let mut specs = vec![if world == World::WallCuboid {
                wall(half.x, half.y)
            } else {
                mesh_wall(half)
            }];
            let (x0, spread) = if spins { (-1.0, 0.5) } else { (-4.0, 1.0) };
            for k in 0..20 {
                let shape = if k % 2 == 0 {
                    SharedShape::ball(0.05)
                } else {
                    SharedShape::cuboid(0.05, 0.05, 0.05)
                };
                let cell = Vector::new(0.0, (k % 4) as f64 * 1.4 - 2.1, (k / 4) as f64 * 1.4 - 2.8);
                let pos = Vector::new(x0 + r.range(-spread, spread), 0.0, 0.0)
                    + cell
                    + jitter(&mut r, 0.3);
                let lin = if spins {
                    let sp = r.range(20.0, 60.0);
                    Vector::new(sp, 0.0, 0.0) + jitter(&mut r, 0.05 * sp)
                } else {
                    Vector::new(200.0, 0.0, 0.0) + jitter(&mut r, 4.0)
                };
                let ang = unit(&mut r)
                    * if spins {
                        r.range(100.0, 300.0)
                    } else {
                        r.range(0.0, 60.0)
                    };
                specs.push(dynamic(shape, Pose::from_parts(pos, rot(&mut r)), lin, ang));
            }
            specs
        }
        World::Stack => {
            let h = 0.1;
            let mut specs = vec![Spec {
                shape: SharedShape::cuboid(4.0, 0.1, 4.0),
                pose: Pose::from_translation(Vector::new(0.0, -0.1, 0.0)),
                linvel: Vector::ZERO,
                angvel: Vector::ZERO,
                dynamic: false,
                thin: None,
            }];
            for col in 0..4 {
                let x = (col % 2) as f64 * 0.6 - 0.3;
                let z = (col / 2) as f64 * 0.6 - 0.3;
                for level in 0..5 {
                    let y = h + 1e-3 + level as f64 * (2.0 * h + 1e-3);
                    let pos = Vector::new(x + r.range(-0.01, 0.01), y, z + r.range(-0.01, 0.01));
                    let turn = Rotation::from_axis_angle(Vector::Y, r.range(-0.1, 0.1));
                    specs.push(dynamic(
                        SharedShape::cuboid(h, h, h),
                        Pose::from_parts(pos, turn),
                        Vector::ZERO,
                        Vector::ZERO,
                    ));
                }
            }
            specs
        }
    }
}

/// A user's mesh of a thin wall: the box's 12 triangles, a surface (not
/// flagged as a solid).
fn mesh_wall(half: Vector) -> Spec {
    let (v, t) = parry3d_f64::shape::Cuboid::new(half).to_trimesh();
    Spec {
        shape: SharedShape::trimesh(v, t).expect("a valid box mesh"),
        pose: Pose::IDENTITY,
        linvel: Vector::ZERO,
        angvel: Vector::ZERO,
        dynamic: false,
        thin: Some(Thin { axis: 0, half }),
    }
}

// ---------------------------------------------------------------------------
// The independent checker.

/// A body as the checker sees it: the plain shape, its centre of mass and
/// its reach from it.
struct Geo {
    shape: SharedShape,
    com: Vector,
    reach: f64,
    dynamic: bool,
    thin: Option<Thin>,
}

impl Geo {
    fn new(s: &Spec) -> Self {
        let com = s.shape.mass_properties(1.0).local_com;
        let aabb = s.shape.compute_local_aabb();
        let reach = aabb
            .vertices()
            .iter()
            .map(|c| (*c - com).length())
            .fold(0.0, f64::max);
        Self {
            shape: s.shape.clone(),
            com,
            reach,
            dynamic: s.dynamic,
            thin: s.thin,
        }
    }
}

/// Constant-velocity motion about the centre of mass: centre lerped,
/// rotation slerped.
fn interp(p0: &Pose, p1: &Pose, com: Vector, t: f64) -> Pose {
    let c = p0.transform_point(com).lerp(p1.transform_point(com), t);
    let q = p0.rotation.slerp(p1.rotation, t).normalize();
    Pose::from_parts(c - q * com, q)
}

fn rot_angle(a: &Rotation, b: &Rotation) -> f64 {
    2.0 * a.dot(*b).abs().min(1.0).acos()
}

/// Penetration depth (`0` when apart), by parry's static contact query.
fn pen(pa: &Pose, ga: &dyn Shape, pb: &Pose, gb: &dyn Shape) -> f64 {
    match query::contact(pa, ga, pb, gb, 0.0) {
        Ok(Some(c)) => (-c.dist).max(0.0),
        Ok(None) => 0.0,
        Err(_) => panic!("the checker met a pair parry's contact does not take"),
    }
}

/// One pair's verdict over one step.
#[derive(Default, Clone, Copy)]
struct Verdict {
    tunnelled: bool,
    late: bool,
}

fn check_pair(a: &Geo, a0: &Pose, a1: &Pose, b: &Geo, b0: &Pose, b1: &Pose) -> Verdict {
    let ca0 = a0.transform_point(a.com);
    let ca1 = a1.transform_point(a.com);
    let cb0 = b0.transform_point(b.com);
    let cb1 = b1.transform_point(b.com);
    // Quick rejection: A's swept volume is inside the capsule (ca0, ca1,
    // reach), B's too when it moves.
    let cap_a = Capsule::new(ca0, ca1, a.reach);
    let far = if b.dynamic {
        let cap_b = Capsule::new(cb0, cb1, b.reach);
        query::distance(&Pose::IDENTITY, &cap_a, &Pose::IDENTITY, &cap_b)
            .expect("capsules")
            .distance
            > TOL
    } else {
        query::distance(&Pose::IDENTITY, &cap_a, b0, b.shape.as_ref())
            .expect("a capsule and a fixed shape")
            .distance
            > TOL
    };
    // A crossing of a thin fixed obstacle's mid-plane by A's centre of mass.
    let mut crossed = false;
    if let (Some(thin), false) = (b.thin, b.dynamic) {
        let l0 = b0.inverse_transform_point(ca0);
        let l1 = b0.inverse_transform_point(ca1);
        let (s0, s1) = (l0[thin.axis], l1[thin.axis]);
        if s0 * s1 < 0.0 {
            let l = l0.lerp(l1, s0 / (s0 - s1));
            crossed = (0..3).all(|k| k == thin.axis || l[k].abs() <= thin.half[k]);
        }
    }
    if far && !crossed {
        return Verdict::default();
    }
    let disp = (ca1 - ca0).length()
        + rot_angle(&a0.rotation, &a1.rotation) * a.reach
        + (cb1 - cb0).length()
        + rot_angle(&b0.rotation, &b1.rotation) * b.reach;
    let n = ((disp / (0.5 * TOL)).ceil() as usize).clamp(64, 50_000);
    let (ga, gb) = (a.shape.as_ref(), b.shape.as_ref());
    let p_start = pen(a0, ga, b0, gb);
    let p_end = pen(a1, ga, b1, gb);
    let mut p_mid: f64 = 0.0;
    if !far {
        for k in 1..n {
            let t = k as f64 / n as f64;
            let pa = interp(a0, a1, a.com, t);
            let pb = interp(b0, b1, b.com, t);
            p_mid = p_mid.max(pen(&pa, ga, &pb, gb));
            if p_mid > TOL && p_start <= TOL {
                break; // the verdict is decided
            }
        }
    }
    Verdict {
        tunnelled: crossed || (p_end <= TOL && p_start <= TOL && p_mid > TOL),
        late: !crossed && p_end > TOL,
    }
}

// ---------------------------------------------------------------------------
// Running a world.

/// A world's counts over its launches.
#[derive(Debug, Default, Clone, Copy)]
pub(crate) struct Tally {
    /// Launches run.
    pub(crate) launches: usize,
    /// Steps run.
    pub(crate) steps: usize,
    /// Launches with a tunnelled step.
    pub(crate) tunnelled: usize,
    /// Launches with a late step.
    pub(crate) late: usize,
    /// Seconds spent in `step()` (and, for `Ours`, in the certified pass).
    pub(crate) step_secs: f64,
    /// Of those, seconds spent in the certified pass alone (`record` and
    /// `clamp`; `Ours` and `Swept`).
    pub(crate) pass_secs: f64,
    /// The certified pass's casts and bodies moved back (`Ours`).
    pub(crate) pass_casts: usize,
    /// Bodies the certified pass moved back to a time of impact.
    pub(crate) pass_clamped: usize,
    /// Touching pairs the pass decided by the closed form, no cast.
    pub(crate) pass_checked: usize,
    /// The dispatcher's counts (`Installed` and `Ours`).
    pub(crate) stats: DispatchStats,
}

impl Tally {
    /// Mean milliseconds per step.
    pub(crate) fn ms_per_step(&self) -> f64 {
        1e3 * self.step_secs / self.steps.max(1) as f64
    }
}

fn make_world(
    specs: &[Spec],
    mode: Mode,
    dispatcher: &CertifiedDispatcher,
    gravity: Vector,
) -> (PhysicsWorld, Vec<RigidBodyHandle>) {
    let mut w = PhysicsWorld {
        gravity,
        ..PhysicsWorld::default()
    };
    w.integration_parameters.dt = DT;
    if !matches!(mode, Mode::Default | Mode::NoCcd) {
        w.narrow_phase = NarrowPhase::with_query_dispatcher(dispatcher.clone());
    }
    let mut handles = Vec::new();
    for s in specs {
        let (rb, shape) = if s.dynamic {
            let rb = RigidBodyBuilder::dynamic()
                .pose(s.pose)
                .linvel(s.linvel)
                .angvel(s.angvel)
                .ccd_enabled(mode != Mode::NoCcd)
                .can_sleep(false);
            let shape = if matches!(mode, Mode::Swept | Mode::SweptOnly) {
                Swept::shared(s.shape.clone())
            } else {
                s.shape.clone()
            };
            (rb, shape)
        } else {
            (RigidBodyBuilder::fixed().pose(s.pose), s.shape.clone())
        };
        let (h, _) = w.insert(rb, ColliderBuilder::new(shape).restitution(0.3));
        handles.push(h);
    }
    (w, handles)
}

/// Runs `world`'s launches `0..launches` of `steps` steps each in `mode`,
/// judged by the checker when `check`; `verbose` prints each failing step.
pub(crate) fn run_world(
    world: World,
    mode: Mode,
    launches: u64,
    steps: usize,
    check: bool,
    verbose: bool,
) -> Tally {
    let dispatcher = CertifiedDispatcher::new();
    let mut pass = CertifiedPass::new().with_dispatcher(dispatcher.clone());
    let mut t = Tally::default();
    for seed in 0..launches {
        let specs = build(world, seed);
        let geos: Vec<Geo> = specs.iter().map(Geo::new).collect();
        let (mut w, hs) = make_world(&specs, mode, &dispatcher, world.gravity());
        let (mut tunnelled, mut late) = (false, false);
        for step in 0..steps {
            let before: Vec<Pose> = hs.iter().map(|h| *w.bodies[*h].position()).collect();
            let t0 = Instant::now();
            if matches!(mode, Mode::Ours | Mode::Swept) {
                // `pass.step(&mut w)`, with the pass's own time apart.
                pass.record(&w.bodies);
                let t1 = Instant::now();
                w.step();
                let t2 = Instant::now();
                let dt = w.integration_parameters.dt;
                let c = pass.clamp(&mut w.bodies, &w.colliders, dt);
                t.pass_secs += (t1 - t0).as_secs_f64() + t2.elapsed().as_secs_f64();
                t.pass_casts += c.casts;
                t.pass_clamped += c.bodies;
                t.pass_checked += c.checked;
            } else {
                w.step();
            }
            t.step_secs += t0.elapsed().as_secs_f64();
            t.steps += 1;
            if !check {
                continue;
            }
            let after: Vec<Pose> = hs.iter().map(|h| *w.bodies[*h].position()).collect();
            for i in 0..geos.len() {
                if !geos[i].dynamic {
                    continue;
                }
                for j in 0..geos.len() {
                    if j == i || (geos[j].dynamic && j < i) {
                        continue;
                    }
                    let v = check_pair(
                        &geos[i], &before[i], &after[i], &geos[j], &before[j], &after[j],
                    );
                    if verbose && (v.tunnelled || v.late) {
                        eprintln!(
                            "{} {mode:?} launch {seed} step {step}: bodies {i} {j} {}",
                            world.name(),
                            if v.tunnelled { "tunnelled" } else { "late" }
                        );
                    }
                    tunnelled |= v.tunnelled;
                    late |= v.late;
                }
            }
        }
        t.launches += 1;
        t.tunnelled += usize::from(tunnelled);
        t.late += usize::from(late);
    }
    t.stats = dispatcher.stats();
    t
}

/// The distance a ball falls in 120 steps after it is stopped at the
/// cuboid wall of `wall-cuboid` (gravity on, 9.81 down y; radius 0.05, at
/// 200 m/s from 0.5 in front of the wall, spinning at `spin` rad/s about
/// `z`, restitution 0), in `mode`.
pub(crate) fn slide(mode: Mode, spin: f64) -> f64 {
    let dispatcher = CertifiedDispatcher::new();
    let mut pass = CertifiedPass::new().with_dispatcher(dispatcher.clone());
    let mut w = PhysicsWorld::default();
    w.integration_parameters.dt = DT;
    if mode != Mode::Default {
        w.narrow_phase = NarrowPhase::with_query_dispatcher(dispatcher.clone());
    }
    let wall = SharedShape::cuboid(0.005, 4.0, 4.0);
    w.insert(
        RigidBodyBuilder::fixed(),
        ColliderBuilder::new(wall).restitution(0.0),
    );
    let ball = SharedShape::ball(0.05);
    let ball = if matches!(mode, Mode::Swept | Mode::SweptOnly) {
        Swept::shared(ball)
    } else {
        ball
    };
    let rb = RigidBodyBuilder::dynamic()
        .translation(Vector::new(-0.5, 2.0, 0.0))
        .linvel(Vector::new(200.0, 0.0, 0.0))
        .angvel(Vector::new(0.0, 0.0, spin))
        .ccd_enabled(true)
        .can_sleep(false);
    let (h, _) = w.insert(rb, ColliderBuilder::new(ball).restitution(0.0));
    let y0 = w.bodies[h].translation().y;
    for _ in 0..120 {
        if matches!(mode, Mode::Ours | Mode::Swept) {
            pass.step(&mut w);
        } else {
            w.step();
        }
    }
    y0 - w.bodies[h].translation().y
}

fn main() {
    let mut args = Args::from_env(
        "rapier_worlds [--launches 20] [--steps 150] [--world NAME] [--rounds 1] [--verbose] [--swept] [--only default|ours|no-ccd]",
    );
    let launches: u64 = args.value_or("--launches", 20);
    let steps: usize = args.value_or("--steps", STEPS);
    let verbose = args.flag("--verbose");
    let with_swept = args.flag("--swept");
    let only: Option<String> = args.value("--world");
    let rounds: usize = args.value_or("--rounds", 1);
    let only_mode: Option<String> = args.value("--only");
    args.finish();
    println!(
        "{launches} launches x {steps} steps per world, dt 1/60, gravity off (stack: on), CCD on, TOL {TOL}"
    );
    let worlds: Vec<World> = World::ALL
        .into_iter()
        .filter(|w| only.as_deref().is_none_or(|o| o == w.name()))
        .collect();
    // `--only MODE`: that setup alone, unchecked, one round (for a profiler).
    if let Some(m) = only_mode {
        let mode = match m.as_str() {
            "default" => Mode::Default,
            "ours" => Mode::Ours,
            "no-ccd" => Mode::NoCcd,
            _ => {
                eprintln!("--only takes default, ours or no-ccd");
                std::process::exit(2);
            }
        };
        for &world in &worlds {
            let t = run_world(world, mode, launches, steps, false, false);
            println!(
                "{} {m}: ms per step {:.4}, pass casts {}, checked {}, dispatcher certified casts {}",
                world.name(),
                t.ms_per_step(),
                t.pass_casts,
                t.pass_checked,
                t.stats.certified
            );
        }
        return;
    }
    let mut stats = Vec::new();
    for &world in &worlds {
        let d = run_world(world, Mode::Default, launches, steps, true, verbose);
        let o = run_world(world, Mode::Ours, launches, steps, true, verbose);
        // With `--rounds R`, R - 1 more unchecked rounds, alternated: the
        // fastest of each (the least disturbed by the machine).
        let (mut d_secs, mut o_secs) = (d.step_secs, o.step_secs);
        // The stack's reference: rapier with CCD off (checked too).
        let resting = world == World::Stack;
        let mut n_secs = f64::INFINITY;
        if resting {
            let n = run_world(world, Mode::NoCcd, launches, steps, true, verbose);
            n_secs = n.step_secs;
            println!(
                "no-ccd {}: tunnelled {}, late {}",
                world.name(),
                n.tunnelled,
                n.late
            );
        }
        for _ in 1..rounds {
            let d = run_world(world, Mode::Default, launches, steps, false, false);
            let o = run_world(world, Mode::Ours, launches, steps, false, false);
            d_secs = d_secs.min(d.step_secs);
            o_secs = o_secs.min(o.step_secs);
            if resting {
                let n = run_world(world, Mode::NoCcd, launches, steps, false, false);
                n_secs = n_secs.min(n.step_secs);
            }
        }
        if resting {
            println!(
                "resting {}: ms per step no-ccd {:.4} (ours / no-ccd {:.3})",
                world.name(),
                1e3 * n_secs / d.steps.max(1) as f64,
                o_secs / n_secs
            );
        }
        println!(
            "world {}: tunnelled default {} ours {}, late default {} ours {}, \
             ms per step default {:.4} ours {:.4}",
            world.name(),
            d.tunnelled,
            o.tunnelled,
            d.late,
            o.late,
            1e3 * d_secs / d.steps.max(1) as f64,
            1e3 * o_secs / o.steps.max(1) as f64,
        );
        if with_swept {
            for (mode, label) in [(Mode::Swept, "swept"), (Mode::SweptOnly, "swept, no pass,")] {
                let s = run_world(world, mode, launches, steps, true, verbose);
                println!(
                    "{label} {}: tunnelled {}, late {}, ms per step {:.4}, dispatcher certified casts {}",
                    world.name(),
                    s.tunnelled,
                    s.late,
                    s.ms_per_step(),
                    s.stats.certified,
                );
            }
        }
        stats.push((
            world,
            o.stats,
            o.pass_casts,
            o.pass_clamped,
            o.pass_checked,
            o.pass_secs,
            o.steps,
        ));
    }
    for (world, s, casts, clamped, checked, pass_secs, steps) in stats {
        println!(
            "stats {}: dispatcher certified casts {}, handed to parry {}; \
             pass casts {casts}, touching pairs checked without a cast {checked}, \
             bodies moved back {clamped}, pass ms per step {:.4}",
            world.name(),
            s.certified,
            s.handed_to_parry,
            1e3 * pass_secs / steps.max(1) as f64
        );
    }
    // A ball stopped at the wall, then sliding down it under gravity.
    for spin in [0.0, 24.0] {
        let d = slide(Mode::Default, spin);
        let fell = [Mode::Ours, Mode::Swept, Mode::SweptOnly].map(|m| slide(m, spin));
        println!(
            "slide, spin {spin} rad/s: fell in 120 steps default {d:.3}, ours {:.3} ({:.3} of default), \
             swept {:.3}, swept no pass {:.3}",
            fell[0],
            fell[0] / d,
            fell[1],
            fell[2],
        );
    }
    // The cost of installing the dispatcher with nothing wrapped: the same
    // launches, unchecked, default and installed alternated, five rounds;
    // the fastest round of each (the least disturbed by the machine).
    const ROUNDS: usize = 5;
    let (mut d_secs, mut i_secs, mut n) = (0.0, 0.0, 0);
    for &world in &worlds {
        let (mut d_best, mut i_best) = (f64::INFINITY, f64::INFINITY);
        let mut casts = 0;
        let mut world_steps = 0;
        for _ in 0..ROUNDS {
            let d = run_world(world, Mode::Default, launches, steps, false, false);
            let i = run_world(world, Mode::Installed, launches, steps, false, false);
            d_best = d_best.min(d.step_secs);
            i_best = i_best.min(i.step_secs);
            casts = i.stats.certified;
            world_steps = d.steps;
        }
        println!(
            "installed, nothing wrapped, {}: ms per step default {:.4} installed {:.4} \
             (certified casts {casts})",
            world.name(),
            1e3 * d_best / world_steps.max(1) as f64,
            1e3 * i_best / world_steps.max(1) as f64,
        );
        d_secs += d_best;
        i_secs += i_best;
        n += world_steps;
    }
    println!(
        "installed, nothing wrapped, all worlds: ms per step default {:.4} installed {:.4}",
        1e3 * d_secs / n.max(1) as f64,
        1e3 * i_secs / n.max(1) as f64,
    );
}
