//! Conservative advancement never reports a contact late and never misses one
//! (`proofs/09-ca-toi.md`), against an independent ground truth: the first
//! of densely sampled times at which the meshes intersect, decided by exact
//! orientation predicates (`testkit::ground_truth`), with bodies placed by
//! its own quaternion code.
//!
//! The scenes rotate: interlocking-prone torus knots and rings, a thin board
//! spinning fast, and convex solids through the GJK stepper. Set
//! `CA_TOI_QUERIES` to run more queries per scene.

use motion_bound::bodies::{board, icosphere, torus, TorusKnot};
use motion_bound::ca::{
    time_of_impact, BallPair, BoundChoice, CaOutcome, CaParams, CaReport, CaStep, ContactCriterion,
    MeshPair, MeshParams, StepResult, VertexSetPair,
};
use motion_bound::testkit::ground_truth::{first_sampled_contact, MeshRef};
use motion_bound::testkit::toi::{fly_by, random_rotation, reach, rotate_mesh, FlyBy, Rng};
use motion_bound::{
    BallTree, BoundingBall, PreparedMotion, RigidMotion, TriMesh, VertexSet, VertexTree,
};

/// Ground-truth samples per query over `[0, 1]`.
const SAMPLES: usize = 256;

fn queries_per_scene(default: usize) -> usize {
    std::env::var("CA_TOI_QUERIES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(default)
}

#[derive(Default, Debug)]
struct Tally {
    queries: usize,
    sampled_contacts: usize,
    ca_contacts: usize,
    /// Of the contacts, those declared by time tolerance (a stall).
    ca_stalls: usize,
    separated: usize,
    /// Queries ended by the work budget or the precision limit (possible
    /// contacts at the time reached).
    work_limits: usize,
    precision_limits: usize,
    iterations: u64,
    /// The most node pairs and triangle pairs one query used.
    most_work: (u64, u64),
    violations: Vec<String>,
}

impl Tally {
    /// Records one query: `report` from CA, `truth` the first sampled
    /// intersection over `[0, 1]`.
    fn record<T: motion_bound::Float>(
        &mut self,
        what: &str,
        report: &CaReport<T>,
        truth: Option<f64>,
    ) {
        self.queries += 1;
        self.iterations += u64::from(report.iterations);
        self.most_work.0 = self.most_work.0.max(report.work.node_pairs);
        self.most_work.1 = self.most_work.1.max(report.work.triangle_pairs);
        self.sampled_contacts += usize::from(truth.is_some());
        let reported = report.outcome.earliest_possible_contact().map(T::to_f64);
        self.ca_contacts += usize::from(report.outcome.contact().is_some());
        match report.outcome {
            CaOutcome::Separated => self.separated += 1,
            CaOutcome::WorkLimit { .. } => self.work_limits += 1,
            CaOutcome::PrecisionLimit { .. } => self.precision_limits += 1,
            CaOutcome::Contact {
                contact,
                criterion: ContactCriterion::TimeTolerance,
            } => {
                self.ca_stalls += 1;
                // A stall leaves at least the time tolerance before the end.
                if contact.time.to_f64() + 1e-9 >= 1.0 {
                    self.violations.push(format!(
                        "{what}: a contact by time tolerance within the tolerance of the end: {report:?}"
                    ));
                }
            }
            _ => {}
        }
        match (reported, truth) {
            (None, Some(g)) => self
                .violations
                .push(format!("{what}: MISSED a contact sampled at t = {g}")),
            (Some(t), Some(g)) if g < t => self.violations.push(format!(
                "{what}: LATE: reported {t} after a sampled intersection at {g}"
            )),
            _ => {}
        }
    }

    fn assert_clean(&self, scene: &str) {
        println!(
            "{scene}: {} queries, {} sampled contacts, {} CA contacts ({} by time tolerance), {} CA separated, {} work limits, {} precision limits, {} sampled without contact, {:.2} iterations per query, at most {} node pairs and {} triangle pairs per query, {} violations",
            self.queries,
            self.sampled_contacts,
            self.ca_contacts,
            self.ca_stalls,
            self.separated,
            self.work_limits,
            self.precision_limits,
            self.queries - self.sampled_contacts,
            self.iterations as f64 / self.queries.max(1) as f64,
            self.most_work.0,
            self.most_work.1,
            self.violations.len()
        );
        assert!(
            self.violations.is_empty(),
            "{scene}: {} violations, first: {}",
            self.violations.len(),
            self.violations[0]
        );
        assert!(
            self.sampled_contacts * 4 >= self.queries,
            "{scene}: too few real contacts ({} of {}) for the test to have power",
            self.sampled_contacts,
            self.queries
        );
    }
}

/// `orientations` randomly rotated copies of `mesh` with their trees.
fn oriented(
    mesh: &TriMesh<f64>,
    orientations: usize,
    rng: &mut Rng,
) -> Vec<(TriMesh<f64>, BallTree<f64>)> {
    (0..orientations)
        .map(|_| {
            let m = rotate_mesh(mesh, &random_rotation(rng));
            let t = BallTree::try_from_mesh(&m).expect("valid mesh");
            (m, t)
        })
        .collect()
}

/// Runs `n` random fly-by queries of A against B, alternating the bounds,
/// with the default horizon factor and far ratio.
fn run_meshes(scene: &str, a: &TriMesh<f64>, b: &TriMesh<f64>, spin: f64, n: usize, seed: u64) {
    run_meshes_with(scene, (a, b), spin, n, seed, |_| None);
}

/// As [`run_meshes`], with query `k` using `(horizon factor, far ratio,
/// one-sided bounds)` from `settings(k)` when it gives one.
fn run_meshes_with(
    scene: &str,
    (a, b): (&TriMesh<f64>, &TriMesh<f64>),
    spin: f64,
    n: usize,
    seed: u64,
    settings: impl Fn(usize) -> Option<(f64, f64, bool)>,
) {
    let mut rng = Rng::new(seed);
    let (oa, ob) = (oriented(a, 4, &mut rng), oriented(b, 4, &mut rng));
    let (ra, rb) = (reach(a), reach(b));
    let eps = 1e-3 * (ra + rb);
    let mut tally = Tally::default();
    for k in 0..n {
        let (ma, ta) = &oa[k % 4];
        let (mb, tb) = &ob[(k / 4) % 4];
        let q = fly_by(&mut rng, ra, rb, spin);
        let bound = [BoundChoice::Evq, BoundChoice::Nevq, BoundChoice::Auto][k % 3];
        let mut params = CaParams::default()
            .with_contact_distance(eps)
            .with_bound(bound);
        let mut pair = MeshPair::new(ta, tb);
        if let Some((horizon, far, one_sided)) = settings(k) {
            params = params
                .with_horizon_factor(horizon)
                .with_one_sided(one_sided);
            pair = pair
                .try_with_params(MeshParams::default().with_far_ratio(far))
                .expect("valid knobs");
        }
        let report = time_of_impact(&mut pair, &q.a, &q.b, &params).expect("valid query");
        let truth = first_sampled_contact(
            MeshRef::from(ma),
            &q.a,
            MeshRef::from(mb),
            &q.b,
            (0.0, 1.0),
            SAMPLES,
        );
        tally.record(&format!("{scene} query {k} ({bound:?})"), &report, truth);
    }
    tally.assert_clean(scene);
}

// The knot scene in two halves (other seeds), so that the two cores share it.
#[test]
fn torus_knots_with_rotation_are_never_late_and_never_missed() {
    let knot = TorusKnot::TREFOIL.mesh::<f64>(60, 8).expect("knot");
    run_meshes(
        "knot vs knot",
        &knot,
        &knot,
        6.0,
        queries_per_scene(300) / 2,
        1,
    );
}

#[test]
fn torus_knots_with_rotation_are_never_late_and_never_missed_more() {
    let knot = TorusKnot::TREFOIL.mesh::<f64>(60, 8).expect("knot");
    run_meshes(
        "knot vs knot, second half",
        &knot,
        &knot,
        6.0,
        queries_per_scene(300) / 2,
        101,
    );
}

#[test]
fn horizon_and_far_ratio_stay_sound() {
    // The time-resolved step off, short and long horizons; never settling a
    // pair, settling eagerly and rarely (`proofs/09-ca-toi.md`, Lemma 9.3);
    // the seed's absolute bounds and the one-sided ones (Lemma 10.2).
    let knot = TorusKnot::TREFOIL.mesh::<f64>(60, 8).expect("knot");
    let horizons = [0.0, 1.5, 8.0];
    let far = [f64::INFINITY, 0.5, 16.0];
    run_meshes_with(
        "knot vs knot, other horizons, far ratios, absolute bounds",
        (&knot, &knot),
        6.0,
        queries_per_scene(90),
        11,
        |k| Some((horizons[(k / 3) % 3], far[(k / 9) % 3], (k / 27) % 2 == 0)),
    );
}

#[test]
fn a_mesh_pair_reused_across_queries_stays_sound() {
    // One `MeshPair` per tree pair for every query: each query's first step
    // starts from the leaf pairs the previous query left behind, for other
    // motions (`proofs/09-ca-toi.md`, Lemma 9.4: any seed is sound).
    let knot = TorusKnot::TREFOIL.mesh::<f64>(60, 8).expect("knot");
    let mut rng = Rng::new(21);
    let (oa, ob) = (oriented(&knot, 2, &mut rng), oriented(&knot, 2, &mut rng));
    let r = reach(&knot);
    let params = CaParams::default().with_contact_distance(1e-3 * 2.0 * r);
    // Half of them carry the front from step to step (Lemma 9.9): a front
    // must never leak from one query into the next.
    let mut pairs: Vec<MeshPair<'_, f64>> = (0..4)
        .map(|k| {
            MeshPair::new(&oa[k % 2].1, &ob[k / 2].1)
                .try_with_params(MeshParams::default().with_carry_front(k % 2 == 0))
                .expect("knobs")
        })
        .collect();
    let mut tally = Tally::default();
    for k in 0..queries_per_scene(80) {
        let q = fly_by(&mut rng, r, r, 6.0);
        let report = time_of_impact(&mut pairs[k % 4], &q.a, &q.b, &params).expect("valid query");
        let truth = first_sampled_contact(
            MeshRef::from(&oa[k % 2].0),
            &q.a,
            MeshRef::from(&ob[(k % 4) / 2].0),
            &q.b,
            (0.0, 1.0),
            SAMPLES,
        );
        tally.record(&format!("reused pair, query {k}"), &report, truth);
    }
    tally.assert_clean("knot vs knot, reused pairs");
}

#[test]
fn seeds_shorten_the_descent() {
    // The same step taken twice by one `MeshPair`: the second starts from the
    // first one's least-step leaf pairs (Lemma 9.4), so its best step is
    // known from the start and it pops fewer node pairs in all (about 4 %
    // here, far from contact; 10 to 12 % over whole knot queries in
    // `examples/table1`). Its step is the least over another cut, so it may
    // differ either way; soundness is the other tests' business. Without
    // seeds both steps would do the same work.
    let knot = TorusKnot::TREFOIL.mesh::<f64>(60, 8).expect("knot");
    let tree = BallTree::try_from_mesh(&knot).expect("tree");
    let r = reach(&knot);
    let params = CaParams::default().with_contact_distance(1e-3);
    let mut rng = Rng::new(5);
    let (mut first_pops, mut second_pops, mut taken) = (0, 0, 0);
    for k in 0..40 {
        let q = fly_by(&mut rng, r, r, 6.0);
        let t = 0.05 * f64::from(k % 8);
        let (a, b) = (
            PreparedMotion::new(&q.a.restrict(t, 1.0).expect("sub-interval")),
            PreparedMotion::new(&q.b.restrict(t, 1.0).expect("sub-interval")),
        );
        // The front off: the second step would otherwise start from the
        // first one's cut (Lemma 9.9, `tests/front.rs`), not the seeds alone.
        let mut pair = MeshPair::new(&tree, &tree)
            .try_with_params(MeshParams::default().with_carry_front(false))
            .expect("knobs");
        let first = pair.step(t, &a, &b, &params);
        let after_first = pair.stats().node_pairs;
        let second = pair.step(t, &a, &b, &params);
        let after_second = pair.stats().node_pairs - after_first;
        match (first, second) {
            (StepResult::Advance { .. }, StepResult::Advance { .. }) => {
                first_pops += after_first;
                second_pops += after_second;
                taken += 1;
            }
            (StepResult::Touching { .. }, StepResult::Touching { .. }) => {}
            (x, y) => panic!("query {k}: the two steps disagree: {x:?} then {y:?}"),
        }
    }
    assert!(taken >= 20, "only {taken} of 40 steps advanced");
    println!("seeded steps: {second_pops} node pairs, fresh steps: {first_pops}");
    assert!(
        second_pops < first_pops,
        "the seeds saved nothing: {second_pops} node pairs against {first_pops}"
    );
}

#[test]
fn rings_with_rotation_are_never_late_and_never_missed() {
    let ring = torus::<f64>(0.5, 0.08, 32, 8).expect("ring");
    run_meshes("ring vs ring", &ring, &ring, 6.0, queries_per_scene(300), 2);
}

#[test]
fn thin_fast_spinning_board_is_never_late_and_never_missed() {
    let plank = board::<f64>(1.0, 0.4, 0.005).expect("board");
    let knot = TorusKnot::TREFOIL.mesh::<f64>(60, 8).expect("knot");
    run_meshes(
        "spinning board vs knot",
        &plank,
        &knot,
        40.0,
        queries_per_scene(300),
        3,
    );
}

/// A board of 12 large triangles against a fine sphere: the board's
/// hierarchy of pieces is taken (`proofs/09-ca-toi.md`, Lemma 9.5), and the
/// ground truth is that of the whole triangles.
#[test]
fn a_board_of_large_triangles_is_cut_into_pieces_and_never_late() {
    let plank = board::<f64>(2.0, 2.0, 0.002).expect("board");
    let ball = icosphere::<f64>(0.3, 4).expect("sphere");
    let (tp, tb) = (
        BallTree::try_from_mesh(&plank).expect("valid"),
        BallTree::try_from_mesh(&ball).expect("valid"),
    );
    assert!(tp.piece_leaf_count() > 1_000, "the board is cut");
    assert_eq!(MeshPair::new(&tp, &tb).pieces_in_use(), (true, false));
    run_meshes(
        "large-triangle board (pieces) vs sphere",
        &plank,
        &ball,
        40.0,
        queries_per_scene(200),
        11,
    );
}

#[test]
fn convex_solids_through_gjk_are_never_late_and_never_missed() {
    let ball = icosphere::<f64>(0.3, 1).expect("icosphere");
    let slab = board::<f64>(0.8, 0.5, 0.02).expect("board");
    let mut rng = Rng::new(4);
    let (ra, rb) = (reach(&ball), reach(&slab));
    let mut tally = Tally::default();
    for k in 0..queries_per_scene(200) {
        let rot = random_rotation(&mut rng);
        let (a, b) = (
            rotate_mesh(&ball, &rot),
            rotate_mesh(&slab, &random_rotation(&mut rng)),
        );
        let q = fly_by(&mut rng, ra, rb, 20.0);
        let (va, vb) = (
            VertexSet::try_new(a.vertices()).expect("valid"),
            VertexSet::try_new(b.vertices()).expect("valid"),
        );
        let bound = [BoundChoice::Evq, BoundChoice::Nevq, BoundChoice::Auto][k % 3];
        let params = CaParams::default()
            .with_contact_distance(1e-4)
            .with_bound(bound);
        // Every other query bounds through the bodies' vertex trees
        // (`proofs/08-ball-bound.md`, Lemma 8.2).
        let (ta, tb) = (
            VertexTree::try_new(&va).expect("valid"),
            VertexTree::try_new(&vb).expect("valid"),
        );
        let mut pair = VertexSetPair::with_gjk(va, vb);
        if k % 2 == 1 {
            pair = pair.with_vertex_trees(Some(&ta), Some(&tb));
        }
        let report = time_of_impact(&mut pair, &q.a, &q.b, &params).expect("valid query");
        let truth = first_sampled_contact(
            MeshRef::from(&a),
            &q.a,
            MeshRef::from(&b),
            &q.b,
            (0.0, 1.0),
            SAMPLES,
        );
        tally.record(&format!("convex query {k} ({bound:?})"), &report, truth);
    }
    tally.assert_clean("convex (GJK)");
}

/// The same knot scene in `f32`: meshes and motions rounded to `f32`, the
/// ground truth computed in `f64` from exactly those rounded inputs.
#[test]
fn f32_meshes_are_never_late_and_never_missed() {
    let knot64 = TorusKnot::TREFOIL.mesh::<f64>(60, 8).expect("knot");
    let mut rng = Rng::new(5);
    let shapes: Vec<(TriMesh<f64>, BallTree<f32>)> = (0..4)
        .map(|_| {
            let m32: TriMesh<f32> = rotate_mesh(&knot64, &random_rotation(&mut rng))
                .try_convert()
                .expect("fits f32");
            let tree = BallTree::try_from_mesh(&m32).expect("valid");
            (m32.try_convert().expect("exact"), tree)
        })
        .collect();
    let r = reach(&knot64);
    let to32 = |m: &RigidMotion<f64>| {
        let f = |v: [f64; 3]| v.map(|x| x as f32);
        RigidMotion::<f32>::try_from_arrays(
            f(m.centre().to_array()),
            f(m.linear().to_array()),
            f(m.angular().to_array()),
        )
        .expect("finite")
    };
    let to64 = |m: &RigidMotion<f32>| {
        let f = |v: [f32; 3]| v.map(f64::from);
        RigidMotion::<f64>::try_from_arrays(
            f(m.centre().to_array()),
            f(m.linear().to_array()),
            f(m.angular().to_array()),
        )
        .expect("finite")
    };
    let mut tally = Tally::default();
    for k in 0..queries_per_scene(200) {
        let (ma, ta) = &shapes[k % 4];
        let (mb, tb) = &shapes[(k + 1) % 4];
        let FlyBy { a, b } = fly_by(&mut rng, r, r, 6.0);
        let (a32, b32) = (to32(&a), to32(&b));
        let bound = [BoundChoice::Evq, BoundChoice::Nevq][k % 2];
        let params = CaParams::<f32>::default()
            .with_contact_distance(2e-3)
            .with_bound(bound);
        let report =
            time_of_impact(&mut MeshPair::new(ta, tb), &a32, &b32, &params).expect("valid");
        let truth = first_sampled_contact(
            MeshRef::from(ma),
            &to64(&a32),
            MeshRef::from(mb),
            &to64(&b32),
            (0.0, 1.0),
            SAMPLES,
        );
        tally.record(&format!("f32 query {k} ({bound:?})"), &report, truth);
    }
    tally.assert_clean("knot vs knot, f32");
}

#[test]
fn ball_pair_matches_the_closed_form() {
    // Two balls approaching head-on with spin about their centres: the
    // spin moves no point of a ball centred on its rotation centre off the
    // ball, so contact is at the closed-form time (d - ra - rb) / |v|.
    let mut rng = Rng::new(6);
    for _ in 0..500 {
        let (ra, rb) = (rng.range(0.1, 1.0), rng.range(0.1, 1.0));
        let dir = rng.direction();
        let dist = ra + rb + rng.range(0.01, 3.0);
        let speed = rng.range(0.5, 8.0);
        let a = RigidMotion::try_from_arrays([0.0; 3], dir.map(|x| x * speed), rng.direction())
            .expect("finite");
        let b = RigidMotion::try_from_arrays(
            dir.map(|x| x * dist),
            [0.0; 3],
            rng.direction().map(|x| x * 5.0),
        )
        .expect("finite");
        let pair = &mut BallPair::new(
            BoundingBall::try_new([0.0; 3], ra).expect("ball"),
            BoundingBall::try_new([0.0; 3], rb).expect("ball"),
        );
        let eps = 1e-6;
        let report = time_of_impact(
            pair,
            &a,
            &b,
            &CaParams::default().with_contact_distance(eps),
        )
        .expect("valid");
        let exact = (dist - ra - rb) / speed;
        match report.outcome.contact() {
            Some(c) => {
                assert!(c.time <= exact, "late: {} > {exact}", c.time);
                assert!(
                    c.time >= exact - 2.0 * eps / speed,
                    "too early: {} vs {exact}",
                    c.time
                );
            }
            None => assert!(
                exact > 1.0,
                "missed a contact at {exact}: {:?}",
                report.outcome
            ),
        }
    }
}

#[test]
fn parameters_and_intervals_are_validated() {
    let ball = BoundingBall::try_new([0.0; 3], 1.0).expect("ball");
    let m = RigidMotion::try_from_arrays([0.0; 3], [1.0, 0.0, 0.0], [0.0; 3]).expect("motion");
    let pair = &mut BallPair::new(ball, ball);
    let bad = CaParams::default().with_contact_distance(f64::NAN);
    assert!(time_of_impact(pair, &m, &m, &bad).is_err(), "NaN tolerance");
    // Surfaces that meet exactly cannot be certified in floating point: a
    // zero contact distance is refused when the query is made.
    for d in [0.0, -0.0, -1e-3, f64::INFINITY] {
        let bad = CaParams::default().with_contact_distance(d);
        assert_eq!(
            time_of_impact(pair, &m, &m, &bad).err(),
            Some(motion_bound::ca::CaError::InvalidParameter(
                motion_bound::ca::Parameter::ContactDistance
            )),
            "contact distance {d}"
        );
    }
    let bad = CaParams::default().with_max_iterations(0);
    assert!(
        time_of_impact(pair, &m, &m, &bad).is_err(),
        "zero iterations"
    );
    for f in [0.5, 1.0, -1.0, f64::NAN] {
        let bad = CaParams::default().with_horizon_factor(f);
        assert_eq!(
            time_of_impact(pair, &m, &m, &bad).err(),
            Some(motion_bound::ca::CaError::InvalidParameter(
                motion_bound::ca::Parameter::HorizonFactor
            )),
            "horizon factor {f}"
        );
    }
    let other = m.restrict(0.0, 0.5).expect("sub-interval");
    assert!(
        time_of_impact(pair, &m, &other, &CaParams::default()).is_err(),
        "interval mismatch"
    );
    // Overlapping from the start: an initial contact, in one iteration.
    let r = time_of_impact(pair, &m, &m, &CaParams::default()).expect("valid");
    assert!(
        matches!(r.outcome, CaOutcome::InitialContact(_)),
        "{:?}",
        r.outcome
    );
    assert_eq!(r.iterations, 1, "one iteration");
}
