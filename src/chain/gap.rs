//! Certified gaps between two placed hierarchies: a node pair's balls, a
//! triangle pair's slab, the descent of a node pair, and the branch and
//! bound for the smallest gap over triangle pairs.

use alloc::vec::Vec;

use crate::bvh::{Hierarchy, Node, OrientedBox};
use crate::chain::bound::LinkMotion;
use crate::chain::report::ChainStats;
use crate::geometry::closest::triangle_triangle_vec;
use crate::rounding::{gamma, gap_down, step_down};
use crate::{Float, Pose, Vec3};

/// The centre line of two balls as a computed unit vector, or `None`.
#[inline]
fn unit<T: Float>(v: Vec3<T>) -> Option<Vec3<T>> {
    v.try_normalize()
}

/// The certified gap between two placed balls along their centre line
/// (`gap_down` of the centre distance less the radii).
#[inline]
fn ball_gap<T: Float>(
    ca: Vec3<T>,
    ra: T,
    cb: Vec3<T>,
    rb: T,
    a: &LinkMotion<T>,
    b: &LinkMotion<T>,
) -> T {
    let d = (cb - ca).length();
    gap_down(d - ra - rb, a.delta, b.delta, a.reach + b.reach)
}

/// A node pair of two hierarchies placed in the world: the nodes, their
/// balls' placed centres and their radii.
pub(super) struct PlacedNodes<'a, T> {
    pub(super) na: &'a Node<T>,
    pub(super) nb: &'a Node<T>,
    pub(super) ca: Vec3<T>,
    pub(super) cb: Vec3<T>,
    pub(super) ra: T,
    pub(super) rb: T,
}

impl<'a, T: Float> PlacedNodes<'a, T> {
    /// Node `ia` of `ta` placed by `a`'s pose and node `ib` of `tb` by `b`'s.
    /// (Always inlined: it runs for every node pair visited, and a call
    /// that returns the struct through memory costs more than its work.)
    #[inline(always)]
    pub(super) fn new(
        ta: &'a Hierarchy<T>,
        tb: &'a Hierarchy<T>,
        a: &LinkMotion<T>,
        b: &LinkMotion<T>,
        ia: u32,
        ib: u32,
    ) -> Self {
        let (na, nb) = (&ta.nodes[ia as usize], &tb.nodes[ib as usize]);
        let ca = a.pose.transform_point(*na.ball.centre());
        let cb = b.pose.transform_point(*nb.ball.centre());
        let (ra, rb) = (na.ball.radius(), nb.ball.radius());
        Self {
            na,
            nb,
            ca,
            cb,
            ra,
            rb,
        }
    }

    /// The certified gap between the two balls ([`ball_gap`]).
    #[inline]
    pub(super) fn ball_gap(&self, a: &LinkMotion<T>, b: &LinkMotion<T>) -> T {
        ball_gap(self.ca, self.ra, self.cb, self.rb, a, b)
    }

    /// The certified slab gap of the two nodes' boxes along the direction
    /// from the larger box's point nearest the smaller ball's centre to that
    /// centre (the nearest face of a long node, Lemma 13.6's item 2), and
    /// that direction as a computed unit from A towards B; `-inf` (and the
    /// centre line) when the centre is inside the box.
    #[inline]
    pub(super) fn face_gap(&self, a: &LinkMotion<T>, b: &LinkMotion<T>) -> (T, Option<Vec3<T>>) {
        let d = if self.rb > self.ra {
            -from_box(&self.nb.obb, b, self.ca)
        } else {
            from_box(&self.na.obb, a, self.cb)
        };
        match d.try_normalize() {
            Some(n) => {
                let hi_a = box_support_up(&self.na.obb, a, n);
                let lo_b = -box_support_up(&self.nb.obb, b, -n);
                (
                    gap_down(lo_b - hi_a, a.delta, b.delta, a.reach + b.reach),
                    Some(n),
                )
            }
            None => (-T::INFINITY, None),
        }
    }

