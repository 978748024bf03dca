//! The scene query (`proofs/11-scene.md`): swept boxes hold their bodies
//! (Lemma 11.1, against independent placement), culled pairs never come
//! within the contact distance and tested pairs are never late (Lemma 11.2,
//! against sampled ground truth), every skip shows in its counter
//! (Lemma 11.3), and the parallel query reports what the serial one does.

mod common;

use motion_bound::bodies;
use motion_bound::ca::{CaOutcome, CaParams, Shape, ShapeKind};
use motion_bound::scene::{Groups, Scene, SceneParams, SceneQueryError, SceneWorkspace, SweptBox};
use motion_bound::testkit::ground_truth::{first_sampled_contact, place, MeshRef};
use motion_bound::testkit::toi::Rng;
use motion_bound::{
    BallTree, BoundingBall, Float, Isometry, RigidMotion, Rotation, TimeInterval, Vec3, VertexSet,
};
use proptest::prelude::*;

/// A body's motion over `[0, duration]` in `f32` or `f64`, as components
/// (so that the same exact motion can be built in both precisions).
#[derive(Clone, Debug)]
struct MotionSpec {
    x0: [f64; 3],
    v: [f64; 3],
    w: [f64; 3],
    q: [f64; 4],
    local_centre: [f64; 3],
    duration: f64,
}

impl MotionSpec {
    fn build<T: Float>(&self) -> RigidMotion<T> {
        let c = |a: [f64; 3]| Vec3::from_array(a.map(T::from_f64));
        let q = self.q.map(T::from_f64);
        let start = Isometry::try_new(
            Rotation::try_from_quaternion(q[0], q[1], q[2], q[3]).expect("non-zero quaternion"),
            c(self.x0),
        )
        .expect("finite pose");
        RigidMotion::try_from_start(start, c(self.v), c(self.w), T::from_f64(self.duration))
            .expect("finite motion")
            .try_with_local_centre(c(self.local_centre))
            .expect("finite centre")
    }
}

/// The same exact motion in `f64`: every component of the `T` motion is
/// converted exactly (the start quaternion as stored, which the ground truth
/// normalises itself).
fn widen<T: Float>(m: &RigidMotion<T>) -> RigidMotion<f64> {
    let w = |v: Vec3<T>| Vec3::from_array(v.to_array().map(Float::to_f64));
    let q = m.orientation().quaternion().map(Float::to_f64);
    RigidMotion::try_about_centre(
        motion_bound::Point3::from_array(m.centre().to_array().map(Float::to_f64)),
        w(m.local_centre()),
        Rotation::try_from_quaternion(q[0], q[1], q[2], q[3]).expect("unit"),
        w(m.linear()),
        w(m.angular()),
        m.interval().end().to_f64(),
    )
    .expect("finite")
}

fn vec3(scale: f64) -> impl Strategy<Value = [f64; 3]> {
    prop::array::uniform3(-scale..scale)
}

/// Half the motions keep a zero velocity or a zero spin (the static and
/// translation-only paths).
fn motion_spec() -> impl Strategy<Value = MotionSpec> {
    (
        vec3(10.0),
        prop_oneof![Just([0.0; 3]), vec3(20.0)],
        prop_oneof![Just([0.0; 3]), vec3(15.0), vec3(0.5)],
        prop::array::uniform4(-1.0..1.0f64)
            .prop_filter("non-zero", |q| q.iter().map(|x| x * x).sum::<f64>() > 1e-3),
        prop_oneof![Just([0.0; 3]), vec3(1.0)],
        0.01..2.0f64,
    )
        .prop_map(|(x0, v, w, q, local_centre, duration)| MotionSpec {
            x0,
            v,
            w,
            q,
            local_centre,
            duration,
        })
}

