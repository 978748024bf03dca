//! A planner's edge checks, certified: the Panda (its collision meshes) in
//! MotionBenchMaker's scenes (`data/mbm/`: boxes, cylinders and spheres, as
//! shapes, never meshed), random edges of 0.05 to 0.3 rad, each checked by
//! `EdgeChecker::check` on one core; the first edges of each scene also
//! against an independent ground truth (`tests/common/chain_truth.rs`: its
//! own forward kinematics, the obstacles as meshes *inscribed* in the shapes
//! (boxes exactly, cylinders as 64-sided prisms, spheres as icospheres with
//! their vertices on the sphere), exact triangle distances and dense
//! sampling), so that a touch it finds is a touch of the real shapes.
//!
//! ```text
//! cargo run --release --features urdf --example planner_edges [-- --edges 10000 --truth 500 --seed 1 --write-edges DIR]
//! ```
//!
//! One line per scene: `scene S: edges N, colliding C, missed M, late L,
//! mean us per edge X, p99 us Y, max ms Z` (`colliding`: edges not certified
//! free; `missed`: of the truth's edges, those the truth finds touching and
//! we call free; `late`: those where our `free_until` is past the truth's
//! first touching sample), then the work and the undecided count.
//! `--write-edges DIR` writes each scene's edges (`DIR/S.edges`, 14 numbers a
//! line: `q0` then `q1`, the seven arm joints) for `compare/vamp/`.

#[path = "../tests/common/arm_scene.rs"]
mod arm_scene;
#[path = "../tests/common/chain_truth.rs"]
mod chain_truth;

use std::fmt::Write as _;
use std::time::Instant;

use arm_scene::{bare_arm_scene, joint_limits, panda_edge, Arm};
use chain_truth::Truth;
use motion_bound::chain::{ChainParams, ChainScene, EdgeOutcome, Obstacle, ShapeObstacle};
use motion_bound::{bodies, Convex, Pose, Vec3};
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

/// One scene's obstacles: each as a shape, and as a mesh inscribed in it
/// (for the truth).
struct Scene {
    shapes: Vec<ShapeObstacle<f64>>,
    meshes: Vec<Obstacle<f64>>,
}

fn load(name: &str) -> Result<Scene, Error> {
    let path = format!(
        "{}/data/mbm/{name}.json",
        concat!(env!("CARGO_MANIFEST_DIR"), "/..")
    );
    let json: Value = serde_json::from_str(&std::fs::read_to_string(&path)?)?;
    let mut scene = Scene {
        shapes: Vec::new(),
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
        scene
            .meshes
            // The box as its 12 triangles, exactly (`2 h / 2` is `h`).
            .push(Obstacle::try_new(
                name,
                bodies::cuboid(h.map(|x| 2.0 * x))?,
                pose,
            )?);
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
        scene
            .meshes
            // The 64-sided prism inscribed, along the file's own z.
            .push(Obstacle::try_new(
                name,
                bodies::prism(r, 2.0 * h, 64, 1)?,
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
        scene
            .meshes
            .push(Obstacle::try_new(name, bodies::icosphere(r, 2)?, pose)?);
    }
    Ok(scene)
}

fn main() -> Result<(), Error> {
    let mut args = Args::from_env(
        "planner_edges [--edges 10000] [--truth 500] [--seed 1] [--scene S] [--write-edges DIR] [--vamp DIR] [--first-contact]",
    );
    let edges: usize = args.value_or("--edges", 10_000);
    let truth_edges: usize = args.value_or("--truth", 500);
    let seed: u64 = args.value_or("--seed", 1);
    let write: String = args.value_or("--write-edges", String::new());
    let only: String = args.value_or("--scene", String::new());
    let first = args.flag("--first-contact");
    let vamp: String = args.value_or("--vamp", String::new());
    args.finish();
    let (arm, _) = bare_arm_scene(Arm::Panda)?;
    let limits = joint_limits(arm.chain());
    println!(
        "the Panda ({} links, its collision meshes), random edges of 0.05 to 0.3 rad, one core; CPU: {}",
        arm.chain().link_count(),
        cpu_name()
    );
    for name in SCENES {
        if !only.is_empty() && only != name {
            continue;
        }
        let loaded = load(name)?;
        let mut scene: ChainScene<f64> = arm.clone();
        scene.set_params(ChainParams::default().with_within_limits(true))?;
        let mut meshed = arm.clone();
        if std::env::var_os("PE_NOSHAPES").is_none() {
            for s in loaded.shapes {
                scene.add_shape(s);
            }
        }
        if let Ok(pair) = std::env::var("PE_PAIR") {
            let p: Vec<usize> = pair.split(',').filter_map(|x| x.parse().ok()).collect();
            let n = scene.chain().link_count();
            for a in 0..n {
                for b in 0..n {
                    if a != b && !(a.min(b) == p[0].min(p[1]) && a.max(b) == p[0].max(p[1])) {
                        scene.allow_collision(a, b);
                    }
                }
            }
        }
        if std::env::var_os("PE_NOSELF").is_some() {
            let n = scene.chain().link_count();
            for a in 0..n {
                for b in 0..n {
                    if a != b {
                        scene.allow_collision(a, b);
                    }
                }
            }
        }
        for m in loaded.meshes {
            meshed.add_obstacle(m);
        }
        let truth = Truth::new(&meshed);
        let mut rng = Rng::new(seed);
        let mut range = |lo: f64, hi: f64| rng.range(lo, hi);
        let list: Vec<(Vec<f64>, Vec<f64>)> = (0..edges)
            .map(|_| panda_edge(&mut range, &limits))
            .collect();
        if !write.is_empty() {
            let mut out = String::new();
            for (a, b) in &list {
                for x in a[..7].iter().chain(&b[..7]) {
                    write!(out, "{x:.17e} ")?;
                }
                out.push('\n');
            }
            std::fs::create_dir_all(&write)?;
            std::fs::write(format!("{write}/{name}.edges"), out)?;
        }
        let mut checker = scene.edge_checker();
        let mut times = Vec::with_capacity(edges);
        let (mut colliding, mut undecided, mut tests, mut intervals) = (0, 0, 0usize, 0usize);
        let mut verdicts = Vec::with_capacity(edges);
        let mut work = Vec::with_capacity(edges);
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
            if std::env::var_os("PE_SLOW").is_some()
                && times[times.len() - 1]
                    > std::env::var("PE_SLOW")
                        .ok()
                        .and_then(|v| v.parse().ok())
                        .unwrap_or(3e-3)
            {
                println!(
                    "    slow {:.2} ms: {:?} {:?}",
                    times[times.len() - 1] * 1e3,
                    report.outcome,
                    report.stats
                );
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
                    EdgeOutcome::Contact { free_until, .. }
                    | EdgeOutcome::Undecided { free_until }
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
            "  {} shapes; median us {:.1}; undecided {undecided}; per edge: {:.0} tests, {:.1} intervals; truth over the first {}: {truth_colliding} touching",
            scene.shapes().len(),
            sorted[edges / 2] * 1e6,
            tests as f64 / edges as f64,
            intervals as f64 / edges as f64,
            truth_edges.min(edges)
        );
    }
    Ok(())
}
