//! A robot arm in a cluttered scene: random joint-space segments checked by
//! conservative advancement (`ChainScene::check_segment`), by the discrete
//! checks planners run today (a static check every 0.005 and every 0.05 of
//! the joint-space extent, as OMPL's `longest_valid_segment_fraction`), and
//! by an independent ground truth (dense sampling with a crude speed bound
//! and exact triangle distances, `tests/common/chain_truth.rs`).
//!
//! ```text
//! cargo run --release --features urdf --example arm [-- --segments 1000 --arm panda|kuka --seed 7]
//! ```
//!
//! The last line: `segments S, colliding C, missed M, late L, mean ms per
//! segment X, discrete 0.005: missed D1 ms Y1, discrete 0.05: missed D2 ms Y2`
//! (`colliding`: segments on which the truth finds surfaces meeting;
//! `missed`: of those, segments reported free; `late`: contacts reported
//! after the truth's first touching sample).

#[path = "../tests/common/arm_scene.rs"]
mod arm_scene;
#[path = "../tests/common/chain_truth.rs"]
mod chain_truth;

use std::time::Instant;

use arm_scene::{arm_scene, Arm};
use chain_truth::Truth;
use motion_bound::chain::{ChainScene, EdgeOutcome, SegmentOutcome};
use motion_bound_devkit::{cpu_name, Args, Rng};

