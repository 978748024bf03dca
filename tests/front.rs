//! The front carried from step to step (`proofs/09-ca-toi.md`, Lemma 9.9)
//! gives the outcomes of the descent from the roots: the same contacts and
//! separations, contact times within a small fraction of the interval, the
//! witness the closest triangle pair (a brute force over every pair, the
//! bodies placed by the testkit's own quaternions).
//! Pairs are reused across queries, so a front left by one query must not
//! leak into the next.

use motion_bound::bodies::{board, icosphere, torus};
use motion_bound::ca::{time_of_impact, CaOutcome, CaParams, MeshPair, MeshParams};
use motion_bound::testkit::ground_truth::place;
use motion_bound::testkit::toi::{fly_by, reach, Rng};
use motion_bound::{try_triangle_triangle, BallTree, Point3, RigidMotion, TriMesh};

/// The least distance over every triangle pair, the bodies placed at `t`.
fn brute_force(
    a: &TriMesh<f64>,
    ma: &RigidMotion<f64>,
    b: &TriMesh<f64>,
    mb: &RigidMotion<f64>,
    t: f64,
) -> f64 {
    let placed = |m: &TriMesh<f64>, motion: &RigidMotion<f64>| -> Vec<[Point3<f64>; 3]> {
        let v: Vec<Point3<f64>> = m
            .vertices()
            .iter()
            .map(|&r| Point3::from_array(place(motion, r, t)))
            .collect();
        m.triangles()
            .iter()
            .map(|tri| tri.map(|i| v[i as usize]))
            .collect()
    };
    let (ta, tb) = (placed(a, ma), placed(b, mb));
    let mut least = f64::INFINITY;
    for x in &ta {
        for y in &tb {
            least = least.min(try_triangle_triangle(x, y).expect("finite").distance);
        }
    }
    least
}

/// What one query ended with: kind (0 contact, 1 initial contact, 2
/// separated, 3 other), time, witness distance.
fn summary(outcome: &CaOutcome<f64>) -> (u8, f64, Option<f64>) {
    match outcome {
        CaOutcome::Contact { contact, .. } => {
            (0, contact.time, contact.witness.map(|w| w.distance))
        }
        CaOutcome::InitialContact(contact) => {
            (1, contact.time, contact.witness.map(|w| w.distance))
        }
        CaOutcome::Separated => (2, 1.0, None),
        _ => (3, 0.0, None),
    }
}

/// `n` fly-bys of `a` past `b` spinning up to `spin` rad per unit time,
/// each run with the front carried (one pair reused for every query) and
/// from the roots (a new pair per query).
fn compare(scene: &str, a: &TriMesh<f64>, b: &TriMesh<f64>, spin: f64, n: usize) {
    let (ta, tb) = (
        BallTree::try_from_mesh(a).expect("tree"),
        BallTree::try_from_mesh(b).expect("tree"),
    );
    let (ra, rb) = (reach(a), reach(b));
    let cd = 1e-2 * (ra + rb);
    let params = CaParams::default().with_contact_distance(cd);
    let front = MeshParams::default().with_carry_front(true);
    let roots = MeshParams::default().with_carry_front(false);
    let tol = 1e-12 * (ra + rb);
    let mut carried = MeshPair::new(&ta, &tb)
        .try_with_params(front)
        .expect("knobs");
    let mut rng = Rng::new(20_261_203);
    let (mut contacts, mut worst_dt) = (0, 0.0f64);
    let (mut pairs_front, mut pairs_roots) = (0u64, 0u64);
    for q in 0..n {
        let f = fly_by(&mut rng, ra, rb, spin);
        let with_front = time_of_impact(&mut carried, &f.a, &f.b, &params).expect("valid");
        let mut fresh = MeshPair::new(&ta, &tb)
            .try_with_params(roots)
            .expect("knobs");
        let from_roots = time_of_impact(&mut fresh, &f.a, &f.b, &params).expect("valid");
        pairs_front += with_front.work.node_pairs;
        pairs_roots += from_roots.work.node_pairs;
        let (x, y) = (summary(&with_front.outcome), summary(&from_roots.outcome));
        assert!(x.0 < 3 && y.0 < 3, "{scene} {q}: undecided {x:?} {y:?}");
        assert_eq!(x.0, y.0, "{scene} {q}: front {x:?}, roots {y:?}");
        if x.0 == 0 {
            contacts += 1;
            let dt = (x.1 - y.1).abs();
            worst_dt = worst_dt.max(dt);
            // Both stop where the bodies are between the clearance and the
            // contact distance apart: a band of about 1e-2 here.
            assert!(dt <= 1e-2, "{scene} {q}: contact times {} and {}", x.1, y.1);
            // The front's witness is the closest pair at its time.
            let least = brute_force(a, &f.a, b, &f.b, x.1);
            let w = x.2.expect("a witness");
            assert!(
                w <= cd && (w - least).abs() <= tol,
                "{scene} {q}: witness {w}, least {least}"
            );
        }
    }
    println!(
        "{scene}: {n} queries, {contacts} contacts, contact times within {worst_dt:.2e}, node pairs {pairs_front} carried against {pairs_roots} from the roots"
    );
    assert!(contacts >= n / 4, "{scene}: too few contacts ({contacts})");
    // The front is used: steps took pairs over from it, and kept most of
    // them without measuring them anew (whether that is cheaper depends on
    // the meshes: `docs/performance.md`).
    let s = carried.stats();
    assert!(
        s.carried > 0 && s.refreshed < s.carried,
        "{scene}: the front was not used ({} carried, {} measured anew)",
        s.carried,
        s.refreshed
    );
}

