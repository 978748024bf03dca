//! Conservative advancement of every pair of convex shape kinds
//! (`ConvexPair`) against sampled ground truth: never late, never missed
//! (`proofs/12-shapes.md`).
//!
//! The ground truth is independent of the code under test: each shape's core
//! is tessellated *inside* itself (cylinder and cone rims by inscribed
//! 24-gons, a polytope by every triangle of three of its vertices, segments
//! and points as degenerate triangles), placed at each sampled time by the
//! testkit's own quaternion placement, and the shapes are taken to touch when
//! two of their triangles are within the sum of the radii (the exact
//! triangle distance). An inscribed core is inside the true one, so a
//! sampled contact is a true contact: the first sampled one is never before
//! the true first contact, and a query reporting later, or `Separated`,
//! fails. `SHAPES_QUERIES` sets the queries per pair of kinds (default 3).

#[path = "common/shape_truth.rs"]
mod shape_truth;

use motion_bound::bodies::{torus, TorusKnot};
use motion_bound::ca::{
    time_of_impact, AnyPair, CaError, CaOutcome, CaParams, ConvexPair, HalfSpacePair,
    MeshConvexPair, Shape,
};
use motion_bound::testkit::toi::Rng;
use motion_bound::{
    BallTree, BoundingBall, Convex, HalfSpace, RigidMotion, TriMesh, Vec3, VertexSet,
};
use shape_truth::Solid;

/// Ground-truth samples over `[0, 1]`.
const SAMPLES: usize = 200;
/// Sides of the inscribed polygons of rims.
const SIDES: usize = 24;

/// A shape kind: its shape, its core's inscribed triangles, its radius.
struct Kind {
    name: &'static str,
    shape: Convex<'static, f64>,
    triangles: Vec<[[f64; 3]; 3]>,
    radius: f64,
}

fn rim(h: f64, rho: f64, y: f64) -> Vec<[f64; 3]> {
    (0..SIDES)
        .map(|k| {
            let phi = k as f64 * core::f64::consts::TAU / SIDES as f64;
            // Pulled in by 1e-12 so that rounding keeps it inside.
            let r = rho * (1.0 - 1e-12);
            [r * phi.cos(), y * h * (1.0 - 1e-12), r * phi.sin()]
        })
        .collect()
}

fn fan(centre: [f64; 3], ring: &[[f64; 3]]) -> Vec<[[f64; 3]; 3]> {
    (0..ring.len())
        .map(|k| [centre, ring[k], ring[(k + 1) % ring.len()]])
        .collect()
}

fn kinds(vertices: &'static [[f64; 3]]) -> Vec<Kind> {
    let (h, r, rho) = (0.4, 0.15, 0.35);
    let half = [0.4, 0.25, 0.3];
    let mut box_tris = Vec::new();
    let c = |k: usize| [0, 1, 2].map(|i| if k >> i & 1 == 1 { half[i] } else { -half[i] });
    for axis in 0..3 {
        for side in 0..2 {
            let corners: Vec<[f64; 3]> =
                (0..8).filter(|&k| (k >> axis) & 1 == side).map(c).collect();
            // The face's four corners: both diagonal triangulations.
            box_tris.push([corners[0], corners[1], corners[2]]);
            box_tris.push([corners[1], corners[2], corners[3]]);
            box_tris.push([corners[0], corners[1], corners[3]]);
            box_tris.push([corners[0], corners[2], corners[3]]);
        }
    }
    let mut cylinder = Vec::new();
    let (top, bottom) = (rim(h, rho, 1.0), rim(h, rho, -1.0));
    for k in 0..SIDES {
        let j = (k + 1) % SIDES;
        cylinder.push([top[k], top[j], bottom[k]]);
        cylinder.push([top[j], bottom[j], bottom[k]]);
    }
    cylinder.extend(fan([0.0, h, 0.0], &top));
    cylinder.extend(fan([0.0, -h, 0.0], &bottom));
    let mut cone = fan([0.0, h * (1.0 - 1e-12), 0.0], &bottom);
    cone.extend(fan([0.0, -h, 0.0], &bottom));
    let mut poly = Vec::new();
    for i in 0..vertices.len() {
        for j in i + 1..vertices.len() {
            for k in j + 1..vertices.len() {
                poly.push([vertices[i], vertices[j], vertices[k]]);
            }
        }
    }
    let set = VertexSet::try_new(vertices).expect("vertices");
    let point = vec![[[0.0; 3]; 3]];
    let seg = vec![[[0.0, -h, 0.0], [0.0, h, 0.0], [0.0, h, 0.0]]];
    let k = |name, shape: Result<Convex<'static, f64>, _>, triangles, radius| Kind {
        name,
        shape: shape.expect("a valid shape"),
        triangles,
        radius,
    };
    vec![
        k("ball", Convex::try_ball(r), point, r),
        k("capsule", Convex::try_capsule(h, r), seg, r),
        k("cuboid", Convex::try_cuboid(half), box_tris.clone(), 0.0),
        k(
            "rounded cuboid",
            Convex::try_cuboid(half).and_then(|s| s.try_rounded(0.1)),
            box_tris,
            0.1,
        ),
        k(
            "cylinder",
            Convex::try_cylinder(h, rho),
            cylinder.clone(),
            0.0,
        ),
        k(
            "rounded cylinder",
            Convex::try_cylinder(h, rho).and_then(|s| s.try_rounded(0.05)),
            cylinder,
            0.05,
        ),
        k("cone", Convex::try_cone(h, rho), cone, 0.0),
        k("polytope", Ok(Convex::polytope(set)), poly, 0.0),
    ]
}

