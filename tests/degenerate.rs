//! Degenerate meshes (issue 38): copies of one triangle, triangles on one
//! point, zero-area triangles and doubled vertices keep the tree small and
//! every query within its work budget, and dropping exact duplicates leaves
//! every distance unchanged (`proofs/09-ca-toi.md`, Lemma 9.2,
//! "Duplicates"). No timing here: `examples/degenerate_meshes.rs` times the
//! same cases.

#[path = "common/degenerate.rs"]
mod degenerate;
#[path = "common/meshes.rs"]
mod meshes;

use motion_bound::bodies::icosphere;
use motion_bound::ca::{time_of_impact, AnyPair, CaOutcome, CaParams, MeshPair, Shape, Work};
use motion_bound::testkit::ground_truth::{first_sampled_contact, MeshRef};
use motion_bound::testkit::toi::Rng;
use motion_bound::{
    try_triangle_triangle, BallTree, Point3, RigidMotion, TimeInterval, TriMesh, Vec3,
};

/// The bunny (3,674 triangles) centred and scaled to reach 1.
fn bunny() -> TriMesh<f64> {
    let m = meshes::load_shipped("bunny-npm-3674.obj.gz");
    let (c, r) = m.bounding_sphere();
    m.recentred(c)
        .and_then(|m| m.scaled(1.0 / r))
        .expect("the bunny")
}

#[test]
fn copies_and_points_are_one_leaf_and_doubled_vertices_add_none() {
    for n in [1, 10, 10_000, 100_000] {
        let tree = BallTree::try_from_mesh(&degenerate::copies(degenerate::triangle(1.0), n))
            .expect("a tree");
        assert_eq!(
            (tree.triangle_count(), tree.distinct_triangle_count()),
            (n, 1),
            "{n} copies"
        );
        assert_eq!((tree.node_count(), tree.depth()), (1, 1), "{n} copies");
        let tree = BallTree::try_from_mesh(&degenerate::on_one_point([0.5, -1.0, 2.0], n))
            .expect("a tree");
        assert_eq!(tree.node_count(), 1, "{n} triangles on one point");
    }
    // Near copies are distinct: each keeps its leaf.
    let near = degenerate::near_copies(degenerate::triangle(1.0), 1_000, 1e-9, &mut Rng::new(1));
    let tree = BallTree::try_from_mesh(&near).expect("a tree");
    assert_eq!(tree.distinct_triangle_count(), 1_000, "near copies");
    // Doubling every vertex adds no triangle; each zero-area one is at most
    // one more.
    let bunny = bunny();
    let one = BallTree::try_from_mesh(&bunny).expect("a tree");
    let doubled = BallTree::try_from_mesh(&degenerate::doubled_with_slivers(
        &bunny,
        0,
        &mut Rng::new(2),
    ))
    .expect("a tree");
    assert_eq!(
        doubled.distinct_triangle_count(),
        one.distinct_triangle_count(),
        "doubled vertices"
    );
    let slivers = BallTree::try_from_mesh(&degenerate::doubled_with_slivers(
        &bunny,
        1_000,
        &mut Rng::new(3),
    ))
    .expect("a tree");
    let added = slivers.distinct_triangle_count() - one.distinct_triangle_count();
    assert!(
        (300..=1_000).contains(&added),
        "{added} distinct zero-area triangles of 1,000"
    );
}

/// Split keys that all tie (distinct triangles about one centroid, in one
/// plane: the same centroid and normal) still split at the median
/// position: a balanced tree.
#[test]
fn tied_split_keys_keep_the_tree_balanced() {
    let n = 1_024u32;
    let mut v = Vec::new();
    let mut t = Vec::new();
    for k in 0..n {
        let a = f64::from(k) * core::f64::consts::TAU / f64::from(3 * n);
        for j in 0..3 {
            let phi = a + f64::from(j) * core::f64::consts::TAU / 3.0;
            v.push([phi.cos(), phi.sin(), 0.0]);
        }
        t.push([3 * k, 3 * k + 1, 3 * k + 2]);
    }
    let tree = BallTree::try_new(&v, &t).expect("a tree");
    assert_eq!(tree.distinct_triangle_count(), 1_024, "all distinct");
    assert_eq!(tree.node_count(), 2 * 1_024 - 1, "2 M - 1 nodes");
    assert_eq!(tree.depth(), 11, "depth log2(1024) + 1");
}

