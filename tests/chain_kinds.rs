//! Every query of a `ChainScene` on every obstacle kind (issue 63): meshes,
//! convex primitives, half-spaces and point clouds, alone and mixed, against
//! an independent truth (`tests/common/chain_truth.rs`: its own forward
//! kinematics, sphere trees, exact triangle distances to polytopes, planes
//! and points, dense sampling), on MotionBenchMaker's three scenes with the
//! Panda and on mixed scenes.
//!
//! `CHAIN_KINDS_SEGMENTS` and `CHAIN_KINDS_CONFIGS` set the segments and
//! configurations per scene (defaults 40 and 200; the closing note's run
//! uses 500 and 2,000).

#[path = "common/arm_scene.rs"]
mod arm_scene;
#[path = "common/chain_truth.rs"]
mod chain_truth;

use arm_scene::{bare_arm_scene, joint_limits, panda_edge, Arm, PANDA_FINGERS};
use chain_truth::{Place, Truth, TruthShape};
use motion_bound::chain::{
    ChainBuilder, ChainPair, ChainScene, JointKind, JointSpec, Obstacle, SegmentOutcome,
    ShapeObstacle,
};
use motion_bound::testkit::toi::Rng;
use motion_bound::{bodies, Convex, Pose, TriMesh, Vec3};
use serde_json::Value;

type Error = Box<dyn std::error::Error>;
type V3 = [f64; 3];
type M3 = [[f64; 3]; 3];
/// A scene and its truth's shapes (`(lower, upper)` each).
type WithTruth = (ChainScene<f64>, Vec<(TruthShape, TruthShape)>);
/// What adds one obstacle to a scene.
type Adder = Box<dyn Fn(&mut ChainScene<f64>)>;

fn count(var: &str, default: usize) -> usize {
    std::env::var(var)
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(default)
}

/// The truth's sampling tolerance (world units).
const TOL: f64 = 1e-4;

/// How far below the true distance `clearance` may be where the truth is
/// exact: `REL` of it, at every true distance drawn (the near-contact ones
/// from `NEAR_LO`). What the certified gap loses in `f64` is about
/// `1e-14` at most here: against a shape, its support's rounding at its
/// exact pose by kind (`proofs/12-shapes.md`, section "Support at an exact
/// pose"; the rigid certificate's `64 u` of the weights lost up to `4e-14`,
/// `4e-9` relative at `NEAR_LO`); against meshes and links, Lemma 13.16's
/// placement errors and the slab's `gamma_8` of the reaches. Without the
/// double-double re-placement of the nearest pair (Lemma 13.16) the
/// deficit is Lemma 13.3's placement margin, about `4e-13` on the Panda,
/// `1e-9` relative at `4e-4`, which the near-contact configurations below
/// reach.
const REL: f64 = 1e-9;
/// Where a cylinder's truth is a sandwich (`lo < hi`), the check is one
/// sided (never above `hi`); below `lo` by at most `REL` of it or `ABS`.
const ABS: f64 = 1e-10;
/// Near-contact configurations are sought with a true distance in
/// `[NEAR_LO, NEAR_HI]`.
const NEAR_LO: f64 = 1e-5;
const NEAR_HI: f64 = 2e-4;

/// Sides of the prisms about and in a cylinder (the truth's two bounds).
const SIDES: u32 = 64;

fn place(p: &Pose<f64>) -> Place {
    Place {
        r: p.rotation,
        x: p.translation.to_array(),
    }
}

fn corners(m: &TriMesh<f64>) -> Vec<[V3; 3]> {
    m.triangle_corners().collect()
}

fn mat_mul(a: &M3, b: &M3) -> M3 {
    let mut o = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            o[i][j] = (0..3).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    o
}

fn vec3(v: &Value) -> Result<V3, Error> {
    let a = v.as_array().ok_or("an array")?;
    Ok([0, 1, 2].map(|i| a.get(i).and_then(Value::as_f64).unwrap_or(f64::NAN)))
}

fn rotation(v: &Value) -> Result<M3, Error> {
    let a = v.as_array().ok_or("rows")?;
    let mut r = [[0.0; 3]; 3];
    for (i, row) in a.iter().take(3).enumerate() {
        r[i] = vec3(row)?;
    }
    Ok(r)
}