/// The first sampled time at which the two shapes touch (their inscribed
/// cores within the sum of the radii): `shape_truth`'s, with its per-part
/// and per-triangle culls.
fn first_sampled_contact(
    a: &Kind,
    ma: &RigidMotion<f64>,
    b: &Kind,
    mb: &RigidMotion<f64>,
) -> Option<f64> {
    shape_truth::first_sampled_contact(&solid(a), ma, &solid(b), mb, (0.0, 1.0), SAMPLES)
}

/// A kind's ground truth as `shape_truth`'s body.
fn solid(k: &Kind) -> Solid {
    Solid {
        parts: vec![(k.triangles.clone(), k.radius)],
    }
}

#[test]
fn every_pair_of_shape_kinds_is_never_late_and_never_missed() {
    let queries: usize = std::env::var("SHAPES_QUERIES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(3);
    let mut rng = Rng::new(26);
    let vertices: &'static [[f64; 3]] = Box::leak(
        (0..8)
            .map(|_| rng.direction().map(|x| x * rng.range(0.2, 0.45)))
            .collect::<Vec<_>>()
            .into_boxed_slice(),
    );
    let kinds = kinds(vertices);
    let (mut pairs, mut contacts, mut sampled, mut separated) = (0, 0, 0, 0);
    let mut undecided = Vec::new();
    for i in 0..kinds.len() {
        for j in i..kinds.len() {
            let (a, b) = (&kinds[i], &kinds[j]);
            pairs += 1;
            let before = (contacts, sampled, separated, undecided.len());
            for q in 0..queries {
                // A flies at B from 1.2 to 1.6 apart, aimed within 0.6 of
                // B's centre, both spinning.
                let start = rng.direction().map(|x| x * rng.range(1.2, 1.6));
                let aim = rng.direction().map(|x| x * 0.6 * rng.unit());
                let v = [0, 1, 2].map(|k| aim[k] - start[k]);
                let spin = [0.0, 3.0, 20.0][q % 3];
                let wa = rng.direction().map(|x| x * spin * rng.unit());
                let wb = rng.direction().map(|x| x * spin * 0.25 * rng.unit());
                let ma = RigidMotion::try_from_arrays(start, v, wa).expect("motion");
                let mb = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], wb).expect("motion");
                let params = CaParams::default().with_contact_distance(1e-3);
                let report =
                    time_of_impact(&mut ConvexPair::new(a.shape, b.shape), &ma, &mb, &params)
                        .expect("a valid query");
                let truth = first_sampled_contact(a, &ma, b, &mb);
                let what = format!(
                    "{} vs {} query {q}: {report:?}, sampled {truth:?}",
                    a.name, b.name
                );
                let reported = report.outcome.earliest_possible_contact();
                match (reported, truth) {
                    (None, Some(_)) => panic!("MISSED: {what}"),
                    (Some(t), Some(g)) => assert!(t <= g, "LATE: {what}"),
                    _ => {}
                }
                contacts += usize::from(report.outcome.contact().is_some());
                sampled += usize::from(truth.is_some());
                separated += usize::from(matches!(report.outcome, CaOutcome::Separated));
                if report.outcome.contact().is_none()
                    && !matches!(report.outcome, CaOutcome::Separated)
                {
                    undecided.push(format!("{} vs {}: {:?}", a.name, b.name, report.outcome));
                }
            }
            println!(
                "{} - {}: {queries} queries, {} contacts, {} sampled contacts, {} separated, {} undecided; 0 missed, 0 late",
                a.name,
                b.name,
                contacts - before.0,
                sampled - before.1,
                separated - before.2,
                undecided.len() - before.3
            );
        }
    }
    println!(
        "{pairs} pairs of kinds, {} queries: {contacts} contacts, {sampled} sampled contacts, {separated} separated, {} undecided {undecided:?}; 0 missed, 0 late",
        pairs * queries,
        undecided.len()
    );
    assert!(
        sampled * 2 >= pairs * queries,
        "too few sampled contacts for power"
    );
}

