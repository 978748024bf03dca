//! Degenerate meshes against the bunny under the default `CaParams` (issue
//! 38): copies of one triangle (10, 10,000 and 100,000, of the bunny's size
//! and a tenth of it), triangles on one point, near copies, and the bunny
//! with every vertex doubled and 1,000 zero-area triangles added (and the
//! 75K bunny so made up to 100,000 triangles). Each query is timed with the
//! pair's construction (`AnyPair::try_new`, as a scene or the Python module
//! makes it inside the query), the trees built beforehand and timed apart.
//!
//! Run with `cargo run --release --example degenerate_meshes` (about 10 s,
//! most of it building the trees of 100,000 distinct triangles; `-- --quick`
//! leaves out the 100,000-triangle cases).
//!
//! One line per case: the triangles, the tree's nodes (duplicates share one
//! leaf), the tree build in ms (with its hierarchy of pieces), the pair's
//! first construction in ms, the most ms of one query with its pair over the
//! fly-bys (`tests/common/degenerate.rs`, `fly_by`), the most work of one,
//! the most us a unit of work (node pair or triangle pair) took in a query of
//! at least 10,000 units (the query's time alone), and the outcomes (contact
//! C, initial contact I, separated S, work limit W, other O). The last line:
//! `max ms M, over 50 ms: K` (K queries over 50 ms, or neither decided nor
//! `WorkLimit`, or over the work budget).

#[path = "../tests/common/degenerate.rs"]
mod degenerate;
#[path = "../tests/common/meshes.rs"]
mod meshes;

use std::time::Instant;

use motion_bound::ca::{time_of_impact, AnyPair, CaOutcome, CaParams, Shape, Work};
use motion_bound::testkit::toi::Rng;
use motion_bound::{BallTree, TriMesh};
use motion_bound_devkit::{cpu_name, Args};

/// The bound every query must meet, in ms.
const BOUND_MS: f64 = 50.0;

/// What one case found.
#[derive(Default)]
struct Tally {
    max_ms: f64,
    over: usize,
    per_unit_us: f64,
}

/// The bunny (3,674 triangles) centred and scaled to reach 1.
fn bunny() -> TriMesh<f64> {
    let m = meshes::load_shipped("bunny-npm-3674.obj.gz");
    let (c, r) = m.bounding_sphere();
    m.recentred(c)
        .and_then(|m| m.scaled(1.0 / r))
        .expect("the bunny")
}

fn case(name: &str, mesh: &TriMesh<f64>, bunny: &BallTree<f64>, motions: usize, all: &mut Tally) {
    let start = Instant::now();
    let tree = BallTree::try_from_mesh(mesh).expect("a tree");
    let build_ms = start.elapsed().as_secs_f64() * 1e3;
    let params = CaParams::<f64>::default();
    let (mut first_ms, mut max_ms) = (0.0, 0.0f64);
    let mut most = Work::ZERO;
    let mut counts = [0usize; 5];
    let mut per_unit = 0.0f64;
    for k in 0..motions {
        let (ma, mb) = degenerate::fly_by(k);
        let start = Instant::now();
        let mut pair = AnyPair::try_new(Shape::Mesh(&tree), Shape::Mesh(bunny)).expect("a pair");
        let pair_ms = start.elapsed().as_secs_f64() * 1e3;
        if k == 0 {
            first_ms = pair_ms;
        }
        let r = time_of_impact(&mut pair, &ma, &mb, &params).expect("a valid query");
        let ms = start.elapsed().as_secs_f64() * 1e3;
        max_ms = max_ms.max(ms);
        most = Work::new(
            most.node_pairs.max(r.work.node_pairs),
            most.triangle_pairs.max(r.work.triangle_pairs),
        );
        let slot = match r.outcome {
            CaOutcome::Contact { .. } => 0,
            CaOutcome::InitialContact(_) => 1,
            CaOutcome::Separated => 2,
            CaOutcome::WorkLimit { .. } => 3,
            _ => 4,
        };
        counts[slot] += 1;
        if ms > BOUND_MS || slot == 4 || r.work.exceeds(params.work_budget) {
            all.over += 1;
        }
        // The query's time per unit where the work, not its fixed cost,
        // dominates.
        let units = (r.work.node_pairs + r.work.triangle_pairs) as f64;
        if units >= 10_000.0 {
            per_unit = per_unit.max((ms - pair_ms) * 1e3 / units);
        }
    }
    all.max_ms = all.max_ms.max(max_ms);
    all.per_unit_us = all.per_unit_us.max(per_unit);
    let per_unit = if per_unit > 0.0 {
        format!("{per_unit:.2}")
    } else {
        "-".into()
    };
    println!(
        "| {name} | {} | {} | {build_ms:.1} | {first_ms:.1} | {max_ms:.1} | {} / {} | {per_unit} | C {} I {} S {} W {} O {} |",
        mesh.triangle_count(),
        tree.node_count(),
        most.node_pairs,
        most.triangle_pairs,
        counts[0],
        counts[1],
        counts[2],
        counts[3],
        counts[4],
    );
}

