//! A closed convex mesh stepped as its hull (`proofs/12-shapes.md`, Lemma
//! 12.9), against sampled ground truth that does not use the hull: the
//! mesh's own triangles and each shape's tessellated core
//! (`common/shape_truth.rs`), the exact triangle distance at 201 times.
//!
//! - Boxes, a thin wall and an icosahedron (outward- and inward-wound)
//!   against seven convex kinds flying in from outside: never late, never
//!   missed, never early (at a reported contact by distance the sampled
//!   bodies are within the contact distance), and the hull decides most
//!   queries alone (no node of the tree visited).
//! - A ball and a cube inside a hollow box (inside the hull): they meet
//!   its walls where the samples say and never before; a solid box is in
//!   contact at the start.
//! - A solid box and icosahedron met by other meshes (a ring, a plate of
//!   two triangles, a solid box) through `AnyPair`, which takes the solid
//!   one as its hull: never late, missed or early.
//! - Open, dented, flipped and two-piece meshes do not take the hull.

#[path = "common/shape_truth.rs"]
mod shape_truth;

use motion_bound::bodies::{cuboid, icosphere, torus};
use motion_bound::ca::{
    time_of_impact, AnyPair, CaOutcome, CaParams, ContactCriterion, MeshConvexPair, Shape,
};
use motion_bound::testkit::toi::Rng;
use motion_bound::{BallTree, Convex, HalfSpace, RigidMotion, TriMesh, Vec3};
use shape_truth::{first_sampled_contact, touch_at, Solid};

/// Ground-truth samples over `[0, 1]`.
const SAMPLES: usize = 200;
/// The queries' contact distance.
const CD: f64 = 1e-3;

/// A box of half-extents `half` about `centre` (`bodies::cuboid`, moved).
fn cuboid_mesh(half: [f64; 3], centre: [f64; 3]) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let b = cuboid::<f64>(half.map(|h| 2.0 * h)).expect("a box");
    let v = b
        .vertices()
        .iter()
        .map(|p| [0, 1, 2].map(|i| p[i] + centre[i]))
        .collect();
    (v, b.triangles().to_vec())
}

/// An icosahedron of circumradius `r` (`bodies::icosphere` undivided).
fn icosahedron(r: f64) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let b = icosphere::<f64>(r, 0).expect("an icosahedron");
    (b.vertices().to_vec(), b.triangles().to_vec())
}

fn mesh((v, t): (Vec<[f64; 3]>, Vec<[u32; 3]>)) -> TriMesh<f64> {
    TriMesh::try_new(v, t).expect("a valid mesh")
}

fn inward(m: &TriMesh<f64>) -> TriMesh<f64> {
    let t = m.triangles().iter().map(|&[a, b, c]| [a, c, b]).collect();
    TriMesh::try_new(m.vertices().to_vec(), t).expect("a valid mesh")
}

/// Whether the sampled bodies are within the contact distance at `t` (a
/// small allowance for the two placements' rounding): the mesh's triangles
/// against the shape's core grown by the contact distance.
fn within_contact_distance(
    m: &Solid,
    ma: &RigidMotion<f64>,
    s: &Solid,
    mb: &RigidMotion<f64>,
    t: f64,
    slack: f64,
) -> bool {
    let grown = Solid {
        parts: s
            .parts
            .iter()
            .map(|(tris, r)| (tris.clone(), r + CD + slack))
            .collect(),
    };
    touch_at(m, ma, &grown, mb, t)
}

/// Never missed, never late against the sampled first contact `truth`, and
/// never early: at a contact by distance the sampled bodies `a` and `b` are
/// within the contact distance (`slack` for a tessellated truth's sagitta).
fn judge(
    outcome: &CaOutcome<f64>,
    truth: Option<f64>,
    a: (&Solid, &RigidMotion<f64>),
    b: (&Solid, &RigidMotion<f64>),
    slack: f64,
    what: &str,
) {
    match (outcome.earliest_possible_contact(), truth) {
        (None, Some(_)) => panic!("MISSED: {what}"),
        (Some(t), Some(g)) => assert!(t <= g, "LATE: {what}"),
        _ => {}
    }
    if let CaOutcome::Contact {
        contact,
        criterion: ContactCriterion::Distance,
    } = *outcome
    {
        assert!(
            within_contact_distance(a.0, a.1, b.0, b.1, contact.time, slack),
            "EARLY: {what}"
        );
    }
}

