//! Ground truth for time-of-impact tests: the first sampled time at which
//! two moving meshes intersect, by an exact triangle intersection test.
//!
//! Deliberately independent of the code under test: bodies are placed by a
//! unit quaternion computed here (not [`RigidMotion::pose_at`]), candidate
//! triangle pairs come from a sort-and-sweep of axis-aligned boxes (not the
//! ball trees), and intersection is decided by exact orientation predicates
//! ([`triangles_intersect_exact`](crate::testkit::triangles_intersect_exact)). Sampling can
//! miss a contact shorter than the sampling step; it never reports one that
//! is not there (for the rounded sample positions).

extern crate std;
use std::vec::Vec;

use crate::RigidMotion;

/// A triangle mesh as plain slices: vertices in the body frame, and index
/// triples.
#[derive(Clone, Copy, Debug)]
pub struct MeshRef<'a> {
    /// Vertices in the body frame.
    pub vertices: &'a [[f64; 3]],
    /// Triangles as index triples into `vertices`.
    pub triangles: &'a [[u32; 3]],
}

impl<'a> From<&'a crate::TriMesh<f64>> for MeshRef<'a> {
    fn from(m: &'a crate::TriMesh<f64>) -> Self {
        Self {
            vertices: m.vertices(),
            triangles: m.triangles(),
        }
    }
}

/// Rotates `r` by the unit quaternion `(w, q)`:
/// `r' = r + 2 w (q x r) + 2 q x (q x r)`.
fn quat_rotate(w: f64, q: [f64; 3], r: [f64; 3]) -> [f64; 3] {
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let cx = cross(q, r);
    let ccx = cross(q, cx);
    [0, 1, 2].map(|k| r[k] + 2.0 * w * cx[k] + 2.0 * ccx[k])
}

/// Places the body point `r` at time `t`:
/// `x0 + v t + q_s q0 (r - c) q0^-1 q_s^-1`, with `q0` the start orientation's
/// quaternion (normalised here), `c` the rotation centre in the body frame
/// and `q_s` the unit quaternion of the rotation by `|w| t` about `w/|w|`.
#[must_use]
pub fn place(motion: &RigidMotion<f64>, r: [f64; 3], t: f64) -> [f64; 3] {
    let w = motion.angular();
    let x0 = motion.centre();
    let v = motion.linear();
    let c = motion.local_centre();
    let d = [r[0] - c.x, r[1] - c.y, r[2] - c.z];
    let [q0w, q0x, q0y, q0z] = motion.orientation().quaternion();
    let l = (q0w * q0w + q0x * q0x + q0y * q0y + q0z * q0z).sqrt();
    let arm = quat_rotate(q0w / l, [q0x / l, q0y / l, q0z / l], d);
    let omega = (w.x * w.x + w.y * w.y + w.z * w.z).sqrt();
    let rotated = if omega == 0.0 {
        arm
    } else {
        let half = 0.5 * omega * t;
        let (s, cw) = (half.sin() / omega, half.cos());
        quat_rotate(cw, [w.x * s, w.y * s, w.z * s], arm)
    };
    [
        x0.x + v.x * t + rotated[0],
        x0.y + v.y * t + rotated[1],
        x0.z + v.z * t + rotated[2],
    ]
}

/// Whether the two meshes, placed at time `t`, share a point (closed
/// triangles; exact predicates on the rounded placed vertices).
#[must_use]
pub fn intersect_at(
    a: MeshRef<'_>,
    ma: &RigidMotion<f64>,
    b: MeshRef<'_>,
    mb: &RigidMotion<f64>,
    t: f64,
) -> bool {
    let pa: Vec<[f64; 3]> = a.vertices.iter().map(|&r| place(ma, r, t)).collect();
    let pb: Vec<[f64; 3]> = b.vertices.iter().map(|&r| place(mb, r, t)).collect();
    let boxes = |p: &[[f64; 3]], tris: &[[u32; 3]], side: u8| {
        tris.iter()
            .enumerate()
            .map(|(i, tri)| {
                let c = tri.map(|k| p[k as usize]);
                let lo = [0, 1, 2].map(|k| c[0][k].min(c[1][k]).min(c[2][k]));
                let hi = [0, 1, 2].map(|k| c[0][k].max(c[1][k]).max(c[2][k]));
                (lo, hi, side, i)
            })
            .collect::<Vec<_>>()
    };
    let mut all = boxes(&pa, a.triangles, 0);
    all.extend(boxes(&pb, b.triangles, 1));
    all.sort_by(|x, y| x.0[0].total_cmp(&y.0[0]));
    // Sweep along x; keep the boxes whose x-range is still open.
    let mut open: Vec<usize> = Vec::new();
    for (k, bx) in all.iter().enumerate() {
        open.retain(|&o| all[o].1[0] >= bx.0[0]);
        for &o in &open {
            let other = &all[o];
            if other.2 == bx.2 {
                continue;
            }
            let overlap = (1..3).all(|d| other.0[d] <= bx.1[d] && bx.0[d] <= other.1[d]);
            if !overlap {
                continue;
            }
            let (ia, ib) = if bx.2 == 0 {
                (bx.3, other.3)
            } else {
                (other.3, bx.3)
            };
            let ta = a.triangles[ia].map(|v| pa[v as usize]);
            let tb = b.triangles[ib].map(|v| pb[v as usize]);
            if crate::testkit::triangles_intersect_exact(&ta, &tb) {
                return true;
            }
        }
        open.push(k);
    }
    false
}

/// The first of `samples` evenly spaced times in `[t0, t1]` (both ends
/// included) at which the meshes intersect, or `None`.
#[must_use]
pub fn first_sampled_contact(
    a: MeshRef<'_>,
    ma: &RigidMotion<f64>,
    b: MeshRef<'_>,
    mb: &RigidMotion<f64>,
    (t0, t1): (f64, f64),
    samples: usize,
) -> Option<f64> {
    let m = samples.max(2);
    (0..m)
        .map(|k| t0 + (t1 - t0) * k as f64 / (m - 1) as f64)
        .find(|&t| intersect_at(a, ma, b, mb, t))
}