/// The first sampled time at which the shape comes within its radius of the
/// ground plane `{x : (x - p(t)) . m <= 0}`.
fn first_sampled_landing(
    a: &Kind,
    ma: &RigidMotion<f64>,
    ground: &RigidMotion<f64>,
    m: [f64; 3],
) -> Option<f64> {
    shape_truth::first_sampled_landing(&solid(a), ma, ground, m, (0.0, 1.0), SAMPLES)
}

#[test]
fn every_shape_kind_against_a_moving_ground_is_never_late_and_never_missed() {
    let queries: usize = std::env::var("SHAPES_QUERIES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(3)
        * 4;
    let mut rng = Rng::new(27);
    let vertices: &'static [[f64; 3]] = Box::leak(
        (0..8)
            .map(|_| rng.direction().map(|x| x * rng.range(0.2, 0.45)))
            .collect::<Vec<_>>()
            .into_boxed_slice(),
    );
    let (mut landed, mut sampled) = (0, 0);
    for kind in &kinds(vertices) {
        for q in 0..queries {
            // A tilted ground rising slowly; the shape thrown down at it.
            let m = {
                let d = rng.direction();
                let up = [d[0] * 0.3, 1.0, d[2] * 0.3];
                let l = (up[0] * up[0] + up[1] * up[1] + up[2] * up[2]).sqrt();
                up.map(|x| x / l)
            };
            let ground = HalfSpace::try_new(Vec3::from_array(m)).expect("normal");
            let stored = ground.normal().get().to_array();
            let mg = RigidMotion::try_from_arrays([0.0; 3], m.map(|x| x * 0.2), [0.0; 3])
                .expect("ground");
            let start = [
                rng.range(-1.0, 1.0),
                rng.range(0.8, 1.5),
                rng.range(-1.0, 1.0),
            ];
            let v = [
                rng.range(-1.0, 1.0),
                -rng.range(0.5, 3.0),
                rng.range(-1.0, 1.0),
            ];
            let spin = [0.0, 3.0, 20.0][q % 3];
            let w = rng.direction().map(|x| x * spin * rng.unit());
            let ma = RigidMotion::try_from_arrays(start, v, w).expect("motion");
            let params = CaParams::default().with_contact_distance(1e-3);
            let report = time_of_impact(
                &mut HalfSpacePair::new(kind.shape, ground),
                &ma,
                &mg,
                &params,
            )
            .expect("a valid query");
            let truth = first_sampled_landing(kind, &ma, &mg, stored);
            let what = format!("{} query {q}: {report:?}, sampled {truth:?}", kind.name);
            match (report.outcome.earliest_possible_contact(), truth) {
                (None, Some(_)) => panic!("MISSED: {what}"),
                (Some(t), Some(g)) => assert!(t <= g, "LATE: {what}"),
                _ => {}
            }
            landed += usize::from(report.outcome.contact().is_some());
            sampled += usize::from(truth.is_some());
        }
    }
    println!(
        "{} landings: {landed} contacts, {sampled} sampled; 0 missed, 0 late",
        8 * queries
    );
    assert!(
        sampled * 2 >= 8 * queries,
        "too few sampled landings for power"
    );
    // A turning half-space is a typed error, not a guess.
    let ball = Convex::try_ball(0.1).expect("ball");
    let ground = HalfSpace::try_new(Vec3::new(0.0, 1.0, 0.0)).expect("normal");
    let a = RigidMotion::try_from_arrays([0.0, 1.0, 0.0], [0.0; 3], [0.0; 3]).expect("motion");
    let spinning =
        RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0, 0.0, 1.0]).expect("motion");
    let r = time_of_impact(
        &mut HalfSpacePair::new(ball, ground),
        &a,
        &spinning,
        &CaParams::default(),
    );
    assert_eq!(r.err(), Some(CaError::TurnedHalfSpace), "a spinning ground");
}

/// A mesh as a `Kind` (its triangles exactly, no radius).
fn mesh_kind(name: &'static str, mesh: &TriMesh<f64>) -> Kind {
    Kind {
        name,
        shape: Convex::try_ball(0.0).expect("unused"),
        triangles: mesh.triangle_corners().collect(),
        radius: 0.0,
    }
}

