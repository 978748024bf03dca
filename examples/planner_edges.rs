//! A planner's edge checks, certified: the Panda (its collision meshes) in
//! MotionBenchMaker's scenes (`data/mbm/`: boxes and cylinders), random edges
//! of 0.05 to 0.3 rad, each checked by `EdgeChecker::check_any` on one core,
//! in seven scenes:
//!
//! - **`table_pick`, `bookshelf_small`, `cage`**: the obstacles as shapes
//!   (`ShapeObstacle`: cuboids, cylinders), never meshed. Their truth takes
//!   the obstacles as meshes *inscribed* in the shapes (boxes exactly,
//!   cylinders as 64-sided prisms, spheres as icospheres with their vertices
//!   on the sphere), so that a touch it finds is a touch of the real shapes.
//! - **`table_pick-mesh`, `bookshelf_small-mesh`, `cage-mesh`**: the same
//!   scenes with every obstacle given as a triangle mesh (`Obstacle`), as a
//!   planner gets them from CAD: a box as its 12 triangles
//!   (`bodies::cuboid`), a cylinder as the 16-sided prism *circumscribed*
//!   about it (`bodies::prism` of radius `r / cos(pi / 16)`, widened by
//!   `1e-9` of it against rounding: its faces are at least `r` from the axis,
//!   so it contains the cylinder; its caps are the cylinder's; 64 triangles),
//!   a sphere as the icosphere scaled until its faces clear the sphere.
//!   Their truth takes the very meshes the checker is given.
//! - **`poles-mesh`**: 20 upright poles given as triangle meshes, each a
//!   12-sided prism of radius 2.5 cm and 1 m (48 triangles, as a CAD or URDF
//!   file gives it; `examples/narrow_passage.rs`'s coarse poles), 0.3 to
//!   0.8 m from the base's axis and at least 10 cm apart; truth on the same
//!   meshes. About two random configurations in three touch a pole, so
//!   here, as in `narrow_passage`, an edge is drawn again until both its
//!   ends are free (`EdgeChecker::collides_at`; a planner checks its states
//!   before its edges).
//!
//! Every scene's edges come from the same generator (`panda_edge`, seeded by
//! `--seed`); in the MotionBenchMaker scenes an edge may start or end in
//! collision.
//! The truth (`tests/common/chain_truth.rs`) is independent of the code under
//! test: its own forward kinematics, its own sphere trees over the meshes,
//! exact triangle distances and dense sampling.
//!
//! ```text
//! cargo run --release --features urdf --example planner_edges [-- --edges 10000 --truth 500 --seed 1 --obstacles all|primitive|mesh --scene S --write-edges DIR]
//! ```
//!
//! One line per scene: `scene S: edges N, colliding C, missed M, late L,
//! mean us per edge X, p99 us Y, max ms Z` (`colliding`: edges not certified
//! free; `missed`: of the truth's edges, those the truth finds touching and
//! we call free; `late`: those where our `free_until` is past the truth's
//! first touching sample), then the work and the undecided count.
//! `--obstacles` picks the primitive scenes, the mesh scenes (the poles
//! among them) or all (the default); `--scene S` one MotionBenchMaker scene
//! (`poles` for the poles). `--write-edges DIR` writes each scene's edges
//! (`DIR/S.edges`, 14 numbers a line: `q0` then `q1`, the seven arm joints)
//! for `compare/vamp/`.

#[path = "../tests/common/arm_scene.rs"]
mod arm_scene;
#[path = "../tests/common/chain_truth.rs"]
mod chain_truth;

use std::fmt::Write as _;
use std::time::Instant;

use arm_scene::{bare_arm_scene, joint_limits, panda_edge, pole_sites, Arm};
use chain_truth::Truth;
use motion_bound::chain::{ChainParams, ChainScene, EdgeOutcome, Obstacle, ShapeObstacle};
use motion_bound::{bodies, Convex, Pose, TriMesh, Vec3};
use motion_bound_devkit::{cpu_name, Args, Rng};
use serde_json::Value;

type Error = Box<dyn std::error::Error>;