/// A cylinder (half-length `h`, radius `r`, along the frame's z) as the
/// truth's two polytopes: the prism about it (its faces at least `r` from
/// the axis) and the prism in it.
fn cylinder_truth(r: f64, h: f64, at: &Place) -> Result<(TruthShape, TruthShape), Error> {
    let outer = r / (std::f64::consts::PI / f64::from(SIDES)).cos() * (1.0 + 1e-9);
    let about = bodies::prism::<f64>(outer, 2.0 * h, SIDES, 1)?;
    let inside = bodies::prism::<f64>(r, 2.0 * h, SIDES, 1)?;
    Ok((
        TruthShape::polytope(&corners(&about), at),
        TruthShape::polytope(&corners(&inside), at),
    ))
}

/// Adds a cylinder along the world pose's z (`file`) to the scene and the truth.
fn add_cylinder(
    scene: &mut ChainScene<f64>,
    truth: &mut Vec<(TruthShape, TruthShape)>,
    name: &str,
    r: f64,
    h: f64,
    file: Pose<f64>,
) -> Result<(), Error> {
    // Ours are along their y: turn y onto z.
    let y_to_z = [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]];
    let pose = Pose {
        rotation: mat_mul(&file.rotation, &y_to_z),
        ..file
    };
    scene.add_shape(ShapeObstacle::try_new(
        name,
        Convex::try_cylinder(h, r)?,
        pose,
    )?);
    truth.push(cylinder_truth(r, h, &place(&file))?);
    Ok(())
}

/// Adds a cuboid to the scene and the truth (its 12 triangles, exactly).
fn add_cuboid(
    scene: &mut ChainScene<f64>,
    truth: &mut Vec<(TruthShape, TruthShape)>,
    name: &str,
    h: V3,
    pose: Pose<f64>,
) -> Result<(), Error> {
    scene.add_shape(ShapeObstacle::try_new(name, Convex::try_cuboid(h)?, pose)?);
    let mesh = bodies::cuboid::<f64>(h.map(|x| 2.0 * x))?;
    let t = TruthShape::polytope(&corners(&mesh), &place(&pose));
    truth.push((t.clone(), t));
    Ok(())
}

/// The Panda in MotionBenchMaker's scene `name` (cuboids and cylinders as
/// shapes), and the truth's shapes.
fn mbm(name: &str) -> Result<WithTruth, Error> {
    let (mut scene, _) = bare_arm_scene(Arm::Panda)?;
    let path = format!(
        "{}/data/mbm/{name}.json",
        concat!(env!("CARGO_MANIFEST_DIR"), "/..")
    );
    let json: Value = serde_json::from_str(&std::fs::read_to_string(&path)?)?;
    let list = |key: &str| json[key].as_array().cloned().unwrap_or_default();
    let mut truth = Vec::new();
    for c in list("cuboids") {
        let pose = Pose {
            rotation: rotation(&c["rotation"])?,
            translation: Vec3::from_array(vec3(&c["center"])?),
        };
        add_cuboid(
            &mut scene,
            &mut truth,
            "cuboid",
            vec3(&c["half_extents"])?,
            pose,
        )?;
    }
    for c in list("cylinders") {
        let file = Pose {
            rotation: rotation(&c["rotation"])?,
            translation: Vec3::from_array(vec3(&c["center"])?),
        };
        let r = c["radius"].as_f64().ok_or("radius")?;
        let h = c["half_length"].as_f64().ok_or("half_length")?;
        add_cylinder(&mut scene, &mut truth, "cylinder", r, h, file)?;
    }
    Ok((scene, truth))
}

