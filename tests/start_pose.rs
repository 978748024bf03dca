//! A body's start pose, end to end: the same queries run through a mesh
//! pre-rotated into the world frame with the identity start orientation,
//! and through the body's own mesh (its tree built once) with its start
//! rotation (and, for a third of them, a rotation centre off the body
//! origin). Both must be never late and never miss against sampled ground
//! truth (`testkit::ground_truth`, which places bodies with its own
//! quaternion code), agree on the outcome, and report times that differ by
//! no more than the time the bodies take to close the contact distance.
//!
//! 1,000 queries by default, in two halves; set `CA_TOI_QUERIES` to run more.

use motion_bound::bodies::TorusKnot;
use motion_bound::ca::{time_of_impact, CaOutcome, CaParams, MeshPair};
use motion_bound::testkit::ground_truth::{first_sampled_contact, place, MeshRef};
use motion_bound::testkit::toi::{fly_by, reach, Rng};
use motion_bound::{BallTree, Isometry, RigidMotion, Rotation, TriMesh, Vec3};

const SAMPLES: usize = 64;

/// A uniformly random unit quaternion (Shoemake).
fn random_rotation(rng: &mut Rng) -> Rotation<f64> {
    let (u1, u2, u3) = (rng.unit(), rng.unit(), rng.unit());
    let tau = core::f64::consts::TAU;
    let (a, b) = ((1.0 - u1).sqrt(), u1.sqrt());
    Rotation::try_from_quaternion(
        b * (tau * u3).cos(),
        a * (tau * u2).sin(),
        a * (tau * u2).cos(),
        b * (tau * u3).sin(),
    )
    .expect("a unit quaternion")
}

/// `mesh` placed by `motion`'s start pose (`x0 = 0`): the pre-rotated copy,
/// each vertex `Q0 (r - c)` computed by the ground truth's own quaternion
/// code (not the crate's matrices).
fn pre_rotated(mesh: &TriMesh<f64>, motion: &RigidMotion<f64>) -> TriMesh<f64> {
    let turn = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0; 3])
        .expect("still")
        .with_orientation(motion.orientation());
    let c = motion.local_centre();
    let vertices = mesh
        .vertices()
        .iter()
        .map(|&r| place(&turn, [r[0] - c.x, r[1] - c.y, r[2] - c.z], 0.0))
        .collect();
    TriMesh::try_new(vertices, mesh.triangles().to_vec()).expect("a rotated valid mesh")
}

// Two halves of the queries (different seeds), so that the two cores share them.
#[test]
fn a_turned_body_and_its_pre_rotated_copy_agree_and_are_never_late_first_half() {
    turned_against_pre_rotated(20_261_201);
}

#[test]
fn a_turned_body_and_its_pre_rotated_copy_agree_and_are_never_late_second_half() {
    turned_against_pre_rotated(20_261_202);
}