const SCENES: [&str; 3] = ["table_pick", "bookshelf_small", "cage"];

fn numbers(v: &Value) -> Result<Vec<f64>, Error> {
    v.as_array()
        .ok_or("expected an array")?
        .iter()
        .map(|x| x.as_f64().ok_or_else(|| "expected a number".into()))
        .collect()
}

fn vec3(v: &Value) -> Result<[f64; 3], Error> {
    let n = numbers(v)?;
    Ok([n[0], n[1], n[2]])
}

fn rotation(v: &Value) -> Result<[[f64; 3]; 3], Error> {
    let rows = v.as_array().ok_or("rotation: expected rows")?;
    Ok([vec3(&rows[0])?, vec3(&rows[1])?, vec3(&rows[2])?])
}

fn mat_mul(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    let mut o = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            o[i][j] = (0..3).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    o
}

/// One scene's obstacles: each as a shape, as a mesh inscribed in it (the
/// shapes' truth), and as a mesh that contains it (the mesh scene).
struct Scene {
    shapes: Vec<ShapeObstacle<f64>>,
    inscribed: Vec<Obstacle<f64>>,
    meshes: Vec<Obstacle<f64>>,
}

/// Sides of the prism circumscribed about a cylinder in the mesh scenes.
const PRISM_SIDES: u32 = 16;

/// The least distance from the origin to the plane of a face of `mesh`
/// whose normal makes an angle of more than 60 degrees with `z` (every face
/// but a prism's caps; every face of an icosphere but those near its poles
/// when `sides_only`, all of them otherwise).
fn inner_radius(mesh: &TriMesh<f64>, sides_only: bool) -> Result<f64, Error> {
    let mut inner = f64::INFINITY;
    for [a, b, c] in mesh.triangle_corners() {
        let (a, b, c) = (
            Vec3::from_array(a),
            Vec3::from_array(b),
            Vec3::from_array(c),
        );
        let n = (b - a)
            .cross(c - a)
            .try_normalize()
            .ok_or("a degenerate face")?;
        if !sides_only || n.z.abs() < 0.5 {
            inner = inner.min(n.dot(a).abs());
        }
    }
    Ok(inner)
}

/// The prism of `sides` sides circumscribed about the cylinder of `radius`
/// and `length` along `z`: its vertices on the circle of radius
/// `radius / cos(pi / sides)` widened by `1e-9` of it against rounding (the
/// vertices' and the planes' rounding is about `1e-16` of the radius), so
/// every side face's plane is at least `radius` from the axis (checked here),
/// and its caps are the cylinder's: it contains the cylinder.
fn prism_around(radius: f64, length: f64, sides: u32) -> Result<TriMesh<f64>, Error> {
    let outer = radius / (std::f64::consts::PI / f64::from(sides)).cos() * (1.0 + 1e-9);
    let mesh = bodies::prism(outer, length, sides, 1)?;
    if inner_radius(&mesh, true)? < radius {
        return Err("a circumscribed prism's face is inside the cylinder".into());
    }
    Ok(mesh)
}

/// `mesh` (centred on the origin) scaled until every face's plane is at
/// least `radius` from the origin (and checked), so that it contains the
/// ball of `radius`.
fn around_ball(mesh: TriMesh<f64>, radius: f64) -> Result<TriMesh<f64>, Error> {
    let inner = inner_radius(&mesh, false)?;
    let out = mesh.scaled(radius / inner * (1.0 + 1e-9))?;
    if inner_radius(&out, false)? < radius {
        return Err("a circumscribed icosphere's face is inside the ball".into());
    }
    Ok(out)
}

