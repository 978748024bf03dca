//! The seed's Table 1 rigid-body rows, "RBD for Bunnies" and "RBD for
//! Rings": many bodies dropped into a box and driven by a real rigid-body
//! engine (rapier3d), every frame replayed through motion-bound's scene
//! query, every CCD query timed ([`run`]), shared by `examples/rbd.rs` and
//! the `report` binary.
//!
//! Each frame, every body's pose before rapier's step (its centre of mass,
//! orientation) and its velocities after the step (those rapier integrates
//! the frame's positions with) make its motion over the frame,
//! `RigidMotion::try_about_centre`; the bodies' triangle meshes (one shared
//! tree per shape) go through `Scene::query`. Rapier itself collides
//! simplified shapes (the bunny's convex hull, a ring of capsules): it only
//! supplies the motions.
//!
//! Ground truth, on every 10th frame: every tested pair and every culled
//! pair whose bounding spheres come within reach of each other, by
//! `testkit::ground_truth::first_sampled_contact` (bodies placed by its own
//! quaternion code, exact triangle intersection, 16 times over the frame).
//! MISSED: a pair the query reported without a possible contact (or culled)
//! that the sampling finds touching; LATE: a reported first possible contact
//! after the sampled one. parry3d's `cast_shapes_nonlinear` runs on the same
//! tested pairs of those frames, with the same motions.

use std::time::Instant;

use motion_bound::bodies::torus;
use motion_bound::ca::{self, BoundChoice};
use motion_bound::scene::{Scene, SceneParams, SceneStats, SceneWorkspace};
use motion_bound::testkit::ground_truth::{first_sampled_contact, MeshRef};
use motion_bound::testkit::toi::Rng;
use motion_bound::{BallTree, Point3, RigidMotion, Rotation, TimeInterval, TriMesh, Vec3};
use parry3d_f64::query::{cast_shapes_nonlinear, NonlinearRigidMotion};
use parry3d_f64::shape::TriMesh as ParryMesh;
use rapier3d_f64::math::Rotation as Rot3;
use rapier3d_f64::prelude::*;

/// The frame length.
pub const DT: f64 = 1.0 / 60.0;
/// Ground truth and parry on every this many frames.
const CHECK_EVERY: usize = 10;

