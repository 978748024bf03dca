//! Coarse and fine obstacles for the Panda (issue 39's narrow passage, issue
//! 43's coarse and fine surfaces), in two scenes.
//!
//! **The opening** (`--scene opening`): the hand reaching into a cupboard of five plates
//! built around the hand (and fingers) at a reaching pose, its opening 1.5 cm
//! wider than the hand on each side, and 200 random segments from a
//! pose 20 cm back along the hand's approach into it (both ends perturbed by
//! up to 0.025 rad a joint, both free). The same plates
//! three ways: as shapes (cuboids), as coarse meshes (12 triangles a plate)
//! and as fine meshes (a 4 cm grid); each checked by `EdgeChecker::check`
//! against an independent ground truth on its own meshes (the shapes' truth
//! on the coarse meshes: a box is exactly its 12 triangles).
//!
//! **The poles** (`--scene poles`): 20 upright poles of radius 2.5 cm and 1 m
//! around the arm, each a 12-sided prism, coarse as a CAD or URDF file gives
//! it (48 triangles, `bodies::prism` with one segment) and fine (rings every
//! 4 cm: 624 triangles), and random planner edges of 0.05 to 0.3 rad between
//! free configurations; each variant checked against the truth on its own
//! meshes.
//!
//! ```text
//! cargo run --release --features urdf --example narrow_passage [-- --segments 200 --seed 3 --scene opening|poles --first-contact N]
//! ```
//!
//! One line per variant: `S: segments N, colliding C, missed M, late L, mean
//! ms X, median ms Y, p99 ms Z, max ms W`, then the mean and 99th
//! percentile of the pairs measured (`EdgeStats::tests`, a count that does
//! not depend on the machine). With `--first-contact N`, the
//! conservative advancement's first-contact query (`ChainScene::check_segment`)
//! is also timed on the first `N` segments of the mesh variants (its contact
//! time checked against the truth likewise), one line each. `--no-truth`
//! skips the truth (for a run under callgrind: missed and late then read 0);
//! `--variant V` runs only the variants whose name starts with `V`.

#[path = "../tests/common/arm_scene.rs"]
mod arm_scene;
#[path = "../tests/common/chain_truth.rs"]
mod chain_truth;

use std::time::Instant;

use arm_scene::{bare_arm_scene, cuboid, joint_limits, panda_edge, pole_sites, Arm};
use chain_truth::Truth;
use motion_bound::chain::{ChainScene, EdgeOutcome, Obstacle, SegmentOutcome, ShapeObstacle};
use motion_bound::{bodies, Convex, Pose, Vec3};
use motion_bound_devkit::{cpu_name, Args, Rng};

type Error = Box<dyn std::error::Error>;

/// The reaching pose (the hand pointing forward, about 0.55 m out).
const REACH: [f64; 9] = [0.0, 0.45, 0.0, -1.75, 0.0, 2.2, 0.785, 0.04, 0.04];

/// The pose whose hand is the reaching pose's moved `back` along its own
/// approach axis (its `z`), same orientation: gradient descent on the
/// squared position and rotation error with finite differences (the
/// example's own inverse kinematics; only the scene depends on it).
fn retracted(
    chain: &motion_bound::chain::Chain<f64>,
    hand: usize,
    back: f64,
) -> Result<[f64; 9], Error> {
    let goal = chain.try_forward_kinematics(&REACH)?[hand];
    let target = goal.transform_point(Vec3::new(0.0, 0.0, -back));
    let cost = |q: &[f64; 9]| -> Result<f64, Error> {
        let p = chain.try_forward_kinematics(q)?[hand];
        let mut c = (p.translation - target).length_squared();
        for i in 0..3 {
            for j in 0..3 {
                c += 0.05 * (p.rotation[i][j] - goal.rotation[i][j]).powi(2);
            }
        }
        Ok(c)
    };
    let mut q = REACH;
    let mut step = 0.5;
    let mut c = cost(&q)?;
    for _ in 0..4000 {
        let mut g = [0.0; 7];
        for (k, gk) in g.iter_mut().enumerate() {
            let mut e = q;
            e[k] += 1e-6;
            *gk = (cost(&e)? - c) / 1e-6;
        }
        let mut next = q;
        for k in 0..7 {
            next[k] -= step * g[k];
        }
        let cn = cost(&next)?;
        if cn < c {
            q = next;
            c = cn;
            step *= 1.2;
        } else {
            step *= 0.5;
        }
        if c < 1e-10 {
            break;
        }
    }
    Ok(q)
}

