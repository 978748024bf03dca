//! Benchmarks of the NEVQ bound: nanoseconds per query, `f32` and `f64`.
//!
//! Each iteration evaluates NEVQ on a fixed set of [`QUERIES`] precomputed
//! random motions and directions (linear velocities in `[-1, 1)^3`, angular
//! speeds log-uniform in `[0.1, 10]`, the unit interval or a random
//! sub-interval of it); the throughput is [`QUERIES`] elements, so criterion
//! reports the time (and rate) of a single query. The body summary is computed
//! once, outside the timed loop, either from a random blob of vertices or
//! directly from a bounding radius.

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkId, Criterion, Throughput};
use motion_bound::testkit::{random_blob, SplitMix64};
use motion_bound::{nevq, BodySummary, Direction, Float, RigidMotion, Vec3, VertexSet};

/// How many precomputed queries one iteration evaluates.
const QUERIES: usize = 1024;

/// [`QUERIES`] random motions and directions, in the precision `T`.
fn queries<T: Float>(seed: u64) -> Vec<(RigidMotion<T>, Direction<T>)> {
    let mut rng = SplitMix64(seed);
    (0..QUERIES)
        .map(|i| {
            let v = rng.vec3().map(T::from_f64);
            let omega = 10f64.powf(rng.range(-1.0, 1.0));
            let w = rng.direction().map(|x| T::from_f64(x * omega));
            let motion = RigidMotion::try_from_arrays([T::ZERO; 3], v, w)
                .expect("random motion is finite and small");
            let motion = if i % 2 == 0 {
                motion
            } else {
                let a = rng.range(0.0, 1.0);
                let b = rng.range(0.0, 1.0);
                let (a, b) = if a <= b { (a, b) } else { (b, a) };
                motion
                    .restrict(T::from_f64(a), T::from_f64(b))
                    .expect("sub-interval of [0, 1]")
            };
            let n = Direction::try_new(Vec3::from_array(rng.direction().map(T::from_f64)))
                .expect("unit direction");
            (motion, n)
        })
        .collect()
}

/// NEVQ over every precomputed query.
fn bench_precision<T: Float>(c: &mut Criterion, precision: &str) {
    let mut rng = SplitMix64(0x5EED_0001);
    let blob: Vec<[T; 3]> = random_blob(&mut rng, 1024);
    let from_vertices = VertexSet::try_new(&blob)
        .expect("random blob is valid")
        .summary();
    let from_radius = BodySummary::from_radius(T::from_f64(3f64.sqrt())).expect("valid radius");
    let queries = queries::<T>(0x5EED_0002);

    let mut group = c.benchmark_group("nevq");
    group
        .sample_size(20)
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(500))
        .throughput(Throughput::Elements(QUERIES as u64));
    for (name, summary) in [("vertex_set", from_vertices), ("from_radius", from_radius)] {
        group.bench_with_input(BenchmarkId::new(name, precision), &summary, |b, summary| {
            b.iter(|| {
                let summary = black_box(summary);
                for (motion, n) in black_box(&queries) {
                    black_box(nevq(summary, motion, *n));
                }
            });
        });
    }
    group.finish();
}

fn nevq_benches(c: &mut Criterion) {
    bench_precision::<f32>(c, "f32");
    bench_precision::<f64>(c, "f64");
}

// `criterion_group!` would define an undocumented `pub fn`; this is what it
// and `criterion_main!` expand to.
fn main() {
    let mut criterion = Criterion::default().configure_from_args();
    nevq_benches(&mut criterion);
    criterion.final_summary();
}
