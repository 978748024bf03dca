//! Forward kinematics in `f32` lanes: the chain placed at eight times at
//! once, each lane the same arithmetic as `Chain::place` in `f32`
//! (`proofs/13-chains.md`, Lemma 13.10), written as loops over fixed-size
//! arrays that the compiler turns into SIMD.
//!
//! The chain's numbers are stored here rounded to `f32`; the turns' cosines
//! and sines come from the caller (computed in `f64` and rounded), so that no
//! lane calls a transcendental function.

// Lane loops index fixed-size arrays by lane: the form the compiler turns
// into SIMD. A gap compared as `!(g > tau)` fails a NaN gap, as it must.
#![allow(clippy::needless_range_loop, clippy::neg_cmp_op_on_partial_ord)]

use alloc::vec::Vec;

use crate::chain::model::{Chain, JointKind};
use crate::{Float, Pose};

/// The lanes: eight times of one edge.
pub(crate) const LANES: usize = 8;

/// One number per lane.
pub(crate) type Lane = [f32; LANES];

/// A pose per lane: rotation entries and translation.
#[derive(Clone, Copy, Debug)]
pub(crate) struct LanePose {
    pub(crate) r: [[Lane; 3]; 3],
    pub(crate) t: [Lane; 3],
}

impl Default for LanePose {
    fn default() -> Self {
        Self {
            r: [[[0.0; LANES]; 3]; 3],
            t: [[0.0; LANES]; 3],
        }
    }
}

impl LanePose {
    /// The same pose in every lane.
    fn splat(p: &Pose<f32>) -> Self {
        let mut out = Self::default();
        for i in 0..3 {
            for j in 0..3 {
                out.r[i][j] = [p.rotation[i][j]; LANES];
            }
        }
        out.t = p.translation.to_array().map(|x| [x; LANES]);
        out
    }

    /// `R c + t` in every lane for a point `c` of the body frame
    /// (`Pose::transform_point`'s arithmetic).
    #[inline]
    pub(crate) fn place(&self, c: [f32; 3]) -> [Lane; 3] {
        let mut out = [[0.0f32; LANES]; 3];
        for (i, o) in out.iter_mut().enumerate() {
            for l in 0..LANES {
                o[l] = (self.r[i][0][l] * c[0] + self.r[i][1][l] * c[1] + self.r[i][2][l] * c[2])
                    + self.t[i][l];
            }
        }
        out
    }
}

/// A joint as the lanes need it.
#[derive(Clone, Debug)]
struct LaneJoint {
    parent: usize,
    child: usize,
    origin: Pose<f32>,
    axis: [f32; 3],
    /// `None` for a fixed joint; the coordinate and whether it turns.
    dof: Option<(usize, bool)>,
}

/// A chain's joints rounded to `f32`, parents first.
#[derive(Clone, Debug, Default)]
pub(crate) struct LaneChain {
    joints: Vec<LaneJoint>,
    root: usize,
    links: usize,
}

fn pose32<T: Float>(p: &Pose<T>) -> Pose<f32> {
    Pose {
        rotation: p.rotation.map(|row| row.map(|x| x.to_f64() as f32)),
        translation: crate::Vec3::from_array(p.translation.to_array().map(|x| x.to_f64() as f32)),
    }
}

impl LaneChain {
    /// The chain's joints in `f32`.
    pub(crate) fn new<T: Float>(chain: &Chain<T>) -> Self {
        let joints = chain
            .order
            .iter()
            .map(|&j| {
                let joint = &chain.joints[j];
                LaneJoint {
                    parent: joint.spec.parent,
                    child: joint.spec.child,
                    origin: pose32(&joint.spec.origin),
                    axis: joint.axis.to_array().map(|x| x.to_f64() as f32),
                    dof: joint
                        .dof
                        .map(|d| (d, joint.spec.kind != JointKind::Prismatic)),
                }
            })
            .collect();
        Self {
            joints,
            root: chain.root,
            links: chain.links.len(),
        }
    }

    /// Every link's pose in each lane: `turn[d]` the cosine and sine of
    /// coordinate `d` in each lane (turning joints), `slide[d]` the
    /// coordinate itself (sliding joints); the base placed by `base`.
    pub(crate) fn place<T: Float>(
        &self,
        base: &Pose<T>,
        turn: &[(Lane, Lane)],
        slide: &[Lane],
        poses: &mut Vec<LanePose>,
    ) {
        poses.clear();
        poses.resize(self.links, LanePose::default());
        poses[self.root] = LanePose::splat(&pose32(base));
        for j in &self.joints {
            let parent = poses[j.parent];
            let frame = compose_fixed(&parent, &j.origin);
            let child = match j.dof {
                Some((d, true)) => {
                    let (c, s) = &turn[d];
                    compose_turn(&frame, j.axis, c, s)
                }
                Some((d, false)) => {
                    let mut p = frame;
                    // frame.t + (R axis) q
                    for i in 0..3 {
                        for l in 0..LANES {
                            let a = frame.r[i][0][l] * j.axis[0]
                                + frame.r[i][1][l] * j.axis[1]
                                + frame.r[i][2][l] * j.axis[2];
                            p.t[i][l] = frame.t[i][l] + a * slide[d][l];
                        }
                    }
                    p
                }
                None => frame,
            };
            poses[j.child] = child;
        }
    }
}

