//! Static levers: for each link and each movable joint on its path, a bound
//! of the distance of every point of the link from that joint's axis *at
//! every configuration* (`proofs/13-chains.md`, Lemma 13.11). With them the
//! chain bound (Lemma 13.1) gives a speed bound of a whole link that does
//! not depend on where the chain is, so a rake over time sweeps every lane
//! by one number per link; and the placement error of the rake's `f32`
//! lanes (Lemma 13.10).

use alloc::vec::Vec;

use crate::chain::model::{compose, Chain, JointKind};
use crate::{Float, Pose, Vec3};

/// The unit roundoff of `f32`, in `f64`.
pub(crate) const U32: f64 = 1.0 / 16_777_216.0;

/// `gamma_k` of `f32` (`(k + 1) u`), in `f64`.
#[inline]
pub(crate) fn gamma32(k: u32) -> f64 {
    f64::from(k + 1) * U32
}

fn pose64<T: Float>(p: &Pose<T>) -> Pose<f64> {
    Pose {
        rotation: p.rotation.map(|r| r.map(T::to_f64)),
        translation: Vec3::from_array(p.translation.to_array().map(T::to_f64)),
    }
}

/// The levers of link `link` for the points `vertices` (its mesh, link
/// frame), one per joint of its path (root first); `L_i` bounds
/// `dist(p, axis_i)` at every configuration for every point of the
/// triangles, less the slides of the prismatic joints below `i` (added per
/// edge by [`sweep_rate`]). Empty for a link without movable joints above.
pub(crate) fn link_levers<T: Float>(
    chain: &Chain<T>,
    link: usize,
    vertices: &[[T; 3]],
) -> Vec<f64> {
    // Every joint from the root down to the link, root first.
    let mut all = Vec::new();
    let mut at = link;
    while let Some(j) = chain.links[at].parent_joint {
        all.push(j);
        at = chain.joints[j].spec.parent;
    }
    all.reverse();
    let m = all.len() as u32;
    let movable: Vec<usize> = (0..all.len())
        .filter(|&i| chain.joints[all[i]].dof.is_some())
        .collect();
    let Some(&deepest) = movable.last() else {
        return Vec::new();
    };
    let axis = |i: usize| chain.joints[all[i]].axis.to_array().map(T::to_f64);
    let cross_len = |g: [f64; 3], k: [f64; 3]| {
        let c = [
            g[1] * k[2] - g[2] * k[1],
            g[2] * k[0] - g[0] * k[2],
            g[0] * k[1] - g[1] * k[0],
        ];
        (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt()
    };
    let len = |g: [f64; 3]| (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]).sqrt();
    // The fixed placement of the joints after position `a` up to `b`
    // (inclusive): origins composed, in the frame of joint `a`'s child.
    let chain_of = |a: usize, b: usize| {
        let mut p = Pose::<f64>::IDENTITY;
        for &j in &all[a + 1..=b] {
            p = compose(&p, &pose64(&chain.joints[j].spec.origin));
        }
        p
    };
    // The deepest joint: the link's own points in its child's frame.
    let to_link = if deepest + 1 < all.len() {
        chain_of(deepest, all.len() - 1)
    } else {
        Pose::IDENTITY
    };
    let k_last = axis(deepest);
    let (mut lever_last, mut reach) = (0.0f64, 0.0f64);
    for v in vertices {
        let p = to_link
            .transform_point(Vec3::from_array(v.map(T::to_f64)))
            .to_array();
        lever_last = lever_last.max(cross_len(p, k_last));
        reach = reach.max(len(p));
    }
    let n = movable.len();
    let mut lever = alloc::vec![0.0f64; n];
    lever[n - 1] = lever_last;
    // Up the path: dist(p, axis_i) <= dist(o_next, axis_i) + |p - o_next|.
    for i in (0..n - 1).rev() {
        let (a, b) = (movable[i], movable[i + 1]);
        let g = chain_of(a, b).translation.to_array();
        lever[i] = cross_len(g, axis(a)) + reach;
        reach += len(g);
    }
    // Rounding: the f64 evaluation (a few ulps of the terms, `2^-40` of
    // `reach`), the stored rotations' distance from exact ones (`48 u` each,
    // convention (O)) and the axes' normalisation (`4.5 u`), at most
    // `gamma_{64 (m + 1)}` of `reach` in `T`'s `u`.
    let slack =
        reach * (crate::rounding::gamma::<T>(64 * (m + 1)).to_f64() + 1.0 / 1_099_511_627_776.0);
    for l in &mut lever {
        *l = (*l + slack) * (1.0 + 1.0 / 1_099_511_627_776.0);
    }
    lever
}

