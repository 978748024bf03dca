//! A tour of motion-bound: the NEVQ and EVQ directed motion bounds, then
//! conservative-advancement time of impact on built-in scenes.
//!
//! Run with `cargo run --release --example demo`. It opens with one time of
//! impact told in words (a turned torus knot flying at a ring). Part 1: for a few built-in
//! bodies and motions it prints the two speed bounds next to the exact
//! supremum of the directed speed and the exact directed displacement (from
//! the closed-form `reference` oracle, evaluated in `f64`), how loose each
//! bound is, and how long each evaluation takes. Part 2: first contact of
//! moving meshes (torus knots, rings, a thin spinning board, the Stanford
//! bunny) by conservative advancement with each bound, checked against a
//! sampled exact-intersection ground truth.

use std::hint::black_box;
use std::time::{Duration, Instant};

#[path = "../tests/common/meshes.rs"]
mod meshes;

use motion_bound::bodies::{board, torus, TorusKnotSize};
use motion_bound::ca::{time_of_impact, BoundChoice, CaParams, MeshPair};
use motion_bound::reference::{exact, Exact};
use motion_bound::testkit::ground_truth::{first_sampled_contact, MeshRef};
use motion_bound::testkit::toi::{fly_by, random_rotation, reach, rotate_mesh, Rng};
use motion_bound::testkit::{random_blob, SplitMix64};
use motion_bound::{evq, nevq, Direction, RigidMotion, VertexSet};
use motion_bound::{BallTree, Isometry, Rotation, TriMesh, Vec3};

/// A named body: vertices relative to the rotation centre.
struct Body {
    name: &'static str,
    vertices: Vec<[f64; 3]>,
}

/// A named motion over `[0, 1]` with the direction it is measured along.
struct Motion {
    name: &'static str,
    motion: RigidMotion<f64>,
    n: Direction<f64>,
}

/// The corners of the box `[-hx, hx] x [-hy, hy] x [-hz, hz]`.
fn box_corners(hx: f64, hy: f64, hz: f64) -> Vec<[f64; 3]> {
    (0..8)
        .map(|i| {
            let s = |bit: u32, h: f64| if i >> bit & 1 == 1 { h } else { -h };
            [s(0, hx), s(1, hy), s(2, hz)]
        })
        .collect()
}

fn bodies() -> Vec<Body> {
    let mut rng = SplitMix64(2006);
    vec![
        Body {
            name: "unit cube (8)",
            vertices: box_corners(0.5, 0.5, 0.5),
        },
        Body {
            name: "random blob (1000)",
            vertices: random_blob(&mut rng, 1000),
        },
        Body {
            name: "thin rod 10x0.1 (8)",
            vertices: box_corners(5.0, 0.05, 0.05),
        },
    ]
}

fn motions() -> Vec<Motion> {
    let m = |v: [f64; 3], w: [f64; 3]| {
        RigidMotion::try_from_arrays([0.0; 3], v, w).expect("built-in motion is valid")
    };
    let d = |n: [f64; 3]| Direction::try_from_array(n).expect("built-in direction is nonzero");
    vec![
        Motion {
            name: "slow spin",
            motion: m([0.5, 0.0, 0.0], [0.0, 0.0, 0.2]),
            n: d([1.0, 1.0, 0.0]),
        },
        Motion {
            name: "fast spin (>pi)",
            motion: m([0.5, 0.0, 0.0], [0.3, 0.4, 5.0]),
            n: d([1.0, 1.0, 0.0]),
        },
        Motion {
            name: "translation only",
            motion: m([1.0, 2.0, 0.5], [0.0; 3]),
            n: d([1.0, 1.0, 0.0]),
        },
        Motion {
            name: "n nearly || w",
            motion: m([0.1, 0.0, 0.0], [0.0, 0.0, 2.0]),
            n: d([1e-3, 0.0, 1.0]),
        },
    ]
}

/// Mean nanoseconds per call of `f`, doubling the repetitions until one run
/// of them takes at least 20 ms.
fn ns_per_call<R>(mut f: impl FnMut() -> R) -> f64 {
    let mut reps: u32 = 1;
    loop {
        let start = Instant::now();
        for _ in 0..reps {
            black_box(f());
        }
        let elapsed = start.elapsed();
        if elapsed >= Duration::from_millis(20) || reps >= 1 << 30 {
            return elapsed.as_secs_f64() * 1e9 / f64::from(reps);
        }
        reps *= 2;
    }
}

/// `bound / exact`, or a dash when the exact value is zero.
fn ratio(bound: f64, exact: f64) -> String {
    if exact > 0.0 {
        format!("{:.4}", bound / exact)
    } else {
        "-".to_owned()
    }
}