fn load(name: &str) -> Result<Scene, Error> {
    let path = format!(
        "{}/data/mbm/{name}.json",
        concat!(env!("CARGO_MANIFEST_DIR"), "/..")
    );
    let json: Value = serde_json::from_str(&std::fs::read_to_string(&path)?)?;
    let mut scene = Scene {
        shapes: Vec::new(),
        inscribed: Vec::new(),
        meshes: Vec::new(),
    };
    let list = |key: &str| json[key].as_array().cloned().unwrap_or_default();
    for c in list("cuboids") {
        let h = vec3(&c["half_extents"])?;
        let pose = Pose {
            rotation: rotation(&c["rotation"])?,
            translation: Vec3::from_array(vec3(&c["center"])?),
        };
        let name = c["name"].as_str().unwrap_or("cuboid").to_string();
        scene
            .shapes
            .push(ShapeObstacle::try_new(&name, Convex::try_cuboid(h)?, pose)?);
        // The box as its 12 triangles, exactly (`2 h / 2` is `h`): both
        // the shapes' truth and the mesh scene's obstacle.
        let mesh = Obstacle::try_new(name, bodies::cuboid(h.map(|x| 2.0 * x))?, pose)?;
        scene.inscribed.push(mesh.clone());
        scene.meshes.push(mesh);
    }
    // The file's cylinders are along their local z; ours along y: turn y onto z.
    let y_to_z = [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]];
    for c in list("cylinders") {
        let (r, h) = (
            c["radius"].as_f64().ok_or("radius")?,
            c["half_length"].as_f64().ok_or("half_length")?,
        );
        let file_pose = Pose {
            rotation: rotation(&c["rotation"])?,
            translation: Vec3::from_array(vec3(&c["center"])?),
        };
        let pose = Pose {
            rotation: mat_mul(&file_pose.rotation, &y_to_z),
            ..file_pose
        };
        let name = c["name"].as_str().unwrap_or("cylinder").to_string();
        scene.shapes.push(ShapeObstacle::try_new(
            &name,
            Convex::try_cylinder(h, r)?,
            pose,
        )?);
        // The 64-sided prism inscribed, along the file's own z.
        scene.inscribed.push(Obstacle::try_new(
            name.clone(),
            bodies::prism(r, 2.0 * h, 64, 1)?,
            file_pose,
        )?);
        // The 16-sided prism circumscribed, along the file's own z.
        scene.meshes.push(Obstacle::try_new(
            name,
            prism_around(r, 2.0 * h, PRISM_SIDES)?,
            file_pose,
        )?);
    }
    for c in list("spheres") {
        let r = c["radius"].as_f64().ok_or("radius")?;
        let pose = Pose::from_translation(Vec3::from_array(vec3(&c["center"])?));
        let name = c["name"].as_str().unwrap_or("sphere").to_string();
        scene
            .shapes
            .push(ShapeObstacle::try_new(&name, Convex::try_ball(r)?, pose)?);
        scene.inscribed.push(Obstacle::try_new(
            name.clone(),
            bodies::icosphere(r, 2)?,
            pose,
        )?);
        scene.meshes.push(Obstacle::try_new(
            name,
            around_ball(bodies::icosphere(r, 2)?, r)?,
            pose,
        )?);
    }
    Ok(scene)
}

/// The 20 poles (`examples/narrow_passage.rs`'s coarse poles): 12-sided
/// prisms of radius 2.5 cm and 1 m, upright on the floor 0.3 to 0.8 m from
/// the base's axis, at least 10 cm apart.
fn poles(seed: u64) -> Result<Vec<Obstacle<f64>>, Error> {
    let (radius, length, sides) = (0.025, 1.0, 12);
    let thin = bodies::prism(radius, length, sides, 1)?;
    let mut out = Vec::new();
    for p in pole_sites(&mut Rng::new(seed ^ 0x9e37_79b9_7f4a_7c15)) {
        let pose = Pose::from_translation(Vec3::new(p[0], p[1], length / 2.0));
        out.push(Obstacle::try_new("pole", thin.clone(), pose)?);
    }
    Ok(out)
}