#[test]
fn closed_convex_meshes_are_stepped_as_their_hulls_never_late_missed_or_early() {
    let mut rng = Rng::new(55);
    let kinds = shape_truth::convex_kinds(&mut rng);
    let outward_box = mesh(cuboid_mesh([0.4, 0.3, 0.5], [0.0; 3]));
    let meshes = [
        ("box", outward_box.clone()),
        ("inward box", inward(&outward_box)),
        ("wall", mesh(cuboid_mesh([0.005, 0.6, 0.6], [0.0; 3]))),
        ("icosahedron", mesh(icosahedron(0.5))),
    ];
    let (mut n, mut contacts, mut sampled, mut hull_alone) = (0, 0, 0, 0);
    for (name, m) in &meshes {
        let tree = BallTree::try_from_mesh(m).expect("tree");
        assert!(tree.is_closed_convex(), "{name} is closed and convex");
        let truth_m = Solid::mesh(m);
        for (kind, shape, truth_s) in &kinds {
            // Rims are inscribed by 16-gons: their samples are only within
            // the polygons' sagitta of the true shape.
            let slack = if kind.contains("cyl") || kind.contains("cone") {
                0.02
            } else {
                1e-9
            };
            for q in 0..3 {
                let start = rng.direction().map(|x| x * rng.range(1.2, 1.6));
                let aim = rng.direction().map(|x| x * 0.3 * rng.unit());
                let v = [0, 1, 2].map(|k| aim[k] - start[k]);
                let spin = [0.0, 3.0, 20.0][q % 3];
                let wa = rng.direction().map(|x| x * spin * 0.25 * rng.unit());
                let wb = rng.direction().map(|x| x * spin * rng.unit());
                let ma = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], wa).expect("motion");
                let mb = RigidMotion::try_from_arrays(start, v, wb).expect("motion");
                let mut pair = MeshConvexPair::new(&tree, *shape);
                assert!(pair.steps_hull());
                let params = CaParams::default().with_contact_distance(CD);
                let report = time_of_impact(&mut pair, &ma, &mb, &params).expect("a query");
                let truth = first_sampled_contact(&truth_m, &ma, truth_s, &mb, (0.0, 1.0), SAMPLES);
                let what = format!("{name} vs {kind} query {q}: {report:?}, sampled {truth:?}");
                judge(
                    &report.outcome,
                    truth,
                    (&truth_m, &ma),
                    (truth_s, &mb),
                    slack,
                    &what,
                );
                contacts += usize::from(report.outcome.contact().is_some());
                sampled += usize::from(truth.is_some());
                hull_alone += usize::from(pair.stats().node_pairs == 0);
                n += 1;
            }
        }
    }
    println!("{n} queries: {contacts} contacts, {sampled} sampled, {hull_alone} by the hull alone");
    assert!(sampled * 2 >= n, "too few sampled contacts for power");
    assert!(
        hull_alone * 4 >= n * 3,
        "the hull decides most queries alone"
    );
}