/// The least distance over every pair of triangles of `a` placed at `xa`
/// and `b` at `xb` (translations: exact enough for the tolerance).
fn brute_force(a: &TriMesh<f64>, xa: [f64; 3], b: &TriMesh<f64>, xb: [f64; 3]) -> f64 {
    let placed = |m: &TriMesh<f64>, x: [f64; 3]| -> Vec<[Point3<f64>; 3]> {
        m.triangles()
            .iter()
            .map(|tri| {
                tri.map(|i| {
                    let p = m.vertices()[i as usize];
                    Point3::new(p[0] + x[0], p[1] + x[1], p[2] + x[2])
                })
            })
            .collect()
    };
    let (ta, tb) = (placed(a, xa), placed(b, xb));
    let mut least = f64::INFINITY;
    for x in &ta {
        for y in &tb {
            least = least.min(try_triangle_triangle(x, y).expect("finite").distance);
        }
    }
    least
}

/// The distance the tree pair finds between `a` at `xa` and `b` at `xb`,
/// standing still: the closest pair's witness of the initial contact under
/// a contact distance larger than any distance, with no work limit.
fn tree_distance(a: &BallTree<f64>, xa: [f64; 3], b: &BallTree<f64>, xb: [f64; 3]) -> f64 {
    let still = |x: [f64; 3]| {
        RigidMotion::try_new(
            Point3::from_array(x),
            Vec3::ZERO,
            Vec3::ZERO,
            TimeInterval::UNIT,
        )
        .expect("a motion")
    };
    let params = CaParams::default()
        .with_contact_distance(100.0)
        .with_work_budget(Work::UNLIMITED);
    let report = time_of_impact(&mut MeshPair::new(a, b), &still(xa), &still(xb), &params)
        .expect("a valid query");
    match report.outcome {
        CaOutcome::InitialContact(c) => c.witness.expect("a witness").distance,
        other => panic!("not an initial contact: {other:?}"),
    }
}

/// The number of distinct sets of points among `mesh`'s triangles, counted
/// the plain way: each triangle's corners as bit patterns (`-0` as `+0`),
/// sorted, repeats dropped, into a set.
fn distinct_point_sets(mesh: &TriMesh<f64>) -> usize {
    let mut sets = std::collections::HashSet::new();
    for tri in mesh.triangles() {
        let mut corners: Vec<[u64; 3]> = tri
            .iter()
            .map(|&i| mesh.vertices()[i as usize].map(|x| (x + 0.0).to_bits()))
            .collect();
        corners.sort_unstable();
        corners.dedup();
        sets.insert(corners);
    }
    sets.len()
}

/// Dropping exact duplicates changes no distance: against every triangle
/// pair (duplicates and zero-area triangles included) and against the same
/// mesh without its duplicates, from a small ball at 16 places near each
/// mesh; and the tree keeps one leaf per distinct set of points, counted
/// apart.
#[test]
fn duplicates_leave_every_distance_unchanged() {
    let mut rng = Rng::new(38);
    let ball = icosphere::<f64>(0.05, 1).expect("a sphere");
    // An icosphere with each triangle three times (turned, from doubled
    // vertices) and zero-area triangles on its vertices and across it.
    let base = icosphere::<f64>(0.8, 2).expect("a sphere");
    let n = base.vertices().len() as u32;
    let mut v = base.vertices().to_vec();
    v.extend_from_slice(base.vertices());
    let mut t = base.triangles().to_vec();
    for &[i, j, k] in base.triangles() {
        t.push([j + n, k, i]);
        t.push([k, i + n, j + n]);
    }
    let mut slivers = Vec::new();
    for s in 0..60u32 {
        let (a, b) = (s * 7 % n, s * 13 % n);
        slivers.push([a, a + n, a]);
        slivers.push([a, b, b + n]);
    }
    t.extend_from_slice(&slivers);
    let duplicated = TriMesh::try_new(v, t).expect("a mesh");
    let mut plain_t = base.triangles().to_vec();
    plain_t.extend_from_slice(&slivers);
    let plain =
        TriMesh::try_new([base.vertices(), base.vertices()].concat(), plain_t).expect("a mesh");
    let (td, tp, tb) = (
        BallTree::try_from_mesh(&duplicated).expect("a tree"),
        BallTree::try_from_mesh(&plain).expect("a tree"),
        BallTree::try_from_mesh(&ball).expect("a tree"),
    );
    assert!(
        td.distinct_triangle_count() < duplicated.triangle_count() / 2,
        "duplicates dropped: {} of {}",
        td.distinct_triangle_count(),
        duplicated.triangle_count()
    );
    // The doubled bunny with its zero-area triangles, too.
    let bunny = bunny();
    let doubled = degenerate::doubled_with_slivers(&bunny, 1_000, &mut rng);
    let tdb = BallTree::try_from_mesh(&doubled).expect("a tree");
    for (mesh, tree) in [(&duplicated, &td), (&plain, &tp), (&doubled, &tdb)] {
        assert_eq!(
            tree.distinct_triangle_count(),
            distinct_point_sets(mesh),
            "one leaf per distinct set of points"
        );
    }
    for k in 0..16 {
        let d = rng.direction();
        for (what, mesh, tree, other, x) in [
            (
                "duplicated icosphere",
                &duplicated,
                &td,
                Some(&tp),
                d.map(|c| c * 0.9),
            ),
            (
                "doubled bunny",
                &doubled,
                &tdb,
                None,
                d.map(|c| c * rng.range(0.4, 1.1)),
            ),
        ] {
            let least = brute_force(mesh, [0.0; 3], &ball, x);
            let got = tree_distance(tree, [0.0; 3], &tb, x);
            let tol = 1e-12;
            assert!(
                (got - least).abs() <= tol,
                "{what}, placement {k}: the tree finds {got}, every triangle pair {least}"
            );
            if let Some(other) = other {
                let without = tree_distance(other, [0.0; 3], &tb, x);
                assert!(
                    (got - without).abs() <= tol,
                    "{what}, placement {k}: {got} with duplicates, {without} without"
                );
            }
        }
    }
}

