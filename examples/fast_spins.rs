//! Fast spins under the default parameters: fly-bys in which each body turns
//! 20, 60 and 200 rad over the query's interval, for convex pairs of every
//! kind, convex shapes against a mesh (the bunny) and the bunny thrown at a
//! ground half-space, checked against sampled ground truth
//! (`tests/common/shape_truth.rs`).
//!
//! Run with `cargo run --release --example fast_spins` (`--queries N` per
//! pair of kinds, `--spins 20,60,200`, `--seed S`, `--no-truth` for the
//! times alone, `--verbose` for a line per query).
//!
//! A query is *decided* when it ends in a contact or `Separated`; an
//! undecided one (`IterationLimit`, `WorkLimit`, `PrecisionLimit`) is what
//! an engine must treat as a contact. The ground truth samples each query up
//! to its reported time, densely enough that the fastest point moves about
//! 0.02 between samples; a sampled contact is a true contact, so a query is
//! MISSED when it reports no possible contact and the sampling finds one,
//! LATE when its first possible contact is after the sampled one. The time
//! of a query includes making its pair (`AnyPair::try_new`).
//!
//! One line per spin and group of kinds, then `queries Q, decided D, over 50
//! ms O, max ms X, missed M, late L`.

#[path = "../tests/common/meshes.rs"]
mod meshes;
#[path = "../tests/common/shape_truth.rs"]
mod shape_truth;

use std::time::Instant;

use motion_bound::ca::{time_of_impact, AnyPair, CaOutcome, CaParams, Shape};
use motion_bound::{BallTree, HalfSpace, RigidMotion, Vec3};
use motion_bound_devkit::{cpu_name, Args, Rng};
use shape_truth::{convex_kinds, first_sampled_contact, first_sampled_landing, Solid};

/// A body kind: its shape, its ground truth, its reach.
struct Kind {
    shape: Shape<'static, f64>,
    solid: Solid,
    reach: f64,
}

fn leak<T>(x: T) -> &'static T {
    Box::leak(Box::new(x))
}

/// What one group of queries found.
#[derive(Default)]
struct Tally {
    queries: usize,
    contacts: usize,
    separated: usize,
    undecided: usize,
    over: usize,
    max_ms: f64,
    max_iterations: u32,
    missed: usize,
    late: usize,
}

impl Tally {
    fn add(&mut self, outcome: &CaOutcome<f64>, iterations: u32, ms: f64, truth: Option<f64>) {
        self.queries += 1;
        match outcome {
            CaOutcome::Contact { .. } | CaOutcome::InitialContact(_) => self.contacts += 1,
            CaOutcome::Separated => self.separated += 1,
            _ => self.undecided += 1,
        }
        self.over += usize::from(ms > 50.0);
        self.max_ms = self.max_ms.max(ms);
        self.max_iterations = self.max_iterations.max(iterations);
        match (outcome.earliest_possible_contact(), truth) {
            (None, Some(_)) => self.missed += 1,
            (Some(t), Some(g)) if t > g => self.late += 1,
            _ => {}
        }
    }

    fn merge(&mut self, o: &Self) {
        self.queries += o.queries;
        self.contacts += o.contacts;
        self.separated += o.separated;
        self.undecided += o.undecided;
        self.over += o.over;
        self.max_ms = self.max_ms.max(o.max_ms);
        self.max_iterations = self.max_iterations.max(o.max_iterations);
        self.missed += o.missed;
        self.late += o.late;
    }
}

/// Samples over `[0, 1]` for a fastest point speed of `speed`: a sample
/// every 0.02 of travel, at least 200.
fn samples(speed: f64) -> usize {
    ((speed / 0.02).ceil() as usize).max(200)
}

/// What to print and check.
#[derive(Clone, Copy)]
struct Opts {
    /// Check against the ground truth (`--no-truth`: times only).
    truth: bool,
    /// One line per query (`--verbose`).
    verbose: bool,
}

