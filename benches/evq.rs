//! Benchmarks of the EVQ scan: nanoseconds per vertex, `f32` and `f64`.
//!
//! The bodies are random blobs (`testkit::random_blob`, coordinates in
//! `[-1, 1)`) of `N - 1` vertices plus one vertex on the rotation axis at
//! distance 2 from the centre. That vertex is the farthest one, so it sets the
//! NEVQ radius, but rotation does not move it: no vertex reaches the NEVQ
//! value and EVQ's early exit never fires, so every query scans all `N`
//! vertices. Each benchmark asserts `evq < nevq` on its query before timing.
//!
//! * `evq_scan`: throughput `N` elements, so criterion's elements per second
//!   is vertices per second (per-vertex cost), for `N = 64, 1024, 16384` in two
//!   regimes: a sweep of 1 radian (below pi: the per-vertex case split with
//!   trigonometry at the arc's ends) and a sweep of 7 radians (at least pi:
//!   the distance-from-axis scan).
//! * `nevq_vs_evq`: the same query through NEVQ and EVQ, throughput one
//!   element, so the two times per query can be divided directly.
//! * `evq_tree_vs_scan`: the same query by scan and by branch and bound over
//!   the body's `VertexTree` (`N = 64` to `131072`), throughput one
//!   query: the ratio is the tree's speed-up.

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkId, Criterion, Throughput};
use motion_bound::testkit::{random_blob, SplitMix64};
use motion_bound::{
    evq, nevq, Direction, Float, PreparedMotion, RigidMotion, VertexSet, VertexTree,
};

/// The unit rotation axis of every benchmarked motion.
const AXIS: [f64; 3] = [0.36, -0.48, 0.8];

/// Body sizes of the scan benchmarks.
const SIZES: [usize; 3] = [64, 1024, 16384];

/// `n - 1` random-blob vertices after one vertex at distance 2 on the axis.
fn body<T: Float>(n: usize) -> Vec<[T; 3]> {
    let mut rng = SplitMix64(0xB0D1_0000 + n as u64);
    let mut vertices = vec![AXIS.map(|x| T::from_f64(2.0 * x))];
    vertices.extend(random_blob::<T>(&mut rng, n - 1));
    vertices
}

/// A motion over `[0, 1]` about [`AXIS`] at angular speed `omega` (the sweep),
/// and a direction well away from the axis.
fn query<T: Float>(omega: f64) -> (RigidMotion<T>, Direction<T>) {
    let motion = RigidMotion::try_from_arrays(
        [T::ZERO; 3],
        [0.3, -0.2, 0.1].map(T::from_f64),
        AXIS.map(|x| T::from_f64(omega * x)),
    )
    .expect("finite motion");
    let n = Direction::try_from_array([1.0, 0.5, -0.25].map(T::from_f64)).expect("nonzero");
    (motion, n)
}

/// The two motion regimes: name and sweep over the unit interval.
const REGIMES: [(&str, f64); 2] = [("sweep_1rad", 1.0), ("full_turn_7rad", 7.0)];

/// Panics unless EVQ is strictly below NEVQ on this query, i.e. the scan
/// cannot have stopped early at the NEVQ value.
fn assert_full_scan<T: Float>(body: &VertexSet<'_, T>, motion: &RigidMotion<T>, n: Direction<T>) {
    let e = evq(body, motion, n).speed;
    let ne = nevq(&body.summary(), motion, n).speed;
    assert!(
        e < ne,
        "EVQ ({e}) must be below NEVQ ({ne}) so that the benchmark times the full scan"
    );
}

