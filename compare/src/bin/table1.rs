//! The seed's Table 1 (torus knot vs torus knot, 2.8K / 11K / 34K triangles)
//! reproduced in one run: time per conservative-advancement query with NEVQ
//! and with EVQ, iterations, contact fraction and traversal counters, beside
//! the seed's numbers; parry3d-f64's `cast_shapes_nonlinear` on the first
//! queries; and a check of every method against a sampled ground truth.
//!
//! ```sh
//! cargo run --release -p motion-bound-compare --bin table1 -- [--queries N] [--spin S] [--parry-queries M]
//!     [--truth-queries K] [--samples S] [--sizes 2.8K,11K,34K] [--parry-budget SECONDS]
//! ```
//!
//! Defaults: 200 queries, spin 2 rad per unit time, 10 parry queries, ground
//! truth on the first `K = M` queries with 1000 samples, all sizes, a parry
//! budget of 120 s per size (`--parry-budget 0` skips parry).
//!
//! The queries are those of `cargo bench -p motion-bound-compare --bench toi`
//! (`motion_bound::testkit::table1`): 8 seeded random orientations of the
//! knot and seeded fly-bys over `[0, 1]` (`testkit::toi::fly_by`), contact
//! distance `1e-3`, default time tolerance `1e-9` and iteration limit 100, in
//! `f64`. Each query is timed with `Instant` around making the `MeshPair`
//! and `time_of_impact` (parry: around `cast_shapes_nonlinear`), NEVQ and EVQ
//! interleaved query by query. **These timings are a report, not a benchmark
//! claim**: one pass, on a machine that may be busy; the criterion benchmark
//! `cargo bench -p motion-bound-compare --bench toi` is the measurement to quote.
//!
//! Ground truth: `testkit::ground_truth::first_sampled_contact`, the first of
//! `S` evenly spaced times in `[0, 1]` at which the two meshes intersect, by
//! an exact triangle-triangle test (independent of the code under test).
//! Samples where the rotation centres are farther apart than twice the
//! knot's reach cannot intersect and are skipped (the remaining samples are
//! those of the same grid). A method is LATE on a query when it reports a
//! first contact (for us, `earliest_possible_contact`) more than `1e-6` after
//! the first sampled contact, and MISSES a contact the sampling finds when it
//! reports none. Sampling can miss a contact shorter than the sample step, so
//! the counts are lower bounds of the real errors.
//!
//! Parry runs the first `M` queries, or as many of them as fit the budget
//! (per size): it starts only the queries that the previous size's time per
//! query and triangle says fit, and stops when one more query of its mean
//! duration so far would pass the budget; it is skipped when not even one
//! fits. The output says how many ran. With the defaults the whole run takes
//! about 10 minutes on two busy cores (parry and the ground truth at 11K and
//! 34K take most of it).

use std::time::Instant;

use motion_bound::bodies::TorusKnotSize;
use motion_bound::ca::{BoundChoice, CaOutcome, ContactCriterion, TraversalStats};
use motion_bound::testkit::ground_truth::{first_sampled_contact, MeshRef};

use motion_bound::testkit::table1::{
    label, KnotScene, Query, CONTACT_DISTANCE, ORIENTATIONS, SPIN,
};
use motion_bound_compare::parry::{mapping_error, parry_meshes, parry_toi, ParryAnswer};

/// A reported contact later than the first sampled contact by more than this
/// is LATE.
const LATE_TOLERANCE: f64 = 1e-6;

/// The seed's Table 1 and Figure 3: (ms with EVQ, ms without, iterations
/// with EVQ, iterations without).
fn seed_numbers(size: TorusKnotSize) -> (f64, f64, f64, f64) {
    match size {
        TorusKnotSize::K2_8 => (0.983, 0.937, 4.16, 4.49),
        TorusKnotSize::K11 => (2.98, 2.50, 4.18, 4.49),
        TorusKnotSize::K34 => (5.88, 5.38, 4.16, 4.46),
    }
}

struct Args {
    queries: usize,
    spin: f64,
    parry_queries: usize,
    truth_queries: Option<usize>,
    samples: usize,
    sizes: Vec<TorusKnotSize>,
    parry_budget: f64,
}

