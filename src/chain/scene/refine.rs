//! A chain's clearance refined (`proofs/13-chains.md`, Lemma 13.16): when
//! what the nearest pair's certified gap deducts for the placement of its
//! links (Lemma 13.3's `delta`, which grows with the depth as
//! `gamma_{128 (m + 1)}` of the reach) is more than `2^-33` of the gap,
//! that pair's links are placed again in double-double arithmetic, rounded
//! to `T` once, with a placement error of a few `u` of the reach instead,
//! and the pair measured again; so is every other pair whose certified gap
//! is still below the new one. Every gap stays a certified lower bound, so
//! the least of them is.

use alloc::vec;
use alloc::vec::Vec;
use core::cmp::Ordering;

use super::ChainScene;
use crate::chain::bound::LinkMotion;
use crate::chain::dispatch::{first_link, placed_gap, PlacedPair};
use crate::chain::model::Chain;
use crate::chain::report::{ChainPair, ChainStats};
use crate::dd::DoubleDouble as D;
use crate::{Float, Pose, Vec3};

type M = [[D; 3]; 3];
type V = [D; 3];

/// `2^-33` (about `1.2e-10`): a pair whose placement deduction is more than
/// this part of its gap is refined.
const REFINE_ABOVE: f64 = 1.164_153_218_269_348_1e-10;
/// `2^-90`: the budget of a placement's double-double roundings, per unit of
/// `1 + L` (Lemma 13.16, item 2).
const DD_BUDGET: f64 = 8.077_935_669_463_161e-28;
/// `1 + 2^-40`: covers the `f64` roundings of the margins' own evaluation.
const UP: f64 = 1.0 + 9.094_947_017_729_282e-13;
/// The deepest path refined (the double-double budget assumes it).
const MAX_DEPTH: u32 = 64;
/// The largest joint coordinate refined (double-double `sin` and `cos` are
/// at full accuracy far beyond).
const MAX_COORD: f64 = 1e6;
/// `2^-20`: the largest total distance of the stored rotations from
/// rotations refined, and the widening before rounding to `T`.
const MAX_OFF: f64 = 9.536_743_164_062_5e-7;

/// One `(bound, pair, deduction)` per checked pair: a certified lower bound
/// of the pair's distance and what its placements deducted.
pub(super) type Bounds<T> = Vec<(T, ChainPair, T)>;

fn d<T: Float>(x: T) -> D {
    D::from_f64(x.to_f64())
}

fn mat<T: Float>(m: &[[T; 3]; 3]) -> M {
    m.map(|r| r.map(d))
}