#[test]
fn bodies_inside_a_hollow_closed_convex_mesh_meet_only_its_walls() {
    let mut rng = Rng::new(56);
    let room = mesh(cuboid_mesh([0.6, 0.5, 0.7], [0.1, 0.0, -0.1]));
    let tree = BallTree::try_from_mesh(&room).expect("tree");
    let solid_room =
        BallTree::try_from_mesh(&room.clone().try_solid().expect("closed")).expect("tree");
    assert!(tree.is_closed_convex() && !tree.is_solid() && solid_room.is_solid());
    let truth_m = Solid::mesh(&room);
    let shapes = [
        (
            "ball",
            Convex::try_ball(0.05).expect("ball"),
            Solid::ball(0.05),
        ),
        (
            "cube",
            Convex::try_cuboid([0.05; 3]).expect("cube"),
            Solid::cuboid([0.05; 3], 0.0),
        ),
    ];
    let (mut n, mut contacts, mut descended) = (0, 0, 0);
    for (kind, shape, truth_s) in &shapes {
        for q in 0..12 {
            let start = rng.direction().map(|x| x * 0.2 * rng.unit());
            let start = [start[0] + 0.1, start[1], start[2] - 0.1];
            // Some stay inside, most reach a wall.
            let speed = [0.3, 1.5, 4.0][q % 3];
            let v = rng.direction().map(|x| x * speed);
            let w = rng.direction().map(|x| x * 20.0 * rng.unit());
            let ma = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0; 3]).expect("still");
            let mb = RigidMotion::try_from_arrays(start, v, w).expect("motion");
            let params = CaParams::default().with_contact_distance(CD);
            let mut pair = MeshConvexPair::new(&tree, *shape);
            let report = time_of_impact(&mut pair, &ma, &mb, &params).expect("a query");
            let truth = first_sampled_contact(&truth_m, &ma, truth_s, &mb, (0.0, 1.0), SAMPLES);
            let what = format!("{kind} inside, query {q}: {report:?}, sampled {truth:?}");
            assert!(
                !matches!(report.outcome, CaOutcome::InitialContact(_)),
                "inside is not a contact: {what}"
            );
            judge(
                &report.outcome,
                truth,
                (&truth_m, &ma),
                (truth_s, &mb),
                1e-9,
                &what,
            );
            contacts += usize::from(report.outcome.contact().is_some());
            descended += usize::from(pair.stats().node_pairs > 0);
            n += 1;
            // The same room declared solid: the body is in it at the start.
            let mut solid = MeshConvexPair::new(&solid_room, *shape);
            let report = time_of_impact(&mut solid, &ma, &mb, &params).expect("a query");
            assert!(
                matches!(report.outcome, CaOutcome::InitialContact(_)),
                "{kind} in a solid room, query {q}: {report:?}"
            );
        }
    }
    println!("{n} queries inside: {contacts} contacts, {descended} descended the tree");
    assert!(contacts >= n / 2, "too few contacts for power");
    assert_eq!(descended, n, "inside the hull, the tree decides");
}

#[test]
fn open_dented_and_two_piece_meshes_do_not_take_the_hull() {
    let (v, t) = cuboid_mesh([0.4, 0.3, 0.5], [0.0; 3]);
    let tree = |v: &[[f64; 3]], t: &[[u32; 3]]| BallTree::try_new(v, t).expect("tree");
    let ball = Convex::try_ball(0.1).expect("ball");
    let closed = tree(&v, &t);
    assert!(closed.is_closed_convex());
    assert!(MeshConvexPair::new(&closed, ball).steps_hull());
    let ground = HalfSpace::try_new(Vec3::new(0.0, 1.0, 0.0)).expect("normal");
    assert!(
        !MeshConvexPair::with_half_space(&closed, ground).steps_hull(),
        "a half-space keeps the tree"
    );
    let open = tree(&v, &t[1..]);
    let mut dented = v.clone();
    dented[7] = [0.1, 0.1, 0.1];
    let dented = tree(&dented, &t);
    let mut flipped = t.clone();
    flipped[0] = [t[0][0], t[0][2], t[0][1]];
    let flipped = tree(&v, &flipped);
    // Two boxes side by side: each closed and convex, not the two.
    let (v2, t2) = cuboid_mesh([0.1; 3], [2.0, 0.0, 0.0]);
    let mut v_two = v.clone();
    v_two.extend(v2);
    let mut t_two = t.clone();
    t_two.extend(t2.iter().map(|tri| tri.map(|i| i + 8)));
    let two = tree(&v_two, &t_two);
    let ring =
        BallTree::try_from_mesh(&torus::<f64>(0.5, 0.12, 12, 6).expect("ring")).expect("tree");
    for (name, tree) in [
        ("open", &open),
        ("dented", &dented),
        ("flipped", &flipped),
        ("two boxes", &two),
        ("ring", &ring),
    ] {
        assert!(!tree.is_closed_convex(), "{name}");
        assert!(!MeshConvexPair::new(tree, ball).steps_hull(), "{name}");
    }
}

