//! Benchmark of the conservative-advancement time of impact of two torus
//! knots: the seed's Table 1 scenario (torus knot vs torus knot at 2.8K, 11K
//! and 34K triangles), in milliseconds per query.
//!
//! The queries (`motion_bound::testkit::table1`, shared with
//! the `table1` report): per size, 8 copies of the knot turned by seeded
//! random rotations (built once, outside the timing, with their ball trees),
//! and a fixed seeded list of [`QUERIES`] fly-bys over `[0, 1]`
//! (`testkit::toi::fly_by` with spin [`SPIN`] = 2 rad per unit time for A,
//! up to 0.5 for B), contact distance `1e-3`, default time tolerance
//! (`1e-9`) and iteration limit, in `f64`.
//!
//! * `toi_<size>/nevq` and `toi_<size>/evq`: each criterion iteration runs
//!   the next query of the list (cycling), making the `MeshPair` and running
//!   `time_of_impact`, so criterion's mean is the mean time per query over
//!   the list. `toi_<size>/evq_seed_steps`: EVQ stepping as the seed does
//!   (absolute speeds over the rest of the interval: `one_sided` off,
//!   horizon factor 0), for the ratio that one-sided bounds and the
//!   time-resolved step buy.
//! * `toi_<size>/parry_nonlinear`: parry3d-f64's `cast_shapes_nonlinear` on
//!   the same meshes (as parry `TriMesh`es) and motions, cycling over the
//!   first [`PARRY_QUERIES`] queries, one query per sample (flat sampling,
//!   10 samples; criterion warns that it cannot finish in the 1 s target,
//!   which is expected), and `nevq_first10`/`evq_first10`: ours on those same
//!   queries, for the ratio. Parry takes seconds per query at 2.8K triangles
//!   (1 to 12 s here, depending on the machine's load) and about
//!   proportionally longer for larger meshes: it always runs at 2.8K, and a
//!   larger size whose parry run is estimated (from the smaller size's time
//!   per query and triangle) at more than [`PARRY_BUDGET_S`] seconds is
//!   skipped; the output says so.
//!
//! Before timing, the motion mapping to parry is checked on the first query:
//! every vertex of both bodies placed by us and by parry at `t = 0.5` must
//! agree to `1e-12`.
//!
//! `cargo bench -p motion-bound-compare --bench toi` takes about 4 to 5 minutes on two shared cores
//! (about 2 of them for parry at 2.8K);
//! `TOI_SIZES=2.8K cargo bench --bench toi` builds and runs one size (a
//! comma-separated list of `2.8K`, `11K`, `34K`; criterion's own name filter
//! still applies within a size). `examples/table1.rs`
//! prints the whole table (iterations, contact fractions, traversal counters,
//! ground truth) from one run.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{BenchmarkId, Criterion, SamplingMode};
use motion_bound::bodies::TorusKnotSize;
use motion_bound::ca::BoundChoice;

// The example reads fields (reach, parry's answers) that the benchmark does not.
use motion_bound::testkit::table1::{label, KnotScene, SPIN};
#[allow(dead_code)]
use motion_bound_compare::parry::{mapping_error, parry_meshes, parry_toi};

/// Queries in each size's list.
const QUERIES: usize = 200;
/// Queries of the list that parry (and ours, for the ratio) run.
const PARRY_QUERIES: usize = 10;
/// The longest a size's parry measurement may take, estimated, in seconds.
const PARRY_BUDGET_S: f64 = 120.0;

/// The target time of each of our benchmarks: enough for criterion's 20
/// samples to cycle through the 200-query list about 2 to 4 times.
fn measurement_time(size: TorusKnotSize) -> Duration {
    Duration::from_secs(match size {
        TorusKnotSize::K2_8 => 4,
        TorusKnotSize::K11 => 8,
        TorusKnotSize::K34 => 15,
    })
}

