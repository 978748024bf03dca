//! Motion that maps a shape onto itself is not motion (`proofs/12-shapes.md`,
//! Lemma 12.5): a ball sliding along a wall or rolling on a floor while it
//! spins about its centre, a wheel rolling about its axle, a capsule and a
//! cone spinning about their axes, each 1.01 to 10 contact distances from a
//! wall or a floor (a cuboid, a half-space, a 12-triangle mesh), rounded or
//! not, in `f32` and `f64`, are `Separated` within three iterations over an
//! engine's step, by `AnyPair` and through a scene. Before Lemma 12.5 the
//! spinning ball ended in `IterationLimit` after 116 iterations.
//!
//! The same motions turned towards the obstacle (a control) must still
//! report their contact: the reduction takes away only motion that moves no
//! surface.

use motion_bound::bodies::cuboid;
use motion_bound::ca::{time_of_impact, AnyPair, CaOutcome, CaParams, CaReport, Shape};
use motion_bound::scene::{Scene, SceneParams, SceneWorkspace};
use motion_bound::{
    BallTree, Convex, Float, HalfSpace, Isometry, RigidMotion, Rotation, TimeInterval, Vec3,
};

const CONTACT: f64 = 1e-4;
const DT: f64 = 1.0 / 60.0;

/// A moving body: its name, its shape and its motion.
struct Case<T: Float> {
    name: String,
    shape: Convex<'static, T>,
    motion: RigidMotion<T>,
}

fn v<T: Float>(a: [f64; 3]) -> Vec3<T> {
    Vec3::new(T::from_f64(a[0]), T::from_f64(a[1]), T::from_f64(a[2]))
}

/// The cases, each `gap` above the floor `y = 0` (its lowest point at
/// `y = gap`), moving over `[0, DT]`, with `toward` added to its velocity
/// along `-y`.
fn cases<T: Float>(gap: f64, toward: f64) -> Vec<Case<T>> {
    let t = T::from_f64;
    let mut out = Vec::new();
    for rounding in [0.0, 0.01] {
        let round = |s: Convex<'static, T>| {
            if rounding > 0.0 {
                s.try_rounded(t(rounding)).expect("rounded")
            } else {
                s
            }
        };
        let r = 0.05;
        // A ball sliding along the floor (down a wall, turned) while spinning
        // about its centre at 24 rad/s about a slanted axis.
        let ball = Convex::try_ball(t(r + rounding)).expect("ball");
        let centre = [0.3, gap + r + rounding, -0.2];
        out.push(Case {
            name: format!("ball sliding and spinning, rounding {rounding}"),
            shape: ball,
            motion: motion(
                centre,
                [0.0; 3],
                [3.0, -toward, 1.0],
                [14.0, 9.0, -17.0],
                None,
            ),
        });
        // The same ball rolling along x: w = v / r about -z.
        let rr = r + rounding;
        out.push(Case {
            name: format!("ball rolling, rounding {rounding}"),
            shape: ball,
            motion: motion(
                centre,
                [0.0; 3],
                [2.0, -toward, 0.0],
                [0.0, 0.0, -2.0 / rr],
                None,
            ),
        });
        // A wheel: a cylinder of radius 0.05, half width 0.02, its axle along z
        // (the shape's y turned onto z), rolling along x.
        let axle =
            Rotation::try_from_axis_angle(v([1.0, 0.0, 0.0]), t(core::f64::consts::FRAC_PI_2))
                .expect("rotation");
        let wheel = round(Convex::try_cylinder(t(0.02), t(r)).expect("wheel"));
        out.push(Case {
            name: format!("wheel rolling, rounding {rounding}"),
            shape: wheel,
            motion: motion(
                [0.0, gap + rr, 0.0],
                [0.0; 3],
                [3.0, -toward, 0.0],
                [0.0, 0.0, -3.0 / rr],
                Some(axle),
            ),
        });
        // A capsule lying along x (its y turned onto x), spinning about its
        // own axis at 40 rad/s and sliding along z.
        let lying =
            Rotation::try_from_axis_angle(v([0.0, 0.0, 1.0]), t(-core::f64::consts::FRAC_PI_2))
                .expect("rotation");
        out.push(Case {
            name: format!("capsule spinning about its axis, rounding {rounding}"),
            shape: Convex::try_capsule(t(0.2), t(r + rounding)).expect("capsule"),
            motion: motion(
                [0.0, gap + rr, 0.0],
                [0.0; 3],
                [0.0, -toward, 1.5],
                [40.0, 0.0, 0.0],
                Some(lying),
            ),
        });
        // A cone standing on its apex side up (base down), spinning about its
        // axis at 30 rad/s about its centre of mass (a quarter up from the base).
        let (h, base) = (0.1, 0.06);
        out.push(Case {
            name: format!("cone spinning about its axis, rounding {rounding}"),
            shape: round(Convex::try_cone(t(h), t(base)).expect("cone")),
            motion: motion(
                [0.1, gap + rounding + h, 0.1],
                [0.0, -h / 2.0, 0.0],
                [1.0, -toward, -1.0],
                [0.0, 30.0, 0.0],
                None,
            ),
        });
    }
    out
}