#[test]
fn the_front_gives_the_outcomes_of_the_roots_ring_against_ring() {
    let ring = torus::<f64>(0.5, 0.1, 16, 8).expect("ring");
    compare("ring vs ring", &ring, &ring, 6.0, 60);
}

#[test]
fn the_front_gives_the_outcomes_of_the_roots_board_against_sphere() {
    compare(
        "board (pieces) vs sphere",
        &board::<f64>(1.0, 1.0, 0.01).expect("board"),
        &icosphere::<f64>(0.3, 3).expect("sphere"),
        6.0,
        60,
    );
}

/// Fast spins: many steps per query, the driver's balls about the rotation
/// centres often stepping past the front's deadlines.
#[test]
fn the_front_gives_the_outcomes_of_the_roots_fast_spins() {
    compare(
        "ring vs sphere, 60 rad",
        &torus::<f64>(0.5, 0.12, 16, 8).expect("ring"),
        &icosphere::<f64>(0.4, 2).expect("sphere"),
        60.0,
        40,
    );
}

/// A mesh against convex shapes (`MeshConvexPair`): the same outcomes with
/// the front as from the roots, contact times within the band between the
/// clearance and the contact distance, at 6 and 200 rad.
#[test]
fn the_front_gives_the_outcomes_of_the_roots_mesh_against_convex() {
    use motion_bound::ca::MeshConvexPair;
    use motion_bound::Convex;
    let ring = torus::<f64>(0.5, 0.12, 24, 8).expect("ring");
    let tree = BallTree::try_from_mesh(&ring).expect("tree");
    let shapes = [
        Convex::try_cylinder(0.2, 0.1).expect("cylinder"),
        Convex::try_cuboid([0.2, 0.1, 0.15]).expect("box"),
        Convex::try_cone(0.2, 0.12).expect("cone"),
    ];
    let ra = reach(&ring);
    let rb = 0.3;
    let params = CaParams::default().with_contact_distance(1e-2 * (ra + rb));
    let mut rng = Rng::new(20_261_204);
    let (mut contacts, mut carried, mut refreshed) = (0, 0, 0);
    for (k, shape) in shapes.iter().enumerate() {
        let mut with_front = MeshConvexPair::new(&tree, *shape);
        for q in 0..40 {
            let spin = if q % 2 == 0 { 6.0 } else { 200.0 };
            let f = fly_by(&mut rng, ra, rb, spin);
            let x = time_of_impact(&mut with_front, &f.a, &f.b, &params).expect("valid");
            let mut roots = MeshConvexPair::new(&tree, *shape).with_carry_front(false);
            let y = time_of_impact(&mut roots, &f.a, &f.b, &params).expect("valid");
            let (x, y) = (summary(&x.outcome), summary(&y.outcome));
            assert!(x.0 < 3 && y.0 < 3, "shape {k}, {q}: undecided {x:?} {y:?}");
            assert_eq!(x.0, y.0, "shape {k}, {q}: front {x:?}, roots {y:?}");
            if x.0 == 0 {
                contacts += 1;
                assert!(
                    (x.1 - y.1).abs() <= 1e-2,
                    "shape {k}, {q}: contact times {} and {}",
                    x.1,
                    y.1
                );
            }
        }
        carried += with_front.stats().carried;
        refreshed += with_front.stats().refreshed;
    }
    println!(
        "mesh vs convex: {contacts} contacts, {carried} pairs carried, {refreshed} measured anew"
    );
    assert!(contacts >= 30, "too few contacts ({contacts})");
    assert!(
        carried > 0 && refreshed < carried,
        "the front was not used ({carried} carried, {refreshed} measured anew)"
    );
}
