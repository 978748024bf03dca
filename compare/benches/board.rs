//! Benchmark of a board of a few large triangles against a detailed mesh:
//! the armadillo (52K triangles, radius 0.5) against a spinning
//! `2 x 2 x 0.002` board, as 12 triangles and as the same solid finely
//! tessellated, on the same motions.
//!
//! The queries: [`QUERIES`] seeded fly-bys over `[0, 1]`
//! (`testkit::toi::fly_by`, the board as A spinning at up to [`SPIN`] rad
//! per unit time, the armadillo as B at up to a quarter of it), contact
//! distance `1e-3`, EVQ, default parameters; each criterion iteration runs
//! the next query of the list (cycling).
//!
//! * `board_armadillo/board12`: the 12-triangle board with its default tree,
//!   whose hierarchy of pieces the query takes
//!   ([`BallTree::try_with_piece_length`]);
//! * `board_armadillo/tessellated`: the board of [`CELLS`] x [`CELLS`] cells a
//!   face (`bodies::tessellated_board`, 16,896 triangles);
//! * `board_armadillo/board12_whole`: the 12-triangle board without pieces
//!   (`f64::INFINITY`), on the first [`WHOLE_QUERIES`] queries only (seconds
//!   each): what the pieces remove. `tessellated_first` runs the tessellated
//!   board on those same queries, for the ratio.
//!
//! Before timing, each variant runs the list once and prints its mean node
//! pairs, triangle pairs, iterations and contacts; the 12-triangle and the
//! tessellated boards are the same solid, so it also prints how many
//! queries agree on contact or none, and the largest difference of their
//! contact times (both are sound; they differ by where each stops within
//! the contact distance).
//!
//! `cargo bench -p motion-bound-compare --bench board` (about 2 minutes).

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkId, Criterion, SamplingMode};
use motion_bound::bodies::{board, tessellated_board};
use motion_bound::ca::{time_of_impact, BoundChoice, CaParams, CaReport, MeshPair};
use motion_bound::testkit::toi::{fly_by, reach, FlyBy, Rng};
use motion_bound::BallTree;
use motion_bound_compare::shipped_mesh;

/// Queries in the list.
const QUERIES: usize = 20;
/// The board's largest spin, rad per unit time.
const SPIN: f64 = 40.0;
/// Cells a side of each face of the tessellated board.
const CELLS: u32 = 64;
/// Queries the board without pieces runs.
const WHOLE_QUERIES: usize = 2;

fn params() -> CaParams<f64> {
    CaParams::default()
        .with_contact_distance(1e-3)
        .with_bound(BoundChoice::Evq)
}

fn run(board: &BallTree<f64>, armadillo: &BallTree<f64>, q: &FlyBy) -> (CaReport<f64>, u64, u64) {
    let mut pair = MeshPair::new(board, armadillo);
    let report = time_of_impact(&mut pair, &q.a, &q.b, &params()).expect("valid query");
    let s = pair.stats();
    (report, s.node_pairs, s.triangle_pairs)
}

fn summary(
    name: &str,
    board: &BallTree<f64>,
    armadillo: &BallTree<f64>,
    list: &[FlyBy],
) -> Vec<Option<f64>> {
    let (mut nodes, mut tris, mut iters) = (0, 0, 0);
    let mut times = Vec::new();
    for q in list {
        let (r, n, t) = run(board, armadillo, q);
        nodes += n;
        tris += t;
        iters += u64::from(r.iterations);
        times.push(r.outcome.contact().map(|c| c.time));
    }
    let k = list.len() as f64;
    println!(
        "board_armadillo/{name}: {} queries, node pairs {:.0}, triangle pairs {:.0}, iterations {:.2}, contacts {}",
        list.len(),
        nodes as f64 / k,
        tris as f64 / k,
        iters as f64 / k,
        times.iter().flatten().count()
    );
    times
}

fn main() {
    let mut criterion = Criterion::default().configure_from_args();
    let armadillo_mesh = shipped_mesh("armadillo.off.gz");
    let armadillo = BallTree::try_from_mesh(&armadillo_mesh).expect("valid");
    let coarse = board::<f64>(2.0, 2.0, 0.002).expect("board");
    let fine = tessellated_board::<f64>(2.0, 2.0, 0.002, CELLS).expect("board");
    let board12 = BallTree::try_from_mesh(&coarse).expect("valid");
    let tessellated = BallTree::try_from_mesh(&fine).expect("valid");
    let whole =
        BallTree::try_with_piece_length(coarse.vertices(), coarse.triangles(), f64::INFINITY)
            .expect("valid");
    assert_eq!(
        MeshPair::new(&board12, &armadillo).pieces_in_use(),
        (true, false)
    );
    let mut rng = Rng::new(7);
    let list: Vec<FlyBy> = (0..QUERIES)
        .map(|_| fly_by(&mut rng, reach(&coarse), reach(&armadillo_mesh), SPIN))
        .collect();
    println!(
        "board_armadillo: armadillo {} triangles; board 12 triangles ({} leaves in its pieces); tessellated board {} triangles",
        armadillo_mesh.triangle_count(),
        board12.piece_leaf_count(),
        fine.triangle_count()
    );
    let t12 = summary("board12", &board12, &armadillo, &list);
    let tf = summary("tessellated", &tessellated, &armadillo, &list);
    summary("board12_whole", &whole, &armadillo, &list[..WHOLE_QUERIES]);
    let agree = t12
        .iter()
        .zip(&tf)
        .filter(|(a, b)| a.is_some() == b.is_some())
        .count();
    let gap = t12
        .iter()
        .zip(&tf)
        .filter_map(|(a, b)| Some((a.as_ref()? - b.as_ref()?).abs()))
        .fold(0.0, f64::max);
    println!(
        "board_armadillo: board12 and tessellated agree on contact in {agree} of {QUERIES} queries; largest contact-time difference {gap:.2e}"
    );

    let mut group = criterion.benchmark_group("board_armadillo");
    group
        .sample_size(20)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(8));
    for (id, tree, list) in [
        ("board12", &board12, &list[..]),
        ("tessellated", &tessellated, &list[..]),
        ("tessellated_first", &tessellated, &list[..WHOLE_QUERIES]),
    ] {
        group.bench_function(BenchmarkId::from_parameter(id), |b| {
            let mut k = 0;
            b.iter(|| {
                let q = &list[k % list.len()];
                k += 1;
                run(tree, &armadillo, black_box(q)).0
            });
        });
    }
    group
        .sampling_mode(SamplingMode::Flat)
        .sample_size(10)
        .warm_up_time(Duration::from_millis(1))
        .measurement_time(Duration::from_secs(1));
    group.bench_function(BenchmarkId::from_parameter("board12_whole"), |b| {
        let mut k = 0;
        b.iter(|| {
            let q = &list[k % WHOLE_QUERIES];
            k += 1;
            run(&whole, &armadillo, black_box(q)).0
        });
    });
    group.finish();
    criterion.final_summary();
}
