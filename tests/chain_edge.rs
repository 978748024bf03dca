//! The edge query of kinematic chains (`ChainScene::check_edge`,
//! `edge_is_free`, `edges_are_free`, `EdgeChecker`) against truths
//! independent of the code under test:
//!
//! * `tests/common/chain_truth.rs` (its own forward kinematics, sphere trees,
//!   exact triangle distances, dense sampling whose step comes from a crude
//!   link-speed bound) for mesh obstacles and self pairs;
//! * for shape obstacles, the same truth on a *twin* scene of meshes
//!   inscribed in the shapes (a box as its 12 triangles, balls, capsules and
//!   cylinders as lathed polygons with their vertices on the surface, a
//!   half-space as a large box just below its plane, a cloud's point as a
//!   small tetrahedron inside its ball): a touch of the twin is a touch of
//!   the shape;
//! * for padding, this file's own brute-force exact triangle distances on
//!   coarse meshes, sampled with a step the crude speed bound certifies.
//!
//! What is asserted is soundness: `Free` never where the truth touches (or
//! comes within the padding), `free_until` never past the truth's first
//! touching sample, a contact's `at` within the contact distance plus the
//! padding; and, as a sanity check of tightness only, that the edge query
//! agrees with `check_segment` on most edges.
//!
//! `CHAIN_EDGE_CASES=40 cargo test --all-features --test chain_edge -- --nocapture`
//! runs more edges per scene (default 8).

#[path = "common/arm_scene.rs"]
mod arm_scene;
#[path = "common/chain_truth.rs"]
mod chain_truth;

use arm_scene::{bare_arm_scene, chain_in_f32, cuboid, random_chain, to32, to64, Arm};
use chain_truth::Truth;
use motion_bound::chain::{
    Chain, ChainBuilder, ChainError, ChainPair, ChainParams, ChainScene, EdgeOutcome, JointKind,
    JointSpec, Obstacle, SegmentOutcome, ShapeObstacle,
};
use motion_bound::testkit::toi::{random_rotation, Rng};
use motion_bound::{bodies, try_triangle_triangle, Convex, Point3, Pose, TriMesh, Vec3};

type V3 = [f64; 3];
type M3 = [[f64; 3]; 3];