/// The Panda among every kind at once: a cuboid and a cylinder (shapes),
/// a mesh obstacle (a box's triangles), a floor (a half-space) and a point
/// cloud of 150 balls, placed by `seed`.
fn mixed(seed: u64) -> Result<WithTruth, Error> {
    let (mut scene, _) = bare_arm_scene(Arm::Panda)?;
    let mut rng = Rng::new(seed);
    let mut truth = Vec::new();
    let at = |rng: &mut Rng, z: f64| {
        let a = rng.range(-3.1, 3.1);
        let d = rng.range(0.35, 0.65);
        Vec3::new(d * a.cos(), d * a.sin(), z)
    };
    let box_pose = Pose::from_translation(at(&mut rng, 0.3));
    add_cuboid(&mut scene, &mut truth, "box", [0.08, 0.12, 0.3], box_pose)?;
    let cyl = Pose::from_translation(at(&mut rng, 0.4));
    add_cylinder(&mut scene, &mut truth, "pole", 0.04, 0.4, cyl)?;
    // The floor, 2 cm below the base.
    scene.add_shape(ShapeObstacle::try_half_space(
        "floor",
        [0.0, 0.0, 1.0],
        [0.0, 0.0, -0.02],
    )?);
    let floor = TruthShape::Plane {
        n: [0.0, 0.0, 1.0],
        p: [0.0, 0.0, -0.02],
    };
    truth.push((floor.clone(), floor));
    // A cloud: a depth camera's patch of a wall.
    let c = at(&mut rng, 0.5);
    let points: Vec<V3> = (0..150)
        .map(|_| {
            [
                c.x + rng.range(-0.1, 0.1),
                c.y + rng.range(-0.1, 0.1),
                c.z + rng.range(-0.2, 0.2),
            ]
        })
        .collect();
    scene.add_shape(ShapeObstacle::try_points("cloud", &points, 0.01)?);
    let cloud = TruthShape::Points { points, r: 0.01 };
    truth.push((cloud.clone(), cloud));
    // A mesh obstacle: a shelf board as triangles.
    let board = bodies::cuboid::<f64>([0.3, 0.2, 0.02])?;
    scene.add_obstacle(Obstacle::try_new(
        "board",
        board,
        Pose::from_translation(at(&mut rng, 0.45)),
    )?);
    Ok((scene, truth))
}

fn random_q(rng: &mut Rng, limits: &[[f64; 2]]) -> Vec<f64> {
    limits[..7]
        .iter()
        .map(|&[lo, hi]| rng.range(lo, hi))
        .chain([PANDA_FINGERS, PANDA_FINGERS])
        .collect()
}

#[derive(Debug, Default)]
struct Tally {
    configs: usize,
    /// Configurations whose nearest pair is of an exact kind (not a
    /// cylinder's two bounds).
    exact_min: usize,
    above_truth: usize,
    loose: usize,
    worst_rel: f64,
    /// The truth's distance where `worst_rel` was seen.
    worst_at: f64,
    /// The largest `truth - clearance` over configurations with `lo == hi`.
    worst_abs: f64,
    collides_wrong: usize,
    ambiguous: usize,
    /// Configurations at a true distance in `[NEAR_LO, NEAR_HI]`, found by
    /// bisection on the truth along the segments that touch (of `configs`).
    near: usize,
    segments: usize,
    contacts: usize,
    truth_touches: usize,
    missed: usize,
    late: usize,
    undecided: usize,
}

/// Runs the configurations and segments of one scene against its truth.
#[allow(clippy::too_many_lines)]
fn run(
    scene: &ChainScene<f64>,
    truth: &Truth,
    seed: u64,
    configs: usize,
    segments: usize,
) -> Tally {
    let limits = joint_limits(scene.chain());
    let mut rng = Rng::new(seed);
    let mut t = Tally::default();
    for _ in 0..configs {
        let q = random_q(&mut rng, &limits);
        check_config(scene, truth, &q, &mut t);
    }
    // Near contact (one configuration in 20 more): bisection between a
    // free and a touching random configuration.
    for _ in 0..configs {
        if t.near >= configs.div_ceil(20) {
            break;
        }
        let (qa, qb) = (random_q(&mut rng, &limits), random_q(&mut rng, &limits));
        let (da, db) = (
            truth.min_distance_exact(&qa).0,
            truth.min_distance_exact(&qb).0,
        );
        let (free, touching) = match (da > NEAR_HI, db > NEAR_HI) {
            (true, false) if db < NEAR_LO => (qa, qb),
            (false, true) if da < NEAR_LO => (qb, qa),
            _ => continue,
        };
        if let Some(q) = near_contact(truth, &free, &touching) {
            t.near += 1;
            check_config(scene, truth, &q, &mut t);
        }
    }
    let mut range = |a: f64, b: f64| rng.range(a, b);
    for e in 0..segments {
        // Half the segments from a free configuration.
        let (q0, q1) = loop {
            let (q0, q1) = panda_edge(&mut range, &limits);
            if e % 2 == 1 || !truth.touches_at(&q0) {
                break (q0, q1);
            }
        };
        let report = scene
            .check_segment(&q0, &q1)
            .expect("check_segment takes every kind");
        let path = scene
            .check_path(&[q0.clone(), q1.clone()])
            .expect("check_path takes every kind");
        assert_eq!(
            path.outcome, report.outcome,
            "a path of one segment is that segment"
        );
        let sampled = truth.sample(&q0, &q1, TOL);
        t.segments += 1;

        let found = match report.outcome {
            SegmentOutcome::Contact(c) => {
                t.contacts += 1;
                Some(c.time)
            }
            SegmentOutcome::IterationLimit { time, .. } => {
                t.undecided += 1;
                Some(time)
            }
            SegmentOutcome::Separated => None,
            _ => None,
        };
        if let Some((touch, _, pair)) = sampled.touch {
            t.truth_touches += 1;
            match found {
                None => {
                    t.missed += 1;
                    eprintln!("missed {pair:?} at {touch}: {q0:?} -> {q1:?}");
                }
                Some(time) if time > touch => {
                    t.late += 1;
                    eprintln!("late: {time} after the truth's touch at {touch} ({pair:?}): {q0:?} -> {q1:?}");
                }
                Some(_) => {}
            }
        }
    }
    t
}