/// The discrete check: a static check at `i / n`, `i = 1..=n`, with `n`
/// samples of at most `fraction * extent` apart; the first colliding
/// sample's time, if any.
fn discrete(
    scene: &ChainScene<f64>,
    q0: &[f64],
    q1: &[f64],
    fraction: f64,
    extent: f64,
) -> Result<Option<f64>, Box<dyn std::error::Error>> {
    let len = q0
        .iter()
        .zip(q1)
        .map(|(a, b)| (b - a) * (b - a))
        .sum::<f64>()
        .sqrt();
    let n = (len / (fraction * extent)).ceil().max(1.0) as usize;
    for i in 1..=n {
        let t = i as f64 / n as f64;
        let q: Vec<f64> = q0.iter().zip(q1).map(|(a, b)| a + t * (b - a)).collect();
        if scene.collides_at(&q)? {
            return Ok(Some(t));
        }
    }
    Ok(None)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = Args::from_env("arm [--segments 1000] [--arm panda|kuka] [--seed 7]");
    let segments: usize = args.value_or("--segments", 1000);
    let seed: u64 = args.value_or("--seed", 7);
    let arm: String = args.value_or("--arm", "panda".into());
    args.finish();
    let which = match arm.as_str() {
        "panda" => Arm::Panda,
        "kuka" => Arm::Kuka,
        other => return Err(format!("--arm {other}: panda or kuka").into()),
    };
    let (scene, defaults) = arm_scene(which)?;
    let limits: Vec<[f64; 2]> = scene
        .chain()
        .limits()
        .into_iter()
        .map(|l| l.unwrap_or([-std::f64::consts::PI, std::f64::consts::PI]))
        .collect();
    let extent = limits
        .iter()
        .map(|[lo, hi]| (hi - lo) * (hi - lo))
        .sum::<f64>()
        .sqrt();
    let truth = Truth::new(&scene);
    println!(
        "arm {arm} ({} joints, {} links), {} obstacles, {} pairs checked ({} link pairs allowed at the ready pose); contact distance {}; CPU: {}",
        scene.chain().dof(),
        scene.chain().link_count(),
        scene.obstacles().len(),
        truth.pairs.len(),
        defaults.len(),
        scene.params().contact_distance,
        cpu_name()
    );
    let mut rng = Rng::new(seed);
    let sample_free = |rng: &mut Rng| -> Result<Vec<f64>, Box<dyn std::error::Error>> {
        loop {
            let q: Vec<f64> = limits.iter().map(|&[lo, hi]| rng.range(lo, hi)).collect();
            if !scene.collides_at(&q)? {
                return Ok(q);
            }
        }
    };
    let (mut colliding, mut missed, mut late, mut undecided, mut early_far) = (0, 0, 0, 0, 0);
    let (mut ours_s, mut truth_s) = (0.0f64, 0.0f64);
    let mut disc = [(0.005, 0usize, 0.0f64), (0.05, 0, 0.0)];
    let mut iterations = 0usize;
    // The work and outcomes, summed, to compare two builds.
    let (mut node_pairs, mut contacts, mut separations, mut time_sum) =
        (0usize, 0usize, 0usize, 0.0);
    // The edge query (`ChainScene::check_edge`) on the same segments.
    let mut checker = scene.edge_checker();
    let (mut edge_s, mut edge_tests, mut edge_missed, mut edge_late, mut edge_undecided) =
        (0.0f64, 0usize, 0usize, 0usize, 0usize);
    for s in 0..segments {
        let q0 = sample_free(&mut rng)?;
        let q1 = sample_free(&mut rng)?;
        let start = Instant::now();
        let report = scene.check_segment(&q0, &q1)?;
        ours_s += start.elapsed().as_secs_f64();
        iterations += report.stats.iterations;
        node_pairs += report.stats.node_pairs;
        match report.outcome {
            SegmentOutcome::Contact(c) => {
                contacts += 1;
                time_sum += c.time;
            }
            SegmentOutcome::Separated => separations += 1,
            _ => {}
        }
        let start = Instant::now();
        let edge = checker.check(&q0, &q1)?;
        edge_s += start.elapsed().as_secs_f64();
        edge_tests += edge.stats.tests;
        let start = Instant::now();
        let sampled = truth.sample(&q0, &q1, 1e-4);
        truth_s += start.elapsed().as_secs_f64();
        let mut found = Vec::new();
        for d in &mut disc {
            let start = Instant::now();
            let hit = discrete(&scene, &q0, &q1, d.0, extent)?;
            d.2 += start.elapsed().as_secs_f64();
            found.push(hit);
        }
        if std::env::var_os("ARM_VERBOSE").is_some() {
            println!(
                "segment {s}: {:?} ({} iterations, {} node pairs), truth {:?} ({} samples), discrete {:?}",
                report.outcome, report.stats.iterations, report.stats.node_pairs, sampled.touch, sampled.samples, found
            );
        }
        match (sampled.touch, edge.outcome) {
            (Some((t_touch, _, _)), EdgeOutcome::Free) => {
                edge_missed += 1;
                println!("segment {s}: the edge query MISSED the truth's touch at {t_touch}");
            }
            (Some((t_touch, _, _)), EdgeOutcome::Contact { free_until, .. })
                if free_until > t_touch =>
            {
                edge_late += 1;
                println!("segment {s}: the edge query is LATE: free until {free_until} past the truth's touch at {t_touch}");
            }
            (_, EdgeOutcome::Undecided { .. }) => edge_undecided += 1,
            _ => {}
        }
        if let Some((t_touch, _, pair)) = sampled.touch {
            colliding += 1;
            for (d, hit) in disc.iter_mut().zip(&found) {
                if hit.is_none() {
                    d.1 += 1;
                }
            }
            match report.outcome {
                SegmentOutcome::Contact(c) if c.time <= t_touch => {}
                SegmentOutcome::Contact(c) => {
                    late += 1;
                    println!("segment {s}: LATE contact at {} after the truth's touch at {t_touch} ({pair:?})", c.time);
                }
                SegmentOutcome::Separated => {
                    missed += 1;
                    println!("segment {s}: MISSED the truth's touch at {t_touch} ({pair:?})");
                }
                _ => undecided += 1,
            }
        } else if let SegmentOutcome::IterationLimit { .. } = report.outcome {
            undecided += 1;
        }
        // A contact must be within the contact distance when it is reported.
        if let SegmentOutcome::Contact(c) = report.outcome {
            let q: Vec<f64> = q0
                .iter()
                .zip(&q1)
                .map(|(a, b)| a + c.time * (b - a))
                .collect();
            let (d, _) = truth.min_distance(&q);
            if d > scene.params().contact_distance * (1.0 + 1e-6) {
                early_far += 1;
                println!(
                    "segment {s}: contact at {} with the surfaces {d} apart",
                    c.time
                );
            }
        }
    }
    let n = segments as f64;
    println!(
        "ours: {:.2} iterations per segment; undecided {undecided}; contacts reported beyond the contact distance {early_far}; truth ms per segment {:.3}",
        iterations as f64 / n,
        truth_s / n * 1e3
    );
    println!(
        "work: iterations {iterations}, node pairs {node_pairs}, contacts {contacts}, separations {separations}, contact times' sum {time_sum:.17e}"
    );
    println!(
        "edge queries (check_edge): missed {edge_missed}, late {edge_late}, undecided {edge_undecided}, mean ms per segment {:.4} ({:.0} tests), {:.1} times faster than conservative advancement",
        edge_s / n * 1e3,
        edge_tests as f64 / n,
        ours_s / edge_s
    );
    println!(
        "segments {segments}, colliding {colliding}, missed {missed}, late {late}, mean ms per segment {:.4}, discrete 0.005: missed {} ms {:.4}, discrete 0.05: missed {} ms {:.4}",
        ours_s / n * 1e3,
        disc[0].1,
        disc[0].2 / n * 1e3,
        disc[1].1,
        disc[1].2 / n * 1e3
    );
    if missed + late + early_far + edge_missed + edge_late > 0 {
        return Err("missed, late or far contacts".into());
    }
    Ok(())
}
