//! The oriented boxes of `BallTree` nodes hold every corner they were fitted
//! to (`proofs/floating-point.md`, "Oriented box"), checked against an
//! independent projection: exact products and a double-double sum.

use motion_bound::reference::dd::{two_prod, DoubleDouble};
use motion_bound::testkit::oriented_box_supports;
use proptest::prelude::*;

/// `(p - c).m` in double-double from f64 inputs: each product exact
/// (`two_prod`), the sums in double-double.
fn projection(p: [f64; 3], c: [f64; 3], m: [f64; 3]) -> f64 {
    let mut acc = DoubleDouble::new(0.0, 0.0);
    for k in 0..3 {
        for (x, sign) in [(p[k], 1.0), (c[k], -1.0)] {
            let (hi, lo) = two_prod(x * sign, m[k]);
            acc = acc.add_dd(DoubleDouble::new(hi, lo));
        }
    }
    acc.to_f64()
}

/// A cloud: a random patch (points near a tilted, curved sheet), so the fit
/// gets a thin axis, sometimes a line or a single point; scale and offset
/// span many magnitudes.
fn cloud() -> impl Strategy<Value = (Vec<[f64; 3]>, Vec<[f64; 3]>)> {
    (
        prop::collection::vec((-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0), 1..40),
        (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0),
        0.0f64..0.3,
        -6i32..7,
        -6i32..7,
        prop::collection::vec((-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0), 16),
        0u8..3,
    )
        .prop_map(|(raw, tilt, curve, scale, offset, dirs, shape)| {
            let (s, o) = (10f64.powi(scale), 10f64.powi(offset));
            let pts = raw
                .iter()
                .map(|&(x, y, z)| {
                    let (y, z) = match shape {
                        0 => (y, z),     // a blob
                        1 => (y, 0.0),   // a sheet, bent below
                        _ => (0.0, 0.0), // a segment
                    };
                    let z = z * 1e-3 + curve * (x * x + y * y) + tilt.0 * x + tilt.1 * y;
                    [x * s + o, y * s - o * tilt.2, z * s + 0.5 * o]
                })
                .collect();
            let dirs = dirs
                .iter()
                .map(|&(x, y, z)| {
                    let l = (x * x + y * y + z * z).sqrt().max(1e-9);
                    [x / l, y / l, z / l]
                })
                .collect();
            (pts, dirs)
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn f64_boxes_hold_their_points((pts, dirs) in cloud()) {
        let (c, supp) = oriented_box_supports(&pts, &dirs);
        for (m, s) in dirs.iter().zip(&supp) {
            for p in &pts {
                let proj = projection(*p, c, *m);
                prop_assert!(proj.abs() <= *s, "{p:?} projects to {proj} > support {s} along {m:?}");
            }
        }
    }

    #[test]
    fn f32_boxes_hold_their_points((pts, dirs) in cloud()) {
        let to32 = |v: &Vec<[f64; 3]>| v.iter().map(|p| p.map(|x| x as f32)).collect::<Vec<_>>();
        let (pts, dirs) = (to32(&pts), to32(&dirs));
        let (c, supp) = oriented_box_supports(&pts, &dirs);
        let up = |p: [f32; 3]| p.map(f64::from);
        for (m, s) in dirs.iter().zip(&supp) {
            for p in &pts {
                let proj = projection(up(*p), up(c), up(*m));
                prop_assert!(proj.abs() <= f64::from(*s), "{p:?} projects to {proj} > support {s} along {m:?}");
            }
        }
    }
}

#[test]
fn the_check_is_not_vacuous() {
    // The support of a box of a flat unit square along its normal is tiny and
    // along its side is about the half side: a wrong centre or a missing
    // extent would fail the property above.
    let pts: [[f64; 3]; 4] = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [1.0, 1.0, 0.0],
    ];
    let (c, s) = oriented_box_supports(&pts, &[[0.0, 0.0, 1.0], [1.0, 0.0, 0.0]]);
    assert!(s[0] < 1e-12, "thin along the normal: {}", s[0]);
    assert!((s[1] - 0.5).abs() < 1e-9, "half the side: {}", s[1]);
    assert!(
        (c[0] - 0.5).abs() < 1e-12 && (c[1] - 0.5).abs() < 1e-12,
        "centre {c:?}"
    );
}