/// Edges per scene (`CHAIN_EDGE_CASES`, default 8).
fn cases() -> usize {
    std::env::var("CHAIN_EDGE_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(8)
}

/// The sampling tolerance of the truth (world units).
const TOL: f64 = 1e-4;

fn limits_of<T: motion_bound::Float>(chain: &Chain<T>) -> Vec<[f64; 2]> {
    chain
        .limits()
        .into_iter()
        .map(|l| l.map_or([-3.0, 3.0], |[a, b]| [a.to_f64(), b.to_f64()]))
        .collect()
}

fn lerp(q0: &[f64], q1: &[f64], t: f64) -> Vec<f64> {
    q0.iter().zip(q1).map(|(a, b)| a + t * (b - a)).collect()
}

/// A random edge within `limits`: a planner's short edge (0.05 to 0.4 in
/// joint space) from a random start, or a long one between two random
/// configurations.
fn random_edge(rng: &mut Rng, limits: &[[f64; 2]]) -> (Vec<f64>, Vec<f64>) {
    let q0: Vec<f64> = limits.iter().map(|[lo, hi]| rng.range(*lo, *hi)).collect();
    if rng.unit() < 0.5 {
        let q1 = limits.iter().map(|[lo, hi]| rng.range(*lo, *hi)).collect();
        return (q0, q1);
    }
    let dir: Vec<f64> = limits.iter().map(|_| rng.range(-1.0, 1.0)).collect();
    let len = dir.iter().map(|x| x * x).sum::<f64>().sqrt().max(1e-9);
    let step = rng.range(0.05, 0.4);
    let q1 = q0
        .iter()
        .zip(&dir)
        .zip(limits)
        .map(|((a, d), [lo, hi])| (a + d / len * step).clamp(*lo, *hi))
        .collect();
    (q0, q1)
}

/// Boxes and thin poles around a random chain (faces in squares at most
/// `cell` wide).
fn add_mesh_obstacles(scene: &mut ChainScene<f64>, cell: f64) {
    for (i, (c, h)) in [
        ([0.45, 0.1, 0.3], [0.05, 0.2, 0.02]),
        ([-0.3, 0.35, 0.4], [0.005, 0.005, 0.5]),
        ([0.1, -0.4, 0.4], [0.005, 0.005, 0.5]),
        ([0.0, 0.0, -0.05], [0.8, 0.8, 0.02]),
        ([-0.25, -0.2, 0.55], [0.06, 0.04, 0.05]),
    ]
    .into_iter()
    .enumerate()
    {
        let (m, p) = cuboid(c, h, cell).expect("box");
        scene.add_obstacle(Obstacle::try_new(format!("o{i}"), m, p).expect("obstacle"));
    }
}

/// What a batch of edges gave against the truth.
#[derive(Debug, Default)]
struct Tally {
    edges: usize,
    /// Edges on which the truth's surfaces meet.
    colliding: usize,
    free: usize,
    contacts: usize,
    undecided: usize,
    /// Free where the truth touches.
    missed: usize,
    /// `free_until` past the truth's first touching sample.
    late: usize,
    /// A contact's `at` where the truth's surfaces are farther than the
    /// contact distance plus the padding (checked for mesh scenes only).
    far: usize,
    /// `free_until` outside `[0, 1]` or after `at`.
    malformed: usize,
    /// Edges on which `check_segment` was compared, and agreed.
    compared: usize,
    agreed: usize,
}

impl Tally {
    fn add(&mut self, o: &Tally) {
        self.edges += o.edges;
        self.colliding += o.colliding;
        self.free += o.free;
        self.contacts += o.contacts;
        self.undecided += o.undecided;
        self.missed += o.missed;
        self.late += o.late;
        self.far += o.far;
        self.malformed += o.malformed;
        self.compared += o.compared;
        self.agreed += o.agreed;
    }

    fn unsound(&self) -> (usize, usize, usize, usize) {
        (self.missed, self.late, self.far, self.malformed)
    }
}

/// Checks `n` random edges of `scene` (its edge query) against `truth` (of
/// `scene` itself, or of its inscribed twin). `at_distance` checks a
/// contact's `at` against the truth's distance (meaningful only when the
/// truth's meshes are the scene's); `segment` compares with
/// `check_segment` (mesh scenes only). Of every four edges, two start and
/// end where the truth does not touch, one starts there and ends where it
/// touches (when one is found in 200 tries), one is any.
fn check_edges(
    scene: &ChainScene<f64>,
    truth: &Truth,
    n: usize,
    seed: u64,
    at_distance: bool,
    segment: bool,
) -> Tally {
    let limits = limits_of(scene.chain());
    let mut rng = Rng::new(seed);
    let mut tally = Tally::default();
    let p = scene.params();
    let touch_distance = p.contact_distance + p.padding;
    for e in 0..n {
        let mut tries = 0;
        let (q0, q1) = loop {
            let (q0, q1) = random_edge(&mut rng, &limits);
            tries += 1;
            let ok = match e % 4 {
                3 => true,
                // Towards a configuration the truth finds touching.
                2 => !truth.touches_at(&q0) && truth.touches_at(&q1),
                _ => !(truth.touches_at(&q0) || truth.touches_at(&q1)),
            };
            if ok || tries > 200 {
                break (q0, q1);
            }
        };
        let report = scene.check_edge(&q0, &q1).expect("a valid edge");
        let sampled = truth.sample(&q0, &q1, TOL);
        tally.edges += 1;
        let until = match report.outcome {
            EdgeOutcome::Free => {
                tally.free += 1;
                None
            }
            EdgeOutcome::Contact {
                free_until,
                at,
                pair,
            } => {
                tally.contacts += 1;
                if !(0.0..=1.0).contains(&free_until) || !(free_until..=1.0).contains(&at) {
                    tally.malformed += 1;
                    eprintln!("edge {e}: malformed {report:?}");
                }
                if at_distance {
                    let (d, _) = truth.min_distance(&lerp(&q0, &q1, at));
                    if d > touch_distance * (1.0 + 1e-6) + 1e-12 {
                        tally.far += 1;
                        eprintln!(
                            "edge {e}: contact {pair:?} at {at} with the truth's surfaces {d} apart; q0 {q0:?} q1 {q1:?}"
                        );
                    }
                }
                Some(free_until)
            }
            EdgeOutcome::Undecided { free_until } => {
                tally.undecided += 1;
                if !(0.0..=1.0).contains(&free_until) {
                    tally.malformed += 1;
                }
                Some(free_until)
            }
            other => panic!("an unknown outcome {other:?}"),
        };
        if let Some((t_touch, lower, pair)) = sampled.touch {
            tally.colliding += 1;
            match until {
                None => {
                    tally.missed += 1;
                    eprintln!(
                        "edge {e}: Free but the truth touches in [{lower}, {t_touch}] ({pair:?}); q0 {q0:?} q1 {q1:?}"
                    );
                }
                Some(u) if u > t_touch => {
                    tally.late += 1;
                    eprintln!(
                        "edge {e}: free until {u} past the truth's touch in [{lower}, {t_touch}] ({pair:?}): {report:?}; q0 {q0:?} q1 {q1:?}"
                    );
                }
                Some(_) => {}
            }
        }
        if segment {
            let s = scene.check_segment(&q0, &q1).expect("a valid segment");
            let both = match (s.outcome, report.outcome) {
                (SegmentOutcome::Separated, EdgeOutcome::Free) => Some(true),
                (SegmentOutcome::Contact(_), EdgeOutcome::Contact { .. }) => Some(true),
                (SegmentOutcome::IterationLimit { .. }, _) | (_, EdgeOutcome::Undecided { .. }) => {
                    None
                }
                _ => Some(false),
            };
            if let Some(agree) = both {
                tally.compared += 1;
                tally.agreed += usize::from(agree);
                if !agree {
                    eprintln!(
                        "edge {e}: check_segment {:?}, check_edge {:?}",
                        s.outcome, report.outcome
                    );
                }
            }
        }
    }
    tally
}

/// Lemma 13.5 end to end on mesh obstacles: random chains of every joint
/// kind (revolute, continuous, prismatic, fixed) among boxes and thin
/// poles; no edge the truth touches is Free, `free_until` is never past the
/// truth's first touching sample, a contact's `at` is within the contact
/// distance of the truth's surfaces; and (tightness, not soundness) the
/// edge query's free/contact verdict agrees with `check_segment`'s on at
/// least 80 % of the edges.
#[test]
fn edges_on_random_chains_are_never_free_or_late_where_the_truth_touches() {
    let mut rng = Rng::new(39);
    let mut total = Tally::default();
    for k in 0..5u64 {
        let mut scene = ChainScene::new(random_chain(&mut rng, 2 + (k as usize) % 5, 0.05));
        add_mesh_obstacles(&mut scene, 0.05);
        let truth = Truth::new(&scene);
        let t = check_edges(&scene, &truth, cases(), 1000 + k, true, true);
        total.add(&t);
    }
    eprintln!("random chains, mesh obstacles: {total:?}");
    assert_eq!(total.unsound(), (0, 0, 0, 0), "{total:?}");
    assert!(
        total.colliding > 0 && total.free > 0,
        "the edges both hit and miss: {total:?}"
    );
    assert!(
        total.agreed * 5 >= total.compared * 4,
        "check_edge agrees with check_segment on most edges: {total:?}"
    );
}

// ---------------------------------------------------------------------------
// Shapes and their inscribed twins.

fn mesh(vertices: Vec<V3>, triangles: Vec<[u32; 3]>) -> TriMesh<f64> {
    TriMesh::try_new(vertices, triangles).expect("an inscribed mesh")
}

/// The box of half extents `h` exactly: its 8 corners, 12 triangles
/// (`bodies::cuboid`: `2 h / 2` is `h`).
fn box_mesh(h: V3) -> TriMesh<f64> {
    bodies::cuboid(h.map(|x| 2.0 * x)).expect("a box")
}

/// A surface of revolution about the `y` axis through the profile's points
/// `(rho, y)` (first and last with `rho = 0`: the poles), `sides` points a
/// ring. Every vertex is on the solid's surface (pulled towards the origin
/// by `1e-12` of itself, so rounding keeps it inside a convex solid about
/// the origin); the triangles, spanned by points of a convex solid, are
/// inside it.
fn lathe(profile: &[(f64, f64)], sides: u32) -> TriMesh<f64> {
    let shrink = 1.0 - 1e-12;
    let mut v: Vec<V3> = Vec::new();
    let mut t: Vec<[u32; 3]> = Vec::new();
    let last = profile.len() - 1;
    v.push([0.0, profile[0].1 * shrink, 0.0]);
    for &(rho, y) in &profile[1..last] {
        for k in 0..sides {
            let phi = f64::from(k) * std::f64::consts::TAU / f64::from(sides);
            v.push([
                rho * phi.cos() * shrink,
                y * shrink,
                rho * phi.sin() * shrink,
            ]);
        }
    }
    v.push([0.0, profile[last].1 * shrink, 0.0]);
    let rings = (last - 1) as u32;
    let at = |r: u32, k: u32| 1 + r * sides + k % sides;
    for k in 0..sides {
        t.push([0, at(0, k + 1), at(0, k)]);
        for r in 0..rings - 1 {
            t.push([at(r, k), at(r, k + 1), at(r + 1, k + 1)]);
            t.push([at(r, k), at(r + 1, k + 1), at(r + 1, k)]);
        }
        let top = v.len() as u32 - 1;
        t.push([top, at(rings - 1, k), at(rings - 1, k + 1)]);
    }
    mesh(v, t)
}

/// The capsule of the segment `|y| <= h` and radius `r` (a ball for
/// `h = 0`), inscribed.
fn capsule_mesh(h: f64, r: f64) -> TriMesh<f64> {
    let mut profile = vec![(0.0, -h - r)];
    let k = 6;
    for i in 1..=k {
        let a = f64::from(i) / f64::from(k) * std::f64::consts::FRAC_PI_2;
        profile.push((r * a.sin(), -h - r * a.cos()));
    }
    for i in (0..k).rev() {
        let a = f64::from(i) / f64::from(k) * std::f64::consts::FRAC_PI_2;
        profile.push((r * a.sin(), h + r * a.cos()));
    }
    // The last pushed is (0, h + r): the top pole.
    lathe(&profile, 16)
}

/// The cylinder `|y| <= h` of radius `r`, inscribed.
fn cylinder_mesh(h: f64, r: f64) -> TriMesh<f64> {
    lathe(&[(0.0, -h), (r, -h), (r, h), (0.0, h)], 16)
}

/// A small tetrahedron inside the ball of radius `r` about `p` (its
/// corners on the sphere, pulled in by `1e-9` of the radius).
fn tetra_in_ball(p: V3, r: f64, v: &mut Vec<V3>, t: &mut Vec<[u32; 3]>) {
    let s = r * (1.0 - 1e-9) / 3f64.sqrt();
    let base = v.len() as u32;
    for c in [
        [1.0, 1.0, 1.0],
        [1.0, -1.0, -1.0],
        [-1.0, 1.0, -1.0],
        [-1.0, -1.0, 1.0],
    ] {
        v.push([p[0] + s * c[0], p[1] + s * c[1], p[2] + s * c[2]]);
    }
    for f in [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]] {
        t.push(f.map(|i| base + i));
    }
}