#[test]
fn meshes_against_every_shape_kind_and_the_ground_are_never_late_and_never_missed() {
    let queries: usize = std::env::var("SHAPES_QUERIES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(3)
        * 2;
    let mut rng = Rng::new(28);
    let vertices: &'static [[f64; 3]] = Box::leak(
        (0..8)
            .map(|_| rng.direction().map(|x| x * rng.range(0.2, 0.45)))
            .collect::<Vec<_>>()
            .into_boxed_slice(),
    );
    let ring = torus::<f64>(0.5, 0.12, 24, 8).expect("ring");
    let knot = TorusKnot::TREFOIL.mesh::<f64>(48, 6).expect("knot");
    let (mut contacts, mut sampled, mut n) = (0, 0, 0);
    for (name, mesh) in [("ring", &ring), ("knot", &knot)] {
        let tree = BallTree::try_from_mesh(mesh).expect("tree");
        let as_kind = mesh_kind(name, mesh);
        for kind in &kinds(vertices) {
            for q in 0..queries {
                let start = rng.direction().map(|x| x * rng.range(1.2, 1.6));
                let aim = rng.direction().map(|x| x * 0.6 * rng.unit());
                let v = [0, 1, 2].map(|k| aim[k] - start[k]);
                let spin = [0.0, 3.0, 20.0][q % 3];
                let wa = rng.direction().map(|x| x * spin * 0.25 * rng.unit());
                let wb = rng.direction().map(|x| x * spin * rng.unit());
                // The mesh is body A (turning in place), the shape flies in.
                let ma = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], wa).expect("motion");
                let mb = RigidMotion::try_from_arrays(start, v, wb).expect("motion");
                let params = CaParams::default().with_contact_distance(1e-3);
                let report = time_of_impact(
                    &mut MeshConvexPair::new(&tree, kind.shape),
                    &ma,
                    &mb,
                    &params,
                )
                .expect("a valid query");
                let truth = first_sampled_contact(&as_kind, &ma, kind, &mb);
                let what = format!(
                    "{name} vs {} query {q}: {report:?}, sampled {truth:?}",
                    kind.name
                );
                match (report.outcome.earliest_possible_contact(), truth) {
                    (None, Some(_)) => panic!("MISSED: {what}"),
                    (Some(t), Some(g)) => assert!(t <= g, "LATE: {what}"),
                    _ => {}
                }
                contacts += usize::from(report.outcome.contact().is_some());
                sampled += usize::from(truth.is_some());
                n += 1;
            }
        }
        // The mesh thrown on a rising ground.
        for q in 0..queries * 4 {
            let m = [0.0, 1.0, 0.0];
            let ground = HalfSpace::try_new(Vec3::from_array(m)).expect("normal");
            let mg =
                RigidMotion::try_from_arrays([0.0; 3], [0.0, 0.2, 0.0], [0.0; 3]).expect("ground");
            let start = [
                rng.range(-1.0, 1.0),
                rng.range(0.8, 1.5),
                rng.range(-1.0, 1.0),
            ];
            let v = [
                rng.range(-1.0, 1.0),
                -rng.range(0.5, 3.0),
                rng.range(-1.0, 1.0),
            ];
            let w = rng
                .direction()
                .map(|x| x * [0.0, 3.0, 20.0][q % 3] * rng.unit());
            let ma = RigidMotion::try_from_arrays(start, v, w).expect("motion");
            let params = CaParams::default().with_contact_distance(1e-3);
            let report = time_of_impact(
                &mut MeshConvexPair::with_half_space(&tree, ground),
                &ma,
                &mg,
                &params,
            )
            .expect("a valid query");
            let truth = first_sampled_landing(&as_kind, &ma, &mg, m);
            let what = format!("{name} on the ground query {q}: {report:?}, sampled {truth:?}");
            match (report.outcome.earliest_possible_contact(), truth) {
                (None, Some(_)) => panic!("MISSED: {what}"),
                (Some(t), Some(g)) => assert!(t <= g, "LATE: {what}"),
                _ => {}
            }
            contacts += usize::from(report.outcome.contact().is_some());
            sampled += usize::from(truth.is_some());
            n += 1;
        }
    }
    println!("{n} mesh queries: {contacts} contacts, {sampled} sampled; 0 missed, 0 late");
    assert!(sampled * 2 >= n, "too few sampled contacts for power");
}

