//! Curved cores (cylinders and cones, rounded or not) flying past and into
//! the other kinds, spinning, in `f32` and `f64`: never late and never
//! missed against sampled ground truth (`proofs/12-shapes.md`, the lemma
//! "The closest direction, to the stepper's need": GJK on a curved core
//! stops as soon as its duality gap is a small share of the gap the step
//! uses, and the step stays certified by the gap it measures itself).
//!
//! The truth is `shape_truth`'s, independent of the code under test: each
//! core tessellated inside itself (rims by inscribed 16-gons), placed by the
//! testkit's own quaternion placement, in `f64`. An `f32` query's shapes
//! and motions are `f32` values, the truth's the same values in `f64`
//! (exactly), so the `f32` cast is judged against the exact motion of its
//! own parameters. `CURVED_QUERIES` sets the queries per pair (default 4).

#[path = "common/shape_truth.rs"]
mod shape_truth;

use motion_bound::ca::{time_of_impact, CaOutcome, CaParams, ConvexPair};
use motion_bound::testkit::toi::Rng;
use motion_bound::{Convex, Float, RigidMotion};
use shape_truth::Solid;

/// Ground-truth samples over `[0, 1]`.
const SAMPLES: usize = 200;

/// A shape kind by its dimensions (in `f64`, rounded to the precision
/// under test before use).
#[derive(Clone, Copy, Debug)]
enum Kind {
    /// Half-height, radius, rounding.
    Cylinder(f64, f64, f64),
    /// Half-height, base radius, rounding.
    Cone(f64, f64, f64),
    /// Half extents, rounding.
    Cuboid([f64; 3], f64),
}

/// `x` rounded to `T` and back: the value both the query and its truth use.
fn exact<T: Float>(x: f64) -> f64 {
    T::from_f64(x).to_f64()
}

impl Kind {
    fn name(self) -> String {
        match self {
            Self::Cylinder(h, r, s) => format!("cylinder({h}, {r}) + {s}"),
            Self::Cone(h, r, s) => format!("cone({h}, {r}) + {s}"),
            Self::Cuboid(h, s) => format!("cuboid({h:?}) + {s}"),
        }
    }

    fn shape<T: Float>(self) -> Convex<'static, T> {
        let f = T::from_f64;
        let (core, s) = match self {
            Self::Cylinder(h, r, s) => (Convex::try_cylinder(f(h), f(r)), s),
            Self::Cone(h, r, s) => (Convex::try_cone(f(h), f(r)), s),
            Self::Cuboid(h, s) => (Convex::try_cuboid(h.map(f)), s),
        };
        let core = core.expect("valid dimensions");
        if s > 0.0 {
            core.try_rounded(f(s)).expect("valid rounding")
        } else {
            core
        }
    }

    fn solid<T: Float>(self) -> Solid {
        let e = exact::<T>;
        let (core, s) = match self {
            Self::Cylinder(h, r, s) => (Solid::cylinder(e(h), e(r)), s),
            Self::Cone(h, r, s) => (Solid::cone(e(h), e(r)), s),
            Self::Cuboid(h, s) => (Solid::cuboid(h.map(e), 0.0), s),
        };
        Solid {
            parts: core.parts.into_iter().map(|(t, _)| (t, e(s))).collect(),
        }
    }
}

/// The curved kinds under test: the cylinder world's (rapier's
/// `cylinder(0.3, 0.05)` and `cone(0.3, 0.08)`), rounded forms, a flat
/// wheel.
const CURVED: [Kind; 5] = [
    Kind::Cylinder(0.3, 0.05, 0.0),
    Kind::Cone(0.3, 0.08, 0.0),
    Kind::Cylinder(0.3, 0.05, 0.02),
    Kind::Cone(0.3, 0.08, 0.02),
    Kind::Cylinder(0.05, 0.3, 0.0),
];