/// A rotation whose third column is the unit `m`.
fn frame_with_z(m: V3) -> M3 {
    let a = if m[0].abs() < 0.9 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let cross = |a: V3, b: V3| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let u = cross(a, m);
    let l = (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]).sqrt();
    let u = u.map(|x| x / l);
    let w = cross(m, u);
    [0, 1, 2].map(|i| [u[i], w[i], m[i]])
}

/// A chain scene with shape obstacles, and its twin with the shapes as
/// inscribed meshes (same chain, same allowed pairs).
struct Twin {
    shaped: ChainScene<f64>,
    meshed: ChainScene<f64>,
}

impl Twin {
    fn new(chain: Chain<f64>) -> Self {
        Self {
            shaped: ChainScene::new(chain.clone()),
            meshed: ChainScene::new(chain),
        }
    }

    fn convex(
        &mut self,
        name: &str,
        shape: Convex<'static, f64>,
        inside: TriMesh<f64>,
        at: Pose<f64>,
    ) {
        self.shaped
            .add_shape(ShapeObstacle::try_new(name, shape, at).expect("a shape"));
        self.meshed
            .add_obstacle(Obstacle::try_new(name, inside, at).expect("its twin"));
    }

    /// The half-space below the plane through `point` with unit normal `m`;
    /// its twin a box 2.4 wide and 0.4 deep whose top face is `1e-9` below
    /// the plane.
    fn half_space(&mut self, m: V3, point: V3) {
        self.shaped
            .add_shape(ShapeObstacle::try_half_space("half", m, point).expect("a half-space"));
        let depth = 0.2;
        let c = [0, 1, 2].map(|k| point[k] - m[k] * (depth + 1e-9));
        let at = Pose::new(frame_with_z(m), Vec3::from_array(c));
        let twin = box_mesh([1.2, 1.2, depth]);
        self.meshed
            .add_obstacle(Obstacle::try_new("half", twin, at).expect("its twin"));
    }

    fn cloud(&mut self, points: &[V3], r: f64) {
        self.shaped
            .add_shape(ShapeObstacle::try_points("cloud", points, r).expect("a cloud"));
        let (mut v, mut t) = (Vec::new(), Vec::new());
        for p in points {
            tetra_in_ball(*p, r, &mut v, &mut t);
        }
        self.meshed.add_obstacle(
            Obstacle::try_new("cloud", mesh(v, t), Pose::IDENTITY).expect("its twin"),
        );
    }
}

fn random_pose(rng: &mut Rng, reach: f64) -> Pose<f64> {
    let c = [
        rng.range(-reach, reach),
        rng.range(-reach, reach),
        rng.range(0.0, 0.9),
    ];
    Pose::new(random_rotation(rng), Vec3::from_array(c))
}

/// A random chain among random shapes of every kind: a cuboid, a ball, a
/// capsule, a cylinder, a floor (half-space) and a tilted wall, and a
/// point cloud of small balls.
fn random_twin(rng: &mut Rng, joints: usize) -> Twin {
    let mut twin = Twin::new(random_chain(rng, joints, 0.05));
    let h = [
        rng.range(0.01, 0.15),
        rng.range(0.01, 0.15),
        rng.range(0.01, 0.15),
    ];
    let at = random_pose(rng, 0.5);
    twin.convex(
        "cuboid",
        Convex::try_cuboid(h).expect("cuboid"),
        box_mesh(h),
        at,
    );
    let r = rng.range(0.02, 0.12);
    let at = random_pose(rng, 0.5);
    twin.convex(
        "ball",
        Convex::try_ball(r).expect("ball"),
        capsule_mesh(0.0, r),
        at,
    );
    let (hh, r) = (rng.range(0.05, 0.3), rng.range(0.005, 0.05));
    let at = random_pose(rng, 0.5);
    twin.convex(
        "capsule",
        Convex::try_capsule(hh, r).expect("capsule"),
        capsule_mesh(hh, r),
        at,
    );
    let (hh, r) = (rng.range(0.05, 0.4), rng.range(0.005, 0.06));
    let at = random_pose(rng, 0.5);
    twin.convex(
        "cylinder",
        Convex::try_cylinder(hh, r).expect("cylinder"),
        cylinder_mesh(hh, r),
        at,
    );
    twin.half_space([0.0, 0.0, 1.0], [0.0, 0.0, rng.range(-0.2, 0.0)]);
    let m = [
        rng.range(-1.0, 1.0),
        rng.range(-1.0, 1.0),
        rng.range(-0.3, 0.3),
    ];
    let l = (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]).sqrt().max(1e-3);
    let m = m.map(|x| -x / l);
    // The wall's plane 0.5 to 0.8 from the base, on the side `-m` points to.
    let d = rng.range(0.5, 0.8);
    twin.half_space(m, [-m[0] * d, -m[1] * d, -m[2] * d]);
    let centre = [
        rng.range(-0.4, 0.4),
        rng.range(-0.4, 0.4),
        rng.range(0.2, 0.7),
    ];
    let points: Vec<V3> = (0..40)
        .map(|_| {
            [
                centre[0] + rng.range(-0.1, 0.1),
                centre[1] + rng.range(-0.1, 0.1),
                centre[2] + rng.range(-0.02, 0.02),
            ]
        })
        .collect();
    twin.cloud(&points, rng.range(0.002, 0.03));
    twin
}