/// Points on (just inside) the ball's sphere: the 26 directions of the
/// cube's faces, edges and corners.
fn sphere_points(centre: [f64; 3], radius: f64) -> Vec<[f64; 3]> {
    let mut out = vec![centre];
    for i in -1..=1i32 {
        for j in -1..=1i32 {
            for k in -1..=1i32 {
                if (i, j, k) == (0, 0, 0) {
                    continue;
                }
                let d = [f64::from(i), f64::from(j), f64::from(k)];
                let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
                let s = radius * (1.0 - 1e-12) / l;
                out.push([0, 1, 2].map(|a| centre[a] + s * d[a]));
            }
        }
    }
    out
}

/// Checks Lemma 11.1 at 65 times: every sampled point of the ball, placed
/// by the ground truth's own quaternion code, inside the box, up to `tol`
/// (the `f64` ground truth's own rounding; zero for `f32` boxes, which an
/// `f64` placement resolves far below their rounding).
fn check_box<T: Float>(
    spec: &MotionSpec,
    centre: [f64; 3],
    radius: f64,
    tol_rel: f64,
) -> Result<(), TestCaseError> {
    let m = spec.build::<T>();
    let ball = BoundingBall::try_new(centre.map(T::from_f64), T::from_f64(radius)).expect("ball");
    let swept = SweptBox::new(&ball, &m);
    let (lo, hi) = (
        swept.lo().to_array().map(Float::to_f64),
        swept.hi().to_array().map(Float::to_f64),
    );
    let exact = widen(&m);
    let c = ball.centre().map(Float::to_f64);
    let rho = ball.radius().to_f64();
    let l1 = |a: [f64; 3]| a.iter().map(|x| x.abs()).sum::<f64>();
    let t_end = exact.interval().end();
    let scale = l1(exact.centre().to_array())
        + l1(exact.linear().to_array()) * t_end
        + l1(c)
        + rho
        + l1(exact.local_centre().to_array());
    let tol = tol_rel * scale;
    for j in 0..=64 {
        let t = t_end * f64::from(j) / 64.0;
        for r in sphere_points(c, rho) {
            let p = place(&exact, r, t);
            for k in 0..3 {
                prop_assert!(
                    p[k] >= lo[k] - tol && p[k] <= hi[k] + tol,
                    "({}) point {r:?} at t = {t} is at {p:?}, outside the box {lo:?} .. {hi:?} along {k}",
                    core::any::type_name::<T>()
                );
            }
        }
    }
    // Tighter than the ball grown by the crude speed |v| + |w| (|s| + rho + |c|).
    let norm = |a: [f64; 3]| l1(a.map(|x| x * x)).sqrt();
    let crude = norm(exact.linear().to_array())
        + norm(exact.angular().to_array())
            * (norm(c) + rho + norm(exact.local_centre().to_array()));
    for k in 0..3 {
        let width = hi[k] - lo[k];
        let sphere = 2.0 * (rho + crude * t_end);
        prop_assert!(
            width <= sphere * (1.0 + 1e-4) + 1e-4 * scale,
            "({}) width {width} along {k} above the crude sphere's {sphere}",
            core::any::type_name::<T>()
        );
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(common::cases()))]

    /// Lemma 11.1 in `f32` (no tolerance: the `f64` ground truth is exact at
    /// `f32`'s resolution) and in `f64` (up to the ground truth's own
    /// rounding, `1e-14` of the reach: about 45 ulps).
    #[test]
    fn a_swept_box_holds_its_body_throughout_the_frame(
        spec in motion_spec(),
        centre in vec3(2.0),
        radius in 0.0..2.0f64,
    ) {
        check_box::<f32>(&spec, centre, radius, 0.0)?;
        check_box::<f64>(&spec, centre, radius, 1e-14)?;
    }
}

