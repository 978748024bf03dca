//! A query in a steady loop allocates nothing: the trees are built once,
//! the mesh stepper's scratch space is a `MeshWorkspace` handed from pair to
//! pair, and the driver, the bounds and the steppers never touch the heap.
//! (The allocation counter is `allocation-counter`'s global allocator, which
//! only this test binary links.)

use motion_bound::bodies::{torus, TorusKnot};
use motion_bound::ca::{time_of_impact, BallPair, CaParams, MeshPair, MeshWorkspace};
use motion_bound::testkit::toi::{fly_by, reach, Rng};
use motion_bound::{BallTree, BoundingBall, Isometry, Point3, RigidMotion, Rotation, Vec3};

#[test]
fn a_steady_query_loop_allocates_nothing() {
    let knot = TorusKnot::TREFOIL.mesh::<f64>(60, 8).expect("knot");
    let ring = torus::<f64>(0.5, 0.08, 32, 8).expect("ring");
    let (tk, tr) = (
        BallTree::try_from_mesh(&knot).expect("tree"),
        BallTree::try_from_mesh(&ring).expect("tree"),
    );
    let r = reach(&knot).max(reach(&ring));
    let mut rng = Rng::new(3);
    let queries: Vec<_> = (0..60)
        .map(|k| {
            let q = fly_by(&mut rng, r, r, 6.0);
            let turn = Rotation::try_from_axis_angle(Vec3::new(1.0, 2.0, 3.0), 0.1 * k as f64)
                .expect("valid");
            let start = Isometry::try_new(turn, q.a.centre().to_vec3()).expect("finite");
            let a = RigidMotion::try_from_start(start, q.a.linear(), q.a.angular(), 1.0)
                .expect("valid");
            (a, q.b)
        })
        .collect();
    let params = CaParams::default().with_contact_distance(1e-3);
    let mut workspace = MeshWorkspace::new();
    let run = |workspace: MeshWorkspace<f64>| {
        let mut ws = workspace;
        let mut contacts = 0;
        for (k, (a, b)) in queries.iter().enumerate() {
            let (ta, tb) = if k % 2 == 0 { (&tk, &tr) } else { (&tr, &tk) };
            let mut pair = MeshPair::with_workspace(ta, tb, ws);
            let report = time_of_impact(&mut pair, a, b, &params).expect("valid");
            contacts += usize::from(report.outcome.contact().is_some());
            ws = pair.into_workspace();
            let ball = BoundingBall::try_new(Point3::ORIGIN.to_array(), r).expect("ball");
            let report = time_of_impact(&mut BallPair::new(ball, ball), a, b, &params).expect("ok");
            contacts += usize::from(report.outcome.contact().is_some());
        }
        (ws, contacts)
    };
    // Warm up: the workspace grows to the largest query.
    let (ws, warm) = run(workspace);
    workspace = ws;
    let mut steady = 0;
    let info = allocation_counter::measure(|| {
        let (ws, contacts) = run(std::mem::take(&mut workspace));
        workspace = ws;
        steady = contacts;
    });
    assert_eq!(steady, warm, "the same queries, the same outcomes");
    assert!(warm > 20, "the loop has contacts to find ({warm})");
    assert_eq!(
        info.count_total, 0,
        "{} allocations ({} bytes) in the steady loop",
        info.count_total, info.bytes_total
    );
    // The counter counts: a fresh pair allocates its workspace as it grows.
    let (a, b) = &queries[0];
    let fresh = allocation_counter::measure(|| {
        let mut pair = MeshPair::new(&tk, &tr);
        let _ = time_of_impact(&mut pair, a, b, &params);
    });
    assert!(
        fresh.count_total > 0,
        "a fresh pair allocates its scratch space"
    );
}

/// A scene frame loop: the same scene re-queried with new motions each frame
/// (`Scene::try_set_motion`), one `SceneWorkspace`: nothing allocated once
/// the workspace has grown.
#[test]
fn a_steady_scene_frame_loop_allocates_nothing() {
    use motion_bound::ca::Shape;
    use motion_bound::scene::{Scene, SceneParams, SceneWorkspace};
    use motion_bound::TimeInterval;
    let ring = torus::<f64>(0.5, 0.1, 24, 8).expect("ring");
    let tree = BallTree::try_from_mesh(&ring).expect("tree");
    let mut rng = Rng::new(11);
    let frames: Vec<Vec<RigidMotion<f64>>> = (0..6)
        .map(|_| {
            (0..24)
                .map(|_| {
                    let x0 = [0, 1, 2].map(|_| rng.range(-3.0, 3.0));
                    let v = rng.direction().map(|x| x * rng.range(0.0, 1.5));
                    let w = rng.direction().map(|x| x * rng.range(0.0, 5.0));
                    RigidMotion::try_from_arrays(x0, v, w).expect("motion")
                })
                .collect()
        })
        .collect();
    let mut scene = Scene::try_new(TimeInterval::try_new(0.0, 1.0).expect("frame")).expect("scene");
    for m in &frames[0] {
        scene.try_add(Shape::Mesh(&tree), *m).expect("body");
    }
    let params = SceneParams::default();
    let mut ws = SceneWorkspace::new();
    let run = |scene: &mut Scene<'_, f64>, ws: &mut SceneWorkspace<f64>| {
        let mut tested = 0;
        for frame in &frames {
            for (i, m) in frame.iter().enumerate() {
                scene.try_set_motion(i, *m).expect("same frame");
            }
            tested += scene.query(ws, &params).expect("valid").pairs().len();
        }
        tested
    };
    let warm = run(&mut scene, &mut ws);
    let mut steady = 0;
    let info = allocation_counter::measure(|| steady = run(&mut scene, &mut ws));
    assert_eq!(steady, warm, "the same frames, the same pairs");
    assert!(warm > 10, "the frames have pairs to test ({warm})");
    assert_eq!(
        info.count_total, 0,
        "{} allocations ({} bytes) in the steady frame loop",
        info.count_total, info.bytes_total
    );
}

