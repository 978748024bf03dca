//! A coarse surface against the same surface finely meshed, for a rigid mesh
//! pair (issue 43, point 3): a thin board (1 x 1 x 0.02) as a box of 12
//! triangles and the same box with each face on a 4 cm grid
//! (`tests/common/arm_scene.rs`, `cuboid`), each against the bunny (3,674
//! triangles, scaled to reach 0.5, or `--bunny R`), on the same fly-bys (the testkit's
//! `toi::fly_by`: the bunny translating past and into the board while
//! spinning at up to `--spin` rad per unit time, the board turning slowly),
//! under the default `CaParams`, through `AnyPair` and `time_of_impact` (the
//! pair made inside the timed query, as a scene or the bindings make it;
//! the trees built beforehand).
//!
//! Run with `cargo run --release --features urdf --example coarse_fine` (`--queries N`,
//! default 200; `--spin S`, default 4; `--seed S`; `--no-truth` for the
//! work and times alone; `--only coarse|fine` for one board, e.g. under
//! callgrind; `--piece L` builds the coarse board's pieces at length `L`,
//! `BallTree::try_with_piece_length`, instead of the default).
//!
//! Ground truth, independent of the code under test: each query is sampled
//! up to its reported time, densely enough that the fastest point moves
//! about 0.01 between samples, and at each sample the two bodies touch when
//! some bunny triangle and some board triangle are within distance 0
//! (`try_triangle_triangle`, the exact distance), the bodies placed by the
//! testkit's own quaternion placement. Both boards cover the same surface,
//! so the 12-triangle board is the truth for both. A sampled contact is a
//! true contact: a query is MISSED when it reports no possible contact and
//! the sampling finds one, LATE when its first possible contact is after the
//! sampled one.
//!
//! One line per board: queries, mean and 99th-percentile ms, mean and most
//! iterations, mean and most node pairs and triangle pairs, the outcomes
//! (contact C, initial contact I, separated S, other O), missed and late;
//! then the ratios coarse / fine of the mean and the 99th percentile.

#[path = "../tests/common/arm_scene.rs"]
mod arm_scene;
#[path = "../tests/common/meshes.rs"]
mod meshes;

use std::time::Instant;

use motion_bound::ca::{time_of_impact, AnyPair, CaOutcome, CaParams, Shape};
use motion_bound::testkit::ground_truth::place;
use motion_bound::testkit::toi::{fly_by, Rng};
use motion_bound::{try_triangle_triangle, BallTree, Point3, RigidMotion, TriMesh};
use motion_bound_devkit::{cpu_name, Args};

/// The board's half extents.
const HALF: [f64; 3] = [0.5, 0.5, 0.01];
/// The fine board's grid.
const CELL: f64 = 0.04;
/// The bunny (3,674 triangles) centred and scaled to reach `reach`.
fn bunny(reach: f64) -> TriMesh<f64> {
    let m = meshes::load_shipped("bunny-npm-3674.obj.gz");
    let (c, r) = m.bounding_sphere();
    m.recentred(c)
        .and_then(|m| m.scaled(reach / r))
        .expect("the bunny")
}

/// The board with faces on a grid of `cell` (a cell larger than the board:
/// 2 triangles a face).
fn board(cell: f64) -> TriMesh<f64> {
    arm_scene::cuboid([0.0; 3], HALF, cell).expect("a board").0
}

/// A triangle mapped by the motion's pose at `t`.
fn placed(tri: &[[f64; 3]; 3], m: &RigidMotion<f64>, t: f64) -> [Point3<f64>; 3] {
    tri.map(|p| Point3::from_array(place(m, p, t)))
}