/// Lemma 13.6 end to end on shape obstacles: random chains among cuboids,
/// balls, capsules, cylinders, half-spaces and point clouds; the truth runs
/// on the twin scene of inscribed meshes, so a truth touch is a real touch.
/// No edge the truth touches is Free, and `free_until` is never past the
/// truth's first touching sample.
#[test]
fn edges_among_shapes_are_never_free_or_late_where_the_inscribed_truth_touches() {
    let mut rng = Rng::new(6);
    let mut total = Tally::default();
    for k in 0..5u64 {
        let twin = random_twin(&mut rng, 2 + (k as usize) % 4);
        let truth = Truth::new(&twin.meshed);
        let t = check_edges(&twin.shaped, &truth, cases(), 2000 + k, false, false);
        total.add(&t);
    }
    eprintln!("random chains, shape obstacles: {total:?}");
    assert_eq!(total.unsound(), (0, 0, 0, 0), "{total:?}");
    assert!(
        total.colliding > 0 && total.free > 0,
        "the edges both hit and miss: {total:?}"
    );
}

/// Each kind of shape alone (so a miss names its kind), with a random chain
/// sweeping through it: the same checks as above.
#[test]
fn each_shape_kind_alone_is_never_missed() {
    let mut rng = Rng::new(17);
    for kind in 0..6 {
        let mut total = Tally::default();
        for k in 0..3u64 {
            let mut twin = Twin::new(random_chain(&mut rng, 3 + k as usize, 0.05));
            let at = random_pose(&mut rng, 0.35);
            match kind {
                0 => {
                    let h = [
                        rng.range(0.0, 0.2),
                        rng.range(0.01, 0.2),
                        rng.range(0.01, 0.2),
                    ];
                    // A zero extent: a rectangle (its twin two flat triangles a face).
                    twin.convex(
                        "cuboid",
                        Convex::try_cuboid(h).expect("cuboid"),
                        box_mesh(h),
                        at,
                    );
                }
                1 => {
                    let r = rng.range(0.01, 0.2);
                    twin.convex(
                        "ball",
                        Convex::try_ball(r).expect("ball"),
                        capsule_mesh(0.0, r),
                        at,
                    );
                }
                2 => {
                    let (h, r) = (rng.range(0.05, 0.4), rng.range(0.003, 0.08));
                    twin.convex(
                        "capsule",
                        Convex::try_capsule(h, r).expect("capsule"),
                        capsule_mesh(h, r),
                        at,
                    );
                }
                3 => {
                    let (h, r) = (rng.range(0.02, 0.5), rng.range(0.003, 0.1));
                    twin.convex(
                        "cylinder",
                        Convex::try_cylinder(h, r).expect("cylinder"),
                        cylinder_mesh(h, r),
                        at,
                    );
                }
                4 => {
                    let m = [rng.range(-0.3, 0.3), rng.range(-0.3, 0.3), 1.0];
                    let l = (m[0] * m[0] + m[1] * m[1] + 1.0).sqrt();
                    // Below the base (the first link starts 0.05 above it).
                    twin.half_space(m.map(|x| x / l), [0.0, 0.0, rng.range(-0.3, 0.0)]);
                }
                _ => {
                    let c = at.translation.to_array();
                    let points: Vec<V3> = (0..60)
                        .map(|_| [0, 1, 2].map(|k| c[k] + rng.range(-0.15, 0.15)))
                        .collect();
                    twin.cloud(&points, rng.range(0.001, 0.04));
                }
            }
            let truth = Truth::new(&twin.meshed);
            let t = check_edges(
                &twin.shaped,
                &truth,
                cases(),
                3000 + 10 * kind + k,
                false,
                false,
            );
            total.add(&t);
        }
        eprintln!("shape kind {kind}: {total:?}");
        assert_eq!(
            total.unsound(),
            (0, 0, 0, 0),
            "shape kind {kind}: {total:?}"
        );
    }
}

/// Self pairs (Lemma 13.2, part 3, through the edge query): the Panda alone
/// (its SRDF's disabled pairs and those touching at its ready pose
/// allowed), long and short edges; never Free or late where the truth's
/// links meet, contacts within the contact distance.
#[test]
fn panda_self_collision_edges_are_never_free_or_late() {
    let (scene, _) = bare_arm_scene(Arm::Panda).expect("the Panda");
    let truth = Truth::new(&scene);
    let t = check_edges(&scene, &truth, cases(), 77, true, false);
    eprintln!("panda self pairs: {t:?}");
    assert_eq!(t.unsound(), (0, 0, 0, 0), "{t:?}");
    assert!(t.colliding > 0, "the links meet on some edges: {t:?}");
}

// ---------------------------------------------------------------------------
// Padding: this file's own exact distances.

/// Link and obstacle triangles in their own frames, for brute force.
struct Exact {
    truth: Truth,
    links: Vec<Vec<[V3; 3]>>,
    obstacles: Vec<Vec<[V3; 3]>>,
}

impl Exact {
    fn new(scene: &ChainScene<f64>) -> Self {
        let chain = scene.chain();
        let links = (0..chain.link_count())
            .map(|l| {
                chain
                    .link_mesh(l)
                    .map_or_else(Vec::new, |m| m.triangle_corners().collect())
            })
            .collect();
        let obstacles = scene
            .obstacles()
            .iter()
            .map(|o| {
                let p = o.pose();
                let x = p.translation.to_array();
                o.mesh()
                    .triangle_corners()
                    .map(|t| t.map(|v| place(&p.rotation, x, v)))
                    .collect()
            })
            .collect();
        Self {
            truth: Truth::new(scene),
            links,
            obstacles,
        }
    }

    /// The exact distance of `pair` at `q` (brute force over the triangles).
    fn pair_distance(&self, pair: ChainPair, q: &[f64]) -> f64 {
        let places = self.truth.places(q);
        let at = |l: usize| -> Vec<[V3; 3]> {
            self.links[l]
                .iter()
                .map(|t| t.map(|v| place(&places[l].r, places[l].x, v)))
                .collect()
        };
        let (a, b) = match pair {
            ChainPair::Obstacle { link, obstacle } => (at(link), self.obstacles[obstacle].clone()),
            ChainPair::SelfCollision { a, b } => (at(a), at(b)),
            _ => unreachable!("meshes only"),
        };
        let mut best = f64::INFINITY;
        for ta in &a {
            for tb in &b {
                let d =
                    try_triangle_triangle(&ta.map(Point3::from_array), &tb.map(Point3::from_array))
                        .map_or(0.0, |c| c.distance);
                best = best.min(d);
            }
        }
        best
    }