fn scan_precision<T: Float>(c: &mut Criterion, precision: &str) {
    let mut group = c.benchmark_group("evq_scan");
    group
        .sample_size(20)
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(500));
    for &size in &SIZES {
        let vertices = body::<T>(size);
        let set = VertexSet::try_new(&vertices).expect("valid body");
        group.throughput(Throughput::Elements(size as u64));
        for (regime, omega) in REGIMES {
            let (motion, n) = query::<T>(omega);
            assert_full_scan(&set, &motion, n);
            group.bench_with_input(
                BenchmarkId::new(format!("{regime}/{precision}"), size),
                &(set, motion, n),
                |b, (set, motion, n)| {
                    b.iter(|| evq(black_box(set), black_box(motion), black_box(*n)));
                },
            );
        }
    }
    group.finish();
}

fn compare_precision<T: Float>(c: &mut Criterion, precision: &str) {
    let mut group = c.benchmark_group("nevq_vs_evq");
    group
        .sample_size(20)
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(500))
        .throughput(Throughput::Elements(1));
    for size in [64, 1024] {
        let vertices = body::<T>(size);
        let set = VertexSet::try_new(&vertices).expect("valid body");
        let summary = set.summary();
        let (motion, n) = query::<T>(REGIMES[0].1);
        assert_full_scan(&set, &motion, n);
        group.bench_with_input(
            BenchmarkId::new(format!("nevq/{precision}"), size),
            &(summary, motion, n),
            |b, (summary, motion, n)| {
                b.iter(|| nevq(black_box(summary), black_box(motion), black_box(*n)));
            },
        );
        group.bench_with_input(
            BenchmarkId::new(format!("evq/{precision}"), size),
            &(set, motion, n),
            |b, (set, motion, n)| {
                b.iter(|| evq(black_box(set), black_box(motion), black_box(*n)));
            },
        );
    }
    group.finish();
}

/// EVQ of a whole body by scan and by branch and bound over its
/// `VertexTree` (the same body, motion and direction; the tree's value is
/// asserted equal to the scan's first), throughput one query.
fn tree_precision<T: Float>(c: &mut Criterion, precision: &str) {
    let mut group = c.benchmark_group("evq_tree_vs_scan");
    group
        .sample_size(20)
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(500))
        .throughput(Throughput::Elements(1));
    for size in [64, 256, 1024, 16384, 131_072] {
        let vertices = body::<T>(size);
        let set = VertexSet::try_new(&vertices).expect("valid body");
        let tree = VertexTree::try_new(&set).expect("valid tree");
        for (regime, omega) in REGIMES {
            let (motion, n) = query::<T>(omega);
            assert_full_scan(&set, &motion, n);
            let probe = PreparedMotion::new(&motion).probe(n);
            let (fast, visited) = tree.speed_with_stats(&probe);
            assert!(
                fast == probe.evq_speed(&set),
                "the tree's value is the scan's"
            );
            println!("evq_tree_vs_scan {regime}/{precision}/{size}: {visited} nodes visited");
            group.bench_with_input(
                BenchmarkId::new(format!("scan/{regime}/{precision}"), size),
                &(set, motion, n),
                |b, (set, motion, n)| {
                    b.iter(|| evq(black_box(set), black_box(motion), black_box(*n)));
                },
            );
            group.bench_with_input(
                BenchmarkId::new(format!("tree/{regime}/{precision}"), size),
                &(&tree, motion, n),
                |b, (tree, motion, n)| {
                    b.iter(|| black_box(tree).evq(black_box(motion), black_box(*n)));
                },
            );
        }
    }
    group.finish();
}

fn evq_benches(c: &mut Criterion) {
    tree_precision::<f64>(c, "f64");
    tree_precision::<f32>(c, "f32");
    scan_precision::<f32>(c, "f32");
    scan_precision::<f64>(c, "f64");
    compare_precision::<f32>(c, "f32");
    compare_precision::<f64>(c, "f64");
}

// `criterion_group!` would define an undocumented `pub fn`; this is what it
// and `criterion_main!` expand to.
fn main() {
    let mut criterion = Criterion::default().configure_from_args();
    evq_benches(&mut criterion);
    criterion.final_summary();
}
