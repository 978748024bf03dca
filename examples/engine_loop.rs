//! motion-bound inside an engine loop: a few bodies tumbling in a box for
//! 240 frames, each body's ball tree built once, every pair's time of impact
//! per frame, checked against sampled ground truth.
//!
//! Run with `cargo run --release --example engine_loop`.
//!
//! The "engine" here is the smallest that shows the pattern: each body has a
//! state (its centre of mass `x`, orientation `q`, linear velocity `v`,
//! angular velocity `w`), integrated every frame as an engine does
//! (`x += v dt`, `q = exp(w dt) q`); walls reflect velocities and contacts
//! exchange the normal components of the two bodies' velocities. What it
//! hands to motion-bound is what any engine has: the body's pose at the start
//! of the frame, its velocities about its centre of mass, and the frame
//! length: `RigidMotion::try_from_start(pose, v, w, dt)` then
//! `try_with_local_centre(centre of mass)`. The meshes and their trees never
//! change; one `MeshWorkspace` serves every query.
//!
//! Ground truth: for pairs whose bounding spheres come close enough to touch
//! during the frame, `testkit::ground_truth::first_sampled_contact` (bodies
//! placed by its own quaternion code from the same poses, exact triangle
//! intersection) at 24 times over the frame. A query is MISSED when it
//! reports no possible contact and the sampling finds one, LATE when its
//! first possible contact is after the sampled one.

#[path = "../tests/common/meshes.rs"]
mod meshes;

use std::time::Instant;

use motion_bound::bodies::{torus, TorusKnot};
use motion_bound::ca::{time_of_impact, CaOutcome, CaParams, MeshPair, MeshWorkspace};
use motion_bound::testkit::ground_truth::{first_sampled_contact, MeshRef};
use motion_bound::testkit::toi::Rng;
use motion_bound::{BallTree, Isometry, RigidMotion, Rotation, TriMesh, Vec3};

/// Frames to run.
const FRAMES: usize = 240;
/// The frame length.
const DT: f64 = 1.0 / 60.0;
/// The box's half width.
const HALF_BOX: f64 = 1.6;
/// Ground-truth samples per frame.
const SAMPLES: usize = 24;

/// A body: its mesh in its own frame, its tree (built once), its centre of
/// mass in that frame, its reach about it, and its state.
struct Body {
    name: &'static str,
    mesh: TriMesh<f64>,
    tree: BallTree<f64>,
    centre_of_mass: Vec3<f64>,
    reach: f64,
    x: Vec3<f64>,
    q: Rotation<f64>,
    v: Vec3<f64>,
    w: Vec3<f64>,
}

impl Body {
    fn new(name: &'static str, mesh: TriMesh<f64>, rng: &mut Rng, trees: &mut usize) -> Self {
        let tree = BallTree::try_from_mesh(&mesh).expect("a valid mesh");
        *trees += 1;
        let c = Vec3::from_array(mesh.volume_centroid().expect("a closed mesh"));
        let reach = mesh
            .vertices()
            .iter()
            .map(|p| (Vec3::from_array(*p) - c).length())
            .fold(0.0, f64::max);
        let place = HALF_BOX - 0.6;
        Self {
            name,
            mesh,
            tree,
            centre_of_mass: c,
            reach,
            x: Vec3::from_array(rng.vec3().map(|s| s * place)),
            q: Rotation::try_from_axis_angle(
                Vec3::from_array(rng.direction()),
                rng.range(0.0, 6.0),
            )
            .expect("a valid rotation"),
            v: Vec3::from_array(rng.direction()) * rng.range(1.0, 2.5),
            w: Vec3::from_array(rng.direction()) * rng.range(1.0, 6.0),
        }
    }

    /// What the engine hands over for this frame: the pose of the body's
    /// frame at the start, `v` and `w` about the centre of mass, over
    /// `[0, DT]`.
    fn motion(&self) -> RigidMotion<f64> {
        let origin = self.x - self.q.rotate(self.centre_of_mass);
        let pose = Isometry::try_new(self.q, origin).expect("finite");
        RigidMotion::try_from_start(pose, self.v, self.w, DT)
            .and_then(|m| m.try_with_local_centre(self.centre_of_mass))
            .expect("a valid motion")
    }

    /// One step of the engine's integrator.
    fn integrate(&mut self) {
        self.x = self.x + self.v * DT;
        let turn = self.w.length() * DT;
        if turn > 0.0 {
            let r = Rotation::try_from_axis_angle(self.w, turn).expect("a valid rotation");
            self.q = r * self.q;
        }
        // Walls: reflect the velocity of a body leaving the box.
        let lim = HALF_BOX - self.reach;
        let (mut x, mut v) = (self.x.to_array(), self.v.to_array());
        for k in 0..3 {
            if (x[k] > lim && v[k] > 0.0) || (x[k] < -lim && v[k] < 0.0) {
                v[k] = -v[k];
                x[k] = x[k].clamp(-lim, lim);
            }
        }
        (self.x, self.v) = (Vec3::from_array(x), Vec3::from_array(v));
    }
}

/// The least distance over `[0, DT]` between two centres moving linearly.
fn closest_centres(a: &Body, b: &Body) -> f64 {
    let (d, dv) = (b.x - a.x, b.v - a.v);
    let vv = dv.dot(dv);
    let t = if vv > 0.0 {
        (-d.dot(dv) / vv).clamp(0.0, DT)
    } else {
        0.0
    };
    (d + dv * t).length()
}