/// `AnyPair` takes every pair of kinds in either order, and the order
/// changes nothing but which body is A: the same outcome, the time within
/// rounding, the normal reversed. Two half-spaces are a typed error.
#[test]
fn any_pair_answers_every_pair_of_kinds_in_either_order() {
    let mut rng = Rng::new(29);
    let vertices: &'static [[f64; 3]] = Box::leak(
        (0..8)
            .map(|_| rng.direction().map(|x| x * rng.range(0.2, 0.45)))
            .collect::<Vec<_>>()
            .into_boxed_slice(),
    );
    let ring = torus::<f64>(0.5, 0.12, 24, 8).expect("ring");
    let tree = BallTree::try_from_mesh(&ring).expect("tree");
    let ground = HalfSpace::try_new(Vec3::new(0.0, 1.0, 0.0)).expect("normal");
    let mut shapes: Vec<(&str, Shape<'_, f64>)> = kinds(vertices)
        .into_iter()
        .map(|k| (k.name, Shape::Convex(k.shape)))
        .collect();
    shapes.push(("ring", Shape::Mesh(&tree)));
    shapes.push(("ground", Shape::HalfSpace(ground)));
    // The dispatch's own fast paths: two vertex sets (GJK on the points) and
    // two balls (closed form), and each met by every other kind.
    shapes.push((
        "vertex set",
        Shape::VertexSet(VertexSet::try_new(vertices).expect("points")),
    ));
    shapes.push((
        "offset ball",
        Shape::Ball(BoundingBall::try_new([0.1, -0.05, 0.08], 0.3).expect("ball")),
    ));
    let mut checked = 0;
    for (na, a) in &shapes {
        for (nb, b) in &shapes {
            let grounds = usize::from(matches!(a, Shape::HalfSpace(_)))
                + usize::from(matches!(b, Shape::HalfSpace(_)));
            if grounds == 2 {
                assert_eq!(AnyPair::try_new(*a, *b).err(), Some(CaError::Unsupported));
                continue;
            }
            for _ in 0..3 {
                // B's start is above A's (a ground stays at the origin and
                // still: it may only translate).
                let spin = |rng: &mut Rng, s: &Shape<'_, f64>| match s {
                    Shape::HalfSpace(_) => [0.0; 3],
                    _ => rng.direction().map(|x| x * 3.0 * rng.unit()),
                };
                let at = |rng: &mut Rng, s: &Shape<'_, f64>, y: f64| match s {
                    Shape::HalfSpace(_) => [0.0; 3],
                    _ => [rng.range(-0.3, 0.3), y, rng.range(-0.3, 0.3)],
                };
                let ma =
                    RigidMotion::try_from_arrays(at(&mut rng, a, 0.0), [0.0; 3], spin(&mut rng, a))
                        .expect("motion");
                let mb = RigidMotion::try_from_arrays(
                    at(&mut rng, b, 2.0),
                    if matches!(b, Shape::HalfSpace(_)) {
                        [0.0, 0.5, 0.0]
                    } else {
                        [0.0, -3.0, 0.0]
                    },
                    spin(&mut rng, b),
                )
                .expect("motion");
                let params = CaParams::default().with_contact_distance(1e-3);
                let ab = time_of_impact(
                    &mut AnyPair::try_new(*a, *b).expect("pair"),
                    &ma,
                    &mb,
                    &params,
                )
                .expect("query");
                let ba = time_of_impact(
                    &mut AnyPair::try_new(*b, *a).expect("pair"),
                    &mb,
                    &ma,
                    &params,
                )
                .expect("query");
                let what = format!("{na} / {nb}: {ab:?} against {ba:?}");
                assert_eq!(
                    core::mem::discriminant(&ab.outcome),
                    core::mem::discriminant(&ba.outcome),
                    "{what}"
                );
                let (ta, tb) = (
                    ab.outcome.earliest_possible_contact(),
                    ba.outcome.earliest_possible_contact(),
                );
                if let (Some(x), Some(y)) = (ta, tb) {
                    assert!((x - y).abs() <= 1e-3 / 3.0, "{what}");
                }
                if let (Some(x), Some(y)) = (ab.outcome.contact(), ba.outcome.contact()) {
                    if let (Some(p), Some(q)) = (x.normal, y.normal) {
                        assert!(p.get().dot(q.get()) < -0.9, "normals not reversed: {what}");
                    }
                }
                checked += 1;
            }
        }
    }
    println!("{checked} ordered pairs of kinds checked in both orders");
}

/// A body of several parts for the ground truth: each part's inscribed
/// triangles (placed in the body frame) and radius.
struct Multi {
    name: &'static str,
    shape: Shape<'static, f64>,
    parts: Vec<(Vec<[[f64; 3]; 3]>, f64)>,
}

