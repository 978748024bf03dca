//! Precision that does not depend on where a pair is, and a bounded cost on
//! every input: tests that count work (node pairs and triangle pairs), not
//! time (`proofs/floating-point.md`, sections "Pair frame" and "Resolution";
//! `proofs/09-ca-toi.md`, Lemma 9.6).
//!
//! The story: the shipped bunny flying past a copy of itself, at `1e7` in
//! `f32`, took two minutes for one iteration and reported a contact by time
//! tolerance at `t = 0`. The placement's rounding grew with the distance
//! from the world origin (`8 u |x0|`, about 5 at `1e7` in `f32`), beyond the
//! contact distance, so every node pair counted as near and was split down to
//! every triangle pair. Conservative advancement now places each pair in its
//! own frame, with the relative translation exact (or its rounding carried),
//! and bounds each query's work.
//!
//! "The same pair at the origin" is the pair whose start positions are the
//! exact differences of the far pair's (representable) inputs: the relative
//! geometry both queries see.

#[path = "common/meshes.rs"]
mod meshes;

use motion_bound::bodies::icosphere;
use motion_bound::ca::{
    time_of_impact, CaOutcome, CaParams, CaReport, ContactCriterion, MeshPair, Work,
};
use motion_bound::{BallTree, Float, Point3, RigidMotion, TimeInterval, TriMesh, Vec3};

/// The contact distance (at unit scale).
const CONTACT: f64 = 1e-3;

/// The shipped bunny (3,674 triangles) centred and scaled to reach 0.5.
fn bunny() -> TriMesh<f64> {
    let m = meshes::load_shipped("bunny-npm-3674.obj.gz");
    let (c, r) = m.bounding_sphere();
    m.recentred(c)
        .and_then(|m| m.scaled(0.5 / r))
        .expect("the bunny centred and scaled")
}

/// The fly-by, scaled by `scale`, B's centre at `(offset, offset,
/// offset)` and A's at `offset + scale (-1.3, 0.1, 0)`, each rounded to `T`:
/// A moves at `scale (2.6, 0, 0)` turning at `(0, 3, 1.5)`, B turns at
/// `(0.3, 0, 0)`. Returns A's and B's motions, and A's centre relative to
/// B's, exactly (the difference of the rounded inputs).
fn fly_by<T: Float>(offset: f64, scale: f64) -> (RigidMotion<T>, RigidMotion<T>, [f64; 3]) {
    let at = |rel: f64| T::from_f64(offset + rel * scale);
    let ca = [at(-1.3), at(0.1), at(0.0)];
    let cb = [at(0.0); 3];
    let rel = [0, 1, 2].map(|k| ca[k].to_f64() - cb[k].to_f64());
    let motion = |c: [T; 3], v: [f64; 3], w: [f64; 3]| {
        RigidMotion::try_new(
            Point3::from_array(c),
            Vec3::from_array(v.map(|x| T::from_f64(x * scale))),
            Vec3::from_array(w.map(T::from_f64)),
            TimeInterval::UNIT,
        )
        .expect("a valid motion")
    };
    (
        motion(ca, [2.6, 0.0, 0.0], [0.0, 3.0, 1.5]),
        motion(cb, [0.0; 3], [0.3, 0.0, 0.0]),
        rel,
    )
}

/// One query of `tree` against itself, with the contact distance `cd`.
fn query<T: Float>(
    tree: &BallTree<T>,
    a: &RigidMotion<T>,
    b: &RigidMotion<T>,
    cd: f64,
) -> CaReport<T> {
    let params = CaParams::<T>::default().with_contact_distance(T::from_f64(cd));
    time_of_impact(&mut MeshPair::new(tree, tree), a, b, &params).expect("a valid query")
}

/// The reported time, or `None` when separated.
fn time<T: Float>(r: &CaReport<T>) -> Option<f64> {
    r.outcome.earliest_possible_contact().map(T::to_f64)
}

/// Whether the outcome is a contact by distance (what both the far pair and
/// the one at the origin should report here).
fn by_distance<T: Float>(r: &CaReport<T>) -> bool {
    matches!(
        r.outcome,
        CaOutcome::Contact {
            criterion: ContactCriterion::Distance,
            ..
        }
    )
}

