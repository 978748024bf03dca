//! The robot-arm scene of `examples/arm.rs` and `tests/chain.rs`: an arm
//! from `data/arms/` in clutter (a table under its base, a shelf with two
//! boards and side walls, a box and three thin poles), with its SRDF's
//! disabled pairs.

#![allow(dead_code, unreachable_pub)]

use motion_bound::chain::{Chain, ChainBuilder, ChainScene, JointKind, JointSpec, Obstacle};
use motion_bound::testkit::toi::Rng;
use motion_bound::{Pose, TriMesh, Vec3};

/// An obstacle: its name, mesh and pose.
pub type Item = (&'static str, TriMesh<f64>, Pose<f64>);
type Error = Box<dyn std::error::Error>;
/// Two links' indices.
pub type LinkPair = (usize, usize);

/// Which arm.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Arm {
    /// Franka Emika Panda (seven joints and two fingers).
    Panda,
    /// KUKA LBR iiwa (seven joints).
    Kuka,
}

/// A box of half-extents `h` centred at `c`, each face a grid of squares
/// at most `cell` wide (two triangles each): collision meshes of obstacles
/// are made of triangles of about the robot's own size.
pub fn cuboid(
    c: [f64; 3],
    h: [f64; 3],
    cell: f64,
) -> Result<(TriMesh<f64>, Pose<f64>), Box<dyn std::error::Error>> {
    let mut v: Vec<[f64; 3]> = Vec::new();
    let mut t: Vec<[u32; 3]> = Vec::new();
    // Each face: fixed axis `k` at side `s`, spanned by axes `u` and `w`.
    for k in 0..3 {
        for s in [-1.0, 1.0] {
            let (u, w) = ((k + 1) % 3, (k + 2) % 3);
            let nu = (2.0 * h[u] / cell).ceil().max(1.0) as u32;
            let nw = (2.0 * h[w] / cell).ceil().max(1.0) as u32;
            let base = v.len() as u32;
            for i in 0..=nu {
                for j in 0..=nw {
                    let mut p = [0.0; 3];
                    p[k] = s * h[k];
                    p[u] = -h[u] + 2.0 * h[u] * f64::from(i) / f64::from(nu);
                    p[w] = -h[w] + 2.0 * h[w] * f64::from(j) / f64::from(nw);
                    v.push(p);
                }
            }
            let at = |i: u32, j: u32| base + i * (nw + 1) + j;
            for i in 0..nu {
                for j in 0..nw {
                    let (a, b, c2, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
                    // Outward for s = +1 (u x w = +k); flipped for s = -1.
                    if s > 0.0 {
                        t.push([a, b, c2]);
                        t.push([a, c2, d]);
                    } else {
                        t.push([a, c2, b]);
                        t.push([a, d, c2]);
                    }
                }
            }
        }
    }
    Ok((
        TriMesh::try_new(v, t)?,
        Pose::from_translation(Vec3::from_array(c)),
    ))
}

/// The Panda's pairs of links that MoveIt never checks, from Franka Emika's
/// MoveIt configuration (`franka_ros`, `franka_moveit_config/config/franka_emika.srdf`,
/// Apache-2.0; its `disable_collisions` entries, Adjacent, Default and Never).
pub const PANDA_SRDF_DISABLED: [(&str, &str); 36] = [
    ("hand", "leftfinger"),
    ("hand", "link3"),
    ("hand", "link4"),
    ("hand", "link5"),
    ("hand", "link6"),
    ("hand", "link7"),
    ("hand", "rightfinger"),
    ("leftfinger", "link3"),
    ("leftfinger", "link4"),
    ("leftfinger", "link6"),
    ("leftfinger", "link7"),
    ("leftfinger", "rightfinger"),
    ("link0", "link1"),
    ("link0", "link2"),
    ("link0", "link3"),
    ("link0", "link4"),
    ("link1", "link2"),
    ("link1", "link3"),
    ("link1", "link4"),
    ("link2", "link3"),
    ("link2", "link4"),
    ("link2", "link6"),
    ("link3", "link4"),
    ("link3", "link5"),
    ("link3", "link6"),
    ("link3", "link7"),
    ("link3", "rightfinger"),
    ("link4", "link5"),
    ("link4", "link6"),
    ("link4", "link7"),
    ("link4", "rightfinger"),
    ("link5", "link6"),
    ("link5", "link7"),
    ("link6", "link7"),
    ("link6", "rightfinger"),
    ("link7", "rightfinger"),
];

/// The clutter: a table under the base, a shelf with two boards and side
/// walls in front, a box on the table and three thin poles (1 cm square).
pub fn clutter() -> Result<Vec<Item>, Error> {
    let items: [(&str, [f64; 3], [f64; 3]); 9] = [
        ("table", [0.2, 0.0, -0.045], [0.7, 0.7, 0.025]),
        ("shelf low", [0.6, 0.0, 0.3], [0.12, 0.3, 0.01]),
        ("shelf high", [0.6, 0.0, 0.6], [0.12, 0.3, 0.01]),
        ("shelf left", [0.6, 0.31, 0.45], [0.12, 0.01, 0.45]),
        ("shelf right", [0.6, -0.31, 0.45], [0.12, 0.01, 0.45]),
        ("box", [-0.1, 0.5, 0.05], [0.07, 0.07, 0.07]),
        ("pole a", [-0.3, 0.35, 0.6], [0.005, 0.005, 0.6]),
        ("pole b", [0.2, -0.45, 0.6], [0.005, 0.005, 0.6]),
        ("pole c", [-0.4, -0.3, 0.6], [0.005, 0.005, 0.6]),
    ];
    items
        .iter()
        .map(|&(name, c, h)| {
            let (m, p) = cuboid(c, h, 0.04)?;
            Ok((name, m, p))
        })
        .collect()
}

/// The arm alone (no obstacles), with the SRDF's disabled pairs (the
/// Panda's) and the pairs touching at its ready pose disabled; and those
/// last pairs.
pub fn bare_arm_scene(arm: Arm) -> Result<(ChainScene<f64>, Vec<LinkPair>), Error> {
    let (path, ready) = arm_file(arm);
    let chain = Chain::<f64>::from_urdf_file(format!(
        "{}/{path}",
        concat!(env!("CARGO_MANIFEST_DIR"), "/..")
    ))?;
    let mut scene = ChainScene::new(chain);
    if arm == Arm::Panda {
        for (a, b) in PANDA_SRDF_DISABLED {
            let a = scene.chain().link_index(&format!("panda_{a}"))?;
            let b = scene.chain().link_index(&format!("panda_{b}"))?;
            scene.allow_collision(a, b);
        }
    }
    let defaults = scene.allow_collisions_at(&ready, 0.0)?;
    Ok((scene, defaults))
}

/// The arm's URDF (from the repository's root) and its ready pose.
fn arm_file(arm: Arm) -> (&'static str, Vec<f64>) {
    match arm {
        Arm::Panda => (
            "data/arms/franka_panda/panda.urdf",
            vec![0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785, 0.02, 0.02],
        ),
        Arm::Kuka => (
            "data/arms/kuka_iiwa/model.urdf",
            vec![0.0, 0.5, 0.0, -1.2, 0.0, 0.8, 0.0],
        ),
    }
}

/// The arm in the clutter, with the SRDF's disabled pairs (the Panda's) and
/// the pairs touching at its ready pose disabled; and those last pairs.
pub fn arm_scene(arm: Arm) -> Result<(ChainScene<f64>, Vec<LinkPair>), Error> {
    // The pairs allowed at the ready pose are link pairs: the same with or
    // without the clutter.
    let (mut scene, defaults) = bare_arm_scene(arm)?;
    for (name, mesh, pose) in clutter()? {
        scene.add_obstacle(Obstacle::try_new(name, mesh, pose)?);
    }
    Ok((scene, defaults))
}

/// The Panda's finger opening on a planner's edges (both fingers; VAMP's
/// model holds them fixed).
pub const PANDA_FINGERS: f64 = 0.04;

/// Each joint's limits, `[-pi, pi]` for a joint without.
pub fn joint_limits(chain: &Chain<f64>) -> Vec<[f64; 2]> {
    chain
        .limits()
        .into_iter()
        .map(|l| l.unwrap_or([-std::f64::consts::PI, std::f64::consts::PI]))
        .collect()
}

/// A random planner's edge for the Panda: the seven arm joints uniform
/// within `limits`, moved 0.05 to 0.3 rad along a random direction (drawn
/// again until the far end is within the limits), the fingers held open.
/// `range(lo, hi)` draws uniformly from `[lo, hi)`.
pub fn panda_edge(
    range: &mut impl FnMut(f64, f64) -> f64,
    limits: &[[f64; 2]],
) -> (Vec<f64>, Vec<f64>) {
    loop {
        let q0: Vec<f64> = limits[..7].iter().map(|&[lo, hi]| range(lo, hi)).collect();
        let d: Vec<f64> = (0..7).map(|_| range(-1.0, 1.0)).collect();
        let n = d.iter().map(|x| x * x).sum::<f64>().sqrt();
        if !(n > 0.1 && n <= 1.0) {
            continue;
        }
        let len = range(0.05, 0.3);
        let q1: Vec<f64> = q0.iter().zip(&d).map(|(a, x)| a + x / n * len).collect();
        if q1
            .iter()
            .zip(limits)
            .all(|(x, [lo, hi])| x >= lo && x <= hi)
        {
            let full = |q: Vec<f64>| {
                q.into_iter()
                    .chain([PANDA_FINGERS, PANDA_FINGERS])
                    .collect()
            };
            return (full(q0), full(q1));
        }
    }
}

/// A random serial chain of `joints` joints of every kind (revolute,
/// continuous, prismatic, fixed; random axes and origins) with box links
/// (faces in squares at most `cell` wide), as in `tests/chain.rs`.
pub fn random_chain(rng: &mut Rng, joints: usize, cell: f64) -> Chain<f64> {
    let mut b = ChainBuilder::new();
    let mut parent = b.add_link("base", None).expect("link");
    for j in 0..joints {
        let half = [
            rng.range(0.02, 0.06),
            rng.range(0.02, 0.06),
            rng.range(0.08, 0.2),
        ];
        let (mesh, _) = cuboid([0.0; 3], half, cell).expect("box");
        let mesh = mesh.translated([0.0, 0.0, half[2]]).expect("shift");
        let child = b.add_link(format!("link{j}"), Some(mesh)).expect("link");
        let kind = match j % 4 {
            0 | 3 => JointKind::Revolute,
            1 => JointKind::Continuous,
            _ => {
                if rng.unit() < 0.5 {
                    JointKind::Prismatic
                } else {
                    JointKind::Fixed
                }
            }
        };
        let axis = [
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
        ];
        let turn = motion_bound::Rotation::try_from_axis_angle(
            Vec3::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), 1.0),
            rng.range(-0.5, 0.5),
        )
        .expect("rotation");
        let limits = match kind {
            JointKind::Prismatic => Some([0.0, 0.15]),
            JointKind::Continuous => None,
            _ => Some([-2.5, 2.5]),
        };
        b.add_joint(JointSpec {
            name: format!("j{j}"),
            kind,
            parent,
            child,
            origin: Pose::new(
                turn.matrix(),
                Vec3::new(0.0, 0.0, if j == 0 { 0.05 } else { 0.25 }),
            ),
            axis,
            limits,
        })
        .expect("joint");
        parent = child;
    }
    b.build().expect("chain")
}