/// The example's diagnostic switches (environment variables): `PE_NOSHAPES`
/// (no obstacles), `PE_NOSELF` (no link pairs), `PE_PAIR=a,b` (that link
/// pair alone).
fn restrict(scene: &mut ChainScene<f64>) {
    let n = scene.chain().link_count();
    if let Ok(pair) = std::env::var("PE_PAIR") {
        let p: Vec<usize> = pair.split(',').filter_map(|x| x.parse().ok()).collect();
        for a in 0..n {
            for b in 0..n {
                if a != b && !(a.min(b) == p[0].min(p[1]) && a.max(b) == p[0].max(p[1])) {
                    scene.allow_collision(a, b);
                }
            }
        }
    }
    if std::env::var_os("PE_NOSELF").is_some() {
        for a in 0..n {
            for b in 0..n {
                if a != b {
                    scene.allow_collision(a, b);
                }
            }
        }
    }
}

/// One scene to run: its name, the scene checked, and the scene its truth
/// is built on.
struct Case {
    name: String,
    scene: ChainScene<f64>,
    truth: ChainScene<f64>,
    /// Whether the edges are drawn again until both ends are free (a
    /// planner's edges between free configurations).
    free_ends: bool,
}

fn main() -> Result<(), Error> {
    let mut args = Args::from_env(
        "planner_edges [--edges 10000] [--truth 500] [--seed 1] [--obstacles all|primitive|mesh] [--scene S] [--write-edges DIR] [--vamp DIR] [--first-contact] [--no-rake]",
    );
    let edges: usize = args.value_or("--edges", 10_000);
    let truth_edges: usize = args.value_or("--truth", 500);
    let seed: u64 = args.value_or("--seed", 1);
    let write: String = args.value_or("--write-edges", String::new());
    let only: String = args.value_or("--scene", String::new());
    let kinds: String = args.value_or("--obstacles", "all".to_string());
    let first = args.flag("--first-contact");
    let vamp: String = args.value_or("--vamp", String::new());
    let no_rake = args.flag("--no-rake");
    args.finish();
    let (primitive, mesh) = match kinds.as_str() {
        "all" => (true, true),
        "primitive" => (true, false),
        "mesh" => (false, true),
        _ => return Err("--obstacles: all, primitive or mesh".into()),
    };
    let (arm, _) = bare_arm_scene(Arm::Panda)?;
    let limits = joint_limits(arm.chain());
    println!(
        "the Panda ({} links, its collision meshes), random edges of 0.05 to 0.3 rad, one core; CPU: {}",
        arm.chain().link_count(),
        cpu_name()
    );
    let mut base = arm.clone();
    base.set_params(
        ChainParams::default()
            .with_within_limits(true)
            .with_rake(!no_rake),
    )?;
    restrict(&mut base);
    let obstacles = std::env::var_os("PE_NOSHAPES").is_none();
    let mut cases = Vec::new();
    for (kind, wanted) in [("", primitive), ("-mesh", mesh)] {
        for name in SCENES {
            if !wanted || (!only.is_empty() && only != name) {
                continue;
            }
            let loaded = load(name)?;
            let mut scene = base.clone();
            let mut truth = base.clone();
            if kind.is_empty() {
                for (s, m) in loaded.shapes.into_iter().zip(loaded.inscribed) {
                    if obstacles {
                        scene.add_shape(s);
                        truth.add_obstacle(m);
                    }
                }
            } else {
                for m in loaded.meshes {
                    if obstacles {
                        scene.add_obstacle(m.clone());
                        truth.add_obstacle(m);
                    }
                }
            }
            cases.push(Case {
                name: format!("{name}{kind}"),
                scene,
                truth,
                free_ends: false,
            });
        }
        if wanted && !kind.is_empty() && (only.is_empty() || only == "poles") {
            let mut scene = base.clone();
            if obstacles {
                for m in poles(seed)? {
                    scene.add_obstacle(m);
                }
            }
            cases.push(Case {
                name: "poles-mesh".to_string(),
                truth: scene.clone(),
                scene,
                free_ends: true,
            });
        }
    }
    for case in cases {
        run(
            &case,
            &limits,
            Options {
                edges,
                truth_edges,
                seed,
                first,
                write: &write,
                vamp: &vamp,
            },
        )?;
    }
    Ok(())
}

/// What every scene is run with.
#[derive(Clone, Copy)]
struct Options<'a> {
    edges: usize,
    truth_edges: usize,
    seed: u64,
    first: bool,
    write: &'a str,
    vamp: &'a str,
}