/// Checks `clearance` and `collides_at` at `q` against the truth.
fn check_config(scene: &ChainScene<f64>, truth: &Truth, q: &[f64], t: &mut Tally) {
    let (lo, hi, pair) = truth.min_distance_exact(q);
    let (c, _) = scene.clearance(q).expect("clearance takes every kind");
    t.configs += 1;
    if lo == hi {
        t.exact_min += 1;
    }
    // Never above the true distance (at most `hi`).
    if c > hi {
        t.above_truth += 1;
        eprintln!("clearance {c} above the truth's {hi} ({pair:?}) at {q:?}");
    }
    // Within 1e-9 relative of it where it is exact; of `lo`, the least it
    // can be, by `ABS` more for a cylinder's sandwich.
    if lo > 0.0 {
        let rel = (lo - c) / lo;
        if lo == hi && rel > t.worst_rel {
            (t.worst_rel, t.worst_at) = (rel, lo);
        }
        if lo == hi {
            t.worst_abs = t.worst_abs.max(lo - c);
        }
        let least = if lo == hi {
            lo * (1.0 - REL)
        } else {
            lo * (1.0 - REL) - ABS
        };
        if c < least {
            t.loose += 1;
            eprintln!("clearance {c} below the truth's {lo} by {rel} ({pair:?}) at {q:?}");
        }
    }
    let collides = scene.collides_at(q).expect("collides_at takes every kind");
    if hi <= 0.0 && !collides || lo > 1e-9 && collides {
        t.collides_wrong += 1;
        eprintln!("collides_at {collides} with the truth's [{lo}, {hi}] ({pair:?})");
    } else if !(hi <= 0.0 || lo > 1e-9) {
        t.ambiguous += 1;
    }
}

/// A configuration of the segment `q0 -> q1` at a true distance in
/// `[NEAR_LO, NEAR_HI]`: bisection on the truth's distance between the free
/// `q0` and the touching `q1` (at most 80 halvings).
fn near_contact(truth: &Truth, q0: &[f64], q1: &[f64]) -> Option<Vec<f64>> {
    let at = |s: f64| -> Vec<f64> { q0.iter().zip(q1).map(|(a, b)| a + s * (b - a)).collect() };
    let (mut free, mut near) = (0.0, 1.0);
    for _ in 0..80 {
        let mid = 0.5 * (free + near);
        let q = at(mid);
        let d = truth.min_distance_exact(&q).0;
        if d > NEAR_HI {
            free = mid;
        } else if d < NEAR_LO {
            near = mid;
        } else {
            return Some(q);
        }
    }
    None
}

fn check(name: &str, t: &Tally) {
    println!("{name}: {t:?}");
    assert_eq!(
        t.above_truth, 0,
        "{name}: clearance above the true distance"
    );
    assert_eq!(
        t.loose, 0,
        "{name}: clearance more than 1e-9 below the true distance"
    );
    assert_eq!(t.collides_wrong, 0, "{name}: collides_at wrong");
    assert_eq!(t.missed, 0, "{name}: a contact missed");
    assert_eq!(t.late, 0, "{name}: a contact late");
    assert!(
        t.contacts > 0 && t.truth_touches > 0,
        "{name}: no contact exercised"
    );
    assert!(t.near > 0, "{name}: no near-contact configuration");
}

