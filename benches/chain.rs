//! A robot arm's motion validation: the Franka Panda (`data/arms`, 9
//! coordinates) in a cluttered cell, certified continuous checking against
//! discrete sampling, and what a chain segment costs against a rigid-body
//! query of the same meshes.
//!
//! The cell is `examples/arm.rs`'s (`tests/common/arm_scene.rs`): a table
//! under the base, a shelf with two boards and side walls, a box and three
//! thin poles, every box meshed in 4 cm cells; Franka's SRDF pairs disabled.
//! (With 12-triangle boxes and no SRDF pairs, a first version of this bench
//! measured 686 ms per segment: the long triangles and the near-permanent
//! link pairs are what the cell and the SRDF take away.) The segments: 50 seeded pairs of collision-free
//! configurations (`collides_at`), each uniform within the joint limits.
//!
//! * `chain/check_segment`: `ChainScene::check_segment`. Each criterion
//!   iteration is a batch of five segments and each sample one iteration,
//!   so the ten samples are the 50 segments once; the time is per segment
//!   (the mean over the 50). The table printed last has the outcomes, the
//!   work, the median and the slowest segments.
//! * `chain/discrete_0.005`, `chain/discrete_0.05`: a discrete validator at
//!   a resolution of 0.5 % and 5 % of the joint-space extent
//!   (`sqrt(sum (hi - lo)^2)`): samples at `i / n`, `n = ceil(|q1 - q0| /
//!   (f extent))`, each `collides_at`, stopping at the first collision; per
//!   segment, measured as above. The table says what each one misses.
//! * `chain/pair_{chain,rigid}/{hit,miss}`: the hand (200 triangles)
//!   against one pole, the hand swept 1.2 rad about joint 1's axis, the pole
//!   on its way (a contact about half way) or 2 cm beyond the hand's reach
//!   (a near miss). The chain query is `check_segment` of a scene of the
//!   Panda in which only the hand has a mesh and only the pole is an
//!   obstacle (one pair); the rigid query is `ca::time_of_impact` through
//!   `MeshPair` of the same two trees, the hand turning at the same rate
//!   about a point of joint 1's axis (`RigidMotion::try_with_local_centre`):
//!   the same sweep exactly. Per query.
//!
//! Criterion warns that ten samples do not fit its (short) target time:
//! one iteration per sample is the point. `cargo bench --features urdf --bench chain`;
//! about a minute and a half (the 50 segments about twice with each
//! validator).

#[path = "../tests/common/arm_scene.rs"]
mod arm_scene;
use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{Criterion, SamplingMode};
use motion_bound::ca::{time_of_impact, CaParams, MeshPair};
use motion_bound::chain::{Chain, ChainBuilder, ChainScene, ChainStats, Obstacle, SegmentOutcome};
use motion_bound::testkit::toi::Rng;
use motion_bound::{bodies, BodyPoint, Isometry, Pose, RigidMotion, Rotation, TriMesh, Vec3};

/// The Panda's ready pose (seven arm joints, two fingers).
const READY: [f64; 9] = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785, 0.02, 0.02];

/// Segments benchmarked.
const SEGMENTS: usize = 50;

/// Discrete resolutions, as fractions of the joint-space extent.
const RESOLUTIONS: [f64; 2] = [0.005, 0.05];

/// A box of half extents `half` about its origin: 8 corners, 12 triangles
/// (`bodies::cuboid`: `2 h / 2` is `h`).
fn box_mesh(half: [f64; 3]) -> TriMesh<f64> {
    bodies::cuboid(half.map(|x| 2.0 * x)).expect("a box")
}

fn box_obstacle(name: &str, centre: [f64; 3], half: [f64; 3]) -> Obstacle<f64> {
    Obstacle::try_new(
        name,
        box_mesh(half),
        Pose::from_translation(Vec3::from_array(centre)),
    )
    .expect("a box obstacle")
}

/// The joint-space extent `sqrt(sum (hi - lo)^2)` and the limits.
fn limits(chain: &Chain<f64>) -> (Vec<[f64; 2]>, f64) {
    let lim: Vec<[f64; 2]> = chain
        .limits()
        .into_iter()
        .map(|l| l.unwrap_or([-std::f64::consts::PI, std::f64::consts::PI]))
        .collect();
    let extent = lim
        .iter()
        .map(|[lo, hi]| (hi - lo) * (hi - lo))
        .sum::<f64>()
        .sqrt();
    (lim, extent)
}

