//! How tight the NEVQ and EVQ speed bounds are on random motions.
//!
//! Run with `cargo run --release --example tightness`. For `f64` and `f32`
//! inputs it draws 10,000 random cases: a blob of 32 vertices with coordinates
//! in `[-1, 1)`, a linear velocity in `[-1, 1)^3`, an angular velocity of
//! random direction and magnitude log-uniform in `[0.1, 10]`, over the unit
//! interval (even cases) or a random sub-interval of it (odd cases), and a
//! random direction `n`. For each it divides each bound by the exact value
//! from the `reference` oracle (evaluated in `f64`) and prints the median, the
//! 90th percentile, the worst (largest) and the smallest ratio. A ratio below 1
//! would be an unsound bound: it is reported as a VIOLATION and the example
//! exits with status 1.

use std::process::ExitCode;

use motion_bound::reference::{exact, Exact};
use motion_bound::testkit::{random_blob, SplitMix64};
use motion_bound::{evq, nevq, Direction, Float, RigidMotion, Vec3, VertexSet};

/// Cases per precision.
const CASES: usize = 10_000;
/// Vertices per body.
const VERTICES: usize = 32;

/// The ratios of one quantity, split by interval kind.
#[derive(Default)]
struct Ratios {
    unit: Vec<f64>,
    sub: Vec<f64>,
}

impl Ratios {
    fn push(&mut self, unit_interval: bool, r: f64) {
        if unit_interval {
            self.unit.push(r);
        } else {
            self.sub.push(r);
        }
    }
}

/// Nearest-rank percentile of sorted data.
fn percentile(sorted: &[f64], p: f64) -> f64 {
    let rank = (p * sorted.len() as f64).ceil() as usize;
    sorted[rank.clamp(1, sorted.len()) - 1]
}

/// Prints one row of statistics; returns the number of ratios below 1.
fn report(label: &str, which: &str, data: &[f64]) -> usize {
    let mut sorted = data.to_vec();
    sorted.sort_by(f64::total_cmp);
    if sorted.is_empty() {
        println!("  {label:<18} {which:<13} (no cases)");
        return 0;
    }
    let below = sorted.iter().filter(|&&r| r < 1.0 || r.is_nan()).count();
    println!(
        "  {label:<18} {which:<13} {:>6} {:>10.4} {:>10.4} {:>11.4} {:>20.17}",
        sorted.len(),
        percentile(&sorted, 0.5),
        percentile(&sorted, 0.9),
        sorted[sorted.len() - 1],
        sorted[0]
    );
    if below > 0 {
        println!(
            "  !!! VIOLATION: {below} {label} ratio(s) below 1 ({which}): smallest {:.17}",
            sorted[0]
        );
    }
    below
}

/// Runs the cases in precision `T`; returns the number of violations.
fn run<T: Float>(precision: &str, seed: u64) -> usize {
    let mut rng = SplitMix64(seed);
    let mut nevq_speed = Ratios::default();
    let mut evq_speed = Ratios::default();
    let mut nevq_disp = Ratios::default();
    let mut evq_disp = Ratios::default();
    let mut skipped = 0usize;
    for i in 0..CASES {
        let vertices: Vec<[T; 3]> = random_blob(&mut rng, VERTICES);
        let v = rng.vec3().map(T::from_f64);
        let omega = 10f64.powf(rng.range(-1.0, 1.0));
        let w = rng.direction().map(|x| T::from_f64(x * omega));
        let full = RigidMotion::try_from_arrays([T::ZERO; 3], v, w).expect("finite motion");
        let unit_interval = i % 2 == 0;
        let motion = if unit_interval {
            full
        } else {
            let a = rng.range(0.0, 1.0);
            let b = rng.range(0.0, 1.0);
            let (a, b) = if a <= b { (a, b) } else { (b, a) };
            full.restrict(T::from_f64(a), T::from_f64(b))
                .expect("sub-interval of [0, 1]")
        };
        let n = Direction::try_new(Vec3::from_array(rng.direction().map(T::from_f64)))
            .expect("unit direction");

        let set = VertexSet::try_new(&vertices).expect("random blob is valid");
        let loose = nevq(&set.summary(), &motion, n);
        let tight = evq(&set, &motion, n);
        let ex: Exact<f64> = exact::<T, f64>(&vertices, &motion, n);
        if ex.sup_speed == 0.0 {
            skipped += 1;
            continue;
        }
        nevq_speed.push(unit_interval, loose.speed.to_f64() / ex.sup_speed);
        evq_speed.push(unit_interval, tight.speed.to_f64() / ex.sup_speed);
        if ex.displacement > 0.0 {
            nevq_disp.push(unit_interval, loose.displacement.to_f64() / ex.displacement);
            evq_disp.push(unit_interval, tight.displacement.to_f64() / ex.displacement);
        }
    }

    println!(
        "{precision}: {CASES} cases, {VERTICES} vertices each, {skipped} skipped (exact speed 0)"
    );
    println!(
        "  {:<18} {:<13} {:>6} {:>10} {:>10} {:>11} {:>20}",
        "ratio", "interval", "cases", "median", "p90", "worst(max)", "min (must be >= 1)"
    );
    let mut violations = 0;
    for (label, r) in [
        ("NEVQ speed/exact", &nevq_speed),
        ("EVQ speed/exact", &evq_speed),
        ("NEVQ disp/exact", &nevq_disp),
        ("EVQ disp/exact", &evq_disp),
    ] {
        let all: Vec<f64> = r.unit.iter().chain(&r.sub).copied().collect();
        violations += report(label, "all", &all);
        report(label, "[0, 1]", &r.unit);
        report(label, "sub-interval", &r.sub);
    }
    println!();
    violations
}

fn main() -> ExitCode {
    println!("Tightness of the directed speed bounds: bound / exact (1 = tight, < 1 = unsound).");
    println!("The displacement rows compare speed * length with the exact displacement.");
    println!();
    let violations = run::<f64>("f64", 0x7167_0064) + run::<f32>("f32", 0x7167_0032);
    if violations > 0 {
        println!("VIOLATION: {violations} ratio(s) below 1: a bound is below the exact value");
        ExitCode::FAILURE
    } else {
        println!("OK: every bound is at least the exact value.");
        ExitCode::SUCCESS
    }
}