/// The far pair against the same pair at the origin: the same outcome, the
/// time within the closing time of the contact distance (A approaches at
/// 2.6), and node pairs within a factor two. Returns the two reports.
fn far_against_origin<T: Float + Named>(
    tree: &BallTree<T>,
    offset: f64,
) -> (CaReport<T>, CaReport<T>) {
    let (a, b, rel) = fly_by::<T>(offset, 1.0);
    let far = query(tree, &a, &b, CONTACT);
    let (a0, b0, rel0) = fly_by::<T>(0.0, 1.0);
    // The origin's pair with the far pair's relative start.
    let a0 = RigidMotion::try_new(
        Point3::from_array(rel.map(T::from_f64)),
        a0.linear(),
        a0.angular(),
        TimeInterval::UNIT,
    )
    .expect("valid");
    let near = query(tree, &a0, &b0, CONTACT);
    let what = format!(
        "{} at offset {offset:e} (relative start {rel:?}, unit {rel0:?})",
        T::NAME
    );
    assert!(
        by_distance(&near),
        "{what}: the pair at the origin should touch: {near:?}"
    );
    assert!(by_distance(&far), "{what}: far from the origin: {far:?}");
    let (tf, tn) = (time(&far).expect("contact"), time(&near).expect("contact"));
    assert!(
        (tf - tn).abs() <= CONTACT / 2.6,
        "{what}: contact at {tf}, at the origin {tn}"
    );
    let (wf, wn) = (far.work.node_pairs, near.work.node_pairs);
    assert!(
        wf <= 2 * wn && wn <= 2 * wf,
        "{what}: {wf} node pairs, at the origin {wn}"
    );
    (far, near)
}

/// A name per precision for messages.
trait Named {
    const NAME: &'static str;
}
impl Named for f32 {
    const NAME: &'static str = "f32";
}
impl Named for f64 {
    const NAME: &'static str = "f64";
}

/// The rows: `f32` at `3e5`, `1e6`, `1e7` reported `TimeTolerance`
/// at 0 after 65 to 116 s; every decade from 1 to `1e7` now gets the
/// outcome of the same pair at the origin, with as much work.
#[test]
fn f32_pairs_from_1_to_1e7_get_the_outcome_and_the_work_of_the_origin() {
    let tree = BallTree::try_from_mesh(&bunny().try_convert::<f32>().expect("f32")).expect("tree");
    let mut offsets: Vec<f64> = (0..=7).map(|k| 10f64.powi(k)).collect();
    offsets.push(3e5);
    for offset in offsets {
        let (far, near) = far_against_origin(&tree, offset);
        println!(
            "f32 offset {offset:e}: contact at {:?} ({} node pairs), at the origin {:?} ({})",
            time(&far),
            far.work.node_pairs,
            time(&near),
            near.work.node_pairs
        );
    }
}

/// The rows: `f64` at `1e14` to `1e16` reported `TimeTolerance` at 0
/// after 19 s, 78 s and more than two minutes.
#[test]
fn f64_pairs_from_1_to_1e16_get_the_outcome_and_the_work_of_the_origin() {
    let tree = BallTree::try_from_mesh(&bunny()).expect("tree");
    for k in 0..=16 {
        let offset = 10f64.powi(k);
        let (far, near) = far_against_origin(&tree, offset);
        println!(
            "f64 offset {offset:e}: contact at {:?} ({} node pairs), at the origin {:?} ({})",
            time(&far),
            far.work.node_pairs,
            time(&near),
            near.work.node_pairs
        );
    }
}