/// A collision-free configuration uniform within the limits.
fn free_configuration(scene: &ChainScene<f64>, lim: &[[f64; 2]], rng: &mut Rng) -> Vec<f64> {
    loop {
        let q: Vec<f64> = lim.iter().map(|[lo, hi]| rng.range(*lo, *hi)).collect();
        if !scene.collides_at(&q).expect("a valid configuration") {
            return q;
        }
    }
}

/// A discrete validator: the first colliding sample's time, if any.
fn discrete(scene: &ChainScene<f64>, q0: &[f64], q1: &[f64], step: f64) -> Option<f64> {
    let len = q0
        .iter()
        .zip(q1)
        .map(|(a, b)| (b - a) * (b - a))
        .sum::<f64>()
        .sqrt();
    let n = ((len / step).ceil() as usize).max(1);
    let mut q = vec![0.0; q0.len()];
    for i in 0..=n {
        let t = i as f64 / n as f64;
        for (k, x) in q.iter_mut().enumerate() {
            *x = q0[k] + t * (q1[k] - q0[k]);
        }
        if scene.collides_at(&q).expect("a valid configuration") {
            return Some(t);
        }
    }
    None
}

/// The chain with only `keep`'s mesh (same links, joints and coordinates).
fn only_link(chain: &Chain<f64>, keep: usize) -> Chain<f64> {
    let mut b = ChainBuilder::new();
    for l in 0..chain.link_count() {
        let mesh = (l == keep).then(|| chain.link_mesh(l).cloned()).flatten();
        let name = chain.link_name(l).expect("a link");
        assert_eq!(b.add_link(name, mesh), Ok(l), "links in order");
    }
    for j in chain.joints() {
        b.add_joint(j.clone()).expect("the chain's joint");
    }
    b.build().expect("the same tree").with_base(chain.base())
}

/// The rotation of a row-major rotation matrix (Shepperd's method).
fn rotation_of(m: &[[f64; 3]; 3]) -> Rotation<f64> {
    let tr = m[0][0] + m[1][1] + m[2][2];
    let (w, x, y, z) = if tr > 0.0 {
        let s = (tr + 1.0).sqrt() * 2.0;
        (
            0.25 * s,
            (m[2][1] - m[1][2]) / s,
            (m[0][2] - m[2][0]) / s,
            (m[1][0] - m[0][1]) / s,
        )
    } else if m[0][0] > m[1][1] && m[0][0] > m[2][2] {
        let s = (1.0 + m[0][0] - m[1][1] - m[2][2]).sqrt() * 2.0;
        (
            (m[2][1] - m[1][2]) / s,
            0.25 * s,
            (m[0][1] + m[1][0]) / s,
            (m[0][2] + m[2][0]) / s,
        )
    } else if m[1][1] > m[2][2] {
        let s = (1.0 + m[1][1] - m[0][0] - m[2][2]).sqrt() * 2.0;
        (
            (m[0][2] - m[2][0]) / s,
            (m[0][1] + m[1][0]) / s,
            0.25 * s,
            (m[1][2] + m[2][1]) / s,
        )
    } else {
        let s = (1.0 + m[2][2] - m[0][0] - m[1][1]).sqrt() * 2.0;
        (
            (m[1][0] - m[0][1]) / s,
            (m[0][2] + m[2][0]) / s,
            (m[1][2] + m[2][1]) / s,
            0.25 * s,
        )
    };
    let r = Rotation::try_from_quaternion(w, x, y, z).expect("a rotation");
    let back = r.matrix();
    let off = (0..9)
        .map(|k| (back[k / 3][k % 3] - m[k / 3][k % 3]).abs())
        .fold(0.0, f64::max);
    assert!(off < 1e-9, "the quaternion of {m:?} gives {back:?}");
    r
}

fn outcome_name(o: &SegmentOutcome<f64>) -> String {
    match o {
        SegmentOutcome::Contact(c) => format!("contact at t = {:.4}", c.time),
        SegmentOutcome::Separated => "separated".into(),
        other => format!("{other:?}"),
    }
}

