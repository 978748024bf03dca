//! Precision and cost against where a pair is and how large it is: the
//! shipped bunny (3,674 triangles, reach 0.5) flying past a copy of itself,
//! at offsets from the origin and at scales, in `f32` and `f64`, one query
//! each; the table of `docs/performance.md` ("Far from the origin").
//!
//! Run with `cargo run --release --example far_from_origin` (about 20 s;
//! `-- --quick` for the rows only).
//!
//! The fly-by: B's rotation centre at `(x, x, x)` turning at `(0.3, 0, 0)`,
//! A's at `x + s (-1.3, 0.1, 0)` moving at `s (2.6, 0, 0)` and turning at
//! `(0, 3, 1.5)`, over `[0, 1]`, contact distance `1e-3 s`, default
//! parameters (so the default work budget); `x` the offset and `s` the
//! scale, the inputs rounded to the precision. Each time is the least of
//! three runs of the query (trees built beforehand).

#[path = "../tests/common/meshes.rs"]
mod meshes;

use std::time::Instant;

use motion_bound::bodies::icosphere;
use motion_bound::ca::{time_of_impact, CaOutcome, CaParams, CaReport, MeshPair};
use motion_bound::{BallTree, Float, Point3, RigidMotion, TimeInterval, TriMesh, Vec3};
use motion_bound_devkit::{cpu_name, Args};

/// The bunny centred and scaled to reach 0.5, times `scale`.
fn bunny(scale: f64) -> Result<TriMesh<f64>, String> {
    let m = meshes::load_shipped("bunny-npm-3674.obj.gz");
    let (c, r) = m.bounding_sphere();
    m.recentred(c)
        .and_then(|m| m.scaled(0.5 / r))
        .and_then(|m| m.scaled(scale))
        .map_err(|e| e.to_string())
}

/// The fly-by's motions at offset `x` and scale `s`.
fn fly_by<T: Float>(x: f64, s: f64) -> Result<(RigidMotion<T>, RigidMotion<T>), String> {
    let t = T::from_f64;
    let motion = |c: [f64; 3], v: [f64; 3], w: [f64; 3]| {
        RigidMotion::try_new(
            Point3::from_array(c.map(|c| t(x + c * s))),
            Vec3::from_array(v.map(|v| t(v * s))),
            Vec3::from_array(w.map(t)),
            TimeInterval::UNIT,
        )
        .map_err(|e| e.to_string())
    };
    Ok((
        motion([-1.3, 0.1, 0.0], [2.6, 0.0, 0.0], [0.0, 3.0, 1.5])?,
        motion([0.0; 3], [0.0; 3], [0.3, 0.0, 0.0])?,
    ))
}

/// The outcome in a few words.
fn outcome<T: Float>(r: &CaReport<T>) -> String {
    match r.outcome {
        CaOutcome::Contact { contact, .. } => format!("contact at {:.4}", contact.time.to_f64()),
        CaOutcome::InitialContact(_) => "initial contact".into(),
        CaOutcome::Separated => "separated".into(),
        CaOutcome::IterationLimit { time } => format!("iteration limit at {:.4}", time.to_f64()),
        CaOutcome::WorkLimit { time } => format!("`WorkLimit` at {:.4}", time.to_f64()),
        CaOutcome::PrecisionLimit { time, resolution } => format!(
            "`PrecisionLimit` at {:.4} (resolution {:.1e})",
            time.to_f64(),
            resolution.to_f64()
        ),
        _ => format!("{:?}", r.outcome),
    }
}