#[test]
fn mbm_scenes_with_primitives_against_the_truth() {
    let (configs, segments) = (
        count("CHAIN_KINDS_CONFIGS", 200),
        count("CHAIN_KINDS_SEGMENTS", 40),
    );
    for (i, name) in ["table_pick", "bookshelf_small", "cage"].iter().enumerate() {
        let (scene, shapes) = mbm(name).expect("scene");
        let truth = Truth::new(&scene).with_shapes(shapes);
        let t = run(&scene, &truth, 63 + i as u64, configs, segments);
        check(name, &t);
    }
}

#[test]
fn mixed_scenes_against_the_truth() {
    let (configs, segments) = (
        count("CHAIN_KINDS_CONFIGS", 200),
        count("CHAIN_KINDS_SEGMENTS", 40),
    );
    for seed in [1, 2] {
        let (scene, shapes) = mixed(seed).expect("scene");
        let truth = Truth::new(&scene).with_shapes(shapes);
        let t = run(&scene, &truth, 630 + seed, configs, segments);
        check(&format!("mixed {seed}"), &t);
    }
}

/// A one-link arm (a bar along x turning about z) and one obstacle of each
/// kind in its way at 45 degrees: every query takes it, and the sweep
/// through it is a contact, the sweep away separated.
#[test]
fn every_query_takes_every_obstacle_kind() {
    let bar = TriMesh::try_new(
        vec![
            [0.0, -0.02, -0.02],
            [1.0, 0.0, 0.0],
            [0.0, 0.02, -0.02],
            [0.0, 0.0, 0.02],
        ],
        vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
    )
    .expect("bar");
    let at = Pose::from_translation(Vec3::new(0.5, 0.5, 0.0));
    let kinds: Vec<(&str, Adder)> = vec![
        (
            "mesh",
            Box::new(move |s| {
                let m = bodies::cuboid::<f64>([0.05, 0.05, 0.4]).expect("box");
                s.add_obstacle(Obstacle::try_new("mesh", m, at).expect("mesh"));
            }),
        ),
        ("ball", shape(Convex::try_ball(0.05), at)),
        ("capsule", shape(Convex::try_capsule(0.2, 0.03), at)),
        ("cuboid", shape(Convex::try_cuboid([0.05, 0.05, 0.3]), at)),
        ("cylinder", shape(Convex::try_cylinder(0.3, 0.03), at)),
        ("cone", shape(Convex::try_cone(0.3, 0.05), at)),
        (
            "rounded cuboid",
            shape(
                Convex::try_cuboid([0.03, 0.03, 0.2]).and_then(|c| c.try_rounded(0.01)),
                at,
            ),
        ),
        (
            "half-space",
            Box::new(|s| {
                // The wall x + y >= 1.3 (outward normal towards the
                // origin): the bar's tip is in it from 22 to 68 degrees.
                let wall =
                    ShapeObstacle::try_half_space("wall", [-1.0, -1.0, 0.0], [0.65, 0.65, 0.0]);
                s.add_shape(wall.expect("wall"));
            }),
        ),
        (
            "point cloud",
            Box::new(|s| {
                let pts: Vec<V3> = (0..20)
                    .map(|i| [0.5, 0.5, -0.1 + 0.01 * f64::from(i)])
                    .collect();
                s.add_shape(ShapeObstacle::try_points("cloud", &pts, 0.01).expect("cloud"));
            }),
        ),
    ];
    for (name, add) in &kinds {
        let mut b = ChainBuilder::new();
        let base = b.add_link("base", None).expect("base");
        let arm = b.add_link("arm", Some(bar.clone())).expect("arm");
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
        add(&mut scene);
        let (start, toward, back) = ([0.0], [1.5], [-1.5]);
        let hit = scene.check_segment(&start, &toward).expect(name);
        let c = hit
            .outcome
            .contact()
            .unwrap_or_else(|| panic!("{name}: {hit:?}"));
        assert!(c.time > 0.2 && c.time < 0.55, "{name}: {c:?}");
        assert!(
            matches!(c.pair, ChainPair::Obstacle { .. } | ChainPair::Shape { .. }),
            "{name}: {c:?}"
        );
        let miss = scene.check_segment(&start, &back).expect(name);
        assert_eq!(miss.outcome, SegmentOutcome::Separated, "{name}");
        let path = scene.check_path(&[[0.0], [-1.0], [1.5]]).expect(name);
        assert_eq!(path.segment, 1, "{name}: {path:?}");
        let (free, _) = scene.clearance(&[-1.0]).expect(name);
        let (touching, pair) = scene.clearance(&[std::f64::consts::FRAC_PI_4]).expect(name);
        assert!(
            free > 0.1 && touching <= 0.0 && pair.is_some(),
            "{name}: {free} {touching}"
        );
        assert!(!scene.collides_at(&[-1.0]).expect(name), "{name}");
        assert!(
            scene
                .collides_at(&[std::f64::consts::FRAC_PI_4])
                .expect(name),
            "{name}"
        );
        assert!(!scene.edge_is_free(&[0.0], &[1.5]).expect(name), "{name}");
        assert!(scene.edge_is_free(&[0.0], &[-1.5]).expect(name), "{name}");
        assert!(
            scene.check_edge(&[0.0], &[1.5]).expect(name).outcome
                != motion_bound::chain::EdgeOutcome::Free,
            "{name}"
        );
        assert_eq!(
            scene
                .edges_are_free(&[([0.0], [1.5]), ([0.0], [-1.5])])
                .expect(name),
            vec![false, true],
            "{name}"
        );
        // Link pairs only: the shapes are kept.
        assert!(
            scene
                .allow_collisions_at(&[0.0], 0.0)
                .expect(name)
                .is_empty(),
            "{name}"
        );
    }
}