/// A scene of `n` unit-ish balls over `[0, 1]`, a third static, a third
/// translating, a third turning, spread over a cube of side `side`.
fn ball_scene(rng: &mut Rng, n: usize, side: f64) -> Vec<(BoundingBall<f64>, RigidMotion<f64>)> {
    (0..n)
        .map(|i| {
            let ball = BoundingBall::try_new(rng.direction().map(|x| 0.3 * x), rng.range(0.2, 0.6))
                .expect("ball");
            let x0 = [0, 1, 2].map(|_| rng.range(-side / 2.0, side / 2.0));
            let v = match i % 3 {
                0 => [0.0; 3],
                _ => rng.direction().map(|x| x * rng.range(0.0, 3.0)),
            };
            let w = match i % 3 {
                2 => rng.direction().map(|x| x * rng.range(0.0, 8.0)),
                _ => [0.0; 3],
            };
            (
                ball,
                RigidMotion::try_from_arrays(x0, v, w).expect("motion"),
            )
        })
        .collect()
}

/// The sampled distance between two balls (centres placed independently).
fn ball_distance(
    (ba, ma): &(BoundingBall<f64>, RigidMotion<f64>),
    (bb, mb): &(BoundingBall<f64>, RigidMotion<f64>),
    t: f64,
) -> f64 {
    let (pa, pb) = (place(ma, *ba.centre(), t), place(mb, *bb.centre(), t));
    let d = [0, 1, 2].map(|k| pb[k] - pa[k]);
    (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt() - ba.radius() - bb.radius()
}

/// Lemma 11.2 and the narrow phase on balls: over 20 random scenes of 60
/// balls, every pair not reported stays beyond the contact distance at 257
/// sampled times, and every reported pair's contact is never later than the
/// first sampled time within the clearance (half the contact distance), and
/// `Separated` only without one.
#[test]
fn culled_ball_pairs_never_touch_and_tested_ones_are_never_late() {
    let d = 0.05;
    let params = SceneParams::default().with_ca(CaParams::default().with_contact_distance(d));
    let mut ws = SceneWorkspace::new();
    let (mut culled, mut tested, mut contacts) = (0, 0, 0);
    for seed in 0..20 {
        let mut rng = Rng::new(seed);
        let bodies = ball_scene(&mut rng, 60, 14.0);
        let mut scene = Scene::try_new(TimeInterval::try_new(0.0, 1.0).unwrap()).unwrap();
        for (ball, m) in &bodies {
            scene.try_add(Shape::Ball(*ball), *m).unwrap();
        }
        let report = scene.query(&mut ws, &params).unwrap();
        let reported: std::collections::BTreeMap<(usize, usize), CaOutcome<f64>> = report
            .pairs()
            .iter()
            .map(|p| ((p.a, p.b), p.report.outcome))
            .collect();
        for i in 0..bodies.len() {
            for j in i + 1..bodies.len() {
                let times = || (0..=256).map(|k| f64::from(k) / 256.0);
                // Culled pairs stay beyond the contact distance; a tested
                // pair's contact comes no later than the distance's first
                // fall to the clearance, half of it (`CaParams::clearance`).
                let first = times().find(|&t| ball_distance(&bodies[i], &bodies[j], t) <= d);
                let first_clear =
                    times().find(|&t| ball_distance(&bodies[i], &bodies[j], t) <= d / 2.0);
                match reported.get(&(i, j)) {
                    None => {
                        let both_static = i % 3 == 0 && j % 3 == 0;
                        assert!(
                            both_static || first.is_none(),
                            "seed {seed}: culled pair ({i}, {j}) within {d} at t = {first:?}"
                        );
                        culled += 1;
                    }
                    Some(outcome) => {
                        tested += 1;
                        match (outcome.earliest_possible_contact(), first_clear) {
                            (Some(t), Some(s)) => {
                                contacts += 1;
                                assert!(t <= s, "seed {seed}: pair ({i}, {j}) late: {t} > {s}");
                            }
                            (None, Some(s)) => {
                                panic!("seed {seed}: pair ({i}, {j}) missed the contact at {s}")
                            }
                            _ => {}
                        }
                    }
                }
            }
        }
    }
    println!("balls: {culled} pairs culled, {tested} tested, {contacts} sampled contacts");
    assert!(
        culled > 10 * tested && contacts > 20,
        "the scenes exercise both"
    );
}

/// The same on meshes: eight tumbling tori sharing one tree, close enough to
/// hit each other, against sampled exact intersection.
#[test]
fn mesh_scene_pairs_match_sampled_ground_truth() {
    let mesh = bodies::torus::<f64>(0.5, 0.15, 24, 12).unwrap();
    let tree = BallTree::try_from_mesh(&mesh).unwrap();
    let mr = MeshRef::from(&mesh);
    let params = SceneParams::default();
    let mut ws = SceneWorkspace::new();
    let (mut tested, mut contacts, mut culled) = (0, 0, 0);
    for seed in 0..6 {
        let mut rng = Rng::new(100 + seed);
        let mut scene = Scene::try_new(TimeInterval::try_new(0.0, 1.0).unwrap()).unwrap();
        let motions: Vec<RigidMotion<f64>> = (0..8)
            .map(|_| {
                let x0 = [0, 1, 2].map(|_| rng.range(-2.0, 2.0));
                let v = rng.direction().map(|x| x * rng.range(0.0, 2.0));
                let w = rng.direction().map(|x| x * rng.range(0.0, 6.0));
                RigidMotion::try_from_arrays(x0, v, w).unwrap()
            })
            .collect();
        for m in &motions {
            scene.try_add(Shape::Mesh(&tree), *m).unwrap();
        }
        let report = scene.query(&mut ws, &params).unwrap();
        for i in 0..8 {
            for j in i + 1..8 {
                let truth =
                    first_sampled_contact(mr, &motions[i], mr, &motions[j], (0.0, 1.0), 129);
                match report.pairs().iter().find(|p| (p.a, p.b) == (i, j)) {
                    None => {
                        culled += 1;
                        assert!(
                            truth.is_none(),
                            "seed {seed}: culled ({i}, {j}) meets at {truth:?}"
                        );
                    }
                    Some(p) => {
                        tested += 1;
                        let t = p.report.outcome.earliest_possible_contact();
                        if let Some(s) = truth {
                            contacts += 1;
                            let t =
                                t.unwrap_or_else(|| panic!("seed {seed}: ({i}, {j}) missed {s}"));
                            assert!(t <= s, "seed {seed}: ({i}, {j}) late: {t} > {s}");
                        }
                    }
                }
            }
        }
    }
    println!("tori: {culled} culled, {tested} tested, {contacts} sampled contacts");
    assert!(culled > 0 && contacts > 5, "the scenes exercise both");
}

/// Lemma 11.3's shortcuts, each shown by its counter.
#[test]
fn every_skip_shows_in_its_counter() {
    let cube: Vec<[f64; 3]> = (0..8)
        .map(|i| [0, 1, 2].map(|k| if i >> k & 1 == 1 { 0.5 } else { -0.5 }))
        .collect();
    let set = VertexSet::try_new(&cube).unwrap();
    let frame = TimeInterval::try_new(0.0, 1.0).unwrap();
    let mut scene = Scene::try_new(frame).unwrap();
    let still = |x: f64| Isometry::try_from_translation(Vec3::new(x, 0.0, 0.0)).unwrap();
    // Two static cubes touching each other, far from the rest.
    scene
        .try_add_static(Shape::VertexSet(set), still(100.0))
        .unwrap();
    scene
        .try_add_static(Shape::VertexSet(set), still(100.9))
        .unwrap();
    // Two cubes translating at each other, a turning one far away.
    let a = scene
        .try_add(
            Shape::VertexSet(set),
            RigidMotion::try_from_arrays([-2.0, 0.0, 0.0], [3.0, 0.0, 0.0], [0.0; 3]).unwrap(),
        )
        .unwrap();
    let b = scene
        .try_add(
            Shape::VertexSet(set),
            RigidMotion::try_from_arrays([2.0, 0.0, 0.0], [-1.0, 0.0, 0.0], [0.0; 3]).unwrap(),
        )
        .unwrap();
    scene
        .try_add(
            Shape::VertexSet(set),
            RigidMotion::try_from_arrays([0.0, -50.0, 0.0], [0.0; 3], [0.0, 0.0, 5.0]).unwrap(),
        )
        .unwrap();
    let mut ws = SceneWorkspace::new();
    let s = scene
        .query(&mut ws, &SceneParams::default())
        .unwrap()
        .stats();
    assert_eq!(
        (s.static_bodies, s.translating_bodies, s.turning_bodies),
        (2, 2, 1),
        "{s:?}"
    );
    assert_eq!((s.box_rates, s.box_rates_skipped), (6, 24), "{s:?}");
    assert_eq!((s.pairs_all, s.pairs_static), (10, 1), "{s:?}");
    assert_eq!((s.pairs_tested, s.pairs_culled), (1, 8), "{s:?}");
    // Neither cube of the tested pair turns: NEVQ alone at every step.
    assert!(s.evq_skipped > 0 && s.evq_evaluated == 0, "{s:?}");
    let t = ws.report().earliest_for(a).unwrap();
    assert_eq!(t.1, b);
    // The faces meet at t = 3 / 4.
    assert!(t.0 <= 0.75 && t.0 > 0.75 - 1e-4, "{t:?}");

    // The filter and the groups.
    let s = scene
        .query_filtered(&mut ws, &SceneParams::default(), |i, j| (i, j) != (a, b))
        .unwrap()
        .stats();
    assert_eq!((s.pairs_filtered, s.pairs_tested), (1, 0), "{s:?}");
    assert!(ws.report().pairs().is_empty() && ws.report().earliest().is_none());
    scene.try_set_groups(a, Groups::NONE).unwrap();
    let s = scene
        .query(&mut ws, &SceneParams::default())
        .unwrap()
        .stats();
    assert_eq!((s.pairs_filtered, s.pairs_tested), (1, 0), "{s:?}");
}

#[test]
fn bad_scenes_are_typed_errors() {
    let tree = BallTree::try_from_mesh(&bodies::torus::<f64>(0.5, 0.1, 8, 4).unwrap()).unwrap();
    let ball = BoundingBall::try_new([0.0; 3], 1.0).unwrap();
    let mut scene = Scene::try_new(TimeInterval::try_new(0.0, 1.0).unwrap()).unwrap();
    let m = RigidMotion::try_from_arrays([0.0; 3], [1.0, 0.0, 0.0], [0.0; 3]).unwrap();
    scene.try_add(Shape::Mesh(&tree), m).unwrap();
    // Kinds mix (an earlier version refused a ball among meshes).
    assert_eq!(scene.try_add(Shape::Ball(ball), m), Ok(1));
    assert_eq!(scene.bodies()[1].shape().kind(), ShapeKind::Ball);
    let other = m.restrict(0.0, 0.5).unwrap();
    assert_eq!(
        scene.try_add(Shape::Mesh(&tree), other).err(),
        Some(SceneQueryError::IntervalMismatch { body: 2 })
    );
    assert_eq!(
        scene.try_set_motion(7, m).err(),
        Some(SceneQueryError::UnknownBody(7))
    );
    let bad = SceneParams::default().with_ca(CaParams::default().with_contact_distance(-1.0));
    assert!(matches!(
        scene.query(&mut SceneWorkspace::new(), &bad),
        Err(SceneQueryError::Ca(_))
    ));
}

/// Point 4: the parallel narrow phase reports what the serial one does, pair
/// for pair, on 1, 2 and 3 threads.
#[cfg(feature = "parallel")]
#[test]
fn the_parallel_query_reports_what_the_serial_one_does() {
    let mesh = bodies::torus::<f64>(0.5, 0.15, 24, 12).unwrap();
    let tree = BallTree::try_from_mesh(&mesh).unwrap();
    let mut rng = Rng::new(7);
    let mut scene = Scene::try_new(TimeInterval::try_new(0.0, 1.0).unwrap()).unwrap();
    for _ in 0..40 {
        let x0 = [0, 1, 2].map(|_| rng.range(-4.0, 4.0));
        let v = rng.direction().map(|x| x * rng.range(0.0, 2.0));
        let w = rng.direction().map(|x| x * rng.range(0.0, 6.0));
        scene
            .try_add(
                Shape::Mesh(&tree),
                RigidMotion::try_from_arrays(x0, v, w).unwrap(),
            )
            .unwrap();
    }
    let params = SceneParams::default();
    let mut ws = SceneWorkspace::new();
    let serial = scene.query(&mut ws, &params).unwrap().clone();
    assert!(serial.pairs().len() > 10, "{} pairs", serial.pairs().len());
    for threads in 1..=3 {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        let mut pws = SceneWorkspace::new();
        let parallel = pool.install(|| scene.par_query(&mut pws, &params).unwrap().clone());
        assert_eq!(parallel.pairs(), serial.pairs(), "{threads} threads");
        assert_eq!(parallel.stats(), serial.stats(), "{threads} threads");
        for b in 0..scene.len() {
            assert_eq!(parallel.earliest_for(b), serial.earliest_for(b));
        }
    }
}

/// A scene of every kind at once (issue 26: `MixedShapes` is gone): a moving
/// ground, balls, capsules, boxes, cylinders, cones, a rounded box, a vertex
/// set and a mesh, thrown about. Every pair the broad phase keeps gets
/// exactly the report of the pair's own stepper (`AnyPair`, or the
/// family's stepper for two meshes, two vertex sets, two balls), and no
/// pair it culls has a contact by that stepper: the culling is certified.
#[test]
fn a_scene_of_every_kind_matches_each_pair_alone_and_culls_only_what_cannot_touch() {
    use motion_bound::ca::{time_of_impact, AnyPair};
    use motion_bound::{Convex, HalfSpace};
    let ring = BallTree::try_from_mesh(&bodies::torus::<f64>(0.3, 0.06, 16, 6).unwrap()).unwrap();
    let hull = [
        [0.2, 0.0, 0.0],
        [-0.1, 0.17, 0.0],
        [-0.1, -0.17, 0.0],
        [0.0, 0.0, 0.25],
    ];
    let set = VertexSet::try_new(&hull).unwrap();
    let shapes: Vec<Shape<'_, f64>> = vec![
        Shape::Convex(Convex::try_ball(0.2).unwrap()),
        Shape::Convex(Convex::try_capsule(0.2, 0.1).unwrap()),
        Shape::Convex(Convex::try_cuboid([0.2, 0.15, 0.1]).unwrap()),
        Shape::Convex(Convex::try_cylinder(0.2, 0.15).unwrap()),
        Shape::Convex(Convex::try_cone(0.2, 0.15).unwrap()),
        Shape::Convex(
            Convex::try_cuboid([0.1; 3])
                .unwrap()
                .try_rounded(0.05)
                .unwrap(),
        ),
        Shape::VertexSet(set),
        Shape::Ball(BoundingBall::try_new([0.05, 0.0, 0.0], 0.15).unwrap()),
        Shape::Mesh(&ring),
    ];
    let frame = TimeInterval::try_new(0.0, 0.5).unwrap();
    let mut rng = Rng::new(2612);
    let (mut tested, mut culled, mut contacts) = (0, 0, 0);
    for round in 0..6 {
        let mut scene = Scene::try_new(frame).unwrap();
        let ground = HalfSpace::try_new(Vec3::new(0.0, 1.0, 0.0)).unwrap();
        let rise = if round % 2 == 0 { 0.0 } else { 0.3 };
        let mg = RigidMotion::try_new(
            motion_bound::Point3::new(0.0, -0.5, 0.0),
            Vec3::new(0.0, rise, 0.0),
            Vec3::ZERO,
            frame,
        )
        .unwrap();
        scene.try_add(Shape::HalfSpace(ground), mg).unwrap();
        for shape in &shapes {
            for _ in 0..2 {
                let m = RigidMotion::try_new(
                    motion_bound::Point3::new(
                        rng.range(-1.2, 1.2),
                        rng.range(-0.4, 0.8),
                        rng.range(-1.2, 1.2),
                    ),
                    Vec3::from_array(rng.direction().map(|x| x * rng.range(0.0, 3.0))),
                    Vec3::from_array(rng.direction().map(|x| x * rng.range(0.0, 6.0))),
                    frame,
                )
                .unwrap();
                scene.try_add(*shape, m).unwrap();
            }
        }
        let params =
            SceneParams::default().with_ca(CaParams::default().with_contact_distance(1e-3));
        let mut ws = SceneWorkspace::new();
        let report = scene.query(&mut ws, &params).unwrap();
        let bodies = scene.bodies();
        for i in 0..bodies.len() {
            for j in i + 1..bodies.len() {
                let (bi, bj) = (&bodies[i], &bodies[j]);
                if matches!(
                    (bi.shape(), bj.shape()),
                    (Shape::HalfSpace(_), Shape::HalfSpace(_))
                ) {
                    continue;
                }
                let kept = report.pairs().iter().find(|p| (p.a, p.b) == (i, j));
                let alone = time_of_impact(
                    &mut AnyPair::try_new(*bi.shape(), *bj.shape()).unwrap(),
                    bi.motion(),
                    bj.motion(),
                    &params.ca,
                )
                .unwrap();
                // Through the general convex stepper: another computation,
                // whose steps (and the balls the driver steps fast turns by,
                // Lemma 9.8) differ, so only the verdict must agree.
                let general = time_of_impact(
                    &mut AnyPair::try_new(any_shape(bi), any_shape(bj)).unwrap(),
                    bi.motion(),
                    bj.motion(),
                    &params.ca,
                )
                .unwrap();
                assert_eq!(
                    general.outcome.earliest_possible_contact().is_some(),
                    alone.outcome.earliest_possible_contact().is_some(),
                    "pair ({i}, {j}): {general:?} against {alone:?}"
                );
                match kept {
                    Some(p) => {
                        tested += 1;
                        contacts += usize::from(p.report.outcome.contact().is_some());
                        let ta = p.report.outcome.earliest_possible_contact();
                        let tb = alone.outcome.earliest_possible_contact();
                        assert_eq!(
                            ta.is_some(),
                            tb.is_some(),
                            "pair ({i}, {j}): {p:?} alone {alone:?}"
                        );
                        if let (Some(x), Some(y)) = (ta, tb) {
                            assert!((x - y).abs() <= 1e-9, "pair ({i}, {j}): {x} against {y}");
                        }
                    }
                    None => {
                        culled += 1;
                        assert!(
                            alone.outcome.contact().is_none(),
                            "culled pair ({i}, {j}) touches: {alone:?}"
                        );
                    }
                }
            }
        }
    }
    println!("mixed scenes: {tested} pairs tested ({contacts} contacts), {culled} culled and contact-free");
    assert!(
        tested > 50 && culled > 50 && contacts > 5,
        "too little of either to mean anything"
    );
}

/// A scene body's shape as the general convex stepper takes it: vertex sets
/// as polytopes and balls as rounded points, so that a pair alone goes
/// through another stepper than the dispatch's fast paths for two vertex sets
/// (GJK on the points) and two balls (closed form).
fn any_shape<'s>(
    b: &'s motion_bound::scene::SceneBody<'_, f64>,
) -> motion_bound::ca::Shape<'s, f64> {
    use motion_bound::Convex;
    match *b.shape() {
        Shape::Convex(c) => Shape::Convex(c),
        Shape::HalfSpace(h) => Shape::HalfSpace(h),
        Shape::Mesh(t) => Shape::Mesh(t),
        Shape::VertexSet(v) => Shape::Convex(Convex::polytope(v)),
        Shape::Ball(_) => {
            let ball = b.bounding_ball();
            let c = VertexSet::try_new(std::slice::from_ref(ball.centre())).unwrap();
            Shape::Convex(Convex::polytope(c).try_rounded(ball.radius()).unwrap())
        }
        _ => unreachable!("every kind is listed"),
    }
}