/// One query, told in words: a torus knot, turned at the start and
/// spinning, flies at a still ring; when and where do they first touch?
fn one_query() {
    let knot = TorusKnotSize::K2_8.mesh::<f64>().expect("built-in scene");
    let ring = torus::<f64>(0.5, 0.1, 48, 12).expect("built-in scene");
    // One tree per body, built once in the body's own frame.
    let (tk, tr) = (
        BallTree::try_from_mesh(&knot).expect("valid mesh"),
        BallTree::try_from_mesh(&ring).expect("valid mesh"),
    );
    let turn = Rotation::try_from_axis_angle(Vec3::new(0.0, 0.0, 1.0), 0.5).expect("valid");
    let start = Isometry::try_new(turn, Vec3::new(-1.6, 0.2, 0.0)).expect("valid");
    let a = RigidMotion::try_from_start(
        start,
        Vec3::new(2.0, -0.3, 0.0),
        Vec3::new(0.0, 1.5, 0.0),
        1.0,
    )
    .expect("valid motion");
    let b = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0; 3]).expect("still");
    let params = CaParams::default().with_contact_distance(1e-3);
    let report = time_of_impact(&mut MeshPair::new(&tk, &tr), &a, &b, &params).expect("valid");
    println!(
        "One query. Body A: a trefoil torus knot ({} triangles, reach {:.2}), starting at",
        knot.triangle_count(),
        reach(&knot)
    );
    println!("(-1.6, 0.2, 0) turned 0.5 rad about z, moving at (2, -0.3, 0) per unit time and");
    println!(
        "spinning at 1.5 rad per unit time about y. Body B: a ring of radius 0.5 ({} triangles),",
        ring.triangle_count()
    );
    println!("still at the origin. Over t in [0, 1], with contact distance 1e-3:");
    match report.outcome.contact() {
        Some(c) => {
            let fmt =
                |p: motion_bound::Point3<f64>| format!("({:.4}, {:.4}, {:.4})", p.x, p.y, p.z);
            print!(
                "they touch at t = {:.6} (after {} conservative-advancement steps)",
                c.time, report.iterations
            );
            if let Some(w) = c.witness {
                print!(
                    ", A at {} and B at {}, {:.2e} apart",
                    fmt(w.on_a),
                    fmt(w.on_b),
                    w.distance
                );
            }
            if let Some(n) = c.normal {
                let n = n.get();
                print!(", normal from A to B ({:.3}, {:.3}, {:.3})", n.x, n.y, n.z);
            }
            println!(".");
            println!("No contact happens before that time: every step was certified contact-free.");
        }
        None => println!("they do not touch ({:?}).", report.outcome),
    }
    println!();
}

fn main() {
    println!("motion-bound demo: directed motion bounds for conservative advancement (f64)");
    println!();
    one_query();
    println!("Each motion runs over t in [0, 1] with linear velocity v and angular velocity w");
    println!("about the body's centre; n is the closest direction of a CA step.");
    println!("  NEVQ, EVQ   upper bounds of the directed speed sup_t max_i |p_i'(t).n|");
    println!("  exact sup   that supremum, from the closed-form reference oracle");
    println!("  exact disp  the exact directed displacement max_i integral |p_i'(t).n| dt");
    println!("  /exact      bound divided by the exact sup (1.0000 is perfectly tight)");
    println!("  ns ...      mean time per call (many repetitions, std::time::Instant)");
    println!();
    println!(
        "{:<20} {:<17} {:>9} {:>9} {:>9} {:>10} {:>10} {:>10} {:>8} {:>8} {:>9}",
        "body",
        "motion",
        "NEVQ",
        "EVQ",
        "exact sup",
        "exact disp",
        "NEVQ/exact",
        "EVQ/exact",
        "ns NEVQ",
        "ns EVQ",
        "ns exact"
    );
    println!("{}", "-".repeat(20 + 17 + 9 * 3 + 10 * 3 + 8 * 2 + 9 + 10));
    for body in bodies() {
        let set = VertexSet::try_new(&body.vertices).expect("built-in body is valid");
        let summary = set.summary();
        for m in motions() {
            let (motion, n) = (m.motion, m.n);
            let loose = nevq(&summary, &motion, n);
            let tight = evq(&set, &motion, n);
            let ex: Exact<f64> = exact::<f64, f64>(&body.vertices, &motion, n);
            assert!(
                loose.speed >= ex.sup_speed && tight.speed >= ex.sup_speed,
                "a bound is below the exact value"
            );
            let t_nevq =
                ns_per_call(|| nevq(black_box(&summary), black_box(&motion), black_box(n)));
            let t_evq = ns_per_call(|| evq(black_box(&set), black_box(&motion), black_box(n)));
            let t_exact = ns_per_call(|| {
                exact::<f64, f64>(black_box(&body.vertices), black_box(&motion), black_box(n))
            });
            println!(
                "{:<20} {:<17} {:>9.4} {:>9.4} {:>9.4} {:>10.4} {:>10} {:>10} {:>8.1} {:>8.1} {:>9.1}",
                body.name,
                m.name,
                loose.speed,
                tight.speed,
                ex.sup_speed,
                ex.displacement,
                ratio(loose.speed, ex.sup_speed),
                ratio(tight.speed, ex.sup_speed),
                t_nevq,
                t_evq,
                t_exact
            );
        }
    }
    println!();
    println!("NEVQ costs O(1) per query from a summary computed once; EVQ scans the vertices");
    println!("(O(N)) and is never looser than NEVQ. Both bound the speed at every time, so a");
    println!("conservative-advancement step may advance by gap / bound.");
    println!();
    time_of_impact_tour();
}