    /// The certified step that closes the gap `g` along the balls' centre
    /// line (`x` for coincident centres) at the balls' directed speeds.
    #[inline]
    pub(super) fn step(&self, g: T, a: &LinkMotion<T>, b: &LinkMotion<T>, x: Vec3<T>) -> T {
        let n = unit(self.cb - self.ca).unwrap_or(x);
        let (mu_a, _) = a.ball_speed(self.ca, self.ra, n);
        let (mu_b, _) = b.ball_speed(self.cb, self.rb, n);
        step_down(g, T::ZERO, mu_a, mu_b)
    }

    /// Descends the pair `(ia, ib)` when it is not two leaves: pushes the
    /// children of the node that is not a leaf, or of two inner nodes those
    /// of the one with the larger ball ([`push_children`]).
    #[inline]
    #[allow(clippy::too_many_arguments)]
    pub(super) fn descend(
        &self,
        stack: &mut Vec<(u32, u32)>,
        ta: &Hierarchy<T>,
        tb: &Hierarchy<T>,
        a: &LinkMotion<T>,
        b: &LinkMotion<T>,
        ia: u32,
        ib: u32,
    ) {
        if self.na.leaf().is_none() && (self.nb.leaf().is_some() || self.ra >= self.rb) {
            push_children(stack, self.na, &ta.nodes, &a.pose, self.cb, ia, ib, true);
        } else {
            push_children(stack, self.nb, &tb.nodes, &b.pose, self.ca, ia, ib, false);
        }
    }
}

/// The corners of leaf `leaf` of `tree` placed by `m`'s pose.
#[inline]
pub(super) fn placed_corners<T: Float>(
    tree: &Hierarchy<T>,
    leaf: usize,
    m: &LinkMotion<T>,
) -> [Vec3<T>; 3] {
    tree.leaves[leaf].corners.map(|p| m.pose.transform_point(p))
}

/// Pushes the children of the node of the larger ball (of A when
/// `on_a`), the one whose ball centre is nearer the other node's centre last
/// (taken first: a small step is found early and prunes the rest).
#[inline]
#[allow(clippy::too_many_arguments)]
fn push_children<T: Float>(
    stack: &mut Vec<(u32, u32)>,
    node: &Node<T>,
    children: &[Node<T>],
    pose: &Pose<T>,
    other: Vec3<T>,
    ia: u32,
    ib: u32,
    on_a: bool,
) {
    let d = |i: u32| {
        let c = pose.transform_point(*children[i as usize].ball.centre());
        (c - other).length() - children[i as usize].ball.radius()
    };
    let (near, far) = if d(node.left) <= d(node.right) {
        (node.left, node.right)
    } else {
        (node.right, node.left)
    };
    if on_a {
        stack.push((far, ib));
        stack.push((near, ib));
    } else {
        stack.push((ia, far));
        stack.push((ia, near));
    }
}

/// The certified gap of two placed triangles along the computed direction
/// `d` (from A towards B): `min_B q.n - max_A p.n`, less the rounding and
/// the pieces' `inflate`
/// (`gap_down`); `-inf` for a zero direction.
pub(super) fn slab_gap<T: Float>(
    pa: &[Vec3<T>; 3],
    pb: &[Vec3<T>; 3],
    d: Vec3<T>,
    a: &LinkMotion<T>,
    b: &LinkMotion<T>,
    inflate: T,
) -> T {
    let Some(n) = d.try_normalize() else {
        return -T::INFINITY;
    };
    let hi_a = pa.iter().map(|p| p.dot(n)).fold(-T::INFINITY, T::max_nan);
    let lo_b = pb.iter().map(|p| p.dot(n)).fold(T::INFINITY, T::min_nan);
    // A piece's exact points lie within `inflate` of its corners' triangle:
    // taken with the placement error, as `gap_down` rounds it.
    gap_down(lo_b - hi_a, a.delta + inflate, b.delta, a.reach + b.reach)
}