fn dot(a: &V, b: &V) -> D {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn mul_mv(a: &M, v: &V) -> V {
    [dot(&a[0], v), dot(&a[1], v), dot(&a[2], v)]
}

fn mul_mm(a: &M, b: &M) -> M {
    let col = |j: usize| [b[0][j], b[1][j], b[2][j]];
    let (c0, c1, c2) = (col(0), col(1), col(2));
    [0, 1, 2].map(|i| [dot(&a[i], &c0), dot(&a[i], &c1), dot(&a[i], &c2)])
}

fn add_v(a: V, b: V) -> V {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// `|v|` of a `T` vector in `f64`, rounded up (within `UP`).
fn length_up<T: Float>(v: Vec3<T>) -> f64 {
    let [x, y, z] = v.to_array().map(T::to_f64);
    (x * x + y * y + z * z).sqrt() * UP
}

/// An upper bound of `||S - U||_2` for the nearest rotation `U` of the
/// stored matrix `S` (`||S^T S - I||_F`, Lemma 13.16, item 1), or `None`
/// when `S` is no near rotation (`det S <= 1/2`, or not finite).
fn off_rotation<T: Float>(s: &[[T; 3]; 3]) -> Option<f64> {
    let s = mat(s);
    let col = |j: usize| [s[0][j], s[1][j], s[2][j]];
    let cols = [col(0), col(1), col(2)];
    let mut sum = 0.0;
    for i in 0..3 {
        for j in 0..3 {
            let eye = D::from_f64(if i == j { 1.0 } else { 0.0 });
            let g = (dot(&cols[i], &cols[j]) - eye).to_f64().abs() * UP + DD_BUDGET;
            sum += g * g;
        }
    }
    let det = dot(
        &cols[0],
        &[
            cols[1][1] * cols[2][2] - cols[1][2] * cols[2][1],
            cols[1][2] * cols[2][0] - cols[1][0] * cols[2][2],
            cols[1][0] * cols[2][1] - cols[1][1] * cols[2][0],
        ],
    );
    let off = sum.sqrt() * UP;
    (off.is_finite() && det.to_f64() > 0.5).then_some(off)
}

/// The exact unit `axis / |axis|` in double-double (divided by its largest
/// component first, as `model::unit_axis`).
fn unit<T: Float>(axis: Vec3<T>) -> Option<V> {
    let a = axis.to_array().map(T::to_f64);
    let m = a.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    if !(m > 0.0 && m.is_finite()) {
        return None;
    }
    let s = a.map(|x| D::from_f64(x).div_f64(m));
    let n = dot(&s, &s).sqrt();
    Some(s.map(|x| x.div_dd(n)))
}

/// The turn by `angle` about the unit `k` (Rodrigues), as `model::turn`.
fn turn(k: &V, angle: f64) -> M {
    let (s, c) = D::from_f64(angle).sin_cos();
    let w = D::ONE - c;
    let [x, y, z] = *k;
    [
        [c + x * x * w, x * y * w - z * s, x * z * w + y * s],
        [y * x * w + z * s, c + y * y * w, y * z * w - x * s],
        [z * x * w - y * s, z * y * w + x * s, c + z * z * w],
    ]
}

/// Link `l` of `chain` still at `q`, placed in double-double and rounded to
/// `T` once, with Lemma 13.16's placement error, rotation error and reach
/// (`None` where the lemma does not apply: too deep, a coordinate beyond
/// `1e6`, a stored rotation far from every rotation, a zero axis).
pub(super) fn placed_link<T: Float>(chain: &Chain<T>, q: &[T], l: usize) -> Option<LinkMotion<T>> {
    let mut path = Vec::new();
    let mut at = l;
    while let Some(j) = chain.links[at].parent_joint {
        path.push(j);
        at = chain.joints[j].spec.parent;
        if path.len() > MAX_DEPTH as usize {
            return None;
        }
    }
    let base = &chain.base;
    let mut r = mat(&base.rotation);
    let mut x = base.translation.to_array().map(d);
    let mut off = off_rotation(&base.rotation)?;
    let mut lever = length_up(base.translation);
    for &j in path.iter().rev() {
        let joint = &chain.joints[j];
        let origin = &joint.spec.origin;
        // The joint's frame: `(R, x) * (S_o, x_o)`.
        x = add_v(mul_mv(&r, &origin.translation.to_array().map(d)), x);
        r = mul_mm(&r, &mat(&origin.rotation));
        off += off_rotation(&origin.rotation)?;
        lever += length_up(origin.translation);
        let Some(dof) = joint.dof else { continue };
        let qj = q[dof].to_f64();
        if qj.is_nan() || qj.abs() > MAX_COORD {
            return None;
        }
        let k = unit(Vec3::from_array(joint.spec.axis))?;
        if joint.spec.kind.is_rotational() {
            r = mul_mm(&r, &turn(&k, qj));
        } else {
            x = add_v(x, mul_mv(&r, &k.map(|c| c * qj)));
            lever += qj.abs();
        }
    }
    if off.is_nan() || off > MAX_OFF {
        return None;
    }
    let pose = Pose {
        rotation: r.map(|row| row.map(|e| T::from_f64(e.to_f64()))),
        translation: Vec3::from_array(x.map(|e| T::from_f64(e.to_f64()))),
    };
    let u = T::UNIT_ROUNDOFF.to_f64();
    let eta = T::ETA_NORMAL.to_f64();
    let reach = chain.links[l].reach.to_f64();
    let moved = length_up(pose.translation);
    let lever = (lever + reach) * UP;
    let delta = (16.0 * u * (reach + moved)
        + 2.0 * off * lever
        + DD_BUDGET * (1.0 + lever)
        + 16.0 * eta * (1.0 + reach + moved))
        * UP;
    let axis_err = (4.0 * u + 2.0 * off + DD_BUDGET + 4.0 * eta) * UP;
    let reach_placed = (lever + delta) * UP;
    // `T` rounds to nearest: widened by `2^-20` first, the results stay
    // upper bounds (`u <= 2^-24`).
    let up = |v: f64| T::from_f64(v * (1.0 + MAX_OFF));
    let (delta, axis_err, reach_placed) = (up(delta), up(axis_err), up(reach_placed));
    if !(delta.is_finite() && reach_placed.is_finite()) {
        return None;
    }
    let mut m = LinkMotion::still(pose, delta, reach_placed);
    m.axis_err = axis_err;
    Some(m)
}

impl<T: Float> ChainScene<T> {
    /// Lemma 13.16: the least of `bounds` (the first pair attaining it),
    /// after the nearest pair, and every pair then still below it, are
    /// measured with their links placed by [`placed_link`] when the nearest
    /// pair's deduction is more than `2^-33` of its gap.
    pub(super) fn refined_clearance(
        &self,
        q: &[T],
        mut bounds: Bounds<T>,
    ) -> (T, Option<ChainPair>) {
        let least = |b: &Bounds<T>| {
            let mut best = (T::INFINITY, None, 0);
            for (i, &(g, pair, _)) in b.iter().enumerate() {
                if g < best.0 {
                    best = (g, Some(pair), i);
                }
            }
            best
        };
        let (g0, pair0, i0) = least(&bounds);
        let Some(pair0) = pair0 else {
            return (g0, None);
        };
        let deducted = bounds[i0].2;
        let above = g0.abs() * T::from_f64(REFINE_ABOVE);
        if deducted.partial_cmp(&above) != Some(Ordering::Greater) {
            return (g0, Some(pair0));
        }
        let mut placed: Vec<Option<Option<LinkMotion<T>>>> = vec![None; self.chain.links.len()];
        let mut stack = Vec::new();
        let mut stats = ChainStats::default();
        let Some(g) = self.refined_gap(q, pair0, T::INFINITY, &mut placed, &mut stack, &mut stats)
        else {
            return (g0, Some(pair0));
        };
        let theta = g.max_nan(g0);
        bounds[i0].0 = theta;
        for (i, b) in bounds.iter_mut().enumerate() {
            let (gi, pair, _) = *b;
            if i == i0 || gi.partial_cmp(&theta) != Some(Ordering::Less) {
                continue;
            }
            match self.refined_gap(q, pair, theta, &mut placed, &mut stack, &mut stats) {
                Some(g) => b.0 = g.max_nan(gi),
                // A link the lemma does not place: the first answer stands.
                None => return (g0, Some(pair0)),
            }
        }
        let (g, pair, _) = least(&bounds);
        (g, pair)
    }

    /// `pair`'s certified gap at `q` (node pairs at least `cap` apart not
    /// refined) with its links placed by [`placed_link`] (cached in
    /// `placed`), or `None` when a link cannot be.
    fn refined_gap(
        &self,
        q: &[T],
        pair: ChainPair,
        cap: T,
        placed: &mut [Option<Option<LinkMotion<T>>>],
        stack: &mut Vec<(u32, u32)>,
        stats: &mut ChainStats,
    ) -> Option<T> {
        let mut place = |l: usize| {
            placed[l]
                .get_or_insert_with(|| placed_link(&self.chain, q, l))
                .clone()
        };
        let a = place(first_link(pair))?;
        let b = match pair {
            ChainPair::SelfCollision { b, .. } => place(b)?,
            ChainPair::Obstacle { obstacle, .. } => {
                let o = &self.obstacles[obstacle];
                LinkMotion::still(o.pose, o.delta, o.reach)
            }
            ChainPair::Shape { .. } => a.clone(),
        };
        let ta = &self.chain.links[first_link(pair)].tree.as_ref()?.whole;
        let tb = self.segment_view(q, q).trees(pair).map(|t| t.1);
        let p = PlacedPair {
            pair,
            ta,
            tb,
            a: &a,
            b: &b,
        };
        Some(placed_gap(&p, &self.shapes, cap, T::ZERO, stack, stats).gap)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chain::{ChainBuilder, JointKind, JointSpec};
    use crate::rng::SplitMix64 as Rng;
    use crate::TriMesh;

    /// A rotation by `angle` about a random unit axis, rounded to `T`.
    fn rounded_turn<T: Float>(rng: &mut Rng) -> [[T; 3]; 3] {
        let a = [
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
        ];
        let axis = Vec3::from_array(a.map(|x| D::from_f64(x).to_f64()));
        let k = unit(axis).expect("a nonzero axis");
        let r = turn(&k, rng.range(-3.2, 3.2));
        r.map(|row| row.map(|e| T::from_f64(e.to_f64())))
    }

    /// A random chain of up to 9 links (a tetrahedron each, up to 0.4 from
    /// its frame), turning and sliding joints, origins rounded from exact
    /// turns (a third left the identity), a random base; and a random `q`.
    fn random_chain<T: Float>(rng: &mut Rng) -> (Chain<T>, Vec<T>) {
        let n = 2 + (rng.next_u64() % 8) as usize;
        let mut b = ChainBuilder::<T>::new();
        let t = |x: f64| T::from_f64(x);
        for l in 0..n {
            let v: Vec<[T; 3]> = (0..4)
                .map(|_| [0; 3].map(|_| t(rng.range(-0.4, 0.4))))
                .collect();
            let mesh = TriMesh::try_new(v, vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]).ok();
            b.add_link(alloc::format!("l{l}"), mesh).expect("a link");
        }
        for c in 1..n {
            let rotation = if rng.unit() < 0.3 {
                Pose::<T>::IDENTITY.rotation
            } else {
                rounded_turn(rng)
            };
            let kind = match rng.next_u64() % 5 {
                0 => JointKind::Prismatic,
                1 => JointKind::Fixed,
                _ => JointKind::Revolute,
            };
            b.add_joint(JointSpec {
                name: alloc::format!("j{c}"),
                kind,
                parent: (rng.next_u64() % c as u64) as usize,
                child: c,
                origin: Pose::new(
                    rotation,
                    Vec3::from_array([0; 3].map(|_| t(rng.range(-0.5, 0.5)))),
                ),
                axis: [0; 3].map(|_| t(rng.range(-1.0, 1.0))),
                limits: None,
            })
            .expect("a joint");
        }
        let base = Pose::new(
            rounded_turn(rng),
            Vec3::from_array([0; 3].map(|_| t(rng.range(-2.0, 2.0)))),
        );
        let chain = b.build().expect("a tree").with_base(base);
        let q = (0..chain.dof()).map(|_| t(rng.range(-3.0, 3.0))).collect();
        (chain, q)
    }

    /// The exact place of link `l`'s point `p` with the stored matrices
    /// read as exact (`E_S`), in double-double, carried up the path from
    /// the link to the root (the other order from [`placed_link`]'s).
    fn exact_place<T: Float>(chain: &Chain<T>, q: &[T], l: usize, p: [T; 3]) -> V {
        let mut y = p.map(d);
        let mut at = l;
        while let Some(j) = chain.links[at].parent_joint {
            let joint = &chain.joints[j];
            if let Some(dof) = joint.dof {
                let k = unit(Vec3::from_array(joint.spec.axis)).expect("an axis");
                let qj = q[dof].to_f64();
                y = if joint.spec.kind.is_rotational() {
                    mul_mv(&turn(&k, qj), &y)
                } else {
                    add_v(y, k.map(|c| c * qj))
                };
            }
            let o = &joint.spec.origin;
            y = add_v(
                mul_mv(&mat(&o.rotation), &y),
                o.translation.to_array().map(d),
            );
            at = joint.spec.parent;
        }
        add_v(
            mul_mv(&mat(&chain.base.rotation), &y),
            chain.base.translation.to_array().map(d),
        )
    }

    /// The worst ratio of a placed point's error to Lemma 13.16's `delta`
    /// over random chains in `T`, and of the rotation's to its bound.
    fn worst<T: Float>(cases: u64) -> (f64, f64) {
        let (mut pts, mut rot) = (0.0f64, 0.0f64);
        for seed in 0..cases {
            let mut rng = Rng::new(seed);
            let (chain, q) = random_chain::<T>(&mut rng);
            for l in 0..chain.links.len() {
                let m = placed_link(&chain, &q, l).expect("a placeable link");
                let mut points = vec![[T::ZERO; 3]];
                if let Some(mesh) = &chain.links[l].mesh {
                    points.extend(mesh.vertices().iter().copied());
                }
                for p in points {
                    let got = m
                        .pose
                        .transform_point(Vec3::from_array(p))
                        .to_array()
                        .map(d);
                    let e = exact_place(&chain, &q, l, p);
                    let diff = [got[0] - e[0], got[1] - e[1], got[2] - e[2]];
                    let err = dot(&diff, &diff).sqrt().to_f64();
                    pts = pts.max(err / m.delta.to_f64());
                }
                // The rotation: the images of the unit vectors.
                let o = exact_place(&chain, &q, l, [T::ZERO; 3]);
                let mut fro = D::ZERO;
                for k in 0..3 {
                    let mut ek = [T::ZERO; 3];
                    ek[k] = T::ONE;
                    let e = exact_place(&chain, &q, l, ek);
                    for i in 0..3 {
                        let x = d(m.pose.rotation[i][k]) - (e[i] - o[i]);
                        fro = fro + x * x;
                    }
                }
                rot = rot.max(fro.sqrt().to_f64() / m.axis_err.to_f64());
            }
        }
        (pts, rot)
    }

    /// Lemma 13.16, items 2 and 3: every placed point (mesh vertices and
    /// the frame's origin) of every link of 400 random chains, placed by
    /// [`placed_link`] and `Pose::transform_point`, is within its `delta`
    /// of the exact place, and the rounded rotation within its `axis_err`,
    /// in both precisions; against the double-double evaluation carried
    /// the other way up the chain (its own error about `2^-100`).
    #[test]
    fn refined_placements_are_within_their_error() {
        let (p64, r64) = worst::<f64>(400);
        let (p32, r32) = worst::<f32>(400);
        assert!(
            p64 <= 1.0 && r64 <= 1.0,
            "f64: points {p64}, rotation {r64} of the bound"
        );
        assert!(
            p32 <= 1.0 && r32 <= 1.0,
            "f32: points {p32}, rotation {r32} of the bound"
        );
        // Not vacuous: the rounding to `T` uses a visible part of the bound.
        assert!(p64 > 0.01 && p32 > 0.01, "slack: f64 {p64}, f32 {p32}");
        std::println!("worst error / bound: f64 points {p64:.3}, rotation {r64:.3}; f32 points {p32:.3}, rotation {r32:.3}");
    }
}