/// Part 2: conservative advancement on built-in scenes.
fn time_of_impact_tour() {
    println!("Time of impact by conservative advancement (f64): body A flies at body B over");
    println!("t in [0, 1], both spinning; contact distance 1e-3 of the bodies' size. Per scene,");
    println!("queries are checked against the first of 256 sampled times at which the meshes");
    println!("intersect (exact predicates): 'late' and 'missed' must be 0.");
    println!();
    let knot = TorusKnotSize::K2_8.mesh::<f64>().expect("built-in scene");
    let ring = torus::<f64>(0.5, 0.08, 48, 12).expect("built-in scene");
    let plank = board::<f64>(1.0, 0.4, 0.005).expect("built-in scene");
    let bunny = meshes::try_load_shipped("bunny-npm-3674.obj.gz")
        .ok()
        .map(|m| {
            // Recentre on the bounding-sphere centre and scale to unit size.
            let (c, r) = m.bounding_sphere();
            m.recentred(c)
                .and_then(|m| m.scaled(0.5 / r))
                .expect("valid bunny")
        });
    let mut scenes: Vec<(&str, &TriMesh<f64>, &TriMesh<f64>, f64)> = vec![
        ("knot vs knot (2.8K)", &knot, &knot, 2.0),
        ("ring vs ring", &ring, &ring, 2.0),
        ("spinning board vs knot", &plank, &knot, 30.0),
    ];
    if let Some(b) = &bunny {
        scenes.push(("bunny vs bunny (3.7K)", b, b, 2.0));
    } else {
        println!("(data/bunny-npm-3674.obj.gz not found: bunny scene skipped)");
    }
    println!(
        "{:<24} {:>6} {:>10} {:>10} {:>8} {:>8} {:>9} {:>5} {:>7}",
        "scene", "tris", "ms NEVQ", "ms EVQ", "it NEVQ", "it EVQ", "contacts", "late", "missed"
    );
    for (name, a, b, spin) in scenes {
        let mut rng = Rng::new(2007);
        let ma = rotate_mesh(a, &random_rotation(&mut rng));
        let mb = rotate_mesh(b, &random_rotation(&mut rng));
        let (ta, tb) = (
            BallTree::try_from_mesh(&ma).expect("valid mesh"),
            BallTree::try_from_mesh(&mb).expect("valid mesh"),
        );
        let (ra, rb) = (reach(&ma), reach(&mb));
        let queries: Vec<_> = (0..20).map(|_| fly_by(&mut rng, ra, rb, spin)).collect();
        let mut row = Vec::new();
        let (mut contacts, mut late, mut missed) = (0, 0, 0);
        for bound in [BoundChoice::Nevq, BoundChoice::Evq] {
            let params = CaParams::default()
                .with_contact_distance(1e-3 * (ra + rb))
                .with_bound(bound);
            let (mut secs, mut iters) = (0.0, 0u32);
            for q in &queries {
                let start = Instant::now();
                let report = time_of_impact(&mut MeshPair::new(&ta, &tb), &q.a, &q.b, &params)
                    .expect("valid query");
                secs += start.elapsed().as_secs_f64();
                iters += report.iterations;
                if bound == BoundChoice::Evq {
                    let reported = report.outcome.earliest_possible_contact();
                    let (ga, gb) = (MeshRef::from(&ma), MeshRef::from(&mb));
                    let truth = first_sampled_contact(ga, &q.a, gb, &q.b, (0.0, 1.0), 256);
                    contacts += usize::from(report.outcome.contact().is_some());
                    match (reported, truth) {
                        (None, Some(_)) => missed += 1,
                        (Some(t), Some(g)) if g < t => late += 1,
                        _ => {}
                    }
                }
            }
            let n = queries.len() as f64;
            row.push((secs * 1e3 / n, f64::from(iters) / n));
        }
        println!(
            "{:<24} {:>6} {:>10.3} {:>10.3} {:>8.2} {:>8.2} {:>9} {:>5} {:>7}",
            name,
            a.triangle_count(),
            row[0].0,
            row[1].0,
            row[0].1,
            row[1].1,
            format!("{contacts}/{}", queries.len()),
            late,
            missed
        );
    }
    println!();
    println!("Times are wall-clock means per query on this machine (Instant; a report, not a");
    println!("benchmark: see `cargo bench -p motion-bound-compare --bench toi`, and the seed's");
    println!(
        "Table 1 beside parry3d with `cargo run --release -p motion-bound-compare --bin table1`)."
    );
}
