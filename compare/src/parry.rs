//! Parry's side of the Table 1 scenario (`motion_bound::testkit::table1`),
//! shared by the `toi` benchmark and the `table1` report, so that both run
//! the very same queries.
//! Parry gets the same rotated copies as triangle meshes and the same
//! motions (checked by [`mapping_error`]).

use motion_bound::testkit::table1::{KnotScene, Query};
use motion_bound::RigidMotion;
use parry3d_f64::math::{Pose, Vector};
use parry3d_f64::query::{cast_shapes_nonlinear, NonlinearRigidMotion, ShapeCastStatus};
use parry3d_f64::shape::TriMesh as ParryMesh;

/// Our motion `p(t) = x0 + v t + R(|w| t, w/|w|) r` as parry's: start at the
/// translation `x0` with the identity rotation, rotation about the local
/// origin (our rotation centre), `linvel = v`, `angvel = w`. Parry places a
/// local point `r` at `T(c) T(v t) R(w t) T(-c) start r` with
/// `c = start * local_center = x0`, which is `x0 + v t + R(w t) r`.
pub fn parry_motion(m: &RigidMotion<f64>) -> NonlinearRigidMotion {
    let (c, v, w) = (m.centre(), m.linear(), m.angular());
    NonlinearRigidMotion::new(
        Pose::from_translation(Vector::new(c.x, c.y, c.z)),
        Vector::ZERO,
        Vector::new(v.x, v.y, v.z),
        Vector::new(w.x, w.y, w.z),
    )
}

/// The same rotated copies as parry triangle meshes.
pub fn parry_meshes(scene: &KnotScene) -> Vec<ParryMesh> {
    scene
        .meshes
        .iter()
        .map(|m| {
            let vertices = m
                .vertices()
                .iter()
                .map(|v| Vector::new(v[0], v[1], v[2]))
                .collect();
            ParryMesh::new(vertices, m.triangles().to_vec()).expect("a valid mesh")
        })
        .collect()
}

/// What parry's nonlinear shape cast answered for one query.
#[derive(Clone, Copy, Debug)]
pub struct ParryAnswer {
    /// The time of impact, or `None` when parry found no impact in `[0, 1]`.
    pub time: Option<f64>,
    /// Whether parry's status was `Failed` (it still returns a time).
    pub failed: bool,
}

/// Parry's `cast_shapes_nonlinear` over `[0, 1]` for query `q`, stopping at
/// penetration (like our initial contact).
pub fn parry_toi(meshes: &[ParryMesh], q: &Query) -> ParryAnswer {
    let hit = cast_shapes_nonlinear(
        &parry_motion(&q.motion.a),
        &meshes[q.a],
        &parry_motion(&q.motion.b),
        &meshes[q.b],
        0.0,
        1.0,
        true,
    )
    .expect("parry supports triangle mesh against triangle mesh");
    ParryAnswer {
        time: hit.map(|h| h.time_of_impact),
        failed: hit.is_some_and(|h| h.status == ShapeCastStatus::Failed),
    }
}

/// The largest distance, over every vertex of both bodies of `q` at time
/// `t`, between our placement (`RigidMotion::pose_at`) and parry's
/// (`NonlinearRigidMotion::position_at_time`): checks [`parry_motion`].
pub fn mapping_error(scene: &KnotScene, q: &Query, t: f64) -> f64 {
    let mut worst = 0.0_f64;
    for (mesh, motion) in [
        (&scene.meshes[q.a], &q.motion.a),
        (&scene.meshes[q.b], &q.motion.b),
    ] {
        let ours = motion.pose_at(t);
        let theirs = parry_motion(motion).position_at_time(t);
        for v in mesh.vertices() {
            let p = ours.transform_point(motion_bound::Vec3::from_array(*v));
            let s = theirs.transform_point(Vector::new(v[0], v[1], v[2]));
            let d = ((p.x - s.x).powi(2) + (p.y - s.y).powi(2) + (p.z - s.z).powi(2)).sqrt();
            worst = worst.max(d);
        }
    }
    worst
}