    /// The first time in `[0, 1]` at which some pair comes within `p`,
    /// sampled pair by pair with steps of `max(d - p, TOL) / L` (`L` the
    /// truth's crude speed bound of the pair: no pair comes within `p - TOL`
    /// between samples); and the least distance seen.
    fn first_within(&self, q0: &[f64], q1: &[f64], p: f64) -> (Option<f64>, f64) {
        let mut first: Option<f64> = None;
        let mut least = f64::INFINITY;
        for &pair in &self.truth.pairs {
            let l = match pair {
                ChainPair::Obstacle { link, .. } => self.truth.crude_speed(link, q0, q1),
                ChainPair::SelfCollision { a, b } => {
                    self.truth.crude_speed(a, q0, q1) + self.truth.crude_speed(b, q0, q1)
                }
                _ => unreachable!("meshes only"),
            };
            let until = first.unwrap_or(1.0);
            let mut t = 0.0f64;
            loop {
                let d = self.pair_distance(pair, &lerp(q0, q1, t));
                least = least.min(d);
                if d <= p {
                    first = Some(first.map_or(t, |f| f.min(t)));
                    break;
                }
                if l <= 0.0 || t >= until {
                    break;
                }
                t = (t + (d - p).max(TOL) / l).min(until);
            }
        }
        (first, least)
    }
}

fn place(r: &M3, x: V3, v: V3) -> V3 {
    [0, 1, 2].map(|i| r[i][0] * v[0] + r[i][1] * v[1] + r[i][2] * v[2] + x[i])
}

/// Padding: with `ChainParams::padding` p, an edge is Free only if every
/// pair stays more than `p` apart (this file's exact distances, sampled
/// with a certified step: the least distance sampled exceeds `p - TOL`);
/// `free_until` is never past the first sample within `p`, and a contact's
/// `at` is within the contact distance plus `p` (exactly).
#[test]
fn padded_edges_keep_the_padding_by_exact_distances() {
    let mut rng = Rng::new(8);
    let mut counts = [0usize; 4]; // edges, free, within the padding, contacts
    for k in 0..4u64 {
        // Coarse meshes (12 triangles a box) for the brute force.
        let mut scene = ChainScene::new(random_chain(&mut rng, 2 + k as usize, 10.0));
        add_mesh_obstacles(&mut scene, 10.0);
        let pad = [0.005, 0.02, 0.05, 0.1][k as usize];
        scene
            .set_params(ChainParams::default().with_padding(pad))
            .expect("a padding");
        let cd = scene.params().contact_distance;
        let exact = Exact::new(&scene);
        let limits = limits_of(scene.chain());
        for e in 0..cases() {
            let (q0, q1) = random_edge(&mut rng, &limits);
            let report = scene.check_edge(&q0, &q1).expect("a valid edge");
            let (first, least) = exact.first_within(&q0, &q1, pad);
            counts[0] += 1;
            counts[2] += usize::from(first.is_some());
            match report.outcome {
                EdgeOutcome::Free => {
                    counts[1] += 1;
                    assert!(
                        first.is_none() && least > pad - TOL,
                        "scene {k} edge {e}: Free with padding {pad} but the surfaces come {least} apart (first at {first:?}); q0 {q0:?} q1 {q1:?}"
                    );
                }
                EdgeOutcome::Contact {
                    free_until,
                    at,
                    pair,
                } => {
                    counts[3] += 1;
                    assert!(
                        first.is_none_or(|f| free_until <= f),
                        "scene {k} edge {e}: free until {free_until} past the first sample within {pad} at {first:?}"
                    );
                    let d = exact.pair_distance(pair, &lerp(&q0, &q1, at));
                    assert!(
                        d <= (cd + pad) * (1.0 + 1e-9) + 1e-12,
                        "scene {k} edge {e}: contact {pair:?} at {at} with the surfaces {d} apart (padding {pad})"
                    );
                }
                EdgeOutcome::Undecided { free_until } => {
                    assert!(
                        first.is_none_or(|f| free_until <= f),
                        "scene {k} edge {e}: undecided free until {free_until} past {first:?}"
                    );
                }
                other => panic!("an unknown outcome {other:?}"),
            }
        }
    }
    eprintln!("padding: edges, free, within the padding, contacts: {counts:?}");
    assert!(
        counts[1] > 0 && counts[2] > 0,
        "both kinds of edge: {counts:?}"
    );
}

// ---------------------------------------------------------------------------
// f32.

/// `f32` chains: random chains in `f32` among `f32` mesh boxes and `f32`
/// cuboid shapes and a floor; the `f64` truth of exactly the same numbers
/// (the shapes as their exact boxes) never touches on an edge the `f32`
/// query calls Free, nor before its `free_until`.
#[test]
fn f32_edges_are_never_free_where_the_f64_truth_touches() {
    let mut rng = Rng::new(32);
    let mut total = Tally::default();
    for k in 0..4u64 {
        let chain = random_chain(&mut rng, 2 + k as usize, 0.05);
        let (c32, c64) = chain_in_f32(&chain);
        let mut s32 = ChainScene::new(c32);
        let mut s64 = ChainScene::new(c64);
        let mut meshes = ChainScene::new(chain);
        add_mesh_obstacles(&mut meshes, 0.05);
        for o in meshes.obstacles() {
            let m32 = o.mesh().try_convert::<f32>().expect("f32 obstacle");
            let p32 = to32(&o.pose());
            let m64 = m32.try_convert::<f64>().expect("back");
            s64.add_obstacle(Obstacle::try_new(o.name(), m64, to64(&p32)).expect("obstacle"));
            s32.add_obstacle(Obstacle::try_new(o.name(), m32, p32).expect("obstacle"));
        }
        for i in 0..2 {
            let h = [0; 3].map(|_| rng.range(0.02, 0.15) as f32);
            let p32 = to32(&random_pose(&mut rng, 0.5));
            s32.add_shape(
                ShapeObstacle::try_new(format!("box{i}"), Convex::try_cuboid(h).expect("box"), p32)
                    .expect("shape"),
            );
            let h64 = h.map(f64::from);
            s64.add_obstacle(
                Obstacle::try_new(format!("box{i}"), box_mesh(h64), to64(&p32)).expect("twin"),
            );
        }
        let z = rng.range(-0.1, 0.0) as f32;
        s32.add_shape(
            ShapeObstacle::try_half_space("floor", [0.0, 0.0, 1.0], [0.0, 0.0, z]).expect("floor"),
        );
        let floor = Pose::from_translation(Vec3::new(0.0, 0.0, f64::from(z) - 0.2 - 1e-9));
        s64.add_obstacle(
            Obstacle::try_new("floor", box_mesh([1.2, 1.2, 0.2]), floor).expect("twin"),
        );
        let truth = Truth::new(&s64);
        let limits = limits_of(s64.chain());
        for e in 0..cases() {
            let (q0, q1) = random_edge(&mut rng, &limits);
            let q0: Vec<f32> = q0.iter().map(|&x| x as f32).collect();
            let q1: Vec<f32> = q1.iter().map(|&x| x as f32).collect();
            let report = s32.check_edge(&q0, &q1).expect("a valid edge");
            let (d0, d1): (Vec<f64>, Vec<f64>) = (
                q0.iter().map(|&x| f64::from(x)).collect(),
                q1.iter().map(|&x| f64::from(x)).collect(),
            );
            total.edges += 1;
            let until = match report.outcome {
                EdgeOutcome::Free => {
                    total.free += 1;
                    None
                }
                EdgeOutcome::Contact { free_until, .. } => {
                    total.contacts += 1;
                    Some(f64::from(free_until))
                }
                EdgeOutcome::Undecided { free_until } => Some(f64::from(free_until)),
                other => panic!("an unknown outcome {other:?}"),
            };
            if let Some((t_touch, _, pair)) = truth.sample(&d0, &d1, TOL).touch {
                total.colliding += 1;
                match until {
                    None => {
                        total.missed += 1;
                        eprintln!("f32 scene {k} edge {e}: Free, the f64 truth touches at {t_touch} ({pair:?}); q0 {q0:?} q1 {q1:?}");
                    }
                    Some(u) if u > t_touch => {
                        total.late += 1;
                        eprintln!("f32 scene {k} edge {e}: free until {u} past the truth's touch at {t_touch}");
                    }
                    Some(_) => {}
                }
            }
        }
    }
    eprintln!("f32: {total:?}");
    assert_eq!(total.unsound(), (0, 0, 0, 0), "{total:?}");
    assert!(
        total.colliding > 0,
        "the f32 edges hit something: {total:?}"
    );
}

