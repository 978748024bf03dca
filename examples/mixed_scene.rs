//! Every shape an engine has, in one scene: a ground half-space, 10 balls, 10
//! capsules, 10 cuboids, 5 cylinders, 5 cones, 5 bunny meshes and 3
//! compounds (a table of cuboids, a dumbbell of two balls and a capsule, a
//! bunny with a box) thrown about a room for 240 frames; every frame one
//! `Scene::query` gives every pair's first contact, checked against sampled
//! ground truth.
//!
//! Run with `cargo run --release --example mixed_scene`.
//!
//! The "engine" integrates each body's state (`x += v dt`, `q = exp(w dt) q`),
//! reflects velocities at the walls and the ceiling, and on a reported
//! contact exchanges the two bodies' velocity components along the normal (a
//! ball of the ground reflects). Ground truth
//! (`tests/common/shape_truth.rs`: each part's core tessellated inside
//! itself, placed by the testkit's own quaternions, exact triangle
//! distances) at 9 times over the frame, for every tested pair whose bounding
//! spheres come close, and for every culled pair whose bounding spheres come
//! close (the broad phase must never cull a pair that touches). A pair is
//! MISSED when the query reports no possible contact and the sampling finds
//! one, LATE when its first possible contact is after the sampled one.
//!
//! The last line: `frames F, pairs P, pair kinds K, missed M, late L, mean ms
//! per query X`.

#[path = "../tests/common/meshes.rs"]
mod meshes;
#[path = "../tests/common/shape_truth.rs"]
mod shape_truth;

use std::collections::BTreeSet;
use std::time::Instant;

use motion_bound::ca::{CaParams, Compound, Part, Shape};
use motion_bound::scene::{Scene, SceneParams, SceneWorkspace};
use motion_bound::testkit::toi::Rng;
use motion_bound::{
    BallTree, Convex, HalfSpace, Isometry, RigidMotion, Rotation, TimeInterval, Vec3,
};
use shape_truth::{first_sampled_contact, first_sampled_landing, Solid};

/// Frames to run.
const FRAMES: usize = 240;
/// The frame length.
const DT: f64 = 1.0 / 60.0;
/// The room: `|x|, |z| <= HALF`, `0 <= y <= 2 HALF` (the ground is `y <= 0`).
const HALF: f64 = 3.0;
/// Ground-truth samples per frame (9 times).
const SAMPLES: usize = 8;

/// A body: its kind's name, its shape, its ground truth, its reach, its
/// state.
struct Body {
    kind: &'static str,
    shape: Shape<'static, f64>,
    solid: Solid,
    reach: f64,
    x: Vec3<f64>,
    q: Rotation<f64>,
    v: Vec3<f64>,
    w: Vec3<f64>,
}

impl Body {
    fn new(kind: &'static str, shape: Shape<'static, f64>, solid: Solid, rng: &mut Rng) -> Self {
        let reach = solid.reach();
        let room = HALF - reach;
        Self {
            kind,
            shape,
            solid,
            reach,
            x: Vec3::new(
                rng.range(-room, room),
                rng.range(reach, 2.0 * HALF - reach),
                rng.range(-room, room),
            ),
            q: Rotation::try_from_axis_angle(
                Vec3::from_array(rng.direction()),
                rng.range(0.0, 6.0),
            )
            .expect("a rotation"),
            v: Vec3::from_array(rng.direction()) * rng.range(0.5, 3.0),
            w: Vec3::from_array(rng.direction()) * rng.range(0.0, 6.0),
        }
    }

    fn motion(&self, frame: TimeInterval<f64>) -> RigidMotion<f64> {
        if matches!(self.shape, Shape::HalfSpace(_)) {
            return RigidMotion::try_new(
                motion_bound::Point3::ORIGIN,
                Vec3::ZERO,
                Vec3::ZERO,
                frame,
            )
            .expect("the ground");
        }
        let pose = Isometry::try_new(self.q, self.x).expect("finite");
        RigidMotion::try_from_start(pose, self.v, self.w, DT).expect("a valid motion")
    }

