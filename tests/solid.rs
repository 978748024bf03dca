//! Solid meshes (`TriMesh::try_solid`, `proofs/09-ca-toi.md`, Lemma 9.7): a
//! body that starts inside a solid mesh is in contact with it, whatever its
//! kind and on every path (`AnyPair` both ways round, a compound's part, a
//! scene); declared hollow, the same body inside is separated; a mesh with a
//! hole or wound inward is refused; the exact inside test agrees with
//! independent truths (the analytic box on points chosen to put the ray
//! through edges and corners; a floating-point ray count of its own on the
//! bunny, at points far from its surface, also through placed, rotated
//! queries); and a body that starts outside gets the very outcome it had
//! with the mesh hollow.

#[path = "common/meshes.rs"]
mod meshes;

use motion_bound::bodies::cuboid;
use motion_bound::ca::{
    time_of_impact, AnyPair, CaOutcome, CaParams, CaReport, Compound, Part, Shape,
};
use motion_bound::scene::{Scene, SceneParams, SceneWorkspace};
use motion_bound::testkit::toi::Rng;
use motion_bound::{
    BallTree, BoundingBall, Convex, Float, Isometry, MeshError, RigidMotion, Rotation, TriMesh,
    Vec3, VertexSet,
};

type M = RigidMotion<f64>;

fn motion(x: [f64; 3], v: [f64; 3], w: [f64; 3]) -> M {
    RigidMotion::try_from_arrays(x, v, w).expect("finite")
}

fn query<T: Float>(
    a: Shape<'_, T>,
    b: Shape<'_, T>,
    ma: &RigidMotion<T>,
    mb: &RigidMotion<T>,
) -> CaReport<T> {
    let mut pair = AnyPair::try_new(a, b).expect("a supported pair");
    time_of_impact(&mut pair, ma, mb, &CaParams::default()).expect("a valid query")
}

/// The bunny of `data/`, about its centre of mass, scaled to a reach of
/// `reach` (declared hollow).
fn bunny(reach: f64) -> TriMesh<f64> {
    let m = meshes::load_shipped("bunny-npm-3674.obj.gz");
    let m = m
        .recentred(m.volume_centroid().expect("closed"))
        .expect("finite");
    let r = m
        .vertices()
        .iter()
        .map(|v| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt())
        .fold(0.0, f64::max);
    m.scaled(reach / r).expect("finite")
}

/// `a - b`, `a . b`, `a x b` in `f64`: the test's own geometry, independent
/// of the crate's.
fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The distance from `p` to triangle `t` (Ericson's closest point by
/// Voronoi regions, in `f64`).
fn point_triangle_distance(p: [f64; 3], t: &[[f64; 3]; 3]) -> f64 {
    let [a, b, c] = *t;
    let (ab, ac, ap) = (sub(b, a), sub(c, a), sub(p, a));
    let closest = (|| {
        let (d1, d2) = (dot(ab, ap), dot(ac, ap));
        if d1 <= 0.0 && d2 <= 0.0 {
            return a;
        }
        let bp = sub(p, b);
        let (d3, d4) = (dot(ab, bp), dot(ac, bp));
        if d3 >= 0.0 && d4 <= d3 {
            return b;
        }
        let vc = d1 * d4 - d3 * d2;
        if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
            let v = d1 / (d1 - d3);
            return [a[0] + v * ab[0], a[1] + v * ab[1], a[2] + v * ab[2]];
        }
        let cp = sub(p, c);
        let (d5, d6) = (dot(ab, cp), dot(ac, cp));
        if d6 >= 0.0 && d5 <= d6 {
            return c;
        }
        let vb = d5 * d2 - d1 * d6;
        if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
            let w = d2 / (d2 - d6);
            return [a[0] + w * ac[0], a[1] + w * ac[1], a[2] + w * ac[2]];
        }
        let va = d3 * d6 - d5 * d4;
        if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
            let w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
            let bc = sub(c, b);
            return [b[0] + w * bc[0], b[1] + w * bc[1], b[2] + w * bc[2]];
        }
        let denom = 1.0 / (va + vb + vc);
        let (v, w) = (vb * denom, vc * denom);
        [0, 1, 2].map(|k| a[k] + ab[k] * v + ac[k] * w)
    })();
    let d = sub(p, closest);
    dot(d, d).sqrt()
}