/// The same for a scene of every kind (a ground, convex shapes, a mesh, a
/// compound): every pair family's stepper shares the scene's workspace.
#[test]
fn a_steady_mixed_scene_frame_loop_allocates_nothing() {
    use motion_bound::ca::{Compound, Part, Shape};
    use motion_bound::scene::{Scene, SceneParams, SceneWorkspace};
    use motion_bound::{Convex, HalfSpace, TimeInterval};
    let ring = torus::<f64>(0.5, 0.1, 24, 8).expect("ring");
    let tree = BallTree::try_from_mesh(&ring).expect("tree");
    let at = |x: f64| Isometry::try_from_translation(Vec3::new(x, 0.0, 0.0)).expect("pose");
    let dumbbell = Compound::try_new(vec![
        Part::Convex(
            Convex::try_ball(0.3)
                .and_then(|b| b.try_placed(at(-0.6)))
                .expect("ball"),
        ),
        Part::Convex(
            Convex::try_ball(0.3)
                .and_then(|b| b.try_placed(at(0.6)))
                .expect("ball"),
        ),
        Part::Mesh(&tree),
    ])
    .expect("compound");
    let shapes = [
        Shape::Convex(Convex::try_ball(0.4).expect("ball")),
        Shape::Convex(Convex::try_capsule(0.4, 0.2).expect("capsule")),
        Shape::Convex(Convex::try_cuboid([0.3, 0.4, 0.2]).expect("cuboid")),
        Shape::Convex(Convex::try_cylinder(0.4, 0.3).expect("cylinder")),
        Shape::Mesh(&tree),
        Shape::Compound(&dumbbell),
    ];
    let mut rng = Rng::new(12);
    let frames: Vec<Vec<RigidMotion<f64>>> = (0..6)
        .map(|_| {
            (0..24)
                .map(|_| {
                    let x0 = [
                        rng.range(-2.5, 2.5),
                        rng.range(0.0, 2.0),
                        rng.range(-2.5, 2.5),
                    ];
                    let v = rng.direction().map(|x| x * rng.range(0.0, 1.5));
                    let w = rng.direction().map(|x| x * rng.range(0.0, 5.0));
                    RigidMotion::try_from_arrays(x0, v, w).expect("motion")
                })
                .collect()
        })
        .collect();
    let mut scene = Scene::try_new(TimeInterval::try_new(0.0, 1.0).expect("frame")).expect("scene");
    let ground = HalfSpace::try_new(Vec3::new(0.0, 1.0, 0.0)).expect("ground");
    let still = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0; 3]).expect("still");
    scene
        .try_add(Shape::HalfSpace(ground), still)
        .expect("ground");
    for (i, m) in frames[0].iter().enumerate() {
        scene.try_add(shapes[i % shapes.len()], *m).expect("body");
    }
    let params = SceneParams::default();
    let mut ws = SceneWorkspace::new();
    let run = |scene: &mut Scene<'_, f64>, ws: &mut SceneWorkspace<f64>| {
        let (mut tested, mut contacts) = (0, 0);
        for frame in &frames {
            for (i, m) in frame.iter().enumerate() {
                scene.try_set_motion(i + 1, *m).expect("same frame");
            }
            let report = scene.query(ws, &params).expect("valid");
            tested += report.pairs().len();
            contacts += report.contacts().count();
        }
        (tested, contacts)
    };
    let warm = run(&mut scene, &mut ws);
    let mut steady = (0, 0);
    let info = allocation_counter::measure(|| steady = run(&mut scene, &mut ws));
    assert_eq!(steady, warm, "the same frames, the same pairs");
    assert!(
        warm.0 > 20 && warm.1 > 5,
        "the frames have pairs and contacts ({warm:?})"
    );
    assert_eq!(
        info.count_total, 0,
        "{} allocations ({} bytes) in the steady mixed frame loop",
        info.count_total, info.bytes_total
    );
}