/// A motion over `[0, DT]` whose body origin is at `origin` at the start,
/// turning about the body point `local` with velocity `lin` and angular
/// velocity `ang`, from the start orientation `q`.
fn motion<T: Float>(
    origin: [f64; 3],
    local: [f64; 3],
    lin: [f64; 3],
    ang: [f64; 3],
    q: Option<Rotation<T>>,
) -> RigidMotion<T> {
    let q = q.unwrap_or(Rotation::IDENTITY);
    let start = Isometry::try_new(q, v(origin)).expect("pose");
    RigidMotion::try_from_start(start, v(lin), v(ang), T::from_f64(DT))
        .expect("motion")
        .try_with_local_centre(v(local))
        .expect("centre")
}

/// The obstacles: the floor as a half-space, as a cuboid's top face, and as
/// a 12-triangle mesh box's top face (their tops at `y = 0`).
fn obstacles<T: Float>(tree: &BallTree<T>) -> Vec<(&'static str, Shape<'_, T>, RigidMotion<T>)> {
    let still = |y: f64| motion::<T>([0.0, y, 0.0], [0.0; 3], [0.0; 3], [0.0; 3], None);
    vec![
        (
            "half-space",
            Shape::HalfSpace(HalfSpace::try_new(v([0.0, 1.0, 0.0])).expect("plane")),
            still(0.0),
        ),
        (
            "cuboid",
            Shape::Convex(Convex::try_cuboid([2.0, 0.05, 2.0].map(T::from_f64)).expect("box")),
            still(-0.05),
        ),
        ("mesh", Shape::Mesh(tree), still(-0.05)),
    ]
}