/// Whether `p` is inside the closed `mesh` by the parity of the crossings of
/// a ray from `p` in a random direction (Möller and Trumbore, in `f64`); a
/// ray passing within `1e-9` (barycentric) of an edge is redrawn. Only for
/// points well away from the surface.
fn inside_by_ray_parity(mesh: &TriMesh<f64>, p: [f64; 3], rng: &mut Rng) -> bool {
    'ray: loop {
        let d = rng.direction();
        let mut crossings = 0;
        for t in mesh.triangle_corners() {
            let (e1, e2) = (sub(t[1], t[0]), sub(t[2], t[0]));
            let h = cross(d, e2);
            let det = dot(e1, h);
            if det.abs() < 1e-14 {
                continue;
            }
            let s = sub(p, t[0]);
            let u = dot(s, h) / det;
            let q = cross(s, e1);
            let v = dot(d, q) / det;
            let along = dot(e2, q) / det;
            let near_edge = |x: f64| x.abs() < 1e-9;
            if near_edge(u) || near_edge(v) || near_edge(1.0 - u - v) {
                if u > -1e-9 && v > -1e-9 && u + v < 1.0 + 1e-9 && along > 0.0 {
                    continue 'ray;
                }
                continue;
            }
            if u > 0.0 && v > 0.0 && u + v < 1.0 && along > 0.0 {
                crossings += 1;
            }
        }
        return crossings % 2 == 1;
    }
}

/// The least distance from `p` to the mesh's triangles.
fn distance_to_surface(mesh: &TriMesh<f64>, p: [f64; 3]) -> f64 {
    mesh.triangle_corners()
        .map(|t| point_triangle_distance(p, &t))
        .fold(f64::INFINITY, f64::min)
}

/// A point inside the closed `mesh` at least `clearance` from its surface,
/// found among random points of its bounding box by the test's own ray
/// count.
fn deep_point(mesh: &TriMesh<f64>, clearance: f64, rng: &mut Rng) -> [f64; 3] {
    let (lo, hi) = mesh.aabb();
    for _ in 0..100_000 {
        let p = [0, 1, 2].map(|k| rng.range(lo[k], hi[k]));
        if inside_by_ray_parity(mesh, p, rng) && distance_to_surface(mesh, p) >= clearance {
            return p;
        }
    }
    panic!("no point {clearance} deep in the mesh");
}

fn is_initial_contact<T: Float>(o: &CaOutcome<T>) -> bool {
    matches!(o, CaOutcome::InitialContact(_))
}