/// A pose rounded to `f32`.
pub fn to32(p: &Pose<f64>) -> Pose<f32> {
    Pose::new(
        p.rotation.map(|r| r.map(|x| x as f32)),
        Vec3::from_array(p.translation.to_array().map(|x| x as f32)),
    )
}

/// An `f32` pose in `f64` (exact).
pub fn to64(p: &Pose<f32>) -> Pose<f64> {
    Pose::new(
        p.rotation.map(|r| r.map(f64::from)),
        Vec3::from_array(p.translation.to_array().map(f64::from)),
    )
}

/// The chain in `f32`, and the `f64` chain of exactly its numbers.
pub fn chain_in_f32(chain: &Chain<f64>) -> (Chain<f32>, Chain<f64>) {
    let mut b32 = ChainBuilder::<f32>::new();
    for l in 0..chain.link_count() {
        let mesh = chain
            .link_mesh(l)
            .map(|m| m.try_convert::<f32>().expect("f32 mesh"));
        b32.add_link(chain.link_name(l).expect("name"), mesh)
            .expect("link");
    }
    for j in chain.joints() {
        b32.add_joint(JointSpec {
            name: j.name.clone(),
            kind: j.kind,
            parent: j.parent,
            child: j.child,
            origin: to32(&j.origin),
            axis: j.axis.map(|x| x as f32),
            limits: j.limits.map(|l| l.map(|x| x as f32)),
        })
        .expect("joint");
    }
    let c32 = b32.build().expect("f32 chain");
    let mut b64 = ChainBuilder::<f64>::new();
    for l in 0..c32.link_count() {
        let mesh = c32
            .link_mesh(l)
            .map(|m| m.try_convert::<f64>().expect("f64 mesh"));
        b64.add_link(c32.link_name(l).expect("name"), mesh)
            .expect("link");
    }
    for j in c32.joints() {
        b64.add_joint(JointSpec {
            name: j.name.clone(),
            kind: j.kind,
            parent: j.parent,
            child: j.child,
            origin: to64(&j.origin),
            axis: j.axis.map(f64::from),
            limits: j.limits.map(|l| l.map(f64::from)),
        })
        .expect("joint");
    }
    (c32, b64.build().expect("f64 chain"))
}

/// Where the 20 thin poles of `examples/narrow_passage.rs` and
/// `examples/planner_edges.rs` stand: `(x, y)` on the floor, 0.3 to 0.8 m
/// from the base's axis, at least 10 cm apart, drawn from `rng`.
pub fn pole_sites(rng: &mut Rng) -> Vec<[f64; 2]> {
    let mut placed: Vec<[f64; 2]> = Vec::new();
    while placed.len() < 20 {
        let (r, a) = (rng.range(0.3, 0.8), rng.range(-3.1, 3.1));
        let p = [r * a.cos(), r * a.sin()];
        if placed
            .iter()
            .any(|q| (q[0] - p[0]).hypot(q[1] - p[1]) < 0.1)
        {
            continue;
        }
        placed.push(p);
    }
    placed
}
