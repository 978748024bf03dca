//! The broad phase of a segment: each link's root ball swept over
//! sub-intervals against the obstacles' world boxes and the other links'
//! swept balls, giving each pair the sub-intervals in which it may meet.

use alloc::vec::Vec;

use crate::chain::report::{ChainPair, ChainStats};
use crate::chain::segment::{take_motion, Segment, Work};
use crate::rounding::gamma;
use crate::{Float, Vec3};

/// The broad phase: each link's root ball swept over `broad_pieces`
/// sub-intervals (its centre at the piece's start, its radius grown by
/// the undirected speed bound over the piece and twice the placement
/// error) against each obstacle's world box and each other link's swept
/// ball over the same piece. Each live pair comes with the mask of the
/// pieces in which its volumes may meet.
pub(super) fn broad_phase<T: Float>(
    segment: &Segment<'_, T>,
    pairs: &[(ChainPair, bool)],
    work: &mut Work<T>,
    stats: &mut ChainStats,
) -> Vec<(ChainPair, u64)> {
    let k = segment.params.broad_pieces;
    let n = segment.chain.links.len();
    let cd = segment.params.contact_distance;
    // balls[piece][link] = (centre, radius), full-chain bound.
    let mut balls: Vec<Vec<(Vec3<T>, T)>> = Vec::with_capacity(k);
    for piece in 0..k {
        let t0 = T::from_u32(piece as u32) / T::from_u32(k as u32);
        let t1 = T::from_u32(piece as u32 + 1) / T::from_u32(k as u32);
        segment.place(work, t0);
        let dt = (t1 - t0) * (T::ONE + gamma::<T>(2));
        let mut row = Vec::with_capacity(n);
        let mut m = take_motion(&mut work.a);
        for l in 0..n {
            match &segment.chain.links[l].tree {
                Some(tree) => {
                    work.fill(segment.chain, &mut m, l, 0, dt);
                    let root = &tree.whole.nodes[0].ball;
                    let c = m.pose.transform_point(*root.centre());
                    let (_, speed) =
                        m.ball_speed(c, root.radius(), Vec3::new(T::ONE, T::ZERO, T::ZERO));
                    let r =
                        (root.radius() + speed * dt + T::TWO * m.delta) * (T::ONE + gamma::<T>(4));
                    row.push((c, r));
                }
                None => row.push((Vec3::ZERO, T::ZERO)),
            }
        }
        work.a = Some(m);
        balls.push(row);
    }
    // Each obstacle's world box, grown by its placement error.
    let boxes: Vec<(Vec3<T>, Vec3<T>)> = segment
        .obstacles
        .iter()
        .map(|o| {
            let mut lo = Vec3::new(T::INFINITY, T::INFINITY, T::INFINITY).to_array();
            let mut hi = Vec3::new(-T::INFINITY, -T::INFINITY, -T::INFINITY).to_array();
            for v in o.mesh.vertices() {
                let p = o.pose.transform_point(*v).to_array();
                for d in 0..3 {
                    lo[d] = lo[d].min_nan(p[d]);
                    hi[d] = hi[d].max_nan(p[d]);
                }
            }
            let e = T::TWO * o.delta;
            (
                Vec3::from_array(lo.map(|x| x - e)),
                Vec3::from_array(hi.map(|x| x + e)),
            )
        })
        .collect();
    let apart = |(ca, ra): (Vec3<T>, T), (cb, rb): (Vec3<T>, T)| {
        let d = (cb - ca).length() * (T::ONE - gamma::<T>(4));
        d > (ra + rb + cd) * (T::ONE + gamma::<T>(2))
    };
    let apart_box = |(c, r): (Vec3<T>, T), (lo, hi): (Vec3<T>, Vec3<T>)| {
        let (c, lo, hi) = (c.to_array(), lo.to_array(), hi.to_array());
        let near = [0, 1, 2].map(|d| c[d].max_nan(lo[d]).min_nan(hi[d]));
        let d = (Vec3::from_array(c) - Vec3::from_array(near)).length() * (T::ONE - gamma::<T>(4));
        d > (r + cd) * (T::ONE + gamma::<T>(2))
    };
    let mut live = Vec::new();
    for &(pair, checked) in pairs {
        stats.pairs += 1;
        if !checked {
            stats.excluded += 1;
            continue;
        }
        let mut mask = 0u64;
        for (i, row) in balls.iter().enumerate() {
            let meet = match pair {
                ChainPair::Obstacle { link, obstacle } => !apart_box(row[link], boxes[obstacle]),
                ChainPair::SelfCollision { a, b } => !apart(row[a], row[b]),
                // Not a pair of this query (shape pairs go to the edge engine, `dispatch.rs`).
                _ => true,
            };
            if meet {
                mask |= 1 << i;
            }
        }
        if mask != 0 {
            live.push((pair, mask));
        } else {
            stats.culled += 1;
        }
    }
    live
}
