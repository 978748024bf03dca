//! Time of impact per pair kind: capsule-capsule, cuboid-cuboid,
//! ball-mesh, capsule-mesh, cylinder-mesh, mesh-half-space (the shipped
//! bunny, 3,674 triangles, reach 0.5), each over the same 30 seeded fly-bys
//! (spins up to 8 rad per unit time, contact distance `1e-3`) through
//! `AnyPair`. `shapes/<pair>` is the time of the 30 queries: divide by 30
//! for one. `cargo run --release -p motion-bound-compare --example shapes`
//! puts parry3d's `cast_shapes_nonlinear` beside the same kinds, with ground
//! truth.

#[path = "../tests/common/meshes.rs"]
mod meshes;

use std::hint::black_box;
use std::time::Duration;

use criterion::Criterion;
use motion_bound::ca::{time_of_impact, AnyPair, CaParams, Shape};
use motion_bound::testkit::toi::{shape_fly_by, Rng};
use motion_bound::{BallTree, Convex, HalfSpace, RigidMotion, Vec3};

/// Queries per pair kind.
const QUERIES: usize = 30;

/// `QUERIES` fly-bys of A past B (or A falling on B, a ground).
fn fly_bys(seed: u64, ground: bool) -> Vec<(RigidMotion<f64>, RigidMotion<f64>)> {
    let mut rng = Rng::new(seed);
    (0..QUERIES)
        .map(|q| shape_fly_by(&mut rng, q, ground))
        .collect()
}

fn main() {
    let mut c = Criterion::default()
        .configure_from_args()
        .sample_size(20)
        .measurement_time(Duration::from_secs(3));
    let bunny = {
        let m = meshes::load_shipped("bunny-npm-3674.obj.gz");
        let (centre, r) = m.bounding_sphere();
        m.recentred(centre)
            .and_then(|m| m.scaled(0.5 / r))
            .expect("bunny")
    };
    let tree = BallTree::try_from_mesh(&bunny).expect("tree");
    let convex = |s: Result<Convex<'static, f64>, _>| Shape::Convex(s.expect("a valid shape"));
    let ground = Shape::HalfSpace(HalfSpace::try_new(Vec3::new(0.0, 1.0, 0.0)).expect("ground"));
    let pairs: [(&str, Shape<'_, f64>, Shape<'_, f64>); 6] = [
        (
            "capsule-capsule",
            convex(Convex::try_capsule(0.3, 0.15)),
            convex(Convex::try_capsule(0.3, 0.15)),
        ),
        (
            "cuboid-cuboid",
            convex(Convex::try_cuboid([0.3, 0.2, 0.25])),
            convex(Convex::try_cuboid([0.3, 0.2, 0.25])),
        ),
        (
            "ball-mesh",
            convex(Convex::try_ball(0.25)),
            Shape::Mesh(&tree),
        ),
        (
            "capsule-mesh",
            convex(Convex::try_capsule(0.3, 0.15)),
            Shape::Mesh(&tree),
        ),
        (
            "cylinder-mesh",
            convex(Convex::try_cylinder(0.3, 0.2)),
            Shape::Mesh(&tree),
        ),
        ("mesh-half-space", Shape::Mesh(&tree), ground),
    ];
    let params = CaParams::default().with_contact_distance(1e-3);
    let mut g = c.benchmark_group("shapes");
    for (k, (name, a, b)) in pairs.iter().enumerate() {
        let queries = fly_bys(2027 + k as u64, matches!(b, Shape::HalfSpace(_)));
        g.bench_function(*name, |bench| {
            bench.iter(|| {
                let mut hits = 0;
                for (ma, mb) in &queries {
                    let r = time_of_impact(
                        &mut AnyPair::try_new(*a, *b).expect("pair"),
                        ma,
                        mb,
                        &params,
                    )
                    .expect("valid");
                    hits += usize::from(r.outcome.contact().is_some());
                }
                black_box(hits)
            });
        });
    }
    g.finish();
    c.final_summary();
}
