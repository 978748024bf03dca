//! The Table 1 torus-knot queries with EVQ alone, for comparing two builds of
//! the crate: time per query and instruction counts.
//!
//! ```sh
//! cargo run --release -p motion-bound-compare --example knots -- [--sizes 2.8K,11K,34K] [--queries N] [--skip K] [--bound evq|nevq] [--passes P] [--front on|off] [--witness closest|first] [--witness-tolerance X]
//! ```
//!
//! Runs queries `K .. K + N` of the scene of `--queries`'s length (default:
//! all 200 queries of `table1`), one pass after a warm-up of the first
//! eight, and prints per size: mean ms per query (the `Instant` around each
//! query, as `table1` times it), iterations, node pairs, triangle pairs,
//! contacts and separations; `--passes P` runs them `P` times and prints
//! also the mean over the queries of each one's least time (the counts are
//! the first pass's). `--front on` carries the front from step to
//! step (`MeshParams::carry_front`); `--witness first` stops at the first pair
//! found within the contact distance (`WitnessSearch::First`; default: the
//! closest pair), and `--witness-tolerance X` lets the witness be up to `X`
//! farther than the closest pair (`CaParams::witness_tolerance`). The queries are timed inside
//! `run_queries`, which is never inlined, so that an instruction count can
//! be limited to them (the trees' builds left out):
//!
//! ```sh
//! valgrind --tool=callgrind --collect-atstart=no --toggle-collect='*run_queries*' \
//!     target/release/examples/knots --sizes 2.8K --queries 20
//! ```
//!
//! The file uses only `motion_bound::testkit::table1`, which has not changed
//! since `f8e816b`, so the same file builds against older commits
//! (`docs/performance.md`, entries of 2026-12-03).

use std::process::ExitCode;
use std::time::Instant;

use motion_bound::ca::{BoundChoice, CaOutcome, CaParams, MeshParams, WitnessSearch};
#[allow(deprecated)] // The old path, so that this file still builds against older commits.
use motion_bound::scenes::TorusKnotSize;
use motion_bound::testkit::table1::{label, KnotScene, SPIN};

/// What a run of queries measured.
#[derive(Default)]
struct Totals {
    ms: f64,
    queries: usize,
    iterations: u64,
    node_pairs: u64,
    triangle_pairs: u64,
    contacts: usize,
    separated: usize,
    /// Each query's time, ms.
    per_query: Vec<f64>,
}

/// Runs `queries` of `scene` with `params`, timing each.
#[inline(never)]
fn run_queries(
    scene: &KnotScene,
    skip: usize,
    params: &CaParams<f64>,
    mesh: MeshParams<f64>,
) -> Totals {
    let mut t = Totals::default();
    for q in scene.queries.iter().skip(skip) {
        let start = Instant::now();
        let (report, stats) = scene.run_with(q, params, mesh);
        let ms = start.elapsed().as_secs_f64() * 1e3;
        t.ms += ms;
        t.per_query.push(ms);
        t.queries += 1;
        t.iterations += u64::from(report.iterations);
        t.node_pairs += stats.node_pairs;
        t.triangle_pairs += stats.triangle_pairs;
        match report.outcome {
            CaOutcome::Separated => t.separated += 1,
            CaOutcome::Contact { .. } | CaOutcome::InitialContact(_) => t.contacts += 1,
            _ => {}
        }
    }
    t
}

fn main() -> ExitCode {
    let mut sizes = TorusKnotSize::ALL.to_vec();
    let (mut queries, mut skip, mut bound) = (200, 0, BoundChoice::Evq);
    let mut mesh = MeshParams::default();
    let mut witness = WitnessSearch::default();
    let mut tolerance = 0.0;
    let mut passes = 1;
    let mut it = std::env::args().skip(1);
    while let Some(flag) = it.next() {
        let value = it.next().unwrap_or_default();
        match flag.as_str() {
            "--sizes" => {
                sizes = value
                    .split(',')
                    .filter_map(|s| TorusKnotSize::ALL.into_iter().find(|&k| label(k) == s))
                    .collect();
            }
            "--queries" => queries = value.parse().unwrap_or(0),
            "--skip" => skip = value.parse().unwrap_or(0),
            "--passes" => passes = value.parse().unwrap_or(0),
            "--bound" if value == "nevq" => bound = BoundChoice::Nevq,
            "--bound" if value == "evq" => bound = BoundChoice::Evq,
            "--front" if value == "on" => mesh = mesh.with_carry_front(true),
            "--front" if value == "off" => mesh = mesh.with_carry_front(false),
            "--witness" if value == "closest" => witness = WitnessSearch::Closest,
            "--witness" if value == "first" => witness = WitnessSearch::First,
            "--witness-tolerance" => match value.parse::<f64>() {
                Ok(x) => tolerance = x,
                Err(_) => tolerance = f64::NAN,
            },
            _ => {
                eprintln!(
                    "usage: knots [--sizes 2.8K,11K,34K] [--queries N] [--skip K] [--bound evq|nevq] [--passes P] [--front on|off] [--witness closest|first] [--witness-tolerance X]"
                );
                return ExitCode::FAILURE;
            }
        }
    }
    if queries == 0 || passes == 0 || sizes.is_empty() {
        eprintln!("--queries must be positive and --sizes name 2.8K, 11K or 34K");
        return ExitCode::FAILURE;
    }
    let params = KnotScene::params(bound)
        .with_witness(witness)
        .with_witness_tolerance(tolerance);
    if params.validate().is_err() {
        eprintln!("--witness-tolerance must be finite and at least 0");
        return ExitCode::FAILURE;
    }
    for size in sizes {
        let scene = KnotScene::new(size, skip + queries, SPIN);
        for q in scene.queries.iter().take(8) {
            std::hint::black_box(scene.run_with(q, &params, mesh));
        }
        let mut t = run_queries(&scene, skip, &params, mesh);
        // Each query's least time over the passes (the first pass's counts).
        for _ in 1..passes {
            let again = run_queries(&scene, skip, &params, mesh);
            for (m, a) in t.per_query.iter_mut().zip(&again.per_query) {
                *m = m.min(*a);
            }
        }
        let n = t.queries as f64;
        println!(
            "{:>5}: queries {}, mean ms {:.4}, iterations {:.3}, node pairs {:.1}, triangle pairs {:.1}, contacts {}, separated {}, per-query min ms {:.4} ({} passes)",
            label(size),
            t.queries,
            t.ms / n,
            t.iterations as f64 / n,
            t.node_pairs as f64 / n,
            t.triangle_pairs as f64 / n,
            t.contacts,
            t.separated,
            t.per_query.iter().sum::<f64>() / n,
            passes
        );
    }
    ExitCode::SUCCESS
}