/// Half of the queries (500 by default, `CA_TOI_QUERIES / 2`) from `seed`.
fn turned_against_pre_rotated(seed: u64) {
    let knot = TorusKnot::TREFOIL.mesh::<f64>(40, 6).expect("knot");
    let tree = BallTree::try_from_mesh(&knot).expect("tree"); // once, in the body frame
    let r = reach(&knot);
    let cd = 1e-3 * 2.0 * r;
    let params = CaParams::default().with_contact_distance(cd);
    let mut rng = Rng::new(seed);
    let n = std::env::var("CA_TOI_QUERIES")
        .ok()
        .and_then(|s| s.parse::<usize>().ok())
        .unwrap_or(1000)
        / 2;
    let (mut contacts, mut separated, mut worst_ratio) = (0, 0, 0.0f64);
    let mut violations = Vec::new();
    for k in 0..n {
        let q = fly_by(&mut rng, r, r, 6.0);
        let centre = if k % 3 == 0 {
            Vec3::from_array(rng.direction().map(|x| x * 0.3 * r))
        } else {
            Vec3::ZERO
        };
        // The turned bodies: the fly-by's motions with a start orientation
        // (and centre), the rotation centre where the fly-by puts it.
        let turned = |m: &RigidMotion<f64>, rot: Rotation<f64>| {
            let start = Isometry::try_new(rot, m.centre().to_vec3()).expect("finite");
            RigidMotion::try_from_start(start, m.linear(), m.angular(), 1.0)
                .expect("valid")
                .try_with_local_centre(centre)
                .expect("valid")
        };
        let (ra, rb) = (random_rotation(&mut rng), random_rotation(&mut rng));
        let (ma, mb) = (turned(&q.a, ra), turned(&q.b, rb));
        // The pre-rotated copies rotate about their origin: same world motion
        // of the rotation centre, identity start.
        let (ka, kb) = (pre_rotated(&knot, &ma), pre_rotated(&knot, &mb));
        let still = |m: &RigidMotion<f64>| {
            RigidMotion::try_new(m.centre(), m.linear(), m.angular(), m.interval()).expect("valid")
        };
        let (pa, pb) = (still(&ma), still(&mb));
        let (ta, tb) = (
            BallTree::try_from_mesh(&ka).expect("tree"),
            BallTree::try_from_mesh(&kb).expect("tree"),
        );
        let own = time_of_impact(&mut MeshPair::new(&tree, &tree), &ma, &mb, &params).expect("ok");
        let pre = time_of_impact(&mut MeshPair::new(&ta, &tb), &pa, &pb, &params).expect("ok");
        let truth_own = first_sampled_contact(
            MeshRef::from(&knot),
            &ma,
            MeshRef::from(&knot),
            &mb,
            (0.0, 1.0),
            SAMPLES,
        );
        let truth_pre = first_sampled_contact(
            MeshRef::from(&ka),
            &pa,
            MeshRef::from(&kb),
            &pb,
            (0.0, 1.0),
            SAMPLES,
        );
        for (what, report, truth) in [("own", &own, truth_own), ("pre", &pre, truth_pre)] {
            match (report.outcome.earliest_possible_contact(), truth) {
                (None, Some(g)) => violations.push(format!("query {k} {what}: MISSED {g}")),
                (Some(t), Some(g)) if t > g => {
                    violations.push(format!("query {k} {what}: LATE {t} after {g}"))
                }
                _ => {}
            }
        }
        let kind = |o: &CaOutcome<f64>| match o {
            CaOutcome::Separated => 0,
            CaOutcome::IterationLimit { .. } => 2,
            _ => 1,
        };
        if kind(&own.outcome) != kind(&pre.outcome) {
            violations.push(format!(
                "query {k}: outcomes differ: {:?} vs {:?}",
                own.outcome, pre.outcome
            ));
            continue;
        }
        match (own.outcome.contact(), pre.outcome.contact()) {
            (Some(a), Some(b)) => {
                contacts += 1;
                // The time the bodies take to close the contact distance at
                // the rate they approach at the contact: the relative velocity
                // of the witness points along the normal, from the rigid
                // velocity field `v + w x (p - x(t))` of each motion (the
                // first contact's, the earlier of the two).
                let first = if a.time <= b.time {
                    (a, &ma, &mb)
                } else {
                    (b, &pa, &pb)
                };
                let (c, m1, m2) = first;
                let Some(w) = c.witness else {
                    continue;
                };
                let field = |m: &RigidMotion<f64>, p: Vec3<f64>| {
                    let x = m.centre().to_vec3() + m.linear() * c.time;
                    m.linear() + m.angular().cross(p - x)
                };
                let (pa_w, pb_w) = (w.on_a.to_vec3(), w.on_b.to_vec3());
                let Some(normal) = (pb_w - pa_w).try_normalize() else {
                    continue;
                };
                let rate = (field(m1, pa_w) - field(m2, pb_w)).dot(normal);
                if rate <= 0.0 {
                    continue; // not approaching there: no closing time to compare with
                }
                let close = cd / rate;
                let diff = (a.time - b.time).abs();
                worst_ratio = worst_ratio.max(diff / close);
                if diff > close {
                    violations.push(format!(
                        "query {k}: times {} and {} differ by {diff:e}, more than {close:e}",
                        a.time, b.time
                    ));
                }
            }
            _ => separated += 1,
        }
    }
    println!(
        "{n} queries: {contacts} contacts in both, {separated} without, worst time difference {worst_ratio:.3} of the closing time, {} violations",
        violations.len()
    );
    assert!(
        violations.is_empty(),
        "{} violations, first: {}",
        violations.len(),
        violations[0]
    );
    assert!(
        contacts * 2 >= n,
        "too few contacts ({contacts} of {n}) for power"
    );
}