/// Whether the bunny (vertices `bv`, triangles `bt`, motion `ma`) and the
/// board (triangles `board`, motion `mb`) touch at `t`: some pair of
/// triangles at exact distance 0. A bunny triangle is skipped only when it
/// is plainly apart from the board: all its corners beyond the board's
/// bounding sphere's reach of one another, or all on one side of the slab
/// the board lies in (each with a margin of 1e-9).
fn touch_at(
    (bv, bt, ma): (&[[f64; 3]], &[[u32; 3]], &RigidMotion<f64>),
    (board, mb): (&[[[f64; 3]; 3]], &RigidMotion<f64>),
    t: f64,
) -> bool {
    let o = place(mb, [0.0; 3], t);
    let z = place(mb, [0.0, 0.0, 1.0], t);
    let n = [0, 1, 2].map(|k| z[k] - o[k]);
    let reach = (HALF[0] * HALF[0] + HALF[1] * HALF[1] + HALF[2] * HALF[2]).sqrt() + 1e-9;
    let slab = HALF[2] + 1e-9;
    let tris: Vec<[Point3<f64>; 3]> = board.iter().map(|x| placed(x, mb, t)).collect();
    let verts: Vec<[f64; 3]> = bv.iter().map(|&p| place(ma, p, t)).collect();
    let height = |p: &[f64; 3]| (0..3).map(|k| (p[k] - o[k]) * n[k]).sum::<f64>();
    let off = |p: &[f64; 3]| (0..3).map(|k| (p[k] - o[k]).powi(2)).sum::<f64>().sqrt();
    bt.iter().any(|tri| {
        let c = tri.map(|i| verts[i as usize]);
        let h = c.map(|p| height(&p));
        if h.iter().all(|&x| x > slab) || h.iter().all(|&x| x < -slab) {
            return false;
        }
        // Apart from the board's bounding sphere.
        let g = [0, 1, 2].map(|k| (c[0][k] + c[1][k] + c[2][k]) / 3.0);
        let r = c
            .iter()
            .map(|p| (0..3).map(|k| (p[k] - g[k]).powi(2)).sum::<f64>().sqrt())
            .fold(0.0, f64::max);
        if off(&g) > reach + r + 1e-9 {
            return false;
        }
        let x = c.map(Point3::from_array);
        tris.iter()
            .any(|y| try_triangle_triangle(&x, y).expect("finite").distance <= 0.0)
    })
}

/// The first of `samples + 1` evenly spaced times of `[0, end]` at which
/// the bodies touch.
fn first_sampled_contact(
    bunny: (&[[f64; 3]], &[[u32; 3]], &RigidMotion<f64>),
    board: (&[[[f64; 3]; 3]], &RigidMotion<f64>),
    end: f64,
    samples: usize,
) -> Option<f64> {
    (0..=samples)
        .map(|s| end * s as f64 / samples as f64)
        .find(|&t| touch_at(bunny, board, t))
}

/// One query's figures.
#[derive(Clone, Copy)]
struct Query {
    ms: f64,
    iterations: u32,
    node_pairs: u64,
    triangle_pairs: u64,
    outcome: usize,
    contact: Option<f64>,
}

/// A board's queries.
#[derive(Default)]
struct Tally {
    queries: Vec<Query>,
    missed: usize,
    late: usize,
}

impl Tally {
    fn percentile_ms(&self, p: f64) -> f64 {
        let mut ms: Vec<f64> = self.queries.iter().map(|q| q.ms).collect();
        ms.sort_by(f64::total_cmp);
        let k = ((p * ms.len() as f64).ceil() as usize).clamp(1, ms.len()) - 1;
        ms[k]
    }

    fn mean(&self, f: impl Fn(&Query) -> f64) -> f64 {
        self.queries.iter().map(f).sum::<f64>() / self.queries.len() as f64
    }

    fn line(&self, name: &str, tree: &BallTree<f64>) {
        let mut outcomes = [0usize; 4];
        for q in &self.queries {
            outcomes[q.outcome] += 1;
        }
        let most_it = self.queries.iter().map(|q| q.iterations).max().unwrap_or(0);
        let most_np = self.queries.iter().map(|q| q.node_pairs).max().unwrap_or(0);
        let mut np: Vec<u64> = self.queries.iter().map(|q| q.node_pairs).collect();
        np.sort_unstable();
        let p99_np = np[((0.99 * np.len() as f64).ceil() as usize).clamp(1, np.len()) - 1];
        let most_tp = self
            .queries
            .iter()
            .map(|q| q.triangle_pairs)
            .max()
            .unwrap_or(0);
        println!(
            "{name}: {} triangles, {} piece leaves; queries {}, mean ms {:.3}, p99 ms {:.3}, \
             iterations mean {:.1} max {most_it}, node pairs mean {:.0} p99 {p99_np} max {most_np}, \
             triangle pairs mean {:.0} max {most_tp}, C {} I {} S {} O {}, missed {}, late {}",
            tree.triangle_count(),
            tree.piece_leaf_count(),
            self.queries.len(),
            self.mean(|q| q.ms),
            self.percentile_ms(0.99),
            self.mean(|q| f64::from(q.iterations)),
            self.mean(|q| q.node_pairs as f64),
            self.mean(|q| q.triangle_pairs as f64),
            outcomes[0],
            outcomes[1],
            outcomes[2],
            outcomes[3],
            self.missed,
            self.late,
        );
    }
}

