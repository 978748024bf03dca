//! Ours against parry3d's `cast_shapes_nonlinear` on every pair kind the
//! issue names (capsule-capsule, cuboid-cuboid, ball-mesh, capsule-mesh,
//! cylinder-mesh, mesh-half-space, and a few more), on the same shapes and
//! motions: ms per query and missed / late for both against sampled ground
//! truth (`tests/common/shape_truth.rs`: each shape's core tessellated inside
//! itself, placed by the testkit's own quaternions, exact triangle
//! distances, 65 times over `[0, 1]`).
//!
//! Run with `cargo run --release -p motion-bound-compare --example shapes`
//! (`-- --queries N`, default 100 per pair kind).
//!
//! A query of parry's is MISSED when it reports no impact and the sampling
//! finds a contact, LATE when its time of impact is after the first sampled
//! contact (plus `1e-6`); ours likewise with its first possible contact.

#[path = "../../tests/common/shape_truth.rs"]
mod shape_truth;

use std::time::Instant;

use motion_bound::ca::{time_of_impact, AnyPair, CaParams, Shape};
use motion_bound::testkit::toi::{shape_fly_by, Rng};
use motion_bound::{BallTree, Convex, HalfSpace, Vec3};
use motion_bound_compare::parry::parry_motion;
use motion_bound_devkit::{cpu_name, Args};
use parry3d_f64::math::Vector;
use parry3d_f64::query::cast_shapes_nonlinear;
use parry3d_f64::shape::{
    Ball, Capsule, Cone, Cuboid, Cylinder, HalfSpace as ParryHalfSpace, Shape as ParryShape,
    TriMesh as ParryMesh,
};
use shape_truth::{first_sampled_contact, first_sampled_landing, Solid};

/// Ground-truth samples over `[0, 1]` (65 times).
const SAMPLES: usize = 64;

/// A shape in both libraries, with its ground truth.
struct Both {
    name: &'static str,
    ours: Shape<'static, f64>,
    parry: Box<dyn ParryShape>,
    solid: Solid,
}