fn parse_args() -> Args {
    let mut flags = motion_bound_devkit::Args::from_env(
        "table1 [--queries N] [--spin S] [--parry-queries M] [--truth-queries K] [--samples S] \
         [--sizes 2.8K,11K,34K] [--parry-budget SECONDS]",
    );
    let sizes = flags.value::<String>("--sizes").map(|list| {
        list.split(',')
            .map(|s| {
                TorusKnotSize::ALL
                    .into_iter()
                    .find(|&k| label(k) == s.trim())
                    .unwrap_or_else(|| flags.fail(&format!("unknown size {s} (2.8K, 11K or 34K)")))
            })
            .collect()
    });
    let mut args = Args {
        queries: flags.value_or("--queries", 200),
        spin: flags.value_or("--spin", SPIN),
        parry_queries: flags.value_or("--parry-queries", 10),
        truth_queries: flags.value("--truth-queries"),
        samples: flags.value_or("--samples", 1000).max(2),
        sizes: sizes.unwrap_or_else(|| TorusKnotSize::ALL.to_vec()),
        parry_budget: flags.value_or("--parry-budget", 120.0),
    };
    flags.finish();
    if args.queries == 0 || !(args.spin.is_finite() && args.spin >= 0.0) {
        flags.fail("--queries must be positive and --spin finite and >= 0");
    }
    args.parry_queries = args.parry_queries.min(args.queries);
    args
}

/// One bound's results over the query list.
#[derive(Default)]
struct Run {
    times_ms: Vec<f64>,
    iterations: u64,
    /// Per query: the earliest possible contact (contact time or the
    /// iteration limit's time), `None` when certified separated.
    earliest: Vec<Option<f64>>,
    contacts: usize,
    initial: usize,
    by_time_tolerance: usize,
    /// Contacts by time tolerance declared within `1e-9` of the interval's
    /// end (none should be: near the end a short step is no stall).
    tolerance_at_end: usize,
    /// The indices of the queries certified separated.
    separated: Vec<usize>,
    iteration_limit: usize,
    stats: TraversalStats,
}

impl Run {
    fn record(&mut self, ms: f64, outcome: &CaOutcome<f64>, iterations: u32, s: TraversalStats) {
        let index = self.times_ms.len();
        self.times_ms.push(ms);
        self.iterations += u64::from(iterations);
        self.earliest.push(outcome.earliest_possible_contact());
        match outcome {
            CaOutcome::Contact { criterion, contact } => {
                self.contacts += 1;
                if *criterion == ContactCriterion::TimeTolerance {
                    self.by_time_tolerance += 1;
                    if contact.time >= 1.0 - 1e-9 {
                        self.tolerance_at_end += 1;
                    }
                }
            }
            CaOutcome::Separated => self.separated.push(index),
            CaOutcome::InitialContact(_) => {
                self.contacts += 1;
                self.initial += 1;
            }
            CaOutcome::IterationLimit { .. } => self.iteration_limit += 1,
            _ => {}
        }
        self.stats.node_pairs += s.node_pairs;
        self.stats.pruned += s.pruned;
        self.stats.triangle_pairs += s.triangle_pairs;
        self.stats.bounds += s.bounds;
        self.stats.overlapping += s.overlapping;
        self.stats.settled += s.settled;
    }
}

/// Mean and median.
fn mean_median(xs: &[f64]) -> (f64, f64) {
    if xs.is_empty() {
        return (f64::NAN, f64::NAN);
    }
    let mut v = xs.to_vec();
    v.sort_by(f64::total_cmp);
    let n = v.len();
    let median = if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    };
    (v.iter().sum::<f64>() / n as f64, median)
}

/// The first sampled contact of query `q` on the grid of `samples` times in
/// `[0, 1]`, skipping the samples where the rotation centres are farther
/// apart than the two reaches (no intersection is possible there).
fn sampled_truth(scene: &KnotScene, q: &Query, samples: usize) -> Option<f64> {
    let (ma, mb) = (&q.motion.a, &q.motion.b);
    let (ca, cb, va, vb) = (ma.centre(), mb.centre(), ma.linear(), mb.linear());
    let d0 = [ca.x - cb.x, ca.y - cb.y, ca.z - cb.z];
    let dv = [va.x - vb.x, va.y - vb.y, va.z - vb.z];
    let dot = |x: [f64; 3], y: [f64; 3]| x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
    // A generous margin over the rounding of the placed points.
    let r = 2.0 * scene.reach * (1.0 + 1e-9) + 1e-9;
    // |d0 + dv t|^2 <= r^2  <=>  a t^2 + 2 b t + c <= 0.
    let (a, b, c) = (dot(dv, dv), dot(d0, dv), dot(d0, d0) - r * r);
    let (lo, hi) = if a == 0.0 {
        if c > 0.0 {
            return None;
        }
        (0.0, 1.0)
    } else {
        let disc = b * b - a * c;
        if disc < 0.0 {
            return None;
        }
        let s = disc.sqrt();
        ((-b - s) / a, (-b + s) / a)
    };
    let h = 1.0 / (samples - 1) as f64;
    // One grid step of slack on each side of the window.
    let k_lo = ((lo / h).floor() - 1.0).max(0.0) as usize;
    let k_hi = ((hi / h).ceil() + 1.0).min((samples - 1) as f64);
    if k_hi < 0.0 || (k_lo as f64) > k_hi {
        return None;
    }
    let k_hi = k_hi as usize;
    let mesh = |i: usize| MeshRef {
        vertices: scene.meshes[i].vertices(),
        triangles: scene.meshes[i].triangles(),
    };
    first_sampled_contact(
        mesh(q.a),
        ma,
        mesh(q.b),
        mb,
        (k_lo as f64 * h, k_hi as f64 * h),
        k_hi - k_lo + 1,
    )
}