/// The dispatch's arms for vertex sets and balls, against closed forms: a
/// cube (its eight corners as a vertex set) and a ball off its body origin
/// fall without turning onto the ground, a convex ball, each other and
/// themselves; the first touch is where their lowest points (or centres'
/// distance) say. Never late, and within the closing time of the contact
/// distance.
#[test]
fn vertex_sets_and_balls_meet_every_kind_where_the_closed_form_says() {
    let mut cube = [[0.0f64; 3]; 8];
    for (i, c) in cube.iter_mut().enumerate() {
        *c = [0, 1, 2].map(|k| if i >> k & 1 == 1 { 0.5 } else { -0.5 });
    }
    let set = Shape::VertexSet(VertexSet::try_new(&cube).expect("cube"));
    // A ball of radius 0.25 whose centre is 0.1 below the body origin.
    let ball = Shape::Ball(BoundingBall::try_new([0.0, -0.1, 0.0], 0.25).expect("ball"));
    let ground = Shape::HalfSpace(HalfSpace::try_new(Vec3::new(0.0, 1.0, 0.0)).expect("n"));
    let sphere = Shape::Convex(Convex::try_ball(0.5).expect("sphere"));
    // How far below its body origin each falling shape reaches, and how far
    // above its origin each still one does (both along y).
    let below = |s: &Shape<'_, f64>| match s {
        Shape::VertexSet(_) => 0.5,
        Shape::Ball(_) => 0.35,
        _ => unreachable!("only the cube and the ball fall"),
    };
    let above = |s: &Shape<'_, f64>| match s {
        Shape::VertexSet(_) => 0.5,
        Shape::Ball(_) => 0.15,
        Shape::Convex(_) => 0.5,
        Shape::HalfSpace(_) => 0.0,
        _ => unreachable!("no other kind is still"),
    };
    let params = CaParams::default().with_contact_distance(1e-3);
    let speed = 4.0;
    let mut checked = 0;
    for falling in [set, ball] {
        for still in [ground, sphere, set, ball] {
            for order in [false, true] {
                let y0 = 3.0;
                let drop =
                    RigidMotion::try_from_arrays([0.0, y0, 0.0], [0.0, -speed, 0.0], [0.0; 3])
                        .expect("motion");
                let rest =
                    RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0; 3]).expect("rest");
                let report = if order {
                    time_of_impact(
                        &mut AnyPair::try_new(still, falling).expect("pair"),
                        &rest,
                        &drop,
                        &params,
                    )
                } else {
                    time_of_impact(
                        &mut AnyPair::try_new(falling, still).expect("pair"),
                        &drop,
                        &rest,
                        &params,
                    )
                }
                .expect("query");
                // Faces, a face and a ball, or two balls on one vertical line:
                // the gap along y is the distance.
                let truth = (y0 - below(&falling) - above(&still)) / speed;
                let what = format!(
                    "{:?} onto {:?} ({order}): {report:?}, truth {truth}",
                    falling.kind(),
                    still.kind()
                );
                let t = report.outcome.contact().expect(&what).time;
                assert!(t <= truth, "LATE: {what}");
                assert!(t >= truth - 1e-3 / speed, "too early: {what}");
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 16, "every pair in both orders");
}

/// The first sampled time at which some part of `a` comes within the sum
/// of radii of some part of `b`.
fn first_sampled_multi(
    a: &Multi,
    ma: &RigidMotion<f64>,
    b: &Multi,
    mb: &RigidMotion<f64>,
) -> Option<f64> {
    let solid = |m: &Multi| Solid {
        parts: m.parts.clone(),
    };
    shape_truth::first_sampled_contact(&solid(a), ma, &solid(b), mb, (0.0, 1.0), SAMPLES)
}

/// Triangles mapped by a pose (the stored matrix and the translation).
fn placed_triangles(
    tris: &[[[f64; 3]; 3]],
    pose: &motion_bound::Isometry<f64>,
) -> Vec<[[f64; 3]; 3]> {
    let m = pose.rotation().matrix();
    let t = pose.translation().to_array();
    tris.iter()
        .map(|tri| {
            tri.map(|p| [0, 1, 2].map(|i| (0..3).map(|j| m[i][j] * p[j]).sum::<f64>() + t[i]))
        })
        .collect()
}