fn main() {
    let mut rng = Rng::new(60);
    let mut trees = 0;
    let knot = TorusKnot::TREFOIL
        .mesh::<f64>(140, 10)
        .expect("built-in scene");
    let ring = torus::<f64>(0.45, 0.08, 48, 12).expect("built-in scene");
    let bunny = meshes::try_load_shipped("bunny-npm-3674.obj.gz")
        .ok()
        .map(|m| {
            let (_, r) = m.bounding_sphere();
            m.scaled(0.45 / r).expect("valid bunny")
        });
    let mut bodies = vec![
        Body::new("torus knot", knot, &mut rng, &mut trees),
        Body::new("ring", ring.clone(), &mut rng, &mut trees),
        Body::new("second ring", ring, &mut rng, &mut trees),
    ];
    match bunny {
        Some(b) => bodies.push(Body::new("bunny", b, &mut rng, &mut trees)),
        None => println!("(data/bunny-npm-3674.obj.gz not found: the bunny stays out)"),
    }
    println!(
        "{} bodies tumbling in a box of half width {HALF_BOX} for {FRAMES} frames of {DT:.4}:",
        bodies.len()
    );
    for b in &bodies {
        println!(
            "  {:<12} {:>5} triangles, reach {:.3} about its centre of mass",
            b.name,
            b.mesh.triangle_count(),
            b.reach
        );
    }
    let params = CaParams::default().with_contact_distance(1e-3);
    let mut workspace = MeshWorkspace::new();
    let (mut queries, mut contacts, mut missed, mut late, mut checked) = (0usize, 0, 0, 0, 0);
    let mut seconds = 0.0;
    // The work and outcomes, summed, to compare two builds (the times' sum
    // in full precision: equal sums of equal counts mean equal answers).
    let (mut iterations, mut node_pairs, mut separations, mut time_sum) = (0u64, 0u64, 0u64, 0.0);
    for frame in 0..FRAMES {
        let motions: Vec<RigidMotion<f64>> = bodies.iter().map(Body::motion).collect();
        let mut impulses = Vec::new();
        for i in 0..bodies.len() {
            for j in i + 1..bodies.len() {
                let (a, b) = (&bodies[i], &bodies[j]);
                let start = Instant::now();
                let mut pair = MeshPair::with_workspace(&a.tree, &b.tree, workspace);
                let report =
                    time_of_impact(&mut pair, &motions[i], &motions[j], &params).expect("valid");
                workspace = pair.into_workspace();
                seconds += start.elapsed().as_secs_f64();
                queries += 1;
                iterations += u64::from(report.iterations);
                node_pairs += report.work.node_pairs;
                separations += u64::from(report.outcome == CaOutcome::Separated);
                time_sum += report.outcome.earliest_possible_contact().unwrap_or(0.0);
                if let Some(c) = report.outcome.contact() {
                    contacts += 1;
                    let n = c.normal.map_or(b.x - a.x, motion_bound::Direction::get);
                    impulses.push((i, j, n));
                }
                // Ground truth where the bounding spheres can meet.
                if closest_centres(a, b) <= a.reach + b.reach {
                    checked += 1;
                    let truth = first_sampled_contact(
                        MeshRef::from(&a.mesh),
                        &motions[i],
                        MeshRef::from(&b.mesh),
                        &motions[j],
                        (0.0, DT),
                        SAMPLES,
                    );
                    match (report.outcome.earliest_possible_contact(), truth) {
                        (None, Some(g)) => {
                            missed += 1;
                            println!(
                                "frame {frame}: {} and {}: MISSED a contact at {g}",
                                a.name, b.name
                            );
                        }
                        (Some(t), Some(g)) if t > g => {
                            late += 1;
                            println!(
                                "frame {frame}: {} and {}: LATE, {t} after {g}",
                                a.name, b.name
                            );
                        }
                        _ => {}
                    }
                }
                if frame % 60 == 0 && i == 0 && j == 1 {
                    let what = match report.outcome {
                        CaOutcome::Separated => "separated".to_owned(),
                        CaOutcome::InitialContact(_) => "in contact at the start".to_owned(),
                        o => format!("{o:?}"),
                    };
                    println!("frame {frame:>3}: {} and {}: {what}", a.name, b.name);
                }
            }
        }
        // Contacts: exchange the normal components of the velocities (equal
        // masses, elastic), once per pair and frame, if they approach.
        for (i, j, n) in impulses {
            let Some(n) = n.try_normalize() else { continue };
            let closing = (bodies[i].v - bodies[j].v).dot(n);
            if closing > 0.0 {
                bodies[i].v = bodies[i].v - n * closing;
                bodies[j].v = bodies[j].v + n * closing;
            }
        }
        for b in &mut bodies {
            b.integrate();
        }
    }
    println!(
        "{queries} pair queries, {contacts} with a contact, {checked} checked against sampled ground truth"
    );
    println!(
        "work: iterations {iterations}, node pairs {node_pairs}, contacts {contacts}, separations {separations}, contact times' sum {time_sum:.17e}"
    );
    println!(
        "frames {FRAMES}, pairs {queries}, trees built {trees}, missed {missed}, late {late}, mean ms per query {:.4}",
        seconds * 1e3 / queries as f64
    );
}