/// Runs one query (timed, with its pair made inside), and its ground truth
/// up to the reported time.
fn run(
    opts: Opts,
    (a, ma): (Shape<'static, f64>, &RigidMotion<f64>),
    (b, mb): (Shape<'static, f64>, &RigidMotion<f64>),
    (truth, speed): (impl Fn(f64, usize) -> Option<f64>, f64),
    tally: &mut Tally,
) {
    let params = CaParams::default().with_contact_distance(1e-3);
    let start = Instant::now();
    let report = AnyPair::try_new(a, b)
        .and_then(|mut pair| time_of_impact(&mut pair, ma, mb, &params))
        .expect("a valid query");
    let ms = start.elapsed().as_secs_f64() * 1e3;
    let end = report.outcome.earliest_possible_contact().unwrap_or(1.0);
    let n = ((samples(speed) as f64 * end).ceil() as usize).max(1);
    if opts.verbose {
        println!(
            "  {ms:.2} ms, {} iterations, {:?}, {:?}",
            report.iterations, report.work, report.outcome
        );
    }
    let truth = if opts.truth { truth(end, n) } else { None };
    tally.add(&report.outcome, report.iterations, ms, truth);
}

fn main() {
    let mut args = Args::from_env(
        "fast_spins [--queries 3] [--spins 20,60,200] [--seed 38] [--no-truth] [--verbose]",
    );
    let queries: usize = args.value_or("--queries", 3);
    let spins: String = args.value_or("--spins", "20,60,200".to_string());
    let seed: u64 = args.value_or("--seed", 38);
    let opts = Opts {
        truth: !args.flag("--no-truth"),
        verbose: args.flag("--verbose"),
    };
    args.finish();
    let spins: Vec<f64> = spins
        .split(',')
        .map(|s| s.trim().parse().expect("--spins: numbers"))
        .collect();
    println!("CPU: {}", cpu_name());
    let mut rng = Rng::new(seed);
    let kinds: Vec<Kind> = convex_kinds(&mut rng)
        .into_iter()
        .map(|(_, shape, solid)| Kind {
            reach: solid.reach(),
            shape: Shape::Convex(shape),
            solid,
        })
        .collect();
    let bunny_mesh = {
        let m = meshes::load_shipped("bunny-npm-3674.obj.gz");
        let (c, r) = m.bounding_sphere();
        m.recentred(c)
            .and_then(|m| m.scaled(0.5 / r))
            .expect("bunny")
    };
    let bunny = Kind {
        shape: Shape::Mesh(leak(BallTree::try_from_mesh(&bunny_mesh).expect("tree"))),
        solid: Solid::mesh(&bunny_mesh),
        reach: 0.5,
    };
    let ground = HalfSpace::try_new(Vec3::new(0.0, 1.0, 0.0)).expect("ground");
    let mut total = Tally::default();
    for &spin in &spins {
        let axis = |rng: &mut Rng| rng.direction().map(|x| x * spin);
        let fly = |rng: &mut Rng, a: &Kind, b: &Kind| {
            let reach = a.reach + b.reach;
            let start = rng.direction().map(|x| x * reach * rng.range(1.1, 1.5));
            let aim = rng.direction().map(|x| x * reach * 0.6 * rng.unit());
            let v = [0, 1, 2].map(|k| aim[k] - start[k]);
            let ma = RigidMotion::try_from_arrays(start, v, axis(rng)).expect("motion");
            let mb = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], axis(rng)).expect("motion");
            let speed = Vec3::from_array(v).length() + spin * (a.reach + b.reach);
            (ma, mb, speed)
        };
        // Convex pairs of every kind.
        let mut convex = Tally::default();
        for i in 0..kinds.len() {
            for j in i..kinds.len() {
                let (a, b) = (&kinds[i], &kinds[j]);
                for _ in 0..queries {
                    let (ma, mb, speed) = fly(&mut rng, a, b);
                    let truth = |end: f64, n: usize| {
                        first_sampled_contact(&a.solid, &ma, &b.solid, &mb, (0.0, end), n)
                    };
                    run(
                        opts,
                        (a.shape, &ma),
                        (b.shape, &mb),
                        (truth, speed),
                        &mut convex,
                    );
                }
            }
        }
        // Convex shapes against the bunny.
        let mut mesh = Tally::default();
        for kind in &kinds {
            for _ in 0..queries * 3 {
                let (ma, mb, speed) = fly(&mut rng, kind, &bunny);
                let truth = |end: f64, n: usize| {
                    first_sampled_contact(&kind.solid, &ma, &bunny.solid, &mb, (0.0, end), n)
                };
                let (a, b) = ((kind.shape, &ma), (bunny.shape, &mb));
                run(opts, a, b, (truth, speed), &mut mesh);
            }
        }
        // The bunny thrown at the ground.
        let mut landing = Tally::default();
        let m = [0.0, 1.0, 0.0];
        let mg = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0; 3]).expect("ground");
        for _ in 0..queries * kinds.len() * 3 {
            let start = [
                rng.range(-1.0, 1.0),
                rng.range(0.6, 1.5),
                rng.range(-1.0, 1.0),
            ];
            let v = [
                rng.range(-1.0, 1.0),
                -rng.range(0.2, 2.0),
                rng.range(-1.0, 1.0),
            ];
            let ma = RigidMotion::try_from_arrays(start, v, axis(&mut rng)).expect("motion");
            let speed = Vec3::from_array(v).length() + spin * bunny.reach;
            let truth = |end: f64, n: usize| {
                first_sampled_landing(&bunny.solid, &ma, &mg, m, (0.0, end), n)
            };
            let (a, b) = ((bunny.shape, &ma), (Shape::HalfSpace(ground), &mg));
            run(opts, a, b, (truth, speed), &mut landing);
        }
        for (group, t) in [
            ("convex pairs", &convex),
            ("convex vs bunny", &mesh),
            ("bunny vs ground", &landing),
        ] {
            println!(
                "spin {spin} rad, {group}: queries {}, contacts {}, separated {}, undecided {}, max iterations {}, over 50 ms {}, max ms {:.2}, missed {}, late {}",
                t.queries, t.contacts, t.separated, t.undecided, t.max_iterations, t.over, t.max_ms, t.missed, t.late
            );
            total.merge(t);
        }
    }
    println!(
        "queries {}, decided {}, over 50 ms {}, max ms {:.2}, missed {}, late {}",
        total.queries,
        total.queries - total.undecided,
        total.over,
        total.max_ms,
        total.missed,
        total.late
    );
}