fn bench_size(c: &mut Criterion, size: TorusKnotSize, parry_per_triangle: &mut Option<f64>) {
    let name = format!("toi_{}", label(size));
    let scene = KnotScene::new(size, QUERIES, SPIN);
    let q0 = &scene.queries[0];
    let err = mapping_error(&scene, q0, 0.5);
    assert!(
        err <= 1e-12,
        "parry and we place the bodies {err} apart at t = 0.5"
    );

    let mut group = c.benchmark_group(&name);
    group
        .sample_size(20)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(measurement_time(size));
    let seed_steps = KnotScene::params(BoundChoice::Evq)
        .with_one_sided(false)
        .with_horizon_factor(0.0);
    for (id, params, first) in [
        ("nevq", KnotScene::params(BoundChoice::Nevq), true),
        ("evq", KnotScene::params(BoundChoice::Evq), true),
        ("evq_seed_steps", seed_steps, false),
    ] {
        let lists = [
            (id.to_owned(), &scene.queries[..]),
            (
                format!("{id}_first{PARRY_QUERIES}"),
                &scene.queries[..PARRY_QUERIES],
            ),
        ];
        for (id, list) in lists.into_iter().take(if first { 2 } else { 1 }) {
            group.bench_function(BenchmarkId::from_parameter(id), |b| {
                let mut k = 0;
                b.iter(|| {
                    let q = &list[k % list.len()];
                    k += 1;
                    scene.run(black_box(q), &params).0
                });
            });
        }
    }

    // Parry: always at the smallest size; at a larger size only when its
    // run (a warm-up query and 10 samples of one query) is estimated within
    // the budget, from the smaller size's time per query and triangle, or
    // else from one query.
    let meshes = parry_meshes(&scene);
    let tris = size.triangle_count() as f64;
    let per_query = if size == TorusKnotSize::K2_8 {
        None
    } else if let Some(p) = *parry_per_triangle {
        Some(p * tris)
    } else {
        let start = Instant::now();
        black_box(parry_toi(&meshes, q0));
        Some(start.elapsed().as_secs_f64())
    };
    let estimate = per_query.map(|s| s * (PARRY_QUERIES as f64 + 1.0));
    if let Some(e) = estimate.filter(|&e| e > PARRY_BUDGET_S) {
        println!(
            "{name}/parry_nonlinear: SKIPPED: estimated {:.1} s per query, {e:.0} s for the run \
             (budget {PARRY_BUDGET_S:.0} s)",
            per_query.unwrap_or_default()
        );
    } else {
        // Flat sampling, 10 samples: the warm-up runs one query, and with a
        // query longer than a tenth of the target time every sample is one
        // query (criterion then says it cannot finish in the target time).
        group
            .sampling_mode(SamplingMode::Flat)
            .sample_size(10)
            .warm_up_time(Duration::from_millis(1))
            .measurement_time(Duration::from_secs(1));
        let list = &scene.queries[..PARRY_QUERIES];
        let (mut total, mut count) = (Duration::ZERO, 0_u32);
        group.bench_function(BenchmarkId::from_parameter("parry_nonlinear"), |b| {
            let mut k = 0;
            b.iter_custom(|iters| {
                let start = Instant::now();
                for _ in 0..iters {
                    let q = &list[k % list.len()];
                    k += 1;
                    black_box(parry_toi(&meshes, black_box(q)));
                }
                let elapsed = start.elapsed();
                total += elapsed;
                count += u32::try_from(iters).unwrap_or(u32::MAX);
                elapsed
            });
        });
        if count > 0 {
            *parry_per_triangle = Some(total.as_secs_f64() / f64::from(count) / tris);
        }
    }
    group.finish();
}

// `criterion_group!` would define an undocumented `pub fn`; this is what it
// and `criterion_main!` expand to.
fn main() {
    let mut criterion = Criterion::default().configure_from_args();
    let sizes = std::env::var("TOI_SIZES").unwrap_or_default();
    let mut parry_per_triangle = None;
    for size in TorusKnotSize::ALL {
        if sizes.is_empty() || sizes.split(',').any(|s| s.trim() == label(size)) {
            bench_size(&mut criterion, size, &mut parry_per_triangle);
        }
    }
    criterion.final_summary();
}
