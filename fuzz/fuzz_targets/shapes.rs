//! Every pair of shape kinds end to end: two bodies each of a fuzzed kind
//! (ball, capsule, cuboid, cylinder, cone, each possibly rounded and placed
//! at a fuzzed local pose; a mesh of one to three triangles; a compound of
//! two such parts; or, for the second body, a translating ground
//! half-space) on fuzzed motions, through `AnyPair` and `time_of_impact`.
//!
//! * Building the shapes gives `Ok` (their parameters are in range by
//!   construction) and the query never panics and returns `Ok`.
//! * Under the default parameters a query takes at most ten times the
//!   default work budget's time bound (`TIME_BOUND_MS`), fast spins
//!   (up to 300 rad per unit time) included.
//! * The reported first possible contact is never later than the first of
//!   33 sampled times at which the bodies touch, and `Separated` is never
//!   reported when sampling finds a contact (the ground truth of
//!   `tests/common/shape_truth.rs`: each part's core tessellated inside
//!   itself, the testkit's own placement, exact triangle distances).
//!
//! The input is raw bytes read as bounded numbers (missing bytes read as
//! zero).

#![no_main]

#[path = "../../tests/common/shape_truth.rs"]
mod shape_truth;

use libfuzzer_sys::fuzz_target;
use motion_bound::ca::{time_of_impact, AnyPair, CaParams, Compound, Part, Shape};
use motion_bound::{BallTree, Convex, HalfSpace, Isometry, RigidMotion, Rotation, Vec3};
use motion_bound_fuzz::Bytes;
use shape_truth::{first_sampled_contact, first_sampled_landing, Solid};

/// A query's time bound: ten times the default work budget's 50 ms.
const TIME_BOUND_MS: u128 = 500;

/// Ground-truth samples over `[0, 1]` (33 times).
const SAMPLES: usize = 32;

fn vector(b: &mut Bytes<'_>, half: f64) -> [f64; 3] {
    [
        b.range(-half, half),
        b.range(-half, half),
        b.range(-half, half),
    ]
}

/// A convex part and its ground truth, possibly rounded and placed.
fn convex(b: &mut Bytes<'_>) -> (Convex<'static, f64>, Solid) {
    let (h, r) = (b.range(0.05, 0.5), b.range(0.02, 0.4));
    let (shape, solid) = match b.u8() % 5 {
        0 => (Convex::try_ball(r), Solid::ball(r)),
        1 => (Convex::try_capsule(h, r), Solid::capsule(h, r)),
        2 => {
            let half = [b.range(0.02, 0.5), b.range(0.0, 0.5), b.range(0.02, 0.5)];
            (Convex::try_cuboid(half), Solid::cuboid(half, 0.0))
        }
        3 => (Convex::try_cylinder(h, r), Solid::cylinder(h, r)),
        _ => (Convex::try_cone(h, r), Solid::cone(h, r)),
    };
    let mut shape = shape.expect("parameters in range");
    let mut solid = solid;
    if b.u8().is_multiple_of(3) {
        let extra = b.range(0.0, 0.2);
        shape = shape.try_rounded(extra).expect("a radius in range");
        for part in &mut solid.parts {
            part.1 += extra;
        }
    }
    if b.u8().is_multiple_of(2) {
        let q = [0; 4].map(|_| b.range(-1.0, 1.0));
        let t = vector(b, 0.5);
        if let Ok(rot) = Rotation::try_from_quaternion(q[0], q[1], q[2], q[3]) {
            let pose = Isometry::try_new(rot, Vec3::from_array(t)).expect("a pose");
            shape = shape.try_placed(pose).expect("placed once");
            solid = solid.placed(&pose);
        }
    }
    (shape, solid)
}

/// A small mesh (one to three triangles in `[-0.6, 0.6]^3`) with its tree.
fn mesh(b: &mut Bytes<'_>) -> (BallTree<f64>, Solid) {
    let count = 1 + usize::from(b.u8() % 3);
    let vertices: Vec<[f64; 3]> = (0..3 * count).map(|_| vector(b, 0.6)).collect();
    let triangles: Vec<[u32; 3]> = (0..count as u32)
        .map(|k| [3 * k, 3 * k + 1, 3 * k + 2])
        .collect();
    let tree = BallTree::try_new(&vertices, &triangles).expect("finite vertices give a tree");
    let solid = Solid {
        parts: vec![(
            triangles
                .iter()
                .map(|t| t.map(|i| vertices[i as usize]))
                .collect(),
            0.0,
        )],
    };
    (tree, solid)
}