/// The largest certified slab gap of two placed triangles over the
/// separating axes of a triangle pair: each triangle's normal, then the nine
/// cross products of an edge of each, every direction taken both ways (the
/// larger of `min_B q.n - max_A p.n` and `min_A p.n - max_B q.n`), less the
/// rounding and `inflate` as [`slab_gap`]. It stops at the first direction
/// whose gap exceeds `enough`. Each slab gap is at most the distance
/// (Lemma 13.6, item 4), so the largest is too. It is the distance where the
/// nearest points are a face's inside and a corner, or two edges' insides;
/// coplanar triangles are not separated by these axes (all are normal to
/// the plane), and are left to their closest points. Two large triangles
/// side by side (a link's side along a pole's long face) are told apart
/// here without their closest points.
pub(super) fn axes_gap<T: Float>(
    pa: &[Vec3<T>; 3],
    pb: &[Vec3<T>; 3],
    a: &LinkMotion<T>,
    b: &LinkMotion<T>,
    inflate: T,
    enough: T,
) -> T {
    let ea = [pa[1] - pa[0], pa[2] - pa[1], pa[0] - pa[2]];
    let eb = [pb[1] - pb[0], pb[2] - pb[1], pb[0] - pb[2]];
    let (err_a, reach) = (a.delta + inflate, a.reach + b.reach);
    let mut out = -T::INFINITY;
    let normals = [eb[0].cross(eb[1]), ea[0].cross(ea[1])];
    let crosses = (0..9).map(|k| ea[k / 3].cross(eb[k % 3]));
    for d in normals.into_iter().chain(crosses) {
        let Some(n) = d.try_normalize() else {
            continue;
        };
        let (mut lo_a, mut hi_a) = (T::INFINITY, -T::INFINITY);
        for p in pa {
            let x = p.dot(n);
            lo_a = lo_a.min_nan(x);
            hi_a = hi_a.max_nan(x);
        }
        let (mut lo_b, mut hi_b) = (T::INFINITY, -T::INFINITY);
        for q in pb {
            let x = q.dot(n);
            lo_b = lo_b.min_nan(x);
            hi_b = hi_b.max_nan(x);
        }
        // The slab along `n` or along `-n` (a negated unit is exact).
        let g = gap_down((lo_b - hi_a).max_nan(lo_a - hi_b), err_a, b.delta, reach);
        if g > out {
            out = g;
            if out > enough {
                break;
            }
        }
    }
    out
}

/// What the distance phase found: a certified lower bound of the distance
/// (or of `cap`, when everything is farther), and the closest triangle pair
/// measured (its computed distance and witnesses).
pub(super) struct Near<T> {
    pub(super) gap: T,
    pub(super) closest: Option<(T, Vec3<T>, Vec3<T>)>,
}