#[test]
fn compounds_against_every_kind_are_never_late_and_never_missed() {
    use motion_bound::ca::{Compound, Part};
    use motion_bound::{Isometry, Rotation};
    let queries: usize = std::env::var("SHAPES_QUERIES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(3);
    let mut rng = Rng::new(30);
    let vertices: &'static [[f64; 3]] = Box::leak(
        (0..8)
            .map(|_| rng.direction().map(|x| x * rng.range(0.2, 0.45)))
            .collect::<Vec<_>>()
            .into_boxed_slice(),
    );
    let ks = kinds(vertices);
    let (ball, capsule, cuboid) = (&ks[0], &ks[1], &ks[2]);
    let at = |x: [f64; 3]| Isometry::try_from_translation(Vec3::from_array(x)).expect("pose");
    let turned = |axis: [f64; 3], angle: f64, x: [f64; 3]| {
        Isometry::try_new(
            Rotation::try_from_axis_angle(Vec3::from_array(axis), angle).expect("rotation"),
            Vec3::from_array(x),
        )
        .expect("pose")
    };
    // A dumbbell: two balls on a bar along x.
    let bar = turned([0.0, 0.0, 1.0], core::f64::consts::FRAC_PI_2, [0.0; 3]);
    let dumbbell_parts = [
        (ball, at([-0.5, 0.0, 0.0])),
        (ball, at([0.5, 0.0, 0.0])),
        (capsule, bar),
    ];
    // A table: a top and four legs (the cuboid kind, turned and moved).
    let table_parts = [
        (cuboid, turned([0.0, 1.0, 0.0], 0.3, [0.0, 0.35, 0.0])),
        (cuboid, at([0.45, -0.2, 0.3])),
        (cuboid, at([-0.45, -0.2, 0.3])),
        (cuboid, at([0.45, -0.2, -0.3])),
        (cuboid, at([-0.45, -0.2, -0.3])),
    ];
    let ring = torus::<f64>(0.5, 0.12, 24, 8).expect("ring");
    let ring_tree: &'static BallTree<f64> =
        Box::leak(Box::new(BallTree::try_from_mesh(&ring).expect("tree")));
    let multi = |name: &'static str,
                 parts: &[(&Kind, Isometry<f64>)],
                 mesh: Option<&TriMesh<f64>>|
     -> Multi {
        let mut shape_parts: Vec<Part<'static, f64>> = parts
            .iter()
            .map(|(k, pose)| Part::Convex(k.shape.try_placed(*pose).expect("placed")))
            .collect();
        let mut gt: Vec<(Vec<[[f64; 3]; 3]>, f64)> = parts
            .iter()
            .map(|(k, pose)| (placed_triangles(&k.triangles, pose), k.radius))
            .collect();
        if let Some(m) = mesh {
            shape_parts.push(Part::Mesh(ring_tree));
            gt.push((m.triangle_corners().collect(), 0.0));
        }
        let compound: &'static Compound<'static, f64> =
            Box::leak(Box::new(Compound::try_new(shape_parts).expect("compound")));
        Multi {
            name,
            shape: Shape::Compound(compound),
            parts: gt,
        }
    };
    let compounds = [
        multi("dumbbell", &dumbbell_parts, None),
        multi("table", &table_parts, None),
        multi(
            "ring with a box",
            &[(cuboid, turned([1.0, 0.0, 0.0], 0.5, [0.0, 0.4, 0.0]))],
            Some(&ring),
        ),
    ];
    let mut others: Vec<Multi> = ks
        .iter()
        .map(|k| Multi {
            name: k.name,
            shape: Shape::Convex(k.shape),
            parts: vec![(k.triangles.clone(), k.radius)],
        })
        .collect();
    others.push(Multi {
        name: "ring",
        shape: Shape::Mesh(ring_tree),
        parts: vec![(ring.triangle_corners().collect(), 0.0)],
    });
    let (mut n, mut contacts, mut sampled) = (0, 0, 0);
    for c in &compounds {
        for o in others.iter().chain(compounds.iter()) {
            for q in 0..queries {
                let start = rng.direction().map(|x| x * rng.range(1.4, 1.9));
                let aim = rng.direction().map(|x| x * 0.6 * rng.unit());
                let v = [0, 1, 2].map(|k| aim[k] - start[k]);
                let spin = [0.0, 3.0, 12.0][q % 3];
                let wa = rng.direction().map(|x| x * spin * 0.25 * rng.unit());
                let wb = rng.direction().map(|x| x * spin * rng.unit());
                let ma = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], wa).expect("motion");
                let mb = RigidMotion::try_from_arrays(start, v, wb).expect("motion");
                let params = CaParams::default().with_contact_distance(1e-3);
                let report = time_of_impact(
                    &mut AnyPair::try_new(c.shape, o.shape).expect("pair"),
                    &ma,
                    &mb,
                    &params,
                )
                .expect("a valid query");
                let truth = first_sampled_multi(c, &ma, o, &mb);
                let what = format!(
                    "{} vs {} query {q}: {report:?}, sampled {truth:?}",
                    c.name, o.name
                );
                match (report.outcome.earliest_possible_contact(), truth) {
                    (None, Some(_)) => panic!("MISSED: {what}"),
                    (Some(t), Some(g)) => assert!(t <= g, "LATE: {what}"),
                    _ => {}
                }
                n += 1;
                contacts += usize::from(report.outcome.contact().is_some());
                sampled += usize::from(truth.is_some());
            }
        }
    }
    println!("{n} compound queries: {contacts} contacts, {sampled} sampled; 0 missed, 0 late");
    assert!(sampled * 2 >= n, "too few sampled contacts for power");
}

