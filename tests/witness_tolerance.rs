//! `CaParams::witness_tolerance`: the search for the closest pair may stop
//! once every pair left is certified no closer than the witness less the
//! tolerance (`proofs/09-ca-toi.md`, Lemma 9.6, item "tolerance"). Checked
//! against a brute force over every triangle pair that shares no code with
//! the crate's triangle distance (GJK on each pair as two polytopes, its
//! certified lower bound and its realised distance), the bodies placed by
//! the testkit's own quaternions:
//!
//! - the witness's distance is at most the least distance plus the
//!   tolerance, and never below the least;
//! - the contact's time and outcome are those of the search for the closest
//!   pair (the tolerance only stops the search earlier);
//! - a tolerance does stop it earlier (less work over a scene), so the
//!   checks can tell a tolerance from none.

use motion_bound::bodies::{board, icosphere, torus};
use motion_bound::ca::{time_of_impact, CaParams, MeshPair};
use motion_bound::testkit::ground_truth::place;
use motion_bound::testkit::toi::{fly_by, reach, Rng};
use motion_bound::{gjk_distance, BallTree, ConvexPolytope, GjkParams, Pose, RigidMotion, TriMesh};

/// The corners of every triangle of `m` placed by `motion` at `t`, and
/// each one's box (least and greatest corner).
type Placed = Vec<([[f64; 3]; 3], [f64; 3], [f64; 3])>;

fn placed(m: &TriMesh<f64>, motion: &RigidMotion<f64>, t: f64) -> Placed {
    let v: Vec<[f64; 3]> = m.vertices().iter().map(|&r| place(motion, r, t)).collect();
    m.triangles()
        .iter()
        .map(|tri| {
            let c = tri.map(|i| v[i as usize]);
            let lo = [0, 1, 2].map(|k| c[0][k].min(c[1][k]).min(c[2][k]));
            let hi = [0, 1, 2].map(|k| c[0][k].max(c[1][k]).max(c[2][k]));
            (c, lo, hi)
        })
        .collect()
}

/// The least distance between the placed triangles of A and B, bracketed:
/// GJK's certified lower bound and realised distance of the closest pair
/// (pairs whose boxes are farther apart than the best realised distance
/// are skipped: the boxes' gap is a lower bound of theirs).
fn least_distance(a: &Placed, b: &Placed) -> (f64, f64) {
    let params = GjkParams::default();
    let (mut lower, mut upper) = (f64::INFINITY, f64::INFINITY);
    for (ta, la, ha) in a {
        for (tb, lb, hb) in b {
            let gap2: f64 = (0..3)
                .map(|k| (la[k] - hb[k]).max(lb[k] - ha[k]).max(0.0).powi(2))
                .sum();
            if gap2.sqrt() > upper {
                continue;
            }
            let pa = ConvexPolytope::try_new(ta, Pose::IDENTITY).expect("finite corners");
            let pb = ConvexPolytope::try_new(tb, Pose::IDENTITY).expect("finite corners");
            let g = gjk_distance(&pa, &pb, &params);
            lower = lower.min(g.lower_bound);
            upper = upper.min(g.distance);
        }
    }
    (lower, upper)
}

/// `n` fly-bys of `a` past `b` with the contact distance `1 %` of the
/// reaches, run with no tolerance and with `fraction` of the contact
/// distance; checks every contact of the latter against the brute force.
/// Returns the node pairs of both runs over the scene.
fn scene(name: &str, a: &TriMesh<f64>, b: &TriMesh<f64>, fraction: f64, n: usize) -> (u64, u64) {
    let (ta, tb) = (
        BallTree::try_from_mesh(a).expect("tree"),
        BallTree::try_from_mesh(b).expect("tree"),
    );
    let (ra, rb) = (reach(a), reach(b));
    let cd = 1e-2 * (ra + rb);
    let exact = CaParams::default().with_contact_distance(cd);
    let tol = fraction * cd;
    let loose = exact.with_witness_tolerance(tol);
    // Rounding: the placements (pose matrices against quaternions), the
    // triangle distances and GJK's differ by a few ulps of the coordinates.
    let rounding = 1e-12 * (ra + rb);
    let mut rng = Rng::new(20_261_204);
    let (mut work_exact, mut work_loose, mut checked, mut beyond) = (0, 0, 0, 0);
    for _ in 0..n {
        let q = fly_by(&mut rng, ra, rb, 6.0);
        let run = |p: &CaParams<f64>| {
            time_of_impact(&mut MeshPair::new(&ta, &tb), &q.a, &q.b, p).expect("valid query")
        };
        let (r0, r1) = (run(&exact), run(&loose));
        work_exact += r0.work.node_pairs;
        work_loose += r1.work.node_pairs;
        let (c0, c1) = (r0.outcome.contact(), r1.outcome.contact());
        assert_eq!(
            c0.map(|c| c.time),
            c1.map(|c| c.time),
            "{name}: the contact time moved"
        );
        assert_eq!(r0.iterations, r1.iterations, "{name}: the iterations moved");
        let Some(w) = c1.and_then(|c| c.witness) else {
            continue;
        };
        checked += 1;
        let t = c1.map_or(0.0, |c| c.time);
        let (lower, upper) = least_distance(&placed(a, &q.a, t), &placed(b, &q.b, t));
        assert!(
            w.distance <= cd
                && w.distance >= lower - rounding
                && w.distance <= upper + tol + rounding,
            "{name}: witness {} against the least in [{lower}, {upper}], tolerance {tol}",
            w.distance
        );
        beyond += usize::from(w.distance > upper + rounding);
    }
    println!(
        "{name}: {checked} contacts checked, {beyond} witnesses beyond the least; node pairs {work_exact} without a tolerance, {work_loose} with {fraction} of the contact distance"
    );
    assert!(checked >= n / 4, "{name}: too few contacts ({checked})");
    (work_exact, work_loose)
}

#[test]
fn a_witness_is_within_its_tolerance_of_the_closest_pair() {
    let plank = board::<f64>(1.0, 1.0, 0.01).expect("board");
    let ball = icosphere::<f64>(0.3, 3).expect("sphere");
    let ring = torus::<f64>(0.5, 0.12, 16, 8).expect("ring");
    let mut totals = (0, 0);
    for (name, a, b) in [
        ("board vs sphere", &plank, &ball),
        ("ring vs sphere", &ring, &ball),
        ("board vs board", &plank, &plank),
    ] {
        let (w0, w1) = scene(name, a, b, 0.05, 40);
        assert!(w1 <= w0, "{name}: more work with a tolerance ({w1} > {w0})");
        totals = (totals.0 + w0, totals.1 + w1);
    }
    assert!(
        totals.1 < totals.0,
        "the tolerance never stopped a search earlier"
    );
}