/// What they meet: the cylinder world's thin wall, a rounded box, a
/// cylinder, a cone.
const PARTNERS: [Kind; 4] = [
    Kind::Cuboid([0.01, 0.6, 0.6], 0.0),
    Kind::Cuboid([0.3, 0.2, 0.25], 0.03),
    Kind::Cylinder(0.25, 0.2, 0.0),
    Kind::Cone(0.3, 0.25, 0.0),
];

/// A motion of `T` values from `f64` draws, and the same values in `f64`.
fn motion<T: Float>(c: [f64; 3], v: [f64; 3], w: [f64; 3]) -> (RigidMotion<T>, RigidMotion<f64>) {
    let (c, v, w) = (c.map(exact::<T>), v.map(exact::<T>), w.map(exact::<T>));
    let t = |a: [f64; 3]| a.map(T::from_f64);
    (
        RigidMotion::try_from_arrays(t(c), t(v), t(w)).expect("finite motion"),
        RigidMotion::try_from_arrays(c, v, w).expect("finite motion"),
    )
}

/// Every curved kind against every partner, `queries` each: A flies at B
/// from 1.0 to 1.4 apart, aimed within B's reach of its centre (grazing
/// passes and hits), both spinning. Returns (queries, sampled contacts,
/// undecided) after asserting never late and never missed.
fn curved_against_partners<T: Float>(seed: u64) -> (usize, usize, Vec<String>) {
    let queries: usize = std::env::var("CURVED_QUERIES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(4);
    let mut rng = Rng::new(seed);
    let (mut total, mut sampled, mut undecided) = (0, 0, Vec::new());
    for a in CURVED {
        for b in PARTNERS {
            let (sa, sb) = (a.shape::<T>(), b.shape::<T>());
            let (ta, tb) = (a.solid::<T>(), b.solid::<T>());
            for q in 0..queries {
                let start = rng.direction().map(|x| x * rng.range(1.0, 1.4));
                let aim = rng.direction().map(|x| x * rng.range(0.3, 0.8));
                let v = [0, 1, 2].map(|k| aim[k] - start[k]);
                let spin = [0.0, 3.0, 20.0, 40.0][q % 4];
                let wa = rng.direction().map(|x| x * spin * rng.range(0.5, 1.0));
                let wb = rng.direction().map(|x| x * spin * 0.1 * rng.unit());
                let (ma, ma64) = motion::<T>(start, v, wa);
                let (mb, mb64) = motion::<T>([0.0; 3], [0.0; 3], wb);
                let params = CaParams::default()
                    .with_contact_distance(T::from_f64(1e-3))
                    .with_max_iterations(2_000);
                let report = time_of_impact(&mut ConvexPair::new(sa, sb), &ma, &mb, &params)
                    .expect("a valid query");
                let truth =
                    shape_truth::first_sampled_contact(&ta, &ma64, &tb, &mb64, (0.0, 1.0), SAMPLES);
                let what = format!(
                    "{} vs {} query {q}: {report:?}, sampled {truth:?}",
                    a.name(),
                    b.name()
                );
                match (report.outcome.earliest_possible_contact(), truth) {
                    (None, Some(_)) => panic!("MISSED: {what}"),
                    (Some(t), Some(g)) => assert!(t.to_f64() <= g, "LATE: {what}"),
                    _ => {}
                }
                total += 1;
                sampled += usize::from(truth.is_some());
                if report.outcome.contact().is_none()
                    && !matches!(report.outcome, CaOutcome::Separated)
                {
                    undecided.push(what);
                }
            }
        }
    }
    println!(
        "{total} queries, {sampled} sampled contacts, {} undecided {undecided:?}; 0 missed, 0 late",
        undecided.len()
    );
    assert!(sampled * 3 >= total, "too few sampled contacts for power");
    (total, sampled, undecided)
}

#[test]
fn curved_cores_against_every_kind_are_never_late_and_never_missed_f64() {
    let (_, _, undecided) = curved_against_partners::<f64>(55);
    assert!(undecided.is_empty(), "undecided: {undecided:?}");
}

#[test]
fn curved_cores_against_every_kind_are_never_late_and_never_missed_f32() {
    curved_against_partners::<f32>(56);
}
