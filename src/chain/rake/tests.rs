//! The rake against an independent truth: what it clears is apart at every
//! sampled time and point (`proofs/13-chains.md`, Lemma 13.13), and the
//! sweep it adds is needed: with half of it, the same truth finds pairs
//! cleared that touch.

use alloc::vec::Vec;

use crate::chain::edge::Target;
use crate::chain::{ChainBuilder, ChainScene, JointKind, JointSpec, ShapeObstacle};
use crate::rng::SplitMix64;
use crate::{Convex, Pose, TriMesh, Vec3};

/// A box of half extents `h` centred at `c` as 12 triangles.
fn box_mesh(h: [f64; 3], c: [f64; 3]) -> TriMesh<f64> {
    let mut v = Vec::new();
    for i in 0..8 {
        v.push([0, 1, 2].map(|k| c[k] + if i >> k & 1 == 1 { h[k] } else { -h[k] }));
    }
    let t = [
        [0, 2, 1],
        [1, 2, 3],
        [4, 5, 6],
        [5, 7, 6],
        [0, 1, 4],
        [1, 5, 4],
        [2, 6, 3],
        [3, 6, 7],
        [0, 4, 2],
        [2, 4, 6],
        [1, 3, 5],
        [3, 7, 5],
    ];
    TriMesh::try_new(v, t.to_vec()).expect("a box")
}

/// Points of a mesh: corners and a barycentric grid of `n` per edge.
fn samples(mesh: &TriMesh<f64>, n: u32) -> Vec<Vec3<f64>> {
    let mut out = Vec::new();
    for [a, b, c] in mesh.triangle_corners() {
        for i in 0..=n {
            for j in 0..=(n - i) {
                let (s, u) = (f64::from(i) / f64::from(n), f64::from(j) / f64::from(n));
                out.push(Vec3::from_array(
                    [0, 1, 2].map(|k| a[k] + s * (b[k] - a[k]) + u * (c[k] - a[k])),
                ));
            }
        }
    }
    out
}

/// A shape of the test in closed form: the distance from a world point.
#[derive(Clone, Copy)]
enum Solid {
    Cuboid([f64; 3]),
    Cylinder(f64, f64),
    Capsule(f64, f64),
    Ball(f64),
}

fn distance(solid: Solid, pose: &Pose<f64>, p: Vec3<f64>) -> f64 {
    let y = pose
        .inverse_transform_vector(p - pose.translation)
        .to_array();
    match solid {
        Solid::Cuboid(h) => {
            let e = [0, 1, 2].map(|k| (y[k].abs() - h[k]).max(0.0));
            (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]).sqrt()
        }
        Solid::Cylinder(half, r) => {
            let dx = ((y[0] * y[0] + y[2] * y[2]).sqrt() - r).max(0.0);
            let dy = (y[1].abs() - half).max(0.0);
            (dx * dx + dy * dy).sqrt()
        }
        Solid::Capsule(half, r) => {
            let t = y[1].clamp(-half, half);
            ((y[0] * y[0] + (y[1] - t) * (y[1] - t) + y[2] * y[2]).sqrt() - r).max(0.0)
        }
        Solid::Ball(r) => ((y[0] * y[0] + y[1] * y[1] + y[2] * y[2]).sqrt() - r).max(0.0),
    }
}

struct Case {
    scene: ChainScene<f64>,
    meshes: Vec<Option<Vec<Vec3<f64>>>>,
    solids: Vec<(Solid, Pose<f64>)>,
    edges: Vec<(Vec<f64>, Vec<f64>)>,
}