/// One query, timed with its pair made inside.
fn query(
    board: &BallTree<f64>,
    bunny: &BallTree<f64>,
    ma: &RigidMotion<f64>,
    mb: &RigidMotion<f64>,
) -> Query {
    let params = CaParams::<f64>::default();
    let start = Instant::now();
    let r = AnyPair::try_new(Shape::Mesh(bunny), Shape::Mesh(board))
        .and_then(|mut pair| time_of_impact(&mut pair, ma, mb, &params))
        .expect("a valid query");
    let ms = start.elapsed().as_secs_f64() * 1e3;
    Query {
        ms,
        iterations: r.iterations,
        node_pairs: r.work.node_pairs,
        triangle_pairs: r.work.triangle_pairs,
        outcome: match r.outcome {
            CaOutcome::Contact { .. } => 0,
            CaOutcome::InitialContact(_) => 1,
            CaOutcome::Separated => 2,
            _ => 3,
        },
        contact: r.outcome.earliest_possible_contact(),
    }
}

fn main() {
    let mut args = Args::from_env(
        "coarse_fine [--queries 200] [--spin 4] [--seed 43] [--no-truth] [--only coarse|fine] [--bunny 0.5] [--piece L]",
    );
    let queries: usize = args.value_or("--queries", 200);
    let spin: f64 = args.value_or("--spin", 4.0);
    let seed: u64 = args.value_or("--seed", 43);
    let truth = !args.flag("--no-truth");
    let only: Option<String> = args.value("--only");
    let bunny_reach: f64 = args.value_or("--bunny", 0.5);
    let piece: Option<f64> = args.value("--piece");
    args.finish();
    let (coarse_mesh, fine_mesh, bunny_mesh) = (board(2.0), board(CELL), bunny(bunny_reach));
    let start = Instant::now();
    let coarse = match piece {
        Some(l) => {
            BallTree::try_with_piece_length(coarse_mesh.vertices(), coarse_mesh.triangles(), l)
        }
        None => BallTree::try_from_mesh(&coarse_mesh),
    }
    .expect("a tree");
    let coarse_build_ms = start.elapsed().as_secs_f64() * 1e3;
    let fine = BallTree::try_from_mesh(&fine_mesh).expect("a tree");
    let bunny = BallTree::try_from_mesh(&bunny_mesh).expect("a tree");
    let board_tris: Vec<[[f64; 3]; 3]> = coarse_mesh.triangle_corners().collect();
    let board_reach = (HALF[0] * HALF[0] + HALF[1] * HALF[1] + HALF[2] * HALF[2]).sqrt();
    println!(
        "CPU: {}; board {HALF:?} half extents, coarse {} and fine {} triangles (cell {CELL}), \
         bunny {} triangles at reach {bunny_reach}; {queries} fly-bys, spin up to {spin}, seed {seed}",
        cpu_name(),
        coarse_mesh.triangle_count(),
        fine_mesh.triangle_count(),
        bunny_mesh.triangle_count(),
    );
    println!("coarse board's tree built in {coarse_build_ms:.1} ms (with its pieces)");
    let run_coarse = only.as_deref() != Some("fine");
    let run_fine = only.as_deref() != Some("coarse");
    let mut rng = Rng::new(seed);
    let (mut tc, mut tf) = (Tally::default(), Tally::default());
    for _ in 0..queries {
        let f = fly_by(&mut rng, bunny_reach, board_reach, spin);
        let (ma, mb) = (f.a, f.b);
        let qc = run_coarse.then(|| query(&coarse, &bunny, &ma, &mb));
        let qf = run_fine.then(|| query(&fine, &bunny, &ma, &mb));
        if truth {
            // One truth for both (the same surface), sampled up to the later
            // of the two reported times.
            let end = [qc, qf]
                .iter()
                .flatten()
                .map(|q| q.contact.unwrap_or(1.0))
                .fold(0.0, f64::max);
            let speed = ma.linear().length()
                + ma.angular_speed() * bunny_reach
                + mb.angular_speed() * board_reach;
            let n = (((speed / 0.02).ceil().max(200.0)) * end).ceil() as usize;
            let g = first_sampled_contact(
                (bunny_mesh.vertices(), bunny_mesh.triangles(), &ma),
                (&board_tris, &mb),
                end,
                n.max(1),
            );
            for (q, t) in [(qc, &mut tc), (qf, &mut tf)] {
                if let Some(q) = q {
                    match (q.contact, g) {
                        (None, Some(_)) => t.missed += 1,
                        (Some(c), Some(g)) if c > g => t.late += 1,
                        _ => {}
                    }
                }
            }
        }
        if let Some(q) = qc {
            tc.queries.push(q);
        }
        if let Some(q) = qf {
            tf.queries.push(q);
        }
    }
    if run_coarse {
        tc.line("coarse", &coarse);
    }
    if run_fine {
        tf.line("fine", &fine);
    }
    if run_coarse && run_fine {
        println!(
            "coarse / fine: mean {:.2}, p99 {:.2} (times in one run); bunny {} piece leaves",
            tc.mean(|q| q.ms) / tf.mean(|q| q.ms),
            tc.percentile_ms(0.99) / tf.percentile_ms(0.99),
            bunny.piece_leaf_count(),
        );
    }
}