/// The five plates (centre and half extents in the hand's frame at
/// `REACH`), around the hand and fingers' box `[lo, hi]` in that frame.
fn plates(lo: [f64; 3], hi: [f64; 3]) -> Vec<(&'static str, [f64; 3], [f64; 3])> {
    let (m, t) = (0.015, 0.01); // the margin each side, the plates' half thickness
    let (x0, x1, y0, y1) = (lo[0] - m, hi[0] + m, lo[1] - m, hi[1] + m);
    // The slot reaches from 0.12 behind the fingertips to 0.03 past them.
    let (z0, z1) = (hi[2] - 0.12, hi[2] + 0.03);
    let (cz, hz) = ((z0 + z1) / 2.0, (z1 - z0) / 2.0);
    let (cx, hx, cy, hy) = (
        (x0 + x1) / 2.0,
        (x1 - x0) / 2.0 + 2.0 * t,
        (y0 + y1) / 2.0,
        (y1 - y0) / 2.0 + 2.0 * t,
    );
    vec![
        ("left", [x0 - t, cy, cz], [t, hy, hz]),
        ("right", [x1 + t, cy, cz], [t, hy, hz]),
        ("bottom", [cx, y0 - t, cz], [hx, t, hz]),
        ("top", [cx, y1 + t, cz], [hx, t, hz]),
        ("back", [cx, cy, z1 + t], [hx, hy, t]),
    ]
}

/// The opening's scenes (shapes, coarse and fine plates) and its segments.
fn opening(arm: &ChainScene<f64>, segments: usize, seed: u64) -> Result<Scenes, Error> {
    let chain = arm.chain();
    let hand = chain.link_index("panda_hand")?;
    let fingers = [
        chain.link_index("panda_leftfinger")?,
        chain.link_index("panda_rightfinger")?,
    ];
    let retract = retracted(chain, hand, 0.2)?;
    let poses = chain.try_forward_kinematics(&REACH)?;
    let frame = poses[hand];
    // The hand's and fingers' vertices in the hand's frame at REACH.
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [-f64::INFINITY; 3]);
    for l in [hand, fingers[0], fingers[1]] {
        let Some(mesh) = chain.link_mesh(l) else {
            continue;
        };
        for v in mesh.vertices() {
            let w = poses[l].transform_point(*v) - frame.translation;
            let local = frame.inverse_transform_vector(w).to_array();
            for k in 0..3 {
                lo[k] = lo[k].min(local[k]);
                hi[k] = hi[k].max(local[k]);
            }
        }
    }
    let place = |c: [f64; 3]| Pose {
        rotation: frame.rotation,
        translation: frame.transform_point(Vec3::from_array(c)),
    };
    let mut shapes = arm.clone();
    let mut coarse = arm.clone();
    let mut fine = arm.clone();
    for (name, c, h) in plates(lo, hi) {
        shapes.add_shape(ShapeObstacle::try_new(
            name,
            Convex::try_cuboid(h)?,
            place(c),
        )?);
        let (m, _) = cuboid([0.0; 3], h, 10.0)?;
        coarse.add_obstacle(Obstacle::try_new(name, m, place(c))?);
        let (m, _) = cuboid([0.0; 3], h, 0.04)?;
        fine.add_obstacle(Obstacle::try_new(name, m, place(c))?);
    }
    let truth_coarse = Truth::new(&coarse);
    let truth_fine = Truth::new(&fine);
    // Segments: both ends perturbed by up to 0.025 rad per joint, free.
    let mut rng = Rng::new(seed);
    let mut list = Vec::new();
    while list.len() < segments {
        let jitter = |q: &[f64; 9], rng: &mut Rng| -> Vec<f64> {
            q.iter()
                .enumerate()
                .map(|(i, x)| {
                    if i < 7 {
                        x + rng.range(-0.025, 0.025)
                    } else {
                        *x
                    }
                })
                .collect()
        };
        let (a, b) = (jitter(&retract, &mut rng), jitter(&REACH, &mut rng));
        if !truth_coarse.touches_at(&a) && !truth_coarse.touches_at(&b) {
            list.push((a, b));
        }
    }
    Ok(Scenes {
        title: format!("the Panda's hand into an opening 1.5 cm wider than the hand each side (five plates), {segments} segments"),
        variants: vec![
            ("shapes (cuboids)", shapes, Truth::new(&coarse), false),
            ("coarse meshes (12 triangles a plate)", coarse, truth_coarse, true),
            ("fine meshes (4 cm grid)", fine, truth_fine, true),
        ],
        list,
    })
}