/// The bunny scaled by `scale` (and its motion and contact distance with it)
/// against unit scale: the same contact time within the closing time and
/// node pairs within a factor two; or, beyond the range of the bounds, a
/// typed answer at once: `TooLarge` at input above `MAX_INPUT` (`2^507`,
/// `2^59`), `PrecisionLimit` with no work below the least resolved reach
/// (about `1e-159`, `3e-20`). The bunny scaled by `1e-300` took 35 s for a
/// `TimeTolerance` at 0.
fn scales<T: Float + Named>(scales: &[f64]) {
    let unit_tree = BallTree::try_from_mesh(&bunny().try_convert::<T>().expect("T")).expect("tree");
    let (a, b, _) = fly_by::<T>(0.0, 1.0);
    let unit = query(&unit_tree, &a, &b, CONTACT);
    let t_unit = time(&unit).expect("a contact at unit scale");
    let (mut resolved, mut limited, mut rejected) = (0, 0, 0);
    for &s in scales {
        let what = format!("{} at scale {s:e}", T::NAME);
        // Too large for the input range: a typed error, no query.
        let Ok(mesh) = bunny().scaled(s).and_then(|m| m.try_convert::<T>()) else {
            rejected += 1;
            assert!(s > 1e10, "{what}: rejected");
            continue;
        };
        let Ok(tree) = BallTree::try_from_mesh(&mesh) else {
            rejected += 1;
            assert!(s > 1e10, "{what}: no tree");
            continue;
        };
        let (a, b, _) = fly_by::<T>(0.0, s);
        let r = query(&tree, &a, &b, CONTACT * s);
        match r.outcome {
            CaOutcome::PrecisionLimit { time, resolution } => {
                limited += 1;
                assert!(
                    s < 1e-10 && time == T::ZERO && r.work == Work::ZERO,
                    "{what}: a precision limit with work: {r:?}"
                );
                assert!(
                    resolution.to_f64() > CONTACT * s,
                    "{what}: a resolution below the contact distance: {r:?}"
                );
            }
            _ => {
                resolved += 1;
                assert!(by_distance(&r), "{what}: {r:?}");
                let t = time(&r).expect("contact");
                assert!(
                    (t - t_unit).abs() <= CONTACT / 2.6,
                    "{what}: contact at {t}, at unit scale {t_unit}"
                );
                let (w, wu) = (r.work.node_pairs, unit.work.node_pairs);
                assert!(
                    w <= 2 * wu && wu <= 2 * w,
                    "{what}: {w} node pairs, at unit scale {wu}"
                );
            }
        }
    }
    println!(
        "{}: {resolved} scales as at unit scale, {limited} precision limits at once, {rejected} rejected as too large",
        T::NAME
    );
    assert!(
        resolved >= scales.len() / 2 && limited >= 1 && rejected >= 1,
        "{}: every kind of answer should occur",
        T::NAME
    );
}

#[test]
fn f64_scales_from_1e_minus_300_to_1e300_cost_as_unit_scale_or_get_a_typed_answer() {
    let s: Vec<f64> = (-30..=30).map(|k| 10f64.powi(10 * k)).collect();
    scales::<f64>(&s);
}

#[test]
fn f32_scales_from_1e_minus_35_to_1e35_cost_as_unit_scale_or_get_a_typed_answer() {
    let s: Vec<f64> = (-7..=7).map(|k| 10f64.powi(5 * k)).collect();
    scales::<f32>(&s);
}

/// The smaller case: an icosphere at `1e6` in `f32` took 6.4 s for
/// one iteration (4.4 ms at `1e3`).
#[test]
fn an_f32_icosphere_at_1e6_gets_the_outcome_and_the_work_of_the_origin() {
    let tree = BallTree::try_from_mesh(&icosphere::<f32>(0.5, 3).expect("sphere")).expect("tree");
    let (far, near) = far_against_origin(&tree, 1e6);
    println!(
        "icosphere f32 at 1e6: contact at {:?} ({} node pairs), at the origin {:?} ({})",
        time(&far),
        far.work.node_pairs,
        time(&near),
        near.work.node_pairs
    );
}