/// `a * b` for a pose `b` the same in every lane (`model::compose`).
#[inline]
fn compose_fixed(a: &LanePose, b: &Pose<f32>) -> LanePose {
    let mut out = LanePose::default();
    for i in 0..3 {
        for k in 0..3 {
            for l in 0..LANES {
                out.r[i][k][l] = a.r[i][0][l] * b.rotation[0][k]
                    + a.r[i][1][l] * b.rotation[1][k]
                    + a.r[i][2][l] * b.rotation[2][k];
            }
        }
        let bt = b.translation.to_array();
        for l in 0..LANES {
            out.t[i][l] =
                (a.r[i][0][l] * bt[0] + a.r[i][1][l] * bt[1] + a.r[i][2][l] * bt[2]) + a.t[i][l];
        }
    }
    out
}

/// `a * turn(axis, angle)` with the angle's cosine and sine per lane
/// (`model::turn`'s entries, then `model::compose`; the turn's translation
/// is zero, so the frame's translation is kept).
#[inline]
fn compose_turn(a: &LanePose, axis: [f32; 3], c: &Lane, s: &Lane) -> LanePose {
    let [x, y, z] = axis;
    let mut m = [[[0.0f32; LANES]; 3]; 3];
    for l in 0..LANES {
        let (c, s) = (c[l], s[l]);
        let k = 1.0 - c;
        m[0][0][l] = c + x * x * k;
        m[0][1][l] = x * y * k - z * s;
        m[0][2][l] = x * z * k + y * s;
        m[1][0][l] = y * x * k + z * s;
        m[1][1][l] = c + y * y * k;
        m[1][2][l] = y * z * k - x * s;
        m[2][0][l] = z * x * k - y * s;
        m[2][1][l] = z * y * k + x * s;
        m[2][2][l] = c + z * z * k;
    }
    let mut out = LanePose {
        r: [[[0.0; LANES]; 3]; 3],
        t: a.t,
    };
    for i in 0..3 {
        for k in 0..3 {
            for l in 0..LANES {
                out.r[i][k][l] = a.r[i][0][l] * m[0][k][l]
                    + a.r[i][1][l] * m[1][k][l]
                    + a.r[i][2][l] * m[2][k][l];
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chain::{ChainBuilder, JointSpec};
    use crate::Vec3;

    /// The lanes' placements of points within 0.5 of each link frame's
    /// origin agree with `f64` forward kinematics (itself within about
    /// `1e-15` of exact) within Lemma 13.10's `delta`, over many chains
    /// (that bound has room: the largest error seen is printed).
    #[test]
    fn lanes_place_like_f64_forward_kinematics() {
        let mut worst = 0.0f64;
        for seed in 0..60 {
            worst = worst.max(one_chain(seed));
        }
        std::println!("largest error over delta: {worst:.2e}");
    }

    fn one_chain(seed: u64) -> f64 {
        let mut worst = 0.0f64;
        let mut rng = crate::rng::SplitMix64::new(seed);
        let mut b = ChainBuilder::<f64>::new();
        let mut prev = b.add_link("base", None).expect("link");
        for i in 0..6 {
            let l = b.add_link(alloc::format!("l{i}"), None).expect("link");
            let kind = [JointKind::Revolute, JointKind::Prismatic, JointKind::Fixed]
                [(i + seed as usize) % 3];
            let turn =
                crate::chain::model::turn(Vec3::from_array(rng.direction()), rng.range(-3.0, 3.0));
            b.add_joint(JointSpec {
                name: alloc::format!("j{i}"),
                kind,
                parent: prev,
                child: l,
                origin: Pose {
                    rotation: turn.rotation,
                    translation: Vec3::from_array(rng.vec3()),
                },
                axis: rng.direction(),
                limits: None,
            })
            .expect("joint");
            prev = l;
        }
        let chain = b.build().expect("chain");
        let lanes = LaneChain::new(&chain);
        let q: Vec<Vec<f64>> = (0..LANES)
            .map(|_| (0..chain.dof()).map(|_| rng.range(-2.0, 2.0)).collect())
            .collect();
        let kinds = chain.coordinate_kinds();
        let mut turn = Vec::new();
        let mut slide = Vec::new();
        for d in 0..chain.dof() {
            let mut c = [0.0f32; LANES];
            let mut s = [0.0f32; LANES];
            let mut x = [0.0f32; LANES];
            for l in 0..LANES {
                c[l] = q[l][d].cos() as f32;
                s[l] = q[l][d].sin() as f32;
                x[l] = q[l][d] as f32;
            }
            let _ = kinds[d];
            turn.push((c, s));
            slide.push(x);
        }
        let mut poses = Vec::new();
        lanes.place(&chain.base, &turn, &slide, &mut poses);
        let points: Vec<[f32; 3]> = (0..6)
            .map(|_| rng.vec3().map(|x| (x * 0.25) as f32))
            .collect();
        for l in 0..LANES {
            let exact = chain.try_forward_kinematics(&q[l]).expect("fk");
            for (k, p) in exact.iter().enumerate() {
                let (delta, _) = crate::chain::lever::lane_delta(&chain, &q[l], &q[l], k, 0.5);
                for c in &points {
                    let lane = poses[k].place(*c);
                    let want = p
                        .transform_point(Vec3::from_array(c.map(f64::from)))
                        .to_array();
                    let err = (0..3)
                        .map(|i| (f64::from(lane[i][l]) - want[i]).powi(2))
                        .sum::<f64>()
                        .sqrt();
                    assert!(
                        err <= delta,
                        "link {k}: error {err:e} above delta {delta:e}"
                    );
                    worst = worst.max(err / delta);
                }
            }
        }
        worst
    }
}