/// A body as built: what its shape borrows.
enum Built {
    Mesh(BallTree<f64>),
    Compound(Compound<'static, f64>),
    Convex(Convex<'static, f64>),
    Ground(HalfSpace<f64>),
}

impl Built {
    fn shape(&self) -> Shape<'_, f64> {
        match self {
            Built::Mesh(t) => Shape::Mesh(t),
            Built::Compound(c) => Shape::Compound(c),
            Built::Convex(c) => Shape::Convex(*c),
            Built::Ground(h) => Shape::HalfSpace(*h),
        }
    }
}

/// A body of a fuzzed kind (a ground only when `ground` allows it).
fn body(b: &mut Bytes<'_>, ground: bool) -> (Built, Solid) {
    match b.u8() % 4 {
        0 => {
            let (t, s) = mesh(b);
            (Built::Mesh(t), s)
        }
        1 => {
            let (p, sp) = convex(b);
            let (q, sq) = convex(b);
            let c = Compound::try_new(vec![Part::Convex(p), Part::Convex(q)]).expect("two parts");
            (Built::Compound(c), Solid::union(vec![sp, sq]))
        }
        2 if ground => (
            Built::Ground(HalfSpace::try_new(Vec3::new(0.0, 1.0, 0.0)).expect("ground")),
            Solid::default(),
        ),
        _ => {
            let (c, s) = convex(b);
            (Built::Convex(c), s)
        }
    }
}

fn run(data: &[u8]) {
    let mut b = Bytes::new(data);
    let (ba, ta) = body(&mut b, false);
    let (bb, tb) = body(&mut b, true);
    let (sa, sb) = (ba.shape(), bb.shape());
    let is_ground = matches!(sb, Shape::HalfSpace(_));
    // Still, turning a few times, or fast (up to about 50 turns: Lemma 9.8).
    let spin = |b: &mut Bytes<'_>| match b.u8() % 8 {
        0 | 1 => [0.0; 3],
        2 => vector(b, 300.0),
        _ => vector(b, 12.0),
    };
    let ma = RigidMotion::try_from_arrays(vector(&mut b, 2.0), vector(&mut b, 4.0), spin(&mut b))
        .expect("bounded motion");
    let mb = if is_ground {
        RigidMotion::try_from_arrays([0.0, -1.0, 0.0], [0.0, b.range(-1.0, 1.0), 0.0], [0.0; 3])
    } else {
        RigidMotion::try_from_arrays(vector(&mut b, 1.0), vector(&mut b, 2.0), spin(&mut b))
    }
    .expect("bounded motion");
    let contact = [1e-3, 1e-6, 1e-2][usize::from(b.u8() % 3)];
    let params = CaParams::default().with_contact_distance(contact);
    let mut pair = AnyPair::try_new(sa, sb).expect("never two half-spaces");
    let start = std::time::Instant::now();
    let report = time_of_impact(&mut pair, &ma, &mb, &params).expect("a valid query");
    // The default work budget bounds a query's time (about 50 ms,
    // `CaParams::DEFAULT_WORK_BUDGET`); ten times that under the fuzzer's
    // instrumentation.
    let elapsed = start.elapsed();
    assert!(
        elapsed.as_millis() <= TIME_BOUND_MS,
        "SLOW: {elapsed:?} for {report:?}"
    );
    let truth = if is_ground {
        first_sampled_landing(&ta, &ma, &mb, [0.0, 1.0, 0.0], (0.0, 1.0), SAMPLES)
    } else {
        first_sampled_contact(&ta, &ma, &tb, &mb, (0.0, 1.0), SAMPLES)
    };
    if let Some(g) = truth {
        match report.outcome.earliest_possible_contact() {
            None => panic!("MISSED: Separated, but the bodies touch at t = {g} ({report:?})"),
            Some(t) => assert!(
                t <= g,
                "LATE: first possible contact {t} after a contact at t = {g} ({report:?})"
            ),
        }
    }
}

fuzz_target!(|data: &[u8]| run(data));