#[test]
fn a_ball_a_box_and_the_bunny_inside_a_solid_mesh_start_in_contact() {
    let mut rng = Rng::new(38);
    let big_box = cuboid::<f64>([2.0, 2.0, 2.0]).unwrap();
    let big_bunny = bunny(1.0);
    let small_bunny = bunny(0.05);
    let small_bunny_tree = BallTree::try_from_mesh(&small_bunny).unwrap();
    let solid_small_bunny =
        BallTree::try_from_mesh(&small_bunny.clone().try_solid().unwrap()).unwrap();
    let ball = Convex::try_ball(0.04).unwrap();
    let little_box = Convex::try_cuboid([0.03, 0.02, 0.04]).unwrap();
    let tet = [
        [0.03, 0.03, 0.03],
        [0.03, -0.03, -0.03],
        [-0.03, 0.03, -0.03],
        [-0.03, -0.03, 0.03],
    ];
    let set = VertexSet::try_new(&tet).unwrap();
    let sphere = BoundingBall::try_new([0.01, 0.0, -0.01], 0.03).unwrap();
    let at = Isometry::try_from_translation(Vec3::new(0.01, 0.0, 0.0)).unwrap();
    let compound = Compound::try_new(vec![
        Part::Convex(Convex::try_ball(0.02).unwrap().try_placed(at).unwrap()),
        Part::Mesh(&small_bunny_tree),
    ])
    .unwrap();
    let inner: [(&str, Shape<'_, f64>); 7] = [
        ("ball", Shape::Convex(ball)),
        ("box", Shape::Convex(little_box)),
        ("vertex set", Shape::VertexSet(set)),
        ("sphere", Shape::Ball(sphere)),
        ("bunny", Shape::Mesh(&small_bunny_tree)),
        ("solid bunny", Shape::Mesh(&solid_small_bunny)),
        ("compound", Shape::Compound(&compound)),
    ];
    for (name, container, centre) in [
        ("box", &big_box, [0.3, -0.2, 0.1]),
        ("bunny", &big_bunny, deep_point(&big_bunny, 0.25, &mut rng)),
    ] {
        let solid = BallTree::try_from_mesh(&container.clone().try_solid().unwrap()).unwrap();
        let hollow = BallTree::try_from_mesh(container).unwrap();
        assert!(
            solid.is_solid() && !hollow.is_solid(),
            "{name}: the tree knows"
        );
        // The container turns about its centre of mass by 0.1 rad; the inner
        // body drifts by 0.05 and spins: together they move by less than
        // 0.2, and every inner body is within 0.05 of its centre, 0.25 from
        // every wall.
        let mc = motion([0.0; 3], [0.0; 3], [0.0, 0.0, 0.1]);
        let mi = motion(centre, [0.05, 0.0, 0.0], [1.0, 2.0, 3.0]);
        for (inner_name, shape) in inner {
            for (outer, expect_contact) in [(&solid, true), (&hollow, false)] {
                let o = Shape::Mesh(outer);
                let ab = query(o, shape, &mc, &mi).outcome;
                let ba = query(shape, o, &mi, &mc).outcome;
                for (order, outcome) in [("container first", ab), ("container second", ba)] {
                    if expect_contact {
                        assert!(
                            is_initial_contact(&outcome),
                            "{inner_name} in the solid {name}, {order}: {outcome:?}"
                        );
                        let c = outcome.contact().unwrap();
                        assert_eq!(c.time, 0.0, "at the start");
                        let w = c.witness.expect("the point found inside");
                        assert_eq!((w.distance, w.on_a), (0.0, w.on_b), "one point");
                    } else {
                        assert_eq!(
                            outcome,
                            CaOutcome::Separated,
                            "{inner_name} in the hollow {name}, {order}"
                        );
                    }
                }
            }
        }
        // A solid body holding a hollow one touches nothing: the bunny
        // inside the hollow container is not the container inside the bunny.
        let o = query(
            Shape::Mesh(&hollow),
            Shape::Mesh(&solid_small_bunny),
            &mc,
            &mi,
        );
        assert_eq!(
            o.outcome,
            CaOutcome::Separated,
            "{name}: solid inside hollow"
        );
    }
    // In f32 too.
    let box32 =
        BallTree::try_from_mesh(&cuboid::<f32>([2.0; 3]).unwrap().try_solid().unwrap()).unwrap();
    let still = RigidMotion::<f32>::try_from_arrays([0.0; 3], [0.0; 3], [0.0; 3]).unwrap();
    let moving =
        RigidMotion::<f32>::try_from_arrays([0.2, 0.0, 0.0], [0.1, 0.0, 0.0], [0.0, 3.0, 0.0])
            .unwrap();
    let o = query(
        Shape::Mesh(&box32),
        Shape::Convex(Convex::try_ball(0.1f32).unwrap()),
        &still,
        &moving,
    );
    assert!(is_initial_contact(&o.outcome), "f32: {:?}", o.outcome);
}

#[test]
fn a_scene_reports_the_body_inside_a_solid_mesh() {
    let container = cuboid::<f64>([2.0, 2.0, 2.0]).unwrap();
    let solid = BallTree::try_from_mesh(&container.clone().try_solid().unwrap()).unwrap();
    let hollow = BallTree::try_from_mesh(&container).unwrap();
    let ball = Shape::Convex(Convex::try_ball(0.1).unwrap());
    for (tree, inside_pair_contact) in [(&solid, true), (&hollow, false)] {
        let mut scene = Scene::try_new(motion_bound::TimeInterval::UNIT).unwrap();
        let c = scene
            .try_add_static(Shape::Mesh(tree), Isometry::IDENTITY)
            .unwrap();
        let inside = scene
            .try_add(ball, motion([0.1, 0.2, 0.0], [0.3, 0.0, 0.0], [0.0; 3]))
            .unwrap();
        let outside = scene
            .try_add(ball, motion([3.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0; 3]))
            .unwrap();
        let mut ws = SceneWorkspace::new();
        let report = scene.query(&mut ws, &SceneParams::default()).unwrap();
        let outcome = |b: usize| {
            report
                .pairs()
                .iter()
                .find(|p| (p.a, p.b) == (c.min(b), c.max(b)))
                .map(|p| p.report.outcome)
        };
        let o = outcome(inside).expect("the boxes overlap: the pair is kept");
        assert_eq!(is_initial_contact(&o), inside_pair_contact, "inside: {o:?}");
        if !inside_pair_contact {
            assert_eq!(o, CaOutcome::Separated, "hollow");
        }
        assert!(
            outcome(outside).is_none_or(|o| o == CaOutcome::Separated),
            "the ball outside"
        );
    }
}

#[test]
fn a_mesh_with_a_hole_or_wound_inward_is_refused_as_solid() {
    let b = cuboid::<f64>([2.0, 2.0, 2.0]).unwrap();
    let (v, mut t) = b.clone().into_parts();
    t.pop();
    let holed = TriMesh::try_new(v.clone(), t).unwrap();
    assert_eq!(
        holed.try_solid(),
        Err(MeshError::NotClosed {
            unpaired: 3,
            repeated: 0,
            degenerate_triangles: 0
        }),
        "one triangle missing"
    );
    let e = TriMesh::try_new(v.clone(), b.triangles()[..10].to_vec())
        .unwrap()
        .try_solid()
        .unwrap_err();
    assert!(e.to_string().contains("not closed"), "{e}");
    let inward: Vec<[u32; 3]> = b.triangles().iter().map(|&[a, b, c]| [a, c, b]).collect();
    assert_eq!(
        TriMesh::try_new(v, inward).unwrap().try_solid(),
        Err(MeshError::InsideOut),
        "wound inward"
    );
    let bunny = bunny(1.0);
    let (v, mut t) = bunny.into_parts();
    t.swap_remove(100);
    assert!(
        matches!(
            TriMesh::try_new(v, t).unwrap().try_solid(),
            Err(MeshError::NotClosed { unpaired: 3, .. })
        ),
        "the bunny with a hole"
    );
}

#[test]
fn the_inside_test_agrees_with_the_analytic_box() {
    let mut rng = Rng::new(7);
    let b = cuboid::<f64>([2.0, 2.0, 2.0]).unwrap().try_solid().unwrap();
    // Coordinates on the box's planes and through its edges and corners put
    // the ray along edges, through corners and across face diagonals.
    let grid = [-1.5, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5];
    let mut checked = 0;
    for i in 0..20_000 {
        let p = if i % 2 == 0 {
            [0, 1, 2].map(|_| grid[(rng.next_u64() % 7) as usize])
        } else {
            [0, 1, 2].map(|_| rng.range(-1.5, 1.5))
        };
        let inside = p.iter().all(|x| x.abs() < 1.0);
        let outside = p.iter().any(|x| x.abs() > 1.0);
        let w = b.winding_number(p);
        if inside {
            assert_eq!(w, Some(1), "inside at {p:?}");
        } else if outside {
            assert_eq!(w, Some(0), "outside at {p:?}");
        } else {
            // On the surface: on it, or the point beside it.
            assert!(
                matches!(w, None | Some(0) | Some(1)),
                "surface at {p:?}: {w:?}"
            );
        }
        checked += usize::from(inside || outside);
    }
    assert!(checked > 15_000, "{checked} points off the surface");

    // Placed: a tiny ball at random points against the solid box turned and
    // moved, through the whole query.
    let tree = BallTree::try_from_mesh(&b).unwrap();
    let ball = Shape::Convex(Convex::try_ball(1e-6).unwrap());
    for _ in 0..400 {
        let q = [
            rng.signed_unit(),
            rng.signed_unit(),
            rng.signed_unit(),
            rng.signed_unit(),
        ];
        let turn = Rotation::try_from_quaternion(q[0], q[1], q[2], q[3]).unwrap();
        let x = [0, 1, 2].map(|_| rng.range(-3.0, 3.0));
        let p = [0, 1, 2].map(|_| rng.range(-1.4, 1.4));
        let depth = p
            .iter()
            .map(|c| 1.0 - c.abs())
            .fold(f64::INFINITY, f64::min);
        if depth.abs() < 1e-3 {
            continue;
        }
        let world = turn.rotate(Vec3::from_array(p)).to_array();
        let mc = motion(x, [0.0; 3], [0.0; 3]).with_orientation(turn);
        let mb = motion([0, 1, 2].map(|k| x[k] + world[k]), [0.0; 3], [0.0; 3]);
        let o = query(Shape::Mesh(&tree), ball, &mc, &mb).outcome;
        if depth > 0.0 {
            assert!(is_initial_contact(&o), "inside at {p:?}: {o:?}");
        } else {
            assert_eq!(o, CaOutcome::Separated, "outside at {p:?}");
        }
    }
}

#[test]
fn the_inside_test_agrees_with_an_independent_ray_count_on_the_bunny() {
    let mut rng = Rng::new(3674);
    let mesh = bunny(1.0).try_solid().unwrap();
    let tree = BallTree::try_from_mesh(&mesh).unwrap();
    let ball = Shape::Convex(Convex::try_ball(1e-6).unwrap());
    let (lo, hi) = mesh.aabb();
    let (mut inside, mut outside) = (0, 0);
    while inside < 150 || outside < 150 {
        let p = [0, 1, 2].map(|k| rng.range(lo[k] - 0.1, hi[k] + 0.1));
        if distance_to_surface(&mesh, p) < 1e-3 {
            continue;
        }
        let truth = inside_by_ray_parity(&mesh, p, &mut rng);
        let w = mesh.winding_number(p);
        assert_eq!(w, Some(i64::from(truth)), "winding number at {p:?}");
        // The same point through a placed query: the bunny turned and moved.
        let q = [
            rng.signed_unit(),
            rng.signed_unit(),
            rng.signed_unit(),
            rng.signed_unit(),
        ];
        let turn = Rotation::try_from_quaternion(q[0], q[1], q[2], q[3]).unwrap();
        let x = [0, 1, 2].map(|_| rng.range(-10.0, 10.0));
        let world = turn.rotate(Vec3::from_array(p)).to_array();
        let mc = motion(x, [0.0; 3], [0.0; 3]).with_orientation(turn);
        let mb = motion([0, 1, 2].map(|k| x[k] + world[k]), [0.0; 3], [0.0; 3]);
        let o = query(Shape::Mesh(&tree), ball, &mc, &mb).outcome;
        if truth {
            assert!(is_initial_contact(&o), "inside at {p:?}: {o:?}");
            inside += 1;
        } else {
            assert_eq!(o, CaOutcome::Separated, "outside at {p:?}");
            outside += 1;
        }
    }
    assert!(
        inside > 100 && outside > 100,
        "{inside} inside, {outside} outside"
    );
}

#[test]
fn bodies_starting_outside_get_the_outcome_they_had_hollow() {
    let mut rng = Rng::new(2026);
    let mesh = bunny(1.0);
    let solid = BallTree::try_from_mesh(&mesh.clone().try_solid().unwrap()).unwrap();
    let hollow = BallTree::try_from_mesh(&mesh).unwrap();
    let small = bunny(0.15);
    let small_tree = BallTree::try_from_mesh(&small).unwrap();
    let ball = Shape::Convex(Convex::try_ball(0.1).unwrap());
    let little_box = Shape::Convex(Convex::try_cuboid([0.1, 0.05, 0.08]).unwrap());
    let (lo, hi) = mesh.aabb();
    let (mut same, mut inside, mut contacts) = (0, 0, 0);
    for k in 0..240 {
        let shape = [ball, little_box, Shape::Mesh(&small_tree)][k % 3];
        // Starts anywhere in and around the bunny's box (one query in four
        // deep inside), moves up to 2 in any direction and spins.
        let start = if k % 4 == 0 {
            deep_point(&mesh, 0.2, &mut rng)
        } else {
            [0, 1, 2].map(|j| rng.range(lo[j] - 0.3, hi[j] + 0.3))
        };
        let v = rng.direction().map(|c| c * rng.range(0.0, 2.0));
        let w = rng.direction().map(|c| c * rng.range(0.0, 6.0));
        let mb = motion(start, v, w);
        let mc = motion([0.0; 3], [0.0; 3], rng.direction().map(|c| c * 0.5));
        let s = query(Shape::Mesh(&solid), shape, &mc, &mb);
        let h = query(Shape::Mesh(&hollow), shape, &mc, &mb);
        let starts_inside = inside_by_ray_parity(&mesh, start, &mut rng);
        let clear = distance_to_surface(&mesh, start) > 0.2;
        if starts_inside && clear {
            // Every body here reaches within 0.15 of its centre.
            assert!(
                is_initial_contact(&s.outcome),
                "inside at {start:?}: {:?}",
                s.outcome
            );
            inside += 1;
        } else if !starts_inside {
            assert_eq!(s.outcome, h.outcome, "outside at {start:?}");
            assert!(
                s.work.node_pairs >= h.work.node_pairs,
                "the check's work is counted"
            );
            same += 1;
            contacts += usize::from(h.outcome.contact().is_some());
        }
    }
    assert!(
        same > 80 && inside > 40 && contacts > 20,
        "{same} outside ({contacts} contacts), {inside} inside"
    );
}