/// The smallest certified gap over triangle pairs (branch and bound on the
/// balls and the boxes' nearest faces; node pairs at least `cap` apart are
/// not refined).
#[allow(clippy::too_many_arguments)]
pub(super) fn min_gap<T: Float>(
    ta: &Hierarchy<T>,
    tb: &Hierarchy<T>,
    a: &LinkMotion<T>,
    b: &LinkMotion<T>,
    cap: T,
    slack: T,
    cap_touch: T,
    stack: &mut Vec<(u32, u32)>,
    stats: &mut ChainStats,
) -> Near<T> {
    let mut best = cap;
    // The least gap of the node pairs left unrefined within the slack.
    let mut kept = T::INFINITY;
    let keep = T::ONE - slack;
    let mut closest: Option<(T, Vec3<T>, Vec3<T>)> = None;
    stack.clear();
    stack.push((0, 0));
    while let Some((ia, ib)) = stack.pop() {
        stats.node_pairs += 1;
        let nodes = PlacedNodes::new(ta, tb, a, b, ia, ib);
        let mut g = nodes.ball_gap(a, b);
        if g >= best {
            continue;
        }
        // The boxes' gap along the larger's nearest face: a long triangle's
        // node beside a link's (a pole's side, a plate's edge).
        g = g.max_nan(nodes.face_gap(a, b).0);
        if g >= best {
            continue;
        }
        if slack > T::ZERO && g >= best * keep && g > T::ZERO {
            kept = kept.min_nan(g);
            continue;
        }
        match (nodes.na.leaf(), nodes.nb.leaf()) {
            (Some(la), Some(lb)) => {
                stats.leaf_pairs += 1;
                let pa = placed_corners(ta, la, a);
                let pb = placed_corners(tb, lb, b);
                // A piece's exact points are within `inflate` of its corners' triangle.
                let inflate =
                    (ta.leaves[la].inflate + tb.leaves[lb].inflate) * (T::ONE + T::UNIT_ROUNDOFF);
                // First the cheap slab gap along the balls' centre line: a
                // pair it shows farther than the contact distance, and within
                // the slack of the best, needs no exact distance.
                let g0 = slab_gap(&pa, &pb, nodes.cb - nodes.ca, a, b, inflate);
                if g0 >= best {
                    continue;
                }
                if slack > T::ZERO && g0 > cap_touch && g0 >= best * keep {
                    kept = kept.min_nan(g0);
                    continue;
                }
                // Then the separating axes (two large triangles side by
                // side, where the centre line is tilted): the same tests.
                let g1 = axes_gap(&pa, &pb, a, b, inflate, best);
                if g1 >= best {
                    continue;
                }
                if slack > T::ZERO && g1 > cap_touch && g1 >= best * keep {
                    kept = kept.min_nan(g1);
                    continue;
                }
                let cp = triangle_triangle_vec(&pa, &pb);
                let distance = cp.distance - inflate;
                if closest.is_none_or(|(d, _, _)| distance < d) {
                    closest = Some((distance, cp.on_a, cp.on_b));
                }
                // The slab along the closest points' computed direction, or
                // the separating axes' when larger: near-parallel features
                // tilt the former by their witnesses' rounding, about `u`
                // of the coordinates over the distance (Lemma 13.16, item 4).
                let g = slab_gap(&pa, &pb, cp.on_b - cp.on_a, a, b, inflate)
                    .max_nan(g1)
                    .min_nan(distance);
                let g = if g.is_nan() { -T::INFINITY } else { g };
                if g < best {
                    best = g;
                }
            }
            _ => nodes.descend(stack, ta, tb, a, b, ia, ib),
        }
    }
    Near {
        gap: best.min_nan(kept),
        closest,
    }
}

/// An upper bound of `x . n` over the exact placed box of a link (or
/// obstacle) node, for the computed unit `n` (Lemma 13.6): the placed
/// centre's `c . n` plus the box's support about its centre along
/// `fl(R^T n)`, widened by the box's error weight times the rotation's error
/// `epsilon_R` (Lemma 13.3) and the direction's rounding `8 u`; the placed
/// centre's own error is `delta`, taken by the caller's `gap_down`.
#[inline]
pub(super) fn box_support_up<T: Float>(obb: &OrientedBox<T>, m: &LinkMotion<T>, n: Vec3<T>) -> T {
    let c = m.pose.transform_point(obb.centre);
    let local = obb.support_raw(m.pose.inverse_transform_vector(n)) * (T::ONE + gamma::<T>(4));
    let widen = obb.error_weight * (m.axis_err + T::from_u32(8) * T::UNIT_ROUNDOFF);
    c.dot(n) + (local + widen) * (T::ONE + gamma::<T>(2))
}