// ---------------------------------------------------------------------------
// Bad input, budgets, batches.

/// A one-joint arm (limits `[-3, 3]`) and a pole shape in its way.
fn small_scene() -> ChainScene<f64> {
    let mut b = ChainBuilder::new();
    let base = b.add_link("base", None).expect("link");
    let (bar, _) = cuboid([0.0; 3], [0.5, 0.01, 0.01], 0.05).expect("bar");
    let bar = bar.translated([0.5, 0.0, 0.0]).expect("shift");
    let arm = b.add_link("arm", Some(bar)).expect("link");
    b.add_joint(JointSpec {
        name: "j".into(),
        kind: JointKind::Revolute,
        parent: base,
        child: arm,
        origin: Pose::IDENTITY,
        axis: [0.0, 0.0, 1.0],
        limits: Some([-3.0, 3.0]),
    })
    .expect("joint");
    let mut scene = ChainScene::new(b.build().expect("chain"));
    let upright = Pose::new(
        [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]],
        Vec3::new(0.0, 0.6, 0.0),
    );
    scene.add_shape(
        ShapeObstacle::try_new(
            "pole",
            Convex::try_cylinder(0.5, 0.005).expect("pole"),
            upright,
        )
        .expect("shape"),
    );
    scene
}

/// Bad input is refused with the typed `ChainError` by every edge entry
/// point (wrong length, NaN, infinite and huge coordinates, ends beyond the
/// limits unless the check is off), bad parameters and shapes too; a scene
/// with shapes refuses the first-contact queries; a budget of one item is
/// `Undecided` (free until a time in `[0, 1]`, never past the contact),
/// never a panic.
#[test]
fn bad_edge_input_is_a_typed_error_and_a_tiny_budget_is_undecided() {
    let mut scene = small_scene();
    let wrong = ChainError::WrongDof {
        expected: 1,
        got: 2,
    };
    let expect = |q0: &[f64], q1: &[f64], want: ChainError, scene: &ChainScene<f64>| {
        assert_eq!(
            scene.check_edge(q0, q1).err(),
            Some(want.clone()),
            "check_edge {q0:?} {q1:?}"
        );
        assert_eq!(
            scene.edge_is_free(q0, q1).err(),
            Some(want.clone()),
            "edge_is_free {q0:?} {q1:?}"
        );
        assert_eq!(
            scene.edge_checker().check(q0, q1).err(),
            Some(want.clone()),
            "EdgeChecker::check {q0:?} {q1:?}"
        );
        let edges = vec![(vec![0.0], vec![0.5]), (q0.to_vec(), q1.to_vec())];
        assert_eq!(
            scene.edges_are_free(&edges).err(),
            Some(want),
            "edges_are_free {q0:?} {q1:?}"
        );
    };
    expect(&[0.0, 0.0], &[1.0], wrong, &scene);
    expect(
        &[0.0],
        &[],
        ChainError::WrongDof {
            expected: 1,
            got: 0,
        },
        &scene,
    );
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 1e300] {
        expect(&[0.0], &[bad], ChainError::NonFiniteCoordinate(0), &scene);
        expect(&[bad], &[0.0], ChainError::NonFiniteCoordinate(0), &scene);
    }
    expect(&[0.0], &[3.0 + 1e-9], ChainError::BeyondLimits(0), &scene);
    expect(&[-3.5], &[0.0], ChainError::BeyondLimits(0), &scene);
    // Shapes: every query takes them (issue 63; `tests/chain_kinds.rs`
    // checks their answers against the truth).
    assert!(
        scene.check_segment(&[0.0], &[1.0]).is_ok(),
        "check_segment with shapes"
    );
    assert!(
        scene.check_path(&[[0.0], [1.0]]).is_ok(),
        "check_path with shapes"
    );
    assert!(scene.clearance(&[0.0]).is_ok(), "clearance with shapes");
    assert!(scene.collides_at(&[0.0]).is_ok(), "collides_at with shapes");
    // Bad parameters.
    for bad in [
        ChainParams::default().with_padding(-1e-3),
        ChainParams::default().with_padding(f64::NAN),
        ChainParams::default().with_padding(f64::INFINITY),
        ChainParams::default().with_edge_budget(0),
    ] {
        assert!(
            matches!(scene.set_params(bad), Err(ChainError::InvalidParameter(_))),
            "{bad:?}"
        );
    }
    // Bad shapes.
    assert!(matches!(
        ShapeObstacle::try_half_space("h", [0.0; 3], [0.0; 3]),
        Err(ChainError::Shape(_))
    ));
    assert!(matches!(
        ShapeObstacle::try_half_space("h", [f64::NAN, 0.0, 1.0], [0.0; 3]),
        Err(ChainError::Shape(_))
    ));
    assert!(matches!(
        ShapeObstacle::try_half_space("h", [0.0, 0.0, 1.0], [f64::INFINITY, 0.0, 0.0]),
        Err(ChainError::Shape(_))
    ));
    assert!(matches!(
        ShapeObstacle::<f64>::try_points("c", &[], 0.1),
        Err(ChainError::Shape(_))
    ));
    assert!(matches!(
        ShapeObstacle::try_points("c", &[[0.0; 3]], -0.1),
        Err(ChainError::Shape(_))
    ));
    assert!(matches!(
        ShapeObstacle::try_points("c", &[[0.0; 3]], f64::NAN),
        Err(ChainError::Shape(_))
    ));
    assert!(matches!(
        ShapeObstacle::try_points("c", &[[f64::NAN, 0.0, 0.0]], 0.1),
        Err(ChainError::Shape(_))
    ));
    let nan_pose = Pose::from_translation(Vec3::new(f64::NAN, 0.0, 0.0));
    assert!(matches!(
        ShapeObstacle::try_new("b", Convex::try_ball(0.1).expect("ball"), nan_pose),
        Err(ChainError::InvalidParameter(_))
    ));
    let not_rotation = Pose::new(
        [[3.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        Vec3::new(0.0, 0.0, 0.0),
    );
    assert!(matches!(
        ShapeObstacle::try_new("b", Convex::try_ball(0.1).expect("ball"), not_rotation),
        Err(ChainError::InvalidParameter(_))
    ));
    // Beyond the limits with the check off: answered.
    scene
        .set_params(ChainParams::default().with_within_limits(false))
        .expect("params");
    assert!(
        scene.check_edge(&[-3.5], &[3.5]).is_ok(),
        "the limit check off"
    );
    // A budget of one item: undecided, free until a time before the pole
    // (the bar meets it near pi/2 - 0.02 rad, t about 0.52 of 0 -> 3).
    scene
        .set_params(ChainParams::default().with_edge_budget(1))
        .expect("params");
    // Only the first edge passes the pole; the others may be Free even on
    // one item (the bar against the pole, clear at once).
    for (q0, q1) in [
        ([0.0], [3.0]),
        ([0.0], [-3.0]),
        ([1.0], [1.0]),
        ([2.9], [-2.9]),
    ] {
        let report = scene.check_edge(&q0, &q1).expect("an edge");
        assert!(report.stats.tests <= 2, "budget 1: {report:?}");
        let through = q0 == [0.0] && q1 == [3.0];
        match report.outcome {
            EdgeOutcome::Undecided { free_until } | EdgeOutcome::Contact { free_until, .. } => {
                assert!(
                    (0.0..=1.0).contains(&free_until),
                    "{q0:?} {q1:?}: {report:?}"
                );
                if through {
                    assert!(
                        free_until * 3.0 < std::f64::consts::FRAC_PI_2 - 0.0105,
                        "free until {free_until}"
                    );
                }
            }
            EdgeOutcome::Free => assert!(!through, "budget 1: Free through the pole"),
            other => panic!("budget 1, {q0:?} -> {q1:?}: {other:?}"),
        }
        if through {
            assert!(
                matches!(report.outcome, EdgeOutcome::Undecided { .. }),
                "budget 1 through the pole: {report:?}"
            );
        }
    }
    // Every budget from 1 up: never a panic, never free through the pole.
    for budget in [2, 3, 5, 10, 30, 100, 1000] {
        scene
            .set_params(ChainParams::default().with_edge_budget(budget))
            .expect("params");
        let out = scene.check_edge(&[0.0], &[3.0]).expect("an edge").outcome;
        assert!(!out.is_free(), "budget {budget}: {out:?}");
    }
}

/// `edges_are_free` equals `edge_is_free` edge by edge, and both equal
/// `check_edge(..).outcome.is_free()`; a reused `EdgeChecker` gives the
/// same outcome as a fresh query (no state carried between edges).
#[test]
fn edges_are_free_equals_edge_is_free_one_by_one() {
    let mut rng = Rng::new(404);
    // Free edges and all edges, over the scenes.
    let mut counts = (0usize, 0usize);
    for k in 0..3u64 {
        let mut twin = random_twin(&mut rng, 2 + k as usize);
        add_mesh_obstacles(&mut twin.shaped, 0.05);
        let scene = &twin.shaped;
        let limits = limits_of(scene.chain());
        let edges: Vec<(Vec<f64>, Vec<f64>)> = (0..4 * cases())
            .map(|_| random_edge(&mut rng, &limits))
            .collect();
        let batch = scene.edges_are_free(&edges).expect("valid edges");
        assert_eq!(batch.len(), edges.len(), "one answer an edge");
        let mut checker = scene.edge_checker();
        let mut free = 0;
        for (i, (q0, q1)) in edges.iter().enumerate() {
            let one = scene.edge_is_free(q0, q1).expect("a valid edge");
            let fresh = scene.check_edge(q0, q1).expect("a valid edge");
            let reused = checker.check(q0, q1).expect("a valid edge");
            assert_eq!(batch[i], one, "scene {k} edge {i}: batch and one by one");
            assert_eq!(
                one,
                fresh.outcome.is_free(),
                "scene {k} edge {i}: edge_is_free and check_edge"
            );
            assert_eq!(
                fresh.outcome, reused.outcome,
                "scene {k} edge {i}: fresh and reused checker"
            );
            free += usize::from(one);
        }
        eprintln!("scene {k}: {free} of {} edges free", edges.len());
        counts.0 += free;
        counts.1 += edges.len();
    }
    assert!(
        counts.0 > 0 && counts.0 < counts.1,
        "free and not free edges: {counts:?}"
    );
}

// ---------------------------------------------------------------------------
// Link pairs by their hulls (Lemma 13.7).

/// A hook: a bar along `z` with two prongs along `x` at its ends (three
/// boxes in one mesh), so that its convex hull holds a pocket of empty
/// space where another link's prong can sit without touching it.
fn hook(rng: &mut Rng) -> TriMesh<f64> {
    let len = rng.range(0.1, 0.2);
    let reach = rng.range(0.06, 0.12);
    let t = rng.range(0.008, 0.02);
    let boxes = [
        ([0.0, 0.0, len], [t, t, len]),
        ([reach, 0.0, t], [reach, t, t]),
        ([reach, 0.0, 2.0 * len - t], [reach, t, t]),
    ];
    let (mut v, mut tris) = (Vec::new(), Vec::new());
    for (c, h) in boxes {
        let (m, p) = cuboid(c, h, 0.05).expect("box");
        let base = v.len() as u32;
        let x = p.translation.to_array();
        v.extend(
            m.vertices()
                .iter()
                .map(|q| [q[0] + x[0], q[1] + x[1], q[2] + x[2]]),
        );
        tris.extend(m.triangles().iter().map(|f| f.map(|i| i + base)));
    }
    TriMesh::try_new(v, tris).expect("hook")
}

/// A serial chain of hooks on revolute joints with random axes, short
/// enough between joints that non-adjacent hooks reach into each other's
/// pockets.
fn hooked_chain(rng: &mut Rng, joints: usize) -> Chain<f64> {
    let mut b = ChainBuilder::new();
    let mut parent = b.add_link("base", Some(hook(rng))).expect("link");
    for j in 0..joints {
        let child = b
            .add_link(format!("hook{j}"), Some(hook(rng)))
            .expect("link");
        let axis = [rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), 1.0];
        b.add_joint(JointSpec {
            name: format!("j{j}"),
            kind: JointKind::Revolute,
            parent,
            child,
            origin: Pose::new(
                random_rotation(rng),
                Vec3::new(rng.range(-0.05, 0.05), rng.range(-0.05, 0.05), 0.12),
            ),
            axis,
            limits: Some([-2.8, 2.8]),
        })
        .expect("joint");
        parent = child;
    }
    b.build().expect("chain")
}