/// The hand-and-pole comparison: the one-pair chain scene, the pole, and
/// its (still) rigid motion.
struct PairCase {
    name: &'static str,
    scene: ChainScene<f64>,
    pole: Obstacle<f64>,
    still: RigidMotion<f64>,
}

/// Segments per criterion iteration: ten samples of one iteration each are
/// the 50 segments once.
const BATCH: usize = 5;

/// One batch of segments per iteration, batch after batch (by a counter that
/// persists across criterion's calls, so that any ten consecutive batches
/// are the 50 segments once); the time is per segment. `run` times one
/// segment and keeps its result.
fn bench_batches<R>(
    g: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    name: &str,
    results: &mut [Option<(R, f64)>],
    mut run: impl FnMut(usize) -> R,
) {
    let mut calls = 0usize;
    g.bench_function(name, |bench| {
        bench.iter_custom(|iters| {
            let mut total = Duration::ZERO;
            for _ in 0..iters {
                let k = calls % (SEGMENTS / BATCH);
                calls += 1;
                for (i, slot) in results.iter_mut().enumerate().skip(k * BATCH).take(BATCH) {
                    let start = Instant::now();
                    let r = black_box(run(i));
                    let e = start.elapsed();
                    total += e;
                    *slot = Some((r, e.as_secs_f64()));
                }
            }
            total / BATCH as u32
        });
    });
}

/// The results of every segment: those criterion kept, the others run now
/// (when a filter left the benchmark out).
fn complete<R>(results: Vec<Option<(R, f64)>>, mut run: impl FnMut(usize) -> R) -> Vec<(R, f64)> {
    results
        .into_iter()
        .enumerate()
        .map(|(i, r)| {
            r.unwrap_or_else(|| {
                let start = Instant::now();
                let r = run(i);
                (r, start.elapsed().as_secs_f64())
            })
        })
        .collect()
}

fn length(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (y - x) * (y - x))
        .sum::<f64>()
        .sqrt()
}