/// The poles' scenes (coarse and fine prisms) and their edges.
fn poles(arm: &ChainScene<f64>, segments: usize, seed: u64) -> Result<Scenes, Error> {
    let (radius, length, sides) = (0.025, 1.0, 12);
    let mut rng = Rng::new(seed ^ 0x9e37_79b9_7f4a_7c15);
    let mut coarse = arm.clone();
    let mut fine = arm.clone();
    let (thin, ringed) = (
        bodies::prism(radius, length, sides, 1)?,
        bodies::prism(radius, length, sides, (length / 0.04).round() as u32)?,
    );
    for p in pole_sites(&mut rng) {
        let pose = Pose::from_translation(Vec3::new(p[0], p[1], length / 2.0));
        let name = "pole";
        coarse.add_obstacle(Obstacle::try_new(name, thin.clone(), pose)?);
        fine.add_obstacle(Obstacle::try_new(name, ringed.clone(), pose)?);
    }
    let truth_coarse = Truth::new(&coarse);
    let truth_fine = Truth::new(&fine);
    let limits = joint_limits(arm.chain());
    let mut range = |lo: f64, hi: f64| rng.range(lo, hi);
    let mut list = Vec::new();
    while list.len() < segments {
        let (q0, q1) = panda_edge(&mut range, &limits);
        if !truth_coarse.touches_at(&q0) && !truth_coarse.touches_at(&q1) {
            list.push((q0, q1));
        }
    }
    Ok(Scenes {
        title: format!(
            "the Panda among 20 poles (12-sided prisms, radius {radius}, {length} m), {segments} planner edges of 0.05 to 0.3 rad between free configurations"
        ),
        variants: vec![
            ("coarse prisms (48 triangles a pole)", coarse, truth_coarse, true),
            ("fine prisms (rings every 4 cm, 624 triangles a pole)", fine, truth_fine, true),
        ],
        list,
    })
}