/// One row: `a` against `b`, the least time of three runs.
fn row<T: Float>(label: &str, a: &TriMesh<T>, b: &TriMesh<T>, x: f64, s: f64) {
    let trees = BallTree::try_from_mesh(a).and_then(|ta| Ok((ta, BallTree::try_from_mesh(b)?)));
    let ((ta, tb), (ma, mb)) = match (trees, fly_by::<T>(x, s)) {
        (Ok(t), Ok(m)) => (t, m),
        (Err(e), _) => return println!("| {label} | rejected: {e} | | | | |"),
        (_, Err(e)) => return println!("| {label} | rejected: {e} | | | | |"),
    };
    let params = CaParams::<T>::default().with_contact_distance(T::from_f64(1e-3 * s));
    let mut best = f64::INFINITY;
    let mut report = None;
    for _ in 0..3 {
        let start = Instant::now();
        let r = time_of_impact(&mut MeshPair::new(&ta, &tb), &ma, &mb, &params).expect("valid");
        best = best.min(start.elapsed().as_secs_f64() * 1e3);
        report = Some(r);
    }
    let r = report.expect("three runs");
    println!(
        "| {label} | {} | {} | {} | {} | {best:.2} |",
        outcome(&r),
        r.iterations,
        r.work.node_pairs,
        r.work.triangle_pairs
    );
}

fn bunnies<T: Float>(label: &str, x: f64, s: f64) {
    match bunny(s).and_then(|m| m.try_convert::<T>().map_err(|e| e.to_string())) {
        Ok(m) => row(label, &m, &m, x, s),
        Err(e) => println!("| {label} | rejected: {e} | | | | |"),
    }
}

fn main() {
    let mut args = Args::from_env("far_from_origin [--quick]");
    let quick = args.flag("--quick");
    args.finish();
    let cpu = cpu_name();
    println!("CPU: {cpu}; ms: the least of three runs of one query\n");
    println!("| pair | outcome | iterations | node pairs | triangle pairs | ms |");
    println!("|---|---|---|---|---|---|");
    for x in [0.0, 1e4, 1e5, 3e5, 1e6, 1e7] {
        bunnies::<f32>(&format!("bunny f32 at offset {x:e}"), x, 1.0);
    }
    for x in [0.0, 1e13, 1e14, 1e15, 1e16] {
        bunnies::<f64>(&format!("bunny f64 at offset {x:e}"), x, 1.0);
    }
    bunnies::<f64>("bunny f64 scaled by 1e-300", 0.0, 1e-300);
    let sphere = icosphere::<f32>(0.5, 3).expect("sphere");
    for x in [1e3, 1e6] {
        row(
            &format!("icosphere f32 at offset {x:e}"),
            &sphere,
            &sphere,
            x,
            1.0,
        );
    }
    // 100,000 copies of one triangle against the bunny.
    let (mut v, mut t) = (Vec::new(), Vec::new());
    for i in 0..100_000u32 {
        v.extend([[0.0, 0.0, 0.0], [0.2, 0.0, 0.0], [0.0, 0.2, 0.0]]);
        t.push([3 * i, 3 * i + 1, 3 * i + 2]);
    }
    let copies = TriMesh::try_new(v, t).expect("copies");
    row(
        "100,000 copies of a triangle against the bunny, f64",
        &copies,
        &bunny(1.0).expect("bunny"),
        0.0,
        1.0,
    );
    if quick {
        return;
    }
    for k in [0, 1, 2, 3] {
        let x = 10f64.powi(k);
        bunnies::<f32>(&format!("bunny f32 at offset {x:e}"), x, 1.0);
    }
    for k in [0, 4, 8, 12] {
        let x = 10f64.powi(k);
        bunnies::<f64>(&format!("bunny f64 at offset {x:e}"), x, 1.0);
    }
    for k in [-35, -20, -19, -10, 10, 17, 18, 30] {
        let s = 10f64.powi(k);
        bunnies::<f32>(&format!("bunny f32 scaled by {s:e}"), 0.0, s);
    }
    for k in [-300, -200, -160, -150, -100, -10, 10, 100, 150, 160, 300] {
        let s = 10f64.powi(k);
        bunnies::<f64>(&format!("bunny f64 scaled by {s:e}"), 0.0, s);
    }
}