/// The shipped bunny, recentred on its bounding sphere and scaled to a
/// reach of 0.5.
///
/// # Panics
/// If `data/bunny-npm-3674.obj.gz` cannot be read.
#[must_use]
pub fn load_bunny() -> TriMesh<f64> {
    use std::io::Read;
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../data/bunny-npm-3674.obj.gz");
    let file = std::fs::File::open(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let mut text = String::new();
    flate2::read::GzDecoder::new(file)
        .read_to_string(&mut text)
        .unwrap_or_else(|e| panic!("{path}: {e}"));
    let mesh = TriMesh::from_obj_str(&text).expect("the shipped bunny");
    let (c, r) = mesh.bounding_sphere();
    mesh.recentred(c)
        .and_then(|m| m.scaled(0.5 / r))
        .expect("a valid bunny")
}

/// One scene's shape: our mesh and tree, rapier's collider shape, parry's mesh.
pub struct Shape {
    /// The triangle mesh (body frame).
    pub mesh: TriMesh<f64>,
    tree: BallTree<f64>,
    collider: SharedShape,
    parry: ParryMesh,
    reach: f64,
}

impl Shape {
    /// Our mesh with rapier's collider shape for it.
    ///
    /// # Panics
    /// For an invalid mesh.
    #[must_use]
    pub fn new(mesh: TriMesh<f64>, collider: SharedShape) -> Self {
        let tree = BallTree::try_from_mesh(&mesh).expect("a valid mesh");
        let vertices = mesh
            .vertices()
            .iter()
            .map(|v| Vector::new(v[0], v[1], v[2]))
            .collect();
        let parry = ParryMesh::new(vertices, mesh.triangles().to_vec()).expect("a valid mesh");
        let reach = mesh
            .vertices()
            .iter()
            .map(|v| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt())
            .fold(0.0, f64::max);
        Self {
            mesh,
            tree,
            collider,
            parry,
            reach,
        }
    }
}

/// A ring of `n` capsules for rapier (a torus's convex hull would be a disc).
fn ring_of_capsules(major: f64, minor: f64, n: usize) -> SharedShape {
    let point = |k: usize| {
        let a = std::f64::consts::TAU * k as f64 / n as f64;
        Vector::new(major * a.cos(), major * a.sin(), 0.0)
    };
    let parts = (0..n)
        .map(|k| {
            (
                Pose::IDENTITY,
                SharedShape::capsule(point(k), point(k + 1), minor),
            )
        })
        .collect();
    SharedShape::compound(parts)
}

/// A box of half width `half` (floor at `y = 0`, walls up to `height`).
fn add_box(world: &mut PhysicsWorld, half: f64, height: f64) {
    let t = 0.2;
    let walls = [
        (
            Vector::new(0.0, -t, 0.0),
            Vector::new(half + t, t, half + t),
        ),
        (
            Vector::new(half + t, height / 2.0, 0.0),
            Vector::new(t, height / 2.0, half + t),
        ),
        (
            Vector::new(-half - t, height / 2.0, 0.0),
            Vector::new(t, height / 2.0, half + t),
        ),
        (
            Vector::new(0.0, height / 2.0, half + t),
            Vector::new(half + t, height / 2.0, t),
        ),
        (
            Vector::new(0.0, height / 2.0, -half - t),
            Vector::new(half + t, height / 2.0, t),
        ),
    ];
    for (centre, h) in walls {
        world.insert(
            RigidBodyBuilder::fixed().translation(centre),
            ColliderBuilder::cuboid(h.x, h.y, h.z),
        );
    }
}

/// A rapier body's motion over the next frame: its pose before the step,
/// its velocities after.
fn motion_of(pose: &Pose, local_com: Vector, body: &RigidBody) -> RigidMotion<f64> {
    let q = pose.rotation;
    let com = pose.transform_point(local_com);
    let (v, w) = (body.linvel(), body.angvel());
    RigidMotion::try_about_centre(
        Point3::new(com.x, com.y, com.z),
        Vec3::new(local_com.x, local_com.y, local_com.z),
        Rotation::try_from_quaternion(q.w, q.x, q.y, q.z).expect("a unit quaternion"),
        Vec3::new(v.x, v.y, v.z),
        Vec3::new(w.x, w.y, w.z),
        DT,
    )
    .expect("finite rapier state")
}

/// Parry's motion for the same frame: the body origin's start pose, the
/// centre of mass in the body frame, the velocities.
fn parry_motion(m: &RigidMotion<f64>) -> NonlinearRigidMotion {
    let start = m.start_pose();
    let t = start.translation();
    let [w, x, y, z] = start.rotation().quaternion();
    let pose = Pose::from_parts(Vector::new(t.x, t.y, t.z), Rot3::from_xyzw(x, y, z, w));
    let (c, v, w) = (m.local_centre(), m.linear(), m.angular());
    NonlinearRigidMotion::new(
        pose,
        Vector::new(c.x, c.y, c.z),
        Vector::new(v.x, v.y, v.z),
        Vector::new(w.x, w.y, w.z),
    )
}

/// What one scene's run measured.
#[derive(Default, Clone, Debug)]
#[allow(missing_docs)]
pub struct Tally {
    pub queries: u64,
    pub query_ms: f64,
    pub frame_ms: f64,
    pub broad_ms: f64,
    pub iterations: u64,
    pub contacts: u64,
    pub checked: u64,
    pub checked_culled: u64,
    pub sampled_contacts: u64,
    pub missed: u64,
    pub late: u64,
    pub parry_queries: u64,
    pub parry_ms: f64,
    pub ours_on_parry_pairs_ms: f64,
    pub parry_hits: u64,
    pub skips: SceneStats,
    pub worst_end: f64,
}

/// One rigid-body scene: `bodies` copies of a shape dropped into a box of
/// half width `half`, their start states drawn from `seed`.
#[derive(Clone, Copy, Debug)]
pub struct RbdScene {
    /// The Table 1 row's name.
    pub name: &'static str,
    /// How many bodies.
    pub bodies: usize,
    /// The box's half width.
    pub half: f64,
    /// The seed of the bodies' start states.
    pub seed: u64,
}

/// Runs `scene` with `shape` for `frames` frames, every frame's CCD through
/// the scene query with `bound`; prints its lines unless `quiet`, and
/// returns its tally.
///
/// # Panics
/// Never for the shipped shapes.
pub fn run(
    scene: &RbdScene,
    shape: &Shape,
    frames: usize,
    bound: BoundChoice,
    quiet: bool,
) -> Tally {
    let RbdScene {
        name,
        bodies,
        half,
        seed,
    } = *scene;
    let mut world = PhysicsWorld::default();
    add_box(&mut world, half, 40.0);
    let mut rng = Rng::new(seed);
    let per_layer = ((bodies as f64).sqrt().ceil() as usize).max(1);
    let spacing = 2.2 * shape.reach;
    let mut handles = Vec::new();
    for i in 0..bodies {
        let (layer, k) = (i / (per_layer * per_layer), i % (per_layer * per_layer));
        let x = (k % per_layer) as f64 * spacing - (per_layer - 1) as f64 * spacing / 2.0;
        let z = (k / per_layer) as f64 * spacing - (per_layer - 1) as f64 * spacing / 2.0;
        let y = 1.0 + layer as f64 * spacing;
        let axis = rng.direction();
        let angle = rng.range(0.0, std::f64::consts::PI);
        let spin = rng.direction().map(|c| c * 4.0);
        let (h, _) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(x, y, z))
                .rotation(Vector::new(axis[0], axis[1], axis[2]) * angle)
                .linvel(Vector::new(rng.range(-1.0, 1.0), 0.0, rng.range(-1.0, 1.0)))
                .angvel(Vector::new(spin[0], spin[1], spin[2])),
            ColliderBuilder::new(shape.collider.clone()).density(1.0),
        );
        handles.push(h);
    }
    let frame = TimeInterval::try_new(0.0, DT).expect("frame");
    let mut scene = Scene::try_new(frame).expect("scene");
    let still = RigidMotion::try_new(Point3::ORIGIN, Vec3::ZERO, Vec3::ZERO, frame).expect("still");
    for _ in &handles {
        scene
            .try_add(ca::Shape::Mesh(&shape.tree), still)
            .expect("body");
    }
    let params =
        SceneParams::default().with_ca(motion_bound::ca::CaParams::default().with_bound(bound));
    let mut ws = SceneWorkspace::new();
    let mut tally = Tally::default();
    let mref = MeshRef::from(&shape.mesh);
    let mut worst_end = 0.0f64;
    for f in 0..frames {
        let before: Vec<(Pose, Vector)> = handles
            .iter()
            .map(|&h| {
                (
                    *world.bodies[h].position(),
                    world.bodies[h].local_center_of_mass(),
                )
            })
            .collect();
        world.step();
        let motions: Vec<RigidMotion<f64>> = handles
            .iter()
            .zip(&before)
            .map(|(&h, (pose, com))| motion_of(pose, *com, &world.bodies[h]))
            .collect();
        // How far our motion's end pose is from rapier's (its position
        // corrections are not in its velocities).
        for (&h, m) in handles.iter().zip(&motions) {
            let ours = m.pose_at(DT).translation;
            let theirs = world.bodies[h].position().transform_point(Vector::ZERO);
            let d = ((ours.x - theirs.x).powi(2)
                + (ours.y - theirs.y).powi(2)
                + (ours.z - theirs.z).powi(2))
            .sqrt();
            worst_end = worst_end.max(d);
        }
        for (i, m) in motions.iter().enumerate() {
            scene.try_set_motion(i, *m).expect("same frame");
        }
        let start = Instant::now();
        scene
            .broad_phase(&mut ws, &params, |_, _| true)
            .expect("valid");
        let broad = start.elapsed().as_secs_f64() * 1e3;
        let report = scene.narrow_phase(&mut ws, &params).expect("valid");
        let total = start.elapsed().as_secs_f64() * 1e3;
        let st = report.stats();
        tally.queries += st.pairs_tested;
        tally.query_ms += total - broad;
        tally.frame_ms += total;
        tally.broad_ms += broad;
        tally.iterations += st.iterations;
        tally.contacts += report.contacts().count() as u64;
        let k = &mut tally.skips;
        k.static_bodies += st.static_bodies;
        k.translating_bodies += st.translating_bodies;
        k.box_rates_skipped += st.box_rates_skipped;
        k.pairs_all += st.pairs_all;
        k.pairs_static += st.pairs_static;
        k.pairs_culled += st.pairs_culled;
        if f % CHECK_EVERY != CHECK_EVERY - 1 {
            continue;
        }
        // Ground truth on every pair within reach.
        let pairs: Vec<(usize, usize, Option<f64>)> = report
            .pairs()
            .iter()
            .map(|p| (p.a, p.b, p.report.outcome.earliest_possible_contact()))
            .collect();
        for i in 0..motions.len() {
            for j in i + 1..motions.len() {
                let reported = pairs.iter().find(|p| (p.0, p.1) == (i, j));
                let (ca, cb) = (motions[i].centre(), motions[j].centre());
                let near = (cb - ca).length()
                    < 2.0 * shape.reach
                        + (motions[i].linear() - motions[j].linear()).length() * DT
                        + 1.0;
                let both_static = scene.bodies()[i].is_static() && scene.bodies()[j].is_static();
                if reported.is_none() && (!near || both_static) {
                    continue;
                }
                let truth =
                    first_sampled_contact(mref, &motions[i], mref, &motions[j], (0.0, DT), 16);
                tally.checked += 1;
                tally.sampled_contacts += u64::from(truth.is_some());
                match (reported, truth) {
                    (None, t) => {
                        tally.checked_culled += 1;
                        tally.missed += u64::from(t.is_some());
                    }
                    (Some(&(_, _, None)), Some(_)) => tally.missed += 1,
                    (Some(&(_, _, Some(t))), Some(s)) => tally.late += u64::from(t > s),
                    _ => {}
                }
            }
        }
        // parry on the same tested pairs.
        for p in report.pairs() {
            let (ma, mb) = (&motions[p.a], &motions[p.b]);
            let start = Instant::now();
            let hit = cast_shapes_nonlinear(
                &parry_motion(ma),
                &shape.parry,
                &parry_motion(mb),
                &shape.parry,
                0.0,
                DT,
                true,
            )
            .expect("parry supports mesh against mesh");
            tally.parry_ms += start.elapsed().as_secs_f64() * 1e3;
            tally.parry_queries += 1;
            tally.parry_hits += u64::from(hit.is_some());
            let start = Instant::now();
            let mut one = Scene::try_new(frame).expect("scene");
            one.try_add(ca::Shape::Mesh(&shape.tree), *ma)
                .expect("body");
            one.try_add(ca::Shape::Mesh(&shape.tree), *mb)
                .expect("body");
            let mut ws1 = SceneWorkspace::new();
            let _ = one.query(&mut ws1, &params).expect("valid");
            tally.ours_on_parry_pairs_ms += start.elapsed().as_secs_f64() * 1e3;
        }
    }
    let q = tally.queries.max(1) as f64;
    if !quiet {
        println!(
        "{name}: {bodies} bodies of {} triangles, {frames} frames: {} CCD queries ({} with a contact), \
         mean {:.4} ms per query, {:.3} ms per frame (broad phase {:.3}), {:.2} iterations per query; \
         checked {} pairs ({} culled), {} sampled contacts: missed {}, late {}; \
         parry3d cast_shapes_nonlinear on {} of the tested pairs: {:.3} ms per query against our {:.3} ({:.0}x), {} hits",
        shape.mesh.triangle_count(),
        tally.queries,
        tally.contacts,
        tally.query_ms / q,
        tally.frame_ms / frames as f64,
        tally.broad_ms / frames as f64,
        tally.iterations as f64 / q,
        tally.checked,
        tally.checked_culled,
        tally.sampled_contacts,
        tally.missed,
        tally.late,
        tally.parry_queries,
        tally.parry_ms / tally.parry_queries.max(1) as f64,
        tally.ours_on_parry_pairs_ms / tally.parry_queries.max(1) as f64,
        tally.parry_ms / tally.ours_on_parry_pairs_ms.max(1e-12),
        tally.parry_hits,
    );
        let k = &tally.skips;
        println!(
            "  skipped over all frames: {} of {} pairs culled by the swept boxes, {} pairs of two \
         resting bodies, {} box rates of {} resting and {} non-turning bodies",
            k.pairs_culled,
            k.pairs_all,
            k.pairs_static,
            k.box_rates_skipped,
            k.static_bodies,
            k.translating_bodies
        );
        println!(
            "  (largest gap between our motion's end and rapier's next position: {worst_end:.2e})"
        );
    }
    tally.worst_end = worst_end;
    tally
}