/// A scene's variants (name, scene, its truth, whether it is all meshes)
/// and the segments they share.
struct Scenes {
    title: String,
    variants: Vec<(&'static str, ChainScene<f64>, Truth, bool)>,
    list: Vec<(Vec<f64>, Vec<f64>)>,
}

/// Mean, median, 99th percentile and max of `values` (sorted in place).
fn stats(values: &mut [f64]) -> [f64; 4] {
    let n = values.len();
    let mean = values.iter().sum::<f64>() / n as f64;
    values.sort_by(f64::total_cmp);
    [
        mean,
        values[n / 2],
        values[((n as f64 - 1.0) * 0.99) as usize],
        values[n - 1],
    ]
}

/// [`stats`] of times in ms, as printed.
fn summary(times: &mut [f64]) -> String {
    let [mean, median, p99, max] = stats(times);
    format!("mean ms {mean:.3}, median ms {median:.3}, p99 ms {p99:.3}, max ms {max:.3}")
}

fn main() -> Result<(), Error> {
    let mut args = Args::from_env(
        "narrow_passage [--segments 200] [--seed 3] [--scene opening|poles] [--first-contact N] [--no-truth] [--variant coarse|fine|shapes]",
    );
    let segments: usize = args.value_or("--segments", 200);
    let seed: u64 = args.value_or("--seed", 3);
    let only: String = args.value_or("--scene", String::new());
    let first: usize = args.value_or("--first-contact", 0);
    let truth = !args.flag("--no-truth");
    let variant: String = args.value_or("--variant", String::new());
    args.finish();
    let (arm, _) = bare_arm_scene(Arm::Panda)?;
    println!("CPU: {}", cpu_name());
    let mut failed = false;
    for (key, build) in [
        (
            "opening",
            opening as fn(&ChainScene<f64>, usize, u64) -> Result<Scenes, Error>,
        ),
        ("poles", poles),
    ] {
        if !only.is_empty() && only != key {
            continue;
        }
        let scenes = build(&arm, segments, seed)?;
        println!("{}", scenes.title);
        for (name, scene, sampled, meshes) in &scenes.variants {
            if !name.starts_with(variant.as_str()) {
                continue;
            }
            let mut checker = scene.edge_checker();
            let mut times = Vec::new();
            let (mut colliding, mut missed, mut late, mut undecided) = (0, 0, 0, 0);
            let mut touches = Vec::new();
            let mut tests = Vec::new();
            let mut leaves = 0usize;
            for (q0, q1) in &scenes.list {
                let start = Instant::now();
                let report = checker.check(q0, q1)?;
                times.push(start.elapsed().as_secs_f64() * 1e3);
                tests.push(report.stats.tests as f64);
                leaves += report.stats.leaf_tests;
                let touch = if truth {
                    sampled.sample(q0, q1, 1e-4).touch.map(|(t, _, _)| t)
                } else {
                    None
                };
                match (touch, report.outcome) {
                    (Some(_), EdgeOutcome::Free) => missed += 1,
                    (Some(t), EdgeOutcome::Contact { free_until, .. }) if free_until > t => {
                        late += 1
                    }
                    (_, EdgeOutcome::Undecided { .. }) => undecided += 1,
                    _ => {}
                }
                if touch.is_some() {
                    colliding += 1;
                }
                touches.push(touch);
            }
            println!(
                "{name}: segments {}, colliding {colliding}, missed {missed}, late {late}, undecided {undecided}, {}",
                times.len(),
                summary(&mut times)
            );
            let [mean, median, p99, _] = stats(&mut tests);
            println!(
                "    pairs measured (`EdgeStats::tests`) mean {mean:.0}, median {median:.0}, p99 {p99:.0}; leaf pairs measured mean {:.0}",
                leaves as f64 / tests.len() as f64
            );
            failed |= missed + late > 0;
            if first == 0 || !*meshes {
                continue;
            }
            // The first-contact query on the first segments, its contact
            // time against the same truth.
            let mut times = Vec::new();
            let (mut missed, mut late, mut undecided) = (0, 0, 0);
            for ((q0, q1), touch) in scenes.list.iter().zip(&touches).take(first) {
                let start = Instant::now();
                let report = scene.check_segment(q0, q1)?;
                times.push(start.elapsed().as_secs_f64() * 1e3);
                match (touch, report.outcome) {
                    (Some(_), SegmentOutcome::Separated) => missed += 1,
                    (Some(t), SegmentOutcome::Contact(c)) if c.time > *t => late += 1,
                    (_, SegmentOutcome::IterationLimit { .. }) => undecided += 1,
                    _ => {}
                }
            }
            println!(
                "{name}, first contact (check_segment): segments {}, missed {missed}, late {late}, undecided {undecided}, {}",
                times.len(),
                summary(&mut times)
            );
            failed |= missed + late > 0;
        }
    }
    if failed {
        return Err("missed or late".into());
    }
    Ok(())
}