fn shape(c: Result<Convex<'static, f64>, motion_bound::InputError>, at: Pose<f64>) -> Adder {
    let c = c.expect("shape");
    Box::new(move |s| {
        s.add_shape(ShapeObstacle::try_new("shape", c, at).expect("shape"));
    })
}

/// `x` rounded to `f32` and back.
fn r32(x: f64) -> f64 {
    f64::from(x as f32)
}

/// The Panda's bare scene in `f32` and its `f64` twin of exactly the same
/// numbers (the same pairs allowed).
fn panda_twins() -> Result<(ChainScene<f32>, ChainScene<f64>), Error> {
    let (bare, _) = bare_arm_scene(Arm::Panda)?;
    let (c32, c64) = arm_scene::chain_in_f32(bare.chain());
    let (mut s32, mut s64) = (ChainScene::new(c32), ChainScene::new(c64));
    let n = bare.chain().link_count();
    for a in 0..n {
        for b in a + 1..n {
            let has = |l: usize| bare.chain().link_mesh(l).is_some();
            if has(a) && has(b) && !bare.checks_pair(a, b) {
                s32.allow_collision(a, b);
                s64.allow_collision(a, b);
            }
        }
    }
    Ok((s32, s64))
}

/// MotionBenchMaker's scene `name` in `f32` (every number of the scene
/// rounded to `f32`: poses, half-extents, radii) and its exact `f64` twin
/// for the truth, with the truth's shapes.
fn mbm_f32(name: &str) -> Result<(ChainScene<f32>, WithTruth), Error> {
    let (mut s32, s64) = panda_twins()?;
    let path = format!(
        "{}/data/mbm/{name}.json",
        concat!(env!("CARGO_MANIFEST_DIR"), "/..")
    );
    let json: Value = serde_json::from_str(&std::fs::read_to_string(&path)?)?;
    let list = |key: &str| json[key].as_array().cloned().unwrap_or_default();
    let pose32 = |r: &M3, c: &V3| Pose::<f32> {
        rotation: r.map(|row| row.map(|x| x as f32)),
        translation: Vec3::from_array(c.map(|x| x as f32)),
    };
    let mut truth = Vec::new();
    for c in list("cuboids") {
        let (r, centre) = (
            rotation(&c["rotation"])?.map(|row| row.map(r32)),
            vec3(&c["center"])?.map(r32),
        );
        let h = vec3(&c["half_extents"])?.map(r32);
        s32.add_shape(ShapeObstacle::try_new(
            "cuboid",
            Convex::try_cuboid(h.map(|x| x as f32))?,
            pose32(&r, &centre),
        )?);
        let mesh = bodies::cuboid::<f64>(h.map(|x| 2.0 * x))?;
        let t = TruthShape::polytope(&corners(&mesh), &Place { r, x: centre });
        truth.push((t.clone(), t));
    }
    for c in list("cylinders") {
        let (r, centre) = (
            rotation(&c["rotation"])?.map(|row| row.map(r32)),
            vec3(&c["center"])?.map(r32),
        );
        let radius = r32(c["radius"].as_f64().ok_or("radius")?);
        let h = r32(c["half_length"].as_f64().ok_or("half_length")?);
        // Ours are along their y: turn y onto z (a signed permutation, exact).
        let y_to_z = [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]];
        s32.add_shape(ShapeObstacle::try_new(
            "cylinder",
            Convex::try_cylinder(h as f32, radius as f32)?,
            pose32(&mat_mul(&r, &y_to_z), &centre),
        )?);
        truth.push(cylinder_truth(radius, h, &Place { r, x: centre })?);
    }
    Ok((s32, (s64, truth)))
}

