//! Benchmarks of the scene query: time per frame against the number of
//! bodies, the broad phase's share, and serial against parallel.
//!
//! Every scene is `N` rings (a 384-triangle torus of reach 0.6, one shared
//! tree) tumbling for one frame `[0, 1]` in a cube holding them at a fixed
//! density: **sparse**, one body per `6^3` (neighbours about 6 apart, each
//! moving up to 1 and turning up to 3 rad per frame), and **crowded**, one
//! per `2^3`. At a fixed density the close pairs grow like `N`, all pairs
//! like `N^2`; a table of both is printed first.
//!
//! * `scene_query/{sparse,crowded}/N`: the whole query (broad and narrow).
//! * `scene_broad/{sparse,crowded}/N`: the broad phase alone (swept boxes,
//!   sweep and prune, filter), so its share is the ratio of the two.
//! * `scene_threads/crowded/{serial,parallel}`: the same 1,000-body crowded
//!   frame through `Scene::query` and `Scene::par_query` (all cores).

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkId, Criterion};
use motion_bound::bodies::torus;
use motion_bound::ca::Shape;
use motion_bound::scene::{Scene, SceneParams, SceneWorkspace};
use motion_bound::testkit::toi::Rng;
use motion_bound::{BallTree, RigidMotion, TimeInterval};

const SIZES: [usize; 5] = [10, 30, 100, 300, 1000];

/// The motions of `n` bodies at one body per `spacing^3`.
fn motions(n: usize, spacing: f64, seed: u64) -> Vec<RigidMotion<f64>> {
    let side = spacing * (n as f64).cbrt();
    let mut rng = Rng::new(seed);
    (0..n)
        .map(|_| {
            let x0 = [0, 1, 2].map(|_| rng.range(-side / 2.0, side / 2.0));
            let v = rng.direction().map(|x| x * rng.range(0.0, 1.0));
            let w = rng.direction().map(|x| x * rng.range(0.0, 3.0));
            RigidMotion::try_from_arrays(x0, v, w).expect("finite motion")
        })
        .collect()
}

fn scene<'a>(tree: &'a BallTree<f64>, n: usize, spacing: f64) -> Scene<'a, f64> {
    let mut s = Scene::try_new(TimeInterval::try_new(0.0, 1.0).expect("frame")).expect("scene");
    for m in motions(n, spacing, 0x5CE7E + n as u64) {
        s.try_add(Shape::Mesh(tree), m).expect("body");
    }
    s
}

fn main() {
    let ring = torus::<f64>(0.5, 0.1, 32, 6).expect("ring");
    let tree = BallTree::try_from_mesh(&ring).expect("tree");
    let params = SceneParams::default();
    let densities = [("sparse", 6.0), ("crowded", 2.0)];

    println!("scene: {} triangles per body", tree.triangle_count());
    println!("density  bodies  all pairs  tested  tested %  contacts  iterations/pair");
    for (name, spacing) in densities {
        for n in SIZES {
            let s = scene(&tree, n, spacing);
            let mut ws = SceneWorkspace::new();
            let r = s.query(&mut ws, &params).expect("valid");
            let st = r.stats();
            println!(
                "{name:8} {n:6} {:10} {:7} {:8.3}% {:9} {:16.2}",
                st.pairs_all,
                st.pairs_tested,
                100.0 * st.pairs_tested as f64 / st.pairs_all as f64,
                r.contacts().count(),
                st.iterations as f64 / st.pairs_tested.max(1) as f64,
            );
        }
    }

    let mut c = Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
        .configure_from_args();
    for (name, spacing) in densities {
        let mut g = c.benchmark_group(format!("scene_query/{name}"));
        for n in SIZES {
            let s = scene(&tree, n, spacing);
            let mut ws = SceneWorkspace::new();
            g.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
                b.iter(|| black_box(s.query(&mut ws, &params).expect("valid").pairs().len()));
            });
        }
        g.finish();
        let mut g = c.benchmark_group(format!("scene_broad/{name}"));
        for n in SIZES {
            let s = scene(&tree, n, spacing);
            let mut ws = SceneWorkspace::new();
            g.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
                b.iter(|| {
                    s.broad_phase(&mut ws, &params, |_, _| true).expect("valid");
                    black_box(ws.candidates().count())
                });
            });
        }
        g.finish();
    }
    let s = scene(&tree, 1000, 2.0);
    let mut ws = SceneWorkspace::new();
    let serial = s.query(&mut ws, &params).expect("valid").clone();
    let parallel = s.par_query(&mut ws, &params).expect("valid").clone();
    assert_eq!(serial.pairs(), parallel.pairs(), "identical reports");
    println!(
        "threads: {} pairs, identical serial and parallel reports on {} threads",
        serial.pairs().len(),
        rayon::current_num_threads()
    );
    let mut g = c.benchmark_group("scene_threads/crowded");
    g.bench_function("serial", |b| {
        b.iter(|| black_box(s.query(&mut ws, &params).expect("valid").pairs().len()));
    });
    g.bench_function("parallel", |b| {
        b.iter(|| black_box(s.par_query(&mut ws, &params).expect("valid").pairs().len()));
    });
    g.finish();
    c.final_summary();
}