/// Lemma 13.7 end to end: chains of hooks (far from convex: a hull's gap
/// can be small, or none, where the meshes are far apart), the link pairs
/// alone, each pair first by its hulls (cleared, kept whole for the
/// halves, or handed to the trees); no edge the truth touches is Free,
/// `free_until` never past the truth's first touching sample, a contact's
/// `at` within the contact distance of the truth's surfaces.
#[test]
fn hooked_link_pairs_by_their_hulls_are_never_free_or_late() {
    edges_by_hulls_are_never_free_or_late(713, 7000, "hooked chains, link pairs", |rng, joints| {
        ChainScene::new(hooked_chain(rng, joints))
    });
}

/// Lemma 13.7 at one time, against this file's exact distances (brute
/// force over every triangle pair: `Exact`, not the truth's sampling, whose
/// distances are lower bounds within 20 %): at random configurations of
/// chains of hooks, with the padding just above the least exact distance
/// over the checked link pairs, the static check must find them touching
/// (a hull's gap, or any other certified gap, above the padding would be
/// above the distance); with the padding at 90 % of it, it finds them
/// apart on most configurations (tightness: the hulls do not refuse
/// near-convex pairs).
#[test]
fn hooked_link_pairs_touch_at_a_padding_just_above_their_exact_distance() {
    touch_at_a_padding_just_above_the_exact_distance(714, "hooked chains", |rng, joints| {
        ChainScene::new(hooked_chain(rng, joints))
    });
}