/// `n` copies of one triangle (a degenerate mesh: every node's volume is the
/// triangle's), flown past the bunny. Every internal node pair has a step a
/// little below its leaves', so certifying a step visits every copy: 60
/// million node pairs and 79 s for the first query measured. The budget ends
/// it with a typed outcome, never late, with at most the budget's work.
#[test]
fn a_hundred_thousand_copies_of_one_triangle_stop_at_the_work_budget() {
    let n = 100_000u32;
    let mut vertices = Vec::with_capacity(3 * n as usize);
    let mut triangles = Vec::with_capacity(n as usize);
    for i in 0..n {
        vertices.extend([[0.0, 0.0, 0.0], [0.2, 0.0, 0.0], [0.0, 0.2, 0.0]]);
        triangles.push([3 * i, 3 * i + 1, 3 * i + 2]);
    }
    let copies = BallTree::try_new(&vertices, &triangles).expect("a tree of copies");
    let rabbit = BallTree::try_from_mesh(&bunny()).expect("tree");
    let (a, b, _) = fly_by::<f64>(0.0, 1.0);
    let budget = CaParams::<f64>::DEFAULT_WORK_BUDGET;
    let params = CaParams::default().with_contact_distance(CONTACT);
    let r = time_of_impact(&mut MeshPair::new(&copies, &rabbit), &a, &b, &params).expect("valid");
    println!("copies against the bunny: {r:?}");
    assert!(
        !r.work.exceeds(budget),
        "more work than the budget: {:?}",
        r.work
    );
    // The answer with the budget is never later than the one without, which
    // the same query with a single copy gives (its contact is the same).
    let one = BallTree::try_new(&vertices[..3], &triangles[..1]).expect("one triangle");
    let single = time_of_impact(&mut MeshPair::new(&one, &rabbit), &a, &b, &params).expect("valid");
    let t_single = time(&single).expect("the single triangle touches");
    match r.outcome {
        CaOutcome::WorkLimit { time } => assert!(time <= t_single, "late: {time} > {t_single}"),
        _ => {
            let t = time(&r).expect("a contact");
            assert!(t <= t_single, "late: {t} > {t_single}");
        }
    }
    // A smaller budget is honoured exactly too.
    let small = Work::new(1_000, 10);
    let r = time_of_impact(
        &mut MeshPair::new(&copies, &rabbit),
        &a,
        &b,
        &params.with_work_budget(small),
    )
    .expect("valid");
    assert!(
        matches!(r.outcome, CaOutcome::WorkLimit { .. }) && !r.work.exceeds(small),
        "{r:?}"
    );
}

/// A contact distance below what the placement resolves (a body of reach
/// `1e4` in `f32`, rounding about `0.1` a placement, with a contact distance
/// of `1e-6`): the query says so when the bodies come close, never later
/// than the first sampled intersection, instead of visiting every triangle
/// pair.
#[test]
fn a_contact_distance_below_the_resolution_is_a_precision_limit_with_little_work() {
    use motion_bound::testkit::ground_truth::{first_sampled_contact, MeshRef};
    let big = bunny()
        .scaled(2e4)
        .expect("big")
        .try_convert::<f32>()
        .expect("f32");
    let tree = BallTree::try_from_mesh(&big).expect("tree");
    let (a, b, _) = fly_by::<f32>(0.0, 2e4);
    let fine = query(&tree, &a, &b, 1e-6);
    let coarse = query(&tree, &a, &b, 1e-3 * 2e4);
    println!("f32 bunny at 2e4, contact distance 1e-6: {fine:?}; at 20: {coarse:?}");
    // The same geometry and motions in f64 (exact conversions), sampled.
    let big64 = big.try_convert::<f64>().expect("f64");
    let (a64, b64) = (to_f64(&a), to_f64(&b));
    let truth = first_sampled_contact(
        MeshRef::from(&big64),
        &a64,
        MeshRef::from(&big64),
        &b64,
        (0.0, 1.0),
        2_000,
    )
    .expect("the bodies meet");
    match fine.outcome {
        CaOutcome::PrecisionLimit { time, resolution } => {
            assert!(resolution > 5e-7, "{fine:?}");
            assert!(f64::from(time) <= truth, "late: {fine:?}, sampled {truth}");
        }
        _ => panic!("expected a precision limit: {fine:?}"),
    }
    assert!(
        fine.work.node_pairs <= 4 * coarse.work.node_pairs.max(1_000),
        "{fine:?} against {coarse:?}"
    );
}

/// An `f32` motion as an `f64` one (every value converts exactly).
fn to_f64(m: &RigidMotion<f32>) -> RigidMotion<f64> {
    let v = |x: Vec3<f32>| Vec3::from_array(x.to_array().map(f64::from));
    RigidMotion::try_new(
        Point3::from_array(m.centre().to_array().map(f64::from)),
        v(m.linear()),
        v(m.angular()),
        TimeInterval::UNIT,
    )
    .expect("valid")
}