/// The bunny scene: 30 bunnies (rapier: their convex hulls).
///
/// # Panics
/// If the shipped bunny cannot be read.
#[must_use]
pub fn bunny_shape() -> Shape {
    let bunny = load_bunny();
    let hull: Vec<Vector> = bunny
        .vertices()
        .iter()
        .map(|v| Vector::new(v[0], v[1], v[2]))
        .collect();
    Shape::new(bunny, SharedShape::convex_hull(&hull).expect("a hull"))
}

/// The ring scene's shape: a 1,152-triangle ring (rapier: 16 capsules).
///
/// # Panics
/// Never.
#[must_use]
pub fn ring_shape() -> Shape {
    Shape::new(
        torus::<f64>(0.45, 0.08, 48, 12).expect("a ring"),
        ring_of_capsules(0.45, 0.08, 16),
    )
}

/// The bunny row: 30 bunnies.
pub const BUNNIES: RbdScene = RbdScene {
    name: "RBD for Bunnies",
    bodies: 30,
    half: 2.0,
    seed: 1,
};

/// The ring row: 40 rings.
pub const RINGS: RbdScene = RbdScene {
    name: "RBD for Rings",
    bodies: 40,
    half: 2.0,
    seed: 2,
};

/// Runs both scenes (30 bunnies, 40 rings) for `frames` frames with
/// `bound`, printing their lines unless `quiet`.
#[must_use]
pub fn run_both(frames: usize, bound: BoundChoice, quiet: bool) -> [Tally; 2] {
    let bunny = bunny_shape();
    let a = run(&BUNNIES, &bunny, frames, bound, quiet);
    let ring = ring_shape();
    let b = run(&RINGS, &ring, frames, bound, quiet);
    [a, b]
}
