//! Benchmark of the conservative-advancement time of impact of two torus
//! knots: the seed's Table 1 scenario (torus knot vs torus knot at 2.8K, 11K
//! and 34K triangles), in milliseconds per query.
//!
//! The queries (`benches/support/knot_queries.rs`, shared with
//! `examples/table1.rs`): per size, 8 copies of the knot turned by seeded
//! random rotations (built once, outside the timing, with their ball trees),
//! and a fixed seeded list of [`QUERIES`] fly-bys over `[0, 1]`
//! (`testkit::toi::fly_by` with spin [`SPIN`] = 2 rad per unit time for A,
//! up to 0.5 for B), contact distance `1e-3`, default time tolerance
//! (`1e-9`) and iteration limit, in `f64`.
//!
//! * `toi_<size>/nevq` and `toi_<size>/evq`: each criterion iteration runs
//!   the next query of the list (cycling), making the `MeshPair` and running
//!   `time_of_impact`, so criterion's mean is the mean time per query over
//!   the list.
//! * `toi_<size>/parry_nonlinear`: parry3d-f64's `cast_shapes_nonlinear` on
//!   the same meshes (as parry `TriMesh`es) and motions, cycling over the
//!   first [`PARRY_QUERIES`] queries, one query per sample (flat sampling,
//!   10 samples), and `nevq_first10`/`evq_first10`: ours on those same
//!   queries, for the ratio. Parry takes about a second per query at 2.8K
//!   triangles, more for larger meshes: a size whose parry run is estimated
//!   (from one timed query) at more than [`PARRY_BUDGET_S`] seconds is
//!   skipped, and the output says so.
//!
//! Before timing, the motion mapping to parry is checked on the first query:
//! every vertex of both bodies placed by us and by parry at `t = 0.5` must
//! agree to `1e-12`.
//!
//! `cargo bench --bench toi` takes about 3 to 6 minutes on two shared cores;
//! `TOI_SIZES=2.8K cargo bench --bench toi` builds and runs one size (a
//! comma-separated list of `2.8K`, `11K`, `34K`; criterion's own name filter
//! still applies within a size). `examples/table1.rs`
//! prints the whole table (iterations, contact fractions, traversal counters,
//! ground truth) from one run.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{BenchmarkId, Criterion, SamplingMode};
use motion_bound::ca::BoundChoice;
use motion_bound::scenes::TorusKnotSize;

// The example reads fields (reach, parry's answers) that the benchmark does not.
#[allow(dead_code)]
#[path = "support/knot_queries.rs"]
mod knot_queries;

use knot_queries::{label, mapping_error, parry_meshes, parry_toi, KnotScene, SPIN};

/// Queries in each size's list.
const QUERIES: usize = 200;
/// Queries of the list that parry (and ours, for the ratio) run.
const PARRY_QUERIES: usize = 10;
/// The longest a size's parry measurement may take, estimated, in seconds.
const PARRY_BUDGET_S: f64 = 120.0;

fn bench_size(c: &mut Criterion, size: TorusKnotSize) {
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
        .measurement_time(Duration::from_secs(4));
    for (id, bound) in [("nevq", BoundChoice::Nevq), ("evq", BoundChoice::Evq)] {
        let params = KnotScene::params(bound);
        for (id, list) in [
            (id.to_owned(), &scene.queries[..]),
            (
                format!("{id}_first{PARRY_QUERIES}"),
                &scene.queries[..PARRY_QUERIES],
            ),
        ] {
            group.bench_function(BenchmarkId::from_parameter(id), |b| {
                let mut k = 0;
                b.iter(|| {
                    let q = &list[k % list.len()];
                    k += 1;
                    scene.ours(black_box(q), &params).0
                });
            });
        }
    }

    // Parry: estimate from one query first.
    let meshes = parry_meshes(&scene);
    let start = Instant::now();
    black_box(parry_toi(&meshes, q0));
    let one = start.elapsed().as_secs_f64();
    // Warm-up (one query) and 10 samples of one query each.
    let estimate = one * (PARRY_QUERIES as f64 + 1.0);
    if estimate > PARRY_BUDGET_S {
        println!(
            "{name}/parry_nonlinear: skipped: one query took {one:.1} s, \
             the run would take about {estimate:.0} s (budget {PARRY_BUDGET_S:.0} s)"
        );
    } else {
        group
            .sampling_mode(SamplingMode::Flat)
            .sample_size(10)
            .warm_up_time(Duration::from_millis(1))
            .measurement_time(Duration::from_secs_f64(one * PARRY_QUERIES as f64));
        let list = &scene.queries[..PARRY_QUERIES];
        group.bench_function(BenchmarkId::from_parameter("parry_nonlinear"), |b| {
            let mut k = 0;
            b.iter(|| {
                let q = &list[k % list.len()];
                k += 1;
                parry_toi(&meshes, black_box(q))
            });
        });
    }
    group.finish();
}

// `criterion_group!` would define an undocumented `pub fn`; this is what it
// and `criterion_main!` expand to.
fn main() {
    let mut criterion = Criterion::default().configure_from_args();
    let sizes = std::env::var("TOI_SIZES").unwrap_or_default();
    for size in TorusKnotSize::ALL {
        if sizes.is_empty() || sizes.split(',').any(|s| s.trim() == label(size)) {
            bench_size(&mut criterion, size);
        }
    }
    criterion.final_summary();
}