/// The most joints of a path a pair may skip (their common ancestor's):
/// deeper chains are left to the edge engine by the rake.
pub(crate) const MAX_SKIP: usize = 15;

/// For every `skip` in `0..=MAX_SKIP`, an upper bound of `|p'(t)|` for
/// every point `p` of link `link` at every time of the segment `q0 -> q1`,
/// counting the joints of its path after the first `skip` (Lemma 13.11 with
/// Lemma 13.1): `sum over turning joints of r_j (L_j + slides below j) +
/// sum over sliding joints of r_j`, into `out[skip]` (one pass up the path).
pub(crate) fn sweep_rates<T: Float>(
    chain: &Chain<T>,
    link: usize,
    levers: &[f64],
    q0: &[T],
    q1: &[T],
    out: &mut [f64],
) {
    let path = &chain.links[link].path;
    let n = path.len().min(levers.len());
    let (mut v, mut extra) = (0.0f64, 0.0f64);
    // The rounding of the sums, the same for every skip.
    let up = 1.0 + f64::from(4 * n as u32 + 8) * f64::EPSILON;
    for skip in (n.min(out.len())..out.len()).rev() {
        out[skip] = 0.0;
    }
    for i in (0..n).rev() {
        let joint = &chain.joints[path[i]];
        if let Some(d) = joint.dof {
            let (a, b) = (q0[d].to_f64(), q1[d].to_f64());
            // `fl(b - a)` is within `u |b - a|` of it in `f64` (exact for `f32`).
            let r = (b - a).abs() * (1.0 + 2.0 * f64::EPSILON);
            if joint.spec.kind == JointKind::Prismatic {
                v += r;
                extra += a.abs().max(b.abs());
            } else {
                v += r * (levers[i] + extra);
            }
        }
        if i < out.len() {
            out[i] = v * up;
        }
    }
}

/// Lemma 13.10: an upper bound of the distance between a point of link
/// `link` within `local_reach` of its frame's origin as the `f32` lanes
/// place it (`lanes.rs`) at a time of the segment `q0 -> q1` and its exact
/// place in the chain as stored (in `T`); and an upper bound of every such
/// placed point's distance from the world origin. Lemma 13.3's `delta` in
/// `f32` arithmetic, plus the rounding of the chain's numbers to `f32`;
/// `+inf` for a chain deeper than Lemma 13.3 allows in `f32`.
pub(crate) fn lane_delta<T: Float>(
    chain: &Chain<T>,
    q0: &[T],
    q1: &[T],
    link: usize,
    local_reach: f64,
) -> (f64, f64) {
    let base = chain.base.translation.length().to_f64();
    let mut depth = 0u32;
    let (mut q_rot, mut q_slide, mut slide_len) = (0.0f64, 0.0f64, 0.0f64);
    let mut at = link;
    while let Some(j) = chain.links[at].parent_joint {
        depth += 1;
        let joint = &chain.joints[j];
        if let Some(dof) = joint.dof {
            let (a, b) = (q0[dof].to_f64(), q1[dof].to_f64());
            let mag = a.abs() + (b - a).abs();
            if joint.spec.kind.is_rotational() {
                q_rot += mag;
            } else {
                q_slide += mag;
                slide_len += a.abs().max(b.abs());
            }
        }
        at = joint.spec.parent;
    }
    let d = f64::from(depth);
    if d * (d + 1.0) * U32 > 1.0 / 512.0 {
        return (f64::INFINITY, f64::INFINITY);
    }
    let up = 1.0 + 64.0 * f64::EPSILON;
    let origins = base + chain.links[link].origin_reach.to_f64();
    let len = (origins + slide_len + local_reach) * (1.0 + gamma32(2 * depth + 4)) * up;
    let eps = gamma32(128 * (depth + 1))
        + gamma32(3) * q_rot * (1.0 + gamma32(depth + 2))
        + f64::from(f32::MIN_POSITIVE);
    let delta = (eps * len + gamma32(3) * q_slide) * (1.0 + gamma32(4))
        + 16.0 * f64::from(f32::MIN_POSITIVE);
    // The chain's numbers rounded to f32 (origins, base, slides: `u` of each
    // length; the axes and rotations within Lemma 13.3's own budgets).
    let convert = 2.0 * U32 * (origins + q_slide + slide_len);
    let delta = (delta + convert) * up;
    (delta, (len + delta) * up)
}

