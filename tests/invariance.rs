//! Bounds are invariant under a rigid change of frame and obey the scaling
//! laws (`proofs/01-definitions.md`, sections "Frame invariance" and
//! "Scaling").

mod common;

use approx::{assert_relative_eq, relative_eq};
use common::{case_spec, cases};
use motion_bound::testkit::Case;
use motion_bound::{
    evq, nevq, rotate_about_axis, Direction, Point3, RigidMotion, Rotation, TimeInterval, Vec3,
    VertexSet,
};
use proptest::prelude::*;

fn bounds(case: &Case<f64>) -> (f64, f64) {
    let body = VertexSet::try_new(&case.vertices).unwrap();
    (
        nevq(&body.summary(), &case.motion, case.n).speed,
        evq(&body, &case.motion, case.n).speed,
    )
}

fn transformed(case: &Case<f64>, axis: Vec3<f64>, angle: f64, shift: Vec3<f64>) -> Case<f64> {
    let q = |v: Vec3<f64>| rotate_about_axis(v, axis, angle);
    let m = &case.motion;
    let motion = RigidMotion::try_new(
        Point3::from_array(q(m.centre().to_vec3()).to_array()) + shift,
        q(m.linear()),
        q(m.angular()),
        m.interval(),
    )
    .unwrap();
    if m.orientation().is_identity() {
        // Body points in the world frame: rotate them.
        Case {
            vertices: case
                .vertices
                .iter()
                .map(|r| q(Vec3::from_array(*r)).to_array())
                .collect(),
            motion,
            n: Direction::try_new(q(case.n.get())).unwrap(),
        }
    } else {
        // A turned body: the points stay in its frame, its orientation
        // turns with the world.
        let g = Rotation::try_from_axis_angle(axis, angle).unwrap();
        let motion = motion
            .with_orientation(g * m.orientation())
            .try_with_local_centre(m.local_centre())
            .unwrap();
        Case {
            vertices: case.vertices.clone(),
            motion,
            n: Direction::try_new(q(case.n.get())).unwrap(),
        }
    }
}

fn scaled_motion(case: &Case<f64>, lambda: f64, size: f64) -> Case<f64> {
    let m = &case.motion;
    let iv = m.interval();
    let motion = RigidMotion::try_new(
        m.centre(),
        m.linear() * (lambda * size),
        m.angular() * lambda,
        TimeInterval::try_new(iv.start() / lambda, iv.end() / lambda).unwrap(),
    )
    .unwrap()
    .with_orientation(m.orientation())
    .try_with_local_centre(m.local_centre() * size)
    .unwrap();
    Case {
        vertices: case.vertices.iter().map(|r| r.map(|x| x * size)).collect(),
        motion,
        n: case.n,
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    /// A rigid change of frame (rotation of every vector, translation of the
    /// centre) leaves both bounds unchanged up to the rounding of the
    /// transformation itself.
    #[test]
    fn bounds_are_invariant_under_a_rigid_change_of_frame(
        spec in case_spec(),
        axis in [-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0],
        angle in -10.0f64..10.0,
        shift in [-1e3f64..1e3, -1e3f64..1e3, -1e3f64..1e3],
    ) {
        let Some(case) = spec.build::<f64>() else { return Ok(()) };
        let axis = Vec3::from_array(axis).normalize_or(Vec3::new(0.0, 0.0, 1.0));
        let moved = transformed(&case, axis, angle, Vec3::from_array(shift));
        let (n0, e0) = bounds(&case);
        let (n1, e1) = bounds(&moved);
        // The rotation perturbs every input by a few ulps; the bounds are
        // Lipschitz in their inputs with constants of the order of the input
        // scale |v| + |w| R (proofs/01-definitions.md, "Frame invariance").
        let r = case.vertices.iter().map(|p| Vec3::from_array(*p).length()).fold(0.0, f64::max);
        let scale = case.motion.linear().length() + case.motion.angular().length() * r;
        let tol = 1e-12 * scale;
        prop_assert!(relative_eq!(n0, n1, epsilon = tol, max_relative = 1e-12), "NEVQ {n0:e} vs {n1:e}");
        prop_assert!(relative_eq!(e0, e1, epsilon = tol, max_relative = 1e-12), "EVQ {e0:e} vs {e1:e}");
    }

    /// `mu` is linear in `(v, w)` jointly once time is rescaled to keep the
    /// swept arc (`(lambda v, lambda w)` over `[t_a/lambda, t_b/lambda]`), and
    /// the whole bound is linear in the body's size when `v` scales with it.
    /// With powers of two every rounding scales exactly.
    #[test]
    fn bounds_obey_the_scaling_laws(spec in case_spec(), le in -20i32..20, se in -20i32..20) {
        let Some(case) = spec.build::<f64>() else { return Ok(()) };
        let (lambda, size) = (2f64.powi(le), 2f64.powi(se));
        let scaled = scaled_motion(&case, lambda, size);
        let (n0, e0) = bounds(&case);
        let (n1, e1) = bounds(&scaled);
        let k = lambda * size;
        // Absolute slack: the underflow terms of the margin (sqrt(eta) scale) do not scale.
        let eps = 1e-150;
        prop_assert!(relative_eq!(n1, k * n0, epsilon = eps, max_relative = 1e-13), "NEVQ {n1:e} vs {:e}", k * n0);
        prop_assert!(relative_eq!(e1, k * e0, epsilon = eps, max_relative = 1e-13), "EVQ {e1:e} vs {:e}", k * e0);
    }
}

#[test]
fn nevq_is_linear_in_v_and_w_jointly_on_any_interval() {
    let body = VertexSet::try_new(&[[0.3, -0.2, 0.9], [1.0, 0.5, -0.5]]).unwrap();
    let n = Direction::try_new(Vec3::new(0.2, 0.9, -0.4)).unwrap();
    let m = RigidMotion::try_from_arrays([0.0; 3], [0.4, 1.0, -2.0], [1.5, -0.3, 0.7]).unwrap();
    let base = nevq(&body.summary(), &m, n).speed;
    for lambda in [0.001, 0.37, 3.0, 1e4] {
        let ml = RigidMotion::try_from_arrays(
            [0.0; 3],
            (m.linear() * lambda).to_array(),
            (m.angular() * lambda).to_array(),
        )
        .unwrap();
        assert_relative_eq!(
            nevq(&body.summary(), &ml, n).speed,
            lambda * base,
            max_relative = 1e-13
        );
    }
}