fn main() {
    println!("chain: CPU {}", motion_bound_devkit::cpu_name());
    // The scene of `examples/arm.rs`: boxes meshed in 4 cm cells, Franka's
    // SRDF pairs disabled.
    let (scene, allowed) = arm_scene::arm_scene(arm_scene::Arm::Panda).expect("the Panda scene");
    let panda = scene.chain().clone();
    assert!(
        !scene.collides_at(&READY).expect("ready pose"),
        "the ready pose is free"
    );
    let triangles: usize = (0..panda.link_count())
        .filter_map(|l| panda.link_mesh(l))
        .map(TriMesh::triangle_count)
        .sum();
    let (lim, extent) = limits(&panda);
    let mut rng = Rng::new(0xC4A1_2025);
    let segments: Vec<(Vec<f64>, Vec<f64>)> = (0..SEGMENTS)
        .map(|_| {
            let q0 = free_configuration(&scene, &lim, &mut rng);
            let q1 = free_configuration(&scene, &lim, &mut rng);
            (q0, q1)
        })
        .collect();
    println!(
        "chain: Panda, {} links ({} triangles), {} coordinates; {} obstacles; {} pairs allowed at the ready pose; clearance there {:.4}; joint-space extent {extent:.3}; {SEGMENTS} segments, mean length {:.3}",
        panda.link_count(),
        triangles,
        panda.dof(),
        scene.obstacles().len(),
        allowed.len(),
        scene.clearance(&READY).expect("ready pose").0,
        segments.iter().map(|(a, b)| length(a, b)).sum::<f64>() / SEGMENTS as f64
    );

    // One pair: the hand and a pole, the hand swept about the base's
    // vertical axis by joint 1 (1.2 rad): every hand point keeps its
    // distance from the axis. "hit": a pole at the hand's middle radius, 0.6
    // rad ahead of its leading edge (a contact about half way); "miss": the
    // same pole 2 cm beyond the hand's farthest point (a near miss).
    let hand = panda.link_index("panda_hand").expect("the hand");
    let single = only_link(&panda, hand);
    let turn = 1.2;
    let mut q1 = READY;
    q1[0] += turn;
    let poses0 = panda.try_forward_kinematics(&READY).expect("ready");
    let poses1 = panda.try_forward_kinematics(&q1).expect("turned");
    let mesh = panda.link_mesh(hand).expect("the hand's mesh");
    let (r_min, r_max, lead) = mesh
        .vertices()
        .iter()
        .map(|v| poses0[hand].transform_point(*v))
        .fold((f64::INFINITY, 0.0f64, -f64::INFINITY), |(lo, hi, a), p| {
            let r = (p.x * p.x + p.y * p.y).sqrt();
            (lo.min(r), hi.max(r), a.max(p.y.atan2(p.x)))
        });
    let height = poses0[hand].translation.z;
    // The rigid motion of the same sweep: turning about joint 1's world
    // axis (through a point of it, the rotation centre) at 1.2 rad per unit
    // time, that point still.
    let joint1 = panda.joints().next().expect("joint 1");
    let frame = {
        let parent = poses0[joint1.parent];
        let o = joint1.origin;
        Pose::new(
            [0, 1, 2].map(|i| {
                [0, 1, 2].map(|j| {
                    (0..3)
                        .map(|k| parent.rotation[i][k] * o.rotation[k][j])
                        .sum()
                })
            }),
            parent.transform_point(o.translation),
        )
    };
    let axis = frame.transform_vector(panda.joint_axis(0).expect("joint 1's axis"));
    let start = Isometry::try_new(
        rotation_of(&poses0[hand].rotation),
        poses0[hand].translation,
    )
    .expect("the hand's pose");
    let pivot = poses0[hand].inverse_transform_vector(frame.translation - poses0[hand].translation);
    let hand_motion = RigidMotion::try_from_start(start, Vec3::ZERO, axis * turn, 1.0)
        .and_then(|m| m.try_with_local_centre(pivot))
        .expect("a bounded motion");
    for v in mesh.vertices().iter().step_by(17) {
        let rigid = hand_motion
            .point_at(BodyPoint::new(v[0], v[1], v[2]), 1.0)
            .to_vec3();
        let arm = poses1[hand].transform_point(*v);
        assert!(
            (rigid - arm).length() < 1e-9,
            "the rigid motion ends where the hand does"
        );
    }
    let hand_tree = panda.link_tree(hand).expect("the hand's mesh");
    let angle = lead + 0.6;
    let pair_cases: Vec<PairCase> = [
        ("hit", 0.5 * (r_min + r_max)),
        ("miss", r_max + 0.02 + 0.005),
    ]
    .into_iter()
    .map(|(name, r)| {
        let centre = [r * angle.cos(), r * angle.sin(), height];
        let pole = box_obstacle("pole", centre, [0.005, 0.005, 0.5]);
        let still = RigidMotion::try_from_start(
            Isometry::try_from_translation(Vec3::from_array(centre)).expect("a pose"),
            Vec3::ZERO,
            Vec3::ZERO,
            1.0,
        )
        .expect("still");
        let mut scene = ChainScene::new(single.clone());
        scene.add_obstacle(pole.clone());
        PairCase {
            name,
            scene,
            pole,
            still,
        }
    })
    .collect();
    let ca = CaParams::default();
    println!(
        "pair: hand ({} triangles, {r_min:.3} to {r_max:.3} from joint 1's axis) against a pole (12 triangles), turning {turn} rad about joint 1's axis",
        hand_tree.triangle_count()
    );
    for PairCase {
        name,
        scene: s,
        pole,
        still,
    } in &pair_cases
    {
        let chain = s.check_segment(&READY, &q1).expect("valid");
        let rigid = time_of_impact(
            &mut MeshPair::new(hand_tree, pole.tree()),
            &hand_motion,
            still,
            &ca,
        )
        .expect("valid");
        println!(
            "pair {name}: chain {} ({} iterations, {} node pairs); rigid {} ({} iterations)",
            outcome_name(&chain.outcome),
            chain.stats.iterations,
            chain.stats.node_pairs,
            rigid
                .outcome
                .earliest_possible_contact()
                .map_or("separated".into(), |t| format!("contact at t = {t:.4}")),
            rigid.iterations,
        );
    }

    let mut c = Criterion::default()
        .configure_from_args()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300));
    let mut g = c.benchmark_group("chain");
    // One iteration per sample (a batch, or one pair query).
    g.sampling_mode(SamplingMode::Flat);
    g.measurement_time(Duration::from_millis(100));
    let mut checked = vec![None; SEGMENTS];
    bench_batches(&mut g, "check_segment", &mut checked, |i| {
        let (a, b) = &segments[i];
        scene.check_segment(a, b).expect("valid")
    });
    let mut sampled = Vec::new();
    for f in RESOLUTIONS {
        let step = f * extent;
        let mut found = vec![None; SEGMENTS];
        bench_batches(&mut g, &format!("discrete_{f}"), &mut found, |i| {
            let (a, b) = &segments[i];
            discrete(&scene, a, b, step)
        });
        sampled.push(found);
    }
    for PairCase {
        name,
        scene: s,
        pole,
        still,
    } in &pair_cases
    {
        g.bench_function(format!("pair_chain/{name}"), |bench| {
            bench.iter(|| black_box(s.check_segment(&READY, &q1).expect("valid").outcome));
        });
        g.bench_function(format!("pair_rigid/{name}"), |bench| {
            bench.iter(|| {
                black_box(
                    time_of_impact(
                        &mut MeshPair::new(hand_tree, pole.tree()),
                        &hand_motion,
                        still,
                        &ca,
                    )
                    .expect("valid")
                    .outcome,
                )
            });
        });
    }
    g.finish();

    // What each validator said, and the work.
    let checked = complete(checked, |i| {
        let (a, b) = &segments[i];
        scene.check_segment(a, b).expect("valid")
    });
    let contacts = checked
        .iter()
        .filter(|(r, _)| r.outcome.contact().is_some())
        .count();
    let separated = checked
        .iter()
        .filter(|(r, _)| r.outcome == SegmentOutcome::Separated)
        .count();
    let sum = |f: &dyn Fn(&ChainStats) -> usize| {
        checked.iter().map(|(r, _)| f(&r.stats)).sum::<usize>() as f64 / SEGMENTS as f64
    };
    let mut order: Vec<usize> = (0..SEGMENTS).collect();
    order.sort_by(|&i, &j| checked[i].1.total_cmp(&checked[j].1));
    println!(
        "check_segment: {contacts} contacts, {separated} separated, {} undecided; per segment {:.1} pairs, {:.1} culled, {:.1} advanced, {:.1} iterations, {:.0} node pairs; mean {:.1} ms, median {:.1} ms; slowest: {}",
        SEGMENTS - contacts - separated,
        sum(&|s| s.pairs),
        sum(&|s| s.culled),
        sum(&|s| s.advanced),
        sum(&|s| s.iterations),
        sum(&|s| s.node_pairs),
        checked.iter().map(|(_, t)| t).sum::<f64>() * 1e3 / SEGMENTS as f64,
        checked[order[SEGMENTS / 2]].1 * 1e3,
        order[SEGMENTS - 3..]
            .iter()
            .rev()
            .map(|&i| format!(
                "#{i} {:.0} ms ({}, {} iterations)",
                checked[i].1 * 1e3,
                outcome_name(&checked[i].0.outcome),
                checked[i].0.stats.iterations,
            ))
            .collect::<Vec<_>>()
            .join(", ")
    );
    for (f, found) in RESOLUTIONS.into_iter().zip(sampled) {
        let step = f * extent;
        let found = complete(found, |i| {
            let (a, b) = &segments[i];
            discrete(&scene, a, b, step)
        });
        let mut hits = 0;
        let mut stepped_over = 0;
        let mut samples = 0usize;
        for (((a, b), (r, _)), (first, _)) in segments.iter().zip(&checked).zip(&found) {
            hits += usize::from(first.is_some());
            if r.outcome.contact().is_some() && first.is_none() {
                stepped_over += 1;
            }
            let n = ((length(a, b) / step).ceil() as usize).max(1);
            samples += match first {
                Some(t) => (t * n as f64).round() as usize + 1,
                None => n + 1,
            };
        }
        println!(
            "discrete {f}: {hits} colliding, {stepped_over} of check_segment's contacts not seen (stepped over, or only within its 1 mm contact distance); {:.1} samples and {:.2} ms per segment",
            samples as f64 / SEGMENTS as f64,
            found.iter().map(|(_, t)| t).sum::<f64>() * 1e3 / SEGMENTS as f64
        );
    }
    c.final_summary();
}
