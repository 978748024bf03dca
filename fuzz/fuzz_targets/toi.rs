//! The time-of-impact engine end to end: two small triangle meshes (one to
//! four triangles each, any shape, degenerate ones included) on fuzzed
//! motions with rotation, through `MeshPair` and `time_of_impact` with fuzzed
//! parameters (bound, one-sided rates, horizon, far ratio, accept fraction,
//! contact distance).
//!
//! * Building the trees (with pieces of large triangles of several lengths,
//!   `proofs/09-ca-toi.md` Lemma 9.5) and running the query never panics, and the query
//!   (its parameters valid by construction) returns `Ok`.
//! * The reported first possible contact is never later than the first of
//!   128 sampled times at which the meshes intersect
//!   (`testkit::ground_truth::first_sampled_contact`: its own quaternion
//!   placement and exact orientation predicates), and `Separated` is never
//!   reported when sampling finds an intersection (`proofs/09-ca-toi.md`).
//! * A contact by time tolerance (a stall) is at least the tolerance before
//!   the interval's end (near the end short steps are no stall).
//!
//! The input is raw bytes read as bounded numbers (missing bytes read as
//! zero): vertices in `[-1, 1]^3`, centres within 3 of the origin, speeds up
//! to 6, angular speeds up to 20 rad per unit time, over `[0, 1]`; then, for
//! each body, a start orientation (a quaternion) and a rotation centre off
//! the body origin, or neither.

#![no_main]

use libfuzzer_sys::fuzz_target;
use motion_bound::ca::{
    time_of_impact, BoundChoice, CaOutcome, CaParams, ContactCriterion, MeshPair, MeshParams,
};
use motion_bound::testkit::ground_truth::{first_sampled_contact, MeshRef};
use motion_bound::{BallTree, RigidMotion, Rotation, Vec3};
use motion_bound_fuzz::Bytes;

/// Ground-truth samples over `[0, 1]`.
const SAMPLES: usize = 128;

/// One body: its triangles' corners (three vertices per triangle) and the
/// index triples.
fn body(b: &mut Bytes<'_>) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let count = 1 + usize::from(b.u8() % 4);
    let vertices: Vec<[f64; 3]> = (0..3 * count)
        .map(|_| [b.range(-1.0, 1.0), b.range(-1.0, 1.0), b.range(-1.0, 1.0)])
        .collect();
    let triangles = (0..count as u32)
        .map(|k| [3 * k, 3 * k + 1, 3 * k + 2])
        .collect();
    (vertices, triangles)
}

fn vector(b: &mut Bytes<'_>, half: f64) -> [f64; 3] {
    [
        b.range(-half, half),
        b.range(-half, half),
        b.range(-half, half),
    ]
}

fn run(data: &[u8]) {
    let mut b = Bytes::new(data);
    let (va, fa) = body(&mut b);
    let (vb, fb) = body(&mut b);
    // The trees: by the input's length (so that older inputs read the same
    // bytes), mostly with pieces of a fuzzed coarse length (cheap to build,
    // and every piece certified as the default's are), sometimes without
    // pieces, and one input in 32 with the default tree (its 16,384 pieces
    // take tens of ms to build with the tree).
    let tree = |v: &[[f64; 3]], f: &[[u32; 3]]| {
        let length = match data.len() % 32 {
            0 => None,
            k => Some([0.5, f64::INFINITY, 0.25, 0.125][k % 4] * 1.74),
        };
        match length {
            None => BallTree::try_new(v, f),
            Some(l) => BallTree::try_with_piece_length(v, f, l),
        }
        .expect("finite vertices in range give a tree")
    };
    let (ta, tb) = (tree(&va, &fa), tree(&vb, &fb));
    let spin = |b: &mut Bytes<'_>| {
        if b.u8().is_multiple_of(4) {
            [0.0; 3]
        } else {
            vector(b, 20.0)
        }
    };
    let ma = RigidMotion::try_from_arrays(vector(&mut b, 3.0), vector(&mut b, 6.0), spin(&mut b))
        .expect("bounded motion");
    let mb = RigidMotion::try_from_arrays(vector(&mut b, 1.0), vector(&mut b, 2.0), spin(&mut b))
        .expect("bounded motion");
    let bound = [BoundChoice::Evq, BoundChoice::Nevq, BoundChoice::Auto][usize::from(b.u8() % 3)];
    let contact = [1e-3, 1e-6, 1e-9, 1e-2][usize::from(b.u8() % 4)];
    let horizon = [2.0, 0.0, 1.5, 8.0][usize::from(b.u8() % 4)];
    let far = [6.0, 0.5, f64::INFINITY][usize::from(b.u8() % 3)];
    let accept = [1.0, 0.5][usize::from(b.u8() % 2)];
    let one_sided = b.u8().is_multiple_of(2);
    // A start orientation and a rotation centre off the body origin, read
    // last so that older inputs keep their meaning (identity, origin).
    let turned = |m: RigidMotion<f64>, b: &mut Bytes<'_>| match b.u8() % 3 {
        0 => m,
        k => {
            let q = [0; 4].map(|_| b.range(-1.0, 1.0));
            let m = match Rotation::try_from_quaternion(q[0], q[1], q[2], q[3]) {
                Ok(r) => m.with_orientation(r),
                Err(_) => m,
            };
            if k == 2 {
                m.try_with_local_centre(Vec3::from_array(vector(b, 1.0)))
                    .expect("a bounded centre")
            } else {
                m
            }
        }
    };
    let ma = turned(ma, &mut b);
    let mb = turned(mb, &mut b);
    let params = CaParams::default()
        .with_bound(bound)
        .with_contact_distance(contact)
        .with_horizon_factor(horizon)
        .with_one_sided(one_sided);
    let mut pair = MeshPair::new(&ta, &tb)
        .try_with_params(
            MeshParams::default()
                .with_far_ratio(far)
                .with_accept_fraction(accept),
        )
        .expect("knobs in range");
    let report = time_of_impact(&mut pair, &ma, &mb, &params).expect("valid query");
    let truth = first_sampled_contact(
        MeshRef {
            vertices: &va,
            triangles: &fa,
        },
        &ma,
        MeshRef {
            vertices: &vb,
            triangles: &fb,
        },
        &mb,
        (0.0, 1.0),
        SAMPLES,
    );
    // A stall (a contact by time tolerance) leaves at least the tolerance
    // before the end; `Separated` is checked against the sampled truth below.
    if let CaOutcome::Contact {
        contact,
        criterion: ContactCriterion::TimeTolerance,
    } = report.outcome
    {
        assert!(
            contact.time + params.time_tolerance < 1.0,
            "STALL AT THE END: a contact by time tolerance at {} ({report:?})",
            contact.time
        );
    }
    let reported = report.outcome.earliest_possible_contact();
    if let Some(g) = truth {
        match reported {
            None => panic!("MISSED: Separated, but the meshes intersect at t = {g} ({report:?})"),
            Some(t) => assert!(
                t <= g,
                "LATE: first possible contact {t} after an intersection at t = {g} ({report:?})"
            ),
        }
    }
}

fuzz_target!(|data: &[u8]| run(data));
