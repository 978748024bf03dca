//! Shared proptest strategies and oracle checks for the integration tests.
//!
//! The strategies generate `testkit::CaseSpec`, the same description the
//! fuzzer builds from `arbitrary` input, biased to the hard cases.

#![allow(dead_code, unreachable_pub)]

use motion_bound::reference::{exact, Exact, Real};
use motion_bound::testkit::{BodyFrame, Case, CaseSpec, Layout, Normal, Sweep};
use motion_bound::Float;
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

/// How many cases each property runs by default.
pub const CASES: u32 = 4096;

/// `PROPTEST_CASES` from the environment, else [`CASES`]. (An explicit
/// `ProptestConfig::with_cases` would otherwise ignore the variable.)
pub fn cases() -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(CASES)
}

fn coord() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => -1.0f64..1.0,
        1 => Just(0.0),
        1 => Just(1.0),
        1 => Just(-1.0),
    ]
}

fn vec3() -> impl Strategy<Value = [f64; 3]> {
    [coord(), coord(), coord()]
}

pub fn layout() -> impl Strategy<Value = Layout> {
    prop_oneof![
        4 => Just(Layout::Blob),
        1 => Just(Layout::OnAxis),
        1 => Just(Layout::HalfOnAxis),
        1 => Just(Layout::InPlane),
        1 => Just(Layout::FarFromCentre),
        2 => Just(Layout::Single),
    ]
}

pub fn sweep() -> impl Strategy<Value = Sweep> {
    prop_oneof![
        3 => (0.0f64..20.0).prop_map(Sweep::Free),
        3 => (0u8..4, -64i8..=64).prop_map(|(k, ulps)| Sweep::NearMultipleOfPi { k, ulps }),
        1 => (0u8..13).prop_map(Sweep::Tiny),
    ]
}

pub fn normal() -> impl Strategy<Value = Normal> {
    prop_oneof![
        4 => vec3().prop_map(Normal::Free),
        2 => (vec3(), 0u8..=64).prop_map(|(towards, ulps)| Normal::NearlyParallel { towards, ulps }),
        1 => Just(Normal::Parallel),
        1 => vec3().prop_map(Normal::Orthogonal),
    ]
}

/// The body frame: mostly the world frame (the hard cases as they are),
/// often a turned body, sometimes one rotating about a point off its origin.
pub fn frame() -> impl Strategy<Value = BodyFrame> {
    let q = [-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0];
    prop_oneof![
        3 => Just(BodyFrame::World),
        2 => q.clone().prop_map(BodyFrame::Oriented),
        1 => (q, vec3()).prop_map(|(q, c)| BodyFrame::OrientedAbout(q, c)),
    ]
}

/// Case descriptions biased to the hard cases.
pub fn case_spec() -> impl Strategy<Value = CaseSpec> {
    (
        prop::collection::vec(vec3(), 1..10),
        layout(),
        prop_oneof![3 => Just(0i8), 1 => -12i8..=12],
        vec3(),
        prop_oneof![3 => -1i8..=1, 1 => -12i8..=4],
        0.0f64..1.0,
        sweep(),
        prop_oneof![2 => Just(0.0f64), 1 => 0.0f64..4.0],
        normal(),
        vec3(),
        prop_oneof![3 => Just(0i8), 1 => -6i8..=6],
        frame(),
    )
        .prop_map(
            |(
                vertices,
                layout,
                size_exp,
                axis,
                omega_exp,
                omega_frac,
                sweep,
                start,
                normal,
                linear,
                linear_exp,
                frame,
            )| {
                CaseSpec {
                    vertices,
                    layout,
                    size_exp,
                    axis,
                    omega_exp,
                    omega_frac,
                    sweep,
                    start,
                    normal,
                    linear,
                    linear_exp,
                    frame,
                }
            },
        )
}

/// Ordinary cases: unit-sized bodies, moderate speeds, any sweep.
pub fn plain_spec() -> impl Strategy<Value = CaseSpec> {
    (
        prop::collection::vec(vec3(), 1..10),
        vec3(),
        -1i8..=1,
        0.0f64..1.0,
        sweep(),
        vec3(),
        vec3(),
    )
        .prop_map(
            |(vertices, axis, omega_exp, omega_frac, sweep, n, linear)| CaseSpec {
                vertices,
                layout: Layout::Blob,
                size_exp: 0,
                axis,
                omega_exp,
                omega_frac,
                sweep,
                start: 0.0,
                normal: Normal::Free(n),
                linear,
                linear_exp: 0,
                frame: BodyFrame::World,
            },
        )
}

/// The oracle in a precision above `T`'s: `f64` for `f32` inputs and
/// double-double for `f64` inputs.
pub trait Oracle: Float {
    fn exact_hp(case: &Case<Self>) -> Exact<f64>;
    /// Directed speeds of every vertex at `m` evenly spaced times, in the
    /// oracle's precision, rounded to f64 upwards in magnitude is not needed:
    /// the returned values are the high-precision values rounded to nearest.
    fn sampled_hp(case: &Case<Self>, m: usize) -> f64;
}