#[test]
fn solid_closed_convex_meshes_meet_other_meshes_as_their_hulls() {
    let mut rng = Rng::new(57);
    let solid = |m: TriMesh<f64>| m.try_solid().expect("closed, outward");
    let solids = [
        (
            "solid box",
            solid(mesh(cuboid_mesh([0.3, 0.2, 0.25], [0.0; 3]))),
        ),
        ("solid icosahedron", solid(mesh(icosahedron(0.35)))),
    ];
    let plate = mesh((
        vec![
            [-0.8, 0.0, -0.8],
            [0.8, 0.0, -0.8],
            [0.8, 0.0, 0.8],
            [-0.8, 0.0, 0.8],
        ],
        vec![[0, 1, 2], [0, 2, 3]],
    ));
    let others = [
        ("ring", torus::<f64>(0.5, 0.12, 16, 6).expect("ring")),
        ("plate", plate),
        (
            "solid box",
            solid(mesh(cuboid_mesh([0.2, 0.3, 0.1], [0.0; 3]))),
        ),
    ];
    let (mut n, mut contacts, mut sampled) = (0, 0, 0);
    for (name_a, a) in &solids {
        let tree_a = BallTree::try_from_mesh(a).expect("tree");
        let truth_a = Solid::mesh(a);
        for (name_b, b) in &others {
            let tree_b = BallTree::try_from_mesh(b).expect("tree");
            let truth_b = Solid::mesh(b);
            for q in 0..4 {
                let start = rng.direction().map(|x| x * rng.range(1.3, 1.7));
                let aim = rng.direction().map(|x| x * 0.2 * rng.unit());
                let v = [0, 1, 2].map(|k| aim[k] - start[k]);
                let spin = [0.0, 3.0, 20.0, 8.0][q % 4];
                let wa = rng.direction().map(|x| x * spin * rng.unit());
                let wb = rng.direction().map(|x| x * spin * 0.25 * rng.unit());
                let ma = RigidMotion::try_from_arrays(start, v, wa).expect("motion");
                let mb = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], wb).expect("motion");
                let params = CaParams::default().with_contact_distance(CD);
                // Either order: the solid mesh first or second.
                let (report, truth) = if q % 2 == 0 {
                    let mut pair = AnyPair::try_new(Shape::Mesh(&tree_a), Shape::Mesh(&tree_b))
                        .expect("a pair");
                    let r = time_of_impact(&mut pair, &ma, &mb, &params).expect("a query");
                    (
                        r,
                        first_sampled_contact(&truth_a, &ma, &truth_b, &mb, (0.0, 1.0), SAMPLES),
                    )
                } else {
                    let mut pair = AnyPair::try_new(Shape::Mesh(&tree_b), Shape::Mesh(&tree_a))
                        .expect("a pair");
                    let r = time_of_impact(&mut pair, &mb, &ma, &params).expect("a query");
                    (
                        r,
                        first_sampled_contact(&truth_b, &mb, &truth_a, &ma, (0.0, 1.0), SAMPLES),
                    )
                };
                let what = format!("{name_a} vs {name_b} query {q}: {report:?}, sampled {truth:?}");
                judge(
                    &report.outcome,
                    truth,
                    (&truth_a, &ma),
                    (&truth_b, &mb),
                    1e-9,
                    &what,
                );
                contacts += usize::from(report.outcome.contact().is_some());
                sampled += usize::from(truth.is_some());
                n += 1;
            }
        }
    }
    println!("{n} mesh pairs: {contacts} contacts, {sampled} sampled");
    assert!(sampled * 2 >= n, "too few sampled contacts for power");
}