fn run<T: Float>(a: &Case<T>, b: &(&str, Shape<'_, T>, RigidMotion<T>)) -> CaReport<T> {
    let params = CaParams::default().with_contact_distance(T::from_f64(CONTACT));
    let mut pair = AnyPair::try_new(Shape::Convex(a.shape), b.1).expect("pair");
    time_of_impact(&mut pair, &a.motion, &b.2, &params).expect("query")
}

fn separated_within_three<T: Float>() {
    let tree = BallTree::try_from_mesh(&cuboid::<T>([4.0, 0.1, 4.0]).expect("mesh")).expect("tree");
    let (mut checked, mut failed) = (0, Vec::new());
    for gap in [1.01 * CONTACT, 2.0 * CONTACT, 10.0 * CONTACT] {
        for case in cases::<T>(gap, 0.0) {
            for obstacle in obstacles(&tree) {
                let report = run(&case, &obstacle);
                if !(matches!(report.outcome, CaOutcome::Separated) && report.iterations <= 3) {
                    failed.push(format!(
                        "{} at {gap} above the {}: {:?} after {} iterations",
                        case.name, obstacle.0, report.outcome, report.iterations
                    ));
                }
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 3 * 10 * 3, "every case ran");
    assert!(
        failed.is_empty(),
        "{} of {checked}:\n{}",
        failed.len(),
        failed.join("\n")
    );
}

#[test]
fn symmetric_spins_are_separated_within_three_iterations_f64() {
    separated_within_three::<f64>();
}

#[test]
fn symmetric_spins_are_separated_within_three_iterations_f32() {
    separated_within_three::<f32>();
}

/// The control: the same shapes and spins, moving down at 1 from 10 contact
/// distances, touch the floor within the step: after the distance reaches
/// the contact distance and before it reaches half of it.
#[test]
fn the_same_motions_towards_the_floor_still_touch() {
    let tree =
        BallTree::try_from_mesh(&cuboid::<f64>([4.0, 0.1, 4.0]).expect("mesh")).expect("tree");
    let gap = 10.0 * CONTACT;
    for case in cases::<f64>(gap, 1.0) {
        for obstacle in obstacles(&tree) {
            let report = run(&case, &obstacle);
            let contact = report.outcome.contact().unwrap_or_else(|| {
                panic!(
                    "{} towards the {}: {:?}",
                    case.name, obstacle.0, report.outcome
                )
            });
            // The lowest point reaches the contact distance at (gap - CONTACT) / 1
            // and half of it at (gap - CONTACT / 2) / 1: the contact lies between.
            assert!(
                contact.time <= gap - CONTACT / 2.0 + 1e-12 && contact.time >= gap - CONTACT - 1e-9,
                "{} towards the {}: contact at {}",
                case.name,
                obstacle.0,
                contact.time
            );
        }
    }
}

/// Through a scene: every case beside a static floor box, one frame, no
/// contact and every tested pair separated within three iterations.
#[test]
fn through_a_scene_symmetric_spins_are_separated() {
    for gap in [1.01 * CONTACT, 10.0 * CONTACT] {
        let cases = cases::<f64>(gap, 0.0);
        let mut scene =
            Scene::try_new(TimeInterval::try_new(0.0, DT).expect("frame")).expect("scene");
        let floor = Convex::try_cuboid([2.0, 0.05, 2.0]).expect("box");
        scene
            .try_add_static(
                Shape::Convex(floor),
                Isometry::try_from_translation(Vec3::new(0.0, -0.05, 0.0)).expect("pose"),
            )
            .expect("floor");
        // Far apart along z so that only the floor pairs are tested.
        for (k, case) in cases.iter().enumerate() {
            let shifted = RigidMotion::try_from_start(
                Isometry::try_new(
                    case.motion.orientation(),
                    case.motion.start_pose().translation()
                        + Vec3::new(0.0, 0.0, 0.4 * k as f64 - 1.8),
                )
                .expect("pose"),
                case.motion.linear(),
                case.motion.angular(),
                DT,
            )
            .expect("motion")
            .try_with_local_centre(case.motion.local_centre())
            .expect("centre");
            scene
                .try_add(Shape::Convex(case.shape), shifted)
                .expect("body");
        }
        let params =
            SceneParams::default().with_ca(CaParams::default().with_contact_distance(CONTACT));
        let mut ws = SceneWorkspace::new();
        let report = scene.query(&mut ws, &params).expect("query");
        assert_eq!(report.contacts().count(), 0, "no contact at {gap}");
        let floor_pairs = report.pairs().iter().filter(|p| p.a == 0).count();
        assert_eq!(
            floor_pairs,
            cases.len(),
            "every body tested against the floor at {gap}"
        );
        for p in report.pairs() {
            assert!(
                matches!(p.report.outcome, CaOutcome::Separated) && p.report.iterations <= 3,
                "{} at {gap}: {:?} after {}",
                cases[p.b - 1].name,
                p.report.outcome,
                p.report.iterations
            );
        }
    }
}