/// LATE, MISSED and "only the method" counts of one method against the truth.
#[derive(Default)]
struct Verdict {
    late: usize,
    worst_late: f64,
    /// The most a reported contact precedes the first sampled one.
    worst_early: f64,
    missed: usize,
    only_method: usize,
}

impl Verdict {
    fn add(&mut self, method: Option<f64>, truth: Option<f64>) {
        match (method, truth) {
            (Some(m), Some(t)) if m > t + LATE_TOLERANCE => {
                self.late += 1;
                self.worst_late = self.worst_late.max(m - t);
            }
            (Some(m), Some(t)) => self.worst_early = self.worst_early.max(t - m),
            (None, Some(_)) => self.missed += 1,
            (Some(_), None) => self.only_method += 1,
            _ => {}
        }
    }

    fn row(&self, name: &str) {
        let worst = if self.late > 0 {
            format!(" (latest by {:.3e})", self.worst_late)
        } else {
            String::new()
        };
        println!(
            "    {name:<14} LATE {:>3}{worst}   MISSED {:>3}   contact only by the method {:>3}   \
             reported at most {:.2e} before the first sampled contact",
            self.late, self.missed, self.only_method, self.worst_early
        );
    }
}

/// What one size produced, for the closing summary.
struct Summary {
    size: TorusKnotSize,
    nevq: (f64, f64, f64),
    evq: (f64, f64, f64),
    parry: Option<(usize, f64, f64, f64)>,
}