fn main() {
    let mut args = Args::from_env("shapes [--queries 100]");
    let queries: usize = args.value_or("--queries", 100);
    args.finish();
    let bunny_mesh = motion_bound_compare::shipped_mesh("bunny-npm-3674.obj.gz");
    let tree: &'static BallTree<f64> = Box::leak(Box::new(
        BallTree::try_from_mesh(&bunny_mesh).expect("tree"),
    ));
    let parry_bunny = ParryMesh::new(
        bunny_mesh
            .vertices()
            .iter()
            .map(|v| Vector::new(v[0], v[1], v[2]))
            .collect(),
        bunny_mesh.triangles().to_vec(),
    )
    .expect("a parry mesh");
    let ball = || Both {
        name: "ball",
        ours: Shape::Convex(Convex::try_ball(0.25).expect("ball")),
        parry: Box::new(Ball::new(0.25)),
        solid: Solid::ball(0.25),
    };
    let capsule = || Both {
        name: "capsule",
        ours: Shape::Convex(Convex::try_capsule(0.3, 0.15).expect("capsule")),
        parry: Box::new(Capsule::new_y(0.3, 0.15)),
        solid: Solid::capsule(0.3, 0.15),
    };
    let cuboid = || Both {
        name: "cuboid",
        ours: Shape::Convex(Convex::try_cuboid([0.3, 0.2, 0.25]).expect("cuboid")),
        parry: Box::new(Cuboid::new(Vector::new(0.3, 0.2, 0.25))),
        solid: Solid::cuboid([0.3, 0.2, 0.25], 0.0),
    };
    let cylinder = || Both {
        name: "cylinder",
        ours: Shape::Convex(Convex::try_cylinder(0.3, 0.2).expect("cylinder")),
        parry: Box::new(Cylinder::new(0.3, 0.2)),
        solid: Solid::cylinder(0.3, 0.2),
    };
    let cone = || Both {
        name: "cone",
        ours: Shape::Convex(Convex::try_cone(0.3, 0.25).expect("cone")),
        parry: Box::new(Cone::new(0.3, 0.25)),
        solid: Solid::cone(0.3, 0.25),
    };
    let mesh = || Both {
        name: "bunny mesh",
        ours: Shape::Mesh(tree),
        parry: Box::new(parry_bunny.clone()),
        solid: Solid::mesh(&bunny_mesh),
    };
    let ground = || Both {
        name: "ground",
        ours: Shape::HalfSpace(HalfSpace::try_new(Vec3::new(0.0, 1.0, 0.0)).expect("ground")),
        parry: Box::new(ParryHalfSpace::new(Vector::new(0.0, 1.0, 0.0))),
        solid: Solid::default(),
    };
    let pairs = [
        (capsule(), capsule()),
        (cuboid(), cuboid()),
        (ball(), mesh()),
        (capsule(), mesh()),
        (cylinder(), mesh()),
        (mesh(), ground()),
        (cylinder(), cylinder()),
        (cone(), cuboid()),
        (cuboid(), ground()),
        (ball(), ground()),
    ];
    let cpu = cpu_name();
    println!("CPU: {cpu}; {queries} fly-bys per pair kind with spins up to 8 rad per unit time, contact distance 1e-3\n");
    println!("| pair | ours ms per query | ours missed / late | parry ms per query | parry missed / late | parry / ours |");
    println!("|---|---|---|---|---|---|");
    let mut rng = Rng::new(2027);
    for (a, b) in &pairs {
        let (mut ours_s, mut parry_s) = (0.0, 0.0);
        let (mut om, mut ol, mut pm, mut pl, mut sampled) = (0, 0, 0, 0, 0);
        let mut unsupported = false;
        for q in 0..queries {
            let ground_b = b.name == "ground";
            let (ma, mb) = shape_fly_by(&mut rng, q, ground_b);
            let params = CaParams::default().with_contact_distance(1e-3);
            let t0 = Instant::now();
            let ours = time_of_impact(
                &mut AnyPair::try_new(a.ours, b.ours).expect("pair"),
                &ma,
                &mb,
                &params,
            )
            .expect("a valid query")
            .outcome
            .earliest_possible_contact();
            ours_s += t0.elapsed().as_secs_f64();
            let t0 = Instant::now();
            let parry = cast_shapes_nonlinear(
                &parry_motion(&ma),
                a.parry.as_ref(),
                &parry_motion(&mb),
                b.parry.as_ref(),
                0.0,
                1.0,
                true,
            )
            .map(|hit| hit.map(|h| h.time_of_impact));
            let Ok(parry) = parry else {
                unsupported = true;
                continue;
            };
            parry_s += t0.elapsed().as_secs_f64();
            let truth = if ground_b {
                first_sampled_landing(&a.solid, &ma, &mb, [0.0, 1.0, 0.0], (0.0, 1.0), SAMPLES)
            } else {
                first_sampled_contact(&a.solid, &ma, &b.solid, &mb, (0.0, 1.0), SAMPLES)
            };
            if let Some(g) = truth {
                sampled += 1;
                match ours {
                    None => om += 1,
                    Some(t) if t > g + 1e-6 => ol += 1,
                    _ => {}
                }
                match parry {
                    None => pm += 1,
                    Some(t) if t > g + 1e-6 => pl += 1,
                    _ => {}
                }
            }
        }
        let n = queries as f64;
        if unsupported {
            println!(
                "| {} - {} | {:.4} | {om} / {ol} | unsupported by parry | | |",
                a.name,
                b.name,
                ours_s * 1e3 / n
            );
            continue;
        }
        println!(
            "| {} - {} ({sampled} sampled contacts) | {:.4} | {om} / {ol} | {:.4} | {pm} / {pl} | {:.1}x |",
            a.name,
            b.name,
            ours_s * 1e3 / n,
            parry_s * 1e3 / n,
            parry_s / ours_s
        );
    }
}
