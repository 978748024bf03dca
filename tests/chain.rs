//! End-to-end checks of chains moving along joint-space segments: against
//! the independent ground truth of `tests/common/chain_truth.rs` (its own
//! forward kinematics, sphere trees and exact triangle distances, dense
//! sampling with a crude speed bound), the URDF loader, and bad input.
//!
//! `CHAIN_SEGMENTS=200 cargo test --release --features urdf --test chain -- --nocapture`
//! runs more segments.

#[path = "common/arm_scene.rs"]
mod arm_scene;
#[path = "common/chain_truth.rs"]
mod chain_truth;
mod common;

use arm_scene::{arm_scene, chain_in_f32, cuboid, random_chain, to32, to64, Arm};
use chain_truth::Truth;
use motion_bound::chain::{
    Chain, ChainBuilder, ChainError, ChainPair, ChainParams, ChainScene, JointKind, JointSpec,
    Obstacle, SegmentOutcome, UrdfOptions,
};
use motion_bound::testkit::toi::Rng;
use motion_bound::{Pose, TriMesh, Vec3};

fn segments() -> usize {
    std::env::var("CHAIN_SEGMENTS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(12)
}

/// What a batch of segments gave against the truth.
#[derive(Debug, Default)]
struct Tally {
    segments: usize,
    colliding: usize,
    contacts: usize,
    missed: usize,
    late: usize,
    far: usize,
}

/// Checks `n` random segments between configurations the truth finds free,
/// within `limits`; returns the tally (and prints every failure).
fn check_against_truth(scene: &ChainScene<f64>, limits: &[[f64; 2]], n: usize, seed: u64) -> Tally {
    let truth = Truth::new(scene);
    let mut rng = Rng::new(seed);
    let mut tally = Tally::default();
    let free = |rng: &mut Rng| loop {
        let q: Vec<f64> = limits.iter().map(|[lo, hi]| rng.range(*lo, *hi)).collect();
        if !truth.touches_at(&q) {
            return q;
        }
    };
    for s in 0..n {
        let q0 = free(&mut rng);
        let q1 = free(&mut rng);
        let report = scene.check_segment(&q0, &q1).expect("valid segment");
        let sampled = truth.sample(&q0, &q1, 1e-4);
        tally.segments += 1;
        if let SegmentOutcome::Contact(c) = report.outcome {
            tally.contacts += 1;
            // Reported within the contact distance (the truth's lower bound).
            let q: Vec<f64> = q0
                .iter()
                .zip(&q1)
                .map(|(a, b)| a + c.time * (b - a))
                .collect();
            let (d, _) = truth.min_distance(&q);
            if d > scene.params().contact_distance * (1.0 + 1e-6) {
                tally.far += 1;
                eprintln!(
                    "segment {s}: contact at {} with the surfaces {d} apart",
                    c.time
                );
            }
        }
        if let Some((t_touch, lower, pair)) = sampled.touch {
            tally.colliding += 1;
            match report.outcome {
                SegmentOutcome::Contact(c) if c.time <= t_touch => {}
                SegmentOutcome::Contact(c) => {
                    tally.late += 1;
                    eprintln!("segment {s}: contact at {} after the truth's touch in [{lower}, {t_touch}] ({pair:?})", c.time);
                }
                other => {
                    tally.missed += 1;
                    eprintln!("segment {s}: {other:?} but the truth touches in [{lower}, {t_touch}] ({pair:?})");
                }
            }
        }
    }
    tally
}

fn limits_of(chain: &Chain<f64>) -> Vec<[f64; 2]> {
    chain
        .limits()
        .into_iter()
        .map(|l| l.unwrap_or([-3.0, 3.0]))
        .collect()
}

/// A random serial chain of `joints` joints of every kind with small box
/// links, and a few boxes and thin poles around it.
fn random_chain_scene(rng: &mut Rng, joints: usize) -> ChainScene<f64> {
    let mut scene = ChainScene::new(random_chain(rng, joints, 0.05));
    for (i, (c, h)) in [
        ([0.45, 0.1, 0.3], [0.05, 0.2, 0.02]),
        ([-0.3, 0.35, 0.4], [0.005, 0.005, 0.5]),
        ([0.1, -0.4, 0.4], [0.005, 0.005, 0.5]),
        ([0.0, 0.0, -0.05], [0.8, 0.8, 0.02]),
    ]
    .into_iter()
    .enumerate()
    {
        let (m, p) = cuboid(c, h, 0.05).expect("box");
        scene.add_obstacle(Obstacle::try_new(format!("o{i}"), m, p).expect("obstacle"));
    }
    scene
}

/// Lemma 13.4 end to end: the Panda in clutter and random chains of every
/// joint kind among boxes and thin poles; no segment on which the truth's
/// surfaces meet is reported free or later than the truth's first meeting
/// sample, and every reported contact is within the contact distance.
#[test]
fn segments_against_sampled_truth_are_never_late_or_missed() {
    let (panda, _) = arm_scene(Arm::Panda).expect("the Panda scene");
    let limits = limits_of(panda.chain());
    let t = check_against_truth(&panda, &limits, segments(), 11);
    eprintln!("panda: {t:?}");
    assert_eq!((t.missed, t.late, t.far), (0, 0, 0), "panda: {t:?}");
    assert!(t.colliding > 0, "the clutter is hit at all: {t:?}");
    let mut rng = Rng::new(5);
    let mut total = Tally::default();
    for k in 0..6 {
        let scene = random_chain_scene(&mut rng, 2 + k % 5);
        let limits = limits_of(scene.chain());
        let t = check_against_truth(&scene, &limits, segments(), 100 + k as u64);
        total.segments += t.segments;
        total.colliding += t.colliding;
        total.contacts += t.contacts;
        total.missed += t.missed;
        total.late += t.late;
        total.far += t.far;
    }
    eprintln!("random chains: {total:?}");
    assert_eq!(
        (total.missed, total.late, total.far),
        (0, 0, 0),
        "random chains: {total:?}"
    );
    assert!(
        total.colliding > 0,
        "random chains hit something: {total:?}"
    );
}

/// The same for an `f32` chain: the Panda's meshes and joints in `f32`
/// against the `f64` truth of the same (converted) scene.
#[test]
fn f32_chain_contacts_are_never_later_than_the_f64_truth() {
    let (panda, _) = arm_scene(Arm::Panda).expect("the Panda scene");
    let chain = panda.chain();
    // The f64 truth of exactly the f32 scene: convert back (exact).
    let (c32, c64) = chain_in_f32(chain);
    let mut s32 = ChainScene::new(c32);
    let mut s64 = ChainScene::new(c64);
    for o in panda.obstacles() {
        let m32 = o.mesh().try_convert::<f32>().expect("f32 obstacle");
        let p32 = to32(&o.pose());
        let m64 = m32.try_convert::<f64>().expect("back");
        let p64 = to64(&p32);
        s32.add_obstacle(Obstacle::try_new(o.name(), m32, p32).expect("obstacle"));
        s64.add_obstacle(Obstacle::try_new(o.name(), m64, p64).expect("obstacle"));
    }
    for a in 0..chain.link_count() {
        for b in a + 1..chain.link_count() {
            if !panda.checks_pair(a, b) {
                s32.allow_collision(a, b);
                s64.allow_collision(a, b);
            }
        }
    }
    let truth = Truth::new(&s64);
    let limits = limits_of(s64.chain());
    let mut rng = Rng::new(23);
    let (mut colliding, mut bad) = (0, 0);
    for _ in 0..segments() {
        let pick = |rng: &mut Rng| -> Vec<f32> {
            loop {
                let q: Vec<f32> = limits
                    .iter()
                    .map(|[lo, hi]| rng.range(*lo, *hi) as f32)
                    .collect();
                let q64: Vec<f64> = q.iter().map(|&x| f64::from(x)).collect();
                if !truth.touches_at(&q64) {
                    return q;
                }
            }
        };
        let (q0, q1) = (pick(&mut rng), pick(&mut rng));
        let report = s32.check_segment(&q0, &q1).expect("segment");
        let q0d: Vec<f64> = q0.iter().map(|&x| f64::from(x)).collect();
        let q1d: Vec<f64> = q1.iter().map(|&x| f64::from(x)).collect();
        if let Some((t_touch, _, _)) = truth.sample(&q0d, &q1d, 1e-4).touch {
            colliding += 1;
            match report.outcome {
                SegmentOutcome::Contact(c) if f64::from(c.time) <= t_touch => {}
                other => {
                    bad += 1;
                    eprintln!("f32: {other:?} against the truth's touch at {t_touch}");
                }
            }
        }
    }
    assert_eq!(
        bad, 0,
        "f32 segments late or missed ({colliding} colliding)"
    );
}

/// A path stops at its first segment with a contact.
#[test]
fn path_query_stops_at_the_first_contact() {
    let mut b = ChainBuilder::new();
    let base = b.add_link("base", None).expect("link");
    let (bar, _) = cuboid([0.0; 3], [0.5, 0.01, 0.01], 0.05).expect("bar");
    let bar = bar.translated([0.5, 0.0, 0.0]).expect("shift");
    let arm = b.add_link("arm", Some(bar)).expect("link");
    b.add_joint(JointSpec {
        name: "j".into(),
        kind: JointKind::Continuous,
        parent: base,
        child: arm,
        origin: Pose::IDENTITY,
        axis: [0.0, 0.0, 1.0],
        limits: None,
    })
    .expect("joint");
    let mut scene = ChainScene::new(b.build().expect("chain"));
    // A thin pole at 90 degrees, 0.6 from the axis.
    let (pole, at) = cuboid([0.0, 0.6, 0.0], [0.005, 0.005, 0.5], 0.05).expect("pole");
    scene.add_obstacle(Obstacle::try_new("pole", pole, at).expect("obstacle"));
    let path = [vec![0.0], vec![1.0], vec![1.4], vec![2.5], vec![3.0]];
    let report = scene.check_path(&path).expect("path");
    // Segment 0 (0 to 1 rad) is free; segment 1 (1 to 1.4) reaches the pole
    // near pi/2 less the half-widths (about 1.5 rad): free too; segment 2
    // crosses it.
    assert_eq!(report.segment, 2, "{report:?}");
    let c = report.outcome.contact().expect("a contact");
    let angle = 1.4 + c.time * 1.1;
    assert!(
        angle < std::f64::consts::FRAC_PI_2 && angle > 1.45,
        "contact at {angle} rad"
    );
    assert_eq!(
        c.pair,
        ChainPair::Obstacle {
            link: arm,
            obstacle: 0
        }
    );
    // A path that never reaches it is separated, reported on its last segment.
    let report = scene
        .check_path(&[vec![0.0], vec![1.0], vec![-2.0]])
        .expect("path");
    assert_eq!(
        (report.segment, report.outcome),
        (1, SegmentOutcome::Separated)
    );
    // The discrete check at 0.11 rad steps over the 1 cm pole (the bar
    // overlaps it over 0.05 rad only).
    let hits = (0..=10).any(|i| {
        scene
            .collides_at(&[1.4 + 1.1 * f64::from(i) / 10.0])
            .expect("q")
    });
    let fine = (0..=2000).any(|i| {
        scene
            .collides_at(&[1.4 + 1.1 * f64::from(i) / 2000.0])
            .expect("q")
    });
    assert!(
        !hits && fine,
        "coarse sampling misses the pole, fine sampling finds it"
    );
}

/// Links hanging from a common ancestor are checked only through the
/// joints below it: two fingers on a turning hand, one sliding into the
/// other, touch when the gap closes, whatever the hand does.
#[test]
fn self_collision_counts_only_the_joints_below_the_common_ancestor() {
    let mut b = ChainBuilder::new();
    let base = b.add_link("base", None).expect("link");
    let hand = b.add_link("hand", None).expect("link");
    let (finger, _) = cuboid([0.0, 0.0, 0.05], [0.01, 0.01, 0.05], 0.05).expect("finger");
    let left = b.add_link("left", Some(finger.clone())).expect("link");
    let right = b.add_link("right", Some(finger)).expect("link");
    let spec = |name: &str, kind, parent, child, x: f64, axis| JointSpec {
        name: name.into(),
        kind,
        parent,
        child,
        origin: Pose::from_translation(Vec3::new(x, 0.0, 0.0)),
        axis,
        limits: Some([-3.0, 3.0]),
    };
    b.add_joint(spec(
        "wrist",
        JointKind::Revolute,
        base,
        hand,
        0.0,
        [1.0, 1.0, 0.0],
    ))
    .expect("joint");
    b.add_joint(spec(
        "l",
        JointKind::Prismatic,
        hand,
        left,
        -0.1,
        [1.0, 0.0, 0.0],
    ))
    .expect("joint");
    b.add_joint(spec(
        "r",
        JointKind::Prismatic,
        hand,
        right,
        0.1,
        [1.0, 0.0, 0.0],
    ))
    .expect("joint");
    let scene = ChainScene::new(b.build().expect("chain"));
    assert!(scene.checks_pair(left, right), "siblings are not adjacent");
    // The left finger slides 0.2 towards the right one (gap 0.18 between
    // faces) while the wrist turns 3 rad: contact at t = 0.9.
    let report = scene
        .check_segment(&[0.0, 0.0, 0.0], &[3.0, 0.2, 0.0])
        .expect("segment");
    let c = report.outcome.contact().expect("fingers meet");
    assert!(c.time <= 0.9 && c.time > 0.85, "contact at {}", c.time);
}

#[test]
fn urdf_arms_load_with_their_joints_and_meshes() {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/..");
    let panda = Chain::<f64>::from_urdf_file(format!("{root}/data/arms/franka_panda/panda.urdf"))
        .expect("panda");
    assert_eq!((panda.dof(), panda.link_count()), (9, 13));
    let kinds = panda.coordinate_kinds();
    assert_eq!(
        kinds.iter().filter(|k| **k == JointKind::Prismatic).count(),
        2
    );
    assert!(panda
        .link_mesh(panda.link_index("panda_link6").expect("link6"))
        .is_some());
    let kuka = Chain::<f64>::from_urdf_file(format!("{root}/data/arms/kuka_iiwa/model.urdf"))
        .expect("kuka");
    assert_eq!((kuka.dof(), kuka.link_count()), (7, 8));
    // STL meshes read: every link has triangles.
    for l in 0..kuka.link_count() {
        assert!(
            kuka.link_mesh(l).is_some_and(|m| m.triangle_count() > 100),
            "link {l}"
        );
    }
    // Forward kinematics at zero: the iiwa stands straight up (its flange
    // about 1.2 above the base).
    let poses = kuka.try_forward_kinematics(&[0.0; 7]).expect("fk");
    let z = poses[7].translation.to_array()[2];
    assert!(z > 1.0 && z < 1.4, "flange height {z}");
}

#[test]
fn urdf_errors_are_typed() {
    let dir = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."));
    let opts = UrdfOptions::default();
    let with_mesh = |file: &str| {
        format!(
            r#"<robot name="r"><link name="a"><collision><geometry><mesh filename="{file}"/></geometry></collision></link></robot>"#
        )
    };
    for (text, what) in [
        (with_mesh("m.dae"), "COLLADA"),
        (with_mesh("m.ply"), "format"),
        (with_mesh("missing.obj"), "missing.obj"),
        ("<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/><joint name=\"j\" type=\"floating\"><parent link=\"a\"/><child link=\"b\"/></joint></robot>".to_string(), "not supported"),
        ("<robot".to_string(), ""),
    ] {
        match Chain::<f64>::from_urdf_str(&text, dir, &opts) {
            Err(ChainError::Urdf(m)) => assert!(m.contains(what), "{m}"),
            other => panic!("{what}: {other:?}"),
        }
    }
    // Two roots are not a tree.
    let two = r#"<robot name="r"><link name="a"/><link name="b"/></robot>"#;
    assert_eq!(
        Chain::<f64>::from_urdf_str(two, dir, &opts).err(),
        Some(ChainError::NotATree)
    );
    // Primitives become meshes that contain them.
    let prims = r#"<robot name="r"><link name="a"><collision><geometry><cylinder radius="0.1" length="0.4"/></geometry></collision>
        <collision><origin xyz="0 0 1"/><geometry><sphere radius="0.2"/></geometry></collision>
        <collision><geometry><box size="0.1 0.2 0.3"/></geometry></collision>
        <collision><geometry><capsule radius="0.05" length="0.3"/></geometry></collision></link></robot>"#;
    let c = Chain::<f64>::from_urdf_str(prims, dir, &opts).expect("primitives");
    let mesh = c.link_mesh(0).expect("merged mesh");
    // Every vertex of the sphere part is at least 0.2 from its centre, and the
    // mesh contains the ball: its face planes are at least 0.2 away (checked
    // through the vertices' distance, which is larger).
    let far = mesh
        .vertices()
        .iter()
        .map(|v| (v[0] * v[0] + v[1] * v[1] + (v[2] - 1.0) * (v[2] - 1.0)).sqrt())
        .filter(|d| *d < 0.5)
        .fold(f64::INFINITY, f64::min);
    assert!(far >= 0.2, "sphere vertices at least the radius out: {far}");
}

#[test]
fn bad_chain_input_is_a_typed_error() {
    let mut b = ChainBuilder::<f64>::new();
    let a = b.add_link("a", None).expect("link");
    let c = b.add_link("c", None).expect("link");
    assert_eq!(
        b.add_link("a", None),
        Err(ChainError::DuplicateName("a".into()))
    );
    let spec = |axis, limits| JointSpec {
        name: "j".into(),
        kind: JointKind::Revolute,
        parent: a,
        child: c,
        origin: Pose::IDENTITY,
        axis,
        limits,
    };
    assert_eq!(
        b.add_joint(spec([0.0; 3], None)),
        Err(ChainError::BadJoint("j".into()))
    );
    assert_eq!(
        b.add_joint(spec([f64::NAN, 0.0, 1.0], None)),
        Err(ChainError::BadJoint("j".into()))
    );
    assert_eq!(
        b.add_joint(spec([0.0, 0.0, 1.0], Some([1.0, -1.0]))),
        Err(ChainError::BadLimits("j".into()))
    );
    assert_eq!(
        b.add_joint(JointSpec {
            child: 7,
            ..spec([0.0, 0.0, 1.0], None)
        }),
        Err(ChainError::NoSuchLink(7))
    );
    b.add_joint(spec([0.0, 0.0, 1.0], None)).expect("joint");
    let chain = b.build().expect("chain");
    let scene = ChainScene::new(chain.clone());
    assert_eq!(
        chain.try_forward_kinematics(&[]).err(),
        Some(ChainError::WrongDof {
            expected: 1,
            got: 0
        })
    );
    for q in [f64::NAN, f64::INFINITY, 1e300] {
        assert_eq!(
            scene.check_segment(&[0.0], &[q]).err(),
            Some(ChainError::NonFiniteCoordinate(0))
        );
    }
    assert!(
        scene.check_path::<Vec<f64>>(&[vec![0.0]]).is_err(),
        "one waypoint"
    );
    let mut s = scene.clone();
    assert!(
        s.set_params(ChainParams::default().with_contact_distance(0.0))
            .is_err(),
        "zero contact distance"
    );
    assert!(
        s.set_params(ChainParams::default().with_contact_distance(f64::NAN))
            .is_err(),
        "NaN contact distance"
    );
    let tet = TriMesh::try_new(
        vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
    )
    .expect("tet");
    let bad_pose = Pose::from_translation(Vec3::new(f64::NAN, 0.0, 0.0));
    assert!(Obstacle::try_new("o", tet, bad_pose).is_err(), "NaN pose");
    // A cycle: a hangs from c and c from a.
    let mut b = ChainBuilder::<f64>::new();
    let a = b.add_link("a", None).expect("link");
    let c = b.add_link("c", None).expect("link");
    let r = b.add_link("r", None).expect("link");
    let _ = r;
    for (name, p, ch) in [("x", a, c), ("y", c, a)] {
        b.add_joint(JointSpec {
            name: name.into(),
            kind: JointKind::Fixed,
            parent: p,
            child: ch,
            origin: Pose::IDENTITY,
            axis: [0.0, 0.0, 1.0],
            limits: None,
        })
        .expect("joint");
    }
    assert_eq!(b.build().err(), Some(ChainError::NotATree));
}

#[test]
fn limits_are_typed_errors_and_segments_stay_within_them() {
    let dir = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."));
    let urdf = |lower: &str| {
        format!(
            r#"<robot name="r"><link name="a"/><link name="b"/><joint name="j" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/><limit lower="{lower}" upper="1" effort="1" velocity="1"/></joint></robot>"#
        )
    };
    let opts = UrdfOptions::default();
    assert_eq!(
        Chain::<f64>::from_urdf_str(&urdf("NaN"), dir, &opts).err(),
        Some(ChainError::BadLimits("j".into())),
        "a NaN limit"
    );
    let chain = Chain::<f64>::from_urdf_str(&urdf("-1"), dir, &opts).expect("a limited joint");
    assert_eq!(chain.limits(), vec![Some([-1.0, 1.0])]);
    let mut scene = ChainScene::new(chain);
    for (q0, q1, beyond) in [
        (-1.0, 1.0, false),
        (0.0, 1.0 + 1e-12, true),
        (-1.5, 0.0, true),
        (0.5, 0.25, false),
    ] {
        let r = scene.check_segment(&[q0], &[q1]);
        if beyond {
            assert_eq!(r.err(), Some(ChainError::BeyondLimits(0)), "{q0} to {q1}");
        } else {
            assert!(r.is_ok(), "{q0} to {q1}: {r:?}");
        }
    }
    assert_eq!(
        scene.check_path(&[vec![0.0], vec![0.5], vec![2.0]]).err(),
        Some(ChainError::BeyondLimits(0)),
        "a waypoint beyond"
    );
    scene
        .set_params(ChainParams::default().with_within_limits(false))
        .expect("params");
    assert!(scene.check_segment(&[0.0], &[2.0]).is_ok(), "the check off");
}