fn exact_in<T: Float, R: Real>(case: &Case<T>) -> Exact<f64> {
    let e: Exact<R> = exact(&case.vertices, &case.motion, case.n);
    Exact {
        sup_speed: e.sup_speed.to_f64(),
        displacement: e.displacement.to_f64(),
    }
}

fn sampled_in<T: Float, R: Real>(case: &Case<T>, m: usize) -> f64 {
    use motion_bound::reference::Frame;
    let f: Frame<R> = Frame::new(&case.motion, case.n);
    let iv = case.motion.interval();
    let (ta, tb) = (iv.start().to_f64(), iv.end().to_f64());
    let mut best = 0.0f64;
    for r in &case.vertices {
        let p = f.profile(*r);
        for j in 0..m {
            let t = ta + (tb - ta) * j as f64 / (m - 1).max(1) as f64;
            best = best.max(p.speed_at(R::from_f64(t)).abs().to_f64());
        }
    }
    best
}

impl Oracle for f32 {
    fn exact_hp(case: &Case<f32>) -> Exact<f64> {
        exact_in::<f32, f64>(case)
    }
    fn sampled_hp(case: &Case<f32>, m: usize) -> f64 {
        sampled_in::<f32, f64>(case, m)
    }
}

impl Oracle for f64 {
    fn exact_hp(case: &Case<f64>) -> Exact<f64> {
        exact_in::<f64, motion_bound::reference::dd::DoubleDouble>(case)
    }
    fn sampled_hp(case: &Case<f64>, m: usize) -> f64 {
        sampled_in::<f64, motion_bound::reference::dd::DoubleDouble>(case, m)
    }
}

/// The soundness property every directed bound must satisfy:
/// `speed >= sup |p'(t).n|` and `displacement >= integral |p'(t).n|` against
/// the high-precision exact value, and `speed >=` every densely sampled speed.
/// Comparisons are strict: the oracle is rounded to nearest f64 from ~106
/// bits (or exact f64 for f32 inputs); see `proofs/floating-point.md`.
pub fn check_sound<T: Oracle>(
    case: &Case<T>,
    speed: T,
    displacement: T,
    what: &str,
) -> Result<(), TestCaseError> {
    let ex = T::exact_hp(case);
    let (s, d) = (speed.to_f64(), displacement.to_f64());
    prop_assert!(!s.is_nan() && !d.is_nan(), "{what}: NaN bound");
    prop_assert!(
        s >= ex.sup_speed,
        "{what}: speed bound {s:e} below exact sup {:e} (ratio {:e})",
        ex.sup_speed,
        s / ex.sup_speed
    );
    prop_assert!(
        d >= ex.displacement,
        "{what}: displacement bound {d:e} below exact integral {:e}",
        ex.displacement
    );
    let sampled = T::sampled_hp(case, 33);
    prop_assert!(
        s >= sampled,
        "{what}: speed bound {s:e} below a sampled speed {sampled:e}"
    );
    Ok(())
}

/// `|n x w| / |n|` in `R` from the float inputs, exactly up to `R`'s
/// precision: the rim term's factor of a ball's bound along the exact unit
/// `n/|n|` (`proofs/08-ball-bound.md`, `proofs/10-one-sided.md`).
pub fn c_over_n<T: Float, R: Real>(
    n: motion_bound::Direction<T>,
    motion: &motion_bound::RigidMotion<T>,
) -> R {
    let r = |x: T| R::from_f64(x.to_f64());
    let (n, w) = (n.get(), motion.angular());
    let c = [
        r(n.y).mul(r(w.z)).sub(r(n.z).mul(r(w.y))),
        r(n.z).mul(r(w.x)).sub(r(n.x).mul(r(w.z))),
        r(n.x).mul(r(w.y)).sub(r(n.y).mul(r(w.x))),
    ];
    let n_len = r(n.x)
        .mul(r(n.x))
        .add(r(n.y).mul(r(n.y)))
        .add(r(n.z).mul(r(n.z)))
        .sqrt();
    c[0].mul(c[0])
        .add(c[1].mul(c[1]))
        .add(c[2].mul(c[2]))
        .sqrt()
        .div(n_len)
}

/// A ball centred at the first vertex holding every vertex, its radius
/// grown by `grow` (relative) and a `1e-6` margin over the `f64` distances;
/// `None` when the ball is out of range.
pub fn ball_around_first<T: Float>(
    vertices: &[[T; 3]],
    grow: f64,
) -> Option<motion_bound::BoundingBall<T>> {
    let s = *vertices.first()?;
    let mut rho = 0.0f64;
    for v in vertices {
        let d: f64 = (0..3)
            .map(|k| (v[k].to_f64() - s[k].to_f64()).powi(2))
            .sum();
        rho = rho.max(d.sqrt());
    }
    let rho = T::from_f64(rho * (1.0 + grow) * (1.0 + 1e-6));
    motion_bound::BoundingBall::try_new(s, rho).ok()
}