/// The Panda in `f32` among a cuboid, a cylinder, a floor, a point cloud
/// and a mesh board (every number `f32`-exact), its `f64` twin of exactly
/// the same numbers for the truth, and the truth's shapes.
fn mixed_f32(seed: u64) -> Result<(ChainScene<f32>, WithTruth), Error> {
    let (mut s32, mut s64) = panda_twins()?;
    let mut rng = Rng::new(seed);
    let mut truth = Vec::new();
    let at = |rng: &mut Rng, z: f64| {
        let a = rng.range(-3.1, 3.1);
        let d = rng.range(0.35, 0.65);
        [r32(d * a.cos()), r32(d * a.sin()), r32(z)]
    };
    let p32 = |p: V3| Pose::<f32>::from_translation(Vec3::from_array(p.map(|x| x as f32)));
    let p64 = |p: V3| Pose::<f64>::from_translation(Vec3::from_array(p));
    // A cuboid.
    let (h, c) = ([r32(0.08), r32(0.12), r32(0.3)], at(&mut rng, 0.3));
    s32.add_shape(ShapeObstacle::try_new(
        "box",
        Convex::try_cuboid(h.map(|x| x as f32))?,
        p32(c),
    )?);
    let mesh = bodies::cuboid::<f64>(h.map(|x| 2.0 * x))?;
    let t = TruthShape::polytope(&corners(&mesh), &place(&p64(c)));
    truth.push((t.clone(), t));
    // A cylinder along z (ours along y: turned, exactly).
    let (r, hl, c) = (r32(0.04), r32(0.4), at(&mut rng, 0.4));
    let turned = Pose::<f32> {
        rotation: [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]],
        ..p32(c)
    };
    s32.add_shape(ShapeObstacle::try_new(
        "pole",
        Convex::try_cylinder(hl as f32, r as f32)?,
        turned,
    )?);
    truth.push(cylinder_truth(r, hl, &place(&p64(c)))?);
    // The floor.
    let below = [0.0, 0.0, r32(-0.02)];
    s32.add_shape(ShapeObstacle::try_half_space(
        "floor",
        [0.0, 0.0, 1.0],
        below.map(|x| x as f32),
    )?);
    let floor = TruthShape::Plane {
        n: [0.0, 0.0, 1.0],
        p: below,
    };
    truth.push((floor.clone(), floor));
    // A cloud.
    let c = at(&mut rng, 0.5);
    let points: Vec<V3> = (0..150)
        .map(|_| {
            [0, 1, 2].map(|k| r32(c[k] + rng.range(-0.1, 0.1) * if k == 2 { 2.0 } else { 1.0 }))
        })
        .collect();
    let r = r32(0.01);
    let p32s: Vec<[f32; 3]> = points.iter().map(|p| p.map(|x| x as f32)).collect();
    s32.add_shape(ShapeObstacle::try_points("cloud", &p32s, r as f32)?);
    let cloud = TruthShape::Points { points, r };
    truth.push((cloud.clone(), cloud));
    // A mesh board, in both scenes (the truth reads the twin's meshes).
    let board = bodies::cuboid::<f32>([0.3, 0.2, 0.02])?;
    let c = at(&mut rng, 0.45);
    s64.add_obstacle(Obstacle::try_new(
        "board",
        board.try_convert::<f64>()?,
        p64(c),
    )?);
    s32.add_obstacle(Obstacle::try_new("board", board, p32(c))?);
    Ok((s32, (s64, truth)))
}