/// Bad shapes are typed errors, never a panic; a capsule of zero length is
/// a ball.
#[test]
fn bad_shapes_are_typed_errors() {
    use motion_bound::ca::Compound;
    use motion_bound::{InputError, Isometry, Quantity};
    assert_eq!(
        Convex::<f64>::try_ball(-0.1),
        Err(InputError::NegativeRadius)
    );
    assert_eq!(
        Convex::<f64>::try_ball(f64::NAN),
        Err(InputError::NonFinite(Quantity::Radius))
    );
    assert_eq!(
        Convex::<f64>::try_ball(f64::INFINITY),
        Err(InputError::NonFinite(Quantity::Radius))
    );
    assert_eq!(
        Convex::<f64>::try_ball(1e300),
        Err(InputError::TooLarge(Quantity::Radius))
    );
    assert_eq!(
        Convex::<f64>::try_capsule(f64::NAN, 0.1),
        Err(InputError::NonFinite(Quantity::Extent))
    );
    assert_eq!(
        Convex::<f64>::try_capsule(0.5, -1.0),
        Err(InputError::NegativeRadius)
    );
    let stub = Convex::<f64>::try_capsule(0.0, 0.3).expect("a capsule of zero length");
    assert_eq!(
        stub.reach(),
        Convex::<f64>::try_ball(0.3).expect("ball").reach(),
        "a ball"
    );
    assert_eq!(
        Convex::<f64>::try_cuboid([1.0, -1.0, 1.0]),
        Err(InputError::NegativeRadius)
    );
    assert_eq!(
        Convex::<f64>::try_cylinder(0.0, 1.0),
        Err(InputError::ZeroHeight)
    );
    assert_eq!(
        Convex::<f64>::try_cone(0.0, 1.0),
        Err(InputError::ZeroHeight)
    );
    assert_eq!(
        Convex::<f64>::try_cone(1.0, f64::NAN),
        Err(InputError::NonFinite(Quantity::Radius))
    );
    let ball = Convex::<f64>::try_ball(0.1).expect("ball");
    assert_eq!(ball.try_rounded(-0.1), Err(InputError::NegativeRadius));
    let placed = ball.try_placed(Isometry::IDENTITY).expect("placed");
    assert_eq!(
        placed.try_placed(Isometry::IDENTITY),
        Err(InputError::AlreadyPlaced)
    );
    assert_eq!(
        HalfSpace::try_new(Vec3::<f64>::ZERO).err(),
        Some(InputError::ZeroDirection)
    );
    assert_eq!(
        HalfSpace::try_new(Vec3::new(f64::NAN, 1.0, 0.0)).err(),
        Some(InputError::NonFinite(Quantity::Direction))
    );
    assert_eq!(
        Compound::<f64>::try_new(Vec::new()).err(),
        Some(InputError::EmptyCompound)
    );
    let ground = Shape::HalfSpace(HalfSpace::try_new(Vec3::new(0.0, 1.0, 0.0)).expect("ground"));
    assert_eq!(
        AnyPair::try_new(ground, ground).err(),
        Some(CaError::Unsupported)
    );
}

/// A contact declared by distance is a near contact in truth: at its time
/// the exact ground truth (`shape_truth`, the cores as degenerate
/// triangles placed by the testkit's own quaternions) finds the bodies
/// within the contact distance. Regression: the closed-form closest points
/// of point and segment cores ignored a placed shape's own pose (a
/// compound's ball or capsule), so a contact was declared up to `0.05`
/// early in a body with a turned start (never late: the steps' gaps were
/// certified along the shape's placed supports). Found by
/// `motion-bound-parry`'s ground truth on parry's off-axis capsules.
#[test]
fn a_contact_by_distance_is_within_the_contact_distance_for_placed_cores() {
    use motion_bound::ca::ContactCriterion;
    use motion_bound::{Isometry, Rotation};
    let mut rng = Rng::new(317);
    let params = CaParams::default();
    let mut by_distance = 0;
    for q in 0..200 {
        let mut rotation = || {
            Rotation::try_from_axis_angle(
                Vec3::from_array(rng.direction()),
                rng.range(0.0, core::f64::consts::PI),
            )
            .expect("rotation")
        };
        let (place_rotation, start_rotation) = (rotation(), rotation());
        let offset = rng.direction().map(|x| x * rng.range(0.0, 0.3));
        let pose = Isometry::try_new(place_rotation, Vec3::from_array(offset)).expect("pose");
        let (shape, solid) = if q % 2 == 0 {
            (Convex::try_capsule(0.3, 0.1), Solid::capsule(0.3, 0.1))
        } else {
            (Convex::try_ball(0.15), Solid::ball(0.15))
        };
        let shape = shape.expect("shape").try_placed(pose).expect("placed");
        let solid = solid.placed(&pose);
        let spin = rng.direction().map(|x| x * rng.range(0.0, 6.0));
        let a = RigidMotion::try_from_start(
            Isometry::try_new(start_rotation, Vec3::ZERO).expect("start"),
            Vec3::ZERO,
            Vec3::from_array(spin),
            1.0,
        )
        .expect("motion");
        let from = rng.direction().map(|x| x * 1.5);
        let b = RigidMotion::try_from_arrays(from, from.map(|x| -x), [0.0; 3]).expect("motion");
        let ball = Convex::try_ball(0.3).expect("ball");
        let mut pair = AnyPair::try_new(Shape::Convex(shape), Shape::Convex(ball)).expect("pair");
        let report = time_of_impact(&mut pair, &a, &b, &params).expect("query");
        if let CaOutcome::Contact {
            contact,
            criterion: ContactCriterion::Distance,
        } = report.outcome
        {
            by_distance += 1;
            // Grown by the contact distance (and a hair for the samples'
            // own rounding), the bodies touch at the reported time.
            let grow = |mut s: Solid| {
                for (_, r) in &mut s.parts {
                    *r += params.contact_distance * (1.0 + 1e-9) + 1e-12;
                }
                s
            };
            assert!(
                shape_truth::touch_at(&grow(solid), &a, &Solid::ball(0.3), &b, contact.time),
                "query {q}: contact declared at {} beyond the contact distance",
                contact.time
            );
        }
    }
    assert!(
        by_distance > 150,
        "{by_distance} of 200 contacts by distance"
    );
}