fn run_size(args: &Args, size: TorusKnotSize, parry_per_triangle: &mut Option<f64>) -> Summary {
    let built = Instant::now();
    let scene = KnotScene::new(size, args.queries, args.spin);
    let n = scene.queries.len();
    let tris = size.triangle_count();
    println!(
        "\n== torus knot {} vs torus knot: {} triangles, {} vertices each, reach {:.4}; \
         {n} queries, spin {} rad/unit time ==",
        label(size),
        tris,
        scene.meshes[0].vertices().len(),
        scene.reach,
        args.spin
    );
    println!(
        "   {ORIENTATIONS} orientations and ball trees built in {:.2} s (tree depth {})",
        built.elapsed().as_secs_f64(),
        scene.trees[0].depth()
    );

    // Ours, NEVQ and EVQ interleaved (rotating which goes first), and EVQ
    // stepping as the seed does (absolute bounds over the rest of the
    // interval: no one-sided rates, no horizon), to show what those add.
    let (pn, pe) = (
        KnotScene::params(BoundChoice::Nevq),
        KnotScene::params(BoundChoice::Evq),
    );
    let pa = pe.with_one_sided(false).with_horizon_factor(0.0);
    for q in scene.queries.iter().take(ORIENTATIONS) {
        std::hint::black_box((scene.run(q, &pn), scene.run(q, &pe), scene.run(q, &pa)));
    }
    let (mut nevq, mut evq, mut evq_abs) = (Run::default(), Run::default(), Run::default());
    for (i, q) in scene.queries.iter().enumerate() {
        let mut order: [(&mut Run, _); 3] =
            [(&mut nevq, &pn), (&mut evq, &pe), (&mut evq_abs, &pa)];
        order.rotate_left(i % 3);
        for (run, params) in order {
            let start = Instant::now();
            let (report, stats) = scene.run(q, params);
            let ms = start.elapsed().as_secs_f64() * 1e3;
            run.record(ms, &report.outcome, report.iterations, stats);
        }
    }
    let (seed_evq_ms, seed_nevq_ms, seed_evq_it, seed_nevq_it) = seed_numbers(size);
    println!(
        "   {:<5} {:>8} {:>9} {:>6} {:>8} {:>11} {:>10} {:>9} {:>8} {:>8} {:>8} | {:>8} {:>9}",
        "bound",
        "mean ms",
        "median ms",
        "iters",
        "contact",
        "node pairs",
        "tri pairs",
        "bounds",
        "pruned",
        "overlap",
        "settled",
        "seed ms",
        "seed iters"
    );
    let nf = n as f64;
    let row = |name: &str, r: &Run, seed_ms: f64, seed_it: f64| {
        let (mean, median) = mean_median(&r.times_ms);
        println!(
            "   {name:<5} {mean:>8.3} {median:>9.3} {:>6.2} {:>7.1}% {:>11.0} {:>10.1} {:>9.0} {:>8.0} {:>8.0} {:>8.0} | {seed_ms:>8.3} {seed_it:>9.2}",
            r.iterations as f64 / nf,
            100.0 * r.contacts as f64 / nf,
            r.stats.node_pairs as f64 / nf,
            r.stats.triangle_pairs as f64 / nf,
            r.stats.bounds as f64 / nf,
            r.stats.pruned as f64 / nf,
            r.stats.overlapping as f64 / nf,
            r.stats.settled as f64 / nf,
        );
        (mean, median, r.iterations as f64 / nf)
    };
    let sn = row("NEVQ", &nevq, seed_nevq_ms, seed_nevq_it);
    let se = row("EVQ", &evq, seed_evq_ms, seed_evq_it);
    let sa = row("EVQ-s", &evq_abs, seed_evq_ms, seed_evq_it);
    println!(
        "   EVQ-s: EVQ as the seed steps (absolute speeds over the rest of the interval); \
         EVQ-s/EVQ time {:.2}, iterations {:.2}",
        sa.0 / se.0,
        sa.2 / se.2
    );
    for (name, r) in [("NEVQ", &nevq), ("EVQ", &evq)] {
        println!(
            "   {name:<5} outcomes: {} contacts ({} initial, {} by time tolerance, {} of them within 1e-9 of the end), {} separated, {} iteration limit",
            r.contacts,
            r.initial,
            r.by_time_tolerance,
            r.tolerance_at_end,
            r.separated.len(),
            r.iteration_limit
        );
        if !r.separated.is_empty() {
            let list: Vec<String> = r.separated.iter().map(usize::to_string).collect();
            println!("         separated queries: {}", list.join(", "));
        }
    }
    println!(
        "   EVQ/NEVQ time: mean {:.3}, median {:.3} (seed: {:.3}); iterations EVQ/NEVQ {:.3} (seed: {:.3})",
        se.0 / sn.0,
        se.1 / sn.1,
        seed_evq_ms / seed_nevq_ms,
        se.2 / sn.2,
        seed_evq_it / seed_nevq_it
    );

    // Parry on the first M queries.
    // `--parry-budget 0` (or `--parry-queries 0`) skips parry altogether.
    let m = if args.parry_budget > 0.0 {
        args.parry_queries
    } else {
        0
    };
    let mut parry: Vec<Option<ParryAnswer>> = vec![None; m];
    let mut parry_ms = Vec::new();
    let mut summary_parry = None;
    if m > 0 {
        let err = mapping_error(&scene, &scene.queries[0], 0.5);
        println!(
            "   motion mapping to parry checked on query 0: every vertex of both bodies at t = 0.5 \
             within {err:.1e} of ours"
        );
        assert!(err <= 1e-12, "the motion mapping to parry is wrong");
        let meshes = parry_meshes(&scene);
        // How many queries fit the budget, by the previous size's time per
        // query and triangle, else by this size's first query.
        let allowed = match *parry_per_triangle {
            Some(p) => ((args.parry_budget / (p * tris as f64)) as usize).min(m),
            None => m,
        };
        if allowed < m {
            println!(
                "   parry3d-f64 cast_shapes_nonlinear: about {:.1} s per query estimated from the \
                 previous size: {allowed} of {m} queries fit the budget of {:.0} s",
                parry_per_triangle.unwrap_or(0.0) * tris as f64,
                args.parry_budget
            );
        }
        let mut spent = 0.0;
        for (k, q) in scene.queries[..allowed].iter().enumerate() {
            let start = Instant::now();
            parry[k] = Some(parry_toi(&meshes, q));
            let s = start.elapsed().as_secs_f64();
            parry_ms.push(s * 1e3);
            spent += s;
            // Stop when one more query of the mean duration would overrun.
            let next = spent + spent / (k + 1) as f64;
            if k + 1 < allowed && next > args.parry_budget {
                println!(
                    "   parry3d-f64 cast_shapes_nonlinear: stopped after {} of {m} queries \
                     ({spent:.0} s; one more would pass the budget of {:.0} s)",
                    k + 1,
                    args.parry_budget
                );
                break;
            }
        }
        if parry_ms.is_empty() {
            println!("   parry3d-f64 cast_shapes_nonlinear: SKIPPED (no query fits the budget)");
        } else {
            let done = parry_ms.len();
            let (pm, pmed) = mean_median(&parry_ms);
            *parry_per_triangle = Some(pm * 1e-3 / tris as f64);
            let failed = parry.iter().flatten().filter(|a| a.failed).count();
            let hits = parry.iter().flatten().filter(|a| a.time.is_some()).count();
            let (on, _) = mean_median(&nevq.times_ms[..done]);
            let (oe, _) = mean_median(&evq.times_ms[..done]);
            println!(
                "   parry3d-f64 0.31.1 cast_shapes_nonlinear on the first {done} queries: mean {pm:.1} ms, \
                 median {pmed:.1} ms; {hits} impacts, {failed} with status Failed"
            );
            println!(
                "   ours on the same {done} queries: NEVQ mean {on:.3} ms, EVQ mean {oe:.3} ms; \
                 ours/parry time: NEVQ {:.2e}, EVQ {:.2e} (parry/ours: {:.0}x, {:.0}x)",
                on / pm,
                oe / pm,
                pm / on,
                pm / oe
            );
            summary_parry = Some((done, pm, on / pm, oe / pm));
        }
    }

    // Ground truth.
    let k = args.truth_queries.unwrap_or(m).min(n);
    if k > 0 {
        let start = Instant::now();
        let (mut vn, mut ve, mut vp) = (Verdict::default(), Verdict::default(), Verdict::default());
        let mut sampled = 0;
        let mut parry_checked = 0;
        for (i, q) in scene.queries[..k].iter().enumerate() {
            let truth = sampled_truth(&scene, q, args.samples);
            sampled += usize::from(truth.is_some());
            vn.add(nevq.earliest[i], truth);
            ve.add(evq.earliest[i], truth);
            if let Some(Some(p)) = parry.get(i) {
                vp.add(p.time, truth);
                parry_checked += 1;
            }
        }
        println!(
            "   ground truth on the first {k} queries (first_sampled_contact, {} samples over [0, 1], \
             exact triangle test; {:.1} s): {sampled} sampled contacts; LATE = reported > sampled + {LATE_TOLERANCE:e}",
            args.samples,
            start.elapsed().as_secs_f64()
        );
        vn.row("NEVQ");
        ve.row("EVQ");
        if parry_checked > 0 {
            vp.row(&format!("parry ({parry_checked} q)"));
        }
    }
    Summary {
        size,
        nevq: sn,
        evq: se,
        parry: summary_parry,
    }
}