/// A chain of hooks among mesh obstacles for Lemma 13.8: three hooks (far
/// from convex: a link's prong can sit in an obstacle's pocket, its hull's
/// gap zero or small while the meshes are apart), a thin pole and a flat
/// box (convex: their hulls are the meshes), placed where the chain
/// reaches; the link pairs allowed, so that every contact is a link
/// against an obstacle.
fn hooks_among_hooks(rng: &mut Rng, joints: usize) -> ChainScene<f64> {
    let mut scene = ChainScene::new(hooked_chain(rng, joints));
    let n = scene.chain().link_count();
    for a in 0..n {
        for b in a + 1..n {
            scene.allow_collision(a, b);
        }
    }
    // About the chain's reach from its base: touched on some edges, clear
    // of most configurations.
    let near = |rng: &mut Rng| {
        let d = motion_bound_devkit::direction(rng, 0.1);
        let r = rng.range(0.25, 0.45);
        [d[0] * r, d[1] * r, d[2] * r + 0.2]
    };
    for i in 0..3 {
        let pose = Pose::new(random_rotation(rng), Vec3::from_array(near(rng)));
        scene.add_obstacle(Obstacle::try_new(format!("hook{i}"), hook(rng), pose).expect("hook"));
    }
    for (i, h) in [[0.005, 0.005, 0.3], [0.1, 0.08, 0.01]]
        .into_iter()
        .enumerate()
    {
        let (m, p) = cuboid(near(rng), h, 10.0).expect("box");
        scene.add_obstacle(Obstacle::try_new(format!("box{i}"), m, p).expect("box"));
    }
    scene
}

/// Lemma 13.8 end to end: chains of hooks among hooks, a pole and a plate
/// given as meshes, each link against each obstacle first by their hulls
/// (cleared, kept whole for the halves, or handed to the trees); no edge
/// the truth touches is Free, `free_until` never past the truth's first
/// touching sample, a contact's `at` within the contact distance of the
/// truth's surfaces.
#[test]
fn links_against_mesh_obstacles_by_their_hulls_are_never_free_or_late() {
    edges_by_hulls_are_never_free_or_late(
        815,
        8100,
        "hooked chains among mesh obstacles",
        hooks_among_hooks,
    );
}

/// Lemma 13.8 at one time, against this file's exact distances (brute
/// force over every triangle pair): at random configurations of chains of
/// hooks among mesh obstacles, with the padding just above the least exact
/// distance over the links and obstacles, the static check must find them
/// touching (a hull's gap above the padding would be above the distance);
/// with the padding at 90 % of it, it finds them apart on most
/// configurations (tightness).
#[test]
fn links_and_mesh_obstacles_touch_at_a_padding_just_above_their_exact_distance() {
    touch_at_a_padding_just_above_the_exact_distance(
        816,
        "hooked chains among mesh obstacles",
        hooks_among_hooks,
    );
}

/// The edges of the scenes `build` makes (six, of 3 to 5 joints), checked
/// against the sampled truth with the hulls on: never Free where the truth
/// touches, never late; both outcomes occur.
fn edges_by_hulls_are_never_free_or_late(
    seed: u64,
    edge_seed: u64,
    what: &str,
    build: fn(&mut Rng, usize) -> ChainScene<f64>,
) {
    let mut rng = Rng::new(seed);
    let mut total = Tally::default();
    for k in 0..6u64 {
        let scene = build(&mut rng, 3 + (k as usize) % 3);
        let truth = Truth::new(&scene);
        let t = check_edges(&scene, &truth, 2 * cases(), edge_seed + k, true, false);
        total.add(&t);
    }
    eprintln!("{what}: {total:?}");
    assert_eq!(total.unsound(), (0, 0, 0, 0), "{total:?}");
    assert!(
        total.colliding > 0 && total.free > 0,
        "the edges both hit and miss: {total:?}"
    );
}

/// At random configurations of the scenes `build` makes, the static check
/// with the padding just above the least exact distance finds them touching;
/// at 90 % of it, apart on most configurations.
fn touch_at_a_padding_just_above_the_exact_distance(
    seed: u64,
    what: &str,
    build: fn(&mut Rng, usize) -> ChainScene<f64>,
) {
    let mut rng = Rng::new(seed);
    let (mut checked, mut apart) = (0, 0);
    for k in 0..6usize {
        let mut scene = build(&mut rng, 3 + k % 3);
        let exact = Exact::new(&scene);
        let limits = limits_of(scene.chain());
        for _ in 0..4 * cases() {
            let q: Vec<f64> = limits.iter().map(|&[lo, hi]| rng.range(lo, hi)).collect();
            let d = exact
                .truth
                .pairs
                .iter()
                .map(|&p| exact.pair_distance(p, &q))
                .fold(f64::INFINITY, f64::min);
            if !d.is_finite() || d <= 1e-6 {
                continue;
            }
            checked += 1;
            let above = ChainParams::default().with_padding(d * (1.0 + 1e-6) + 1e-12);
            scene.set_params(above).expect("params");
            assert!(
                scene.collides_at(&q).expect("valid q"),
                "certified apart beyond the exact distance {d} at {q:?}"
            );
            scene
                .set_params(ChainParams::default().with_padding(0.9 * d))
                .expect("params");
            apart += usize::from(!scene.collides_at(&q).expect("valid q"));
        }
    }
    eprintln!("{what} at one time: {apart} of {checked} apart at 90 % of the distance");
    assert!(checked > 0, "some configurations are free");
    assert!(
        apart * 2 >= checked,
        "most are found apart: {apart} of {checked}"
    );
}
