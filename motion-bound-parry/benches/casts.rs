//! Ours against parry's `cast_shapes_nonlinear`, per parry shape pair kind:
//! time per query (criterion), and missed / late for both against sampled
//! ground truth (parry's own kinematics and static intersection test at 257
//! times, `tests/common/cases.rs`), on the same shapes and fly-bys.
//!
//! `cargo bench -p motion-bound-parry --bench casts` (one criterion group per
//! pair kind, `ours` and `parry` in it, each iteration `QUERIES` queries; the
//! missed / late lines are printed before each group). `CASTS_FILTER=cone`
//! keeps the pair kinds whose names contain it.
//!
//! MISSED: the sampling finds the shapes intersecting and the cast reports
//! no hit. LATE: the cast's time is after the first sampled intersection.

// criterion_group! makes an undocumented public function.
#![allow(missing_docs)]

#[path = "../tests/common/cases.rs"]
mod cases;

use std::hint::black_box;
use std::time::{Duration, Instant};

use cases::{first_sampled, fly_by, shapes, Rng};
use criterion::{criterion_group, criterion_main, Criterion};
use motion_bound_parry::ShapeCache;
use parry3d_f64::query::{self, NonlinearRigidMotion, ShapeCastHit};
use parry3d_f64::shape::SharedShape;

/// Fly-bys per pair kind (one criterion iteration runs them all).
const QUERIES: usize = 20;

/// The fixed queries of one pair kind.
struct Kind {
    name: String,
    a: SharedShape,
    b: SharedShape,
    motions: Vec<(NonlinearRigidMotion, NonlinearRigidMotion)>,
    truth: Vec<Option<f64>>,
}

/// Missed and late against the sampled truth, and the wall time of one pass.
fn judge(
    kind: &Kind,
    cast: &dyn Fn(&NonlinearRigidMotion, &NonlinearRigidMotion) -> Option<Option<ShapeCastHit>>,
) -> Option<(usize, usize, Duration)> {
    let (mut missed, mut late) = (0, 0);
    let start = Instant::now();
    for ((m1, m2), truth) in kind.motions.iter().zip(&kind.truth) {
        let hit = cast(m1, m2)?;
        match (truth, hit) {
            (Some(_), None) => missed += 1,
            (Some(t), Some(h)) if h.time_of_impact > t + 1e-12 => late += 1,
            _ => {}
        }
    }
    Some((missed, late, start.elapsed()))
}

fn bench(c: &mut Criterion) {
    let filter = std::env::var("CASTS_FILTER").unwrap_or_default();
    // One shape per parry kind (the tests take a few more).
    let keep = [
        "ball",
        "cuboid",
        "capsule",
        "cylinder",
        "cone",
        "round cuboid",
        "convex hull",
        "mesh",
        "dumbbell",
        "ground",
    ];
    let all: Vec<(&str, SharedShape)> = shapes()
        .into_iter()
        .filter(|(n, _)| keep.contains(n))
        .collect();
    let cache = ShapeCache::new();
    for (_, s) in &all {
        cache.try_register(s).expect("every shape converts");
    }
    let mut rng = Rng::new(2027);
    let cpu = motion_bound_devkit::cpu_name();
    println!("CPU: {cpu}; {QUERIES} fly-bys per pair kind over [0, 1]");
    for i in 0..all.len() {
        for j in i..all.len() {
            let ((na, ga), (nb, gb)) = (&all[i], &all[j]);
            let ground = *nb == "ground";
            if ground && *na == "ground" {
                continue;
            }
            let motions: Vec<_> = (0..QUERIES).map(|_| fly_by(&mut rng, ground)).collect();
            let name = format!("{na}-{nb}");
            if !name.contains(&filter) {
                continue;
            }
            let truth = motions
                .iter()
                .map(|(m1, m2)| first_sampled(m1, ga.as_ref(), m2, gb.as_ref(), 0.0, 1.0))
                .collect();
            let kind = Kind {
                name,
                a: ga.clone(),
                b: gb.clone(),
                motions,
                truth,
            };
            let ours = |m1: &NonlinearRigidMotion, m2: &NonlinearRigidMotion| {
                cache
                    .cast_shapes_nonlinear(
                        m1,
                        kind.a.as_ref(),
                        m2,
                        kind.b.as_ref(),
                        0.0,
                        1.0,
                        true,
                        &Default::default(),
                    )
                    .ok()
            };
            let parry = |m1: &NonlinearRigidMotion, m2: &NonlinearRigidMotion| {
                query::cast_shapes_nonlinear(
                    m1,
                    kind.a.as_ref(),
                    m2,
                    kind.b.as_ref(),
                    0.0,
                    1.0,
                    true,
                )
                .ok()
            };
            let sampled = kind.truth.iter().filter(|t| t.is_some()).count();
            let show = |r: Option<(usize, usize, Duration)>| match r {
                Some((m, l, d)) => format!(
                    "missed {m}, late {l} ({:.4} ms per query, one pass)",
                    d.as_secs_f64() * 1e3 / QUERIES as f64
                ),
                None => "unsupported".into(),
            };
            let ours_judged = judge(&kind, &ours);
            let parry_judged = judge(&kind, &parry);
            println!(
                "{}: {sampled} of {QUERIES} sampled contacts; ours {}; parry {}",
                kind.name,
                show(ours_judged),
                show(parry_judged)
            );
            let mut group = c.benchmark_group(&kind.name);
            group.sample_size(10);
            group.warm_up_time(Duration::from_millis(300));
            group.measurement_time(Duration::from_secs(1));
            if ours_judged.is_some() {
                group.bench_function("ours", |b| {
                    b.iter(|| {
                        for (m1, m2) in &kind.motions {
                            black_box(ours(m1, m2));
                        }
                    });
                });
            }
            // Parry at more than 50 ms per query would take minutes per
            // sample: its one timed pass above stands for it.
            if parry_judged.is_some_and(|(_, _, d)| d.as_secs_f64() / (QUERIES as f64) < 0.05) {
                group.bench_function("parry", |b| {
                    b.iter(|| {
                        for (m1, m2) in &kind.motions {
                            black_box(parry(m1, m2));
                        }
                    });
                });
            }
            group.finish();
        }
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