/// A chain of `joints` bars turning about random axes (one thin bar for
/// `joints == 1`: its lever and cover are tight, so its sweep is nearly the
/// exact one), with shapes placed at points the chain's surface passes
/// through or near (within 4 cm) at the middle of some edges, so that edges
/// graze and touch them.
fn case(rng: &mut SplitMix64, joints: usize) -> Case {
    let mut b = ChainBuilder::new();
    let mut prev = b.add_link("base", None).expect("link");
    let mut meshes = alloc::vec![None];
    let mut offset = 0.0;
    for i in 0..joints {
        let len = rng.range(0.2, 0.45);
        let th = if joints == 1 {
            rng.range(0.002, 0.006)
        } else {
            rng.range(0.02, 0.05)
        };
        let mesh = box_mesh([len / 2.0, th, th], [len / 2.0, 0.0, 0.0]);
        meshes.push(Some(samples(&mesh, 6)));
        let link = b
            .add_link(alloc::format!("l{i}"), Some(mesh))
            .expect("link");
        let axis =
            [[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], rng.direction()][(rng.next_u64() % 3) as usize];
        b.add_joint(JointSpec {
            name: alloc::format!("j{i}"),
            kind: JointKind::Revolute,
            parent: prev,
            child: link,
            origin: Pose::from_translation(Vec3::new(offset, 0.0, 0.0)),
            axis,
            limits: None,
        })
        .expect("joint");
        offset = len;
        prev = link;
    }
    let chain = b.build().expect("chain");
    let mut scene = ChainScene::new(chain);
    // Allow every link pair: this test is about the shapes.
    for a in 0..=joints {
        for c in 0..=joints {
            if a != c {
                scene.allow_collision(a, c);
            }
        }
    }
    let mut solids = Vec::new();
    let mut edges = Vec::new();
    for _ in 0..4 {
        let q: Vec<f64> = (0..joints).map(|_| rng.range(-2.5, 2.5)).collect();
        let poses = scene.chain().try_forward_kinematics(&q).expect("fk");
        let link = 1 + (rng.next_u64() % joints as u64) as usize;
        let pts = meshes[link].as_ref().expect("mesh");
        let p = poses[link].transform_point(pts[(rng.next_u64() as usize) % pts.len()]);
        let out = Vec3::from_array(rng.direction()) * rng.range(-0.01, 0.04);
        let rot =
            crate::chain::model::turn(Vec3::from_array(rng.direction()), rng.range(-3.0, 3.0))
                .rotation;
        let (a, c) = (rng.range(0.02, 0.12), rng.range(0.02, 0.12));
        let (solid, shape) = match rng.next_u64() % 4 {
            0 => (Solid::Cuboid([a, c, a]), Convex::try_cuboid([a, c, a])),
            1 => (Solid::Cylinder(a, c), Convex::try_cylinder(a, c)),
            2 => (Solid::Capsule(a, c), Convex::try_capsule(a, c)),
            _ => (Solid::Ball(c), Convex::try_ball(c)),
        };
        // The shape's surface near the chosen point: its centre pushed back
        // by its extent along the offset.
        let back = out.try_normalize().unwrap_or(Vec3::new(1.0, 0.0, 0.0)) * (a.max(c));
        let pose = Pose {
            rotation: rot,
            translation: p + out + back,
        };
        scene
            .add_shape(ShapeObstacle::try_new("s", shape.expect("shape"), pose).expect("obstacle"));
        solids.push((solid, pose));
        for _ in 0..6 {
            let dq: Vec<f64> = (0..joints).map(|_| rng.range(-0.5, 0.5)).collect();
            let f = rng.range(0.2, 0.8);
            let q0: Vec<f64> = q.iter().zip(&dq).map(|(x, d)| x - f * d).collect();
            let q1: Vec<f64> = q.iter().zip(&dq).map(|(x, d)| x + (1.0 - f) * d).collect();
            edges.push((q0, q1));
        }
    }
    Case {
        scene,
        meshes,
        solids,
        edges,
    }
}

/// The (edge, sub-interval, pair) the rake cleared at `scale` of its sweeps
/// (sub-intervals picked for `sweep` times the scene's sweep) where the
/// truth samples a point of the link within the shape: the number of such,
/// and of cleared pairs checked.
fn violations(scale: f64, sweep: f64, cases: usize) -> (usize, usize) {
    let mut rng = SplitMix64::new(0x5eed_0062);
    let (mut bad, mut checked) = (0, 0);
    for n in 0..cases {
        let c = case(&mut rng, if n % 2 == 0 { 1 } else { 3 });
        let mut checker = c.scene.edge_checker();
        for (q0, q1) in &c.edges {
            let (fails, times, items) = checker
                .rake_only(q0, q1, scale, sweep)
                .expect("the rake applies");
            for (i, it) in items.iter().enumerate() {
                let Target::Shape(s) = it.target else {
                    continue;
                };
                let (solid, pose) = c.solids[s as usize];
                let pts = c.meshes[it.link as usize].as_ref().expect("mesh");
                for lane in 0..times {
                    if fails.iter().any(|f| f.1 == lane && f.2 as usize == i) {
                        continue;
                    }
                    checked += 1;
                    let mut touches = false;
                    for k in 0..=16 {
                        let t = (f64::from(lane) + f64::from(k) / 16.0) / f64::from(times);
                        let q: Vec<f64> = q0.iter().zip(q1).map(|(a, b)| a + t * (b - a)).collect();
                        let poses = c.scene.chain().try_forward_kinematics(&q).expect("fk");
                        let link = &poses[it.link as usize];
                        if pts
                            .iter()
                            .any(|p| distance(solid, &pose, link.transform_point(*p)) <= 0.0)
                        {
                            touches = true;
                            break;
                        }
                    }
                    bad += usize::from(touches);
                }
            }
        }
    }
    (bad, checked)
}

#[test]
fn rake_clears_only_what_the_sampled_truth_finds_apart() {
    // As the queries rake, and with long sub-intervals (wide sweeps).
    for sweep in [1.0, 8.0] {
        let (bad, checked) = violations(1.0, sweep, 40);
        assert!(checked > 1000, "too few cleared pairs checked: {checked}");
        assert_eq!(
            bad, 0,
            "{bad} cleared (sub-interval, pair)s touch, of {checked}"
        );
    }
}

#[test]
fn rake_with_half_its_sweep_clears_pairs_that_touch() {
    // The test above has power: with the sweeps halved the same truth finds
    // cleared pairs that touch.
    // Long sub-intervals, so that the sweep outweighs the covers' excess.
    let (bad, checked) = violations(0.5, 8.0, 40);
    assert!(
        bad > 0,
        "no cleared pair touches with half the sweep ({checked} checked)"
    );
}