/// The direction from the placed box's point nearest `c` to `c` (zero when
/// `c` is inside), computed: only the choice of a slab's direction depends
/// on it, never a gap's soundness.
#[inline]
pub(super) fn from_box<T: Float>(obb: &OrientedBox<T>, m: &LinkMotion<T>, c: Vec3<T>) -> Vec3<T> {
    let local = m
        .pose
        .inverse_transform_vector(c - m.pose.transform_point(obb.centre));
    let mut out = Vec3::new(T::ZERO, T::ZERO, T::ZERO);
    for k in 0..3 {
        let axis = Vec3::from_array(obb.axes[k]);
        let (x, h) = (local.dot(axis), obb.half[k]);
        if x > h {
            out = out + axis * (x - h);
        } else if x < -h {
            out = out + axis * (x + h);
        }
    }
    m.pose.transform_vector(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::SplitMix64;
    use crate::Pose;

    /// Points of a barycentric grid of `n + 1` per side over the triangle.
    fn grid(t: &[[f64; 3]; 3], n: usize) -> Vec<[f64; 3]> {
        let mut out = Vec::new();
        for i in 0..=n {
            for j in 0..=n - i {
                let (u, v) = (i as f64 / n as f64, j as f64 / n as f64);
                let w = 1.0 - u - v;
                out.push(core::array::from_fn(|k| {
                    u * t[0][k] + v * t[1][k] + w * t[2][k]
                }));
            }
        }
        out
    }

    /// The smallest distance between the two grids: at least the
    /// triangles' distance.
    fn sampled_distance(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]) -> f64 {
        let (ga, gb) = (grid(a, 24), grid(b, 24));
        let mut best = f64::INFINITY;
        for p in &ga {
            for q in &gb {
                let d2: f64 = (0..3).map(|k| (p[k] - q[k]) * (p[k] - q[k])).sum();
                best = best.min(d2);
            }
        }
        best.sqrt()
    }

    fn still<T: Float>(corners: &[Vec3<T>]) -> LinkMotion<T> {
        let reach = corners.iter().map(|p| p.length()).fold(T::ZERO, T::max_nan);
        LinkMotion::still(Pose::IDENTITY, T::ZERO, reach * T::TWO)
    }

    fn placed<T: Float>(t: &[[f64; 3]; 3]) -> [Vec3<T>; 3] {
        t.map(|p| Vec3::new(T::from_f64(p[0]), T::from_f64(p[1]), T::from_f64(p[2])))
    }

    fn back<T: Float>(t: &[Vec3<T>; 3]) -> [[f64; 3]; 3] {
        t.map(|p| [p.x.to_f64(), p.y.to_f64(), p.z.to_f64()])
    }

    /// A random triangle about `at`: of any shape, or long and thin (a
    /// pole's side) when `thin`.
    fn triangle(rng: &mut SplitMix64, at: [f64; 3], scale: f64, thin: bool) -> [[f64; 3]; 3] {
        if thin {
            let (d, w) = (rng.vec3(), rng.vec3());
            let p0: [f64; 3] = core::array::from_fn(|k| at[k] - 0.5 * scale * d[k]);
            let p1: [f64; 3] = core::array::from_fn(|k| at[k] + 0.5 * scale * d[k]);
            let p2: [f64; 3] = core::array::from_fn(|k| p1[k] + 0.013 * scale * w[k]);
            [p0, p1, p2]
        } else {
            core::array::from_fn(|_| {
                let r = rng.vec3();
                core::array::from_fn(|k| at[k] + scale * r[k])
            })
        }
    }

    fn check_never_above_sampling<T: Float>(seed: u64) {
        let mut rng = SplitMix64::new(seed);
        let mut apart = 0;
        for case in 0..160 {
            let scale = [0.01, 0.3, 1.0, 40.0][case % 4];
            let at = rng.vec3().map(|x| x * scale * 3.0);
            let a = triangle(&mut rng, [0.0; 3], scale, case % 3 == 0);
            let size = scale * rng.range(0.05, 1.0);
            let b = triangle(&mut rng, at, size, case % 5 == 1);
            let (pa, pb) = (placed::<T>(&a), placed::<T>(&b));
            let (ma, mb) = (still(&pa), still(&pb));
            let g = axes_gap(&pa, &pb, &ma, &mb, T::ZERO, T::INFINITY).to_f64();
            // The truth from the corners as stored in `T`.
            let truth = sampled_distance(&back(&pa), &back(&pb));
            assert!(
                g <= truth,
                "case {case}: axes gap {g:e} above the sampled distance {truth:e}"
            );
            apart += usize::from(g > 0.0);
        }
        assert!(apart > 40, "only {apart} of 160 pairs found apart");
    }

    #[test]
    fn axes_gap_is_never_above_the_sampled_distance_f64() {
        check_never_above_sampling::<f64>(0xA7E5);
    }

    #[test]
    fn axes_gap_is_never_above_the_sampled_distance_f32() {
        check_never_above_sampling::<f32>(0x5EED);
    }

    /// A random orthonormal frame (Gram-Schmidt of random vectors).
    fn frame(rng: &mut SplitMix64) -> [[f64; 3]; 3] {
        let norm = |v: [f64; 3]| {
            let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            v.map(|x| x / l)
        };
        let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let x = norm(rng.vec3());
        let r = rng.vec3();
        let y = norm(core::array::from_fn(|k| r[k] - dot(r, x) * x[k]));
        let z = [
            x[1] * y[2] - x[2] * y[1],
            x[2] * y[0] - x[0] * y[2],
            x[0] * y[1] - x[1] * y[0],
        ];
        [x, y, z]
    }

    /// Two configurations whose distance is `h` in closed form: a corner of
    /// B at height `h` over the inside of A's face (the rest of B higher),
    /// and two edges crossing at right angles `h` apart (the triangles
    /// turned away from each other). The separating axes find `h` itself,
    /// up to rounding.
    #[test]
    fn axes_gap_is_the_distance_over_a_face_and_across_two_edges() {
        let mut rng = SplitMix64::new(0xFACE);
        for case in 0..200 {
            let f = frame(&mut rng);
            let o = rng.vec3();
            let h = rng.range(1e-3, 0.5);
            let s = rng.range(0.05, 2.0);
            let (a, b) = if case % 2 == 0 {
                let a = [[-s, -s, 0.0], [s, -s, 0.0], [0.0, s, 0.0]];
                let b = [
                    [0.0, 0.0, h],
                    [s, 0.3 * s, h + s],
                    [-0.4 * s, s, h + 0.5 * s],
                ];
                (a, b)
            } else {
                let a = [[-s, 0.0, 0.0], [s, 0.0, 0.0], [0.0, 0.0, -s]];
                let b = [[0.0, -s, h], [0.0, s, h], [0.0, 0.0, h + s]];
                (a, b)
            };
            let to_world = |t: [[f64; 3]; 3]| {
                t.map(|p| {
                    core::array::from_fn(|k| {
                        o[k] + p[0] * f[0][k] + p[1] * f[1][k] + p[2] * f[2][k]
                    })
                })
            };
            let (pa, pb) = (placed::<f64>(&to_world(a)), placed::<f64>(&to_world(b)));
            let (ma, mb) = (still(&pa), still(&pb));
            let g = axes_gap(&pa, &pb, &ma, &mb, 0.0, f64::INFINITY);
            assert!(
                g <= h * (1.0 + 1e-12) && g >= h - 1e-12,
                "case {case}: axes gap {g:e} against the distance {h:e}"
            );
            // It stops at the first direction past `enough`.
            let early = axes_gap(&pa, &pb, &ma, &mb, 0.0, 0.5 * h);
            assert!(early > 0.5 * h && early <= g, "case {case}: {early:e}");
        }
    }
}