fn main() {
    let args = parse_args();
    println!(
        "Table 1 reproduction: torus knot vs torus knot, conservative advancement (f64), \
         contact distance {CONTACT_DISTANCE:e}, time tolerance 1e-9, at most 100 iterations."
    );
    println!(
        "Timings are Instant-based, one pass: a report, not a benchmark (see `cargo bench -p motion-bound-compare --bench toi`)."
    );
    let mut parry_per_triangle = None;
    let summaries: Vec<_> = args
        .sizes
        .iter()
        .map(|&s| run_size(&args, s, &mut parry_per_triangle))
        .collect();

    println!("\n== summary (ms per query; seed's Table 1 in brackets) ==");
    println!(
        "   {:<5} {:>17} {:>17} {:>9} {:>15} {:>12} {:>26}",
        "size",
        "NEVQ mean",
        "EVQ mean",
        "EVQ/NEVQ",
        "iters N / E",
        "seed iters",
        "parry mean, ours/parry N E"
    );
    for s in &summaries {
        let (se, sn, sie, sin) = seed_numbers(s.size);
        let parry = s.parry.map_or_else(
            || "skipped".to_owned(),
            |(q, pm, rn, re)| format!("{pm:.0} ms ({q} q), {rn:.1e} {re:.1e}"),
        );
        println!(
            "   {:<5} {:>8.3} [{sn:>6.3}] {:>8.3} [{se:>6.3}] {:>9.3} {:>6.2} / {:>5.2} {sin:>5.2}/{sie:>5.2} {parry:>26}",
            label(s.size),
            s.nevq.0,
            s.evq.0,
            s.evq.0 / s.nevq.0,
            s.nevq.2,
            s.evq.2,
        );
    }
}