fn main() {
    let mut args = Args::from_env("degenerate_meshes [--quick] [--motions N]");
    let quick = args.flag("--quick");
    let motions = args.value_or("--motions", 6usize);
    args.finish();
    println!(
        "CPU: {}; default CaParams; {motions} fly-bys a case, each timed with its pair's construction\n",
        cpu_name()
    );
    let bunny_mesh = bunny();
    let bunny = BallTree::try_from_mesh(&bunny_mesh).expect("the bunny's tree");
    println!("| case | triangles | nodes | tree build ms | first pair ms | max ms (pair + query) | most node / triangle pairs | us per unit | outcomes |");
    println!("|---|---|---|---|---|---|---|---|---|");
    let mut all = Tally::default();
    let sizes: &[usize] = if quick {
        &[10, 10_000]
    } else {
        &[10, 10_000, 100_000]
    };
    for (scale, what) in [(1.0, "bunny-sized"), (0.1, "a tenth")] {
        for &n in sizes {
            let mesh = degenerate::copies(degenerate::triangle(scale), n);
            case(
                &format!("{n} copies of a triangle, {what}"),
                &mesh,
                &bunny,
                motions,
                &mut all,
            );
        }
    }
    let mut rng = Rng::new(38);
    let n = if quick { 10_000 } else { 100_000 };
    case(
        &format!("{n} triangles on one point"),
        &degenerate::on_one_point([0.0, 0.3, -0.2], n),
        &bunny,
        motions,
        &mut all,
    );
    case(
        &format!("{n} near copies (within 1e-9) of a triangle, bunny-sized"),
        &degenerate::near_copies(degenerate::triangle(1.0), n, 1e-9, &mut rng),
        &bunny,
        motions,
        &mut all,
    );
    case(
        "the bunny (3.7K), vertices doubled, 1,000 zero-area triangles added",
        &degenerate::doubled_with_slivers(&bunny_mesh, 1_000, &mut rng),
        &bunny,
        motions,
        &mut all,
    );
    if !quick {
        let big = meshes::load_shipped("bunny00.off.gz");
        let (c, r) = big.bounding_sphere();
        let big = big
            .recentred(c)
            .and_then(|m| m.scaled(1.0 / r))
            .expect("the 75K bunny");
        let extra = 100_000 - big.triangle_count();
        case(
            &format!("the bunny (75K), vertices doubled, {extra} zero-area triangles added"),
            &degenerate::doubled_with_slivers(&big, extra, &mut rng),
            &bunny,
            motions,
            &mut all,
        );
    }
    println!(
        "\nmost us per unit of work (node pair or triangle pair) in a query of at least 10,000 units: {:.2}",
        all.per_unit_us
    );
    println!("max ms {:.1}, over {BOUND_MS} ms: {}", all.max_ms, all.over);
}