#[cfg(test)]
#[allow(clippy::needless_range_loop)]
mod tests {
    use super::*;
    use crate::chain::model::JointFrame;
    use crate::chain::{ChainBuilder, JointSpec};
    use crate::rng::SplitMix64;
    use crate::TriMesh;
    use alloc::vec;

    /// A random chain of `n` joints (turning, sliding and fixed, origins
    /// with turns), each link a small random mesh.
    fn chain(rng: &mut SplitMix64, n: usize) -> Chain<f64> {
        let mut b = ChainBuilder::new();
        let mut prev = b.add_link("base", None).expect("link");
        for i in 0..n {
            let v: Vec<[f64; 3]> = (0..5).map(|_| rng.vec3().map(|x| x * 0.3)).collect();
            let mesh = TriMesh::try_new(v, vec![[0, 1, 2], [1, 3, 4], [0, 2, 4]]).expect("mesh");
            let l = b
                .add_link(alloc::format!("l{i}"), Some(mesh))
                .expect("link");
            let kind = match rng.next_u64() % 5 {
                0 => JointKind::Prismatic,
                1 => JointKind::Fixed,
                _ => JointKind::Revolute,
            };
            let turn =
                crate::chain::model::turn(Vec3::from_array(rng.direction()), rng.range(-3.0, 3.0));
            b.add_joint(JointSpec {
                name: alloc::format!("j{i}"),
                kind,
                parent: prev,
                child: l,
                origin: Pose {
                    rotation: turn.rotation,
                    translation: Vec3::from_array(rng.vec3().map(|x| x * 0.4)),
                },
                axis: rng.direction(),
                limits: None,
            })
            .expect("joint");
            prev = l;
        }
        b.build().expect("chain")
    }

    /// Lemma 13.11 against sampling: at random configurations, every vertex
    /// of every link is within its lever (plus the slides below) of each
    /// turning joint's axis on its path, the axes placed by forward
    /// kinematics. Returns the largest ratio of a distance to its bound.
    fn worst_ratio(scale: f64) -> f64 {
        let mut rng = SplitMix64::new(0x1e7e_0013);
        let mut worst = 0.0f64;
        for case in 0..300 {
            let c = chain(&mut rng, 1 + case % 6);
            for _ in 0..20 {
                let q: Vec<f64> = (0..c.dof()).map(|_| rng.range(-3.0, 3.0)).collect();
                let mut poses = vec![Pose::IDENTITY; c.links.len()];
                let mut frames = vec![
                    JointFrame {
                        axis: Vec3::ZERO,
                        point: Vec3::ZERO
                    };
                    c.joints.len()
                ];
                c.place(|d| q[d], &mut poses, &mut frames);
                for l in 0..c.links.len() {
                    let Some(mesh) = c.links[l].mesh.as_ref() else {
                        continue;
                    };
                    let levers = link_levers(&c, l, mesh.vertices());
                    let path = &c.links[l].path;
                    for (i, &j) in path.iter().enumerate() {
                        if c.joints[j].spec.kind == JointKind::Prismatic {
                            continue;
                        }
                        let slides: f64 = path[i + 1..]
                            .iter()
                            .filter(|&&k| c.joints[k].spec.kind == JointKind::Prismatic)
                            .map(|&k| q[c.joints[k].dof.expect("dof")].abs())
                            .sum();
                        let bound = (levers[i] + slides) * scale;
                        for v in mesh.vertices() {
                            let p = poses[l].transform_point(Vec3::from_array(*v));
                            let d = (p - frames[j].point).cross(frames[j].axis).length();
                            worst = worst.max(d / bound);
                        }
                    }
                }
            }
        }
        worst
    }

    #[test]
    fn levers_bound_every_sampled_distance_from_an_axis() {
        let worst = worst_ratio(1.0);
        assert!(
            worst <= 1.0,
            "a vertex is {worst} times its lever from an axis"
        );
        // Tight enough to matter: some sampled distance is near its lever,
        // so that 0.8 of the levers fails this test.
        assert!(worst_ratio(0.8) > 1.0, "the levers are never approached");
    }
}