/// An `f32` scene against the truth on its exact `f64` twin: the
/// clearance never above the truth's distance (and within `5e-4` of it:
/// the `f32` forward kinematics' certified placement margins, Lemma 13.3,
/// are a few `1e-5` of the arm's reach per link, both links' for a self
/// pair; Lemma 13.16 re-places the nearest pair's links), `collides_at`
/// exact away from the `f32` rounding band, `check_segment` never late nor
/// missed. Asserts and prints the tally under `name`.
fn run_f32(name: &str, s32: &ChainScene<f32>, s64: &ChainScene<f64>, truth: &Truth, seed: u64) {
    let (configs, segments) = (
        count("CHAIN_KINDS_CONFIGS", 200),
        count("CHAIN_KINDS_SEGMENTS", 40),
    );
    let limits = joint_limits(s64.chain());
    let mut rng = Rng::new(seed);
    let (mut above, mut loose, mut wrong, mut missed, mut late, mut contacts, mut touches) =
        (0, 0, 0, 0, 0, 0, 0);
    let mut worst = 0.0f64;
    let to32 = |q: &[f64]| -> Vec<f32> { q.iter().map(|&x| x as f32).collect() };
    let to64 = |q: &[f32]| -> Vec<f64> { q.iter().map(|&x| f64::from(x)).collect() };
    for _ in 0..configs {
        let q = to32(&random_q(&mut rng, &limits));
        let (lo, hi, pair) = truth.min_distance_exact(&to64(&q));
        let c = f64::from(s32.clearance(&q).expect("clearance").0);
        if c > hi {
            above += 1;
            eprintln!("{name}: f32 clearance {c} above the truth's {hi} ({pair:?})");
        }
        if lo == hi && lo > 0.0 {
            worst = worst.max(lo - c);
        }
        if lo > 0.0 && c < lo - 5e-4 {
            loose += 1;
            eprintln!("{name}: f32 clearance {c} below the truth's {lo} ({pair:?})");
        }
        let collides = s32.collides_at(&q).expect("collides_at");
        // Touching taken on a computed distance, or on no certified gap
        // past the `f32` margins (a tie within rounding: touching).
        if hi <= 0.0 && !collides || lo > 5e-4 && collides {
            wrong += 1;
            eprintln!(
                "{name}: f32 collides_at {collides}, the truth's [{lo}, {hi}] ({pair:?}), clearance {c}"
            );
        }
    }
    let mut range = |a: f64, b: f64| rng.range(a, b);
    for _ in 0..segments {
        let (q0, q1) = panda_edge(&mut range, &limits);
        let (q0, q1) = (to32(&q0), to32(&q1));
        let report = s32.check_segment(&q0, &q1).expect("check_segment");
        let found = match report.outcome {
            SegmentOutcome::Contact(c) => {
                contacts += 1;
                Some(f64::from(c.time))
            }
            SegmentOutcome::IterationLimit { time, .. } => Some(f64::from(time)),
            _ => None,
        };
        if let Some((touch, _, pair)) = truth.sample(&to64(&q0), &to64(&q1), TOL).touch {
            touches += 1;
            match found {
                None => {
                    missed += 1;
                    eprintln!("{name}: f32 missed {pair:?} at {touch}");
                }
                Some(t) if t > touch => {
                    late += 1;
                    eprintln!("{name}: f32 late {t} after {touch} ({pair:?})");
                }
                Some(_) => {}
            }
        }
    }
    println!(
        "f32 {name}: configs {configs}, above {above}, loose {loose} (worst deficit {worst:e}), collides_at wrong {wrong}; \
         segments {segments}, contacts {contacts}, truth touches {touches}, missed {missed}, late {late}"
    );
    assert_eq!(
        (above, loose, wrong, missed, late),
        (0, 0, 0, 0, 0),
        "{name}: f32 against the truth"
    );
    assert!(contacts > 0 && touches > 0, "{name}: no contact exercised");
}

/// The mixed scene in `f32` against the truth on its exact `f64` twin
/// ([`run_f32`]).
#[test]
fn mixed_scenes_in_f32_against_the_truth() {
    let (s32, (s64, shapes)) = mixed_f32(7).expect("scene");
    let truth = Truth::new(&s64).with_shapes(shapes);
    run_f32("mixed", &s32, &s64, &truth, 6363);
}

/// MotionBenchMaker's three scenes in `f32` (numbers rounded to `f32`)
/// against the truth on their exact `f64` twins ([`run_f32`]).
#[test]
fn mbm_scenes_in_f32_against_the_truth() {
    for (i, name) in ["table_pick", "bookshelf_small", "cage"].iter().enumerate() {
        let (s32, (s64, shapes)) = mbm_f32(name).expect("scene");
        let truth = Truth::new(&s64).with_shapes(shapes);
        run_f32(name, &s32, &s64, &truth, 6400 + i as u64);
    }
}