/// The cases against the bunny under the default parameters, each
/// pair made inside the query as a scene makes it: every query decided or
/// ended by the work limit, within the budget; for the small ones, never
/// late nor missed against sampled ground truth.
#[test]
fn degenerate_queries_end_decided_or_at_the_work_limit() {
    let bunny_mesh = bunny();
    let bunny = BallTree::try_from_mesh(&bunny_mesh).expect("a tree");
    let mut rng = Rng::new(38);
    let mut cases: Vec<(String, TriMesh<f64>)> = Vec::new();
    for scale in [1.0, 0.1] {
        for n in [10, 10_000, 100_000] {
            cases.push((
                format!("{n} copies at scale {scale}"),
                degenerate::copies(degenerate::triangle(scale), n),
            ));
        }
    }
    cases.push((
        "triangles on one point".into(),
        degenerate::on_one_point([0.0, 0.3, -0.2], 10_000),
    ));
    cases.push((
        "near copies".into(),
        degenerate::near_copies(degenerate::triangle(1.0), 2_000, 1e-9, &mut rng),
    ));
    cases.push((
        "the doubled bunny with 1,000 zero-area triangles".into(),
        degenerate::doubled_with_slivers(&bunny_mesh, 1_000, &mut rng),
    ));
    let params = CaParams::<f64>::default();
    let mut outcomes = [0usize; 4];
    for (what, mesh) in &cases {
        let tree = BallTree::try_from_mesh(mesh).expect("a tree");
        for k in 0..6 {
            let (ma, mb) = degenerate::fly_by(k);
            let mut pair =
                AnyPair::try_new(Shape::Mesh(&tree), Shape::Mesh(&bunny)).expect("a pair");
            let r = time_of_impact(&mut pair, &ma, &mb, &params).expect("a valid query");
            assert!(
                !r.work.exceeds(params.work_budget),
                "{what}, fly-by {k}: work {:?} beyond the budget",
                r.work
            );
            let slot = match r.outcome {
                CaOutcome::Contact { .. } => 0,
                CaOutcome::InitialContact(_) => 1,
                CaOutcome::Separated => 2,
                CaOutcome::WorkLimit { .. } => 3,
                other => panic!("{what}, fly-by {k}: undecided: {other:?}"),
            };
            outcomes[slot] += 1;
            if mesh.triangle_count() <= 10 {
                let truth = first_sampled_contact(
                    MeshRef::from(mesh),
                    &ma,
                    MeshRef::from(&bunny_mesh),
                    &mb,
                    (0.0, 1.0),
                    64,
                );
                let reported = r.outcome.earliest_possible_contact();
                match (reported, truth) {
                    (None, Some(g)) => panic!("{what}, fly-by {k}: MISSED a contact at {g}"),
                    (Some(t), Some(g)) => {
                        assert!(t <= g, "{what}, fly-by {k}: LATE: {t} after {g}");
                    }
                    _ => {}
                }
            }
        }
    }
    println!(
        "{} queries: {} contacts, {} initial contacts, {} separated, {} work limits",
        6 * cases.len(),
        outcomes[0],
        outcomes[1],
        outcomes[2],
        outcomes[3]
    );
    assert!(outcomes[0] + outcomes[2] > 0, "some decided");
}