    fn integrate(&mut self) {
        if matches!(self.shape, Shape::HalfSpace(_)) {
            return;
        }
        self.x = self.x + self.v * DT;
        let turn = self.w.length() * DT;
        if turn > 0.0 {
            self.q = Rotation::try_from_axis_angle(self.w, turn).expect("a rotation") * self.q;
        }
        let (mut x, mut v) = (self.x.to_array(), self.v.to_array());
        let lo = [-HALF + self.reach, self.reach, -HALF + self.reach];
        let hi = [
            HALF - self.reach,
            2.0 * HALF - self.reach,
            HALF - self.reach,
        ];
        for k in 0..3 {
            if (x[k] > hi[k] && v[k] > 0.0) || (x[k] < lo[k] && v[k] < 0.0) {
                v[k] = -v[k];
                x[k] = x[k].clamp(lo[k], hi[k]);
            }
        }
        (self.x, self.v) = (Vec3::from_array(x), Vec3::from_array(v));
    }
}

/// The least distance over the frame between two centres moving linearly.
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

fn leak<T>(x: T) -> &'static T {
    Box::leak(Box::new(x))
}

fn main() {
    let mut rng = Rng::new(26);
    let frame = TimeInterval::try_new(0.0, DT).expect("frame");
    let bunny_mesh = {
        let m = meshes::load_shipped("bunny-npm-3674.obj.gz");
        let (c, r) = m.bounding_sphere();
        m.recentred(c)
            .and_then(|m| m.scaled(0.5 / r))
            .expect("bunny")
    };
    let bunny: &'static BallTree<f64> = leak(BallTree::try_from_mesh(&bunny_mesh).expect("tree"));
    let at = |x: [f64; 3]| Isometry::try_from_translation(Vec3::from_array(x)).expect("pose");
    let mut bodies = Vec::new();
    let ground = HalfSpace::try_new(Vec3::new(0.0, 1.0, 0.0)).expect("ground");
    bodies.push(Body {
        kind: "ground",
        shape: Shape::HalfSpace(ground),
        solid: Solid::default(),
        reach: 0.0,
        x: Vec3::ZERO,
        q: Rotation::IDENTITY,
        v: Vec3::ZERO,
        w: Vec3::ZERO,
    });
    for _ in 0..10 {
        let r = rng.range(0.15, 0.3);
        bodies.push(Body::new(
            "ball",
            Shape::Convex(Convex::try_ball(r).expect("ball")),
            Solid::ball(r),
            &mut rng,
        ));
    }
    for _ in 0..10 {
        let (h, r) = (rng.range(0.15, 0.4), rng.range(0.08, 0.2));
        let s = Convex::try_capsule(h, r).expect("capsule");
        bodies.push(Body::new(
            "capsule",
            Shape::Convex(s),
            Solid::capsule(h, r),
            &mut rng,
        ));
    }
    for k in 0..10 {
        let half = [
            rng.range(0.1, 0.35),
            rng.range(0.1, 0.35),
            rng.range(0.1, 0.35),
        ];
        let r = if k % 3 == 0 { 0.05 } else { 0.0 };
        let s = Convex::try_cuboid(half)
            .and_then(|c| c.try_rounded(r))
            .expect("cuboid");
        bodies.push(Body::new(
            "cuboid",
            Shape::Convex(s),
            Solid::cuboid(half, r),
            &mut rng,
        ));
    }
    for _ in 0..5 {
        let (h, rho) = (rng.range(0.15, 0.4), rng.range(0.1, 0.3));
        let s = Convex::try_cylinder(h, rho).expect("cylinder");
        bodies.push(Body::new(
            "cylinder",
            Shape::Convex(s),
            Solid::cylinder(h, rho),
            &mut rng,
        ));
    }
    for _ in 0..5 {
        let (h, rho) = (rng.range(0.15, 0.4), rng.range(0.1, 0.3));
        let s = Convex::try_cone(h, rho).expect("cone");
        bodies.push(Body::new(
            "cone",
            Shape::Convex(s),
            Solid::cone(h, rho),
            &mut rng,
        ));
    }
    for _ in 0..5 {
        bodies.push(Body::new(
            "bunny",
            Shape::Mesh(bunny),
            Solid::mesh(&bunny_mesh),
            &mut rng,
        ));
    }
    // A table: a top and four legs.
    let (top, leg) = ([0.5, 0.04, 0.35], [0.04, 0.3, 0.04]);
    let table_at = [
        ([0.0, 0.3, 0.0], top),
        ([0.42, 0.0, 0.28], leg),
        ([-0.42, 0.0, 0.28], leg),
        ([0.42, 0.0, -0.28], leg),
        ([-0.42, 0.0, -0.28], leg),
    ];
    let table = leak(
        Compound::try_new(
            table_at
                .iter()
                .map(|(x, h)| {
                    Part::Convex(
                        Convex::try_cuboid(*h)
                            .and_then(|c| c.try_placed(at(*x)))
                            .expect("part"),
                    )
                })
                .collect(),
        )
        .expect("table"),
    );
    let table_truth = Solid::union(
        table_at
            .iter()
            .map(|(x, h)| Solid::cuboid(*h, 0.0).placed(&at(*x)))
            .collect(),
    );
    bodies.push(Body::new(
        "compound",
        Shape::Compound(table),
        table_truth,
        &mut rng,
    ));
    // A dumbbell: two balls on a bar along x.
    let bar = Isometry::try_new(
        Rotation::try_from_axis_angle(Vec3::new(0.0, 0.0, 1.0), core::f64::consts::FRAC_PI_2)
            .expect("rotation"),
        Vec3::ZERO,
    )
    .expect("pose");
    let dumbbell = leak(
        Compound::try_new(vec![
            Part::Convex(
                Convex::try_ball(0.2)
                    .and_then(|b| b.try_placed(at([-0.45, 0.0, 0.0])))
                    .expect("ball"),
            ),
            Part::Convex(
                Convex::try_ball(0.2)
                    .and_then(|b| b.try_placed(at([0.45, 0.0, 0.0])))
                    .expect("ball"),
            ),
            Part::Convex(
                Convex::try_capsule(0.45, 0.05)
                    .and_then(|c| c.try_placed(bar))
                    .expect("bar"),
            ),
        ])
        .expect("dumbbell"),
    );
    let dumbbell_truth = Solid::union(vec![
        Solid::ball(0.2).placed(&at([-0.45, 0.0, 0.0])),
        Solid::ball(0.2).placed(&at([0.45, 0.0, 0.0])),
        Solid::capsule(0.45, 0.05).placed(&bar),
    ]);
    bodies.push(Body::new(
        "compound",
        Shape::Compound(dumbbell),
        dumbbell_truth,
        &mut rng,
    ));
    // A bunny on a box.
    let stand = at([0.0, -0.55, 0.0]);
    let bunny_box = leak(
        Compound::try_new(vec![
            Part::Mesh(bunny),
            Part::Convex(
                Convex::try_cuboid([0.35, 0.1, 0.35])
                    .and_then(|c| c.try_placed(stand))
                    .expect("box"),
            ),
        ])
        .expect("bunny on a box"),
    );
    let bunny_box_truth = Solid::union(vec![
        Solid::mesh(&bunny_mesh),
        Solid::cuboid([0.35, 0.1, 0.35], 0.0).placed(&stand),
    ]);
    bodies.push(Body::new(
        "compound",
        Shape::Compound(bunny_box),
        bunny_box_truth,
        &mut rng,
    ));

    println!(
        "{} bodies in a room of half width {HALF} for {FRAMES} frames of {DT:.4}",
        bodies.len()
    );
    let params = SceneParams::default().with_ca(CaParams::default().with_contact_distance(1e-3));
    let mut ws = SceneWorkspace::new();
    let (mut pairs, mut missed, mut late, mut contacts, mut checked, mut culled_checked) =
        (0u64, 0, 0, 0, 0, 0);
    let mut kinds = BTreeSet::new();
    let mut seconds = 0.0;
    // The work and outcomes, summed, to compare two builds (the times' sum
    // in full precision: equal sums of equal counts mean equal answers).
    let (mut iterations, mut node_pairs, mut separations, mut time_sum) = (0u64, 0u64, 0u64, 0.0);
    for f in 0..FRAMES {
        let motions: Vec<RigidMotion<f64>> = bodies.iter().map(|b| b.motion(frame)).collect();
        let mut scene = Scene::try_new(frame).expect("scene");
        for (b, m) in bodies.iter().zip(&motions) {
            scene.try_add(b.shape, *m).expect("a body");
        }
        let start = Instant::now();
        let report = scene.query(&mut ws, &params).expect("query");
        seconds += start.elapsed().as_secs_f64();
        let mut tested = BTreeSet::new();
        let mut impulses = Vec::new();
        for p in report.pairs() {
            let (a, b) = (&bodies[p.a], &bodies[p.b]);
            pairs += 1;
            tested.insert((p.a, p.b));
            let (ka, kb) = if a.kind <= b.kind {
                (a.kind, b.kind)
            } else {
                (b.kind, a.kind)
            };
            kinds.insert((ka, kb));
            let reported = p.report.outcome.earliest_possible_contact();
            iterations += u64::from(p.report.iterations);
            node_pairs += p.node_pairs;
            separations += u64::from(p.report.outcome == motion_bound::ca::CaOutcome::Separated);
            time_sum += reported.unwrap_or(0.0);
            if let Some(c) = p.report.outcome.contact() {
                contacts += 1;
                let n = c.normal.map_or(b.x - a.x, motion_bound::Direction::get);
                impulses.push((p.a, p.b, n));
            }
            let truth = truth(a, &motions[p.a], b, &motions[p.b]);
            if let Some(g) = truth {
                checked += 1;
                match reported {
                    None => {
                        missed += 1;
                        println!(
                            "frame {f}: MISSED {} / {}: sampled at {g}, {:?}",
                            a.kind, b.kind, p.report
                        );
                    }
                    Some(t) if t > g => {
                        late += 1;
                        println!("frame {f}: LATE {} / {}: {t} after {g}", a.kind, b.kind);
                    }
                    _ => {}
                }
            }
        }
        // Every culled pair that comes close: it must not touch.
        for i in 0..bodies.len() {
            for j in i + 1..bodies.len() {
                if tested.contains(&(i, j)) {
                    continue;
                }
                let (a, b) = (&bodies[i], &bodies[j]);
                let ground = [a, b]
                    .iter()
                    .filter(|x| matches!(x.shape, Shape::HalfSpace(_)))
                    .count();
                if ground == 2 {
                    continue;
                }
                let close = if ground == 1 {
                    let body = if ground == 1 && matches!(a.shape, Shape::HalfSpace(_)) {
                        b
                    } else {
                        a
                    };
                    body.x.y.min(body.x.y + body.v.y * DT) <= body.reach + 0.1
                } else {
                    closest_centres(a, b) <= a.reach + b.reach + 0.1
                };
                if !close {
                    continue;
                }
                culled_checked += 1;
                if let Some(g) = truth(a, &motions[i], b, &motions[j]) {
                    missed += 1;
                    println!(
                        "frame {f}: MISSED (culled) {} / {}: sampled at {g}",
                        a.kind, b.kind
                    );
                }
            }
        }
        for (i, j, n) in impulses {
            let n = n * (1.0 / n.length().max(1e-300));
            if matches!(bodies[i].shape, Shape::HalfSpace(_)) {
                let vj = bodies[j].v;
                bodies[j].v = vj - n * (2.0 * vj.dot(n).min(0.0));
            } else if matches!(bodies[j].shape, Shape::HalfSpace(_)) {
                let vi = bodies[i].v;
                bodies[i].v = vi - n * (2.0 * vi.dot(n).max(0.0));
            } else {
                let (vi, vj) = (bodies[i].v, bodies[j].v);
                let (si, sj) = (vi.dot(n), vj.dot(n));
                if si > sj {
                    bodies[i].v = vi + n * (sj - si);
                    bodies[j].v = vj + n * (si - sj);
                }
            }
        }
        for b in &mut bodies {
            b.integrate();
        }
    }
    println!(
        "{contacts} contacts; ground truth on {checked} tested pairs with a sampled contact and {culled_checked} close culled pairs; pair kinds: {kinds:?}"
    );
    println!(
        "work: iterations {iterations}, node pairs {node_pairs}, contacts {contacts}, separations {separations}, contact times' sum {time_sum:.17e}"
    );
    println!(
        "frames {FRAMES}, pairs {pairs}, pair kinds {}, missed {missed}, late {late}, mean ms per query {:.4}",
        kinds.len(),
        seconds * 1e3 / pairs.max(1) as f64
    );
}

/// The first sampled contact of two bodies over the frame (a ground by its
/// plane).
fn truth(a: &Body, ma: &RigidMotion<f64>, b: &Body, mb: &RigidMotion<f64>) -> Option<f64> {
    match (&a.shape, &b.shape) {
        (Shape::HalfSpace(h), _) => first_sampled_landing(
            &b.solid,
            mb,
            ma,
            h.normal().get().to_array(),
            (0.0, DT),
            SAMPLES,
        ),
        (_, Shape::HalfSpace(h)) => first_sampled_landing(
            &a.solid,
            ma,
            mb,
            h.normal().get().to_array(),
            (0.0, DT),
            SAMPLES,
        ),
        _ => {
            if closest_centres(a, b) > a.reach + b.reach + 0.05 {
                return None;
            }
            first_sampled_contact(&a.solid, ma, &b.solid, mb, (0.0, DT), SAMPLES)
        }
    }
}