fn run(case: &Case, limits: &[[f64; 2]], opt: Options<'_>) -> Result<(), Error> {
    let Options {
        edges,
        truth_edges,
        seed,
        first,
        write,
        vamp,
    } = opt;
    let name = &case.name;
    let scene = &case.scene;
    let truth = Truth::new(&case.truth);
    let mut rng = Rng::new(seed);
    let mut range = |lo: f64, hi: f64| rng.range(lo, hi);
    let mut list: Vec<(Vec<f64>, Vec<f64>)> = Vec::with_capacity(edges);
    let mut checker = scene.edge_checker();
    while list.len() < edges {
        let (q0, q1) = panda_edge(&mut range, limits);
        // The checker's static test picks the ends (the truth's is much
        // slower); an end it wrongly took as free would show in `missed`.
        if !case.free_ends || !(checker.collides_at(&q0)? || checker.collides_at(&q1)?) {
            list.push((q0, q1));
        }
    }
    if !write.is_empty() {
        let mut out = String::new();
        for (a, b) in &list {
            for x in a[..7].iter().chain(&b[..7]) {
                write!(out, "{x:.17e} ")?;
            }
            out.push('\n');
        }
        std::fs::create_dir_all(write)?;
        std::fs::write(format!("{write}/{name}.edges"), out)?;
    }
    let mut times = Vec::with_capacity(edges);
    let (mut colliding, mut undecided, mut tests, mut intervals) = (0, 0, 0usize, 0usize);
    let (mut raked, mut lane_tests, mut handed) = (0usize, 0usize, 0usize);
    let (mut free_time, mut free_count) = (0.0f64, 0usize);
    let mut verdicts = Vec::with_capacity(edges);
    let mut work = Vec::with_capacity(edges);
    let slow: Option<f64> = std::env::var("PE_SLOW")
        .ok()
        .map(|v| v.parse().unwrap_or(3e-3));
    for (q0, q1) in &list {
        let start = Instant::now();
        let report = if first {
            checker.check(q0, q1)?
        } else {
            checker.check_any(q0, q1)?
        };
        times.push(start.elapsed().as_secs_f64());
        tests += report.stats.tests;
        intervals += report.stats.intervals;
        raked += report.stats.raked_intervals;
        lane_tests += report.stats.lane_tests;
        handed += report.stats.handed;
        if report.outcome.is_free() {
            free_time += times[times.len() - 1];
            free_count += 1;
        }
        match report.outcome {
            EdgeOutcome::Free => {}
            EdgeOutcome::Undecided { .. } => {
                undecided += 1;
                colliding += 1;
            }
            _ => colliding += 1,
        }
        verdicts.push(report.outcome);
        work.push(report.stats.tests);
        if let Some(limit) = slow {
            if times[times.len() - 1] > limit {
                println!(
                    "    slow {:.2} ms: {:?} {:?}",
                    times[times.len() - 1] * 1e3,
                    report.outcome,
                    report.stats
                );
            }
        }
    }
    if std::env::var_os("PE_WORK").is_some() {
        let mut w = work.clone();
        w.sort_unstable();
        let tot: usize = w.iter().sum();
        let top1: usize = w[w.len() * 99 / 100..].iter().sum();
        let top10: usize = w[w.len() * 90 / 100..].iter().sum();
        println!(
            "  tests p50 {} p90 {} p99 {} max {}; share of top 1% {:.2}, top 10% {:.2}",
            w[w.len() / 2],
            w[w.len() * 9 / 10],
            w[w.len() * 99 / 100],
            w[w.len() - 1],
            top1 as f64 / tot as f64,
            top10 as f64 / tot as f64
        );
    }
    if std::env::var_os("PE_SPLIT").is_some() {
        let (mut tf, mut nf, mut tc, mut nc, mut t0, mut n0) = (0.0, 0, 0.0, 0, 0.0, 0);
        for (t, o) in times.iter().zip(&verdicts) {
            match o {
                EdgeOutcome::Free => {
                    tf += t;
                    nf += 1;
                }
                EdgeOutcome::Contact { free_until, .. } if *free_until == 0.0 => {
                    t0 += t;
                    n0 += 1;
                }
                _ => {
                    tc += t;
                    nc += 1;
                }
            }
        }
        println!("  free {nf} mean us {:.1} (sum ms {:.1}); contact at 0 {n0} mean us {:.1} (sum ms {:.1}); contact later {nc} mean us {:.1} (sum ms {:.1})",
            tf / nf.max(1) as f64 * 1e6, tf * 1e3, t0 / n0.max(1) as f64 * 1e6, t0 * 1e3, tc / nc.max(1) as f64 * 1e6, tc * 1e3);
    }
    // VAMP's verdicts on the same edges (`compare/vamp/`: 1 = colliding), if given.
    let vamp_verdicts: Option<Vec<bool>> = if vamp.is_empty() {
        None
    } else {
        let text = std::fs::read_to_string(format!("{vamp}/{name}.verdicts"))?;
        Some(text.lines().map(|l| l.trim() == "1").collect())
    };
    let (mut vamp_missed, mut vamp_false) = (0, 0);
    let (mut missed, mut late, mut truth_colliding) = (0, 0, 0);
    for (e, ((q0, q1), outcome)) in list.iter().zip(&verdicts).take(truth_edges).enumerate() {
        let sampled = truth.sample(q0, q1, 1e-4);
        if let Some(v) = vamp_verdicts.as_ref().and_then(|v| v.get(e)) {
            match (sampled.touch.is_some(), *v) {
                (true, false) => vamp_missed += 1,
                (false, true) if sampled.min_distance > 0.0 => vamp_false += 1,
                _ => {}
            }
        }
        if let Some((t_touch, _, _)) = sampled.touch {
            truth_colliding += 1;
            match *outcome {
                EdgeOutcome::Free => missed += 1,
                EdgeOutcome::Contact { free_until, .. } | EdgeOutcome::Undecided { free_until }
                    if free_until > t_touch =>
                {
                    late += 1;
                }
                _ => {}
            }
        }
    }
    if let Some(v) = &vamp_verdicts {
        println!(
            "  VAMP on the same edges: colliding {} of {}; over the truth's edges: free where the truth touches {vamp_missed}, colliding where it never touches {vamp_false}",
            v.iter().filter(|&&x| x).count(),
            v.len()
        );
    }
    let mean = times.iter().sum::<f64>() / edges as f64;
    let mut sorted = times.clone();
    sorted.sort_by(f64::total_cmp);
    let p99 = sorted[((edges as f64 - 1.0) * 0.99) as usize];
    let max = sorted[edges - 1];
    println!(
        "scene {name}: edges {edges}, colliding {colliding}, missed {missed}, late {late}, mean us per edge {:.1}, p99 us {:.1}, max ms {:.2}",
        mean * 1e6,
        p99 * 1e6,
        max * 1e3
    );
    println!(
        "  {} shapes, {} mesh obstacles ({} triangles); median us {:.1}; undecided {undecided}; per edge: {:.0} tests, {:.1} intervals; truth over the first {}: {truth_colliding} touching",
        scene.shapes().len(),
        scene.obstacles().len(),
        scene
            .obstacles()
            .iter()
            .map(|o| o.mesh().triangle_count())
            .sum::<usize>(),
        sorted[edges / 2] * 1e6,
        tests as f64 / edges as f64,
        intervals as f64 / edges as f64,
        truth_edges.min(edges)
    );
    println!(
        "  rake: {:.1} sub-intervals, {:.0} lane tests, {:.1} handed on per edge; mean us free {:.1}, colliding {:.1}",
        raked as f64 / edges as f64,
        lane_tests as f64 / edges as f64,
        handed as f64 / edges as f64,
        free_time / free_count.max(1) as f64 * 1e6,
        (times.iter().sum::<f64>() - free_time) / (edges - free_count).max(1) as f64 * 1e6,
    );
    Ok(())
}
