//! Numerical stress sweep (`proofs/floating-point.md`, "Stress sweep"):
//! vertex magnitudes 1e-12..1e12, |w| 1e-12..1e4, sweeps within a few ulps
//! of pi and 2 pi, n within a few ulps of parallel to w, bodies far from the
//! rotation centre with small extents. Violations must be 0; the slack
//! (bound / exact - 1) is reported. Run with `--nocapture` to see the report.

mod common;

use common::Oracle;
use motion_bound::testkit::{BodyFrame, CaseSpec, Layout, Normal, SplitMix64, Sweep};
use motion_bound::{evq, nevq, VertexSet};

#[derive(Default)]
struct Tally {
    cases: usize,
    violations: usize,
    slack: Vec<f64>,
}

impl Tally {
    fn add(&mut self, bound: f64, exact: f64) {
        self.cases += 1;
        if bound < exact || bound.is_nan() {
            self.violations += 1;
        } else if exact > 0.0 {
            self.slack.push(bound / exact - 1.0);
        }
    }
    fn report(&mut self, name: &str) -> String {
        self.slack.sort_by(f64::total_cmp);
        let med = self
            .slack
            .get(self.slack.len() / 2)
            .copied()
            .unwrap_or(f64::NAN);
        let worst = self.slack.last().copied().unwrap_or(f64::NAN);
        format!(
            "| {name} | {} | {} | {:.3e} | {:.3e} |",
            self.cases, self.violations, med, worst
        )
    }
}

fn specs() -> Vec<CaseSpec> {
    let mut rng = SplitMix64(0x5eed_2026);
    let mut out = Vec::new();
    let sweeps = [
        Sweep::NearMultipleOfPi { k: 0, ulps: -4 },
        Sweep::NearMultipleOfPi { k: 0, ulps: 0 },
        Sweep::NearMultipleOfPi { k: 0, ulps: 3 },
        Sweep::NearMultipleOfPi { k: 1, ulps: -3 },
        Sweep::NearMultipleOfPi { k: 1, ulps: 0 },
        Sweep::NearMultipleOfPi { k: 1, ulps: 4 },
        Sweep::Free(1.0),
    ];
    for _rep in 0..4 {
        for size_exp in (-12i8..=12).step_by(3) {
            for omega_exp in (-12i8..=4).step_by(2) {
                for sweep in sweeps {
                    for nk in 0..3 {
                        for layout in [Layout::Blob, Layout::FarFromCentre, Layout::HalfOnAxis] {
                            let normal = match nk {
                                0 => Normal::Free(rng.vec3()),
                                1 => Normal::NearlyParallel {
                                    towards: rng.vec3(),
                                    ulps: (rng.next_u64() % 8 + 1) as u8,
                                },
                                _ => Normal::Parallel,
                            };
                            out.push(CaseSpec {
                                vertices: (0..8).map(|_| rng.vec3()).collect(),
                                layout,
                                size_exp,
                                axis: rng.vec3(),
                                omega_exp,
                                omega_frac: rng.signed_unit().abs(),
                                sweep,
                                start: rng.signed_unit().abs(),
                                normal,
                                linear: rng.vec3(),
                                linear_exp: 0,
                                frame: if layout == Layout::Blob {
                                    BodyFrame::Oriented([
                                        rng.signed_unit(),
                                        rng.signed_unit(),
                                        rng.signed_unit(),
                                        rng.signed_unit(),
                                    ])
                                } else {
                                    BodyFrame::World
                                },
                            });
                        }
                    }
                }
            }
        }
    }
    out
}

fn sweep<T: Oracle>() -> (Tally, Tally) {
    let (mut tn, mut te) = (Tally::default(), Tally::default());
    let mut worst_free = 0.0f64;
    for spec in specs() {
        let Some(case) = spec.build::<T>() else {
            continue;
        };
        let body = VertexSet::try_new(&case.vertices).expect("valid body");
        let ex = T::exact_hp(&case);
        tn.add(
            nevq(&body.summary(), &case.motion, case.n).speed.to_f64(),
            ex.sup_speed,
        );
        let e = evq(&body, &case.motion, case.n).speed.to_f64();
        te.add(e, ex.sup_speed);
        if matches!(spec.normal, Normal::Free(_)) && ex.sup_speed > 0.0 {
            worst_free = worst_free.max(e / ex.sup_speed - 1.0);
        }
    }
    println!("worst EVQ slack with n free (not near the axis): {worst_free:.3e}");
    (tn, te)
}

#[test]
fn stress_sweep_has_no_violation() {
    let (mut n64, mut e64) = sweep::<f64>();
    let (mut n32, mut e32) = sweep::<f32>();
    println!("| bound | cases | violations | median slack | worst slack |");
    println!("|---|---|---|---|---|");
    for line in [
        n64.report("NEVQ f64"),
        e64.report("EVQ f64"),
        n32.report("NEVQ f32"),
        e32.report("EVQ f32"),
    ] {
        println!("{line}");
    }
    for (t, name) in [
        (&n64, "NEVQ f64"),
        (&e64, "EVQ f64"),
        (&n32, "NEVQ f32"),
        (&e32, "EVQ f32"),
    ] {
        assert!(t.cases >= 20_000, "{name}: only {} cases built", t.cases);
        assert_eq!(t.violations, 0, "{name}: bound below the exact value");
    }
}
